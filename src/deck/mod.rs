//! The Digital DATCOM deck reader: text to cases of namelist values and control cards.
//!
//! Reading is in three layers: [`lexer`] (nom) splits namelist text into tokens; [`namelist`]
//! reads assignments from the tokens of one namelist body; this module walks the deck line by
//! line, sorts lines into control cards, namelists and comments, applies assignments to the
//! schema of each namelist, and groups everything into cases. Every problem becomes a
//! [`Diagnostic`]; reading never stops early and never panics.

pub mod cards;
pub mod lexer;
pub mod namelist;
pub mod schema;
pub mod writer;

use std::borrow::Cow;
use std::collections::BTreeMap;

use serde::{Deserialize, Serialize};

use crate::error::{DeckProblem, Diagnostic, Severity};
use cards::{AirfoilCard, Card, Cards, Surface};
use lexer::{Tok, Token};
use namelist::Lit;
use schema::{Kind, Table};

/// Columns the original program reads from each card.
pub const CARD_COLUMNS: usize = 80;

/// The longest number the original program reads, in characters: with 12 to 15 it does not
/// run the case, with 16 or more it reads another value (measured with a build of its source:
/// XCG=8.030000000 is read, XCG=8.0300000001 stops the case, XCG=8.030000000000001 is read as
/// 8.0).
pub const NUMBER_CHARACTERS: usize = 11;

/// The value of one namelist variable as read.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(untagged)]
pub enum Value {
    /// Numbers by element; `None` for elements never assigned.
    Numbers(Vec<Option<f64>>),
    /// Logicals by element (most logicals are scalars: one element).
    Logicals(Vec<Option<bool>>),
}

impl Value {
    /// The assigned elements from the first up to the last assigned one.
    pub fn numbers(&self) -> Option<&[Option<f64>]> {
        match self {
            Value::Numbers(v) => Some(v),
            Value::Logicals(_) => None,
        }
    }

    /// First element of a logical.
    pub fn logical(&self) -> Option<bool> {
        match self {
            Value::Logicals(v) => v.first().copied().flatten(),
            Value::Numbers(_) => None,
        }
    }

    /// First element, when assigned.
    pub fn scalar(&self) -> Option<f64> {
        self.numbers().and_then(|v| v.first().copied().flatten())
    }

    /// How many elements, counting from the first, are assigned without a gap.
    pub fn leading_count(&self) -> usize {
        match self {
            Value::Numbers(v) => v.iter().take_while(|x| x.is_some()).count(),
            Value::Logicals(v) => v.iter().take_while(|x| x.is_some()).count(),
        }
    }
}

/// The variables of one namelist in one case, after merging every occurrence.
pub type NamelistValues = BTreeMap<String, Value>;

/// One case of a deck, as read: namelists, control cards and airfoil cards.
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
pub struct RawCase {
    /// 1-based position in the deck.
    pub number: usize,
    /// Line where the case's first card is.
    pub first_line: usize,
    pub caseid: Option<String>,
    pub namelists: BTreeMap<String, NamelistValues>,
    pub cards: Cards,
    pub airfoils: Vec<AirfoilCard>,
    /// The case ends with SAVE: its data carries into the next case.
    pub save: bool,
    /// Where each variable was last assigned, so that later checks can point at it.
    #[serde(skip)]
    pub origins: Origins,
}

/// Where each variable of a case was last assigned: (line, column) by namelist and variable.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Origins {
    /// By the [`schema::key`]s of the namelist's and the variable's names, sorted.
    places: Vec<((u64, u64), (usize, usize))>,
}

impl Origins {
    /// Where variable `var` of namelist `nl` was last assigned.
    pub fn get(&self, nl: &str, var: &str) -> Option<(usize, usize)> {
        let k = (schema::key(nl)?, schema::key(var)?);
        let i = self.places.binary_search_by_key(&k, |(pk, _)| *pk).ok()?;
        Some(self.places[i].1)
    }

    /// Where namelist `nl`'s first recorded assignment from line `from` on is (line, column):
    /// the nearest place to its start in a case beginning at `from`. Values a SAVE carried
    /// from an earlier case are recorded where that case gave them: the earliest of those
    /// when the case gives none of its own.
    pub fn first_in(&self, nl: &str, from: usize) -> Option<(usize, usize)> {
        let n = schema::key(nl)?;
        let places = || {
            self.places
                .iter()
                .filter(move |((k, _), _)| *k == n)
                .map(|(_, at)| *at)
        };
        places()
            .filter(|(line, _)| *line >= from)
            .min()
            .or_else(|| places().min())
    }

    /// Records that variable `var` of namelist `nl` was assigned at `at` (line, column). Names
    /// longer than eight characters, which no namelist or variable has, are not recorded.
    pub fn insert(&mut self, nl: &str, var: &str, at: (usize, usize)) {
        let (Some(n), Some(v)) = (schema::key(nl), schema::key(var)) else {
            return;
        };
        match self.places.binary_search_by_key(&(n, v), |(k, _)| *k) {
            Ok(i) => self.places[i].1 = at,
            Err(i) => self.places.insert(i, ((n, v), at)),
        }
    }
}

impl RawCase {
    /// A number of namelist `nl`, variable `var`, element 1.
    pub fn scalar(&self, nl: &str, var: &str) -> Option<f64> {
        self.namelists.get(nl)?.get(var)?.scalar()
    }

    /// True until a card of the case's own is read (data carried over by SAVE does not count).
    fn is_empty(&self) -> bool {
        self.first_line == 0
    }
}

/// A deck as read: its cases and every problem found.
#[derive(Debug, Clone, PartialEq, Default, Serialize)]
pub struct RawDeck {
    pub file: String,
    pub cases: Vec<RawCase>,
    pub diagnostics: Vec<Diagnostic>,
}

impl crate::error::Diagnosed for RawDeck {
    fn diagnostics(&self) -> &[Diagnostic] {
        &self.diagnostics
    }
}

/// A namelist being read: opened on some line; its tokens are gathered in [`Reader::body`]
/// until `$`.
struct Open<'a> {
    name: Cow<'a, str>,
    /// The namelist's schema, when Digital DATCOM has it.
    table: Option<&'static Table>,
    line: usize,
    column: usize,
}

/// Longest excerpt of deck text quoted in a message.
const EXCERPT_CHARS: usize = 40;
/// Tokens of a namelist body that the reader makes room for at once.
const BODY_TOKENS: usize = 256;
/// Most cards listed as swallowed by an unterminated namelist.
const SWALLOWED_LISTED: usize = 8;

/// Deck text for a message: at most [`EXCERPT_CHARS`] characters, control characters escaped.
fn excerpt(text: &str) -> String {
    let mut out: String = text
        .trim()
        .chars()
        .take(EXCERPT_CHARS)
        .flat_map(|c| {
            if c.is_control() || c == '\u{a0}' {
                c.escape_default().collect::<Vec<_>>()
            } else {
                vec![c]
            }
        })
        .collect();
    if text.trim().chars().count() > EXCERPT_CHARS {
        out.push('…');
    }
    out
}

/// Column (1-based, in characters) of byte offset `byte` in `text`.
fn column_of(text: &str, byte: usize) -> usize {
    text[..byte.min(text.len())].chars().count() + 1
}

/// Diagnostics of one deck as they are found.
struct Diags<'a> {
    file: &'a str,
    list: Vec<Diagnostic>,
}

impl Diags<'_> {
    fn push(
        &mut self,
        severity: Severity,
        (line, column): (usize, usize),
        card: Option<&str>,
        variable: Option<&str>,
        problem: DeckProblem,
        hint: Option<String>,
    ) {
        self.list.push(Diagnostic {
            severity,
            file: self.file.to_string(),
            line,
            column,
            card: card.map(str::to_string),
            variable: variable.map(str::to_string),
            problem,
            hint,
        });
    }
}

/// What the current case holds of one namelist: a record for each variable of its schema, at
/// the variable's place in [`Table::vars`]. The case's map of values and its [`Origins`] are
/// made from these when the case ends; while reading, an assignment finds its variable by
/// index instead of through maps keyed by name.
#[derive(Clone)]
struct NamelistRecord<'a> {
    name: Cow<'a, str>,
    /// The [`schema::key`] of the name; records are sorted by it, which is the order of names.
    key: u64,
    table: &'static Table,
    /// The namelist is among the case's namelists (`$SYMFLP` and `$ASYFLP` remove each other;
    /// the places of their assignments stay recorded).
    present: bool,
    /// The namelist appeared in the current case (data carried by SAVE does not count).
    seen: bool,
    /// Where its variables' records start in [`Records::vars`].
    first: usize,
}

impl NamelistRecord<'_> {
    fn var_range(&self) -> std::ops::Range<usize> {
        self.first..self.first + self.table.vars().len()
    }
}

#[derive(Clone, Default)]
struct VarRecord {
    value: Option<Value>,
    /// Elements assigned in the current case: bit `i` for element `i`.
    assigned: u128,
    /// Where the variable was last assigned (line, column).
    origin: Option<(usize, usize)>,
}

/// The namelists of the current case, and the records of their variables in one list (one
/// allocation for the case rather than one a namelist).
#[derive(Default)]
struct Records<'a> {
    /// Sorted by key.
    namelists: Vec<NamelistRecord<'a>>,
    vars: Vec<VarRecord>,
}

impl<'a> Records<'a> {
    /// Room for the namelists and variables of most cases at once.
    fn with_capacity() -> Self {
        Records {
            namelists: Vec::with_capacity(16),
            vars: Vec::with_capacity(256),
        }
    }

    fn find(&self, key: u64) -> Option<&NamelistRecord<'a>> {
        let i = self.namelists.binary_search_by_key(&key, |r| r.key).ok()?;
        Some(&self.namelists[i])
    }

    fn vars(&self, r: &NamelistRecord) -> &[VarRecord] {
        &self.vars[r.var_range()]
    }

    fn var(&self, r: &NamelistRecord, name: &str) -> Option<&VarRecord> {
        r.table.index(name).map(|i| &self.vars(r)[i])
    }

    /// The value of `name` in `r`, when the namelist is among the case's and the variable was
    /// set.
    fn value(&self, r: &NamelistRecord, name: &str) -> Option<&Value> {
        self.var(r, name)
            .filter(|_| r.present)
            .and_then(|v| v.value.as_ref())
    }

    /// The place of the namelist `open` (its name's key `key`, its schema `table`) in
    /// [`Records::namelists`], added if missing.
    fn entry(&mut self, open: &Open<'a>, key: u64, table: &'static Table) -> usize {
        match self.namelists.binary_search_by_key(&key, |r| r.key) {
            Ok(i) => i,
            Err(i) => {
                let first = self.vars.len();
                let len = table.vars().len();
                self.vars.resize(first + len, VarRecord::default());
                let record = NamelistRecord {
                    name: open.name.clone(),
                    key,
                    table,
                    present: false,
                    seen: false,
                    first,
                };
                self.namelists.insert(i, record);
                i
            }
        }
    }

    fn clear(&mut self) {
        self.namelists.clear();
        self.vars.clear();
    }

    /// The case's namelists and the places of their assignments; the values are moved out of
    /// the records when `take`, else copied.
    fn materialize(&mut self, take: bool) -> (BTreeMap<String, NamelistValues>, Origins) {
        let assigned = self.vars.iter().filter(|v| v.origin.is_some()).count();
        let mut places = Vec::with_capacity(assigned);
        let mut namelists = BTreeMap::new();
        for r in &self.namelists {
            let mut values = NamelistValues::new();
            let vars = &mut self.vars[r.var_range()];
            for (v, (var_key, spec)) in vars.iter_mut().zip(r.table.vars()) {
                if let Some(at) = v.origin {
                    places.push(((r.key, *var_key), at));
                }
                let value = if take {
                    v.value.take()
                } else {
                    v.value.clone()
                };
                if let Some(value) = value {
                    values.insert(spec.name.clone(), value);
                }
            }
            if r.present {
                namelists.insert(r.name.to_string(), values);
            }
        }
        (namelists, Origins { places })
    }
}

struct Reader<'a> {
    file: &'a str,
    diags: Diags<'a>,
    cases: Vec<RawCase>,
    case: RawCase,
    records: Records<'a>,
    /// Room for the values of one assignment, reused by every namelist.
    values: Vec<Lit>,
    /// Surfaces that had a NACA card in the current case.
    seen_naca: Vec<Surface>,
    /// The current case began with data carried by SAVE, in this unit system.
    carried: Option<cards::Dim>,
    open: Option<Open<'a>>,
    /// Tokens of the open namelist so far, then those of the line being read that are not
    /// sorted yet (see [`Reader::feed`]). Lines are lexed straight into it.
    body: Vec<Token<'a>>,
    lines: Vec<&'a str>,
}

/// Splits deck text into lines: LF, CRLF or CR, final newline optional.
fn split_lines(text: &str) -> Vec<&str> {
    let mut out = Vec::new();
    for l in text.split('\n') {
        let l = l.strip_suffix('\r').unwrap_or(l);
        // Most decks end lines with LF or CRLF only: a lone CR is looked for once a line.
        if l.as_bytes().contains(&b'\r') {
            out.extend(l.split('\r'));
        } else {
            out.push(l);
        }
    }
    // A final line break leaves an empty piece after it.
    if (text.ends_with('\n') || text.ends_with('\r')) && out.last() == Some(&"") {
        out.pop();
    }
    out
}

/// A comment card of DATCOM+ (`*` or `#` in the first non-blank column).
fn is_comment(trimmed: &str) -> bool {
    trimmed.starts_with('*') || trimmed.starts_with('#')
}

/// Splits off a trailing `!` comment, returning the text before it.
fn strip_bang(text: &str) -> (&str, bool) {
    match find_byte(text, b'!') {
        Some(i) => (&text[..i], true),
        None => (text, false),
    }
}

/// The byte offset of the first `byte` (ASCII) in `text`. Most lines have none: a quick test
/// for any comes first.
fn find_byte(text: &str, byte: u8) -> Option<usize> {
    let bytes = text.as_bytes();
    if bytes.contains(&byte) {
        bytes.iter().position(|b| *b == byte)
    } else {
        None
    }
}

/// `$NAME` or `&NAME` at the start of a trimmed line: the name in upper case.
fn opens_namelist(trimmed: &str) -> Option<Cow<'_, str>> {
    let rest = trimmed.strip_prefix(['$', '&'])?;
    let len = rest
        .bytes()
        .take_while(|c| c.is_ascii_alphanumeric())
        .count();
    let name = &rest[..len];
    if name.is_empty() || name.eq_ignore_ascii_case("END") {
        None
    } else {
        Some(lexer::upper(name))
    }
}

/// Describes a line for "swallowed" lists: its namelist or the start of the card.
fn card_label(line: &str) -> String {
    let t = line.trim();
    if let Some(n) = opens_namelist(t) {
        return format!("${n}");
    }
    excerpt(&t.chars().take(24).collect::<String>())
}

/// True for tokens that begin an assignment (`NAME =` or `NAME (`).
fn has_assignment<'t>(toks: &'t [Token<'_>]) -> Option<&'t str> {
    toks.windows(2).find_map(|w| match (&w[0].tok, &w[1].tok) {
        (Tok::Name(n), Tok::Equals | Tok::LParen) => Some(n.as_ref()),
        _ => None,
    })
}

impl<'a> Reader<'a> {
    fn diag(
        &mut self,
        severity: Severity,
        at: (usize, usize),
        card: Option<&str>,
        variable: Option<&str>,
        problem: DeckProblem,
        hint: Option<String>,
    ) {
        self.diags.push(severity, at, card, variable, problem, hint);
    }

    fn note_dialect(&mut self, line: usize, column: usize, what: &str) {
        self.diag(
            Severity::Note,
            (line, column),
            None,
            None,
            DeckProblem::Dialect { what: what.into() },
            None,
        );
    }

    /// Text the reader ignores on line `line`: a warning with its excerpt.
    fn trailing_text(&mut self, line: usize, column: usize, found: &str, hint: &str) {
        self.diag(
            Severity::Warning,
            (line, column),
            None,
            None,
            DeckProblem::TrailingText {
                found: excerpt(found),
            },
            Some(hint.into()),
        );
    }

    /// A control card whose output of the original this program does not produce: a warning,
    /// so that the missing pages are not a surprise.
    fn output_not_reproduced(&mut self, line: usize, column: usize, card: &str, what: &str) {
        self.diag(
            Severity::Warning,
            (line, column),
            Some(card),
            None,
            DeckProblem::Case {
                message: format!("a {card} card: {what}"),
            },
            None,
        );
    }

    fn touch_case(&mut self, line: usize) {
        if self.case.first_line == 0 {
            self.case.first_line = line;
        }
    }

    fn run(mut self) -> RawDeck {
        if let Some(d) = self.missile_check().or_else(|| self.listing_check()) {
            return RawDeck {
                file: self.file.to_string(),
                cases: Vec::new(),
                diagnostics: vec![d],
            };
        }
        let lines = std::mem::take(&mut self.lines);
        for (i, raw) in lines.iter().enumerate() {
            self.line(i + 1, raw, &lines);
        }
        if let Some(open) = self.open.take() {
            let hint = format!("(last line of the deck is {})", lines.len());
            let len = self.body.len();
            self.unterminated(open, len, vec!["the end of the deck".into()], &hint);
        }
        self.end_case(true);
        let mut diagnostics = self.diags.list;
        sort_diagnostics(&mut diagnostics);
        RawDeck {
            file: self.file.to_string(),
            cases: self.cases,
            diagnostics,
        }
    }

    fn missile_check(&self) -> Option<Diagnostic> {
        for (i, l) in self.lines.iter().enumerate() {
            let t = l.trim();
            let Some(n) = opens_namelist(t) else { continue };
            if schema::MISSILE_NAMELISTS.contains(&n.as_ref()) {
                return Some(Diagnostic {
                    severity: Severity::Error,
                    file: self.file.to_string(),
                    line: i + 1,
                    column: l.find(['$', '&']).map_or(1, |c| column_of(l, c)),
                    card: Some(n.to_string()),
                    variable: None,
                    problem: DeckProblem::MissileDatcom {
                        namelist: n.into_owned(),
                    },
                    hint: Some(
                        "run it with Missile DATCOM; Digital DATCOM describes aircraft with $BODY, $WGPLNF, $SYNTHS ...".into(),
                    ),
                });
            }
        }
        None
    }

    /// A listing of the original program (for006.dat) given as a deck: it echoes the deck's
    /// cards among its pages, which would be read as a deck with many errors. A listing's
    /// marks come before the cards it echoes: the lines up to the first namelist are looked at.
    fn listing_check(&self) -> Option<Diagnostic> {
        let before_namelists = self
            .lines
            .iter()
            .position(|l| opens_namelist(l.trim()).is_some())
            .unwrap_or(self.lines.len());
        let line = self.lines[..before_namelists]
            .iter()
            .position(|l| crate::report::legacy::is_listing_line(l))?;
        Some(Diagnostic {
            severity: Severity::Error,
            file: self.file.to_string(),
            line: line + 1,
            column: 1,
            card: None,
            variable: None,
            problem: DeckProblem::Case {
                message: "this is a listing (the original program's for006.dat, or a report of `datcom-rs run`), not an input deck".into(),
            },
            hint: Some(
                "`datcom-rs import` reads a listing in the original's layout (the original's, or `run --format for006`) into JSON, and `datcom-rs compare` and `report` take one as the reference".into(),
            ),
        })
    }

    fn line(&mut self, n: usize, raw: &'a str, all: &[&str]) {
        let trimmed_all = raw.trim();
        let first_col = column_of(raw, raw.len() - raw.trim_start().len());
        if trimmed_all.is_empty() {
            if self.open.is_none() {
                self.note_dialect(n, 1, "a blank card");
            }
            return;
        }
        if is_comment(trimmed_all) {
            self.note_dialect(n, first_col, "a DATCOM+ comment card");
            return;
        }
        let is_caseid = self.open.is_none()
            && trimmed_all
                .as_bytes()
                .get(..6)
                .is_some_and(|w| w.eq_ignore_ascii_case(b"CASEID"));
        let (text, had_bang) = if is_caseid {
            (raw, false)
        } else {
            strip_bang(raw)
        };
        if had_bang {
            self.note_dialect(n, text.chars().count() + 1, "a trailing `!` comment");
        }
        if raw.starts_with(['$', '&']) {
            self.note_dialect(
                n,
                1,
                "a namelist starting in column 1 (the original needs column 1 blank)",
            );
        }
        if !is_caseid {
            // A byte search: no byte of a multi-byte character is an ASCII letter.
            // Tested over the whole line first (a loop without early exit, which compiles to
            // vector instructions): most lines have no lower case.
            let bytes = text.as_bytes();
            let any_lower = bytes
                .iter()
                .fold(false, |any, c| any | c.is_ascii_lowercase());
            let first_lower = any_lower
                .then(|| bytes.iter().position(u8::is_ascii_lowercase))
                .flatten();
            if let Some(c) = first_lower {
                let col = column_of(text, c);
                self.note_dialect(n, col, "lower case (the original reads upper case only)");
            }
        }
        if let Some(c) = find_byte(raw, b'\t') {
            self.note_dialect(n, column_of(raw, c), "a TAB character");
        }
        // A line of at most 80 bytes has at most 80 characters.
        let past = if text.len() > CARD_COLUMNS {
            text.char_indices()
                .nth(CARD_COLUMNS)
                .map_or("", |(i, _)| &text[i..])
        } else {
            ""
        };
        if !past.trim().is_empty() {
            let card = match (&self.open, is_caseid) {
                (Some(o), _) => Some(o.name.as_ref()),
                (None, true) => Some("CASEID"),
                (None, false) => None,
            };
            self.diags.push(
                Severity::Warning,
                (n, CARD_COLUMNS + 1),
                card,
                None,
                DeckProblem::PastColumn80 {
                    found: excerpt(past),
                },
                Some("break the card into lines of at most 80 columns".into()),
            );
        }
        match self.open.take() {
            Some(open) => self.namelist_line(n, text, all, open),
            None => self.outside_line(n, text),
        }
    }

    /// A warning for each number of the body from token `from` on that the original cannot
    /// read ([`NUMBER_CHARACTERS`]).
    fn long_numbers(&mut self, from: usize) {
        if !self.body[from..].iter().any(
            |t| matches!(t.tok, lexer::Tok::Number { text, .. } if text.len() > NUMBER_CHARACTERS),
        ) {
            return;
        }
        // Each number's namelist: the open one, or the last one opened before it on the line.
        let mut name = self.open.as_ref().map(|o| o.name.to_string());
        let mut long: Vec<(usize, usize, String, Option<String>)> = Vec::new();
        for t in &self.body[from..] {
            match &t.tok {
                lexer::Tok::Open(n) => name = Some(n.to_string()),
                lexer::Tok::Number { text, .. } if text.len() > NUMBER_CHARACTERS => {
                    long.push((t.line, t.column, text.to_string(), name.clone()));
                }
                _ => {}
            }
        }
        for (line, column, text, name) in long {
            self.diags.push(
                Severity::Warning,
                (line, column),
                name.as_deref(),
                None,
                DeckProblem::LongNumber {
                    length: text.chars().count(),
                    found: text,
                },
                Some(format!(
                    "write it with at most {NUMBER_CHARACTERS} characters: a REAL of the original holds about 7 significant digits"
                )),
            );
        }
    }

    /// A line that begins something new (a control card or another namelist), which, met inside
    /// a namelist, means that namelist was never closed.
    fn begins_new(text: &str, n: usize) -> bool {
        let t = text.trim();
        if let Some(name) = opens_namelist(t) {
            return schema::table(&name).is_some();
        }
        parse_card(t, n).is_some()
    }

    fn namelist_line(&mut self, n: usize, text: &'a str, all: &[&str], open: Open<'a>) {
        if Self::begins_new(text, n) {
            // The original reads on to the next `$`: list the cards it would swallow.
            let mut swallowed = Vec::new();
            let mut more = 0;
            for l in all.iter().skip(n - 1) {
                let (l, _) = strip_bang(l);
                if l.trim().is_empty() || is_comment(l.trim()) {
                    continue;
                }
                if swallowed.len() < SWALLOWED_LISTED {
                    swallowed.push(card_label(l));
                } else {
                    more += 1;
                }
                if l.contains('$') {
                    break;
                }
            }
            if more > 0 {
                swallowed.push(format!("{more} more cards"));
            }
            let len = self.body.len();
            self.unterminated(open, len, swallowed, &format!("before line {n}"));
            self.outside_line(n, text);
            return;
        }
        if text.starts_with(|c: char| !c.is_whitespace()) {
            self.note_dialect(
                n,
                1,
                "a namelist continuation starting in column 1 (the original reads it as a control card)",
            );
        }
        self.open = Some(open);
        let from = self.body.len();
        lexer::lex_line(text, n, 1, &mut self.body);
        self.long_numbers(from);
        self.feed(from);
    }

    /// Sorts the tokens of a line, lexed into [`Reader::body`] from index `from`: into the open
    /// namelist until `$` closes it; after that, a `$NAME` opens the next one, and anything
    /// else on the line is stray. Tokens before `from` are the open namelist's; with none open,
    /// there are none.
    fn feed(&mut self, from: usize) {
        // Tokens before `i` are the open namelist's body, or the stray tokens so far.
        let mut i = from;
        while let Some(t) = self.body.get(i) {
            match (&self.open, &t.tok) {
                (Some(_), Tok::Close) => {
                    let open = self.open.take().expect("open");
                    self.close(open, i);
                    self.body.drain(..1);
                    i = 0;
                }
                (Some(_), Tok::Open(name)) if schema::table(name).is_some() => {
                    let (name, line, column) = (name.clone(), t.line, t.column);
                    let open = self.open.take().expect("open");
                    let swallowed = vec![format!("${name} (line {line})")];
                    let where_to_close = format!("before ${name}");
                    self.unterminated(open, i, swallowed, &where_to_close);
                    self.body.drain(..1);
                    self.start(name, line, column);
                    i = 0;
                }
                (None, Tok::Open(name)) => {
                    let (name, line, column) = (name.clone(), t.line, t.column);
                    self.stray(i);
                    self.body.drain(..1);
                    self.start(name, line, column);
                    i = 0;
                }
                // `$$`: a doubled terminator; harmless.
                (None, Tok::Close) if i == 0 => {
                    self.body.drain(..1);
                }
                _ => i += 1,
            }
        }
        if self.open.is_none() {
            self.stray(self.body.len());
        }
    }

    /// The first `len` tokens of [`Reader::body`], which came after a closing `$` on the same
    /// card, taken and reported. Assignments there are lost in the original too, so they are an
    /// error; other text a warning.
    fn stray(&mut self, len: usize) {
        let toks = &self.body[..len];
        let Some(first) = toks.first() else { return };
        let text: Vec<String> = toks.iter().take(8).map(|t| t.tok.text()).collect();
        let found = excerpt(&text.join(" "));
        let at = (first.line, first.column);
        let assigned = has_assignment(toks).map(str::to_string);
        self.body.drain(..len);
        match assigned {
            Some(var) => {
                self.diag(
                    Severity::Error,
                    at,
                    None,
                    Some(&var),
                    DeckProblem::AfterClose { found },
                    Some(format!(
                        "remove the `$` before {var}, or open a namelist for it"
                    )),
                );
            }
            None => self.diag(
                Severity::Warning,
                at,
                None,
                None,
                DeckProblem::TrailingText { found },
                None,
            ),
        }
    }

    fn start(&mut self, name: Cow<'a, str>, line: usize, column: usize) {
        self.touch_case(line);
        let table = schema::table(&name);
        if name == "EXPR00" {
            self.diag(
                Severity::Error,
                (line, column),
                Some(&name),
                None,
                DeckProblem::UnknownNamelist { found: name.to_string() },
                Some("experimental-data namelists are EXPR01, EXPR02, ..., one per Mach number of $FLTCON".into()),
            );
        } else if table.is_none() {
            let hint = schema::nearest(&name, schema::namelists().keys().map(String::as_str))
                .map(|n| format!("did you mean ${n}?"));
            self.diag(
                Severity::Error,
                (line, column),
                Some(&name),
                None,
                DeckProblem::UnknownNamelist {
                    found: name.to_string(),
                },
                hint,
            );
        }
        self.open = Some(Open {
            name,
            table,
            line,
            column,
        });
    }

    fn outside_line(&mut self, n: usize, text: &'a str) {
        let trimmed = text.trim();
        let col = column_of(text, text.len() - text.trim_start().len());
        if trimmed.starts_with(['$', '&']) {
            // With no namelist open, every token read before has been sorted.
            debug_assert!(self.body.is_empty());
            lexer::lex_line(text, n, 1, &mut self.body);
            self.long_numbers(0);
            let toks = &self.body;
            // `$ NAME`: a blank between `$` and a namelist's name.
            if let (Some(Tok::Close), Some(Tok::Name(name))) =
                (toks.first().map(|t| &t.tok), toks.get(1).map(|t| &t.tok))
            {
                if schema::table(name).is_some() {
                    let name = name.clone();
                    let at = (toks[1].line, toks[1].column);
                    self.diag(
                        Severity::Error,
                        (n, col),
                        Some(&name),
                        None,
                        DeckProblem::Syntax {
                            expected: format!("`${name}` with no blank after `$`"),
                            found: format!("`$ {name}`"),
                        },
                        Some(format!("write ${name}; read here as ${name}")),
                    );
                    self.start(name, at.0, at.1);
                    self.body.drain(..2);
                    self.feed(0);
                    return;
                }
            }
            match toks.first().map(|t| &t.tok) {
                Some(Tok::Open(_)) => self.feed(0),
                _ => {
                    self.body.clear();
                    self.trailing_text(n, col, trimmed, "a `$` outside a namelist closes nothing");
                }
            }
            return;
        }
        match parse_card(trimmed, n) {
            Some(parsed) => {
                if col > 1 && !matches!(parsed.card, Card::NextCase) {
                    self.note_dialect(
                        n,
                        col,
                        "a control card not in column 1 (the original reads it as namelist data)",
                    );
                }
                if let Some(extra) = &parsed.extra {
                    self.trailing_text(
                        n,
                        col,
                        extra,
                        "the card needs nothing more; the rest is ignored",
                    );
                }
                self.card(n, col, parsed.card);
            }
            None => {
                let upper = trimmed.to_ascii_uppercase();
                let word: String = upper
                    .chars()
                    .take_while(|c| c.is_ascii_alphanumeric())
                    .collect();
                let rest = upper[word.len()..].trim_start();
                if !word.is_empty() && (rest.starts_with('=') || rest.starts_with('(')) {
                    let home = schema::homes(&word)
                        .map(|h| format!("{word} belongs in {h}: put it inside that namelist"));
                    self.diag(
                        Severity::Error,
                        (n, col),
                        None,
                        Some(&excerpt(&word)),
                        DeckProblem::AssignmentOutsideNamelist {
                            found: excerpt(trimmed),
                        },
                        home.or_else(|| Some("was the namelist above closed too early?".into())),
                    );
                } else {
                    let hint = schema::nearest(&word, cards::KEYWORDS.iter().copied())
                        .map(|k| format!("did you mean {k}?"));
                    self.diag(
                        Severity::Error,
                        (n, col),
                        None,
                        None,
                        DeckProblem::UnknownCard {
                            found: excerpt(trimmed),
                        },
                        hint,
                    );
                }
            }
        }
    }

    fn card(&mut self, n: usize, col: usize, card: Card) {
        if card != Card::NextCase {
            self.touch_case(n);
        }
        match card {
            Card::CaseId(text) => self.case.caseid = Some(text),
            Card::NextCase => self.end_case(false),
            Card::Save => self.case.save = true,
            Card::Dim(d) => {
                if let Some(old) = self.carried.filter(|old| *old != d) {
                    self.diag(
                        Severity::Warning,
                        (n, col),
                        Some("DIM"),
                        None,
                        DeckProblem::Case {
                            message: format!(
                                "the unit system changes from DIM {} to DIM {} in a case that carries saved namelists: they are read in the new units",
                                old.name(),
                                d.name()
                            ),
                        },
                        None,
                    );
                }
                self.case.cards.dim = Some(d);
            }
            Card::Deriv(d) => self.case.cards.deriv = Some(d),
            Card::Damp => self.case.cards.damp = true,
            Card::Build => self.case.cards.build = true,
            Card::Part => {
                self.case.cards.part = true;
                self.output_not_reproduced(
                    n,
                    col,
                    "PART",
                    "of the original's CONFIGURATION AUXILIARY AND PARTIAL OUTPUT the transonic data fairing and the panel rows of cranked planforms are not printed",
                );
            }
            Card::Trim => {
                self.case.cards.trim = true;
                self.output_not_reproduced(
                    n,
                    col,
                    "TRIM",
                    "the trim computation and its pages are not done; the untrimmed pages are printed",
                );
            }
            Card::Plot => self.case.cards.plot = true,
            Card::PrintExtrap => self.case.cards.print_extrap = true,
            Card::Namelist => self.case.cards.namelist = true,
            Card::Dump(s) => self.case.cards.dump.push(s),
            Card::Write(s) => {
                self.case.cards.write.push(s);
                self.diag(
                    Severity::Note,
                    (n, col),
                    Some("WRITE"),
                    None,
                    DeckProblem::Dialect {
                        what: "a WRITE card (kept, with no effect)".into(),
                    },
                    None,
                );
            }
            Card::Naca(a) => {
                if let Some(old) = self.case.airfoils.iter().find(|b| b.surface == a.surface) {
                    if old.line > 0 && self.seen_naca.contains(&a.surface) {
                        let message = format!(
                            "a second NACA card for the {} replaces the one on line {}",
                            a.surface.name(),
                            old.line
                        );
                        self.diag(
                            Severity::Warning,
                            (n, col),
                            Some("NACA"),
                            None,
                            DeckProblem::Case { message },
                            None,
                        );
                    }
                }
                if !self.seen_naca.contains(&a.surface) {
                    self.seen_naca.push(a.surface);
                }
                self.case.airfoils.retain(|b| b.surface != a.surface);
                self.case.airfoils.push(a);
            }
            Card::Bad(card, expected, found) => self.diag(
                Severity::Error,
                (n, col),
                Some(&card),
                None,
                DeckProblem::BadCard {
                    card: card.clone(),
                    expected,
                    found: excerpt(&found),
                },
                None,
            ),
        }
    }

    /// Reports a namelist never closed by `$`, then reads what it holds: the first `len` tokens
    /// of [`Reader::body`].
    fn unterminated(
        &mut self,
        open: Open<'a>,
        len: usize,
        swallowed: Vec<String>,
        where_to_close: &str,
    ) {
        self.diag(
            Severity::Error,
            (open.line, open.column),
            Some(&open.name),
            None,
            DeckProblem::UnterminatedNamelist {
                namelist: open.name.to_string(),
                opened_line: open.line,
                swallowed,
            },
            Some(format!("end ${} with `$` {where_to_close}", open.name)),
        );
        self.close(open, len);
    }

    /// Applies a closed namelist's assignments, its body the first `len` tokens of
    /// [`Reader::body`], to the current case; the tokens are taken.
    fn close(&mut self, open: Open<'a>, len: usize) {
        // Out of the reader while the assignments are applied to it.
        let mut body = std::mem::take(&mut self.body);
        self.apply(open, &body[..len]);
        body.drain(..len);
        self.body = body;
    }

    fn apply(&mut self, open: Open<'a>, body: &[Token<'a>]) {
        if open.name == "EXPR00" {
            return;
        }
        let Some(table) = open.table else {
            return;
        };
        let name: &str = &open.name;
        let nl_key = schema::key(name).expect("known namelists have short names");
        let i = self.records.entry(&open, nl_key, table);
        if self.records.namelists[i].seen {
            self.diags.push(
                Severity::Note,
                (open.line, open.column),
                Some(name),
                None,
                DeckProblem::NamelistRepeated {
                    namelist: name.to_string(),
                },
                None,
            );
        } else {
            self.records.namelists[i].seen = true;
        }
        // Symmetric and asymmetric flap data share storage in the original: reading one
        // clears the other.
        let rival = match name {
            "SYMFLP" => Some("ASYFLP"),
            "ASYFLP" => Some("SYMFLP"),
            _ => None,
        };
        let rival_record = rival.and_then(schema::key).and_then(|k| {
            let records = &self.records.namelists;
            records.binary_search_by_key(&k, |r| r.key).ok()
        });
        if let (Some(rival), Some(r)) = (rival, rival_record) {
            let record = &mut self.records.namelists[r];
            if std::mem::take(&mut record.present) {
                for v in &mut self.records.vars[record.var_range()] {
                    v.value = None;
                }
                self.diags.push(
                    Severity::Warning,
                    (open.line, open.column),
                    Some(name),
                    None,
                    DeckProblem::Case {
                        message: format!(
                            "${name} replaces the ${rival} read before it: the two share storage in DATCOM, one flap kind per case"
                        ),
                    },
                    None,
                );
            }
        }
        let record = &mut self.records.namelists[i];
        record.present = true;
        let vars = &mut self.records.vars[record.var_range()];
        // Assignments are applied as they are read; what they find wrong is reported after the
        // body's syntax problems.
        let mut found = Diags {
            file: self.file,
            list: Vec::new(),
        };
        let mut target = Target {
            name,
            table,
            vars,
            diags: &mut found,
        };
        let problems = namelist::parse_body(body, &mut self.values, |a| target.assign(a));
        for p in problems {
            self.diags.push(
                Severity::Error,
                (p.line, p.column),
                Some(name),
                p.variable.as_deref(),
                p.problem,
                p.hint,
            );
        }
        self.diags.list.append(&mut found.list);
    }

    /// Checks count variables against the arrays they count (NALPHA against ALSCHD, ...), in
    /// both directions, and experimental-data namelists against the Mach numbers.
    fn check_counts(&mut self) {
        let mismatch =
            |nl: &str, name: &str, count_var: &str, count: f64, given: usize, hint: String| {
                (
                    nl.to_string(),
                    Some(name.to_string()),
                    Severity::Warning,
                    DeckProblem::CountMismatch {
                        count_variable: count_var.to_string(),
                        count,
                        variable: name.to_string(),
                        given,
                    },
                    Some(hint),
                )
            };
        let mut found = Vec::new();
        let nmach = schema::key("FLTCON")
            .and_then(|k| self.records.find(k))
            .and_then(|r| self.records.value(r, "NMACH"))
            .and_then(Value::scalar);
        for record in self.records.namelists.iter().filter(|r| r.present) {
            let nl = &record.name;
            if let (Some(nn), Some(nmach)) = (nl.strip_prefix("EXPR"), nmach) {
                if nn.parse::<f64>().is_ok_and(|k| k > nmach) {
                    found.push((
                        nl.to_string(),
                        None,
                        Severity::Warning,
                        DeckProblem::Case {
                            message: format!(
                                "${nl} is for Mach number {nn} but NMACH={nmach}: it is not used"
                            ),
                        },
                        None,
                    ));
                }
            }
            let vars = self.records.vars(record);
            for (v, (_, var)) in vars.iter().zip(record.table.vars()) {
                let Some(value) = &v.value else { continue };
                let name = &var.name;
                let Some(count_var) = &var.count else {
                    continue;
                };
                // Counts in another namelist (`NMACH(FLTCON)` for per-Mach section data,
                // `NALPHA(FLTCON)` for experimental data) mark optional per-condition inputs:
                // fewer values than conditions is normal there.
                if count_var.contains('(') {
                    continue;
                }
                let Some(count) = self
                    .records
                    .value(record, count_var)
                    .and_then(Value::scalar)
                else {
                    continue;
                };
                let given = value.leading_count();
                if count.fract() != 0.0 || count < 0.0 || count > var.len as f64 {
                    found.push((
                        nl.to_string(),
                        Some(count_var.clone()),
                        Severity::Error,
                        DeckProblem::WrongKind {
                            variable: count_var.clone(),
                            expected: format!("a whole number from 0 to {}", var.len),
                            found: format!("{count}"),
                        },
                        None,
                    ));
                } else if (given as f64) < count {
                    // The original runs such a case, reading the missing values as zero (for
                    // angles of attack it prints a row of NDM); we use the values given.
                    let hint = if given == 0 {
                        format!("give {count} values of {name}")
                    } else {
                        format!("give {count} values of {name} or set {count_var}={given}.0; only the {given} given are used here, the original reads the others as zero")
                    };
                    found.push(mismatch(nl, name, count_var, count, given, hint));
                } else if (given as f64) > count
                    // Elements after the first `count` (a whole number up to the length).
                    && v.assigned >> (count as u32 + 1) != 0
                {
                    // Values beyond the count written in this case (saved data may hold more
                    // values than a later case asks for on purpose).
                    let hint = format!(
                        "{name} beyond the first {count} is not used; raise {count_var} to use all {given}"
                    );
                    found.push(mismatch(nl, name, count_var, count, given, hint));
                }
            }
        }
        for (nl, var, severity, problem, hint) in found {
            let at = var
                .as_ref()
                .and_then(|v| {
                    let record = self.records.find(schema::key(&nl)?)?;
                    self.records.var(record, v)?.origin
                })
                .unwrap_or((self.case.first_line, 0));
            self.diag(severity, at, Some(&nl), var.as_deref(), problem, hint);
        }
    }

    /// Closes the current case (at NEXT CASE or the end of the deck) and starts the next one,
    /// carrying the namelists and airfoil cards over when the case had SAVE. DIM and DERIV stay
    /// in force for every later case, SAVE or not (the original keeps them in global storage);
    /// every other control card belongs to its case.
    fn end_case(&mut self, at_end: bool) {
        let mut next = RawCase::default();
        next.cards.dim = self.case.cards.dim;
        next.cards.deriv = self.case.cards.deriv;
        if self.case.is_empty() {
            if !at_end && self.carried.is_some() {
                // The original runs the saved data once more as a case of its own here.
                self.note_dialect(
                    0,
                    0,
                    "a NEXT CASE with no cards of its own after SAVE: the original runs the saved namelists once more as a separate case; datcom-rs does not",
                );
            }
            if !at_end {
                self.case = next;
                self.carried = None;
                self.records.clear();
                self.seen_naca.clear();
            }
            return;
        }
        self.check_counts();
        let (namelists, origins) = self.records.materialize(!self.case.save);
        self.case.namelists = namelists;
        self.case.origins = origins;
        if self.case.save {
            next.airfoils = self.case.airfoils.clone();
            self.carried = Some(self.case.cards.dim.unwrap_or_default());
            for r in &mut self.records.namelists {
                r.seen = false;
            }
            for v in &mut self.records.vars {
                v.assigned = 0;
            }
        } else {
            self.carried = None;
            self.records.clear();
        }
        let mut done = std::mem::replace(&mut self.case, next);
        done.number = self.cases.len() + 1;
        self.cases.push(done);
        self.seen_naca.clear();
    }
}

/// A namelist of the current case that assignments are applied to.
struct Target<'r, 'd> {
    /// The namelist's name (upper case).
    name: &'r str,
    table: &'static Table,
    /// The records of the namelist's variables, by their place in the table.
    vars: &'r mut [VarRecord],
    diags: &'r mut Diags<'d>,
}

impl Target<'_, '_> {
    /// Applies one assignment.
    fn assign(&mut self, a: &namelist::Assignment) {
        let name = self.name;
        let at = (a.line, a.column);
        let written: &str = &a.name;
        let canonical = schema::canonical(&self.table.spec.name, written);
        let Some(index) = self.table.index(canonical) else {
            let near = schema::nearest(written, self.table.spec.vars.keys().map(String::as_str))
                .map(|n| format!("did you mean {n}?"))
                .or_else(|| {
                    schema::homes(written).map(|h| format!("{written} is a variable of {h}"))
                });
            self.diags.push(
                Severity::Error,
                at,
                Some(name),
                Some(&excerpt(written)),
                DeckProblem::UnknownVariable {
                    namelist: name.into(),
                    found: excerpt(written),
                },
                near,
            );
            return;
        };
        let var = self.table.vars()[index].1;
        let start = a.index.unwrap_or(1);
        let last = start.saturating_add(a.values.len().saturating_sub(1));
        if last > var.len {
            self.diags.push(
                Severity::Error,
                at,
                Some(name),
                Some(written),
                DeckProblem::TooManyValues {
                    variable: written.into(),
                    capacity: var.len,
                    given: a.values.len(),
                    last_index: last,
                },
                None,
            );
        }
        // Kind check, element by element: the last element of a wrong kind is reported.
        let bad = a.values.iter().rev().find(|lit| match (var.kind, lit) {
            (Kind::Logical, Lit::Number { .. }) => true,
            (Kind::Real | Kind::Integer, Lit::Logical(_)) => true,
            (Kind::Integer, Lit::Number { value, .. }) => value.is_finite() && value.fract() != 0.0,
            _ => false,
        });
        if let Some(bad) = bad {
            let found = match bad {
                Lit::Logical(_) => "a logical".to_string(),
                Lit::Number { value, .. } if var.kind == Kind::Integer => format!("{value}"),
                Lit::Number { .. } => "a number".to_string(),
            };
            let expected = match var.kind {
                Kind::Logical => "a logical (.TRUE. or .FALSE.)",
                Kind::Integer => "a whole number",
                Kind::Real => "a number",
            };
            self.diags.push(
                Severity::Error,
                at,
                Some(name),
                Some(written),
                DeckProblem::WrongKind {
                    variable: written.into(),
                    expected: expected.into(),
                    found,
                },
                None,
            );
            return;
        }
        // Elements beyond the array's capacity are reported above and not stored; an
        // assignment starting beyond it stores nothing.
        if start > var.len {
            return;
        }
        let end = last.min(var.len);
        let record = &mut self.vars[index];
        // Recorded up to the first element assigned before, as a search that stops there.
        let mut reassigned = false;
        for i in start..=end {
            let bit = 1u128 << i;
            if record.assigned & bit != 0 {
                reassigned = true;
                break;
            }
            record.assigned |= bit;
        }
        if reassigned {
            self.diags.push(
                Severity::Warning,
                at,
                Some(name),
                Some(written),
                DeckProblem::Reassigned {
                    variable: written.into(),
                },
                None,
            );
        }
        record.origin = Some(at);
        let entry = record.value.get_or_insert_with(|| match var.kind {
            Kind::Logical => Value::Logicals(Vec::new()),
            Kind::Real | Kind::Integer => Value::Numbers(Vec::new()),
        });
        // The elements written reach index `end` at most: room for them at once.
        match &mut *entry {
            Value::Numbers(v) => v.reserve(end.saturating_sub(v.len())),
            Value::Logicals(v) => v.reserve(end.saturating_sub(v.len())),
        }
        for (k, lit) in a
            .values
            .iter()
            .enumerate()
            .take(end.saturating_sub(start) + 1)
        {
            let i = start + k;
            match (&mut *entry, lit) {
                (Value::Numbers(v), Lit::Number { value, .. }) => {
                    if v.len() < i {
                        v.resize(i, None);
                    }
                    // A number beyond double precision (said where it was read) is not
                    // assigned: the element keeps what it held.
                    if value.is_finite() {
                        v[i - 1] = Some(*value);
                    }
                }
                (Value::Logicals(v), Lit::Logical(b)) => {
                    if v.len() < i {
                        v.resize(i, None);
                    }
                    v[i - 1] = Some(*b);
                }
                // Kinds were checked above.
                _ => {}
            }
        }
    }
}

/// Orders diagnostics by place (line, then column), whole-case ones after those of the same
/// line; the sort is stable, so problems at one place keep the order they were found in. The
/// same problem at the same place (found again in a case that carries saved data) is kept once.
pub fn sort_diagnostics(d: &mut Vec<Diagnostic>) {
    d.sort_by_key(|x| (x.line, x.column == 0, x.column));
    d.dedup();
}

use cards::parse_card;

/// Reads a deck from text. `file` names it in diagnostics.
pub fn read(text: &str, file: &str) -> RawDeck {
    let reader = Reader {
        file,
        diags: Diags {
            file,
            list: Vec::new(),
        },
        cases: Vec::new(),
        case: RawCase::default(),
        records: Records::with_capacity(),
        values: Vec::new(),
        seen_naca: Vec::new(),
        carried: None,
        open: None,
        // Room for the tokens of most namelists (a token a value, one a comma), so that the
        // list seldom grows.
        body: Vec::with_capacity(BODY_TOKENS),
        lines: split_lines(text),
    };
    reader.run()
}
