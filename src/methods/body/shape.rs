//! The body as the body-alone methods see it: stations measured from the nose, the moment
//! reference centre on the same axis, and the quantities of [`BodyGeometry`] checked for use.

use crate::geometry::BodyGeometry;

use super::BodyMethodError;

/// Body stations from the nose and the quantities the methods read, SI.
#[derive(Debug, Clone, PartialEq)]
pub struct BodyShape {
    /// Stations from the first one (the nose), m.
    pub x: Vec<f64>,
    /// Cross-section areas, m².
    pub s: Vec<f64>,
    /// Equivalent radii, m.
    pub r: Vec<f64>,
    /// Body length, m.
    pub length: f64,
    /// Largest cross-section area, m².
    pub max_area: f64,
    /// Base area, at least 0.3 of the largest area, m².
    pub base_area: f64,
    /// Length over the diameter of the circle of the largest area.
    pub fineness: f64,
    /// Wetted area, m².
    pub wetted_area: f64,
    /// Moment reference centre from the nose, m.
    pub xcg: f64,
}

impl BodyShape {
    /// The body of `geometry` with its stations and the moment reference centre `xcg` (on the
    /// deck's axis) measured from the first station, as the original shifts them.
    pub fn new(geometry: &BodyGeometry, xcg: f64) -> Result<BodyShape, BodyMethodError> {
        let degenerate = |reason: &str| {
            Err(BodyMethodError::Degenerate {
                reason: reason.to_string(),
            })
        };
        let n = geometry.x.len();
        if n < 2 || geometry.s.len() < n || geometry.r.len() < n {
            return degenerate("the body needs at least 2 stations with areas and radii");
        }
        let all_finite = geometry.x[..n]
            .iter()
            .chain(&geometry.s[..n])
            .chain(&geometry.r[..n])
            .all(|v| v.is_finite());
        if !all_finite || !xcg.is_finite() {
            return degenerate("a body station, area, radius or XCG is not a finite number");
        }
        if geometry.x.windows(2).any(|w| w[1] < w[0]) {
            return degenerate("body stations X decrease");
        }
        let x0 = geometry.x[0];
        let x: Vec<f64> = geometry.x.iter().map(|x| x - x0).collect();
        let length = x[n - 1];
        if length <= 0.0 {
            return degenerate("the body length (last station minus first) is not positive");
        }
        if geometry.max_area <= 0.0 || !geometry.max_area.is_finite() {
            return degenerate("the body has no cross-section area");
        }
        if geometry.wetted_area <= 0.0 || !geometry.wetted_area.is_finite() {
            return degenerate("the body has no wetted area (perimeters are zero)");
        }
        Ok(BodyShape {
            x,
            s: geometry.s[..n].to_vec(),
            r: geometry.r[..n].to_vec(),
            length,
            max_area: geometry.max_area,
            base_area: geometry.base_area,
            fineness: geometry.fineness,
            wetted_area: geometry.wetted_area,
            xcg: xcg - x0,
        })
    }
}
