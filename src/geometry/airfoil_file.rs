//! Airfoil coordinate files (Selig and Lednicer formats, as the UIUC database distributes them)
//! turned into the section input of a deck: `XCORD` with `YUPPER`/`YLOWER` at common chord
//! stations (DATCOM's TYPEIN=1 section input, at most 50 points).
//!
//! Selig: a name line, then x y pairs from the trailing edge over the upper surface to the
//! leading edge and back over the lower surface. Lednicer: a name line, a line with the point
//! counts of the two surfaces, then each surface from the leading edge to the trailing edge.

use crate::case::SectionInput;

/// Most chord stations a section namelist holds (XCORD(50)).
pub const MAX_STATIONS: usize = 50;

/// Why a coordinate file cannot be used.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum AirfoilFileError {
    #[error("line {line}: expected two numbers `x y`, found `{found}`")]
    BadLine { line: usize, found: String },
    #[error("too few points ({0}); an airfoil needs at least 3 on each surface")]
    TooFewPoints(usize),
    #[error(
        "the chord is not 0 to 1 (x from {min} to {max}); scale the coordinates to unit chord"
    )]
    NotUnitChord { min: f64, max: f64 },
    #[error("{0} stations asked for; between 3 and {MAX_STATIONS}")]
    Stations(usize),
}

/// An airfoil's two surfaces, each from the leading edge to the trailing edge.
#[derive(Debug, Clone, PartialEq)]
pub struct AirfoilSurfaces {
    pub name: String,
    pub upper: Vec<(f64, f64)>,
    pub lower: Vec<(f64, f64)>,
}

fn numbers(line: &str) -> Option<(f64, f64)> {
    let mut it = line.split_whitespace().map(str::parse::<f64>);
    match (it.next(), it.next(), it.next()) {
        (Some(Ok(x)), Some(Ok(y)), None) if x.is_finite() && y.is_finite() => Some((x, y)),
        _ => None,
    }
}

/// Reads a Selig or Lednicer coordinate file.
pub fn read(text: &str) -> Result<AirfoilSurfaces, AirfoilFileError> {
    let mut lines = text
        .lines()
        .enumerate()
        .filter(|(_, l)| !l.trim().is_empty());
    let name = lines
        .next()
        .map(|(_, l)| l.trim().to_string())
        .unwrap_or_default();
    let mut points = Vec::new();
    for (i, l) in lines {
        match numbers(l) {
            Some(p) => points.push(p),
            None => {
                return Err(AirfoilFileError::BadLine {
                    line: i + 1,
                    found: l.trim().chars().take(40).collect(),
                })
            }
        }
    }
    // Lednicer: the first pair holds the point counts of the two surfaces (both > 1).
    let (upper, lower) = match points.first() {
        Some(&(nu, nl)) if nu > 1.0 && nl > 1.0 && nu.fract() == 0.0 && nl.fract() == 0.0 => {
            let nu = nu as usize;
            let rest = &points[1..];
            if rest.len() < nu + 3 {
                return Err(AirfoilFileError::TooFewPoints(rest.len()));
            }
            (rest[..nu].to_vec(), rest[nu..].to_vec())
        }
        _ => {
            // Selig: split at the leading edge (smallest x).
            let le = points
                .iter()
                .enumerate()
                .min_by(|a, b| a.1 .0.total_cmp(&b.1 .0))
                .map_or(0, |(i, _)| i);
            let mut upper: Vec<(f64, f64)> = points[..=le].to_vec();
            upper.reverse();
            (upper, points[le..].to_vec())
        }
    };
    if upper.len() < 3 || lower.len() < 3 {
        return Err(AirfoilFileError::TooFewPoints(upper.len().min(lower.len())));
    }
    let all = upper.iter().chain(&lower).map(|p| p.0);
    let (min, max) = all.fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), x| {
        (a.min(x), b.max(x))
    });
    /// Coordinates are unit chord when they start and end within this of 0 and 1.
    const UNIT_CHORD: f64 = 1e-3;
    if min.abs() > UNIT_CHORD || (max - 1.0).abs() > UNIT_CHORD {
        return Err(AirfoilFileError::NotUnitChord { min, max });
    }
    Ok(AirfoilSurfaces { name, upper, lower })
}

/// `y` of a surface (leading edge to trailing edge) at chord station `x`, linear between points.
fn surface_at(s: &[(f64, f64)], x: f64) -> f64 {
    let n = s.len();
    if x <= s[0].0 {
        return s[0].1;
    }
    let k = s.windows(2).position(|w| x <= w[1].0).unwrap_or(n - 2);
    let ((x0, y0), (x1, y1)) = (s[k], s[k + 1]);
    if x1 == x0 {
        return y1;
    }
    y0 + (x - x0) / (x1 - x0) * (y1 - y0)
}

impl AirfoilSurfaces {
    /// The section input of a deck: `n` chord stations spaced closer at both edges
    /// (x = (1 − cos θ)/2), both surfaces interpolated linearly there.
    pub fn to_section_input(&self, n: usize) -> Result<SectionInput, AirfoilFileError> {
        if !(3..=MAX_STATIONS).contains(&n) {
            return Err(AirfoilFileError::Stations(n));
        }
        let x: Vec<f64> = (0..n)
            .map(|i| {
                let theta = std::f64::consts::PI * i as f64 / (n - 1) as f64;
                // Rounded to 5 decimals, as a deck would write them.
                ((1.0 - theta.cos()) / 2.0 * 1e5).round() / 1e5
            })
            .collect();
        let round = |v: f64| (v * 1e5).round() / 1e5;
        let mut input = SectionInput {
            yupper: x
                .iter()
                .map(|&x| round(surface_at(&self.upper, x)))
                .collect(),
            ylower: x
                .iter()
                .map(|&x| round(surface_at(&self.lower, x)))
                .collect(),
            xcord: x,
            ..SectionInput::default()
        };
        input.scalars.insert("TYPEIN".into(), 1.0);
        input.scalars.insert("NPTS".into(), n as f64);
        Ok(input)
    }
}

/// The section input as a `$WGSCHR`-style namelist (for `name` = WGSCHR, HTSCHR, ...).
pub fn namelist_text(name: &str, input: &SectionInput) -> String {
    let mut out = format!(" ${name} TYPEIN=1.0, NPTS={}.0,\n", input.xcord.len());
    for (var, values) in [
        ("XCORD", &input.xcord),
        ("YUPPER", &input.yupper),
        ("YLOWER", &input.ylower),
    ] {
        let mut line = format!("   {var}(1)=");
        for v in values.iter() {
            let item = format!("{v:.5},");
            if line.len() + item.len() > 79 {
                out.push_str(&line);
                out.push('\n');
                line = "     ".to_string();
            }
            line.push_str(&item);
        }
        out.push_str(&line);
        out.push('\n');
    }
    out.push_str("   $\n");
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    const SELIG: &str = "TEST\n1.0 0.0\n0.5 0.06\n0.0 0.0\n0.5 -0.04\n1.0 0.0\n";

    #[test]
    fn selig_split_at_the_leading_edge() {
        let a = read(SELIG).unwrap();
        assert_eq!(a.upper, vec![(0.0, 0.0), (0.5, 0.06), (1.0, 0.0)]);
        assert_eq!(a.lower, vec![(0.0, 0.0), (0.5, -0.04), (1.0, 0.0)]);
        let s = a.to_section_input(5).unwrap();
        assert_eq!(s.xcord, vec![0.0, 0.14645, 0.5, 0.85355, 1.0]);
        assert_eq!(s.yupper[2], 0.06);
        assert_eq!(s.ylower[2], -0.04);
    }

    #[test]
    fn lednicer_counts_line() {
        let t = "TEST\n3. 3.\n0.0 0.0\n0.5 0.06\n1.0 0.0\n0.0 0.0\n0.5 -0.04\n1.0 0.0\n";
        let a = read(t).unwrap();
        assert_eq!(a.upper.len(), 3);
        assert_eq!(a.lower[1], (0.5, -0.04));
    }

    #[test]
    fn bad_files() {
        assert!(matches!(
            read("X\n1 2 3\n"),
            Err(AirfoilFileError::BadLine { line: 2, .. })
        ));
        assert!(matches!(
            read("X\n10.0 0.0\n5.0 1.0\n0.0 0.0\n5.0 -1.0\n10.0 0.0\n"),
            Err(AirfoilFileError::NotUnitChord { .. })
        ));
        let a = read(SELIG).unwrap();
        assert!(matches!(
            a.to_section_input(51),
            Err(AirfoilFileError::Stations(51))
        ));
    }

    #[test]
    fn namelist_reads_back() {
        let a = read(SELIG).unwrap();
        let s = a.to_section_input(9).unwrap();
        let text = format!(
            " $FLTCON NMACH=1.0, MACH(1)=0.1$\n $SYNTHS XCG=0.0$\n{}",
            namelist_text("WGSCHR", &s)
        );
        let deck = crate::read_deck(&text, "t");
        let back = &deck.cases[0].sections["WING"];
        assert_eq!(back.xcord, s.xcord);
        assert_eq!(back.yupper, s.yupper);
    }
}
