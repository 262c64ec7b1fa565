//! Thickness distributions: the half thickness y_t(x) of a section, perpendicular to its mean
//! line, as a fraction of chord, for x from 0 (leading edge) to 1 (trailing edge).

/// NACA 4-digit thickness, y_t = 5t (a0 sqrt(x) + a1 x + a2 x^2 + a3 x^3 + a4 x^4): the
/// coefficients of NACA Report 460 (Jacobs, Ward & Pinkerton 1933), as Abbott & von Doenhoff,
/// Theory of Wing Sections, chapter 6 give them (a4 = -0.1015: the trailing edge is open).
const FOUR_DIGIT_POLYNOMIAL: [f64; 5] = [0.2969, -0.1260, -0.3516, 0.2843, -0.1015];
/// Factor 5 of the 4-digit equation (its coefficients are those of a 20-percent-thick section).
const FOUR_DIGIT_SCALE: f64 = 5.0;
/// Leading-edge radius of the 4-digit thickness, r = 1.1019 t^2 (Abbott & von Doenhoff,
/// chapter 6; COORD4 line 5945).
const FOUR_DIGIT_LE_RADIUS: f64 = 1.1019;
/// Position of the maximum of the 4-digit thickness, fraction of chord (NACA Report 460).
const FOUR_DIGIT_MAX_X: f64 = 0.30;
/// Leading-edge radius index of the normal 4-digit radius (modified 4-digit series, NACA Report
/// 492): the radius is 1.1019 (t I / 6)^2.
const NORMAL_LE_INDEX: f64 = 6.0;
/// Trailing-edge half thickness of the modified 4-digit thickness over t: d0 = 0.002 for
/// t = 0.20 (NACA Report 492; CORD4M line 6236).
const MODIFIED_D0_OVER_T: f64 = 0.01;
/// DATCOM's fit of the 6-series leading-edge radius, r = 0.01 (c2 t^2 + c1 t + c0)
/// (COORD6 line 6115): [c0, c1, c2] and the factor 0.01.
const SIX_SERIES_LE_RADIUS: [f64; 3] = [0.0014, 0.0182, 68.682];
const SIX_SERIES_LE_RADIUS_SCALE: f64 = 0.01;

/// A half-thickness distribution.
#[derive(Debug, Clone, PartialEq)]
pub enum Thickness {
    /// NACA 4-digit thickness of ratio `t` (also that of the 5-digit sections).
    FourDigit { t: f64 },
    /// A nose polynomial joined at the maximum thickness to a cubic tail: the NACA modified
    /// 4-digit and 16-series thickness, and DATCOM's fit of the 6- and 6A-series forms.
    Joined(JoinedThickness),
    /// Supersonic double wedge (NACA S-1): straight from the leading edge to the ridge at
    /// `ridge` and on to the trailing edge.
    DoubleWedge { t: f64, ridge: f64 },
    /// Supersonic biconvex (NACA S-2): two circular arcs, maximum thickness at mid chord.
    Biconvex { t: f64 },
    /// Supersonic hexagon (NACA S-3): wedge to `ridge`, flat over `flat`, wedge to the trailing
    /// edge.
    Hexagonal { t: f64, ridge: f64, flat: f64 },
}

impl Thickness {
    /// Half thickness at `x` (fraction of chord; values outside 0..1 are taken at the nearer
    /// end). NACA Report 460 (4-digit), Report 492 (modified 4-digit), COORD6 (6-series fit),
    /// CORDSP (supersonic, datcom.f lines 6418-6548).
    pub fn half(&self, x: f64) -> f64 {
        let x = x.clamp(0.0, 1.0);
        match *self {
            Thickness::FourDigit { t } => four_digit_half(t, x),
            Thickness::Joined(ref j) => j.half(x),
            Thickness::DoubleWedge { t, ridge } => wedge_half(t, ridge, 0.0, x),
            Thickness::Hexagonal { t, ridge, flat } => wedge_half(t, ridge, flat, x),
            Thickness::Biconvex { t } if t <= 0.0 => 0.0,
            Thickness::Biconvex { t } => {
                let r = (t * t + 1.0) / (4.0 * t);
                t / 2.0 - r + (r * r - (x - 0.5).powi(2)).max(0.0).sqrt()
            }
        }
    }

    /// Maximum thickness, fraction of chord (the designation's t/c).
    pub fn ratio(&self) -> f64 {
        match *self {
            Thickness::FourDigit { t }
            | Thickness::DoubleWedge { t, .. }
            | Thickness::Biconvex { t }
            | Thickness::Hexagonal { t, .. } => t,
            Thickness::Joined(ref j) => j.t,
        }
    }

    /// Chordwise position of the maximum thickness (the start of the flat for a hexagon).
    pub fn max_thickness_x(&self) -> f64 {
        match *self {
            Thickness::FourDigit { .. } => FOUR_DIGIT_MAX_X,
            Thickness::Joined(ref j) => j.max_x,
            Thickness::DoubleWedge { ridge, .. } | Thickness::Hexagonal { ridge, .. } => ridge,
            Thickness::Biconvex { .. } => 0.5,
        }
    }

    /// Leading-edge radius, fraction of chord: 1.1019 t^2 for the 4-digit thickness, the
    /// index-scaled radius of the modified series, DATCOM's fit for the 6-series, 0 for the sharp
    /// supersonic sections.
    pub fn leading_edge_radius(&self) -> f64 {
        match *self {
            Thickness::FourDigit { t } => FOUR_DIGIT_LE_RADIUS * t * t,
            Thickness::Joined(ref j) => j.leading_edge_radius,
            Thickness::DoubleWedge { .. }
            | Thickness::Biconvex { .. }
            | Thickness::Hexagonal { .. } => 0.0,
        }
    }
}

/// NACA 4-digit half thickness (NACA Report 460; Abbott & von Doenhoff, chapter 6).
fn four_digit_half(t: f64, x: f64) -> f64 {
    let [a0, a1, a2, a3, a4] = FOUR_DIGIT_POLYNOMIAL;
    let polynomial = a0 * x.sqrt() + x * (a1 + x * (a2 + x * (a3 + x * a4)));
    FOUR_DIGIT_SCALE * t * polynomial
}

/// Half thickness of a wedge to `ridge`, a flat of length `flat` and a wedge to the trailing
/// edge (CORDSP: double wedge with `flat` = 0, hexagon otherwise).
fn wedge_half(t: f64, ridge: f64, flat: f64, x: f64) -> f64 {
    if x < ridge {
        x * t / (2.0 * ridge)
    } else if x <= ridge + flat {
        t / 2.0
    } else {
        t / 2.0 * (1.0 - x) / (1.0 - ridge - flat)
    }
}

/// A half thickness made of a nose a0 sqrt(x) + a1 x + a2 x^2 + a3 x^3 up to the maximum
/// thickness at `max_x` and a tail d0 + d1 (1-x) + d2 (1-x)^2 + d3 (1-x)^3 behind it, the two
/// meeting at `max_x` with the value t/2, zero slope and equal curvature. a0 sets the
/// leading-edge radius (r = a0^2 / 2), d0 the trailing-edge thickness and d1 the trailing-edge
/// slope. This is the NACA modified 4-digit thickness (NACA Report 492; Abbott & von Doenhoff,
/// chapter 6), of which the 16-series thickness is one case, and the form of DATCOM's 6-series
/// fit (routines CORD4M, datcom.f lines 6236-6266, and COORD6, lines 6104-6135).
#[derive(Debug, Clone, PartialEq)]
pub struct JoinedThickness {
    /// Maximum thickness, fraction of chord.
    pub t: f64,
    /// Position of the maximum thickness, fraction of chord.
    pub max_x: f64,
    /// a0..a3 of the nose.
    pub nose: [f64; 4],
    /// d0..d3 of the tail.
    pub tail: [f64; 4],
    /// Leading-edge radius, fraction of chord.
    pub leading_edge_radius: f64,
    /// From this station on the half thickness is the straight line to zero at the trailing
    /// edge (6A sections, NACA Report 903).
    pub straight_from: Option<f64>,
}

impl JoinedThickness {
    /// Solves the joining conditions for the nose and tail coefficients, given the thickness
    /// `t`, the position of the maximum `max_x` (strictly between 0 and 1), the leading-edge
    /// radius and the tail's d0 and d1.
    pub(crate) fn new(t: f64, max_x: f64, leading_edge_radius: f64, d0: f64, d1: f64) -> Self {
        let z = max_x;
        let a0 = (2.0 * leading_edge_radius).sqrt();
        // Tail: value t/2 and zero slope at z, in s = 1 - x.
        let s = 1.0 - z;
        let remainder = t / 2.0 - d0 - d1 * s;
        let d3 = -(d1 + 2.0 * remainder / s) / (s * s);
        let d2 = (remainder - d3 * s.powi(3)) / (s * s);
        let tail_curvature = 2.0 * d2 + 6.0 * d3 * s;
        // Nose: value t/2, zero slope and the tail's curvature at z.
        let value = t / 2.0 - a0 * z.sqrt();
        let slope = -a0 / (2.0 * z.sqrt());
        let curvature = tail_curvature + a0 / (4.0 * z.powf(1.5));
        let u = slope - value / z;
        let a3 = (curvature / 2.0 - u / z) / z;
        let a2 = u / z - 2.0 * a3 * z;
        let a1 = value / z - a2 * z - a3 * z * z;
        JoinedThickness {
            t,
            max_x,
            nose: [a0, a1, a2, a3],
            tail: [d0, d1, d2, d3],
            leading_edge_radius,
            straight_from: None,
        }
    }

    /// NACA modified 4-digit thickness (NACA Report 492): leading-edge radius index `le_index`
    /// (6 = the 4-digit radius, 0 = sharp), maximum at `max_x`, trailing-edge slope
    /// `d1_over_t * t` (chart `airfoil-modified-4digit-d1`) and trailing-edge half thickness
    /// 0.01 t. CORD4M, datcom.f lines 6206-6296.
    pub(crate) fn modified_four_digit(t: f64, le_index: f64, max_x: f64, d1_over_t: f64) -> Self {
        let radius = FOUR_DIGIT_LE_RADIUS * (t * le_index / NORMAL_LE_INDEX).powi(2);
        Self::new(t, max_x, radius, MODIFIED_D0_OVER_T * t, d1_over_t * t)
    }

    /// DATCOM's fit of a 6-series thickness form (COORD6, datcom.f lines 6077-6130): maximum at
    /// `max_x`, sharp trailing edge with slope `d1`, leading-edge radius
    /// 0.01 (68.682 t^2 + 0.0182 t + 0.0014).
    pub(crate) fn six_series_fit(t: f64, max_x: f64, d1: f64) -> Self {
        let [c0, c1, c2] = SIX_SERIES_LE_RADIUS;
        let radius = SIX_SERIES_LE_RADIUS_SCALE * (c2 * t * t + c1 * t + c0);
        Self::new(t, max_x, radius, 0.0, d1)
    }

    /// The same thickness, straight from `x` to zero at the trailing edge.
    pub(crate) fn straight_from(self, x: f64) -> Self {
        JoinedThickness {
            straight_from: Some(x),
            ..self
        }
    }

    fn half(&self, x: f64) -> f64 {
        match self.straight_from {
            Some(xs) if x > xs => self.curved(xs) * (1.0 - x) / (1.0 - xs),
            _ => self.curved(x),
        }
    }

    fn curved(&self, x: f64) -> f64 {
        if x < self.max_x {
            let [a0, a1, a2, a3] = self.nose;
            a0 * x.sqrt() + x * (a1 + x * (a2 + x * a3))
        } else {
            let [d0, d1, d2, d3] = self.tail;
            let s = 1.0 - x;
            d0 + s * (d1 + s * (d2 + s * d3))
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn joined_thickness_meets_its_conditions() {
        let j = JoinedThickness::modified_four_digit(0.12, 6.0, 0.4, 1.575);
        let h = 1e-6;
        let at = |x: f64| j.curved(x);
        assert!((at(0.4) - 0.06).abs() < 1e-12);
        assert!((at(0.4 - 1e-9) - 0.06).abs() < 1e-9);
        let nose_slope = (at(0.4 - h) - at(0.4 - 2.0 * h)) / h;
        let tail_slope = (at(0.4 + 2.0 * h) - at(0.4 + h)) / h;
        assert!(nose_slope.abs() < 1e-5 && tail_slope.abs() < 1e-5);
        assert!((at(1.0) - 0.0012).abs() < 1e-12, "d0 = 0.01 t");
        // Normal radius: the 4-digit 1.1019 t^2.
        assert!((j.leading_edge_radius - 1.1019 * 0.0144).abs() < 1e-12);
    }

    #[test]
    fn straight_tail_reaches_zero() {
        let j = JoinedThickness::six_series_fit(0.04, 0.4, 1.17 * 0.04).straight_from(0.8);
        let y8 = j.half(0.8);
        assert!((j.half(0.9) - y8 / 2.0).abs() < 1e-15);
        assert_eq!(j.half(1.0), 0.0);
    }

    #[test]
    fn outside_the_chord_is_the_nearer_end() {
        let t = Thickness::FourDigit { t: 0.12 };
        assert_eq!(t.half(-1.0), 0.0);
        assert_eq!(t.half(2.0), t.half(1.0));
        assert!(Thickness::Biconvex { t: 0.05 }.half(0.0).abs() < 1e-15);
    }
}
