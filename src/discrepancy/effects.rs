//! The effect catalogue: named physical causes of a gap between a DATCOM prediction and a
//! measurement, each a parametric change of the predicted coefficients (docs/discrepancy.md).
//!
//! Effects are applied in a fixed order so that a model of several is well defined: first
//! what changes the lift curve (zero_lift_shift, lift_slope_scale, tail_efficiency,
//! stall_onset), then drag (parasite_drag, induced_drag_factor, on the changed CL) and moment
//! (cm0_offset, moment_reference_shift, on the changed CL).

use serde::Serialize;

/// A predicted coefficient set at one angle of attack.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Coefficients {
    pub cl: f64,
    pub cd: f64,
    pub cm: f64,
}

/// The prediction as curves against angle of attack (degrees), sorted by angle: CL, CD, Cm,
/// and, where the prediction knows them, the horizontal tail's contributions to CL and Cm
/// (the configuration with the tail less the one without).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Prediction {
    pub alpha_deg: Vec<f64>,
    pub cl: Vec<f64>,
    pub cd: Vec<f64>,
    pub cm: Vec<f64>,
    pub tail_cl: Option<Vec<f64>>,
    pub tail_cm: Option<Vec<f64>>,
}

/// Linear interpolation in `y(x)` (x increasing); linear extrapolation on the end segments
/// when `extrapolate`, else none outside.
pub fn interpolate(x: &[f64], y: &[f64], at: f64, extrapolate: bool) -> Option<f64> {
    let n = x.len().min(y.len());
    if n == 0 {
        return None;
    }
    if n == 1 {
        return (at == x[0]).then_some(y[0]);
    }
    if !extrapolate && (at < x[0] || at > x[n - 1]) {
        return None;
    }
    let k = match x[..n].iter().position(|v| *v >= at) {
        Some(0) => 0,
        Some(k) => k - 1,
        None => n - 2,
    };
    let t = (at - x[k]) / (x[k + 1] - x[k]);
    let v = y[k] + t * (y[k + 1] - y[k]);
    v.is_finite().then_some(v)
}

impl Prediction {
    /// CL, CD, Cm at `alpha_deg`; none outside the predicted angles.
    pub fn at(&self, alpha_deg: f64) -> Option<Coefficients> {
        let a = &self.alpha_deg;
        Some(Coefficients {
            cl: interpolate(a, &self.cl, alpha_deg, false)?,
            cd: interpolate(a, &self.cd, alpha_deg, false)?,
            cm: interpolate(a, &self.cm, alpha_deg, false)?,
        })
    }

    /// The checks a prediction must pass: at least two angles, increasing, every column as
    /// long as the angles, every number finite.
    pub fn validate(&self) -> Result<(), String> {
        let n = self.alpha_deg.len();
        if n < 2 {
            return Err(format!(
                "the prediction has {n} angle(s); at least 2 are needed"
            ));
        }
        if self.alpha_deg.windows(2).any(|w| w[1] <= w[0]) {
            return Err("the prediction's angles of attack must increase".into());
        }
        let columns = [
            ("CL", Some(&self.cl)),
            ("CD", Some(&self.cd)),
            ("Cm", Some(&self.cm)),
            ("CL_tail", self.tail_cl.as_ref()),
            ("Cm_tail", self.tail_cm.as_ref()),
        ];
        for (name, c) in columns {
            let Some(c) = c else { continue };
            if c.len() != n {
                return Err(format!(
                    "prediction column {name} has {} values for {n} angles",
                    c.len()
                ));
            }
            if let Some(k) = c.iter().position(|v| !v.is_finite()) {
                return Err(format!(
                    "prediction column {name} is not finite at alpha {} deg",
                    self.alpha_deg[k]
                ));
            }
        }
        Ok(())
    }
}

/// An effect of the catalogue.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum EffectId {
    ParasiteDrag,
    InducedDragFactor,
    LiftSlopeScale,
    ZeroLiftShift,
    Cm0Offset,
    MomentReferenceShift,
    StallOnset,
    TailEfficiency,
}

/// Which coefficient an effect changes.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub enum Coefficient {
    CL,
    CD,
    Cm,
}

impl EffectId {
    /// Every effect, in the catalogue's order.
    pub const ALL: [EffectId; 8] = [
        EffectId::ParasiteDrag,
        EffectId::InducedDragFactor,
        EffectId::LiftSlopeScale,
        EffectId::ZeroLiftShift,
        EffectId::Cm0Offset,
        EffectId::MomentReferenceShift,
        EffectId::StallOnset,
        EffectId::TailEfficiency,
    ];

    /// The id as written in reports.
    pub fn name(self) -> &'static str {
        match self {
            EffectId::ParasiteDrag => "parasite_drag",
            EffectId::InducedDragFactor => "induced_drag_factor",
            EffectId::LiftSlopeScale => "lift_slope_scale",
            EffectId::ZeroLiftShift => "zero_lift_shift",
            EffectId::Cm0Offset => "cm0_offset",
            EffectId::MomentReferenceShift => "moment_reference_shift",
            EffectId::StallOnset => "stall_onset",
            EffectId::TailEfficiency => "tail_efficiency",
        }
    }

    /// Parameter names (units in the name).
    pub fn parameters(self) -> &'static [&'static str] {
        match self {
            EffectId::ParasiteDrag => &["dCD0"],
            EffectId::InducedDragFactor => &["dK"],
            EffectId::LiftSlopeScale => &["s"],
            EffectId::ZeroLiftShift => &["dalpha0_deg"],
            EffectId::Cm0Offset => &["dCm0"],
            EffectId::MomentReferenceShift => &["dx_chords"],
            EffectId::StallOnset => &["alpha_onset_deg", "dCL_per_deg2", "dCm_per_deg2"],
            EffectId::TailEfficiency => &["eta_ratio"],
        }
    }

    /// The parameters' values that leave the prediction unchanged.
    pub fn nominal(self) -> Vec<f64> {
        match self {
            EffectId::LiftSlopeScale | EffectId::TailEfficiency => vec![1.0],
            EffectId::StallOnset => vec![90.0, 0.0, 0.0],
            _ => vec![0.0; self.parameters().len()],
        }
    }

    /// The parameters' typical sizes (finite-difference steps of the fit).
    pub fn scales(self) -> Vec<f64> {
        match self {
            EffectId::ParasiteDrag => vec![0.01],
            EffectId::InducedDragFactor => vec![0.01],
            EffectId::LiftSlopeScale | EffectId::TailEfficiency => vec![1.0],
            EffectId::ZeroLiftShift => vec![1.0],
            EffectId::Cm0Offset => vec![0.01],
            EffectId::MomentReferenceShift => vec![0.01],
            EffectId::StallOnset => vec![1.0, 0.001, 0.001],
        }
    }

    /// The coefficients the effect changes.
    pub fn touches(self) -> &'static [Coefficient] {
        match self {
            EffectId::ParasiteDrag | EffectId::InducedDragFactor => &[Coefficient::CD],
            EffectId::LiftSlopeScale | EffectId::ZeroLiftShift => &[Coefficient::CL],
            EffectId::Cm0Offset | EffectId::MomentReferenceShift => &[Coefficient::Cm],
            EffectId::StallOnset | EffectId::TailEfficiency => &[Coefficient::CL, Coefficient::Cm],
        }
    }

    /// What the effect is and why DATCOM can miss it.
    pub fn description(self) -> &'static str {
        match self {
            EffectId::ParasiteDrag => "CD += dCD0: protuberances, a blunt fuselage, landing gear, cooling and leakage drag; DATCOM's zero-lift drag counts skin friction and form of clean components only",
            EffectId::InducedDragFactor => "CD += dK·CL²: a different span efficiency (low Reynolds number, separation, interference); DATCOM's drag due to lift assumes attached flow",
            EffectId::LiftSlopeScale => "CL scaled by s about its zero-lift angle: low Reynolds number section slope, aeroelastic washout, wall effects; DATCOM's slopes are for Reynolds numbers of full-size aircraft",
            EffectId::ZeroLiftShift => "lift curve shifted by dalpha0 (CL(α) → CL(α − dα0)): wing incidence, section camber, a rig or flow-angle offset of the measurement",
            EffectId::Cm0Offset => "Cm += dCm0: camber, fuselage and tail-incidence moments the section data do not capture",
            EffectId::MomentReferenceShift => "Cm += dx·CL (dx in reference chords, positive aft): the c.g. or the balance centre differs from the deck's moment reference",
            EffectId::StallOnset => "lift and moment depart from the linear curves from alpha_onset: CL −= dCL·(α − α_on)², Cm += dCm·(α − α_on)² above it; earlier stall (low Reynolds number, roughness) than DATCOM's CLmax method gives",
            EffectId::TailEfficiency => "the horizontal tail's CL and Cm contributions scaled by eta_ratio: dynamic-pressure ratio at the tail, propeller slipstream, fuselage blanking",
        }
    }
}

/// The prediction with `effects` (each with its parameters) applied, at `alpha_deg`. None
/// outside the prediction's angles, or for the tail effect when the prediction has no tail
/// contributions.
pub fn apply(
    prediction: &Prediction,
    effects: &[(EffectId, &[f64])],
    alpha_deg: f64,
) -> Option<Coefficients> {
    let base = prediction.at(alpha_deg)?;
    let find = |id: EffectId| effects.iter().find(|(e, _)| *e == id).map(|(_, p)| *p);
    let (mut cl, mut cd, mut cm) = (base.cl, base.cd, base.cm);
    if let Some(p) = find(EffectId::ZeroLiftShift) {
        // The lift curve read dα0 earlier, extrapolated past its ends.
        cl = interpolate(
            &prediction.alpha_deg,
            &prediction.cl,
            alpha_deg - p[0],
            true,
        )?;
    }
    if let Some(p) = find(EffectId::LiftSlopeScale) {
        cl *= p[0];
    }
    if let Some(p) = find(EffectId::TailEfficiency) {
        let a = &prediction.alpha_deg;
        let tcl = interpolate(a, prediction.tail_cl.as_ref()?, alpha_deg, false)?;
        let tcm = interpolate(a, prediction.tail_cm.as_ref()?, alpha_deg, false)?;
        cl += (p[0] - 1.0) * tcl;
        cm += (p[0] - 1.0) * tcm;
    }
    if let Some(p) = find(EffectId::StallOnset) {
        let past = (alpha_deg - p[0]).max(0.0);
        cl -= p[1] * past * past;
        cm += p[2] * past * past;
    }
    if let Some(p) = find(EffectId::ParasiteDrag) {
        cd += p[0];
    }
    if let Some(p) = find(EffectId::InducedDragFactor) {
        cd += p[0] * cl * cl;
    }
    if let Some(p) = find(EffectId::Cm0Offset) {
        cm += p[0];
    }
    if let Some(p) = find(EffectId::MomentReferenceShift) {
        cm += p[0] * cl;
    }
    [cl, cd, cm]
        .iter()
        .all(|v| v.is_finite())
        .then_some(Coefficients { cl, cd, cm })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn linear() -> Prediction {
        let alpha: Vec<f64> = (-4..=12).map(f64::from).collect();
        Prediction {
            cl: alpha.iter().map(|a| 0.1 * (a + 2.0)).collect(),
            cd: alpha.iter().map(|a| 0.02 + 0.001 * a * a).collect(),
            cm: alpha.iter().map(|a| -0.01 * a).collect(),
            tail_cl: Some(alpha.iter().map(|a| 0.01 * a).collect()),
            tail_cm: Some(alpha.iter().map(|a| -0.03 * a).collect()),
            alpha_deg: alpha,
        }
    }

    #[test]
    fn nominal_parameters_leave_the_prediction_unchanged() {
        let p = linear();
        let nominal: Vec<(EffectId, Vec<f64>)> =
            EffectId::ALL.iter().map(|e| (*e, e.nominal())).collect();
        let refs: Vec<(EffectId, &[f64])> =
            nominal.iter().map(|(e, v)| (*e, v.as_slice())).collect();
        for a in [-3.5, 0.0, 7.25] {
            assert_eq!(apply(&p, &refs, a), p.at(a));
        }
    }

    #[test]
    fn each_effect_changes_what_it_says() {
        let p = linear();
        let at = 4.0;
        let b = p.at(at).unwrap();
        let one = |e: EffectId, v: &[f64]| apply(&p, &[(e, v)], at).unwrap();
        assert!((one(EffectId::ParasiteDrag, &[0.01]).cd - (b.cd + 0.01)).abs() < 1e-12);
        assert!(
            (one(EffectId::InducedDragFactor, &[0.05]).cd - (b.cd + 0.05 * b.cl * b.cl)).abs()
                < 1e-12
        );
        assert!((one(EffectId::LiftSlopeScale, &[0.9]).cl - 0.9 * b.cl).abs() < 1e-12);
        // CL(α − 1) on a slope of 0.1 per degree.
        assert!((one(EffectId::ZeroLiftShift, &[1.0]).cl - (b.cl - 0.1)).abs() < 1e-12);
        assert!((one(EffectId::Cm0Offset, &[-0.02]).cm - (b.cm - 0.02)).abs() < 1e-12);
        assert!(
            (one(EffectId::MomentReferenceShift, &[0.05]).cm - (b.cm + 0.05 * b.cl)).abs() < 1e-12
        );
        let s = one(EffectId::StallOnset, &[2.0, 0.01, -0.005]);
        assert!((s.cl - (b.cl - 0.04)).abs() < 1e-12 && (s.cm - (b.cm - 0.02)).abs() < 1e-12);
        let t = one(EffectId::TailEfficiency, &[0.5]);
        assert!((t.cl - (b.cl - 0.5 * 0.04)).abs() < 1e-12);
        assert!((t.cm - (b.cm + 0.5 * 0.12)).abs() < 1e-12);
    }

    #[test]
    fn outside_the_prediction_there_is_no_value() {
        assert_eq!(linear().at(20.0), None);
        assert_eq!(interpolate(&[0.0, 1.0], &[0.0, 2.0], 3.0, true), Some(6.0));
    }
}
