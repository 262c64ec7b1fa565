//! Twin vertical panels ($TVTPAN): CYβ, Cnβ and Clβ, DATCOM 5.3.1.1 (twin vertical panels,
//! figures 5.3.1.1-24a to -24c) applied as the original's SUBLAT does, at subsonic speeds.
//!
//! The original adds these terms to the vertical tail's, so every page with the vertical tail
//! carries them; it has no longitudinal term for the panels (their drag, lift and pitching
//! moment are not computed), and above Mach 1 it leaves them out and says so ("LATERAL
//! STABILITY DERIVATIVES DO NOT INCLUDE THE EFFECTS OF TWIN VERTICAL PANELS").

use serde::Serialize;

use super::figures::{self, read};
use super::{Lateral, LateralError, LateralWarning};
use crate::case::Case;

/// The terms of the twin panels' derivatives (lengths in metres).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct TwinPanelLateralTerms {
    /// BVP/BV: the panel span above the lifting surface over the panel span.
    pub span_above_over_span: f64,
    /// A_eff/A of the panel's position, figure 5.3.1.1-24a.
    pub position_factor: f64,
    /// Geometric aspect ratio of one panel, BV²/SV.
    pub aspect_ratio: f64,
    /// Effective aspect ratio, position factor × aspect ratio.
    pub effective_aspect_ratio: f64,
    /// Lift-curve slope of one panel, per radian, figure 5.3.1.1-24b (VPHITE, A_eff).
    pub lift_curve_slope_per_rad: f64,
    /// BH over the body length, and BDV/BV: the arguments of figure 5.3.1.1-24c.
    pub spacing_over_body_length: f64,
    pub body_depth_over_span: f64,
    /// The side-force factor of figure 5.3.1.1-24c.
    pub body_factor: f64,
    /// Area of both panels, 2·SV, m².
    pub area: f64,
    /// VLP and ZP, the arms of the panels' side force, m.
    pub arm_x: f64,
    pub arm_z: f64,
}

/// True when the case's twin vertical panels count at flight condition `condition_index`: the
/// original adds their terms up to STMACH and leaves them out above it.
pub fn twin_panels_counted(case: &Case, condition_index: usize) -> bool {
    case.twin_panels.is_some()
        && case
            .conditions
            .get(condition_index)
            .is_some_and(|c| c.mach <= crate::methods::body::subsonic_limit(case))
}

/// CYβ, Cnβ (first row) and Clβ (every row) of the twin vertical panels for flight condition
/// `condition_index` of `case`, per radian:
///
/// - A_eff = (A_eff/A)·BV²/SV, figure 5.3.1.1-24a at BVP/BV;
/// - CLα_p of figure 5.3.1.1-24b (VPHITE, A_eff);
/// - CYβ = −K·CLα_p·2 SV/S, K of figure 5.3.1.1-24c (BH/l_B, BDV/BV), l_B the body length;
/// - Cnβ = −CYβ·VLP/b; Clβ(α) = CYβ (ZP cos α − VLP sin α)/b.
///
/// Subsonic only (the caller leaves the panels out above STMACH, as the original:
/// [`twin_panels_counted`]). VPHITE not given is 0°, with a warning. Errors: no $TVTPAN,
/// another variable of it missing, no body (its length), no reference area or lateral
/// reference length, charts.
pub fn twin_panel_lateral(case: &Case, alpha_deg: &[f64]) -> Result<Lateral, LateralError> {
    let missing = |what: &str| LateralError::Geometry {
        reason: format!("the twin vertical panels' sideslip terms need {what}"),
    };
    let p = case
        .twin_panels
        .as_ref()
        .ok_or_else(|| missing("$TVTPAN"))?;
    let need = |v: Option<f64>, name: &str| {
        v.filter(|x| x.is_finite())
            .ok_or_else(|| missing(&format!("$TVTPAN {name}")))
    };
    let bv = need(p.bv, "BV").and_then(|b| {
        if b > 0.0 {
            Ok(b)
        } else {
            Err(missing("$TVTPAN BV > 0"))
        }
    })?;
    let sv = need(p.sv, "SV").and_then(|s| {
        if s > 0.0 {
            Ok(s)
        } else {
            Err(missing("$TVTPAN SV > 0"))
        }
    })?;
    let (bvp, bdv, bh) = (need(p.bvp, "BVP")?, need(p.bdv, "BDV")?, need(p.bh, "BH")?);
    let mut warnings = Vec::new();
    // Unset, the original's VPHITE is 0 (its listing equals the one with VPHITE=0.0).
    let vphite = p.vphite.filter(|v| v.is_finite()).unwrap_or_else(|| {
        warnings.push(LateralWarning::NoTrailingEdgeAngle);
        0.0
    });
    let (arm_x, arm_z) = (need(p.vlp, "VLP")?, p.zp.unwrap_or(0.0));
    // From the nose: the original measures the body from X(1) (a deck whose nose is not at
    // 0 gives the same length).
    let body_length = case
        .body
        .as_ref()
        .and_then(|b| Some(b.x.last()? - b.x.first()?))
        .filter(|l| *l > 0.0)
        .ok_or_else(|| missing("the body's length"))?;
    let s_ref = super::reference_area(case).ok_or_else(|| missing("a reference area"))?;
    let b_ref = super::body::lateral_reference_span(case).ok_or(LateralError::NoReferenceSpan)?;

    let span_above_over_span = bvp / bv;
    let position_factor = read(
        figures::TWIN_PANEL_POSITION,
        &[span_above_over_span],
        &mut warnings,
    )?;
    let aspect_ratio = bv * bv / sv;
    let effective_aspect_ratio = position_factor * aspect_ratio;
    let lift_curve_slope_per_rad = read(
        figures::TWIN_PANEL_LIFT_SLOPE,
        &[vphite, effective_aspect_ratio],
        &mut warnings,
    )?;
    let spacing_over_body_length = bh / body_length;
    let body_depth_over_span = bdv / bv;
    let body_factor = read(
        figures::TWIN_PANEL_BODY,
        &[spacing_over_body_length, body_depth_over_span],
        &mut warnings,
    )?;
    let area = 2.0 * sv;
    let cyb = -body_factor * lift_curve_slope_per_rad * area / s_ref;

    let (cyb_rows, cnb_rows, clb) =
        super::vertical_tail::side_force_rows(alpha_deg, cyb, arm_x, arm_z, b_ref);
    Ok(Lateral {
        alpha_deg: alpha_deg.to_vec(),
        cyb: cyb_rows,
        cnb: cnb_rows,
        clb,
        wing_terms: None,
        wing_body_terms: None,
        fin_terms: None,
        twin_panel_terms: Some(TwinPanelLateralTerms {
            span_above_over_span,
            position_factor,
            aspect_ratio,
            effective_aspect_ratio,
            lift_curve_slope_per_rad,
            spacing_over_body_length,
            body_depth_over_span,
            body_factor,
            area,
            arm_x,
            arm_z,
        }),
        warnings,
    })
}
