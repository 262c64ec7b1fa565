//! Static lateral-directional derivatives at subsonic speeds (src/methods/lateral) against the
//! original program, for the body alone, the wing alone and the wing-body.
//!
//! Oracle: every `BODY ALONE`, `WING ALONE` and `WING-BODY CONFIGURATION` static table of
//! ../shared/oracle/cases/*/for006.dat whose flight condition is subsonic (Mach ≤ STMACH),
//! columns CYB, CNB, CLB (per degree unless the page says PER RADIAN), compared number by
//! number with `datcom::report::compare::agrees`. Ours from `methods::body::body_alone` and
//! `methods::wing::wing_alone`, with the section Reynolds number of the original
//! (`SectionReynolds::Original`, the floors) and of the library (the default, reported).
//! Run `cargo test --test lateral -- --nocapture` to see the figures.

mod common;

use datcom::case::{Case, Deck, SectionReynolds};
use datcom::charts;
use datcom::geometry::body;
use datcom::methods::body::{body_alone, subsonic_limit};
use datcom::methods::lateral::{body_lateral, figures, wing_body_lateral, wing_lateral, Lateral};
use datcom::methods::wing::wing_alone;
use datcom::methods::wing_body::wing_body;
use datcom::report::compare::agrees;
use datcom::report::legacy::{self, ListedCondition};

const COLUMNS: [&str; 3] = ["CYB", "CNB", "CLB"];
/// Angles of attack in the listing are printed with one decimal (F5.1).
const ALPHA_PRINTED: f64 = 0.05;
/// Mach numbers in the FLIGHT CONDITIONS row are printed with three decimals (F6.3).
const MACH_PRINTED: f64 = 0.0005;
/// Numbers reached per column with the original's section Reynolds number (floors;
/// docs/lateral.md explains each miss).
const FLOORS_BODY: [usize; 3] = [99, 99, 104];
const FLOORS_WING: [usize; 3] = [120, 146, 150];
const FLOORS_WING_BODY: [usize; 3] = [472, 472, 398];

#[derive(Clone, Copy, PartialEq)]
enum Config {
    Body,
    Wing,
    WingBody,
}

impl Config {
    fn page(self) -> &'static str {
        match self {
            Config::Body => "BODY ALONE CONFIGURATION",
            Config::Wing => "WING ALONE CONFIGURATION",
            Config::WingBody => "WING-BODY CONFIGURATION",
        }
    }
}

struct Tally {
    matched: [usize; 3],
    total: [usize; 3],
    misses: Vec<String>,
}

fn ours(case: &Case, k: usize, config: Config) -> Result<Lateral, String> {
    let alpha = &case.flight.as_ref().ok_or("no flight")?.alpha_deg;
    match config {
        Config::Body => {
            let b = case.body.as_ref().ok_or("no body")?;
            let g = body(b).map_err(|e| e.to_string())?;
            let r = body_alone(case, &g, &case.conditions[k], alpha).map_err(|e| e.to_string())?;
            Ok(body_lateral(&r, case))
        }
        Config::Wing => {
            let w = wing_alone(case, k, alpha).map_err(|e| e.to_string())?;
            wing_lateral(case, k, alpha, &w).map_err(|e| e.to_string())
        }
        Config::WingBody => {
            let w = wing_alone(case, k, alpha).map_err(|e| e.to_string())?;
            let wb = wing_body(case, k, alpha).map_err(|e| e.to_string())?;
            wing_body_lateral(case, k, alpha, &w, &wb).map_err(|e| e.to_string())
        }
    }
}

fn compare(
    case: &Case,
    k: usize,
    listed: &ListedCondition,
    at: &str,
    config: Config,
    t: &mut Tally,
) {
    let table = listed.statics.as_ref().expect("a static table");
    let result = ours(case, k, config);
    let unit = if listed.deriv_per_radian {
        1.0
    } else {
        std::f64::consts::PI / 180.0
    };
    let listed_alpha = table.column("ALPHA").unwrap_or(&[]);
    for (row, a) in listed_alpha.iter().enumerate() {
        let Some(a) = a else { continue };
        for (j, column) in COLUMNS.iter().enumerate() {
            let Some(printed) = table.column(column).and_then(|v| v.get(row)) else {
                continue;
            };
            t.total[j] += 1;
            let mine = match &result {
                Ok(r) => r
                    .alpha_deg
                    .iter()
                    .position(|x| (x - a).abs() <= ALPHA_PRINTED)
                    .and_then(|i| match j {
                        0 => r.cyb[i],
                        1 => r.cnb[i],
                        _ => r.clb[i],
                    })
                    .map(|v| v * unit),
                Err(_) => None,
            };
            let ok = match (mine, printed) {
                (Some(o), Some(p)) => agrees(column, o, *p),
                (None, None) => true,
                _ => false,
            };
            if ok {
                t.matched[j] += 1;
            } else {
                let why = result.as_ref().err().cloned().unwrap_or_default();
                t.misses.push(format!(
                    "{at} alpha {a} {column}: ours {mine:?}, listing {printed:?} {why}"
                ));
            }
        }
    }
}

fn run(decks: &[(String, Deck, String)], config: Config) -> Tally {
    let mut t = Tally {
        matched: [0; 3],
        total: [0; 3],
        misses: Vec::new(),
    };
    for (name, deck, text) in decks {
        let listings = common::case_listings(text);
        for (ci, (case, listing)) in deck.cases.iter().zip(&listings).enumerate() {
            let mut next = 0;
            for listed_case in legacy::read_listing(listing) {
                for listed in &listed_case.conditions {
                    if !listed.configuration.contains(config.page()) || listed.statics.is_none() {
                        continue;
                    }
                    let Some(mach) = listed.row.field("mach").and_then(|f| f.value) else {
                        continue;
                    };
                    let Some(k) = (next..case.conditions.len())
                        .find(|&k| (case.conditions[k].mach - mach).abs() <= MACH_PRINTED)
                    else {
                        continue;
                    };
                    next = k + 1;
                    if case.conditions[k].mach > subsonic_limit(case) {
                        continue;
                    }
                    let at = format!("{name} case {} line {}", ci + 1, listed.row.line);
                    compare(case, k, listed, &at, config, &mut t);
                }
            }
        }
    }
    t
}

#[test]
fn lateral_derivatives_agree_with_the_original() {
    let Some(sources) = common::oracle_cases(
        "lateral oracle",
        &[
            "BODY ALONE CONFIGURATION",
            "WING ALONE CONFIGURATION",
            "WING-BODY CONFIGURATION",
        ],
    ) else {
        return;
    };
    for (rule, title, check) in [
        (
            SectionReynolds::Original,
            "original section Reynolds number",
            true,
        ),
        (
            SectionReynolds::Flight,
            "library default (flight Reynolds number)",
            false,
        ),
    ] {
        let decks: Vec<(String, Deck, String)> = sources
            .iter()
            .map(|(n, d, l)| {
                (
                    n.clone(),
                    datcom::read_deck(d, n).with_section_reynolds(rule),
                    l.clone(),
                )
            })
            .collect();
        for (config, floors) in [
            (Config::Body, FLOORS_BODY),
            (Config::Wing, FLOORS_WING),
            (Config::WingBody, FLOORS_WING_BODY),
        ] {
            let t = run(&decks, config);
            eprintln!("{title}: {}", config.page());
            for (j, c) in COLUMNS.iter().enumerate() {
                eprintln!("  {c}: {} / {}", t.matched[j], t.total[j]);
            }
            for m in &t.misses {
                eprintln!("  miss: {m}");
            }
            if check {
                for (j, c) in COLUMNS.iter().enumerate() {
                    assert!(
                        t.matched[j] >= floors[j],
                        "{title} {}: {c} {} / {} below the floor {}",
                        config.page(),
                        t.matched[j],
                        t.total[j],
                        floors[j]
                    );
                }
            }
        }
    }
}

#[test]
fn lateral_charts_are_embedded() {
    for id in figures::ALL {
        assert!(charts::get(id).is_some(), "chart {id}");
    }
}

/// The bundled UAV with BUILD: its `WING-BODY CONFIGURATION` entries carry the wing-body
/// sideslip derivatives, the same numbers the method gives (CYβ and Cnβ on the first row only,
/// as the original prints them; Clβ on every row).
#[test]
fn a_build_run_reports_wing_body_sideslip_derivatives() {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("namelists/example-uav.dcm");
    let text = common::text(&path).replace("DAMP\n", "DAMP\nBUILD\n");
    let deck = datcom::read_deck(&text, "example-uav.dcm");
    let case = &deck.cases[0];
    assert!(case.cards.build, "the BUILD card was read");
    let results = datcom::results::run_case(case);
    let entries: Vec<_> = results
        .conditions
        .iter()
        .filter(|c| c.configuration == datcom::results::WING_BODY)
        .collect();
    assert_eq!(
        entries.len(),
        case.conditions.len(),
        "one wing-body entry per condition"
    );
    for (k, entry) in entries.iter().enumerate() {
        let s = &entry.static_coefficients;
        let direct = ours(case, k, Config::WingBody).expect("the method runs on the UAV");
        assert!(
            s.cyb[0].is_some() && s.cnb[0].is_some(),
            "CYB and CNB on the first row"
        );
        assert!(s.clb.iter().all(Option::is_some), "CLB on every row");
        assert_eq!(s.cyb, direct.cyb);
        assert_eq!(s.cnb, direct.cnb);
        assert_eq!(s.clb, direct.clb);
    }
}
