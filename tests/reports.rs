//! Reports: the text report's FLIGHT CONDITIONS rows read back by the listing reader give our
//! numbers; the JSON of `run` has the documented shape; the CSV has a row per angle.

use datcom::report::legacy::{self, last_digit_unit};
use datcom::report::{condition_view, reference_view};
use datcom::Diagnosed;

fn example() -> datcom::Results {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("namelists/example-uav.dcm");
    let deck = datcom::read_deck_file(&path).expect("bundled deck");
    assert!(!deck.has_errors(), "{:?}", deck.diagnostics);
    datcom::run(&deck)
}

#[test]
fn text_rows_read_back_to_our_numbers() {
    let r = example();
    let text = datcom::report::text::to_string(&r);
    let rows = legacy::flight_condition_rows(&text);
    let case = &r.cases[0];
    // With DAMP each condition has a static and a dynamic page, each with its row.
    let pages = if case.conditions.iter().all(|c| c.dynamic.is_some()) {
        2
    } else {
        1
    };
    assert_eq!(case.conditions.len(), 4, "2 Mach numbers x 2 altitudes");
    assert_eq!(rows.len(), pages * case.conditions.len());
    let (area, long, lat, xcg, zcg) = reference_view(case);
    let paired = rows
        .chunks(pages)
        .zip(&case.conditions)
        .flat_map(|(rows, c)| rows.iter().map(move |row| (row, c)));
    for (row, c) in paired {
        let v = condition_view(c, case.dim);
        let ours = [
            Some(v.mach),
            v.altitude,
            v.velocity,
            v.pressure,
            v.temperature,
            Some(v.reynolds_per_length),
            area,
            long,
            lat,
            Some(xcg),
            Some(zcg),
        ];
        for (((name, _, _), printed), o) in legacy::FIELDS.iter().zip(&row.fields).zip(ours) {
            let p = printed
                .value
                .unwrap_or_else(|| panic!("{name} not printed: {:?}", printed.text));
            let o = o.unwrap();
            assert!(
                (p - o).abs() <= 0.5 * last_digit_unit(&printed.text) * (1.0 + 1e-9),
                "{name}: printed {} for {o}",
                printed.text
            );
        }
    }
}

#[test]
fn json_has_the_documented_shape() {
    let r = example();
    let v: serde_json::Value = serde_json::from_str(&datcom::report::json::to_string(&r)).unwrap();
    let c = &v["cases"][0];
    assert_eq!(c["caseid"], "DATCOM-RS EXAMPLE UAV, WING-BODY-TAIL");
    let k = &c["conditions"][0];
    for key in [
        "mach",
        "altitude",
        "velocity",
        "pressure",
        "temperature",
        "reynolds_per_length",
        "configuration",
        "deriv_unit",
        "static",
        "dynamic",
    ] {
        assert!(k.get(key).is_some(), "missing {key}");
    }
    assert_eq!(k["deriv_unit"], "rad");
    for key in [
        "alpha", "CD", "CL", "CM", "CN", "CA", "XCP", "CLA", "CMA", "CYB", "CNB", "CLB",
    ] {
        assert_eq!(
            k["static"][key].as_array().map(Vec::len),
            Some(9),
            "static.{key}"
        );
    }
    for key in [
        "alpha", "CLQ", "CMQ", "CLAD", "CMAD", "CLP", "CYP", "CNP", "CNR", "CLR",
    ] {
        assert_eq!(
            k["dynamic"][key].as_array().map(Vec::len),
            Some(9),
            "dynamic.{key}"
        );
    }
    // The configuration's side-force derivative: a number on the first row, null on the
    // others (the original prints it once per configuration), never a number made up.
    assert!(k["static"]["CYB"][0].as_f64().is_some_and(f64::is_finite));
    assert!(k["static"]["CYB"][1].is_null());
    // Deck units: metres and kelvins under DIM M.
    assert_eq!(k["altitude"], 0.0);
    assert!((k["temperature"].as_f64().unwrap() - 288.15).abs() < 1e-9);
}

#[test]
fn csv_has_a_row_per_condition_and_angle() {
    let r = example();
    let csv = datcom::report::csv::to_string(&r);
    let lines: Vec<&str> = csv.lines().collect();
    assert_eq!(
        lines[0].split(',').count(),
        datcom::report::csv::HEADER.len()
    );
    assert_eq!(lines.len(), 1 + 4 * 9);
    assert!(
        lines[1].starts_with("1,\"DATCOM-RS EXAMPLE UAV, WING-BODY-TAIL\",1,"),
        "{}",
        lines[1]
    );
}

/// `--format for006` read back by our listing importer gives our numbers to the printed
/// precision (F formats: half a unit of the last decimal; E formats: 4 significant digits).
#[test]
fn for006_pages_read_back_to_our_numbers() {
    let mut r = example();
    // Every column filled with a distinct value so that a misplaced column is caught.
    for case in &mut r.cases {
        for c in &mut case.conditions {
            let n = c.alpha_deg.len();
            let val = |k: usize| {
                (0..n)
                    .map(|i| Some(0.01 * (k as f64 + 1.0) + 0.001 * i as f64))
                    .collect::<Vec<_>>()
            };
            for (k, (_, col)) in c.static_coefficients.columns_mut().into_iter().enumerate() {
                *col = val(k);
            }
            if let Some(d) = &mut c.dynamic {
                for (k, (_, col)) in d.columns_mut().into_iter().enumerate() {
                    *col = val(20 + k);
                }
                // A column without a DATCOM method: NDM in the first row.
                d.no_method = vec!["CLAD"];
                d.clad = vec![None; n];
            }
            if let Some(w) = &mut c.downwash {
                w.dynamic_pressure_ratio = (0..n).map(|i| Some(0.9 + 0.001 * i as f64)).collect();
                w.epsilon_deg = (0..n).map(|i| Some(-1.5 + 0.25 * i as f64)).collect();
                w.gradient = (0..n).map(|i| Some(0.6 - 0.05 * i as f64)).collect();
                // A value not computed is blank.
                w.gradient[n - 1] = None;
            }
        }
    }
    let listing = datcom::report::for006::to_string(&r);
    assert!(listing.contains("NDM PRINTED WHEN NO DATCOM METHODS EXIST"));
    let back = legacy::read_listing(&listing);
    assert_eq!(back.len(), 1);
    assert_eq!(back[0].conditions.len(), 4);
    let c = &r.cases[0].conditions[0];
    let b = &back[0].conditions[0];
    let st = b.statics.as_ref().unwrap();
    let cl = st.column("CL").unwrap();
    let cla = st.column("CLA").unwrap();
    for i in 0..c.alpha_deg.len() {
        let ours_cl = c.static_coefficients.cl[i].unwrap();
        assert!((cl[i].unwrap() - ours_cl).abs() <= 0.0005 + 1e-12, "CL {i}");
        let ours_cla = c.static_coefficients.cla[i].unwrap();
        assert!(
            (cla[i].unwrap() - ours_cla).abs() <= 0.5e-3 * ours_cla.abs() + 1e-12,
            "CLA {i}"
        );
    }
    let dy = b.dynamics.as_ref().unwrap();
    let clr = dy.column("CLR").unwrap();
    assert!((clr[0].unwrap() - c.dynamic.as_ref().unwrap().clr[0].unwrap()).abs() < 1e-6);
    assert_eq!(dy.no_method(), vec!["CLAD".to_string()]);
    // The neighbours of the NDM field are read in their own columns.
    let cmad = dy.column("CMAD").unwrap();
    assert!((cmad[0].unwrap() - c.dynamic.as_ref().unwrap().cmad[0].unwrap()).abs() < 1e-6);
    // The downwash table under the pages with a horizontal tail (F10.3 fields).
    let mut tables = 0;
    for (c, b) in r.cases[0].conditions.iter().zip(&back[0].conditions) {
        let (Some(w), Some(t)) = (&c.downwash, &b.downwash) else {
            assert!(
                c.downwash.is_none() && b.downwash.is_none(),
                "{}",
                c.configuration
            );
            continue;
        };
        tables += 1;
        for (name, ours) in [
            ("Q/QINF", &w.dynamic_pressure_ratio),
            ("EPSLON", &w.epsilon_deg),
            ("D(EPSLON)/D(ALPHA)", &w.gradient),
        ] {
            let read = t.column(name).unwrap();
            assert_eq!(read.len(), ours.len(), "{name}");
            for (o, r) in ours.iter().zip(read) {
                match (o, r) {
                    (Some(o), Some(r)) => assert!((o - r).abs() <= 0.0005 + 1e-12, "{name}"),
                    (None, None) => {}
                    _ => panic!("{name}: ours {o:?}, read {r:?}"),
                }
            }
        }
    }
    assert!(tables > 0, "the example has a page with a horizontal tail");
}

/// The case's warnings are written once per text; a section's are written each, one per flight
/// condition where they repeat (the example's two altitudes give each Mach number's line
/// twice), as the reports always wrote them.
#[test]
fn case_warnings_are_said_once_and_section_warnings_each() {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("namelists/example-uav.dcm");
    let deck = datcom::read_deck_file(&path)
        .expect("the bundled deck")
        .with_original_rules();
    let r = datcom::run(&deck);
    let text = datcom::report::text::to_string(&r);
    let line = "warning: WING section: no Reynolds number for Mach 0.06: the section characteristics use 1e6";
    assert_eq!(text.matches(line).count(), 2, "{text}");
    let v: serde_json::Value =
        serde_json::from_str(&datcom::report::json::to_string(&r)).expect("JSON");
    let wing = v["cases"][0]["sections"]["WING"]["warnings"]
        .as_array()
        .expect("the wing section's warnings");
    assert_eq!(wing.len(), 4, "{wing:?}");
    let said: Vec<&str> = text
        .lines()
        .filter(|l| l.starts_with(" warning (case 1)"))
        .collect();
    let mut once = said.clone();
    once.sort_unstable();
    once.dedup();
    assert_eq!(once.len(), said.len(), "a case warning said twice");
    assert!(!said.is_empty());
}
