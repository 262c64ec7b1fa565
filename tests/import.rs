//! Reading the original's listings into the JSON of `run`, and comparing results.

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
