//! DATCOM 4.1.3.2 (lift-curve slope), 4.1.3.4 (maximum lift and its angle) and 4.1.3.3 (the
//! lift curve to and beyond maximum lift) of wings at subsonic speeds.

use std::f64::consts::PI;

use serde::Serialize;

use super::figures::{self, *};
use super::planform::WingPlanform;
use super::{WingMethodError, WingType, WingWarning};

/// DATCOM 4.1.3.2 equation 4.1.3.2-a (Helmbold's, as DATCOM writes it; the original's
/// WTLIFT), the lift-curve slope of a straight-tapered planform, per radian, on its own area:
///
/// CLα = 2πA / (2 + √(A²β²/κ² · (1 + tan²Λc/2 / β²) + 4)),  κ = β c_lα,M / (2π),
///
/// so that A²β²/κ² = (2πA / c_lα,M)², with c_lα,M the section slope at the Mach number (per
/// radian). Valid at subsonic speeds for any aspect ratio (β = √(1 − M²)).
pub fn helmbold_lift_curve_slope(
    aspect_ratio: f64,
    section_slope_per_rad: f64,
    tan_half_chord_sweep: f64,
    beta: f64,
) -> f64 {
    let k = 2.0 * PI * aspect_ratio / section_slope_per_rad;
    let compressible = 1.0 + tan_half_chord_sweep * tan_half_chord_sweep / (beta * beta);
    2.0 * PI * aspect_ratio / (2.0 + (k * k * compressible + 4.0).sqrt())
}

/// Lift-curve slope of the wing and its terms, per radian.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct LiftCurveSlope {
    /// Of the exposed planform on its own area (equation 4.1.3.2-a).
    pub exposed_per_rad: f64,
    /// Cranked wing: the ratio of figure 4.1.3.2-52 applied.
    pub cranked_ratio: Option<f64>,
    /// Two-panel planforms: of the inboard panel and of the extended outboard panel (the
    /// weights of the aerodynamic centre, DATCOM 4.1.4.2).
    pub inboard_panel_per_rad: Option<f64>,
    pub extended_outboard_per_rad: Option<f64>,
    /// On the reference area: exposed slope × ratio × S_exposed/S_ref.
    pub per_rad: f64,
}

/// DATCOM 4.1.3.2: the wing's lift-curve slope at subsonic speed (the original's WTLIFT).
/// Straight-tapered, double-delta and cranked planforms use equation 4.1.3.2-a on the exposed
/// planform with the total half-chord sweep; a cranked wing's slope is multiplied by the ratio
/// of figure 4.1.3.2-52 (against βA).
pub fn lift_curve_slope(
    planform: &WingPlanform,
    kind: WingType,
    section_slope_per_rad: f64,
    beta: f64,
    reference_area: f64,
    warnings: &mut Vec<WingWarning>,
) -> Result<LiftCurveSlope, WingMethodError> {
    let exposed = helmbold_lift_curve_slope(
        planform.aspect_ratio,
        section_slope_per_rad,
        planform.half_chord.tan,
        beta,
    );
    let cranked_ratio = if kind == WingType::Cranked {
        Some(figures::read(
            CRANKED_SLOPE_RATIO,
            &[beta * planform.aspect_ratio],
            warnings,
        )?)
    } else {
        None
    };
    let (inboard, extended) = match (&planform.outboard, &planform.extended_outboard) {
        (Some(o), Some(e)) => (
            Some(helmbold_lift_curve_slope(
                planform.inboard.aspect_ratio,
                section_slope_per_rad,
                planform.inboard.half_chord.tan,
                beta,
            )),
            Some(helmbold_lift_curve_slope(
                e.aspect_ratio,
                section_slope_per_rad,
                o.half_chord.tan,
                beta,
            )),
        ),
        _ => (None, None),
    };
    Ok(LiftCurveSlope {
        exposed_per_rad: exposed,
        cranked_ratio,
        inboard_panel_per_rad: inboard,
        extended_outboard_per_rad: extended,
        per_rad: exposed * cranked_ratio.unwrap_or(1.0) * planform.exposed_area / reference_area,
    })
}

/// The taper factors of DATCOM 4.1.3.4 (figure 4.1.3.4-24b) and the low-aspect-ratio
/// criterion.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct AspectRatioClass {
    pub c1: f64,
    pub c2: f64,
    /// (C1 + 1) cos Λ_LE.
    pub c1_cos_le: f64,
    /// (C2 + 1) A tan Λ_LE.
    pub c2_aspect_tan_le: f64,
    /// A < ARCL / ((C1 + 1) cos Λ_LE): the low-aspect-ratio methods apply.
    pub low_aspect_ratio: bool,
}

/// How near DATCOM's aspect-ratio boundary (relative) a wing gets a warning that its methods
/// switch there: a design sweep that crosses it sees a step (CMA by 11 % over 5 mm of span on a
/// light aircraft's wing), the handbook's, not the sweep's.
pub const ASPECT_RATIO_BOUNDARY_BAND: f64 = 0.02;

/// DATCOM 4.1.3.4: the aspect-ratio class of the planform (the original's ARCLSS and WTLIFT):
/// low aspect ratio when A < ARCL/((C1 + 1) cos Λ_LE), C1 and C2 from figure 4.1.3.4-24b.
pub fn aspect_ratio_class(
    planform: &WingPlanform,
    arcl: f64,
    warnings: &mut Vec<WingWarning>,
) -> Result<AspectRatioClass, WingMethodError> {
    let c1 = figures::read(TAPER_FACTOR_C1, &[planform.taper], warnings)?;
    let c2 = figures::read(TAPER_FACTOR_C2, &[planform.taper], warnings)?;
    let c1_cos_le = (c1 + 1.0) * planform.leading_edge.cos;
    let boundary = arcl / c1_cos_le;
    if (planform.aspect_ratio - boundary).abs() <= ASPECT_RATIO_BOUNDARY_BAND * boundary.abs() {
        warnings.push(WingWarning::NearAspectRatioBoundary {
            aspect_ratio: planform.aspect_ratio,
            boundary,
        });
    }
    Ok(AspectRatioClass {
        c1,
        c2,
        c1_cos_le,
        c2_aspect_tan_le: (c2 + 1.0) * planform.leading_edge.tan * planform.aspect_ratio,
        low_aspect_ratio: planform.aspect_ratio < arcl / c1_cos_le,
    })
}

/// Maximum lift of the wing and its angle.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct MaxLift {
    pub low_aspect_ratio: bool,
    /// High aspect ratio: CLmax/clmax (figure 4.1.3.4-21a), Δα(CLmax) (21b, deg) and the Mach
    /// increment ΔCLmax (22).
    pub clmax_ratio: f64,
    pub alpha_increment_deg: f64,
    pub mach_increment: Option<f64>,
    /// CLmax on the reference area; none for a high-aspect-ratio wing without section clmax.
    pub clmax: Option<f64>,
    /// Angle of attack of maximum lift, deg.
    pub alpha_deg: Option<f64>,
}

/// DATCOM 4.1.3.4 low-aspect-ratio maximum lift (the original's CLMXBS): (CLmax,base of figure
/// 4.1.3.4-23a or -23b (maximum thickness aft of 35 % chord) + ΔCLmax of figure 4.1.3.4-24a)
/// on the reference area, at the parameter `c1_aspect_over_beta` = (C1 + 1) A cos Λ_LE / β.
pub fn low_aspect_ratio_max_lift(
    planform: &WingPlanform,
    class: &AspectRatioClass,
    c1_aspect_over_beta: f64,
    flow: &LowAspectRatioFlow,
    warnings: &mut Vec<WingWarning>,
) -> Result<f64, WingMethodError> {
    let LowAspectRatioFlow {
        delta_y_percent,
        max_thickness_x,
        mach,
        reference_area,
    } = *flow;
    let increment = figures::read(
        LOW_AR_MAX_LIFT_INCREMENT,
        &[mach, class.c2_aspect_tan_le],
        warnings,
    )?;
    let base_chart = if max_thickness_x.unwrap_or(0.0) > 0.35 {
        LOW_AR_MAX_LIFT_AFT
    } else {
        LOW_AR_MAX_LIFT_FORWARD
    };
    let base = figures::read(
        base_chart,
        &[delta_y_percent, c1_aspect_over_beta],
        warnings,
    )?;
    Ok((base + increment) * planform.exposed_area / reference_area)
}

/// Section and flight values of the low-aspect-ratio maximum lift.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LowAspectRatioFlow {
    pub delta_y_percent: f64,
    /// Chord fraction of maximum thickness (chart 23b aft of 35 %).
    pub max_thickness_x: Option<f64>,
    pub mach: f64,
    pub reference_area: f64,
}

/// Inputs of the maximum-lift methods.
pub struct MaxLiftInputs {
    pub section_max_lift: Option<f64>,
    pub delta_y_percent: f64,
    pub max_thickness_x: Option<f64>,
    pub mach: f64,
    pub beta: f64,
    pub reference_area: f64,
    pub lift_curve_slope_per_rad: f64,
    pub zero_lift_alpha_deg: f64,
}

/// DATCOM 4.1.3.4, subsonic maximum lift and its angle (the original's WTLIFT).
///
/// - High aspect ratio (method 1): CLmax = ((CLmax/clmax) clmax + ΔCLmax) S_exp/S_ref with
///   figures 4.1.3.4-21a and -22, and α(CLmax) = CLmax/CLα + α0 + Δα(CLmax) (figure 21b).
/// - Low aspect ratio (method 2): CLmax of figures 23 and 24a; α(CLmax) = α(CLmax),base of
///   figure 25a + Δα of figure 25b (not adding α0).
pub fn max_lift(
    planform: &WingPlanform,
    class: &AspectRatioClass,
    i: &MaxLiftInputs,
    warnings: &mut Vec<WingWarning>,
) -> Result<MaxLift, WingMethodError> {
    let le_deg = planform.leading_edge.deg;
    let clmax_ratio = figures::read(MAX_LIFT_RATIO, &[i.delta_y_percent, le_deg], warnings)?;
    let alpha_increment_deg = figures::read(
        MAX_LIFT_ANGLE_INCREMENT,
        &[i.delta_y_percent, le_deg],
        warnings,
    )?;
    if !class.low_aspect_ratio {
        let mach_increment = figures::read(
            MAX_LIFT_MACH_INCREMENT,
            &[le_deg, i.delta_y_percent, i.mach],
            warnings,
        )?;
        let clmax = i.section_max_lift.map(|cl| {
            (clmax_ratio * cl + mach_increment) * planform.exposed_area / i.reference_area
        });
        if clmax.is_none() {
            warnings.push(WingWarning::NoSectionMaxLift);
        }
        let alpha_deg = clmax.map(|c| {
            (c / i.lift_curve_slope_per_rad).to_degrees()
                + i.zero_lift_alpha_deg
                + alpha_increment_deg
        });
        return Ok(MaxLift {
            low_aspect_ratio: false,
            clmax_ratio,
            alpha_increment_deg,
            mach_increment: Some(mach_increment),
            clmax,
            alpha_deg,
        });
    }
    let parameter = planform.aspect_ratio * class.c1_cos_le / i.beta;
    let flow = LowAspectRatioFlow {
        delta_y_percent: i.delta_y_percent,
        max_thickness_x: i.max_thickness_x,
        mach: i.mach,
        reference_area: i.reference_area,
    };
    let clmax = low_aspect_ratio_max_lift(planform, class, parameter, &flow, warnings)?;
    let base = figures::read(LOW_AR_MAX_LIFT_ANGLE, &[parameter], warnings)?;
    let increment = if class.c2_aspect_tan_le > 4.5 {
        figures::read(
            LOW_AR_MAX_LIFT_ANGLE_INCREMENT,
            &[i.mach, class.c2_aspect_tan_le],
            warnings,
        )?
    } else {
        let t = planform.taper;
        figures::read(
            LOW_AR_MAX_LIFT_ANGLE_INCREMENT_LOW,
            &[
                planform.aspect_ratio * planform.leading_edge.cos * (1.0 + 4.0 * t * t),
                class.c2_aspect_tan_le,
            ],
            warnings,
        )?
    };
    Ok(MaxLift {
        low_aspect_ratio: true,
        clmax_ratio,
        alpha_increment_deg,
        mach_increment: None,
        clmax: Some(clmax),
        alpha_deg: Some(base + increment),
    })
}

/// The lift curve at one angle of attack.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct LiftAtAngle {
    /// Wing angle of attack (schedule angle + incidence), deg.
    pub alpha_deg: f64,
    pub cl: f64,
    /// The nonlinear method's normal-force coefficient CL/cos α (the moment's lever).
    pub cn: f64,
    /// Straight-tapered: CNαα used at this angle.
    pub cn_alpha_alpha: Option<f64>,
}

/// The straight-tapered nonlinear lift terms.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct NonlinearLift {
    /// Planform parameter J of figure 4.1.3.3-55a.
    pub j: f64,
    /// CNαα at maximum lift.
    pub cn_alpha_alpha_at_max_lift: f64,
    /// CLmax of the post-stall factor (high aspect ratio: the low-aspect-ratio CLmax at
    /// (C1 + 1) A cos Λ_LE / β = 4/β; low aspect ratio: CLmax).
    pub post_stall_clmax: Option<f64>,
}

/// Inputs of the lift curve.
pub struct LiftCurveInputs<'a> {
    pub planform: &'a WingPlanform,
    pub kind: WingType,
    pub class: &'a AspectRatioClass,
    pub slope: &'a LiftCurveSlope,
    pub max_lift: &'a MaxLift,
    pub zero_lift_alpha_deg: f64,
    pub beta: f64,
    pub reference_area: f64,
    pub delta_y_percent: f64,
    pub max_thickness_x: Option<f64>,
    pub mach: f64,
}

/// DATCOM 4.1.3.3, the lift curve of straight-tapered wings (the original's LIFTCF): the
/// normal force CN' = (CNα cos θ + CNαα |sin θ|) sin θ, θ = α − α0, with CNαα at maximum lift
/// from CLmax and α(CLmax), plus ΔCNαα of figure 4.1.3.3-55a below the stall; beyond it the
/// post-stall interpolation towards CNαα at 90° (figure 4.1.3.3-55b) with the factor D;
/// CL = CN' cos α.
pub fn straight_lift_curve(
    i: &LiftCurveInputs,
    alpha_deg: &[f64],
    warnings: &mut Vec<WingWarning>,
) -> Result<Option<(NonlinearLift, Vec<LiftAtAngle>)>, WingMethodError> {
    let p = i.planform;
    let (Some(clmax), Some(alpha_max)) = (i.max_lift.clmax, i.max_lift.alpha_deg) else {
        return Ok(None);
    };
    // The curve rises from zero lift to a stall above it: with CLmax at or below zero (a
    // nonsensical deck value, or a section whose computed maximum lift is not positive) the
    // stall falls at or below the zero-lift angle, where the curve's readings divide by zero.
    // The linear results stand, as without a CLmax.
    let reason = if clmax <= 0.0 {
        Some(format!(
            "the wing's maximum lift CLmax = {clmax:.4} is not positive"
        ))
    } else if alpha_max <= i.zero_lift_alpha_deg {
        Some(format!(
            "the angle of maximum lift, {alpha_max:.4} deg, is not above the zero-lift angle, {:.4} deg",
            i.zero_lift_alpha_deg
        ))
    } else {
        None
    };
    if let Some(reason) = reason {
        warnings.push(WingWarning::NoStallAboveZeroLift { reason });
        return Ok(None);
    }
    let c1 = i.class.c1;
    let cube = (i.class.c2_aspect_tan_le / 7.0).powi(3);
    let j = 0.3
        * (c1 + 1.0)
        * p.aspect_ratio
        * p.leading_edge.cos
        * ((c1 + 1.0) * (i.class.c2 + 1.0) - cube)
        / i.beta;
    let stall = (alpha_max - i.zero_lift_alpha_deg).to_radians();
    let (s1, c1s, t1) = (stall.sin(), stall.cos(), stall.tan());
    let cna = i.slope.per_rad;
    let at_max = (clmax / (s1 * c1s) - cna * c1s) / s1.abs();
    if !at_max.is_finite() {
        return Err(WingMethodError::Degenerate {
            reason: "the angle of maximum lift equals the zero-lift angle".into(),
        });
    }
    let area_ratio = p.exposed_area / i.reference_area;
    let mut post_stall_clmax = None;
    let mut out = Vec::with_capacity(alpha_deg.len());
    for &a in alpha_deg {
        let (theta, cnaa) = if a < alpha_max {
            let theta = (a - i.zero_lift_alpha_deg).to_radians();
            let ratio = (theta.tan() / t1).abs();
            let d = figures::read(NORMAL_FORCE_INCREMENT, &[j, ratio], warnings)?;
            (theta, at_max + d * area_ratio)
        } else {
            let reference = match post_stall_clmax {
                Some(c) => c,
                None => {
                    let c = if i.class.low_aspect_ratio {
                        clmax
                    } else {
                        let flow = LowAspectRatioFlow {
                            delta_y_percent: i.delta_y_percent,
                            max_thickness_x: i.max_thickness_x,
                            mach: i.mach,
                            reference_area: i.reference_area,
                        };
                        low_aspect_ratio_max_lift(p, i.class, 4.0 / i.beta, &flow, warnings)?
                    };
                    post_stall_clmax = Some(c);
                    c
                }
            };
            let k = i.zero_lift_alpha_deg / (90.0 - alpha_max);
            let theta = (a * (1.0 + k) - 90.0 * k).to_radians();
            let ratio = (t1 / theta.tan()).abs();
            let d = figures::read(POST_STALL_FACTOR, &[ratio], warnings)?;
            let at_90 = if p.aspect_ratio > 1.0 {
                figures::read(
                    NORMAL_FORCE_90_BY_INVERSE_ASPECT,
                    &[1.0 / p.aspect_ratio],
                    warnings,
                )? * area_ratio
            } else {
                figures::read(NORMAL_FORCE_90_BY_ASPECT, &[p.aspect_ratio], warnings)?
            };
            let q = i.beta * clmax / reference;
            (
                theta,
                at_max + (at_90 - at_max) * (1.0 - ratio) + d * cna / 2.3 * q * q,
            )
        };
        let (s, c) = theta.sin_cos();
        let cn = (cna * c + cnaa * s.abs()) * s;
        out.push(LiftAtAngle {
            alpha_deg: a,
            cl: cn * a.to_radians().cos(),
            cn,
            cn_alpha_alpha: Some(cnaa),
        });
    }
    Ok(Some((
        NonlinearLift {
            j,
            cn_alpha_alpha_at_max_lift: at_max,
            post_stall_clmax,
        },
        out,
    )))
}

/// The double-delta and cranked lift terms.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct PanelLift {
    /// Span factor (SSPNE − SSPNOP)/(SSPNE A_inboard).
    pub span_factor: f64,
    /// β tan Λ_LE,inboard.
    pub beta_tan_le: f64,
    /// Cranked: the break angle of figure 4.1.3.3-57, deg.
    pub break_alpha_deg: Option<f64>,
}

/// DATCOM 4.1.3.3, the lift curves of double-delta and cranked wings (the original's LIFTCF,
/// figures 4.1.3.3-56 and -57), CL = (figure 56 at α) CLα (b_i/(b_e A_i)) for a double delta
/// (odd in α); a cranked wing is linear up to the break angle of figure 57 and adds the
/// increase of figure 56 beyond it. The normal force is CL/cos α. Only the solid curves of
/// figure 56 are used: the dashed ones (Mach 0.7 and above with A < 3 and β tan Λ_LE ≤ 7) are
/// not covered (warning).
pub fn panel_lift_curve(
    i: &LiftCurveInputs,
    alpha_deg: &[f64],
    warnings: &mut Vec<WingWarning>,
) -> Result<(PanelLift, Vec<LiftAtAngle>), WingMethodError> {
    let p = i.planform;
    let span_factor = p.inboard.span / (p.exposed_semispan * p.inboard.aspect_ratio);
    let beta_tan_le = i.beta * p.inboard.leading_edge.tan;
    if !(p.aspect_ratio >= 3.0 || i.mach < 0.7 || beta_tan_le > 7.0) {
        warnings.push(WingWarning::DashedCurvesNotCovered);
    }
    let cla = i.slope.per_rad;
    let curve = |a: f64, warnings: &mut Vec<WingWarning>| -> Result<f64, WingMethodError> {
        Ok(figures::read(DOUBLE_DELTA_LIFT, &[a, beta_tan_le], warnings)? * cla * span_factor)
    };
    let mut out = Vec::with_capacity(alpha_deg.len());
    let break_alpha_deg = if i.kind == WingType::Cranked {
        let brk = figures::read(
            CRANKED_BREAK_ANGLE,
            &[1.0 / p.inboard.leading_edge.tan],
            warnings,
        )?;
        let at_break = curve(brk, warnings)?;
        for &a in alpha_deg {
            let cl = if a > brk {
                cla * brk.to_radians() + curve(a, warnings)? - at_break
            } else {
                cla * a.to_radians()
            };
            out.push(angle(a, cl));
        }
        Some(brk)
    } else {
        for &a in alpha_deg {
            let at_magnitude = curve(a.abs(), warnings)?;
            out.push(angle(a, if a < 0.0 { -at_magnitude } else { at_magnitude }));
        }
        None
    };
    Ok((
        PanelLift {
            span_factor,
            beta_tan_le,
            break_alpha_deg,
        },
        out,
    ))
}

fn angle(alpha_deg: f64, cl: f64) -> LiftAtAngle {
    LiftAtAngle {
        alpha_deg,
        cl,
        cn: cl / alpha_deg.to_radians().cos(),
        cn_alpha_alpha: None,
    }
}
