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

/// A listing split where the original lists a case's input cards: one text per case.
pub fn case_listings(text: &str) -> Vec<String> {
    let mut out: Vec<String> = Vec::new();
    for line in text.lines() {
        if line.contains("LIST OF ALL INPUT CARDS FOR THIS CASE") {
            out.push(String::new());
        }
        if let Some(last) = out.last_mut() {
            last.push_str(line);
            last.push('\n');
        }
    }
    out
}

/// The oracle cases (../shared/oracle/cases/<name>/ with input.dcm and for006.dat), sorted by
/// name, whose listing prints one of the `pages` (any page when empty): (name, deck text,
/// listing text). `None` after printing why `test` is skipped when the oracle is absent.
pub fn oracle_cases(test: &str, pages: &[&str]) -> Option<Vec<(String, String, String)>> {
    let dir = shared_dir("oracle/cases", test)?;
    let mut dirs: Vec<_> = std::fs::read_dir(&dir)
        .ok()?
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.is_dir())
        .collect();
    dirs.sort();
    let mut out = Vec::new();
    for d in dirs {
        let (deck, listing) = (d.join("input.dcm"), d.join("for006.dat"));
        if !deck.is_file() || !listing.is_file() {
            continue;
        }
        let listing = text(&listing);
        if !pages.is_empty() && !pages.iter().any(|p| listing.contains(p)) {
            continue;
        }
        let name = d.file_name().unwrap().to_string_lossy().into_owned();
        out.push((name, text(&deck), listing));
    }
    Some(out)
}

/// [`oracle_cases`] with each deck read.
pub fn oracle_decks(
    test: &str,
    pages: &[&str],
) -> Option<Vec<(String, datcom::case::Deck, String)>> {
    let cases = oracle_cases(test, pages)?;
    Some(
        cases
            .into_iter()
            .map(|(name, deck, listing)| {
                let deck = datcom::read_deck(&deck, &name);
                (name, deck, listing)
            })
            .collect(),
    )
}

/// Spot values of charts read off the original's DATA statements: (chart id, arguments,
/// value at a node).
pub type Spots = &'static [(&'static str, &'static [f64], f64)];

/// Every chart of `ids` is embedded and has at least two spot values, and every spot value is
/// the chart's value at its node, read without a warning.
pub fn check_chart_spots<'a>(ids: impl IntoIterator<Item = &'a str>, spots: Spots) {
    for id in ids {
        assert!(datcom::charts::get(id).is_some(), "chart {id} is embedded");
        assert!(
            spots.iter().filter(|s| s.0 == id).count() >= 2,
            "chart {id} has spot values"
        );
    }
    for (id, args, expected) in spots {
        let l = datcom::charts::get(id).expect("chart").lookup(args);
        assert_eq!(l.value, Some(*expected), "{id} at {args:?}");
        assert!(l.warnings.is_empty(), "{id} at {args:?}: {:?}", l.warnings);
    }
}

/// `deck` under a section rule as the oracle tests tally it: with
/// `SectionReynolds::Original`, the original program's rules (its section Reynolds number and
/// its reading of NACA 5-digit designations, `Deck::with_original_rules`); else the library's.
pub fn under_rule(
    deck: datcom::case::Deck,
    rule: datcom::case::SectionReynolds,
) -> datcom::case::Deck {
    match rule {
        datcom::case::SectionReynolds::Original => deck.with_original_rules(),
        other => deck.with_section_reynolds(other),
    }
}

/// One downwash table: Mach of its page, the page's configuration, line of its header in the
/// case's listing, rows (alpha, q/q∞, ε, dε/dα; none where not a number).
pub struct DownwashTable {
    pub mach: f64,
    pub configuration: String,
    pub line: usize,
    pub rows: Vec<[Option<f64>; 4]>,
}

/// The downwash tables of a case's listing (the legacy importer does not read them).
pub fn downwash_tables(listing: &str) -> Vec<DownwashTable> {
    let lines: Vec<&str> = listing.lines().collect();
    let mut out = Vec::new();
    let mut mach = None;
    let mut configuration = String::new();
    let mut after_header = false;
    let mut i = 0;
    while i < lines.len() {
        let line = lines[i];
        if line.contains("CHARACTERISTICS AT ANGLE OF ATTACK") {
            configuration = lines.get(i + 1).map_or("", |s| s.trim()).to_string();
        }
        if line.contains("FLIGHT CONDITIONS") {
            after_header = true;
        } else if after_header && line.starts_with('0') {
            mach = line.get(1..8).and_then(|s| s.trim().parse::<f64>().ok());
            after_header = false;
        }
        if line.contains("D(EPSLON)/D(ALPHA)") {
            let header = i + 1;
            let mut rows = Vec::new();
            i += 1;
            while i < lines.len() {
                let t = lines[i].trim();
                if t == "0" || t.is_empty() {
                    if !rows.is_empty() {
                        break;
                    }
                    i += 1;
                    continue;
                }
                let tokens: Vec<&str> = t.split_whitespace().collect();
                if tokens.len() != 4 || tokens[0].parse::<f64>().is_err() {
                    break;
                }
                let mut r = [None; 4];
                for (k, tok) in tokens.iter().enumerate() {
                    r[k] = tok.parse::<f64>().ok();
                }
                rows.push(r);
                i += 1;
            }
            if let Some(m) = mach {
                out.push(DownwashTable {
                    mach: m,
                    configuration: configuration.clone(),
                    line: header,
                    rows,
                });
            }
            continue;
        }
        i += 1;
    }
    out
}
