//! Body alone: CYβ, Cnβ, Clβ as the original's body-alone page gives them.

use super::{finite, Lateral, LateralWarning};
use crate::case::Case;
use crate::methods::body::BodyAlone;

/// DATCOM 5.2.1.1 as the original codes it for the body-alone page (M04O04, M06O06): by
/// slender-body symmetry the side force in sideslip is the lift in incidence with the sign
/// turned, and the yawing moment the pitching moment on the lateral reference length:
///
/// CYβ = −CLα,  Cnβ = −(c̄/b)·CMα,  Clβ = 0,
///
/// at every angle of the page, with its CLα and CMα (the analytic slopes at the first angle,
/// the slopes of the CL(α) and CM(α) curves at the others). c̄ is the body page's reference
/// length, b the lateral reference length ($OPTINS BLREF, else the wing span 2·SSPN). The
/// yawing-moment method of DATCOM 5.2.3.1 (figure 5.2.3.1-8) is not what the original prints
/// here. Per radian; none where the page's slope is none (or, for Cnβ, without b).
pub fn body_lateral(body: &BodyAlone, case: &Case) -> Lateral {
    let mut warnings = Vec::new();
    let span = lateral_reference_span(case);
    if span.is_none() {
        warnings.push(LateralWarning::NoReferenceSpan);
    }
    let ratio = span.map(|b| body.reference.length / b);
    let cyb = body
        .cla_per_rad
        .iter()
        .map(|s| s.and_then(|v| finite(-v)))
        .collect();
    let cnb = body
        .cma_per_rad
        .iter()
        .map(|s| match (s, ratio) {
            (Some(v), Some(r)) => finite(-r * v),
            _ => None,
        })
        .collect();
    Lateral {
        alpha_deg: body.alpha_deg.clone(),
        cyb,
        cnb,
        clb: vec![Some(0.0); body.alpha_deg.len()],
        wing_terms: None,
        wing_body_terms: None,
        fin_terms: None,
        twin_panel_terms: None,
        warnings,
    }
}

/// $OPTINS BLREF, else the wing's span 2·SSPN; none when neither is a positive number.
pub(super) fn lateral_reference_span(case: &Case) -> Option<f64> {
    case.reference
        .span
        .or_else(|| case.wing.as_ref().and_then(|w| w.sspn).map(|s| 2.0 * s))
        .filter(|b| b.is_finite() && *b > 0.0)
}
