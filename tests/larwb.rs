//! The low-aspect-ratio wing-body ($LARWB, DATCOM 4.8 and 5.5; docs/larwb.md).
//!
//! Oracle: every `LOW ASPECT RATIO WINGS AND WING-BODY COMBINATIONS` page of
//! ../shared/oracle/cases/*/for006.dat (lkampoli__ex9, and the same lifting body in
//! arktools__sprob), compared number by number within max(2 %, one printed unit), every column
//! (CD ... CLB). Charts: spot values from the DATA statements of the original's LOARWB.

mod common;

use datcom::methods::low_aspect_ratio::{
    figures, low_aspect_ratio_wing_body, normal_force_coefficient, LowAspectRatioError,
    LowAspectRatioFlight, NormalForceTerms,
};
use datcom::report::{compare, json};
use datcom::results::LOW_ASPECT_RATIO;
use serde_json::Value;

/// Only the low-aspect-ratio pages of a run or listing JSON.
fn only_larwb(mut v: Value) -> Value {
    if let Some(cases) = v["cases"].as_array_mut() {
        for c in cases {
            if let Some(conds) = c["conditions"].as_array_mut() {
                conds.retain(|k| k["configuration"].as_str() == Some(LOW_ASPECT_RATIO));
            }
        }
    }
    v
}

#[test]
fn pages_agree_with_the_original_number_by_number() {
    let Some(cases) = common::oracle_cases("larwb oracle", &[LOW_ASPECT_RATIO]) else {
        return;
    };
    assert!(!cases.is_empty(), "the oracle has $LARWB pages (ex9)");
    for (name, deck, listing) in cases {
        let deck = datcom::read_deck(&deck, &name);
        let ours: Value =
            serde_json::from_str(&json::to_string(&datcom::run(&deck))).expect("run JSON");
        let reference: Value =
            serde_json::from_str(&json::listing_to_string(&listing, &name)).expect("listing");
        let rows = compare::compare(&only_larwb(ours), &only_larwb(reference));
        let mut total = 0;
        for r in &rows {
            if r.compared + r.missing == 0 {
                continue;
            }
            eprintln!(
                "{name} {}: {}/{}",
                r.coefficient,
                r.agreeing,
                r.compared + r.missing
            );
            total += r.agreeing;
            assert_eq!(
                r.missing, 0,
                "{name} {}: numbers not computed",
                r.coefficient
            );
            assert_eq!(
                r.agreeing, r.compared,
                "{name} {}: worst {:?}",
                r.coefficient, r.worst
            );
        }
        // 6 angles x 11 columns, less XCP at CN = 0 (printed ******).
        assert!(total >= 65, "{name}: {total} numbers agree");
    }
}

const EX9: &str = " $FLTCON NMACH=1.0, MACH(1)=0.26, NALPHA=6.0,
   ALSCHD(1)=-5.0,0.0,5.0,10.0,15.0,20.0, RNNUB(1)=1.868E6$
 $LARWB ZB=0.0, SREF=0.989, DELTEP=90.0, SFRONT=0.307, AR=1.076,
   L=1.915, SWET=2.28, PERBAS=2.38, SBASE=0.307, HB=0.595,
   BB=1.03, BLF=.FALSE., XCG=1.44, THETAD=15.0, ROUNDN=.FALSE.,
   SBS=0.57, SBSLB=0.0228, XCENSB=1.277, XCENW=1.277$
CASEID LIFTING BODY WITH SHARP LEADING EDGE, EXAMPLE PROBLEM 9
";

fn flight() -> LowAspectRatioFlight {
    LowAspectRatioFlight {
        mach: 0.26,
        reynolds_per_length: 1.868e6 / 0.3048,
        roughness: 0.16e-3 * 0.0254,
    }
}

/// The terms of ex9 by hand from DATCOM 4.8.1.2 and the figures at DELTEP = 90°: slope
/// (π·1.076/2 + 2·0.307/0.989)·4/5.076, factor 0.775 (midway 0.82 and 0.73); CN20 =
/// 2.195·1.686/5.076 times 0.955; z = 0.97; centre of pressure 0.6 + 0.102·0.307/0.989.
#[test]
fn ex9_terms_by_hand() {
    let deck = datcom::read_deck(EX9, "ex9");
    let lb = deck.cases[0].larwb.as_ref().expect("$LARWB");
    let alpha = [-5.0, 0.0, 5.0, 10.0, 15.0, 20.0];
    let p = low_aspect_ratio_wing_body(lb, flight(), &alpha).expect("page");
    // Only the rounding of the inputs' unit conversion separates these from the hand values.
    const ROUNDING: f64 = 1e-9;
    let close = |a: f64, b: f64| (a - b).abs() < ROUNDING * b.abs().max(1.0);
    let slope = (std::f64::consts::PI * 1.076 / 2.0 + 2.0 * 0.307 / 0.989) * 4.0 / 5.076;
    assert!(
        close(p.normal_force.slope, slope * 0.775),
        "{:?}",
        p.normal_force
    );
    assert!(close(p.normal_force.cn20, 2.195 * 1.686 / 5.076 * 0.955));
    assert!(close(p.normal_force.shape_z, 0.97));
    let xcp = 0.6 + 0.102 * 0.307 / 0.989;
    assert!(close(p.pitching_moment.arm, 1.44 / 1.915 - xcp));
    assert_eq!(p.alpha0_deg, 0.0);
    // CN(0) = 0: no centre of pressure there (the original prints ******).
    assert_eq!(p.cn[1], 0.0);
    assert_eq!(p.xcp[1], None);
    // XCP is the fixed arm wherever CN is not zero.
    for (k, x) in p.xcp.iter().enumerate() {
        if k != 1 {
            assert!(close(x.unwrap(), 1.44 / 1.915 - xcp));
        }
    }
    // Sharp leading edge (r_LE = 0): figure 4.8.2.2-10 on its first curve, between S_F/S = 0.3
    // (0.38) and 0.4 (0.43), times 0.349 (A + 2)/(A + 4).
    let factor = 0.38 + (0.307 / 0.989 - 0.3) / 0.1 * 0.05;
    assert!(close(p.axial_force.suction, factor * 0.349 * 3.076 / 5.076));
    assert!(p.sideslip.is_ok());
}

/// 4.8.1.2: the cubic passes through CN20 at 20° (0.349 rad) when z = 1, with the slope CNα
/// at zero.
#[test]
fn normal_force_cubic_passes_through_cn20() {
    let t = NormalForceTerms {
        slope_theory: 1.0,
        slope_factor: 1.0,
        cn20_theory: 0.5,
        cn20_factor: 1.0,
        shape_z: 1.0,
        slope: 1.0,
        cn20: 0.5,
    };
    // 8.21 is DATCOM's 1/0.349² to three figures.
    assert!((normal_force_coefficient(&t, 0.349) - 0.5).abs() < 1e-3);
    assert_eq!(normal_force_coefficient(&t, 0.0), 0.0);
    let h = 1e-6;
    assert!((normal_force_coefficient(&t, h) / h - 1.0).abs() < 1e-5);
}

/// Missing inputs are typed errors, never NaN; without SBS the longitudinal page stands and
/// the sideslip derivatives are refused.
#[test]
fn missing_inputs_are_typed_errors() {
    let deck = datcom::read_deck(EX9, "ex9");
    let mut lb = deck.cases[0].larwb.clone().expect("$LARWB");
    let alpha = [0.0, 5.0];
    let mut no_edge = lb.clone();
    no_edge.deltep_deg = None;
    assert_eq!(
        low_aspect_ratio_wing_body(&no_edge, flight(), &alpha).unwrap_err(),
        LowAspectRatioError::NoLeadingEdge
    );
    let mut no_ar = lb.clone();
    no_ar.aspect_ratio = None;
    assert_eq!(
        low_aspect_ratio_wing_body(&no_ar, flight(), &alpha).unwrap_err(),
        LowAspectRatioError::MissingInput { variable: "AR" }
    );
    lb.sbs = None;
    let p = low_aspect_ratio_wing_body(&lb, flight(), &alpha).expect("page");
    assert_eq!(
        p.sideslip,
        Err(LowAspectRatioError::MissingInput { variable: "SBS" })
    );
    assert!(p.cl.iter().chain(&p.cd).chain(&p.cm).all(|v| v.is_finite()));
}

/// Round leading edge (R3LEOB, DELTAL, no DELTEP) and a blunt nose take the round-edge and
/// blunting figures; the page is finite.
#[test]
fn round_leading_edge_and_blunt_nose() {
    let deck = datcom::read_deck(EX9, "ex9");
    let mut lb = deck.cases[0].larwb.clone().expect("$LARWB");
    lb.deltep_deg = None;
    lb.r3leob = Some(0.04);
    lb.deltal_deg = Some(70.0);
    lb.roundn = Some(true);
    let p = low_aspect_ratio_wing_body(&lb, flight(), &[0.0, 10.0, 20.0]).expect("page");
    // Figure 4.8.1.2-12b at 0.04: 0.89; -13b: 0.82; -14b: 0.83.
    assert_eq!(p.normal_force.slope_factor, 0.89);
    assert_eq!(p.normal_force.cn20_factor, 0.82);
    assert_eq!(p.normal_force.shape_z, 0.83);
    assert!(p.axial_force.suction > 0.0, "a round edge has suction");
    assert!(
        p.pitching_moment.xcp_blunting < 0.0,
        "blunting moves x_cp forward"
    );
    let s = p.sideslip.as_ref().expect("sideslip");
    assert!(s.terms.clb_per_cn0_blunt > 0.0);
    for v in
        p.cl.iter()
            .chain(&p.cd)
            .chain(&p.cm)
            .chain(&s.cyb)
            .chain(&s.clb)
    {
        assert!(v.is_finite());
    }
}

/// Spot values of every figure against the DATA statements of LOARWB.
#[test]
fn charts_match_their_data_statements() {
    const SPOTS: common::Spots = &[
        ("4.8.1.2-12a", &[0.0], 1.18),
        ("4.8.1.2-12a", &[80.0], 0.82),
        ("4.8.1.2-12b", &[0.02], 1.01),
        ("4.8.1.2-12b", &[0.12], 0.77),
        ("4.8.1.2-13a", &[40.0], 1.09),
        ("4.8.1.2-13a", &[120.0], 0.89),
        ("4.8.1.2-13b", &[0.04], 0.82),
        ("4.8.1.2-13b", &[0.1], 0.70),
        ("4.8.1.2-14a", &[80.0], 0.98),
        ("4.8.1.2-14a", &[120.0], 0.92),
        ("4.8.1.2-14b", &[0.06], 0.60),
        ("4.8.1.2-14b", &[0.12], 0.20),
        ("4.8.2.1-7", &[0.02], -0.08),
        ("4.8.2.1-7", &[0.12], -0.255),
        ("4.8.2.2-10", &[0.0, 0.5], 0.48),
        ("4.8.2.2-10", &[0.5, 0.3], 0.75),
        ("4.8.2.2-10", &[1.0, 0.5], 1.195),
        ("4.8.2.2-11a", &[2.0], 1.3),
        ("4.8.2.2-11a", &[24.0], 2.2),
        ("4.8.2.2-11b", &[4.0], 1.15),
        ("4.8.2.2-11b", &[16.0], 1.47),
        ("4.8.3.2-6b", &[0.0], 0.65),
        ("4.8.3.2-6b", &[40.0], 0.55),
        ("4.8.3.2-7a", &[0.0, 0.01], -0.056),
        ("4.8.3.2-7a", &[30.0, 0.21], -0.098),
        ("5.5.1.1-6", &[0.1], -0.009),
        ("5.5.1.1-6", &[0.6], -0.55),
        ("5.5.1.2-8", &[0.0, 0.5], -0.95),
        ("5.5.1.2-8", &[0.1, 0.5], 1.6),
        ("5.5.1.2-9", &[0.0, 0.5], -0.95),
        ("5.5.1.2-9", &[60.0, 0.5], 0.75),
        ("5.5.2.1-8a", &[3.5], -2.7),
        ("5.5.2.1-8a", &[45.0], -0.16),
        ("5.5.2.1-8b", &[5.0, 0.2], 0.77),
        ("5.5.2.1-8b", &[30.0, 0.01], 0.019),
        ("5.5.2.2-12a", &[0.0], 1.0),
        ("5.5.2.2-12a", &[0.145], 1.61),
        ("5.5.2.2-12b", &[10.0], 0.94),
        ("5.5.2.2-12b", &[70.0], 0.10),
        ("5.5.2.2-13", &[0.6], 0.26),
        ("5.5.2.2-13", &[1.0], 0.125),
        ("5.5.3.1-6", &[0.1], 1.04),
        ("5.5.3.1-6", &[0.17], 0.0),
    ];
    common::check_chart_spots(
        figures::ALL
            .iter()
            .copied()
            .filter(|id| *id != figures::CUTOFF_REYNOLDS),
        SPOTS,
    );
}
