//! Real-time benchmark of the machine thread: `cargo bench -p ladder-engine --bench runner`.
//!
//! Runs `projects/stress-5000.ldp` with the simulated CNC on a [`Runner`] at real time for
//! a minute (`RUNNER_SECONDS` to change it), recording every tick with the scan recorder as
//! the editor does, and prints how late ticks started against their 8 ms schedule: the target
//! is no tick more than one tick (8 ms) late.

use ladder_engine::file;
use ladder_engine::machine::{Machine, MachineCommand};
use ladder_engine::recorder::Recorder;
use ladder_engine::runner::{Published, Request, Runner, Speed};
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

fn main() {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/../projects/stress-5000.ldp");
    let project = file::load(std::path::Path::new(path)).expect("the stress project loads");
    let machine = Machine::new(&project, true).expect("it compiles");
    let size = machine.plc().layout().size as usize;
    let recorder = Arc::new(Mutex::new(Recorder::new(size, 7500)));
    let rec = Arc::clone(&recorder);
    let hook = Box::new(move |m: &Machine| {
        rec.lock()
            .unwrap()
            .record(m.plc().ticks(), &m.plc().image()[..size]);
    });
    let runner = Runner::start(machine, hook, Box::new(|_| {})).unwrap();
    let seconds: u64 = std::env::var("RUNNER_SECONDS")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(60);
    runner.send(Request::Speed(Speed::RealTime));
    runner.send(Request::Command(MachineCommand::Run));
    let start = Instant::now();
    let mut p = Published::default();
    // A UI taking the state at 60 frames a second, as the editor does.
    let poll: u64 = std::env::var("RUNNER_POLL_MS")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(16);
    while start.elapsed() < Duration::from_secs(seconds) {
        std::thread::sleep(Duration::from_millis(poll));
        runner.take(&mut p);
    }
    runner.take(&mut p);
    let l = p.lateness;
    let wall = start.elapsed().as_secs_f64();
    let virtual_s = p.snapshot.ticks as f64 * 0.008;
    println!(
        "runner, stress-5000 with the CNC and the recorder, real time for {seconds} s: ticks={} virtual_s={virtual_s:.2} wall_s={wall:.2} max_late_ms={:.3} ticks_over_8ms_late={} timed={}",
        p.snapshot.ticks, l.max_ms, l.over_a_tick, l.timed
    );
    let bytes = recorder.lock().unwrap().bytes_used();
    println!(
        "recorder after {virtual_s:.0} s: bytes_used={bytes} bytes_per_recorded_second={:.0}",
        bytes as f64 / virtual_s.clamp(1.0, 60.0)
    );
    runner.stop();
}
