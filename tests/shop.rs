//! Part programs in the styles shops write (tests/nc: FANUC 0i two-block cycles, FS15/Haas
//! one-block cycles in inch, GSK, drilling cycles, subprograms) run on the sample lathe as an
//! engineer would run them, against the sample's machine model (docs/machine.md): reference
//! return on the dogs, AUTO, cycle start (again after M00/M01), #3401 = 0 and #3402 bit 4 = 0
//! as on a FANUC lathe. Each must reach M30 without an alarm, with gang tooling (K0000.1 = 0)
//! and, when it calls only the four stations the turret has, with the electric tool post the
//! sample ships with; a program with a typing error stops with a P/S alarm naming its block.

use ladder_engine::address::Address;
use ladder_engine::cnc::command::{CncCommand, CncKey};
use ladder_engine::cnc::program::read_program_file;
use ladder_engine::file;
use ladder_engine::machine::{Machine, MachineCommand, Probe};
use ladder_tests::here;

fn a(t: &str) -> Address {
    Address::parse(t).unwrap()
}

fn value(m: &Machine, key: &str) -> String {
    let k = CncKey::parse(key, ladder_engine::ProfileId::Gsk988ta).unwrap();
    m.read(&Probe::Cnc(k)).unwrap().to_string()
}

fn cnc(m: &mut Machine, c: CncCommand) {
    m.apply(&MachineCommand::Cnc(c)).unwrap();
}

/// Presses a panel key (an X bit) for one scan.
fn press(m: &mut Machine, key: &str) {
    m.plc_mut().write(a(key), 1, 1);
    m.tick();
    m.plc_mut().write(a(key), 1, 0);
    m.tick();
}

/// How a program run ended.
#[derive(Debug)]
struct Outcome {
    /// Parts counted (#6711): 1 when M30 or M02 was reached.
    parts: String,
    alarms: String,
    block: String,
    ticks: u64,
    /// A0000.2, the ladder's "T code out of range" message (1003).
    plc_alarm: i64,
}

/// Sets the sample lathe up as the shop runs it and runs `nc` until it ends, stops on an
/// alarm, or `limit` scans pass.
fn run_program(nc: &str, limit: u64) -> Outcome {
    run_on_sample(
        &here().join("nc").join(nc),
        Setup::Fanuc { turret: false },
        limit,
    )
}

/// How the sample is set up before a run.
#[derive(Clone, Copy)]
enum Setup {
    /// #3401 = 0 and #3402 = 0; the electric tool post on or off (gang tooling).
    Fanuc { turret: bool },
    /// The sample's own settings.
    Sample,
}

/// Runs the program at `path` on the sample lathe and its machine model. Only what an
/// operator does is done by hand: the E-stop released, the override knobs, the keys.
fn run_on_sample(path: &std::path::Path, setup: Setup, limit: u64) -> Outcome {
    let mut m = start_on_sample(path, setup);
    run_until_end(&mut m, limit)
}

/// The sample lathe set up, referenced, in AUTO, with the program at `path` started.
fn start_on_sample(path: &std::path::Path, setup: Setup) -> Machine {
    let nc = path.display().to_string();
    let project = file::load(&here().join("../projects/lathe-988ta.ldp")).expect("the sample");
    let mut m = Machine::new(&project, true).expect("builds");
    assert!(m.plant().is_some(), "the sample ships with its machine");
    m.plc_mut().write(a("X0000.5"), 1, 1);
    m.plc_mut().write(a("X0005"), 1, 15);
    m.plc_mut().write(a("X0006"), 1, 5);
    if let Setup::Fanuc { turret } = setup {
        m.plc_mut().write(a("K0000.1"), 1, i64::from(turret));
        for number in [3401, 3402] {
            let value = 0;
            cnc(
                &mut m,
                CncCommand::Param {
                    number,
                    selector: None,
                    value,
                },
            );
        }
    }
    let text = read_program_file(path).expect("the program");
    cnc(&mut m, CncCommand::Program(text));
    m.run_ticks(2, |_| {});
    // Reference return on the machine's own dogs: REF mode, X+ and Z+ pressed once.
    press(&mut m, "X0002.5");
    m.plc_mut().write(a("X0004.0"), 1, 1);
    m.plc_mut().write(a("X0004.2"), 1, 1);
    m.tick();
    m.plc_mut().write(a("X0004.0"), 1, 0);
    m.plc_mut().write(a("X0004.2"), 1, 0);
    for _ in 0..2000 {
        m.tick();
        if m.plc().read(a("F0120"), 1) == 3 {
            break;
        }
    }
    assert_eq!(m.plc().read(a("F0120"), 1), 3, "{nc}: reference points set");
    press(&mut m, "X0002.1");
    press(&mut m, "X0002.6");
    m
}

/// Runs until the program ends, stops on an alarm, or `limit` scans pass; cycle start is
/// pressed again after M00/M01.
fn run_until_end(m: &mut Machine, limit: u64) -> Outcome {
    let mut ticks = 0;
    while ticks < limit {
        m.tick();
        ticks += 1;
        let run = value(m, "cnc.run");
        if value(m, "cnc.alarms") != "0" || run == "IDLE" {
            break;
        }
        if run == "STOP" {
            // M00 / M01: the operator presses cycle start again.
            press(m, "X0002.6");
        }
    }
    Outcome {
        parts: value(m, "cnc.param.6711"),
        alarms: value(m, "cnc.alarms"),
        block: value(m, "cnc.block"),
        ticks,
        plc_alarm: m.plc().read(a("A0000.2"), 1),
    }
}

#[test]
fn shop_programs_in_every_style_run_to_their_end_without_an_alarm() {
    for nc in [
        "fanuc-0i-shaft.nc",
        "haas-bushing-inch.nc",
        "gsk-flange.nc",
        "face-drilling.nc",
        "subprogram-grooves.nc",
        "fanuc-flange-g72.nc",
        "gsk-taper-g90.nc",
        "macro-grooves-g65.nc",
        "macro-chamfer-inch.nc",
        "gsk-macro-thread.nc",
    ] {
        let o = run_program(nc, 400_000);
        assert_eq!(
            (o.alarms.as_str(), o.parts.as_str()),
            ("0", "1"),
            "{nc}: {o:?}"
        );
        assert!(o.ticks < 400_000, "{nc}: ended, not timed out");
    }
}

#[test]
fn a_typing_error_stops_the_program_with_a_ps_alarm_naming_its_block() {
    for nc in ["typo-go1.nc", "typo-number.nc"] {
        let o = run_program(nc, 50_000);
        assert_eq!(o.alarms, "1", "{nc}: {o:?}");
        assert_eq!(o.block, "30", "{nc}: the alarm names N30");
        assert_eq!(o.parts, "0");
    }
}

#[test]
fn the_sample_job_runs_to_m30_with_the_sample_s_own_settings() {
    let o = run_on_sample(
        &here().join("../projects/lathe-988ta.nc"),
        Setup::Sample,
        400_000,
    );
    assert_eq!((o.alarms.as_str(), o.parts.as_str()), ("0", "1"), "{o:?}");
}

#[test]
fn with_the_electric_tool_post_the_turret_model_answers_every_t_code() {
    for nc in [
        "haas-bushing-inch.nc",
        "gsk-flange.nc",
        "subprogram-grooves.nc",
        "fanuc-flange-g72.nc",
        "gsk-taper-g90.nc",
    ] {
        let o = run_on_sample(
            &here().join("nc").join(nc),
            Setup::Fanuc { turret: true },
            400_000,
        );
        assert_eq!(
            (o.alarms.as_str(), o.parts.as_str()),
            ("0", "1"),
            "{nc}: {o:?}"
        );
    }
}

#[test]
fn a_station_the_turret_does_not_have_ends_in_the_ladder_s_own_alarm() {
    // The shaft program calls T05 on a 4-station turret: the ladder's T-code check raises
    // A0000.2, PLC alarm 1003, and the program goes no further.
    let o = run_on_sample(
        &here().join("nc").join("fanuc-0i-shaft.nc"),
        Setup::Fanuc { turret: true },
        400_000,
    );
    assert_eq!((o.alarms.as_str(), o.parts.as_str()), ("1", "0"), "{o:?}");
    assert_eq!(o.plc_alarm, 1, "A0000.2 (1003) is on: {o:?}");
}

#[test]
fn the_cell_dispatcher_waits_half_an_hour_for_an_idle_plc_then_runs_the_job_it_is_given() {
    // The sample ladder leaves G214 alone: the dispatcher says it is ready (#1100, F214.0)
    // and waits in WHILE, one pass per exchange, without an alarm.
    let mut m = start_on_sample(
        &here().join("nc").join("macro-cell-dispatcher.nc"),
        Setup::Fanuc { turret: false },
    );
    let half_hour = 30 * 60 * 1000 / ladder_engine::vm::TICK_MS;
    let o = run_until_end(&mut m, half_hour);
    assert_eq!(o.ticks, half_hour, "still waiting: {o:?}");
    assert_eq!(
        (value(&m, "cnc.run").as_str(), o.alarms.as_str()),
        ("RUN", "0")
    );
    assert_eq!(m.plc().read(a("F0214.0"), 1), 1, "#1100: ready");
    // A cell controller asks for job 2 through G214.1 (#1001): the CNC takes #1100 back,
    // runs O2002 with #1101 on, counts the job and waits again once the request drops.
    m.plc_mut().write(a("G0214.1"), 1, 1);
    m.tick();
    m.tick();
    assert_eq!(m.plc().read(a("F0214.0"), 1), 0);
    assert_eq!(m.plc().read(a("F0214.1"), 1), 1, "#1101: a job runs");
    let mut ticks = 0;
    while value(&m, "cnc.macro.510") != "1" && ticks < 20_000 {
        m.tick();
        ticks += 1;
    }
    assert_eq!(value(&m, "cnc.macro.510"), "1", "job counted");
    assert_eq!(value(&m, "cnc.alarms"), "0");
    m.plc_mut().write(a("G0214.1"), 1, 0);
    for _ in 0..10 {
        m.tick();
    }
    assert_eq!(m.plc().read(a("F0214.0"), 1), 1, "ready again");
    assert_eq!(m.plc().read(a("F0214.1"), 1), 0);
    assert_eq!(value(&m, "cnc.run"), "RUN");
}
