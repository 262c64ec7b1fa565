//! Typed errors and diagnostics.
//!
//! A deck problem is a [`Diagnostic`]: where it is (file, line, column), in which card and
//! variable, what is wrong ([`DeckProblem`], which carries what was expected and what was found),
//! how serious it is and, where we can tell, how to fix it. The reader reports every problem of a
//! deck in one pass; it never stops at the first.
//!
//! Failures that are not about a deck's content (a file that cannot be read, a case that cannot
//! be computed) are [`Error`].

use serde::Serialize;
use std::fmt;
use std::path::PathBuf;

/// How serious a diagnostic is.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Severity {
    /// Accepted as written; the original program differs here (it may reject it).
    Note,
    /// Read, but probably not what the author meant, or read differently from the original.
    Warning,
    /// The deck is wrong: the original program would fail or compute nonsense.
    Error,
}

impl fmt::Display for Severity {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Severity::Note => "note",
            Severity::Warning => "warning",
            Severity::Error => "error",
        })
    }
}

/// What is wrong with a deck. Each variant carries what was expected and what was found.
#[derive(Debug, Clone, PartialEq, thiserror::Error, Serialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
#[non_exhaustive]
pub enum DeckProblem {
    #[error("this is a Missile DATCOM deck (namelist ${namelist}); datcom-rs reads USAF Digital DATCOM decks only")]
    MissileDatcom { namelist: String },
    #[error("unknown namelist ${found}")]
    UnknownNamelist { found: String },
    #[error("unknown variable {found} in ${namelist}")]
    UnknownVariable { namelist: String, found: String },
    #[error("unrecognised card `{found}`")]
    UnknownCard { found: String },
    #[error("namelist ${namelist} opened on line {opened_line} is not closed by `$`; the original program would read on and swallow {}", swallowed.join(", "))]
    UnterminatedNamelist {
        namelist: String,
        opened_line: usize,
        swallowed: Vec<String>,
    },
    #[error("assignment `{found}` outside any namelist")]
    AssignmentOutsideNamelist { found: String },
    #[error("missing comma between assignments: expected `,` before {found}")]
    MissingComma { found: String },
    #[error("expected {expected}, found {found}")]
    Syntax { expected: String, found: String },
    #[error("{variable} holds at most {capacity} values; {given} given (last index {last_index})")]
    TooManyValues {
        variable: String,
        capacity: usize,
        given: usize,
        last_index: usize,
    },
    #[error("{variable} expects {expected}, found {found}")]
    WrongKind {
        variable: String,
        expected: String,
        found: String,
    },
    #[error("{count_variable}={count} but {variable} has {given} values")]
    CountMismatch {
        count_variable: String,
        count: f64,
        variable: String,
        given: usize,
    },
    #[error("{variable} is assigned more than once in this case; the last value wins")]
    Reassigned { variable: String },
    #[error("${namelist} appears more than once in this case; the later values are merged over the earlier")]
    NamelistRepeated { namelist: String },
    #[error(
        "text after column 80 (`{found}`) is ignored by the original program; it is read here"
    )]
    PastColumn80 { found: String },
    #[error(
        "the number `{found}` has {length} characters; the original program reads at most 11 (with 12 to 15 it does not run the case, with more it reads another value); it is read here in full"
    )]
    LongNumber { found: String, length: usize },
    #[error("{what} is accepted here; the original program rejects it")]
    Dialect { what: String },
    #[error("text ignored: `{found}`")]
    TrailingText { found: String },
    #[error("assignments after the closing `$` are outside any namelist and are lost: `{found}`")]
    AfterClose { found: String },
    #[error("{card} {found}: expected {expected}")]
    BadCard {
        card: String,
        expected: String,
        found: String,
    },
    #[error("{variable}{} must {}; found {found}", index.map(|i| format!("({i})")).unwrap_or_default(), if *allow_zero { "not be negative" } else { "be positive" })]
    NotPositive {
        variable: String,
        index: Option<usize>,
        found: f64,
        allow_zero: bool,
    },
    #[error(
        "{variable} = {found}{} is outside {min} to {max}{}",
        spaced(unit),
        spaced(unit)
    )]
    OutOfRange {
        variable: String,
        found: f64,
        min: f64,
        max: f64,
        unit: String,
    },
    #[error("{message}")]
    Physical { message: String },
    #[error("{message}")]
    Case { message: String },
}

/// One problem found in a deck, with its place and a hint.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Diagnostic {
    pub severity: Severity,
    /// File name as given to the reader (may be empty for text read from memory).
    pub file: String,
    /// 1-based line; 0 when the problem concerns the whole case or deck.
    pub line: usize,
    /// 1-based column in characters; 0 when not applicable.
    pub column: usize,
    /// Card or namelist the problem is in (`FLTCON`, `NACA`, `DIM`, ...).
    pub card: Option<String>,
    /// Variable the problem is about.
    pub variable: Option<String>,
    pub problem: DeckProblem,
    /// How to fix it, where we can tell.
    pub hint: Option<String>,
}

impl Diagnostic {
    pub fn is_error(&self) -> bool {
        self.severity == Severity::Error
    }
}

impl fmt::Display for Diagnostic {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if !self.file.is_empty() {
            write!(f, "{}:", self.file)?;
        }
        if self.line > 0 {
            write!(f, "{}:", self.line)?;
            if self.column > 0 {
                write!(f, "{}:", self.column)?;
            }
        }
        write!(f, " {}", self.severity)?;
        match (&self.card, &self.variable) {
            (Some(c), Some(v)) => write!(f, " [{c} {v}]")?,
            (Some(c), None) => write!(f, " [{c}]")?,
            (None, Some(v)) => write!(f, " [{v}]")?,
            (None, None) => {}
        }
        write!(f, ": {}", self.problem)?;
        if let Some(h) = &self.hint {
            write!(f, " (hint: {h})")?;
        }
        Ok(())
    }
}

/// Anything that carries diagnostics: counts by severity.
pub trait Diagnosed {
    fn diagnostics(&self) -> &[Diagnostic];

    fn error_count(&self) -> usize {
        self.count(Severity::Error)
    }

    fn warning_count(&self) -> usize {
        self.count(Severity::Warning)
    }

    fn count(&self, severity: Severity) -> usize {
        self.diagnostics()
            .iter()
            .filter(|d| d.severity == severity)
            .count()
    }

    fn has_errors(&self) -> bool {
        self.error_count() > 0
    }
}

/// Failures of the library outside deck content.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum Error {
    #[error("cannot read {path}: {source}")]
    Io {
        path: PathBuf,
        #[source]
        source: std::io::Error,
    },
    #[error("{path}: {count} error(s) in the deck; first: {first}")]
    Deck {
        path: String,
        count: usize,
        first: Box<Diagnostic>,
    },
    #[error("case {case}: {message}")]
    Compute { case: String, message: String },
}

/// A unit after a number: a space and the unit, or nothing for a pure number.
fn spaced(unit: &str) -> String {
    if unit.is_empty() {
        String::new()
    } else {
        format!(" {unit}")
    }
}
