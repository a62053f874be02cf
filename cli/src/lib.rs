//! The headless subcommands (docs/files.md, "Command line"). Exit codes: 0 success, 1 valid
//! input that fails (compile errors), 2 unusable input (missing, unreadable or corrupt file, bad
//! arguments).

mod callgrind;
mod coverage;
mod print;
mod running;
mod say;
mod source;
mod testing;

pub use say::Say;
use say::shown;

use clap::{Parser, Subcommand};
use ladder_engine::diagnose::diagnose;
use ladder_engine::sim;
use ladder_engine::{file, il};
use ladder_text::cli::{CheckText, Counts, FileText, StartText};
use source::{EngineArg, Source, print_diagnostics, project_of};
use std::ffi::OsString;
use std::io::Write;
use std::path::{Path, PathBuf};

/// Ladder editor, compiler and simulator for the PLC of GSK CNC controllers.
#[derive(Parser, Debug)]
#[command(name = "ladder-studio", version, about)]
pub struct Cli {
    /// A project to open in the editor (without a subcommand).
    pub project: Option<PathBuf>,
    /// Start the editor online: the PLC and the simulated CNC running at real time.
    #[arg(long)]
    pub run: bool,
    /// With --run: load this NC program into the CNC and start it from the operator panel
    /// (its AUTO key, then Cycle start).
    #[arg(long, value_name = "FILE", requires = "run")]
    pub nc: Option<PathBuf>,
    /// The language of the messages (zh or en; default: the locale's). With export-comments
    /// and import-comments it also chooses the one comment column to write or read.
    #[arg(long, global = true, value_name = "zh|en", value_parser = ["zh", "en"])]
    pub lang: Option<String>,
    /// What to do.
    #[command(subcommand)]
    pub command: Option<CliCommand>,
}

/// The subcommands.
#[derive(Subcommand, Debug)]
pub enum CliCommand {
    /// Compile and list every error and warning; exits 1 when there are errors.
    Check {
        /// A project (.ldp) or an instruction list (.il).
        path: PathBuf,
    },
    /// Write the instruction list of a project or IL file.
    ExportIl {
        /// A project (.ldp) or an instruction list (.il).
        path: PathBuf,
        /// Output file (default: standard output).
        #[arg(short, long)]
        output: Option<PathBuf>,
    },
    /// Write symbols, addresses and comments as CSV, a column per language.
    ExportComments {
        /// A project (.ldp) or an instruction list (.il).
        path: PathBuf,
        /// Output file (default: standard output).
        #[arg(short, long)]
        output: Option<PathBuf>,
    },
    /// Read comments from CSV into a project: every row applies, or none does.
    ImportComments {
        /// The project to change.
        project: PathBuf,
        /// The CSV file.
        csv: PathBuf,
    },
    /// Print the reference index, the bit-usage table or the byte-usage table.
    Xref {
        /// A project (.ldp) or an instruction list (.il).
        path: PathBuf,
        /// The reference index (the default).
        #[arg(long, group = "table")]
        index: bool,
        /// The bit-usage table.
        #[arg(long, group = "table")]
        bits: bool,
        /// The byte-usage table.
        #[arg(long, group = "table")]
        bytes: bool,
    },
    /// Run the program on the simulated PLC under a stimulus script.
    Sim {
        /// A project (.ldp) or an instruction list (.il).
        path: PathBuf,
        /// The scan engine (default: native where available, checked in a debug build).
        #[arg(long, value_enum)]
        engine: Option<EngineArg>,
        /// The stimulus script.
        #[arg(long)]
        script: PathBuf,
        /// Write every watched address per tick to this CSV file.
        #[arg(long)]
        trace: Option<PathBuf>,
        /// Also run the simulated CNC (the `cnc` script commands and `cnc.KEY` values).
        #[arg(long)]
        cnc: bool,
        /// Run without the project's machine model, so that the script drives every input.
        #[arg(long)]
        no_machine: bool,
        /// Measure rung coverage and write it to this JSON file (a summary is printed).
        #[arg(long, value_name = "OUT.json")]
        coverage: Option<PathBuf>,
        /// Measure rung coverage and write it as an HTML page.
        #[arg(long, value_name = "OUT.html")]
        coverage_html: Option<PathBuf>,
    },
    /// Run every script of the project's test folder (NAME.tests/ beside NAME.ldp), each on
    /// a fresh machine, several at once; exits 1 when one fails.
    Test {
        /// A project (.ldp) or an instruction list (.il).
        path: PathBuf,
        /// The scan engine (default: native where available, checked in a debug build).
        #[arg(long, value_enum)]
        engine: Option<EngineArg>,
        /// Also write the results as JUnit XML, for a CI server.
        #[arg(long, value_name = "OUT.xml")]
        junit: Option<PathBuf>,
        /// Scripts run at once (default: one per core).
        #[arg(long, value_parser = clap::value_parser!(u16).range(1..=256))]
        jobs: Option<u16>,
        /// Measure rung coverage over all the scripts and write it to this JSON file.
        #[arg(long, value_name = "OUT.json")]
        coverage: Option<PathBuf>,
        /// Measure rung coverage over all the scripts and write it as an HTML page.
        #[arg(long, value_name = "OUT.html")]
        coverage_html: Option<PathBuf>,
    },
    /// Time the scan.
    Bench {
        /// A project (.ldp) or an instruction list (.il).
        path: PathBuf,
        /// The scan engine (default: native where available, checked in a debug build).
        #[arg(long, value_enum)]
        engine: Option<EngineArg>,
        /// Also count machine instructions per scan and per step with valgrind's callgrind
        /// (steady on a busy machine, where the clock is not).
        #[arg(long)]
        instructions: bool,
        /// Time the ticks only, without the exchange's and the machine model's own timings
        /// (what `--instructions` counts).
        #[arg(long, hide = true)]
        ticks_only: bool,
        /// Scans to time, 1 to 100000000.
        #[arg(long, default_value_t = 10_000,
              value_parser = clap::value_parser!(u64).range(1..=sim::MAX_TICKS))]
        scans: u64,
        /// Run the simulated CNC too, and time its exchange.
        #[arg(long)]
        cnc: bool,
        /// A stimulus script run first, untimed (set the machine up, start a program).
        #[arg(long)]
        script: Option<PathBuf>,
        /// Run without the project's machine model.
        #[arg(long)]
        no_machine: bool,
        /// Measure rung coverage while timing (its cost against the plain scan).
        #[arg(long)]
        coverage: bool,
    },
    /// Print the project: a PDF document, or SVG pages.
    Print(print::PrintArgs),
    /// Build a project whose ladder diagram is drawn from an instruction list.
    ImportIl {
        /// The instruction list.
        il: PathBuf,
        /// The project file to write.
        #[arg(short, long)]
        output: PathBuf,
    },
}

/// Runs the command line; returns the exit code. Messages are in the system locale's
/// language unless `--lang` says otherwise.
pub fn run<I, T>(args: I, editor: Editor<'_>, out: &mut dyn Write, err: &mut dyn Write) -> i32
where
    I: IntoIterator<Item = T>,
    T: Into<OsString> + Clone,
{
    run_with(args, &Say::system_locale(), editor, out, err)
}

/// Runs the command line as in `locale` (tests give one, so they read the same everywhere),
/// without an editor: the subcommands only.
pub fn run_in<I, T>(args: I, locale: &str, out: &mut dyn Write, err: &mut dyn Write) -> i32
where
    I: IntoIterator<Item = T>,
    T: Into<OsString> + Clone,
{
    run_with(
        args,
        locale,
        &|start| {
            let lang = start.lang.unwrap_or(Say::new(None, locale).lang());
            Err(anyhow::anyhow!(StartText::NoEditor.text(lang)))
        },
        out,
        err,
    )
}

/// What the editor opens when no subcommand is given.
pub struct EditorStart {
    /// The project to open.
    pub project: Option<PathBuf>,
    /// Go online and run at once.
    pub run: bool,
    /// An NC program to load and start from the operator panel.
    pub nc: Option<String>,
    /// The UI language asked for on the command line (else the saved setting).
    pub lang: Option<ladder_text::Lang>,
}

/// Opens the editor window on an [`EditorStart`] and blocks until it closes. The binary passes the
/// window in, so this crate and its tests do not link the GUI.
pub type Editor<'a> = &'a dyn Fn(EditorStart) -> anyhow::Result<()>;

/// Runs the command line as in `locale`, opening `editor` when no subcommand is given.
pub fn run_with<I, T>(
    args: I,
    locale: &str,
    editor: Editor<'_>,
    out: &mut dyn Write,
    err: &mut dyn Write,
) -> i32
where
    I: IntoIterator<Item = T>,
    T: Into<OsString> + Clone,
{
    let cli = match Cli::try_parse_from(args) {
        Ok(cli) => cli,
        Err(e) => {
            let code = if e.use_stderr() { 2 } else { 0 };
            let text = e.render().to_string();
            let _ = if code == 0 {
                write!(out, "{text}")
            } else {
                write!(err, "{text}")
            };
            return code;
        }
    };
    let say = Say::new(cli.lang.as_deref(), locale);
    let lang = cli.lang.as_deref();
    if cli.command.is_some() && (cli.project.is_some() || cli.run) {
        let _ = writeln!(
            err,
            "ladder-studio: {}",
            say.text(StartText::ProjectAndSubcommand)
        );
        return 2;
    }
    let result = match cli.command {
        None => open_editor(cli, say, editor, err),
        Some(CliCommand::Check { path }) => check(&path, say, out),
        Some(CliCommand::ExportIl { path, output }) => {
            export_il(&path, output.as_deref(), say, out, err)
        }
        Some(CliCommand::ImportIl { il, output }) => import_il(&il, &output, say, err),
        Some(CliCommand::Sim {
            path,
            engine,
            script,
            trace,
            cnc,
            no_machine,
            coverage,
            coverage_html,
        }) => running::sim(
            &path,
            (
                &script,
                trace.as_deref(),
                coverage::Outputs {
                    json: coverage.as_deref(),
                    html: coverage_html.as_deref(),
                },
            ),
            (cnc, !no_machine, engine.map(EngineArg::engine)),
            say,
            out,
            err,
        ),
        Some(CliCommand::Test {
            path,
            engine,
            junit,
            jobs,
            coverage,
            coverage_html,
        }) => testing::test(
            &path,
            (
                junit.as_deref(),
                coverage::Outputs {
                    json: coverage.as_deref(),
                    html: coverage_html.as_deref(),
                },
            ),
            (jobs.map(usize::from), engine.map(EngineArg::engine)),
            say,
            out,
        ),
        Some(CliCommand::Bench {
            path,
            engine,
            instructions,
            ticks_only,
            scans,
            cnc,
            script,
            no_machine,
            coverage,
        }) => running::bench(
            &path,
            (scans, engine.map(EngineArg::engine), instructions),
            (cnc, !no_machine, coverage, ticks_only),
            script.as_deref(),
            say,
            out,
            err,
        ),
        Some(CliCommand::ExportComments { path, output }) => {
            export_comments(&path, lang, output.as_deref(), say, out, err)
        }
        Some(CliCommand::ImportComments { project, csv }) => {
            import_comments(&project, &csv, lang, say, out, err)
        }
        Some(CliCommand::Xref {
            path, bits, bytes, ..
        }) => xref(&path, bits, bytes, say, out, err),
        Some(CliCommand::Print(args)) => print::print(&args, say, out, err),
    };
    match result {
        Ok(code) => code,
        Err(e) => {
            let _ = writeln!(err, "ladder-studio: {e:#}");
            2
        }
    }
}

/// Without a subcommand: the editor, on PROJECT (online with `--run`), once the options
/// are known to be usable.
fn open_editor(cli: Cli, say: Say, editor: Editor<'_>, err: &mut dyn Write) -> anyhow::Result<i32> {
    if let Some(p) = &cli.project
        && !p.exists()
    {
        let _ = writeln!(
            err,
            "ladder-studio: {}",
            say.text(StartText::NoProjectOrSubcommand { name: shown(p) })
        );
        return Ok(2);
    }
    let read = ladder_engine::cnc::program::read_program_file;
    let nc = match cli.nc.as_deref().map(read) {
        Some(Ok(text)) => Some(text),
        Some(Err(e)) => {
            let nc = cli.nc.as_deref().unwrap_or(Path::new(""));
            let message = ladder_text::script::program_file_error(&e, nc, say.lang());
            let _ = writeln!(err, "ladder-studio: {message}");
            return Ok(2);
        }
        None => None,
    };
    // winit aborts without a display; say so instead.
    let display = ["DISPLAY", "WAYLAND_DISPLAY"]
        .iter()
        .any(|v| std::env::var_os(v).is_some_and(|s| !s.is_empty()));
    if !display {
        let _ = writeln!(err, "ladder-studio: {}", say.text(StartText::NoDisplay));
        return Ok(2);
    }
    let start = EditorStart {
        project: cli.project,
        run: cli.run,
        nc,
        lang: cli.lang.as_deref().map(|l| {
            if l == "zh" {
                ladder_text::Lang::Zh
            } else {
                ladder_text::Lang::En
            }
        }),
    };
    editor(start).map(|()| 0)
}

fn check(path: &Path, say: Say, out: &mut dyn Write) -> anyhow::Result<i32> {
    let source = Source::read(path, say)?;
    let compiled = source.compiled();
    print_diagnostics(path, &compiled, say, out);
    let _ = writeln!(out, "{}", say.summary(&compiled));
    Ok(i32::from(compiled.errors() > 0))
}

fn export_il(
    path: &Path,
    output: Option<&Path>,
    say: Say,
    out: &mut dyn Write,
    err: &mut dyn Write,
) -> anyhow::Result<i32> {
    let source = Source::read(path, say)?;
    let compiled = match &source {
        Source::Project(p) => diagnose(p),
        Source::Il { imported, .. } => match &imported.project {
            // Through the drawing, so the export is what the ladder holds.
            Some(p) => diagnose(p),
            None => imported.compiled.clone(),
        },
    };
    if compiled.diagnostics.iter().any(|d| d.code.is_structural()) {
        print_diagnostics(path, &compiled, say, err);
        let _ = writeln!(
            err,
            "{}",
            say.text(CheckText::IlNotWritten(Counts::of(&compiled)))
        );
        return Ok(1);
    }
    // Other errors (an undefined symbol, an address out of range) do not stop the export:
    // the list is what the ladder says, and the check explains what to fix.
    print_diagnostics(path, &compiled, say, err);
    let text = il::print(&compiled.program);
    write_output(output, &text, say, out)?;
    Ok(0)
}

/// Writes `text` to the `-o` file (whole or not at all, as every writer does), or to standard
/// output without one.
fn write_output(
    output: Option<&Path>,
    text: &str,
    say: Say,
    out: &mut dyn Write,
) -> anyhow::Result<()> {
    match output {
        Some(o) => ladder_engine::file::write_atomic(o, text.as_bytes())
            .map_err(|e| anyhow::anyhow!(say.cannot_write(o, e))),
        None => {
            let _ = out.write_all(text.as_bytes());
            Ok(())
        }
    }
}

fn import_il(path: &Path, output: &Path, say: Say, err: &mut dyn Write) -> anyhow::Result<i32> {
    let source = Source::read(path, say)?;
    let Source::Il { imported, .. } = source else {
        anyhow::bail!(say.text(FileText::IsAProject { path: shown(path) }));
    };
    print_diagnostics(path, &imported.compiled, say, err);
    let counts = Counts::of(&imported.compiled);
    let Some(project) = imported.project else {
        let _ = writeln!(err, "{}", say.text(CheckText::NoProjectWritten(counts)));
        return Ok(1);
    };
    file::save(&project, output).map_err(|e| anyhow::anyhow!(say.cannot_save(output, e)))?;
    let errors = counts.errors;
    if errors > 0 {
        let _ = writeln!(
            err,
            "{}",
            say.text(CheckText::WrittenWithErrors {
                counts,
                path: shown(output)
            })
        );
    }
    Ok(i32::from(errors > 0))
}

fn export_comments(
    path: &Path,
    lang: Option<&str>,
    output: Option<&Path>,
    say: Say,
    out: &mut dyn Write,
    err: &mut dyn Write,
) -> anyhow::Result<i32> {
    let project = match project_of(path, say, err)? {
        Ok(p) => p,
        Err(code) => return Ok(code),
    };
    let text = ladder_engine::comments::export(&project, lang);
    write_output(output, &text, say, out)?;
    Ok(0)
}

fn import_comments(
    project_path: &Path,
    csv_path: &Path,
    lang: Option<&str>,
    say: Say,
    out: &mut dyn Write,
    err: &mut dyn Write,
) -> anyhow::Result<i32> {
    let mut project =
        file::load(project_path).map_err(|e| anyhow::anyhow!(say.cannot_open(project_path, e)))?;
    let text = file::read_input_text(csv_path)
        .map_err(|e| anyhow::anyhow!(say.cannot_read(csv_path, e)))?;
    match ladder_engine::comments::import(&mut project, &text, lang) {
        Ok(n) => {
            file::save(&project, project_path)
                .map_err(|e| anyhow::anyhow!(say.cannot_save(project_path, e)))?;
            let _ = writeln!(
                out,
                "{}",
                say.text(CheckText::RowsApplied {
                    rows: n,
                    path: shown(project_path)
                })
            );
            Ok(0)
        }
        Err(ladder_engine::comments::CommentsError::Rejected(rows)) => {
            for (line, why) in &rows {
                let why = ladder_text::errors::rejection(why, say.lang());
                let _ = writeln!(err, "{}:{line}: {why}", csv_path.display());
            }
            let _ = writeln!(
                err,
                "{}",
                say.text(CheckText::RowsRejected { rows: rows.len() })
            );
            Ok(1)
        }
        Err(e) => anyhow::bail!(
            "{}: {}",
            csv_path.display(),
            ladder_text::errors::comments_error(&e, say.lang())
        ),
    }
}

fn xref(
    path: &Path,
    bits: bool,
    bytes: bool,
    say: Say,
    out: &mut dyn Write,
    err: &mut dyn Write,
) -> anyhow::Result<i32> {
    let project = match project_of(path, say, err)? {
        Ok(p) => p,
        Err(code) => return Ok(code),
    };
    let x = ladder_engine::xref::build(&project);
    let text = if bits {
        ladder_engine::xref::bits_text(&x)
    } else if bytes {
        ladder_engine::xref::bytes_text(&x)
    } else {
        ladder_engine::xref::index_text(&project, &x)
    };
    let _ = out.write_all(text.as_bytes());
    Ok(0)
}
