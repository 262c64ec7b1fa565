//! Body alone at subsonic speeds: the static longitudinal coefficients of the original's
//! `BODY ALONE CONFIGURATION` page (CD, CL, CM, CN, CA, XCP, CLA, CMA against angle of attack)
//! and the zero-lift drag of its BASIC BODY PROPERTIES.
//!
//! Methods (DATCOM sections; the original's routines):
//! - zero-lift drag, 4.2.3.1 (skin friction with a form factor, base drag), module
//!   `zero_lift_drag`;
//! - a body of revolution, or any body described by its cross-section areas: slender-body lift
//!   and moment slopes (4.2.1.1, 4.2.2.1) with the viscous crossflow of 4.2.1.2 and drag due to
//!   lift (4.2.3.2), module `axisymmetric` (BODYRT);
//! - a cambered body (upper and lower contours ZU, ZL given, METHOD=1): camber-line zero-lift
//!   angle and moment, kp/kv normal force and the onset angle of crossflow, module `cambered`
//!   (BODOPT);
//! - METHOD=2: Jorgensen's normal force and moment after the axisymmetric method, module
//!   `jorgensen` (BODYJM).
//!
//! Then, as the original does for the page (M04O04/M06O06): experimental values of `$EXPRnn`
//! replace computed ones; CLA and CMA are the method's analytic slopes at the first angle of
//! attack and the slopes of the CL(α) and CM(α) curves at the others (the parabola through the
//! angle and its neighbours; through the last three at the last angle); CN and CA are resolved
//! from CL and CD.
//!
//! Axes, signs and units of every output: CL normal to the free stream, positive up; CD along
//! the free stream, positive aft; CN normal to the body axis, positive up; CA along the body
//! axis, positive aft; CM about the moment reference centre (XCG on the body axis; ZCG does not
//! enter), positive nose up; all on the reference area S and, for CM, the reference length c̄.
//! XCP = CM/CN, the centre of pressure in reference lengths ahead of XCG. CLA and CMA per
//! radian. Angles in degrees, lengths in metres.
//!
//! Where this differs from the original, see `docs/body.md`.

mod axisymmetric;
mod cambered;
mod experimental;
mod figures;
mod jorgensen;
mod shape;
mod tables;
mod zero_lift_drag;

use std::fmt;

use serde::Serialize;

use crate::case::units::to_si;
use crate::case::Case;
use crate::charts::{ChartWarning, Query};
use crate::conditions::FlightCondition;
use crate::deck::schema::Dimension;
use crate::geometry::BodyGeometry;
use crate::results::planform_area_and_mac;

pub use axisymmetric::{
    axisymmetric_body, lift_curve_slope, pitching_moment_slope, Axisymmetric, AxisymmetricAngle,
    LiftCurveSlope,
};
pub use cambered::{cambered_body, Cambered, CamberedAngle};
pub use experimental::ExperimentalData;
pub use figures::ALL as FIGURES;
pub use jorgensen::{jorgensen_body, Jorgensen, JorgensenAngle};
pub use shape::BodyShape;
pub use zero_lift_drag::{skin_friction_coefficient, zero_lift_drag, ZeroLiftDrag};

/// The subsonic methods apply up to STMACH: 0.6 unless the deck gives another value, which is
/// held between these limits (as the original does).
pub const DEFAULT_SUBSONIC_LIMIT: f64 = 0.6;
pub const MAX_SUBSONIC_LIMIT: f64 = 0.99;
/// Roughness height when the deck gives none (or less than 1E-10 in its unit): 1.6E-4 in,
/// the original's default.
pub const DEFAULT_ROUGHNESS_IN: f64 = 1.6e-4;
const ROUGHNESS_NOT_GIVEN_BELOW: f64 = 1e-10;
const METRES_PER_INCH: f64 = 0.0254;
/// METHOD above this selects Jorgensen's method (the original's CHECK rounds METHOD to 1 or 2).
const JORGENSEN_METHOD_ABOVE: f64 = 1.5;

/// Reference area and length of the coefficients, SI.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct BodyReference {
    /// m².
    pub area: f64,
    /// m.
    pub length: f64,
}

/// Which method computed the table.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum BodyMethod {
    /// Slender body with viscous crossflow (BODYRT).
    Axisymmetric,
    /// Cambered body (BODOPT).
    Cambered,
    /// Jorgensen's method after the axisymmetric one (BODYRT then BODYJM).
    Jorgensen,
}

/// The named terms of the method used.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(tag = "method", rename_all = "snake_case")]
pub enum BodyTerms {
    Axisymmetric(Axisymmetric),
    Cambered(Cambered),
    Jorgensen {
        axisymmetric: Axisymmetric,
        jorgensen: Jorgensen,
    },
}

/// Why the body-alone coefficients cannot be computed.
#[derive(Debug, Clone, PartialEq, thiserror::Error, Serialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
#[non_exhaustive]
pub enum BodyMethodError {
    #[error("Mach {} is above the subsonic limit STMACH = {limit}: the subsonic body methods do not apply", crate::charts::Query(*mach))]
    NotSubsonic { mach: f64, limit: f64 },
    #[error("the case is a low-aspect-ratio wing-body ($LARWB): the original computes no body-alone page for it")]
    LowAspectRatioWingBody,
    #[error("no reference area: give SREF in $OPTINS (or a wing, whose area is the default)")]
    NoReferenceArea,
    #[error("no reference length: give CBARR in $OPTINS (or a wing, whose mean aerodynamic chord is the default)")]
    NoReferenceLength,
    #[error("the body cannot be computed: {reason}")]
    Degenerate { reason: String },
    #[error("the cambered-body method is not defined for this body: {reason}")]
    CamberedBodyUndefined { reason: String },
    #[error("angle of attack {alpha_deg} is not a number")]
    Angle { alpha_deg: f64 },
    #[error("the Reynolds number {reynolds} is not a positive number")]
    Reynolds { reynolds: f64 },
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
pub enum BodyWarning {
    /// A chart was read outside its data.
    Chart(ChartWarning),
    /// x0 is in the last interval of the body's table: no viscous crossflow (as the original).
    NoCrossflowAftOfX0 { x0: f64 },
    /// The area does not change from the nose to x0: the moment integral is zero here; the
    /// original's value is undefined there.
    ConstantAreaToX0 { x0: f64 },
    /// A coefficient has no value at an angle.
    NoValue {
        alpha_deg: f64,
        coefficient: &'static str,
        reason: &'static str,
    },
    /// Experimental data of the deck replaced computed values.
    ExperimentalData { namelist: String },
    /// The zero-lift drag cannot be computed.
    NoZeroLiftDrag { reason: String },
    /// The area drops in a step (a station repeated): x1 is there.
    AreaStep { x1: f64 },
    /// ZU and ZL are given at fewer stations than X.
    ContoursShort { given: usize, stations: usize },
    /// The cambered body's radius reaches 0.96 of its largest value at its first station (a
    /// blunt nose), so the forebody ahead of that station has no length.
    BluntNose,
}

impl fmt::Display for BodyWarning {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            BodyWarning::Chart(w) => write!(f, "{w}"),
            BodyWarning::NoCrossflowAftOfX0 { x0 } => write!(
                f,
                "x0 = {} m lies in the last interval of the body stations: no viscous crossflow is added (as in the original)",
                Query(*x0)
            ),
            BodyWarning::ConstantAreaToX0 { x0 } => write!(
                f,
                "the cross-section area is constant from the nose to x0 = {} m: the moment integral is taken as zero (the original's value is undefined)",
                Query(*x0)
            ),
            BodyWarning::NoValue {
                alpha_deg,
                coefficient,
                reason,
            } => write!(f, "no {coefficient} at alpha = {alpha_deg} deg: {reason}"),
            BodyWarning::ExperimentalData { namelist } => write!(
                f,
                "experimental body data of ${namelist} replace the computed values"
            ),
            BodyWarning::NoZeroLiftDrag { reason } => write!(
                f,
                "no zero-lift drag ({reason}): CD, CN and CA are not computed"
            ),
            BodyWarning::AreaStep { x1 } => write!(
                f,
                "the cross-section area drops in a step at x = {} m (a repeated station): the steepest decrease x1 is taken there (the original's slope is not a number there and it takes x1 = the body length)",
                Query(*x1)
            ),
            BodyWarning::ContoursShort { given, stations } => write!(
                f,
                "ZU and ZL are given at {given} of the {stations} body stations: the others are taken as 0, as the original reads them"
            ),
            BodyWarning::BluntNose => write!(
                f,
                "the radius reaches 0.96 of its largest value at the first station (a blunt nose): the potential normal force is taken at the nose, where the area grows (the original reads outside its arrays or extrapolates before the nose there)"
            ),
        }
    }
}

/// The body-alone coefficients at each angle of attack, with the terms they come from.
/// `None` where a value cannot be computed.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct BodyAlone {
    pub method: BodyMethod,
    pub reference: BodyReference,
    /// Moment reference centre, m from the body's first station.
    pub xcg_from_nose: f64,
    pub alpha_deg: Vec<f64>,
    pub cd: Vec<Option<f64>>,
    pub cl: Vec<Option<f64>>,
    pub cm: Vec<Option<f64>>,
    pub cn: Vec<Option<f64>>,
    pub ca: Vec<Option<f64>>,
    /// CM/CN: centre of pressure in reference lengths ahead of XCG (none where CN = 0).
    pub xcp: Vec<Option<f64>>,
    pub cla_per_rad: Vec<Option<f64>>,
    pub cma_per_rad: Vec<Option<f64>>,
    /// Zero-lift drag and its parts; none when it cannot be computed (a zero Reynolds number:
    /// Mach 0), and then no CD, CN, CA either (nor CL of the methods that need the drag).
    pub zero_lift_drag: Option<ZeroLiftDrag>,
    pub terms: BodyTerms,
    /// The `$EXPRnn` namelist whose values replaced computed ones.
    pub experimental: Option<String>,
    pub warnings: Vec<BodyWarning>,
}

/// The Mach number up to which the subsonic methods apply for this case (STMACH).
pub fn subsonic_limit(case: &Case) -> f64 {
    case.flight
        .as_ref()
        .and_then(|f| f.stmach)
        .map_or(DEFAULT_SUBSONIC_LIMIT, |m| {
            m.clamp(DEFAULT_SUBSONIC_LIMIT, MAX_SUBSONIC_LIMIT)
        })
}

/// Reference area and length: $OPTINS SREF and CBARR, else the wing's theoretical area and
/// mean aerodynamic chord (as `datcom::results` defaults them).
pub fn body_reference(case: &Case) -> Result<BodyReference, BodyMethodError> {
    let wing = case.wing.as_ref().and_then(planform_area_and_mac);
    let area = case
        .reference
        .area
        .or(wing.map(|w| w.0))
        .filter(|a| *a > 0.0 && a.is_finite())
        .ok_or(BodyMethodError::NoReferenceArea)?;
    let length = case
        .reference
        .chord
        .or(wing.map(|w| w.1))
        .filter(|c| *c > 0.0 && c.is_finite())
        .ok_or(BodyMethodError::NoReferenceLength)?;
    Ok(BodyReference { area, length })
}

/// Roughness height, m: $OPTINS ROUGFC, or 1.6E-4 in when not given (or below 1E-10 in the
/// deck's unit).
pub fn roughness_height(case: &Case) -> f64 {
    let tiny = to_si(ROUGHNESS_NOT_GIVEN_BELOW, case.dim, Dimension::Roughness);
    case.reference
        .roughness
        .filter(|k| *k >= tiny && k.is_finite())
        .unwrap_or(DEFAULT_ROUGHNESS_IN * METRES_PER_INCH)
}

/// CD, CL, CM of the method and its analytic slopes at the first angle.
struct Computed {
    method: BodyMethod,
    terms: BodyTerms,
    cd: Vec<f64>,
    cl: Vec<f64>,
    cm: Vec<f64>,
    cla_first: f64,
    cma_first: f64,
}

fn compute(
    case: &Case,
    shape: &BodyShape,
    condition: &FlightCondition,
    alpha_deg: &[f64],
    reference: &BodyReference,
    cd0: f64,
    warnings: &mut Vec<BodyWarning>,
) -> Result<Computed, BodyMethodError> {
    let body = case.body.as_ref();
    let method = body.and_then(|b| b.method).unwrap_or(1.0);
    let jorgensen = method > JORGENSEN_METHOD_ABOVE;
    if let Some(b) = body.filter(|b| !jorgensen && !b.zl.is_empty()) {
        let (t, cl) = cambered_body(shape, &b.zu, &b.zl, cd0, alpha_deg, reference, warnings)?;
        let cd = t.angles.iter().map(|a| cd0 + a.cd_lift).collect();
        let cm = t
            .angles
            .iter()
            .map(|a| t.cm0 + a.cm_potential + a.cm_viscous)
            .collect();
        return Ok(Computed {
            method: BodyMethod::Cambered,
            cd,
            cl,
            cm,
            cla_first: t.cla_per_rad,
            cma_first: t.cma_per_rad,
            terms: BodyTerms::Cambered(t),
        });
    }
    let slender = axisymmetric_body(shape, condition.mach, alpha_deg, reference, warnings)?;
    if jorgensen {
        let ellipticity = body
            .and_then(|b| b.ellip)
            .filter(|e| *e > 0.0)
            .unwrap_or(1.0);
        let j = jorgensen_body(shape, ellipticity, &slender, cd0, reference);
        let mut cd = Vec::with_capacity(alpha_deg.len());
        let mut cl = Vec::with_capacity(alpha_deg.len());
        for t in &j.angles {
            let (sin, cos) = t.alpha_deg.to_radians().sin_cos();
            let cn = t.cn_potential + t.cn_viscous;
            cl.push(cn * cos - t.ca * sin);
            cd.push(t.ca * cos + cn * sin);
        }
        let cm = j
            .angles
            .iter()
            .map(|t| t.cm_potential + t.cm_viscous)
            .collect();
        return Ok(Computed {
            method: BodyMethod::Jorgensen,
            cd,
            cl,
            cm,
            cla_first: slender.cla_per_rad,
            cma_first: slender.cma_per_rad,
            terms: BodyTerms::Jorgensen {
                axisymmetric: slender,
                jorgensen: j,
            },
        });
    }
    let cd = slender.angles.iter().map(|a| cd0 + a.cd_lift).collect();
    let cl = slender
        .angles
        .iter()
        .map(|a| a.cl_potential + a.cl_viscous)
        .collect();
    let cm = slender
        .angles
        .iter()
        .map(|a| a.cm_potential + a.cm_viscous)
        .collect();
    Ok(Computed {
        method: BodyMethod::Axisymmetric,
        cd,
        cl,
        cm,
        cla_first: slender.cla_per_rad,
        cma_first: slender.cma_per_rad,
        terms: BodyTerms::Axisymmetric(slender),
    })
}

/// Slope of the curve `f(α)` at each angle, per radian: the parabola through the angle and its
/// neighbours, through the first or last three at the ends, the chord for two angles.
fn curve_slopes(alpha_rad: &[f64], f: &[f64]) -> Vec<Option<f64>> {
    use tables::{node_slope, EndSlope};
    (0..alpha_rad.len())
        .map(|k| node_slope(alpha_rad, f, k, EndSlope::Parabola, EndSlope::Parabola))
        .collect()
}

fn finite(v: f64) -> Option<f64> {
    v.is_finite().then_some(v)
}

/// The static longitudinal coefficients of the body alone at subsonic speed for the flight
/// condition `condition` of `case` at the angles `alpha_deg` (degrees).
///
/// The method is chosen as the original chooses it: the cambered-body method when the deck
/// gives ZL and METHOD is not 2, Jorgensen's when METHOD is 2, the axisymmetric method
/// otherwise. Reference area and length come from $OPTINS or the wing; the moment reference
/// centre is $SYNTHS XCG (0 when not given) on the body axis; roughness is $OPTINS ROUGFC or
/// 1.6E-4 in. See the module documentation for axes, signs and units.
///
/// Errors: a Mach number above STMACH (the subsonic methods do not apply), a $LARWB case, no
/// reference area or length, a body the methods cannot compute.
pub fn body_alone(
    case: &Case,
    geometry: &BodyGeometry,
    condition: &FlightCondition,
    alpha_deg: &[f64],
) -> Result<BodyAlone, BodyMethodError> {
    if case.larwb.is_some() {
        return Err(BodyMethodError::LowAspectRatioWingBody);
    }
    let limit = subsonic_limit(case);
    if condition.mach > limit || !condition.mach.is_finite() {
        return Err(BodyMethodError::NotSubsonic {
            mach: condition.mach,
            limit,
        });
    }
    let reference = body_reference(case)?;
    let xcg = case.synthesis.as_ref().and_then(|s| s.xcg).unwrap_or(0.0);
    let shape = BodyShape::new(geometry, xcg)?;
    let mut warnings = Vec::new();
    let drag = match zero_lift_drag(
        &shape,
        condition.mach,
        condition.reynolds_per_length,
        roughness_height(case),
        reference.area,
        &mut warnings,
    ) {
        Ok(d) => Some(d),
        Err(e @ (BodyMethodError::Reynolds { .. } | BodyMethodError::Degenerate { .. })) => {
            warnings.push(BodyWarning::NoZeroLiftDrag {
                reason: e.to_string(),
            });
            None
        }
        Err(e) => return Err(e),
    };
    // Without the zero-lift drag the coefficients that contain it come out as NaN and are
    // reported as none.
    let cd0 = drag.as_ref().map_or(f64::NAN, |d| d.total);
    if let Some(&alpha) = alpha_deg.iter().find(|a| !a.is_finite()) {
        return Err(BodyMethodError::Angle { alpha_deg: alpha });
    }
    let angles = alpha_deg;
    let Computed {
        method,
        terms,
        mut cd,
        mut cl,
        mut cm,
        cla_first,
        cma_first,
    } = compute(
        case,
        &shape,
        condition,
        angles,
        &reference,
        cd0,
        &mut warnings,
    )?;
    let n = angles.len();
    let alpha_rad: Vec<f64> = angles.iter().map(|a| a.to_radians()).collect();
    let experimental = ExperimentalData::of_case(
        case,
        condition.mach_index,
        crate::methods::experimental::BODY,
    );
    let per_deg_to_per_rad = 180.0 / std::f64::consts::PI;
    if let Some(e) = &experimental {
        experimental::substitute(&mut cd, &e.cd);
        experimental::substitute(&mut cl, &e.cl);
        experimental::substitute(&mut cm, &e.cm);
        warnings.push(BodyWarning::ExperimentalData {
            namelist: e.namelist.clone(),
        });
    }
    let slopes_from_first = experimental
        .as_ref()
        .is_some_and(ExperimentalData::gives_first_angle);
    let mut cla = curve_slopes(&alpha_rad, &cl);
    let mut cma = curve_slopes(&alpha_rad, &cm);
    if n > 0 && !slopes_from_first {
        cla[0] = Some(cla_first);
        cma[0] = Some(cma_first);
    }
    if let Some(e) = &experimental {
        for (slopes, given) in [(&mut cla, &e.cla_per_deg), (&mut cma, &e.cma_per_deg)] {
            for (s, g) in slopes.iter_mut().zip(given) {
                if let Some(g) = g {
                    *s = Some(g * per_deg_to_per_rad);
                }
            }
        }
    }
    let given = |v: &[f64]| -> Vec<Option<f64>> { v.iter().copied().map(Some).collect() };
    let crate::numeric::BodyAxes { cn, ca, xcp } =
        crate::numeric::body_axes(&alpha_rad, &given(&cl), &given(&cd), &given(&cm));
    let keep = |v: Vec<Option<f64>>| -> Vec<Option<f64>> {
        v.into_iter().map(|x| x.and_then(finite)).collect()
    };
    let plain = |v: Vec<f64>| -> Vec<Option<f64>> { v.into_iter().map(finite).collect() };
    Ok(BodyAlone {
        method,
        reference,
        xcg_from_nose: shape.xcg,
        alpha_deg: alpha_deg.to_vec(),
        cd: plain(cd),
        cl: plain(cl),
        cm: plain(cm),
        cn: keep(cn),
        ca: keep(ca),
        xcp: keep(xcp),
        cla_per_rad: keep(cla),
        cma_per_rad: keep(cma),
        zero_lift_drag: drag,
        terms,
        experimental: experimental.map(|e| e.namelist),
        warnings,
    })
}
