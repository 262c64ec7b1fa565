//! Body alone: CLq, Cmq, CLα̇, Cmα̇, DATCOM 7.2.1.1, 7.2.1.2, 7.2.2.1, 7.2.2.2 (the original's
//! DYNBOD).

use super::{finite, Column, Dynamic, DynamicError, DynamicWarning};
use crate::case::Case;
use crate::geometry::body as body_geometry;
use crate::methods::body::BodyAlone;
use crate::numeric::trapezoid;

/// The body alone's dynamic derivatives, per radian, from the body-alone results `body` (its
/// lift and moment slopes at the first angle, CLα_B and Cmα_B, on the reference area and
/// length):
///
/// with l the body length (BLN + BLA when given), x_m = XCG from the nose, V the volume
/// ∫S dx over the body stations, x_c its centroid, S_b the largest cross-section and
/// ξ = x_m/l, τ = V/(S_b l):
/// - CLq = 2 CLα_B (1 − ξ),  Cmq = 2 Cmα_B [(1 − ξ)² − τ (x_c/l − ξ)]/(1 − ξ − τ),
/// - CLα̇ = 2 CLα_B τ,  Cmα̇ = 2 Cmα_B τ (x_c/l − ξ)/(1 − ξ − τ),
///
/// each then multiplied by S_base/S (l/c̄)² (CLα̇: S_base/S · l/c̄), S_base the base area of the
/// subsonic methods. The slopes are already on S and c̄, so this second referencing scales the
/// body derivatives once more, as the original does (docs/dynamic.md). On the first row only;
/// Clp, CYp, Cnp, Cnr have no body method; Clr is 0 at every angle (as the original).
pub fn body_dynamic(
    case: &Case,
    body: &BodyAlone,
    alpha_deg: &[f64],
) -> Result<Dynamic, DynamicError> {
    let n = alpha_deg.len();
    let input = case.body.as_ref().ok_or_else(|| DynamicError::Geometry {
        reason: "the case has no body ($BODY)".into(),
    })?;
    let g = body_geometry(input).map_err(|e| DynamicError::Geometry {
        reason: format!("body geometry: {e}"),
    })?;
    let mut out = Dynamic::no_method(alpha_deg);
    if input.btail.is_some() {
        out.warnings.push(DynamicWarning::BodyShape);
    }
    let length = match (input.bln, input.bla) {
        (None, None) => g.length,
        (a, b) => a.unwrap_or(0.0) + b.unwrap_or(0.0),
    };
    let x0 = g.x.first().copied().unwrap_or(0.0);
    let x: Vec<f64> = g.x.iter().map(|v| v - x0).collect();
    let volume = trapezoid(&x, &g.s);
    let moment: Vec<f64> = g.s.iter().zip(&x).map(|(s, x)| s * x).collect();
    let centroid = trapezoid(&x, &moment) / volume;
    let xi = body.xcg_from_nose / length;
    let tau = volume / (g.max_area * length);
    let cla = body.cla_per_rad.first().copied().flatten();
    let cma = body.cma_per_rad.first().copied().flatten();
    let area_ratio = g.base_area / body.reference.area;
    let length_ratio = length / body.reference.length;
    let scale2 = area_ratio * length_ratio * length_ratio;
    let lever = centroid / length - xi;
    let denominator = 1.0 - xi - tau;
    // The original works per degree; the slopes here are per radian and so are the results.
    let clq = cla.and_then(|a| finite(2.0 * a * (1.0 - xi) * scale2));
    let cmq = cma
        .and_then(|m| finite(2.0 * m * ((1.0 - xi).powi(2) - tau * lever) / denominator * scale2));
    let clad = cla.and_then(|a| finite(2.0 * a * tau * area_ratio * length_ratio));
    let cmad = cma.and_then(|m| finite(2.0 * m * tau * lever / denominator * scale2));
    out.clq = Column::first(n, clq);
    out.cmq = Column::first(n, cmq);
    out.clad = Column::first(n, clad);
    out.cmad = Column::first(n, cmad);
    out.clr = Column::rows(vec![Some(0.0); n]);
    Ok(out)
}
