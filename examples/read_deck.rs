//! Library use from a design tool: read a deck, report its problems, sweep the flight
//! conditions, and build a case in code by editing a deck's namelist values.
//!
//! `cargo run --example read_deck -- namelists/example-uav.dcm`

use datcom::deck::{self, writer, Value};
use datcom::Diagnosed;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let path = std::env::args()
        .nth(1)
        .unwrap_or_else(|| "namelists/example-uav.dcm".into());
    let deck = datcom::read_deck_file(std::path::Path::new(&path))?;
    for d in &deck.diagnostics {
        if d.severity != datcom::Severity::Note {
            eprintln!("{d}");
        }
    }
    if deck.has_errors() {
        return Err(format!("{path}: {} error(s)", deck.error_count()).into());
    }
    let results = datcom::run(&deck);
    for case in &results.cases {
        println!(
            "case {}: {}",
            case.number,
            case.caseid.as_deref().unwrap_or("")
        );
        for c in &case.conditions {
            let f = &c.condition;
            println!(
                "  Mach {:.3}  altitude {:>8.1} m  V {:>7.2} m/s  Re/m {:.4e}",
                f.mach,
                f.altitude.unwrap_or(f64::NAN),
                f.velocity.unwrap_or(f64::NAN),
                f.reynolds_per_length
            );
        }
    }

    // A design sweep: the same aircraft at a higher altitude, written back as a deck.
    let text = std::fs::read_to_string(&path)?;
    let mut raw = deck::read(&text, &path);
    if let Some(case) = raw.cases.first_mut() {
        let fltcon = case.namelists.entry("FLTCON".into()).or_default();
        fltcon.insert(
            "ALT".into(),
            Value::Numbers(vec![Some(1500.0), Some(3000.0)]),
        );
        let variant = writer::write_case(case);
        let results = datcom::run(&datcom::read_deck(&variant, "variant"));
        let first = &results.cases[0].conditions[0].condition;
        println!(
            "variant at {:.0} m: temperature {:.2} K",
            first.altitude.unwrap_or(0.0),
            first.temperature.unwrap_or(0.0)
        );
    }
    Ok(())
}
