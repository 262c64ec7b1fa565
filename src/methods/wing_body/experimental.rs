//! Experimental wing-body data of the deck ($EXPRnn CDWB, CLWB, CMWB, CLAWB, CMAWB): the given
//! values replace the computed ones on the wing-body page and, through it, wherever the
//! wing-body's coefficients enter (the configurations with tails, the wing-body Clβ), as the
//! original does (EXSUBT after WBAERO's lift, drag and moment, and again before the
//! configuration totals).

use serde::Serialize;

use crate::case::Case;
use crate::methods::experimental;

/// The wing-body's experimental values for one Mach number, by angle-of-attack index; `None`
/// where the deck gives no value.
#[derive(Debug, Clone, PartialEq, Default, Serialize)]
pub struct ExperimentalWingBody {
    /// The namelist the values come from (`EXPR01`, ...).
    pub namelist: String,
    pub cd: Vec<Option<f64>>,
    pub cl: Vec<Option<f64>>,
    pub cm: Vec<Option<f64>>,
    /// Slopes as the deck gives them, per degree.
    pub cla_per_deg: Vec<Option<f64>>,
    pub cma_per_deg: Vec<Option<f64>>,
}

impl ExperimentalWingBody {
    /// The wing-body data of `$EXPRnn` for the Mach number of index `mach_index` (0-based),
    /// when the case has that namelist with any of CDWB, CLWB, CMWB, CLAWB, CMAWB.
    pub fn of_case(case: &Case, mach_index: usize) -> Option<ExperimentalWingBody> {
        let (namelist, values) = experimental::namelist(case, mach_index)?;
        let [cd, cl, cm, cla, cma] = experimental::WING_BODY;
        let read = |var: &str| experimental::column(values, var);
        let data = ExperimentalWingBody {
            cd: read(cd),
            cl: read(cl),
            cm: read(cm),
            cla_per_deg: read(cla),
            cma_per_deg: read(cma),
            namelist,
        };
        (!data.given().is_empty()).then_some(data)
    }

    /// The variables given, each with the number of angles it gives.
    pub fn given(&self) -> Vec<(&'static str, usize)> {
        let columns = [
            &self.cd,
            &self.cl,
            &self.cm,
            &self.cla_per_deg,
            &self.cma_per_deg,
        ];
        experimental::WING_BODY
            .iter()
            .zip(columns)
            .map(|(name, c)| (*name, c.iter().filter(|v| v.is_some()).count()))
            .filter(|(_, n)| *n > 0)
            .collect()
    }
}

/// The computed values the experimental data replaced, kept so that every substituted number
/// can be traced to its namelist and compared with the method's.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Substitution {
    pub data: ExperimentalWingBody,
    pub computed_cd: Vec<Option<f64>>,
    pub computed_cl: Vec<Option<f64>>,
    pub computed_cm: Vec<Option<f64>>,
    /// Per rad.
    pub computed_cla_per_rad: Vec<Option<f64>>,
    pub computed_cma_per_rad: Vec<Option<f64>>,
}
