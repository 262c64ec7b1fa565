//! Reading speed: the whole ../shared/corpus (98 decks) read and typed, per iteration.
//! Run with `cargo bench --bench read_corpus`. Without ../shared it benchmarks one bundled deck.

use criterion::{criterion_group, criterion_main, Criterion};
use std::hint::black_box;
use std::path::PathBuf;

fn decks() -> Vec<(String, String)> {
    let dir = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../shared/corpus/decks");
    let mut out: Vec<(String, String)> = std::fs::read_dir(&dir)
        .map(|rd| {
            rd.filter_map(Result::ok)
                .filter_map(|e| {
                    let bytes = std::fs::read(e.path()).ok()?;
                    Some((
                        e.file_name().to_string_lossy().into_owned(),
                        String::from_utf8_lossy(&bytes).into_owned(),
                    ))
                })
                .collect()
        })
        .unwrap_or_default();
    if out.is_empty() {
        eprintln!("../shared/corpus/decks is absent: benchmarking the bundled example deck only");
        let p = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("namelists/example-uav.dcm");
        out.push((
            "example-uav.dcm".into(),
            std::fs::read_to_string(p).unwrap_or_default(),
        ));
    }
    out.sort();
    out
}

fn bench(c: &mut Criterion) {
    let decks = decks();
    c.bench_function(&format!("read {} decks", decks.len()), |b| {
        b.iter(|| {
            for (name, text) in &decks {
                black_box(datcom::read_deck(black_box(text), name));
            }
        })
    });
    c.bench_function(
        &format!("read and run {} decks (flight conditions)", decks.len()),
        |b| {
            b.iter(|| {
                for (name, text) in &decks {
                    let deck = datcom::read_deck(black_box(text), name);
                    black_box(datcom::run(&deck));
                }
            })
        },
    );
}

criterion_group!(benches, bench);
criterion_main!(benches);
