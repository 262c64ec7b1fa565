//! Jorgensen's method for the normal force and pitching moment of a body at angles of attack
//! up to 180° (L. H. Jorgensen, NASA TR R-474, 1977), circular or elliptic cross-sections: the
//! original's METHOD=2 (routine BODYJM, lines 2248-2324), run after the axisymmetric method,
//! whose slopes, η and cdc it uses.

use std::f64::consts::PI;

use serde::Serialize;

use super::axisymmetric::Axisymmetric;
use super::shape::BodyShape;
use super::tables::trapezoid;
use super::BodyReference;

/// Jorgensen's coefficients of one body.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Jorgensen {
    /// Cross-section height over width (ELLIP; 1 for a circular body).
    pub ellipticity: f64,
    /// Volume (frustums on the equivalent radii), m³.
    pub volume: f64,
    /// Planform area 2∫r_eq dx on the stations, m².
    pub planform_area: f64,
    /// Planform centroid, m from the nose.
    pub planform_centroid: f64,
    /// Coefficient of the potential moment, sin 2α cos(α/2) term.
    pub a1: f64,
    /// Coefficient of the viscous moment.
    pub a2: f64,
    /// Area of the potential normal force, m².
    pub a3: f64,
    /// Potential normal force of the elliptic section over that of the circular one.
    pub potential_ratio: f64,
    /// Viscous normal force of the elliptic section over that of the circular one.
    pub viscous_ratio: f64,
    pub angles: Vec<JorgensenAngle>,
}

/// The terms at one angle of attack.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct JorgensenAngle {
    pub alpha_deg: f64,
    /// Potential normal force A3 sin 2α cos(α/2) (CN ratio)/S.
    pub cn_potential: f64,
    /// Viscous normal force Sp η cdc sin α |sin α| (CN ratio)/S.
    pub cn_viscous: f64,
    pub cm_potential: f64,
    pub cm_viscous: f64,
    /// Axial force CD0 cos²α.
    pub ca: f64,
}

/// Normal force of an elliptic cross-section over that of a circle of the same area: the
/// potential ratio (1/(a/b) for a section higher than wide, a/b for one wider than high) and
/// the viscous crossflow ratio (Jorgensen's closed forms in a/b ≥ 1). Circular: both 1.
fn elliptic_section_ratios(ellipticity: f64) -> (f64, f64) {
    if ellipticity == 1.0 {
        return (1.0, 1.0);
    }
    if ellipticity < 1.0 {
        let aob = 1.0 / ellipticity;
        let q = 1.0 - 1.0 / (aob * aob);
        let viscous = 1.5
            * aob.sqrt()
            * (-1.0 / (aob * aob) / q.powf(1.5) * (aob * (1.0 + q.sqrt())).ln() + 1.0 / q);
        (aob, viscous)
    } else {
        let aob = ellipticity;
        let q = aob * aob - 1.0;
        let viscous =
            1.5 * (1.0 / aob).sqrt() * (aob * aob / q.powf(1.5) * q.sqrt().atan() - 1.0 / q);
        (1.0 / aob, viscous)
    }
}

/// Normal force, axial force and pitching moment by Jorgensen's method:
/// CN = [A3 sin 2α cos(α/2) (CN ratio) + Sp η cdc sin α |sin α| (CN ratio)]/S,
/// CM = A1 sin 2α cos(α/2) (ratio) + A2 η cdc sin α |sin α| (ratio), CA = CD0 cos²α, with
/// A1 = (V − S_b (l − xcg))/(S c̄), A2 = Sp (xcg − x_c)/(S c̄), A3 = S_b; for a circular body
/// A1 and A3 come from the slender-body slopes (A1 = Cmα/2, A3 = CLα S/2, per radian). η and
/// cdc are those of the axisymmetric method. Subsonic here (the original runs it only then).
pub fn jorgensen_body(
    shape: &BodyShape,
    ellipticity: f64,
    slender: &Axisymmetric,
    cd0: f64,
    reference: &BodyReference,
) -> Jorgensen {
    let r_eq: Vec<f64> = shape.s.iter().map(|s| (s / PI).sqrt()).collect();
    let volume: f64 = shape
        .x
        .windows(2)
        .zip(r_eq.windows(2))
        .map(|(x, r)| PI / 3.0 * (x[1] - x[0]) * (r[0] * r[0] + r[1] * r[1] + r[0] * r[1]))
        .sum();
    let planform_area = 2.0 * trapezoid(&shape.x, &r_eq);
    let rx: Vec<f64> = r_eq.iter().zip(&shape.x).map(|(r, x)| r * x).collect();
    let planform_centroid = 2.0 * trapezoid(&shape.x, &rx) / planform_area;
    let moment_area = reference.area * reference.length;
    let (mut a1, a2, mut a3) = (
        (volume - shape.base_area * (shape.length - shape.xcg)) / moment_area,
        planform_area * (shape.xcg - planform_centroid) / moment_area,
        shape.base_area,
    );
    if ellipticity == 1.0 {
        a1 = slender.cma_per_rad / 2.0;
        a3 = slender.cla_per_rad * reference.area / 2.0;
    }
    let (potential_ratio, viscous_ratio) = elliptic_section_ratios(ellipticity);
    let angles = slender
        .angles
        .iter()
        .map(|t| {
            let a = t.alpha_deg.to_radians();
            let (sin, cos) = a.sin_cos();
            let potential = (2.0 * a).sin() * (a / 2.0).cos() * potential_ratio;
            let viscous =
                slender.eta * t.crossflow_drag_coefficient * sin * sin.abs() * viscous_ratio;
            JorgensenAngle {
                alpha_deg: t.alpha_deg,
                cn_potential: a3 * potential / reference.area,
                cn_viscous: planform_area * viscous / reference.area,
                cm_potential: a1 * potential,
                cm_viscous: a2 * viscous,
                ca: cd0 * cos * cos,
            }
        })
        .collect();
    Jorgensen {
        ellipticity,
        volume,
        planform_area,
        planform_centroid,
        a1,
        a2,
        a3,
        potential_ratio,
        viscous_ratio,
        angles,
    }
}
