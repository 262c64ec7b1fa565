//! Wing-body combination at subsonic speeds: the static longitudinal coefficients of the
//! original's `WING-BODY CONFIGURATION` page (CD, CL, CM, CN, CA, XCP, CLA, CMA against angle of
//! attack) and its auxiliary values CLA-B(W), CLA-W(B), K-B(W), K-W(B), XAC/C-B(W).
//!
//! Methods (DATCOM sections; the original's routines):
//! - lift, 4.3.1.2 with the interference factors K_W(B), K_B(W), k_W(B), k_B(W) of slender-body
//!   theory, and the lift the body vortices take from the wing, 4.3.1.3 (WBLIFT, BODOWG, ALI),
//!   module `lift`;
//! - drag, 4.3.3.1 with the interference factor R_WB (WBDRAG), and for straight wings the
//!   original's regression of the drag due to lift (WBCD, WBCDL, TABLES), module `drag`;
//! - pitching moment, 4.3.2.1 with the aerodynamic centre of the carry-over lift, 4.3.2.2
//!   (WBCM), module `moment`.
//!
//! They are built on the body alone (`methods::body`) and the wing alone (`methods::wing`),
//! whose tables they read. Then, as the original does for the page (WBAERO): CLA is the slope
//! of the CL(α) curve at every angle, CMA that of CM(α) up to the first angle where the wing's
//! moment is not applicable (none from there on); CN and CA are resolved from CL and CD at
//! the schedule angle.
//!
//! Experimental data of the deck ($EXPRnn CDWB, CLWB, CMWB) replace the computed CD, CL, CM
//! before the slopes are taken, and CLAWB, CMAWB the slopes where given, as the original does
//! (EXSUBT); the computed values stay in the terms (module `experimental`,
//! docs/experimental-data.md).
//!
//! Not covered: d/b > 0.8 (figure 4.3.1.2-12c), Mach numbers above STMACH,
//! and the regression above Mach 0.8 (the original's transonic tables): there the drag due to
//! lift is the components' sum.
//!
//! Axes, signs and units of every output: CL normal to the free stream, positive up; CD along
//! it, positive aft; CN normal to the body axis, positive up; CA along it, positive aft; CM
//! about the moment reference centre (XCG, ZCG), positive nose up; all on the reference area S
//! and, for CM, the reference length c̄ ($OPTINS SREF, CBARR, else the wing's theoretical area
//! and MAC). XCP = CM/CN in reference lengths (positive: centre of pressure ahead of XCG). CLA
//! and CMA per radian. Angles in degrees, lengths in metres.
//!
//! Where this differs from the original, see `docs/wing-body.md`.

mod drag;
mod experimental;
pub mod figures;
mod lift;
mod moment;

use crate::methods::experimental::substitute;
use crate::numeric::curve_slopes;
use std::fmt;

use serde::Serialize;

use crate::case::Case;
use crate::charts::ChartWarning;
use crate::geometry::{body as body_geometry, planform as planform_geometry, Span};
use crate::methods::body::{
    body_alone, subsonic_limit, BodyAlone, BodyMethodError, BodyTerms, BodyWarning,
};
use crate::methods::section::SectionCharacteristics;
use crate::methods::wing::{
    computed_wing_section, wing_alone_with_section, WingAlone, WingMethodError, WingType,
    WingWarning,
};

pub use drag::{
    regression_drag_due_to_lift, wing_body_zero_lift_drag, DragMethod, RegressionInputs,
    WingBodyDrag, WingBodyZeroLiftDrag,
};
pub use experimental::{ExperimentalWingBody, Substitution};
pub use lift::{
    body_vortex, interference_factors, vortex_interference_factor, wing_body_lift, BodyVortex,
    InterferenceFactors, LiftAtAngle, LiftInputs, LARGE_BODY_SPAN_RATIO, VORTEX_ONSET_ALPHA_DEG,
};
pub use moment::{
    carry_over_centre, wing_body_moment, CarryOverCentre, CarryOverInputs, MomentAtAngle,
    MomentInputs, WingAtAngle, SLENDER_BODY_BETA_A,
};

/// Why the wing-body coefficients cannot be computed.
#[derive(Debug, Clone, PartialEq, thiserror::Error, Serialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
#[non_exhaustive]
pub enum WingBodyError {
    #[error("the case has no body ($BODY)")]
    NoBody,
    #[error("the case has no wing ($WGPLNF)")]
    NoWing,
    #[error("no flight condition {index} (a case's conditions are derived from its flight input by Case::prepare)")]
    NoCondition { index: usize },
    #[error("Mach {} is above the subsonic limit STMACH = {limit}: the subsonic wing-body methods do not apply", crate::charts::Query(*mach))]
    NotSubsonic { mach: f64, limit: f64 },
    #[error("body geometry: {reason}")]
    BodyGeometry { reason: String },
    #[error("wing planform: {reason}")]
    WingGeometry { reason: String },
    #[error("body alone: {0}")]
    Body(BodyMethodError),
    #[error("wing alone: {0}")]
    Wing(WingMethodError),
    #[error("body width over span d/b = {body_span_ratio} exceeds {limit}: the large-body method (figure 4.3.1.2-12c) is not covered")]
    LargeBody { body_span_ratio: f64, limit: f64 },
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
pub enum WingBodyWarning {
    /// A chart was read outside its data.
    Chart(ChartWarning),
    /// The wing alone's warnings.
    Wing(WingWarning),
    /// The body alone's warnings.
    Body(BodyWarning),
    /// No CD (and so no CN, CA) at this angle: the regression gives none beyond 18°.
    NoRegressionDrag { alpha_deg: f64 },
    /// CM and CMA are not applicable from this angle on (the wing's moment is not).
    MomentNotApplicable { alpha_deg: f64 },
    /// Experimental data of the deck replaced computed values: the namelist, and each variable
    /// with the number of angles it gives.
    ExperimentalData {
        namelist: String,
        variables: Vec<(String, usize)>,
    },
}

impl fmt::Display for WingBodyWarning {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            WingBodyWarning::Chart(w) => write!(f, "{w}"),
            WingBodyWarning::Wing(w) => write!(f, "wing alone: {w}"),
            WingBodyWarning::Body(w) => write!(f, "body alone: {w}"),
            WingBodyWarning::NoRegressionDrag { alpha_deg } => write!(
                f,
                "no drag at alpha = {alpha_deg} deg: the straight-wing regression has no data beyond 18 deg"
            ),
            WingBodyWarning::MomentNotApplicable { alpha_deg } => write!(
                f,
                "CM and CMA not applicable from alpha = {alpha_deg} deg (the wing's moment is not)"
            ),
            WingBodyWarning::ExperimentalData {
                namelist,
                variables,
            } => {
                let list: Vec<String> = variables
                    .iter()
                    .map(|(v, k)| format!("{v} ({k} angle{})", if *k == 1 { "" } else { "s" }))
                    .collect();
                write!(
                    f,
                    "experimental data from ${namelist} {} replace the computed wing-body values",
                    list.join(", ")
                )
            }
        }
    }
}

/// The auxiliary values of the original's CONFIGURATION AUXILIARY AND PARTIAL OUTPUT page.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Auxiliary {
    /// CLA-B(W) = K_B(W) CLα_W, per rad.
    pub body_in_presence_of_wing_slope_per_rad: f64,
    /// CLA-W(B) = K_W(B) CLα_W, per rad.
    pub wing_in_presence_of_body_slope_per_rad: f64,
    /// K-B(W), K-W(B).
    pub body_in_presence_of_wing: f64,
    pub wing_in_presence_of_body: f64,
    /// XAC/C-B(W): aerodynamic centre of the carry-over lift behind the exposed root's leading
    /// edge, in reference lengths.
    pub carry_over_centre: f64,
}

impl Auxiliary {
    /// The line of a surface with lift-curve slope `slope_per_rad` (on the reference area) on
    /// the body: its interference factors and the centre of its carry-over lift.
    pub fn of(factors: &InterferenceFactors, slope_per_rad: f64, centre: &CarryOverCentre) -> Self {
        Auxiliary {
            body_in_presence_of_wing_slope_per_rad: factors.body_in_presence_of_wing
                * slope_per_rad,
            wing_in_presence_of_body_slope_per_rad: factors.wing_in_presence_of_body
                * slope_per_rad,
            body_in_presence_of_wing: factors.body_in_presence_of_wing,
            wing_in_presence_of_body: factors.wing_in_presence_of_body,
            carry_over_centre: centre.over_reference_length,
        }
    }
}

/// The named terms behind the coefficients.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct WingBodyTerms {
    pub body: BodyAlone,
    pub wing: WingAlone,
    pub interference: InterferenceFactors,
    pub vortices: Vec<BodyVortex>,
    pub lift: Vec<LiftAtAngle>,
    pub drag: Option<WingBodyDrag>,
    pub carry_over_centre: CarryOverCentre,
    /// Per angle; none where the wing's moment is not applicable.
    pub moment: Vec<Option<MomentAtAngle>>,
    /// The experimental data ($EXPRnn) that replaced computed values, and those values.
    pub experimental: Option<Substitution>,
}

/// The wing-body coefficients at each angle of attack. `None` where a value cannot be computed
/// or the method does not apply (the original's NA or blank).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct WingBody {
    pub reference_area: f64,
    pub reference_length: f64,
    pub alpha_deg: Vec<f64>,
    pub cd: Vec<Option<f64>>,
    pub cl: Vec<Option<f64>>,
    pub cm: Vec<Option<f64>>,
    pub cn: Vec<Option<f64>>,
    pub ca: Vec<Option<f64>>,
    pub xcp: Vec<Option<f64>>,
    pub cla_per_rad: Vec<Option<f64>>,
    pub cma_per_rad: Vec<Option<f64>>,
    pub auxiliary: Auxiliary,
    pub terms: WingBodyTerms,
    pub warnings: Vec<WingBodyWarning>,
}

/// The static longitudinal coefficients of the wing-body combination at subsonic speed, for
/// flight condition `condition_index` of `case` at the schedule angles `alpha_deg` (degrees).
///
/// The wing section is the user's $WGSCHR values, else the section method's (see
/// [`computed_wing_section`]). Reference area and length: $OPTINS, else the wing's theoretical
/// area and MAC. Moment reference: $SYNTHS XCG, ZCG; the wing at XW, ZW with incidence ALIW
/// (0 when not given). See the module documentation for axes, signs and units.
///
/// Errors: no body or wing, a Mach number above STMACH, d/b > 0.8, and the errors of the body
/// and wing methods.
pub fn wing_body(
    case: &Case,
    condition_index: usize,
    alpha_deg: &[f64],
) -> Result<WingBody, WingBodyError> {
    let computed = computed_wing_section(case)
        .transpose()
        .map_err(WingBodyError::Wing)?;
    wing_body_with_section(case, condition_index, alpha_deg, computed.as_ref())
}

/// [`wing_body`] with the section method's characteristics given (or none: the user's
/// $WGSCHR values only).
pub fn wing_body_with_section(
    case: &Case,
    condition_index: usize,
    alpha_deg: &[f64],
    computed: Option<&SectionCharacteristics>,
) -> Result<WingBody, WingBodyError> {
    wing_body_with_surface(case, condition_index, alpha_deg, computed, None)
}

/// The body's drag due to lift in the wing-body drag when the body is computed by Jorgensen's
/// method (METHOD=2).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum JorgensenDragReading {
    /// The drag due to lift of the body the deck asked for, Jorgensen's.
    #[default]
    Handbook,
    /// As the original program: the axisymmetric method's (its WBDRAG reads BODYRT's whatever
    /// METHOD says). For reproducing old listings (docs/differences.md).
    Original,
}

/// The horizontal tail in the wing's place (the BODY-HORIZONTAL TAIL page): the tail alone as
/// its own page has it (its moment with the tail's "not applicable" rule, M33O41) and the
/// lift-curve slope its rules give it ([`crate::methods::tail::HorizontalTailAlone`]).
#[derive(Debug, Clone)]
pub struct SurfaceInPlace {
    pub surface: WingAlone,
    /// Per rad, on the reference area: the slope of the combination's incidence, body-vortex
    /// and carry-over terms.
    pub slope_per_rad: f64,
}

/// [`wing_body_with_section`] with the surface alone given (`None`: the wing method on the
/// case's wing, with its analytic slope).
pub fn wing_body_with_surface(
    case: &Case,
    condition_index: usize,
    alpha_deg: &[f64],
    computed: Option<&SectionCharacteristics>,
    in_place: Option<SurfaceInPlace>,
) -> Result<WingBody, WingBodyError> {
    let body_input = case.body.as_ref().ok_or(WingBodyError::NoBody)?;
    let plan = case.wing.as_ref().ok_or(WingBodyError::NoWing)?;
    let condition = case
        .conditions
        .get(condition_index)
        .ok_or(WingBodyError::NoCondition {
            index: condition_index,
        })?;
    let limit = subsonic_limit(case);
    if condition.mach.is_nan() || condition.mach > limit {
        return Err(WingBodyError::NotSubsonic {
            mach: condition.mach,
            limit,
        });
    }
    let shape = body_geometry(body_input).map_err(|e| WingBodyError::BodyGeometry {
        reason: e.to_string(),
    })?;
    let geometry =
        planform_geometry(plan, Span::Both).map_err(|e| WingBodyError::WingGeometry {
            reason: e.to_string(),
        })?;
    let body = body_alone(case, &shape, condition, alpha_deg).map_err(WingBodyError::Body)?;
    let (wing, slope_per_rad) = match in_place {
        Some(t) => (t.surface, Some(t.slope_per_rad)),
        None => (
            wing_alone_with_section(case, condition_index, alpha_deg, computed)
                .map_err(WingBodyError::Wing)?,
            None,
        ),
    };
    let mut warnings: Vec<WingBodyWarning> = Vec::new();
    warnings.extend(body.warnings.iter().cloned().map(WingBodyWarning::Body));
    warnings.extend(wing.warnings.iter().cloned().map(WingBodyWarning::Wing));

    let synthesis = case.synthesis.as_ref();
    let get = |f: fn(&crate::case::Synthesis) -> Option<f64>| synthesis.and_then(f).unwrap_or(0.0);
    let (xcg, zcg, xw, zw) = (get(|s| s.xcg), get(|s| s.zcg), get(|s| s.xw), get(|s| s.zw));
    let incidence_deg = wing.incidence_deg;
    let reference_area = wing.reference_area;
    let reference_length = wing.reference_length;
    let p = &wing.terms.planform;
    let slope = slope_per_rad.unwrap_or(wing.terms.lift_curve_slope.per_rad);
    let n = alpha_deg.len();
    let semispan = p.semispan;
    let body_width = 2.0 * (semispan - p.exposed_semispan);
    let span = 2.0 * semispan;
    let body_semispan_fraction = (semispan - p.exposed_semispan) / semispan;
    let mach = condition.mach;
    let beta = (1.0 - mach * mach).abs().sqrt();

    // Lift.
    let factors = interference_factors(body_width / span, &mut warnings)?;
    let body_radius = (shape.max_area / std::f64::consts::PI).sqrt();
    // From the body's nose, its first station (figure 4.3.1.3-13a's x; the original measures
    // positions from the nose internally).
    let x_quarter_chord = xw + geometry.x_mac_le + geometry.theoretical.mac / 4.0 - shape.nose();
    let vortices = alpha_deg
        .iter()
        .map(|&a| {
            body_vortex(
                a,
                x_quarter_chord,
                body_radius,
                semispan,
                p.taper,
                &mut warnings,
            )
        })
        .collect::<Result<Vec<_>, _>>()?;
    let wing_alpha: Vec<f64> = alpha_deg.iter().map(|a| a + incidence_deg).collect();
    let lift_inputs = LiftInputs {
        factors: &factors,
        incidence_deg,
        wing_slope_per_rad: slope,
        body_semispan_fraction,
        wing_alpha_deg: &wing_alpha,
        wing_cl: &wing.cl,
    };
    let lift: Vec<LiftAtAngle> = (0..n)
        .map(|k| wing_body_lift(&lift_inputs, alpha_deg[k], body.cl[k], &vortices[k]))
        .collect();
    let cl: Vec<Option<f64>> = lift.iter().map(|l| l.cl).collect();

    // Drag.
    let drag = wing_body_drag(
        case,
        condition_index,
        computed,
        &body,
        &wing,
        &shape,
        &geometry,
        xw,
        &mut warnings,
    )?;
    let cd: Vec<Option<f64>> = drag
        .as_ref()
        .map_or_else(|| vec![None; n], |d| d.cd.clone());

    // Pitching moment.
    let root_le = xw
        + (semispan - p.exposed_semispan)
            * p.inboard.leading_edge.tan
            * incidence_deg.to_radians().cos();
    let centre = carry_over_centre(
        &CarryOverInputs::of_planform(p, beta, reference_length),
        &mut warnings,
    )?;
    let cm0 = wing.terms.pitching_moment.as_ref().map(|m| m.zero_lift.cm0);
    let moment_inputs = cm0.map(|cm0| MomentInputs {
        factors: &factors,
        incidence_lift: slope * incidence_deg.to_radians(),
        wing_zero_lift_moment: cm0,
        carry_over_lever: (xcg - root_le) / reference_length - centre.over_reference_length,
        wing_height: (zw - zcg) / reference_length,
    });
    let moment: Vec<Option<MomentAtAngle>> = (0..n)
        .map(|k| {
            let i = moment_inputs.as_ref()?;
            let w = WingAtAngle {
                cm: wing.cm[k]?,
                cn: wing.cn[k]?,
                ca: wing.ca[k]?,
            };
            let m = wing_body_moment(i, alpha_deg[k], body.cm[k]?, w, lift[k].body_vortex);
            m.cm.is_finite().then_some(m)
        })
        .collect();
    let mut cm: Vec<Option<f64>> = moment.iter().map(|m| m.map(|m| m.cm)).collect();
    if let Some(k) = cm.iter().position(Option::is_none) {
        for v in cm.iter_mut().skip(k) {
            *v = None;
        }
    }
    let mut cl = cl;
    let mut cd = cd;
    let alpha_rad: Vec<f64> = alpha_deg.iter().map(|a| a.to_radians()).collect();
    let slopes = |cl: &[Option<f64>], cm: &[Option<f64>]| {
        let applicable = cm.iter().position(Option::is_none).unwrap_or(n);
        let cla = curve_slopes(&alpha_rad, cl);
        let mut cma = curve_slopes(&alpha_rad[..applicable], &cm[..applicable]);
        cma.resize(n, None);
        (cla, cma)
    };
    let (mut cla, mut cma) = slopes(&cl, &cm);

    // Experimental data replace the computed values; the slopes are then those of the
    // substituted curves, except where the deck gives them.
    let substitution = ExperimentalWingBody::of_case(
        case,
        condition.mach_index,
        crate::methods::experimental::WING_BODY,
    )
    .map(|data| {
        let kept = Substitution {
            data,
            computed_cd: cd.clone(),
            computed_cl: cl.clone(),
            computed_cm: cm.clone(),
            computed_cla_per_rad: cla.clone(),
            computed_cma_per_rad: cma.clone(),
        };
        let e = &kept.data;
        substitute(&mut cd, &e.cd);
        substitute(&mut cl, &e.cl);
        substitute(&mut cm, &e.cm);
        (cla, cma) = slopes(&cl, &cm);
        let per_rad = |v: &[Option<f64>]| -> Vec<Option<f64>> {
            v.iter().map(|g| g.map(f64::to_degrees)).collect()
        };
        substitute(&mut cla, &per_rad(&e.cla_per_deg));
        substitute(&mut cma, &per_rad(&e.cma_per_deg));
        warnings.push(WingBodyWarning::ExperimentalData {
            namelist: e.namelist.clone(),
            variables: e
                .given()
                .into_iter()
                .map(|(v, k)| (v.to_string(), k))
                .collect(),
        });
        kept
    });
    if let Some(k) = cm.iter().position(Option::is_none) {
        warnings.push(WingBodyWarning::MomentNotApplicable {
            alpha_deg: alpha_deg[k],
        });
    }

    // The page.
    let crate::numeric::BodyAxes { cn, ca, xcp } =
        crate::numeric::body_axes(&alpha_rad, &cl, &cd, &cm);
    let auxiliary = Auxiliary::of(&factors, slope, &centre);
    Ok(WingBody {
        reference_area,
        reference_length,
        alpha_deg: alpha_deg.to_vec(),
        cd,
        cl,
        cm,
        cn,
        ca,
        xcp,
        cla_per_rad: cla,
        cma_per_rad: cma,
        auxiliary,
        terms: WingBodyTerms {
            body,
            wing,
            interference: factors,
            vortices,
            lift,
            drag,
            carry_over_centre: centre,
            moment,
            experimental: substitution,
        },
        warnings,
    })
}

/// Zero-lift drag with R_WB, plus the drag due to lift of the components, or for a straight
/// wing the original's regression where it applies. None when the body or wing has no
/// zero-lift drag.
#[allow(clippy::too_many_arguments)]
fn wing_body_drag(
    case: &Case,
    condition_index: usize,
    computed: Option<&SectionCharacteristics>,
    body: &BodyAlone,
    wing: &WingAlone,
    shape: &crate::geometry::BodyGeometry,
    geometry: &crate::geometry::PlanformGeometry,
    xw: f64,
    warnings: &mut Vec<WingBodyWarning>,
) -> Result<Option<WingBodyDrag>, WingBodyError> {
    let condition = &case.conditions[condition_index];
    let (Some(body_zero), Some(wing_zero), Some(wing_lift)) = (
        body.zero_lift_drag.as_ref(),
        wing.terms.zero_lift_drag.as_ref(),
        wing.terms.drag_due_to_lift.as_ref(),
    ) else {
        return Ok(None);
    };
    let n = body.alpha_deg.len();
    let zero_lift = wing_body_zero_lift_drag(
        condition.mach,
        condition.reynolds_per_length * shape.length,
        wing_zero.total,
        body_zero.friction,
        body_zero.base,
        warnings,
    )?;
    let body_lift: Vec<Option<f64>> = match &body.terms {
        // The original's WBDRAG takes the axisymmetric method's (BODYRT's) drag due to lift
        // for a Jorgensen body.
        BodyTerms::Jorgensen { axisymmetric, .. }
            if case.jorgensen_drag == JorgensenDragReading::Original =>
        {
            axisymmetric
                .angles
                .iter()
                .map(|a| Some(a.cd_lift))
                .collect()
        }
        _ => body
            .cd
            .iter()
            .map(|c| c.map(|c| c - body_zero.total))
            .collect(),
    };
    let wing_lift: Vec<Option<f64>> = (0..n).map(|k| wing_lift.cd.get(k).copied()).collect();
    let mut out = WingBodyDrag {
        zero_lift,
        method: DragMethod::Components,
        cd: (0..n)
            .map(|k| Some(zero_lift.total + body_lift[k]? + wing_lift[k]?))
            .collect(),
        body_lift,
        wing_lift,
        regression_inputs: None,
        regression_not_used: None,
        regression: Vec::new(),
    };
    if wing.planform_type != WingType::Straight {
        return Ok(Some(out));
    }
    let plan = case.wing.as_ref().ok_or(WingBodyError::NoWing)?;
    let section = &wing.terms.section;
    let user = case.sections.get("WING");
    let user_scalar = |name: &str| user.and_then(|u| u.scalars.get(name).copied());
    let body_width = 2.0 * (geometry.semispan - geometry.exposed_semispan);
    let tan_le = geometry.tan_sweep_inboard(0.0);
    let tan_te = geometry.tan_sweep_inboard(1.0);
    // Stations from the body's nose, as the original measures them internally.
    let x_nose = shape.nose();
    let x_max_area = shape.x_max_area - x_nose;
    let mut nose = (xw - x_nose + 0.5 * body_width * tan_le) / body_width;
    let mut after =
        (xw - x_nose + plan.chrdr.unwrap_or(0.0) + 0.5 * body_width * tan_te) / body_width;
    if x_max_area < nose * body_width {
        nose = nose * body_width / shape.max_diameter;
    }
    if x_max_area > after * body_width {
        after = after * body_width / shape.max_diameter;
    }
    let inputs = RegressionInputs {
        aspect_ratio: geometry.theoretical.aspect_ratio,
        taper: geometry.theoretical.taper,
        tan_leading_edge: tan_le,
        thickness_ratio: section.thickness_ratio.unwrap_or(f64::NAN),
        nose_length: nose,
        afterbody_length: shape.length / body_width - after,
        transition: if case.flight.as_ref().is_some_and(|f| f.transition_strips) {
            1.0
        } else {
            0.0
        },
        leading_edge_radius: section.leading_edge_radius.unwrap_or(0.0),
        twist_deg: plan.twista_deg.unwrap_or(0.0),
        max_camber: user_scalar("YCM")
            .or(computed.map(|c| c.max_camber))
            .unwrap_or(0.0),
        design_lift: user_scalar("CLD").unwrap_or(0.0),
        reynolds_number: (condition.reynolds_per_length * geometry.theoretical.mac)
            .clamp(drag::REYNOLDS_NUMBER.0, drag::REYNOLDS_NUMBER.1),
    };
    out.regression_inputs = Some(inputs);
    if let Some((name, value)) = inputs.outside_data() {
        out.regression_not_used =
            Some(format!("{name} = {value} is outside the regression's data"));
        return Ok(Some(out));
    }
    let mut quiet = Vec::new();
    let regression = body
        .alpha_deg
        .iter()
        .map(|&a| regression_drag_due_to_lift(&inputs, condition.mach, a, &mut quiet))
        .collect::<Result<Vec<_>, _>>()?;
    if regression.first().is_some_and(Option::is_none) {
        out.regression_not_used = Some(format!(
            "no regression coefficients at Mach {} and alpha {} deg",
            condition.mach, body.alpha_deg[0]
        ));
        return Ok(Some(out));
    }
    warnings.extend(quiet);
    for (k, r) in regression.iter().enumerate() {
        if r.is_none() {
            warnings.push(WingBodyWarning::NoRegressionDrag {
                alpha_deg: body.alpha_deg[k],
            });
        }
    }
    out.method = DragMethod::Regression;
    out.cd = regression
        .iter()
        .map(|r| r.map(|r| zero_lift.total + r))
        .collect();
    out.regression = regression;
    Ok(Some(out))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn slopes_of_a_parabola_are_exact() {
        let a: Vec<f64> = [0.0, 0.1, 0.2, 0.4].to_vec();
        let f: Vec<Option<f64>> = a
            .iter()
            .map(|x| Some(1.0 + 2.0 * x + 3.0 * x * x))
            .collect();
        for (k, s) in curve_slopes(&a, &f).iter().enumerate() {
            assert!((s.unwrap() - (2.0 + 6.0 * a[k])).abs() < 1e-9);
        }
    }
}
