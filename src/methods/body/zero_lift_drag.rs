//! DATCOM 4.2.3.1, subsonic zero-lift drag of a body: skin friction with the fineness-ratio
//! form factor, and base drag (the original's routines BODYRT and BODOPT, lines 1892-1928 and
//! 2395-2521, with FIG26 for the skin-friction coefficient).

use serde::Serialize;

use super::figures;
use super::shape::BodyShape;
use super::{BodyMethodError, BodyWarning};

/// Form factor of the skin friction (DATCOM 4.2.3.1): 1 + 60/(l/d)³ + 0.0025 (l/d).
const FORM_FACTOR_CUBIC: f64 = 60.0;
const FORM_FACTOR_LINEAR: f64 = 0.0025;
/// Base drag (DATCOM 4.2.3.1): C_Db = 0.029 (d_b/d)³ / √C_Df, both on the largest area.
const BASE_DRAG_CONSTANT: f64 = 0.029;
/// FIG26 reads the tabulated Mach row itself, without interpolation, when the Mach number is
/// within this much above it.
const MACH_ROW_SNAP: f64 = 0.02;

/// Zero-lift drag of the body and its parts; coefficients on the reference area.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ZeroLiftDrag {
    /// Reynolds number on the body length.
    pub reynolds_number: f64,
    /// Cut-off Reynolds number of the surface roughness (Fig. 4.1.5.1-27).
    pub cutoff_reynolds_number: f64,
    /// The smaller of the two: the Reynolds number the skin friction is read at.
    pub reynolds_number_used: f64,
    /// Turbulent flat-plate skin-friction coefficient (Fig. 4.1.5.1-26).
    pub skin_friction_coefficient: f64,
    /// 1 + 60/(l/d)³ + 0.0025 (l/d).
    pub form_factor: f64,
    /// Wetted area, m².
    pub wetted_area: f64,
    /// Skin friction with the form factor (friction and pressure drag of the forebody).
    pub friction: f64,
    /// Base drag.
    pub base: f64,
    /// Pressure drag: none apart at subsonic speeds (the form factor carries it).
    pub pressure: Option<f64>,
    /// Friction plus base.
    pub total: f64,
}

/// Turbulent flat-plate skin-friction coefficient at Reynolds number `reynolds` and Mach
/// number `mach` (DATCOM figure 4.1.5.1-26; routine FIG26).
///
/// The figure is held as fifth-degree polynomials in log10 R, one per tabulated Mach number;
/// between tabulated Mach numbers the coefficient is interpolated linearly, except within 0.02
/// above a tabulated Mach number, where that row is read as it is (as FIG26 does).
pub fn skin_friction_coefficient(
    reynolds: f64,
    mach: f64,
    warnings: &mut Vec<BodyWarning>,
) -> Result<f64, BodyMethodError> {
    if reynolds <= 0.0 || !reynolds.is_finite() {
        return Err(BodyMethodError::Reynolds { reynolds });
    }
    let machs = figures::outer_nodes(figures::SKIN_FRICTION)?;
    let row_mach = machs
        .iter()
        .copied()
        .filter(|m| *m <= mach)
        .fold(None, |best: Option<f64>, m| {
            Some(best.map_or(m, |b| b.max(m)))
        });
    let mach_read = match row_mach {
        Some(m) if mach - m <= MACH_ROW_SNAP => m,
        _ => mach,
    };
    let log_r = reynolds.log10();
    let mut cf = 0.0;
    let mut power_of_log = 1.0;
    for n in 1..=5 {
        power_of_log *= log_r;
        let c = figures::read(figures::SKIN_FRICTION, &[mach_read, n as f64], warnings)?;
        cf += c * power_of_log;
    }
    Ok(cf)
}

/// Zero-lift drag of the body (DATCOM 4.2.3.1; original routines BODYRT and BODOPT).
///
/// On the largest cross-section Smax,
/// C_Df = C_f (1 + 60/(l/d)³ + 0.0025 l/d) S_wet/Smax, with C_f of figure 4.1.5.1-26 at the
/// smaller of the length Reynolds number and the cut-off Reynolds number of the roughness
/// (figure 4.1.5.1-27); base drag C_Db = 0.029 (d_b/d)³/√C_Df on Smax,
/// with the base area at least 0.3 Smax (the original's boat-tail rule); both then referred to
/// the reference area. Valid for subsonic flow with a turbulent boundary layer.
pub fn zero_lift_drag(
    shape: &BodyShape,
    mach: f64,
    reynolds_per_length: f64,
    roughness: f64,
    reference_area: f64,
    warnings: &mut Vec<BodyWarning>,
) -> Result<ZeroLiftDrag, BodyMethodError> {
    let length = shape.length;
    let reynolds_number = reynolds_per_length * length;
    let length_over_roughness = length / roughness;
    let log_cutoff = figures::read(
        figures::CUTOFF_REYNOLDS,
        &[mach, length_over_roughness.log10()],
        warnings,
    )?;
    let cutoff_reynolds_number = 10f64.powf(log_cutoff);
    let reynolds_number_used = reynolds_number.min(cutoff_reynolds_number);
    let cf = skin_friction_coefficient(reynolds_number_used, mach, warnings)?;
    let fineness = shape.fineness;
    let form_factor =
        1.0 + FORM_FACTOR_CUBIC / (fineness * fineness * fineness) + FORM_FACTOR_LINEAR * fineness;
    let friction_on_max_area = cf * form_factor * shape.wetted_area / shape.max_area;
    if friction_on_max_area <= 0.0 || !friction_on_max_area.is_finite() {
        return Err(BodyMethodError::Degenerate {
            reason: format!(
                "the skin-friction drag is not positive (C_f = {cf}, wetted area {} m²)",
                shape.wetted_area
            ),
        });
    }
    let base_over_max_diameter_cubed = (shape.base_area / shape.max_area).powf(1.5);
    let area_ratio = shape.max_area / reference_area;
    let base = BASE_DRAG_CONSTANT * base_over_max_diameter_cubed / friction_on_max_area.sqrt()
        * area_ratio;
    let friction = friction_on_max_area * area_ratio;
    Ok(ZeroLiftDrag {
        reynolds_number,
        cutoff_reynolds_number,
        reynolds_number_used,
        skin_friction_coefficient: cf,
        form_factor,
        wetted_area: shape.wetted_area,
        friction,
        base,
        pressure: None,
        total: friction + base,
    })
}
