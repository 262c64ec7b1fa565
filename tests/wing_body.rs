//! Wing-body combination at subsonic speeds (src/methods/wing_body) against the original
//! program and against values worked by hand from the DATCOM equations; the wing-body charts
//! against their DATA lines.
//!
//! Oracle: every `WING-BODY CONFIGURATION` static table of ../shared/oracle/cases/*/for006.dat
//! whose flight condition is subsonic (Mach ≤ STMACH), compared number by number with
//! `datcom::report::compare::agrees` (within max(2 %, one unit in the last printed digit)), and
//! the auxiliary line CLA-B(W), CLA-W(B), K-B(W), K-W(B), XAC/C-B(W) of the same conditions.
//! Run `cargo test --test wing_body -- --nocapture` to see the figures.

mod common;

use datcom::case::{Case, Deck};
use datcom::charts;
use datcom::methods::body::subsonic_limit;
use datcom::methods::section::SectionCharacteristics;
use datcom::methods::wing::computed_wing_section;
use datcom::methods::wing_body::{
    figures, vortex_interference_factor, wing_body, wing_body_with_section, DragMethod, WingBody,
};
use datcom::report::compare::agrees;
use datcom::report::legacy::{self, ListedCondition};

/// Columns of the static table we compute.
const COLUMNS: [&str; 8] = ["CD", "CL", "CM", "CN", "CA", "XCP", "CLA", "CMA"];
/// The auxiliary values (the original's names).
const AUX: [&str; 5] = ["CLA-B(W)", "CLA-W(B)", "K-B(W)", "K-W(B)", "XAC/C-B(W)"];
/// Angles of attack in the listing are printed with one decimal (F5.1).
const ALPHA_PRINTED: f64 = 0.05;
/// Mach numbers in the FLIGHT CONDITIONS row are printed with three decimals (F6.3).
const MACH_PRINTED: f64 = 0.0005;
/// Figures reached per column (floors; docs/wing-body.md explains each miss), with the section
/// computed at the flight Reynolds number (the library) and the original's way (10⁶).
const FLOORS_LIBRARY: [usize; 8] = [193, 141, 280, 140, 170, 318, 111, 255];
const FLOORS_AUX_LIBRARY: [usize; 5] = [2, 2, 19, 19, 19];
const FLOORS_ORIGINAL_RE: [usize; 8] = [350, 362, 400, 362, 354, 403, 384, 460];
const FLOORS_AUX: [usize; 5] = [19, 19, 19, 19, 19];
/// The decks whose section CLMAX is given: every number (docs/wing-body.md).
const FLOORS_CLMAX_GIVEN: [usize; 8] = [112; 8];
const FLOORS_AUX_CLMAX_GIVEN: [usize; 5] = [3; 5];

struct Tally {
    matched: Vec<usize>,
    total: Vec<usize>,
    aux_matched: Vec<usize>,
    aux_total: Vec<usize>,
    misses: Vec<String>,
}

impl Tally {
    fn new() -> Tally {
        Tally {
            matched: vec![0; COLUMNS.len()],
            total: vec![0; COLUMNS.len()],
            aux_matched: vec![0; AUX.len()],
            aux_total: vec![0; AUX.len()],
            misses: Vec::new(),
        }
    }
}

/// One auxiliary line: Mach of the page, line number in the case's listing, (name, value)s.
type AuxiliaryLine = (f64, usize, Vec<(String, f64)>);

/// The auxiliary lines of a case's listing.
fn auxiliary_lines(listing: &str) -> Vec<AuxiliaryLine> {
    let mut out = Vec::new();
    let mut mach = None;
    let mut after_header = false;
    for (i, line) in listing.lines().enumerate() {
        if line.contains("FLIGHT CONDITIONS") {
            after_header = true;
            continue;
        }
        if after_header && line.starts_with('0') {
            mach = line.get(1..8).and_then(|s| s.trim().parse::<f64>().ok());
            after_header = false;
            continue;
        }
        if !line.contains("CLA-B(W)=") {
            continue;
        }
        let Some(m) = mach else { continue };
        let mut values = Vec::new();
        for name in AUX {
            let key = format!("{name}=");
            if let Some(at) = line.find(&key) {
                let rest = &line[at + key.len()..];
                if let Some(v) = rest.split_whitespace().next().and_then(|t| t.parse().ok()) {
                    values.push((name.to_string(), v));
                }
            }
        }
        out.push((m, i + 1, values));
    }
    out
}

/// Which decks a comparison covers.
#[derive(Clone, Copy, PartialEq)]
enum Group {
    All,
    /// Decks whose $WGSCHR gives the section CLMAX (the wing alone's lift does not need the
    /// original's MAXCL).
    SectionMaxLiftGiven,
}

fn section_max_lift_given(case: &Case) -> bool {
    case.sections
        .get("WING")
        .is_some_and(|s| s.per_mach.contains_key("CLMAX"))
}

/// How the wing section is computed for the comparison.
#[derive(Clone, Copy, PartialEq)]
enum SectionRe {
    /// The library: the condition's flight Reynolds number.
    Flight,
    /// The original's (`SectionReynolds::Original`): RNNUB where the deck gives it, else the
    /// section methods' fixed values (10⁶ for the slope).
    Original,
}

fn section(case: &Case, how: SectionRe) -> Option<SectionCharacteristics> {
    match how {
        SectionRe::Flight => computed_wing_section(case)?.ok(),
        SectionRe::Original => {
            // The library's rule for the original's Reynolds number (RNNUB where given).
            let mut case = case.clone();
            case.section_reynolds = datcom::case::SectionReynolds::Original;
            computed_wing_section(&case)?.ok()
        }
    }
}

fn value(ours: &WingBody, column: &str, i: usize, unit: f64) -> Option<f64> {
    match column {
        "CD" => ours.cd[i],
        "CL" => ours.cl[i],
        "CM" => ours.cm[i],
        "CN" => ours.cn[i],
        "CA" => ours.ca[i],
        "XCP" => ours.xcp[i],
        "CLA" => ours.cla_per_rad[i].map(|v| v * unit),
        _ => ours.cma_per_rad[i].map(|v| v * unit),
    }
}

fn aux_value(ours: &WingBody, name: &str) -> f64 {
    let a = &ours.auxiliary;
    let per_deg = std::f64::consts::PI / 180.0;
    match name {
        "CLA-B(W)" => a.body_in_presence_of_wing_slope_per_rad * per_deg,
        "CLA-W(B)" => a.wing_in_presence_of_body_slope_per_rad * per_deg,
        "K-B(W)" => a.body_in_presence_of_wing,
        "K-W(B)" => a.wing_in_presence_of_body,
        _ => a.carry_over_centre,
    }
}

fn compare_table(
    ours: &Result<WingBody, String>,
    listed: &ListedCondition,
    at: &str,
    tally: &mut Tally,
) -> usize {
    let table = listed.statics.as_ref().expect("a static table");
    let ours = match ours {
        Ok(r) => r,
        Err(e) => {
            tally.misses.push(format!("{at}: not computed: {e}"));
            for (j, c) in COLUMNS.iter().enumerate() {
                tally.total[j] += table.column(c).map_or(0, |v| v.len());
            }
            return 0;
        }
    };
    let unit = if listed.deriv_per_radian {
        1.0
    } else {
        std::f64::consts::PI / 180.0
    };
    let listed_alpha = table.column("ALPHA").unwrap_or(&[]);
    for (row, a) in listed_alpha.iter().enumerate() {
        let Some(a) = a else { continue };
        let Some(i) = ours
            .alpha_deg
            .iter()
            .position(|x| (x - a).abs() <= ALPHA_PRINTED)
        else {
            tally.misses.push(format!("{at}: alpha {a} is not ours"));
            continue;
        };
        for (j, column) in COLUMNS.iter().enumerate() {
            let Some(printed) = table.column(column).and_then(|v| v.get(row)) else {
                continue;
            };
            tally.total[j] += 1;
            let ours_v = value(ours, column, i, unit);
            // The original prints NA or blank where the method does not apply; ours is none.
            let ok = match (ours_v, printed) {
                (Some(o), Some(r)) => agrees(column, o, *r),
                (None, None) => true,
                _ => false,
            };
            if ok {
                tally.matched[j] += 1;
            } else {
                tally.misses.push(format!(
                    "{at} alpha {a} {column}: ours {ours_v:?}, listing {printed:?}"
                ));
            }
        }
    }
    listed_alpha.len()
}

/// Compares every subsonic wing-body table of the oracle; returns (tables, rows).
fn run_oracle(
    decks: &[(String, Deck, String)],
    how: SectionRe,
    group: Group,
    tally: &mut Tally,
) -> (usize, usize) {
    let (mut tables, mut rows) = (0, 0);
    for (name, deck, text) in decks {
        let listings = common::case_listings(text);
        for (ci, (case, listing)) in deck.cases.iter().zip(&listings).enumerate() {
            if group == Group::SectionMaxLiftGiven && !section_max_lift_given(case) {
                continue;
            }
            let alpha = case
                .flight
                .as_ref()
                .map(|f| f.alpha_deg.clone())
                .unwrap_or_default();
            let sec = section(case, how);
            let compute = |k: usize| -> Result<WingBody, String> {
                wing_body_with_section(case, k, &alpha, sec.as_ref()).map_err(|e| e.to_string())
            };
            let mut next = 0;
            for listed_case in legacy::read_listing(listing) {
                for listed in &listed_case.conditions {
                    if !listed.configuration.contains("WING-BODY CONFIGURATION")
                        || listed.configuration.contains("TAIL")
                        || listed.statics.is_none()
                    {
                        continue;
                    }
                    let Some(mach) = listed.row.field("mach").and_then(|f| f.value) else {
                        continue;
                    };
                    let Some(k) = (next..case.conditions.len())
                        .find(|&k| (case.conditions[k].mach - mach).abs() <= MACH_PRINTED)
                    else {
                        tally.misses.push(format!(
                            "{name} case {}: no condition at Mach {mach}",
                            ci + 1
                        ));
                        continue;
                    };
                    next = k + 1;
                    if case.conditions[k].mach > subsonic_limit(case) {
                        continue;
                    }
                    let at = format!("{name} case {} line {}", ci + 1, listed.row.line);
                    tables += 1;
                    rows += compare_table(&compute(k), listed, &at, tally);
                }
            }
            // The auxiliary line of each subsonic condition.
            let mut next = 0;
            for (mach, line, values) in auxiliary_lines(listing) {
                let Some(k) = (next..case.conditions.len())
                    .find(|&k| (case.conditions[k].mach - mach).abs() <= MACH_PRINTED)
                else {
                    continue;
                };
                next = k + 1;
                if case.conditions[k].mach > subsonic_limit(case) {
                    continue;
                }
                let Ok(ours) = compute(k) else {
                    for (n, _) in &values {
                        if let Some(j) = AUX.iter().position(|a| a == n) {
                            tally.aux_total[j] += 1;
                        }
                    }
                    continue;
                };
                for (n, printed) in &values {
                    let Some(j) = AUX.iter().position(|a| a == n) else {
                        continue;
                    };
                    tally.aux_total[j] += 1;
                    let o = aux_value(&ours, n);
                    if agrees(n, o, *printed) {
                        tally.aux_matched[j] += 1;
                    } else {
                        tally.misses.push(format!(
                            "{name} case {} aux line {line} {n}: ours {o}, listing {printed}",
                            ci + 1
                        ));
                    }
                }
            }
        }
    }
    (tables, rows)
}

fn report(title: &str, tables: usize, rows: usize, tally: &Tally) {
    eprintln!("{title}: {tables} subsonic WING-BODY tables, {rows} rows");
    for (j, c) in COLUMNS.iter().enumerate() {
        eprintln!("{c:>10}: {} / {}", tally.matched[j], tally.total[j]);
    }
    for (j, c) in AUX.iter().enumerate() {
        eprintln!("{c:>10}: {} / {}", tally.aux_matched[j], tally.aux_total[j]);
    }
    for m in &tally.misses {
        eprintln!("  miss: {m}");
    }
}

#[test]
fn wing_body_tables_agree_with_the_original() {
    let Some(decks) = common::oracle_decks("wing_body oracle", &["WING-BODY CONFIGURATION"]) else {
        return;
    };
    for (how, group, title, floors, aux_floors) in [
        (
            SectionRe::Flight,
            Group::All,
            "all decks, library (section at the flight Reynolds number)",
            FLOORS_LIBRARY,
            FLOORS_AUX_LIBRARY,
        ),
        (
            SectionRe::Original,
            Group::All,
            "all decks, section at Re = 1E6 (the original's)",
            FLOORS_ORIGINAL_RE,
            FLOORS_AUX,
        ),
        (
            SectionRe::Original,
            Group::SectionMaxLiftGiven,
            "decks with section CLMAX given, section at Re = 1E6",
            FLOORS_CLMAX_GIVEN,
            FLOORS_AUX_CLMAX_GIVEN,
        ),
    ] {
        let mut tally = Tally::new();
        let (tables, rows) = run_oracle(&decks, how, group, &mut tally);
        report(title, tables, rows, &tally);
        for (j, c) in COLUMNS.iter().enumerate() {
            assert!(
                tally.matched[j] >= floors[j],
                "{title}: {c} {} / {} below the floor {}",
                tally.matched[j],
                tally.total[j],
                floors[j]
            );
        }
        for (j, c) in AUX.iter().enumerate() {
            assert!(
                tally.aux_matched[j] >= aux_floors[j],
                "{title}: {c} {} / {} below the floor {}",
                tally.aux_matched[j],
                tally.aux_total[j],
                aux_floors[j]
            );
        }
    }
}

// ---------------------------------------------------------------------------------------------
// Values worked by hand from the DATCOM equations.

/// Hand-worked values are compared to this (they are written to 6 or more digits).
const HAND: f64 = 1e-6;
/// The charts are read to two decimals; slender-body theory is compared to this.
const CHART_READING: f64 = 0.015;

#[test]
fn interference_factors_follow_slender_body_theory() {
    use datcom::methods::wing_body::interference_factors;
    // DATCOM 4.3.1.2 (Pitts, Nielsen and Kaattari), τ = d/b = 0.2:
    // K_W(B) = 2/π /(1 − τ)² {(1 + τ⁴)[½ atan(½(1/τ − τ)) + π/4] − τ²[(1/τ − τ) + 2 atan τ]}
    //   ½(1/τ − τ) = 2.4, atan 2.4 = 1.176005, (1 + τ⁴) = 1.0016, [0.588003 + 0.785398] = 1.373401,
    //   → 1.375598; τ²[4.8 + 2·0.197396] = 0.04·5.194791 = 0.207792; difference 1.167806,
    //   × 2/π/0.64 = 0.994718 → K_W(B) = 1.161639.
    // K_W(B) + K_B(W) = (1 + τ)² = 1.44 → K_B(W) = 0.278361.
    let mut w = Vec::new();
    let f = interference_factors(0.2, &mut w).unwrap();
    assert!((f.wing_in_presence_of_body - 1.161639).abs() < CHART_READING);
    assert!((f.body_in_presence_of_wing - 0.278361).abs() < CHART_READING);
    assert!((f.wing_in_presence_of_body + f.body_in_presence_of_wing - 1.44).abs() < CHART_READING);
    // The chart values themselves (DATA Y10A, Y10B at d/b = 0.2).
    assert_eq!(f.wing_in_presence_of_body, 1.16);
    assert_eq!(f.body_in_presence_of_wing, 0.29);
    assert!(w.is_empty(), "{w:?}");
    // Beyond d/b = 0.8 the method is not covered.
    assert!(interference_factors(0.85, &mut w).is_err());
}

#[test]
fn vortex_interference_factor_by_hand() {
    // DATCOM 4.3.1.3 strip theory with image vortices, values of the original's FUNCTION ALI
    // (REAL*4, run through the reference transcription): z0 = 0.5, y0 = 0.6, s = 3, r = 0.4,
    // λ = 0.5 → −0.4930118; z0 = 0.8, y0 = 1.2, s = 2.5, r = 0.5, λ = 0.3 → −1.2216146.
    let a = vortex_interference_factor(0.5, 0.6, 3.0, 0.4, 0.5);
    assert!((a - (-0.4930118)).abs() < 1e-5, "{a}");
    let b = vortex_interference_factor(0.8, 1.2, 2.5, 0.5, 0.3);
    assert!((b - (-1.2216146)).abs() < 1e-5, "{b}");
}

#[test]
fn carry_over_centre_fairs_an_ellipse_between_beta_a_0_and_4() {
    use datcom::methods::wing_body::{carry_over_centre, CarryOverInputs};
    // A_e = 2, λ_e = 0.5, tan Λ_LE = 0.5: A(1 + λ) tan Λ_LE/4 = 0.375 → figure 36b: 0.1875.
    // d/b = 0.2 → BRAC = 0.22; span 4, body 0.8, c_re = 1, tan Λc/4 = 0.4:
    // 0.25 + 3.2/2 · 0.4 · 0.22 = 0.3908. βA = 2 (β = 1): √(1 − 0.25) = 0.866025,
    // x = 0.1875 + (0.3908 − 0.1875) 0.866025 = 0.363563.
    let mut i = CarryOverInputs {
        exposed_aspect_ratio: 2.0,
        exposed_taper: 0.5,
        exposed_root_chord: 1.0,
        tan_leading_edge: 0.5,
        tan_quarter_chord: 0.4,
        span: 4.0,
        body_width: 0.8,
        beta: 1.0,
        reference_length: 2.0,
    };
    let mut w = Vec::new();
    let c = carry_over_centre(&i, &mut w).unwrap();
    assert!((c.at_zero_beta_a - 0.1875).abs() < HAND);
    assert!((c.slender_body - 0.3908).abs() < HAND);
    assert!(
        (c.over_root_chord - 0.363563).abs() < HAND,
        "{}",
        c.over_root_chord
    );
    assert!((c.over_reference_length - 0.1817815).abs() < HAND);
    i.beta = 2.5;
    let c = carry_over_centre(&i, &mut w).unwrap();
    assert!((c.over_root_chord - 0.3908).abs() < HAND);
}

/// A small UAV with a body, a straight wing with incidence and a NACA section.
fn example_uav() -> Deck {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("namelists/example-uav.dcm");
    datcom::read_deck(&common::text(&path), "example-uav.dcm")
}

#[test]
fn totals_are_sums_of_named_terms() {
    let deck = example_uav();
    let case = &deck.cases[0];
    let alpha = case.flight.as_ref().unwrap().alpha_deg.clone();
    let r = wing_body(case, 0, &alpha).unwrap();
    let t = &r.terms;
    let drag = t.drag.as_ref().expect("drag");
    for k in 0..alpha.len() {
        let l = &t.lift[k];
        if let (Some(b), Some(w)) = (l.body, l.wing_and_carry_over) {
            assert_eq!(r.cl[k], Some(b + w + l.body_vortex));
        }
        let ratio =
            t.interference.wing_in_presence_of_body + t.interference.body_in_presence_of_wing;
        if let Some(w) = l.wing_alone {
            assert_eq!(l.wing_and_carry_over, Some(ratio * w));
        }
        if let Some(m) = &t.moment[k] {
            let sum = m.body
                + m.wing_zero_lift
                + m.wing_in_presence_of_body
                + m.carry_over
                + m.body_vortex
                + m.axial_force;
            assert_eq!(m.cm, sum);
            if r.cm[k].is_some() {
                assert_eq!(r.cm[k], Some(m.cm));
            }
        }
        let z = drag.zero_lift.total;
        let expected = match drag.method {
            DragMethod::Regression => drag.regression[k].map(|d| z + d),
            DragMethod::Components => drag.body_lift[k]
                .zip(drag.wing_lift[k])
                .map(|(b, w)| z + b + w),
        };
        assert_eq!(r.cd[k], expected);
    }
    let z = &drag.zero_lift;
    assert_eq!(
        z.total,
        (z.wing + z.body_friction) * z.interference_factor + z.body_base
    );
    // The auxiliary values are the interference factors and their slopes.
    let slope = t.wing.terms.lift_curve_slope.per_rad;
    assert_eq!(
        r.auxiliary.wing_in_presence_of_body_slope_per_rad,
        t.interference.wing_in_presence_of_body * slope
    );
    assert!(r
        .cd
        .iter()
        .chain(&r.cl)
        .chain(&r.cm)
        .flatten()
        .all(|v| v.is_finite()));
}

#[test]
fn a_wing_alone_case_is_refused() {
    let deck = example_uav();
    let mut case = deck.cases[0].clone();
    case.body = None;
    let e = wing_body(&case, 0, &[0.0]).unwrap_err();
    assert!(e.to_string().contains("no body"), "{e}");
}

// ---------------------------------------------------------------------------------------------
// Chart spot values: each written from the DATA statement lines of datcom.f (cited), at nodes.

const SPOTS: &[(&str, &[f64], f64)] = &[
    // X10A(3) = 0.2, Y10A(3) = 1.16 (charts/wing; CDRAG's copy of WBLIFT's DATA 47903-47904)
    ("4.3.1.2-10a", &[0.2], 1.16),
    ("4.3.1.2-10a", &[0.5], 1.46),
    // X10B, Y10B 47909-47910: (0.2, 0.29), (0.7, 1.22)
    ("4.3.1.2-10b", &[0.2], 0.29),
    ("4.3.1.2-10b", &[0.7], 1.22),
    // X12A1, Y12A1 47915-47916 (4*0.94 from 0.3 to 0.6): (0.1, 0.97), (0.5, 0.94)
    ("4.3.1.2-12a1", &[0.1], 0.97),
    ("4.3.1.2-12a1", &[0.5], 0.94),
    // X12A2, Y12A2 47921-47922: (0.3, 0.31), (0.6, 0.60)
    ("4.3.1.2-12a2", &[0.3], 0.31),
    ("4.3.1.2-12a2", &[0.6], 0.6),
    // X1313A, Y1313A 2183-2186: (8, 17), (13.4, 10)
    ("4.3.1.3-13a", &[8.0], 17.0),
    ("4.3.1.3-13a", &[13.4], 10.0),
    // X1313B, Y1313B 2191-2192: (0, 0.86), (3.3, 1.8)
    ("4.3.1.3-13b", &[0.0], 0.86),
    ("4.3.1.3-13b", &[3.3], 1.8),
    // X31314, Y31314 2197-2198: (1, 0.62), (3.5, 0.735)
    ("4.3.1.3-14", &[1.0], 0.62),
    ("4.3.1.3-14", &[3.5], 0.735),
    // X31315, Y31315 2203-2205: (2, 0.81), (5.5, 1.6)
    ("4.3.1.3-15", &[2.0], 0.81),
    ("4.3.1.3-15", &[5.5], 1.6),
    // X21C, Y21C 47585-47587: (0.075, 0.130), (0.3, 0.266)
    ("4.3.2.2-35", &[0.075], 0.13),
    ("4.3.2.2-35", &[0.3], 0.266),
    // X38B, Y38B 47581-47582: (0, 0), (1, 0.5)
    ("4.3.2.2-36b", &[0.0], 0.0),
    ("4.3.2.2-36b", &[1.0], 0.5),
    // X137, X237, Y37 47842-47857: Y37(1) at (0.25, 3E6) = 1.063; Y37(4) at (0.25, 1E7) = 1.076;
    // Y37(20) at (0.4, 3E6) = 1.02
    ("4.3.3.1-37", &[0.25, 3.0e6], 1.063),
    ("4.3.3.1-37", &[0.25, 1.0e7], 1.076),
    ("4.3.3.1-37", &[0.4, 3.0e6], 1.02),
    // DATA B0 39278-39279: the first two words, coefficients B0 and B1 at M = 0.6, |α| = 1°
    ("4.3.3.1-regression", &[0.6, 1.0, 0.0], 4.4885930e-04),
    ("4.3.3.1-regression", &[0.6, 1.0, 1.0], 1.6466172e-03),
    // The α = 0 set is all zero (TABLES).
    ("4.3.3.1-regression", &[0.7, 0.0, 5.0], 0.0),
];

#[test]
fn wing_body_charts_give_their_data_statement_values() {
    assert!(charts::invalid().is_empty(), "{:?}", charts::invalid());
    common::check_chart_spots(figures::ALL.iter().copied(), SPOTS);
}
