//! Wing-body drag at subsonic speeds, DATCOM 4.3.3.1 (zero-lift drag with the interference
//! factor R_WB; drag due to lift of the body and the wing), and the original's regression of
//! the drag due to lift of straight-wing bodies.

use serde::Serialize;

use super::figures;
use super::{WingBodyError, WingBodyWarning};

/// Zero-lift drag of the combination and its parts, on the reference area.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct WingBodyZeroLiftDrag {
    /// Reynolds number on the body length, R_l.
    pub fuselage_reynolds_number: f64,
    /// R_WB of figure 4.3.3.1-37.
    pub interference_factor: f64,
    /// Wing-alone zero-lift drag.
    pub wing: f64,
    /// Body skin friction with its form factor.
    pub body_friction: f64,
    /// Body base drag (not multiplied by R_WB).
    pub body_base: f64,
    /// (wing + body friction) R_WB + body base.
    pub total: f64,
}

/// DATCOM 4.3.3.1, eq. 4.3.3.1-a at zero lift: C_D0,WB = (C_D0,W + C_Df,B) R_WB + C_Db,B, with
/// R_WB from figure 4.3.3.1-37 at the Mach number and the Reynolds number on the body length
/// (quadratic extrapolation beyond the chart, linear above its Reynolds numbers, as the
/// original). Original: WBDRAG.
pub fn wing_body_zero_lift_drag(
    mach: f64,
    fuselage_reynolds_number: f64,
    wing: f64,
    body_friction: f64,
    body_base: f64,
    warnings: &mut Vec<WingBodyWarning>,
) -> Result<WingBodyZeroLiftDrag, WingBodyError> {
    let r = figures::read(
        figures::DRAG_INTERFERENCE,
        &[mach, fuselage_reynolds_number],
        warnings,
    )?;
    Ok(WingBodyZeroLiftDrag {
        fuselage_reynolds_number,
        interference_factor: r,
        wing,
        body_friction,
        body_base,
        total: (wing + body_friction) * r + body_base,
    })
}

/// The variables of the regression, as the original forms them.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct RegressionInputs {
    /// Theoretical aspect ratio A and taper ratio λ.
    pub aspect_ratio: f64,
    pub taper: f64,
    /// tan Λ_LE.
    pub tan_leading_edge: f64,
    /// Section thickness ratio t/c.
    pub thickness_ratio: f64,
    /// l_n: body length ahead of the exposed root's leading edge, in body widths at the wing
    /// (in maximum body diameters when the largest section lies ahead of it).
    pub nose_length: f64,
    /// l_a: body length behind the exposed root's trailing edge, likewise.
    pub afterbody_length: f64,
    /// Transition strips (FLTCON TR): 1, else 0.
    pub transition: f64,
    /// Section leading-edge radius over chord.
    pub leading_edge_radius: f64,
    /// Twist TWISTA, deg.
    pub twist_deg: f64,
    /// Section maximum camber y_c/c (YCM) and design lift coefficient (CLD).
    pub max_camber: f64,
    pub design_lift: f64,
    /// Reynolds number on the theoretical mean aerodynamic chord, held in [8E5, 8E6].
    pub reynolds_number: f64,
}

/// Ranges of the regression's data; outside them the original does not use it.
const ASPECT_RATIO: (f64, f64) = (1.6, 6.0);
const TAN_LEADING_EDGE: (f64, f64) = (0.0, 2.74748);
const THICKNESS_RATIO: (f64, f64) = (0.025, 0.1);
const NOSE_LENGTH: (f64, f64) = (2.2, 8.4);
const AFTERBODY_LENGTH: (f64, f64) = (0.3, 5.6);
const TAPER: (f64, f64) = (0.0, 1.0);
const LEADING_EDGE_RADIUS: (f64, f64) = (0.0, 0.015);
const TWIST_DEG: (f64, f64) = (-9.4, 0.0);
const MAX_CAMBER: (f64, f64) = (0.0, 0.0263);
const DESIGN_LIFT: (f64, f64) = (0.0, 0.45);
pub const REYNOLDS_NUMBER: (f64, f64) = (8.0e5, 8.0e6);
/// Number of coefficients B0..B15.
const TERMS: usize = 16;
/// The original's degrees per radian in the twist term.
const DEG_PER_RAD: f64 = 57.29578;

impl RegressionInputs {
    /// The first variable outside the regression's data, if any.
    pub fn outside_data(&self) -> Option<(&'static str, f64)> {
        let checks = [
            ("A", self.aspect_ratio, ASPECT_RATIO),
            ("tan LE sweep", self.tan_leading_edge, TAN_LEADING_EDGE),
            ("t/c", self.thickness_ratio, THICKNESS_RATIO),
            ("l_n", self.nose_length, NOSE_LENGTH),
            ("l_a", self.afterbody_length, AFTERBODY_LENGTH),
            ("taper", self.taper, TAPER),
            ("LER", self.leading_edge_radius, LEADING_EDGE_RADIUS),
            ("twist", self.twist_deg, TWIST_DEG),
            ("YCM", self.max_camber, MAX_CAMBER),
            ("CLD", self.design_lift, DESIGN_LIFT),
        ];
        checks
            .into_iter()
            .find(|(_, v, (lo, hi))| !(*v >= *lo && *v <= *hi))
            .map(|(n, v, _)| (n, v))
    }
}

/// Digital DATCOM's regression of the drag due to lift of a body with a straight wing (no
/// DATCOM figure; the original applies it after DATCOM 4.3.3.1 for TYPE 1 wings):
/// CD_L = B0 + B1/A + B2 A + B3 √tan Λ_LE + B4 t/c + B5 l_n + B6 l_a + B7 λ + B8 λ² +
/// B9 λ³ + B10 TR + B11 r_LE − B12 θ/57.3 + B13 y_c + B14 c_ld + B15 R/10⁶, the coefficients linear
/// in |α| between whole degrees and in Mach between 0.6, 0.7 and 0.8 (those of 0.6 below it).
/// None at an angle beyond 18° (the original prints no drag there) or a Mach number above 0.8
/// (the original's transonic tables, not given). Originals: WBCDL, TABLES, TBSUB.
pub fn regression_drag_due_to_lift(
    i: &RegressionInputs,
    mach: f64,
    alpha_deg: f64,
    warnings: &mut Vec<WingBodyWarning>,
) -> Result<Option<f64>, WingBodyError> {
    let mut b = [0.0; TERMS];
    let mut quiet = Vec::new();
    for (k, bk) in b.iter_mut().enumerate() {
        match figures::read_optional(
            figures::DRAG_REGRESSION,
            &[mach, alpha_deg.abs(), k as f64],
            &mut quiet,
        )? {
            Some(v) => *bk = v,
            None => return Ok(None),
        }
    }
    // Below Mach 0.6 the original takes the 0.6 coefficients as they are: not a departure.
    warnings.extend(quiet.into_iter().filter(|w| match w {
        WingBodyWarning::Chart(c) => c.variable != "mach" || c.value > c.max,
        _ => true,
    }));
    let t = i.taper;
    let cd = b[0]
        + b[1] / i.aspect_ratio
        + b[2] * i.aspect_ratio
        + b[3] * i.tan_leading_edge.sqrt()
        + b[4] * i.thickness_ratio
        + b[5] * i.nose_length
        + b[6] * i.afterbody_length
        + b[7] * t
        + b[8] * t * t
        + b[9] * t * t * t
        + b[10] * i.transition
        + b[11] * i.leading_edge_radius
        - b[12] * i.twist_deg / DEG_PER_RAD
        + b[13] * i.max_camber
        + b[14] * i.design_lift
        + b[15] * i.reynolds_number / 1.0e6;
    Ok(Some(cd).filter(|v| v.is_finite()))
}

/// How the drag due to lift of the combination was taken.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum DragMethod {
    /// Body and wing drag due to lift added (DATCOM 4.3.3.1).
    Components,
    /// The original's regression for straight wings.
    Regression,
}

/// The drag of the combination and its terms.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct WingBodyDrag {
    pub zero_lift: WingBodyZeroLiftDrag,
    pub method: DragMethod,
    /// Drag due to lift of the body alone and of the wing alone, per angle.
    pub body_lift: Vec<Option<f64>>,
    pub wing_lift: Vec<Option<f64>>,
    /// The regression's variables, when the wing is straight.
    pub regression_inputs: Option<RegressionInputs>,
    /// Why the regression was not used, for a straight wing.
    pub regression_not_used: Option<String>,
    /// The regression's drag due to lift per angle (when used).
    pub regression: Vec<Option<f64>>,
    /// Zero-lift drag + the drag due to lift of the method used.
    pub cd: Vec<Option<f64>>,
}
