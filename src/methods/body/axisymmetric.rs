//! Body of revolution (or treated as one by its cross-section areas): slender-body lift and
//! moment with Allen and Perkins' viscous crossflow (DATCOM 4.2.1.1, 4.2.1.2, 4.2.2.1, 4.2.3.2;
//! the original's routine BODYRT, lines 2326-2562).

use serde::Serialize;

use super::figures;
use super::shape::BodyShape;
use super::tables::{first_maximum, interpolate, node_slope, trapezoid, EndSlope, Resampled};
use super::{BodyMethodError, BodyReference, BodyWarning};

/// DATCOM 4.2.1.1's empirical station x0 where the flow stops being potential:
/// x0 = 0.378 l + 0.527 x1, x1 the station of the steepest area decrease (or the base).
const X0_LENGTH_FACTOR: f64 = 0.378;
const X0_X1_FACTOR: f64 = 0.527;

/// The slender-body and crossflow quantities of an axisymmetric body.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Axisymmetric {
    /// Station of the steepest decrease of cross-section area (the length when the area never
    /// decreases), m from the nose.
    pub x1: f64,
    /// Station x0 where the potential flow ends, m from the nose.
    pub x0: f64,
    /// Cross-section area at x0, m².
    pub s0: f64,
    /// Apparent-mass factor k2 − k1 (Fig. 4.2.1.1-20).
    pub k2_minus_k1: f64,
    /// Lift-curve slope 2 (k2 − k1) S0/S, per radian (the original's first-row CLA).
    pub cla_per_rad: f64,
    /// Pitching-moment slope about XCG, per radian (the original's first-row CMA).
    pub cma_per_rad: f64,
    /// ∫₀^x0 x (dS/dx) dx, m³.
    pub area_moment: f64,
    /// Crossflow drag proportionality factor η (Fig. 4.2.1.2-35a).
    pub eta: f64,
    /// ∫_x0^l r dx: half the planform area aft of x0, m².
    pub crossflow_half_area: f64,
    /// ∫_x0^l r x dx, m³.
    pub crossflow_half_area_moment: f64,
    /// The terms at each angle of attack.
    pub angles: Vec<AxisymmetricAngle>,
}

/// The terms of lift, moment and drag due to lift at one angle of attack.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct AxisymmetricAngle {
    pub alpha_deg: f64,
    /// Crossflow drag coefficient cdc at M |sin α| (Fig. 4.2.1.2-35b).
    pub crossflow_drag_coefficient: f64,
    /// Slender-body (potential) lift, CLα α.
    pub cl_potential: f64,
    /// Viscous crossflow lift, 2 η cdc sin²α (∫_x0^l r dx)/S, odd in α.
    pub cl_viscous: f64,
    /// Potential moment, CMα α.
    pub cm_potential: f64,
    /// Viscous crossflow moment about XCG.
    pub cm_viscous: f64,
    /// Drag due to lift, CL sin α (DATCOM 4.2.3.2).
    pub cd_lift: f64,
}

/// Slope of the cross-section area at station `k` for the search of the steepest decrease:
/// the parabola through the station and its neighbours (the first parabola at the nose, the
/// last chord at the base). At a step in the area (a station repeated with two areas) the slope
/// is infinite with the sign of the step; next to a step, the chord to the nearest distinct
/// station.
fn area_slope(x: &[f64], s: &[f64], k: usize) -> f64 {
    if let Some(d) = node_slope(x, s, k, EndSlope::Parabola, EndSlope::Chord) {
        return d;
    }
    let n = x.len();
    let step = if k + 1 < n && x[k + 1] == x[k] {
        s[k + 1] - s[k]
    } else if k > 0 && x[k - 1] == x[k] {
        s[k] - s[k - 1]
    } else {
        0.0
    };
    if step != 0.0 {
        return step.signum() * f64::INFINITY;
    }
    let next = (k + 1..n).find(|&j| x[j] != x[k]);
    let previous = (0..k).rev().find(|&j| x[j] != x[k]);
    match (previous, next) {
        (_, Some(j)) | (Some(j), None) => (s[j] - s[k]) / (x[j] - x[k]),
        (None, None) => 0.0,
    }
}

/// Station of the steepest decrease of the cross-section area: the first node where −dS/dx is
/// largest (see [`area_slope`]); the body length when S never decreases.
fn steepest_area_decrease_station(
    shape: &BodyShape,
    warnings: &mut Vec<BodyWarning>,
) -> Result<f64, BodyMethodError> {
    let (x, s) = (&shape.x, &shape.s);
    if s.windows(2).all(|w| w[1] >= w[0]) {
        return Ok(shape.length);
    }
    let decrease: Vec<f64> = (0..x.len()).map(|k| -area_slope(x, s, k)).collect();
    let k = first_maximum(&decrease).ok_or_else(|| BodyMethodError::Degenerate {
        reason: "no area slope along the body".into(),
    })?;
    if decrease[k].is_infinite() {
        warnings.push(BodyWarning::AreaStep { x1: x[k] });
    }
    Ok(x[k])
}

/// The slender-body lift-curve slope and the quantities it comes from.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct LiftCurveSlope {
    /// Station of the steepest area decrease (the body length when the area never decreases),
    /// m from the nose.
    pub x1: f64,
    /// x0 = 0.378 l + 0.527 x1, m from the nose.
    pub x0: f64,
    /// Cross-section area at x0, m².
    pub s0: f64,
    /// k2 − k1 from figure 4.2.1.1-20.
    pub k2_minus_k1: f64,
    /// 2 (k2 − k1) S0/S, per radian.
    pub cla_per_rad: f64,
}

/// Lift-curve slope of a body at α = 0, DATCOM 4.2.1.1 (slender-body theory with the
/// apparent-mass factor): CLα = 2 (k2 − k1) S0/S per radian, with S0 the cross-section area at
/// x0 = 0.378 l + 0.527 x1 (x1 the station of the steepest area decrease) and k2 − k1 from
/// figure 4.2.1.1-20 at the fineness ratio l/d (data 4 to 20; parabola below, line above, with
/// a warning). Subsonic speeds, small angles. Original: BODYRT (lines 2405-2463).
pub fn lift_curve_slope(
    shape: &BodyShape,
    reference_area: f64,
    warnings: &mut Vec<BodyWarning>,
) -> Result<LiftCurveSlope, BodyMethodError> {
    let x1 = steepest_area_decrease_station(shape, warnings)?;
    let x0 = X0_LENGTH_FACTOR * shape.length + X0_X1_FACTOR * x1;
    let s0 = interpolate(&shape.x, &shape.s, x0);
    let k2_minus_k1 = figures::read(figures::APPARENT_MASS, &[shape.fineness], warnings)?;
    Ok(LiftCurveSlope {
        x1,
        x0,
        s0,
        k2_minus_k1,
        cla_per_rad: 2.0 * k2_minus_k1 * s0 / reference_area,
    })
}

/// Pitching-moment slope of a body about XCG at α = 0, DATCOM 4.2.2.1 (slender-body theory):
/// Cmα = 2 (k2 − k1)/(S c̄) [xcg S0 − ∫₀^x0 x (dS/dx) dx] per radian, the moment positive nose
/// up. The integral is taken as the original does (BODYRT lines 2468-2480): the area table is
/// cut at x0 and after its last change of area, resampled on 20 equal stations, and dS/dx is
/// the parabola slope at each station. Subsonic speeds, small angles.
///
/// Returns (Cmα per radian, the integral in m³).
pub fn pitching_moment_slope(
    shape: &BodyShape,
    lift: &LiftCurveSlope,
    reference: &BodyReference,
    warnings: &mut Vec<BodyWarning>,
) -> (f64, f64) {
    let x0 = lift.x0;
    let n = shape.x.len();
    let cut = shape.x.iter().position(|&x| x >= x0).unwrap_or(n - 1);
    let mut x = shape.x[..=cut].to_vec();
    let mut s = shape.s[..=cut].to_vec();
    x[cut] = x0;
    s[cut] = lift.s0;
    let last_change = (1..=cut).rev().find(|&k| s[k] != s[k - 1]);
    let area_moment = match last_change {
        Some(k) => {
            let table = Resampled::new(&x[..=k], &s[..=k]);
            let integrand: Vec<f64> = table
                .slopes()
                .iter()
                .zip(&table.x)
                .map(|(d, x)| d * x)
                .collect();
            trapezoid(&table.x, &integrand)
        }
        None => {
            warnings.push(BodyWarning::ConstantAreaToX0 { x0 });
            0.0
        }
    };
    let cma = shape.xcg * lift.cla_per_rad / reference.length
        - 2.0 * lift.k2_minus_k1 * area_moment / (reference.area * reference.length);
    (cma, area_moment)
}

/// ∫_x0^l r dx and ∫_x0^l r x dx over the body aft of x0, for the viscous crossflow. As the
/// original (BODYRT lines 2492-2497): the radius table from the first station at or aft of x0,
/// that station moved to x0 but keeping its radius, resampled on 20 equal stations; when x0 is
/// in the last interval of the table both integrals are zero (no viscous crossflow).
fn crossflow_integrals(shape: &BodyShape, x0: f64, warnings: &mut Vec<BodyWarning>) -> (f64, f64) {
    let n = shape.x.len();
    let cut = shape.x.iter().position(|&x| x >= x0).unwrap_or(n - 1);
    if cut == n - 1 {
        warnings.push(BodyWarning::NoCrossflowAftOfX0 { x0 });
        return (0.0, 0.0);
    }
    let mut x = shape.x[cut..].to_vec();
    x[0] = x0;
    let table = Resampled::new(&x, &shape.r[cut..]);
    let moment: Vec<f64> = table.f.iter().zip(&table.x).map(|(r, x)| r * x).collect();
    (table.integral(), trapezoid(&table.x, &moment))
}

/// Lift, pitching moment and drag due to lift of an axisymmetric body at each angle of attack
/// (DATCOM 4.2.1.2 with 4.2.1.1, 4.2.2.1 and 4.2.3.2; original: BODYRT).
///
/// CL = CLα α + 2 η cdc sin²α (∫_x0^l r dx)/S, CM = Cmα α − 2 η cdc sin²α
/// (∫_x0^l r (x − xcg) dx)/(S c̄), both viscous terms odd in α; CD_L = CL sin α. η from figure
/// 4.2.1.2-35a at l/d, cdc from figure 4.2.1.2-35b at M |sin α|. The original puts the viscous
/// crossflow term (a normal-force term in DATCOM) in the lift and keeps the potential lift
/// linear in α; this follows it. Subsonic speeds; the crossflow model is meant for angles of
/// attack up to about 90°.
pub fn axisymmetric_body(
    shape: &BodyShape,
    mach: f64,
    alpha_deg: &[f64],
    reference: &BodyReference,
    warnings: &mut Vec<BodyWarning>,
) -> Result<Axisymmetric, BodyMethodError> {
    let lift = lift_curve_slope(shape, reference.area, warnings)?;
    let (cma_per_rad, area_moment) = pitching_moment_slope(shape, &lift, reference, warnings);
    let LiftCurveSlope {
        x1,
        x0,
        s0,
        k2_minus_k1,
        cla_per_rad,
    } = lift;
    let (half_area, half_area_moment) = crossflow_integrals(shape, x0, warnings);
    let eta = figures::read(figures::CROSSFLOW_ETA, &[shape.fineness], warnings)?;
    let mut angles = Vec::with_capacity(alpha_deg.len());
    for &alpha in alpha_deg {
        let a = alpha.to_radians();
        let sin = a.sin();
        let sign = if alpha < 0.0 { -1.0 } else { 1.0 };
        let cdc = figures::read(figures::CROSSFLOW_CDC, &[mach * sin.abs()], warnings)?;
        let crossflow = 2.0 * sin * sin * eta * cdc * sign;
        let cl_potential = cla_per_rad * a;
        let cl_viscous = crossflow * half_area / reference.area;
        angles.push(AxisymmetricAngle {
            alpha_deg: alpha,
            crossflow_drag_coefficient: cdc,
            cl_potential,
            cl_viscous,
            cm_potential: cma_per_rad * a,
            cm_viscous: -crossflow * (half_area_moment - shape.xcg * half_area)
                / (reference.length * reference.area),
            cd_lift: (cl_potential + cl_viscous) * sin,
        });
    }
    Ok(Axisymmetric {
        x1,
        x0,
        s0,
        k2_minus_k1,
        cla_per_rad,
        cma_per_rad,
        area_moment,
        eta,
        crossflow_half_area: half_area,
        crossflow_half_area_moment: half_area_moment,
        angles,
    })
}
