//! Writing cases back as deck text that both this reader and the original program accept:
//! control cards from column 1, namelists as ` $NAME` with assignments on cards of at most 80
//! columns, numbers in a form that reads back to the same `f64`.

use super::cards::{DerivUnit, Dim, NacaSeries, Surface};
use super::{RawCase, Value, CARD_COLUMNS};

/// A number as the shortest text that reads back to the same value, always with a decimal
/// point or exponent so that it reads as REAL.
pub fn number(v: f64) -> String {
    let s = format!("{v:?}");
    if s.contains(['.', 'e', 'E']) {
        s.replace('e', "E")
    } else {
        format!("{s}.0")
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
