//! Synthetic data for testing the workflow: a prediction plus hidden effects plus noise, and a
//! flight with a hidden effect. Every generator is deterministic in its seed (SplitMix64 and
//! Box–Muller, written out here so that the data are the same on every machine and version).

use std::collections::BTreeMap;

use super::effects::{apply, EffectId, Prediction};
use super::flight::{simulate, trim, Airframe, FlightRecord, State};
use super::Measurement;

/// A small deterministic random generator (SplitMix64) with normal deviates (Box–Muller).
#[derive(Debug, Clone)]
pub struct Rng {
    state: u64,
    spare: Option<f64>,
}

impl Rng {
    pub fn new(seed: u64) -> Rng {
        Rng {
            state: seed,
            spare: None,
        }
    }

    /// Uniform in (0, 1).
    pub fn uniform(&mut self) -> f64 {
        self.state = self.state.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.state;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^= z >> 31;
        ((z >> 11) as f64 + 0.5) / (1u64 << 53) as f64
    }

    /// Standard normal.
    pub fn normal(&mut self) -> f64 {
        if let Some(s) = self.spare.take() {
            return s;
        }
        let (u1, u2) = (self.uniform(), self.uniform());
        let r = (-2.0 * u1.ln()).sqrt();
        let t = std::f64::consts::TAU * u2;
        self.spare = Some(r * t.sin());
        r * t.cos()
    }
}

/// Noise of a wind-tunnel balance on a small model, standard deviations of CL, CD, Cm (the
/// level the tests use: a few thousandths in CL and Cm, one thousandth in CD).
pub const TUNNEL_NOISE: [f64; 3] = [0.005, 0.001, 0.002];

/// A hidden effect's parameters for the tests: sizes a real gap of each kind can have.
pub fn typical(id: EffectId) -> Vec<f64> {
    match id {
        EffectId::ParasiteDrag => vec![0.012],
        EffectId::InducedDragFactor => vec![0.03],
        EffectId::LiftSlopeScale => vec![0.9],
        EffectId::ZeroLiftShift => vec![1.5],
        EffectId::Cm0Offset => vec![-0.03],
        EffectId::MomentReferenceShift => vec![0.04],
        EffectId::StallOnset => vec![7.0, 0.006, -0.003],
        EffectId::TailEfficiency => vec![0.8],
    }
}

/// Static "measurements": the prediction with `hidden` effects at every angle of `alphas`
/// (beta 0), plus independent normal noise of standard deviations `noise` (CL, CD, Cm) from
/// `seed`. No sigma columns: the workflow estimates the noise.
pub fn static_measurement(
    prediction: &Prediction,
    hidden: &[(EffectId, &[f64])],
    alphas: &[f64],
    noise: [f64; 3],
    seed: u64,
) -> Measurement {
    let mut rng = Rng::new(seed);
    let mut cl = Vec::new();
    let mut cd = Vec::new();
    let mut cm = Vec::new();
    let mut kept = Vec::new();
    for a in alphas {
        if let Some(c) = apply(prediction, hidden, *a) {
            kept.push(*a);
            cl.push(Some(c.cl + noise[0] * rng.normal()));
            cd.push(Some(c.cd + noise[1] * rng.normal()));
            cm.push(Some(c.cm + noise[2] * rng.normal()));
        }
    }
    let mut values = BTreeMap::new();
    values.insert("CL".to_string(), cl);
    values.insert("CD".to_string(), cd);
    values.insert("Cm".to_string(), cm);
    Measurement {
        beta_deg: vec![0.0; kept.len()],
        alpha_deg: kept,
        values,
        sigma: BTreeMap::new(),
        sigma_set_for_all_rows: Default::default(),
    }
}

/// Noise of flight sensors: airspeed m/s, alpha deg, pitch rate deg/s, pitch attitude deg.
pub const FLIGHT_NOISE: [f64; 4] = [0.3, 0.3, 0.5, 0.2];

/// A recorded flight of the aircraft with `hidden` effects: trimmed at `speed` m/s in level
/// flight, the pilot holding that trim's thrust with an elevator doublet of ±2° (at 5 s and
/// 7 s, 2 s each) and a 20 % throttle step from 30 s to 45 s, sampled at `dt` s for
/// `duration` s, states with noise [`FLIGHT_NOISE`] from `seed`. None when the aircraft
/// cannot be trimmed or the simulation diverges.
pub fn flight_record(
    prediction: &Prediction,
    hidden: &[(EffectId, &[f64])],
    airframe: &Airframe,
    speed: f64,
    dt: f64,
    duration: f64,
    seed: u64,
) -> Option<FlightRecord> {
    let (alpha, de, thrust) = trim(prediction, hidden, airframe, speed)?;
    let n = (duration / dt).round() as usize + 1;
    let t: Vec<f64> = (0..n).map(|k| k as f64 * dt).collect();
    let elevator_deg: Vec<f64> = t
        .iter()
        .map(|&s| {
            de.to_degrees()
                + if (5.0..7.0).contains(&s) {
                    2.0
                } else if (7.0..9.0).contains(&s) {
                    -2.0
                } else {
                    0.0
                }
        })
        .collect();
    let thrust_n: Vec<f64> = t
        .iter()
        .map(|&s| thrust * if (30.0..45.0).contains(&s) { 1.2 } else { 1.0 })
        .collect();
    let a = alpha.to_radians();
    let initial = State {
        u: speed * a.cos(),
        w: speed * a.sin(),
        q: 0.0,
        theta: a,
    };
    let mut record = FlightRecord {
        t,
        elevator_deg,
        thrust_n,
        airspeed_mps: Vec::new(),
        alpha_deg: Vec::new(),
        pitch_rate_dps: Vec::new(),
        theta_deg: Vec::new(),
    };
    let states = simulate(prediction, hidden, airframe, &record, initial)?;
    let mut rng = Rng::new(seed);
    for s in &states {
        record
            .airspeed_mps
            .push(s.airspeed() + FLIGHT_NOISE[0] * rng.normal());
        record
            .alpha_deg
            .push(s.alpha_deg() + FLIGHT_NOISE[1] * rng.normal());
        record
            .pitch_rate_dps
            .push(s.q.to_degrees() + FLIGHT_NOISE[2] * rng.normal());
        record
            .theta_deg
            .push(s.theta.to_degrees() + FLIGHT_NOISE[3] * rng.normal());
    }
    Some(record)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_generator_is_deterministic_and_roughly_standard_normal() {
        let mut a = Rng::new(7);
        let mut b = Rng::new(7);
        let xs: Vec<f64> = (0..20000).map(|_| a.normal()).collect();
        assert!(xs
            .iter()
            .zip((0..20000).map(|_| b.normal()))
            .all(|(x, y)| *x == y));
        let mean = xs.iter().sum::<f64>() / xs.len() as f64;
        let var = xs.iter().map(|x| (x - mean) * (x - mean)).sum::<f64>() / xs.len() as f64;
        // 20 000 draws: the mean within 4 standard errors (0.028), the variance within 5 %.
        assert!(mean.abs() < 0.028, "{mean}");
        assert!((var - 1.0).abs() < 0.05, "{var}");
    }
}
