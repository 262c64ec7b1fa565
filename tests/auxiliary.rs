//! The PART card's CONFIGURATION AUXILIARY AND PARTIAL OUTPUT against the original: every
//! oracle deck with PART is run (original rules) and written as a listing (`--format for006`);
//! on both listings the pages' records are read (BASIC BODY PROPERTIES line, XCG relative to
//! the MAC, each TOTAL THEORITICAL / TOTAL EXPOSED planform row, the CLA-B(W) and CLA-B(H)
//! interference lines, the sidewash, the body-vortex table, the
//! dynamic-derivative increments with CLB/GAMMA and the twist terms) and compared number by number for the flight conditions at Mach ≤ 0.6.
//!
//! Known defects of the original left out of the comparison (docs/differences.md): the
//! ventral fin's rows (the fin takes the vertical tail's sweep), and the theoretical sweep of a
//! planform of TYPE other than 1 (arc cosine of area-weighted cosines, the vertical tail's
//! inboard area not halved).

mod common;

use std::collections::BTreeMap;

/// The agreement rule: within 2 % or one unit in the last printed digit.
const RELATIVE: f64 = 0.02;
/// Bar for each kind of record: the 95 %.
const BAR: f64 = 0.95;
/// Misses in all, at most: the three exposed zero-lift drags at Mach 0.036 to 0.059 that
/// docs/output.md explains (the R_LS reading); any other is a regression.
const EXPLAINED_MISSES: usize = 3;

/// Records of one case's listing: key (condition line, occurrence, record) → printed tokens.
fn records(listing: &str) -> BTreeMap<(String, usize, String), Vec<String>> {
    let mut out = BTreeMap::new();
    let mut seen: BTreeMap<String, usize> = BTreeMap::new();
    let lines: Vec<&str> = listing.lines().collect();
    let (mut in_aux, mut condition, mut surface) = (false, String::new(), String::new());
    let mut occurrence = 0;
    for (i, l) in lines.iter().enumerate() {
        if l.starts_with('1') {
            in_aux = lines
                .get(i + 1)
                .is_some_and(|n| n.contains("CONFIGURATION AUXILIARY AND PARTIAL OUTPUT"));
            continue;
        }
        if !in_aux {
            continue;
        }
        if l.contains("FLIGHT CONDITIONS") {
            // The condition row: four lines below, its Mach number and altitude.
            let row = lines.get(i + 4).copied().unwrap_or("");
            condition = row.get(..20).unwrap_or(row).trim().to_string();
            let n = seen.entry(condition.clone()).or_insert(0);
            *n += 1;
            occurrence = *n;
            continue;
        }
        let t = l.trim();
        let mut put = |record: String, tokens: Vec<String>| {
            out.insert((condition.clone(), occurrence, record), tokens);
        };
        if t.starts_with("WETTED AREA") {
            if let Some(v) = lines.get(i + 1) {
                put(
                    "body".into(),
                    v.split_whitespace().map(String::from).collect(),
                );
            }
        } else if let Some(v) = t.strip_prefix("XCG RELATIVE TO THEORETICAL LEADING EDGE MAC=") {
            put("xcg".into(), vec![v.trim().to_string()]);
        } else if l.starts_with('0')
            && ["WING", "HORIZONTAL TAIL", "VERTICAL TAIL", "VENTRAL FIN"]
                .contains(&t.trim_start_matches('0').trim())
        {
            surface = t.trim_start_matches('0').trim().to_string();
        } else if t == "TOTAL THEORITICAL" || t == "TOTAL EXPOSED" {
            if let Some(v) = lines.get(i + 1).filter(|d| d.starts_with('+')) {
                put(
                    format!("{surface} {t}"),
                    v[1..].split_whitespace().map(String::from).collect(),
                );
            }
        } else if let Some((surface, t)) = ["W", "H"].iter().find_map(|s| {
            let t = t.trim_start_matches('0').trim_start();
            t.starts_with(&format!("CLA-B({s})=")).then_some((s, t))
        }) {
            let tokens = t
                .split('=')
                .skip(1)
                .filter_map(|p| p.split_whitespace().next().map(String::from))
                .collect();
            put(format!("interference {surface}"), tokens);
        } else if let Some(v) = t.split("QV/Q =").nth(1) {
            put("sidewash".into(), vec![v.trim().to_string()]);
        } else if t.starts_with("CLP(GAMMA=CL=0) =") {
            let after = |line: &str| -> Vec<String> {
                line.split('=')
                    .skip(1)
                    .filter_map(|p| p.split_whitespace().next().map(String::from))
                    .collect()
            };
            let mut tokens = after(t);
            tokens.extend(after(lines.get(i + 1).copied().unwrap_or("")));
            put("increments".into(), tokens);
        } else if t.starts_with("ALPHA") && t.contains("IV-B(W)") {
            // Fixed columns, one record per row.
            for row in lines.iter().skip(i + 2) {
                let cell = |left: usize, right: usize| {
                    row.get(left..right.min(row.len()))
                        .unwrap_or("")
                        .trim()
                        .to_string()
                };
                let alpha = cell(0, 22);
                if alpha.parse::<f64>().is_err() {
                    break;
                }
                put(
                    format!("vortex {alpha}"),
                    vec![
                        cell(22, 39),
                        cell(39, 56),
                        cell(56, 73),
                        cell(73, 90),
                        cell(90, 115),
                    ],
                );
            }
        } else if t.starts_with("CLB/GAMMA") {
            if let Some(v) = lines.get(i + 1) {
                put(
                    "clb and twist".into(),
                    v.split_whitespace().map(String::from).collect(),
                );
            }
        }
    }
    out
}

fn mach(condition: &str) -> Option<f64> {
    condition
        .trim_start_matches('0')
        .split_whitespace()
        .next()?
        .parse()
        .ok()
}

fn agrees(printed: &str, ours: &str) -> bool {
    let (Ok(p), Ok(o)) = (printed.parse::<f64>(), ours.parse::<f64>()) else {
        return false;
    };
    let unit = datcom::report::legacy::last_digit_unit(printed);
    (p - o).abs() <= (RELATIVE * p.abs()).max(unit) + 1e-12
}

/// Records left out: the original's defects (module documentation).
fn known_defect(deck: &datcom::case::Case, record: &str, column: usize) -> bool {
    if record.starts_with("VENTRAL FIN") {
        return true;
    }
    let planform = match record.split(" TOTAL").next() {
        Some("WING") => deck.wing.as_ref(),
        Some("HORIZONTAL TAIL") => deck.horizontal_tail.as_ref(),
        Some("VERTICAL TAIL") => deck.vertical_tail.as_ref(),
        _ => None,
    };
    let type1 = planform
        .and_then(|p| p.planform_type)
        .is_none_or(|t| (t + 0.5).floor() == 1.0);
    record.ends_with("TOTAL THEORITICAL") && column == 3 && !type1
}

#[test]
fn part_pages_agree_with_the_original() {
    let Some(decks) = common::oracle_cases("auxiliary (PART pages)", &["AUXILIARY AND PARTIAL"])
    else {
        return;
    };
    // Per record kind: (matched, compared).
    let mut tally: BTreeMap<String, (usize, usize)> = BTreeMap::new();
    let mut misses = Vec::new();
    let mut decks_compared = 0;
    for (name, text, listing) in &decks {
        let deck = datcom::read_deck(text, name).with_original_rules();
        let ours = datcom::report::for006::to_string(&datcom::run(&deck));
        let (theirs, ours) = (common::case_listings(listing), common::case_listings(&ours));
        decks_compared += 1;
        for (k, (t, o)) in theirs.iter().zip(&ours).enumerate() {
            let Some(case) = deck.cases.get(k) else {
                continue;
            };
            let ours = records(o);
            for (key, printed) in records(t) {
                if mach(&key.0).is_none_or(|m| m > 0.6) {
                    continue;
                }
                let kind = match key.2.as_str() {
                    r if r.starts_with("vortex") => "vortex table".to_string(),
                    "body" | "xcg" | "sidewash" | "increments" | "clb and twist" => key.2.clone(),
                    r => r.split(" TOTAL").next().unwrap_or(r).to_lowercase(),
                };
                let mine = ours.get(&key);
                for (j, p) in printed.iter().enumerate() {
                    // Text (NA, NDM) and the original's NaN (ORACLE.md) are not numbers to match.
                    let printed = p.parse::<f64>().ok().filter(|v| v.is_finite());
                    if printed.is_none() || known_defect(case, &key.2, j) {
                        continue;
                    }
                    let o = mine.and_then(|m| m.get(j));
                    let ok = o.is_some_and(|o| agrees(p, o));
                    let entry = tally.entry(kind.clone()).or_default();
                    entry.1 += 1;
                    entry.0 += usize::from(ok);
                    if !ok {
                        misses.push(format!(
                            "{name} case {} [{}] {} #{j}: printed {p}, ours {:?}",
                            k + 1,
                            key.0,
                            key.2,
                            o
                        ));
                    }
                }
            }
        }
    }
    let (mut matched, mut total) = (0, 0);
    for (kind, (m, n)) in &tally {
        eprintln!("{kind:>16}: {m} / {n}");
        matched += m;
        total += n;
    }
    eprintln!("PART pages, Mach <= 0.6, {decks_compared} decks: {matched} / {total}");
    for m in &misses {
        eprintln!("  miss: {m}");
    }
    assert!(
        decks_compared >= 20,
        "only {decks_compared} decks with PART"
    );
    for (kind, (m, n)) in &tally {
        assert!(*m as f64 >= BAR * *n as f64, "{kind}: {m} / {n}");
    }
    assert!(
        total - matched <= EXPLAINED_MISSES,
        "{} misses, {EXPLAINED_MISSES} explained",
        total - matched
    );
}

/// With BUILD the component pages come first; only the case's own configuration carries the
/// PART output, and without PART no page does. Needs no ../shared (the bundled example deck).
#[test]
fn part_output_is_on_the_case_configuration_only() {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("namelists/example-uav.dcm");
    let deck_text = common::text(&path);
    let with = |cards: &str| {
        let deck = datcom::read_deck(&format!("{cards}{deck_text}"), "example-uav.dcm");
        datcom::run(&deck)
    };
    let plain = with("BUILD\n");
    assert!(
        plain.cases[0].conditions.len() > 1,
        "BUILD gives component pages"
    );
    assert!(plain.cases[0]
        .conditions
        .iter()
        .all(|c| c.auxiliary.is_none()));
    let part = with("BUILD\nPART\n");
    let case = &part.cases[0];
    let own = case.most_complete();
    let with_part = case
        .conditions
        .iter()
        .filter(|c| c.auxiliary.is_some())
        .count();
    assert_eq!(with_part, own.len(), "one page per flight condition");
    for c in own {
        let a = c
            .auxiliary
            .as_ref()
            .expect("PART output on the own configuration");
        assert!(a.body.is_some() && a.wing_body.is_some());
        assert!(a.planforms.len() >= 3, "wing and tails");
    }
    let listing = datcom::report::for006::to_string(&part);
    assert!(listing.contains("CONFIGURATION AUXILIARY AND PARTIAL OUTPUT"));
    assert!(listing.contains("CLA-B(W)="));
}

/// Half a unit in the last digit of the listing's formats, relative: E formats print 3 or 4
/// significant digits (0.ddd at worst 0.100, so 5e-3).
const PRINTED_RELATIVE: f64 = 5e-3;
/// F formats: XCG on the MAC F7.2, taper ratio and sweep F.3, base area F.4: half a unit.
const PRINTED_ABSOLUTE: [(&str, f64); 4] = [
    ("xcg_behind_mac_leading_edge", 0.005),
    ("taper_ratio", 0.0005),
    ("quarter_chord_sweep", 0.0005),
    ("base_area", 0.00005),
];

/// Every number of `ours` equals the same field of `back` within the printed precision.
fn same_within_print(
    ours: &serde_json::Value,
    back: &serde_json::Value,
    path: &str,
) -> Vec<String> {
    use serde_json::Value;
    match (ours, back) {
        (Value::Object(a), Value::Object(b)) => a
            .iter()
            .flat_map(|(k, v)| {
                same_within_print(v, b.get(k).unwrap_or(&Value::Null), &format!("{path}.{k}"))
            })
            .collect(),
        (Value::Array(a), Value::Array(b)) if a.len() == b.len() => a
            .iter()
            .zip(b)
            .enumerate()
            .flat_map(|(i, (x, y))| same_within_print(x, y, &format!("{path}[{i}]")))
            .collect(),
        (Value::Number(x), Value::Number(y)) => {
            let (x, y) = (
                x.as_f64().unwrap_or(f64::NAN),
                y.as_f64().unwrap_or(f64::NAN),
            );
            let absolute = PRINTED_ABSOLUTE
                .iter()
                .find(|(k, _)| path.ends_with(k))
                .map_or(0.0, |(_, a)| *a);
            let ok = (x - y).abs() <= PRINTED_RELATIVE * x.abs() + absolute;
            if ok {
                Vec::new()
            } else {
                vec![format!("{path}: ours {x}, read back {y}")]
            }
        }
        (a, b) if a == b => Vec::new(),
        (a, b) => vec![format!("{path}: ours {a}, read back {b}")],
    }
}

/// Our listing's PART pages read back by the importer give our JSON's `auxiliary` numbers.
#[test]
fn part_pages_read_back_to_our_numbers() {
    let Some(decks) =
        common::oracle_cases("auxiliary (PART round trip)", &["AUXILIARY AND PARTIAL"])
    else {
        return;
    };
    let (mut blocks, mut problems) = (0, Vec::new());
    for (name, text, _) in &decks {
        let deck = datcom::read_deck(text, name).with_original_rules();
        let results = datcom::run(&deck);
        let ours: serde_json::Value =
            serde_json::to_value(datcom::report::json::view(&results)).unwrap();
        let listing = datcom::report::for006::to_string(&results);
        let back: serde_json::Value =
            serde_json::from_str(&datcom::report::json::listing_to_string(&listing, name)).unwrap();
        for (ci, case) in ours["cases"].as_array().unwrap().iter().enumerate() {
            // Our listing prints one page per condition and configuration, as `run` lists them.
            let conditions = case["conditions"].as_array().unwrap();
            let read = back["cases"][ci]["conditions"]
                .as_array()
                .cloned()
                .unwrap_or_default();
            for (k, c) in conditions.iter().enumerate() {
                let Some(a) = c.get("auxiliary") else {
                    continue;
                };
                blocks += 1;
                let b = read.get(k).and_then(|r| r.get("auxiliary")).cloned();
                match b {
                    Some(b) => problems.extend(same_within_print(
                        a,
                        &b,
                        &format!("{name} case {} condition {k}", ci + 1),
                    )),
                    None => problems.push(format!(
                        "{name} case {} condition {k}: not read back",
                        ci + 1
                    )),
                }
            }
        }
    }
    eprintln!(
        "PART blocks read back: {blocks}, problems: {}",
        problems.len()
    );
    assert!(blocks >= 29, "only {blocks} blocks");
    assert!(problems.is_empty(), "{}", problems.join("\n"));
}
