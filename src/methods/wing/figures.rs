//! The charts the wing methods read (files under charts/wing/, and two of charts/body/), by
//! DATCOM figure id, and one way of reading them that turns chart warnings into wing warnings.

use super::{WingMethodError, WingWarning};
use crate::charts;

/// 4.1.3.1-4: zero-lift angle change per degree of twist (taper, A, Λc/4).
pub const TWIST_ZERO_LIFT_ANGLE: &str = "4.1.3.1-4";
/// 4.1.3.1-5: Mach correction of the zero-lift angle (t/c percent, M cos Λc/4).
pub const CAMBER_MACH_CORRECTION: &str = "4.1.3.1-5";
/// 4.1.3.2-52: cranked-wing lift-curve slope ratio (βA).
pub const CRANKED_SLOPE_RATIO: &str = "4.1.3.2-52";
/// 4.1.3.3-55a: ΔCNαα below the stall (J, tan ratio).
pub const NORMAL_FORCE_INCREMENT: &str = "4.1.3.3-55a";
/// 4.1.3.3-55b: CNαα at 90° against A (A ≤ 1) and against 1/A (A > 1).
pub const NORMAL_FORCE_90_BY_ASPECT: &str = "4.1.3.3-55b-ar";
pub const NORMAL_FORCE_90_BY_INVERSE_ASPECT: &str = "4.1.3.3-55b-inverse-ar";
/// 4.1.3.3 post-stall factor D (tan ratio).
pub const POST_STALL_FACTOR: &str = "4.1.3.3-D";
/// 4.1.3.3-56: double-delta and cranked lift parameter (α, β tan Λ_LE,i).
pub const DOUBLE_DELTA_LIFT: &str = "4.1.3.3-56";
/// 4.1.3.3-57: cranked-wing break angle (1/tan Λ_LE,i).
pub const CRANKED_BREAK_ANGLE: &str = "4.1.3.3-57";
/// 4.1.3.4-21a/b: CLmax/clmax and Δα(CLmax), high aspect ratio (Δy, Λ_LE).
pub const MAX_LIFT_RATIO: &str = "4.1.3.4-21a";
pub const MAX_LIFT_ANGLE_INCREMENT: &str = "4.1.3.4-21b";
/// 4.1.3.4-22: ΔCLmax for Mach, high aspect ratio (Λ_LE, Δy, M).
pub const MAX_LIFT_MACH_INCREMENT: &str = "4.1.3.4-22";
/// 4.1.3.4-23a/b: CLmax base, low aspect ratio (Δy, (C1+1)A cos Λ_LE/β).
pub const LOW_AR_MAX_LIFT_FORWARD: &str = "4.1.3.4-23a";
pub const LOW_AR_MAX_LIFT_AFT: &str = "4.1.3.4-23b";
/// 4.1.3.4-24a: ΔCLmax, low aspect ratio (M, (C2+1)A tan Λ_LE).
pub const LOW_AR_MAX_LIFT_INCREMENT: &str = "4.1.3.4-24a";
/// 4.1.3.4-24b: taper factors C1 and C2.
pub const TAPER_FACTOR_C1: &str = "4.1.3.4-24b-c1";
pub const TAPER_FACTOR_C2: &str = "4.1.3.4-24b-c2";
/// 4.1.3.4-25a/b: α(CLmax), low aspect ratio.
pub const LOW_AR_MAX_LIFT_ANGLE: &str = "4.1.3.4-25a";
pub const LOW_AR_MAX_LIFT_ANGLE_INCREMENT: &str = "4.1.3.4-25b";
pub const LOW_AR_MAX_LIFT_ANGLE_INCREMENT_LOW: &str = "4.1.3.4-25b-low";
/// 4.1.4.1-5 and -6: Cm0 per degree of twist (taper, A, Λc/4); Cm0 Mach factor (M).
pub const TWIST_PITCHING_MOMENT: &str = "4.1.4.1-5";
pub const PITCHING_MOMENT_MACH_FACTOR: &str = "4.1.4.1-6";
/// 4.1.4.2-26a/b: aerodynamic centre over root chord (taper, A tan Λ_LE, tan Λ_LE/β or β/tan Λ_LE).
pub const AERODYNAMIC_CENTRE_SUBSONIC_EDGE: &str = "4.1.4.2-26a";
pub const AERODYNAMIC_CENTRE_SONIC_EDGE: &str = "4.1.4.2-26b";
/// The same for forward-swept leading edges (A |tan Λ_LE|, |tan Λ_LE|/β or β/|tan Λ_LE|);
/// the last as the original reads it (its supersonic table: docs/differences.md).
pub const FORWARD_AERODYNAMIC_CENTRE_SUBSONIC_EDGE: &str = "4.1.4.2-26a-forward";
pub const FORWARD_AERODYNAMIC_CENTRE_SONIC_EDGE: &str = "4.1.4.2-26b-forward";
pub const FORWARD_AERODYNAMIC_CENTRE_AS_ORIGINAL: &str = "4.1.4.2-26-forward-original";
/// 4.1.4.3: low-aspect-ratio centre of pressure.
pub const CENTRE_OF_PRESSURE_DELTA_Y: &str = "4.1.4.3-21a";
pub const CENTRE_OF_PRESSURE_TAPER_FACTOR: &str = "4.1.4.3-21b";
pub const CENTRE_OF_PRESSURE_AT_MAX_LIFT: &str = "4.1.4.3-22a";
pub const STABILITY_INDEX: &str = "4.1.4.3-22b";
pub const CENTRE_OF_PRESSURE_SHIFT_BELOW: &str = "4.1.4.3-23a";
pub const CENTRE_OF_PRESSURE_SHIFT_ABOVE: &str = "4.1.4.3-23b";
pub const ASPECT_RATIO_INDEX: &str = "4.1.4.3-24a";
pub const ASPECT_RATIO_SHIFT_BELOW: &str = "4.1.4.3-24b-1";
pub const ASPECT_RATIO_SHIFT_ABOVE: &str = "4.1.4.3-24b-2";
/// 4.1.5.1-27 (shared with the body): log10 of the cut-off Reynolds number (M, log10 l/k).
pub const CUTOFF_REYNOLDS: &str = "4.1.5.1-27";
/// 4.1.5.1-28b: lifting-surface correlation factor (M, cos Λ_tmax); dashed curves for the
/// inboard panel of two-panel wings.
pub const LIFTING_SURFACE_FACTOR: &str = "4.1.5.1-28b";
pub const LIFTING_SURFACE_FACTOR_DASHED: &str = "4.1.5.1-28b-dashed";
/// 4.1.5.2-42 and -48: twist drag factors v and βw (taper, atan(tan Λc/4/β), βA).
pub const TWIST_DRAG_V: &str = "4.1.5.2-42";
pub const TWIST_DRAG_W: &str = "4.1.5.2-48";
/// 4.1.5.2-53a (polynomial coefficients: Z, power) and -53b (Z): leading-edge suction R.
pub const SUCTION_LOW_REYNOLDS: &str = "4.1.5.2-53a";
pub const SUCTION_HIGH_REYNOLDS: &str = "4.1.5.2-53b";
/// 4.1.5.2-54: cranked-wing drag-due-to-lift increment (|CL|/A, A).
pub const CRANKED_DRAG_INCREMENT: &str = "4.1.5.2-54";
/// 4.3.1.2-10a: K_W(B) ((SSPN − SSPNE)/SSPN).
pub const WING_BODY_LIFT_RATIO: &str = "4.3.1.2-10a";

/// Every chart the wing methods read.
pub const ALL: &[&str] = &[
    TWIST_ZERO_LIFT_ANGLE,
    CAMBER_MACH_CORRECTION,
    CRANKED_SLOPE_RATIO,
    NORMAL_FORCE_INCREMENT,
    NORMAL_FORCE_90_BY_ASPECT,
    NORMAL_FORCE_90_BY_INVERSE_ASPECT,
    POST_STALL_FACTOR,
    DOUBLE_DELTA_LIFT,
    CRANKED_BREAK_ANGLE,
    MAX_LIFT_RATIO,
    MAX_LIFT_ANGLE_INCREMENT,
    MAX_LIFT_MACH_INCREMENT,
    LOW_AR_MAX_LIFT_FORWARD,
    LOW_AR_MAX_LIFT_AFT,
    LOW_AR_MAX_LIFT_INCREMENT,
    TAPER_FACTOR_C1,
    TAPER_FACTOR_C2,
    LOW_AR_MAX_LIFT_ANGLE,
    LOW_AR_MAX_LIFT_ANGLE_INCREMENT,
    LOW_AR_MAX_LIFT_ANGLE_INCREMENT_LOW,
    TWIST_PITCHING_MOMENT,
    PITCHING_MOMENT_MACH_FACTOR,
    AERODYNAMIC_CENTRE_SUBSONIC_EDGE,
    AERODYNAMIC_CENTRE_SONIC_EDGE,
    FORWARD_AERODYNAMIC_CENTRE_SUBSONIC_EDGE,
    FORWARD_AERODYNAMIC_CENTRE_SONIC_EDGE,
    FORWARD_AERODYNAMIC_CENTRE_AS_ORIGINAL,
    CENTRE_OF_PRESSURE_DELTA_Y,
    CENTRE_OF_PRESSURE_TAPER_FACTOR,
    CENTRE_OF_PRESSURE_AT_MAX_LIFT,
    STABILITY_INDEX,
    CENTRE_OF_PRESSURE_SHIFT_BELOW,
    CENTRE_OF_PRESSURE_SHIFT_ABOVE,
    ASPECT_RATIO_INDEX,
    ASPECT_RATIO_SHIFT_BELOW,
    ASPECT_RATIO_SHIFT_ABOVE,
    CUTOFF_REYNOLDS,
    LIFTING_SURFACE_FACTOR,
    LIFTING_SURFACE_FACTOR_DASHED,
    TWIST_DRAG_V,
    TWIST_DRAG_W,
    SUCTION_LOW_REYNOLDS,
    SUCTION_HIGH_REYNOLDS,
    CRANKED_DRAG_INCREMENT,
    WING_BODY_LIFT_RATIO,
];

/// The chart's value at `args`; leaving its data is a warning.
pub fn read(
    id: &'static str,
    args: &[f64],
    warnings: &mut Vec<WingWarning>,
) -> Result<f64, WingMethodError> {
    let chart = charts::get(id).ok_or(WingMethodError::MissingChart { chart: id })?;
    let value = chart.lookup_each(args, |w| {
        let w = WingWarning::Chart(w);
        if !warnings.contains(&w) {
            warnings.push(w);
        }
    });
    value.ok_or_else(|| WingMethodError::ChartNoValue {
        chart: id,
        args: args.to_vec(),
    })
}
