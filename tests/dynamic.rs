//! Dynamic derivatives (DAMP) against the original program.
//!
//! Oracle: every DYNAMIC DERIVATIVES table of ../shared/oracle/cases/*/for006.dat whose flight
//! condition is subsonic (Mach ≤ STMACH) and has no power effects, columns CLQ, CMQ, CLAD,
//! CMAD, CLP, CYP, CNP, CNR, CLR, compared number by number with
//! `datcom::report::compare::agrees` against the same configuration's entry of
//! `results::run_case` (the original's section Reynolds number, `SectionReynolds::Original`,
//! floors asserted; the library default reported). A printed number counts; so does an NDM
//! (ours must mark the column as without method), and a number we give where the original
//! prints a blank. Run `cargo test --test dynamic -- --nocapture` for the figures per
//! configuration and per case.

mod common;

use std::collections::BTreeMap;

use datcom::case::{Deck, SectionReynolds};
use datcom::methods::body::subsonic_limit;
use datcom::report::compare::agrees;
use datcom::report::legacy::{self, ListedCondition};
use datcom::results::{run_case, ConditionResults, DYNAMIC_NAMES};

/// Angles of attack in the dynamic table are printed with two decimals (F7.2).
const ALPHA_PRINTED: f64 = 0.005;
/// Mach numbers in the FLIGHT CONDITIONS row are printed with three decimals (F6.3).
const MACH_PRINTED: f64 = 0.0005;
/// Numbers reached per column with the original's section Reynolds number (floors;
/// docs/dynamic.md explains each miss).
const FLOORS: [usize; 9] = [0, 0, 0, 0, 0, 0, 0, 0, 0];

#[derive(Default)]
struct Tally {
    matched: [usize; 9],
    total: [usize; 9],
    misses: Vec<String>,
    /// Per configuration page: (matched, total) over all columns.
    pages: BTreeMap<String, (usize, usize)>,
    /// Per deck: (matched, total) over all columns.
    decks: BTreeMap<String, (usize, usize)>,
}

fn compare(
    ours: Option<&ConditionResults>,
    listed: &ListedCondition,
    at: &str,
    deck: &str,
    t: &mut Tally,
) {
    let Some(table) = listed.dynamics.as_ref() else {
        return;
    };
    let unit = if listed.deriv_per_radian {
        1.0
    } else {
        std::f64::consts::PI / 180.0
    };
    let ndm = table.no_method();
    let dynamic = ours.and_then(|c| c.dynamic.as_ref());
    let listed_alpha = table.column("ALPHA").unwrap_or(&[]);
    for (row, a) in listed_alpha.iter().enumerate() {
        let Some(a) = a else { continue };
        let our_row = ours.and_then(|c| {
            c.alpha_deg
                .iter()
                .position(|x| (x - a).abs() <= ALPHA_PRINTED)
        });
        for (j, name) in DYNAMIC_NAMES.iter().enumerate() {
            let Some(printed) = table.column(name).and_then(|v| v.get(row)) else {
                continue;
            };
            let listed_ndm = row == 0 && ndm.iter().any(|n| n == name);
            let our_ndm = row == 0 && dynamic.is_some_and(|d| d.no_method.contains(name));
            let mine = match (dynamic, our_row) {
                (Some(d), Some(i)) => d
                    .columns()
                    .iter()
                    .find(|(n, _)| n == name)
                    .and_then(|(_, col)| col.get(i).copied().flatten())
                    .map(|v| v * unit),
                _ => None,
            };
            let ok = if listed_ndm || our_ndm {
                listed_ndm && our_ndm
            } else {
                match (mine, printed) {
                    (Some(o), Some(p)) => agrees(name, o, *p),
                    (None, None) => continue,
                    _ => false,
                }
            };
            t.total[j] += 1;
            let page = t.pages.entry(listed.configuration.clone()).or_default();
            page.1 += 1;
            let d = t.decks.entry(deck.to_string()).or_default();
            d.1 += 1;
            if ok {
                t.matched[j] += 1;
                t.pages.get_mut(&listed.configuration).expect("page").0 += 1;
                t.decks.get_mut(deck).expect("deck").0 += 1;
            } else {
                let p = if listed_ndm {
                    "NDM".to_string()
                } else {
                    format!("{printed:?}")
                };
                let o = if our_ndm {
                    "NDM".to_string()
                } else {
                    format!("{mine:?}")
                };
                t.misses.push(format!(
                    "{at} {} alpha {a} {name}: ours {o}, listing {p}",
                    listed.configuration
                ));
            }
        }
    }
}

fn run(decks: &[(String, Deck, String)]) -> Tally {
    let mut t = Tally::default();
    for (name, deck, text) in decks {
        let listings = common::case_listings(text);
        for (ci, (case, listing)) in deck.cases.iter().zip(&listings).enumerate() {
            if case.other.contains_key("PROPWR") || case.other.contains_key("JETPWR") {
                continue;
            }
            let results = run_case(case);
            // The entries of our run for each configuration, in condition order.
            let mut next: BTreeMap<String, usize> = BTreeMap::new();
            for listed_case in legacy::read_listing(listing) {
                for listed in &listed_case.conditions {
                    if listed.dynamics.is_none() {
                        continue;
                    }
                    let Some(mach) = listed.row.field("mach").and_then(|f| f.value) else {
                        continue;
                    };
                    let from = *next.get(&listed.configuration).unwrap_or(&0);
                    let ours = results
                        .conditions
                        .iter()
                        .filter(|c| c.configuration.trim() == listed.configuration.trim())
                        .enumerate()
                        .skip(from)
                        .find(|(_, c)| (c.condition.mach - mach).abs() <= MACH_PRINTED);
                    if let Some((k, _)) = ours {
                        next.insert(listed.configuration.clone(), k + 1);
                    }
                    if mach > subsonic_limit(case) {
                        continue;
                    }
                    let at = format!("{name} case {} line {}", ci + 1, listed.row.line);
                    compare(ours.map(|(_, c)| c), listed, &at, name, &mut t);
                }
            }
        }
    }
    t
}

#[test]
fn dynamic_derivatives_agree_with_the_original() {
    let Some(sources) = common::oracle_cases("dynamic oracle", &["DYNAMIC DERIVATIVES"]) else {
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
        let t = run(&decks);
        eprintln!("{title}:");
        let (mut m, mut n) = (0, 0);
        for (j, c) in DYNAMIC_NAMES.iter().enumerate() {
            eprintln!("  {c}: {} / {}", t.matched[j], t.total[j]);
            m += t.matched[j];
            n += t.total[j];
        }
        eprintln!(
            "  overall: {m} / {n} ({:.1} %)",
            100.0 * m as f64 / n.max(1) as f64
        );
        for (page, (a, b)) in &t.pages {
            eprintln!("  page {page}: {a} / {b}");
        }
        for (deck, (a, b)) in &t.decks {
            eprintln!("  deck {deck}: {a} / {b}");
        }
        for miss in &t.misses {
            eprintln!("  miss: {miss}");
        }
        if check {
            for (j, c) in DYNAMIC_NAMES.iter().enumerate() {
                assert!(
                    t.matched[j] >= FLOORS[j],
                    "{title}: {c} {} / {} below the floor {}",
                    t.matched[j],
                    t.total[j],
                    FLOORS[j]
                );
            }
        }
    }
}
