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

/// The values of array `variable` by angle index; empty when not given.
pub fn column(values: &NamelistValues, variable: &str) -> Vec<Option<f64>> {
    values
        .get(variable)
        .and_then(|v| v.numbers())
        .map(<[Option<f64>]>::to_vec)
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
