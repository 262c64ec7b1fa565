//! Reading the original's listings into the JSON of `run`, and comparing results.

mod common;

use datcom::report::{compare, json, legacy};

#[test]
fn every_listing_imports_with_consistent_tables() {
    let dir = std::path::PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../shared/oracle/cases");
    if !dir.is_dir() {
        eprintln!("SKIPPED every_listing_imports_with_consistent_tables: ../shared/oracle/cases is absent");
        return;
    }
    let (mut statics, mut dynamics, mut rows) = (0, 0, 0);
    for e in std::fs::read_dir(&dir).unwrap().filter_map(Result::ok) {
        let path = e.path().join("for006.dat");
        let text = String::from_utf8_lossy(&std::fs::read(&path).unwrap()).into_owned();
        for case in legacy::read_listing(&text) {
            for c in &case.conditions {
                for (t, count) in [(&c.statics, &mut statics), (&c.dynamics, &mut dynamics)] {
                    let Some(t) = t else { continue };
                    *count += 1;
                    let n = t.column("ALPHA").unwrap().len();
                    rows += n;
                    for (name, col) in &t.columns {
                        assert_eq!(col.len(), n, "{}: {name}", path.display());
                    }
                }
            }
        }
        // A listing agrees with itself everywhere.
        let v: serde_json::Value =
            serde_json::from_str(&json::listing_to_string(&text, "x")).unwrap();
        for r in compare::compare(&v, &v) {
            assert_eq!(r.fraction(), 1.0, "{}: {}", path.display(), r.coefficient);
        }
    }
    eprintln!("imported {statics} static and {dynamics} dynamic tables ({rows} rows)");
    assert!(statics > 100 && dynamics > 20, "{statics} {dynamics}");
}

#[test]
fn navion_listing_values() {
    let path = std::path::PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("../shared/oracle/cases/arktools__Navion_clean/for006.dat");
    let Ok(bytes) = std::fs::read(&path) else {
        eprintln!(
            "SKIPPED navion_listing_values: {} is absent",
            path.display()
        );
        return;
    };
    let v: serde_json::Value = serde_json::from_str(&json::listing_to_string(
        &String::from_utf8_lossy(&bytes),
        "navion",
    ))
    .unwrap();
    let c = &v["cases"][0]["conditions"][0];
    // for006.dat line 387: -2.0 0.020 0.142 0.1060 ... 5.598E+00 -6.870E-01 -4.766E-01 5.071E-02 -8.782E-02
    assert_eq!(c["static"]["alpha"][0], -2.0);
    assert_eq!(c["static"]["CM"][0], 0.106);
    assert_eq!(c["static"]["CYB"][0], -0.4766);
    assert!(
        c["static"]["CYB"][1].is_null(),
        "CYB is printed on the first row only"
    );
    assert_eq!(c["deriv_unit"], "rad");
    // line 422: -2.00 7.731E+00 -1.487E+01 3.603E+00 ...
    assert_eq!(c["dynamic"]["CLQ"][0], 7.731);
    assert_eq!(c["dynamic"]["CLAD"][0], 3.603);
    assert_eq!(c["mach"], 0.158);
}

/// Our own listing of the bundled example with `note` printed under the first static page's
/// configuration line, as the original prints the effects a page includes.
fn with_note(listing: &str, configuration: &str, note: &str) -> String {
    let mut lines: Vec<String> = listing.lines().map(str::to_string).collect();
    let at = lines
        .iter()
        .position(|l| l.contains("CHARACTERISTICS AT ANGLE OF ATTACK"))
        .expect("a static page");
    assert_eq!(
        lines[at + 1].trim(),
        configuration,
        "the configuration line"
    );
    lines.insert(at + 2, format!("{:>31}{note}", ""));
    lines.join("\n")
}

/// A page the original prints with power (or ground) effects included carries the note under
/// its configuration line. The importer keeps the note (`included`), reads the CASEID from the
/// line after it, and puts the configuration's dynamic page with it. `compare` counts as
/// missing, against a page without the effects (ours), the numbers the effects change: with
/// power CD, CL, CM, CN, CA and XCP; at a ground height every static and downwash number;
/// out of ground effect (FREE AIR) none. The dynamic derivatives include neither.
#[test]
fn a_page_with_power_or_ground_effects_is_marked_and_compared_for_what_they_leave() {
    const POWER: &str = "PROPELLER POWER EFFECTS INCLUDED IN THE LONGITUDINAL STABILITY RESULTS";
    const GROUND: &str =
        "GROUND EFFECTS INCLUDED IN THE LONGITUDINAL STABILITY RESULTS , GROUND HEIGHT=   5.00";
    const FREE_AIR: &str =
        "GROUND EFFECTS INCLUDED IN THE LONGITUDINAL STABILITY RESULTS , GROUND HEIGHT= FREE AIR";
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("namelists/example-uav.dcm");
    let deck = datcom::read_deck_file(&path).expect("the bundled deck");
    let results = datcom::run(&deck);
    let listing = datcom::report::for006::to_string(&results);
    let configuration = results.cases[0].conditions[0].configuration.clone();
    let ours: serde_json::Value =
        serde_json::from_str(&json::to_string(&results)).expect("our JSON");
    let agreement = |listing: &str| {
        let reference: serde_json::Value =
            serde_json::from_str(&json::listing_to_string(listing, "x")).expect("imported");
        compare::compare(&ours, &reference)
    };
    let plain = agreement(&listing);
    let counts = |rows: &[compare::ColumnAgreement], name: &str| {
        rows.iter()
            .find(|r| r.coefficient == name)
            .map(|r| (r.compared, r.missing))
            .unwrap_or_else(|| panic!("{name} compared"))
    };
    assert_eq!(counts(&plain, "CL").1, 0);
    let n = results.cases[0].conditions[0].alpha_deg.len();
    let fewer = |name: &str| (counts(&plain, name).0 - n, n);

    let powered = with_note(&listing, &configuration, POWER);
    let read = legacy::read_listing(&powered);
    let page = &read[0].conditions[0];
    assert_eq!(page.included, vec![POWER.to_string()]);
    assert_eq!(read[0].caseid, legacy::read_listing(&listing)[0].caseid);
    assert!(page.statics.is_some() && page.dynamics.is_some());
    let rows = agreement(&powered);
    for name in ["CD", "CL", "CM", "CN", "CA", "XCP"] {
        assert_eq!(counts(&rows, name), fewer(name), "{name} with power");
    }
    for name in ["CLA", "CMA", "CLB", "CLQ", "CLP", "EPSLON"] {
        assert_eq!(
            counts(&rows, name),
            counts(&plain, name),
            "{name} with power"
        );
    }

    let rows = agreement(&with_note(&listing, &configuration, GROUND));
    for name in ["CL", "CLA", "CLB", "EPSLON"] {
        assert_eq!(counts(&rows, name), fewer(name), "{name} in ground effect");
    }
    assert_eq!(counts(&rows, "CLQ"), counts(&plain, "CLQ"));

    let rows = agreement(&with_note(&listing, &configuration, FREE_AIR));
    for name in ["CL", "CLA", "CLQ", "EPSLON"] {
        assert_eq!(
            counts(&rows, name),
            counts(&plain, name),
            "{name} out of ground effect"
        );
    }

    // A CASEID that says "included in" is a CASEID, not a note.
    let caseid = with_note(&listing, &configuration, "FLAPS INCLUDED IN THIS RUN");
    let read = legacy::read_listing(&caseid);
    assert!(read[0].conditions[0].included.is_empty());
    assert_eq!(
        read[0].caseid.as_deref(),
        Some("FLAPS INCLUDED IN THIS RUN")
    );
}

/// The units of an imported listing are those `run --format json` gives for the same deck:
/// metric (`N/ M**2`, `DEG K`, `1/ M` as the original prints them), centimetre, inch and foot
/// listings. The unit line was split on blanks and its words taken by place, so the metric
/// listings had pressure `N/`, temperature `M**2`, and the feet listings temperature `DEG`.
#[test]
fn imported_units_are_those_run_gives_for_the_deck() {
    let Some(dir) = common::shared_dir(
        "oracle/cases",
        "imported_units_are_those_run_gives_for_the_deck",
    ) else {
        return;
    };
    let mut lengths = std::collections::BTreeSet::new();
    for case_dir in std::fs::read_dir(&dir).unwrap().filter_map(Result::ok) {
        let listing = common::text(&case_dir.path().join("for006.dat"));
        let deck = datcom::read_deck(&common::text(&case_dir.path().join("input.dcm")), "deck");
        let ours: serde_json::Value =
            serde_json::from_str(&json::to_string(&datcom::run(&deck))).unwrap();
        let imported: serde_json::Value =
            serde_json::from_str(&json::listing_to_string(&listing, "x")).unwrap();
        let our_units: Vec<&serde_json::Value> = ours["cases"]
            .as_array()
            .unwrap()
            .iter()
            .map(|c| &c["units"])
            .collect();
        for c in imported["cases"].as_array().unwrap() {
            assert!(
                our_units.contains(&&c["units"]),
                "{}: imported {} is none of run's {our_units:?}",
                case_dir.path().display(),
                c["units"]
            );
            lengths.insert(c["units"]["length"].as_str().unwrap().to_string());
        }
    }
    assert_eq!(
        lengths.into_iter().collect::<Vec<_>>(),
        ["CM", "FT", "IN", "M"],
        "listings of every DIM"
    );
}

/// `import` reads a listing, ours (`--format for006`) or the original's, and refuses what would
/// import as nothing or as invented numbers. Our text report (`run`'s default) was read as a
/// listing: its static table is a column off the listing's, so CL, CM and CLA came back null
/// and CYB = 1, CLB = -9.941 were invented (navion). Any other text imported as no case, and
/// so did a listing whose pages are none that are read, with no word said.
#[test]
fn import_refuses_the_text_report_and_what_is_no_listing() {
    use legacy::NotImported;
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("namelists");
    for deck in common::files(&dir) {
        let text = common::text(&deck);
        let results = datcom::run(&datcom::read_deck(&text, "deck"));
        let report = datcom::report::text::to_string(&results);
        assert_eq!(
            legacy::import(&report).err(),
            Some(NotImported::TextReport),
            "{}",
            deck.display()
        );
        let listing = datcom::report::for006::to_string(&results);
        assert_eq!(
            legacy::import(&listing).map(|c| c.len()).ok(),
            Some(results.cases.len()),
            "{}: our listing imports",
            deck.display()
        );
        for other in [
            text,
            datcom::report::json::to_string(&results),
            datcom::report::csv::to_string(&results),
        ] {
            assert_eq!(legacy::import(&other).err(), Some(NotImported::NotAListing));
        }
    }
    let message = NotImported::TextReport.to_string();
    assert!(
        message.contains("--format json") && message.contains("--format for006"),
        "{message}"
    );
    // A listing whose only result page is of a kind not read (lkampoli ex10's transverse jet).
    let jet = " THIS SOFTWARE AND ANY ACCOMPANYING DOCUMENTATION\n\
        1                          AUTOMATED STABILITY AND CONTROL METHODS PER APRIL 1976 VERSION OF DATCOM\n\
        \x20                                                    SPECIAL CONTROL METHODS\n\
        \x20                                              TRANSVERSE-JET CONTROL EFFECTIVENESS\n";
    assert_eq!(
        legacy::import(jet).err(),
        Some(NotImported::NoPageRead {
            kinds: vec!["SPECIAL CONTROL METHODS".into()]
        })
    );
    let stopped = " THIS SOFTWARE AND ANY ACCOMPANYING DOCUMENTATION\n\
        1                         CONERR - INPUT ERROR CHECKING\n0 F - SYNTAX ERROR\n";
    assert_eq!(
        legacy::import(stopped).err(),
        Some(NotImported::NoResultPage)
    );
}

/// Every listing of the original imports, but those whose result pages are of kinds not read
/// (the hypersonic and transverse-jet examples), which say so.
#[test]
fn every_oracle_listing_imports_or_says_why_not() {
    let Some(dir) = common::shared_dir(
        "oracle/cases",
        "every_oracle_listing_imports_or_says_why_not",
    ) else {
        return;
    };
    let mut not_read = Vec::new();
    for case_dir in std::fs::read_dir(&dir).unwrap().filter_map(Result::ok) {
        let listing = common::text(&case_dir.path().join("for006.dat"));
        match legacy::import(&listing) {
            Ok(cases) => assert!(!cases.is_empty()),
            Err(legacy::NotImported::NoPageRead { kinds }) => {
                assert!(!kinds.is_empty(), "{}", case_dir.path().display());
                not_read.push(case_dir.file_name().to_string_lossy().into_owned());
            }
            Err(e) => panic!("{}: {e}", case_dir.path().display()),
        }
    }
    not_read.sort();
    assert_eq!(not_read, ["lkampoli__ex10", "lkampoli__ex11"]);
}
