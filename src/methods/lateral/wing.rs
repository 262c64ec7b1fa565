//! Wing alone: CYβ, Cnβ and Clβ, DATCOM 5.1.2.1 (the original's SUBLAT, wing terms).

use std::f64::consts::PI;

use serde::Serialize;

use super::body::lateral_reference_span;
use super::figures::{self, read};
use super::{finite, wing_inputs, Lateral, LateralError, LateralWarning, WingInputs};
use crate::case::units::from_si;
use crate::case::Case;
use crate::deck::cards::Dim;
use crate::deck::schema::Dimension;
use crate::methods::wing::{mach_zero_wing, Sweep, WingAlone, WingPlanform, WingType, WingWarning};

/// Degrees per radian: the charts and the original's equations are per degree.
pub(super) const DEG_PER_RAD: f64 = 180.0 / PI;
/// Below this theoretical aspect ratio Clβ takes the low-aspect-ratio form (5.1.2.1, A < 1).
const LOW_ASPECT_RATIO: f64 = 1.0;
/// Side force per degree of effective dihedral per degree of sideslip (the original's
/// empirical dihedral term of the wing CYβ).
const CYB_PER_DIHEDRAL: f64 = 0.0001;

/// The terms behind the wing derivatives.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct WingLateralTerms {
    /// Theoretical aspect ratio and taper ratio of the whole planform.
    pub aspect_ratio: f64,
    pub taper: f64,
    /// Theoretical area, m², and span 2·SSPN, m.
    pub theoretical_area: f64,
    pub span: f64,
    /// Effective uniform dihedral, deg: (Γ_i (b'/2 − y_d) + Γ_o y_d)/(b'/2), b'/2 the
    /// exposed semispan, y_d = SSPNDD.
    pub effective_dihedral_deg: f64,
    /// Wing CL at Mach 0 at each angle (the CYβ equation's reference lift).
    pub cl_mach_zero: Vec<Option<f64>>,
    /// The chart values of Clβ (none for the low-aspect-ratio form and non-uniform dihedral).
    pub rolling_moment: Option<RollingMomentTerms>,
}

/// Chart values of the Clβ method, per degree.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(tag = "planform", rename_all = "snake_case")]
pub enum RollingMomentTerms {
    /// Straight tapered wing (figures 5.1.2.1-27 to -28b, -30b, and the dihedral charts).
    Straight {
        sweep_per_cl: f64,
        sweep_compressibility: f64,
        aspect_per_cl: f64,
        twist: f64,
        dihedral: DihedralRoll,
    },
    /// Double-delta and cranked wings: the inboard panel and the extended outboard panel
    /// (sweep term × compressibility + aspect-ratio term, per unit lift), each weighted by
    /// its lift.
    Panels {
        inboard_per_cl: f64,
        outboard_per_cl: f64,
    },
}

/// Sweep, aspect-ratio and compressibility terms of one trapezoidal panel, DATCOM 5.1.2.1
/// equation (b) without dihedral and twist: (Clβ/CL)_Λ·K_MΛ + (Clβ/CL)_A per degree; for
/// A < 1 the slender-wing value −2/(3A) per radian.
fn panel_roll_per_cl(
    aspect_ratio: f64,
    taper: f64,
    half_chord_sweep_deg: f64,
    cos_half_chord: f64,
    mach: f64,
    warnings: &mut Vec<LateralWarning>,
) -> Result<f64, LateralError> {
    if aspect_ratio < LOW_ASPECT_RATIO {
        return Ok(-2.0 / (3.0 * DEG_PER_RAD * aspect_ratio));
    }
    let (sweep, aspect) = panel_sweep_and_aspect_roll(
        aspect_ratio,
        taper,
        half_chord_sweep_deg,
        cos_half_chord,
        mach,
        warnings,
    )?;
    Ok(sweep + aspect)
}

/// The dihedral charts of a straight wing's Clβ.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[serde(tag = "dihedral", rename_all = "snake_case")]
pub enum DihedralRoll {
    /// Uniform dihedral (SSPNDD not given or zero): Clβ/Γ per deg² of figure 5.1.2.1-29 at
    /// |Λc/2|, and its compressibility factor K_MΓ of figure 5.1.2.1-30a.
    Uniform {
        per_dihedral: f64,
        compressibility: f64,
    },
    /// Dihedral changing at the station SSPNDD from the tip (DHDADI inboard, DHDADO outboard):
    /// figure 5.1.2.1-31 at the station η = 1 − SSPNDD/SSPN where the outboard panel starts
    /// and at the tip (η = 1), with κ = c_lα/(2π) of the section and β = √(1 − M²).
    NonUniform {
        /// κ/β.
        kappa_over_beta: f64,
        /// Figure 5.1.2.1-31 at the outboard panel's root and at the tip.
        at_break: f64,
        at_tip: f64,
    },
}

impl DihedralRoll {
    /// The dihedral term of Clβ per degree of sideslip on the wing's own area, for inboard
    /// and outboard dihedral Γ_i, Γ_o in degrees: Γ_i (Clβ/Γ) K_MΓ (uniform), or
    /// κ/β·[(f(1) − f(η))Γ_o + f(η)Γ_i]/57.3 with f figure 5.1.2.1-31 (non-uniform: the
    /// outboard panel adds its dihedral from η to the tip, the inboard dihedral spans the
    /// wing up to η).
    pub fn term(&self, dihedral_in_deg: f64, dihedral_out_deg: f64) -> f64 {
        match *self {
            DihedralRoll::Uniform {
                per_dihedral,
                compressibility,
            } => dihedral_in_deg * per_dihedral * compressibility,
            DihedralRoll::NonUniform {
                kappa_over_beta,
                at_break,
                at_tip,
            } => {
                kappa_over_beta
                    * ((at_tip - at_break) * dihedral_out_deg + at_break * dihedral_in_deg)
                    / DEG_PER_RAD
            }
        }
    }
}

/// The chart values of a straight wing's Clβ, as [`straight_roll_charts`] reads them (the
/// fields of [`RollingMomentTerms::Straight`]).
pub(super) struct StraightRollCharts {
    pub sweep_per_cl: f64,
    pub sweep_compressibility: f64,
    pub aspect_per_cl: f64,
    pub twist: f64,
    pub dihedral: DihedralRoll,
}

/// Where the dihedral changes and what the non-uniform dihedral chart needs.
pub(super) struct DihedralBreak {
    /// η = (SSPN − SSPNDD)/SSPN.
    pub eta: f64,
    /// Section lift-curve slope, per radian, at this Mach number.
    pub section_slope_per_rad: f64,
    /// Quarter-chord sweep tangent of the inboard panel.
    pub tan_quarter_chord: f64,
}

/// The chart values of a straight wing's Clβ (DATCOM 5.1.2.1 equation b): figures
/// 5.1.2.1-27 and -28a (sweep term and its compressibility factor, at |Λc/2|; a forward-swept
/// half chord takes the magnitude of the chart value, as the original), -28b (aspect ratio),
/// -30b (twist), and for the dihedral -29 and -30a (uniform) or -31 (a break at SSPNDD).
pub(super) fn straight_roll_charts(
    taper: f64,
    aspect_ratio: f64,
    half_chord: Sweep,
    mach: f64,
    dihedral_break: Option<DihedralBreak>,
    warnings: &mut Vec<LateralWarning>,
) -> Result<StraightRollCharts, LateralError> {
    let x_aspect = aspect_ratio / half_chord.cos;
    let x_mach = mach * half_chord.cos;
    let mut sweep_per_cl = read(
        figures::SWEEP_ROLL_PER_LIFT,
        &[taper, aspect_ratio, half_chord.deg.abs()],
        warnings,
    )?;
    if half_chord.deg < 0.0 {
        sweep_per_cl = sweep_per_cl.abs();
    }
    let sweep_compressibility = read(
        figures::SWEEP_COMPRESSIBILITY,
        &[x_aspect, x_mach],
        warnings,
    )?;
    let aspect_per_cl = read(
        figures::ASPECT_ROLL_PER_LIFT,
        &[taper, aspect_ratio],
        warnings,
    )?;
    let twist = read(figures::TWIST_ROLL, &[taper, aspect_ratio], warnings)?;
    let dihedral = match dihedral_break {
        None => DihedralRoll::Uniform {
            compressibility: read(
                figures::DIHEDRAL_COMPRESSIBILITY,
                &[x_aspect, x_mach],
                warnings,
            )?,
            per_dihedral: read(
                figures::DIHEDRAL_ROLL,
                &[taper, half_chord.deg.abs(), aspect_ratio],
                warnings,
            )?,
        },
        Some(at) => {
            let beta = (1.0 - mach * mach).abs().sqrt();
            let kappa = at.section_slope_per_rad / (2.0 * PI);
            let sweep = (at.tan_quarter_chord / beta).atan().to_degrees();
            let x3 = beta * aspect_ratio / kappa;
            let mut chart = |eta: f64| {
                read(
                    figures::NON_UNIFORM_DIHEDRAL_ROLL,
                    &[taper, x3, sweep, eta],
                    warnings,
                )
            };
            let at_break = chart(at.eta)?;
            let at_tip = chart(1.0)?;
            DihedralRoll::NonUniform {
                kappa_over_beta: kappa / beta,
                at_break,
                at_tip,
            }
        }
    };
    Ok(StraightRollCharts {
        sweep_per_cl,
        sweep_compressibility,
        aspect_per_cl,
        twist,
        dihedral,
    })
}

/// The two chart terms of one trapezoidal panel, per degree: the sweep term with its
/// compressibility factor, (Clβ/CL)_Λ·K_MΛ (figures 5.1.2.1-27, -28a, at |Λc/2|), and the
/// aspect-ratio term (Clβ/CL)_A (figure 5.1.2.1-28b).
pub(super) fn panel_sweep_and_aspect_roll(
    aspect_ratio: f64,
    taper: f64,
    half_chord_sweep_deg: f64,
    cos_half_chord: f64,
    mach: f64,
    warnings: &mut Vec<LateralWarning>,
) -> Result<(f64, f64), LateralError> {
    let sweep = read(
        figures::SWEEP_ROLL_PER_LIFT,
        &[taper, aspect_ratio, half_chord_sweep_deg.abs()],
        warnings,
    )?;
    let km = read(
        figures::SWEEP_COMPRESSIBILITY,
        &[aspect_ratio / cos_half_chord, mach * cos_half_chord],
        warnings,
    )?;
    let aspect = read(
        figures::ASPECT_ROLL_PER_LIFT,
        &[taper, aspect_ratio],
        warnings,
    )?;
    Ok((sweep * km, aspect))
}

/// The wing-alone CYβ, Cnβ and Clβ at subsonic speed for flight condition `condition_index`
/// of `case`, from the wing-alone results `wing` at the schedule angles `alpha_deg`.
///
/// DATCOM 5.1.2.1 (Clβ; figures 5.1.2.1-27, -28a, -28b, -29, -30a, -30b), with the side
/// force and yawing moment the original's SUBLAT computes for the wing alone:
///
/// - CYβ = (A + 4cos Λ)/(Aβ_Λ + 4cos Λ) · CL·[CL₀·6 tan Λ sin Λ/(πA(A + 4cos Λ)) − 0.0001|Γ|/CL₀]
///   per degree, where Λ is the quarter-chord sweep of the planform, β_Λ = √(1 − M²cos²Λ), CL
///   the wing's lift at this Mach number and CL₀ its lift at Mach 0 at the same angle (zero when
///   CL₀ is zero);
/// - Cnβ = (A + 4cos Λ)/(Aβ_Λ + 4cos Λ) · ((Aβ_Λ)² + 4Aβ_Λ cos Λ − 8cos²Λ)/(A² + 4A cos Λ −
///   8cos²Λ) · [1/(4πA) − |tan Λ|/(πA(A + 4cos Λ))·(cos Λ − A/2 − A²/(8cos Λ) + 6 x̄ |sin Λ|/A)]
///   · CL² · b_w S/(b S_exposed) per degree, the DATCOM 5.1.3.1 form with x̄ = (CM/CN)/c̄ (the
///   original divides the centre of pressure, already in reference lengths, by c̄ once more, in
///   feet, its working length unit, whatever the deck's DIM; x̄ = 0 where the page's CM is not
///   applicable, as the original's NA, 2·10⁻³⁰ in the moment's place, leaves it);
/// - Clβ, straight wings with A ≥ 1 and uniform dihedral (equation b):
///   [CL·S/S_w·((Clβ/CL)_Λ K_MΛ + (Clβ/CL)_A) + θ tan Λc/4,i ΔClβ/(θ tan Λc/4) + Γ (Clβ/Γ) K_MΓ]
///   · S_w/S · b_w/b; with a dihedral break (SSPNDD) the dihedral term is that of figure
///   5.1.2.1-31 ([`DihedralRoll::NonUniform`]); A < 1: [−2/(3A)·CL − ΓA/6·S_w/S]·b_w/b per
///   radian (per deg² for Γ);
///   double-delta and cranked wings: the lift-weighted panel values, the inboard panel on its
///   theoretical planform scaled by its exposed span fraction, the outboard panel extended to
///   mid inboard panel, without dihedral and twist.
///
/// A is the theoretical aspect ratio, S_w the theoretical area, b_w = 2·SSPN, S the reference
/// area, b the lateral reference length (BLREF, else b_w), Γ the effective dihedral. Per
/// radian. Errors: no wing, no condition, wing results of another schedule, charts.
pub fn wing_lateral(
    case: &Case,
    condition_index: usize,
    alpha_deg: &[f64],
    wing: &WingAlone,
) -> Result<Lateral, LateralError> {
    surface_lateral(case, condition_index, alpha_deg, wing, &wing.cm)
}

/// [`wing_lateral`] with the page's moment `cm` (its own "not applicable" rows) in Cnβ's
/// centre of pressure: the horizontal tail's page takes the tail's rule (M33O41).
pub(super) fn surface_lateral(
    case: &Case,
    condition_index: usize,
    alpha_deg: &[f64],
    wing: &WingAlone,
    cm: &[Option<f64>],
) -> Result<Lateral, LateralError> {
    let WingInputs {
        plan,
        condition,
        semispan,
        root,
        tip,
        exposed_semispan,
        area,
    } = wing_inputs(case, condition_index, alpha_deg.len(), wing.cl.len())?;
    let n = alpha_deg.len();
    let mut warnings = Vec::new();
    let p: &WingPlanform = &wing.terms.planform;
    let span = 2.0 * semispan;
    let aspect_ratio = span * span / area;
    let taper = tip / root;
    let s_ref = wing.reference_area;
    let b_ref = lateral_reference_span(case);
    if b_ref.is_none() {
        warnings.push(LateralWarning::NoReferenceSpan);
    }
    let mach = condition.mach;

    // Effective dihedral (as the original's lateral geometry).
    let dihedral_in = plan.dhdadi_deg.unwrap_or(0.0);
    let dihedral_station = plan.sspndd.unwrap_or(0.0);
    let dihedral_out = plan.dhdado_deg.unwrap_or(dihedral_in);
    let effective_dihedral_deg = (dihedral_in * (exposed_semispan - dihedral_station)
        + dihedral_out * dihedral_station)
        / exposed_semispan;

    let quarter = p.quarter_chord;
    let (sin_q, cos_q, tan_q) = (quarter.deg.to_radians().sin(), quarter.cos, quarter.tan);
    let beta_sweep = (1.0 - (mach * cos_q).powi(2)).abs().sqrt();
    let a = aspect_ratio;
    let compressible = (a + 4.0 * cos_q) / (a * beta_sweep + 4.0 * cos_q);

    // CYβ: the lift at Mach 0 is the equation's reference lift.
    let cl_mach_zero = mach_zero_lift(case, condition_index, alpha_deg, &mut warnings);
    let sweep_term = 6.0 * tan_q * sin_q / (PI * a * (a + 4.0 * cos_q));
    let cyb: Vec<Option<f64>> = (0..n)
        .map(|k| {
            let cl = wing.cl[k]?;
            let cl0 = cl_mach_zero[k]?;
            if cl0 == 0.0 {
                return Some(0.0);
            }
            let per_cl0 = cl0 * cl0 * sweep_term / DEG_PER_RAD
                - CYB_PER_DIHEDRAL * effective_dihedral_deg.abs();
            finite(compressible * per_cl0 / cl0 * cl * DEG_PER_RAD)
        })
        .collect();

    // Cnβ.
    // In feet, the original's working unit, whatever the deck's DIM (it converts inches,
    // metres and centimetres to feet): measured with a build of its source on one deck read
    // as FT, IN, M and CM, the term follows CBARR in feet.
    let chord_in_feet = from_si(wing.reference_length, Dim::Ft, Dimension::Length);
    let ab = a * beta_sweep;
    let mach_ratio = (ab * ab + 4.0 * ab * cos_q - 8.0 * cos_q * cos_q)
        / (a * a + 4.0 * a * cos_q - 8.0 * cos_q * cos_q);
    let cnb: Vec<Option<f64>> = (0..n)
        .map(|k| {
            let cl = wing.cl[k]?;
            let b = b_ref?;
            let cn = wing.cn[k]?;
            // Where the page's moment is not applicable (NA) the centre of pressure is left
            // out: the original's NA is its 2·10⁻³⁰ in the moment's place. Where the method
            // computed no moment at all there is no Cnβ.
            let centre = match cm.get(k).copied().flatten() {
                _ if cn == 0.0 => 0.0,
                Some(cm) => 6.0 * (cm / cn / chord_in_feet) * sin_q.abs() / a,
                None => {
                    let m = wing.terms.pitching_moment.as_ref()?;
                    m.cm.get(k).copied().filter(|v| v.is_finite())?;
                    0.0
                }
            };
            let bracket = 1.0 / (4.0 * PI * a)
                - tan_q.abs() / (PI * a * (a + 4.0 * cos_q))
                    * (cos_q - a / 2.0 - a * a / (8.0 * cos_q) + centre);
            finite(
                compressible * mach_ratio * bracket * cl * cl * span * s_ref / (b * p.exposed_area),
            )
        })
        .collect();

    // Clβ.
    let (clb, rolling_moment) = match b_ref {
        None => (vec![None; n], None),
        Some(b) => rolling_moment(
            &RollInputs {
                case,
                wing,
                aspect_ratio: a,
                taper,
                area,
                span,
                b_ref: b,
                mach,
                dihedral_in,
                dihedral_out,
                effective_dihedral_deg,
            },
            &mut warnings,
        )?,
    };

    Ok(Lateral {
        alpha_deg: alpha_deg.to_vec(),
        cyb,
        cnb,
        clb,
        wing_body_terms: None,
        fin_terms: None,
        twin_panel_terms: None,
        wing_terms: Some(WingLateralTerms {
            aspect_ratio,
            taper,
            theoretical_area: area,
            span,
            effective_dihedral_deg,
            cl_mach_zero,
            rolling_moment,
        }),
        warnings,
    })
}

struct RollInputs<'a> {
    case: &'a Case,
    wing: &'a WingAlone,
    aspect_ratio: f64,
    taper: f64,
    area: f64,
    span: f64,
    b_ref: f64,
    mach: f64,
    dihedral_in: f64,
    dihedral_out: f64,
    effective_dihedral_deg: f64,
}

type RollResult = (Vec<Option<f64>>, Option<RollingMomentTerms>);

/// Clβ per radian at each angle, DATCOM 5.1.2.1 (see [`wing_lateral`]).
fn rolling_moment(
    r: &RollInputs,
    warnings: &mut Vec<LateralWarning>,
) -> Result<RollResult, LateralError> {
    let plan = r.case.wing.as_ref().ok_or(LateralError::NoWing)?;
    let wing = r.wing;
    let p = &wing.terms.planform;
    let s_ref = wing.reference_area;
    let a = r.aspect_ratio;
    let span_ratio = r.span / r.b_ref;
    let per_cl = |k: usize, f: &dyn Fn(f64) -> f64| wing.cl[k].and_then(|cl| finite(f(cl)));
    let n = wing.cl.len();
    if wing.planform_type == WingType::Straight {
        if a < LOW_ASPECT_RATIO {
            let dihedral = r.effective_dihedral_deg * a / (6.0 * DEG_PER_RAD * DEG_PER_RAD);
            let clb = (0..n)
                .map(|k| {
                    per_cl(k, &|cl| {
                        (-2.0 / (3.0 * DEG_PER_RAD * a) * cl - dihedral * r.area / s_ref)
                            * span_ratio
                            * DEG_PER_RAD
                    })
                })
                .collect();
            return Ok((clb, None));
        }
        let StraightRollCharts {
            sweep_per_cl,
            sweep_compressibility,
            aspect_per_cl,
            twist,
            dihedral,
        } = straight_roll_charts(
            r.taper,
            a,
            p.inboard.half_chord,
            r.mach,
            dihedral_break(plan, wing),
            warnings,
        )?;
        let tan_quarter_in = 0.5 * (p.inboard.leading_edge.tan + p.inboard.half_chord.tan);
        let twist_term = plan.twista_deg.unwrap_or(0.0) * tan_quarter_in * twist;
        let dihedral_term = dihedral.term(r.dihedral_in, r.dihedral_out);
        let lift_term = sweep_per_cl * sweep_compressibility + aspect_per_cl;
        let clb = (0..n)
            .map(|k| {
                per_cl(k, &|cl| {
                    (lift_term * cl * s_ref / r.area + twist_term + dihedral_term) * r.area / s_ref
                        * span_ratio
                        * DEG_PER_RAD
                })
            })
            .collect();
        return Ok((
            clb,
            Some(RollingMomentTerms::Straight {
                sweep_per_cl,
                sweep_compressibility,
                aspect_per_cl,
                twist,
                dihedral,
            }),
        ));
    }

    // Double delta and cranked: the inboard panel on its theoretical planform and the outboard
    // panel extended to mid inboard panel, weighted by their lift.
    let geometry = |what: &str| LateralError::Geometry {
        reason: format!("a two-panel planform needs {what}"),
    };
    let outboard = p.outboard.ok_or_else(|| geometry("an outboard panel"))?;
    let extended = p
        .extended_outboard
        .ok_or_else(|| geometry("an outboard panel"))?;
    let slope = &wing.terms.lift_curve_slope;
    let (slope_in, slope_out) = slope
        .inboard_panel_per_rad
        .zip(slope.extended_outboard_per_rad)
        .ok_or_else(|| geometry("the panel lift-curve slopes"))?;
    let root = plan.chrdr.unwrap_or(0.0);
    let break_chord = plan.chrdbp.ok_or_else(|| geometry("CHRDBP"))?;
    let outboard_span = plan.sspnop.ok_or_else(|| geometry("SSPNOP"))?;
    let semispan = r.span / 2.0;
    let inboard_span = semispan - outboard_span;
    let inboard_aspect = 4.0 * inboard_span / (root + break_chord);
    let inboard_taper = break_chord / root;
    let inboard = panel_roll_per_cl(
        inboard_aspect,
        inboard_taper,
        p.inboard.half_chord.deg,
        p.inboard.half_chord.cos,
        r.mach,
        warnings,
    )?;
    let outboard_per_cl = panel_roll_per_cl(
        extended.aspect_ratio,
        extended.taper,
        outboard.half_chord.deg,
        outboard.half_chord.cos,
        r.mach,
        warnings,
    )?;
    let lift_in = slope_in * p.inboard.area / s_ref;
    let lift_out = slope_out * extended.area / s_ref;
    let exposed_inboard_fraction = (p.exposed_semispan - outboard_span) / semispan;
    let weighted = lift_in * inboard * exposed_inboard_fraction + lift_out * outboard_per_cl;
    let total_lift = lift_in + lift_out;
    let clb = (0..n)
        .map(|k| {
            per_cl(k, &|cl| {
                cl / total_lift * weighted * span_ratio * DEG_PER_RAD
            })
        })
        .collect();
    Ok((
        clb,
        Some(RollingMomentTerms::Panels {
            inboard_per_cl: inboard,
            outboard_per_cl,
        }),
    ))
}

/// The dihedral break of a straight wing for figure 5.1.2.1-31: none for uniform dihedral
/// (SSPNDD not given or zero).
pub(super) fn dihedral_break(
    plan: &crate::case::Planform,
    wing: &WingAlone,
) -> Option<DihedralBreak> {
    let station = plan.sspndd.filter(|&y| y != 0.0)?;
    let semispan = plan.sspn?;
    let p = &wing.terms.planform;
    Some(DihedralBreak {
        eta: (semispan - station) / semispan,
        section_slope_per_rad: wing.terms.section.lift_curve_slope_per_rad,
        tan_quarter_chord: 0.5 * (p.inboard.leading_edge.tan + p.inboard.half_chord.tan),
    })
}

/// The wing's CL at Mach 0 at each angle (the original's CLMCH0, see [`mach_zero_wing`]):
/// none, with a warning, when it cannot be computed.
fn mach_zero_lift(
    case: &Case,
    condition_index: usize,
    alpha_deg: &[f64],
    warnings: &mut Vec<LateralWarning>,
) -> Vec<Option<f64>> {
    let n = alpha_deg.len();
    match mach_zero_wing(case, condition_index, alpha_deg) {
        Ok(low) if low.wing.cl.len() == n => {
            if low.wing.cl.iter().all(Option::is_none)
                && low.wing.warnings.contains(&WingWarning::NoSectionMaxLift)
            {
                // The original reads an unset CLMAXL as 0 and computes on; we say why not.
                warnings.push(LateralWarning::NoMachZeroLift {
                    reason: "the wing has no maximum lift at Mach 0: give CLMAXL in $WGSCHR (or a NACA card or section coordinates)".into(),
                });
            }
            low.wing.cl
        }
        Ok(_) => {
            warnings.push(LateralWarning::NoMachZeroLift {
                reason: "the lift curve is not computed".into(),
            });
            vec![None; n]
        }
        Err(e) => {
            warnings.push(LateralWarning::NoMachZeroLift {
                reason: e.to_string(),
            });
            vec![None; n]
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Non-uniform dihedral worked by hand (DATCOM 5.1.2.1, figure 5.1.2.1-31):
    /// taper λ = 0.5, A = 4, M = 0 (β = 1), unswept quarter chord (atan(tan Λc/4/β) = 0°),
    /// section slope 2π per rad (κ = 1, so βA/κ = 4), SSPN = 10 and SSPNDD = 4 (η = 0.6),
    /// Γ_i = 2°, Γ_o = 10°.
    /// Figure 5.1.2.1-31 (datcom.f DATA T31B, λ = 0.5, curve βA/κ = 4, sweep 0°):
    ///   f(0.6) = −0.0045, f(1.0) = −0.00935.
    /// Dihedral term = κ/β·[(f(1) − f(η))·Γ_o + f(η)·Γ_i]/57.29578
    ///   = [(−0.00935 + 0.0045)·10 + (−0.0045)·2]/57.29578 = (−0.0485 − 0.009)/57.29578
    ///   = −0.0575/57.29578 = −1.003564E-3 per degree of sideslip.
    #[test]
    fn non_uniform_dihedral_by_hand() {
        let mut warnings = Vec::new();
        let half_chord = Sweep {
            deg: 0.0,
            cos: 1.0,
            tan: 0.0,
        };
        let charts = straight_roll_charts(
            0.5,
            4.0,
            half_chord,
            0.0,
            Some(DihedralBreak {
                eta: 0.6,
                section_slope_per_rad: 2.0 * PI,
                tan_quarter_chord: 0.0,
            }),
            &mut warnings,
        )
        .unwrap();
        // Figure 5.1.2.1-28a starts at M cos Λ = 0.1 (its warning at M = 0 is expected); the
        // dihedral chart is read at its nodes.
        assert!(
            !warnings
                .iter()
                .any(|w| w.to_string().contains("5.1.2.1-31")),
            "{warnings:?}"
        );
        let DihedralRoll::NonUniform {
            at_break, at_tip, ..
        } = charts.dihedral
        else {
            panic!("expected the non-uniform dihedral chart");
        };
        assert!((at_break + 0.0045).abs() < 1e-9 && (at_tip + 0.00935).abs() < 1e-9);
        let term = charts.dihedral.term(2.0, 10.0);
        assert!((term + 1.003564e-3).abs() < 1e-9, "{term}");
    }

    /// Uniform dihedral: Γ·(Clβ/Γ)·K_MΓ with the two chart values given, Γ = 5°:
    /// 5 × (−2.0E-4) × 1.1 = −1.1E-3 per degree; the outboard dihedral plays no part.
    #[test]
    fn uniform_dihedral_term() {
        let d = DihedralRoll::Uniform {
            per_dihedral: -2.0e-4,
            compressibility: 1.1,
        };
        assert!((d.term(5.0, 40.0) + 1.1e-3).abs() < 1e-15);
    }
}
