//! US Standard Atmosphere 1962, as Digital DATCOM evaluates it.
//!
//! Below 295 276 ft (90 km geometric) temperature is linear in geopotential altitude
//! H = R0·Z/(R0 + Z) within each layer, and pressure follows the hydrostatic equation for a
//! constant molecular weight: P = Pb·(Tb/T)^(g0·M0/(R*·L)) in gradient layers and
//! P = Pb·exp(−g0·M0·(H − Hb)/(R*·T)) in isothermal ones. Above, molecular-scale temperature
//! is linear in geometric altitude, molecular weight varies linearly, and the hydrostatic
//! equation is integrated with inverse-square gravity.
//!
//! The layer tables are the standard's, in the customary units in which Digital DATCOM holds
//! them (feet, degrees Rankine, pounds per square foot; routine ATMOS); the public functions take
//! and return SI. Valid from −16 404 ft (−5 km) to 2 296 588 ft (700 km); beyond, the end
//! layers are extrapolated and [`standard`] says so.

use crate::case::units::{KELVIN_PER_RANKINE, NEWTONS_PER_POUND};

const FT: f64 = 0.3048;
/// Earth radius, ft.
const R0: f64 = 20_890_855.0;
/// g0·M0/R*, °R per ft.
const GMRS: f64 = 0.018_743_418;
/// Sea-level molecular weight.
const WM0: f64 = 28.9644;
/// Layer bases in geopotential altitude, ft. The ninth is 79 km = 259 186 ft; the original
/// program's table has 250 186 (a transposed digit), which puts its atmosphere between 61 and
/// 88.7 km off the standard (docs/differences.md).
const HG: [f64; 10] = [
    -16404.0, 0.0, 36089.0, 65617.0, 104987.0, 154199.0, 170604.0, 200131.0, 259186.0, 291160.0,
];
/// Layer bases in geometric altitude above 90 km, ft.
const ZM: [f64; 14] = [
    295276.0, 328084.0, 360892.0, 393701.0, 492126.0, 524934.0, 557743.0, 623360.0, 754593.0,
    984252.0, 1312336.0, 1640420.0, 1968504.0, 2296588.0,
];
/// Molecular weight at the ZM bases.
const WM: [f64; 14] = [
    28.9644, 28.88, 28.56, 28.07, 26.92, 26.66, 26.4, 25.85, 24.7, 22.66, 19.94, 17.94, 16.84,
    16.17,
];
/// Molecular-scale temperature at the bases, °R: 1..10 at HG, 10..23 at ZM.
const TM: [f64; 23] = [
    577.17, 518.67, 389.97, 389.97, 411.57, 487.17, 487.17, 454.77, 325.17, 325.17, 379.17, 469.17,
    649.17, 1729.17, 1999.17, 2179.17, 2431.17, 2791.17, 3295.17, 3889.17, 4357.17, 4663.17,
    4861.17,
];
/// Pressure at the bases, lb/ft².
const PM: [f64; 22] = [
    3711.0839,
    2116.2165,
    472.67563,
    114.34314,
    18.128355,
    2.3162178,
    1.2321972,
    0.38030279,
    2.1671352E-2,
    3.4313478E-3,
    6.2773411E-4,
    1.5349091E-4,
    5.2624212E-5,
    1.0561806E-5,
    7.7083076E-6,
    5.8267151E-6,
    3.5159854E-6,
    1.4520255E-6,
    3.9290563E-7,
    8.4030242E-8,
    2.2835256E-8,
    7.1875452E-9,
];

/// Temperature and pressure of the standard atmosphere.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct State {
    /// Static temperature, K.
    pub temperature: f64,
    /// Static pressure, Pa.
    pub pressure: f64,
    /// False when the altitude is outside the standard's tables (end layers extrapolated).
    pub in_range: bool,
}

/// (°R, lb/ft²) at geometric altitude `z` ft.
fn customary(z: f64) -> (f64, f64) {
    if z <= ZM[0] {
        let h = R0 * z / (R0 + z);
        let j = (1..HG.len()).find(|&i| HG[i] >= h).map_or(8, |i| i - 1);
        let lapse = (TM[j + 1] - TM[j]) / (HG[j + 1] - HG[j]);
        let t = TM[j] + lapse * (h - HG[j]);
        let p = if lapse != 0.0 {
            PM[j] * (TM[j] / t).powf(GMRS / lapse)
        } else {
            PM[j] * (GMRS * (HG[j] - h) / t).exp()
        };
        (t, p)
    } else {
        let k = (1..ZM.len()).find(|&i| ZM[i] >= z).map_or(12, |i| i - 1);
        let j = k + 9;
        let lapse = (TM[j + 1] - TM[j]) / (ZM[k + 1] - ZM[k]);
        let tms = TM[j] + lapse * (z - ZM[k]);
        let wm = WM[k] + (WM[k + 1] - WM[k]) / (ZM[k + 1] - ZM[k]) * (z - ZM[k]);
        let zlz = z - tms / lapse;
        let exponent = GMRS / lapse
            * (R0 / (R0 + zlz)).powi(2)
            * ((z - ZM[k]) * (R0 + zlz) / (R0 + z) / (R0 + ZM[k])
                - (tms * (R0 + ZM[k]) / TM[j] / (R0 + z)).ln());
        (wm * tms / WM0, PM[j] * exponent.exp())
    }
}

/// The standard atmosphere at geometric altitude `altitude` (m).
pub fn standard(altitude: f64) -> State {
    let z = altitude / FT;
    let (t, p) = customary(z);
    State {
        temperature: t * KELVIN_PER_RANKINE,
        pressure: p * NEWTONS_PER_POUND / (FT * FT),
        in_range: (HG[0]..=ZM[ZM.len() - 1]).contains(&z),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Half a unit in the last digit of the original's F9.3 temperature column, °R.
    const TEMPERATURE_PRINTED_HALF_UNIT: f64 = 0.0005;

    /// Values printed by Digital DATCOM in FLIGHT CONDITIONS rows (`../shared/oracle`):
    /// (altitude ft, temperature °R as printed F9.3, pressure psf as printed 1PE10.4).
    #[test]
    fn printed_values_of_the_original() {
        let cases = [
            // YANG-DEMIN__myself_Citation_myself_clean/for006.dat line 478
            (0.0, 518.670, 2.1162e3),
            // arktools__sprob/for006.dat line 986
            (2000.0, 511.538, 1.9677e3),
            // arktools__sprob/for006.dat line 1099
            (40000.0, 389.970, 3.9312e2),
            // arktools__canard_clean/for006.dat line 252
            (90000.0, 403.136, 3.6777e1),
        ];
        for (z, t_r, p_psf) in cases {
            let (t, p) = customary(z);
            assert!((t - t_r).abs() <= TEMPERATURE_PRINTED_HALF_UNIT, "{z}: {t}");
            let half_unit = 0.5 * 10f64.powi(f64::log10(p_psf).floor() as i32 - 4);
            assert!((p - p_psf).abs() <= half_unit, "{z}: {p}");
        }
    }

    /// Each layer, integrated from its base, must reach the next base's tabulated pressure:
    /// this catches a wrong base altitude (as in the original's table) or a wrong pressure.
    /// Relative agreement of a layer's integrated top pressure with the next base's tabulated
    /// value: the table gives five or six significant digits.
    const LAYER_PRESSURE_REL: f64 = 2e-4;
    /// The 90 km junction of the two models (geopotential below, geometric above) matches to
    /// the third digit in the standard's own tables.
    const JUNCTION_REL: f64 = 2e-3;

    #[test]
    fn layers_are_continuous() {
        for j in 1..HG.len() - 1 {
            let z_top = HG[j + 1] * R0 / (R0 - HG[j + 1]);
            let (_, p) = customary(z_top - 1e-6);
            assert!(
                (p / PM[j + 1] - 1.0).abs() < LAYER_PRESSURE_REL,
                "layer {j}: {p} vs {}",
                PM[j + 1]
            );
        }
        let (_, below) = customary(ZM[0] - 1e-6);
        let (_, above) = customary(ZM[0] + 1e-6);
        assert!(
            (below / above - 1.0).abs() < JUNCTION_REL,
            "90 km: {below} vs {above}"
        );
    }

    #[test]
    fn sea_level_si() {
        // 518.67 °R and 2116.2165 psf are 288.15 K and 101 325.7 Pa (the table's sea-level
        // pressure is rounded to 0.0001 psf, 0.005 Pa).
        let s = standard(0.0);
        assert!((s.temperature - 288.15).abs() < 1e-9);
        assert!((s.pressure - 101_325.7).abs() < 0.05);
        assert!(s.in_range);
        assert!(!standard(1.0e6).in_range);
    }

    #[test]
    fn pressure_falls_with_altitude() {
        let mut last = f64::INFINITY;
        for k in -5..700 {
            let s = standard(f64::from(k) * 1000.0);
            assert!(s.pressure < last && s.pressure > 0.0, "{k} km");
            assert!(s.temperature > 0.0);
            last = s.pressure;
        }
    }
}
