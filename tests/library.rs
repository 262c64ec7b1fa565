//! The library without a deck: a case built in code (`examples/build_case.rs`) computes as the
//! same aircraft read from its deck.

mod common;

// The example's `main` is not called here, only its case.
#[allow(dead_code)]
#[path = "../examples/build_case.rs"]
mod build_case;

/// Whether a warning of `r` says `text`.
fn says(r: &datcom::results::CaseResults, text: &str) -> bool {
    r.warnings.iter().any(|w| w.to_string().contains(text))
}

/// An edit of the example's case.
type Edit = dyn Fn(&mut datcom::Case);

/// The example's case with `edit` applied, prepared and run.
fn run(edit: &Edit) -> datcom::results::CaseResults {
    let mut case = build_case::example_uav();
    edit(&mut case);
    case.prepare();
    datcom::results::run_case(&case)
}

#[test]
fn a_case_built_in_code_computes_as_its_deck() {
    let mut built = build_case::example_uav();
    assert!(
        built.conditions.is_empty(),
        "nothing derived before prepare"
    );
    let warnings = built.prepare();

    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("namelists/example-uav.dcm");
    let deck = datcom::read_deck_file(&path).expect("the bundled deck reads");
    let read = &deck.cases[0];
    assert_eq!(warnings, read.condition_warnings);
    assert_eq!(built.conditions, read.conditions);
    assert_eq!(built.flight, read.flight);

    let ours = datcom::results::run_case(&built);
    let theirs = datcom::results::run_case(read);
    assert_eq!(
        ours.conditions.len(),
        4,
        "two Mach numbers at two altitudes"
    );
    assert_eq!(ours.conditions, theirs.conditions);
    assert_eq!(ours.sections, theirs.sections);
    assert_eq!(ours.warnings, theirs.warnings);
}

/// Angles given out of order are put in order by `prepare`, which says so.
#[test]
fn prepare_orders_the_angles_and_says_so() {
    let mut case = build_case::example_uav();
    if let Some(f) = case.flight.as_mut() {
        f.alpha_deg = vec![4.0, 0.0, 2.0];
    }
    let warnings = case.prepare();
    assert_eq!(
        case.flight.as_ref().map(|f| f.alpha_deg.clone()),
        Some(vec![0.0, 2.0, 4.0])
    );
    assert!(
        warnings.iter().any(|w| w.contains("do not increase")),
        "{warnings:?}"
    );
    assert_eq!(case.conditions.len(), 4);
}

/// What a user of the API can forget: `prepare` after changing the flight input (the run then
/// derives the conditions itself and says so), the vertical tail's direction (up unless set),
/// and a case whose flight input is removed (no condition left behind).
#[test]
fn what_a_case_built_in_code_does_not_need() {
    assert!(
        datcom::case::Synthesis::default().vertup,
        "VERTUP defaults to up, as in a deck"
    );

    let mut case = build_case::example_uav();
    let prepared = {
        let mut c = case.clone();
        c.prepare();
        datcom::results::run_case(&c)
    };
    let unprepared = datcom::results::run_case(&case);
    assert_eq!(unprepared.conditions, prepared.conditions);
    assert!(
        unprepared.warnings[0]
            .to_string()
            .contains("Case::prepare was not called"),
        "{:?}",
        unprepared.warnings.first()
    );
    assert!(!prepared
        .warnings
        .iter()
        .any(|w| w.to_string().contains("Case::prepare")));

    // Stale: prepared, then the Mach numbers changed.
    case.prepare();
    if let Some(f) = case.flight.as_mut() {
        f.mach = vec![0.1];
    }
    let stale = datcom::results::run_case(&case);
    assert!(stale.conditions.iter().all(|c| c.condition.mach == 0.1));

    case.flight = None;
    case.prepare();
    assert!(case.conditions.is_empty() && case.condition_warnings.is_empty());
}

/// Values a deck's checks refuse reach a case built in code unchecked: the methods refuse them
/// (not computed, with a warning naming the value) instead of printing coefficients of 1e60,
/// and a reference dimension that is not a number is none in the results.
#[test]
fn values_a_deck_would_refuse_are_refused_in_code() {
    for (what, edit) in [
        (
            "SAVSI",
            &(|c: &mut datcom::Case| c.wing.as_mut().unwrap().savsi_deg = Some(90.0))
                as &dyn Fn(&mut datcom::Case),
        ),
        ("SSPNE", &|c: &mut datcom::Case| {
            c.wing.as_mut().unwrap().sspne = Some(7.0)
        }),
        ("CHRDTP", &|c: &mut datcom::Case| {
            c.wing.as_mut().unwrap().chrdtp = Some(-0.5)
        }),
        ("R(4)", &|c: &mut datcom::Case| {
            c.body.as_mut().unwrap().r[3] = -0.6
        }),
    ] {
        let r = run(edit);
        let page = &r.conditions[0];
        assert!(
            page.static_coefficients.cl.iter().all(Option::is_none),
            "{what}: {:?}",
            page.static_coefficients.cl
        );
        assert!(says(&r, &format!("{what} = ")), "{what}: {:?}", r.warnings);
    }
    // Not a number is not given: the wing's area is the reference, as without SREF, for the
    // results and for the methods (which said "no reference area" and gave no CL; found by
    // fuzzing the library).
    let r = run(&|c: &mut datcom::Case| c.reference.area = Some(f64::NAN));
    let wing_area = 2.0 * 1.20 * (0.44 + 0.32) / 2.0;
    assert_eq!(r.reference.area, Some(wing_area));
    let without = run(&|c: &mut datcom::Case| c.reference.area = None);
    assert_eq!(r.conditions, without.conditions);
    assert!(
        says(
            &r,
            "the case's $OPTINS SREF = NaN is not a number: not given"
        ),
        "{:?}",
        r.warnings
    );
}

/// Relative difference allowed between a value and the same value written in a deck's units and
/// read back: the unit conversions' rounding (a few units in the last place of f64).
const ROUND_TRIP: f64 = 1e-12;

/// `a` and `b` equal, numbers within [`ROUND_TRIP`]; the path of the first difference.
fn same(a: &serde_json::Value, b: &serde_json::Value, path: &str) -> Result<(), String> {
    use serde_json::Value as J;
    match (a, b) {
        (J::Number(x), J::Number(y)) => {
            let (x, y) = (
                x.as_f64().unwrap_or(f64::NAN),
                y.as_f64().unwrap_or(f64::NAN),
            );
            if (x - y).abs() <= ROUND_TRIP * x.abs().max(y.abs()) {
                Ok(())
            } else {
                Err(format!("{path}: {x} != {y}"))
            }
        }
        (J::Array(x), J::Array(y)) if x.len() == y.len() => x
            .iter()
            .zip(y)
            .enumerate()
            .try_for_each(|(i, (x, y))| same(x, y, &format!("{path}[{i}]"))),
        (J::Object(x), J::Object(y)) if x.len() == y.len() => x
            .iter()
            .try_for_each(|(k, v)| same(v, y.get(k).unwrap_or(&J::Null), &format!("{path}.{k}"))),
        _ if a == b => Ok(()),
        _ => Err(format!("{path}: {a} != {b}")),
    }
}

/// Every case of every deck without errors (the bundled ones; the oracle's and the corpus's when
/// ../shared is there), written as namelists and cards and read back, is the same case: `to_raw` writes
/// every typed value, in the deck's units. A case's deck diagnostics from `diagnose` are those
/// of the deck's own checks (without the reader's, which need the text).
#[test]
fn every_case_written_as_a_deck_reads_back_the_same() {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut decks = common::files(&root.join("namelists"));
    if let Some(dir) = common::shared_dir(
        "oracle/cases",
        "every_case_written_as_a_deck_reads_back_the_same",
    ) {
        decks.extend(
            std::fs::read_dir(dir)
                .into_iter()
                .flatten()
                .flatten()
                .map(|e| e.path().join("input.dcm")),
        );
    }
    if let Some(dir) = common::shared_dir(
        "corpus/decks",
        "every_case_written_as_a_deck_reads_back_the_same",
    ) {
        decks.extend(common::files(&dir));
    }
    let mut cases = 0;
    for path in &decks {
        let deck = datcom::read_deck(&common::text(path), &path.display().to_string());
        // A deck with errors lost the values the reader refused: not the case it meant.
        if deck.diagnostics.iter().any(|d| d.is_error()) {
            continue;
        }
        for case in &deck.cases {
            let (again, _) = datcom::Case::from_raw(&case.to_raw(), "again");
            let a = serde_json::to_value(case).expect("a case serializes");
            let b = serde_json::to_value(&again).expect("a case serializes");
            if let Err(e) = same(&a, &b, "case") {
                panic!("{} case {}: {e}", path.display(), case.number);
            }
            // Its written deck is as clean as the deck it came from.
            let errors: Vec<String> = case
                .diagnose()
                .iter()
                .filter(|d| d.is_error())
                .map(ToString::to_string)
                .collect();
            assert!(
                errors.is_empty(),
                "{} case {}: {errors:?}",
                path.display(),
                case.number
            );
            cases += 1;
        }
    }
    assert!(cases >= 6, "{cases} cases");
    eprintln!("{cases} cases of {} decks read back the same", decks.len());
}

/// A case built in code is checked as its deck would be: the example UAV is clean, and an
/// exposed semi-span beyond the semi-span is the deck's error, named with its variable.
#[test]
fn a_case_built_in_code_is_checked_as_a_deck() {
    let mut case = build_case::example_uav();
    case.prepare();
    let errors = |case: &datcom::Case| -> Vec<String> {
        case.diagnose()
            .iter()
            .filter(|d| d.is_error())
            .map(ToString::to_string)
            .collect()
    };
    assert_eq!(errors(&case), Vec::<String>::new());
    if let Some(w) = case.wing.as_mut() {
        w.sspne = Some(7.0);
    }
    let e = errors(&case);
    assert!(e.iter().any(|e| e.contains("[WGPLNF SSPNE]")), "{e:?}");
    // What only the reader sees of the written deck: more angles than ALSCHD holds, a value
    // that is not a number.
    let mut many = build_case::example_uav();
    if let Some(f) = many.flight.as_mut() {
        f.alpha_deg = (0..30).map(f64::from).collect();
    }
    let e = errors(&many);
    assert!(e.iter().any(|e| e.contains("ALSCHD")), "{e:?}");
    let mut nan = build_case::example_uav();
    if let Some(w) = nan.wing.as_mut() {
        w.savsi_deg = Some(f64::NAN);
    }
    let e = errors(&nan);
    assert!(
        e.iter()
            .any(|e| e.contains("[WGPLNF SAVSI]") && e.contains("not a number")),
        "{e:?}"
    );
    // The deck it writes is read by the reader as this case.
    let text = datcom::deck::writer::write_case(&build_case::example_uav().to_raw());
    let read = datcom::read_deck(&text, "written.dcm");
    assert!(
        !read.diagnostics.iter().any(|d| d.is_error()),
        "{:?}",
        read.diagnostics
    );
    let mut prepared = build_case::example_uav();
    prepared.prepare();
    assert_eq!(
        datcom::results::run_case(&read.cases[0]).conditions.len(),
        datcom::results::run_case(&prepared).conditions.len()
    );
}

/// Edits of a case read from a deck are what its deck is written with: the units (a metric
/// DIM for a deck in feet), the scale, the low-aspect-ratio wing-body; the values are written
/// as the shortest decimals that read back exactly.
#[test]
fn edits_are_what_the_deck_is_written_with() {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
    let deck = datcom::read_deck(&common::text(&root.join("namelists/navion.dcm")), "navion");
    let mut case = deck.cases[0].clone();
    assert_eq!(case.dim, datcom::deck::cards::Dim::Ft);
    let span = case.wing.as_ref().and_then(|w| w.sspn);
    case.dim = datcom::deck::cards::Dim::M;
    let (again, _) = datcom::Case::from_raw(&case.to_raw(), "again");
    assert_eq!(again.dim, datcom::deck::cards::Dim::M);
    assert_eq!(again.wing.as_ref().and_then(|w| w.sspn), span);

    let mut scaled = deck.cases[0].clone();
    scaled.scale = 2.0;
    let raw = scaled.to_raw();
    let (again, _) = datcom::Case::from_raw(&raw, "again");
    assert_eq!(again.scale, 2.0);
    assert_eq!(again.wing.as_ref().and_then(|w| w.sspn), span);

    // At other scales, read back to the conversion's rounding (no deck value gives some SI
    // values exactly: 2.19456 m at SCALE 0.1 in feet reads back as 2.1945599999999996).
    for scale in [0.1, 1.7, 7.0] {
        let mut scaled = deck.cases[0].clone();
        scaled.scale = scale;
        let (again, _) = datcom::Case::from_raw(&scaled.to_raw(), "again");
        let json = |c: &datcom::Case| serde_json::to_value(&c.wing).expect("serializes");
        if let Err(e) = same(&json(&scaled), &json(&again), "wing") {
            panic!("scale {scale}: {e}");
        }
    }
    // SCALE lives in $SYNTHS: a scaled case without one still reads back at its scale.
    let mut bare = build_case::example_uav();
    bare.synthesis = None;
    bare.scale = 2.0;
    let (again, _) = datcom::Case::from_raw(&bare.to_raw(), "again");
    assert_eq!((again.scale, again.wing), (2.0, bare.wing));

    let text = datcom::deck::writer::write_case(&deck.cases[0].to_raw());
    let long = text
        .split([',', '=', '\n', ' '])
        .filter(|t| t.parse::<f64>().is_ok())
        .filter(|t| t.len() > 12)
        .collect::<Vec<_>>();
    assert!(long.is_empty(), "numbers written long: {long:?}");
}

/// Fuzzing the library found a case's `scale` of 0, NaN or infinity taken as given: the
/// coefficients were computed, and the reference dimensions (turned back into the deck's by
/// the scale) came out as NaN or infinity, null in the JSON, with no warning. Such a scale is
/// taken as 1, with a warning naming it. So is a positive scale so small that the reference
/// dimensions divided by it overflow (1e-300: the reference block was null, with no warning).
#[test]
fn a_scale_that_is_not_a_positive_number_is_taken_as_one() {
    let mut plain = build_case::example_uav();
    plain.prepare();
    let expected = datcom::results::run_case(&plain);
    let reference = datcom::report::json::to_string(&datcom::Results {
        cases: vec![expected.clone()],
        file: String::new(),
    });
    let too_small = "overflow in the deck's units: taken as 1";
    let not_positive = "is not a positive number: taken as 1";
    for (scale, why) in [
        (0.0, not_positive),
        (-0.0, not_positive),
        (-2.0, not_positive),
        (f64::NAN, not_positive),
        (f64::INFINITY, not_positive),
        (1e-300, too_small),
        (f64::MIN_POSITIVE, too_small),
    ] {
        let mut case = plain.clone();
        case.scale = scale;
        let r = datcom::results::run_case(&case);
        assert!(says(&r, why), "scale {scale}: {:?}", r.warnings);
        assert_eq!(r.scale, 1.0);
        assert_eq!(r.conditions, expected.conditions, "scale {scale}");
        let mut without = r.clone();
        without.warnings.remove(0);
        let json = datcom::report::json::to_string(&datcom::Results {
            cases: vec![without],
            file: String::new(),
        });
        assert_eq!(json, reference, "scale {scale}");
        // `check` says so too (found by review: the deck written had the scale of 1).
        assert!(
            case.diagnose()
                .iter()
                .any(|d| d.severity == datcom::Severity::Error
                    && d.variable.as_deref() == Some("SCALE")),
            "scale {scale}"
        );
    }
}

/// A derivative per radian beyond f64::MAX/π overflowed to infinity when given per degree
/// (the product with π came first); found by fuzzing the library with a span of 1e-310.
#[test]
fn a_finite_derivative_stays_finite_per_degree() {
    use datcom::deck::cards::DerivUnit;
    let huge = 1e308;
    let per_degree = datcom::report::derivative_view(Some(huge), DerivUnit::Deg).unwrap();
    assert_eq!(per_degree, huge * (std::f64::consts::PI / 180.0));
    // Ordinary values keep the digits they have always had.
    let v = 0.0871_f64;
    assert_eq!(
        datcom::report::derivative_view(Some(v), DerivUnit::Deg),
        Some(v * std::f64::consts::PI / 180.0)
    );
}

/// Fuzzing the library found a schedule of one angle giving the configuration's first-row
/// moment terms as NaN (a drag slope from one point) through `methods::tail::configuration`:
/// there is no such term then, and the terms that are given are numbers.
#[test]
fn one_angle_gives_no_moment_terms_that_are_not_numbers() {
    let mut case = build_case::example_uav();
    case.flight.as_mut().unwrap().alpha_deg = vec![0.0];
    case.prepare();
    let totals = datcom::methods::tail::configuration(&case, 0, &[0.0]).expect("computed");
    let first = totals.terms.first_slopes.expect("first-row slopes");
    assert!(first.cla_per_rad.is_finite(), "{first:?}");
    // One point gives no slope of the wing-body's drag, so no wing-body moment term and no
    // CMA; the lift slope and the tail's term stand.
    assert_eq!(first.wing_body_moment, None, "{first:?}");
    assert_eq!(first.cma_per_rad, None, "{first:?}");
    assert!(first.tail_moment.is_some_and(f64::is_finite), "{first:?}");
}

/// How far the pitch damping CMQ at one angle may lie from the first row of the schedule −4
/// to 12 by 2: the tail's share takes the analytic slope at one angle and the slope of the
/// tail's CL curve in a schedule (a low-aspect-ratio straight tail, as the original reads it),
/// about 25 % apart for the example's tail; without the tail's share it was 98 % off.
const PITCH_DAMPING_SCHEDULE_SPREAD: f64 = 0.3;

/// The library review found a schedule of one angle giving wrong numbers without a word:
/// DATCOM's build-up reads slopes and the downwash from its curves over the schedule, and a
/// curve of one point was read with a slope of 0 (CLA 0.497 per rad where the schedule gives
/// 4.98; CM -0.088 where it gives +0.002; with BUILD, CLA = 0 on the combinations' pages).
/// At one angle the single components' pages keep their values at that angle (the same as
/// in a schedule), CLA and CMA are given only where they are a method's analytic slopes, the
/// pages with the downwash at the horizontal tail are not given, and a warning says why.
#[test]
fn one_angle_gives_no_slopes_and_no_downwash_pages_and_says_why() {
    let page = |r: &datcom::results::CaseResults, name: &str| {
        r.conditions
            .iter()
            .find(|c| c.configuration.starts_with(name) && c.condition.altitude == Some(0.0))
            .cloned()
            .unwrap_or_else(|| panic!("{name}"))
    };
    let full = run(&|c: &mut datcom::Case| c.cards.build = true);
    let at = full.conditions[0]
        .alpha_deg
        .iter()
        .position(|&a| a == 4.0)
        .expect("4 deg in the example's schedule");
    let one = run(&|c: &mut datcom::Case| {
        c.cards.build = true;
        c.flight.as_mut().unwrap().alpha_deg = vec![4.0];
    });
    assert!(says(
        &one,
        "one angle of attack: DATCOM's build-up reads slopes"
    ));
    for name in [
        "DATCOM BODY ALONE",
        "WING ALONE",
        "HORIZONTAL TAIL CONFIGURATION",
    ] {
        let (f, o) = (page(&full, name), page(&one, name));
        let (f, o) = (&f.static_coefficients, &o.static_coefficients);
        assert_eq!(
            (o.cl[0], o.cd[0], o.cm[0]),
            (f.cl[at], f.cd[at], f.cm[at]),
            "{name}"
        );
        assert!(o.cl[0].is_some(), "{name}");
    }
    let mut downwash_pages = 0;
    for (c, f) in one.conditions.iter().zip(&full.conditions) {
        let s = &c.static_coefficients;
        // The body's, the wing's and the tail's first-angle slopes are their methods'
        // analytic ones.
        let analytic = [
            "DATCOM BODY ALONE",
            "WING ALONE",
            "HORIZONTAL TAIL CONFIGURATION",
        ]
        .iter()
        .any(|p| c.configuration.starts_with(p));
        assert_eq!(
            (s.cla[0].is_some(), s.cma[0].is_some()),
            (analytic, analytic),
            "{}",
            c.configuration
        );
        if f.downwash.is_some() {
            downwash_pages += 1;
            assert!(c.downwash.is_none(), "{}", c.configuration);
            assert!(
                [&s.cl, &s.cd, &s.cm, &s.cn, &s.ca, &s.xcp]
                    .iter()
                    .all(|v| v[0].is_none()),
                "{}: {s:?}",
                c.configuration
            );
            // The sideslip derivatives do not rest on the downwash (the session review found
            // them left out), and the tail's share of the pitch damping is there (it was 0:
            // the low-aspect-ratio tail's first CLA was its flat curve's slope).
            assert!(
                s.cyb[0].is_some() && s.clb[0].is_some(),
                "{}",
                c.configuration
            );
            let (d, full_d) = (c.dynamic.as_ref().unwrap(), f.dynamic.as_ref().unwrap());
            let (one_cmq, full_cmq) = (d.cmq[0].unwrap(), full_d.cmq[0].unwrap());
            assert!(
                (one_cmq / full_cmq - 1.0).abs() < PITCH_DAMPING_SCHEDULE_SPREAD,
                "{}: CMQ {one_cmq} at one angle, {full_cmq} in the schedule",
                c.configuration
            );
        }
    }
    assert!(downwash_pages >= 2, "{downwash_pages}");
}

/// The library review found a method called on a case never prepared saying only "no flight
/// condition 0": it names `Case::prepare`.
#[test]
fn a_case_without_conditions_names_prepare() {
    let case = build_case::example_uav();
    let e = datcom::methods::wing::wing_alone(&case, 0, &[0.0, 4.0]).unwrap_err();
    assert!(e.to_string().contains("Case::prepare"), "{e}");
}

/// The library review found a wing of zero span reported as "the wing section cannot be
/// computed: planform: SSPN must be positive": the planform is at fault, and says so.
#[test]
fn a_planform_error_is_not_blamed_on_the_section() {
    let r = run(&|c: &mut datcom::Case| c.wing.as_mut().unwrap().sspn = Some(0.0));
    let texts = datcom::warning::texts(&r.warnings);
    assert!(
        texts.iter().any(|t| t.contains("wing planform: SSPN")),
        "{texts:?}"
    );
    assert!(
        !texts
            .iter()
            .any(|t| t.contains("section cannot be computed: planform")),
        "{texts:?}"
    );
}

/// The library review found common omissions said only through their consequences: a case
/// without $SYNTHS (six warnings of a wake ahead of the tail), and Mach 0 ("the Reynolds
/// number 0 is not a positive number" from the skin friction). The run names the cause.
#[test]
fn the_cause_of_common_omissions_is_named() {
    let r = run(&|c: &mut datcom::Case| c.synthesis = None);
    assert!(
        says(&r, "the case has no synthesis ($SYNTHS)"),
        "{:?}",
        r.warnings
    );
    let r = run(&|c: &mut datcom::Case| c.flight.as_mut().unwrap().mach[0] = 0.0);
    assert!(
        says(
            &r,
            "MACH(1) = 0 (conditions 1, 3) gives a Reynolds number of 0"
        ),
        "{:?}",
        r.warnings
    );
    let clean = run(&|_| {});
    assert!(!says(&clean, "no synthesis") && !says(&clean, "gives a Reynolds number of 0"));
}

/// The library review found `run_case` computing at 400° without a word, where `check`
/// gives an error (and named only the first such angle): the run says what `check` says of
/// the schedule, naming every angle.
#[test]
fn angles_beyond_the_methods_are_said_by_the_run() {
    let r = run(&|c: &mut datcom::Case| {
        c.flight.as_mut().unwrap().alpha_deg = vec![-200.0, 0.0, 4.0, 400.0];
    });
    assert!(
        says(
            &r,
            "alpha = -200, 400 deg: an angle of attack lies between -180 and 180 deg: computed as given"
        ),
        "{:?}",
        r.warnings
    );
    let r = run(&|c: &mut datcom::Case| {
        c.flight.as_mut().unwrap().alpha_deg = vec![0.0, 4.0, 95.0];
    });
    assert!(says(
        &r,
        "alpha = 95 deg: the wing and tail methods give no meaningful numbers at 90 deg and beyond"
    ));
    let mut case = build_case::example_uav();
    case.flight.as_mut().unwrap().alpha_deg = vec![-200.0, 0.0, 400.0];
    case.prepare();
    assert!(case.diagnose().iter().any(|d| d.is_error()
        && d.to_string()
            .contains("ALSCHD(1) = -200, ALSCHD(3) = 400 deg")));
}

/// Fuzzing the library found a NaN in a case's experimental data ($EXPR01 CDWB) put into the
/// wing-body's drag column, and a NaN section lift-curve slope (CLALPA) kept as the section's
/// slope: a value that is not a number is not given, and the case computes as without it.
#[test]
fn user_data_that_is_not_a_number_is_not_given() {
    let plain = run(&|_| {});
    let experimental = run(&|c: &mut datcom::Case| {
        c.other.entry("EXPR01".into()).or_default().insert(
            "CDWB".into(),
            datcom::deck::Value::Numbers(vec![None, Some(f64::NAN)]),
        );
    });
    assert_eq!(experimental.conditions, plain.conditions);
    // The example's wing has a NACA card and no section input: an empty one, and the same
    // with the values that are not numbers.
    let empty = run(&|c: &mut datcom::Case| {
        c.sections.entry("WING".into()).or_default();
    });
    let slope = run(&|c: &mut datcom::Case| {
        let wing = c.sections.entry("WING".into()).or_default();
        wing.per_mach.insert("CLALPA".into(), vec![f64::NAN]);
        wing.scalars.insert("LERI".into(), f64::NAN);
    });
    assert_eq!(slope.conditions, empty.conditions);
    assert_eq!(slope.sections, empty.sections);
}

/// Fuzzing the library found an altitude only reported (pressure and temperature given) of
/// f64::MAX, and a velocity only reported (with its Mach number) of f64::MIN, kept as the
/// flight condition's and printed as inf in feet: such a condition is not computed, and the
/// warning gives its values.
#[test]
fn a_reported_altitude_or_velocity_that_no_flight_has_is_refused() {
    for (what, edit) in [
        (
            "altitude",
            &(|c: &mut datcom::Case| {
                let f = c.flight.as_mut().unwrap();
                f.pressure = vec![101_325.0; f.mach.len()];
                f.temperature = vec![288.15; f.mach.len()];
                f.altitude = vec![f64::MAX; f.mach.len()];
            }) as &dyn Fn(&mut datcom::Case),
        ),
        ("velocity", &|c: &mut datcom::Case| {
            // Mach numbers and Reynolds numbers without an atmosphere: the velocity is only
            // reported.
            let f = c.flight.as_mut().unwrap();
            f.altitude.clear();
            f.reynolds_per_length = vec![1.0e6; f.mach.len()];
            f.velocity = vec![f64::MIN; f.mach.len()];
        }),
    ] {
        let r = run(edit);
        assert!(r.conditions.is_empty(), "{what}: {:?}", r.conditions.len());
        let csv = datcom::report::csv::to_string(&datcom::Results {
            file: String::new(),
            cases: vec![r.clone()],
        });
        assert!(!csv.contains("inf"), "{what}: {csv}");
    }
}

/// Words of a debug text that are a value that is not a number (`NaN`, `inf`, `-inf`).
fn not_numbers_in(text: &str) -> usize {
    text.split(|c: char| !c.is_alphanumeric())
        .filter(|w| *w == "NaN" || *w == "inf")
        .count()
}

/// Fuzzing the library found input geometry that is not a number (a CHSTAT of inf, a ZCG of
/// NaN, an ALIW of -inf) giving NaN in the partial output's values, where the coefficient
/// pages leave the numbers out: such an optional value is not given, and a warning names
/// each. The results are those of the case without it.
#[test]
fn an_optional_value_that_is_not_a_number_is_not_given() {
    let edits: [(&str, &Edit, &Edit); 5] = [
        (
            "$WGPLNF CHSTAT = inf",
            &|c| c.wing.as_mut().unwrap().chstat = Some(f64::INFINITY),
            &|c| c.wing.as_mut().unwrap().chstat = None,
        ),
        (
            "$SYNTHS ZCG = NaN",
            &|c| c.synthesis.as_mut().unwrap().zcg = Some(f64::NAN),
            &|c| c.synthesis.as_mut().unwrap().zcg = None,
        ),
        (
            "$SYNTHS ALIW = -inf",
            &|c| c.synthesis.as_mut().unwrap().aliw_deg = Some(f64::NEG_INFINITY),
            &|c| c.synthesis.as_mut().unwrap().aliw_deg = None,
        ),
        // SCALE beside the case's own `scale`, which the deck gives.
        (
            "$SYNTHS SCALE = NaN",
            &|c| c.synthesis.as_mut().unwrap().scale = Some(f64::NAN),
            &|c| c.synthesis.as_mut().unwrap().scale = None,
        ),
        (
            "$OPTINS CBARR = inf",
            &|c| c.reference.chord = Some(f64::INFINITY),
            &|c| c.reference.chord = None,
        ),
    ];
    for (named, bad, none) in edits {
        let r = run(&|c: &mut datcom::Case| {
            c.cards.part = true;
            bad(c)
        });
        let expected = run(&|c: &mut datcom::Case| {
            c.cards.part = true;
            none(c)
        });
        assert_eq!(not_numbers_in(&format!("{:?}", r.conditions)), 0, "{named}");
        assert_eq!(r.conditions, expected.conditions, "{named}");
        assert_eq!(r.sections, expected.sections, "{named}");
        assert!(
            says(
                &r,
                &format!("the case's {named} is not a number: not given")
            ),
            "{named}: {:?}",
            r.warnings
        );

        let mut case = build_case::example_uav();
        bad(&mut case);
        let listed = case.values_not_numbers();
        assert_eq!(listed.len(), 1, "{named}: {listed:?}");
        assert_eq!(listed[0].to_string(), named);
        // `check` says the same of the case.
        let said = listed[0].assignment();
        assert!(
            case.diagnose()
                .iter()
                .any(|d| d.severity == datcom::Severity::Error && d.to_string().contains(&said)),
            "{named}: diagnose does not say {said}"
        );
    }
    let clean = build_case::example_uav();
    assert!(clean.values_not_numbers().is_empty());
}

/// An element of an array that is not a number is refused where the array is read, which
/// says so: the flight condition at a Mach number that is not a number, the body with a
/// radius that is not one. The other conditions, and the other components, are computed.
/// (The review of the first fix found it read the case as a deck, where such an element ended
/// the array: every later Mach number was lost.)
#[test]
fn an_array_element_that_is_not_a_number_is_refused_where_it_is_read() {
    let plain = run(&|_| {});
    let mach = run(&|c: &mut datcom::Case| c.flight.as_mut().unwrap().mach[0] = f64::NAN);
    // The example pairs its two Mach numbers with two altitudes: the first Mach number's two
    // conditions are refused, the second's computed.
    assert_eq!(plain.conditions.len(), 4);
    assert_eq!(mach.conditions.len(), 2);
    assert!(mach.conditions.iter().all(|c| c.condition.mach == 0.09));
    for k in [1, 3] {
        let refused = format!("condition {k} not computed: Mach NaN");
        assert!(says(&mach, &refused), "{refused}: {:?}", mach.warnings);
    }
    let body = run(&|c: &mut datcom::Case| c.body.as_mut().unwrap().r[2] = f64::NAN);
    assert!(says(
        &body,
        "body geometry: R(3) = NaN (SI): must be finite"
    ));
    // The run names an element even where nothing reads it (a velocity beside Mach numbers;
    // found by fuzzing: the run said nothing while `check` gave an error).
    for (r, named) in [
        (&mach, "$FLTCON MACH(1) = NaN"),
        (&body, "$BODY R(3) = NaN"),
    ] {
        let said =
            format!("the case's {named} is not a number: kept in place, refused where it is read");
        assert!(says(r, &said), "{said}: {:?}", r.warnings);
    }
    let velocity =
        run(&|c: &mut datcom::Case| c.flight.as_mut().unwrap().velocity = vec![f64::NAN]);
    assert_eq!(velocity.conditions, plain.conditions);
    assert!(says(
        &velocity,
        "the case's $FLTCON VINF(1) = NaN is not a number: kept in place"
    ));
    for r in [&mach, &body] {
        assert_eq!(not_numbers_in(&format!("{:?}", r.conditions)), 0);
    }
    let mut case = build_case::example_uav();
    case.flight.as_mut().unwrap().mach[0] = f64::NAN;
    case.body.as_mut().unwrap().r[2] = f64::NAN;
    let listed: Vec<String> = case
        .values_not_numbers()
        .iter()
        .map(ToString::to_string)
        .collect();
    assert_eq!(listed, ["$FLTCON MACH(1) = NaN", "$BODY R(3) = NaN"]);

    // Section input under a surface name the library does not use is named by its keys (it
    // was named by its places, `sections{0}.scalars{0}`).
    let mut canard = build_case::example_uav();
    let mut section = datcom::case::SectionInput::default();
    section.scalars.insert("TOVC".into(), f64::NAN);
    canard.sections.insert("CANARD".into(), section);
    let listed: Vec<String> = canard
        .values_not_numbers()
        .iter()
        .map(ToString::to_string)
        .collect();
    assert_eq!(
        listed,
        ["sections{CANARD}.scalars{TOVC} = NaN (not in its deck)"]
    );
}

/// Fuzzing the library found a tiny positive value (1e-323) in a case with feet as units
/// panicking in the deck writer of a debug build, where it looked for the floats next to the
/// value in the deck's units below the least positive float. The panic was an overflow check:
/// this test fails without the fix in a debug build (`cargo test`, as CI runs it), not with
/// `--release`, where the subtraction wrapped to a NaN that was filtered out.
#[test]
fn a_tiny_value_is_written_in_other_units() {
    let mut case = build_case::example_uav();
    case.dim = datcom::deck::cards::Dim::Ft;
    let f = case.flight.as_mut().unwrap();
    f.reynolds_per_length = vec![1e-323; f.mach.len()];
    let raw = case.to_raw();
    let written = raw.namelists["FLTCON"]["RNNUB"].numbers().unwrap()[0];
    assert!(
        written.is_some_and(|r| (0.0..1e-300).contains(&r)),
        "{written:?}"
    );
    case.diagnose();
}
