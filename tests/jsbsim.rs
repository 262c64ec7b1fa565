//! Acceptance of the JSBSim export (issue 9): each deck below is exported as a whole aircraft
//! by the command line, loaded and flown by JSBSim itself (tests/jsbsim/trim_check.py, the
//! `jsbsim` Python package), and JSBSim's coefficients at the trim angle of attack, at other
//! angles and with sideslip and body rates must equal ours; a 10 s glide must stay finite.
//!
//! `cargo test --test jsbsim -- --nocapture` prints the figures. Without python3 or its
//! `jsbsim` module the test says `SKIPPED ...` and passes, except when the environment variable
//! CI is set, where it fails (.ci/run installs jsbsim first).

mod common;

use std::path::{Path, PathBuf};
use std::process::Command;

use datcom::results::ConditionResults;

/// JSBSim must give back our coefficients to 0.5 %: the tables are written to eight
/// significant digits and JSBSim interpolates linearly between them as we do here, so the
/// only differences left are JSBSim's Mach number (its atmosphere and ours differ in the last
/// digits) and rounding; a unit, axis, sign or table error is far larger.
const REL_TOL: f64 = 0.005;

/// The magnitude below which a percentage is meaningless (Cm is zero at the pitch trim by
/// construction): errors are taken relative to max(|ours|, this). A thousandth is below the
/// precision DATCOM prints coefficients to.
const COEFF_FLOOR: f64 = 1e-3;

/// Seconds of the glide that must stay finite.
const SIMULATED_S: f64 = 10.0;

const M_PER_FT: f64 = 0.3048;

/// A deck to fly, with what JSBSim needs that the deck may not give.
struct Flight {
    label: &'static str,
    deck: PathBuf,
    /// lbf, when the deck has no WT.
    weight_lbf: Option<f64>,
    /// Ixx, Iyy, Izz, slug·ft², when known (else the export's estimate).
    inertia_slugft2: Option<[f64; 3]>,
}

/// The decks of the acceptance test: the bundled ones (add a line to extend), then oracle
/// decks from ../shared when it is present.
fn flights() -> Vec<Flight> {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    let bundled = ["example-uav", "aeromech1"];
    let mut out: Vec<Flight> = bundled
        .iter()
        .map(|name| root.join("namelists").join(format!("{name}.dcm")))
        .zip(bundled)
        .filter(|(p, _)| p.is_file())
        .map(|(deck, label)| Flight {
            label,
            deck,
            weight_lbf: None,
            inertia_slugft2: None,
        })
        .collect();
    if let Some(cases) = common::shared_dir("oracle/cases", "jsbsim (oracle decks)") {
        out.push(Flight {
            label: "uav_example",
            deck: cases.join("uav_example/input.dcm"),
            weight_lbf: None,
            inertia_slugft2: None,
        });
        // The deck has no WT. Navion's gross weight and inertias: Nelson, Flight Stability and
        // Automatic Control (2nd ed.), appendix B (W = 2750 lb; Ixx, Iyy, Izz = 1048, 3000,
        // 3530 slug·ft²).
        out.push(Flight {
            label: "navion",
            deck: cases.join("arktools__Navion_clean/input.dcm"),
            weight_lbf: Some(2750.0),
            inertia_slugft2: Some([1048.0, 3000.0, 3530.0]),
        });
    }
    out
}

/// Whether python3 with the jsbsim module can run, or why not.
fn python_jsbsim() -> Result<String, String> {
    let out = Command::new("python3")
        .args(["-c", "import jsbsim; print(jsbsim.__version__)"])
        .output()
        .map_err(|e| format!("python3 cannot be run ({e})"))?;
    if !out.status.success() {
        return Err(format!(
            "python3 has no jsbsim module ({})",
            String::from_utf8_lossy(&out.stderr)
                .lines()
                .last()
                .unwrap_or("")
        ));
    }
    Ok(String::from_utf8_lossy(&out.stdout).trim().to_string())
}

/// A result column by its DATCOM name (empty without DAMP).
fn column<'a>(c: &'a ConditionResults, name: &str) -> &'a [Option<f64>] {
    c.column(name).unwrap_or(&[])
}

/// Our value of a column at α (deg) in one condition: linear between the two angles around
/// it; a derivative given on the first angle only is that value at every angle.
fn at_alpha(alpha_deg: &[f64], values: &[Option<f64>], a: f64) -> Option<f64> {
    if values.len() > 1 && values[1..].iter().all(Option::is_none) && values[0].is_some() {
        return values[0];
    }
    let i = alpha_deg.windows(2).position(|w| w[0] <= a && a <= w[1])?;
    let (a0, a1) = (alpha_deg[i], alpha_deg[i + 1]);
    let (v0, v1) = (values.get(i).copied()??, values.get(i + 1).copied()??);
    Some(v0 + (v1 - v0) * (a - a0) / (a1 - a0))
}

/// Our value at α (deg) and Mach: linear in α in each condition, then in Mach (held beyond
/// the first and last, as JSBSim does).
fn ours(conditions: &[&ConditionResults], name: &str, alpha_deg: f64, mach: f64) -> Option<f64> {
    let v = |c: &ConditionResults| at_alpha(&c.alpha_deg, column(c, name), alpha_deg);
    let m: Vec<f64> = conditions.iter().map(|c| c.condition.mach).collect();
    if conditions.len() == 1 || mach <= m[0] {
        return v(conditions[0]);
    }
    if mach >= m[m.len() - 1] {
        return v(conditions[m.len() - 1]);
    }
    let i = m.windows(2).position(|w| w[0] <= mach && mach <= w[1])?;
    let (v0, v1) = (v(conditions[i])?, v(conditions[i + 1])?);
    Some(v0 + (v1 - v0) * (mach - m[i]) / (m[i + 1] - m[i]))
}

/// Each exported function: its DATCOM column and the sample's fields it is multiplied by.
const FUNCTIONS: [(&str, &str, &str); 15] = [
    ("CL", "CL", "qbar_psf sw_sqft"),
    ("CLq", "CLQ", "qbar_psf sw_sqft ci2vel q_rad_sec"),
    ("CLadot", "CLAD", "qbar_psf sw_sqft ci2vel alphadot_rad_sec"),
    ("CD", "CD", "qbar_psf sw_sqft"),
    ("CYb", "CYB", "qbar_psf sw_sqft beta_rad"),
    ("CYp", "CYP", "qbar_psf sw_sqft bi2vel p_rad_sec"),
    ("Clb", "CLB", "qbar_psf sw_sqft bw_ft beta_rad"),
    ("Clp", "CLP", "qbar_psf sw_sqft bw_ft bi2vel p_rad_sec"),
    ("Clr", "CLR", "qbar_psf sw_sqft bw_ft bi2vel r_rad_sec"),
    ("Cm", "CM", "qbar_psf sw_sqft cbarw_ft"),
    ("Cmq", "CMQ", "qbar_psf sw_sqft cbarw_ft ci2vel q_rad_sec"),
    (
        "Cmadot",
        "CMAD",
        "qbar_psf sw_sqft cbarw_ft ci2vel alphadot_rad_sec",
    ),
    ("Cnb", "CNB", "qbar_psf sw_sqft bw_ft beta_rad"),
    ("Cnp", "CNP", "qbar_psf sw_sqft bw_ft bi2vel p_rad_sec"),
    ("Cnr", "CNR", "qbar_psf sw_sqft bw_ft bi2vel r_rad_sec"),
];

fn field(sample: &serde_json::Value, key: &str) -> f64 {
    sample[key]
        .as_f64()
        .unwrap_or_else(|| panic!("no {key} in {sample}"))
}

/// One comparison: (what, JSBSim, ours).
type Row = (String, f64, f64);

fn relative(jsbsim: f64, ours: f64) -> f64 {
    (jsbsim - ours).abs() / ours.abs().max(COEFF_FLOOR)
}

/// Compares one JSBSim sample with our coefficients: every function whose factors are not
/// zero, and (without sideslip or rates) CL, CD and Cm from JSBSim's total forces and moment.
fn compare_sample(conditions: &[&ConditionResults], s: &serde_json::Value) -> Vec<Row> {
    let kind = s["kind"].as_str().unwrap_or("?");
    let alpha_rad = field(s, "alpha_rad");
    let alpha_deg = alpha_rad.to_degrees();
    let mach = field(s, "mach");
    let at = |name: &str| {
        ours(conditions, name, alpha_deg, mach)
            .unwrap_or_else(|| panic!("{name}: no value of ours at alpha {alpha_deg} deg"))
    };
    let mut rows = Vec::new();
    let functions = &s["functions"];
    for (name, col, factors) in FUNCTIONS {
        let Some(value) = functions[name].as_f64() else {
            continue;
        };
        let scale: f64 = factors.split_whitespace().map(|f| field(s, f)).product();
        if scale.abs() < 1e-9 {
            continue;
        }
        rows.push((format!("{kind} {name}"), value / scale, at(col)));
    }
    if kind != "rates" {
        let (qs, c) = (
            field(s, "qbar_psf") * field(s, "sw_sqft"),
            field(s, "cbarw_ft"),
        );
        let (fx, fz) = (field(s, "fbx_lbs"), field(s, "fbz_lbs"));
        let (sin, cos) = alpha_rad.sin_cos();
        let adot = field(s, "alphadot_rad_sec") * field(s, "ci2vel");
        let dynamic = |name: &str| {
            if adot == 0.0 {
                0.0
            } else {
                at(name) * adot
            }
        };
        rows.push((
            format!("{kind} CL from forces"),
            (fx * sin - fz * cos) / qs,
            at("CL") + dynamic("CLAD"),
        ));
        rows.push((
            format!("{kind} CD from forces"),
            (-fx * cos - fz * sin) / qs,
            at("CD"),
        ));
        rows.push((
            format!("{kind} Cm from moment"),
            field(s, "m_lbsft") / (qs * c),
            at("CM") + dynamic("CMAD"),
        ));
    }
    rows
}

/// Exports, flies and compares one deck; returns the failures.
fn fly(f: &Flight, tmp: &Path) -> Vec<String> {
    let deck = datcom::read_deck_file(&f.deck).expect("readable deck");
    let results = datcom::results::run_case(&deck.cases[0]);
    let (conditions, _) = datcom::report::jsbsim::conditions(&results).expect("conditions");
    let cruise = conditions
        .last()
        .unwrap_or_else(|| panic!("{}: no condition", f.label));
    let speed_fps = cruise.condition.velocity.expect("a velocity") / M_PER_FT;
    let altitude_ft = cruise.condition.altitude.unwrap_or(0.0) / M_PER_FT;
    // The angles where CL, CD and Cm all have a value: where the trim is looked for.
    let alpha = &cruise.alpha_deg;
    let valid: Vec<f64> = (0..alpha.len())
        .filter(|&i| {
            ["CL", "CD", "CM"]
                .iter()
                .all(|n| conditions.iter().all(|c| column(c, n)[i].is_some()))
        })
        .map(|i| alpha[i])
        .collect();
    let (lo, hi) = (valid[0], valid[valid.len() - 1]);
    // Two more angles between table nodes, so that JSBSim's interpolation is exercised.
    let others = [lo + 0.3 * (valid[1] - lo), 0.5 * (lo + hi) + 0.25];

    let mut cmd = Command::new(env!("CARGO_BIN_EXE_datcom-rs"));
    cmd.args(["export", "jsbsim"])
        .arg(&f.deck)
        .arg("-o")
        .arg(tmp.join(format!("{}-aero.xml", f.label)))
        .arg("--aircraft")
        .arg(tmp.join("aircraft"))
        .args(["--name", f.label]);
    if let Some(w) = f.weight_lbf {
        cmd.arg(format!("--weight-lbf={w}"));
    }
    if let Some([a, b, c]) = f.inertia_slugft2 {
        cmd.arg(format!("--inertia-slugft2={a},{b},{c}"));
    }
    let out = cmd.output().expect("datcom-rs runs");
    assert!(
        out.status.success(),
        "{}: export failed: {}",
        f.label,
        String::from_utf8_lossy(&out.stderr)
    );
    let aero = std::fs::read_to_string(tmp.join(format!("{}-aero.xml", f.label))).unwrap();
    assert!(
        !aero.contains("NaN") && !aero.contains("inf"),
        "{}: a NaN or infinity was written",
        f.label
    );

    let json_path = tmp.join(format!("{}.json", f.label));
    let script = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("tests/jsbsim/trim_check.py");
    let out = Command::new("python3")
        .arg(&script)
        .arg("--root")
        .arg(tmp)
        .args(["--model", f.label])
        .arg(format!("--altitude-ft={altitude_ft}"))
        .arg(format!("--speed-fps={speed_fps}"))
        .arg(format!("--alpha-range-deg={lo},{hi}"))
        .arg(format!("--alphas-deg={},{}", others[0], others[1]))
        .arg(format!("--seconds={SIMULATED_S}"))
        .arg("--out")
        .arg(&json_path)
        .output()
        .expect("python3 runs");
    assert!(
        out.status.success(),
        "{}: trim_check.py failed:\n{}\n{}",
        f.label,
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    );
    let report: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&json_path).unwrap()).unwrap();

    let mut failures = Vec::new();
    println!(
        "\n{}: {} (Mach {:.4}, {:.0} ft, {:.1} ft/s); trim: {}, alpha = {:.4} deg",
        f.label,
        f.deck.display(),
        cruise.condition.mach,
        altitude_ft,
        speed_fps,
        report["trim"]["method"].as_str().unwrap_or("?"),
        report["trim"]["alpha_deg"].as_f64().unwrap_or(f64::NAN)
    );
    println!(
        "  {:<28} {:>10} {:>14} {:>14} {:>9}",
        "sample term", "alpha deg", "JSBSim", "ours", "diff %"
    );
    let mut worst = 0.0_f64;
    for s in report["samples"].as_array().expect("samples") {
        let alpha_deg = field(s, "alpha_rad").to_degrees();
        for (what, jsb, our) in compare_sample(&conditions, s) {
            let rel = relative(jsb, our);
            worst = worst.max(rel);
            println!(
                "  {what:<28} {alpha_deg:>10.4} {jsb:>14.7} {our:>14.7} {:>9.4}",
                100.0 * rel
            );
            if rel.is_nan() || rel > REL_TOL {
                failures.push(format!(
                    "{}: {what} at alpha {alpha_deg:.3} deg: JSBSim {jsb}, ours {our} ({:.3} %)",
                    f.label,
                    100.0 * rel
                ));
            }
        }
    }
    println!(
        "  largest difference: {:.2e} % (tolerance {} %)",
        100.0 * worst,
        100.0 * REL_TOL
    );
    let sim = &report["simulation"];
    println!(
        "  glide from the trim: {} s at {:.1} ft/s, gamma {:.2} deg, altitude {:.0} to {:.0} ft, every state finite: {}",
        sim["time_s"].as_f64().unwrap_or(0.0),
        sim["speed_fps"].as_f64().unwrap_or(f64::NAN),
        sim["gamma_deg"].as_f64().unwrap_or(f64::NAN),
        sim["h_min_ft"].as_f64().unwrap_or(f64::NAN),
        sim["h_max_ft"].as_f64().unwrap_or(f64::NAN),
        sim["finite"]
    );
    if sim["finite"].as_bool() != Some(true) {
        failures.push(format!(
            "{}: a state left the finite numbers: {}",
            f.label, sim["first_non_finite"]
        ));
    }
    if sim["time_s"].as_f64().unwrap_or(0.0) < SIMULATED_S - 0.1 {
        failures.push(format!(
            "{}: the simulation stopped before {SIMULATED_S} s",
            f.label
        ));
    }
    failures
}

#[test]
fn jsbsim_flies_the_export_with_our_coefficients() {
    match python_jsbsim() {
        Ok(version) => println!("JSBSim {version} (Python package)"),
        Err(why) if std::env::var_os("CI").is_some() => {
            panic!("CI is set and {why}: the JSBSim acceptance test may not be skipped in CI (.ci/run installs jsbsim)")
        }
        Err(why) => {
            eprintln!("SKIPPED jsbsim_flies_the_export_with_our_coefficients: {why} (python3 -m pip install jsbsim==1.3.3)");
            return;
        }
    }
    let tmp = std::env::temp_dir().join(format!("datcom-rs-jsbsim-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&tmp);
    std::fs::create_dir_all(&tmp).unwrap();
    let flights = flights();
    assert!(!flights.is_empty(), "no deck to fly");
    let failures: Vec<String> = flights.iter().flat_map(|f| fly(f, &tmp)).collect();
    let _ = std::fs::remove_dir_all(&tmp);
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

/// The export itself, without JSBSim: every axis and term of a complete deck, and nothing
/// padded where DATCOM gives no value.
#[test]
fn the_example_exports_every_axis_and_term() {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("namelists/example-uav.dcm");
    let deck = datcom::read_deck_file(&path).unwrap();
    let results = datcom::results::run_case(&deck.cases[0]);
    let model = datcom::report::jsbsim::model("example-uav.dcm", &results).unwrap();
    let xml = datcom::report::jsbsim::aerodynamics_xml(&model);
    for axis in ["LIFT", "DRAG", "SIDE", "ROLL", "PITCH", "YAW"] {
        assert!(xml.contains(&format!("<axis name=\"{axis}\">")), "{axis}");
    }
    for (name, _, _) in FUNCTIONS {
        assert!(
            xml.contains(&format!("<function name=\"aero/coefficient/{name}\">")),
            "{name}"
        );
    }
    assert_eq!(xml.matches("<description>").count(), FUNCTIONS.len());
    assert!(xml.contains(&format!("datcom-rs {}", env!("CARGO_PKG_VERSION"))));
    // Two Mach numbers at the first altitude: Mach is the tables' second index; 500 m is said
    // to be left out.
    assert!(xml.contains("<independentVar lookup=\"column\">velocities/mach</independentVar>"));
    assert!(xml.contains("Mach 0.06 at 500 m: only the first altitude is exported"));
}

#[test]
fn a_table_is_cut_where_datcom_gives_no_value_and_the_header_says_so() {
    let Some(cases) = common::shared_dir("oracle/cases", "jsbsim table cut") else {
        return;
    };
    let deck = datcom::read_deck_file(&cases.join("uav_example/input.dcm")).unwrap();
    let results = datcom::results::run_case(&deck.cases[0]);
    // CM has no value beyond CLmax (14 to 18 deg) in this deck.
    assert!(results.conditions.last().unwrap().static_coefficients.cm[10].is_none());
    let model = datcom::report::jsbsim::model("uav_example", &results).unwrap();
    let cm = model.functions.iter().find(|f| f.name == "Cm").unwrap();
    let datcom::report::jsbsim::Coefficient::OverAlpha { alpha_rad, .. } = &cm.coefficient else {
        panic!("Cm is a table over alpha");
    };
    assert_eq!(alpha_rad.len(), 10, "-6 to 12 deg");
    let xml = datcom::report::jsbsim::aerodynamics_xml(&model);
    assert!(xml.contains(
        "Cm: CM has no value at alpha = 14, 16, 18 deg; tabulated for alpha = -6 to 12 deg only"
    ));
    // CL has a value at every angle: all 13 rows.
    let cl = model.functions.iter().find(|f| f.name == "CL").unwrap();
    assert!(cl.cut.is_none());
}

#[test]
fn a_deck_without_coefficients_is_a_typed_error() {
    let text = " $FLTCON NMACH=1.0, MACH(1)=0.4, NALT=1.0, ALT(1)=0.0,\n   NALPHA=2.0, ALSCHD(1)=0.0,4.0$\n $SYNTHS XCG=1.0$\n";
    let deck = datcom::read_deck(text, "empty.dcm");
    let results = datcom::results::run_case(&deck.cases[0]);
    let err = datcom::report::jsbsim::model("empty.dcm", &results).unwrap_err();
    assert!(
        matches!(
            err,
            datcom::report::jsbsim::ExportError::NothingExportable { .. }
        ),
        "{err}"
    );
}

#[test]
fn an_aircraft_without_weight_is_a_typed_error() {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("namelists/example-uav.dcm");
    let mut deck = datcom::read_deck_file(&path).unwrap();
    deck.cases[0].flight.as_mut().unwrap().weight = None;
    let results = datcom::results::run_case(&deck.cases[0]);
    let model = datcom::report::jsbsim::model("x", &results).unwrap();
    let options = datcom::report::jsbsim::AircraftOptions {
        name: "x".into(),
        ..Default::default()
    };
    let err = datcom::report::jsbsim::aircraft_xml(&model, &deck.cases[0], &options).unwrap_err();
    assert_eq!(
        err,
        datcom::report::jsbsim::ExportError::MissingWeight { case: 1 }
    );
}

/// The user review found a deck with a Mach number beyond the methods' subsonic range beside
/// one within it exported nothing ("has no coefficient with a value"): every term's table
/// over Mach needed a value at every Mach number. Such a condition is left out, and the header
/// says so.
#[test]
fn a_mach_number_without_values_is_left_out_of_the_export() {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("namelists/example-uav.dcm");
    let mut deck = datcom::read_deck_file(&path).unwrap();
    let case = &mut deck.cases[0];
    case.flight.as_mut().unwrap().mach = vec![0.3, 0.7];
    case.prepare();
    let results = datcom::results::run_case(case);
    let model = datcom::report::jsbsim::model("x", &results).unwrap();
    assert_eq!(model.mach, [0.3]);
    assert!(
        model
            .conditions_not_used
            .iter()
            .any(|c| c.starts_with("Mach 0.7 at 0 m: no coefficient has a value")),
        "{:?}",
        model.conditions_not_used
    );
    // Every Mach number without values: the error names them.
    case.flight.as_mut().unwrap().mach = vec![0.7, 0.8];
    case.prepare();
    let results = datcom::results::run_case(case);
    let err = datcom::report::jsbsim::model("x", &results).unwrap_err();
    assert!(
        err.to_string()
            .contains("(Mach 0.7 at 0 m; Mach 0.8 at 0 m"),
        "{err}"
    );
}
