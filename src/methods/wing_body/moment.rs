//! Wing-body pitching moment at subsonic speeds, DATCOM 4.3.2: the wing's moment with its
//! interference lift at the wing's centre of pressure, the lift carried over onto the body at
//! its own aerodynamic centre (DATCOM 4.3.2.2), the body vortex's lift and the wing's axial
//! force at its height.

use serde::Serialize;

use super::figures;
use super::lift::InterferenceFactors;
use super::{WingBodyError, WingBodyWarning};

/// βA_e at and above which the carry-over centre is the slender-body value of figure
/// 4.3.2.2-35; below it the original fairs an ellipse to the βA = 0 value (figure 4.3.2.2-36b).
pub const SLENDER_BODY_BETA_A: f64 = 4.0;
/// x'ac/c_re at βA = 0 when A_e (1 + λ_e) tan Λ_LE / 4 ≥ 1 (the original's value).
const CENTRE_AT_ZERO_BETA_A_ABOVE_1: f64 = 0.5;
/// Quarter chord.
const QUARTER: f64 = 0.25;

/// The aerodynamic centre of the lift carried over onto the body.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct CarryOverCentre {
    /// x'ac/c_re at βA = 0 (figure 4.3.2.2-36b).
    pub at_zero_beta_a: f64,
    /// Slender-body value 1/4 + (b − d)/(2 c_re) tan Λ_c/4 BRAC (figure 4.3.2.2-35).
    pub slender_body: f64,
    /// βA_e.
    pub beta_a: f64,
    /// x_ac/c_re behind the exposed root's leading edge at this βA.
    pub over_root_chord: f64,
    /// The same in reference lengths (the original's XAC/C-B(W)).
    pub over_reference_length: f64,
}

/// Planform inputs of [`carry_over_centre`].
#[derive(Debug, Clone, Copy)]
pub struct CarryOverInputs {
    /// Exposed aspect ratio, taper ratio and root chord (m).
    pub exposed_aspect_ratio: f64,
    pub exposed_taper: f64,
    pub exposed_root_chord: f64,
    /// tan Λ_LE and tan Λ_c/4 of the planform.
    pub tan_leading_edge: f64,
    pub tan_quarter_chord: f64,
    /// Span 2 SSPN and body width at the wing 2 (SSPN − SSPNE), m.
    pub span: f64,
    pub body_width: f64,
    pub beta: f64,
    pub reference_length: f64,
}

impl CarryOverInputs {
    /// The inputs of a surface (wing, or horizontal tail on the body) from its planform terms
    /// `p`: its exposed panel, span 2 b′/2 and body width 2 (b′/2 − b′e/2), at `beta`, on the
    /// reference length `reference_length`.
    pub fn of_planform(
        p: &crate::methods::wing::WingPlanform,
        beta: f64,
        reference_length: f64,
    ) -> CarryOverInputs {
        CarryOverInputs {
            exposed_aspect_ratio: p.aspect_ratio,
            exposed_taper: p.taper,
            exposed_root_chord: p.exposed_root_chord,
            tan_leading_edge: p.leading_edge.tan,
            tan_quarter_chord: p.quarter_chord.tan,
            span: 2.0 * p.semispan,
            body_width: 2.0 * (p.semispan - p.exposed_semispan),
            beta,
            reference_length,
        }
    }
}

/// DATCOM 4.3.2.2, figures 4.3.2.2-35 (βA_e ≥ 4) and -36b (βA_e = 0): the aerodynamic centre
/// of the lift carried over onto the body, behind the exposed root's leading edge. Between
/// βA_e = 0 and 4 the original fairs the quarter ellipse
/// x/c_re = x0 + (x4 − x0) √(1 − ((βA_e − 4)/4)²). Subsonic. Original: WBCM.
pub fn carry_over_centre(
    i: &CarryOverInputs,
    warnings: &mut Vec<WingBodyWarning>,
) -> Result<CarryOverCentre, WingBodyError> {
    let sweep_parameter =
        i.exposed_aspect_ratio * (1.0 + i.exposed_taper) * i.tan_leading_edge / 4.0;
    let at_zero_beta_a = if sweep_parameter < 1.0 {
        figures::read(
            figures::CARRY_OVER_CENTRE_AT_ZERO_BETA_A,
            &[sweep_parameter],
            warnings,
        )?
    } else {
        CENTRE_AT_ZERO_BETA_A_ABOVE_1
    };
    let brac = figures::read(
        figures::CARRY_OVER_CENTRE_TERM,
        &[i.body_width / i.span],
        warnings,
    )?;
    let slender_body = QUARTER
        + (i.span - i.body_width) / (2.0 * i.exposed_root_chord) * i.tan_quarter_chord * brac;
    let beta_a = i.beta * i.exposed_aspect_ratio;
    let over_root_chord = if beta_a >= SLENDER_BODY_BETA_A {
        slender_body
    } else {
        let u = (beta_a - SLENDER_BODY_BETA_A) / SLENDER_BODY_BETA_A;
        at_zero_beta_a + (slender_body - at_zero_beta_a) * (1.0 - u * u).max(0.0).sqrt()
    };
    Ok(CarryOverCentre {
        at_zero_beta_a,
        slender_body,
        beta_a,
        over_root_chord,
        over_reference_length: over_root_chord * i.exposed_root_chord / i.reference_length,
    })
}

/// The pitching moment of the combination at one angle and its terms, about the moment
/// reference centre, on S and c̄.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct MomentAtAngle {
    pub alpha_deg: f64,
    /// Body alone.
    pub body: f64,
    /// Wing zero-lift moment Cm0.
    pub wing_zero_lift: f64,
    /// Centre of pressure of the wing's lift ahead of the reference centre,
    /// (Cm_W − Cm0)/CN_W, in reference lengths (0 where CN_W = 0).
    pub wing_centre_of_pressure: f64,
    /// The wing in the presence of the body: [(CN_W − CLα_W i_W) K_W(B) + CLα_W i_W k_W(B)]
    /// times the wing's centre of pressure.
    pub wing_in_presence_of_body: f64,
    /// The lift carried over onto the body: [(CN_W − CLα_W i_W) K_B(W) + CLα_W i_W k_B(W)]
    /// times (x_ref − x_ac,B(W))/c̄.
    pub carry_over: f64,
    /// The body vortex's lift at the wing's centre of pressure.
    pub body_vortex: f64,
    /// The wing's axial force at its height: CA_W (z_W − z_ref)/c̄.
    pub axial_force: f64,
    /// The sum.
    pub cm: f64,
}

/// Inputs of [`wing_body_moment`] that do not change with angle of attack.
#[derive(Debug, Clone, Copy)]
pub struct MomentInputs<'a> {
    pub factors: &'a InterferenceFactors,
    /// CLα_W i_W: wing lift-curve slope (per rad) times the incidence (rad).
    pub incidence_lift: f64,
    pub wing_zero_lift_moment: f64,
    /// (x_ref − x_ac,B(W))/c̄: the carry-over lift's lever, positive ahead of the reference.
    pub carry_over_lever: f64,
    /// (z_W − z_ref)/c̄.
    pub wing_height: f64,
}

/// The wing-alone values at one angle the moment needs.
#[derive(Debug, Clone, Copy)]
pub struct WingAtAngle {
    pub cm: f64,
    pub cn: f64,
    pub ca: f64,
}

/// DATCOM 4.3.2.1 (eq. 4.3.2.1-a in the form of the original): Cm_WB = Cm_B + Cm0_W +
/// [(CN_W − CLα_W i_W) K_W(B) + CLα_W i_W k_W(B)] Δx_W + [(CN_W − CLα_W i_W) K_B(W) +
/// CLα_W i_W k_B(W)] Δx_B(W) + ΔCN_vortex Δx_W + CA_W (z_W − z_ref)/c̄, where Δx_W =
/// (Cm_W − Cm0_W)/CN_W is the wing's centre of pressure and Δx_B(W) that of the carry-over lift
/// (DATCOM 4.3.2.2), both ahead of the reference centre in reference lengths. Subsonic.
/// Original: WBCM.
pub fn wing_body_moment(
    i: &MomentInputs,
    alpha_deg: f64,
    body_cm: f64,
    wing: WingAtAngle,
    vortex_normal_force: f64,
) -> MomentAtAngle {
    let f = i.factors;
    let wing_centre_of_pressure = if wing.cn != 0.0 {
        (wing.cm - i.wing_zero_lift_moment) / wing.cn
    } else {
        0.0
    };
    let angle_lift = wing.cn - i.incidence_lift;
    let wing_in_presence_of_body = (angle_lift * f.wing_in_presence_of_body
        + i.incidence_lift * f.wing_incidence)
        * wing_centre_of_pressure;
    let carry_over = (angle_lift * f.body_in_presence_of_wing
        + i.incidence_lift * f.body_incidence)
        * i.carry_over_lever;
    let body_vortex = vortex_normal_force * wing_centre_of_pressure;
    let axial_force = wing.ca * i.wing_height;
    MomentAtAngle {
        alpha_deg,
        body: body_cm,
        wing_zero_lift: i.wing_zero_lift_moment,
        wing_centre_of_pressure,
        wing_in_presence_of_body,
        carry_over,
        body_vortex,
        axial_force,
        cm: body_cm
            + i.wing_zero_lift_moment
            + wing_in_presence_of_body
            + carry_over
            + body_vortex
            + axial_force,
    }
}
