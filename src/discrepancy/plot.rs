//! SVG figures of the discrepancy workflow (plotters, through `report::plot`): measured,
//! predicted and corrected CL, CD, Cm against alpha; for a flight, the recorded and simulated
//! airspeed, alpha, pitch rate and pitch attitude against time.

use super::effects::{apply, EffectId, Prediction};
use super::flight::{FlightAnalysis, FlightRecord, STATES};
use super::{model_of, Analysis, Measurement};
use crate::report::plot::{draw, Figure, PlotError, Series};

fn figure(
    name: &str,
    title: String,
    x_label: &str,
    y_label: &str,
    series: Vec<Series>,
) -> Result<Figure, PlotError> {
    let svg = draw(&title, x_label, y_label, &series).map_err(|e| PlotError::Draw {
        figure: name.to_string(),
        message: e.to_string(),
    })?;
    Ok(Figure {
        name: name.to_string(),
        title,
        series: series.into_iter().map(|s| s.label).collect(),
        svg,
    })
}

/// The prediction (with `effects` applied) at its angles, as one line with a marker at each.
fn curve(prediction: &Prediction, effects: &[(EffectId, &[f64])], k: usize) -> Vec<(f64, f64)> {
    prediction
        .alpha_deg
        .iter()
        .filter_map(|&x| {
            let c = apply(prediction, effects, x)?;
            Some((x, [c.cl, c.cd, c.cm][k]))
        })
        .collect()
}

/// Measured points shown: those within the prediction's angles (and the compared range),
/// with this margin, deg.
const SHOWN_MARGIN_DEG: f64 = 2.0;

/// CL, CD and Cm against alpha: measured (markers), predicted, and with the chosen effects.
pub fn static_figures(
    prediction: &Prediction,
    measured: &Measurement,
    analysis: &Analysis,
    beta_zero_deg: f64,
) -> Result<Vec<Figure>, PlotError> {
    let corrected = model_of(&analysis.effects);
    let refs: Vec<(EffectId, &[f64])> = corrected.iter().map(|(e, p)| (*e, p.as_slice())).collect();
    let names: Vec<&str> = analysis.effects.iter().map(|e| e.id.name()).collect();
    let corrected_label = if names.is_empty() {
        "corrected (no effect added)".to_string()
    } else {
        format!("corrected: {}", names.join(" + "))
    };
    let mut out = Vec::new();
    for (k, name) in ["CL", "CD", "Cm"].into_iter().enumerate() {
        let Some(values) = measured.values.get(name) else {
            continue;
        };
        let points: Vec<Vec<(f64, f64)>> = measured
            .alpha_deg
            .iter()
            .zip(&measured.beta_deg)
            .zip(values)
            .filter(|((_, b), _)| b.abs() <= beta_zero_deg)
            .filter(|((a, _), _)| {
                let (lo, hi) = (
                    prediction.alpha_deg[0],
                    prediction.alpha_deg[prediction.alpha_deg.len() - 1],
                );
                **a >= lo - SHOWN_MARGIN_DEG && **a <= hi + SHOWN_MARGIN_DEG
            })
            .filter_map(|((a, _), v)| Some(vec![(*a, (*v)?)]))
            .collect();
        let series = vec![
            Series {
                label: "measured".into(),
                pieces: points,
                once: false,
            },
            Series {
                label: "predicted (DATCOM)".into(),
                pieces: vec![curve(prediction, &[], k)],
                once: false,
            },
            Series {
                label: corrected_label.clone(),
                pieces: vec![curve(prediction, &refs, k)],
                once: false,
            },
        ];
        out.push(figure(
            &format!("discrepancy-{}", name.to_lowercase()),
            format!("{name}: measured, predicted and corrected"),
            "angle of attack alpha (deg)",
            &format!("{name} (-)"),
            series,
        )?);
    }
    Ok(out)
}

/// Recorded and simulated states against time, before and after the effects.
pub fn flight_figures(
    record: &FlightRecord,
    analysis: &FlightAnalysis,
) -> Result<Vec<Figure>, PlotError> {
    let recorded = [
        &record.airspeed_mps,
        &record.alpha_deg,
        &record.pitch_rate_dps,
        &record.theta_deg,
    ];
    let labels = [
        "airspeed (m/s)",
        "angle of attack (deg)",
        "pitch rate (deg/s)",
        "pitch attitude (deg)",
    ];
    let line = |v: &[f64]| -> Vec<(f64, f64)> {
        record.t.iter().copied().zip(v.iter().copied()).collect()
    };
    let mut out = Vec::new();
    for (k, state) in STATES.iter().enumerate() {
        let (Some(before), Some(after)) = (
            analysis.simulated_before.get(*state),
            analysis.simulated_after.get(*state),
        ) else {
            continue;
        };
        let series = vec![
            Series {
                label: "recorded".into(),
                pieces: vec![line(recorded[k])],
                once: false,
            },
            Series {
                label: "simulated, prediction".into(),
                pieces: vec![line(before)],
                once: false,
            },
            Series {
                label: "simulated, with the effects".into(),
                pieces: vec![line(after)],
                once: false,
            },
        ];
        out.push(figure(
            &format!("flight-{state}"),
            format!("{}: recorded and simulated", labels[k]),
            "time (s)",
            labels[k],
            series,
        )?);
    }
    Ok(out)
}
