//! Chart files against their sources: values written down here by hand from the source each
//! chart names (a NACA report table or a DATA statement / assignment of datcom.f at the lines
//! the chart cites), looked up through the chart. A chart file edited by mistake fails here.

use datcom::charts;

/// Values are copied exactly; lookups at nodes return them exactly (up to f64 parsing).
const EXACT: f64 = 1e-12;

fn at(id: &str, args: &[f64]) -> f64 {
    let c = charts::get(id).unwrap_or_else(|| panic!("chart {id} is embedded"));
    let l = c.lookup(args);
    assert!(l.warnings.is_empty(), "{id} {args:?}: {:?}", l.warnings);
    l.value.unwrap_or_else(|| panic!("{id} {args:?}: no value"))
}

fn check(id: &str, cases: &[(&[f64], f64)]) {
    for (args, want) in cases {
        let got = at(id, args);
        assert!(
            (got - want).abs() <= EXACT,
            "{id} {args:?}: {got} != {want}"
        );
    }
}

#[test]
fn five_digit_mean_line_constants_are_nacas() {
    // Abbott & von Doenhoff, Theory of Wing Sections, section 6.4 (and NASA TM-4741 p. 8):
    // mean lines 210, 220, 230, 240, 250: m = 0.0580, 0.1260, 0.2025, 0.2900, 0.3910;
    // k1 = 361.4, 51.64, 15.957, 6.643, 3.230. Reflexed 221, 231, 241, 251: m = 0.1300,
    // 0.2170, 0.3180, 0.4410; k1 = 51.990, 15.793, 6.520, 3.191.
    check(
        "airfoil-5digit-m",
        &[
            (&[0.0, 0.05], 0.0580),
            (&[0.0, 0.15], 0.2025),
            (&[0.0, 0.25], 0.3910),
            (&[1.0, 0.15], 0.2170),
            (&[1.0, 0.25], 0.4410),
        ],
    );
    check(
        "airfoil-5digit-k1",
        &[
            (&[0.0, 0.05], 361.4),
            (&[0.0, 0.15], 15.957),
            (&[0.0, 0.25], 3.230),
            (&[1.0, 0.15], 15.793),
        ],
    );
}

#[test]
fn modified_four_digit_trailing_edge_slope_is_nacas() {
    // Abbott & von Doenhoff, section 6.4: d1 = 0.200, 0.234, 0.315, 0.465, 0.700 for t = 0.20
    // at maximum-thickness positions 0.2 ... 0.6, i.e. d1/t = 1.0, 1.17, 1.575, 2.325, 3.5.
    check(
        "airfoil-modified-4digit-d1",
        &[(&[0.2], 1.0), (&[0.4], 1.575), (&[0.6], 3.5)],
    );
}

#[test]
fn six_series_fit_constants_are_the_originals() {
    // datcom.f COORD6 lines 6079-6103: series 3: ZT=.35, SM=-.6116, R0=.46; series 4: ZT=.40,
    // SM=-.6888, R0=.523; series 5: ZT=.4, SM=-.8833, R0=.65; other: ZT=.45, SM=-1.268,
    // R0=.873; 6A trailing-edge slope D1 = T, 1.04 T, 1.17 T for series 3, 4, 5.
    check(
        "airfoil-6series-zt",
        &[(&[3.0], 0.35), (&[4.0], 0.40), (&[6.0], 0.45)],
    );
    check(
        "airfoil-6series-sm",
        &[(&[3.0], -0.6116), (&[5.0], -0.8833), (&[6.0], -1.268)],
    );
    check(
        "airfoil-6series-r0",
        &[(&[4.0], 0.523), (&[5.0], 0.65), (&[7.0], 0.873)],
    );
    check(
        "airfoil-6a-d1",
        &[(&[3.0], 1.0), (&[4.0], 1.04), (&[5.0], 1.17)],
    );
}

#[test]
fn stations_are_the_originals_single_precision_sums() {
    // datcom.f DECODE lines 7219-7230: X(1) = 0, steps of 0.001 summed in REAL*4 (X(11) is the
    // float nearest 0.0100000007), then 0.01 (X(12) = 0.019999999552965164 as f32 sums it),
    // X(60) = 1.0 exactly.
    check(
        "airfoil-stations",
        &[
            (&[1.0], 0.0),
            (&[2.0], f64::from(0.001f32)),
            (&[11.0], 0.010000000707805157),
            (&[12.0], 0.019999999552965164),
            (&[60.0], 1.0),
        ],
    );
}
