//! Static lateral-directional derivatives at subsonic speeds: CYβ, Cnβ and Clβ of the original's
//! `BODY ALONE` and `WING ALONE CONFIGURATION` pages.
//!
//! Methods (DATCOM sections; the original's routines):
//! - body alone, DATCOM 5.2.1.1 as the original codes it (M04O04, M06O06): the side force and
//!   yawing moment follow from the body's lift and pitching-moment slopes, no rolling moment;
//!   module `body`;
//! - wing alone, DATCOM 5.1.2.1 (SUBLAT): Clβ from sweep, aspect ratio, taper, twist, dihedral
//!   and compressibility; CYβ and Cnβ from the wing's lift (the original's wing terms of
//!   SUBLAT with the Mach-0 lift of CLMCH0); module `wing`.
//!
//! - wing-body, DATCOM 5.2.2.1 (CYβ, Clβ) and 5.2.3.1 (Cnβ) (SUBLAT, wing-body terms): the
//!   body's side force with the wing-height factor, the body's yawing moment with K_N, and the
//!   wing's Clβ terms with K_f, wing height and body diameter; module `wing_body`.
//!
//! Not covered: tail and total configurations (5.3.1.x), Mach
//! numbers above STMACH, low-aspect-ratio wing-body pages ($LARWB).
//!
//! Axes, signs and units of every output: sideslip β positive nose left (wind from the
//! right); CY positive to the right, Cl positive right wing down, Cn positive nose right; all
//! per radian of sideslip, on the reference area S and, for the moments, the lateral reference
//! length b ($OPTINS BLREF, else the wing's span 2·SSPN).
//!
//! Where this differs from the original, see `docs/lateral.md`.

mod body;
pub mod figures;
mod wing;
mod wing_body;

use std::fmt;

use serde::Serialize;

use crate::case::Case;
use crate::charts::ChartWarning;
use crate::methods::wing::WingMethodError;
use crate::results::planform_area_and_mac;

pub use body::body_lateral;
pub use wing::{wing_lateral, DihedralRoll, RollingMomentTerms, WingLateralTerms};
pub use wing_body::{wing_body_lateral, WingBodyLateralTerms};

/// Why the lateral derivatives cannot be computed.
#[derive(Debug, Clone, PartialEq, thiserror::Error, Serialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
#[non_exhaustive]
pub enum LateralError {
    #[error("the case has no wing ($WGPLNF)")]
    NoWing,
    #[error("no flight condition {index}")]
    NoCondition { index: usize },
    #[error("the wing results have {found} angles of attack, the schedule has {expected}")]
    AngleCount { expected: usize, found: usize },
    #[error("the wing planform is incomplete: {reason}")]
    Geometry { reason: String },
    #[error("no lateral reference length: give BLREF in $OPTINS")]
    NoReferenceSpan,
    #[error("chart {chart} is not embedded or not valid")]
    MissingChart { chart: &'static str },
    #[error("chart {chart} gives no value at {args:?}")]
    ChartNoValue { chart: &'static str, args: Vec<f64> },
}

/// What the caller should know about a result.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
#[non_exhaustive]
pub enum LateralWarning {
    /// A chart was read outside its data.
    Chart(ChartWarning),
    /// No lateral reference length (BLREF, or a wing's span): no Cnβ, Clβ.
    NoReferenceSpan,
    /// The wing lift at Mach 0 (the CYβ term) cannot be computed: no CYβ.
    NoMachZeroLift { reason: String },
    /// The exposed semispan equals the semispan (no body width at the wing root): the wing
    /// height factor of the wing-body CYβ is undefined, no wing-body CYβ.
    NoBodyWidthAtWing,
}

impl fmt::Display for LateralWarning {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            LateralWarning::Chart(w) => write!(f, "{w}"),
            LateralWarning::NoReferenceSpan => write!(
                f,
                "no lateral reference length (BLREF or a wing span): no CNB, CLB"
            ),
            LateralWarning::NoMachZeroLift { reason } => {
                write!(f, "no wing lift at Mach 0, so no wing CYB: {reason}")
            }
            LateralWarning::NoBodyWidthAtWing => write!(
                f,
                "SSPNE equals SSPN (no body width at the wing root): no wing-body CYB"
            ),
        }
    }
}

/// The static lateral-directional derivatives at each angle of attack of the schedule, per
/// radian of sideslip. `None` where a value cannot be computed or the method does not apply.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Lateral {
    pub alpha_deg: Vec<f64>,
    /// Side-force derivative CYβ, per radian.
    pub cyb: Vec<Option<f64>>,
    /// Yawing-moment derivative Cnβ, per radian.
    pub cnb: Vec<Option<f64>>,
    /// Rolling-moment derivative Clβ, per radian.
    pub clb: Vec<Option<f64>>,
    /// The wing method's named terms (none for the body).
    pub wing_terms: Option<WingLateralTerms>,
    /// The wing-body method's named terms (wing-body page only).
    pub wing_body_terms: Option<WingBodyLateralTerms>,
    pub warnings: Vec<LateralWarning>,
}

impl From<WingMethodError> for LateralError {
    fn from(e: WingMethodError) -> Self {
        LateralError::Geometry {
            reason: e.to_string(),
        }
    }
}

/// A finite value, else none.
fn finite(v: f64) -> Option<f64> {
    v.is_finite().then_some(v)
}

/// The checked wing inputs every wing method here starts from (SI lengths): the flight
/// condition, the semispan SSPN, root and tip chords, exposed semispan SSPNE and the
/// theoretical area.
pub(crate) struct WingInputs<'a> {
    pub plan: &'a crate::case::Planform,
    pub condition: &'a crate::conditions::FlightCondition,
    pub semispan: f64,
    pub root: f64,
    pub tip: f64,
    pub exposed_semispan: f64,
    pub area: f64,
}

/// Reads and checks the wing inputs for flight condition `condition_index`, with `rows` the
/// number of rows of the lift results the derivatives are built on, which must match the
/// `angles` of the schedule.
pub(crate) fn wing_inputs(
    case: &Case,
    condition_index: usize,
    angles: usize,
    rows: usize,
) -> Result<WingInputs<'_>, LateralError> {
    let plan = case.wing.as_ref().ok_or(LateralError::NoWing)?;
    let condition = case
        .conditions
        .get(condition_index)
        .ok_or(LateralError::NoCondition {
            index: condition_index,
        })?;
    if rows != angles {
        return Err(LateralError::AngleCount {
            expected: angles,
            found: rows,
        });
    }
    let missing = |what: &str| LateralError::Geometry {
        reason: format!("{what} is not given"),
    };
    let semispan = plan.sspn.ok_or_else(|| missing("SSPN"))?;
    let root = plan.chrdr.ok_or_else(|| missing("CHRDR"))?;
    let exposed_semispan = plan.sspne.unwrap_or(semispan);
    let (area, _) = planform_area_and_mac(plan).ok_or_else(|| missing("the planform"))?;
    if !(semispan > 0.0 && root > 0.0 && area > 0.0 && exposed_semispan > 0.0) {
        return Err(LateralError::Geometry {
            reason: "SSPN, SSPNE, CHRDR and the area must be positive".into(),
        });
    }
    Ok(WingInputs {
        plan,
        condition,
        semispan,
        root,
        tip: plan.chrdtp.unwrap_or(0.0),
        exposed_semispan,
        area,
    })
}
