//! Charts: every embedded file valid; lookups return node values at nodes, stay within the
//! bracketing values inside the data, and warn exactly when a variable leaves the data.

use datcom::charts::{self, parse_chart, Chart};
use proptest::prelude::*;

#[test]
fn every_embedded_chart_is_valid() {
    let bad: Vec<String> = charts::invalid()
        .iter()
        .map(|(f, e)| format!("{f}: {e}"))
        .collect();
    assert!(bad.is_empty(), "{}", bad.join("\n"));
    for c in charts::all() {
        assert!(
            !c.source.figure.is_empty() && !c.source.routine.is_empty(),
            "{}: source",
            c.id
        );
        assert!(!c.axes.is_empty());
    }
}

/// A 1-D or 2-D grid chart in the file format, from generated axes and values.
fn chart_text(axes: &[Vec<f64>], values: &[f64]) -> String {
    let mut s = String::from(
        "id = \"gen\"\ntitle = \"generated\"\noutput = { symbol = \"y\", name = \"y\", unit = \"-\" }\nsource = { figure = \"none\", routine = \"none\", lines = \"none\" }\nnode_tolerance = 0.0\n",
    );
    for (k, x) in axes.iter().enumerate() {
        s.push_str(&format!(
            "[[axes]]\nsymbol = \"x{k}\"\nname = \"x{k}\"\nunit = \"-\"\nbelow = \"clamp\"\nabove = \"linear\"\nvalues = {x:?}\n"
        ));
    }
    s.push_str(&format!("[data]\nvalues = {values:?}\n"));
    s
}

fn axis() -> impl Strategy<Value = Vec<f64>> {
    (
        proptest::collection::vec(0.01f64..10.0, 2..6),
        -50.0f64..50.0,
        any::<bool>(),
    )
        .prop_map(|(steps, start, desc)| {
            let mut x = vec![start];
            for s in steps.iter().take(steps.len() - 1) {
                let last = *x.last().unwrap();
                x.push(last + s);
            }
            if desc {
                x.reverse();
            }
            x
        })
}

fn chart_2d() -> impl Strategy<Value = Chart> {
    (axis(), axis()).prop_flat_map(|(a, b)| {
        let n = a.len() * b.len();
        proptest::collection::vec(-100.0f64..100.0, n).prop_map(move |v| {
            parse_chart(&chart_text(&[a.clone(), b.clone()], &v), "gen.toml").unwrap()
        })
    })
}

fn axes_of(c: &Chart) -> (Vec<f64>, Vec<Vec<f64>>) {
    match &c.data {
        charts::Node::Table { x, nodes } => (
            x.clone(),
            nodes
                .iter()
                .map(|n| match n {
                    charts::Node::Table { nodes, .. } => nodes
                        .iter()
                        .map(|v| match v {
                            charts::Node::Value(v) => *v,
                            charts::Node::Table { .. } => unreachable!(),
                        })
                        .collect(),
                    charts::Node::Value(_) => unreachable!(),
                })
                .collect(),
        ),
        charts::Node::Value(_) => unreachable!(),
    }
}

fn inner_x(c: &Chart) -> Vec<f64> {
    match &c.data {
        charts::Node::Table { nodes, .. } => match &nodes[0] {
            charts::Node::Table { x, .. } => x.clone(),
            charts::Node::Value(_) => unreachable!(),
        },
        charts::Node::Value(_) => unreachable!(),
    }
}

proptest! {
    #[test]
    fn node_values_at_nodes(c in chart_2d()) {
        let (xa, rows) = axes_of(&c);
        let xb = inner_x(&c);
        for (i, a) in xa.iter().enumerate() {
            for (j, b) in xb.iter().enumerate() {
                let l = c.lookup(&[*a, *b]);
                prop_assert_eq!(l.value, Some(rows[i][j]));
                prop_assert!(l.warnings.is_empty());
            }
        }
    }

    #[test]
    fn inside_stays_within_the_cell(c in chart_2d(), fa in 0.0f64..1.0, fb in 0.0f64..1.0) {
        let (xa, rows) = axes_of(&c);
        let xb = inner_x(&c);
        let lerp = |x: &[f64], f: f64| {
            let (lo, hi) = (x.iter().cloned().fold(f64::INFINITY, f64::min), x.iter().cloned().fold(f64::NEG_INFINITY, f64::max));
            lo + f * (hi - lo)
        };
        let (a, b) = (lerp(&xa, fa), lerp(&xb, fb));
        let l = c.lookup(&[a, b]);
        prop_assert!(l.warnings.is_empty(), "{:?}", l.warnings);
        let v = l.value.unwrap();
        // Within the values of the bracketing nodes.
        let bracket = |x: &[f64], q: f64| -> Vec<usize> {
            (0..x.len()).filter(|&i| {
                let others_between = (0..x.len()).any(|k| k != i && x[k] > x[i].min(q) && x[k] < x[i].max(q));
                !others_between
            }).collect()
        };
        let (ia, ib) = (bracket(&xa, a), bracket(&xb, b));
        let cell: Vec<f64> = ia.iter().flat_map(|&i| ib.iter().map(move |&j| (i, j))).map(|(i, j)| rows[i][j]).collect();
        let (lo, hi) = (cell.iter().cloned().fold(f64::INFINITY, f64::min), cell.iter().cloned().fold(f64::NEG_INFINITY, f64::max));
        prop_assert!(v >= lo - 1e-9 && v <= hi + 1e-9, "{v} not in [{lo}, {hi}]");
    }

    #[test]
    fn warns_exactly_when_outside(c in chart_2d(), a in -80.0f64..80.0, b in -80.0f64..80.0) {
        let (xa, _) = axes_of(&c);
        let xb = inner_x(&c);
        let outside = |x: &[f64], q: f64| q < x.iter().cloned().fold(f64::INFINITY, f64::min) || q > x.iter().cloned().fold(f64::NEG_INFINITY, f64::max);
        let l = c.lookup(&[a, b]);
        let vars: Vec<&str> = l.warnings.iter().map(|w| w.variable.as_str()).collect();
        prop_assert_eq!(vars.contains(&"x0"), outside(&xa, a));
        prop_assert_eq!(vars.contains(&"x1"), outside(&xb, b));
        prop_assert!(l.value.is_some_and(f64::is_finite));
    }
}

#[test]
fn malformed_files_are_refused_with_a_reason() {
    let ok = chart_text(&[vec![0.0, 1.0]], &[1.0, 2.0]);
    assert!(parse_chart(&ok, "ok.toml").is_ok());
    let cases = [
        (
            chart_text(&[vec![0.0, 1.0]], &[1.0]),
            "1 values for a grid of 2",
        ),
        (
            chart_text(&[vec![1.0, 0.0, 2.0]], &[1.0, 2.0, 3.0]),
            "not strictly monotone",
        ),
        (
            ok.replace("below = \"clamp\"", "below = \"wrap\""),
            "expected clamp, linear, quadratic or refuse",
        ),
    ];
    for (text, why) in cases {
        let e = parse_chart(&text, "bad.toml").unwrap_err().to_string();
        assert!(e.contains(why), "{e}");
    }
}
