//! SVG figures of a case (`datcom-rs plot`): CL, CD and Cm against α, the drag polar, Cm against
//! CL, the sideslip derivatives and the dynamic derivatives against α, one series per flight
//! condition (Mach and altitude) of the case's most complete configuration, with a legend.
//!
//! An output edge like the other reports: the deck's units (altitude) and the deck's DERIV unit
//! (derivatives per degree unless DERIV RAD). A value DATCOM does not give breaks the line; a
//! derivative DATCOM gives once per configuration is drawn level across the angles and its
//! legend says so.

use plotters::prelude::*;

use super::{condition_view, derivative_view};
use crate::case::units::unit_label;
use crate::deck::cards::DerivUnit;
use crate::deck::schema::Dimension;
use crate::results::{CaseResults, ConditionResults};

/// Why a figure could not be drawn.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum PlotError {
    #[error("case {case}: nothing to plot: no coefficient was computed")]
    NothingToPlot { case: usize },
    #[error("figure {figure}: {message}")]
    Draw { figure: String, message: String },
}

/// One figure: `name` is a short file stem (`cl`, `polar`, `clp` ...).
#[derive(Debug, Clone, PartialEq)]
pub struct Figure {
    pub name: String,
    pub title: String,
    /// The legend labels of the series drawn, in order.
    pub series: Vec<String>,
    pub svg: String,
}

/// A series: its label and its points, in pieces where values are missing (a piece of one
/// point is a marker alone).
pub(crate) struct Series {
    pub(crate) label: String,
    pub(crate) pieces: Vec<Vec<(f64, f64)>>,
    /// One value per configuration: a marker on the first angle only (where DATCOM gives it).
    pub(crate) once: bool,
}

/// What a figure plots against what.
#[derive(Clone, Copy)]
enum Quantity {
    Alpha,
    /// A coefficient column (`CL`, `CLB`, `CLP` ...), a derivative when `per_angle`.
    Column {
        name: &'static str,
        symbol: &'static str,
        per_angle: bool,
    },
}

const fn coefficient(name: &'static str, symbol: &'static str) -> Quantity {
    Quantity::Column {
        name,
        symbol,
        per_angle: false,
    }
}

const fn derivative(name: &'static str, symbol: &'static str) -> Quantity {
    Quantity::Column {
        name,
        symbol,
        per_angle: true,
    }
}

const CL: Quantity = coefficient("CL", "CL");
const CD: Quantity = coefficient("CD", "CD");
const CM: Quantity = coefficient("CM", "Cm");

/// The figures: (file stem, y, x).
const FIGURES: [(&str, Quantity, Quantity); 17] = [
    ("cl", CL, Quantity::Alpha),
    ("cd", CD, Quantity::Alpha),
    ("cm", CM, Quantity::Alpha),
    ("polar", CL, CD),
    ("cm-cl", CM, CL),
    ("cyb", derivative("CYB", "CYβ"), Quantity::Alpha),
    ("cnb", derivative("CNB", "Cnβ"), Quantity::Alpha),
    ("clb", derivative("CLB", "Clβ"), Quantity::Alpha),
    ("clq", derivative("CLQ", "CLq"), Quantity::Alpha),
    ("cmq", derivative("CMQ", "Cmq"), Quantity::Alpha),
    ("clad", derivative("CLAD", "CLα̇"), Quantity::Alpha),
    ("cmad", derivative("CMAD", "Cmα̇"), Quantity::Alpha),
    ("clp", derivative("CLP", "Clp"), Quantity::Alpha),
    ("cyp", derivative("CYP", "CYp"), Quantity::Alpha),
    ("cnp", derivative("CNP", "Cnp"), Quantity::Alpha),
    ("cnr", derivative("CNR", "Cnr"), Quantity::Alpha),
    ("clr", derivative("CLR", "Clr"), Quantity::Alpha),
];

impl Quantity {
    fn label(self, deriv: DerivUnit) -> String {
        match self {
            Quantity::Alpha => "α (deg)".into(),
            Quantity::Column {
                symbol,
                per_angle: true,
                ..
            } => format!(
                "{symbol} (1/{})",
                match deriv {
                    DerivUnit::Deg => "deg",
                    DerivUnit::Rad => "rad",
                }
            ),
            Quantity::Column { symbol, .. } => format!("{symbol} (-)"),
        }
    }

    /// Values at every angle in the report's units, and whether the column is one value per
    /// configuration (given on the first angle only) drawn level.
    fn values(self, c: &ConditionResults, deriv: DerivUnit) -> (Vec<Option<f64>>, bool) {
        match self {
            Quantity::Alpha => (c.alpha_deg.iter().map(|a| Some(*a)).collect(), false),
            Quantity::Column {
                name, per_angle, ..
            } => {
                let raw = c.column(name).unwrap_or(&[]);
                let view = |v: Option<f64>| {
                    let v = v.filter(|x| x.is_finite());
                    if per_angle {
                        derivative_view(v, deriv)
                    } else {
                        v
                    }
                };
                let once = per_angle
                    && raw.len() > 1
                    && raw[0].is_some()
                    && raw[1..].iter().all(Option::is_none);
                let values = if once {
                    vec![view(raw[0]); raw.len()]
                } else {
                    (0..c.alpha_deg.len())
                        .map(|i| view(raw.get(i).copied().flatten()))
                        .collect()
                };
                (values, once)
            }
        }
    }
}

/// The series of one figure: one per condition, pieces split where a value is missing.
fn series(results: &CaseResults, y: Quantity, x: Quantity) -> Vec<Series> {
    results
        .most_complete()
        .into_iter()
        .filter_map(|c| {
            let (ys, once) = y.values(c, results.deriv);
            let (xs, _) = x.values(c, results.deriv);
            let mut pieces: Vec<Vec<(f64, f64)>> = vec![Vec::new()];
            for (xv, yv) in xs.iter().zip(&ys) {
                match (xv, yv) {
                    (Some(a), Some(b)) => pieces.last_mut().unwrap().push((*a, *b)),
                    _ => pieces.push(Vec::new()),
                }
            }
            pieces.retain(|p| !p.is_empty());
            if pieces.is_empty() {
                return None;
            }
            let v = condition_view(c, results.dim);
            let mut label = format!("Mach {}", v.mach);
            if let Some(h) = v.altitude {
                label.push_str(&format!(
                    ", {h} {}",
                    unit_label(results.dim, Dimension::Length).to_lowercase()
                ));
            }
            if once {
                label.push_str(" (one value per configuration)");
            }
            Some(Series {
                label,
                pieces,
                once,
            })
        })
        .collect()
}

/// The data range with a margin, never empty.
fn range(values: impl Iterator<Item = f64>) -> std::ops::Range<f64> {
    let (lo, hi) = values.fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), v| {
        (l.min(v), h.max(v))
    });
    // Nearly level data get a span of a tenth of their magnitude, so that the tick labels
    // differ.
    let magnitude = lo.abs().max(hi.abs()).max(1e-3);
    if hi - lo < 0.02 * magnitude {
        let mid = 0.5 * (lo + hi);
        return (mid - 0.05 * magnitude)..(mid + 0.05 * magnitude);
    }
    let pad = 0.05 * (hi - lo);
    (lo - pad)..(hi + pad)
}

/// Distinct colours for the series (the "tab10" set), repeated beyond ten.
const COLOURS: [(u8, u8, u8); 10] = [
    (31, 119, 180),
    (214, 39, 40),
    (44, 160, 44),
    (255, 127, 14),
    (148, 103, 189),
    (140, 86, 75),
    (227, 119, 194),
    (127, 127, 127),
    (23, 190, 207),
    (188, 189, 34),
];

/// The legend goes in the right-hand corner the data leave free: below when the points in
/// the right third of the figure lie mostly in its upper half.
fn legend_position(
    series: &[Series],
    x: &std::ops::Range<f64>,
    y: &std::ops::Range<f64>,
) -> SeriesLabelPosition {
    let right: Vec<f64> = series
        .iter()
        .flat_map(|s| s.pieces.iter().flatten())
        .filter(|p| (p.0 - x.start) / (x.end - x.start) > 0.66)
        .map(|p| (p.1 - y.start) / (y.end - y.start))
        .collect();
    let upper = right.iter().filter(|&&v| v > 0.5).count();
    if 2 * upper > right.len() {
        SeriesLabelPosition::LowerRight
    } else {
        SeriesLabelPosition::UpperRight
    }
}

pub(crate) fn draw(
    title: &str,
    x_label: &str,
    y_label: &str,
    series: &[Series],
) -> Result<String, Box<dyn std::error::Error>> {
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, (900, 600)).into_drawing_area();
        root.fill(&WHITE)?;
        let points = || series.iter().flat_map(|s| s.pieces.iter().flatten());
        let xr = range(points().map(|p| p.0));
        let yr = range(points().map(|p| p.1));
        let legend = legend_position(series, &xr, &yr);
        let mut chart = ChartBuilder::on(&root)
            .caption(title, ("sans-serif", 22))
            .margin(20)
            .x_label_area_size(50)
            .y_label_area_size(80)
            .build_cartesian_2d(xr, yr)?;
        chart
            .configure_mesh()
            .x_desc(x_label)
            .y_desc(y_label)
            .axis_desc_style(("sans-serif", 18))
            .light_line_style(WHITE)
            .draw()?;
        for (i, s) in series.iter().enumerate() {
            let (r, g, b) = COLOURS[i % COLOURS.len()];
            let color = RGBColor(r, g, b).to_rgba();
            for (k, piece) in s.pieces.iter().enumerate() {
                let line = chart.draw_series(LineSeries::new(
                    piece.iter().copied(),
                    color.stroke_width(2),
                ))?;
                if k == 0 {
                    line.label(s.label.clone()).legend(move |(x, y)| {
                        PathElement::new(vec![(x, y), (x + 20, y)], color.stroke_width(2))
                    });
                }
                let marked = if s.once { &piece[..1] } else { &piece[..] };
                chart.draw_series(marked.iter().map(|&p| Circle::new(p, 3, color.filled())))?;
            }
        }
        chart
            .configure_series_labels()
            .background_style(WHITE.mix(0.85))
            .border_style(BLACK)
            .position(legend)
            .draw()?;
        root.present()?;
    }
    Ok(svg)
}

/// The figures of a case that has something to show; `NothingToPlot` when none has.
pub fn figures(results: &CaseResults) -> Result<Vec<Figure>, PlotError> {
    let case_name = results
        .caseid
        .clone()
        .unwrap_or_else(|| format!("case {}", results.number));
    let mut out = Vec::new();
    for (name, y, x) in FIGURES {
        let s = series(results, y, x);
        if s.is_empty() {
            continue;
        }
        let short = |q: Quantity| match q {
            Quantity::Alpha => "α".to_string(),
            Quantity::Column { symbol, .. } => symbol.to_string(),
        };
        let title = format!("{case_name}: {} against {}", short(y), short(x));
        let svg =
            draw(&title, &x.label(results.deriv), &y.label(results.deriv), &s).map_err(|e| {
                PlotError::Draw {
                    figure: name.to_string(),
                    message: e.to_string(),
                }
            })?;
        out.push(Figure {
            name: name.to_string(),
            title,
            series: s.into_iter().map(|s| s.label).collect(),
            svg,
        });
    }
    if out.is_empty() {
        return Err(PlotError::NothingToPlot {
            case: results.number,
        });
    }
    Ok(out)
}
