//! Interpolation of section ordinates between chordwise stations, as the section module uses
//! it: a smooth piecewise cubic for the Weber points (the original's routine ASMINT) and
//! straight lines (the value part of the original's table routine TBFUNX).

/// Ordinates given at strictly ascending stations; at least [`MIN_STATIONS`] of them.
///
/// Callers check the stations (see [`super::SectionShape::new`]); the functions here assume
/// they are strictly ascending and finite.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Ordinates<'a> {
    pub x: &'a [f64],
    pub y: &'a [f64],
}

/// Fewest stations the smooth interpolation works on: two end intervals and one interior one.
pub(crate) const MIN_STATIONS: usize = 4;

impl Ordinates<'_> {
    /// Slope of the chord from station `i` to station `i + 1`.
    fn chord_slope(&self, i: usize) -> f64 {
        (self.y[i + 1] - self.y[i]) / (self.x[i + 1] - self.x[i])
    }

    /// Slope at interior station `i`: the tangent of the mean of the inclinations of the two
    /// chords that meet there (the bisector of the angle they make).
    fn node_slope(&self, i: usize) -> f64 {
        let left = self.chord_slope(i - 1).atan();
        let right = self.chord_slope(i).atan();
        (0.5 * (left + right)).tan()
    }

    /// Smooth interpolation at `x` (ASMINT).
    ///
    /// - Between interior stations: the cubic that takes the ordinates and the slopes
    ///   [`Self::node_slope`] at both ends of the interval (a Hermite cubic; the original writes
    ///   the same cubic in global coordinates, which loses digits in single precision).
    /// - In the first and last intervals: the parabola through both end ordinates whose slope
    ///   at the interval's inner station is that station's slope. Beyond the stations the end
    ///   parabolas continue.
    pub fn smooth(&self, x: f64) -> f64 {
        let n = self.x.len();
        let last_interior = n - 2;
        if x < self.x[1] {
            return self.end_parabola(0, 1, x);
        }
        if x > self.x[last_interior] {
            return self.end_parabola(last_interior, last_interior, x);
        }
        // Interval [x[j], x[j+1]] with 1 <= j <= n-3 holding x.
        let j = self.x[1..last_interior]
            .partition_point(|xi| *xi <= x)
            .clamp(1, last_interior - 1);
        let (a, b) = (self.x[j], self.x[j + 1]);
        let h = b - a;
        let t = (x - a) / h;
        let (ma, mb) = (self.node_slope(j), self.node_slope(j + 1));
        let t2 = t * t;
        let t3 = t2 * t;
        let h00 = 2.0 * t3 - 3.0 * t2 + 1.0;
        let h10 = t3 - 2.0 * t2 + t;
        let h01 = -2.0 * t3 + 3.0 * t2;
        let h11 = t3 - t2;
        h00 * self.y[j] + h10 * h * ma + h01 * self.y[j + 1] + h11 * h * mb
    }

    /// The parabola through stations `i` and `i + 1` whose slope at station `inner` (one of
    /// them) is the node slope there, at `x`.
    fn end_parabola(&self, i: usize, inner: usize, x: f64) -> f64 {
        let (a, b) = (self.x[i], self.x[i + 1]);
        let chord = self.chord_slope(i);
        // y = y_a + (x − a)·(chord + k·(x − b)): through both points, slope
        // chord + k·(2x − a − b), which is the node slope at x = x[inner].
        let k = (self.node_slope(inner) - chord) / (2.0 * self.x[inner] - a - b);
        self.y[i] + (x - a) * (chord + k * (x - b))
    }

    /// Straight-line interpolation at `x`, the end ordinate beyond the stations (TBFUNX with
    /// no extrapolation).
    pub fn linear(&self, x: f64) -> f64 {
        let n = self.x.len();
        if x <= self.x[0] {
            return self.y[0];
        }
        if x >= self.x[n - 1] {
            return self.y[n - 1];
        }
        let j = self.x.partition_point(|xi| *xi <= x).clamp(1, n - 1) - 1;
        let (a, b) = (self.x[j], self.x[j + 1]);
        self.y[j] + (self.y[j + 1] - self.y[j]) * (x - a) / (b - a)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A cubic whose node slopes (bisectors of the chord angles) are not its own slopes still
    /// passes through every station, and a straight line is reproduced everywhere (all node
    /// slopes equal the line's).
    #[test]
    fn smooth_passes_through_stations_and_keeps_lines() {
        let x = [0.0, 0.1, 0.3, 0.6, 0.8, 1.0];
        let y: Vec<f64> = x.iter().map(|x| x * x * x - x).collect();
        let o = Ordinates { x: &x, y: &y };
        for (xi, yi) in x.iter().zip(&y) {
            assert!((o.smooth(*xi) - yi).abs() < 1e-15, "at {xi}");
        }
        let line: Vec<f64> = x.iter().map(|x| 0.3 - 0.2 * x).collect();
        let o = Ordinates { x: &x, y: &line };
        for q in [0.0, 0.05, 0.2, 0.45, 0.7, 0.9, 1.0] {
            assert!((o.smooth(q) - (0.3 - 0.2 * q)).abs() < 1e-15, "at {q}");
        }
    }

    /// Worked by hand: stations 0, 1, 2, 3 with ordinates 0, 1, 1, 0. Node slopes: at 1 the
    /// chords rise 1 and 0, angles 45° and 0°, slope tan 22.5° = √2 − 1; at 2, −(√2 − 1). The
    /// first interval's parabola y = x·(1 + k(x − 1)) with slope 1 + k at x = 1 equal to √2 − 1
    /// gives k = √2 − 2, so y(0.5) = 0.5·(1 − 0.5k) = 0.5 + 0.25·(2 − √2) = 0.646447. The middle
    /// cubic is symmetric: y(1.5) = 1 + 2·h10(½)·(√2 − 1) with h10(½) = 1/8: 1.103553.
    #[test]
    fn smooth_worked_by_hand() {
        let x = [0.0, 1.0, 2.0, 3.0];
        let y = [0.0, 1.0, 1.0, 0.0];
        let o = Ordinates { x: &x, y: &y };
        let r2 = std::f64::consts::SQRT_2;
        assert!((o.smooth(0.5) - (0.5 + 0.25 * (2.0 - r2))).abs() < 1e-15);
        assert!((o.smooth(1.5) - (1.0 + 0.25 * (r2 - 1.0))).abs() < 1e-15);
        assert!((o.smooth(2.5) - o.smooth(0.5)).abs() < 1e-15);
    }

    #[test]
    fn linear_clamps_beyond_the_stations() {
        let x = [0.0, 0.5, 1.0];
        let y = [0.0, 1.0, 0.0];
        let o = Ordinates { x: &x, y: &y };
        assert_eq!(o.linear(-1.0), 0.0);
        assert_eq!(o.linear(2.0), 0.0);
        assert!((o.linear(0.25) - 0.5).abs() < 1e-15);
        assert!((o.linear(0.75) - 0.5).abs() < 1e-15);
        assert_eq!(o.linear(0.5), 1.0);
    }
}
