//! User-defined sections: the coordinates of an xxSCHR namelist with TYPEIN = 1 (upper and
//! lower ordinates) or TYPEIN = 2 (mean line and thickness), tabulated at the user's own XCORD
//! stations (routines SECI, datcom.f line 26457, and XYCORD, lines 50953-51031).

use super::{CoordinateRow, SectionCoordinates, SectionError};
use crate::case::SectionInput;
use crate::charts::Query;
use crate::methods::section::SHORTEST_TRAILING_EDGE;

/// A section needs the leading edge, the trailing edge and a point between.
const MIN_POINTS: usize = 3;
/// How far the first and last XCORD may lie from 0 and 1: the namelist's decimals are exact to
/// far better than this, and a larger offset is a table that does not span the chord.
const END_TOLERANCE: f64 = 1e-6;

/// What the two ordinate arrays hold.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Ordinates {
    /// TYPEIN = 1: YUPPER and YLOWER.
    Surfaces,
    /// TYPEIN = 2: MEAN and THICK (the thickness, twice the half thickness).
    MeanAndThickness,
}

fn problem(variable: &'static str, problem: String) -> SectionError {
    SectionError::UserSection { variable, problem }
}

/// The coordinate table of a user-defined section (XYCORD, datcom.f lines 50953-51031): mean
/// line and half thickness from the input (for TYPEIN = 1, y_c = (y_u + y_l)/2 and
/// y_t = (y_u - y_l)/2), both set to zero at the first and last stations (the chord runs from
/// the leading to the trailing edge), the mean-line slope at each station that of the parabola
/// through the station and its neighbours (QUAD through TBFUNX), and the surfaces laid off
/// perpendicular to the mean line. XCORD must run from 0 to 1, increasing; a table that stops
/// short of 1 (at [`SHORTEST_TRAILING_EDGE`] or after) is closed at its last station, with a
/// warning, as the original's XYCORD closes it.
pub fn user_defined(input: &SectionInput) -> Result<SectionCoordinates, SectionError> {
    let kind = ordinates(input)?;
    let n = point_count(input)?;
    let x = array(input, "XCORD", n)?;
    let warnings = check_stations(x)?;
    let (mut mean, mut half) = mean_and_half(input, kind, n)?;
    for v in [&mut mean, &mut half] {
        v[0] = 0.0;
        v[n - 1] = 0.0;
    }
    let rows: Vec<CoordinateRow> = (0..n)
        .map(|i| {
            if i == 0 {
                CoordinateRow::leading_edge(x[0])
            } else if i == n - 1 {
                CoordinateRow::trailing_edge(x[i])
            } else {
                CoordinateRow::perpendicular(x[i], mean[i], slope(x, &mean, i), half[i])
            }
        })
        .collect();
    // Stations a few units of f64's least value apart pass the increasing test, but the mean
    // line's slope through them, or the surfaces laid off along it, are not numbers (found by
    // fuzzing the library: XCORD 5e-324 apart).
    if let Some(i) = rows
        .iter()
        .position(|r| r.values().iter().any(|v| !v.is_finite()))
    {
        return Err(problem(
            "XCORD",
            format!(
                "XCORD({}) = {}: the stations beside it are too close together for the mean \
                 line's slope there to be a number",
                i + 1,
                Query(x[i])
            ),
        ));
    }
    let leading_edge_radius = leading_edge_radius(input, x[1], half[1])?;
    if !leading_edge_radius.is_finite() {
        return Err(problem(
            "XCORD",
            format!(
                "XCORD(2) = {}: too close to the leading edge for the leading-edge radius \
                 (x² + y_t²)/(2x) to be a number; give LERI",
                Query(x[1])
            ),
        ));
    }
    let (max_thickness, max_thickness_x) = rows.iter().fold((0.0, 0.0), |(t, at), r| {
        if r.thickness > t {
            (r.thickness, r.x)
        } else {
            (t, at)
        }
    });
    Ok(SectionCoordinates {
        title: "USER DEFINED".into(),
        subtitle: None,
        rows,
        max_thickness,
        max_thickness_x,
        leading_edge_radius,
        warnings,
    })
}

fn ordinates(input: &SectionInput) -> Result<Ordinates, SectionError> {
    match input.scalars.get("TYPEIN").copied() {
        Some(1.0) => Ok(Ordinates::Surfaces),
        Some(2.0) => Ok(Ordinates::MeanAndThickness),
        found => Err(problem(
            "TYPEIN",
            format!(
                "{}; 1.0 takes XCORD, YUPPER and YLOWER, 2.0 takes XCORD, MEAN and THICK",
                found.map_or("not given".to_string(), |t| format!(
                    "{t} is not a section type"
                ))
            ),
        )),
    }
}

/// NPTS, or for a case built in code without it, the number of XCORD stations (the deck
/// writer gives NPTS so; a deck without NPTS is an error of its checks, as the original reads
/// no station then).
fn point_count(input: &SectionInput) -> Result<usize, SectionError> {
    let given = input.scalars.get("NPTS").copied();
    let npts = given.or((!input.xcord.is_empty()).then_some(input.xcord.len() as f64));
    match npts {
        Some(npts) if npts.is_finite() && npts + 0.5 >= MIN_POINTS as f64 => {
            Ok((npts + 0.5) as usize)
        }
        found => Err(problem(
            "NPTS",
            format!(
                "{}; it counts the XCORD stations, at least {MIN_POINTS}",
                found.map_or("not given".to_string(), |n| format!("{n} points"))
            ),
        )),
    }
}

/// The `n` values of array `name`, all finite.
fn array<'a>(
    input: &'a SectionInput,
    name: &'static str,
    n: usize,
) -> Result<&'a [f64], SectionError> {
    let v: &[f64] = match name {
        "XCORD" => &input.xcord,
        "YUPPER" => &input.yupper,
        "YLOWER" => &input.ylower,
        "MEAN" => &input.mean,
        _ => &input.thick,
    };
    if v.len() != n {
        return Err(problem(name, format!("{} values for NPTS = {n}", v.len())));
    }
    if let Some(i) = v.iter().position(|x| !x.is_finite()) {
        return Err(problem(name, format!("value {} is not a number", i + 1)));
    }
    Ok(v)
}

/// The array `name`, or `alias` when only that is given: in the original MEAN and THICK share
/// their storage with YUPPER and YLOWER.
fn array_or_alias<'a>(
    input: &'a SectionInput,
    name: &'static str,
    alias: &'static str,
    n: usize,
) -> Result<&'a [f64], SectionError> {
    let given = |a: &'static str| match a {
        "YUPPER" => !input.yupper.is_empty(),
        "YLOWER" => !input.ylower.is_empty(),
        "MEAN" => !input.mean.is_empty(),
        _ => !input.thick.is_empty(),
    };
    if !given(name) && given(alias) {
        array(input, alias, n)
    } else {
        array(input, name, n)
    }
}

/// XCORD from the leading edge (0), strictly increasing, to the trailing edge (1). A last
/// station short of 1 is taken as the trailing edge, with a warning, as the original's XYCORD
/// takes it (its thickness and camber set to zero there, the section ending at that
/// fraction of the chord): real decks give tables that stop short of the trailing edge.
fn check_stations(x: &[f64]) -> Result<Vec<String>, SectionError> {
    let n = x.len();
    if x[0].abs() > END_TOLERANCE {
        return Err(problem(
            "XCORD",
            format!(
                "XCORD(1) = {}: the first station is the leading edge, 0",
                x[0]
            ),
        ));
    }
    if x[n - 1] - 1.0 > END_TOLERANCE || x[n - 1] < SHORTEST_TRAILING_EDGE {
        return Err(problem(
            "XCORD",
            format!(
                "XCORD({n}) = {}: the last station is the trailing edge, 1 (a table may stop \
                 short of it down to {SHORTEST_TRAILING_EDGE}, closed there with a warning)",
                x[n - 1]
            ),
        ));
    }
    let mut warnings = Vec::new();
    if 1.0 - x[n - 1] > END_TOLERANCE {
        warnings.push(format!(
            "XCORD({n}) = {}: the table stops short of the trailing edge (1); its last station \
             is taken as the trailing edge, with no thickness or camber, as the original takes it",
            x[n - 1]
        ));
    }
    if let Some(i) = (1..n).find(|&i| x[i] <= x[i - 1]) {
        return Err(problem(
            "XCORD",
            format!(
                "XCORD({}) = {} does not exceed XCORD({}) = {}: the stations must increase",
                i + 1,
                x[i],
                i,
                x[i - 1]
            ),
        ));
    }
    Ok(warnings)
}

/// Mean line and half thickness at the stations, from either kind of input.
fn mean_and_half(
    input: &SectionInput,
    kind: Ordinates,
    n: usize,
) -> Result<(Vec<f64>, Vec<f64>), SectionError> {
    let (first, second) = match kind {
        Ordinates::Surfaces => (
            array_or_alias(input, "YUPPER", "MEAN", n)?,
            array_or_alias(input, "YLOWER", "THICK", n)?,
        ),
        Ordinates::MeanAndThickness => (
            array_or_alias(input, "MEAN", "YUPPER", n)?,
            array_or_alias(input, "THICK", "YLOWER", n)?,
        ),
    };
    let (mean, half): (Vec<f64>, Vec<f64>) = match kind {
        Ordinates::Surfaces => first
            .iter()
            .zip(second)
            .map(|(u, l)| (0.5 * (u + l), 0.5 * (u - l)))
            .unzip(),
        Ordinates::MeanAndThickness => first.iter().zip(second).map(|(c, t)| (*c, 0.5 * t)).unzip(),
    };
    // Ordinates whose half sum or half difference overflows (±1e308) are not a section.
    let names = match kind {
        Ordinates::Surfaces => ("YUPPER", "YLOWER"),
        Ordinates::MeanAndThickness => ("MEAN", "THICK"),
    };
    if let Some(i) = (0..n).find(|&i| !(mean[i].is_finite() && half[i].is_finite())) {
        return Err(problem(
            names.0,
            format!(
                "value {}: {} and {} there give no mean line or thickness that is a number",
                i + 1,
                names.0,
                names.1
            ),
        ));
    }
    if let Some(i) = (1..n - 1).find(|&i| half[i] < 0.0) {
        let what = match kind {
            Ordinates::Surfaces => ("YUPPER", "lies below YLOWER"),
            Ordinates::MeanAndThickness => ("THICK", "is negative"),
        };
        return Err(problem(what.0, format!("value {} {}", i + 1, what.1)));
    }
    Ok((mean, half))
}

/// Slope of the mean line at station `i`: the derivative there of the parabola through the
/// station and its two neighbours (the first or last three stations at the ends), as the
/// original's TBFUNX/QUAD (datcom.f lines 39097-39264, 25384-25408).
fn slope(x: &[f64], y: &[f64], i: usize) -> f64 {
    let k = i.clamp(1, x.len() - 2) - 1;
    let (x0, x1, x2) = (x[k], x[k + 1], x[k + 2]);
    let (y0, y1, y2) = (y[k], y[k + 1], y[k + 2]);
    let at = x[i];
    y0 * (2.0 * at - x1 - x2) / ((x0 - x1) * (x0 - x2))
        + y1 * (2.0 * at - x0 - x2) / ((x1 - x0) * (x1 - x2))
        + y2 * (2.0 * at - x0 - x1) / ((x2 - x0) * (x2 - x1))
}

/// LERI when given, else the radius of the circle centred on the chord through the leading
/// edge and the upper surface point at the second station, (x^2 + y_t^2) / (2x) (M50O62).
fn leading_edge_radius(input: &SectionInput, x1: f64, half1: f64) -> Result<f64, SectionError> {
    match input.scalars.get("LERI").copied() {
        Some(r) if r.is_finite() && r >= 0.0 => Ok(r),
        Some(r) => Err(problem(
            "LERI",
            format!("{r}: the leading-edge radius is a fraction of chord, not negative"),
        )),
        None => Ok((x1 * x1 + half1 * half1) / (2.0 * x1)),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn input(typein: f64, x: &[f64], a: &[f64], b: &[f64]) -> SectionInput {
        let mut s = SectionInput::default();
        s.scalars.insert("TYPEIN".into(), typein);
        s.scalars.insert("NPTS".into(), x.len() as f64);
        s.xcord = x.to_vec();
        if typein == 1.0 {
            s.yupper = a.to_vec();
            s.ylower = b.to_vec();
        } else {
            s.mean = a.to_vec();
            s.thick = b.to_vec();
        }
        s
    }

    #[test]
    fn both_kinds_give_the_same_section() {
        let x = [0.0, 0.1, 0.3, 0.6, 1.0];
        let up = [0.0, 0.05, 0.07, 0.05, 0.0];
        let lo = [0.0, -0.03, -0.04, -0.02, 0.0];
        let mean: Vec<f64> = up.iter().zip(&lo).map(|(u, l)| (u + l) / 2.0).collect();
        let thick: Vec<f64> = up.iter().zip(&lo).map(|(u, l)| u - l).collect();
        let a = user_defined(&input(1.0, &x, &up, &lo)).unwrap();
        let b = user_defined(&input(2.0, &x, &mean, &thick)).unwrap();
        for (r, s) in a.rows.iter().zip(&b.rows) {
            assert!((r.upper_y - s.upper_y).abs() < 1e-15 && (r.lower_x - s.lower_x).abs() < 1e-15);
        }
        assert!((a.max_thickness - 0.11).abs() < 1e-15 && a.max_thickness_x == 0.3);
        // Circle through (0, 0) and (0.1, 0.04): (0.01 + 0.0016) / 0.2.
        assert!((a.leading_edge_radius - 0.058).abs() < 1e-15);
    }

    #[test]
    fn the_slope_is_that_of_the_parabola_through_the_neighbours() {
        let x = [0.0, 0.2, 0.5, 1.0];
        let y: Vec<f64> = x.iter().map(|x| 0.3 * x * x - 0.1 * x).collect();
        for i in 0..4 {
            assert!((slope(&x, &y, i) - (0.6 * x[i] - 0.1)).abs() < 1e-14);
        }
    }

    #[test]
    fn bad_inputs_are_refused_with_the_variable() {
        let x = [0.0, 0.5, 1.0];
        let y = [0.0, 0.05, 0.0];
        let z = [0.0, -0.05, 0.0];
        let cases = [
            (input(3.0, &x, &y, &z), "TYPEIN: 3 is not a section type"),
            (
                input(1.0, &[0.0, 0.5, 1.1], &y, &z),
                "XCORD: XCORD(3) = 1.1",
            ),
            (
                input(1.0, &[0.0, 0.5, 0.5, 1.0], &[0.0; 4], &[0.0; 4]),
                "XCORD(3) = 0.5 does not exceed",
            ),
            (input(1.0, &x, &z, &y), "YUPPER: value 2 lies below YLOWER"),
            (input(1.0, &x, &y, &z[..2]), "YLOWER: 2 values for NPTS = 3"),
            (input(1.0, &x[..2], &y[..2], &z[..2]), "NPTS: 2 points"),
            // Found by fuzzing the library: stations 5e-324 apart gave NaN surfaces.
            (
                input(
                    1.0,
                    &[0.0, 5e-324, 0.5, 1.0],
                    &[0.0, 0.02, 0.05, 0.0],
                    &[0.0; 4],
                ),
                "XCORD(2) = 5e-324: the stations beside it are too close together",
            ),
            (
                input(
                    1.0,
                    &[0.0, 1e-313, 0.5, 1.0],
                    &[0.0, 0.02, 0.05, 0.0],
                    &[0.0, -0.02, -0.05, 0.0],
                ),
                "XCORD(2) = 1e-313: too close to the leading edge",
            ),
            // Found by review: ordinates that overflow were blamed on the stations.
            (
                input(1.0, &x, &[0.0, 1e308, 0.0], &[0.0, -1e308, 0.0]),
                "YUPPER: value 2: YUPPER and YLOWER there give no mean line or thickness",
            ),
        ];
        for (s, why) in cases {
            let e = user_defined(&s).unwrap_err().to_string();
            assert!(e.contains(why), "{e}");
        }
    }

    /// A table short of the trailing edge is closed at its last station, as the original's
    /// XYCORD closes it, with a warning.
    #[test]
    fn a_table_short_of_the_trailing_edge_ends_at_its_last_station() {
        let short = input(
            1.0,
            &[0.0, 0.5, 0.97],
            &[0.0, 0.05, 0.01],
            &[0.0, -0.05, -0.01],
        );
        let c = user_defined(&short).expect("read with a warning");
        assert_eq!(c.warnings.len(), 1, "{:?}", c.warnings);
        assert!(
            c.warnings[0].contains("XCORD(3) = 0.97"),
            "{:?}",
            c.warnings
        );
        let last = c.rows.last().expect("rows");
        assert_eq!((last.x, last.thickness, last.mean), (0.97, 0.0, 0.0));
        // Shorter than SHORTEST_TRAILING_EDGE: refused.
        let e = user_defined(&input(1.0, &[0.0, 0.5, 0.9], &[0.0; 3], &[0.0; 3]))
            .unwrap_err()
            .to_string();
        assert!(e.contains("XCORD(3) = 0.9: the last station"), "{e}");
        let full = input(1.0, &[0.0, 0.5, 1.0], &[0.0, 0.05, 0.0], &[0.0, -0.05, 0.0]);
        assert!(user_defined(&full).expect("read").warnings.is_empty());
    }
}
