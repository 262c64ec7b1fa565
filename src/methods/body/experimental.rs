//! Experimental body data of the deck ($EXPRnn, nn the Mach number's index in $FLTCON): the
//! given values replace the computed ones, as in the original (routines EXSUBT and EXPDAT).

use crate::methods::experimental;

/// The body's experimental values ($EXPRnn CDB, CLB, CMB, CLAB, CMAB).
pub type ExperimentalData = experimental::ComponentData;

/// `values[j]` replaced by `given[j]` where given.
pub fn substitute(values: &mut [f64], given: &[Option<f64>]) {
    for (v, g) in values.iter_mut().zip(given) {
        if let Some(g) = g {
            *v = *g;
        }
    }
}
