//! Design values of the NACA uniform-load ("a") mean lines: the 1-series and 6-series design
//! lift coefficient and load extent `a` fix the ideal angle and the thin-airfoil zero-lift
//! angle (NACA Report 824; Abbott & von Doenhoff, Theory of Wing Sections, section 4.3; the
//! original's routines COORD1 and COORD6 preset them instead of integrating the mean line).

use std::f64::consts::PI;

use crate::geometry::section::MeanLine;

use super::DesignLift;

/// The a-mean line's factor h: with C = 1 − a, g = −(a²(½ ln a − ¼) + ¼)/C and
/// h = (½C² ln C − ¼C²)/C + g.
fn a_mean_line_h(a: f64) -> f64 {
    let c = 1.0 - a;
    let g = -(a * a * (0.5 * a.ln() - 0.25) + 0.25) / c;
    (0.5 * c * c * c.ln() - 0.25 * c * c) / c + g
}

/// Design values of the uniform-load mean line of design lift coefficient `cl` and load
/// extent `a` (uniform from the leading edge to `a`, then falling linearly to zero at the
/// trailing edge). For a = 1 the ideal angle is 0 and the zero-lift angle −c_l,i/(2π); for
/// a < 1 the ideal angle is −c_l,i·h/(2π(1 + a)) and the zero-lift angle is shifted by it.
pub fn a_mean_line(cl: f64, a: f64) -> DesignLift {
    let alpha0_a1 = -cl / (2.0 * PI);
    let ideal = if a > 0.0 && a < 1.0 {
        alpha0_a1 * a_mean_line_h(a) / (a + 1.0)
    } else {
        0.0
    };
    DesignLift {
        ideal_cl: cl,
        ideal_alpha_deg: ideal.to_degrees(),
        zero_lift_alpha_deg: (alpha0_a1 + ideal).to_degrees(),
    }
}

/// The design values of a mean line, when its definition names them (the uniform-load lines
/// of the 1- and 6-series); `None` for the others, whose values come from thin-airfoil theory
/// on their ordinates.
pub fn design_lift(mean_line: &MeanLine) -> Option<DesignLift> {
    match *mean_line {
        MeanLine::Uniform { design_cl, a } => Some(a_mean_line(design_cl, a)),
        _ => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// NACA Report 824 for a = 0.8: g = −0.0930, h = −0.3039, so for c_l,i = 1 the ideal angle
    /// is 0.3039/(2π·1.8) rad = 1.539° and the zero-lift angle −1/(2π) rad + 1.539° = −7.580°.
    #[test]
    fn a_08_mean_line_worked_by_hand() {
        assert!((a_mean_line_h(0.8) + 0.30392).abs() < 1e-4);
        let d = a_mean_line(1.0, 0.8);
        assert!((d.ideal_alpha_deg - 1.5394).abs() < 1e-3, "{d:?}");
        assert!((d.zero_lift_alpha_deg + 7.5795).abs() < 1e-3, "{d:?}");
    }

    #[test]
    fn a_1_mean_line_has_no_ideal_angle() {
        let d = a_mean_line(0.6, 1.0);
        assert_eq!(d.ideal_alpha_deg, 0.0);
        assert!((d.zero_lift_alpha_deg + 0.6 / (2.0 * PI) * 180.0 / PI).abs() < 1e-12);
    }
}
