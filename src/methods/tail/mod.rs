//! Downwash at the horizontal tail and the configurations with tails at subsonic speeds: the
//! original's pages WING-BODY-HORIZONTAL TAIL, WING-BODY-VERTICAL TAIL and WING-BODY-VERTICAL
//! TAIL-HORIZONTAL TAIL (CD, CL, CM, CN, CA, XCP, CLA, CMA against angle of attack) and the
//! table ALPHA, Q/QINF, EPSLON, D(EPSLON)/D(ALPHA) printed under them.
//!
//! Methods (DATCOM sections; the original's routines):
//! - downwash and dynamic pressure at the tail, 4.4.1 (DWASH, DYPRLS, INFTGM), module
//!   `downwash`;
//! - the horizontal tail alone, 4.1.3 to 4.1.5 applied to the tail (M16O20, M05O05, M33O41),
//!   and the vertical tail's and ventral fin's zero-lift drag, 4.1.5.1 (VTDRAG, VFDRAG), module
//!   `surfaces`;
//! - the tail in the presence of the body behind the wing, 4.3.1.2, 4.3.1.3 and 4.3.2 applied
//!   to the tail, summed as in 4.5.1 (WBTAIL), module `tail_body`;
//! - canard configurations (downwash method 3: the deck's wing is the canard, its horizontal
//!   tail the main wing), 4.4.1's canard method (WGEOTL, WBTAIL's canard branch), module
//!   `canard`;
//! - the configuration totals (M10O12), here.
//!
//! The wing-body terms are `methods::wing_body`'s, the surfaces' the wing methods'
//! (`methods::wing`). The vertical tail's only longitudinal term is its zero-lift drag, as in
//! the original.
//!
//! Experimental wing-body data ($EXPRnn CDWB, CLWB, CMWB, CLAWB, CMAWB) enter through the
//! wing-body's coefficients (`methods::wing_body`), as in the original.
//!
//! Not covered: experimental
//! downwash and q/q∞ ($EXPRnn EPSLON, DEODA, QOQINF) and tail data, non-straight wings with a tail (the original then
//! prints no configuration totals either), trim pages, Mach numbers above STMACH (transonic
//! and supersonic downwash and tails), the body-horizontal tail and body-vertical tail pages.
//!
//! Axes, signs and units of every output: as `methods::wing_body` (CL normal to the free
//! stream, positive up; CD along it, positive aft; CN, CA in body axes; CM about (XCG, ZCG),
//! positive nose up; on the reference area and length; XCP = CM/CN in reference lengths; CLA,
//! CMA per radian). ε in degrees, positive when the flow at the tail is deflected down;
//! dε/dα and q/q∞ dimensionless. Lengths in metres.
//!
//! Where this differs from the original, see `docs/tail.md`.

mod canard;
mod downwash;
pub mod figures;
mod surfaces;
pub(crate) mod table;
mod tail_body;

use std::fmt;

use serde::Serialize;

use crate::case::Case;
use crate::charts::ChartWarning;
use crate::deck::cards::Surface;
use crate::geometry::{body as body_geometry, planform as planform_geometry, Span};
use crate::methods::body::{subsonic_limit, BodyWarning};
use crate::methods::wing::{WingMethodError, WingType, WingWarning};
use crate::methods::wing_body::{wing_body, WingBody, WingBodyError, WingBodyWarning};

pub(crate) use canard::vortex_inputs;
pub use canard::{canard_vortex, Canard, CanardInputs, CanardVortex, CanardVortexAtAngle};
pub use downwash::{
    downwash_gradient_at_tail, downwash_method, effective_aspect_ratio_ratio,
    empirical_downwash_gradient, tail_placement, wing_wake, Downwash, DownwashMethod,
    DownwashTerms, TailPlacement, VortexSheet, Wake,
};
pub use surfaces::{
    fin_zero_lift_drag, horizontal_tail_alone, low_speed_wing, tail_as_wing, tail_position,
    FinZeroLiftDrag, HorizontalTailAlone, LowSpeedWing, TailSlopeReading,
    TAIL_NOT_APPLICABLE_SLOPE_CHANGE,
};
pub use tail_body::{tail_body, TailAtAngle, TailBody, TailBodyInputs};

use table::{node_slopes, read, End};

/// Why the downwash or the configuration totals cannot be computed.
#[derive(Debug, Clone, PartialEq, thiserror::Error, Serialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
#[non_exhaustive]
pub enum TailError {
    #[error("the case has no wing ($WGPLNF)")]
    NoWing,
    #[error("the case has no body ($BODY)")]
    NoBody,
    #[error("the case has no horizontal tail ($HTPLNF)")]
    NoHorizontalTail,
    #[error("the case has no vertical tail or ventral fin ($VTPLNF, $VFPLNF)")]
    NoVerticalTail,
    #[error("the case has no tail")]
    NoTail,
    #[error("no flight condition {index} (a case's conditions are derived from its flight input by Case::prepare)")]
    NoCondition { index: usize },
    #[error("Mach {} is above the subsonic limit STMACH = {limit}: the subsonic downwash and tail methods do not apply", crate::charts::Query(*mach))]
    NotSubsonic { mach: f64, limit: f64 },
    #[error("the wing is not straight tapered: the original computes no downwash and no configuration totals for it")]
    NotStraightWing,
    #[error("the configuration is a canard (downwash method 3): no downwash table; its effect on the aft surface is in the configuration totals")]
    Canard,
    #[error("no wing maximum lift at low speed (give CLMAXL in $WGSCHR, or an airfoil section): the downwash needs its angle")]
    NoLowSpeedMaxLift,
    #[error("no reference area: give SREF in $OPTINS")]
    NoReferenceArea,
    #[error("geometry: {reason}")]
    Geometry { reason: String },
    #[error("wing-body: {0}")]
    WingBody(WingBodyError),
    #[error("wing: {0}")]
    Wing(WingMethodError),
    #[error("horizontal tail alone: {0}")]
    HorizontalTail(WingMethodError),
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
pub enum TailWarning {
    /// A chart was read outside its data.
    Chart(ChartWarning),
    /// Warnings of the wing methods (on the wing, the tail or a fin).
    Wing(WingWarning),
    /// Warnings of the wing methods on the horizontal tail, in a configuration's warnings
    /// (labelled: they would read as the wing's).
    HorizontalTail(WingWarning),
    /// Warnings of the wing-body methods.
    WingBody(WingBodyWarning),
    /// A fin has no section (no thickness ratio): its zero-lift drag is the skin friction's
    /// alone (t/c = 0), as the original computes it.
    FinDragFrictionOnly { surface: &'static str },
    /// The wing has no zero-lift drag: no q/q∞.
    NoWingZeroLiftDrag,
    /// At this wing angle (deg) the wing's wake leaves ahead of the tail: the distance along
    /// it to the tail, x/c, is below −0.15, where the wake's half-width has no value. No q/q∞
    /// there; the original prints NaN.
    WakeMissesTail { wing_alpha_deg: f64 },
    /// At this wing angle (deg) the wake method gives no q/q∞ (a value that is not finite).
    NoDynamicPressureRatio { wing_alpha_deg: f64 },
    /// The tail has no pitching moment terms (aerodynamic centre, Cm0): no CM with it.
    NoTailMoment,
    /// A double-delta or cranked wing with tails: no downwash, lift, drag or moment of the
    /// configuration (the original prints NDM); the sideslip and rate derivatives are given.
    NoLongitudinalMethod,
}

impl fmt::Display for TailWarning {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            TailWarning::Chart(w) => write!(f, "{w}"),
            TailWarning::Wing(w) => write!(f, "{w}"),
            TailWarning::HorizontalTail(w) => write!(f, "horizontal tail: {w}"),
            TailWarning::WingBody(w) => write!(f, "{w}"),
            TailWarning::FinDragFrictionOnly { surface } => write!(
                f,
                "{surface}: no section (NACA card, coordinates or TOVC): its zero-lift drag is skin friction only (thickness ratio 0, as in the original)"
            ),
            TailWarning::NoWingZeroLiftDrag => {
                write!(f, "the wing has no zero-lift drag: no q/q_inf at the tail")
            }
            TailWarning::NoDynamicPressureRatio { wing_alpha_deg } => write!(
                f,
                "at a wing angle of {wing_alpha_deg} deg the wake method gives no q/q_inf at the horizontal tail: no coefficients with the tail there"
            ),
            TailWarning::WakeMissesTail { wing_alpha_deg } => write!(
                f,
                "at a wing angle of {wing_alpha_deg} deg the wing's wake leaves ahead of the horizontal tail (DATCOM 4.4.1's wake is for a tail behind the wing): no q/q_inf there and no coefficients with the tail (the original prints NaN)"
            ),
            TailWarning::NoLongitudinalMethod => write!(
                f,
                "the wing is not straight tapered: DATCOM's downwash and the configuration's CD, CL, CM, CN, CA, XCP, CLA and CMA with tails are for straight-tapered wings (the original prints NDM); the sideslip and rate derivatives are computed"
            ),
            TailWarning::NoTailMoment => write!(
                f,
                "the horizontal tail has no aerodynamic centre or Cm0: no CM with the tail"
            ),
        }
    }
}

/// The static longitudinal coefficients of one configuration page. `None` where the original
/// prints NA or blank, or a value cannot be computed.
#[derive(Debug, Clone, PartialEq, Serialize, Default)]
pub struct Coefficients {
    pub cd: Vec<Option<f64>>,
    pub cl: Vec<Option<f64>>,
    pub cm: Vec<Option<f64>>,
    pub cn: Vec<Option<f64>>,
    pub ca: Vec<Option<f64>>,
    pub xcp: Vec<Option<f64>>,
    pub cla_per_rad: Vec<Option<f64>>,
    pub cma_per_rad: Vec<Option<f64>>,
}

impl Coefficients {
    /// No value at any of `n` angles (a page without a method).
    pub fn none(n: usize) -> Coefficients {
        let none = || vec![None; n];
        Coefficients {
            cd: none(),
            cl: none(),
            cm: none(),
            cn: none(),
            ca: none(),
            xcp: none(),
            cla_per_rad: none(),
            cma_per_rad: none(),
        }
    }

    /// CD, CL, CM, CLA, CMA given; CN, CA resolved at the schedule angle and XCP = CM/CN.
    pub fn resolved(
        alpha_deg: &[f64],
        cd: Vec<Option<f64>>,
        cl: Vec<Option<f64>>,
        cm: Vec<Option<f64>>,
        cla_per_rad: Vec<Option<f64>>,
        cma_per_rad: Vec<Option<f64>>,
    ) -> Coefficients {
        let finite = crate::numeric::finite_only;
        let (cd, cl, cm) = (finite(cd), finite(cl), finite(cm));
        let alpha_rad: Vec<f64> = alpha_deg.iter().map(|a| a.to_radians()).collect();
        let crate::numeric::BodyAxes { cn, ca, xcp } =
            crate::numeric::body_axes(&alpha_rad, &cl, &cd, &cm);
        Coefficients {
            cd,
            cl,
            cm,
            cn,
            ca,
            xcp,
            cla_per_rad: finite(cla_per_rad),
            cma_per_rad: finite(cma_per_rad),
        }
    }
}

/// The named terms behind the totals.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ConfigurationTerms {
    pub wing_body: WingBody,
    pub horizontal_tail: Option<HorizontalTailAlone>,
    pub downwash: Option<Downwash>,
    /// Canard configurations (downwash method 3): the canard's wake and vortices at the aft
    /// surface, in place of the downwash.
    pub canard: Option<Canard>,
    pub tail_body: Option<TailBody>,
    pub vertical_tail: Option<FinZeroLiftDrag>,
    pub ventral_fin: Option<FinZeroLiftDrag>,
    /// Zero-lift drag of the vertical tail and ventral fin together (0 without either).
    pub fin_drag: f64,
    /// The first CLA and CMA of the wing-body-horizontal tail, per rad, and their terms (the
    /// later ones are slopes of the CL and CM curves).
    pub first_slopes: Option<FirstSlopes>,
}

/// The analytic slopes at the first angle of the wing-body-horizontal tail page.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct FirstSlopes {
    /// CLα_WB + (K_H(B) + K_B(H)) CLα_H (1 − dε/dα) q/q∞.
    pub cla_per_rad: f64,
    /// The wing-body's moment slope resolved about the moment reference (CMα_WB/CLα_WB times
    /// the normal-force slope, less the height of the wing's aerodynamic centre times the
    /// axial-force slope) and the tail's ((x_cg − x_ac,H)/c̄ and (z_H − z_cg)/c̄ times its
    /// normal- and axial-force slopes, times q (1 − dε/dα)).
    pub wing_body_moment: Option<f64>,
    pub tail_moment: Option<f64>,
    pub cma_per_rad: Option<f64>,
}

/// The configuration totals at each angle of attack.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ConfigurationTotals {
    pub reference_area: f64,
    pub reference_length: f64,
    pub alpha_deg: Vec<f64>,
    /// Present when the case has a horizontal tail.
    pub wing_body_horizontal_tail: Option<Coefficients>,
    /// Present when the case has a vertical tail (or ventral fin).
    pub wing_body_vertical_tail: Option<Coefficients>,
    /// Present when the case has both.
    pub wing_body_vertical_tail_horizontal_tail: Option<Coefficients>,
    pub terms: ConfigurationTerms,
    pub warnings: Vec<TailWarning>,
}

fn subsonic_condition(case: &Case, condition_index: usize) -> Result<(), TailError> {
    let condition = case
        .conditions
        .get(condition_index)
        .ok_or(TailError::NoCondition {
            index: condition_index,
        })?;
    let limit = subsonic_limit(case);
    if condition.mach.is_nan() || condition.mach > limit {
        return Err(TailError::NotSubsonic {
            mach: condition.mach,
            limit,
        });
    }
    Ok(())
}

/// The wing-body of a configuration with tails, at a subsonic condition.
fn tail_wing_body(
    case: &Case,
    condition_index: usize,
    alpha_deg: &[f64],
) -> Result<WingBody, TailError> {
    if case.wing.is_none() {
        return Err(TailError::NoWing);
    }
    if case.body.is_none() {
        return Err(TailError::NoBody);
    }
    subsonic_condition(case, condition_index)?;
    wing_body(case, condition_index, alpha_deg).map_err(TailError::WingBody)
}

/// [`tail_wing_body`] with a straight-tapered wing (the downwash methods need one).
fn straight_wing_body(
    case: &Case,
    condition_index: usize,
    alpha_deg: &[f64],
) -> Result<WingBody, TailError> {
    let wb = tail_wing_body(case, condition_index, alpha_deg)?;
    if wb.terms.wing.planform_type != WingType::Straight {
        return Err(TailError::NotStraightWing);
    }
    Ok(wb)
}

/// Downwash ε, its gradient dε/dα and the dynamic-pressure ratio q/q∞ at the horizontal tail
/// at subsonic speed, for flight condition `condition_index` of `case` at the schedule angles
/// `alpha_deg` (degrees): DATCOM 4.4.1.
///
/// - The wing's vortex sheet (DWASH 1): at each angle the local gradient at the tail, equation
///   4.4.1-b with figure 4.4.1-67, at the effective aspect ratio of figure 4.4.1-66 (as the
///   original fits it) is integrated from the wing's zero-lift angle, and the average factor of
///   figure 4.4.1-68b for the tail's height above the rolled-up vortices and its span applied;
///   the sheet's height follows the wing-alone lift (times K_W(B)) and, per figure 4.4.1-68a,
///   leaves from the leading edge when the section's Δy is small. The angle scale is the
///   wing's zero-lift angle and angle of maximum lift at Mach 0 with CLMAXL ([`LowSpeedWing`]).
///   DWASH 2: the empirical gradient of equation 4.4.1-a.
/// - q/q∞: the wing's wake (figures 4.4.1-69 to -71): its centre along the downwash, its
///   half-width and centre loss from the wing's zero-lift drag.
/// - dε/dα: the slope of ε(α), the end chords at the first and last angles.
///
/// Valid for straight-tapered wings with a body, the tail behind the wing, subsonic Mach
/// numbers. Original: DWASH, DYPRLS (and CLMCH0, INFTGM). Errors: no wing, body or tail, a
/// non-straight wing, a canard, no low-speed maximum lift, and the wing-body's errors.
pub fn downwash(
    case: &Case,
    condition_index: usize,
    alpha_deg: &[f64],
) -> Result<Downwash, TailError> {
    let wb = straight_wing_body(case, condition_index, alpha_deg)?;
    let tail = horizontal_tail_alone(case, condition_index, alpha_deg)?;
    downwash::downwash_from(case, alpha_deg, condition_index, &wb, &tail)
}

/// The static longitudinal coefficients of the case's configurations with tails at subsonic
/// speed (see [`ConfigurationTotals`]), for flight condition `condition_index` of `case` at the
/// schedule angles `alpha_deg` (degrees), each a sum of named terms:
///
/// - wing-body-horizontal tail: CD = CD_WB + tail drag; CL = CL_WB + tail lift + vortex lift;
///   CM = CM_WB + the moments of the tail's normal and axial forces + Cm0_H q (see
///   [`TailAtAngle`]); CLA at the first angle analytic ([`FirstSlopes`]), then the slope of
///   CL(α); CMA likewise, up to the first angle where the wing-body's CM is not applicable;
/// - wing-body-vertical tail: the wing-body's with CD + the fins' zero-lift drag;
/// - wing-body-vertical tail-horizontal tail: the wing-body-horizontal tail's with CD + the
///   fins' zero-lift drag.
///
/// CN and CA are resolved at the schedule angle. Original: M10O12, WBTAIL, VTDRAG. Errors: no
/// wing, body or tail, a non-straight wing, and the downwash's and wing-body's.
///
/// Canard configurations (downwash method 3, see [`downwash_method`]): the deck's wing is the
/// canard and its horizontal tail the aft surface; the aft surface works in the canard's wake
/// (q/q∞) without downwash (ε = 0, dε/dα = 0), and the lift the canard's vortices induce on it,
/// ΔCLα α, joins CL, its moment CM, and ΔCLα the first CLA and CMA ([`Canard`], DATCOM 4.4.1's
/// canard method).
pub fn configuration(
    case: &Case,
    condition_index: usize,
    alpha_deg: &[f64],
) -> Result<ConfigurationTotals, TailError> {
    // Twin vertical panels have no longitudinal terms (docs/tail.md): their pages carry the
    // same numbers as without them.
    let has_fin =
        case.vertical_tail.is_some() || case.ventral_fin.is_some() || case.twin_panels.is_some();
    if case.horizontal_tail.is_none() && !has_fin {
        return Err(TailError::NoTail);
    }
    let wb = tail_wing_body(case, condition_index, alpha_deg)?;
    // A double-delta or cranked wing: no downwash method, and the original gives the pages no
    // lift, drag or moment (NDM); their sideslip and rate derivatives are computed.
    let straight = wb.terms.wing.planform_type == WingType::Straight;
    let n = alpha_deg.len();
    // Of the wing-body's warnings, those the configuration's numbers carry without a page of
    // their own: experimental data used, the body's where its numbers are ours because the
    // original's are undefined, and a wing beside the aspect-ratio boundary.
    let mut warnings: Vec<TailWarning> = wb
        .warnings
        .iter()
        .filter(|w| {
            matches!(
                w,
                WingBodyWarning::ExperimentalData { .. }
                    | WingBodyWarning::Body(
                        BodyWarning::BluntNose
                            | BodyWarning::AreaStep { .. }
                            | BodyWarning::ConstantAreaToX0 { .. }
                    )
                    | WingBodyWarning::Wing(WingWarning::NearAspectRatioBoundary { .. })
            )
        })
        .cloned()
        .map(TailWarning::WingBody)
        .collect();
    if !straight {
        warnings.push(TailWarning::NoLongitudinalMethod);
    }

    // Fins.
    let mut fin = |surface: Surface, present: bool| -> Result<Option<FinZeroLiftDrag>, TailError> {
        present
            .then(|| fin_zero_lift_drag(case, condition_index, surface, &mut warnings))
            .transpose()
    };
    let vertical_tail = fin(Surface::VerticalTail, case.vertical_tail.is_some())?;
    let ventral_fin = fin(Surface::VentralFin, case.ventral_fin.is_some())?;
    let fin_drag = vertical_tail.as_ref().map_or(0.0, |d| d.drag.total)
        + ventral_fin.as_ref().map_or(0.0, |d| d.drag.total);
    let with_fins = |cd: &[Option<f64>]| -> Vec<Option<f64>> {
        cd.iter().map(|c| c.map(|c| c + fin_drag)).collect()
    };
    let wing_body_vertical_tail = has_fin.then(|| {
        if !straight {
            return Coefficients::none(n);
        }
        Coefficients::resolved(
            alpha_deg,
            with_fins(&wb.cd),
            wb.cl.clone(),
            wb.cm.clone(),
            wb.cla_per_rad.clone(),
            wb.cma_per_rad.clone(),
        )
    });

    // Horizontal tail.
    let (mut horizontal_tail, mut dw, mut tb, mut first_slopes, mut wbh, mut wbhv) =
        (None, None, None, None, None, None);
    let mut canard_terms = None;
    if case.horizontal_tail.is_some() {
        let tail = horizontal_tail_alone(case, condition_index, alpha_deg)?;
        warnings.extend(
            tail.surface
                .warnings
                .iter()
                .cloned()
                .map(TailWarning::HorizontalTail),
        );
        let method = downwash_method(
            case.sections
                .get("WING")
                .and_then(|u| u.scalars.get("DWASH").copied()),
            wb.terms.wing.terms.planform.semispan,
            tail.surface.terms.planform.semispan,
        );
        if !straight {
            wbh = Some(Coefficients::none(n));
            wbhv = has_fin.then(|| Coefficients::none(n));
        } else {
            let (t, first, page) = if method == DownwashMethod::Canard {
                let mut c =
                    canard::canard(case, condition_index, alpha_deg, &wb, &tail, &mut warnings)?;
                let zeros = vec![Some(0.0); alpha_deg.len()];
                let q = c.dynamic_pressure_ratio.clone();
                let flow = FlowAtTail {
                    dynamic_pressure_ratio: &q,
                    epsilon_deg: &zeros,
                    gradient: &zeros,
                    canard: Some(&mut c),
                };
                let out =
                    wing_body_horizontal_tail(case, alpha_deg, &wb, &tail, flow, &mut warnings)?;
                canard_terms = Some(c);
                out
            } else {
                let d = downwash::downwash_from(case, alpha_deg, condition_index, &wb, &tail)?;
                warnings.extend(d.warnings.iter().cloned());
                let flow = FlowAtTail {
                    dynamic_pressure_ratio: &d.dynamic_pressure_ratio,
                    epsilon_deg: &d.epsilon_deg,
                    gradient: &d.gradient,
                    canard: None,
                };
                let out =
                    wing_body_horizontal_tail(case, alpha_deg, &wb, &tail, flow, &mut warnings)?;
                dw = Some(d);
                out
            };
            if has_fin {
                wbhv = Some(Coefficients::resolved(
                    alpha_deg,
                    with_fins(&page.cd),
                    page.cl.clone(),
                    page.cm.clone(),
                    page.cla_per_rad.clone(),
                    page.cma_per_rad.clone(),
                ));
            }
            tb = Some(t);
            first_slopes = first;
            wbh = Some(page);
        }
        horizontal_tail = Some(tail);
    }
    Ok(ConfigurationTotals {
        reference_area: wb.reference_area,
        reference_length: wb.reference_length,
        alpha_deg: alpha_deg.to_vec(),
        wing_body_horizontal_tail: wbh,
        wing_body_vertical_tail,
        wing_body_vertical_tail_horizontal_tail: wbhv,
        terms: ConfigurationTerms {
            wing_body: wb,
            horizontal_tail,
            downwash: dw,
            canard: canard_terms,
            tail_body: tb,
            vertical_tail,
            ventral_fin,
            fin_drag,
            first_slopes,
        },
        warnings,
    })
}

/// The flow at the horizontal tail: q/q∞, ε (deg), dε/dα, and for a canard configuration its
/// vortex terms (ε and dε/dα then 0; the canard's moments are filled in).
struct FlowAtTail<'a> {
    dynamic_pressure_ratio: &'a [Option<f64>],
    epsilon_deg: &'a [Option<f64>],
    gradient: &'a [Option<f64>],
    canard: Option<&'a mut Canard>,
}

/// The wing-body-horizontal tail page and its terms.
fn wing_body_horizontal_tail(
    case: &Case,
    alpha_deg: &[f64],
    wb: &WingBody,
    tail: &HorizontalTailAlone,
    flow: FlowAtTail,
    warnings: &mut Vec<TailWarning>,
) -> Result<(TailBody, Option<FirstSlopes>, Coefficients), TailError> {
    let n = alpha_deg.len();
    let s = case.synthesis.as_ref();
    let get = |f: fn(&crate::case::Synthesis) -> Option<f64>| s.and_then(f).unwrap_or(0.0);
    let (xcg, zcg, xw, zw, aliw, alih) = (
        get(|s| s.xcg),
        get(|s| s.zcg),
        get(|s| s.xw),
        get(|s| s.zw),
        get(|s| s.aliw_deg),
        get(|s| s.alih_deg),
    );
    let (xh, zh) = tail_position(s);
    let c_ref = wb.reference_length;
    let tp = &tail.surface.terms.planform;
    let tail_plan = case
        .horizontal_tail
        .as_ref()
        .ok_or(TailError::NoHorizontalTail)?;
    let tail_geometry =
        planform_geometry(tail_plan, Span::Both).map_err(|e| TailError::Geometry {
            reason: format!("horizontal tail: {e}"),
        })?;
    let body = case.body.as_ref().ok_or(TailError::NoBody)?;
    let shape = body_geometry(body).map_err(|e| TailError::Geometry {
        reason: format!("body: {e}"),
    })?;
    let tail_moment = tail.surface.terms.pitching_moment.as_ref();
    if tail_moment.is_none() {
        warnings.push(TailWarning::NoTailMoment);
    }
    let body_span = tp.semispan - tp.exposed_semispan;
    let tail_ac = tail_moment.map(|m| {
        xh + body_span * tp.inboard.leading_edge.tan + m.aerodynamic_centre * tp.exposed_root_chord
    });
    let lever = tail_ac.map_or(f64::NAN, |x| (xcg - x) / c_ref);
    let height = (zh - zcg) / c_ref;
    let tail_alpha: Vec<f64> = alpha_deg.iter().map(|a| a + alih).collect();
    let inputs = TailBodyInputs {
        body_semispan_fraction: body_span / tp.semispan,
        tail_alpha_deg: &tail_alpha,
        tail_zero_lift_deg: tail.surface.terms.zero_lift_angle.wing_deg,
        tail_cl: &tail.surface.cl,
        tail_cd: &tail.surface.cd,
        tail_slope_per_rad: tail.slope_per_rad,
        tail_zero_lift_moment: tail_moment.map_or(f64::NAN, |m| m.zero_lift.cm0),
        incidence_deg: alih,
        lever,
        height,
        // From the body's nose (its first station), as for the wing.
        x_quarter_chord: xh + tail_geometry.x_mac_le + tail_geometry.theoretical.mac / 4.0
            - shape.nose(),
        body_radius: (shape.max_area / std::f64::consts::PI).sqrt(),
        semispan: tp.semispan,
        exposed_taper: tp.taper,
    };
    let t = tail_body(
        &inputs,
        alpha_deg,
        flow.dynamic_pressure_ratio,
        flow.epsilon_deg,
        flow.gradient,
        warnings,
    )?;
    let at = &t.at_angle;
    // The canard's vortex lift on the aft surface and its moment (0 without a canard).
    let canard_at: Vec<Option<CanardVortexAtAngle>> = match &flow.canard {
        Some(c) => c.vortex.at_angle.clone(),
        None => vec![None; n],
    };
    let is_canard = flow.canard.is_some();
    let canard_lift = |k: usize| -> Option<f64> {
        if is_canard {
            Some(canard_at[k]?.lift)
        } else {
            Some(0.0)
        }
    };
    let canard_moment: Vec<Option<f64>> = (0..n)
        .map(|k| {
            if is_canard {
                Some(canard_at[k]?.moment(lever, height)).filter(|v| v.is_finite())
            } else {
                Some(0.0)
            }
        })
        .collect();
    let cd: Vec<Option<f64>> = (0..n).map(|k| Some(wb.cd[k]? + at[k]?.drag)).collect();
    let cl: Vec<Option<f64>> = (0..n)
        .map(|k| {
            let a = at[k]?;
            Some(wb.cl[k]? + a.lift + a.vortex_lift + canard_lift(k)?)
        })
        .collect();
    let cm: Vec<Option<f64>> = (0..n)
        .map(|k| {
            let a = at[k]?;
            let v = wb.cm[k]?
                + a.moment_of_normal_force
                + a.moment_of_axial_force
                + a.zero_lift_moment
                + canard_moment[k]?;
            v.is_finite().then_some(v)
        })
        .collect();
    let applicable = wb.cm.iter().position(Option::is_none).unwrap_or(n);
    let alpha_rad: Vec<f64> = alpha_deg.iter().map(|a| a.to_radians()).collect();
    let mut cla = node_slopes(&alpha_rad, &cl);
    let mut cma = node_slopes(&alpha_rad[..applicable], &cm[..applicable]);
    cma.resize(n, None);

    // The first angle: analytic slopes.
    let k_sum = t.interference.wing_in_presence_of_body + t.interference.body_in_presence_of_wing;
    let first = (|| {
        let a = at.first().copied()??;
        // With a canard, its vortex lift slope (over q) joins the aft surface's.
        let (canard_slope, canard_lift0) = if is_canard {
            let c = canard_at.first().copied()??;
            (c.lift_slope_per_rad, c.lift)
        } else {
            (0.0, 0.0)
        };
        let dclda = k_sum * tail.slope_per_rad + canard_slope / a.dynamic_pressure_ratio;
        let cla_wb = wb.cla_per_rad[0]?;
        let cla1 = cla_wb + dclda * (1.0 - a.gradient) * a.dynamic_pressure_ratio;
        let moment = (|| {
            if applicable == 0 {
                return None;
            }
            let cma_wb = wb.cma_per_rad[0]?;
            let (cl_wb, cd_wb) = (wb.cl[0]?, wb.cd[0]?);
            let prefix = wb.cd.iter().position(Option::is_none).unwrap_or(n);
            let dcd = read(
                &alpha_rad[..prefix],
                &wb.cd[..prefix],
                alpha_rad[0],
                End::Hold,
                End::Hold,
            )?
            .1;
            let wing_moment = wb.terms.wing.terms.pitching_moment.as_ref()?;
            let wing_ac =
                wing_moment.aerodynamic_centre * wb.terms.wing.terms.planform.exposed_root_chord;
            let (si_w, ci_w) = aliw.to_radians().sin_cos();
            // XW from the body's nose (its first station), as the original measures it.
            let wing_height =
                (zw - (xw - shape.nose()) * si_w / ci_w - wing_ac * si_w - zcg) / c_ref;
            let (s, c) = alpha_rad[0].sin_cos();
            let wing_body_moment = cma_wb / cla_wb * ((-cl_wb + dcd) * s + (cla_wb + cd_wb) * c)
                - wing_height * ((cla_wb + cd_wb) * s + (cl_wb - dcd) * c);
            let tail_rad: Vec<f64> = tail_alpha.iter().map(|a| a.to_radians()).collect();
            let (cdht, dcdda) = read(
                &tail_rad,
                &tail.surface.cd,
                (tail_alpha[0] - a.epsilon_deg).to_radians(),
                End::Hold,
                End::Hold,
            )?;
            let clht = (a.lift + a.vortex_lift + canard_lift0) / a.dynamic_pressure_ratio;
            let (sa, ca) = (alpha_deg[0] - a.epsilon_deg).to_radians().sin_cos();
            let e = a.dynamic_pressure_ratio * (1.0 - a.gradient);
            let tail_moment = lever * ((-clht + dcdda) * sa + (dclda + cdht) * ca) * e
                - height * ((dclda + cdht) * sa + (clht - dcdda) * ca) * e;
            Some((wing_body_moment, tail_moment))
        })();
        // One angle gives no slope of the drag (NaN): no such term then, rather than one that
        // is not a number (found by fuzzing the library).
        Some(FirstSlopes {
            cla_per_rad: cla1,
            wing_body_moment: moment.map(|m| m.0).filter(|v| v.is_finite()),
            tail_moment: moment.map(|m| m.1).filter(|v| v.is_finite()),
            cma_per_rad: moment.map(|m| m.0 + m.1).filter(|v| v.is_finite()),
        })
    })();
    if n > 0 {
        cla[0] = first.map(|f| f.cla_per_rad);
        cma[0] = first.and_then(|f| f.cma_per_rad);
    }
    if let Some(c) = flow.canard {
        c.moment = canard_moment;
    }
    let page = Coefficients::resolved(alpha_deg, cd, cl, cm, cla, cma);
    Ok((t, first, page))
}
