//! Vertical tail and ventral fin: CYβ, Cnβ and Clβ, DATCOM 5.3.1.1 (single vertical panel on
//! the plane of symmetry, with the body and horizontal tail end-plate effects and the sidewash
//! of 5.3.1.1) applied as the original's SUBLAT does.

use std::f64::consts::PI;

use serde::Serialize;

use super::figures::{self, read};
use super::wing_body::body_side;
use super::{finite, Lateral, LateralError, LateralWarning};
use crate::case::{Case, Planform};
use crate::deck::cards::Surface;
use crate::geometry::{planform as planform_geometry, PlanformGeometry, Span};
use crate::methods::section::{section_characteristics, surface_section};
use crate::methods::tail::tail_position;
use crate::methods::wing::WingType;

/// The sidewash factor (1 + dσ/dβ)·q_v/q of DATCOM 5.3.1.1 (equation 5.3.1.1-b):
/// 0.724 + 3.06 (S_v/S)/(1 + cos Λc/4) + 0.4 z_w/d + 0.009 A.
const SIDEWASH_CONSTANT: f64 = 0.724;
const SIDEWASH_AREA: f64 = 3.06;
const SIDEWASH_HEIGHT: f64 = 0.4;
const SIDEWASH_ASPECT: f64 = 0.009;

/// Which vertical surface.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Fin {
    /// $VTPLNF at XV, ZV (above the body when VERTUP); sidewash from the wing, end plate from
    /// the horizontal tail; twin panels of PHIV.
    VerticalTail,
    /// $VFPLNF at XVF, ZVF; the original treats it as a vertical tail behind the horizontal
    /// tail (the sidewash from the horizontal tail, no end plate), twin panels of PHIF.
    VentralFin,
}

impl Fin {
    fn name(self) -> &'static str {
        match self {
            Fin::VerticalTail => "vertical tail",
            Fin::VentralFin => "ventral fin",
        }
    }
}

/// The terms of the fin's derivatives (lengths in metres).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct FinLateralTerms {
    pub fin: Fin,
    /// b_v/(2 r₁): the panel's span over the body depth at the panel (SSPN/(2(SSPN − SSPNE))).
    pub span_over_body_depth: f64,
    /// Geometric aspect ratio of the panel, b_v²/S_v, and its area S_v, m².
    pub aspect_ratio: f64,
    pub area: f64,
    /// A_v(B)/A_v, figure 5.3.1.1-22a.
    pub body_aspect_ratio_factor: f64,
    /// A_v(HB)/A_v(B), figure 5.3.1.1-22b, and K_H, figure 5.3.1.1-22c (none without the
    /// horizontal tail's end-plate effect).
    pub tail_aspect_ratio_factor: Option<f64>,
    pub tail_size_factor: Option<f64>,
    /// A_v,eff = A_v(B)/A_v · A_v · (1 + K_H (A_v(HB)/A_v(B) − 1)).
    pub effective_aspect_ratio: f64,
    /// (1 + dσ/dβ) q_v/q.
    pub sidewash: f64,
    /// κ = c_lα/(2π) of the panel's section at this Mach number.
    pub kappa: f64,
    /// Lift-curve slope of the panel on its own area, per rad.
    pub lift_curve_slope_per_rad: f64,
    /// k of figure 5.3.1.1-22d.
    pub k: f64,
    /// l_v: XCG to the quarter chord of the panel's MAC, positive aft; z_v: height of the MAC
    /// above ZCG (the original's sign rule, see docs/lateral.md).
    pub arm_x: f64,
    pub arm_z: f64,
    /// 2 cos² φ for twin panels (PHIV, PHIF), none for one panel.
    pub twin_factor: Option<f64>,
}

/// Section lift-curve slope of the fin, per rad, at flight condition `k`: the user's CLALPA
/// (per degree in the deck) for the condition's Mach index, else the section method's value.
fn section_slope(case: &Case, surface: Surface, k: usize) -> Result<f64, LateralError> {
    let condition = case
        .conditions
        .get(k)
        .ok_or(LateralError::NoCondition { index: k })?;
    let user = case
        .sections
        .get(surface.name())
        .and_then(|s| s.per_mach.get("CLALPA"))
        .and_then(|v| v.get(condition.mach_index).copied())
        .filter(|v| v.is_finite() && *v > 0.0);
    if let Some(per_deg) = user {
        return Ok(per_deg.to_degrees());
    }
    let (what, namelist) = match surface {
        Surface::VentralFin => ("ventral fin", "VFSCHR"),
        _ => ("vertical tail", "VTSCHR"),
    };
    let none = || {
        LateralError::Geometry {
        reason: format!(
            "the {what} has no section lift-curve slope (give a NACA card, section coordinates or CLALPA in ${namelist})"
        ),
    }
    };
    let s = surface_section(case, surface)
        .ok_or_else(none)?
        .map_err(|e| LateralError::Geometry {
            reason: e.to_string(),
        })?;
    let c = section_characteristics(&s.shape, &s.conditions, &s.overrides).map_err(|e| {
        LateralError::Geometry {
            reason: e.to_string(),
        }
    })?;
    c.per_mach
        .get(k)
        .and_then(|m| m.cla_per_rad)
        .filter(|v| v.is_finite() && *v > 0.0)
        .ok_or_else(none)
}

fn geometry(plan: &Planform, span: Span, what: &str) -> Result<PlanformGeometry, LateralError> {
    planform_geometry(plan, span).map_err(|e| LateralError::Geometry {
        reason: format!("{what}: {e}"),
    })
}

/// The panel's chordwise position x of the horizontal tail's MAC quarter chord behind the
/// panel's leading edge at the tail height `zh`, and the panel chord there (the arguments of
/// figure 5.3.1.1-22b; the original's M29O35).
fn chord_at_tail_height(
    plan: &Planform,
    g: &PlanformGeometry,
    tail_quarter_chord_behind_panel_apex: f64,
    zh: f64,
) -> (f64, f64) {
    let root = plan.chrdr.unwrap_or(0.0);
    let tip = plan.chrdtp.unwrap_or(0.0);
    let semispan = g.semispan;
    let tan_le_in = g.tan_sweep_inboard(0.0);
    let outboard_span = plan.sspnop.filter(|s| *s > 0.0).unwrap_or(0.0);
    // TYPE read as the wing methods read it (rounded; 5 and above straight). Without an
    // outboard panel the panel is straight whatever TYPE says, as the planform's geometry
    // takes it: a TYPE other than 1 without SSPNOP divided by the outboard panel's zero span
    // above the tip, and took CHRDBP as a break chord below it.
    let straight_type = WingType::from_input(plan.planform_type) == Some(WingType::Straight)
        || outboard_span == 0.0;
    if straight_type {
        return (
            tail_quarter_chord_behind_panel_apex - zh * tan_le_in,
            root - (root - tip) * zh / semispan,
        );
    }
    let break_chord = plan.chrdbp.unwrap_or(root);
    let inboard_span = semispan - outboard_span;
    if zh <= inboard_span {
        (
            tail_quarter_chord_behind_panel_apex - zh * tan_le_in,
            root - (root - break_chord) * zh / inboard_span,
        )
    } else {
        (
            tail_quarter_chord_behind_panel_apex
                - inboard_span * tan_le_in
                - (zh - inboard_span) * g.tan_sweep_outboard(0.0),
            tip + (break_chord - tip) * (semispan - zh) / outboard_span,
        )
    }
}

/// CYβ, Cnβ (first row) and Clβ (every row) of the vertical tail or the ventral fin at subsonic
/// speed for flight condition `condition_index` of `case`, per radian, DATCOM 5.3.1.1 as the
/// original's SUBLAT applies it:
///
/// - A_v,eff = (A_v(B)/A_v)·A_v·[1 + K_H (A_v(HB)/A_v(B) − 1)], figures 5.3.1.1-22a (panel
///   taper, b_v/2r₁), -22b (x/c_v of the horizontal tail, −z_H/b_v) and -22c (S_H/S_v); the
///   end-plate factors only for the vertical tail with a horizontal tail at or above the
///   panel root (z_H after the tail's incidence ≥ 0);
/// - CLα_v = 2πA_eff/(2 + √(A_eff²/κ²·(1 + tan²Λc/2/β²) + 4)), κ = c_lα/(2π), β = √(1 − M²);
/// - (1 + dσ/dβ)q_v/q = 0.724 + 3.06 (S_v/S_w)/(1 + cos Λc/4,w) + 0.4 z_w/d + 0.009 A_w with
///   the wing (the horizontal tail for the ventral fin), z_w = −Z_W + c_r/4·sin i_W and d the
///   body's largest height;
/// - CYβ = −k·CLα_v·(1 + dσ/dβ)q_v/q·S_v/S, k of figure 5.3.1.1-22d (b_v/2r₁);
///   Cnβ = −CYβ·l_v/b; Clβ(α) = CYβ (z_v cos α − l_v sin α)/b; twin panels (PHIV, PHIF)
///   × 2cos²φ.
///
/// l_v is from XCG to the quarter chord of the panel's MAC, z_v the height of the MAC above
/// ZCG (the ventral fin's counted downward when VERTUP, as the original). Errors: no such
/// surface, no body, no wing (vertical tail) or horizontal tail (ventral fin), whose sidewash
/// the original needs, no section slope, charts.
pub fn fin_lateral(
    case: &Case,
    condition_index: usize,
    alpha_deg: &[f64],
    fin: Fin,
) -> Result<Lateral, LateralError> {
    let missing = |what: &str| LateralError::Geometry {
        reason: format!("the {} sideslip terms need {what}", fin.name()),
    };
    let (plan, surface, sidewash_plan) = match fin {
        Fin::VerticalTail => (
            case.vertical_tail
                .as_ref()
                .ok_or_else(|| missing("$VTPLNF"))?,
            Surface::VerticalTail,
            case.wing.as_ref().ok_or_else(|| missing("the wing"))?,
        ),
        Fin::VentralFin => (
            case.ventral_fin
                .as_ref()
                .ok_or_else(|| missing("$VFPLNF"))?,
            Surface::VentralFin,
            case.horizontal_tail
                .as_ref()
                .ok_or_else(|| missing("the horizontal tail"))?,
        ),
    };
    let condition = case
        .conditions
        .get(condition_index)
        .ok_or(LateralError::NoCondition {
            index: condition_index,
        })?;
    let side = body_side(case).ok_or_else(|| missing("the body"))?;
    let s_ref = super::reference_area(case).ok_or_else(|| missing("a reference area"))?;
    let b_ref = super::body::lateral_reference_span(case).ok_or(LateralError::NoReferenceSpan)?;
    let mut warnings = Vec::new();

    let g = geometry(plan, Span::Single, fin.name())?;
    let gw = geometry(sidewash_plan, Span::Both, "the sidewash surface")?;
    let synthesis = case.synthesis.as_ref();
    let get = |f: fn(&crate::case::Synthesis) -> Option<f64>| synthesis.and_then(f).unwrap_or(0.0);
    let vertup = synthesis.is_none_or(|s| s.vertup);
    let (xcg, zcg) = (get(|s| s.xcg), get(|s| s.zcg));

    // Body depth at the panel, and the panel in the presence of the body.
    let body_depth_span = g.semispan - g.exposed_semispan;
    let span_over_body_depth = if body_depth_span > 0.0 {
        g.semispan / (2.0 * body_depth_span)
    } else {
        warnings.push(LateralWarning::NoBodyAtFin);
        f64::MAX
    };
    let root = plan.chrdr.unwrap_or(0.0);
    let taper = plan.chrdtp.unwrap_or(0.0) / root;
    let mut body_chart_warnings = Vec::new();
    let body_aspect_ratio_factor = read(
        figures::FIN_ASPECT_IN_BODY,
        &[taper, span_over_body_depth],
        &mut body_chart_warnings,
    )?;
    let k = read(
        figures::FIN_SIDE_FORCE_K,
        &[span_over_body_depth],
        &mut body_chart_warnings,
    )?;
    // Without body depth the ratio is unbounded: NoBodyAtFin says the charts are held at their
    // last nodes, and a chart warning quoting f64::MAX would say nothing more.
    let unbounded = body_depth_span <= 0.0;
    warnings.extend(body_chart_warnings.into_iter().filter(|w| {
        !(unbounded && matches!(w, LateralWarning::Chart(c) if c.value == span_over_body_depth))
    }));

    // End plate of the horizontal tail (vertical tail only).
    let mut tail_aspect_ratio_factor = None;
    let mut tail_size_factor = None;
    if let (Fin::VerticalTail, Some(ht)) = (fin, case.horizontal_tail.as_ref()) {
        let gh = geometry(ht, Span::Both, "the horizontal tail")?;
        let (xh, zh) = tail_position(synthesis);
        let alih = get(|s| s.alih_deg);
        let zh_mac = zh - gh.x_exposed_mac_quarter * alih.to_radians().sin();
        if zh_mac >= 0.0 {
            let quarter = xh + gh.x_mac_le + gh.theoretical.mac / 4.0 - get(|s| s.xv);
            let (x, chord) = chord_at_tail_height(plan, &g, quarter, zh);
            tail_aspect_ratio_factor = Some(read(
                figures::FIN_ASPECT_WITH_TAIL,
                &[x / chord, -zh_mac / g.semispan],
                &mut warnings,
            )?);
            tail_size_factor = Some(read(
                figures::FIN_TAIL_SIZE,
                &[gh.theoretical.area / g.theoretical.area],
                &mut warnings,
            )?);
        }
    }
    let aspect_ratio = g.theoretical.aspect_ratio;
    let effective_aspect_ratio = body_aspect_ratio_factor
        * aspect_ratio
        * (1.0 + tail_size_factor.unwrap_or(0.0) * (tail_aspect_ratio_factor.unwrap_or(0.0) - 1.0));

    // Sidewash and dynamic pressure from the wing (the horizontal tail for the ventral fin).
    let (z_surface, incidence) = match fin {
        Fin::VerticalTail => (get(|s| s.zw), get(|s| s.aliw_deg)),
        Fin::VentralFin => (get(|s| s.zh), get(|s| s.alih_deg)),
    };
    let height =
        -z_surface + sidewash_plan.chrdr.unwrap_or(0.0) / 4.0 * incidence.to_radians().sin();
    let cos_quarter = gw.sweep_deg(0.25).to_radians().cos();
    let sidewash = SIDEWASH_CONSTANT
        + SIDEWASH_AREA * (g.theoretical.area / gw.theoretical.area) / (1.0 + cos_quarter)
        + SIDEWASH_HEIGHT * height / side.max_height
        + SIDEWASH_ASPECT * gw.theoretical.aspect_ratio;

    // Lift-curve slope of the panel (DATCOM 4.1.3.2 with A_eff).
    let kappa = section_slope(case, surface, condition_index)? / (2.0 * PI);
    let beta = (1.0 - condition.mach * condition.mach).abs().sqrt();
    let tan_half = g.sweep_deg(0.5).to_radians().tan();
    let lift_curve_slope_per_rad = 2.0 * PI * effective_aspect_ratio
        / (2.0
            + (effective_aspect_ratio * effective_aspect_ratio / (kappa * kappa)
                * (1.0 + tan_half * tan_half / (beta * beta))
                + 4.0)
                .sqrt());

    // Arms.
    let (x_fin, z_fin) = match fin {
        Fin::VerticalTail => (get(|s| s.xv), get(|s| s.zv)),
        Fin::VentralFin => (get(|s| s.xvf), get(|s| s.zvf)),
    };
    let arm_x = (x_fin - xcg) + g.x_mac_le + g.theoretical.mac / 4.0;
    let mac_height = g.theoretical.y_mac + z_fin;
    let downward = match fin {
        Fin::VerticalTail => !vertup,
        Fin::VentralFin => vertup,
    };
    let arm_z = if downward {
        -zcg - mac_height
    } else {
        -zcg + mac_height
    };
    let twin_angle = match fin {
        Fin::VerticalTail => synthesis.and_then(|s| s.phiv_deg),
        Fin::VentralFin => synthesis.and_then(|s| s.phif_deg),
    };
    let twin_factor = twin_angle.map(|p| 2.0 * p.to_radians().cos().powi(2));
    let twin = twin_factor.unwrap_or(1.0);

    let cyb = -k * lift_curve_slope_per_rad * sidewash * g.theoretical.area / s_ref * twin;
    let (cyb_rows, cnb_rows, clb) = side_force_rows(alpha_deg, cyb, arm_x, arm_z, b_ref);
    Ok(Lateral {
        alpha_deg: alpha_deg.to_vec(),
        cyb: cyb_rows,
        cnb: cnb_rows,
        clb,
        wing_terms: None,
        wing_body_terms: None,
        fin_terms: Some(FinLateralTerms {
            fin,
            span_over_body_depth,
            aspect_ratio,
            area: g.theoretical.area,
            body_aspect_ratio_factor,
            tail_aspect_ratio_factor,
            tail_size_factor,
            effective_aspect_ratio,
            sidewash,
            kappa,
            lift_curve_slope_per_rad,
            k,
            arm_x,
            arm_z,
            twin_factor,
        }),
        twin_panel_terms: None,
        warnings,
    })
}

/// CYβ, Cnβ and Clβ against angle of attack.
pub(super) type SideForceRows = (Vec<Option<f64>>, Vec<Option<f64>>, Vec<Option<f64>>);

/// The sideslip columns of a side force CYβ acting at `arm_x` aft of and `arm_z` above the
/// moment reference (DATCOM 5.3.1.1): CYβ and Cnβ = −CYβ·l/b on the first row (the original
/// gives them once), Clβ = CYβ (z cos α − l sin α)/b at every angle.
pub(super) fn side_force_rows(
    alpha_deg: &[f64],
    cyb: f64,
    arm_x: f64,
    arm_z: f64,
    b_ref: f64,
) -> SideForceRows {
    let n = alpha_deg.len();
    let mut cyb_rows = vec![None; n];
    let mut cnb_rows = vec![None; n];
    if n > 0 {
        cyb_rows[0] = finite(cyb);
        cnb_rows[0] = finite(-cyb * arm_x / b_ref);
    }
    let clb = alpha_deg
        .iter()
        .map(|a| {
            let (sin, cos) = a.to_radians().sin_cos();
            finite(cyb * (arm_z * cos - arm_x * sin) / b_ref)
        })
        .collect();
    (cyb_rows, cnb_rows, clb)
}
