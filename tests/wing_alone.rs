//! Wing alone at subsonic speeds (src/methods/wing) against the original program and against
//! values worked by hand from the DATCOM equations; the wing charts against their DATA lines.
//!
//! Oracle: every `WING ALONE CONFIGURATION` static table of ../shared/oracle/cases/*/for006.dat
//! whose flight condition is subsonic (Mach ≤ STMACH), compared number by number with
//! `datcom::report::compare::agrees` (within max(2 %, one unit in the last printed digit)).
//! Run `cargo test --test wing_alone -- --nocapture` to see the figures.

mod common;

use datcom::case::{Case, Deck};
use datcom::charts;
use datcom::methods::body::subsonic_limit;
use datcom::methods::section::SectionCharacteristics;
use datcom::methods::wing::{
    computed_wing_section, figures, helmbold_lift_curve_slope, wing_alone_with_section, WingAlone,
    WingType, WingWarning,
};
use datcom::report::compare::agrees;
use datcom::report::legacy::{self, ListedCondition};

/// Columns of the static table we compute.
const COLUMNS: [&str; 8] = ["CD", "CL", "CM", "CN", "CA", "XCP", "CLA", "CMA"];
/// Angles of attack in the listing are printed with one decimal (F5.1).
const ALPHA_PRINTED: f64 = 0.05;
/// Mach numbers in the FLIGHT CONDITIONS row are printed with three decimals (F6.3).
const MACH_PRINTED: f64 = 0.0005;
/// The oracle: 15 subsonic WING ALONE tables, 150 rows (docs/wing.md).
const ORACLE_TABLES: usize = 14;
const ORACLE_ROWS: usize = 150;
/// Figures reached per column (floors; docs/wing.md explains each miss), with the section
/// computed at the flight Reynolds number (the library) and the original's way (10⁶).
const FLOORS_LIBRARY: [usize; 8] = [140, 139, 149, 139, 142, 142, 137, 140];
const FLOORS_ORIGINAL_RE: [usize; 8] = [150, 150, 150, 150, 150, 150, 149, 150];

struct Tally {
    matched: Vec<usize>,
    total: Vec<usize>,
    misses: Vec<String>,
}

impl Tally {
    fn new() -> Tally {
        Tally {
            matched: vec![0; COLUMNS.len()],
            total: vec![0; COLUMNS.len()],
            misses: Vec::new(),
        }
    }
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

fn value(ours: &WingAlone, column: &str, i: usize, unit: f64) -> Option<f64> {
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

fn compare_table(
    case: &Case,
    k: usize,
    listed: &ListedCondition,
    at: &str,
    how: SectionRe,
    tally: &mut Tally,
) -> usize {
    let table = listed.statics.as_ref().expect("a static table");
    let alpha = case
        .flight
        .as_ref()
        .map(|f| f.alpha_deg.clone())
        .unwrap_or_default();
    let sec = section(case, how);
    let ours = match wing_alone_with_section(case, k, &alpha, sec.as_ref()) {
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
            let ours_v = value(&ours, column, i, unit);
            // The original prints NA (no number) where the method does not apply; ours is none.
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

/// Compares every subsonic wing-alone table of the oracle; returns (tables, rows).
fn run_oracle(
    decks: &[(String, Deck, String)],
    how: SectionRe,
    tally: &mut Tally,
) -> (usize, usize) {
    let (mut tables, mut rows) = (0, 0);
    for (name, deck, text) in decks {
        let listings = common::case_listings(text);
        for (ci, (case, listing)) in deck.cases.iter().zip(&listings).enumerate() {
            let mut next = 0;
            for listed_case in legacy::read_listing(listing) {
                for listed in &listed_case.conditions {
                    if !listed.configuration.contains("WING ALONE CONFIGURATION")
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
                    rows += compare_table(case, k, listed, &at, how, tally);
                }
            }
        }
    }
    (tables, rows)
}

fn report(title: &str, tables: usize, rows: usize, tally: &Tally) {
    eprintln!("{title}: {tables} subsonic WING ALONE tables, {rows} rows");
    for (j, c) in COLUMNS.iter().enumerate() {
        eprintln!("{c:>4}: {} / {}", tally.matched[j], tally.total[j]);
    }
    for m in &tally.misses {
        eprintln!("  miss: {m}");
    }
}

#[test]
fn wing_alone_tables_agree_with_the_original() {
    let Some(decks) = common::oracle_decks("wing_alone oracle", &["WING ALONE CONFIGURATION"])
    else {
        return;
    };
    for (how, title, floors) in [
        (
            SectionRe::Flight,
            "library (section at the flight Reynolds number)",
            FLOORS_LIBRARY,
        ),
        (
            SectionRe::Original,
            "section at Re = 1E6 (the original's)",
            FLOORS_ORIGINAL_RE,
        ),
    ] {
        let mut tally = Tally::new();
        let (tables, rows) = run_oracle(&decks, how, &mut tally);
        report(title, tables, rows, &tally);
        assert_eq!(tables, ORACLE_TABLES, "tables compared");
        assert_eq!(rows, ORACLE_ROWS, "rows compared");
        for (j, c) in COLUMNS.iter().enumerate() {
            assert!(
                tally.matched[j] >= floors[j],
                "{title}: {c} {} / {} below the floor {}",
                tally.matched[j],
                tally.total[j],
                floors[j]
            );
        }
    }
}

// ---------------------------------------------------------------------------------------------
// Values worked by hand from the DATCOM equations.

/// Hand-worked values are compared to this (they are written to 6 or more digits).
const HAND: f64 = 1e-6;

#[test]
fn lift_curve_slope_by_hand() {
    // DATCOM 4.1.3.2 eq. (a): CLα = 2πA / (2 + √((2πA/c_lα)² (1 + tan²Λc/2/β²) + 4)).
    // A = 6, c_lα = 2π, Λc/2 = 0, M = 0: (2π·6/2π)² = 36, √(36 + 4) = 6.324555,
    // CLα = 12π / 8.324555 = 37.699112 / 8.324555 = 4.528664 per rad.
    let s = helmbold_lift_curve_slope(6.0, 2.0 * std::f64::consts::PI, 0.0, 1.0);
    assert!((s - 4.528664).abs() < HAND, "{s}");
    // A = 4, c_lα = 6.0, tan Λc/2 = 0.5, M = 0.6 (β = 0.8): 2πA/c_lα = 4.188790,
    // 1 + 0.25/0.64 = 1.390625, 4.188790² · 1.390625 = 24.399855, √(28.399855) = 5.329151,
    // CLα = 8π / 7.329151 = 3.429147 per rad.
    let s = helmbold_lift_curve_slope(4.0, 6.0, 0.5, 0.8);
    assert!((s - 3.429147).abs() < HAND, "{s}");
}

/// A = 6, λ = 0.5, Λc/4 = 30°, no body: CHRDR 2, CHRDTP 1, SSPN = SSPNE = 4.5 (S = 13.5,
/// A = 4·4.5²/13.5 = 6), SAVSI 30 at CHSTAT 0.25.
fn twisted_planform() -> datcom::methods::wing::WingPlanform {
    use datcom::case::Planform;
    use datcom::geometry::{planform, Span};
    use datcom::methods::wing::{Chords, MaxThicknessStations, WingPlanform};
    let p = Planform {
        chrdr: Some(2.0),
        chrdtp: Some(1.0),
        sspn: Some(4.5),
        sspne: Some(4.5),
        savsi_deg: Some(30.0),
        chstat: Some(0.25),
        twista_deg: Some(-3.0),
        ..Planform::default()
    };
    let g = planform(&p, Span::Both).expect("planform");
    WingPlanform::new(
        &g,
        Chords {
            tip: 1.0,
            at_break: 1.0,
        },
        MaxThicknessStations::default(),
    )
}

#[test]
fn twist_changes_the_zero_lift_angle_by_hand() {
    use datcom::methods::wing::wing_zero_lift_angle;
    // DATCOM 4.1.3.1: α0 = α0,section + θ (Δα0/θ). Figure 4.1.3.1-4 at λ = 0.5, A = 6,
    // Λc/4 = 30°: DA0OT(16, 6) (column 3·(2−1)+3, DATA DAP line 2831ff, 126th value) = −0.3965.
    // θ = −3°, α0,section = −2°: α0 = −2 + (−3)(−0.3965) = −0.8105° (uncambered: no Mach factor).
    let p = twisted_planform();
    let mut w = Vec::new();
    let z = wing_zero_lift_angle(&p, -2.0, -3.0, false, Some(0.1), 0.2, &mut w).unwrap();
    assert_eq!(z.per_twist, Some(-0.3965));
    assert!((z.wing_deg - (-0.8105)).abs() < HAND, "{}", z.wing_deg);
    assert!(w.is_empty(), "{w:?}");
}

/// The original's CALCA0 corrects the zero-lift angle for a twist of 0.5° or more only
/// (a build of its source prints the untwisted wing's CL for a deck with TWISTA = 0.39°):
/// with the original's reading a smaller twist leaves the angle as untwisted; the handbook's
/// reading applies any twist.
#[test]
fn the_originals_zero_lift_angle_leaves_a_twist_below_half_a_degree_out() {
    use datcom::methods::wing::{wing_zero_lift_angle_read, ZeroLiftReading};
    let p = twisted_planform();
    let mut w = Vec::new();
    let mut at = |twist: f64, reading| {
        wing_zero_lift_angle_read(&p, -2.0, twist, false, Some(0.1), 0.2, reading, &mut w)
            .unwrap()
            .wing_deg
    };
    let untwisted = at(0.0, ZeroLiftReading::Original);
    assert_eq!(at(0.4, ZeroLiftReading::Original), untwisted);
    assert_eq!(at(-0.4, ZeroLiftReading::Original), untwisted);
    assert_ne!(at(0.5, ZeroLiftReading::Original), untwisted);
    assert_ne!(at(0.4, ZeroLiftReading::Handbook), untwisted);
}

#[test]
fn twist_changes_the_zero_lift_moment_by_hand() {
    use datcom::methods::wing::zero_lift_moment;
    // DATCOM 4.1.4.1: Cm0 = [A cos²Λ/(A + 2 cos Λ) cm0 + (ΔCm0/θ) θ] (Mach factor)
    // S_exp c̄_exp/(S_ref c̄_ref). cm0 = 0; figure 4.1.4.1-5 at λ = 0.5, A = 6, Λc/4 = 30°:
    // Y415 value 170 (DATA Y415A line 4621ff; slab 2, AR index 3, sweep index 16) = −0.0054;
    // figure 4.1.4.1-6 at M = 0.2: 1.0 (XCMOM 0, 0.25 → YCMOM 1, 1); S_ref = S_exp = 13.5,
    // c̄_ref = c̄_exp: Cm0 = (−0.0054)(−3) = 0.0162.
    let p = twisted_planform();
    let mut w = Vec::new();
    let m = zero_lift_moment(&p, 0.0, -3.0, 0.2, p.exposed_area, p.mac, &mut w).unwrap();
    assert_eq!(m.per_twist, Some(-0.0054));
    assert!((m.cm0 - 0.0162).abs() < HAND, "{}", m.cm0);
}

#[test]
fn twist_drag_by_hand() {
    use datcom::methods::wing::{drag_due_to_lift, DragInputs};
    // DATCOM 4.1.5.2: CDL = CL²/(πAe) + θ' CL v + θ'² w, θ' = 2π θ/57.3 (the original's
    // scaling), θ = −3°: θ' = −0.3289868. M = 0 (β = 1), Λc/4 = 30°, βA = 6, λ = 0.5:
    // v = figure 4.1.5.2-42, Y42 value 272 (DATA Y42A line 3323ff) = 0.00238;
    // βw = figure 4.1.5.2-48, Y48 value 215 (DATA Y48A line 3387ff) = 0.00184.
    // The twist terms at CL = 0.5: θ' CL v + θ'² w = −0.000391494 + 0.000199147 = −0.000192347;
    // at CL = 0: θ'² w = 0.000199147.
    let p = twisted_planform();
    let inputs = |twist_deg: f64| DragInputs {
        planform: &p,
        kind: WingType::Straight,
        mach: 0.0,
        beta: 1.0,
        reynolds_per_length: 1e6,
        roughness: 1e-5,
        reference_area: p.exposed_area,
        thickness_ratio: 0.1,
        max_thickness_x: Some(0.3),
        outboard_thickness_ratio: 0.1,
        outboard_max_thickness_x: Some(0.3),
        leading_edge_radius: 0.01,
        outboard_leading_edge_radius: 0.01,
        twist_deg,
    };
    let mut w = Vec::new();
    let twisted =
        drag_due_to_lift(&inputs(-3.0), 4.0, &[0.0, 0.5], &[0.0, 5.0], None, &mut w).unwrap();
    let plain =
        drag_due_to_lift(&inputs(0.0), 4.0, &[0.0, 0.5], &[0.0, 5.0], None, &mut w).unwrap();
    assert_eq!(twisted.twist_v, Some(0.00238));
    assert!(
        (twisted.cd[0] - 0.000199147).abs() < HAND,
        "{}",
        twisted.cd[0]
    );
    assert!((twisted.cd[1] - plain.cd[1] - (-0.000192347)).abs() < HAND);
}

/// Example problem 2, case 1 of the original's manual (sprob case 5): a straight tapered
/// low-aspect-ratio wing with camber and incidence, no body.
const EXAMPLE_2: &str =
    " $FLTCON NMACH=1.0,MACH(1)=0.60,NALPHA=11.,ALSCHD(1)=-6.0,-4.0,-2.0,0.0,2.0,
  4.0,8.0,12.0,16.0,20.0,24.0,RNNUB(1)=4.28E6$
 $OPTINS SREF=8.85,CBARR=2.46,BLREF=4.28$
 $SYNTHS XW=3.61,ZW=-.80,ALIW=2.0,XCG=4.14$
 $WGPLNF CHRDTP=0.64,SSPNE=1.59,SSPN=1.59,CHRDR=2.90,SAVSI=55.0,CHSTAT=0.0,
  TWISTA=0.0,SSPNDD=0.0,DHDADI=0.0,DHDADO=0.0,TYPE=1.0$
 $WGSCHR DELTAY=2.85,XOVC=0.40,CLI=0.127,ALPHAI=0.123,CLALPA(1)=.1335,
  TOVC=0.11,CLMAXL=1.55,
  CLMAX(1)=1.195,CMO=-.0262,LERI=.0134,CAMBER=.TRUE.,CLAMO=.105,TCEFF=0.055$
CASEID STRAIGHT TAPERED EXPOSED WING SOLUTION
NEXT CASE
";

#[test]
fn totals_are_sums_of_named_terms() {
    let deck = datcom::read_deck(EXAMPLE_2, "example2.dcm");
    let case = &deck.cases[0];
    let alpha = case.flight.as_ref().unwrap().alpha_deg.clone();
    let r = datcom::methods::wing::wing_alone(case, 0, &alpha).unwrap();
    let cd0 = r.terms.zero_lift_drag.as_ref().unwrap().total;
    let cdl = &r.terms.drag_due_to_lift.as_ref().unwrap().cd;
    let m = r.terms.pitching_moment.as_ref().unwrap();
    for k in 0..alpha.len() {
        assert_eq!(r.cd[k], Some(cd0 + cdl[k]));
        assert_eq!(r.cl[k], Some(r.terms.lift[k].cl));
        assert_eq!(r.cm[k], Some(m.cm[k]));
        // The methods see the schedule angle plus ALIW = 2.
        assert_eq!(r.terms.lift[k].alpha_deg, alpha[k] + 2.0);
    }
    assert_eq!(r.cla_per_rad[0], Some(r.terms.lift_curve_slope.per_rad));
    assert_eq!(
        r.cma_per_rad[0],
        Some(m.dcm_dcl * r.terms.lift_curve_slope.per_rad)
    );
    assert!(r.terms.aspect_ratio_class.low_aspect_ratio);
    // Low-aspect-ratio straight wing: the NA rule does not apply.
    assert!(r.cm.iter().all(Option::is_some));
}

#[test]
fn above_stmach_is_refused() {
    let text = EXAMPLE_2.replace("MACH(1)=0.60", "MACH(1)=0.90");
    let deck = datcom::read_deck(&text, "example2.dcm");
    let case = &deck.cases[0];
    let e = datcom::methods::wing::wing_alone(case, 0, &[0.0]).unwrap_err();
    assert!(e.to_string().contains("STMACH"), "{e}");
    assert_eq!(WingType::from_input(Some(3.0)), Some(WingType::Cranked));
    let _ = WingWarning::NoSectionMaxLift.to_string();
}

// ---------------------------------------------------------------------------------------------
// Chart spot values: each written from the DATA statement lines of datcom.f (cited), at nodes.

const SPOTS: &[(&str, &[f64], f64)] = &[
    // BA(1) = 1.15, CLOVCL(1) = 1.25; BA 49533-49533; CLOVCL 49534-49534
    ("4.1.3.2-52", &[1.15], 1.25),
    // BA(6) = 3.6, CLOVCL(6) = 1; BA 49533-49533; CLOVCL 49534-49534
    ("4.1.3.2-52", &[3.6], 1.0),
    // BA(12) = 9, CLOVCL(12) = 0.94; BA 49533-49533; CLOVCL 49534-49534
    ("4.1.3.2-52", &[9.0], 0.94),
    // TR(2) = 0.1, C2(2) = 0.21; TR 49502-49502; C2 49503-49503
    ("4.1.3.4-24b-c2", &[0.1], 0.21),
    // TR(5) = 0.4, C2(5) = 1.08; TR 49502-49502; C2 49503-49503
    ("4.1.3.4-24b-c2", &[0.4], 1.08),
    // C1ABCS(4) = 1.2, ACLMX(4) = 32; C1ABCS 49507-49507; ACLMX 49508-49508
    ("4.1.3.4-25a", &[1.2], 32.0),
    // C1ABCS(10) = 3.6, ACLMX(10) = 21; C1ABCS 49507-49507; ACLMX 49508-49508
    ("4.1.3.4-25a", &[3.6], 21.0),
    // TIR(2) = 0.1, C90(2) = 1.32; TIR 17230-17230; C90 17236-17236; C90I 17235-17235
    ("4.1.3.3-55b-ar", &[0.1], 1.32),
    // TIR(6) = 0.5, C90(6) = 1.2; TIR 17230-17230; C90 17236-17236; C90I 17235-17235
    ("4.1.3.3-55b-ar", &[0.5], 1.2),
    // TIR(2) = 0.1, C90I(2) = 1.4; TIR 17230-17230; C90 17236-17236; C90I 17235-17235
    ("4.1.3.3-55b-inverse-ar", &[0.1], 1.4),
    // TIR(4) = 0.3, C90I(4) = 1.21; TIR 17230-17230; C90 17236-17236; C90I 17235-17235
    ("4.1.3.3-55b-inverse-ar", &[0.3], 1.21),
    // TIR(4) = 0.3, D(4) = -1; TIR 17230-17230; D 17231-17231
    ("4.1.3.3-D", &[0.3], -1.0),
    // TIR(7) = 0.6, D(7) = -1.55; TIR 17230-17230; D 17231-17231
    ("4.1.3.3-D", &[0.6], -1.55),
    // X13357(5) = 0.4, Y13357(5) = 7; X13357 17274-17274; Y13357 17275-17275
    ("4.1.3.3-57", &[0.4], 7.0),
    // X13357(9) = 0.8, Y13357(9) = 6.2; X13357 17274-17274; Y13357 17275-17275
    ("4.1.3.3-57", &[0.8], 6.2),
    // XCMOM(9) = 0.6, YCMOM(9) = 1.132; XCMOM 4606-4607; YCMOM 4608-4610
    ("4.1.4.1-6", &[0.6], 1.132),
    // XCMOM(15) = 0.9, YCMOM(15) = 1.445; XCMOM 4606-4607; YCMOM 4608-4610
    ("4.1.4.1-6", &[0.9], 1.445),
    // X211A(3) = 0.42, Y11A(3) = 0.58; X211A 4714-4714; Y11A 4715-4715
    ("4.1.4.3-21a", &[0.42], 0.58),
    // X211A(8) = 1.2, Y11A(8) = 0.59; X211A 4714-4714; Y11A 4715-4715
    ("4.1.4.3-21a", &[1.2], 0.59),
    // X211B(4) = 0.5, Y11B(4) = 1.05; X211B 4724-4724; Y11B 4723-4723
    ("4.1.4.3-21b", &[0.5], 1.05),
    // X211B(6) = 0.8, Y11B(6) = 1.75; X211B 4724-4724; Y11B 4723-4723
    ("4.1.4.3-21b", &[0.8], 1.75),
    // X53B(1) = 0, Y53B(1) = 0.72956; X53B 3434-3434; Y53B 3435-3436
    ("4.1.5.2-53b", &[0.0], 0.72956),
    // X53B(6) = 6, Y53B(6) = 0.96226; X53B 3434-3434; Y53B 3435-3436
    ("4.1.5.2-53b", &[6.0], 0.96226),
    // X1OA(3) = 0.2, Y1OA(3) = 1.16; X1OA 3289-3289; Y1OA 3290-3290
    ("4.3.1.2-10a", &[0.2], 1.16),
    // X1OA(8) = 0.7, Y1OA(8) = 1.67; X1OA 3289-3289; Y1OA 3290-3290
    ("4.3.1.2-10a", &[0.7], 1.67),
    // AJ(1) = -4, TRAT(1) = 0.2: DC(1) = -0.9; AJ 17216-17216; TRAT 17217-17217; DC 17218-17223
    ("4.1.3.3-55a", &[-4.0, 0.2], -0.9),
    // AJ(9) = 1.5, TRAT(4) = 0.5: DC(60) = 1.852; AJ 17216-17216; TRAT 17217-17217; DC 17218-17223
    ("4.1.3.3-55a", &[1.5, 0.5], 1.852),
    // X13356(2) = 4, X23356(1) = 0: Y13356(13) = 0.165; X13356 17241-17241; X23356 17245-17245; Y13356 17249-17254
    ("4.1.3.3-56", &[4.0, 0.0], 0.165),
    // X13356(4) = 12, X23356(6) = 5: Y13356(42) = 0.25; X13356 17241-17241; X23356 17245-17245; Y13356 17249-17254
    ("4.1.3.3-56", &[12.0, 5.0], 0.25),
    // DELTAY(1) = 1.4, SALE(13) = 60: CLL(13) = 1.3; DELTAY 49483-49483; SALE 49482-49482; CLL 49484-49489
    ("4.1.3.4-21a", &[1.4, 60.0], 1.3),
    // DELTAY(4) = 2, SALE(7) = 30: CLL(46) = 0.89; DELTAY 49483-49483; SALE 49482-49482; CLL 49484-49489
    ("4.1.3.4-21a", &[2.0, 30.0], 0.89),
    // DY(1) = 1.2, SALE(4) = 15: DACLL(4) = 2.7; DY 49493-49493; SALE 49482-49482; DACLL 49494-49497
    ("4.1.3.4-21b", &[1.2, 15.0], 2.7),
    // DY(3) = 3, SALE(11) = 50: DACLL(37) = 5.3; DY 49493-49493; SALE 49482-49482; DACLL 49494-49497
    ("4.1.3.4-21b", &[3.0, 50.0], 5.3),
    // DYAG(1) = 0, C1ABC(2) = 0.2: CBASE(2) = 1.38; DYAG 4259-4259; C1ABC 4257-4258; CBASE 4260-4275
    ("4.1.3.4-23a", &[0.0, 0.2], 1.38),
    // DYAG(6) = 1.35, C1ABC(11) = 2: CBASE(106) = 0.91; DYAG 4259-4259; C1ABC 4257-4258; CBASE 4260-4275
    ("4.1.3.4-23a", &[1.35, 2.0], 0.91),
    // DYAG(1) = 0, C1ABC(2) = 0.2: CBASE(116) = 1.18; DYAG 4259-4259; C1ABC 4257-4258; CBASE 4260-4275
    ("4.1.3.4-23b", &[0.0, 0.2], 1.18),
    // DYAG(6) = 1.35, C1ABC(11) = 2: CBASE(220) = 0.91; DYAG 4259-4259; C1ABC 4257-4258; CBASE 4260-4275
    ("4.1.3.4-23b", &[1.35, 2.0], 0.91),
    // AMN(1) = 0.2, C2A(7) = 6: DE(7) = 0.115; AMN 4280-4280; C2A 4279-4279; DE 4281-4284
    ("4.1.3.4-24a", &[0.2, 6.0], 0.115),
    // AMN(3) = 0.6, C2A(15) = 14: DE(45) = 0.08; AMN 4280-4280; C2A 4279-4279; DE 4281-4284
    ("4.1.3.4-24a", &[0.6, 14.0], 0.08),
    // DMN(1) = 0.2, C1TAB(4) = 6: DACL(4) = 1.4; DMN 49513-49513; C1TAB 49514-49515; DACL 49516-49519
    ("4.1.3.4-25b", &[0.2, 6.0], 1.4),
    // DMN(3) = 0.6, C1TAB(20) = 14: DACL(60) = 8.5; DMN 49513-49513; C1TAB 49514-49515; DACL 49516-49519
    ("4.1.3.4-25b", &[0.6, 14.0], 8.5),
    // ACLE(1) = 0, C1TABO(3) = 1: DACLO(3) = 6.9; ACLE 49520-49520; C1TABO 49529-49529; DACLO 49521-49528
    ("4.1.3.4-25b-low", &[0.0, 1.0], 6.9),
    // ACLE(4) = 4, C1TABO(6) = 2.5: DACLO(36) = -2.1; ACLE 49520-49520; C1TABO 49529-49529; DACLO 49521-49528
    ("4.1.3.4-25b-low", &[4.0, 2.5], -2.1),
    // X111C(1) = 1, X211C(8) = 5: Y11C(8) = 0.115; X111C 4730-4730; X211C 4731-4731; Y11C 4732-4736
    ("4.1.4.3-22a", &[1.0, 5.0], 0.115),
    // X111C(4) = 6, X211C(15) = 17: Y11C(60) = 0.78; X111C 4730-4730; X211C 4731-4731; Y11C 4732-4736
    ("4.1.4.3-22a", &[6.0, 17.0], 0.78),
    // X112A(1) = 0, X212A(2) = 0.2: Y12A(2) = 4.7; X112A 4742-4742; X212A 4743-4743; Y12A 4744-4748
    ("4.1.4.3-22b", &[0.0, 0.2], 4.7),
    // X112A(5) = 4, X212A(6) = 1: Y12A(30) = -1.65; X112A 4742-4742; X212A 4743-4743; Y12A 4744-4748
    ("4.1.4.3-22b", &[4.0, 1.0], -1.65),
    // X112B1(1) = 0.2, X212B1(4) = 2.5: Y12B1(4) = -0.203; X112B1 4754-4754; X212B1 4755-4756; Y12B1 4757-4767
    ("4.1.4.3-23a", &[0.2, 2.5], -0.203),
    // X112B1(6) = 1, X212B1(25) = -4: Y12B1(150) = 0; X112B1 4754-4754; X212B1 4755-4756; Y12B1 4757-4767
    ("4.1.4.3-23a", &[1.0, -4.0], 0.0),
    // X112B2(1) = 0.6, X212B2(5) = 2.5: Y12B2(5) = -0.29; X112B2 4773-4773; X212B2 4774-4775; Y12B2 4776-4779
    ("4.1.4.3-23b", &[0.6, 2.5], -0.29),
    // X112B2(3) = 1, X212B2(21) = -4: Y12B2(63) = 0; X112B2 4773-4773; X212B2 4774-4775; Y12B2 4776-4779
    ("4.1.4.3-23b", &[1.0, -4.0], 0.0),
    // X113A(1) = 0.25, X213A(5) = 0.25: Y13A(5) = 0.297; X113A 4786-4786; X213A 4785-4785; Y13A 4787-4798
    ("4.1.4.3-24a", &[0.25, 0.25], 0.297),
    // X113A(9) = 6, X213A(15) = 1: Y13A(135) = -0.63; X113A 4786-4786; X213A 4785-4785; Y13A 4787-4798
    ("4.1.4.3-24a", &[6.0, 1.0], -0.63),
    // X113B1(2) = 0.3, X213B1(3) = 0.6: Y13B1(12) = 0.35; X113B1 4805-4805; X213B1 4804-4804; Y13B1 4806-4809
    ("4.1.4.3-24b-1", &[0.3, 0.6], 0.35),
    // X113B1(6) = 1, X213B1(9) = -0.6: Y13B1(54) = 0; X113B1 4805-4805; X213B1 4804-4804; Y13B1 4806-4809
    ("4.1.4.3-24b-1", &[1.0, -0.6], 0.0),
    // X113B2(1) = 0.6, X213B2(1) = 1: Y13B2(1) = 0.3; X113B2 4816-4816; X213B2 4815-4815; Y13B2 4817-4818
    ("4.1.4.3-24b-2", &[0.6, 1.0], 0.3),
    // X113B2(2) = 0.8, X213B2(6) = 0: Y13B2(15) = 0.1; X113B2 4816-4816; X213B2 4815-4815; Y13B2 4817-4818
    ("4.1.4.3-24b-2", &[0.8, 0.0], 0.1),
    // X128B(1) = 0.9, X228B(1) = 0.5: Y28B(1) = 1.1; X128B 3300-3300; X228B 3299-3299; Y28B 3301-3304
    ("4.1.5.1-28b", &[0.9, 0.5], 1.1),
    // X128B(4) = 0.25, X228B(11) = 1: Y28B(44) = 1.07; X128B 3300-3300; X228B 3299-3299; Y28B 3301-3304
    ("4.1.5.1-28b", &[0.25, 1.0], 1.07),
    // X128BD(2) = 0.8, X228BD(1) = 0.45: Y28BD(10) = 1.11; X128BD 3311-3311; X228BD 3310-3310; Y28BD 3312-3314
    ("4.1.5.1-28b-dashed", &[0.8, 0.45], 1.11),
    // X128BD(3) = 0.6, X228BD(9) = 1: Y28BD(27) = 1.15; X128BD 3311-3311; X228BD 3310-3310; Y28BD 3312-3314
    ("4.1.5.1-28b-dashed", &[0.6, 1.0], 1.15),
    // X154(1) = 0.24, X254(1) = 3: Y54(1) = 0.07; X154 3442-3442; X254 3441-3441; Y54 3443-3450
    ("4.1.5.2-54", &[0.24, 3.0], 0.07),
    // X154(6) = 0.14, X254(14) = 9: Y54(84) = 0.0625; X154 3442-3442; X254 3441-3441; Y54 3443-3450
    ("4.1.5.2-54", &[0.14, 9.0], 0.0625),
    // SALE4(1) = 0, DYA(2) = 2.25, AMACH(3) = 0.4: DCAR(8) = -0.19; DYA 49468-49468; AMACH 49467-49467; SALE4 49469-49469; DCAR 49470-49478
    ("4.1.3.4-22", &[0.0, 2.25, 0.4], -0.19),
    // SALE4(4) = 60, DYA(6) = 4.5, AMACH(5) = 0.6: DCAR(120) = -0.2; DYA 49468-49468; AMACH 49467-49467; SALE4 49469-49469; DCAR 49470-49478
    ("4.1.3.4-22", &[60.0, 4.5, 0.6], -0.2),
    // X31412(2) = 0.5, X11412(3) = 6, X21412(10) = 0: Y(164) = 0; X11412 4617-4617; X21412 4618-4620; X31412 4616-4616; Y415A+Y415B+Y415C 4621-4636
    ("4.1.4.1-5", &[0.5, 6.0, 0.0], 0.0),
    // X31412(3) = 1, X11412(5) = 1.5, X21412(22) = 60: Y(330) = -0.001; X11412 4617-4617; X21412 4618-4620; X31412 4616-4616; Y415A+Y415B+Y415C 4621-4636
    ("4.1.4.1-5", &[1.0, 1.5, 60.0], -0.001),
    // X322A(1) = 0, X122A(1) = 6, X222A(1) = 0: Y22A(1) = 0.68; X122A 4675-4675; X222A 4676-4676; X322A 4674-4674; Y22A 4677-4688
    ("4.1.4.2-26a", &[0.0, 6.0, 0.0], 0.68),
    // X322A(6) = 1, X122A(4) = 3, X222A(5) = 0.8: Y22A(203) = 1; X122A 4675-4675; X222A 4676-4676; X322A 4674-4674; Y22A 4677-4688
    ("4.1.4.2-26a", &[1.0, 3.0, 0.8], 1.0),
    // X322B(1) = 0, X122B(1) = 6, X222B(1) = 1: Y22B(1) = 0.78; X122B 4695-4695; X222B 4696-4696; X322B 4694-4694; Y22B 4697-4709
    ("4.1.4.2-26b", &[0.0, 6.0, 1.0], 0.78),
    // X322B(6) = 1, X122B(4) = 3, X222B(5) = 0.2: Y22B(203) = 0.98; X122B 4695-4695; X222B 4696-4696; X322B 4694-4694; Y22B 4697-4709
    ("4.1.4.2-26b", &[1.0, 3.0, 0.2], 0.98),
    // FWDXAC: TGRAPH(1) = 0, TCURVE(1) = 1, TX(1) = 0: SUBT1(1) = 0.08; TGRAPH 10327; TCURVE 10328; TX 10329; SUBT1 10333-10339
    ("4.1.4.2-26a-forward", &[0.0, 1.0, 0.0], 0.08),
    // TGRAPH(6) = 1, TCURVE(6) = 6, TX(1) = 0: SUBT6(31) = -1.25; SUBT6 10383-10389
    ("4.1.4.2-26a-forward", &[1.0, 6.0, 0.0], -1.25),
    // TGRAPH(4) = 0.33, TCURVE(2) = 2, TX(3) = 0.4: SUBT10(9) = -0.13; SUBT10 10423-10429
    ("4.1.4.2-26b-forward", &[0.33, 2.0, 0.4], -0.13),
    // TGRAPH(6) = 1, TCURVE(6) = 6, TX(6) = 1: SUBT12(36) = -1.04; SUBT12 10443-10449
    ("4.1.4.2-26b-forward", &[1.0, 6.0, 1.0], -1.04),
    // TGRAPH(1) = 0, TCURVE(1) = 1, TX(1) = 0: SUPT7(1) = 0.22; SUPT7 10513-10519
    ("4.1.4.2-26-forward-original", &[0.0, 1.0, 0.0], 0.22),
    // TGRAPH(6) = 1, TCURVE(5) = 5, TX(4) = 0.6: SUPT12(28) = -0.67; SUPT12 10563-10569
    ("4.1.4.2-26-forward-original", &[1.0, 5.0, 0.6], -0.67),
    // X342(1) = 0.1, X142(1) = 60, X242(1) = 2: Y(1) = 0.00025; X142 3321-3321; X242 3322-3322; X342 3320-3320; Y42A+Y42B+Y42C+Y42D 3323-3340
    ("4.1.5.2-42", &[0.1, 60.0, 2.0], 0.00025),
    // X342(6) = 0.5, X142(4) = 0, X242(8) = 6: Y(284) = 0.00013; X142 3321-3321; X242 3322-3322; X342 3320-3320; Y42A+Y42B+Y42C+Y42D 3323-3340
    ("4.1.5.2-42", &[0.5, 0.0, 6.0], 0.00013),
    // X348(1) = 0.1, X148(1) = 0, X248(1) = 2: Y(1) = 0.00084; X148 3385-3385; X248 3386-3386; X348 3384-3384; Y48A+Y48B+Y48C 3387-3400
    ("4.1.5.2-48", &[0.1, 0.0, 2.0], 0.00084),
    // X348(6) = 0.5, X148(1) = 0, X248(5) = 6: Y(205) = 0.00191; X148 3385-3385; X248 3386-3386; X348 3384-3384; Y48A+Y48B+Y48C 3387-3400
    ("4.1.5.2-48", &[0.5, 0.0, 6.0], 0.00191),
    // TOC(1) = 16: curve 1 = CX(1..7), CY(1..7): CX(4) = 0.55, CY(4) = 0.65; TOC 2862-2862; CX 2866-2866; CY 2867-2869
    ("4.1.3.1-5", &[16.0, 0.55], 0.65),
    // TOC(3) = 12: curve 3 = CX(5..8), CY(14..17): CX(7) = 0.7, CY(16) = 0.6; TOC 2862-2862; CX 2866-2866; CY 2867-2869
    ("4.1.3.1-5", &[12.0, 0.7], 0.6),
    // TR(2) = 0.5, AR(3) = 6: DA0OT(10, 6) = -0.412 (column 3*(2-1)+3), SAQC(10) = 0; SAQC 2829-2830; AR 2828-2828; TR 2828-2828; DAP+DAPP 2831-2848
    ("4.1.3.1-4", &[0.5, 6.0, 0.0], -0.412),
    // TR(3) = 1, AR(3) = 6: DA0OT(1, 9) = -0.456 (column 3*(3-1)+3), SAQC(1) = -45; SAQC 2829-2830; AR 2828-2828; TR 2828-2828; DAP+DAPP 2831-2848
    ("4.1.3.1-4", &[1.0, 6.0, -45.0], -0.456),
    // TR(3) = 1, AR(1) = 1.5: DA0OT(22, 7) = -0.39 (column 3*(3-1)+1), SAQC(22) = 60; SAQC 2829-2830; AR 2828-2828; TR 2828-2828; DAP+DAPP 2831-2848
    ("4.1.3.1-4", &[1.0, 1.5, 60.0], -0.39),
    // ARCLSS: X(4) = 0.3, Y(4) = 0.496; lines 420-421
    ("4.1.3.4-24b-c1", &[0.3], 0.496),
    // ARCLSS: X(10) = 0.9, Y(10) = 0.0475; lines 420-421
    ("4.1.3.4-24b-c1", &[0.9], 0.0475),
    // FIG53A: ZZ(2) = 1, A(2) = 4.50351E-03 (x^5); line 9472
    ("4.1.5.2-53a", &[1.0, 5.0], 0.00450351),
    // FIG53A: ZZ(4) = 4, E(4) = 1.02609 (x^1); line 9476
    ("4.1.5.2-53a", &[4.0, 1.0], 1.02609),
];

#[test]
fn wing_charts_give_their_data_statement_values() {
    for id in figures::ALL {
        assert!(
            charts::get(id).is_some(),
            "chart {id} is embedded and valid"
        );
    }
    // Spot values for every chart but the cut-off Reynolds number one (only its embedding is
    // checked here).
    common::check_chart_spots(
        figures::ALL
            .iter()
            .copied()
            .filter(|id| *id != figures::CUTOFF_REYNOLDS),
        SPOTS,
    );
}

/// Figure 4.1.3.1-4 as the original's CALCA0 reads it, worked by hand for the Citation's
/// exposed wing (λ = 0.34169, A = 7.9396, Λc/4 = 1.3°; a build of the original printed
/// Δα0/θ = −0.399651 for it). Sweep fraction 1.3/5 = 0.26 between 0° and 5°; the aspect-ratio
/// fraction (7.9396 − 6)/4 = 0.48491. Taper 0.5 curve, A = 6 and 10 (DAP columns 6 and 7 at
/// sweep 0° and 5°: −0.412, −0.409; −0.410, −0.4095): −0.41122 and −0.40987, so −0.41057 at A.
/// Taper 0 curve, read on the pair one lower, A = 3.5 and 6 (columns 2 and 3: −0.384, −0.3825;
/// −0.3685, −0.367): −0.38361 and −0.36811, so −0.37609 at the same fraction. Taper fraction
/// 0.34169/0.5 = 0.68338: −0.37609 + 0.68338 (−0.41057 + 0.37609) = −0.39965. The linear
/// reading of the same chart gives −0.40336 (taper 0, A = 10: −0.409, −0.408 in place of the
/// pair one lower).
#[test]
fn twist_term_read_as_the_original_by_hand() {
    use datcom::methods::wing::twist_term_as_the_original;
    let mut w = Vec::new();
    let original = twist_term_as_the_original(0.341688156, 7.9396224, 1.30000353, &mut w).unwrap();
    assert!((original - (-0.39965)).abs() < 2e-5, "{original}");
    // At or below A = 6, and at a taper node, the reading is the linear one.
    let p = twisted_planform();
    let linear = |t: f64, a: f64| {
        let mut q = p.clone();
        q.taper = t;
        q.aspect_ratio = a;
        datcom::methods::wing::wing_zero_lift_angle(
            &q,
            0.0,
            -1.0,
            false,
            None,
            0.2,
            &mut Vec::new(),
        )
        .unwrap()
        .per_twist
        .unwrap()
    };
    for (t, a) in [(0.34, 5.0), (0.5, 8.0), (0.0, 7.0), (0.8, 2.0)] {
        let o = twist_term_as_the_original(t, a, p.quarter_chord.deg, &mut w).unwrap();
        assert!(
            (o - linear(t, a)).abs() < 1e-12,
            "λ {t}, A {a}: {o} {}",
            linear(t, a)
        );
    }
    assert!((linear(0.341688156, 7.9396224) - original).abs() > 3e-3);
}

/// A wing near DATCOM's boundary between its high- and low-aspect-ratio methods is told so
/// (a sweep across it sees a step in CLmax and the moment); one far from it is not.
#[test]
fn a_wing_near_the_aspect_ratio_boundary_is_told() {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("namelists/example-uav.dcm");
    let text = std::fs::read_to_string(path).expect("the bundled deck");
    let near = |text: &str| {
        let deck = datcom::read_deck(text, "uav.dcm");
        datcom::results::run_case(&deck.cases[0])
            .warnings
            .iter()
            .any(|w| w.to_string().contains("near DATCOM's boundary"))
    };
    assert!(!near(&text), "A = 6.3 is far from the boundary");
    // With the chords kept, A = (2·SSPN)²/(SSPN·(0.44 + 0.32)) = 5.26·SSPN: from 1.05 to 6.3
    // over semi-spans of 0.2 to 1.2 m, across the boundary ARCL/((C1 + 1) cos Λ_LE); the 2 %
    // band around it is a few hundredths of A wide, so few of the 101 spans fall in it.
    let found = (20..=120)
        .filter(|&k| {
            let sspn = f64::from(k) / 100.0;
            near(&text.replace(
                "SSPN=1.20, SSPNE=1.13",
                &format!("SSPN={sspn}, SSPNE={}", sspn - 0.07),
            ))
        })
        .count();
    assert!(
        (1..=4).contains(&found),
        "{found} of 101 semi-spans from 0.2 to 1.2 m put the wing near the boundary"
    );
}
