//! The numbers of a case's input structures by their deck variable names: one list per
//! structure of its optional numbers and one of its arrays, read by the deck writer and where
//! a case built in code is searched for values that are not numbers.

use super::{
    Body, FlightInput, LowAspectRatioWingBody, Planform, Reference, SectionInput, Synthesis,
    TwinPanels,
};

/// Writes, for a structure, `arrays`: each array of numbers with its deck variable name.
macro_rules! named_arrays {
    ($ty:ty { $($field:ident => $name:literal),* $(,)? }) => {
        impl $ty {
            /// Each array of numbers with its deck variable name.
            pub(crate) fn arrays(&self) -> impl Iterator<Item = (&'static str, &[f64])> {
                [$(($name, self.$field.as_slice())),*].into_iter()
            }
        }
    };
}

named_arrays!(FlightInput {
    mach => "MACH",
    velocity => "VINF",
    reynolds_per_length => "RNNUB",
    altitude => "ALT",
    pressure => "PINF",
    temperature => "TINF",
    alpha_deg => "ALSCHD",
});

named_arrays!(Body {
    x => "X",
    s => "S",
    p => "P",
    r => "R",
    zu => "ZU",
    zl => "ZL",
});

named_arrays!(SectionInput {
    xcord => "XCORD",
    yupper => "YUPPER",
    ylower => "YLOWER",
    mean => "MEAN",
    thick => "THICK",
});

/// A structure's optional numbers by their deck variable names.
pub(crate) trait NamedScalars {
    /// Each optional number with its deck variable name.
    fn scalars(&self) -> impl Iterator<Item = (&'static str, Option<f64>)>;
    /// [`NamedScalars::scalars`], to edit.
    fn scalars_mut(&mut self) -> impl Iterator<Item = (&'static str, &mut Option<f64>)>;
}

/// Writes a structure's [`NamedScalars`] from one list.
macro_rules! named_scalars {
    ($ty:ty { $($field:ident => $name:literal),* $(,)? }) => {
        impl NamedScalars for $ty {
            fn scalars(&self) -> impl Iterator<Item = (&'static str, Option<f64>)> {
                [$(($name, self.$field)),*].into_iter()
            }

            fn scalars_mut(&mut self) -> impl Iterator<Item = (&'static str, &mut Option<f64>)> {
                [$(($name, &mut self.$field)),*].into_iter()
            }
        }
    };
}

named_scalars!(FlightInput {
    weight => "WT",
    gamma_deg => "GAMMA",
    stmach => "STMACH",
    tsmach => "TSMACH",
});

named_scalars!(Reference {
    area => "SREF",
    chord => "CBARR",
    span => "BLREF",
    roughness => "ROUGFC",
});

// SCALE is the case's `scale` in the deck the writer gives; it is listed here for the edit.
named_scalars!(Synthesis {
    xcg => "XCG",
    zcg => "ZCG",
    xw => "XW",
    zw => "ZW",
    aliw_deg => "ALIW",
    xh => "XH",
    zh => "ZH",
    alih_deg => "ALIH",
    xv => "XV",
    zv => "ZV",
    xvf => "XVF",
    zvf => "ZVF",
    yv => "YV",
    yf => "YF",
    phiv_deg => "PHIV",
    phif_deg => "PHIF",
    hinax => "HINAX",
    scale => "SCALE",
});

named_scalars!(Body {
    bnose => "BNOSE",
    btail => "BTAIL",
    bln => "BLN",
    bla => "BLA",
    ds => "DS",
    itype => "ITYPE",
    method => "METHOD",
    ellip => "ELLIP",
});

named_scalars!(Planform {
    chrdr => "CHRDR",
    chrdbp => "CHRDBP",
    chrdtp => "CHRDTP",
    sspn => "SSPN",
    sspne => "SSPNE",
    sspnop => "SSPNOP",
    sspndd => "SSPNDD",
    savsi_deg => "SAVSI",
    savso_deg => "SAVSO",
    chstat => "CHSTAT",
    twista_deg => "TWISTA",
    dhdadi_deg => "DHDADI",
    dhdado_deg => "DHDADO",
    planform_type => "TYPE",
    swafp_deg => "SWAFP",
});

named_scalars!(TwinPanels {
    bvp => "BVP",
    bv => "BV",
    bdv => "BDV",
    bh => "BH",
    sv => "SV",
    vphite => "VPHITE",
    vlp => "VLP",
    zp => "ZP",
});

named_scalars!(LowAspectRatioWingBody {
    sref => "SREF",
    length => "L",
    xcg => "XCG",
    zb => "ZB",
    deltep_deg => "DELTEP",
    sfront => "SFRONT",
    aspect_ratio => "AR",
    r3leob => "R3LEOB",
    deltal_deg => "DELTAL",
    swet => "SWET",
    perbas => "PERBAS",
    sbase => "SBASE",
    hb => "HB",
    bb => "BB",
    thetad_deg => "THETAD",
    sbs => "SBS",
    sbslb => "SBSLB",
    xcensb => "XCENSB",
    xcenw => "XCENW",
});

#[cfg(test)]
mod tests {
    use super::*;

    /// Every optional number of a structure is in its list: with each listed one set, the
    /// structure serializes with no number missing (a field added later and not listed would
    /// stay null). `others` are its optional values that are not numbers.
    fn all_listed<T: NamedScalars + Default + serde::Serialize>(others: &[&str]) {
        let mut value = T::default();
        for (_, v) in value.scalars_mut() {
            *v = Some(1.0);
        }
        let json = serde_json::to_value(&value).unwrap();
        let unset: Vec<&String> = json
            .as_object()
            .unwrap()
            .iter()
            .filter(|(k, v)| v.is_null() && !others.contains(&k.as_str()))
            .map(|(k, _)| k)
            .collect();
        assert!(unset.is_empty(), "not listed: {unset:?}");
    }

    #[test]
    fn every_optional_number_is_listed() {
        all_listed::<FlightInput>(&[]);
        all_listed::<Reference>(&[]);
        all_listed::<Synthesis>(&[]);
        all_listed::<Body>(&[]);
        all_listed::<Planform>(&[]);
        all_listed::<TwinPanels>(&[]);
        all_listed::<LowAspectRatioWingBody>(&["blf", "roundn"]);
    }

    /// Every array of numbers of a structure is in its list: the structures' arrays that are
    /// not listed are the ones named here (none holds numbers), and a default structure's
    /// arrays are all empty.
    #[test]
    fn every_array_is_listed() {
        fn arrays(json: serde_json::Value) -> Vec<String> {
            json.as_object()
                .unwrap()
                .iter()
                .filter(|(_, v)| v.is_array())
                .map(|(k, _)| k.clone())
                .collect()
        }
        let flight = FlightInput::default();
        assert_eq!(
            arrays(serde_json::to_value(&flight).unwrap()).len(),
            flight.arrays().count()
        );
        let body = Body::default();
        assert_eq!(
            arrays(serde_json::to_value(&body).unwrap()).len(),
            body.arrays().count()
        );
        let section = SectionInput::default();
        assert_eq!(
            arrays(serde_json::to_value(&section).unwrap()).len(),
            section.arrays().count()
        );
    }

    /// Each listed name is a variable of its namelist.
    #[test]
    fn the_names_are_the_namelists_variables() {
        let named: [(&str, Vec<&str>); 7] = [
            (
                "FLTCON",
                FlightInput::default().scalars().map(|(n, _)| n).collect(),
            ),
            (
                "OPTINS",
                Reference::default().scalars().map(|(n, _)| n).collect(),
            ),
            (
                "SYNTHS",
                Synthesis::default().scalars().map(|(n, _)| n).collect(),
            ),
            ("BODY", Body::default().scalars().map(|(n, _)| n).collect()),
            (
                "WGPLNF",
                Planform::default().scalars().map(|(n, _)| n).collect(),
            ),
            (
                "TVTPAN",
                TwinPanels::default().scalars().map(|(n, _)| n).collect(),
            ),
            (
                "LARWB",
                LowAspectRatioWingBody::default()
                    .scalars()
                    .map(|(n, _)| n)
                    .collect(),
            ),
        ];
        let arrays: [(&str, Vec<&str>); 3] = [
            (
                "FLTCON",
                FlightInput::default().arrays().map(|(n, _)| n).collect(),
            ),
            ("BODY", Body::default().arrays().map(|(n, _)| n).collect()),
            (
                "WGSCHR",
                SectionInput::default().arrays().map(|(n, _)| n).collect(),
            ),
        ];
        for (nl, names) in named.into_iter().chain(arrays) {
            let table = crate::deck::schema::table(nl).unwrap();
            for name in names {
                assert!(table.var(name).is_some(), "{nl} has no {name}");
            }
        }
    }
}
