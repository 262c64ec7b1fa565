//! A run's warnings, kept as what the methods found (their typed warnings, with where they
//! arose) and put into words only when they are read. A design tool that runs thousands of
//! variants and reads no warning text does not pay for formatting it; one that does can match
//! on [`Detail`] instead of parsing text.

use std::fmt;

use serde::{Serialize, Serializer};

use crate::charts::ChartWarning;
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

/// What a warning says: a method's own warning, or text.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum Detail {
    Text(String),
    Chart(ChartWarning),
    Body(BodyWarning),
    Wing(WingWarning),
    WingBody(WingBodyWarning),
    Tail(TailWarning),
    Lateral(LateralWarning),
    Dynamic(DynamicWarning),
    Section(SectionWarning),
}

/// Where a warning arose, the start of its text.
#[derive(Debug, Clone, PartialEq)]
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

    /// What the warning says, without where it arose.
    pub fn detail(&self) -> &Detail {
        &self.detail
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

macro_rules! detail_from {
    ($($variant:ident($ty:ty)),* $(,)?) => {
        $(impl From<$ty> for Detail {
            fn from(w: $ty) -> Self {
                Detail::$variant(w)
            }
        })*
    };
}

detail_from!(
    Text(String),
    Chart(ChartWarning),
    Body(BodyWarning),
    Wing(WingWarning),
    WingBody(WingBodyWarning),
    Tail(TailWarning),
    Lateral(LateralWarning),
    Dynamic(DynamicWarning),
    Section(SectionWarning),
);

impl fmt::Display for Detail {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Detail::Text(t) => f.write_str(t),
            Detail::Chart(w) => w.fmt(f),
            Detail::Body(w) => w.fmt(f),
            Detail::Wing(w) => w.fmt(f),
            Detail::WingBody(w) => w.fmt(f),
            Detail::Tail(w) => w.fmt(f),
            Detail::Lateral(w) => w.fmt(f),
            Detail::Dynamic(w) => w.fmt(f),
            Detail::Section(w) => w.fmt(f),
        }
    }
}

impl fmt::Display for Warning {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match &self.context {
            Context::Case => {}
            Context::Part(label) => write!(f, "{label}: ")?,
            Context::Sideslip(label) => write!(f, "{label}, sideslip: ")?,
            Context::Dynamic { mach } => write!(f, "Mach {mach}: dynamic derivatives: ")?,
            Context::Section(surface) => write!(f, "{} section: ", surface.name())?,
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
/// printed digits read the same and are written once.
pub fn texts(warnings: &[Warning]) -> Vec<String> {
    let mut seen = std::collections::BTreeSet::new();
    warnings
        .iter()
        .map(ToString::to_string)
        .filter(|t| seen.insert(t.clone()))
        .collect()
}

/// Keeps the first of equal warnings, in order.
pub(crate) fn dedup(warnings: &mut Vec<Warning>) {
    let mut kept: Vec<Warning> = Vec::with_capacity(warnings.len());
    for w in warnings.drain(..) {
        if !kept.contains(&w) {
            kept.push(w);
        }
    }
    *warnings = kept;
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

    #[test]
    fn equal_texts_are_written_once_and_equal_warnings_kept_once() {
        let a = Warning::text("a");
        let b = Warning::new(Context::Part("wing alone"), Detail::Text("a".into()));
        let mut list = vec![a.clone(), b.clone(), a.clone()];
        dedup(&mut list);
        assert_eq!(list, vec![a.clone(), b.clone()]);
        // Different warnings with one text: written once.
        let same_text = vec![a.clone(), Warning::text("a"), b];
        assert_eq!(
            texts(&same_text),
            vec!["a".to_string(), "wing alone: a".into()]
        );
    }
}
