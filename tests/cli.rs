//! The command line: exit codes 0/1/2, every subcommand, output files.

use std::process::Command;

fn bin() -> Command {
    Command::new(env!("CARGO_BIN_EXE_datcom-rs"))
}

fn example() -> String {
    format!("{}/namelists/example-uav.dcm", env!("CARGO_MANIFEST_DIR"))
}

fn temp_dir(name: &str) -> std::path::PathBuf {
    let d = std::env::temp_dir().join(format!("datcom-rs-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

#[test]
fn check_clean_deck_exits_0() {
    let out = bin().args(["check", &example()]).output().unwrap();
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stdout)
    );
    assert!(String::from_utf8_lossy(&out.stdout).contains("0 error(s)"));
}

#[test]
fn check_deck_with_errors_exits_1_and_names_the_place() {
    let dir = temp_dir("check");
    let deck = dir.join("bad.dcm");
    std::fs::write(&deck, " $FLTCON NMACH=1.0, MACH(1)=0.4$\n $SYNTHS XCG=1.0$\n $WGPLNF CHRDR=1.0, DHDAHI=2.0$\nNACA-W-4-0012\n").unwrap();
    let out = bin()
        .args(["check", deck.to_str().unwrap()])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(1));
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(
        stdout.contains("bad.dcm:3:21: error [WGPLNF DHDAHI]"),
        "{stdout}"
    );
    assert!(stdout.contains("did you mean DHDADI?"), "{stdout}");
}

#[test]
fn missing_file_exits_2() {
    let out = bin()
        .args(["check", "/nonexistent/deck.dcm"])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("cannot read"));
}

#[test]
fn usage_error_exits_2() {
    let out = bin().args(["run"]).output().unwrap();
    assert_eq!(out.status.code(), Some(2));
}

#[test]
fn run_json_and_csv_and_output_dir() {
    let out = bin()
        .args(["run", &example(), "--format", "json"])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(0));
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(v["cases"][0]["conditions"].as_array().unwrap().len(), 4);

    let dir = temp_dir("run");
    let out = bin()
        .args([
            "run",
            &example(),
            "--format",
            "csv",
            "-o",
            dir.to_str().unwrap(),
        ])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(0));
    let csv = std::fs::read_to_string(dir.join("example-uav.csv")).unwrap();
    assert!(csv.starts_with("case,caseid,condition"));
}

#[test]
fn parse_prints_typed_cases() {
    let out = bin()
        .args(["parse", &example(), "--format", "json"])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(0));
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let case = &v["cases"][0];
    assert_eq!(case["dim"], "M");
    assert!((case["wing"]["chrdr"].as_f64().unwrap() - 0.44).abs() < 1e-12);
    assert_eq!(case["airfoils"].as_array().unwrap().len(), 3);
}

#[test]
fn help_everywhere() {
    for args in [
        vec!["--help"],
        vec!["check", "--help"],
        vec!["parse", "--help"],
        vec!["run", "--help"],
    ] {
        let out = bin().args(&args).output().unwrap();
        assert_eq!(out.status.code(), Some(0), "{args:?}");
        assert!(!out.stdout.is_empty());
    }
}

/// The README's main command: the AEROMECH I deck runs and prints its configuration pages with
/// static and dynamic derivatives.
#[test]
fn the_readme_main_command_prints_the_aeromech1_results() {
    let deck = format!("{}/namelists/aeromech1.dcm", env!("CARGO_MANIFEST_DIR"));
    let out = bin().args(["run", &deck]).output().unwrap();
    assert_eq!(out.status.code(), Some(0));
    let stdout = String::from_utf8_lossy(&out.stdout);
    for page in [
        "WING-BODY-VERTICAL TAIL-HORIZONTAL TAIL CONFIGURATION",
        "DYNAMIC DERIVATIVES",
        "AEROMECH",
    ] {
        assert!(stdout.contains(page), "no {page:?} in the output");
    }
}

/// `--original` is every rule of the original at once: the same output as the four options
/// given one by one, and (on a deck with a 5-digit wing) not the library's defaults.
#[test]
fn original_is_every_original_rule_at_once() {
    let deck = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("namelists/example-uav.dcm");
    let run = |extra: &[&str]| {
        let out = bin()
            .arg("run")
            .arg(&deck)
            .args(["--format", "json"])
            .args(extra)
            .output()
            .unwrap();
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        out.stdout
    };
    let all = run(&["--original"]);
    let one_by_one = run(&[
        "--reynolds",
        "original",
        "--five-digit",
        "original",
        "--six-a",
        "original",
        "--section-maximum",
        "last-rise",
        "--zero-lift",
        "original",
        "--forward-sweep",
        "original",
        "--tail-slope",
        "original",
        "--outboard-section",
        "original",
        "--jorgensen-drag",
        "original",
    ]);
    assert_eq!(all, one_by_one);
    assert_ne!(
        all,
        run(&[]),
        "the original's rules change this deck's numbers"
    );
}

/// A listing of the original that stopped at input errors has no result pages. It holds the
/// deck's cards (the original echoes them), so read as a deck it was run here and agreed with
/// ours in every number: `compare` and `report` reported 100 % against nothing.
#[test]
fn a_listing_without_results_is_refused_not_read_as_a_deck() {
    let dir = temp_dir("empty-listing");
    let deck = std::fs::read_to_string(example()).unwrap();
    let listing = dir.join("for006.dat");
    std::fs::write(
        &listing,
        format!(
            " THIS SOFTWARE AND ANY ACCOMPANYING DOCUMENTATION\n IS RELEASED \"AS IS\".\n\
             1                         CONERR - INPUT ERROR CHECKING\n\
             0 F - SYNTAX ERROR\n\
             1          THE FOLLOWING IS A LIST OF ALL INPUT CARDS FOR THIS CASE.\n{deck}\n\
             1 END OF JOB.\n"
        ),
    )
    .unwrap();
    let listing = listing.to_str().unwrap();
    for args in [
        ["compare", &example(), listing],
        ["report", &example(), &format!("--reference={listing}")],
    ] {
        let command = args[0];
        let out = bin().args(args).output().unwrap();
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{command}: {stderr}");
        assert!(
            stderr.contains("without any result page"),
            "{command}: {stderr}"
        );
        assert!(out.stdout.is_empty(), "{command}");
    }
    // Every listing has the input-checking page: one with a page of results (here of a kind
    // the importer does not read, as lkampoli ex10's hypersonic flap pages) is a reference
    // with nothing to compare, not a refusal.
    let with_page = dir.join("with-page.dat");
    std::fs::write(
        &with_page,
        format!(
            "{}1                               AUTOMATED STABILITY AND CONTROL METHODS PER APRIL 1976 VERSION OF DATCOM
                         HYPERSONIC FLAP CHARACTERISTICS
",
            std::fs::read_to_string(listing).unwrap()
        ),
    )
    .unwrap();
    let out = bin()
        .args(["compare", &example(), with_page.to_str().unwrap()])
        .output()
        .unwrap();
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
}
