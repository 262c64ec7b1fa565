//! The prediction of a deck for the discrepancy workflow: the full configuration's CL, CD, Cm
//! against alpha at one flight condition, the horizontal tail's contributions (the full
//! configuration less the one without the horizontal tail, from the build-up) and what the
//! flight simulation needs (reference dimensions, weight, pitch damping).

use serde::Serialize;

use super::{DiscrepancyError, Prediction};
use crate::case::Deck;
use crate::results::{page_name, run_case, ConditionResults, WING_BODY, WING_BODY_VT};

/// What the flight simulation takes from the deck, SI.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct DeckModel {
    pub prediction: Prediction,
    pub configuration: String,
    pub mach: f64,
    pub altitude_m: Option<f64>,
    pub velocity_mps: Option<f64>,
    /// kg/m³ from the condition's pressure and temperature.
    pub density: Option<f64>,
    pub reference_area_m2: Option<f64>,
    pub reference_chord_m: Option<f64>,
    /// WT of $FLTCON, newtons.
    pub weight_n: Option<f64>,
    /// Per radian, first row of the dynamic page (with DAMP).
    pub clq_per_rad: Option<f64>,
    pub cmq_per_rad: Option<f64>,
    pub cmad_per_rad: Option<f64>,
    pub warnings: Vec<String>,
}

/// Specific gas constant of air, J/(kg K) (the 1962 standard atmosphere's).
const GAS_CONSTANT_AIR: f64 = 287.053;

/// The prediction of `deck`: case `case` (1-based), condition `condition` (0-based, in the
/// order of the run), the case's most complete configuration. The angles kept are those where
/// CL, CD and Cm are all computed (a warning says which were dropped).
pub fn from_deck(
    deck: &Deck,
    case: usize,
    condition: usize,
) -> Result<DeckModel, DiscrepancyError> {
    let c = deck
        .cases
        .get(case.wrapping_sub(1))
        .ok_or_else(|| DiscrepancyError::NoPrediction {
            reason: format!("the deck has no case {case} (it has {})", deck.cases.len()),
        })?;
    // The build-up gives the configuration without the horizontal tail as well.
    let mut built = c.clone();
    built.cards.build = true;
    let results = run_case(&built);
    let mut groups: Vec<Vec<&ConditionResults>> = Vec::new();
    for e in &results.conditions {
        match groups.last_mut() {
            Some(g) if g[0].condition == e.condition => g.push(e),
            _ => groups.push(vec![e]),
        }
    }
    let group = groups
        .get(condition)
        .ok_or_else(|| DiscrepancyError::NoPrediction {
            reason: format!(
                "case {case} has no condition {} (it has {})",
                condition + 1,
                groups.len()
            ),
        })?;
    let full = group[group.len() - 1];
    if full.configuration != results.configuration {
        return Err(DiscrepancyError::NoPrediction {
            reason: format!(
                "case {case}: the build-up has no page for its configuration {} (only the pages of its largest parts)",
                results.configuration
            ),
        });
    }
    let s = &full.static_coefficients;
    let mut warnings: Vec<String> = Vec::new();
    let mut alpha = Vec::new();
    let (mut cl, mut cd, mut cm) = (Vec::new(), Vec::new(), Vec::new());
    let mut kept = Vec::new();
    for (k, a) in full.alpha_deg.iter().enumerate() {
        match (s.cl[k], s.cd[k], s.cm[k]) {
            (Some(l), Some(d), Some(m)) => {
                alpha.push(*a);
                cl.push(l);
                cd.push(d);
                cm.push(m);
                kept.push(k);
            }
            _ => warnings.push(format!(
                "alpha {a} deg left out of the prediction: CL, CD or Cm not computed there"
            )),
        }
    }
    // The horizontal tail's contribution: with it less without it.
    let without = if full.configuration.contains("HORIZONTAL TAIL") {
        let name = if full.configuration.contains("VERTICAL TAIL") {
            page_name(&built, WING_BODY_VT)
        } else {
            WING_BODY.to_string()
        };
        group.iter().find(|e| e.configuration == name)
    } else {
        None
    };
    let tail = |f: fn(&ConditionResults) -> &Vec<Option<f64>>| -> Option<Vec<f64>> {
        let w = without?;
        kept.iter().map(|&k| Some(f(full)[k]? - f(w)[k]?)).collect()
    };
    let tail_cl = tail(|e| &e.static_coefficients.cl);
    let tail_cm = tail(|e| &e.static_coefficients.cm);
    if full.configuration.contains("HORIZONTAL TAIL") && (tail_cl.is_none() || tail_cm.is_none()) {
        warnings.push("the horizontal tail's contributions are not known at every kept angle: tail_efficiency is not a candidate".into());
    }
    let prediction = Prediction {
        alpha_deg: alpha,
        cl,
        cd,
        cm,
        tail_cl,
        tail_cm,
    };
    prediction
        .validate()
        .map_err(|reason| DiscrepancyError::NoPrediction {
            reason: format!("{}: {reason}", full.configuration.trim()),
        })?;
    let cond = &full.condition;
    let density = match (cond.pressure, cond.temperature) {
        (Some(p), Some(t)) if t > 0.0 => Some(p / (GAS_CONSTANT_AIR * t)),
        _ => None,
    };
    let first = |name: &str| -> Option<f64> {
        full.dynamic
            .as_ref()?
            .columns()
            .into_iter()
            .find(|(n, _)| *n == name)?
            .1
            .first()
            .copied()
            .flatten()
    };
    Ok(DeckModel {
        prediction,
        configuration: full.configuration.trim().to_string(),
        mach: cond.mach,
        altitude_m: cond.altitude,
        velocity_mps: cond.velocity,
        density,
        reference_area_m2: results.reference.area,
        reference_chord_m: results.reference.chord,
        weight_n: c.flight.as_ref().and_then(|f| f.weight),
        clq_per_rad: first("CLQ"),
        cmq_per_rad: first("CMQ"),
        cmad_per_rad: first("CMAD"),
        warnings,
    })
}
