//! A run's warnings, kept as what the methods found (their typed warnings, with where they
//! arose) and put into words only when they are read. A design tool that runs thousands of
//! variants and reads no warning text does not pay for formatting it; one that does can match
//! on [`Detail`] instead of parsing text.

use std::collections::HashMap;
use std::fmt;
use std::hash::{BuildHasherDefault, Hash, Hasher};

use serde::{Serialize, Serializer};

use crate::charts::{ChartWarning, IdHasher};
use crate::deck::cards::Surface;
use crate::methods::body::BodyWarning;
use crate::methods::dynamic::DynamicWarning;
use crate::methods::lateral::LateralWarning;
use crate::methods::section::SectionWarning;
use crate::methods::tail::TailWarning;
use crate::methods::wing::WingWarning;
use crate::methods::wing_body::WingBodyWarning;

/// One warning of a run: where it arose and what it says. Its text is its [`fmt::Display`]
/// (`tails: horizontal tail: chart 4.1.5.1-28b: mach = 0.0588 is outside ...`); JSON writes
/// that text.
#[derive(Debug, Clone, PartialEq)]
pub struct Warning {
    context: Context,
    detail: Detail,
}

/// [`Detail`]: one variant a kind of warning, each made from its warning (`From`) and said as
/// that warning says itself (`Display`).
macro_rules! details {
    ($($(#[$doc:meta])* $variant:ident($ty:ty)),* $(,)?) => {
        /// What a warning says: a method's own warning, or text.
        #[derive(Debug, Clone, PartialEq)]
        #[non_exhaustive]
        pub enum Detail {
            $($(#[$doc])* $variant($ty),)*
        }

        $(impl From<$ty> for Detail {
            fn from(w: $ty) -> Self {
                Detail::$variant(w)
            }
        })*

        impl fmt::Display for Detail {
            fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
                match self {
                    $(Detail::$variant(w) => fmt::Display::fmt(w, f),)*
                }
            }
        }
    };
}

details! {
    /// In words only: notes of the run (build-up implied, conditions derived, ...), a method's
    /// error, a section's reading.
    Text(String),
    /// A chart read outside its data (the low-aspect-ratio wing-body's charts).
    Chart(ChartWarning),
    /// The body-alone methods' (DATCOM 4.2).
    Body(BodyWarning),
    /// The wing-alone methods' (DATCOM 4.1).
    Wing(WingWarning),
    /// The wing-body methods' (DATCOM 4.3).
    WingBody(WingBodyWarning),
    /// The tails' and the configuration's (DATCOM 4.4-4.5), with their surfaces' as wings.
    Tail(TailWarning),
    /// The sideslip derivatives' (DATCOM 5).
    Lateral(LateralWarning),
    /// The dynamic derivatives' (DATCOM 7).
    Dynamic(DynamicWarning),
    /// The airfoil section method's (DATCOM 4.1.1).
    Section(SectionWarning),
}

/// Where a warning arose, the start of its text.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum Context {
    /// Said of the case as a whole: no prefix.
    Case,
    /// A configuration's or method's name (`wing alone: ...`, `tails: ...`).
    Part(&'static str),
    /// A configuration's sideslip derivatives (`wing-body, sideslip: ...`).
    Sideslip(&'static str),
    /// The dynamic derivatives at a Mach number (`Mach 0.0588: dynamic derivatives: ...`).
    Dynamic { mach: f64 },
    /// A surface's airfoil section (`WING section: ...`).
    Section(Surface),
}

impl Warning {
    /// A warning said of the case as a whole, in words.
    pub fn text(text: impl Into<String>) -> Self {
        Self {
            context: Context::Case,
            detail: Detail::Text(text.into()),
        }
    }

    pub(crate) fn new(context: Context, detail: impl Into<Detail>) -> Self {
        Self {
            context,
            detail: detail.into(),
        }
    }

    /// Each of a method's `warnings`, said under `context`.
    pub(crate) fn all_under<'a, W: Clone + Into<Detail>>(
        context: Context,
        warnings: &'a [W],
    ) -> impl Iterator<Item = Warning> + 'a {
        warnings
            .iter()
            .map(move |w| Warning::new(context, w.clone()))
    }

    /// What the warning says, without where it arose.
    pub fn detail(&self) -> &Detail {
        &self.detail
    }

    /// Where the warning arose, as its text begins (`wing-body, sideslip`, `Mach 0.0588:
    /// dynamic derivatives`, `WING section`); none for a warning of the whole case.
    pub fn label(&self) -> Option<String> {
        (self.context != Context::Case).then(|| self.context.to_string())
    }

    /// The same warning said of part `to` where it was said of part `from` (a page computed
    /// by another configuration's methods, e.g. the horizontal tail in the wing's place).
    pub(crate) fn renamed(self, from: &str, to: &'static str) -> Warning {
        let context = match self.context {
            Context::Part(label) if label == from => Context::Part(to),
            Context::Sideslip(label) if label == from => Context::Sideslip(to),
            other => other,
        };
        Warning { context, ..self }
    }

    /// The chart reading that left the chart's data, when this warning is one (see
    /// [`Detail::chart`]).
    pub fn chart(&self) -> Option<&ChartWarning> {
        self.detail.chart()
    }
}

impl Detail {
    /// The chart reading that left the chart's data, when this warning is one, also inside a
    /// component's warning (the horizontal tail's as a wing, the wing-body's body, ...).
    pub fn chart(&self) -> Option<&ChartWarning> {
        fn body(w: &BodyWarning) -> Option<&ChartWarning> {
            match w {
                BodyWarning::Chart(c) => Some(c),
                _ => None,
            }
        }
        fn wing(w: &WingWarning) -> Option<&ChartWarning> {
            match w {
                WingWarning::Chart(c) => Some(c),
                _ => None,
            }
        }
        fn wing_body(w: &WingBodyWarning) -> Option<&ChartWarning> {
            match w {
                WingBodyWarning::Chart(c) => Some(c),
                WingBodyWarning::Wing(w) => wing(w),
                WingBodyWarning::Body(w) => body(w),
                _ => None,
            }
        }
        match self {
            Detail::Chart(c)
            | Detail::Lateral(LateralWarning::Chart(c))
            | Detail::Dynamic(DynamicWarning::Chart(c)) => Some(c),
            Detail::Body(w) => body(w),
            Detail::Wing(w) => wing(w),
            Detail::WingBody(w) => wing_body(w),
            Detail::Tail(w) => match w {
                TailWarning::Chart(c) => Some(c),
                TailWarning::Wing(w) | TailWarning::HorizontalTail(w) => wing(w),
                TailWarning::WingBody(w) => wing_body(w),
                _ => None,
            },
            _ => None,
        }
    }
}

impl From<String> for Warning {
    fn from(text: String) -> Self {
        Self::text(text)
    }
}

impl From<&str> for Warning {
    fn from(text: &str) -> Self {
        Self::text(text)
    }
}

/// The label a warning's text begins with (nothing for the whole case).
impl fmt::Display for Context {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Context::Case => Ok(()),
            Context::Part(label) => f.write_str(label),
            Context::Sideslip(label) => write!(f, "{label}, sideslip"),
            Context::Dynamic { mach } => {
                write!(
                    f,
                    "Mach {}: dynamic derivatives",
                    crate::charts::Query(*mach)
                )
            }
            Context::Section(surface) => write!(f, "{} section", surface.name()),
        }
    }
}

impl fmt::Display for Warning {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.context != Context::Case {
            write!(f, "{}: ", self.context)?;
        }
        self.detail.fmt(f)
    }
}

impl Serialize for Warning {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.collect_str(self)
    }
}

/// The warnings' texts in order, each said once: two warnings that differ only beyond the
/// printed digits read the same and are written once. (A result's list keeps both: it
/// drops only equal warnings.)
pub fn texts(warnings: &[Warning]) -> Vec<String> {
    let all: Vec<String> = warnings.iter().map(ToString::to_string).collect();
    let mut seen = std::collections::HashSet::with_capacity(all.len());
    let first: Vec<bool> = all.iter().map(|t| seen.insert(t.as_str())).collect();
    all.into_iter()
        .zip(first)
        .filter_map(|(t, first)| first.then_some(t))
        .collect()
}

/// Keeps the first of equal warnings, in order. Warnings are compared only with those of the
/// same [`Warning::fingerprint`], so that a case with a thousand warnings (a build-up at many
/// conditions) is not compared pairwise.
pub(crate) fn dedup(warnings: &mut Vec<Warning>) {
    // The latest kept warning of each fingerprint, and before each kept warning the one of the
    // same fingerprint kept before it.
    let mut latest: HashMap<u64, usize, BuildHasherDefault<IdHasher>> =
        HashMap::with_capacity_and_hasher(warnings.len(), Default::default());
    let mut earlier: Vec<Option<usize>> = Vec::with_capacity(warnings.len());
    let mut kept: Vec<Warning> = Vec::with_capacity(warnings.len());
    for w in warnings.drain(..) {
        let f = w.fingerprint();
        let mut at = latest.get(&f).copied();
        while let Some(k) = at {
            if kept[k] == w {
                break;
            }
            at = earlier[k];
        }
        if at.is_none() {
            earlier.push(latest.insert(f, kept.len()));
            kept.push(w);
        }
    }
    *warnings = kept;
}

impl Warning {
    /// A hash of what identifies most warnings (where, which kind, and the chart reading when
    /// there is one), equal for equal warnings. Numbers are hashed by their bits, so that 0 and
    /// −0 (equal, but printed differently) fall in different groups and are both kept.
    fn fingerprint(&self) -> u64 {
        let mut h = IdHasher::default();
        match &self.context {
            Context::Case => 0u8.hash(&mut h),
            Context::Part(label) => (1u8, label).hash(&mut h),
            Context::Sideslip(label) => (2u8, label).hash(&mut h),
            Context::Dynamic { mach } => (3u8, mach.to_bits()).hash(&mut h),
            Context::Section(surface) => (4u8, surface.name()).hash(&mut h),
        }
        std::mem::discriminant(&self.detail).hash(&mut h);
        match (&self.detail, self.chart()) {
            (Detail::Text(t), _) => t.hash(&mut h),
            (_, Some(c)) => (
                c.chart.as_str(),
                c.variable.as_str(),
                c.value.to_bits(),
                c.min.to_bits(),
                c.max.to_bits(),
            )
                .hash(&mut h),
            _ => {}
        }
        h.finish()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_text_is_the_context_then_the_detail() {
        let w = Warning::new(
            Context::Sideslip("wing-body"),
            LateralWarning::VentralFinLeftOut,
        );
        assert!(w.to_string().starts_with("wing-body, sideslip: "), "{w}");
        let d = Warning::new(Context::Dynamic { mach: 0.0588 }, Detail::Text("x".into()));
        assert_eq!(d.to_string(), "Mach 0.0588: dynamic derivatives: x");
        let s = Warning::new(Context::Section(Surface::Wing), Detail::Text("y".into()));
        assert_eq!(s.to_string(), "WING section: y");
        assert_eq!(Warning::text("z").to_string(), "z");
    }

    #[test]
    fn a_chart_reading_is_found_inside_a_components_warning() {
        let reading = ChartWarning {
            chart: "4.1.3.3-55a".into(),
            variable: "tan_ratio".into(),
            value: 0.1053,
            min: 0.2,
            max: 1.0,
            action: crate::charts::Outside::Linear,
        };
        let nested = Warning::new(
            Context::Part("tails"),
            TailWarning::HorizontalTail(WingWarning::Chart(reading.clone())),
        );
        assert_eq!(nested.chart(), Some(&reading));
        let other = Warning::new(Context::Part("tails"), TailWarning::NoTailMoment);
        assert_eq!(other.chart(), None);
        assert_eq!(Warning::text("x").chart(), None);
    }

    /// A chart reading of `value` under "tails", printed to four digits.
    fn reading(value: f64) -> Warning {
        Warning::new(
            Context::Part("tails"),
            ChartWarning {
                chart: "4.1.3.3-55a".into(),
                variable: "tan_ratio".into(),
                value,
                min: 0.2,
                max: 1.0,
                action: crate::charts::Outside::Linear,
            },
        )
    }

    #[test]
    fn results_keep_unequal_warnings_and_the_writers_say_a_text_once_in_order() {
        // Two readings that differ beyond the printed digits: unequal, one text.
        let (near, nearer) = (reading(0.10533), reading(0.10534));
        assert_ne!(near, nearer);
        assert_eq!(near.to_string(), nearer.to_string());
        let mut list = vec![
            Warning::text("b"),
            near.clone(),
            Warning::text("a"),
            nearer.clone(),
            Warning::text("b"),
        ];
        dedup(&mut list);
        // The equal repeat of "b" goes; both readings stay.
        assert_eq!(
            list,
            vec![Warning::text("b"), near.clone(), Warning::text("a"), nearer]
        );
        // Written once each, first occurrences in order (not sorted).
        assert_eq!(
            texts(&list),
            vec!["b".to_string(), near.to_string(), "a".to_string()]
        );
    }

    #[test]
    fn zero_and_minus_zero_are_both_kept() {
        // Equal numbers printed differently ("Mach 0" and "Mach -0"): both stay, as texts.
        let zero = Warning::new(Context::Dynamic { mach: 0.0 }, Detail::Text("x".into()));
        let minus = Warning::new(Context::Dynamic { mach: -0.0 }, Detail::Text("x".into()));
        assert_eq!(zero, minus);
        let mut list = vec![zero.clone(), minus.clone()];
        dedup(&mut list);
        assert_eq!(list.len(), 2);
        assert_eq!(texts(&list).len(), 2, "{:?}", texts(&list));
    }

    #[test]
    fn many_warnings_are_deduplicated_in_order() {
        // A thousand warnings, each value three times: the first of each kept, in order.
        let values: Vec<f64> = (0..1000).map(|k| 0.3 + f64::from(k) * 1e-3).collect();
        let mut list: Vec<Warning> = (0..3)
            .flat_map(|_| values.iter().map(|&v| reading(v)))
            .collect();
        dedup(&mut list);
        let expected: Vec<Warning> = values.iter().map(|&v| reading(v)).collect();
        assert_eq!(list, expected);
    }

    #[test]
    fn a_warning_is_said_of_another_part_by_its_context() {
        let w = Warning::new(Context::Sideslip("wing-body"), LateralWarning::NoBodyAtFin)
            .renamed("wing-body", "body-horizontal tail");
        assert_eq!(w.label().as_deref(), Some("body-horizontal tail, sideslip"));
        assert_eq!(Warning::text("x").label(), None);
        let other = Warning::new(Context::Part("tails"), LateralWarning::NoBodyAtFin)
            .renamed("wing-body", "body-horizontal tail");
        assert_eq!(other.label().as_deref(), Some("tails"));
    }
}
