//! `test PROJECT [--junit OUT.xml] [--jobs N]`: runs every stimulus script of the project's
//! test folder, each on a fresh machine, several at once, and says which passed
//! (docs/scripts.md, "Test folders").
//!
//! The test folder of `NAME.ldp` (or `NAME.il`) is `NAME.tests/` beside it; its scripts are
//! its `*.script` files, run in name order. A script chooses how it runs with a comment
//! line `# test: cnc` (the simulated CNC, as `sim --cnc`) and `# test: no-machine` (without
//! the project's machine model, as `sim --no-machine`); words may share one line.

use super::running::{STOPPED, read_script, stop_on_ctrl_c};
use super::say::{Say, shown};
use ladder_engine::compiler::Program;
use ladder_engine::coverage::Coverage;
use ladder_engine::sim::{self, Control};
use ladder_engine::vm::Engine;
use ladder_text::Lang;
use ladder_text::cli::{CaseFailure, FileText, TestText};
use ladder_text::errors::coverage_error;
use quick_junit::{NonSuccessKind, Report, TestCase, TestCaseStatus, TestSuite};
use std::io::Write;
use std::path::{Path, PathBuf};
use std::sync::Mutex;
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::time::{Duration, Instant};

/// One script of a test folder and how it runs.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Case {
    /// The script.
    pub file: PathBuf,
    /// As it is named in the output: `FOLDER/NAME.script`.
    pub name: String,
    /// With the simulated CNC.
    pub cnc: bool,
    /// With the project's machine model.
    pub devices: bool,
}

/// What one script did.
#[derive(Clone, Debug, Default)]
struct Ran {
    /// Checks (`expect`, `expectf`) that held.
    passed: usize,
    /// Checks that did not, and commands that could not apply.
    failed: usize,
    /// What the run printed (failed checks, `print`s, halts).
    output: Vec<String>,
    /// Why the script could not run at all (the program does not compile, the script does
    /// not parse), as the `sim` command would have said it.
    error: Option<String>,
    /// Stopped by Ctrl+C before its end.
    stopped: bool,
    /// How long it took.
    time: Duration,
    /// Its rung coverage, when measured.
    coverage: Option<Coverage>,
}

impl Ran {
    fn ok(&self) -> bool {
        self.failed == 0 && self.error.is_none() && !self.stopped
    }
}

/// The test folder of a project: `NAME.tests/` beside `NAME.ldp`.
pub fn test_folder(project: &Path) -> PathBuf {
    let stem = project
        .file_stem()
        .map_or("project".into(), |s| s.to_string_lossy());
    project.with_file_name(format!("{stem}.tests"))
}

/// How a script asks to run: its `# test:` comment lines.
pub fn directives(text: &str) -> (bool, bool) {
    let (mut cnc, mut devices) = (false, true);
    for line in text.lines() {
        let Some(words) = line.trim().strip_prefix('#') else {
            continue;
        };
        let Some(words) = words.trim().strip_prefix("test:") else {
            continue;
        };
        for w in words.split_whitespace() {
            match w {
                "cnc" => cnc = true,
                "no-machine" => devices = false,
                _ => {}
            }
        }
    }
    (cnc, devices)
}

/// The scripts of a test folder, in name order.
pub fn cases(folder: &Path) -> std::io::Result<Vec<Case>> {
    let mut files: Vec<PathBuf> = std::fs::read_dir(folder)?
        .filter_map(Result::ok)
        .map(|e| e.path())
        .filter(|p| p.is_file() && p.extension().is_some_and(|x| x == "script"))
        .collect();
    files.sort();
    let shown = folder
        .file_name()
        .map_or(String::new(), |n| n.to_string_lossy().into_owned());
    files
        .into_iter()
        .map(|file| {
            let text = std::fs::read_to_string(&file)?;
            let (cnc, devices) = directives(&text);
            let name = file
                .file_name()
                .map_or(String::new(), |n| n.to_string_lossy().into_owned());
            Ok(Case {
                name: format!("{shown}/{name}"),
                file,
                cnc,
                devices,
            })
        })
        .collect()
}

/// Runs one script on a machine of its own.
/// With `program`, rung coverage is measured on it.
fn run_case(
    project: &Path,
    case: &Case,
    (stop, program, engine): (&AtomicBool, Option<&Program>, Option<Engine>),
    say: Say,
) -> Ran {
    let start = Instant::now();
    let mut said = Vec::new();
    let mut ran = Ran::default();
    let machine = match super::source::machine(project, (case.cnc, engine), say, &mut said) {
        Ok(Ok(m)) if case.devices => Some(m),
        Ok(Ok(m)) => Some(m.without_devices()),
        Ok(Err(_)) => None,
        Err(e) => {
            let _ = writeln!(said, "{e:#}");
            None
        }
    };
    let script = match &machine {
        Some(m) => match read_script((project, &case.file), m, case.cnc, say, &mut said) {
            Ok(Ok(s)) => Some(s),
            Ok(Err(_)) => None,
            Err(e) => {
                let _ = writeln!(said, "{e:#}");
                None
            }
        },
        None => None,
    };
    match (machine, script) {
        (Some(mut machine), Some(script)) => {
            if program.is_some() {
                machine.plc_mut().set_coverage(true);
            }
            let control = Control {
                trace: None,
                stop: Some(stop),
                progress: None,
            };
            let name = case.file.display().to_string();
            match sim::run_with(&mut machine, &script, &name, control) {
                Ok(o) => {
                    ran.passed = o.passed;
                    ran.failed = o.failed;
                    ran.output = o
                        .output
                        .iter()
                        .map(|r| ladder_text::sim::report(&o.script, r, say.lang()))
                        .collect();
                    ran.stopped = o.stopped.is_some();
                    ran.coverage = program.and_then(|p| Coverage::measure(machine.plc(), p));
                }
                Err(e) => ran.error = Some(e.to_string()),
            }
        }
        _ => ran.error = Some(String::from_utf8_lossy(&said).trim_end().to_string()),
    }
    ran.time = start.elapsed();
    ran
}

/// Runs the cases on `jobs` threads; the results come back in the cases' order.
/// Once Ctrl+C sets `stop`, the script running stops and no other starts.
fn run_all(
    project: &Path,
    cases: &[Case],
    (jobs, stop, program, engine): (usize, &AtomicBool, Option<&Program>, Option<Engine>),
    say: Say,
) -> Vec<Ran> {
    let next = AtomicUsize::new(0);
    let results: Mutex<Vec<Option<Ran>>> = Mutex::new(vec![None; cases.len()]);
    std::thread::scope(|scope| {
        for worker in 0..jobs.clamp(1, cases.len().max(1)) {
            let (next, results) = (&next, &results);
            let spawned = std::thread::Builder::new()
                .name(format!("test-{worker}"))
                .spawn_scoped(scope, move || {
                    loop {
                        let i = next.fetch_add(1, Ordering::SeqCst);
                        let Some(case) = cases.get(i) else { break };
                        if stop.load(Ordering::SeqCst) {
                            break;
                        }
                        let ran = run_case(project, case, (stop, program, engine), say);
                        if let Ok(mut r) = results.lock() {
                            r[i] = Some(ran);
                        }
                    }
                });
            if spawned.is_err() {
                // No thread to be had: the cases left run on the threads there are, or
                // below on this one.
                break;
            }
        }
    });
    let results = results.into_inner().unwrap_or_default();
    results
        .into_iter()
        .zip(cases)
        .map(|(r, case)| match r {
            Some(r) => r,
            // Not started: stopped before its turn, else no thread could be had.
            None if stop.load(Ordering::SeqCst) => Ran {
                stopped: true,
                ..Ran::default()
            },
            None => run_case(project, case, (stop, program, engine), say),
        })
        .collect()
}

/// The JUnit XML report of a run: one test suite (the project), one test case per script.
fn junit(project: &Path, cases: &[Case], results: &[Ran]) -> String {
    let project_name = project
        .file_name()
        .map_or(String::new(), |n| n.to_string_lossy().into_owned());
    let mut suite = TestSuite::new(project_name.clone());
    let mut total = Duration::ZERO;
    for (case, ran) in cases.iter().zip(results) {
        let status = if ran.ok() {
            TestCaseStatus::success()
        } else {
            let kind = if ran.error.is_some() {
                NonSuccessKind::Error
            } else {
                NonSuccessKind::Failure
            };
            let mut s = TestCaseStatus::non_success(kind);
            let message = match &ran.error {
                Some(e) => e.lines().next().unwrap_or_default().to_string(),
                // English whatever the language: the report is read by a CI server.
                None if ran.stopped => CaseFailure::Stopped.text(Lang::En),
                None => CaseFailure::Checks {
                    failed: ran.failed,
                    checks: ran.passed + ran.failed,
                }
                .text(Lang::En),
            };
            s.set_message(message);
            let detail = ran.error.clone().unwrap_or_else(|| ran.output.join("\n"));
            s.set_description(detail);
            s
        };
        let mut tc = TestCase::new(case.name.clone(), status);
        tc.set_classname(project_name.clone())
            .set_assertions(ran.passed + ran.failed)
            .set_time(ran.time);
        if !ran.output.is_empty() {
            tc.set_system_out(ran.output.join("\n"));
        }
        total += ran.time;
        suite.add_test_case(tc);
    }
    suite.set_time(total);
    let mut report = Report::new("ladder-studio test");
    report.add_test_suite(suite);
    report.to_string().unwrap_or_default()
}

/// `test PROJECT`: exit 0 when every script passes, 1 when one fails or cannot run, 2 when
/// there is nothing to run or the report cannot be written.
pub(super) fn test(
    project: &Path,
    (junit_out, coverage_out): (Option<&Path>, super::coverage::Outputs<'_>),
    (jobs, engine): (Option<usize>, Option<Engine>),
    say: Say,
    out: &mut dyn Write,
) -> anyhow::Result<i32> {
    if !project.is_file() {
        let path = shown(project);
        anyhow::bail!(if project.exists() {
            say.text(FileText::NotAProjectFile { path })
        } else {
            say.text(FileText::NoSuchFile { path })
        });
    }
    coverage_out.check(say)?;
    if let Some(path) = junit_out {
        super::coverage::writable(path, say)?;
    }
    let folder = test_folder(project);
    let cases = cases(&folder).map_err(|e| {
        anyhow::anyhow!(say.text(TestText::NoTestFolder {
            folder: shown(&folder),
            why: e.to_string(),
        }))
    })?;
    if cases.is_empty() {
        anyhow::bail!(say.text(TestText::NoScripts {
            folder: shown(&folder)
        }));
    }
    let jobs = jobs.unwrap_or_else(|| std::thread::available_parallelism().map_or(1, |n| n.get()));
    let program = match coverage_out.wanted() {
        true => Some(super::source::program_of(project, say)?),
        false => None,
    };
    let results = run_all(
        project,
        &cases,
        (jobs, stop_on_ctrl_c(), program.as_ref(), engine),
        say,
    );
    let mut failed = 0;
    for (case, ran) in cases.iter().zip(&results) {
        let checks = ran.passed + ran.failed;
        if ran.ok() {
            let _ = writeln!(
                out,
                "{}",
                say.text(TestText::CaseOk {
                    name: case.name.clone(),
                    checks
                })
            );
            continue;
        }
        failed += 1;
        let why = match &ran.error {
            Some(_) => CaseFailure::CannotRun,
            None if ran.stopped => CaseFailure::Stopped,
            None => CaseFailure::Checks {
                failed: ran.failed,
                checks,
            },
        };
        let _ = writeln!(
            out,
            "{}",
            say.text(TestText::CaseFailed {
                name: case.name.clone(),
                why
            })
        );
        let detail = ran.error.iter().flat_map(|e| e.lines().map(str::to_string));
        for line in detail.chain(ran.output.iter().cloned()) {
            let _ = writeln!(out, "      {line}");
        }
    }
    if coverage_out.wanted() {
        // Merged in the scripts' order: the same whatever finished first.
        let mut merged: Option<Coverage> = None;
        for c in results.iter().filter_map(|r| r.coverage.as_ref()) {
            match &mut merged {
                None => merged = Some(c.clone()),
                Some(m) => m
                    .merge(c)
                    .map_err(|e| anyhow::anyhow!(coverage_error(&e, say.lang())))?,
            }
        }
        if let Some(m) = merged {
            coverage_out.report(&m, project, say, out)?;
        }
    }
    let passed = cases.len() - failed;
    let _ = writeln!(out, "{}", say.passed(passed, failed));
    if let Some(path) = junit_out {
        let xml = junit(project, &cases, &results);
        ladder_engine::file::write_atomic(path, xml.as_bytes())
            .map_err(|e| anyhow::anyhow!(say.cannot_write(path, e)))?;
    }
    if results.iter().any(|r| r.stopped) {
        return Ok(STOPPED);
    }
    Ok(i32::from(failed > 0))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn directives_choose_the_cnc_and_the_machine_model() {
        assert_eq!(directives("scan 1\n"), (false, true));
        assert_eq!(directives("# test: cnc\nscan 1\n"), (true, true));
        assert_eq!(directives("#test: no-machine cnc\n"), (true, false));
        // Only comment lines speak to the runner.
        assert_eq!(directives("print test: cnc\n"), (false, true));
    }

    #[test]
    fn the_test_folder_is_named_after_the_project() {
        assert_eq!(
            test_folder(Path::new("/p/lathe.ldp")),
            PathBuf::from("/p/lathe.tests")
        );
    }
}
