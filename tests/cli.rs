//! The command line: exit codes 0/1/2, every subcommand, output files.

use std::process::Command;

fn bin() -> Command {
    Command::new(env!("CARGO_BIN_EXE_datcom-rs"))
}

fn example() -> String {
    format!("{}/namelists/example-uav.dcm", env!("CARGO_MANIFEST_DIR"))
}

/// `run DECK --format json EXTRA…`, which must succeed: its output.
fn run_json(deck: &std::path::Path, extra: &[&str]) -> Vec<u8> {
    let out = bin()
        .arg("run")
        .arg(deck)
        .args(["--format", "json"])
        .args(extra)
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{} {extra:?}: {}",
        deck.display(),
        String::from_utf8_lossy(&out.stderr)
    );
    out.stdout
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

/// `airfoil`: a --points out of range is a usage error (2; the user review found 1); a file
/// that is not coordinates is input with errors (1), as a deck with errors.
#[test]
fn airfoil_exit_codes() {
    let dir = temp_dir("airfoil");
    let good = dir.join("good.dat");
    std::fs::write(&good, "test\n1 0\n0.5 0.05\n0 0\n0.5 -0.05\n1 0\n").unwrap();
    let bad = dir.join("bad.dat");
    std::fs::write(&bad, "not coordinates\nx y z\n").unwrap();
    let code = |file: &std::path::Path, extra: &[&str]| {
        bin()
            .arg("airfoil")
            .arg(file)
            .args(extra)
            .output()
            .unwrap()
            .status
            .code()
    };
    assert_eq!(code(&good, &["--points", "60"]), Some(2));
    assert_eq!(code(&bad, &[]), Some(1));
    assert_eq!(code(&dir.join("missing.dat"), &[]), Some(2));
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
    // The CSV and the listing have no place for the cases' warnings: they go to stderr (the
    // user review found the CSV run said nothing of them).
    for format in ["csv", "for006"] {
        let out = bin()
            .args(["run", &example(), "--format", format])
            .output()
            .unwrap();
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert!(
            stderr.contains(" warning (case 1): Mach 0.06: dynamic derivatives:"),
            "{format}: {stderr}"
        );
        assert!(!String::from_utf8_lossy(&out.stdout).contains("warning (case"));
    }
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
    let run = |extra: &[&str]| run_json(&deck, extra);
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

/// `run`'s default text output was read back by `import`, `compare` and `report` as a listing,
/// its static table a column off: CL, CM and CLA null, CYB = 1 and CLB = -9.941 invented, 0/11
/// agreeing, exit 0. It is refused with a pointer to the formats that read back; so is any
/// file that is no listing, and a listing with no page that is read (exit 2: a file error).
#[test]
fn the_text_report_and_other_files_are_not_imported() {
    let dir = temp_dir("text-report");
    let deck = format!("{}/namelists/navion.dcm", env!("CARGO_MANIFEST_DIR"));
    let run = |format: &str| {
        let out = bin()
            .args(["run", &deck, "--format", format])
            .output()
            .unwrap();
        assert_eq!(out.status.code(), Some(0), "run --format {format}");
        let path = dir.join(format!("navion.{format}"));
        std::fs::write(&path, &out.stdout).unwrap();
        path.to_str().unwrap().to_string()
    };
    let (text, listing, csv) = (run("text"), run("for006"), run("csv"));
    for args in [
        vec!["import", &text],
        vec!["compare", &text, &deck],
        vec!["compare", &deck, &text],
        vec!["report", &deck, "--reference", &text],
    ] {
        let out = bin().args(&args).output().unwrap();
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{args:?}: {stderr}");
        assert!(
            stderr.contains("text report") && stderr.contains("--format for006"),
            "{args:?}: {stderr}"
        );
        assert!(out.stdout.is_empty(), "{args:?}");
    }
    let jet = dir.join("jet.dat");
    std::fs::write(
        &jet,
        " THIS SOFTWARE AND ANY ACCOMPANYING DOCUMENTATION
         1                          AUTOMATED STABILITY AND CONTROL METHODS PER APRIL 1976 VERSION OF DATCOM
                                                              SPECIAL CONTROL METHODS
",
    )
    .unwrap();
    let readme = format!("{}/README.md", env!("CARGO_MANIFEST_DIR"));
    for (file, says) in [
        (csv.as_str(), "not a listing"),
        (readme.as_str(), "not a listing"),
        (jet.to_str().unwrap(), "SPECIAL CONTROL METHODS"),
    ] {
        let out = bin().args(["import", file]).output().unwrap();
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{file}: {stderr}");
        assert!(stderr.contains(says), "{file}: {stderr}");
        assert!(out.stdout.is_empty(), "{file}");
    }
    // The listing of the same deck reads back, and agrees with the deck everywhere.
    let out = bin().args(["compare", &listing, &deck]).output().unwrap();
    assert_eq!(out.status.code(), Some(0));
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(stdout.lines().count() > 10, "{stdout}");
    for line in stdout.lines().skip(1) {
        assert!(line.contains(" 100.0%"), "{line}");
    }
}

/// `compare` took any file as a deck: a README, a TOML or CSV file, a JSON that is no result
/// compared as nothing, exit 0; a deck with errors was run without a word. Now the first is
/// refused (exit 2) and the second prints its diagnostics and is refused as the commands that
/// need a whole deck refuse it (exit 1).
#[test]
fn compare_refuses_what_is_no_result_and_a_deck_with_errors() {
    let dir = temp_dir("compare-files");
    let root = env!("CARGO_MANIFEST_DIR");
    let csv = dir.join("uav.csv");
    let out = bin()
        .args(["run", &example(), "--format", "csv"])
        .output()
        .unwrap();
    std::fs::write(&csv, &out.stdout).unwrap();
    let not_result = dir.join("other.json");
    std::fs::write(&not_result, "{\"a\": 1}\n").unwrap();
    // `parse` writes cases too, of typed input (the session review found it accepted).
    let parsed = dir.join("parsed.json");
    let out = bin().args(["parse", &example()]).output().unwrap();
    std::fs::write(&parsed, &out.stdout).unwrap();
    for (file, says) in [
        (format!("{root}/README.md"), "neither a deck"),
        (format!("{root}/Cargo.toml"), "neither a deck"),
        (csv.to_str().unwrap().to_string(), "neither a deck"),
        (
            not_result.to_str().unwrap().to_string(),
            "not of `run` or `import`",
        ),
        (
            parsed.to_str().unwrap().to_string(),
            "not of `run` or `import`",
        ),
    ] {
        for args in [
            ["compare", &example(), &file],
            ["compare", &file, &example()],
        ] {
            let out = bin().args(args).output().unwrap();
            let stderr = String::from_utf8_lossy(&out.stderr);
            assert_eq!(out.status.code(), Some(2), "{args:?}: {stderr}");
            assert!(stderr.contains(says), "{args:?}: {stderr}");
            assert!(out.stdout.is_empty(), "{args:?}");
        }
    }
    let misspelled = dir.join("m1.dcm");
    std::fs::write(
        &misspelled,
        std::fs::read_to_string(example())
            .unwrap()
            .replace("SSPNE=", "SSPNEE="),
    )
    .unwrap();
    let out = bin()
        .args(["compare", &example(), misspelled.to_str().unwrap()])
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(1), "{stderr}");
    assert!(
        stderr.contains("error [VTPLNF SSPNEE]: unknown variable SSPNEE"),
        "{stderr}"
    );
    assert!(stderr.contains("m1.dcm has"), "{stderr}");
    assert!(out.stdout.is_empty());
}

/// Two results with no flight condition in common showed every row missing without a word;
/// now `compare` says that no page was paired and names each side's conditions.
#[test]
fn compare_says_when_no_flight_condition_is_in_common() {
    let navion = format!("{}/namelists/navion.dcm", env!("CARGO_MANIFEST_DIR"));
    let out = bin()
        .args(["compare", &example(), &navion])
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(0), "{stderr}");
    for says in [
        "no page of the reference has a counterpart in ours",
        "ours has case 1: Mach 0.06 altitude 0, Mach 0.09 altitude 0",
        "the reference has case 1: Mach 0.158 altitude 0",
    ] {
        assert!(stderr.contains(says), "{says}: {stderr}");
    }
    let out = bin()
        .args(["compare", &example(), &example()])
        .output()
        .unwrap();
    assert!(
        out.stderr.is_empty(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
}

/// A deck compared with a listing of the original under the library's rules agrees on 0-15 %
/// of most columns (100 % with --original), and nothing said so: now a hint names --original.
/// Not with --original, nor against our own listing (`--format for006`, which has neither the
/// original's disclaimer nor its input-checking page).
#[test]
fn compare_with_a_listing_of_the_original_hints_at_original() {
    let dir = temp_dir("original-hint");
    let ours = dir.join("ours.out");
    let out = bin()
        .args(["run", &example(), "--format", "for006"])
        .output()
        .unwrap();
    std::fs::write(&ours, &out.stdout).unwrap();
    let original = dir.join("for006.dat");
    std::fs::write(
        &original,
        [
            &b" THIS SOFTWARE AND ANY ACCOMPANYING DOCUMENTATION\n"[..],
            &out.stdout,
        ]
        .concat(),
    )
    .unwrap();
    let hint = |args: &[&str]| {
        let out = bin().args(args).output().unwrap();
        let stderr = String::from_utf8_lossy(&out.stderr).into_owned();
        assert_eq!(out.status.code(), Some(0), "{args:?}: {stderr}");
        stderr.contains("hint:") && stderr.contains("--original")
    };
    let (original, ours) = (original.to_str().unwrap(), ours.to_str().unwrap());
    assert!(hint(&["compare", &example(), original]));
    assert!(hint(&["compare", original, &example()]));
    assert!(hint(&["report", &example(), "--reference", original]));
    assert!(!hint(&["compare", &example(), original, "--original"]));
    assert!(!hint(&["compare", &example(), ours]));
    assert!(!hint(&["compare", ours, original]));
}

/// Each rule flag on a deck it changes: `--X original` differs from the default, `--X`
/// with the default's value does not. (`--original` sets every rule without reading the
/// flags, so only this catches a flag mapped to the wrong rule.)
#[test]
fn each_rule_flag_changes_the_deck_it_is_about() {
    let dir = temp_dir("rules");
    let low_aspect_ratio_tail = " $FLTCON NMACH=1.0, MACH(1)=0.28, NALT=1.0, ALT(1)=10.0,\n   \
        NALPHA=6.0, ALSCHD(1)=-50.0,-5.0,0.0,5.0,10.0,14.0$\n \
        $OPTINS SREF=235.0, CBARR=6.3, BLREF=37.5$\n \
        $SYNTHS XCG=8.25, ZCG=-1.0, XW=6.25, ZW=-2.33, ALIW=1.0, XH=22.8, ZH=1.06, ALIH=2.0$\n \
        $BODY NX=6.0, X(1)=-3.0,-0.75,2.0,8.7,20.0,27.0, R(1)=0.1,1.25,2.5,3.0,3.0,0.4$\n\
        NACA-W-6-63A216\n \
        $WGPLNF CHRDTP=4.0, SSPNE=16.25, SSPN=18.75, CHRDR=8.67, SAVSI=0.0, TYPE=1.0$\n\
        NACA-H-6-63A014\n \
        $HTPLNF CHRDTP=2.5, SSPNE=5.7, SSPN=6.6, CHRDR=4.5, SAVSI=0.0, TYPE=1.0$\nBUILD\n";
    let double_delta = " $FLTCON NMACH=1.0, MACH(1)=0.2, NALT=1.0, ALT(1)=0.0,\n   \
        NALPHA=3.0, ALSCHD(1)=0.0, 4.0, 8.0$\n $OPTINS SREF=2.2, CBARR=0.6, BLREF=4.0$\n \
        $SYNTHS XCG=0.5, ZCG=0.0, XW=0.2, ZW=0.0$\n \
        $WGPLNF CHRDR=1.2, CHRDBP=0.6, CHRDTP=0.3, SSPN=2.0, SSPNOP=1.4, SSPNE=2.0,\n   \
        SAVSI=50.0, SAVSO=20.0, CHSTAT=0.0, TYPE=2.0$\nNACA-W-4-4412\n \
        $WGSCHR CMO=-0.2, TOVC=0.15$\n";
    let jorgensen_body = " $FLTCON NMACH=1.0, MACH(1)=0.3, NALT=1.0, ALT(1)=0.0,\n   \
        NALPHA=4.0, ALSCHD(1)=0.0, 8.0, 16.0, 24.0$\n $OPTINS SREF=300.0, CBARR=6.0, BLREF=50.0$\n \
        $SYNTHS XCG=30.0, ZCG=0.0, XW=25.0, ZW=0.0$\n \
        $BODY NX=5.0, X(1)=0.0,10.0,40.0,60.0,70.0, R(1)=0.0,2.5,3.0,3.0,1.0, METHOD=2.0$\n \
        $WGPLNF CHRDR=8.0, CHRDTP=4.0, SSPN=25.0, SSPNE=22.0, SAVSI=5.0, TYPE=1.0$\n\
        NACA-W-4-2412\n";
    let forward_swept = " $FLTCON NMACH=1.0, MACH(1)=0.6, NALPHA=3.0, ALSCHD(1)=0.0,4.0,8.0$\n \
        $OPTINS SREF=2.25, CBARR=0.822, BLREF=3.0$\n $SYNTHS XCG=2.6, ZCG=0.0, XW=1.7, ZW=0.0$\n \
        $BODY NX=4.0, X(1)=0.0,0.5,3.5,4.5, R(1)=0.0,0.2,0.2,0.1$\n \
        $WGPLNF CHRDR=1.16, CHRDTP=0.346, SSPN=1.5, SSPNE=1.29, SAVSI=-55.0, TYPE=1.0$\n\
        NACA-W-4-0006\n";
    for (flag, default, text) in [
        ("--tail-slope", "handbook", low_aspect_ratio_tail),
        ("--outboard-section", "uniform", double_delta),
        ("--jorgensen-drag", "handbook", jorgensen_body),
        ("--forward-sweep", "handbook", forward_swept),
    ] {
        let deck = dir.join(format!("{}.dcm", flag.trim_start_matches('-')));
        std::fs::write(&deck, text).unwrap();
        let run = |extra: &[&str]| run_json(&deck, extra);
        let plain = run(&[]);
        assert_ne!(
            run(&[flag, "original"]),
            plain,
            "{flag} original changes nothing"
        );
        assert_eq!(
            run(&[flag, default]),
            plain,
            "{flag} {default} is not the default"
        );
    }
}
