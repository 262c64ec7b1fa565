//! The planform quantities the wing methods use, from `geometry::planform` (DATCOM 2.2.2):
//! exposed totals, the inboard and outboard panels, the "extended" outboard panel of the
//! double-delta and cranked methods, and sweeps at the chord lines the methods name.

use serde::Serialize;

use crate::geometry::PlanformGeometry;

/// Sweep of one chord line: angle, cosine and tangent.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Sweep {
    pub deg: f64,
    pub cos: f64,
    pub tan: f64,
}

impl Sweep {
    fn from_tan(tan: f64) -> Sweep {
        let a = tan.atan();
        Sweep {
            deg: a.to_degrees(),
            cos: a.cos(),
            tan,
        }
    }

    fn from_deg(deg: f64) -> Sweep {
        let a = deg.to_radians();
        Sweep {
            deg,
            cos: a.cos(),
            tan: a.tan(),
        }
    }
}

/// One trapezoidal panel of the exposed planform.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct PanelTerms {
    /// Area of both halves, m².
    pub area: f64,
    pub aspect_ratio: f64,
    pub taper: f64,
    /// Mean aerodynamic chord, m.
    pub mac: f64,
    /// Semi-span of the panel, m.
    pub span: f64,
    pub leading_edge: Sweep,
    pub half_chord: Sweep,
    /// Cosine of the sweep of the line of maximum thickness.
    pub cos_max_thickness: f64,
}

/// The outboard panel extended inboard to the middle of the exposed inboard panel (the
/// double-delta and cranked aerodynamic-centre method, DATCOM 4.1.4.2).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct ExtendedOutboard {
    /// Semi-span from mid-inboard-panel to the tip, m.
    pub span: f64,
    /// Chord at its root (mid-inboard-panel), m.
    pub root_chord: f64,
    pub area: f64,
    pub aspect_ratio: f64,
    pub taper: f64,
}

/// Planform quantities of the wing methods; lengths in metres.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct WingPlanform {
    pub semispan: f64,
    pub exposed_semispan: f64,
    /// Chord at the body side.
    pub exposed_root_chord: f64,
    pub exposed_area: f64,
    pub aspect_ratio: f64,
    /// Tip chord over exposed root chord.
    pub taper: f64,
    /// Exposed mean aerodynamic chord.
    pub mac: f64,
    /// Sweeps of the exposed planform (a two-panel planform: the exposed-area weighted
    /// cosine, unsigned, as the original averages them).
    pub leading_edge: Sweep,
    pub quarter_chord: Sweep,
    pub half_chord: Sweep,
    pub cos_max_thickness: f64,
    /// Mid-chord of the exposed MAC behind the exposed root's leading edge.
    pub x_mac_mid_chord: f64,
    pub inboard: PanelTerms,
    pub outboard: Option<PanelTerms>,
    pub extended_outboard: Option<ExtendedOutboard>,
    /// Spanwise station of the outboard MAC behind the break.
    pub y_outboard_mac_from_break: f64,
}

/// Chord fractions of maximum thickness of the inboard and outboard sections (none: the
/// leading edge, as the original's unset value gives).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct MaxThicknessStations {
    pub inboard: Option<f64>,
    pub outboard: Option<f64>,
}

/// Tip and break chords of the planform as given (CHRDTP, CHRDBP), m.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Chords {
    pub tip: f64,
    pub at_break: f64,
}

fn cos_of_tan(t: f64) -> f64 {
    1.0 / (1.0 + t * t).sqrt()
}

impl WingPlanform {
    /// The quantities of `g` with the sections' maximum-thickness stations.
    pub fn new(g: &PlanformGeometry, chords: Chords, tmax: MaxThicknessStations) -> WingPlanform {
        let x_in = tmax.inboard.unwrap_or(0.0);
        let x_out = tmax.outboard.unwrap_or(x_in);
        let inboard_span = g.exposed_semispan - g.outboard_span;
        let inboard = PanelTerms {
            area: g.inboard_exposed.area,
            aspect_ratio: g.inboard_exposed.aspect_ratio,
            taper: g.inboard_exposed.taper,
            mac: g.inboard_exposed.mac,
            span: inboard_span,
            leading_edge: Sweep::from_tan(g.tan_sweep_inboard(0.0)),
            half_chord: Sweep::from_tan(g.tan_sweep_inboard(0.5)),
            cos_max_thickness: cos_of_tan(g.tan_sweep_inboard(x_in)),
        };
        let outboard = g.outboard.map(|o| PanelTerms {
            area: o.area,
            aspect_ratio: o.aspect_ratio,
            taper: o.taper,
            mac: o.mac,
            span: g.outboard_span,
            leading_edge: Sweep::from_tan(g.tan_sweep_outboard(0.0)),
            half_chord: Sweep::from_tan(g.tan_sweep_outboard(0.5)),
            cos_max_thickness: cos_of_tan(g.tan_sweep_outboard(x_out)),
        });
        let exposed = g.exposed;
        let (tan_le_in, tan_le_out) = (g.tan_sweep_inboard(0.0), g.tan_sweep_outboard(0.0));
        let y_out_from_root = g.outboard.map_or(inboard_span, |o| o.y_mac);
        let area_out = g.outboard.map_or(0.0, |o| o.area);
        let x_mac_mid_chord = exposed.mac / 2.0
            + (inboard.area * g.inboard_exposed.y_mac * tan_le_in
                + area_out
                    * (inboard_span * tan_le_in + (y_out_from_root - inboard_span) * tan_le_out))
                / exposed.area;
        let cos_max_thickness = match &outboard {
            None => inboard.cos_max_thickness,
            Some(o) => {
                (inboard.area * inboard.cos_max_thickness + o.area * o.cos_max_thickness)
                    / exposed.area
            }
        };
        let extended_outboard = g.outboard.map(|_| {
            let span = inboard_span / 2.0 + g.outboard_span;
            let tip = chords.tip;
            let break_chord = chords.at_break;
            let root_chord = tip + span * (break_chord - tip) / g.outboard_span;
            let area = (root_chord + tip) * span;
            ExtendedOutboard {
                span,
                root_chord,
                area,
                aspect_ratio: 4.0 * span * span / area,
                taper: tip / root_chord,
            }
        });
        WingPlanform {
            semispan: g.semispan,
            exposed_semispan: g.exposed_semispan,
            exposed_root_chord: g.exposed_root_chord,
            exposed_area: exposed.area,
            aspect_ratio: exposed.aspect_ratio,
            taper: exposed.taper,
            mac: exposed.mac,
            leading_edge: total_sweep(g, 0.0),
            quarter_chord: total_sweep(g, 0.25),
            half_chord: total_sweep(g, 0.5),
            cos_max_thickness,
            x_mac_mid_chord,
            inboard,
            outboard,
            extended_outboard,
            y_outboard_mac_from_break: y_out_from_root - inboard_span,
        }
    }

    /// Whether the planform has an outboard panel.
    pub fn two_panel(&self) -> bool {
        self.outboard.is_some()
    }
}

/// The quarter-chord sweep the wing methods take ([`WingPlanform::quarter_chord`]).
pub fn quarter_chord_sweep(g: &PlanformGeometry) -> Sweep {
    total_sweep(g, 0.25)
}

fn total_sweep(g: &PlanformGeometry, x: f64) -> Sweep {
    if g.outboard.is_none() {
        Sweep::from_tan(g.tan_sweep_inboard(x))
    } else {
        Sweep::from_deg(g.sweep_deg(x))
    }
}
