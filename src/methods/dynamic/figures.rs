//! The charts the dynamic-derivative methods read (files under charts/dynamic/), by DATCOM
//! figure id, and one way of reading them that turns chart warnings into dynamic warnings.

use super::{DynamicError, DynamicWarning};
use crate::charts;

/// 7.1.4.1-6: β CL_g/(πA/2) of a triangular wing (βA).
pub const ALPHA_DOT_LIFT: &str = "7.1.4.1-6";
/// 7.1.4.2-8: β Cm0_g/(Aπ/2) of a triangular wing (βA).
pub const ALPHA_DOT_MOMENT: &str = "7.1.4.2-8";
/// 7.1.2.1-9, construction steps and (CYp/CL) (A; sweep, step a; taper, step b).
pub const ROLL_SIDE_FORCE_STEP_A: &str = "7.1.2.1-9-step-a";
pub const ROLL_SIDE_FORCE_STEP_B: &str = "7.1.2.1-9-step-b";
pub const ROLL_SIDE_FORCE: &str = "7.1.2.1-9";
/// 7.1.2.2-20a to -20d: β Clp/κ at zero lift for taper 0, 0.25, 0.5 and 1 (βA/κ, Λβ).
pub const ROLL_DAMPING: [&str; 4] = ["7.1.2.2-20a", "7.1.2.2-20b", "7.1.2.2-20c", "7.1.2.2-20d"];
/// The taper ratios of the four roll-damping charts.
pub const ROLL_DAMPING_TAPERS: [f64; 4] = [0.0, 0.25, 0.5, 1.0];
/// 7.1.2.2-24: (ΔClp)_drag/CL² (sweep, A).
pub const ROLL_DAMPING_DRAG: &str = "7.1.2.2-24";
/// 7.1.2.3-12: ΔCnp/θ (taper, A).
pub const ROLL_YAW_TWIST: &str = "7.1.2.3-12";
/// 7.1.3.2-10: the sweep-free ordinate of (Clr/CL) (taper, A).
pub const YAW_ROLL_UNIT: &str = "7.1.3.2-10";
/// 7.1.3.2-9 as the original codes it: the sweep scale of the ordinate (sweep).
pub const YAW_ROLL_INTERCEPT: &str = "7.1.3.2-9-intercept";
pub const YAW_ROLL_SLOPE: &str = "7.1.3.2-9-slope";
/// 7.1.3.2-11: ΔClr/θ (taper, A).
pub const YAW_ROLL_TWIST: &str = "7.1.3.2-11";
/// 7.1.3.3-6: Cnr/CL², construction step (x̄, sweep, A) and result (taper, step).
pub const YAW_DAMPING_STEP: &str = "7.1.3.3-6-step";
pub const YAW_DAMPING_LIFT: &str = "7.1.3.3-6";
/// 7.1.3.3-7: Cnr/CD0 (x̄, |sweep|, A).
pub const YAW_DAMPING_DRAG: &str = "7.1.3.3-7";

/// Every chart the dynamic methods read.
pub const ALL: &[&str] = &[
    ALPHA_DOT_LIFT,
    ALPHA_DOT_MOMENT,
    ROLL_SIDE_FORCE_STEP_A,
    ROLL_SIDE_FORCE_STEP_B,
    ROLL_SIDE_FORCE,
    ROLL_DAMPING[0],
    ROLL_DAMPING[1],
    ROLL_DAMPING[2],
    ROLL_DAMPING[3],
    ROLL_DAMPING_DRAG,
    ROLL_YAW_TWIST,
    YAW_ROLL_UNIT,
    YAW_ROLL_INTERCEPT,
    YAW_ROLL_SLOPE,
    YAW_ROLL_TWIST,
    YAW_DAMPING_STEP,
    YAW_DAMPING_LIFT,
    YAW_DAMPING_DRAG,
];

/// The chart's value at `args`; leaving its data is a warning.
pub fn read(
    id: &'static str,
    args: &[f64],
    warnings: &mut Vec<DynamicWarning>,
) -> Result<f64, DynamicError> {
    let chart = charts::get(id).ok_or(DynamicError::MissingChart { chart: id })?;
    let value = chart.lookup_each(args, |w| {
        let w = DynamicWarning::Chart(w);
        if !warnings.contains(&w) {
            warnings.push(w);
        }
    });
    value.ok_or_else(|| DynamicError::ChartNoValue {
        chart: id,
        args: args.to_vec(),
    })
}
