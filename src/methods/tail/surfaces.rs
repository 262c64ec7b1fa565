//! The tail surfaces on their own: the horizontal tail by the wing methods (DATCOM 4.1.3 to
//! 4.1.5 applied to the tail, as the original's M16O20, M05O05 and M33O41 do), the vertical
//! tail's and ventral fin's zero-lift drag (DATCOM 4.1.5.1, the original's VTDRAG and VFDRAG),
//! and the wing at Mach 0 whose zero-lift angle and angle of maximum lift the downwash method
//! takes (the original's CLMCH0).

use serde::Serialize;

use super::table::node_slopes;
use super::{TailError, TailWarning};
use crate::case::{Case, Planform, Synthesis};
use crate::deck::cards::Surface;
use crate::geometry::{planform as planform_geometry, Span};
use crate::methods::body::roughness_height;
use crate::methods::section::{section_characteristics, surface_section};
use crate::methods::wing::{
    mach_zero_wing, outboard_defaults, wing_alone, wing_zero_lift_drag, Chords, DragInputs,
    MaxThicknessStations, OutboardDefaults, PanelTerms, WingAlone, WingMethodError, WingPlanform,
    WingType, WingZeroLiftDrag, NONLINEAR_ASPECT_LIMIT,
};
use crate::results::planform_area_and_mac;

/// A CLA at an angle after the first that departs from the first angle's slope of the CL
/// curve by more than this fraction makes the tail's moment "not applicable" from that angle
/// on (the original's M33O41 test for the horizontal tail; the wing's is 90 %).
pub const TAIL_NOT_APPLICABLE_SLOPE_CHANGE: f64 = 0.075;

/// Which lift-curve slope a low-aspect-ratio straight horizontal tail (A ≤ 6/((C1 + 1) cos
/// Λ_LE)) takes into its combinations with the body and the wing (the incidence, body-vortex
/// and carry-over terms, the configuration's CLα).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum TailSlopeReading {
    /// The tail's lift-curve slope of DATCOM 4.1.3.2, as for any other tail.
    #[default]
    Handbook,
    /// As the original program: the slope of the tail's CL curve at the first angle of the
    /// schedule (M33O41 skips the line that restores the analytic slope for such a tail), so
    /// that a schedule starting beyond the stall gives the tail almost no slope. For
    /// reproducing old listings (docs/differences.md).
    Original,
}

/// XH and ZH after the rotation about the hinge axis HINAX (the original's INFTGM): with the
/// tail at incidence ALIH about x = HINAX, ZH += sin ALIH (HINAX − XH) and XH = HINAX (1 −
/// cos ALIH) + XH cos ALIH. Without HINAX, XH and ZH as given (0 when absent).
pub fn tail_position(s: Option<&Synthesis>) -> (f64, f64) {
    let get = |f: fn(&Synthesis) -> Option<f64>| s.and_then(f).unwrap_or(0.0);
    let (xh, zh, alih) = (get(|s| s.xh), get(|s| s.zh), get(|s| s.alih_deg));
    match s.and_then(|s| s.hinax) {
        Some(hinax) => {
            let (sin, cos) = alih.to_radians().sin_cos();
            (hinax * (1.0 - cos) + xh * cos, zh + sin * (hinax - xh))
        }
        None => (xh, zh),
    }
}

/// Reference area and length of the case: $OPTINS, else the wing's theoretical area and MAC.
fn reference(case: &Case) -> (Option<f64>, Option<f64>) {
    let wing = case.wing.as_ref().and_then(planform_area_and_mac);
    (
        case.reference.area.or(wing.map(|w| w.0)),
        case.reference.chord.or(wing.map(|w| w.1)),
    )
}

/// The case with the horizontal tail in the wing's place (planform, section, position and
/// incidence), on the case's reference area and length: the wing methods applied to it give
/// the horizontal tail alone.
pub fn tail_as_wing(case: &Case) -> Result<Case, TailError> {
    let tail = case
        .horizontal_tail
        .clone()
        .ok_or(TailError::NoHorizontalTail)?;
    // The tail's section input in the wing's place; the other surfaces' are not read.
    let sections = case
        .sections
        .get(Surface::HorizontalTail.name())
        .map(|s| (Surface::Wing.name().to_string(), s.clone()))
        .into_iter()
        .collect();
    let mut proxy = case.with_sections(sections);
    let (area, chord) = reference(case);
    proxy.reference.area = area;
    proxy.reference.chord = chord;
    proxy.wing = Some(tail);
    proxy.airfoils = case
        .airfoils
        .iter()
        .filter(|a| a.surface == Surface::HorizontalTail)
        .cloned()
        .map(|mut a| {
            a.surface = Surface::Wing;
            a
        })
        .collect();
    let (xh, zh) = tail_position(case.synthesis.as_ref());
    let mut s = case.synthesis.clone().unwrap_or_default();
    s.xw = Some(xh);
    s.zw = Some(zh);
    s.aliw_deg = s.alih_deg;
    proxy.synthesis = Some(s);
    proxy.larwb = None;
    // The deck's experimental wing-body data belong to the wing, not to the tail in its
    // place (the original's body-horizontal tail takes none); its body data stay.
    for (name, values) in proxy.other.iter_mut() {
        if name.starts_with("EXPR") {
            values
                .retain(|var, _| !crate::methods::experimental::WING_BODY.contains(&var.as_str()));
        }
    }
    Ok(proxy)
}

/// The horizontal tail alone (the original's HORIZONTAL TAIL CONFIGURATION page) and the
/// lift-curve slope its combination with the wing and body takes.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct HorizontalTailAlone {
    /// The wing methods on the tail: CL, CD, CM at the tail angles α + ALIH, on the case's
    /// reference area and length, moments about XCG. Its CLA, CMA and CM are the wing page's;
    /// the tail page's are below.
    pub surface: WingAlone,
    /// The page's CM, CLA, CMA (per rad) and XCP after the tail's own rules.
    pub cm: Vec<Option<f64>>,
    pub xcp: Vec<Option<f64>>,
    pub cla_per_rad: Vec<Option<f64>>,
    pub cma_per_rad: Vec<Option<f64>>,
    /// CLα_H, per rad, on the reference area, that the tail's combinations take: the analytic
    /// slope, or for a low-aspect-ratio straight tail with [`TailSlopeReading::Original`] the
    /// slope of its CL curve at the first angle.
    pub slope_per_rad: f64,
    /// The tail is a low-aspect-ratio straight planform (A ≤ 6/((C1 + 1) cos Λ_LE)).
    pub low_aspect_ratio_straight: bool,
}

impl HorizontalTailAlone {
    /// The tail in the wing's place of the wing-body methods (the BODY-HORIZONTAL TAIL page):
    /// the surface with the page's moment (the tail's "not applicable" rule) and the slope its
    /// combinations take.
    pub fn in_place(self) -> crate::methods::wing_body::SurfaceInPlace {
        let mut surface = self.surface;
        surface.cm = self.cm;
        crate::methods::wing_body::SurfaceInPlace {
            surface,
            slope_per_rad: self.slope_per_rad,
        }
    }
}

/// DATCOM 4.1.3 to 4.1.5 applied to the horizontal tail at subsonic speeds: the wing-alone
/// methods of `methods::wing` on the tail's planform ($HTPLNF), section ($HTSCHR or a NACA-H
/// card), position (XH, ZH after HINAX) and incidence ALIH, on the case's reference area and
/// length. Then, as the original's M33O41: for a low-aspect-ratio straight tail the first
/// angle's CLA and CMA are the slopes of the CL and CM curves there (and so is CLα_H with
/// [`TailSlopeReading::Original`]); otherwise CM and CMA are not applicable from the first
/// angle whose CLA departs from the first angle's curve slope by more than 7.5 %, and the first
/// angle keeps the analytic slopes. Validity: that of the wing methods. Original: M16O20,
/// M05O05, M33O41.
pub fn horizontal_tail_alone(
    case: &Case,
    condition_index: usize,
    alpha_deg: &[f64],
) -> Result<HorizontalTailAlone, TailError> {
    let proxy = tail_as_wing(case)?;
    let surface =
        wing_alone(&proxy, condition_index, alpha_deg).map_err(TailError::HorizontalTail)?;
    let n = alpha_deg.len();
    let alpha_rad: Vec<f64> = alpha_deg.iter().map(|a| a.to_radians()).collect();
    let curve_cla = node_slopes(&alpha_rad, &surface.cl);
    let curve_cma = node_slopes(&alpha_rad, &surface.cm);
    let class = &surface.terms.aspect_ratio_class;
    let low_aspect_ratio_straight = surface.planform_type == WingType::Straight
        && surface.terms.planform.aspect_ratio <= NONLINEAR_ASPECT_LIMIT / class.c1_cos_le;
    let mut cm = surface.cm.clone();
    let mut cla = surface.cla_per_rad.clone();
    let mut cma = surface.cma_per_rad.clone();
    let analytic = surface.terms.lift_curve_slope.per_rad;
    let mut slope_per_rad = analytic;
    if n > 0 {
        // A schedule of one angle gives a curve without a slope: the analytic one stands.
        if low_aspect_ratio_straight && n > 1 {
            cla[0] = curve_cla[0];
            cma[0] = curve_cma[0];
            if case.tail_slope == TailSlopeReading::Original {
                slope_per_rad = curve_cla[0].unwrap_or(analytic);
            }
        } else if let Some(first) = curve_cla[0].filter(|s| *s != 0.0) {
            if let Some(from) = (1..n).find(|&k| {
                cla[k].is_some_and(|s| (s / first - 1.0).abs() > TAIL_NOT_APPLICABLE_SLOPE_CHANGE)
            }) {
                for k in from..n {
                    cm[k] = None;
                    cma[k] = None;
                }
            }
        }
    }
    let xcp = (0..n)
        .map(|k| match (cm[k], surface.cn[k]) {
            (Some(m), Some(nf)) if nf != 0.0 => Some(m / nf).filter(|v| v.is_finite()),
            _ => None,
        })
        .collect();
    Ok(HorizontalTailAlone {
        surface,
        cm,
        xcp,
        cla_per_rad: cla,
        cma_per_rad: cma,
        slope_per_rad,
        low_aspect_ratio_straight,
    })
}

/// The wing at Mach 0 (β = 1) with the section's first lift-curve slope (CLAMO when any Mach
/// of the case lies between STMACH and TSMACH) and its low-speed maximum lift CLMAXL: its
/// zero-lift angle and angle of maximum lift, deg, which set the downwash's angle scale.
/// Original: CLMCH0.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct LowSpeedWing {
    pub zero_lift_alpha_deg: f64,
    pub max_lift_alpha_deg: f64,
    /// CLAMO was used (a transonic Mach number in the case).
    pub transonic_slope: bool,
}

/// See [`LowSpeedWing`] and [`mach_zero_wing`]. None when the wing has no maximum lift at low
/// speed (no CLMAXL and no computed section) or no angle of maximum lift.
pub fn low_speed_wing(
    case: &Case,
    condition_index: usize,
    alpha_deg: &[f64],
) -> Result<Option<LowSpeedWing>, TailError> {
    let low = mach_zero_wing(case, condition_index, alpha_deg).map_err(|e| match e {
        WingMethodError::NoCondition { index } => TailError::NoCondition { index },
        e => TailError::Wing(e),
    })?;
    let w = &low.wing;
    Ok(w.terms.max_lift.alpha_deg.map(|a| LowSpeedWing {
        zero_lift_alpha_deg: w.terms.zero_lift_angle.wing_deg,
        max_lift_alpha_deg: a,
        transonic_slope: low.transonic_slope,
    }))
}

/// Zero-lift drag of a vertical tail or ventral fin (one panel).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct FinZeroLiftDrag {
    pub surface: Surface,
    /// TYPE rounds to 1 (or is 5 or more): one straight-tapered panel. Otherwise (TYPE 2 to 4,
    /// and also TYPE 0 or absent, as the original reads the tail's TYPE) the inboard panel
    /// with the dashed curves of figure 4.1.5.1-28b plus the outboard panel.
    pub straight_tapered: bool,
    pub drag: WingZeroLiftDrag,
}

/// DATCOM 4.1.5.1, equation 4.1.5.1-a on the vertical tail (or ventral fin), a single panel:
/// CD0 = Cf (1 + L t/c + 100 (t/c)⁴) R_LS 2 S_exposed/S_ref with the skin friction of figure
/// 4.1.5.1-26 at the Reynolds number on the exposed MAC (at most the cut-off of figure
/// 4.1.5.1-27) and R_LS of figure 4.1.5.1-28b; reuses the wing's zero-lift drag. Section:
/// $VTSCHR (or $VFSCHR) TOVC, XOVC, else the computed section. Subsonic. Original: VTDRAG,
/// VFDRAG. Without a section thickness ratio (no section at all) the drag is the skin
/// friction's alone, t/c = 0, with a warning, as the original computes it then.
pub fn fin_zero_lift_drag(
    case: &Case,
    condition_index: usize,
    surface: Surface,
    warnings: &mut Vec<TailWarning>,
) -> Result<FinZeroLiftDrag, TailError> {
    let plan: &Planform = match surface {
        Surface::VerticalTail => case.vertical_tail.as_ref(),
        Surface::VentralFin => case.ventral_fin.as_ref(),
        _ => None,
    }
    .ok_or(TailError::NoVerticalTail)?;
    let condition = case
        .conditions
        .get(condition_index)
        .ok_or(TailError::NoCondition {
            index: condition_index,
        })?;
    let (Some(reference_area), _) = reference(case) else {
        return Err(TailError::NoReferenceArea);
    };
    let geometry = planform_geometry(plan, Span::Single).map_err(|e| TailError::Geometry {
        reason: format!("{}: {e}", surface.name()),
    })?;
    let user = case.sections.get(surface.name());
    let scalar = |n: &str| user.and_then(|u| u.scalars.get(n).copied());
    let computed = match surface_section(case, surface) {
        Some(Ok(s)) => section_characteristics(&s.shape, &s.conditions, &s.overrides).ok(),
        _ => None,
    };
    let thickness_ratio = match scalar("TOVC").or(computed
        .as_ref()
        .map(|c| c.thickness_ratio(case.section_maximum)))
    {
        Some(t) => t,
        None => {
            warnings.push(TailWarning::FinDragFrictionOnly {
                surface: surface.name(),
            });
            0.0
        }
    };
    let max_thickness_x = scalar("XOVC").or(computed.as_ref().map(|c| c.max_thickness_x));
    let outboard = outboard_defaults(
        case.outboard_section,
        case.section_maximum,
        computed.as_ref(),
        OutboardDefaults {
            thickness_ratio: Some(thickness_ratio),
            max_thickness_x,
            leading_edge_radius: Some(0.0),
            cm0: None,
        },
    );
    let outboard_max_thickness_x = scalar("XOVCO").or(outboard.max_thickness_x);
    let mut p = WingPlanform::new(
        &geometry,
        Chords {
            tip: plan.chrdtp.unwrap_or(0.0),
            at_break: plan.chrdbp.unwrap_or(0.0),
        },
        MaxThicknessStations {
            inboard: max_thickness_x,
            outboard: outboard_max_thickness_x,
        },
    );
    let type_word = plan.planform_type.unwrap_or(0.0);
    let straight_tapered = (type_word + 0.5).floor() == 1.0 || type_word >= 5.0;
    if !straight_tapered && p.outboard.is_none() {
        // No outboard panel (its area is nil), but the inboard panel read as a two-panel
        // surface's.
        p.outboard = Some(PanelTerms {
            area: 0.0,
            ..p.inboard
        });
    } else if straight_tapered {
        p.outboard = None;
    }
    let mach = condition.mach;
    let inputs = DragInputs {
        planform: &p,
        kind: if straight_tapered {
            WingType::Straight
        } else {
            WingType::Cranked
        },
        mach,
        beta: (1.0 - mach * mach).abs().sqrt(),
        reynolds_per_length: condition.reynolds_per_length,
        roughness: roughness_height(case),
        reference_area,
        thickness_ratio,
        max_thickness_x,
        outboard_thickness_ratio: scalar("TOVCO")
            .or(outboard.thickness_ratio)
            .unwrap_or(thickness_ratio),
        outboard_max_thickness_x,
        leading_edge_radius: 0.0,
        outboard_leading_edge_radius: 0.0,
        twist_deg: 0.0,
    };
    let mut wing_warnings = Vec::new();
    let drag = wing_zero_lift_drag(&inputs, &mut wing_warnings).map_err(TailError::Wing)?;
    warnings.extend(wing_warnings.into_iter().map(TailWarning::Wing));
    Ok(FinZeroLiftDrag {
        surface,
        straight_tapered,
        drag,
    })
}
