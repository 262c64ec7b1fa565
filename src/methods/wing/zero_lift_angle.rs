//! DATCOM 4.1.3.1, the wing zero-lift angle at subsonic speeds.

use serde::Serialize;

use super::figures::{self, CAMBER_MACH_CORRECTION, TWIST_ZERO_LIFT_ANGLE};
use super::planform::WingPlanform;
use super::{WingMethodError, WingWarning};

/// How the wing's zero-lift angle is read.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum ZeroLiftReading {
    /// DATCOM 4.1.3.1: the section's low-speed zero-lift angle, figure 4.1.3.1-4 read linearly
    /// in taper ratio, aspect ratio and sweep. The rate derivatives (7.1.2.2, 7.1.2.3) read
    /// zero lift on the rising part of the lift curve.
    #[default]
    Handbook,
    /// As the original program (SECO, CALCA0): the section's zero-lift angle as its section
    /// method left it after the last Mach number it computed (for every Mach number of the
    /// case, and, with the section's maximum lift from there, for the wing at Mach 0: CLMCH0),
    /// figure 4.1.3.1-4 read as [`twist_term_as_the_original`] does and applied only to
    /// a twist of 0.5° or more; the rate
    /// derivatives read zero lift on the whole lift curve (SUBRYW), where a curve that falls
    /// through zero beyond the stall gives that crossing. For reproducing old listings
    /// (docs/wing.md, docs/differences.md).
    Original,
}

/// The least twist (deg, either sign) the original's CALCA0 corrects the zero-lift angle for;
/// below it the wing's zero-lift angle is the untwisted one.
const ORIGINAL_MIN_TWIST_DEG: f64 = 0.5;

/// The distance within which the original's CALCA0 takes a node's curve of figure 4.1.3.1-4
/// without interpolating (its own bracketing, not the chart's GLOOK tolerance).
const ORIGINAL_NODE_SNAP: f64 = 0.02;

/// Where `x` lies among `nodes` as the original's CALCA0 brackets it: `(upper, fraction)` with
/// the fraction from node `upper − 1`, or `(node, None)` when `x` is within
/// [`ORIGINAL_NODE_SNAP`] of a node or beyond the ends (the end node).
fn original_bracket(x: f64, nodes: &[f64]) -> (usize, Option<f64>) {
    for (i, &n) in nodes.iter().enumerate() {
        if (x - n).abs() < ORIGINAL_NODE_SNAP {
            return (i, None);
        }
        if x < n {
            return if i == 0 {
                (0, None)
            } else {
                (i, Some((x - nodes[i - 1]) / (n - nodes[i - 1])))
            };
        }
    }
    (nodes.len() - 1, None)
}

/// Figure 4.1.3.1-4 (Δα0/θ) read as the original's CALCA0 reads it: each variable bracketed
/// on its own (a value within 0.02 of a node takes the node), linear in sweep, then in aspect
/// ratio, then in taper ratio; but on the lower taper curve, when the aspect ratio lies above
/// 6, it reads the aspect-ratio pair one lower (3.5 and 6, with the fraction between 6 and 10;
/// above 10, the curve at 6), its table having ten columns for the twelve curves. The same as
/// the linear reading wherever the taper ratio or the aspect ratio is at a node or the aspect
/// ratio is at most 6.
pub fn twist_term_as_the_original(
    taper: f64,
    aspect_ratio: f64,
    sweep_deg: f64,
    warnings: &mut Vec<WingWarning>,
) -> Result<f64, WingMethodError> {
    // The chart's taper-ratio and aspect-ratio nodes (its outer two axes).
    let chart = crate::charts::get(TWIST_ZERO_LIFT_ANGLE);
    let (Some(taper_nodes), Some(aspect_nodes)) = (
        chart.and_then(|c| c.axis_nodes(0)),
        chart.and_then(|c| c.axis_nodes(1)),
    ) else {
        // No chart: the linear reading reports it.
        return figures::read(
            TWIST_ZERO_LIFT_ANGLE,
            &[taper, aspect_ratio, sweep_deg],
            warnings,
        );
    };
    let (t_upper, t_fraction) = original_bracket(taper, taper_nodes);
    let (a_upper, a_fraction) = original_bracket(aspect_ratio, aspect_nodes);
    // The aspect ratio read on a taper curve, from the pair of nodes ending at `upper`.
    let on_pair = |upper: usize| match a_fraction {
        Some(f) => aspect_nodes[upper - 1] + f * (aspect_nodes[upper] - aspect_nodes[upper - 1]),
        None => aspect_nodes[upper],
    };
    let mut curve =
        |t: f64, a: f64| figures::read(TWIST_ZERO_LIFT_ANGLE, &[t, a, sweep_deg], warnings);
    let upper = curve(taper_nodes[t_upper], on_pair(a_upper))?;
    let Some(f) = t_fraction else {
        return Ok(upper);
    };
    let last = aspect_nodes.len() - 1;
    let lower_pair = if a_upper == last { last - 1 } else { a_upper };
    let lower = curve(taper_nodes[t_upper - 1], on_pair(lower_pair))?;
    Ok(lower + f * (upper - lower))
}

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
/// for any twist, and with [`ZeroLiftReading::Original`] as the original.
pub fn wing_zero_lift_angle(
    planform: &WingPlanform,
    section_deg: f64,
    twist_deg: f64,
    cambered: bool,
    thickness_ratio: Option<f64>,
    mach: f64,
    warnings: &mut Vec<WingWarning>,
) -> Result<ZeroLiftAngle, WingMethodError> {
    wing_zero_lift_angle_read(
        planform,
        section_deg,
        twist_deg,
        cambered,
        thickness_ratio,
        mach,
        ZeroLiftReading::Handbook,
        warnings,
    )
}

/// [`wing_zero_lift_angle`] with figure 4.1.3.1-4 read by `reading`.
#[allow(clippy::too_many_arguments)]
pub fn wing_zero_lift_angle_read(
    planform: &WingPlanform,
    section_deg: f64,
    twist_deg: f64,
    cambered: bool,
    thickness_ratio: Option<f64>,
    mach: f64,
    reading: ZeroLiftReading,
    warnings: &mut Vec<WingWarning>,
) -> Result<ZeroLiftAngle, WingMethodError> {
    let (taper, aspect_ratio, sweep) = (
        planform.taper,
        planform.aspect_ratio,
        planform.quarter_chord.deg,
    );
    // The original's CALCA0 leaves a twist below ORIGINAL_MIN_TWIST_DEG out.
    let twist_deg =
        if reading == ZeroLiftReading::Original && twist_deg.abs() < ORIGINAL_MIN_TWIST_DEG {
            0.0
        } else {
            twist_deg
        };
    let per_twist = if twist_deg == 0.0 {
        None
    } else if reading == ZeroLiftReading::Original {
        Some(twist_term_as_the_original(
            taper,
            aspect_ratio,
            sweep,
            warnings,
        )?)
    } else {
        Some(figures::read(
            TWIST_ZERO_LIFT_ANGLE,
            &[taper, aspect_ratio, sweep],
            warnings,
        )?)
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
