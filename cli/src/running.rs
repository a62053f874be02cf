//! The commands that run the program: `sim` under a stimulus script and `bench`. Both can
//! run for a long time, so both show progress on standard error once a run takes more than a
//! moment, and both stop cleanly on Ctrl+C with what they have (docs/scripts.md, "Long runs").

use super::say::{Say, shown};
use super::source::machine;
use ladder_engine::coverage::Coverage;
use ladder_engine::machine::Machine;
use ladder_engine::sim::{self, Control, Progress, Script};
use ladder_engine::vm::Engine;
use ladder_engine::vm::cnc::Cnc;
use ladder_text::cli::{FileText, RunText};
use std::io::Write;
use std::path::Path;
use std::sync::atomic::{AtomicBool, Ordering};
use std::time::{Duration, Instant};

/// The exit code of a run stopped by Ctrl+C (128 + SIGINT, as a shell reports it).
pub(super) const STOPPED: i32 = 130;

/// How long a run goes quietly before its first progress line, and between two lines.
const PROGRESS_AFTER: Duration = Duration::from_secs(2);

/// Set by Ctrl+C.
static STOP: AtomicBool = AtomicBool::new(false);

/// Listens for Ctrl+C from now on and returns the flag it sets. A second Ctrl+C ends the
/// process at once, for a run stuck where the flag is not read.
pub(super) fn stop_on_ctrl_c() -> &'static AtomicBool {
    static INSTALL: std::sync::Once = std::sync::Once::new();
    INSTALL.call_once(|| {
        // Without a handler (none can be installed) Ctrl+C ends the process as usual.
        let _ = ctrlc::set_handler(|| {
            if STOP.swap(true, Ordering::SeqCst) {
                std::process::exit(STOPPED);
            }
        });
    });
    STOP.store(false, Ordering::SeqCst);
    &STOP
}

/// Writes a progress line at most every [`PROGRESS_AFTER`], the first one only once the run
/// has taken that long, so short runs stay quiet.
struct Ticker {
    next: Instant,
}

impl Ticker {
    fn new() -> Ticker {
        Ticker {
            next: Instant::now() + PROGRESS_AFTER,
        }
    }

    /// Whether a line is due now.
    fn due(&mut self) -> bool {
        let now = Instant::now();
        if now < self.next {
            return false;
        }
        self.next = now + PROGRESS_AFTER;
        true
    }
}

fn percent(done: u64, of: u64) -> u64 {
    (done as u128 * 100 / u128::from(of.max(1))) as u64
}

/// Reads and parses a stimulus script (`cnc program-file` paths relative to its folder), or
/// reports its first bad line (exit 2).
pub(super) fn read_script(
    (project_path, script_path): (&Path, &Path),
    machine: &Machine,
    cnc: bool,
    say: Say,
    err: &mut dyn Write,
) -> anyhow::Result<Result<Script, i32>> {
    let text = ladder_engine::file::read_input_text(script_path)
        .map_err(|e| anyhow::anyhow!(say.cannot_read(script_path, e)))?;
    let folder = script_path
        .parent()
        .map(Path::to_path_buf)
        .unwrap_or_default();
    let read_file = |p: &str| -> Result<String, String> {
        let full = folder.join(p);
        ladder_engine::cnc::program::read_program_file(&full)
            .map_err(|e| ladder_text::script::program_file_error(&e, &full, say.lang()))
    };
    // The project again, for its saved scenarios and operator panel (`scenario` lines).
    let project = match super::source::Source::read(project_path, say)? {
        super::source::Source::Project(p) => Some(p),
        super::source::Source::Il { .. } => None,
    };
    let options = sim::Options {
        cnc,
        read_file: &read_file,
        machine: machine.plant().map(|p| p.model()),
        project: project.as_ref(),
    };
    match Script::parse_with(&text, machine.plc().profile(), &options) {
        Ok(s) => Ok(Ok(s)),
        Err(e) => {
            let message = ladder_text::script::script_error(&e, say.lang());
            let _ = writeln!(err, "{}:{}: {message}", script_path.display(), e.line);
            Ok(Err(2))
        }
    }
}

/// `sim PATH --script S [--trace OUT.csv] [--cnc] [--no-machine]`: runs the script,
/// streaming the trace. `(cnc, devices)`: with the simulated CNC, with the machine model.
pub(super) fn sim(
    path: &Path,
    (script_path, trace, coverage): (&Path, Option<&Path>, super::coverage::Outputs<'_>),
    (cnc, devices, engine): (bool, bool, Option<Engine>),
    say: Say,
    out: &mut dyn Write,
    err: &mut dyn Write,
) -> anyhow::Result<i32> {
    if !script_path.exists() {
        anyhow::bail!(say.text(FileText::NoSuchFile {
            path: shown(script_path)
        }));
    }
    let mut machine = match machine(path, (cnc, engine), say, err)? {
        Ok(m) if devices => m,
        Ok(m) => m.without_devices(),
        Err(code) => return Ok(code),
    };
    let script = match read_script((path, script_path), &machine, cnc, say, err)? {
        Ok(s) => s,
        Err(code) => return Ok(code),
    };
    let name = script_path.display().to_string();
    // The trace goes to its file tick by tick: a long run with many watches would not fit
    // in memory.
    let mut trace_file = match trace {
        Some(t) => Some(std::io::BufWriter::new(
            std::fs::File::create(t).map_err(|e| anyhow::anyhow!(say.cannot_write(t, e)))?,
        )),
        None => None,
    };
    let mut ticker = Ticker::new();
    let mut progress = |p: Progress| {
        if ticker.due() {
            let _ = writeln!(
                err,
                "{}",
                say.text(RunText::SimProgress {
                    script: name.clone(),
                    line: p.line,
                    done: p.done,
                    of: p.of,
                    percent: percent(p.done, p.of),
                })
            );
        }
    };
    let control = Control {
        trace: trace_file.as_mut().map(|w| w as &mut dyn Write),
        stop: Some(stop_on_ctrl_c()),
        progress: Some(&mut progress),
    };
    if coverage.wanted() {
        coverage.check(say)?;
        machine.plc_mut().set_coverage(true);
    }
    let outcome = sim::run_with(&mut machine, &script, &name, control);
    let outcome = match (outcome, trace) {
        (Ok(o), _) => o,
        (Err(e), Some(t)) => anyhow::bail!(say.cannot_write(t, e)),
        (Err(e), None) => return Err(e.into()),
    };
    for r in &outcome.output {
        let line = ladder_text::sim::report(&outcome.script, r, say.lang());
        let _ = writeln!(out, "{line}");
    }
    if let Some(s) = outcome.stopped {
        let _ = writeln!(
            err,
            "{}",
            say.text(RunText::SimStopped {
                script: name.clone(),
                line: s.line,
                done: s.done,
                of: s.of,
                ticks: s.ticks,
            })
        );
    }
    if coverage.wanted() {
        let program = super::source::program_of(path, say)?;
        if let Some(measured) = Coverage::measure(machine.plc(), &program) {
            coverage.report(&measured, path, say, out)?;
        }
    }
    let (passed, failed) = (outcome.passed, outcome.failed);
    let _ = writeln!(out, "{}", say.passed(passed, failed));
    if outcome.stopped.is_some() {
        return Ok(STOPPED);
    }
    Ok(i32::from(outcome.failed > 0))
}

/// `bench PATH [--scans N] [--cnc] [--script S] [--no-machine]`: times the scan; Ctrl+C ends the timing
/// early and the figures cover the scans timed.
pub(super) fn bench(
    path: &Path,
    (scans, engine, instructions): (u64, Option<Engine>, bool),
    (cnc, devices, coverage, ticks_only): (bool, bool, bool, bool),
    setup: Option<&Path>,
    say: Say,
    out: &mut dyn Write,
    err: &mut dyn Write,
) -> anyhow::Result<i32> {
    let mut machine = match machine(path, (cnc, engine), say, err)? {
        Ok(m) if devices => m,
        Ok(m) => m.without_devices(),
        Err(code) => return Ok(code),
    };
    if let Some(script_path) = setup
        && let Some(code) = set_up(&mut machine, (path, script_path), cnc, say, err)?
    {
        return Ok(code);
    }
    // Timed with coverage measured, for its cost against the plain scan.
    machine.plc_mut().set_coverage(coverage);
    let stop = stop_on_ctrl_c();
    let scans = scans.max(1);
    // Warm up caches and branch predictors before timing.
    for _ in 0..scans.min(1000) {
        machine.tick();
    }
    let mut ticker = Ticker::new();
    let before = machine.plc().executed_steps();
    let start = Instant::now();
    let mut timed = 0u64;
    // The clock and the flag are read once a block, so the figure stays the scan's.
    const BLOCK: u64 = 1024;
    while timed < scans && !stop.load(Ordering::Relaxed) {
        let n = BLOCK.min(scans - timed);
        for _ in 0..n {
            machine.tick();
        }
        timed += n;
        if ticker.due() {
            let _ = writeln!(
                err,
                "{}",
                say.text(RunText::BenchProgress {
                    timed,
                    scans,
                    percent: percent(timed, scans),
                })
            );
        }
    }
    let elapsed = start.elapsed().as_nanos() as f64;
    if let Some(h) = machine.plc().halt() {
        let why = ladder_text::halt::halt(h, say.lang());
        let _ = writeln!(err, "{}", say.text(RunText::BenchHalted { why }));
        return Ok(1);
    }
    let stopped = timed < scans;
    if stopped {
        let _ = writeln!(err, "{}", say.text(RunText::BenchStopped { timed, scans }));
    }
    let scans = timed.max(1);
    let steps = (machine.plc().executed_steps() - before) as f64 / scans as f64;
    let ns_per_scan = elapsed / scans as f64;
    if !stopped
        && !ticks_only
        && let (plc, Some(cnc)) = machine.parts_mut()
    {
        // The exchange alone, timed inside the same kind of run (the clock read adds a few
        // tens of ns to each figure).
        let mut timed = TimedCnc { cnc, nanos: 0 };
        for _ in 0..scans {
            plc.tick(&mut timed);
        }
        let per = timed.nanos as f64 / scans as f64;
        let hour = ns_per_scan * 450_000.0 / 1e9;
        let _ = writeln!(
            out,
            "cnc_ns_per_exchange={per:.1} machine_ns_per_tick={ns_per_scan:.1} one_hour_s={hour:.3}"
        );
    }
    if !stopped
        && !ticks_only
        && let Some(count) = machine.plant().map(|p| p.names().count())
    {
        // The machine model alone, stepped as often as the ticks timed.
        let start = Instant::now();
        for _ in 0..scans {
            machine.step_devices();
        }
        let per = start.elapsed().as_nanos() as f64 / scans as f64;
        let _ = writeln!(
            out,
            "devices={count} devices_ns_per_tick={per:.1} devices_share_pct={:.2}",
            100.0 * per / ns_per_scan.max(1.0)
        );
    }
    let engine = machine.plc().engine();
    if instructions && !stopped {
        let same = (path, engine, (cnc, devices, coverage), setup);
        match super::callgrind::per_scan(&super::callgrind::bench_args(same), scans) {
            Ok(per) => {
                let _ = writeln!(
                    out,
                    "instructions_per_scan={per:.0} instructions_per_step={:.2}",
                    per / steps.max(1.0)
                );
            }
            Err(e) => {
                let _ = writeln!(err, "{}", say.text(e.said()));
                return Ok(1);
            }
        }
    }
    let _ = writeln!(
        out,
        "steps={} scans={scans} ns_per_scan={:.1} ns_per_step={:.3} engine={}",
        steps.round() as u64,
        ns_per_scan,
        ns_per_scan / steps.max(1.0),
        engine.name()
    );
    Ok(if stopped { STOPPED } else { 0 })
}

/// Runs `bench`'s set-up script, untimed; the exit code when it cannot run or fails.
fn set_up(
    machine: &mut Machine,
    (path, script_path): (&Path, &Path),
    cnc: bool,
    say: Say,
    err: &mut dyn Write,
) -> anyhow::Result<Option<i32>> {
    let script = match read_script((path, script_path), machine, cnc, say, err)? {
        Ok(s) => s,
        Err(code) => return Ok(Some(code)),
    };
    let name = script_path.display().to_string();
    let outcome = sim::run(machine, &script, &name, false);
    if outcome.failed == 0 {
        return Ok(None);
    }
    for r in &outcome.output {
        let line = ladder_text::sim::report(&outcome.script, r, say.lang());
        let _ = writeln!(err, "{line}");
    }
    let _ = writeln!(err, "{}", say.text(RunText::SetUpFailed));
    Ok(Some(1))
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
