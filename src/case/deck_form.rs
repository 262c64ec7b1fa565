//! A typed case written back as the namelists and cards of a deck (in the case's units): so
//! that a case built in code can be checked as a deck is, and written as a deck for the
//! original program or for keeping.

use std::collections::BTreeMap;

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
        .flat_map(move |k| [f64::from_bits(bits + k), f64::from_bits(bits - k)])
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
        self.array(NL, "MACH", &f.mach);
        self.array(NL, "VINF", &f.velocity);
        self.array(NL, "RNNUB", &f.reynolds_per_length);
        // NALT as the deck had it (without it, LOOP=1 does not check it against NMACH).
        if f.nalt_given {
            self.count(NL, "NALT", f.altitude.len().max(f.pressure.len()));
        }
        self.array(NL, "ALT", &f.altitude);
        self.array(NL, "PINF", &f.pressure);
        self.array(NL, "TINF", &f.temperature);
        self.count(NL, "NALPHA", f.alpha_deg.len());
        self.array(NL, "ALSCHD", &f.alpha_deg);
        let loop_mode = match f.loop_mode {
            Loop::Together => None,
            Loop::AltitudeOuter => Some(2.0),
            Loop::MachOuter => Some(3.0),
        };
        self.real(NL, "LOOP", loop_mode);
        self.real(NL, "WT", f.weight);
        self.real(NL, "GAMMA", f.gamma_deg);
        self.real(NL, "TR", f.transition_strips.then_some(1.0));
        self.real(NL, "STMACH", f.stmach);
        self.real(NL, "TSMACH", f.tsmach);
        self.logical(NL, "HYPERS", f.hypersonic.then_some(true));
    }

    fn reference(&mut self) {
        const NL: &str = "OPTINS";
        let r = &self.case.reference;
        for (var, v) in [
            ("SREF", r.area),
            ("CBARR", r.chord),
            ("BLREF", r.span),
            ("ROUGFC", r.roughness),
        ] {
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
        for (var, v) in [
            ("XCG", s.xcg),
            ("ZCG", s.zcg),
            ("XW", s.xw),
            ("ZW", s.zw),
            ("ALIW", s.aliw_deg),
            ("XH", s.xh),
            ("ZH", s.zh),
            ("ALIH", s.alih_deg),
            ("XV", s.xv),
            ("ZV", s.zv),
            ("XVF", s.xvf),
            ("ZVF", s.zvf),
            ("YV", s.yv),
            ("YF", s.yf),
            ("PHIV", s.phiv_deg),
            ("PHIF", s.phif_deg),
            ("HINAX", s.hinax),
        ] {
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
        for (var, v) in [
            ("X", &b.x),
            ("S", &b.s),
            ("P", &b.p),
            ("R", &b.r),
            ("ZU", &b.zu),
            ("ZL", &b.zl),
        ] {
            self.array(NL, var, v);
        }
        for (var, v) in [
            ("BNOSE", b.bnose),
            ("BTAIL", b.btail),
            ("BLN", b.bln),
            ("BLA", b.bla),
            ("DS", b.ds),
            ("ITYPE", b.itype),
            ("METHOD", b.method),
            ("ELLIP", b.ellip),
        ] {
            self.real(NL, var, v);
        }
    }

    fn planform(&mut self, nl: &str, p: &Planform) {
        self.present(nl);
        for (var, v) in [
            ("CHRDR", p.chrdr),
            ("CHRDBP", p.chrdbp),
            ("CHRDTP", p.chrdtp),
            ("SSPN", p.sspn),
            ("SSPNE", p.sspne),
            ("SSPNOP", p.sspnop),
            ("SSPNDD", p.sspndd),
            ("SAVSI", p.savsi_deg),
            ("SAVSO", p.savso_deg),
            ("CHSTAT", p.chstat),
            ("TWISTA", p.twista_deg),
            ("DHDADI", p.dhdadi_deg),
            ("DHDADO", p.dhdado_deg),
            ("TYPE", p.planform_type),
            ("SWAFP", p.swafp_deg),
        ] {
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
        for (var, v) in [
            ("XCORD", &s.xcord),
            ("YUPPER", &s.yupper),
            ("YLOWER", &s.ylower),
            ("MEAN", &s.mean),
            ("THICK", &s.thick),
        ] {
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
        for (var, v) in [
            ("BVP", t.bvp),
            ("BV", t.bv),
            ("BDV", t.bdv),
            ("BH", t.bh),
            ("SV", t.sv),
            ("VPHITE", t.vphite),
            ("VLP", t.vlp),
            ("ZP", t.zp),
        ] {
            self.real(NL, var, v);
        }
    }

    fn larwb(&mut self) {
        let Some(l) = &self.case.larwb else {
            return;
        };
        const NL: &str = "LARWB";
        self.present(NL);
        for (var, v) in [
            ("SREF", l.sref),
            ("L", l.length),
            ("XCG", l.xcg),
            ("ZB", l.zb),
            ("DELTEP", l.deltep_deg),
            ("SFRONT", l.sfront),
            ("AR", l.aspect_ratio),
            ("R3LEOB", l.r3leob),
            ("DELTAL", l.deltal_deg),
            ("SWET", l.swet),
            ("PERBAS", l.perbas),
            ("SBASE", l.sbase),
            ("HB", l.hb),
            ("BB", l.bb),
            ("THETAD", l.thetad_deg),
            ("SBS", l.sbs),
            ("SBSLB", l.sbslb),
            ("XCENSB", l.xcensb),
            ("XCENW", l.xcenw),
        ] {
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
    /// variable and element (line 0), and the deck is read without it.
    pub fn diagnose(&self) -> Vec<crate::error::Diagnostic> {
        use crate::error::{DeckProblem, Diagnostic, Severity};
        let mut raw = self.to_raw();
        let mut found: Vec<Diagnostic> = without_values_not_numbers(&mut raw)
            .into_iter()
            .map(|v| Diagnostic {
                severity: Severity::Error,
                file: "case".into(),
                line: 0,
                column: 0,
                card: Some(v.namelist.clone()),
                variable: Some(v.variable.clone()),
                problem: DeckProblem::Physical {
                    message: format!("{}: not a number", v.assignment()),
                },
                hint: None,
            })
            .collect();
        let text = crate::deck::writer::write_case(&raw);
        found.extend(crate::read_deck(&text, "case").diagnostics);
        found
    }

    /// The values of this case that are not numbers (NaN or ±inf), by namelist and variable
    /// as its deck ([`Case::to_raw`]) gives them; none for a case read from a deck.
    pub fn values_not_numbers(&self) -> Vec<NotANumber> {
        let Some(first) = super::finite::first_value_not_a_number(self) else {
            return Vec::new();
        };
        let found = without_values_not_numbers(&mut self.to_raw());
        if found.is_empty() {
            vec![NotANumber::outside_the_deck(first)]
        } else {
            found
        }
    }

    /// This case as its deck would be read without its values that are not numbers, and
    /// those values; `None` when it has none (always for a case read from a deck). The deck
    /// is this case's [`Case::to_raw`] with each such value not given, as a deck's reader
    /// leaves a number it cannot read; the reading rules, number and place are this case's.
    /// Lengths go through the deck's units and back, so they can differ from this case's in
    /// the last digit when its units are not metres.
    pub fn without_values_not_numbers(&self) -> Option<(Case, Vec<NotANumber>)> {
        let first = super::finite::first_value_not_a_number(self)?;
        let mut raw = self.to_raw();
        let mut found = without_values_not_numbers(&mut raw);
        if found.is_empty() {
            found.push(NotANumber::outside_the_deck(first));
        }
        let (read, _checks) = Case::from_raw(&raw, "case");
        Some((
            Case {
                number: self.number,
                first_line: self.first_line,
                section_reynolds: self.section_reynolds,
                five_digit: self.five_digit,
                section_maximum: self.section_maximum,
                six_a: self.six_a,
                zero_lift: self.zero_lift,
                forward_sweep: self.forward_sweep,
                tail_slope: self.tail_slope,
                outboard_section: self.outboard_section,
                jorgensen_drag: self.jorgensen_drag,
                ..read
            },
            found,
        ))
    }
}

/// A value of a case that is not a number, where its deck would give it.
#[derive(Debug, Clone, PartialEq)]
pub struct NotANumber {
    /// The namelist; empty for a field of the case that its deck has no place for (the
    /// variable is then the field's path in the case, `synthesis.scale`).
    pub namelist: String,
    pub variable: String,
    /// The element (from 1) of an array; none for a scalar.
    pub element: Option<usize>,
    pub value: f64,
}

impl NotANumber {
    /// The first value found by the walk of the case's fields, when the deck has no place
    /// for it.
    fn outside_the_deck((path, value): (String, f64)) -> NotANumber {
        NotANumber {
            namelist: String::new(),
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
        if self.namelist.is_empty() {
            write!(f, "{} (not in its deck)", self.assignment())
        } else {
            write!(f, "${} {}", self.namelist, self.assignment())
        }
    }
}

/// Takes every value that is not a number out of `raw`'s namelists (not given, as a deck's
/// reader leaves a number it cannot read) and returns them, in the namelists' order.
fn without_values_not_numbers(raw: &mut RawCase) -> Vec<NotANumber> {
    let mut found = Vec::new();
    for (nl, values) in &mut raw.namelists {
        for (var, value) in values.iter_mut() {
            let Value::Numbers(v) = value else { continue };
            let scalar = v.len() == 1;
            for (i, x) in v.iter_mut().enumerate() {
                if let Some(bad) = x.filter(|x| !x.is_finite()) {
                    *x = None;
                    found.push(NotANumber {
                        namelist: nl.clone(),
                        variable: var.clone(),
                        element: (!scalar).then_some(i + 1),
                        value: bad,
                    });
                }
            }
        }
    }
    found
}
