//! Coefficient-by-coefficient agreement between two results in the JSON shape of `run` (ours,
//! or a listing of the original read by [`super::legacy`]), number by number.
//!
//! A number agrees when it is within max(2 %, one unit in the last digit the original prints
//! for that column) of the reference: F9.3 for CD, CL, CN, CA, XCP; F9.4 for CM; three
//! decimals of the mantissa for derivatives (E format). This is the measure the method issues
//! use.

use serde::Serialize;
use serde_json::Value;

/// Relative agreement accepted for any number.
pub const RELATIVE: f64 = 0.02;

/// One unit in the last digit the original prints for `column` at value `v`.
pub fn printed_unit(column: &str, v: f64) -> f64 {
    match column {
        "CD" | "CL" | "CN" | "CA" | "XCP" => 1e-3,
        // The downwash table's F.3 fields.
        "Q/QINF" | "EPSLON" | "D(EPSLON)/D(ALPHA)" => 1e-3,
        "CM" => 1e-4,
        _ => {
            if v == 0.0 {
                1e-3
            } else {
                10f64.powi(v.abs().log10().floor() as i32 - 3)
            }
        }
    }
}

/// Whether `ours` agrees with `reference` for `column`.
pub fn agrees(column: &str, ours: f64, reference: f64) -> bool {
    let tol = (RELATIVE * reference.abs()).max(printed_unit(column, reference));
    (ours - reference).abs() <= tol * (1.0 + 1e-9)
}

/// Agreement of one coefficient.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ColumnAgreement {
    pub coefficient: String,
    /// Numbers both sides have.
    pub compared: usize,
    pub agreeing: usize,
    /// Numbers the reference has and we do not.
    pub missing: usize,
    /// Largest difference, where: (|ours − reference|, case, condition, alpha, ours, reference).
    pub worst: Option<Worst>,
}

#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Worst {
    pub difference: f64,
    pub case: usize,
    pub condition: usize,
    pub alpha: f64,
    pub ours: f64,
    pub reference: f64,
    /// For the PART blocks: the quantity within the block (`planforms[1].exposed.area`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub field: Option<String>,
}

impl ColumnAgreement {
    fn new(coefficient: &str) -> Self {
        ColumnAgreement {
            coefficient: coefficient.to_string(),
            compared: 0,
            agreeing: 0,
            missing: 0,
            worst: None,
        }
    }

    /// Counts one reference number: missing when we have none, else compared (agreeing when
    /// `agree` says so), keeping the largest difference with its place (case, condition,
    /// angle, PART field) from `place`.
    fn count(
        &mut self,
        ours: Option<f64>,
        reference: f64,
        agree: impl Fn(f64) -> bool,
        place: impl FnOnce() -> (usize, usize, f64, Option<String>),
    ) {
        let Some(o) = ours else {
            self.missing += 1;
            return;
        };
        self.compared += 1;
        if agree(o) {
            self.agreeing += 1;
        }
        let d = (o - reference).abs();
        if self.worst.as_ref().is_none_or(|w| d > w.difference) {
            let (case, condition, alpha, field) = place();
            self.worst = Some(Worst {
                difference: d,
                case,
                condition,
                alpha,
                ours: o,
                reference,
                field,
            });
        }
    }

    pub fn fraction(&self) -> f64 {
        if self.compared + self.missing == 0 {
            1.0
        } else {
            self.agreeing as f64 / (self.compared + self.missing) as f64
        }
    }
}

const STATIC: [&str; 11] = [
    "CD", "CL", "CM", "CN", "CA", "XCP", "CLA", "CMA", "CYB", "CNB", "CLB",
];
const DYNAMIC: [&str; 9] = [
    "CLQ", "CMQ", "CLAD", "CMAD", "CLP", "CYP", "CNP", "CNR", "CLR",
];
const DOWNWASH: [&str; 3] = ["Q/QINF", "EPSLON", "D(EPSLON)/D(ALPHA)"];
/// Prefix of the rows of the PART card's blocks (`auxiliary`), one row per block.
const PART: &str = "PART ";

/// Whether a PART number agrees: as [`agrees`], with one unit of the fixed-point formats the
/// original prints some of them in (XCG on the MAC F7.2; taper ratio and sweep F.3; base area
/// F.4), the others E formats.
fn part_agrees(block: &str, path: &str, ours: f64, reference: f64) -> bool {
    let fixed = if block == "xcg_behind_mac_leading_edge" {
        Some(1e-2)
    } else if path.ends_with("taper_ratio") || path.ends_with("quarter_chord_sweep") {
        Some(1e-3)
    } else if path.ends_with("base_area") {
        Some(1e-4)
    } else {
        None
    };
    match fixed {
        Some(unit) => {
            let tol = (RELATIVE * reference.abs()).max(unit);
            (ours - reference).abs() <= tol * (1.0 + 1e-9)
        }
        None => agrees(&format!("{PART}{block}"), ours, reference),
    }
}

/// Every number under `v` with its path.
fn leaves(v: &Value, path: &str, out: &mut Vec<(String, f64)>) {
    match v {
        Value::Number(n) => out.extend(n.as_f64().map(|x| (path.to_string(), x))),
        Value::Array(a) => {
            for (i, x) in a.iter().enumerate() {
                leaves(x, &format!("{path}[{i}]"), out);
            }
        }
        Value::Object(o) => {
            for (k, x) in o {
                let p = if path.is_empty() {
                    k.clone()
                } else {
                    format!("{path}.{k}")
                };
                leaves(x, &p, out);
            }
        }
        _ => {}
    }
}

/// The number at `path` (as [`leaves`] writes it) under `v`.
fn at_path<'a>(v: &'a Value, path: &str) -> Option<&'a Value> {
    let mut cur = v;
    for part in path.split('.') {
        let (name, indices) = part.split_once('[').map_or((part, ""), |(n, r)| (n, r));
        if !name.is_empty() {
            cur = cur.get(name)?;
        }
        for i in indices.split('[').filter(|s| !s.is_empty()) {
            cur = cur.get(i.trim_end_matches(']').parse::<usize>().ok()?)?;
        }
    }
    Some(cur)
}

fn numbers(v: &Value) -> Vec<Option<f64>> {
    v.as_array()
        .map(|a| a.iter().map(Value::as_f64).collect())
        .unwrap_or_default()
}

/// What the effects a page includes (`included`, the original's notes under its
/// configuration line) change, from the least to the most.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
enum Effects {
    /// None (or out of ground effect: `GROUND HEIGHT= FREE AIR`).
    None,
    /// Power: the original adds its increments to CD, CL, CM, CN and CA (XCP follows) and
    /// prints the slopes, the sideslip derivatives and the downwash as without power.
    Power,
    /// Ground effects at a height: every static and downwash number.
    Ground,
}

/// The static columns power effects change ([`Effects::Power`]).
const POWER_COLUMNS: [&str; 6] = ["CD", "CL", "CM", "CN", "CA", "XCP"];

/// The most a page's notes change (none without notes).
fn effects(page: &Value) -> Effects {
    let notes = page["included"]
        .as_array()
        .map(Vec::as_slice)
        .unwrap_or(&[]);
    notes
        .iter()
        .filter_map(Value::as_str)
        .map(|n| {
            if n.contains("FREE AIR") {
                Effects::None
            } else if n.contains("POWER EFFECTS INCLUDED") {
                Effects::Power
            } else {
                Effects::Ground
            }
        })
        .max()
        .unwrap_or(Effects::None)
}

/// A page's configuration and flight condition (Mach number and altitude).
type PageKey = (String, Option<f64>, Option<f64>);

fn page_key(c: &Value) -> PageKey {
    (
        c["configuration"].as_str().unwrap_or("").to_string(),
        c["mach"].as_f64(),
        c["altitude"].as_f64(),
    )
}

fn same_page(p: &PageKey, q: &PageKey) -> bool {
    let near = |a: Option<f64>, b: Option<f64>| match (a, b) {
        (Some(a), Some(b)) => (a - b).abs() <= 1e-3 * a.abs().max(1.0),
        (None, None) => true,
        _ => false,
    };
    p.0 == q.0 && near(p.1, q.1) && near(p.2, q.2)
}

/// For each reference page of a case (`cb`), the index of our page (`ca`) paired with it:
/// the one of the same configuration and flight condition (Mach and altitude); the order of
/// configuration pages differs between programs under BUILD.
fn counterparts(ca: &[Value], cb: &[Value]) -> Vec<Option<usize>> {
    // Pages with power or ground effects included are paired after the others, so that a
    // page without them (printed before or after them) finds its counterpart first.
    let mut counterpart: Vec<Option<usize>> = vec![None; cb.len()];
    let mut used = vec![false; ca.len()];
    for with_effects in [false, true] {
        for (j, y) in cb.iter().enumerate() {
            if (effects(y) != Effects::None) != with_effects {
                continue;
            }
            let ky = page_key(y);
            if let Some(i) = (0..ca.len()).find(|&i| !used[i] && same_page(&page_key(&ca[i]), &ky))
            {
                used[i] = true;
                counterpart[j] = Some(i);
            }
        }
    }
    counterpart
}

fn cases(v: &Value) -> &[Value] {
    v["cases"].as_array().map_or(&[], Vec::as_slice)
}

fn pages(case: &Value) -> &[Value] {
    case["conditions"].as_array().map_or(&[], Vec::as_slice)
}

/// A side's cases and their pages, for [`nothing_in_common`]: per case its flight conditions
/// (Mach number, altitude) and configurations, each once.
fn describe(v: &Value) -> String {
    const SHOWN: usize = 8;
    let number = |x: Option<f64>| x.map_or("none".to_string(), |x| format!("{x}"));
    let list = |items: Vec<String>| {
        let more = items.len().saturating_sub(SHOWN);
        let mut s = items.into_iter().take(SHOWN).collect::<Vec<_>>().join(", ");
        if more > 0 {
            s.push_str(&format!(" and {more} more"));
        }
        s
    };
    let described: Vec<String> = cases(v)
        .iter()
        .enumerate()
        .map(|(k, case)| {
            let mut conditions: Vec<String> = Vec::new();
            let mut configurations: Vec<String> = Vec::new();
            for page in pages(case) {
                let (configuration, mach, altitude) = page_key(page);
                let condition = format!("Mach {} altitude {}", number(mach), number(altitude));
                if !conditions.contains(&condition) {
                    conditions.push(condition);
                }
                if !configurations.contains(&configuration) {
                    configurations.push(configuration);
                }
            }
            if conditions.is_empty() {
                return format!("case {}: no page", k + 1);
            }
            format!(
                "case {}: {} ({})",
                k + 1,
                list(conditions),
                list(configurations)
            )
        })
        .collect();
    if described.is_empty() {
        "no case".to_string()
    } else {
        described.join("; ")
    }
}

/// When the reference has pages and none of them has a counterpart in `ours` (every number
/// would count as missing), why: the pages are paired case by case by configuration, Mach
/// number and altitude, and each side's are named. `None` when a page is in common.
pub fn nothing_in_common(ours: &Value, reference: &Value) -> Option<String> {
    let reference_pages: usize = cases(reference).iter().map(|c| pages(c).len()).sum();
    let paired = cases(ours)
        .iter()
        .zip(cases(reference))
        .any(|(a, b)| counterparts(pages(a), pages(b)).iter().any(Option::is_some));
    (reference_pages > 0 && !paired).then(|| {
        format!(
            "no page of the reference has a counterpart in ours (pages are paired case by case, by configuration, Mach number and altitude): ours has {}; the reference has {}",
            describe(ours),
            describe(reference)
        )
    })
}

/// Compares every coefficient of `ours` with `reference` (both in the JSON shape of `run`),
/// case by case and condition by condition in order; worst agreement first. A reference page
/// with power or ground effects that ours does not include has the numbers they change
/// counted as missing (with power CD, CL, CM, CN, CA and XCP; at a ground height every static
/// and downwash number).
pub fn compare(ours: &Value, reference: &Value) -> Vec<ColumnAgreement> {
    let mut out: Vec<ColumnAgreement> = STATIC
        .iter()
        .chain(DYNAMIC.iter())
        .chain(DOWNWASH.iter())
        .map(|c| ColumnAgreement::new(c))
        .collect();
    for (ci, (a, b)) in cases(ours).iter().zip(cases(reference)).enumerate() {
        let (ca, cb) = (pages(a), pages(b));
        let counterpart = counterparts(ca, cb);
        // Without a counterpart every reference number of the entry is missing on our side.
        let pairs = cb
            .iter()
            .zip(counterpart)
            .map(|(y, i)| (i.map_or(&Value::Null, |i| &ca[i]), y));
        for (ki, (x, y)) in pairs.enumerate() {
            // A reference page with effects that our page does not include (ours includes
            // neither power nor ground effects): the numbers they change have no counterpart.
            let differ = if x["included"] == y["included"] {
                Effects::None
            } else {
                effects(x).max(effects(y))
            };
            for (block, names) in [
                ("static", &STATIC[..]),
                ("dynamic", &DYNAMIC[..]),
                ("downwash", &DOWNWASH[..]),
            ] {
                let alpha = numbers(&y[block]["alpha"]);
                for name in names {
                    let col = out
                        .iter_mut()
                        .find(|c| c.coefficient == *name)
                        .expect("every coefficient has an entry");
                    let changed = match differ {
                        Effects::None => false,
                        Effects::Power => block == "static" && POWER_COLUMNS.contains(name),
                        Effects::Ground => block != "dynamic",
                    };
                    let x = if changed { &Value::Null } else { x };
                    let ov = numbers(&x[block][name]);
                    for (i, r) in numbers(&y[block][name]).iter().enumerate() {
                        let Some(r) = r else { continue };
                        let at = alpha.get(i).copied().flatten().unwrap_or(f64::NAN);
                        col.count(
                            ov.get(i).copied().flatten(),
                            *r,
                            |o| agrees(name, o, *r),
                            || (ci + 1, ki + 1, at, None),
                        );
                    }
                }
            }
            // The PART blocks: every number of the reference's, one row per block.
            let Some(aux) = y["auxiliary"].as_object() else {
                continue;
            };
            for (block, value) in aux {
                let name = format!("{PART}{block}");
                if !out.iter().any(|c| c.coefficient == name) {
                    out.push(ColumnAgreement::new(&name));
                }
                let col = out
                    .iter_mut()
                    .find(|c| c.coefficient == name)
                    .expect("pushed above");
                let mut numbers = Vec::new();
                leaves(value, "", &mut numbers);
                // The angles of the vortex table are its rows' keys, not results.
                for (path, r) in numbers.into_iter().filter(|(p, _)| !p.starts_with("alpha")) {
                    let ours =
                        at_path(&x["auxiliary"][block.as_str()], &path).and_then(Value::as_f64);
                    let joint = if path.starts_with('[') || path.is_empty() {
                        ""
                    } else {
                        "."
                    };
                    col.count(
                        ours,
                        r,
                        |o| part_agrees(block, &path, o, r),
                        || {
                            (
                                ci + 1,
                                ki + 1,
                                f64::NAN,
                                Some(format!("{block}{joint}{path}")),
                            )
                        },
                    );
                }
            }
        }
    }
    out.retain(|c| c.compared + c.missing > 0);
    out.sort_by(|a, b| a.fraction().total_cmp(&b.fraction()));
    out
}

/// The agreement as a text table.
pub fn to_text(rows: &[ColumnAgreement]) -> String {
    // The name column fits the longest name (D(EPSLON)/D(ALPHA)).
    let w = rows
        .iter()
        .map(|r| r.coefficient.len())
        .max()
        .unwrap_or(0)
        .max(12);
    let mut s = format!(
        "{:<w$} agree/total   fraction  missing  worst |ours - reference| (case, condition, alpha or field: ours vs reference)\n",
        "coefficient"
    );
    for r in rows {
        let worst = r.worst.as_ref().map_or(String::new(), |w| {
            let at = w
                .field
                .clone()
                .unwrap_or_else(|| format!("alpha {}", w.alpha));
            format!(
                "{:.4e} (case {}, condition {}, {at}: {} vs {})",
                w.difference, w.case, w.condition, w.ours, w.reference
            )
        });
        s.push_str(&format!(
            "{:<w$} {:>5}/{:<7} {:>8.1}% {:>8}  {}\n",
            r.coefficient,
            r.agreeing,
            r.compared + r.missing,
            100.0 * r.fraction(),
            r.missing,
            worst
        ));
    }
    if rows.is_empty() {
        s.push_str("(no coefficient values to compare)\n");
    }
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tolerance_is_two_percent_or_one_printed_unit() {
        assert!(agrees("CL", 0.1005, 0.100));
        assert!(!agrees("CL", 0.1035, 0.100));
        assert!(agrees("CD", 0.0205, 0.020), "one unit of F9.3 is 0.001");
        assert!(agrees("CM", 0.00015, 0.0001));
        assert!(agrees("CLA", 5.598, 5.6));
        assert!(!agrees("CLA", 5.8, 5.6));
    }

    #[test]
    fn part_blocks_are_compared_by_field() {
        let a: Value = serde_json::from_str(r#"{"cases":[{"conditions":[{"configuration":"W","mach":0.2,"auxiliary":{"body":{"wetted_area":100.0,"base_area":2.0},"planforms":[{"exposed":{"area":10.0}}]}}]}]}"#).unwrap();
        let b: Value = serde_json::from_str(r#"{"cases":[{"conditions":[{"configuration":"W","mach":0.2,"auxiliary":{"body":{"wetted_area":100.5,"base_area":2.5},"planforms":[{"exposed":{"area":10.0}}],"sidewash":1.0}}]}]}"#).unwrap();
        let r = compare(&a, &b);
        let row = |n: &str| r.iter().find(|c| c.coefficient == n).unwrap();
        assert_eq!(
            (row("PART body").agreeing, row("PART body").compared),
            (1, 2)
        );
        let worst = row("PART body").worst.as_ref().unwrap();
        assert_eq!(worst.field.as_deref(), Some("body.base_area"));
        assert_eq!(row("PART planforms").agreeing, 1);
        assert_eq!(row("PART sidewash").missing, 1, "not in ours");
    }

    #[test]
    fn part_fixed_point_fields_take_their_printed_unit() {
        // XCG on the MAC is printed F7.2: 0.0267 prints as 0.03.
        assert!(part_agrees("xcg_behind_mac_leading_edge", "", 0.0267, 0.03));
        assert!(!part_agrees("xcg_behind_mac_leading_edge", "", 0.045, 0.03));
        // Taper printed F.3: 0.0105 prints as 0.010 (5 % off, one unit); an E-format field
        // holds 2 %.
        assert!(part_agrees(
            "planforms",
            "[0].exposed.taper_ratio",
            0.0105,
            0.010
        ));
        assert!(!part_agrees("planforms", "[0].exposed.area", 0.0105, 0.010));
    }

    #[test]
    fn no_page_in_common_is_explained() {
        let a: Value = serde_json::from_str(r#"{"cases":[{"conditions":[{"configuration":"W","mach":0.2,"altitude":0.0,"static":{"alpha":[0],"CL":[0.1]}},{"configuration":"W","mach":0.3,"altitude":0.0,"static":{"alpha":[0],"CL":[0.1]}}]}]}"#).unwrap();
        let b: Value = serde_json::from_str(r#"{"cases":[{"conditions":[{"configuration":"W","mach":0.6,"altitude":1000.0,"static":{"alpha":[0],"CL":[0.1]}}]}]}"#).unwrap();
        let why = nothing_in_common(&a, &b).expect("nothing in common");
        assert!(
            why.contains("ours has case 1: Mach 0.2 altitude 0, Mach 0.3 altitude 0 (W)"),
            "{why}"
        );
        assert!(
            why.contains("the reference has case 1: Mach 0.6 altitude 1000 (W)"),
            "{why}"
        );
        assert_eq!(nothing_in_common(&a, &a), None);
        // No reference page: nothing to explain (the table says there is nothing to compare).
        let none: Value = serde_json::from_str(r#"{"cases":[]}"#).unwrap();
        assert_eq!(nothing_in_common(&a, &none), None);
        assert!(nothing_in_common(&none, &b)
            .expect("ours has no case")
            .contains("ours has no case"));
    }

    #[test]
    fn counts_and_worst() {
        let a: Value = serde_json::from_str(r#"{"cases":[{"conditions":[{"static":{"alpha":[0,2],"CL":[0.1,0.3]},"dynamic":null}]}]}"#).unwrap();
        let b: Value = serde_json::from_str(r#"{"cases":[{"conditions":[{"static":{"alpha":[0,2],"CL":[0.1,0.2]},"dynamic":null}]}]}"#).unwrap();
        let r = compare(&a, &b);
        assert_eq!(r.len(), 1);
        assert_eq!((r[0].agreeing, r[0].compared), (1, 2));
        assert_eq!(r[0].worst.as_ref().unwrap().alpha, 2.0);
    }
}
