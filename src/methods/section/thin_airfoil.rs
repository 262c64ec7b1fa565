//! Ideal angle of attack, zero-lift angle and ideal lift coefficient of the mean line by
//! thin-airfoil theory (DATCOM 4.1.1.1 defines the section zero-lift angle; the original
//! computes these in routine IDEAL, with Weber's end corrections).
//!
//! With x = (1 + cos θ)/2, thin-airfoil theory gives the zero-lift angle as
//! α₀ = −(2/π) ∫₀^π z_c/(1 − cos θ) dθ and the ideal angle (no leading-edge singularity) as a
//! similar integral of z_c·cos θ/sin²θ. Both are sampled at Weber's points with step π/N; the
//! intervals next to the trailing edge (θ < θ₄, x > 0.96) and the leading edge (θ > θ₂₈,
//! x < 0.04), where the integrands are singular, are replaced by end corrections in the
//! ordinate and the slope sum S5 there.

use std::f64::consts::PI;

use super::weber::{Grid, Terms, N, POINTS};

/// Coefficients of the end corrections (routine IDEAL; the method names no figure).
/// Ideal angle: leading-edge part, on the ordinate at ν = 28 and the slope sum at ν = 31.
const IDEAL_LE_ORDINATE: f64 = 0.3739;
const IDEAL_LE_SLOPE: f64 = 0.04745;
/// Ideal angle: trailing-edge part, on the ordinate at ν = 4 and the slope sum at ν = 1
/// (the ordinate coefficient is −0.3739).
const IDEAL_TE_ORDINATE: f64 = -0.3739;
const IDEAL_TE_SLOPE: f64 = 0.04745;
/// Zero-lift angle: trailing-edge part, on the ordinate at ν = 4 and the slope sum at ν = 1.
const ZERO_LIFT_TE_ORDINATE: f64 = -0.7834;
const ZERO_LIFT_TE_SLOPE: f64 = 0.09518;
/// First and last points of the regular parts of the sums (ν), after the end corrections.
const TE_POINT: usize = 4;
const LE_POINT: usize = N - 4;

/// The thin-airfoil values of a mean line.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct ThinAirfoil {
    pub ideal_alpha_deg: f64,
    pub zero_lift_alpha_deg: f64,
    pub ideal_cl: f64,
}

impl ThinAirfoil {
    /// The mean line's values from its ordinates and slope sums at Weber's points.
    pub fn from_terms(t: &Terms) -> ThinAirfoil {
        let g = &t.grid;
        let n = N as f64;
        let at = Grid::at;
        let zc_te = t.zc[at(TE_POINT)];
        let zc_le = t.zc[at(LE_POINT)];
        let slope_te = t.s5[at(1)];
        let slope_le = t.s5[at(POINTS)];
        // z·cos θ/(sin θ/2)², the ideal-angle integrand at point ν (index k).
        let ideal_term = |k: usize| {
            let h = g.sin[k] / 2.0;
            -t.zc[k] * g.cos[k] / (h * h)
        };
        let ends_ideal = 0.5 * (ideal_term(at(TE_POINT)) + ideal_term(at(LE_POINT)));
        let sum_ideal: f64 = (at(TE_POINT + 1)..=at(LE_POINT - 1)).map(ideal_term).sum();
        let ideal_rad = IDEAL_LE_ORDINATE * zc_le
            + IDEAL_LE_SLOPE * slope_le
            + 0.5 / n * (ends_ideal + sum_ideal)
            + IDEAL_TE_ORDINATE * zc_te
            + IDEAL_TE_SLOPE * slope_te;
        let end_zero_lift = 0.5 * zc_te / (1.0 - g.cos[at(TE_POINT)]);
        let sum_zero_lift: f64 = (at(TE_POINT + 1)..=at(POINTS))
            .map(|k| t.zc[k] / (1.0 - g.cos[k]))
            .sum();
        let zero_lift_rad = ZERO_LIFT_TE_ORDINATE * zc_te + ZERO_LIFT_TE_SLOPE * slope_te
            - 2.0 / n * (end_zero_lift + sum_zero_lift);
        ThinAirfoil {
            ideal_alpha_deg: ideal_rad.to_degrees(),
            zero_lift_alpha_deg: zero_lift_rad.to_degrees(),
            // Thin-airfoil lift slope 2π per radian.
            ideal_cl: 2.0 * PI * (ideal_rad - zero_lift_rad),
        }
    }
}
