//! Flight mode: a longitudinal simulation (u, w, q, θ; flat earth, still air, constant
//! density) driven by the prediction's CL, CD, Cm against alpha, its pitch damping and the
//! elevator derivatives, with the recorded elevator and thrust; and output-error fitting of
//! the effect catalogue to a recorded time history (docs/discrepancy.md).
//!
//! Body axes, x forward, z down; V = √(u² + w²), α = atan2(w, u), q̄ = ½ρV²:
//! m(u̇ + qw) = T − D cos α + L sin α − mg sin θ; m(ẇ − qu) = −D sin α − L cos α + mg cos θ;
//! I_yy q̇ = q̄ S c̄ Cm; θ̇ = q. CL = CL(α) + CL_q q c̄/2V + CL_δe δe, CD = CD(α),
//! Cm = Cm(α) + Cm_q q c̄/2V + Cm_δe δe. The α̇ terms are left out (their effect on a slow
//! airspeed history is small; the model says so rather than guess α̇). Thrust acts along x.

use std::collections::BTreeMap;

use serde::{Deserialize, Serialize};

use super::data::noise_estimate;
use super::effects::{apply, Prediction};
use super::{
    chosen_effects, model_of, stepwise, ChosenEffect, DiscrepancyError, EffectId, Model, Nuisance,
    Options,
};

/// Standard gravity, m/s².
pub const G: f64 = 9.80665;
/// Integration steps per recorded sample (RK4).
const SUBSTEPS: usize = 2;

/// The aircraft's mass, inertia, reference dimensions, air density and the derivatives the
/// prediction does not give (elevator), SI, per radian.
#[derive(Debug, Clone, PartialEq, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct Airframe {
    pub mass_kg: f64,
    pub iyy_kgm2: f64,
    pub area_m2: f64,
    pub chord_m: f64,
    pub density_kgm3: f64,
    #[serde(default)]
    pub clq_per_rad: f64,
    pub cmq_per_rad: f64,
    pub cl_de_per_rad: f64,
    pub cm_de_per_rad: f64,
}

impl Airframe {
    fn validate(&self) -> Result<(), DiscrepancyError> {
        let positive = [
            ("mass_kg", self.mass_kg),
            ("iyy_kgm2", self.iyy_kgm2),
            ("area_m2", self.area_m2),
            ("chord_m", self.chord_m),
            ("density_kgm3", self.density_kgm3),
        ];
        for (name, v) in positive {
            if !(v.is_finite() && v > 0.0) {
                return Err(DiscrepancyError::Invalid {
                    reason: format!("airframe {name} must be a positive number, found {v}"),
                });
            }
        }
        if self.cm_de_per_rad == 0.0 || !self.cm_de_per_rad.is_finite() {
            return Err(DiscrepancyError::Invalid {
                reason: "airframe cm_de_per_rad must be a non-zero number (elevator power)".into(),
            });
        }
        Ok(())
    }
}

/// The state u, w (m/s), q (rad/s), θ (rad).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct State {
    pub u: f64,
    pub w: f64,
    pub q: f64,
    pub theta: f64,
}

impl State {
    pub fn airspeed(&self) -> f64 {
        self.u.hypot(self.w)
    }
    pub fn alpha_deg(&self) -> f64 {
        self.w.atan2(self.u).to_degrees()
    }
    fn add(&self, d: &State, h: f64) -> State {
        State {
            u: self.u + h * d.u,
            w: self.w + h * d.w,
            q: self.q + h * d.q,
            theta: self.theta + h * d.theta,
        }
    }
}

/// A recorded (or simulated) time history: the CSV columns of docs/discrepancy.md.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct FlightRecord {
    pub t: Vec<f64>,
    pub elevator_deg: Vec<f64>,
    pub thrust_n: Vec<f64>,
    pub airspeed_mps: Vec<f64>,
    pub alpha_deg: Vec<f64>,
    pub pitch_rate_dps: Vec<f64>,
    pub theta_deg: Vec<f64>,
}

impl FlightRecord {
    /// The recorded state at sample `k`.
    pub fn state(&self, k: usize) -> State {
        let (v, a) = (self.airspeed_mps[k], self.alpha_deg[k].to_radians());
        State {
            u: v * a.cos(),
            w: v * a.sin(),
            q: self.pitch_rate_dps[k].to_radians(),
            theta: self.theta_deg[k].to_radians(),
        }
    }

    /// Reads the CSV (columns t, elevator_deg, thrust_n, airspeed_mps, alpha_deg,
    /// pitch_rate_dps, theta_deg; t increasing).
    pub fn from_csv(text: &str, file: &str) -> Result<FlightRecord, DiscrepancyError> {
        let table = super::data::read_table(text, file)?;
        let column = |name: &str| table.required(name, file);
        let t = column("t")?;
        if t.len() < 3 || t.windows(2).any(|w| w[1] <= w[0]) {
            return Err(DiscrepancyError::Invalid {
                reason: format!("{file}: t must increase over at least 3 samples"),
            });
        }
        Ok(FlightRecord {
            t,
            elevator_deg: column("elevator_deg")?,
            thrust_n: column("thrust_n")?,
            airspeed_mps: column("airspeed_mps")?,
            alpha_deg: column("alpha_deg")?,
            pitch_rate_dps: column("pitch_rate_dps")?,
            theta_deg: column("theta_deg")?,
        })
    }

    /// The record as CSV.
    pub fn to_csv(&self) -> String {
        let mut out = String::from(
            "t,elevator_deg,thrust_n,airspeed_mps,alpha_deg,pitch_rate_dps,theta_deg\n",
        );
        for k in 0..self.t.len() {
            out.push_str(&format!(
                "{},{},{},{},{},{},{}\n",
                self.t[k],
                self.elevator_deg[k],
                self.thrust_n[k],
                self.airspeed_mps[k],
                self.alpha_deg[k],
                self.pitch_rate_dps[k],
                self.theta_deg[k]
            ));
        }
        out
    }
}

/// The state derivative; none where the angle of attack leaves the prediction.
fn derivative(
    prediction: &Prediction,
    effects: &[(EffectId, &[f64])],
    a: &Airframe,
    s: &State,
    elevator_rad: f64,
    thrust_n: f64,
) -> Option<State> {
    let v = s.airspeed();
    if !(v.is_finite() && v > 0.1) {
        return None;
    }
    let alpha = s.w.atan2(s.u);
    let c = apply(prediction, effects, alpha.to_degrees())?;
    let qbar = 0.5 * a.density_kgm3 * v * v;
    let rate = s.q * a.chord_m / (2.0 * v);
    let cl = c.cl + a.clq_per_rad * rate + a.cl_de_per_rad * elevator_rad;
    let cm = c.cm + a.cmq_per_rad * rate + a.cm_de_per_rad * elevator_rad;
    let (lift, drag) = (qbar * a.area_m2 * cl, qbar * a.area_m2 * c.cd);
    let (sa, ca) = alpha.sin_cos();
    let x = thrust_n - drag * ca + lift * sa;
    let z = -drag * sa - lift * ca;
    let m = a.mass_kg;
    Some(State {
        u: x / m - G * s.theta.sin() - s.q * s.w,
        w: z / m + G * s.theta.cos() + s.q * s.u,
        q: qbar * a.area_m2 * a.chord_m * cm / a.iyy_kgm2,
        theta: s.q,
    })
}

/// Simulates from `initial` with the recorded inputs of `record` (held over each sample,
/// RK4 with 2 steps per sample); one state per sample. None when the simulation
/// leaves the prediction's angles or diverges.
pub fn simulate(
    prediction: &Prediction,
    effects: &[(EffectId, &[f64])],
    airframe: &Airframe,
    record: &FlightRecord,
    initial: State,
) -> Option<Vec<State>> {
    let mut s = initial;
    let mut out = Vec::with_capacity(record.t.len());
    out.push(s);
    for k in 1..record.t.len() {
        let h = (record.t[k] - record.t[k - 1]) / SUBSTEPS as f64;
        let (de, t) = (
            record.elevator_deg[k - 1].to_radians(),
            record.thrust_n[k - 1],
        );
        for _ in 0..SUBSTEPS {
            let f = |x: &State| derivative(prediction, effects, airframe, x, de, t);
            let k1 = f(&s)?;
            let k2 = f(&s.add(&k1, h / 2.0))?;
            let k3 = f(&s.add(&k2, h / 2.0))?;
            let k4 = f(&s.add(&k3, h))?;
            s = State {
                u: s.u + h / 6.0 * (k1.u + 2.0 * k2.u + 2.0 * k3.u + k4.u),
                w: s.w + h / 6.0 * (k1.w + 2.0 * k2.w + 2.0 * k3.w + k4.w),
                q: s.q + h / 6.0 * (k1.q + 2.0 * k2.q + 2.0 * k3.q + k4.q),
                theta: s.theta + h / 6.0 * (k1.theta + 2.0 * k2.theta + 2.0 * k3.theta + k4.theta),
            };
        }
        if ![s.u, s.w, s.q, s.theta].iter().all(|v| v.is_finite()) {
            return None;
        }
        out.push(s);
    }
    Some(out)
}

/// Level-flight trim at airspeed `v`: (alpha deg, elevator rad, thrust N), by bisection on
/// the normal-force balance over the prediction's angles with Cm = 0 by the elevator and
/// thrust balancing drag. None when no angle of the prediction balances the weight.
pub fn trim(
    prediction: &Prediction,
    effects: &[(EffectId, &[f64])],
    a: &Airframe,
    v: f64,
) -> Option<(f64, f64, f64)> {
    let qbar = 0.5 * a.density_kgm3 * v * v;
    let w = a.mass_kg * G;
    let balance = |alpha_deg: f64| -> Option<(f64, f64, f64)> {
        let c = apply(prediction, effects, alpha_deg)?;
        let de = -c.cm / a.cm_de_per_rad;
        let lift = qbar * a.area_m2 * (c.cl + a.cl_de_per_rad * de);
        let drag = qbar * a.area_m2 * c.cd;
        let (sa, ca) = alpha_deg.to_radians().sin_cos();
        // θ = α in level flight: the z balance, and thrust from the x balance.
        let normal = -drag * sa - lift * ca + w * ca;
        let thrust = drag * ca - lift * sa + w * sa;
        Some((normal, de, thrust))
    };
    let alphas = &prediction.alpha_deg;
    let (mut lo, mut hi) = (alphas[0], alphas[alphas.len() - 1]);
    let (mut f_lo, _, _) = balance(lo)?;
    let (f_hi, _, _) = balance(hi)?;
    if f_lo.signum() == f_hi.signum() {
        return None;
    }
    for _ in 0..80 {
        let mid = 0.5 * (lo + hi);
        let (f_mid, _, _) = balance(mid)?;
        if f_mid.signum() == f_lo.signum() {
            lo = mid;
            f_lo = f_mid;
        } else {
            hi = mid;
        }
    }
    let alpha = 0.5 * (lo + hi);
    let (_, de, thrust) = balance(alpha)?;
    Some((alpha, de, thrust))
}

/// Samples over which the initial state is estimated (a straight-line fit of each recorded
/// state, evaluated at the first time): 1 s at 20 Hz. Starting from the first noisy sample
/// instead would give every simulation a transient that other effects then try to explain.
const INITIAL_SAMPLES: usize = 20;

/// The state at the first recorded time, each component from a least-squares line over the
/// first samples.
pub fn initial_state(record: &FlightRecord) -> State {
    let m = INITIAL_SAMPLES.min(record.t.len());
    let line_at_start = |y: &[f64]| -> f64 {
        let t = &record.t[..m];
        let tm = t.iter().sum::<f64>() / m as f64;
        let ym = y[..m].iter().sum::<f64>() / m as f64;
        let stt: f64 = t.iter().map(|x| (x - tm) * (x - tm)).sum();
        let sty: f64 = t
            .iter()
            .zip(&y[..m])
            .map(|(x, v)| (x - tm) * (v - ym))
            .sum();
        let slope = if stt > 0.0 { sty / stt } else { 0.0 };
        ym + slope * (t[0] - tm)
    };
    let v = line_at_start(&record.airspeed_mps);
    let a = line_at_start(&record.alpha_deg).to_radians();
    State {
        u: v * a.cos(),
        w: v * a.sin(),
        q: line_at_start(&record.pitch_rate_dps).to_radians(),
        theta: line_at_start(&record.theta_deg).to_radians(),
    }
}

/// The four recorded states of a simulation, in the record's units.
fn outputs(states: &[State]) -> [Vec<f64>; 4] {
    [
        states.iter().map(State::airspeed).collect(),
        states.iter().map(State::alpha_deg).collect(),
        states.iter().map(|s| s.q.to_degrees()).collect(),
        states.iter().map(|s| s.theta.to_degrees()).collect(),
    ]
}

/// A flight record needs this many samples (four initial-state parameters and the effects'
/// are fitted; the selection keeps at least two residuals per parameter).
pub const MIN_FLIGHT_SAMPLES: usize = 20;

/// The smallest noise a recorded state is given (m/s, deg, deg/s, deg): a record without
/// scatter (a simulation, a smoothed file) would otherwise make any mismatch significant.
pub const SENSOR_RESOLUTION: [f64; 4] = [0.01, 0.01, 0.01, 0.01];

/// Names of the compared states.
pub const STATES: [&str; 4] = ["airspeed_mps", "alpha_deg", "pitch_rate_dps", "theta_deg"];

/// The flight mode's result.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct FlightAnalysis {
    pub effects: Vec<ChosenEffect>,
    pub confounded: Vec<Vec<EffectId>>,
    /// RMS of simulated − recorded per state, with the prediction and with the effects.
    pub rms_before: BTreeMap<String, f64>,
    pub rms_after: BTreeMap<String, f64>,
    /// Noise per state (estimated from the record's scatter).
    pub sigma: BTreeMap<String, f64>,
    /// How effects are chosen, with the threshold's value.
    pub criterion: String,
    /// Every step of the selection with each candidate's fall of BIC.
    pub selection: Vec<super::Step>,
    /// The simulated histories, prediction and corrected, per state.
    pub simulated_before: BTreeMap<String, Vec<f64>>,
    pub simulated_after: BTreeMap<String, Vec<f64>>,
    pub warnings: Vec<String>,
}

fn rms_of(sim: &[Vec<f64>; 4], rec: &[&Vec<f64>; 4]) -> BTreeMap<String, f64> {
    STATES
        .iter()
        .enumerate()
        .map(|(k, n)| {
            let d: f64 = sim[k]
                .iter()
                .zip(rec[k].iter())
                .map(|(a, b)| (a - b) * (a - b))
                .sum();
            (n.to_string(), (d / sim[k].len().max(1) as f64).sqrt())
        })
        .collect()
}

/// Output-error fit of the catalogue to a recorded flight: the same stepwise selection as the
/// static workflow (BIC), on the residuals (simulated − recorded)/σ of airspeed, alpha,
/// pitch rate and pitch attitude, each simulation starting from the first recorded state.
pub fn analyse_flight(
    prediction: &Prediction,
    airframe: &Airframe,
    record: &FlightRecord,
    options: &Options,
) -> Result<FlightAnalysis, DiscrepancyError> {
    prediction
        .validate()
        .map_err(|reason| DiscrepancyError::NoPrediction { reason })?;
    airframe.validate()?;
    let mut warnings = Vec::new();
    let recorded = [
        &record.airspeed_mps,
        &record.alpha_deg,
        &record.pitch_rate_dps,
        &record.theta_deg,
    ];
    if record.t.len() < MIN_FLIGHT_SAMPLES {
        return Err(DiscrepancyError::Invalid {
            reason: format!(
                "the flight record has {} samples: at least {MIN_FLIGHT_SAMPLES} are needed to fit effects and the initial state",
                record.t.len()
            ),
        });
    }
    let mut sigma = [1.0; 4];
    for k in 0..4 {
        let estimate = noise_estimate(&record.t, recorded[k]).unwrap_or(0.0);
        if estimate < SENSOR_RESOLUTION[k] {
            warnings.push(format!(
                "the recorded {} shows no scatter (noise estimated {estimate:.2e}): its noise is taken as the resolution {} of the units",
                STATES[k], SENSOR_RESOLUTION[k]
            ));
        }
        sigma[k] = estimate.max(SENSOR_RESOLUTION[k]);
    }
    // The initial state is fitted with every model (output-error practice): a start from
    // noisy samples would leave a transient (a phugoid) that effects would try to explain.
    let initial = initial_state(record);
    let nuisance = Nuisance {
        start: vec![initial.u, initial.w, initial.q, initial.theta],
        scales: vec![1.0, 1.0, 0.1, 0.1],
    };
    let residuals = |m: &Model, x0: &[f64]| -> Option<Vec<f64>> {
        let refs: Vec<(EffectId, &[f64])> = m.iter().map(|(e, p)| (*e, p.as_slice())).collect();
        let start = State {
            u: x0[0],
            w: x0[1],
            q: x0[2],
            theta: x0[3],
        };
        let sim = simulate(prediction, &refs, airframe, record, start)?;
        let out = outputs(&sim);
        let mut r = Vec::with_capacity(4 * sim.len());
        for k in 0..4 {
            for (s, m) in out[k].iter().zip(recorded[k].iter()) {
                r.push((s - m) / sigma[k]);
            }
        }
        Some(r)
    };
    let before = simulate(prediction, &[], airframe, record, initial).ok_or_else(|| {
        DiscrepancyError::NoPrediction {
            reason: "the simulation with the prediction leaves its angles of attack or diverges"
                .into(),
        }
    })?;
    let mut candidates = options.candidates.clone();
    if prediction.tail_cl.is_none() || prediction.tail_cm.is_none() {
        candidates.retain(|c| *c != EffectId::TailEfficiency);
        warnings.push("tail_efficiency is not a candidate: the prediction has no horizontal-tail contributions".into());
    }
    let selection = stepwise(
        &residuals,
        &candidates,
        &prediction.alpha_deg,
        &nuisance,
        options,
    )
    .ok_or_else(|| DiscrepancyError::NoPrediction {
        reason: "the simulation cannot be evaluated".into(),
    })?;
    let effects = chosen_effects(&residuals, &selection, &nuisance);
    let corrected = model_of(&effects);
    let refs: Vec<(EffectId, &[f64])> = corrected.iter().map(|(e, p)| (*e, p.as_slice())).collect();
    let x0 = &selection.nuisance;
    let fitted_start = State {
        u: x0[0],
        w: x0[1],
        q: x0[2],
        theta: x0[3],
    };
    let after = simulate(prediction, &refs, airframe, record, fitted_start).unwrap_or_else(|| {
        warnings
            .push("the corrected model's simulation diverges; shown as the prediction's".into());
        before.clone()
    });
    let (ob, oa) = (outputs(&before), outputs(&after));
    let named = |o: &[Vec<f64>; 4]| -> BTreeMap<String, Vec<f64>> {
        STATES
            .iter()
            .zip(o.iter())
            .map(|(n, v)| (n.to_string(), v.clone()))
            .collect()
    };
    Ok(FlightAnalysis {
        rms_before: rms_of(&ob, &recorded),
        rms_after: rms_of(&oa, &recorded),
        sigma: STATES
            .iter()
            .zip(sigma)
            .map(|(n, s)| (n.to_string(), s))
            .collect(),
        effects,
        confounded: selection.confounded,
        criterion: format!(
            "BIC = chi-square + k ln n on the output errors, added when it falls by more than {}",
            options.min_bic_drop
        ),
        selection: selection.trace.clone(),
        simulated_before: named(&ob),
        simulated_after: named(&oa),
        warnings,
    })
}

/// The airframe as a file gives it (TOML, every field optional): what a deck does not give
/// (inertia, elevator derivatives), or overrides of what it gives.
#[derive(Debug, Clone, PartialEq, Default, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct AirframeInput {
    pub mass_kg: Option<f64>,
    pub iyy_kgm2: Option<f64>,
    pub area_m2: Option<f64>,
    pub chord_m: Option<f64>,
    pub density_kgm3: Option<f64>,
    pub clq_per_rad: Option<f64>,
    pub cmq_per_rad: Option<f64>,
    pub cl_de_per_rad: Option<f64>,
    pub cm_de_per_rad: Option<f64>,
}

impl AirframeInput {
    /// The airframe from this input, completed from a deck's model (mass from WT, reference
    /// area and chord, density of the condition, CLq and Cmq of its dynamic page). An error
    /// names each value neither gives.
    pub fn resolve(
        &self,
        deck: Option<&super::prediction::DeckModel>,
    ) -> Result<Airframe, DiscrepancyError> {
        let mut missing = Vec::new();
        let mut need = |name: &'static str, given: Option<f64>, from_deck: Option<f64>| {
            given.or(from_deck).unwrap_or_else(|| {
                missing.push(name);
                f64::NAN
            })
        };
        let a = Airframe {
            mass_kg: need(
                "mass_kg",
                self.mass_kg,
                deck.and_then(|d| d.weight_n).map(|w| w / G),
            ),
            iyy_kgm2: need("iyy_kgm2", self.iyy_kgm2, None),
            area_m2: need(
                "area_m2",
                self.area_m2,
                deck.and_then(|d| d.reference_area_m2),
            ),
            chord_m: need(
                "chord_m",
                self.chord_m,
                deck.and_then(|d| d.reference_chord_m),
            ),
            density_kgm3: need(
                "density_kgm3",
                self.density_kgm3,
                deck.and_then(|d| d.density),
            ),
            clq_per_rad: self
                .clq_per_rad
                .or(deck.and_then(|d| d.clq_per_rad))
                .unwrap_or(0.0),
            cmq_per_rad: need(
                "cmq_per_rad",
                self.cmq_per_rad,
                deck.and_then(|d| d.cmq_per_rad),
            ),
            cl_de_per_rad: self.cl_de_per_rad.unwrap_or(0.0),
            cm_de_per_rad: need("cm_de_per_rad", self.cm_de_per_rad, None),
        };
        if !missing.is_empty() {
            return Err(DiscrepancyError::Invalid {
                reason: format!(
                    "the flight mode needs {} (hint: give them in the --airframe file; a deck with WT, $OPTINS and DAMP gives mass, area, chord, density and cmq)",
                    missing.join(", ")
                ),
            });
        }
        a.validate()?;
        Ok(a)
    }
}
