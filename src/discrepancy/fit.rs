//! Weighted non-linear least squares by Levenberg–Marquardt (nalgebra), with the parameter
//! covariance at the solution. The residuals are already weighted (divided by their noise), so
//! the sum of squares is a χ²; the covariance is scaled by the reduced χ² (χ²/(n − p)) because
//! the noise is often estimated from the data rather than known.

use nalgebra::{DMatrix, DVector};
use serde::Serialize;

/// Largest number of Levenberg–Marquardt iterations.
pub const MAX_ITERATIONS: usize = 200;
/// Relative decrease of χ² below which the fit has converged.
const CONVERGED_DECREASE: f64 = 1e-12;
/// Relative step of the finite-difference Jacobian (on the parameter's scale).
const JACOBIAN_STEP: f64 = 1e-6;
/// Singular values below this fraction of the largest are dropped in the covariance.
const PSEUDO_INVERSE_EPS: f64 = 1e-12;

/// Why the iteration stopped.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Termination {
    Converged,
    MaxIterations,
    /// No step lowered χ² however small (a flat or singular problem).
    NoImprovement,
}

/// A least-squares solution.
#[derive(Debug, Clone, PartialEq)]
pub struct Fit {
    pub parameters: Vec<f64>,
    /// Standard errors of the parameters (from the scaled covariance); NaN where the data
    /// carry no information on a parameter.
    pub standard_errors: Vec<f64>,
    /// Correlation of the parameters (p × p).
    pub correlation: DMatrix<f64>,
    /// Σ r² of the weighted residuals.
    pub chi_square: f64,
    pub residual_count: usize,
    pub iterations: usize,
    pub termination: Termination,
}

/// Σ r², or none when a residual is not finite.
fn sum_of_squares(r: &[f64]) -> Option<f64> {
    let s: f64 = r.iter().map(|x| x * x).sum();
    s.is_finite().then_some(s)
}

fn jacobian<F>(residuals: &F, at: &[f64], r0: &[f64], scales: &[f64]) -> Option<DMatrix<f64>>
where
    F: Fn(&[f64]) -> Option<Vec<f64>>,
{
    let (n, p) = (r0.len(), at.len());
    let mut j = DMatrix::zeros(n, p);
    let mut shifted = at.to_vec();
    for k in 0..p {
        let h = JACOBIAN_STEP * at[k].abs().max(scales[k]);
        shifted[k] = at[k] + h;
        let r = residuals(&shifted)?;
        shifted[k] = at[k];
        if r.len() != n {
            return None;
        }
        for i in 0..n {
            j[(i, k)] = (r[i] - r0[i]) / h;
        }
    }
    Some(j)
}

/// Minimises Σ r(θ)² from `start`; `scales` gives each parameter's typical size (for the
/// finite differences). `residuals` returns none where it cannot be evaluated (a diverged
/// simulation): such a step is refused. None when the start itself cannot be evaluated.
pub fn levenberg_marquardt<F>(residuals: F, start: &[f64], scales: &[f64]) -> Option<Fit>
where
    F: Fn(&[f64]) -> Option<Vec<f64>>,
{
    let p = start.len();
    let mut theta = start.to_vec();
    let mut r = residuals(&theta)?;
    let mut chi = sum_of_squares(&r)?;
    let n = r.len();
    let mut lambda = 1e-3;
    let mut iterations = 0;
    let mut termination = Termination::MaxIterations;
    if p == 0 {
        termination = Termination::Converged;
    }
    while p > 0 && iterations < MAX_ITERATIONS {
        iterations += 1;
        let j = jacobian(&residuals, &theta, &r, scales)?;
        let jt = j.transpose();
        let a = &jt * &j;
        let g = &jt * DVector::from_column_slice(&r);
        let mut improved = false;
        while lambda < 1e12 {
            let mut damped = a.clone();
            for k in 0..p {
                damped[(k, k)] += lambda * a[(k, k)].max(1e-12);
            }
            let Some(step) = damped.lu().solve(&(-&g)) else {
                lambda *= 10.0;
                continue;
            };
            let trial: Vec<f64> = theta.iter().zip(step.iter()).map(|(t, s)| t + s).collect();
            match residuals(&trial).and_then(|rt| Some((sum_of_squares(&rt)?, rt))) {
                Some((c, rt)) if c < chi => {
                    let decrease = (chi - c) / chi.max(f64::MIN_POSITIVE);
                    theta = trial;
                    r = rt;
                    chi = c;
                    lambda = (lambda / 10.0).max(1e-12);
                    improved = true;
                    if decrease < CONVERGED_DECREASE {
                        termination = Termination::Converged;
                    }
                    break;
                }
                _ => lambda *= 10.0,
            }
        }
        if !improved {
            termination = if iterations > 1 {
                Termination::Converged
            } else {
                Termination::NoImprovement
            };
            break;
        }
        if termination == Termination::Converged {
            break;
        }
    }
    let (standard_errors, correlation) = match jacobian(&residuals, &theta, &r, scales) {
        Some(j) if p > 0 => {
            let a = j.transpose() * &j;
            // The residuals are weighted by the noise, so (JᵀJ)⁻¹ is the covariance when the
            // noise is right; a larger reduced χ² (a misfit, or noise underestimated) widens
            // it, a smaller one does not narrow it.
            let scale = if n > p {
                (chi / (n - p) as f64).max(1.0)
            } else {
                1.0
            };
            let inverse = a
                .clone()
                .pseudo_inverse(PSEUDO_INVERSE_EPS * a.amax().max(f64::MIN_POSITIVE))
                .unwrap_or_else(|_| DMatrix::zeros(p, p));
            let cov = inverse * scale;
            // A direction the pseudo-inverse dropped (no information in the data) has no
            // standard error: NaN, never 0.
            let se: Vec<f64> = (0..p)
                .map(|k| {
                    let v = cov[(k, k)];
                    if v.is_finite() && v > 0.0 {
                        v.sqrt()
                    } else {
                        f64::NAN
                    }
                })
                .collect();
            let corr = DMatrix::from_fn(p, p, |a, b| {
                let d = se[a] * se[b];
                if d > 0.0 {
                    cov[(a, b)] / d
                } else if a == b {
                    1.0
                } else {
                    0.0
                }
            });
            (se, corr)
        }
        _ => (vec![f64::NAN; p], DMatrix::identity(p, p)),
    };
    Some(Fit {
        parameters: theta,
        standard_errors,
        correlation,
        chi_square: chi,
        residual_count: n,
        iterations,
        termination,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A straight line y = 2 + 3x with known residuals: the least-squares solution and its
    /// standard errors are the textbook ones (worked here by the normal equations).
    #[test]
    fn a_line_is_fitted_as_the_normal_equations_give() {
        let x = [0.0, 1.0, 2.0, 3.0, 4.0];
        let noise = [0.1, -0.1, 0.05, 0.0, -0.05];
        let y: Vec<f64> = x
            .iter()
            .zip(noise)
            .map(|(x, e)| 2.0 + 3.0 * x + e)
            .collect();
        let f = |t: &[f64]| -> Option<Vec<f64>> {
            Some(x.iter().zip(&y).map(|(x, y)| t[0] + t[1] * x - y).collect())
        };
        let fit = levenberg_marquardt(f, &[0.0, 0.0], &[1.0, 1.0]).unwrap();
        // Normal equations: slope = Sxy/Sxx, intercept = ȳ − slope x̄.
        let xm = 2.0;
        let ym: f64 = y.iter().sum::<f64>() / 5.0;
        let sxx: f64 = x.iter().map(|x| (x - xm) * (x - xm)).sum();
        let sxy: f64 = x.iter().zip(&y).map(|(x, y)| (x - xm) * (y - ym)).sum();
        let slope = sxy / sxx;
        approx::assert_relative_eq!(fit.parameters[1], slope, max_relative = 1e-6);
        approx::assert_relative_eq!(fit.parameters[0], ym - slope * xm, max_relative = 1e-6);
        // SE(slope) = s/√Sxx with s² = max(1, RSS/(n − 2)) (unit-weight residuals).
        let s2 = (fit.chi_square / 3.0).max(1.0);
        approx::assert_relative_eq!(
            fit.standard_errors[1],
            (s2 / sxx).sqrt(),
            max_relative = 1e-4
        );
    }

    #[test]
    fn a_residual_that_cannot_be_evaluated_at_the_start_gives_none() {
        let f = |_: &[f64]| -> Option<Vec<f64>> { None };
        assert!(levenberg_marquardt(f, &[1.0], &[1.0]).is_none());
    }
}
