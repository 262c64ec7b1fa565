//! Downwash and dynamic pressure at the horizontal tail at subsonic speeds, DATCOM 4.4.1
//! (the original's DWASH, DYPRLS and the downwash geometry of INFTGM).

use std::f64::consts::PI;

use serde::Serialize;

use super::figures;
use super::surfaces::{low_speed_wing, tail_position, HorizontalTailAlone, LowSpeedWing};
use super::table::{read, End};
use super::{TailError, TailWarning};
use crate::case::Case;
use crate::geometry::{planform as planform_geometry, Span};
use crate::methods::wing_body::WingBody;
use crate::numeric::trapezoid;

/// Which downwash method applies (the original's WGSCHR DWASH, checked against the ratio of
/// wing span to tail span as its CHECK does).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum DownwashMethod {
    /// DWASH 1 (the default): the wing's trailing vortex sheet rolled up at an effective
    /// aspect ratio, figures 4.4.1-66 to -68b.
    VortexSheet,
    /// DWASH 2: the empirical gradient 4.44 (K_A K_λ K_H √cos Λc/4)^1.19.
    Empirical,
    /// DWASH 3: the forward surface is the tail (a canard), not covered.
    Canard,
}

/// Span ratios of the original's method check (CHECK).
const CANARD_BELOW_SPAN_RATIO: f64 = 1.5;
const EMPIRICAL_FROM_SPAN_RATIO: f64 = 1.25;
const EMPIRICAL_UP_TO_SPAN_RATIO: f64 = 3.6;
const VORTEX_SHEET_ABOVE_SPAN_RATIO: f64 = 1.0;

/// The downwash method for a wing of semispan `wing_semispan` ahead of a tail of semispan
/// `tail_semispan` and the user's choice DWASH (WGSCHR): as the original's CHECK, DWASH 3
/// (canard) when not given and the span ratio is below 1.5; ≤ 1.5 is 1, ≥ 2.5 is 3; 2 becomes
/// 3 below a span ratio of 1.25 and 1 above 3.6; 1 becomes 3 at or below 1; 3 becomes 1 above
/// 1.5.
pub fn downwash_method(
    user: Option<f64>,
    wing_semispan: f64,
    tail_semispan: f64,
) -> DownwashMethod {
    let ratio = wing_semispan / tail_semispan;
    let d = match user {
        None if ratio < CANARD_BELOW_SPAN_RATIO => 3.0,
        None => 1.0,
        Some(d) => d,
    };
    let mut m = if d <= 1.5 {
        1
    } else if d >= 2.5 {
        3
    } else {
        2
    };
    if m == 2 && ratio < EMPIRICAL_FROM_SPAN_RATIO {
        m = 3;
    }
    if m == 2 && ratio > EMPIRICAL_UP_TO_SPAN_RATIO {
        m = 1;
    }
    if m == 1 && ratio <= VORTEX_SHEET_ABOVE_SPAN_RATIO {
        m = 3;
    }
    if m == 3 && ratio > CANARD_BELOW_SPAN_RATIO {
        m = 1;
    }
    match m {
        1 => DownwashMethod::VortexSheet,
        2 => DownwashMethod::Empirical,
        _ => DownwashMethod::Canard,
    }
}

/// Where the tail is relative to the wing, in the wing's root-chord frame (DATCOM 4.4.1,
/// figure 4.4.1-67's l_H and h_H; the original's INFTGM).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct TailPlacement {
    /// Distance along the wing root chord from the root's trailing edge to the quarter chord of
    /// the tail's exposed MAC, m (A(24)).
    pub arm: f64,
    /// Height of that point above the wing root chord's extension, m (A(12)).
    pub height: f64,
    /// atan(height/arm), rad (A(11)): the angle the tail subtends.
    pub angle_rad: f64,
    /// Wing root chord less the distance of the theoretical MAC's leading edge behind the
    /// apex, m (A(22)).
    pub root_chord_less_mac_le: f64,
}

/// The tail's placement (see [`TailPlacement`]): with the tail's exposed-MAC quarter chord
/// `tail_quarter_chord` behind its apex at (XH, ZH), the wing's apex at (XW, ZW) with root
/// chord c_r and incidences i_W, i_H: x_t = XH − XW − c_r cos i_W + x_c/4 cos i_H, z_t = ZH −
/// x_c/4 sin i_H − ZW + c_r sin i_W; arm = (x_t − z_t tan i_W) cos i_W, height = z_t/cos i_W +
/// (x_t − z_t tan i_W) sin i_W.
#[allow(clippy::too_many_arguments)]
pub fn tail_placement(
    wing_apex: (f64, f64),
    wing_incidence_deg: f64,
    wing_root_chord: f64,
    wing_mac_le: f64,
    tail_apex: (f64, f64),
    tail_incidence_deg: f64,
    tail_quarter_chord: f64,
) -> TailPlacement {
    let (si_w, ci_w) = wing_incidence_deg.to_radians().sin_cos();
    let (si_h, ci_h) = tail_incidence_deg.to_radians().sin_cos();
    let x = tail_apex.0 - wing_apex.0 - wing_root_chord * ci_w + tail_quarter_chord * ci_h;
    let z = tail_apex.1 - tail_quarter_chord * si_h - wing_apex.1 + wing_root_chord * si_w;
    let along = x - z * si_w / ci_w;
    let arm = along * ci_w;
    let height = z / ci_w + along * si_w;
    TailPlacement {
        arm,
        height,
        angle_rad: (height / arm).atan(),
        root_chord_less_mac_le: wing_root_chord - wing_mac_le,
    }
}

/// DATCOM figure 4.4.1-66 as the original fits it: the effective aspect ratio of the
/// wing's vortex sheet over the geometric one, A_eff/A = λ/3 + (1 − λ/3)(1.4 − t·α/α_CLmax)
/// with t = 1.4 − cos Λc/4 + 0.04 tan Λc/4, and 1 while α/α_CLmax < 0.4/t (angles from the
/// zero-lift angle). λ: exposed taper ratio.
pub fn effective_aspect_ratio_ratio(
    taper: f64,
    cos_quarter_chord: f64,
    tan_quarter_chord: f64,
    fraction_of_stall: f64,
) -> f64 {
    let t = 1.4 - cos_quarter_chord + 0.04 * tan_quarter_chord;
    if fraction_of_stall < 0.4 / t {
        1.0
    } else {
        taper / 3.0 + (1.0 - taper / 3.0) * (1.4 - t * fraction_of_stall)
    }
}

/// DATCOM 4.4.1, equation 4.4.1-b and figure 4.4.1-67: the downwash gradient at the tail from
/// the gradient at infinity dε/dα∞ = 1.62 CLα/(π A) (radians; CLα on the wing's own area) and
/// the tail's distance behind the wing over its semispan, 2 l/b: with
/// z = 2l/b + √(½(√(1 + 4/A²) − 1)), dε/dα = dε/dα∞ + (1 − dε/dα∞)/(A z √(1 + z²)).
pub fn downwash_gradient_at_tail(
    at_infinity: f64,
    aspect_ratio: f64,
    arm_over_semispan: f64,
) -> f64 {
    let a = aspect_ratio;
    let z = arm_over_semispan + (0.5 * (-1.0 + (1.0 + 4.0 / (a * a)).sqrt())).sqrt();
    at_infinity + (1.0 - at_infinity) / (a * z * (1.0 + z * z).sqrt())
}

/// The empirical downwash gradient of DATCOM 4.4.1 (equation 4.4.1-a), as the original's
/// DWASH 2: dε/dα = 4.44 (K_A K_λ K_H √cos Λc/4)^1.19 with K_A = 1/A − 1/(1 + A^1.7),
/// K_λ = (10 − 3λ)/7, K_H = (1 − |h_H/b|)/(2 l_H/b)^(1/3); here h_H/b = height/(2 b_e/2) and
/// 2 l_H/b = lever/(b_e/2) on the exposed semispan.
pub fn empirical_downwash_gradient(
    aspect_ratio: f64,
    taper: f64,
    cos_quarter_chord: f64,
    height: f64,
    lever: f64,
    exposed_semispan: f64,
) -> f64 {
    let ka = 1.0 / aspect_ratio - 1.0 / (1.0 + aspect_ratio.powf(1.7));
    let kl = (10.0 - 3.0 * taper) / 7.0;
    let kh = (1.0 - (0.5 * height / exposed_semispan).abs())
        / (lever / exposed_semispan).powf(1.0 / 3.0);
    4.44 * (ka * kl * kh * cos_quarter_chord.sqrt()).powf(1.19)
}

/// The wake of the wing at the tail at one angle (DATCOM 4.4.1, figures 4.4.1-69 to -71;
/// the original's DYPRLS).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Wake {
    /// Downwash at infinity behind the wing, 1.62 CL/(π A), rad (CL on the exposed area).
    pub downwash_rad: f64,
    /// Distance from the wing's trailing edge to the tail along the wake, over the wing MAC.
    pub distance_over_chord: f64,
    /// Wake half-width z_W/c = 0.68 √(CD0 (x/c + 0.15)).
    pub half_width_over_chord: f64,
    /// Dynamic-pressure loss at the wake centre, Δq/q = 2.42 √CD0 / (x/c + 0.3).
    pub centre_loss: f64,
    /// Height of the tail above the wake centre, z/c.
    pub height_over_chord: f64,
    /// q/q∞ = 1 − Δq/q cos²(π/2 z/z_W) inside the wake, 1 outside.
    pub dynamic_pressure_ratio: f64,
}

/// The distance term of the wake half-width, z_W/c = 0.68 √(CD0 (x/c + 0.15)) (DATCOM 4.4.1):
/// below x/c = −0.15 the width has no value.
const WAKE_WIDTH_OFFSET: f64 = 0.15;

/// See [`Wake`]: the wing of exposed aspect ratio `aspect_ratio` and MAC `mac` (exposed),
/// lift coefficient `cl` and zero-lift drag `cd0` (both on the exposed area) at wing angle
/// `wing_alpha_deg`, the tail at `arm` and subtending `tail_angle_rad`. Subsonic. Original:
/// DYPRLS.
pub fn wing_wake(
    aspect_ratio: f64,
    mac: f64,
    cl: f64,
    cd0: f64,
    wing_alpha_deg: f64,
    arm: f64,
    tail_angle_rad: f64,
) -> Wake {
    let downwash_rad = 1.62 / (PI * aspect_ratio) * cl;
    let angle = tail_angle_rad - wing_alpha_deg.to_radians() + downwash_rad;
    let x = arm * angle.cos() / (tail_angle_rad.cos() * mac);
    let half_width = 0.68 * (cd0 * (x + WAKE_WIDTH_OFFSET)).sqrt();
    let centre_loss = 2.42 * cd0.sqrt() / (x + 0.3);
    let z = x * angle.tan();
    let ratio = z / half_width;
    let dynamic_pressure_ratio = if ratio.abs() >= 1.0 {
        1.0
    } else {
        1.0 - centre_loss * (0.5 * PI * ratio).cos().powi(2)
    };
    Wake {
        downwash_rad,
        distance_over_chord: x,
        half_width_over_chord: half_width,
        centre_loss,
        height_over_chord: z,
        dynamic_pressure_ratio,
    }
}

/// The vortex-sheet terms at the last step of one angle's integration.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct VortexSheet {
    /// Wing angle α + ALIW, deg, and the number of steps the gradient is integrated over.
    pub wing_alpha_deg: f64,
    pub steps: usize,
    /// Effective aspect ratio and vortex span b_eff (m) at the angle.
    pub effective_aspect_ratio: f64,
    pub effective_span: f64,
    /// Local gradient dε/dα at the angle (figure 4.4.1-67, or the empirical one).
    pub gradient: f64,
    /// Height of the tail above the vortex sheet h (m) and the span of the rolled-up vortices
    /// b_v (m).
    pub height_above_vortices: f64,
    pub vortex_span: f64,
    /// ε_avg/ε of figure 4.4.1-68b (1 with the empirical gradient).
    pub average_factor: f64,
}

/// The named terms of the downwash.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct DownwashTerms {
    pub method: DownwashMethod,
    pub placement: TailPlacement,
    pub low_speed_wing: LowSpeedWing,
    /// The wing section's Δy is below the limit of figure 4.4.1-68a: the sheet leaves the
    /// leading edge.
    pub leading_edge_separation: bool,
    pub sheets: Vec<VortexSheet>,
    pub wakes: Vec<Option<Wake>>,
}

/// Downwash and dynamic pressure at the horizontal tail against angle of attack (the original's
/// table ALPHA, Q/QINF, EPSLON, D(EPSLON)/D(ALPHA)).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Downwash {
    pub alpha_deg: Vec<f64>,
    /// q/q∞ at the tail.
    pub dynamic_pressure_ratio: Vec<Option<f64>>,
    /// Downwash angle ε at the tail, deg (positive down).
    pub epsilon_deg: Vec<Option<f64>>,
    /// dε/dα.
    pub gradient: Vec<Option<f64>>,
    pub terms: DownwashTerms,
    pub warnings: Vec<TailWarning>,
}

/// The number of steps the original integrates the gradient over up to wing angle `a`:
/// int(|a| + 1.5), at least 2 and at most 21 points.
fn integration_points(a: f64) -> usize {
    ((a.abs() + 1.5).floor() as usize).clamp(2, 21)
}

/// The tail's placement behind the wing of geometry `wing` (see [`tail_placement`]), from the
/// case's positions and incidences and the tail's exposed-MAC quarter chord.
pub(crate) fn placement_of(
    case: &Case,
    wing: &crate::geometry::PlanformGeometry,
    tail: &HorizontalTailAlone,
) -> TailPlacement {
    let s = case.synthesis.as_ref();
    let get = |f: fn(&crate::case::Synthesis) -> Option<f64>| s.and_then(f).unwrap_or(0.0);
    let tp = &tail.surface.terms.planform;
    let chrdr = case.wing.as_ref().and_then(|w| w.chrdr).unwrap_or(0.0);
    let tail_quarter_chord = tp.x_mac_mid_chord - tp.mac / 4.0
        + (tp.semispan - tp.exposed_semispan) * tp.inboard.leading_edge.tan;
    tail_placement(
        (get(|s| s.xw), get(|s| s.zw)),
        get(|s| s.aliw_deg),
        chrdr,
        wing.x_mac_le,
        tail_position(s),
        get(|s| s.alih_deg),
        tail_quarter_chord,
    )
}

/// The wing's wake at the tail at each wing angle `wing_alpha_deg` (α + ALIW), see
/// [`wing_wake`]: none where the wing has no CL or no zero-lift drag (then a warning).
pub(crate) fn wakes_of(
    wb: &WingBody,
    wing_alpha_deg: &[f64],
    placement: &TailPlacement,
    warnings: &mut Vec<TailWarning>,
) -> Vec<Option<Wake>> {
    let wing = &wb.terms.wing;
    let p = &wing.terms.planform;
    let area_ratio = wb.reference_area / p.exposed_area;
    let cd0 = wing
        .terms
        .zero_lift_drag
        .as_ref()
        .map(|d| d.total * area_ratio);
    if cd0.is_none() {
        warnings.push(TailWarning::NoWingZeroLiftDrag);
    }
    wing_alpha_deg
        .iter()
        .enumerate()
        .map(|(k, &a)| {
            let cl = wing.cl.get(k).copied()?? * area_ratio;
            let wake = wing_wake(
                p.aspect_ratio,
                p.mac,
                cl,
                cd0?,
                a,
                placement.arm,
                placement.angle_rad,
            );
            if !wake.dynamic_pressure_ratio.is_finite() {
                warnings.push(if wake.distance_over_chord + WAKE_WIDTH_OFFSET < 0.0 {
                    TailWarning::WakeMissesTail { wing_alpha_deg: a }
                } else {
                    TailWarning::NoDynamicPressureRatio { wing_alpha_deg: a }
                });
            }
            Some(wake)
        })
        .collect()
}

/// q/q∞ of each wake (none where the wake or its value is not finite).
pub(crate) fn dynamic_pressure_ratios(wakes: &[Option<Wake>]) -> Vec<Option<f64>> {
    wakes
        .iter()
        .map(|w| {
            w.map(|w| w.dynamic_pressure_ratio)
                .filter(|v| v.is_finite())
        })
        .collect()
}

/// DATCOM 4.4.1 at subsonic speeds with the wing-body `wb` and the tail `tail` computed:
/// see [`super::downwash`].
pub(crate) fn downwash_from(
    case: &Case,
    alpha_deg: &[f64],
    condition_index: usize,
    wb: &WingBody,
    tail: &HorizontalTailAlone,
) -> Result<Downwash, TailError> {
    let mut warnings = Vec::new();
    let plan = case.wing.as_ref().ok_or(TailError::NoWing)?;
    let tail_plan = case
        .horizontal_tail
        .as_ref()
        .ok_or(TailError::NoHorizontalTail)?;
    let wing = &wb.terms.wing;
    let p = &wing.terms.planform;
    let geometry = planform_geometry(plan, Span::Both).map_err(|e| TailError::Geometry {
        reason: format!("wing: {e}"),
    })?;
    let tail_geometry =
        planform_geometry(tail_plan, Span::Both).map_err(|e| TailError::Geometry {
            reason: format!("horizontal tail: {e}"),
        })?;
    let tp = &tail.surface.terms.planform;
    let user = case.sections.get("WING");
    let method = downwash_method(
        user.and_then(|u| u.scalars.get("DWASH").copied()),
        p.semispan,
        tp.semispan,
    );
    if method == DownwashMethod::Canard {
        return Err(TailError::Canard);
    }
    let s = case.synthesis.as_ref();
    let get = |f: fn(&crate::case::Synthesis) -> Option<f64>| s.and_then(f).unwrap_or(0.0);
    let (xw, aliw) = (get(|s| s.xw), get(|s| s.aliw_deg));
    let alih = get(|s| s.alih_deg);
    let tail_apex = tail_position(s);
    let chrdr = plan.chrdr.unwrap_or(0.0);
    let placement = placement_of(case, &geometry, tail);
    let low =
        low_speed_wing(case, condition_index, alpha_deg)?.ok_or(TailError::NoLowSpeedMaxLift)?;
    let (a126, a127) = (low.zero_lift_alpha_deg, low.max_lift_alpha_deg);

    let n = alpha_deg.len();
    let reference_area = wb.reference_area;
    let area_ratio = reference_area / p.exposed_area;
    let kwb = wb.terms.interference.wing_in_presence_of_body;
    let a7 = p.aspect_ratio;
    let taper = p.taper;
    let c4 = p.quarter_chord;
    let semispan = p.semispan;
    let separation_limit =
        figures::read(figures::LEADING_EDGE_SEPARATION, &[c4.deg], &mut warnings)?;
    let delta_y = wing.terms.section.delta_y_percent.unwrap_or(0.0);
    let leading_edge_separation = separation_limit > delta_y;
    let vortex_root_factor = 0.78 + 0.10 * (geometry.theoretical.taper - 0.40) + 0.003 * c4.deg;
    let wing_alpha: Vec<f64> = alpha_deg.iter().map(|a| a + aliw).collect();
    let zero_lift_deg = wing.terms.zero_lift_angle.wing_deg;
    let below = if a126 < wing_alpha.first().copied().unwrap_or(0.0) {
        End::Hold
    } else {
        End::Linear
    };
    let chrdtp = plan.chrdtp.unwrap_or(0.0);
    let chrdbp = plan.chrdbp.unwrap_or(chrdtp);
    let sspnop = plan.sspnop.filter(|v| *v > 0.0);
    let inboard_dihedral = plan.dhdadi_deg.unwrap_or(0.0).to_radians().tan();
    let outboard_dihedral = plan.dhdado_deg.unwrap_or(0.0).to_radians().tan();
    let dihedral_break = semispan - plan.sspndd.unwrap_or(0.0);
    let tail_semispan = tp.semispan;
    let arm_over_semispan = placement.arm / semispan;

    // The empirical gradient (DWASH 2) does not change along the integration.
    let empirical = (method == DownwashMethod::Empirical).then(|| {
        let lever = (tail_apex.0
            - (tail_geometry.x_mac_le + tail_geometry.theoretical.mac / 4.0)
                * alih.to_radians().cos())
            - (xw - (geometry.x_mac_le + geometry.theoretical.mac / 4.0) * aliw.to_radians().cos());
        empirical_downwash_gradient(
            a7,
            taper,
            c4.cos,
            placement.height,
            lever,
            p.exposed_semispan,
        )
    });

    let mut sheets = Vec::with_capacity(n);
    let mut epsilon: Vec<Option<f64>> = Vec::with_capacity(n);
    for &a in &wing_alpha {
        let points = integration_points(a);
        let steps = (points - 1) as f64;
        let mut angles = Vec::with_capacity(points);
        let mut gradients = Vec::with_capacity(points);
        let mut last: Option<VortexSheet> = None;
        for k in 0..points {
            let f = k as f64 / steps;
            // Weighted so that the last point is the angle itself, exactly: the curve's slope
            // there is read at a node, and a rounding below it would read the interval before.
            angles.push((1.0 - f) * zero_lift_deg + f * a);
            let at = (1.0 - f) * a126 + f * a;
            let fraction_of_stall = ((at - a126) / (a127 - a126)).abs();
            let Some((mut cl, slope_per_deg)) = read(&wing_alpha, &wing.cl, at, below, End::Linear)
            else {
                break;
            };
            let ratio = effective_aspect_ratio_ratio(taper, c4.cos, c4.tan, fraction_of_stall);
            let aeff = a7 * ratio;
            let gradient = match empirical {
                Some(g) => g,
                None => {
                    let at_infinity =
                        1.62 * slope_per_deg.to_degrees() / (PI * aeff) * area_ratio * kwb;
                    downwash_gradient_at_tail(at_infinity, aeff, arm_over_semispan)
                }
            };
            gradients.push(gradient);
            if k + 1 < points {
                continue;
            }
            // The vortex sheet at the angle itself (the last point), the one the average
            // downwash is read for.
            if below == End::Hold && at < wing_alpha[0] {
                cl *= (at - a126) / (wing_alpha[0] - a126);
            }
            let cl = area_ratio * cl * kwb;
            let span_ratio = 2.0 * ratio / ((1.0 + taper) + ratio * (1.0 - taper));
            let beff = 2.0 * semispan * span_ratio;
            let half = beff / 2.0;
            let tip_chord_at = match sspnop {
                None => (chrdtp - chrdr) / semispan * half + chrdr,
                Some(op) => (chrdtp - chrdbp) / op * (op - (semispan - half)) + chrdbp,
            };
            let trailing =
                placement.arm - (half * p.inboard.leading_edge.tan + tip_chord_at / 4.0) + chrdr;
            let lever = if leading_edge_separation {
                placement.arm + placement.root_chord_less_mac_le
            } else {
                trailing
            };
            let sheet_angle = at.to_radians() - 0.41 * cl / (PI * aeff);
            let dihedral = if half > dihedral_break {
                dihedral_break * inboard_dihedral + (half - dihedral_break) * outboard_dihedral
            } else {
                0.5 * beff * inboard_dihedral
            };
            let height = placement.height - lever * sheet_angle - dihedral;
            let vortex_span = if cl == 0.0 {
                beff
            } else {
                beff - (beff - vortex_root_factor * beff)
                    * (trailing / (semispan * 0.56 * a7 / cl)).abs().sqrt()
            };
            last = Some(VortexSheet {
                wing_alpha_deg: a,
                steps: points,
                effective_aspect_ratio: aeff,
                effective_span: beff,
                gradient,
                height_above_vortices: height,
                vortex_span,
                // Read below for the sheet at the angle itself (the last point), the one used.
                average_factor: 1.0,
            });
        }
        match last.filter(|_| gradients.len() == points) {
            Some(mut sheet) => {
                if method != DownwashMethod::Empirical {
                    sheet.average_factor = figures::read(
                        figures::AVERAGE_DOWNWASH,
                        &[
                            (2.0 * sheet.height_above_vortices / sheet.vortex_span).abs(),
                            2.0 * tail_semispan / sheet.vortex_span,
                        ],
                        &mut warnings,
                    )?
                    .max(0.0);
                }
                let e = trapezoid(&angles, &gradients) * sheet.average_factor;
                epsilon.push(Some(e).filter(|v| v.is_finite()));
                sheets.push(sheet);
            }
            None => epsilon.push(None),
        }
    }
    let gradient: Vec<Option<f64>> = alpha_deg
        .iter()
        .map(|&a| read(alpha_deg, &epsilon, a, End::Linear, End::Linear).map(|r| r.1))
        .collect();

    let wakes = wakes_of(wb, &wing_alpha, &placement, &mut warnings);
    Ok(Downwash {
        alpha_deg: alpha_deg.to_vec(),
        dynamic_pressure_ratio: dynamic_pressure_ratios(&wakes),
        epsilon_deg: epsilon,
        gradient,
        terms: DownwashTerms {
            method,
            placement,
            low_speed_wing: low,
            leading_edge_separation,
            sheets,
            wakes,
        },
        warnings,
    })
}
