//! Geometric section parameters (DATCOM 2.2.1): leading-edge radius, maximum thickness and
//! camber with their positions, and the leading-edge sharpness parameter Δy (the original's
//! M50O62 and routine DELY).

use super::interpolation::Ordinates;
use super::{MaximumReading, SectionShape};

/// Chordwise stations of the sharpness parameter Δy: 0.15 % and 6 % of the chord.
const DELTA_Y_FORE: f64 = 0.0015;
const DELTA_Y_AFT: f64 = 0.06;

/// The largest ordinate and its station (the first of equal ones); `(0, 0)` when none is
/// positive.
fn maximum(x: &[f64], y: &[f64]) -> (f64, f64) {
    x.iter().zip(y).fold(
        (0.0, 0.0),
        |(best, at), (&x, &y)| {
            if y > best {
                (y, x)
            } else {
                (best, at)
            }
        },
    )
}

/// The ordinate at the last station where it rose above the one before, and that station;
/// `(0, 0)` when it never rises.
fn last_rise(x: &[f64], y: &[f64]) -> (f64, f64) {
    y.windows(2)
        .zip(x.iter().skip(1))
        .rev()
        .find(|(pair, _)| pair[1] > pair[0])
        .map_or((0.0, 0.0), |(pair, &at)| (pair[1], at))
}

/// The section's maximum of `y` by its reading rule.
fn maximum_by(shape: &SectionShape, y: &[f64]) -> (f64, f64) {
    match shape.maximum_reading {
        MaximumReading::Greatest => maximum(&shape.x, y),
        MaximumReading::LastRise => last_rise(&shape.x, y),
    }
}

/// Maximum thickness (both sides) and its station.
pub(crate) fn max_thickness(shape: &SectionShape) -> (f64, f64) {
    let (t, x) = maximum_by(shape, &shape.half_thickness);
    (2.0 * t, x)
}

/// Maximum mean-line ordinate and its station.
pub(crate) fn max_camber(shape: &SectionShape) -> (f64, f64) {
    maximum_by(shape, &shape.camber)
}

/// Leading-edge radius when the designation does not fix it: the circle through the nose and
/// the first station behind it, centred on the chord, r = (x² + z_t²)/(2x).
pub(crate) fn nose_circle_radius(shape: &SectionShape) -> f64 {
    let (x, t) = (shape.x[1], shape.half_thickness[1]);
    (x * x + t * t) / (2.0 * x)
}

/// Δy, percent of chord: the half thickness at 6 % of the chord less that at 0.15 %,
/// interpolated linearly between stations. (DATCOM defines it on the upper surface; the
/// original, and we, take the half thickness, which is the same for symmetric sections and
/// what DATCOM's tables of Δy against thickness for the NACA families measure.)
pub(crate) fn delta_y_percent(shape: &SectionShape) -> f64 {
    let t = Ordinates {
        x: &shape.x,
        y: &shape.half_thickness,
    };
    100.0 * (t.linear(DELTA_Y_AFT) - t.linear(DELTA_Y_FORE))
}
