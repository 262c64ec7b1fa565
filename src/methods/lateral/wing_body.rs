//! Wing-body: CYβ, Cnβ and Clβ of the original's `WING-BODY CONFIGURATION` page, DATCOM
//! 5.2.2.1 and 5.2.3.1 (the original's SUBLAT, wing-body terms, with the lateral geometry of
//! M29O35).

use serde::Serialize;

use super::body::lateral_reference_span;
use super::figures::{self, read};
use super::wing::{
    dihedral_break, panel_sweep_and_aspect_roll, straight_roll_charts, StraightRollCharts,
    DEG_PER_RAD,
};
use super::{finite, wing_inputs, Lateral, LateralError, LateralWarning, WingInputs};
use crate::case::Case;
use crate::geometry::body::body as body_geometry;
use crate::methods::wing::{WingAlone, WingType};
use crate::methods::wing_body::WingBody;
use crate::numeric::trapezoid;

/// Side-force factor of the wing height, wing above the body axis (z_w/(d/2) ≥ 0), per unit
/// z_w/(d/2) (DATCOM figure 5.2.1.1-7 as the original codes it).
const CYB_HIGH_WING_SLOPE: f64 = 0.49;
/// The same, wing below the body axis.
const CYB_LOW_WING_SLOPE: f64 = 0.85;
/// The largest |z_w/(d/2)| of figure 5.2.1.1-7: the wing at the top or bottom of the body.
const WING_HEIGHT_RANGE: f64 = 1.0;
/// Side force per degree of effective dihedral per degree of sideslip (as the wing's).
const CYB_PER_DIHEDRAL: f64 = 0.0001;
/// Reynolds-number factor K_Rl = 1 + ln(Re_l/10⁶)/4.86 (DATCOM figure 5.2.3.1-9 as a formula).
const REYNOLDS_FACTOR_SCALE: f64 = 4.86;
/// ΔClβ of the wing height: 1.2·√A/57.3 · (z_w/(b/2))·(d/(b/2)) (DATCOM 5.2.2.1 equation).
const WING_HEIGHT_ROLL: f64 = 1.2;
/// ΔClβ/Γ of the body diameter: −0.0005·A·(d/b)² (as the original codes it, with √A).
const BODY_DIAMETER_ROLL: f64 = -0.0005;

/// The geometry and chart values behind the wing-body derivatives (SI lengths).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct WingBodyLateralTerms {
    /// Wing height for the side force: −ZW + (c_r,exposed/4 + x_LE,exposed)·sin i_w −
    /// (b/2 − b'/2)·tan Γ_i, m (positive below the body axis).
    pub wing_height_side_force: f64,
    /// Wing height for the rolling moment: −ZW + c_r/4·sin i_w, m.
    pub wing_height_roll: f64,
    /// Body width at the wing 2(b/2 − b'/2), m.
    pub body_width_at_wing: f64,
    /// Side-force factor of the wing height applied to the body CLα.
    pub side_force_factor: f64,
    /// K_N (per degree) and K_Rl of DATCOM 5.2.3.1; none when not computable.
    pub k_n: Option<f64>,
    pub k_rl: Option<f64>,
    /// Body side projected area S_Bs, m², and body length l_B, m.
    pub side_area: f64,
    pub body_length: f64,
    /// K_f of figure 5.2.2.1-26 and the nose-to-tip-half-chord distance l_f, m.
    pub k_f: Option<f64>,
    pub nose_to_tip_half_chord: f64,
}

/// The body side-view quantities the yawing moment method needs (DATCOM 5.2.3.1): side
/// projected area, heights at l/4 and 3l/4, largest height and width, length.
pub(super) struct BodySide {
    length: f64,
    side_area: f64,
    height_quarter: f64,
    height_three_quarter: f64,
    pub max_height: f64,
    max_width: f64,
}

fn interpolate(x: &[f64], y: &[f64], at: f64) -> Option<f64> {
    let i = x.windows(2).position(|w| w[0] <= at && at <= w[1])?;
    let (x0, x1, y0, y1) = (x[i], x[i + 1], y[i], y[i + 1]);
    if x1 == x0 {
        return Some(y0);
    }
    Some(y0 + (y1 - y0) * (at - x0) / (x1 - x0))
}

fn largest(v: &[f64]) -> Option<f64> {
    v.iter().copied().filter(|v| v.is_finite()).reduce(f64::max)
}

pub(super) fn body_side(case: &Case) -> Option<BodySide> {
    let input = case.body.as_ref()?;
    let g = body_geometry(input).ok()?;
    let x0 = *g.x.first()?;
    let x: Vec<f64> = g.x.iter().map(|v| v - x0).collect();
    let length = g.length;
    let (quarter, three_quarter) = (0.25 * length, 0.75 * length);
    let max_width = 2.0 * largest(&g.r)?;
    let given_heights = !input.zu.is_empty() && input.zu.len() == input.zl.len();
    let (side_area, h1, h2, max_height) = if given_heights && input.x.len() == input.zu.len() {
        let xi: Vec<f64> = input.x.iter().map(|v| v - x0).collect();
        let height: Vec<f64> = input.zu.iter().zip(&input.zl).map(|(u, l)| u - l).collect();
        (
            trapezoid(&xi, &input.zu) - trapezoid(&xi, &input.zl),
            interpolate(&xi, &height, quarter)?,
            interpolate(&xi, &height, three_quarter)?,
            largest(&height)?,
        )
    } else {
        (
            2.0 * trapezoid(&x, &g.r),
            2.0 * interpolate(&x, &g.r, quarter)?,
            2.0 * interpolate(&x, &g.r, three_quarter)?,
            max_width,
        )
    };
    Some(BodySide {
        length,
        side_area,
        height_quarter: h1,
        height_three_quarter: h2,
        max_height,
        max_width,
    })
}

/// The wing-body CYβ, Cnβ and Clβ at subsonic speed for flight condition `condition_index`
/// of `case`, from the wing-alone results `wing` and the wing-body results `wing_body` at the
/// schedule angles `alpha_deg`. Per radian.
///
/// - CYβ, DATCOM 5.2.2.1 with figure 5.2.1.1-7 as the original codes it (SUBLAT):
///   CYβ = −K_i·CLα,B − 0.0001|Γ| per degree, K_i = 1 + 0.49·z/(d/2) (z ≥ 0) or
///   1 − 0.85·z/(d/2) (z < 0), CLα,B the body-alone slope at the first angle, z the wing height
///   below the body axis, d the body width at the wing, Γ the effective dihedral. The wing's own
///   CYβ is not added (as the original).
/// - Cnβ, DATCOM 5.2.3.1 (figure 5.2.3.1-8 K_N, K_Rl = 1 + ln(Re_l/10⁶)/4.86 of figure
///   5.2.3.1-9): Cnβ = −K_N K_Rl S_Bs l_B/(S b) per degree, the body in the presence of the
///   wing; the wing's own Cnβ is not added (as the original).
/// - Clβ, DATCOM 5.2.2.1 equation 5.2.2.1-a: straight wings
///   [CL_WB((Clβ/CL)_Λ K_MΛ K_f + (Clβ/CL)_A) + (Γ(Clβ/Γ)K_MΓ + ΔClβ/Γ·Γ)·S_w/S +
///   (ΔClβ,zw + θ tan Λc/4 ΔClβ/(θ tan Λc/4))·S_w/S]·b_w/b, K_f of figure 5.2.2.1-26; cranked
///   and double-delta wings: K_f on the two panels' sweep terms, their aspect-ratio terms, the
///   body-diameter term without the area ratio, no twist or dihedral (as the original).
///
/// Only the first row carries CYβ and Cnβ (the original prints them there only). Errors: no
/// wing, no condition, results of another schedule, charts.
pub fn wing_body_lateral(
    case: &Case,
    condition_index: usize,
    alpha_deg: &[f64],
    wing: &WingAlone,
    wing_body: &WingBody,
) -> Result<Lateral, LateralError> {
    let exposed = exposed_root(case, wing);
    wing_body_lateral_at_root(case, condition_index, alpha_deg, wing, wing_body, exposed)
}

/// The exposed root of a lifting surface on the body: DATCOM 5.2.2.1 takes the surface's
/// height z_w at the quarter chord of this root and the distance l_f of figure 5.2.2.1-26 from
/// the nose to the tip's half chord along the surface from this root.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct ExposedRoot {
    /// The chord at the body side c_r,e, m.
    pub chord: f64,
    /// Its leading edge behind the surface's apex (XW) along the body axis at the incidence
    /// i_w: (b/2 − b_e/2)·tan Λ_LE·cos i_w, m.
    pub leading_edge: f64,
}

/// The exposed root of the case's wing (whatever surface is in the wing's place: the
/// horizontal tail on the body-horizontal tail page), from the wing-alone planform terms, its
/// SSPN, SSPNE and incidence ALIW.
pub fn exposed_root(case: &Case, wing: &WingAlone) -> ExposedRoot {
    let p = &wing.terms.planform;
    let inboard_body = case
        .wing
        .as_ref()
        .and_then(|w| Some(w.sspn? - w.sspne.or(w.sspn)?))
        .unwrap_or(0.0);
    let incidence = case
        .synthesis
        .as_ref()
        .and_then(|s| s.aliw_deg)
        .unwrap_or(0.0);
    ExposedRoot {
        chord: p.exposed_root_chord,
        leading_edge: inboard_body * p.inboard.leading_edge.tan * incidence.to_radians().cos(),
    }
}

/// [`wing_body_lateral`] with the surface's exposed root given: the same method, the height
/// of the side-force factor and the l_f of K_f taken from `exposed` (as the rest of the geometry
/// from the case's wing). Per radian.
pub fn wing_body_lateral_at_root(
    case: &Case,
    condition_index: usize,
    alpha_deg: &[f64],
    wing: &WingAlone,
    wing_body: &WingBody,
    exposed: ExposedRoot,
) -> Result<Lateral, LateralError> {
    let WingInputs {
        plan,
        condition,
        semispan,
        root,
        tip,
        exposed_semispan,
        area,
    } = wing_inputs(case, condition_index, alpha_deg.len(), wing_body.cl.len())?;
    let n = alpha_deg.len();
    let outboard_span = plan.sspnop.unwrap_or(0.0);
    let mut warnings = Vec::new();
    let b_ref = lateral_reference_span(case);
    if b_ref.is_none() {
        warnings.push(LateralWarning::NoReferenceSpan);
    }
    let s_ref = wing_body.reference_area;
    let p = &wing.terms.planform;
    let span = 2.0 * semispan;
    let a = span * span / area;
    let mach = condition.mach;

    let synthesis = case.synthesis.as_ref();
    let get = |f: fn(&crate::case::Synthesis) -> Option<f64>| synthesis.and_then(f).unwrap_or(0.0);
    let (xw, zw, incidence) = (get(|s| s.xw), get(|s| s.zw), get(|s| s.aliw_deg));
    let sin_i = incidence.to_radians().sin();
    let nose = case
        .body
        .as_ref()
        .and_then(|b| b.x.first().copied())
        .unwrap_or(0.0);

    let dihedral_in = plan.dhdadi_deg.unwrap_or(0.0);
    let dihedral_station = plan.sspndd.unwrap_or(0.0);
    let dihedral_out = plan.dhdado_deg.unwrap_or(dihedral_in);
    let effective_dihedral_deg = (dihedral_in * (exposed_semispan - dihedral_station)
        + dihedral_out * dihedral_station)
        / exposed_semispan;

    // Lateral geometry (the original's M29O35).
    let inboard_body = semispan - exposed_semispan;
    let body_width_at_wing = 2.0 * inboard_body;
    let tan_le_in = p.inboard.leading_edge.tan;
    let tan_le_out = p.outboard.map_or(0.0, |o| o.leading_edge.tan);
    let exposed_root_le = exposed.leading_edge;
    let wing_height_side_force = -zw + (0.25 * exposed.chord + exposed_root_le) * sin_i
        - inboard_body * dihedral_in.to_radians().tan();
    let wing_height_roll = -zw + root / 4.0 * sin_i;
    let nose_to_tip_half_chord = (xw - nose)
        + exposed_root_le
        + outboard_span * tan_le_out
        + (exposed_semispan - outboard_span) * tan_le_in
        + tip / 2.0;

    // CYβ.
    let height_ratio = 2.0 * wing_height_side_force / body_width_at_wing;
    let side_force_factor = if height_ratio >= 0.0 {
        1.0 + CYB_HIGH_WING_SLOPE * height_ratio
    } else {
        1.0 - CYB_LOW_WING_SLOPE * height_ratio
    };
    let body = &wing_body.terms.body;
    let body_slope_per_deg = body
        .cla_per_rad
        .first()
        .copied()
        .flatten()
        .map(|v| v / DEG_PER_RAD);
    if body_width_at_wing <= 0.0 {
        warnings.push(LateralWarning::NoBodyWidthAtWing);
    } else if height_ratio.abs() > WING_HEIGHT_RANGE {
        warnings.push(LateralWarning::WingHeightOutside {
            ratio: height_ratio,
            factor: side_force_factor,
        });
    }
    let cyb_first = body_slope_per_deg.and_then(|cla| {
        finite(
            (-side_force_factor * cla - CYB_PER_DIHEDRAL * effective_dihedral_deg.abs())
                * DEG_PER_RAD,
        )
    });

    // Cnβ.
    let side = body_side(case);
    let reynolds = condition.reynolds_per_length * side.as_ref().map_or(0.0, |s| s.length);
    let k_rl = (reynolds > 0.0).then(|| 1.0 + (1e-6 * reynolds).ln() / REYNOLDS_FACTOR_SCALE);
    let k_n = match &side {
        Some(s)
            if s.side_area > 0.0
                && s.length > 0.0
                && s.height_three_quarter > 0.0
                && s.max_width > 0.0 =>
        {
            let step_a = read(
                figures::KN_STEP_A,
                &[
                    s.length * s.length / s.side_area,
                    body.xcg_from_nose / s.length,
                ],
                &mut warnings,
            )?;
            let step_b = read(
                figures::KN_STEP_B,
                &[(s.height_quarter / s.height_three_quarter).sqrt(), step_a],
                &mut warnings,
            )?;
            Some(read(
                figures::KN,
                &[s.max_height / s.max_width, step_b],
                &mut warnings,
            )?)
        }
        _ => None,
    };
    let cnb_first = match (k_n, k_rl, &side, b_ref) {
        (Some(kn), Some(krl), Some(s), Some(b)) => {
            finite(-kn * krl * s.side_area * s.length / (s_ref * b) * DEG_PER_RAD)
        }
        _ => None,
    };

    // Clβ.
    let sqrt_a = a.sqrt();
    let wing_height_term = WING_HEIGHT_ROLL * wing_height_roll * body_width_at_wing * sqrt_a
        / (DEG_PER_RAD * 2.0 * semispan * semispan);
    let diameter_term =
        BODY_DIAMETER_ROLL * sqrt_a * effective_dihedral_deg * (body_width_at_wing / span).powi(2);
    let k_f = read(
        figures::FUSELAGE_CORRECTION,
        &[a / p.half_chord.cos, nose_to_tip_half_chord / span],
        &mut warnings,
    )?;
    let parts = roll_parts(case, wing, a, mach, &mut warnings)?;
    let clb = match (parts, b_ref) {
        (Some(parts), Some(b)) => {
            let lift = parts.sweep * k_f + parts.aspect;
            let constant = if parts.straight {
                (parts.dihedral + diameter_term) * area / s_ref
            } else {
                diameter_term
            };
            let fixed = (wing_height_term + parts.twist) * area / s_ref;
            wing_body
                .cl
                .iter()
                .map(|cl| {
                    cl.and_then(|cl| {
                        finite((cl * lift + constant + fixed) * span / b * DEG_PER_RAD)
                    })
                })
                .collect()
        }
        _ => vec![None; n],
    };

    let mut cyb = vec![None; n];
    let mut cnb = vec![None; n];
    if n > 0 {
        cyb[0] = cyb_first;
        cnb[0] = cnb_first;
    }
    let terms = WingBodyLateralTerms {
        wing_height_side_force,
        wing_height_roll,
        body_width_at_wing,
        side_force_factor,
        k_n,
        k_rl,
        side_area: side.as_ref().map_or(0.0, |s| s.side_area),
        body_length: side.as_ref().map_or(0.0, |s| s.length),
        k_f: Some(k_f),
        nose_to_tip_half_chord,
    };
    Ok(Lateral {
        alpha_deg: alpha_deg.to_vec(),
        cyb,
        cnb,
        clb,
        wing_terms: None,
        wing_body_terms: Some(terms),
        fin_terms: None,
        twin_panel_terms: None,
        warnings,
    })
}

/// The wing's Clβ chart terms as the wing-body equation regroups them, per degree.
struct RollParts {
    straight: bool,
    /// (Clβ/CL)_Λ·K_MΛ (both panels summed for a two-panel planform).
    sweep: f64,
    /// (Clβ/CL)_A (both panels summed).
    aspect: f64,
    /// Γ_i (Clβ/Γ) K_MΓ (straight wings).
    dihedral: f64,
    /// θ tan Λc/4 ΔClβ/(θ tan Λc/4) (straight wings).
    twist: f64,
}

/// Chart terms of DATCOM 5.1.2.1 for the wing-body Clβ; none where the original's wing-body
/// equation has no defined value here (straight wing with A < 1).
fn roll_parts(
    case: &Case,
    wing: &WingAlone,
    a: f64,
    mach: f64,
    warnings: &mut Vec<LateralWarning>,
) -> Result<Option<RollParts>, LateralError> {
    let plan = case.wing.as_ref().ok_or(LateralError::NoWing)?;
    let p = &wing.terms.planform;
    let root = plan.chrdr.unwrap_or(0.0);
    let tip = plan.chrdtp.unwrap_or(0.0);
    if wing.planform_type == WingType::Straight {
        if a < 1.0 {
            return Ok(None);
        }
        let StraightRollCharts {
            sweep_per_cl,
            sweep_compressibility,
            aspect_per_cl,
            twist,
            dihedral,
        } = straight_roll_charts(
            tip / root,
            a,
            p.inboard.half_chord,
            mach,
            dihedral_break(plan, wing),
            warnings,
        )?;
        let tan_quarter_in = 0.5 * (p.inboard.leading_edge.tan + p.inboard.half_chord.tan);
        let dihedral_in = plan.dhdadi_deg.unwrap_or(0.0);
        return Ok(Some(RollParts {
            straight: true,
            sweep: sweep_per_cl * sweep_compressibility,
            aspect: aspect_per_cl,
            dihedral: dihedral.term(dihedral_in, plan.dhdado_deg.unwrap_or(dihedral_in)),
            twist: plan.twista_deg.unwrap_or(0.0) * tan_quarter_in * twist,
        }));
    }
    let geometry = |what: &str| LateralError::Geometry {
        reason: format!("a two-panel planform needs {what}"),
    };
    let outboard = p.outboard.ok_or_else(|| geometry("an outboard panel"))?;
    let extended = p
        .extended_outboard
        .ok_or_else(|| geometry("an outboard panel"))?;
    let break_chord = plan.chrdbp.ok_or_else(|| geometry("CHRDBP"))?;
    let outboard_span = plan.sspnop.ok_or_else(|| geometry("SSPNOP"))?;
    let semispan = plan.sspn.unwrap_or(0.0);
    let inboard_aspect = 4.0 * (semispan - outboard_span) / (root + break_chord);
    let (sweep_in, aspect_in) = panel_sweep_and_aspect_roll(
        inboard_aspect,
        break_chord / root,
        p.inboard.half_chord.deg,
        p.inboard.half_chord.cos,
        mach,
        warnings,
    )?;
    let (sweep_out, aspect_out) = panel_sweep_and_aspect_roll(
        extended.aspect_ratio,
        extended.taper,
        outboard.half_chord.deg,
        outboard.half_chord.cos,
        mach,
        warnings,
    )?;
    Ok(Some(RollParts {
        straight: false,
        sweep: sweep_in + sweep_out,
        aspect: aspect_in + aspect_out,
        dihedral: 0.0,
        twist: 0.0,
    }))
}
