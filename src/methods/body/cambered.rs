//! Cambered body (the original's "asymmetrical body": upper and lower contours ZU, ZL given):
//! zero-lift angle and moment from the camber line, potential and viscous normal force with
//! the body-aspect-ratio factors kp and kv, and the onset angle of viscous crossflow (DATCOM
//! 4.2.1.2 and 4.2.2.1 cambered-body method; the original's routine BODOPT, lines 1805-2155).

use std::f64::consts::PI;

use serde::Serialize;

use super::figures;
use super::shape::BodyShape;
use super::tables::{first_maximum, trapezoid, Resampled};
use super::{BodyMethodError, BodyReference, BodyWarning};

/// The potential normal force acts at a fraction of the station where the radius first reaches
/// this fraction of its largest value (the original's X95, "0.95 YMAX", computed with 0.96).
const FOREBODY_RADIUS_FRACTION: f64 = 0.96;
/// Width over depth and fineness ratio the original reads Fig. 4.2.1.2-37 at when the base
/// area is zero.
const POINTED_BASE_WIDTH_OVER_DEPTH: f64 = 3.0;
const POINTED_BASE_FINENESS: f64 = 10.0;

/// The quantities of the cambered-body method.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Cambered {
    /// Zero-lift angle of attack from the camber line, deg.
    pub alpha0_deg: f64,
    /// Pitching moment at zero lift from the camber line, about XCG.
    pub cm0: f64,
    /// Planform area 2∫r dx, m².
    pub planform_area: f64,
    /// Body aspect ratio 4 rmax²/Sp.
    pub aspect_ratio: f64,
    /// Potential normal-force factor kp (Fig. 4.2.1.2-36a).
    pub kp: f64,
    /// Viscous normal-force factor kv (Fig. 4.2.1.2-36b).
    pub kv: f64,
    /// Base width over base depth, a/b.
    pub width_over_depth: f64,
    /// Fineness ratio on the base area, l / √(4 S_base/π).
    pub base_fineness: f64,
    /// Angle of attack where viscous crossflow begins (Fig. 4.2.1.2-37), deg.
    pub alpha_v_deg: f64,
    /// Station where the radius first reaches 0.96 of its largest value, m from the nose.
    pub forebody_station: f64,
    /// Planform area ahead of that station, m².
    pub forebody_planform_area: f64,
    /// Centre of the potential normal force over the body length.
    pub potential_centre_over_length: f64,
    /// Planform centroid (where the viscous normal force acts) over the body length.
    pub planform_centroid_over_length: f64,
    /// Lift-curve slope kp Sp/S at α0, per radian (the original's first-row CLA).
    pub cla_per_rad: f64,
    /// Pitching-moment slope at α0, per radian (the original's first-row CMA).
    pub cma_per_rad: f64,
    pub angles: Vec<CamberedAngle>,
}

/// The terms of the normal force, moment and drag due to lift at one angle of attack.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct CamberedAngle {
    pub alpha_deg: f64,
    /// Potential normal force kp sin(α − α0) cos(α − α0) Sp/S.
    pub cn_potential: f64,
    /// Viscous normal force kv sin²(α − αv) Sp/S, zero up to αv.
    pub cn_viscous: f64,
    /// Moment of the potential normal force about XCG.
    pub cm_potential: f64,
    /// Moment of the viscous normal force about XCG.
    pub cm_viscous: f64,
    /// Drag due to lift CN sin(α − α0).
    pub cd_lift: f64,
}

/// Zero-lift angle (deg) and zero-lift moment coefficient per unit (Sp/S)(l/c̄) of a cambered
/// body, from the camber line z'(ξ) measured from the chord through the end mid-points:
/// α0 = −(1/π) ∫ (z'/l) / ((1 − ξ) √(ξ(1 − ξ))) dξ and Cm0 ∝ 2 ∫ (z'/l)(1 − 2ξ)/√(ξ(1 − ξ)) dξ,
/// ξ = x/l, on 20 equal stations (BODOPT lines 1932-2002). As the original, the α0 integral
/// leaves out the last interval, where the integrand is singular.
fn camber_line_terms(shape: &BodyShape, zu: &[f64], zl: &[f64]) -> (f64, f64) {
    let n = shape.x.len();
    let l = shape.length;
    let mid = |k: usize| 0.5 * (zu[k] + zl[k]);
    let (z_nose, z_base) = (mid(0), mid(n - 1));
    let chord_slope = (z_base - z_nose) / l;
    let camber_over_length: Vec<f64> = (0..n)
        .map(|k| (mid(k) - (shape.x[k] * chord_slope + z_nose)) / l)
        .collect();
    let table = Resampled::new(&shape.x, &camber_over_length);
    let xi: Vec<f64> = table.x.iter().map(|x| x / l).collect();
    let m = xi.len();
    let mut alpha_integrand = vec![0.0; m];
    let mut moment_integrand = vec![0.0; m];
    for k in 1..m - 1 {
        let q = (xi[k] - xi[k] * xi[k]).sqrt();
        alpha_integrand[k] = table.f[k] / ((1.0 - xi[k]) * q);
        moment_integrand[k] = table.f[k] * (1.0 - 2.0 * xi[k]) / q;
    }
    let alpha0_rad = -trapezoid(&xi[..m - 1], &alpha_integrand[..m - 1]) / PI;
    let cm0_unit = 2.0 * trapezoid(&xi, &moment_integrand);
    (alpha0_rad.to_degrees(), cm0_unit)
}

/// The forebody up to the station where the radius first reaches 0.96 of its largest value
/// (the original's X95), the largest being at station `imax`.
struct Forebody {
    /// The station, m, and its radius.
    x96: f64,
    r96: f64,
    /// Planform area ahead of it, m².
    area: f64,
}

/// None for a blunt nose: the radius reaches 0.96 of its largest value at the first station.
///
/// The original finds the station on the interval ending at the largest radius, extrapolating
/// when the radius is already above 0.96 of it at the interval's start; where that puts it at
/// or before the nose (its forebody would have no area, or it reads outside its arrays) the
/// station is found where the radius first reaches the value.
fn forebody(shape: &BodyShape, imax: usize) -> Result<Option<Forebody>, &'static str> {
    let (x, r) = (&shape.x, &shape.r);
    let r96 = FOREBODY_RADIUS_FRACTION * r[imax];
    let on = |k: usize| x[k - 1] + (x[k] - x[k - 1]) * (r96 - r[k - 1]) / (r[k] - r[k - 1]);
    let mut x96 = if imax > 0 {
        on(imax)
    } else {
        f64::NEG_INFINITY
    };
    // At or before the nose, or not a number (a flat interval).
    let ahead_of_nose = x96.partial_cmp(&x[0]) != Some(std::cmp::Ordering::Greater);
    if ahead_of_nose {
        match r.iter().position(|&rk| rk >= r96) {
            Some(k) if k > 0 => x96 = on(k),
            _ => return Ok(None),
        }
    }
    let i96 = shape
        .x
        .iter()
        .position(|&x| x >= x96)
        .ok_or("the station of 0.96 of the largest radius lies aft of the body")?;
    let mut fx = shape.x[..=i96].to_vec();
    let mut fr = shape.r[..=i96].to_vec();
    fx[i96] = x96;
    fr[i96] = r96;
    let area = 2.0 * Resampled::new(&fx, &fr).integral();
    if area <= 0.0 || !area.is_finite() {
        return Err("no planform area ahead of the station of 0.96 of the largest radius");
    }
    Ok(Some(Forebody { x96, r96, area }))
}

/// Normal force, pitching moment and drag due to lift of a cambered body at each angle of
/// attack (DATCOM 4.2.1.2 cambered-body method with 4.2.2.1; original: BODOPT, lines
/// 2007-2152).
///
/// CN = [kp sin(α−α0) cos(α−α0) + kv sin²(α−αv)] Sp/S (the viscous part only above αv),
/// with kp, kv from figures 4.2.1.2-36a/b at the body aspect ratio 4 rmax²/Sp and αv from
/// figure 4.2.1.2-37 at the base's width over depth and fineness ratio; CD = CD0 +
/// CN sin(α−α0); CM = Cm0 + the potential force at its centre + the viscous force at the
/// planform centroid, about XCG; CL = (CN − CD sin α)/cos α. Subsonic speeds; the viscous
/// crossflow acts on the positive-α side only.
pub fn cambered_body(
    shape: &BodyShape,
    zu: &[f64],
    zl: &[f64],
    cd0: f64,
    alpha_deg: &[f64],
    reference: &BodyReference,
    warnings: &mut Vec<BodyWarning>,
) -> Result<(Cambered, Vec<f64>), BodyMethodError> {
    let n = shape.x.len();
    let undefined = |reason: String| Err(BodyMethodError::CamberedBodyUndefined { reason });
    let given = zu.len().min(zl.len());
    if given < n {
        warnings.push(BodyWarning::ContoursShort { given, stations: n });
    }
    let padded =
        |z: &[f64]| -> Vec<f64> { (0..n).map(|k| z.get(k).copied().unwrap_or(0.0)).collect() };
    let (zu, zl) = (&padded(zu)[..], &padded(zl)[..]);
    let l = shape.length;
    let (alpha0_deg, cm0_unit) = camber_line_terms(shape, zu, zl);
    let planform = Resampled::new(&shape.x, &shape.r);
    let planform_area = 2.0 * planform.integral();
    if planform_area <= 0.0 || !planform_area.is_finite() {
        return undefined("the body has no planform area".into());
    }
    let area_ratio = planform_area / reference.area;
    let length_ratio = l / reference.length;
    let cm0 = cm0_unit * area_ratio * length_ratio;

    let Some(imax) = first_maximum(&shape.r) else {
        return undefined("no radius along the body".into());
    };
    let r_max = shape.r[imax];
    let aspect_ratio = 4.0 * r_max * r_max / planform_area;
    let kp = figures::read(figures::POTENTIAL_FACTOR, &[aspect_ratio], warnings)?;
    let kv = figures::read(figures::VISCOUS_FACTOR, &[aspect_ratio], warnings)?;

    let base_area = shape.s[n - 1];
    let base_diameter = (4.0 * base_area / PI).sqrt();
    let (width_over_depth, base_fineness) = if base_diameter == 0.0 {
        (POINTED_BASE_WIDTH_OVER_DEPTH, POINTED_BASE_FINENESS)
    } else {
        let depth = zu[n - 1] - zl[n - 1];
        let width = 2.0 * shape.r[n - 1];
        let ratio = if depth != 0.0 {
            width / depth
        } else if width == 0.0 {
            0.0
        } else {
            return undefined(
                "the base has an area but no depth (ZU = ZL at the last station)".into(),
            );
        };
        (ratio, l / base_diameter)
    };

    let forebody =
        forebody(shape, imax).map_err(|reason| BodyMethodError::CamberedBodyUndefined {
            reason: reason.into(),
        })?;
    if forebody.is_none() {
        warnings.push(BodyWarning::BluntNose);
    }
    let alpha_v_deg = figures::read(
        figures::CROSSFLOW_ONSET,
        &[width_over_depth, base_fineness],
        warnings,
    )?;
    let (x96, forebody_planform_area, potential_centre_over_length) = match forebody {
        // With the forebody's radius a power law r ∝ x^e through (x96, r96) of the same
        // planform area, the area grows as x^2e and the potential loading dS/dx has its centre
        // at 2e/(2e+1) of x96.
        Some(Forebody { x96, r96, area }) => {
            let exponent = 2.0 * r96 * x96 / area - 1.0;
            (x96, area, 2.0 * exponent / (2.0 * exponent + 1.0) * x96 / l)
        }
        // A blunt nose: the area grows in a step there, where the loading acts.
        None => (shape.x[0], 0.0, shape.x[0] / l),
    };
    let potential_arm = shape.xcg / l - potential_centre_over_length;
    let strips: f64 = planform
        .x
        .windows(2)
        .zip(planform.f.windows(2))
        .map(|(x, r)| {
            let strip_area = 2.0 * 0.5 * (x[1] - x[0]) * (r[0] + r[1]);
            strip_area * 0.5 * (x[0] + x[1])
        })
        .sum();
    let planform_centroid_over_length = strips / planform_area / l;
    let viscous_arm = shape.xcg / l - planform_centroid_over_length;

    let mut angles = Vec::with_capacity(alpha_deg.len());
    let mut cl = Vec::with_capacity(alpha_deg.len());
    for &alpha in alpha_deg {
        let from_zero_lift = (alpha - alpha0_deg).to_radians();
        let (sin0, cos0) = from_zero_lift.sin_cos();
        let potential = kp * sin0 * cos0;
        let viscous = if alpha > alpha_v_deg {
            let s = (alpha - alpha_v_deg).to_radians().sin();
            kv * s * s
        } else {
            0.0
        };
        let cn = (potential + viscous) * area_ratio;
        let cd_lift = cn * sin0;
        let (sin, cos) = alpha.to_radians().sin_cos();
        if cos.abs() < f64::EPSILON {
            warnings.push(BodyWarning::NoValue {
                alpha_deg: alpha,
                coefficient: "CL",
                reason: "the lift is the normal force over cos α, and cos α is zero",
            });
            cl.push(f64::NAN);
        } else {
            cl.push((cn - (cd0 + cd_lift) * sin) / cos);
        }
        angles.push(CamberedAngle {
            alpha_deg: alpha,
            cn_potential: potential * area_ratio,
            cn_viscous: viscous * area_ratio,
            cm_potential: potential * potential_arm * area_ratio * length_ratio,
            cm_viscous: viscous * viscous_arm * area_ratio * length_ratio,
            cd_lift,
        });
    }
    Ok((
        Cambered {
            alpha0_deg,
            cm0,
            planform_area,
            aspect_ratio,
            kp,
            kv,
            width_over_depth,
            base_fineness,
            alpha_v_deg,
            forebody_station: x96,
            forebody_planform_area,
            potential_centre_over_length,
            planform_centroid_over_length,
            cla_per_rad: kp * area_ratio,
            cma_per_rad: kp * potential_arm * area_ratio * length_ratio,
            angles,
        },
        cl,
    ))
}
