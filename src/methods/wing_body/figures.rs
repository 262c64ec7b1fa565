//! The charts the wing-body methods read (files under charts/wing_body/, and K_W(B) of
//! charts/wing/, which the wing's drag method shares), by DATCOM figure id, and one way of
//! reading them that turns chart warnings into wing-body warnings.

use super::{WingBodyError, WingBodyWarning};
use crate::charts;

/// 4.3.1.2-10a: K_W(B), lift of the wing in the presence of the body over the wing alone (d/b).
pub const WING_LIFT_RATIO: &str = "4.3.1.2-10a";
/// 4.3.1.2-10b: K_B(W), lift carried over onto the body over the wing alone (d/b).
pub const BODY_LIFT_RATIO: &str = "4.3.1.2-10b";
/// 4.3.1.2-12a: k_W(B) and k_B(W), the same ratios for lift due to wing incidence (d/b).
pub const WING_INCIDENCE_LIFT_RATIO: &str = "4.3.1.2-12a1";
pub const BODY_INCIDENCE_LIFT_RATIO: &str = "4.3.1.2-12a2";
/// 4.3.1.3-13a: body-vortex separation station x0/r (|α|).
pub const VORTEX_SEPARATION: &str = "4.3.1.3-13a";
/// 4.3.1.3-13b, -14, -15: vortex height z0/r, lateral position y0/r and strength (XD).
pub const VORTEX_HEIGHT: &str = "4.3.1.3-13b";
pub const VORTEX_LATERAL_POSITION: &str = "4.3.1.3-14";
pub const VORTEX_STRENGTH: &str = "4.3.1.3-15";
/// 4.3.2.2-35: the body carry-over centre term (d/b), for βA ≥ 4.
pub const CARRY_OVER_CENTRE_TERM: &str = "4.3.2.2-35";
/// 4.3.2.2-36b: the body carry-over centre at βA = 0 (A_e (1 + λ_e) tan Λ_LE / 4).
pub const CARRY_OVER_CENTRE_AT_ZERO_BETA_A: &str = "4.3.2.2-36b";
/// 4.3.3.1-37: R_WB, the wing-body interference factor of the zero-lift drag (M, R_l).
pub const DRAG_INTERFERENCE: &str = "4.3.3.1-37";
/// The original's drag-due-to-lift regression of straight-wing bodies (M, |α|, term index).
pub const DRAG_REGRESSION: &str = "4.3.3.1-regression";

/// Every chart the wing-body methods read.
pub const ALL: &[&str] = &[
    WING_LIFT_RATIO,
    BODY_LIFT_RATIO,
    WING_INCIDENCE_LIFT_RATIO,
    BODY_INCIDENCE_LIFT_RATIO,
    VORTEX_SEPARATION,
    VORTEX_HEIGHT,
    VORTEX_LATERAL_POSITION,
    VORTEX_STRENGTH,
    CARRY_OVER_CENTRE_TERM,
    CARRY_OVER_CENTRE_AT_ZERO_BETA_A,
    DRAG_INTERFERENCE,
    DRAG_REGRESSION,
];

/// The chart's value at `args`; leaving its data is a warning (a refusal gives `None`).
pub fn read_optional(
    id: &'static str,
    args: &[f64],
    warnings: &mut Vec<WingBodyWarning>,
) -> Result<Option<f64>, WingBodyError> {
    let chart = charts::get(id).ok_or(WingBodyError::MissingChart { chart: id })?;
    let value = chart.lookup_each(args, |w| {
        let w = WingBodyWarning::Chart(w);
        if !warnings.contains(&w) {
            warnings.push(w);
        }
    });
    Ok(value)
}

/// The chart's value at `args`; leaving its data is a warning, a refusal an error.
pub fn read(
    id: &'static str,
    args: &[f64],
    warnings: &mut Vec<WingBodyWarning>,
) -> Result<f64, WingBodyError> {
    read_optional(id, args, warnings)?.ok_or_else(|| WingBodyError::ChartNoValue {
        chart: id,
        args: args.to_vec(),
    })
}
