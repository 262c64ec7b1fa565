//! The horizontal tail in the presence of the wing and body at subsonic speeds: DATCOM 4.3.1.2
//! and 4.3.2 applied to the tail (interference factors K_H(B), K_B(H), k_H(B), k_B(H), the body
//! vortex on the tail, 4.3.1.3) behind the wing's downwash and wake (4.4.1), summed as in
//! DATCOM 4.5.1 (the original's WBTAIL, non-canard branch).

use serde::Serialize;

use super::table::{read, End};
use super::{TailError, TailWarning};
use crate::methods::wing_body::{
    body_vortex, interference_factors, BodyVortex, InterferenceFactors,
};

/// The tail-body terms at one angle of attack (coefficients on the reference area; moments
/// about (XCG, ZCG) on the reference length).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct TailAtAngle {
    pub alpha_deg: f64,
    /// q/q∞, ε (deg) and dε/dα at the tail.
    pub dynamic_pressure_ratio: f64,
    pub epsilon_deg: f64,
    pub gradient: f64,
    /// Tail angle from its zero-lift angle, α + ALIH − ε − α0_H, deg, and the tail-alone CL,
    /// CD there (on the reference area, per unit q).
    pub tail_alpha_deg: f64,
    pub tail_cl: f64,
    pub tail_cd: f64,
    /// Angle at which the tail's lift in the presence of the body is read: α − α0_H + ALIH
    /// (k_H(B) + k_B(H))/(K_H(B) + K_B(H)) − ε, deg.
    pub effective_alpha_deg: f64,
    /// q (K_H(B) + K_B(H)) CL_H(effective angle): the tail's lift with its carry-over.
    pub lift: f64,
    /// The body vortices' lift on the tail: i_H(B) Γ/(2π a V r) (r/b_H/2) q CLα_H (α + ALIH −
    /// α0_H − ε).
    pub vortex_lift: f64,
    /// The tail's lift along its own normal and its drag at q: ((lift + vortex)/q + CD_H sin
    /// ε)/cos ε · q and CD_H q.
    pub normal_force: f64,
    pub axial_force: f64,
    /// Moment of the tail's forces: (x_cg − x_ac,H)/c̄ (N cos(α − ε) + A sin(α − ε)) and
    /// (z_H − z_cg)/c̄ (A cos(α − ε) − N sin(α − ε)), and Cm0_H q.
    pub moment_of_normal_force: f64,
    pub moment_of_axial_force: f64,
    pub zero_lift_moment: f64,
    /// Drag: (CD_H cos ε + CL_H sin ε) q.
    pub drag: f64,
}

/// What the tail-body terms take from the tail alone and the geometry.
#[derive(Debug, Clone, Copy)]
pub struct TailBodyInputs<'a> {
    /// (SSPN_H − SSPNE_H)/SSPN_H.
    pub body_semispan_fraction: f64,
    /// Tail angles α + ALIH, deg, its zero-lift angle, deg, and its CL, CD there.
    pub tail_alpha_deg: &'a [f64],
    pub tail_zero_lift_deg: f64,
    pub tail_cl: &'a [Option<f64>],
    pub tail_cd: &'a [Option<f64>],
    /// CLα_H, per rad, and Cm0_H, on the reference dimensions.
    pub tail_slope_per_rad: f64,
    pub tail_zero_lift_moment: f64,
    pub incidence_deg: f64,
    /// (x_cg − x_ac,H)/c̄ and (z_H − z_cg)/c̄.
    pub lever: f64,
    pub height: f64,
    /// x of the tail's theoretical-MAC quarter chord from the nose, body radius √(S_max/π),
    /// tail semispan, exposed taper: the body vortex at the tail.
    pub x_quarter_chord: f64,
    pub body_radius: f64,
    pub semispan: f64,
    pub exposed_taper: f64,
}

/// The interference factors and vortices of the tail-body terms.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct TailBody {
    pub interference: InterferenceFactors,
    pub vortices: Vec<BodyVortex>,
    pub at_angle: Vec<Option<TailAtAngle>>,
}

/// See [`TailAtAngle`]; DATCOM 4.3.1.2 (figures 4.3.1.2-10a, -10b, -12a at the tail's d/b,
/// valid up to 0.8), 4.3.1.3 (figures 4.3.1.3-13a to -15), 4.4.1. Original: WBTAIL.
pub fn tail_body(
    i: &TailBodyInputs,
    alpha_deg: &[f64],
    q: &[Option<f64>],
    epsilon_deg: &[Option<f64>],
    gradient: &[Option<f64>],
    warnings: &mut Vec<TailWarning>,
) -> Result<TailBody, TailError> {
    let mut wb_warnings = Vec::new();
    let interference = interference_factors(i.body_semispan_fraction, &mut wb_warnings)
        .map_err(TailError::WingBody)?;
    let vortices = alpha_deg
        .iter()
        .map(|&a| {
            body_vortex(
                a,
                i.x_quarter_chord,
                i.body_radius,
                i.semispan,
                i.exposed_taper,
                &mut wb_warnings,
            )
        })
        .collect::<Result<Vec<_>, _>>()
        .map_err(TailError::WingBody)?;
    warnings.extend(wb_warnings.into_iter().map(TailWarning::WingBody));
    let from_zero: Vec<f64> = i
        .tail_alpha_deg
        .iter()
        .map(|a| a - i.tail_zero_lift_deg)
        .collect();
    let k_sum = interference.wing_in_presence_of_body + interference.body_in_presence_of_wing;
    let incidence_share = if k_sum == 0.0 {
        0.0
    } else {
        (interference.wing_incidence + interference.body_incidence) / k_sum
    };
    let at_angle = (0..alpha_deg.len())
        .map(|k| {
            let (q, eps, grad) = (q[k]?, epsilon_deg[k]?, gradient[k]?);
            let a = alpha_deg[k];
            let tail_alpha = a + i.incidence_deg - eps - i.tail_zero_lift_deg;
            let tail_cl = read(&from_zero, i.tail_cl, tail_alpha, End::Linear, End::Linear)?.0;
            let tail_cd = read(&from_zero, i.tail_cd, tail_alpha, End::Linear, End::Linear)?.0;
            let effective = a - i.tail_zero_lift_deg + incidence_share * i.incidence_deg - eps;
            let lift =
                read(&from_zero, i.tail_cl, effective, End::Linear, End::Linear)?.0 * q * k_sum;
            let v = &vortices[k];
            let vortex_lift = v.interference_factor
                * v.strength
                * i.body_radius
                * q
                * i.tail_slope_per_rad
                * tail_alpha.to_radians()
                / i.semispan;
            let (se, ce) = eps.to_radians().sin_cos();
            let normal_force = ((lift + vortex_lift) / q + tail_cd * se) / ce * q;
            let axial_force = tail_cd * q;
            let (s, c) = (a - eps).to_radians().sin_cos();
            let moment_of_normal_force = i.lever * (normal_force * c + axial_force * s);
            let moment_of_axial_force = i.height * (axial_force * c - normal_force * s);
            let zero_lift_moment = i.tail_zero_lift_moment * q;
            let drag = (tail_cd * ce + tail_cl * se) * q;
            let out = TailAtAngle {
                alpha_deg: a,
                dynamic_pressure_ratio: q,
                epsilon_deg: eps,
                gradient: grad,
                tail_alpha_deg: tail_alpha,
                tail_cl,
                tail_cd,
                effective_alpha_deg: effective,
                lift,
                vortex_lift,
                normal_force,
                axial_force,
                moment_of_normal_force,
                moment_of_axial_force,
                zero_lift_moment,
                drag,
            };
            [
                lift,
                vortex_lift,
                normal_force,
                moment_of_normal_force,
                moment_of_axial_force,
                drag,
            ]
            .iter()
            .all(|v| v.is_finite())
            .then_some(out)
        })
        .collect();
    Ok(TailBody {
        interference,
        vortices,
        at_angle,
    })
}
