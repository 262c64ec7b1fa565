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

/// The unit names of a FLIGHT CONDITIONS header's unit line, each read in the columns of its
/// field ([`FIELDS`]), with the blanks the original leaves inside a name dropped after a slash
/// (`N/ M**2` is `N/M**2`, `1/ M` is `1/M`; `DEG R` keeps its blank): (field, unit) for each
/// field with a unit printed above it.
pub fn unit_names(line: &str) -> Vec<(&'static str, String)> {
    FIELDS
        .iter()
        .filter_map(|(name, a, b)| {
            let words: Vec<String> = slice(line, *a, *b)
                .split_whitespace()
                .map(str::to_string)
                .collect();
            let unit = words.join(" ").replace("/ ", "/");
            (!unit.is_empty()).then_some((*name, unit))
        })
        .collect()
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

/// Lines only the original program's output (and our listing layout) has: its page title
/// (first: the title of every result page), the disclaimer it opens with, its input-error
/// checking page (in every listing) and its echo of the input cards. A deck
/// has none of them (its cards are what a listing echoes, not these lines).
const LISTING_MARKS: [&str; 4] = [
    "AUTOMATED STABILITY AND CONTROL METHODS",
    "THIS SOFTWARE AND ANY ACCOMPANYING DOCUMENTATION",
    "CONERR - INPUT ERROR CHECKING",
    "THE FOLLOWING IS A LIST OF ALL INPUT CARDS",
];

/// Whether `text` is a listing of the original program (for006.dat), also one that stopped
/// before any result page (an input error), rather than a deck.
pub fn is_listing(text: &str) -> bool {
    LISTING_MARKS.iter().any(|m| text.contains(m))
}

/// The length of the shortest of [`LISTING_MARKS`].
const SHORTEST_MARK: usize = {
    let mut shortest = usize::MAX;
    let mut i = 0;
    while i < LISTING_MARKS.len() {
        if LISTING_MARKS[i].len() < shortest {
            shortest = LISTING_MARKS[i].len();
        }
        i += 1;
    }
    shortest
};

/// Whether one line of a file is one of a listing's marks (lines shorter than every mark are
/// not searched: the deck reader asks this of a deck's first cards).
pub fn is_listing_line(line: &str) -> bool {
    line.len() >= SHORTEST_MARK && is_listing(line)
}

/// Whether a listing is the original program's: it opens with its disclaimer and has its
/// input-checking page, which ours (`run --format for006`) does not print.
pub fn is_original_listing(text: &str) -> bool {
    LISTING_MARKS[1..3].iter().any(|m| text.contains(m))
}

/// Whether a listing has any page of results (the original's page title, which a listing
/// that stopped at input errors lacks; every listing has the CONERR page).
pub fn has_result_pages(text: &str) -> bool {
    text.contains(LISTING_MARKS[0])
}

/// Why a text is not imported as a listing ([`import`]).
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum NotImported {
    /// datcom-rs's own text report (`run`'s default format): its static table is not in the
    /// listing's columns and its cases are not marked, so it cannot be read back reliably.
    #[error("this is datcom-rs's text report (the default format of `run`), which is not read back (its static table is not in the listing's columns); write the results with `run --format json` or `run --format for006`")]
    TextReport,
    /// No page title, disclaimer, input-checking page or input-card list of the original.
    #[error("not a listing of the original program (for006.dat): none of its page titles or input-card lists")]
    NotAListing,
    /// A listing of the original that stopped before computing (input errors).
    #[error("a listing of the original program without any result page (it stopped before computing: the error lines of its CONERR page say why)")]
    NoResultPage,
    /// Result pages, none of a kind the reader reads (static, dynamic, PART).
    #[error("a listing of the original program whose result pages{} are none of the pages read (CHARACTERISTICS AT ANGLE OF ATTACK AND IN SIDESLIP, DYNAMIC DERIVATIVES, CONFIGURATION AUXILIARY AND PARTIAL OUTPUT)", if kinds.is_empty() { String::new() } else { format!(" ({})", kinds.join("; ")) })]
    NoPageRead {
        /// The kinds of its result pages (the line under each page title), each once.
        kinds: Vec<String>,
    },
}

/// Reads a listing of the original program (or ours, `--format for006`) as [`read_listing`]
/// does, refusing what would read as nothing or as invented numbers: datcom-rs's text report,
/// a text that is no listing, a listing without result pages or without a page read.
pub fn import(text: &str) -> Result<Vec<ListedCase>, NotImported> {
    let lines = || text.lines().map(str::trim_end);
    if lines().any(|l| l == super::text::TITLE) {
        return Err(NotImported::TextReport);
    }
    if !is_listing(text) {
        return Err(NotImported::NotAListing);
    }
    if !has_result_pages(text) {
        return Err(NotImported::NoResultPage);
    }
    let cases = read_listing(text);
    if cases.is_empty() {
        let all: Vec<&str> = text.lines().collect();
        let mut kinds: Vec<String> = Vec::new();
        for (i, l) in all.iter().enumerate() {
            if !l.contains(LISTING_MARKS[0]) {
                continue;
            }
            // The first line under the title that is not the rest of it (some pages print
            // `APRIL 1976 VERSION OF DATCOM` on a line of its own).
            let kind = all[i + 1..]
                .iter()
                .map(|k| k.trim())
                .take(3)
                .find(|k| !k.is_empty() && !k.contains("VERSION OF DATCOM"));
            if let Some(kind) = kind.filter(|k| !kinds.iter().any(|x| x == k)) {
                kinds.push(kind.to_string());
            }
        }
        return Err(NotImported::NoPageRead { kinds });
    }
    Ok(cases)
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
    }

    /// Each unit in its field's columns: the original's two-word names (`DEG K`) and the
    /// blank it leaves after a slash (`N/ M**2`) were split into separate units and read by
    /// their place in the line (pressure `N/`, temperature `M**2`).
    #[test]
    fn reads_the_units_by_column() {
        let metric = "              M        M/SEC      N/ M**2       DEG K         1/ M                M**2         M         M         M         M";
        let units = unit_names(metric);
        let unit = |f: &str| units.iter().find(|(n, _)| *n == f).map(|(_, u)| u.as_str());
        assert_eq!(unit("mach"), None);
        assert_eq!(unit("altitude"), Some("M"));
        assert_eq!(unit("velocity"), Some("M/SEC"));
        assert_eq!(unit("pressure"), Some("N/M**2"));
        assert_eq!(unit("temperature"), Some("DEG K"));
        assert_eq!(unit("reynolds_per_length"), Some("1/M"));
        assert_eq!(unit("area"), Some("M**2"));
        assert_eq!(unit("zcg"), Some("M"));
        assert!((last_digit_unit("511.570") - 0.001).abs() < 1e-12);
    }
}

/// Columns of the static table (CHARACTERISTICS AT ANGLE OF ATTACK AND IN SIDESLIP): name and
/// the column just past its right edge (fields are right-aligned between edges).
pub const STATIC_COLUMNS: [(&str, usize); 12] = [
    ("ALPHA", 7),
    ("CD", 16),
    ("CL", 25),
    ("CM", 35),
    ("CN", 43),
    ("CA", 52),
    ("XCP", 61),
    ("CLA", 74),
    ("CMA", 87),
    ("CYB", 100),
    ("CNB", 113),
    ("CLB", 126),
];

/// Columns of the DYNAMIC DERIVATIVES table, as [`STATIC_COLUMNS`].
pub const DYNAMIC_COLUMNS: [(&str, usize); 10] = [
    ("ALPHA", 9),
    ("CLQ", 22),
    ("CMQ", 35),
    ("CLAD", 49),
    ("CMAD", 62),
    ("CLP", 75),
    ("CYP", 88),
    ("CNP", 101),
    ("CNR", 114),
    ("CLR", 127),
];

/// The table under a page with a horizontal tail (ALPHA, Q/QINF, EPSLON, D(EPSLON)/D(ALPHA)):
/// each column's right edge.
pub const DOWNWASH_COLUMNS: [(&str, usize); 4] = [
    ("ALPHA", 41),
    ("Q/QINF", 52),
    ("EPSLON", 63),
    ("D(EPSLON)/D(ALPHA)", 76),
];

/// The downwash table's heading as the original prints it.
pub const DOWNWASH_HEADING: &str =
    "0                                    ALPHA     Q/QINF    EPSLON  D(EPSLON)/D(ALPHA)";

/// A table read from a listing: its columns by name, one entry per row (`None`: blank, NDM,
/// NA or an overflowed field), with the printed text kept for precision.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Table {
    pub columns: Vec<(String, Vec<Option<f64>>)>,
    pub texts: Vec<Vec<String>>,
}

impl Table {
    pub fn column(&self, name: &str) -> Option<&[Option<f64>]> {
        self.columns
            .iter()
            .find(|(n, _)| n == name)
            .map(|(_, v)| v.as_slice())
    }

    /// The columns printed `NDM` (no DATCOM method) in the first row, in page order.
    pub fn no_method(&self) -> Vec<String> {
        let Some(first) = self.texts.first() else {
            return Vec::new();
        };
        self.columns
            .iter()
            .zip(first)
            .filter(|(_, text)| text.trim() == "NDM")
            .map(|((name, _), _)| name.clone())
            .collect()
    }
}

fn read_table(lines: &[&str], start: usize, columns: &[(&str, usize)]) -> Table {
    let mut t = Table {
        columns: columns
            .iter()
            .map(|(n, _)| (n.to_string(), Vec::new()))
            .collect(),
        texts: Vec::new(),
    };
    for l in lines.iter().skip(start) {
        if l.trim().is_empty() || l.starts_with('0') || l.starts_with('1') {
            break;
        }
        // A row whose angle is not a number (NDM: an angle the deck left unset) is left out.
        if slice(l, 0, columns[0].1).parse::<f64>().is_err() {
            continue;
        }
        let mut left = 0;
        let mut texts = Vec::new();
        for (k, (_, right)) in columns.iter().enumerate() {
            let text = slice(l, left, *right);
            left = *right;
            t.columns[k]
                .1
                .push(text.parse::<f64>().ok().filter(|v| v.is_finite()));
            texts.push(text);
        }
        t.texts.push(texts);
    }
    t
}

/// One flight condition and configuration of a listing with its tables.
#[derive(Debug, Clone, PartialEq)]
pub struct ListedCondition {
    pub row: ConditionRow,
    pub configuration: String,
    /// What the original says its static page includes, printed under the configuration:
    /// `PROPELLER POWER EFFECTS INCLUDED IN THE LONGITUDINAL STABILITY RESULTS`, the jet's, or
    /// ground effects; empty for the ordinary page. (With BUILD the original prints the
    /// configuration's page without them first, then the page with them.)
    pub included: Vec<String>,
    pub deriv_per_radian: bool,
    pub statics: Option<Table>,
    pub dynamics: Option<Table>,
    /// The downwash table printed under the static page.
    pub downwash: Option<Table>,
    /// With PART: the CONFIGURATION AUXILIARY AND PARTIAL OUTPUT pages of this condition.
    pub auxiliary: Option<super::auxiliary::AuxiliaryJson>,
}

/// One case of a listing.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct ListedCase {
    pub caseid: Option<String>,
    /// Unit names of the FLIGHT CONDITIONS header by field of [`FIELDS`] (altitude FT,
    /// velocity FT/SEC, pressure LB/FT**2, temperature DEG R, reynolds_per_length 1/FT, area
    /// FT**2, ...), read by [`unit_names`].
    pub units: Vec<(&'static str, String)>,
    pub conditions: Vec<ListedCondition>,
}

/// Whether a line under a page's configuration is the original's note of the effects the page
/// includes: power (`PROPELLER POWER EFFECTS INCLUDED IN THE LONGITUDINAL STABILITY RESULTS`,
/// the jet's), ground effects (`GROUND EFFECTS INCLUDED IN THE LONGITUDINAL STABILITY RESULTS ,
/// GROUND HEIGHT= ...`) and the flap in ground effect (`WING FLAP DEFLECTION INCLUDED IN GROUND
/// EFFECTS DATA, ...`), and not a CASEID.
fn is_effects_note(line: &str) -> bool {
    line.contains("INCLUDED IN THE LONGITUDINAL STABILITY RESULTS")
        || line.contains("INCLUDED IN GROUND EFFECTS DATA")
}

/// Whether `c` is of the configuration and flight-condition row printed.
fn same_page(c: &ListedCondition, configuration: &str, row: &ConditionRow) -> bool {
    c.configuration == configuration
        && c.row
            .fields
            .iter()
            .map(|f| &f.text)
            .eq(row.fields.iter().map(|f| &f.text))
}

/// Reads the static and dynamic tables of a listing, grouped by case, flight condition and
/// configuration. A case begins where the original lists its input cards.
pub fn read_listing(listing: &str) -> Vec<ListedCase> {
    let lines: Vec<&str> = listing.lines().collect();
    let mut cases: Vec<ListedCase> = Vec::new();
    let mut new_case = true;
    for (i, l) in lines.iter().enumerate() {
        if l.contains("LIST OF ALL INPUT CARDS FOR THIS CASE") {
            new_case = true;
            continue;
        }
        if !(l.starts_with('1') && l.contains("AUTOMATED STABILITY AND CONTROL METHODS")) {
            continue;
        }
        let kind = lines.get(i + 1).map_or("", |s| s.trim());
        let is_static = kind == "CHARACTERISTICS AT ANGLE OF ATTACK AND IN SIDESLIP";
        let is_dynamic = kind == "DYNAMIC DERIVATIVES";
        let is_auxiliary = kind == "CONFIGURATION AUXILIARY AND PARTIAL OUTPUT";
        if !(is_static || is_dynamic || is_auxiliary) {
            continue;
        }
        let configuration = lines.get(i + 2).map_or("", |s| s.trim()).to_string();
        // Power or ground effects included in the page, each on a line of its own.
        let included: Vec<String> = lines[(i + 3).min(lines.len())..]
            .iter()
            .map(|s| s.trim())
            .take_while(|s| is_effects_note(s))
            .map(str::to_string)
            .collect();
        let caseid = lines
            .get(i + 3 + included.len())
            .map(|s| s.trim())
            .filter(|s| !s.is_empty())
            .map(str::to_string);
        // The FLIGHT CONDITIONS block follows within a few lines.
        let Some(fc) = (i + 3..(i + 8 + included.len()).min(lines.len()))
            .find(|&k| lines[k].contains("FLIGHT CONDITIONS") && lines[k].contains("REFERENCE"))
        else {
            continue;
        };
        let Some(row) = flight_condition_rows(&lines[fc..(fc + 6).min(lines.len())].join("\n"))
            .into_iter()
            .next()
        else {
            continue;
        };
        let row = ConditionRow {
            line: fc + 5,
            page: kind.to_string(),
            ..row
        };
        if is_auxiliary {
            // Onto the condition's page of the same configuration read before it.
            let end = (fc + 5..lines.len())
                .find(|&k| lines[k].starts_with('1'))
                .unwrap_or(lines.len());
            // Of the pages read so far, the latest with the fewest effects included: the page
            // without power effects before the page with them (BUILD), at the ground height
            // being printed.
            if let Some(c) = cases.last_mut().filter(|_| !new_case).and_then(|case| {
                let (k, _) = case
                    .conditions
                    .iter()
                    .enumerate()
                    .rev()
                    .filter(|(_, c)| same_page(c, &configuration, &row))
                    .min_by_key(|(_, c)| c.included.len())?;
                case.conditions.get_mut(k)
            }) {
                let aux = c.auxiliary.get_or_insert_with(Default::default);
                super::auxiliary::read_page(&lines[fc + 5..end], aux);
            }
            continue;
        }
        let header = (fc + 5..(fc + 12).min(lines.len())).find(|&k| {
            let h = lines[k];
            h.starts_with('0') && h.contains("ALPHA") && (h.contains(" CD ") || h.contains("CLQ"))
        });
        let Some(header) = header else { continue };
        let per_radian = lines[fc + 5..header]
            .iter()
            .any(|h| h.contains("PER RADIAN"));
        let table = read_table(
            &lines,
            header + 2,
            if is_static {
                &STATIC_COLUMNS
            } else {
                &DYNAMIC_COLUMNS
            },
        );
        // Under a static page, before the next page: the downwash table, when there is one.
        let downwash = is_static
            .then(|| {
                let rows = table.texts.len();
                lines
                    .iter()
                    .enumerate()
                    .skip(header + 2 + rows)
                    .take_while(|(_, l)| !l.starts_with('1'))
                    .find(|(_, l)| {
                        l.starts_with('0') && l.contains("Q/QINF") && l.contains("EPSLON")
                    })
                    .map(|(k, _)| read_table(&lines, k + 2, &DOWNWASH_COLUMNS))
            })
            .flatten();
        if new_case || cases.is_empty() {
            cases.push(ListedCase::default());
            new_case = false;
        }
        let case = cases.last_mut().expect("a case was just pushed");
        if case.caseid.is_none() {
            case.caseid = caseid;
        }
        if case.units.is_empty() {
            case.units = lines.get(fc + 3).map_or_else(Vec::new, |u| unit_names(u));
        }
        let same = |c: &ListedCondition| same_page(c, &configuration, &row);
        // A static page goes with the dynamic page of its configuration, condition and
        // inclusions; a dynamic page (the original's include no power or ground effects) with
        // the first static page of its configuration and condition.
        let idx = match case.conditions.iter().position(|c| {
            same(c)
                && if is_static {
                    c.statics.is_none() && c.included == included
                } else {
                    c.dynamics.is_none()
                }
        }) {
            Some(k) => k,
            None => {
                case.conditions.push(ListedCondition {
                    row,
                    configuration: configuration.clone(),
                    included: if is_static { included } else { Vec::new() },
                    deriv_per_radian: per_radian,
                    statics: None,
                    dynamics: None,
                    downwash: None,
                    auxiliary: None,
                });
                case.conditions.len() - 1
            }
        };
        let c = &mut case.conditions[idx];
        if is_static {
            c.statics = Some(table);
            c.deriv_per_radian = per_radian;
            c.downwash = downwash;
        } else {
            c.dynamics = Some(table);
        }
    }
    cases
}
