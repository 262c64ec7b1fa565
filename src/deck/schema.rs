//! The namelists Digital DATCOM accepts: each variable's kind, array length, count variable and
//! physical unit.
//!
//! The table is data (`schema.tsv`, embedded at build time), taken from the declarations and
//! namelist-emulator name tables of the original program (reader routines XNAM1..XNAM23 and the
//! COMMON blocks they fill). The dimension column follows the original's unit conversion
//! (routine CONV) slot by slot: `length`/`area` are geometry and scale with SYNTHS SCALE,
//! `*_unscaled` do not; it is used to convert at the edge under DIM FT/IN/M/CM.

use std::collections::BTreeMap;
use std::sync::OnceLock;

/// Value kind of a namelist variable.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Kind {
    Real,
    Integer,
    Logical,
}

/// Physical dimension of a variable, for unit conversion at the edge.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Dimension {
    /// Dimensionless, angles (degrees), counts, flags, chord or span fractions.
    None,
    Length,
    Area,
    /// Per unit length (Reynolds number per length).
    PerLength,
    Velocity,
    Pressure,
    Temperature,
    /// Weight or force.
    Force,
    /// Surface roughness height: inches under FT and IN, centimetres under M and CM.
    Roughness,
}

#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct VarSpec {
    pub name: String,
    pub kind: Kind,
    /// Array length; 1 for scalars.
    pub len: usize,
    /// The variable that says how many values the array holds (`NALPHA` for `ALSCHD`).
    pub count: Option<String>,
    pub dimension: Dimension,
    /// Multiplied by SYNTHS SCALE (lengths by SCALE, areas by SCALE²), as the original does
    /// for geometry; flight conditions, roughness and $LARWB are not scaled.
    pub scaled: bool,
}

#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct NamelistSpec {
    pub name: String,
    pub vars: BTreeMap<String, VarSpec>,
}

impl NamelistSpec {
    pub fn var(&self, name: &str) -> Option<&VarSpec> {
        self.vars.get(name)
    }
}

const SCHEMA_TSV: &str = include_str!("schema.tsv");

fn parse_kind(s: &str) -> Kind {
    match s {
        "integer" => Kind::Integer,
        "logical" => Kind::Logical,
        _ => Kind::Real,
    }
}

fn parse_dimension(s: &str) -> Dimension {
    match s {
        "length" | "length_unscaled" => Dimension::Length,
        "area" | "area_unscaled" => Dimension::Area,
        "roughness" => Dimension::Roughness,
        "per_length" => Dimension::PerLength,
        "velocity" => Dimension::Velocity,
        "pressure" => Dimension::Pressure,
        "temperature" => Dimension::Temperature,
        "force" => Dimension::Force,
        _ => Dimension::None,
    }
}

fn load() -> BTreeMap<String, NamelistSpec> {
    let mut out: BTreeMap<String, NamelistSpec> = BTreeMap::new();
    for line in SCHEMA_TSV.lines().skip(1) {
        let f: Vec<&str> = line.split('\t').collect();
        if f.len() < 6 || f[0].starts_with('#') {
            continue;
        }
        let spec = VarSpec {
            name: f[1].to_string(),
            kind: parse_kind(f[2]),
            len: f[3].parse().unwrap_or(1),
            count: (!f[4].is_empty()).then(|| f[4].to_string()),
            dimension: parse_dimension(f[5]),
            scaled: matches!(f[5], "length" | "area"),
        };
        out.entry(f[0].to_string())
            .or_insert_with(|| NamelistSpec {
                name: f[0].to_string(),
                vars: BTreeMap::new(),
            })
            .vars
            .insert(spec.name.clone(), spec);
    }
    out
}

/// Every namelist of Digital DATCOM, by name.
pub fn namelists() -> &'static BTreeMap<String, NamelistSpec> {
    static SCHEMA: OnceLock<BTreeMap<String, NamelistSpec>> = OnceLock::new();
    SCHEMA.get_or_init(load)
}

/// A name of at most eight bytes as one integer, for lookups that compare integers instead of
/// strings. Bytes are packed first to last into the high to low end, padded with zeros, so that
/// keys order as their names do. `None` for longer names and names holding a NUL byte, which no
/// namelist or variable has.
pub(crate) fn key(name: &str) -> Option<u64> {
    let b = name.as_bytes();
    if b.len() > 8 {
        return None;
    }
    let mut k = 0u64;
    for (i, c) in b.iter().enumerate() {
        if *c == 0 {
            return None;
        }
        k |= u64::from(*c) << (56 - 8 * i);
    }
    Some(k)
}

/// A namelist's schema with its variables in a table sorted by [`key`], for the reader's many
/// lookups.
pub(crate) struct Table {
    pub spec: &'static NamelistSpec,
    vars: Vec<(u64, &'static VarSpec)>,
}

impl Table {
    /// The variable called `name` (upper case), as [`NamelistSpec::var`].
    pub fn var(&self, name: &str) -> Option<&'static VarSpec> {
        self.index(name).map(|i| self.vars[i].1)
    }

    /// The place of the variable called `name` (upper case) in [`Table::vars`].
    pub fn index(&self, name: &str) -> Option<usize> {
        let k = key(name)?;
        self.vars.binary_search_by_key(&k, |(vk, _)| *vk).ok()
    }

    /// The variables with their [`key`]s, in the order of their names.
    pub fn vars(&self) -> &[(u64, &'static VarSpec)] {
        &self.vars
    }
}

/// Every namelist's [`Table`], sorted by the key of its name.
fn tables() -> &'static [(u64, Table)] {
    static TABLES: OnceLock<Vec<(u64, Table)>> = OnceLock::new();
    TABLES.get_or_init(|| {
        let mut out: Vec<(u64, Table)> = namelists()
            .values()
            .map(|spec| {
                let mut vars: Vec<(u64, &'static VarSpec)> = spec
                    .vars
                    .values()
                    .map(|v| (key(&v.name).expect("variable names are short"), v))
                    .collect();
                vars.sort_by_key(|(k, _)| *k);
                let k = key(&spec.name).expect("namelist names are short");
                (k, Table { spec, vars })
            })
            .collect();
        out.sort_by_key(|(k, _)| *k);
        out
    })
}

/// The [`Table`] of the namelist called `name`, as [`namelist`].
pub(crate) fn table(name: &str) -> Option<&'static Table> {
    let name = match name.strip_prefix("EXPR") {
        Some(nn) if nn.len() == 2 && nn.bytes().all(|c| c.is_ascii_digit()) => "EXPRnn",
        _ => name,
    };
    let k = key(name)?;
    let tables = tables();
    tables
        .binary_search_by_key(&k, |(tk, _)| *tk)
        .ok()
        .map(|i| &tables[i].1)
}

/// The namelist called `name` (upper case), if Digital DATCOM has one. The experimental-data
/// namelists `EXPR01`, `EXPR02`, ... (one per Mach number) share the schema `EXPRnn`.
pub fn namelist(name: &str) -> Option<&'static NamelistSpec> {
    table(name).map(|t| t.spec)
}

/// Namelists of Missile DATCOM that Digital DATCOM does not have: their presence marks a deck
/// written for the other program.
pub const MISSILE_NAMELISTS: &[&str] = &[
    "REFQ", "AXIBOD", "ELLBOD", "FINSET1", "FINSET2", "FINSET3", "FINSET4", "PROTUB", "INLET",
    "DEFLCT", "INERTIA", "SYMCS",
];

/// The variable an assignment to `var` in `namelist` sets: itself, unless it is an alias, a name
/// that shares storage with another in the original (EQUIVALENCE).
pub fn canonical<'a>(namelist: &str, var: &'a str) -> &'a str {
    let section = matches!(namelist, "WGSCHR" | "HTSCHR" | "VTSCHR" | "VFSCHR");
    match var {
        "ALPHA" if namelist == "FLTCON" => "ALSCHD",
        "CMO" if section => "CM0",
        "CMOT" if section => "CM0T",
        "CLAM0" if section => "CLAMO",
        "ALPHA0" if section => "ALPHAO",
        "SCHD" if namelist == "SYMFLP" => "SCHA",
        _ => var,
    }
}

/// The namelists that have a variable called `var`, as `$NAME` joined by commas.
pub fn homes(var: &str) -> Option<String> {
    let v: Vec<String> = namelists()
        .values()
        .filter(|s| s.var(var).is_some())
        .map(|s| format!("${}", s.name))
        .collect();
    (!v.is_empty()).then(|| v.join(", "))
}

/// Edit distance, for "did you mean" hints.
pub fn edit_distance(a: &str, b: &str) -> usize {
    let b: Vec<char> = b.chars().collect();
    let mut prev: Vec<usize> = (0..=b.len()).collect();
    for (i, ca) in a.chars().enumerate() {
        let mut cur = vec![i + 1; b.len() + 1];
        for (j, cb) in b.iter().enumerate() {
            let sub = prev[j] + usize::from(ca != *cb);
            cur[j + 1] = sub.min(prev[j + 1] + 1).min(cur[j] + 1);
        }
        prev = cur;
    }
    prev[b.len()]
}

/// The candidate nearest to `word`, when it is near enough to be a plausible typo.
pub fn nearest<'a>(word: &str, candidates: impl IntoIterator<Item = &'a str>) -> Option<&'a str> {
    let limit = (word.len() / 3).max(1);
    candidates
        .into_iter()
        .map(|c| (edit_distance(word, c), c))
        .filter(|(d, _)| *d <= limit)
        .min_by_key(|(d, c)| (*d, *c))
        .map(|(_, c)| c)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn typo_hint() {
        let wg = namelist("WGPLNF").unwrap();
        assert_eq!(
            nearest("DHDAHI", wg.vars.keys().map(String::as_str)),
            Some("DHDADI")
        );
    }

    #[test]
    fn known_sizes() {
        let f = namelist("FLTCON").unwrap();
        assert_eq!(f.var("ALSCHD").unwrap().len, 20);
        assert_eq!(f.var("ALSCHD").unwrap().count.as_deref(), Some("NALPHA"));
        assert_eq!(f.var("MACH").unwrap().len, 20);
        let b = namelist("BODY").unwrap();
        assert_eq!(b.var("X").unwrap().len, 20);
        assert_eq!(b.var("X").unwrap().dimension, Dimension::Length);
        assert_eq!(
            namelist("SYNTHS").unwrap().var("VERTUP").unwrap().kind,
            Kind::Logical
        );
    }

    #[test]
    fn aliases() {
        assert_eq!(canonical("FLTCON", "ALPHA"), "ALSCHD");
        assert_eq!(canonical("BODY", "ALPHA"), "ALPHA");
        for nl in ["WGSCHR", "HTSCHR", "VTSCHR", "VFSCHR"] {
            assert_eq!(canonical(nl, "CMO"), "CM0");
            assert_eq!(canonical(nl, "CMOT"), "CM0T");
            assert_eq!(canonical(nl, "CLAM0"), "CLAMO");
            assert_eq!(canonical(nl, "ALPHA0"), "ALPHAO");
            assert_eq!(canonical(nl, "ALPHA"), "ALPHA");
        }
        assert_eq!(canonical("SYMFLP", "SCHD"), "SCHA");
        assert_eq!(canonical("ASYFLP", "SCHD"), "SCHD");
        assert_eq!(canonical("FLTCON", "CMO"), "CMO");
    }

    #[test]
    fn tables_find_what_the_maps_hold() {
        for (name, spec) in namelists() {
            let t = table(name).unwrap();
            assert_eq!(t.spec, spec);
            for (v, var) in &spec.vars {
                assert_eq!(t.var(v), Some(var));
                // The reader keeps which elements were assigned in a 128-bit set.
                assert!(var.len < 128, "{name} {v}");
            }
            assert_eq!(t.var("NOSUCHVAR"), None);
        }
        assert_eq!(namelist("EXPR07").unwrap().name, "EXPRnn");
        assert_eq!(namelist("EXPR7"), None);
        assert_eq!(namelist("FLTCON\0"), None);
        assert_eq!(namelist("FLTCONXYZ"), None);
        assert_eq!(key("AB"), Some(0x4142 << 48));
        assert!(key("AB") < key("ABC") && key("ABC") < key("ABD") && key("AZ") < key("B"));
    }
}
