//! Body alone at subsonic speeds (src/methods/body) against the original program and against
//! values worked by hand from the DATCOM equations; the body charts against their DATA lines.
//!
//! Oracle: every `DATCOM BODY ALONE CONFIGURATION` static table of
//! ../shared/oracle/cases/*/for006.dat whose flight condition is subsonic (Mach ≤ STMACH), and
//! every subsonic BASIC BODY PROPERTIES row, compared number by number with
//! `datcom::report::compare::agrees` (within max(2 %, one unit in the last printed digit)).
//! Run `cargo test --test body_alone -- --nocapture` to see the figures.

mod common;

use datcom::case::{Case, Deck};
use datcom::charts;
use datcom::conditions::FlightCondition;
use datcom::geometry::body;
use datcom::methods::body::{
    body_alone, skin_friction_coefficient, subsonic_limit, BodyAlone, BodyMethod, BodyMethodError,
    BodyTerms, BodyWarning, FIGURES,
};
use datcom::report::compare::agrees;
use datcom::report::legacy::{self, ListedCondition};

/// Columns of the static table we compute.
const COLUMNS: [&str; 8] = ["CD", "CL", "CM", "CN", "CA", "XCP", "CLA", "CMA"];
/// Columns of BASIC BODY PROPERTIES we compute, and their token index in the printed row
/// (WETTED AREA, XCG, ZCG, BASE AREA, ZERO LIFT DRAG, BASE DRAG, FRICTION DRAG, PRESSURE DRAG).
const PROPERTY_COLUMNS: [(&str, usize); 3] = [
    ("ZERO LIFT DRAG", 4),
    ("BASE DRAG", 5),
    ("FRICTION DRAG", 6),
];
/// The drags of BASIC BODY PROPERTIES are printed E11.4, four significant digits, as the
/// derivative columns are: their printed unit is measured as a derivative column's.
const E_FORMAT_COLUMN: &str = "CLA";
/// Angles of attack in the listing are printed with one decimal (F5.1).
const ALPHA_PRINTED: f64 = 0.05;
/// Mach numbers in the FLIGHT CONDITIONS row are printed with three decimals (F6.3).
const MACH_PRINTED: f64 = 0.0005;
/// Figures reached (docs/body.md): every number of every table.
const ORACLE_TABLE_ROWS: usize = 104;
const ORACLE_PROPERTY_ROWS: usize = 31;
/// CLA and CMA of lkampoli ex1 case 2, rows 5 to 10 ([`UNSET_ANGLE_SLOPES`]).
const ORACLE_KNOWN_MISSES: usize = 12;

#[derive(Default)]
struct Tally {
    matched: Vec<usize>,
    total: Vec<usize>,
    misses: Vec<String>,
}

impl Tally {
    fn new(n: usize) -> Tally {
        Tally {
            matched: vec![0; n],
            total: vec![0; n],
            misses: Vec::new(),
        }
    }

    fn count(&mut self, k: usize, column: &str, ours: Option<f64>, reference: f64, at: &str) {
        self.total[k] += 1;
        match ours {
            Some(o) if agrees(column, o, reference) => self.matched[k] += 1,
            _ => self
                .misses
                .push(format!("{at} {column}: ours {ours:?}, listing {reference}")),
        }
    }
}

fn is_subsonic(case: &Case, c: &FlightCondition) -> bool {
    c.mach <= subsonic_limit(case)
}

/// Our conditions of `case` matched in order to listed Mach numbers: the next condition with
/// that Mach number after the previous match.
struct ConditionCursor {
    next: usize,
}

impl ConditionCursor {
    fn find(&mut self, case: &Case, mach: f64) -> Option<usize> {
        let k = (self.next..case.conditions.len())
            .find(|&k| (case.conditions[k].mach - mach).abs() <= MACH_PRINTED)?;
        self.next = k + 1;
        Some(k)
    }
}

fn compute(case: &Case, k: usize) -> Result<BodyAlone, String> {
    let b = case.body.as_ref().ok_or("no body")?;
    let g = body(b).map_err(|e| e.to_string())?;
    let alpha = &case.flight.as_ref().ok_or("no flight")?.alpha_deg;
    body_alone(case, &g, &case.conditions[k], alpha).map_err(|e| e.to_string())
}

fn compare_table(
    case: &Case,
    k: usize,
    listed: &ListedCondition,
    at: &str,
    tally: &mut Tally,
) -> usize {
    let table = listed.statics.as_ref().expect("a static table");
    let ours = match compute(case, k) {
        Ok(r) => r,
        Err(e) => {
            tally.misses.push(format!("{at}: not computed: {e}"));
            for (j, c) in COLUMNS.iter().enumerate() {
                tally.total[j] += table.column(c).map_or(0, |v| v.iter().flatten().count());
            }
            return 0;
        }
    };
    let per_deg = std::f64::consts::PI / 180.0;
    let derivative_unit = if listed.deriv_per_radian {
        1.0
    } else {
        per_deg
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
            let Some(Some(reference)) = table.column(column).and_then(|v| v.get(row)) else {
                continue;
            };
            let value = match *column {
                "CD" => ours.cd[i],
                "CL" => ours.cl[i],
                "CM" => ours.cm[i],
                "CN" => ours.cn[i],
                "CA" => ours.ca[i],
                "XCP" => ours.xcp[i],
                "CLA" => ours.cla_per_rad[i].map(|v| v * derivative_unit),
                _ => ours.cma_per_rad[i].map(|v| v * derivative_unit),
            };
            let at = if j < 6 {
                at.replace(UNSET_ANGLE, "")
            } else {
                at.to_string()
            };
            tally.count(j, column, value, *reference, &format!("{at} alpha {a}"));
        }
    }
    listed_alpha.len()
}

/// BASIC BODY PROPERTIES rows of a case listing: (Mach of the page, printed tokens, line).
fn property_rows(listing: &str) -> Vec<(f64, Vec<String>, usize)> {
    let lines: Vec<&str> = listing.lines().collect();
    let mut out = Vec::new();
    let mut mach = None;
    for (i, l) in lines.iter().enumerate() {
        if l.contains("FLIGHT CONDITIONS") && l.contains("REFERENCE DIMENSIONS") {
            mach = lines
                .get(i + 4)
                .and_then(|r| r.get(1..8))
                .and_then(|m| m.trim().parse::<f64>().ok());
        }
        if l.contains("BASIC BODY PROPERTIES") {
            if let (Some(m), Some(row)) = (mach, lines.get(i + 3)) {
                out.push((
                    m,
                    row.split_whitespace().map(str::to_string).collect(),
                    i + 3,
                ));
            }
        }
    }
    out
}

/// Slopes the original computes across an angle the deck leaves unset (NALPHA larger than the
/// number of ALSCHD values, e.g. lkampoli ex1): the original runs a row at the unset angle,
/// printed NDM, and its slopes CLA and CMA are read across that row; we compute the angles
/// given (the reader warns). Such tables are recognised by their NDM row and their slope
/// misses counted apart. See docs/body.md.
const UNSET_ANGLE: &str = " (unset angle in the deck)";

fn known_miss(miss: &str) -> bool {
    miss.contains(UNSET_ANGLE)
}

/// Whether the table whose FLIGHT CONDITIONS row is on `line` (1-based) has a row at an
/// unset angle (printed NDM in the ALPHA column).
fn has_unset_angle(listing: &str, line: usize) -> bool {
    listing
        .lines()
        .skip(line)
        .take_while(|l| !l.starts_with('1'))
        .any(|l| l.get(..8).is_some_and(|a| a.trim() == "NDM"))
}

/// Compares every subsonic body-alone table of one deck's listing; returns (tables, rows).
fn compare_listing(name: &str, deck: &Deck, text: &str, tally: &mut Tally) -> (usize, usize) {
    let listings = common::case_listings(text);
    // The listing ends with an empty card list before END OF JOB.
    if listings.len() < deck.cases.len() {
        eprintln!(
            "{name}: {} case listings for {} deck cases; not compared",
            listings.len(),
            deck.cases.len()
        );
        return (0, 0);
    }
    let (mut tables, mut rows) = (0, 0);
    for (ci, (case, listing)) in deck.cases.iter().zip(&listings).enumerate() {
        let mut cursor = ConditionCursor { next: 0 };
        for listed_case in legacy::read_listing(listing) {
            for listed in &listed_case.conditions {
                if !listed.configuration.contains("BODY ALONE CONFIGURATION")
                    || listed.statics.is_none()
                {
                    continue;
                }
                let Some(mach) = listed.row.field("mach").and_then(|f| f.value) else {
                    continue;
                };
                let Some(k) = cursor.find(case, mach) else {
                    tally.misses.push(format!(
                        "{name} case {}: no condition at Mach {mach}",
                        ci + 1
                    ));
                    continue;
                };
                if !is_subsonic(case, &case.conditions[k]) {
                    continue;
                }
                let unset = if has_unset_angle(listing, listed.row.line) {
                    UNSET_ANGLE
                } else {
                    ""
                };
                let at = format!("{name} case {} line {}{unset}", ci + 1, listed.row.line);
                tables += 1;
                rows += compare_table(case, k, listed, &at, tally);
            }
        }
    }
    (tables, rows)
}

fn report(title: &str, tables: usize, rows: usize, tally: &Tally) -> usize {
    eprintln!("{title}: {tables} subsonic BODY ALONE tables, {rows} rows");
    for (j, c) in COLUMNS.iter().enumerate() {
        eprintln!("{c:>4}: {} / {}", tally.matched[j], tally.total[j]);
    }
    let mut unexplained = 0;
    for m in &tally.misses {
        if known_miss(m) {
            eprintln!("  known (unset angle in the deck): {m}");
        } else {
            unexplained += 1;
            eprintln!("  miss: {m}");
        }
    }
    unexplained
}

#[test]
fn body_alone_tables_agree_with_the_original() {
    let Some(decks) = common::oracle_decks("body_alone oracle", &[]) else {
        return;
    };
    let mut tally = Tally::new(COLUMNS.len());
    let (mut tables, mut rows) = (0, 0);
    for (name, deck, text) in &decks {
        let (t, r) = compare_listing(name, deck, text, &mut tally);
        tables += t;
        rows += r;
    }
    let unexplained = report("oracle", tables, rows, &tally);
    assert_eq!(rows, ORACLE_TABLE_ROWS, "rows compared");
    assert_eq!(unexplained, 0, "every number agrees but the known ones");
    let known = tally.misses.len();
    assert!(known <= ORACLE_KNOWN_MISSES, "{known} known misses");
}

/// Each column's agreement required of more listings (below).
const MORE_LISTINGS_FRACTION: f64 = 0.9;

/// Listings of the original for decks the oracle lacks, when `DATCOM_BODY_LISTINGS` names a
/// folder of `<deck>/input.dcm` + `<deck>/datcom.out` (or `for006.dat`) pairs, searched two
/// levels deep: the same comparison, figures printed. Such folders hold decks the original
/// computes from undefined values (NX or NALPHA beyond the values given, repeated stations),
/// where we differ on purpose (docs/body.md).
#[test]
fn body_alone_tables_agree_with_more_listings_when_given() {
    let Ok(root) = std::env::var("DATCOM_BODY_LISTINGS") else {
        eprintln!("SKIPPED body_alone_tables_agree_with_more_listings_when_given: DATCOM_BODY_LISTINGS is not set");
        return;
    };
    let mut dirs = Vec::new();
    let list = |p: &std::path::Path| -> Vec<std::path::PathBuf> {
        let mut v: Vec<_> = std::fs::read_dir(p)
            .map(|rd| {
                rd.filter_map(|e| e.ok().map(|e| e.path()))
                    .filter(|p| p.is_dir())
                    .collect()
            })
            .unwrap_or_default();
        v.sort();
        v
    };
    for d in list(std::path::Path::new(&root)) {
        if d.join("input.dcm").is_file() {
            dirs.push(d);
        } else {
            dirs.extend(
                list(&d)
                    .into_iter()
                    .filter(|d| d.join("input.dcm").is_file()),
            );
        }
    }
    let mut tally = Tally::new(COLUMNS.len());
    let (mut tables, mut rows) = (0, 0);
    for d in &dirs {
        let listing = [d.join("datcom.out"), d.join("for006.dat")]
            .into_iter()
            .find(|p| p.is_file());
        let Some(listing) = listing else { continue };
        let name = d.strip_prefix(&root).unwrap_or(d).display().to_string();
        let deck = datcom::read_deck(&common::text(&d.join("input.dcm")), &name);
        let (t, r) = compare_listing(&name, &deck, &common::text(&listing), &mut tally);
        tables += t;
        rows += r;
    }
    let unexplained = report(&root, tables, rows, &tally);
    eprintln!("{unexplained} misses not explained by an unset angle (see docs/body.md)");
    for (j, c) in COLUMNS.iter().enumerate() {
        let fraction = tally.matched[j] as f64 / tally.total[j].max(1) as f64;
        assert!(fraction >= MORE_LISTINGS_FRACTION, "{c}: {fraction}");
    }
}

#[test]
fn basic_body_properties_drag_agrees_with_the_original() {
    let Some(decks) = common::oracle_decks("body_alone oracle", &[]) else {
        return;
    };
    let mut tally = Tally::new(PROPERTY_COLUMNS.len());
    let mut rows = 0;
    for (name, deck, text) in &decks {
        let listings = common::case_listings(text);
        if listings.len() < deck.cases.len() {
            continue;
        }
        for (ci, (case, listing)) in deck.cases.iter().zip(&listings).enumerate() {
            let mut cursor = ConditionCursor { next: 0 };
            for (mach, tokens, line) in property_rows(listing) {
                let Some(k) = cursor.find(case, mach) else {
                    continue;
                };
                if !is_subsonic(case, &case.conditions[k]) {
                    continue;
                }
                let at = format!("{name} case {} line {line}", ci + 1);
                let ours = compute(case, k);
                let mut counted = false;
                for (j, (column, token)) in PROPERTY_COLUMNS.iter().enumerate() {
                    let Some(reference) = tokens.get(*token).and_then(|t| t.parse::<f64>().ok())
                    else {
                        continue;
                    };
                    counted = true;
                    let value = ours
                        .as_ref()
                        .ok()
                        .and_then(|r| r.zero_lift_drag.as_ref())
                        .map(|d| match j {
                            0 => d.total,
                            1 => d.base,
                            _ => d.friction,
                        });
                    tally.count(
                        j,
                        E_FORMAT_COLUMN,
                        value,
                        reference,
                        &format!("{at} {column}"),
                    );
                }
                // Subsonic pressure drag is not a separate term: printed NA.
                if let (Some(d), Some(t)) = (
                    ours.as_ref().ok().and_then(|r| r.zero_lift_drag.as_ref()),
                    tokens.get(7),
                ) {
                    assert!(d.pressure.is_none() && t == "NA", "{at}");
                }
                rows += usize::from(counted);
            }
        }
    }
    eprintln!("subsonic BASIC BODY PROPERTIES rows: {rows}");
    for (j, (c, _)) in PROPERTY_COLUMNS.iter().enumerate() {
        eprintln!("{c:>14}: {} / {}", tally.matched[j], tally.total[j]);
    }
    for m in &tally.misses {
        eprintln!("  miss: {m}");
    }
    assert_eq!(rows, ORACLE_PROPERTY_ROWS, "rows compared");
    for (j, (c, _)) in PROPERTY_COLUMNS.iter().enumerate() {
        assert_eq!(tally.matched[j], tally.total[j], "{c}: every number agrees");
    }
}

// ---------------------------------------------------------------------------------------------
// Values worked by hand from the DATCOM equations.

/// Hand values are carried to 8 or more significant digits; the lookups and integrals they
/// check are exact for the bodies chosen (straight lines between stations), so only rounding
/// separates them.
const HAND: f64 = 1e-7;

fn case_of(text: &str) -> Case {
    let deck = datcom::read_deck(text, "hand.dcm");
    assert!(
        !deck
            .diagnostics
            .iter()
            .any(|d| d.severity == datcom::Severity::Error),
        "{:?}",
        deck.diagnostics
    );
    deck.cases.into_iter().next().expect("one case")
}

fn run_case(case: &Case) -> Result<BodyAlone, BodyMethodError> {
    let g = body(case.body.as_ref().expect("a body")).expect("body geometry");
    body_alone(
        case,
        &g,
        &case.conditions[0],
        &case.flight.as_ref().unwrap().alpha_deg,
    )
}

fn close(what: &str, got: f64, want: f64, rel: f64) {
    assert!(
        (got - want).abs() <= rel * want.abs().max(1e-12),
        "{what}: {got} != {want}"
    );
}

/// A cone (length 1 m, base radius 0.5 m) and a cylinder to 10 m, in metres; Mach 0.3,
/// 1E6 per metre; S = 1 m², c̄ = 1 m, XCG 5 m from the nose.
const CONE_CYLINDER: &str = "DIM M
 $FLTCON NMACH=1.0, MACH(1)=0.3, RNNUB(1)=1.0E6,
   NALPHA=3.0, ALSCHD(1)=0.0,10.0,20.0$
 $OPTINS SREF=1.0, CBARR=1.0$
 $SYNTHS XCG=5.0$
 $BODY NX=5.0, X(1)=0.0,1.0,5.0,9.5,10.0, R(1)=0.0,0.5,0.5,0.5,0.5$
";

#[test]
fn slender_body_slopes_and_crossflow_by_hand() {
    let r = run_case(&case_of(CONE_CYLINDER)).unwrap();
    assert_eq!(r.method, BodyMethod::Axisymmetric);
    let BodyTerms::Axisymmetric(t) = &r.terms else {
        panic!("axisymmetric terms")
    };
    // Fineness ratio l/d = 10/1 = 10: k2 − k1 = 0.94 (Fig. 4.2.1.1-20 node), η = 0.66 +
    // (10 − 8)/(12 − 8)·(0.71 − 0.66) = 0.685 (Fig. 4.2.1.2-35a).
    close("k2-k1", t.k2_minus_k1, 0.94, HAND);
    close("eta", t.eta, 0.685, HAND);
    // The area never decreases: x1 = l = 10, x0 = 0.378·10 + 0.527·10 = 9.05 m, S0 = π/4.
    close("x1", t.x1, 10.0, HAND);
    close("x0", t.x0, 9.05, HAND);
    close("S0", t.s0, std::f64::consts::FRAC_PI_4, HAND);
    // 4.2.1.1: CLα = 2 (k2 − k1) S0/S = 2·0.94·0.78539816 = 1.4765485 per radian.
    close("CLA", t.cla_per_rad, 1.476_548_547, HAND);
    close("CLA row 1", r.cla_per_rad[0].unwrap(), 1.476_548_547, HAND);
    // 4.2.2.1: ∫₀^x0 x dS/dx dx = ∫₀¹ x·(π/4) dx = π/8 = 0.39269908 (the area is constant
    // from 1 m on); Cmα = 2 (k2 − k1)/(S c̄)·(xcg S0 − π/8) = 1.88·(3.9269908 − 0.39269908)
    // = 6.6444685 per radian.
    close(
        "area moment",
        t.area_moment,
        std::f64::consts::PI / 8.0,
        HAND,
    );
    close("CMA", t.cma_per_rad, 6.644_468_462, HAND);
    // Crossflow aft of x0: r = 0.5 from 9.05 to 10: ∫r dx = 0.475 m², ∫r x dx =
    // 0.5·(10² − 9.05²)/2 = 4.524375 m³.
    close("half area", t.crossflow_half_area, 0.475, HAND);
    close(
        "half area moment",
        t.crossflow_half_area_moment,
        4.524_375,
        HAND,
    );
    // α = 10°: sin α = 0.17364818, M sin α = 0.052 < 0.2: cdc = 1.2 (Fig. 4.2.1.2-35b).
    // CL = 1.4765485·0.17453293 + 2·0.030153690·0.685·1.2·0.475 = 0.25770634 + 0.023547016.
    let a = &t.angles[1];
    close("cdc", a.crossflow_drag_coefficient, 1.2, HAND);
    close("CL potential", a.cl_potential, 0.257_706_337, HAND);
    close("CL viscous", a.cl_viscous, 0.023_547_016, HAND);
    close("CL", r.cl[1].unwrap(), 0.281_253_353, HAND);
    // CM = Cmα α − 2 sin²α η cdc (∫r x dx − xcg ∫r dx)/(S c̄)
    //    = 1.1596785 − 2·0.030153690·0.685·1.2·(4.524375 − 2.375) = 1.1596785 − 0.10655025.
    close("CM", r.cm[1].unwrap(), 1.053_128_269, HAND);
    // 4.2.3.2: CD_L = CL sin α = 0.048839132.
    close("CD_L", a.cd_lift, 0.048_839_132, HAND);
    // At α = 0 there is no normal force: no centre of pressure.
    assert_eq!(r.cn[0], Some(0.0));
    assert_eq!(r.xcp[0], None);
    // Inside: the slope of CL(α) is the parabola through the neighbours.
    assert!(r.cla_per_rad[1].unwrap() > t.cla_per_rad);
}

#[test]
fn zero_lift_drag_of_a_cylinder_by_hand() {
    let text = CONE_CYLINDER.replace(
        "NX=5.0, X(1)=0.0,1.0,5.0,9.5,10.0, R(1)=0.0,0.5,0.5,0.5,0.5",
        "NX=2.0, X(1)=0.0,10.0, R(1)=0.5,0.5",
    );
    let r = run_case(&case_of(&text)).unwrap();
    let d = r.zero_lift_drag.as_ref().unwrap();
    // Roughness 1.6E-4 in = 4.064E-6 m: l/k = 2.4606E6; Fig. 4.1.5.1-27 at M = 0.3: intercept
    // 1.5778 + 0.3·(1.67221 − 1.5778) = 1.606123, log10 Rcut = 1.0482·6.391046 + 1.606123 =
    // 8.3052177, far above R = 1E6·10 = 1E7, which is used.
    close(
        "log10 Rcut",
        d.cutoff_reynolds_number.log10(),
        8.305_217_732,
        HAND,
    );
    close("R", d.reynolds_number_used, 1.0e7, HAND);
    // Fig. 4.1.5.1-26 at M = 0.3 (a node, FIG26 DATA line 9431-9441 row 2), X = log10 R = 7:
    // Cf = 7·2.18366E-2 − 49·9.59519E-3 + 343·1.65388E-3 − 2401·1.3037E-4 + 16807·3.92725E-6
    //    = 2.95965075E-3.
    close("Cf", d.skin_friction_coefficient, 2.959_650_75e-3, HAND);
    // 4.2.3.1-a: 1 + 60/10³ + 0.0025·10 = 1.085; Swet/Smax = 10π/(π/4) = 40:
    // C_Df = 2.95965075E-3·1.085·40 = 0.12844884 on Smax, ·π/4 = 0.10088349 on S.
    close("form factor", d.form_factor, 1.085, HAND);
    close("friction", d.friction, 0.100_883_485, HAND);
    // 4.2.3.1-b: base = body: 0.029·1/√0.12844884·π/4 = 0.063551057.
    close("base", d.base, 0.063_551_057, HAND);
    close("CD0", d.total, 0.164_434_543, HAND);
    assert_eq!(d.total, d.friction + d.base);
    assert_eq!(d.pressure, None);
    // A cylinder from the nose: x0 = 9.05 m lies in the last interval (no crossflow, as the
    // original) and the area does not change ahead of it (moment integral zero).
    assert!(r
        .warnings
        .iter()
        .any(|w| matches!(w, BodyWarning::NoCrossflowAftOfX0 { .. })));
    assert!(r
        .warnings
        .iter()
        .any(|w| matches!(w, BodyWarning::ConstantAreaToX0 { .. })));
    // Then Cmα = xcg CLα/c̄ = 5·1.4765485.
    close("CMA", r.cma_per_rad[0].unwrap(), 5.0 * 1.476_548_547, HAND);
    // CD = CD0 at α = 0.
    close("CD(0)", r.cd[0].unwrap(), 0.164_434_543, HAND);
}

#[test]
fn skin_friction_between_mach_rows_by_hand() {
    let mut w = Vec::new();
    // M = 0 row (DATA line 9431-9441, first of each of A..E), log10 R = 7:
    // 7·2.23641E-2 − 49·9.88935E-3 + 343·1.7162E-3 − 2401·1.36204E-4 + 16807·4.12963E-6
    // = 3.00803741E-3.
    close(
        "Cf M=0",
        skin_friction_coefficient(1.0e7, 0.0, &mut w).unwrap(),
        3.008_037_41e-3,
        HAND,
    );
    // Within 0.02 above the M = 0.3 row FIG26 reads that row.
    close(
        "Cf M=0.31",
        skin_friction_coefficient(1.0e7, 0.31, &mut w).unwrap(),
        2.959_650_75e-3,
        HAND,
    );
    // M = 0.5: halfway between the rows 0.3 (2.95965075E-3) and 0.7 (2.87654871E-3).
    close(
        "Cf M=0.5",
        skin_friction_coefficient(1.0e7, 0.5, &mut w).unwrap(),
        2.918_099_73e-3,
        HAND,
    );
    assert!(w.is_empty());
    assert!(matches!(
        skin_friction_coefficient(0.0, 0.5, &mut w),
        Err(BodyMethodError::Reynolds { .. })
    ));
}

#[test]
fn above_stmach_the_subsonic_method_does_not_apply() {
    let text = CONE_CYLINDER.replace("MACH(1)=0.3", "MACH(1)=0.7");
    let case = case_of(&text);
    assert!(matches!(
        run_case(&case),
        Err(BodyMethodError::NotSubsonic { mach, limit }) if mach == 0.7 && limit == 0.6
    ));
    // STMACH raises the limit (up to 0.99).
    let text = text.replace("NMACH=1.0,", "NMACH=1.0, STMACH=0.8,");
    assert!(run_case(&case_of(&text)).is_ok());
}

#[test]
fn without_reference_area_there_is_no_coefficient() {
    let text = CONE_CYLINDER.replace(" $OPTINS SREF=1.0, CBARR=1.0$\n", "");
    assert_eq!(
        run_case(&case_of(&text)).unwrap_err(),
        BodyMethodError::NoReferenceArea
    );
}

#[test]
fn a_short_body_reads_figure_20_beyond_its_data_with_a_warning() {
    // l/d = 2: below the data of Fig. 4.2.1.1-20 (4 to 20): the parabola through 4, 5, 6 gives
    // 0.77 + (2−4)·(0.055) + (2−4)(2−5)/2·(−0.015) = 0.615.
    let text = CONE_CYLINDER.replace(
        "NX=5.0, X(1)=0.0,1.0,5.0,9.5,10.0, R(1)=0.0,0.5,0.5,0.5,0.5",
        "NX=3.0, X(1)=0.0,1.0,2.0, R(1)=0.0,0.5,0.5",
    );
    let r = run_case(&case_of(&text)).unwrap();
    let BodyTerms::Axisymmetric(t) = &r.terms else {
        panic!()
    };
    close("k2-k1", t.k2_minus_k1, 0.615, HAND);
    assert!(r.warnings.iter().any(|w| matches!(w,
        BodyWarning::Chart(c) if c.chart == "4.2.1.1-20" && c.value == 2.0)));
}

/// USAF DATCOM example problem 1 (the original's EX1, the oracle's YANG-DEMIN__exwin_EX1):
/// case 1 an axisymmetric body, case 2 the same with ZU/ZL (cambered).
const EXAMPLE_1: &str = " $FLTCON NMACH = 1.0, MACH(1)=0.60, NALPHA = 11.0,
         ALSCHD(1) = -6.0, -4.0, -2.0, 0.0, 2.0,
                      4.0, 8.0, 12.0, 16.0, 20.0, 24.0,
         RNNUB=4.28E6$
 $OPTINS SREF=8.85, CBARR=2.48, BLREF=4.28$
 $SYNTHS XCG=4.14, ZCG=-0.20$
 $BODY NX = 10.0,
   X(1)=0.0,0.258,0.589,1.260,2.260,2.590,2.930,3.590,4.570,6.260,
   R(1)=0.0,0.186,0.286,0.424,0.533,0.533,0.533,0.533,0.533,0.533,
   S(1)=0.0,0.080,0.160,0.323,0.751,0.883,0.939,1.032,1.032,1.032,
   P(1)=0.0,1.00,1.42,2.01,3.08,3.34,3.44,3.61,3.61,3.61$
";
const EXAMPLE_1_CAMBER: &str = " $BODY ZU(1)= -.595,-.476,-.372,-.138, .200,
               .334, .343, .343, .343, .343,
       ZL(1)= -.595,-.715,-.754,-.805,-.868,
              -.868,-.868,-.868,-.868,-.868$
";

/// The original's intermediate values of example 1 (docs of the reference: body.md §9 and
/// §5.3, from the DUMP CASE of the listing), single precision: agreement within this.
const ORIGINAL_SINGLE: f64 = 2e-5;
const FT: f64 = 0.3048;

#[test]
fn example_1_axisymmetric_terms_are_the_originals() {
    let r = run_case(&case_of(EXAMPLE_1)).unwrap();
    let BodyTerms::Axisymmetric(t) = &r.terms else {
        panic!()
    };
    let per_deg = std::f64::consts::PI / 180.0;
    // L = 6.26 ft, x0 = 0.905 L = 5.6653 ft, S0 = 1.032 ft², k2 − k1 = 0.843444 at l/d =
    // 5.46109, CLA = 3.43321E-3 and CMA = 3.41517E-3 per degree.
    close("x0", t.x0 / FT, 5.6653, ORIGINAL_SINGLE);
    close("S0", t.s0 / (FT * FT), 1.032, ORIGINAL_SINGLE);
    close("k2-k1", t.k2_minus_k1, 0.843_444, ORIGINAL_SINGLE);
    close("CLA", t.cla_per_rad * per_deg, 3.433_21e-3, ORIGINAL_SINGLE);
    close("CMA", t.cma_per_rad * per_deg, 3.415_17e-3, ORIGINAL_SINGLE);
    close("eta", t.eta, 0.621_916, ORIGINAL_SINGLE);
    // x0 lies in the last interval: no viscous crossflow, CL linear.
    assert_eq!(t.crossflow_half_area, 0.0);
    // Drag: Rcut 3.79712E7 > R L = 2.67928E7, Cf = 2.48495E-3, Swet = 18.3698 ft², friction
    // 7.12853E-3, base 1.36774E-2, CD0 2.08059E-2.
    let d = r.zero_lift_drag.as_ref().unwrap();
    close("Rcut", d.cutoff_reynolds_number, 3.797_12e7, 1e-4);
    close("RL", d.reynolds_number, 2.679_28e7, ORIGINAL_SINGLE);
    close(
        "Cf",
        d.skin_friction_coefficient,
        2.484_95e-3,
        ORIGINAL_SINGLE,
    );
    close("Swet", d.wetted_area / (FT * FT), 18.3698, ORIGINAL_SINGLE);
    close("friction", d.friction, 7.128_53e-3, ORIGINAL_SINGLE);
    close("base", d.base, 1.367_74e-2, ORIGINAL_SINGLE);
    close("CD0", d.total, 2.080_59e-2, ORIGINAL_SINGLE);
}

#[test]
fn example_1_cambered_terms_are_the_originals() {
    let text = format!("{EXAMPLE_1}SAVE\nNEXT CASE\n{EXAMPLE_1_CAMBER}");
    let deck = datcom::read_deck(&text, "ex1.dcm");
    let case = &deck.cases[1];
    let r = run_case(case).unwrap();
    assert_eq!(r.method, BodyMethod::Cambered);
    let BodyTerms::Cambered(t) = &r.terms else {
        panic!()
    };
    let per_deg = std::f64::consts::PI / 180.0;
    // ALPHZD = −1.49999°, SP = 5.88921 ft², CM0 = −0.00540997, ARB = 0.192956,
    // kp = 0.277856, kv = 3.14, FR = 5.46109, a/b = 0.880264, αv = 15.8696°,
    // X95 = 2.06440 ft, A95MAX = 1.43158 ft², XOLCNP·X95/L = 0.487562·2.06440/6.26,
    // XOVLCA = 0.552729, CLA(1) = 3.22709E-3, CMA(1) = 4.07742E-3 per degree.
    close("alpha0", t.alpha0_deg, -1.499_99, ORIGINAL_SINGLE);
    close("Sp", t.planform_area / (FT * FT), 5.889_21, ORIGINAL_SINGLE);
    close("CM0", t.cm0, -0.005_409_97, 1e-4);
    close("ARB", t.aspect_ratio, 0.192_956, ORIGINAL_SINGLE);
    close("kp", t.kp, 0.277_856, ORIGINAL_SINGLE);
    close("kv", t.kv, KV_SMALL_ASPECT_RATIO, ORIGINAL_SINGLE);
    close("FR", t.base_fineness, 5.461_09, ORIGINAL_SINGLE);
    close("a/b", t.width_over_depth, 0.880_264, ORIGINAL_SINGLE);
    close("alpha_v", t.alpha_v_deg, 15.8696, ORIGINAL_SINGLE);
    close("X95", t.forebody_station / FT, 2.064_40, ORIGINAL_SINGLE);
    close(
        "A95MAX",
        t.forebody_planform_area / (FT * FT),
        1.431_58,
        ORIGINAL_SINGLE,
    );
    close(
        "potential centre",
        t.potential_centre_over_length,
        0.487_562 * 2.064_40 / 6.26,
        ORIGINAL_SINGLE,
    );
    close(
        "planform centroid",
        t.planform_centroid_over_length,
        0.552_729,
        ORIGINAL_SINGLE,
    );
    close("CLA", t.cla_per_rad * per_deg, 3.227_09e-3, ORIGINAL_SINGLE);
    close("CMA", t.cma_per_rad * per_deg, 4.077_42e-3, ORIGINAL_SINGLE);
}

#[test]
fn totals_are_sums_of_the_named_terms() {
    let axisymmetric = case_of(CONE_CYLINDER);
    let jorgensen = case_of(&CONE_CYLINDER.replace("NX=5.0,", "NX=5.0, METHOD=2.0,"));
    let text = format!("{EXAMPLE_1}SAVE\nNEXT CASE\n{EXAMPLE_1_CAMBER}");
    let deck = datcom::read_deck(&text, "ex1.dcm");
    let sum = |v: &[f64]| v.iter().sum::<f64>();
    for case in [&axisymmetric, &jorgensen, &deck.cases[1]] {
        let r = run_case(case).unwrap();
        let cd0 = r.zero_lift_drag.as_ref().unwrap().total;
        for (i, alpha) in r.alpha_deg.iter().enumerate() {
            let (sin, cos) = alpha.to_radians().sin_cos();
            let (cd, cl, cm) = (r.cd[i].unwrap(), r.cl[i].unwrap(), r.cm[i].unwrap());
            match &r.terms {
                BodyTerms::Axisymmetric(t) => {
                    let a = &t.angles[i];
                    close("CL", cl, sum(&[a.cl_potential, a.cl_viscous]), 1e-14);
                    close("CM", cm, sum(&[a.cm_potential, a.cm_viscous]), 1e-14);
                    close("CD", cd, sum(&[cd0, a.cd_lift]), 1e-14);
                }
                BodyTerms::Cambered(t) => {
                    let a = &t.angles[i];
                    let cn = sum(&[a.cn_potential, a.cn_viscous]);
                    close("CN", r.cn[i].unwrap(), cn, 1e-12);
                    close("CM", cm, sum(&[t.cm0, a.cm_potential, a.cm_viscous]), 1e-14);
                    close("CD", cd, sum(&[cd0, a.cd_lift]), 1e-14);
                }
                BodyTerms::Jorgensen { jorgensen, .. } => {
                    let a = &jorgensen.angles[i];
                    let cn = sum(&[a.cn_potential, a.cn_viscous]);
                    close("CN", r.cn[i].unwrap(), cn, 1e-12);
                    close("CA", r.ca[i].unwrap(), a.ca, 1e-12);
                    close("CM", cm, sum(&[a.cm_potential, a.cm_viscous]), 1e-14);
                }
            }
            // CN and CA are CL and CD resolved on the body axes.
            close("CN", r.cn[i].unwrap(), cl * cos + cd * sin, 1e-14);
            close("CA", r.ca[i].unwrap(), cd * cos - cl * sin, 1e-14);
        }
    }
}

#[test]
fn jorgensen_circular_body_uses_the_slender_body_slopes() {
    let r = run_case(&case_of(
        &CONE_CYLINDER.replace("NX=5.0,", "NX=5.0, METHOD=2.0,"),
    ))
    .unwrap();
    assert_eq!(r.method, BodyMethod::Jorgensen);
    let BodyTerms::Jorgensen {
        axisymmetric,
        jorgensen,
    } = &r.terms
    else {
        panic!()
    };
    // Circular: A3 = CLα S/2 and A1 = Cmα/2, so near α = 0 the normal force is
    // A3 sin 2α/S ≈ CLα α: the slopes agree with the slender-body ones.
    close("A3", jorgensen.a3, axisymmetric.cla_per_rad / 2.0, HAND);
    close("A1", jorgensen.a1, axisymmetric.cma_per_rad / 2.0, HAND);
    assert_eq!(
        (jorgensen.potential_ratio, jorgensen.viscous_ratio),
        (1.0, 1.0)
    );
    // CA = CD0 cos²α; at α = 20°: CD0·0.88302222.
    let cd0 = r.zero_lift_drag.as_ref().unwrap().total;
    close(
        "CA",
        jorgensen.angles[2].ca,
        cd0 * 0.883_022_221_559_5,
        HAND,
    );
}

// ---------------------------------------------------------------------------------------------
// Chart files against their DATA lines (values written down by hand from datcom.f).

/// kv below a body aspect ratio of 0.5: YBA2(1) = YBA2(2) = 3.14, the DATA value (not π).
#[allow(clippy::approx_constant)]
const KV_SMALL_ASPECT_RATIO: f64 = 3.14;

/// Node values are copied exactly; a lookup at a node returns them exactly.
const EXACT: f64 = 1e-12;

fn chart_at(id: &str, args: &[f64]) -> f64 {
    let c = charts::get(id).unwrap_or_else(|| panic!("chart {id} is embedded"));
    let l = c.lookup(args);
    assert!(l.warnings.is_empty(), "{id} {args:?}: {:?}", l.warnings);
    l.value.unwrap_or_else(|| panic!("{id} {args:?}: no value"))
}

fn spot(id: &str, cases: &[(&[f64], f64)]) {
    for (args, want) in cases {
        let got = chart_at(id, args);
        assert!(
            (got - want).abs() <= EXACT,
            "{id} {args:?}: {got} != {want}"
        );
    }
}

#[test]
fn body_charts_are_the_data_statements() {
    // BODYRT 2387-2388: X21120 /4.,5.,6.,8.,...,20./, Y21120 /.77,.825,.865,.91,...,.975/.
    spot(
        "4.2.1.1-20",
        &[(&[4.0], 0.77), (&[8.0], 0.91), (&[20.0], 0.975)],
    );
    // BODYRT 2382-2383: X1217A /2.,4.,8.,...,28./, Y1217A /.56,.6,.66,...,.79/.
    spot(
        "4.2.1.2-35a",
        &[(&[2.0], 0.56), (&[12.0], 0.71), (&[28.0], 0.79)],
    );
    // BODYRT 2375-2377: X1217B /0.,.2,.3,.36,.4,...,1./, Y1217B /1.2,1.2,1.21,1.23,1.27,...,
    // 3*1.8,1.79/ (0.86, 0.9 and 0.98 all 1.8).
    spot(
        "4.2.1.2-35b",
        &[(&[0.36], 1.23), (&[0.9], 1.8), (&[1.0], 1.79)],
    );
    // BODYRT 2368-2369: X27I /1.57780,1.67221,1.98509,2.28874/ at X27M /0.,1.,2.,3./; the
    // intercept is the value at log10(l/k) = 0, and the slope 1.0482 (line 2504) gives
    // 10.482 more at log10(l/k) = 10.
    spot(
        "4.1.5.1-27",
        &[
            (&[0.0, 0.0], 1.5778),
            (&[2.0, 0.0], 1.98509),
            (&[3.0, 10.0], 2.28874 + 10.482),
        ],
    );
    // FIG26 9431-9441: A(1) = 4.12963E-6 (power 5 at M = 0), E(3) = 2.33437E-2 (power 1 at
    // M = 0.7), C(9) = 1.49335E-3 (power 3 at M = 3).
    spot(
        "4.1.5.1-26",
        &[
            (&[0.0, 5.0], 4.12963e-6),
            (&[0.7, 1.0], 2.33437e-2),
            (&[3.0, 3.0], 1.49335e-3),
        ],
    );
    // BODOPT 1868-1869: XBA1 /0.0,0.5,...,4.0/, YBA1 /0.0,.72,1.33,...,3.37/.
    spot(
        "4.2.1.2-36a",
        &[(&[0.5], 0.72), (&[2.0], 2.225), (&[4.0], 3.37)],
    );
    // BODOPT 1873-1874: YBA2 /3.14,3.14,3.15,3.19,3.21,3.626,3.31,3.9,3.47/.
    spot(
        "4.2.1.2-36b",
        &[
            (&[0.0], KV_SMALL_ASPECT_RATIO),
            (&[2.5], 3.626),
            (&[3.5], 3.9),
        ],
    );
    // BODOPT 1878-1884: YBA3 column a/b = 1 starts 34.85 (l/d = 0); a/b = 2, l/d = 5 is 9.10;
    // a/b = 4, l/d = 10 is 1.70; the a/b = 100 column is 12*0.
    spot(
        "4.2.1.2-37",
        &[
            (&[1.0, 0.0], 34.85),
            (&[2.0, 5.0], 9.10),
            (&[4.0, 10.0], 1.70),
            (&[100.0, 3.0], 0.0),
        ],
    );
}

#[test]
fn body_figures_come_from_the_body_chart_files() {
    // Figures 4.1.5.1-26/-27 serve other components too; whichever file holds an id must be
    // the body's as long as the body reads it with these axes.
    for id in FIGURES {
        let c = charts::get(id).unwrap_or_else(|| panic!("chart {id} is embedded"));
        assert!(c.file.starts_with("body/"), "{id} comes from {}", c.file);
        assert!(c.source.lines.chars().any(|ch| ch.is_ascii_digit()), "{id}");
    }
}

#[test]
fn a_step_in_the_area_places_x1_at_the_step() {
    // The area drops from π·0.25 to π·0.09 at x = 4 m (station 4 repeated): −dS/dx is infinite
    // there, so x1 = 4 and x0 = 0.378·5 + 0.527·4 = 3.998 m. (The original's slope is not a
    // number there and it ends with x1 = l.)
    let text = CONE_CYLINDER.replace(
        "NX=5.0, X(1)=0.0,1.0,5.0,9.5,10.0, R(1)=0.0,0.5,0.5,0.5,0.5",
        "NX=5.0, X(1)=0.0,1.0,4.0,4.0,5.0, R(1)=0.0,0.5,0.5,0.3,0.3",
    );
    let r = run_case(&case_of(&text)).unwrap();
    let BodyTerms::Axisymmetric(t) = &r.terms else {
        panic!()
    };
    close("x1", t.x1, 4.0, HAND);
    close("x0", t.x0, 3.998, HAND);
    assert!(r
        .warnings
        .iter()
        .any(|w| matches!(w, BodyWarning::AreaStep { x1 } if *x1 == 4.0)));
}

/// A cambered body computed, with its method's terms.
fn cambered(text: &str) -> (BodyAlone, datcom::methods::body::Cambered) {
    let r = run_case(&case_of(text)).expect("the cambered body is computed");
    let BodyTerms::Cambered(t) = &r.terms else {
        panic!("cambered terms: {:?}", r.terms)
    };
    let t = t.clone();
    (r, t)
}

#[test]
fn a_cambered_body_widest_at_the_nose_takes_its_potential_force_there() {
    // The cambered-body method puts the potential normal force on the forebody up to the
    // station where the radius first reaches 0.96 of its largest value; with the largest at
    // the first station (a blunt nose) there is none ahead of it (the original reads outside
    // its arrays). The area grows in a step at the nose, so the force acts there: centre at
    // x = 0, forebody planform area 0, and CMA = CLA·(XCG − 0)/c̄ = CLA·5/1.
    let text = CONE_CYLINDER.replace(
        "NX=5.0, X(1)=0.0,1.0,5.0,9.5,10.0, R(1)=0.0,0.5,0.5,0.5,0.5",
        "NX=3.0, X(1)=0.0,5.0,10.0, R(1)=0.5,0.4,0.3,
   ZU(1)=0.5,0.4,0.3, ZL(1)=-0.5,-0.4,-0.3",
    );
    let (r, t) = cambered(&text);
    assert_eq!(t.forebody_station, 0.0);
    assert_eq!(t.forebody_planform_area, 0.0);
    assert_eq!(t.potential_centre_over_length, 0.0);
    close("CMA", t.cma_per_rad, t.cla_per_rad * 5.0, HAND);
    assert!(t.cla_per_rad > 0.0);
    assert!(r
        .warnings
        .iter()
        .any(|w| matches!(w, BodyWarning::BluntNose)));
    assert!(r.cl.iter().chain(&r.cm).all(Option::is_some));
}

#[test]
fn a_nose_already_near_its_largest_radius_is_not_refused() {
    // The original finds the station of 0.96 rmax on the interval ending at the largest
    // radius, extrapolating backwards when the radius already exceeds 0.96 rmax at its start.
    // Where that lands at or before the nose, the station is where the radius first reaches
    // 0.96 rmax: on a cone-cylinder X = 0, 1, 10, R = 0, 0.49, 0.5 it is 0.48/0.49 of the way
    // up the cone (the extrapolation gave x = -8 and the body was refused); with the radius
    // above 0.96 rmax at the first station (R = 0.49, 0.5, 0.3) the nose is blunt.
    let body = |stations: &str| {
        CONE_CYLINDER.replace(
            "NX=5.0, X(1)=0.0,1.0,5.0,9.5,10.0, R(1)=0.0,0.5,0.5,0.5,0.5",
            stations,
        )
    };
    let cone = body(
        "NX=3.0, X(1)=0.0,1.0,10.0, R(1)=0.0,0.49,0.5,
   ZU(1)=0.0,0.49,0.5, ZL(1)=0.0,-0.49,-0.5",
    );
    let (r, t) = cambered(&cone);
    close("x96", t.forebody_station, 0.48 / 0.49, HAND);
    assert!(!r
        .warnings
        .iter()
        .any(|w| matches!(w, BodyWarning::BluntNose)));

    let near = body(
        "NX=3.0, X(1)=0.0,5.0,10.0, R(1)=0.49,0.5,0.3,
   ZU(1)=0.49,0.5,0.3, ZL(1)=-0.49,-0.5,-0.3",
    );
    let (r, t) = cambered(&near);
    assert_eq!(t.potential_centre_over_length, 0.0);
    assert!(r
        .warnings
        .iter()
        .any(|w| matches!(w, BodyWarning::BluntNose)));
}

#[test]
fn at_mach_zero_only_the_drag_is_missing() {
    // No Reynolds number at M = 0 (no speed): no skin friction, so no CD, CN, CA; the
    // slender-body lift and moment do not need them.
    let text = CONE_CYLINDER.replace(
        "MACH(1)=0.3, RNNUB(1)=1.0E6,",
        "MACH(1)=0.0, NALT=1.0, ALT(1)=0.0,",
    );
    let r = run_case(&case_of(&text)).unwrap();
    assert!(r.zero_lift_drag.is_none());
    assert!(r.cd.iter().chain(&r.cn).chain(&r.ca).all(Option::is_none));
    assert!(r.cl.iter().chain(&r.cm).all(Option::is_some));
    assert!(r
        .warnings
        .iter()
        .any(|w| matches!(w, BodyWarning::NoZeroLiftDrag { .. })));
}

// ---------------------------------------------------------------------------------------------
// Any body: no panic, no NaN or infinity out.

fn body_deck(
    x_steps: &[f64],
    radii: &[f64],
    camber: Option<f64>,
    method2: bool,
    alphas: &[f64],
    mach: f64,
) -> String {
    let mut x = vec![0.0];
    for s in x_steps.iter().take(radii.len() - 1) {
        x.push(x.last().unwrap() + s);
    }
    let n = x.len();
    let list = |v: &[f64]| {
        v.iter()
            .map(|a| format!("{a:.3}"))
            .collect::<Vec<_>>()
            .join(",")
    };
    let mut text = format!(
        " $FLTCON NMACH=1.0, MACH(1)={mach:.3}, RNNUB(1)=2.0E6,\n   NALPHA={}.0,\n   ALSCHD(1)={}$\n $OPTINS SREF=2.0, CBARR=1.5$\n $SYNTHS XCG=1.0$\n $BODY NX={n}.0,{}\n   X(1)={},\n   R(1)={}",
        alphas.len(),
        list(alphas),
        if method2 { " METHOD=2.0," } else { "" },
        list(&x),
        list(&radii[..n]),
    );
    if let Some(c) = camber {
        let zu: Vec<f64> = radii[..n].iter().map(|r| r + c).collect();
        let zl: Vec<f64> = radii[..n].iter().map(|r| -r + c).collect();
        text.push_str(&format!(
            ",\n   ZU(1)={},\n   ZL(1)={}",
            list(&zu),
            list(&zl)
        ));
    }
    text.push_str("$\n");
    text
}

proptest::proptest! {
    #![proptest_config(proptest::prelude::ProptestConfig::with_cases(256))]
    #[test]
    fn any_body_gives_numbers_or_none_never_nan(
        x_steps in proptest::collection::vec(0.0f64..3.0, 8),
        radii in proptest::collection::vec(0.0f64..1.0, 2..8),
        camber in proptest::option::of(-0.3f64..0.3),
        method2 in proptest::bool::ANY,
        alphas in proptest::collection::vec(-30.0f64..60.0, 1..6),
        mach in 0.0f64..0.6,
    ) {
        let mut alphas = alphas;
        alphas.sort_by(f64::total_cmp);
        let text = body_deck(&x_steps, &radii, camber, method2, &alphas, mach);
        let deck = datcom::read_deck(&text, "gen.dcm");
        let case = &deck.cases[0];
        let (Some(b), Some(f)) = (&case.body, &case.flight) else { return Ok(()) };
        let Ok(g) = body(b) else { return Ok(()) };
        for c in &case.conditions {
            if let Ok(r) = body_alone(case, &g, c, &f.alpha_deg) {
                for v in [&r.cd, &r.cl, &r.cm, &r.cn, &r.ca, &r.xcp, &r.cla_per_rad, &r.cma_per_rad] {
                    proptest::prop_assert_eq!(v.len(), f.alpha_deg.len());
                    proptest::prop_assert!(v.iter().flatten().all(|x| x.is_finite()));
                }
            }
        }
    }
}
