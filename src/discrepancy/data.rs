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

/// A CSV table: header names and rows of optional numbers, with line numbers.
pub(crate) struct Table {
    header: Vec<String>,
    rows: Vec<(usize, Vec<Option<f64>>)>,
}

/// Reads a CSV table (`#` comment lines, cells trimmed, empty cells none); a cell that is not
/// a finite number is an error naming its file, line and column.
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
        let mut values = Vec::with_capacity(header.len());
        for (k, cell) in record.iter().enumerate() {
            if cell.is_empty() {
                values.push(None);
                continue;
            }
            match cell.parse::<f64>() {
                Ok(v) if v.is_finite() => values.push(Some(v)),
                _ => {
                    return Err(DiscrepancyError::BadNumber {
                        file: file.into(),
                        line,
                        column: header.get(k).cloned().unwrap_or_default(),
                        text: cell.to_string(),
                    })
                }
            }
        }
        rows.push((line, values));
    }
    Ok(Table { header, rows })
}

impl Table {
    fn index(&self, name: &str) -> Option<usize> {
        self.header.iter().position(|h| h == name)
    }

    /// Column `name`, every row given.
    pub(crate) fn required(&self, name: &str, file: &str) -> Result<Vec<f64>, DiscrepancyError> {
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
                r.get(k)
                    .copied()
                    .flatten()
                    .ok_or_else(|| DiscrepancyError::BadNumber {
                        file: file.into(),
                        line: *line,
                        column: name.into(),
                        text: String::new(),
                    })
            })
            .collect()
    }

    fn optional(&self, name: &str) -> Option<Vec<Option<f64>>> {
        let k = self.index(name)?;
        Some(
            self.rows
                .iter()
                .map(|(_, r)| r.get(k).copied().flatten())
                .collect(),
        )
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
        if let Some(v) = t.optional(c) {
            values.insert(c.to_string(), v);
        }
        if let Some(s) = t.optional(&format!("sigma_{c}")) {
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

/// Reads a prediction table: `alpha_deg`, `CL`, `CD`, `Cm`, optionally `CL_tail`, `Cm_tail`
/// (the horizontal tail's contributions), rows in increasing alpha.
pub fn read_prediction(text: &str, file: &str) -> Result<Prediction, DiscrepancyError> {
    let t = read_table(text, file)?;
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
    Ok(p)
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
