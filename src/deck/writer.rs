//! Writing cases back as deck text that both this reader and the original program accept:
//! control cards from column 1, namelists as ` $NAME` with assignments on cards of at most 80
//! columns, numbers of at most 11 characters (the most the original reads) that read back to
//! the same `f64` where 11 characters hold it.

use super::cards::{DerivUnit, Dim, NacaSeries, Surface};
use super::{RawCase, Value, CARD_COLUMNS, NUMBER_CHARACTERS};

/// A number as the shortest text that reads back to the same value, always with a decimal
/// point or exponent so that it reads as REAL; when that text is longer than the original
/// reads ([`NUMBER_CHARACTERS`]), the nearest decimal of at most that many characters: 6
/// significant digits or more for magnitudes from 1e-9 to 1e10 (the original's REAL holds
/// about 7), as few as 4 for a negative number with a three-digit exponent.
pub fn number(v: f64) -> String {
    let exact = shortest(v);
    if exact.len() <= NUMBER_CHARACTERS || !v.is_finite() {
        return exact;
    }
    // A rounding that overflows (|v| near f64::MAX) is not a number: the exact text then.
    (1..=17)
        .rev()
        .map(|digits| with_digits(v, digits))
        .find(|s| s.len() <= NUMBER_CHARACTERS && s.parse::<f64>().is_ok_and(f64::is_finite))
        .unwrap_or(exact)
}

/// The shortest text that reads back to `v` exactly, as REAL.
fn shortest(v: f64) -> String {
    let s = format!("{v:?}");
    let fixed = if s.contains(['.', 'e', 'E']) {
        s.replace('e', "E")
    } else {
        format!("{s}.0")
    };
    // Rust writes 1e16 and up in full: the exponent form is shorter there.
    let exponent = exponent_form(&format!("{v:e}"));
    if exponent.len() < fixed.len() && exponent.parse::<f64>() == Ok(v) {
        exponent
    } else {
        fixed
    }
}

/// `v` rounded to `digits` significant digits, in the shorter of fixed and exponent form.
fn with_digits(v: f64, digits: usize) -> String {
    let exponent = exponent_form(&format!("{v:.*e}", digits - 1));
    let magnitude = if v == 0.0 {
        0
    } else {
        v.abs().log10().floor() as i64
    };
    let decimals = (digits as i64 - 1 - magnitude).max(0) as usize;
    let fixed = trim_zeros(&format!("{v:.decimals$}"));
    if fixed.len() <= exponent.len() && fixed.parse::<f64>().ok() == exponent.parse::<f64>().ok() {
        fixed
    } else {
        exponent
    }
}

/// Rust's `1.2300e5` as `1.23E5` (a mantissa with a decimal point, so that it reads as REAL).
fn exponent_form(s: &str) -> String {
    let (mantissa, exp) = s.split_once('e').unwrap_or((s, "0"));
    let mantissa = trim_zeros(mantissa);
    format!("{mantissa}E{exp}")
}

/// `1.2300` as `1.23`, `5.000` and `5` as `5.0`.
fn trim_zeros(s: &str) -> String {
    if !s.contains('.') {
        return format!("{s}.0");
    }
    let t = s.trim_end_matches('0');
    if t.ends_with('.') {
        format!("{t}0")
    } else {
        t.to_string()
    }
}

fn surface_letter(s: Surface) -> char {
    match s {
        Surface::Wing => 'W',
        Surface::HorizontalTail => 'H',
        Surface::VerticalTail => 'V',
        Surface::VentralFin => 'F',
    }
}

fn series_letter(s: NacaSeries) -> char {
    match s {
        NacaSeries::One => '1',
        NacaSeries::Four => '4',
        NacaSeries::Five => '5',
        NacaSeries::Six => '6',
        NacaSeries::Supersonic => 'S',
    }
}

/// Items of one variable: `NAME(i)=v,v,...` groups, one per run of assigned elements.
fn items(name: &str, value: &Value) -> Vec<String> {
    let mut out = Vec::new();
    let texts: Vec<Option<String>> = match value {
        Value::Numbers(v) => v.iter().map(|x| x.map(number)).collect(),
        Value::Logicals(v) => v
            .iter()
            .map(|x| {
                x.map(|b| {
                    if b {
                        ".TRUE.".to_string()
                    } else {
                        ".FALSE.".to_string()
                    }
                })
            })
            .collect(),
    };
    let mut i = 0;
    while i < texts.len() {
        if texts[i].is_none() {
            i += 1;
            continue;
        }
        let start = i;
        let mut run = Vec::new();
        while let Some(Some(t)) = texts.get(i) {
            run.push(t.clone());
            i += 1;
        }
        let head = if texts.len() == 1 {
            format!("{name}=")
        } else {
            format!("{name}({})=", start + 1)
        };
        // The head goes with the first value; every value is its own item so that cards can
        // break between values.
        let mut first = true;
        for t in run {
            if first {
                out.push(format!("{head}{t}"));
                first = false;
            } else {
                out.push(t);
            }
        }
    }
    out
}

/// Deck text for one case (without a closing NEXT CASE).
pub fn write_case(case: &RawCase) -> String {
    let mut out = String::new();
    let c = &case.cards;
    if let Some(d) = c.dim {
        let name = match d {
            Dim::Ft => "FT",
            Dim::In => "IN",
            Dim::M => "M",
            Dim::Cm => "CM",
        };
        out.push_str(&format!("DIM {name}\n"));
    }
    if let Some(d) = c.deriv {
        out.push_str(match d {
            DerivUnit::Deg => "DERIV DEG\n",
            DerivUnit::Rad => "DERIV RAD\n",
        });
    }
    for (flag, card) in [
        (c.damp, "DAMP"),
        (c.build, "BUILD"),
        (c.part, "PART"),
        (c.trim, "TRIM"),
        (c.plot, "PLOT"),
        (c.print_extrap, "PRINT EXTRAP"),
        (c.namelist, "NAMELIST"),
    ] {
        if flag {
            out.push_str(card);
            out.push('\n');
        }
    }
    for d in &c.dump {
        out.push_str(&format!("DUMP {d}\n"));
    }
    for (name, values) in &case.namelists {
        let mut card = format!(" ${name} ");
        let all: Vec<String> = values.iter().flat_map(|(k, v)| items(k, v)).collect();
        for (k, item) in all.iter().enumerate() {
            let sep = if k + 1 == all.len() { "$" } else { "," };
            if card.len() + item.len() + sep.len() > CARD_COLUMNS {
                out.push_str(card.trim_end());
                out.push('\n');
                card = "    ".to_string();
            }
            card.push_str(item);
            card.push_str(sep);
        }
        if all.is_empty() {
            card.push('$');
        }
        out.push_str(&card);
        out.push('\n');
    }
    for a in &case.airfoils {
        out.push_str(&format!(
            "NACA-{}-{}-{}\n",
            surface_letter(a.surface),
            series_letter(a.series),
            a.designation
        ));
    }
    if let Some(id) = &case.caseid {
        out.push_str(&format!("CASEID {id}\n"));
    }
    if case.save {
        out.push_str("SAVE\n");
    }
    out
}

/// Deck text for several cases, separated by NEXT CASE.
pub fn write_deck(cases: &[RawCase]) -> String {
    cases
        .iter()
        .map(write_case)
        .collect::<Vec<_>>()
        .join("NEXT CASE\n")
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The largest relative rounding of a number from 1e-9 to 1e10 that needs more than 11
    /// characters: an 11-character decimal holds at least 6 significant digits there
    /// (`-1.23457E-9`), half a unit of the sixth.
    const ROUNDING: f64 = 5e-6;

    #[test]
    fn numbers_fit_the_original_and_read_back() {
        for (v, text) in [
            (184.0, "184.0"),
            (0.5175000000000001, "0.5175"),
            (8.030000000000001, "8.03"),
            (1e-10, "1E-10"),
            (-2.5, "-2.5"),
            (123456789012.0, "1.234568E11"),
            (1e20, "1E20"),
        ] {
            assert_eq!(number(v), text, "{v:?}");
        }
        for v in [
            0.1 + 0.2,
            std::f64::consts::PI,
            -std::f64::consts::E * 1e-7,
            2.19456 / 0.3048,
            -123456.789012,
            -1.2345678901e-9,
            9.87654321012e9,
        ] {
            let s = number(v);
            let back: f64 = s.parse().expect("reads as a number");
            assert!(s.len() <= NUMBER_CHARACTERS, "{s}");
            assert!((back - v).abs() <= ROUNDING * v.abs(), "{v:?} written {s}");
        }
        // Exact wherever 11 characters hold the value.
        for v in [0.3048, 12.5, -1234.5678, 3.0e-8] {
            assert_eq!(number(v).parse::<f64>(), Ok(v));
        }
        // A rounding that would overflow is not taken.
        assert_eq!(number(-f64::MAX).parse::<f64>(), Ok(-f64::MAX));
    }
}
