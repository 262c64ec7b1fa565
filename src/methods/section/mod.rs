//! Airfoil section characteristics: what the original prints on its `<SURFACE> SECTION
//! DEFINITION` pages, from the section's ordinates (DATCOM 2.2.1 section parameters, 4.1.1.1
//! zero-lift angle, 4.1.1.2 lift-curve slope, 4.1.2.1 zero-lift pitching moment, 4.1.4.1
//! aerodynamic centre; the original's routines M50O62, DELY, THEORY, IDEAL and SLOPE), and the
//! section maximum lift coefficient (DATCOM 4.1.1.4, routine MAXCL; module `max_lift`).
//!
//! The method is Weber's: the velocity on the section at 31 chordwise points from sums over
//! the thickness and mean-line ordinates (module `weber`), the pressure from it with
//! compressibility, lift and moment integrated from the pressure (module `lift`). The zero-lift
//! angle is found by Newton's iteration on that lift; the lift-curve slope is the difference
//! over one degree above it, corrected for viscosity by the fit of DATCOM figure 4.1.1.2-8a
//! (module `viscous`). Thin-airfoil theory gives the ideal angle and lift coefficient
//! (module `thin_airfoil`); the crest-critical Mach number bounds the subsonic method
//! (module `crest`).
//!
//! Units: fractions of chord for lengths, degrees for angles, lift-curve slopes per radian.
//! Lift is normal to the free stream, positive up; the pitching moment is about the quarter
//! chord, positive nose up; the aerodynamic centre is a fraction of chord from the leading
//! edge.
//!
//! Where this differs from the original (single precision, the zero-lift iteration's
//! tolerance, and the original's defects), see `docs/section-characteristics.md`.

mod characteristics;
mod crest;
pub mod design;
mod interpolation;
mod lift;
mod max_lift;
mod parameters;
mod shape;
mod surface;
mod thin_airfoil;
mod viscous;
mod weber;

use serde::Serialize;

pub use characteristics::{
    CharacteristicsError, CrestCritical, MachCharacteristics, SectionCharacteristics,
    SectionWarning, SlopeSource,
};
pub use max_lift::{
    section_max_lift, ConditionMaxLift, MaxLiftError, MaxLiftGeometry, MaxLiftWarning,
    SectionMaxLift, BASE_CHART as MAX_LIFT_BASE_CHART, CAMBER_CHART as MAX_LIFT_CAMBER_CHART,
    MAX_LIFT_REFERENCE_REYNOLDS_NUMBER, REYNOLDS_CHART as MAX_LIFT_REYNOLDS_CHART,
    THICKNESS_POSITION_CHART as MAX_LIFT_THICKNESS_POSITION_CHART,
};
pub use shape::{
    DesignLift, MaximumReading, SectionShape, ShapeError, StationValues, ThicknessReading,
    SHORTEST_TRAILING_EDGE,
};
pub use surface::{surface_section, SurfaceSection, SurfaceSectionError};
pub use viscous::MIN_REYNOLDS_NUMBER;

use interpolation::Ordinates;
use thin_airfoil::ThinAirfoil;
use weber::{Reading, Terms};

/// Reynolds number (on the chord) of the Mach-0 values, and of a Mach number whose Reynolds
/// number is not known (the original's value for both).
pub const REFERENCE_REYNOLDS_NUMBER: f64 = 1.0e6;

/// Lift within which the zero-lift iteration stops by default: far below anything printed,
/// so the zero-lift angle does not depend on where the iteration starts.
pub const ZERO_LIFT_CL_TOLERANCE: f64 = 1.0e-10;

/// The original's tolerance: it stops when |c_l| ≤ 0.001 (about 0.01° from zero lift), so
/// its zero-lift angle and the values at it depend on the iteration's path.
pub const ORIGINAL_ZERO_LIFT_CL_TOLERANCE: f64 = 1.0e-3;

/// One flight condition of the section.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct SectionCondition {
    pub mach: f64,
    /// Reynolds number on the chord the section is computed for (the exposed mean
    /// aerodynamic chord of the surface); `None` when not known:
    /// [`REFERENCE_REYNOLDS_NUMBER`] is used, with a warning.
    pub reynolds_number: Option<f64>,
}

/// What the user gives in xxSCHR that the method takes instead of computing it.
#[derive(Debug, Clone, PartialEq, Default, Serialize)]
pub struct SectionOverrides {
    /// Leading-edge radius (LERI), fraction of chord; used when the section's designation does
    /// not fix it (user-defined sections).
    pub leading_edge_radius: Option<f64>,
    /// Lift-curve slope per condition (CLALPA), per radian: where given, that condition is not
    /// computed.
    pub lift_curve_slope_per_rad: Vec<Option<f64>>,
}

/// Numerical settings.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct SectionOptions {
    /// |c_l| at which the zero-lift iteration stops.
    pub zero_lift_cl_tolerance: f64,
}

impl Default for SectionOptions {
    fn default() -> Self {
        SectionOptions {
            zero_lift_cl_tolerance: ZERO_LIFT_CL_TOLERANCE,
        }
    }
}

/// The section characteristics with the default options. See
/// [`section_characteristics_with`].
///
/// The method is a pure function of its inputs and the costliest step of a run (the Weber
/// integration at every condition), while the build-up asks for the same section from several
/// methods (wing, wing lateral, tails) at each flight condition. So the last few results are
/// remembered per thread, keyed by the whole input compared exactly; a changed input is
/// computed afresh. (A NaN among the shape's station values compares equal to the same shared
/// values, so such a shape can be remembered; the method refuses it before computing anything,
/// with the same error each time.)
pub fn section_characteristics(
    shape: &SectionShape,
    conditions: &[SectionCondition],
    user: &SectionOverrides,
) -> Result<SectionCharacteristics, CharacteristicsError> {
    memo::remembered(shape, conditions, user, || {
        section_characteristics_with(shape, conditions, user, &SectionOptions::default())
    })
}

mod memo {
    use std::cell::RefCell;

    use super::{
        CharacteristicsError, SectionCharacteristics, SectionCondition, SectionOverrides,
        SectionShape,
    };

    /// How many distinct sections a thread remembers: a case has at most four (wing,
    /// horizontal tail, vertical tail, ventral fin).
    const REMEMBERED: usize = 4;

    type Output = Result<SectionCharacteristics, CharacteristicsError>;
    type Entry = (
        SectionShape,
        Vec<SectionCondition>,
        SectionOverrides,
        Output,
    );

    thread_local! {
        static LAST: RefCell<Vec<Entry>> = const { RefCell::new(Vec::new()) };
    }

    pub(super) fn remembered(
        shape: &SectionShape,
        conditions: &[SectionCondition],
        user: &SectionOverrides,
        compute: impl FnOnce() -> Output,
    ) -> Output {
        let hit = LAST.with(|last| {
            last.borrow()
                .iter()
                .find(|(s, c, u, _)| s == shape && c.as_slice() == conditions && u == user)
                .map(|(_, _, _, out)| out.clone())
        });
        if let Some(out) = hit {
            return out;
        }
        let out = compute();
        LAST.with(|last| {
            let mut last = last.borrow_mut();
            if last.len() == REMEMBERED {
                let _evicted = last.remove(0);
            }
            last.push((
                shape.clone(),
                conditions.to_vec(),
                user.clone(),
                out.clone(),
            ));
        });
        out
    }
}

/// Slope over one degree converted to per radian.
fn per_rad(per_deg: f64) -> f64 {
    per_deg / lift::ALPHA_STEP_DEG.to_radians()
}

/// The section characteristics of `shape` at Mach 0 and at each condition.
///
/// - Mach 0 (Reynolds number 10⁶): zero-lift angle, zero-lift pitching moment, lift-curve
///   slope, aerodynamic centre and the crest-critical Mach number.
/// - Each condition below the crest-critical Mach number: lift-curve slope and aerodynamic
///   centre by Weber's compressible method at the condition's Reynolds number, unless the user
///   gives the slope. At or above it: the crest-critical slope. (Unlike the original, the
///   order of the conditions does not matter.)
///
/// The leading-edge radius is the designation's, else the user's (LERI), else the circle
/// through the nose and the first station.
pub fn section_characteristics_with(
    shape: &SectionShape,
    conditions: &[SectionCondition],
    user: &SectionOverrides,
    options: &SectionOptions,
) -> Result<SectionCharacteristics, CharacteristicsError> {
    shape.check()?;
    let rho = shape
        .leading_edge_radius
        .or(user.leading_edge_radius)
        .unwrap_or_else(|| parameters::nose_circle_radius(shape));
    if !(rho.is_finite() && rho >= 0.0) {
        return Err(CharacteristicsError::LeadingEdgeRadius(rho));
    }
    let thickness = Ordinates {
        x: &shape.x,
        y: &shape.half_thickness,
    };
    let camber = Ordinates {
        x: &shape.x,
        y: &shape.camber,
    };
    let reading = match shape.thickness_reading {
        ThicknessReading::Smooth => Reading::Smooth,
        ThicknessReading::Linear => Reading::Linear,
    };
    let terms = Terms::new(thickness, camber, reading, rho);
    let thin = match shape.design {
        Some(d) => ThinAirfoil {
            ideal_alpha_deg: d.ideal_alpha_deg,
            zero_lift_alpha_deg: d.zero_lift_alpha_deg,
            ideal_cl: d.ideal_cl,
        },
        None => ThinAirfoil::from_terms(&terms),
    };
    let tan_half_te = trailing_edge_slope(&terms);
    let tolerance = options.zero_lift_cl_tolerance;

    let mach0 = lift::zero_lift(&terms, 0.0, thin.zero_lift_alpha_deg, tolerance)
        .map_err(|f| CharacteristicsError::MachZero(f.to_string()))?;
    let ratio0 = viscous::lift_curve_slope_ratio(REFERENCE_REYNOLDS_NUMBER, tan_half_te);
    let cla0_per_deg = mach0.cla_per_deg() * ratio0 * viscous::EMPIRICAL_FACTOR;
    let xac0 = 0.25 - mach0.cma_per_deg() / cla0_per_deg;

    let mut warnings = Vec::new();
    let crest = match crest::crest_critical(
        &terms,
        mach0.above.alpha_deg,
        &mach0.above.upper_velocity,
        cla0_per_deg,
    ) {
        Ok(c) => Some(c),
        Err(crest::NoCrest::NotLocated) => {
            warnings.push(SectionWarning::CrestNotLocated);
            None
        }
    };
    let critical_mach = crest.map_or(1.0, |c| c.mach.min(1.0));

    let mut subsonic = Subsonic {
        terms: &terms,
        tan_half_te,
        tolerance,
        start_deg: mach0.at.alpha_deg,
    };
    let mut exceeded = false;
    let mut per_mach: Vec<MachCharacteristics> = conditions
        .iter()
        .enumerate()
        .map(|(i, c)| {
            let user_slope = user.lift_curve_slope_per_rad.get(i).copied().flatten();
            let row = subsonic.row(c, i, user_slope, crest.as_ref(), &mut warnings);
            exceeded |= row.mach >= critical_mach;
            row
        })
        .collect();

    let (max_thickness_measured, max_thickness_x) = parameters::max_thickness(shape);
    let (max_camber, max_camber_x) = parameters::max_camber(shape);
    let delta_y_percent = parameters::delta_y_percent(shape);
    let max_lift = section_max_lift(
        &MaxLiftGeometry {
            delta_y_percent,
            max_thickness_x,
            max_camber,
            max_camber_x,
        },
        &conditions
            .iter()
            .map(|c| c.reynolds_number)
            .collect::<Vec<_>>(),
    )
    .ok();
    if let Some(m) = &max_lift {
        for (row, at) in per_mach.iter_mut().zip(&m.per_condition) {
            row.max_cl = Some(at.max_cl);
        }
    }
    let out = SectionCharacteristics {
        ideal_alpha_deg: thin.ideal_alpha_deg,
        ideal_cl: thin.ideal_cl,
        zero_lift_alpha_deg: mach0.at.alpha_deg,
        thin_airfoil_zero_lift_alpha_deg: thin.zero_lift_alpha_deg,
        cm0: mach0.at.cm,
        cla_mach0_per_rad: per_rad(cla0_per_deg),
        cla_mach0_theory_per_rad: per_rad(mach0.cla_per_deg()),
        cla_ratio_mach0: ratio0,
        xac_mach0: xac0,
        tan_half_trailing_edge_angle: tan_half_te,
        leading_edge_radius: rho,
        max_thickness: shape.max_thickness.unwrap_or(max_thickness_measured),
        tabulated_max_thickness: max_thickness_measured,
        max_thickness_x,
        max_camber,
        max_camber_x,
        delta_y_percent,
        per_mach,
        max_lift,
        crest_critical: crest.map(|c| CrestCritical {
            mach: c.mach,
            x: c.x,
            cla_per_rad: c.cla_per_deg.map(per_rad),
            exceeded,
        }),
        warnings,
    };
    let scalars = [
        out.ideal_alpha_deg,
        out.ideal_cl,
        out.zero_lift_alpha_deg,
        out.cm0,
        out.cla_mach0_per_rad,
        out.xac_mach0,
        out.tan_half_trailing_edge_angle,
        out.delta_y_percent,
    ];
    if scalars.iter().any(|v| !v.is_finite()) {
        return Err(CharacteristicsError::MachZero(
            "the pressure distribution has no finite value".into(),
        ));
    }
    Ok(out)
}

/// The per-condition part of the method: Weber's compressible slope below the crest-critical
/// Mach number, each zero-lift iteration starting where the previous one ended (as the
/// original's does).
struct Subsonic<'a> {
    terms: &'a Terms,
    tan_half_te: f64,
    tolerance: f64,
    start_deg: f64,
}

impl Subsonic<'_> {
    /// The values at condition `c`, the `index`-th (0-based) of the case's; `user_slope` is
    /// the user's CLALPA for it, per radian.
    fn row(
        &mut self,
        c: &SectionCondition,
        index: usize,
        user_slope: Option<f64>,
        crest: Option<&crest::Crest>,
        warnings: &mut Vec<SectionWarning>,
    ) -> MachCharacteristics {
        let mach = c.mach;
        let mut row = MachCharacteristics {
            mach,
            source: SlopeSource::Failed,
            cla_per_rad: None,
            xac: None,
            zero_lift_alpha_deg: None,
            reynolds_number: None,
            cla_ratio: None,
            max_cl: None,
        };
        if !(mach.is_finite() && mach >= 0.0) {
            warnings.push(SectionWarning::MachInvalid { mach });
            return row;
        }
        let critical_mach = crest.map_or(1.0, |c| c.mach.min(1.0));
        if let Some(cla) = user_slope {
            row.source = SlopeSource::User;
            row.cla_per_rad = Some(cla);
            return row;
        }
        if mach >= critical_mach {
            match crest {
                Some(cc) => {
                    row.source = SlopeSource::CrestCritical;
                    row.cla_per_rad = cc.cla_per_deg.map(per_rad);
                }
                None => warnings.push(SectionWarning::Failed {
                    mach,
                    reason: "Weber's method is subsonic and no crest-critical slope is known"
                        .into(),
                }),
            }
            return row;
        }
        let reynolds = reynolds_number(c, index, warnings);
        match lift::zero_lift(self.terms, mach, self.start_deg, self.tolerance) {
            Ok(z) => {
                self.start_deg = z.at.alpha_deg;
                let ratio = viscous::lift_curve_slope_ratio(reynolds, self.tan_half_te);
                let cla = z.cla_per_deg() * ratio * viscous::EMPIRICAL_FACTOR;
                let xac = 0.25 - z.cma_per_deg() / cla;
                if cla.is_finite() {
                    row.source = SlopeSource::Computed;
                    row.cla_per_rad = Some(per_rad(cla));
                    row.xac = xac.is_finite().then_some(xac);
                    row.zero_lift_alpha_deg = Some(z.at.alpha_deg);
                    row.reynolds_number = Some(reynolds);
                    row.cla_ratio = Some(ratio);
                }
            }
            Err(f) => warnings.push(SectionWarning::Failed {
                mach,
                reason: f.to_string(),
            }),
        }
        row
    }
}

/// The Reynolds number of a condition for the viscous correction: its own, at least
/// [`MIN_REYNOLDS_NUMBER`]; [`REFERENCE_REYNOLDS_NUMBER`] when it has none. `index`: the
/// condition's, 0-based (a Mach number at several altitudes has several).
fn reynolds_number(c: &SectionCondition, index: usize, warnings: &mut Vec<SectionWarning>) -> f64 {
    let mach = c.mach;
    match c.reynolds_number.filter(|r| r.is_finite() && *r > 0.0) {
        Some(r) if r < MIN_REYNOLDS_NUMBER => {
            warnings.push(SectionWarning::ReynoldsNumberLow {
                mach,
                reynolds_number: r,
                condition: index + 1,
            });
            MIN_REYNOLDS_NUMBER
        }
        Some(r) => r,
        None => {
            warnings.push(SectionWarning::ReynoldsNumberMissing { mach });
            REFERENCE_REYNOLDS_NUMBER
        }
    }
}

/// tan(φ_TE/2): the fall of the half thickness from between Weber's points 6 and 7
/// (x ≈ 0.90) to point 2 (x ≈ 0.99), over that distance.
fn trailing_edge_slope(t: &Terms) -> f64 {
    use weber::Grid;
    let (k2, k6, k7) = (Grid::at(2), Grid::at(6), Grid::at(7));
    let x = &t.grid.x;
    let run = x[k2] - 0.5 * (x[k6] + x[k7]);
    (0.5 * (t.zt[k6] + t.zt[k7]) - t.zt[k2]) / run
}
