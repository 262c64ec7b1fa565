//! Experimental wing-body data of the deck ($EXPRnn CDWB, CLWB, CMWB, CLAWB, CMAWB): the given
//! values replace the computed ones on the wing-body page and, through it, wherever the
//! wing-body's coefficients enter (the configurations with tails, the wing-body Clβ), as the
//! original does (EXSUBT after WBAERO's lift, drag and moment, and again before the
//! configuration totals).

use serde::Serialize;

use crate::methods::experimental;

/// The wing-body's experimental values ($EXPRnn CDWB, CLWB, CMWB, CLAWB, CMAWB).
pub type ExperimentalWingBody = experimental::ComponentData;

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
