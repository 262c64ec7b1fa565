//! Section maximum lift (DATCOM 4.1.1.4, `methods::section::section_max_lift`): the charts
//! against the DATA statements of the original's MAXCL, values worked by hand from the charts,
//! the original's own values, and the wing taking the computed value when the deck gives no
//! CLMAX.
//!
//! "Original" values come from the rebuilt original program (GNU Fortran 12.2, -O2
//! -fno-automatic, see /tmp/ref/maxcl/maxcl.md section 7) with one WRITE added after MAXCL's
//! sum, run on the oracle decks named; the printed WING ALONE values come from that binary run
//! on the deck text given here.

use datcom::charts;
use datcom::deck::cards::Surface;
use datcom::methods::section::{
    section_characteristics, section_max_lift, surface_section, MaxLiftGeometry, MaxLiftWarning,
    SectionCharacteristics, MAX_LIFT_BASE_CHART, MAX_LIFT_CAMBER_CHART,
    MAX_LIFT_REFERENCE_REYNOLDS_NUMBER, MAX_LIFT_REYNOLDS_CHART, MAX_LIFT_THICKNESS_POSITION_CHART,
};
use datcom::methods::wing::{wing_alone_with_section, wing_section};
use datcom::report::compare::agrees;

/// Chart values are copied exactly from the DATA statements.
const EXACT: f64 = 1e-12;
/// Hand-worked values are written to 7 significant digits.
const HAND: f64 = 1e-7;
/// The original computes in REAL*4 and its section geometry (Δy) differs from ours in the 6th
/// digit; its c_lmax is compared to this.
const ORIGINAL: f64 = 2e-5;

fn at(id: &str, args: &[f64]) -> f64 {
    let c = charts::get(id).unwrap_or_else(|| panic!("chart {id} is embedded"));
    let l = c.lookup(args);
    assert!(l.warnings.is_empty(), "{id} {args:?}: {:?}", l.warnings);
    l.value.unwrap_or_else(|| panic!("{id} {args:?}: no value"))
}

#[test]
fn charts_give_their_data_statement_values() {
    // datcom.f MAXCL: EVAL58 (22470-22473) at PARM58 delta-y 3.5 (10th) for XOVC .30 and .45;
    // delta-y 0 is 0.8 on every curve.
    for (args, want) in [
        (&[0.30, 3.5][..], 1.59),
        (&[0.45, 3.5], 1.35),
        (&[0.40, 4.0], 1.43),
        (&[0.35, 0.0], 0.8),
    ] {
        assert!((at(MAX_LIFT_BASE_CHART, args) - want).abs() <= EXACT);
    }
    // EVAL59 (22476-22491): position .30, camber .06: 0,.53,.64,.56,.38,.22,.10,.06,.06,0;
    // position .50, camber .04: 0,.10,.19,.27,.30,.22,.15,.13,.18,.12.
    for (args, want) in [
        (&[0.30, 0.06, 1.0][..], 0.53),
        (&[0.30, 0.06, 2.0], 0.56),
        (&[0.50, 0.04, 4.5], 0.18),
        (&[0.15, 0.02, 2.0], 0.32),
        (&[0.40, 0.0, 2.0], 0.0),
    ] {
        assert!((at(MAX_LIFT_CAMBER_CHART, args) - want).abs() <= EXACT);
    }
    // EVAL60 (22493-22495): x/c .35 ends -.04 at delta-y 4.5; .45 has .12 at 4.0.
    for (args, want) in [(&[0.35, 4.5][..], -0.04), (&[0.45, 4.0], 0.12)] {
        assert!((at(MAX_LIFT_THICKNESS_POSITION_CHART, args) - want).abs() <= EXACT);
    }
    // EVAL61 (22498-22500): Re 3E6 at delta-y 4: -.24; 2.5E7 at 1.5: .14; 9E6: 0.
    for (args, want) in [
        (&[3.0e6, 4.0][..], -0.24),
        (&[2.5e7, 1.5], 0.14),
        (&[9.0e6, 2.5], 0.0),
    ] {
        assert!((at(MAX_LIFT_REYNOLDS_CHART, args) - want).abs() <= EXACT);
    }
}

fn geometry(dy: f64, xt: f64, yc: f64, xc: f64) -> MaxLiftGeometry {
    MaxLiftGeometry {
        delta_y_percent: dy,
        max_thickness_x: xt,
        max_camber: yc,
        max_camber_x: xc,
    }
}

#[test]
fn uncambered_section_by_hand() {
    // Base chart, x/c 0.30: 1.58 at delta-y 3.0, 1.59 at 3.5; delta-y 3.16898 (the NACA 0012 of
    // uav_example's tails): 1.58 + 0.01·0.16898/0.5 = 1.5833796. No camber, no Reynolds
    // number: no increments. The original (uav_example, tails): 1.5833795.
    let r = section_max_lift(&geometry(3.16898, 0.30, 0.0, 0.0), &[None]).unwrap();
    assert!((r.base - 1.5833796).abs() <= HAND, "{}", r.base);
    assert_eq!(
        (r.camber_increment, r.thickness_position_increment),
        (0.0, 0.0)
    );
    let c = r.per_condition[0];
    assert_eq!(c.reynolds_number, MAX_LIFT_REFERENCE_REYNOLDS_NUMBER);
    assert_eq!(c.reynolds_increment, 0.0);
    assert!((c.max_cl - 1.5833796).abs() <= HAND);
    assert_eq!(
        r.warnings,
        vec![MaxLiftWarning::ReynoldsNumberMissing { condition: 0 }]
    );
}

#[test]
fn cambered_section_by_hand() {
    // NACA 4415 (datcom2modelica_shadow's wing): delta-y 3.96122, thickness at 0.30, camber 0.04
    // at 0.40. Base: 1.59 − 0.04·0.46122/0.5 = 1.5531024. Camber chart, position 0.40, camber
    // 0.04: 0.10 at delta-y 3.5, 0.07 at 4.0: 0.10 − 0.03·0.92244 = 0.0723268. Maximum
    // thickness at 0.30: no thickness-position increment. Sum 1.6254292; the original 1.6254292.
    let r = section_max_lift(&geometry(3.96122, 0.30, 0.04, 0.40), &[None]).unwrap();
    assert!((r.base - 1.5531024).abs() <= HAND);
    assert!((r.camber_increment - 0.0723268).abs() <= HAND);
    assert_eq!(r.thickness_position_increment, 0.0);
    assert!((r.per_condition[0].max_cl - 1.6254292).abs() <= HAND);
}

#[test]
fn thickness_position_increment_by_hand() {
    // for005's wing: delta-y 0.82454, thickness at 0.40, camber 0.01358 at 0.50. Base: 0.8
    // (delta-y below 1). Camber chart, position 0.50: the 0.02 curve is 0 at delta-y 0 and 1,
    // so 0 (the original: 0). Thickness position 0.40: 0.16 at delta-y 0.25, 0.19 at 1.0:
    // 0.16 + 0.03·0.57454/0.75 = 0.1829816 (the original: 0.18298163).
    let r = section_max_lift(&geometry(0.82454, 0.40, 0.01358, 0.50), &[None]).unwrap();
    assert!((r.base - 0.8).abs() <= HAND);
    assert!((r.thickness_position_increment - 0.1829816).abs() <= HAND);
    assert_eq!(r.camber_increment, 0.0);
}

#[test]
fn reynolds_increment_by_hand() {
    // sprob's vertical tail: delta-y 0.24375, Re 4.2968E6 on the chord. Reynolds chart at
    // delta-y 0.24375: Re 3E6 curve −0.09·0.24375 = −0.0219375, Re 6E6 curve 0; at 4.2968E6:
    // −0.0219375·(1 − 1.2968/3) = −0.0124547 (the original: −0.012454362).
    let r = section_max_lift(&geometry(0.24375, 0.35, 0.0, 0.0), &[Some(4.2968e6)]).unwrap();
    let c = r.per_condition[0];
    assert!((c.reynolds_increment - -0.0124547).abs() <= HAND);
    assert!((c.max_cl - (0.8 - 0.0124547)).abs() <= HAND);
    assert!(r.warnings.is_empty());
}

#[test]
fn outside_the_charts_the_end_values_are_held_with_a_warning() {
    // NACA 0022 (datcom2modelica_shadowmaster's wing): delta-y 5.81 beyond the base chart's
    // 5.0: 1.42, as the original (1.42000). Re 1E5: the 3E6 curve, with a warning.
    let r = section_max_lift(&geometry(5.80979, 0.30, 0.0, 0.0), &[Some(1e5)]).unwrap();
    assert!((r.base - 1.42).abs() <= EXACT);
    assert!((r.per_condition[0].reynolds_increment - -0.24).abs() <= EXACT);
    let charts: Vec<&str> = r
        .warnings
        .iter()
        .filter_map(|w| match w {
            MaxLiftWarning::Chart(c) => Some(c.chart.as_str()),
            _ => None,
        })
        .collect();
    assert!(charts.contains(&MAX_LIFT_BASE_CHART), "{:?}", r.warnings);
    assert!(
        charts.contains(&MAX_LIFT_REYNOLDS_CHART),
        "{:?}",
        r.warnings
    );
}

#[test]
fn nan_geometry_is_refused() {
    assert!(section_max_lift(&geometry(f64::NAN, 0.3, 0.0, 0.0), &[None]).is_err());
}

/// Wing-alone variant of the oracle deck datcom2modelica_shadow (its first case without body,
/// tails, flaps and DUMP cards): a NACA 4415 wing and no $WGSCHR.
const SHADOW_WING: &str = "DIM FT
DERIV DEG
 $FLTCON WT=467.0, LOOP=1.0,
         NMACH=1.0, MACH(1)=0.10582,
         NALT=1.0, ALT(1)=0.0,
         NALPHA=20.0,
         ALSCHD(1)= -16.0, -8.0, -6.0, -4.0, -2.0,
                     0.0, 2.0,  4.0,  8.0,  9.0,
                     10.0, 12.0, 14.0, 16.0, 18.0,
                     19.0, 20.0, 21.0, 22.0, 24.0,
         STMACH=0.6, TSMACH=1.4, TR=1.0$
 $OPTINS ROUGFC=0.40E-3$
 $SYNTHS XCG=3.7, ZCG=0.0, XW=3.2, ZW=0.5, ALIW=0.0,
         XH=10.62, ZH=2.12, ALIH=0.0,
         XV=10.62, ZV=-0.13, SCALE=1.0, VERTUP=.TRUE.$
 $WGPLNF CHRDTP=1.47,SSPNE=9.442,SSPN=9.9,
 CHRDR=2.1, SAVSI=0.0,TWISTA=0.0,
    CHSTAT=0.0, DHDADI=0.0,TYPE=1.0$
NACA W 4 4415
CASEID WING ALONE: shadow
";

/// The wing section of the first case, computed the original's way (no Reynolds number
/// reaches its section routine: slope at 1E6, c_lmax at 9E6) or at the flight Reynolds number.
fn shadow_section(original_reynolds: bool) -> (datcom::case::Case, SectionCharacteristics) {
    let deck = datcom::read_deck(SHADOW_WING, "shadow-wing.dcm");
    let case = deck.cases[0].clone();
    let mut s = surface_section(&case, Surface::Wing).unwrap().unwrap();
    if original_reynolds {
        for c in &mut s.conditions {
            c.reynolds_number = None;
        }
    }
    let r = section_characteristics(&s.shape, &s.conditions, &s.overrides).unwrap();
    (case, r)
}

#[test]
fn section_characteristics_carry_the_maximum_lift() {
    // The original's MAXCL for this wing: DELTAY 3.96122, XOVC 0.30, COVC 0.04 at 0.40,
    // CLMAX(1) = 1.6254292 (rebuilt original on datcom2modelica_shadow).
    let (_, r) = shadow_section(true);
    let m = r.max_lift.as_ref().expect("maximum lift computed");
    assert!((m.geometry.delta_y_percent - 3.96122).abs() <= 1e-5);
    // (the stations are the original's single-precision values: 0.40000001, 0.29999998)
    assert!((m.geometry.max_camber - 0.04).abs() <= 1e-7);
    assert!((m.geometry.max_camber_x - 0.40).abs() <= 1e-7);
    let clmax = r.per_mach[0].max_cl.expect("per condition");
    assert!((clmax - 1.6254292).abs() <= ORIGINAL, "{clmax}");
    // At the flight Reynolds number (sea level, Mach 0.10582, exposed mean chord about 1.8 ft:
    // Re about 2.3E6, below the chart's 3E6) the 3E6 curve is held: a lower value.
    let (_, flight) = shadow_section(false);
    let m = flight.max_lift.as_ref().unwrap();
    assert!(m.per_condition[0].reynolds_number < 3.0e6);
    assert!(flight.per_mach[0].max_cl.unwrap() < clmax);
}

#[test]
fn naca_wing_without_clmax_has_lift() {
    // Before the section c_lmax was computed, a high-aspect-ratio wing with a NACA card and no
    // CLMAX had no CL at all. The original's WING ALONE table of SHADOW_WING (rebuilt
    // original, listing lines 114-133), CL column:
    let alpha = [
        -16.0, -8.0, -6.0, -4.0, -2.0, 0.0, 2.0, 4.0, 8.0, 9.0, 10.0, 12.0, 14.0, 16.0, 18.0, 19.0,
        20.0, 21.0, 22.0, 24.0,
    ];
    let printed_cl = [
        -1.015, -0.344, -0.183, -0.026, 0.129, 0.291, 0.458, 0.631, 0.982, 1.069, 1.138, 1.258,
        1.349, 1.404, 1.339, 1.220, 0.845, 0.443, 0.126, -0.393,
    ];
    let (case, section) = shadow_section(true);
    let w = wing_alone_with_section(&case, 0, &alpha, Some(&section)).unwrap();
    for (i, want) in printed_cl.iter().enumerate() {
        let ours = w.cl[i].unwrap_or_else(|| panic!("CL at alpha {}", alpha[i]));
        assert!(
            agrees("CL", ours, *want),
            "alpha {}: ours {ours}, printed {want}",
            alpha[i]
        );
    }
}

#[test]
fn user_clmax_wins_over_the_computed_one() {
    let with_user = SHADOW_WING.replace("NACA W 4 4415", "NACA W 4 4415\n $WGSCHR CLMAX(1)=1.2$");
    let deck = datcom::read_deck(&with_user, "shadow-user.dcm");
    let case = &deck.cases[0];
    let s = surface_section(case, Surface::Wing).unwrap().unwrap();
    let r = section_characteristics(&s.shape, &s.conditions, &s.overrides).unwrap();
    let mut warnings = Vec::new();
    let w = wing_section(case, 0, Some(&r), &mut warnings).unwrap();
    assert_eq!(w.max_lift, Some(1.2));
    let (case, r) = shadow_section(false);
    let w = wing_section(&case, 0, Some(&r), &mut warnings).unwrap();
    assert_eq!(w.max_lift, r.per_mach[0].max_cl);
}
