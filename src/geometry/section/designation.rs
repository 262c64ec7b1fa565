//! Reading NACA designations (the text of a NACA card after its series), and the designation
//! line the original prints above the coordinate table (AIRFOL, datcom.f lines 167-190).
//!
//! The original's DECODE (datcom.f lines 7120-7232) reads the card column by column into ten
//! digit slots and never refuses a card; here a designation is read as NACA writes it, and one
//! that names no section is refused with the reason (see docs/sections.md).

use super::SectionError;
use crate::deck::cards::NacaSeries;

const FOUR_FORM: &str =
    "4 digits MPTT, or MPTT-IM for the modified series (e.g. 0012, 2412, 0012-34)";
const FIVE_FORM: &str =
    "5 digits LPQTT, or LPQTT-IM for the modified series (e.g. 23012, 23112, 23012-33)";
const ONE_FORM: &str = "16-LTT (e.g. 16-212)";
const SIX_FORM: &str = "6S-LTT, 6S,K-LTT, 6SK-LTT, 6SALTT or 6S,KALTT, optionally followed by A=a (e.g. 63-012, 64,3-618, 643-618, 65A004, 64A204 A=0.8)";
const SUPERSONIC_FORM: &str = "type-ridge-thickness[-flat], lengths in percent of chord (e.g. 1-50.0-2.5, 2-50.0-5.0, 3-30.0-2.5-20.0)";

/// The two digits after the dash of a modified 4- or 5-digit designation.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Modification {
    /// Leading-edge radius index (6 = the 4-digit radius, 0 = sharp).
    pub le_index: u8,
    /// Position of maximum thickness, tenths of chord.
    pub max_thickness: u8,
}

/// A NACA designation, digit by digit as NACA defines them.
#[derive(Debug, Clone, PartialEq)]
pub(crate) enum Designation {
    /// MPTT[-IM]: camber in percent, its position in tenths, thickness in percent.
    FourDigit {
        camber: u8,
        position: u8,
        thickness: u8,
        modification: Option<Modification>,
    },
    /// LPQTT[-IM]: design lift coefficient in 0.15 steps, position of maximum camber in
    /// twentieths, reflex flag, thickness in percent.
    FiveDigit {
        lift: u8,
        position: u8,
        reflex: u8,
        thickness: u8,
        modification: Option<Modification>,
    },
    /// 1S-LTT: minimum-pressure position in tenths, design lift coefficient in tenths,
    /// thickness in percent.
    OneSeries { series: u8, lift: u8, thickness: u8 },
    /// 6S[,K]-LTT or 6S[,K]ALTT [A=a]: minimum-pressure position in tenths, low-drag range
    /// (0 when not written), 6A flag, design lift coefficient in tenths, thickness in percent,
    /// load extent of the mean line.
    SixSeries {
        series: u8,
        low_drag: u8,
        six_a: bool,
        lift: u8,
        thickness: u8,
        load_extent: Option<f64>,
    },
    /// S-T-R-T-F: type (1 double wedge, 2 biconvex, 3 hexagon), ridge position, thickness and
    /// flat length, all in percent of chord.
    Supersonic {
        kind: u8,
        ridge: f64,
        thickness: f64,
        flat: f64,
    },
}

/// The series as the error messages name it.
pub(crate) fn series_name(series: NacaSeries) -> &'static str {
    match series {
        NacaSeries::One => "1",
        NacaSeries::Four => "4",
        NacaSeries::Five => "5",
        NacaSeries::Six => "6",
        NacaSeries::Supersonic => "S",
    }
}

/// Reads `text` (blanks are ignored, letters may be lower case) as a designation of `series`.
pub(crate) fn parse(series: NacaSeries, text: &str) -> Result<Designation, SectionError> {
    let text: String = text
        .chars()
        .filter(|c| !c.is_whitespace())
        .collect::<String>()
        .to_ascii_uppercase();
    let form = |expected: &'static str| SectionError::Form {
        series: series_name(series),
        designation: text.clone(),
        expected,
    };
    match series {
        NacaSeries::Four => four_or_five(&text, 4).ok_or_else(|| form(FOUR_FORM)),
        NacaSeries::Five => four_or_five(&text, 5).ok_or_else(|| form(FIVE_FORM)),
        NacaSeries::One => one_series(&text).ok_or_else(|| form(ONE_FORM)),
        NacaSeries::Six => six_series(&text).ok_or_else(|| form(SIX_FORM)),
        NacaSeries::Supersonic => supersonic(&text).ok_or_else(|| form(SUPERSONIC_FORM)),
    }
}

/// The digits of `s`, when it is digits only.
fn digits(s: &str) -> Option<Vec<u8>> {
    s.bytes()
        .map(|b| b.is_ascii_digit().then(|| b - b'0'))
        .collect()
}

fn four_or_five(text: &str, count: usize) -> Option<Designation> {
    let (main, modified) = match text.split_once('-') {
        Some((main, after)) => (main, Some(after)),
        None => (text, None),
    };
    let d = digits(main).filter(|d| d.len() == count)?;
    let modification = match modified {
        None => None,
        Some(after) => match digits(after)?.as_slice() {
            [le_index, max_thickness] => Some(Modification {
                le_index: *le_index,
                max_thickness: *max_thickness,
            }),
            _ => return None,
        },
    };
    Some(if count == 4 {
        Designation::FourDigit {
            camber: d[0],
            position: d[1],
            thickness: 10 * d[2] + d[3],
            modification,
        }
    } else {
        Designation::FiveDigit {
            lift: d[0],
            position: d[1],
            reflex: d[2],
            thickness: 10 * d[3] + d[4],
            modification,
        }
    })
}

fn one_series(text: &str) -> Option<Designation> {
    let (head, tail) = text.split_once('-')?;
    match (digits(head)?.as_slice(), digits(tail)?.as_slice()) {
        ([1, series], [lift, t1, t2]) => Some(Designation::OneSeries {
            series: *series,
            lift: *lift,
            thickness: 10 * t1 + t2,
        }),
        _ => None,
    }
}

fn six_series(text: &str) -> Option<Designation> {
    let (body, load_extent) = match text.split_once("A=") {
        Some((body, a)) => (body, Some(fraction(a)?)),
        None => (text, None),
    };
    let b = body.as_bytes();
    if b.first() != Some(&b'6') {
        return None;
    }
    let series = digit(b.get(1))?;
    let mut i = 2;
    let mut low_drag = 0;
    if b.get(i) == Some(&b',') {
        low_drag = digit(b.get(i + 1))?;
        i += 2;
    } else if let (Some(k), Some(b'-' | b'A')) = (digit(b.get(i)), b.get(i + 1)) {
        low_drag = k;
        i += 1;
    }
    let six_a = match b.get(i) {
        Some(b'-') => false,
        Some(b'A') => true,
        _ => return None,
    };
    match digits(&body[i + 1..])?.as_slice() {
        [lift, t1, t2] => Some(Designation::SixSeries {
            series,
            low_drag,
            six_a,
            lift: *lift,
            thickness: 10 * t1 + t2,
            load_extent,
        }),
        _ => None,
    }
}

fn digit(b: Option<&u8>) -> Option<u8> {
    b.filter(|b| b.is_ascii_digit()).map(|b| b - b'0')
}

/// A plain decimal number: digits with at most one point.
fn fraction(s: &str) -> Option<f64> {
    let plain = !s.is_empty()
        && s.bytes().all(|b| b.is_ascii_digit() || b == b'.')
        && s.bytes().filter(|b| *b == b'.').count() <= 1
        && s != ".";
    plain.then(|| s.parse().ok()).flatten()
}

fn supersonic(text: &str) -> Option<Designation> {
    let text = text.strip_prefix("S-").unwrap_or(text);
    let mut parts = text.split('-');
    let kind = match digits(parts.next()?)?.as_slice() {
        [k] => *k,
        _ => return None,
    };
    let mut numbers = [0.0; 3];
    for slot in numbers.iter_mut() {
        match parts.next() {
            Some(p) => *slot = fraction(p)?,
            None => break,
        }
    }
    if parts.next().is_some() {
        return None;
    }
    let [ridge, thickness, flat] = numbers;
    Some(Designation::Supersonic {
        kind,
        ridge,
        thickness,
        flat,
    })
}

impl Designation {
    /// The designation line of the coordinate page, as the original prints it (AIRFOL formats
    /// 1110-1190 and 1270) without its leading blanks: `NACA 0012`, `NACA 0012 - 25`,
    /// `NACA 23014`, `NACA 16 - 212`, `NACA 64,3-618`, `NACA 65A004`,
    /// `NACA S-3-30.0-02.5-20.0`.
    pub(crate) fn title(&self) -> String {
        let modified = |m: &Option<Modification>| {
            m.map(|m| format!(" - {}{}", m.le_index, m.max_thickness))
                .unwrap_or_default()
        };
        match self {
            Designation::FourDigit {
                camber,
                position,
                thickness,
                modification,
            } => format!(
                "NACA {camber}{position}{thickness:02}{}",
                modified(modification)
            ),
            Designation::FiveDigit {
                lift,
                position,
                reflex,
                thickness,
                modification,
            } => format!(
                "NACA {lift}{position}{reflex}{thickness:02}{}",
                modified(modification)
            ),
            Designation::OneSeries {
                series,
                lift,
                thickness,
            } => format!("NACA 1{series} - {lift}{thickness:02}"),
            Designation::SixSeries {
                series,
                low_drag,
                six_a,
                lift,
                thickness,
                ..
            } => {
                let subscript = if *low_drag > 0 {
                    format!(",{low_drag}")
                } else {
                    String::new()
                };
                let separator = if *six_a { "A" } else { "-" };
                format!("NACA 6{series}{subscript}{separator}{lift}{thickness:02}")
            }
            Designation::Supersonic {
                kind,
                ridge,
                thickness,
                flat,
            } => {
                // The biconvex section has its ridge at mid chord whatever the card says
                // (AIRFOL lines 144-147).
                let ridge = if *kind == 2 { 50.0 } else { *ridge };
                format!("NACA S-{kind}-{ridge:04.1}-{thickness:04.1}-{flat:04.1}")
            }
        }
    }

    /// The second designation line: the mean line's load extent `A=0.8` (AIRFOL format 1200).
    pub(crate) fn subtitle(&self) -> Option<String> {
        match self {
            Designation::SixSeries {
                load_extent: Some(a),
                ..
            } => Some(if (a * 10.0).fract() == 0.0 {
                format!("A={a:.1}")
            } else {
                format!("A={a}")
            }),
            _ => None,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Characters below '0' among the digits are refused, not an overflow of the digit's value
    /// (a debug build panicked: the property test's mutated decks, once `check` read every
    /// designation).
    #[test]
    fn characters_below_zero_are_not_digits() {
        for text in ["0,12", "00.2", "0+12", "23 12", "6,-012", "1,-012"] {
            for series in [
                NacaSeries::One,
                NacaSeries::Four,
                NacaSeries::Five,
                NacaSeries::Six,
                NacaSeries::Supersonic,
            ] {
                let _ = parse(series, text);
            }
        }
        assert!(parse(NacaSeries::Four, "0,12").is_err());
    }

    fn title(series: NacaSeries, text: &str) -> String {
        parse(series, text).map(|d| d.title()).unwrap_or_default()
    }

    /// The designation lines of the oracle listings (coords.md section 3.3).
    #[test]
    fn titles_as_the_original_prints_them() {
        use NacaSeries::*;
        assert_eq!(title(Four, "0012"), "NACA 0012");
        assert_eq!(title(Four, "0012-25"), "NACA 0012 - 25");
        assert_eq!(title(Five, "23014"), "NACA 23014");
        assert_eq!(title(Five, "23012-33"), "NACA 23012 - 33");
        assert_eq!(title(One, "16-212"), "NACA 16 - 212");
        assert_eq!(title(Six, "643-618"), "NACA 64,3-618");
        assert_eq!(title(Six, "64,3-618"), "NACA 64,3-618");
        assert_eq!(title(Six, "631-012"), "NACA 63,1-012");
        assert_eq!(title(Six, "63-012"), "NACA 63-012");
        assert_eq!(title(Six, "65A004"), "NACA 65A004");
        assert_eq!(title(Six, "64,1A212"), "NACA 64,1A212");
        assert_eq!(
            title(Supersonic, "3-30.0-2.5-20.0"),
            "NACA S-3-30.0-02.5-20.0"
        );
        assert_eq!(title(Supersonic, "1-50.0-2.5"), "NACA S-1-50.0-02.5-00.0");
        assert_eq!(title(Supersonic, "2-40.0-5.0"), "NACA S-2-50.0-05.0-00.0");
        let d = parse(Six, "64A204A=0.8").unwrap();
        assert_eq!(d.title(), "NACA 64A204");
        assert_eq!(d.subtitle().as_deref(), Some("A=0.8"));
    }

    #[test]
    fn malformed_designations_say_what_is_expected() {
        use NacaSeries::*;
        for (series, text) in [
            (Four, "00121"),
            (Four, "0012-2"),
            (Five, "2301"),
            (One, "16212"),
            (Six, "64-21"),
            (Six, "74-212"),
            (Six, "64(3)-618"),
            (Six, "64A204A=x"),
            (Supersonic, "1-50.0-2.5-1-2"),
        ] {
            let e = parse(series, text).unwrap_err().to_string();
            assert!(e.contains("cannot be read: expected"), "{text}: {e}");
        }
    }
}
