//! The section values the wing methods take: the user's xxSCHR values where given, else the
//! values the section method computes (DATCOM 4.1.1; `methods::section`), as the original's
//! SECO fills the words the user leaves unset.

use super::zero_lift_angle::ZeroLiftReading;
use serde::Serialize;

use super::{WingMethodError, WingType, WingWarning};
use crate::case::{Case, SectionInput};
use crate::methods::section::{MachCharacteristics, MaximumReading, SectionCharacteristics};

/// The outboard panel's section values (TOVCO, XOVCO, LERO, CMOT) of a surface that is not
/// straight tapered, where the deck leaves them unset.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum OutboardSectionReading {
    /// A uniform section: the inboard panel's values (the user's TOVC, XOVC, LERI, else the
    /// section method's), and CMO alone for the zero-lift moment.
    #[default]
    Uniform,
    /// As the original program (SECO): the section method's thickness (as the methods take it,
    /// [`SectionCharacteristics::thickness_ratio`]), its position and zero-lift moment
    /// (averaged with a given CMO), and LERI (given or computed), when a section is computed
    /// (NACA card or coordinates); otherwise its unset value, about 0, for TOVCO, XOVCO and
    /// LERO. For reproducing old listings (docs/differences.md).
    Original,
}

/// The outboard defaults of a surface that is not straight tapered: thickness ratio, its
/// chord position, leading-edge radius and zero-lift moment (None: not averaged with CMO).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct OutboardDefaults {
    pub thickness_ratio: Option<f64>,
    pub max_thickness_x: Option<f64>,
    pub leading_edge_radius: Option<f64>,
    pub cm0: Option<f64>,
}

/// The outboard panel's values where the deck leaves them unset (see
/// [`OutboardSectionReading`]), from the inboard panel's and the section method's.
pub fn outboard_defaults(
    reading: OutboardSectionReading,
    maximum: MaximumReading,
    computed: Option<&SectionCharacteristics>,
    inboard: OutboardDefaults,
) -> OutboardDefaults {
    match (reading, computed) {
        (OutboardSectionReading::Uniform, _) => OutboardDefaults {
            cm0: None,
            ..inboard
        },
        (OutboardSectionReading::Original, Some(c)) => OutboardDefaults {
            thickness_ratio: Some(c.thickness_ratio(maximum)),
            max_thickness_x: Some(c.max_thickness_x),
            leading_edge_radius: inboard.leading_edge_radius,
            cm0: Some(c.cm0),
        },
        (OutboardSectionReading::Original, None) => OutboardDefaults {
            thickness_ratio: Some(0.0),
            max_thickness_x: Some(0.0),
            leading_edge_radius: Some(0.0),
            cm0: None,
        },
    }
}

/// Section characteristics of the wing at one flight condition.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct WingSection {
    /// Section lift-curve slope at the condition's Mach number (CLALPA), per radian.
    pub lift_curve_slope_per_rad: f64,
    /// Section maximum lift coefficient at the condition's Mach number (CLMAX; else the
    /// section method's, DATCOM 4.1.1.4, at the condition's Reynolds number).
    pub max_lift: Option<f64>,
    /// Section zero-lift angle (ALPHAO; else the computed one; else ALPHAI − CLI/c_lα), deg.
    pub zero_lift_alpha_deg: f64,
    /// The zero-lift angle takes the Mach correction of figure 4.1.3.1-5 (CAMBER, or a
    /// computed section).
    pub cambered: bool,
    /// Zero-lift pitching moment about the quarter chord (CMO, averaged with CMOT when both
    /// are given).
    pub cm0: f64,
    /// Thickness ratio and chord fraction of maximum thickness (TOVC, XOVC), inboard and
    /// outboard (TOVCO, XOVCO; the inboard values when not given).
    pub thickness_ratio: Option<f64>,
    pub max_thickness_x: Option<f64>,
    pub outboard_thickness_ratio: Option<f64>,
    pub outboard_max_thickness_x: Option<f64>,
    /// Leading-edge sharpness parameter Δy, percent chord (DELTAY).
    pub delta_y_percent: Option<f64>,
    /// Leading-edge radius over chord, inboard and outboard (LERI, LERO; LERI when LERO is
    /// not given).
    pub leading_edge_radius: Option<f64>,
    pub outboard_leading_edge_radius: Option<f64>,
    /// Section aerodynamic centre, fraction of chord (XAC).
    pub aerodynamic_centre: Option<f64>,
    /// ARCL of the low-aspect-ratio criterion (3.5 unless given; held in [3, 4]).
    pub arcl: f64,
}

/// ARCL when not given, and its limits (as the original's CHECK holds it).
const DEFAULT_ARCL: f64 = 3.5;
const ARCL_RANGE: (f64, f64) = (3.0, 4.0);
/// CMO and CMOT are averaged only when both exceed this in magnitude (as the original).
const CM0_GIVEN_ABOVE: f64 = 1e-10;

fn scalar(input: Option<&SectionInput>, names: &[&str]) -> Option<f64> {
    let i = input?;
    names
        .iter()
        .find_map(|n| i.scalars.get(*n).copied())
        .filter(|v| v.is_finite())
}

fn per_mach(input: Option<&SectionInput>, name: &str, mach_index: usize) -> Option<f64> {
    input?
        .per_mach
        .get(name)?
        .get(mach_index)
        .copied()
        .filter(|v| v.is_finite())
}

/// A section value as the original's section method leaves it after the last Mach number it
/// computed (SECO stores it once, after the Mach loop): the last Mach number's among the
/// conditions whose characteristics give one.
pub(super) fn at_last_mach(
    case: &Case,
    computed: &SectionCharacteristics,
    value: fn(&MachCharacteristics) -> Option<f64>,
) -> Option<f64> {
    case.conditions
        .iter()
        .zip(&computed.per_mach)
        .filter_map(|(k, m)| value(m).map(|v| (k.mach_index, v)))
        .max_by_key(|(i, _)| *i)
        .map(|(_, v)| v)
}

/// The wing section at flight condition `condition_index` of `case`: the user's $WGSCHR
/// values, else those of `computed` (the section method's characteristics of the case's
/// wing section, one `per_mach` entry per condition).
pub fn wing_section(
    case: &Case,
    condition_index: usize,
    computed: Option<&SectionCharacteristics>,
    warnings: &mut Vec<WingWarning>,
) -> Result<WingSection, WingMethodError> {
    let condition = case
        .conditions
        .get(condition_index)
        .ok_or(WingMethodError::NoCondition {
            index: condition_index,
        })?;
    let m = condition.mach_index;
    let user = case.sections.get("WING");
    let at_condition = computed.and_then(|c| c.per_mach.get(condition_index));
    let lift_curve_slope_per_rad = per_mach(user, "CLALPA", m)
        .map(f64::to_degrees)
        .or(at_condition.and_then(|c| c.cla_per_rad))
        .filter(|s| *s > 0.0)
        .ok_or(WingMethodError::NoSectionLiftCurveSlope {
            mach: condition.mach,
        })?;
    // The original's rule: the zero-lift angle its section method left after the last Mach
    // number, for every condition.
    let section_zero_lift = match case.zero_lift {
        ZeroLiftReading::Handbook => computed.map(|c| c.zero_lift_alpha_deg),
        ZeroLiftReading::Original => computed
            .and_then(|c| at_last_mach(case, c, |m| m.zero_lift_alpha_deg))
            .or(computed.map(|c| c.zero_lift_alpha_deg)),
    };
    let zero_lift_alpha_deg = scalar(user, &["ALPHAO", "ALPHA0"])
        .or(section_zero_lift)
        .unwrap_or_else(|| {
            let cli = scalar(user, &["CLI"]).unwrap_or(0.0);
            let ai = scalar(user, &["ALPHAI"]).unwrap_or(0.0);
            ai - cli / lift_curve_slope_per_rad.to_radians()
        });
    let cambered = user.and_then(|u| u.camber).unwrap_or(false) || computed.is_some();
    let thickness_ratio =
        scalar(user, &["TOVC"]).or(computed.map(|c| c.thickness_ratio(case.section_maximum)));
    let max_thickness_x = scalar(user, &["XOVC"]).or(computed.map(|c| c.max_thickness_x));
    let delta_y_percent = scalar(user, &["DELTAY"]).or(computed.map(|c| c.delta_y_percent));
    let leading_edge_radius = scalar(user, &["LERI"]).or(computed.map(|c| c.leading_edge_radius));
    let straight = case
        .wing
        .as_ref()
        .and_then(|w| WingType::from_input(w.planform_type))
        .is_none_or(|t| t == WingType::Straight);
    let outboard = (!straight).then(|| {
        outboard_defaults(
            case.outboard_section,
            case.section_maximum,
            computed,
            OutboardDefaults {
                thickness_ratio,
                max_thickness_x,
                leading_edge_radius,
                cm0: None,
            },
        )
    });
    let cmo = scalar(user, &["CMO", "CM0"]).or(computed.map(|c| c.cm0));
    let cmot = scalar(user, &["CMOT", "CM0T"]).or(outboard.and_then(|o| o.cm0));
    let cm0 = match (cmo, cmot) {
        (Some(a), Some(b)) if a.abs() >= CM0_GIVEN_ABOVE && b.abs() >= CM0_GIVEN_ABOVE => {
            0.5 * (a + b)
        }
        (Some(a), _) => a,
        (None, _) => 0.0,
    };
    for (name, v) in [
        ("TOVC", thickness_ratio),
        ("DELTAY", delta_y_percent),
        ("LERI", leading_edge_radius),
    ] {
        if v.is_none() {
            warnings.push(WingWarning::SectionValueMissing { name });
        }
    }
    let arcl = scalar(user, &["ARCL"])
        .unwrap_or(DEFAULT_ARCL)
        .clamp(ARCL_RANGE.0, ARCL_RANGE.1);
    Ok(WingSection {
        lift_curve_slope_per_rad,
        max_lift: per_mach(user, "CLMAX", m).or(at_condition.and_then(|c| c.max_cl)),
        zero_lift_alpha_deg,
        cambered,
        cm0,
        thickness_ratio,
        max_thickness_x,
        outboard_thickness_ratio: scalar(user, &["TOVCO"])
            .or(outboard.map_or(thickness_ratio, |o| o.thickness_ratio)),
        outboard_max_thickness_x: scalar(user, &["XOVCO"])
            .or(outboard.map_or(max_thickness_x, |o| o.max_thickness_x)),
        delta_y_percent,
        leading_edge_radius,
        outboard_leading_edge_radius: scalar(user, &["LERO"])
            .or(outboard.map_or(leading_edge_radius, |o| o.leading_edge_radius)),
        aerodynamic_centre: per_mach(user, "XAC", m).or(at_condition.and_then(|c| c.xac)),
        arcl,
    })
}
