//! Section lift, pitching moment, zero-lift angle, lift-curve slope and aerodynamic centre by
//! Weber's compressible pressure distribution (DATCOM 4.1.1.1 zero-lift angle, 4.1.1.2
//! lift-curve slope, 4.1.2.1 zero-lift pitching moment, 4.1.4.1 aerodynamic centre; the
//! original's routine SLOPE).
//!
//! At each of Weber's points the surface velocity over free stream is, upper (+) and lower (−),
//!
//! V/U = [cos α·(1 + S1/B ± S4/β) ± sin α/β·(1 + S3/B)·√((1 − x)/x)] / √(1 + ((S2 ± S5)/B)²)
//!
//! with β = √(1 − M²) and a local factor B = √(1 − M²·(1 − M·Cp,t)), Cp,t = 1 − (1 + S1)²/(1 + S2²)
//! being the incompressible pressure of the thickness alone. The pressure is 1 − (V/U)² at
//! Mach 0 and the isentropic relation otherwise; lift and quarter-chord moment are the
//! pressure differences integrated over θ with Weber's weights (sin θ)/2 · π/N. There is no
//! separate Prandtl–Glauert factor and no chart: compressibility is in B, β and the isentropic
//! pressure.

use std::f64::consts::PI;

use super::weber::{Terms, N, POINTS};

/// Ratio of specific heats of air.
const GAMMA: f64 = 1.4;
/// The two angles of attack of a slope evaluation are one degree apart: the slopes are per
/// degree differences (the original's method).
pub(crate) const ALPHA_STEP_DEG: f64 = 1.0;
/// Most Newton steps on the zero-lift angle before giving up (the original has no limit; it
/// never needed more than two steps in the reference listings).
const MAX_ZERO_LIFT_STEPS: usize = 50;

/// Why the pressure distribution cannot be computed at a Mach number.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum Failure {
    /// The local compressibility factor B² is negative at point `x`: the flow there is
    /// supersonic beyond what the method represents.
    LocalFactor { x: f64 },
    /// The isentropic pressure relation has a negative base at point `x` (velocity beyond
    /// the limiting velocity).
    Isentropic { x: f64 },
    /// The zero-lift iteration did not converge (or the lift did not change with angle).
    ZeroLift,
}

impl std::fmt::Display for Failure {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Failure::LocalFactor { x } => write!(
                f,
                "the local compressibility factor of Weber's method is imaginary at x/c = {x:.4}"
            ),
            Failure::Isentropic { x } => write!(
                f,
                "the local velocity at x/c = {x:.4} exceeds the limiting velocity of the isentropic pressure relation"
            ),
            Failure::ZeroLift => write!(f, "the zero-lift angle iteration does not converge"),
        }
    }
}

/// Lift and quarter-chord pitching moment at one angle of attack, and the upper-surface
/// velocity ratios (needed for the crest-critical Mach number).
#[derive(Debug, Clone)]
pub(crate) struct Loads {
    pub alpha_deg: f64,
    pub cl: f64,
    pub cm: f64,
    pub upper_velocity: [f64; POINTS],
}

/// Pressure coefficient for a velocity ratio `v` at Mach `mach`: 1 − v² at Mach 0, else the
/// isentropic Cp = 2/(γM²)·[(1 + (γ − 1)/2·M²·(1 − v²))^(γ/(γ − 1)) − 1], written with
/// ln(1 + ·) and exp(·) − 1 so that it keeps its digits at low Mach numbers (where the
/// original, in single precision, loses three or four of them).
fn pressure(v: f64, mach: f64) -> Option<f64> {
    let dv = 1.0 - v * v;
    if mach == 0.0 {
        return Some(dv);
    }
    let m2 = mach * mach;
    let rise = 0.5 * (GAMMA - 1.0) * m2 * dv;
    (rise >= -1.0).then(|| 2.0 / (GAMMA * m2) * (GAMMA / (GAMMA - 1.0) * rise.ln_1p()).exp_m1())
}

/// Weber's pressure distribution at `alpha_deg` and `mach` (subsonic), integrated.
pub(crate) fn loads(t: &Terms, mach: f64, alpha_deg: f64) -> Result<Loads, Failure> {
    let g = &t.grid;
    let beta = (1.0 - mach * mach).sqrt();
    let (sin_a, cos_a) = alpha_deg.to_radians().sin_cos();
    let mut upper_velocity = [0.0; POINTS];
    let (mut lift, mut moment) = (0.0, 0.0);
    for (k, upper) in upper_velocity.iter_mut().enumerate() {
        let x = g.x[k];
        let (s1, s2, s3, s4, s5) = (t.s1[k], t.s2[k], t.s3[k], t.s4[k], t.s5[k]);
        let cp_thickness = 1.0 - (1.0 + s1) * (1.0 + s1) / (1.0 + s2 * s2);
        let b2 = 1.0 - mach * mach * (1.0 - mach * cp_thickness);
        if b2 < 0.0 {
            return Err(Failure::LocalFactor { x });
        }
        let b = b2.sqrt();
        let nose = sin_a / beta * (1.0 + s3 / b) * ((1.0 - x) / x).sqrt();
        let along = cos_a * (1.0 + s1 / b);
        let camber = cos_a * s4 / beta;
        let vu = (along + camber + nose) / (1.0 + ((s2 + s5) / b).powi(2)).sqrt();
        let vl = (along - camber - nose) / (1.0 + ((s2 - s5) / b).powi(2)).sqrt();
        *upper = vu;
        let cpu = pressure(vu, mach).ok_or(Failure::Isentropic { x })?;
        let cpl = pressure(vl, mach).ok_or(Failure::Isentropic { x })?;
        let weight = g.sin[k] / 2.0;
        lift -= (cpu - cpl) * weight;
        moment += (cpu - cpl) * (x - 0.25) * weight;
    }
    let n = N as f64;
    Ok(Loads {
        alpha_deg,
        cl: lift * PI / (cos_a * n),
        cm: moment * PI / n,
        upper_velocity,
    })
}

/// The section at its zero-lift angle: loads there and one degree above.
#[derive(Debug, Clone)]
pub(crate) struct ZeroLift {
    pub at: Loads,
    pub above: Loads,
}

impl ZeroLift {
    /// Inviscid lift-curve slope, per degree (difference over one degree).
    pub fn cla_per_deg(&self) -> f64 {
        (self.above.cl - self.at.cl) / ALPHA_STEP_DEG
    }

    /// Pitching-moment slope about the quarter chord, per degree.
    pub fn cma_per_deg(&self) -> f64 {
        (self.above.cm - self.at.cm) / ALPHA_STEP_DEG
    }
}

/// Newton's iteration on the angle of attack for zero lift, from `start_deg`, until the lift
/// there is within `cl_tolerance` of zero; the slope of each step is the difference over one
/// degree.
pub(crate) fn zero_lift(
    t: &Terms,
    mach: f64,
    start_deg: f64,
    cl_tolerance: f64,
) -> Result<ZeroLift, Failure> {
    let mut alpha = start_deg;
    for _ in 0..=MAX_ZERO_LIFT_STEPS {
        let at = loads(t, mach, alpha)?;
        let above = loads(t, mach, alpha + ALPHA_STEP_DEG)?;
        if at.cl.abs() <= cl_tolerance {
            return Ok(ZeroLift { at, above });
        }
        let slope = above.cl - at.cl;
        let next = alpha - at.cl / slope * ALPHA_STEP_DEG;
        if !next.is_finite() {
            return Err(Failure::ZeroLift);
        }
        alpha = next;
    }
    Err(Failure::ZeroLift)
}
