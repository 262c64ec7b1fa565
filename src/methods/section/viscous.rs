//! Viscous correction of the section lift-curve slope (DATCOM 4.1.1.2, equation
//! c_lα = 1.05/β · [c_lα/(c_lα)theory] · (c_lα)theory, with the ratio of Figure 4.1.1.2-8a as
//! a function of Reynolds number and trailing-edge angle; the original's routine SLOPE, which
//! uses a curve fit in place of the figure and names none).
//!
//! The ratio is 1 − (ln(Re/10⁵))^(−1 + 5/2·τ) · (0.232 + 1.785·τ − 2.950·τ²), at least 0.6896,
//! with τ = tan(φ_TE/2), the half-thickness slope between x ≈ 0.90 and x ≈ 0.99. The 1/β of the
//! handbook's equation is not applied here: Weber's compressible pressure distribution already
//! holds it.

/// Coefficients of the fit of Figure 4.1.1.2-8a (routine SLOPE).
const FIT_C0: f64 = 0.232;
const FIT_C1: f64 = 1.785;
const FIT_C2: f64 = 2.950;
/// Exponent of ln(Re/10⁵): −1 + FIT_EXP_SLOPE·τ.
const FIT_EXP_SLOPE: f64 = 2.5;
/// Reference Reynolds number of the fit.
const FIT_RE_REF: f64 = 1.0e5;
/// Smallest ratio the fit gives.
const FIT_MIN_RATIO: f64 = 0.6896;
/// Empirical factor of equation 4.1.1.2-a.
pub(crate) const EMPIRICAL_FACTOR: f64 = 1.05;

/// Lowest Reynolds number the fit is used at: e·10⁵, where ln(Re/10⁵) = 1. Below it the fit's
/// power of a logarithm under 1 grows without bound, so the section is computed at this value
/// with a warning. (The original tests against 2.71828E5 but substitutes 2.7182E5.)
pub const MIN_REYNOLDS_NUMBER: f64 = std::f64::consts::E * FIT_RE_REF;

/// c_lα/(c_lα)theory at Reynolds number `reynolds` (already at least
/// [`MIN_REYNOLDS_NUMBER`]) for a trailing edge of half-angle tangent `tan_half_te`.
pub(crate) fn lift_curve_slope_ratio(reynolds: f64, tan_half_te: f64) -> f64 {
    let t = tan_half_te;
    let exponent = -1.0 + FIT_EXP_SLOPE * t;
    let ratio =
        1.0 - (reynolds / FIT_RE_REF).ln().powf(exponent) * (FIT_C0 + FIT_C1 * t - FIT_C2 * t * t);
    ratio.max(FIT_MIN_RATIO)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Worked by hand: τ = 0.1 at Re = 10⁶: ln 10 = 2.302585, exponent −0.75,
    /// 2.302585^−0.75 = exp(−0.75·0.834032) = 0.534981; bracket 0.232 + 0.1785 − 0.0295 = 0.381;
    /// ratio 1 − 0.203828 = 0.796172.
    #[test]
    fn ratio_worked_by_hand() {
        assert!((lift_curve_slope_ratio(1.0e6, 0.1) - 0.796172).abs() < 1e-6);
    }

    #[test]
    fn ratio_is_floored() {
        assert_eq!(
            lift_curve_slope_ratio(MIN_REYNOLDS_NUMBER, 0.3),
            FIT_MIN_RATIO
        );
    }
}
