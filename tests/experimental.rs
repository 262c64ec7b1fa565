//! Experimental data substitution ($EXPRnn): the cases of the oracle decks that give
//! experimental data, compared with the original's listing (every static number at Mach <= 0.6,
//! within max(2 %, one printed unit), under the original's rules), and the warnings that name
//! the substituted and the unused variables.
//!
//! Decks: `lkampoli__ex7` (Example problem 7: $EXPR01 CLWB), `lkampoli__ex3` and
//! `arktools__sprob` (Example problem 3 cases 2 to 5: $EXPR01 wing-body and body curves and
//! slopes, $EXPR02 slopes and transonic fairing data; sprob case 19 is Example problem 7).

mod common;

use datcom::case::SectionReynolds;
use datcom::report::{compare, json};
use serde_json::Value;

/// The original's default subsonic limit: conditions above it are not compared here.
const MACH_LIMIT: f64 = 0.6;

const COLUMNS: [&str; 11] = [
    "CD", "CL", "CM", "CN", "CA", "XCP", "CLA", "CMA", "CYB", "CNB", "CLB",
];

/// Agreement reached over the cases with experimental data of the three decks (fraction of
/// all printed numbers), measured 2026-11-25 with CDWB, CLWB, CMWB, CLAWB, CMAWB and the body's
/// CDB, CLB, CMB, CLAB, CMAB substituted.
const FLOOR: f64 = 0.95;

/// Keeps, in a run's JSON, the conditions at Mach <= 0.6 of the cases whose number is in `keep`.
fn only(mut v: Value, keep: &[usize]) -> Value {
    if let Some(cases) = v["cases"].as_array_mut() {
        for (k, c) in cases.iter_mut().enumerate() {
            if let Some(conds) = c["conditions"].as_array_mut() {
                conds.retain(|x| {
                    keep.contains(&(k + 1)) && x["mach"].as_f64().is_some_and(|m| m <= MACH_LIMIT)
                });
            }
        }
    }
    v
}

#[test]
fn cases_with_experimental_data_against_the_original() {
    let Some(dir) = common::shared_dir(
        "oracle/cases",
        "cases_with_experimental_data_against_the_original",
    ) else {
        return;
    };
    let mut total = [(0usize, 0usize); COLUMNS.len()];
    eprintln!(
        "{:<40} {}",
        "deck (cases with $EXPR)",
        COLUMNS.map(|c| format!("{c:>9}")).join("")
    );
    for name in ["arktools__sprob", "lkampoli__ex3", "lkampoli__ex7"] {
        let text = common::text(&dir.join(name).join("input.dcm"));
        let listing = common::text(&dir.join(name).join("for006.dat"));
        let deck = common::under_rule(datcom::read_deck(&text, name), SectionReynolds::Original);
        let keep: Vec<usize> = deck
            .cases
            .iter()
            .enumerate()
            .filter(|(_, c)| c.other.keys().any(|k| k.starts_with("EXPR")))
            // Power effects and twin vertical panels are not computed: not part of this measure.
            .filter(|(_, c)| {
                !["PROPWR", "JETPWR", "TVTPAN"]
                    .iter()
                    .any(|n| c.other.contains_key(*n))
            })
            .map(|(k, _)| k + 1)
            .collect();
        assert!(!keep.is_empty(), "{name}: no case with $EXPR");
        let results = datcom::run(&deck);
        for &k in &keep {
            let warnings = &results.cases[k - 1].warnings;
            assert!(
                warnings
                    .iter()
                    .any(|w| w.to_string().contains("experimental data from $EXPR01")),
                "{name} case {k}: no warning naming the substituted data: {warnings:?}"
            );
        }
        let ours = only(
            serde_json::from_str(&json::to_string(&results)).unwrap(),
            &keep,
        );
        let reference = only(
            serde_json::from_str(&json::listing_to_string(&listing, name)).unwrap(),
            &keep,
        );
        let rows = compare::compare(&ours, &reference);
        let mut line = format!("{:<40} ", format!("{name} {keep:?}"));
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
    let (a, n) = total.iter().fold((0, 0), |(a, n), (x, y)| (a + x, n + y));
    eprintln!("ALL {a}/{n} ({:.1} %)", 100.0 * a as f64 / n.max(1) as f64);
    assert!(
        a as f64 / n.max(1) as f64 >= FLOOR,
        "{a}/{n} below the floor {FLOOR}"
    );
}

/// Example problem 3 case 2 gives, besides the wing-body and body data, the wing-alone,
/// horizontal-tail and transonic fairing variables of $EXPR02 (ALPOW, ALPLW, ACLMW, CLMW,
/// ALPOH, ALPLH, ACLMH, CLMH), which the run does not use: it says so.
#[test]
fn unused_experimental_variables_are_named() {
    let deck = datcom::read_deck(
        " $FLTCON NMACH=2.0,MACH(1)=.4,.5,NALPHA=3.0,ALSCHD(1)=0.0,2.0,4.0,RNNUB(1)=2*2.0E6$\n \
         $EXPR01 CLWB(1)=0.1,0.2,0.3,CLW(1)=0.1,0.2,0.3$\n \
         $EXPR02 ALPOW=0.0,ALPLW=8.8$\nCASEID EXPR\n",
        "expr.dcm",
    );
    let warnings = &datcom::run(&deck).cases[0].warnings;
    assert!(
        warnings.iter().any(|w| w
            .to_string()
            .starts_with("$EXPR01: experimental data CLW not used")),
        "{warnings:?}"
    );
    assert!(
        warnings.iter().any(|w| w
            .to_string()
            .starts_with("$EXPR02: experimental data ALPLW, ALPOW not used")),
        "{warnings:?}"
    );
}

/// Example problem 7 ($EXPR01 CLWB at the 9 angles): the wing-body CL is the experimental one,
/// the computed one is kept in the terms, CLA is the slope of the experimental curve, and CD and
/// CM stay computed.
#[test]
fn experimental_wing_body_lift_replaces_the_computed_and_keeps_it_traceable() {
    let Some(dir) = common::shared_dir(
        "oracle/cases",
        "experimental_wing_body_lift_replaces_the_computed_and_keeps_it_traceable",
    ) else {
        return;
    };
    let text = common::text(&dir.join("lkampoli__ex7").join("input.dcm"));
    let deck = common::under_rule(datcom::read_deck(&text, "ex7"), SectionReynolds::Original);
    let case = &deck.cases[0];
    let alpha = &case.flight.as_ref().unwrap().alpha_deg;
    let wb = datcom::methods::wing_body::wing_body(case, 0, alpha).unwrap();
    let given = [0.09, 0.204, 0.330, 0.450, 0.690, 0.895, 1.070, 1.180, 1.174];
    for (cl, g) in wb.cl.iter().zip(given) {
        assert_eq!(*cl, Some(g));
    }
    let e = wb
        .terms
        .experimental
        .as_ref()
        .expect("substitution recorded");
    assert_eq!(e.data.namelist, "EXPR01");
    assert_ne!(e.computed_cl, wb.cl);
    assert_eq!(e.computed_cd, wb.cd);
    assert_eq!(e.computed_cm, wb.cm);
    // Slope of the parabola through the first three experimental points, at the first.
    let h = 2f64.to_radians();
    let first = (-3.0 * given[0] + 4.0 * given[1] - given[2]) / (2.0 * h);
    assert!((wb.cla_per_rad[0].unwrap() - first).abs() < 1e-9);
    assert!(wb.warnings.iter().any(|w| w
        .to_string()
        .contains("experimental data from $EXPR01 CLWB (9 angles)")));
}
