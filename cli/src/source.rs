//! Reading a PATH argument: a project file or an instruction list, told apart by content,
//! and what the commands build from it: its diagnostics, its project, its program, its machine.

use super::say::{Say, shown};
use anyhow::{Result, anyhow, bail};
use ladder_engine::compiler::{Compiled, compile};
use ladder_engine::machine::Machine;
use ladder_engine::model::Project;
use ladder_engine::vm::Engine;
use ladder_engine::{file, il};
use ladder_text::cli::{CheckText, Counts, FileText, RunText};
use ladder_text::errors::build_error;
use std::io::Write;
use std::path::Path;

/// What a PATH held.
pub enum Source {
    /// A project file.
    Project(Project),
    /// An instruction list, with the project drawn from it when it could be drawn.
    Il {
        /// The import result (diagnostics carry IL lines).
        imported: il::Imported,
    },
}

impl Source {
    /// Reads a `.ldp` project or an `.il` text; the content decides, not the extension.
    /// Errors are said in `say`'s language.
    pub fn read(path: &Path, say: Say) -> Result<Source> {
        let bytes = file::read_input(path).map_err(|e| anyhow!(say.cannot_read(path, e)))?;
        if file::is_project_text(&bytes) {
            let project =
                file::from_bytes(&bytes).map_err(|e| anyhow!(say.cannot_open(path, e)))?;
            return Ok(Source::Project(project));
        }
        let Ok(text) = String::from_utf8(bytes) else {
            bail!(say.text(FileText::NotText { path: shown(path) }));
        };
        let imported = il::import(&text);
        Ok(Source::Il { imported })
    }

    /// The compile result: for a project, every diagnostic of it (`diagnose`); for IL, the IL
    /// checked.
    pub fn compiled(&self) -> Compiled {
        match self {
            Source::Project(p) => ladder_engine::diagnose::diagnose(p),
            Source::Il { imported, .. } => imported.compiled.clone(),
        }
    }
}

/// Prints each diagnostic of `compiled` on a line of its own, named by `path`.
pub(super) fn print_diagnostics(path: &Path, compiled: &Compiled, say: Say, w: &mut dyn Write) {
    let shown = path.display().to_string();
    for d in &compiled.diagnostics {
        let _ = writeln!(w, "{}", say.diagnostic(d, &shown));
    }
}

/// The program a PATH runs, as [`machine`] builds it (for placing what the machine measured,
/// such as coverage, back on its instructions).
pub(super) fn program_of(
    path: &Path,
    say: Say,
) -> anyhow::Result<ladder_engine::compiler::Program> {
    Ok(match Source::read(path, say)? {
        Source::Project(p) => compile(&p).program,
        Source::Il { imported, .. } => imported.compiled.program,
    })
}

/// `--engine`: the scan engines by their command-line names.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum EngineArg {
    /// The interpreter, the reference.
    Interp,
    /// Generated machine code.
    Native,
    /// Both, checked against each other at every tick.
    Checked,
}

impl EngineArg {
    /// The engine this name stands for.
    pub(super) fn engine(self) -> Engine {
        match self {
            EngineArg::Interp => Engine::Interpreter,
            EngineArg::Native => Engine::Native,
            EngineArg::Checked => Engine::Checked,
        }
    }
}

/// Builds the machine for a PATH (with the simulated CNC when `cnc`), or reports why the
/// program cannot run (exit 1).
pub(super) fn machine(
    path: &Path,
    (cnc, engine): (bool, Option<Engine>),
    say: Say,
    err: &mut dyn Write,
) -> anyhow::Result<Result<Machine, i32>> {
    let mut built = machine_of(path, cnc, say, err)?;
    if let (Ok(m), Some(engine)) = (&mut built, engine)
        && m.plc_mut().set_engine(engine) != engine
    {
        let _ = writeln!(err, "{}", say.text(RunText::NoNativeCode));
    }
    Ok(built)
}

/// Builds the machine that runs `path`, on the engine a new PLC starts with.
fn machine_of(
    path: &Path,
    cnc: bool,
    say: Say,
    err: &mut dyn Write,
) -> anyhow::Result<Result<Machine, i32>> {
    let source = Source::read(path, say)?;
    let cannot_run = |compiled: &Compiled, err: &mut dyn Write| {
        print_diagnostics(path, compiled, say, err);
        let _ = writeln!(
            err,
            "{}",
            say.text(CheckText::CannotRun(Counts::of(compiled)))
        );
    };
    let project = match source {
        Source::Project(p) => p,
        // An instruction list runs exactly as written, drawable or not: its steps decide
        // where each level-2 slice ends, and its diagnostics name its lines.
        Source::Il { imported, .. } => {
            if imported.compiled.errors() > 0 {
                cannot_run(&imported.compiled, err);
                return Ok(Err(1));
            }
            let base = Project::default();
            let m = Machine::from_program(&base, &imported.compiled.program, cnc)
                .map_err(|e| anyhow!(build_error(&e, say.lang())))?;
            return Ok(Ok(m));
        }
    };
    let compiled = compile(&project);
    if compiled.errors() > 0 {
        cannot_run(&compiled, err);
        return Ok(Err(1));
    }
    Ok(Ok(
        Machine::new(&project, cnc).map_err(|e| anyhow!(build_error(&e, say.lang())))?
    ))
}

/// The project a PATH holds (an IL file drawn as a ladder), or the exit code when it has none.
pub(super) fn project_of(
    path: &Path,
    say: Say,
    err: &mut dyn Write,
) -> anyhow::Result<Result<ladder_engine::model::Project, i32>> {
    Ok(match Source::read(path, say)? {
        Source::Project(p) => Ok(p),
        Source::Il { imported, .. } => match imported.project {
            Some(p) => Ok(p),
            None => {
                print_diagnostics(path, &imported.compiled, say, err);
                let _ = writeln!(
                    err,
                    "{}",
                    say.text(CheckText::NotDrawable(Counts::of(&imported.compiled)))
                );
                Err(1)
            }
        },
    })
}
