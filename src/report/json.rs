//! The JSON of `datcom-rs run --format json`, in the deck's units (documented in
//! docs/output.md). Field names are a contract with users' scripts: keep them.

use serde::Serialize;

use super::{condition_view, derivative_view, reference_view, ConditionView};
use crate::deck::cards::DerivUnit;
use crate::results::{CaseResults, ConditionResults, Results};

#[derive(Serialize)]
pub struct StaticJson {
    pub alpha: Vec<f64>,
    #[serde(rename = "CD")]
    pub cd: Vec<Option<f64>>,
    #[serde(rename = "CL")]
    pub cl: Vec<Option<f64>>,
    #[serde(rename = "CM")]
    pub cm: Vec<Option<f64>>,
    #[serde(rename = "CN")]
    pub cn: Vec<Option<f64>>,
    #[serde(rename = "CA")]
    pub ca: Vec<Option<f64>>,
    #[serde(rename = "XCP")]
    pub xcp: Vec<Option<f64>>,
    #[serde(rename = "CLA")]
    pub cla: Vec<Option<f64>>,
    #[serde(rename = "CMA")]
    pub cma: Vec<Option<f64>>,
    #[serde(rename = "CYB")]
    pub cyb: Vec<Option<f64>>,
    #[serde(rename = "CNB")]
    pub cnb: Vec<Option<f64>>,
    #[serde(rename = "CLB")]
    pub clb: Vec<Option<f64>>,
}

#[derive(Serialize)]
pub struct DynamicJson {
    pub alpha: Vec<f64>,
    #[serde(rename = "CLQ")]
    pub clq: Vec<Option<f64>>,
    #[serde(rename = "CMQ")]
    pub cmq: Vec<Option<f64>>,
    #[serde(rename = "CLAD")]
    pub clad: Vec<Option<f64>>,
    #[serde(rename = "CMAD")]
    pub cmad: Vec<Option<f64>>,
    #[serde(rename = "CLP")]
    pub clp: Vec<Option<f64>>,
    #[serde(rename = "CYP")]
    pub cyp: Vec<Option<f64>>,
    #[serde(rename = "CNP")]
    pub cnp: Vec<Option<f64>>,
    #[serde(rename = "CNR")]
    pub cnr: Vec<Option<f64>>,
    #[serde(rename = "CLR")]
    pub clr: Vec<Option<f64>>,
    /// Extension, not on the original's page: the vertical panels' side force due to yaw rate
    /// (docs/output.md); absent where there is none (and in imported listings).
    #[serde(rename = "CYR", default, skip_serializing_if = "Option::is_none")]
    pub cyr: Option<Vec<Option<f64>>>,
    /// Columns for which DATCOM has no method for this configuration (the original's NDM).
    pub no_method: Vec<String>,
}

#[derive(Serialize)]
pub struct ConditionJson {
    #[serde(flatten)]
    pub condition: ConditionView,
    pub configuration: String,
    /// On a page imported from the original's listing: what its static page includes, as the
    /// original prints it under the configuration (power or ground effects). Absent on ours
    /// (no power or ground effects are computed) and on the original's ordinary pages.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub included: Vec<String>,
    pub deriv_unit: DerivUnit,
    #[serde(rename = "static")]
    pub static_coefficients: StaticJson,
    pub dynamic: Option<DynamicJson>,
    /// The downwash at the horizontal tail (the original's table under the page); absent on
    /// pages without one.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub downwash: Option<DownwashJson>,
    /// With the PART card, on the case's own configuration: the original's CONFIGURATION
    /// AUXILIARY AND PARTIAL OUTPUT (docs/output.md); absent otherwise.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub auxiliary: Option<super::auxiliary::AuxiliaryJson>,
}

/// The ALPHA Q/QINF EPSLON D(EPSLON)/D(ALPHA) table.
#[derive(Serialize)]
pub struct DownwashJson {
    pub alpha: Vec<f64>,
    #[serde(rename = "Q/QINF")]
    pub q_over_q_inf: Vec<Option<f64>>,
    /// Degrees.
    #[serde(rename = "EPSLON")]
    pub epsilon: Vec<Option<f64>>,
    #[serde(rename = "D(EPSLON)/D(ALPHA)")]
    pub gradient: Vec<Option<f64>>,
}

#[derive(Serialize)]
pub struct ReferenceJson {
    pub area: Option<f64>,
    pub longitudinal: Option<f64>,
    pub lateral: Option<f64>,
    pub xcg: f64,
    pub zcg: f64,
}

#[derive(Serialize)]
pub struct UnitsJson {
    pub length: String,
    pub velocity: String,
    pub pressure: String,
    pub temperature: String,
    pub reynolds_per_length: String,
    pub area: String,
}

/// A section's lift-curve slope and aerodynamic centre at one Mach number.
#[derive(Serialize)]
pub struct SectionMachJson {
    pub mach: f64,
    pub lift_curve_slope_per_deg: Option<f64>,
    pub xac: Option<f64>,
}

/// A section's characteristics (the SECTION DEFINITION page); null where not computed.
#[derive(Serialize)]
pub struct SectionJson {
    pub title: Option<String>,
    pub ideal_alpha_deg: Option<f64>,
    pub zero_lift_alpha_deg: Option<f64>,
    pub ideal_cl: Option<f64>,
    pub cm0: Option<f64>,
    pub cla_mach0_per_deg: Option<f64>,
    pub le_radius: Option<f64>,
    pub max_thickness: Option<f64>,
    pub delta_y: Option<f64>,
    pub per_mach: Vec<SectionMachJson>,
    pub warnings: Vec<String>,
}

fn section_json(s: &crate::results::SectionResult) -> SectionJson {
    let per_deg = std::f64::consts::PI / 180.0;
    let k = s.characteristics.as_ref();
    let mut per_mach: Vec<SectionMachJson> = Vec::new();
    for m in k.map(|k| k.per_mach.as_slice()).unwrap_or_default() {
        if per_mach.iter().any(|p| p.mach == m.mach) {
            continue;
        }
        per_mach.push(SectionMachJson {
            mach: m.mach,
            lift_curve_slope_per_deg: m.cla_per_rad.map(|v| v * per_deg),
            xac: m.xac,
        });
    }
    SectionJson {
        title: s.coordinates.as_ref().map(|c| c.title.clone()),
        ideal_alpha_deg: k.map(|k| k.ideal_alpha_deg),
        zero_lift_alpha_deg: k.map(|k| k.zero_lift_alpha_deg),
        ideal_cl: k.map(|k| k.ideal_cl),
        cm0: k.map(|k| k.cm0),
        cla_mach0_per_deg: k.map(|k| k.cla_mach0_per_rad * per_deg),
        le_radius: k.map(|k| k.leading_edge_radius),
        max_thickness: k.map(|k| k.max_thickness),
        delta_y: k.map(|k| k.delta_y_percent),
        per_mach,
        // Each of a section's warnings (one per condition where they repeat), as ever.
        warnings: s.warnings.iter().map(ToString::to_string).collect(),
    }
}

#[derive(Serialize)]
pub struct CaseJson {
    pub case: usize,
    pub caseid: Option<String>,
    pub units: UnitsJson,
    pub reference: ReferenceJson,
    /// By surface name: WING, HORIZONTAL TAIL, VERTICAL TAIL, VENTRAL FIN.
    pub sections: std::collections::BTreeMap<String, SectionJson>,
    pub conditions: Vec<ConditionJson>,
    pub warnings: Vec<String>,
}

#[derive(Serialize)]
pub struct ResultsJson {
    pub file: String,
    pub cases: Vec<CaseJson>,
}

fn d(v: &[Option<f64>], unit: DerivUnit) -> Vec<Option<f64>> {
    v.iter().map(|x| derivative_view(*x, unit)).collect()
}

fn condition(c: &ConditionResults, case: &CaseResults) -> ConditionJson {
    let u = case.deriv;
    let s = &c.static_coefficients;
    ConditionJson {
        condition: condition_view(c, case.dim),
        configuration: c.configuration.clone(),
        included: Vec::new(),
        deriv_unit: u,
        static_coefficients: StaticJson {
            alpha: c.alpha_deg.clone(),
            cd: s.cd.clone(),
            cl: s.cl.clone(),
            cm: s.cm.clone(),
            cn: s.cn.clone(),
            ca: s.ca.clone(),
            xcp: s.xcp.clone(),
            cla: d(&s.cla, u),
            cma: d(&s.cma, u),
            cyb: d(&s.cyb, u),
            cnb: d(&s.cnb, u),
            clb: d(&s.clb, u),
        },
        dynamic: c.dynamic.as_ref().map(|y| DynamicJson {
            alpha: c.alpha_deg.clone(),
            clq: d(&y.clq, u),
            cmq: d(&y.cmq, u),
            clad: d(&y.clad, u),
            cmad: d(&y.cmad, u),
            clp: d(&y.clp, u),
            cyp: d(&y.cyp, u),
            cnp: d(&y.cnp, u),
            cnr: d(&y.cnr, u),
            clr: d(&y.clr, u),
            cyr: y.cyr.as_ref().map(|c| d(c, u)),
            no_method: y.no_method.iter().map(|n| n.to_string()).collect(),
        }),
        downwash: c.downwash.as_ref().map(|w| DownwashJson {
            alpha: c.alpha_deg.clone(),
            q_over_q_inf: w.dynamic_pressure_ratio.clone(),
            epsilon: w.epsilon_deg.clone(),
            gradient: w.gradient.clone(),
        }),
        auxiliary: c
            .auxiliary
            .as_ref()
            .map(|a| super::auxiliary::view(a, case)),
    }
}

/// The serialisable view of a deck's results.
pub fn view(results: &Results) -> ResultsJson {
    use crate::case::units::unit_label;
    use crate::deck::schema::Dimension as D;
    ResultsJson {
        file: results.file.clone(),
        cases: results
            .cases
            .iter()
            .map(|c| {
                let (area, longitudinal, lateral, xcg, zcg) = reference_view(c);
                CaseJson {
                    case: c.number,
                    caseid: c.caseid.clone(),
                    units: UnitsJson {
                        length: unit_label(c.dim, D::Length).into(),
                        velocity: unit_label(c.dim, D::Velocity).into(),
                        pressure: unit_label(c.dim, D::Pressure).into(),
                        temperature: unit_label(c.dim, D::Temperature).into(),
                        reynolds_per_length: unit_label(c.dim, D::PerLength).into(),
                        area: unit_label(c.dim, D::Area).into(),
                    },
                    reference: ReferenceJson {
                        area,
                        longitudinal,
                        lateral,
                        xcg,
                        zcg,
                    },
                    sections: c
                        .sections
                        .iter()
                        .map(|s| (s.surface.name().to_string(), section_json(s)))
                        .collect(),
                    conditions: c.conditions.iter().map(|k| condition(k, c)).collect(),
                    warnings: crate::warning::texts(&c.warnings),
                }
            })
            .collect(),
    }
}

/// Pretty JSON text of a deck's results.
pub fn to_string(results: &Results) -> String {
    // Serialising plain structs of numbers and strings cannot fail; non-finite numbers become
    // null, and the library does not produce them (see the no-NaN tests).
    serde_json::to_string_pretty(&view(results))
        .unwrap_or_else(|e| format!("{{\"error\":\"{e}\"}}"))
}

fn listed_column(t: &Option<super::legacy::Table>, name: &str) -> Vec<Option<f64>> {
    t.as_ref()
        .and_then(|t| t.column(name))
        .map(<[Option<f64>]>::to_vec)
        .unwrap_or_default()
}

/// The JSON of a listing of the original program, in the shape of `run`'s (values in the
/// listing's units, derivatives in its unit).
pub fn from_listing(cases: &[super::legacy::ListedCase], file: &str) -> ResultsJson {
    ResultsJson {
        file: file.to_string(),
        cases: cases
            .iter()
            .enumerate()
            .map(|(i, c)| {
                let unit = |field: &str| {
                    c.units
                        .iter()
                        .find(|(f, _)| *f == field)
                        .map(|(_, u)| u.clone())
                        .unwrap_or_default()
                };
                let first = c.conditions.first();
                let field =
                    |name: &str| first.and_then(|k| k.row.field(name)).and_then(|f| f.value);
                CaseJson {
                    case: i + 1,
                    caseid: c.caseid.clone(),
                    units: UnitsJson {
                        length: unit("altitude"),
                        velocity: unit("velocity"),
                        pressure: unit("pressure"),
                        temperature: unit("temperature"),
                        reynolds_per_length: unit("reynolds_per_length"),
                        area: unit("area"),
                    },
                    sections: Default::default(),
                    reference: ReferenceJson {
                        area: field("area"),
                        longitudinal: field("longitudinal"),
                        lateral: field("lateral"),
                        xcg: field("xcg").unwrap_or(0.0),
                        zcg: field("zcg").unwrap_or(0.0),
                    },
                    conditions: c
                        .conditions
                        .iter()
                        .map(|k| {
                            let f = |name: &str| k.row.field(name).and_then(|f| f.value);
                            let s = &k.statics;
                            let d = &k.dynamics;
                            let alpha = |t: &Option<super::legacy::Table>| -> Vec<f64> {
                                listed_column(t, "ALPHA").into_iter().flatten().collect()
                            };
                            ConditionJson {
                                condition: ConditionView {
                                    mach: f("mach").unwrap_or(0.0),
                                    altitude: f("altitude"),
                                    velocity: f("velocity"),
                                    pressure: f("pressure"),
                                    temperature: f("temperature"),
                                    reynolds_per_length: f("reynolds_per_length").unwrap_or(0.0),
                                },
                                configuration: k.configuration.clone(),
                                included: k.included.clone(),
                                deriv_unit: if k.deriv_per_radian {
                                    DerivUnit::Rad
                                } else {
                                    DerivUnit::Deg
                                },
                                static_coefficients: StaticJson {
                                    alpha: alpha(s),
                                    cd: listed_column(s, "CD"),
                                    cl: listed_column(s, "CL"),
                                    cm: listed_column(s, "CM"),
                                    cn: listed_column(s, "CN"),
                                    ca: listed_column(s, "CA"),
                                    xcp: listed_column(s, "XCP"),
                                    cla: listed_column(s, "CLA"),
                                    cma: listed_column(s, "CMA"),
                                    cyb: listed_column(s, "CYB"),
                                    cnb: listed_column(s, "CNB"),
                                    clb: listed_column(s, "CLB"),
                                },
                                dynamic: d.as_ref().map(|_| DynamicJson {
                                    alpha: alpha(d),
                                    clq: listed_column(d, "CLQ"),
                                    cmq: listed_column(d, "CMQ"),
                                    clad: listed_column(d, "CLAD"),
                                    cmad: listed_column(d, "CMAD"),
                                    clp: listed_column(d, "CLP"),
                                    cyp: listed_column(d, "CYP"),
                                    cnp: listed_column(d, "CNP"),
                                    cnr: listed_column(d, "CNR"),
                                    clr: listed_column(d, "CLR"),
                                    cyr: None,
                                    no_method: d
                                        .as_ref()
                                        .map(super::legacy::Table::no_method)
                                        .unwrap_or_default(),
                                }),
                                downwash: k.downwash.as_ref().map(|_| DownwashJson {
                                    alpha: alpha(&k.downwash),
                                    q_over_q_inf: listed_column(&k.downwash, "Q/QINF"),
                                    epsilon: listed_column(&k.downwash, "EPSLON"),
                                    gradient: listed_column(&k.downwash, "D(EPSLON)/D(ALPHA)"),
                                }),
                                auxiliary: k.auxiliary.clone(),
                            }
                        })
                        .collect(),
                    warnings: Vec::new(),
                }
            })
            .collect(),
    }
}

fn listed_to_string(cases: &[super::legacy::ListedCase], file: &str) -> String {
    serde_json::to_string_pretty(&from_listing(cases, file))
        .unwrap_or_else(|e| format!("{{\"error\":\"{e}\"}}"))
}

/// Pretty JSON text of a listing of the original program (whatever [`super::legacy::read_listing`]
/// reads in it: nothing from a text that is no listing).
pub fn listing_to_string(listing: &str, file: &str) -> String {
    listed_to_string(&super::legacy::read_listing(listing), file)
}

/// Pretty JSON text of a listing, as `datcom-rs import` writes it: an error for a text that
/// would import as nothing or as invented numbers ([`super::legacy::import`]).
pub fn import_listing(listing: &str, file: &str) -> Result<String, super::legacy::NotImported> {
    super::legacy::import(listing).map(|cases| listed_to_string(&cases, file))
}
