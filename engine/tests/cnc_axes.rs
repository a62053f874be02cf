//! PLC axis control of the simulated CNC (docs/cnc.md, "PLC axis control"), through the
//! group signals and through the AXCTL instruction of a running machine.

use crate::common::Rig;
use ladder_engine::address::Address;
use ladder_engine::cnc::command::CncCommand;
use ladder_engine::il;
use ladder_engine::machine::{Machine, MachineCommand};

/// A rig with three axes, Y in group A and claimed by the PLC.
fn rig() -> Rig {
    let mut r = Rig::new();
    r.cmd(&["param", "8130", "3"]);
    r.cmd(&["param", "8010", "3", "1"]);
    r.set(136, 2, true);
    r.x();
    r
}

/// A machine running `il` with three axes, Y in group A (the PLC claims it in the ladder).
fn y_machine(il: &str) -> Machine {
    let p = il::import(il).project.expect("draws");
    let mut m = Machine::new(&p, true).unwrap();
    for c in [
        CncCommand::Param {
            number: 8130,
            selector: None,
            value: 3,
        },
        CncCommand::Param {
            number: 8010,
            selector: Some(3),
            value: 1,
        },
    ] {
        m.apply(&MachineCommand::Cnc(c)).unwrap();
    }
    m
}

/// Issues a command to group A: EC, EIF, EID, and EBUF toggled.
fn issue(r: &mut Rig, ec: u8, eif: u16, eid: i32) {
    r.g[141] = (r.g[141] & 0x80) | ec;
    r.g[142..144].copy_from_slice(&eif.to_le_bytes());
    r.g[144..148].copy_from_slice(&eid.to_le_bytes());
    r.g[140] ^= 0x80;
}

#[test]
fn the_manual_example_moves_y_10_mm_and_axctl_sees_fin_from_tick_t_plus_125() {
    let mut m = y_machine(
        "LEVEL2\nNETWORK\nLDI R0999.7\nMOVN 1 255 G0114\nMOVN 1 255 G0116\nOUT G0008.0\nOUT G0008.1\nOUT G0008.3\nOUT G0008.4\nOUT G0008.5\nOUT G0136.2\nMOVN 1 10 G0012\nNETWORK\nLD X0000.0\nAXCTL 1 1 600 10000 R0000.1 R0001.0 R0001.1\n",
    );
    m.tick();
    let a = |t: &str| Address::parse(t).unwrap();
    m.plc_mut().write(a("X0.0"), 1, 1);
    m.tick(); // tick t
    let t = m.plc().ticks();
    assert!(m.plc().read_bit(a("F140.7")), "EBSYA at t");
    assert!(m.plc().read_bit(a("F140.4")), "EGENA at t");
    assert!(m.plc().read_bit(a("F129.7")), "*EAXSL at t");
    assert_eq!(m.cnc().unwrap().axes()[2].m, 80);
    while m.plc().ticks() < t + 124 {
        m.tick();
        assert!(!m.plc().read_bit(a("R1.0")), "no FIN before t+125");
    }
    assert_eq!(m.cnc().unwrap().axes()[2].m, 10_000, "at t+124");
    m.tick();
    assert!(m.plc().read_bit(a("R1.0")), "FIN from tick t+125");
    assert!(!m.plc().read_bit(a("R1.1")));
    assert!(!m.plc().read_bit(a("F129.7")));
}

#[test]
fn without_feed_override_the_axis_never_moves() {
    let mut r = rig();
    r.g[12] = 0;
    issue(&mut r, 1, 600, 10_000);
    r.xs(50);
    assert_eq!(r.m(2), 0);
    assert!(r.fb(129, 5), "EOV0");
    assert!(
        r.fb(129, 7) && !r.fb(112, 2),
        "*EAXSL, EADEN3 = 0 while unfinished"
    );
}

#[test]
fn buffered_commands_run_back_to_back_as_the_manual_example_says() {
    let mut r = rig();
    issue(&mut r, 1, 600, 2000);
    r.x();
    let t = r.n;
    assert!(r.fb(140, 7));
    issue(&mut r, 1, 1200, 1000);
    r.x();
    assert!(!r.fb(140, 7), "read at its own exchange: EBSY follows EBUF");
    issue(&mut r, 0, 0, -3000);
    r.x();
    assert!(r.fb(141, 1), "EABUFA with three held, from t+2");
    issue(&mut r, 4, 0, 100); // a dwell, tick t+3: waits for a free slot
    let mut at = Vec::new();
    let mut last = r.m(2);
    let mut read = None;
    for _ in 0..40 {
        r.x();
        if r.m(2) != last {
            at.push((r.n - t, r.m(2)));
            last = r.m(2);
        }
        if read.is_none() && r.fb(140, 7) == (r.g[140] >> 7 == 1) {
            read = Some(r.n - t);
        }
    }
    assert_eq!(r.m(2), 0, "+2 +1 −3 mm");
    let first = |from: i64| at.iter().find(|(k, _)| *k >= from as u64).map(|x| x.0);
    assert_eq!(at.iter().find(|(_, p)| *p == 2000).map(|x| x.0), Some(24));
    assert_eq!(first(25), Some(25));
    assert_eq!(at.iter().find(|(_, p)| *p == 3000).map(|x| x.0), Some(31));
    assert_eq!(at.last().map(|x| x.0), Some(35));
    assert_eq!(read, Some(25), "the fourth toggle is read at t+25");
}

#[test]
fn a_rapid_uses_1420_and_the_rapid_override() {
    let mut r = rig();
    r.g[14] = 1; // 50 %
    issue(&mut r, 0, 0, 10_000);
    r.x();
    assert_eq!(r.m(2), 400);
    assert!(r.fb(2, 1), "RPDO");
    r.cmd(&["param", "8002", "1"]); // RPD: EIF
    issue(&mut r, 0x20, 1200, 0); // held behind; G53 to 0 at EIF × 50 %
    r.until(100, |r| r.m(2) == 10_000);
    r.x();
    assert_eq!(r.m(2), 10_000 - 80);
}

#[test]
fn errors_end_the_command_and_set_eial() {
    // No axis in the group.
    let mut r = rig();
    r.set(136, 2, false);
    r.x();
    issue(&mut r, 1, 600, 1000);
    r.x();
    assert_eq!(r.v("cnc.alarm.130"), "1");
    assert!(r.fb(140, 2), "EIALA");
    let st = ladder_engine::vm::cnc::Cnc::axis_status(&r.cnc, 1, r.g[140] >> 7 == 1);
    assert!(st.ended && st.error);
    // An unknown command.
    let mut r = rig();
    issue(&mut r, 0x33, 0, 0);
    r.x();
    assert_eq!(r.v("cnc.alarm.130"), "1");
    // 08h before the reference point: 0090, EIAL unchanged.
    let mut r = rig();
    issue(&mut r, 0x08, 0, 0);
    r.x();
    assert_eq!(r.v("cnc.alarm.90"), "1");
    assert!(!r.fb(140, 2));
    // EAX changes while *EAXSL = 1: 0139 and EIAL.
    let mut r = rig();
    issue(&mut r, 1, 600, 100_000);
    r.xs(3);
    r.set(136, 2, false);
    r.x();
    assert_eq!(r.v("cnc.alarm.139"), "1");
    assert!(r.fb(140, 2));
    // ECLR clears EIAL once the alarm is reset.
    r.set(140, 6, true);
    r.x();
    assert!(r.fb(140, 2), "the alarm is still active");
    r.cmd(&["reset"]);
    r.x();
    assert!(!r.fb(140, 2), "EIAL outlives the reset until ECLR");
}

#[test]
fn eclr_ends_a_continuous_feed_normally_and_a_toggle_changes_its_speed() {
    let mut r = rig();
    issue(&mut r, 6, 600, 0);
    r.xs(10);
    assert_eq!(r.m(2), 800);
    issue(&mut r, 6, 1200, i32::MIN); // same EC: new speed and direction
    r.x();
    assert!(r.m(2) < 800);
    r.xs(3);
    r.set(140, 6, true);
    r.x();
    let p = r.m(2);
    r.x();
    assert_eq!(r.m(2), p, "stopped at once");
    let st = ladder_engine::vm::cnc::Cnc::axis_status(&r.cnc, 1, r.g[140] >> 7 == 1);
    assert!(st.ended && !st.error, "a normal end");
    assert!(!r.fb(129, 7));
}

#[test]
fn an_aux_function_waits_for_efin_and_a_dwell_counts_its_exchanges() {
    let mut r = rig();
    issue(&mut r, 0x12, 0, 0x1234);
    r.x();
    assert!(r.fb(141, 0) && r.fb(140, 3), "EMFA, EDENA");
    assert_eq!(r.fv(142, 2), 0x1234);
    r.xs(3);
    r.set(140, 0, true);
    r.x();
    assert!(!r.fb(141, 0) && r.fv(142, 2) == 0);
    r.set(140, 0, false);
    // 04h: 100 ms = 13 exchanges, the first the one it starts in.
    issue(&mut r, 4, 0, 100);
    r.x();
    let s = r.n;
    let end = r.until(40, |r| !r.fb(129, 7));
    assert_eq!(end, s + 12);
    // ESTP pauses a dwell.
    issue(&mut r, 4, 0, 80);
    r.set(140, 5, true);
    r.xs(30);
    assert!(r.fb(129, 7));
    r.set(140, 5, false);
    r.xs(10);
    assert!(!r.fb(129, 7));
}

#[test]
fn a_speed_command_turns_without_moving_and_e_stop_ends_it_in_error() {
    let mut r = rig();
    issue(&mut r, 0x10, 500, 0);
    r.xs(3);
    assert!(r.fb(140, 4) && !r.fb(140, 0), "EGEN, not EINP");
    assert!(!r.fb(112, 2), "EADEN3 = 0");
    assert_eq!(r.m(2), 0);
    r.set(8, 4, false);
    r.x();
    let st = ladder_engine::vm::cnc::Cnc::axis_status(&r.cnc, 1, r.g[140] >> 7 == 1);
    assert!(st.ended && st.error);
    assert!(!r.fb(140, 2), "E-stop: no EIAL");
}

#[test]
fn a_plc_claim_of_an_axis_in_a_program_motion_raises_0139() {
    let mut r = Rig::new();
    r.mode(ladder_engine::cnc::Mode::Mem);
    r.x();
    r.program("O0001;G01 W10 F600");
    r.start();
    r.xs(2);
    r.set(136, 1, true);
    r.x();
    assert_eq!(r.v("cnc.alarm.139"), "1");
    assert_eq!(r.v("cnc.run"), "STOP");
    // A block that moves a claimed axis.
    let mut r = Rig::new();
    r.mode(ladder_engine::cnc::Mode::Mem);
    r.set(136, 1, true);
    r.x();
    r.program("O0001;N7 G00 W1");
    r.start();
    assert_eq!(r.v("cnc.alarm.139"), "1");
    assert_eq!(r.v("cnc.block"), "7");
}

#[test]
fn eaxsl_stays_1_while_a_command_waits_and_esbk_holds_the_next_one() {
    let mut r = rig();
    issue(&mut r, 1, 600, 800); // 10 exchanges
    r.x();
    r.set(140, 3, true); // ESBK: block stop
    issue(&mut r, 1, 600, 800);
    r.x();
    r.until(20, |r| r.m(2) == 800);
    r.xs(5);
    assert_eq!(r.m(2), 800, "ESBK = 1: the held command does not start");
    assert!(r.fb(129, 7), "*EAXSL stays 1 while a command is held");
    assert!(r.fb(182, 2), "EACNT3");
    r.set(140, 3, false);
    r.x();
    assert_eq!(r.m(2), 880, "released: it starts at once");
}

#[test]
fn emsbk_lets_the_next_command_start_despite_esbk() {
    let mut r = rig();
    r.set(140, 3, true);
    r.set(141, 7, true); // EMSBK with the first command
    issue(&mut r, 1, 600, 80);
    r.x();
    r.set(141, 7, false);
    issue(&mut r, 1, 600, 80);
    r.x();
    // ESBK = 1 held the first one back too: nothing executes, the oldest waits.
    assert_eq!(r.m(2), 0);
    r.set(140, 3, false);
    r.x(); // the first starts and ends (0.08 mm in one exchange)
    assert_eq!(r.m(2), 80);
    r.set(140, 3, true);
    r.x();
    assert_eq!(
        r.m(2),
        160,
        "the command before had EMSBK = 1: the next starts"
    );
}

#[test]
fn a_07h_return_on_an_axis_without_reference_point_uses_the_dog_at_1424() {
    let mut r = rig();
    r.cmd(&["param", "1424", "3", "3000"]);
    r.cmd(&["param", "1240", "3", "5000"]);
    issue(&mut r, 7, 0, 0);
    r.x();
    assert_eq!(r.m(2), 400, "rapid phase at #1424 = 3000 mm/min");
    r.set(196, 2, false);
    r.x();
    assert_eq!(r.m(2), 416, "FL on the dog");
    r.set(196, 2, true);
    r.x();
    assert_eq!(r.m(2), 5000);
    assert!(r.fb(94, 2) && r.fb(120, 2), "ZP3, ZRF3");
    let st = ladder_engine::vm::cnc::Cnc::axis_status(&r.cnc, 1, r.g[140] >> 7 == 1);
    assert!(st.ended && !st.error);
    // With the reference point known, 08h goes to #1241 and sets ZP2n.
    r.cmd(&["param", "1241", "3", "2000"]);
    issue(&mut r, 8, 0, 0);
    r.until(20, |r| r.m(2) == 2000);
    assert!(r.fb(96, 2));
}

#[test]
fn a_claim_during_a_program_motion_leaves_eial_alone() {
    let mut r = rig();
    r.set(136, 2, false);
    r.mode(ladder_engine::cnc::Mode::Mem);
    r.x();
    r.program("O0001;G01 V10 F600");
    r.start();
    r.xs(2);
    r.set(136, 2, true);
    r.x();
    assert_eq!(r.v("cnc.alarm.139"), "1");
    assert!(!r.fb(140, 2), "EAX 0→1 while *EAXSL = 0: no EIAL");
}

#[test]
fn the_issuing_scan_never_reports_the_previous_command_as_this_ones_end() {
    // AXCTL writes ESBK := 0 on ACT 0→1: a command abandoned earlier does not block the next.
    let mut m = y_machine(
        "LEVEL2\nNETWORK\nLDI R0999.7\nMOVN 1 255 G0114\nMOVN 1 255 G0116\nOUT G0008.4\nOUT G0136.2\nMOVN 1 10 G0012\nNETWORK\nLD X0000.0\nAXCTL 1 1 600 8000 R0000.1 R0001.0 R0001.1\n",
    );
    let a = |t: &str| Address::parse(t).unwrap();
    m.plc_mut().write(a("X0.0"), 1, 1);
    m.tick();
    m.tick();
    m.plc_mut().write(a("X0.0"), 1, 0); // ACT drops before the end: ESBK := 1
    m.tick();
    assert!(m.plc().read_bit(a("G140.3")));
    m.run_ticks(200, |_| {});
    m.plc_mut().write(a("X0.0"), 1, 1);
    m.tick();
    assert!(
        !m.plc().read_bit(a("G140.3")),
        "ESBK withdrawn by the new command"
    );
    assert!(
        !m.plc().read_bit(a("R1.0")),
        "not ended on the issuing scan"
    );
    m.run_ticks(101, |_| {});
    assert!(m.plc().read_bit(a("R1.0")), "the new command ran and ended");
    assert_eq!(m.cnc().unwrap().axes()[2].m, 16_000);
}

#[test]
fn a_plc_return_stopped_by_a_limit_reports_the_direction_it_moved_in() {
    let mut r = rig();
    r.cmd(&["param", "1006", "3", "32"]); // ZMI: Y returns in −
    r.set(116, 2, false); // *−L3
    r.x();
    issue(&mut r, 5, 0, 0);
    r.x();
    assert!(r.fb(140, 6) && !r.fb(140, 5), "EOTNA, not EOTPA");
    assert!(r.fb(140, 2));
    r.set(116, 2, true);
    r.set(140, 6, true);
    r.x();
    assert!(r.fb(140, 6), "ECLR keeps EOTN while 0507 is active");
    r.cmd(&["reset"]);
    r.xs(2);
    assert!(!r.fb(140, 6) && !r.fb(140, 2));
}

#[test]
fn when_one_axis_of_a_plc_move_stops_on_its_limit_the_others_do_not_advance() {
    let mut r = Rig::new();
    r.cmd(&["param", "8130", "3"]);
    r.cmd(&["param", "8010", "1", "1"]);
    r.cmd(&["param", "8010", "3", "1"]);
    // Reference points of X and Y by dog returns at 0 (before the PLC claims them).
    r.home(&[0, 2]);
    r.mode(ladder_engine::cnc::Mode::Mdi);
    r.set(136, 0, true);
    r.set(136, 2, true);
    r.x();
    assert!(r.fb(120, 0) && r.fb(120, 2), "ZRF1, ZRF3");
    r.cmd(&["param", "1320", "3", "500"]);
    issue(&mut r, 1, 600, 10_000);
    r.until(50, |r| r.m(2) == 500);
    assert_eq!(r.v("cnc.alarm.500"), "1");
    let at_stop = r.m(0);
    r.xs(3);
    assert_eq!(r.m(0), at_stop, "X stopped with Y");
    assert!(
        at_stop < 1000,
        "X did not advance in the exchange Y stopped: {at_stop}"
    );
}

#[test]
fn e_stop_drops_commands_held_behind_esbk() {
    let mut r = rig();
    r.set(140, 3, true);
    issue(&mut r, 1, 600, 800);
    r.x();
    assert!(r.fb(129, 7), "held");
    r.set(8, 4, false);
    r.x();
    r.set(8, 4, true);
    r.set(140, 3, false);
    r.xs(20);
    assert_eq!(r.m(2), 0, "the held command was dropped");
    assert!(!r.fb(129, 7));
}

#[test]
fn a_return_to_where_the_axis_already_is_still_sets_zp() {
    let mut r = rig();
    // Y's reference point by a dog return (07h), then a 07h again at the point.
    issue(&mut r, 7, 0, 0);
    r.x();
    r.set(196, 2, false);
    r.x();
    r.set(196, 2, true);
    r.x();
    assert!(r.fb(94, 2));
    r.cmd(&["param", "1240", "3", "0"]);
    issue(&mut r, 4, 0, 0);
    r.x();
    r.cmd(&["position", "Y", "0"]);
    issue(&mut r, 7, 0, 0);
    r.xs(2);
    assert!(r.fb(94, 2), "ZP3 at the point");
}

#[test]
fn a_block_that_names_a_claimed_axis_without_moving_it_runs() {
    let mut r = Rig::new();
    r.mode(ladder_engine::cnc::Mode::Mem);
    r.set(136, 1, true);
    r.x();
    r.program("O0001;N7 G00 W0 M03");
    r.start();
    assert_eq!(r.v("cnc.alarms"), "0", "W0 does not move Z");
    assert!(r.fb(7, 0));
}
