//! The machine model's device kinds, tick by tick (docs/machine.md): each kind's timing to
//! the tick, the faults, and that a device writes nothing but the inputs it is bound to.

use ladder_engine::address::Address;
use ladder_engine::devices::CncView;
use ladder_engine::devices::model::*;
use ladder_engine::devices::{Device, DeviceKind, Fault, MachineModel, ModelError, Plant};
use ladder_engine::model::Project;
use ladder_engine::vm::Layout;
use ladder_engine::vm::Vm;
use ladder_engine::{Profile, ProfileId};
use proptest::prelude::*;

fn a(t: &str) -> Address {
    Address::parse(t).unwrap()
}

/// A machine model on a bare memory image, stepped by hand.
struct Bench {
    plant: Plant,
    mem: Vec<u8>,
    layout: Layout,
    view: CncView,
    ticks: u64,
}

fn profile() -> &'static Profile {
    Profile::get(ProfileId::Gsk988ta)
}

impl Bench {
    fn new(devices: Vec<(&str, DeviceKind)>) -> Bench {
        Bench::with_start(devices, Vec::new())
    }

    fn with_start(devices: Vec<(&str, DeviceKind)>, start_mm: Vec<f64>) -> Bench {
        let model = MachineModel {
            devices: devices
                .into_iter()
                .map(|(n, kind)| Device {
                    name: n.into(),
                    kind,
                })
                .collect(),
            start_mm,
        };
        let plant = Plant::new(&model, profile()).expect("a valid model");
        let mem = Vm::new(&Project::default()).unwrap().image().to_vec();
        Bench {
            plant,
            mem,
            layout: Layout::new(profile()),
            view: CncView::default(),
            ticks: 0,
        }
    }

    fn set(&mut self, addr: &str, v: bool) {
        let ad = a(addr);
        let off = self.layout.loc(ad, false).off as usize;
        let m = 1 << ad.bit.unwrap();
        self.mem[off] = if v {
            self.mem[off] | m
        } else {
            self.mem[off] & !m
        };
    }

    fn get(&self, addr: &str) -> bool {
        let ad = a(addr);
        self.mem[self.layout.loc(ad, false).off as usize] >> ad.bit.unwrap() & 1 == 1
    }

    fn byte(&self, addr: &str) -> u8 {
        self.mem[self.layout.loc(a(addr), false).off as usize]
    }

    fn tick(&mut self) {
        self.plant.step_with(&mut self.mem, Some(&self.view));
        self.ticks += 1;
    }

    fn run(&mut self, n: u64) {
        for _ in 0..n {
            self.tick();
        }
    }

    /// Ticks until `addr` reads `v`; returns how many ticks that took (counting the one
    /// where it first reads so).
    fn until(&mut self, addr: &str, v: bool, max: u64) -> u64 {
        for k in 1..=max {
            self.tick();
            if self.get(addr) == v {
                return k;
            }
        }
        panic!("{addr} never read {v} in {max} ticks");
    }
}

fn follower(input: &str, when: &str, on_ms: u32, off_ms: u32) -> DeviceKind {
    DeviceKind::Follower(Logic {
        input: a(input),
        when: when.into(),
        on_ms,
        off_ms,
    })
}

fn cylinder(retract: Option<&str>, travel_ms: u32) -> DeviceKind {
    DeviceKind::Actuator(Actuator {
        advance: a("Y0000.6"),
        retract: retract.map(a),
        travel_ms,
        at_advanced: Some(a("X0001.6")),
        at_retracted: Some(a("X0001.7")),
        moving: Some(a("X0002.0")),
        start_advanced: false,
    })
}

fn turret(encoding: Encoding, bits: u8, active_low: bool) -> Turret {
    Turret {
        stations: 4,
        cw: a("Y0000.4"),
        ccw: Some(a("Y0000.5")),
        direction: None,
        ccw_locks: false,
        station_ms: 400,
        window_pct: 30,
        lock: None,
        code: StationCode {
            first: a("X0000.0"),
            bits,
            encoding,
            active_low,
        },
        in_position: Some(a("X0000.6")),
        start_station: 1,
    }
}

#[test]
fn a_follower_comes_on_after_its_on_delay_and_off_after_its_off_delay() {
    let mut b = Bench::new(vec![(
        "pump",
        follower("X0003.0", "Y0000.2 & !Y0000.3", 100, 40),
    )]);
    b.run(5);
    assert!(!b.get("X0003.0"));
    b.set("Y0000.2", true);
    // 100 ms: ⌈100 / 8⌉ = 13 ticks.
    assert_eq!(b.until("X0003.0", true, 100), 13);
    b.set("Y0000.3", true);
    assert_eq!(b.until("X0003.0", false, 100), 5);
    // A condition that drops before the delay is up starts the delay again.
    b.set("Y0000.3", false);
    b.run(10);
    b.set("Y0000.3", true);
    b.run(1);
    b.set("Y0000.3", false);
    assert!(!b.get("X0003.0"));
    assert_eq!(b.until("X0003.0", true, 100), 13);
}

#[test]
fn a_zero_delay_follower_answers_in_the_same_tick() {
    let mut b = Bench::new(vec![("ready", follower("X0001.5", "1", 0, 0))]);
    b.tick();
    assert!(b.get("X0001.5"));
}

#[test]
fn an_actuator_travels_between_its_end_switches_in_its_travel_time() {
    let mut b = Bench::new(vec![("chuck", cylinder(Some("Y0000.7"), 400))]);
    b.tick();
    assert!(b.get("X0001.7") && !b.get("X0001.6") && !b.get("X0002.0"));
    b.set("Y0000.6", true);
    b.tick();
    assert!(
        !b.get("X0001.7") && b.get("X0002.0"),
        "left the end, moving"
    );
    // 400 ms = 50 ticks end to end.
    assert_eq!(b.until("X0001.6", true, 100), 49);
    assert!(!b.get("X0002.0"));
    // Both solenoids off: a double-acting cylinder stays where it is.
    b.set("Y0000.6", false);
    b.run(60);
    assert!(b.get("X0001.6"));
    b.set("Y0000.7", true);
    assert_eq!(b.until("X0001.7", true, 100), 50);
    assert_eq!(b.plant.status(0).unwrap().operations, 2);
}

#[test]
fn a_single_solenoid_actuator_springs_back() {
    let mut b = Bench::new(vec![("door", cylinder(None, 80))]);
    b.set("Y0000.6", true);
    assert_eq!(b.until("X0001.6", true, 100), 10);
    b.set("Y0000.6", false);
    assert_eq!(b.until("X0001.7", true, 100), 10);
}

#[test]
fn a_turret_shows_each_station_as_it_passes_and_stops_where_the_ladder_stops_it() {
    let mut b = Bench::new(vec![(
        "turret",
        DeviceKind::Turret(turret(Encoding::OneHot, 4, false)),
    )]);
    b.tick();
    assert_eq!(b.byte("X0000") & 0x0f, 0b0001);
    assert!(b.get("X0000.6"), "in position");
    b.set("Y0000.4", true);
    b.tick();
    assert!(!b.get("X0000.6"), "turning");
    // Station 1's window is ±60 ms: it reads until 60 ms of turning.
    assert_eq!(b.until("X0000.0", false, 100), 7);
    // Station 2's window starts 340 ms from station 1: tick 43 (344 ms).
    assert_eq!(b.until("X0000.1", true, 100) + 8, 43);
    b.set("Y0000.4", false);
    b.tick();
    assert_eq!(b.byte("X0000") & 0x0f, 0b0010);
    assert!(b.get("X0000.6"));
    // CCW turns it back through station 1 to station 4.
    b.set("Y0000.5", true);
    b.until("X0000.0", true, 200);
    b.until("X0000.3", true, 200);
    b.set("Y0000.5", false);
    b.tick();
    assert_eq!(b.plant.value(0), Some(4));
}

#[test]
fn station_codes_in_every_encoding_and_polarity() {
    for (encoding, bits, low, codes) in [
        (Encoding::Binary, 3, false, [1u8, 2, 3, 4]),
        (Encoding::Bcd, 4, false, [1, 2, 3, 4]),
        (Encoding::Gray, 3, false, [1, 3, 2, 6]),
        (Encoding::OneHot, 4, false, [1, 2, 4, 8]),
        (Encoding::Binary, 3, true, [6, 5, 4, 3]),
    ] {
        let mut b = Bench::new(vec![("t", DeviceKind::Turret(turret(encoding, bits, low)))]);
        let mask = (1u8 << bits) - 1;
        b.tick();
        let mut seen = vec![b.byte("X0000") & mask];
        b.set("Y0000.4", true);
        for _ in 0..3 {
            // 400 ms per station: 50 ticks from centre to centre.
            b.run(50);
            seen.push(b.byte("X0000") & mask);
        }
        assert_eq!(seen, codes, "{encoding:?} low={low}");
        // Between stations no code shows (all inputs inactive).
        b.run(25);
        let none = if low { mask } else { 0 };
        assert_eq!(b.byte("X0000") & mask, none, "{encoding:?}");
    }
}

#[test]
fn a_one_way_tool_post_locks_on_ccw_and_a_lock_stage_holds_it_until_unlocked() {
    let mut t = turret(Encoding::OneHot, 4, false);
    t.ccw_locks = true;
    let mut b = Bench::new(vec![("post", DeviceKind::Turret(t))]);
    b.set("Y0000.4", true);
    b.until("X0000.1", true, 100);
    b.set("Y0000.4", false);
    b.set("Y0000.5", true);
    b.run(20);
    // CCW does not turn it back: it stays at station 2, locked.
    assert_eq!(b.byte("X0000") & 0x0f, 0b0010);
    assert!(matches!(
        b.plant.status(0).unwrap().state,
        ladder_engine::devices::DeviceState::Turret { locked: true, .. }
    ));

    let mut t = turret(Encoding::OneHot, 4, false);
    t.lock = Some(TurretLock {
        unlock: a("Y0001.0"),
        ms: 200,
        unlocked: Some(a("X0002.1")),
        locked: Some(a("X0002.2")),
    });
    let mut b = Bench::new(vec![("indexer", DeviceKind::Turret(t))]);
    b.set("Y0000.4", true);
    b.run(30);
    assert_eq!(
        b.byte("X0000") & 0x0f,
        0b0001,
        "locked: the motor cannot turn it"
    );
    assert!(b.get("X0002.2"));
    b.set("Y0001.0", true);
    assert_eq!(b.until("X0002.1", true, 100), 25);
    assert!(!b.get("X0002.2"));
    b.until("X0000.0", false, 100);
}

#[test]
fn a_run_output_with_a_direction_output_turns_either_way() {
    let mut t = turret(Encoding::Binary, 3, false);
    t.ccw = None;
    t.direction = Some(a("Y0000.5"));
    let mut b = Bench::new(vec![("t", DeviceKind::Turret(t))]);
    b.set("Y0000.5", true);
    b.set("Y0000.4", true);
    b.run(50);
    assert_eq!(b.byte("X0000") & 7, 4, "CCW from 1 is 4");
}

#[test]
fn a_position_switch_follows_the_axis_through_a_reference_return() {
    let dog = DeviceKind::PositionSwitch(PositionSwitch {
        input: a("X0007.0"),
        axis: 0,
        from_mm: -5.0,
        to_mm: 0.0,
        active_low: true,
    });
    let mut b = Bench::with_start(vec![("dog", dog)], vec![-7.0]);
    b.tick();
    assert!(b.get("X0007.0"), "off the dog (normally closed)");
    // The CNC's machine coordinate moves 1 mm a tick from 0 (where it powers on).
    for k in 1..=8 {
        b.view.m[0] = k * 1000;
        b.tick();
        assert_eq!(b.get("X0007.0"), !(2..=7).contains(&k), "at {} mm", k - 7);
    }
    // The reference return sets the machine coordinate without moving the axis.
    b.view.m[0] = 0;
    b.view.zrf[0] = true;
    b.tick();
    assert_eq!(b.plant.axis_mm(0), 1.0);
    assert!(b.get("X0007.0"));
    b.view.m[0] = -2000;
    b.tick();
    assert!(!b.get("X0007.0"), "back on the dog at −1 mm");
}

#[test]
fn spindle_feedback_ramps_to_the_commanded_speed() {
    let sp = DeviceKind::Spindle(SpindleFeedback {
        run: "Y0000.0".into(),
        arrival: Some(a("X0003.0")),
        zero: Some(a("X0003.1")),
        ramp_ms: 1000,
        full_rpm: 1000,
        tolerance_pct: 10,
        zero_rpm: 10,
    });
    let mut b = Bench::new(vec![("spindle", sp)]);
    b.view.s_out = 800;
    b.tick();
    assert!(
        b.get("X0003.1") && !b.get("X0003.0"),
        "not running: zero speed"
    );
    b.set("Y0000.0", true);
    // 1 rpm per ms: 720 rpm (within 10 % of 800) after 720 ms = 90 ticks.
    assert_eq!(b.until("X0003.0", true, 200), 90);
    assert!(!b.get("X0003.1"));
    b.set("Y0000.0", false);
    // From 720 rpm down to 10 rpm: 710 ms = ⌈88.75⌉ ticks.
    assert_eq!(b.until("X0003.1", true, 200), 89);
}

#[test]
fn lubrication_builds_pressure_and_runs_low_after_its_operations() {
    let lube = DeviceKind::Lubrication(Lubrication {
        pump: a("Y0000.3"),
        pressure: Some(a("X0003.2")),
        build_ms: 800,
        decay_ms: 400,
        level_low: Some(a("X0000.7")),
        operations: 2,
    });
    let mut b = Bench::new(vec![("lube", lube)]);
    b.set("Y0000.3", true);
    assert_eq!(b.until("X0003.2", true, 200), 100);
    b.set("Y0000.3", false);
    assert_eq!(b.until("X0003.2", false, 200), 50);
    assert!(!b.get("X0000.7"));
    b.set("Y0000.3", true);
    b.tick();
    assert!(b.get("X0000.7"), "the second start empties it");
    b.plant.reset(0);
    b.tick();
    assert!(!b.get("X0000.7"), "refilled");
}

#[test]
fn a_pulse_source_and_a_counter() {
    let mut b = Bench::new(vec![
        (
            "clock",
            DeviceKind::Pulse(Pulse {
                input: a("X0003.0"),
                period_ms: 80,
                on_ms: 16,
                enable: "Y0000.0".into(),
            }),
        ),
        (
            "bar_end",
            DeviceKind::Counter(Counter {
                input: a("X0003.1"),
                source: "clock.on".into(),
                count: 3,
            }),
        ),
    ]);
    b.run(20);
    assert!(!b.get("X0003.0"), "disabled");
    b.set("Y0000.0", true);
    let mut pattern = String::new();
    for _ in 0..20 {
        b.tick();
        pattern.push(if b.get("X0003.0") { '1' } else { '0' });
    }
    assert_eq!(pattern, "11000000001100000000");
    b.run(10);
    assert!(b.get("X0003.1"), "three pulses counted");
}

#[test]
fn an_expression_reads_outputs_and_other_devices_states() {
    let mut b = Bench::new(vec![
        ("chuck", cylinder(Some("Y0000.7"), 80)),
        (
            "ok",
            DeviceKind::Expression(Logic {
                input: a("X0004.0"),
                when: "chuck.advanced AND NOT (Y0001.0 | Y0001.1)".into(),
                on_ms: 0,
                off_ms: 0,
            }),
        ),
    ]);
    b.set("Y0000.6", true);
    assert_eq!(b.until("X0004.0", true, 100), 10);
    b.set("Y0001.1", true);
    b.tick();
    assert!(!b.get("X0004.0"));
}

#[test]
fn faults_bend_what_a_device_writes() {
    let chuck = || cylinder(Some("Y0000.7"), 400);
    // Stuck at 0, one input only.
    let mut b = Bench::new(vec![("chuck", chuck())]);
    b.plant.set_fault(
        0,
        Some(Fault::Stuck {
            value: false,
            input: Some(a("X0001.6")),
        }),
    );
    b.set("Y0000.6", true);
    b.run(100);
    assert!(!b.get("X0001.6"), "the clamp switch never closes");
    assert!(!b.get("X0001.7"), "but it did travel");
    b.plant.set_fault(0, None);
    b.tick();
    assert!(b.get("X0001.6"));

    // Slow by 2: 100 ticks instead of 50.
    let mut b = Bench::new(vec![("chuck", chuck())]);
    b.plant.set_fault(0, Some(Fault::Slow { factor: 2.0 }));
    b.set("Y0000.6", true);
    assert_eq!(b.until("X0001.6", true, 200), 100);

    // Fails after one operation: the second move never happens.
    let mut b = Bench::new(vec![("chuck", chuck())]);
    b.plant
        .set_fault(0, Some(Fault::FailAfter { operations: 1 }));
    b.set("Y0000.6", true);
    b.until("X0001.6", true, 100);
    b.set("Y0000.6", false);
    b.set("Y0000.7", true);
    b.run(200);
    assert!(b.get("X0001.6") && !b.get("X0001.7"));
    assert!(b.plant.status(0).unwrap().failed);

    // Flicker every 80 ms: one tick in ten reads inverted.
    let mut b = Bench::new(vec![("ready", follower("X0001.5", "1", 0, 0))]);
    b.plant.set_fault(0, Some(Fault::Flicker { period_ms: 80 }));
    let mut pattern = String::new();
    for _ in 0..20 {
        b.tick();
        pattern.push(if b.get("X0001.5") { '1' } else { '0' });
    }
    assert_eq!(pattern, "01111111110111111111");
}

#[test]
fn a_model_with_errors_is_refused_with_the_device_and_field() {
    let bad = |kind: DeviceKind| {
        let m = MachineModel {
            devices: vec![Device {
                name: "d".into(),
                kind,
            }],
            start_mm: vec![],
        };
        Plant::new(&m, profile()).unwrap_err()
    };
    let e = bad(follower("Y0000.1", "1", 0, 0));
    assert!(matches!(e, ModelError::NotInput { .. }), "{e}");
    assert!(e.to_string().contains("a device writes X bits"), "{e}");
    let e = bad(follower("X0000.1", "Y0000.1 &", 0, 0));
    assert!(e.to_string().contains("the condition ends"), "{e}");
    let e = bad(follower("X0000.1", "other.on", 0, 0));
    assert!(e.to_string().contains("no device is named `other`"), "{e}");
    let mut t = turret(Encoding::Binary, 2, false);
    t.stations = 4;
    let e = bad(DeviceKind::Turret(t));
    assert_eq!(e.code(), "M003", "{e}");
    assert!(e.to_string().contains("code.bits"), "{e}");
}

/// A random valid device on random addresses within X0000–X0009 / Y0000–Y0009.
fn any_device() -> impl Strategy<Value = DeviceKind> {
    let x = (0u16..10, 0u8..8).prop_map(|(n, b)| Address::bit(ladder_engine::Area::X, n, b));
    let y = (0u16..10, 0u8..8).prop_map(|(n, b)| Address::bit(ladder_engine::Area::Y, n, b));
    prop_oneof![
        (x.clone(), y.clone(), 0u32..100, 0u32..100).prop_map(|(i, o, on, off)| {
            DeviceKind::Follower(Logic {
                input: i,
                when: o.to_string(),
                on_ms: on,
                off_ms: off,
            })
        }),
        (x.clone(), y.clone(), y.clone(), 1u32..200).prop_map(|(i, o, r, t)| {
            DeviceKind::Actuator(Actuator {
                advance: o,
                retract: Some(r),
                travel_ms: t,
                at_advanced: Some(i),
                at_retracted: None,
                moving: None,
                start_advanced: false,
            })
        }),
        (0u16..9, y.clone(), y.clone(), 2u8..9).prop_map(|(n, cw, ccw, s)| {
            DeviceKind::Turret(Turret {
                stations: s,
                cw,
                ccw: Some(ccw),
                direction: None,
                ccw_locks: false,
                station_ms: 40,
                window_pct: 30,
                lock: None,
                code: StationCode {
                    first: Address::bit(ladder_engine::Area::X, n, 3),
                    bits: 4,
                    encoding: Encoding::Binary,
                    active_low: true,
                },
                in_position: None,
                start_station: 1,
            })
        }),
        (x.clone(), y.clone()).prop_map(|(i, o)| {
            DeviceKind::Lubrication(Lubrication {
                pump: o,
                pressure: Some(i),
                build_ms: 50,
                decay_ms: 50,
                level_low: None,
                operations: 0,
            })
        }),
        (x, 1u32..100).prop_map(|(i, p)| DeviceKind::Pulse(Pulse {
            input: i,
            period_ms: p,
            on_ms: p / 2,
            enable: String::new(),
        })),
    ]
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    #[test]
    fn a_device_model_never_writes_outside_its_bindings(
        kinds in prop::collection::vec(any_device(), 1..6),
        seed in any::<u64>(),
    ) {
        // Keep the first device of each written input, as `check` would insist.
        let mut taken = std::collections::HashSet::new();
        let mut devices = Vec::new();
        for (k, kind) in kinds.into_iter().enumerate() {
            let inputs: Vec<Address> = kind.inputs().into_iter().map(|(_, a)| a).collect();
            if inputs.iter().all(|a| taken.insert(*a)) {
                devices.push(Device { name: format!("dev{k}"), kind });
            }
        }
        let model = MachineModel { devices, start_mm: vec![] };
        let mut plant = Plant::new(&model, profile()).unwrap();
        let layout = Layout::new(profile());
        let mut mem = Vm::new(&Project::default()).unwrap().image().to_vec();
        let mut owned = vec![0u8; mem.len()];
        for b in plant.written_bits() {
            owned[b.off as usize] |= b.mask;
        }
        let y = layout.area_range(ladder_engine::Area::Y);
        let mut s = seed;
        for _ in 0..200 {
            // Random outputs and random memory elsewhere, as a scan would leave them.
            s = s.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
            let at = (s >> 33) as usize % mem.len();
            mem[at] ^= (s >> 20) as u8;
            mem[y.start + (s >> 40) as usize % 10] = (s >> 48) as u8;
            let before = mem.clone();
            plant.step_with(&mut mem, None);
            for (k, (b, a)) in before.iter().zip(&mem).enumerate() {
                prop_assert_eq!(b & !owned[k], a & !owned[k], "byte {} changed outside the bindings", k);
            }
        }
    }
}

#[test]
fn a_turret_made_fast_never_steps_over_a_station_unseen() {
    // A 2 % window is 8 ms, one tick; ten times faster the turret moves 80 ms a tick.
    let mut t = turret(Encoding::Binary, 3, false);
    t.window_pct = 2;
    let mut b = Bench::new(vec![("t", DeviceKind::Turret(t))]);
    b.plant.set_fault(0, Some(Fault::Slow { factor: 0.1 }));
    b.set("Y0000.4", true);
    let mut seen = std::collections::BTreeSet::new();
    for _ in 0..100 {
        b.tick();
        seen.insert(b.byte("X0000") & 7);
    }
    assert_eq!(
        seen.into_iter().collect::<Vec<_>>(),
        [0, 1, 2, 3, 4],
        "every station shows"
    );
}

#[test]
fn a_model_edited_while_running_keeps_the_state_of_the_devices_it_did_not_change() {
    let model = |travel_ms| MachineModel {
        devices: vec![
            (
                "turret",
                DeviceKind::Turret(turret(Encoding::OneHot, 4, false)),
            ),
            ("chuck", cylinder(Some("Y0000.7"), travel_ms)),
        ]
        .into_iter()
        .map(|(n, kind)| Device {
            name: n.into(),
            kind,
        })
        .collect(),
        start_mm: vec![-7.0],
    };
    let mut b = Bench::new(vec![]);
    b.plant = Plant::new(&model(400), profile()).unwrap();
    b.set("Y0000.4", true);
    b.set("Y0000.6", true);
    b.until("X0000.2", true, 200);
    b.set("Y0000.4", false);
    b.view.m[0] = 3000;
    b.run(60);
    assert_eq!(b.plant.value(0), Some(3));
    assert_eq!(b.plant.value(1), Some(100));
    b.plant.set_fault(1, Some(Fault::Slow { factor: 2.0 }));
    // The chuck's travel time edited; the turret untouched.
    let mut edited = Plant::new(&model(800), profile()).unwrap();
    edited.take_over(&b.plant);
    b.plant = edited;
    assert_eq!(b.plant.value(1), Some(0), "the edited chuck starts afresh");
    b.tick();
    assert_eq!(b.plant.value(0), Some(3), "the turret stays at station 3");
    assert_eq!(
        b.plant.status(1).unwrap().fault,
        Some(Fault::Slow { factor: 2.0 })
    );
    assert_eq!(b.plant.axis_mm(0), -4.0, "the axis stays where it is");
}

#[test]
fn a_condition_too_deep_for_the_evaluator_is_refused_and_parentheses_say_where() {
    let parse = |text: &str| {
        ladder_engine::devices::expr::parse(
            text,
            profile(),
            &ladder_engine::devices::expr::Names {
                devices: &[],
                states: true,
            },
        )
    };
    let mut deep = String::new();
    for _ in 0..40 {
        deep.push_str("Y0.0 | Y0.1 & (");
    }
    deep.push_str("Y0.2");
    deep.push_str(&")".repeat(40));
    let e = parse(&deep).unwrap_err();
    assert!(e.to_string().contains("too deep"), "{e}");
    let e = parse("(Y0.0 Y0.1)").unwrap_err();
    assert!(e.to_string().contains("`Y0.1` at character 7"), "{e}");
    assert!(
        parse("(Y0.0")
            .unwrap_err()
            .to_string()
            .contains("not closed")
    );
    // NOT binds tightest, then AND, then OR.
    let t = parse("!Y0.0 | Y0.1 & Y0.2").unwrap();
    use ladder_engine::devices::expr::Term::*;
    assert!(matches!(
        t.as_slice(),
        [Bit(_), Not, Bit(_), Bit(_), And, Or]
    ));
}
