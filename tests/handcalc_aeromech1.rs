//! Independent recomputation of the AEROMECH I hand calculation
//! (docs/handcalc/aeromech1.md) and a check of the values recorded in
//! tests/reference/aeromech1_handcalc.toml.
//!
//! This test does not use the datcom library: it holds the geometry of
//! namelists/aeromech1.dcm and the chart readings of the written working as
//! named constants and repeats the arithmetic step by step, with the same
//! classical formulas. It guards the reference file against slips of
//! arithmetic or transcription; it says nothing about the tool's results.

use std::f64::consts::PI;

/// Relative tolerance between the recomputed value and the TOML value: the
/// TOML holds the written working's values rounded to four significant
/// figures (at most 0.05 % off), so 0.5 % leaves room for rounding only.
const TOLERANCE: f64 = 0.005;

// Flight condition (docs/handcalc/aeromech1.md §1; deck $FLTCON).
/// Mach number, the deck's second MACH (70 km/h).
const MACH: f64 = 0.0573;
/// Altitude, m: the deck's second ALT.
const ALTITUDE: f64 = 200.0;
/// Weight, N: deck $FLTCON WT (4.5 kg).
const WEIGHT: f64 = 44.13;

// 1962 standard atmosphere below 11 km (§1).
const SEA_LEVEL_TEMPERATURE: f64 = 288.15;
const SEA_LEVEL_PRESSURE: f64 = 101_325.0;
const LAPSE_RATE: f64 = 0.0065;
const GAS_CONSTANT: f64 = 287.052_87;
const GAMMA_AIR: f64 = 1.4;
/// Exponent g0/(R·lapse rate) of the pressure law.
const PRESSURE_EXPONENT: f64 = 5.255_88;
/// Sutherland's law constants (kg/(m s K^0.5) and K).
const SUTHERLAND_C1: f64 = 1.458e-6;
const SUTHERLAND_S: f64 = 110.4;

// Reference values (deck $OPTINS).
const S_REF: f64 = 0.504;
const C_BAR: f64 = 0.2819;
const B_REF: f64 = 1.80;

// Positions (deck $SYNTHS), m from the nose.
const X_CG: f64 = 0.410;
const X_WING: f64 = 0.33;
const Z_WING: f64 = 0.05;
/// Wing incidence, deg (ALIW).
const WING_INCIDENCE_DEG: f64 = -4.0;
const X_HTAIL: f64 = 1.07;
const X_VTAIL: f64 = 1.10;

// Wing (deck $WGPLNF).
const WING_ROOT_CHORD: f64 = 0.32;
const WING_TIP_CHORD: f64 = 0.24;
const WING_SPAN: f64 = 1.80;
/// Dihedral, deg (DHDADI).
const DIHEDRAL_DEG: f64 = 2.0;

// Horizontal tail (deck $HTPLNF).
const HT_ROOT_CHORD: f64 = 0.25;
const HT_TIP_CHORD: f64 = 0.19;
const HT_SPAN: f64 = 0.39;

// Vertical tail (deck $VTPLNF), span from the boom axis.
const VT_ROOT_CHORD: f64 = 0.22;
const VT_TIP_CHORD: f64 = 0.12;
const VT_SPAN: f64 = 0.24;
/// Leading-edge sweep, deg (SAVSI at CHSTAT=0).
const VT_LE_SWEEP_DEG: f64 = 20.0;

// Body (deck $BODY).
const BODY_X: [f64; 11] = [
    0.0, 0.05, 0.12, 0.22, 0.35, 0.55, 0.70, 0.82, 0.92, 1.10, 1.32,
];
const BODY_R: [f64; 11] = [
    0.0, 0.030, 0.048, 0.058, 0.060, 0.060, 0.050, 0.030, 0.018, 0.015, 0.015,
];
/// Largest pod diameter (height and width), m.
const BODY_DIAMETER: f64 = 0.12;
/// Boom radius at the tails, m.
const BOOM_RADIUS: f64 = 0.015;

// Assumptions of the hand calculation (§0).
/// Section lift-curve slope, per degree, for E423 and NACA 0012 alike.
const SECTION_SLOPE_PER_DEG: f64 = 0.1;
/// Horizontal tail dynamic-pressure ratio.
const ETA_H: f64 = 0.9;
/// Factor on the tail's pitch damping for the wing and body (Nelson).
const CMQ_WING_BODY_FACTOR: f64 = 1.1;
/// Section thickness ratio and its position (E423), for the form factor.
const WING_THICKNESS: f64 = 0.125;
const WING_THICKNESS_POSITION: f64 = 0.24;
/// Wetted area over planform area of a 12.5 % section.
const WETTED_FACTOR: f64 = 1.02;

// Chart readings (§2, §3), as written in the working.
/// k2 - k1 at fineness ratio 11 (DATCOM figure 4.2.1.1-20): 0.94 at 10, 0.955 at 12.
const K2_MINUS_K1: f64 = 0.9475;
/// K_i at z_w/(d/2) = -0.93, high wing (DATCOM figure 5.2.1.1-7).
const K_I: f64 = 1.79;
/// A_v(B)/A_v at b_v/2r1 = 8, taper 0.6 curve (DATCOM figure 5.3.1.1-22a).
const AV_B_OVER_AV: f64 = 1.02;
/// A_v(HB)/A_v(B), tail at the fin root, x/c_v at or below 0.5 (figure 5.3.1.1-22b).
const AV_HB_OVER_AV_B: f64 = 1.05;
/// K_H at S_H/S_v = 2.10 (figure 5.3.1.1-22c, end of the curve).
const K_H_FIN: f64 = 1.13;
/// k at b_v/2r1 = 8 (figure 5.3.1.1-22d).
const K_FIN: f64 = 1.0;
/// Cnr/CD0 at A = 6.43, no sweep, xbar/c = 0 (DATCOM figure 7.1.3.3-7).
const CNR_PER_CD0: f64 = -0.293;

/// Relative difference check with a message naming the derivative.
fn check(name: &str, computed: f64, reference: f64) {
    let relative = ((computed - reference) / reference).abs();
    assert!(
        relative <= TOLERANCE,
        "{name}: recomputed {computed:.6} vs TOML {reference:.6} ({:.3} %)",
        100.0 * relative
    );
}

/// Lift-curve slope per radian, DATCOM 4.1.3.2 (Helmbold-Polhamus form).
fn lift_slope(aspect_ratio: f64, tan_half_chord: f64, beta: f64, kappa: f64) -> f64 {
    let root = (aspect_ratio * aspect_ratio * beta * beta / (kappa * kappa)
        * (1.0 + tan_half_chord * tan_half_chord / (beta * beta))
        + 4.0)
        .sqrt();
    2.0 * PI * aspect_ratio / (2.0 + root)
}

/// Linear interpolation in a table with ascending abscissae.
fn interpolate(x: f64, xs: &[f64], ys: &[f64]) -> f64 {
    let i = xs
        .windows(2)
        .position(|w| w[0] <= x && x <= w[1])
        .expect("inside the table");
    ys[i] + (ys[i + 1] - ys[i]) * (x - xs[i]) / (xs[i + 1] - xs[i])
}

/// The 14 derivatives, per radian, in the order of the TOML.
fn hand_values() -> Vec<(&'static str, f64)> {
    // §1 Flight condition.
    let temperature = SEA_LEVEL_TEMPERATURE - LAPSE_RATE * ALTITUDE;
    let sound = (GAMMA_AIR * GAS_CONSTANT * temperature).sqrt();
    let velocity = MACH * sound;
    let pressure =
        SEA_LEVEL_PRESSURE * (temperature / SEA_LEVEL_TEMPERATURE).powf(PRESSURE_EXPONENT);
    let density = pressure / (GAS_CONSTANT * temperature);
    let viscosity = SUTHERLAND_C1 * temperature.powf(1.5) / (temperature + SUTHERLAND_S);
    let reynolds_per_m = density * velocity / viscosity;
    let dynamic_pressure = 0.5 * density * velocity * velocity;
    let beta = (1.0 - MACH * MACH).sqrt();
    let cl0 = WEIGHT / (dynamic_pressure * S_REF);

    // §0 Geometry.
    let taper = WING_TIP_CHORD / WING_ROOT_CHORD;
    let aspect = WING_SPAN * WING_SPAN / S_REF;
    let tan_half = -(4.0 / aspect) * 0.25 * (1.0 - taper) / (1.0 + taper);
    let kappa = SECTION_SLOPE_PER_DEG.to_degrees() / (2.0 * PI);
    let ht_taper = HT_TIP_CHORD / HT_ROOT_CHORD;
    let ht_area = HT_SPAN * (HT_ROOT_CHORD + HT_TIP_CHORD) / 2.0;
    let ht_aspect = HT_SPAN * HT_SPAN / ht_area;
    let ht_tan_half = -(4.0 / ht_aspect) * 0.25 * (1.0 - ht_taper) / (1.0 + ht_taper);
    let wing_quarter = X_WING + 0.25 * WING_ROOT_CHORD;
    let ht_quarter = X_HTAIL + 0.25 * HT_ROOT_CHORD;
    let tail_arm = ht_quarter - X_CG;
    let tail_volume = ht_area * tail_arm / (S_REF * C_BAR);

    // §2.1 CLα.
    let cla_w = lift_slope(aspect, tan_half, beta, kappa);
    let cla_w0 = lift_slope(aspect, tan_half, 1.0, kappa);
    let d_over_b = BODY_DIAMETER / WING_SPAN;
    let k_wb = 1.0 + 0.025 * d_over_b - 0.25 * d_over_b * d_over_b;
    let cla_wb = k_wb * cla_w;
    let cla_h = lift_slope(ht_aspect, ht_tan_half, beta, kappa);
    let k_a = 1.0 / aspect - 1.0 / (1.0 + aspect.powf(1.7));
    let k_lambda = (10.0 - 3.0 * taper) / 7.0;
    let tail_height = Z_WING;
    let k_h =
        (1.0 - tail_height / WING_SPAN) / (2.0 * (ht_quarter - wing_quarter) / WING_SPAN).cbrt();
    let downwash = 4.44 * (k_a * k_lambda * k_h).powf(1.19) * cla_w / cla_w0;
    let cla = cla_wb + ETA_H * ht_area / S_REF * cla_h * (1.0 - downwash);

    // §2.2 Cmα (c.g. on the wing's aerodynamic centre: no wing term).
    let volume: f64 = (0..BODY_X.len() - 1)
        .map(|i| {
            let (r1, r2) = (BODY_R[i], BODY_R[i + 1]);
            PI * (BODY_X[i + 1] - BODY_X[i]) * (r1 * r1 + r1 * r2 + r2 * r2) / 3.0
        })
        .sum();
    let body_length = BODY_X[BODY_X.len() - 1];
    let base_area = PI * BOOM_RADIUS * BOOM_RADIUS;
    let cma_body =
        2.0 * K2_MINUS_K1 * (volume - base_area * (body_length - X_CG)) / (S_REF * C_BAR);
    let cma_tail = -ETA_H * tail_volume * cla_h * (1.0 - downwash);
    let cma = cma_body + cma_tail;

    // §2.3 CYβ.
    let dihedral = DIHEDRAL_DEG.to_radians();
    let cyb_wing = -0.0001 * DIHEDRAL_DEG * 1.0_f64.to_degrees();
    let (i1, _) = (0..BODY_X.len() - 1)
        .map(|i| {
            let s1 = PI * BODY_R[i] * BODY_R[i];
            let s2 = PI * BODY_R[i + 1] * BODY_R[i + 1];
            (i, (s2 - s1) / (BODY_X[i + 1] - BODY_X[i]))
        })
        .fold(
            (0, f64::MAX),
            |best, item| if item.1 < best.1 { item } else { best },
        );
    let x1 = 0.5 * (BODY_X[i1] + BODY_X[i1 + 1]);
    let x0 = body_length * (0.378 + 0.527 * x1 / body_length);
    let r0 = interpolate(x0, &BODY_X, &BODY_R);
    let cla_body = 2.0 * K2_MINUS_K1 * PI * r0 * r0 / S_REF;
    let cyb_body = -K_I * cla_body;
    let z_w = -(Z_WING - 0.25 * WING_ROOT_CHORD * WING_INCIDENCE_DEG.to_radians().sin());
    let vt_taper = VT_TIP_CHORD / VT_ROOT_CHORD;
    let vt_area = VT_SPAN * (VT_ROOT_CHORD + VT_TIP_CHORD) / 2.0;
    let vt_aspect = VT_SPAN * VT_SPAN / vt_area;
    let vt_tan_le = VT_LE_SWEEP_DEG.to_radians().tan();
    let vt_tan_half =
        vt_tan_le - 4.0 / (2.0 * vt_aspect) * 0.5 * (1.0 - vt_taper) / (1.0 + vt_taper);
    let effective_aspect = AV_B_OVER_AV * vt_aspect * (1.0 + K_H_FIN * (AV_HB_OVER_AV_B - 1.0));
    let cla_v = lift_slope(effective_aspect, vt_tan_half, beta, kappa);
    let sidewash =
        0.724 + 3.06 * (vt_area / S_REF) / 2.0 + 0.4 * z_w / BODY_DIAMETER + 0.009 * aspect;
    let cyb_v = -K_FIN * cla_v * sidewash * vt_area / S_REF;
    let cyb = cyb_wing + cyb_body + cyb_v;

    // §2.4 Cnβ.
    let vt_mac_height = VT_SPAN / 3.0 * (1.0 + 2.0 * vt_taper) / (1.0 + vt_taper);
    let vt_mac =
        2.0 / 3.0 * VT_ROOT_CHORD * (1.0 + vt_taper + vt_taper * vt_taper) / (1.0 + vt_taper);
    let l_v = X_VTAIL + vt_mac_height * vt_tan_le + 0.25 * vt_mac - X_CG;
    let z_v = vt_mac_height;
    let cnb_wing = cl0 * cl0 / (4.0 * PI * aspect);
    let side_area: f64 = (0..BODY_X.len() - 1)
        .map(|i| (BODY_X[i + 1] - BODY_X[i]) * (BODY_R[i] + BODY_R[i + 1]))
        .sum();
    let xm = X_CG / body_length;
    let step_a_20 = 0.1 + (1.88 - 0.1) * (xm - 0.2) / 0.6;
    let step_a_14 = 0.4 + (2.21 - 0.4) * (xm - 0.2) / 0.6;
    let step_a =
        step_a_20 + (step_a_14 - step_a_20) * (20.0 - body_length * body_length / side_area) / 6.0;
    let h1 = 2.0 * interpolate(0.25 * body_length, &BODY_X, &BODY_R);
    let h2 = 2.0 * interpolate(0.75 * body_length, &BODY_X, &BODY_R);
    let step_b_14 = step_a * 4.18 / 3.0;
    let step_b_16 = step_a * 4.79 / 3.0;
    let step_b = step_b_16 + (step_b_16 - step_b_14) * ((h1 / h2).sqrt() - 1.6) / 0.2;
    let k_n = -0.00048 + (0.00559 + 0.00048) * step_b / 6.0;
    let k_rl = 1.0 + (reynolds_per_m * body_length / 1e6).ln() / 4.86;
    let cnb_body =
        -k_n * k_rl * (side_area / S_REF) * (body_length / WING_SPAN) * 1.0_f64.to_degrees();
    let cnb_v = -cyb_v * l_v / B_REF;
    let cnb = cnb_wing + cnb_body + cnb_v;

    // §2.5 Clβ.
    let clb_dihedral = -cla_w * dihedral / 6.0 * (1.0 + 2.0 * taper) / (1.0 + taper);
    let clb_position = 1.2 * aspect.sqrt() * (z_w / WING_SPAN) * (2.0 * BODY_DIAMETER / WING_SPAN);
    let clb_v = cyb_v * z_v / B_REF;
    let clb = clb_dihedral + clb_position + clb_v;

    // §3.1-3.4 Pitch rate and α̇ (c.g. on the wing's aerodynamic centre).
    let clq = 0.5 * cla_w + 2.0 * cla_h * ETA_H * tail_volume;
    let cmq = -2.0 * CMQ_WING_BODY_FACTOR * cla_h * ETA_H * tail_volume * tail_arm / C_BAR;
    let clad = 2.0 * cla_h * ETA_H * tail_volume * downwash;
    let cmad = -2.0 * cla_h * ETA_H * tail_volume * tail_arm / C_BAR * downwash;

    // §3.5 Clp.
    let clp_w = -cla_w / 12.0 * (1.0 + 3.0 * taper) / (1.0 + taper);
    let clp_h_own = -cla_h / 12.0 * (1.0 + 3.0 * ht_taper) / (1.0 + ht_taper);
    let clp_h = 0.5 * clp_h_own * (ht_area / S_REF) * (HT_SPAN / B_REF).powi(2);
    let clp_v = 2.0 * cyb_v * (z_v / B_REF).powi(2);
    let clp = clp_w + clp_h + clp_v;

    // §3.6 CYp, §3.7 Cnp.
    let cyp = 3.0 * dihedral.sin() * clp_w + 2.0 * cyb_v * z_v / B_REF;
    let fin_cross = -2.0 * l_v * z_v / (B_REF * B_REF) * cyb_v;
    let cnp = -cl0 / 8.0 + fin_cross;

    // §3.8 Cnr.
    let root_exposed = WING_ROOT_CHORD
        - (WING_ROOT_CHORD - WING_TIP_CHORD) * (BODY_DIAMETER / 2.0) / (WING_SPAN / 2.0);
    let taper_exposed = WING_TIP_CHORD / root_exposed;
    let reynolds_mac = reynolds_per_m * C_BAR;
    let friction = 0.455 / reynolds_mac.log10().powf(2.58);
    let form_factor =
        1.0 + 0.6 / WING_THICKNESS_POSITION * WING_THICKNESS + 100.0 * WING_THICKNESS.powi(4);
    let exposed_area = (WING_SPAN / 2.0 - BODY_DIAMETER / 2.0) * (root_exposed + WING_TIP_CHORD);
    let cd0_w = friction * form_factor * 2.0 * WETTED_FACTOR * exposed_area / S_REF;
    let step = interpolate(aspect, &[5.99, 6.98], &[2.01, 2.06]);
    let at_taper_0 = -0.11 + 0.21 * step / 4.0;
    let at_taper_1 = -0.127 + 0.21 * step / 4.0;
    let cnr_per_cl2 = at_taper_0 + (at_taper_1 - at_taper_0) * taper_exposed;
    let cnr_w = cnr_per_cl2 * cl0 * cl0 + CNR_PER_CD0 * cd0_w;
    let cnr_v = 2.0 * (l_v / B_REF).powi(2) * cyb_v;
    let cnr = cnr_w + cnr_v;

    // §3.9 Clr.
    let clr = cl0 / 4.0 + fin_cross;

    vec![
        ("CLA", cla),
        ("CMA", cma),
        ("CYB", cyb),
        ("CNB", cnb),
        ("CLB", clb),
        ("CLQ", clq),
        ("CMQ", cmq),
        ("CLAD", clad),
        ("CMAD", cmad),
        ("CLP", clp),
        ("CYP", cyp),
        ("CNP", cnp),
        ("CNR", cnr),
        ("CLR", clr),
    ]
}

fn reference() -> toml::Value {
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/tests/reference/aeromech1_handcalc.toml"
    );
    let text = std::fs::read_to_string(path).expect("reference file");
    toml::from_str(&text).expect("valid TOML")
}

#[test]
fn reference_file_names_the_deck_and_condition() {
    let r = reference();
    assert_eq!(r["aircraft"].as_str(), Some("AEROMECH I"));
    let deck = r["deck"].as_str().expect("deck");
    let deck_path = format!("{}/{deck}", env!("CARGO_MANIFEST_DIR"));
    let deck_text = std::fs::read_to_string(deck_path).expect("the deck exists");
    let condition = &r["condition"];
    let mach = condition["mach"].as_float().expect("mach");
    assert!((mach - MACH).abs() < 1e-12);
    assert!(deck_text.contains("MACH(1)=0.0450,0.0573,0.0695"));
    let altitude = condition["altitude_m"].as_float().expect("altitude");
    assert!((altitude - ALTITUDE).abs() < 1e-12);
    assert!(deck_text.contains("ALT(1)=100.0,200.0,300.0"));
    assert_eq!(condition["alpha_deg"].as_float(), Some(0.0));
}

#[test]
fn hand_calculation_matches_the_reference_values() {
    let r = reference();
    let values = r["values"].as_array().expect("values");
    let computed = hand_values();
    assert_eq!(values.len(), computed.len());
    for (entry, (name, value)) in values.iter().zip(computed) {
        assert_eq!(entry["name"].as_str(), Some(name));
        assert_eq!(entry["unit"].as_str(), Some("per_rad"));
        let reference = entry["value"].as_float().expect("value");
        check(name, value, reference);
    }
}
