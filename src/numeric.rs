//! Small numerical rules shared by the methods: the trapezoidal integral and the slopes of a
//! curve given at its nodes, as the original program takes them (routines TRAPZ and TBFUNX's
//! derivative from the parabola through three nodes); and how a number is rounded for a
//! person to read.

/// Trapezoidal integral of `f` over `x`.
pub fn trapezoid(x: &[f64], f: &[f64]) -> f64 {
    x.windows(2)
        .zip(f.windows(2))
        .map(|(x, f)| 0.5 * (x[1] - x[0]) * (f[1] + f[0]))
        .sum()
}

/// Slope at `at` of the parabola through three points; `None` when two abscissae coincide.
pub fn parabola_slope(x: [f64; 3], y: [f64; 3], at: f64) -> Option<f64> {
    let d01 = x[0] - x[1];
    let d02 = x[0] - x[2];
    let d12 = x[1] - x[2];
    if d01 == 0.0 || d02 == 0.0 || d12 == 0.0 {
        return None;
    }
    let s = y[0] * ((at - x[1]) + (at - x[2])) / (d01 * d02)
        - y[1] * ((at - x[0]) + (at - x[2])) / (d01 * d12)
        + y[2] * ((at - x[0]) + (at - x[1])) / (d02 * d12);
    s.is_finite().then_some(s)
}

/// Slope of the curve `f(α)` at each of its angles (`alpha_rad`, radians), per radian: the
/// parabola through the angle and its neighbours, through the first or last three at the ends;
/// the chord for two angles, zero for one. `None` where a point it needs is `None`.
pub fn curve_slopes(alpha_rad: &[f64], f: &[Option<f64>]) -> Vec<Option<f64>> {
    let n = alpha_rad.len().min(f.len());
    (0..n)
        .map(|k| match n {
            1 => f[0].map(|_| 0.0),
            2 => {
                let h = alpha_rad[1] - alpha_rad[0];
                let (a, b) = (f[0]?, f[1]?);
                (h != 0.0).then(|| (b - a) / h)
            }
            _ => {
                let j = k.clamp(1, n - 2);
                parabola_slope(
                    [alpha_rad[j - 1], alpha_rad[j], alpha_rad[j + 1]],
                    [f[j - 1]?, f[j]?, f[j + 1]?],
                    alpha_rad[k],
                )
            }
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rounding_to_significant_digits_is_the_decimal_rounding_of_the_exact_value() {
        // 2.3375 is stored a little below itself: its four digits are 2.337, where scaling by
        // 1000 and rounding would give 2.338.
        assert!(format!("{:.20}", 2.3375_f64).starts_with("2.33749"));
        assert_eq!(round_significant(2.3375, 4), Some(2.337));
        assert_eq!(round_significant(0.10533802696765625, 4), Some(0.1053));
        assert_eq!(round_significant(123.456789, 8), Some(123.45679));
        assert_eq!(round_significant(f64::MAX, 4), None);
        assert_eq!(round_significant(f64::NAN, 4), None);
    }

    /// At 0° the body axes are the wind axes; at 90° lift is axial (negative) and drag normal;
    /// CN = 0 gives no centre of pressure; a missing CL or CD gives no CN or CA.
    #[test]
    fn body_axes_by_hand() {
        let alpha = [0.0, std::f64::consts::FRAC_PI_2, 0.0, 0.0];
        let cl = [Some(0.5), Some(0.5), Some(0.0), None];
        let cd = [Some(0.02), Some(0.02), Some(0.0), Some(0.02)];
        let cm = [Some(-0.1), Some(-0.1), Some(-0.1), Some(-0.1)];
        let a = body_axes(&alpha, &cl, &cd, &cm);
        // Only the rounding of sin, cos and the products separates these from the hand values.
        const ROUNDING: f64 = 1e-12;
        let close = |x: Option<f64>, y: f64| (x.unwrap() - y).abs() < ROUNDING;
        assert!(close(a.cn[0], 0.5) && close(a.ca[0], 0.02) && close(a.xcp[0], -0.2));
        assert!(close(a.cn[1], 0.02) && close(a.ca[1], -0.5) && close(a.xcp[1], -5.0));
        assert_eq!(a.xcp[2], None);
        assert_eq!((a.cn[3], a.ca[3], a.xcp[3]), (None, None, None));
    }

    #[test]
    fn slopes_of_a_parabola_are_exact() {
        // f = α² has slope 2α at every node, also at the ends (one parabola fits all).
        let a = [0.0, 0.1, 0.25, 0.4];
        let f: Vec<Option<f64>> = a.iter().map(|x| Some(x * x)).collect();
        for (s, x) in curve_slopes(&a, &f).iter().zip(a) {
            assert!((s.unwrap() - 2.0 * x).abs() < 1e-12);
        }
        assert_eq!(
            curve_slopes(&[0.0, 1.0], &[Some(1.0), Some(3.0)]),
            vec![Some(2.0); 2]
        );
        assert_eq!(curve_slopes(&[0.0], &[Some(1.0)]), vec![Some(0.0)]);
        assert_eq!(trapezoid(&[0.0, 1.0, 3.0], &[1.0, 1.0, 1.0]), 3.0);
    }
}

/// Coefficients resolved into body axes at each angle of attack.
#[derive(Debug, Clone, PartialEq)]
pub struct BodyAxes {
    /// Normal force CN = CL cos α + CD sin α.
    pub cn: Vec<Option<f64>>,
    /// Axial force CA = CD cos α − CL sin α.
    pub ca: Vec<Option<f64>>,
    /// Centre of pressure CM/CN in reference lengths (none where CN = 0).
    pub xcp: Vec<Option<f64>>,
}

/// CN, CA and CM/CN from CL, CD and CM at the angles `alpha_rad` (the columns every
/// configuration page prints); a value that is not finite is none.
pub fn body_axes(
    alpha_rad: &[f64],
    cl: &[Option<f64>],
    cd: &[Option<f64>],
    cm: &[Option<f64>],
) -> BodyAxes {
    let n = alpha_rad.len();
    let mut axes = BodyAxes {
        cn: Vec::with_capacity(n),
        ca: Vec::with_capacity(n),
        xcp: Vec::with_capacity(n),
    };
    for (k, alpha) in alpha_rad.iter().enumerate() {
        let (s, c) = alpha.sin_cos();
        let (lift, drag, moment) = (
            cl.get(k).copied().flatten(),
            cd.get(k).copied().flatten(),
            cm.get(k).copied().flatten(),
        );
        let (normal, axial) = match (lift, drag) {
            (Some(l), Some(d)) => (Some(l * c + d * s), Some(d * c - l * s)),
            _ => (None, None),
        };
        axes.cn.push(normal.filter(|v| v.is_finite()));
        axes.ca.push(axial.filter(|v| v.is_finite()));
        axes.xcp.push(match (moment, normal) {
            (Some(m), Some(nf)) if nf != 0.0 => Some(m / nf).filter(|v| v.is_finite()),
            _ => None,
        });
    }
    axes
}

/// The values that are finite; the others become none.
pub fn finite_only(v: Vec<Option<f64>>) -> Vec<Option<f64>> {
    v.into_iter().map(|x| x.filter(|y| y.is_finite())).collect()
}

/// `v` rounded to `digits` significant decimal digits (the decimal rounding of its exact value,
/// as `{:e}` formatting with that precision gives it); none when the rounding leaves the finite
/// numbers (or `v` is not finite).
pub fn round_significant(v: f64, digits: usize) -> Option<f64> {
    let r: f64 = format!("{v:.*e}", digits.saturating_sub(1)).parse().ok()?;
    r.is_finite().then_some(r)
}
