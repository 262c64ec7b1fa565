//! JSBSim export (docs/jsbsim.md): a case's coefficients as a JSBSim `<aerodynamics>` section,
//! one `aero/coefficient/<Name>` function per DATCOM term, each a product of JSBSim's standard
//! properties and a table over `aero/alpha-rad` (and `velocities/mach` when the case has several
//! Mach numbers); or a whole minimal aircraft around it, so the export can be flown.
//!
//! This is an output edge: SI inside becomes feet, pounds and slugs here. Coefficients are
//! dimensionless and per radian, as JSBSim wants them, so only the reference dimensions, the
//! positions, the weight and the inertias are converted.
//!
//! Nothing is padded silently: a term without a value at some angle is tabulated over the
//! longest run of angles where it has one, and the file's header says so, term by term (JSBSim
//! holds a table's end value beyond it). No NaN or infinity is ever written.

use std::fmt::Write as _;

use crate::case::Case;
use crate::results::{CaseResults, ConditionResults, ReferenceDimensions};

/// JSBSim's units in SI (exact by definition of the foot, the pound and the slug).
pub const M_PER_FT: f64 = 0.3048;
pub const M_PER_IN: f64 = 0.0254;
pub const N_PER_LBF: f64 = 4.448_221_615_260_5;
pub const KGM2_PER_SLUGFT2: f64 = 1.355_817_948_331_400_4;
const STANDARD_GRAVITY: f64 = 9.806_65;

/// Roskam, Airplane Design Part V (1985), non-dimensional radii of gyration of single-engine
/// propeller aeroplanes: I = (W/g)·(R̄·d/2)² with d the span (roll), the length (pitch) and their
/// mean (yaw). An estimate only, used when no inertias are given.
const ROSKAM_RADII: [f64; 3] = [0.25, 0.38, 0.39];

/// Why a case cannot be exported.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum ExportError {
    #[error("case {case} is not in the deck ({count} case(s))")]
    NoSuchCase { case: usize, count: usize },
    #[error("case {case}: no flight condition was computed (no $FLTCON with Mach numbers and angles of attack)")]
    NoConditions { case: usize },
    #[error("case {case}: the build-up has no page for its configuration {configuration} (only the pages of its largest parts): nothing to export for the whole aircraft")]
    NoWholeConfiguration { case: usize, configuration: String },
    #[error("case {case}: the angles of attack {alpha_deg:?} are not strictly increasing, as JSBSim tables need")]
    AlphaNotIncreasing { case: usize, alpha_deg: Vec<f64> },
    #[error("case {case}: nothing to export: the {configuration} has no coefficient with a value (see the warnings of `datcom-rs run`)")]
    NothingExportable { case: usize, configuration: String },
    #[error("case {case}: no reference {what} (give it in $OPTINS, or a wing)")]
    MissingReference { case: usize, what: &'static str },
    #[error("case {case}: no weight (give WT in $FLTCON, or a weight)")]
    MissingWeight { case: usize },
    #[error("case {case}: no body and no surface positions to estimate the inertias from (give the inertias)")]
    NoLengthForInertia { case: usize },
    #[error("aircraft name {name:?}: use letters, digits, '-', '_' or '.', not starting with '.'")]
    BadName { name: String },
    #[error("{what} must be positive and finite, not {value}")]
    BadValue { what: &'static str, value: f64 },
}

/// JSBSim's force and moment axes (wind axes for the forces, body axes for the moments).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Axis {
    Lift,
    Drag,
    Side,
    Roll,
    Pitch,
    Yaw,
}

impl Axis {
    pub const ALL: [Axis; 6] = [
        Axis::Lift,
        Axis::Drag,
        Axis::Side,
        Axis::Roll,
        Axis::Pitch,
        Axis::Yaw,
    ];

    pub fn name(self) -> &'static str {
        match self {
            Axis::Lift => "LIFT",
            Axis::Drag => "DRAG",
            Axis::Side => "SIDE",
            Axis::Roll => "ROLL",
            Axis::Pitch => "PITCH",
            Axis::Yaw => "YAW",
        }
    }
}

/// A result column of [`ConditionResults`] that a term reads.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Column {
    Cl,
    Cd,
    Cm,
    Cyb,
    Cnb,
    Clb,
    Clq,
    Cmq,
    Clad,
    Cmad,
    Clp,
    Cyp,
    Cnp,
    Cnr,
    Clr,
}

impl Column {
    /// The column's name on the original's pages (and in `run`'s JSON).
    fn label(self) -> &'static str {
        match self {
            Column::Cl => "CL",
            Column::Cd => "CD",
            Column::Cm => "CM",
            Column::Cyb => "CYB",
            Column::Cnb => "CNB",
            Column::Clb => "CLB",
            Column::Clq => "CLQ",
            Column::Cmq => "CMQ",
            Column::Clad => "CLAD",
            Column::Cmad => "CMAD",
            Column::Clp => "CLP",
            Column::Cyp => "CYP",
            Column::Cnp => "CNP",
            Column::Cnr => "CNR",
            Column::Clr => "CLR",
        }
    }

    /// The page of the original's listing that prints the column.
    fn page(self) -> &'static str {
        match self {
            Column::Cl | Column::Cd | Column::Cm | Column::Cyb | Column::Cnb | Column::Clb => {
                "static"
            }
            _ => "dynamic",
        }
    }

    /// The column's values, or why there are none.
    fn values(self, c: &ConditionResults) -> Result<&[Option<f64>], &'static str> {
        c.column(self.label())
            .ok_or("no DAMP card: dynamic derivatives not computed")
    }

    fn no_method(self, c: &ConditionResults) -> bool {
        c.dynamic
            .as_ref()
            .is_some_and(|d| d.no_method.contains(&self.label()))
    }

    /// Static coefficients are functions of α; a derivative may be one value per
    /// configuration (DATCOM prints it on the first angle only).
    fn is_derivative(self) -> bool {
        !matches!(self, Column::Cl | Column::Cd | Column::Cm)
    }
}

const QBAR: &str = "aero/qbar-psf";
const AREA: &str = "metrics/Sw-sqft";
const SPAN: &str = "metrics/bw-ft";
const CHORD: &str = "metrics/cbarw-ft";
const BI2VEL: &str = "aero/bi2vel";
const CI2VEL: &str = "aero/ci2vel";
const BETA: &str = "aero/beta-rad";
const ALPHADOT: &str = "aero/alphadot-rad_sec";
const P: &str = "velocities/p-aero-rad_sec";
const Q: &str = "velocities/q-aero-rad_sec";
const R: &str = "velocities/r-aero-rad_sec";
/// The table indices.
pub const ALPHA_PROPERTY: &str = "aero/alpha-rad";
pub const MACH_PROPERTY: &str = "velocities/mach";

/// One term of the export: its axis, function name, the properties it multiplies and where
/// its coefficient comes from.
struct Term {
    axis: Axis,
    name: &'static str,
    column: Column,
    factors: &'static [&'static str],
    what: &'static str,
    source: &'static str,
}

const STATIC_4: &str = "DATCOM section 4 (4.1 wing, 4.2 body, 4.3 wing-body, 4.5 with tails)";
const SIDESLIP_5: &str =
    "DATCOM section 5 (5.1.2.1 wing, 5.2.1.1 body, 5.2.2.1 and 5.2.3.1 wing-body, 5.3.1.1 tails)";

const TERMS: [Term; 15] = [
    Term {
        axis: Axis::Lift,
        name: "CL",
        column: Column::Cl,
        factors: &[QBAR, AREA],
        what: "lift coefficient CL(alpha)",
        source: STATIC_4,
    },
    Term {
        axis: Axis::Lift,
        name: "CLq",
        column: Column::Clq,
        factors: &[QBAR, AREA, CI2VEL, Q],
        what: "lift due to pitch rate CLq, per unit q.c/2V",
        source: "DATCOM 7.1.1, 7.2.1, 7.4.1.1",
    },
    Term {
        axis: Axis::Lift,
        name: "CLadot",
        column: Column::Clad,
        factors: &[QBAR, AREA, CI2VEL, ALPHADOT],
        what: "lift due to alpha-dot CLalphadot, per unit alphadot.c/2V",
        source: "DATCOM 7.1.4, 7.2.2, 7.4.4.1",
    },
    Term {
        axis: Axis::Drag,
        name: "CD",
        column: Column::Cd,
        factors: &[QBAR, AREA],
        what: "drag coefficient CD(alpha)",
        source: STATIC_4,
    },
    Term {
        axis: Axis::Side,
        name: "CYb",
        column: Column::Cyb,
        factors: &[QBAR, AREA, BETA],
        what: "side force due to sideslip CYbeta",
        source: SIDESLIP_5,
    },
    Term {
        axis: Axis::Side,
        name: "CYp",
        column: Column::Cyp,
        factors: &[QBAR, AREA, BI2VEL, P],
        what: "side force due to roll rate CYp, per unit p.b/2V",
        source: "DATCOM 7.1.2.1, 7.4.2.2",
    },
    Term {
        axis: Axis::Roll,
        name: "Clb",
        column: Column::Clb,
        factors: &[QBAR, AREA, SPAN, BETA],
        what: "rolling moment due to sideslip Clbeta(alpha)",
        source: SIDESLIP_5,
    },
    Term {
        axis: Axis::Roll,
        name: "Clp",
        column: Column::Clp,
        factors: &[QBAR, AREA, SPAN, BI2VEL, P],
        what: "roll damping Clp, per unit p.b/2V",
        source: "DATCOM 7.1.2.2, 7.4.2.1",
    },
    Term {
        axis: Axis::Roll,
        name: "Clr",
        column: Column::Clr,
        factors: &[QBAR, AREA, SPAN, BI2VEL, R],
        what: "rolling moment due to yaw rate Clr, per unit r.b/2V",
        source: "DATCOM 7.1.3.2, 7.4.3.2",
    },
    Term {
        axis: Axis::Pitch,
        name: "Cm",
        column: Column::Cm,
        factors: &[QBAR, AREA, CHORD],
        what: "pitching moment coefficient Cm(alpha) about the moment reference centre",
        source: "DATCOM section 4 (4.1.4 wing, 4.2.2 body, 4.3.2 wing-body, 4.5.2 with tails)",
    },
    Term {
        axis: Axis::Pitch,
        name: "Cmq",
        column: Column::Cmq,
        factors: &[QBAR, AREA, CHORD, CI2VEL, Q],
        what: "pitch damping Cmq, per unit q.c/2V",
        source: "DATCOM 7.1.1, 7.2.1, 7.4.1.1",
    },
    Term {
        axis: Axis::Pitch,
        name: "Cmadot",
        column: Column::Cmad,
        factors: &[QBAR, AREA, CHORD, CI2VEL, ALPHADOT],
        what: "pitching moment due to alpha-dot Cmalphadot, per unit alphadot.c/2V",
        source: "DATCOM 7.1.4, 7.2.2, 7.4.4.1",
    },
    Term {
        axis: Axis::Yaw,
        name: "Cnb",
        column: Column::Cnb,
        factors: &[QBAR, AREA, SPAN, BETA],
        what: "yawing moment due to sideslip Cnbeta",
        source: SIDESLIP_5,
    },
    Term {
        axis: Axis::Yaw,
        name: "Cnp",
        column: Column::Cnp,
        factors: &[QBAR, AREA, SPAN, BI2VEL, P],
        what: "yawing moment due to roll rate Cnp, per unit p.b/2V",
        source: "DATCOM 7.1.2.3, 7.4.2.2",
    },
    Term {
        axis: Axis::Yaw,
        name: "Cnr",
        column: Column::Cnr,
        factors: &[QBAR, AREA, SPAN, BI2VEL, R],
        what: "yaw damping Cnr, per unit r.b/2V",
        source: "DATCOM 7.1.3.3, 7.4.3.1",
    },
];

/// What a function's coefficient is: one value, a table over Mach, or a table over α (rows)
/// and Mach (columns, one when the export has one Mach number).
#[derive(Debug, Clone, PartialEq)]
pub enum Coefficient {
    Constant(f64),
    OverMach {
        mach: Vec<f64>,
        values: Vec<f64>,
    },
    OverAlpha {
        alpha_rad: Vec<f64>,
        mach: Vec<f64>,
        /// `values[row][column]`: row an angle, column a Mach number.
        values: Vec<Vec<f64>>,
    },
}

/// One `aero/coefficient/<name>` function.
#[derive(Debug, Clone, PartialEq)]
pub struct Function {
    pub axis: Axis,
    /// The name after `aero/coefficient/`.
    pub name: &'static str,
    /// The DATCOM column it comes from (`CL`, `CYB`, `CLP` ...).
    pub column: &'static str,
    pub description: String,
    /// The JSBSim properties the coefficient is multiplied by.
    pub factors: &'static [&'static str],
    pub coefficient: Coefficient,
    /// What was done where DATCOM gives no value at some angle (the table cut to the angles
    /// where it has one), or `None` when the table is complete.
    pub cut: Option<String>,
}

/// The aerodynamics of one case, ready to write.
#[derive(Debug, Clone, PartialEq)]
pub struct AeroModel {
    pub deck: String,
    pub case: usize,
    pub caseid: Option<String>,
    pub configuration: String,
    /// The Mach numbers of the tables, increasing.
    pub mach: Vec<f64>,
    /// The altitude of the flight conditions used, m (`None` when the deck gives none).
    pub altitude_m: Option<f64>,
    /// SI, as in the results.
    pub reference: ReferenceDimensions,
    /// The deck's angles of attack, deg.
    pub alpha_deg: Vec<f64>,
    pub functions: Vec<Function>,
    /// Terms not exported, with the reason.
    pub omitted: Vec<String>,
    /// Flight conditions of the case not used, with the reason.
    pub conditions_not_used: Vec<String>,
}

/// The flight conditions the export uses: for each condition the last configuration entry
/// (the case's most complete configuration), at the first altitude, one per Mach number,
/// sorted by Mach; and what was left out, with the reason.
pub fn conditions(
    results: &CaseResults,
) -> Result<(Vec<&ConditionResults>, Vec<String>), ExportError> {
    let case = results.number;
    let last = results.most_complete();
    if last.is_empty() && !results.conditions.is_empty() {
        return Err(ExportError::NoWholeConfiguration {
            case,
            configuration: results.configuration.clone(),
        });
    }
    let first_altitude = last
        .iter()
        .map(|c| c.condition.altitude_index)
        .min()
        .ok_or(ExportError::NoConditions { case })?;
    let mut used: Vec<&ConditionResults> = Vec::new();
    let mut not_used = Vec::new();
    let describe = |c: &ConditionResults| match c.condition.altitude {
        Some(h) => format!("Mach {} at {} m", num(c.condition.mach), num(h)),
        None => format!("Mach {}", num(c.condition.mach)),
    };
    // A condition where no exported term has a value (a Mach number beyond the methods'
    // range) is left out, not allowed to empty every term's table.
    let has_values = |c: &ConditionResults| {
        TERMS.iter().any(|t| {
            t.column
                .values(c)
                .is_ok_and(|v| v.iter().any(|x| x.is_some_and(f64::is_finite)))
        })
    };
    for &c in &last {
        if c.condition.altitude_index != first_altitude {
            not_used.push(format!(
                "{}: only the first altitude is exported",
                describe(c)
            ));
        } else if used.iter().any(|u| u.condition.mach == c.condition.mach) {
            not_used.push(format!(
                "{}: its Mach number is already exported",
                describe(c)
            ));
        } else if !has_values(c) {
            not_used.push(format!(
                "{}: no coefficient has a value (see the warnings of `datcom-rs run`)",
                describe(c)
            ));
        } else {
            used.push(c);
        }
    }
    if used.is_empty() {
        let conditions: Vec<String> = last.iter().map(|c| describe(c)).collect();
        return Err(ExportError::NothingExportable {
            case,
            configuration: format!(
                "{} ({})",
                results.configuration.to_lowercase(),
                conditions.join("; ")
            ),
        });
    }
    used.sort_by(|a, b| a.condition.mach.total_cmp(&b.condition.mach));
    let alpha = &used[0].alpha_deg;
    if alpha.windows(2).any(|w| w[1] <= w[0]) || alpha.iter().any(|a| !a.is_finite()) {
        return Err(ExportError::AlphaNotIncreasing {
            case,
            alpha_deg: alpha.clone(),
        });
    }
    Ok((used, not_used))
}

/// The longest run of consecutive indices where `ok` holds (the first of equal ones).
fn longest_run(n: usize, ok: impl Fn(usize) -> bool) -> std::ops::Range<usize> {
    let mut best = 0..0;
    let mut start = None;
    for i in 0..=n {
        match (i < n && ok(i), start) {
            (true, None) => start = Some(i),
            (false, Some(s)) => {
                if i - s > best.len() {
                    best = s..i;
                }
                start = None;
            }
            _ => {}
        }
    }
    best
}

fn degrees(list: &[f64]) -> String {
    list.iter().map(|a| num(*a)).collect::<Vec<_>>().join(", ")
}

/// A term's coefficient from the selected conditions, with what was cut; `Err` says why the
/// term is not exported.
fn coefficient(
    term: &Term,
    conditions: &[&ConditionResults],
    alpha_deg: &[f64],
) -> Result<(Coefficient, Option<String>), String> {
    let label = term.column.label();
    if conditions.iter().any(|c| term.column.no_method(c)) {
        return Err(format!(
            "{}: NDM, DATCOM has no method for {label} in this configuration",
            term.name
        ));
    }
    let columns = conditions
        .iter()
        .map(|c| term.column.values(c))
        .collect::<Result<Vec<_>, _>>()
        .map_err(|why| format!("{}: {why}", term.name))?;
    let n = alpha_deg.len();
    let mach: Vec<f64> = conditions.iter().map(|c| c.condition.mach).collect();
    let at = |i: usize, m: usize| columns[m].get(i).copied().flatten();
    let ok = |i: usize| (0..mach.len()).all(|m| at(i, m).is_some_and(f64::is_finite));
    let first_row_only =
        n > 1 && ok(0) && (1..n).all(|i| (0..mach.len()).all(|m| at(i, m).is_none()));
    let one_value = |i: usize, note: Option<String>| {
        let values: Vec<f64> = (0..mach.len()).filter_map(|m| at(i, m)).collect();
        let c = if mach.len() == 1 {
            Coefficient::Constant(values[0])
        } else {
            Coefficient::OverMach {
                mach: mach.clone(),
                values,
            }
        };
        Ok((c, note))
    };
    if term.column.is_derivative() && (first_row_only || n == 1) && ok(0) {
        // DATCOM gives one value per configuration (on the first angle): a constant.
        return one_value(0, None);
    }
    let run = longest_run(n, ok);
    if run.is_empty() {
        return Err(format!(
            "{}: {label} has no value at any angle of attack",
            term.name
        ));
    }
    let cut = (run.len() < n).then(|| {
        let missing: Vec<f64> = (0..n).filter(|&i| !ok(i)).map(|i| alpha_deg[i]).collect();
        let dropped: Vec<f64> = (0..n)
            .filter(|&i| ok(i) && !run.contains(&i))
            .map(|i| alpha_deg[i])
            .collect();
        let mut s = format!(
            "{}: {label} has no value at alpha = {} deg; ",
            term.name,
            degrees(&missing)
        );
        if run.len() == 1 {
            let _ = write!(
                s,
                "exported as the constant at alpha = {} deg",
                num(alpha_deg[run.start])
            );
        } else {
            let _ = write!(
                s,
                "tabulated for alpha = {} to {} deg only, JSBSim holds the end values beyond",
                num(alpha_deg[run.start]),
                num(alpha_deg[run.end - 1])
            );
        }
        if !dropped.is_empty() {
            let _ = write!(
                s,
                " (values at alpha = {} deg, beyond the gap, left out)",
                degrees(&dropped)
            );
        }
        s
    });
    if run.len() == 1 {
        return one_value(run.start, cut);
    }
    let alpha_rad = run.clone().map(|i| alpha_deg[i].to_radians()).collect();
    let values = run
        .map(|i| (0..mach.len()).filter_map(|m| at(i, m)).collect())
        .collect();
    Ok((
        Coefficient::OverAlpha {
            alpha_rad,
            mach,
            values,
        },
        cut,
    ))
}

/// The aerodynamics of a case: the last configuration of each of its flight conditions at the
/// first altitude.
pub fn model(deck: &str, results: &CaseResults) -> Result<AeroModel, ExportError> {
    let (conditions, conditions_not_used) = conditions(results)?;
    let first = conditions[0];
    let alpha_deg = first.alpha_deg.clone();
    let mut functions = Vec::new();
    let mut omitted = Vec::new();
    for term in &TERMS {
        match coefficient(term, &conditions, &alpha_deg) {
            Ok((coefficient, cut)) => functions.push(Function {
                axis: term.axis,
                name: term.name,
                column: term.column.label(),
                description: format!(
                    "{}: {}; {}; {}, {} page column {}",
                    term.name,
                    term.what,
                    first.configuration.to_lowercase(),
                    term.source,
                    term.column.page(),
                    term.column.label()
                ),
                factors: term.factors,
                coefficient,
                cut,
            }),
            Err(why) => omitted.push(why),
        }
    }
    if functions.is_empty() {
        return Err(ExportError::NothingExportable {
            case: results.number,
            configuration: first.configuration.to_lowercase(),
        });
    }
    Ok(AeroModel {
        deck: deck.to_string(),
        case: results.number,
        caseid: results.caseid.clone(),
        configuration: first.configuration.clone(),
        mach: conditions.iter().map(|c| c.condition.mach).collect(),
        altitude_m: first.condition.altitude,
        reference: results.reference.clone(),
        alpha_deg,
        functions,
        omitted,
        conditions_not_used,
    })
}

/// A number as written in the XML: eight significant digits, plain where that reads well.
/// Only finite numbers reach here.
fn num(v: f64) -> String {
    debug_assert!(v.is_finite());
    let r = crate::numeric::round_significant(v, 8).unwrap_or(v);
    if r == 0.0 {
        "0".to_string()
    } else if (1e-4..1e7).contains(&r.abs()) {
        format!("{r}")
    } else {
        format!("{r:e}")
    }
}

fn escape(s: &str) -> String {
    s.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
}

/// Text that is safe inside an XML comment (no `--`).
fn comment_safe(s: &str) -> String {
    let mut out = s.to_string();
    while out.contains("--") {
        out = out.replace("--", "- -");
    }
    out
}

fn area_view(m2: Option<f64>) -> String {
    m2.map_or("none".into(), |a| {
        format!("{} m2 ({} ft2)", num(a), num(a / (M_PER_FT * M_PER_FT)))
    })
}

fn length_view(m: Option<f64>) -> String {
    m.map_or("none".into(), |l| {
        format!("{} m ({} ft)", num(l), num(l / M_PER_FT))
    })
}

/// The header comment of the aerodynamics: generator, deck, conditions, units, signs, what was
/// cut and what is not there.
fn header(m: &AeroModel, pad: &str) -> String {
    let mut lines = vec![
        format!(
            "JSBSim aerodynamics written by datcom-rs {} from {}, case {}{}.",
            env!("CARGO_PKG_VERSION"),
            m.deck,
            m.case,
            m.caseid
                .as_ref()
                .map(|c| format!(" ({c})"))
                .unwrap_or_default()
        ),
        format!(
            "Configuration: {} (the most complete configuration the case computes).",
            m.configuration.to_lowercase()
        ),
        format!(
            "Flight conditions: Mach {}{}; alpha = {} deg.",
            degrees(&m.mach),
            m.altitude_m
                .map(|h| format!(" at altitude {} m (the first altitude of the deck)", num(h)))
                .unwrap_or_default(),
            degrees(&m.alpha_deg)
        ),
    ];
    for c in &m.conditions_not_used {
        lines.push(format!("  not used: {c}"));
    }
    let r = &m.reference;
    lines.extend([
        format!(
            "Reference: S = {}, c = {}, b = {}; moment reference centre XCG = {}, ZCG = {} (the AERORP).",
            area_view(r.area),
            length_view(r.chord),
            length_view(r.span),
            length_view(Some(r.xcg)),
            length_view(Some(r.zcg)),
        ),
        "Units: force = qbar (psf) * S (ft2) * C in lbf, moments with b or c in ft (lbf.ft);".into(),
        "  angles in rad, rates in rad/s; coefficients dimensionless, derivatives per rad.".into(),
        format!(
            "Tables: over {ALPHA_PROPERTY}{}; JSBSim holds a table's end values beyond it (no extrapolation).",
            if m.mach.len() > 1 { format!(" (rows) and {MACH_PROPERTY} (columns)") } else { String::new() }
        ),
        "Signs (DATCOM's, which are JSBSim's): alpha positive nose up; beta positive with the".into(),
        "  wind from the right (nose left); lift up, drag aft, side force to the right; rolling".into(),
        "  moment positive right wing down, pitching nose up, yawing nose right.".into(),
        "Rate derivatives are per unit p.b/2V, q.c/2V, r.b/2V, alphadot.c/2V (aero/bi2vel,".into(),
        "  aero/ci2vel). DATCOM's lateral and rate derivatives are stability-axis values; they".into(),
        "  are applied here about JSBSim's body axes as they are (the difference grows with alpha).".into(),
        "Derivatives DATCOM gives once per configuration (on the first angle) are constants.".into(),
    ]);
    let cuts: Vec<&String> = m.functions.iter().filter_map(|f| f.cut.as_ref()).collect();
    if cuts.is_empty() {
        lines.push("Every table holds all the deck's angles of attack.".into());
    } else {
        lines.push("Tables cut where DATCOM gives no value (never padded):".into());
        lines.extend(cuts.iter().map(|c| format!("  {c}")));
    }
    lines.push("Not in this export:".into());
    lines.extend(m.omitted.iter().map(|o| format!("  {o}")));
    lines.extend([
        "  CYr (a datcom-rs extension, JSON and CSV only), Cl and Cn due to alphadot, CD due to sideslip: not DATCOM estimates."
            .into(),
        "  Control derivatives (elevator, aileron, rudder, flaps) and power effects: not computed"
            .into(),
        "  by datcom-rs; the export has no control surfaces.".into(),
    ]);
    let body: String = lines
        .iter()
        .map(|l| format!("{pad}  {}\n", comment_safe(l)))
        .collect();
    format!("{pad}<!--\n{body}{pad}-->\n")
}

fn table(out: &mut String, c: &Coefficient, pad: &str) {
    let row_var = |out: &mut String, lookup: &str, var: &str| {
        let _ = writeln!(
            out,
            "{pad}  <independentVar lookup=\"{lookup}\">{var}</independentVar>"
        );
    };
    match c {
        Coefficient::Constant(v) => {
            let _ = writeln!(out, "{pad}<value>{}</value>", num(*v));
        }
        Coefficient::OverMach { mach, values } => {
            let _ = writeln!(out, "{pad}<table>");
            row_var(out, "row", MACH_PROPERTY);
            let _ = writeln!(out, "{pad}  <tableData>");
            for (m, v) in mach.iter().zip(values) {
                let _ = writeln!(out, "{pad}    {:>14} {:>14}", num(*m), num(*v));
            }
            let _ = writeln!(out, "{pad}  </tableData>\n{pad}</table>");
        }
        Coefficient::OverAlpha {
            alpha_rad,
            mach,
            values,
        } => {
            let _ = writeln!(out, "{pad}<table>");
            row_var(out, "row", ALPHA_PROPERTY);
            if mach.len() > 1 {
                row_var(out, "column", MACH_PROPERTY);
            }
            let _ = writeln!(out, "{pad}  <tableData>");
            if mach.len() > 1 {
                let head: String = mach.iter().map(|m| format!(" {:>14}", num(*m))).collect();
                let _ = writeln!(out, "{pad}    {:>14}{head}", "");
            }
            for (a, row) in alpha_rad.iter().zip(values) {
                let cells: String = row.iter().map(|v| format!(" {:>14}", num(*v))).collect();
                let _ = writeln!(out, "{pad}    {:>14}{cells}", num(*a));
            }
            let _ = writeln!(out, "{pad}  </tableData>\n{pad}</table>");
        }
    }
}

/// The `<aerodynamics>` element, indented by `indent` spaces.
fn aerodynamics_element(m: &AeroModel, indent: usize) -> String {
    let p0 = " ".repeat(indent);
    let mut out = format!("{p0}<aerodynamics>\n");
    for axis in Axis::ALL {
        let functions: Vec<&Function> = m.functions.iter().filter(|f| f.axis == axis).collect();
        if functions.is_empty() {
            continue;
        }
        let _ = writeln!(out, "{p0}  <axis name=\"{}\">", axis.name());
        for f in functions {
            let p = format!("{p0}    ");
            let _ = writeln!(
                out,
                "{p}<function name=\"aero/coefficient/{}\">\n{p}  <description>{}</description>\n{p}  <product>",
                f.name,
                escape(&f.description)
            );
            for factor in f.factors {
                let _ = writeln!(out, "{p}    <property>{factor}</property>");
            }
            table(&mut out, &f.coefficient, &format!("{p}    "));
            let _ = writeln!(out, "{p}  </product>\n{p}</function>");
        }
        let _ = writeln!(out, "{p0}  </axis>");
    }
    let _ = writeln!(out, "{p0}</aerodynamics>");
    out
}

/// A standalone `<aerodynamics>` file (`datcom-rs export jsbsim DECK -o aero.xml`).
pub fn aerodynamics_xml(m: &AeroModel) -> String {
    format!(
        "<?xml version=\"1.0\"?>\n{}{}",
        header(m, ""),
        aerodynamics_element(m, 0)
    )
}

/// What the whole aircraft needs beyond the aerodynamics; SI.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct AircraftOptions {
    /// The aircraft's name (its folder and file), letters, digits, `-`, `_`, `.`.
    pub name: String,
    /// Weight, N; the deck's WT when `None`.
    pub weight_n: Option<f64>,
    /// Ixx, Iyy, Izz about the centre of gravity, kg·m²; estimated when `None`.
    pub inertia_kgm2: Option<[f64; 3]>,
}

/// A whole minimal JSBSim aircraft around the aerodynamics: metrics from the reference
/// dimensions, AERORP, EYEPOINT, VRP and CG at (XCG, ZCG), the weight and inertias, three
/// ground contacts so that JSBSim can initialise it, no propulsion and no controls (a glider).
pub fn aircraft_xml(
    m: &AeroModel,
    case: &Case,
    options: &AircraftOptions,
) -> Result<String, ExportError> {
    let n = m.case;
    let name = &options.name;
    let name_ok = !name.is_empty()
        && !name.starts_with('.')
        && name
            .chars()
            .all(|c| c.is_ascii_alphanumeric() || "-_.".contains(c));
    if !name_ok {
        return Err(ExportError::BadName { name: name.clone() });
    }
    let r = &m.reference;
    let need = |v: Option<f64>, what| v.ok_or(ExportError::MissingReference { case: n, what });
    let (area, chord, span) = (
        need(r.area, "area")?,
        need(r.chord, "chord")?,
        need(r.span, "span")?,
    );
    let weight = options
        .weight_n
        .or(case.flight.as_ref().and_then(|f| f.weight))
        .ok_or(ExportError::MissingWeight { case: n })?;
    let positive = |v: f64, what| {
        if v.is_finite() && v > 0.0 {
            Ok(v)
        } else {
            Err(ExportError::BadValue { what, value: v })
        }
    };
    positive(weight, "the weight")?;
    positive(area, "the reference area")?;
    positive(chord, "the reference chord")?;
    positive(span, "the reference span")?;
    let length = aircraft_length(case);
    let (inertia, inertia_note) = match options.inertia_kgm2 {
        Some(i) => {
            for v in i {
                positive(v, "an inertia")?;
            }
            (i, "Inertias: as given.".to_string())
        }
        None => {
            let l = length.ok_or(ExportError::NoLengthForInertia { case: n })?;
            let mass = weight / STANDARD_GRAVITY;
            let d = [span, l, 0.5 * (span + l)];
            let i = [0, 1, 2].map(|k| mass * (ROSKAM_RADII[k] * d[k] / 2.0).powi(2));
            (
                i,
                format!(
                    "Inertias: estimated, I = (W/g)(R.d/2)^2 with Roskam's radii of gyration of \
                     single-engine propeller aeroplanes (Airplane Design Part V: Rx = {}, Ry = {}, \
                     Rz = {}), d = span {} m, length {} m, their mean; give real inertias for a \
                     real model.",
                    ROSKAM_RADII[0],
                    ROSKAM_RADII[1],
                    ROSKAM_RADII[2],
                    num(span),
                    num(l)
                ),
            )
        }
    };
    let ft = |v: f64| num(v / M_PER_FT);
    let inch = |v: f64| num(v / M_PER_IN);
    let location = |label: &str, x: f64, y: f64, z: f64, pad: &str| {
        format!(
            "{pad}<location{label} unit=\"IN\">\n{pad}  <x>{}</x>\n{pad}  <y>{}</y>\n{pad}  <z>{}</z>\n{pad}</location>\n",
            inch(x),
            inch(y),
            inch(z)
        )
    };
    let (xcg, zcg) = (r.xcg, r.zcg);
    let mut out = String::from("<?xml version=\"1.0\"?>\n");
    let version = env!("CARGO_PKG_VERSION");
    let _ = write!(
        out,
        "<fdm_config name=\"{name}\" version=\"2.0\" release=\"ALPHA\">\n  <fileheader>\n    \
         <author>datcom-rs {version} (generated)</author>\n    <version>{version}</version>\n    \
         <description>{}</description>\n",
        escape(&format!(
            "DATCOM estimate of {} from {}, case {}: a glider without propulsion or controls, to fly the aerodynamics",
            m.caseid.as_deref().unwrap_or("the aircraft"),
            m.deck,
            m.case
        )),
    );
    let notes = [
        inertia_note.as_str(),
        "Ground contacts: three stiff points below the centre of gravity so that JSBSim can \
         initialise the aircraft; they are not a landing-gear model.",
        "Centre of gravity, AERORP, EYEPOINT and VRP: the deck's moment reference centre (XCG, ZCG).",
    ];
    for note in notes {
        let _ = writeln!(out, "    <note>{}</note>", escape(note));
    }
    out.push_str("  </fileheader>\n");
    let _ = write!(
        out,
        "  <metrics>\n    <wingarea unit=\"FT2\">{}</wingarea>\n    <wingspan unit=\"FT\">{}</wingspan>\n    <chord unit=\"FT\">{}</chord>\n",
        num(area / (M_PER_FT * M_PER_FT)),
        ft(span),
        ft(chord)
    );
    for label in ["AERORP", "EYEPOINT", "VRP"] {
        out.push_str(&location(
            &format!(" name=\"{label}\""),
            xcg,
            0.0,
            zcg,
            "    ",
        ));
    }
    out.push_str("  </metrics>\n  <mass_balance>\n");
    for (axis, v) in ["ixx", "iyy", "izz"].iter().zip(inertia) {
        let _ = writeln!(
            out,
            "    <{axis} unit=\"SLUG*FT2\">{}</{axis}>",
            num(v / KGM2_PER_SLUGFT2)
        );
    }
    let _ = writeln!(
        out,
        "    <emptywt unit=\"LBS\">{}</emptywt>",
        num(weight / N_PER_LBF)
    );
    out.push_str(&location(" name=\"CG\"", xcg, 0.0, zcg, "    "));
    out.push_str("  </mass_balance>\n  <ground_reactions>\n");
    // Contacts scaled on the aircraft: a nose point ahead of the c.g., two main points just
    // behind it, 15 % of the length below; springs that hold a third of the weight each at a
    // deflection of 2 % of the length, about 70 % of critical damping.
    let l = length.unwrap_or(span);
    let (weight_lbf, l_ft) = (weight / N_PER_LBF, l / M_PER_FT);
    let spring = weight_lbf / (0.02 * l_ft);
    let damping = 1.4 * (spring * weight_lbf / 3.0 / (STANDARD_GRAVITY / M_PER_FT)).sqrt();
    let below = zcg - 0.15 * l;
    let contacts = [
        ("NOSE", xcg - 0.3 * l, 0.0),
        ("LEFT_MAIN", xcg + 0.1 * l, -0.15 * span),
        ("RIGHT_MAIN", xcg + 0.1 * l, 0.15 * span),
    ];
    for (label, x, y) in contacts {
        let _ = write!(
            out,
            "    <contact type=\"BOGEY\" name=\"{label}\">\n{}      <static_friction>0.8</static_friction>\n      \
             <dynamic_friction>0.5</dynamic_friction>\n      <rolling_friction>0.02</rolling_friction>\n      \
             <spring_coeff unit=\"LBS/FT\">{}</spring_coeff>\n      <damping_coeff unit=\"LBS/FT/SEC\">{}</damping_coeff>\n      \
             <max_steer unit=\"DEG\">0</max_steer>\n      <brake_group>NONE</brake_group>\n      <retractable>0</retractable>\n    </contact>\n",
            location("", x, y, below, "      "),
            num(spring),
            num(damping)
        );
    }
    out.push_str("  </ground_reactions>\n  <propulsion/>\n");
    out.push_str(&header(m, "  "));
    out.push_str(&aerodynamics_element(m, 2));
    out.push_str("</fdm_config>\n");
    Ok(out)
}

/// The aircraft's length for the inertia estimate and the contacts: the body's, else the
/// extent of the surfaces' positions and root chords; SI.
fn aircraft_length(case: &Case) -> Option<f64> {
    if let Some(b) = &case.body {
        let lo = b.x.iter().copied().fold(f64::INFINITY, f64::min);
        let hi = b.x.iter().copied().fold(f64::NEG_INFINITY, f64::max);
        if hi > lo {
            return Some(hi - lo);
        }
    }
    let s = case.synthesis.as_ref()?;
    let surfaces = [
        (s.xw, case.wing.as_ref()),
        (s.xh, case.horizontal_tail.as_ref()),
        (s.xv, case.vertical_tail.as_ref()),
    ];
    let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
    for (x, p) in surfaces {
        if let (Some(x), Some(p)) = (x, p) {
            lo = lo.min(x);
            hi = hi.max(x + p.chrdr.unwrap_or(0.0));
        }
    }
    (hi > lo).then_some(hi - lo)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn longest_run_takes_the_first_of_equal_runs() {
        let ok = [true, true, false, true, true, false];
        assert_eq!(longest_run(6, |i| ok[i]), 0..2);
        assert_eq!(longest_run(3, |_| false), 0..0);
        assert_eq!(longest_run(3, |_| true), 0..3);
    }

    #[test]
    fn numbers_are_short_and_exact_to_eight_digits() {
        assert_eq!(num(0.0), "0");
        assert_eq!(num(0.24307372140007694), "0.24307372");
        assert_eq!(num(-4.0), "-4");
        assert_eq!(num(1.2345678e-6), "1.2345678e-6");
    }

    #[test]
    fn comments_never_hold_a_double_dash() {
        assert!(!comment_safe("a---b--c").contains("--"));
    }
}
