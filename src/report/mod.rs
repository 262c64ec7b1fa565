//! Reports: results in the deck's units, as text, JSON or CSV; and reading the original
//! program's listings ([`legacy`]).
//!
//! This is the output edge: SI and per-radian values inside become the deck's units (DIM) and
//! per degree unless DERIV RAD here, and nowhere else.

pub mod auxiliary;
pub mod compare;
pub mod csv;
pub mod for006;
pub mod jsbsim;
pub mod json;
pub mod legacy;
pub mod percent_error;
pub mod plot;
pub mod text;

use crate::case::units::from_si;
use crate::deck::cards::{DerivUnit, Dim};
use crate::deck::schema::Dimension;
use crate::results::{CaseResults, ConditionResults};

/// A flight condition in the deck's units (its fields are the JSON's condition fields).
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct ConditionView {
    pub mach: f64,
    pub altitude: Option<f64>,
    pub velocity: Option<f64>,
    pub pressure: Option<f64>,
    pub temperature: Option<f64>,
    pub reynolds_per_length: f64,
}

/// Converts a condition to the deck's units.
pub fn condition_view(c: &ConditionResults, dim: Dim) -> ConditionView {
    let f = &c.condition;
    ConditionView {
        mach: f.mach,
        altitude: f.altitude.map(|v| from_si(v, dim, Dimension::Length)),
        velocity: f.velocity.map(|v| from_si(v, dim, Dimension::Velocity)),
        pressure: f.pressure.map(|v| from_si(v, dim, Dimension::Pressure)),
        temperature: f
            .temperature
            .map(|v| from_si(v, dim, Dimension::Temperature)),
        reynolds_per_length: from_si(f.reynolds_per_length, dim, Dimension::PerLength),
    }
}

/// Reference dimensions in the deck's units (geometry divided back by SCALE):
/// (area, longitudinal length, lateral length, XCG, ZCG).
pub fn reference_view(c: &CaseResults) -> (Option<f64>, Option<f64>, Option<f64>, f64, f64) {
    let r = c.reference.in_deck_units(c.dim, c.scale);
    (r.area, r.chord, r.span, r.xcg, r.zcg)
}

/// A derivative per radian in the unit the case asks for.
pub fn derivative_view(per_rad: Option<f64>, unit: DerivUnit) -> Option<f64> {
    per_rad.map(|v| match unit {
        DerivUnit::Rad => v,
        DerivUnit::Deg => {
            // π/180 as the product then the quotient (the printed digits have always been
            // those); a value beyond f64::MAX/π, which the product would overflow, by the
            // factor (found by fuzzing the library: a finite derivative printed as inf).
            let product = v * std::f64::consts::PI;
            if product.is_finite() {
                product / 180.0
            } else {
                v * (std::f64::consts::PI / 180.0)
            }
        }
    })
}
