//! Static lateral-directional derivatives at subsonic speeds: CYβ, Cnβ and Clβ of the original's
//! `BODY ALONE`, `WING ALONE`, `WING-BODY` and tail configuration pages.
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
//! - horizontal tail alone: the wing method on the tail (`horizontal_tail_lateral`);
//! - vertical tail and ventral fin, DATCOM 5.3.1.1 (SUBLAT, tail terms): the panel's lift-curve
//!   slope at its effective aspect ratio in the presence of the body and the horizontal tail,
//!   the sidewash factor and k, with the arms of the panel's MAC; module `vertical_tail`;
//! - configurations: the sum of their components (`sum`), CYβ and Cnβ on the first row.
//!
//! - twin vertical panels ($TVTPAN), DATCOM 5.3.1.1 figures 5.3.1.1-24a to -24c (SUBLAT): added
//!   to the vertical tail's terms on every page with it, below Mach 1; module `twin_panels`;
//!
//! Not covered: the body-horizontal
//! tail terms (the original's BH page), Mach numbers above STMACH, low-aspect-ratio wing-body
//! pages ($LARWB).
//!
//! Axes, signs and units of every output: sideslip β positive nose left (wind from the
//! right); CY positive to the right, Cl positive right wing down, Cn positive nose right; all
//! per radian of sideslip, on the reference area S and, for the moments, the lateral reference
//! length b ($OPTINS BLREF, else the wing's span 2·SSPN).
//!
//! Where this differs from the original, see `docs/lateral.md`.

mod body;
pub mod figures;
mod twin_panels;
mod vertical_tail;
mod wing;
mod wing_body;

use std::fmt;

use serde::Serialize;

use crate::case::Case;
use crate::charts::{ChartWarning, Query};
use crate::methods::wing::WingMethodError;
use crate::results::planform_area_and_mac;

pub use body::body_lateral;
pub use twin_panels::{twin_panel_lateral, twin_panels_counted, TwinPanelLateralTerms};
pub use vertical_tail::{fin_lateral, Fin, FinLateralTerms};
pub use wing::{wing_lateral, DihedralRoll, RollingMomentTerms, WingLateralTerms};
pub use wing_body::{
    exposed_root, wing_body_lateral, wing_body_lateral_at_root, ExposedRoot, WingBodyLateralTerms,
};

/// Why the lateral derivatives cannot be computed.
#[derive(Debug, Clone, PartialEq, thiserror::Error, Serialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
#[non_exhaustive]
pub enum LateralError {
    #[error("the case has no wing ($WGPLNF)")]
    NoWing,
    #[error("no flight condition {index} (a case's conditions are derived from its flight input by Case::prepare)")]
    NoCondition { index: usize },
    #[error("the wing results have {found} angles of attack, the schedule has {expected}")]
    AngleCount { expected: usize, found: usize },
    /// An input the method needs is missing or out of range (the reason names it).
    #[error("incomplete input: {reason}")]
    Geometry { reason: String },
    #[error("no lateral reference length: give BLREF in $OPTINS")]
    NoReferenceSpan,
    #[error("chart {chart} is not embedded or not valid")]
    MissingChart { chart: &'static str },
    #[error(
        "chart {chart} gives no value at {}",
        crate::charts::describe_query(chart, args)
    )]
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
    /// The wing's (or the tail's in its place) height over the body's half width there,
    /// z/(d/2), lies outside figure 5.2.1.1-7's range (−1 to 1, a surface that meets the body):
    /// the height factor of the wing-body CYβ is extrapolated linearly, as in the original.
    WingHeightOutside { ratio: f64, factor: f64 },
    /// The vertical panel's exposed span is not below its span (no body depth at the panel): the
    /// charts of b_v/2r₁ are held at their last nodes (the isolated panel).
    NoBodyAtFin,
    /// $TVTPAN without VPHITE: the panels' trailing-edge angle is taken as 0°.
    NoTrailingEdgeAngle,
    /// A ventral fin in a case without a horizontal tail: its sideslip terms are left out
    /// ([`ventral_fin_left_out`]).
    VentralFinLeftOut,
}

/// Why a ventral fin's sideslip (and so roll and yaw rate) terms are left out of a
/// configuration without a horizontal tail.
pub const VENTRAL_FIN_LEFT_OUT: &str = "the ventral fin's sideslip and roll and yaw rate terms are left out: its sidewash factor comes from the horizontal tail (DATCOM 5.3.1.1 as the original applies it) and the case has none; the original leaves them out too (its drag is counted)";

/// True when the case's ventral fin has no sidewash surface (no horizontal tail): the
/// original computes the fin's sideslip terms from the horizontal tail's planform and, without
/// one, leaves them out of the configuration's totals; so does the build-up here, with
/// [`LateralWarning::VentralFinLeftOut`].
pub fn ventral_fin_left_out(case: &Case) -> bool {
    case.ventral_fin.is_some() && case.horizontal_tail.is_none()
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
            LateralWarning::NoBodyAtFin => write!(
                f,
                "the vertical panel's SSPNE is not below its SSPN (no body depth at the panel): \
                 figures 5.3.1.1-22a and -22d are held at their last nodes"
            ),
            LateralWarning::VentralFinLeftOut => f.write_str(VENTRAL_FIN_LEFT_OUT),
            LateralWarning::NoTrailingEdgeAngle => write!(
                f,
                "$TVTPAN gives no VPHITE: the twin panels' trailing-edge angle is taken as 0 deg (figure 5.3.1.1-24b's 0-deg curve), as the original reads it"
            ),
            LateralWarning::NoBodyWidthAtWing => write!(
                f,
                "SSPNE equals SSPN (no body width at the wing root): no wing-body CYB"
            ),
            LateralWarning::WingHeightOutside { ratio, factor } => write!(
                f,
                "figure 5.2.1.1-7: z/(d/2) = {} is outside the data (-1 to 1, a surface that meets the body; d = 2(SSPN - SSPNE) of the wing, or of the tail in its place): the height factor of CYB, {}, is extrapolated linearly (as in the original)",
                Query(*ratio),
                Query(*factor)
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
    /// The vertical tail's or ventral fin's named terms.
    pub fin_terms: Option<FinLateralTerms>,
    /// The twin vertical panels' named terms.
    pub twin_panel_terms: Option<TwinPanelLateralTerms>,
    pub warnings: Vec<LateralWarning>,
}

impl Lateral {
    /// No sideslip derivatives: CYβ, Cnβ 0 on the first row, Clβ 0 at every angle (a
    /// component that adds nothing, as the original prints zeros for it).
    pub fn zero(alpha_deg: &[f64]) -> Self {
        let (cyb, cnb, clb) = vertical_tail::side_force_rows(alpha_deg, 0.0, 0.0, 0.0, 1.0);
        Lateral {
            alpha_deg: alpha_deg.to_vec(),
            cyb,
            cnb,
            clb,
            wing_terms: None,
            wing_body_terms: None,
            fin_terms: None,
            twin_panel_terms: None,
            warnings: Vec::new(),
        }
    }
}

impl From<WingMethodError> for LateralError {
    fn from(e: WingMethodError) -> Self {
        LateralError::Geometry {
            reason: e.to_string(),
        }
    }
}

/// The horizontal tail alone: the wing method (DATCOM 5.1.2.1) on the tail's planform, section
/// and lift `tail` (as the original's SUBLAT with the tail in the wing's place), on the case's
/// reference area and lateral reference length.
pub fn horizontal_tail_lateral(
    case: &Case,
    condition_index: usize,
    alpha_deg: &[f64],
    tail: &crate::methods::tail::HorizontalTailAlone,
) -> Result<Lateral, LateralError> {
    let mut proxy =
        crate::methods::tail::tail_as_wing(case).map_err(|e| LateralError::Geometry {
            reason: e.to_string(),
        })?;
    proxy.reference.span = body::lateral_reference_span(case);
    // The tail page's moment, with its own "not applicable" rule (M33O41), in Cnβ's centre of
    // pressure.
    wing::surface_lateral(&proxy, condition_index, alpha_deg, &tail.surface, &tail.cm)
}

/// The sum of components' derivatives, as the original forms a configuration's: CYβ and Cnβ
/// on the first row only, Clβ at every row; none where a component has none.
pub fn sum(parts: &[&Lateral]) -> Lateral {
    let first = parts.first();
    let alpha_deg = first.map(|p| p.alpha_deg.clone()).unwrap_or_default();
    let n = alpha_deg.len();
    let total = |f: fn(&Lateral) -> &Vec<Option<f64>>, k: usize| -> Option<f64> {
        parts
            .iter()
            .map(|p| f(p).get(k).copied().flatten())
            .sum::<Option<f64>>()
            .and_then(finite)
    };
    let mut cyb = vec![None; n];
    let mut cnb = vec![None; n];
    if n > 0 {
        cyb[0] = total(|p| &p.cyb, 0);
        cnb[0] = total(|p| &p.cnb, 0);
    }
    Lateral {
        clb: (0..n).map(|k| total(|p| &p.clb, k)).collect(),
        alpha_deg,
        cyb,
        cnb,
        wing_terms: None,
        wing_body_terms: None,
        fin_terms: None,
        twin_panel_terms: None,
        warnings: Vec::new(),
    }
}

/// [`sum`] of owned parts, keeping every part's warnings.
pub fn sum_with_warnings(parts: Vec<Lateral>) -> Lateral {
    let mut total = sum(&parts.iter().collect::<Vec<_>>());
    total.warnings = parts.into_iter().flat_map(|l| l.warnings).collect();
    total
}

/// The lateral reference length b: $OPTINS BLREF, else the wing's span 2·SSPN.
pub fn lateral_reference_length(case: &Case) -> Option<f64> {
    body::lateral_reference_span(case)
}

/// The reference area: $OPTINS SREF, else the wing's theoretical area.
fn reference_area(case: &Case) -> Option<f64> {
    case.reference.area.or_else(|| {
        case.wing
            .as_ref()
            .and_then(planform_area_and_mac)
            .map(|w| w.0)
    })
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
