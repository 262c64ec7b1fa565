//! Section maximum lift coefficient, DATCOM 4.1.1.4 (the original's routine MAXCL).
//!
//! c_lmax = c_lmax,base + Δ₁c_lmax + Δ₂c_lmax + Δ₃c_lmax, each read from a chart of
//! `charts/section_max_lift/` against the leading-edge sharpness parameter Δy (percent chord):
//!
//! - c_lmax,base (`4.1.1.4-base`): uncambered section at a Reynolds number of 9·10⁶, against
//!   Δy and the position of the maximum thickness (0.30 to 0.45 chord);
//! - Δ₁ (`4.1.1.4-camber`): camber, against Δy, the maximum camber and its position; zero for
//!   a section without positive camber;
//! - Δ₂ (`4.1.1.4-thickness-position`): a cambered section whose maximum thickness is not at
//!   0.30 chord (the camber increment is for that position), against Δy and that position;
//! - Δ₃ (`4.1.1.4-reynolds`): Reynolds number on the chord, against Δy and the Reynolds
//!   number (3·10⁶ to 2.5·10⁷; zero at 9·10⁶).
//!
//! Validity: subsonic flow, conventional sections (Δy up to 5 % chord, camber up to 6 %,
//! maximum thickness between 0.30 and 0.45 chord); every chart holds its end values beyond the
//! data, as the original does, with a warning naming chart and value. The method has no Mach
//! term: the wing's maximum lift takes Mach number into account (DATCOM 4.1.3.4).
//!
//! Inputs are the section's computed geometry (Δy, maximum thickness and camber with their
//! positions), as the original's MAXCL reads them: the user's $WGSCHR DELTAY, XOVC or TOVC do
//! not enter. The user's CLMAX, where given, replaces the result (the wing's
//! `section_inputs`).

use serde::Serialize;

use crate::charts::{self, ChartWarning};

/// Chart of the basic maximum lift (Δy, position of maximum thickness).
pub const BASE_CHART: &str = "4.1.1.4-base";
/// Chart of the camber increment Δ₁ (Δy, maximum camber, its position).
pub const CAMBER_CHART: &str = "4.1.1.4-camber";
/// Chart of the increment Δ₂ of a cambered section for the maximum-thickness position.
pub const THICKNESS_POSITION_CHART: &str = "4.1.1.4-thickness-position";
/// Chart of the Reynolds-number increment Δ₃.
pub const REYNOLDS_CHART: &str = "4.1.1.4-reynolds";

/// Reynolds number of the basic chart (Δ₃ = 0 there); also used for a condition whose
/// Reynolds number is not known, as the original does for every condition without RNNUB.
pub const MAX_LIFT_REFERENCE_REYNOLDS_NUMBER: f64 = 9.0e6;

/// Position of the maximum thickness for which the camber increment is drawn: a cambered
/// section with its maximum thickness there takes no Δ₂.
const CAMBER_CHART_THICKNESS_POSITION: f64 = 0.30;
/// A maximum-thickness position this close to 0.30 is taken as 0.30 (the original's
/// tolerance; NACA stations are not exact in binary).
const THICKNESS_POSITION_TOLERANCE: f64 = 1e-5;

/// The section geometry the method reads, fractions of chord unless stated.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct MaxLiftGeometry {
    /// Leading-edge sharpness parameter Δy, percent chord.
    pub delta_y_percent: f64,
    /// Chordwise position of the maximum thickness.
    pub max_thickness_x: f64,
    /// Largest mean-line ordinate (0 when none is positive) and its position.
    pub max_camber: f64,
    pub max_camber_x: f64,
}

impl MaxLiftGeometry {
    /// The section has positive camber (the camber increments apply).
    pub fn cambered(&self) -> bool {
        self.max_camber > 0.0
    }
}

/// The maximum lift at one flight condition.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct ConditionMaxLift {
    /// Reynolds number on the chord read in the Reynolds chart: the condition's, or
    /// [`MAX_LIFT_REFERENCE_REYNOLDS_NUMBER`] when it has none.
    pub reynolds_number: f64,
    /// Δ₃c_lmax.
    pub reynolds_increment: f64,
    /// c_lmax = base + camber + thickness-position + Reynolds increments.
    pub max_cl: f64,
}

/// What the maximum-lift method could not do as asked.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
#[non_exhaustive]
pub enum MaxLiftWarning {
    /// A lookup left a chart's data (end value used).
    Chart(ChartWarning),
    /// Condition `condition` (index) has no Reynolds number: the reference 9·10⁶ was used.
    ReynoldsNumberMissing { condition: usize },
}

impl std::fmt::Display for MaxLiftWarning {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            MaxLiftWarning::Chart(w) => write!(f, "section maximum lift: {w}"),
            MaxLiftWarning::ReynoldsNumberMissing { condition } => write!(
                f,
                "section maximum lift: no Reynolds number for condition {}: computed at {MAX_LIFT_REFERENCE_REYNOLDS_NUMBER:.0e}",
                condition + 1
            ),
        }
    }
}

/// The section maximum lift: the terms common to all conditions, and one value per condition.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct SectionMaxLift {
    pub geometry: MaxLiftGeometry,
    /// c_lmax,base (uncambered, Re 9·10⁶).
    pub base: f64,
    /// Δ₁c_lmax for camber (0 without positive camber).
    pub camber_increment: f64,
    /// Δ₂c_lmax of a cambered section for its maximum-thickness position (0 at 0.30 chord or
    /// without camber).
    pub thickness_position_increment: f64,
    /// One per condition, in the order given.
    pub per_condition: Vec<ConditionMaxLift>,
    pub warnings: Vec<MaxLiftWarning>,
}

/// Why no maximum lift is computed.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum MaxLiftError {
    #[error("section maximum lift: {name} is {value}, not a number the method can read")]
    Input { name: &'static str, value: f64 },
    #[error("section maximum lift: chart {chart} is not embedded or gives no value")]
    Chart { chart: &'static str },
}

fn read(
    id: &'static str,
    args: &[f64],
    warnings: &mut Vec<MaxLiftWarning>,
) -> Result<f64, MaxLiftError> {
    let chart = charts::get(id).ok_or(MaxLiftError::Chart { chart: id })?;
    let value = chart.lookup_each(args, |w| warnings.push(MaxLiftWarning::Chart(w)));
    value.ok_or(MaxLiftError::Chart { chart: id })
}

/// The section maximum lift coefficient of `geometry` at each Reynolds number on the chord
/// (`None`: not known, [`MAX_LIFT_REFERENCE_REYNOLDS_NUMBER`] with a warning).
///
/// DATCOM 4.1.1.4: c_lmax = c_lmax,base(Δy, x_t) + Δ₁(Δy, y_c, x_c) + Δ₂(Δy, x_t) + Δ₃(Δy, Re),
/// with Δ₁ and Δ₂ only for a cambered section and Δ₂ only when x_t ≠ 0.30 (see the module
/// documentation for the charts).
pub fn section_max_lift(
    geometry: &MaxLiftGeometry,
    reynolds_numbers: &[Option<f64>],
) -> Result<SectionMaxLift, MaxLiftError> {
    for (name, value) in [
        (
            "the leading-edge sharpness parameter",
            geometry.delta_y_percent,
        ),
        (
            "the position of the maximum thickness",
            geometry.max_thickness_x,
        ),
        ("the maximum camber", geometry.max_camber),
        ("the position of the maximum camber", geometry.max_camber_x),
    ] {
        if !value.is_finite() {
            return Err(MaxLiftError::Input { name, value });
        }
    }
    let dy = geometry.delta_y_percent;
    let xt = if (geometry.max_thickness_x - CAMBER_CHART_THICKNESS_POSITION).abs()
        <= THICKNESS_POSITION_TOLERANCE
    {
        CAMBER_CHART_THICKNESS_POSITION
    } else {
        geometry.max_thickness_x
    };
    let mut warnings = Vec::new();
    let base = read(BASE_CHART, &[xt, dy], &mut warnings)?;
    let (camber_increment, thickness_position_increment) = if geometry.cambered() {
        let d1 = read(
            CAMBER_CHART,
            &[geometry.max_camber_x, geometry.max_camber, dy],
            &mut warnings,
        )?;
        let d2 = if xt == CAMBER_CHART_THICKNESS_POSITION {
            0.0
        } else {
            read(THICKNESS_POSITION_CHART, &[xt, dy], &mut warnings)?
        };
        (d1, d2)
    } else {
        (0.0, 0.0)
    };
    let per_condition = reynolds_numbers
        .iter()
        .enumerate()
        .map(|(i, re)| {
            let reynolds_number = match re.filter(|r| r.is_finite() && *r > 0.0) {
                Some(r) => r,
                None => {
                    warnings.push(MaxLiftWarning::ReynoldsNumberMissing { condition: i });
                    MAX_LIFT_REFERENCE_REYNOLDS_NUMBER
                }
            };
            let d3 = read(REYNOLDS_CHART, &[reynolds_number, dy], &mut warnings)?;
            Ok(ConditionMaxLift {
                reynolds_number,
                reynolds_increment: d3,
                max_cl: base + camber_increment + thickness_position_increment + d3,
            })
        })
        .collect::<Result<Vec<_>, MaxLiftError>>()?;
    let mut unique: Vec<MaxLiftWarning> = Vec::with_capacity(warnings.len());
    for w in warnings {
        if !unique.contains(&w) {
            unique.push(w);
        }
    }
    Ok(SectionMaxLift {
        geometry: *geometry,
        base,
        camber_increment,
        thickness_position_increment,
        per_condition,
        warnings: unique,
    })
}
