//! Dynamic derivatives at subsonic speeds (the DAMP card): CLq, Cmq, CLα̇, Cmα̇, Clp, CYp, Cnp,
//! Cnr and Clr of the original's DYNAMIC DERIVATIVES pages, component by component.
//!
//! Methods (DATCOM sections; the original's routines):
//! - body alone, 7.2.1.1, 7.2.1.2, 7.2.2.1, 7.2.2.2 (DYNBOD): pitch-rate and α̇ derivatives
//!   from the body's lift and moment slopes, its volume and centroid; module `body`;
//! - wing and horizontal tail alone: pitch rate 7.1.1.1, 7.1.1.2 and α̇ 7.1.4.1, 7.1.4.2 with the
//!   Mach-0 aerodynamic centre (CMALPO, SUBPAW, SUBPAH); roll rate 7.1.2.1 (CYp), 7.1.2.2 (Clp),
//!   7.1.2.3 (Cnp); yaw rate 7.1.3.3 (Cnr) (SUBRYW, SUBHYW) and 7.1.3.2 (Clr, CLRDER); module
//!   `surface`;
//! - wing-body 7.3 (DNPAWB), wing-body-horizontal tail 7.4.1.1, 7.4.4.1 (DNPWBT), vertical tail
//!   and ventral fin 7.4.2.1, 7.4.2.2, 7.4.3.1, 7.4.3.2 (SUBWBT, CLRDER) and the configuration
//!   totals (M46O56, CLRDER); module `configuration`.
//!
//! Every value is per radian of the rate (q c̄/2V, p b/2V, r b/2V, α̇ c̄/2V) and of α, on the
//! reference area, chord (pitch) and lateral reference length (roll, yaw), about XCG, ZCG.
//! A column for which DATCOM has no method in a configuration is [`Column::NoMethod`] (the
//! original prints NDM). Where this differs from the original, see `docs/dynamic.md`.

mod body;
mod configuration;
pub mod figures;
mod surface;

use std::fmt;

use serde::Serialize;

use crate::charts::ChartWarning;

pub use body::body_dynamic;
pub use configuration::{
    fin_dynamic, wing_body_dynamic, wing_body_tail_dynamic, ConfigurationDynamic, TailConfiguration,
};
pub use surface::{horizontal_tail_dynamic, wing_dynamic, RollIncrements, SurfaceDynamicTerms};

/// Degrees per radian: the original's methods and charts work per degree.
pub(crate) const DEG_PER_RAD: f64 = 180.0 / std::f64::consts::PI;

/// Why the dynamic derivatives cannot be computed.
#[derive(Debug, Clone, PartialEq, thiserror::Error, Serialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
#[non_exhaustive]
pub enum DynamicError {
    #[error("no flight condition {index} (a case's conditions are derived from its flight input by Case::prepare)")]
    NoCondition { index: usize },
    #[error("the {what} results have {found} angles of attack, the schedule has {expected}")]
    AngleCount {
        what: &'static str,
        expected: usize,
        found: usize,
    },
    #[error("{reason}")]
    Geometry { reason: String },
    #[error("chart {chart} is not embedded or not valid")]
    MissingChart { chart: &'static str },
    #[error(
        "chart {chart} gives no value at {}",
        crate::charts::describe_query(chart, args)
    )]
    ChartNoValue { chart: &'static str, args: Vec<f64> },
}

/// What the caller should know about a result.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
#[non_exhaustive]
pub enum DynamicWarning {
    /// A chart was read outside its data.
    Chart(ChartWarning),
    /// A derivative could not be computed (a missing static input), with the reason.
    NotComputed {
        derivative: &'static str,
        reason: String,
    },
    /// The exposed planform is not triangular, or βA > 4: DATCOM has no α̇ method (NDM).
    NoAlphaDotMethod,
    /// The body covers more than 30 % of the semispan: the original gives no roll and yaw
    /// derivatives of the surface (NDM).
    BodyTooWide { fraction: f64 },
    /// A forward-swept quarter chord: no Clr method (NDM).
    ForwardSweep,
    /// Under the original's forward-sweep reading, a fin's Clp and Clr with a forward-swept
    /// wing: left out (NDM), as the original skips them.
    FinRollTermsLeftOut,
    /// The body's nose or tail is not of the nose-cylinder type the body method assumes.
    BodyShape,
    /// A ventral fin without a horizontal tail: its terms are left out
    /// ([`crate::methods::lateral::ventral_fin_left_out`]).
    VentralFinLeftOut,
}

impl fmt::Display for DynamicWarning {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            DynamicWarning::Chart(w) => write!(f, "{w}"),
            DynamicWarning::NotComputed { derivative, reason } => {
                write!(f, "{derivative} not computed: {reason}")
            }
            DynamicWarning::VentralFinLeftOut => {
                f.write_str(crate::methods::lateral::VENTRAL_FIN_LEFT_OUT)
            }
            DynamicWarning::NoAlphaDotMethod => write!(
                f,
                "the wing's (or tail's) own CLAD and CMAD: DATCOM's α̇ method is for triangular planforms with βA ≤ 4 only (NDM; a configuration with a horizontal tail still has the tail's downwash-lag terms)"
            ),
            DynamicWarning::BodyTooWide { fraction } => write!(
                f,
                "the body covers {:.0} % of the semispan (more than 30 %): no roll and yaw rate derivatives of the surface (NDM), as the original",
                100.0 * fraction
            ),
            DynamicWarning::ForwardSweep => write!(
                f,
                "forward-swept quarter chord: no CLR method (NDM), as the original; nor for a configuration with it"
            ),
            DynamicWarning::FinRollTermsLeftOut => write!(
                f,
                "the vertical panels' CLP and CLR are left out with a forward-swept wing, as the original (--forward-sweep original)"
            ),
            DynamicWarning::BodyShape => write!(
                f,
                "the body dynamic-derivative method is valid for a nose-cylinder body only (BTAIL given)"
            ),
        }
    }
}

/// One derivative against angle of attack.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(tag = "kind", content = "values", rename_all = "snake_case")]
pub enum Column {
    /// DATCOM has no method for this derivative here (the original prints NDM).
    NoMethod,
    /// Per radian at each angle; `None` where the derivative is not computed or, for the
    /// derivatives the original gives once per configuration, after the first row.
    Rows(Vec<Option<f64>>),
}

impl Column {
    /// A value on the first row only.
    pub fn first(n: usize, v: Option<f64>) -> Column {
        let mut rows = vec![None; n];
        if n > 0 {
            rows[0] = v.filter(|x| x.is_finite());
        }
        Column::Rows(rows)
    }

    /// A value at every row.
    pub fn rows(values: Vec<Option<f64>>) -> Column {
        Column::Rows(
            values
                .into_iter()
                .map(|v| v.filter(|x| x.is_finite()))
                .collect(),
        )
    }

    /// The value at row `k` (none for NoMethod).
    pub fn at(&self, k: usize) -> Option<f64> {
        match self {
            Column::NoMethod => None,
            Column::Rows(r) => r.get(k).copied().flatten(),
        }
    }

    /// The sum of columns as the original forms a configuration's: a term without a method
    /// adds nothing (the original's 1E-30 placeholder); no method in every term is no method;
    /// a row is computed where every term with a method is.
    pub fn sum(parts: &[&Column], n: usize) -> Column {
        let with: Vec<&Vec<Option<f64>>> = parts
            .iter()
            .filter_map(|c| match c {
                Column::Rows(r) => Some(r),
                Column::NoMethod => None,
            })
            .collect();
        if with.is_empty() {
            return Column::NoMethod;
        }
        Column::rows(
            (0..n)
                .map(|k| {
                    with.iter()
                        .map(|r| r.get(k).copied().flatten())
                        .sum::<Option<f64>>()
                })
                .collect(),
        )
    }

    /// The first row kept, the others blank.
    pub fn first_row_only(self) -> Column {
        match self {
            Column::NoMethod => Column::NoMethod,
            Column::Rows(mut r) => {
                for v in r.iter_mut().skip(1) {
                    *v = None;
                }
                Column::Rows(r)
            }
        }
    }
}

/// The nine dynamic derivatives of one configuration at one flight condition.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Dynamic {
    pub alpha_deg: Vec<f64>,
    pub clq: Column,
    pub cmq: Column,
    pub clad: Column,
    pub cmad: Column,
    pub clp: Column,
    pub cyp: Column,
    pub cnp: Column,
    pub cnr: Column,
    pub clr: Column,
    /// Extension, not printed by the original: the side force due to yaw rate CYr of the
    /// vertical panels, −2 (l cos α + z sin α)/b · CYβ per panel, the side force whose yawing
    /// and rolling moments are the panels' Cnr and Clr ([`fin_dynamic`]). No method elsewhere
    /// (DATCOM gives none for the wing and body).
    pub cyr: Column,
    pub warnings: Vec<DynamicWarning>,
}

impl Dynamic {
    /// Every derivative without a method.
    pub fn no_method(alpha_deg: &[f64]) -> Dynamic {
        Dynamic {
            alpha_deg: alpha_deg.to_vec(),
            clq: Column::NoMethod,
            cmq: Column::NoMethod,
            clad: Column::NoMethod,
            cmad: Column::NoMethod,
            clp: Column::NoMethod,
            cyp: Column::NoMethod,
            cnp: Column::NoMethod,
            cnr: Column::NoMethod,
            clr: Column::NoMethod,
            cyr: Column::NoMethod,
            warnings: Vec::new(),
        }
    }

    /// The columns in page order with the page's names.
    pub fn columns(&self) -> [(&'static str, &Column); 9] {
        [
            ("CLQ", &self.clq),
            ("CMQ", &self.cmq),
            ("CLAD", &self.clad),
            ("CMAD", &self.cmad),
            ("CLP", &self.clp),
            ("CYP", &self.cyp),
            ("CNP", &self.cnp),
            ("CNR", &self.cnr),
            ("CLR", &self.clr),
        ]
    }
}

/// A finite value, else none.
fn finite(v: f64) -> Option<f64> {
    v.is_finite().then_some(v)
}
