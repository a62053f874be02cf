//! Scan-recorder benchmarks: `cargo bench -p ladder-engine --bench recorder`.
//!
//! Prints the recorder's figures: the mean tick of `projects/stress-5000.ldp` under the
//! simulated CNC (as loaded, and with an input byte changing every tick) without and with
//! [`Recorder::record`] after every tick, and its cost in percent of the tick (target ≤ 10 %),
//! the same for the sample lathe; the recorder's memory per recorded second of virtual
//! time for that project and for the sample lathe (a healthy machine idle, and looping the part
//! program of projects/lathe-988ta.tests/cycle.script); and the time to rebuild an image and to query one
//! byte's changes over the window.

use ladder_engine::machine::{Machine, MachineCommand, Target};
use ladder_engine::recorder::{DEFAULT_CAPACITY_TICKS, Recorder};
use ladder_engine::sim::{self, Options, Script};
use ladder_engine::{Address, Area};
use std::hint::black_box;
use std::path::{Path, PathBuf};
use std::time::Instant;

fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("..")
}

fn machine(project: &str) -> Machine {
    let project = ladder_engine::file::load(&root().join(project)).expect("the project loads");
    Machine::new(&project, true)
        .expect("the project compiles")
        .without_devices()
}

/// Runs a stimulus script's text on the machine; every expectation must hold.
fn run_script(machine: &mut Machine, text: &str) {
    let script = Script::parse_with(
        text,
        machine.plc().profile(),
        &Options {
            cnc: true,
            read_file: &|p| Err(p.to_string()),
            machine: None,
            project: None,
        },
    )
    .expect("the script parses");
    let outcome = sim::run(machine, &script, "setup", false);
    assert_eq!(outcome.failed, 0, "{:?}", outcome.output);
}

fn recorder_for(machine: &Machine) -> Recorder {
    Recorder::new(machine.plc().layout().size as usize, DEFAULT_CAPACITY_TICKS)
}

/// What changes the machine's inputs before a tick, besides the CNC.
type Stimulus = Option<fn(&mut Machine)>;

/// One tick, after the stimulus.
fn step(machine: &mut Machine, stimulus: Stimulus) {
    if let Some(f) = stimulus {
        f(machine);
    }
    machine.tick();
}

/// An operator's inputs: one X byte of X0000–X0127 takes a new value each tick, so the
/// stress program's outputs change too.
fn inputs(machine: &mut Machine) {
    let t = machine.plc().ticks();
    let target = Target {
        address: Address {
            area: Area::X,
            number: (t % 128) as u16,
            bit: None,
        },
        bytes: 1,
        explicit: false,
    };
    let value = (t.wrapping_mul(0x9E37_79B9_7F4A_7C15) >> 56) as i64;
    machine
        .apply(&MachineCommand::Write(target, value))
        .expect("X is writable");
}

fn record(machine: &Machine, rec: &mut Recorder) {
    rec.record(machine.plc().ticks(), machine.plc().image());
}

/// What [`scan_cost`] measured, in ns per tick.
struct Cost {
    /// Mean tick without recording.
    off: f64,
    /// Mean tick with `record` after it.
    on: f64,
    /// The median over the batches of (with / without − 1), in percent: a figure a burst of
    /// load on a shared machine moves less than the ratio of the means.
    median_pct: f64,
    /// Mean of the `record` call alone.
    alone: f64,
}

/// Ticks in `batches` alternating batches of `ticks` ticks without and with recording
/// (alternating so a busy shared machine slows both alike), then the `record` call timed
/// alone.
fn scan_cost(machine: &mut Machine, batches: usize, ticks: u64, stimulus: Stimulus) -> Cost {
    let mut rec = recorder_for(machine);
    let (mut off, mut on, mut ratios) = (0.0, 0.0, Vec::new());
    for _ in 0..batches {
        let t = Instant::now();
        for _ in 0..ticks {
            step(machine, stimulus);
        }
        let batch_off = t.elapsed().as_nanos() as f64;
        // The gap restarts the recording: a fresh base, as after a pause.
        let t = Instant::now();
        for _ in 0..ticks {
            step(machine, stimulus);
            record(machine, &mut rec);
        }
        let batch_on = t.elapsed().as_nanos() as f64;
        off += batch_off;
        on += batch_on;
        ratios.push((batch_on / batch_off - 1.0) * 100.0);
    }
    ratios.sort_by(f64::total_cmp);
    // The call alone: each timed in place, less what a pair of clock reads costs.
    let clock = {
        let t = Instant::now();
        for _ in 0..100_000 {
            black_box(Instant::now().elapsed());
        }
        t.elapsed().as_nanos() as f64 / 100_000.0
    };
    let mut alone = 0.0;
    for _ in 0..batches {
        for _ in 0..ticks {
            step(machine, stimulus);
            let t = Instant::now();
            record(machine, &mut rec);
            alone += t.elapsed().as_nanos() as f64 - clock;
        }
    }
    let n = (batches as u64 * ticks) as f64;
    Cost {
        off: off / n,
        on: on / n,
        median_pct: ratios[ratios.len() / 2],
        alone: alone / n,
    }
}

fn print_cost(name: &str, machine: &mut Machine, batches: usize, stimulus: Stimulus) {
    let c = scan_cost(machine, batches, 2000, stimulus);
    println!(
        "{name}, with the CNC: mean tick without recording={:.0} ns, with recording={:.0} ns ({:+.1}%, median of batches {:+.1}%); record alone={:.0} ns = {:.1}% of the tick",
        c.off,
        c.on,
        (c.on / c.off - 1.0) * 100.0,
        c.median_pct,
        c.alone,
        c.alone / c.off * 100.0
    );
}

/// Records 60 s, then another 60 s, returning bytes per recorded second at both points and
/// the recorder.
fn memory(machine: &mut Machine, stimulus: Stimulus) -> (f64, f64, Recorder) {
    let mut rec = recorder_for(machine);
    let seconds = (DEFAULT_CAPACITY_TICKS * ladder_engine::vm::TICK_MS) as f64 / 1000.0;
    for _ in 0..DEFAULT_CAPACITY_TICKS {
        step(machine, stimulus);
        record(machine, &mut rec);
    }
    let first = rec.bytes_used() as f64 / seconds;
    for _ in 0..DEFAULT_CAPACITY_TICKS {
        step(machine, stimulus);
        record(machine, &mut rec);
    }
    (first, rec.bytes_used() as f64 / seconds, rec)
}

/// Mean, 99th percentile and worst µs of `image_at` over ticks spread across the window,
/// mean µs of a `changes_of` of the byte that changed most, and of a `last_change` across the
/// image and the slowest on one bit of that byte.
#[allow(clippy::type_complexity)]
fn queries(rec: &Recorder) -> (f64, f64, f64, f64, f64, f64, usize) {
    let (oldest, newest) = (rec.oldest().unwrap(), rec.newest().unwrap());
    let mut out = Vec::new();
    let samples = 2000u64;
    let mut times = Vec::with_capacity(samples as usize);
    for k in 0..samples {
        let tick = oldest + (newest - oldest) * k / (samples - 1);
        let t = Instant::now();
        assert!(rec.image_at(tick, &mut out));
        times.push(t.elapsed().as_nanos() as f64 / 1000.0);
        black_box(&out);
    }
    let mean = times.iter().sum::<f64>() / times.len() as f64;
    times.sort_by(f64::total_cmp);
    let (p99, worst) = (times[times.len() * 99 / 100], times[times.len() - 1]);
    // The busiest byte: the worst case for a trace.
    let mut changes = Vec::new();
    let mut busiest = (0, 0);
    for off in 0..out.len() as u32 {
        rec.changes_of(off, oldest, newest, &mut changes);
        if changes.len() > busiest.1 {
            busiest = (off, changes.len());
        }
    }
    let t = Instant::now();
    for _ in 0..100 {
        rec.changes_of(busiest.0, oldest, newest, &mut changes);
        black_box(&changes);
    }
    let trace_us = t.elapsed().as_nanos() as f64 / 100.0 / 1000.0;
    let t = Instant::now();
    for k in 0..1000u32 {
        // Across the image: most bytes never change, and the segments they did not change in
        // are skipped.
        black_box(rec.last_change(newest, k % out.len() as u32, 0xFF));
    }
    let last_us = t.elapsed().as_nanos() as f64 / 1000.0 / 1000.0;
    // One bit of the busiest byte at a time: a bit that never changes walks every tick.
    let mut last_worst_us = 0.0f64;
    for bit in 0..8 {
        let t = Instant::now();
        black_box(rec.last_change(newest, busiest.0, 1 << bit));
        last_worst_us = last_worst_us.max(t.elapsed().as_nanos() as f64 / 1000.0);
    }
    (
        mean,
        p99,
        worst,
        trace_us,
        last_us,
        last_worst_us,
        busiest.1,
    )
}

fn report(name: &str, machine: &mut Machine, stimulus: Stimulus) {
    let (first, steady, rec) = memory(machine, stimulus);
    let (mean, p99, worst, trace, last, last_worst, changes) = queries(&rec);
    println!(
        "{name}: recorder memory per recorded second: {first:.0} B after 60 s, {steady:.0} B after 120 s (bytes_used {} KiB); image_at mean={mean:.1} µs p99={p99:.1} µs max={worst:.1} µs; changes_of the busiest byte over the window ({changes} changes) {trace:.1} µs; last_change mean={last:.2} µs, slowest on a bit of that byte {last_worst:.1} µs",
        rec.bytes_used() / 1024
    );
}

fn main() {
    let mut stress = machine("projects/stress-5000.ldp");
    println!(
        "stress-5000: image {} bytes recorded",
        stress.plc().layout().size
    );
    stress.run_ticks(1000, |_| {});
    for (name, stimulus) in [
        ("stress-5000", None),
        (
            "stress-5000, an X byte changing each tick",
            Some(inputs as fn(&mut Machine)),
        ),
    ] {
        print_cost(name, &mut stress, 20, stimulus);
        report(name, &mut stress, stimulus);
    }

    // The healthy-machine inputs of the lathe scripts: the lines before the part program.
    let cycle =
        std::fs::read_to_string(root().join("projects/lathe-988ta.tests/cycle.script")).unwrap();
    let healthy: String = cycle
        .lines()
        .take_while(|l| !l.starts_with("cnc program"))
        .map(|l| format!("{l}\n"))
        .collect();
    let mut idle = machine("projects/lathe-988ta.ldp");
    run_script(
        &mut idle,
        &format!("{healthy}scan 100\nexpect cnc.alarms 0\n"),
    );
    print_cost("lathe-988ta healthy, idle", &mut idle, 20, None);
    report("lathe-988ta healthy, idle", &mut idle, None);

    let mut looping = machine("projects/lathe-988ta.ldp");
    run_script(&mut looping, &cycle);
    print_cost(
        "lathe-988ta looping the part program",
        &mut looping,
        20,
        None,
    );
    report("lathe-988ta looping the part program", &mut looping, None);
    let status = looping.cnc().unwrap().status();
    assert_eq!(
        status.run,
        ladder_engine::cnc::RunState::Run,
        "the loop still runs"
    );
}
