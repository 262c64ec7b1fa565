//! Reading listings of the original program (`for006.dat`).
//!
//! For now: the FLIGHT CONDITIONS rows, read by the fixed columns the original writes them in
//! (blanks, `NDM` and `NA` are not numbers; see the layout in [`FIELDS`]).

/// Fields of a FLIGHT CONDITIONS row: (name, first column, end column exclusive), 0-based, as
/// the original's format writes them (F6.3, F8.2, F8.2, 1PE10.4, F9.3, 1PE10.4, F9.3, 4×F8.3).
pub const FIELDS: [(&str, usize, usize); 11] = [
    ("mach", 1, 7),
    ("altitude", 10, 18),
    ("velocity", 21, 29),
    ("pressure", 32, 42),
    ("temperature", 45, 54),
    ("reynolds_per_length", 59, 69),
    ("area", 78, 87),
    ("longitudinal", 90, 98),
    ("lateral", 100, 108),
    ("xcg", 110, 118),
    ("zcg", 120, 128),
];

/// A printed field: its text and the number it reads as.
#[derive(Debug, Clone, PartialEq)]
pub struct Field {
    pub text: String,
    pub value: Option<f64>,
}

/// One FLIGHT CONDITIONS row of a listing.
#[derive(Debug, Clone, PartialEq)]
pub struct ConditionRow {
    /// 1-based line in the listing.
    pub line: usize,
    /// Page kind: the first title line after the page header.
    pub page: String,
    pub fields: Vec<Field>,
}

impl ConditionRow {
    pub fn field(&self, name: &str) -> Option<&Field> {
        FIELDS
            .iter()
            .position(|(n, _, _)| *n == name)
            .and_then(|i| self.fields.get(i))
    }
}

fn slice(line: &str, a: usize, b: usize) -> String {
    line.chars()
        .skip(a)
        .take(b - a)
        .collect::<String>()
        .trim()
        .to_string()
}

/// Unit in the last printed digit of a fixed or exponent field (`1.9676E+03` -> 0.1).
pub fn last_digit_unit(text: &str) -> f64 {
    let t = text.trim();
    let (mant, exp) = match t.find(['E', 'e']) {
        Some(i) => (&t[..i], t[i + 1..].parse::<i32>().unwrap_or(0)),
        None => (t, 0),
    };
    let decimals = mant.find('.').map_or(0, |p| mant.len() - p - 1) as i32;
    10f64.powi(exp - decimals)
}

/// Every FLIGHT CONDITIONS row of a listing, with its page kind.
pub fn flight_condition_rows(listing: &str) -> Vec<ConditionRow> {
    let lines: Vec<&str> = listing.lines().collect();
    let mut out = Vec::new();
    let mut page = String::new();
    for (i, l) in lines.iter().enumerate() {
        if l.starts_with('1') && l.contains("AUTOMATED STABILITY AND CONTROL METHODS") {
            page = lines
                .get(i + 1)
                .map(|t| t.trim().to_string())
                .unwrap_or_default();
        }
        if l.contains("FLIGHT CONDITIONS") && l.contains("REFERENCE DIMENSIONS") {
            let Some(row) = lines.get(i + 4) else {
                continue;
            };
            if !row.starts_with('0') {
                continue;
            }
            let fields = FIELDS
                .iter()
                .map(|(_, a, b)| {
                    let text = slice(row, *a, *b);
                    let value = text.parse::<f64>().ok();
                    Field { text, value }
                })
                .collect();
            out.push(ConditionRow {
                line: i + 5,
                page: page.clone(),
                fields,
            });
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reads_a_row() {
        let listing = "1         AUTOMATED STABILITY AND CONTROL METHODS PER APRIL 1976 VERSION OF DATCOM\n                         CHARACTERISTICS AT ANGLE OF ATTACK AND IN SIDESLIP\n -----------------------  FLIGHT CONDITIONS  ------------------------           --------------  REFERENCE DIMENSIONS  ------------\n x\n x\n x\n0 0.158    2000.00     175.17   1.9676E+03     511.570     1.0700E+06           184.000      5.700    33.400     8.030    -0.470\n";
        let rows = flight_condition_rows(listing);
        assert_eq!(rows.len(), 1);
        let r = &rows[0];
        assert_eq!(r.page, "CHARACTERISTICS AT ANGLE OF ATTACK AND IN SIDESLIP");
        assert_eq!(r.field("mach").unwrap().value, Some(0.158));
        assert_eq!(r.field("pressure").unwrap().value, Some(1967.6));
        assert_eq!(r.field("zcg").unwrap().value, Some(-0.47));
        assert!((last_digit_unit("1.9676E+03") - 0.1).abs() < 1e-12);
        assert!((last_digit_unit("511.570") - 0.001).abs() < 1e-12);
    }
}
