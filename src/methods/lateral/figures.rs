//! The charts the lateral methods read (files under charts/lateral/), by DATCOM figure id, and
//! one way of reading them that turns chart warnings into lateral warnings.

use super::{LateralError, LateralWarning};
use crate::charts;

/// 5.1.2.1-27: (Clβ/CL) of the half-chord sweep, per deg (taper, A, |Λc/2|).
pub const SWEEP_ROLL_PER_LIFT: &str = "5.1.2.1-27";
/// 5.1.2.1-28a: its compressibility factor K_MΛ (A/cos Λc/2, M cos Λc/2).
pub const SWEEP_COMPRESSIBILITY: &str = "5.1.2.1-28a";
/// 5.1.2.1-28b: (Clβ/CL) of the aspect ratio, per deg (taper, A).
pub const ASPECT_ROLL_PER_LIFT: &str = "5.1.2.1-28b";
/// 5.1.2.1-29: Clβ/Γ, per deg² (taper, |Λc/2|, A).
pub const DIHEDRAL_ROLL: &str = "5.1.2.1-29";
/// 5.1.2.1-30a: its compressibility factor K_MΓ (A/cos Λc/2, M cos Λc/2).
pub const DIHEDRAL_COMPRESSIBILITY: &str = "5.1.2.1-30a";
/// 5.1.2.1-31: Clβ/Γ·β/κ of the dihedral outboard of a station (taper, βA/κ,
/// atan(tan Λc/4/β), η).
pub const NON_UNIFORM_DIHEDRAL_ROLL: &str = "5.1.2.1-31";
/// 5.1.2.1-30b: ΔClβ/(θ tan Λc/4), per deg² (taper, A).
pub const TWIST_ROLL: &str = "5.1.2.1-30b";

/// 5.2.2.1-26: fuselage correction K_f of the sweep term (A/cos Λc/2, l_f/b).
pub const FUSELAGE_CORRECTION: &str = "5.2.2.1-26";
/// 5.2.3.1-8, first construction step (l_B²/S_Bs, x_m/l_B).
pub const KN_STEP_A: &str = "5.2.3.1-8a";
/// 5.2.3.1-8, second construction step (√(h1/h2), step a).
pub const KN_STEP_B: &str = "5.2.3.1-8b";
/// 5.2.3.1-8: K_N, per degree (h/w, step b).
pub const KN: &str = "5.2.3.1-8c";

/// 5.3.1.1-22a: A_v(B)/A_v (panel taper, b_v/2r₁).
pub const FIN_ASPECT_IN_BODY: &str = "5.3.1.1-22a";
/// 5.3.1.1-22b: A_v(HB)/A_v(B) (x/c_v, −z_H/b_v).
pub const FIN_ASPECT_WITH_TAIL: &str = "5.3.1.1-22b";
/// 5.3.1.1-22c: K_H (S_H/S_v).
pub const FIN_TAIL_SIZE: &str = "5.3.1.1-22c";
/// 5.3.1.1-22d: k of the panel's side force (b_v/2r₁).
pub const FIN_SIDE_FORCE_K: &str = "5.3.1.1-22d";

/// 5.3.1.1-24a: A_eff/A of a twin panel's position (BVP/BV).
pub const TWIN_PANEL_POSITION: &str = "5.3.1.1-24a";
/// 5.3.1.1-24b: a twin panel's lift-curve slope, per rad (VPHITE, A_eff).
pub const TWIN_PANEL_LIFT_SLOPE: &str = "5.3.1.1-24b";
/// 5.3.1.1-24c: the twin panels' side-force factor (BH/l_B, BDV/BV).
pub const TWIN_PANEL_BODY: &str = "5.3.1.1-24c";

/// Every chart the lateral methods read.
pub const ALL: &[&str] = &[
    SWEEP_ROLL_PER_LIFT,
    SWEEP_COMPRESSIBILITY,
    ASPECT_ROLL_PER_LIFT,
    DIHEDRAL_ROLL,
    DIHEDRAL_COMPRESSIBILITY,
    TWIST_ROLL,
    NON_UNIFORM_DIHEDRAL_ROLL,
    FUSELAGE_CORRECTION,
    KN_STEP_A,
    KN_STEP_B,
    KN,
    FIN_ASPECT_IN_BODY,
    FIN_ASPECT_WITH_TAIL,
    FIN_TAIL_SIZE,
    FIN_SIDE_FORCE_K,
    TWIN_PANEL_POSITION,
    TWIN_PANEL_LIFT_SLOPE,
    TWIN_PANEL_BODY,
];

/// The chart's value at `args`; leaving its data is a warning.
pub fn read(
    id: &'static str,
    args: &[f64],
    warnings: &mut Vec<LateralWarning>,
) -> Result<f64, LateralError> {
    let chart = charts::get(id).ok_or(LateralError::MissingChart { chart: id })?;
    let value = chart.lookup_each(args, |w| {
        let w = LateralWarning::Chart(w);
        if !warnings.contains(&w) {
            warnings.push(w);
        }
    });
    value.ok_or_else(|| LateralError::ChartNoValue {
        chart: id,
        args: args.to_vec(),
    })
}
