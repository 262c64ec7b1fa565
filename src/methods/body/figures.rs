//! The DATCOM figures the body methods read, looked up in the chart files under
//! `charts/body/`; a lookup outside a chart's data becomes a [`BodyWarning::Chart`].

use super::{BodyMethodError, BodyWarning};
use crate::charts;

/// Fig. 4.2.1.1-20: apparent-mass factor k2 − k1 against fineness ratio.
pub const APPARENT_MASS: &str = "4.2.1.1-20";
/// Fig. 4.2.1.2-35a: crossflow drag proportionality factor η against fineness ratio.
pub const CROSSFLOW_ETA: &str = "4.2.1.2-35a";
/// Fig. 4.2.1.2-35b: crossflow drag coefficient of a circular cylinder against M·|sin α|.
pub const CROSSFLOW_CDC: &str = "4.2.1.2-35b";
/// Fig. 4.1.5.1-26: turbulent skin friction, polynomial coefficients by Mach number.
pub const SKIN_FRICTION: &str = "4.1.5.1-26";
/// Fig. 4.1.5.1-27: cut-off Reynolds number of a rough surface.
pub const CUTOFF_REYNOLDS: &str = "4.1.5.1-27";
/// Fig. 4.2.1.2-36a: potential normal-force factor kp against body aspect ratio.
pub const POTENTIAL_FACTOR: &str = "4.2.1.2-36a";
/// Fig. 4.2.1.2-36b: viscous normal-force factor kv against body aspect ratio.
pub const VISCOUS_FACTOR: &str = "4.2.1.2-36b";
/// Fig. 4.2.1.2-37: angle of attack where viscous crossflow begins.
pub const CROSSFLOW_ONSET: &str = "4.2.1.2-37";

/// Every figure the body methods read.
pub const ALL: [&str; 8] = [
    APPARENT_MASS,
    CROSSFLOW_ETA,
    CROSSFLOW_CDC,
    SKIN_FRICTION,
    CUTOFF_REYNOLDS,
    POTENTIAL_FACTOR,
    VISCOUS_FACTOR,
    CROSSFLOW_ONSET,
];

/// The chart `id`, or an error naming it.
pub fn chart(id: &'static str) -> Result<&'static charts::Chart, BodyMethodError> {
    charts::get(id).ok_or(BodyMethodError::MissingChart { chart: id })
}

/// Reads figure `id` at `args`, recording any excursion outside its data in `warnings`.
pub fn read(
    id: &'static str,
    args: &[f64],
    warnings: &mut Vec<BodyWarning>,
) -> Result<f64, BodyMethodError> {
    let value = chart(id)?.lookup_each(args, |w| {
        let w = BodyWarning::Chart(w);
        if !warnings.contains(&w) {
            warnings.push(w);
        }
    });
    value.ok_or_else(|| BodyMethodError::ChartNoValue {
        chart: id,
        args: args.to_vec(),
    })
}

/// The node values of the outermost axis of figure `id`.
pub fn outer_nodes(id: &'static str) -> Result<&'static [f64], BodyMethodError> {
    match &chart(id)?.data {
        charts::Node::Table { x, .. } => Ok(x),
        charts::Node::Value(_) => Err(BodyMethodError::MissingChart { chart: id }),
    }
}
