//! Part programs in the styles shops write (tests/nc: FANUC 0i two-block cycles, FS15/Haas
//! one-block cycles in inch, GSK, drilling cycles, subprograms) run on the sample lathe as an
//! engineer would run them: reference return, AUTO, cycle start (again after M00/M01), no
//! electric tool post (K0000.1 = 0), #3401 = 0 and #3402 bit 4 = 0 as on a FANUC lathe. Each
//! must reach M30 without an alarm; a program with a typing error stops with a P/S alarm
//! naming its block.

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
    m.plc.write(a(key), 1, 1);
    m.tick();
    m.plc.write(a(key), 1, 0);
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
}

/// Sets the sample lathe up as the shop runs it and runs `nc` until it ends, stops on an
/// alarm, or `limit` scans pass.
fn run_program(nc: &str, limit: u64) -> Outcome {
    run_on_sample(&here().join("nc").join(nc), true, limit)
}

/// Runs the program at `path` on the sample lathe; `fanuc` sets #3401 = 0, #3402 bit 4 = 0 and
/// K0000.1 = 0 first, otherwise the sample's own settings stay.
fn run_on_sample(path: &std::path::Path, fanuc: bool, limit: u64) -> Outcome {
    let nc = path.display().to_string();
    let project = file::load(&here().join("../projects/lathe-988ta.ldp")).expect("the sample");
    let mut m = Machine::new(&project, true).expect("builds");
    // A healthy machine: E-stop released, limits closed, spindle ready, dogs off, overrides.
    for bit in [
        "X0000.5", "X0001.5", "X0001.0", "X0001.1", "X0001.2", "X0001.3", "X0001.6",
    ] {
        m.plc.write(a(bit), 1, 1);
    }
    m.plc.write(a("X0005"), 1, 15);
    m.plc.write(a("X0006"), 1, 5);
    m.plc.write(a("X0007"), 1, 3);
    if fanuc {
        m.plc.write(a("K0000.1"), 1, 0);
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
    // Reference return on the dogs.
    press(&mut m, "X0002.5");
    m.plc.write(a("X0004.0"), 1, 1);
    m.plc.write(a("X0004.2"), 1, 1);
    m.tick();
    m.plc.write(a("X0004.0"), 1, 0);
    m.plc.write(a("X0004.2"), 1, 0);
    m.run_ticks(20, |_| {});
    m.plc.write(a("X0007"), 1, 0);
    m.run_ticks(10, |_| {});
    m.plc.write(a("X0007"), 1, 3);
    m.run_ticks(3, |_| {});
    assert_eq!(m.plc.read(a("F0120"), 1), 3, "{nc}: reference points set");
    press(&mut m, "X0002.1");
    press(&mut m, "X0002.6");
    let mut ticks = 0;
    while ticks < limit {
        m.tick();
        ticks += 1;
        let run = value(&m, "cnc.run");
        if value(&m, "cnc.alarms") != "0" || run == "IDLE" {
            break;
        }
        if run == "STOP" {
            // M00 / M01: the operator presses cycle start again.
            press(&mut m, "X0002.6");
        }
    }
    Outcome {
        parts: value(&m, "cnc.param.6711"),
        alarms: value(&m, "cnc.alarms"),
        block: value(&m, "cnc.block"),
        ticks,
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
    let o = run_on_sample(&here().join("../projects/lathe-988ta.nc"), false, 400_000);
    assert_eq!((o.alarms.as_str(), o.parts.as_str()), ("0", "1"), "{o:?}");
}
