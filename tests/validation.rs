//! Published reference cases and the AEROMECH I hand calculation (issue 7): `report` on each
//! bundled deck against its reference file in tests/reference/, every derivative's error held
//! within a band. docs/validation.md gives the tables and the reasons for the bands.

use datcom::report::percent_error::{report, Family, Reference, Report};

fn root(path: &str) -> std::path::PathBuf {
    std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join(path)
}

fn run(reference: &str) -> Report {
    let file = root(reference);
    let text = std::fs::read_to_string(&file).unwrap();
    let r = Reference::from_toml(&text, reference).unwrap();
    let deck = datcom::read_deck_file(&root(r.deck.as_deref().unwrap())).unwrap();
    assert!(
        !datcom::Diagnosed::has_errors(&deck),
        "{:?}",
        deck.diagnostics
    );
    report(&datcom::run(&deck), &r).unwrap()
}

/// Error bands, percent of the reference. They are regression guards around what DATCOM's
/// methods give for light aircraft, not accuracy claims (docs/validation.md):
/// - lift-curve slope and the lateral-directional static derivatives: DATCOM's build-up of
///   CLα runs 25-35 % above the published whole-aircraft values of the three light aircraft
///   (the original program gives the same on the Navion, oracle arktools__Navion_clean), and
///   its CYβ, Cnβ (body and fin sidewash charts) 20-45 % below them;
const STATIC_BAND: f64 = 50.0;
/// - Cmα: the difference of two nearly equal terms (wing-body and tail), so its percentage
///   error is the static-margin error over the static margin: 75 % on the Cessna 182. Not
///   applied where the published aircraft is close to neutral (|Cmα| < [`NEAR_NEUTRAL`]).
const CMA_BAND: f64 = 100.0;
const NEAR_NEUTRAL: f64 = 0.2;
/// - dynamic derivatives: DATCOM's tail-volume methods for CLq, Cmq, CLα̇, Cmα̇ and the
///   wing-only roll/yaw methods differ from the published estimates by up to a factor 2.3
///   (Navion CMAD, CLQ), the known weakness of the q and α̇ methods (docs/validation.md).
const DYNAMIC_BAND: f64 = 150.0;
/// - the hand calculation of AEROMECH I uses the same classical formulas DATCOM simplifies, so
///   it stays closer: static 20 %, dynamic 80 % (its α̇ terms take the textbook downwash
///   gradient, DATCOM's the integrated one).
const HAND_STATIC_BAND: f64 = 20.0;
const HAND_DYNAMIC_BAND: f64 = 80.0;

fn check(r: &Report, static_band: f64, dynamic_band: f64) {
    eprintln!("{} ({}):", r.aircraft, r.deck);
    for row in &r.rows {
        eprintln!(
            "  {:<5} ours {:>10.5} reference {:>10.5} error {}",
            row.name,
            row.ours.unwrap_or(f64::NAN),
            row.reference,
            row.percent_error
                .map_or("-".to_string(), |e| format!("{e:+.1} %"))
        );
        assert!(
            row.ours.is_some(),
            "{}: {} not computed: {}",
            r.aircraft,
            row.name,
            row.note
        );
        let Some(e) = row.percent_error else {
            // A zero reference (Navion CLAD): no percentage; ours must be finite.
            continue;
        };
        let band = match (row.family, row.name.as_str()) {
            (_, "CMA") if row.reference.abs() < NEAR_NEUTRAL => continue,
            (_, "CMA") => CMA_BAND.max(static_band),
            (Family::Dynamic, _) => dynamic_band,
            _ => static_band,
        };
        assert!(
            e.abs() <= band,
            "{}: {} error {e:.1} % beyond the band {band} %",
            r.aircraft,
            row.name
        );
    }
    for s in &r.summary {
        eprintln!(
            "  {}: mean |error| {:.1} %, max {:.1} % ({})",
            s.family.map_or("all", Family::label),
            s.mean_abs_percent.unwrap_or(f64::NAN),
            s.max_abs_percent.unwrap_or(f64::NAN),
            s.worst.as_deref().unwrap_or("-")
        );
    }
}

#[test]
fn aeromech1_against_its_hand_calculation() {
    let r = run("tests/reference/aeromech1_handcalc.toml");
    assert_eq!(r.rows.len(), 14, "the study's 14 derivatives");
    check(&r, HAND_STATIC_BAND, HAND_DYNAMIC_BAND);
}

#[test]
fn navion_against_its_published_derivatives() {
    check(
        &run("tests/reference/navion.toml"),
        STATIC_BAND,
        DYNAMIC_BAND,
    );
}

#[test]
fn cessna182_against_its_published_derivatives() {
    check(
        &run("tests/reference/cessna182.toml"),
        STATIC_BAND,
        DYNAMIC_BAND,
    );
}

#[test]
fn cessna310_against_its_published_derivatives() {
    check(
        &run("tests/reference/cessna310.toml"),
        STATIC_BAND,
        DYNAMIC_BAND,
    );
}
