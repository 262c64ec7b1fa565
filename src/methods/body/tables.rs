//! Tabulated functions along the body: interpolation, slopes, resampling and integrals, read
//! the way the original's body routines read them (TBFUNX for values and slopes, EQSPC1 for the
//! 20 equally spaced stations, TRAPZ for the integrals), in double precision.

pub use crate::numeric::{parabola_slope, trapezoid};
/// Stations the body routines resample a table onto before integrating (EQSPC1/EQSPCE).
pub const RESAMPLED_STATIONS: usize = 20;

/// How the slope is taken at an end of a table.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum EndSlope {
    /// Slope of the parabola through the three end points (TBFUNX with LEX 0 or 2).
    Parabola,
    /// Slope of the chord through the two end points (TBFUNX with LEX 1).
    Chord,
}

/// `f` at `at`, linear between stations and the end value beyond them (TBFUNX value, LEX 0).
/// `x` ascends; with repeated stations the first bracketing interval is used.
pub fn interpolate(x: &[f64], f: &[f64], at: f64) -> f64 {
    let n = x.len().min(f.len());
    if n == 0 {
        return f64::NAN;
    }
    if n == 1 || at <= x[0] {
        return f[0];
    }
    if at >= x[n - 1] {
        return f[n - 1];
    }
    let k = (0..n - 1).find(|&k| at <= x[k + 1]).unwrap_or(n - 2);
    let h = x[k + 1] - x[k];
    if h == 0.0 {
        return f[k + 1];
    }
    f[k] + (at - x[k]) / h * (f[k + 1] - f[k])
}

fn chord_slope(x0: f64, x1: f64, y0: f64, y1: f64) -> Option<f64> {
    let h = x1 - x0;
    (h != 0.0).then(|| (y1 - y0) / h).filter(|s| s.is_finite())
}

/// Slope of the tabulated `f` at its node `k`: the parabola through the node and its two
/// neighbours inside the table; at the ends, as `first` and `last` say. Two points give the
/// chord, one point a zero slope. `None` when stations repeat where the slope is taken.
pub fn node_slope(x: &[f64], f: &[f64], k: usize, first: EndSlope, last: EndSlope) -> Option<f64> {
    let n = x.len().min(f.len());
    match n {
        0 => None,
        1 => Some(0.0),
        2 => chord_slope(x[0], x[1], f[0], f[1]),
        _ if k == 0 => match first {
            EndSlope::Parabola => parabola_slope([x[0], x[1], x[2]], [f[0], f[1], f[2]], x[0]),
            EndSlope::Chord => chord_slope(x[0], x[1], f[0], f[1]),
        },
        _ if k >= n - 1 => match last {
            EndSlope::Parabola => parabola_slope(
                [x[n - 3], x[n - 2], x[n - 1]],
                [f[n - 3], f[n - 2], f[n - 1]],
                x[n - 1],
            ),
            EndSlope::Chord => chord_slope(x[n - 2], x[n - 1], f[n - 2], f[n - 1]),
        },
        _ => parabola_slope([x[k - 1], x[k], x[k + 1]], [f[k - 1], f[k], f[k + 1]], x[k]),
    }
}

/// A table resampled onto equally spaced stations from its first station to its last.
#[derive(Debug, Clone, PartialEq)]
pub struct Resampled {
    pub x: Vec<f64>,
    pub f: Vec<f64>,
}

impl Resampled {
    /// `f` on [`RESAMPLED_STATIONS`] stations equally spaced over `x`, linear between the
    /// given stations. A one-point table gives that point at every station (and so zero
    /// integrals), as in the original.
    pub fn new(x: &[f64], f: &[f64]) -> Resampled {
        let n = RESAMPLED_STATIONS;
        if x.len() < 2 || f.len() < 2 {
            let (x0, f0) = (
                x.first().copied().unwrap_or(0.0),
                f.first().copied().unwrap_or(0.0),
            );
            return Resampled {
                x: vec![x0; n],
                f: vec![f0; n],
            };
        }
        let (a, b) = (x[0], x[x.len() - 1]);
        let step = (b - a) / (n - 1) as f64;
        let xe: Vec<f64> = (0..n)
            .map(|i| if i == n - 1 { b } else { a + i as f64 * step })
            .collect();
        let fe = xe.iter().map(|&at| interpolate(x, f, at)).collect();
        Resampled { x: xe, f: fe }
    }

    /// Slopes at the stations (interior: central parabola; ends: the end parabola), zero for
    /// a one-point table.
    pub fn slopes(&self) -> Vec<f64> {
        (0..self.x.len())
            .map(|k| {
                node_slope(&self.x, &self.f, k, EndSlope::Parabola, EndSlope::Parabola)
                    .unwrap_or(0.0)
            })
            .collect()
    }

    /// Trapezoidal integral of the resampled values.
    pub fn integral(&self) -> f64 {
        trapezoid(&self.x, &self.f)
    }
}

/// Index of the first largest value (scanning from the start, strictly greater; NaN ignored).
pub fn first_maximum(f: &[f64]) -> Option<usize> {
    let mut best: Option<usize> = None;
    for (k, v) in f.iter().enumerate() {
        if v.is_nan() {
            continue;
        }
        if best.is_none_or(|b| *v > f[b]) {
            best = Some(k);
        }
    }
    best
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Exact arithmetic up to a few roundings.
    const ROUNDING: f64 = 1e-12;

    #[test]
    fn parabola_slopes_are_exact_for_a_parabola() {
        // y = x²: slope 2x anywhere.
        let x = [0.0, 1.0, 3.0];
        let y = [0.0, 1.0, 9.0];
        for at in [0.0, 1.0, 3.0, 2.0] {
            assert!((parabola_slope(x, y, at).unwrap() - 2.0 * at).abs() < ROUNDING);
        }
        assert_eq!(parabola_slope([0.0, 0.0, 1.0], y, 0.0), None);
    }

    #[test]
    fn node_slopes_follow_the_end_rules() {
        let x = [0.0, 1.0, 2.0, 4.0];
        let f: Vec<f64> = x.iter().map(|x| x * x).collect();
        assert!(
            (node_slope(&x, &f, 0, EndSlope::Parabola, EndSlope::Chord).unwrap()).abs() < ROUNDING
        );
        assert!(
            (node_slope(&x, &f, 0, EndSlope::Chord, EndSlope::Chord).unwrap() - 1.0).abs()
                < ROUNDING
        );
        assert!(
            (node_slope(&x, &f, 2, EndSlope::Chord, EndSlope::Chord).unwrap() - 4.0).abs()
                < ROUNDING
        );
        // Last chord: (16 - 4) / 2 = 6; last parabola: 8.
        assert!(
            (node_slope(&x, &f, 3, EndSlope::Chord, EndSlope::Chord).unwrap() - 6.0).abs()
                < ROUNDING
        );
        assert!(
            (node_slope(&x, &f, 3, EndSlope::Chord, EndSlope::Parabola).unwrap() - 8.0).abs()
                < ROUNDING
        );
    }

    #[test]
    fn resampling_integrates_a_line_exactly() {
        let r = Resampled::new(&[1.0, 3.0, 5.0], &[0.0, 2.0, 4.0]);
        assert_eq!(r.x.len(), RESAMPLED_STATIONS);
        assert_eq!(r.x[RESAMPLED_STATIONS - 1], 5.0);
        // ∫₁⁵ (x − 1) dx = 8.
        assert!((r.integral() - 8.0).abs() < ROUNDING);
        assert!(r.slopes().iter().all(|s| (s - 1.0).abs() < 1e-9));
        let one = Resampled::new(&[2.0], &[3.0]);
        assert_eq!(one.integral(), 0.0);
    }
}
