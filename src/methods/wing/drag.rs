//! DATCOM 4.1.5.1 (zero-lift drag) and 4.1.5.2 (drag due to lift) of wings at subsonic
//! speeds (the original's CDRAG, with FIG26 and FIG53A).

use std::f64::consts::PI;

use serde::Serialize;

use super::figures::{self, *};
use super::planform::{PanelTerms, WingPlanform};
use super::{WingMethodError, WingType, WingWarning};
use crate::methods::body::{skin_friction_coefficient, BodyMethodError, BodyWarning};

/// Form factor of DATCOM 4.1.5.1 equation 4.1.5.1-a: 1 + L (t/c) + 100 (t/c)⁴, with L = 1.2
/// when the maximum thickness is at or aft of 30 % chord, else 2.0.
const THICKNESS_LOCATION_SPLIT: f64 = 0.30;
/// A computed section's station of maximum thickness is a single-precision number: a NACA
/// 4-digit section's 0.3 comes out as 0.29999998. Within this of the split it counts as at 30 %
/// (the original, and DATCOM's intent: the 4-digit sections take L = 1.2).
const THICKNESS_LOCATION_TOLERANCE: f64 = 1e-6;
const L_AFT: f64 = 1.2;
const L_FORWARD: f64 = 2.0;
const FOURTH_POWER_FACTOR: f64 = 100.0;
/// Leading-edge Reynolds parameter above which figure 4.1.5.2-53b replaces the polynomials of
/// 53a.
const SUCTION_POLYNOMIALS_UP_TO: f64 = 1.3e5;
/// Straight-tapered wings: e = 1.1 (CLα/A) / (R CLα/A + (1 − R) π) (DATCOM 4.1.5.2 eq. c).
const STRAIGHT_EFFICIENCY_FACTOR: f64 = 1.1;
/// Double-delta wings: CDL = 0.95 CL tan α (as the original, for want of a DATCOM method).
const DOUBLE_DELTA_DRAG_FACTOR: f64 = 0.95;

/// Skin friction of one panel.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct PanelFriction {
    /// Reynolds number on the panel's MAC, and the one used (the smaller of it and the
    /// cut-off Reynolds number).
    pub reynolds_number: f64,
    pub reynolds_number_used: f64,
    /// Turbulent flat-plate skin-friction coefficient (figure 4.1.5.1-26).
    pub skin_friction_coefficient: f64,
    pub form_factor: f64,
    /// Lifting-surface correlation factor R_LS (figure 4.1.5.1-28b).
    pub lifting_surface_factor: f64,
    /// Cf (form factor) R_LS S_wet/S_ref, with S_wet = 2 S_panel.
    pub drag: f64,
}

/// Zero-lift drag of the wing.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct WingZeroLiftDrag {
    /// Cut-off Reynolds number of the surface roughness (figure 4.1.5.1-27).
    pub cutoff_reynolds_number: f64,
    /// Straight-tapered: the exposed planform; two-panel: the inboard panel.
    pub inboard: PanelFriction,
    pub outboard: Option<PanelFriction>,
    pub total: f64,
}

/// Drag due to lift terms.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct DragDueToLift {
    /// K_W(B) of figure 4.3.1.2-10a by which CLα and CL are scaled when the case has a body.
    pub wing_body_lift_ratio: Option<f64>,
    /// Leading-edge suction parameter R (figure 4.1.5.2-53).
    pub suction_parameter: Option<f64>,
    /// Span efficiency factor e.
    pub efficiency: Option<f64>,
    /// Twist drag factors v and w (figures 4.1.5.2-42, -48), straight-tapered wings.
    pub twist_v: Option<f64>,
    pub twist_w: Option<f64>,
    /// CDL at each angle.
    pub cd: Vec<f64>,
}

/// One panel as the zero-lift drag sees it.
struct FrictionPanel {
    mac: f64,
    area: f64,
    thickness_ratio: f64,
    max_thickness_x: Option<f64>,
    cos_max_thickness: f64,
    /// Read R_LS on the dashed curves (inboard panel of a two-panel wing).
    dashed: bool,
}

fn panel_friction(
    i: &DragInputs,
    panel: &FrictionPanel,
    cutoff: f64,
    warnings: &mut Vec<WingWarning>,
) -> Result<PanelFriction, WingMethodError> {
    let FrictionPanel {
        mac: panel_mac,
        area: panel_area,
        thickness_ratio,
        max_thickness_x,
        cos_max_thickness,
        dashed,
    } = *panel;
    let (mach, reference_area) = (i.mach, i.reference_area);
    let reynolds_number = i.reynolds_per_length * panel_mac;
    let used = reynolds_number.min(cutoff);
    let mut body_warnings = Vec::new();
    let cf = skin_friction_coefficient(used, mach, &mut body_warnings).map_err(
        |e: BodyMethodError| WingMethodError::SkinFriction {
            reason: e.to_string(),
        },
    )?;
    for w in body_warnings {
        if let BodyWarning::Chart(c) = w {
            warnings.push(WingWarning::Chart(c));
        }
    }
    let l = if max_thickness_x.unwrap_or(0.0)
        >= THICKNESS_LOCATION_SPLIT - THICKNESS_LOCATION_TOLERANCE
    {
        L_AFT
    } else {
        L_FORWARD
    };
    let t = thickness_ratio;
    let form_factor = 1.0 + l * t + FOURTH_POWER_FACTOR * t.powi(4);
    let chart = if dashed {
        LIFTING_SURFACE_FACTOR_DASHED
    } else {
        LIFTING_SURFACE_FACTOR
    };
    let rls = figures::read(chart, &[mach, cos_max_thickness], warnings)?;
    Ok(PanelFriction {
        reynolds_number,
        reynolds_number_used: used,
        skin_friction_coefficient: cf,
        form_factor,
        lifting_surface_factor: rls,
        drag: cf * form_factor * rls * 2.0 * panel_area / reference_area,
    })
}

/// Inputs of the drag methods.
pub struct DragInputs<'a> {
    pub planform: &'a WingPlanform,
    pub kind: WingType,
    pub mach: f64,
    pub beta: f64,
    pub reynolds_per_length: f64,
    /// Roughness height, m.
    pub roughness: f64,
    pub reference_area: f64,
    pub thickness_ratio: f64,
    pub max_thickness_x: Option<f64>,
    pub outboard_thickness_ratio: f64,
    pub outboard_max_thickness_x: Option<f64>,
    pub leading_edge_radius: f64,
    pub outboard_leading_edge_radius: f64,
    pub twist_deg: f64,
}

/// DATCOM 4.1.5.1, the wing's subsonic zero-lift drag: per panel
/// CD0 = Cf (1 + L t/c + 100 (t/c)⁴) R_LS S_wet/S_ref (equation 4.1.5.1-a), with the skin
/// friction of figure 4.1.5.1-26 at the Reynolds number on the panel's MAC (at most the
/// cut-off Reynolds number of figure 4.1.5.1-27), R_LS of figure 4.1.5.1-28b (the dashed
/// curves for the inboard panel of a two-panel wing) and S_wet = 2 S_exposed.
pub fn wing_zero_lift_drag(
    i: &DragInputs,
    warnings: &mut Vec<WingWarning>,
) -> Result<WingZeroLiftDrag, WingMethodError> {
    let p = i.planform;
    let log_length_over_roughness = (p.mac / i.roughness).log10();
    let cutoff = 10f64.powf(figures::read(
        CUTOFF_REYNOLDS,
        &[i.mach, log_length_over_roughness],
        warnings,
    )?);
    let (inboard, outboard) = match &p.outboard {
        None => (
            FrictionPanel {
                mac: p.mac,
                area: p.exposed_area,
                thickness_ratio: i.thickness_ratio,
                max_thickness_x: i.max_thickness_x,
                cos_max_thickness: p.cos_max_thickness,
                dashed: false,
            },
            None,
        ),
        Some(o) => (
            FrictionPanel {
                mac: p.inboard.mac,
                area: p.inboard.area,
                thickness_ratio: i.thickness_ratio,
                max_thickness_x: i.max_thickness_x,
                cos_max_thickness: p.inboard.cos_max_thickness,
                dashed: true,
            },
            Some(FrictionPanel {
                mac: o.mac,
                area: o.area,
                thickness_ratio: i.outboard_thickness_ratio,
                max_thickness_x: i.outboard_max_thickness_x,
                cos_max_thickness: o.cos_max_thickness,
                dashed: false,
            }),
        ),
    };
    let inboard = panel_friction(i, &inboard, cutoff, warnings)?;
    let outboard = match outboard {
        Some(o) => Some(panel_friction(i, &o, cutoff, warnings)?),
        None => None,
    };
    Ok(WingZeroLiftDrag {
        cutoff_reynolds_number: cutoff,
        total: inboard.drag + outboard.map_or(0.0, |o| o.drag),
        inboard,
        outboard,
    })
}

/// DATCOM figure 4.1.5.2-53: the leading-edge suction parameter R at the leading-edge
/// Reynolds parameter `rv` = R_LER cot Λ_LE √(1 − M² cos² Λ_LE) and Z = A λ / cos Λ_LE: the
/// polynomials of 53a up to 1.3E5 (negative values taken as 0), figure 53b above.
pub fn suction_parameter(
    rv: f64,
    z: f64,
    warnings: &mut Vec<WingWarning>,
) -> Result<f64, WingMethodError> {
    if rv > SUCTION_POLYNOMIALS_UP_TO || rv.is_infinite() {
        return figures::read(SUCTION_HIGH_REYNOLDS, &[z], warnings);
    }
    if rv <= 0.0 {
        return Ok(0.0);
    }
    let x = rv.log10();
    let mut r = 0.0;
    let mut power = 1.0;
    for n in 1..=5 {
        power *= x;
        r += figures::read(SUCTION_LOW_REYNOLDS, &[z, n as f64], warnings)? * power;
    }
    Ok(r.max(0.0))
}

/// The leading-edge Reynolds parameter of a panel: R_LER/|tan Λ_LE| √(1 − M² cos² Λ_LE)
/// (infinite for an unswept leading edge).
fn leading_edge_reynolds(
    re_per_length: f64,
    radius: f64,
    mac: f64,
    panel: Sweep2,
    mach: f64,
) -> f64 {
    let r_ler = re_per_length * radius * mac;
    if r_ler == 0.0 {
        return 0.0;
    }
    if panel.tan == 0.0 {
        return f64::INFINITY;
    }
    let m = mach * panel.cos;
    r_ler / panel.tan.abs() * (1.0 - m * m).sqrt()
}

#[derive(Clone, Copy)]
struct Sweep2 {
    tan: f64,
    cos: f64,
}

fn le(p: &PanelTerms) -> Sweep2 {
    Sweep2 {
        tan: p.leading_edge.tan,
        cos: p.leading_edge.cos,
    }
}

/// DATCOM 4.1.5.2, subsonic drag due to lift at each CL (and wing angle `alpha_deg`).
///
/// - Straight-tapered: CDL = CL²/(π A e) S_ref/S_exp + θ' CL v + θ'² w S_exp/S_ref, with
///   e = 1.1 (CLα/A)/(R CLα/A + (1 − R) π) (CLα per radian on the exposed area), R of figure
///   4.1.5.2-53, v and w = βw/β of figures 4.1.5.2-42 and -48, θ' = 2π θ/57.3 (θ the twist,
///   deg; the original's scaling).
/// - Cranked: e = X/(R X + (1 − R) π) with R the span-weighted suction of the two panels (the
///   inboard at Z = 0), plus ΔCDL of figure 4.1.5.2-54.
/// - Double delta: CDL = 0.95 CL tan α.
///
/// With a body, CLα and CL are multiplied by K_W(B) of figure 4.3.1.2-10a for this
/// computation only (as the original).
pub fn drag_due_to_lift(
    i: &DragInputs,
    lift_curve_slope_per_rad: f64,
    cl: &[f64],
    alpha_deg: &[f64],
    body_span_ratio: Option<f64>,
    warnings: &mut Vec<WingWarning>,
) -> Result<DragDueToLift, WingMethodError> {
    let p = i.planform;
    let kwb = match body_span_ratio {
        Some(r) => Some(figures::read(WING_BODY_LIFT_RATIO, &[r], warnings)?),
        None => None,
    };
    let k = kwb.unwrap_or(1.0);
    let cla = lift_curve_slope_per_rad * k;
    let area_ratio = p.exposed_area / i.reference_area;
    let a = p.aspect_ratio;
    let x = cla / area_ratio / a;
    let mut out = DragDueToLift {
        wing_body_lift_ratio: kwb,
        suction_parameter: None,
        efficiency: None,
        twist_v: None,
        twist_w: None,
        cd: Vec::with_capacity(cl.len()),
    };
    match (i.kind, &p.outboard) {
        (WingType::Straight, _) => {
            let whole = Sweep2 {
                tan: p.leading_edge.tan,
                cos: p.leading_edge.cos,
            };
            let rv = leading_edge_reynolds(
                i.reynolds_per_length,
                i.leading_edge_radius,
                p.mac,
                whole,
                i.mach,
            );
            let r = suction_parameter(rv, a * p.taper / p.leading_edge.cos, warnings)?;
            let e = STRAIGHT_EFFICIENCY_FACTOR * x / (r * x + (1.0 - r) * PI);
            let sweep = (p.quarter_chord.tan / i.beta).atan().to_degrees();
            let v = figures::read(TWIST_DRAG_V, &[p.taper, sweep, a * i.beta], warnings)?;
            let beta_w = figures::read(TWIST_DRAG_W, &[p.taper, sweep, a * i.beta], warnings)?;
            let w = beta_w / i.beta;
            let theta = 2.0 * PI * i.twist_deg.to_radians();
            for c in cl {
                let c = c * k;
                out.cd.push(
                    c * c / (PI * a * e) / area_ratio
                        + theta * c * v
                        + theta * theta * w * area_ratio,
                );
            }
            out.suction_parameter = Some(r);
            out.efficiency = Some(e);
            out.twist_v = Some(v);
            out.twist_w = Some(beta_w / i.beta);
        }
        (WingType::Cranked, Some(o)) => {
            let rv_in = leading_edge_reynolds(
                i.reynolds_per_length,
                i.leading_edge_radius,
                p.inboard.mac,
                le(&p.inboard),
                i.mach,
            );
            let rv_out = leading_edge_reynolds(
                i.reynolds_per_length,
                i.outboard_leading_edge_radius,
                o.mac,
                le(o),
                i.mach,
            );
            let r_in = suction_parameter(rv_in, 0.0, warnings)?;
            let r_out = suction_parameter(
                rv_out,
                o.aspect_ratio * o.taper / o.leading_edge.cos,
                warnings,
            )?;
            let f = p.inboard.span / p.exposed_semispan;
            let r = r_in * f + r_out * (1.0 - f);
            let e = x / (r * x + (1.0 - r) * PI);
            for c in cl {
                let c = c * k;
                let increment = figures::read(
                    CRANKED_DRAG_INCREMENT,
                    &[c.abs() / a / area_ratio, a],
                    warnings,
                )?;
                out.cd
                    .push(c * c / (PI * e * a) / area_ratio + increment * area_ratio);
            }
            out.suction_parameter = Some(r);
            out.efficiency = Some(e);
        }
        _ => {
            for (c, al) in cl.iter().zip(alpha_deg) {
                out.cd
                    .push(DOUBLE_DELTA_DRAG_FACTOR * c * k * al.to_radians().tan());
            }
        }
    }
    Ok(out)
}
