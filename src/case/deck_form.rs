//! A typed case written back as the namelists and cards of a deck (in the case's units): so
//! that a case built in code can be checked as a deck is, and written as a deck for the
//! original program or for keeping.

use std::collections::BTreeMap;

use super::scalars::NamedScalars;
use super::{units, Case, Loop, Planform, SectionInput, PLANFORMS, SECTION_NAMELISTS};
use crate::deck::cards::{DerivUnit, Dim};
use crate::deck::schema::{self, Dimension};
use crate::deck::{NamelistValues, RawCase, Value};

/// How many floats on each side of the nearest deck value are tried.
const NEIGHBOURS: u64 = 4;

/// The floats next to `x`, nearest first (none for 0 or a value that is not finite).
fn neighbours(x: f64) -> impl Iterator<Item = f64> {
    let bits = x.to_bits();
    let finite = x.is_finite() && x != 0.0;
    (1..=NEIGHBOURS)
        .filter(move |_| finite)
        // Below the least positive float the bits run out (found by fuzzing the library: a
        // value of 1e-323 in feet panicked in a debug build).
        .flat_map(move |k| [bits.checked_add(k), bits.checked_sub(k)])
        .flatten()
        .map(f64::from_bits)
        .filter(|v| v.is_finite())
}

/// The most significant digits a written value is tried with (an f64 needs 17).
const SIGNIFICANT_DIGITS: usize = 17;

/// The namelists of one case being written, in the case's units.
struct Namelists<'a> {
    case: &'a Case,
    /// SYNTHS SCALE as the case applies it (1 without).
    scale: f64,
    out: BTreeMap<String, NamelistValues>,
}

impl Namelists<'_> {
    /// `si` in the deck's units of `nl`'s `var`: the inverse of reading it (the unit of the
    /// case's DIM, and SCALE for the geometry the schema marks as scaled), as the shortest
    /// decimal that reads back to `si` exactly (184.0, not 184.00000000000003), else a value
    /// next to the nearest that does, else the nearest.
    fn deck_units(&self, nl: &str, var: &str, si: f64) -> f64 {
        let Some(spec) = schema::table(nl).and_then(|t| t.var(var)) else {
            return si;
        };
        let scale = match spec.dimension {
            Dimension::Length if spec.scaled => self.scale,
            Dimension::Area if spec.scaled => self.scale * self.scale,
            _ => 1.0,
        };
        let (dim, dimension) = (self.case.dim, spec.dimension);
        let deck = units::from_si(si / scale, dim, dimension);
        let read = |d: f64| units::to_si(d, dim, dimension) * scale;
        // The shortest decimal, else a neighbour of the nearest value, that reads back exactly.
        (1..=SIGNIFICANT_DIGITS)
            .filter_map(|digits| format!("{deck:.*e}", digits - 1).parse::<f64>().ok())
            .chain(neighbours(deck))
            .find(|&d| read(d) == si)
            .unwrap_or(deck)
    }

    fn put(&mut self, nl: &str, var: &str, value: Value) {
        self.out
            .entry(nl.to_string())
            .or_default()
            .insert(var.to_string(), value);
    }

    /// An array (nothing when empty), converted from SI.
    fn array(&mut self, nl: &str, var: &str, si: &[f64]) {
        if si.is_empty() {
            return;
        }
        let v = si
            .iter()
            .map(|&x| Some(self.deck_units(nl, var, x)))
            .collect();
        self.put(nl, var, Value::Numbers(v));
    }

    fn real(&mut self, nl: &str, var: &str, si: Option<f64>) {
        if let Some(x) = si {
            self.array(nl, var, &[x]);
        }
    }

    /// A count (NMACH, NALPHA, NX ...) of `n` values; nothing for none.
    fn count(&mut self, nl: &str, var: &str, n: usize) {
        if n > 0 {
            self.put(nl, var, Value::Numbers(vec![Some(n as f64)]));
        }
    }

    /// A value written as it is (no unit: SCALE itself).
    fn put_plain(&mut self, nl: &str, var: &str, value: Option<f64>) {
        if let Some(x) = value {
            self.put(nl, var, Value::Numbers(vec![Some(x)]));
        }
    }

    fn logical(&mut self, nl: &str, var: &str, value: Option<bool>) {
        if let Some(b) = value {
            self.put(nl, var, Value::Logicals(vec![Some(b)]));
        }
    }

    /// Touches a namelist so that it is present (the case has it) even with no value.
    fn present(&mut self, nl: &str) {
        self.out.entry(nl.to_string()).or_default();
    }

    fn flight(&mut self) {
        let Some(f) = &self.case.flight else {
            return;
        };
        const NL: &str = "FLTCON";
        self.present(NL);
        self.count(NL, "NMACH", f.mach.len().max(f.velocity.len()));
        // NALT as the deck had it (without it, LOOP=1 does not check it against NMACH).
        if f.nalt_given {
            self.count(NL, "NALT", f.altitude.len().max(f.pressure.len()));
        }
        self.count(NL, "NALPHA", f.alpha_deg.len());
        for (var, v) in f.arrays() {
            self.array(NL, var, v);
        }
        let loop_mode = match f.loop_mode {
            Loop::Together => None,
            Loop::AltitudeOuter => Some(2.0),
            Loop::MachOuter => Some(3.0),
        };
        self.real(NL, "LOOP", loop_mode);
        for (var, v) in f.scalars() {
            self.real(NL, var, v);
        }
        self.real(NL, "TR", f.transition_strips.then_some(1.0));
        self.logical(NL, "HYPERS", f.hypersonic.then_some(true));
    }

    fn reference(&mut self) {
        const NL: &str = "OPTINS";
        for (var, v) in self.case.reference.scalars() {
            self.real(NL, var, v);
        }
    }

    fn synthesis(&mut self) {
        const NL: &str = "SYNTHS";
        let Some(s) = &self.case.synthesis else {
            // SCALE lives in $SYNTHS: a scaled case without one gets one for it.
            if self.scale != 1.0 {
                self.put_plain(NL, "SCALE", Some(self.scale));
            }
            return;
        };
        self.present(NL);
        for (var, v) in s.scalars().filter(|(var, _)| *var != "SCALE") {
            self.real(NL, var, v);
        }
        // The scale the case applies ([`Case::scale`]), given where the case gives one.
        let scale = (s.scale.is_some() || self.scale != 1.0).then_some(self.scale);
        self.put_plain(NL, "SCALE", scale);
        // Up is the default.
        self.logical(NL, "VERTUP", (!s.vertup).then_some(false));
    }

    fn body(&mut self) {
        let Some(b) = &self.case.body else {
            return;
        };
        const NL: &str = "BODY";
        self.present(NL);
        self.count(NL, "NX", b.x.len());
        for (var, v) in b.arrays() {
            self.array(NL, var, v);
        }
        for (var, v) in b.scalars() {
            self.real(NL, var, v);
        }
    }

    fn planform(&mut self, nl: &str, p: &Planform) {
        self.present(nl);
        for (var, v) in p.scalars() {
            self.real(nl, var, v);
        }
    }

    fn section(&mut self, nl: &str, s: &SectionInput) {
        self.present(nl);
        // Scalars are kept as the deck gives them.
        for (var, &x) in &s.scalars {
            self.put(nl, var, Value::Numbers(vec![Some(x)]));
        }
        if !s.scalars.contains_key("NPTS") {
            self.count(nl, "NPTS", s.xcord.len());
        }
        for (var, v) in s.arrays() {
            self.array(nl, var, v);
        }
        for (var, v) in &s.per_mach {
            self.array(nl, var, v);
        }
        self.logical(nl, "CAMBER", s.camber);
    }

    fn twin_panels(&mut self) {
        let Some(t) = &self.case.twin_panels else {
            return;
        };
        const NL: &str = "TVTPAN";
        self.present(NL);
        for (var, v) in t.scalars() {
            self.real(NL, var, v);
        }
    }

    fn larwb(&mut self) {
        let Some(l) = &self.case.larwb else {
            return;
        };
        const NL: &str = "LARWB";
        self.present(NL);
        for (var, v) in l.scalars() {
            self.real(NL, var, v);
        }
        self.logical(NL, "BLF", l.blf);
        self.logical(NL, "ROUNDN", l.roundn);
    }
}

impl Case {
    /// The case as a deck gives it: its namelists in the case's units (`dim`, and SYNTHS
    /// SCALE for the scaled geometry), its control and airfoil cards. Written with
    /// [`crate::deck::writer::write_case`] it is a deck for the original program; read back
    /// ([`Case::from_raw`]) it is this case again, up to the rounding of the unit conversion
    /// (and, as text, of a value that needs more than the 11 characters the original reads:
    /// the writer rounds it to 6 significant digits or more for magnitudes from 1e-9 to
    /// 1e10).
    /// A case built in code is checked as a deck is with [`Case::diagnose`].
    pub fn to_raw(&self) -> RawCase {
        let scale = Some(self.scale)
            .filter(|s| *s > 0.0 && s.is_finite())
            .unwrap_or(1.0);
        let mut n = Namelists {
            case: self,
            scale,
            out: BTreeMap::new(),
        };
        n.flight();
        n.reference();
        n.synthesis();
        n.body();
        for ((pl, _), p) in PLANFORMS.iter().zip([
            &self.wing,
            &self.horizontal_tail,
            &self.vertical_tail,
            &self.ventral_fin,
        ]) {
            if let Some(p) = p {
                n.planform(pl, p);
            }
        }
        for (sc, surface) in SECTION_NAMELISTS {
            if let Some(s) = self.sections.get(surface.name()) {
                n.section(sc, s);
            }
        }
        n.twin_panels();
        n.larwb();
        let mut namelists = n.out;
        // The namelists kept as read, unless typed here too ($LARWB is both: the typed values
        // are the ones the methods use, and an edit of them is what is written).
        for (name, values) in &self.other {
            namelists
                .entry(name.clone())
                .or_insert_with(|| values.clone());
        }
        if self.larwb.is_none() {
            namelists.remove("LARWB");
        }
        // DIM and DERIV cards for the case's units (a card kept from the deck could say
        // other units than the values are written in).
        let mut cards = self.cards.clone();
        if cards.dim.is_some() || self.dim != Dim::default() {
            cards.dim = Some(self.dim);
        }
        if cards.deriv.is_some() || self.deriv != DerivUnit::default() {
            cards.deriv = Some(self.deriv);
        }
        RawCase {
            number: self.number,
            first_line: self.first_line,
            caseid: self.caseid.clone(),
            namelists,
            cards,
            airfoils: self.airfoils.clone(),
            save: self.save,
            origins: Default::default(),
        }
    }

    /// What `datcom-rs check` says of this case's deck: the deck [`Case::to_raw`] gives,
    /// written ([`crate::deck::writer::write_case`]) and read (reader and case checks, with
    /// the library's default reading rules). For a case built in code, what a deck with its
    /// values would be told: errors where the methods refuse part of it, a value that is not a
    /// number, more values than an array holds, text beyond column 80 the original would not
    /// read. The places are lines of that written deck.
    ///
    /// A value that is not a number cannot be written: each is an error naming its namelist,
    /// variable and element (line 0), and the deck is read without it. So is a finite value
    /// too large for the deck's units (a length of 1e307 m in inches).
    pub fn diagnose(&self) -> Vec<crate::error::Diagnostic> {
        use crate::error::{DeckProblem, Diagnostic, Severity};
        let error = |v: &NotANumber, message: String| Diagnostic {
            severity: Severity::Error,
            file: "case".into(),
            line: 0,
            column: 0,
            card: v.namelist.clone(),
            variable: Some(v.variable.clone()),
            problem: DeckProblem::Physical { message },
            hint: None,
        };
        let own = self.values_not_numbers();
        let mut found: Vec<Diagnostic> = own
            .iter()
            .map(|v| error(v, format!("{}: not a number", v.assignment())))
            .collect();
        // The deck gives the scale the case applies; one that cannot be used is taken as 1
        // (one that is not a number is listed above).
        if let Some(why) =
            crate::results::why_the_scale_is_not_used(self).filter(|_| self.scale.is_finite())
        {
            let scale = NotANumber::scalar("SYNTHS", "SCALE", self.scale);
            found.push(error(
                &scale,
                format!("{}: {why}, taken as 1", scale.assignment()),
            ));
        }
        let mut raw = self.to_raw();
        for v in without_values_not_numbers(&mut raw.namelists) {
            let the_case_s = own
                .iter()
                .any(|o| o.namelist == v.namelist && o.variable == v.variable);
            if !the_case_s {
                found.push(error(
                    &v,
                    format!(
                        "{}: too large for the deck's units, it cannot be written",
                        v.assignment()
                    ),
                ));
            }
        }
        let text = crate::deck::writer::write_case(&raw);
        found.extend(crate::read_deck(&text, "case").diagnostics);
        found
    }

    /// The input values of this case that are not numbers (NaN or ±inf), by namelist,
    /// variable and element as its deck gives them, with their values; none for a case read
    /// from a deck.
    pub fn values_not_numbers(&self) -> Vec<NotANumber> {
        let Some(first) = super::finite::first_value_not_a_number(self) else {
            return Vec::new();
        };
        let mut found = Vec::new();
        self.each_value_not_a_number(|v| found.push(v));
        if found.is_empty() {
            // A field the lists below do not hold (none is known).
            found.push(NotANumber::outside_the_deck(first));
        }
        found
    }

    /// Gives each input value that is not a number to `each`, namelist by namelist.
    fn each_value_not_a_number(&self, mut each: impl FnMut(NotANumber)) {
        let mut scalars = |nl: &str, values: &mut dyn Iterator<Item = (&str, Option<f64>)>| {
            for (var, v) in values {
                if let Some(bad) = v.filter(|x| !x.is_finite()) {
                    each(NotANumber::scalar(nl, var, bad));
                }
            }
        };
        let f = self.flight.as_ref();
        scalars("FLTCON", &mut f.into_iter().flat_map(|f| f.scalars()));
        scalars("OPTINS", &mut self.reference.scalars());
        let synthesis = self.synthesis.as_ref();
        scalars(
            "SYNTHS",
            &mut synthesis.into_iter().flat_map(|s| s.scalars()),
        );
        scalars("SYNTHS", &mut std::iter::once(("SCALE", Some(self.scale))));
        scalars("BODY", &mut self.body.iter().flat_map(|b| b.scalars()));
        let planforms = [
            &self.wing,
            &self.horizontal_tail,
            &self.vertical_tail,
            &self.ventral_fin,
        ];
        for ((nl, _), p) in PLANFORMS.iter().zip(planforms) {
            scalars(nl, &mut p.iter().flat_map(|p| p.scalars()));
        }
        scalars(
            "TVTPAN",
            &mut self.twin_panels.iter().flat_map(|t| t.scalars()),
        );
        scalars("LARWB", &mut self.larwb.iter().flat_map(|l| l.scalars()));
        for (nl, surface) in SECTION_NAMELISTS {
            let Some(s) = self.sections.get(surface.name()) else {
                continue;
            };
            let given = s.scalars.iter().map(|(var, v)| (var.as_str(), Some(*v)));
            scalars(nl, &mut given.collect::<Vec<_>>().into_iter());
        }
        // Arrays, element by element.
        let mut arrays = |nl: &str, values: &mut dyn Iterator<Item = (&str, &[f64])>| {
            for (var, v) in values {
                for (k, &x) in v.iter().enumerate().filter(|(_, x)| !x.is_finite()) {
                    each(NotANumber::element(nl, var, k, x));
                }
            }
        };
        arrays("FLTCON", &mut f.into_iter().flat_map(|f| f.arrays()));
        arrays("BODY", &mut self.body.iter().flat_map(|b| b.arrays()));
        for (nl, surface) in SECTION_NAMELISTS {
            let Some(s) = self.sections.get(surface.name()) else {
                continue;
            };
            arrays(nl, &mut s.arrays());
            let per_mach = s
                .per_mach
                .iter()
                .map(|(var, v)| (var.as_str(), v.as_slice()));
            arrays(nl, &mut per_mach.collect::<Vec<_>>().into_iter());
        }
        // The namelists kept as read (found only on a copy: the case is left as it is).
        for v in without_values_not_numbers(&mut self.other.clone()) {
            each(v);
        }
    }

    /// This case without its optional values that are not numbers (NaN or ±inf, which no deck
    /// can give), as a deck without them: each is not given. Those values are returned, and
    /// then those left in place; none when the case has none (always for a case read from a
    /// deck). An array's element that is not a number is left in place: what reads the array
    /// refuses it and says so (a flight condition, a body, a section's coordinates), as a
    /// value of a section's per-Mach input that is not a number is not given for its Mach
    /// number.
    pub(crate) fn without_scalars_not_numbers(&self) -> Option<NotNumbersTakenOut> {
        super::finite::first_value_not_a_number(self)?;
        let mut case = self.clone();
        let mut found = Vec::new();
        let mut take = |nl: &str, values: &mut dyn Iterator<Item = (&str, &mut Option<f64>)>| {
            for (var, v) in values {
                if let Some(bad) = v.filter(|x| !x.is_finite()) {
                    *v = None;
                    found.push(NotANumber::scalar(nl, var, bad));
                }
            }
        };
        if let Some(f) = case.flight.as_mut() {
            take("FLTCON", &mut f.scalars_mut());
        }
        take("OPTINS", &mut case.reference.scalars_mut());
        if let Some(s) = case.synthesis.as_mut() {
            take("SYNTHS", &mut s.scalars_mut());
        }
        if let Some(b) = case.body.as_mut() {
            take("BODY", &mut b.scalars_mut());
        }
        let planforms = [
            &mut case.wing,
            &mut case.horizontal_tail,
            &mut case.vertical_tail,
            &mut case.ventral_fin,
        ];
        for ((nl, _), p) in PLANFORMS.iter().zip(planforms) {
            if let Some(p) = p.as_mut() {
                take(nl, &mut p.scalars_mut());
            }
        }
        if let Some(t) = case.twin_panels.as_mut() {
            take("TVTPAN", &mut t.scalars_mut());
        }
        if let Some(l) = case.larwb.as_mut() {
            take("LARWB", &mut l.scalars_mut());
        }
        for (nl, surface) in SECTION_NAMELISTS {
            if let Some(s) = case.sections.get_mut(surface.name()) {
                s.scalars.retain(|var, v| {
                    let keep = v.is_finite();
                    if !keep {
                        found.push(NotANumber::scalar(nl, var, *v));
                    }
                    keep
                });
            }
        }
        found.extend(without_values_not_numbers(&mut case.other));
        let left = case.values_not_numbers();
        Some(NotNumbersTakenOut {
            case,
            not_given: found,
            left,
        })
    }
}

/// A case without its optional values that are not numbers
/// ([`Case::without_scalars_not_numbers`]).
pub(crate) struct NotNumbersTakenOut {
    pub case: Case,
    /// The values taken out: not given.
    pub not_given: Vec<NotANumber>,
    /// The values left in place: the elements of arrays, refused where they are read.
    pub left: Vec<NotANumber>,
}

/// A value of a case that is not a number, where its deck would give it.
#[derive(Debug, Clone, PartialEq)]
pub struct NotANumber {
    /// The namelist; none for a field of the case that its deck has no place for.
    pub namelist: Option<String>,
    /// The deck's variable name; for a field its deck has no place for, its path in the case
    /// (`body.r[2]`, counted from 0 as in Rust).
    pub variable: String,
    /// The element (from 1, as the deck counts) of an array; none for a scalar.
    pub element: Option<usize>,
    pub value: f64,
}

impl NotANumber {
    fn scalar(nl: &str, var: &str, value: f64) -> NotANumber {
        NotANumber {
            namelist: Some(nl.to_string()),
            variable: var.to_string(),
            element: None,
            value,
        }
    }

    /// Element `k` (from 0) of an array.
    fn element(nl: &str, var: &str, k: usize, value: f64) -> NotANumber {
        NotANumber {
            element: Some(k + 1),
            ..NotANumber::scalar(nl, var, value)
        }
    }

    /// The first value found by the walk of the case's fields, when the deck has no place
    /// for it.
    fn outside_the_deck((path, value): (String, f64)) -> NotANumber {
        NotANumber {
            namelist: None,
            variable: path,
            element: None,
            value,
        }
    }

    /// `VAR = value` or `VAR(k) = value`.
    pub fn assignment(&self) -> String {
        match self.element {
            Some(k) => format!("{}({k}) = {}", self.variable, self.value),
            None => format!("{} = {}", self.variable, self.value),
        }
    }
}

impl std::fmt::Display for NotANumber {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match &self.namelist {
            Some(nl) => write!(f, "${nl} {}", self.assignment()),
            None => write!(f, "{} (not in its deck)", self.assignment()),
        }
    }
}

/// Takes every value that is not a number out of `namelists` (not given, as a deck's reader
/// leaves a number it cannot read) and returns them, in the namelists' order; a value alone
/// is named as a scalar, as a deck gives it.
fn without_values_not_numbers(namelists: &mut BTreeMap<String, NamelistValues>) -> Vec<NotANumber> {
    let mut found = Vec::new();
    for (nl, values) in namelists {
        for (var, value) in values.iter_mut() {
            let Value::Numbers(v) = value else { continue };
            let alone = v.len() == 1;
            for (k, x) in v.iter_mut().enumerate() {
                if let Some(bad) = x.filter(|x| !x.is_finite()) {
                    *x = None;
                    found.push(if alone {
                        NotANumber::scalar(nl, var, bad)
                    } else {
                        NotANumber::element(nl, var, k, bad)
                    });
                }
            }
        }
    }
    found
}
