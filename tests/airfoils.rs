//! Airfoil coordinate files from ../shared/data/airfoils: read, resampled to a deck's section
//! input, and read back by the deck reader.

use datcom::geometry::airfoil_file;

/// The shared README computes E423: t/c 12.5 % at 24 % chord, camber 10.0 % at 45 % chord.
/// Resampled to 50 stations (linear interpolation between the file's points) these hold to
/// within half a percent of chord thickness and five percent of chord in position.
const THICKNESS_TOL: f64 = 0.005;
const POSITION_TOL: f64 = 0.05;

#[test]
fn e423_becomes_a_section_input() {
    let path = std::path::PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("../shared/data/airfoils/e423.dat");
    let Ok(text) = std::fs::read_to_string(&path) else {
        eprintln!(
            "SKIPPED e423_becomes_a_section_input: ../shared/data/airfoils/e423.dat is absent"
        );
        return;
    };
    let a = airfoil_file::read(&text).unwrap();
    assert_eq!(a.name, "E423");
    let s = a.to_section_input(airfoil_file::MAX_STATIONS).unwrap();
    let thickness: Vec<f64> = s.yupper.iter().zip(&s.ylower).map(|(u, l)| u - l).collect();
    let camber: Vec<f64> = s
        .yupper
        .iter()
        .zip(&s.ylower)
        .map(|(u, l)| (u + l) / 2.0)
        .collect();
    let argmax = |v: &[f64]| {
        v.iter()
            .enumerate()
            .max_by(|a, b| a.1.total_cmp(b.1))
            .map(|(i, m)| (s.xcord[i], *m))
            .unwrap()
    };
    let (xt, t) = argmax(&thickness);
    let (xc, c) = argmax(&camber);
    assert!(
        (t - 0.125).abs() < THICKNESS_TOL && (xt - 0.24).abs() < POSITION_TOL,
        "t/c {t} at {xt}"
    );
    assert!(
        (c - 0.100).abs() < THICKNESS_TOL && (xc - 0.45).abs() < POSITION_TOL,
        "camber {c} at {xc}"
    );
    let deck_text = format!(
        " $FLTCON NMACH=1.0, MACH(1)=0.06, NALT=1.0, ALT(1)=100.0, NALPHA=1.0, ALSCHD(1)=0.0$\n $SYNTHS XCG=0.1$\n $WGPLNF CHRDR=0.28, CHRDTP=0.28, SSPN=0.9, SSPNE=0.85$\n{}",
        airfoil_file::namelist_text("WGSCHR", &s)
    );
    let deck = datcom::read_deck(&deck_text, "e423.dcm");
    assert!(
        deck.diagnostics.iter().all(|d| !d.is_error()),
        "{:?}",
        deck.diagnostics
    );
    assert_eq!(deck.cases[0].sections["WING"].xcord.len(), 50);
}

/// The E423 from its coordinate file through the section method. Published data for the E423
/// (Selig et al., Summary of Low-Speed Airfoil Data vol. 1, 1995: zero-lift angle about -11
/// to -13 degrees, c_m,c/4 about -0.23 to -0.25 at Re 2E5-5E5) bound the plausible values;
/// the bands are wide because those are measurements and ours is potential-flow theory with
/// DATCOM's empirical viscous correction.
#[test]
fn e423_section_characteristics_are_plausible() {
    use datcom::geometry::section::user_defined;
    use datcom::methods::section::{
        section_characteristics, SectionCondition, SectionOverrides, SectionShape,
    };
    let path = std::path::PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("../shared/data/airfoils/e423.dat");
    let Ok(text) = std::fs::read_to_string(&path) else {
        eprintln!("SKIPPED e423_section_characteristics_are_plausible: ../shared/data/airfoils/e423.dat is absent");
        return;
    };
    let input = airfoil_file::read(&text)
        .unwrap()
        .to_section_input(airfoil_file::MAX_STATIONS)
        .unwrap();
    let coords = user_defined(&input).unwrap();
    assert!(
        (coords.max_thickness - 0.125).abs() < THICKNESS_TOL,
        "{}",
        coords.max_thickness
    );
    let shape = SectionShape::from_coordinates(&coords).unwrap();
    let conditions = [SectionCondition {
        mach: 0.06,
        reynolds_number: Some(3.0e5),
    }];
    let c = section_characteristics(&shape, &conditions, &SectionOverrides::default()).unwrap();
    eprintln!(
        "E423: zero-lift {:.2} deg (thin airfoil {:.2}), cm0 {:.3}, cla(M=0) {:.4}/deg, cla(M=0.06, Re 3E5) {:?}/deg",
        c.zero_lift_alpha_deg,
        c.thin_airfoil_zero_lift_alpha_deg,
        c.cm0,
        c.cla_mach0_per_rad.to_radians(),
        c.per_mach[0].cla_per_rad.map(f64::to_radians)
    );
    assert!(
        (-14.0..-9.0).contains(&c.zero_lift_alpha_deg),
        "{}",
        c.zero_lift_alpha_deg
    );
    assert!((-0.32..-0.18).contains(&c.cm0), "{}", c.cm0);
    let cla_deg = c.cla_mach0_per_rad.to_radians();
    assert!((0.08..0.125).contains(&cla_deg), "{cla_deg}");
}
