//! # datcom
//!
//! USAF Digital DATCOM stability and control derivatives, in Rust.
//!
//! Data flows one way: deck text → [`deck`] (namelists and control cards, every problem a
//! [`Diagnostic`]) → [`case`] (typed cases, SI units inside) → [`conditions`] (flight conditions
//! from the 1962 US Standard Atmosphere) → [`results`] → [`report`] (text, JSON, CSV).
//!
//! ```
//! let text = " $FLTCON NMACH=1.0, MACH(1)=0.4, NALT=1.0, ALT(1)=0.0,
//!    NALPHA=2.0, ALSCHD(1)=0.0,4.0$
//!  $SYNTHS XCG=1.0$
//! ";
//! use datcom::Diagnosed;
//! let deck = datcom::read_deck(text, "x.dcm");
//! assert!(!deck.has_errors(), "{:?}", deck.diagnostics);
//! let results = datcom::run(&deck);
//! let sea_level = &results.cases[0].conditions[0].condition;
//! assert!((sea_level.temperature.unwrap() - 288.15).abs() < 1e-9);
//! ```

pub mod atmosphere;
pub mod auxiliary;
pub mod case;
pub mod charts;
pub mod conditions;
pub mod deck;
pub mod discrepancy;
pub mod error;
pub mod geometry;
pub mod methods;
pub mod numeric;
pub mod report;
pub mod results;
pub mod warning;

pub use case::{Case, Deck};
pub use error::{DeckProblem, Diagnosed, Diagnostic, Error, Severity};
pub use results::{CaseResults, ConditionResults, Results};
pub use warning::Warning;

/// Reads a deck from text; `file` names it in diagnostics. Never fails: every problem is a
/// diagnostic in the returned deck.
pub fn read_deck(text: &str, file: &str) -> Deck {
    Deck::from_raw(deck::read(text, file))
}

/// Reads a deck from a file.
pub fn read_deck_file(path: &std::path::Path) -> Result<Deck, Error> {
    let bytes = std::fs::read(path).map_err(|source| Error::Io {
        path: path.to_path_buf(),
        source,
    })?;
    let text = String::from_utf8_lossy(&bytes);
    Ok(read_deck(&text, &path.display().to_string()))
}

/// Computes every case of a deck.
pub fn run(deck: &Deck) -> Results {
    results::run(deck)
}
