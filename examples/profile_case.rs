//! A deck read and computed many times over, for profilers (callgrind, DHAT, perf): the work
//! of `benches/run_case.rs`'s single-case benchmark without criterion's own code around it.
//! Prints the mean wall-clock time per case (a rough figure: the benchmark is the measure).
//!
//! ```text
//! cargo build --profile bench --example profile_case
//! valgrind --tool=callgrind target/release/examples/profile_case DECK 200
//! ```
//!
//! Instructions per case: the difference between runs of 400 and 200 cases, divided by 200
//! (the charts are read once, on first use; the difference leaves that out). docs/performance.md.

use std::time::Instant;

/// Cases computed when the command line gives no count.
const DEFAULT_REPEATS: usize = 1000;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let mut args = std::env::args().skip(1);
    let path = args
        .next()
        .unwrap_or_else(|| "namelists/example-uav.dcm".into());
    let repeats = match args.next() {
        Some(n) => n
            .parse::<usize>()
            .map_err(|e| format!("repeat count {n:?}: {e}"))?,
        None => DEFAULT_REPEATS,
    };
    let text = std::fs::read_to_string(&path).map_err(|e| format!("{path}: {e}"))?;
    let start = Instant::now();
    let mut pages = 0usize;
    for _ in 0..repeats {
        let deck = datcom::read_deck(std::hint::black_box(&text), &path);
        let results = datcom::run(&deck);
        pages += std::hint::black_box(&results)
            .cases
            .iter()
            .map(|c| c.conditions.len())
            .sum::<usize>();
    }
    let elapsed = start.elapsed();
    if repeats > 0 {
        eprintln!(
            "{path}: {repeats} runs, {pages} pages, {:.1} µs per run",
            elapsed.as_secs_f64() * 1e6 / repeats as f64
        );
    }
    Ok(())
}
