//! Text report: for each case and flight condition, the FLIGHT CONDITIONS and REFERENCE
//! DIMENSIONS block in the original's column layout, then the coefficient table.

use std::fmt::Write;

use super::{condition_view, derivative_view, reference_view};
use crate::case::units::unit_label;
use crate::deck::cards::{DerivUnit, Surface};
use crate::deck::schema::Dimension as D;
use crate::results::{CaseResults, ConditionResults, Results};

/// What a number field shows for a value that is not finite: not available, as the original
/// marks a value it does not give (the results say why in their warnings).
pub(crate) fn not_available(w: usize) -> String {
    format!("{:>w$}", "NA")
}

/// Fortran `1PEw.d`: one digit before the point, `d` after, exponent with sign and two digits;
/// NA for a value that is not finite.
pub fn fortran_e(v: f64, d: usize, w: usize) -> String {
    if !v.is_finite() {
        return not_available(w);
    }
    if v == 0.0 {
        return format!("{:>w$}", format!("{:.d$}E+00", 0.0));
    }
    let s = format!("{:.*E}", d, v);
    let (mant, exp) = s.split_once('E').unwrap_or((&s, "0"));
    let e: i32 = exp.parse().unwrap_or(0);
    let sign = if e < 0 { '-' } else { '+' };
    format!("{:>w$}", format!("{mant}E{sign}{:02}", e.abs()))
}

/// Fortran `Fw.d`, right-aligned; `******` when it does not fit, as the original prints; NA for
/// a value that is not finite.
pub fn fortran_f(v: f64, d: usize, w: usize) -> String {
    if !v.is_finite() {
        return not_available(w);
    }
    let s = format!("{v:>w$.d$}");
    if s.len() > w {
        "*".repeat(w)
    } else {
        s
    }
}

fn opt_f(v: Option<f64>, d: usize, w: usize) -> String {
    v.map_or_else(|| " ".repeat(w), |x| fortran_f(x, d, w))
}

fn opt_e(v: Option<f64>, w: usize) -> String {
    v.map_or_else(|| " ".repeat(w), |x| fortran_e(x, 4, w))
}

/// The FLIGHT CONDITIONS / REFERENCE DIMENSIONS block for one condition.
pub fn flight_conditions_block(case: &CaseResults, c: &ConditionResults) -> String {
    let dim = case.dim;
    let v = condition_view(c, dim);
    let (area, long, lat, xcg, zcg) = reference_view(case);
    let mut s = String::new();
    let _ = writeln!(
        s,
        " -----------------------  FLIGHT CONDITIONS  ------------------------           --------------  REFERENCE DIMENSIONS  ------------"
    );
    let _ = writeln!(
        s,
        "  MACH    ALTITUDE   VELOCITY    PRESSURE    TEMPERATURE     REYNOLDS             REF.      REFERENCE LENGTH   MOMENT REF. CENTER"
    );
    let _ = writeln!(
        s,
        " NUMBER                                                       NUMBER              AREA       LONG.     LAT.     HORIZ      VERT"
    );
    let _ = writeln!(
        s,
        "            {:>3}       {:>6}     {:>8}       {:>5}         {:>4}               {:>5}        {:>2}        {:>2}        {:>2}        {:>2}",
        unit_label(dim, D::Length),
        unit_label(dim, D::Velocity),
        unit_label(dim, D::Pressure),
        unit_label(dim, D::Temperature),
        unit_label(dim, D::PerLength),
        unit_label(dim, D::Area),
        unit_label(dim, D::Length),
        unit_label(dim, D::Length),
        unit_label(dim, D::Length),
        unit_label(dim, D::Length),
    );
    let _ = writeln!(
        s,
        "0{}   {}   {}   {}   {}     {}         {}   {}  {}  {}  {}",
        fortran_f(v.mach, 3, 6),
        opt_f(v.altitude, 2, 8),
        opt_f(v.velocity, 2, 8),
        opt_e(v.pressure, 10),
        opt_f(v.temperature, 3, 9),
        fortran_e(v.reynolds_per_length, 4, 10),
        opt_f(area, 3, 9),
        opt_f(long, 3, 8),
        opt_f(lat, 3, 8),
        fortran_f(xcg, 3, 8),
        fortran_f(zcg, 3, 8),
    );
    s
}

fn table(case: &CaseResults, c: &ConditionResults) -> String {
    let unit = case.deriv;
    let per = match unit {
        DerivUnit::Deg => "PER DEGREE",
        DerivUnit::Rad => "PER RADIAN",
    };
    let mut s = String::new();
    let _ = writeln!(s, "0{:>80}", format!("DERIVATIVE ({per})"));
    let _ = writeln!(
        s,
        "0 ALPHA     CD       CL       CM       CN       CA       XCP        CLA          CMA          CYB          CNB          CLB"
    );
    let st = &c.static_coefficients;
    let cell = |v: Option<f64>, w: usize, d: usize| {
        v.map_or_else(|| format!("{:>w$}", ""), |x| fortran_f(x, d, w))
    };
    let ecell = |v: Option<f64>| v.map_or_else(|| format!("{:>13}", ""), |x| fortran_e(x, 3, 13));
    for (i, a) in c.alpha_deg.iter().enumerate() {
        let at = |col: &Vec<Option<f64>>| col.get(i).copied().flatten();
        let dv = |col: &Vec<Option<f64>>| derivative_view(at(col), unit);
        let _ = writeln!(
            s,
            " {}{}{}{}{}{}{}{}{}{}{}{}",
            fortran_f(*a, 1, 7),
            cell(at(&st.cd), 9, 3),
            cell(at(&st.cl), 9, 3),
            cell(at(&st.cm), 9, 4),
            cell(at(&st.cn), 9, 3),
            cell(at(&st.ca), 9, 3),
            cell(at(&st.xcp), 9, 3),
            ecell(dv(&st.cla)),
            ecell(dv(&st.cma)),
            ecell(dv(&st.cyb)),
            ecell(dv(&st.cnb)),
            ecell(dv(&st.clb)),
        );
    }
    let computed = [&st.cd, &st.cl, &st.cm, &st.cla, &st.cyb, &st.clb]
        .iter()
        .any(|col| col.iter().any(Option::is_some));
    if !computed {
        let _ = writeln!(
            s,
            "  (no coefficients computed for this configuration: the warnings say why)"
        );
    }
    s
}

/// The title of the text report's result pages; the listing reader knows the report by it
/// ([`super::legacy::NotImported::TextReport`]: its tables are not in the listing's columns).
pub(crate) const TITLE: &str =
    "1         AUTOMATED STABILITY AND CONTROL METHODS PER APRIL 1976 VERSION OF DATCOM (datcom-rs)";

/// The whole text report.
pub fn to_string(results: &Results) -> String {
    let mut s = String::new();
    for case in &results.cases {
        s.push_str(&section_pages(case));
        for c in &case.conditions {
            let _ = writeln!(s, "{TITLE}");
            let _ = writeln!(
                s,
                "{:^120}",
                "CHARACTERISTICS AT ANGLE OF ATTACK AND IN SIDESLIP"
            );
            let _ = writeln!(s, "{:^120}", c.configuration);
            let _ = writeln!(s, "{:^120}", case.caseid.as_deref().unwrap_or(""));
            s.push_str(&flight_conditions_block(case, c));
            s.push_str(&table(case, c));
            super::for006::downwash_table(&mut s, c);
            s.push('\n');
            super::for006::dynamic_page(&mut s, case, c);
            if let Some(a) = &c.auxiliary {
                let view = super::auxiliary::view(a, case);
                let (_, _, _, xcg, zcg) = super::reference_view(case);
                let _ = writeln!(s, "\n{:^120}", "AUXILIARY AND PARTIAL OUTPUT (PART)");
                {
                    use crate::case::units::unit_label;
                    use crate::deck::schema::Dimension as D;
                    let _ = writeln!(
                        s,
                        "{:^120}",
                        format!(
                            "lengths in {}, areas in {}, drag on the reference area, lift-curve slopes per degree",
                            unit_label(case.dim, D::Length),
                            unit_label(case.dim, D::Area)
                        )
                    );
                }
                super::auxiliary::basic_properties(&mut s, &view, xcg, zcg);
                super::auxiliary::interference(&mut s, &view);
            }
        }
        s.push_str(&warning_lines(case));
    }
    s
}

/// A case's warnings, one line each, as the text report ends its case with them (and the
/// command line writes them to stderr with the formats that have no place for them).
pub fn warning_lines(case: &CaseResults) -> String {
    let mut s = String::new();
    for w in crate::warning::texts(&case.warnings) {
        let _ = writeln!(s, " warning (case {}): {w}", case.number);
    }
    s
}

/// Page title line of the original.
const PAGE_TITLE: &str =
    "1                             AUTOMATED STABILITY AND CONTROL METHODS PER APRIL 1976 VERSION OF DATCOM";

/// Right edges of the coordinate table's columns (F.5 fields).
const COORDINATE_EDGES: [usize; 7] = [16, 35, 53, 71, 92, 110, 124];

/// A `LABEL =   value` line of the characteristics page: the label right-aligned to the `=`
/// in column 56, the value F10.5, then the unit.
fn labelled(first: bool, label: &str, value: f64, unit: &str) -> String {
    let lead = if first { "0" } else { " " };
    format!(
        "{lead}{:>55}={}{unit}",
        format!("{label} "),
        fortran_f(value, 5, 10)
    )
}

/// The SECTION DEFINITION pages of a case (coordinate table, then characteristics), as the
/// original prints them before the flight conditions.
pub fn section_pages(case: &CaseResults) -> String {
    let mut s = String::new();
    for section in &case.sections {
        let name = format!("{} SECTION DEFINITION", section.surface.name());
        // The original's indents (AIRFOL formats): the surface line, and the designation line.
        let indent = match section.surface {
            Surface::Wing => 56,
            Surface::HorizontalTail => 51,
            Surface::VerticalTail => 52,
            Surface::VentralFin => 53,
        };
        let name = format!("{:indent$}{name}", "");
        if let Some(c) = &section.coordinates {
            let _ = writeln!(s, "{PAGE_TITLE}");
            let _ = writeln!(s, "{name}");
            let _ = writeln!(s, "{:62}{}", "", c.title);
            if let Some(sub) = &c.subtitle {
                let _ = writeln!(s, "{:62}{sub}", "");
            }
            let _ = writeln!(
                s,
                "     UPPER ABSCISSA     UPPER ORDINATE     LOWER ABSCISSA     LOWER ORDINATE      X-FRACTION CHORD    MEAN LINE    THICKNESS"
            );
            for r in &c.rows {
                let values = r.values();
                let mut line = String::new();
                let mut left = 0;
                for (v, right) in values.iter().zip(COORDINATE_EDGES) {
                    line.push_str(&fortran_f(*v, 5, right - left));
                    left = right;
                }
                let _ = writeln!(s, "{line}");
            }
        }
        if let Some(k) = &section.characteristics {
            let _ = writeln!(s, "{PAGE_TITLE}");
            let _ = writeln!(s, "{name}");
            let per_deg = std::f64::consts::PI / 180.0;
            let lines = [
                ("IDEAL ANGLE OF ATTACK", k.ideal_alpha_deg, " DEG."),
                ("ZERO LIFT ANGLE OF ATTACK", k.zero_lift_alpha_deg, " DEG."),
                ("IDEAL LIFT COEFFICIENT", k.ideal_cl, ""),
                ("ZERO LIFT PITCHING MOMENT COEFFICIENT", k.cm0, ""),
                (
                    "MACH ZERO LIFT-CURVE-SLOPE",
                    k.cla_mach0_per_rad * per_deg,
                    " /DEG.",
                ),
                (
                    "LEADING EDGE RADIUS",
                    k.leading_edge_radius,
                    " FRACTION CHORD",
                ),
                (
                    "MAXIMUM AIRFOIL THICKNESS",
                    k.max_thickness,
                    " FRACTION CHORD",
                ),
                ("DELTA-Y", k.delta_y_percent, " PERCENT CHORD"),
            ];
            for (i, (label, v, unit)) in lines.iter().enumerate() {
                let _ = writeln!(s, "{}", labelled(i == 0, label, *v, unit));
                let _ = writeln!(s);
            }
            for m in per_mach_lines(k) {
                let _ = writeln!(s, "{m}");
            }
        }
        // Each of a section's warnings (one per condition where they repeat), as ever.
        for w in &section.warnings {
            let _ = writeln!(s, " warning: {w}");
        }
    }
    s
}

/// One line per Mach number (the first condition of each), as the original prints them.
fn per_mach_lines(k: &crate::methods::section::SectionCharacteristics) -> Vec<String> {
    let per_deg = std::f64::consts::PI / 180.0;
    let mut seen: Vec<f64> = Vec::new();
    let mut out = Vec::new();
    for m in &k.per_mach {
        if seen.contains(&m.mach) {
            continue;
        }
        seen.push(m.mach);
        let slope = m
            .cla_per_rad
            .map_or("       NDM".to_string(), |v| fortran_f(v * per_deg, 5, 10));
        let xac = m
            .xac
            .map_or("       NDM".to_string(), |v| fortran_f(v, 5, 10));
        out.push(format!(
            "0{:>25}MACH={} LIFT-CURVE-SLOPE ={slope} /DEG.      XAC ={xac}",
            "",
            fortran_f(m.mach, 4, 7)
        ));
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fortran_formats() {
        assert_eq!(fortran_e(1967.62, 4, 10), "1.9676E+03");
        assert_eq!(fortran_e(-0.0006870, 3, 10), "-6.870E-04");
        assert_eq!(fortran_f(0.158, 3, 6), " 0.158");
        assert_eq!(fortran_f(123456.0, 3, 6), "******");
        for v in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
            assert_eq!(fortran_e(v, 4, 10), "        NA");
            assert_eq!(fortran_f(v, 3, 6), "    NA");
        }
    }
}
