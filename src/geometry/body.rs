//! Body geometry (DATCOM section 2.3 and 4.2.1: bodies of revolution and arbitrary
//! cross-section described by stations X with areas S, perimeters P and radii R; the
//! original's INPUTB completion and routines BODYRT, BODYJM, EQSPCE, TRAPZ).
//!
//! A body is given by its radii (circular, or elliptical with `ELLIP` = height/width), by its
//! areas, or by radii, areas and perimeters all three (any other shape). The rest is completed
//! from what is given: S = π·R²·E, P = 2π·R·√((E² + 1)/2) and the equivalent radius √(S/π).

use serde::Serialize;

use crate::case::Body;
use crate::numeric::trapezoid;

/// Stations the wetted area is integrated over: the body length divided equally, as the
/// original resamples it (EQSPCE).
const WETTED_AREA_STATIONS: usize = 20;
/// The base area used for base drag is at least this fraction of the largest cross-section
/// (the original's boat-tail adjustment in BODYRT).
const MIN_BASE_AREA_FRACTION: f64 = 0.3;

/// Why a body has no geometry.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum BodyError {
    #[error("the body is not adequately defined: give X with R, or X with S, or X with R, S and P (ELLIP for an elliptical body)")]
    NotDefined,
    #[error("the body needs at least 2 stations; {0} given")]
    TooFewStations(usize),
    #[error("{0} has fewer values than X")]
    Short(&'static str),
    /// A value a deck's checks refuse, met in a case built in code.
    #[error("{what}({index}) = {value} (SI): must be finite{rule}")]
    Invalid {
        what: &'static str,
        index: usize,
        value: f64,
        rule: &'static str,
    },
}

/// What a case built in code can hold and a deck's checks refuse: a station, radius, area or
/// perimeter that is not a number, or a negative radius, area or perimeter.
fn check_values(b: &Body) -> Result<(), BodyError> {
    let arrays: [(&'static str, &[f64], &'static str); 6] = [
        ("X", &b.x, ""),
        ("R", &b.r, " and not negative"),
        ("S", &b.s, " and not negative"),
        ("P", &b.p, " and not negative"),
        ("ZU", &b.zu, ""),
        ("ZL", &b.zl, ""),
    ];
    for (what, values, rule) in arrays {
        let bad = |v: f64| !v.is_finite() || (!rule.is_empty() && v < 0.0);
        if let Some(index) = values.iter().position(|&v| bad(v)) {
            return Err(BodyError::Invalid {
                what,
                index: index + 1,
                value: values[index],
                rule,
            });
        }
    }
    Ok(())
}

/// A body's stations completed and its derived quantities, SI.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct BodyGeometry {
    /// Stations along the deck's x axis, m: the nose is the first, not necessarily at 0.
    pub x: Vec<f64>,
    /// Cross-section areas, m².
    pub s: Vec<f64>,
    /// Perimeters, m.
    pub p: Vec<f64>,
    /// Equivalent radii √(S/π) (the radius for a circular body), m.
    pub r: Vec<f64>,
    /// Last station minus first, m.
    pub length: f64,
    /// Largest cross-section area and its station, m², m.
    pub max_area: f64,
    pub x_max_area: f64,
    /// Diameter of the circle of the largest area, m.
    pub max_diameter: f64,
    /// Length over maximum diameter.
    pub fineness: f64,
    /// Base area as the subsonic methods use it (at least 0.3 of the largest area), m².
    pub base_area: f64,
    /// Wetted area: the perimeter integrated along the body (trapezoids over 20 equal
    /// intervals), m².
    pub wetted_area: f64,
    /// Volume: frustums between stations on the equivalent radii, m³.
    pub volume: f64,
    /// Planform area: twice the integral of the equivalent radius, m².
    pub planform_area: f64,
}

impl BodyGeometry {
    /// x of the nose (the first station), m: the origin of the stations the methods measure
    /// from the nose, as the original does internally.
    pub fn nose(&self) -> f64 {
        self.x.first().copied().unwrap_or(0.0)
    }
}

/// `f` at `at`, linear between stations and clamped beyond the ends.
fn interpolate(x: &[f64], f: &[f64], at: f64) -> f64 {
    let n = x.len();
    if at <= x[0] {
        return f[0];
    }
    if at >= x[n - 1] {
        return f[n - 1];
    }
    let k = x.windows(2).position(|w| at <= w[1]).unwrap_or(n - 2);
    let t = (at - x[k]) / (x[k + 1] - x[k]);
    f[k] + t * (f[k + 1] - f[k])
}

/// Completes S, P and R from what the deck gives and derives the body's quantities.
pub fn body(b: &Body) -> Result<BodyGeometry, BodyError> {
    let n = b.x.len();
    if n < 2 {
        return Err(BodyError::TooFewStations(n));
    }
    check_values(b)?;
    let e = b.ellip.filter(|e| *e > 0.0).unwrap_or(1.0);
    let take = |v: &[f64], name: &'static str| -> Result<Vec<f64>, BodyError> {
        if v.len() < n {
            return Err(BodyError::Short(name));
        }
        Ok(v[..n].to_vec())
    };
    let pi = std::f64::consts::PI;
    let (s, p, r): (Vec<f64>, Vec<f64>, Vec<f64>) =
        match (!b.r.is_empty(), !b.s.is_empty(), !b.p.is_empty()) {
            (true, false, false) => {
                let r = take(&b.r, "R")?;
                let s = r.iter().map(|r| pi * r * r * e).collect();
                let p = r
                    .iter()
                    .map(|r| 2.0 * pi * r * ((e * e + 1.0) / 2.0).sqrt())
                    .collect();
                (s, p, r.iter().map(|r| r * e.sqrt()).collect())
            }
            (false, true, false) => {
                let s = take(&b.s, "S")?;
                let r: Vec<f64> = s.iter().map(|s| (s / pi).sqrt()).collect();
                let p = s
                    .iter()
                    .map(|s| 2.0 * pi * ((s / e) * (e * e + 1.0) / 2.0 / pi).sqrt())
                    .collect();
                (s, p, r)
            }
            (true, true, true) => {
                let r = take(&b.r, "R")?;
                (
                    take(&b.s, "S")?,
                    take(&b.p, "P")?,
                    r.iter().map(|r| r * e.sqrt()).collect(),
                )
            }
            _ => return Err(BodyError::NotDefined),
        };
    let x = b.x[..n].to_vec();
    let length = x[n - 1] - x[0];
    // The first largest area, scanning from the nose.
    let (imax, max_area) =
        s.iter()
            .copied()
            .enumerate()
            .fold(
                (0, f64::NEG_INFINITY),
                |(i, m), (k, v)| if v > m { (k, v) } else { (i, m) },
            );
    let max_diameter = (4.0 * max_area / pi).sqrt();
    let base_area = if s[n - 1] <= MIN_BASE_AREA_FRACTION * max_area {
        MIN_BASE_AREA_FRACTION * max_area
    } else {
        s[n - 1]
    };
    let step = length / (WETTED_AREA_STATIONS - 1) as f64;
    let xe: Vec<f64> = (0..WETTED_AREA_STATIONS)
        .map(|i| x[0] + i as f64 * step)
        .collect();
    let pe: Vec<f64> = xe.iter().map(|at| interpolate(&x, &p, *at)).collect();
    let wetted_area = trapezoid(&xe, &pe);
    let volume = x
        .windows(2)
        .zip(r.windows(2))
        .map(|(x, r)| pi / 3.0 * (x[1] - x[0]) * (r[0] * r[0] + r[1] * r[1] + r[0] * r[1]))
        .sum();
    let planform_area = 2.0 * trapezoid(&x, &r);
    Ok(BodyGeometry {
        length,
        max_area,
        x_max_area: x[imax],
        max_diameter,
        fineness: if max_diameter > 0.0 {
            length / max_diameter
        } else {
            0.0
        },
        base_area,
        wetted_area,
        volume,
        planform_area,
        x,
        s,
        p,
        r,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Closed-form results of a cylinder agree to rounding.
    const ROUNDING: f64 = 1e-12;

    #[test]
    fn cylinder() {
        let b = Body {
            x: vec![0.0, 1.0, 2.0, 4.0],
            r: vec![0.5; 4],
            ..Body::default()
        };
        let g = body(&b).unwrap();
        let pi = std::f64::consts::PI;
        assert!((g.wetted_area - pi * 1.0 * 4.0).abs() < ROUNDING);
        assert!((g.volume - pi * 0.25 * 4.0).abs() < ROUNDING);
        assert!((g.planform_area - 4.0).abs() < ROUNDING);
        assert!((g.fineness - 4.0).abs() < ROUNDING);
        assert!((g.base_area - pi * 0.25).abs() < ROUNDING);
    }

    #[test]
    fn pointed_tail_gets_the_boat_tail_base_area() {
        let b = Body {
            x: vec![0.0, 1.0, 2.0],
            r: vec![0.0, 1.0, 0.0],
            ..Body::default()
        };
        let g = body(&b).unwrap();
        assert!((g.base_area - 0.3 * std::f64::consts::PI).abs() < ROUNDING);
    }

    #[test]
    fn areas_only_and_not_defined() {
        let b = Body {
            x: vec![0.0, 1.0],
            s: vec![std::f64::consts::PI, std::f64::consts::PI],
            ..Body::default()
        };
        let g = body(&b).unwrap();
        assert!((g.r[0] - 1.0).abs() < ROUNDING);
        assert!((g.p[0] - 2.0 * std::f64::consts::PI).abs() < ROUNDING);
        let b = Body {
            x: vec![0.0, 1.0],
            s: vec![1.0, 1.0],
            p: vec![1.0, 1.0],
            ..Body::default()
        };
        assert_eq!(body(&b), Err(BodyError::NotDefined));
    }
}
