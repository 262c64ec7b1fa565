//! Library use without a deck: a whole aircraft built in code (the bundled example UAV of
//! `namelists/example-uav.dcm`: body, wing, horizontal and vertical tail, NACA sections), run,
//! checked as its deck would be, and read: every coefficient of the configuration's pages, then
//! the terms behind them from the methods themselves (the wing's lift-curve slope, zero-lift
//! angle and maximum lift, and the downwash at the tail).
//!
//! `cargo run --example build_case` (`-- uav.dcm` also writes the case as a deck)
//!
//! Everything is SI inside the library (metres, newtons, pascals, kelvins); angles are in
//! degrees and derivatives per radian.

use datcom::case::{Body, Case, FlightInput, Loop, Planform, Reference, Synthesis};
use datcom::deck::cards::{AirfoilCard, DerivUnit, NacaSeries, Surface};

/// A straight-tapered planform: root and tip chords, semi-span and exposed semi-span (m),
/// sweep of the quarter-chord line (CHSTAT = 0.25) and dihedral (deg).
fn planform(
    root: f64,
    tip: f64,
    semispan: f64,
    exposed: f64,
    sweep: f64,
    dihedral: f64,
) -> Planform {
    Planform {
        chrdr: Some(root),
        chrdtp: Some(tip),
        sspn: Some(semispan),
        sspne: Some(exposed),
        savsi_deg: Some(sweep),
        chstat: Some(0.25),
        twista_deg: Some(0.0),
        dhdadi_deg: Some(dihedral),
        planform_type: Some(1.0),
        ..Planform::default()
    }
}

/// A NACA 4-digit section on `surface`.
fn naca4(surface: Surface, digits: &str) -> AirfoilCard {
    AirfoilCard::new(surface, NacaSeries::Four, digits)
}

/// The example UAV of `namelists/example-uav.dcm`, built in code.
pub fn example_uav() -> Case {
    let mut case = Case::new();
    case.caseid = Some("DATCOM-RS EXAMPLE UAV, WING-BODY-TAIL".into());
    case.deriv = DerivUnit::Rad;
    case.cards.damp = true;
    case.flight = Some(FlightInput {
        mach: vec![0.06, 0.09],
        altitude: vec![0.0, 500.0],
        loop_mode: Loop::AltitudeOuter,
        alpha_deg: vec![-4.0, -2.0, 0.0, 2.0, 4.0, 6.0, 8.0, 10.0, 12.0],
        weight: Some(98.1),
        nalt_given: true,
        ..FlightInput::default()
    });
    case.reference = Reference {
        area: Some(0.96),
        chord: Some(0.40),
        span: Some(2.40),
        roughness: None,
    };
    case.synthesis = Some(Synthesis {
        xcg: Some(0.62),
        zcg: Some(0.0),
        xw: Some(0.50),
        zw: Some(0.05),
        aliw_deg: Some(2.0),
        xh: Some(1.55),
        zh: Some(0.05),
        alih_deg: Some(-1.0),
        xv: Some(1.50),
        zv: Some(0.05),
        vertup: true,
        ..Synthesis::default()
    });
    case.body = Some(Body {
        x: vec![0.0, 0.10, 0.30, 0.60, 0.90, 1.20, 1.50, 1.80],
        r: vec![0.0, 0.05, 0.07, 0.07, 0.07, 0.05, 0.03, 0.01],
        ..Body::default()
    });
    case.wing = Some(planform(0.44, 0.32, 1.20, 1.13, 0.0, 2.0));
    case.horizontal_tail = Some(planform(0.22, 0.16, 0.40, 0.36, 5.0, 0.0));
    case.vertical_tail = Some(Planform {
        twista_deg: None,
        dhdadi_deg: None,
        ..planform(0.26, 0.14, 0.28, 0.24, 20.0, 0.0)
    });
    case.airfoils = vec![
        naca4(Surface::Wing, "2412"),
        naca4(Surface::HorizontalTail, "0012"),
        naca4(Surface::VerticalTail, "0012"),
    ];
    case
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let mut case = example_uav();
    case.prepare();
    // The checks of `datcom-rs check` on the case as its deck would give it.
    for d in case.diagnose() {
        if d.severity != datcom::Severity::Note {
            eprintln!("{d}");
        }
    }
    // And that deck, for the original program or for keeping.
    if let Some(path) = std::env::args().nth(1) {
        std::fs::write(&path, datcom::deck::writer::write_case(&case.to_raw()))?;
        eprintln!("wrote {path}");
    }

    // Every coefficient: one page per flight condition (with BUILD, one per component too).
    let results = datcom::results::run_case(&case);
    for page in &results.conditions {
        let c = &page.condition;
        println!(
            "{} at Mach {:.3}, {:.0} m ({:.1} m/s):",
            page.configuration,
            c.mach,
            c.altitude.unwrap_or(0.0),
            c.velocity.unwrap_or(0.0)
        );
        println!("  alpha      CL      CD      CM    CLA/rad  CMA/rad");
        let s = &page.static_coefficients;
        let cell = |v: Option<f64>| v.map_or("      NA".to_string(), |x| format!("{x:8.4}"));
        for (k, alpha) in page.alpha_deg.iter().enumerate() {
            println!(
                "  {alpha:5.1} {} {} {} {} {}",
                cell(s.cl[k]),
                cell(s.cd[k]),
                cell(s.cm[k]),
                cell(s.cla[k]),
                cell(s.cma[k])
            );
        }
        if let Some(d) = &page.dynamic {
            println!(
                "  CMQ {} per rad, CLP {} per rad (first angle)",
                cell(d.cmq[0]),
                cell(d.clp[0])
            );
        }
        if let Some(t) = &page.downwash {
            let eps: Vec<String> = t.epsilon_deg.iter().map(|&e| cell(e)).collect();
            println!("  downwash at the tail, deg: {}", eps.join(""));
        }
    }
    for w in datcom::warning::texts(&results.warnings) {
        eprintln!("warning: {w}");
    }
    // The warnings are typed: what a method found, matched on without reading text.
    let charts_left = results
        .warnings
        .iter()
        .filter(|w| w.chart().is_some())
        .count();
    println!("{charts_left} chart readings outside the charts' data");

    // The terms: any method runs on the case directly and returns its named terms.
    let alpha = &case
        .flight
        .as_ref()
        .map(|f| f.alpha_deg.clone())
        .unwrap_or_default();
    let wing = datcom::methods::wing::wing_alone(&case, 0, alpha)?;
    let t = &wing.terms;
    let shown = |v: Option<f64>| v.map_or("not computed".to_string(), |x| format!("{x:.3}"));
    println!(
        "wing alone at Mach {:.3}: CLalpha {:.4} per rad, zero-lift angle {:.3} deg, CLmax {} at {} deg",
        case.conditions[0].mach,
        t.lift_curve_slope.per_rad,
        t.zero_lift_angle.wing_deg,
        shown(t.max_lift.clmax),
        shown(t.max_lift.alpha_deg)
    );
    Ok(())
}
