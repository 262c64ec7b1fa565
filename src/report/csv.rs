//! CSV of `datcom-rs run --format csv`: one row per case, flight condition and angle of attack,
//! in the deck's units; empty cells where there is no value.

use super::{condition_view, derivative_view};
use crate::results::Results;

/// Column names, in order.
pub const HEADER: &[&str] = &[
    "case",
    "caseid",
    "condition",
    "configuration",
    "mach",
    "altitude",
    "velocity",
    "pressure",
    "temperature",
    "reynolds_per_length",
    "deriv_unit",
    "alpha",
    "CD",
    "CL",
    "CM",
    "CN",
    "CA",
    "XCP",
    "CLA",
    "CMA",
    "CYB",
    "CNB",
    "CLB",
    "CLQ",
    "CMQ",
    "CLAD",
    "CMAD",
    "CLP",
    "CYP",
    "CNP",
    "CNR",
    "CLR",
    "CYR",
];

fn cell(v: Option<f64>) -> String {
    v.map(|x| format!("{x}")).unwrap_or_default()
}

fn quote(s: &str) -> String {
    if s.contains([',', '"', '\n']) {
        format!("\"{}\"", s.replace('"', "\"\""))
    } else {
        s.to_string()
    }
}

/// The CSV text of a deck's results.
pub fn to_string(results: &Results) -> String {
    let mut out = HEADER.join(",");
    out.push('\n');
    for case in &results.cases {
        let unit = case.deriv;
        for (k, c) in case.conditions.iter().enumerate() {
            let v = condition_view(c, case.dim);
            let s = &c.static_coefficients;
            for (i, alpha) in c.alpha_deg.iter().enumerate() {
                let at = |col: &Vec<Option<f64>>| col.get(i).copied().flatten();
                let dd = |col: &Vec<Option<f64>>| cell(derivative_view(at(col), unit));
                let mut row = vec![
                    case.number.to_string(),
                    quote(case.caseid.as_deref().unwrap_or("")),
                    (k + 1).to_string(),
                    quote(&c.configuration),
                    format!("{}", v.mach),
                    cell(v.altitude),
                    cell(v.velocity),
                    cell(v.pressure),
                    cell(v.temperature),
                    format!("{}", v.reynolds_per_length),
                    format!("{unit:?}").to_lowercase(),
                    format!("{alpha}"),
                    cell(at(&s.cd)),
                    cell(at(&s.cl)),
                    cell(at(&s.cm)),
                    cell(at(&s.cn)),
                    cell(at(&s.ca)),
                    cell(at(&s.xcp)),
                    dd(&s.cla),
                    dd(&s.cma),
                    dd(&s.cyb),
                    dd(&s.cnb),
                    dd(&s.clb),
                ];
                match &c.dynamic {
                    Some(y) => {
                        for (name, col) in y.columns() {
                            // No DATCOM method: `NDM` in the first row, as the original.
                            if i == 0 && y.no_method.contains(&name) {
                                row.push("NDM".into());
                            } else {
                                row.push(dd(col));
                            }
                        }
                    }
                    None => row.extend(std::iter::repeat_n(String::new(), 9)),
                }
                // Extension: the vertical panels' CYr, empty where there is none.
                row.push(
                    c.dynamic
                        .as_ref()
                        .and_then(|y| y.cyr.as_ref())
                        .map(dd)
                        .unwrap_or_default(),
                );
                out.push_str(&row.join(","));
                out.push('\n');
            }
        }
    }
    out
}
