//! Results of running a deck: per case, per flight condition, the configuration computed and
//! its coefficients against angle of attack. Everything is SI and per radian inside; reports
//! convert to the deck's units and to per degree unless DERIV RAD.

use crate::case::{Case, Deck, Planform};
use crate::conditions::FlightCondition;
use crate::deck::cards::Surface;
use crate::deck::cards::{DerivUnit, Dim};
use crate::geometry::section::{section_for, SectionCoordinates};
use crate::methods::section::surface_section;
use crate::methods::section::{section_characteristics, SectionCharacteristics};
use crate::warning::{Context, Warning};

/// Static coefficients against angle of attack (columns of the original's static page), one
/// row per angle of [`ConditionResults::alpha_deg`]. Coefficients are on the reference area
/// (moments also on the reference length); derivatives are per radian (the reports convert
/// to the DERIV unit). Axes and signs as DATCOM's (docs/conventions.md). `None` where there
/// is no value.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct StaticCoefficients {
    /// CD: drag coefficient, wind axes, positive aft.
    pub cd: Vec<Option<f64>>,
    /// CL: lift coefficient, wind axes, positive up.
    pub cl: Vec<Option<f64>>,
    /// CM: pitching moment coefficient about the moment reference centre, nose up positive.
    pub cm: Vec<Option<f64>>,
    /// CN: normal force coefficient, body axes, positive up.
    pub cn: Vec<Option<f64>>,
    /// CA: axial force coefficient, body axes, positive aft.
    pub ca: Vec<Option<f64>>,
    /// XCP: centre of pressure, CM/CN, in reference lengths ahead of the moment reference
    /// centre.
    pub xcp: Vec<Option<f64>>,
    /// CLA: dCL/dα, per radian.
    pub cla: Vec<Option<f64>>,
    /// CMA: dCM/dα, per radian.
    pub cma: Vec<Option<f64>>,
    /// CYB: dCY/dβ (side force, positive right), per radian. At every angle on the body-,
    /// wing- and horizontal-tail-alone pages; on the others on the first row only, one value
    /// per flight condition, as the original prints it (docs/lateral.md).
    pub cyb: Vec<Option<f64>>,
    /// CNB: dCn/dβ (yawing moment, nose right positive), per radian; rows as CYB.
    pub cnb: Vec<Option<f64>>,
    /// CLB: dCl/dβ (rolling moment, right wing down positive), per radian; at every angle.
    pub clb: Vec<Option<f64>>,
}

/// Dynamic derivatives against angle of attack (DAMP), per radian of the non-dimensional
/// rates q c̄/2V, α̇ c̄/2V, p b/2V and r b/2V, one row per angle. Which columns DATCOM gives
/// at every angle and which once per condition, on the first row, depends on the
/// configuration (docs/dynamic.md). `None` where there is no value.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct DynamicDerivatives {
    /// CLQ: dCL/d(q c̄/2V); on the first row only.
    pub clq: Vec<Option<f64>>,
    /// CMQ: dCM/d(q c̄/2V); on the first row only.
    pub cmq: Vec<Option<f64>>,
    /// CLAD: dCL/d(α̇ c̄/2V); on the first row only, except on the pages with a wing, a body
    /// and a horizontal tail (every angle).
    pub clad: Vec<Option<f64>>,
    /// CMAD: dCM/d(α̇ c̄/2V); as CLAD.
    pub cmad: Vec<Option<f64>>,
    /// CLP: dCl/d(p b/2V), rolling moment due to roll rate.
    pub clp: Vec<Option<f64>>,
    /// CYP: dCY/d(p b/2V), side force due to roll rate.
    pub cyp: Vec<Option<f64>>,
    /// CNP: dCn/d(p b/2V), yawing moment due to roll rate.
    pub cnp: Vec<Option<f64>>,
    /// CNR: dCn/d(r b/2V), yawing moment due to yaw rate.
    pub cnr: Vec<Option<f64>>,
    /// CLR: dCl/d(r b/2V), rolling moment due to yaw rate.
    pub clr: Vec<Option<f64>>,
    /// Extension (not on the original's page): the vertical panels' side force due to yaw
    /// rate CYr, per rad, where the configuration has a vertical tail or ventral fin; none
    /// otherwise (docs/dynamic.md).
    pub cyr: Option<Vec<Option<f64>>>,
    /// Columns (`CLQ`, `CMQ`, `CLAD`, `CMAD`, `CLP`, `CYP`, `CNP`, `CNR`, `CLR`) for which DATCOM
    /// has no method for this configuration: the original prints NDM on their first row.
    pub no_method: Vec<&'static str>,
}

/// The dynamic-derivative columns, in the order of the page.
pub const DYNAMIC_NAMES: [&str; 9] = [
    "CLQ", "CMQ", "CLAD", "CMAD", "CLP", "CYP", "CNP", "CNR", "CLR",
];

fn nones(n: usize) -> Vec<Option<f64>> {
    vec![None; n]
}

impl StaticCoefficients {
    /// No value computed yet at any of `n` angles.
    pub fn empty(n: usize) -> Self {
        Self {
            cd: nones(n),
            cl: nones(n),
            cm: nones(n),
            cn: nones(n),
            ca: nones(n),
            xcp: nones(n),
            cla: nones(n),
            cma: nones(n),
            cyb: nones(n),
            cnb: nones(n),
            clb: nones(n),
        }
    }

    /// The columns in page order with their names on the original's pages, to change.
    pub fn columns_mut(&mut self) -> [(&'static str, &mut Vec<Option<f64>>); 11] {
        [
            ("CD", &mut self.cd),
            ("CL", &mut self.cl),
            ("CM", &mut self.cm),
            ("CN", &mut self.cn),
            ("CA", &mut self.ca),
            ("XCP", &mut self.xcp),
            ("CLA", &mut self.cla),
            ("CMA", &mut self.cma),
            ("CYB", &mut self.cyb),
            ("CNB", &mut self.cnb),
            ("CLB", &mut self.clb),
        ]
    }
}

impl DynamicDerivatives {
    pub fn empty(n: usize) -> Self {
        Self {
            clq: nones(n),
            cmq: nones(n),
            clad: nones(n),
            cmad: nones(n),
            clp: nones(n),
            cyp: nones(n),
            cnp: nones(n),
            cnr: nones(n),
            clr: nones(n),
            cyr: None,
            no_method: Vec::new(),
        }
    }

    /// The block of a method's result: a column without a method is left empty and named in
    /// `no_method`.
    pub fn from_columns(d: &crate::methods::dynamic::Dynamic) -> Self {
        use crate::methods::dynamic::Column;
        let n = d.alpha_deg.len();
        let mut out = Self::empty(n);
        let cols = d.columns();
        let targets = [
            &mut out.clq,
            &mut out.cmq,
            &mut out.clad,
            &mut out.cmad,
            &mut out.clp,
            &mut out.cyp,
            &mut out.cnp,
            &mut out.cnr,
            &mut out.clr,
        ];
        for ((name, col), target) in cols.iter().zip(targets) {
            match col {
                Column::NoMethod => out.no_method.push(name),
                Column::Rows(r) => *target = r.clone(),
            }
        }
        if let Column::Rows(r) = &d.cyr {
            out.cyr = Some(r.clone());
        }
        out
    }

    /// The columns in page order, with their names.
    pub fn columns(&self) -> [(&'static str, &Vec<Option<f64>>); 9] {
        [
            (DYNAMIC_NAMES[0], &self.clq),
            (DYNAMIC_NAMES[1], &self.cmq),
            (DYNAMIC_NAMES[2], &self.clad),
            (DYNAMIC_NAMES[3], &self.cmad),
            (DYNAMIC_NAMES[4], &self.clp),
            (DYNAMIC_NAMES[5], &self.cyp),
            (DYNAMIC_NAMES[6], &self.cnp),
            (DYNAMIC_NAMES[7], &self.cnr),
            (DYNAMIC_NAMES[8], &self.clr),
        ]
    }

    /// [`DynamicDerivatives::columns`], to change.
    pub fn columns_mut(&mut self) -> [(&'static str, &mut Vec<Option<f64>>); 9] {
        [
            (DYNAMIC_NAMES[0], &mut self.clq),
            (DYNAMIC_NAMES[1], &mut self.cmq),
            (DYNAMIC_NAMES[2], &mut self.clad),
            (DYNAMIC_NAMES[3], &mut self.cmad),
            (DYNAMIC_NAMES[4], &mut self.clp),
            (DYNAMIC_NAMES[5], &mut self.cyp),
            (DYNAMIC_NAMES[6], &mut self.cnp),
            (DYNAMIC_NAMES[7], &mut self.cnr),
            (DYNAMIC_NAMES[8], &mut self.clr),
        ]
    }
}

/// Reference dimensions and moment reference centre of a case, SI.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct ReferenceDimensions {
    pub area: Option<f64>,
    pub chord: Option<f64>,
    pub span: Option<f64>,
    pub xcg: f64,
    pub zcg: f64,
}

/// [`ReferenceDimensions`] in a deck's units, the geometry divided back by the case's scale.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ReferenceInDeckUnits {
    pub area: Option<f64>,
    /// The longitudinal reference length (the chord).
    pub chord: Option<f64>,
    /// The lateral reference length (the span).
    pub span: Option<f64>,
    pub xcg: f64,
    pub zcg: f64,
}

impl ReferenceDimensions {
    /// The dimensions in the units `dim` of a deck, divided back by `scale` (SCALE: the
    /// geometry is held scaled, the reference dimensions are reported as the deck gives them).
    pub fn in_deck_units(&self, dim: Dim, scale: f64) -> ReferenceInDeckUnits {
        use crate::case::units::from_si;
        use crate::deck::schema::Dimension;
        let len = |v: f64| from_si(v, dim, Dimension::Length) / scale;
        ReferenceInDeckUnits {
            area: self
                .area
                .map(|a| from_si(a, dim, Dimension::Area) / (scale * scale)),
            chord: self.chord.map(len),
            span: self.span.map(len),
            xcg: len(self.xcg),
            zcg: len(self.zcg),
        }
    }
}

impl ReferenceInDeckUnits {
    /// Whether every value given is a number.
    fn is_finite(&self) -> bool {
        [
            self.area,
            self.chord,
            self.span,
            Some(self.xcg),
            Some(self.zcg),
        ]
        .into_iter()
        .flatten()
        .all(f64::is_finite)
    }
}

/// One flight condition's results.
#[derive(Debug, Clone, PartialEq)]
pub struct ConditionResults {
    pub condition: FlightCondition,
    /// Configuration name as the original prints it (`WING-BODY CONFIGURATION`, ...).
    pub configuration: String,
    pub alpha_deg: Vec<f64>,
    pub static_coefficients: StaticCoefficients,
    /// Present when the case has DAMP.
    pub dynamic: Option<DynamicDerivatives>,
    /// The downwash and dynamic pressure at the horizontal tail (the original's ALPHA Q/QINF
    /// EPSLON D(EPSLON)/D(ALPHA) table under the page), on the configurations with a
    /// horizontal tail behind the wing.
    pub downwash: Option<DownwashTable>,
    /// With the PART card, on the case's own configuration: the original's CONFIGURATION
    /// AUXILIARY AND PARTIAL OUTPUT (see [`crate::auxiliary`]).
    pub auxiliary: Option<crate::auxiliary::AuxiliaryOutput>,
}

/// The downwash at the horizontal tail at each angle of attack of the page (DATCOM 4.4.1):
/// none where it is not computed.
#[derive(Debug, Clone, PartialEq)]
pub struct DownwashTable {
    /// Dynamic pressure at the tail over the free stream's, q/q∞.
    pub dynamic_pressure_ratio: Vec<Option<f64>>,
    /// Downwash angle ε, degrees (positive down).
    pub epsilon_deg: Vec<Option<f64>>,
    /// dε/dα.
    pub gradient: Vec<Option<f64>>,
}

impl From<&crate::methods::tail::Downwash> for DownwashTable {
    fn from(d: &crate::methods::tail::Downwash) -> Self {
        DownwashTable {
            dynamic_pressure_ratio: d.dynamic_pressure_ratio.clone(),
            epsilon_deg: d.epsilon_deg.clone(),
            gradient: d.gradient.clone(),
        }
    }
}

/// A lifting surface's airfoil section: its coordinate table and characteristics (the
/// original's SECTION DEFINITION pages).
#[derive(Debug, Clone, PartialEq)]
pub struct SectionResult {
    pub surface: Surface,
    pub coordinates: Option<SectionCoordinates>,
    pub characteristics: Option<SectionCharacteristics>,
    /// What was assumed or could not be computed for the section, one per flight condition
    /// where it repeats.
    pub warnings: Vec<Warning>,
}

/// One case's results.
#[derive(Debug, Clone, PartialEq)]
pub struct CaseResults {
    pub number: usize,
    pub caseid: Option<String>,
    pub dim: Dim,
    pub deriv: DerivUnit,
    /// SYNTHS SCALE: the geometry inside is the deck's times this factor.
    pub scale: f64,
    pub reference: ReferenceDimensions,
    /// Sections of the wing, horizontal tail, vertical tail and ventral fin that have one.
    pub sections: Vec<SectionResult>,
    pub conditions: Vec<ConditionResults>,
    /// What was assumed or could not be computed, the first of equal warnings only. Two
    /// warnings that differ beyond their printed digits are both here and read the same:
    /// [`crate::warning::texts`] gives each text once, as the reports write them.
    pub warnings: Vec<Warning>,
    /// The case's whole configuration as the original names it. No page has this name when
    /// the build-up has no page for the combination (a wing and tails without a body, ...):
    /// the pages of its largest parts are given instead, none of them the whole aircraft.
    pub configuration: String,
}

impl ConditionResults {
    /// A coefficient column by its name on the original's pages (`CL`, `CYB`, `CLP` ...);
    /// `None` for a dynamic column without DAMP or an unknown name.
    pub fn column(&self, name: &str) -> Option<&[Option<f64>]> {
        let s = &self.static_coefficients;
        Some(match name {
            "CD" => &s.cd,
            "CL" => &s.cl,
            "CM" => &s.cm,
            "CN" => &s.cn,
            "CA" => &s.ca,
            "XCP" => &s.xcp,
            "CLA" => &s.cla,
            "CMA" => &s.cma,
            "CYB" => &s.cyb,
            "CNB" => &s.cnb,
            "CLB" => &s.clb,
            _ => {
                let d = self.dynamic.as_ref()?;
                let (_, column) = d.columns().into_iter().find(|(n, _)| *n == name)?;
                column
            }
        })
    }
}

impl CaseResults {
    /// For each flight condition, its last configuration entry when it is the case's whole
    /// configuration (with BUILD the component configurations come first), in condition
    /// order; none when the build-up has no page for the combination ([`Self::configuration`]).
    pub fn most_complete(&self) -> Vec<&ConditionResults> {
        let mut last: Vec<&ConditionResults> = Vec::new();
        let key = |x: &ConditionResults| (x.condition.mach_index, x.condition.altitude_index);
        for c in &self.conditions {
            match last.last_mut() {
                Some(l) if key(l) == key(c) => *l = c,
                _ => last.push(c),
            }
        }
        last.retain(|c| c.configuration == self.configuration);
        last
    }
}

/// Results of every case of a deck.
#[derive(Debug, Clone, PartialEq)]
pub struct Results {
    pub file: String,
    pub cases: Vec<CaseResults>,
}

/// Theoretical area (both halves, to the centreline) and area-weighted mean aerodynamic chord of
/// a straight-tapered or cranked planform: the reference area and length the original uses
/// when $OPTINS does not give them (DATCOM section 2.2.2, trapezoidal panels).
pub fn planform_area_and_mac(p: &Planform) -> Option<(f64, f64)> {
    let root = p.chrdr?;
    let span = p.sspn?;
    let tip = p.chrdtp.unwrap_or(0.0);
    let (break_chord, break_span) = match (p.chrdbp, p.sspnop) {
        (Some(c), Some(outer)) if outer > 0.0 => (c, outer),
        _ => (tip, 0.0),
    };
    let inner_span = span - break_span;
    let inner_area = (root + break_chord) * inner_span;
    let outer_area = (break_chord + tip) * break_span;
    let area = inner_area + outer_area;
    let mac = |c_root: f64, c_tip: f64| {
        if c_root + c_tip == 0.0 {
            return 0.0;
        }
        let l = c_tip / c_root;
        2.0 * c_root * (1.0 + l + l * l) / (3.0 * (1.0 + l))
    };
    if area <= 0.0 || root <= 0.0 {
        return None;
    }
    let mac = (inner_area * mac(root, break_chord) + outer_area * mac(break_chord, tip)) / area;
    Some((area, mac))
}

/// The original's configuration line for the body alone.
pub const BODY_ALONE: &str = "DATCOM BODY ALONE CONFIGURATION";

/// A page's coefficients made of the longitudinal columns of a method's result (fields cd, cl,
/// cm, cn, ca, xcp, cla_per_rad, cma_per_rad, as every static method names them), moved, and
/// sideslip columns of `$n` rows not computed yet.
macro_rules! longitudinal {
    ($result:expr, $n:expr) => {{
        let r = $result;
        let n = $n;
        StaticCoefficients {
            cd: r.cd,
            cl: r.cl,
            cm: r.cm,
            cn: r.cn,
            ca: r.ca,
            xcp: r.xcp,
            cla: r.cla_per_rad,
            cma: r.cma_per_rad,
            cyb: nones(n),
            cnb: nones(n),
            clb: nones(n),
        }
    }};
}

/// Puts a configuration's sideslip derivatives into its coefficients, or the reason there are
/// none into its warnings, labelled with the configuration (`wing-body, sideslip: ...`).
fn add_sideslip(
    s: &mut StaticCoefficients,
    warnings: &mut Vec<Warning>,
    label: &'static str,
    lateral: Result<crate::methods::lateral::Lateral, String>,
) {
    match lateral {
        Ok(lat) => {
            warnings.extend(Warning::all_under(Context::Sideslip(label), &lat.warnings));
            s.cyb = lat.cyb;
            s.cnb = lat.cnb;
            s.clb = lat.clb;
        }
        Err(e) => warnings.push(Warning::new(Context::Sideslip(label), e)),
    }
}

/// The page of a low-aspect-ratio wing-body ($LARWB), as the original titles it.
pub const LOW_ASPECT_RATIO: &str = "LOW ASPECT RATIO WINGS AND WING-BODY COMBINATIONS";

/// The low-aspect-ratio wing-body coefficients at one condition (DATCOM 4.8 and 5.5), or the
/// reason there are none.
fn low_aspect_ratio_coefficients(
    case: &Case,
    condition: &FlightCondition,
    alpha_deg: &[f64],
) -> Result<(StaticCoefficients, Vec<Warning>), String> {
    use crate::methods::low_aspect_ratio as lar;
    let lb = case.larwb.as_ref().ok_or("the case has no $LARWB")?;
    let flight = lar::LowAspectRatioFlight {
        mach: condition.mach,
        reynolds_per_length: condition.reynolds_per_length,
        roughness: crate::methods::body::roughness_height(case),
    };
    let page = lar::low_aspect_ratio_wing_body(lb, flight, alpha_deg)
        .map_err(|e| format!("low-aspect-ratio wing-body: {e}"))?;
    let mut warnings: Vec<Warning> =
        Warning::all_under(Context::Part("low-aspect-ratio wing-body"), &page.warnings).collect();
    let some = |v: &[f64]| {
        v.iter()
            .map(|x| Some(*x).filter(|y| y.is_finite()))
            .collect()
    };
    let mut s = StaticCoefficients::empty(alpha_deg.len());
    s.cd = some(&page.cd);
    s.cl = some(&page.cl);
    s.cm = some(&page.cm);
    s.cn = some(&page.cn);
    s.ca = some(&page.ca);
    s.xcp = page.xcp.clone();
    s.cla = page.cla.clone();
    s.cma = page.cma.clone();
    match &page.sideslip {
        Ok(d) => {
            s.cyb = some(&d.cyb);
            s.cnb = some(&d.cnb);
            s.clb = some(&d.clb);
        }
        Err(e) => warnings.push(format!("low-aspect-ratio wing-body sideslip: {e}").into()),
    }
    Ok((s, warnings))
}

/// The body-alone coefficients at one condition (DATCOM 4.2), or the reason there are none.
fn body_alone_coefficients(
    case: &Case,
    condition: &FlightCondition,
    alpha_deg: &[f64],
) -> Result<(StaticCoefficients, Vec<Warning>), String> {
    let body = case.body.as_ref().ok_or("the case has no body")?;
    let geometry = crate::geometry::body(body).map_err(|e| format!("body geometry: {e}"))?;
    let b = crate::methods::body::body_alone(case, &geometry, condition, alpha_deg)
        .map_err(|e| format!("body alone: {e}"))?;
    let mut warnings: Vec<Warning> =
        Warning::all_under(Context::Part("body alone"), &b.warnings).collect();
    // Sideslip derivatives of the body alone (DATCOM 5.2.1.1 as the original forms them).
    let lateral = crate::methods::lateral::body_lateral(&b, case);
    let mut s = longitudinal!(b, alpha_deg.len());
    add_sideslip(&mut s, &mut warnings, "body alone", Ok(lateral));
    Ok((s, warnings))
}

/// The wing-alone coefficients at one condition (DATCOM 4.1.3-4.1.5), or the reason there are
/// none.
fn wing_alone_coefficients(
    case: &Case,
    condition_index: usize,
    alpha_deg: &[f64],
    section: Option<&SectionCharacteristics>,
) -> Result<(StaticCoefficients, Vec<Warning>), String> {
    let w =
        crate::methods::wing::wing_alone_with_section(case, condition_index, alpha_deg, section)
            .map_err(|e| format!("wing alone: {e}"))?;
    let mut warnings: Vec<Warning> =
        Warning::all_under(Context::Part("wing alone"), &w.warnings).collect();
    // Sideslip derivatives of the wing alone (DATCOM 5.1.2.1).
    let lateral = crate::methods::lateral::wing_lateral(case, condition_index, alpha_deg, &w)
        .map_err(|e| e.to_string());
    let mut s = longitudinal!(w, alpha_deg.len());
    add_sideslip(&mut s, &mut warnings, "wing alone", lateral);
    Ok((s, warnings))
}

/// The original's configuration line for the wing alone.
pub const WING_ALONE: &str = "WING ALONE CONFIGURATION";
/// The original's configuration line for the wing and body.
pub const WING_BODY: &str = "WING-BODY CONFIGURATION";
/// The original's configuration lines with tails.
pub const WING_BODY_HT: &str = "WING-BODY-HORIZONTAL TAIL CONFIGURATION";
pub const WING_BODY_VT: &str = "WING-BODY-VERTICAL TAIL CONFIGURATION";
pub const WING_BODY_VT_HT: &str = "WING-BODY-VERTICAL TAIL-HORIZONTAL TAIL CONFIGURATION";
/// The configuration of a case without a body, wing, tail, fin or $LARWB.
pub const NO_COMPONENT: &str = "NO COMPONENT";

/// The vertical tail's sideslip derivatives (DATCOM 5.3.1.1), with the twin vertical panels'
/// ($TVTPAN, figures 5.3.1.1-24a to -24c) added as the original adds them, up to STMACH; above
/// it the panels are left out and a warning says so, as the original notes. Twin panels
/// without a vertical tail are the panels' terms alone (zero above STMACH).
fn vertical_tail_sideslip(
    case: &Case,
    condition_index: usize,
    alpha_deg: &[f64],
    warnings: &mut Vec<Warning>,
) -> Result<crate::methods::lateral::Lateral, crate::methods::lateral::LateralError> {
    use crate::methods::lateral::{self, fin_lateral, Fin};
    let with_fin = case.vertical_tail.is_some() || case.twin_panels.is_none();
    let fin = if with_fin {
        fin_lateral(case, condition_index, alpha_deg, Fin::VerticalTail)?
    } else {
        lateral::Lateral::zero(alpha_deg)
    };
    if case.twin_panels.is_none() {
        return Ok(fin);
    }
    if !lateral::twin_panels_counted(case, condition_index) {
        let mach = case.conditions.get(condition_index).map_or(0.0, |c| c.mach);
        warnings.push(Warning::text(format!(
            "Mach {mach:.3}: the lateral stability derivatives do not include the effects of the \
             twin vertical panels (no DATCOM method above STMACH)"
        )));
        return Ok(fin);
    }
    let twin = lateral::twin_panel_lateral(case, alpha_deg)?;
    if !with_fin {
        return Ok(twin);
    }
    let mut total = lateral::sum(&[&fin, &twin]);
    total.fin_terms = fin.fin_terms;
    total.twin_panel_terms = twin.twin_panel_terms;
    total.warnings = fin.warnings.into_iter().chain(twin.warnings).collect();
    Ok(total)
}

fn coefficients(c: &crate::methods::tail::Coefficients) -> StaticCoefficients {
    longitudinal!(c.clone(), c.cd.len())
}

/// A configuration with tails at one condition (DATCOM 4.4, 4.5, totals), taken from the
/// totals computed once for the condition, with its sideslip derivatives: the sum of the
/// wing-body's and the tails' (DATCOM 5.2.2.1, 5.2.3.1, 5.1.2.1 on the horizontal tail,
/// 5.3.1.1 for the vertical tail and ventral fin), as the original sums them.
fn tail_configuration_coefficients(
    case: &Case,
    condition_index: usize,
    totals: &Result<crate::methods::tail::ConfigurationTotals, String>,
    part: &str,
) -> Result<(StaticCoefficients, Vec<Warning>), String> {
    use crate::methods::lateral;
    let t = totals.as_ref().map_err(Clone::clone)?;
    let c = match part {
        WING_BODY_HT => t.wing_body_horizontal_tail.as_ref(),
        WING_BODY_VT => t.wing_body_vertical_tail.as_ref(),
        _ => t.wing_body_vertical_tail_horizontal_tail.as_ref(),
    }
    .ok_or_else(|| format!("{part}: not computed"))?;
    let mut warnings: Vec<Warning> =
        Warning::all_under(Context::Part("tails"), &t.warnings).collect();
    let mut s = coefficients(c);
    let alpha = &t.alpha_deg;
    let wb = &t.terms.wing_body;
    let with_ht = part != WING_BODY_VT;
    let with_fins = part != WING_BODY_HT;
    let mut parts = vec![lateral::wing_body_lateral(
        case,
        condition_index,
        alpha,
        &wb.terms.wing,
        wb,
    )];
    if with_ht {
        if let Some(ht) = &t.terms.horizontal_tail {
            parts.push(lateral::horizontal_tail_lateral(
                case,
                condition_index,
                alpha,
                ht,
            ));
        }
    }
    if with_fins {
        match fins_sideslip(
            case,
            condition_index,
            alpha,
            "configuration with tails, sideslip",
            &mut warnings,
        ) {
            Ok(fins) => parts.extend(fins.into_iter().map(Ok)),
            Err(e) => parts.push(Err(e)),
        }
    }
    let total = parts
        .into_iter()
        .collect::<Result<Vec<_>, _>>()
        .map(lateral::sum_with_warnings)
        .map_err(|e| e.to_string());
    add_sideslip(&mut s, &mut warnings, "configuration with tails", total);
    Ok((s, warnings))
}

/// The wing-body coefficients at one condition (DATCOM 4.3), or the reason there are none.
fn wing_body_coefficients(
    case: &Case,
    condition_index: usize,
    alpha_deg: &[f64],
    section: Option<&SectionCharacteristics>,
    in_place: Option<crate::methods::wing_body::SurfaceInPlace>,
) -> Result<(StaticCoefficients, Vec<Warning>), String> {
    let w = crate::methods::wing_body::wing_body_with_surface(
        case,
        condition_index,
        alpha_deg,
        section,
        in_place,
    )
    .map_err(|e| format!("wing-body: {e}"))?;
    let mut warnings: Vec<Warning> =
        Warning::all_under(Context::Part("wing-body"), &w.warnings).collect();
    // Sideslip derivatives of the wing-body (DATCOM 5.2.2.1, 5.2.3.1), which need the wing
    // alone as well.
    let lateral =
        crate::methods::wing::wing_alone_with_section(case, condition_index, alpha_deg, section)
            .map_err(|e| e.to_string())
            .and_then(|wing| {
                crate::methods::lateral::wing_body_lateral(
                    case,
                    condition_index,
                    alpha_deg,
                    &wing,
                    &w,
                )
                .map_err(|e| e.to_string())
            });
    let mut s = longitudinal!(w, alpha_deg.len());
    add_sideslip(&mut s, &mut warnings, "wing-body", lateral);
    Ok((s, warnings))
}

/// The original's configuration lines for the tails alone and with the body alone (BUILD).
pub const HORIZONTAL_TAIL: &str = "HORIZONTAL TAIL CONFIGURATION";
pub const VERTICAL_TAIL: &str = "VERTICAL TAIL CONFIGURATION";
pub const VENTRAL_FIN: &str = "VENTRAL FIN CONFIGURATION";
pub const BODY_HT: &str = "BODY-HORIZONTAL TAIL CONFIGURATION";
pub const BODY_VT: &str = "BODY-VERTICAL TAIL CONFIGURATION";

/// The horizontal tail alone at one condition: the wing methods on the tail (DATCOM 4.1.3 to
/// 4.1.5 and 5.1.2.1 on the tail's planform, section, position and incidence, on the case's
/// reference dimensions), or the reason there are none.
fn horizontal_tail_coefficients(
    case: &Case,
    condition_index: usize,
    alpha_deg: &[f64],
) -> Result<(StaticCoefficients, Vec<Warning>), String> {
    let t = crate::methods::tail::horizontal_tail_alone(case, condition_index, alpha_deg)
        .map_err(|e| format!("horizontal tail alone: {e}"))?;
    let mut warnings: Vec<Warning> =
        Warning::all_under(Context::Part("horizontal tail alone"), &t.surface.warnings).collect();
    let mut s = coefficients(&crate::methods::tail::Coefficients::resolved(
        alpha_deg,
        t.surface.cd.clone(),
        t.surface.cl.clone(),
        t.cm.clone(),
        t.cla_per_rad.clone(),
        t.cma_per_rad.clone(),
    ));
    let lateral =
        crate::methods::lateral::horizontal_tail_lateral(case, condition_index, alpha_deg, &t)
            .map_err(|e| e.to_string());
    add_sideslip(&mut s, &mut warnings, "horizontal tail alone", lateral);
    Ok((s, warnings))
}

/// A fin's zero-lift drag (DATCOM 4.1.5.1) on the case's reference area, its warnings
/// labelled; 0 for a fin the case does not have.
fn fin_drag(
    case: &Case,
    condition_index: usize,
    surface: Surface,
    label: &'static str,
    warnings: &mut Vec<Warning>,
) -> Result<f64, String> {
    let present = match surface {
        Surface::VerticalTail => case.vertical_tail.is_some(),
        Surface::VentralFin => case.ventral_fin.is_some(),
        _ => false,
    };
    if !present {
        return Ok(0.0);
    }
    let mut tail_warnings = Vec::new();
    let drag = crate::methods::tail::fin_zero_lift_drag(
        case,
        condition_index,
        surface,
        &mut tail_warnings,
    )
    .map_err(|e| format!("{label}: {e}"))?;
    warnings.extend(
        tail_warnings
            .into_iter()
            .map(|w| Warning::new(Context::Part(label), w)),
    );
    Ok(drag.drag.total)
}

/// The vertical tail's and ventral fin's zero-lift drag together.
fn fins_drag(
    case: &Case,
    condition_index: usize,
    label: &'static str,
    warnings: &mut Vec<Warning>,
) -> Result<f64, String> {
    Ok(fin_drag(
        case,
        condition_index,
        Surface::VerticalTail,
        label,
        warnings,
    )? + fin_drag(case, condition_index, Surface::VentralFin, label, warnings)?)
}

/// The sideslip derivatives of the case's fins, one part each for the caller's sum: the
/// vertical tail with its twin panels ([`vertical_tail_sideslip`]) and the ventral fin (left
/// out, with a warning, without a horizontal tail: `lateral::ventral_fin_left_out`).
fn fins_sideslip(
    case: &Case,
    condition_index: usize,
    alpha_deg: &[f64],
    label: &'static str,
    warnings: &mut Vec<Warning>,
) -> Result<Vec<crate::methods::lateral::Lateral>, crate::methods::lateral::LateralError> {
    use crate::methods::lateral::{self, Fin, LateralWarning};
    let mut parts = Vec::new();
    if case.vertical_tail.is_some() || case.twin_panels.is_some() {
        parts.push(vertical_tail_sideslip(
            case,
            condition_index,
            alpha_deg,
            warnings,
        )?);
    }
    if lateral::ventral_fin_left_out(case) {
        warnings.push(Warning::new(
            Context::Part(label),
            LateralWarning::VentralFinLeftOut,
        ));
    } else if case.ventral_fin.is_some() {
        parts.push(lateral::fin_lateral(
            case,
            condition_index,
            alpha_deg,
            Fin::VentralFin,
        )?);
    }
    Ok(parts)
}

/// A fin alone at one condition (the vertical tail with its twin panels, or the ventral fin):
/// its zero-lift drag (DATCOM 4.1.5.1) on the first row, no lift, moment or slopes (0 on the
/// first row, as the original prints them), and its sideslip derivatives (DATCOM 5.3.1.1, with
/// the sidewash of its configuration).
fn fin_alone_coefficients(
    case: &Case,
    condition_index: usize,
    alpha_deg: &[f64],
    fin: crate::methods::lateral::Fin,
) -> Result<(StaticCoefficients, Vec<Warning>), String> {
    use crate::methods::lateral::{self, Fin, Lateral, LateralWarning};
    let mut warnings = Vec::new();
    let (surface, label) = match fin {
        Fin::VerticalTail => (Surface::VerticalTail, "vertical tail alone"),
        Fin::VentralFin => (Surface::VentralFin, "ventral fin alone"),
    };
    let drag = fin_drag(case, condition_index, surface, label, &mut warnings)?;
    let n = alpha_deg.len();
    let mut s = StaticCoefficients::empty(n);
    // Twin vertical panels without a vertical tail: no longitudinal numbers, as the original.
    let panels_only = fin == Fin::VerticalTail && case.vertical_tail.is_none();
    if n > 0 && !panels_only {
        s.cd[0] = Some(drag);
        for column in [&mut s.cl, &mut s.cm, &mut s.cn, &mut s.cla, &mut s.cma] {
            column[0] = Some(0.0);
        }
    }
    let lateral = match fin {
        Fin::VerticalTail => {
            vertical_tail_sideslip(case, condition_index, alpha_deg, &mut warnings)
        }
        Fin::VentralFin if lateral::ventral_fin_left_out(case) => {
            warnings.push(Warning::new(
                Context::Part(label),
                LateralWarning::VentralFinLeftOut,
            ));
            Ok(Lateral::zero(alpha_deg))
        }
        Fin::VentralFin => lateral::fin_lateral(case, condition_index, alpha_deg, fin),
    }
    .map_err(|e| e.to_string());
    add_sideslip(&mut s, &mut warnings, label, lateral);
    Ok((s, warnings))
}

/// The body with its fins at one condition: the body alone (DATCOM 4.2) with the vertical
/// tail's and ventral fin's zero-lift drag added to CD (CN, CA, XCP resolved again), and the
/// body's and the fins' sideslip derivatives summed (5.2.1.1, 5.3.1.1).
fn body_vertical_tail_coefficients(
    case: &Case,
    condition: &FlightCondition,
    condition_index: usize,
    alpha_deg: &[f64],
) -> Result<(StaticCoefficients, Vec<Warning>), String> {
    use crate::methods::lateral;
    let label = "body-vertical tail";
    let (body, mut warnings) = body_alone_coefficients(case, condition, alpha_deg)?;
    let drag = fins_drag(case, condition_index, label, &mut warnings)?;
    let cd: Vec<Option<f64>> = body.cd.iter().map(|c| c.map(|c| c + drag)).collect();
    // Twin vertical panels alone on the body: the original prints no longitudinal numbers.
    let panels_only = case.vertical_tail.is_none() && case.ventral_fin.is_none();
    let mut s = if panels_only {
        StaticCoefficients::empty(alpha_deg.len())
    } else {
        coefficients(&crate::methods::tail::Coefficients::resolved(
            alpha_deg,
            cd,
            body.cl.clone(),
            body.cm.clone(),
            body.cla.clone(),
            body.cma.clone(),
        ))
    };
    let body_sideslip = lateral::Lateral {
        alpha_deg: alpha_deg.to_vec(),
        cyb: body.cyb,
        cnb: body.cnb,
        clb: body.clb,
        wing_terms: None,
        wing_body_terms: None,
        fin_terms: None,
        twin_panel_terms: None,
        warnings: Vec::new(),
    };
    let total = fins_sideslip(case, condition_index, alpha_deg, label, &mut warnings)
        .map(|fins| lateral::sum_with_warnings([vec![body_sideslip], fins].concat()))
        .map_err(|e| e.to_string());
    add_sideslip(&mut s, &mut warnings, label, total);
    Ok((s, warnings))
}

/// The body with the horizontal tail at one condition: the wing-body methods (DATCOM 4.3,
/// 5.2.2.1, 5.2.3.1) with the horizontal tail in the wing's place (planform, section,
/// position, incidence), on the case's reference dimensions, as the original forms this page.
fn body_horizontal_tail_coefficients(
    case: &Case,
    condition_index: usize,
    alpha_deg: &[f64],
) -> Result<(StaticCoefficients, Vec<Warning>), String> {
    let mut proxy = crate::methods::tail::tail_as_wing(case)
        .map_err(|e| format!("body-horizontal tail: {e}"))?;
    proxy.reference.span = crate::methods::lateral::lateral_reference_length(case);
    let section = crate::methods::wing::computed_wing_section(&proxy)
        .transpose()
        .map_err(|e| format!("body-horizontal tail: {e}"))?;
    // The tail as its own page has it: its moment with the tail's "not applicable" rule, and
    // its lift-curve slope (the first angle's with `TailSlopeReading::Original` for a
    // low-aspect-ratio straight tail), as in the configuration.
    let tail = crate::methods::tail::horizontal_tail_alone(case, condition_index, alpha_deg)
        .map_err(|e| format!("body-horizontal tail: {e}"))?;
    let (s, warnings) = wing_body_coefficients(
        &proxy,
        condition_index,
        alpha_deg,
        section.as_ref(),
        Some(tail.in_place()),
    )?;
    // The tail is in the wing's place: its page's labels, and its moment where that is not
    // applicable (said in words).
    let label = |w: Warning| {
        use crate::methods::wing_body::WingBodyWarning;
        use crate::warning::Detail;
        let in_words = matches!(
            w.detail(),
            Detail::WingBody(WingBodyWarning::MomentNotApplicable { .. })
        ) || w.label().is_none();
        if in_words {
            Warning::text(
                w.to_string()
                    .replacen("wing-body", "body-horizontal tail", 1)
                    .replace("(the wing's moment is not)", "(the tail's moment is not)"),
            )
        } else {
            w.renamed("wing-body", "body-horizontal tail")
        }
    };
    Ok((s, warnings.into_iter().map(label).collect()))
}

/// The dynamic derivatives of `part` at condition `index` (DAMP), with what could not be
/// computed said in the warnings; a configuration without methods gives an empty block.
fn dynamic_derivatives(
    case: &Case,
    index: usize,
    alpha_deg: &[f64],
    part: &str,
    section: Option<&SectionCharacteristics>,
    totals: Option<&Result<crate::methods::tail::ConfigurationTotals, String>>,
) -> (DynamicDerivatives, Vec<Warning>) {
    use crate::methods::dynamic::{self as dy, Dynamic, TailConfiguration};
    let n = alpha_deg.len();
    let mach = case.conditions.get(index).map_or(0.0, |c| c.mach);
    // With a double-delta or cranked wing the original computes none of the tails' pitch-rate
    // and α̇ terms: the fins' and body-tail pages print NDM there (docs/tail.md).
    let wing_not_straight = double_delta_or_cranked_wing(case);
    let computed: Result<Dynamic, String> = (|| {
        let body = |b: &crate::methods::body::BodyAlone| {
            dy::body_dynamic(case, b, alpha_deg).map_err(|e| e.to_string())
        };
        let wing = |w: &crate::methods::wing::WingAlone| {
            dy::wing_dynamic(case, index, alpha_deg, w)
                .map(|r| r.0)
                .map_err(|e| e.to_string())
        };
        let wing_body = |wb: &crate::methods::wing_body::WingBody| -> Result<Dynamic, String> {
            Ok(dy::wing_body_dynamic(
                &wing(&wb.terms.wing)?,
                &body(&wb.terms.body)?,
                wb,
            ))
        };
        let body_alone = || -> Result<Dynamic, String> {
            let input = case.body.as_ref().ok_or("the case has no body")?;
            let g = crate::geometry::body(input).map_err(|e| e.to_string())?;
            let condition = case.conditions.get(index).ok_or("no condition")?;
            let b = crate::methods::body::body_alone(case, &g, condition, alpha_deg)
                .map_err(|e| e.to_string())?;
            body(&b)
        };
        let horizontal_tail = || -> Result<Dynamic, String> {
            let h = crate::methods::tail::horizontal_tail_alone(case, index, alpha_deg)
                .map_err(|e| e.to_string())?;
            dy::horizontal_tail_dynamic(case, index, alpha_deg, &h)
                .map(|r| r.0)
                .map_err(|e| e.to_string())
        };
        match part {
            BODY_ALONE => body_alone(),
            HORIZONTAL_TAIL => horizontal_tail(),
            VERTICAL_TAIL | VENTRAL_FIN => {
                // The fin's roll and yaw terms (DATCOM 7.4.2, 7.4.3); the original prints 0
                // for its pitch-rate and α̇ derivatives.
                use crate::methods::lateral::Fin;
                let fin = if part == VENTRAL_FIN {
                    Fin::VentralFin
                } else {
                    Fin::VerticalTail
                };
                // Twin vertical panels without a vertical tail: no roll or yaw method (NDM),
                // as the original.
                let mut d = if part == VERTICAL_TAIL && case.vertical_tail.is_none() {
                    Dynamic::no_method(alpha_deg)
                } else if part == VENTRAL_FIN && crate::methods::lateral::ventral_fin_left_out(case)
                {
                    // Without a horizontal tail the fin's terms are left out (0, as the
                    // original prints them), as from the configuration's.
                    let mut d = Dynamic::no_method(alpha_deg);
                    for column in [
                        &mut d.clp, &mut d.cyp, &mut d.cnp, &mut d.cnr, &mut d.clr, &mut d.cyr,
                    ] {
                        *column = dy::Column::rows(vec![Some(0.0); n]);
                    }
                    d.warnings.push(dy::DynamicWarning::VentralFinLeftOut);
                    d
                } else {
                    dy::fin_dynamic(case, index, alpha_deg, fin).map_err(|e| e.to_string())?
                };
                for column in [&mut d.clq, &mut d.cmq, &mut d.clad, &mut d.cmad] {
                    *column = if wing_not_straight {
                        dy::Column::NoMethod
                    } else {
                        dy::Column::first(n, Some(0.0))
                    };
                }
                Ok(d)
            }
            BODY_VT => {
                // The body's pitch-rate and α̇ derivatives; no roll or yaw method (NDM), as
                // the original.
                let b = body_alone()?;
                let mut d = Dynamic::no_method(alpha_deg);
                d.warnings = b.warnings;
                if !wing_not_straight {
                    (d.clq, d.cmq, d.clad, d.cmad) = (b.clq, b.cmq, b.clad, b.cmad);
                }
                Ok(d)
            }
            BODY_HT => {
                // The wing-body's rule (DATCOM 7.3) with the tail in the wing's place; its
                // roll damping is the tail's, no yaw or side-force method (NDM), as the
                // original.
                let mut proxy =
                    crate::methods::tail::tail_as_wing(case).map_err(|e| e.to_string())?;
                proxy.reference.span = crate::methods::lateral::lateral_reference_length(case);
                let wb = crate::methods::wing_body::wing_body(&proxy, index, alpha_deg)
                    .map_err(|e| e.to_string())?;
                let mut d = dy::wing_body_dynamic(&horizontal_tail()?, &body_alone()?, &wb);
                for column in [&mut d.cyp, &mut d.cnp, &mut d.cnr, &mut d.clr] {
                    *column = dy::Column::NoMethod;
                }
                if wing_not_straight {
                    d.clq = dy::Column::NoMethod;
                    d.cmq = dy::Column::NoMethod;
                }
                Ok(d)
            }
            WING_ALONE => {
                let w =
                    crate::methods::wing::wing_alone_with_section(case, index, alpha_deg, section)
                        .map_err(|e| e.to_string())?;
                wing(&w)
            }
            WING_BODY => {
                let wb = crate::methods::wing_body::wing_body_with_section(
                    case, index, alpha_deg, section,
                )
                .map_err(|e| e.to_string())?;
                wing_body(&wb)
            }
            _ => {
                let t = totals
                    .ok_or("no configuration totals")?
                    .as_ref()
                    .map_err(Clone::clone)?;
                let wb = wing_body(&t.terms.wing_body)?;
                let tail = match &t.terms.horizontal_tail {
                    Some(h) => Some(
                        dy::horizontal_tail_dynamic(case, index, alpha_deg, h)
                            .map(|r| r.0)
                            .map_err(|e| e.to_string())?,
                    ),
                    None => None,
                };
                let which = match part {
                    WING_BODY_HT => TailConfiguration::WingBodyHorizontalTail,
                    WING_BODY_VT => TailConfiguration::WingBodyVerticalTail,
                    _ => TailConfiguration::WingBodyVerticalTailHorizontalTail,
                };
                dy::wing_body_tail_dynamic(case, index, which, &wb, tail.as_ref(), t)
                    .map(|c| c.total)
                    .map_err(|e| e.to_string())
            }
        }
    })();
    match computed {
        Ok(d) => {
            let warnings = Warning::all_under(Context::Dynamic { mach }, &d.warnings).collect();
            (DynamicDerivatives::from_columns(&d), warnings)
        }
        Err(e) => (
            DynamicDerivatives::empty(n),
            vec![Warning::new(Context::Dynamic { mach }, e)],
        ),
    }
}

/// The components a build-up page holds, one bit each: body, wing, horizontal tail, the
/// vertical tail with its twin panels, the ventral fin (every fin on the pages named after
/// the vertical tail). Any other name is the full configuration.
fn page_components(part: &str) -> u8 {
    const BODY: u8 = 1;
    const WING: u8 = 2;
    const HORIZONTAL: u8 = 4;
    const VERTICAL: u8 = 8;
    const VENTRAL: u8 = 16;
    match part {
        BODY_ALONE => BODY,
        WING_ALONE => WING,
        HORIZONTAL_TAIL => HORIZONTAL,
        VERTICAL_TAIL => VERTICAL,
        VENTRAL_FIN => VENTRAL,
        WING_BODY => WING | BODY,
        BODY_HT => BODY | HORIZONTAL,
        BODY_VT => BODY | VERTICAL | VENTRAL,
        WING_BODY_HT => WING | BODY | HORIZONTAL,
        WING_BODY_VT => WING | BODY | VERTICAL | VENTRAL,
        _ => WING | BODY | HORIZONTAL | VERTICAL | VENTRAL,
    }
}

/// The original's name of build-up page `part` (one of the constants above) for `case`: the
/// pages with the vertical tail are named with the fins the case has besides it, twin vertical
/// panels ($TVTPAN) on each, the ventral fin on those with the body (BODY-VERTICAL
/// TAIL-VENTRAL FIN; the full configuration with a ventral fin is named by
/// [`configuration_name`]).
pub fn page_name(case: &Case, part: &str) -> String {
    let (vt, vf, twin) = (
        case.vertical_tail.is_some(),
        case.ventral_fin.is_some(),
        case.twin_panels.is_some(),
    );
    if !vf && !twin {
        return part.to_string();
    }
    let fins = |with_ventral_fin: bool| {
        let mut names = Vec::new();
        if vt {
            names.push("VERTICAL TAIL");
        }
        if vf && with_ventral_fin {
            names.push("VENTRAL FIN");
        }
        if twin {
            names.push("TWIN VERTICAL PANEL");
        }
        names.join("-")
    };
    match part {
        VERTICAL_TAIL => format!("{} CONFIGURATION", fins(false)),
        BODY_VT => format!("BODY-{} CONFIGURATION", fins(true)),
        WING_BODY_VT => format!("WING-BODY-{} CONFIGURATION", fins(true)),
        WING_BODY_VT_HT if twin => {
            format!("WING-BODY-HORIZONTAL TAIL-{} CONFIGURATION", fins(true))
        }
        other => other.to_string(),
    }
}

/// Configuration name as the original prints it, from the components present.
pub fn configuration_name(case: &Case) -> String {
    if case.larwb.is_some() {
        return LOW_ASPECT_RATIO.to_string();
    }
    let body = case.body.is_some();
    let wing = case.wing.is_some();
    let mut parts: Vec<&str> = Vec::new();
    if wing {
        parts.push("WING");
    }
    if body {
        parts.push("BODY");
    }
    let ht = case.horizontal_tail.is_some();
    let vt = case.vertical_tail.is_some();
    let vf = case.ventral_fin.is_some();
    let twin = case.twin_panels.is_some();
    if vf || twin {
        // With a ventral fin or twin panels the original names the horizontal tail first.
        if ht {
            parts.push("HORIZONTAL TAIL");
        }
        if vt {
            parts.push("VERTICAL TAIL");
        }
        if vf {
            parts.push("VENTRAL FIN");
        }
        if twin {
            parts.push("TWIN VERTICAL PANEL");
        }
    } else {
        if vt {
            parts.push("VERTICAL TAIL");
        }
        if ht {
            parts.push("HORIZONTAL TAIL");
        }
    }
    match parts.as_slice() {
        [] => NO_COMPONENT.to_string(),
        // The original's name for the body alone.
        ["BODY"] => BODY_ALONE.to_string(),
        ["TWIN VERTICAL PANEL"] => "TWIN VERTICAL PANEL CONFIGURATION".to_string(),
        [one] => format!("{one} ALONE CONFIGURATION"),
        _ => format!("{} CONFIGURATION", parts.join("-")),
    }
}

/// Reference dimensions: $OPTINS, else the wing's theoretical area, mean aerodynamic chord and
/// span; $LARWB's SREF, L and XCG replace them when given (as in the original).
fn reference(case: &Case) -> ReferenceDimensions {
    // A value that is not a number (a case built in code can hold one) is not given: the
    // wing's area and chord are used, as without SREF and CBARR.
    let given = |v: Option<f64>| v.filter(|x| x.is_finite());
    // A planform too large for f64 gives no reference (and `run_case` says so).
    let from_wing = case
        .wing
        .as_ref()
        .and_then(planform_area_and_mac)
        .filter(|(area, chord)| area.is_finite() && chord.is_finite());
    let synth = case.synthesis.as_ref();
    let zcg = given(synth.and_then(|s| s.zcg)).unwrap_or(0.0);
    if let Some(lb) = &case.larwb {
        return ReferenceDimensions {
            area: given(lb.sref),
            chord: given(lb.length),
            span: given(case.reference.span),
            xcg: given(lb.xcg).unwrap_or(0.0),
            zcg,
        };
    }
    ReferenceDimensions {
        area: given(case.reference.area).or(from_wing.map(|w| w.0)),
        chord: given(case.reference.chord).or(from_wing.map(|w| w.1)),
        span: given(case.reference.span)
            .or_else(|| given(case.wing.as_ref().and_then(|w| w.sspn).map(|s| 2.0 * s))),
        xcg: given(synth.and_then(|s| s.xcg)).unwrap_or(0.0),
        zcg,
    }
}

/// Why a case's scale cannot be used, if it cannot: it is not a positive number, or it is so
/// small that the reference dimensions divided back by it overflow in the deck's units. Such
/// a scale is taken as 1.
pub(crate) fn why_the_scale_is_not_used(case: &Case) -> Option<&'static str> {
    if case.scale == 1.0 {
        return None;
    }
    if !(case.scale.is_finite() && case.scale > 0.0) {
        return Some("is not a positive number");
    }
    let reported = reference(case).in_deck_units(case.dim, case.scale);
    (!reported.is_finite()).then_some(
        "is so small that the reference dimensions divided by it overflow in the deck's units",
    )
}

/// A case whose scale cannot be used ([`why_the_scale_is_not_used`]): the same case with a
/// scale of 1, and the warning that says so.
fn with_a_scale_that_is_a_number(case: &Case) -> Option<(Case, Warning)> {
    let why = why_the_scale_is_not_used(case)?;
    // The case's geometry is already scaled; SCALE only turns the reference dimensions back
    // into the deck's.
    let mut fixed = case.clone();
    fixed.scale = 1.0;
    let said = Warning::text(format!(
        "the case's scale {} {why}: taken as 1 (the reference dimensions are reported as the case gives them)",
        crate::charts::Query(case.scale)
    ));
    Some((fixed, said))
}

/// Runs one case. A case whose angles of attack are not in increasing order is computed at
/// its angles in increasing order, each once, with a warning (see
/// [`crate::case::FlightInput::angles_in_order`]).
///
/// A case built in code whose flight conditions were not derived from its `flight` (no
/// [`Case::prepare`] after `flight` was set or changed) is computed at the conditions `flight`
/// gives, with a warning. So is a case whose scale is not a positive number (taken as 1). An
/// optional input value that is not a number (NaN or ±inf, which no deck can give: a
/// reference area, a chord station, a position) is not given, with a warning naming each; an
/// element of an array that is not a number is kept in place, named by a warning, and refused
/// by what reads it, which says so (a flight condition, a body, a section's coordinates).
///
/// The build-up reads slopes and the downwash from its curves over the schedule of angles,
/// as the original does: the values at an angle depend on the other angles given
/// (docs/tail.md). A schedule of one angle gives no longitudinal coefficients on the pages
/// with the downwash at a horizontal tail, and CLA and CMA only where they are analytic, with
/// a warning. Angles of ±90° and beyond with a lifting surface, and beyond ±180°, are computed
/// with a warning, as `check` says of them.
pub fn run_case(case: &Case) -> CaseResults {
    if let Some((fixed, said)) = with_a_scale_that_is_a_number(case) {
        let mut results = run_case(&fixed);
        results.warnings.insert(0, said);
        return results;
    }
    if let Some(taken) = case.without_scalars_not_numbers() {
        let mut results = run_scalars_given(&taken.case);
        let said = [
            (taken.not_given, "not given"),
            (taken.left, "kept in place, refused where it is read"),
        ];
        let warnings = said
            .iter()
            .filter_map(|(found, what)| not_numbers_said(found, what))
            .map(Warning::text);
        results.warnings.splice(0..0, warnings);
        return results;
    }
    run_scalars_given(case)
}

/// What a warning says of a case's values that are not numbers, and `what` becomes of them.
fn not_numbers_said(found: &[crate::case::NotANumber], what: &str) -> Option<String> {
    let named: Vec<String> = found.iter().map(ToString::to_string).collect();
    match named.as_slice() {
        [] => None,
        [one] => Some(format!("the case's {one} is not a number: {what}")),
        many => Some(format!(
            "the case's {} are not numbers: {what}",
            many.join(", ")
        )),
    }
}

/// [`run_case`] for a case whose optional input values are all numbers.
fn run_scalars_given(case: &Case) -> CaseResults {
    if build_up_implied(case) {
        // The original's pages for such a case: the whole build-up and the partial output.
        let mut built = case.clone();
        built.cards.build = true;
        built.cards.part = true;
        let mut results = run_case(&built);
        results.warnings.insert(0, Warning::text(BUILD_UP_IMPLIED));
        return results;
    }
    let ordered = case
        .flight
        .as_ref()
        .and_then(crate::case::FlightInput::angles_in_order);
    let derived = case.flight.as_ref().and_then(|f| {
        let (conditions, warnings) = crate::conditions::flight_conditions(f);
        (conditions != case.conditions).then_some((conditions, warnings))
    });
    if ordered.is_none() && derived.is_none() {
        return compute_case(case);
    }
    let mut fixed = case.clone();
    let mut notes = Vec::new();
    if let Some((conditions, warnings)) = derived {
        fixed.conditions = conditions;
        fixed.condition_warnings = warnings;
        notes.push(
            "the flight conditions are derived from the case's flight input here: Case::prepare was not called after it was set or changed".to_string(),
        );
    }
    if let (Some(ordered), Some(f)) = (ordered, fixed.flight.as_mut()) {
        f.alpha_deg = ordered.angles;
        notes.push(ordered.reason);
    }
    let mut results = compute_case(&fixed);
    results
        .warnings
        .splice(0..0, notes.into_iter().map(Warning::from));
    results
}

/// Why a case without BUILD or PART prints the build-up and the partial output.
const BUILD_UP_IMPLIED: &str = "a double-delta or cranked wing with a body and tails: the configuration has no lift, drag or moment method, and the pages of the build-up and the partial output (PART) are given as with BUILD and PART, as the original prints them";

/// A body, a double-delta or cranked wing and a tail or fin, without BUILD or PART: the
/// original prints the build-up and the partial output for it as if both cards were given (its
/// configuration page has no lift, drag or moment method).
fn build_up_implied(case: &Case) -> bool {
    let tails = case.horizontal_tail.is_some()
        || case.vertical_tail.is_some()
        || case.ventral_fin.is_some();
    case.body.is_some()
        && tails
        && double_delta_or_cranked_wing(case)
        && !(case.cards.build && case.cards.part)
}

/// The case's wing is a double delta or cranked (TYPE 2 or 3).
fn double_delta_or_cranked_wing(case: &Case) -> bool {
    use crate::methods::wing::WingType;
    case.wing.as_ref().is_some_and(|w| {
        matches!(
            WingType::from_input(w.planform_type),
            Some(WingType::DoubleDelta | WingType::Cranked)
        )
    })
}

/// Leaves none of a page's coefficients infinite or NaN: each such value becomes none (not
/// computed, as the original's NA), and the warning returned says which, where. A method's
/// inputs that pass the deck's checks can still overflow (a body radius of 1e300, a chord of
/// 1e-30 beside a span of 3).
fn without_non_finite(entry: &mut ConditionResults) -> Option<String> {
    let alpha = &entry.alpha_deg;
    let mut found: Vec<String> = Vec::new();
    let mut scan = |name: &str, column: &mut Vec<Option<f64>>| {
        let mut at = Vec::new();
        for (k, v) in column.iter_mut().enumerate() {
            if v.is_some_and(|x| !x.is_finite()) {
                *v = None;
                at.push(
                    alpha
                        .get(k)
                        .map_or_else(|| format!("row {}", k + 1), |a| format!("{a}")),
                );
            }
        }
        if !at.is_empty() {
            found.push(format!("{name} at alpha {}", at.join(", ")));
        }
    };
    for (name, column) in entry.static_coefficients.columns_mut() {
        scan(name, column);
    }
    if let Some(d) = entry.dynamic.as_mut() {
        for (name, column) in d.columns_mut() {
            scan(name, column);
        }
        if let Some(cyr) = d.cyr.as_mut() {
            scan("CYR", cyr);
        }
    }
    (!found.is_empty()).then(|| {
        format!(
            "Mach {}, {}: not finite, not computed: {}",
            crate::charts::Query(entry.condition.mach),
            entry.configuration,
            found.join("; ")
        )
    })
}

fn compute_case(case: &Case) -> CaseResults {
    let mut warnings = Vec::new();
    // A schedule of one angle left something out ([`without_schedule_readings`]).
    let mut one_angle_left_out = false;
    let mut conditions = Vec::new();
    // Sections first: the wing methods take the wing's section from here (computed once).
    let sections = sections(case);
    let wing_section = sections
        .iter()
        .find(|s| s.surface == Surface::Wing)
        .and_then(|s| s.characteristics.as_ref());
    let configuration = configuration_name(case);
    if let Some(f) = &case.flight {
        let conds = case.conditions.clone();
        warnings.extend(
            case.condition_warnings
                .iter()
                .map(|w| Warning::text(w.as_str())),
        );
        // What `check` says of the schedule, said by the run too (a case built in code may
        // not have been checked).
        let lifting = case.has_lifting_surface();
        // By value: the run's schedule is in increasing order, not always the deck's.
        let angles = f.alpha_deg.iter().map(|&a| (None, a));
        if let Some((_, problem)) = crate::case::angles_of_attack_problem(angles, lifting) {
            warnings.push(format!("{problem}: computed as given").into());
        }
        if case.synthesis.is_none() && case.larwb.is_none() && (lifting || case.body.is_some()) {
            warnings.push(
                "the case has no synthesis ($SYNTHS): the centre of gravity and every component's position are taken as 0 (the original does not run such a case)".into(),
            );
        }
        warnings.extend(
            crate::methods::experimental::unused_variables(case)
                .into_iter()
                .map(Warning::from),
        );
        let n = f.alpha_deg.len();
        // Component configurations: the configuration itself when it is one component, and
        // with BUILD the parts of the build-up the methods so far compute.
        let wb = case.wing.is_some() && case.body.is_some();
        let (ht, vt) = (case.horizontal_tail.is_some(), case.vertical_tail.is_some());
        // With a ventral fin the full configuration (the original's WING-BODY-HORIZONTAL
        // TAIL-VERTICAL TAIL-VENTRAL FIN page) takes the place of WING_BODY_VT_HT: the same
        // totals with the fin's drag and sideslip terms.
        let vf = case.ventral_fin.is_some();
        let twin = case.twin_panels.is_some();
        // Twin vertical panels without a vertical tail: the full configuration is named
        // without it (WING-BODY-HORIZONTAL TAIL-TWIN VERTICAL PANEL).
        let full = if vf || (twin && !vt) {
            configuration.as_str()
        } else {
            WING_BODY_VT_HT
        };
        // In the original's page order.
        let body = case.body.is_some();
        // With a ventral fin the pages with the vertical tail carry it too, and are named
        // with it ([`page_name`]); without a horizontal tail (a finned rocket) the
        // WING-BODY-VERTICAL TAIL-VENTRAL FIN page is the configuration.
        let parts: [(&str, bool); 12] = [
            (LOW_ASPECT_RATIO, case.larwb.is_some()),
            (BODY_ALONE, body),
            (WING_ALONE, case.wing.is_some()),
            (HORIZONTAL_TAIL, ht),
            (VERTICAL_TAIL, vt || twin),
            (VENTRAL_FIN, vf),
            (WING_BODY, wb),
            (BODY_HT, body && ht),
            (BODY_VT, body && (vt || vf || twin)),
            (WING_BODY_HT, wb && ht),
            (WING_BODY_VT, wb && (vt || vf || twin)),
            (full, wb && ht && (vt || vf || twin)),
        ];
        // The case's own pages: the page of its configuration; for a combination the
        // build-up has no page for (a wing and tails without a body, a body and tails without
        // a wing), the largest pages it has, as the original prints them (WING ALONE and
        // HORIZONTAL TAIL for a wing with a horizontal tail; BODY-HORIZONTAL TAIL and
        // BODY-VERTICAL TAIL for a body with both tails).
        let own_pages: Vec<&str> = {
            let present: Vec<&str> = parts
                .iter()
                .filter(|(part, present)| *present && *part != LOW_ASPECT_RATIO)
                .map(|(part, _)| *part)
                .collect();
            // Page names differ from the parts' constants only with fins besides the
            // vertical tail (`page_name`): compared without building them otherwise.
            let renamed = vf || twin;
            match parts.iter().find(|(part, present)| {
                *present
                    && if renamed {
                        page_name(case, part) == configuration
                    } else {
                        *part == configuration
                    }
            }) {
                Some((part, _)) => vec![*part],
                None => {
                    let within = |a: &str, b: &str| {
                        let (a, b) = (page_components(a), page_components(b));
                        a != b && a & b == a
                    };
                    present
                        .iter()
                        .copied()
                        .filter(|a| !present.iter().any(|b| within(a, b)))
                        .collect()
                }
            }
        };
        if own_pages.len() > 1 && !conds.is_empty() {
            warnings.push(format!(
                "{configuration}: the build-up has no page of its own for this combination of components: the pages of its largest parts are given ({}), as the original prints them",
                own_pages.join(", ")
            ).into());
        }
        for (index, c) in conds.into_iter().enumerate() {
            let mut own_computed = false;
            // The configurations with tails come from one computation per condition.
            let mut totals: Option<Result<crate::methods::tail::ConfigurationTotals, String>> =
                None;
            for (part, present) in parts {
                let name = page_name(case, part);
                let own = own_pages.contains(&part);
                if !present || !(own || case.cards.build) {
                    continue;
                }
                let computed = match part {
                    LOW_ASPECT_RATIO => low_aspect_ratio_coefficients(case, &c, &f.alpha_deg),
                    BODY_ALONE => body_alone_coefficients(case, &c, &f.alpha_deg),
                    WING_ALONE => wing_alone_coefficients(case, index, &f.alpha_deg, wing_section),
                    WING_BODY => {
                        wing_body_coefficients(case, index, &f.alpha_deg, wing_section, None)
                    }
                    HORIZONTAL_TAIL => horizontal_tail_coefficients(case, index, &f.alpha_deg),
                    VERTICAL_TAIL => {
                        let fin = crate::methods::lateral::Fin::VerticalTail;
                        fin_alone_coefficients(case, index, &f.alpha_deg, fin)
                    }
                    VENTRAL_FIN => {
                        let fin = crate::methods::lateral::Fin::VentralFin;
                        fin_alone_coefficients(case, index, &f.alpha_deg, fin)
                    }
                    BODY_HT => body_horizontal_tail_coefficients(case, index, &f.alpha_deg),
                    BODY_VT => body_vertical_tail_coefficients(case, &c, index, &f.alpha_deg),
                    _ => {
                        let t = totals.get_or_insert_with(|| {
                            crate::methods::tail::configuration(case, index, &f.alpha_deg)
                                .map_err(|e| format!("configuration with tails: {e}"))
                        });
                        tail_configuration_coefficients(case, index, t, part)
                    }
                };
                let (static_coefficients, static_warnings) = match computed {
                    Ok((s, w)) => (s, Ok(w)),
                    Err(e) => (StaticCoefficients::empty(n), Err(e)),
                };
                let mut entry = ConditionResults {
                    condition: c.clone(),
                    configuration: name,
                    alpha_deg: f.alpha_deg.clone(),
                    static_coefficients,
                    // With DAMP the original prints a dynamic page after each configuration's
                    // static page.
                    dynamic: None,
                    downwash: None,
                    auxiliary: None,
                };
                // The pages with a horizontal tail behind the wing carry its downwash.
                if !matches!(
                    part,
                    LOW_ASPECT_RATIO
                        | BODY_ALONE
                        | WING_ALONE
                        | WING_BODY
                        | HORIZONTAL_TAIL
                        | VERTICAL_TAIL
                        | VENTRAL_FIN
                        | BODY_HT
                        | BODY_VT
                        | WING_BODY_VT
                ) {
                    if let Some(Ok(t)) = &totals {
                        entry.downwash = t.terms.downwash.as_ref().map(DownwashTable::from);
                    }
                }
                if case.cards.damp {
                    let (d, mut w) = dynamic_derivatives(
                        case,
                        index,
                        &f.alpha_deg,
                        part,
                        wing_section,
                        totals.as_ref(),
                    );
                    entry.dynamic = Some(d);
                    warnings.append(&mut w);
                }
                // The page's own warnings after its dynamic derivatives'.
                match static_warnings {
                    Ok(mut w) => warnings.append(&mut w),
                    Err(e) => {
                        warnings.push(format!("Mach {}: {e}", crate::charts::Query(c.mach)).into())
                    }
                }
                if own {
                    own_computed = true;
                    if case.cards.part && own_pages.last() == Some(&part) {
                        entry.auxiliary = Some(crate::auxiliary::auxiliary_output(
                            case,
                            index,
                            &f.alpha_deg,
                            wing_section,
                        ));
                    }
                }
                if n == 1 {
                    one_angle_left_out |= without_schedule_readings(&mut entry, part);
                }
                if let Some(w) = without_non_finite(&mut entry) {
                    warnings.push(w.into());
                }
                conditions.push(entry);
            }
            if !own_computed {
                // Only a case without a component has no page of its own (the deck's check
                // says so).
                conditions.push(ConditionResults {
                    condition: c,
                    configuration: configuration.clone(),
                    alpha_deg: f.alpha_deg.clone(),
                    static_coefficients: StaticCoefficients::empty(n),
                    dynamic: case.cards.damp.then(|| DynamicDerivatives::empty(n)),
                    downwash: None,
                    auxiliary: None,
                });
            }
        }
    }
    if one_angle_left_out {
        warnings.push(ONE_ANGLE.into());
    }
    // The same warning from several configurations of a condition is said once (the
    // writers also say a text once: `warning::texts`).
    crate::warning::dedup(&mut warnings);
    let wing_reference = case.wing.as_ref().and_then(planform_area_and_mac);
    if wing_reference.is_some_and(|(area, chord)| !(area.is_finite() && chord.is_finite())) {
        warnings.push(
            "the wing's planform gives no finite reference area or chord (its dimensions overflow): no reference taken from it".into(),
        );
    }
    CaseResults {
        number: case.number,
        caseid: case.caseid.clone(),
        dim: case.dim,
        deriv: case.deriv,
        scale: case.scale,
        reference: reference(case),
        sections,
        conditions,
        warnings,
        configuration,
    }
}

/// What a schedule of one angle of attack does not give ([`without_schedule_readings`]).
const ONE_ANGLE: &str = "one angle of attack: DATCOM's build-up reads slopes and the downwash at the horizontal tail from its curves over the schedule's angles, which one angle does not give (a curve of one point is flat): CLA and CMA are given only where they are a method's analytic slopes (body, wing and horizontal tail alone), and the longitudinal coefficients of the pages with the downwash at a horizontal tail are not given; the other values read their curves at nearby angles as flat (a few per cent); give a schedule of several angles around the one wanted";

/// A page computed at one angle of attack, without what DATCOM's build-up reads as slopes of
/// its curves over the schedule (a curve of one point was read with a slope of 0): the slopes
/// CLA and CMA, except on the body-, wing- and horizontal-tail-alone pages, whose first
/// angle's are their methods' analytic slopes; on a page with the downwash at a horizontal
/// tail (its gradient, and the longitudinal coefficients through it) CD, CL, CM, CN, CA, XCP,
/// the downwash table and the α̇ derivatives. The sideslip derivatives stand, as do the other
/// values, as the original prints them (docs/differences.md). Whether anything was left out.
fn without_schedule_readings(entry: &mut ConditionResults, part: &str) -> bool {
    let s = &mut entry.static_coefficients;
    let mut left_out = false;
    let mut leave_out = |column: &mut Vec<Option<f64>>| {
        for v in column.iter_mut() {
            left_out |= v.take().is_some();
        }
    };
    if ![BODY_ALONE, WING_ALONE, HORIZONTAL_TAIL].contains(&part) {
        leave_out(&mut s.cla);
        leave_out(&mut s.cma);
    }
    if entry.downwash.take().is_some() {
        for column in [
            &mut s.cd, &mut s.cl, &mut s.cm, &mut s.cn, &mut s.ca, &mut s.xcp,
        ] {
            leave_out(column);
        }
        if let Some(d) = &mut entry.dynamic {
            leave_out(&mut d.clad);
            leave_out(&mut d.cmad);
        }
        left_out = true;
    }
    left_out
}

/// The section of every surface that has one (coordinates and characteristics), with what
/// could not be computed said in its warnings.
fn sections(case: &Case) -> Vec<SectionResult> {
    let surfaces = [
        Surface::Wing,
        Surface::HorizontalTail,
        Surface::VerticalTail,
        Surface::VentralFin,
    ];
    surfaces
        .into_iter()
        .filter_map(|surface| {
            let mut warnings = Vec::new();
            let coordinates = match section_for(case, surface)? {
                Ok(c) => Some(c),
                Err(e) => {
                    warnings.push(Warning::new(Context::Section(surface), e.to_string()));
                    None
                }
            };
            let characteristics = match surface_section(case, surface) {
                None => None,
                Some(Err(e)) => {
                    warnings.push(Warning::new(Context::Section(surface), e.to_string()));
                    None
                }
                Some(Ok(s)) => {
                    warnings.extend(Warning::all_under(Context::Section(surface), &s.warnings));
                    match section_characteristics(&s.shape, &s.conditions, &s.overrides) {
                        Ok(c) => {
                            warnings
                                .extend(Warning::all_under(Context::Section(surface), &c.warnings));
                            Some(c)
                        }
                        Err(e) => {
                            warnings.push(
                                format!("{} section characteristics: {e}", surface.name()).into(),
                            );
                            None
                        }
                    }
                }
            };
            Some(SectionResult {
                surface,
                coordinates,
                characteristics,
                warnings,
            })
        })
        .collect()
}

/// Runs every case of a deck.
pub fn run(deck: &Deck) -> Results {
    Results {
        file: deck.file.clone(),
        cases: deck.cases.iter().map(run_case).collect(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn mac_of_a_rectangle_is_its_chord() {
        let p = Planform {
            chrdr: Some(2.0),
            chrdtp: Some(2.0),
            sspn: Some(5.0),
            ..Planform::default()
        };
        let (area, mac) = planform_area_and_mac(&p).unwrap();
        assert!((area - 20.0).abs() < 1e-12);
        assert!((mac - 2.0).abs() < 1e-12);
    }
}
