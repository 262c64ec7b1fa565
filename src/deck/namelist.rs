//! Assignments inside one namelist body: `VAR = v, v, n*v, ...` and `VAR(i) = ...`.
//!
//! The grammar is Fortran NAMELIST as Digital DATCOM's namelist emulator reads it: assignments
//! separated by commas, a value list that runs until the next `NAME =` or `NAME(`, repeat counts
//! `n*value`, logicals `.TRUE.`/`.FALSE.` (also `T`/`F`). The parser never gives up: after a
//! problem it skips to the next assignment and goes on, so every problem is reported.

use std::borrow::Cow;

use super::lexer::{Tok, Token};
use crate::error::DeckProblem;

/// A constant in a value list.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Lit {
    Number { value: f64, integer: bool },
    Logical(bool),
}

/// One `NAME(index) = values` assignment, repeat counts expanded.
#[derive(Debug, Clone, PartialEq)]
pub struct Assignment<'t> {
    /// The variable as written (upper case).
    pub name: Cow<'t, str>,
    /// 1-based starting index when written `NAME(i)`.
    pub index: Option<usize>,
    pub values: Vec<Lit>,
    pub line: usize,
    pub column: usize,
}

/// A problem found while parsing a body, with its place and an optional hint.
#[derive(Debug, Clone, PartialEq)]
pub struct BodyProblem {
    pub line: usize,
    pub column: usize,
    pub variable: Option<String>,
    pub problem: DeckProblem,
    pub hint: Option<String>,
}

/// Largest repeat count accepted in `n*value`; more than any DATCOM array holds.
const MAX_REPEAT: usize = 1000;
/// Largest array index accepted in `NAME(i)`; more than any DATCOM array holds.
const MAX_INDEX: f64 = 1000.0;

struct Parser<'s, 't> {
    toks: &'s [Token<'t>],
    pos: usize,
    problems: Vec<BodyProblem>,
}

fn is_logical_name(n: &str) -> Option<bool> {
    match n {
        "T" | "TRUE" => Some(true),
        "F" | "FALSE" => Some(false),
        _ => None,
    }
}

impl<'s, 't> Parser<'s, 't> {
    fn peek(&self, k: usize) -> Option<&'s Token<'t>> {
        self.toks.get(self.pos + k)
    }

    fn problem(
        &mut self,
        at: &Token,
        variable: Option<&str>,
        problem: DeckProblem,
        hint: Option<String>,
    ) {
        self.problems.push(BodyProblem {
            line: at.line,
            column: at.column,
            variable: variable.map(str::to_string),
            problem,
            hint,
        });
    }

    /// Reports that `expected` was wanted where the cursor's token (or the end) stands.
    fn expected_here(&mut self, fallback: &'s Token<'t>, variable: Option<&str>, expected: String) {
        let at = self.peek(0).unwrap_or(fallback);
        let found = self
            .peek(0)
            .map_or_else(|| "end of namelist".to_string(), |t| t.tok.describe());
        self.problem(at, variable, DeckProblem::Syntax { expected, found }, None);
    }

    /// True when the tokens at `k` start an assignment: `NAME =` or `NAME (`.
    fn starts_assignment(&self, k: usize) -> bool {
        matches!(
            (
                self.peek(k).map(|t| &t.tok),
                self.peek(k + 1).map(|t| &t.tok)
            ),
            (Some(Tok::Name(_)), Some(Tok::Equals | Tok::LParen))
        )
    }

    /// Skips to the start of the next assignment (after a comma) or the end.
    fn recover(&mut self) {
        while let Some(t) = self.peek(0) {
            if matches!(t.tok, Tok::Comma) && self.starts_assignment(1) {
                self.pos += 1;
                return;
            }
            if self.starts_assignment(0) && self.pos > 0 {
                return;
            }
            self.pos += 1;
        }
    }

    /// Reads every assignment, handing each to `each`; the vector of values (empty) is reused
    /// from one assignment to the next, and left empty.
    fn parse(&mut self, values: &mut Vec<Lit>, each: &mut dyn FnMut(&Assignment<'t>)) {
        while let Some(t) = self.peek(0) {
            match &t.tok {
                Tok::Comma => {
                    self.pos += 1;
                }
                Tok::Name(_) if self.starts_assignment(0) => {
                    if let Some(a) = self.assignment(values) {
                        each(&a);
                        *values = a.values;
                        values.clear();
                    }
                }
                other => {
                    let found = other.describe();
                    self.problem(
                        t,
                        None,
                        DeckProblem::Syntax {
                            expected: "a variable name followed by `=`".into(),
                            found,
                        },
                        None,
                    );
                    self.pos += 1;
                    self.recover();
                }
            }
        }
    }

    /// One assignment; its values are read into `values` (empty), which it takes.
    fn assignment(&mut self, values: &mut Vec<Lit>) -> Option<Assignment<'t>> {
        let head = self.peek(0)?;
        let Tok::Name(name) = &head.tok else {
            return None;
        };
        self.pos += 1;
        let mut index = None;
        if matches!(self.peek(0).map(|t| &t.tok), Some(Tok::LParen)) {
            self.pos += 1;
            match (self.peek(0).map(|t| &t.tok), self.peek(1).map(|t| &t.tok)) {
                (
                    Some(Tok::Number {
                        value,
                        integer: true,
                        ..
                    }),
                    Some(Tok::RParen),
                ) if (1.0..=MAX_INDEX).contains(value) => {
                    index = Some(*value as usize);
                    self.pos += 2;
                }
                _ => {
                    let at = self.peek(0).unwrap_or(head);
                    let found = self
                        .peek(0)
                        .map_or("end of namelist".into(), |t| t.tok.describe());
                    self.problem(
                        at,
                        Some(name),
                        DeckProblem::Syntax {
                            expected: format!(
                                "a whole-number index from 1 to {MAX_INDEX} in {name}(...)"
                            ),
                            found,
                        },
                        Some(format!("write {name}(1)=... to start at the first element")),
                    );
                    self.recover();
                    return None;
                }
            }
        }
        match self.peek(0) {
            Some(t) if matches!(t.tok, Tok::Equals) => self.pos += 1,
            other => {
                let at = other.unwrap_or(head);
                self.expected_here(at, Some(name), format!("`=` after {name}"));
                self.recover();
                return None;
            }
        }
        self.values(name, head, values);
        Some(Assignment {
            name: name.clone(),
            index,
            values: std::mem::take(values),
            line: head.line,
            column: head.column,
        })
    }

    fn constant(&mut self) -> Option<Lit> {
        let t = self.peek(0)?;
        let lit = match &t.tok {
            Tok::Number { value, text, .. } if !value.is_finite() => {
                let found = format!("`{text}`");
                self.problem(
                    t,
                    None,
                    DeckProblem::Syntax {
                        expected: "a number within the range of double precision (about ±1.8E308)"
                            .into(),
                        found,
                    },
                    None,
                );
                // Kept in its place, and not assigned (the reader skips values that are not
                // numbers): no later check reads a value the deck does not give.
                Lit::Number {
                    value: f64::NAN,
                    integer: false,
                }
            }
            Tok::Number { value, integer, .. } => Lit::Number {
                value: *value,
                integer: *integer,
            },
            Tok::Logical(b) => Lit::Logical(*b),
            Tok::Name(n) if !self.starts_assignment(0) => Lit::Logical(is_logical_name(n)?),
            _ => return None,
        };
        self.pos += 1;
        Some(lit)
    }

    /// One list item: `c` or `n*c`.
    fn item(&mut self, name: &str, out: &mut Vec<Lit>) -> bool {
        let Some(t) = self.peek(0) else {
            return false;
        };
        if let (
            Tok::Number {
                value,
                integer: true,
                ..
            },
            Some(Tok::Star),
        ) = (&t.tok, self.peek(1).map(|t| &t.tok))
        {
            let count = *value;
            self.pos += 2;
            let Some(lit) = self.constant() else {
                self.expected_here(
                    t,
                    Some(name),
                    "a constant after the repeat count `n*`".to_string(),
                );
                return false;
            };
            if !(1.0..=MAX_REPEAT as f64).contains(&count) {
                self.problem(
                    t,
                    Some(name),
                    DeckProblem::Syntax {
                        expected: format!("a repeat count from 1 to {MAX_REPEAT}"),
                        found: format!("{count}"),
                    },
                    None,
                );
                return true;
            }
            out.extend(std::iter::repeat_n(lit, count as usize));
            return true;
        }
        match self.constant() {
            Some(lit) => {
                out.push(lit);
                true
            }
            None => false,
        }
    }

    /// Reads the value list of `name` into `out`.
    fn values(&mut self, name: &str, head: &'s Token<'t>, out: &mut Vec<Lit>) {
        if !self.item(name, out) {
            let at = self.peek(0).unwrap_or(head);
            self.expected_here(at, Some(name), format!("a value for {name}"));
            self.recover();
            return;
        }
        loop {
            let Some(t) = self.peek(0) else {
                return;
            };
            match &t.tok {
                Tok::Comma => {
                    if self.starts_assignment(1) || self.peek(1).is_none() {
                        return;
                    }
                    if matches!(self.peek(1).map(|t| &t.tok), Some(Tok::Comma)) {
                        // `a,,b` is a null value in Fortran namelist; DATCOM decks do not use it.
                        self.problem(
                            t,
                            Some(name),
                            DeckProblem::Syntax {
                                expected: "a value between the commas".into(),
                                found: "`,,`".into(),
                            },
                            None,
                        );
                        self.pos += 1;
                        continue;
                    }
                    self.pos += 1;
                    if !self.item(name, out) {
                        self.expected_here(t, Some(name), format!("a value for {name}"));
                        self.recover();
                        return;
                    }
                }
                // The end of a card separates items as a comma does (the original's reader).
                _ if self.pos > 0 && self.toks[self.pos - 1].line != t.line => {
                    if self.starts_assignment(0) {
                        return;
                    }
                    if !self.item(name, out) {
                        self.expected_here(t, Some(name), "`,` or the next assignment".to_string());
                        self.recover();
                        return;
                    }
                }
                Tok::Name(next) if self.starts_assignment(0) => {
                    self.problem(
                        t,
                        Some(name),
                        DeckProblem::MissingComma {
                            found: next.to_string(),
                        },
                        Some(format!("write `,` after the value of {name}")),
                    );
                    return;
                }
                Tok::Number { .. } | Tok::Logical(_) => {
                    // Blank-separated values: Fortran list input allows them.
                    self.problem(
                        t,
                        Some(name),
                        DeckProblem::MissingComma {
                            found: t.tok.describe(),
                        },
                        Some("separate the values with commas".into()),
                    );
                    if !self.item(name, out) {
                        self.pos += 1;
                    }
                }
                _ => {
                    self.expected_here(t, Some(name), "`,` or the next assignment".to_string());
                    self.recover();
                    return;
                }
            }
        }
    }
}

/// Parses the tokens of one namelist body (without its `$NAME` and closing `$`), handing each
/// assignment to `each` in order as it is read; returns the problems found. `values` is room
/// for the values of an assignment, reused by the caller from one body to the next; it is left
/// empty.
pub fn parse_body<'t>(
    toks: &[Token<'t>],
    values: &mut Vec<Lit>,
    mut each: impl FnMut(&Assignment<'t>),
) -> Vec<BodyProblem> {
    let mut p = Parser {
        toks,
        pos: 0,
        problems: Vec::new(),
    };
    values.clear();
    p.parse(values, &mut each);
    p.problems
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::deck::lexer::lex_line;

    fn parse(s: &str) -> (Vec<Assignment<'_>>, Vec<BodyProblem>) {
        let mut toks = Vec::new();
        for (i, l) in s.lines().enumerate() {
            lex_line(l, i + 1, 1, &mut toks);
        }
        let mut out = Vec::new();
        let problems = parse_body(&toks, &mut Vec::new(), |a| out.push(a.clone()));
        (out, problems)
    }

    fn nums(a: &Assignment) -> Vec<f64> {
        a.values
            .iter()
            .map(|l| match l {
                Lit::Number { value, .. } => *value,
                Lit::Logical(_) => f64::NAN,
            })
            .collect()
    }

    #[test]
    fn continuation_lines_and_trailing_comma() {
        let (a, p) = parse("ALSCHD(1)=-2.0,0.0,\n  1.0, 2.0, NALPHA=4.0,");
        assert!(p.is_empty(), "{p:?}");
        assert_eq!(a.len(), 2);
        assert_eq!(a[0].index, Some(1));
        assert_eq!(nums(&a[0]), vec![-2.0, 0.0, 1.0, 2.0]);
        assert_eq!(nums(&a[1]), vec![4.0]);
    }

    #[test]
    fn repeat_counts_expand() {
        let (a, p) = parse("CLALPA(1)=2*0.141,LERI=.0075");
        assert!(p.is_empty());
        assert_eq!(nums(&a[0]), vec![0.141, 0.141]);
    }

    #[test]
    fn logical_spellings() {
        let (a, p) = parse("VERTUP=T, A=.FALSE.");
        assert!(p.is_empty());
        assert_eq!(a[0].values, vec![Lit::Logical(true)]);
        assert_eq!(a[1].values, vec![Lit::Logical(false)]);
    }

    #[test]
    fn missing_comma_is_reported_and_both_read() {
        let (a, p) = parse("XW=1.0 ZW=2.0");
        assert_eq!(a.len(), 2);
        assert_eq!(p.len(), 1);
        assert!(matches!(p[0].problem, DeckProblem::MissingComma { .. }));
        assert_eq!((p[0].line, p[0].column), (1, 8));
    }

    #[test]
    fn end_of_card_separates_like_a_comma() {
        let (a, p) = parse("X(1)=0.0, 0.5, 33\nR(1)=0.0,\n 0.44 \n 1.25");
        assert!(p.is_empty(), "{p:?}");
        assert_eq!(nums(&a[0]), vec![0.0, 0.5, 33.0]);
        assert_eq!(nums(&a[1]), vec![0.0, 0.44, 1.25]);
    }

    #[test]
    fn recovers_after_garbage() {
        let (a, p) = parse("XW=1.0, @@ ZW=2.0, XH=3.0");
        assert_eq!(p.len(), 1, "{p:?}");
        assert_eq!(
            a.iter().map(|a| a.name.as_ref()).collect::<Vec<_>>(),
            ["XW", "ZW", "XH"]
        );
    }
}
