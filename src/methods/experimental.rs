//! Experimental data of a deck: the namelists `$EXPR01`, `$EXPR02`, ... (nn the 1-based index of
//! the Mach number in $FLTCON), whose values replace computed component data at that Mach
//! number, as Digital DATCOM's experimental-data substitution does (users manual, namelist
//! EXPRnn; the original's routines EXPDAT and EXSUBT).
//!
//! Arrays are by angle-of-attack index of the schedule; an element not given keeps the computed
//! value. Slopes (CLA.., CMA..) are per degree whatever DERIV says, as the original reads them.
//!
//! Which variables are used, and where: `docs/experimental-data.md`. The others are named in
//! the case's warnings by [`unused_variables`].

use crate::case::Case;
use crate::deck::NamelistValues;

/// The body-alone variables (used by `methods::body`).
pub const BODY: [&str; 5] = ["CDB", "CLB", "CMB", "CLAB", "CMAB"];

/// The wing-body variables (used by `methods::wing_body`).
pub const WING_BODY: [&str; 5] = ["CDWB", "CLWB", "CMWB", "CLAWB", "CMAWB"];

/// The namelist of the Mach number of 0-based index `mach_index`: `EXPR01`, ...
pub fn namelist_name(mach_index: usize) -> String {
    format!("EXPR{:02}", mach_index + 1)
}

/// The case's experimental-data namelist for the Mach number of 0-based index `mach_index`,
/// with its name.
pub fn namelist(case: &Case, mach_index: usize) -> Option<(String, &NamelistValues)> {
    let name = namelist_name(mach_index);
    let values = case.other.get(&name)?;
    Some((name, values))
}

/// The values of array `variable` by angle index; empty when not given. A value that is not
/// a number (a case built in code can hold one) is not given.
pub fn column(values: &NamelistValues, variable: &str) -> Vec<Option<f64>> {
    values
        .get(variable)
        .and_then(|v| v.numbers())
        .map(|v| crate::numeric::finite_only(v.to_vec()))
        .unwrap_or_default()
}

/// True when `variable` is one the run substitutes.
pub fn is_used(variable: &str) -> bool {
    BODY.contains(&variable) || WING_BODY.contains(&variable)
}

/// One warning per experimental-data namelist of the case that gives variables the run does
/// not substitute (wing alone, horizontal tail alone, vertical tail, downwash and dynamic
/// pressure, zero-lift and stall angles, transonic fairing data): their values are not used.
pub fn unused_variables(case: &Case) -> Vec<String> {
    case.other
        .iter()
        .filter(|(name, _)| is_experimental_namelist(name))
        .filter_map(|(name, values)| {
            let unused: Vec<&str> = values
                .iter()
                .filter(|(_, v)| v.numbers().is_some_and(|n| n.iter().any(Option::is_some)))
                .map(|(var, _)| var.as_str())
                .filter(|var| !is_used(var))
                .collect();
            (!unused.is_empty()).then(|| {
                format!(
                    "${name}: experimental data {} not used (not yet supported: the computed values are kept)",
                    unused.join(", ")
                )
            })
        })
        .collect()
}

fn is_experimental_namelist(name: &str) -> bool {
    name.strip_prefix("EXPR")
        .is_some_and(|nn| nn.len() == 2 && nn.chars().all(|c| c.is_ascii_digit()))
}

/// `values[j]` replaced by `given[j]` where given; true when any was.
pub fn substitute(values: &mut [Option<f64>], given: &[Option<f64>]) -> bool {
    let mut any = false;
    for (v, g) in values.iter_mut().zip(given) {
        if let Some(g) = g {
            *v = Some(*g);
            any = true;
        }
    }
    any
}

/// One component's experimental values ($EXPRnn) for one Mach number, by angle-of-attack
/// index; `None` where the deck gives no value. `variables` names them (e.g. [`BODY`],
/// [`WING_BODY`]).
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct ComponentData {
    /// The namelist the values come from (`EXPR01`, ...).
    pub namelist: String,
    /// The five variable names, in the order of the fields below.
    pub variables: [&'static str; 5],
    pub cd: Vec<Option<f64>>,
    pub cl: Vec<Option<f64>>,
    pub cm: Vec<Option<f64>>,
    /// Slopes as the deck gives them, per degree.
    pub cla_per_deg: Vec<Option<f64>>,
    pub cma_per_deg: Vec<Option<f64>>,
}

impl ComponentData {
    /// The data of `variables` in `$EXPRnn` for the Mach number of index `mach_index`
    /// (0-based), when the case has that namelist with any of them.
    pub fn of_case(
        case: &Case,
        mach_index: usize,
        variables: [&'static str; 5],
    ) -> Option<ComponentData> {
        let (namelist, values) = namelist(case, mach_index)?;
        let [cd, cl, cm, cla, cma] = variables.map(|v| column(values, v));
        let data = ComponentData {
            namelist,
            variables,
            cd,
            cl,
            cm,
            cla_per_deg: cla,
            cma_per_deg: cma,
        };
        (!data.given().is_empty()).then_some(data)
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

    /// The variables given, each with the number of angles it gives.
    pub fn given(&self) -> Vec<(&'static str, usize)> {
        self.variables
            .iter()
            .zip(self.columns())
            .map(|(name, c)| (*name, c.iter().filter(|v| v.is_some()).count()))
            .filter(|(_, n)| *n > 0)
            .collect()
    }

    /// The original takes the slopes of the first angle from the curves (not from the method's
    /// analytic slopes) when any of the five arrays gives its first element.
    pub fn gives_first_angle(&self) -> bool {
        self.columns()
            .iter()
            .any(|c| c.first().copied().flatten().is_some())
    }
}
