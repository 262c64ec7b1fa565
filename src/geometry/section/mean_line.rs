//! Mean lines: the camber y_c(x) of a section and its slope dy_c/dx, fractions of chord, for x
//! from 0 (leading edge) to 1 (trailing edge).

use std::f64::consts::PI;

/// The a = 0.8 (modified) mean line of the 6A-series (NACA Report 903, Loftin 1948, as NASA
/// TM-4741, Ladson et al. 1996, p. 8 writes it): the a = 0.8 line times this factor ...
const SIX_A_SCALE: f64 = 0.97948;
/// ... up to this station, and from there a straight line to the trailing edge ...
const SIX_A_STRAIGHT_FROM: f64 = 0.86;
/// ... of this slope per unit design lift coefficient.
const SIX_A_TAIL_SLOPE: f64 = -0.24521;
/// The load extent of the line the 6A-series modifies.
pub(crate) const SIX_A_LOAD_EXTENT: f64 = 0.8;

/// A mean line.
#[derive(Debug, Clone, PartialEq)]
pub enum MeanLine {
    /// No camber.
    Symmetric,
    /// NACA 4-digit mean line: two parabolas meeting at the maximum camber `max_camber` at
    /// `position` (NACA Report 460; Abbott & von Doenhoff, Theory of Wing Sections, chapter 6).
    FourDigit { max_camber: f64, position: f64 },
    /// NACA 5-digit mean line (standard or reflexed).
    FiveDigit(FiveDigitMeanLine),
    /// NACA 6-series mean line: uniform load from the leading edge to `a`, falling linearly to
    /// zero at the trailing edge, for the ideal lift coefficient `design_cl` (Abbott & von
    /// Doenhoff, eqs. 4.26 and 4.27; NACA Report 824). `a` = 1 is the line of the 1-series and of
    /// 6-series designations without `A=`.
    Uniform { design_cl: f64, a: f64 },
    /// The a = 0.8 (modified) line of the 6A-series (NACA Report 903).
    SixAModified { design_cl: f64 },
}

impl MeanLine {
    /// Camber at `x` (values outside 0..1 are taken at the nearer end).
    pub fn camber(&self, x: f64) -> f64 {
        let x = x.clamp(0.0, 1.0);
        match *self {
            MeanLine::Symmetric => 0.0,
            MeanLine::FourDigit {
                max_camber,
                position,
            } => {
                if x < position || position >= 1.0 {
                    max_camber / (position * position) * (2.0 * position * x - x * x)
                } else {
                    max_camber / (1.0 - position).powi(2)
                        * (1.0 - 2.0 * position + 2.0 * position * x - x * x)
                }
            }
            MeanLine::FiveDigit(ref line) => line.camber(x),
            MeanLine::Uniform { design_cl, a } => design_cl * uniform_load_camber(a, x),
            MeanLine::SixAModified { design_cl } => {
                if x > SIX_A_STRAIGHT_FROM {
                    design_cl * SIX_A_TAIL_SLOPE * (x - 1.0)
                } else {
                    design_cl * SIX_A_SCALE * uniform_load_camber(SIX_A_LOAD_EXTENT, x)
                }
            }
        }
    }

    /// Slope dy_c/dx at `x` (values outside 0..1 are taken at the nearer end). The uniform-load
    /// lines have a logarithmically infinite slope at the leading edge (and, for a = 1, at the
    /// trailing edge): there the slope is infinite, never NaN.
    pub fn slope(&self, x: f64) -> f64 {
        let x = x.clamp(0.0, 1.0);
        match *self {
            MeanLine::Symmetric => 0.0,
            MeanLine::FourDigit {
                max_camber,
                position,
            } => {
                if x < position || position >= 1.0 {
                    2.0 * max_camber / (position * position) * (position - x)
                } else {
                    2.0 * max_camber / (1.0 - position).powi(2) * (position - x)
                }
            }
            MeanLine::FiveDigit(ref line) => line.slope(x),
            MeanLine::Uniform { design_cl, a } => design_cl * uniform_load_slope(a, x),
            MeanLine::SixAModified { design_cl } => {
                if x > SIX_A_STRAIGHT_FROM {
                    design_cl * SIX_A_TAIL_SLOPE
                } else {
                    design_cl * SIX_A_SCALE * uniform_load_slope(SIX_A_LOAD_EXTENT, x)
                }
            }
        }
    }
}

/// NACA 5-digit mean line (NACA Report 537, Jacobs & Pinkerton 1935; Report 610; NASA TM-4741
/// p. 8): a cubic from the leading edge to `m`, then a straight line (standard line,
/// `k2_over_k1` = 0) or a cubic that turns up again (reflexed line) to the trailing edge:
///
/// y_c = k1/6 [(x-m)^3 - k (1-m)^3 x - m^3 x + m^3]      for x < m,
/// y_c = k1/6 [k (x-m)^3 - k (1-m)^3 x - m^3 x + m^3]    for x >= m,  with k = k2/k1.
///
/// NACA tabulates m and k1 (for a design lift coefficient of 0.3) by the position of maximum
/// camber (charts `airfoil-5digit-m`, `airfoil-5digit-k1`); k1 scales with the design lift
/// coefficient, and for the reflexed line k2/k1 = (3(m-p)^2 - m^3)/(1-m)^3 puts the maximum
/// camber at p.
#[derive(Debug, Clone, PartialEq)]
pub struct FiveDigitMeanLine {
    pub m: f64,
    pub k1: f64,
    pub k2_over_k1: f64,
}

impl FiveDigitMeanLine {
    /// Camber at `x`, 0 <= x <= 1.
    pub fn camber(&self, x: f64) -> f64 {
        let FiveDigitMeanLine {
            m,
            k1,
            k2_over_k1: k,
        } = *self;
        let common = -k * (1.0 - m).powi(3) * x - m.powi(3) * x + m.powi(3);
        let cubic = if x < m { 1.0 } else { k } * (x - m).powi(3);
        k1 / 6.0 * (cubic + common)
    }

    /// Slope at `x`, 0 <= x <= 1.
    pub fn slope(&self, x: f64) -> f64 {
        let FiveDigitMeanLine {
            m,
            k1,
            k2_over_k1: k,
        } = *self;
        let common = -k * (1.0 - m).powi(3) - m.powi(3);
        let cubic = if x < m { 1.0 } else { k } * 3.0 * (x - m).powi(2);
        k1 / 6.0 * (cubic + common)
    }
}

/// v ln|v|, and its limit 0 at v = 0.
fn v_ln_v(v: f64) -> f64 {
    if v == 0.0 {
        0.0
    } else {
        v * v.abs().ln()
    }
}

/// The 6-series mean line of load extent `a` for a design lift coefficient of 1 (Abbott & von
/// Doenhoff, eq. 4.26; COORD6, datcom.f lines 6136-6155):
///
/// y_c = 1/(2 pi (a+1)) [ (1/2 (a-x)^2 ln|a-x| - 1/2 (1-x)^2 ln(1-x) + 1/4 (1-x)^2 - 1/4 (a-x)^2)
///       / (1-a) - x ln x + g - h x ],
/// g = -(a^2 (ln(a)/2 - 1/4) + 1/4) / (1-a),  h = ((1-a)^2 (ln(1-a)/2 - 1/4)) / (1-a) + g,
///
/// and, for a = 1, y_c = -((1-x) ln(1-x) + x ln x) / (4 pi).
fn uniform_load_camber(a: f64, x: f64) -> f64 {
    if a >= 1.0 {
        return -(v_ln_v(1.0 - x) + v_ln_v(x)) / (4.0 * PI);
    }
    let (g, h) = uniform_load_g_h(a);
    let (d, s) = (a - x, 1.0 - x);
    let bracket = 0.5 * d * v_ln_v(d) - 0.5 * s * v_ln_v(s) + 0.25 * s * s - 0.25 * d * d;
    (bracket / (1.0 - a) - v_ln_v(x) + g - h * x) / (2.0 * PI * (a + 1.0))
}

/// Slope of [`uniform_load_camber`] (Abbott & von Doenhoff, eq. 4.27):
/// dy_c/dx = 1/(2 pi (a+1)) [ ((1-x) ln(1-x) - (a-x) ln|a-x|) / (1-a) - ln x - 1 - h ],
/// and, for a = 1, -(ln x - ln(1-x)) / (4 pi).
fn uniform_load_slope(a: f64, x: f64) -> f64 {
    if a >= 1.0 {
        return if x <= 0.0 {
            f64::INFINITY
        } else if x >= 1.0 {
            f64::NEG_INFINITY
        } else {
            -(x.ln() - (1.0 - x).ln()) / (4.0 * PI)
        };
    }
    if x <= 0.0 {
        return f64::INFINITY;
    }
    let (_, h) = uniform_load_g_h(a);
    let bracket = (v_ln_v(1.0 - x) - v_ln_v(a - x)) / (1.0 - a);
    (bracket - x.ln() - 1.0 - h) / (2.0 * PI * (a + 1.0))
}

/// The constants g and h of the uniform-load line of extent `a` < 1.
fn uniform_load_g_h(a: f64) -> (f64, f64) {
    let c = 1.0 - a;
    let g = -(a * v_ln_v(a) / 2.0 - a * a / 4.0 + 0.25) / c;
    let h = (c * v_ln_v(c) / 2.0 - c * c / 4.0) / c + g;
    (g, h)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The 6-series lines of Abbott & von Doenhoff, Appendix II, as recomputed by PDAS naca456
    /// (Carmichael; pdas docs/source/meanlines.rst), ordinates in percent of chord for a design
    /// lift coefficient of 1, printed to 4 decimals.
    #[test]
    fn six_series_lines_match_the_published_tables() {
        let cases = [
            (
                MeanLine::Uniform {
                    design_cl: 1.0,
                    a: 1.0,
                },
                0.50,
                5.5159,
            ),
            (
                MeanLine::Uniform {
                    design_cl: 1.0,
                    a: 1.0,
                },
                0.05,
                1.5797,
            ),
            (
                MeanLine::Uniform {
                    design_cl: 1.0,
                    a: 0.8,
                },
                0.50,
                6.7896,
            ),
            (
                MeanLine::Uniform {
                    design_cl: 1.0,
                    a: 0.8,
                },
                0.90,
                2.4349,
            ),
            (
                MeanLine::Uniform {
                    design_cl: 1.0,
                    a: 0.8,
                },
                0.80,
                4.7713,
            ),
            (MeanLine::SixAModified { design_cl: 1.0 }, 0.50, 6.6503),
            (MeanLine::SixAModified { design_cl: 1.0 }, 0.85, 3.6070),
            (MeanLine::SixAModified { design_cl: 1.0 }, 0.90, 2.4521),
        ];
        for (line, x, percent) in cases {
            let y = 100.0 * line.camber(x);
            assert!((y - percent).abs() < 0.6e-4, "{line:?} at {x}: {y}");
        }
    }

    #[test]
    fn uniform_load_limits_are_finite() {
        for a in [0.0, 0.5, 0.8, 1.0] {
            let line = MeanLine::Uniform { design_cl: 0.4, a };
            assert_eq!(line.camber(0.0), 0.0);
            assert!(line.camber(1.0).abs() < 1e-15);
            assert!(line.camber(a).is_finite());
            assert!(!line.slope(0.0).is_nan() && !line.slope(1.0).is_nan());
        }
    }

    #[test]
    fn five_digit_line_is_continuous_with_zero_slope_at_maximum_camber() {
        // NACA 231 (reflexed): p = 0.15, m = 0.217, k1 = 15.793.
        let (p, m) = (0.15_f64, 0.217_f64);
        let k = (3.0 * (m - p).powi(2) - m.powi(3)) / (1.0 - m).powi(3);
        let line = FiveDigitMeanLine {
            m,
            k1: 15.793,
            k2_over_k1: k,
        };
        assert!((line.camber(m - 1e-12) - line.camber(m)).abs() < 1e-12);
        assert!(line.slope(p).abs() < 1e-12);
        assert!(line.camber(1.0).abs() < 1e-15);
    }
}
