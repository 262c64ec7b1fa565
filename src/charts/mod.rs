//! Digitised DATCOM charts as interpolation tables.
//!
//! Each chart is a TOML file under `charts/` (embedded at build time): figure id, title, axes
//! with symbols and units, the values, the source (DATCOM figure and the Digital DATCOM routine
//! whose DATA statement holds the values), what a lookup does beyond the data on each side of
//! each axis, and known defects. See `charts/README.md` for the format.
//!
//! Lookups behave as the original program's table routines (TLIN1X/TLINEX/TLIN3X/TLIN4X with
//! GLOOK, and TBFUNX): linear interpolation between nodes, axis by axis from the innermost; a
//! query within a relative 1E-3 of a node takes the node's value (GLOOK; `node_tolerance = 0`
//! for TBFUNX tables); beyond the data, per axis and side: clamp to the end value, extrapolate
//! linearly from the last two nodes, extrapolate quadratically through the last three, or refuse.
//! Leaving the data is always a [`ChartWarning`] naming the chart, the variable and the value.

mod lookup;
mod parse;

use std::cell::Cell;
use std::collections::{BTreeMap, HashMap};
use std::fmt;
use std::hash::{BuildHasherDefault, Hasher};
use std::ops::Deref;
use std::sync::{Arc, OnceLock};

use serde::Serialize;

pub use lookup::Lookup;
pub use parse::{parse_chart, ChartError};

include!(concat!(env!("OUT_DIR"), "/charts.rs"));

/// What a lookup does beyond the data on one side of an axis.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Outside {
    /// Take the end value.
    Clamp,
    /// Extrapolate linearly from the two end nodes.
    Linear,
    /// Extrapolate with the parabola through the three end nodes (the original's QUAD).
    Quadratic,
    /// Give no value.
    Refuse,
}

/// An independent variable of a chart.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Axis {
    /// Shared with the warnings that name it.
    pub symbol: Name,
    pub name: String,
    pub unit: String,
    pub below: Outside,
    pub above: Outside,
}

/// The dependent variable.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Output {
    pub symbol: String,
    pub name: String,
    pub unit: String,
}

/// Where the values come from.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Source {
    /// DATCOM figure or table, e.g. `DATCOM figure 4.1.3.2-49`.
    pub figure: String,
    /// Digital DATCOM routine whose DATA statement holds the values.
    pub routine: String,
    /// Lines of that DATA statement in datcom.f (PDAS revision, January 1996).
    pub lines: String,
}

/// Values over the axes: a node per axis value, down to numbers. A regular grid has the same
/// x values in every branch; a family of curves has its own x values per curve.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(untagged)]
pub enum Node {
    Value(f64),
    Table { x: Vec<f64>, nodes: Vec<Node> },
}

/// A digitised chart, as [`parse_chart`] builds and checks it. The lookups rely on its checks
/// (every axis strictly monotone, with finite nodes; `shared_axes` alike in every branch): a
/// chart whose `data` is changed afterwards must keep them, or set `shared_axes` to 0.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Chart {
    /// Shared with the warnings that name the chart.
    pub id: Name,
    pub title: String,
    /// Axes from the outermost (first lookup argument) to the innermost (last).
    pub axes: Vec<Axis>,
    pub output: Output,
    pub source: Source,
    pub notes: String,
    pub defects: Vec<String>,
    /// Relative distance within which a query takes a node's value.
    pub node_tolerance: f64,
    pub data: Node,
    /// How many axes, from the outermost, have the same nodes in every branch of `data`:
    /// every axis of a grid, all but the innermost of a family of curves. A lookup finds the
    /// query among such an axis's nodes once.
    #[serde(skip)]
    pub shared_axes: usize,
    /// Path of the file under charts/.
    pub file: String,
}

impl Chart {
    /// The nodes of axis `depth` (0 the outermost) of a grid chart, read along its first
    /// branch; `None` past the innermost axis.
    pub fn axis_nodes(&self, depth: usize) -> Option<&[f64]> {
        let mut node = &self.data;
        for _ in 0..depth {
            match node {
                Node::Table { nodes, .. } => node = nodes.first()?,
                Node::Value(_) => return None,
            }
        }
        match node {
            Node::Table { x, .. } => Some(x),
            Node::Value(_) => None,
        }
    }
}

/// A chart id or axis symbol as a warning holds it: shared with the chart, so that making,
/// copying and comparing warnings allocates nothing. Reads as a `str`.
#[derive(Clone, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct Name(Arc<str>);

impl Name {
    pub fn as_str(&self) -> &str {
        &self.0
    }
}

impl Default for Name {
    fn default() -> Self {
        Name(Arc::from(""))
    }
}

impl Deref for Name {
    type Target = str;
    fn deref(&self) -> &str {
        &self.0
    }
}

impl From<&str> for Name {
    fn from(s: &str) -> Self {
        Name(Arc::from(s))
    }
}

impl From<String> for Name {
    fn from(s: String) -> Self {
        Name(Arc::from(s))
    }
}

impl PartialEq<str> for Name {
    fn eq(&self, other: &str) -> bool {
        *self.0 == *other
    }
}

impl PartialEq<&str> for Name {
    fn eq(&self, other: &&str) -> bool {
        *self.0 == **other
    }
}

impl PartialEq<String> for Name {
    fn eq(&self, other: &String) -> bool {
        *self.0 == **other
    }
}

impl fmt::Debug for Name {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        fmt::Debug::fmt(&*self.0, f)
    }
}

impl fmt::Display for Name {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        fmt::Display::fmt(&*self.0, f)
    }
}

impl Serialize for Name {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.serialize_str(&self.0)
    }
}

/// A lookup left the data of a chart.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ChartWarning {
    pub chart: Name,
    pub variable: Name,
    pub value: f64,
    pub min: f64,
    pub max: f64,
    pub action: Outside,
}

impl fmt::Display for ChartWarning {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let what = match self.action {
            Outside::Clamp => "end value used",
            Outside::Linear => "extrapolated linearly",
            Outside::Quadratic => "extrapolated quadratically",
            Outside::Refuse => "no value",
        };
        if !self.value.is_finite() {
            // A query the walk refused before reading the chart (lookup_each).
            return write!(
                f,
                "chart {}: {} = {} is not finite: no value",
                self.chart, self.variable, self.value
            );
        }
        write!(
            f,
            "chart {}: {} = {} is outside the data ({} to {}): {what}",
            self.chart,
            self.variable,
            Query(self.value),
            self.min,
            self.max
        )
    }
}

/// The arguments of a lookup of chart `id` as a person reads them: `mach = 0.6, t_over_c =
/// inf`, each value to four significant digits (`[0.6, inf]` when the chart is not known or
/// the count does not match its axes).
pub fn describe_query(id: &str, args: &[f64]) -> String {
    match get(id).filter(|c| c.axes.len() == args.len()) {
        Some(c) => c
            .axes
            .iter()
            .zip(args)
            .map(|(a, &v)| format!("{} = {}", a.symbol, Query(v)))
            .collect::<Vec<_>>()
            .join(", "),
        None => format!(
            "[{}]",
            args.iter()
                .map(|&v| Query(v).to_string())
                .collect::<Vec<_>>()
                .join(", ")
        ),
    }
}

/// Significant digits of a query value in a warning: more than a chart is read to, fewer than
/// a float's seventeen (`tan_ratio = 0.10533802696765625` is shown as `0.1053`).
const QUERY_DIGITS: usize = 4;

/// A query value as a person reads it: rounded to [`QUERY_DIGITS`] significant digits, plain
/// from 1e-4 to below 1e6, in exponent form beyond (the warning's `value` keeps it exactly).
pub(crate) struct Query(pub(crate) f64);

impl fmt::Display for Query {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let v = self.0;
        if v == 0.0 || !v.is_finite() {
            return write!(f, "{v}");
        }
        match Query::digits(v) {
            Some((digits, exponent)) => Query::write_digits(f, v < 0.0, digits, exponent),
            None => Query::exact(f, v),
        }
    }
}

impl Query {
    /// The query rounded by the decimal rounding of its exact value (a float formatting in
    /// exact mode), written as the float nearest that rounding is shown.
    fn exact(f: &mut fmt::Formatter<'_>, v: f64) -> fmt::Result {
        match crate::numeric::round_significant(v, QUERY_DIGITS) {
            Some(r) if (1e-4..1e6).contains(&r.abs()) => write!(f, "{r}"),
            Some(r) => write!(f, "{r:e}"),
            // Rounded up beyond the largest float.
            None => write!(f, "{v:.*e}", QUERY_DIGITS - 1),
        }
    }

    /// The [`QUERY_DIGITS`] significant digits of `v` (finite, not 0) as an integer `m` of
    /// exactly that many digits and the decimal exponent `e` of the first (|v| rounds to
    /// m·10^(e+1−QUERY_DIGITS)), by arithmetic; none where the arithmetic's few units of
    /// rounding error could decide the rounding (a near tie, a near power of ten, the ends of
    /// the float range): [`Query::exact`] decides those.
    fn digits(v: f64) -> Option<(u32, i32)> {
        /// Distance from a rounding boundary below which the arithmetic is not trusted: far
        /// above its error (a few units in the last place of a number below 10^4).
        const MARGIN: f64 = 1e-6;
        let low = 10f64.powi(QUERY_DIGITS as i32 - 1);
        let a = v.abs();
        if !(1e-290..1e290).contains(&a) {
            return None;
        }
        let e = a.log10().floor() as i32;
        let shift = QUERY_DIGITS as i32 - 1 - e;
        let scaled = if shift >= 0 {
            a * 10f64.powi(shift)
        } else {
            a / 10f64.powi(-shift)
        };
        let fraction = scaled - scaled.floor();
        let near_tie = (fraction - 0.5).abs() < MARGIN;
        if near_tie || !(low + MARGIN..10.0 * low - 0.5 - MARGIN).contains(&scaled) {
            return None;
        }
        Some((scaled.round() as u32, e))
    }

    /// Writes `digits`·10^(exponent+1−QUERY_DIGITS) as Rust shows the float nearest it: plain
    /// from 1e-4 to below 1e6, else in exponent form, with the shortest digits (those given,
    /// trailing zeros dropped).
    fn write_digits(
        f: &mut fmt::Formatter<'_>,
        negative: bool,
        mut digits: u32,
        exponent: i32,
    ) -> fmt::Result {
        let mut count = QUERY_DIGITS as i32;
        while digits % 10 == 0 {
            digits /= 10;
            count -= 1;
        }
        // The digits as text, without allocating (at most QUERY_DIGITS of them).
        let mut buffer = [0u8; QUERY_DIGITS];
        let mut rest = digits;
        for place in (0..count as usize).rev() {
            buffer[place] = b'0' + (rest % 10) as u8;
            rest /= 10;
        }
        let text = std::str::from_utf8(&buffer[..count as usize]).map_err(|_| fmt::Error)?;
        if negative {
            f.write_str("-")?;
        }
        if !(-4..6).contains(&exponent) {
            let (first, rest) = text.split_at(1);
            f.write_str(first)?;
            if !rest.is_empty() {
                write!(f, ".{rest}")?;
            }
            return write!(f, "e{exponent}");
        }
        if exponent < 0 {
            f.write_str("0.")?;
            for _ in 0..(-exponent - 1) {
                f.write_str("0")?;
            }
            return f.write_str(text);
        }
        let whole = (exponent + 1) as usize;
        if (count as usize) <= whole {
            f.write_str(text)?;
            for _ in 0..whole - count as usize {
                f.write_str("0")?;
            }
            Ok(())
        } else {
            let (int, frac) = text.split_at(whole);
            write!(f, "{int}.{frac}")
        }
    }
}

struct Registry {
    charts: BTreeMap<String, Chart>,
    errors: Vec<(String, ChartError)>,
}

fn registry() -> &'static Registry {
    static REGISTRY: OnceLock<Registry> = OnceLock::new();
    REGISTRY.get_or_init(|| {
        let mut charts = BTreeMap::new();
        let mut errors = Vec::new();
        for (file, text) in CHART_FILES {
            match parse_chart(text, file) {
                Ok(c) => {
                    charts.insert(c.id.to_string(), c);
                }
                Err(e) => errors.push((file.to_string(), e)),
            }
        }
        Registry { charts, errors }
    })
}

/// FNV-1a, the hash of the chart index (and of warnings' fingerprints): chart ids are short
/// strings fixed at build time, so the standard hasher's protection against chosen keys buys
/// nothing and costs several times more per lookup.
pub(crate) struct IdHasher(u64);

impl Default for IdHasher {
    fn default() -> Self {
        IdHasher(0xcbf2_9ce4_8422_2325)
    }
}

impl Hasher for IdHasher {
    fn finish(&self) -> u64 {
        self.0
    }

    fn write(&mut self, bytes: &[u8]) {
        for b in bytes {
            self.0 = (self.0 ^ u64::from(*b)).wrapping_mul(0x0100_0000_01b3);
        }
    }
}

type Index = HashMap<&'static str, usize, BuildHasherDefault<IdHasher>>;

/// The chart files by the id they declare (build.rs reads it): a lookup parses only the file of
/// the chart it needs, once per process, instead of every embedded chart.
fn index() -> &'static Index {
    static INDEX: OnceLock<Index> = OnceLock::new();
    INDEX.get_or_init(|| {
        CHART_IDS
            .iter()
            .enumerate()
            .filter(|(_, id)| !id.is_empty())
            .map(|(slot, id)| (*id, slot))
            .collect()
    })
}

/// The chart of file `slot`, parsed on first use; none when the file is not valid or does not
/// hold the chart its id line names.
fn parsed(slot: usize) -> Option<&'static Chart> {
    static PARSED: OnceLock<Vec<OnceLock<Option<Chart>>>> = OnceLock::new();
    let (file, text) = *CHART_FILES.get(slot)?;
    PARSED
        .get_or_init(|| CHART_FILES.iter().map(|_| OnceLock::new()).collect())
        .get(slot)?
        .get_or_init(|| {
            parse_chart(text, file)
                .ok()
                .filter(|c| CHART_IDS.get(slot) == Some(&c.id.as_str()))
        })
        .as_ref()
}

/// The chart with this id (`4.1.3.2-49`, ...), when it is embedded and valid. A file whose id
/// line is not what its parsed chart says falls back on the registry of every chart.
pub fn get(id: &str) -> Option<&'static Chart> {
    found(id)
}

/// The charts found last are kept per thread in a small table addressed by where the id's
/// text is (the methods pass the same constant each time): a hit costs a comparison of the id
/// instead of hashing it. The id is always compared: a place alone does not name a text (a
/// freed string's place is reused by another).
fn found(id: &str) -> Option<&'static Chart> {
    const RECENT: usize = 64;
    thread_local! {
        static FOUND: [Cell<Option<&'static Chart>>; RECENT] =
            const { [const { Cell::new(None) }; RECENT] };
    }
    let slot = ((id.as_ptr() as usize >> 2) ^ id.len()) % RECENT;
    if let Ok(Some(c)) = FOUND.try_with(|f| f[slot].get()) {
        if c.id == id {
            return Some(c);
        }
    }
    let chart = index()
        .get(id)
        .and_then(|&slot| parsed(slot))
        .or_else(|| registry().charts.get(id));
    if let Some(c) = chart {
        let _ = FOUND.try_with(|f| f[slot].set(Some(c)));
    }
    chart
}

/// Every valid embedded chart.
pub fn all() -> impl Iterator<Item = &'static Chart> {
    registry().charts.values()
}

/// Embedded chart files that failed to parse or validate (a test keeps this empty).
pub fn invalid() -> &'static [(String, ChartError)] {
    &registry().errors
}

#[cfg(test)]
mod tests {
    use super::{describe_query, get, Query, CHART_IDS};

    /// A chart asked for by a fixed id and by the same id in other text is the same chart, on
    /// the first asking and the next.
    #[test]
    fn ids_find_their_charts_wherever_their_text_is() {
        for _ in 0..2 {
            for &id in CHART_IDS {
                let copied = id.to_string();
                assert_eq!(get(id).map(|c| c.id.as_str()), Some(id), "{id}");
                assert_eq!(get(&copied).map(|c| c.id.as_str()), Some(id), "{id}");
            }
        }
    }

    /// A text at the place where another id was asked for is still read: the table of charts
    /// found last is addressed by place, but a hit compares the id.
    #[test]
    fn a_reused_place_with_another_text_finds_that_text() {
        let id = CHART_IDS
            .iter()
            .find(|id| id.bytes().any(|b| b.is_ascii_lowercase()))
            .expect("a chart id with a letter");
        let text: &'static mut str = id.to_string().leak();
        assert_eq!(get(text).map(|c| c.id.as_str()), Some(*id));
        // The same place, the same length, another text (no chart has it).
        text.make_ascii_uppercase();
        assert_ne!(&*text, *id);
        assert_eq!(get(text).map(|c| c.id.as_str()), None, "{text}");
    }

    #[test]
    fn a_query_is_described_by_its_axes() {
        let id = CHART_IDS[0];
        let chart = get(id).expect("the first chart");
        let args: Vec<f64> = (0..chart.axes.len()).map(|k| 0.5 + k as f64).collect();
        let mut infinite = args.clone();
        infinite[0] = f64::INFINITY;
        let described = describe_query(id, &infinite);
        assert!(
            described.starts_with(&format!("{} = inf", chart.axes[0].symbol)),
            "{described}"
        );
        assert_eq!(described.matches(" = ").count(), chart.axes.len());
        // Not a chart, or not its number of arguments: the values alone.
        assert_eq!(
            describe_query("no-such-chart", &[0.5, f64::NAN]),
            "[0.5, NaN]"
        );
        let warning = chart.lookup(&infinite).warnings;
        assert_eq!(warning.len(), 1);
        assert!(
            warning[0]
                .to_string()
                .ends_with("= inf is not finite: no value"),
            "{}",
            warning[0]
        );
    }

    #[test]
    fn query_values_are_shown_to_four_significant_digits() {
        let shown = |v: f64| Query(v).to_string();
        assert_eq!(shown(0.10533802696765625), "0.1053");
        assert_eq!(shown(0.058722834612423405), "0.05872");
        assert_eq!(shown(8.000000000000007), "8");
        assert_eq!(shown(-3.168976464449363), "-3.169");
        assert_eq!(shown(205_220.4), "205200");
        assert_eq!(shown(0.0), "0");
        assert_eq!(shown(1.23456e-7), "1.235e-7");
        assert_eq!(shown(1.2345678e10), "1.235e10");
        assert_eq!(shown(f64::MAX), "1.798e308");
        assert_eq!(shown(f64::INFINITY), "inf");
    }

    /// The arithmetic rounding writes what the exact decimal rounding writes, wherever it
    /// answers (ties and the ends of the range are left to the exact one).
    #[test]
    fn the_arithmetic_rounding_agrees_with_the_exact_one() {
        struct Exact(f64);
        impl std::fmt::Display for Exact {
            fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
                Query::exact(f, self.0)
            }
        }
        // A deterministic spread over many decades, every sign, and decimal ties.
        let mut x: u64 = 0x9E37_79B9_7F4A_7C15;
        let mut values = vec![
            2.3375, 0.12345, 999.95, 9999.5, 1e6, 999_999.7, 1e-4, 9.9995e-5,
        ];
        for _ in 0..200_000 {
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            let mantissa = (x >> 11) as f64 / (1u64 << 53) as f64;
            let decade = (x % 40) as i32 - 20;
            let sign = if x & 1 == 0 { 1.0 } else { -1.0 };
            values.push(sign * (1.0 + 9.0 * mantissa) * 10f64.powi(decade));
        }
        let mut answered = 0;
        for v in values {
            if Query::digits(v).is_some() {
                answered += 1;
            }
            assert_eq!(Query(v).to_string(), Exact(v).to_string(), "{v:e}");
        }
        assert!(
            answered > 190_000,
            "the arithmetic answers almost always: {answered}"
        );
    }
}
