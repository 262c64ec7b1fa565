//! DATCOM 4.1.3.1, the wing zero-lift angle at subsonic speeds.

use serde::Serialize;

use super::figures::{self, CAMBER_MACH_CORRECTION, TWIST_ZERO_LIFT_ANGLE};
use super::planform::WingPlanform;
use super::{WingMethodError, WingWarning};

/// The zero-lift angle and its terms, degrees.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct ZeroLiftAngle {
    /// Section zero-lift angle.
    pub section_deg: f64,
    /// Δα0/θ of figure 4.1.3.1-4, when the wing is twisted.
    pub per_twist: Option<f64>,
    /// α0(M)/α0(M=0) of figure 4.1.3.1-5, when the section is cambered.
    pub mach_factor: Option<f64>,
    /// The wing's zero-lift angle.
    pub wing_deg: f64,
}

/// DATCOM 4.1.3.1 (the original's CALCA0): the wing zero-lift angle
///
/// α0 = [α0,section + θ (Δα0/θ)] · α0(M)/α0(M=0),
///
/// with the twist term of figure 4.1.3.1-4 (linear twist θ, deg, negative for washout; against
/// taper ratio, exposed aspect ratio and quarter-chord sweep) and the Mach correction of
/// figure 4.1.3.1-5 (against M cos Λc/4, per thickness ratio), applied to cambered sections.
/// Valid for straight-tapered wings at subsonic speeds (M cos Λc/4 up to the curves' ends,
/// where the end value is held). The original adds the twist term only for |θ| ≥ 0.5°; here
/// for any twist.
pub fn wing_zero_lift_angle(
    planform: &WingPlanform,
    section_deg: f64,
    twist_deg: f64,
    cambered: bool,
    thickness_ratio: Option<f64>,
    mach: f64,
    warnings: &mut Vec<WingWarning>,
) -> Result<ZeroLiftAngle, WingMethodError> {
    let per_twist = if twist_deg != 0.0 {
        Some(figures::read(
            TWIST_ZERO_LIFT_ANGLE,
            &[
                planform.taper,
                planform.aspect_ratio,
                planform.quarter_chord.deg,
            ],
            warnings,
        )?)
    } else {
        None
    };
    let untwisted = section_deg + per_twist.map_or(0.0, |d| d * twist_deg);
    let mach_factor = match (cambered, thickness_ratio) {
        (true, Some(tc)) => Some(figures::read(
            CAMBER_MACH_CORRECTION,
            &[100.0 * tc, mach * planform.quarter_chord.cos],
            warnings,
        )?),
        (true, None) => {
            warnings.push(WingWarning::NoCamberMachCorrection);
            None
        }
        (false, _) => None,
    };
    Ok(ZeroLiftAngle {
        section_deg,
        per_twist,
        mach_factor,
        wing_deg: untwisted * mach_factor.unwrap_or(1.0),
    })
}
