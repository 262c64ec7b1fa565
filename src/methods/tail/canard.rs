//! Canard configurations at subsonic speeds: DATCOM 4.4.1, the canard method (the original's
//! downwash method 3: WGEOTL and WBTAIL's canard branch).
//!
//! As in the original's input, the forward surface (the canard) is the deck's wing ($WGPLNF)
//! and the aft surface (the main wing) the deck's horizontal tail ($HTPLNF). The canard's
//! trailing vortices pass the aft surface at the spanwise station of figure 4.4.1-71; their
//! effect on the aft surface is a lift increment proportional to the canard's lift, written as
//! a lift-curve slope ΔCLα (negative: the vortices' downwash inboard of them outweighs their
//! upwash outboard). The aft surface works in the canard's wake (q/q∞) but with no other
//! downwash: ε = 0 in the tail-body terms, and the increment stands in for it (the effective
//! ε and dε/dα printed by the original as partial output).

use std::f64::consts::PI;

use serde::Serialize;

use super::downwash::{dynamic_pressure_ratios, placement_of, wakes_of, TailPlacement, Wake};
use super::figures;
use super::surfaces::HorizontalTailAlone;
use super::{TailError, TailWarning};
use crate::case::Case;
use crate::geometry::{planform as planform_geometry, Span};
use crate::methods::wing_body::{interference_factors, vortex_interference_factor, WingBody};

/// The canard's vortices at the aft surface and the lift they induce on it at one angle of
/// attack.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct CanardVortexAtAngle {
    pub alpha_deg: f64,
    /// Height of the vortex above the aft surface's chord plane at its quarter chord, m:
    /// z_v = h − (l − y_v tan Λ_TE) tan(α + i_c).
    pub height: f64,
    /// Interference factor i of the vortex pair on the aft surface's exposed panels (strip
    /// theory with the body's images, as 4.3.1.3).
    pub interference_factor: f64,
    /// q/q∞ at the aft surface.
    pub dynamic_pressure_ratio: f64,
    /// ΔCLα = CLα_c CLα_H q/q∞ K_W(B) i s'_H / (2π A_H (y_v − r_c)) · S_ref/S_H, per rad, on the
    /// reference area.
    pub lift_slope_per_rad: f64,
    /// ΔCL = ΔCLα α (the schedule angle, as the original).
    pub lift: f64,
    /// The effective downwash gradient and angle the increment stands for:
    /// (dε/dα)_eff = −ΔCLα/((K_H(B) + K_B(H)) CLα_H q/q∞), ε_eff = (dε/dα)_eff (α + i_c − α0_c)
    /// in degrees (0 where the aft surface is at its zero-lift angle).
    pub effective_gradient: f64,
    pub effective_epsilon_deg: f64,
}

/// The canard's vortex terms.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct CanardVortex {
    /// Figure 4.4.1-71: spanwise station of the vortex core over the canard's exposed semispan.
    pub exposed_span_fraction: f64,
    /// y_v: spanwise station of the vortex core from the centre line, m.
    pub lateral_position: f64,
    pub at_angle: Vec<Option<CanardVortexAtAngle>>,
}

/// What the canard method takes from the two surfaces and their placement.
#[derive(Debug, Clone, Copy)]
pub struct CanardInputs {
    /// Forward surface (the deck's wing): theoretical aspect ratio, taper ratio and tangent of
    /// the leading-edge sweep, tangent of the inboard trailing-edge sweep, semispan and
    /// exposed semispan (m), β = √(1 − M²).
    pub canard_aspect_ratio: f64,
    pub canard_taper: f64,
    pub canard_tan_leading_edge: f64,
    pub canard_tan_trailing_edge: f64,
    pub canard_semispan: f64,
    pub canard_exposed_semispan: f64,
    pub beta: f64,
    /// CLα_c (the canard alone, per rad, on the reference area), its K_W(B), incidence and
    /// zero-lift angle (deg).
    pub canard_slope_per_rad: f64,
    pub canard_in_presence_of_body: f64,
    pub canard_incidence_deg: f64,
    pub canard_zero_lift_deg: f64,
    /// Aft surface (the deck's horizontal tail): semispan, exposed semispan (m), exposed taper,
    /// exposed aspect ratio and area (m²), CLα_H (per rad, on the reference area), K_H(B) +
    /// K_B(H), incidence and zero-lift angle (deg).
    pub aft_semispan: f64,
    pub aft_exposed_semispan: f64,
    pub aft_exposed_taper: f64,
    pub aft_exposed_aspect_ratio: f64,
    pub aft_exposed_area: f64,
    pub aft_slope_per_rad: f64,
    pub aft_interference_sum: f64,
    pub aft_incidence_deg: f64,
    pub aft_zero_lift_deg: f64,
    /// The aft surface's placement behind the canard (`TailPlacement`'s arm and height, m).
    pub arm: f64,
    pub height: f64,
    pub reference_area: f64,
}

/// DATCOM 4.4.1, canard method: the vortex station of figure 4.4.1-71 (y_v = s'_c f(λ_c,
/// A_c tan Λ_LE, β A_c) + r_c, on the canard's theoretical aspect ratio and taper), its height
/// at the aft surface at each angle, the interference factor i there and the lift increment
/// ΔCLα(α) α with the effective ε and dε/dα (see [`CanardVortexAtAngle`]), at the schedule
/// angles `alpha_deg` with q/q∞ `dynamic_pressure_ratio`. Subsonic. Original: WGEOTL, WBTAIL
/// (canard branch).
pub fn canard_vortex(
    i: &CanardInputs,
    alpha_deg: &[f64],
    dynamic_pressure_ratio: &[Option<f64>],
    warnings: &mut Vec<TailWarning>,
) -> Result<CanardVortex, TailError> {
    let fraction = figures::read(
        figures::CANARD_VORTEX_STATION,
        &[
            i.canard_taper,
            i.canard_aspect_ratio * i.canard_tan_leading_edge,
            i.beta * i.canard_aspect_ratio,
        ],
        warnings,
    )?;
    let canard_body_radius = i.canard_semispan - i.canard_exposed_semispan;
    let y_v = i.canard_exposed_semispan * fraction + canard_body_radius;
    let aft_body_radius = i.aft_semispan - i.aft_exposed_semispan;
    let at_angle = alpha_deg
        .iter()
        .enumerate()
        .map(|(k, &a)| {
            let q = dynamic_pressure_ratio.get(k).copied()??;
            let height = i.height
                - (i.arm - i.canard_tan_trailing_edge * y_v)
                    * (a + i.canard_incidence_deg).to_radians().tan();
            let factor = vortex_interference_factor(
                height,
                y_v,
                i.aft_semispan,
                aft_body_radius,
                i.aft_exposed_taper,
            );
            let slope = i.canard_slope_per_rad
                * i.aft_slope_per_rad
                * q
                * i.canard_in_presence_of_body
                * factor
                * i.aft_exposed_semispan
                / (2.0 * PI * i.aft_exposed_aspect_ratio * (y_v - canard_body_radius))
                * i.reference_area
                / i.aft_exposed_area;
            let effective_gradient = -slope / (i.aft_interference_sum * i.aft_slope_per_rad * q);
            let aft_from_zero_lift = a + i.aft_incidence_deg - i.aft_zero_lift_deg;
            let effective_epsilon_deg = if aft_from_zero_lift == 0.0 {
                0.0
            } else {
                effective_gradient * (a + i.canard_incidence_deg - i.canard_zero_lift_deg)
            };
            let out = CanardVortexAtAngle {
                alpha_deg: a,
                height,
                interference_factor: factor,
                dynamic_pressure_ratio: q,
                lift_slope_per_rad: slope,
                lift: slope * a.to_radians(),
                effective_gradient,
                effective_epsilon_deg,
            };
            [slope, effective_gradient, effective_epsilon_deg]
                .iter()
                .all(|v| v.is_finite())
                .then_some(out)
        })
        .collect();
    Ok(CanardVortex {
        exposed_span_fraction: fraction,
        lateral_position: y_v,
        at_angle,
    })
}

impl CanardVortexAtAngle {
    /// The increment's pitching moment about the moment reference: ΔCL along the aft surface's
    /// normal at the schedule angle, (x_cg − x_ac,H)/c̄ ΔCL cos α − (z_H − z_cg)/c̄ ΔCL sin α.
    pub fn moment(&self, lever: f64, height: f64) -> f64 {
        let (s, c) = self.alpha_deg.to_radians().sin_cos();
        lever * self.lift * c - height * self.lift * s
    }
}

/// The canard configuration's terms: the aft surface's placement behind the canard, the
/// canard's wake there (q/q∞, DATCOM 4.4.1 figures 4.4.1-69 to -71 as for a tail behind a wing)
/// and its vortices (see [`canard_vortex`]).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Canard {
    pub placement: TailPlacement,
    pub wakes: Vec<Option<Wake>>,
    pub dynamic_pressure_ratio: Vec<Option<f64>>,
    pub vortex: CanardVortex,
    /// The increment's pitching moment at each angle ([`CanardVortexAtAngle::moment`]).
    pub moment: Vec<Option<f64>>,
}

/// The canard terms of `case` at flight condition `condition_index` and schedule angles
/// `alpha_deg`, with the canard-body `wb` (the deck's wing-body) and the aft surface alone
/// `tail` computed. Subsonic, straight canard. Original: DYPRLS, WGEOTL, WBTAIL.
pub(crate) fn canard(
    case: &Case,
    condition_index: usize,
    alpha_deg: &[f64],
    wb: &WingBody,
    tail: &HorizontalTailAlone,
    warnings: &mut Vec<TailWarning>,
) -> Result<Canard, TailError> {
    let plan = case.wing.as_ref().ok_or(TailError::NoWing)?;
    let geometry = planform_geometry(plan, Span::Both).map_err(|e| TailError::Geometry {
        reason: format!("wing: {e}"),
    })?;
    let placement = placement_of(case, &geometry, tail);
    let aliw = case
        .synthesis
        .as_ref()
        .and_then(|s| s.aliw_deg)
        .unwrap_or(0.0);
    let wing_alpha: Vec<f64> = alpha_deg.iter().map(|a| a + aliw).collect();
    let wakes = wakes_of(wb, &wing_alpha, &placement, warnings);
    let q = dynamic_pressure_ratios(&wakes);
    let inputs = vortex_inputs(case, condition_index, wb, tail, &placement)?;
    let vortex = canard_vortex(&inputs, alpha_deg, &q, warnings)?;
    Ok(Canard {
        placement,
        wakes,
        dynamic_pressure_ratio: q,
        vortex,
        moment: Vec::new(),
    })
}

/// The leading-edge sweep (tangent) figure 4.4.1-71 is read at: a straight-tapered planform's
/// own; for two panels the planform's sweep ([`PlanformGeometry::sweep_deg`]: the arc cosine
/// of the panels' cosines weighted by their exposed areas, the original's A(38)), since the
/// figure is for straight-tapered wings.
///
/// [`PlanformGeometry::sweep_deg`]: crate::geometry::PlanformGeometry::sweep_deg
fn effective_tan_leading_edge(g: &crate::geometry::PlanformGeometry) -> f64 {
    match g.outboard {
        None => g.tan_sweep_inboard(0.0),
        Some(_) => g.sweep_deg(0.0).to_radians().tan(),
    }
}

/// The inputs of [`canard_vortex`] for the deck's wing ahead of its horizontal tail at
/// `placement`: a canard and its aft surface, or a conventional wing and tail (whose tip
/// vortices' factor at the tail the original prints with PART as IV-W(H)).
pub(crate) fn vortex_inputs(
    case: &Case,
    condition_index: usize,
    wb: &WingBody,
    tail: &HorizontalTailAlone,
    placement: &TailPlacement,
) -> Result<CanardInputs, TailError> {
    let plan = case.wing.as_ref().ok_or(TailError::NoWing)?;
    let geometry = planform_geometry(plan, Span::Both).map_err(|e| TailError::Geometry {
        reason: format!("wing: {e}"),
    })?;
    let s = case.synthesis.as_ref();
    let get = |f: fn(&crate::case::Synthesis) -> Option<f64>| s.and_then(f).unwrap_or(0.0);
    let (aliw, alih) = (get(|s| s.aliw_deg), get(|s| s.alih_deg));
    let mach =
        case.conditions
            .get(condition_index)
            .map(|c| c.mach)
            .ok_or(TailError::NoCondition {
                index: condition_index,
            })?;
    let wing = &wb.terms.wing;
    let p = &wing.terms.planform;
    let tp = &tail.surface.terms.planform;
    let mut wb_warnings = Vec::new();
    let aft = interference_factors(
        (tp.semispan - tp.exposed_semispan) / tp.semispan,
        &mut wb_warnings,
    )
    .map_err(TailError::WingBody)?;
    let canard_slope =
        wing.cla_per_rad
            .first()
            .copied()
            .flatten()
            .ok_or_else(|| TailError::Geometry {
                reason: "the canard (wing) has no lift-curve slope".to_string(),
            })?;
    Ok(CanardInputs {
        canard_aspect_ratio: geometry.theoretical.aspect_ratio,
        canard_taper: geometry.theoretical.taper,
        canard_tan_leading_edge: effective_tan_leading_edge(&geometry),
        canard_tan_trailing_edge: geometry.tan_sweep_inboard(1.0),
        canard_semispan: p.semispan,
        canard_exposed_semispan: p.exposed_semispan,
        beta: (1.0 - mach * mach).sqrt(),
        canard_slope_per_rad: canard_slope,
        canard_in_presence_of_body: wb.terms.interference.wing_in_presence_of_body,
        canard_incidence_deg: aliw,
        canard_zero_lift_deg: wing.terms.zero_lift_angle.wing_deg,
        aft_semispan: tp.semispan,
        aft_exposed_semispan: tp.exposed_semispan,
        aft_exposed_taper: tp.taper,
        aft_exposed_aspect_ratio: tp.aspect_ratio,
        aft_exposed_area: tp.exposed_area,
        aft_slope_per_rad: tail.slope_per_rad,
        aft_interference_sum: aft.wing_in_presence_of_body + aft.body_in_presence_of_wing,
        aft_incidence_deg: alih,
        aft_zero_lift_deg: tail.surface.terms.zero_lift_angle.wing_deg,
        arm: placement.arm,
        height: placement.height,
        reference_area: wb.reference_area,
    })
}

#[cfg(test)]
mod tests {
    use super::effective_tan_leading_edge;
    use crate::geometry::{planform, Span};

    /// Tolerance: the original's A(38) printed with six digits by an instrumented build.
    const PRINTED: f64 = 5e-6;

    fn wing(card: &str) -> crate::geometry::PlanformGeometry {
        let deck = crate::read_deck(
            &format!(" $FLTCON NMACH=1.0, MACH(1)=0.2$\n $SYNTHS XCG=1.0$\n{card}\n"),
            "t.dcm",
        );
        let plan = deck.cases[0].wing.clone().expect("a wing");
        planform(&plan, Span::Both).expect("a planform")
    }

    #[test]
    fn straight_wing_keeps_its_leading_edge() {
        let g = wing(" $WGPLNF CHRDR=2.0, CHRDTP=1.0, SSPN=5.0, SSPNE=4.5, SAVSI=30.0, CHSTAT=0.0, TYPE=1.0$");
        assert!(g.outboard.is_none());
        assert_eq!(effective_tan_leading_edge(&g), g.tan_sweep_inboard(0.0));
    }

    #[test]
    fn two_panels_take_the_equivalent_sweep_of_the_original() {
        // arktools__datcom2modelica_shadowmaster_echo's wing (feet): an unswept inboard panel
        // and a 39.52° outboard panel; the instrumented original's A(38) is 0.143153.
        let g = wing(
            " $WGPLNF CHRDBP=4.881,CHRDTP=3.959,SSPNE=19.886,SSPN=22.601,SSPNOP=0.965,\n  CHRDR=4.881, SAVSO=39.52,TWISTA=0.0, CHSTAT=0.0, DHDADI=0.0,TYPE=1.0$",
        );
        assert_eq!(g.tan_sweep_inboard(0.0), 0.0);
        assert!((effective_tan_leading_edge(&g) - 0.143153).abs() < PRINTED);
    }
}
