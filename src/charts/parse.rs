//! Reading and validating chart files.

use serde::Deserialize;

use super::{Axis, Chart, Name, Node, Output, Outside, Source};

/// Why a chart file cannot be used.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum ChartError {
    #[error("{file}: not a chart file: {message}")]
    Syntax { file: String, message: String },
    #[error("{file}: axis {axis}: {message}")]
    Axis {
        file: String,
        axis: String,
        message: String,
    },
    #[error("{file}: data: {message}")]
    Data { file: String, message: String },
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct FileAxis {
    symbol: String,
    name: String,
    unit: String,
    below: Outside,
    above: Outside,
    /// Node values; absent on the innermost axis of a family of curves.
    values: Option<Vec<f64>>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct FileCurve {
    x: Vec<f64>,
    y: Vec<f64>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct FileChart {
    id: String,
    title: String,
    output: FileOutput,
    source: FileSource,
    #[serde(default)]
    notes: String,
    #[serde(default)]
    defects: Vec<String>,
    node_tolerance: Option<f64>,
    axes: Vec<FileAxis>,
    data: FileData,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct FileData {
    /// Regular grid: values, innermost axis fastest.
    values: Option<Vec<f64>>,
    /// Family of curves: one per combination of the outer axes' values, innermost fastest.
    #[serde(default)]
    curves: Vec<FileCurve>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct FileOutput {
    symbol: String,
    name: String,
    unit: String,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct FileSource {
    figure: String,
    routine: String,
    lines: String,
}

impl<'de> Deserialize<'de> for Outside {
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let s = String::deserialize(d)?;
        match s.as_str() {
            "clamp" => Ok(Outside::Clamp),
            "linear" => Ok(Outside::Linear),
            "quadratic" => Ok(Outside::Quadratic),
            "refuse" => Ok(Outside::Refuse),
            other => Err(serde::de::Error::custom(format!(
                "`{other}`: expected clamp, linear, quadratic or refuse"
            ))),
        }
    }
}

/// Strictly ascending or strictly descending, finite, at least two values.
fn check_axis(file: &str, axis: &str, x: &[f64]) -> Result<(), ChartError> {
    let err = |message: String| ChartError::Axis {
        file: file.into(),
        axis: axis.into(),
        message,
    };
    if x.len() < 2 {
        return Err(err(format!("needs at least 2 values, has {}", x.len())));
    }
    if let Some(v) = x.iter().find(|v| !v.is_finite()) {
        return Err(err(format!("non-finite value {v}")));
    }
    let up = x.windows(2).all(|w| w[1] > w[0]);
    let down = x.windows(2).all(|w| w[1] < w[0]);
    if !(up || down) {
        return Err(err("values are not strictly monotone".into()));
    }
    Ok(())
}

fn data_err(file: &str, message: String) -> ChartError {
    ChartError::Data {
        file: file.into(),
        message,
    }
}

/// Builds the node tree for axes `axes[k..]` from a flat grid, consuming values in order.
fn grid(axes: &[Vec<f64>], values: &mut std::slice::Iter<'_, f64>) -> Node {
    match axes.split_first() {
        None => Node::Value(values.next().copied().unwrap_or(f64::NAN)),
        Some((x, rest)) => Node::Table {
            x: x.clone(),
            nodes: x.iter().map(|_| grid(rest, values)).collect(),
        },
    }
}

/// Builds the node tree for outer axes `axes` over a list of curves, consuming curves in order.
fn family(axes: &[Vec<f64>], curves: &mut std::slice::Iter<'_, FileCurve>) -> Node {
    match axes.split_first() {
        None => match curves.next() {
            Some(c) => Node::Table {
                x: c.x.clone(),
                nodes: c.y.iter().map(|y| Node::Value(*y)).collect(),
            },
            None => Node::Value(f64::NAN),
        },
        Some((x, rest)) => Node::Table {
            x: x.clone(),
            nodes: x.iter().map(|_| family(rest, curves)).collect(),
        },
    }
}

/// Parses and validates one chart file.
pub fn parse_chart(text: &str, file: &str) -> Result<Chart, ChartError> {
    let f: FileChart = toml::from_str(text).map_err(|e| ChartError::Syntax {
        file: file.into(),
        message: e.to_string(),
    })?;
    if f.axes.is_empty() {
        return Err(data_err(file, "a chart needs at least one axis".into()));
    }
    let n = f.axes.len();
    let mut outer: Vec<Vec<f64>> = Vec::new();
    for (k, a) in f.axes.iter().enumerate() {
        match (&a.values, k + 1 == n) {
            (Some(v), _) => {
                check_axis(file, &a.symbol, v)?;
                outer.push(v.clone());
            }
            (None, true) => {}
            (None, false) => {
                return Err(ChartError::Axis {
                    file: file.into(),
                    axis: a.symbol.clone(),
                    message: "only the innermost axis may leave its values to the curves".into(),
                })
            }
        }
    }
    let shared_axes = outer.len();
    let data = match (&f.data.values, f.data.curves.is_empty(), outer.len() == n) {
        (Some(values), true, true) => {
            let expected: usize = outer.iter().map(Vec::len).product();
            if values.len() != expected {
                return Err(data_err(
                    file,
                    format!("{} values for a grid of {expected}", values.len()),
                ));
            }
            if let Some(v) = values.iter().find(|v| !v.is_finite()) {
                return Err(data_err(file, format!("non-finite value {v}")));
            }
            grid(&outer, &mut values.iter())
        }
        (None, false, false) => {
            let expected: usize = outer.iter().map(Vec::len).product();
            if f.data.curves.len() != expected {
                return Err(data_err(
                    file,
                    format!("{} curves for {expected} combinations of the outer axes", f.data.curves.len()),
                ));
            }
            for (i, c) in f.data.curves.iter().enumerate() {
                check_axis(file, &format!("{} (curve {})", f.axes[n - 1].symbol, i + 1), &c.x)?;
                if c.y.len() != c.x.len() {
                    return Err(data_err(
                        file,
                        format!("curve {}: {} x and {} y values", i + 1, c.x.len(), c.y.len()),
                    ));
                }
                if let Some(v) = c.y.iter().find(|v| !v.is_finite()) {
                    return Err(data_err(file, format!("curve {}: non-finite value {v}", i + 1)));
                }
            }
            family(&outer, &mut f.data.curves.iter())
        }
        _ => {
            return Err(data_err(
                file,
                "give either `values` with every axis's values (a grid) or `curves` with the innermost axis's values left out (a family)".into(),
            ))
        }
    };
    let tol = f.node_tolerance.unwrap_or(1e-3);
    if !(0.0..0.1).contains(&tol) {
        return Err(data_err(
            file,
            format!("node_tolerance {tol} is not in [0, 0.1)"),
        ));
    }
    Ok(Chart {
        id: Name::from(f.id),
        title: f.title,
        axes: f
            .axes
            .into_iter()
            .map(|a| Axis {
                symbol: Name::from(a.symbol),
                name: a.name,
                unit: a.unit,
                below: a.below,
                above: a.above,
            })
            .collect(),
        output: Output {
            symbol: f.output.symbol,
            name: f.output.name,
            unit: f.output.unit,
        },
        source: Source {
            figure: f.source.figure,
            routine: f.source.routine,
            lines: f.source.lines,
        },
        notes: f.notes,
        defects: f.defects,
        node_tolerance: tol,
        data,
        shared_axes,
        file: file.into(),
    })
}
