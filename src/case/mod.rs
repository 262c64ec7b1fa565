//! Typed cases: what a deck says, in SI units, with physical checks.
//!
//! [`Deck::from_raw`] turns the namelist values of each case into [`Case`]: flight conditions
//! ([`FlightInput`]), reference dimensions ([`Reference`]), synthesis ([`Synthesis`]), body
//! ([`Body`]), planforms ([`Planform`]), airfoil sections ([`SectionInput`]) and the control
//! cards. Lengths are metres, areas square metres, pressure pascals, temperature kelvins, weight
//! newtons; angles stay in degrees. Namelists not yet used by any method (flaps, power, ground
//! effect, ...) are kept as read, in the deck's units, in [`Case::other`].

mod deck_form;
mod finite;
mod scalars;
pub mod units;

pub use deck_form::NotANumber;

use std::collections::BTreeMap;

use serde::Serialize;

use crate::conditions;
use crate::deck::cards::{AirfoilCard, Cards, DerivUnit, Dim, Surface};
use crate::deck::schema::{self, Dimension};
use crate::deck::{NamelistValues, RawCase, RawDeck, Value};
use crate::error::{DeckProblem, Diagnostic, Severity};
use crate::geometry::planform::{EXPOSED_SPAN_TOLERANCE, RIGHT_ANGLE_DEG};
use crate::geometry::section::SectionError;
pub use crate::methods::section::MaximumReading;
pub use crate::methods::tail::TailSlopeReading;
pub use crate::methods::wing::{ForwardSweepReading, OutboardSectionReading, ZeroLiftReading};
pub use crate::methods::wing_body::JorgensenDragReading;

/// Every value of a case by the [`schema::key`]s of its namelist's and its own name, sorted:
/// lookups compare integers, not names. Longer names, which no namelist or variable has, are
/// left out.
struct ValueIndex<'a> {
    entries: Vec<((u64, u64), &'a Value)>,
}

impl<'a> ValueIndex<'a> {
    fn new(raw: &'a RawCase) -> ValueIndex<'a> {
        let count = raw.namelists.values().map(NamelistValues::len).sum();
        let mut entries = Vec::with_capacity(count);
        // Keys order as the names do: the maps' order is the index's.
        for (nl, values) in &raw.namelists {
            let Some(nl) = schema::key(nl) else { continue };
            let keyed = values
                .iter()
                .filter_map(|(var, v)| Some(((nl, schema::key(var)?), v)));
            entries.extend(keyed);
        }
        ValueIndex { entries }
    }

    /// The entries of namelist `nl`.
    fn namelist(&self, nl: &str) -> &[((u64, u64), &'a Value)] {
        let Some(k) = schema::key(nl) else {
            return &[];
        };
        let start = self.entries.partition_point(|((n, _), _)| *n < k);
        let len = self.entries[start..].partition_point(|((n, _), _)| *n == k);
        &self.entries[start..start + len]
    }

    fn get(&self, nl: &str, var: &str) -> Option<&'a Value> {
        lookup(self.namelist(nl), var)
    }
}

/// The value of variable `var` among the entries of one namelist.
fn lookup<'a>(entries: &[((u64, u64), &'a Value)], var: &str) -> Option<&'a Value> {
    let k = schema::key(var)?;
    let i = entries.binary_search_by_key(&k, |((_, v), _)| *v).ok()?;
    Some(entries[i].1)
}

/// Accessor over one namelist's values that converts to SI.
struct Nl<'a> {
    /// The namelist's schema (looked up once, not for every variable read).
    table: Option<&'static schema::Table>,
    values: Option<&'a NamelistValues>,
    /// The namelist's entries in the case's [`ValueIndex`].
    by_key: &'a [((u64, u64), &'a Value)],
    dim: Dim,
    /// SYNTHS SCALE, applied to the variables the schema marks as scaled geometry.
    scale: f64,
}

impl<'a> Nl<'a> {
    fn new(
        table: Option<&'static schema::Table>,
        values: Option<&'a NamelistValues>,
        by_key: &'a [((u64, u64), &'a Value)],
        dim: Dim,
        scale: f64,
    ) -> Nl<'a> {
        Nl {
            table,
            values,
            by_key,
            dim,
            scale,
        }
    }

    fn spec(&self, var: &str) -> Option<&'static schema::VarSpec> {
        self.table.and_then(|s| s.var(var))
    }

    /// How `var` converts to SI: its dimension and SCALE factor; none for a variable the schema
    /// does not know (kept as given).
    fn conversion(&self, var: &str) -> Option<(Dimension, f64)> {
        let spec = self.spec(var)?;
        let scale = match spec.dimension {
            Dimension::Length if spec.scaled => self.scale,
            Dimension::Area if spec.scaled => self.scale * self.scale,
            _ => 1.0,
        };
        Some((spec.dimension, scale))
    }

    fn convert(&self, conversion: Option<(Dimension, f64)>, x: f64) -> f64 {
        match conversion {
            Some((dimension, scale)) => units::to_si(x, self.dim, dimension) * scale,
            None => x,
        }
    }

    fn to_si(&self, var: &str, x: f64) -> f64 {
        self.convert(self.conversion(var), x)
    }

    fn raw(&self, var: &str) -> Option<&'a Value> {
        lookup(self.by_key, var)
    }

    /// Scalar in SI.
    fn real(&self, var: &str) -> Option<f64> {
        let v = self.raw(var)?.scalar()?;
        Some(self.to_si(var, v))
    }

    /// Leading assigned elements in SI.
    fn array(&self, var: &str) -> Vec<f64> {
        self.raw(var)
            .and_then(Value::numbers)
            .map(|v| {
                let conversion = self.conversion(var);
                v.iter()
                    .map_while(|x| *x)
                    .map(|x| self.convert(conversion, x))
                    .collect()
            })
            .unwrap_or_default()
    }

    /// Array truncated to the count its count variable gives (when given).
    fn counted(&self, var: &str, count: Option<usize>) -> Vec<f64> {
        let mut v = self.array(var);
        if let Some(n) = count {
            v.truncate(n);
        }
        v
    }

    fn count(&self, var: &str) -> Option<usize> {
        self.raw(var)?
            .scalar()
            .filter(|c| *c >= 0.0)
            .map(|c| (c + 0.5) as usize)
    }

    fn logical(&self, var: &str) -> Option<bool> {
        self.raw(var)?.logical()
    }
}

/// How the Mach and altitude lists combine into flight conditions (FLTCON LOOP).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Default)]
#[serde(rename_all = "snake_case")]
pub enum Loop {
    /// LOOP=1: Mach and altitude vary together, pairwise.
    #[default]
    Together,
    /// LOOP=2: altitude fixed in the outer loop, Mach varied in the inner.
    AltitudeOuter,
    /// LOOP=3: Mach fixed in the outer loop, altitude varied in the inner.
    MachOuter,
}

/// $FLTCON in SI (angles in degrees). The speeds (`mach`, `velocity`, `reynolds_per_length`)
/// are indexed together, and so are the altitudes (`altitude`, `pressure`, `temperature`);
/// `loop_mode` pairs them into flight conditions. After setting or changing it, call
/// [`Case::prepare`], which derives [`Case::conditions`] from it.
#[derive(Debug, Clone, PartialEq, Serialize, Default)]
pub struct FlightInput {
    /// MACH: free-stream Mach numbers (NMACH is their count).
    pub mach: Vec<f64>,
    /// VINF: free-stream velocity, m/s. Used where no Mach number is given (Mach = V/a): a
    /// given Mach number wins.
    pub velocity: Vec<f64>,
    /// RNNUB: Reynolds number per metre; where not given, computed from the condition's
    /// pressure, temperature and Mach number.
    pub reynolds_per_length: Vec<f64>,
    /// ALT: geometric altitude, m; the 1962 US Standard Atmosphere gives pressure and
    /// temperature there. With neither ALT nor PINF and TINF: sea level, where needed.
    pub altitude: Vec<f64>,
    /// PINF: free-stream static pressure, Pa. Used only with `temperature` (then the altitude
    /// is only reported); alone it is ignored.
    pub pressure: Vec<f64>,
    /// TINF: free-stream static temperature, K. Used only with `pressure`.
    pub temperature: Vec<f64>,
    /// ALSCHD (or ALPHA): angles of attack, deg, in increasing order ([`Case::prepare`] puts
    /// them in order).
    pub alpha_deg: Vec<f64>,
    /// LOOP: how the speeds and the altitudes combine (see [`Loop`]).
    pub loop_mode: Loop,
    /// WT: weight, N. No method uses it; the JSBSim export takes it for the aircraft's weight.
    pub weight: Option<f64>,
    /// GAMMA: flight-path angle, deg. Kept and written back; no method uses it.
    pub gamma_deg: Option<f64>,
    /// TR: transition strips present (TR > 0 in a deck); read by the wing-body's drag due to
    /// lift of a straight wing (the original's regression).
    pub transition_strips: bool,
    /// STMACH: the Mach number up to which the subsonic methods apply, clamped to 0.6..0.99;
    /// `None`: 0.6.
    pub stmach: Option<f64>,
    /// TSMACH: the Mach number from which the original's supersonic methods apply (not
    /// implemented here); read only to tell whether a Mach number of the case lies between
    /// STMACH and TSMACH, where the wing at Mach 0 (the downwash's scale) takes CLAMO for the
    /// section slope. Clamped to 1.01..1.4; `None`: 1.4.
    pub tsmach: Option<f64>,
    /// HYPERS: kept and written back; the hypersonic methods are not implemented.
    pub hypersonic: bool,
    /// NALT is given (LOOP=1 then checks it against NMACH). [`Case::prepare`] sets it when
    /// `altitude` is not empty.
    pub nalt_given: bool,
}

/// The angles of attack of a schedule that is not in increasing order, put in order, and why.
#[derive(Debug, Clone, PartialEq)]
pub struct OrderedAngles {
    /// The finite angles in increasing order, each once.
    pub angles: Vec<f64>,
    /// What was wrong and what is computed instead (a warning for the user).
    pub reason: String,
}

impl FlightInput {
    /// None when the angles of attack increase strictly (as the methods need: every curve is
    /// read against them, and the original prints wrong numbers for any other schedule);
    /// otherwise the angles to compute at, in increasing order and each once, and why.
    pub fn angles_in_order(&self) -> Option<OrderedAngles> {
        let alpha = &self.alpha_deg;
        let increasing =
            alpha.iter().all(|a| a.is_finite()) && alpha.windows(2).all(|w| w[0] < w[1]);
        if increasing {
            return None;
        }
        let mut angles: Vec<f64> = alpha.iter().copied().filter(|a| a.is_finite()).collect();
        angles.sort_by(f64::total_cmp);
        angles.dedup();
        let list = |v: &[f64]| {
            v.iter()
                .map(|a| format!("{a}"))
                .collect::<Vec<_>>()
                .join(", ")
        };
        Some(OrderedAngles {
            reason: format!(
                "the angles of attack (ALSCHD: {}) do not increase from each to the next: computed at {} (every curve is read against increasing angles; the original prints wrong numbers for this schedule)",
                list(alpha),
                list(&angles)
            ),
            angles,
        })
    }
}

/// $OPTINS: reference dimensions and roughness, SI. A case with $LARWB takes its SREF, L and
/// XCG in place of `area`, `chord` and the moment reference centre's x.
#[derive(Debug, Clone, PartialEq, Serialize, Default)]
pub struct Reference {
    /// SREF: reference area, m²; `None`: the wing's theoretical area (both halves).
    pub area: Option<f64>,
    /// CBARR: longitudinal reference length, m; `None`: the wing's theoretical mean
    /// aerodynamic chord.
    pub chord: Option<f64>,
    /// BLREF: lateral reference length, m; `None`: the wing's span, 2·SSPN.
    pub span: Option<f64>,
    /// ROUGFC: surface roughness height, m (a deck gives it in inches or centimetres);
    /// `None`, or below 1E-10 in the deck's unit: 1.6E-4 in.
    pub roughness: Option<f64>,
}

/// $SYNTHS: positions of the components and the moment reference centre, SI; angles in degrees.
/// The default has every position unset and the vertical tail up, as a deck without them.
///
/// Positions are in the deck's frame, the one of [`Body::x`] (usually from the body's nose):
/// x positive aft, z positive up. A position not given is 0. A surface's x is that of its
/// theoretical apex, the leading edge of its root chord on the centre line; its z that of its
/// root chord.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Synthesis {
    /// XCG: x of the moment reference centre, m.
    pub xcg: Option<f64>,
    /// ZCG: z of the moment reference centre, m (positive up).
    pub zcg: Option<f64>,
    /// XW: x of the wing's theoretical apex, m.
    pub xw: Option<f64>,
    /// ZW: z of the wing's root chord, m (positive up).
    pub zw: Option<f64>,
    /// ALIW: wing incidence to the body axis, deg, leading edge up positive (the wing sees
    /// α + ALIW).
    pub aliw_deg: Option<f64>,
    /// XH: x of the horizontal tail's theoretical apex, m (at zero incidence when `hinax` is
    /// given).
    pub xh: Option<f64>,
    /// ZH: z of the horizontal tail's root chord, m (at zero incidence when `hinax` is given).
    pub zh: Option<f64>,
    /// ALIH: horizontal tail incidence to the body axis, deg, leading edge up positive.
    pub alih_deg: Option<f64>,
    /// XV: x of the vertical tail's theoretical apex, m.
    pub xv: Option<f64>,
    /// ZV: z of the vertical tail's root chord, m.
    pub zv: Option<f64>,
    /// XVF: x of the ventral fin's theoretical apex, m.
    pub xvf: Option<f64>,
    /// ZVF: z of the ventral fin's root chord, m.
    pub zvf: Option<f64>,
    /// YV: lateral position of the vertical tail, m. Kept and written back; no method uses it.
    pub yv: Option<f64>,
    /// YF: lateral position of the ventral fin, m. Kept and written back; no method uses it.
    pub yf: Option<f64>,
    /// PHIV: dihedral of twin vertical panels, deg. When given, the vertical tail's sideslip
    /// derivatives are multiplied by 2 cos² PHIV (two panels).
    pub phiv_deg: Option<f64>,
    /// PHIF: as `phiv_deg`, for the ventral fin.
    pub phif_deg: Option<f64>,
    /// HINAX: x of the all-moving horizontal tail's hinge axis, m. When given, XH and ZH are
    /// rotated by ALIH about it.
    pub hinax: Option<f64>,
    /// SCALE as the deck gives it. The factor applied is [`Case::scale`]: changing this
    /// field changes nothing computed, and [`Case::to_raw`] writes [`Case::scale`] in its
    /// place.
    pub scale: Option<f64>,
    /// VERTUP: the vertical tail stands above its root chord (default true); false hangs it
    /// below. The ventral fin is taken to hang below when this is true.
    pub vertup: bool,
}

impl Default for Synthesis {
    fn default() -> Self {
        Synthesis {
            xcg: None,
            zcg: None,
            xw: None,
            zw: None,
            aliw_deg: None,
            xh: None,
            zh: None,
            alih_deg: None,
            xv: None,
            zv: None,
            xvf: None,
            zvf: None,
            yv: None,
            yf: None,
            phiv_deg: None,
            phif_deg: None,
            hinax: None,
            scale: None,
            vertup: true,
        }
    }
}

/// $BODY: stations and their areas, perimeters, radii and contours, SI. The cross-sections
/// are given by R alone, by S alone, or by R, S and P together (the rest is completed from
/// them: [`crate::geometry::body()`]); the arrays run over the stations of `x`.
#[derive(Debug, Clone, PartialEq, Serialize, Default)]
pub struct Body {
    /// X: stations, m, not decreasing, at least 2; the first is the nose. The positions of
    /// [`Synthesis`] are in this frame.
    pub x: Vec<f64>,
    /// S: cross-section areas, m².
    pub s: Vec<f64>,
    /// P: cross-section perimeters, m.
    pub p: Vec<f64>,
    /// R: radii, m (of an elliptical body, see ELLIP, the area is π R² ELLIP).
    pub r: Vec<f64>,
    /// ZU: z of the upper contour, m (positive up).
    pub zu: Vec<f64>,
    /// ZL: z of the lower contour, m, not above ZU. Given, it selects the cambered-body
    /// method (unless METHOD is 2).
    pub zl: Vec<f64>,
    /// BNOSE: the nose's shape code. Kept and written back; no method here uses it.
    pub bnose: Option<f64>,
    /// BTAIL: the tail's shape code. Given, the body's dynamic derivatives carry a warning
    /// (their method assumes a nose-cylinder body).
    pub btail: Option<f64>,
    /// BLN: nose length, m. When BLN or BLA is given, BLN + BLA is the body length the
    /// dynamic derivatives take (else the length of `x`).
    pub bln: Option<f64>,
    /// BLA: afterbody length, m (see `bln`).
    pub bla: Option<f64>,
    /// DS: nose bluntness diameter, m. Kept and written back; no method here uses it.
    pub ds: Option<f64>,
    /// ITYPE: kept and written back; no method here uses it.
    pub itype: Option<f64>,
    /// METHOD: 1 (or `None`) DATCOM's methods, 2 Jorgensen's (any value above 1.5).
    pub method: Option<f64>,
    /// ELLIP: height over width of elliptical cross-sections; `None` or not positive: 1.
    pub ellip: Option<f64>,
}

/// $WGPLNF, $HTPLNF, $VTPLNF, $VFPLNF: planform, SI; angles in degrees. One trapezoidal panel
/// from the centre line to the tip, or two (inboard to the break, outboard from it) when
/// `sspnop` is positive ([`crate::geometry::planform()`]). A vertical tail or ventral fin is a
/// single panel.
#[derive(Debug, Clone, PartialEq, Serialize, Default)]
pub struct Planform {
    /// CHRDR: theoretical root chord (on the centre line), m; required.
    pub chrdr: Option<f64>,
    /// CHRDBP: chord at the break, m; required with an outboard panel.
    pub chrdbp: Option<f64>,
    /// CHRDTP: tip chord, m; `None`: 0 (a pointed tip).
    pub chrdtp: Option<f64>,
    /// SSPN: theoretical semi-span, root chord to tip, m; required.
    pub sspn: Option<f64>,
    /// SSPNE: exposed semi-span, body side to tip, m; `None`: SSPN (no body).
    pub sspne: Option<f64>,
    /// SSPNOP: outboard panel's semi-span, break to tip, m; `None` or not positive: one panel.
    pub sspnop: Option<f64>,
    /// SSPNDD: semi-span of the outboard dihedral panel (DHDADO), dihedral break to tip, m;
    /// `None`: DHDADI over the whole span.
    pub sspndd: Option<f64>,
    /// SAVSI: inboard panel's sweep at chord station CHSTAT, deg, positive aft; `None`: 0.
    pub savsi_deg: Option<f64>,
    /// SAVSO: outboard panel's sweep at CHSTAT, deg; `None`: 0. Read only with an outboard
    /// panel.
    pub savso_deg: Option<f64>,
    /// CHSTAT: chord station of SAVSI and SAVSO, fraction of the chord from the leading edge
    /// (0 to 1); `None`: 0, the sweeps are the leading edge's.
    pub chstat: Option<f64>,
    /// TWISTA: twist of the tip relative to the root, deg; negative is washout (tip nose
    /// down). `None`: 0.
    pub twista_deg: Option<f64>,
    /// DHDADI: inboard dihedral, deg, tips up positive; `None`: 0.
    pub dhdadi_deg: Option<f64>,
    /// DHDADO: outboard dihedral (outboard of SSPNDD), deg. `None`: DHDADI for the sideslip
    /// and rate derivatives, 0 for the downwash.
    pub dhdado_deg: Option<f64>,
    /// TYPE: 1 straight tapered, 2 double delta, 3 cranked, 4 curved (no method); rounded to
    /// the nearest integer, 5 and above read as 1, below 0.5 refused by the wing methods.
    /// `None`: straight tapered for the wing methods; a vertical tail's or ventral fin's
    /// zero-lift drag takes it as not straight tapered, as the original.
    pub planform_type: Option<f64>,
    /// SWAFP: kept and written back; no method uses it (the original discards it too).
    pub swafp_deg: Option<f64>,
}

/// $TVTPAN: twin vertical panels, SI (lengths and SV scaled by SYNTHS SCALE, as the original).
#[derive(Debug, Clone, PartialEq, Serialize, Default)]
pub struct TwinPanels {
    /// BVP: panel span above the lifting surface.
    pub bvp: Option<f64>,
    /// BV: panel span.
    pub bv: Option<f64>,
    /// BDV: body depth at the panels.
    pub bdv: Option<f64>,
    /// BH: distance between the panels.
    pub bh: Option<f64>,
    /// SV: area of one panel.
    pub sv: Option<f64>,
    /// VPHITE: the curve parameter of figure 5.3.1.1-24b, as given.
    pub vphite: Option<f64>,
    /// VLP: distance from the centre of gravity aft to the panels' centre of pressure.
    pub vlp: Option<f64>,
    /// ZP: height of the panels' centre of pressure above the centre of gravity.
    pub zp: Option<f64>,
}

/// $LARWB: the low-aspect-ratio wing-body (lifting body), SI, angles in degrees. SREF, L and
/// XCG replace the reference area, length and moment centre, as in the original. Its lengths
/// and areas are not multiplied by SYNTHS SCALE (as the original's unit conversion).
#[derive(Debug, Clone, PartialEq, Serialize, Default)]
pub struct LowAspectRatioWingBody {
    /// SREF: reference area, m² (in place of $OPTINS SREF).
    pub sref: Option<f64>,
    /// Body length L, the reference length, m.
    pub length: Option<f64>,
    /// XCG: x of the moment reference centre, m (in place of $SYNTHS XCG).
    pub xcg: Option<f64>,
    /// ZB: height of the apex above the base's centre (sets the zero-lift angle).
    pub zb: Option<f64>,
    /// DELTEP: leading-edge angle of a sharp-edged planform, degrees (sharp leading edge when given).
    pub deltep_deg: Option<f64>,
    /// SFRONT: frontal (projected) area.
    pub sfront: Option<f64>,
    /// AR: aspect ratio of the planform.
    pub aspect_ratio: Option<f64>,
    /// R3LEOB: leading-edge radius over span, round leading edges.
    pub r3leob: Option<f64>,
    /// DELTAL: leading-edge sweep of a round-edged planform, degrees.
    pub deltal_deg: Option<f64>,
    /// SWET: wetted area.
    pub swet: Option<f64>,
    /// PERBAS: perimeter of the base.
    pub perbas: Option<f64>,
    /// SBASE: base area.
    pub sbase: Option<f64>,
    /// HB: height of the base.
    pub hb: Option<f64>,
    /// BB: span of the base.
    pub bb: Option<f64>,
    /// BLF: the base lies aft of non-lifting surfaces (body-like base).
    pub blf: Option<bool>,
    /// THETAD: semi-apex angle of the planform, degrees.
    pub thetad_deg: Option<f64>,
    /// ROUNDN: the nose is rounded (blunted).
    pub roundn: Option<bool>,
    /// SBS: body side area.
    pub sbs: Option<f64>,
    /// SBSLB: side area ahead of 0.2 of the length.
    pub sbslb: Option<f64>,
    /// XCENSB: centroid of the side area, from the apex.
    pub xcensb: Option<f64>,
    /// XCENW: centroid of the planform area, from the apex.
    pub xcenw: Option<f64>,
}

/// $WGSCHR and its kin: section characteristics the user gives (fractions of chord), held in
/// [`Case::sections`] by the surface's name. Every value is as the deck gives it (none has a
/// unit to convert).
#[derive(Debug, Clone, PartialEq, Serialize, Default)]
pub struct SectionInput {
    /// Every scalar given, by variable name (TOVC, XOVC, CLI, ..., and TYPEIN and NPTS, which
    /// a section given by its coordinates needs here).
    pub scalars: BTreeMap<String, f64>,
    /// XCORD: the coordinates' stations, fractions of the chord increasing from 0 to 1.
    pub xcord: Vec<f64>,
    /// YUPPER: upper surface ordinates at `xcord` (TYPEIN = 1), fractions of the chord.
    pub yupper: Vec<f64>,
    /// YLOWER: lower surface ordinates at `xcord` (TYPEIN = 1), fractions of the chord.
    pub ylower: Vec<f64>,
    /// MEAN: mean-line ordinates at `xcord` (TYPEIN = 2), fractions of the chord.
    pub mean: Vec<f64>,
    /// THICK: thickness (not half thickness) at `xcord` (TYPEIN = 2), fractions of the chord.
    pub thick: Vec<f64>,
    /// The other arrays by variable name: CLALPA, CLMAX and XAC (one value per Mach number of
    /// $FLTCON) and SLOPE.
    pub per_mach: BTreeMap<String, Vec<f64>>,
    /// CAMBER: the section is cambered.
    pub camber: Option<bool>,
}

/// Which Reynolds number the section methods (lift-curve slope, maximum lift) take when the
/// deck gives no RNNUB.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum SectionReynolds {
    /// The flight condition's Reynolds number on the exposed mean aerodynamic chord (the
    /// method's intent; what low-Reynolds-number aircraft need).
    #[default]
    Flight,
    /// As the original program: the given RNNUB when there is one, else its fixed values
    /// (1E6 for the lift-curve slope, 9E6 for the maximum lift), which it takes because it
    /// computes the flight Reynolds number only later. For reproducing old listings.
    Original,
}

/// How a NACA 5-digit designation is read.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum FiveDigitReading {
    /// NACA's definition: the first digit is the design lift coefficient in 0.15 steps, the
    /// mean line's camber follows from it (2.0 % nominal, 1.84 % exactly, for a 230 line;
    /// docs/sections.md).
    #[default]
    Naca,
    /// As the original program: the first digit is the maximum camber in percent, the standard
    /// line whatever the third digit (COORD5, CORD5M). For reproducing old listings.
    Original,
}

/// How a NACA 6A designation is read.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum SixAReading {
    /// NACA's definition (Report 903): thickness straight aft of 0.8 chord, the a = 0.8
    /// (modified) mean line unless `A=` gives another a (docs/sections.md).
    #[default]
    Naca,
    /// As the original program: the thickness left curved (only the printed surfaces are
    /// straightened), the plain a = 0.8 line with `A=0.8` and the a = 1 line without `A=`
    /// (COORD6). For reproducing old listings.
    Original,
}

/// One case of a deck, typed and in SI.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Case {
    /// 1-based position of the case in its deck (1 for [`Case::new`]).
    pub number: usize,
    /// Line of the deck where the case's first card is (0 for a case built in code).
    pub first_line: usize,
    /// The CASEID card's text.
    pub caseid: Option<String>,
    /// The units of the case's deck form and reports: [`Case::to_raw`] writes the values in
    /// them with a DIM card for them, and the reports give lengths, areas, pressures ... in
    /// them. The values of `other` are in them. This, not `cards.dim` (the DIM card as read),
    /// is the case's unit system.
    pub dim: Dim,
    /// SYNTHS SCALE (default 1): the geometry of the typed case is already the deck's times
    /// this factor (lengths, and areas by its square), so it scales no computation. It turns
    /// the reported reference dimensions and PART pages, and the deck [`Case::to_raw`] writes,
    /// back into the deck's dimensions. One that is not a positive number, or so small that
    /// the reference dimensions divided by it overflow, is taken as 1 by `run_case`, with a
    /// warning.
    pub scale: f64,
    /// The unit of the reported derivatives (DERIV card: per degree unless DERIV RAD); the
    /// results themselves are per radian. This, not `cards.deriv` (the DERIV card as read),
    /// is the case's unit: [`Case::to_raw`] writes it in the cards.
    pub deriv: DerivUnit,
    /// Reynolds number rule of the section methods (see [`SectionReynolds`]).
    pub section_reynolds: SectionReynolds,
    /// How NACA 5-digit designations are read (see [`FiveDigitReading`]).
    pub five_digit: FiveDigitReading,
    /// Which station gives a section's maximum thickness and camber (see
    /// [`MaximumReading`]).
    pub section_maximum: MaximumReading,
    /// How NACA 6A designations are read (see [`SixAReading`]).
    pub six_a: SixAReading,
    /// How the wing's zero-lift angle is read (see [`ZeroLiftReading`]).
    pub zero_lift: ZeroLiftReading,
    /// How a forward-swept wing's aerodynamic centre is read (see [`ForwardSweepReading`]).
    pub forward_sweep: ForwardSweepReading,
    /// Which lift-curve slope a low-aspect-ratio straight horizontal tail takes into its
    /// combinations (see [`TailSlopeReading`]).
    pub tail_slope: TailSlopeReading,
    /// The outboard panel's unset section values (see [`OutboardSectionReading`]).
    pub outboard_section: OutboardSectionReading,
    /// A Jorgensen body's drag due to lift in the wing-body (see [`JorgensenDragReading`]).
    pub jorgensen_drag: JorgensenDragReading,
    /// The control cards as read (DAMP, BUILD, PART, ...). Their `dim` and `deriv` record the
    /// DIM and DERIV cards; the case's units are [`Case::dim`] and [`Case::deriv`].
    pub cards: Cards,
    /// $FLTCON. After setting or changing it, call [`Case::prepare`] to derive `conditions`.
    pub flight: Option<FlightInput>,
    /// $OPTINS: reference dimensions and roughness.
    pub reference: Reference,
    /// $SYNTHS: positions of the components and the moment reference centre.
    pub synthesis: Option<Synthesis>,
    /// $BODY.
    pub body: Option<Body>,
    /// $WGPLNF: the wing's planform.
    pub wing: Option<Planform>,
    /// $HTPLNF: the horizontal tail's planform.
    pub horizontal_tail: Option<Planform>,
    /// $VTPLNF: the vertical tail's planform (one panel).
    pub vertical_tail: Option<Planform>,
    /// $VFPLNF: the ventral fin's planform (one panel).
    pub ventral_fin: Option<Planform>,
    /// $TVTPAN.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub twin_panels: Option<TwinPanels>,
    /// $WGSCHR, $HTSCHR, $VTSCHR, $VFSCHR by the surface's name (`WING`, `HORIZONTAL TAIL`,
    /// `VERTICAL TAIL`, `VENTRAL FIN`).
    pub sections: BTreeMap<String, SectionInput>,
    /// $LARWB.
    pub larwb: Option<LowAspectRatioWingBody>,
    /// Flight conditions of the case, derived from `flight` when the case is typed or
    /// [`Case::prepare`]d (a run of a case whose `flight` changed since computes at what
    /// `flight` gives, with a warning).
    pub conditions: Vec<crate::conditions::FlightCondition>,
    /// What was assumed or could not be computed for the flight conditions.
    pub condition_warnings: Vec<String>,
    /// NACA cards. A surface's section is its last card, unless its section namelist gives
    /// TYPEIN (the coordinates of `sections`).
    pub airfoils: Vec<AirfoilCard>,
    /// Namelists kept as read (deck units): flaps, power, ground effect, experimental data ...
    pub other: BTreeMap<String, NamelistValues>,
    /// The case ends with SAVE: in a deck its data carry into the next case.
    pub save: bool,
}

impl Default for Case {
    /// [`Case::new`].
    fn default() -> Self {
        Case::new()
    }
}

/// A deck: its typed cases and every diagnostic (reader's and physical checks').
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Deck {
    pub file: String,
    pub cases: Vec<Case>,
    pub diagnostics: Vec<Diagnostic>,
}

impl crate::error::Diagnosed for Deck {
    fn diagnostics(&self) -> &[Diagnostic] {
        &self.diagnostics
    }
}

impl Deck {
    /// The same deck with `set` applied to every case.
    fn each_case(mut self, set: impl Fn(&mut Case)) -> Deck {
        self.cases.iter_mut().for_each(set);
        self
    }

    /// The same deck with every case using `rule` for the section Reynolds number.
    pub fn with_section_reynolds(self, rule: SectionReynolds) -> Deck {
        self.each_case(|c| c.section_reynolds = rule)
    }

    /// The same deck with every case reading NACA 5-digit designations by `reading`.
    pub fn with_five_digit_reading(self, reading: FiveDigitReading) -> Deck {
        self.each_case(|c| c.five_digit = reading)
    }

    /// The same deck with every case finding a section's maximum thickness and camber by
    /// `reading`.
    pub fn with_section_maximum(self, reading: MaximumReading) -> Deck {
        self.each_case(|c| c.section_maximum = reading)
    }

    /// The same deck with every case reading NACA 6A designations by `reading`.
    pub fn with_six_a_reading(self, reading: SixAReading) -> Deck {
        self.each_case(|c| c.six_a = reading)
    }

    /// The same deck with every case reading the wing's zero-lift angle by `reading`.
    pub fn with_zero_lift_reading(self, reading: ZeroLiftReading) -> Deck {
        self.each_case(|c| c.zero_lift = reading)
    }

    /// The same deck with every case reading a forward-swept wing's aerodynamic centre by
    /// `reading`.
    pub fn with_forward_sweep_reading(self, reading: ForwardSweepReading) -> Deck {
        self.each_case(|c| c.forward_sweep = reading)
    }

    /// The same deck with every case's low-aspect-ratio straight horizontal tail taking its
    /// lift-curve slope by `reading`.
    pub fn with_tail_slope_reading(self, reading: TailSlopeReading) -> Deck {
        self.each_case(|c| c.tail_slope = reading)
    }

    /// The same deck with every case's outboard panel taking the section values the deck
    /// leaves unset by `reading`.
    pub fn with_outboard_section_reading(self, reading: OutboardSectionReading) -> Deck {
        self.each_case(|c| c.outboard_section = reading)
    }

    /// The same deck with every case's wing-body taking a Jorgensen body's drag due to lift by
    /// `reading`.
    pub fn with_jorgensen_drag_reading(self, reading: JorgensenDragReading) -> Deck {
        self.each_case(|c| c.jorgensen_drag = reading)
    }

    /// The same deck with the original program's rules (its section Reynolds number, its
    /// 5-digit and 6A readings, its search for a section's maximum thickness and camber, its
    /// reading of the wing's zero-lift angle and of a forward-swept wing's aerodynamic
    /// centre, its low-aspect-ratio horizontal tail's slope, its outboard section values, its
    /// wing-body drag with a Jorgensen body), to reproduce its listings.
    pub fn with_original_rules(self) -> Deck {
        self.with_section_reynolds(SectionReynolds::Original)
            .with_five_digit_reading(FiveDigitReading::Original)
            .with_six_a_reading(SixAReading::Original)
            .with_section_maximum(MaximumReading::LastRise)
            .with_zero_lift_reading(ZeroLiftReading::Original)
            .with_forward_sweep_reading(ForwardSweepReading::Original)
            .with_tail_slope_reading(TailSlopeReading::Original)
            .with_outboard_section_reading(OutboardSectionReading::Original)
            .with_jorgensen_drag_reading(JorgensenDragReading::Original)
    }

    /// Types every case of a deck as read, adding the physical checks' diagnostics.
    pub fn from_raw(raw: RawDeck) -> Deck {
        let mut diagnostics = raw.diagnostics;
        let cases = raw
            .cases
            .iter()
            .map(|c| {
                let (case, mut d) = Case::from_raw(c, &raw.file);
                diagnostics.append(&mut d);
                case
            })
            .collect();
        crate::deck::sort_diagnostics(&mut diagnostics);
        Deck {
            file: raw.file,
            cases,
            diagnostics,
        }
    }
}

/// The section namelists and their surfaces.
const SECTION_NAMELISTS: [(&str, Surface); 4] = [
    ("WGSCHR", Surface::Wing),
    ("HTSCHR", Surface::HorizontalTail),
    ("VTSCHR", Surface::VerticalTail),
    ("VFSCHR", Surface::VentralFin),
];

/// Namelists the original reads whose methods are not implemented here, and what a run leaves
/// out because of them.
const NOT_IMPLEMENTED: [(&str, &str); 8] = [
    ("SYMFLP", "the methods of symmetrically deflected high-lift and control devices (DATCOM section 6.1) are not implemented: their increments and pages are not computed; the pages are those of the undeflected configuration"),
    ("ASYFLP", "the methods of asymmetrically deflected controls (DATCOM section 6.2) are not implemented: their rolling and yawing moments are not computed"),
    ("PROPWR", "the propeller power effects are not implemented: the pages are power-off, where the original adds the power increments"),
    ("JETPWR", "the jet power effects are not implemented: the pages are power-off, where the original adds the power increments"),
    ("GRNDEF", "the ground-effect methods are not implemented: the pages are out of ground effect, and the original's ground-effect pages are not computed"),
    ("CONTAB", "the control-tab methods are not implemented: their hinge moments are not computed"),
    ("HYPEFF", "the hypersonic flap methods are not implemented: the flap's increments are not computed"),
    ("TRNJET", "the transverse-jet control methods are not implemented: the jet's increments are not computed"),
];

/// How diagnostics name an airfoil card.
const NACA_CARD: &str = "NACA";

const PLANFORMS: [(&str, &str); 4] = [
    ("WGPLNF", "WGSCHR"),
    ("HTPLNF", "HTSCHR"),
    ("VTPLNF", "VTSCHR"),
    ("VFPLNF", "VFSCHR"),
];

/// Whether namelist `name` has a typed home in [`Case`].
fn typed(name: &str) -> bool {
    matches!(
        name,
        "FLTCON"
            | "OPTINS"
            | "SYNTHS"
            | "BODY"
            | "WGPLNF"
            | "HTPLNF"
            | "VTPLNF"
            | "VFPLNF"
            | "WGSCHR"
            | "HTSCHR"
            | "VTSCHR"
            | "VFSCHR"
            | "TVTPAN"
    )
}

fn flight(n: &Nl) -> FlightInput {
    let nmach = n.count("NMACH");
    let nalt = n.count("NALT");
    let nalpha = n.count("NALPHA");
    let loop_mode = match n
        .raw("LOOP")
        .and_then(Value::scalar)
        .map(|l| (l + 0.5) as i64)
    {
        Some(2) => Loop::AltitudeOuter,
        Some(3) => Loop::MachOuter,
        _ => Loop::Together,
    };
    let mut alpha = n.counted("ALSCHD", nalpha);
    if alpha.is_empty() {
        alpha = n.counted("ALPHA", nalpha);
    }
    FlightInput {
        mach: n.counted("MACH", nmach),
        velocity: n.counted("VINF", nmach),
        reynolds_per_length: n.counted("RNNUB", nmach),
        altitude: n.counted("ALT", nalt),
        pressure: n.counted("PINF", nalt),
        temperature: n.counted("TINF", nalt),
        alpha_deg: alpha,
        loop_mode,
        weight: n.real("WT"),
        gamma_deg: n.real("GAMMA"),
        transition_strips: n.real("TR").is_some_and(|t| t > 0.0),
        stmach: n.real("STMACH"),
        tsmach: n.real("TSMACH"),
        hypersonic: n.logical("HYPERS").unwrap_or(false),
        nalt_given: nalt.is_some_and(|k| k > 0),
    }
}

fn planform(n: &Nl) -> Planform {
    Planform {
        chrdr: n.real("CHRDR"),
        chrdbp: n.real("CHRDBP"),
        chrdtp: n.real("CHRDTP"),
        sspn: n.real("SSPN"),
        sspne: n.real("SSPNE"),
        sspnop: n.real("SSPNOP"),
        sspndd: n.real("SSPNDD"),
        savsi_deg: n.real("SAVSI"),
        savso_deg: n.real("SAVSO"),
        chstat: n.real("CHSTAT"),
        twista_deg: n.real("TWISTA"),
        dhdadi_deg: n.real("DHDADI"),
        dhdado_deg: n.real("DHDADO"),
        planform_type: n.real("TYPE"),
        swafp_deg: n.real("SWAFP"),
    }
}

fn section(n: &Nl) -> SectionInput {
    let npts = n.count("NPTS");
    let mut s = SectionInput {
        xcord: n.counted("XCORD", npts),
        yupper: n.counted("YUPPER", npts),
        ylower: n.counted("YLOWER", npts),
        mean: n.counted("MEAN", npts),
        thick: n.counted("THICK", npts),
        camber: n.logical("CAMBER"),
        ..SectionInput::default()
    };
    if let Some(values) = n.values {
        for (name, v) in values {
            match name.as_str() {
                "XCORD" | "YUPPER" | "YLOWER" | "MEAN" | "THICK" => {}
                "CLALPA" | "CLMAX" | "XAC" | "SLOPE" => {
                    s.per_mach.insert(name.clone(), n.array(name));
                }
                _ => {
                    if let Some(x) = v.scalar() {
                        s.scalars.insert(name.clone(), x);
                    }
                }
            }
        }
    }
    s
}

/// Collects the physical checks of one case. Messages quote the deck's own values and units.
struct Checks<'a> {
    file: &'a str,
    raw: &'a RawCase,
    index: &'a ValueIndex<'a>,
    out: Vec<Diagnostic>,
}

impl<'a> Checks<'a> {
    /// Where a problem of `card` (and `var`) is: the variable's assignment; without a
    /// variable, the namelist's first assignment; else the case's first line.
    fn at(&self, card: &str, var: Option<&str>) -> (usize, usize) {
        match var {
            Some(v) => self.raw.origins.get(card, v),
            None => self.raw.origins.first_in(card, self.raw.first_line),
        }
        .unwrap_or((self.raw.first_line, 0))
    }

    fn problem(
        &mut self,
        severity: Severity,
        card: &str,
        var: Option<&str>,
        problem: DeckProblem,
        hint: Option<&str>,
    ) {
        let at = self.at(card, var);
        self.problem_at(severity, at, card, var, problem, hint);
    }

    /// A problem of `card` found at a place other than the card's (the case's first line when
    /// none is known).
    fn at_place(
        &mut self,
        severity: Severity,
        at: Option<(usize, usize)>,
        card: &str,
        message: String,
        hint: Option<&str>,
    ) {
        let at = at.unwrap_or((self.raw.first_line, 0));
        let problem = DeckProblem::Physical { message };
        self.problem_at(severity, at, card, None, problem, hint);
    }

    fn problem_at(
        &mut self,
        severity: Severity,
        (line, column): (usize, usize),
        card: &str,
        var: Option<&str>,
        problem: DeckProblem,
        hint: Option<&str>,
    ) {
        self.out.push(Diagnostic {
            severity,
            file: self.file.to_string(),
            line,
            column,
            card: Some(card.to_string()),
            variable: var.map(str::to_string),
            problem,
            hint: hint.map(str::to_string),
        });
    }

    /// A problem of a card as a whole (or of the case: no card), at a line.
    fn at_line(
        &mut self,
        severity: Severity,
        line: usize,
        card: Option<&str>,
        message: String,
        hint: Option<&str>,
    ) {
        self.out.push(Diagnostic {
            severity,
            file: self.file.to_string(),
            line,
            column: 0,
            card: card.map(str::to_string),
            variable: None,
            problem: DeckProblem::Physical { message },
            hint: hint.map(str::to_string),
        });
    }

    fn push(
        &mut self,
        severity: Severity,
        card: &str,
        var: Option<&str>,
        message: String,
        hint: Option<&str>,
    ) {
        self.problem(severity, card, var, DeckProblem::Physical { message }, hint);
    }

    /// The deck's values of an array (or scalar), as written, with their 1-based indices.
    fn values(&self, card: &str, var: &str) -> impl Iterator<Item = (usize, f64)> + Clone + 'a {
        self.index
            .get(card, var)
            .and_then(Value::numbers)
            .unwrap_or_default()
            .iter()
            .enumerate()
            .filter_map(|(i, x)| x.map(|x| (i + 1, x)))
    }

    /// The variable is a scalar in the schema (named without an index in messages).
    fn is_scalar(card: &str, var: &str) -> bool {
        schema::table(card)
            .and_then(|s| s.var(var))
            .is_some_and(|v| v.len == 1)
    }

    /// How a message names element `i` (1-based) of `var`: `SAVSI` for a scalar, `X(3)`.
    fn element(card: &str, var: &str, i: usize) -> String {
        if Self::is_scalar(card, var) {
            var.to_string()
        } else {
            format!("{var}({i})")
        }
    }

    fn sign(&mut self, card: &str, var: &str, allow_zero: bool) {
        self.sign_of_first(card, var, allow_zero, usize::MAX);
    }

    /// [`Checks::sign`] of the first `count` elements only (an array per Mach number, whose
    /// values beyond the case's Mach numbers are not read).
    fn sign_of_first(&mut self, card: &str, var: &str, allow_zero: bool, count: usize) {
        let bad = self
            .values(card, var)
            .take_while(|&(i, _)| i <= count)
            .find(|(_, x)| if allow_zero { *x < 0.0 } else { *x <= 0.0 });
        if let Some((i, found)) = bad {
            let problem = DeckProblem::NotPositive {
                variable: var.to_string(),
                index: (!Self::is_scalar(card, var)).then_some(i),
                found,
                allow_zero,
            };
            self.problem(Severity::Error, card, Some(var), problem, None);
        }
    }

    fn positive(&mut self, card: &str, var: &str) {
        self.sign(card, var, false);
    }

    /// An angle, deg, that the methods divide by the cosine of (a sweep, a dihedral, an
    /// incidence): at ±90° and beyond they give no meaningful number. (Not the angles of
    /// attack: body-alone decks run to 90° and beyond, and the body methods take them.)
    fn acute(&mut self, card: &str, var: &str, what: &str) {
        if let Some((i, found)) = self
            .values(card, var)
            .find(|(_, x)| x.abs() >= RIGHT_ANGLE_DEG)
        {
            let name = Self::element(card, var, i);
            self.push(
                Severity::Error,
                card,
                Some(var),
                format!(
                    "{name} = {found} deg: {what} must lie between -{RIGHT_ANGLE_DEG} and {RIGHT_ANGLE_DEG} deg"
                ),
                None,
            );
        }
    }

    fn non_negative(&mut self, card: &str, var: &str) {
        self.sign(card, var, true);
    }

    /// The angles of attack ([`angles_of_attack_problem`]).
    fn angles_of_attack(&mut self, lifting_surfaces: bool) {
        let (card, var) = ("FLTCON", "ALSCHD");
        let angles = self.values(card, var).map(|(i, a)| (Some(i), a));
        if let Some((severity, message)) = angles_of_attack_problem(angles, lifting_surfaces) {
            self.push(severity, card, Some(var), message, None);
        }
    }

    /// Values outside `[min, max]` given in SI, reported in the deck's units.
    fn range(&mut self, card: &str, var: &str, (min, max): (f64, f64), dim: Dim) {
        let d = schema::table(card)
            .and_then(|s| s.var(var))
            .map_or(Dimension::None, |v| v.dimension);
        let lo = units::from_si(min, dim, d);
        let hi = units::from_si(max, dim, d);
        if let Some((i, found)) = self.values(card, var).find(|(_, x)| !(lo..=hi).contains(x)) {
            let problem = DeckProblem::OutOfRange {
                variable: Self::element(card, var, i),
                found,
                min: lo,
                max: hi,
                unit: units::unit_label(dim, d).to_string(),
            };
            self.problem(Severity::Error, card, Some(var), problem, None);
        }
    }
}

/// What is wrong with a schedule of angles of attack, naming every angle concerned (by its
/// 1-based index in the deck when `indices` are given, `ALSCHD(3) = 95`, else by its value,
/// `alpha = 95`): beyond ±180° none is meant (an error); from ±90° the lifting-surface
/// methods (which divide by cos α) give no meaningful number, although the body methods do
/// (body-alone decks run to 90° and beyond): a warning when the case has a lifting surface.
pub(crate) fn angles_of_attack_problem(
    angles: impl Iterator<Item = (Option<usize>, f64)> + Clone,
    lifting_surfaces: bool,
) -> Option<(Severity, String)> {
    let right = crate::geometry::planform::RIGHT_ANGLE_DEG;
    if angles.clone().all(|(_, a)| a.abs() < right) {
        return None;
    }
    let list = |beyond: &dyn Fn(f64) -> bool| {
        let mut by_value = false;
        let found: Vec<String> = angles
            .clone()
            .filter(|(_, a)| beyond(*a))
            .map(|(i, a)| match i {
                Some(i) => format!("ALSCHD({i}) = {a}"),
                None => {
                    by_value = true;
                    a.to_string()
                }
            })
            .collect();
        let prefix = if by_value { "alpha = " } else { "" };
        (!found.is_empty()).then(|| format!("{prefix}{}", found.join(", ")))
    };
    if let Some(found) = list(&|a| a.abs() > HALF_TURN_DEG) {
        return Some((
            Severity::Error,
            format!("{found} deg: an angle of attack lies between -{HALF_TURN_DEG} and {HALF_TURN_DEG} deg"),
        ));
    }
    let found = list(&|a| lifting_surfaces && a.abs() >= right)?;
    let next = if found.contains(',') {
        "these"
    } else {
        "this one"
    };
    Some((
        Severity::Warning,
        format!("{found} deg: the wing and tail methods give no meaningful numbers at {right} deg and beyond (only the body's do), nor the slopes CLA and CMA at the angles next to {next} in the schedule"),
    ))
}

/// Altitudes the 1962 US Standard Atmosphere tabulates, m.
const ATMOSPHERE_RANGE_M: (f64, f64) = (-5000.0, 700_000.0);
/// Mach numbers beyond which no DATCOM method (hypersonic ones included) applies.
const MACH_RANGE: (f64, f64) = (0.0, 100.0);
/// The largest angle of attack in magnitude, deg.
const HALF_TURN_DEG: f64 = 180.0;
/// A station or length along the chord as a fraction of it, from the leading to the trailing
/// edge: CHSTAT (the chord station of the sweep angles SAVSI/SAVSO), a section's thickness
/// ratio TOVC and the station XOVC of its greatest thickness.
const CHORD_FRACTION: (f64, f64) = (0.0, 1.0);

impl Case {
    /// A copy of the case with `sections` in place of its section inputs: what a method that
    /// applies the wing methods to another surface, or to the wing under other inputs, runs
    /// on (the other surfaces' inputs are not copied).
    pub(crate) fn with_sections(&self, sections: BTreeMap<String, SectionInput>) -> Case {
        // Every field named, so that a new field is copied here too.
        let Case {
            number,
            first_line,
            caseid,
            dim,
            scale,
            deriv,
            section_reynolds,
            five_digit,
            section_maximum,
            six_a,
            zero_lift,
            forward_sweep,
            tail_slope,
            outboard_section,
            jorgensen_drag,
            cards,
            flight,
            reference,
            synthesis,
            body,
            wing,
            horizontal_tail,
            vertical_tail,
            ventral_fin,
            twin_panels,
            sections: _,
            larwb,
            conditions,
            condition_warnings,
            airfoils,
            other,
            save,
        } = self;
        Case {
            number: *number,
            first_line: *first_line,
            caseid: caseid.clone(),
            dim: *dim,
            scale: *scale,
            deriv: *deriv,
            section_reynolds: *section_reynolds,
            five_digit: *five_digit,
            section_maximum: *section_maximum,
            six_a: *six_a,
            zero_lift: *zero_lift,
            forward_sweep: *forward_sweep,
            tail_slope: *tail_slope,
            outboard_section: *outboard_section,
            jorgensen_drag: *jorgensen_drag,
            cards: cards.clone(),
            flight: flight.clone(),
            reference: reference.clone(),
            synthesis: synthesis.clone(),
            body: body.clone(),
            wing: wing.clone(),
            horizontal_tail: horizontal_tail.clone(),
            vertical_tail: vertical_tail.clone(),
            ventral_fin: ventral_fin.clone(),
            twin_panels: twin_panels.clone(),
            sections,
            larwb: larwb.clone(),
            conditions: conditions.clone(),
            condition_warnings: condition_warnings.clone(),
            airfoils: airfoils.clone(),
            other: other.clone(),
            save: *save,
        }
    }

    /// Types one case as read; returns it with the diagnostics of its physical checks.
    pub fn from_raw(raw: &RawCase, file: &str) -> (Case, Vec<Diagnostic>) {
        let dim = raw.cards.dim.unwrap_or_default();
        let scale = raw
            .scalar("SYNTHS", "SCALE")
            .filter(|s| *s > 0.0)
            .unwrap_or(1.0);
        let index = ValueIndex::new(raw);
        let nl = |name: &'static str| {
            let values = raw.namelists.get(name);
            Nl::new(
                schema::table(name),
                values,
                index.namelist(name),
                dim,
                scale,
            )
        };
        let has = |name: &str| raw.namelists.contains_key(name);
        let fl = nl("FLTCON");
        let op = nl("OPTINS");
        let sy = nl("SYNTHS");
        let bo = nl("BODY");
        let mut planforms: Vec<Option<Planform>> = Vec::new();
        let mut sections = BTreeMap::new();
        for ((pl, sc), surface) in PLANFORMS.iter().zip([
            Surface::Wing,
            Surface::HorizontalTail,
            Surface::VerticalTail,
            Surface::VentralFin,
        ]) {
            planforms.push(has(pl).then(|| planform(&nl(pl))));
            if has(sc) {
                sections.insert(surface.name().to_string(), section(&nl(sc)));
            }
        }
        let case = Case {
            number: raw.number,
            first_line: raw.first_line,
            caseid: raw.caseid.clone(),
            dim,
            scale,
            deriv: raw.cards.deriv.unwrap_or_default(),
            section_reynolds: SectionReynolds::default(),
            section_maximum: MaximumReading::default(),
            six_a: SixAReading::default(),
            zero_lift: ZeroLiftReading::default(),
            forward_sweep: ForwardSweepReading::default(),
            tail_slope: TailSlopeReading::default(),
            outboard_section: OutboardSectionReading::default(),
            jorgensen_drag: JorgensenDragReading::default(),
            five_digit: FiveDigitReading::default(),
            cards: raw.cards.clone(),
            flight: has("FLTCON").then(|| flight(&fl)),
            reference: Reference {
                area: op.real("SREF"),
                chord: op.real("CBARR"),
                span: op.real("BLREF"),
                roughness: op.real("ROUGFC"),
            },
            synthesis: has("SYNTHS").then(|| Synthesis {
                xcg: sy.real("XCG"),
                zcg: sy.real("ZCG"),
                xw: sy.real("XW"),
                zw: sy.real("ZW"),
                aliw_deg: sy.real("ALIW"),
                xh: sy.real("XH"),
                zh: sy.real("ZH"),
                alih_deg: sy.real("ALIH"),
                xv: sy.real("XV"),
                zv: sy.real("ZV"),
                xvf: sy.real("XVF"),
                zvf: sy.real("ZVF"),
                yv: sy.real("YV"),
                yf: sy.real("YF"),
                phiv_deg: sy.real("PHIV"),
                phif_deg: sy.real("PHIF"),
                hinax: sy.real("HINAX"),
                scale: sy.real("SCALE"),
                vertup: sy.logical("VERTUP").unwrap_or(true),
            }),
            body: has("BODY").then(|| {
                let nx = bo.count("NX");
                Body {
                    x: bo.counted("X", nx),
                    s: bo.counted("S", nx),
                    p: bo.counted("P", nx),
                    r: bo.counted("R", nx),
                    zu: bo.counted("ZU", nx),
                    zl: bo.counted("ZL", nx),
                    bnose: bo.real("BNOSE"),
                    btail: bo.real("BTAIL"),
                    bln: bo.real("BLN"),
                    bla: bo.real("BLA"),
                    ds: bo.real("DS"),
                    itype: bo.real("ITYPE"),
                    method: bo.real("METHOD"),
                    ellip: bo.real("ELLIP"),
                }
            }),
            wing: planforms[0].take(),
            horizontal_tail: planforms[1].take(),
            vertical_tail: planforms[2].take(),
            ventral_fin: planforms[3].take(),
            twin_panels: has("TVTPAN").then(|| {
                let t = nl("TVTPAN");
                TwinPanels {
                    bvp: t.real("BVP"),
                    bv: t.real("BV"),
                    bdv: t.real("BDV"),
                    bh: t.real("BH"),
                    sv: t.real("SV"),
                    vphite: t.real("VPHITE"),
                    vlp: t.real("VLP"),
                    zp: t.real("ZP"),
                }
            }),
            sections,
            larwb: has("LARWB").then(|| {
                let l = nl("LARWB");
                LowAspectRatioWingBody {
                    sref: l.real("SREF"),
                    length: l.real("L"),
                    xcg: l.real("XCG"),
                    zb: l.real("ZB"),
                    deltep_deg: l.real("DELTEP"),
                    sfront: l.real("SFRONT"),
                    aspect_ratio: l.real("AR"),
                    r3leob: l.real("R3LEOB"),
                    deltal_deg: l.real("DELTAL"),
                    swet: l.real("SWET"),
                    perbas: l.real("PERBAS"),
                    sbase: l.real("SBASE"),
                    hb: l.real("HB"),
                    bb: l.real("BB"),
                    blf: l.logical("BLF"),
                    thetad_deg: l.real("THETAD"),
                    roundn: l.logical("ROUNDN"),
                    sbs: l.real("SBS"),
                    sbslb: l.real("SBSLB"),
                    xcensb: l.real("XCENSB"),
                    xcenw: l.real("XCENW"),
                }
            }),
            conditions: Vec::new(),
            condition_warnings: Vec::new(),
            airfoils: raw.airfoils.clone(),
            other: raw
                .namelists
                .iter()
                .filter(|(k, _)| !typed(k))
                .map(|(k, v)| (k.clone(), v.clone()))
                .collect(),
            save: raw.save,
        };
        let mut checks = Checks {
            file,
            raw,
            index: &index,
            out: Vec::new(),
        };
        case.check(&mut checks);
        let mut case = case;
        // Angles out of order were reported by the checks: the case computes them in order.
        let _reported = case.derive_conditions();
        for w in &case.condition_warnings {
            checks.push(Severity::Warning, "FLTCON", None, w.clone(), None);
        }
        (case, checks.out)
    }

    /// A case with no component, no flight condition and nothing computed, to be filled in
    /// code: set `flight`, `reference`, `synthesis`, the components (`body`, `wing`, ...) and
    /// the sections (`airfoils`, `sections`), every quantity in SI as the fields say, then
    /// [`Case::prepare`] it and give it to [`crate::results::run_case`] (or to any method of
    /// [`crate::methods`]). Reports are written in metres (`dim`) with derivatives per degree
    /// (`deriv`) unless these are changed. `examples/build_case.rs` builds a whole aircraft.
    ///
    /// ```
    /// use datcom::case::{Case, FlightInput, Planform, Reference};
    /// use datcom::deck::cards::{AirfoilCard, NacaSeries, Surface};
    ///
    /// let mut case = Case::new();
    /// case.flight = Some(FlightInput {
    ///     mach: vec![0.2],
    ///     altitude: vec![0.0],
    ///     alpha_deg: vec![0.0, 4.0],
    ///     ..FlightInput::default()
    /// });
    /// case.reference = Reference { area: Some(10.0), chord: Some(1.0), span: Some(10.0), roughness: None };
    /// case.wing = Some(Planform {
    ///     chrdr: Some(1.0), chrdtp: Some(1.0), sspn: Some(5.0), sspne: Some(5.0),
    ///     savsi_deg: Some(0.0), chstat: Some(0.25), planform_type: Some(1.0),
    ///     ..Planform::default()
    /// });
    /// case.airfoils.push(AirfoilCard::new(Surface::Wing, NacaSeries::Four, "0012"));
    /// assert!(case.prepare().is_empty());
    /// let results = datcom::results::run_case(&case);
    /// let cl = &results.conditions[0].static_coefficients.cl;
    /// assert_eq!(cl[0], Some(0.0)); // symmetric section, no twist
    /// assert!(cl[1].is_some_and(|cl| cl > 0.2 && cl < 0.4));
    /// ```
    pub fn new() -> Case {
        Case {
            number: 1,
            first_line: 0,
            caseid: None,
            dim: Dim::M,
            scale: 1.0,
            deriv: DerivUnit::default(),
            section_reynolds: SectionReynolds::default(),
            five_digit: FiveDigitReading::default(),
            section_maximum: MaximumReading::default(),
            six_a: SixAReading::default(),
            zero_lift: ZeroLiftReading::default(),
            forward_sweep: ForwardSweepReading::default(),
            tail_slope: TailSlopeReading::default(),
            outboard_section: OutboardSectionReading::default(),
            jorgensen_drag: JorgensenDragReading::default(),
            cards: Cards::default(),
            flight: None,
            reference: Reference::default(),
            synthesis: None,
            body: None,
            wing: None,
            horizontal_tail: None,
            vertical_tail: None,
            ventral_fin: None,
            twin_panels: None,
            sections: BTreeMap::new(),
            larwb: None,
            conditions: Vec::new(),
            condition_warnings: Vec::new(),
            airfoils: Vec::new(),
            other: BTreeMap::new(),
            save: false,
        }
    }

    /// Whether the case has a wing or tail, whose methods (unlike the body's) give no
    /// meaningful number from ±90° of angle of attack.
    pub(crate) fn has_lifting_surface(&self) -> bool {
        self.wing.is_some() || self.horizontal_tail.is_some() || self.vertical_tail.is_some()
    }

    /// Makes a case built in code ready to run, as reading a deck makes a deck's case: the
    /// angles of attack of `flight` put in increasing order (each once) and the flight
    /// conditions derived from it (the 1962 US Standard Atmosphere at the altitudes where
    /// pressure and temperature are not given; `nalt_given` is set when altitudes are given).
    /// Returns what was assumed or changed (the condition warnings are also kept in
    /// `condition_warnings`). Without `flight` the case has no condition. The deck checks of
    /// `datcom-rs check` are [`Case::diagnose`]; [`Case::to_raw`] writes the case as a deck.
    pub fn prepare(&mut self) -> Vec<String> {
        // In code the altitudes given are the altitudes (a deck's NALT counts them).
        if let Some(f) = self.flight.as_mut() {
            f.nalt_given |= !f.altitude.is_empty();
        }
        let reordered = self.derive_conditions();
        reordered
            .into_iter()
            .chain(self.condition_warnings.iter().cloned())
            .collect()
    }

    /// Puts the angles of attack in increasing order, saying why when they were not, and
    /// derives the flight conditions and their warnings from `flight`.
    fn derive_conditions(&mut self) -> Option<String> {
        let Some(f) = self.flight.as_mut() else {
            self.conditions.clear();
            self.condition_warnings.clear();
            return None;
        };
        let reordered = f.angles_in_order().map(|ordered| {
            f.alpha_deg = ordered.angles;
            ordered.reason
        });
        let (conditions, warnings) = conditions::flight_conditions(f);
        self.conditions = conditions;
        self.condition_warnings = warnings;
        reordered
    }

    /// Each surface's section made as the methods make it (the xxSCHR coordinates with
    /// TYPEIN, else the NACA card): a coordinate table or a designation that gives no section
    /// is an error here, where the deck is checked, and not only a warning of the run (whose
    /// surface then has no section characteristics).
    fn check_sections(&self, c: &mut Checks) {
        use crate::geometry::section::{section_source, user_defined, NacaSection, SectionSource};
        for (name, surface) in SECTION_NAMELISTS {
            match section_source(self, surface) {
                Some(SectionSource::User(input)) if !input.scalars.contains_key("NPTS") => {
                    let message = format!(
                        "{} section: user-defined section: NPTS: not given; it counts the XCORD stations (the original reads none without it)",
                        surface.name()
                    );
                    c.push(Severity::Error, name, Some("NPTS"), message, None);
                }
                Some(SectionSource::User(input)) => match user_defined(input) {
                    Err(e @ SectionError::UserSection { variable, .. }) => {
                        let hint = (variable == "XCORD").then_some(
                            "XCORD gives the stations as fractions of the chord, increasing from 0 at the leading edge to 1 at the trailing edge",
                        );
                        let message = format!("{} section: {e}", surface.name());
                        c.push(Severity::Error, name, Some(variable), message, hint);
                    }
                    Ok(coordinates) => {
                        for w in coordinates.warnings {
                            let message = format!("{} section: {w}", surface.name());
                            c.push(Severity::Warning, name, Some("XCORD"), message, None);
                        }
                    }
                    Err(_) => {}
                },
                Some(SectionSource::Naca(card)) => {
                    // The designation is what can be wrong; its coordinates are made when
                    // the case runs.
                    if let Err(e) = NacaSection::from_card_with(card, self.five_digit, self.six_a) {
                        let message = format!("{} section: {e}", surface.name());
                        c.at_line(Severity::Error, card.line, Some(NACA_CARD), message, None);
                    }
                }
                None => {}
            }
        }
    }

    fn check(&self, c: &mut Checks) {
        let components = [
            self.body.is_some(),
            self.wing.is_some(),
            self.horizontal_tail.is_some(),
            self.vertical_tail.is_some(),
            self.ventral_fin.is_some(),
            self.larwb.is_some(),
        ];
        if !components.contains(&true) {
            c.at_line(
                Severity::Warning,
                c.raw.first_line,
                None,
                "the case has no component (a body, wing, tail, ventral fin or $LARWB): no coefficient is computed".into(),
                Some("give $BODY, $WGPLNF, $HTPLNF, $VTPLNF, $VFPLNF or $LARWB"),
            );
        }
        for (name, what) in NOT_IMPLEMENTED {
            if self.other.contains_key(name) {
                c.push(
                    Severity::Warning,
                    name,
                    None,
                    format!("${name}: {what}"),
                    None,
                );
            }
        }
        // The original runs a case only with $FLTCON and $SYNTHS, unless it is a
        // low-aspect-ratio wing-body ($LARWB), hypersonic ($HYPEFF) or transverse-jet ($TRNJET)
        // case; and only with planform and section of the wing and of the horizontal tail
        // given together (a NACA card is a section).
        let special = ["LARWB", "HYPEFF", "TRNJET"]
            .iter()
            .any(|n| self.other.contains_key(*n));
        if !special && self.synthesis.is_none() {
            c.push(
                Severity::Error,
                "SYNTHS",
                None,
                "the case has no $SYNTHS; the original does not run it".into(),
                Some("add $SYNTHS with XCG, ZCG and the component positions"),
            );
        }
        let has_section = |surface: Surface| {
            self.sections.contains_key(surface.name())
                || self.airfoils.iter().any(|a| a.surface == surface)
        };
        // Where a surface's section is given: its NACA card or its section namelist, the
        // earlier (a section without its planform is pointed at there).
        let section_place = |c: &Checks, surface: Surface| {
            let card = self
                .airfoils
                .iter()
                .filter(|a| a.surface == surface && a.line > 0)
                .map(|a| (a.line, 1))
                .min();
            let namelist = SECTION_NAMELISTS
                .iter()
                .find(|(_, s)| *s == surface)
                .and_then(|(nl, _)| c.raw.origins.first_in(nl, c.raw.first_line));
            card.into_iter().chain(namelist).min()
        };
        for (planform, present, surface, pl, sc) in [
            (
                "wing",
                self.wing.is_some(),
                Surface::Wing,
                "WGPLNF",
                "WGSCHR or NACA-W",
            ),
            (
                "horizontal tail",
                self.horizontal_tail.is_some(),
                Surface::HorizontalTail,
                "HTPLNF",
                "HTSCHR or NACA-H",
            ),
        ] {
            if present && !has_section(surface) {
                let message = format!("the {planform} has a planform (${pl}) but no section ({sc}); the original does not run the case");
                c.push(Severity::Error, pl, None, message, None);
            } else if !present && has_section(surface) {
                let message = format!("the {planform} has a section ({sc}) but no planform (${pl}); the original does not run the case");
                let at = section_place(c, surface);
                c.at_place(Severity::Error, at, pl, message, None);
            }
        }
        // The original refuses a vertical-tail section without its planform, and runs a
        // case with a ventral-fin section without one (it has no such test).
        if self.vertical_tail.is_none() && has_section(Surface::VerticalTail) {
            let at = section_place(c, Surface::VerticalTail);
            c.at_place(
                Severity::Error,
                at,
                "VTPLNF",
                "a vertical-tail section is given without $VTPLNF; the original does not run the case".into(),
                None,
            );
        }
        if self.ventral_fin.is_none() && has_section(Surface::VentralFin) {
            let at = section_place(c, Surface::VentralFin);
            c.at_place(
                Severity::Warning,
                at,
                "VFPLNF",
                "a ventral-fin section is given without $VFPLNF: the case has no ventral fin, and no method uses the section".into(),
                Some("add $VFPLNF, or remove the section"),
            );
        }
        match &self.flight {
            None if special => {}
            None => c.push(
                Severity::Error,
                "FLTCON",
                None,
                "the case has no $FLTCON: no flight condition to compute".into(),
                Some("add $FLTCON with NMACH, MACH(1)=... and NALPHA, ALSCHD(1)=..."),
            ),
            Some(f) => {
                if f.mach.is_empty() && f.velocity.is_empty() {
                    c.push(
                        Severity::Error,
                        "FLTCON",
                        Some("MACH"),
                        "neither MACH nor VINF is given".into(),
                        Some("give NMACH and MACH(1)=..., or VINF(1)=... with ALT or TINF"),
                    );
                }
                if f.alpha_deg.is_empty() {
                    c.push(
                        Severity::Warning,
                        "FLTCON",
                        Some("ALSCHD"),
                        "no angle of attack is given: no coefficient table can be computed".into(),
                        Some("give NALPHA and ALSCHD(1)=..."),
                    );
                }
                if let Some(ordered) = f.angles_in_order() {
                    c.push(
                        Severity::Warning,
                        "FLTCON",
                        Some("ALSCHD"),
                        ordered.reason,
                        Some("give the angles of attack in increasing order"),
                    );
                }
                c.range("FLTCON", "MACH", MACH_RANGE, self.dim);
                c.range("FLTCON", "ALT", ATMOSPHERE_RANGE_M, self.dim);
                c.positive("FLTCON", "VINF");
                c.positive("FLTCON", "PINF");
                c.positive("FLTCON", "TINF");
                c.positive("FLTCON", "RNNUB");
                if let Some(l) = c.raw.scalar("FLTCON", "LOOP") {
                    if ![1.0, 2.0, 3.0].contains(&l) {
                        c.problem(
                            Severity::Error,
                            "FLTCON",
                            Some("LOOP"),
                            DeckProblem::WrongKind {
                                variable: "LOOP".into(),
                                expected: "1.0, 2.0 or 3.0".into(),
                                found: format!("{l}"),
                            },
                            Some("LOOP=1 pairs Mach i with altitude i; 2 varies Mach at each altitude; 3 varies altitude at each Mach"),
                        );
                    }
                }
                if f.pressure.is_empty() != f.temperature.is_empty() {
                    let (given, missing) = if f.pressure.is_empty() {
                        ("TINF", "PINF")
                    } else {
                        ("PINF", "TINF")
                    };
                    c.push(
                        Severity::Warning,
                        "FLTCON",
                        Some(given),
                        format!("{given} is given without {missing}: pressure and temperature are used only together, so {given} is ignored (as in the original)"),
                        Some("give both PINF and TINF, or ALT alone"),
                    );
                }
            }
        }
        c.angles_of_attack(self.has_lifting_surface());
        c.acute("SYNTHS", "ALIW", "the wing's incidence");
        c.acute("SYNTHS", "ALIH", "the horizontal tail's incidence");
        // At least one Mach number's values are read.
        let mach_count = self.flight.as_ref().map_or(1, |f| f.mach.len().max(1));
        for (name, _) in SECTION_NAMELISTS {
            // Fractions of the chord: the thickness ratio and its station.
            c.range(name, "TOVC", CHORD_FRACTION, self.dim);
            c.range(name, "XOVC", CHORD_FRACTION, self.dim);
            c.non_negative(name, "DELTAY");
            // A maximum lift at or below zero puts the stall at or below the zero-lift angle,
            // where the non-linear lift curve divides by zero. CLMAX is given per Mach number:
            // only the case's Mach numbers' values are read.
            c.sign_of_first(name, "CLMAX", false, mach_count);
            c.positive(name, "CLMAXL");
        }
        self.check_sections(c);
        c.positive("OPTINS", "SREF");
        c.positive("OPTINS", "CBARR");
        c.positive("OPTINS", "BLREF");
        // The geometry is multiplied by SCALE: one of zero or less is read as 1.
        c.positive("SYNTHS", "SCALE");
        for (name, p) in [
            ("WGPLNF", &self.wing),
            ("HTPLNF", &self.horizontal_tail),
            ("VTPLNF", &self.vertical_tail),
            ("VFPLNF", &self.ventral_fin),
        ] {
            let Some(p) = p else { continue };
            c.positive(name, "CHRDR");
            c.positive(name, "SSPN");
            c.positive(name, "SSPNE");
            c.non_negative(name, "CHRDTP");
            c.range(name, "CHSTAT", CHORD_FRACTION, self.dim);
            c.non_negative(name, "CHRDBP");
            for (var, what) in [
                ("SAVSI", "a sweep angle"),
                ("SAVSO", "a sweep angle"),
                ("DHDADI", "a dihedral angle"),
                ("DHDADO", "a dihedral angle"),
            ] {
                c.acute(name, var, what);
            }
            if p.chrdr.is_none() {
                c.push(
                    Severity::Error,
                    name,
                    Some("CHRDR"),
                    "root chord CHRDR is not given".into(),
                    None,
                );
            }
            if p.sspn.is_none() {
                c.push(
                    Severity::Error,
                    name,
                    Some("SSPN"),
                    "semi-span SSPN is not given".into(),
                    None,
                );
            }
            if let (Some(e), Some(s)) = (p.sspne, p.sspn) {
                if e > s * (1.0 + EXPOSED_SPAN_TOLERANCE) {
                    c.push(
                        Severity::Error,
                        name,
                        Some("SSPNE"),
                        "exposed semi-span SSPNE is larger than the semi-span SSPN".into(),
                        None,
                    );
                }
            }
        }
        if let Some(b) = &self.body {
            let n = b.x.len();
            if n < 2 {
                c.push(
                    Severity::Error,
                    "BODY",
                    Some("X"),
                    format!("the body needs at least 2 stations; {n} given"),
                    None,
                );
            }
            let x: Vec<(usize, f64)> = c.values("BODY", "X").collect();
            if let Some(w) = x.windows(2).find(|w| w[1].1 < w[0].1) {
                let ((i, xi), (j, xj)) = (w[0], w[1]);
                c.push(
                    Severity::Error,
                    "BODY",
                    Some("X"),
                    format!(
                        "body stations X must not decrease: X({j})={xj} is less than X({i})={xi}"
                    ),
                    None,
                );
            }
            if n >= 2 && b.x[n - 1] - b.x[0] <= 0.0 {
                c.push(
                    Severity::Error,
                    "BODY",
                    Some("X"),
                    "body length (last X minus first X) must be positive".into(),
                    None,
                );
            }
            for var in ["R", "S", "P"] {
                c.non_negative("BODY", var);
            }
            let upper: Vec<(usize, f64)> = c.values("BODY", "ZU").collect();
            let lower: Vec<(usize, f64)> = c.values("BODY", "ZL").collect();
            let crossing = upper.iter().find_map(|&(i, zu)| {
                lower
                    .iter()
                    .find(|&&(j, zl)| j == i && zl > zu)
                    .map(|&(_, zl)| (i, zu, zl))
            });
            if let Some((i, zu, zl)) = crossing {
                c.push(
                    Severity::Error,
                    "BODY",
                    Some("ZL"),
                    format!(
                        "the lower contour is above the upper one at station {i}: ZL({i})={zl} is above ZU({i})={zu}"
                    ),
                    None,
                );
            }
        }
        if self.larwb.is_some() {
            c.positive("LARWB", "SREF");
            c.positive("LARWB", "L");
            // The method divides by the frontal area (the suction's geometry), by the base's
            // width, and by its height only when there is a base (the base's shape).
            for var in ["SFRONT", "BB"] {
                c.positive("LARWB", var);
            }
            let has_base = self
                .larwb
                .as_ref()
                .and_then(|l| l.sbase)
                .is_some_and(|s| s > 0.0);
            if has_base {
                c.positive("LARWB", "HB");
            }
            for var in ["SWET", "PERBAS", "SBASE", "HB", "SBS", "SBSLB"] {
                c.non_negative("LARWB", var);
            }
        }
    }

    /// Namelists present in the case (typed and other), by name.
    pub fn namelist_names(&self) -> Vec<String> {
        let mut v = Vec::new();
        let typed: [(&str, bool); 9] = [
            ("FLTCON", self.flight.is_some()),
            ("SYNTHS", self.synthesis.is_some()),
            ("BODY", self.body.is_some()),
            ("WGPLNF", self.wing.is_some()),
            ("HTPLNF", self.horizontal_tail.is_some()),
            ("VTPLNF", self.vertical_tail.is_some()),
            ("VFPLNF", self.ventral_fin.is_some()),
            ("TVTPAN", self.twin_panels.is_some()),
            ("OPTINS", self.reference != Reference::default()),
        ];
        for (n, present) in typed {
            if present {
                v.push(n.to_string());
            }
        }
        for (sc, surface) in SECTION_NAMELISTS {
            if self.sections.contains_key(surface.name()) {
                v.push(sc.to_string());
            }
        }
        v.extend(self.other.keys().cloned());
        v.sort();
        v
    }
}
