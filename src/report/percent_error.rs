//! Percent-error reports: our stability derivatives against reference values (a hand
//! calculation, a published table, flight data), derivative by derivative, the way a
//! stability study reports them: our value, the reference value, the percentage error
//! (ours − reference)/|reference|·100, the unit and the DATCOM method behind our value, with
//! the mean and largest absolute error per derivative family.
//!
//! A reference file is TOML (docs/validation.md):
//!
//! ```toml
//! aircraft = "AEROMECH I"
//! deck = "namelists/aeromech1.dcm"      # optional: the deck the values are for
//! citation = "where the values come from"
//! configuration = "WING-BODY-VERTICAL TAIL-HORIZONTAL TAIL CONFIGURATION"   # optional
//! [condition]
//! case = 1            # optional, 1-based (default 1)
//! mach = 0.0571       # one of the case's Mach numbers
//! altitude_m = 200.0  # optional, metres
//! alpha_deg = 0.0     # values that vary with alpha are read (interpolated) here
//! [[values]]
//! name = "CLA"        # CLA CMA CYB CNB CLB CLQ CMQ CLAD CMAD CLP CYP CNP CNR CLR
//! value = 5.12
//! unit = "per_rad"    # or "per_deg"
//! source = "docs/handcalc/aeromech1.md §2.1"
//! ```
//!
//! Without `configuration` the most complete configuration of the condition is used (the last
//! one the run gives for it).

use serde::{Deserialize, Serialize};
use thiserror::Error;

use crate::results::{CaseResults, ConditionResults, Results};

/// Mach numbers of a reference and of a run agree within this (the original prints three
/// decimals; reference files often give four).
pub const MACH_MATCH: f64 = 5e-4;
/// Altitudes agree within this, metres (decks give whole metres or feet).
pub const ALTITUDE_MATCH_M: f64 = 0.5;

/// The unit of a derivative in a reference file.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum DerivativeUnit {
    PerRad,
    PerDeg,
}

impl DerivativeUnit {
    /// Multiplies a per-radian value into this unit.
    fn per_rad_factor(self) -> f64 {
        match self {
            DerivativeUnit::PerRad => 1.0,
            DerivativeUnit::PerDeg => std::f64::consts::PI / 180.0,
        }
    }

    pub fn label(self) -> &'static str {
        match self {
            DerivativeUnit::PerRad => "1/rad",
            DerivativeUnit::PerDeg => "1/deg",
        }
    }
}

/// Which family a derivative belongs to, for the summary lines.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Family {
    StaticLongitudinal,
    StaticLateralDirectional,
    Dynamic,
}

impl Family {
    pub fn label(self) -> &'static str {
        match self {
            Family::StaticLongitudinal => "static longitudinal",
            Family::StaticLateralDirectional => "static lateral-directional",
            Family::Dynamic => "dynamic",
        }
    }
}

/// A derivative the report knows: its column name (as the original's pages), family, the
/// DATCOM sections behind our value and whether DATCOM gives it once per configuration (on
/// the first row) rather than at each angle.
struct Known {
    name: &'static str,
    family: Family,
    method: &'static str,
}

const KNOWN: [Known; 14] = [
    Known {
        name: "CLA",
        family: Family::StaticLongitudinal,
        method:
            "DATCOM 4.1.3.2 wing, 4.2.1.1 body, 4.3.1.2 wing-body, 4.4.1 downwash, 4.5.1.1 tail",
    },
    Known {
        name: "CMA",
        family: Family::StaticLongitudinal,
        method:
            "DATCOM 4.1.4.2 wing, 4.2.2.1 body, 4.3.2.2 wing-body, 4.4.1 downwash, 4.5.2.1 tail",
    },
    Known {
        name: "CYB",
        family: Family::StaticLateralDirectional,
        method: "DATCOM 5.2.1.1 body, 5.2.2.1 wing-body, 5.3.1.1 vertical tail (sidewash)",
    },
    Known {
        name: "CNB",
        family: Family::StaticLateralDirectional,
        method: "DATCOM 5.2.3.1 wing-body, 5.3.1.1 vertical tail",
    },
    Known {
        name: "CLB",
        family: Family::StaticLateralDirectional,
        method: "DATCOM 5.1.2.1 wing, 5.2.2.1 wing-body, 5.3.1.1 vertical tail",
    },
    Known {
        name: "CLQ",
        family: Family::Dynamic,
        method: "DATCOM 7.1.1.1 wing, 7.2.1.1 body, 7.3.1.1 wing-body, 7.4.1.1 tail",
    },
    Known {
        name: "CMQ",
        family: Family::Dynamic,
        method: "DATCOM 7.1.1.2 wing, 7.2.1.2 body, 7.3.1.2 wing-body, 7.4.1.1 tail",
    },
    Known {
        name: "CLAD",
        family: Family::Dynamic,
        method: "DATCOM 7.1.4.1 wing, 7.2.2.1 body, 7.4.4.1 tail downwash lag",
    },
    Known {
        name: "CMAD",
        family: Family::Dynamic,
        method: "DATCOM 7.1.4.2 wing, 7.2.2.2 body, 7.4.4.1 tail downwash lag",
    },
    Known {
        name: "CLP",
        family: Family::Dynamic,
        method: "DATCOM 7.1.2.2 wing, 7.4.2.1 tails",
    },
    Known {
        name: "CYP",
        family: Family::Dynamic,
        method: "DATCOM 7.1.2.1 wing, 7.4.2.2 vertical tail",
    },
    Known {
        name: "CNP",
        family: Family::Dynamic,
        method: "DATCOM 7.1.2.3 wing, 7.4.2.2 vertical tail",
    },
    Known {
        name: "CNR",
        family: Family::Dynamic,
        method: "DATCOM 7.1.3.3 wing, 7.4.3.1 vertical tail",
    },
    Known {
        name: "CLR",
        family: Family::Dynamic,
        method: "DATCOM 7.1.3.2 wing, 7.4.3.2 vertical tail",
    },
];

fn known(name: &str) -> Option<&'static Known> {
    KNOWN.iter().find(|k| k.name == name)
}

/// Where a reference file's condition lies in the run.
#[derive(Debug, Clone, PartialEq, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct ReferenceCondition {
    /// 1-based case number of the deck (default 1).
    #[serde(default)]
    pub case: Option<usize>,
    pub mach: f64,
    /// Metres; any altitude of the case when absent.
    #[serde(default)]
    pub altitude_m: Option<f64>,
    /// Angle of attack, degrees, at which values that vary with alpha are read.
    #[serde(default)]
    pub alpha_deg: f64,
}

/// One reference value.
#[derive(Debug, Clone, PartialEq, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct ReferenceValue {
    pub name: String,
    pub value: f64,
    pub unit: DerivativeUnit,
    /// Where this value is printed or worked (book and page, section of a calculation).
    pub source: String,
}

/// A reference file (see the module documentation).
#[derive(Debug, Clone, PartialEq, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct Reference {
    pub aircraft: String,
    #[serde(default)]
    pub deck: Option<String>,
    pub citation: String,
    #[serde(default)]
    pub configuration: Option<String>,
    pub condition: ReferenceCondition,
    pub values: Vec<ReferenceValue>,
}

/// What is wrong with a reference, or why it does not fit the run.
#[derive(Debug, Clone, PartialEq, Error)]
#[non_exhaustive]
pub enum ReferenceError {
    #[error("{file}: not a reference file: {reason}")]
    Syntax { file: String, reason: String },
    #[error("{file}: values[{index}] name {name:?} is not a derivative the report knows (expected one of CLA CMA CYB CNB CLB CLQ CMQ CLAD CMAD CLP CYP CNP CNR CLR)")]
    UnknownDerivative {
        file: String,
        index: usize,
        name: String,
    },
    #[error("{file}: values[{index}] ({name}) value {value} is not a finite number")]
    NotFinite {
        file: String,
        index: usize,
        name: String,
        value: f64,
    },
    #[error("{file}: condition {what} = {value} is not a finite number")]
    BadCondition {
        file: String,
        what: &'static str,
        value: f64,
    },
    #[error("the run has no case {case} (it has {cases})")]
    NoCase { case: usize, cases: usize },
    #[error("case {case} has no condition at Mach {mach}{altitude} (its Mach numbers: {available}) (hint: give one of the deck's Mach numbers in [condition])")]
    NoCondition {
        case: usize,
        mach: f64,
        altitude: String,
        available: String,
    },
    #[error("case {case} has no {configuration} at Mach {mach} (it has: {available})")]
    NoConfiguration {
        case: usize,
        configuration: String,
        mach: f64,
        available: String,
    },
}

impl Reference {
    /// Reads and checks a reference file's text; `file` names it in errors.
    pub fn from_toml(text: &str, file: &str) -> Result<Reference, ReferenceError> {
        let r: Reference = toml::from_str(text).map_err(|e| ReferenceError::Syntax {
            file: file.to_string(),
            reason: e.to_string().trim().to_string(),
        })?;
        for (what, value) in [
            ("mach", Some(r.condition.mach)),
            ("altitude_m", r.condition.altitude_m),
            ("alpha_deg", Some(r.condition.alpha_deg)),
        ] {
            if let Some(v) = value.filter(|v| !v.is_finite()) {
                return Err(ReferenceError::BadCondition {
                    file: file.to_string(),
                    what,
                    value: v,
                });
            }
        }
        if r.values.is_empty() {
            return Err(ReferenceError::Syntax {
                file: file.to_string(),
                reason: "no [[values]]: a reference file gives at least one derivative".into(),
            });
        }
        for (index, v) in r.values.iter().enumerate() {
            if r.values[..index].iter().any(|w| w.name == v.name) {
                return Err(ReferenceError::Syntax {
                    file: file.to_string(),
                    reason: format!(
                        "values[{index}]: {} is given twice (one value per derivative)",
                        v.name
                    ),
                });
            }
            if known(&v.name).is_none() {
                return Err(ReferenceError::UnknownDerivative {
                    file: file.to_string(),
                    index,
                    name: v.name.clone(),
                });
            }
            if !v.value.is_finite() {
                return Err(ReferenceError::NotFinite {
                    file: file.to_string(),
                    index,
                    name: v.name.clone(),
                    value: v.value,
                });
            }
        }
        Ok(r)
    }
}

/// One line of the report.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Row {
    pub name: String,
    pub family: Family,
    pub unit: DerivativeUnit,
    /// Ours in the reference's unit; none where we give no value (see `note`).
    pub ours: Option<f64>,
    pub reference: f64,
    /// (ours − reference)/|reference|·100; none without our value or for a zero reference.
    pub percent_error: Option<f64>,
    pub method: &'static str,
    pub source: String,
    /// How our value was read, or why there is none.
    pub note: String,
}

/// Mean and largest absolute percentage error over the rows of a family (or all rows).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Summary {
    /// `None` for the line over every row.
    pub family: Option<Family>,
    /// Rows with a percentage error.
    pub compared: usize,
    /// Rows without one (no value of ours, or a zero reference).
    pub not_compared: usize,
    pub mean_abs_percent: Option<f64>,
    pub max_abs_percent: Option<f64>,
    /// The derivative with the largest error.
    pub worst: Option<String>,
}

/// The report of one reference against one run.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Report {
    pub aircraft: String,
    pub citation: String,
    pub deck: String,
    pub case: usize,
    pub configuration: String,
    pub mach: f64,
    /// Metres, when the run knows it.
    pub altitude_m: Option<f64>,
    pub alpha_deg: f64,
    pub rows: Vec<Row>,
    /// Per family present, then over every row.
    pub summary: Vec<Summary>,
}

/// Our value of column `name` in `entry`, per radian, at `alpha_deg`, and how it was read.
fn our_value(entry: &ConditionResults, name: &str, alpha_deg: f64) -> (Option<f64>, String) {
    let s = &entry.static_coefficients;
    let column: Option<&Vec<Option<f64>>> = match name {
        "CLA" => Some(&s.cla),
        "CMA" => Some(&s.cma),
        "CYB" => Some(&s.cyb),
        "CNB" => Some(&s.cnb),
        "CLB" => Some(&s.clb),
        _ => None,
    };
    let column = match (column, &entry.dynamic) {
        (Some(c), _) => c,
        (None, None) => {
            return (
                None,
                "no dynamic derivatives (the deck has no DAMP card)".into(),
            )
        }
        (None, Some(d)) => {
            if d.no_method.contains(&name) {
                return (None, "DATCOM has no method here (NDM)".into());
            }
            match d.columns().into_iter().find(|(n, _)| *n == name) {
                Some((_, c)) => c,
                None => return (None, "not computed".into()),
            }
        }
    };
    let points: Vec<(f64, f64)> = entry
        .alpha_deg
        .iter()
        .zip(column)
        .filter_map(|(a, v)| Some((*a, (*v)?)))
        .collect();
    match points.as_slice() {
        [] => (None, "not computed at this condition".into()),
        [(a, v)] if *a == entry.alpha_deg[0] && entry.alpha_deg.len() > 1 => {
            (Some(*v), "one value per configuration (first row)".into())
        }
        [(a, v)] if *a == alpha_deg => (Some(*v), format!("at alpha {a} deg")),
        [(a, _)] => (
            None,
            format!("computed at alpha {a} deg only, not at {alpha_deg} deg"),
        ),
        _ => interpolate(&points, alpha_deg),
    }
}

/// Linear interpolation in a column's (alpha, value) points; none outside them.
fn interpolate(points: &[(f64, f64)], alpha_deg: f64) -> (Option<f64>, String) {
    if let Some((_, v)) = points.iter().find(|(a, _)| *a == alpha_deg) {
        return (Some(*v), format!("at alpha {alpha_deg} deg"));
    }
    let bracket = points
        .windows(2)
        .find(|w| (w[0].0 - alpha_deg) * (w[1].0 - alpha_deg) < 0.0);
    match bracket {
        Some(w) => {
            let t = (alpha_deg - w[0].0) / (w[1].0 - w[0].0);
            (
                Some(w[0].1 + t * (w[1].1 - w[0].1)),
                format!(
                    "at alpha {alpha_deg} deg, interpolated between {} and {} deg",
                    w[0].0, w[1].0
                ),
            )
        }
        None => (
            None,
            format!("alpha {alpha_deg} deg is outside the computed angles"),
        ),
    }
}

fn find_entry<'a>(
    case: &'a CaseResults,
    reference: &Reference,
) -> Result<&'a ConditionResults, ReferenceError> {
    let c = &reference.condition;
    let at_condition: Vec<&ConditionResults> = case
        .conditions
        .iter()
        .filter(|e| {
            (e.condition.mach - c.mach).abs() <= MACH_MATCH
                && c.altitude_m.is_none_or(|alt| {
                    e.condition
                        .altitude
                        .is_some_and(|a| (a - alt).abs() <= ALTITUDE_MATCH_M)
                })
        })
        .collect();
    if at_condition.is_empty() {
        let mut machs: Vec<f64> = case.conditions.iter().map(|e| e.condition.mach).collect();
        machs.sort_by(f64::total_cmp);
        machs.dedup();
        let machs: Vec<String> = machs.iter().map(|m| format!("{m}")).collect();
        return Err(ReferenceError::NoCondition {
            case: case.number,
            mach: c.mach,
            altitude: c
                .altitude_m
                .map_or(String::new(), |a| format!(" and altitude {a} m")),
            available: machs.join(", "),
        });
    }
    // Without an altitude the case's first one at this Mach; its configurations in run order.
    let first = &at_condition[0].condition;
    let at_condition: Vec<&ConditionResults> = at_condition
        .iter()
        .copied()
        .filter(|e| e.condition.altitude == first.altitude)
        .collect();
    // The reference's configuration, else the case's whole configuration (none when the
    // build-up has no page for it).
    let name = reference
        .configuration
        .as_deref()
        .unwrap_or(&case.configuration);
    at_condition
        .iter()
        .copied()
        .find(|e| e.configuration.trim() == name.trim())
        .ok_or_else(|| {
            let mut names: Vec<&str> = at_condition
                .iter()
                .map(|e| e.configuration.as_str())
                .collect();
            names.dedup();
            ReferenceError::NoConfiguration {
                case: case.number,
                configuration: name.to_string(),
                mach: c.mach,
                available: names.join("; "),
            }
        })
}

fn summary(rows: &[Row], family: Option<Family>) -> Summary {
    let of_family: Vec<&Row> = rows
        .iter()
        .filter(|r| family.is_none_or(|f| r.family == f))
        .collect();
    let errors: Vec<(&str, f64)> = of_family
        .iter()
        .filter_map(|r| Some((r.name.as_str(), r.percent_error?.abs())))
        .collect();
    let worst = errors.iter().copied().max_by(|a, b| a.1.total_cmp(&b.1));
    Summary {
        family,
        compared: errors.len(),
        not_compared: of_family.len() - errors.len(),
        mean_abs_percent: (!errors.is_empty())
            .then(|| errors.iter().map(|e| e.1).sum::<f64>() / errors.len() as f64),
        max_abs_percent: worst.map(|w| w.1),
        worst: worst.map(|w| w.0.to_string()),
    }
}

/// The report of `reference` against `results` (a run of the reference's deck).
pub fn report(results: &Results, reference: &Reference) -> Result<Report, ReferenceError> {
    let case_number = reference.condition.case.unwrap_or(1);
    let case = results
        .cases
        .get(case_number.wrapping_sub(1))
        .ok_or(ReferenceError::NoCase {
            case: case_number,
            cases: results.cases.len(),
        })?;
    let entry = find_entry(case, reference)?;
    let alpha = reference.condition.alpha_deg;
    let rows: Vec<Row> = reference
        .values
        .iter()
        .filter_map(|v| {
            let k = known(&v.name)?;
            let (ours_rad, note) = our_value(entry, k.name, alpha);
            let ours = ours_rad.map(|x| x * v.unit.per_rad_factor());
            let percent_error = ours
                .filter(|_| v.value != 0.0)
                .map(|o| (o - v.value) / v.value.abs() * 100.0)
                .filter(|p| p.is_finite());
            let note = if ours.is_some() && v.value == 0.0 {
                format!("{note}; reference is 0: no percentage")
            } else {
                note
            };
            Some(Row {
                name: k.name.to_string(),
                family: k.family,
                unit: v.unit,
                ours,
                reference: v.value,
                percent_error,
                method: k.method,
                source: v.source.clone(),
                note,
            })
        })
        .collect();
    let mut families: Vec<Family> = rows.iter().map(|r| r.family).collect();
    families.sort();
    families.dedup();
    let mut summaries: Vec<Summary> = families
        .into_iter()
        .map(|f| summary(&rows, Some(f)))
        .collect();
    summaries.push(summary(&rows, None));
    Ok(Report {
        aircraft: reference.aircraft.clone(),
        citation: reference.citation.clone(),
        deck: results.file.clone(),
        case: case.number,
        configuration: entry.configuration.clone(),
        mach: entry.condition.mach,
        altitude_m: entry.condition.altitude,
        alpha_deg: alpha,
        rows,
        summary: summaries,
    })
}

fn number(v: Option<f64>) -> String {
    v.map_or("-".to_string(), |x| format!("{x:.5}"))
}

fn percent(v: Option<f64>) -> String {
    v.map_or("-".to_string(), |x| format!("{x:+.1}"))
}

fn summary_label(s: &Summary) -> &'static str {
    s.family.map_or("all", Family::label)
}

fn summary_numbers(s: &Summary) -> String {
    match (s.mean_abs_percent, s.max_abs_percent, &s.worst) {
        (Some(mean), Some(max), Some(w)) => format!(
            "mean |error| {mean:.1} %, max |error| {max:.1} % ({w}), {} compared{}",
            s.compared,
            if s.not_compared > 0 {
                format!(", {} without a percentage", s.not_compared)
            } else {
                String::new()
            }
        ),
        _ => format!("nothing compared ({} without a percentage)", s.not_compared),
    }
}

fn heading(r: &Report) -> Vec<String> {
    vec![
        format!("{}: {}", r.aircraft, r.deck),
        format!("reference: {}", r.citation),
        format!(
            "case {}, {}, Mach {}{}, alpha {} deg",
            r.case,
            r.configuration.trim(),
            r.mach,
            r.altitude_m
                .map_or(String::new(), |a| format!(", altitude {a} m")),
            r.alpha_deg
        ),
    ]
}

/// The report as aligned text.
pub fn to_text(r: &Report) -> String {
    let mut out = heading(r).join("\n");
    out.push_str("\n\n");
    out.push_str(&format!(
        "{:<6} {:>12} {:>12} {:>9}  {:<6}  {}\n",
        "deriv", "ours", "reference", "error %", "unit", "method; how read; source"
    ));
    for row in &r.rows {
        out.push_str(&format!(
            "{:<6} {:>12} {:>12} {:>9}  {:<6}  {}; {}; {}\n",
            row.name,
            number(row.ours),
            number(Some(row.reference)),
            percent(row.percent_error),
            row.unit.label(),
            row.method,
            row.note,
            row.source
        ));
    }
    out.push('\n');
    for s in &r.summary {
        out.push_str(&format!("{}: {}\n", summary_label(s), summary_numbers(s)));
    }
    out
}

/// The report as a Markdown table with the summary below.
pub fn to_markdown(r: &Report) -> String {
    let mut out: String = heading(r).iter().map(|l| format!("{l}  \n")).collect();
    out.push_str("\n| derivative | ours | reference | error % | unit | method | source |\n");
    out.push_str("|---|---|---|---|---|---|---|\n");
    for row in &r.rows {
        out.push_str(&format!(
            "| {} | {} | {} | {} | {} | {} | {} |\n",
            row.name,
            number(row.ours),
            number(Some(row.reference)),
            percent(row.percent_error),
            row.unit.label(),
            row.method,
            row.source.replace('|', "/")
        ));
    }
    out.push('\n');
    for s in &r.summary {
        out.push_str(&format!(
            "- **{}**: {}\n",
            summary_label(s),
            summary_numbers(s)
        ));
    }
    out
}

fn csv_field(s: &str) -> String {
    if s.contains([',', '"', '\n']) {
        format!("\"{}\"", s.replace('"', "\"\""))
    } else {
        s.to_string()
    }
}

/// The report as CSV: one line per derivative (empty cells where there is no value).
pub fn to_csv(r: &Report) -> String {
    let mut out =
        String::from("derivative,family,ours,reference,percent_error,unit,method,note,source\n");
    let cell = |v: Option<f64>| v.map_or(String::new(), |x| format!("{x}"));
    for row in &r.rows {
        out.push_str(&format!(
            "{},{},{},{},{},{},{},{},{}\n",
            row.name,
            csv_field(row.family.label()),
            cell(row.ours),
            row.reference,
            cell(row.percent_error),
            row.unit.label(),
            csv_field(row.method),
            csv_field(&row.note),
            csv_field(&row.source)
        ));
    }
    out
}

/// The report as JSON.
pub fn to_json(r: &Report) -> String {
    serde_json::to_string_pretty(r).unwrap_or_else(|e| format!("{{\"error\": \"{e}\"}}"))
}

#[cfg(test)]
mod tests {
    use super::*;

    const DECK: &str = " $FLTCON NMACH=1.0, MACH(1)=0.2, NALT=1.0, ALT(1)=0.0,
   NALPHA=3.0, ALSCHD(1)=-2.0,0.0,2.0$
 $OPTINS SREF=2.0, CBARR=0.5, BLREF=4.0$
 $SYNTHS XCG=0.3, ZCG=0.0, XW=0.2, ZW=0.0, ALIW=0.0$
 $WGPLNF CHRDR=0.5, CHRDTP=0.5, SSPN=2.0, SSPNE=2.0, SAVSI=0.0, CHSTAT=0.25,
   TWISTA=0.0, DHDADI=0.0, TYPE=1.0$
NACA-W-4-0012
CASEID RECTANGULAR WING
";

    fn reference(values: &str) -> String {
        format!(
            "aircraft = \"test wing\"\ncitation = \"worked in this test\"\n[condition]\nmach = 0.2\naltitude_m = 0.0\nalpha_deg = 1.0\n{values}"
        )
    }

    fn run() -> Results {
        crate::run(&crate::read_deck(DECK, "wing.dcm"))
    }

    #[test]
    fn percent_error_is_relative_to_the_reference_in_its_unit() {
        let results = run();
        let entry = &results.cases[0].conditions[0];
        // CLA at alpha 1: halfway between the 0 and 2 deg rows, per rad.
        let cla = (entry.static_coefficients.cla[1].unwrap()
            + entry.static_coefficients.cla[2].unwrap())
            / 2.0;
        let per_deg = cla.to_radians();
        let text = reference(&format!(
            "[[values]]\nname = \"CLA\"\nvalue = {}\nunit = \"per_deg\"\nsource = \"x\"\n",
            per_deg * 1.1
        ));
        let r = Reference::from_toml(&text, "ref.toml").unwrap();
        let rep = report(&results, &r).unwrap();
        let row = &rep.rows[0];
        approx::assert_relative_eq!(row.ours.unwrap(), per_deg, max_relative = 1e-12);
        // ours = ref / 1.1: error = (1/1.1 − 1)·100.
        approx::assert_relative_eq!(
            row.percent_error.unwrap(),
            (1.0 / 1.1 - 1.0) * 100.0,
            max_relative = 1e-9
        );
        assert_eq!(rep.summary.len(), 2);
        assert_eq!(rep.summary[1].compared, 1);
    }

    #[test]
    fn an_unknown_derivative_is_an_error_naming_it() {
        let text = reference(
            "[[values]]\nname = \"CLBETA\"\nvalue = 1.0\nunit = \"per_rad\"\nsource = \"x\"\n",
        );
        let e = Reference::from_toml(&text, "ref.toml").unwrap_err();
        assert!(e.to_string().contains("CLBETA"), "{e}");
    }

    #[test]
    fn a_condition_not_in_the_run_is_an_error_listing_the_machs() {
        let text = reference(
            "[[values]]\nname = \"CLA\"\nvalue = 5.0\nunit = \"per_rad\"\nsource = \"x\"\n",
        )
        .replace("mach = 0.2", "mach = 0.3");
        let r = Reference::from_toml(&text, "ref.toml").unwrap();
        let e = report(&run(), &r).unwrap_err();
        assert!(e.to_string().contains("0.2"), "{e}");
    }

    #[test]
    fn dynamic_values_without_damp_are_reported_as_missing() {
        let text = reference(
            "[[values]]\nname = \"CMQ\"\nvalue = -10.0\nunit = \"per_rad\"\nsource = \"x\"\n",
        );
        let r = Reference::from_toml(&text, "ref.toml").unwrap();
        let rep = report(&run(), &r).unwrap();
        assert_eq!(rep.rows[0].ours, None);
        assert!(rep.rows[0].note.contains("DAMP"), "{}", rep.rows[0].note);
        assert_eq!(rep.summary.last().unwrap().not_compared, 1);
        for f in [
            to_text(&rep),
            to_markdown(&rep),
            to_csv(&rep),
            to_json(&rep),
        ] {
            assert!(f.contains("CMQ"));
        }
    }

    #[test]
    fn interpolation_stays_inside_the_computed_angles() {
        let points = [(0.0, 1.0), (2.0, 3.0)];
        assert_eq!(interpolate(&points, 1.0).0, Some(2.0));
        assert_eq!(interpolate(&points, 2.0).0, Some(3.0));
        assert_eq!(interpolate(&points, 3.0).0, None);
    }
}
