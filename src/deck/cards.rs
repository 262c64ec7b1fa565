//! Control cards: CASEID, NEXT CASE, SAVE, DIM, DERIV, DAMP, BUILD, PART, TRIM, DUMP, PLOT,
//! PRINT EXTRAP, NAMELIST, WRITE and the NACA airfoil cards.

use serde::{Deserialize, Serialize};

/// Unit system of a case (the DIM card). Default FT.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
pub enum Dim {
    #[default]
    #[serde(rename = "FT")]
    Ft,
    #[serde(rename = "IN")]
    In,
    #[serde(rename = "M")]
    M,
    #[serde(rename = "CM")]
    Cm,
}

impl Dim {
    /// Metres per unit of length.
    pub fn metres(self) -> f64 {
        match self {
            Dim::Ft => 0.3048,
            Dim::In => 0.0254,
            Dim::M => 1.0,
            Dim::Cm => 0.01,
        }
    }

    /// True for the metric systems (M, CM), which take SI units for pressure, temperature and
    /// force; FT and IN take pounds and degrees Rankine.
    pub fn is_metric(self) -> bool {
        matches!(self, Dim::M | Dim::Cm)
    }

    pub fn name(self) -> &'static str {
        match self {
            Dim::Ft => "FT",
            Dim::In => "IN",
            Dim::M => "M",
            Dim::Cm => "CM",
        }
    }
}

/// Unit of printed derivatives (the DERIV card). Default DEG.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum DerivUnit {
    #[default]
    Deg,
    Rad,
}

/// Which lifting surface a NACA card describes.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Serialize, Deserialize)]
pub enum Surface {
    #[serde(rename = "W")]
    Wing,
    #[serde(rename = "H")]
    HorizontalTail,
    #[serde(rename = "V")]
    VerticalTail,
    #[serde(rename = "F")]
    VentralFin,
}

impl Surface {
    fn from_letter(c: &str) -> Option<Surface> {
        match c {
            "W" => Some(Surface::Wing),
            "H" => Some(Surface::HorizontalTail),
            "V" => Some(Surface::VerticalTail),
            "F" => Some(Surface::VentralFin),
            _ => None,
        }
    }

    /// Name as the original prints it on its SECTION DEFINITION pages.
    pub fn name(self) -> &'static str {
        match self {
            Surface::Wing => "WING",
            Surface::HorizontalTail => "HORIZONTAL TAIL",
            Surface::VerticalTail => "VERTICAL TAIL",
            Surface::VentralFin => "VENTRAL FIN",
        }
    }
}

/// NACA series of an airfoil card: 1, 4, 5, 6 or S (supersonic).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
pub enum NacaSeries {
    #[serde(rename = "1")]
    One,
    #[serde(rename = "4")]
    Four,
    #[serde(rename = "5")]
    Five,
    #[serde(rename = "6")]
    Six,
    #[serde(rename = "S")]
    Supersonic,
}

/// `NACA-W-4-0012` or `NACA W 4 0012`.
#[derive(Debug, Clone, PartialEq, Eq, Serialize, Deserialize)]
pub struct AirfoilCard {
    pub surface: Surface,
    pub series: NacaSeries,
    /// Designation as written after the series, e.g. `0012`, `631-012`, `65A010`.
    pub designation: String,
    pub line: usize,
}

impl AirfoilCard {
    /// The card of a NACA section for a case built in code (no deck line).
    pub fn new(surface: Surface, series: NacaSeries, designation: &str) -> AirfoilCard {
        AirfoilCard {
            surface,
            series,
            designation: designation.to_string(),
            line: 0,
        }
    }
}

/// The control cards of one case.
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
pub struct Cards {
    pub dim: Option<Dim>,
    pub deriv: Option<DerivUnit>,
    pub damp: bool,
    pub build: bool,
    pub part: bool,
    pub trim: bool,
    pub plot: bool,
    pub print_extrap: bool,
    pub namelist: bool,
    /// DUMP options as written (CASE, ALL, INPUT, IOM, ...).
    pub dump: Vec<String>,
    /// WRITE cards as written.
    pub write: Vec<String>,
}

/// What a control card line is.
#[derive(Debug, Clone, PartialEq)]
pub enum Card {
    CaseId(String),
    NextCase,
    Save,
    Dim(Dim),
    Deriv(DerivUnit),
    Damp,
    Build,
    Part,
    Trim,
    Plot,
    PrintExtrap,
    Namelist,
    Dump(String),
    Write(String),
    Naca(AirfoilCard),
    /// A known card keyword with an argument we cannot read: (card, expected, found).
    Bad(String, String, String),
}

/// Keywords of every control card, for "did you mean" hints.
pub const KEYWORDS: &[&str] = &[
    "CASEID",
    "NEXT CASE",
    "SAVE",
    "DIM",
    "DERIV",
    "DAMP",
    "BUILD",
    "PART",
    "TRIM",
    "DUMP",
    "PLOT",
    "PRINT EXTRAP",
    "NAMELIST",
    "WRITE",
    "NACA",
];

fn parse_naca(upper: &str, line: usize) -> Card {
    let rest = upper[4..].trim_start_matches([' ', '-']);
    // Surface letter, series, designation: separated by `-` or blanks.
    let mut parts = rest.splitn(3, ['-', ' ', '\t']);
    let surface = parts.next().unwrap_or("");
    let series = parts.next().unwrap_or("").trim();
    let designation: String = parts
        .next()
        .unwrap_or("")
        .trim()
        .chars()
        .filter(|c| !c.is_whitespace())
        .collect();
    let Some(surface) = Surface::from_letter(surface.trim()) else {
        return Card::Bad(
            "NACA".into(),
            "a surface letter W, H, V or F after NACA".into(),
            surface.into(),
        );
    };
    let series = match series {
        "1" => NacaSeries::One,
        "4" => NacaSeries::Four,
        "5" => NacaSeries::Five,
        "6" => NacaSeries::Six,
        "S" => NacaSeries::Supersonic,
        other => return Card::Bad("NACA".into(), "series 1, 4, 5, 6 or S".into(), other.into()),
    };
    // Characters each series' designation may hold (the original's DECODE reads digits, and
    // `-`, `,`, `.`, `A` and `=` where the series has them).
    let allowed = |c: char| match series {
        NacaSeries::One | NacaSeries::Four | NacaSeries::Five => c.is_ascii_digit() || c == '-',
        NacaSeries::Six => c.is_ascii_digit() || "-,.A=".contains(c),
        NacaSeries::Supersonic => c.is_ascii_digit() || "-.".contains(c),
    };
    if !designation.starts_with(|c: char| c.is_ascii_digit()) || !designation.chars().all(allowed) {
        let found = if designation.is_empty() {
            "nothing".to_string()
        } else {
            designation.chars().take(30).collect()
        };
        return Card::Bad(
            "NACA".into(),
            "a designation such as 0012, 0012-25, 23012, 16-212, 64,3-618, 65A010 or S-1-50.0-2.5"
                .into(),
            found,
        );
    }
    Card::Naca(AirfoilCard {
        surface,
        series,
        designation,
        line,
    })
}

/// A control card as read, with any text after what the card needs (the original compares
/// fixed columns and ignores the rest).
#[derive(Debug, Clone, PartialEq)]
pub struct ParsedCard {
    pub card: Card,
    pub extra: Option<String>,
}

/// Reads a line as a control card; `None` when it is not one.
pub fn parse_card(text: &str, line: usize) -> Option<ParsedCard> {
    let trimmed = text.trim();
    // Every card begins with a word of letters, NACA and CASEID even when their data run on:
    // namelist lines and values are turned away here, before the line is copied.
    let head = trimmed.split_whitespace().next()?.as_bytes();
    let begins = |word: &str| {
        head.get(..word.len())
            .is_some_and(|b| b.eq_ignore_ascii_case(word.as_bytes()))
    };
    if !(begins("NACA") || begins("CASEID") || head.iter().all(u8::is_ascii_alphabetic)) {
        return None;
    }
    let mut words = trimmed.split_whitespace();
    let first = words.next()?;
    let second = words.next().unwrap_or("");
    let plain = |card: Card| ParsedCard { card, extra: None };
    if begins("NACA") && (trimmed.len() == 4 || trimmed[4..].starts_with([' ', '-', '\t'])) {
        return Some(plain(parse_naca(&trimmed.to_ascii_uppercase(), line)));
    }
    if begins("CASEID") {
        return Some(plain(Card::CaseId(trimmed[6..].trim().to_string())));
    }
    // Words are compared in any case and copied in upper case only into what the card keeps.
    let is = |word: &str, keyword: &str| word.eq_ignore_ascii_case(keyword);
    let rest = |used: usize| {
        let rest: Vec<String> = trimmed
            .split_whitespace()
            .skip(used)
            .map(str::to_ascii_uppercase)
            .collect();
        rest.join(" ")
    };
    let count = || trimmed.split_whitespace().count();
    // (card, number of words it uses)
    let keyword = KEYWORDS
        .iter()
        .filter_map(|k| k.split(' ').next())
        .find(|k| is(first, k));
    let (card, used) = match keyword {
        Some("NEXT") if is(second, "CASE") => (Card::NextCase, 2),
        Some("SAVE") => (Card::Save, 1),
        Some("DAMP") => (Card::Damp, 1),
        Some("BUILD") => (Card::Build, 1),
        Some("PART") => (Card::Part, 1),
        Some("TRIM") => (Card::Trim, 1),
        Some("PLOT") => (Card::Plot, 1),
        Some("NAMELIST") => (Card::Namelist, 1),
        Some("PRINT") if is(second, "EXTRAP") => (Card::PrintExtrap, 2),
        Some("DIM") => {
            let dims = [Dim::Ft, Dim::In, Dim::M, Dim::Cm];
            let card = match dims.into_iter().find(|d| is(second, d.name())) {
                Some(d) => Card::Dim(d),
                None => Card::Bad(
                    "DIM".into(),
                    "FT, IN, M or CM".into(),
                    second.to_ascii_uppercase(),
                ),
            };
            (card, 2)
        }
        Some("DERIV") => {
            let card = if is(second, "DEG") {
                Card::Deriv(DerivUnit::Deg)
            } else if is(second, "RAD") {
                Card::Deriv(DerivUnit::Rad)
            } else {
                Card::Bad(
                    "DERIV".into(),
                    "DEG or RAD".into(),
                    second.to_ascii_uppercase(),
                )
            };
            (card, 2)
        }
        Some("DUMP") => (Card::Dump(rest(1)), count()),
        Some("WRITE") => (Card::Write(rest(1)), count()),
        _ => return None,
    };
    let extra = trimmed
        .split_whitespace()
        .nth(used)
        .is_some()
        .then(|| rest(used));
    Some(ParsedCard { card, extra })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn card(s: &str) -> Option<Card> {
        parse_card(s, 1).map(|p| p.card)
    }

    #[test]
    fn naca_dash_and_blank_forms() {
        for s in ["NACA-W-6-643-618", "NACA W 6 643-618", "naca-w-6-643-618"] {
            match card(s) {
                Some(Card::Naca(a)) => {
                    assert_eq!(a.surface, Surface::Wing);
                    assert_eq!(a.series, NacaSeries::Six);
                    assert_eq!(a.designation, "643-618");
                }
                other => panic!("{s}: {other:?}"),
            }
        }
        assert!(matches!(card("NACA-Q-4-0012"), Some(Card::Bad(..))));
    }

    #[test]
    fn simple_cards() {
        assert_eq!(card(" NEXT CASE"), Some(Card::NextCase));
        assert_eq!(card("DIM M"), Some(Card::Dim(Dim::M)));
        assert_eq!(card("DERIV RAD"), Some(Card::Deriv(DerivUnit::Rad)));
        assert_eq!(
            card("CASEID NAVION, ELEVATOR"),
            Some(Card::CaseId("NAVION, ELEVATOR".into()))
        );
        assert_eq!(card("SAVSI=1.0"), None);
    }

    #[test]
    fn any_case_read_and_kept_in_upper_case() {
        let p = parse_card("dump case all", 1).unwrap();
        assert_eq!(p.card, Card::Dump("CASE ALL".into()));
        assert_eq!(p.extra, None);
        let p = parse_card("next case now", 1).unwrap();
        assert_eq!((p.card, p.extra.as_deref()), (Card::NextCase, Some("NOW")));
        assert_eq!(
            card("dim xx"),
            Some(Card::Bad(
                "DIM".into(),
                "FT, IN, M or CM".into(),
                "XX".into()
            ))
        );
        assert_eq!(card("Dim cm"), Some(Card::Dim(Dim::Cm)));
        assert_eq!(card("print extrap"), Some(Card::PrintExtrap));
        assert_eq!(card("print"), None);
        assert_eq!(card("NACAX W 4 0012"), None);
        assert_eq!(card("NACA\u{2003}W 4 0012"), None);
        assert_eq!(card("WRITE"), Some(Card::Write(String::new())));
    }

    #[test]
    fn extra_text_is_reported() {
        let p = parse_card("DERIV RAD LATDER", 1).unwrap();
        assert_eq!(p.card, Card::Deriv(DerivUnit::Rad));
        assert_eq!(p.extra.as_deref(), Some("LATDER"));
        assert_eq!(
            parse_card("SAVE IT", 1).unwrap().extra.as_deref(),
            Some("IT")
        );
        assert_eq!(parse_card("NEXT CASE", 1).unwrap().extra, None);
    }
}
