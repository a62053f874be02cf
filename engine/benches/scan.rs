//! Scan benchmarks: `cargo bench -p ladder-engine --bench scan`.
//!
//! Prints the figures of the scan-engine targets: hot ns/step of a 5000-step bit-logic
//! program, the median of scans paced 8 ms apart, a 5000-step mixed program, the cost of
//! monitoring 50 networks, one hour of machine time of a 500-step program, and one hour of
//! the sample lathe running a looping part program under the simulated CNC.

use ladder_engine::generate::{Mix, program_il};
use ladder_engine::il;
use ladder_engine::machine::Machine;
use ladder_engine::sim::{self, Options, Script};
use ladder_engine::vm::Vm;
use ladder_engine::vm::cnc::NoCnc;
use std::time::{Duration, Instant};

fn vm(steps: u32, mix: Mix) -> Vm {
    let project = il::import(&program_il(steps, mix, 1))
        .project
        .expect("generated programs draw");
    Vm::new(&project).expect("generated programs compile")
}

/// Nanoseconds per scan and per executed step over `scans` back-to-back scans.
fn hot(vm: &mut Vm, scans: u64) -> (f64, f64) {
    for _ in 0..1000 {
        vm.tick(&mut NoCnc);
    }
    let before = vm.executed_steps();
    let t = Instant::now();
    for _ in 0..scans {
        vm.tick(&mut NoCnc);
    }
    let ns = t.elapsed().as_nanos() as f64;
    let steps = (vm.executed_steps() - before) as f64;
    (ns / scans as f64, ns / steps)
}

fn main() {
    let mut bits = vm(5000, Mix::BitLogic);
    let (scan_ns, step_ns) = hot(&mut bits, 20_000);
    println!("bit-logic 5000 steps, hot: ns_per_scan={scan_ns:.0} ns_per_step={step_ns:.3}");

    let mut paced = Vec::new();
    for _ in 0..200 {
        std::thread::sleep(Duration::from_millis(8));
        let t = Instant::now();
        bits.tick(&mut NoCnc);
        paced.push(t.elapsed().as_nanos() as f64);
    }
    paced.sort_by(f64::total_cmp);
    println!(
        "bit-logic 5000 steps, paced 8 ms apart: median_ns_per_scan={:.0} median_ns_per_step={:.3}",
        paced[paced.len() / 2],
        paced[paced.len() / 2] / 5000.0
    );

    let mut mixed = vm(5000, Mix::Mixed);
    let (scan_ns, step_ns) = hot(&mut mixed, 20_000);
    println!("mixed 5000 steps, hot: ns_per_scan={scan_ns:.0} ns_per_step={step_ns:.3}");

    let (_, off) = hot(&mut mixed, 20_000);
    let networks = mixed.code().networks.len();
    for n in (0..networks).step_by((networks / 50).max(1)).take(50) {
        mixed.watch(n, true);
    }
    let (_, on) = hot(&mut mixed, 20_000);
    println!(
        "monitoring 50 networks: ns_per_step off={off:.3} on={on:.3} cost={:+.1}%",
        (on / off - 1.0) * 100.0
    );

    let mut small = vm(500, Mix::Mixed);
    let t = Instant::now();
    for _ in 0..450_000 {
        small.tick(&mut NoCnc);
    }
    println!(
        "one hour of machine time (450000 ticks) of a {}-step program: {:.3} s",
        small.executed_steps() / 450_000,
        t.elapsed().as_secs_f64()
    );

    // The sample lathe under the simulated CNC, set up and started by projects/lathe-988ta.tests/cycle.script.
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
    let project = ladder_engine::file::load(&root.join("projects/lathe-988ta.ldp"))
        .expect("the sample loads");
    // The cycle script sets the machine's sensors by hand, as `sim --no-machine` runs it.
    let mut machine = Machine::new(&project, true)
        .expect("the sample compiles")
        .without_devices();
    let text =
        std::fs::read_to_string(root.join("projects/lathe-988ta.tests/cycle.script")).unwrap();
    let script = Script::parse_with(
        &text,
        machine.plc().profile(),
        &Options {
            cnc: true,
            read_file: &|p| Err(p.to_string()),
            machine: None,
            project: None,
        },
    )
    .expect("the cycle script parses");
    let outcome = sim::run(&mut machine, &script, "cycle", false);
    assert_eq!(outcome.failed, 0, "{:?}", outcome.output);
    let t = Instant::now();
    machine.run_ticks(450_000, |_| {});
    let hour = t.elapsed().as_secs_f64();
    let status = machine.cnc().unwrap().status();
    assert_eq!(
        status.run,
        ladder_engine::cnc::RunState::Run,
        "the loop still runs"
    );
    println!(
        "one hour of the sample lathe looping a part program with the simulated CNC: {hour:.3} s ({:.0} ns per tick)",
        hour * 1e9 / 450_000.0
    );
}
