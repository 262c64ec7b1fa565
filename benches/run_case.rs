//! Computing speed: one full-aircraft case (../shared/oracle/cases/uav_example, or the bundled
//! example deck without ../shared) read and computed; and a sweep of 10 000 geometry variants
//! (wing semi-span) computed from the library API on every core (rayon): from namelist values
//! (each variant typed and checked as a deck's case is) and from typed cases edited in code.
//! Run with `cargo bench --bench run_case`.

use criterion::{criterion_group, criterion_main, Criterion};
use datcom::deck::{self, Value};
use rayon::prelude::*;
use std::hint::black_box;
use std::path::PathBuf;

fn deck_text() -> (String, String) {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    let oracle = root.join("../shared/oracle/cases/uav_example/input.dcm");
    match std::fs::read_to_string(&oracle) {
        Ok(t) => ("uav_example".into(), t),
        Err(_) => {
            eprintln!("../shared is absent: benchmarking the bundled example deck");
            let t =
                std::fs::read_to_string(root.join("namelists/example-uav.dcm")).unwrap_or_default();
            ("example-uav".into(), t)
        }
    }
}

/// Pages with a lift coefficient: what a sweep computed (a refused variant has pages with
/// none, so counting pages alone would not tell).
fn computed_pages(results: &datcom::CaseResults) -> usize {
    results
        .conditions
        .iter()
        .filter(|c| c.static_coefficients.cl.iter().any(Option::is_some))
        .count()
}

fn bench(c: &mut Criterion) {
    let (name, text) = deck_text();
    c.bench_function(&format!("read and compute one case ({name})"), |b| {
        b.iter(|| {
            let deck = datcom::read_deck(black_box(&text), "bench.dcm");
            black_box(datcom::run(&deck))
        })
    });
    // Variants: the first case with the wing semi-span scaled from 0.8 to 1.2, the exposed
    // semi-span moved with it (the body's width at the wing stays; scaled alone, SSPNE would
    // exceed SSPN below k = 0.94 and the wing would be refused).
    let raw = deck::read(&text, "bench.dcm");
    let Some(base) = raw.cases.first().cloned() else {
        return;
    };
    let variants: Vec<deck::RawCase> = (0..10_000)
        .map(|i| {
            let mut case = base.clone();
            let k = 0.8 + 0.4 * f64::from(i) / 10_000.0;
            if let Some(w) = case.namelists.get_mut("WGPLNF") {
                let first = |w: &deck::NamelistValues, var: &str| match w.get(var) {
                    Some(Value::Numbers(v)) => v.first().copied().flatten(),
                    _ => None,
                };
                if let Some(span) = first(w, "SSPN") {
                    w.insert("SSPN".into(), Value::Numbers(vec![Some(span * k)]));
                    if let Some(exposed) = first(w, "SSPNE") {
                        w.insert(
                            "SSPNE".into(),
                            Value::Numbers(vec![Some(exposed + span * (k - 1.0))]),
                        );
                    }
                }
            }
            case
        })
        .collect();
    // Every variant is an aircraft the methods compute (a refused one would be timed as a
    // shortcut).
    let refused = variants
        .par_iter()
        .filter(|raw| {
            let (case, _) = datcom::Case::from_raw(raw, "variant");
            computed_pages(&datcom::results::run_case(&case)) == 0
        })
        .count();
    assert_eq!(refused, 0, "variants the methods refuse");
    let mut group = c.benchmark_group("sweep");
    group.sample_size(10);
    group.bench_function("10 000 wing-span variants, all cores", |b| {
        b.iter(|| {
            let n: usize = variants
                .par_iter()
                .map(|raw| {
                    let (case, _) = datcom::Case::from_raw(raw, "variant");
                    computed_pages(&datcom::results::run_case(&case))
                })
                .sum();
            black_box(n)
        })
    });
    // The same sweep on typed cases edited in code (a design tool's way: no namelists, no
    // deck checks per variant); the exposed semi-span moves with the span, so the body's width
    // at the wing stays.
    let typed = datcom::read_deck(&text, "bench.dcm");
    if let Some(base) = typed.cases.first() {
        let variants: Vec<datcom::Case> = (0..10_000)
            .map(|i| {
                let mut case = base.clone();
                let k = 0.8 + 0.4 * f64::from(i) / 10_000.0;
                if let Some(w) = case.wing.as_mut() {
                    if let Some(span) = w.sspn {
                        w.sspn = Some(span * k);
                        w.sspne = w.sspne.map(|exposed| exposed + span * (k - 1.0));
                    }
                }
                case
            })
            .collect();
        group.bench_function("10 000 wing-span variants built in code, all cores", |b| {
            b.iter(|| {
                let n: usize = variants
                    .par_iter()
                    .map(|case| computed_pages(&datcom::results::run_case(case)))
                    .sum();
                black_box(n)
            })
        });
    }
    group.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
