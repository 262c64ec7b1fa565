//! The section data of `charts/sections/`: the coordinate-table stations and the tabulated
//! constants of the NACA families, looked up at their nodes.

use std::sync::OnceLock;

use super::SectionError;
use crate::charts::{self, Node};

/// Chart ids (see the files in `charts/sections/` for source, axes and notes).
pub(crate) const STATIONS: &str = "airfoil-stations";
pub(crate) const MODIFIED_D1: &str = "airfoil-modified-4digit-d1";
pub(crate) const FIVE_DIGIT_M: &str = "airfoil-5digit-m";
pub(crate) const FIVE_DIGIT_K1: &str = "airfoil-5digit-k1";
pub(crate) const SIX_ZT: &str = "airfoil-6series-zt";
pub(crate) const SIX_SM: &str = "airfoil-6series-sm";
pub(crate) const SIX_R0: &str = "airfoil-6series-r0";
pub(crate) const SIX_A_D1: &str = "airfoil-6a-d1";

/// The value of chart `id` at `args`, or `None` when `args` lie outside its data (every
/// section chart refuses to extrapolate: a designation outside the table names no section).
pub(crate) fn lookup(id: &'static str, args: &[f64]) -> Result<Option<f64>, SectionError> {
    let chart = charts::get(id).ok_or(SectionError::MissingChart(id))?;
    Ok(chart.lookup(args).value)
}

/// The 60 chordwise stations of the coordinate table of a NACA-card section (DECODE, datcom.f
/// lines 7219-7230): 0 to 0.01 by 0.001, to 0.30 by 0.01, to 0.80 by 0.05, to 1 by 0.02, as the
/// original's single-precision sums (chart `airfoil-stations`).
pub fn stations() -> Result<&'static [f64], SectionError> {
    static STATIONS_X: OnceLock<Option<Vec<f64>>> = OnceLock::new();
    STATIONS_X
        .get_or_init(|| {
            let chart = charts::get(STATIONS)?;
            match &chart.data {
                Node::Table { nodes, .. } => nodes
                    .iter()
                    .map(|n| match n {
                        Node::Value(v) => Some(*v),
                        Node::Table { .. } => None,
                    })
                    .collect(),
                Node::Value(_) => None,
            }
        })
        .as_deref()
        .ok_or(SectionError::MissingChart(STATIONS))
}
