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
