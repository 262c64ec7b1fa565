//! Wing and horizontal tail alone: pitch-rate, α̇, roll-rate and yaw-rate derivatives, DATCOM
//! 7.1 (the original's CMALPO, SUBPAW, SUBPAH, SUBRYW, SUBHYW and the wing part of CLRDER).

use std::f64::consts::PI;

use serde::Serialize;

use super::figures::{self, read};
use super::{finite, Column, Dynamic, DynamicError, DynamicWarning, DEG_PER_RAD};
use crate::case::{Case, Planform, ZeroLiftReading};
use crate::geometry::{planform as planform_geometry, Span};
use crate::methods::tail::table::{read as curve, End};
use crate::methods::tail::HorizontalTailAlone;
use crate::methods::wing::{
    aerodynamic_centre, computed_wing_section, wing_section, CentreInputs, WingAlone, WingType,
    WingWarning,
};

/// Below this exposed fraction of the semispan the roll and yaw methods apply with a body
/// (the original's SUBRYW returns when (SSPN − SSPNE)/SSPN > 0.3).
const MAX_BODY_SPAN_FRACTION: f64 = 0.3;
/// βA above which DATCOM has no α̇ method for triangular wings (figures 7.1.4.1-6, 7.1.4.2-8).
const MAX_ALPHA_DOT_BETA_ASPECT: f64 = 4.0;
/// Mach number above which Cmq takes the compressibility factor of equation 7.1.1.2-b.
const CMQ_INCOMPRESSIBLE_MACH: f64 = 0.2;
/// Wing to horizontal-tail semispan ratio from which the tail's Clp counts half (DATCOM
/// 7.4.2.1; the original's HORTYW).
const TAIL_CLP_HALF_SPAN_RATIO: f64 = 1.5;

/// The terms behind a surface's derivatives.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct SurfaceDynamicTerms {
    /// x̄: the Mach-0 aerodynamic centre behind the moment reference, in exposed mean
    /// aerodynamic chords (positive aft), the original's CMALPO.
    pub xbar_mach_zero: f64,
    /// The same at this Mach number (from the wing-alone pitching moment).
    pub xbar: f64,
    /// Section lift-curve slope at Mach 0 as the original takes it: the first Mach's slope
    /// times its √|1 − M²|, per rad.
    pub section_slope_mach_zero_per_rad: f64,
    /// Zero-lift angle (deg) and CD at zero lift read on the CL curve; CLα there, per deg.
    pub zero_lift_alpha_deg: Option<f64>,
    pub zero_lift_drag: Option<f64>,
    /// β Clp/κ at zero lift (figures 7.1.2.2-20a to -20d) and κ·β.
    pub roll_damping_parameter: Option<f64>,
    pub kappa_beta: f64,
    /// The roll-rate increments the original prints with PART (DYNAMIC DERIVATIVE
    /// INCREMENTALS), none where the roll method does not get to them.
    pub increments: Option<RollIncrements>,
}

/// The intermediate roll- and yaw-rate terms of a surface (DATCOM 7.1.2.1 to 7.1.2.3), per
/// radian, on the surface's own area.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct RollIncrements {
    /// Clp at zero lift without dihedral, (β Clp/κ) κ/β: CLP(GAMMA=CL=0).
    pub clp_zero_lift: f64,
    /// 1 − 2 (z/b′) sin Γ + 3 (z/b′)² sin² Γ (b′ the semispan): CLP(GAMMA)/CLP(GAMMA=0).
    pub dihedral_factor: f64,
    /// ΔCnp per degree of twist (figure 7.1.2.3-12): CNP/THETA.
    pub cnp_per_twist: f64,
    /// The dihedral's side force 3 sin Γ (1 − 2 (z/b′) sin Γ) Clp(Γ = CL = 0): CYP/GAMMA as
    /// the original labels it.
    pub cyp_dihedral: f64,
    /// (CYp/CL) at zero lift at this Mach number: CYP/CL (CL=0).
    pub cyp_per_cl: f64,
}

/// The inputs shared by the surface methods.
struct Surface<'a> {
    case: &'a Case,
    plan: &'a Planform,
    condition_index: usize,
    alpha_deg: &'a [f64],
    results: &'a WingAlone,
    /// CLα at the first angle as the page gives it, per rad.
    cla_first: Option<f64>,
    has_body: bool,
    /// Lateral reference length b.
    span_reference: f64,
    /// Height of the surface's root chord above ZCG (ZW − ZCG; ZH − ZCG).
    height: f64,
}

fn geometry_error(what: &str) -> DynamicError {
    DynamicError::Geometry {
        reason: format!("the planform needs {what}"),
    }
}

fn wing_warnings(from: Vec<WingWarning>, to: &mut Vec<DynamicWarning>) {
    for w in from {
        if let WingWarning::Chart(c) = w {
            let w = DynamicWarning::Chart(c);
            if !to.contains(&w) {
                to.push(w);
            }
        }
    }
}

/// Effective dihedral, deg: (Γ_i (b'/2 − y_d) + Γ_o y_d)/(b'/2), b'/2 the exposed semispan.
fn effective_dihedral_deg(plan: &Planform, semispan: f64) -> f64 {
    let exposed = plan.sspne.unwrap_or(semispan);
    let inboard = plan.dhdadi_deg.unwrap_or(0.0);
    let station = plan.sspndd.unwrap_or(0.0);
    let outboard = plan.dhdado_deg.unwrap_or(inboard);
    (inboard * (exposed - station) + outboard * station) / exposed
}

impl Surface<'_> {
    fn mach(&self) -> Result<f64, DynamicError> {
        self.case
            .conditions
            .get(self.condition_index)
            .map(|c| c.mach)
            .ok_or(DynamicError::NoCondition {
                index: self.condition_index,
            })
    }

    /// The Mach-0 aerodynamic centre over the exposed root chord, as the original's CMALPO:
    /// straight wings not of low aspect ratio take the theoretical MAC's quarter chord
    /// (without the section's aerodynamic centre), the others figure 4.1.4.2-26 at β = 1.
    fn mach_zero_centre(&self, warnings: &mut Vec<DynamicWarning>) -> Result<f64, DynamicError> {
        let w = self.results;
        let p = &w.terms.planform;
        let semispan = self.plan.sspn.ok_or_else(|| geometry_error("SSPN"))?;
        let exposed = self.plan.sspne.unwrap_or(semispan);
        let mut ww = Vec::new();
        let centre = if w.planform_type == WingType::Straight
            && !w.terms.aspect_ratio_class.low_aspect_ratio
        {
            let g =
                planform_geometry(self.plan, Span::Both).map_err(|e| DynamicError::Geometry {
                    reason: e.to_string(),
                })?;
            (g.x_mac_le + g.theoretical.mac / 4.0
                - (semispan - exposed) * p.inboard.leading_edge.tan)
                / p.exposed_root_chord
        } else {
            // The panel weights as CMALPO forms them: Helmbold slopes at the first Mach's β
            // applied to (2πA/c_lα)² (1 + tan²Λc/2), with the first Mach's section slope.
            let slope0 = self.first_section_slope()?;
            let first_mach = self.case.conditions.first().map_or(0.0, |c| c.mach);
            let b2 = (1.0 - first_mach * first_mach).abs();
            let weight = |a: f64, tan_half: f64| {
                let t = 2.0 * PI * a;
                t / (2.0 + (b2 * (t / slope0).powi(2) * (1.0 + tan_half * tan_half) + 4.0).sqrt())
            };
            let panels = match (&p.outboard, &p.extended_outboard) {
                (Some(o), Some(e)) => (
                    Some(weight(p.inboard.aspect_ratio, p.inboard.half_chord.tan)),
                    Some(weight(e.aspect_ratio, o.half_chord.tan)),
                ),
                _ => (None, None),
            };
            let inputs = CentreInputs {
                planform: p,
                kind: w.planform_type,
                low_aspect_ratio: true,
                section_xac: None,
                beta: 1.0,
                panel_slopes: panels,
                reading: self.case.forward_sweep,
            };
            aerodynamic_centre(&inputs, &mut ww).map_err(|e| DynamicError::Geometry {
                reason: e.to_string(),
            })?
        };
        wing_warnings(ww, warnings);
        Ok(centre)
    }

    /// The section lift-curve slope of the first flight condition (the original's CLALPA(1)),
    /// per rad.
    fn first_section_slope(&self) -> Result<f64, DynamicError> {
        let computed =
            computed_wing_section(self.case)
                .transpose()
                .map_err(|e| DynamicError::Geometry {
                    reason: e.to_string(),
                })?;
        let mut ww = Vec::new();
        wing_section(self.case, 0, computed.as_ref(), &mut ww)
            .map(|s| s.lift_curve_slope_per_rad)
            .map_err(|e| DynamicError::Geometry {
                reason: e.to_string(),
            })
    }
}

/// Pitch-rate and α̇ derivatives (DATCOM 7.1.1.1, 7.1.1.2, 7.1.4.1, 7.1.4.2), per rad, first
/// row: CLq = (1/2 + 2x̄_M) CLα c̄_e/c̄; Cmq = −0.7 c_lα,0 cos Λ [A(x̄/2 + 2x̄²)/(A + 2cos Λ) +
/// A³tan²Λ/(24(A + 6cos Λ)) + 1/8] S_e/S (c̄_e/c̄)², above M = 0.2 times [A³tan²Λ/(AB + 6cos Λ) +
/// 3/B]/[A³tan²Λ/(A + 6cos Λ) + 3], B = √(1 − M²cos²Λ); CLα̇, Cmα̇ for triangular exposed
/// planforms with βA ≤ 4 (figures 7.1.4.1-6, 7.1.4.2-8), else no method. A, S_e, c̄_e of the
/// exposed planform, Λ the inboard quarter-chord sweep, x̄ = (x_ac − x_ref)/c̄_e at Mach 0
/// (x̄_M at this Mach), c_lα,0 the first Mach's section slope times its √|1 − M²|.
fn pitch(
    s: &Surface,
    out: &mut Dynamic,
    terms: &mut SurfaceDynamicTerms,
) -> Result<(), DynamicError> {
    let n = s.alpha_deg.len();
    let w = s.results;
    let p = &w.terms.planform;
    let mach = s.mach()?;
    let s_ref = w.reference_area;
    let c_ref = w.reference_length;
    let moment = w.terms.pitching_moment.as_ref();
    let Some(moment) = moment else {
        out.warnings.push(DynamicWarning::NotComputed {
            derivative: "CLQ, CMQ",
            reason: "the surface's pitching moment is not computed".into(),
        });
        out.clq = Column::first(n, None);
        out.cmq = Column::first(n, None);
        return Ok(());
    };
    let root = p.exposed_root_chord;
    let mac = p.mac;
    let a = p.aspect_ratio;
    let tan = 0.5 * (p.inboard.leading_edge.tan + p.inboard.half_chord.tan);
    let cos = 1.0 / (1.0 + tan * tan).sqrt();
    let centre0 = s.mach_zero_centre(&mut out.warnings)?;
    let dcm_dcl0 = (moment.moment_reference - centre0) * root / c_ref;
    let xbar0 = -dcm_dcl0 * c_ref / mac;
    let xbar = -moment.dcm_dcl * c_ref / mac;
    let first_mach = s.case.conditions.first().map_or(0.0, |c| c.mach);
    let slope0 = s.first_section_slope()? * (1.0 - first_mach * first_mach).abs().sqrt();
    terms.xbar_mach_zero = xbar0;
    terms.xbar = xbar;
    terms.section_slope_mach_zero_per_rad = slope0;

    let clq = s
        .cla_first
        .and_then(|cla| finite((0.5 + 2.0 * xbar) * cla * mac / c_ref));
    let a3t2 = a.powi(3) * tan * tan;
    let bracket = a * (0.5 * xbar0 + 2.0 * xbar0 * xbar0) / (a + 2.0 * cos)
        + a3t2 / (24.0 * (a + 6.0 * cos))
        + 0.125;
    let mut cmq = -0.7 * slope0 * cos * bracket * p.exposed_area / s_ref * (mac / c_ref).powi(2);
    if mach > CMQ_INCOMPRESSIBLE_MACH {
        let b = (1.0 - mach * mach * cos * cos).sqrt();
        cmq *= (a3t2 / (a * b + 6.0 * cos) + 3.0 / b) / (a3t2 / (a + 6.0 * cos) + 3.0);
    }
    out.clq = Column::first(n, clq);
    out.cmq = Column::first(n, finite(cmq));

    let beta = (1.0 - mach * mach).sqrt();
    let beta_a = beta * a;
    // (A NaN βA has no method either.)
    let within = beta_a <= MAX_ALPHA_DOT_BETA_ASPECT;
    if p.taper != 0.0 || !within {
        out.warnings.push(DynamicWarning::NoAlphaDotMethod);
        return Ok(());
    }
    let lift_g = read(figures::ALPHA_DOT_LIFT, &[beta_a], &mut out.warnings)? * PI * a
        / (-2.0 * beta * beta);
    let moment_g = read(figures::ALPHA_DOT_MOMENT, &[beta_a], &mut out.warnings)? * a * 0.5 * PI
        / (beta * beta);
    let exposed = p.exposed_area * mac / (s_ref * c_ref);
    let xac = moment.aerodynamic_centre;
    // The original's 19.1 (≈ 57.3/3) and 0.078532 (≈ 4.5/57.3) take its per-degree values;
    // times 57.3 for per radian.
    let clad = s.cla_first.map(|cla| {
        (1.5 * xac * cla * s_ref / p.exposed_area + lift_g * DEG_PER_RAD / 19.1) * exposed
    });
    let cmad = s.cla_first.map(|cla| {
        let pp = (-2.53125 * xac * xac * cla * s_ref / p.exposed_area
            + 0.078532 * DEG_PER_RAD * moment_g)
            * exposed
            * mac
            / c_ref;
        pp + moment.moment_reference * root / c_ref * clad.unwrap_or(0.0)
    });
    out.clad = Column::first(n, clad);
    out.cmad = Column::first(n, cmad);
    Ok(())
}

/// The points of the lift curve `cl` from its least value before its maximum up to the
/// maximum (the first greatest value; at least two points): the rising part of the curve, on
/// which zero lift is read. Beyond either stall the lift may turn through zero again.
fn rising_part(cl: &[f64]) -> std::ops::Range<usize> {
    let least = |part: &[f64], better: fn(f64, f64) -> bool| {
        part.iter().enumerate().fold(
            0,
            |best, (i, v)| if better(*v, part[best]) { i } else { best },
        )
    };
    let top = least(cl, |v, best| v > best);
    let bottom = least(&cl[..=top], |v, best| v < best);
    if top - bottom >= 1 {
        bottom..top + 1
    } else {
        0..cl.len().min(2)
    }
}

/// β Clp/κ of figures 7.1.2.2-20a to -20d, linear in taper between the charts for 0, 0.25,
/// 0.5 and 1 (the original's INTEP3). None outside taper 0 to 1 (the original's is undefined).
fn roll_damping_parameter(
    beta_a_over_kappa: f64,
    sweep_beta_deg: f64,
    taper: f64,
    warnings: &mut Vec<DynamicWarning>,
) -> Result<Option<f64>, DynamicError> {
    let t = figures::ROLL_DAMPING_TAPERS;
    let at = |k: usize, w: &mut Vec<DynamicWarning>| {
        read(
            figures::ROLL_DAMPING[k],
            &[beta_a_over_kappa, sweep_beta_deg],
            w,
        )
    };
    if taper == 0.0 {
        return at(0, warnings).map(Some);
    }
    let Some(k) = (1..4).find(|&k| taper > t[k - 1] && taper <= t[k]) else {
        return Ok(None);
    };
    let lo = at(k - 1, warnings)?;
    let hi = at(k, warnings)?;
    Ok(Some(
        lo + (hi - lo) * (taper - t[k - 1]) / (t[k] - t[k - 1]),
    ))
}

/// Roll- and yaw-rate derivatives (DATCOM 7.1.2.1 CYp, 7.1.2.2 Clp, 7.1.2.3 Cnp, 7.1.3.3 Cnr)
/// at every angle, as the original's SUBRYW (`tail_only`: Clp only, SUBHYW). Per degree inside
/// (the original's bookkeeping), per radian out.
fn roll_yaw(
    s: &Surface,
    out: &mut Dynamic,
    terms: &mut SurfaceDynamicTerms,
    tail_only: bool,
) -> Result<(), DynamicError> {
    let n = s.alpha_deg.len();
    let w = s.results;
    let p = &w.terms.planform;
    let semispan = s.plan.sspn.ok_or_else(|| geometry_error("SSPN"))?;
    let exposed = s.plan.sspne.unwrap_or(semispan);
    let fraction = (semispan - exposed) / semispan;
    if s.has_body && fraction > MAX_BODY_SPAN_FRACTION {
        out.warnings.push(DynamicWarning::BodyTooWide { fraction });
        return Ok(());
    }
    let missing = |out: &mut Dynamic, reason: &str| {
        out.warnings.push(DynamicWarning::NotComputed {
            derivative: if tail_only {
                "the horizontal tail's CLP"
            } else {
                "CLP, CYP, CNP, CNR"
            },
            reason: reason.into(),
        });
        out.clp = Column::rows(vec![None; n]);
        if !tail_only {
            out.cyp = Column::rows(vec![None; n]);
            out.cnp = Column::rows(vec![None; n]);
            out.cnr = Column::rows(vec![None; n]);
        }
    };
    let (Some(cl), Some(cd)) = (
        w.cl.iter().copied().collect::<Option<Vec<f64>>>(),
        w.cd.iter().copied().collect::<Option<Vec<f64>>>(),
    ) else {
        missing(out, "the surface's CL or CD is not computed at every angle");
        return Ok(());
    };
    if cl.len() != n || n < 2 {
        missing(out, "the lift curve has too few angles");
        return Ok(());
    }
    let alpha = s.alpha_deg;
    let mach = s.mach()?;
    let g = planform_geometry(s.plan, Span::Both).map_err(|e| DynamicError::Geometry {
        reason: e.to_string(),
    })?;
    let a = g.theoretical.aspect_ratio;
    let area = g.theoretical.area;
    let taper = p.taper;
    let tan = 0.5 * (p.inboard.leading_edge.tan + p.inboard.half_chord.tan);
    let cos = 1.0 / (1.0 + tan * tan).sqrt();
    let sweep_deg = tan.atan().to_degrees();
    let beta = (1.0 - mach * mach).abs().sqrt();
    let kappa = beta * w.terms.section.lift_curve_slope_per_rad / (2.0 * PI);
    terms.kappa_beta = kappa;
    let cl_o: Vec<Option<f64>> = cl.iter().map(|v| Some(*v)).collect();
    // Zero-lift angle and drag, and the lift slope at zero lift, on the curve up to its
    // maximum lift: beyond the stall the lift may fall through zero again, and that crossing
    // (with its negative slope) is not the zero-lift angle. The original reads the whole
    // curve (ZeroLiftReading::Original; docs/differences.md).
    let part = match s.case.zero_lift {
        ZeroLiftReading::Handbook => rising_part(&cl),
        ZeroLiftReading::Original => 0..n,
    };
    let m = part.len();
    let (alpha_r, cl_r) = (&alpha[part.clone()], &cl[part.clone()]);
    let cl_ro = &cl_o[part.clone()];
    let cd_ro: Vec<Option<f64>> = cd[part].iter().map(|v| Some(*v)).collect();
    let alpha_ro: Vec<Option<f64>> = alpha_r.iter().map(|v| Some(*v)).collect();
    let Some((zero_alpha, _)) = curve(cl_r, &alpha_ro, 0.0, End::Linear, End::Linear) else {
        missing(out, "no zero-lift angle on the lift curve");
        return Ok(());
    };
    let Some((cd0, _)) = curve(cl_r, &cd_ro, 0.0, End::Quadratic, End::Quadratic) else {
        missing(out, "no zero-lift drag on the drag polar");
        return Ok(());
    };
    terms.zero_lift_alpha_deg = Some(zero_alpha);
    terms.zero_lift_drag = Some(cd0);
    // With (α0, 0) added when the curve does not cross zero lift.
    let slope_at_zero = if cl_r[0] <= 0.0 && cl_r[m - 1] >= 0.0 {
        curve(alpha_r, cl_ro, zero_alpha, End::Linear, End::Linear)
    } else if cl_r[0] < 0.0 {
        let mut x = alpha_r.to_vec();
        x.push(zero_alpha);
        let mut y = cl_ro.to_vec();
        y.push(Some(0.0));
        curve(&x, &y, zero_alpha, End::Linear, End::Linear)
    } else {
        let mut x = vec![zero_alpha];
        x.extend_from_slice(alpha_r);
        let mut y = vec![Some(0.0)];
        y.extend(cl_ro.iter().copied());
        curve(&x, &y, zero_alpha, End::Linear, End::Linear)
    }
    .map(|r| r.1);
    let Some(slope_at_zero) = slope_at_zero.filter(|v| *v != 0.0) else {
        missing(out, "no lift slope at zero lift");
        return Ok(());
    };
    let cla: Vec<Option<f64>> = alpha
        .iter()
        .map(|&x| curve(alpha, &cl_o, x, End::Hold, End::Hold).map(|r| r.1))
        .collect();

    let dihedral = effective_dihedral_deg(s.plan, semispan).to_radians().sin();
    let z = s.height;
    let dihedral_factor =
        1.0 - 2.0 * z * dihedral / semispan + 3.0 * (z / semispan).powi(2) * dihedral * dihedral;
    let sweep_beta = (tan / beta).atan().to_degrees();
    let drag_roll = read(
        figures::ROLL_DAMPING_DRAG,
        &[sweep_deg, a],
        &mut out.warnings,
    )?;
    let s_ratio = w.reference_area / area;
    let b = s.span_reference;
    let scale = 4.0 * semispan * semispan / (DEG_PER_RAD * s_ratio * b * b);
    let Some(parameter) =
        roll_damping_parameter(beta * a / kappa, sweep_beta, taper, &mut out.warnings)?
    else {
        missing(
            out,
            "the exposed taper ratio is outside 0 to 1 (figure 7.1.2.2-20)",
        );
        return Ok(());
    };
    terms.roll_damping_parameter = Some(parameter);
    let lift_term = scale * parameter * kappa * dihedral_factor / (beta * slope_at_zero);
    let clp: Vec<Option<f64>> = (0..n)
        .map(|i| {
            let clt = cl[i] * s_ratio;
            cla[i].map(|sl| lift_term * sl + scale * (drag_roll * clt * clt - cd0 / 8.0 * s_ratio))
        })
        .collect();
    out.clp = Column::rows(clp.iter().map(|v| v.map(|x| x * DEG_PER_RAD)).collect());
    if tail_only {
        return Ok(());
    }

    // Cnp (7.1.2.3).
    let bee = (1.0 - mach * mach * cos * cos).sqrt();
    let xbar0 = terms.xbar_mach_zero;
    let cnp_cl0 =
        -(a + 6.0 * (a + cos) * (xbar0 * tan / a + tan * tan / 12.0)) / (6.0 * (a + 4.0 * cos));
    let cnp_cl = (a + 4.0 * cos) / (a * bee + 4.0 * cos)
        * (a * bee + 0.5 * (a * bee + cos) * tan * tan)
        * cnp_cl0
        / (a + 0.5 * (a + cos) * tan * tan);
    let rel: Vec<f64> = alpha
        .iter()
        .map(|x| (x - zero_alpha).to_radians())
        .collect();
    let cl_tan: Vec<Option<f64>> = (0..n)
        .map(|i| Some(cl[i] * s_ratio * rel[i].tan()))
        .collect();
    let cd_rel: Vec<Option<f64>> = (0..n).map(|i| Some((cd[i] - cd0) * s_ratio)).collect();
    let induced: Vec<Option<f64>> = (0..n)
        .map(|i| Some((cl[i] * s_ratio).powi(2) / (a * PI)))
        .collect();
    let cnp_per_twist = read(figures::ROLL_YAW_TWIST, &[taper, a], &mut out.warnings)?;
    let twist = cnp_per_twist * s.plan.twista_deg.unwrap_or(0.0);
    let kay: Vec<Option<f64>> = (0..n)
        .map(|i| {
            if cl[i] == 0.0 {
                return Some(1.0);
            }
            let d = |y: &[Option<f64>]| {
                curve(alpha, y, alpha[i], End::Linear, End::Linear).map(|r| r.1)
            };
            let (t, dr, ind) = (d(&cl_tan)?, d(&cd_rel)?, d(&induced)?);
            finite((t - dr) / (t - ind))
        })
        .collect();
    let cnp: Vec<Option<f64>> = (0..n)
        .map(|i| {
            let k = kay[i]?;
            Some(
                (k - 1.0) * clp[i]? * rel[i].tan() + (k * cnp_cl * cl[i] * s_ratio + twist) * scale,
            )
        })
        .collect();
    out.cnp = Column::rows(cnp.iter().map(|v| v.map(|x| x * DEG_PER_RAD)).collect());

    // CYp (7.1.2.1).
    let clp_gamma = parameter * kappa / beta;
    let dihedral_side = 3.0 * dihedral * (1.0 - 2.0 * z * dihedral / semispan) * clp_gamma;
    let step_a = read(figures::ROLL_SIDE_FORCE_STEP_A, &[a], &mut out.warnings)?;
    let step_b = read(
        figures::ROLL_SIDE_FORCE_STEP_B,
        &[sweep_deg, step_a],
        &mut out.warnings,
    )?;
    let cyp_cl0 = read(
        figures::ROLL_SIDE_FORCE,
        &[taper, step_b],
        &mut out.warnings,
    )?;
    let cyp_cl = (a + 4.0 * cos) * (a * bee + cos) * cyp_cl0 / ((a * bee + 4.0 * cos) * (a + cos));
    terms.increments = Some(RollIncrements {
        clp_zero_lift: clp_gamma,
        dihedral_factor,
        cnp_per_twist,
        cyp_dihedral: dihedral_side,
        cyp_per_cl: cyp_cl,
    });
    let side_scale = scale * b / (2.0 * semispan);
    let cyp: Vec<Option<f64>> = (0..n)
        .map(|i| Some(side_scale * dihedral_side + side_scale * cyp_cl * s_ratio * kay[i]? * cl[i]))
        .collect();
    out.cyp = Column::rows(cyp.iter().map(|v| v.map(|x| x * DEG_PER_RAD)).collect());

    // Cnr (7.1.3.3).
    let step = read(
        figures::YAW_DAMPING_STEP,
        &[xbar0, sweep_deg, a],
        &mut out.warnings,
    )?;
    let per_lift = read(figures::YAW_DAMPING_LIFT, &[taper, step], &mut out.warnings)?;
    let per_drag = read(
        figures::YAW_DAMPING_DRAG,
        &[xbar0, sweep_deg.abs(), a],
        &mut out.warnings,
    )?;
    let cnr: Vec<Option<f64>> = (0..n)
        .map(|i| {
            let clt = cl[i] * s_ratio;
            let profile = cd[i] * s_ratio - induced[i]?;
            Some(scale * (per_lift * clt * clt + per_drag * profile))
        })
        .collect();
    out.cnr = Column::rows(cnr.iter().map(|v| v.map(|x| x * DEG_PER_RAD)).collect());
    Ok(())
}

/// Roll due to yaw rate of the wing (DATCOM 7.1.3.2, the original's CLRDER), per rad at every
/// angle: CLr = CL·(Clr/CL)_M + ΔClr/Γ·Γ + ΔClr/θ·θ, (Clr/CL)_M = (Clr/CL)_{M=0} times the
/// Mach factor of equation 7.1.3.2-a, (Clr/CL)_{M=0} = −(UI + US·UNIT) (figures 7.1.3.2-9, -10),
/// ΔClr/Γ = πA sin Λ/(12(A + 4cos Λ)) per rad², ΔClr/θ figure 7.1.3.2-11 (θ in degrees), with the
/// exposed aspect ratio and taper and the quarter-chord sweep. No method for forward sweep.
fn yaw_roll(s: &Surface, out: &mut Dynamic) -> Result<(), DynamicError> {
    let n = s.alpha_deg.len();
    let w = s.results;
    let p = &w.terms.planform;
    let sweep = p.quarter_chord.deg;
    if sweep < 0.0 {
        out.warnings.push(DynamicWarning::ForwardSweep);
        return Ok(());
    }
    let mach = s.mach()?;
    let a = p.aspect_ratio;
    let taper = p.taper;
    let lam = sweep.to_radians();
    let (sn, cs, ts) = (lam.sin(), lam.cos(), lam.tan());
    let b = (1.0 - (mach * cs).powi(2)).sqrt();
    let ab = a * b;
    let con = (1.0
        + a * (1.0 - b * b) / (2.0 * b * (ab + 2.0 * cs))
        + (ab + 2.0 * cs) / (ab + 4.0 * cs) * ts * ts / 8.0)
        / (1.0 + (a + 2.0 * cs) / (a + 4.0 * cs) * ts * ts / 8.0);
    let per_dihedral = PI * a * sn / (12.0 * (a + 4.0 * cs));
    let unit = read(figures::YAW_ROLL_UNIT, &[taper, a], &mut out.warnings)?;
    let intercept = read(figures::YAW_ROLL_INTERCEPT, &[sweep], &mut out.warnings)?;
    let slope = read(figures::YAW_ROLL_SLOPE, &[sweep], &mut out.warnings)?;
    let per_cl = (intercept + slope * unit) * con;
    let per_twist = read(figures::YAW_ROLL_TWIST, &[taper, a], &mut out.warnings)?;
    let semispan = s.plan.sspn.unwrap_or(0.0);
    let gamma = effective_dihedral_deg(s.plan, semispan).to_radians();
    let fixed = per_dihedral * gamma + per_twist * s.plan.twista_deg.unwrap_or(0.0);
    out.clr = Column::rows(
        (0..n)
            .map(|k| w.cl.get(k).copied().flatten().map(|cl| cl * per_cl + fixed))
            .collect(),
    );
    Ok(())
}

fn no_surface(what: &str) -> DynamicError {
    DynamicError::Geometry {
        reason: format!("the case has no {what}"),
    }
}

/// The wing alone's dynamic derivatives at flight condition `condition_index`, per radian,
/// from the wing-alone results `wing` at the schedule angles `alpha_deg`: pitch rate and α̇
/// on the first row, roll and yaw rate at every angle (see the DATCOM sections of the
/// module). `has_body`: a body is present (the roll and yaw methods then need the body to
/// cover at most 30 % of the semispan, as the original).
pub fn wing_dynamic(
    case: &Case,
    condition_index: usize,
    alpha_deg: &[f64],
    wing: &WingAlone,
) -> Result<(Dynamic, SurfaceDynamicTerms), DynamicError> {
    let plan = case.wing.as_ref().ok_or_else(|| no_surface("wing"))?;
    if wing.cl.len() != alpha_deg.len() {
        return Err(DynamicError::AngleCount {
            what: "wing",
            expected: alpha_deg.len(),
            found: wing.cl.len(),
        });
    }
    let synthesis = case.synthesis.as_ref();
    let get = |f: fn(&crate::case::Synthesis) -> Option<f64>| synthesis.and_then(f).unwrap_or(0.0);
    let s = Surface {
        case,
        plan,
        condition_index,
        alpha_deg,
        results: wing,
        cla_first: wing.cla_per_rad.first().copied().flatten(),
        has_body: case.body.is_some(),
        span_reference: crate::methods::lateral::lateral_reference_length(case).ok_or_else(
            || DynamicError::Geometry {
                reason: "no lateral reference length: give BLREF in $OPTINS".into(),
            },
        )?,
        height: get(|s| s.zw) - get(|s| s.zcg),
    };
    let mut out = Dynamic::no_method(alpha_deg);
    let mut terms = SurfaceDynamicTerms {
        xbar_mach_zero: 0.0,
        xbar: 0.0,
        section_slope_mach_zero_per_rad: 0.0,
        zero_lift_alpha_deg: None,
        zero_lift_drag: None,
        roll_damping_parameter: None,
        kappa_beta: 0.0,
        increments: None,
    };
    pitch(&s, &mut out, &mut terms)?;
    roll_yaw(&s, &mut out, &mut terms, false)?;
    yaw_roll(&s, &mut out)?;
    Ok((out, terms))
}

/// The horizontal tail alone's dynamic derivatives (the original's SUBPAH, SUBHYW, HORTYW): the
/// wing's pitch-rate and α̇ methods on the tail (only when the case has a wing, as the
/// original), its Clp (halved when the wing's semispan is at least 1.5 times the tail's, DATCOM
/// 7.4.2.1, on the tail page too, as the original); CYp, Cnp, Cnr are 0 on the first row with a
/// body and a vertical tail or ventral fin, else no method; no Clr method.
pub fn horizontal_tail_dynamic(
    case: &Case,
    condition_index: usize,
    alpha_deg: &[f64],
    tail: &HorizontalTailAlone,
) -> Result<(Dynamic, SurfaceDynamicTerms), DynamicError> {
    let n = alpha_deg.len();
    let ht = case
        .horizontal_tail
        .as_ref()
        .ok_or_else(|| no_surface("horizontal tail"))?;
    let mut proxy =
        crate::methods::tail::tail_as_wing(case).map_err(|e| DynamicError::Geometry {
            reason: e.to_string(),
        })?;
    let b = crate::methods::lateral::lateral_reference_length(case).ok_or_else(|| {
        DynamicError::Geometry {
            reason: "no lateral reference length: give BLREF in $OPTINS".into(),
        }
    })?;
    proxy.reference.span = Some(b);
    let synthesis = case.synthesis.as_ref();
    let get = |f: fn(&crate::case::Synthesis) -> Option<f64>| synthesis.and_then(f).unwrap_or(0.0);
    let s = Surface {
        case: &proxy,
        plan: ht,
        condition_index,
        alpha_deg,
        results: &tail.surface,
        cla_first: tail.cla_per_rad.first().copied().flatten(),
        has_body: case.body.is_some(),
        span_reference: b,
        height: get(|s| s.zh) - get(|s| s.zcg),
    };
    let mut out = Dynamic::no_method(alpha_deg);
    let mut terms = SurfaceDynamicTerms {
        xbar_mach_zero: 0.0,
        xbar: 0.0,
        section_slope_mach_zero_per_rad: 0.0,
        zero_lift_alpha_deg: None,
        zero_lift_drag: None,
        roll_damping_parameter: None,
        kappa_beta: 0.0,
        increments: None,
    };
    if case.wing.is_some() {
        pitch(&s, &mut out, &mut terms)?;
    }
    roll_yaw(&s, &mut out, &mut terms, true)?;
    let wing_semispan = case.wing.as_ref().and_then(|w| w.sspn).unwrap_or(0.0);
    let tail_semispan = ht.sspn.unwrap_or(f64::INFINITY);
    if wing_semispan / tail_semispan >= TAIL_CLP_HALF_SPAN_RATIO {
        if let Column::Rows(r) = &mut out.clp {
            for v in r.iter_mut().flatten() {
                *v *= 0.5;
            }
        }
    }
    if case.body.is_some() && (case.vertical_tail.is_some() || case.ventral_fin.is_some()) {
        out.cyp = Column::first(n, Some(0.0));
        out.cnp = Column::first(n, Some(0.0));
        out.cnr = Column::first(n, Some(0.0));
    }
    Ok((out, terms))
}

#[cfg(test)]
mod tests {
    use super::rising_part;

    #[test]
    fn zero_lift_is_read_on_the_rising_part_of_the_lift_curve() {
        // Rising through zero, stalling at the fourth angle, falling through zero after it.
        assert_eq!(rising_part(&[-0.2, 0.1, 0.5, 0.9, 0.6, -0.1]), 0..4);
        // A schedule that starts beyond the negative stall: from the least lift before the
        // maximum.
        assert_eq!(rising_part(&[0.1, -0.8, -0.3, 0.4, 1.0, 0.2]), 1..5);
        // Monotone: the whole curve; falling only: the first two points.
        assert_eq!(rising_part(&[-0.1, 0.2, 0.4]), 0..3);
        assert_eq!(rising_part(&[0.4, 0.2, -0.1]), 0..2);
    }
}
