//! Downwash at the horizontal tail and the configurations with tails at subsonic speeds
//! (src/methods/tail) against the original program and against values worked by hand from
//! the DATCOM equations; the tail charts against their DATA lines.
//!
//! Oracle: every subsonic (Mach ≤ STMACH) `HORIZONTAL TAIL CONFIGURATION`,
//! `WING-BODY-HORIZONTAL TAIL`, `WING-BODY-VERTICAL TAIL` and `WING-BODY-VERTICAL
//! TAIL-HORIZONTAL TAIL CONFIGURATION` static table of ../shared/oracle/cases/*/for006.dat and
//! every downwash table (ALPHA, Q/QINF, EPSLON, D(EPSLON)/D(ALPHA)) printed under them,
//! compared number by number with `datcom::report::compare::agrees` (within max(2 %, one unit
//! in the last printed digit)), under both section Reynolds-number rules. Run
//! `cargo test --test tail -- --nocapture` to see the figures; docs/tail.md explains the misses.

mod common;

use std::collections::BTreeMap;

use datcom::case::{Case, Deck, SectionReynolds, TailSlopeReading};
use datcom::charts;
use datcom::methods::body::subsonic_limit;
use datcom::methods::tail::{
    canard_vortex, configuration, downwash_gradient_at_tail, downwash_method,
    effective_aspect_ratio_ratio, empirical_downwash_gradient, figures, horizontal_tail_alone,
    tail_placement, wing_wake, CanardInputs, Coefficients, ConfigurationTotals, DownwashMethod,
    HorizontalTailAlone,
};
use datcom::report::compare::agrees;
use datcom::report::legacy::{self, ListedCondition};

/// Columns of the static tables.
const COLUMNS: [&str; 8] = ["CD", "CL", "CM", "CN", "CA", "XCP", "CLA", "CMA"];
/// Columns of the downwash table (the original's names).
const DOWNWASH: [&str; 3] = ["Q/QINF", "EPSLON", "D(EPSLON)/D(ALPHA)"];
/// Pages compared, by the original's configuration line.
const PAGES: [(&str, &str); 4] = [
    ("HT", "HORIZONTAL TAIL CONFIGURATION"),
    ("WBH", "WING-BODY-HORIZONTAL TAIL CONFIGURATION"),
    ("WBV", "WING-BODY-VERTICAL TAIL CONFIGURATION"),
    (
        "WBHV",
        "WING-BODY-VERTICAL TAIL-HORIZONTAL TAIL CONFIGURATION",
    ),
];
/// Angles of attack in the listing are printed with one decimal (F5.1 / F6.1).
const ALPHA_PRINTED: f64 = 0.05;
/// Mach numbers in the FLIGHT CONDITIONS row are printed with three decimals (F6.3).
const MACH_PRINTED: f64 = 0.0005;

/// Floors: (rule, group, kind, column) → matched numbers at least. docs/tail.md explains the
/// misses. Written from the measured figures of `cargo test --test tail -- --nocapture`.
const FLOORS: &[(&str, &str, &str, &str, usize)] = &[
    ("flight", "all", "DOWNWASH", "Q/QINF", 462),
    // 266 (was 267): with the last downwash point exactly the angle (2026-11-26) one library-default
    // ε moved off its listing; the original-rules figures rose (docs/tail.md).
    ("flight", "all", "DOWNWASH", "EPSLON", 266),
    ("flight", "all", "DOWNWASH", "D(EPSLON)/D(ALPHA)", 240),
    ("flight", "all", "HT", "CD", 40),
    ("flight", "all", "HT", "CL", 36),
    ("flight", "all", "HT", "CM", 33),
    ("flight", "all", "HT", "CN", 38),
    ("flight", "all", "HT", "CA", 40),
    ("flight", "all", "HT", "XCP", 40),
    ("flight", "all", "HT", "CLA", 36),
    ("flight", "all", "HT", "CMA", 36),
    ("flight", "all", "WBH", "CD", 49),
    ("flight", "all", "WBH", "CL", 49),
    ("flight", "all", "WBH", "CM", 52),
    ("flight", "all", "WBH", "CN", 49),
    ("flight", "all", "WBH", "CA", 51),
    ("flight", "all", "WBH", "XCP", 50),
    ("flight", "all", "WBH", "CLA", 47),
    ("flight", "all", "WBH", "CMA", 53),
    ("flight", "all", "WBV", "CD", 27),
    ("flight", "all", "WBV", "CL", 30),
    ("flight", "all", "WBV", "CM", 34),
    ("flight", "all", "WBV", "CN", 30),
    ("flight", "all", "WBV", "CA", 34),
    ("flight", "all", "WBV", "XCP", 31),
    ("flight", "all", "WBV", "CLA", 29),
    ("flight", "all", "WBV", "CMA", 28),
    ("flight", "all", "WBHV", "CD", 175),
    ("flight", "all", "WBHV", "CL", 119),
    ("flight", "all", "WBHV", "CM", 157),
    ("flight", "all", "WBHV", "CN", 123),
    ("flight", "all", "WBHV", "CA", 142),
    ("flight", "all", "WBHV", "XCP", 140),
    ("flight", "all", "WBHV", "CLA", 134),
    ("flight", "all", "WBHV", "CMA", 181),
    ("flight", "complete", "DOWNWASH", "Q/QINF", 72),
    ("flight", "complete", "DOWNWASH", "EPSLON", 72),
    ("flight", "complete", "DOWNWASH", "D(EPSLON)/D(ALPHA)", 72),
    ("flight", "complete", "HT", "CD", 27),
    ("flight", "complete", "HT", "CL", 27),
    ("flight", "complete", "HT", "CM", 27),
    ("flight", "complete", "HT", "CN", 27),
    ("flight", "complete", "HT", "CA", 27),
    ("flight", "complete", "HT", "XCP", 27),
    ("flight", "complete", "HT", "CLA", 27),
    ("flight", "complete", "HT", "CMA", 27),
    ("flight", "complete", "WBH", "CD", 37),
    ("flight", "complete", "WBH", "CL", 37),
    ("flight", "complete", "WBH", "CM", 37),
    ("flight", "complete", "WBH", "CN", 37),
    ("flight", "complete", "WBH", "CA", 37),
    ("flight", "complete", "WBH", "XCP", 37),
    ("flight", "complete", "WBH", "CLA", 37),
    ("flight", "complete", "WBH", "CMA", 37),
    ("flight", "complete", "WBV", "CD", 18),
    ("flight", "complete", "WBV", "CL", 18),
    ("flight", "complete", "WBV", "CM", 18),
    ("flight", "complete", "WBV", "CN", 18),
    ("flight", "complete", "WBV", "CA", 18),
    ("flight", "complete", "WBV", "XCP", 18),
    ("flight", "complete", "WBV", "CLA", 18),
    ("flight", "complete", "WBV", "CMA", 18),
    ("flight", "complete", "WBHV", "CD", 36),
    ("flight", "complete", "WBHV", "CL", 36),
    ("flight", "complete", "WBHV", "CM", 36),
    ("flight", "complete", "WBHV", "CN", 36),
    ("flight", "complete", "WBHV", "CA", 36),
    ("flight", "complete", "WBHV", "XCP", 36),
    ("flight", "complete", "WBHV", "CLA", 36),
    ("flight", "complete", "WBHV", "CMA", 36),
    ("original", "all", "DOWNWASH", "Q/QINF", 466),
    ("original", "all", "DOWNWASH", "EPSLON", 428),
    ("original", "all", "DOWNWASH", "D(EPSLON)/D(ALPHA)", 408),
    ("original", "all", "HT", "CD", 40),
    ("original", "all", "HT", "CL", 40),
    ("original", "all", "HT", "CM", 40),
    ("original", "all", "HT", "CN", 40),
    ("original", "all", "HT", "CA", 40),
    ("original", "all", "HT", "XCP", 40),
    ("original", "all", "HT", "CLA", 40),
    ("original", "all", "HT", "CMA", 40),
    ("original", "all", "WBH", "CD", 60),
    ("original", "all", "WBH", "CL", 60),
    ("original", "all", "WBH", "CM", 60),
    ("original", "all", "WBH", "CN", 60),
    ("original", "all", "WBH", "CA", 60),
    ("original", "all", "WBH", "XCP", 60),
    ("original", "all", "WBH", "CLA", 60),
    ("original", "all", "WBH", "CMA", 60),
    ("original", "all", "WBV", "CD", 40),
    ("original", "all", "WBV", "CL", 51),
    ("original", "all", "WBV", "CM", 51),
    ("original", "all", "WBV", "CN", 51),
    ("original", "all", "WBV", "CA", 38),
    ("original", "all", "WBV", "XCP", 51),
    ("original", "all", "WBV", "CLA", 51),
    ("original", "all", "WBV", "CMA", 51),
    ("original", "all", "WBHV", "CD", 245),
    ("original", "all", "WBHV", "CL", 204),
    ("original", "all", "WBHV", "CM", 204),
    ("original", "all", "WBHV", "CN", 208),
    ("original", "all", "WBHV", "CA", 205),
    ("original", "all", "WBHV", "XCP", 190),
    // 257 (was 258): with the body vortices' station measured from the body's nose (its first
    // station, as the original does: 2026-11-25) arktools__for005 (nose at X = −5) moves; under
    // this rule alone one post-stall CLA at 35° left its listing (−0.00119 against −0.00112),
    // under the full original rules that page now agrees on every CLA (12/13 → 13/13).
    ("original", "all", "WBHV", "CLA", 257),
    ("original", "all", "WBHV", "CMA", 268),
    ("original", "complete", "DOWNWASH", "Q/QINF", 72),
    ("original", "complete", "DOWNWASH", "EPSLON", 72),
    ("original", "complete", "DOWNWASH", "D(EPSLON)/D(ALPHA)", 72),
    ("original", "complete", "HT", "CD", 27),
    ("original", "complete", "HT", "CL", 27),
    ("original", "complete", "HT", "CM", 27),
    ("original", "complete", "HT", "CN", 27),
    ("original", "complete", "HT", "CA", 27),
    ("original", "complete", "HT", "XCP", 27),
    ("original", "complete", "HT", "CLA", 27),
    ("original", "complete", "HT", "CMA", 27),
    ("original", "complete", "WBH", "CD", 37),
    ("original", "complete", "WBH", "CL", 37),
    ("original", "complete", "WBH", "CM", 37),
    ("original", "complete", "WBH", "CN", 37),
    ("original", "complete", "WBH", "CA", 37),
    ("original", "complete", "WBH", "XCP", 37),
    ("original", "complete", "WBH", "CLA", 37),
    ("original", "complete", "WBH", "CMA", 37),
    ("original", "complete", "WBV", "CD", 18),
    ("original", "complete", "WBV", "CL", 18),
    ("original", "complete", "WBV", "CM", 18),
    ("original", "complete", "WBV", "CN", 18),
    ("original", "complete", "WBV", "CA", 18),
    ("original", "complete", "WBV", "XCP", 18),
    ("original", "complete", "WBV", "CLA", 18),
    ("original", "complete", "WBV", "CMA", 18),
    ("original", "complete", "WBHV", "CD", 36),
    ("original", "complete", "WBHV", "CL", 36),
    ("original", "complete", "WBHV", "CM", 36),
    ("original", "complete", "WBHV", "CN", 36),
    ("original", "complete", "WBHV", "CA", 36),
    ("original", "complete", "WBHV", "XCP", 36),
    ("original", "complete", "WBHV", "CLA", 36),
    ("original", "complete", "WBHV", "CMA", 36),
];

#[derive(Default)]
struct Tally {
    /// (group, kind, column) → (matched, total).
    counts: BTreeMap<(String, String, String), (usize, usize)>,
    misses: Vec<String>,
}

impl Tally {
    fn count(
        &mut self,
        group: &str,
        kind: &str,
        column: &str,
        ok: bool,
        miss: impl FnOnce() -> String,
    ) {
        for g in ["all", group] {
            let e = self
                .counts
                .entry((g.to_string(), kind.to_string(), column.to_string()))
                .or_default();
            e.1 += 1;
            if ok {
                e.0 += 1;
            }
        }
        if !ok {
            self.misses.push(miss());
        }
    }

    fn get(&self, group: &str, kind: &str, column: &str) -> (usize, usize) {
        self.counts
            .get(&(group.to_string(), kind.to_string(), column.to_string()))
            .copied()
            .unwrap_or((0, 0))
    }
}

/// Decks whose wing inputs are complete: the section's CLMAX given, CLMAXL given or no
/// airfoil card (the low-speed CLmax then comes from the original's MAXCL), and no
/// experimental data.
fn complete_wing_inputs(case: &Case) -> bool {
    let Some(w) = case.sections.get("WING") else {
        return false;
    };
    let airfoil = case
        .airfoils
        .iter()
        .any(|a| a.surface == datcom::deck::cards::Surface::Wing);
    w.per_mach.contains_key("CLMAX")
        && (w.scalars.contains_key("CLMAXL") || !airfoil)
        && !case.other.keys().any(|k| k.starts_with("EXPR"))
}

fn page_value(page: &Coefficients, column: &str, i: usize, unit: f64) -> Option<f64> {
    match column {
        "CD" => page.cd[i],
        "CL" => page.cl[i],
        "CM" => page.cm[i],
        "CN" => page.cn[i],
        "CA" => page.ca[i],
        "XCP" => page.xcp[i],
        "CLA" => page.cla_per_rad[i].map(|v| v * unit),
        _ => page.cma_per_rad[i].map(|v| v * unit),
    }
}

fn tail_page(t: &HorizontalTailAlone) -> Coefficients {
    let s = &t.surface;
    Coefficients {
        cd: s.cd.clone(),
        cl: s.cl.clone(),
        cm: t.cm.clone(),
        cn: s.cn.clone(),
        ca: s.ca.clone(),
        xcp: t.xcp.clone(),
        cla_per_rad: t.cla_per_rad.clone(),
        cma_per_rad: t.cma_per_rad.clone(),
    }
}

struct Ours {
    totals: Result<ConfigurationTotals, String>,
    tail: Result<HorizontalTailAlone, String>,
}

fn page_of<'a>(
    ours: &'a Ours,
    kind: &str,
    tail: &'a Option<Coefficients>,
) -> Result<&'a Coefficients, String> {
    if kind == "HT" {
        return tail
            .as_ref()
            .ok_or_else(|| ours.tail.as_ref().err().cloned().unwrap_or_default());
    }
    let t = ours.totals.as_ref().map_err(|e| e.clone())?;
    match kind {
        "WBH" => t.wing_body_horizontal_tail.as_ref(),
        "WBV" => t.wing_body_vertical_tail.as_ref(),
        _ => t.wing_body_vertical_tail_horizontal_tail.as_ref(),
    }
    .ok_or_else(|| format!("no {kind} page computed"))
}

#[allow(clippy::too_many_arguments)]
fn compare_page(
    page: Result<&Coefficients, String>,
    alpha: &[f64],
    listed: &ListedCondition,
    kind: &str,
    group: &str,
    at: &str,
    tally: &mut Tally,
) {
    let table = listed.statics.as_ref().expect("a static table");
    let unit = if listed.deriv_per_radian {
        1.0
    } else {
        std::f64::consts::PI / 180.0
    };
    let listed_alpha = table.column("ALPHA").unwrap_or(&[]);
    for (row, a) in listed_alpha.iter().enumerate() {
        let Some(a) = a else { continue };
        let i = alpha.iter().position(|x| (x - a).abs() <= ALPHA_PRINTED);
        for column in COLUMNS {
            let Some(printed) = table.column(column).and_then(|v| v.get(row)) else {
                continue;
            };
            let ours_v = match (&page, i) {
                (Ok(p), Some(i)) => page_value(p, column, i, unit),
                _ => None,
            };
            let ok = match (ours_v, printed) {
                (Some(o), Some(r)) => agrees(column, o, *r),
                (None, None) => page.is_ok() && i.is_some(),
                _ => false,
            };
            tally.count(group, kind, column, ok, || {
                format!(
                    "{at} {kind} alpha {a} {column}: ours {ours_v:?}, listing {printed:?}{}",
                    page.as_ref()
                        .err()
                        .map_or(String::new(), |e| format!(" ({e})"))
                )
            });
        }
    }
}

fn ours_at<'a>(
    cache: &'a mut BTreeMap<usize, Ours>,
    case: &Case,
    alpha: &[f64],
    k: usize,
) -> &'a Ours {
    cache.entry(k).or_insert_with(|| Ours {
        totals: configuration(case, k, alpha).map_err(|e| e.to_string()),
        tail: horizontal_tail_alone(case, k, alpha).map_err(|e| e.to_string()),
    })
}

fn condition_at(case: &Case, mach: f64, from: usize) -> Option<usize> {
    (from..case.conditions.len()).find(|&k| (case.conditions[k].mach - mach).abs() <= MACH_PRINTED)
}

fn run_oracle(decks: &[(String, Deck, String)], rule: SectionReynolds, tally: &mut Tally) {
    for (name, deck, text) in decks {
        let listings = common::case_listings(text);
        for (ci, (case, listing)) in deck.cases.iter().zip(&listings).enumerate() {
            let mut case = case.clone();
            case.section_reynolds = rule;
            // Against the original's listings: its reading of a low-aspect-ratio straight
            // tail's slope (the first angle's; the library's default is the analytic slope,
            // docs/differences.md), whichever section Reynolds number.
            case.tail_slope = TailSlopeReading::Original;
            let case = &case;
            let group = if complete_wing_inputs(case) {
                "complete"
            } else {
                "incomplete"
            };
            let alpha = case
                .flight
                .as_ref()
                .map(|f| f.alpha_deg.clone())
                .unwrap_or_default();
            let mut cache: BTreeMap<usize, Ours> = BTreeMap::new();
            let mut next: BTreeMap<&str, usize> = BTreeMap::new();
            for listed_case in legacy::read_listing(listing) {
                for listed in &listed_case.conditions {
                    let Some((kind, _)) = PAGES.iter().find(|(_, c)| listed.configuration == *c)
                    else {
                        continue;
                    };
                    if listed.statics.is_none() {
                        continue;
                    }
                    let Some(mach) = listed.row.field("mach").and_then(|f| f.value) else {
                        continue;
                    };
                    let from = next.get(kind).copied().unwrap_or(0);
                    let Some(k) = condition_at(case, mach, from) else {
                        continue;
                    };
                    next.insert(kind, k + 1);
                    if case.conditions[k].mach > subsonic_limit(case) {
                        continue;
                    }
                    let at = format!("{name} case {} line {}", ci + 1, listed.row.line);
                    let o = ours_at(&mut cache, case, &alpha, k);
                    let tail = o.tail.as_ref().ok().map(tail_page);
                    compare_page(
                        page_of(o, kind, &tail),
                        &alpha,
                        listed,
                        kind,
                        group,
                        &at,
                        tally,
                    );
                }
            }
            let mut from = 0;
            let mut last_mach = f64::NAN;
            for t in common::downwash_tables(listing) {
                if t.mach != last_mach {
                    from = condition_at(case, t.mach, from).map_or(from, |k| k);
                    last_mach = t.mach;
                }
                let Some(k) = condition_at(case, t.mach, from) else {
                    continue;
                };
                if case.conditions[k].mach > subsonic_limit(case) {
                    continue;
                }
                let at = format!(
                    "{name} case {} line {} [{}]",
                    ci + 1,
                    t.line,
                    t.configuration
                );
                let o = ours_at(&mut cache, case, &alpha, k);
                let dw = o.totals.as_ref().map_err(|e| e.clone()).and_then(|t| {
                    t.terms
                        .downwash
                        .as_ref()
                        .ok_or_else(|| "no downwash".to_string())
                });
                for r in &t.rows {
                    let Some(a) = r[0] else { continue };
                    let i = alpha.iter().position(|x| (x - a).abs() <= ALPHA_PRINTED);
                    for (j, column) in DOWNWASH.iter().enumerate() {
                        let printed = r[j + 1];
                        let ours_v = match (&dw, i) {
                            (Ok(d), Some(i)) => match j {
                                0 => d.dynamic_pressure_ratio[i],
                                1 => d.epsilon_deg[i],
                                _ => d.gradient[i],
                            },
                            _ => None,
                        };
                        let ok = match (ours_v, printed) {
                            (Some(o), Some(p)) => agrees("CL", o, p),
                            _ => false,
                        };
                        tally.count(group, "DOWNWASH", column, ok, || {
                            format!(
                                "{at} alpha {a} {column}: ours {ours_v:?}, listing {printed:?}{}",
                                dw.as_ref()
                                    .err()
                                    .map_or(String::new(), |e| format!(" ({e})"))
                            )
                        });
                    }
                }
            }
        }
    }
}

fn report(title: &str, tally: &Tally) {
    eprintln!("== {title}");
    for group in ["all", "complete", "incomplete"] {
        for kind in ["DOWNWASH", "HT", "WBH", "WBV", "WBHV"] {
            let cols: &[&str] = if kind == "DOWNWASH" {
                &DOWNWASH
            } else {
                &COLUMNS
            };
            let line: Vec<String> = cols
                .iter()
                .map(|c| {
                    let (m, t) = tally.get(group, kind, c);
                    format!("{c} {m}/{t}")
                })
                .collect();
            eprintln!("{group:>10} {kind:>8}: {}", line.join(", "));
        }
    }
    for m in &tally.misses {
        eprintln!("  miss: {m}");
    }
}

#[test]
fn tail_tables_agree_with_the_original() {
    let Some(decks) = common::oracle_decks("tail oracle", &["TAIL CONFIGURATION"]) else {
        return;
    };
    for (rule, title) in [
        (SectionReynolds::Flight, "flight"),
        (SectionReynolds::Original, "original"),
    ] {
        let mut tally = Tally::default();
        run_oracle(&decks, rule, &mut tally);
        report(&format!("section Reynolds number: {title}"), &tally);
        for (r, group, kind, column, floor) in FLOORS {
            if *r != title {
                continue;
            }
            let (m, t) = tally.get(group, kind, column);
            assert!(
                m >= *floor,
                "{title} {group} {kind} {column}: {m} / {t} below the floor {floor}"
            );
        }
    }
}

// ---------------------------------------------------------------------------------------------
// Values worked by hand from the DATCOM equations.

/// Hand-worked values are compared to this (they are written to 6 or more digits).
const HAND: f64 = 1e-6;

#[test]
fn downwash_gradient_at_the_tail_by_hand() {
    // DATCOM 4.4.1 eq. 4.4.1-b, figure 4.4.1-67: A = 6, dε/dα∞ = 1.62 · 4.5/(π · 6) = 0.386747,
    // 2l/b = 0.8: √(½(√(1 + 4/36) − 1)) = √(½ · 0.054093) = 0.164459; z = 0.964459;
    // √(1 + z²) = 1.389298; (1 − 0.386747)/(6 · 0.964459 · 1.389298) = 0.076278
    // → dε/dα = 0.463025.
    let at_infinity = 1.62 * 4.5 / (std::f64::consts::PI * 6.0);
    assert!((at_infinity - 0.386747).abs() < HAND);
    let g = downwash_gradient_at_tail(at_infinity, 6.0, 0.8);
    assert!((g - 0.463025).abs() < 2.0 * HAND, "{g}");
    // Far behind the wing the gradient tends to its value at infinity.
    let far = downwash_gradient_at_tail(at_infinity, 6.0, 1e4);
    assert!((far - at_infinity).abs() < 1e-6);
}

#[test]
fn effective_aspect_ratio_follows_the_fit_of_figure_66() {
    // λ = 0.4, Λc/4 = 30°: cos = 0.866025, tan = 0.577350; t = 1.4 − 0.866025 + 0.023094 =
    // 0.557069; 0.4/t = 0.718044: below it A_eff/A = 1.
    assert_eq!(
        effective_aspect_ratio_ratio(0.4, 0.866025, 0.577350, 0.7),
        1.0
    );
    // At α/α_CLmax = 1: 0.4/3 + (1 − 0.4/3)(1.4 − 0.557069) = 0.133333 + 0.866667 · 0.842931 =
    // 0.863874.
    let r = effective_aspect_ratio_ratio(0.4, 0.866025, 0.577350, 1.0);
    assert!((r - 0.863874).abs() < 2.0 * HAND, "{r}");
}

#[test]
fn empirical_gradient_by_hand() {
    // DATCOM 4.4.1 eq. 4.4.1-a: A = 8, λ = 0.5, Λc/4 = 0: K_A = 1/8 − 1/(1 + 8^1.7) = 0.125 −
    // 1/35.300 = 0.096671 (8^1.7 = 34.296751); K_λ = 8.5/7 = 1.214286; h = 1, l = 10, b_e/2 = 5:
    // K_H = (1 − 0.1)/2^(1/3) = 0.714330; product = 0.083855, ^1.19 = 0.052199 → 0.231763.
    let g = empirical_downwash_gradient(8.0, 0.5, 1.0, 1.0, 10.0, 5.0);
    let ka = 0.125 - 1.0 / (1.0 + 8f64.powf(1.7));
    let kh = 0.9 / 2f64.powf(1.0 / 3.0);
    let expected = 4.44 * (ka * (8.5 / 7.0) * kh).powf(1.19);
    assert!((g - expected).abs() < 1e-12);
    assert!((g - 0.2318).abs() < 1e-3, "{g}");
}

#[test]
fn wake_dynamic_pressure_by_hand() {
    // A = 6, c = 1, CL = 0 (no downwash), CD0 = 0.01, α = 0, tail on the wake centre (angle 0),
    // arm 3: x/c = 3; z_W/c = 0.68 √(0.01 · 3.15) = 0.120688; Δq/q = 2.42 · 0.1/3.3 = 0.073333;
    // z = 0 → q/q∞ = 1 − 0.073333 = 0.926667.
    let w = wing_wake(6.0, 1.0, 0.0, 0.01, 0.0, 3.0, 0.0);
    assert!((w.half_width_over_chord - 0.120688).abs() < HAND);
    assert!((w.dynamic_pressure_ratio - 0.926667).abs() < HAND);
    // Above the wake (the tail subtends 10° and the wing is at 0): q/q∞ = 1.
    let w = wing_wake(6.0, 1.0, 0.0, 0.01, 0.0, 3.0, 10f64.to_radians());
    assert_eq!(w.dynamic_pressure_ratio, 1.0);
}

#[test]
fn tail_placement_without_incidence_is_the_distance_behind_the_root_trailing_edge() {
    // Wing apex (1, 0), root chord 2, MAC leading edge 0.5 behind the apex; tail apex (6, 0.5)
    // with its exposed MAC's quarter chord 0.3 behind it: arm 6 − 1 − 2 + 0.3 = 3.3, height 0.5.
    let p = tail_placement((1.0, 0.0), 0.0, 2.0, 0.5, (6.0, 0.5), 0.0, 0.3);
    assert!((p.arm - 3.3).abs() < 1e-12 && (p.height - 0.5).abs() < 1e-12);
    assert!((p.angle_rad - (0.5f64 / 3.3).atan()).abs() < 1e-12);
    assert!((p.root_chord_less_mac_le - 1.5).abs() < 1e-12);
}

#[test]
fn downwash_method_follows_the_original_check() {
    // Without DWASH: a canard below a span ratio of 1.5.
    assert_eq!(downwash_method(None, 1.4, 1.0), DownwashMethod::Canard);
    assert_eq!(downwash_method(None, 3.0, 1.0), DownwashMethod::VortexSheet);
    assert_eq!(
        downwash_method(Some(2.0), 2.0, 1.0),
        DownwashMethod::Empirical
    );
    assert_eq!(
        downwash_method(Some(2.0), 4.0, 1.0),
        DownwashMethod::VortexSheet
    );
    assert_eq!(downwash_method(Some(2.0), 1.2, 1.0), DownwashMethod::Canard);
    assert_eq!(
        downwash_method(Some(3.0), 2.0, 1.0),
        DownwashMethod::VortexSheet
    );
    assert_eq!(downwash_method(Some(1.0), 0.9, 1.0), DownwashMethod::Canard);
}

/// The UAV example with a horizontal and a vertical tail.
fn example_uav() -> Deck {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("namelists/example-uav.dcm");
    datcom::read_deck(&common::text(&path), "example-uav.dcm")
}

#[test]
fn totals_are_sums_of_named_terms() {
    let deck = example_uav();
    let case = &deck.cases[0];
    if case.horizontal_tail.is_none() {
        eprintln!("SKIPPED totals_are_sums_of_named_terms: the example has no horizontal tail");
        return;
    }
    let alpha = case.flight.as_ref().unwrap().alpha_deg.clone();
    let r = match configuration(case, 0, &alpha) {
        Ok(r) => r,
        Err(e) => {
            eprintln!("SKIPPED totals_are_sums_of_named_terms: {e}");
            return;
        }
    };
    let wb = &r.terms.wing_body;
    let tb = r.terms.tail_body.as_ref().expect("tail-body terms");
    let wbh = r.wing_body_horizontal_tail.as_ref().expect("WBH page");
    for k in 0..alpha.len() {
        let Some(t) = tb.at_angle[k] else { continue };
        if let Some(cl) = wb.cl[k] {
            assert_eq!(wbh.cl[k], Some(cl + t.lift + t.vortex_lift));
        }
        if let Some(cd) = wb.cd[k] {
            assert_eq!(wbh.cd[k], Some(cd + t.drag));
            let f = r.terms.fin_drag;
            if let Some(p) = &r.wing_body_vertical_tail_horizontal_tail {
                assert_eq!(p.cd[k], Some(cd + t.drag + f));
            }
            if let Some(p) = &r.wing_body_vertical_tail {
                assert_eq!(p.cd[k], Some(cd + f));
            }
        }
        if let (Some(cm), Some(out)) = (wb.cm[k], wbh.cm[k]) {
            assert_eq!(
                out,
                cm + t.moment_of_normal_force + t.moment_of_axial_force + t.zero_lift_moment
            );
        }
    }
    if let Some(f) = r.terms.first_slopes {
        assert_eq!(wbh.cla_per_rad[0], Some(f.cla_per_rad));
        if let (Some(a), Some(b)) = (f.wing_body_moment, f.tail_moment) {
            assert_eq!(f.cma_per_rad, Some(a + b));
        }
    }
    let fins = r.terms.vertical_tail.as_ref().map_or(0.0, |d| d.drag.total)
        + r.terms.ventral_fin.as_ref().map_or(0.0, |d| d.drag.total);
    assert_eq!(r.terms.fin_drag, fins);
    for p in [
        &r.wing_body_horizontal_tail,
        &r.wing_body_vertical_tail,
        &r.wing_body_vertical_tail_horizontal_tail,
    ]
    .into_iter()
    .flatten()
    {
        assert!(p
            .cd
            .iter()
            .chain(&p.cl)
            .chain(&p.cm)
            .chain(&p.cla_per_rad)
            .flatten()
            .all(|v| v.is_finite()));
    }
}

#[test]
fn a_case_without_tails_is_refused() {
    let deck = example_uav();
    let mut case = deck.cases[0].clone();
    case.horizontal_tail = None;
    case.vertical_tail = None;
    case.ventral_fin = None;
    let e = configuration(&case, 0, &[0.0]).unwrap_err();
    assert!(e.to_string().contains("no tail"), "{e}");
}

// ---------------------------------------------------------------------------------------------
// Chart spot values: each written from the DATA statement lines of datcom.f (cited), at nodes.

const SPOTS: &[(&str, &[f64], f64)] = &[
    // X4157A, Y4157A 8751-8752: (0, 1.5), (30, 1.68), (54, 3.0)
    ("4.4.1-68a", &[0.0], 1.5),
    ("4.4.1-68a", &[30.0], 1.68),
    ("4.4.1-68a", &[54.0], 3.0),
    // X157B1, X157B2, Y4157B 8757-8763: Y(1) at (0, 0.2) = 1.0; Y(8) at (0, 0.833) = 1.34;
    // Y(19) at (0.2, 0.6) = 0.98; Y(56) at (1.0, 1.5) = 0.27
    ("4.4.1-68b", &[0.0, 0.2], 1.0),
    ("4.4.1-68b", &[0.0, 0.833], 1.34),
    ("4.4.1-68b", &[0.2, 0.6], 0.98),
    ("4.4.1-68b", &[1.0, 1.5], 0.27),
    // X41603, X41601, X41602, Y44160 48712-48728 (taper, A tan LE, beta A): Y(1,1,1) at
    // (0, -4, 0) = 0.785; Y(2,1,1) at (0, -4, 1) = 0.6014; Y(9,3,2) at (0.5, 0, 8) = 0.7728;
    // Y(2,5,3) at (1, 4, 1) = 0.9866
    ("4.4.1-71", &[0.0, -4.0, 0.0], 0.785),
    ("4.4.1-71", &[0.0, -4.0, 1.0], 0.6014),
    ("4.4.1-71", &[0.5, 0.0, 8.0], 0.7728),
    ("4.4.1-71", &[1.0, 4.0, 1.0], 0.9866),
];

#[test]
fn tail_charts_give_their_data_statement_values() {
    assert!(charts::invalid().is_empty(), "{:?}", charts::invalid());
    common::check_chart_spots(figures::ALL.iter().copied(), SPOTS);
    // Beyond 54° figure 68a follows the parabola through its last three nodes (TBFUNX LEXU=2):
    // through (45, 2.25), (50, 2.75), (54, 3.0) at 56: 3.0 + …
    let l = charts::get("4.4.1-68a").unwrap().lookup(&[56.0]);
    let (x, y) = ([45.0, 50.0, 54.0], [2.25, 2.75, 3.0]);
    let a = 56.0;
    let q = y[0] * (a - x[1]) * (a - x[2]) / ((x[0] - x[1]) * (x[0] - x[2]))
        + y[1] * (a - x[0]) * (a - x[2]) / ((x[1] - x[0]) * (x[1] - x[2]))
        + y[2] * (a - x[0]) * (a - x[1]) / ((x[2] - x[0]) * (x[2] - x[1]));
    assert!((l.value.unwrap() - q).abs() < 1e-12);
    assert_eq!(l.warnings.len(), 1);
}

/// A canard configuration made up for the tests: the canard is the deck's wing, the main wing
/// the deck's horizontal tail (span ratio 1.7/4.5, so downwash method 3).
const CANARD_DECK: &str =
    " $FLTCON NMACH=1.0,MACH(1)=0.3,NALPHA=5.0,ALSCHD(1)=0.0,4.0,8.0,12.0,16.0,
   RNNUB(1)=2.0E6$
 $OPTINS SREF=20.0,CBARR=2.5,BLREF=9.0$
 $SYNTHS XCG=5.0,ZCG=0.0,XW=1.5,ZW=0.3,ALIW=2.0,XH=5.0,ZH=0.0,ALIH=1.0$
 $BODY NX=6.0,X(1)=0.0,1.0,2.0,6.0,8.0,9.0,R(1)=0.0,0.4,0.5,0.5,0.4,0.2$
 $WGPLNF CHRDTP=0.3,SSPNE=1.2,SSPN=1.7,CHRDR=1.2,SAVSI=30.0,CHSTAT=0.0,TYPE=1.0$
 $HTPLNF CHRDTP=0.8,SSPNE=4.0,SSPN=4.5,CHRDR=3.0,SAVSI=30.0,CHSTAT=0.0,TYPE=1.0$
NACA-W-4-0009
NACA-H-4-0012
CASEID CANARD TEST
";

#[test]
fn canard_totals_are_sums_of_named_terms() {
    let deck = datcom::read_deck(CANARD_DECK, "canard.dcm");
    let case = &deck.cases[0];
    let alpha = case.flight.as_ref().unwrap().alpha_deg.clone();
    let r = configuration(case, 0, &alpha).expect("canard configuration");
    assert!(r.terms.downwash.is_none());
    let c = r.terms.canard.as_ref().expect("canard terms");
    let wb = &r.terms.wing_body;
    let tb = r.terms.tail_body.as_ref().expect("tail-body terms");
    let wbh = r.wing_body_horizontal_tail.as_ref().expect("WBH page");
    let mut checked = 0;
    for (k, a) in alpha.iter().enumerate() {
        let (Some(t), Some(v)) = (tb.at_angle[k], c.vortex.at_angle[k]) else {
            continue;
        };
        // No downwash at the aft surface: the canard's effect is its vortex lift.
        assert_eq!(t.epsilon_deg, 0.0);
        assert_eq!(
            t.dynamic_pressure_ratio,
            c.dynamic_pressure_ratio[k].unwrap()
        );
        assert!(
            v.lift_slope_per_rad < 0.0,
            "the vortices inboard of the tips lower the lift"
        );
        assert_eq!(v.lift, v.lift_slope_per_rad * a.to_radians());
        assert_eq!(
            wbh.cl[k],
            Some(wb.cl[k].unwrap() + t.lift + t.vortex_lift + v.lift)
        );
        assert_eq!(wbh.cd[k], Some(wb.cd[k].unwrap() + t.drag));
        assert_eq!(
            wbh.cm[k],
            Some(
                wb.cm[k].unwrap()
                    + t.moment_of_normal_force
                    + t.moment_of_axial_force
                    + t.zero_lift_moment
                    + c.moment[k].unwrap()
            )
        );
        checked += 1;
    }
    assert_eq!(checked, alpha.len());
    let f = r.terms.first_slopes.expect("first slopes");
    let (t, v) = (tb.at_angle[0].unwrap(), c.vortex.at_angle[0].unwrap());
    let k = tb.interference.wing_in_presence_of_body + tb.interference.body_in_presence_of_wing;
    let tail = r.terms.horizontal_tail.as_ref().unwrap();
    let expected = wb.cla_per_rad[0].unwrap()
        + k * tail.slope_per_rad * t.dynamic_pressure_ratio
        + v.lift_slope_per_rad;
    assert!((f.cla_per_rad - expected).abs() < 1e-12 * expected.abs());
    assert_eq!(wbh.cla_per_rad[0], Some(f.cla_per_rad));
}

#[test]
fn canard_vortex_by_hand() {
    // Chart 4.4.1-71 at a node: taper 0.5, A tan(LE) 0, beta A 8 gives 0.7728.
    let inputs = CanardInputs {
        canard_aspect_ratio: 8.0,
        canard_taper: 0.5,
        canard_tan_leading_edge: 0.0,
        canard_tan_trailing_edge: -0.1,
        canard_semispan: 1.7,
        canard_exposed_semispan: 1.2,
        beta: 1.0,
        canard_slope_per_rad: 0.5,
        canard_in_presence_of_body: 1.1,
        canard_incidence_deg: 1.0,
        canard_zero_lift_deg: -1.0,
        aft_semispan: 4.5,
        aft_exposed_semispan: 4.0,
        aft_exposed_taper: 0.3,
        aft_exposed_aspect_ratio: 6.0,
        aft_exposed_area: 10.0,
        aft_slope_per_rad: 2.5,
        aft_interference_sum: 1.2,
        aft_incidence_deg: 0.0,
        aft_zero_lift_deg: 0.0,
        arm: 3.0,
        height: 0.2,
        reference_area: 20.0,
    };
    let mut warnings = Vec::new();
    let v = canard_vortex(
        &inputs,
        &[0.0, 4.0],
        &[Some(0.95), Some(0.9)],
        &mut warnings,
    )
    .unwrap();
    assert!(warnings.is_empty());
    assert_eq!(v.exposed_span_fraction, 0.7728);
    // y_v = 1.2 · 0.7728 + 0.5 = 1.42736 m from the centre line.
    assert!((v.lateral_position - 1.42736).abs() < 1e-12);
    let a = v.at_angle[1].unwrap();
    // z_v = 0.2 − (3 + 0.1 · 1.42736) tan(5°) = −0.074937...
    let z = 0.2 - (3.0 + 0.142736) * 5.0_f64.to_radians().tan();
    assert!((a.height - z).abs() < 1e-12);
    let i = datcom::methods::wing_body::vortex_interference_factor(z, 1.42736, 4.5, 0.5, 0.3);
    assert_eq!(a.interference_factor, i);
    // ΔCLα = 0.5 · 2.5 · 0.9 · 1.1 · i · 4 / (2π · 6 · 0.92736) · 20/10.
    let slope =
        0.5 * 2.5 * 0.9 * 1.1 * i * 4.0 / (2.0 * std::f64::consts::PI * 6.0 * 0.92736) * 2.0;
    assert!((a.lift_slope_per_rad - slope).abs() < 1e-12);
    assert!((a.lift - slope * 4.0_f64.to_radians()).abs() < 1e-14);
    let gradient = -slope / (1.2 * 2.5 * 0.9);
    assert!((a.effective_gradient - gradient).abs() < 1e-12);
    // ε_eff from the canard's zero-lift angle: (4 + 1 + 1)°.
    assert!((a.effective_epsilon_deg - 6.0 * gradient).abs() < 1e-12);
    // At α = 0 the aft surface is at its zero-lift angle: ε_eff 0, no lift increment.
    let b = v.at_angle[0].unwrap();
    assert_eq!(b.effective_epsilon_deg, 0.0);
    assert_eq!(b.lift, 0.0);
}

/// Positions along x are measured from wherever the deck puts its origin: moving the body's
/// stations, the surfaces and the moment reference together by the same distance changes no
/// coefficient, also where the body vortices reach the wing or tail (their station is taken
/// from the body's nose, the first station, as the original does).
#[test]
fn coefficients_do_not_depend_on_the_x_origin() {
    /// Distance moved, m.
    const SHIFT: f64 = 1.5;
    /// Only rounding separates the two runs.
    const ROUNDING: f64 = 1e-9;
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("namelists/navion.dcm");
    let deck = datcom::read_deck_file(&path).expect("the bundled Navion deck");
    let mut case = deck.cases[0].clone();
    let alpha = vec![0.0, 8.0, 12.0, 16.0, 20.0];
    case.flight.as_mut().expect("flight conditions").alpha_deg = alpha.clone();
    // Every component page and the dynamic derivatives too.
    case.cards.build = true;
    case.cards.damp = true;
    // The tail's vortex factor is not zero at some angle: the case exercises the station.
    let totals = datcom::methods::tail::configuration(&case, 0, &alpha).expect("the tail method");
    let tail_body = totals.terms.tail_body.expect("tail-body terms");
    assert!(
        tail_body
            .vortices
            .iter()
            .any(|v| v.interference_factor != 0.0),
        "no body vortex reaches the tail: {:?}",
        tail_body.vortices
    );
    let mut moved = case.clone();
    for x in &mut moved.body.as_mut().expect("a body").x {
        *x += SHIFT;
    }
    let s = moved.synthesis.as_mut().expect("$SYNTHS");
    for v in [&mut s.xcg, &mut s.xw, &mut s.xh, &mut s.xv, &mut s.xvf] {
        if let Some(v) = v.as_mut() {
            *v += SHIFT;
        }
    }
    let (a, b) = (
        datcom::results::run_case(&case),
        datcom::results::run_case(&moved),
    );
    assert_eq!(a.conditions.len(), b.conditions.len());
    let mut compared = 0;
    for (ca, cb) in a.conditions.iter().zip(&b.conditions) {
        for name in [
            "CD", "CL", "CM", "CN", "CA", "CLA", "CMA", "CYB", "CNB", "CLB", "CLQ", "CMQ", "CLAD",
            "CMAD", "CLP", "CYP", "CNP", "CNR", "CLR",
        ] {
            let (Some(x), Some(y)) = (ca.column(name), cb.column(name)) else {
                continue;
            };
            for (k, (p, q)) in x.iter().zip(y).enumerate() {
                match (p, q) {
                    (Some(p), Some(q)) => {
                        compared += 1;
                        assert!(
                            (p - q).abs() <= ROUNDING * p.abs().max(1.0),
                            "{} {name} at {}°: {p} moved to {q}",
                            ca.configuration,
                            alpha[k]
                        );
                    }
                    (None, None) => {}
                    _ => panic!(
                        "{} {name} at {}°: {p:?} against {q:?}",
                        ca.configuration, alpha[k]
                    ),
                }
            }
        }
    }
    assert!(compared > 30, "only {compared} numbers compared");
}
