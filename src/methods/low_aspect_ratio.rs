//! DATCOM sections 4.8 and 5.5: low-aspect-ratio wing-body combinations (lifting bodies), the
//! deck's `$LARWB`, at subsonic speeds. The original program's routine is LOARWB, with the
//! slopes of CL and CM taken by its overlay M14O16.
//!
//! * 4.8.1.2, normal force: a cubic through the slope at zero normal force and the normal force
//!   at 20° (both slender-body values times correlation factors), with a shape factor z.
//! * 4.8.2.2, axial force: skin friction and base pressure at zero normal force, a
//!   leading-edge-suction term that grows with CN √(α/20°) and a base-pressure term with (α/20°)².
//! * 4.8.3.2, pitching moment: the centre of pressure of the planform (semi-apex angle, nose
//!   blunting, frontal area), fixed with angle of attack.
//! * 5.5.1, 5.5.2, 5.5.3: sideforce, rolling-moment and yawing-moment derivatives in sideslip,
//!   from their values near zero normal force and correlations at 20°.
//!
//! Angles of the correlations are in degrees as the figures give them. Coefficients are on
//! SREF, moments on the body length L about XCG; derivatives per radian.

use serde::Serialize;

use crate::case::LowAspectRatioWingBody;
use crate::charts::{self, ChartWarning};
use crate::methods::body::{skin_friction_coefficient, BodyMethodError, BodyWarning};
use crate::numeric::curve_slopes;

/// The DATCOM figures this method reads (files under `charts/low_aspect_ratio/` and
/// `charts/body/`).
pub mod figures {
    /// CNα correlation factor at CN = 0, sharp leading edge, against the leading-edge angle.
    pub const CNA_FACTOR_SHARP: &str = "4.8.1.2-12a";
    /// CNα correlation factor at CN = 0, round leading edge, against r_LE/b.
    pub const CNA_FACTOR_ROUND: &str = "4.8.1.2-12b";
    /// CN correlation factor at 20°, sharp leading edge.
    pub const CN20_FACTOR_SHARP: &str = "4.8.1.2-13a";
    /// CN correlation factor at 20°, round leading edge.
    pub const CN20_FACTOR_ROUND: &str = "4.8.1.2-13b";
    /// Shape factor z of the normal-force curve, sharp leading edge.
    pub const SHAPE_Z_SHARP: &str = "4.8.1.2-14a";
    /// Shape factor z of the normal-force curve, round leading edge.
    pub const SHAPE_Z_ROUND: &str = "4.8.1.2-14b";
    /// Base-pressure coefficient at CN = 0 against the base shape parameter.
    pub const BASE_PRESSURE: &str = "4.8.2.1-7";
    /// Axial-force (leading-edge suction) correlation factor at 20°.
    pub const SUCTION_FACTOR: &str = "4.8.2.2-10";
    /// Base-pressure factor at 20°, base aft of the lifting surface.
    pub const BASE_FACTOR_LIFTING: &str = "4.8.2.2-11a";
    /// Base-pressure factor at 20°, base aft of non-lifting surfaces.
    pub const BASE_FACTOR_BODY: &str = "4.8.2.2-11b";
    /// Centre of pressure of thin pointed delta planforms against the semi-apex angle.
    pub const CENTRE_OF_PRESSURE: &str = "4.8.3.2-6b";
    /// Shift of the centre of pressure for nose blunting.
    pub const BLUNT_NOSE_SHIFT: &str = "4.8.3.2-7a";
    /// Sideforce derivative near CN = 0 against the side area.
    pub const SIDEFORCE_ZERO: &str = "5.5.1.1-6";
    /// Sideforce increment over CN² at 20°, round leading edges.
    pub const SIDEFORCE_CN2_ROUND: &str = "5.5.1.2-8";
    /// Sideforce increment over CN² at 20°, sharp leading edges.
    pub const SIDEFORCE_CN2_SHARP: &str = "5.5.1.2-9";
    /// Rolling moment over CN near CN = 0 against the semi-apex angle.
    pub const ROLL_ZERO: &str = "5.5.2.1-8a";
    /// Increment of the rolling moment over CN near CN = 0 for nose blunting.
    pub const ROLL_ZERO_BLUNT: &str = "5.5.2.1-8b";
    /// Rolling-moment factor at 20°, round leading edges.
    pub const ROLL_FACTOR_ROUND: &str = "5.5.2.2-12a";
    /// Rolling-moment factor at 20°, sharp leading edges.
    pub const ROLL_FACTOR_SHARP: &str = "5.5.2.2-12b";
    /// Side-area increment of the rolling-moment factor at 20°.
    pub const ROLL_FACTOR_SIDE_AREA: &str = "5.5.2.2-13";
    /// Centre of pressure of the side area in sideslip.
    pub const SIDE_CENTRE_OF_PRESSURE: &str = "5.5.3.1-6";
    /// Cut-off Reynolds number of the roughness (body figure).
    pub const CUTOFF_REYNOLDS: &str = "4.1.5.1-27";

    /// Every figure of the method.
    pub const ALL: [&str; 22] = [
        CNA_FACTOR_SHARP,
        CNA_FACTOR_ROUND,
        CN20_FACTOR_SHARP,
        CN20_FACTOR_ROUND,
        SHAPE_Z_SHARP,
        SHAPE_Z_ROUND,
        BASE_PRESSURE,
        SUCTION_FACTOR,
        BASE_FACTOR_LIFTING,
        BASE_FACTOR_BODY,
        CENTRE_OF_PRESSURE,
        BLUNT_NOSE_SHIFT,
        SIDEFORCE_ZERO,
        SIDEFORCE_CN2_ROUND,
        SIDEFORCE_CN2_SHARP,
        ROLL_ZERO,
        ROLL_ZERO_BLUNT,
        ROLL_FACTOR_ROUND,
        ROLL_FACTOR_SHARP,
        ROLL_FACTOR_SIDE_AREA,
        SIDE_CENTRE_OF_PRESSURE,
        CUTOFF_REYNOLDS,
    ];
}

/// The reference angle of the correlations, 20°, in degrees and in radians (as DATCOM writes
/// it, 0.349).
const ALPHA_20_DEG: f64 = 20.0;
const ALPHA_20_RAD: f64 = 0.349;
/// 4.8.1.2: 1/0.349², the cubic's coefficient, and the factor of the z term.
const CUBIC_SCALE: f64 = 8.21;
const SHAPE_SLOPE: f64 = 2.81;
/// 4.8.1.2: slender-body CN at 20°, (CN)_20 = 2.195 (A + 0.61)/(A + 4).
const CN20_SLENDER: f64 = 2.195;
const CN20_ASPECT_OFFSET: f64 = 0.61;
/// 4.8.1.2 and 4.8.2.2: the aspect-ratio factor 4/(4 + A) and its kin (A + 2)/(A + 4).
const ASPECT_FOUR: f64 = 4.0;
const ASPECT_TWO: f64 = 2.0;
/// 4.8.3.2: pitching moment at zero normal force per degree of zero-lift angle.
const CM0_PER_DEG: f64 = 0.0003333;
/// 4.8.3.2: centre-of-pressure shift per unit frontal area ratio.
const FRONTAL_AREA_SHIFT: f64 = 0.102;
/// 5.5.2.2: the rolling-moment factor at 20°, 1/(1 + 0.152/tan θ).
const ROLL_APEX_TERM: f64 = 0.152;
/// 5.5.3.1: the planform's share of the yawing moment, per degree.
const YAW_PLANFORM_PER_DEG: f64 = 0.006;

/// Why the method gives no page.
#[derive(Debug, Clone, PartialEq, thiserror::Error, Serialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
#[non_exhaustive]
pub enum LowAspectRatioError {
    #[error("$LARWB has no {variable}: the low-aspect-ratio wing-body method needs it")]
    MissingInput { variable: &'static str },
    #[error("$LARWB gives neither DELTEP (sharp leading edge) nor R3LEOB (round leading edge)")]
    NoLeadingEdge,
    #[error("the low-aspect-ratio wing-body cannot be computed: {reason}")]
    Degenerate { reason: String },
    #[error("chart {chart} is not embedded or not valid")]
    MissingChart { chart: &'static str },
    #[error(
        "chart {chart} gives no value at {}",
        crate::charts::describe_query(chart, args)
    )]
    ChartNoValue { chart: &'static str, args: Vec<f64> },
    #[error("skin friction: {0}")]
    SkinFriction(BodyMethodError),
}

/// Flight condition of one page.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LowAspectRatioFlight {
    pub mach: f64,
    /// Reynolds number per metre.
    pub reynolds_per_length: f64,
    /// Roughness height, m.
    pub roughness: f64,
}

/// 4.8.1.2 terms of the normal-force curve.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct NormalForceTerms {
    /// Slender-body slope at zero normal force, per radian: (πA/2 + 2 S_F/S)·4/(4 + A).
    pub slope_theory: f64,
    /// Correlation factor of the slope (figure 4.8.1.2-12a or -12b).
    pub slope_factor: f64,
    /// Slender-body CN at 20°.
    pub cn20_theory: f64,
    /// Correlation factor of CN at 20° (figure 4.8.1.2-13a or -13b).
    pub cn20_factor: f64,
    /// Shape factor z (figure 4.8.1.2-14a or -14b).
    pub shape_z: f64,
    /// CNα at zero normal force, per radian.
    pub slope: f64,
    /// CN at 20°.
    pub cn20: f64,
}

/// 4.8.2.2 terms of the axial force.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct AxialForceTerms {
    /// Reynolds number on L, or the roughness cut-off when smaller.
    pub reynolds_number: f64,
    /// Turbulent flat-plate skin friction (figure 4.1.5.1-26).
    pub skin_friction: f64,
    /// Base-pressure coefficient at CN = 0 (figure 4.8.2.1-7).
    pub base_pressure: f64,
    /// Base axial-force coefficient at CN = 0: Cp_b P_b S_b/(2 √(π S_b) S).
    pub base_axial: f64,
    /// CA at CN = 0: C_f S_wet/S minus the base term.
    pub ca0: f64,
    /// Suction factor ΔCX/ΔCX_c (figure 4.8.2.2-10) times 0.349 (A + 2)/(A + 4).
    pub suction: f64,
    /// Base-pressure factor at 20° (figure 4.8.2.2-11a or -11b).
    pub base_factor_20: f64,
}

/// 4.8.3.2 terms of the pitching moment.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct PitchingMomentTerms {
    /// Centre of pressure of the pointed planform over L (figure 4.8.3.2-6b).
    pub xcp_planform: f64,
    /// Shift for nose blunting (figure 4.8.3.2-7a), zero for a pointed nose.
    pub xcp_blunting: f64,
    /// Shift for the frontal area, 0.102 S_F/S.
    pub xcp_frontal: f64,
    /// CM at zero normal force.
    pub cm0: f64,
    /// Arm XCG/L − x_cp/L.
    pub arm: f64,
}

/// 5.5 terms of the sideslip derivatives (per radian unless said).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct SideslipTerms {
    /// CYβ near CN = 0 (figure 5.5.1.1-6).
    pub cyb0: f64,
    /// ΔCYβ/CN² at 20° (figure 5.5.1.2-8 or -9).
    pub cyb_per_cn2: f64,
    /// Centre of pressure of the side area (figure 5.5.3.1-6 times XCENSB).
    pub side_xcp: f64,
    /// Clβ/CN near CN = 0 (figures 5.5.2.1-8a and -8b).
    pub clb_per_cn0: f64,
    /// Blunting increment of Clβ/CN near CN = 0.
    pub clb_per_cn0_blunt: f64,
    /// Rolling-moment factor at 20° (figures 5.5.2.2-12 plus -13).
    pub roll_factor_20: f64,
}

/// The page: coefficients at each angle of attack and the terms behind them.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct LowAspectRatioWingBodyPage {
    /// Angle of zero normal force, degrees: atan(ZB/L).
    pub alpha0_deg: f64,
    pub normal_force: NormalForceTerms,
    pub axial_force: AxialForceTerms,
    pub pitching_moment: PitchingMomentTerms,
    pub cn: Vec<f64>,
    pub ca: Vec<f64>,
    pub cm: Vec<f64>,
    pub cl: Vec<f64>,
    pub cd: Vec<f64>,
    /// CM/CN (none where CN = 0).
    pub xcp: Vec<Option<f64>>,
    /// dCL/dα and dCM/dα per radian, from the parabola through neighbouring angles.
    pub cla: Vec<Option<f64>>,
    pub cma: Vec<Option<f64>>,
    /// Sideslip derivatives; `Err` when $LARWB lacks their inputs.
    pub sideslip: Result<Sideslip, LowAspectRatioError>,
    /// Charts read outside their data.
    pub warnings: Vec<ChartWarning>,
}

/// CYβ, Cnβ, Clβ per radian at each angle of attack.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Sideslip {
    pub terms: SideslipTerms,
    pub cyb: Vec<f64>,
    pub cnb: Vec<f64>,
    pub clb: Vec<f64>,
}

struct Reader {
    warnings: Vec<ChartWarning>,
}

impl Reader {
    fn read(&mut self, id: &'static str, args: &[f64]) -> Result<f64, LowAspectRatioError> {
        let chart = charts::get(id).ok_or(LowAspectRatioError::MissingChart { chart: id })?;
        let warnings = &mut self.warnings;
        let value = chart.lookup_each(args, |w| {
            if !warnings.contains(&w) {
                warnings.push(w);
            }
        });
        value.ok_or_else(|| LowAspectRatioError::ChartNoValue {
            chart: id,
            args: args.to_vec(),
        })
    }
}

fn need(v: Option<f64>, variable: &'static str) -> Result<f64, LowAspectRatioError> {
    v.filter(|x| x.is_finite())
        .ok_or(LowAspectRatioError::MissingInput { variable })
}

fn positive(v: Option<f64>, variable: &'static str) -> Result<f64, LowAspectRatioError> {
    let x = need(v, variable)?;
    if x > 0.0 {
        Ok(x)
    } else {
        Err(LowAspectRatioError::Degenerate {
            reason: format!("{variable} = {x} is not positive"),
        })
    }
}

/// The leading edge the normal-force correlations take: sharp when DELTEP is given.
#[derive(Debug, Clone, Copy)]
enum LeadingEdge {
    Sharp {
        angle_deg: f64,
    },
    Round {
        radius_over_span: f64,
        sweep_deg: f64,
    },
}

/// 4.8.1.2: normal force against the angle from zero normal force `alpha_rad`:
/// CN = CNα α + 8.21 (CN20 − 0.349 CNα)(z + 2.81 (1 − z) α) α².
pub fn normal_force_coefficient(t: &NormalForceTerms, alpha_rad: f64) -> f64 {
    t.slope * alpha_rad
        + CUBIC_SCALE
            * (t.cn20 - ALPHA_20_RAD * t.slope)
            * (t.shape_z + SHAPE_SLOPE * (1.0 - t.shape_z) * alpha_rad)
            * alpha_rad
            * alpha_rad
}

/// 4.8.1.2: slope at zero normal force and CN at 20° from slender-body theory times the
/// correlation factors of the leading edge.
fn normal_force_terms(
    aspect_ratio: f64,
    frontal_over_reference: f64,
    edge: LeadingEdge,
    r: &mut Reader,
) -> Result<NormalForceTerms, LowAspectRatioError> {
    let slope_theory = (std::f64::consts::PI * aspect_ratio / 2.0 + 2.0 * frontal_over_reference)
        * (ASPECT_FOUR / (ASPECT_FOUR + aspect_ratio));
    let cn20_theory =
        CN20_SLENDER * ((aspect_ratio + CN20_ASPECT_OFFSET) / (aspect_ratio + ASPECT_FOUR));
    let (slope_factor, cn20_factor, shape_z, sweep_factor) = match edge {
        LeadingEdge::Sharp { angle_deg } => (
            r.read(figures::CNA_FACTOR_SHARP, &[angle_deg])?,
            r.read(figures::CN20_FACTOR_SHARP, &[angle_deg])?,
            r.read(figures::SHAPE_Z_SHARP, &[angle_deg])?,
            1.0,
        ),
        LeadingEdge::Round {
            radius_over_span,
            sweep_deg,
        } => (
            r.read(figures::CNA_FACTOR_ROUND, &[radius_over_span])?,
            r.read(figures::CN20_FACTOR_ROUND, &[radius_over_span])?,
            r.read(figures::SHAPE_Z_ROUND, &[radius_over_span])?,
            (1.0 + sweep_deg.to_radians().cos()) / 2.0,
        ),
    };
    Ok(NormalForceTerms {
        slope_theory,
        slope_factor,
        cn20_theory,
        cn20_factor,
        shape_z,
        slope: slope_theory * slope_factor,
        cn20: cn20_theory * sweep_factor * cn20_factor,
    })
}

/// The $LARWB page at one flight condition (DATCOM 4.8 and 5.5; the original's LOARWB).
///
/// The curves are functions of the angle from zero normal force α' = α − α₀, α₀ = atan(ZB/L).
pub fn low_aspect_ratio_wing_body(
    lb: &LowAspectRatioWingBody,
    flight: LowAspectRatioFlight,
    alpha_deg: &[f64],
) -> Result<LowAspectRatioWingBodyPage, LowAspectRatioError> {
    let mut r = Reader {
        warnings: Vec::new(),
    };
    let sref = positive(lb.sref, "SREF")?;
    let length = positive(lb.length, "L")?;
    let xcg = lb.xcg.unwrap_or(0.0);
    let aspect_ratio = positive(lb.aspect_ratio, "AR")?;
    let sfront = positive(lb.sfront, "SFRONT")?;
    let swet = need(lb.swet, "SWET")?;
    let perbas = need(lb.perbas, "PERBAS")?;
    let sbase = need(lb.sbase, "SBASE")?;
    // The base's height divides its shape only when there is a base.
    let hb = if sbase > 0.0 {
        positive(lb.hb, "HB")?
    } else {
        need(lb.hb, "HB")?
    };
    let bb = positive(lb.bb, "BB")?;
    let theta_deg = need(lb.thetad_deg, "THETAD")?;
    let zb = lb.zb.unwrap_or(0.0);
    let r3leob = lb.r3leob.filter(|x| x.is_finite());
    let edge = match (lb.deltep_deg.filter(|x| x.is_finite()), r3leob) {
        (Some(angle_deg), _) => LeadingEdge::Sharp { angle_deg },
        (None, Some(radius_over_span)) => LeadingEdge::Round {
            radius_over_span,
            sweep_deg: lb.deltal_deg.unwrap_or(0.0),
        },
        (None, None) => return Err(LowAspectRatioError::NoLeadingEdge),
    };
    let frontal = sfront / sref;
    let alpha0_deg = (zb / length).atan().to_degrees();
    let alpha_prime: Vec<f64> = alpha_deg.iter().map(|a| a - alpha0_deg).collect();

    // 4.8.1.2, normal force.
    let normal_force = normal_force_terms(aspect_ratio, frontal, edge, &mut r)?;
    let cn_prime: Vec<f64> = alpha_prime
        .iter()
        .map(|a| normal_force_coefficient(&normal_force, a.to_radians()))
        .collect();

    // 4.8.2.2, axial force.
    let base_shape = 2.0 * sbase / (std::f64::consts::PI * length * (hb + bb));
    let base_pressure = r.read(figures::BASE_PRESSURE, &[base_shape])?;
    // Without a base there is no base drag (the expression's S_b/√S_b is 0/0 there).
    let base_axial = if sbase == 0.0 {
        0.0
    } else {
        base_pressure * perbas * sbase / (2.0 * (std::f64::consts::PI * sbase).sqrt() * sref)
    };
    let reynolds_length = flight.reynolds_per_length * length;
    let log_cutoff = r.read(
        figures::CUTOFF_REYNOLDS,
        &[flight.mach, (length / flight.roughness).log10()],
    )?;
    let reynolds_number = reynolds_length.min(10f64.powf(log_cutoff));
    let mut body_warnings = Vec::new();
    let skin_friction = skin_friction_coefficient(reynolds_number, flight.mach, &mut body_warnings)
        .map_err(LowAspectRatioError::SkinFriction)?;
    for w in body_warnings {
        if let BodyWarning::Chart(c) = w {
            if !r.warnings.contains(&c) {
                r.warnings.push(c);
            }
        }
    }
    let ca0 = skin_friction * swet / sref - base_axial;
    let suction_geometry = 2.0 * r3leob.unwrap_or(0.0) * aspect_ratio / frontal;
    let suction_factor = r.read(figures::SUCTION_FACTOR, &[suction_geometry, frontal])?;
    let suction = suction_factor
        * ALPHA_20_RAD
        * ((aspect_ratio + ASPECT_TWO) / (aspect_ratio + ASPECT_FOUR));
    // Without a base (SBASE = 0) there is no base drag to grow with the angle (and the base's
    // shape, which divides by √SBASE, is not defined): the factor is 1.
    let base_factor_20 = if sbase == 0.0 {
        1.0
    } else {
        let base_width_shape = bb * bb / (hb * sbase.sqrt());
        if lb.blf.unwrap_or(false) {
            r.read(figures::BASE_FACTOR_BODY, &[base_width_shape])?
        } else {
            r.read(figures::BASE_FACTOR_LIFTING, &[base_width_shape])?
        }
    };
    let base_growth = base_axial * (base_factor_20 - 1.0);
    let ca_prime: Vec<f64> = alpha_prime
        .iter()
        .zip(&cn_prime)
        .map(|(a, cn)| {
            ca0 - suction * cn * (a.abs() / ALPHA_20_DEG).sqrt()
                - base_growth * (a / ALPHA_20_DEG).powi(2)
        })
        .collect();
    let axial_force = AxialForceTerms {
        reynolds_number,
        skin_friction,
        base_pressure,
        base_axial,
        ca0,
        suction,
        base_factor_20,
    };

    // 4.8.3.2, pitching moment.
    let bluntness = 1.0 - 4.0 * theta_deg.to_radians().tan() / aspect_ratio;
    let xcp_blunting = if lb.roundn.unwrap_or(false) {
        r.read(figures::BLUNT_NOSE_SHIFT, &[theta_deg, bluntness])?
    } else {
        0.0
    };
    let xcp_planform = r.read(figures::CENTRE_OF_PRESSURE, &[theta_deg])?;
    let xcp_frontal = FRONTAL_AREA_SHIFT * frontal;
    let arm = xcg / length - (xcp_planform + xcp_blunting + xcp_frontal);
    let cm0 = CM0_PER_DEG * alpha0_deg;
    let pitching_moment = PitchingMomentTerms {
        xcp_planform,
        xcp_blunting,
        xcp_frontal,
        cm0,
        arm,
    };
    let cm_prime: Vec<f64> = cn_prime.iter().map(|cn| cm0 + arm * cn).collect();

    // The page's angle α is α₀ + α' (the handbook's reading; the original instead reads its
    // α' tables at α, which undoes the shift, see docs/larwb.md).
    let (cn, ca, cm) = (cn_prime.clone(), ca_prime, cm_prime);
    let mut cl = Vec::with_capacity(cn.len());
    let mut cd = Vec::with_capacity(cn.len());
    let mut xcp = Vec::with_capacity(cn.len());
    for k in 0..cn.len() {
        let (s, c) = alpha_deg[k].to_radians().sin_cos();
        cl.push(cn[k] * c - ca[k] * s);
        cd.push(ca[k] * c + cn[k] * s);
        xcp.push(
            (cn[k] != 0.0)
                .then(|| cm[k] / cn[k])
                .filter(|v| v.is_finite()),
        );
    }
    let alpha_rad: Vec<f64> = alpha_deg.iter().map(|a| a.to_radians()).collect();
    let some = |v: &[f64]| v.iter().map(|x| Some(*x)).collect::<Vec<_>>();
    let cla = curve_slopes(&alpha_rad, &some(&cl));
    let cma = curve_slopes(&alpha_rad, &some(&cm));

    let sideslip = sideslip(
        lb,
        sref,
        xcg,
        theta_deg,
        aspect_ratio,
        bb,
        &alpha_prime,
        &cn_prime,
        &mut r,
    );
    Ok(LowAspectRatioWingBodyPage {
        alpha0_deg,
        normal_force,
        axial_force,
        pitching_moment,
        cn,
        ca,
        cm,
        cl,
        cd,
        xcp,
        cla,
        cma,
        sideslip,
        warnings: r.warnings,
    })
}

/// 5.5.1 to 5.5.3: CYβ = CYβ₀ + (ΔCYβ/CN²)₂₀ CN²; Cnβ from CYβ acting at the side area's
/// centre of pressure and the planform's share acting at its centroid; Clβ = CN [(Clβ/CN)₀
/// (1 − (α/20)²) + (K₂₀ (Clβ/CN)₂₀ + Δ_blunt)(α/20)²].
#[allow(clippy::too_many_arguments)]
fn sideslip(
    lb: &LowAspectRatioWingBody,
    sref: f64,
    xcg: f64,
    theta_deg: f64,
    aspect_ratio: f64,
    bb: f64,
    alpha_prime: &[f64],
    cn_prime: &[f64],
    r: &mut Reader,
) -> Result<Sideslip, LowAspectRatioError> {
    let sbs = positive(lb.sbs, "SBS")?;
    let sbslb = need(lb.sbslb, "SBSLB")?;
    let xcensb = need(lb.xcensb, "XCENSB")?;
    let xcenw = need(lb.xcenw, "XCENW")?;
    let side_area = sbs / sref;
    // 5.5.1: sideforce.
    let cyb0 = r.read(figures::SIDEFORCE_ZERO, &[side_area])?;
    let r3leob = lb.r3leob.filter(|x| x.is_finite());
    let cyb_per_cn2 = match r3leob {
        Some(rle) => r.read(figures::SIDEFORCE_CN2_ROUND, &[rle, side_area])?,
        None => {
            let angle = need(lb.deltep_deg, "DELTEP")?;
            r.read(figures::SIDEFORCE_CN2_SHARP, &[angle, side_area])?
        }
    };
    // 5.5.3.1: centre of pressure of the side area.
    let side_xcp = r.read(figures::SIDE_CENTRE_OF_PRESSURE, &[sbslb / sbs])? * xcensb;
    let side_arm = (xcg - side_xcp) / bb;
    let planform_arm = (xcg - xcenw) / bb;
    // 5.5.2: rolling moment.
    let clb_per_cn0 = r.read(figures::ROLL_ZERO, &[theta_deg])?;
    let bluntness = 1.0 - 4.0 * theta_deg.to_radians().tan() / aspect_ratio;
    let clb_per_cn0_blunt = if lb.roundn.unwrap_or(false) {
        r.read(figures::ROLL_ZERO_BLUNT, &[theta_deg, bluntness])?
    } else {
        0.0
    };
    let edge_factor = match r3leob {
        Some(rle) => r.read(figures::ROLL_FACTOR_ROUND, &[rle])?,
        None => r.read(
            figures::ROLL_FACTOR_SHARP,
            &[need(lb.deltep_deg, "DELTEP")?],
        )?,
    };
    let side_area_factor = r.read(figures::ROLL_FACTOR_SIDE_AREA, &[side_area])?;
    let roll_factor_20 = edge_factor + side_area_factor;
    let clb_per_cn20 = clb_per_cn0 / (1.0 + ROLL_APEX_TERM / theta_deg.to_radians().tan());
    let per_deg = 1f64.to_radians();
    let mut cyb = Vec::with_capacity(cn_prime.len());
    let mut cnb = Vec::with_capacity(cn_prime.len());
    let mut clb = Vec::with_capacity(cn_prime.len());
    for (a, cn) in alpha_prime.iter().zip(cn_prime) {
        let y = cyb0 + cyb_per_cn2 * cn * cn;
        let n_per_deg = (y * per_deg + YAW_PLANFORM_PER_DEG) * side_arm * per_deg
            - YAW_PLANFORM_PER_DEG * planform_arm * per_deg;
        let q = (a / ALPHA_20_DEG).powi(2);
        let l = cn
            * (clb_per_cn0 * (1.0 - q) + (roll_factor_20 * clb_per_cn20 + clb_per_cn0_blunt) * q);
        cyb.push(y);
        cnb.push(n_per_deg / per_deg);
        clb.push(l);
    }
    Ok(Sideslip {
        terms: SideslipTerms {
            cyb0,
            cyb_per_cn2,
            side_xcp,
            clb_per_cn0,
            clb_per_cn0_blunt,
            roll_factor_20,
        },
        cyb,
        cnb,
        clb,
    })
}
