//! Wing-body lift at subsonic speeds, DATCOM 4.3.1.2 (interference factors of slender-body
//! theory) with the lift the body's vortices take from the wing, DATCOM 4.3.1.3.

use serde::Serialize;

use super::figures;
use super::{WingBodyError, WingBodyWarning};

/// Body width over wing span above which DATCOM gives the combination's lift-curve slope by
/// figure 4.3.1.2-12c instead of the interference factors (not covered).
pub const LARGE_BODY_SPAN_RATIO: f64 = 0.8;
/// Below this absolute angle of attack, deg, no vortex leaves the body (DATCOM 4.3.1.3; the
/// original's BODOWG).
pub const VORTEX_ONSET_ALPHA_DEG: f64 = 6.0;
/// Degrees per radian the original's length parameter XD divides by.
const DEG_PER_RAD: f64 = 57.29578;

/// The lift ratios of slender-body theory at one body-width-to-span ratio.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct InterferenceFactors {
    /// d/b: body width at the wing, 2 (SSPN − SSPNE), over the span 2 SSPN.
    pub body_span_ratio: f64,
    /// K_W(B): lift of the wing in the presence of the body over that of the wing alone.
    pub wing_in_presence_of_body: f64,
    /// K_B(W): lift carried over onto the body over that of the wing alone.
    pub body_in_presence_of_wing: f64,
    /// k_W(B), k_B(W): the same ratios for the lift due to wing incidence.
    pub wing_incidence: f64,
    pub body_incidence: f64,
}

impl InterferenceFactors {
    /// (k_W(B) + k_B(W)) / (K_W(B) + K_B(W)): the fraction of the incidence that acts as angle
    /// of attack of the combination.
    pub fn incidence_effectiveness(&self) -> f64 {
        (self.wing_incidence + self.body_incidence)
            / (self.wing_in_presence_of_body + self.body_in_presence_of_wing)
    }
}

/// DATCOM 4.3.1.2, figures 4.3.1.2-10a and -10b (K_W(B), K_B(W)) and 4.3.1.2-12a (k_W(B),
/// k_B(W)), read at the body-width-to-span ratio d/b. Valid for d/b ≤ 0.8 (beyond it DATCOM
/// gives the slope of the combination by figure 4.3.1.2-12c, not covered). Original: WBLIFT.
pub fn interference_factors(
    body_span_ratio: f64,
    warnings: &mut Vec<WingBodyWarning>,
) -> Result<InterferenceFactors, WingBodyError> {
    if body_span_ratio.is_nan() || body_span_ratio > LARGE_BODY_SPAN_RATIO {
        return Err(WingBodyError::LargeBody {
            body_span_ratio,
            limit: LARGE_BODY_SPAN_RATIO,
        });
    }
    let at = [body_span_ratio];
    Ok(InterferenceFactors {
        body_span_ratio,
        wing_in_presence_of_body: figures::read(figures::WING_LIFT_RATIO, &at, warnings)?,
        body_in_presence_of_wing: figures::read(figures::BODY_LIFT_RATIO, &at, warnings)?,
        wing_incidence: figures::read(figures::WING_INCIDENCE_LIFT_RATIO, &at, warnings)?,
        body_incidence: figures::read(figures::BODY_INCIDENCE_LIFT_RATIO, &at, warnings)?,
    })
}

/// Position and strength of the body's vortex pair at one angle of attack, and the lift
/// factor it gives the wing.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct BodyVortex {
    pub alpha_deg: f64,
    /// x0/r, where the vortices leave the body (none below 6° of |α|).
    pub separation_station: Option<f64>,
    /// XD = |α| (x_c/4/r − x0/r)/57.3 (none below 6° of |α|).
    pub length_parameter: Option<f64>,
    /// Vortex height z0/r and lateral position y0/r at the wing (none when no vortex reaches it).
    pub height: Option<f64>,
    pub lateral_position: Option<f64>,
    /// Γ/(2π a V r sin α), the vortex strength parameter (0 without a vortex).
    pub strength: f64,
    /// i_W(B), the wing's interference factor of the vortex pair (0 without a vortex).
    pub interference_factor: f64,
}

/// DATCOM 4.3.1.3, figures 4.3.1.3-13a, -13b, -14 and -15: the body vortex pair at the wing.
/// For |α| ≥ 6° the vortices leave the body at x0 (figure 13a); when the wing's quarter chord
/// of the MAC, `x_quarter_chord` from the nose, lies behind x0, their height, lateral position
/// and strength follow from XD = |α| (x_c/4 − x0)/(57.3 r) and the wing's interference factor
/// from strip theory ([`vortex_interference_factor`]). `body_radius` is √(S_max/π); the span
/// is the wing's semispan `semispan`, `exposed_taper` its exposed taper ratio. Original: BODOWG.
pub fn body_vortex(
    alpha_deg: f64,
    x_quarter_chord: f64,
    body_radius: f64,
    semispan: f64,
    exposed_taper: f64,
    warnings: &mut Vec<WingBodyWarning>,
) -> Result<BodyVortex, WingBodyError> {
    let mut v = BodyVortex {
        alpha_deg,
        separation_station: None,
        length_parameter: None,
        height: None,
        lateral_position: None,
        strength: 0.0,
        interference_factor: 0.0,
    };
    let a = alpha_deg.abs();
    if a < VORTEX_ONSET_ALPHA_DEG {
        return Ok(v);
    }
    let x0 = figures::read(figures::VORTEX_SEPARATION, &[a], warnings)?;
    let xd = a * (x_quarter_chord / body_radius - x0) / DEG_PER_RAD;
    v.separation_station = Some(x0);
    v.length_parameter = Some(xd);
    if xd <= 0.0 {
        return Ok(v);
    }
    let z0 = figures::read(figures::VORTEX_HEIGHT, &[xd], warnings)?;
    let y0 = figures::read(figures::VORTEX_LATERAL_POSITION, &[xd], warnings)?;
    v.height = Some(z0);
    v.lateral_position = Some(y0);
    v.strength = figures::read(figures::VORTEX_STRENGTH, &[xd], warnings)?;
    v.interference_factor = vortex_interference_factor(
        z0 * body_radius,
        y0 * body_radius,
        semispan,
        body_radius,
        exposed_taper,
    );
    Ok(v)
}

/// DATCOM 4.3.1.3: the interference factor i of a vortex pair at height `z0` and lateral
/// position `y0` (from the body axis) on a tapered wing panel from the body radius `r` to the
/// semispan `s` with taper `taper`, by strip theory with the body's image vortices at
/// (r² y0, r² z0)/(y0² + z0²):
///
/// i = 2/(1 + λ) [L(y0, z0) − L(−y0, z0) − L(y_i, z_i) + L(−y_i, z_i)],
/// L(y, z) = (s − λr − (1 − λ) y)/(2(s − r)) ln((z² + (y − s)²)/(z² + (y − r)²))
///           − (1 − λ)/(s − r) [z atan((y − s)/z) − z atan((y − r)/z) + s − r].
///
/// Original: FUNCTION ALI.
pub fn vortex_interference_factor(z0: f64, y0: f64, s: f64, r: f64, taper: f64) -> f64 {
    let span = s - r;
    let strip = |y: f64, z: f64| -> f64 {
        let log = ((z * z + (y - s).powi(2)) / (z * z + (y - r).powi(2))).ln();
        let arc = if z == 0.0 {
            span
        } else {
            z * ((y - s) / z).atan() - z * ((y - r) / z).atan() + span
        };
        (s - taper * r - (1.0 - taper) * y) / (2.0 * span) * log - (1.0 - taper) / span * arc
    };
    let d = y0 * y0 + z0 * z0;
    let (yi, zi) = (y0 * r * r / d, z0 * r * r / d);
    2.0 / (1.0 + taper) * (strip(y0, z0) - strip(-y0, z0) - strip(yi, zi) + strip(-yi, zi))
}

/// The lift of the combination at one angle of attack and its terms.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct LiftAtAngle {
    pub alpha_deg: f64,
    /// Body alone.
    pub body: Option<f64>,
    /// Angle at which the wing-alone lift curve is read: α + ALIW (k_W(B) + k_B(W))/(K_W(B) +
    /// K_B(W)), deg.
    pub wing_alpha_deg: f64,
    /// The wing-alone lift there.
    pub wing_alone: Option<f64>,
    /// (K_W(B) + K_B(W)) times it: the wing in the presence of the body and the lift carried
    /// over onto the body.
    pub wing_and_carry_over: Option<f64>,
    /// Lift the body vortices take from the wing: i_W(B) Γ/(2π a V r sin α) (α + ALIW) CLα_W
    /// (SSPN − SSPNE)/SSPN (negative: a loss).
    pub body_vortex: f64,
    /// The sum.
    pub cl: Option<f64>,
}

/// Inputs of [`wing_body_lift`] that do not change with angle of attack.
#[derive(Debug, Clone, Copy)]
pub struct LiftInputs<'a> {
    pub factors: &'a InterferenceFactors,
    /// Wing incidence ALIW, deg.
    pub incidence_deg: f64,
    /// Wing-alone lift-curve slope, per rad.
    pub wing_slope_per_rad: f64,
    /// (SSPN − SSPNE)/SSPN.
    pub body_semispan_fraction: f64,
    /// Wing angles (schedule angle + ALIW), deg, and the wing-alone lift there.
    pub wing_alpha_deg: &'a [f64],
    pub wing_cl: &'a [Option<f64>],
}

/// DATCOM 4.3.1.2, eq. 4.3.1.2-a with the incidence terms of 4.3.1.2-b and the vortex term of
/// 4.3.1.3: CL_WB = CL_B + (K_W(B) + K_B(W)) CL_W(α + ALIW (k_W(B) + k_B(W))/(K_W(B) + K_B(W))) +
/// i_W(B) Γ/(2π a V r sin α) (α + ALIW) CLα_W (SSPN − SSPNE)/SSPN, on the wing-alone lift
/// curve (nonlinear as the wing method gives it; read linearly between its angles and
/// extrapolated from its end chords). Valid at subsonic speeds for d/b ≤ 0.8. Original: WBLIFT.
pub fn wing_body_lift(
    i: &LiftInputs,
    alpha_deg: f64,
    body_cl: Option<f64>,
    vortex: &BodyVortex,
) -> LiftAtAngle {
    let f = i.factors;
    let ratio = f.wing_in_presence_of_body + f.body_in_presence_of_wing;
    let wing_alpha_deg = alpha_deg + i.incidence_effectiveness_deg(f);
    let wing_alone = lift_curve_at(i.wing_alpha_deg, i.wing_cl, wing_alpha_deg);
    let wing_and_carry_over = wing_alone.map(|cl| ratio * cl);
    let body_vortex = vortex.interference_factor
        * vortex.strength
        * (alpha_deg + i.incidence_deg).to_radians()
        * i.body_semispan_fraction
        * i.wing_slope_per_rad;
    let cl = match (body_cl, wing_and_carry_over) {
        (Some(b), Some(w)) => Some(b + w + body_vortex).filter(|v| v.is_finite()),
        _ => None,
    };
    LiftAtAngle {
        alpha_deg,
        body: body_cl,
        wing_alpha_deg,
        wing_alone,
        wing_and_carry_over,
        body_vortex,
        cl,
    }
}

impl LiftInputs<'_> {
    /// ALIW (k_W(B) + k_B(W))/(K_W(B) + K_B(W)), deg.
    fn incidence_effectiveness_deg(&self, f: &InterferenceFactors) -> f64 {
        if self.incidence_deg == 0.0 {
            0.0
        } else {
            self.incidence_deg * f.incidence_effectiveness()
        }
    }
}

/// The tabulated lift curve at `at`: linear between angles, extrapolated from the end chords
/// (the original's TBFUNX with LEXL = LEXU = 1); a curve of one angle is its value. None where
/// a point it needs is none.
fn lift_curve_at(alpha: &[f64], cl: &[Option<f64>], at: f64) -> Option<f64> {
    let n = alpha.len().min(cl.len());
    if n == 0 {
        return None;
    }
    if let Some(k) = alpha[..n].iter().position(|a| *a == at) {
        return cl[k];
    }
    if n == 1 {
        // One angle: the curve is its one value (TBFUNX with one point).
        return cl[0];
    }
    let k = if at < alpha[0] {
        0
    } else {
        (0..n - 1).find(|&k| at <= alpha[k + 1]).unwrap_or(n - 2)
    };
    let (x0, x1) = (alpha[k], alpha[k + 1]);
    let (y0, y1) = (cl[k]?, cl[k + 1]?);
    (x1 != x0).then(|| y0 + (y1 - y0) * (at - x0) / (x1 - x0))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lift_curve_is_read_between_and_beyond_its_angles() {
        let a = [0.0, 2.0, 4.0];
        let c = [Some(0.0), Some(0.2), Some(0.3)];
        assert_eq!(lift_curve_at(&a, &c, 2.0), Some(0.2));
        assert!((lift_curve_at(&a, &c, 1.0).unwrap() - 0.1).abs() < 1e-12);
        assert!((lift_curve_at(&a, &c, 6.0).unwrap() - 0.4).abs() < 1e-12);
        assert!((lift_curve_at(&a, &c, -2.0).unwrap() + 0.2).abs() < 1e-12);
    }
}
