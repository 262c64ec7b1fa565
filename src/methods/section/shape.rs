//! The section geometry the characteristics are computed from, independent of where it comes
//! from (a NACA designation or the xxSCHR coordinates).

use std::ops::Deref;
use std::sync::Arc;

use serde::Serialize;

use super::interpolation::MIN_STATIONS;

/// How the half thickness is read between stations.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Default)]
#[serde(rename_all = "snake_case")]
pub enum ThicknessReading {
    /// A smooth piecewise cubic (ordinary round-nosed sections).
    #[default]
    Smooth,
    /// Straight lines between stations (sections with corners: the supersonic double-wedge,
    /// biconvex and hexagonal families of NACA `S` cards).
    Linear,
}

/// Design values a NACA designation fixes for its mean line (1- and 6-series: the design lift
/// coefficient and the mean line's load parameter `a`). When given, they are the section's
/// ideal angle, ideal lift coefficient and the start of the zero-lift iteration; otherwise
/// these come from thin-airfoil theory on the mean-line ordinates.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct DesignLift {
    /// Ideal (design) lift coefficient.
    pub ideal_cl: f64,
    /// Ideal angle of attack, degrees.
    pub ideal_alpha_deg: f64,
    /// Zero-lift angle of the mean line by thin-airfoil theory, degrees.
    pub zero_lift_alpha_deg: f64,
}

/// Which station gives the section's maximum thickness and maximum camber (and so the
/// positions the maximum-lift method of DATCOM 4.1.1.4 reads).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum MaximumReading {
    /// The greatest ordinate (the first of equal ones): the handbook's definition.
    #[default]
    Greatest,
    /// As the original program (M50O62): the ordinate at the last station where it rose above
    /// the station before. The same for a smooth section; on digitised coordinates with a
    /// flat, bumpy crest it can be a lower local peak further aft. For reproducing old
    /// listings (docs/section-characteristics.md).
    LastRise,
}

/// Values of a section at its stations (reads as a slice). The copies of a shape share
/// them: copying a shape copies no numbers, and comparing two copies compares none.
#[derive(Debug, Clone)]
pub struct StationValues(Arc<[f64]>);

impl Deref for StationValues {
    type Target = [f64];
    fn deref(&self) -> &[f64] {
        &self.0
    }
}

impl StationValues {
    /// The values to change in place (copied first when another shape shares them).
    pub fn values_mut(&mut self) -> &mut [f64] {
        if Arc::get_mut(&mut self.0).is_none() {
            self.0 = self.0.iter().copied().collect();
        }
        Arc::get_mut(&mut self.0).map_or(&mut [], |v| v)
    }
}

impl PartialEq for StationValues {
    fn eq(&self, other: &Self) -> bool {
        Arc::ptr_eq(&self.0, &other.0) || self.0[..] == other.0[..]
    }
}

impl From<Vec<f64>> for StationValues {
    fn from(v: Vec<f64>) -> Self {
        StationValues(v.into())
    }
}

impl Serialize for StationValues {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        self.0[..].serialize(s)
    }
}

/// An airfoil section: ordinates at chordwise stations, as fractions of the chord.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct SectionShape {
    /// Chordwise stations x/c, strictly ascending from 0 to 1.
    pub x: StationValues,
    /// Mean-line ordinates z_c/c at the stations (0 at both ends for a section on its chord).
    pub camber: StationValues,
    /// Half thickness z_t/c at the stations (0 at both ends).
    pub half_thickness: StationValues,
    pub thickness_reading: ThicknessReading,
    /// Leading-edge radius the designation fixes, fraction of chord.
    pub leading_edge_radius: Option<f64>,
    /// Maximum thickness the designation names, fraction of chord.
    pub max_thickness: Option<f64>,
    pub design: Option<DesignLift>,
    /// How the maximum thickness and camber are found.
    pub maximum_reading: MaximumReading,
}

/// Why ordinates do not make a section.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum ShapeError {
    #[error("a section needs at least {min} chordwise stations; {found} given")]
    TooFewStations { found: usize, min: usize },
    #[error("the section has {x} stations but {ordinates} {what} ordinates")]
    Lengths {
        what: &'static str,
        x: usize,
        ordinates: usize,
    },
    #[error("{what} {index} is not a finite number ({value})")]
    NotFinite {
        what: &'static str,
        index: usize,
        value: f64,
    },
    #[error("the stations must increase strictly: x({index}) = {value} does not exceed x({}) = {previous}", index - 1)]
    NotAscending {
        index: usize,
        value: f64,
        previous: f64,
    },
    #[error("the stations must run along the chord from 0 to 1 (or to at least {SHORTEST_TRAILING_EDGE}); they run from {first} to {last}")]
    NotChord { first: f64, last: f64 },
}

/// How far the first and last stations may be from 0 and 1.
const CHORD_END_TOLERANCE: f64 = 1e-6;
/// The last station of a table that stops short of the trailing edge may lie this far forward
/// of it and no further: the original computes any such table, closing the section at its last
/// station, but the thickness method samples the section to 0.99 chord and beyond the last
/// station extrapolates; over more than 5 % of the chord that gives section slopes of hundreds
/// per degree (a 10 % section ending at 0.35). Real decks end at 0.979.
pub const SHORTEST_TRAILING_EDGE: f64 = 0.95;

impl SectionShape {
    /// A section from stations, mean line and half thickness, checked; read smoothly, with no
    /// designation values.
    pub fn new(
        x: impl Into<StationValues>,
        camber: impl Into<StationValues>,
        half_thickness: impl Into<StationValues>,
    ) -> Result<SectionShape, ShapeError> {
        let shape = SectionShape {
            x: x.into(),
            camber: camber.into(),
            half_thickness: half_thickness.into(),
            thickness_reading: ThicknessReading::Smooth,
            leading_edge_radius: None,
            max_thickness: None,
            design: None,
            maximum_reading: MaximumReading::Greatest,
        };
        shape.check()?;
        Ok(shape)
    }

    /// Checks what the method needs: at least four stations, ascending strictly from 0 to 1,
    /// finite ordinates of the same count, and finite designation values.
    pub fn check(&self) -> Result<(), ShapeError> {
        let n = self.x.len();
        if n < MIN_STATIONS {
            return Err(ShapeError::TooFewStations {
                found: n,
                min: MIN_STATIONS,
            });
        }
        for (what, v) in [
            ("mean-line", &self.camber),
            ("thickness", &self.half_thickness),
        ] {
            if v.len() != n {
                return Err(ShapeError::Lengths {
                    what,
                    x: n,
                    ordinates: v.len(),
                });
            }
        }
        for (what, v) in [
            ("station", &self.x),
            ("mean-line ordinate", &self.camber),
            ("half thickness", &self.half_thickness),
        ] {
            if let Some((i, value)) = v.iter().enumerate().find(|(_, v)| !v.is_finite()) {
                return Err(ShapeError::NotFinite {
                    what,
                    index: i + 1,
                    value: *value,
                });
            }
        }
        if let Some(i) = (1..n).find(|&i| self.x[i] <= self.x[i - 1]) {
            return Err(ShapeError::NotAscending {
                index: i + 1,
                value: self.x[i],
                previous: self.x[i - 1],
            });
        }
        let (first, last) = (self.x[0], self.x[n - 1]);
        // A table may stop short of the trailing edge: its last station is the trailing edge
        // (the original's XYCORD; geometry::section::user_defined warns).
        if first.abs() > CHORD_END_TOLERANCE
            || last - 1.0 > CHORD_END_TOLERANCE
            || last < SHORTEST_TRAILING_EDGE
        {
            return Err(ShapeError::NotChord { first, last });
        }
        let design = self.design.map_or(vec![], |d| {
            vec![d.ideal_cl, d.ideal_alpha_deg, d.zero_lift_alpha_deg]
        });
        for (what, v) in [
            ("leading-edge radius", self.leading_edge_radius),
            ("maximum thickness", self.max_thickness),
        ]
        .into_iter()
        .chain(design.into_iter().map(|d| ("design value", Some(d))))
        {
            if let Some(value) = v.filter(|v| !v.is_finite()) {
                return Err(ShapeError::NotFinite {
                    what,
                    index: 1,
                    value,
                });
            }
        }
        Ok(())
    }
}
