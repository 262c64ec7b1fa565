//! Property tests of the reader.
//! - Cases generated from the namelist schema, written as a deck and read back, are the same.
//! - Random mutations of real decks (byte flips, deleted and duplicated lines, truncation) are
//!   read and run without panic, and nothing non-finite comes out.

mod common;

use std::collections::BTreeMap;

use datcom::deck::cards::{AirfoilCard, Cards, DerivUnit, Dim, NacaSeries, Surface};
use datcom::deck::schema::{self, Kind};
use datcom::deck::{self, writer, RawCase, Value};
use proptest::prelude::*;

fn number() -> impl Strategy<Value = f64> {
    prop_oneof![
        (-1000i32..1000).prop_map(f64::from),
        -1.0e4f64..1.0e4,
        (-9.0f64..9.0, -30i32..30).prop_map(|(m, e)| m * 10f64.powi(e)),
    ]
}

/// A value for a variable of this kind and length: one run of elements from some index.
fn value(kind: Kind, len: usize) -> BoxedStrategy<Value> {
    (1..=len)
        .prop_flat_map(move |start| (Just(start), 1..=(len - start + 1)))
        .prop_flat_map(move |(start, n)| match kind {
            Kind::Logical => proptest::collection::vec(any::<bool>(), n)
                .prop_map(move |v| {
                    let mut out = vec![None; start - 1];
                    out.extend(v.into_iter().map(Some));
                    Value::Logicals(out)
                })
                .boxed(),
            Kind::Real | Kind::Integer => proptest::collection::vec(number(), n)
                .prop_map(move |v| {
                    let mut out = vec![None; start - 1];
                    out.extend(v.into_iter().map(Some));
                    Value::Numbers(out)
                })
                .boxed(),
        })
        .boxed()
}

fn namelist(name: &'static str) -> BoxedStrategy<(String, BTreeMap<String, Value>)> {
    let spec = schema::namelist(name).expect("known namelist");
    // Count variables (NALPHA, NX, ...) hold whole numbers no larger than their arrays.
    let counts: BTreeMap<String, usize> = spec
        .vars
        .values()
        .filter_map(|v| v.count.as_ref().map(|c| (c.clone(), v.len)))
        .collect();
    // Aliases (ALPHA0 for ALPHAO, ...) are the same variable as their target: left out.
    let vars: Vec<(String, Kind, usize, Option<usize>)> = spec
        .vars
        .values()
        .filter(|v| schema::canonical(name, &v.name) == v.name)
        .map(|v| (v.name.clone(), v.kind, v.len, counts.get(&v.name).copied()))
        .collect();
    proptest::sample::subsequence(vars.clone(), 0..vars.len().min(8))
        .prop_flat_map(move |chosen| {
            let strategies: Vec<_> = chosen
                .into_iter()
                .map(|(n, k, l, count)| match count {
                    Some(max) => (0..=max)
                        .prop_map(move |c| (n.clone(), Value::Numbers(vec![Some(c as f64)])))
                        .boxed(),
                    None => value(k, l).prop_map(move |v| (n.clone(), v)).boxed(),
                })
                .collect();
            strategies.prop_map(move |pairs| (name.to_string(), pairs.into_iter().collect()))
        })
        .boxed()
}

const NAMES: &[&str] = &[
    "FLTCON", "OPTINS", "SYNTHS", "BODY", "WGPLNF", "WGSCHR", "HTPLNF", "HTSCHR", "VTPLNF",
    "VTSCHR", "VFPLNF", "VFSCHR", "SYMFLP", "PROPWR", "JETPWR", "GRNDEF", "TVTPAN", "LARWB",
    "HYPEFF", "TRNJET", "CONTAB", "EXPR01", "EXPR02",
];

fn airfoil() -> impl Strategy<Value = AirfoilCard> {
    let series = prop_oneof![
        (Just(NacaSeries::Four), "[0-9]{4}(-[0-9]{2})?"),
        (Just(NacaSeries::Five), "[0-9]{5}"),
        (Just(NacaSeries::One), "1[0-9]-[0-9]{3}"),
        (Just(NacaSeries::Six), "6[3-6](,[0-9])?-[0-9]{3}"),
        (Just(NacaSeries::Six), "6[3-6]A[0-9]{3}"),
        (
            Just(NacaSeries::Supersonic),
            "[1-3]-[0-9]{2}\\.[0-9]-[0-9]\\.[0-9]"
        ),
    ];
    (
        prop_oneof![
            Just(Surface::Wing),
            Just(Surface::HorizontalTail),
            Just(Surface::VerticalTail),
            Just(Surface::VentralFin)
        ],
        series,
    )
        .prop_map(|(surface, (series, designation))| AirfoilCard {
            surface,
            series,
            designation,
            line: 0,
        })
}

fn case() -> impl Strategy<Value = RawCase> {
    let namelists = proptest::sample::subsequence(NAMES.to_vec(), 1..6)
        .prop_flat_map(|names| names.into_iter().map(namelist).collect::<Vec<_>>());
    (
        namelists,
        proptest::option::of("[A-Z][A-Z0-9 ]{0,30}[A-Z0-9]"),
        prop_oneof![Just(Dim::Ft), Just(Dim::In), Just(Dim::M), Just(Dim::Cm)],
        prop_oneof![Just(DerivUnit::Deg), Just(DerivUnit::Rad)],
        any::<[bool; 4]>(),
        proptest::collection::vec(airfoil(), 0..3),
    )
        .prop_map(|(nls, caseid, dim, deriv, flags, mut airfoils)| {
            // One card per surface: a later card replaces an earlier one.
            airfoils.sort_by_key(|a| a.surface);
            airfoils.dedup_by_key(|a| a.surface);
            RawCase {
                namelists: nls.into_iter().collect(),
                caseid,
                cards: Cards {
                    dim: Some(dim),
                    deriv: Some(deriv),
                    damp: flags[0],
                    build: flags[1],
                    part: flags[2],
                    trim: flags[3],
                    ..Cards::default()
                },
                airfoils,
                ..RawCase::default()
            }
        })
}

/// The largest relative rounding of a number the writer shortens to the 11 characters the
/// original reads: 4 significant digits are left in the worst case (`-1.234E-100`), half a
/// unit of the fourth; for magnitudes 1e-9 to 1e10 at least 6 are (the writer's unit test).
const WRITTEN_ROUNDING: f64 = 5e-4;

/// The case's values as the writer writes them: a number whose exact text fits the 11
/// characters the original reads is itself, a longer one the writer's rounding of it (checked
/// here to lie within [`WRITTEN_ROUNDING`]).
fn as_written(c: &RawCase) -> RawCase {
    let mut c = c.clone();
    for values in c.namelists.values_mut() {
        for v in values.values_mut() {
            if let Value::Numbers(xs) = v {
                for x in xs.iter_mut().flatten() {
                    let written: f64 = writer::number(*x).parse().expect("a number");
                    assert!(
                        (written - *x).abs() <= WRITTEN_ROUNDING * x.abs(),
                        "{x:?} written as {written:?}"
                    );
                    *x = written;
                }
            }
        }
    }
    c
}

/// What a reader can see of a case: namelists, CASEID, control cards, airfoil cards.
type Visible = (
    BTreeMap<String, BTreeMap<String, Value>>,
    Option<String>,
    Cards,
    Vec<(Surface, String)>,
);

fn visible(c: &RawCase) -> Visible {
    let mut a: Vec<(Surface, String)> = c
        .airfoils
        .iter()
        .map(|a| (a.surface, a.designation.clone()))
        .collect();
    a.sort();
    (c.namelists.clone(), c.caseid.clone(), c.cards.clone(), a)
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 256, ..ProptestConfig::default() })]

    #[test]
    fn written_cases_read_back_the_same(cases in proptest::collection::vec(case(), 1..4)) {
        let text = writer::write_deck(&cases);
        let read = deck::read(&text, "generated.dcm");
        let errors: Vec<String> = read.diagnostics.iter().filter(|d| d.is_error()).map(|d| d.to_string()).collect();
        prop_assert!(errors.is_empty(), "{}\n{}", errors.join("\n"), text);
        prop_assert_eq!(read.cases.len(), cases.len(), "{}", text);
        for (want, got) in cases.iter().zip(&read.cases) {
            prop_assert_eq!(visible(&as_written(want)), visible(got), "{}", text);
        }
        for line in text.lines() {
            prop_assert!(line.chars().count() <= deck::CARD_COLUMNS, "long card: {}", line);
        }
    }
}

/// A small deck used when ../shared is absent, so the mutation test still runs.
const FALLBACK: &str = "DIM FT\nDAMP\n $FLTCON NMACH=2.0, MACH(1)=0.2,0.4, NALT=2.0, ALT(1)=0.0,5000.0,\n  NALPHA=3.0, ALSCHD(1)=-2.0,0.0,2.0, LOOP=2.0$\n $OPTINS SREF=180.0, CBARR=5.7, BLREF=33.4$\n $SYNTHS XCG=8.0, ZCG=0.0, XW=5.8, ZW=-2.1, ALIW=0.0$\n $BODY NX=3.0, X(1)=0.0,10.0,20.0, R(1)=0.5,1.5,0.2$\n $WGPLNF CHRDR=7.3, CHRDTP=3.7, SSPN=16.7, SSPNE=14.4, SAVSI=1.0, CHSTAT=0.25, TYPE=1.0$\nNACA-W-4-2412\nCASEID FALLBACK\nSAVE\nNEXT CASE\n $FLTCON NMACH=1.0, VINF(1)=300.0$\n";

fn corpus() -> &'static [Vec<u8>] {
    static DECKS: std::sync::OnceLock<Vec<Vec<u8>>> = std::sync::OnceLock::new();
    DECKS.get_or_init(|| {
        let mut decks = vec![FALLBACK.as_bytes().to_vec()];
        if let Some(dir) =
            common::shared_dir("corpus/decks", "mutated_decks_never_panic (corpus part)")
        {
            decks.extend(
                common::files(&dir)
                    .iter()
                    .filter_map(|p| std::fs::read(p).ok()),
            );
        }
        decks
    })
}

/// Text the mutation test inserts: extreme numbers and stray syntax.
const INSERTS: &[&str] = &[
    "1.E30",
    "-1.E300",
    "1E400",
    "0.0",
    "-0.0",
    "$",
    "(",
    ")",
    "=",
    ",",
    "*",
    "99999999999999999999",
    "1E-400",
    ".TRUE.",
    "NEXT CASE\n",
    "SAVE\n",
    "\r",
];

#[derive(Debug, Clone)]
enum Mutation {
    Flip { at: usize, byte: u8 },
    Insert { at: usize, text: usize },
    DeleteLine(usize),
    DuplicateLine(usize),
    Truncate(usize),
}

fn mutation() -> impl Strategy<Value = Mutation> {
    prop_oneof![
        (any::<usize>(), any::<u8>()).prop_map(|(at, byte)| Mutation::Flip { at, byte }),
        (any::<usize>(), 0..INSERTS.len()).prop_map(|(at, text)| Mutation::Insert { at, text }),
        any::<usize>().prop_map(Mutation::DeleteLine),
        any::<usize>().prop_map(Mutation::DuplicateLine),
        any::<usize>().prop_map(Mutation::Truncate),
    ]
}

fn apply(mut bytes: Vec<u8>, m: &Mutation) -> Vec<u8> {
    if bytes.is_empty() {
        return bytes;
    }
    match *m {
        Mutation::Flip { at, byte } => {
            let i = at % bytes.len();
            bytes[i] = byte;
            bytes
        }
        Mutation::Insert { at, text } => {
            let i = at % bytes.len();
            bytes.splice(i..i, INSERTS[text].bytes());
            bytes
        }
        Mutation::Truncate(at) => {
            bytes.truncate(at % bytes.len());
            bytes
        }
        Mutation::DeleteLine(k) | Mutation::DuplicateLine(k) => {
            let mut lines: Vec<Vec<u8>> =
                bytes.split(|b| *b == b'\n').map(<[u8]>::to_vec).collect();
            let i = k % lines.len();
            if matches!(m, Mutation::DeleteLine(_)) {
                lines.remove(i);
            } else {
                let l = lines[i].clone();
                lines.insert(i, l);
            }
            lines.join(&b'\n')
        }
    }
}

fn assert_finite(results: &datcom::Results) {
    for c in &results.cases {
        for k in &c.conditions {
            let f = &k.condition;
            for v in [
                Some(f.mach),
                f.altitude,
                f.velocity,
                f.pressure,
                f.temperature,
                Some(f.reynolds_per_length),
            ]
            .into_iter()
            .flatten()
            {
                assert!(
                    v.is_finite(),
                    "non-finite flight condition value {v} in {:?}",
                    c.caseid
                );
            }
        }
        let r = &c.reference;
        for v in [r.area, r.chord, r.span, Some(r.xcg), Some(r.zcg)]
            .into_iter()
            .flatten()
        {
            assert!(v.is_finite(), "non-finite reference {v}");
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 512, ..ProptestConfig::default() })]

    #[test]
    fn mutated_decks_never_panic(
        pick in any::<usize>(),
        mutations in proptest::collection::vec(mutation(), 1..6),
    ) {
        let decks = corpus();
        let mut bytes = decks[pick % decks.len()].clone();
        for m in &mutations {
            bytes = apply(bytes, m);
        }
        let text = String::from_utf8_lossy(&bytes);
        let deck = datcom::read_deck(&text, "mutated.dcm");
        let results = datcom::run(&deck);
        assert_finite(&results);
        // Each case written back as a deck and checked (the library's path for a case built
        // in code) whatever the reader kept of it.
        for case in &deck.cases {
            let _ = case.diagnose();
        }
        let _ = datcom::report::text::to_string(&results);
        let _ = datcom::report::json::to_string(&results);
        let _ = datcom::report::csv::to_string(&results);
    }
}
