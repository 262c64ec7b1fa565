//! `datcom-rs plot`: one SVG per figure, axis labels with units, the case name in the title,
//! one labelled series per flight condition.

use std::path::PathBuf;

fn example() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("namelists/example-uav.dcm")
}

/// The text elements of an SVG, in order (plotters writes each on its own line).
fn texts(svg: &str) -> Vec<String> {
    let mut out = Vec::new();
    let mut lines = svg.lines();
    while let Some(l) = lines.next() {
        if l.starts_with("<text") {
            if let Some(t) = lines.next() {
                out.push(t.trim().to_string());
            }
        }
    }
    out
}

#[test]
fn every_figure_labels_its_axes_and_every_series() {
    let deck = datcom::read_deck_file(&example()).unwrap();
    let results = datcom::run(&deck);
    let case = &results.cases[0];
    let figures = datcom::report::plot::figures(case).unwrap();
    let names: Vec<&str> = figures.iter().map(|f| f.name.as_str()).collect();
    assert_eq!(
        names,
        [
            "cl", "cd", "cm", "polar", "cm-cl", "cyb", "cnb", "clb", "clq", "cmq", "clad", "cmad",
            "clp", "cyp", "cnp", "cnr", "clr"
        ],
        "the example has DAMP: every figure"
    );
    // Four conditions (2 Mach numbers x 2 altitudes, metres): four series everywhere.
    let conditions = [
        "Mach 0.06, 0 m",
        "Mach 0.09, 0 m",
        "Mach 0.06, 500 m",
        "Mach 0.09, 500 m",
    ];
    for f in &figures {
        let t = texts(&f.svg);
        assert!(
            t[0].starts_with("DATCOM-RS EXAMPLE UAV, WING-BODY-TAIL: "),
            "{}: title {:?}",
            f.name,
            t[0]
        );
        assert_eq!(f.series.len(), 4, "{}", f.name);
        for (label, condition) in f.series.iter().zip(conditions) {
            assert!(label.starts_with(condition), "{}: {label}", f.name);
            assert!(t.contains(label), "{}: no legend {label}", f.name);
        }
        let path_count = f.svg.matches("<polyline").count();
        assert!(path_count >= 4, "{}: {path_count} lines", f.name);
    }
    let by_name = |n: &str| figures.iter().find(|f| f.name == n).unwrap();
    let axes = |n: &str| texts(&by_name(n).svg);
    assert!(axes("cl").contains(&"CL (-)".to_string()));
    assert!(axes("cl").contains(&"α (deg)".to_string()));
    assert!(axes("polar").contains(&"CD (-)".to_string()));
    assert!(axes("cm-cl").contains(&"Cm (-)".to_string()));
    // DERIV RAD: derivatives per radian; CYβ is one value per configuration.
    assert!(axes("clp").contains(&"Clp (1/rad)".to_string()));
    assert!(by_name("cyb").series[0].ends_with("(one value per configuration)"));
    assert!(!by_name("clb").series[0].contains("one value"));
}

#[test]
fn plot_writes_one_file_per_figure() {
    let dir = std::env::temp_dir().join(format!("datcom-rs-plot-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_datcom-rs"))
        .arg("plot")
        .arg(example())
        .arg("-o")
        .arg(&dir)
        .output()
        .unwrap();
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let mut files: Vec<String> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    files.sort();
    assert_eq!(files.len(), 17, "{files:?}");
    assert!(files.contains(&"example-uav-polar.svg".to_string()));
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn a_case_with_nothing_computed_is_a_typed_error() {
    let text = " $FLTCON NMACH=1.0, MACH(1)=0.4, NALT=1.0, ALT(1)=0.0,\n   NALPHA=2.0, ALSCHD(1)=0.0,4.0$\n $SYNTHS XCG=1.0$\n";
    let results = datcom::run(&datcom::read_deck(text, "empty.dcm"));
    assert_eq!(
        datcom::report::plot::figures(&results.cases[0]).unwrap_err(),
        datcom::report::plot::PlotError::NothingToPlot { case: 1 }
    );
}
