//! NACA sections from their designations: thickness distribution and mean line by series, and
//! the coordinate table at the original's 60 stations (AIRFOL and COORD1-CORDSP, datcom.f lines
//! 68-190 and 5830-6548).

use super::designation::{self, Designation, Modification};
use super::mean_line::{FiveDigitMeanLine, MeanLine, SIX_A_LOAD_EXTENT};
use super::tables::{self, lookup};
use super::thickness::{JoinedThickness, Thickness};
use super::{CoordinateRow, SectionCoordinates, SectionError};
use crate::deck::cards::{AirfoilCard, NacaSeries};

/// Design lift coefficient per unit of the first digit of a 5-digit designation (it is 2/3 of
/// the design lift coefficient in tenths: NACA Report 610; Abbott & von Doenhoff, chapter 6).
const FIVE_DIGIT_LIFT_STEP: f64 = 0.15;
/// Design lift coefficient for which NACA tabulates the 5-digit k1.
const FIVE_DIGIT_TABLE_CL: f64 = 0.3;
/// The 16-series thickness is the modified 4-digit thickness with leading-edge index 4 and the
/// maximum at mid chord (Abbott & von Doenhoff, chapter 6; NACA Report 763).
const SIXTEEN_SERIES_LE_INDEX: f64 = 4.0;
const SIXTEEN_SERIES_MAX_X: f64 = 0.5;
/// The 6A thickness is straight from here to the trailing edge (NACA Report 903; COORD6 line
/// 6163 makes the surfaces straight from the first station with x_u >= 0.80).
const SIX_A_STRAIGHT_FROM: f64 = 0.80;
/// Thickness at which the 6-series trailing-edge factor is r0 (COORD6 lines 6084-6101).
const SIX_SERIES_R0_THICKNESS: f64 = 0.06;

/// A NACA section: the designation lines the original prints, and the thickness distribution
/// and mean line that make the section.
#[derive(Debug, Clone, PartialEq)]
pub struct NacaSection {
    pub title: String,
    pub subtitle: Option<String>,
    pub thickness: Thickness,
    pub mean_line: MeanLine,
    /// What was read differently from NACA's definition, and why.
    pub warnings: Vec<String>,
}

impl NacaSection {
    /// The section of a NACA card.
    pub fn from_card(card: &AirfoilCard) -> Result<Self, SectionError> {
        Self::parse(card.series, &card.designation)
    }

    /// The section of a NACA card with 5-digit designations read by `reading` (other series
    /// are the same either way).
    pub fn from_card_read(
        card: &AirfoilCard,
        reading: crate::case::FiveDigitReading,
    ) -> Result<Self, SectionError> {
        let mut s = Self::from_card(card)?;
        if reading == crate::case::FiveDigitReading::Original {
            if let designation::Designation::FiveDigit { lift, position, .. } =
                designation::parse(card.series, &card.designation)?
            {
                s.mean_line = original_five_digit_mean_line(lift, position);
                s.warnings.push(format!(
                    "NACA {}: 5-digit mean line read as the original program reads it ({lift} % camber at {} % chord), not NACA's (docs/sections.md)",
                    card.designation,
                    5 * position
                ));
            }
        }
        Ok(s)
    }

    /// The section of a NACA card with 5-digit and 6A designations read by `five_digit` and
    /// `six_a` (other series are the same either way).
    pub fn from_card_with(
        card: &AirfoilCard,
        five_digit: crate::case::FiveDigitReading,
        six_a: crate::case::SixAReading,
    ) -> Result<Self, SectionError> {
        let mut s = Self::from_card_read(card, five_digit)?;
        if six_a == crate::case::SixAReading::Original {
            if let designation::Designation::SixSeries {
                six_a: true,
                lift,
                load_extent,
                ..
            } = designation::parse(card.series, &card.designation)?
            {
                if let Thickness::Joined(j) = &mut s.thickness {
                    j.straight_from = None;
                }
                if lift > 0 {
                    let a = load_extent.unwrap_or(1.0);
                    s.mean_line = MeanLine::Uniform {
                        design_cl: f64::from(lift) / 10.0,
                        a,
                    };
                }
                s.warnings.push(format!(
                    "NACA {}: 6A section read as the original program reads it (thickness not straightened aft of 0.8 chord; the plain a = {} mean line), not NACA's (docs/sections.md)",
                    card.designation,
                    load_extent.unwrap_or(1.0)
                ));
            }
        }
        Ok(s)
    }

    /// The section of `designation` in `series` (the text after the series on the card).
    pub fn parse(series: NacaSeries, designation: &str) -> Result<Self, SectionError> {
        let d = designation::parse(series, designation)?;
        let undefined =
            |what: &'static str, found: String, accepted: &'static str| SectionError::Undefined {
                series: designation::series_name(series),
                designation: designation.to_string(),
                what,
                found,
                accepted,
            };
        let mut warnings = Vec::new();
        let (thickness, mean_line) = geometry(&d, &undefined, &mut warnings)?;
        Ok(NacaSection {
            title: d.title(),
            subtitle: d.subtitle(),
            thickness,
            mean_line,
            warnings,
        })
    }

    /// The row at station `x`: the leading-edge point at x <= 0, the trailing-edge point at
    /// x >= 1 (the original closes every section there, whatever the thickness equation gives
    /// at x = 1), the perpendicular construction between.
    pub fn row(&self, x: f64) -> CoordinateRow {
        if x <= 0.0 {
            CoordinateRow::leading_edge(x)
        } else if x >= 1.0 {
            CoordinateRow::trailing_edge(x)
        } else {
            CoordinateRow::perpendicular(
                x,
                self.mean_line.camber(x),
                self.mean_line.slope(x),
                self.thickness.half(x),
            )
        }
    }

    /// The coordinate table at `stations`.
    pub fn coordinates_at(&self, stations: &[f64]) -> SectionCoordinates {
        SectionCoordinates {
            title: self.title.clone(),
            subtitle: self.subtitle.clone(),
            rows: stations.iter().map(|&x| self.row(x)).collect(),
            max_thickness: self.thickness.ratio(),
            max_thickness_x: self.thickness.max_thickness_x(),
            leading_edge_radius: self.thickness.leading_edge_radius(),
            warnings: self.warnings.clone(),
        }
    }

    /// The coordinate table at the original's 60 stations ([`super::stations`]).
    ///
    /// A pure function of the section, asked for several times per case (the section page, the
    /// section characteristics, the surfaces' methods): the last few tables are remembered per
    /// thread, keyed by the whole section compared exactly.
    pub fn coordinates(&self) -> Result<SectionCoordinates, SectionError> {
        const REMEMBERED: usize = 8;
        thread_local! {
            static LAST: std::cell::RefCell<Vec<(NacaSection, SectionCoordinates)>> =
                const { std::cell::RefCell::new(Vec::new()) };
        }
        if let Some(hit) = LAST.with(|l| {
            l.borrow()
                .iter()
                .find(|(s, _)| s == self)
                .map(|(_, c)| c.clone())
        }) {
            return Ok(hit);
        }
        let table = self.coordinates_at(tables::stations()?);
        LAST.with(|l| {
            let mut l = l.borrow_mut();
            if l.len() == REMEMBERED {
                l.remove(0);
            }
            l.push((self.clone(), table.clone()));
        });
        Ok(table)
    }
}

type Undefined<'a> = dyn Fn(&'static str, String, &'static str) -> SectionError + 'a;

/// Thickness distribution and mean line of a designation.
fn geometry(
    d: &Designation,
    undefined: &Undefined,
    warnings: &mut Vec<String>,
) -> Result<(Thickness, MeanLine), SectionError> {
    match *d {
        Designation::FourDigit {
            camber,
            position,
            thickness,
            modification,
        } => {
            let t = thickness_ratio(thickness, undefined)?;
            let mean_line = four_digit_mean_line(camber, position, undefined)?;
            Ok((four_digit_thickness(t, modification, undefined)?, mean_line))
        }
        Designation::FiveDigit {
            lift,
            position,
            reflex,
            thickness,
            modification,
        } => {
            let t = thickness_ratio(thickness, undefined)?;
            let mean_line = five_digit_mean_line(lift, position, reflex, undefined, warnings)?;
            Ok((four_digit_thickness(t, modification, undefined)?, mean_line))
        }
        Designation::OneSeries {
            series,
            lift,
            thickness,
        } => {
            if series != 6 {
                return Err(undefined(
                    "series",
                    format!("1{series}"),
                    "only the 16-series: it is the one 1-series family NACA tabulates (Abbott & von Doenhoff, chapter 6)",
                ));
            }
            let t = thickness_ratio(thickness, undefined)?;
            let d1 = modified_d1(SIXTEEN_SERIES_MAX_X, undefined)?;
            let thickness = JoinedThickness::modified_four_digit(
                t,
                SIXTEEN_SERIES_LE_INDEX,
                SIXTEEN_SERIES_MAX_X,
                d1,
            );
            Ok((Thickness::Joined(thickness), uniform_line(lift, 1.0)))
        }
        Designation::SixSeries {
            series,
            six_a,
            lift,
            thickness,
            load_extent,
            ..
        } => {
            let t = thickness_ratio(thickness, undefined)?;
            let thickness = six_series_thickness(series, six_a, t, undefined)?;
            let mean_line = six_series_mean_line(six_a, lift, load_extent, undefined)?;
            Ok((Thickness::Joined(thickness), mean_line))
        }
        Designation::Supersonic {
            kind,
            ridge,
            thickness,
            flat,
        } => Ok((
            supersonic_thickness(
                kind,
                ridge / 100.0,
                thickness / 100.0,
                flat / 100.0,
                undefined,
            )?,
            MeanLine::Symmetric,
        )),
    }
}

/// The last two digits as a thickness ratio; a section needs some thickness.
fn thickness_ratio(percent: u8, undefined: &Undefined) -> Result<f64, SectionError> {
    if percent == 0 {
        return Err(undefined(
            "thickness",
            "00".into(),
            "the last two digits give the thickness in percent of chord, 01 to 99",
        ));
    }
    Ok(f64::from(percent) / 100.0)
}

/// 4-digit thickness, or the modified 4-digit thickness of the digits after the dash (NACA
/// Report 492; CORD4M and CORD5M).
fn four_digit_thickness(
    t: f64,
    modification: Option<Modification>,
    undefined: &Undefined,
) -> Result<Thickness, SectionError> {
    let Some(m) = modification else {
        return Ok(Thickness::FourDigit { t });
    };
    let max_x = f64::from(m.max_thickness) / 10.0;
    let d1 = modified_d1(max_x, undefined)?;
    Ok(Thickness::Joined(JoinedThickness::modified_four_digit(
        t,
        f64::from(m.le_index),
        max_x,
        d1,
    )))
}

/// Trailing-edge slope over t of the modified thickness with its maximum at `max_x` (chart
/// `airfoil-modified-4digit-d1`).
fn modified_d1(max_x: f64, undefined: &Undefined) -> Result<f64, SectionError> {
    lookup(tables::MODIFIED_D1, &[max_x])?.ok_or_else(|| {
        undefined(
            "position of maximum thickness (second digit after the dash)",
            format!("{}", (max_x * 10.0).round()),
            "NACA defines the modified thickness for 2 to 6 (20 to 60 percent chord; NACA Report 492)",
        )
    })
}

/// NACA 4-digit mean line: camber `camber` percent at `position` tenths of chord.
fn four_digit_mean_line(
    camber: u8,
    position: u8,
    undefined: &Undefined,
) -> Result<MeanLine, SectionError> {
    if camber == 0 {
        return Ok(MeanLine::Symmetric);
    }
    if position == 0 {
        return Err(undefined(
            "position of maximum camber (second digit)",
            "0".into(),
            "a cambered section (first digit not 0) needs its maximum camber at 1 to 9 tenths of chord",
        ));
    }
    Ok(MeanLine::FourDigit {
        max_camber: f64::from(camber) / 100.0,
        position: f64::from(position) / 10.0,
    })
}

/// NACA 5-digit mean line (NACA Reports 537 and 610): design lift coefficient 0.15 `lift`,
/// maximum camber at `position` / 20, reflexed when `reflex` is 1; m and k1 as NACA tabulates
/// them.
fn five_digit_mean_line(
    lift: u8,
    position: u8,
    reflex: u8,
    undefined: &Undefined,
    warnings: &mut Vec<String>,
) -> Result<MeanLine, SectionError> {
    // NACA's third digit is 0 (standard line) or 1 (reflexed). Real decks write others
    // (`NACA W 5 65415`, probably meaning the 6-series 65-415); the original reads any of them
    // as the standard line, and so do we, saying so.
    let reflex = if reflex > 1 {
        warnings.push(format!(
            "third digit {reflex} of a 5-digit designation is not NACA's (0 standard, 1 reflexed): read as the standard mean line, as the original does (was a 6-series section, NACA-W-6-..., meant?)"
        ));
        0
    } else {
        reflex
    };
    if lift == 0 {
        return Ok(MeanLine::Symmetric);
    }
    let p = f64::from(position) / 20.0;
    let args = [f64::from(reflex), p];
    let (Some(m), Some(k1)) = (
        lookup(tables::FIVE_DIGIT_M, &args)?,
        lookup(tables::FIVE_DIGIT_K1, &args)?,
    ) else {
        return Err(undefined(
            "position of maximum camber (second digit)",
            position.to_string(),
            "NACA defines 1 to 5 (5 to 25 percent chord), 2 to 5 for a reflexed mean line",
        ));
    };
    let design_cl = FIVE_DIGIT_LIFT_STEP * f64::from(lift);
    let k2_over_k1 = if reflex == 1 {
        (3.0 * (m - p).powi(2) - m.powi(3)) / (1.0 - m).powi(3)
    } else {
        0.0
    };
    Ok(MeanLine::FiveDigit(FiveDigitMeanLine {
        m,
        k1: k1 * design_cl / FIVE_DIGIT_TABLE_CL,
        k2_over_k1,
    }))
}

/// The original program's reading of a 5-digit mean line (COORD5, CORD5M; docs/sections.md,
/// difference 1): maximum camber `camber_digit` percent at p = `position`/20, the standard line
/// (no reflex) whatever the third digit; m is the root of p = m (1 − √(m/3)) (the 5-digit
/// line's definition: zero slope at p) and k1 = 6 c / (p³ − 3 m p² + m² (3 − m) p), which
/// makes the camber at p equal c.
pub fn original_five_digit_mean_line(camber_digit: u8, position: u8) -> MeanLine {
    if camber_digit == 0 || position == 0 {
        return MeanLine::Symmetric;
    }
    let (camber, p) = (f64::from(camber_digit) / 100.0, f64::from(position) / 20.0);
    // p(m) = m (1 − √(m/3)) increases on (0, 4/3): bisection from p to 4/3.
    let (mut lo, mut hi) = (p, 4.0 / 3.0);
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if mid * (1.0 - (mid / 3.0).sqrt()) < p {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    let m = 0.5 * (lo + hi);
    let k1 = 6.0 * camber / (p.powi(3) - 3.0 * m * p * p + m * m * (3.0 - m) * p);
    MeanLine::FiveDigit(FiveDigitMeanLine {
        m,
        k1,
        k2_over_k1: 0.0,
    })
}

/// The uniform-load mean line of extent `a` for a design lift coefficient of `lift` tenths.
fn uniform_line(lift: u8, a: f64) -> MeanLine {
    if lift == 0 {
        MeanLine::Symmetric
    } else {
        MeanLine::Uniform {
            design_cl: f64::from(lift) / 10.0,
            a,
        }
    }
}

/// DATCOM's fit of the 6- and 6A-series thickness (COORD6, datcom.f lines 6077-6135; charts
/// `airfoil-6series-*`, `airfoil-6a-d1`), straight aft of x = 0.8 for a 6A section.
fn six_series_thickness(
    series: u8,
    six_a: bool,
    t: f64,
    undefined: &Undefined,
) -> Result<JoinedThickness, SectionError> {
    let s = [f64::from(series)];
    let not_six = || {
        undefined(
            "series",
            format!("6{series}{}", if six_a { "A" } else { "" }),
            "NACA defines the 63- to 67-series, and the 63A- to 65A-series",
        )
    };
    let zt = lookup(tables::SIX_ZT, &s)?.ok_or_else(not_six)?;
    if six_a {
        let d1 = lookup(tables::SIX_A_D1, &s)?.ok_or_else(not_six)?;
        Ok(JoinedThickness::six_series_fit(t, zt, d1 * t).straight_from(SIX_A_STRAIGHT_FROM))
    } else {
        let (Some(sm), Some(r0)) = (lookup(tables::SIX_SM, &s)?, lookup(tables::SIX_R0, &s)?)
        else {
            return Err(not_six());
        };
        let d1 = (sm * (t - SIX_SERIES_R0_THICKNESS) + r0) * t;
        Ok(JoinedThickness::six_series_fit(t, zt, d1))
    }
}

/// The 6-series mean line: a = 1 unless `A=` says otherwise; the a = 0.8 (modified) line for a
/// 6A section, whose designation implies it (NACA Report 903), unless `A=` gives another a.
fn six_series_mean_line(
    six_a: bool,
    lift: u8,
    load_extent: Option<f64>,
    undefined: &Undefined,
) -> Result<MeanLine, SectionError> {
    if let Some(a) = load_extent.filter(|a| !(0.0..=1.0).contains(a)) {
        return Err(undefined(
            "mean-line load extent A=",
            a.to_string(),
            "it is a fraction of chord from 0 to 1",
        ));
    }
    if lift == 0 {
        return Ok(MeanLine::Symmetric);
    }
    let design_cl = f64::from(lift) / 10.0;
    Ok(match (six_a, load_extent) {
        (true, None) => MeanLine::SixAModified { design_cl },
        (true, Some(a)) if a == SIX_A_LOAD_EXTENT => MeanLine::SixAModified { design_cl },
        (_, a) => MeanLine::Uniform {
            design_cl,
            a: a.unwrap_or(1.0),
        },
    })
}

/// The supersonic sections of CORDSP (datcom.f lines 6418-6548), lengths as fractions of chord.
fn supersonic_thickness(
    kind: u8,
    ridge: f64,
    t: f64,
    flat: f64,
    undefined: &Undefined,
) -> Result<Thickness, SectionError> {
    if !(t > 0.0 && t < 1.0) {
        return Err(undefined(
            "thickness",
            format!("{:.1}", 100.0 * t),
            "the third group is the thickness in percent of chord, above 0 and below 100",
        ));
    }
    // Only the hexagon has a flat; the original ignores a fourth group otherwise.
    let flat = if kind == 3 { flat } else { 0.0 };
    match kind {
        1 | 3 if !(ridge > 0.0 && ridge + flat < 1.0) => Err(undefined(
            "ridge position and flat",
            format!("{:.1} and {:.1}", 100.0 * ridge, 100.0 * flat),
            "the ridge lies behind the leading edge and the ridge plus the flat ahead of the trailing edge",
        )),
        1 => Ok(Thickness::DoubleWedge { t, ridge }),
        2 => Ok(Thickness::Biconvex { t }),
        3 => Ok(Thickness::Hexagonal { t, ridge, flat }),
        _ => Err(undefined(
            "type",
            kind.to_string(),
            "1 (double wedge), 2 (biconvex) or 3 (hexagon)",
        )),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn section(series: NacaSeries, text: &str) -> NacaSection {
        NacaSection::parse(series, text).unwrap()
    }

    /// The original's reading of a 230 line: 2 % camber (the first digit) at p = 0.15 with
    /// zero slope there, against NACA's 1.84 %; the reading changes 5-digit cards only.
    #[test]
    fn the_originals_five_digit_reading_puts_the_first_digit_as_percent_camber_at_p() {
        let line = original_five_digit_mean_line(2, 3);
        assert!(
            (line.camber(0.15) - 0.02).abs() < 1e-9,
            "{}",
            line.camber(0.15)
        );
        assert!(line.slope(0.15).abs() < 1e-9);
        let naca = section(NacaSeries::Five, "23012").mean_line;
        assert!(
            (naca.camber(0.15) - 0.0184).abs() < 2e-4,
            "{}",
            naca.camber(0.15)
        );
        let card = |series, designation: &str| AirfoilCard {
            surface: crate::deck::cards::Surface::Wing,
            series,
            designation: designation.to_string(),
            line: 1,
        };
        let read = |c: &AirfoilCard| {
            NacaSection::from_card_read(c, crate::case::FiveDigitReading::Original).unwrap()
        };
        assert_eq!(read(&card(NacaSeries::Five, "23012")).mean_line, line);
        let four = card(NacaSeries::Four, "2412");
        assert_eq!(read(&four), NacaSection::from_card(&four).unwrap());
    }

    /// The original's 6A reading (for005's 64A204 A=0.8): the plain a = 0.8 line for
    /// c_li = 0.2 and the thickness left curved aft of 0.8; NACA's: the modified line and the
    /// straight thickness. Other 6-series sections read the same either way.
    #[test]
    fn the_originals_six_a_reading_keeps_the_plain_line_and_the_curved_thickness() {
        use crate::case::{FiveDigitReading, SixAReading};
        let card = |designation: &str| AirfoilCard {
            surface: crate::deck::cards::Surface::Wing,
            series: NacaSeries::Six,
            designation: designation.to_string(),
            line: 1,
        };
        let read =
            |c: &AirfoilCard, r| NacaSection::from_card_with(c, FiveDigitReading::Naca, r).unwrap();
        let six_a = card("64A204 A=0.8");
        let naca = read(&six_a, SixAReading::Naca);
        let original = read(&six_a, SixAReading::Original);
        assert_eq!(naca.mean_line, MeanLine::SixAModified { design_cl: 0.2 });
        assert_eq!(
            original.mean_line,
            MeanLine::Uniform {
                design_cl: 0.2,
                a: 0.8
            }
        );
        let (Thickness::Joined(n), Thickness::Joined(o)) = (&naca.thickness, &original.thickness)
        else {
            panic!("6-series thickness");
        };
        assert_eq!(n.straight_from, Some(SIX_A_STRAIGHT_FROM));
        assert_eq!(o.straight_from, None);
        // Without A= the original takes the a = 1 line.
        assert_eq!(
            read(&card("64A204"), SixAReading::Original).mean_line,
            MeanLine::Uniform {
                design_cl: 0.2,
                a: 1.0
            }
        );
        let plain = card("643-618");
        assert_eq!(
            read(&plain, SixAReading::Original),
            read(&plain, SixAReading::Naca)
        );
    }

    #[test]
    fn a_third_digit_nacas_does_not_define_is_the_standard_line_with_a_warning() {
        let odd = section(NacaSeries::Five, "65415");
        let standard = section(NacaSeries::Five, "65015");
        assert_eq!(odd.mean_line, standard.mean_line);
        assert_eq!(odd.title, "NACA 65415");
        assert_eq!(odd.warnings.len(), 1);
        assert!(
            odd.warnings[0].contains("third digit 4"),
            "{:?}",
            odd.warnings
        );
        assert!(standard.warnings.is_empty());
    }

    #[test]
    fn undefined_designations_are_refused_with_the_reason() {
        use NacaSeries::*;
        for (series, text, why) in [
            (Five, "27012", "second digit) 7 is not defined"),
            (Five, "21112", "second digit) 1 is not defined"),
            (Four, "4012", "second digit) 0 is not defined"),
            (Four, "0000", "thickness 00"),
            (Four, "0012-27", "after the dash) 7 is not defined"),
            (One, "18-212", "series 18 is not defined"),
            (Six, "68-212", "series 68 is not defined"),
            (Six, "66A212", "series 66A is not defined"),
            (Supersonic, "4-50.0-2.5", "type 4"),
            (Supersonic, "1-0.0-2.5", "ridge position"),
            (Supersonic, "2-50.0", "thickness 0.0"),
        ] {
            let e = NacaSection::parse(series, text).unwrap_err().to_string();
            assert!(e.contains(why), "{text}: {e}");
        }
    }

    #[test]
    fn sixteen_series_is_the_modified_thickness_with_index_4_at_mid_chord() {
        let s = section(NacaSeries::One, "16-212");
        let m = section(NacaSeries::Four, "0012-45");
        for x in [0.01, 0.2, 0.5, 0.9] {
            assert_eq!(s.thickness.half(x), m.thickness.half(x));
        }
        assert_eq!(
            s.mean_line,
            MeanLine::Uniform {
                design_cl: 0.2,
                a: 1.0
            }
        );
    }

    #[test]
    fn six_a_mean_line_is_the_modified_a_08_line() {
        let plain = section(NacaSeries::Six, "64A204");
        let written = section(NacaSeries::Six, "64A204A=0.8");
        assert_eq!(plain.mean_line, MeanLine::SixAModified { design_cl: 0.2 });
        assert_eq!(written.mean_line, plain.mean_line);
        let other = section(NacaSeries::Six, "64A204A=0.5");
        assert_eq!(
            other.mean_line,
            MeanLine::Uniform {
                design_cl: 0.2,
                a: 0.5
            }
        );
    }

    #[test]
    fn no_nan_anywhere_in_the_tables() {
        use NacaSeries::*;
        for (series, text) in [
            (Four, "9412"),
            (Four, "0012-25"),
            (Five, "23012"),
            (Five, "25112-63"),
            (One, "16-912"),
            (Six, "63-012"),
            (Six, "67-915"),
            (Six, "65A004"),
            (Six, "64,3-618A=0.0"),
            (Supersonic, "1-50.0-2.5"),
            (Supersonic, "2-50.0-5.0"),
            (Supersonic, "3-30.0-2.5-20.0"),
        ] {
            let c = section(series, text).coordinates().unwrap();
            assert_eq!(c.rows.len(), 60);
            for r in &c.rows {
                let v = r.values();
                assert!(v.iter().all(|v| v.is_finite()), "{text}: {r:?}");
            }
        }
    }
}
