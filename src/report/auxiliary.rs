//! The PART card's output in the deck's units: the `auxiliary` block of the JSON and the
//! CONFIGURATION AUXILIARY AND PARTIAL OUTPUT pages of the listing and the text report.

use std::fmt::Write;

use serde::Serialize;

use super::text::{fortran_e, fortran_f};
use crate::auxiliary::{AuxiliaryOutput, PlanformRow};
use crate::case::units::from_si;
use crate::deck::schema::Dimension;
use crate::results::CaseResults;

/// The auxiliary output in the deck's units (lengths in DIM units divided back by SCALE,
/// the interference line's slopes per degree).
#[derive(Debug, Clone, PartialEq, Serialize, Default)]
pub struct AuxiliaryJson {
    #[serde(skip_serializing_if = "Option::is_none")]
    pub body: Option<BodyJson>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub xcg_behind_mac_leading_edge: Option<f64>,
    pub planforms: Vec<PlanformJson>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub wing_body: Option<InterferenceJson>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub tail_body: Option<InterferenceJson>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub sidewash: Option<f64>,
    /// The body-vortex table (IV-B(W), GAMMA/(2*PI*ALPHA*V*R) at the wing; IV-B(H) and its
    /// GAMMA at the horizontal tail); `null` strength: the original's NDM.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub vortices: Option<VortexJson>,
    /// With DAMP: the wing's DYNAMIC DERIVATIVE INCREMENTALS, per radian as the original
    /// prints them.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub roll_increments: Option<IncrementsJson>,
    /// Clβ per degree of dihedral, per deg²: CLB/GAMMA.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub clb_per_dihedral: Option<f64>,
    /// ΔCm0 per degree of twist: (CMO/THETA)W, (CMO/THETA)H.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub wing_cm0_per_twist: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub tail_cm0_per_twist: Option<f64>,
}

/// The body-vortex table by column.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct VortexJson {
    pub alpha: Vec<f64>,
    pub wing_interference: Vec<Option<f64>>,
    pub wing_strength: Vec<Option<f64>>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub tail_interference: Option<Vec<Option<f64>>>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub tail_strength: Option<Vec<Option<f64>>>,
    /// IV-W(H): the wing's tip vortices at the tail.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub tail_wing_interference: Option<Vec<Option<f64>>>,
}

/// CLP(GAMMA=CL=0), CLP(GAMMA)/CLP (GAMMA=0), CNP/THETA, CYP/GAMMA, CYP/CL (CL=0).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct IncrementsJson {
    pub clp_zero_lift: f64,
    pub dihedral_factor: f64,
    pub cnp_per_twist: f64,
    pub cyp_dihedral: f64,
    pub cyp_per_cl: f64,
}

#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct BodyJson {
    pub wetted_area: f64,
    pub base_area: f64,
    pub zero_lift_drag: Option<f64>,
    pub base_drag: Option<f64>,
    pub friction_drag: Option<f64>,
    pub pressure_drag: Option<f64>,
}

#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct PlanformJson {
    pub surface: &'static str,
    pub theoretical: RowJson,
    pub exposed: RowJson,
    pub zero_lift_drag: Option<f64>,
    pub friction_coefficient: Option<f64>,
}

#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct RowJson {
    pub area: f64,
    pub taper_ratio: f64,
    pub aspect_ratio: f64,
    pub quarter_chord_sweep: f64,
    pub mac: f64,
    pub x_mac: f64,
    pub y_mac: f64,
}

/// An interference line (surface S = wing W or horizontal tail H): CLA-B(S) `cla_body`,
/// CLA-S(B) `cla_surface` (lift-curve slopes per degree, as the original prints them whatever
/// DERIV says, on the reference area), K-B(S) `k_body`, K-S(B) `k_surface`, XAC/C-B(S)
/// `xac_over_c`.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct InterferenceJson {
    pub cla_body: f64,
    pub cla_surface: f64,
    pub k_body: f64,
    pub k_surface: f64,
    pub xac_over_c: f64,
}

/// The auxiliary output of a condition of `case` in the deck's units.
pub fn view(a: &AuxiliaryOutput, case: &CaseResults) -> AuxiliaryJson {
    let s = case.scale;
    let len = |v: f64| from_si(v, case.dim, Dimension::Length) / s;
    let area = |v: f64| from_si(v, case.dim, Dimension::Area) / (s * s);
    let row = |r: &PlanformRow| RowJson {
        area: area(r.area),
        taper_ratio: r.taper_ratio,
        aspect_ratio: r.aspect_ratio,
        quarter_chord_sweep: r.quarter_chord_sweep_deg,
        mac: len(r.mac),
        x_mac: len(r.x_mac_quarter_chord),
        y_mac: len(r.y_mac),
    };
    // The original prints the interference lines per degree whatever DERIV says.
    let per = |per_rad: f64| per_rad * std::f64::consts::PI / 180.0;
    let interference = |w: crate::methods::wing_body::Auxiliary| InterferenceJson {
        cla_body: per(w.body_in_presence_of_wing_slope_per_rad),
        cla_surface: per(w.wing_in_presence_of_body_slope_per_rad),
        k_body: w.body_in_presence_of_wing,
        k_surface: w.wing_in_presence_of_body,
        xac_over_c: w.carry_over_centre,
    };
    AuxiliaryJson {
        body: a.body.map(|b| BodyJson {
            wetted_area: area(b.wetted_area),
            base_area: area(b.base_area),
            zero_lift_drag: b.zero_lift_drag,
            base_drag: b.base_drag,
            friction_drag: b.friction_drag,
            pressure_drag: b.pressure_drag,
        }),
        xcg_behind_mac_leading_edge: a.xcg_behind_mac_leading_edge.map(len),
        planforms: a
            .planforms
            .iter()
            .map(|p| PlanformJson {
                surface: p.surface.name(),
                theoretical: row(&p.theoretical),
                exposed: row(&p.exposed),
                zero_lift_drag: p.zero_lift_drag,
                friction_coefficient: p.friction_coefficient,
            })
            .collect(),
        wing_body: a.wing_body.map(interference),
        tail_body: a.tail_body.map(interference),
        sidewash: a.sidewash,
        vortices: a.vortices.as_ref().map(|v| {
            let interference = |r: &[crate::auxiliary::VortexAt]| {
                r.iter().map(|x| Some(x.interference_factor)).collect()
            };
            let strength =
                |r: &[crate::auxiliary::VortexAt]| r.iter().map(|x| x.strength).collect();
            VortexJson {
                alpha: v.alpha_deg.clone(),
                wing_interference: interference(&v.wing),
                wing_strength: strength(&v.wing),
                tail_interference: v.tail.as_deref().map(interference),
                tail_strength: v.tail.as_deref().map(strength),
                tail_wing_interference: v.tail_from_wing_vortices.clone(),
            }
        }),
        roll_increments: a.roll_increments.map(|r| IncrementsJson {
            clp_zero_lift: r.clp_zero_lift,
            dihedral_factor: r.dihedral_factor,
            cnp_per_twist: r.cnp_per_twist,
            cyp_dihedral: r.cyp_dihedral,
            cyp_per_cl: r.cyp_per_cl,
        }),
        clb_per_dihedral: a.clb_per_dihedral,
        wing_cm0_per_twist: a.wing_cm0_per_twist,
        tail_cm0_per_twist: a.tail_cm0_per_twist,
    }
}

/// Fortran `Ew.d` without a scale factor: `0.2817E+03`, right-aligned in `w`; NA for a value
/// that is not finite.
fn fortran_e0(v: f64, d: usize, w: usize) -> String {
    if !v.is_finite() {
        return super::text::not_available(w);
    }
    if v == 0.0 {
        return format!("{:>w$}", format!("0.{}E+00", "0".repeat(d)));
    }
    let s = format!("{:.*E}", d.saturating_sub(1), v.abs());
    let (mant, exp) = s.split_once('E').unwrap_or((&s, "0"));
    let digits: String = mant.chars().filter(char::is_ascii_digit).collect();
    let e = exp.parse::<i32>().unwrap_or(0) + 1;
    let sign = if v < 0.0 { "-" } else { "" };
    let esign = if e < 0 { '-' } else { '+' };
    format!("{:>w$}", format!("{sign}0.{digits}E{esign}{:02}", e.abs()))
}

/// `Ew.d` (no scale factor), or for no value `missing` followed by `pad` blanks within `w`.
fn e0_or(v: Option<f64>, d: usize, w: usize, missing: &str, pad: usize) -> String {
    v.map_or_else(
        || format!("{missing:>width$}{:pad$}", "", width = w - pad),
        |x| fortran_e0(x, d, w),
    )
}

/// The first page: BASIC BODY PROPERTIES, the moment reference centre on the wing's MAC and
/// BASIC PLANFORM PROPERTIES (the blocks the case has).
pub(crate) fn basic_properties(out: &mut String, a: &AuxiliaryJson, xcg: f64, zcg: f64) {
    if let Some(b) = &a.body {
        let _ = writeln!(out, "\n\n{:55}BASIC BODY PROPERTIES\n", "");
        let _ = writeln!(
            out,
            "            WETTED AREA      XCG     ZCG     BASE AREA     ZERO LIFT DRAG   BASE DRAG   FRICTION DRAG   PRESSURE DRAG"
        );
        let line = format!(
            "{}{}{}{}{}{}{}{}",
            fortran_e0(b.wetted_area, 4, 23),
            fortran_f(xcg, 2, 9),
            fortran_f(zcg, 2, 8),
            fortran_f(b.base_area, 4, 13),
            e0_or(b.zero_lift_drag, 4, 18, "NDM", 4),
            e0_or(b.base_drag, 4, 14, "NDM", 0),
            e0_or(b.friction_drag, 4, 14, "NDM", 0),
            e0_or(b.pressure_drag, 4, 16, "NA", 5),
        );
        let _ = writeln!(out, "{}", line.trim_end());
    }
    if let Some(x) = a.xcg_behind_mac_leading_edge {
        let _ = writeln!(
            out,
            "\n\n{:41}XCG RELATIVE TO THEORETICAL LEADING EDGE MAC={}",
            "",
            fortran_f(x, 2, 7)
        );
    }
    if a.planforms.is_empty() {
        return;
    }
    let _ = writeln!(out, "\n\n{:55}BASIC PLANFORM PROPERTIES\n", "");
    let _ = writeln!(
        out,
        "                                    TAPER     ASPECT   QUARTER CHORD             QUARTER CHORD              ZERO LIFT    FRICTION"
    );
    let _ = writeln!(
        out,
        "                         AREA       RATIO      RATIO       SWEEP        MAC        X(MAC)       Y(MAC)        DRAG     COEFFICIENT"
    );
    for p in &a.planforms {
        let indent = match p.surface {
            "WING" => 6,
            "HORIZONTAL TAIL" => 2,
            "VERTICAL TAIL" => 3,
            _ => 4,
        };
        let _ = writeln!(out, "0{:indent$}{}", "", p.surface);
        let row = |r: &RowJson| {
            format!(
                "+{}{}{}{}{}{}{}",
                fortran_e0(r.area, 4, 31),
                fortran_f(r.taper_ratio, 3, 9),
                fortran_e0(r.aspect_ratio, 4, 14),
                fortran_f(r.quarter_chord_sweep, 3, 10),
                fortran_e0(r.mac, 3, 13),
                fortran_e0(r.x_mac, 3, 13),
                fortran_e0(r.y_mac, 3, 13),
            )
        };
        let _ = writeln!(out, "   TOTAL THEORITICAL");
        let _ = writeln!(out, "{}", row(&p.theoretical));
        let _ = writeln!(out, "       TOTAL EXPOSED");
        let _ = writeln!(
            out,
            "{}{}{}",
            row(&p.exposed),
            e0_or(p.zero_lift_drag, 3, 13, "NA", 5),
            e0_or(p.friction_coefficient, 3, 13, "NA", 2),
        );
    }
}

/// The second page's interference lines and sidewash (nothing without a wing and a body).
pub(crate) fn interference(out: &mut String, a: &AuxiliaryJson) {
    for (w, s) in [(&a.wing_body, 'W'), (&a.tail_body, 'H')] {
        let Some(w) = w else { continue };
        let _ = writeln!(
            out,
            "0          CLA-B({s})={}     CLA-{s}(B)={}     K-B({s})={}     K-{s}(B)={}     XAC/C-B({s})={}",
            fortran_e(w.cla_body, 3, 10),
            fortran_e(w.cla_surface, 3, 10),
            fortran_e(w.k_body, 3, 10),
            fortran_e(w.k_surface, 3, 10),
            fortran_e(w.xac_over_c, 3, 10),
        );
    }
    if let Some(s) = a.sidewash {
        let _ = writeln!(
            out,
            "0{:38}SIDEWASH, (1 + D(SIGMA)/D(BETA))QV/Q ={}",
            "",
            fortran_e(s, 7, 14)
        );
    }
    if let Some(v) = &a.vortices {
        vortex_table(out, v);
    }
    // With DAMP: the increments, then CLB/GAMMA and the twist terms (NA without twist).
    let Some(r) = &a.roll_increments else { return };
    let _ = writeln!(out, "\n\n{:50}DYNAMIC DERIVATIVE INCREMENTALS", "");
    let _ = writeln!(
        out,
        "{:10}CLP(GAMMA=CL=0) ={}{:5}CLP(GAMMA)/CLP (GAMMA=0) ={}{:6}CNP/THETA ={}",
        "",
        fortran_e(r.clp_zero_lift, 4, 11),
        "",
        fortran_e(r.dihedral_factor, 4, 11),
        "",
        fortran_e(r.cnp_per_twist, 4, 11),
    );
    let _ = writeln!(
        out,
        "{:30}CYP/GAMMA ={}{:20}CYP/CL (CL=0) ={}\n",
        "",
        fortran_e(r.cyp_dihedral, 4, 11),
        "",
        fortran_e(r.cyp_per_cl, 4, 11),
    );
    let _ = writeln!(
        out,
        "{:45}CLB/GAMMA        (CMO/THETA)W     (CMO/THETA)H",
        ""
    );
    // Fields of 17 columns: a value E11.4 first, NA right-aligned in the first six.
    let value_first = |v: Option<f64>| match v {
        Some(x) => format!("{}{:6}", fortran_e0(x, 4, 11), ""),
        None => format!("{:>6}{:11}", "NA", ""),
    };
    let line = format!(
        "{:45}{}{}{}",
        "",
        value_first(a.clb_per_dihedral),
        value_first(a.wing_cm0_per_twist),
        value_first(a.tail_cm0_per_twist),
    );
    let _ = writeln!(out, "{}", line.trim_end());
}

/// Right edges of the body-vortex table's columns (ALPHA, IV-B(W), IV-W(H), IV-B(H), GAMMA,
/// GAMMA at the tail), as the original prints them.
const VORTEX_EDGES: [usize; 6] = [22, 39, 56, 73, 90, 115];

/// The body-vortex table. Without a horizontal tail its columns are NA, as the original
/// prints them.
fn vortex_table(out: &mut String, v: &VortexJson) {
    let _ = writeln!(
        out,
        "\n\n\n{:16}ALPHA{:9}IV-B(W){:10}IV-W(H){:10}IV-B(H){:10}GAMMA/{:18}GAMMA/",
        "", "", "", "", "", ""
    );
    let _ = writeln!(out, "{:78}2*PI*ALPHA*V*R{:9}(2*PI*ALPHA*V*R)T", "", "");
    let tail = v.tail_interference.is_some();
    for (k, alpha) in v.alpha.iter().enumerate() {
        let at =
            |c: &Option<Vec<Option<f64>>>| c.as_ref().and_then(|c| c.get(k).copied().flatten());
        // A missing value: its text `pad` columns before the field's right edge.
        let cell = |value: Option<f64>, missing: &str, width: usize, pad: usize| match value {
            Some(x) => fortran_e0(x, 4, width),
            None => format!("{missing:>w$}{:pad$}", "", w = width - pad),
        };
        let mut row = fortran_f(*alpha, 3, VORTEX_EDGES[0]);
        row.push_str(&cell(
            v.wing_interference.get(k).copied().flatten(),
            "NDM",
            17,
            5,
        ));
        row.push_str(&cell(
            at(&v.tail_wing_interference),
            tail_missing_text(tail),
            17,
            5,
        ));
        let tail_missing = if tail { "NDM" } else { "NA" };
        row.push_str(&cell(at(&v.tail_interference), tail_missing, 17, 5));
        row.push_str(&cell(
            v.wing_strength.get(k).copied().flatten(),
            "NDM",
            17,
            0,
        ));
        row.push_str(&cell(at(&v.tail_strength), tail_missing, 25, 3));
        let _ = writeln!(out, "{}", row.trim_end());
    }
}

/// The text of a missing tail value: NDM with a tail, NA without one.
fn tail_missing_text(tail: bool) -> &'static str {
    if tail {
        "NDM"
    } else {
        "NA"
    }
}

/// The body-vortex table's rows from the line after its second heading line.
fn read_vortex_rows(lines: &[&str]) -> Option<VortexJson> {
    let mut v = VortexJson {
        alpha: Vec::new(),
        wing_interference: Vec::new(),
        wing_strength: Vec::new(),
        tail_interference: Some(Vec::new()),
        tail_strength: Some(Vec::new()),
        tail_wing_interference: Some(Vec::new()),
    };
    let mut any_tail = false;
    for l in lines {
        let cell = |k: usize| {
            let left = if k == 0 { 0 } else { VORTEX_EDGES[k - 1] };
            l.get(left..VORTEX_EDGES[k].min(l.len()))
                .map(str::trim)
                .and_then(number)
        };
        let Some(alpha) = cell(0) else { break };
        v.alpha.push(alpha);
        v.wing_interference.push(cell(1));
        v.wing_strength.push(cell(4));
        let (tw, ti, ts) = (cell(2), cell(3), cell(5));
        any_tail |= tw.is_some() || ti.is_some() || ts.is_some();
        v.tail_wing_interference.as_mut()?.push(tw);
        v.tail_interference.as_mut()?.push(ti);
        v.tail_strength.as_mut()?.push(ts);
    }
    if !any_tail {
        v.tail_interference = None;
        v.tail_strength = None;
        v.tail_wing_interference = None;
    }
    (!v.alpha.is_empty()).then_some(v)
}

fn number(t: &str) -> Option<f64> {
    t.parse::<f64>().ok().filter(|v| v.is_finite())
}

/// A planform row's first seven numbers (area ... Y(MAC)) and the tokens after them.
fn planform_row(line: &str) -> Option<(RowJson, Vec<&str>)> {
    let w: Vec<&str> = line.get(1..)?.split_whitespace().collect();
    let v: Vec<f64> = w.iter().take(7).map(|t| number(t)).collect::<Option<_>>()?;
    let row = RowJson {
        area: *v.first()?,
        taper_ratio: *v.get(1)?,
        aspect_ratio: *v.get(2)?,
        quarter_chord_sweep: *v.get(3)?,
        mac: *v.get(4)?,
        x_mac: *v.get(5)?,
        y_mac: *v.get(6)?,
    };
    Some((row, w.into_iter().skip(7).collect()))
}

/// Reads the blocks of one CONFIGURATION AUXILIARY AND PARTIAL OUTPUT page (the lines after
/// its FLIGHT CONDITIONS block) into `into`: the basic body and planform properties, the
/// interference lines, the sidewash and the blocks after them, from our listings or the
/// original's. Rows of cranked planforms' panels are skipped.
pub fn read_page(lines: &[&str], into: &mut AuxiliaryJson) {
    let mut surface: Option<&'static str> = None;
    let mut theoretical: Option<RowJson> = None;
    for (k, l) in lines.iter().enumerate() {
        let t = l.trim();
        let t0 = t.trim_start_matches('0').trim();
        let next = lines.get(k + 1).copied().unwrap_or("");
        if t.starts_with("WETTED AREA") {
            let w: Vec<&str> = next.split_whitespace().collect();
            let at = |i: usize| w.get(i).and_then(|t| number(t));
            if let (Some(wet), Some(base)) = (at(0), at(3)) {
                into.body = Some(BodyJson {
                    wetted_area: wet,
                    base_area: base,
                    zero_lift_drag: at(4),
                    base_drag: at(5),
                    friction_drag: at(6),
                    pressure_drag: at(7),
                });
            }
        } else if let Some(v) = t0.strip_prefix("XCG RELATIVE TO THEORETICAL LEADING EDGE MAC=") {
            into.xcg_behind_mac_leading_edge = number(v.trim());
        } else if let Some(s) = ["WING", "HORIZONTAL TAIL", "VERTICAL TAIL", "VENTRAL FIN"]
            .into_iter()
            .find(|s| l.starts_with('0') && t0 == *s)
        {
            surface = Some(s);
            theoretical = None;
        } else if t == "TOTAL THEORITICAL" {
            theoretical = planform_row(next).map(|(r, _)| r);
        } else if t == "TOTAL EXPOSED" {
            if let (Some(s), Some(th), Some((ex, rest))) =
                (surface, theoretical.take(), planform_row(next))
            {
                into.planforms.push(PlanformJson {
                    surface: s,
                    theoretical: th,
                    exposed: ex,
                    zero_lift_drag: rest.first().and_then(|t| number(t)),
                    friction_coefficient: rest.get(1).and_then(|t| number(t)),
                });
            }
        } else if let Some(which) = ['W', 'H']
            .into_iter()
            .find(|s| t0.starts_with(&format!("CLA-B({s})=")))
        {
            let v: Vec<f64> = t0
                .split('=')
                .skip(1)
                .filter_map(|p| p.split_whitespace().next().and_then(number))
                .collect();
            if let [cla_body, cla_surface, k_body, k_surface, xac_over_c] = v[..] {
                let line = Some(InterferenceJson {
                    cla_body,
                    cla_surface,
                    k_body,
                    k_surface,
                    xac_over_c,
                });
                if which == 'W' {
                    into.wing_body = line;
                } else {
                    into.tail_body = line;
                }
            }
        } else if let Some(v) = t0.split("QV/Q =").nth(1) {
            into.sidewash = number(v.trim());
        } else if t0.starts_with("CLP(GAMMA=CL=0) =") {
            // The numbers after the `=` signs (the labels hold `=` too: GAMMA=CL=0).
            let after = |line: &str| -> Vec<f64> {
                line.split('=')
                    .skip(1)
                    .filter_map(|p| p.split_whitespace().next().and_then(number))
                    .collect()
            };
            let (first, second) = (after(t0), after(next));
            if let ([c, d, n], [y, l]) = (&first[..], &second[..]) {
                into.roll_increments = Some(IncrementsJson {
                    clp_zero_lift: *c,
                    dihedral_factor: *d,
                    cnp_per_twist: *n,
                    cyp_dihedral: *y,
                    cyp_per_cl: *l,
                });
            }
        } else if t0.starts_with("ALPHA") && t0.contains("IV-B(W)") {
            into.vortices = read_vortex_rows(lines.get(k + 2..).unwrap_or(&[]));
        } else if t0.starts_with("CLB/GAMMA") {
            let w: Vec<&str> = next.split_whitespace().collect();
            let at = |i: usize| w.get(i).and_then(|t| number(t));
            into.clb_per_dihedral = at(0);
            into.wing_cm0_per_twist = at(1);
            into.tail_cm0_per_twist = at(2);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::fortran_e0;

    #[test]
    fn e_format_without_scale_factor() {
        assert_eq!(fortran_e0(281.7, 4, 11), " 0.2817E+03");
        assert_eq!(fortran_e0(-0.0076123, 3, 10), "-0.761E-02");
        assert_eq!(fortran_e0(0.0, 4, 10), "0.0000E+00");
        assert_eq!(fortran_e0(1.0, 3, 10), " 0.100E+01");
    }
}
