//! `--format for006`: results as pages in the original program's layout (page title, page
//! kind, configuration, CASEID, FLIGHT CONDITIONS block, tables in its fixed columns), so that
//! the listing readers users already have keep working. Blank where there is no value, as the
//! original prints it.

use std::fmt::Write;

use super::derivative_view;
use super::legacy::{DOWNWASH_COLUMNS, DOWNWASH_HEADING, DYNAMIC_COLUMNS, STATIC_COLUMNS};
use super::text::{flight_conditions_block, fortran_e, fortran_f};
use crate::deck::cards::DerivUnit;
use crate::results::{CaseResults, ConditionResults, Results};

const TITLE: &str = "1                               AUTOMATED STABILITY AND CONTROL METHODS PER APRIL 1976 VERSION OF DATCOM";

/// Decimals of each static column after ALPHA (F formats; 0 marks an E format).
const STATIC_DECIMALS: [usize; 11] = [3, 3, 4, 3, 3, 3, 0, 0, 0, 0, 0];

fn centred(text: &str) -> String {
    format!("{:^120}", text).trim_end().to_string()
}

fn field(v: Option<f64>, width: usize, decimals: usize) -> String {
    match v {
        None => " ".repeat(width),
        Some(x) if decimals == 0 => fortran_e(x, 3, width),
        Some(x) => fortran_f(x, decimals, width),
    }
}

fn widths(columns: &[(&str, usize)]) -> Vec<usize> {
    let mut left = 0;
    columns
        .iter()
        .map(|(_, right)| {
            let w = right - left;
            left = *right;
            w
        })
        .collect()
}

fn header(out: &mut String, kind: &str, case: &CaseResults, c: &ConditionResults) {
    let _ = writeln!(out, "{TITLE}");
    let _ = writeln!(out, "{}", centred(kind));
    let _ = writeln!(out, "{}", centred(&c.configuration));
    let _ = writeln!(out, "{}", centred(case.caseid.as_deref().unwrap_or("")));
    let _ = writeln!(out, " ");
    out.push_str(&flight_conditions_block(case, c));
}

fn unit_name(u: DerivUnit) -> &'static str {
    match u {
        DerivUnit::Deg => "PER DEGREE",
        DerivUnit::Rad => "PER RADIAN",
    }
}

fn static_page(out: &mut String, case: &CaseResults, c: &ConditionResults) {
    header(
        out,
        "CHARACTERISTICS AT ANGLE OF ATTACK AND IN SIDESLIP",
        case,
        c,
    );
    let u = case.deriv;
    let _ = writeln!(
        out,
        "0{:>63}-------------------DERIVATIVE ({})-------------------",
        "",
        unit_name(u)
    );
    let _ = writeln!(
        out,
        "0 ALPHA     CD       CL       CM       CN       CA       XCP        CLA          CMA          CYB          CNB          CLB"
    );
    let _ = writeln!(out, "0");
    let s = &c.static_coefficients;
    let w = widths(&STATIC_COLUMNS);
    let cols = [
        &s.cd, &s.cl, &s.cm, &s.cn, &s.ca, &s.xcp, &s.cla, &s.cma, &s.cyb, &s.cnb, &s.clb,
    ];
    for (i, a) in c.alpha_deg.iter().enumerate() {
        let mut row = fortran_f(*a, 1, w[0]);
        for (k, col) in cols.iter().enumerate() {
            let v = col.get(i).copied().flatten();
            let v = if STATIC_DECIMALS[k] == 0 {
                derivative_view(v, u)
            } else {
                v
            };
            row.push_str(&field(v, w[k + 1], STATIC_DECIMALS[k]));
        }
        let _ = writeln!(out, "{}", row.trim_end());
    }
}

/// The downwash table under a page with a horizontal tail (nothing without one); the text
/// report prints the same table.
pub(crate) fn downwash_table(out: &mut String, c: &ConditionResults) {
    let Some(d) = &c.downwash else { return };
    let _ = writeln!(out, "{DOWNWASH_HEADING}");
    let _ = writeln!(out, "0");
    let w = widths(&DOWNWASH_COLUMNS);
    for (i, a) in c.alpha_deg.iter().enumerate() {
        let at = |col: &Vec<Option<f64>>| col.get(i).copied().flatten();
        let row = format!(
            "{}{}{}{}",
            fortran_f(*a, 1, w[0]),
            field(at(&d.dynamic_pressure_ratio), w[1], 3),
            field(at(&d.epsilon_deg), w[2], 3),
            field(at(&d.gradient), w[3], 3),
        );
        let _ = writeln!(out, "{}", row.trim_end());
    }
}

/// The DYNAMIC DERIVATIVES page of a condition (nothing without DAMP); the text report prints
/// the same page.
pub(crate) fn dynamic_page(out: &mut String, case: &CaseResults, c: &ConditionResults) {
    let Some(d) = &c.dynamic else { return };
    header(out, "DYNAMIC DERIVATIVES", case, c);
    let u = case.deriv;
    let _ = writeln!(out, "{:>52}DYNAMIC DERIVATIVES ({})", "", unit_name(u));
    let _ = writeln!(
        out,
        "0           -------PITCHING-------    -----ACCELERATION------    --------------ROLLING--------------    --------YAWING--------"
    );
    let _ = writeln!(
        out,
        "0   ALPHA       CLQ          CMQ           CLAD         CMAD         CLP          CYP          CNP          CNR          CLR"
    );
    let _ = writeln!(out, "0");
    let w = widths(&DYNAMIC_COLUMNS);
    for (i, a) in c.alpha_deg.iter().enumerate() {
        let mut row = fortran_f(*a, 2, w[0]);
        for (k, (name, col)) in d.columns().iter().enumerate() {
            if i == 0 && d.no_method.contains(name) {
                // The original's NDM: three letters four places left of the field's end.
                row.push_str(&format!("{:>width$}    ", "NDM", width = w[k + 1] - 4));
                continue;
            }
            let v = derivative_view(col.get(i).copied().flatten(), u);
            row.push_str(&field(v, w[k + 1], 0));
        }
        let _ = writeln!(out, "{}", row.trim_end());
    }
    if !d.no_method.is_empty() {
        let _ = writeln!(out, "0*** NDM PRINTED WHEN NO DATCOM METHODS EXIST");
    }
}

/// With PART, the CONFIGURATION AUXILIARY AND PARTIAL OUTPUT pages of a condition: the basic
/// properties, then (with a wing and a body) the interference line.
fn auxiliary_pages(out: &mut String, case: &CaseResults, c: &ConditionResults) {
    let Some(a) = &c.auxiliary else { return };
    let view = super::auxiliary::view(a, case);
    let (_, _, _, xcg, zcg) = super::reference_view(case);
    const KIND: &str = "CONFIGURATION AUXILIARY AND PARTIAL OUTPUT";
    header(out, KIND, case, c);
    super::auxiliary::basic_properties(out, &view, xcg, zcg);
    if view.wing_body.is_some() {
        header(out, KIND, case, c);
        super::auxiliary::interference(out, &view);
    }
}

/// The whole listing: for each case, the input-card marker the original opens a case with,
/// then per condition the static page and, with DAMP, the dynamic page.
pub fn to_string(results: &Results) -> String {
    let mut out = String::new();
    for case in &results.cases {
        let _ = writeln!(
            out,
            "1          THE FOLLOWING IS A LIST OF ALL INPUT CARDS FOR THIS CASE."
        );
        let _ = writeln!(out, "0");
        out.push_str(&super::text::section_pages(case));
        for c in &case.conditions {
            static_page(&mut out, case, c);
            downwash_table(&mut out, c);
            dynamic_page(&mut out, case, c);
            auxiliary_pages(&mut out, case, c);
        }
    }
    out
}
