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

use std::collections::{BTreeMap, BTreeSet};

use serde::{Deserialize, Serialize};

use crate::error::{DeckProblem, Diagnostic, Severity};
use cards::{AirfoilCard, Card, Cards};
use lexer::{Tok, Token};
use namelist::Lit;
use schema::{Kind, NamelistSpec};

/// Columns the original program reads from each card.
pub const CARD_COLUMNS: usize = 80;

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
    /// Where each variable was last assigned, `NAMELIST.VARIABLE` -> (line, column), so that
    /// later checks can point at it.
    #[serde(skip)]
    pub origins: BTreeMap<String, (usize, usize)>,
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

/// A namelist being read: opened on some line, its tokens gathered until `$`.
struct Open {
    name: String,
    line: usize,
    column: usize,
    tokens: Vec<Token>,
}

struct Reader<'a> {
    file: &'a str,
    diags: Vec<Diagnostic>,
    cases: Vec<RawCase>,
    case: RawCase,
    /// Elements assigned in the current case (namelist, variable, index), for "assigned twice".
    assigned: BTreeSet<(&'static str, &'static str, usize)>,
    /// Namelists that appeared in the current case.
    seen: BTreeSet<String>,
    open: Option<Open>,
    lines: Vec<&'a str>,
}

/// Splits deck text into lines: LF, CRLF or CR, final newline optional.
fn split_lines(text: &str) -> Vec<&str> {
    let mut out: Vec<&str> = text
        .split('\n')
        .map(|l| l.strip_suffix('\r').unwrap_or(l))
        .collect();
    if text.ends_with('\n') {
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
    match text.find('!') {
        Some(i) => (&text[..i], true),
        None => (text, false),
    }
}

/// `$NAME` or `&NAME` at the start of a trimmed line.
fn opens_namelist(trimmed: &str) -> Option<String> {
    let rest = trimmed.strip_prefix(['$', '&'])?;
    let name: String = rest
        .chars()
        .take_while(|c| c.is_ascii_alphanumeric())
        .collect();
    if name.is_empty() || name.eq_ignore_ascii_case("END") {
        None
    } else {
        Some(name.to_ascii_uppercase())
    }
}

/// Describes a line for "swallowed" lists: its card keyword or namelist.
fn card_label(line: &str) -> String {
    let t = line.trim();
    if let Some(n) = opens_namelist(t) {
        return format!("${n}");
    }
    let label: String = t.chars().take(24).collect();
    label
}

impl<'a> Reader<'a> {
    fn diag(
        &mut self,
        severity: Severity,
        (line, column): (usize, usize),
        card: Option<&str>,
        variable: Option<&str>,
        problem: DeckProblem,
        hint: Option<String>,
    ) {
        self.diags.push(Diagnostic {
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

    fn touch_case(&mut self, line: usize) {
        if self.case.first_line == 0 {
            self.case.first_line = line;
        }
    }

    fn run(mut self) -> RawDeck {
        if let Some(d) = self.missile_check() {
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
            let n = lines.len();
            let hint = format!("(last line of the deck is {n})");
            self.unterminated(open, vec!["the end of the deck".into()], &hint);
        }
        self.end_case(lines.len(), true);
        RawDeck {
            file: self.file.to_string(),
            cases: self.cases,
            diagnostics: self.diags,
        }
    }

    fn missile_check(&self) -> Option<Diagnostic> {
        for (i, l) in self.lines.iter().enumerate() {
            let t = l.trim();
            if let Some(n) = opens_namelist(t) {
                if schema::MISSILE_NAMELISTS.contains(&n.as_str()) {
                    return Some(Diagnostic {
                        severity: Severity::Error,
                        file: self.file.to_string(),
                        line: i + 1,
                        column: l.find(['$', '&']).map_or(1, |c| c + 1),
                        card: Some(n.clone()),
                        variable: None,
                        problem: DeckProblem::MissileDatcom { namelist: n },
                        hint: Some(
                            "run it with Missile DATCOM; Digital DATCOM describes aircraft with $BODY, $WGPLNF, $SYNTHS ...".into(),
                        ),
                    });
                }
            }
        }
        None
    }

    fn line(&mut self, n: usize, raw: &str, all: &[&str]) {
        let trimmed_all = raw.trim();
        if trimmed_all.is_empty() {
            if self.open.is_none() {
                self.note_dialect(n, 1, "a blank card");
            }
            return;
        }
        if is_comment(trimmed_all) {
            let col = raw.len() - raw.trim_start().len() + 1;
            self.note_dialect(n, col, "a DATCOM+ comment card");
            return;
        }
        let is_caseid =
            self.open.is_none() && trimmed_all.to_ascii_uppercase().starts_with("CASEID");
        let (text, had_bang) = if is_caseid {
            (raw, false)
        } else {
            strip_bang(raw)
        };
        if had_bang {
            let col = text.chars().count() + 1;
            self.note_dialect(n, col, "a trailing `!` comment");
        }
        if raw.starts_with(['$', '&']) {
            self.note_dialect(
                n,
                1,
                "a namelist starting in column 1 (the original needs column 1 blank)",
            );
        }
        if !is_caseid && text.chars().any(|c| c.is_ascii_lowercase()) {
            let col = text
                .find(|c: char| c.is_ascii_lowercase())
                .map_or(1, |c| text[..c].chars().count() + 1);
            self.note_dialect(n, col, "lower case (the original reads upper case only)");
        }
        if raw.contains('\t') {
            let col = raw.find('\t').map_or(1, |c| raw[..c].chars().count() + 1);
            self.note_dialect(n, col, "a TAB character");
        }
        let past: String = text.chars().skip(CARD_COLUMNS).collect();
        if !past.trim().is_empty() && !is_caseid {
            let card = self.open.as_ref().map(|o| o.name.clone());
            self.diag(
                Severity::Warning,
                (n, CARD_COLUMNS + 1),
                card.as_deref(),
                None,
                DeckProblem::PastColumn80 {
                    found: past.trim().chars().take(30).collect(),
                },
                Some("break the card into lines of at most 80 columns".into()),
            );
        }
        if self.open.is_some() {
            self.namelist_line(n, text, all);
        } else {
            self.outside_line(n, text);
        }
    }

    /// A line that begins something new (a control card or another namelist), which, met inside
    /// a namelist, means that namelist was never closed.
    fn begins_new(text: &str, n: usize) -> bool {
        let t = text.trim();
        if let Some(name) = opens_namelist(t) {
            return schema::namelist(&name).is_some();
        }
        parse_card(t, n).is_some()
    }

    fn namelist_line(&mut self, n: usize, text: &str, all: &[&str]) {
        if Self::begins_new(text, n) {
            let open = self
                .open
                .take()
                .expect("namelist_line is only called with an open namelist");
            // The original reads on to the next `$`: list the cards it would swallow.
            let mut swallowed = Vec::new();
            for l in all.iter().skip(n - 1) {
                let (l, _) = strip_bang(l);
                if l.trim().is_empty() || is_comment(l.trim()) {
                    continue;
                }
                swallowed.push(card_label(l));
                if l.contains('$') {
                    break;
                }
            }
            self.unterminated(open, swallowed, &format!("before line {n}"));
            self.outside_line(n, text);
            return;
        }
        let mut toks = Vec::new();
        lexer::lex_line(text, n, 1, &mut toks);
        self.feed(toks);
    }

    /// Adds tokens to the open namelist; a `$` closes it, and what follows is read on.
    fn feed(&mut self, toks: Vec<Token>) {
        let mut iter = toks.into_iter();
        while let Some(t) = iter.next() {
            match t.tok {
                Tok::Close => {
                    if let Some(open) = self.open.take() {
                        self.close(open);
                    }
                    let rest: Vec<Token> = iter.collect();
                    self.after_close(rest);
                    return;
                }
                Tok::Open(ref name) if schema::namelist(name).is_some() => {
                    if let Some(open) = self.open.take() {
                        let swallowed = vec![format!("${name} (line {})", t.line)];
                        self.unterminated(open, swallowed, &format!("before ${name}"));
                    }
                    self.start(name.clone(), t.line, t.column);
                }
                _ => {
                    if let Some(open) = self.open.as_mut() {
                        open.tokens.push(t);
                    }
                }
            }
        }
    }

    /// Tokens after a closing `$` on the same line.
    fn after_close(&mut self, rest: Vec<Token>) {
        let Some(first) = rest.first() else {
            return;
        };
        match &first.tok {
            Tok::Open(_) => self.feed_outside(rest),
            Tok::Close => {
                // `$$`: a doubled terminator; harmless.
                let tail: Vec<Token> = rest.into_iter().skip(1).collect();
                self.after_close(tail);
            }
            _ => {
                let found: Vec<String> = rest.iter().take(6).map(|t| t.tok.describe()).collect();
                let (l, c) = (first.line, first.column);
                self.diag(
                    Severity::Warning,
                    (l, c),
                    None,
                    None,
                    DeckProblem::TrailingText {
                        found: found.join(" "),
                    },
                    None,
                );
            }
        }
    }

    fn feed_outside(&mut self, toks: Vec<Token>) {
        let mut iter = toks.into_iter();
        if let Some(t) = iter.next() {
            if let Tok::Open(name) = &t.tok {
                self.start(name.clone(), t.line, t.column);
                self.feed(iter.collect());
            }
        }
    }

    fn start(&mut self, name: String, line: usize, column: usize) {
        self.touch_case(line);
        if schema::namelist(&name).is_none() {
            let hint = schema::nearest(&name, schema::namelists().keys().map(String::as_str))
                .map(|n| format!("did you mean ${n}?"));
            self.diag(
                Severity::Error,
                (line, column),
                Some(&name),
                None,
                DeckProblem::UnknownNamelist {
                    found: name.clone(),
                },
                hint,
            );
        }
        self.open = Some(Open {
            name,
            line,
            column,
            tokens: Vec::new(),
        });
    }

    fn outside_line(&mut self, n: usize, text: &str) {
        let trimmed = text.trim();
        let col = text.len() - text.trim_start().len() + 1;
        if trimmed.starts_with(['$', '&']) {
            let mut toks = Vec::new();
            lexer::lex_line(text, n, 1, &mut toks);
            match toks.first().map(|t| &t.tok) {
                Some(Tok::Open(_)) => self.feed_outside(toks),
                _ => self.diag(
                    Severity::Warning,
                    (n, col),
                    None,
                    None,
                    DeckProblem::TrailingText {
                        found: trimmed.chars().take(30).collect(),
                    },
                    Some("a `$` outside a namelist closes nothing".into()),
                ),
            }
            return;
        }
        match parse_card(trimmed, n) {
            Some(card) => self.card(n, col, card),
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
                        Some(&word),
                        DeckProblem::AssignmentOutsideNamelist {
                            found: trimmed.chars().take(30).collect(),
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
                            found: trimmed.chars().take(40).collect(),
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
        let c = &mut self.case.cards;
        match card {
            Card::CaseId(text) => self.case.caseid = Some(text),
            Card::NextCase => self.end_case(n, false),
            Card::Save => self.case.save = true,
            Card::Dim(d) => c.dim = Some(d),
            Card::Deriv(d) => c.deriv = Some(d),
            Card::Damp => c.damp = true,
            Card::Build => c.build = true,
            Card::Part => c.part = true,
            Card::Trim => c.trim = true,
            Card::Plot => c.plot = true,
            Card::PrintExtrap => c.print_extrap = true,
            Card::Namelist => c.namelist = true,
            Card::Dump(s) => c.dump.push(s),
            Card::Write(s) => {
                c.write.push(s);
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
                    found,
                },
                None,
            ),
        }
    }

    /// Reports a namelist never closed by `$`, then reads what it holds.
    fn unterminated(&mut self, open: Open, swallowed: Vec<String>, where_to_close: &str) {
        self.diag(
            Severity::Error,
            (open.line, open.column),
            Some(&open.name),
            None,
            DeckProblem::UnterminatedNamelist {
                namelist: open.name.clone(),
                opened_line: open.line,
                swallowed,
            },
            Some(format!("end ${} with `$` {where_to_close}", open.name)),
        );
        self.close(open);
    }

    /// Applies a closed namelist's assignments to the current case.
    fn close(&mut self, open: Open) {
        let Some(spec) = schema::namelist(&open.name) else {
            return;
        };
        if !self.seen.insert(open.name.clone()) {
            self.diag(
                Severity::Note,
                (open.line, open.column),
                Some(&open.name),
                None,
                DeckProblem::NamelistRepeated {
                    namelist: open.name.clone(),
                },
                None,
            );
        }
        // Symmetric and asymmetric flap data share storage in the original: reading one
        // clears the other.
        let rival = match open.name.as_str() {
            "SYMFLP" => Some("ASYFLP"),
            "ASYFLP" => Some("SYMFLP"),
            _ => None,
        };
        if let Some(rival) = rival {
            if self.case.namelists.remove(rival).is_some() {
                self.diag(Severity::Warning, (open.line, open.column),
                    Some(&open.name),
                    None,
                    DeckProblem::Case {
                        message: format!(
                            "${} replaces the ${rival} read before it: the two share storage in DATCOM, one flap kind per case",
                            open.name
                        ),
                    },
                    None,
                );
            }
        }
        let (assignments, problems) = namelist::parse_body(&open.tokens);
        for p in problems {
            self.diag(
                Severity::Error,
                (p.line, p.column),
                Some(&open.name),
                p.variable.as_deref(),
                p.problem,
                p.hint,
            );
        }
        self.case.namelists.entry(open.name.clone()).or_default();
        for a in assignments {
            self.assign(spec, &a);
        }
    }

    fn assign(&mut self, spec: &'static NamelistSpec, a: &namelist::Assignment) {
        let nl = spec.name.as_str();
        let Some(var) = spec.var(&a.name) else {
            let near = schema::nearest(&a.name, spec.vars.keys().map(String::as_str))
                .map(|n| format!("did you mean {n}?"))
                .or_else(|| {
                    schema::homes(&a.name).map(|h| format!("{} is a variable of {h}", a.name))
                });
            self.diag(
                Severity::Error,
                (a.line, a.column),
                Some(nl),
                Some(&a.name),
                DeckProblem::UnknownVariable {
                    namelist: nl.into(),
                    found: a.name.clone(),
                },
                near,
            );
            return;
        };
        let start = a.index.unwrap_or(1);
        let last = start + a.values.len().saturating_sub(1);
        if last > var.len {
            self.diag(
                Severity::Error,
                (a.line, a.column),
                Some(nl),
                Some(&a.name),
                DeckProblem::TooManyValues {
                    variable: a.name.clone(),
                    capacity: var.len,
                    given: a.values.len(),
                    last_index: last,
                },
                None,
            );
        }
        // Kind check, element by element.
        let mut bad: Option<String> = None;
        for lit in &a.values {
            match (var.kind, lit) {
                (Kind::Logical, Lit::Number { .. }) => bad = Some("a number".into()),
                (Kind::Real | Kind::Integer, Lit::Logical(_)) => bad = Some("a logical".into()),
                (Kind::Integer, Lit::Number { value, .. }) if value.fract() != 0.0 => {
                    bad = Some(format!("{value}"))
                }
                _ => {}
            }
        }
        if let Some(found) = bad {
            let expected = match var.kind {
                Kind::Logical => "a logical (.TRUE. or .FALSE.)",
                Kind::Integer => "a whole number",
                Kind::Real => "a number",
            };
            self.diag(
                Severity::Error,
                (a.line, a.column),
                Some(nl),
                Some(&a.name),
                DeckProblem::WrongKind {
                    variable: a.name.clone(),
                    expected: expected.into(),
                    found,
                },
                None,
            );
            return;
        }
        let reassigned = (start..=last.min(var.len))
            .any(|i| self.assigned.contains(&(nl, var.name.as_str(), i)));
        if reassigned {
            self.diag(
                Severity::Warning,
                (a.line, a.column),
                Some(nl),
                Some(&a.name),
                DeckProblem::Reassigned {
                    variable: a.name.clone(),
                },
                None,
            );
        }
        let values = self.case.namelists.entry(nl.to_string()).or_default();
        let entry = values
            .entry(a.name.clone())
            .or_insert_with(|| match var.kind {
                Kind::Logical => Value::Logicals(Vec::new()),
                Kind::Real | Kind::Integer => Value::Numbers(Vec::new()),
            });
        for (k, lit) in a.values.iter().enumerate() {
            let i = start + k;
            if i > var.len {
                break;
            }
            match (&mut *entry, lit) {
                (Value::Numbers(v), Lit::Number { value, .. }) => {
                    if v.len() < i {
                        v.resize(i, None);
                    }
                    v[i - 1] = Some(*value);
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
        self.case
            .origins
            .insert(format!("{nl}.{}", a.name), (a.line, a.column));
        for i in start..=last.min(var.len) {
            self.assigned.insert((nl, var.name.as_str(), i));
        }
    }

    /// Checks count variables against the arrays they count (NALPHA against ALSCHD, ...).
    fn check_counts(&mut self) {
        let mut found = Vec::new();
        for (nl, values) in &self.case.namelists {
            let Some(spec) = schema::namelist(nl) else {
                continue;
            };
            for (name, value) in values {
                let Some(var) = spec.var(name) else { continue };
                let Some(count_var) = &var.count else {
                    continue;
                };
                // Counts in another namelist (`NMACH(FLTCON)` for per-Mach section data,
                // `NALPHA(FLTCON)` for experimental data) mark optional per-condition inputs:
                // fewer values than conditions is normal there.
                if count_var.contains('(') {
                    continue;
                }
                let Some(count) = values.get(count_var).and_then(Value::scalar) else {
                    continue;
                };
                let given = value.leading_count();
                if count.fract() != 0.0 || count < 0.0 || count > var.len as f64 {
                    found.push((
                        nl.clone(),
                        count_var.clone(),
                        DeckProblem::WrongKind {
                            variable: count_var.clone(),
                            expected: format!("a whole number from 0 to {}", var.len),
                            found: format!("{count}"),
                        },
                        None,
                    ));
                } else if (given as f64) < count {
                    found.push((
                        nl.clone(),
                        name.clone(),
                        DeckProblem::CountMismatch {
                            count_variable: count_var.clone(),
                            count,
                            variable: name.clone(),
                            given,
                        },
                        Some(format!(
                            "give {count} values of {name} or set {count_var}={given}.0; only the {given} given are used here, the original reads the others as zero"
                        )),
                    ));
                }
            }
        }
        let line = self.case.first_line;
        for (nl, var, problem, hint) in found {
            // The original runs such a case, reading the missing values as zero (for angles of
            // attack it prints a row of NDM); we use the values given, and say so.
            let severity = match problem {
                DeckProblem::CountMismatch { .. } => Severity::Warning,
                _ => Severity::Error,
            };
            self.diag(severity, (line, 0), Some(&nl), Some(&var), problem, hint);
        }
    }

    /// Closes the current case (at NEXT CASE or the end of the deck) and starts the next one,
    /// carrying the namelists and airfoil cards over when the case had SAVE.
    fn end_case(&mut self, line: usize, at_end: bool) {
        let _ = line;
        if self.case.is_empty() {
            if !at_end {
                // NEXT CASE with nothing before it: nothing to close.
                self.case = RawCase::default();
            }
            return;
        }
        self.check_counts();
        let mut next = RawCase::default();
        if self.case.save {
            next.namelists = self.case.namelists.clone();
            next.airfoils = self.case.airfoils.clone();
        }
        // DIM and DERIV stay in force for every later case, SAVE or not (the original keeps
        // them in global storage); every other control card belongs to its case.
        next.cards.dim = self.case.cards.dim;
        next.cards.deriv = self.case.cards.deriv;
        let done = std::mem::replace(&mut self.case, next);
        let mut done = done;
        done.number = self.cases.len() + 1;
        self.cases.push(done);
        self.assigned.clear();
        self.seen.clear();
    }
}

use cards::parse_card;

/// Reads a deck from text. `file` names it in diagnostics.
pub fn read(text: &str, file: &str) -> RawDeck {
    let reader = Reader {
        file,
        diags: Vec::new(),
        cases: Vec::new(),
        case: RawCase::default(),
        assigned: BTreeSet::new(),
        seen: BTreeSet::new(),
        open: None,
        lines: split_lines(text),
    };
    reader.run()
}
