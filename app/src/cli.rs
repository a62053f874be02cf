//! The headless subcommands (docs/files.md, "Command line"). Exit codes: 0 success, 1 valid
//! input that fails (compile errors), 2 unusable input (missing, unreadable or corrupt file, bad
//! arguments).

use crate::source::Source;
use clap::{Parser, Subcommand};
use ladder_engine::compiler::{Compiled, compile};
use ladder_engine::machine::Machine;
use ladder_engine::sim::{self, Script};
use ladder_engine::vm::cnc::Cnc;
use ladder_engine::{file, il};
use std::ffi::OsString;
use std::io::Write;
use std::path::{Path, PathBuf};

/// Ladder editor, compiler and simulator for the PLC of GSK CNC controllers.
#[derive(Parser, Debug)]
#[command(name = "ladder-studio", version, about)]
#[command(args_conflicts_with_subcommands = true)]
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
    /// What to do.
    #[command(subcommand)]
    pub command: Option<Command>,
}

/// The subcommands.
#[derive(Subcommand, Debug)]
pub enum Command {
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
        /// Only this language's column (zh or en).
        #[arg(long)]
        lang: Option<String>,
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
        /// Only this language's column (zh or en).
        #[arg(long)]
        lang: Option<String>,
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
        /// The stimulus script.
        #[arg(long)]
        script: PathBuf,
        /// Write every watched address per tick to this CSV file.
        #[arg(long)]
        trace: Option<PathBuf>,
        /// Also run the simulated CNC (the `cnc` script commands and `cnc.KEY` values).
        #[arg(long)]
        cnc: bool,
    },
    /// Time the scan.
    Bench {
        /// A project (.ldp) or an instruction list (.il).
        path: PathBuf,
        /// Scans to time.
        #[arg(long, default_value_t = 10_000)]
        scans: u64,
        /// Run the simulated CNC too, and time its exchange.
        #[arg(long)]
        cnc: bool,
        /// A stimulus script run first, untimed (set the machine up, start a program).
        #[arg(long)]
        script: Option<PathBuf>,
    },
    /// Build a project whose ladder diagram is drawn from an instruction list.
    ImportIl {
        /// The instruction list.
        il: PathBuf,
        /// The project file to write.
        #[arg(short, long)]
        output: PathBuf,
    },
}

/// Runs the command line; returns the exit code.
pub fn run<I, T>(args: I, out: &mut dyn Write, err: &mut dyn Write) -> i32
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
    let result = match cli.command {
        None => {
            if let Some(p) = &cli.project
                && !p.exists()
            {
                let _ = writeln!(
                    err,
                    "ladder-studio: no project file or subcommand `{}` (see --help)",
                    p.display()
                );
                return 2;
            }
            let nc = match cli.nc.as_deref().map(std::fs::read_to_string) {
                Some(Ok(text)) => Some(text),
                Some(Err(e)) => {
                    let _ = writeln!(
                        err,
                        "ladder-studio: cannot read the NC program {}: {e}",
                        cli.nc.as_deref().unwrap_or(Path::new("")).display()
                    );
                    return 2;
                }
                None => None,
            };
            // winit aborts without a display; say so instead.
            let display = ["DISPLAY", "WAYLAND_DISPLAY"]
                .iter()
                .any(|v| std::env::var_os(v).is_some_and(|s| !s.is_empty()));
            if !display {
                let _ = writeln!(
                    err,
                    "ladder-studio: the editor needs a graphical session (no DISPLAY or WAYLAND_DISPLAY); the subcommands run without one (see --help)"
                );
                return 2;
            }
            let start = crate::gui::Start {
                project: cli.project,
                run: cli.run,
                nc,
            };
            crate::gui::run(start).map(|()| 0)
        }
        Some(Command::Check { path }) => check(&path, out),
        Some(Command::ExportIl { path, output }) => export_il(&path, output.as_deref(), out, err),
        Some(Command::ImportIl { il, output }) => import_il(&il, &output, err),
        Some(Command::Sim {
            path,
            script,
            trace,
            cnc,
        }) => sim(&path, &script, trace.as_deref(), cnc, out, err),
        Some(Command::Bench {
            path,
            scans,
            cnc,
            script,
        }) => bench(&path, scans, cnc, script.as_deref(), out, err),
        Some(Command::ExportComments { path, lang, output }) => {
            export_comments(&path, lang.as_deref(), output.as_deref(), out, err)
        }
        Some(Command::ImportComments { project, csv, lang }) => {
            import_comments(&project, &csv, lang.as_deref(), out, err)
        }
        Some(Command::Xref {
            path, bits, bytes, ..
        }) => xref(&path, bits, bytes, out, err),
    };
    match result {
        Ok(code) => code,
        Err(e) => {
            let _ = writeln!(err, "ladder-studio: {e:#}");
            2
        }
    }
}

fn print_diagnostics(path: &Path, compiled: &Compiled, w: &mut dyn Write) {
    let shown = path.display().to_string();
    for d in &compiled.diagnostics {
        let _ = writeln!(w, "{}", d.render(&shown));
    }
}

fn summary(compiled: &Compiled) -> String {
    let plural = |n: usize, word: &str| format!("{n} {word}{}", if n == 1 { "" } else { "s" });
    format!(
        "{}, {}",
        plural(compiled.errors(), "error"),
        plural(compiled.warnings(), "warning")
    )
}

fn check(path: &Path, out: &mut dyn Write) -> anyhow::Result<i32> {
    let source = Source::read(path)?;
    let compiled = source.compiled();
    print_diagnostics(path, &compiled, out);
    let _ = writeln!(out, "{}", summary(&compiled));
    Ok(i32::from(compiled.errors() > 0))
}

fn export_il(
    path: &Path,
    output: Option<&Path>,
    out: &mut dyn Write,
    err: &mut dyn Write,
) -> anyhow::Result<i32> {
    let source = Source::read(path)?;
    let compiled = match &source {
        Source::Project(p) => compile(p),
        Source::Il { imported, .. } => match &imported.project {
            // Through the drawing, so the export is what the ladder holds.
            Some(p) => compile(p),
            None => imported.compiled.clone(),
        },
    };
    if compiled.diagnostics.iter().any(|d| d.code.is_structural()) {
        print_diagnostics(path, &compiled, err);
        let _ = writeln!(err, "{}; no instruction list written", summary(&compiled));
        return Ok(1);
    }
    // Other errors (an undefined symbol, an address out of range) do not stop the export:
    // the list is what the ladder says, and the check explains what to fix.
    print_diagnostics(path, &compiled, err);
    let text = il::print(&compiled.program);
    write_output(output, &text, out)?;
    Ok(0)
}

/// Writes `text` to the `-o` file, or to standard output without one.
fn write_output(output: Option<&Path>, text: &str, out: &mut dyn Write) -> anyhow::Result<()> {
    match output {
        Some(o) => std::fs::write(o, text)
            .map_err(|e| anyhow::anyhow!("cannot write {}: {e}", o.display())),
        None => {
            let _ = out.write_all(text.as_bytes());
            Ok(())
        }
    }
}

fn import_il(path: &Path, output: &Path, err: &mut dyn Write) -> anyhow::Result<i32> {
    let source = Source::read(path)?;
    let Source::Il { imported, .. } = source else {
        anyhow::bail!(
            "{} is a project file, not an instruction list; use export-il to get its IL",
            path.display()
        );
    };
    print_diagnostics(path, &imported.compiled, err);
    let Some(project) = imported.project else {
        let _ = writeln!(
            err,
            "{}; the instruction list cannot be drawn as a ladder, no project written",
            summary(&imported.compiled)
        );
        return Ok(1);
    };
    file::save(&project, output)
        .map_err(|e| anyhow::anyhow!("cannot save {}: {e}", output.display()))?;
    let errors = imported.compiled.errors();
    if errors > 0 {
        let _ = writeln!(
            err,
            "{}; project written to {} with the errors to fix",
            summary(&imported.compiled),
            output.display()
        );
    }
    Ok(i32::from(errors > 0))
}

/// Builds the machine for a PATH (with the simulated CNC when `cnc`), or reports why the
/// program cannot run (exit 1).
fn machine(path: &Path, cnc: bool, err: &mut dyn Write) -> anyhow::Result<Result<Machine, i32>> {
    let source = Source::read(path)?;
    let project = match source {
        Source::Project(p) => p,
        Source::Il { imported, .. } => match imported.project {
            Some(p) => p,
            None => {
                print_diagnostics(path, &imported.compiled, err);
                let _ = writeln!(
                    err,
                    "{}; the program cannot run",
                    summary(&imported.compiled)
                );
                return Ok(Err(1));
            }
        },
    };
    let compiled = compile(&project);
    if compiled.errors() > 0 {
        print_diagnostics(path, &compiled, err);
        let _ = writeln!(err, "{}; the program cannot run", summary(&compiled));
        return Ok(Err(1));
    }
    Ok(Ok(
        Machine::new(&project, cnc).map_err(|e| anyhow::anyhow!("{e}"))?
    ))
}

/// Reads and parses a stimulus script (`cnc program-file` paths relative to its folder), or
/// reports its first bad line (exit 2).
fn read_script(
    script_path: &Path,
    machine: &Machine,
    cnc: bool,
    err: &mut dyn Write,
) -> anyhow::Result<Result<Script, i32>> {
    let text = std::fs::read_to_string(script_path)
        .map_err(|e| anyhow::anyhow!("cannot read {}: {e}", script_path.display()))?;
    let folder = script_path
        .parent()
        .map(Path::to_path_buf)
        .unwrap_or_default();
    let read_file = |p: &str| -> Result<String, String> {
        let full = folder.join(p);
        std::fs::read_to_string(&full).map_err(|e| format!("cannot read {}: {e}", full.display()))
    };
    let options = sim::Options {
        cnc,
        read_file: &read_file,
    };
    match Script::parse_with(&text, machine.plc.profile(), &options) {
        Ok(s) => Ok(Ok(s)),
        Err(e) => {
            let _ = writeln!(err, "{}:{}: {}", script_path.display(), e.line, e.message);
            Ok(Err(2))
        }
    }
}

fn sim(
    path: &Path,
    script_path: &Path,
    trace: Option<&Path>,
    cnc: bool,
    out: &mut dyn Write,
    err: &mut dyn Write,
) -> anyhow::Result<i32> {
    if !script_path.is_file() {
        anyhow::bail!("cannot read {}: no such file", script_path.display());
    }
    let mut machine = match machine(path, cnc, err)? {
        Ok(m) => m,
        Err(code) => return Ok(code),
    };
    let script = match read_script(script_path, &machine, cnc, err)? {
        Ok(s) => s,
        Err(code) => return Ok(code),
    };
    let name = script_path.display().to_string();
    let outcome = sim::run(&mut machine, &script, &name, trace.is_some());
    for line in &outcome.output {
        let _ = writeln!(out, "{line}");
    }
    if let Some(t) = trace {
        std::fs::write(t, &outcome.trace_csv)
            .map_err(|e| anyhow::anyhow!("cannot write {}: {e}", t.display()))?;
    }
    let _ = writeln!(out, "{} passed, {} failed", outcome.passed, outcome.failed);
    Ok(i32::from(outcome.failed > 0))
}

fn bench(
    path: &Path,
    scans: u64,
    cnc: bool,
    setup: Option<&Path>,
    out: &mut dyn Write,
    err: &mut dyn Write,
) -> anyhow::Result<i32> {
    let mut machine = match machine(path, cnc, err)? {
        Ok(m) => m,
        Err(code) => return Ok(code),
    };
    if let Some(script_path) = setup {
        let script = match read_script(script_path, &machine, cnc, err)? {
            Ok(s) => s,
            Err(code) => return Ok(code),
        };
        let name = script_path.display().to_string();
        let outcome = sim::run(&mut machine, &script, &name, false);
        if outcome.failed > 0 {
            for line in &outcome.output {
                let _ = writeln!(err, "{line}");
            }
            let _ = writeln!(err, "the set-up script failed; nothing was timed");
            return Ok(1);
        }
    }
    let scans = scans.max(1);
    // Warm up caches and branch predictors before timing.
    for _ in 0..scans.min(1000) {
        machine.tick();
    }
    let before = machine.plc.executed_steps();
    let start = std::time::Instant::now();
    for _ in 0..scans {
        machine.tick();
    }
    let elapsed = start.elapsed().as_nanos() as f64;
    if let Some(h) = machine.plc.halt() {
        let _ = writeln!(err, "the PLC halted during the benchmark: {h}");
        return Ok(1);
    }
    let steps = (machine.plc.executed_steps() - before) as f64 / scans as f64;
    let ns_per_scan = elapsed / scans as f64;
    if let Some(cnc) = &mut machine.cnc {
        // The exchange alone, timed inside the same kind of run (the clock read adds a few
        // tens of ns to each figure).
        let mut timed = TimedCnc { cnc, nanos: 0 };
        for _ in 0..scans {
            machine.plc.tick(&mut timed);
        }
        let per = timed.nanos as f64 / scans as f64;
        let hour = ns_per_scan * 450_000.0 / 1e9;
        let _ = writeln!(
            out,
            "cnc_ns_per_exchange={per:.1} machine_ns_per_tick={ns_per_scan:.1} one_hour_s={hour:.3}"
        );
    }
    let _ = writeln!(
        out,
        "steps={} scans={scans} ns_per_scan={:.1} ns_per_step={:.3}",
        steps.round() as u64,
        ns_per_scan,
        ns_per_scan / steps.max(1.0)
    );
    Ok(0)
}

/// The simulated CNC with a stopwatch on its exchange, for `bench --cnc`.
struct TimedCnc<'a> {
    cnc: &'a mut ladder_engine::cnc::SimCnc,
    nanos: u128,
}

impl Cnc for TimedCnc<'_> {
    fn window_is_low_speed(&self, function: i32) -> bool {
        self.cnc.window_is_low_speed(function)
    }
    fn window(&mut self, block: &mut [i32]) {
        self.cnc.window(block);
    }
    fn machine_position(&self, axis: u32) -> Option<i64> {
        self.cnc.machine_position(axis)
    }
    fn axis_status(&self, group: u8, ebuf: bool) -> ladder_engine::vm::cnc::AxisStatus {
        self.cnc.axis_status(group, ebuf)
    }
    fn exchange(&mut self, now_ms: u64, g: &[u8], a: &[u8], f: &mut [u8]) {
        let t = std::time::Instant::now();
        self.cnc.exchange(now_ms, g, a, f);
        self.nanos += t.elapsed().as_nanos();
    }
}

/// The project a PATH holds (an IL file drawn as a ladder), or the exit code when it has none.
fn project_of(
    path: &Path,
    err: &mut dyn Write,
) -> anyhow::Result<Result<ladder_engine::model::Project, i32>> {
    Ok(match Source::read(path)? {
        Source::Project(p) => Ok(p),
        Source::Il { imported, .. } => match imported.project {
            Some(p) => Ok(p),
            None => {
                print_diagnostics(path, &imported.compiled, err);
                let _ = writeln!(
                    err,
                    "{}; the instruction list cannot be drawn",
                    summary(&imported.compiled)
                );
                Err(1)
            }
        },
    })
}

fn check_lang(lang: Option<&str>) -> anyhow::Result<()> {
    match lang {
        None | Some("zh") | Some("en") => Ok(()),
        Some(other) => anyhow::bail!("--lang is zh or en, not `{other}`"),
    }
}

fn export_comments(
    path: &Path,
    lang: Option<&str>,
    output: Option<&Path>,
    out: &mut dyn Write,
    err: &mut dyn Write,
) -> anyhow::Result<i32> {
    check_lang(lang)?;
    let project = match project_of(path, err)? {
        Ok(p) => p,
        Err(code) => return Ok(code),
    };
    let text = ladder_engine::comments::export(&project, lang);
    write_output(output, &text, out)?;
    Ok(0)
}

fn import_comments(
    project_path: &Path,
    csv_path: &Path,
    lang: Option<&str>,
    out: &mut dyn Write,
    err: &mut dyn Write,
) -> anyhow::Result<i32> {
    check_lang(lang)?;
    let mut project = file::load(project_path)
        .map_err(|e| anyhow::anyhow!("{} cannot be opened: {e}", project_path.display()))?;
    let text = std::fs::read_to_string(csv_path)
        .map_err(|e| anyhow::anyhow!("cannot read {}: {e}", csv_path.display()))?;
    match ladder_engine::comments::import(&mut project, &text, lang) {
        Ok(n) => {
            file::save(&project, project_path)
                .map_err(|e| anyhow::anyhow!("cannot save {}: {e}", project_path.display()))?;
            let _ = writeln!(out, "{n} rows applied to {}", project_path.display());
            Ok(0)
        }
        Err(ladder_engine::comments::CommentsError::Rejected(rows)) => {
            for (line, message) in &rows {
                let _ = writeln!(err, "{}:{line}: {message}", csv_path.display());
            }
            let _ = writeln!(
                err,
                "{} row(s) rejected; the project was not changed",
                rows.len()
            );
            Ok(1)
        }
        Err(e) => anyhow::bail!("{}: {e}", csv_path.display()),
    }
}

fn xref(
    path: &Path,
    bits: bool,
    bytes: bool,
    out: &mut dyn Write,
    err: &mut dyn Write,
) -> anyhow::Result<i32> {
    let project = match project_of(path, err)? {
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
