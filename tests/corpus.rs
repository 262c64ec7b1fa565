//! Every real deck of ../shared/corpus read without panic, summarised in a snapshot; Missile
//! DATCOM decks refused; decks the original program runs (../shared/oracle) read without errors.
//!
//! The snapshot `tests/snapshots/corpus.txt` records, per deck: cases, the namelists of each
//! case, and the counts of errors and warnings, with the first error. Regenerate it after an
//! intended change with `DATCOM_UPDATE_SNAPSHOTS=1 cargo test --test corpus` and review the diff.

mod common;

use datcom::Diagnosed;
use datcom::{DeckProblem, Severity};

fn summary(name: &str, text: &str) -> String {
    let deck = datcom::read_deck(text, name);
    let mut s = format!(
        "{name}: {} case(s), {} error(s), {} warning(s), {} note(s)\n",
        deck.cases.len(),
        deck.error_count(),
        deck.warning_count(),
        deck.diagnostics
            .iter()
            .filter(|d| d.severity == Severity::Note)
            .count()
    );
    for c in &deck.cases {
        s.push_str(&format!(
            "  case {} (line {}): {}\n",
            c.number,
            c.first_line,
            c.namelist_names().join(" ")
        ));
    }
    if let Some(d) = deck.diagnostics.iter().find(|d| d.is_error()) {
        s.push_str(&format!("  first error: {d}\n"));
    }
    s
}

#[test]
fn corpus_snapshot() {
    let Some(dir) = common::shared_dir("corpus/decks", "corpus_snapshot") else {
        return;
    };
    let decks = common::files(&dir);
    assert_eq!(decks.len(), 98, "the corpus has 98 decks");
    let mut all = String::new();
    let (mut clean, mut warn_only, mut with_errors) = (0, 0, 0);
    for p in &decks {
        let name = p.file_name().unwrap().to_string_lossy().into_owned();
        let text = common::text(p);
        let deck = datcom::read_deck(&text, &name);
        match (deck.error_count(), deck.warning_count()) {
            (0, 0) => clean += 1,
            (0, _) => warn_only += 1,
            _ => with_errors += 1,
        }
        all.push_str(&summary(&name, &text));
    }
    all.push_str(&format!(
        "TOTAL: {clean} clean, {warn_only} with warnings only, {with_errors} with errors\n"
    ));
    let snap = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/snapshots/corpus.txt");
    if std::env::var_os("DATCOM_UPDATE_SNAPSHOTS").is_some() {
        std::fs::write(&snap, &all).expect("write snapshot");
        return;
    }
    let expected = std::fs::read_to_string(&snap).expect("tests/snapshots/corpus.txt exists");
    if expected != all {
        let diff: Vec<String> = expected
            .lines()
            .zip(all.lines())
            .filter(|(a, b)| a != b)
            .take(10)
            .map(|(a, b)| format!("- {a}\n+ {b}"))
            .collect();
        panic!(
            "corpus summary changed (regenerate with DATCOM_UPDATE_SNAPSHOTS=1 if intended):\n{}",
            diff.join("\n")
        );
    }
}

#[test]
fn missile_datcom_decks_are_refused() {
    let Some(dir) = common::shared_dir("corpus/missile", "missile_datcom_decks_are_refused") else {
        return;
    };
    let decks: Vec<_> = common::files(&dir)
        .into_iter()
        .filter(|p| p.file_name().is_some_and(|n| n != "PROVENANCE.tsv"))
        .collect();
    assert_eq!(decks.len(), 11);
    for p in decks {
        let deck = datcom::read_deck(&common::text(&p), &p.display().to_string());
        assert_eq!(deck.cases.len(), 0, "{}", p.display());
        assert_eq!(deck.diagnostics.len(), 1, "{}", p.display());
        let d = &deck.diagnostics[0];
        assert!(
            matches!(d.problem, DeckProblem::MissileDatcom { .. }),
            "{d}"
        );
        assert!(d.to_string().contains("Missile DATCOM"), "{d}");
    }
}

#[test]
fn decks_the_original_runs_read_without_errors() {
    let Some(dir) = common::shared_dir(
        "oracle/cases",
        "decks_the_original_runs_read_without_errors",
    ) else {
        return;
    };
    let mut n = 0;
    for case in std::fs::read_dir(&dir).unwrap().filter_map(Result::ok) {
        let p = case.path().join("input.dcm");
        if !p.is_file() {
            continue;
        }
        n += 1;
        let deck = datcom::read_deck(&common::text(&p), &p.display().to_string());
        let errors: Vec<String> = deck
            .diagnostics
            .iter()
            .filter(|d| d.is_error())
            .map(ToString::to_string)
            .collect();
        assert!(errors.is_empty(), "{}:\n{}", p.display(), errors.join("\n"));
    }
    assert_eq!(n, 42);
}
