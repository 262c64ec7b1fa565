//! Shared test helpers: where ../shared is, and a clear skip when it is absent.

#![allow(dead_code)]

use std::path::PathBuf;

/// `../shared` relative to the crate root, when present.
pub fn shared() -> Option<PathBuf> {
    let p = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../shared");
    p.is_dir().then_some(p)
}

/// The `../shared/<sub>` directory, or `None` after printing why the test is skipped.
pub fn shared_dir(sub: &str, test: &str) -> Option<PathBuf> {
    match shared().map(|s| s.join(sub)) {
        Some(p) if p.is_dir() => Some(p),
        _ => {
            eprintln!("SKIPPED {test}: ../shared/{sub} is absent (the project's shared data is not checked out next to the crate)");
            None
        }
    }
}

/// Files of a directory, sorted by name.
pub fn files(dir: &std::path::Path) -> Vec<PathBuf> {
    let mut v: Vec<PathBuf> = std::fs::read_dir(dir)
        .map(|rd| {
            rd.filter_map(|e| e.ok().map(|e| e.path()))
                .filter(|p| p.is_file())
                .collect()
        })
        .unwrap_or_default();
    v.sort();
    v
}

/// Reads a file as text, replacing invalid UTF-8 (some decks are Latin-1).
pub fn text(path: &std::path::Path) -> String {
    String::from_utf8_lossy(&std::fs::read(path).expect("readable file")).into_owned()
}
