//! Weber's singularity method for the velocity on an airfoil section: the influence sums of the
//! thickness and mean-line ordinates at Weber's chordwise points (J. Weber, ARC R&M 2918 and
//! 3026; the original's routine IDEAL, which the section-characteristics page calls through
//! THEORY).
//!
//! The chord is mapped to an angle, x = (1 + cos θ)/2, so that θ = 0 is the trailing edge and
//! θ = π the leading edge, and sampled at N = 32 equal steps θ_ν = νπ/N. At each point the
//! velocity on the surface is built from five sums over the ordinates at the other points
//! (the "S" matrices of Weber's method), each a finite-sum form of a thin-wing integral:
//!
//! | sum | from | meaning |
//! |---|---|---|
//! | S1 | half thickness z_t | streamwise velocity of the thickness (source) distribution |
//! | S2 | z_t | slope dz_t/dx |
//! | S3 | z_t | thickness factor on the angle-of-attack term, with Riegels' leading-edge term |
//! | S4 | mean line z_c | streamwise velocity of the camber (vortex) distribution |
//! | S5 | z_c | slope dz_c/dx |

use std::f64::consts::PI;
use std::sync::OnceLock;

use super::interpolation::Ordinates;

/// Number of angular steps of Weber's method (the original's XN); the points used are
/// ν = 1 … N − 1, from the trailing edge to the leading edge.
pub(crate) const N: usize = 32;
/// Points where the velocity is computed: ν = 1 … 31.
pub(crate) const POINTS: usize = N - 1;

/// The chordwise points of Weber's method, ν = 1 … 31 at index ν − 1.
#[derive(Debug, Clone)]
pub(crate) struct Grid {
    /// x_ν = (1 + cos θ_ν)/2: 0.99759 near the trailing edge down to 0.00241 near the
    /// leading edge.
    pub x: [f64; POINTS],
    pub sin: [f64; POINTS],
    pub cos: [f64; POINTS],
}

impl Grid {
    pub fn new() -> Grid {
        let theta: [f64; POINTS] = std::array::from_fn(|k| (k + 1) as f64 * PI / N as f64);
        Grid {
            x: theta.map(|t| 0.5 * (1.0 + t.cos())),
            sin: theta.map(f64::sin),
            cos: theta.map(f64::cos),
        }
    }

    /// Index of point ν (1-based, as in the method's equations).
    pub const fn at(nu: usize) -> usize {
        nu - 1
    }
}

/// (−1)^k for an index difference.
fn parity(k: isize) -> f64 {
    if k.rem_euclid(2) == 0 {
        1.0
    } else {
        -1.0
    }
}

/// Ordinates at Weber's points and the five influence sums at each point.
#[derive(Debug, Clone)]
pub(crate) struct Terms {
    pub grid: Grid,
    /// Half thickness at the points.
    pub zt: [f64; POINTS],
    /// Mean line at the points.
    pub zc: [f64; POINTS],
    pub s1: [f64; POINTS],
    pub s2: [f64; POINTS],
    pub s3: [f64; POINTS],
    pub s4: [f64; POINTS],
    pub s5: [f64; POINTS],
}

/// How the half thickness is read between stations: the smooth cubic for ordinary sections,
/// straight lines for sections with corners (the supersonic wedge and hexagon families).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Reading {
    Smooth,
    Linear,
}

/// The weights of the five sums, which depend on the points only: `weights[ν][μ]` is the
/// weight of ordinate μ in each sum at point ν, and `leading_edge[ν]` Riegels' factor
/// ((−1)^ν − 1)/(n(1 + cos θν)) before √(ρ/2). Computed once per process.
struct Weights {
    grid: Grid,
    weights: Box<[[[f64; 5]; POINTS]; POINTS]>,
    leading_edge: [f64; POINTS],
}

fn weights() -> &'static Weights {
    static WEIGHTS: OnceLock<Weights> = OnceLock::new();
    WEIGHTS.get_or_init(|| {
        let grid = Grid::new();
        let n = N as f64;
        let (c, s) = (&grid.cos, &grid.sin);
        // (−1)^μ − 1 for point index k (μ = k + 1).
        let odd = |k: usize| parity(k as isize + 1) - 1.0;
        let mut weights = Box::new([[[0.0; 5]; POINTS]; POINTS]);
        for (v, row) in weights.iter_mut().enumerate() {
            let (cv, sv) = (c[v], s[v]);
            for (m, w) in row.iter_mut().enumerate() {
                let (cm, sm) = (c[m], s[m]);
                *w = if m == v {
                    [
                        n / sv,
                        cv / (sv * sv),
                        n / sv,
                        n / sv - 2.0 * odd(m) / (n * sv * (1.0 - cv)),
                        -cv / (sv * sv),
                    ]
                } else {
                    let p = parity(m as isize - v as isize);
                    let d = cm - cv;
                    let source = (p - 1.0) / n * 2.0 * sm / (d * d);
                    [
                        source,
                        -2.0 * p * sm / (sv * d),
                        source + 2.0 / n * (1.0 - p) / (sm * d),
                        2.0 * (p - 1.0) / (n * sv) * (1.0 - cm * cv) / (d * d)
                            - 2.0 * odd(m) / (n * sv * (1.0 - cm)),
                        -2.0 * p / d,
                    ]
                };
            }
        }
        let leading_edge = std::array::from_fn(|v| odd(v) / (n * (1.0 + c[v])));
        Weights {
            grid,
            weights,
            leading_edge,
        }
    })
}

impl Terms {
    /// The sums for a section of half thickness `thickness` and mean line `camber` with
    /// leading-edge radius `rho` (fraction of chord). With n = N, p = (−1)^(μ−ν),
    /// d = cos θμ − cos θν and s, c the sines and cosines, the weights of ordinate μ at point
    /// ν ≠ μ are
    ///
    /// - S1: (p − 1)/n · 2 sin θμ/d²,
    /// - S2: −2p sin θμ/(sin θν · d),
    /// - S3: S1's weight + 2/n · (1 − p)/(sin θμ · d),
    /// - S4: 2(p − 1)/(n sin θν) · (1 − cos θμ cos θν)/d² − 2((−1)^μ − 1)/(n sin θν (1 − cos θμ)),
    /// - S5: −2p/d,
    ///
    /// and at μ = ν: n/sin θν (S1, S3), cos θν/sin²θν (S2),
    /// n/sin θν − 2((−1)^ν − 1)/(n sin θν (1 − cos θν)) (S4), −cos θν/sin²θν (S5). Riegels'
    /// leading-edge term adds ((−1)^ν − 1)/(n(1 + cos θν)) · √(ρ/2) to S3. The weights depend
    /// on the points only and are computed once ([`weights`]).
    pub fn new(thickness: Ordinates, camber: Ordinates, reading: Reading, rho: f64) -> Terms {
        let table = weights();
        let grid = table.grid.clone();
        let zt = grid.x.map(|x| match reading {
            Reading::Smooth => thickness.smooth(x),
            Reading::Linear => thickness.linear(x),
        });
        let zc = grid.x.map(|x| camber.smooth(x));
        let riegels = (0.5 * rho).sqrt();
        let mut sums = [[0.0; POINTS]; 5];
        for (v, row) in table.weights.iter().enumerate() {
            let mut acc = [0.0; 5];
            for (m, weights) in row.iter().enumerate() {
                let ordinates = [zt[m], zt[m], zt[m], zc[m], zc[m]];
                for ((a, w), y) in acc.iter_mut().zip(weights).zip(ordinates) {
                    *a += w * y;
                }
            }
            acc[2] += table.leading_edge[v] * riegels;
            for (sum, a) in sums.iter_mut().zip(acc) {
                sum[v] = a;
            }
        }
        let [s1, s2, s3, s4, s5] = sums;
        Terms {
            grid,
            zt,
            zc,
            s1,
            s2,
            s3,
            s4,
            s5,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn grid_runs_from_trailing_to_leading_edge() {
        let g = Grid::new();
        assert!((g.x[0] - 0.997_592_363).abs() < 1e-9);
        assert!((g.x[POINTS - 1] - 0.002_407_637).abs() < 1e-9);
        assert!(g.x.windows(2).all(|w| w[1] < w[0]));
        // x_16 is mid-chord.
        assert!((g.x[Grid::at(16)] - 0.5).abs() < 1e-15);
    }

    /// A flat plate has every sum zero.
    #[test]
    fn flat_plate_has_no_thickness_or_camber_terms() {
        let x = [0.0, 0.3, 0.6, 1.0];
        let zero = [0.0; 4];
        let o = Ordinates { x: &x, y: &zero };
        let t = Terms::new(o, o, Reading::Smooth, 0.0);
        for v in [t.s1, t.s2, t.s3, t.s4, t.s5] {
            assert!(v.iter().all(|s| *s == 0.0));
        }
    }
}
