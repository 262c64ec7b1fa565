//! The deck dialect we accept and the diagnostics we give, one behaviour per test.

use datcom::deck::{self, Value};
use datcom::{DeckProblem, Severity};

const MINIMAL: &str =
    " $FLTCON NMACH=1.0, MACH(1)=0.4, NALPHA=2.0, ALSCHD(1)=0.0,2.0$\n $SYNTHS XCG=1.0$\n";

fn read(text: &str) -> datcom::Deck {
    datcom::read_deck(text, "t.dcm")
}

fn errors(d: &datcom::Deck) -> Vec<&datcom::Diagnostic> {
    d.diagnostics.iter().filter(|x| x.is_error()).collect()
}

fn numbers(raw: &deck::RawCase, nl: &str, var: &str) -> Vec<Option<f64>> {
    match raw.namelists[nl].get(var) {
        Some(Value::Numbers(v)) => v.clone(),
        other => panic!("{nl}.{var}: {other:?}"),
    }
}

#[test]
fn unknown_variable_gets_the_nearest_name() {
    let d = read(&format!(
        "{MINIMAL} $WGPLNF CHRDR=2.0, SSPN=5.0, DHDAHI=3.0$\nNACA-W-4-0012\n"
    ));
    let e = errors(&d);
    assert_eq!(e.len(), 1, "{e:?}");
    let e = e[0];
    assert_eq!((e.line, e.column), (3, 31));
    assert_eq!(e.card.as_deref(), Some("WGPLNF"));
    assert_eq!(e.variable.as_deref(), Some("DHDAHI"));
    assert_eq!(e.hint.as_deref(), Some("did you mean DHDADI?"));
    assert_eq!(
        e.to_string(),
        "t.dcm:3:31: error [WGPLNF DHDAHI]: unknown variable DHDAHI in $WGPLNF (hint: did you mean DHDADI?)"
    );
}

#[test]
fn variable_of_another_namelist_is_named() {
    let d = read(" $FLTCON NMACH=1.0, MACH(1)=0.4, XCG=3.0$\n");
    let e = errors(&d);
    assert!(
        e.iter()
            .any(|e| e.hint.as_deref() == Some("XCG is a variable of $LARWB, $SYNTHS")),
        "{e:?}"
    );
}

#[test]
fn nalpha_beyond_the_values_given() {
    let d = read(" $FLTCON NMACH=1.0, MACH(1)=0.4, NALPHA=11.0,\n   ALSCHD(1)=1.,2.,3.,4.,5.,6.,7.,8.,9.,10.$\n $SYNTHS XCG=1.0$\n");
    let w: Vec<_> = d
        .diagnostics
        .iter()
        .filter(|x| matches!(x.problem, DeckProblem::CountMismatch { .. }))
        .collect();
    assert_eq!(w.len(), 1);
    // The original runs it and prints the 11th angle as NDM: a warning, not an error.
    assert_eq!(w[0].severity, Severity::Warning);
    assert!(
        w[0].to_string()
            .contains("NALPHA=11 but ALSCHD has 10 values"),
        "{}",
        w[0]
    );
    assert_eq!(d.cases[0].flight.as_ref().unwrap().alpha_deg.len(), 10);
}

#[test]
fn unterminated_namelist_names_what_it_swallows() {
    let text = " $FLTCON NMACH=1.0, MACH(1)=0.4, NALPHA=1.0, ALSCHD(1)=0.0$\n $SYNTHS XCG=1.0, XW=1.2\nNACA-W-4-0012\nCASEID X\n $BODY NX=2.0, X(1)=0.0,1.0$\n";
    let d = read(text);
    let e = errors(&d);
    let u = e
        .iter()
        .find(|x| matches!(x.problem, DeckProblem::UnterminatedNamelist { .. }))
        .expect("unterminated namelist reported");
    assert_eq!(u.line, 2);
    match &u.problem {
        DeckProblem::UnterminatedNamelist { swallowed, .. } => {
            assert_eq!(
                swallowed,
                &vec![
                    "NACA-W-4-0012".to_string(),
                    "CASEID X".into(),
                    "$BODY".into()
                ]
            );
        }
        _ => unreachable!(),
    }
    // Reading goes on: the NACA card, CASEID and $BODY are all read.
    assert_eq!(d.cases[0].airfoils.len(), 1);
    assert_eq!(d.cases[0].caseid.as_deref(), Some("X"));
    assert!(d.cases[0].body.is_some());
}

#[test]
fn assignment_outside_any_namelist() {
    let d = read(&format!("{MINIMAL}  SSPN=5.0,\n"));
    let e = errors(&d);
    assert_eq!(e.len(), 1);
    assert!(matches!(
        e[0].problem,
        DeckProblem::AssignmentOutsideNamelist { .. }
    ));
    assert_eq!(e[0].line, 3);
    assert!(
        e[0].hint.as_deref().unwrap().contains("$WGPLNF"),
        "{}",
        e[0]
    );
}

#[test]
fn missing_comma_on_one_card_is_an_error_but_a_card_end_separates() {
    let d = read(" $FLTCON NMACH=1.0 MACH(1)=0.4, NALPHA=1.0,\n ALSCHD(1)=0.0\n LOOP=1.0$\n $SYNTHS XCG=1.0$\n");
    let e = errors(&d);
    assert_eq!(e.len(), 1, "{e:?}");
    assert!(matches!(e[0].problem, DeckProblem::MissingComma { .. }));
    assert_eq!((e[0].line, e[0].column), (1, 20));
    let raw = deck::read(
        " $FLTCON NMACH=1.0 MACH(1)=0.4, NALPHA=1.0,\n ALSCHD(1)=0.0\n LOOP=1.0$\n",
        "t",
    );
    assert_eq!(numbers(&raw.cases[0], "FLTCON", "LOOP"), vec![Some(1.0)]);
    assert_eq!(numbers(&raw.cases[0], "FLTCON", "MACH"), vec![Some(0.4)]);
}

#[test]
fn every_problem_in_one_pass() {
    let text = " $FLTCON NMACH=1.0, MACH(1)=0.4, NALPHA=1.0, ALSCHD(1)=0.0, FOO=1.0$\n $SYNTHS XCG=1.0, BAR=2.0$\nBOGUS CARD\n $BODY NX=2.0, X(1)=0.0,1.0, BAZ=3.0$\n";
    let d = read(text);
    let lines: Vec<usize> = errors(&d).iter().map(|e| e.line).collect();
    assert_eq!(lines, vec![1, 2, 3, 4]);
}

#[test]
fn dialect_of_real_decks() {
    // Indexed and unindexed arrays, continuation, repeat counts, exponents, leading and
    // trailing dots, integers, blanks around `=`, trailing comma, `$` alone on a line, `$NAME`
    // alone on a line, TABs, CRLF, DATCOM+ comments, `!` comments, no final newline.
    let text = "* a DATCOM+ comment\r\n# another\r\nDIM FT\r\n $FLTCON\r\n\tNMACH = 2, MACH = .2, 3.E-1 ,\r\n  NALPHA=3., ALSCHD(1)=-2.,\r\n  0, 2*4.0, ! trailing comment\r\n  RNNUB(1)=1.07E6,2.0E+6,\r\n$\r\n $SYNTHS XCG=1.0, VERTUP=.FALSE.$";
    let d = read(text);
    assert!(errors(&d).is_empty(), "{:?}", errors(&d));
    let raw = deck::read(text, "t");
    let c = &raw.cases[0];
    assert_eq!(numbers(c, "FLTCON", "MACH"), vec![Some(0.2), Some(0.3)]);
    assert_eq!(
        numbers(c, "FLTCON", "ALSCHD"),
        vec![Some(-2.0), Some(0.0), Some(4.0), Some(4.0)]
    );
    assert_eq!(
        numbers(c, "FLTCON", "RNNUB"),
        vec![Some(1.07e6), Some(2.0e6)]
    );
    assert_eq!(
        c.namelists["SYNTHS"]["VERTUP"],
        Value::Logicals(vec![Some(false)])
    );
    let f = d.cases[0].flight.as_ref().unwrap();
    assert_eq!(
        f.alpha_deg,
        vec![-2.0, 0.0, 4.0],
        "NALPHA=3 limits the angles used"
    );
    let notes: Vec<String> = d
        .diagnostics
        .iter()
        .filter(|x| x.severity == Severity::Note)
        .map(|x| x.problem.to_string())
        .collect();
    for what in ["DATCOM+ comment card", "TAB", "`!` comment"] {
        assert!(
            notes.iter().any(|n| n.contains(what)),
            "note for {what}: {notes:?}"
        );
    }
}

#[test]
fn same_key_twice_last_wins_with_a_warning() {
    let d = read(" $FLTCON NMACH=1.0, MACH(1)=0.4, MACH(1)=0.5, NALPHA=1.0, ALSCHD(1)=0.0$\n $SYNTHS XCG=1.0$\n");
    assert_eq!(d.cases[0].flight.as_ref().unwrap().mach, vec![0.5]);
    let w: Vec<_> = d
        .diagnostics
        .iter()
        .filter(|x| matches!(x.problem, DeckProblem::Reassigned { .. }))
        .collect();
    assert_eq!(w.len(), 1);
    assert_eq!(
        (w[0].line, w[0].column, w[0].severity),
        (1, 34, Severity::Warning)
    );
}

#[test]
fn same_namelist_twice_merges() {
    let raw = deck::read(
        " $BODY NX=3.0, X(1)=0.0,1.0,2.0$\n $BODY X(2)=1.5, R(1)=0.1,0.2,0.1$\n",
        "t",
    );
    let c = &raw.cases[0];
    assert_eq!(
        numbers(c, "BODY", "X"),
        vec![Some(0.0), Some(1.5), Some(2.0)]
    );
    assert_eq!(numbers(c, "BODY", "NX"), vec![Some(3.0)]);
    assert_eq!(numbers(c, "BODY", "R").len(), 3);
}

#[test]
fn save_carries_namelists_and_naca_cards_not_other_cards() {
    let text = "DIM M\nDERIV RAD\nDAMP\nCASEID ONE\n $FLTCON NMACH=1.0, MACH(1)=0.4$\nNACA-W-4-0012\nSAVE\nNEXT CASE\n $SYNTHS XCG=1.0$\nNEXT CASE\n $FLTCON NMACH=1.0, MACH(1)=0.5$\n";
    let raw = deck::read(text, "t");
    assert_eq!(raw.cases.len(), 3);
    let (a, b, c) = (&raw.cases[0], &raw.cases[1], &raw.cases[2]);
    assert!(a.save && a.cards.damp);
    assert_eq!(b.namelists.keys().collect::<Vec<_>>(), ["FLTCON", "SYNTHS"]);
    assert_eq!(b.airfoils.len(), 1, "NACA cards are carried by SAVE");
    assert_eq!(b.caseid, None, "CASEID is not carried");
    assert!(!b.cards.damp, "DAMP is not carried");
    assert_eq!(
        b.cards.dim,
        Some(datcom::deck::cards::Dim::M),
        "DIM persists"
    );
    assert_eq!(
        b.cards.deriv,
        Some(datcom::deck::cards::DerivUnit::Rad),
        "DERIV persists"
    );
    // Case 2 had no SAVE: case 3 starts afresh (but DIM and DERIV persist).
    assert_eq!(c.namelists.keys().collect::<Vec<_>>(), ["FLTCON"]);
    assert!(c.airfoils.is_empty());
    assert_eq!(c.cards.dim, Some(datcom::deck::cards::Dim::M));
}

#[test]
fn data_past_column_80_is_read_with_a_warning() {
    let line = format!(
        " $FLTCON NMACH=1.0, MACH(1)=0.4,{}NALPHA=1.0, ALSCHD(1)=0.0$",
        " ".repeat(50)
    );
    let d = read(&format!("{line}\n $SYNTHS XCG=1.0$\n"));
    let w: Vec<_> = d
        .diagnostics
        .iter()
        .filter(|x| matches!(x.problem, DeckProblem::PastColumn80 { .. }))
        .collect();
    assert_eq!(w.len(), 1);
    assert_eq!(
        (w[0].line, w[0].column, w[0].severity),
        (1, 81, Severity::Warning)
    );
    assert_eq!(d.cases[0].flight.as_ref().unwrap().alpha_deg, vec![0.0]);
}

#[test]
fn naca_cards_in_dash_and_blank_forms() {
    let d = read(&format!("{MINIMAL}NACA-W-6-643-618\nNACA H 4 0012\n"));
    let a = &d.cases[0].airfoils;
    assert_eq!(a.len(), 2);
    assert_eq!(a[0].designation, "643-618");
    assert_eq!(a[1].designation, "0012");
}

#[test]
fn units_are_converted_at_the_edge() {
    let d = read("DIM IN\n $FLTCON NMACH=1.0, MACH(1)=0.4, NALPHA=1.0, ALSCHD(1)=0.0$\n $SYNTHS XCG=12.0$\n $OPTINS SREF=144.0$\n");
    let c = &d.cases[0];
    assert!((c.synthesis.as_ref().unwrap().xcg.unwrap() - 0.3048).abs() < 1e-12);
    assert!((c.reference.area.unwrap() - 0.3048 * 0.3048).abs() < 1e-12);
}

#[test]
fn physical_checks() {
    let d = read(&format!(
        "{MINIMAL} $WGPLNF CHRDR=-2.0, SSPN=5.0, SSPNE=6.0$\nNACA-W-4-0012\n $BODY NX=3.0, X(1)=0.0,2.0,1.0, R(1)=0.1,-0.2,0.1$\n"
    ));
    let msgs: Vec<String> = errors(&d).iter().map(|e| e.problem.to_string()).collect();
    for want in [
        "CHRDR must be positive",
        "SSPNE is larger than the semi-span",
        "X(3)=1 is less than X(2)=2",
        "R(2) must not be negative; found -0.2",
    ] {
        assert!(msgs.iter().any(|m| m.contains(want)), "{want}: {msgs:?}");
    }
}

/// CHSTAT is a station along the chord, a fraction of it: outside 0 to 1 the sweep
/// conversions extrapolate the planform (CHSTAT = 1e10 gave CD ~ 1e81, unreported).
#[test]
fn chord_station_is_a_fraction_of_the_chord() {
    for (chstat, bad) in [
        ("1.0E10", true),
        ("-0.5", true),
        ("1.0", false),
        ("0.25", false),
    ] {
        let d = read(&format!(
            "{MINIMAL} $HTPLNF CHRDR=0.18, CHRDTP=0.14, SSPN=0.195, SSPNE=0.18, CHSTAT={chstat}$\n"
        ));
        let msgs: Vec<String> = errors(&d).iter().map(|e| e.problem.to_string()).collect();
        let found = msgs
            .iter()
            .any(|m| m.contains("CHSTAT =") && m.ends_with("is outside 0 to 1"));
        assert_eq!(found, bad, "CHSTAT={chstat}: {msgs:?}");
    }
}

/// A body whose lower contour rises above its upper one has a negative height there: the
/// sideslip charts were read at NaN (found by fuzzing). Likewise negative $LARWB areas.
#[test]
fn contours_and_lifting_body_areas_are_checked() {
    let body = |zl5: &str| {
        read(&format!(
            "{MINIMAL} $BODY NX=3.0, X(1)=0.0,1.0,2.0, ZU(1)=0.0,0.5,0.0, ZL(1)=0.0,{zl5},0.0$\n"
        ))
    };
    let crossing = |d: &datcom::Deck| {
        errors(d).iter().any(|e| {
            e.problem
                .to_string()
                .contains("ZL(2)=0.7 is above ZU(2)=0.5")
        })
    };
    assert!(crossing(&body("0.7")));
    assert!(!crossing(&body("-0.5")), "{:?}", errors(&body("-0.5")));
    let larwb = read(&format!(
        "{MINIMAL} $LARWB ZB=0.0, SREF=10.0, L=5.0, SBASE=-1.0, SWET=40.0$\n"
    ));
    assert!(
        errors(&larwb)
            .iter()
            .any(|e| e.problem.to_string().contains("SBASE must not be negative")),
        "{:?}",
        errors(&larwb)
    );
}

/// The methods divide by the cosine of a sweep, a dihedral or an incidence: at 90 deg the
/// coefficients reached 1e170 unreported (found by fuzzing). A section's thickness ratio and
/// its station are fractions of the chord (a real deck gives XOVC=31).
#[test]
fn right_angles_and_chord_fractions_are_errors() {
    let planform = |var: &str, v: &str| {
        read(&format!(
            "{MINIMAL} $WGPLNF CHRDR=2.0, CHRDTP=1.0, SSPN=5.0, SSPNE=4.0, {var}={v}$\nNACA-W-4-0012\n"
        ))
    };
    let has = |d: &datcom::Deck, text: &str| {
        errors(d)
            .iter()
            .any(|e| e.problem.to_string().contains(text))
    };
    for var in ["SAVSI", "SAVSO", "DHDADI", "DHDADO"] {
        assert!(
            has(&planform(var, "90.0"), &format!("{var} = 90 deg")),
            "{var}"
        );
        assert!(
            has(&planform(var, "-135.0"), &format!("{var} = -135 deg")),
            "{var}"
        );
        assert!(errors(&planform(var, "89.0")).is_empty(), "{var}");
    }
    let incidence = read(&format!(
        "{MINIMAL} $SYNTHS XCG=1.0, ALIW=90.0, ALIH=-2.0$\n"
    ));
    assert!(has(&incidence, "ALIW = 90 deg"));
    assert!(!has(&incidence, "ALIH"));
    let section = |var: &str, v: &str| {
        read(&format!(
            "{MINIMAL} $WGPLNF CHRDR=2.0, SSPN=5.0, SSPNE=4.0$\n $WGSCHR {var}={v}$\n"
        ))
    };
    assert!(has(&section("XOVC", "31.0"), "XOVC = 31 is outside 0 to 1"));
    assert!(has(&section("TOVC", "10.0"), "TOVC = 10 is outside 0 to 1"));
    assert!(errors(&section("TOVC", "0.12")).is_empty());
    assert!(has(
        &section("DELTAY", "-1.0"),
        "DELTAY must not be negative"
    ));
}

/// Angles of attack: none beyond ±180 deg (15000 was read); from ±90 deg with a lifting
/// surface a warning (CM reached 1e34 at -90 deg, found by fuzzing), none for a body alone.
#[test]
fn angles_of_attack_beyond_a_right_angle() {
    let deck = |alpha: &str, wing: bool| {
        let planform = if wing {
            " $WGPLNF CHRDR=2.0, SSPN=5.0, SSPNE=4.0$\n"
        } else {
            ""
        };
        read(&format!(
            " $FLTCON NMACH=1.0, MACH(1)=0.3, NALPHA=2.0, ALSCHD(1)=0.0,{alpha}$\n $SYNTHS XCG=1.0$\n $BODY NX=3.0, X(1)=0.0,1.0,2.0, R(1)=0.0,0.2,0.0$\n{planform}"
        ))
    };
    let said = |d: &datcom::Deck, severity: Severity, text: &str| {
        d.diagnostics
            .iter()
            .any(|x| x.severity == severity && x.problem.to_string().contains(text))
    };
    assert!(said(
        &deck("15000.0", false),
        Severity::Error,
        "ALSCHD(2) = 15000 deg"
    ));
    assert!(said(
        &deck("-90.0", true),
        Severity::Warning,
        "ALSCHD(2) = -90 deg"
    ));
    // Fuzzing found CM of 1e33 at -90 deg and CMA of 5e31 at 0 deg, its neighbour in the
    // schedule: the warning names the slopes too.
    assert!(said(
        &deck("-90.0", true),
        Severity::Warning,
        "nor the slopes CLA and CMA at the angles next to this one"
    ));
    let body_alone = deck("135.0", false);
    assert!(!said(&body_alone, Severity::Warning, "ALSCHD"));
    assert!(errors(&body_alone).is_empty(), "{:?}", errors(&body_alone));
    assert!(!said(&deck("89.0", true), Severity::Warning, "ALSCHD"));
}

#[test]
fn neither_mach_nor_velocity() {
    let d = read(" $FLTCON NALPHA=1.0, ALSCHD(1)=0.0, NALT=1.0, ALT(1)=0.0$\n $SYNTHS XCG=1.0$\n");
    assert!(errors(&d)
        .iter()
        .any(|e| e.problem.to_string().contains("neither MACH nor VINF")));
}

#[test]
fn velocity_and_altitude_without_mach_does_not_hang() {
    // The original loops forever on this deck (VINF and ALT, no MACH, an airfoil card).
    let d = read(" $FLTCON NMACH=1.0, VINF(1)=200.0, NALT=1.0, ALT(1)=1000.0, NALPHA=1.0, ALSCHD(1)=0.0$\n $SYNTHS XCG=1.0$\n $WGPLNF CHRDR=2.0, SSPN=5.0, SSPNE=4.0, CHRDTP=1.0$\nNACA-W-4-0012\n");
    assert!(errors(&d).is_empty(), "{:?}", errors(&d));
    let r = datcom::run(&d);
    let c = &r.cases[0].conditions[0].condition;
    // 200 ft/s at 1000 ft: a = 49.01685·sqrt(514.69 °R) = 1112.0 ft/s.
    assert!((c.mach - 200.0 / 1112.0).abs() < 5e-4, "{}", c.mach);
}

#[test]
fn missile_datcom_is_refused() {
    let d = read("CASEID X\n$FLTCON NALPHA=1., MACH=2.0$\n$REFQ XCG=1.0$\n$AXIBOD LNOSE=1.0$\n");
    assert_eq!(d.diagnostics.len(), 1);
    assert!(d.diagnostics[0].to_string().contains("Missile DATCOM"));
}

#[test]
fn broken_input_never_panics() {
    for text in [
        "",
        "$",
        " $",
        " $FLTCON",
        "$$$$",
        "NACA",
        "NACA-",
        "DIM",
        "X(",
        " $BODY X(0)=1$",
        " $BODY X(99)=1$",
        " $BODY X(1)=999999*1$",
        "\u{0}\u{1}",
        " $FLTCON MACH=1e999$",
    ] {
        let _ = datcom::run(&read(text));
    }
}

/// Values beyond an array's capacity are reported and none of them is stored, whether the
/// assignment starts inside the array or beyond it.
#[test]
fn values_beyond_capacity_are_reported_not_stored() {
    let raw = deck::read(
        " $BODY NX=2.0, X(19)=1.0,2.0,3.0$\n $WGPLNF CHRDR=1.0$\n $BODY R(25)=1.0$\n",
        "t.dcm",
    );
    let too_many = raw
        .diagnostics
        .iter()
        .filter(|d| d.to_string().contains("holds at most 20 values"))
        .count();
    assert_eq!(too_many, 2, "{:?}", raw.diagnostics);
    let case = &raw.cases[0];
    let x = numbers(case, "BODY", "X");
    assert_eq!(x.len(), 20, "X(19)=1,2,3 keeps X(19), X(20): {x:?}");
    assert_eq!(&x[18..], &[Some(1.0), Some(2.0)]);
    assert!(
        !case.namelists["BODY"].contains_key("R"),
        "R(25) is beyond R's 20 elements: {:?}",
        case.namelists["BODY"].get("R")
    );
}

/// A section that cannot be made (coordinates that run beyond the trailing edge, a NACA
/// designation that names no section) is an error of `check`, at the variable or card; before,
/// only the run said so, in a warning, and the deck checked clean. A table that stops short of
/// the trailing edge is computed, as the original computes it, with a warning there.
#[test]
fn sections_that_cannot_be_made_are_errors_where_they_are_given() {
    let planform = " $WGPLNF CHRDR=2.0, SSPN=5.0, SSPNE=5.0, CHRDTP=1.0$\n";
    let user = format!(
        "{MINIMAL}{planform} $WGSCHR TYPEIN=1.0, NPTS=3.0,\n  XCORD=0.0,0.5,1.02, YUPPER=0.0,0.05,0.0, YLOWER=0.0,-0.05,0.0$\n"
    );
    let d = read(&user);
    let e = errors(&d);
    assert_eq!(e.len(), 1, "{e:?}");
    assert_eq!((e[0].line, e[0].column), (5, 3));
    assert_eq!(e[0].card.as_deref(), Some("WGSCHR"));
    assert_eq!(e[0].variable.as_deref(), Some("XCORD"));
    assert!(
        e[0].to_string()
            .contains("XCORD(3) = 1.02: the last station is the trailing edge, 1"),
        "{}",
        e[0]
    );
    // The same table ending at 1 is clean; ending at 0.98, a warning at the same place.
    assert!(errors(&read(&user.replace("1.02", "1.0"))).is_empty());
    let short = read(&user.replace("1.02", "0.98"));
    assert!(errors(&short).is_empty());
    let w: Vec<_> = short
        .diagnostics
        .iter()
        .filter(|x| x.to_string().contains("stops short of the trailing edge"))
        .collect();
    assert_eq!(w.len(), 1, "{:?}", short.diagnostics);
    assert_eq!((w[0].line, w[0].column), (5, 3));
    assert_eq!(w[0].variable.as_deref(), Some("XCORD"));

    let d = read(&format!("{MINIMAL}{planform}NACA-W-5-99912\n"));
    let e = errors(&d);
    assert_eq!(e.len(), 1, "{e:?}");
    assert_eq!((e[0].line, e[0].card.as_deref()), (4, Some("NACA")));
    assert!(e[0].to_string().contains("designation `99912`"), "{}", e[0]);
    assert!(errors(&read(&format!("{MINIMAL}{planform}NACA-W-5-23012\n"))).is_empty());
}

/// A namelist whose methods are not implemented (flaps, power, ground effect, ...) is read and
/// named in a warning at its place that says what the run leaves out: the pages were silently
/// those of the undeflected, power-off configuration.
#[test]
fn namelists_without_methods_are_named() {
    let d = read(&format!(
        "{MINIMAL} $SYMFLP FTYPE=1.0, NDELTA=2.0, DELTA(1)=0.0,10.0$\n $PROPWR NENGSP=1.0$\n"
    ));
    assert!(errors(&d).is_empty(), "{:?}", d.diagnostics);
    let named = |nl: &str| {
        d.diagnostics
            .iter()
            .find(|x| x.card.as_deref() == Some(nl))
            .unwrap_or_else(|| panic!("no diagnostic for ${nl}: {:?}", d.diagnostics))
    };
    let flaps = named("SYMFLP");
    assert_eq!(
        (flaps.severity, flaps.line, flaps.column),
        (Severity::Warning, 3, 10)
    );
    assert!(flaps.to_string().contains("are not implemented"), "{flaps}");
    let power = named("PROPWR");
    assert_eq!(power.line, 4);
    assert!(
        power.to_string().contains("the pages are power-off"),
        "{power}"
    );
    // A deck without them has no such warning.
    let plain = read(MINIMAL);
    assert!(
        plain
            .diagnostics
            .iter()
            .all(|x| !x.to_string().contains("not implemented")),
        "{:?}",
        plain.diagnostics
    );
}

/// A namelist-level problem of a case is placed in that case, also when SAVE carried values of
/// the namelist from an earlier case (their places are the earlier case's); a case with no
/// component says so.
#[test]
fn namelist_problems_are_placed_in_their_own_case() {
    let text = format!(
        "{MINIMAL} $SYMFLP FTYPE=1.0, NDELTA=2.0, DELTA(1)=0.0,10.0$\nSAVE\nNEXT CASE\n $SYMFLP DELTA(1)=0.0,20.0$\n"
    );
    let d = read(&text);
    let lines: Vec<usize> = d
        .diagnostics
        .iter()
        .filter(|x| x.card.as_deref() == Some("SYMFLP"))
        .map(|x| x.line)
        .collect();
    assert_eq!(lines, vec![3, 6], "{:?}", d.diagnostics);
    assert!(
        d.diagnostics
            .iter()
            .any(|x| x.to_string().contains("the case has no component")),
        "{:?}",
        d.diagnostics
    );
}

/// Found by the user review: a number beyond double precision was also checked as 0, giving a
/// second error (`SREF must be positive; found 0`) about a value the deck does not give. It is
/// not assigned: one error, at the number.
#[test]
fn a_number_beyond_double_precision_is_one_error_and_not_assigned() {
    let d = read(&format!("{MINIMAL} $OPTINS SREF=1E400$\n"));
    let e = errors(&d);
    assert_eq!(e.len(), 1, "{e:?}");
    assert_eq!((e[0].line, e[0].column), (3, 15));
    assert!(e[0].to_string().contains("found `1E400`"), "{}", e[0]);
    let raw = deck::read(&format!("{MINIMAL} $OPTINS SREF=1E400$\n"), "t");
    assert_eq!(numbers(&raw.cases[0], "OPTINS", "SREF"), [None]);
    // An element already given keeps its value (the review found it erased).
    let raw = deck::read(
        " $FLTCON NMACH=1.0, MACH(1)=0.4, NALPHA=3.0, ALSCHD(1)=0.0,2.0,4.0,\n ALSCHD(2)=1E400$\n",
        "t",
    );
    assert_eq!(
        numbers(&raw.cases[0], "FLTCON", "ALSCHD"),
        [Some(0.0), Some(2.0), Some(4.0)]
    );
}

/// Found by the user review: a section without its planform was pointed at the case's first
/// line, not at the section; and a ventral-fin section without $VFPLNF was accepted without a
/// word (the original runs such a case: it tests only the wing, horizontal and vertical tail).
#[test]
fn a_section_without_its_planform_is_pointed_at_the_section() {
    let d = read(&format!(
        "{MINIMAL} $BODY NX=2.0, X(1)=0.0,1.0, R(1)=0.1,0.1$\nNACA-V-4-0012\nNACA-F-4-0012\n"
    ));
    let e = errors(&d);
    assert_eq!(e.len(), 1, "{e:?}");
    assert_eq!((e[0].line, e[0].column), (4, 1));
    assert_eq!(e[0].card.as_deref(), Some("VTPLNF"));
    let fin: Vec<_> = d
        .diagnostics
        .iter()
        .filter(|x| x.card.as_deref() == Some("VFPLNF"))
        .collect();
    assert_eq!(fin.len(), 1, "{:?}", d.diagnostics);
    assert_eq!(fin[0].severity, Severity::Warning);
    assert_eq!((fin[0].line, fin[0].column), (5, 1));
    assert!(fin[0].to_string().contains("the case has no ventral fin"));
}

/// Found by the user review: the TRIM card's warning ended mid-sentence.
#[test]
fn the_trim_warning_is_a_whole_sentence() {
    let d = read(&format!("TRIM\n{MINIMAL}"));
    let trim: Vec<String> = d
        .diagnostics
        .iter()
        .filter(|x| x.card.as_deref() == Some("TRIM"))
        .map(ToString::to_string)
        .collect();
    assert_eq!(trim.len(), 1, "{:?}", d.diagnostics);
    assert!(
        trim[0].ends_with("the untrimmed pages are printed"),
        "{}",
        trim[0]
    );
}

/// Found by the user review: a listing of the original given to `check` or `run` was read as
/// a deck from the cards it echoes (129 errors for one listing, two "cases" run). It is one
/// error that says what the file is and what reads it.
#[test]
fn a_listing_of_the_original_is_not_read_as_a_deck() {
    let d = read(&format!(
        " THIS SOFTWARE AND ANY ACCOMPANYING DOCUMENTATION\n IS RELEASED \"AS IS\".\n\
         1          THE FOLLOWING IS A LIST OF ALL INPUT CARDS FOR THIS CASE.\n{MINIMAL}"
    ));
    assert!(d.cases.is_empty());
    let e = errors(&d);
    assert_eq!(e.len(), 1, "{:?}", d.diagnostics);
    assert_eq!((e[0].line, e[0].column), (1, 1));
    assert!(e[0]
        .to_string()
        .contains("this is a listing (the original program's"));
    assert!(e[0]
        .hint
        .as_deref()
        .unwrap_or("")
        .contains("datcom-rs import"));
    // The marks are looked for before the first namelist: a deck that mentions a listing in a
    // later comment is read.
    let d = read(&format!(
        "{MINIMAL}* compare with THE FOLLOWING IS A LIST OF ALL INPUT CARDS\n"
    ));
    assert_eq!(d.cases.len(), 1);
    assert!(errors(&d).is_empty(), "{:?}", d.diagnostics);
}
