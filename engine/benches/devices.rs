//! Machine-model benchmarks: `cargo bench -p ladder-engine --bench devices`.
//!
//! Prints the cost of the sample lathe's machine model in percent of its tick (the sample
//! running its bundled job after a reference return on its dogs; target ≤ 5 %), and the time
//! of one tick of 1 000 devices of eight kinds on a bare memory image (target ≤ 20 µs).

use ladder_engine::address::{Address, Area};
use ladder_engine::devices::CncView;
use ladder_engine::devices::model::*;
use ladder_engine::devices::{Device, DeviceKind, MachineModel, Plant};
use ladder_engine::machine::Machine;
use ladder_engine::model::Project;
use ladder_engine::sim::{self, Options, Script};
use ladder_engine::vm::Vm;
use ladder_engine::{Profile, ProfileId};
use std::hint::black_box;
use std::path::Path;
use std::time::Instant;

/// The sample set up by projects/lathe-988ta.tests/machine-part-program.script up to its cycle start.
fn sample() -> Machine {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
    let project =
        ladder_engine::file::load(&root.join("projects/lathe-988ta.ldp")).expect("the sample");
    let mut m = Machine::new(&project, true).expect("the sample compiles");
    let text = std::fs::read_to_string(
        root.join("projects/lathe-988ta.tests/machine-part-program.script"),
    )
    .unwrap();
    // Up to the first long run: reference return and cycle start.
    let setup: String = text
        .lines()
        .take_while(|l| !l.starts_with("run 80s"))
        .map(|l| {
            l.replace(
                "cnc program-file ../../projects/",
                "cnc program-file projects/",
            )
        })
        .collect::<Vec<_>>()
        .join("\n");
    let read = |p: &str| {
        ladder_engine::cnc::program::read_program_file(&root.join(p)).map_err(|e| {
            ladder_text::script::program_file_error(&e, Path::new(p), ladder_text::Lang::En)
        })
    };
    let script = Script::parse_with(
        &setup,
        m.plc().profile(),
        &Options {
            cnc: true,
            read_file: &read,
            machine: Some(&project.machine),
            project: Some(&project),
        },
    )
    .expect("the set-up parses");
    let out = sim::run(&mut m, &script, "setup", false);
    assert_eq!(out.failed, 0, "{:?}", out.output);
    m
}

fn sample_share() {
    let mut m = sample();
    // Alternating batches, so a burst of load on a shared machine slows both alike; the
    // median of the batches' shares moves less than the ratio of the means.
    let (batches, ticks) = (15, 5_000u64);
    let (mut whole, mut alone, mut shares) = (0.0, 0.0, Vec::new());
    for _ in 0..batches {
        let t = Instant::now();
        for _ in 0..ticks {
            m.tick();
        }
        let w = t.elapsed().as_nanos() as f64;
        let t = Instant::now();
        for _ in 0..ticks {
            m.step_devices();
        }
        let a = t.elapsed().as_nanos() as f64;
        whole += w;
        alone += a;
        shares.push(100.0 * a / w);
    }
    shares.sort_by(f64::total_cmp);
    let n = (batches as u64 * ticks) as f64;
    println!(
        "sample lathe: {} devices, tick {:.0} ns, devices {:.0} ns = {:.2} % of the tick (median of {batches} batches; target ≤ 5 %)",
        m.plant().map_or(0, |p| p.names().count()),
        whole / n,
        alone / n,
        shares[shares.len() / 2]
    );
}

fn bit(area: Area, k: usize) -> Address {
    Address::bit(area, (k / 8 % 128) as u16, (k % 8) as u8)
}

/// 1 000 devices: the kinds in turn, each on its own inputs.
fn thousand() -> MachineModel {
    let mut devices = Vec::new();
    let mut x = 0usize;
    let mut take = |n: usize| {
        let first = x;
        x += n;
        bit(Area::X, first)
    };
    for k in 0..1000 {
        let y = bit(Area::Y, k * 3);
        // Eight kinds in turn, eight inputs per eight devices: 1 000 inputs fit X0–X127.
        let kind = match k % 8 {
            0 => DeviceKind::Follower(Logic {
                input: take(1),
                when: format!("{y} & !{}", bit(Area::Y, k * 3 + 1)),
                on_ms: 40,
                off_ms: 40,
            }),
            1 => DeviceKind::Actuator(Actuator {
                advance: y,
                retract: Some(bit(Area::Y, k * 3 + 1)),
                travel_ms: 300,
                at_advanced: Some(take(1)),
                at_retracted: None,
                moving: None,
                start_advanced: false,
            }),
            2 => DeviceKind::Turret(Turret {
                stations: 2,
                cw: y,
                ccw: None,
                direction: None,
                ccw_locks: false,
                station_ms: 200,
                window_pct: 30,
                lock: None,
                code: StationCode {
                    first: take(2),
                    bits: 2,
                    encoding: Encoding::Binary,
                    active_low: false,
                },
                in_position: None,
                start_station: 1,
            }),
            3 => DeviceKind::PositionSwitch(PositionSwitch {
                input: take(1),
                axis: (k % 2) as u8,
                from_mm: -5.0,
                to_mm: 0.0,
                active_low: true,
            }),
            4 => DeviceKind::Lubrication(Lubrication {
                pump: y,
                pressure: Some(take(1)),
                build_ms: 200,
                decay_ms: 200,
                level_low: None,
                operations: 0,
            }),
            5 => DeviceKind::Pulse(Pulse {
                input: take(1),
                period_ms: 100,
                on_ms: 24,
                enable: y.to_string(),
            }),
            6 => DeviceKind::Spindle(SpindleFeedback {
                run: y.to_string(),
                arrival: None,
                zero: None,
                ramp_ms: 500,
                full_rpm: 3000,
                tolerance_pct: 10,
                zero_rpm: 10,
            }),
            _ => DeviceKind::Counter(Counter {
                input: take(1),
                source: y.to_string(),
                count: 50,
            }),
        };
        devices.push(Device {
            name: format!("d{k:04}x"),
            kind,
        });
    }
    MachineModel {
        devices,
        start_mm: vec![-10.0, -10.0],
    }
}

fn thousand_devices() {
    let profile = Profile::get(ProfileId::Gsk988ta);
    let model = thousand();
    let mut plant = Plant::new(&model, profile).expect("a valid model");
    let mut mem = Vm::new(&Project::default()).unwrap().image().to_vec();
    let layout = ladder_engine::vm::Layout::new(profile);
    let y = layout.area_range(Area::Y);
    let mut view = CncView::default();
    let ticks = 20_000u64;
    let t = Instant::now();
    for k in 0..ticks {
        // Outputs and axes change as a running program would change them.
        mem[y.start + (k as usize % 128)] = (k.wrapping_mul(0x9E37_79B9) >> 8) as u8;
        view.m[0] = (k as i64 % 20_000) - 10_000;
        plant.step_with(black_box(&mut mem), Some(&view));
    }
    let per = t.elapsed().as_nanos() as f64 / ticks as f64;
    println!(
        "1000 devices: {:.2} µs a tick (target ≤ 20 µs)",
        per / 1000.0
    );
}

fn main() {
    // `-- sample` or `-- thousand` runs one part (for `valgrind --tool=callgrind`).
    let only: Vec<String> = std::env::args()
        .skip(1)
        .filter(|a| !a.starts_with('-'))
        .collect();
    let wants = |name: &str| only.is_empty() || only.iter().any(|o| o == name);
    if wants("sample") {
        sample_share();
    }
    if wants("thousand") {
        thousand_devices();
    }
}
