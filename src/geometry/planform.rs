//! Planform geometry of wings, tails and ventral fins (DATCOM section 2.2.2: straight-tapered
//! and cranked planforms as trapezoidal panels; the original's routine WTGEOM).
//!
//! A planform is one trapezoidal panel from the centre line to the tip, or two: an inboard
//! panel from the centre line to the break and an outboard panel from the break to the tip
//! (`SSPNOP` > 0; TYPE 2 double delta and 3 cranked, and any TYPE with `SSPNOP`). The geometry
//! does not depend on TYPE, as in the original. "Exposed" means outboard of the body side at
//! `SSPN - SSPNE` from the centre line.
//!
//! Areas of a wing or horizontal tail are of both halves; a vertical tail or ventral fin is a
//! single panel ([`Span::Single`]), whose areas and aspect ratios are those of the one panel.
//! Sweep angles at any chord fraction follow from the sweep given at `CHSTAT`:
//! tan Λ(x) = tan Λ(CHSTAT) + (c_inner − c_outer)/b_panel · (CHSTAT − x).

use serde::Serialize;

use crate::case::Planform;

/// Whether a surface has two halves (wing, horizontal tail) or is a single panel (vertical
/// tail, ventral fin).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub enum Span {
    Both,
    Single,
}

/// Why a planform has no geometry.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum GeometryError {
    #[error("{0} is not given")]
    Missing(&'static str),
    #[error("{what} must be positive; it is {value}")]
    NotPositive { what: &'static str, value: f64 },
    #[error("the exposed semi-span SSPNE ({sspne}) must exceed the outboard panel's span SSPNOP ({sspnop})")]
    ExposedInsideBreak { sspne: f64, sspnop: f64 },
    /// A value the deck's checks refuse, met in a case built in code (a deck with it has an
    /// error already).
    #[error("{what} = {value} (SI: m, deg): {rule}")]
    Invalid {
        what: &'static str,
        value: f64,
        rule: &'static str,
    },
}

/// The angles (deg) the methods divide by the cosine of (sweeps, dihedrals, incidences) must lie
/// strictly between −90° and 90° (the deck's checks use it too).
pub(crate) const RIGHT_ANGLE_DEG: f64 = 90.0;

/// How far (relative) SSPNE may exceed SSPN: the decimals of a deck that gives them equal.
pub(crate) const EXPOSED_SPAN_TOLERANCE: f64 = 1e-9;

/// What a case built in code can hold and a deck's checks refuse: a negative tip chord, an
/// exposed semi-span beyond the semi-span, a sweep or dihedral of 90° or more, a value that is
/// not a number.
fn check_values(p: &Planform, sspn: f64) -> Result<(), GeometryError> {
    let invalid = |what, value, rule| Err(GeometryError::Invalid { what, value, rule });
    for (what, value) in [
        ("CHRDTP", p.chrdtp),
        ("CHRDBP", p.chrdbp),
        ("SSPNE", p.sspne),
    ] {
        match value {
            Some(v) if v < 0.0 || !v.is_finite() => {
                return invalid(what, v, "must be finite and not negative");
            }
            _ => {}
        }
    }
    if let Some(e) = p
        .sspne
        .filter(|e| *e > sspn * (1.0 + EXPOSED_SPAN_TOLERANCE))
    {
        return invalid(
            "SSPNE",
            e,
            "the exposed semi-span must not exceed the semi-span SSPN",
        );
    }
    for (what, value) in [
        ("SAVSI", p.savsi_deg),
        ("SAVSO", p.savso_deg),
        ("DHDADI", p.dhdadi_deg),
        ("DHDADO", p.dhdado_deg),
    ] {
        match value {
            Some(v) if v.is_nan() || v.abs() >= RIGHT_ANGLE_DEG => {
                return invalid(what, v, "must lie strictly between -90 and 90 deg");
            }
            _ => {}
        }
    }
    Ok(())
}

/// One trapezoid, or a set of them, reduced to the numbers DATCOM uses.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Panel {
    /// Area, m² (both halves for a [`Span::Both`] surface).
    pub area: f64,
    /// Tip chord over root chord.
    pub taper: f64,
    /// Span² over area (of the surface as the area counts it).
    pub aspect_ratio: f64,
    /// Mean aerodynamic chord, m.
    pub mac: f64,
    /// Spanwise station of the MAC from the panel's own root (for totals: see the field docs
    /// of [`PlanformGeometry`]), m.
    pub y_mac: f64,
}

/// Geometry of one planform, SI.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct PlanformGeometry {
    pub span: Span,
    /// One panel from centre line to tip (no outboard panel).
    pub straight: bool,
    /// Chord at the body side (y = SSPN − SSPNE), m.
    pub exposed_root_chord: f64,
    /// Whole theoretical planform; `y_mac` from the centre line.
    pub theoretical: Panel,
    /// Whole exposed planform; `y_mac` from the exposed root.
    pub exposed: Panel,
    /// Theoretical inboard panel (centre line to break); `y_mac` from the centre line.
    pub inboard_theoretical: Panel,
    /// Exposed inboard panel (body side to break); `y_mac` from the exposed root.
    pub inboard_exposed: Panel,
    /// Outboard panel (break to tip); `y_mac` from the exposed root. `None` when straight.
    pub outboard: Option<Panel>,
    /// Chordwise position of the theoretical MAC's leading edge behind the apex (the root
    /// leading edge on the centre line), m.
    pub x_mac_le: f64,
    /// Chordwise position of the exposed MAC's quarter chord behind the apex, m.
    pub x_exposed_mac_quarter: f64,
    /// Semi-span, exposed semi-span and outboard panel span, m.
    pub semispan: f64,
    pub exposed_semispan: f64,
    pub outboard_span: f64,
    /// d(tan Λ)/d(chord fraction) of the inboard and outboard panels (chord change over span).
    inboard_rate: f64,
    outboard_rate: f64,
    /// Chord fraction at which the sweeps are given, and their tangents.
    chstat: f64,
    tan_sweep_inboard_given: f64,
    tan_sweep_outboard_given: f64,
}

/// MAC of a trapezoid with root chord `c` and taper `l`: 2/3·c·(1 + λ + λ²)/(1 + λ).
fn trapezoid_mac(c: f64, l: f64) -> f64 {
    2.0 * c * (1.0 + l + l * l) / (3.0 * (1.0 + l))
}

/// Spanwise station of a trapezoid's MAC from its root: b/3·(1 + 2λ)/(1 + λ).
fn trapezoid_y_mac(b: f64, l: f64) -> f64 {
    b * (1.0 + 2.0 * l) / (3.0 * (1.0 + l))
}

/// Aspect ratio of a two-sided panel of semi-span `b` and area `s` (both halves).
fn aspect(b: f64, s: f64) -> f64 {
    4.0 * b * b / s
}

impl PlanformGeometry {
    /// Tangent of the inboard panel's sweep at chord fraction `x` (0 leading edge, 1 trailing).
    pub fn tan_sweep_inboard(&self, x: f64) -> f64 {
        self.tan_sweep_inboard_given + self.inboard_rate * (self.chstat - x)
    }

    /// Tangent of the outboard panel's sweep at chord fraction `x` (the inboard one when
    /// straight).
    pub fn tan_sweep_outboard(&self, x: f64) -> f64 {
        if self.straight {
            return self.tan_sweep_inboard(x);
        }
        self.tan_sweep_outboard_given + self.outboard_rate * (self.chstat - x)
    }

    /// Sweep of the whole planform at chord fraction `x`, degrees. Straight: the panel's
    /// sweep (signed). With an outboard panel: the angle whose cosine is the exposed-area
    /// weighted mean of the panels' cosines (unsigned), as the original averages it.
    pub fn sweep_deg(&self, x: f64) -> f64 {
        let inboard = self.tan_sweep_inboard(x).atan();
        match &self.outboard {
            None => inboard.to_degrees(),
            Some(o) => {
                let outboard = self.tan_sweep_outboard(x).atan();
                let cos = (self.inboard_exposed.area * inboard.cos() + o.area * outboard.cos())
                    / self.exposed.area;
                cos.clamp(-1.0, 1.0).acos().to_degrees()
            }
        }
    }

    /// Chord fraction `x` at which the inboard sweep is `tan_sweep` (inverse of
    /// [`Self::tan_sweep_inboard`]); `None` for a panel of constant chord.
    pub fn chord_fraction_of_inboard_sweep(&self, tan_sweep: f64) -> Option<f64> {
        (self.inboard_rate != 0.0)
            .then(|| self.chstat - (tan_sweep - self.tan_sweep_inboard_given) / self.inboard_rate)
    }
}

/// The geometry of a planform given in a deck (SI values of [`Planform`]).
pub fn planform(p: &Planform, span: Span) -> Result<PlanformGeometry, GeometryError> {
    let chrdr = p.chrdr.ok_or(GeometryError::Missing("CHRDR"))?;
    let sspn = p.sspn.ok_or(GeometryError::Missing("SSPN"))?;
    for (what, value) in [("CHRDR", chrdr), ("SSPN", sspn)] {
        if value <= 0.0 || !value.is_finite() {
            return Err(GeometryError::NotPositive { what, value });
        }
    }
    check_values(p, sspn)?;
    let sspne = p.sspne.unwrap_or(sspn);
    let chrdtp = p.chrdtp.unwrap_or(0.0);
    // No outboard panel when SSPNOP is absent, zero or negative (the original's test).
    let sspnop = p.sspnop.filter(|s| *s > 0.0).unwrap_or(0.0);
    let straight = sspnop == 0.0;
    let chrdbp = if straight {
        chrdtp
    } else {
        p.chrdbp.ok_or(GeometryError::Missing("CHRDBP"))?
    };
    if sspne <= sspnop {
        return Err(GeometryError::ExposedInsideBreak { sspne, sspnop });
    }
    let b_in = sspn - sspnop; // theoretical inboard semi-span
    let b_in_exposed = sspne - sspnop;
    let taper_in = chrdbp / chrdr;
    let exposed_root_chord = chrdr * (taper_in + (1.0 - taper_in) * b_in_exposed / b_in);
    let taper_in_exposed = chrdbp / exposed_root_chord;
    let taper_out = if chrdbp == 0.0 { 1.0 } else { chrdtp / chrdbp };

    let area_in_exposed = (exposed_root_chord + chrdbp) * b_in_exposed;
    let area_out = (chrdbp + chrdtp) * sspnop;
    let area_exposed = area_in_exposed + area_out;
    let area_in = (chrdr + chrdbp) * b_in;
    let area = area_in + area_out;

    let mac_in_exposed = trapezoid_mac(exposed_root_chord, taper_in_exposed);
    let mac_in = trapezoid_mac(chrdr, taper_in);
    let mac_out = trapezoid_mac(chrdbp, taper_out);
    let mac_exposed = (area_in_exposed * mac_in_exposed + area_out * mac_out) / area_exposed;
    let mac = (area_in * mac_in + area_out * mac_out) / area;

    // Spanwise MAC stations: exposed ones from the exposed root, theoretical from the centre.
    let y_in_exposed = trapezoid_y_mac(b_in_exposed, taper_in_exposed);
    let y_out = if straight {
        b_in_exposed
    } else {
        trapezoid_y_mac(sspnop, taper_out) + b_in_exposed
    };
    let y_exposed = (area_in_exposed * y_in_exposed + area_out * y_out) / area_exposed;
    let y_in = trapezoid_y_mac(b_in, taper_in);
    let y_out_centre = if straight {
        0.0
    } else {
        trapezoid_y_mac(sspnop, taper_out) + b_in
    };
    let y_mac = (area_in * y_in + area_out * y_out_centre) / area;

    let chstat = p.chstat.unwrap_or(0.0);
    let inboard_rate = (chrdr - chrdbp) / b_in;
    let outboard_rate = if straight {
        0.0
    } else {
        (chrdbp - chrdtp) / sspnop
    };
    let tan_in_given = p.savsi_deg.unwrap_or(0.0).to_radians().tan();
    let tan_out_given = p.savso_deg.unwrap_or(0.0).to_radians().tan();
    let tan_le_in = tan_in_given + inboard_rate * chstat;
    let tan_le_out = tan_out_given + outboard_rate * chstat;

    // Leading edge of the theoretical MAC behind the apex.
    let x_mac_le = (area_in * y_in * tan_le_in
        + area_out * (b_in * tan_le_in + (y_out_centre - b_in) * tan_le_out))
        / area;
    // Exposed MAC quarter chord behind the apex: the exposed root's leading edge lies
    // (SSPN − SSPNE)·tan Λ_LE behind the apex, with the planform's total leading-edge sweep.
    let x_exposed_mid = mac_exposed / 2.0
        + (area_in_exposed * y_in_exposed * tan_le_in
            + area_out * (b_in_exposed * tan_le_in + (y_out - b_in_exposed) * tan_le_out))
            / area_exposed;

    let half = match span {
        Span::Both => 1.0,
        Span::Single => 0.5,
    };
    let panel = |area: f64, taper: f64, ar: f64, mac: f64, y: f64| Panel {
        area: area * half,
        taper,
        aspect_ratio: ar * half,
        mac,
        y_mac: y,
    };
    let mut g = PlanformGeometry {
        span,
        straight,
        exposed_root_chord,
        theoretical: panel(area, chrdtp / chrdr, aspect(sspn, area), mac, y_mac),
        exposed: panel(
            area_exposed,
            chrdtp / exposed_root_chord,
            aspect(sspne, area_exposed),
            mac_exposed,
            y_exposed,
        ),
        inboard_theoretical: panel(area_in, taper_in, aspect(b_in, area_in), mac_in, y_in),
        inboard_exposed: panel(
            area_in_exposed,
            taper_in_exposed,
            aspect(b_in_exposed, area_in_exposed),
            mac_in_exposed,
            y_in_exposed,
        ),
        outboard: (!straight).then(|| {
            panel(
                area_out,
                taper_out,
                aspect(sspnop, area_out),
                mac_out,
                y_out,
            )
        }),
        x_mac_le,
        x_exposed_mac_quarter: 0.0,
        semispan: sspn,
        exposed_semispan: sspne,
        outboard_span: sspnop,
        inboard_rate,
        outboard_rate,
        chstat,
        tan_sweep_inboard_given: tan_in_given,
        tan_sweep_outboard_given: tan_out_given,
    };
    let tan_le_total = g.sweep_deg(0.0).to_radians().tan();
    g.x_exposed_mac_quarter = x_exposed_mid + (sspn - sspne) * tan_le_total - mac_exposed / 4.0;
    Ok(g)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Geometry identities hold to rounding.
    const ROUNDING: f64 = 1e-12;

    fn wing() -> Planform {
        Planform {
            chrdr: Some(7.29),
            chrdtp: Some(3.73),
            sspn: Some(16.70),
            sspne: Some(14.43),
            savsi_deg: Some(1.0),
            chstat: Some(0.25),
            ..Planform::default()
        }
    }

    #[test]
    fn rectangle() {
        let p = Planform {
            chrdr: Some(2.0),
            chrdtp: Some(2.0),
            sspn: Some(5.0),
            sspne: Some(5.0),
            ..Planform::default()
        };
        let g = planform(&p, Span::Both).unwrap();
        assert!((g.theoretical.area - 20.0).abs() < ROUNDING);
        assert!((g.theoretical.mac - 2.0).abs() < ROUNDING);
        assert!((g.theoretical.aspect_ratio - 5.0).abs() < ROUNDING);
        assert!((g.theoretical.y_mac - 2.5).abs() < ROUNDING);
    }

    #[test]
    fn straight_taper_by_hand() {
        // Navion wing: S = (7.29 + 3.73)·16.70 = 184.034; λ = 3.73/7.29 = 0.511660;
        // 1 + λ + λ² = 1.773456, 1 + λ = 1.511660, so MAC = 2/3·7.29·1.173198 = 5.70168;
        // A = 4·16.70²/184.034 = 6.06171.
        let g = planform(&wing(), Span::Both).unwrap();
        assert!((g.theoretical.area - 184.034).abs() < 1e-9);
        assert!(
            (g.theoretical.mac - 5.701_68).abs() < 5e-6,
            "{}",
            g.theoretical.mac
        );
        assert!((g.theoretical.aspect_ratio - 6.061_71).abs() < 5e-6);
    }

    #[test]
    fn sweep_conversions_invert() {
        let g = planform(&wing(), Span::Both).unwrap();
        for x in [0.0, 0.25, 0.5, 0.7, 1.0] {
            let t = g.tan_sweep_inboard(x);
            let back = g.chord_fraction_of_inboard_sweep(t).unwrap();
            assert!((back - x).abs() < ROUNDING, "{x} -> {back}");
        }
        assert!(
            (g.sweep_deg(0.25) - 1.0).abs() < ROUNDING,
            "given at CHSTAT"
        );
    }

    #[test]
    fn panels_add_up() {
        let p = Planform {
            chrdr: Some(10.0),
            chrdbp: Some(6.0),
            chrdtp: Some(2.0),
            sspn: Some(20.0),
            sspne: Some(18.0),
            sspnop: Some(12.0),
            ..Planform::default()
        };
        let g = planform(&p, Span::Both).unwrap();
        let o = g.outboard.unwrap();
        assert!((g.inboard_theoretical.area + o.area - g.theoretical.area).abs() < ROUNDING);
        assert!((g.inboard_exposed.area + o.area - g.exposed.area).abs() < ROUNDING);
        let v = planform(&p, Span::Single).unwrap();
        assert!((2.0 * v.theoretical.area - g.theoretical.area).abs() < ROUNDING);
        assert_eq!(v.theoretical.mac, g.theoretical.mac);
    }

    #[test]
    fn missing_or_bad_inputs_are_errors() {
        let mut p = wing();
        p.chrdr = None;
        assert_eq!(
            planform(&p, Span::Both),
            Err(GeometryError::Missing("CHRDR"))
        );
        let mut p = wing();
        p.sspnop = Some(15.0);
        p.chrdbp = Some(4.0);
        assert!(matches!(
            planform(&p, Span::Both),
            Err(GeometryError::ExposedInsideBreak { .. })
        ));
    }
}
