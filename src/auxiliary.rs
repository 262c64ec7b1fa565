//! The PART card's output: the original's CONFIGURATION AUXILIARY AND PARTIAL OUTPUT pages,
//! the intermediate quantities of the build-up a designer checks a hand calculation against.
//!
//! Produced for the case's own configuration at each flight condition (with BUILD the
//! component pages have none, as in the original):
//! - BASIC BODY PROPERTIES: wetted and base areas and the body's zero-lift drag with its base
//!   and friction parts (DATCOM 2.3, 4.2.3.1);
//! - the moment reference centre behind the leading edge of the wing's theoretical MAC;
//! - BASIC PLANFORM PROPERTIES of each surface, theoretical and exposed (DATCOM 2.2.2), with
//!   the exposed panel's zero-lift drag and skin-friction coefficient (DATCOM 4.1.5.1);
//! - the wing-body interference line CLA-B(W), CLA-W(B), K-B(W), K-W(B), XAC/C-B(W)
//!   (DATCOM 4.3.1.2, 4.3.2.2);
//! - the same line for the horizontal tail and the body, and the vertical tail's sidewash
//!   factor (DATCOM 5.3.1.1);
//! - the body-vortex table (DATCOM 4.3.1.3) at the wing and the horizontal tail;
//! - with DAMP, the wing's roll- and yaw-rate increments (DATCOM 7.1.2.1 to 7.1.2.3), its
//!   Clβ per degree of dihedral (5.1.2.1) and the surfaces' ΔCm0 per degree of twist
//!   (4.1.4.1).
//!
//! Not produced yet (docs/output.md): the transonic data-fairing tables.
//!
//! Values are SI (m, m²) and per radian, as everywhere inside the library; reports convert.

use serde::Serialize;

use crate::case::{Case, Planform};
use crate::deck::cards::Surface;
use crate::geometry::{planform, Span};
use crate::methods::section::SectionCharacteristics;

/// The auxiliary output of one flight condition.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct AuxiliaryOutput {
    /// Present with a body.
    pub body: Option<BodyProperties>,
    /// x of the moment reference centre behind the leading edge of the wing's theoretical MAC,
    /// m; present with a wing.
    pub xcg_behind_mac_leading_edge: Option<f64>,
    /// Wing, horizontal tail, vertical tail, ventral fin: those the case has.
    pub planforms: Vec<PlanformProperties>,
    /// The wing-body interference line; present with a wing and a body at subsonic speed
    /// (absent where the wing-body method fails: its error is among the page's warnings).
    pub wing_body: Option<crate::methods::wing_body::Auxiliary>,
    /// The same line of the horizontal tail and the body (CLA-B(H), CLA-H(B), K-B(H), K-H(B),
    /// XAC/C-B(H)); present with a horizontal tail behind the wing and a body.
    pub tail_body: Option<crate::methods::wing_body::Auxiliary>,
    /// The vertical tail's sidewash factor (1 + dσ/dβ) q_v/q (DATCOM 5.3.1.1, equation
    /// 5.3.1.1-b); present with a wing, a body and a vertical tail.
    pub sidewash: Option<f64>,
    /// The body vortices at the wing and, with a horizontal tail, at the tail (DATCOM
    /// 4.3.1.3); present with a wing and a body.
    pub vortices: Option<VortexTable>,
    /// With DAMP: the wing's roll- and yaw-rate increments (DYNAMIC DERIVATIVE INCREMENTALS).
    pub roll_increments: Option<crate::methods::dynamic::RollIncrements>,
    /// The wing's Clβ per degree of uniform dihedral, per deg² (figure 5.1.2.1-29): CLB/GAMMA.
    pub clb_per_dihedral: Option<f64>,
    /// ΔCm0 per degree of twist of the wing and of the horizontal tail (figure 4.1.4.1-5),
    /// present when the surface is twisted: (CMO/THETA)W, (CMO/THETA)H.
    pub wing_cm0_per_twist: Option<f64>,
    pub tail_cm0_per_twist: Option<f64>,
}

/// The body-vortex table: per angle of attack, the vortex pair's interference factor and
/// strength at the wing (IV-B(W), Γ/(2π α V r)) and at the horizontal tail (IV-B(H),
/// (Γ/(2π α V r))T), and the interference factor of the wing's tip vortices at the tail
/// (IV-W(H)).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct VortexTable {
    pub alpha_deg: Vec<f64>,
    pub wing: Vec<VortexAt>,
    pub tail: Option<Vec<VortexAt>>,
    /// IV-W(H): the interference factor of the wing's tip vortices at the horizontal tail
    /// (DATCOM 4.4.1, figure 4.4.1-71 for their spanwise station); with a horizontal tail.
    pub tail_from_wing_vortices: Option<Vec<Option<f64>>>,
}

/// The body vortex pair at a surface at one angle.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct VortexAt {
    /// The surface's interference factor i of the pair (0 without vortices).
    pub interference_factor: f64,
    /// Γ/(2π α V r); 0 below the vortices' onset angle, none where they leave the body behind
    /// the surface (the original's NDM).
    pub strength: Option<f64>,
}

impl From<&crate::methods::wing_body::BodyVortex> for VortexAt {
    fn from(v: &crate::methods::wing_body::BodyVortex) -> Self {
        let behind = v.separation_station.is_some() && v.height.is_none();
        VortexAt {
            interference_factor: v.interference_factor,
            strength: (!behind).then_some(v.strength),
        }
    }
}

/// The body's areas and zero-lift drag (drag on the reference area).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct BodyProperties {
    /// m².
    pub wetted_area: f64,
    /// m².
    pub base_area: f64,
    /// Friction plus base; none where the method is not applicable (the original's NDM).
    pub zero_lift_drag: Option<f64>,
    pub base_drag: Option<f64>,
    /// Skin friction with the form factor.
    pub friction_drag: Option<f64>,
    /// None at subsonic speeds: the form factor carries it (the original's NA).
    pub pressure_drag: Option<f64>,
}

/// One surface's planform properties.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct PlanformProperties {
    pub surface: Surface,
    pub theoretical: PlanformRow,
    pub exposed: PlanformRow,
    /// The exposed surface's zero-lift drag on the reference area; none where it is not
    /// computed (no thickness ratio, or not subsonic).
    pub zero_lift_drag: Option<f64>,
    /// Turbulent flat-plate skin-friction coefficient at the exposed MAC's Reynolds number.
    pub friction_coefficient: Option<f64>,
}

/// A planform's row of the BASIC PLANFORM PROPERTIES block.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct PlanformRow {
    /// m² (horizontal surfaces: both halves; vertical ones: the one panel).
    pub area: f64,
    pub taper_ratio: f64,
    pub aspect_ratio: f64,
    pub quarter_chord_sweep_deg: f64,
    /// Mean aerodynamic chord, m.
    pub mac: f64,
    /// x of the MAC's quarter chord from the body nose, m.
    pub x_mac_quarter_chord: f64,
    /// Spanwise station of the MAC from the centreline, m. Vertical surfaces: the theoretical
    /// row's height includes ZV (above the body axis), the exposed row's is from the
    /// theoretical root, as the original prints them.
    pub y_mac: f64,
}

/// The auxiliary output of flight condition `index` of `case` at the angles `alpha_deg`.
/// Parts whose method fails are left out: the component pages' warnings say why.
pub fn auxiliary_output(
    case: &Case,
    index: usize,
    alpha_deg: &[f64],
    wing_section: Option<&SectionCharacteristics>,
) -> AuxiliaryOutput {
    let body = case.body.as_ref().and_then(|b| {
        let g = crate::geometry::body(b).ok()?;
        let drag = case.conditions.get(index).and_then(|c| {
            crate::methods::body::body_alone(case, &g, c, alpha_deg)
                .ok()
                .and_then(|b| b.zero_lift_drag)
        });
        Some(BodyProperties {
            wetted_area: g.wetted_area,
            base_area: g.base_area,
            zero_lift_drag: drag.as_ref().map(|d| d.total),
            base_drag: drag.as_ref().map(|d| d.base),
            friction_drag: drag.as_ref().map(|d| d.friction),
            pressure_drag: drag.as_ref().and_then(|d| d.pressure),
        })
    });
    let wing = case.wing.as_ref().and_then(|_| {
        crate::methods::wing::wing_alone_with_section(case, index, alpha_deg, wing_section).ok()
    });
    let tail = case
        .horizontal_tail
        .as_ref()
        .and_then(|_| crate::methods::tail::horizontal_tail_alone(case, index, alpha_deg).ok());
    let planforms: Vec<PlanformProperties> = [
        Surface::Wing,
        Surface::HorizontalTail,
        Surface::VerticalTail,
        Surface::VentralFin,
    ]
    .into_iter()
    .filter_map(|s| planform_properties(case, index, s, wing.as_ref(), tail.as_ref()))
    .collect();
    let xcg_behind_mac_leading_edge =
        planforms
            .iter()
            .find(|p| p.surface == Surface::Wing)
            .map(|w| {
                let xcg = case.synthesis.as_ref().and_then(|s| s.xcg).unwrap_or(0.0);
                xcg - (w.theoretical.x_mac_quarter_chord - w.theoretical.mac / 4.0)
            });
    let combination = (case.wing.is_some() && case.body.is_some())
        .then(|| {
            crate::methods::wing_body::wing_body_with_section(case, index, alpha_deg, wing_section)
                .ok()
        })
        .flatten();
    let wing_body = combination.as_ref().map(|wb| wb.auxiliary);
    let totals = (combination.is_some() && case.horizontal_tail.is_some())
        .then(|| crate::methods::tail::configuration(case, index, alpha_deg).ok())
        .flatten();
    let tail_body = totals.as_ref().and_then(|t| tail_body_line(case, index, t));
    let vortices = combination.as_ref().map(|wb| VortexTable {
        alpha_deg: alpha_deg.to_vec(),
        wing: wb.terms.vortices.iter().map(VortexAt::from).collect(),
        tail: totals
            .as_ref()
            .and_then(|t| t.terms.tail_body.as_ref())
            .map(|tb| tb.vortices.iter().map(VortexAt::from).collect()),
        tail_from_wing_vortices: totals
            .as_ref()
            .and_then(|t| tip_vortex_factors(case, index, alpha_deg, t)),
    });
    let sidewash = (case.wing.is_some() && case.body.is_some() && case.vertical_tail.is_some())
        .then(|| {
            crate::methods::lateral::fin_lateral(
                case,
                index,
                alpha_deg,
                crate::methods::lateral::Fin::VerticalTail,
            )
            .ok()?
            .fin_terms
            .map(|t| t.sidewash)
        })
        .flatten();
    let per_twist = |w: &crate::methods::wing::WingAlone| {
        w.terms
            .pitching_moment
            .as_ref()
            .and_then(|m| m.zero_lift.per_twist)
    };
    let roll_increments = wing
        .as_ref()
        .filter(|_| case.cards.damp)
        .and_then(|w| crate::methods::dynamic::wing_dynamic(case, index, alpha_deg, w).ok())
        .and_then(|(_, terms)| terms.increments);
    let clb_per_dihedral = wing
        .as_ref()
        .and_then(|w| crate::methods::lateral::wing_lateral(case, index, alpha_deg, w).ok())
        .and_then(|l| l.wing_terms)
        .and_then(|t| match t.rolling_moment {
            Some(crate::methods::lateral::RollingMomentTerms::Straight {
                dihedral: crate::methods::lateral::DihedralRoll::Uniform { per_dihedral, .. },
                ..
            }) => Some(per_dihedral),
            _ => None,
        });
    AuxiliaryOutput {
        body,
        xcg_behind_mac_leading_edge,
        planforms,
        wing_body,
        tail_body,
        sidewash,
        vortices,
        roll_increments,
        clb_per_dihedral,
        wing_cm0_per_twist: wing.as_ref().and_then(per_twist),
        tail_cm0_per_twist: tail.as_ref().and_then(|t| per_twist(&t.surface)),
    }
}

/// IV-W(H) at each angle: the factor i of the wing's tip vortices at the tail (as the canard
/// method's, which gives it for a canard's vortices at the aft surface; here at the tail's
/// placement behind the wing).
fn tip_vortex_factors(
    case: &Case,
    index: usize,
    alpha_deg: &[f64],
    totals: &crate::methods::tail::ConfigurationTotals,
) -> Option<Vec<Option<f64>>> {
    let terms = &totals.terms;
    let vortex = match &terms.canard {
        Some(c) => c.vortex.clone(),
        None => {
            let tail = terms.horizontal_tail.as_ref()?;
            let placement = &terms.downwash.as_ref()?.terms.placement;
            let inputs =
                crate::methods::tail::vortex_inputs(case, index, &terms.wing_body, tail, placement)
                    .ok()?;
            // The factor does not depend on the dynamic pressure at the tail.
            let q = vec![Some(1.0); alpha_deg.len()];
            crate::methods::tail::canard_vortex(&inputs, alpha_deg, &q, &mut Vec::new()).ok()?
        }
    };
    Some(
        vortex
            .at_angle
            .iter()
            .map(|a| a.map(|a| a.interference_factor))
            .collect(),
    )
}

/// The horizontal tail's interference line: K_B(H), K_H(B) at the tail's d/b (DATCOM 4.3.1.2)
/// times the tail's lift-curve slope on the reference area, and the centre of the lift carried
/// over onto the body (DATCOM 4.3.2.2) from the tail's exposed planform.
fn tail_body_line(
    case: &Case,
    index: usize,
    totals: &crate::methods::tail::ConfigurationTotals,
) -> Option<crate::methods::wing_body::Auxiliary> {
    use crate::methods::wing_body::{carry_over_centre, Auxiliary, CarryOverInputs};
    let factors = &totals.terms.tail_body.as_ref()?.interference;
    let tail = totals.terms.horizontal_tail.as_ref()?;
    let mach = case.conditions.get(index)?.mach;
    let beta = (1.0 - mach * mach).abs().sqrt();
    let centre = carry_over_centre(
        &CarryOverInputs::of_planform(&tail.surface.terms.planform, beta, totals.reference_length),
        &mut Vec::new(),
    )
    .ok()?;
    Some(Auxiliary::of(factors, tail.slope_per_rad, &centre))
}

/// Sweep of the quarter chord over a two-panel planform: the arc cosine of the panels' cosines
/// weighted by their areas (the original's reading for the TOTAL rows); the straight-tapered
/// planform's own sweep otherwise.
fn total_quarter_chord_sweep_deg(g: &crate::geometry::PlanformGeometry, type1: bool) -> f64 {
    let Some(outboard) = g.outboard.filter(|_| !type1) else {
        return g.sweep_deg(0.25);
    };
    let cos_in = g.tan_sweep_inboard(0.25).atan().cos();
    let cos_out = g.tan_sweep_outboard(0.25).atan().cos();
    let a_in = g.inboard_theoretical.area;
    let weighted = (a_in * cos_in + outboard.area * cos_out) / (a_in + outboard.area);
    weighted.clamp(-1.0, 1.0).acos().to_degrees()
}

fn planform_properties(
    case: &Case,
    index: usize,
    surface: Surface,
    wing: Option<&crate::methods::wing::WingAlone>,
    tail: Option<&crate::methods::tail::HorizontalTailAlone>,
) -> Option<PlanformProperties> {
    let syn = case.synthesis.as_ref();
    let (p, span, x0, z0): (&Planform, Span, Option<f64>, Option<f64>) = match surface {
        Surface::Wing => (
            case.wing.as_ref()?,
            Span::Both,
            syn.and_then(|s| s.xw),
            None,
        ),
        Surface::HorizontalTail => (
            case.horizontal_tail.as_ref()?,
            Span::Both,
            syn.and_then(|s| s.xh),
            None,
        ),
        Surface::VerticalTail => (
            case.vertical_tail.as_ref()?,
            Span::Single,
            syn.and_then(|s| s.xv),
            syn.and_then(|s| s.zv),
        ),
        Surface::VentralFin => (
            case.ventral_fin.as_ref()?,
            Span::Single,
            syn.and_then(|s| s.xvf),
            syn.and_then(|s| s.zvf),
        ),
    };
    let g = planform(p, span).ok()?;
    let (x0, z0) = (x0.unwrap_or(0.0), z0.unwrap_or(0.0));
    let type1 = p.planform_type.is_none_or(|t| (t + 0.5).floor() == 1.0);
    let theoretical = PlanformRow {
        area: g.theoretical.area,
        taper_ratio: g.theoretical.taper,
        aspect_ratio: g.theoretical.aspect_ratio,
        quarter_chord_sweep_deg: total_quarter_chord_sweep_deg(&g, type1),
        mac: g.theoretical.mac,
        x_mac_quarter_chord: x0 + g.x_mac_le + g.theoretical.mac / 4.0,
        y_mac: g.theoretical.y_mac + z0,
    };
    let exposed = PlanformRow {
        area: g.exposed.area,
        taper_ratio: g.exposed.taper,
        aspect_ratio: g.exposed.aspect_ratio,
        quarter_chord_sweep_deg: g.sweep_deg(0.25),
        mac: g.exposed.mac,
        x_mac_quarter_chord: x0 + g.x_exposed_mac_quarter,
        // From the centreline, or for a vertical surface from its theoretical root (the
        // original leaves ZV out of the exposed row, as it prints it).
        y_mac: g.exposed.y_mac + g.semispan - g.exposed_semispan,
    };
    let drag = match surface {
        Surface::Wing => wing.and_then(|w| w.terms.zero_lift_drag),
        Surface::HorizontalTail => tail.and_then(|t| t.surface.terms.zero_lift_drag),
        Surface::VerticalTail | Surface::VentralFin => {
            crate::methods::tail::fin_zero_lift_drag(case, index, surface, &mut Vec::new())
                .ok()
                .map(|f| f.drag)
        }
    };
    Some(PlanformProperties {
        surface,
        theoretical,
        exposed,
        zero_lift_drag: drag.as_ref().map(|d| d.total),
        friction_coefficient: drag.map(|d| d.inboard.skin_friction_coefficient),
    })
}
