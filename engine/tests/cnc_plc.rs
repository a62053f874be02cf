//! The PLC and the simulated CNC together in a [`Machine`]: the order of scan and exchange,
//! forces, a halted PLC, and power-cycle (docs/cnc.md, "Tick and exchange", "power-cycle").

use ladder_engine::address::Address;
use ladder_engine::cnc::command::{CncCommand, CncKey};
use ladder_engine::il;
use ladder_engine::machine::{Machine, MachineCommand, Probe};

/// FIN := MF, the mode from X0, ST from X1.0; healthy signals; a JMPB loop while X3.0 = 1.
const LADDER: &str = "LEVEL2\nNETWORK\nLD F0007.0\nOUT G0004.3\nNETWORK\nLDI R0999.7\nMOVN 1 X0000 G0043\nMOVN 1 255 G0114\nMOVN 1 255 G0116\nMOVN 1 10 G0012\nMOVN 1 10 G0030\nOUT G0029.6\nOUT G0008.0\nOUT G0008.1\nOUT G0008.3\nOUT G0008.4\nOUT G0008.5\nNETWORK\nLD X0001.0\nOUT G0007.2\nNETWORK\nLBL L0001\nNETWORK\nLD X0003.0\nJMPB L0001\n";

fn a(t: &str) -> Address {
    Address::parse(t).unwrap()
}

fn machine() -> Machine {
    let p = il::import(LADDER).project.expect("draws");
    let mut m = Machine::new(&p, true).unwrap();
    m.tick();
    m
}

fn cnc(m: &mut Machine, c: CncCommand) {
    m.apply(&MachineCommand::Cnc(c)).unwrap();
}

fn value(m: &Machine, key: &str) -> String {
    let k = CncKey::parse(key, ladder_engine::ProfileId::Gsk988ta).unwrap();
    m.read(&Probe::Cnc(k)).unwrap().to_string()
}

fn start(m: &mut Machine) {
    m.plc_mut().write(a("X1.0"), 1, 1);
    m.tick();
    m.plc_mut().write(a("X1.0"), 1, 0);
    m.tick();
}

#[test]
fn the_ladder_answers_an_f_signal_in_the_tick_after_the_exchange_that_wrote_it() {
    let mut m = machine();
    cnc(&mut m, CncCommand::Mdi("M03;M04".into()));
    start(&mut m); // tick n: N1 starts, MF is 1 after exchange n
    assert!(m.plc().read_bit(a("F7.0")));
    assert!(
        !m.plc().read_bit(a("G4.3")),
        "the ladder has not seen MF yet"
    );
    m.tick(); // n+1: the ladder reads MF, writes FIN; the exchange sees FIN: MF drops
    assert!(m.plc().read_bit(a("G4.3")));
    assert!(!m.plc().read_bit(a("F7.0")));
    assert_eq!(
        m.plc().read(a("F10"), 4),
        3,
        "the code stays until FIN is 0 again"
    );
    m.tick(); // n+2: FIN 0, the block ends
    assert!(!m.plc().read_bit(a("G4.3")));
    assert_eq!(m.plc().read(a("F10"), 4), 0);
    m.tick(); // n+3: the next block
    assert_eq!(m.plc().read(a("F10"), 4), 4);
}

#[test]
fn forces_win_over_the_cnc_and_unforced_bits_come_back() {
    let mut m = machine();
    m.apply(&MachineCommand::Force(a("F0.5"), 1)).unwrap();
    m.tick();
    assert!(m.plc().read_bit(a("F0.5")), "STL forced although IDLE");
    m.apply(&MachineCommand::Unforce(a("F0.5"))).unwrap();
    m.tick();
    assert!(!m.plc().read_bit(a("F0.5")), "the CNC writes it again");
    // A bit the CNC does not own keeps what the user set.
    m.apply(&MachineCommand::Write(
        ladder_engine::machine::Target {
            address: a("F64"),
            bytes: 1,
            explicit: false,
        },
        7,
    ))
    .unwrap();
    m.tick();
    assert_eq!(m.plc().read(a("F64"), 1), 7);
}

#[test]
fn the_cnc_keeps_running_while_the_plc_is_halted() {
    let mut m = machine();
    cnc(&mut m, CncCommand::Mdi("G04 P1000".into()));
    start(&mut m);
    assert_eq!(value(&m, "cnc.run"), "RUN");
    m.plc_mut().write(a("X3.0"), 1, 1);
    m.tick();
    assert!(m.plc().halt().is_some());
    m.run_ticks(130, |_| {});
    assert_eq!(
        value(&m, "cnc.run"),
        "IDLE",
        "the dwell ended on the frozen G"
    );
}

#[test]
fn power_cycle_restarts_the_cnc_and_keeps_positions_programs_and_kept_data() {
    let mut m = machine();
    cnc(
        &mut m,
        CncCommand::Macro {
            number: 100,
            value: Some(1.0),
        },
    );
    cnc(
        &mut m,
        CncCommand::Macro {
            number: 500,
            value: Some(2.0),
        },
    );
    cnc(
        &mut m,
        CncCommand::Position {
            axis: 1,
            value: 12_000,
        },
    );
    cnc(&mut m, CncCommand::Program("O0007;G04 P5000".into()));
    cnc(&mut m, CncCommand::Alarm(3));
    m.plc_mut().write(a("X0.0"), 1, 1);
    m.tick();
    assert_eq!(value(&m, "cnc.alarms"), "1");
    // A parameter written by the PLC's WINDR 18 is pending until power-cycle: here the
    // same path through the window of the CNC itself.
    {
        use ladder_engine::vm::cnc::Cnc;
        let mut b = [18, 0, 1, 8130, 0, 0, 3];
        m.cnc_mut().unwrap().window(&mut b);
        assert_eq!(b[1], 0);
    }
    assert_eq!(value(&m, "cnc.param.8130"), "2");
    m.apply(&MachineCommand::PowerCycle).unwrap();
    assert_eq!(
        m.plc().read(a("F3"), 1),
        0,
        "F all 0 until the next exchange"
    );
    assert_eq!(value(&m, "cnc.alarms"), "0");
    assert_eq!(value(&m, "cnc.macro.100"), "vacant");
    assert_eq!(value(&m, "cnc.macro.500"), "2");
    assert_eq!(value(&m, "cnc.pos.Z"), "12.000");
    assert_eq!(value(&m, "cnc.param.8130"), "3");
    assert_eq!(value(&m, "cnc.prog"), "7");
    assert_eq!(value(&m, "cnc.mode"), "MDI");
    m.tick();
    assert!(
        m.plc().read_bit(a("F3.5")),
        "MEM again from the ladder's G43"
    );
    assert_eq!(value(&m, "cnc.run"), "IDLE");
}

#[test]
fn a_snapshot_copies_memory_forces_and_the_cnc_screen() {
    let mut m = machine();
    cnc(&mut m, CncCommand::Mdi("M03 S700".into()));
    start(&mut m);
    m.apply(&MachineCommand::Force(a("Y0.0"), 1)).unwrap();
    let s = m.snapshot();
    assert_eq!(s.ticks, m.plc().ticks());
    assert_eq!(s.memory.len(), m.plc().image().len());
    assert_eq!(s.forces.len(), 1);
    let c = s.cnc.expect("a CNC");
    assert_eq!(c.run, ladder_engine::cnc::RunState::Run);
    assert!(c.mst.mf && c.mst.sf);
    assert_eq!((c.mst.m, c.mst.s, c.spindle), (3, 700, 700));
    assert!(c.mdi);
    assert_eq!(c.line, Some(1));
}

#[test]
fn the_screen_keeps_the_codes_sent_and_counts_each_strobe_however_short() {
    let mut m = machine();
    cnc(&mut m, CncCommand::Mdi("M03 S700\nM08\nM09".into()));
    start(&mut m);
    for _ in 0..40 {
        m.tick();
    }
    let c = m.snapshot().cnc.unwrap();
    assert_eq!(
        c.run,
        ladder_engine::cnc::RunState::Idle,
        "the MDI program ended"
    );
    assert_eq!(c.mst.m, 0, "the code signals fell with their strobes");
    assert_eq!(
        c.mst.last,
        [9, 700, 0],
        "the codes in effect stay on the screen"
    );
    // MF three times, SF once, no TF; FIN answered each of the three blocks.
    assert_eq!(c.mst.strobes, [3, 1, 0, 3]);
    // The MDI run ended: its line is of the MDI buffer, not of the program.
    assert!(c.line_in_mdi && !c.mdi);
    m.apply(&MachineCommand::PowerCycle).unwrap();
    assert_eq!(m.snapshot().cnc.unwrap().mst.strobes, [0; 4]);
}
