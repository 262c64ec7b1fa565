//! The discrepancy workflow: compare a prediction with measurements, find where they disagree,
//! name the missing physical effect from a catalogue, add it to the model and show the gap
//! shrink (docs/discrepancy.md).
//!
//! - [`effects`]: the catalogue of named effects, each a parametric change of CL, CD, Cm.
//! - [`data`]: the CSV tables (measurements, predictions) and a noise estimate.
//! - [`fit`]: weighted least squares (Levenberg–Marquardt) with parameter covariance.
//! - [`analyse_static`]: residuals with their significance, stepwise selection of effects by
//!   the Bayesian information criterion, fit with 95 % intervals, held-out validation.
//! - [`flight`]: a longitudinal flight simulation driven by the prediction, and output-error
//!   fitting of the same effects to a recorded time history.
//! - [`synthetic`]: the generators of synthetic data the tests use.

pub mod data;
pub mod effects;
pub mod fit;
pub mod flight;
pub mod plot;
pub mod prediction;
pub mod synthetic;

use std::collections::BTreeMap;

use serde::Serialize;
use thiserror::Error;

pub use data::Measurement;
pub use effects::{apply, Coefficient, Coefficients, EffectId, Prediction};

/// What went wrong.
#[derive(Debug, Clone, PartialEq, Error)]
#[non_exhaustive]
pub enum DiscrepancyError {
    #[error("{file}:{line}: cannot read the CSV: {reason}")]
    Csv {
        file: String,
        line: usize,
        reason: String,
    },
    #[error("{file}: no column {column} (the header has: {found})")]
    MissingColumn {
        file: String,
        column: String,
        found: String,
    },
    #[error("{file}:{line}: column {column}: expected a finite number, found {text:?}")]
    BadNumber {
        file: String,
        line: usize,
        column: String,
        text: String,
    },
    #[error("{reason}")]
    Invalid { reason: String },
    #[error("{file}: not a prediction: {reason}; --predicted reads a prediction table (columns alpha_deg, CL, CD, Cm, optional CL_tail, Cm_tail; docs/discrepancy.md) or the CSV that `datcom-rs run --format csv` writes (columns case, condition, alpha, CL, CD, CM); a deck is given with --model")]
    NotAPrediction { file: String, reason: String },
    #[error("the model gives no prediction: {reason}")]
    NoPrediction { reason: String },
    #[error("no measured point lies within the prediction's angles of attack ({from} to {to} deg) with beta 0 and CL, CD or Cm")]
    NoOverlap { from: f64, to: f64 },
}

/// How the selection decides.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Options {
    /// An effect is added when it lowers the Bayesian information criterion
    /// BIC = χ² + k ln n by more than this (10: "very strong" evidence on the scale
    /// of Kass and Raftery, 1995; keeps false alarms on noise-only data near 0.1 % per
    /// candidate).
    pub min_bic_drop: f64,
    /// Two candidates whose BICs differ by less than this, both passing, are confounded:
    /// reported as such and not chosen between (2: "not worth more than a bare mention").
    pub confound_bic: f64,
    /// Every k-th point (in alpha order) is held out of the selection and fit, to validate.
    pub holdout_every: usize,
    /// At most this many effects (and never more parameters than half the residuals).
    pub max_effects: usize,
    /// Rows with |beta| at most this (deg) count as beta = 0 for the longitudinal fit.
    pub beta_zero_deg: f64,
    /// The candidates (default: the whole catalogue).
    pub candidates: Vec<EffectId>,
    /// Only measured angles of attack within this range (deg) are compared (e.g. the attached
    /// flow below stall, where DATCOM's methods hold); all when none.
    pub alpha_range_deg: Option<(f64, f64)>,
}

impl Default for Options {
    fn default() -> Self {
        Options {
            min_bic_drop: 10.0,
            confound_bic: 2.0,
            holdout_every: 4,
            max_effects: EffectId::ALL.len(),
            beta_zero_deg: 0.5,
            candidates: EffectId::ALL.to_vec(),
            alpha_range_deg: None,
        }
    }
}

/// Why an effect was added.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Evidence {
    /// Fall of BIC when the effect was added (on the training points).
    pub bic_drop: f64,
    /// Partial F statistic of the added parameters: ((RSS₀ − RSS₁)/k)/(RSS₁/(n − p)), p
    /// counting every fitted parameter; none for an exact fit (RSS₁ = 0).
    pub partial_f: Option<f64>,
    pub rss_before: f64,
    pub rss_after: f64,
    /// Weighted residuals in the fit.
    pub residuals: usize,
}

/// A chosen effect with its parameters fitted on every point and their 95 % intervals.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ChosenEffect {
    pub id: EffectId,
    pub parameters: BTreeMap<String, f64>,
    pub ci95: BTreeMap<String, [f64; 2]>,
    pub evidence: Evidence,
    pub description: &'static str,
}

/// The residuals of one coefficient over one range of angles.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ResidualBin {
    pub coefficient: String,
    pub alpha_from_deg: f64,
    pub alpha_to_deg: f64,
    pub points: usize,
    /// Mean of measured − predicted.
    pub mean: f64,
    pub rms: f64,
    /// The noise standard deviation used.
    pub sigma: f64,
    /// mean/(σ/√n).
    pub z: f64,
    /// |z| > [`SIGNIFICANT_Z`].
    pub significant: bool,
}

/// A bin's mean residual is significant beyond this many standard errors (3: a 0.3 % chance
/// for noise alone).
pub const SIGNIFICANT_Z: f64 = 3.0;

/// The result of the workflow (its JSON is the CLI's `--json`).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Analysis {
    /// In the order they were added; empty when nothing is missing.
    pub effects: Vec<ChosenEffect>,
    /// RMS of measured − predicted per coefficient, over every point, before and after.
    pub rms_before: BTreeMap<String, f64>,
    pub rms_after: BTreeMap<String, f64>,
    /// Groups of effects that explain the data equally well (not chosen between).
    pub confounded: Vec<Vec<EffectId>>,
    /// RMS on the held-out points, prediction and corrected model (fitted without them).
    pub validation_rms_before: BTreeMap<String, f64>,
    pub validation_rms_after: BTreeMap<String, f64>,
    pub residuals: Vec<ResidualBin>,
    /// Noise standard deviation per coefficient, and where it came from.
    pub sigma: BTreeMap<String, f64>,
    pub sigma_source: BTreeMap<String, String>,
    /// How effects are chosen, with the threshold's value.
    pub criterion: String,
    /// Every step of the selection with each candidate's fall of BIC.
    pub selection: Vec<Step>,
    pub warnings: Vec<String>,
}

/// Fewer measured angles than this are all used for the fit (holding a quarter out would
/// leave too few to select and fit effects); the validation is then not made.
pub const MIN_POINTS_TO_HOLD_OUT: usize = 12;

/// One longitudinal point of the fit.
#[derive(Debug, Clone, PartialEq)]
struct Point {
    alpha_deg: f64,
    /// Measured CL, CD, Cm (none where not measured).
    measured: [Option<f64>; 3],
    /// Their noise: the row's `sigma_<coef>` where given, else the coefficient's.
    sigma: [f64; 3],
}

const LONGITUDINAL: [&str; 3] = ["CL", "CD", "Cm"];

fn pick(c: &Coefficients, k: usize) -> f64 {
    match k {
        0 => c.cl,
        1 => c.cd,
        _ => c.cm,
    }
}

/// Weighted residuals (model − measured)/σ of `points` under `effects`.
fn static_residuals(
    prediction: &Prediction,
    points: &[&Point],
    effects: &[(EffectId, &[f64])],
) -> Option<Vec<f64>> {
    let mut r = Vec::with_capacity(points.len() * 3);
    for p in points {
        let c = apply(prediction, effects, p.alpha_deg)?;
        for (k, s) in p.sigma.iter().enumerate() {
            if let Some(m) = p.measured[k] {
                r.push((pick(&c, k) - m) / s);
            }
        }
    }
    Some(r)
}

/// A model: effects with their parameters.
pub type Model = Vec<(EffectId, Vec<f64>)>;

fn as_refs(model: &Model) -> Vec<(EffectId, &[f64])> {
    model.iter().map(|(e, p)| (*e, p.as_slice())).collect()
}

/// Splits a flat parameter vector over the effects of `ids`.
fn unflatten(ids: &[EffectId], flat: &[f64]) -> Model {
    let mut out = Vec::with_capacity(ids.len());
    let mut k = 0;
    for id in ids {
        let n = id.parameters().len();
        out.push((*id, flat[k..k + n].to_vec()));
        k += n;
    }
    out
}

/// Parameters fitted in every model besides the effects' (e.g. a flight's initial state),
/// with their starting values and typical sizes; none for static data.
#[derive(Debug, Clone, PartialEq, Default)]
pub(crate) struct Nuisance {
    pub start: Vec<f64>,
    pub scales: Vec<f64>,
}

/// The fitted model of `ids` from `start` (the nuisance parameters, then the effects' flat),
/// with its fit (parameters in the same order).
pub(crate) fn fit_model<F>(
    residuals: &F,
    ids: &[EffectId],
    start: &[f64],
    nuisance: &Nuisance,
) -> Option<fit::Fit>
where
    F: Fn(&Model, &[f64]) -> Option<Vec<f64>>,
{
    let nn = nuisance.scales.len();
    let scales: Vec<f64> = nuisance
        .scales
        .iter()
        .copied()
        .chain(ids.iter().flat_map(|e| e.scales()))
        .collect();
    fit::levenberg_marquardt(
        |flat: &[f64]| residuals(&unflatten(ids, &flat[nn..]), &flat[..nn]),
        start,
        &scales,
    )
}

/// Starting points for a candidate's own parameters: nominal, or for the stall onset a few
/// onset angles over the upper part of the data.
fn starts(id: EffectId, alphas: &[f64]) -> Vec<Vec<f64>> {
    match id {
        EffectId::StallOnset => {
            let (lo, hi) = alphas
                .iter()
                .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), x| {
                    (a.min(*x), b.max(*x))
                });
            (1..=5)
                .map(|k| vec![lo + (hi - lo) * (0.3 + 0.12 * f64::from(k)), 0.001, 0.0])
                .collect()
        }
        EffectId::LiftSlopeScale | EffectId::TailEfficiency => vec![vec![0.95]],
        EffectId::ZeroLiftShift => vec![vec![0.5]],
        _ => vec![id.nominal()],
    }
}

/// Whether the candidate `id` (the last effect of `fit`) differs from no effect at all: its
/// amplitude parameter (every parameter but the stall onset's angle) lies outside the 95 %
/// interval around its nominal value, |θ − θ₀| > 1.96 SE with the covariance scaled by the
/// reduced χ² (so that a misfit the model cannot explain widens the interval). An effect
/// whose interval contains "no effect" is not named, however much it lowers χ².
fn departs_from_nominal(id: EffectId, fit: &fit::Fit) -> bool {
    let p = id.parameters().len();
    let first = fit.parameters.len() - p;
    let nominal = id.nominal();
    (0..p)
        .filter(|&j| !(id == EffectId::StallOnset && j == 0))
        .any(|j| {
            let (v, se) = (fit.parameters[first + j], fit.standard_errors[first + j]);
            // An unidentifiable parameter (no information in the data) has no finite,
            // positive standard error: it does not depart.
            se.is_finite() && se > 0.0 && (v - nominal[j]).abs() > Z95 * se
        })
}

/// Two effects whose fitted parameters correlate beyond this are confounded on the data (the
/// data cannot tell them apart: their estimates trade off against each other).
pub const CONFOUNDED_CORRELATION: f64 = 0.95;

/// The effect of `chosen` whose parameters correlate with `new`'s beyond
/// [`CONFOUNDED_CORRELATION`] in `fit` (parameters: `nn` nuisance, then `chosen`'s, then
/// `new`'s).
fn confounded_with(
    chosen: &[EffectId],
    new: EffectId,
    fit: &fit::Fit,
    nn: usize,
) -> Option<EffectId> {
    let start_new = nn + chosen.iter().map(|e| e.parameters().len()).sum::<usize>();
    let mut k = nn;
    for id in chosen {
        for a in k..k + id.parameters().len() {
            for b in start_new..start_new + new.parameters().len() {
                if fit.correlation[(a, b)].abs() > CONFOUNDED_CORRELATION {
                    return Some(*id);
                }
            }
        }
        k += id.parameters().len();
    }
    None
}

/// A stall onset needs this many measured angles beyond it: its curvature (and the onset
/// itself) is not identifiable from fewer.
pub const MIN_ANGLES_PAST_STALL_ONSET: usize = 3;

/// Whether a fitted effect is physically admissible on data spanning `alphas`: a stall onset
/// inside the upper half of the measured angles, with at least
/// [`MIN_ANGLES_PAST_STALL_ONSET`] of them beyond it and a loss (not a gain) of lift, a positive
/// lift-slope scale and a non-negative tail efficiency. Outside, the effect's shape is only a
/// generic curve fit (a "stall" below the data is a quadratic in alpha) and it is not offered.
fn admissible(id: EffectId, p: &[f64], alphas: &[f64]) -> bool {
    let (lo, hi) = alphas
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), x| {
            (a.min(*x), b.max(*x))
        });
    match id {
        EffectId::StallOnset => {
            let above = alphas.iter().filter(|a| **a > p[0]).count();
            p[0] >= 0.5 * (lo + hi) && above >= MIN_ANGLES_PAST_STALL_ONSET && p[1] > 0.0
        }
        EffectId::LiftSlopeScale => p[0] > 0.0,
        EffectId::TailEfficiency => p[0] >= 0.0,
        _ => true,
    }
}

/// The outcome of a stepwise selection.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Selection {
    pub model: Model,
    /// The nuisance parameters fitted with the model.
    pub nuisance: Vec<f64>,
    pub evidence: Vec<Evidence>,
    pub confounded: Vec<Vec<EffectId>>,
    pub trace: Vec<Step>,
}

/// One step of the selection: every candidate tried and how much it lowered BIC (negative:
/// raised it), best first.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Step {
    pub candidates: Vec<Tried>,
}

/// A candidate tried at a step.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Tried {
    pub effect: EffectId,
    /// Fall of BIC with the candidate added (negative: it rises).
    pub bic_drop: f64,
    /// Its amplitude lies outside the 95 % interval around "no effect"; only such candidates
    /// can be chosen.
    pub departs_from_nominal: bool,
}

/// The Bayesian information criterion of a fit with χ² = Σ((model − measured)/σ)² over `n`
/// residuals and `k` parameters, the noise σ known (given, or estimated from the data's own
/// scatter before any model is fitted): −2 ln L + k ln n = χ² + k ln n up to a constant.
/// With the noise known, an effect that removes a gap in one coefficient counts in full even
/// where another coefficient's gap remains (with the noise scale fitted, n ln(RSS/n), the
/// larger gap would hide it).
fn bic(chi_square: f64, n: usize, k: usize) -> f64 {
    chi_square + k as f64 * (n as f64).ln()
}

/// Forward stepwise selection by BIC (see [`Options`]): at each step every remaining
/// candidate is fitted together with the effects already chosen (all parameters free); the
/// one with the lowest BIC is added when it lowers BIC by more than `min_bic_drop`, unless a
/// runner-up passes too and lies within `confound_bic` of it: then both are reported as
/// confounded and the selection stops.
pub(crate) fn stepwise<F>(
    residuals: &F,
    candidates: &[EffectId],
    alphas: &[f64],
    nuisance: &Nuisance,
    options: &Options,
) -> Option<Selection>
where
    F: Fn(&Model, &[f64]) -> Option<Vec<f64>>,
{
    let nn = nuisance.scales.len();
    let mut model: Model = Vec::new();
    let base_fit = fit_model(residuals, &[], &nuisance.start, nuisance)?;
    let mut current_nuisance = base_fit.parameters.clone();
    let n = base_fit.residual_count;
    let mut rss = base_fit.chi_square;
    let mut current_bic = bic(rss, n, 0);
    let mut evidence = Vec::new();
    let mut confounded = Vec::new();
    let mut trace = Vec::new();
    // Candidates set aside as confounded are not tried again; the selection goes on with the
    // others (a gap in another coefficient is still looked for).
    let mut set_aside: Vec<EffectId> = Vec::new();
    while model.len() < options.max_effects {
        let ids: Vec<EffectId> = model.iter().map(|(e, _)| *e).collect();
        let base: Vec<f64> = model.iter().flat_map(|(_, p)| p.clone()).collect();
        let mut trials: Vec<(EffectId, fit::Fit)> = Vec::new();
        let used: usize = ids.iter().map(|e| e.parameters().len()).sum();
        for c in candidates
            .iter()
            .filter(|c| !ids.contains(c) && !set_aside.contains(c))
            .filter(|c| 2 * (nn + used + c.parameters().len()) <= n)
        {
            let mut with: Vec<EffectId> = ids.clone();
            with.push(*c);
            let best = starts(*c, alphas)
                .into_iter()
                .filter_map(|s| {
                    let start: Vec<f64> = current_nuisance
                        .iter()
                        .chain(&base)
                        .copied()
                        .chain(s)
                        .collect();
                    fit_model(residuals, &with, &start, nuisance)
                })
                .filter(|f| {
                    unflatten(&with, &f.parameters[nn..])
                        .iter()
                        .all(|(id, p)| admissible(*id, p, alphas))
                })
                .min_by(|a, b| a.chi_square.total_cmp(&b.chi_square));
            if let Some(f) = best {
                trials.push((*c, f));
            }
        }
        let k_of = |id: EffectId| -> usize {
            ids.iter().map(|e| e.parameters().len()).sum::<usize>() + id.parameters().len()
        };
        let mut all: Vec<(f64, EffectId, fit::Fit)> = trials
            .into_iter()
            .map(|(id, f)| (bic(f.chi_square, n, k_of(id)), id, f))
            .collect();
        all.sort_by(|a, b| a.0.total_cmp(&b.0));
        trace.push(Step {
            candidates: all
                .iter()
                .map(|(b, id, f)| Tried {
                    effect: *id,
                    bic_drop: current_bic - b,
                    departs_from_nominal: departs_from_nominal(*id, f),
                })
                .collect(),
        });
        let scored: Vec<(f64, EffectId, fit::Fit)> = all
            .into_iter()
            .filter(|(_, id, f)| departs_from_nominal(*id, f))
            .collect();
        let Some((best_bic, best_id, best_fit)) = scored.first().cloned() else {
            break;
        };
        if current_bic - best_bic <= options.min_bic_drop {
            break;
        }
        if let Some((runner_bic, runner_id, _)) = scored.get(1) {
            if current_bic - runner_bic > options.min_bic_drop
                && runner_bic - best_bic < options.confound_bic
            {
                confounded.push(vec![best_id, *runner_id]);
                set_aside.extend([best_id, *runner_id]);
                continue;
            }
        }
        // A new effect whose estimate is nearly a copy of an effect already chosen (their
        // parameters correlate beyond CONFOUNDED_CORRELATION) is confounded with it on these
        // data: reported, not added.
        if let Some(other) = confounded_with(&ids, best_id, &best_fit, nn) {
            confounded.push(vec![other, best_id]);
            set_aside.push(best_id);
            continue;
        }
        let p_total = best_fit.parameters.len();
        let k_new = best_id.parameters().len();
        let rss_after = best_fit.chi_square;
        let partial_f = (n > p_total && rss_after > 0.0)
            .then(|| ((rss - rss_after) / k_new as f64) / (rss_after / (n - p_total) as f64))
            .filter(|f| f.is_finite());
        evidence.push(Evidence {
            bic_drop: current_bic - best_bic,
            partial_f,
            rss_before: rss,
            rss_after,
            residuals: n,
        });
        let mut with = ids;
        with.push(best_id);
        model = unflatten(&with, &best_fit.parameters[nn..]);
        current_nuisance = best_fit.parameters[..nn].to_vec();
        rss = rss_after;
        current_bic = best_bic;
    }
    Some(Selection {
        model,
        nuisance: current_nuisance,
        evidence,
        confounded,
        trace,
    })
}

/// RMS of model − measured per longitudinal coefficient over `points`.
fn rms(prediction: &Prediction, points: &[&Point], model: &Model) -> BTreeMap<String, f64> {
    let refs = as_refs(model);
    let mut out = BTreeMap::new();
    for (k, name) in LONGITUDINAL.iter().enumerate() {
        let d: Vec<f64> = points
            .iter()
            .filter_map(|p| {
                let m = p.measured[k]?;
                Some(pick(&apply(prediction, &refs, p.alpha_deg)?, k) - m)
            })
            .collect();
        if !d.is_empty() {
            out.insert(
                name.to_string(),
                (d.iter().map(|x| x * x).sum::<f64>() / d.len() as f64).sqrt(),
            );
        }
    }
    out
}

/// 95 % two-sided normal quantile.
const Z95: f64 = 1.959_963_984_540_054;

/// The chosen effects with parameters and 95 % intervals from a fit of `model` to `all`.
pub(crate) fn chosen_effects<F>(
    residuals: &F,
    selection: &Selection,
    nuisance: &Nuisance,
) -> Vec<ChosenEffect>
where
    F: Fn(&Model, &[f64]) -> Option<Vec<f64>>,
{
    let (model, evidence) = (&selection.model, &selection.evidence);
    let ids: Vec<EffectId> = model.iter().map(|(e, _)| *e).collect();
    let start: Vec<f64> = selection
        .nuisance
        .iter()
        .copied()
        .chain(model.iter().flat_map(|(_, p)| p.clone()))
        .collect();
    let fitted = fit_model(residuals, &ids, &start, nuisance);
    let mut k = selection.nuisance.len();
    ids.iter()
        .zip(evidence)
        .map(|(id, ev)| {
            let mut parameters = BTreeMap::new();
            let mut ci95 = BTreeMap::new();
            for name in id.parameters() {
                let (v, se) = match &fitted {
                    Some(f) => (f.parameters[k], f.standard_errors[k]),
                    None => (start[k], f64::NAN),
                };
                parameters.insert(name.to_string(), v);
                if se.is_finite() && se > 0.0 {
                    ci95.insert(name.to_string(), [v - Z95 * se, v + Z95 * se]);
                }
                k += 1;
            }
            ChosenEffect {
                id: *id,
                parameters,
                ci95,
                evidence: ev.clone(),
                description: id.description(),
            }
        })
        .collect()
}

/// The model of chosen effects.
pub fn model_of(effects: &[ChosenEffect]) -> Model {
    effects
        .iter()
        .map(|e| {
            (
                e.id,
                e.id.parameters()
                    .iter()
                    .map(|n| e.parameters.get(*n).copied().unwrap_or(f64::NAN))
                    .collect(),
            )
        })
        .collect()
}

/// Residual bins: each coefficient over the lower, middle and upper third of the measured
/// angles.
fn residual_bins(prediction: &Prediction, points: &[Point]) -> Vec<ResidualBin> {
    let mut alphas: Vec<f64> = points.iter().map(|p| p.alpha_deg).collect();
    alphas.sort_by(f64::total_cmp);
    alphas.dedup();
    let m = alphas.len();
    if m == 0 {
        return Vec::new();
    }
    let cuts = [0, m / 3, 2 * m / 3, m];
    let mut out = Vec::new();
    for (k, name) in LONGITUDINAL.iter().enumerate() {
        for b in 0..3 {
            if cuts[b] == cuts[b + 1] {
                continue;
            }
            let (from, to) = (alphas[cuts[b]], alphas[cuts[b + 1] - 1]);
            let (d, s2): (Vec<f64>, Vec<f64>) = points
                .iter()
                .filter(|p| p.alpha_deg >= from && p.alpha_deg <= to)
                .filter_map(|p| {
                    let gap = p.measured[k]? - pick(&prediction.at(p.alpha_deg)?, k);
                    Some((gap, p.sigma[k] * p.sigma[k]))
                })
                .unzip();
            if d.is_empty() {
                continue;
            }
            let nf = d.len() as f64;
            let mean = d.iter().sum::<f64>() / nf;
            // The noise of the bin's mean: √(Σσ²)/n.
            let sigma = (s2.iter().sum::<f64>() / nf).sqrt();
            let z = mean / (sigma / nf.sqrt());
            out.push(ResidualBin {
                coefficient: name.to_string(),
                alpha_from_deg: from,
                alpha_to_deg: to,
                points: d.len(),
                mean,
                rms: (d.iter().map(|x| x * x).sum::<f64>() / nf).sqrt(),
                sigma,
                z,
                significant: z.abs() > SIGNIFICANT_Z,
            });
        }
    }
    out
}

/// Below this the noise estimated from the data is taken as this, with a warning: the data
/// are a smooth table, not measurements with scatter.
const NOISE_FLOOR: f64 = 1e-6;

/// The noise of CL, CD, Cm where rows give none (none where no row needs it), and where each
/// came from.
type Noise = ([Option<f64>; 3], BTreeMap<String, String>);

/// The noise of each longitudinal coefficient measured on `rows` where a row gives none: the
/// pooled standard deviation of repeated angles where the data repeat an angle, else the
/// point-to-point scatter of the residual curve measured − predicted
/// ([`data::noise_estimate`]). An error names a coefficient whose noise can be neither read
/// nor estimated (fewer than three angles, no repeats).
fn noise(
    prediction: &Prediction,
    measured: &Measurement,
    rows: &[usize],
    warnings: &mut Vec<String>,
) -> Result<Noise, DiscrepancyError> {
    let mut sigma = [None; 3];
    let mut source = BTreeMap::new();
    for (k, name) in LONGITUDINAL.iter().enumerate() {
        let Some(values) = measured.values.get(*name) else {
            continue;
        };
        let given = measured.sigma.get(*name);
        let measured_rows: Vec<usize> = rows
            .iter()
            .copied()
            .filter(|&r| values[r].is_some())
            .collect();
        if measured_rows.is_empty() {
            continue;
        }
        let unsigned: Vec<usize> = measured_rows
            .iter()
            .copied()
            .filter(|&r| given.and_then(|g| g[r]).is_none())
            .collect();
        if unsigned.is_empty() {
            let given = if measured.sigma_set_for_all_rows.contains(*name) {
                "given by --sigma".to_string()
            } else {
                format!("given by the sigma_{name} column at every row")
            };
            source.insert(name.to_string(), given);
            continue;
        }
        let mut pairs: Vec<(f64, f64)> = measured_rows
            .iter()
            .filter_map(|&r| {
                let a = measured.alpha_deg[r];
                Some((a, values[r]? - pick(&prediction.at(a)?, k)))
            })
            .collect();
        pairs.sort_by(|a, b| a.0.total_cmp(&b.0));
        let (estimate, how) = match pooled_repeats(&pairs) {
            Some(s) => (Some(s), "the pooled scatter of repeated angles"),
            None => {
                let (x, y): (Vec<f64>, Vec<f64>) = pairs.iter().copied().unzip();
                (
                    data::noise_estimate(&x, &y),
                    "the point-to-point scatter of the residuals",
                )
            }
        };
        let Some(estimate) = estimate else {
            return Err(DiscrepancyError::Invalid {
                reason: format!(
                    "the noise of {name} cannot be estimated from {} measured angle(s) without repeats (hint: give --sigma {name}=... or a sigma_{name} column)",
                    pairs.len()
                ),
            });
        };
        if estimate < NOISE_FLOOR {
            warnings.push(format!(
                "the noise of {name} is estimated as about 0 (a smooth table rather than scattered measurements?): taken as {NOISE_FLOOR}, which makes every gap significant (hint: give --sigma {name}=...)"
            ));
        }
        sigma[k] = Some(estimate.max(NOISE_FLOOR));
        let rows_given = measured_rows.len() - unsigned.len();
        source.insert(
            name.to_string(),
            if rows_given > 0 {
                format!(
                    "given by the sigma_{name} column at {rows_given} row(s), elsewhere estimated from {how}"
                )
            } else {
                format!("estimated from {how}")
            },
        );
    }
    Ok((sigma, source))
}

/// The pooled standard deviation of the values at repeated angles (`pairs` sorted by angle),
/// when some angle is repeated.
fn pooled_repeats(pairs: &[(f64, f64)]) -> Option<f64> {
    let mut sum = 0.0;
    let (mut dof, mut i) = (0usize, 0usize);
    while i < pairs.len() {
        let j = i + pairs[i..].iter().take_while(|p| p.0 == pairs[i].0).count();
        let group = &pairs[i..j];
        if group.len() > 1 {
            let mean = group.iter().map(|p| p.1).sum::<f64>() / group.len() as f64;
            sum += group.iter().map(|p| (p.1 - mean).powi(2)).sum::<f64>();
            dof += group.len() - 1;
        }
        i = j;
    }
    (dof > 0).then(|| (sum / dof as f64).sqrt())
}

/// The workflow on static data (see the module documentation and [`Options`]).
pub fn analyse_static(
    prediction: &Prediction,
    measured: &Measurement,
    options: &Options,
) -> Result<Analysis, DiscrepancyError> {
    prediction
        .validate()
        .map_err(|reason| DiscrepancyError::NoPrediction { reason })?;
    let mut warnings = Vec::new();
    let (lo, hi) = (
        prediction.alpha_deg[0],
        prediction.alpha_deg[prediction.alpha_deg.len() - 1],
    );
    let rows: Vec<usize> = (0..measured.alpha_deg.len())
        .filter(|&r| measured.beta_deg[r].abs() <= options.beta_zero_deg)
        .filter(|&r| {
            options
                .alpha_range_deg
                .is_none_or(|(a, b)| (a..=b).contains(&measured.alpha_deg[r]))
        })
        .collect();
    let outside = rows
        .iter()
        .filter(|&&r| !(lo..=hi).contains(&measured.alpha_deg[r]))
        .count();
    if outside > 0 {
        warnings.push(format!(
            "{outside} measured point(s) outside the prediction's angles ({lo} to {hi} deg) are left out"
        ));
    }
    let rows: Vec<usize> = rows
        .into_iter()
        .filter(|&r| (lo..=hi).contains(&measured.alpha_deg[r]))
        .collect();
    let column = |name: &str, r: usize| measured.values.get(name).and_then(|v| v[r]);
    let (default_sigma, sigma_source) = noise(prediction, measured, &rows, &mut warnings)?;
    let row_sigma = |k: usize, r: usize| {
        measured
            .sigma
            .get(LONGITUDINAL[k])
            .and_then(|s| s[r])
            .or(default_sigma[k])
            .unwrap_or(1.0)
    };
    let mut points: Vec<Point> = rows
        .iter()
        .map(|&r| Point {
            alpha_deg: measured.alpha_deg[r],
            measured: [column("CL", r), column("CD", r), column("Cm", r)],
            sigma: [row_sigma(0, r), row_sigma(1, r), row_sigma(2, r)],
        })
        .filter(|p| p.measured.iter().any(Option::is_some))
        .collect();
    if points.is_empty() {
        return Err(match options.alpha_range_deg {
            Some((a, b)) => DiscrepancyError::Invalid {
                reason: format!(
                    "no measured point with beta 0 and CL, CD or Cm lies in --alpha-range {a},{b} within the prediction's angles ({lo} to {hi} deg)"
                ),
            },
            None => DiscrepancyError::NoOverlap { from: lo, to: hi },
        });
    }
    points.sort_by(|a, b| a.alpha_deg.total_cmp(&b.alpha_deg));
    let mut candidates = options.candidates.clone();
    if prediction.tail_cl.is_none() || prediction.tail_cm.is_none() {
        if candidates.contains(&EffectId::TailEfficiency) {
            warnings.push("tail_efficiency is not a candidate: the prediction has no horizontal-tail contributions (CL_tail, Cm_tail)".into());
        }
        candidates.retain(|c| *c != EffectId::TailEfficiency);
    }
    let every = options.holdout_every.max(2);
    let hold = |i: usize| points.len() >= MIN_POINTS_TO_HOLD_OUT && i % every == every - 1;
    if points.len() < MIN_POINTS_TO_HOLD_OUT {
        warnings.push(format!(
            "{} measured angles: too few to hold points out, so no held-out validation (at least {MIN_POINTS_TO_HOLD_OUT})",
            points.len()
        ));
    }
    let training: Vec<&Point> = points
        .iter()
        .enumerate()
        .filter(|(i, _)| !hold(*i))
        .map(|(_, p)| p)
        .collect();
    let held_out: Vec<&Point> = points
        .iter()
        .enumerate()
        .filter(|(i, _)| hold(*i))
        .map(|(_, p)| p)
        .collect();
    let all: Vec<&Point> = points.iter().collect();
    let on_training = |m: &Model, _: &[f64]| static_residuals(prediction, &training, &as_refs(m));
    let on_all = |m: &Model, _: &[f64]| static_residuals(prediction, &all, &as_refs(m));
    let alphas: Vec<f64> = points.iter().map(|p| p.alpha_deg).collect();
    let none = Nuisance::default();
    let selection =
        stepwise(&on_training, &candidates, &alphas, &none, options).ok_or_else(|| {
            DiscrepancyError::NoPrediction {
                reason: "the prediction cannot be evaluated at the measured angles".into(),
            }
        })?;
    let effects = chosen_effects(&on_all, &selection, &none);
    let corrected = model_of(&effects);
    Ok(Analysis {
        rms_before: rms(prediction, &all, &Vec::new()),
        rms_after: rms(prediction, &all, &corrected),
        validation_rms_before: rms(prediction, &held_out, &Vec::new()),
        validation_rms_after: rms(prediction, &held_out, &selection.model),
        effects,
        confounded: selection.confounded,
        residuals: residual_bins(prediction, &points),
        sigma: LONGITUDINAL
            .iter()
            .zip(default_sigma)
            .filter_map(|(n, s)| Some((n.to_string(), s?)))
            .collect(),
        sigma_source,
        criterion: format!(
            "BIC = chi-square + k ln n, added when it falls by more than {}",
            options.min_bic_drop
        ),
        selection: selection.trace,
        warnings,
    })
}

fn map_line(m: &BTreeMap<String, f64>) -> String {
    m.iter()
        .map(|(k, v)| format!("{k} {v:.5}"))
        .collect::<Vec<_>>()
        .join(", ")
}

fn effect_lines(effects: &[ChosenEffect], out: &mut String) {
    if effects.is_empty() {
        out.push_str("no effect named: none lowers BIC enough with its interval excluding no effect (or those that do are confounded, below)\n");
    }
    for (k, e) in effects.iter().enumerate() {
        out.push_str(&format!(
            "{}. {} (BIC falls {:.1}, partial F {})\n   {}\n",
            k + 1,
            e.id.name(),
            e.evidence.bic_drop,
            e.evidence
                .partial_f
                .map_or("- (exact fit)".to_string(), |f| format!("{f:.1}")),
            e.description
        ));
        for (name, v) in &e.parameters {
            let ci = e.ci95.get(name).map_or(String::new(), |[lo, hi]| {
                format!(" (95 %: {lo:.5} to {hi:.5})")
            });
            out.push_str(&format!("   {name} = {v:.5}{ci}\n"));
        }
    }
}

fn trace_lines(steps: &[Step], out: &mut String) {
    for (k, step) in steps
        .iter()
        .enumerate()
        .filter(|(_, s)| !s.candidates.is_empty())
    {
        let tried: Vec<String> = step
            .candidates
            .iter()
            .map(|t| {
                format!(
                    "{} {:.1}{}",
                    t.effect.name(),
                    t.bic_drop,
                    if t.departs_from_nominal {
                        ""
                    } else {
                        " (interval includes no effect)"
                    }
                )
            })
            .collect();
        out.push_str(&format!(
            "step {}: BIC falls by {}\n",
            k + 1,
            tried.join(", ")
        ));
    }
}

fn confounded_lines(groups: &[Vec<EffectId>], out: &mut String) {
    for g in groups {
        let names: Vec<&str> = g.iter().map(|e| e.name()).collect();
        out.push_str(&format!(
            "confounded (explain the data equally well; not chosen between): {}\n",
            names.join(", ")
        ));
    }
}

impl Analysis {
    /// The analysis as text for a person.
    pub fn to_text(&self) -> String {
        let mut out =
            String::from("Where prediction and measurement disagree (measured − predicted):\n");
        out.push_str(&format!(
            "{:<4} {:>16} {:>6} {:>10} {:>10} {:>10} {:>7}\n",
            "coef", "alpha range deg", "points", "mean", "rms", "sigma", "z"
        ));
        for b in &self.residuals {
            out.push_str(&format!(
                "{:<4} {:>7.2} to {:>5.2} {:>6} {:>10.5} {:>10.5} {:>10.5} {:>7.1}{}\n",
                b.coefficient,
                b.alpha_from_deg,
                b.alpha_to_deg,
                b.points,
                b.mean,
                b.rms,
                b.sigma,
                b.z,
                if b.significant { "  significant" } else { "" }
            ));
        }
        for (k, s) in &self.sigma_source {
            out.push_str(&format!("noise of {k}: {s}\n"));
        }
        out.push_str(&format!("\nEffects added ({}):\n", self.criterion));
        effect_lines(&self.effects, &mut out);
        trace_lines(&self.selection, &mut out);
        confounded_lines(&self.confounded, &mut out);
        out.push_str(&format!(
            "\nRMS before: {}\nRMS after:  {}\n",
            map_line(&self.rms_before),
            map_line(&self.rms_after)
        ));
        if self.validation_rms_before.is_empty() {
            out.push_str("held-out validation: not made (too few measured angles)\n");
        } else {
            out.push_str(&format!(
                "held-out points, RMS before: {}\nheld-out points, RMS after:  {}\n",
                map_line(&self.validation_rms_before),
                map_line(&self.validation_rms_after)
            ));
        }
        for w in &self.warnings {
            out.push_str(&format!("warning: {w}\n"));
        }
        out
    }
}

impl flight::FlightAnalysis {
    /// The flight analysis as text for a person.
    pub fn to_text(&self) -> String {
        let mut out = format!(
            "Output-error fit of the effect catalogue ({}):\n",
            self.criterion
        );
        effect_lines(&self.effects, &mut out);
        trace_lines(&self.selection, &mut out);
        confounded_lines(&self.confounded, &mut out);
        out.push_str(&format!(
            "\nstate RMS (simulated − recorded) before: {}\nstate RMS after:  {}\nnoise: {}\n",
            map_line(&self.rms_before),
            map_line(&self.rms_after),
            map_line(&self.sigma)
        ));
        for w in &self.warnings {
            out.push_str(&format!("warning: {w}\n"));
        }
        out
    }
}
