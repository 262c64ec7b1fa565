//! Tabulated curves against angle of attack read the way the original's TBFUNX reads them:
//! linear between nodes; slopes of the parabola through the node pair and a neighbour; beyond
//! the ends as each end says. The build-up methods read the wing, tail and wing-body curves
//! this way (values at angles between the schedule's, and slopes).

/// What a reading does beyond one end of a curve.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum End {
    /// The end value; the slope of the end parabola (TBFUNX LEX ≤ 0). (The original's LEX = 2,
    /// the end parabola's value, is [`End::Quadratic`].)
    Hold,
    /// The chord through the two end points, value and slope (LEX = 1).
    Linear,
    /// The parabola through the three end points, value and slope (LEX = 2).
    Quadratic,
}

/// Value and slope at `at` of the parabola through three points.
fn parabola(x: &[f64], y: &[f64], at: f64) -> Option<(f64, f64)> {
    let (x0, x1, x2) = (x[0], x[1], x[2]);
    let d01 = x0 - x1;
    let d02 = x0 - x2;
    let d12 = x1 - x2;
    if d01 == 0.0 || d02 == 0.0 || d12 == 0.0 {
        return None;
    }
    let value = y[0] * (at - x1) * (at - x2) / (d01 * d02)
        - y[1] * (at - x0) * (at - x2) / (d01 * d12)
        + y[2] * (at - x0) * (at - x1) / (d02 * d12);
    let slope = y[0] * ((at - x1) + (at - x2)) / (d01 * d02)
        - y[1] * ((at - x0) + (at - x2)) / (d01 * d12)
        + y[2] * ((at - x0) + (at - x1)) / (d02 * d12);
    (value.is_finite() && slope.is_finite()).then_some((value, slope))
}

fn chord(x0: f64, x1: f64, y0: f64, y1: f64) -> Option<f64> {
    let h = x1 - x0;
    (h != 0.0).then(|| (y1 - y0) / h).filter(|s| s.is_finite())
}

/// Value and slope of the curve `y(x)` (`x` ascending) at `at`. None where a node the reading
/// uses has no value (a missing value spoils the readings that use it, as a NaN does in the
/// original's, not the whole curve), for an empty curve, or for coincident abscissae where the
/// reading needs them.
pub(crate) fn read(
    x: &[f64],
    y: &[Option<f64>],
    at: f64,
    below: End,
    above: End,
) -> Option<(f64, f64)> {
    let n = x.len().min(y.len());
    let x = &x[..n];
    let y = |i: usize| y[i];
    if !at.is_finite() {
        return None;
    }
    // The parabola through the three nodes from `w`.
    let parabola_from = |w: usize| {
        parabola(
            &[x[w], x[w + 1], x[w + 2]],
            &[y(w)?, y(w + 1)?, y(w + 2)?],
            at,
        )
    };
    match n {
        0 => return None,
        1 => return Some((y(0)?, 0.0)),
        2 => {
            let s = chord(x[0], x[1], y(0)?, y(1)?)?;
            return Some((y(0)? + s * (at - x[0]), s));
        }
        _ => {}
    }
    if at > x[0] && at < x[n - 1] {
        let k = (0..n - 1).rev().find(|&k| at >= x[k]).unwrap_or(0);
        let w = k.max(1) - 1;
        let (_, slope) = parabola_from(w)?;
        let (a, b) = if at < x[1] { (0, 1) } else { (k, k + 1) };
        let s = chord(x[a], x[b], y(a)?, y(b)?)?;
        return Some((y(a)? + s * (at - x[a]), slope));
    }
    let upper = at >= x[n - 1];
    let (w, end, rule) = if upper {
        (n - 3, n - 1, above)
    } else {
        (0, 0, below)
    };
    match rule {
        End::Linear => {
            let s = if upper {
                chord(x[n - 2], x[n - 1], y(n - 2)?, y(n - 1)?)?
            } else {
                chord(x[0], x[1], y(0)?, y(1)?)?
            };
            Some((y(end)? + s * (at - x[end]), s))
        }
        End::Hold => {
            let (_, slope) = parabola_from(w)?;
            Some((y(end)?, slope))
        }
        End::Quadratic => parabola_from(w),
    }
}

/// Slopes of the curve at each of its nodes, the ends read with the end parabola (TBFUNX
/// LEX = 0 at the nodes: what the original's configuration pages print as CLA and CMA).
pub(crate) fn node_slopes(x: &[f64], y: &[Option<f64>]) -> Vec<Option<f64>> {
    x.iter()
        .map(|&at| read(x, y, at, End::Hold, End::Hold).map(|r| r.1))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_missing_value_spoils_only_the_readings_through_it() {
        let x = [0.0, 1.0, 2.0, 3.0, 4.0];
        let mut y: Vec<Option<f64>> = x.iter().map(|v| Some(v * v)).collect();
        y[0] = None;
        let slopes = node_slopes(&x, &y);
        // Nodes 0 and 1 read the parabola through node 0; the others do not.
        assert_eq!(&slopes[..2], &[None, None]);
        for (k, s) in slopes.iter().enumerate().skip(2) {
            let s = s.expect("a slope away from the missing value");
            assert!((s - 2.0 * x[k]).abs() < 1e-12, "node {k}: {s}");
        }
        assert_eq!(read(&x, &y, 0.5, End::Linear, End::Linear), None);
        assert!(read(&x, &y, 2.5, End::Linear, End::Linear).is_some());
    }

    #[test]
    fn a_parabola_is_read_exactly_and_the_ends_as_told() {
        let x = [0.0, 1.0, 2.0, 4.0];
        let y: Vec<Option<f64>> = x.iter().map(|v| Some(1.0 + v * v)).collect();
        // Interior: linear value, parabola slope.
        let (v, s) = read(&x, &y, 1.5, End::Hold, End::Hold).unwrap();
        assert!((v - 3.5).abs() < 1e-12 && (s - 3.0).abs() < 1e-12);
        // Below with the end chord; held above, with the end parabola's slope.
        let (v, s) = read(&x, &y, -1.0, End::Linear, End::Hold).unwrap();
        assert!((v - 0.0).abs() < 1e-12 && (s - 1.0).abs() < 1e-12);
        let (v, s) = read(&x, &y, 5.0, End::Hold, End::Hold).unwrap();
        assert!(v == 17.0 && (s - 10.0).abs() < 1e-12);
        let slopes = node_slopes(&x, &y);
        for (k, s) in slopes.iter().enumerate() {
            assert!((s.unwrap() - 2.0 * x[k]).abs() < 1e-12);
        }
        assert_eq!(
            read(
                &x,
                &[Some(1.0), None, Some(2.0), Some(3.0)],
                1.0,
                End::Hold,
                End::Hold
            ),
            None
        );
    }
}
