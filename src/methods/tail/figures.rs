//! The charts the downwash and tail methods read (files under charts/tail/; the tail-body
//! interference factors are the wing-body charts of figures 4.3.1.2-10 and -12, read through
//! `methods::wing_body`), by DATCOM figure id.

use super::{TailError, TailWarning};
use crate::charts;

/// 4.4.1-68a: the Δy above which the flow separates at the leading edge (c/4 sweep).
pub const LEADING_EDGE_SEPARATION: &str = "4.4.1-68a";
/// 4.4.1-68b: average downwash factor on the aft surface (height and span over the vortex span).
pub const AVERAGE_DOWNWASH: &str = "4.4.1-68b";

/// 4.4.1-71: spanwise station of a canard's tip vortices at the aft surface, over the
/// canard's exposed semispan (taper, A tan Λ_LE, β A).
pub const CANARD_VORTEX_STATION: &str = "4.4.1-71";

/// Every chart of its own the tail methods read.
pub const ALL: &[&str] = &[
    LEADING_EDGE_SEPARATION,
    AVERAGE_DOWNWASH,
    CANARD_VORTEX_STATION,
];

/// The chart's value at `args`; leaving its data is a warning, a refusal an error.
pub fn read(
    id: &'static str,
    args: &[f64],
    warnings: &mut Vec<TailWarning>,
) -> Result<f64, TailError> {
    let chart = charts::get(id).ok_or(TailError::MissingChart { chart: id })?;
    let value = chart.lookup_each(args, |w| {
        let w = TailWarning::Chart(w);
        if !warnings.contains(&w) {
            warnings.push(w);
        }
    });
    value.ok_or_else(|| TailError::ChartNoValue {
        chart: id,
        args: args.to_vec(),
    })
}
