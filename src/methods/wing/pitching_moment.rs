//! DATCOM 4.1.4, the wing's subsonic pitching moment: zero-lift moment (4.1.4.1),
//! aerodynamic centre (4.1.4.2) and the nonlinear centre of pressure of low-aspect-ratio wings
//! (4.1.4.3) (the original's CMALPH).

use std::f64::consts::FRAC_PI_2;

use serde::Serialize;

use super::figures::{self, *};
use super::lift::LiftAtAngle;
use super::planform::WingPlanform;
use super::{WingMethodError, WingType, WingWarning, NONLINEAR_ASPECT_LIMIT};

/// What the methods do with a forward-swept wing where the original departs from DATCOM: the
/// aerodynamic centre of a forward-swept leading edge at subsonic speeds where |tan Λ_LE|/β
/// exceeds 1 (figure 4.1.4.2-26, forward sweep), and the vertical panels' roll-rate terms
/// with a forward-swept quarter chord.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum ForwardSweepReading {
    /// The subsonic chart in β/|tan Λ_LE| (it joins the chart in |tan Λ_LE|/β at 1 and the
    /// supersonic chart at Mach 1); the fins' Clp and Clr as for any wing.
    #[default]
    Handbook,
    /// As the original program: its supersonic chart in tan Λ_LE/β read at β/|tan Λ_LE|, the
    /// subsonic one never read (FWDXAC); the fins' Clp and Clr left out (NDM) when the wing's
    /// quarter chord is swept forward (CLRDER). For reproducing old listings
    /// (docs/differences.md).
    Original,
}

/// Ratio of tan α(CLmax) to tan α at the reference angle of the nonlinear method.
const REFERENCE_TANGENT_RATIO: f64 = 0.6;

/// Zero-lift pitching moment, DATCOM 4.1.4.1 and its terms.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct ZeroLiftMoment {
    /// Section cm0 used.
    pub section_cm0: f64,
    /// Figure 4.1.4.1-6 Mach factor times S_exp c̄_exp/(S_ref c̄_ref).
    pub scale: f64,
    /// ΔCm0/θ of figure 4.1.4.1-5 when the wing is twisted.
    pub per_twist: Option<f64>,
    /// Cm0 on the reference area and length.
    pub cm0: f64,
}

/// DATCOM 4.1.4.1 equation 4.1.4.1-a with the twist term and the Mach correction:
///
/// Cm0 = [A cos²Λc/4 / (A + 2 cos Λc/4) cm0 + (ΔCm0/θ) θ] (Cm0,M/Cm0,M=0) S_exp c̄_exp/(S_ref c̄_ref),
///
/// figures 4.1.4.1-5 (twist, as modified in Digital DATCOM) and 4.1.4.1-6 (Mach). Subsonic,
/// straight-tapered planforms (the original applies it to every type).
pub fn zero_lift_moment(
    p: &WingPlanform,
    section_cm0: f64,
    twist_deg: f64,
    mach: f64,
    reference_area: f64,
    reference_length: f64,
    warnings: &mut Vec<WingWarning>,
) -> Result<ZeroLiftMoment, WingMethodError> {
    let mach_factor = figures::read(PITCHING_MOMENT_MACH_FACTOR, &[mach], warnings)?;
    let scale = mach_factor * p.exposed_area * p.mac / (reference_area * reference_length);
    let a = p.aspect_ratio;
    let c = p.quarter_chord.cos;
    let per_twist = if twist_deg != 0.0 {
        Some(figures::read(
            TWIST_PITCHING_MOMENT,
            &[p.taper, a, p.quarter_chord.deg],
            warnings,
        )?)
    } else {
        None
    };
    let cm0 = (a * c * c / (a + 2.0 * c) * section_cm0 + per_twist.map_or(0.0, |d| d * twist_deg))
        * scale;
    Ok(ZeroLiftMoment {
        section_cm0,
        scale,
        per_twist,
        cm0,
    })
}

/// x_ac/c_r of figure 4.1.4.2-26 for a trapezoid of aspect ratio `a`, taper `taper` and
/// leading-edge sweep tangent `tan_le`, in A |tan Λ_LE|: chart a in |tan Λ_LE|/β below the
/// sonic leading edge, chart b in β/|tan Λ_LE| beyond. A forward-swept leading edge
/// (tan Λ_LE < 0) reads the forward-sweep charts, its chart b by `reading` (the original's
/// FWDXAC; docs/wing.md). As the original, the edge itself is read in chart b when swept back
/// and in chart a when swept forward.
fn trapezoid_aerodynamic_centre(
    a: f64,
    taper: f64,
    tan_le: f64,
    beta: f64,
    reading: ForwardSweepReading,
    warnings: &mut Vec<WingWarning>,
) -> Result<f64, WingMethodError> {
    let tan = tan_le.abs();
    let edge = tan / beta;
    let (chart_a, chart_b, in_chart_a) = if tan_le < 0.0 {
        let chart_b = match reading {
            ForwardSweepReading::Handbook => FORWARD_AERODYNAMIC_CENTRE_SONIC_EDGE,
            ForwardSweepReading::Original => FORWARD_AERODYNAMIC_CENTRE_AS_ORIGINAL,
        };
        (
            FORWARD_AERODYNAMIC_CENTRE_SUBSONIC_EDGE,
            chart_b,
            edge <= 1.0,
        )
    } else {
        (
            AERODYNAMIC_CENTRE_SUBSONIC_EDGE,
            AERODYNAMIC_CENTRE_SONIC_EDGE,
            edge < 1.0,
        )
    };
    if in_chart_a {
        figures::read(chart_a, &[taper, a * tan, edge], warnings)
    } else {
        figures::read(chart_b, &[taper, a * tan, beta / tan], warnings)
    }
}

/// Inputs of [`aerodynamic_centre`].
#[derive(Debug, Clone, Copy)]
pub struct CentreInputs<'a> {
    pub planform: &'a WingPlanform,
    pub kind: WingType,
    /// The low-aspect-ratio method applies (figure 4.1.4.2-26 for a straight-tapered wing).
    pub low_aspect_ratio: bool,
    /// The section's aerodynamic centre over its chord, when known.
    pub section_xac: Option<f64>,
    pub beta: f64,
    /// CLα of the inboard and the extended outboard panel (double-delta and cranked wings).
    pub panel_slopes: (Option<f64>, Option<f64>),
    pub reading: ForwardSweepReading,
}

/// The aerodynamic centre, behind the exposed root's leading edge over the exposed root
/// chord (DATCOM 4.1.4.2; the original's CMALPH):
///
/// - straight-tapered, not low aspect ratio: the exposed MAC's quarter chord, moved by the
///   section's aerodynamic centre (XAC − 0.25) when known;
/// - straight-tapered, low aspect ratio: figure 4.1.4.2-26;
/// - double-delta and cranked: the inboard panel's and the extended outboard panel's
///   figure-26 values weighted by their CLα S (DATCOM 4.1.4.2 method for non-straight
///   planforms).
///
/// A forward-swept leading edge (of the wing or a panel) reads the forward-sweep charts of
/// figure 4.1.4.2-26 by `reading` (the original's FWDXAC).
pub fn aerodynamic_centre(
    i: &CentreInputs,
    warnings: &mut Vec<WingWarning>,
) -> Result<f64, WingMethodError> {
    let CentreInputs {
        planform: p,
        kind,
        low_aspect_ratio,
        section_xac,
        beta,
        panel_slopes,
        reading,
    } = *i;
    let root = p.exposed_root_chord;
    if kind == WingType::Straight {
        if !low_aspect_ratio {
            let quarter = (p.x_mac_mid_chord - 0.25 * p.mac) / root;
            return Ok(quarter + section_xac.map_or(0.0, |x| p.mac * (x - 0.25) / root));
        }
        return trapezoid_aerodynamic_centre(
            p.aspect_ratio,
            p.taper,
            p.leading_edge.tan,
            beta,
            reading,
            warnings,
        );
    }
    let (Some(o), Some(e), (Some(cla_in), Some(cla_out))) =
        (&p.outboard, &p.extended_outboard, panel_slopes)
    else {
        return Err(WingMethodError::Degenerate {
            reason: "a double-delta or cranked wing needs an outboard panel (SSPNOP, CHRDBP)"
                .into(),
        });
    };
    let tan_in = p.inboard.leading_edge.tan;
    let tan_out = o.leading_edge.tan;
    let inboard = trapezoid_aerodynamic_centre(
        p.inboard.aspect_ratio,
        p.inboard.taper,
        tan_in,
        beta,
        reading,
        warnings,
    )?;
    let outboard_own =
        trapezoid_aerodynamic_centre(e.aspect_ratio, e.taper, tan_out, beta, reading, warnings)?;
    // The extended panel's a.c. from the exposed root: its root lies at mid inboard span.
    let half_in = p.inboard.span / 2.0;
    let outboard = outboard_own * e.root_chord / root - half_in * tan_out / root
        + p.inboard.span * tan_in / root;
    let w_in = cla_in * p.inboard.area;
    let w_out = cla_out * e.area;
    Ok((w_in * inboard + w_out * outboard) / (w_in + w_out))
}

/// Terms of the nonlinear centre of pressure (DATCOM 4.1.4.3).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct NonlinearCentre {
    /// Centre of pressure at 90°, over the root chord.
    pub at_90: f64,
    /// Centre of pressure at maximum lift term (figures 21a + 22a).
    pub at_max_lift: f64,
    pub stability_index: f64,
    pub aspect_ratio_index: f64,
    /// Reference angle, rad: tan α_ref = tan α(CLmax)/0.6.
    pub reference_alpha_rad: f64,
    /// Centre of pressure at the reference angle, over the root chord.
    pub at_reference: f64,
}

/// The pitching moment terms.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct PitchingMoment {
    pub zero_lift: ZeroLiftMoment,
    /// Aerodynamic centre behind the exposed root's leading edge, over the exposed root chord.
    pub aerodynamic_centre: f64,
    /// Moment reference behind the exposed root's leading edge, over the exposed root chord.
    pub moment_reference: f64,
    /// dCm/dCL = (x_ref − x_ac) c_r / c̄_ref.
    pub dcm_dcl: f64,
    /// The nonlinear method's terms, when it applies.
    pub nonlinear: Option<NonlinearCentre>,
    /// Cm at each angle.
    pub cm: Vec<f64>,
}

/// Inputs of the moment curve.
pub struct MomentInputs<'a> {
    pub planform: &'a WingPlanform,
    pub kind: WingType,
    /// (C1 + 1) cos Λ_LE.
    pub c1_cos_le: f64,
    pub zero_lift: ZeroLiftMoment,
    pub aerodynamic_centre: f64,
    pub moment_reference: f64,
    pub reference_length: f64,
    pub alpha_max_lift_deg: Option<f64>,
    pub delta_y_percent: f64,
}

/// Whether the linear moment applies: A > 6/((C1 + 1) cos Λ_LE), or a forward-swept leading
/// edge.
pub fn linear_moment_applies(p: &WingPlanform, c1_cos_le: f64) -> bool {
    p.aspect_ratio > NONLINEAR_ASPECT_LIMIT / c1_cos_le || p.leading_edge.deg < 0.0
}

/// DATCOM 4.1.4: Cm(α) = Cm0 + CN' (x_ref − x_cp(α)) c_r/c̄_ref, with x_cp = x_ac (linear
/// method, A > 6/((C1 + 1) cos Λ_LE)) or the nonlinear centre of pressure of DATCOM 4.1.4.3
/// (figures 4.1.4.3-21 to -24) between x_ac at zero lift, the value at maximum lift and that
/// at 90° (low aspect ratio). CN' is the lift method's normal force.
pub fn pitching_moment(
    i: &MomentInputs,
    lift: &[LiftAtAngle],
    warnings: &mut Vec<WingWarning>,
) -> Result<Option<PitchingMoment>, WingMethodError> {
    let p = i.planform;
    let root = p.exposed_root_chord;
    let lever = root / i.reference_length;
    let dcm_dcl = (i.moment_reference - i.aerodynamic_centre) * lever;
    let cm0 = i.zero_lift.cm0;
    let mut out = PitchingMoment {
        zero_lift: i.zero_lift,
        aerodynamic_centre: i.aerodynamic_centre,
        moment_reference: i.moment_reference,
        dcm_dcl,
        nonlinear: None,
        cm: Vec::with_capacity(lift.len()),
    };
    if linear_moment_applies(p, i.c1_cos_le) {
        out.cm = lift.iter().map(|l| l.cn * dcm_dcl + cm0).collect();
        return Ok(Some(out));
    }
    let Some(alpha_max) = i.alpha_max_lift_deg else {
        return Ok(None);
    };
    let taper = p.taper;
    let a = p.aspect_ratio;
    let a_tan_le = a * p.leading_edge.tan;
    let t21 = a * (1.0 + taper) * p.leading_edge.tan / 4.0;
    let mut at_90 = (taper + t21 + (1.0 + t21 * taper) / (1.0 + taper)) / 3.0;
    if i.kind != WingType::Straight && a < NONLINEAR_ASPECT_LIMIT / i.c1_cos_le {
        if let Some(o) = &p.outboard {
            // Area-weighted leading edge of the panels' MACs, from the exposed root.
            let tan_in = p.inboard.leading_edge.tan;
            let y_in =
                p.inboard.span * (1.0 + 2.0 * p.inboard.taper) / (3.0 * (1.0 + p.inboard.taper));
            let x_le = (y_in * p.inboard.area * tan_in
                + (p.inboard.span * tan_in + p.y_outboard_mac_from_break * o.leading_edge.tan)
                    * o.area)
                / p.exposed_area;
            at_90 = (x_le + p.mac / 2.0) / root;
        }
    }
    let c3 = figures::read(CENTRE_OF_PRESSURE_TAPER_FACTOR, &[taper], warnings)?;
    let at_max_planform = figures::read(
        CENTRE_OF_PRESSURE_AT_MAX_LIFT,
        &[a, (c3 + 1.0) * a_tan_le],
        warnings,
    )?;
    let at_max_edge = figures::read(CENTRE_OF_PRESSURE_DELTA_Y, &[i.delta_y_percent], warnings)?;
    let at_max_lift = at_max_planform + at_max_edge;
    let am = alpha_max.to_radians();
    let (sin_max, tan_max) = (am.sin(), am.tan());
    let c30 = at_max_lift / sin_max - i.aerodynamic_centre / tan_max;
    let reference_alpha = (tan_max / REFERENCE_TANGENT_RATIO).atan();
    let ratio_at_reference = tan_max / reference_alpha.tan();
    let stability_index = figures::read(STABILITY_INDEX, &[a_tan_le, taper], warnings)?;
    let aspect_ratio_index = figures::read(
        ASPECT_RATIO_INDEX,
        &[a * p.leading_edge.cos, taper],
        warnings,
    )?;
    let shift_ar = figures::read(
        ASPECT_RATIO_SHIFT_ABOVE,
        &[ratio_at_reference, aspect_ratio_index],
        warnings,
    )?;
    let shift_si = figures::read(
        CENTRE_OF_PRESSURE_SHIFT_ABOVE,
        &[ratio_at_reference, stability_index],
        warnings,
    )?;
    let at_reference = i.aerodynamic_centre * reference_alpha.cos()
        + reference_alpha.sin() * (c30 + shift_ar + shift_si);
    for l in lift {
        let alpha = l.alpha_deg.to_radians();
        let xcp = if alpha > reference_alpha {
            at_reference
                + (at_90 - at_reference) / (FRAC_PI_2 - reference_alpha) * (alpha - reference_alpha)
        } else {
            let tan_a = alpha.tan();
            let (shift_ar, shift_si) = if tan_a > tan_max {
                let r = tan_max / tan_a;
                (
                    figures::read(ASPECT_RATIO_SHIFT_ABOVE, &[r, aspect_ratio_index], warnings)?,
                    figures::read(
                        CENTRE_OF_PRESSURE_SHIFT_ABOVE,
                        &[r, stability_index],
                        warnings,
                    )?,
                )
            } else {
                let r = (tan_a / tan_max).abs();
                (
                    figures::read(ASPECT_RATIO_SHIFT_BELOW, &[r, aspect_ratio_index], warnings)?,
                    figures::read(
                        CENTRE_OF_PRESSURE_SHIFT_BELOW,
                        &[r, stability_index],
                        warnings,
                    )?,
                )
            };
            i.aerodynamic_centre * alpha.cos() + (c30 + shift_si + shift_ar) * alpha.sin()
        };
        out.cm.push(l.cn * (i.moment_reference - xcp) * lever + cm0);
    }
    out.nonlinear = Some(NonlinearCentre {
        at_90,
        at_max_lift,
        stability_index,
        aspect_ratio_index,
        reference_alpha_rad: reference_alpha,
        at_reference,
    });
    Ok(Some(out))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// How far apart the two sides of |tan Λ_LE|/β = 1 are read (the charts' nodes at 1 hold
    /// the same values; between the tables a lookup moves linearly over a step this small).
    const EDGE_STEP: f64 = 1e-9;
    /// The charts' values are printed to two decimals.
    const CHART_DIGIT: f64 = 0.01;

    fn centre(a: f64, taper: f64, tan: f64, beta: f64, reading: ForwardSweepReading) -> f64 {
        let mut w = Vec::new();
        trapezoid_aerodynamic_centre(a, taper, -tan, beta, reading, &mut w).unwrap()
    }

    #[test]
    fn the_forward_sweep_charts_join_where_the_edge_turns_sonic() {
        let mut largest_jump = 0.0_f64;
        for taper in [0.0, 0.2, 0.33, 0.5, 1.0] {
            for a_tan in [1.0, 2.5, 4.0, 6.0] {
                let tan = 0.8;
                let a = a_tan / tan;
                let below = |r| centre(a, taper, tan, tan / (1.0 - EDGE_STEP), r);
                let above = |r| centre(a, taper, tan, tan / (1.0 + EDGE_STEP), r);
                let h = ForwardSweepReading::Handbook;
                assert!(
                    (below(h) - above(h)).abs() < 1e-6,
                    "taper {taper}, A tan {a_tan}: {} {}",
                    below(h),
                    above(h)
                );
                let o = ForwardSweepReading::Original;
                largest_jump = largest_jump.max((below(o) - above(o)).abs());
            }
        }
        // The original's supersonic table does not join: its reading jumps there.
        assert!(largest_jump > 2.0 * CHART_DIGIT, "{largest_jump}");
    }

    #[test]
    fn a_forward_swept_rectangle_has_its_centre_at_the_mean_chords_quarter() {
        // Taper 1, incompressible edge 0: the mean chord lies at mid semi-span, its quarter
        // chord (A |tan Λ|)/4 root chords ahead of the root's quarter chord.
        let mut w = Vec::new();
        for a_tan in [1.0, 2.0, 4.0, 6.0] {
            let tan = 1e-6;
            let x = trapezoid_aerodynamic_centre(
                a_tan / tan,
                1.0,
                -tan,
                1.0,
                ForwardSweepReading::Handbook,
                &mut w,
            )
            .unwrap();
            assert!(
                (x - (0.25 - a_tan / 4.0)).abs() <= 2.0 * CHART_DIGIT,
                "{a_tan}: {x}"
            );
        }
    }
}
