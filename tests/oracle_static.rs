//! The measure of issue 4: for every flight condition at Mach <= 0.6 of every oracle deck
//! without power effects, every static number the original printed (every configuration page,
//! paired with ours by configuration and flight condition) compared within max(2 %, one printed
//! unit). A number we do not compute counts as a miss. Printed per deck and overall, under the
//! default (flight) and the original program's rules (its section Reynolds number and NACA
//! 5-digit reading, `Deck::with_original_rules`); floors keep what has been
//! reached (raise them as methods land).

mod common;

use datcom::case::SectionReynolds;
use datcom::report::{compare, json};
use serde_json::Value;

/// The original's default subsonic limit: conditions above it are not compared here.
const MACH_LIMIT: f64 = 0.6;

const COLUMNS: [&str; 8] = ["CD", "CL", "CM", "CN", "CA", "XCP", "CLA", "CMA"];

/// Overall agreement reached so far (fraction of all printed numbers of the column), per rule.
/// Measured 2026-11-24 with body, wing, wing-body, downwash, tail and tail-alone pages (no canard,
/// no power, no flaps); raised 2026-11-25 with experimental wing-body data ($EXPRnn, ex7), with
/// canard configurations, the low-aspect-ratio wing-body ($LARWB, ex9) and the twin vertical
/// panel pages ($TVTPAN, ex3).
/// 2026-11-26: with the original's reading of a section's maximum camber (Citation_airfoil)
/// every column under the original's rules passes the bars, which are now the floors.
const FLOOR_FLIGHT: [f64; 8] = [0.40; 8];
/// Issue 4's bars: CD, CA, XCP at least 90 %; CL, CM, CN, CLA, CMA at least 95 % (asked of CL,
/// CM, CN below CLmax; held here over every row).
const FLOOR_ORIGINAL: [f64; 8] = [0.90, 0.95, 0.95, 0.95, 0.90, 0.90, 0.95, 0.95];

fn keep_subsonic(mut v: Value) -> Value {
    if let Some(cases) = v["cases"].as_array_mut() {
        for c in cases {
            if let Some(conds) = c["conditions"].as_array_mut() {
                conds.retain(|k| k["mach"].as_f64().is_some_and(|m| m <= MACH_LIMIT));
            }
        }
    }
    v
}

#[test]
fn static_numbers_against_the_original() {
    let dir = std::path::PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../shared/oracle/cases");
    if !dir.is_dir() {
        eprintln!("SKIPPED static_numbers_against_the_original: ../shared/oracle/cases is absent");
        return;
    }
    let mut cases: Vec<_> = std::fs::read_dir(&dir)
        .unwrap()
        .filter_map(Result::ok)
        .map(|e| e.path())
        .collect();
    cases.sort();
    for (rule, floor) in [
        (SectionReynolds::Flight, FLOOR_FLIGHT),
        (SectionReynolds::Original, FLOOR_ORIGINAL),
    ] {
        let mut total = [(0usize, 0usize); 8];
        eprintln!(
            "== rules: {}",
            if rule == SectionReynolds::Original {
                "original (section Reynolds number, NACA 5-digit reading, last-rise section maximum)"
            } else {
                "library default (flight Reynolds number, NACA 5-digit definition)"
            }
        );
        eprintln!(
            "{:<48} {}",
            "deck",
            COLUMNS.map(|c| format!("{c:>9}")).join("")
        );
        for case_dir in &cases {
            let name = case_dir.file_name().unwrap().to_string_lossy().into_owned();
            let text = String::from_utf8_lossy(&std::fs::read(case_dir.join("input.dcm")).unwrap())
                .into_owned();
            if text.contains("PROPWR") || text.contains("JETPWR") {
                continue; // power effects: not part of this measure
            }
            let listing =
                String::from_utf8_lossy(&std::fs::read(case_dir.join("for006.dat")).unwrap())
                    .into_owned();
            let deck = common::under_rule(datcom::read_deck(&text, &name), rule);
            let ours: Value = serde_json::from_str(&json::to_string(&datcom::run(&deck))).unwrap();
            let reference = keep_subsonic(
                serde_json::from_str(&json::listing_to_string(&listing, &name)).unwrap(),
            );
            let rows = compare::compare(&ours, &reference);
            let mut line = format!("{name:<48} ");
            for (k, col) in COLUMNS.iter().enumerate() {
                match rows.iter().find(|r| r.coefficient == *col) {
                    Some(r) => {
                        let n = r.compared + r.missing;
                        total[k].0 += r.agreeing;
                        total[k].1 += n;
                        line.push_str(&format!("{:>9}", format!("{}/{}", r.agreeing, n)));
                    }
                    None => line.push_str(&format!("{:>9}", "-")),
                }
            }
            eprintln!("{line}");
        }
        let mut overall = format!("{:<48} ", "OVERALL");
        for (k, (a, n)) in total.iter().enumerate() {
            let f = *a as f64 / (*n).max(1) as f64;
            overall.push_str(&format!("{:>9}", format!("{:.1}%", 100.0 * f)));
            assert!(
                f >= floor[k],
                "{rule:?} {}: {a}/{n} below the floor {}",
                COLUMNS[k],
                floor[k]
            );
        }
        eprintln!("{overall}");
    }
}
