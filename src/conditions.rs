//! Flight conditions of a case: Mach, altitude, velocity, pressure, temperature and Reynolds
//! number per unit length, from $FLTCON and the 1962 US Standard Atmosphere.
//!
//! Rules, as the original program applies them (routines CHECK and the main program's
//! flight-condition loop), and where we differ:
//! - Pressure and temperature given together are used as given and the altitude is only
//!   reported; otherwise the altitude (absent: sea level) gives them through the atmosphere.
//! - A given Mach number wins over a given velocity: the velocity is recomputed from the Mach
//!   number and the speed of sound. With velocity and no Mach number, Mach = V/a. (The original
//!   hangs there when an airfoil section is given; we do not.)
//! - A given Reynolds number per length is used; otherwise Re/l = ρV/μ with Sutherland's law.
//! - LOOP=1 pairs Mach i with altitude i (NALT defaults to NMACH; when they differ both are cut
//!   to the smaller, with a warning); LOOP=2 holds altitude in the outer loop; LOOP=3 holds Mach
//!   in the outer loop.
//! - Without altitude, pressure or temperature, a case that needs them (no Reynolds number, or a
//!   velocity without Mach number) is computed at sea level with a warning; the original uses a
//!   speed of sound of 1000 ft/s and Re = 5E6 there. A LOOP of 2 or 3 without atmospheric data
//!   falls back to LOOP=1, as in the original.

use serde::Serialize;

use crate::atmosphere;
use crate::case::units::KELVIN_PER_RANKINE;
use crate::case::{FlightInput, Loop};

const FT: f64 = 0.3048;
/// Speed of sound over √T: a = 49.01685·√T ft/s with T in °R (√(γR) for γ = 1.4 and
/// R = 1716.2 ft·lbf/(slug·°R)), the constant of the original's flight-condition loop.
const SOUND_FT_PER_S_PER_SQRT_RANKINE: f64 = 49.01685;
/// Reynolds number per foot = K·p·M·(T + S)/T² with p in lb/ft², T in °R: ρ·a·M/μ with
/// ρ = p/(RT), a as above and Sutherland's law μ = β·T^1.5/(T + S). K folds R, √(γR) and β.
const REYNOLDS_K_PER_FT: f64 = 1.2527e6;
/// Sutherland's constant for air, °R.
const SUTHERLAND_RANKINE: f64 = 198.6;
/// The fastest flight speed taken, m/s: Mach 100 (the Mach numbers' limit) in the hottest
/// air of the standard atmosphere is about 70 km/s; a velocity beyond this is not a flight's.
const VELOCITY_LIMIT: f64 = 1.0e5;

/// Speed of sound, m/s, at static temperature `t` K.
pub fn speed_of_sound(t: f64) -> f64 {
    SOUND_FT_PER_S_PER_SQRT_RANKINE * (t / KELVIN_PER_RANKINE).sqrt() * FT
}

/// Reynolds number per metre at pressure `p` Pa, temperature `t` K and Mach `mach`.
pub fn reynolds_per_metre(p: f64, t: f64, mach: f64) -> f64 {
    let p_psf = p / crate::case::units::NEWTONS_PER_POUND * FT * FT;
    let t_r = t / KELVIN_PER_RANKINE;
    REYNOLDS_K_PER_FT * p_psf * mach * (t_r + SUTHERLAND_RANKINE) / (t_r * t_r) / FT
}

/// One flight condition, SI. `None` where the deck gives no value and none was needed (the
/// original prints a blank there).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct FlightCondition {
    pub mach: f64,
    /// Geometric altitude, m.
    pub altitude: Option<f64>,
    /// m/s.
    pub velocity: Option<f64>,
    /// Pa.
    pub pressure: Option<f64>,
    /// K.
    pub temperature: Option<f64>,
    /// Per metre.
    pub reynolds_per_length: f64,
    /// 0-based Mach and altitude indices in the FLTCON arrays.
    pub mach_index: usize,
    pub altitude_index: usize,
}

/// The flight conditions of a case, in the order the original computes them, with warnings.
pub fn flight_conditions(f: &FlightInput) -> (Vec<FlightCondition>, Vec<String>) {
    let mut warnings = Vec::new();
    let have_mach = !f.mach.is_empty();
    let n_speed = f.mach.len().max(f.velocity.len());
    if n_speed == 0 {
        return (Vec::new(), warnings);
    }
    let have_pt = !f.pressure.is_empty() && !f.temperature.is_empty();
    let have_alt = !f.altitude.is_empty();
    let mut atmosphere_given = have_alt || have_pt;
    let needs_atmosphere = !have_mach || f.reynolds_per_length.len() < n_speed;
    if !atmosphere_given && needs_atmosphere {
        warnings.push(
            "no ALT and no PINF/TINF: computed at sea level in the standard atmosphere (the original assumes a speed of sound of 1000 ft/s and Re = 5E6 per length)"
                .to_string(),
        );
        atmosphere_given = true;
    }
    let n_alt_values = f
        .altitude
        .len()
        .max(f.pressure.len().min(f.temperature.len()));
    let mut loop_mode = f.loop_mode;
    if loop_mode != Loop::Together && !atmosphere_given {
        warnings
            .push("LOOP 2 or 3 without atmospheric data: LOOP=1 used, as in the original".into());
        loop_mode = Loop::Together;
    }
    let mut pairs: Vec<(usize, usize)> = Vec::new();
    match loop_mode {
        Loop::Together => {
            let mut n = n_speed;
            if atmosphere_given && f.nalt_given && n_alt_values != n_speed && n_alt_values > 0 {
                n = n_speed.min(n_alt_values);
                warnings.push(format!(
                    "LOOP=1 and NALT ({n_alt_values}) differs from NMACH ({n_speed}): both taken as {n}, as in the original"
                ));
            }
            pairs.extend((0..n).map(|i| (i, i)));
        }
        Loop::AltitudeOuter | Loop::MachOuter => {
            let n_alt = n_alt_values.max(1);
            if n_alt_values == 0 {
                warnings.push(
                    "LOOP 2 or 3 without NALT: one altitude (sea level) used; the original computes nothing"
                        .into(),
                );
            }
            if loop_mode == Loop::AltitudeOuter {
                for k in 0..n_alt {
                    pairs.extend((0..n_speed).map(|i| (i, k)));
                }
            } else {
                for i in 0..n_speed {
                    pairs.extend((0..n_alt).map(|k| (i, k)));
                }
            }
        }
    }
    let mut out = Vec::with_capacity(pairs.len());
    let mut skipped = 0;
    // Speeds of 0 without a Reynolds number given (by Mach index), with their conditions.
    let mut at_rest: Vec<(usize, Vec<usize>)> = Vec::new();
    for (i, k) in pairs {
        let given_pt = match (f.pressure.get(k), f.temperature.get(k)) {
            (Some(p), Some(t)) if have_pt => Some((*p, *t)),
            _ => None,
        };
        let altitude = f.altitude.get(k).copied();
        let (pressure, temperature) = match given_pt {
            Some((p, t)) => (Some(p), Some(t)),
            None if atmosphere_given => {
                let z = altitude.unwrap_or(0.0);
                let s = atmosphere::standard(z);
                if !s.in_range {
                    warnings.push(format!(
                        "condition {} not computed: altitude {z:.1} m is outside the 1962 US Standard Atmosphere (-5 km to 700 km)",
                        out.len() + skipped + 1
                    ));
                    skipped += 1;
                    continue;
                }
                (Some(s.pressure), Some(s.temperature))
            }
            None => (None, None),
        };
        let altitude = if given_pt.is_none() && atmosphere_given {
            Some(altitude.unwrap_or(0.0))
        } else {
            altitude
        };
        let a = temperature.map(speed_of_sound);
        let (mach, velocity) = match (f.mach.get(i), f.velocity.get(i), a) {
            (Some(m), _, Some(a)) => (*m, Some(m * a)),
            (Some(m), v, None) => (*m, v.copied()),
            (None, Some(v), Some(a)) => (v / a, Some(*v)),
            (None, v, _) => {
                // Not reached: a missing Mach number forces the atmosphere above.
                warnings.push(format!("condition {}: no Mach number can be found", i + 1));
                (0.0, v.copied())
            }
        };
        let reynolds = match (f.reynolds_per_length.get(i), pressure, temperature) {
            (Some(r), _, _) => *r,
            (None, Some(p), Some(t)) => reynolds_per_metre(p, t, mach),
            (None, _, _) => 0.0,
        };
        let physical = |v: Option<f64>| v.is_none_or(|x| x.is_finite() && x > 0.0);
        let finite = [Some(mach), altitude, velocity, Some(reynolds)]
            .iter()
            .flatten()
            .all(|x| x.is_finite());
        // An altitude only reported (pressure and temperature given) or a velocity only
        // reported (with a Mach number) is still a flight's: a case edited in code can give
        // any number there (found by fuzzing the library: 1.8e308 printed as inf in feet).
        let reported = altitude.is_none_or(|z| atmosphere::standard(z).in_range)
            && velocity.is_none_or(|v| (0.0..=VELOCITY_LIMIT).contains(&v));
        if !(finite && reported && physical(pressure) && physical(temperature) && mach >= 0.0) {
            // The altitude and velocity said when they are numbers (a velocity from a
            // temperature below zero is not).
            // Pressure and temperature as given, or not given (they are then the altitude's).
            let given = [
                ("altitude", altitude, "m", true),
                ("velocity", velocity, "m/s", true),
                ("pressure", pressure, "Pa", false),
                ("temperature", temperature, "K", false),
            ]
            .into_iter()
            .filter_map(|(name, v, unit, numbers_only)| match v {
                Some(x) if x.is_finite() || !numbers_only => {
                    Some(format!(", {name} {} {unit}", crate::charts::Query(x)))
                }
                _ => None,
            })
            .collect::<String>();
            warnings.push(format!(
                "condition {} not computed: Mach {}{given} give no physical flight condition",
                out.len() + skipped + 1,
                crate::charts::Query(mach)
            ));
            skipped += 1;
            continue;
        }
        if mach == 0.0 && reynolds == 0.0 && f.reynolds_per_length.get(i).is_none() {
            match at_rest.iter_mut().find(|(m, _)| *m == i) {
                Some((_, conditions)) => conditions.push(out.len() + skipped + 1),
                None => at_rest.push((i, vec![out.len() + skipped + 1])),
            }
        }
        out.push(FlightCondition {
            mach,
            altitude,
            velocity,
            pressure,
            temperature,
            reynolds_per_length: reynolds,
            mach_index: i,
            altitude_index: k,
        });
    }
    for (i, conditions) in at_rest {
        // A few named, more counted.
        const NAMED: usize = 4;
        let which = match conditions.as_slice() {
            [one] => format!("condition {one}"),
            few if few.len() <= NAMED => format!(
                "conditions {}",
                few.iter()
                    .map(usize::to_string)
                    .collect::<Vec<_>>()
                    .join(", ")
            ),
            [first, .., last] => format!(
                "{} conditions, the first {first}, the last {last}",
                conditions.len()
            ),
            [] => continue,
        };
        // The speed is the Mach number's, or the velocity's where no Mach number is given.
        let speed = if f.mach.is_empty() { "VINF" } else { "MACH" };
        warnings.push(format!(
            "{speed}({}) = 0 ({which}) gives a Reynolds number of 0 (no speed): the skin friction and the viscous terms cannot be computed, nor what needs them (drag, and most coefficients); give the flight's Mach number, or RNNUB",
            i + 1
        ));
    }
    (out, warnings)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn input() -> FlightInput {
        FlightInput {
            mach: vec![0.158],
            altitude: vec![2000.0 * FT],
            alpha_deg: vec![0.0],
            nalt_given: true,
            ..FlightInput::default()
        }
    }

    /// Half a unit in the last digit of the original's F8.2 velocity column, ft/s.
    const VELOCITY_PRINTED_HALF_UNIT: f64 = 0.005;

    #[test]
    fn mach_beats_velocity() {
        // Navion deck (oracle arktools__Navion_clean): MACH 0.158, VINF 176 ft/s, P and T given;
        // the listing prints VELOCITY 175.17 ft/s.
        let mut f = input();
        f.velocity = vec![176.0 * FT];
        f.pressure = vec![1967.62 * crate::case::units::NEWTONS_PER_POUND / (FT * FT)];
        f.temperature = vec![511.57 * KELVIN_PER_RANKINE];
        let (c, w) = flight_conditions(&f);
        assert!(w.is_empty());
        let v_ft = c[0].velocity.unwrap() / FT;
        // arktools__Navion_clean/for006.dat line 383 prints VELOCITY 175.17.
        assert!((v_ft - 175.17).abs() < VELOCITY_PRINTED_HALF_UNIT, "{v_ft}");
    }

    #[test]
    fn loop_orders() {
        let mut f = input();
        f.mach = vec![0.1, 0.2];
        f.altitude = vec![0.0, 1000.0, 2000.0];
        f.loop_mode = Loop::AltitudeOuter;
        let (c, _) = flight_conditions(&f);
        let idx: Vec<(usize, usize)> = c.iter().map(|c| (c.mach_index, c.altitude_index)).collect();
        assert_eq!(idx, vec![(0, 0), (1, 0), (0, 1), (1, 1), (0, 2), (1, 2)]);
        f.loop_mode = Loop::MachOuter;
        let (c, _) = flight_conditions(&f);
        let idx: Vec<(usize, usize)> = c.iter().map(|c| (c.mach_index, c.altitude_index)).collect();
        assert_eq!(idx, vec![(0, 0), (0, 1), (0, 2), (1, 0), (1, 1), (1, 2)]);
        f.loop_mode = Loop::Together;
        let (c, w) = flight_conditions(&f);
        assert_eq!(c.len(), 2);
        assert_eq!(w.len(), 1, "NALT differs from NMACH");
    }

    #[test]
    fn velocity_without_mach() {
        let mut f = input();
        f.mach.clear();
        f.velocity = vec![100.0];
        let (c, _) = flight_conditions(&f);
        let a = speed_of_sound(c[0].temperature.unwrap());
        assert_eq!(c[0].mach, 100.0 / a);
        assert!(c[0].reynolds_per_length > 0.0);
    }
}
