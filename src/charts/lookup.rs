//! Interpolation in a chart, as the original's table routines do it.

use super::{Chart, ChartWarning, Node, Outside};

/// The result of a lookup: the value (none when an axis refuses to extrapolate) and a warning
/// for every variable that left the data.
#[derive(Debug, Clone, PartialEq)]
pub struct Lookup {
    pub value: Option<f64>,
    pub warnings: Vec<ChartWarning>,
}

/// Whether a query `a` snaps to node `xi` (the original's GLOOK: relative distance below
/// `tol`, relative to the query, or to the node when the query is 0, or absolute near zero;
/// `tol = 0`: equal only).
fn snaps(xi: f64, a: f64, tol: f64) -> bool {
    /// Relative margin around `tol·|scale|` outside which the comparison is decided without
    /// the division: far beyond the few units of rounding in the product.
    const MARGIN: f64 = 1e-9;
    if tol == 0.0 {
        return xi == a;
    }
    let mut scale = if a == 0.0 { xi } else { a };
    if scale.abs() <= 1e-4 {
        scale = 1.0;
    }
    // The quotient's comparison, decided by a product away from the boundary.
    let distance = (a - xi).abs();
    let bound = tol * scale.abs();
    if distance > bound * (1.0 + MARGIN) {
        return false;
    }
    if distance < bound * (1.0 - MARGIN) {
        return true;
    }
    ((a - xi) / scale).abs() < tol
}

/// Where a query falls on an axis `x` (strictly monotone, finite): `lower` nodes come before it
/// in increasing x (`x` ascending: indices `0..lower`; descending: `n - lower..n`), and the
/// index of the node it snaps to, the first in `x`'s order.
///
/// The nodes a query snaps to are the nodes of an interval of x around the query (the
/// relative distance grows monotonically with the distance on each side, also as rounded),
/// so when there are any, a node next to the query is one of them and the first is found by
/// walking back from it: the same node as a scan of every node from the first.
fn locate(x: &[f64], a: f64, tol: f64) -> (usize, Option<usize>) {
    let n = x.len();
    let ascending = x[n - 1] > x[0];
    // Count of nodes below the query, and the storage index of the nearest below and above.
    // On a monotone axis the nodes before the query are counted: independent comparisons
    // rather than a binary search's chain of dependent loads (axes have a few dozen nodes).
    let (lower, below, above) = if ascending {
        let p = x.iter().filter(|&&v| v < a).count();
        (p, p.checked_sub(1), (p < n).then_some(p))
    } else {
        let p = x.iter().filter(|&&v| v >= a).count();
        // Storage 0..p are at or above the query, p..n below.
        (n - p, (p < n).then_some(p), p.checked_sub(1))
    };
    // The first matching node in storage order: walk to lower indices from a match.
    let first_from = |mut i: usize| {
        while i > 0 && snaps(x[i - 1], a, tol) {
            i -= 1;
        }
        i
    };
    let (first, second) = if ascending {
        (below, above)
    } else {
        (above, below)
    };
    let snapped = match (first, second) {
        (Some(i), _) if snaps(x[i], a, tol) => Some(first_from(i)),
        (_, Some(j)) if snaps(x[j], a, tol) => Some(j),
        _ => None,
    };
    (lower, snapped)
}

/// The parabola through three points, at `a` (the original's QUAD).
fn quadratic(x: [f64; 3], y: [f64; 3], a: f64) -> f64 {
    let l0 = (a - x[1]) * (a - x[2]) / ((x[0] - x[1]) * (x[0] - x[2]));
    let l1 = (a - x[0]) * (a - x[2]) / ((x[1] - x[0]) * (x[1] - x[2]));
    let l2 = (a - x[0]) * (a - x[1]) / ((x[2] - x[0]) * (x[2] - x[1]));
    y[0] * l0 + y[1] * l1 + y[2] * l2
}

/// Axes whose located queries a walk remembers (the charts have at most four).
const REMEMBERED_AXES: usize = 4;

/// Distinct warnings a walk remembers in place so as to say each once (a lookup gives at most
/// one per branch of each axis: four with the embedded charts); more go to a list.
const REMEMBERED_WARNINGS: usize = 16;

/// What makes a warning of a walk distinct: the axis, the value, its range and the action.
type WarningKey = (usize, f64, f64, f64, Outside);

struct Walk<'a, F: FnMut(ChartWarning)> {
    chart: &'a Chart,
    /// Where each warning goes, once.
    sink: F,
    said: [Option<WarningKey>; REMEMBERED_WARNINGS],
    /// Those said once `said` is full (none with the embedded charts).
    said_more: Vec<WarningKey>,
    /// Where the query fell on each shared axis ([`Chart::shared_axes`]), once found.
    located: [Option<(usize, Option<usize>)>; REMEMBERED_AXES],
}

impl<F: FnMut(ChartWarning)> Walk<'_, F> {
    fn warn(&mut self, depth: usize, value: f64, x: &[f64], action: Outside) {
        let (min, max) = x
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), v| {
                (lo.min(*v), hi.max(*v))
            });
        let axes = &self.chart.axes;
        let symbol = &axes[depth].symbol;
        let same = |&(d, v, lo, hi, act): &WarningKey| {
            axes[d].symbol == *symbol && v == value && lo == min && hi == max && act == action
        };
        if self.said.iter().flatten().chain(&self.said_more).any(same) {
            return;
        }
        let key = (depth, value, min, max, action);
        match self.said.iter_mut().find(|k| k.is_none()) {
            Some(free) => *free = Some(key),
            None => self.said_more.push(key),
        }
        (self.sink)(ChartWarning {
            chart: self.chart.id.clone(),
            variable: symbol.clone(),
            value,
            min,
            max,
            action,
        });
    }

    /// A node's value: a leaf's directly, a table's by the walk.
    #[inline(always)]
    fn child(&mut self, node: &Node, depth: usize, args: &[f64]) -> Option<f64> {
        match node {
            Node::Value(v) => Some(*v),
            Node::Table { .. } => self.eval(node, depth, args),
        }
    }

    fn eval(&mut self, node: &Node, depth: usize, args: &[f64]) -> Option<f64> {
        let (x, nodes) = match node {
            Node::Value(v) => return Some(*v),
            Node::Table { x, nodes } => (x, nodes),
        };
        let a = args[depth];
        let shared = depth < self.chart.shared_axes.min(REMEMBERED_AXES);
        let (lower, snapped) = match self.located.get(depth).copied().flatten() {
            Some(found) if shared => found,
            _ => {
                let found = locate(x, a, self.chart.node_tolerance);
                if shared {
                    self.located[depth] = Some(found);
                }
                found
            }
        };
        if let Some(i) = snapped {
            return self.child(&nodes[i], depth + 1, args);
        }
        let n = x.len();
        let ascending = x[n - 1] > x[0];
        // Node indices ordered by increasing x.
        let idx = |k: usize| if ascending { k } else { n - 1 - k };
        if lower > 0 && lower < n {
            // Strictly inside (a node equal to an end would have snapped unless a is beyond it).
            let (i, j) = (idx(lower - 1), idx(lower));
            if a > x[idx(0)] && a < x[idx(n - 1)] {
                let y0 = self.child(&nodes[i], depth + 1, args)?;
                let y1 = self.child(&nodes[j], depth + 1, args)?;
                return Some(y0 + (a - x[i]) / (x[j] - x[i]) * (y1 - y0));
            }
        }
        let axis = &self.chart.axes[depth];
        let below = a <= x[idx(0)];
        let policy = if below { axis.below } else { axis.above };
        self.warn(depth, a, x, policy);
        // End nodes, nearest first.
        let mut end_nodes = [0; 3];
        for (k, e) in end_nodes.iter_mut().enumerate().take(n) {
            *e = if below { idx(k) } else { idx(n - 1 - k) };
        }
        let end = &end_nodes[..n.min(3)];
        match policy {
            Outside::Refuse => None,
            Outside::Clamp => self.child(&nodes[end[0]], depth + 1, args),
            Outside::Quadratic if end.len() == 3 => {
                let mut y = [0.0; 3];
                for (k, &i) in end.iter().enumerate() {
                    y[k] = self.child(&nodes[i], depth + 1, args)?;
                }
                Some(quadratic([x[end[0]], x[end[1]], x[end[2]]], y, a))
            }
            Outside::Linear | Outside::Quadratic => {
                let (i, j) = (end[0], end[1]);
                let y0 = self.child(&nodes[i], depth + 1, args)?;
                let y1 = self.child(&nodes[j], depth + 1, args)?;
                Some(y0 + (a - x[i]) / (x[j] - x[i]) * (y1 - y0))
            }
        }
    }
}

impl Chart {
    /// Looks the chart up at `args`, one value per axis from the outermost. A wrong number of
    /// arguments or a non-finite argument gives no value and a warning.
    pub fn lookup(&self, args: &[f64]) -> Lookup {
        let mut warnings = Vec::new();
        let value = self.lookup_each(args, |w| warnings.push(w));
        Lookup { value, warnings }
    }

    /// [`Chart::lookup`] giving each warning to `sink` as it arises (each distinct one once),
    /// without collecting them.
    pub fn lookup_each(&self, args: &[f64], mut sink: impl FnMut(ChartWarning)) -> Option<f64> {
        if args.len() != self.axes.len() || args.iter().any(|a| !a.is_finite()) {
            sink(ChartWarning {
                chart: self.id.clone(),
                variable: self
                    .axes
                    .iter()
                    .map(|a| a.symbol.as_str())
                    .collect::<Vec<_>>()
                    .join(",")
                    .into(),
                value: args
                    .iter()
                    .copied()
                    .find(|a| !a.is_finite())
                    .unwrap_or(f64::NAN),
                min: f64::NAN,
                max: f64::NAN,
                action: Outside::Refuse,
            });
            return None;
        }
        let mut walk = Walk {
            chart: self,
            sink,
            said: [None; REMEMBERED_WARNINGS],
            said_more: Vec::new(),
            located: [None; REMEMBERED_AXES],
        };
        walk.eval(&self.data, 0, args).filter(|v| v.is_finite())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::charts::parse_chart;

    const GRID: &str = r#"
id = "test-grid"
title = "a 2-D test grid"
output = { symbol = "z", name = "z", unit = "-" }
source = { figure = "none", routine = "none", lines = "none" }
[[axes]]
symbol = "p"
name = "p"
unit = "-"
below = "clamp"
above = "linear"
values = [0.0, 1.0]
[[axes]]
symbol = "x"
name = "x"
unit = "-"
below = "refuse"
above = "quadratic"
values = [0.0, 1.0, 2.0]
[data]
"#;

    fn grid() -> Chart {
        // z = p + x² at the nodes.
        let text = format!("{GRID}values = [0.0, 1.0, 4.0, 1.0, 2.0, 5.0]\n");
        parse_chart(&text, "test.toml").unwrap()
    }

    #[test]
    fn nodes_and_between() {
        let c = grid();
        assert_eq!(c.lookup(&[1.0, 2.0]).value, Some(5.0));
        assert_eq!(c.lookup(&[0.5, 1.5]).value, Some(0.5 + 2.5));
        assert!(c.lookup(&[0.5, 1.5]).warnings.is_empty());
    }

    #[test]
    fn outside_policies() {
        let c = grid();
        let q = c.lookup(&[0.0, 3.0]);
        assert_eq!(q.value, Some(9.0), "quadratic through x² is exact");
        assert_eq!(q.warnings.len(), 1);
        assert_eq!(q.warnings[0].variable, "x");
        let r = c.lookup(&[0.0, -1.0]);
        assert_eq!(r.value, None);
        let l = c.lookup(&[2.0, 1.0]);
        assert_eq!(l.value, Some(3.0));
        let k = c.lookup(&[-1.0, 1.0]);
        assert_eq!(k.value, Some(1.0));
        assert!(k.warnings[0]
            .to_string()
            .contains("chart test-grid: p = -1 is outside the data (0 to 1): end value used"));
    }

    /// A family read outside every axis: each distinct warning is said once, however many
    /// there are (more than a walk keeps in place).
    #[test]
    fn every_distinct_warning_is_said_once() {
        let mut text = String::from(
            r#"
id = "test-family"
title = "a 4-axis test family"
output = { symbol = "z", name = "z", unit = "-" }
source = { figure = "none", routine = "none", lines = "none" }
"#,
        );
        for symbol in ["a", "b", "c"] {
            text += &format!(
                "[[axes]]\nsymbol = \"{symbol}\"\nname = \"{symbol}\"\nunit = \"-\"\n\
                 below = \"clamp\"\nabove = \"quadratic\"\nvalues = [0.0, 1.0, 2.0]\n"
            );
        }
        text += "[[axes]]\nsymbol = \"x\"\nname = \"x\"\nunit = \"-\"\n\
                 below = \"clamp\"\nabove = \"clamp\"\n[data]\ncurves = [\n";
        // 27 curves, each over its own range but the 13th and 14th over the same one.
        for i in 0..27 {
            let start = if i == 13 { 12 } else { i };
            text += &format!(
                "  {{ x = [{start}.0, {}.0], y = [0.0, 1.0] }},\n",
                start + 10
            );
        }
        text += "]\n";
        let chart = parse_chart(&text, "test.toml").unwrap();
        let q = chart.lookup(&[3.0, 3.0, 3.0, -1.0]);
        assert!(q.value.is_some());
        // a, b and c once each (b and c are read in 3 and 9 branches), x once per range.
        let expected = 3 + 26;
        assert!(
            expected > REMEMBERED_WARNINGS,
            "the test must overflow the walk's place"
        );
        assert_eq!(q.warnings.len(), expected, "{:#?}", q.warnings);
        let distinct: std::collections::BTreeSet<String> =
            q.warnings.iter().map(|w| w.to_string()).collect();
        assert_eq!(distinct.len(), q.warnings.len());
    }

    #[test]
    fn snapping_as_glook() {
        let c = grid();
        // Within 0.1 % of x = 1: the node's value, not the interpolated one.
        assert_eq!(c.lookup(&[0.0, 1.0005]).value, Some(1.0));
    }

    /// The snapping test decided by a product agrees with GLOOK's quotient everywhere,
    /// boundaries included.
    #[test]
    fn snapping_without_the_division_is_the_quotient_test() {
        let quotient = |xi: f64, a: f64, tol: f64| {
            let mut scale = if a == 0.0 { xi } else { a };
            if scale.abs() <= 1e-4 {
                scale = 1.0;
            }
            ((a - xi) / scale).abs() < tol
        };
        let mut x: u64 = 0x2545_F491_4F6C_DD1D;
        let mut next = || {
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            (x >> 11) as f64 / (1u64 << 53) as f64
        };
        let tol = 1e-3;
        for _ in 0..200_000 {
            let xi = (next() - 0.5) * 10f64.powi((next() * 12.0) as i32 - 6);
            // Queries at the boundary, within a few units of it, and anywhere near.
            let step = f64::EPSILON * (next() * 8.0 - 4.0).round();
            for a in [
                xi * (1.0 + tol) * (1.0 + step),
                xi * (1.0 - tol) * (1.0 + step),
                xi + tol * (1.0 + step),
                xi * (1.0 + (next() - 0.5) * 4.0 * tol),
                0.0,
            ] {
                assert_eq!(snaps(xi, a, tol), quotient(xi, a, tol), "{xi:e} {a:e}");
            }
        }
    }

    #[test]
    fn bad_arguments_give_no_value() {
        let c = grid();
        assert_eq!(c.lookup(&[0.0]).value, None);
        assert_eq!(c.lookup(&[f64::NAN, 0.0]).value, None);
    }
}
