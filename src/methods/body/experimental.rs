//! Experimental body data of the deck ($EXPRnn, nn the Mach number's index in $FLTCON): the
//! given values replace the computed ones, as in the original (routines EXSUBT and EXPDAT).

use crate::case::Case;
use crate::methods::experimental;

/// The body's experimental values for one Mach number, by angle-of-attack index; `None` where
/// the deck gives no value.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct ExperimentalData {
    /// The namelist the values come from (`EXPR01`, ...).
    pub namelist: String,
    pub cd: Vec<Option<f64>>,
    pub cl: Vec<Option<f64>>,
    pub cm: Vec<Option<f64>>,
    /// Slopes as the deck gives them, per degree.
    pub cla_per_deg: Vec<Option<f64>>,
    pub cma_per_deg: Vec<Option<f64>>,
}

impl ExperimentalData {
    /// The body data of `$EXPRnn` for the Mach number of index `mach_index` (0-based), when the
    /// case has that namelist with any of CDB, CLB, CMB, CLAB, CMAB.
    pub fn of_case(case: &Case, mach_index: usize) -> Option<ExperimentalData> {
        let (namelist, values) = experimental::namelist(case, mach_index)?;
        let [cd, cl, cm, cla, cma] = experimental::BODY;
        let read = |var: &str| experimental::column(values, var);
        let data = ExperimentalData {
            cd: read(cd),
            cl: read(cl),
            cm: read(cm),
            cla_per_deg: read(cla),
            cma_per_deg: read(cma),
            namelist,
        };
        data.any().then_some(data)
    }

    fn columns(&self) -> [&Vec<Option<f64>>; 5] {
        [
            &self.cd,
            &self.cl,
            &self.cm,
            &self.cla_per_deg,
            &self.cma_per_deg,
        ]
    }

    fn any(&self) -> bool {
        self.columns().iter().any(|c| c.iter().any(Option::is_some))
    }

    /// The original takes the slopes of the first angle from the curves (not from the method's
    /// analytic slopes) when any of the five arrays gives its first element.
    pub fn gives_first_angle(&self) -> bool {
        self.columns()
            .iter()
            .any(|c| c.first().copied().flatten().is_some())
    }
}

/// `values[j]` replaced by `given[j]` where given.
pub fn substitute(values: &mut [f64], given: &[Option<f64>]) {
    for (v, g) in values.iter_mut().zip(given) {
        if let Some(g) = g {
            *v = *g;
        }
    }
}
