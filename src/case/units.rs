//! Units at the edge: the deck's system (DIM card) to the one system used inside, and back.
//!
//! Inside the library every quantity is SI: metres, square metres, metres per second, pascals,
//! kelvins, newtons; angles stay in degrees as DATCOM writes them. Decks under DIM FT or DIM IN
//! give pressure in pounds per square foot or inch, temperature in degrees Rankine and weight in
//! pounds; decks under DIM M or DIM CM give newtons per square metre or centimetre, kelvins and
//! newtons (see docs/input-format.md).

use crate::deck::cards::Dim;
use crate::deck::schema::Dimension;

/// Newtons per pound-force (exact by definition of the pound and standard gravity).
pub const NEWTONS_PER_POUND: f64 = 4.448_221_615_260_5;
/// Kelvins per degree Rankine.
pub const KELVIN_PER_RANKINE: f64 = 5.0 / 9.0;

/// SI value of one deck unit of `dimension` under `dim`.
pub fn si_per_unit(dim: Dim, dimension: Dimension) -> f64 {
    let l = dim.metres();
    match dimension {
        Dimension::None => 1.0,
        Dimension::Length => l,
        Dimension::Area => l * l,
        // Reynolds number per length is per foot under FT and IN, per metre under M and CM
        // (routine CONV of the original; see docs/input-format.md).
        Dimension::PerLength => {
            if dim.is_metric() {
                1.0
            } else {
                1.0 / 0.3048
            }
        }
        Dimension::Velocity => l,
        Dimension::Pressure => {
            if dim.is_metric() {
                1.0 / (l * l)
            } else {
                NEWTONS_PER_POUND / (l * l)
            }
        }
        Dimension::Temperature => {
            if dim.is_metric() {
                1.0
            } else {
                KELVIN_PER_RANKINE
            }
        }
        Dimension::Force => {
            if dim.is_metric() {
                1.0
            } else {
                NEWTONS_PER_POUND
            }
        }
        Dimension::Roughness => {
            if dim.is_metric() {
                0.01
            } else {
                0.0254
            }
        }
    }
}

/// Deck units to SI.
pub fn to_si(value: f64, dim: Dim, dimension: Dimension) -> f64 {
    value * si_per_unit(dim, dimension)
}

/// SI to deck units.
pub fn from_si(value: f64, dim: Dim, dimension: Dimension) -> f64 {
    value / si_per_unit(dim, dimension)
}

/// Unit names as the original prints them in its FLIGHT CONDITIONS headers.
pub fn unit_label(dim: Dim, dimension: Dimension) -> &'static str {
    use Dimension as D;
    match (dim, dimension) {
        (_, D::None) => "",
        (Dim::Ft, D::Length) => "FT",
        (Dim::In, D::Length) => "IN",
        (Dim::M, D::Length) => "M",
        (Dim::Cm, D::Length) => "CM",
        (Dim::Ft, D::Area) => "FT**2",
        (Dim::In, D::Area) => "IN**2",
        (Dim::M, D::Area) => "M**2",
        (Dim::Cm, D::Area) => "CM**2",
        (Dim::Ft | Dim::In, D::PerLength) => "1/FT",
        (Dim::M | Dim::Cm, D::PerLength) => "1/M",
        (Dim::Ft, D::Velocity) => "FT/SEC",
        (Dim::In, D::Velocity) => "IN/SEC",
        (Dim::M, D::Velocity) => "M/SEC",
        (Dim::Cm, D::Velocity) => "CM/SEC",
        (Dim::Ft, D::Pressure) => "LB/FT**2",
        (Dim::In, D::Pressure) => "LB/IN**2",
        (Dim::M, D::Pressure) => "N/M**2",
        (Dim::Cm, D::Pressure) => "N/CM**2",
        (Dim::Ft | Dim::In, D::Temperature) => "DEG R",
        (Dim::M | Dim::Cm, D::Temperature) => "DEG K",
        (Dim::Ft | Dim::In, D::Force) => "LB",
        (Dim::M | Dim::Cm, D::Force) => "N",
        (Dim::Ft | Dim::In, D::Roughness) => "IN",
        (Dim::M | Dim::Cm, D::Roughness) => "CM",
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn round_trip_every_dimension() {
        let dims = [Dim::Ft, Dim::In, Dim::M, Dim::Cm];
        let kinds = [
            Dimension::None,
            Dimension::Length,
            Dimension::Area,
            Dimension::PerLength,
            Dimension::Velocity,
            Dimension::Pressure,
            Dimension::Temperature,
            Dimension::Force,
            Dimension::Roughness,
        ];
        for d in dims {
            for k in kinds {
                let x = 123.456;
                let back = from_si(to_si(x, d, k), d, k);
                assert!((back - x).abs() < 1e-12 * x, "{d:?} {k:?}");
            }
        }
    }

    #[test]
    fn sea_level_pressure_in_pounds() {
        // 2116.22 lb/ft² is 101325 Pa (US Standard Atmosphere sea level).
        let pa = to_si(2116.2166, Dim::Ft, Dimension::Pressure);
        assert!((pa - 101_325.0).abs() < 0.05, "{pa}");
    }
}
