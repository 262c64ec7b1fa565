//! `datcom-rs`: a thin command line over the `datcom` library.
//!
//! Exit codes: 0 success; 1 the deck has errors (or a case could not be computed); 2 usage or
//! file errors.

use std::io::Write;
use std::path::{Path, PathBuf};
use std::process::ExitCode;

use clap::{Parser, Subcommand, ValueEnum};
use datcom::Diagnosed;

#[derive(Parser)]
#[command(
    name = "datcom-rs",
    version,
    about = "USAF Digital DATCOM stability and control derivatives",
    long_about = "Reads Digital DATCOM input decks (namelists and control cards), checks them, \
                  and computes the static longitudinal, static lateral-directional and dynamic \
                  derivatives by the USAF DATCOM methods, component by component (body, wing, \
                  wing-body, tails, downwash), as text, a listing in the original's layout \
                  (for006), JSON or CSV."
)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Clone, Copy, ValueEnum)]
enum ParseFormat {
    Json,
}

#[derive(Clone, Copy, ValueEnum)]
enum ReynoldsRule {
    Flight,
    Original,
}

#[derive(Clone, Copy, ValueEnum)]
enum FiveDigitRule {
    Naca,
    Original,
}

#[derive(Clone, Copy, ValueEnum)]
enum SixARule {
    Naca,
    Original,
}

/// The handbook's method or the original program's reading (the zero-lift, forward-sweep,
/// tail-slope and Jorgensen-drag rules).
#[derive(Clone, Copy, ValueEnum)]
enum HandbookRule {
    Handbook,
    Original,
}

#[derive(Clone, Copy, ValueEnum)]
enum OutboardSectionRule {
    Uniform,
    Original,
}

#[derive(Clone, Copy, ValueEnum)]
enum MaximumRule {
    Greatest,
    LastRise,
}

/// The rules that differ between the library and the original program (docs/differences.md):
/// the library's by default, the original's to reproduce its listings.
#[derive(Clone, Copy, clap::Args)]
struct Rules {
    /// Reynolds number of the section methods when the deck gives no RNNUB: the flight
    /// condition's (default), or the original program's fixed values (to reproduce its
    /// listings).
    #[arg(long, value_enum, default_value = "flight")]
    reynolds: ReynoldsRule,
    /// NACA 5-digit designations: NACA's definition (default), or as the original program
    /// reads them (first digit = percent camber; to reproduce its listings; docs/sections.md).
    #[arg(long = "five-digit", value_enum, default_value = "naca")]
    five_digit: FiveDigitRule,
    /// A section's maximum thickness and camber (and their positions, which the maximum-lift
    /// method reads): the greatest ordinate (default), or the original program's, the
    /// ordinate at the last station where it rose, also the thickness its methods take for a
    /// NACA section (to reproduce its listings; docs/section-characteristics.md).
    #[arg(long = "section-maximum", value_enum, default_value = "greatest")]
    section_maximum: MaximumRule,
    /// NACA 6A designations: NACA's definition (default), or as the original program reads
    /// them (thickness not straightened aft of 0.8 chord, the plain a = 0.8 or a = 1 mean
    /// line; to reproduce its listings; docs/sections.md).
    #[arg(long = "six-a", value_enum, default_value = "naca")]
    six_a: SixARule,
    /// The wing's zero-lift angle: DATCOM 4.1.3.1 (default), or as the original program reads
    /// it (the section's zero-lift angle at the last Mach number, and its maximum lift there
    /// for the wing at Mach 0, its reading of figure
    /// 4.1.3.1-4, and the rate derivatives' zero lift read on the whole lift curve, also where
    /// it falls through zero beyond the stall; to reproduce its listings; docs/wing.md,
    /// docs/differences.md).
    #[arg(long = "zero-lift", value_enum, default_value = "handbook")]
    zero_lift: HandbookRule,
    /// A forward-swept wing: its aerodynamic centre where |tan(leading-edge sweep)|/beta
    /// exceeds 1 by the subsonic chart of figure 4.1.4.2-26 and the vertical panels' roll-rate
    /// terms as for any wing (default), or as the original program has them (its supersonic
    /// chart, the panels' CLP and CLR left out; to reproduce its listings;
    /// docs/differences.md).
    #[arg(long = "forward-sweep", value_enum, default_value = "handbook")]
    forward_sweep: HandbookRule,
    /// The lift-curve slope a low-aspect-ratio straight horizontal tail takes into its
    /// combinations with the body and wing: DATCOM 4.1.3.2's (default), or as the original
    /// program has it (the slope of the tail's lift curve at the schedule's first angle; to
    /// reproduce its listings; docs/differences.md).
    #[arg(long = "tail-slope", value_enum, default_value = "handbook")]
    tail_slope: HandbookRule,
    /// The outboard panel's section values a deck leaves unset (TOVCO, XOVCO, LERO, CMOT) on a
    /// surface that is not straight tapered: the inboard panel's, a uniform section (default),
    /// or as the original program has them (the computed section's thickness, its position and
    /// zero-lift moment, and LERI; about 0 without a computed section; to reproduce its
    /// listings; docs/differences.md).
    #[arg(long = "outboard-section", value_enum, default_value = "uniform")]
    outboard_section: OutboardSectionRule,
    /// The body's drag due to lift in the wing-body drag with a Jorgensen body (METHOD=2): that
    /// of the body the deck asks for (default), or as the original program has it (the
    /// axisymmetric method's; to reproduce its listings; docs/differences.md).
    #[arg(long = "jorgensen-drag", value_enum, default_value = "handbook")]
    jorgensen_drag: HandbookRule,
    /// Every rule above as the original program has it (its listings' section Reynolds number,
    /// 5-digit and 6A readings, section maximum, zero-lift angle, forward-swept aerodynamic
    /// centre, low-aspect-ratio tail slope, outboard section values, Jorgensen body's drag),
    /// whatever the other options say.
    #[arg(long)]
    original: bool,
}

impl Rules {
    fn apply(self, deck: datcom::Deck) -> datcom::Deck {
        use datcom::case::{
            FiveDigitReading, ForwardSweepReading, JorgensenDragReading, MaximumReading,
            OutboardSectionReading, SectionReynolds, SixAReading, TailSlopeReading,
            ZeroLiftReading,
        };
        if self.original {
            return deck.with_original_rules();
        }
        deck.with_section_reynolds(match self.reynolds {
            ReynoldsRule::Flight => SectionReynolds::Flight,
            ReynoldsRule::Original => SectionReynolds::Original,
        })
        .with_five_digit_reading(match self.five_digit {
            FiveDigitRule::Naca => FiveDigitReading::Naca,
            FiveDigitRule::Original => FiveDigitReading::Original,
        })
        .with_section_maximum(match self.section_maximum {
            MaximumRule::Greatest => MaximumReading::Greatest,
            MaximumRule::LastRise => MaximumReading::LastRise,
        })
        .with_six_a_reading(match self.six_a {
            SixARule::Naca => SixAReading::Naca,
            SixARule::Original => SixAReading::Original,
        })
        .with_zero_lift_reading(match self.zero_lift {
            HandbookRule::Handbook => ZeroLiftReading::Handbook,
            HandbookRule::Original => ZeroLiftReading::Original,
        })
        .with_forward_sweep_reading(match self.forward_sweep {
            HandbookRule::Handbook => ForwardSweepReading::Handbook,
            HandbookRule::Original => ForwardSweepReading::Original,
        })
        .with_tail_slope_reading(match self.tail_slope {
            HandbookRule::Handbook => TailSlopeReading::Handbook,
            HandbookRule::Original => TailSlopeReading::Original,
        })
        .with_outboard_section_reading(match self.outboard_section {
            OutboardSectionRule::Uniform => OutboardSectionReading::Uniform,
            OutboardSectionRule::Original => OutboardSectionReading::Original,
        })
        .with_jorgensen_drag_reading(match self.jorgensen_drag {
            HandbookRule::Handbook => JorgensenDragReading::Handbook,
            HandbookRule::Original => JorgensenDragReading::Original,
        })
    }
}

#[derive(Clone, Copy, ValueEnum)]
enum CompareFormat {
    Text,
    Json,
}

#[derive(Clone, Copy, ValueEnum)]
enum ReportFormat {
    Text,
    Markdown,
    Csv,
    Json,
}

#[derive(Clone, Copy, ValueEnum)]
enum RunFormat {
    Text,
    Json,
    Csv,
    /// Pages in the original program's layout (for existing listing readers).
    For006,
}

#[derive(Subcommand)]
enum ExportTarget {
    /// A JSBSim `<aerodynamics>` section (and, with --aircraft, a whole minimal aircraft):
    /// one aero/coefficient function per DATCOM term, tables over alpha (and Mach), in feet
    /// and pounds (docs/jsbsim.md).
    Jsbsim(JsbsimExport),
}

/// The options of `export jsbsim`.
#[derive(clap::Args)]
struct JsbsimExport {
    deck: PathBuf,
    /// Write the `<aerodynamics>` file here (standard output when neither -o nor
    /// --aircraft is given).
    #[arg(short = 'o', long = "output", value_name = "FILE")]
    output: Option<PathBuf>,
    /// Also write a whole aircraft, DIR/<name>/<name>.xml, that JSBSim can load.
    #[arg(long, value_name = "DIR")]
    aircraft: Option<PathBuf>,
    /// The aircraft's name (default: the deck's file name without extension).
    #[arg(long)]
    name: Option<String>,
    /// The case of the deck to export (1-based).
    #[arg(long, default_value_t = 1)]
    case: usize,
    /// Weight, lbf, when the deck gives no WT (or to replace it).
    #[arg(long, value_name = "LBF")]
    weight_lbf: Option<f64>,
    /// Ixx,Iyy,Izz about the c.g., slug·ft² (default: an estimate, see docs/jsbsim.md).
    #[arg(long, value_name = "IXX,IYY,IZZ", value_delimiter = ',')]
    inertia_slugft2: Option<Vec<f64>>,
}

#[derive(Subcommand)]
enum Command {
    /// SVG figures of every case: CL, CD, Cm against alpha, the drag polar, Cm against CL, the
    /// sideslip and dynamic derivatives against alpha; one series per flight condition.
    Plot {
        deck: PathBuf,
        /// Directory of the figures: DIR/<deck>-<figure>.svg (<deck>-case<N>-<figure>.svg
        /// when the deck has several cases).
        #[arg(short = 'o', long = "output", value_name = "DIR")]
        output: PathBuf,
    },
    /// Export a case for another tool.
    Export {
        #[command(subcommand)]
        target: ExportTarget,
    },
    /// Check decks and print every problem (exit 0 clean or warnings only, 1 if errors).
    Check {
        /// Deck files.
        #[arg(required = true)]
        decks: Vec<PathBuf>,
        /// Print notes too (dialect accepted here that the original rejects).
        #[arg(long)]
        notes: bool,
    },
    /// Print the typed cases of a deck.
    Parse {
        deck: PathBuf,
        #[arg(long, value_enum, default_value = "json")]
        format: ParseFormat,
    },
    /// Print the section namelist ($WGSCHR, ...) for an airfoil coordinate file (Selig or
    /// Lednicer format, unit chord), resampled to chord stations closer at both edges.
    Airfoil {
        file: PathBuf,
        /// Namelist to write: WGSCHR, HTSCHR, VTSCHR or VFSCHR.
        #[arg(long, default_value = "WGSCHR")]
        namelist: String,
        /// Number of chord stations (3 to 50).
        #[arg(long, default_value_t = 50)]
        points: usize,
    },
    /// Read a listing of the original program (for006.dat), or of `run --format for006`, into
    /// the JSON of `run`. A file with nothing to read (the text report of `run`, a file that
    /// is no listing, a listing without a page read) is refused with exit code 2.
    Import {
        listing: PathBuf,
        #[arg(long, value_enum, default_value = "json")]
        format: ParseFormat,
    },
    /// Agreement between two results, coefficient by coefficient, worst first. Each of OURS
    /// and REFERENCE is a deck (run here), a JSON of `run` or `import`, or a listing; any other
    /// file is refused (exit 2), and a deck with errors too, with its diagnostics (exit 1).
    Compare {
        ours: PathBuf,
        reference: PathBuf,
        #[arg(long, value_enum, default_value = "text")]
        format: CompareFormat,
        #[command(flatten)]
        rules: Rules,
    },
    /// Percentage errors of a deck's derivatives against reference values: a reference file
    /// (TOML: hand calculation, published table; docs/validation.md) gives, per derivative,
    /// ours, the reference, the error, the unit and the DATCOM method, with mean and max
    /// absolute error per family; a listing of the original (for006.dat) or a JSON of `run`
    /// gives the agreement per coefficient, number by number, as `compare`.
    Report {
        deck: PathBuf,
        #[arg(long, value_name = "REF")]
        reference: PathBuf,
        #[arg(long, value_enum, default_value = "text")]
        format: ReportFormat,
        #[command(flatten)]
        rules: Rules,
    },
    /// Compare a prediction with measurements: residuals and their significance, the missing
    /// physical effects named from a catalogue (stepwise, BIC), fitted with 95 % intervals,
    /// and the RMS before and after (docs/discrepancy.md). With --flight, the measurements are
    /// a recorded flight and the effects are fitted by output error through a longitudinal
    /// simulation.
    Discrepancy(DiscrepancyArgs),
    /// Run a deck: flight conditions and coefficients.
    Run {
        deck: PathBuf,
        #[arg(long, value_enum, default_value = "text")]
        format: RunFormat,
        /// Write the output to DIR/<deck name>.<txt|json|csv|out> (`out` for --format for006)
        /// instead of standard output.
        #[arg(short = 'o', long = "output", value_name = "DIR")]
        output: Option<PathBuf>,
        #[command(flatten)]
        rules: Rules,
    },
}

fn print_diagnostics(deck: &datcom::Deck, notes: bool, out: &mut dyn Write) {
    for d in &deck.diagnostics {
        if notes || d.severity != datcom::Severity::Note {
            let _ = writeln!(out, "{d}");
        }
    }
}

fn load(path: &Path) -> Result<datcom::Deck, ExitCode> {
    datcom::read_deck_file(path).map_err(|e| {
        eprintln!("datcom-rs: {e}");
        ExitCode::from(2)
    })
}

/// A deck read under `rules` with its diagnostics printed; exit 2 when unreadable, 1 when it
/// has errors (the commands that need a whole deck refuse one with errors).
fn load_without_errors(path: &Path, rules: Rules) -> Result<datcom::Deck, ExitCode> {
    without_errors(rules.apply(load(path)?), path)
}

/// A deck with its diagnostics printed (as `run` prints them); exit 1 when it has errors.
fn without_errors(d: datcom::Deck, path: &Path) -> Result<datcom::Deck, ExitCode> {
    print_diagnostics(&d, false, &mut std::io::stderr().lock());
    if d.has_errors() {
        eprintln!(
            "datcom-rs: {} has {} error(s)",
            path.display(),
            d.error_count()
        );
        return Err(ExitCode::from(1));
    }
    Ok(d)
}

/// Checks every deck, going on past unreadable files. Exit 2 if a file could not be read,
/// else 1 if a deck has errors, else 0.
fn check(decks: &[PathBuf], notes: bool) -> ExitCode {
    let mut errors = false;
    let mut unreadable = false;
    let mut out = std::io::stdout().lock();
    for path in decks {
        let deck = match load(path) {
            Ok(d) => d,
            Err(_) => {
                unreadable = true;
                continue;
            }
        };
        print_diagnostics(&deck, notes, &mut out);
        let (e, w) = (deck.error_count(), deck.warning_count());
        // A closed pipe (`| head`) ends the output, not the program with a panic.
        let _ = writeln!(
            out,
            "{}: {} case(s), {e} error(s), {w} warning(s)",
            path.display(),
            deck.cases.len()
        );
        errors |= e > 0;
    }
    ExitCode::from(if unreadable { 2 } else { u8::from(errors) })
}

fn emit(text: &str, deck: &Path, ext: &str, output: Option<&Path>) -> ExitCode {
    match output {
        None => {
            let mut out = std::io::stdout().lock();
            if out.write_all(text.as_bytes()).is_err() {
                return ExitCode::from(2);
            }
            ExitCode::SUCCESS
        }
        Some(dir) => {
            let stem = deck
                .file_stem()
                .map_or("deck".into(), |s| s.to_string_lossy());
            let path = dir.join(format!("{stem}.{ext}"));
            if let Err(e) = std::fs::create_dir_all(dir).and_then(|()| std::fs::write(&path, text))
            {
                eprintln!("datcom-rs: cannot write {}: {e}", path.display());
                return ExitCode::from(2);
            }
            eprintln!("wrote {}", path.display());
            ExitCode::SUCCESS
        }
    }
}

/// What a result was read from.
#[derive(Clone, Copy, PartialEq)]
enum Source {
    /// A deck, run here under the rules given.
    Deck,
    /// A JSON of `run` or `import`.
    Json,
    /// A listing of ours (`run --format for006`).
    Listing,
    /// A listing of the original program.
    OriginalListing,
}

/// A result in the JSON shape of `run`, the file it was read from and what that file is.
struct Read {
    value: serde_json::Value,
    name: String,
    source: Source,
}

/// A result in the JSON shape of `run`, from a deck, a JSON file of `run` or `import`, or a
/// listing. Any other file is refused (exit 2), as a deck with errors is (its diagnostics
/// printed; exit 1).
fn results_json(path: &Path, rules: Rules) -> Result<Read, ExitCode> {
    let bytes = std::fs::read(path).map_err(|e| {
        eprintln!("datcom-rs: cannot read {}: {e}", path.display());
        ExitCode::from(2)
    })?;
    let text = String::from_utf8_lossy(&bytes);
    let name = path.display().to_string();
    let (json, source) = if text.trim_start().starts_with('{') {
        (text.into_owned(), Source::Json)
    } else if datcom::report::legacy::is_listing(&text) {
        // A listing without a single page of the original's (it stopped at input errors) is
        // no reference: read as a deck, its echo of the input cards would be run here and
        // agree with ours. Our text report is refused (read as a listing, its numbers came
        // out shifted); a listing whose pages are none that are read has nothing to compare.
        use datcom::report::legacy::{is_original_listing, NotImported};
        let source = if is_original_listing(&text) {
            Source::OriginalListing
        } else {
            Source::Listing
        };
        let json = match datcom::report::json::import_listing(&text, &name) {
            Ok(json) => json,
            Err(e @ NotImported::NoPageRead { .. }) => {
                eprintln!("datcom-rs: {name}: {e}; nothing of it is compared");
                datcom::report::json::listing_to_string(&text, &name)
            }
            Err(e) => {
                eprintln!("datcom-rs: {name}: {e}; nothing to compare");
                return Err(ExitCode::from(2));
            }
        };
        (json, source)
    } else {
        let deck = rules.apply(datcom::read_deck(&text, &name));
        // A file of which no case is read (a README, a TOML or CSV file) is no deck: run, it
        // compared as nothing with exit code 0.
        if deck.cases.is_empty() {
            eprintln!(
                "datcom-rs: {name}: neither a deck (no case is read from it; `datcom-rs check {name}` says why), a JSON of `run` or `import`, nor a listing"
            );
            return Err(ExitCode::from(2));
        }
        let deck = without_errors(deck, path)?;
        (
            datcom::report::json::to_string(&datcom::run(&deck)),
            Source::Deck,
        )
    };
    let value: serde_json::Value = serde_json::from_str(&json).map_err(|e| {
        eprintln!("datcom-rs: {}: not a result: {e}", path.display());
        ExitCode::from(2)
    })?;
    // A result's cases have their units and pages (`parse` writes cases too: typed input).
    let result_case = |c: &serde_json::Value| c["units"].is_object() && c["conditions"].is_array();
    if !value["cases"]
        .as_array()
        .is_some_and(|cases| cases.iter().all(result_case))
    {
        eprintln!(
            "datcom-rs: {name}: a JSON, but not of `run` or `import` (no \"cases\" with units and pages)"
        );
        return Err(ExitCode::from(2));
    }
    Ok(Read {
        value,
        name,
        source,
    })
}

/// The agreement of `ours` with `reference` (`compare`, `report` against a result), saying on
/// standard error why when no page of the reference has a counterpart in ours, and hinting at
/// --original when a deck run under the library's rules meets a listing of the original.
fn agreement(
    ours: &Read,
    reference: &Read,
    rules: Rules,
) -> Vec<datcom::report::compare::ColumnAgreement> {
    for (deck, listing) in [(ours, reference), (reference, ours)] {
        if deck.source == Source::Deck
            && listing.source == Source::OriginalListing
            && !rules.original
        {
            eprintln!(
                "hint: {} is a listing of the original program; --original runs {} under the original's rules (its section Reynolds numbers, NACA readings, ...: docs/differences.md), as its numbers were computed",
                listing.name, deck.name
            );
        }
    }
    if let Some(why) = datcom::report::compare::nothing_in_common(&ours.value, &reference.value) {
        eprintln!("datcom-rs: {why}");
    }
    datcom::report::compare::compare(&ours.value, &reference.value)
}

fn compare(ours: &Path, reference: &Path, format: CompareFormat, rules: Rules) -> ExitCode {
    let (a, b) = match (results_json(ours, rules), results_json(reference, rules)) {
        (Ok(a), Ok(b)) => (a, b),
        (Err(c), _) | (_, Err(c)) => return c,
    };
    let rows = agreement(&a, &b, rules);
    let text = match format {
        CompareFormat::Text => datcom::report::compare::to_text(&rows),
        CompareFormat::Json => serde_json::to_string_pretty(&rows).unwrap_or_default(),
    };
    let _ = write!(std::io::stdout().lock(), "{text}");
    ExitCode::SUCCESS
}

/// Agreement rows as a Markdown or CSV table.
fn agreement_table(rows: &[datcom::report::compare::ColumnAgreement], markdown: bool) -> String {
    let mut out = if markdown {
        String::from(
            "| coefficient | agreeing | compared | missing | fraction |\n|---|---|---|---|---|\n",
        )
    } else {
        String::from("coefficient,agreeing,compared,missing,fraction\n")
    };
    for r in rows {
        let cells = [
            r.coefficient.clone(),
            r.agreeing.to_string(),
            r.compared.to_string(),
            r.missing.to_string(),
            format!("{:.4}", r.fraction()),
        ];
        out.push_str(&if markdown {
            format!("| {} |\n", cells.join(" | "))
        } else {
            format!("{}\n", cells.join(","))
        });
    }
    out
}

fn report(deck: &Path, reference: &Path, format: ReportFormat, rules: Rules) -> ExitCode {
    use datcom::report::percent_error as pe;
    let text = match std::fs::read(reference) {
        Ok(b) => String::from_utf8_lossy(&b).into_owned(),
        Err(e) => {
            eprintln!("datcom-rs: cannot read {}: {e}", reference.display());
            return ExitCode::from(2);
        }
    };
    let is_results =
        text.trim_start().starts_with('{') || datcom::report::legacy::is_listing(&text);
    let out = if is_results {
        // A listing or a result: agreement per coefficient, as `compare`.
        let (a, b) = match (results_json(deck, rules), results_json(reference, rules)) {
            (Ok(a), Ok(b)) => (a, b),
            (Err(c), _) | (_, Err(c)) => return c,
        };
        let rows = agreement(&a, &b, rules);
        match format {
            ReportFormat::Text => datcom::report::compare::to_text(&rows),
            ReportFormat::Markdown => agreement_table(&rows, true),
            ReportFormat::Csv => agreement_table(&rows, false),
            ReportFormat::Json => serde_json::to_string_pretty(&rows).unwrap_or_default(),
        }
    } else {
        let r = match pe::Reference::from_toml(&text, &reference.display().to_string()) {
            Ok(r) => r,
            Err(e) => {
                eprintln!("datcom-rs: {e}");
                return ExitCode::from(2);
            }
        };
        let d = match load_without_errors(deck, rules) {
            Ok(d) => d,
            Err(code) => return code,
        };
        match pe::report(&datcom::run(&d), &r) {
            Ok(rep) => match format {
                ReportFormat::Text => pe::to_text(&rep),
                ReportFormat::Markdown => pe::to_markdown(&rep),
                ReportFormat::Csv => pe::to_csv(&rep),
                ReportFormat::Json => pe::to_json(&rep) + "\n",
            },
            Err(e) => {
                eprintln!("datcom-rs: {}: {e}", reference.display());
                return ExitCode::from(2);
            }
        }
    };
    if std::io::stdout().lock().write_all(out.as_bytes()).is_err() {
        return ExitCode::from(2);
    }
    ExitCode::SUCCESS
}

fn read_text(path: &Path) -> Result<String, ExitCode> {
    std::fs::read(path)
        .map(|b| String::from_utf8_lossy(&b).into_owned())
        .map_err(|e| {
            eprintln!("datcom-rs: cannot read {}: {e}", path.display());
            ExitCode::from(2)
        })
}

/// The options of `discrepancy`.
#[derive(clap::Args)]
// One prediction, from a deck or a table: a missing one is an error naming both options.
#[command(group(
    clap::ArgGroup::new("prediction")
        .args(["model", "predicted"])
        .required(true)
))]
struct DiscrepancyArgs {
    /// A deck whose run is the prediction.
    #[arg(long, value_name = "DECK")]
    model: Option<PathBuf>,
    /// A prediction table (CSV: alpha_deg, CL, CD, Cm, optional CL_tail, Cm_tail), or the CSV
    /// of `run --format csv` (its case and flight condition chosen by --case and --condition).
    #[arg(long, value_name = "PRED.csv")]
    predicted: Option<PathBuf>,
    /// Measurements (CSV): static (alpha_deg, beta_deg, CL, CD, Cm, ..., sigma_<coef>) or,
    /// with --flight, a time history (t, elevator_deg, thrust_n, airspeed_mps, alpha_deg,
    /// pitch_rate_dps, theta_deg).
    #[arg(long, value_name = "MEAS.csv")]
    measured: PathBuf,
    /// The measurements are a recorded flight.
    #[arg(long)]
    flight: bool,
    /// Airframe values for --flight (TOML: mass_kg, iyy_kgm2, cl_de_per_rad,
    /// cm_de_per_rad, ...; the deck gives mass, area, chord, density and cmq).
    #[arg(long, value_name = "FILE", requires = "flight")]
    airframe: Option<PathBuf>,
    /// Case of the deck or of the run CSV (1-based).
    #[arg(long, default_value_t = 1, value_parser = clap::value_parser!(u64).range(1..))]
    case: u64,
    /// Flight condition of the case (1-based, in the order of `run`).
    #[arg(long, default_value_t = 1, value_parser = clap::value_parser!(u64).range(1..))]
    condition: u64,
    /// Write the analysis as JSON to this file.
    #[arg(long, value_name = "OUT")]
    json: Option<PathBuf>,
    /// Write SVG plots of measured, predicted and corrected curves into this folder.
    #[arg(long, value_name = "DIR")]
    plots: Option<PathBuf>,
    /// Compare only measured angles of attack from MIN to MAX deg (after --alpha-offset),
    /// e.g. the attached flow below stall.
    #[arg(
        long,
        value_name = "MIN,MAX",
        value_delimiter = ',',
        allow_hyphen_values = true,
        conflicts_with = "flight"
    )]
    alpha_range: Option<Vec<f64>>,
    /// Subtract this from the measured angles of attack (a known alpha-reference offset).
    #[arg(
        long,
        value_name = "DEG",
        default_value_t = 0.0,
        allow_negative_numbers = true,
        conflicts_with = "flight"
    )]
    alpha_offset: f64,
    /// Noise of measured coefficients, e.g. CL=0.005,CD=0.001,Cm=0.002 (else the
    /// sigma_<coef> columns, else estimated from the data).
    #[arg(
        long,
        value_name = "COEF=SIGMA,...",
        value_delimiter = ',',
        conflicts_with = "flight"
    )]
    sigma: Vec<String>,
    #[command(flatten)]
    rules: Rules,
}

fn discrepancy(a: &DiscrepancyArgs) -> ExitCode {
    use datcom::discrepancy as dy;
    let fail = |e: &dyn std::fmt::Display| {
        eprintln!("datcom-rs: {e}");
        ExitCode::from(2)
    };
    let (prediction, deck_model) = match (&a.model, &a.predicted) {
        (Some(deck), _) => {
            let d = match load_without_errors(deck, a.rules) {
                Ok(d) => d,
                Err(code) => return code,
            };
            match dy::prediction::from_deck(&d, a.case as usize, a.condition as usize - 1) {
                Ok(m) => {
                    for w in &m.warnings {
                        eprintln!("warning: {w}");
                    }
                    (m.prediction.clone(), Some(m))
                }
                Err(e) => return fail(&e),
            }
        }
        (None, Some(p)) => {
            let text = match read_text(p) {
                Ok(t) => t,
                Err(c) => return c,
            };
            let read = dy::data::read_prediction(
                &text,
                &p.display().to_string(),
                a.case as usize,
                a.condition as usize,
            );
            match read {
                Ok(pr) => {
                    if let Some(chosen) = &pr.chosen {
                        eprintln!("note: {chosen}");
                    }
                    for w in &pr.warnings {
                        eprintln!("warning: {w}");
                    }
                    (pr.prediction, None)
                }
                Err(e) => return fail(&e),
            }
        }
        (None, None) => return fail(&"give --model DECK or --predicted PRED.csv"),
    };
    let measured_text = match read_text(&a.measured) {
        Ok(t) => t,
        Err(c) => return c,
    };
    let name = a.measured.display().to_string();
    let alpha_range_deg = match a.alpha_range.as_deref() {
        None => None,
        Some([lo, hi]) if lo <= hi => Some((*lo, *hi)),
        Some(r) => {
            return fail(&format!(
                "--alpha-range: expected MIN,MAX with MIN <= MAX, found {r:?}"
            ))
        }
    };
    let options = dy::Options {
        alpha_range_deg,
        ..dy::Options::default()
    };
    let (text, json, figures) = if a.flight {
        let input: dy::flight::AirframeInput = match &a.airframe {
            Some(f) => match read_text(f).map(|t| toml::from_str(&t)) {
                Ok(Ok(i)) => i,
                Ok(Err(e)) => return fail(&format!("{}: {e}", f.display())),
                Err(c) => return c,
            },
            None => dy::flight::AirframeInput::default(),
        };
        let airframe = match input.resolve(deck_model.as_ref()) {
            Ok(x) => x,
            Err(e) => return fail(&e),
        };
        let record = match dy::flight::FlightRecord::from_csv(&measured_text, &name) {
            Ok(r) => r,
            Err(e) => return fail(&e),
        };
        match dy::flight::analyse_flight(&prediction, &airframe, &record, &options) {
            Ok(r) => {
                let figures = dy::plot::flight_figures(&record, &r);
                (r.to_text(), serde_json::to_string_pretty(&r), figures)
            }
            Err(e) => return fail(&e),
        }
    } else {
        let mut measured = match dy::data::read_measurement(&measured_text, &name) {
            Ok(m) => m.with_alpha_offset(a.alpha_offset),
            Err(e) => return fail(&e),
        };
        for item in &a.sigma {
            let parsed = item
                .split_once('=')
                .and_then(|(c, v)| Some((c.trim(), v.trim().parse::<f64>().ok()?)));
            let Some((coefficient, value)) = parsed else {
                return fail(&format!(
                    "--sigma {item}: expected COEF=VALUE, e.g. CL=0.005"
                ));
            };
            measured = match measured.with_sigma(coefficient, value) {
                Ok(m) => m,
                Err(e) => return fail(&e),
            };
        }
        match dy::analyse_static(&prediction, &measured, &options) {
            Ok(r) => {
                let figures =
                    dy::plot::static_figures(&prediction, &measured, &r, options.beta_zero_deg);
                (r.to_text(), serde_json::to_string_pretty(&r), figures)
            }
            Err(e) => return fail(&e),
        }
    };
    if let Some(dir) = &a.plots {
        let figures = match figures {
            Ok(f) => f,
            Err(e) => return fail(&e),
        };
        for f in figures {
            let path = dir.join(format!("{}.svg", f.name));
            if let Err(e) =
                std::fs::create_dir_all(dir).and_then(|()| std::fs::write(&path, &f.svg))
            {
                eprintln!("datcom-rs: cannot write {}: {e}", path.display());
                return ExitCode::from(2);
            }
            eprintln!("wrote {}", path.display());
        }
    }
    if let Some(path) = &a.json {
        let body = match json {
            Ok(j) => j,
            Err(e) => return fail(&e),
        };
        if let Err(e) = std::fs::write(path, body + "\n") {
            eprintln!("datcom-rs: cannot write {}: {e}", path.display());
            return ExitCode::from(2);
        }
    }
    if std::io::stdout().lock().write_all(text.as_bytes()).is_err() {
        return ExitCode::from(2);
    }
    ExitCode::SUCCESS
}

fn airfoil(file: &Path, namelist: &str, points: usize) -> ExitCode {
    let name = namelist.to_ascii_uppercase();
    if !["WGSCHR", "HTSCHR", "VTSCHR", "VFSCHR"].contains(&name.as_str()) {
        eprintln!("datcom-rs: --namelist {namelist}: expected WGSCHR, HTSCHR, VTSCHR or VFSCHR");
        return ExitCode::from(2);
    }
    let text = match std::fs::read_to_string(file) {
        Ok(t) => t,
        Err(e) => {
            eprintln!("datcom-rs: cannot read {}: {e}", file.display());
            return ExitCode::from(2);
        }
    };
    let input = datcom::geometry::airfoil_file::read(&text)
        .and_then(|a| a.to_section_input(points).map(|s| (a.name, s)));
    match input {
        Ok((airfoil, s)) => {
            let mut out = std::io::stdout().lock();
            let _ = writeln!(
                out,
                "* {airfoil}: {points} stations from {}",
                file.display()
            );
            let _ = write!(
                out,
                "{}",
                datcom::geometry::airfoil_file::namelist_text(&name, &s)
            );
            ExitCode::SUCCESS
        }
        // --points out of range is a usage error; a file that is not coordinates is input
        // with errors, as a deck with errors.
        Err(e @ datcom::geometry::airfoil_file::AirfoilFileError::Stations(_)) => {
            eprintln!("datcom-rs: --points: {e}");
            ExitCode::from(2)
        }
        Err(e) => {
            eprintln!("datcom-rs: {}: {e}", file.display());
            ExitCode::from(1)
        }
    }
}

fn export_jsbsim(o: JsbsimExport) -> ExitCode {
    use datcom::report::jsbsim::{self, KGM2_PER_SLUGFT2, N_PER_LBF};
    let inertia_kgm2 = match o.inertia_slugft2.as_deref() {
        None => None,
        Some(&[ixx, iyy, izz]) => Some([ixx, iyy, izz].map(|v| v * KGM2_PER_SLUGFT2)),
        Some(other) => {
            eprintln!(
                "datcom-rs: --inertia-slugft2 takes three values IXX,IYY,IZZ; {} given",
                other.len()
            );
            return ExitCode::from(2);
        }
    };
    let d = match load(&o.deck) {
        Ok(d) => d,
        Err(code) => return code,
    };
    print_diagnostics(&d, false, &mut std::io::stderr().lock());
    if d.has_errors() {
        eprintln!(
            "datcom-rs: {} has {} error(s); nothing exported",
            o.deck.display(),
            d.error_count()
        );
        return ExitCode::from(1);
    }
    let Some(case) = o.case.checked_sub(1).and_then(|i| d.cases.get(i)) else {
        eprintln!(
            "datcom-rs: {}",
            jsbsim::ExportError::NoSuchCase {
                case: o.case,
                count: d.cases.len()
            }
        );
        return ExitCode::from(2);
    };
    let results = datcom::results::run_case(case);
    let model = match jsbsim::model(&o.deck.display().to_string(), &results) {
        Ok(m) => m,
        Err(e) => {
            eprintln!("datcom-rs: {}: {e}", o.deck.display());
            return ExitCode::from(1);
        }
    };
    let write = |path: &Path, text: &str| -> Result<(), ExitCode> {
        let made = path
            .parent()
            .filter(|p| !p.as_os_str().is_empty())
            .map_or(Ok(()), std::fs::create_dir_all);
        made.and_then(|()| std::fs::write(path, text))
            .map_err(|e| {
                eprintln!("datcom-rs: cannot write {}: {e}", path.display());
                ExitCode::from(2)
            })?;
        eprintln!("wrote {}", path.display());
        Ok(())
    };
    if let Some(dir) = &o.aircraft {
        let name = o.name.clone().unwrap_or_else(|| {
            o.deck
                .file_stem()
                .map_or("aircraft".into(), |s| s.to_string_lossy().into_owned())
        });
        let options = jsbsim::AircraftOptions {
            name: name.clone(),
            weight_n: o.weight_lbf.map(|w| w * N_PER_LBF),
            inertia_kgm2,
        };
        let xml = match jsbsim::aircraft_xml(&model, case, &options) {
            Ok(x) => x,
            Err(e) => {
                eprintln!("datcom-rs: {}: {e}", o.deck.display());
                return ExitCode::from(1);
            }
        };
        if let Err(code) = write(&dir.join(&name).join(format!("{name}.xml")), &xml) {
            return code;
        }
    }
    let xml = jsbsim::aerodynamics_xml(&model);
    match (&o.output, &o.aircraft) {
        (Some(path), _) => write(path, &xml).err().unwrap_or(ExitCode::SUCCESS),
        (None, Some(_)) => ExitCode::SUCCESS,
        (None, None) => {
            if std::io::stdout().lock().write_all(xml.as_bytes()).is_err() {
                return ExitCode::from(2);
            }
            ExitCode::SUCCESS
        }
    }
}

fn plot(deck: &Path, dir: &Path) -> ExitCode {
    let d = match load(deck) {
        Ok(d) => d,
        Err(code) => return code,
    };
    print_diagnostics(&d, false, &mut std::io::stderr().lock());
    let results = datcom::run(&d);
    let stem = deck
        .file_stem()
        .map_or("deck".into(), |s| s.to_string_lossy());
    let several = results.cases.len() > 1;
    let mut code = ExitCode::SUCCESS;
    if let Err(e) = std::fs::create_dir_all(dir) {
        eprintln!("datcom-rs: cannot create {}: {e}", dir.display());
        return ExitCode::from(2);
    }
    for case in &results.cases {
        let figures = match datcom::report::plot::figures(case) {
            Ok(f) => f,
            Err(e) => {
                eprintln!("datcom-rs: {}: {e}", deck.display());
                code = ExitCode::from(1);
                continue;
            }
        };
        for f in figures {
            let file = if several {
                format!("{stem}-case{}-{}.svg", case.number, f.name)
            } else {
                format!("{stem}-{}.svg", f.name)
            };
            let path = dir.join(file);
            if let Err(e) = std::fs::write(&path, &f.svg) {
                eprintln!("datcom-rs: cannot write {}: {e}", path.display());
                return ExitCode::from(2);
            }
            eprintln!("wrote {}", path.display());
        }
    }
    code
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    match cli.command {
        Command::Plot { deck, output } => plot(&deck, &output),
        Command::Export {
            target: ExportTarget::Jsbsim(options),
        } => export_jsbsim(options),
        Command::Check { decks, notes } => check(&decks, notes),
        Command::Import { listing, format } => {
            let text = match std::fs::read(&listing) {
                Ok(b) => String::from_utf8_lossy(&b).into_owned(),
                Err(e) => {
                    eprintln!("datcom-rs: cannot read {}: {e}", listing.display());
                    return ExitCode::from(2);
                }
            };
            let name = listing.display().to_string();
            // A text that would import as nothing, or as invented numbers (our text report,
            // a deck, any other file), is refused.
            let json = match datcom::report::json::import_listing(&text, &name) {
                Ok(json) => json,
                Err(e) => {
                    eprintln!("datcom-rs: {name}: {e}; nothing imported");
                    return ExitCode::from(2);
                }
            };
            match format {
                ParseFormat::Json => {
                    let _ = writeln!(std::io::stdout().lock(), "{json}");
                }
            }
            ExitCode::SUCCESS
        }
        Command::Compare {
            ours,
            reference,
            format,
            rules,
        } => compare(&ours, &reference, format, rules),
        Command::Report {
            deck,
            reference,
            format,
            rules,
        } => report(&deck, &reference, format, rules),
        Command::Discrepancy(args) => discrepancy(&args),
        Command::Airfoil {
            file,
            namelist,
            points,
        } => airfoil(&file, &namelist, points),
        Command::Parse { deck, format } => {
            let d = match load(&deck) {
                Ok(d) => d,
                Err(code) => return code,
            };
            print_diagnostics(&d, false, &mut std::io::stderr().lock());
            match format {
                ParseFormat::Json => match serde_json::to_string_pretty(&d) {
                    Ok(s) => {
                        let _ = writeln!(std::io::stdout().lock(), "{s}");
                        ExitCode::from(u8::from(d.has_errors()))
                    }
                    Err(e) => {
                        eprintln!("datcom-rs: {e}");
                        ExitCode::from(2)
                    }
                },
            }
        }
        Command::Run {
            deck,
            format,
            output,
            rules,
        } => {
            let d = match load(&deck) {
                Ok(d) => rules.apply(d),
                Err(code) => return code,
            };
            print_diagnostics(&d, false, &mut std::io::stderr().lock());
            if d.has_errors() {
                eprintln!(
                    "datcom-rs: {} has {} error(s); cases with errors are computed as far as they can be",
                    deck.display(),
                    d.error_count()
                );
            }
            let results = datcom::run(&d);
            let (text, ext) = match format {
                RunFormat::Text => (datcom::report::text::to_string(&results), "txt"),
                RunFormat::Json => (datcom::report::json::to_string(&results), "json"),
                RunFormat::Csv => (datcom::report::csv::to_string(&results), "csv"),
                RunFormat::For006 => (datcom::report::for006::to_string(&results), "out"),
            };
            // The text and JSON reports hold the cases' warnings; the CSV and the listing have
            // no place for them: they go to stderr.
            if matches!(format, RunFormat::Csv | RunFormat::For006) {
                let mut err = std::io::stderr().lock();
                for case in &results.cases {
                    let _ = err.write_all(datcom::report::text::warning_lines(case).as_bytes());
                }
            }
            let code = emit(&text, &deck, ext, output.as_deref());
            if code == ExitCode::SUCCESS && d.has_errors() {
                ExitCode::from(1)
            } else {
                code
            }
        }
    }
}
