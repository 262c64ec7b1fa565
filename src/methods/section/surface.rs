//! The section method's inputs for one surface of a case: which section, which leading-edge
//! radius and user slopes, which Mach and Reynolds numbers (the original's M50O62 and SECI).

use serde::Serialize;

use std::cell::RefCell;

use crate::case::{Case, FiveDigitReading, Planform, SectionInput, SectionReynolds, SixAReading};
use crate::deck::cards::{AirfoilCard, Surface};
use crate::geometry::section::{
    user_defined, NacaSection, SectionCoordinates, SectionError, Thickness,
};
use crate::geometry::{planform, GeometryError, Span};

use super::{
    design, SectionCondition, SectionOverrides, SectionShape, ShapeError, ThicknessReading,
};

/// Everything [`super::section_characteristics`] needs for one surface.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct SurfaceSection {
    pub surface: Surface,
    /// The designation line (`NACA 0012`, `USER DEFINED`).
    pub title: String,
    pub shape: SectionShape,
    pub overrides: SectionOverrides,
    /// One per flight condition of the case, in the case's order.
    pub conditions: Vec<SectionCondition>,
    /// Mean aerodynamic chord of the exposed planform, m: the Reynolds numbers' length.
    pub chord: f64,
    /// What the coordinates module assumed in reading the section.
    pub warnings: Vec<String>,
}

/// Why a surface's section inputs cannot be formed.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum SurfaceSectionError {
    #[error("{0}")]
    Section(#[from] SectionError),
    #[error("{0}")]
    Shape(#[from] ShapeError),
    #[error("planform: {0}")]
    Planform(#[from] GeometryError),
}

impl SectionShape {
    /// The shape of a coordinate table: stations, mean line and half thickness of its rows,
    /// with its leading-edge radius and maximum thickness; read smoothly, no design values.
    pub fn from_coordinates(c: &SectionCoordinates) -> Result<SectionShape, ShapeError> {
        let mut shape = SectionShape::new(
            c.rows.iter().map(|r| r.x).collect::<Vec<f64>>(),
            c.rows.iter().map(|r| r.mean).collect::<Vec<f64>>(),
            c.rows
                .iter()
                .map(|r| 0.5 * r.thickness)
                .collect::<Vec<f64>>(),
        )?;
        shape.leading_edge_radius = Some(c.leading_edge_radius);
        shape.max_thickness = Some(c.max_thickness);
        Ok(shape)
    }

    /// The shape of a NACA section at the original's stations, with its design values (1- and
    /// 6-series) and, for the sharp supersonic sections, straight lines between stations.
    pub fn from_naca(section: &NacaSection) -> Result<SectionShape, SurfaceSectionError> {
        let mut shape = SectionShape::from_coordinates(&section.coordinates()?)?;
        shape.design = design::design_lift(&section.mean_line);
        shape.thickness_reading = match section.thickness {
            Thickness::DoubleWedge { .. }
            | Thickness::Biconvex { .. }
            | Thickness::Hexagonal { .. } => ThicknessReading::Linear,
            _ => ThicknessReading::Smooth,
        };
        Ok(shape)
    }
}

/// Where a surface's section comes from.
enum Source<'a> {
    User(&'a SectionInput),
    Naca(&'a AirfoilCard),
}

fn planform_of(case: &Case, surface: Surface) -> (Option<&Planform>, Span) {
    match surface {
        Surface::Wing => (case.wing.as_ref(), Span::Both),
        Surface::HorizontalTail => (case.horizontal_tail.as_ref(), Span::Both),
        Surface::VerticalTail => (case.vertical_tail.as_ref(), Span::Single),
        Surface::VentralFin => (case.ventral_fin.as_ref(), Span::Single),
    }
}

/// The title, shape and warnings of the section a NACA card designates.
type NacaShape = (String, SectionShape, Vec<String>);

/// [`NacaShape`] of `card`: a pure function of the card and the readings, asked for by every
/// method that reads the surface's section (a dozen times per case with tails); the last few
/// are remembered per thread, keyed by the whole card and the readings compared exactly.
fn naca_shape(
    card: &AirfoilCard,
    five_digit: FiveDigitReading,
    six_a: SixAReading,
) -> Result<NacaShape, SurfaceSectionError> {
    type Entry = (
        (AirfoilCard, FiveDigitReading, SixAReading),
        Result<NacaShape, SurfaceSectionError>,
    );
    const REMEMBERED: usize = 8;
    thread_local! {
        static LAST: RefCell<Vec<Entry>> = const { RefCell::new(Vec::new()) };
    }
    let hit = LAST.with(|last| {
        last.borrow()
            .iter()
            .find(|((c, f, x), _)| c == card && *f == five_digit && *x == six_a)
            .map(|(_, out)| out.clone())
    });
    if let Some(out) = hit {
        return out;
    }
    let out = NacaSection::from_card_with(card, five_digit, six_a)
        .map_err(SurfaceSectionError::from)
        .and_then(|s| {
            let shape = SectionShape::from_naca(&s)?;
            Ok((s.title, shape, s.warnings))
        });
    LAST.with(|last| {
        let mut last = last.borrow_mut();
        if last.len() == REMEMBERED {
            let _evicted = last.remove(0);
        }
        last.push(((card.clone(), five_digit, six_a), out.clone()));
    });
    out
}

/// The section inputs of `surface` in `case`; `None` when the surface has no planform, or
/// neither user coordinates (xxSCHR TYPEIN) nor a NACA card (the original computes no section
/// for it either).
///
/// - Section: the xxSCHR coordinates when TYPEIN is given, else the surface's (last) NACA card.
/// - Leading-edge radius: the designation's; for user coordinates the surface's own LERI, or
///   the nose circle. (The original takes the vertical tail's LERI for the ventral fin and
///   none for the vertical tail.)
/// - User slopes: the surface's CLALPA(i) (per degree in the deck) for conditions of Mach
///   index i.
/// - Conditions: every flight condition of the case, with the Reynolds number per length of
///   the condition (given RNNUB, or from the atmosphere) times the exposed mean aerodynamic
///   chord. (The original uses RNNUB only, and 10⁶ without it.)
pub fn surface_section(
    case: &Case,
    surface: Surface,
) -> Option<Result<SurfaceSection, SurfaceSectionError>> {
    let (plan, span) = planform_of(case, surface);
    let plan = plan?;
    let input = case.sections.get(surface.name());
    let user = input.filter(|i| i.scalars.contains_key("TYPEIN"));
    let card = case.airfoils.iter().rev().find(|a| a.surface == surface);
    let source = match (user, card) {
        (Some(input), _) => Source::User(input),
        (None, Some(card)) => Source::Naca(card),
        (None, None) => return None,
    };
    Some((|| {
        let (title, mut shape, warnings) = match source {
            Source::User(input) => {
                let c = user_defined(input)?;
                let shape = SectionShape::from_coordinates(&c)?;
                (c.title, shape, c.warnings)
            }
            Source::Naca(card) => naca_shape(card, case.five_digit, case.six_a)?,
        };
        shape.maximum_reading = case.section_maximum;
        let chord = planform(plan, span)?.exposed.mac;
        let user_slopes_per_deg = input
            .and_then(|i| i.per_mach.get("CLALPA"))
            .cloned()
            .unwrap_or_default();
        let overrides = SectionOverrides {
            // A value that is not a number is not given (a case built in code can hold one).
            leading_edge_radius: input
                .and_then(|i| i.scalars.get("LERI"))
                .copied()
                .filter(|r| r.is_finite()),
            lift_curve_slope_per_rad: case
                .conditions
                .iter()
                .map(|c| {
                    user_slopes_per_deg
                        .get(c.mach_index)
                        .filter(|s| s.is_finite())
                        .map(|s| s.to_degrees())
                })
                .collect(),
        };
        let conditions = case
            .conditions
            .iter()
            .map(|c| {
                // Under the original's rule a condition without a given RNNUB has no
                // Reynolds number here, and the section methods take their fixed values.
                let given = case
                    .flight
                    .as_ref()
                    .is_some_and(|f| f.reynolds_per_length.get(c.mach_index).is_some());
                let known = case.section_reynolds == SectionReynolds::Flight || given;
                SectionCondition {
                    mach: c.mach,
                    reynolds_number: known.then_some(c.reynolds_per_length * chord),
                }
            })
            .collect();
        Ok(SurfaceSection {
            surface,
            title,
            shape,
            overrides,
            conditions,
            chord,
            warnings,
        })
    })())
}
