//! Crest-critical Mach number of a section: the free-stream Mach number at which the flow at
//! the crest (the point of the upper surface tangent to the free stream) reaches sonic speed,
//! and the lift-curve slope there (the original's routine SLOPE, Mach-0 pass; the fits name no
//! DATCOM figure).
//!
//! At Mach 0 and one degree above the zero-lift angle:
//! 1. the crest is where the upper-surface slope (Weber's sums S2 + S5) falls to tan α, found
//!    between Weber's points from the leading edge aft and interpolated linearly;
//! 2. the velocity there, V/U, interpolated linearly in x, gives Cp = 1 − (V/U)²;
//! 3. M_cc = 1/(1.023 − 0.9507·Cp − 0.4140·Cp² − 0.1506·Cp³ − 0.0212·Cp⁴), the fit of the
//!    crest pressure against the Mach number at which it becomes critical;
//! 4. the slope at M_cc is a Kármán–Tsien correction of the Mach-0 slope c_lα (per degree, as
//!    the fit was made): c_lα / (β_cc − M_cc²/(1 + β_cc) · c_lα/2), β_cc = √(1 − M_cc²).

use super::weber::{Terms, POINTS};

/// Coefficients of the critical-Mach fit, constant term first (routine SLOPE).
const CRITICAL_MACH_FIT: [f64; 5] = [1.023, -0.9507, -0.4140, -0.1506, -0.0212];

/// Where and at what Mach number the crest becomes critical.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Crest {
    pub x: f64,
    pub mach: f64,
    /// Lift-curve slope at the crest-critical Mach number, per degree; `None` when the crest
    /// is critical only at Mach 1 or above, or the correction has no value.
    pub cla_per_deg: Option<f64>,
}

/// Why the crest-critical Mach number cannot be found.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum NoCrest {
    /// The upper surface is already shallower than the flow at the first point behind the
    /// leading edge (x = 0.0024), or never becomes so.
    NotLocated,
}

/// The crest-critical state from Weber's sums, the Mach-0 upper-surface velocities at
/// `alpha_deg` and the Mach-0 lift-curve slope `cla0_per_deg` (viscous-corrected).
pub(crate) fn crest_critical(
    t: &Terms,
    alpha_deg: f64,
    upper_velocity: &[f64; POINTS],
    cla0_per_deg: f64,
) -> Result<Crest, NoCrest> {
    let x = &t.grid.x;
    let tan_alpha = alpha_deg.to_radians().tan();
    // From the leading edge (last index) aft: the first point whose upper-surface slope is
    // below tan α, and the one before it.
    let slope = |k: usize| t.s2[k] + t.s5[k];
    let aft = (0..POINTS).rev().find(|&k| tan_alpha > slope(k));
    let Some(aft) = aft.filter(|&k| k + 1 < POINTS) else {
        return Err(NoCrest::NotLocated);
    };
    let fore = aft + 1;
    let xc = x[aft] + (tan_alpha - slope(aft)) / (slope(fore) - slope(aft)) * (x[fore] - x[aft]);
    // The velocity at the crest, between the points on either side of it.
    let Some(k) = (0..POINTS).find(|&k| xc > x[k]).filter(|&k| k > 0) else {
        return Err(NoCrest::NotLocated);
    };
    let v = upper_velocity[k]
        + (xc - x[k]) / (x[k - 1] - x[k]) * (upper_velocity[k - 1] - upper_velocity[k]);
    let cp = 1.0 - v * v;
    let denominator = CRITICAL_MACH_FIT
        .iter()
        .rev()
        .fold(0.0, |acc, c| acc * cp + c);
    if denominator.is_nan() || denominator <= 0.0 || !xc.is_finite() {
        return Err(NoCrest::NotLocated);
    }
    let mach = 1.0 / denominator;
    let cla_per_deg = (mach < 1.0)
        .then(|| {
            let beta = (1.0 - mach * mach).sqrt();
            let c = cla0_per_deg.abs();
            c / (beta - mach * mach / (1.0 + beta) * c / 2.0)
        })
        .filter(|c| c.is_finite() && *c > 0.0);
    Ok(Crest {
        x: xc,
        mach,
        cla_per_deg,
    })
}
