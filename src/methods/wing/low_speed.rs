//! The wing at Mach 0 (the original's CLMCH0): the reference lift of the wing's sideslip side
//! force and the angle scale of the downwash.

use super::section_inputs::at_last_mach;
use super::{computed_wing_section, wing_alone_parts, Parts, WingAlone, WingMethodError};
use crate::case::{Case, ZeroLiftReading};
use crate::deck::cards::Surface;
use crate::methods::body::subsonic_limit;

/// TSMACH when not given, and its limits (as the original's INPUTB).
const DEFAULT_TSMACH: f64 = 1.4;
const TSMACH_RANGE: (f64, f64) = (1.01, 1.4);

/// The wing alone at Mach 0 and the rule it was computed with.
#[derive(Debug, Clone, PartialEq)]
pub struct MachZeroWing {
    /// Its lift only: the drag and pitching-moment columns and terms are none (the Mach-0
    /// wing serves the sideslip and downwash methods by its lift).
    pub wing: WingAlone,
    /// The section's CLAMO replaced its first lift-curve slope (a Mach number of the case lies
    /// between STMACH and TSMACH and CLAMO is given).
    pub transonic_slope: bool,
}

/// The wing-alone method at M = 0 (β = 1) for flight condition `condition_index` (its Reynolds
/// number), as the original's CLMCH0 computes it once per case: the section's first lift-curve
/// slope, CLAMO in its place when any Mach number of the case is transonic (between STMACH and
/// TSMACH), and the low-speed maximum lift CLMAXL in place of the first CLMAX (the computed
/// section's maximum lift without CLMAXL).
pub fn mach_zero_wing(
    case: &Case,
    condition_index: usize,
    alpha_deg: &[f64],
) -> Result<MachZeroWing, WingMethodError> {
    let condition = case
        .conditions
        .get(condition_index)
        .ok_or(WingMethodError::NoCondition {
            index: condition_index,
        })?;
    let stmach = subsonic_limit(case);
    let tsmach = case
        .flight
        .as_ref()
        .and_then(|f| f.tsmach)
        .unwrap_or(DEFAULT_TSMACH)
        .clamp(TSMACH_RANGE.0, TSMACH_RANGE.1);
    let any_transonic = case
        .conditions
        .iter()
        .any(|c| c.mach > stmach && c.mach < tsmach);
    let wing_name = Surface::Wing.name();
    // The wing's section input alone: the wing methods read no other surface's.
    let mut proxy = case.with_sections(
        case.sections
            .get(wing_name)
            .map(|s| (wing_name.to_string(), s.clone()))
            .into_iter()
            .collect(),
    );
    let user = case.sections.get(wing_name);
    let scalar = |n: &str| user.and_then(|u| u.scalars.get(n).copied());
    let mut transonic_slope = false;
    if let Some(s) = proxy.sections.get_mut(wing_name) {
        match scalar("CLMAXL") {
            Some(l) => {
                s.per_mach.insert("CLMAX".into(), vec![l]);
            }
            None => {
                s.per_mach.remove("CLMAX");
            }
        }
        if any_transonic {
            if let Some(c) = scalar("CLAMO") {
                s.per_mach.insert("CLALPA".into(), vec![c]);
                transonic_slope = true;
            }
        }
    }
    let mut low = condition.clone();
    low.mach = 0.0;
    low.mach_index = 0;
    proxy.conditions = vec![low];
    let computed = computed_wing_section(case).transpose()?.map(|mut c| {
        // Under the original's rule the Mach-0 wing takes the zero-lift angle and the
        // maximum lift its section method left after the last Mach number (CLMCH0 after
        // SECO); they differ from the first Mach number's when RNNUB varies with it.
        let zero_lift = at_last_mach(case, &c, |m| m.zero_lift_alpha_deg);
        let max_cl = at_last_mach(case, &c, |m| m.max_cl);
        c.per_mach.truncate(1);
        if case.zero_lift == ZeroLiftReading::Original {
            if let Some(first) = c.per_mach.first_mut() {
                first.zero_lift_alpha_deg = zero_lift.or(first.zero_lift_alpha_deg);
                first.max_cl = max_cl.or(first.max_cl);
            }
        }
        c
    });
    let wing = wing_alone_parts(&proxy, 0, alpha_deg, computed.as_ref(), Parts::Lift)?;
    Ok(MachZeroWing {
        wing,
        transonic_slope,
    })
}
