//! Running a parsed script against a machine (docs/scripts.md, "Running"): the lines in
//! order, the `expect`s counted, the trace written row by row as the ticks run, and a way to
//! stop a long run between two ticks with what it has.

use super::{Script, ScriptCommand};
use crate::cnc::CncError;
use crate::machine::{Machine, MachineCommand, Probe, ProbeValue};
use crate::refusal::Refusal;
use crate::vm::Halt;
use std::io::Write;
use std::sync::atomic::{AtomicBool, Ordering};

/// What running a script produced.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Outcome {
    /// The script's name, which prefixes its failure lines when they are worded.
    pub script: String,
    /// What to report (expect failures, `print`s, halts, refused commands), in order; the
    /// command line words each in the user's language (`ladder_text::sim`).
    pub output: Vec<Report>,
    /// `expect`/`expectf` that held.
    pub passed: usize,
    /// `expect`/`expectf` that did not, and commands that could not apply.
    pub failed: usize,
    /// The trace as CSV (header and one row per tick), when [`run`] was asked for it and
    /// anything was watched; [`run_with`] streams it instead and leaves this empty.
    pub trace_csv: String,
    /// Where the run was stopped before the end of the script, if it was.
    pub stopped: Option<Stopped>,
}

/// One thing a run reports: the script line, and what happened there.
#[derive(Clone, Debug, PartialEq)]
pub struct Report {
    /// 1-based script line.
    pub line: usize,
    /// What happened.
    pub event: Event,
}

/// What a run reports at a line. Data only: the words are the caller's, in either language,
/// so the lines keep one shape (`SCRIPT:LINE: expect X0000.0 = 1, got 0`) in both.
#[derive(Clone, Debug, PartialEq)]
pub enum Event {
    /// A `print` line: the probe as named and its value.
    Value {
        /// The probe (`R0010`, `cnc.mode`, `device.door`).
        probe: String,
        /// Its value as read.
        value: String,
    },
    /// The PLC halted (reported once until a power cycle).
    Halted(Halt),
    /// A command the machine refused, and which part of it refused.
    Refused(Part, Refusal),
    /// An `expect` that did not hold: the probe, the value as written, the value read.
    Expected {
        /// The probe as named.
        probe: String,
        /// The value the line expects, as written.
        want: String,
        /// The value read.
        got: String,
    },
    /// A probe that could not be read, and the part that could not give it.
    Unreadable(Part, CncError),
}

/// The part of the machine a failure comes from, named at the start of its line.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Part {
    /// The simulated CNC (`cnc:`).
    Cnc,
    /// A device of the machine model (`device:`).
    Device,
    /// A saved scenario (`scenario:`).
    Scenario,
}

impl Part {
    /// The word that names the part in a failure line, the same in both languages (scripts
    /// read it).
    pub fn word(self) -> &'static str {
        match self {
            Part::Cnc => "cnc",
            Part::Device => "device",
            Part::Scenario => "scenario",
        }
    }
}

/// Where a run was stopped early.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Stopped {
    /// The `scan` or `run` line that was running.
    pub line: usize,
    /// Ticks of that line that ran.
    pub done: u64,
    /// Ticks the line asked for.
    pub of: u64,
    /// Ticks run since the start of the script.
    pub ticks: u64,
}

/// How far a long `scan` or `run` line has got, for a progress line.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Progress {
    /// The script line.
    pub line: usize,
    /// Ticks of the line run so far.
    pub done: u64,
    /// Ticks the line asks for.
    pub of: u64,
}

/// Ticks between two progress calls: often enough for a line a second, rare enough to cost
/// nothing beside a tick.
const PROGRESS_EVERY: u64 = 1 << 14;

/// What a run writes to and listens to besides the machine.
#[derive(Default)]
pub struct Control<'a> {
    /// Where the trace CSV goes, row by row; `None` keeps no trace.
    pub trace: Option<&'a mut dyn Write>,
    /// Read after every tick: once set, the run stops there (Ctrl+C).
    pub stop: Option<&'a AtomicBool>,
    /// Called every few thousand ticks of a `scan` or `run` line.
    pub progress: Option<&'a mut dyn FnMut(Progress)>,
}

fn masked(v: i64, bytes: u32) -> u64 {
    if bytes >= 8 {
        v as u64
    } else {
        (v as u64) & ((1u64 << (8 * bytes)) - 1)
    }
}

/// Writes the trace row of the tick just run, and the header before the first row.
fn trace_row(m: &Machine, header: &mut bool, out: &mut dyn Write) -> std::io::Result<()> {
    let watched = m.watches();
    if watched.is_empty() {
        return Ok(());
    }
    if !*header {
        out.write_all(b"tick,ms")?;
        for p in watched {
            write!(out, ",{}", m.probe_name(p))?;
        }
        out.write_all(b"\n")?;
        *header = true;
    }
    write!(out, "{},{}", m.plc().ticks(), m.plc().now_ms())?;
    for p in watched {
        match m.read(p) {
            Ok(v) => write!(out, ",{v}")?,
            Err(_) => out.write_all(b",")?,
        }
    }
    out.write_all(b"\n")
}

/// Runs a parsed script, keeping the trace in [`Outcome::trace_csv`] when `trace` is set.
/// `name` prefixes failure lines (`SCRIPT:LINE: expect …`).
pub fn run(machine: &mut Machine, script: &Script, name: &str, trace: bool) -> Outcome {
    let mut csv = Vec::new();
    let control = Control {
        trace: if trace { Some(&mut csv) } else { None },
        ..Control::default()
    };
    let mut out = run_with(machine, script, name, control).expect("a Vec takes every write");
    out.trace_csv = String::from_utf8(csv).expect("the trace is text");
    out
}

/// Runs a parsed script, streaming the trace and listening for a stop. The only error is a
/// failed trace write; the run stops at the tick it failed on.
pub fn run_with(
    machine: &mut Machine,
    script: &Script,
    name: &str,
    mut control: Control<'_>,
) -> std::io::Result<Outcome> {
    let mut run = Run {
        out: Outcome {
            script: name.to_string(),
            ..Outcome::default()
        },
        reported_halt: false,
        header: false,
        ticks: 0,
    };
    for (line, command) in &script.commands {
        if control.stop_asked() {
            run.out.stopped = Some(Stopped {
                line: *line,
                done: 0,
                of: 0,
                ticks: run.ticks,
            });
            break;
        }
        match command {
            ScriptCommand::Do(MachineCommand::Tick(n)) => {
                run.tick(machine, *line, *n, &mut control)?;
                if run.out.stopped.is_some() {
                    break;
                }
            }
            ScriptCommand::Do(c) => run.apply(machine, *line, c),
            ScriptCommand::Print(p) => run.print(machine, *line, p),
            ScriptCommand::Expect(t, want) => run.expect(machine, *line, t, *want),
            ScriptCommand::ExpectCnc(key, want, written) => {
                run.expect_cnc(machine, *line, *key, want, written)
            }
            ScriptCommand::ExpectDevice(i, want) => run.expect_device(machine, *line, *i, *want),
            ScriptCommand::ExpectReal(a, want, tol) => {
                run.expect_real(machine, *line, *a, *want, *tol)
            }
        }
    }
    if let Some(t) = control.trace {
        t.flush()?;
    }
    Ok(run.out)
}

impl Control<'_> {
    /// Whether a stop was asked for; read between two ticks and before each line.
    fn stop_asked(&self) -> bool {
        self.stop.is_some_and(|s| s.load(Ordering::Relaxed))
    }
}

/// A run's state between two lines: what it has produced, and what the lines share (a halt
/// is reported once until a power cycle, the trace's header written once, the ticks
/// counted over the whole script for [`Stopped`]).
struct Run {
    out: Outcome,
    reported_halt: bool,
    header: bool,
    ticks: u64,
}

impl Run {
    /// A `scan` or `run` line of `n` ticks: each tick traced, a halt reported, progress
    /// called every [`PROGRESS_EVERY`] ticks; a stop leaves [`Outcome::stopped`] set.
    fn tick(
        &mut self,
        machine: &mut Machine,
        line: usize,
        n: u64,
        control: &mut Control<'_>,
    ) -> std::io::Result<()> {
        for done in 0..n {
            if control.stop_asked() {
                self.out.stopped = Some(Stopped {
                    line,
                    done,
                    of: n,
                    ticks: self.ticks,
                });
                break;
            }
            machine.tick();
            self.ticks += 1;
            if let Some(t) = control.trace.as_deref_mut() {
                trace_row(machine, &mut self.header, t)?;
            }
            if let Some(h) = machine.plc().halt()
                && !self.reported_halt
            {
                self.out.output.push(Report {
                    line,
                    event: Event::Halted(h.clone()),
                });
                self.reported_halt = true;
            }
            if (done + 1) % PROGRESS_EVERY == 0
                && let Some(p) = control.progress.as_deref_mut()
            {
                p(Progress {
                    line,
                    done: done + 1,
                    of: n,
                });
            }
        }
        Ok(())
    }

    /// Any other command for the machine; one that cannot apply is a failure, named by the
    /// part that refused it. A power cycle clears a halt, so the next one is reported again.
    fn apply(&mut self, machine: &mut Machine, line: usize, c: &MachineCommand) {
        if matches!(c, MachineCommand::PowerCycle) {
            self.reported_halt = false;
        }
        if let Err(e) = machine.apply(c) {
            let part = match c {
                MachineCommand::Device(..) => Part::Device,
                MachineCommand::Scenario(..) | MachineCommand::Release(..) => Part::Scenario,
                _ => Part::Cnc,
            };
            self.fail(line, Event::Refused(part, e));
        }
    }

    /// A `print` line: the probe's value, or a failure when it cannot be read.
    fn print(&mut self, machine: &Machine, line: usize, p: &Probe) {
        match machine.read(p) {
            Ok(v) => self.out.output.push(Report {
                line,
                event: Event::Value {
                    probe: machine.probe_name(p),
                    value: v.to_string(),
                },
            }),
            Err(e) => self.fail(line, Event::Unreadable(Part::Cnc, e)),
        }
    }

    /// Records a failure: its line printed, and counted.
    fn fail(&mut self, line: usize, event: Event) {
        self.out.output.push(Report { line, event });
        self.out.failed += 1;
    }

    /// An `expect` that did not hold, with the values as they are shown.
    fn expected(
        &mut self,
        line: usize,
        probe: impl ToString,
        want: impl ToString,
        got: impl ToString,
    ) {
        let event = Event::Expected {
            probe: probe.to_string(),
            want: want.to_string(),
            got: got.to_string(),
        };
        self.fail(line, event);
    }

    /// `expect ADDR[:N] VALUE`: the bytes compared, so a byte's 255 and -1 match.
    fn expect(&mut self, machine: &Machine, line: usize, t: &super::Target, want: i64) {
        let got = machine.plc().read(t.address, t.bytes);
        if masked(got, t.bytes) == masked(want, t.bytes) {
            self.out.passed += 1;
        } else {
            // Show the value the way the expectation was written.
            let shown = if want >= 0 {
                masked(got, t.bytes).to_string()
            } else {
                got.to_string()
            };
            self.expected(line, t.text(), want, shown);
        }
    }

    /// `expect cnc.KEY VALUE`: a failure shows the value as written.
    fn expect_cnc(
        &mut self,
        machine: &Machine,
        line: usize,
        key: crate::cnc::command::CncKey,
        want: &crate::cnc::command::CncValue,
        written: &str,
    ) {
        match machine.read(&Probe::Cnc(key)) {
            Ok(ProbeValue::Cnc(got)) if got == *want => self.out.passed += 1,
            Ok(got) => self.expected(line, key.text(), written, got),
            Err(e) => self.fail(line, Event::Unreadable(Part::Cnc, e)),
        }
    }

    /// `expect device.NAME VALUE`, by the device's index.
    fn expect_device(&mut self, machine: &Machine, line: usize, i: usize, want: i64) {
        let p = Probe::Device(i);
        match machine.read(&p) {
            Ok(ProbeValue::Int(got)) if got == want => self.out.passed += 1,
            Ok(got) => self.expected(line, machine.probe_name(&p), want, got),
            Err(e) => self.fail(line, Event::Unreadable(Part::Device, e)),
        }
    }

    /// `expectf ADDR VALUE [TOL]`: a relative tolerance (absolute around 0), 1e-4 unless
    /// given; NaN never holds.
    fn expect_real(
        &mut self,
        machine: &Machine,
        line: usize,
        a: crate::address::Address,
        want: f32,
        tol: Option<f32>,
    ) {
        let got = machine.plc().read_real(a);
        let tol = tol.unwrap_or(1e-4);
        let ok = if want == 0.0 {
            got.abs() <= tol
        } else {
            ((got - want) / want).abs() <= tol
        };
        if ok && !got.is_nan() {
            self.out.passed += 1;
        } else {
            self.expected(line, a, want, got);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::Project;
    use crate::profile::Profile;

    /// A machine running a one-rung list (R0000.0 follows X0000.0) and a script on it.
    fn machine_and(script: &str) -> (Machine, Script) {
        let imported = crate::il::import("LEVEL1\nNETWORK\nLD X0000.0\nOUT R0000.0\nLEVEL2\n");
        let project: Project = imported.project.expect("the list draws");
        let m = Machine::new(&project, false).expect("the list runs");
        let s = Script::parse(script, Profile::get(project.profile)).expect("the script parses");
        (m, s)
    }

    #[test]
    fn the_streamed_trace_is_the_kept_one() {
        let text = "watch R0000.0\nwatch X0000.0\nscan 2\nset X0000.0 1\nscan 3\n";
        let (mut m, s) = machine_and(text);
        let kept = run(&mut m, &s, "s", true).trace_csv;
        let (mut m, s) = machine_and(text);
        let mut streamed = Vec::new();
        let control = Control {
            trace: Some(&mut streamed),
            ..Control::default()
        };
        let out = run_with(&mut m, &s, "s", control).unwrap();
        assert!(out.trace_csv.is_empty(), "nothing kept while streaming");
        assert_eq!(String::from_utf8(streamed).unwrap(), kept);
        assert_eq!(kept.lines().count(), 6, "{kept}");
        assert_eq!(kept.lines().last(), Some("5,40,1,1"));
    }

    #[test]
    fn without_a_trace_nothing_is_kept() {
        let (mut m, s) = machine_and("watch R0000.0\nscan 50\n");
        assert_eq!(run(&mut m, &s, "s", false).trace_csv, "");
    }

    #[test]
    fn a_stop_ends_the_run_between_ticks_with_the_results_so_far() {
        let (mut m, s) = machine_and(
            "set X0000.0 1\nscan 1\nexpect R0000.0 1\nscan 100000000\nexpect R0000.0 0\n",
        );
        let flag = AtomicBool::new(false);
        let mut calls = Vec::new();
        let mut progress = |p: Progress| {
            calls.push(p);
            if p.done >= 2 * PROGRESS_EVERY {
                flag.store(true, Ordering::Relaxed);
            }
        };
        let control = Control {
            trace: None,
            stop: Some(&flag),
            progress: Some(&mut progress),
        };
        let out = run_with(&mut m, &s, "s", control).unwrap();
        assert_eq!(
            (out.passed, out.failed),
            (1, 0),
            "the last expect did not run"
        );
        assert_eq!(
            out.stopped,
            Some(Stopped {
                line: 4,
                done: 2 * PROGRESS_EVERY,
                of: 100_000_000,
                ticks: 2 * PROGRESS_EVERY + 1,
            })
        );
        assert_eq!(m.plc().ticks(), 2 * PROGRESS_EVERY + 1);
        assert_eq!(calls.len(), 2);
        assert_eq!(calls[0].line, 4);
    }

    #[test]
    fn a_stop_before_a_line_runs_nothing_more() {
        let (mut m, s) = machine_and("scan 3\nexpect R0000.0 0\n");
        let flag = AtomicBool::new(true);
        let control = Control {
            stop: Some(&flag),
            ..Control::default()
        };
        let out = run_with(&mut m, &s, "s", control).unwrap();
        assert_eq!(out.stopped.map(|s| (s.line, s.ticks)), Some((1, 0)));
        assert_eq!((out.passed, m.plc().ticks()), (0, 0));
    }

    #[test]
    fn both_spellings_of_a_byte_match() {
        assert_eq!(masked(255, 1), masked(-1, 1));
        assert_ne!(masked(255, 2), masked(-1, 2));
    }
}
