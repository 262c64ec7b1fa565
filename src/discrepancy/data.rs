//! Reading the discrepancy workflow's tables (CSV, docs/discrepancy.md) and estimating the
//! noise of a measured curve.

use std::collections::{BTreeMap, BTreeSet};

use serde::Serialize;

use super::effects::Prediction;
use super::DiscrepancyError;

/// Coefficient columns a static measurement may have (names as written in the header).
pub const COEFFICIENTS: [&str; 6] = ["CL", "CD", "Cm", "CY", "Cl", "Cn"];

/// Static measurements: one row per (alpha, beta) point.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Measurement {
    pub alpha_deg: Vec<f64>,
    /// 0 where the file has no beta column.
    pub beta_deg: Vec<f64>,
    /// By coefficient name: the value at each row (none where the cell is empty).
    pub values: BTreeMap<String, Vec<Option<f64>>>,
    /// By coefficient name: the noise standard deviation given per row (`sigma_<coef>`).
    pub sigma: BTreeMap<String, Vec<Option<f64>>>,
    /// Coefficients whose noise was set for every row by [`Measurement::with_sigma`] (the
    /// command line's `--sigma`) rather than read from a `sigma_<coef>` column.
    pub sigma_set_for_all_rows: BTreeSet<String>,
}

/// A CSV table: header names and rows of trimmed cells, with line numbers. Cells are read as
/// numbers when their column is used ([`Table::required`], [`Table::optional`]), so a column
/// of text the reader does not use (a `run` CSV's caseid) is no error.
pub(crate) struct Table {
    header: Vec<String>,
    rows: Vec<(usize, Vec<String>)>,
}

/// Reads a CSV table (`#` comment lines, cells trimmed).
pub(crate) fn read_table(text: &str, file: &str) -> Result<Table, DiscrepancyError> {
    let mut reader = csv::ReaderBuilder::new()
        .trim(csv::Trim::All)
        .comment(Some(b'#'))
        .from_reader(text.as_bytes());
    let header: Vec<String> = reader
        .headers()
        .map_err(|e| DiscrepancyError::Csv {
            file: file.into(),
            line: 1,
            reason: e.to_string(),
        })?
        .iter()
        .map(str::to_string)
        .collect();
    let mut rows = Vec::new();
    for record in reader.records() {
        let record = record.map_err(|e| DiscrepancyError::Csv {
            file: file.into(),
            line: e.position().map_or(0, |p| p.line() as usize),
            reason: e.to_string(),
        })?;
        let line = record.position().map_or(0, |p| p.line() as usize);
        rows.push((line, record.iter().map(str::to_string).collect()));
    }
    Ok(Table { header, rows })
}

impl Table {
    fn index(&self, name: &str) -> Option<usize> {
        self.header.iter().position(|h| h == name)
    }

    /// The cells of column `name` as text, empty where the table has no such column.
    fn text(&self, name: &str) -> Vec<&str> {
        let k = self.index(name);
        self.rows
            .iter()
            .map(|(_, r)| k.and_then(|k| r.get(k)).map_or("", String::as_str))
            .collect()
    }

    /// Column `name` read as numbers, none where a cell is empty; a cell that is not a finite
    /// number is an error naming its file, line and column, and so is a missing column.
    fn column(&self, name: &str, file: &str) -> Result<Vec<Option<f64>>, DiscrepancyError> {
        let k = self
            .index(name)
            .ok_or_else(|| DiscrepancyError::MissingColumn {
                file: file.into(),
                column: name.into(),
                found: self.header.join(","),
            })?;
        self.rows
            .iter()
            .map(|(line, r)| {
                let cell = r.get(k).map_or("", String::as_str);
                if cell.is_empty() {
                    return Ok(None);
                }
                match cell.parse::<f64>() {
                    Ok(v) if v.is_finite() => Ok(Some(v)),
                    _ => Err(DiscrepancyError::BadNumber {
                        file: file.into(),
                        line: *line,
                        column: name.into(),
                        text: cell.to_string(),
                    }),
                }
            })
            .collect()
    }

    /// Column `name`, every row given.
    pub(crate) fn required(&self, name: &str, file: &str) -> Result<Vec<f64>, DiscrepancyError> {
        let values = self.column(name, file)?;
        self.rows
            .iter()
            .zip(values)
            .map(|((line, _), v)| {
                v.ok_or_else(|| DiscrepancyError::BadNumber {
                    file: file.into(),
                    line: *line,
                    column: name.into(),
                    text: String::new(),
                })
            })
            .collect()
    }

    /// Column `name` where the table has it, empty cells none.
    fn optional(
        &self,
        name: &str,
        file: &str,
    ) -> Result<Option<Vec<Option<f64>>>, DiscrepancyError> {
        self.index(name)
            .map(|_| self.column(name, file))
            .transpose()
    }
}

impl Measurement {
    /// The measurements with `offset_deg` subtracted from every angle of attack (an alpha
    /// reference known to be off, e.g. the Ultra Stick 120 tables' 2°).
    pub fn with_alpha_offset(mut self, offset_deg: f64) -> Measurement {
        for a in &mut self.alpha_deg {
            *a -= offset_deg;
        }
        self
    }

    /// The measurements with the noise of `coefficient` given as `sigma` at every row (in
    /// place of any `sigma_<coef>` column).
    pub fn with_sigma(
        mut self,
        coefficient: &str,
        sigma: f64,
    ) -> Result<Measurement, DiscrepancyError> {
        if !COEFFICIENTS.contains(&coefficient) {
            return Err(DiscrepancyError::Invalid {
                reason: format!(
                    "sigma for {coefficient:?}: expected one of CL, CD, Cm, CY, Cl, Cn"
                ),
            });
        }
        if !(sigma.is_finite() && sigma > 0.0) {
            return Err(DiscrepancyError::Invalid {
                reason: format!("sigma for {coefficient} must be positive, found {sigma}"),
            });
        }
        self.sigma.insert(
            coefficient.to_string(),
            vec![Some(sigma); self.alpha_deg.len()],
        );
        self.sigma_set_for_all_rows.insert(coefficient.to_string());
        Ok(self)
    }
}

/// Reads static measurements: `alpha_deg` (required), `beta_deg` (optional), any of CL, CD,
/// Cm, CY, Cl, Cn, and `sigma_<coef>` columns.
pub fn read_measurement(text: &str, file: &str) -> Result<Measurement, DiscrepancyError> {
    let t = read_table(text, file)?;
    let alpha_deg = t.required("alpha_deg", file)?;
    let beta_deg = match t.index("beta_deg") {
        Some(_) => t.required("beta_deg", file)?,
        None => vec![0.0; alpha_deg.len()],
    };
    let mut values = BTreeMap::new();
    let mut sigma = BTreeMap::new();
    for c in COEFFICIENTS {
        if let Some(v) = t.optional(c, file)? {
            values.insert(c.to_string(), v);
        }
        if let Some(s) = t.optional(&format!("sigma_{c}"), file)? {
            if let Some(bad) = s.iter().flatten().find(|v| **v <= 0.0) {
                return Err(DiscrepancyError::Invalid {
                    reason: format!("{file}: sigma_{c} must be positive, found {bad}"),
                });
            }
            sigma.insert(c.to_string(), s);
        }
    }
    if values.is_empty() {
        return Err(DiscrepancyError::MissingColumn {
            file: file.into(),
            column: "any of CL, CD, Cm, CY, Cl, Cn".into(),
            found: t.header.join(","),
        });
    }
    if alpha_deg.is_empty() {
        return Err(DiscrepancyError::Invalid {
            reason: format!("{file}: no data rows"),
        });
    }
    Ok(Measurement {
        alpha_deg,
        beta_deg,
        values,
        sigma,
        sigma_set_for_all_rows: BTreeSet::new(),
    })
}

/// Columns of the CSV of `datcom-rs run --format csv` (src/report/csv.rs) that a prediction
/// is read from: the ones that make it recognised as such, and its curve.
const RUN_CASE: &str = "case";
const RUN_CONDITION: &str = "condition";
const RUN_CONFIGURATION: &str = "configuration";
const RUN_ALPHA: &str = "alpha";
/// Its CL, CD and Cm.
const RUN_COEFFICIENTS: [&str; 3] = ["CL", "CD", "CM"];
/// Its columns that describe a flight condition: the same on every configuration's page of
/// one condition (a build-up prints several).
const RUN_FLIGHT_CONDITION: [&str; 6] = [
    "mach",
    "altitude",
    "velocity",
    "pressure",
    "temperature",
    "reynolds_per_length",
];

/// A prediction read from a CSV file, with what the reader has to say about it.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct PredictionFile {
    pub prediction: Prediction,
    /// For the CSV of `run`: which case, flight condition and configuration were read, out of
    /// how many.
    pub chosen: Option<String>,
    /// Angles of a `run` CSV left out (CL, CD or CM empty there).
    pub warnings: Vec<String>,
}

/// Reads a prediction from a CSV in either of two forms:
///
/// - a prediction table: `alpha_deg`, `CL`, `CD`, `Cm`, optionally `CL_tail`, `Cm_tail` (the
///   horizontal tail's contributions), rows in increasing alpha. It is one curve: `case` and
///   `condition` must be 1.
/// - the CSV of `datcom-rs run --format csv`, recognised by its `case`, `condition` and
///   `alpha` columns: case `case`, flight condition `condition` (1-based, in the order of the
///   run, as with a deck), that condition's last configuration (the most complete one of a
///   build-up), at the angles where CL, CD and CM are all given. It gives no tail
///   contributions.
///
/// A file with neither form's columns is [`DiscrepancyError::NotAPrediction`].
pub fn read_prediction(
    text: &str,
    file: &str,
    case: usize,
    condition: usize,
) -> Result<PredictionFile, DiscrepancyError> {
    let t = read_table(text, file)?;
    let read = if [RUN_CASE, RUN_CONDITION, RUN_ALPHA]
        .iter()
        .all(|c| t.index(c).is_some())
    {
        read_run_csv(&t, file, case, condition)
    } else {
        read_prediction_table(&t, file, case, condition)
    };
    read.map_err(|e| match e {
        DiscrepancyError::MissingColumn {
            file,
            column,
            found,
        } => DiscrepancyError::NotAPrediction {
            file,
            reason: format!("no column {column} (the header has: {found})"),
        },
        other => other,
    })
}

/// A prediction table (see [`read_prediction`]).
fn read_prediction_table(
    t: &Table,
    file: &str,
    case: usize,
    condition: usize,
) -> Result<PredictionFile, DiscrepancyError> {
    if (case, condition) != (1, 1) {
        return Err(DiscrepancyError::Invalid {
            reason: format!(
                "{file}: a prediction table is one curve, it has no case {case}, condition {condition} (--case and --condition choose in a deck given by --model or in the CSV of `run --format csv`)"
            ),
        });
    }
    let tail = |name: &str| -> Result<Option<Vec<f64>>, DiscrepancyError> {
        t.index(name).map(|_| t.required(name, file)).transpose()
    };
    let p = Prediction {
        alpha_deg: t.required("alpha_deg", file)?,
        cl: t.required("CL", file)?,
        cd: t.required("CD", file)?,
        cm: t.required("Cm", file)?,
        tail_cl: tail("CL_tail")?,
        tail_cm: tail("Cm_tail")?,
    };
    p.validate().map_err(|reason| DiscrepancyError::Invalid {
        reason: format!("{file}: {reason}"),
    })?;
    Ok(PredictionFile {
        prediction: p,
        chosen: None,
        warnings: Vec::new(),
    })
}

/// The CSV of `run` (see [`read_prediction`]).
fn read_run_csv(
    t: &Table,
    file: &str,
    case: usize,
    condition: usize,
) -> Result<PredictionFile, DiscrepancyError> {
    if t.rows.is_empty() {
        return Err(DiscrepancyError::Invalid {
            reason: format!("{file}: no data rows"),
        });
    }
    let cases = t.text(RUN_CASE);
    let pages = t.text(RUN_CONDITION);
    let flight: Vec<Vec<&str>> = RUN_FLIGHT_CONDITION.iter().map(|c| t.text(c)).collect();
    let same_flight = |r: usize| flight.iter().all(|col| col[r] == col[r - 1]);
    // Each row's case, flight condition within its case and page (configuration at one
    // condition), 0-based: a page is a run of rows with one `condition` number; consecutive
    // pages of one flight condition are its build-up's configurations.
    let mut keys: Vec<(usize, usize, usize)> = Vec::with_capacity(t.rows.len());
    let (mut c, mut f, mut p) = (0, 0, 0);
    for r in 0..t.rows.len() {
        if r > 0 && cases[r] != cases[r - 1] {
            (c, f, p) = (c + 1, 0, p + 1);
        } else if r > 0 && pages[r] != pages[r - 1] {
            p += 1;
            if !same_flight(r) {
                f += 1;
            }
        }
        keys.push((c, f, p));
    }
    let case_count = c + 1;
    if !(1..=case_count).contains(&case) {
        return Err(DiscrepancyError::NoPrediction {
            reason: format!("{file}: the run has no case {case} (it has {case_count})"),
        });
    }
    let in_case: Vec<usize> = (0..keys.len()).filter(|&r| keys[r].0 == case - 1).collect();
    let condition_count = in_case.iter().map(|&r| keys[r].1 + 1).max().unwrap_or(0);
    if !(1..=condition_count).contains(&condition) {
        return Err(DiscrepancyError::NoPrediction {
            reason: format!(
                "{file}: case {case} of the run has no flight condition {condition} (it has {condition_count})"
            ),
        });
    }
    let group: Vec<usize> = in_case
        .into_iter()
        .filter(|&r| keys[r].1 == condition - 1)
        .collect();
    let last_page = group.last().map_or(0, |&r| keys[r].2);
    let page_count = group
        .iter()
        .map(|&r| keys[r].2)
        .collect::<BTreeSet<_>>()
        .len();
    let rows: Vec<usize> = group
        .into_iter()
        .filter(|&r| keys[r].2 == last_page)
        .collect();
    let alpha = t.column(RUN_ALPHA, file)?;
    let [cl, cd, cm] = RUN_COEFFICIENTS.map(|c| t.column(c, file));
    let (cl, cd, cm) = (cl?, cd?, cm?);
    let alpha_text = t.text(RUN_ALPHA);
    let mut prediction = Prediction {
        alpha_deg: Vec::new(),
        cl: Vec::new(),
        cd: Vec::new(),
        cm: Vec::new(),
        tail_cl: None,
        tail_cm: None,
    };
    let mut warnings = Vec::new();
    for &r in &rows {
        match (alpha[r], cl[r], cd[r], cm[r]) {
            (Some(a), Some(l), Some(d), Some(m)) => {
                prediction.alpha_deg.push(a);
                prediction.cl.push(l);
                prediction.cd.push(d);
                prediction.cm.push(m);
            }
            _ => warnings.push(format!(
                "{file}:{}: alpha {} deg left out of the prediction: CL, CD or CM empty there",
                t.rows[r].0, alpha_text[r]
            )),
        }
    }
    let first = rows[0];
    let configuration = match t.text(RUN_CONFIGURATION)[first] {
        "" => String::new(),
        c => format!(", {c}"),
    };
    prediction.validate().map_err(|reason| {
        let left_out = match warnings.len() {
            0 => String::new(),
            n => format!(" ({n} angle(s) left out: CL, CD or CM empty there)"),
        };
        DiscrepancyError::NoPrediction {
            reason: format!(
                "{file}: case {case}, flight condition {condition}{configuration}: {reason}{left_out}"
            ),
        }
    })?;
    let at = match flight[1][first] {
        "" => format!("Mach {}", flight[0][first]),
        altitude => format!("Mach {}, altitude {altitude}", flight[0][first]),
    };
    let of_pages = if page_count > 1 {
        format!(" (the last of its {page_count} configurations)")
    } else {
        String::new()
    };
    let choose = if case_count > 1 || condition_count > 1 {
        "; choose another with --case and --condition"
    } else {
        ""
    };
    Ok(PredictionFile {
        prediction,
        chosen: Some(format!(
            "{file} is the CSV of run --format csv: read case {case} of {case_count}, flight condition {condition} of {condition_count} ({at}){configuration}{of_pages}{choose}"
        )),
        warnings,
    })
}

/// The noise standard deviation of `y(x)` (x increasing, at least 3 points) from how far
/// each point lies off the line through its neighbours (the estimator of Gasser, Sroka and
/// Jennen-Steinmetz, Biometrika 1986): with e_i = y_i − (a_i y_{i−1} + b_i y_{i+1}),
/// σ̂² = mean(e_i² / (1 + a_i² + b_i²)). A smooth curve's own curvature adds to it, so it is
/// an upper estimate where the curve bends sharply.
pub fn noise_estimate(x: &[f64], y: &[f64]) -> Option<f64> {
    let n = x.len().min(y.len());
    if n < 3 {
        return None;
    }
    let mut sum = 0.0;
    let mut count = 0;
    for i in 1..n - 1 {
        let span = x[i + 1] - x[i - 1];
        if span <= 0.0 {
            continue;
        }
        let a = (x[i + 1] - x[i]) / span;
        let b = (x[i] - x[i - 1]) / span;
        let e = y[i] - (a * y[i - 1] + b * y[i + 1]);
        sum += e * e / (1.0 + a * a + b * b);
        count += 1;
    }
    (count > 0).then(|| (sum / count as f64).sqrt())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_measurement_is_read_with_its_optional_columns() {
        let m = read_measurement(
            "alpha_deg,CL,CD,sigma_CL\n0,0.1,0.02,0.005\n2,0.3,,0.005\n",
            "m.csv",
        )
        .unwrap();
        assert_eq!(m.alpha_deg, vec![0.0, 2.0]);
        assert_eq!(m.beta_deg, vec![0.0, 0.0]);
        assert_eq!(m.values["CD"], vec![Some(0.02), None]);
        assert_eq!(m.sigma["CL"], vec![Some(0.005), Some(0.005)]);
    }

    #[test]
    fn errors_name_the_file_line_and_column() {
        let e = read_measurement("alpha_deg,CL\n0,0.1\n2,abc\n", "m.csv").unwrap_err();
        let s = e.to_string();
        assert!(
            s.contains("m.csv:3") && s.contains("CL") && s.contains("abc"),
            "{s}"
        );
        let e = read_measurement("alpha,CL\n0,0.1\n", "m.csv").unwrap_err();
        assert!(e.to_string().contains("alpha_deg"), "{e}");
    }

    #[test]
    fn the_run_csv_columns_read_are_those_run_writes() {
        let header = crate::report::csv::HEADER;
        for c in [RUN_CASE, RUN_CONDITION, RUN_CONFIGURATION, RUN_ALPHA]
            .into_iter()
            .chain(RUN_COEFFICIENTS)
            .chain(RUN_FLIGHT_CONDITION)
        {
            assert!(header.contains(&c), "{c} is not a column of run's CSV");
        }
    }

    /// Two cases; case 1 has two flight conditions, each a build-up of two pages (conditions
    /// 1-2 and 3-4 of the CSV); text in columns the reader does not use; an empty CL.
    const RUN_CSV: &str = "\
case,caseid,condition,configuration,mach,altitude,deriv_unit,alpha,CD,CL,CM,CLQ
1,\"UAV, TAIL\",1,WING-BODY CONFIGURATION,0.1,0,deg,0,0.02,0.1,0.01,NDM
1,\"UAV, TAIL\",1,WING-BODY CONFIGURATION,0.1,0,deg,4,0.03,0.4,-0.01,
1,\"UAV, TAIL\",2,WING-BODY-HORIZONTAL TAIL CONFIGURATION,0.1,0,deg,0,0.025,0.12,0.05,NDM
1,\"UAV, TAIL\",2,WING-BODY-HORIZONTAL TAIL CONFIGURATION,0.1,0,deg,4,0.035,0.5,-0.05,
1,\"UAV, TAIL\",2,WING-BODY-HORIZONTAL TAIL CONFIGURATION,0.1,0,deg,8,0.05,0.8,-0.1,
1,\"UAV, TAIL\",2,WING-BODY-HORIZONTAL TAIL CONFIGURATION,0.1,0,deg,12,0.07,,-0.2,
1,\"UAV, TAIL\",3,WING-BODY CONFIGURATION,0.2,0,deg,0,0.021,0.11,0.01,NDM
1,\"UAV, TAIL\",3,WING-BODY CONFIGURATION,0.2,0,deg,4,0.031,0.41,-0.01,
1,\"UAV, TAIL\",4,WING-BODY-HORIZONTAL TAIL CONFIGURATION,0.2,0,deg,0,0.026,0.13,0.06,NDM
1,\"UAV, TAIL\",4,WING-BODY-HORIZONTAL TAIL CONFIGURATION,0.2,0,deg,4,0.036,0.51,-0.06,
2,WING,1,WING ALONE CONFIGURATION,0.1,100,deg,0,0.01,0.0,0.0,
2,WING,1,WING ALONE CONFIGURATION,0.1,100,deg,5,0.02,0.4,-0.02,
";

    #[test]
    fn a_run_csv_gives_the_chosen_conditions_most_complete_configuration() {
        let r = read_prediction(RUN_CSV, "run.csv", 1, 1).unwrap();
        assert_eq!(r.prediction.alpha_deg, vec![0.0, 4.0, 8.0]);
        assert_eq!(r.prediction.cm, vec![0.05, -0.05, -0.1]);
        assert_eq!(r.prediction.tail_cl, None);
        assert_eq!(r.warnings.len(), 1, "{:?}", r.warnings);
        assert!(r.warnings[0].starts_with("run.csv:7: alpha 12 deg left out"));
        let chosen = r.chosen.unwrap();
        assert!(
            chosen.contains("case 1 of 2, flight condition 1 of 2 (Mach 0.1, altitude 0)")
                && chosen.contains("the last of its 2 configurations")
                && chosen.contains("choose another with --case and --condition"),
            "{chosen}"
        );
        let r = read_prediction(RUN_CSV, "run.csv", 1, 2).unwrap();
        assert_eq!(r.prediction.cl, vec![0.13, 0.51]);
        let r = read_prediction(RUN_CSV, "run.csv", 2, 1).unwrap();
        assert_eq!(r.prediction.cd, vec![0.01, 0.02]);
        for (case, condition, says) in [
            (3, 1, "no case 3 (it has 2)"),
            (2, 2, "no flight condition 2 (it has 1)"),
        ] {
            let e = read_prediction(RUN_CSV, "run.csv", case, condition).unwrap_err();
            assert!(e.to_string().contains(says), "{e}");
        }
        // No configuration column, no angle with CL, CD and CM: an error that says why.
        let empty = "case,condition,alpha,CL,CD,CM\n1,1,0,,,\n1,1,2,,,\n";
        let e = read_prediction(empty, "run.csv", 1, 1)
            .unwrap_err()
            .to_string();
        assert!(
            e.contains("flight condition 1: the prediction has 0 angle(s)")
                && e.contains("(2 angle(s) left out: CL, CD or CM empty there)"),
            "{e}"
        );
    }

    #[test]
    fn a_file_that_is_no_prediction_is_told_what_columns_are_expected() {
        let e = read_prediction("a,b\n1,2\n", "p.csv", 1, 1).unwrap_err();
        let s = e.to_string();
        assert!(
            s.contains("p.csv: not a prediction: no column alpha_deg")
                && s.contains("alpha_deg, CL, CD, Cm")
                && s.contains("run --format csv")
                && s.contains("case, condition, alpha, CL, CD, CM"),
            "{s}"
        );
        let table = "alpha_deg,CL,CD,Cm\n0,0.1,0.02,0\n4,0.4,0.03,-0.02\n";
        assert!(read_prediction(table, "p.csv", 1, 1).is_ok());
        let e = read_prediction(table, "p.csv", 1, 2).unwrap_err();
        assert!(e.to_string().contains("one curve"), "{e}");
    }

    #[test]
    fn the_noise_of_a_straight_line_is_zero_and_of_alternating_points_is_found() {
        let x: Vec<f64> = (0..20).map(f64::from).collect();
        let line: Vec<f64> = x.iter().map(|v| 2.0 * v + 1.0).collect();
        assert!(noise_estimate(&x, &line).unwrap() < 1e-12);
        // ±σ alternating about a line: e_i = ±2σ, weight 1.5: σ̂² = 4σ²/1.5.
        let zigzag: Vec<f64> = x
            .iter()
            .enumerate()
            .map(|(i, v)| v + if i % 2 == 0 { 0.01 } else { -0.01 })
            .collect();
        let s = noise_estimate(&x, &zigzag).unwrap();
        assert!((s - (4.0e-4_f64 / 1.5).sqrt()).abs() < 1e-12, "{s}");
    }
}
