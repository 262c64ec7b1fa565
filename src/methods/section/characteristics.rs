//! What the section method returns: the values of a SECTION DEFINITION page and the terms
//! behind them, per-condition values, warnings and errors.

use serde::Serialize;

use super::{MaximumReading, ShapeError, MIN_REYNOLDS_NUMBER, REFERENCE_REYNOLDS_NUMBER};

/// Where a Mach number's lift-curve slope comes from.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum SlopeSource {
    /// Weber's compressible method at this Mach number.
    Computed,
    /// The Mach number is at or above the crest-critical Mach number: the crest-critical
    /// slope, and no aerodynamic centre.
    CrestCritical,
    /// Given by the user (CLALPA).
    User,
    /// Not computed (a warning says why).
    Failed,
}

/// Section values at one flight condition.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct MachCharacteristics {
    pub mach: f64,
    pub source: SlopeSource,
    /// Lift-curve slope, viscous-corrected, per radian.
    pub cla_per_rad: Option<f64>,
    /// Aerodynamic centre, fraction of chord from the leading edge.
    pub xac: Option<f64>,
    /// Zero-lift angle at this Mach number, degrees.
    pub zero_lift_alpha_deg: Option<f64>,
    /// Reynolds number the viscous correction used.
    pub reynolds_number: Option<f64>,
    /// c_lα/(c_lα)theory of the viscous correction.
    pub cla_ratio: Option<f64>,
    /// Section maximum lift coefficient at this condition's Reynolds number (DATCOM 4.1.1.4;
    /// the terms are in [`SectionCharacteristics::max_lift`]).
    pub max_cl: Option<f64>,
}

/// The crest-critical state.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct CrestCritical {
    /// Free-stream Mach number at which the crest becomes sonic.
    pub mach: f64,
    /// Crest location, fraction of chord.
    pub x: f64,
    /// Lift-curve slope at the crest-critical Mach number, per radian; `None` when the crest
    /// becomes critical only at Mach 1 or above.
    pub cla_per_rad: Option<f64>,
    /// Some condition is at or above the crest-critical Mach number (the original prints the
    /// block only then).
    pub exceeded: bool,
}

/// What could not be computed as asked, and what was done instead.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
#[non_exhaustive]
pub enum SectionWarning {
    /// No (valid) Reynolds number for a condition: the reference value was used.
    ReynoldsNumberMissing { mach: f64 },
    /// The Reynolds number is below the viscous fit's range: the lowest value was used.
    /// `condition`: the flight condition's number, from 1 (a Mach number at several
    /// altitudes has several Reynolds numbers).
    ReynoldsNumberLow {
        mach: f64,
        reynolds_number: f64,
        condition: usize,
    },
    /// A condition's Mach number is negative or not a number.
    MachInvalid { mach: f64 },
    /// Weber's method cannot compute the slope at a Mach number.
    Failed { mach: f64, reason: String },
    /// The crest-critical Mach number cannot be found; conditions at Mach 1 or above have no
    /// slope.
    CrestNotLocated,
}

impl std::fmt::Display for SectionWarning {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            SectionWarning::ReynoldsNumberMissing { mach } => write!(
                f,
                "no Reynolds number for Mach {}: the section characteristics use {REFERENCE_REYNOLDS_NUMBER:.0e}",
                crate::charts::Query(*mach)
            ),
            SectionWarning::ReynoldsNumberLow {
                mach,
                reynolds_number,
                condition,
            } => write!(
                f,
                "Reynolds number {reynolds_number:.4e} at Mach {} (flight condition {condition}) is below the airfoil section method's range: section characteristics computed at {MIN_REYNOLDS_NUMBER:.4e}",
                crate::charts::Query(*mach)
            ),
            SectionWarning::MachInvalid { mach } => {
                write!(f, "Mach number {mach} is not valid: no section characteristics")
            }
            SectionWarning::Failed { mach, reason } => write!(
                f,
                "the airfoil section method cannot compute the lift-curve slope at Mach {}: {reason}; give CLALPA for it",
                crate::charts::Query(*mach)
            ),
            SectionWarning::CrestNotLocated => write!(
                f,
                "the crest (upper-surface point tangent to the flow) cannot be located: no crest-critical Mach number, and no section slope at Mach 1 or above"
            ),
        }
    }
}

/// Why no section characteristics can be computed.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum CharacteristicsError {
    #[error(transparent)]
    Shape(#[from] ShapeError),
    #[error("the leading-edge radius must be a non-negative number; it is {0}")]
    LeadingEdgeRadius(f64),
    #[error("the section's Mach-0 characteristics cannot be computed: {0}")]
    MachZero(String),
}

/// Everything the original prints on a SECTION DEFINITION page, and the terms behind it.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct SectionCharacteristics {
    /// Ideal angle of attack (thin-airfoil theory, or the designation's), degrees.
    pub ideal_alpha_deg: f64,
    /// Ideal lift coefficient.
    pub ideal_cl: f64,
    /// Zero-lift angle of attack at Mach 0 (Weber's method), degrees.
    pub zero_lift_alpha_deg: f64,
    /// Zero-lift angle of the mean line alone by thin-airfoil theory (or the designation's),
    /// degrees: where the iteration starts.
    pub thin_airfoil_zero_lift_alpha_deg: f64,
    /// Zero-lift pitching moment about the quarter chord at Mach 0.
    pub cm0: f64,
    /// Lift-curve slope at Mach 0 and Reynolds number [`REFERENCE_REYNOLDS_NUMBER`],
    /// viscous-corrected, per radian.
    pub cla_mach0_per_rad: f64,
    /// Inviscid (Weber) lift-curve slope at Mach 0, per radian.
    pub cla_mach0_theory_per_rad: f64,
    /// c_lα/(c_lα)theory at Mach 0.
    pub cla_ratio_mach0: f64,
    /// Aerodynamic centre at Mach 0, fraction of chord.
    pub xac_mach0: f64,
    /// tan(φ_TE/2) the viscous correction uses.
    pub tan_half_trailing_edge_angle: f64,
    /// Leading-edge radius, fraction of chord.
    pub leading_edge_radius: f64,
    /// Maximum thickness, fraction of chord (the designation's when it names one).
    pub max_thickness: f64,
    /// The largest tabulated thickness by the shape's maximum reading, fraction of chord:
    /// under the original's reading what its methods take as the section's t/c (its TOVC),
    /// also for a NACA section, whose table rises a little above the designation (a 4-digit
    /// 10 % section: 0.100029 at x = 0.30); see [`SectionCharacteristics::thickness_ratio`].
    pub tabulated_max_thickness: f64,
    /// Station of the largest thickness ordinate, fraction of chord.
    pub max_thickness_x: f64,
    /// Largest mean-line ordinate and its station, fractions of chord (0, 0 if none is
    /// positive).
    pub max_camber: f64,
    pub max_camber_x: f64,
    /// Leading-edge sharpness parameter Δy, percent of chord.
    pub delta_y_percent: f64,
    /// One per condition, in the order given.
    pub per_mach: Vec<MachCharacteristics>,
    /// Section maximum lift (DATCOM 4.1.1.4): its terms and one value per condition; `None`
    /// when it cannot be computed (non-finite geometry).
    pub max_lift: Option<super::SectionMaxLift>,
    pub crest_critical: Option<CrestCritical>,
    pub warnings: Vec<SectionWarning>,
}

impl SectionCharacteristics {
    /// The thickness ratio the wing and tail methods take: the designation's (or the greatest
    /// tabulated) with [`MaximumReading::Greatest`], the tabulated maximum at the last station
    /// where it rose with [`MaximumReading::LastRise`], as the original's SECO hands its methods
    /// (it prints the designation's). It decides, for one, whether the wing-body drag takes the
    /// original's regression (t/c up to 0.100): a NACA 0010 tail gets it by the designation,
    /// not by the original's table (docs/section-characteristics.md).
    pub fn thickness_ratio(&self, reading: MaximumReading) -> f64 {
        match reading {
            MaximumReading::Greatest => self.max_thickness,
            MaximumReading::LastRise => self.tabulated_max_thickness,
        }
    }
}
