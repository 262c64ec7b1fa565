//! Wing alone at subsonic speeds: the static longitudinal coefficients of the original's
//! `WING ALONE CONFIGURATION` page (CD, CL, CM, CN, CA, XCP, CLA, CMA against angle of attack).
//!
//! Methods (DATCOM sections; the original's routines):
//! - zero-lift angle, 4.1.3.1 (CALCA0), module `zero_lift_angle`;
//! - lift-curve slope, 4.1.3.2; maximum lift and its angle, 4.1.3.4; the nonlinear lift
//!   curve, 4.1.3.3 (WTLIFT, CLMXBS, LIFTCF), module `lift`;
//! - pitching moment, 4.1.4.1 to 4.1.4.3 (CMALPH), module `pitching_moment`;
//! - zero-lift drag, 4.1.5.1, and drag due to lift, 4.1.5.2 (CDRAG), module `drag`.
//!
//! Planforms: straight tapered (TYPE 1), double delta (TYPE 2) and cranked (TYPE 3), swept
//! back or forward (a forward-swept leading edge at low aspect ratio reads the forward-sweep
//! charts of figure 4.1.4.2-26, the original's FWDXAC). Not covered: curved planforms
//! (TYPE 4), the dashed curves of figure 4.1.3.3-56 (Mach ≥ 0.7 with A < 3),
//! experimental wing data ($EXPR), Mach numbers above STMACH (transonic and supersonic
//! methods).
//!
//! Then, as the original does for the page: CN and CA are resolved from CL and CD at the
//! schedule angle (without the wing incidence ALIW, which every method includes); CLA and CMA
//! are the analytic slopes at the first angle and the slopes of the CL(α) and CM(α) curves at
//! the others (the parabola through the angle and its neighbours, the first or last three at
//! the ends); from the first angle after the first whose CLA differs from the analytic slope by
//! more than 90 %, CM and CMA are not given (the original prints NA), except for
//! low-aspect-ratio straight wings.
//!
//! Axes, signs and units of every output: CL normal to the free stream, positive up; CD along
//! it, positive aft; CN normal to the wing-root chord line of the schedule angle (the body
//! axis), positive up; CA along it, positive aft; CM about the moment reference centre (XCG;
//! ZCG does not enter), positive nose up; all on the reference area S and, for CM, the
//! reference length c̄ ($OPTINS SREF, CBARR, else the wing's theoretical area and MAC).
//! XCP = CM/CN in reference lengths (positive: centre of pressure ahead of XCG). CLA and CMA
//! per radian. Angles in degrees, lengths in metres.
//!
//! Where this differs from the original, see `docs/wing.md`.

mod drag;
pub mod figures;
mod lift;
mod low_speed;
mod pitching_moment;
mod planform;
mod section_inputs;
mod zero_lift_angle;

use crate::numeric::curve_slopes;
use std::fmt;

use serde::Serialize;

use crate::case::Case;
use crate::charts::ChartWarning;
use crate::conditions::FlightCondition;
use crate::deck::cards::Surface;
use crate::geometry::{planform as planform_geometry, Span};
use crate::methods::body::{roughness_height, subsonic_limit};
use crate::methods::section::{section_characteristics, surface_section, SectionCharacteristics};
use crate::results::planform_area_and_mac;

pub use drag::{
    drag_due_to_lift, suction_parameter, wing_zero_lift_drag, DragDueToLift, DragInputs,
    PanelFriction, WingZeroLiftDrag,
};
pub use lift::{
    aspect_ratio_class, helmbold_lift_curve_slope, lift_curve_slope, low_aspect_ratio_max_lift,
    max_lift, panel_lift_curve, straight_lift_curve, AspectRatioClass, LiftAtAngle,
    LiftCurveInputs, LiftCurveSlope, LowAspectRatioFlow, MaxLift, MaxLiftInputs, NonlinearLift,
    PanelLift,
};
pub use low_speed::{mach_zero_wing, MachZeroWing};
pub use pitching_moment::{
    aerodynamic_centre, linear_moment_applies, pitching_moment, zero_lift_moment, CentreInputs,
    ForwardSweepReading, MomentInputs, NonlinearCentre, PitchingMoment, ZeroLiftMoment,
};
pub use planform::{
    quarter_chord_sweep, Chords, ExtendedOutboard, MaxThicknessStations, PanelTerms, Sweep,
    WingPlanform,
};
pub use section_inputs::{
    outboard_defaults, wing_section, OutboardDefaults, OutboardSectionReading, WingSection,
};
pub use zero_lift_angle::{
    twist_term_as_the_original, wing_zero_lift_angle, wing_zero_lift_angle_read, ZeroLiftAngle,
    ZeroLiftReading,
};

/// A CLA that differs from the analytic slope by more than this fraction makes the moment
/// "not applicable" from that angle on (as the original).
const NOT_APPLICABLE_SLOPE_CHANGE: f64 = 0.9;
/// A ≤ this over (C1 + 1) cos Λ_LE: the low-aspect-ratio moment method (DATCOM 4.1.4.3).
pub const NONLINEAR_ASPECT_LIMIT: f64 = 6.0;

/// The planform TYPE of $WGPLNF.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum WingType {
    /// TYPE 1 (or not given): straight tapered.
    Straight,
    /// TYPE 2: double delta.
    DoubleDelta,
    /// TYPE 3: cranked.
    Cranked,
    /// TYPE 4: curved (not covered).
    Curved,
}

impl WingType {
    /// The type of a TYPE value (rounded, as the original); none for a value it cannot use.
    pub fn from_input(t: Option<f64>) -> Option<WingType> {
        let Some(t) = t else {
            return Some(WingType::Straight);
        };
        if !t.is_finite() {
            return None;
        }
        match (t + 0.5).floor() {
            x if x >= 5.0 => Some(WingType::Straight),
            x => match x as i64 {
                1 => Some(WingType::Straight),
                2 => Some(WingType::DoubleDelta),
                3 => Some(WingType::Cranked),
                4 => Some(WingType::Curved),
                _ => None,
            },
        }
    }
}

/// Why the wing-alone coefficients cannot be computed.
#[derive(Debug, Clone, PartialEq, thiserror::Error, Serialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
#[non_exhaustive]
pub enum WingMethodError {
    #[error("the case has no wing ($WGPLNF)")]
    NoWing,
    #[error("no flight condition {index} (a case's conditions are derived from its flight input by Case::prepare)")]
    NoCondition { index: usize },
    #[error("Mach {} is above the subsonic limit STMACH = {limit}: the subsonic wing methods do not apply (transonic and supersonic wing methods are not implemented)", crate::charts::Query(*mach))]
    NotSubsonic { mach: f64, limit: f64 },
    #[error("the case is a low-aspect-ratio wing-body ($LARWB): the original computes no wing-alone page for it")]
    LowAspectRatioWingBody,
    #[error("wing planform: {reason}")]
    Geometry { reason: String },
    #[error(
        "planform TYPE {value} is not 1 (straight), 2 (double delta), 3 (cranked) or 4 (curved)"
    )]
    UnknownType { value: f64 },
    #[error("curved planforms (TYPE 4) are not covered")]
    CurvedPlanform,
    #[error(
        "no section lift-curve slope at Mach {mach}: give CLALPA in the surface's section namelist ($WGSCHR, $HTSCHR, ...) or a NACA card"
    )]
    NoSectionLiftCurveSlope { mach: f64 },
    #[error("the wing section cannot be computed: {reason}")]
    Section { reason: String },
    #[error("no reference area: give SREF in $OPTINS")]
    NoReferenceArea,
    #[error("no reference length: give CBARR in $OPTINS")]
    NoReferenceLength,
    #[error("angle of attack {alpha_deg} is not a number")]
    Angle { alpha_deg: f64 },
    #[error("skin friction: {reason}")]
    SkinFriction { reason: String },
    #[error("the wing cannot be computed: {reason}")]
    Degenerate { reason: String },
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
pub enum WingWarning {
    /// A chart was read outside its data.
    Chart(ChartWarning),
    /// A section value is neither given nor computed.
    SectionValueMissing { name: &'static str },
    /// A high-aspect-ratio wing without section CLMAX: no CLmax, and so no nonlinear lift.
    NoSectionMaxLift,
    /// The maximum lift is not positive, or its angle not above the zero-lift angle: the
    /// nonlinear lift curve would divide by zero; only the lift-curve slope is given.
    NoStallAboveZeroLift { reason: String },
    /// A cambered section without thickness ratio: no Mach correction of α0.
    NoCamberMachCorrection,
    /// The dashed curves of figure 4.1.3.3-56 would apply; the solid ones were used.
    DashedCurvesNotCovered,
    /// CM and CMA are not applicable from this angle on (the original prints NA).
    MomentNotApplicable { alpha_deg: f64 },
    /// The zero-lift drag cannot be computed (no thickness ratio, or no Reynolds number):
    /// no CD, CN, CA.
    NoDrag { reason: String },
    /// The wing section's own warnings.
    Section { message: String },
    /// The aspect ratio lies within 2 % of DATCOM's boundary between its high- and
    /// low-aspect-ratio methods: maximum lift, the lift beyond the linear range and the
    /// pitching moment change in a step across it.
    NearAspectRatioBoundary { aspect_ratio: f64, boundary: f64 },
}

impl fmt::Display for WingWarning {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            WingWarning::Chart(w) => write!(f, "{w}"),
            WingWarning::SectionValueMissing { name } => write!(
                f,
                "wing section {name} is neither given in $WGSCHR nor computed from a section"
            ),
            WingWarning::NoSectionMaxLift => write!(
                f,
                "no section CLMAX for this Mach number: no wing CLmax, and no CL, CD, CM beyond the lift-curve slope"
            ),
            WingWarning::NoStallAboveZeroLift { reason } => write!(
                f,
                "{reason}: no CL, CD, CM beyond the lift-curve slope"
            ),
            WingWarning::NearAspectRatioBoundary {
                aspect_ratio,
                boundary,
            } => write!(
                f,
                "the aspect ratio {aspect_ratio:.4} lies near DATCOM's boundary between its high- and low-aspect-ratio methods, ARCL/((C1 + 1) cos LE sweep) = {boundary:.4} (4.1.3.4): maximum lift, the lift beyond the linear range and the pitching moment change in a step across it"
            ),
            WingWarning::NoCamberMachCorrection => write!(
                f,
                "cambered section without TOVC: the zero-lift angle is not corrected for Mach number"
            ),
            WingWarning::DashedCurvesNotCovered => write!(
                f,
                "figure 4.1.3.3-56: the dashed curves apply (M >= 0.7, A < 3) and are not covered; the solid curves are used"
            ),
            WingWarning::MomentNotApplicable { alpha_deg } => write!(
                f,
                "CM and CMA not applicable from alpha = {alpha_deg} deg (CLA departs from the lift-curve slope by more than 90 %)"
            ),
            WingWarning::NoDrag { reason } => write!(f, "no drag: {reason}"),
            WingWarning::Section { message } => write!(f, "section: {message}"),
        }
    }
}

/// The named terms behind the coefficients.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct WingTerms {
    pub planform: WingPlanform,
    pub section: WingSection,
    pub aspect_ratio_class: AspectRatioClass,
    pub zero_lift_angle: ZeroLiftAngle,
    pub lift_curve_slope: LiftCurveSlope,
    pub max_lift: MaxLift,
    /// Straight-tapered nonlinear lift terms.
    pub nonlinear_lift: Option<NonlinearLift>,
    /// Double-delta and cranked lift terms.
    pub panel_lift: Option<PanelLift>,
    /// Lift at each wing angle (schedule angle + ALIW).
    pub lift: Vec<LiftAtAngle>,
    pub zero_lift_drag: Option<WingZeroLiftDrag>,
    pub drag_due_to_lift: Option<DragDueToLift>,
    pub pitching_moment: Option<PitchingMoment>,
}

/// The wing-alone coefficients at each angle of attack. `None` where a value cannot be
/// computed or the method does not apply (the original's NA).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct WingAlone {
    pub planform_type: WingType,
    /// Reference area, m², and length, m.
    pub reference_area: f64,
    pub reference_length: f64,
    /// Wing incidence ALIW, deg, added to every schedule angle in the methods.
    pub incidence_deg: f64,
    pub alpha_deg: Vec<f64>,
    pub cd: Vec<Option<f64>>,
    pub cl: Vec<Option<f64>>,
    pub cm: Vec<Option<f64>>,
    pub cn: Vec<Option<f64>>,
    pub ca: Vec<Option<f64>>,
    pub xcp: Vec<Option<f64>>,
    pub cla_per_rad: Vec<Option<f64>>,
    pub cma_per_rad: Vec<Option<f64>>,
    pub terms: WingTerms,
    pub warnings: Vec<WingWarning>,
}

/// The wing section characteristics of `case` by the section method (DATCOM 4.1.1), when the
/// case gives an airfoil (a NACA card or $WGSCHR coordinates); `None` otherwise.
pub fn computed_wing_section(
    case: &Case,
) -> Option<Result<SectionCharacteristics, WingMethodError>> {
    let s = surface_section(case, Surface::Wing)?;
    Some(
        s.map_err(|e| match e {
            // The section's chord and Reynolds number come from the planform: a planform
            // that cannot give them is the planform's error.
            crate::methods::section::SurfaceSectionError::Planform(g) => {
                WingMethodError::Geometry {
                    reason: g.to_string(),
                }
            }
            e => WingMethodError::Section {
                reason: e.to_string(),
            },
        })
        .and_then(|s| {
            section_characteristics(&s.shape, &s.conditions, &s.overrides).map_err(|e| {
                WingMethodError::Section {
                    reason: e.to_string(),
                }
            })
        }),
    )
}

/// The static longitudinal coefficients of the wing alone at subsonic speed, for flight
/// condition `condition_index` of `case` at the schedule angles `alpha_deg` (degrees).
///
/// The section characteristics are the user's $WGSCHR values where given, else those the
/// section method computes from the case's airfoil (see [`computed_wing_section`]; computed at
/// the condition's flight Reynolds number). Reference area and length: $OPTINS, else the
/// wing's theoretical area and MAC. Moment reference: $SYNTHS XCG (0 when not given), the wing
/// at XW (0 when not given) with incidence ALIW. Roughness: $OPTINS ROUGFC or 1.6E-4 in. See
/// the module documentation for axes, signs and units.
///
/// Errors: no wing, a Mach number above STMACH, $LARWB, a planform the methods do not cover,
/// no section lift-curve slope, no reference dimensions.
pub fn wing_alone(
    case: &Case,
    condition_index: usize,
    alpha_deg: &[f64],
) -> Result<WingAlone, WingMethodError> {
    let computed = computed_wing_section(case).transpose()?;
    wing_alone_with_section(case, condition_index, alpha_deg, computed.as_ref())
}

/// [`wing_alone`] with the section method's characteristics given (e.g. computed with other
/// options, or none to use only the user's $WGSCHR values).
pub fn wing_alone_with_section(
    case: &Case,
    condition_index: usize,
    alpha_deg: &[f64],
    computed: Option<&SectionCharacteristics>,
) -> Result<WingAlone, WingMethodError> {
    wing_alone_parts(case, condition_index, alpha_deg, computed, Parts::All)
}

/// What a wing-alone computation produces.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Parts {
    /// Lift, drag and pitching moment.
    All,
    /// The lift curve and its terms only: no drag, no pitching moment (their columns none).
    /// The wing at Mach 0 is used for its lift alone ([`mach_zero_wing`]).
    Lift,
}

pub(crate) fn wing_alone_parts(
    case: &Case,
    condition_index: usize,
    alpha_deg: &[f64],
    computed: Option<&SectionCharacteristics>,
    parts: Parts,
) -> Result<WingAlone, WingMethodError> {
    let plan = case.wing.as_ref().ok_or(WingMethodError::NoWing)?;
    if case.larwb.is_some() {
        return Err(WingMethodError::LowAspectRatioWingBody);
    }
    let condition: &FlightCondition =
        case.conditions
            .get(condition_index)
            .ok_or(WingMethodError::NoCondition {
                index: condition_index,
            })?;
    let limit = subsonic_limit(case);
    if condition.mach.is_nan() || condition.mach > limit {
        return Err(WingMethodError::NotSubsonic {
            mach: condition.mach,
            limit,
        });
    }
    if let Some(&a) = alpha_deg.iter().find(|a| !a.is_finite()) {
        return Err(WingMethodError::Angle { alpha_deg: a });
    }
    let kind = WingType::from_input(plan.planform_type).ok_or(WingMethodError::UnknownType {
        value: plan.planform_type.unwrap_or(f64::NAN),
    })?;
    if kind == WingType::Curved {
        return Err(WingMethodError::CurvedPlanform);
    }
    let geometry = planform_geometry(plan, Span::Both).map_err(|e| WingMethodError::Geometry {
        reason: e.to_string(),
    })?;
    if kind != WingType::Straight && geometry.outboard.is_none() {
        return Err(WingMethodError::Geometry {
            reason: "a double-delta or cranked wing needs SSPNOP and CHRDBP".into(),
        });
    }
    let theoretical = planform_area_and_mac(plan);
    let reference_area = case
        .reference
        .area
        .or(theoretical.map(|t| t.0))
        .filter(|a| *a > 0.0 && a.is_finite())
        .ok_or(WingMethodError::NoReferenceArea)?;
    let reference_length = case
        .reference
        .chord
        .or(theoretical.map(|t| t.1))
        .filter(|c| *c > 0.0 && c.is_finite())
        .ok_or(WingMethodError::NoReferenceLength)?;

    let mut warnings = Vec::new();
    if let Some(c) = computed {
        for w in &c.warnings {
            warnings.push(WingWarning::Section {
                message: w.to_string(),
            });
        }
    }
    let section = wing_section(case, condition_index, computed, &mut warnings)?;
    let p = WingPlanform::new(
        &geometry,
        Chords {
            tip: plan.chrdtp.unwrap_or(0.0),
            at_break: plan.chrdbp.unwrap_or(0.0),
        },
        MaxThicknessStations {
            inboard: section.max_thickness_x,
            outboard: section.outboard_max_thickness_x,
        },
    );
    let synthesis = case.synthesis.as_ref();
    let incidence_deg = synthesis.and_then(|s| s.aliw_deg).unwrap_or(0.0);
    let twist_deg = plan.twista_deg.unwrap_or(0.0);
    let mach = condition.mach;
    let beta = (1.0 - mach * mach).abs().sqrt();
    let wing_alpha: Vec<f64> = alpha_deg.iter().map(|a| a + incidence_deg).collect();

    let zero_lift_angle = wing_zero_lift_angle_read(
        &p,
        section.zero_lift_alpha_deg,
        twist_deg,
        section.cambered,
        section.thickness_ratio,
        mach,
        case.zero_lift,
        &mut warnings,
    )?;
    let class = aspect_ratio_class(&p, section.arcl, &mut warnings)?;
    let slope = lift_curve_slope(
        &p,
        kind,
        section.lift_curve_slope_per_rad,
        beta,
        reference_area,
        &mut warnings,
    )?;
    let delta_y = section.delta_y_percent.unwrap_or(0.0);
    let maximum = max_lift(
        &p,
        &class,
        &MaxLiftInputs {
            section_max_lift: section.max_lift,
            delta_y_percent: delta_y,
            max_thickness_x: section.max_thickness_x,
            mach,
            beta,
            reference_area,
            lift_curve_slope_per_rad: slope.per_rad,
            zero_lift_alpha_deg: zero_lift_angle.wing_deg,
        },
        &mut warnings,
    )?;
    let lift_inputs = LiftCurveInputs {
        planform: &p,
        kind,
        class: &class,
        slope: &slope,
        max_lift: &maximum,
        zero_lift_alpha_deg: zero_lift_angle.wing_deg,
        beta,
        reference_area,
        delta_y_percent: delta_y,
        max_thickness_x: section.max_thickness_x,
        mach,
    };
    let (nonlinear_lift, panel_lift, lift) = if kind == WingType::Straight {
        match straight_lift_curve(&lift_inputs, &wing_alpha, &mut warnings)? {
            Some((n, l)) => (Some(n), None, l),
            None => (None, None, Vec::new()),
        }
    } else {
        let (pl, l) = panel_lift_curve(&lift_inputs, &wing_alpha, &mut warnings)?;
        (None, Some(pl), l)
    };
    let cl: Vec<f64> = lift.iter().map(|l| l.cl).collect();

    // Drag.
    let drag_inputs = section.thickness_ratio.map(|t| DragInputs {
        planform: &p,
        kind,
        mach,
        beta,
        reynolds_per_length: condition.reynolds_per_length,
        roughness: roughness_height(case),
        reference_area,
        thickness_ratio: t,
        max_thickness_x: section.max_thickness_x,
        outboard_thickness_ratio: section.outboard_thickness_ratio.unwrap_or(t),
        outboard_max_thickness_x: section.outboard_max_thickness_x,
        leading_edge_radius: section.leading_edge_radius.unwrap_or(0.0),
        outboard_leading_edge_radius: section.outboard_leading_edge_radius.unwrap_or(0.0),
        twist_deg,
    });
    let (zero_lift_drag, lift_drag) = match &drag_inputs {
        _ if parts == Parts::Lift => (None, None),
        None => {
            warnings.push(WingWarning::NoDrag {
                reason: "no section thickness ratio (TOVC)".into(),
            });
            (None, None)
        }
        Some(_)
            if condition.reynolds_per_length.is_nan() || condition.reynolds_per_length <= 0.0 =>
        {
            warnings.push(WingWarning::NoDrag {
                reason: format!(
                    "the Reynolds number per length is {}",
                    condition.reynolds_per_length
                ),
            });
            (None, None)
        }
        Some(d) => {
            let body_span_ratio = case
                .body
                .as_ref()
                .map(|_| (p.semispan - p.exposed_semispan) / p.semispan);
            let zero = wing_zero_lift_drag(d, &mut warnings)?;
            let induced = drag_due_to_lift(
                d,
                slope.per_rad,
                &cl,
                &wing_alpha,
                body_span_ratio,
                &mut warnings,
            )?;
            (Some(zero), Some(induced))
        }
    };

    // Pitching moment.
    let xw = synthesis.and_then(|s| s.xw).unwrap_or(0.0);
    let xcg = synthesis.and_then(|s| s.xcg).unwrap_or(0.0);
    let root_le = xw
        + (p.semispan - p.exposed_semispan)
            * p.inboard.leading_edge.tan
            * incidence_deg.to_radians().cos();
    let moment_reference = (xcg - root_le) / p.exposed_root_chord;
    let (moment, cma_first) = if parts == Parts::Lift {
        (None, None)
    } else {
        let zero_lift = zero_lift_moment(
            &p,
            section.cm0,
            twist_deg,
            mach,
            reference_area,
            reference_length,
            &mut warnings,
        )?;
        let low_ar_centre = class.low_aspect_ratio;
        let xac = aerodynamic_centre(
            &CentreInputs {
                planform: &p,
                kind,
                low_aspect_ratio: low_ar_centre,
                section_xac: section.aerodynamic_centre,
                beta,
                panel_slopes: (slope.inboard_panel_per_rad, slope.extended_outboard_per_rad),
                reading: case.forward_sweep,
            },
            &mut warnings,
        )?;
        let moment = pitching_moment(
            &MomentInputs {
                planform: &p,
                kind,
                c1_cos_le: class.c1_cos_le,
                zero_lift,
                aerodynamic_centre: xac,
                moment_reference,
                reference_length,
                alpha_max_lift_deg: maximum.alpha_deg,
                delta_y_percent: delta_y,
            },
            &lift,
            &mut warnings,
        )?;
        let cma_first = moment.as_ref().map_or(
            (moment_reference - xac) * p.exposed_root_chord / reference_length * slope.per_rad,
            |m| m.dcm_dcl * slope.per_rad,
        );
        (moment, Some(cma_first))
    };

    // The page.
    let n = alpha_deg.len();
    let have_lift = lift.len() == n;
    let cd: Vec<Option<f64>> = (0..n)
        .map(|k| match (&zero_lift_drag, &lift_drag) {
            (Some(z), Some(l)) if have_lift => Some(z.total + l.cd[k]),
            _ => None,
        })
        .collect();
    let cl_page: Vec<Option<f64>> = (0..n).map(|k| have_lift.then(|| cl[k])).collect();
    let mut cm: Vec<Option<f64>> = (0..n)
        .map(|k| moment.as_ref().filter(|_| have_lift).map(|m| m.cm[k]))
        .collect();
    let alpha_rad: Vec<f64> = alpha_deg.iter().map(|a| a.to_radians()).collect();
    let mut cla = curve_slopes(&alpha_rad, &cl_page);
    let mut cma = curve_slopes(&alpha_rad, &cm);
    if n > 0 {
        cla[0] = Some(slope.per_rad);
        cma[0] = cma_first;
    }
    // The original leaves low-aspect-ratio straight wings out of the NA rule.
    let low_aspect_straight =
        kind == WingType::Straight && p.aspect_ratio <= NONLINEAR_ASPECT_LIMIT / class.c1_cos_le;
    let na_rule = !low_aspect_straight;
    if na_rule {
        if let Some(from) = (1..n).find(|&k| {
            cla[k].is_some_and(|s| (s / slope.per_rad - 1.0).abs() > NOT_APPLICABLE_SLOPE_CHANGE)
        }) {
            for k in from..n {
                cm[k] = None;
                cma[k] = None;
            }
            warnings.push(WingWarning::MomentNotApplicable {
                alpha_deg: alpha_deg[from],
            });
        }
    }
    let crate::numeric::BodyAxes { cn, ca, xcp } =
        crate::numeric::body_axes(&alpha_rad, &cl_page, &cd, &cm);
    let finite = crate::numeric::finite_only;
    Ok(WingAlone {
        planform_type: kind,
        reference_area,
        reference_length,
        incidence_deg,
        alpha_deg: alpha_deg.to_vec(),
        cd: finite(cd),
        cl: finite(cl_page),
        cm: finite(cm),
        cn,
        ca,
        xcp,
        cla_per_rad: finite(cla),
        cma_per_rad: finite(cma),
        terms: WingTerms {
            planform: p,
            section,
            aspect_ratio_class: class,
            zero_lift_angle,
            lift_curve_slope: slope,
            max_lift: maximum,
            nonlinear_lift,
            panel_lift,
            lift,
            zero_lift_drag,
            drag_due_to_lift: lift_drag,
            pitching_moment: moment,
        },
        warnings,
    })
}
