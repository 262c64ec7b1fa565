//! The discrepancy workflow on synthetic data (issue 8): a DATCOM prediction of the bundled
//! example UAV plus hidden catalogue effects plus noise; and a flight with a hidden drag
//! increase. The generators are `datcom::discrepancy::synthetic` (docs/discrepancy.md).

mod common;

use datcom::discrepancy::{
    analyse_static,
    data::read_prediction,
    effects::{EffectId, Prediction},
    flight::{analyse_flight, Airframe},
    prediction::{from_deck, DeckModel},
    synthetic::{flight_record, static_measurement, typical, TUNNEL_NOISE},
    Analysis, Options,
};

/// Noise seeds per scenario (the issue asks for at least 20).
const SEEDS: u64 = 20;
/// Fractions the issue sets: an effect named in at least 90 % of seeds, its parameters inside
/// their 95 % intervals in at least 85 %, nothing named on noise alone in more than 10 %, two
/// hidden effects both found in at least 80 %.
const NAMED: f64 = 0.90;
const COVERED: f64 = 0.85;
const FALSE_ALARM: f64 = 0.10;
const BOTH_FOUND: f64 = 0.80;

fn model() -> DeckModel {
    let path = format!("{}/namelists/example-uav.dcm", env!("CARGO_MANIFEST_DIR"));
    let deck = datcom::read_deck_file(std::path::Path::new(&path)).unwrap();
    from_deck(&deck, 1, 0).unwrap()
}

/// Measured angles: every half degree over the prediction's range.
fn alphas(p: &Prediction) -> Vec<f64> {
    let (lo, hi) = (p.alpha_deg[0], p.alpha_deg[p.alpha_deg.len() - 1]);
    let n = ((hi - lo) / 0.5).round() as usize;
    (0..=n).map(|k| lo + 0.5 * k as f64).collect()
}

fn run(p: &Prediction, hidden: &[(EffectId, Vec<f64>)], seed: u64) -> Analysis {
    let refs: Vec<(EffectId, &[f64])> = hidden.iter().map(|(e, v)| (*e, v.as_slice())).collect();
    let m = static_measurement(p, &refs, &alphas(p), TUNNEL_NOISE, seed);
    analyse_static(p, &m, &Options::default()).unwrap()
}

fn named(a: &Analysis) -> Vec<EffectId> {
    a.effects.iter().map(|e| e.id).collect()
}

#[test]
fn each_hidden_effect_is_named_and_its_parameters_recovered() {
    let m = model();
    let p = &m.prediction;
    assert!(
        p.tail_cl.is_some(),
        "the example UAV's prediction has its tail terms"
    );
    for (k, id) in EffectId::ALL.into_iter().enumerate() {
        let truth = typical(id);
        let (mut right, mut covered) = (0, 0);
        for seed in 0..SEEDS {
            let a = run(p, &[(id, truth.clone())], 1000 * k as u64 + seed);
            if named(&a) == vec![id] {
                right += 1;
                let e = &a.effects[0];
                let inside = id.parameters().iter().zip(&truth).all(|(name, t)| {
                    e.ci95
                        .get(*name)
                        .is_some_and(|[lo, hi]| (*lo..=*hi).contains(t))
                });
                covered += usize::from(inside);
            }
        }
        eprintln!(
            "{}: named {right}/{SEEDS}, parameters inside the 95 % interval {covered}/{SEEDS}",
            id.name()
        );
        assert!(
            right as f64 >= NAMED * SEEDS as f64,
            "{}: named {right}/{SEEDS}",
            id.name()
        );
        assert!(
            covered as f64 >= COVERED * SEEDS as f64,
            "{}: covered {covered}/{SEEDS}",
            id.name()
        );
    }
}

#[test]
fn noise_alone_names_nothing() {
    let m = model();
    let alarms = (0..SEEDS)
        .filter(|seed| !run(&m.prediction, &[], 90_000 + seed).effects.is_empty())
        .count();
    eprintln!("no hidden effect: an effect named in {alarms}/{SEEDS} seeds");
    assert!(alarms as f64 <= FALSE_ALARM * SEEDS as f64);
}

#[test]
fn two_hidden_effects_are_both_found() {
    let m = model();
    let pairs = [
        (EffectId::ParasiteDrag, EffectId::Cm0Offset),
        (EffectId::LiftSlopeScale, EffectId::MomentReferenceShift),
        (EffectId::ZeroLiftShift, EffectId::InducedDragFactor),
        (EffectId::TailEfficiency, EffectId::ParasiteDrag),
    ];
    for (k, (a, b)) in pairs.into_iter().enumerate() {
        let hidden = vec![(a, typical(a)), (b, typical(b))];
        let found = (0..SEEDS)
            .filter(|seed| {
                let n = named(&run(&m.prediction, &hidden, 50_000 + 100 * k as u64 + seed));
                n.len() == 2 && n.contains(&a) && n.contains(&b)
            })
            .count();
        eprintln!("{} + {}: both found in {found}/{SEEDS}", a.name(), b.name());
        assert!(found as f64 >= BOTH_FOUND * SEEDS as f64);
    }
}

/// The airframe of the example UAV for the flight mode: mass from its WT, reference from the
/// deck, pitch damping from its dynamic page; the inertia and elevator derivatives are not in
/// a DATCOM deck and are set here (a 10 kg, 2.4 m span UAV: I_yy ≈ 1.2 kg m²; elevator
/// CL_δe 0.4, Cm_δe −1.2 per rad, tail volume 0.5 with τ ≈ 0.5).
fn airframe(m: &DeckModel) -> Airframe {
    Airframe {
        mass_kg: m.weight_n.unwrap() / datcom::discrepancy::flight::G,
        iyy_kgm2: 1.2,
        area_m2: m.reference_area_m2.unwrap(),
        chord_m: m.reference_chord_m.unwrap(),
        density_kgm3: m.density.unwrap(),
        clq_per_rad: m.clq_per_rad.unwrap_or(0.0),
        cmq_per_rad: m.cmq_per_rad.unwrap(),
        cl_de_per_rad: 0.4,
        cm_de_per_rad: -1.2,
    }
}

/// The UAV study's case: DATCOM's drag too low, the simulated aircraft flies too fast. With
/// a hidden ΔCD0 of 0.02 the workflow names parasite_drag and the airspeed error shrinks by
/// at least a factor 3 (the bar).
#[test]
fn a_flight_with_hidden_drag_names_parasite_drag_and_the_airspeed_error_shrinks() {
    let m = model();
    let a = airframe(&m);
    let hidden = [(EffectId::ParasiteDrag, &[0.02][..])];
    let record = flight_record(&m.prediction, &hidden, &a, 20.0, 0.05, 60.0, 4242).unwrap();
    let r = analyse_flight(&m.prediction, &a, &record, &Options::default()).unwrap();
    let ids: Vec<EffectId> = r.effects.iter().map(|e| e.id).collect();
    let (before, after) = (r.rms_before["airspeed_mps"], r.rms_after["airspeed_mps"]);
    eprintln!(
        "flight: named {ids:?}, dCD0 {:?}, airspeed RMS {before:.3} -> {after:.3} m/s (factor {:.1})",
        r.effects.first().map(|e| &e.parameters),
        before / after
    );
    assert_eq!(ids.first(), Some(&EffectId::ParasiteDrag));
    assert!(before >= 3.0 * after, "airspeed RMS {before} -> {after}");
}

fn bin() -> std::process::Command {
    std::process::Command::new(env!("CARGO_BIN_EXE_datcom-rs"))
}

fn temp_dir(name: &str) -> std::path::PathBuf {
    let d = std::env::temp_dir().join(format!(
        "datcom-rs-discrepancy-{name}-{}",
        std::process::id()
    ));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

fn example_deck() -> String {
    format!("{}/namelists/example-uav.dcm", env!("CARGO_MANIFEST_DIR"))
}

/// `datcom-rs discrepancy` on the example deck with `measured` and `extra` arguments, JSON and
/// plots written into `dir`: exit 0 asserted, the JSON returned.
fn discrepancy_json(
    dir: &std::path::Path,
    measured: &std::path::Path,
    extra: &[&std::ffi::OsStr],
) -> serde_json::Value {
    let deck = example_deck();
    discrepancy_output(dir, &["--model".as_ref(), deck.as_ref()], measured, extra).0
}

/// `datcom-rs discrepancy` with the `prediction` arguments (`--model DECK` or `--predicted
/// FILE`), `measured` and `extra`, JSON and plots written into `dir`: exit 0 asserted, the
/// JSON and the standard error returned.
fn discrepancy_output(
    dir: &std::path::Path,
    prediction: &[&std::ffi::OsStr],
    measured: &std::path::Path,
    extra: &[&std::ffi::OsStr],
) -> (serde_json::Value, String) {
    let json = dir.join("out.json");
    let out = bin()
        .arg("discrepancy")
        .args(prediction)
        .arg("--measured")
        .arg(measured)
        .args(extra)
        .arg("--json")
        .arg(&json)
        .arg("--plots")
        .arg(dir.join("plots"))
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr).into_owned();
    assert_eq!(out.status.code(), Some(0), "{stderr}");
    let v = serde_json::from_str(&std::fs::read_to_string(&json).unwrap()).unwrap();
    (v, stderr)
}

/// The command line in flight mode: a synthetic flight with hidden drag written as CSV, the
/// airframe values a deck lacks in a TOML file; the JSON names parasite_drag first and the
/// plots are written.
#[test]
fn the_command_line_finds_hidden_drag_in_a_recorded_flight() {
    let m = model();
    let a = airframe(&m);
    let hidden = [(EffectId::ParasiteDrag, &[0.02][..])];
    let record = flight_record(&m.prediction, &hidden, &a, 20.0, 0.05, 60.0, 77).unwrap();
    let dir = temp_dir("flight");
    let flight = dir.join("flight.csv");
    std::fs::write(&flight, record.to_csv()).unwrap();
    let frame = dir.join("airframe.toml");
    std::fs::write(
        &frame,
        "iyy_kgm2 = 1.2\ncl_de_per_rad = 0.4\ncm_de_per_rad = -1.2\n",
    )
    .unwrap();
    let v = discrepancy_json(
        &dir,
        &flight,
        &[
            "--flight".as_ref(),
            "--airframe".as_ref(),
            frame.as_os_str(),
        ],
    );
    let plots = dir.join("plots");
    assert_eq!(v["effects"][0]["id"], "parasite_drag");
    for key in ["rms_before", "rms_after", "confounded"] {
        assert!(!v[key].is_null(), "no {key} in the JSON");
    }
    // Regression (review 11): the threshold's value, not its internal name.
    let criterion = v["criterion"].as_str().unwrap();
    let threshold = Options::default().min_bic_drop;
    assert!(
        criterion.ends_with(&format!("falls by more than {threshold}")),
        "{criterion}"
    );
    let svg = std::fs::read_to_string(plots.join("flight-airspeed_mps.svg")).unwrap();
    for label in [
        "recorded",
        "simulated, prediction",
        "simulated, with the effects",
    ] {
        assert!(svg.contains(label), "no {label} in the airspeed plot");
    }
}

/// Synthetic tunnel data of the example UAV with a hidden parasite drag, as the CSV a user
/// gives (`alpha_deg,CL,CD,Cm`, plus a `sigma_CD` column of `sigma_cd` when given).
fn tunnel_csv(seed: u64, sigma_cd: Option<f64>) -> String {
    let m = model();
    let p = &m.prediction;
    let hidden = [(EffectId::ParasiteDrag, typical(EffectId::ParasiteDrag))];
    let refs: Vec<(EffectId, &[f64])> = hidden.iter().map(|(e, v)| (*e, v.as_slice())).collect();
    let meas = static_measurement(p, &refs, &alphas(p), TUNNEL_NOISE, seed);
    let mut csv = String::from("alpha_deg,CL,CD,Cm");
    csv.push_str(if sigma_cd.is_some() {
        ",sigma_CD\n"
    } else {
        "\n"
    });
    for (k, a) in meas.alpha_deg.iter().enumerate() {
        let v = |c: &str| meas.values[c][k].unwrap();
        csv.push_str(&format!("{a},{},{},{}", v("CL"), v("CD"), v("Cm")));
        match sigma_cd {
            Some(s) => csv.push_str(&format!(",{s}\n")),
            None => csv.push('\n'),
        }
    }
    csv
}

/// A static CSV through the command line: the JSON has the shape and the plots
/// carry the three series; a missing column is an error naming it.
#[test]
fn the_command_line_reads_static_measurements_and_says_what_is_wrong() {
    let dir = temp_dir("static");
    let measured = dir.join("tunnel.csv");
    std::fs::write(&measured, tunnel_csv(5, None)).unwrap();
    let v = discrepancy_json(&dir, &measured, &[]);
    let plots = dir.join("plots");
    assert_eq!(v["effects"][0]["id"], "parasite_drag");
    assert!(v["effects"][0]["ci95"]["dCD0"].is_array());
    let svg = std::fs::read_to_string(plots.join("discrepancy-cd.svg")).unwrap();
    for label in ["measured", "predicted (DATCOM)", "corrected: parasite_drag"] {
        assert!(svg.contains(label), "no {label} in the CD plot");
    }
    let bad = dir.join("bad.csv");
    std::fs::write(&bad, "alpha,CL\n0,0.1\n").unwrap();
    let out = bin()
        .args(["discrepancy", "--model", &example_deck(), "--measured"])
        .arg(&bad)
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("no column alpha_deg"));
}

/// Regression (review 11): with `--sigma` the report said the noise was "given (sigma_CD) at
/// every row", as if the CSV had that column, and its criterion named the internal
/// `min_bic_drop` instead of the threshold. Now the source is `--sigma` (a real column is
/// named as a column) and the criterion gives the value.
#[test]
fn the_report_says_where_the_noise_came_from_and_the_threshold() {
    let dir = temp_dir("sigma-source");
    let measured = dir.join("tunnel.csv");
    std::fs::write(&measured, tunnel_csv(5, None)).unwrap();
    let v = discrepancy_json(
        &dir,
        &measured,
        &["--sigma".as_ref(), "CL=0.005,CD=0.001,Cm=0.002".as_ref()],
    );
    for c in ["CL", "CD", "Cm"] {
        assert_eq!(v["sigma_source"][c], "given by --sigma", "{c}");
    }
    let criterion = v["criterion"].as_str().unwrap();
    let threshold = Options::default().min_bic_drop;
    assert!(
        criterion.ends_with(&format!("falls by more than {threshold}"))
            && !criterion.contains("min_bic_drop"),
        "{criterion}"
    );
    let with_column = dir.join("tunnel-sigma.csv");
    std::fs::write(&with_column, tunnel_csv(5, Some(0.001))).unwrap();
    let v = discrepancy_json(&dir, &with_column, &[]);
    assert_eq!(
        v["sigma_source"]["CD"],
        "given by the sigma_CD column at every row"
    );
}

/// Regression (review 6): `--predicted` refused the CSV that `run --format csv` writes
/// ("column caseid: expected a finite number"). It reads it: each flight condition's curve is
/// the deck's prediction as `--model` gives it (less the tail's contributions), the analysis
/// runs, a note says which case and condition were read, and a file of neither form is
/// refused naming the columns each form needs.
#[test]
fn the_csv_of_run_is_read_as_a_prediction() {
    let dir = temp_dir("run-csv");
    let out = bin()
        .args(["run", &example_deck(), "--format", "csv"])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(0));
    let text = String::from_utf8(out.stdout).unwrap();
    let run_csv = dir.join("uav.csv");
    std::fs::write(&run_csv, &text).unwrap();
    // Exact equality: the CSV prints each number's shortest round-trip digits.
    let deck = datcom::read_deck_file(std::path::Path::new(&example_deck())).unwrap();
    for condition in 1..=4 {
        let read = read_prediction(&text, "uav.csv", 1, condition).unwrap();
        let m = from_deck(&deck, 1, condition - 1).unwrap();
        let p = &read.prediction;
        let q = &m.prediction;
        assert_eq!(
            (&p.alpha_deg, &p.cl, &p.cd, &p.cm),
            (&q.alpha_deg, &q.cl, &q.cd, &q.cm),
            "condition {condition}"
        );
        assert_eq!(p.tail_cl, None);
    }
    let measured = dir.join("tunnel.csv");
    std::fs::write(&measured, tunnel_csv(5, None)).unwrap();
    let (v, stderr) = discrepancy_output(
        &dir,
        &["--predicted".as_ref(), run_csv.as_os_str()],
        &measured,
        &[],
    );
    assert_eq!(v["effects"][0]["id"], "parasite_drag");
    assert!(
        stderr.contains("read case 1 of 1, flight condition 1 of 4 (Mach 0.06, altitude 0)")
            && stderr.contains("choose another with --case and --condition"),
        "{stderr}"
    );
    let neither = dir.join("neither.csv");
    std::fs::write(&neither, "a,b\n1,2\n").unwrap();
    let out = bin()
        .args(["discrepancy", "--predicted"])
        .arg(&neither)
        .arg("--measured")
        .arg(&measured)
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("alpha_deg, CL, CD, Cm") && err.contains("run --format csv"),
        "{err}"
    );
}

/// Regression (review 23): without a prediction the usage error named only `--model`; it
/// names both ways of giving one.
#[test]
fn a_missing_prediction_names_model_and_predicted() {
    let dir = temp_dir("no-prediction");
    let measured = dir.join("m.csv");
    std::fs::write(&measured, "alpha_deg,CL\n0,0.1\n").unwrap();
    let out = bin()
        .args(["discrepancy", "--measured"])
        .arg(&measured)
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("--model") && err.contains("--predicted"),
        "{err}"
    );
}

/// Issue 8, real data: the NASA Ultra Stick 120 tunnel tables against our DATCOM model
/// (namelists/ultrastick120.dcm), with the tables' 2° alpha offset removed and below stall
/// (docs/discrepancy-ultrastick120.md). The workflow names the pitching-moment offset, the
/// parasite drag and the zero-lift shift, and every coefficient's RMS falls.
#[test]
fn the_ultrastick120_tunnel_data_name_the_documented_effects() {
    let Some(dir) = common::shared_dir("data/ultrastick120", "discrepancy ultrastick120") else {
        return;
    };
    let text = std::fs::read_to_string(dir.join("aero_static.csv")).unwrap();
    let mut measured = datcom::discrepancy::data::read_measurement(&text, "aero_static.csv")
        .unwrap()
        .with_alpha_offset(2.0);
    for (c, s) in [("CL", 0.005), ("CD", 0.001), ("Cm", 0.002)] {
        measured = measured.with_sigma(c, s).unwrap();
    }
    let path = format!("{}/namelists/ultrastick120.dcm", env!("CARGO_MANIFEST_DIR"));
    let deck = datcom::read_deck_file(std::path::Path::new(&path)).unwrap();
    let m = from_deck(&deck, 1, 0).unwrap();
    let options = Options {
        alpha_range_deg: Some((-6.0, 10.5)),
        ..Options::default()
    };
    let a = analyse_static(&m.prediction, &measured, &options).unwrap();
    eprintln!("{}", a.to_text());
    assert_eq!(
        named(&a),
        vec![
            EffectId::Cm0Offset,
            EffectId::ParasiteDrag,
            EffectId::ZeroLiftShift
        ]
    );
    let dcd0 = a.effects[1].parameters["dCD0"];
    assert!((0.01..0.03).contains(&dcd0), "dCD0 {dcd0}");
    for c in ["CL", "CD", "Cm"] {
        assert!(
            a.rms_after[c] < 0.5 * a.rms_before[c],
            "{c}: {:?} {:?}",
            a.rms_before,
            a.rms_after
        );
    }
    the_ultrastick120_doc_gives_the_figures_of(&a);
}

/// Regression (review 20): docs/discrepancy-ultrastick120.md had gone stale (a BIC fall of
/// 3009 where the tool prints 3006.7, "BIC −136" for "falls by 136.4"). Its figures are the
/// tool's, as the tool rounds them: the |z| range and BIC falls to 0.1, the RMS to 0.0001.
fn the_ultrastick120_doc_gives_the_figures_of(a: &Analysis) {
    let path = format!(
        "{}/docs/discrepancy-ultrastick120.md",
        env!("CARGO_MANIFEST_DIR")
    );
    let doc = std::fs::read_to_string(path).unwrap();
    let z: Vec<f64> = a.residuals.iter().map(|b| b.z.abs()).collect();
    let (lo, hi) = z
        .iter()
        .fold((f64::INFINITY, 0.0_f64), |(l, h), v| (l.min(*v), h.max(*v)));
    let range = format!("|z| from {lo:.1} to {hi:.1}");
    assert!(doc.contains(&range), "the doc does not say {range}");
    for e in &a.effects {
        let row = format!("| `{}` |", e.id.name());
        let line = doc
            .lines()
            .find(|l| l.starts_with(&row))
            .unwrap_or_default();
        let bic = format!("| {:.1} |", e.evidence.bic_drop);
        assert!(
            line.ends_with(&bic),
            "{row}: the doc has {line:?}, the tool {bic}"
        );
    }
    // The last step: the candidates that lower BIC but are not named, each with its fall.
    let rest = doc
        .split("Then nothing more passes")
        .nth(1)
        .and_then(|s| s.split("\n\n").next())
        .unwrap_or_default();
    let last = a.selection.last().unwrap();
    for t in &last.candidates {
        let name = format!("`{}`", t.effect.name());
        let said = rest
            .split_once(name.as_str())
            .and_then(|(_, after)| after.split_once('(')?.1.split_once(')'))
            .map(|(inside, _)| inside.to_string())
            .unwrap_or_default();
        let fall = format!("{:.1}", t.bic_drop);
        assert!(
            said.ends_with(&fall),
            "{name}: the doc has {said:?}, the tool {fall}"
        );
    }
    for (label, rms) in [
        ("DATCOM", &a.rms_before),
        ("with the three effects", &a.rms_after),
    ] {
        let row = format!(
            "| {label} | {:.4} | {:.4} | {:.4} |",
            rms["CL"], rms["CD"], rms["Cm"]
        );
        assert!(doc.contains(&row), "the doc does not have {row}");
    }
}

/// A prediction with a flat lift curve (CL 0.5 at every angle): on it a moment offset and a
/// moment-reference shift (dx·CL) are the same thing, as are parasite and induced drag.
fn flat_prediction() -> Prediction {
    let alpha: Vec<f64> = (-4..=12).map(f64::from).collect();
    Prediction {
        cl: vec![0.5; alpha.len()],
        cd: alpha.iter().map(|a| 0.03 + 0.0005 * a * a).collect(),
        cm: alpha.iter().map(|a| -0.01 * a).collect(),
        tail_cl: None,
        tail_cm: None,
        alpha_deg: alpha,
    }
}

/// Regression (review): a confounded pair stopped the whole selection and the report said
/// nothing was missing. Now the pair is reported and set aside, and an effect on another
/// coefficient is still found.
#[test]
fn a_confounded_pair_is_set_aside_and_the_selection_goes_on() {
    let p = flat_prediction();
    let hidden = [
        (EffectId::Cm0Offset, &[-0.03][..]),
        (EffectId::LiftSlopeScale, &[0.9][..]),
    ];
    let m = static_measurement(&p, &hidden, &alphas(&p), TUNNEL_NOISE, 11);
    let a = analyse_static(&p, &m, &Options::default()).unwrap();
    assert_eq!(named(&a), vec![EffectId::LiftSlopeScale], "{}", a.to_text());
    assert!(
        a.confounded.iter().any(
            |g| g.contains(&EffectId::Cm0Offset) && g.contains(&EffectId::MomentReferenceShift)
        ),
        "{:?}",
        a.confounded
    );
}

/// Regression (review): the rows' sigma_<coef> were averaged into one noise; a single
/// uncertain outlier (σ 10) then hid a clear drag gap measured at σ 0.001.
#[test]
fn each_row_is_weighted_by_its_own_sigma() {
    let m = model();
    let p = &m.prediction;
    let hidden = [(EffectId::ParasiteDrag, &[0.01][..])];
    let mut meas = static_measurement(p, &hidden, &alphas(p), TUNNEL_NOISE, 3);
    let n = meas.alpha_deg.len();
    let mut sigma = vec![Some(0.001); n];
    if let Some(cd) = meas.values.get_mut("CD") {
        cd[0] = cd[0].map(|v| v + 0.5);
    }
    sigma[0] = Some(10.0);
    meas.sigma.insert("CD".into(), sigma);
    let a = analyse_static(p, &meas, &Options::default()).unwrap();
    assert_eq!(
        named(&a).first(),
        Some(&EffectId::ParasiteDrag),
        "{}",
        a.to_text()
    );
}

/// Regression (review): a coefficient whose noise could not be estimated got σ = 1 silently.
#[test]
fn noise_that_cannot_be_estimated_is_an_error_asking_for_sigma() {
    let m = model();
    let p = &m.prediction;
    let meas = static_measurement(p, &[], &[0.0, 4.0], TUNNEL_NOISE, 1);
    let e = analyse_static(p, &meas, &Options::default()).unwrap_err();
    assert!(e.to_string().contains("--sigma"), "{e}");
}
