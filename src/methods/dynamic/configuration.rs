//! Wing-body, vertical tail, ventral fin and the configurations with tails: DATCOM 7.3 and 7.4
//! as the original's DNPAWB, DNPWBT, SUBWBT, CLRDER and M46O56 form them.

use serde::Serialize;

use super::{finite, Column, Dynamic, DynamicError, DynamicWarning};
use crate::case::Case;
use crate::geometry::{planform as planform_geometry, Span};
use crate::methods::lateral::{
    fin_lateral, twin_panel_lateral, twin_panels_counted, ventral_fin_left_out, Fin,
};
use crate::methods::tail::{tail_position, ConfigurationTotals};
use crate::methods::wing::{quarter_chord_sweep, ForwardSweepReading, WingType};
use crate::methods::wing_body::WingBody;

/// Wing to horizontal-tail semispan ratio from which the tail's pitch-rate increment takes the
/// α̇ term (the original's DNPWBT branch for conventional tails).
const CONVENTIONAL_SPAN_RATIO: f64 = 1.5;

/// The wing-body's dynamic derivatives (DATCOM 7.3; the original's DNPAWB, WINGYW, CLRDER):
/// CLq, Cmq (and CLα̇, Cmα̇ where the wing has a method) = (K_W(B) + K_B(W))·wing + body on the
/// first row, K of the wing-body lift; the roll and yaw derivatives and Clr are the wing's (no
/// body term, as the original).
pub fn wing_body_dynamic(wing: &Dynamic, body: &Dynamic, wing_body: &WingBody) -> Dynamic {
    let n = wing.alpha_deg.len();
    let f = &wing_body.terms.interference;
    let k = f.wing_in_presence_of_body + f.body_in_presence_of_wing;
    let combine = |w: &Column, b: &Column| match w {
        Column::NoMethod => Column::NoMethod,
        Column::Rows(_) => Column::first(
            n,
            match (w.at(0), b) {
                (Some(wv), Column::NoMethod) => finite(k * wv),
                (Some(wv), b) => b.at(0).and_then(|bv| finite(k * wv + bv)),
                (None, _) => None,
            },
        ),
    };
    let mut out = Dynamic::no_method(&wing.alpha_deg);
    out.clq = combine(&wing.clq, &body.clq);
    out.cmq = combine(&wing.cmq, &body.cmq);
    out.clad = combine(&wing.clad, &body.clad);
    out.cmad = combine(&wing.cmad, &body.cmad);
    out.clp = wing.clp.clone();
    out.cyp = wing.cyp.clone();
    out.cnp = wing.cnp.clone();
    out.cnr = wing.cnr.clone();
    out.clr = wing.clr.clone();
    out.warnings = wing.warnings.clone();
    for w in &body.warnings {
        if !out.warnings.contains(w) {
            out.warnings.push(w.clone());
        }
    }
    out
}

/// The vertical tail's or ventral fin's roll and yaw terms (DATCOM 7.4.2.1 Clp, 7.4.2.2 CYp and
/// Cnp, 7.4.3.1 Cnr, 7.4.3.2 Clr; the original's SUBWBT and CLRDER), per rad at every angle,
/// from the panel's CYβ (with sidewash) and the arms of its MAC, l (aft of XCG) and z (above
/// ZCG): with Z = z cos α − l sin α, L = l cos α + z sin α and b the lateral reference length,
/// CYp = 2(Z − z)/b·CYβ, Cnp = −2L(Z − z)/b²·CYβ, Cnr = 2L²/b²·CYβ, Clp = 2Z(Z − z)/b²·CYβ,
/// Clr = −2LZ/b²·CYβ; and, as an extension the original does not print, CYr = −2L/b·CYβ, the
/// side force whose moments about the reference centre are those Cnr and Clr. The pitch-rate
/// columns have no method of their own.
///
/// For the ventral fin the original writes CYp with (2Z − z), takes the vertical tail's CYβ in
/// Cnr and Clp, and computes the fin's planform (its MAC, hence l, and its CYβ) with the
/// vertical tail's sweep angles; we use the fin's own planform and terms (docs/dynamic.md).
pub fn fin_dynamic(
    case: &Case,
    condition_index: usize,
    alpha_deg: &[f64],
    fin: Fin,
) -> Result<Dynamic, DynamicError> {
    let lateral =
        fin_lateral(case, condition_index, alpha_deg, fin).map_err(|e| DynamicError::Geometry {
            reason: e.to_string(),
        })?;
    let terms = lateral
        .fin_terms
        .as_ref()
        .ok_or_else(|| DynamicError::Geometry {
            reason: "the fin's sideslip terms are missing".into(),
        })?;
    let b = crate::methods::lateral::lateral_reference_length(case).ok_or_else(|| {
        DynamicError::Geometry {
            reason: "no lateral reference length: give BLREF in $OPTINS".into(),
        }
    })?;
    let mut cyb = lateral.cyb.first().copied().flatten();
    // The original's vertical tail CYβ holds the twin panels' side force (SUBLAT adds it up to
    // STMACH), and its rate derivatives take it so, at the vertical tail's arms.
    if fin == Fin::VerticalTail && twin_panels_counted(case, condition_index) {
        let twin = twin_panel_lateral(case, alpha_deg).map_err(|e| DynamicError::Geometry {
            reason: e.to_string(),
        })?;
        cyb = cyb
            .zip(twin.cyb.first().copied().flatten())
            .map(|(v, t)| v + t);
    }
    let (l, z) = (terms.arm_x, terms.arm_z);
    let mut out = Dynamic::no_method(alpha_deg);
    let each = |f: &dyn Fn(f64, f64, f64) -> f64| {
        Column::rows(
            alpha_deg
                .iter()
                .map(|a| {
                    let (sin, cos) = a.to_radians().sin_cos();
                    let zz = z * cos - l * sin;
                    let ll = l * cos + z * sin;
                    cyb.map(|c| f(c, zz, ll))
                })
                .collect(),
        )
    };
    out.cyp = each(&|c, zz, _| 2.0 * (zz - z) * c / b);
    out.cnp = each(&|c, zz, ll| -(ll * 2.0 * (zz - z)) * c / (b * b));
    out.cnr = each(&|c, _, ll| 2.0 * ll * ll * c / (b * b));
    out.clp = each(&|c, zz, _| 2.0 * c * zz * (zz - z) / (b * b));
    out.clr = each(&|c, zz, ll| -2.0 * c * ll * zz / (b * b));
    out.cyr = each(&|c, _, ll| -2.0 * ll * c / b);
    if case.forward_sweep == ForwardSweepReading::Original && wing_swept_forward(case) {
        // The original computes the fins' Clp and Clr with the configuration's Clr (CLRDER)
        // and skips all three for a forward-swept wing (docs/differences.md).
        out.clp = Column::NoMethod;
        out.clr = Column::NoMethod;
        out.warnings.push(DynamicWarning::FinRollTermsLeftOut);
    }
    Ok(out)
}

/// The wing's quarter chord is swept forward (the wing methods' sweep): DATCOM 7.1.3.2 has
/// no Clr method for it.
fn wing_swept_forward(case: &Case) -> bool {
    case.wing
        .as_ref()
        .and_then(|w| planform_geometry(w, Span::Both).ok())
        .is_some_and(|g| quarter_chord_sweep(&g).deg < 0.0)
}

/// Which configuration with tails.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum TailConfiguration {
    WingBodyHorizontalTail,
    WingBodyVerticalTail,
    /// With the ventral fin, when the case has one.
    WingBodyVerticalTailHorizontalTail,
}

/// A configuration's derivatives and the component terms they sum.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ConfigurationDynamic {
    pub total: Dynamic,
    /// The terms, named: "wing-body", "horizontal tail" (its increments in the presence of the
    /// wing and body), "vertical tail", "ventral fin".
    pub parts: Vec<(&'static str, Dynamic)>,
}

/// The dynamic derivatives of a configuration with tails (DATCOM 7.4; the original's DNPWBT,
/// SUBWBT, CLRDER and M46O56 sums), per rad, the sum of the terms of
///
/// - the wing-body;
/// - the horizontal tail: CLq + 2(K_H(B) + K_B(H)) CLα_H (q/q∞)(l_H/c̄) and Cmq − the same
///   times l_H/c̄ on the first row, CLα̇ and Cmα̇ the same times dε/dα at every angle (the
///   tail's terms alone where the wing-body has no α̇ method, as the original), l_H from XCG to
///   the tail's aerodynamic centre, no α̇ term for a wing semispan under 1.5 tail semispans;
///   for a canard configuration (no downwash table) q/q∞ is the canard's wake and the lift
///   slope ΔCLα the canard's vortices induce on the aft surface joins the pitch-rate
///   increment, (2 (K_H(B) + K_B(H)) CLα_H q/q∞ + ΔCLα) l_H/c̄, and with a pointed canard
///   (exposed taper 0) gives CLα̇ −2 (l_H/c̄) ΔCLα and Cmα̇ +2 (l_H/c̄)² ΔCLα (DNPWBT);
///   its (halved) Clp; nothing else;
/// - the vertical tail and the ventral fin: [`fin_dynamic`] (Clp, CYp, Cnp, Cnr, Clr).
///
/// Two rules of the original override the sums: the wing-body-horizontal tail has no Clr
/// method, and with a wing other than straight-tapered there is no pitch-rate or α̇ method.
/// `wing_body` the wing-body's derivatives, `tail` the horizontal tail alone's
/// ([`super::horizontal_tail_dynamic`]), `totals` the longitudinal totals (downwash, q/q∞,
/// tail-body factors, the tail alone).
pub fn wing_body_tail_dynamic(
    case: &Case,
    condition_index: usize,
    configuration: TailConfiguration,
    wing_body: &Dynamic,
    tail: Option<&Dynamic>,
    totals: &ConfigurationTotals,
) -> Result<ConfigurationDynamic, DynamicError> {
    let alpha = &wing_body.alpha_deg;
    let n = alpha.len();
    let with_tail = configuration != TailConfiguration::WingBodyVerticalTail;
    let with_fins = configuration != TailConfiguration::WingBodyHorizontalTail;
    let mut parts = vec![("wing-body", wing_body.clone())];
    // The wing-body's α̇ derivatives by the triangular-wing method are one value for the
    // linear range: its page prints it once, and a configuration with the horizontal tail
    // (whose downwash-lag term varies with angle) holds it at every angle, as the original
    // sums it (lkampoli ex4 with DAMP: every row of CLAD agrees); without the tail the
    // original prints it once, as the wing-body's.
    if with_tail {
        let wb = &mut parts[0].1;
        for column in [&mut wb.clad, &mut wb.cmad] {
            if let Column::Rows(rows) = column {
                if rows.len() > 1 && rows[1..].iter().all(Option::is_none) {
                    let first = rows[0];
                    rows.fill(first);
                }
            }
        }
    }
    if with_tail {
        let mut ht = Dynamic::no_method(alpha);
        pitch_increments(case, wing_body, totals, &mut ht)?;
        if let Some(t) = tail {
            ht.clp = t.clp.clone();
            ht.warnings = t.warnings.clone();
        }
        parts.push(("horizontal tail", ht));
    }
    if with_fins {
        for (present, fin, name) in [
            (
                case.vertical_tail.is_some(),
                Fin::VerticalTail,
                "vertical tail",
            ),
            (
                case.ventral_fin.is_some() && !ventral_fin_left_out(case),
                Fin::VentralFin,
                "ventral fin",
            ),
        ] {
            if present {
                parts.push((name, fin_dynamic(case, condition_index, alpha, fin)?));
            }
        }
    }
    let sum = |pick: fn(&Dynamic) -> &Column| {
        let cols: Vec<&Column> = parts.iter().map(|(_, d)| pick(d)).collect();
        Column::sum(&cols, n)
    };
    let mut total = Dynamic::no_method(alpha);
    if with_fins && ventral_fin_left_out(case) {
        total.warnings.push(DynamicWarning::VentralFinLeftOut);
    }
    total.clq = sum(|d| &d.clq).first_row_only();
    total.cmq = sum(|d| &d.cmq).first_row_only();
    total.clad = sum(|d| &d.clad);
    total.cmad = sum(|d| &d.cmad);
    total.clp = sum(|d| &d.clp);
    total.cyp = sum(|d| &d.cyp);
    total.cnp = sum(|d| &d.cnp);
    total.cnr = sum(|d| &d.cnr);
    total.clr = sum(|d| &d.clr);
    total.cyr = sum(|d| &d.cyr);
    // Without the wing's Clr (a forward-swept quarter chord) the configuration has none: the
    // fins' terms alone are not its Clr (the original prints NDM).
    if !with_fins || wing_swept_forward(case) {
        total.clr = Column::NoMethod;
    }
    if !with_fins {
        total.cyr = Column::NoMethod;
    }
    // With a double-delta or cranked wing there is no tail pitch-rate or α̇ method: the
    // configurations with the horizontal tail have none, the wing-body-vertical tail the
    // wing-body's pitch-rate terms (as the original prints them).
    if totals.terms.wing_body.terms.wing.planform_type != WingType::Straight {
        if with_tail {
            total.clq = Column::NoMethod;
            total.cmq = Column::NoMethod;
        }
        total.clad = Column::NoMethod;
        total.cmad = Column::NoMethod;
    }
    for (_, d) in &parts {
        for w in &d.warnings {
            if !total.warnings.contains(w) {
                total.warnings.push(w.clone());
            }
        }
    }
    Ok(ConfigurationDynamic { total, parts })
}

/// The horizontal tail's pitch-rate and α̇ increments (DNPWBT) into `out` (which starts
/// without a method): CLq and Cmq on the first row, CLα̇ and Cmα̇ at every angle.
fn pitch_increments(
    case: &Case,
    wing_body: &Dynamic,
    totals: &ConfigurationTotals,
    out: &mut Dynamic,
) -> Result<(), DynamicError> {
    let n = wing_body.alpha_deg.len();
    let t = &totals.terms;
    let (Some(tail), Some(tail_body)) = (&t.horizontal_tail, &t.tail_body) else {
        return Ok(());
    };
    // q/q∞ and dε/dα at the tail, and for a canard configuration the lift slope the canard's
    // vortices induce on the aft surface (per rad).
    type Rows<'a> = &'a [Option<f64>];
    let (dynamic_pressure_ratio, gradient, canard_slope): (Rows, Rows, Vec<Option<f64>>) =
        match (&t.downwash, &t.canard) {
            (Some(d), _) => (&d.dynamic_pressure_ratio, &d.gradient, vec![Some(0.0); n]),
            (None, Some(c)) => (
                &c.dynamic_pressure_ratio,
                &[],
                c.vortex
                    .at_angle
                    .iter()
                    .map(|a| a.map(|a| a.lift_slope_per_rad))
                    .collect(),
            ),
            (None, None) => return Ok(()),
        };
    let ht = case
        .horizontal_tail
        .as_ref()
        .ok_or_else(|| DynamicError::Geometry {
            reason: "the case has no horizontal tail".into(),
        })?;
    let wing = case.wing.as_ref().ok_or_else(|| DynamicError::Geometry {
        reason: "the case has no wing".into(),
    })?;
    let k = tail_body.interference.wing_in_presence_of_body
        + tail_body.interference.body_in_presence_of_wing;
    let surface = &tail.surface;
    let p = &surface.terms.planform;
    let Some(moment) = surface.terms.pitching_moment.as_ref() else {
        return Ok(());
    };
    let (xh, _) = tail_position(case.synthesis.as_ref());
    let xcg = case.synthesis.as_ref().and_then(|s| s.xcg).unwrap_or(0.0);
    let semispan = ht.sspn.unwrap_or(0.0);
    let exposed = ht.sspne.unwrap_or(semispan);
    let x_ac = xh
        + (semispan - exposed) * p.inboard.leading_edge.tan
        + moment.aerodynamic_centre * p.exposed_root_chord;
    let arm = (x_ac - xcg) / totals.reference_length;
    let Some(cla) = tail.cla_per_rad.first().copied().flatten() else {
        return Ok(());
    };
    let vortex_slope = |row: usize| canard_slope.get(row).copied().flatten();
    let increment = |row: usize| {
        let q = dynamic_pressure_ratio.get(row).copied().flatten()?;
        finite((2.0 * k * q * cla + vortex_slope(row)?) * arm)
    };
    let first = increment(0);
    out.clq = Column::first(n, first);
    out.cmq = Column::first(n, first.map(|i| -i * arm));
    let ratio = wing.sspn.unwrap_or(0.0) / semispan;
    if ratio < CONVENTIONAL_SPAN_RATIO {
        // No tail α̇ term, but for a pointed forward surface (exposed taper 0) the lag of the
        // canard's vortices on the aft surface: CLα̇ −2 (l_H/c̄) ΔCLα, Cmα̇ +2 (l_H/c̄)² ΔCLα.
        let pointed = totals.terms.wing_body.terms.wing.terms.planform.taper == 0.0;
        if pointed && t.canard.is_some() {
            let rows = |f: &dyn Fn(f64) -> f64| {
                Column::rows(
                    (0..n)
                        .map(|row| vortex_slope(row).and_then(|d| finite(f(d))))
                        .collect(),
                )
            };
            out.clad = rows(&|d| -2.0 * arm * d);
            out.cmad = rows(&|d| 2.0 * arm * arm * d);
        }
        return Ok(());
    }
    let rows = |f: &dyn Fn(f64, f64) -> f64| {
        Column::rows(
            (0..n)
                .map(|row| {
                    let e = gradient.get(row).copied().flatten()?;
                    increment(row).map(|i| f(i, e))
                })
                .collect(),
        )
    };
    out.clad = rows(&|i, e| i * e);
    out.cmad = rows(&|i, e| -i * arm * e);
    Ok(())
}
