//! `bench --instructions`: the scan's cost in machine instructions, counted by valgrind's
//! callgrind, which gives the same count for the same binary and input however busy the
//! machine is (the clock on a shared machine moves two or three times between runs).
//!
//! The same `bench` runs twice under callgrind, for N and for 2N scans; the difference of
//! the two totals divided by N is the cost of one scan, free of start-up, loading, warm-up
//! and the set-up script, which both runs share.

use ladder_text::cli::RunText;
use std::ffi::OsString;
use std::path::Path;
use std::process::Command;

/// Why instructions could not be counted.
#[derive(Debug)]
pub(super) enum CountError {
    /// valgrind is not installed (or cannot start).
    NoValgrind(String),
    /// A run under valgrind failed.
    Run(String),
    /// A run under valgrind printed no total.
    NoTotal,
}

impl CountError {
    /// What the command line says about it.
    pub(super) fn said(self) -> RunText {
        match self {
            CountError::NoValgrind(why) => RunText::NoValgrind { why },
            CountError::Run(why) => RunText::CountFailed { why },
            CountError::NoTotal => RunText::NoTotal,
        }
    }
}

/// The arguments of a `bench` that runs as this one does (`--ticks-only`, so that only the
/// ticks are counted): its path, engine, `--cnc`, `--no-machine`, `--coverage` and set-up
/// script.
pub(super) fn bench_args(
    (path, engine, (cnc, devices, coverage), setup): (
        &Path,
        ladder_engine::vm::Engine,
        (bool, bool, bool),
        Option<&Path>,
    ),
) -> Vec<OsString> {
    let mut args: Vec<OsString> = vec![path.into(), "--ticks-only".into(), "--engine".into()];
    args.push(engine.name().into());
    for (on, flag) in [
        (cnc, "--cnc"),
        (!devices, "--no-machine"),
        (coverage, "--coverage"),
    ] {
        if on {
            args.push(flag.into());
        }
    }
    if let Some(s) = setup {
        args.extend(["--script".into(), s.into()]);
    }
    args
}

/// Instructions per scan of `bench ARGS` (without `--scans`), from runs of `scans` and
/// `2 × scans` scans of this very program under callgrind.
pub(super) fn per_scan(args: &[OsString], scans: u64) -> Result<f64, CountError> {
    let exe = std::env::current_exe().map_err(|e| CountError::Run(e.to_string()))?;
    let one = total(&exe, args, scans)?;
    let two = total(&exe, args, scans * 2)?;
    Ok(two.saturating_sub(one) as f64 / scans as f64)
}

/// Callgrind's total for one run.
fn total(exe: &Path, args: &[OsString], scans: u64) -> Result<u64, CountError> {
    let output = Command::new("valgrind")
        .arg("--tool=callgrind")
        .arg("--callgrind-out-file=/dev/null")
        .arg(exe)
        .arg("bench")
        .args(args)
        .arg("--scans")
        .arg(scans.to_string())
        .output()
        .map_err(|e| CountError::NoValgrind(e.to_string()))?;
    let stderr = String::from_utf8_lossy(&output.stderr);
    if !output.status.success() {
        let last = stderr
            .lines()
            .rev()
            .find(|l| !l.starts_with("=="))
            .unwrap_or("");
        return Err(CountError::Run(format!("{} {last}", output.status)));
    }
    collected(&stderr).ok_or(CountError::NoTotal)
}

/// The number on callgrind's `==PID== Collected : N` line.
fn collected(stderr: &str) -> Option<u64> {
    stderr.lines().find_map(|line| {
        let (_, rest) = line.split_once("Collected :")?;
        rest.trim().replace(',', "").parse().ok()
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_total_is_read_from_callgrinds_summary() {
        let stderr = "==41== Callgrind, a call-graph generating cache profiler\n\
                      ==41== \n==41== Events    : Ir\n==41== Collected : 126651\n==41== \n\
                      ==41== I   refs:      126,651\n";
        assert_eq!(collected(stderr), Some(126_651));
        assert_eq!(collected("==41== I   refs: 5\n"), None);
    }
}
