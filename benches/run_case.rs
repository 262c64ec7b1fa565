//! Computing speed: one full-aircraft case (../shared/oracle/cases/uav_example, or the bundled
//! example deck without ../shared) read and computed; and a sweep of 10 000 geometry variants
//! (wing semi-span) computed from the library API on every core (rayon).
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

fn bench(c: &mut Criterion) {
    let (name, text) = deck_text();
    c.bench_function(&format!("read and compute one case ({name})"), |b| {
        b.iter(|| {
            let deck = datcom::read_deck(black_box(&text), "bench.dcm");
            black_box(datcom::run(&deck))
        })
    });
    // Variants: the first case with the wing semi-span scaled from 0.8 to 1.2.
    let raw = deck::read(&text, "bench.dcm");
    let Some(base) = raw.cases.first().cloned() else {
        return;
    };
    let variants: Vec<deck::RawCase> = (0..10_000)
        .map(|i| {
            let mut case = base.clone();
            let k = 0.8 + 0.4 * f64::from(i) / 10_000.0;
            if let Some(Value::Numbers(v)) = case
                .namelists
                .get_mut("WGPLNF")
                .and_then(|w| w.get_mut("SSPN"))
            {
                if let Some(Some(s)) = v.first_mut() {
                    *s *= k;
                }
            }
            case
        })
        .collect();
    let mut group = c.benchmark_group("sweep");
    group.sample_size(10);
    group.bench_function("10 000 wing-span variants, all cores", |b| {
        b.iter(|| {
            let n: usize = variants
                .par_iter()
                .map(|raw| {
                    let (case, _) = datcom::Case::from_raw(raw, "variant");
                    datcom::results::run_case(&case).conditions.len()
                })
                .sum();
            black_box(n)
        })
    });
    group.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
