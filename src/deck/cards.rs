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
    if designation.is_empty() {
        return Card::Bad(
            "NACA".into(),
            "a section designation such as 0012".into(),
            "nothing".into(),
        );
    }
    Card::Naca(AirfoilCard {
        surface,
        series,
        designation,
        line,
    })
}

/// Reads a line as a control card; `None` when it is not one.
pub fn parse_card(text: &str, line: usize) -> Option<Card> {
    let trimmed = text.trim();
    let upper = trimmed.to_ascii_uppercase();
    let words: Vec<&str> = upper.split_whitespace().collect();
    let first = *words.first()?;
    if first.starts_with("NACA") && (upper.len() == 4 || upper[4..].starts_with([' ', '-', '\t'])) {
        return Some(parse_naca(&upper, line));
    }
    if first == "CASEID" || upper.starts_with("CASEID") {
        return Some(Card::CaseId(trimmed[6..].trim().to_string()));
    }
    let arg = |n: usize| words.get(n).copied().unwrap_or("");
    let card = match (first, words.len()) {
        ("NEXT", 2) if arg(1) == "CASE" => Card::NextCase,
        ("SAVE", 1) => Card::Save,
        ("DAMP", 1) => Card::Damp,
        ("BUILD", 1) => Card::Build,
        ("PART", 1) => Card::Part,
        ("TRIM", 1) => Card::Trim,
        ("PLOT", 1) => Card::Plot,
        ("NAMELIST", 1) => Card::Namelist,
        ("PRINT", 2) if arg(1) == "EXTRAP" => Card::PrintExtrap,
        ("DIM", _) => match arg(1) {
            "FT" => Card::Dim(Dim::Ft),
            "IN" => Card::Dim(Dim::In),
            "M" => Card::Dim(Dim::M),
            "CM" => Card::Dim(Dim::Cm),
            other => Card::Bad("DIM".into(), "FT, IN, M or CM".into(), other.into()),
        },
        ("DERIV", _) => match arg(1) {
            "DEG" => Card::Deriv(DerivUnit::Deg),
            "RAD" => Card::Deriv(DerivUnit::Rad),
            other => Card::Bad("DERIV".into(), "DEG or RAD".into(), other.into()),
        },
        ("DUMP", _) => Card::Dump(words[1..].join(" ")),
        ("WRITE", _) => Card::Write(words[1..].join(" ")),
        _ => return None,
    };
    Some(card)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn naca_dash_and_blank_forms() {
        for s in ["NACA-W-6-643-618", "NACA W 6 643-618", "naca-w-6-643-618"] {
            match parse_card(s, 1) {
                Some(Card::Naca(a)) => {
                    assert_eq!(a.surface, Surface::Wing);
                    assert_eq!(a.series, NacaSeries::Six);
                    assert_eq!(a.designation, "643-618");
                }
                other => panic!("{s}: {other:?}"),
            }
        }
        assert!(matches!(
            parse_card("NACA-Q-4-0012", 1),
            Some(Card::Bad(..))
        ));
    }

    #[test]
    fn simple_cards() {
        assert_eq!(parse_card(" NEXT CASE", 1), Some(Card::NextCase));
        assert_eq!(parse_card("DIM M", 1), Some(Card::Dim(Dim::M)));
        assert_eq!(
            parse_card("DERIV RAD", 1),
            Some(Card::Deriv(DerivUnit::Rad))
        );
        assert_eq!(
            parse_card("CASEID NAVION, ELEVATOR", 1),
            Some(Card::CaseId("NAVION, ELEVATOR".into()))
        );
        assert_eq!(parse_card("SAVSI=1.0", 1), None);
    }
}
