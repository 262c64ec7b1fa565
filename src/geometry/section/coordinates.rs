//! The coordinate table of a section: one row per chordwise station, as on the original's
//! SECTION DEFINITION pages.

use serde::Serialize;

/// One station of the coordinate table; every value is a fraction of chord, x from the leading
/// edge, y up.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct CoordinateRow {
    pub upper_x: f64,
    pub upper_y: f64,
    pub lower_x: f64,
    pub lower_y: f64,
    /// Station on the chord.
    pub x: f64,
    /// Mean-line ordinate at the station.
    pub mean: f64,
    /// Thickness (twice the half thickness) at the station.
    pub thickness: f64,
}

impl CoordinateRow {
    /// The surfaces at station `x` from the mean line `mean` of slope `slope` and the half
    /// thickness `half`, laid off perpendicular to the mean line: x_u = x - y_t sin(theta),
    /// y_u = y_c + y_t cos(theta), x_l = x + y_t sin(theta), y_l = y_c - y_t cos(theta),
    /// theta = atan(dy_c/dx) (Abbott & von Doenhoff, Theory of Wing Sections, chapter 6;
    /// routines COORD1-COORD6 and XYCORD).
    pub fn perpendicular(x: f64, mean: f64, slope: f64, half: f64) -> Self {
        let (sin, cos) = slope.atan().sin_cos();
        CoordinateRow {
            upper_x: x - half * sin,
            upper_y: mean + half * cos,
            lower_x: x + half * sin,
            lower_y: mean - half * cos,
            x,
            mean,
            thickness: 2.0 * half,
        }
    }

    /// The row's numbers in the order the original prints them: upper x, upper y, lower x,
    /// lower y, station, mean line, thickness.
    pub fn values(&self) -> [f64; 7] {
        [
            self.upper_x,
            self.upper_y,
            self.lower_x,
            self.lower_y,
            self.x,
            self.mean,
            self.thickness,
        ]
    }

    /// The leading-edge point: both surfaces at the origin, at station `x`.
    pub fn leading_edge(x: f64) -> Self {
        Self::edge(0.0, x)
    }

    /// The trailing-edge point: both surfaces at (1, 0), at station `x`.
    pub fn trailing_edge(x: f64) -> Self {
        Self::edge(1.0, x)
    }

    fn edge(surface_x: f64, x: f64) -> Self {
        CoordinateRow {
            upper_x: surface_x,
            upper_y: 0.0,
            lower_x: surface_x,
            lower_y: 0.0,
            x,
            mean: 0.0,
            thickness: 0.0,
        }
    }
}

/// A section's coordinate table and the quantities later methods take from it.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct SectionCoordinates {
    /// The designation line the original prints above the table, e.g. `NACA 0012`,
    /// `NACA 64,3-618`; `USER DEFINED` for xxSCHR coordinates.
    pub title: String,
    /// A second designation line, e.g. `A=0.8` for a 6-series mean line of load extent 0.8.
    pub subtitle: Option<String>,
    /// The table, from the leading edge (first row) to the trailing edge (last row).
    pub rows: Vec<CoordinateRow>,
    /// Maximum thickness, fraction of chord: the designation's for a NACA section, the
    /// greatest tabulated thickness for a user-defined one.
    pub max_thickness: f64,
    /// Where the maximum thickness is, fraction of chord.
    pub max_thickness_x: f64,
    /// Leading-edge radius, fraction of chord: from the designation's equations for a NACA
    /// section (0 for the sharp supersonic sections); LERI, or the circle through the leading
    /// edge and the first point behind it, for a user-defined one.
    pub leading_edge_radius: f64,
    /// What was read differently from the definition of the section, and why.
    pub warnings: Vec<String>,
}
