//! Airfoil sections: coordinates from NACA designations or from the xxSCHR namelists, as the
//! original prints them on its `<SURFACE> SECTION DEFINITION` and `USER DEFINED <SURFACE>
//! SECTION` pages (Digital DATCOM routines AIRFOL, COORD1-CORDSP and XYCORD; USAF DATCOM
//! section 4.1.1 takes its section data from these coordinates).
//!
//! - [`naca`]: a NACA card (1-, 4-, modified 4-, 5-, modified 5-, 6-, 6A-series and the
//!   supersonic S-1, S-2, S-3 sections) tabulated at the original's 60 [`stations`].
//! - [`user_defined`]: TYPEIN = 1 (XCORD, YUPPER, YLOWER) or 2 (XCORD, MEAN, THICK) at XCORD.
//! - [`section_for`]: the section of a surface in a case, chosen as the original chooses it.
//!
//! A section is a [`Thickness`] and a [`MeanLine`] combined perpendicular to the mean line
//! ([`CoordinateRow::perpendicular`]); [`NacaSection`] holds both, so later methods can take the
//! mean-line slope or the thickness at any station. The geometry is NACA's where the original
//! departs from it (5-digit camber, reflexed lines, 16-series, 6A mean line and trailing edge);
//! the 6-series thickness is the original's analytic fit. docs/sections.md lists every
//! difference from the original and why.

mod coordinates;
mod designation;
mod error;
mod mean_line;
mod naca;
mod tables;
mod thickness;
mod user;

pub use coordinates::{CoordinateRow, SectionCoordinates};
pub use error::SectionError;
pub use mean_line::{FiveDigitMeanLine, MeanLine};
pub use naca::NacaSection;
pub use tables::stations;
pub use thickness::{JoinedThickness, Thickness};
pub use user::user_defined;

use crate::case::{Case, SectionInput};
use crate::deck::cards::{AirfoilCard, Surface};

/// The coordinate table of a NACA card at the original's 60 stations (AIRFOL, datcom.f lines
/// 68-190). A designation that names no NACA section is refused with the reason.
pub fn naca(card: &AirfoilCard) -> Result<SectionCoordinates, SectionError> {
    NacaSection::from_card(card)?.coordinates()
}

/// Where the section of a surface comes from.
#[derive(Debug, Clone, Copy)]
pub enum SectionSource<'a> {
    /// The xxSCHR namelist's coordinates (it gives TYPEIN).
    User(&'a SectionInput),
    /// The surface's (last) NACA card.
    Naca(&'a AirfoilCard),
}

/// Where the section of `surface` in `case` comes from, as the original chooses it (M50O62,
/// datcom.f lines 21002-21007): the xxSCHR coordinates when the namelist gives TYPEIN, else
/// the surface's NACA card; `None` when the case has neither.
pub fn section_source(case: &Case, surface: Surface) -> Option<SectionSource<'_>> {
    match case.sections.get(surface.name()) {
        Some(input) if input.scalars.contains_key("TYPEIN") => Some(SectionSource::User(input)),
        _ => case
            .airfoils
            .iter()
            .rev()
            .find(|a| a.surface == surface)
            .map(SectionSource::Naca),
    }
}

/// The section of `surface` in `case` as the original chooses it ([`section_source`]); `None`
/// when the case has none.
pub fn section_for(
    case: &Case,
    surface: Surface,
) -> Option<Result<SectionCoordinates, SectionError>> {
    Some(match section_source(case, surface)? {
        SectionSource::User(input) => user_defined(input),
        SectionSource::Naca(card) => NacaSection::from_card_with(card, case.five_digit, case.six_a)
            .and_then(|s| s.coordinates()),
    })
}
