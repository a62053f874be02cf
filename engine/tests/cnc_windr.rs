//! Every WINDR function code of both profiles on the simulated CNC: the data it reads or
//! writes and each end code its table documents (docs/cnc.md, "WINDR").

use crate::common::Rig;
use ladder_engine::ProfileId;
use ladder_engine::address::Address;
use ladder_engine::il;
use ladder_engine::machine::Machine;
use ladder_engine::model::tables::MessageTable;

fn r988() -> Rig {
    let mut r = Rig::new();
    r.x();
    r
}

fn r980() -> Rig {
    let mut r = Rig::with(ProfileId::Gsk980, &MessageTable::default());
    r.x();
    r
}

/// (end code, length, data) of a block.
fn res(b: &[i32], n: usize) -> (i32, i32, Vec<i32>) {
    (b[1], b[2], b[6..6 + n].to_vec())
}

#[test]
fn gsk988ta_system_permission_and_tool_offsets() {
    let mut r = r988();
    assert_eq!(
        res(&r.windr(0, 0, 0, 0, &[]), 5),
        (0, 5, vec![988, 2, 0, 100, 2])
    );
    assert_eq!(res(&r.windr(5, 0, 0, 0, &[]), 1), (0, 1, vec![2]));
    // 14 writes, 13 reads back.
    assert_eq!(r.windr(14, 5, 3, 1, &[-250])[1], 0);
    assert_eq!(res(&r.windr(13, 5, 3, 0, &[]), 1), (0, 1, vec![-250]));
    assert_eq!(r.v("cnc.offset.5.WZ"), "-0.250");
    assert_eq!(r.windr(14, 5, 7, 1, &[4])[1], 0, "7 aliases the tip");
    assert_eq!(r.v("cnc.offset.5.TIP"), "4");
    assert_eq!(r.windr(14, 5, 6, 1, &[10])[1], 6, "tip 0–9");
    assert_eq!(r.windr(14, 5, 3, 2, &[1, 2])[1], 2);
    assert_eq!(r.windr(14, 0, 3, 1, &[1])[1], 3);
    assert_eq!(r.windr(13, 100, 0, 0, &[])[1], 3);
    assert_eq!(r.windr(13, 1, 10, 0, &[])[1], 4);
    let b = r.windr(13, 1, 10, 0, &[77]);
    assert_eq!((b[2], b[6]), (0, 77), "an error leaves the data alone");
    assert_eq!(r.windr(99, 0, 0, 0, &[])[1], 1, "unknown function");
}

#[test]
fn gsk988ta_parameters() {
    let mut r = r988();
    assert_eq!(
        res(&r.windr(17, 1420, -1, 0, &[]), 2),
        (0, 2, vec![6000, 6000])
    );
    assert_eq!(res(&r.windr(17, 1006, 1, 0, &[]), 1), (0, 1, vec![8]));
    assert_eq!(
        res(&r.windr(17, 3741, -1, 0, &[]), 4).1,
        4,
        "spindle -1: 4 slots"
    );
    assert_eq!(r.windr(17, 1234, 0, 0, &[])[1], 3);
    assert_eq!(r.windr(17, 1420, 0, 0, &[])[1], 4);
    assert_eq!(r.windr(17, 3003, 1, 0, &[])[1], 4);
    assert_eq!(r.windr(17, 1420, 3, 0, &[])[1], 4, "only #8130 axes");
    // 18: single, all with one value, all per slot.
    assert_eq!(r.windr(18, 1420, 2, 1, &[3000])[1], 0);
    assert_eq!(r.v("cnc.param.1420.2"), "3000");
    assert_eq!(r.windr(18, 1423, -1, 1, &[900])[1], 0);
    assert_eq!(res(&r.windr(17, 1423, -1, 0, &[]), 2).2, vec![900, 900]);
    assert_eq!(r.windr(18, 1423, -1, 2, &[700, 800])[1], 0);
    assert_eq!(res(&r.windr(17, 1423, -1, 0, &[]), 2).2, vec![700, 800]);
    assert_eq!(r.windr(18, 1423, -1, 3, &[1, 2, 3])[1], 2);
    assert_eq!(
        r.windr(18, 3003, 0, 1, &[256])[1],
        6,
        "a bit parameter is a byte"
    );
    assert_eq!(r.windr(18, 8130, 0, 1, &[9])[1], 6);
    // A power-on parameter waits for power-cycle.
    assert_eq!(r.windr(18, 8130, 0, 1, &[3])[1], 0);
    assert_eq!(res(&r.windr(17, 8130, 0, 0, &[]), 1).2, vec![2]);
    r.cnc.power_cycle();
    assert_eq!(res(&r.windr(17, 8130, 0, 0, &[]), 1).2, vec![3]);
}

#[test]
fn gsk988ta_macro_variables() {
    let mut r = r988();
    assert_eq!(r.windr(21, 100, 0, 0, &[])[1], 6, "vacant");
    assert_eq!(r.windr(22, 100, 0, 2, &[12345, 3])[1], 0);
    assert_eq!(r.v("cnc.macro.100"), "12.345");
    assert_eq!(res(&r.windr(21, 100, 2, 0, &[]), 2), (0, 2, vec![1235, 2]));
    assert_eq!(r.windr(21, 100, 8, 0, &[])[1], 4);
    assert_eq!(r.windr(21, 5, 0, 0, &[])[1], 3, "local");
    assert_eq!(r.windr(21, 300, 0, 0, &[])[1], 3, "no such variable");
    assert_eq!(r.windr(22, 1000, 0, 2, &[1, 0])[1], 8, "read only");
    assert_eq!(r.windr(22, 100, 0, 1, &[1])[1], 2);
    assert_eq!(r.windr(22, 100, 0, 2, &[1, 9])[1], 6);
    assert_eq!(
        r.windr(22, 1105, 0, 2, &[2, 0])[1],
        6,
        "signal bits are 0 or 1"
    );
    assert_eq!(r.windr(22, 1105, 0, 2, &[1, 0])[1], 0);
    r.x();
    assert!(r.fb(214, 5), "#1105 drives F214.5");
    r.g[215] = 0b100;
    r.x();
    assert_eq!(
        res(&r.windr(21, 1010, 0, 0, &[]), 2).2,
        vec![1, 0],
        "#1010 = G215.2"
    );
    assert_eq!(r.windr(22, 999, 0, 2, &[i32::MAX, 0])[1], 0);
    assert_eq!(r.windr(21, 999, 1, 0, &[])[1], 6, "not representable");
}

#[test]
fn gsk988ta_positions_loads_time_and_clock() {
    let mut r = r988();
    r.cmd(&["position", "Z", "12.5"]);
    r.cmd(&["workpiece", "G54", "Z", "2"]);
    assert_eq!(res(&r.windr(28, 0, -1, 0, &[]), 2).2, vec![0, 12_500]);
    assert_eq!(res(&r.windr(27, 0, 2, 0, &[]), 1).2, vec![10_500]);
    assert_eq!(res(&r.windr(77, 0, 2, 0, &[]), 1).2, vec![12_500]);
    assert_eq!(res(&r.windr(78, 0, -1, 0, &[]), 2).2, vec![0, 0]);
    assert_eq!(r.windr(28, 0, 3, 0, &[])[1], 4);
    for f in [34, 79, 83] {
        assert_eq!(res(&r.windr(f, 0, 1, 0, &[]), 1), (0, 1, vec![0]));
        assert_eq!(r.windr(f, 0, -1, 0, &[])[1], 4);
    }
    for f in [80, 84, 153] {
        assert_eq!(res(&r.windr(f, 0, 1, 0, &[]), 1), (0, 1, vec![0]));
        assert_eq!(r.windr(f, 0, 2, 0, &[])[1], 4);
    }
    assert_eq!(r.windr(82, 0, -1, 0, &[])[..3], [82, 0, 0]);
    assert_eq!(
        res(&r.windr(82, 0, 1, 0, &[]), 1),
        (0, 1, vec![0]),
        "unassigned: 0"
    );
    assert_eq!(r.windr(82, 0, 5, 0, &[])[1], 4);
    assert_eq!(res(&r.windr(81, 0, 0, 0, &[]), 3), (0, 3, vec![0, 0, 0]));
    assert_eq!(
        res(&r.windr(151, 0, 0, 0, &[]), 6).2,
        vec![2026, 1, 1, 0, 0, 0]
    );
    r.cmd(&["clock", "2026-12-31T23:59:58"]);
    r.xs(250);
    assert_eq!(
        res(&r.windr(151, 0, 0, 0, &[]), 6).2,
        vec![2027, 1, 1, 0, 0, 0]
    );
}

#[test]
fn cutting_time_counts_exchanges_with_cutting_feed() {
    let mut r = r988();
    r.mode(ladder_engine::cnc::Mode::Mdi);
    r.cmd(&["mdi", "G01 W-100 F600"]);
    r.start();
    r.xs(250 * 5);
    let b = r.windr(81, 0, 0, 0, &[]);
    assert_eq!(b[6..9], [0, 0, 10], "1250 exchanges of 8 ms");
}

#[test]
fn gsk980_codes() {
    let mut r = r980();
    assert_eq!(res(&r.windr(0, 0, 0, 0, &[]), 5).2, vec![980, 1, 0, 100, 2]);
    // Offsets 0–32; X a radius when No.4 bit 4 = 1.
    assert_eq!(r.windr(14, 0, 1, 1, &[1000])[1], 0);
    assert_eq!(res(&r.windr(13, 0, 1, 0, &[]), 1).2, vec![1000]);
    assert_eq!(r.windr(18, 4, 0, 1, &[16])[1], 0);
    assert_eq!(res(&r.windr(13, 0, 1, 0, &[]), 1).2, vec![500]);
    assert_eq!(r.windr(13, 33, 1, 0, &[])[1], 3);
    assert_eq!(r.windr(13, 1, 6, 0, &[])[1], 4);
    assert_eq!(r.windr(13, 1, 200, 0, &[])[1], 4);
    assert_eq!(r.windr(14, 1, 100, 1, &[12])[1], 6);
    assert_eq!(r.windr(14, 1, 1, 2, &[1, 1])[1], 2);
    // Workpiece offsets.
    assert_eq!(r.windr(16, 1, -1, 5, &[1, 2, 3, 4, 5])[1], 0);
    assert_eq!(res(&r.windr(15, 1, -1, 0, &[]), 5).2, vec![1, 2, 3, 4, 5]);
    assert_eq!(r.windr(16, 1, -1, 1, &[9])[1], 2);
    assert_eq!(r.windr(15, 7, 1, 0, &[])[1], 3);
    assert_eq!(r.windr(15, 1, 6, 0, &[])[1], 4);
    // Parameters 1–254.
    assert_eq!(r.windr(18, 254, 0, 1, &[-7])[1], 0);
    assert_eq!(res(&r.windr(17, 254, 0, 0, &[]), 1).2, vec![-7]);
    assert_eq!(r.windr(17, 255, 0, 0, &[])[1], 3);
    assert_eq!(r.windr(17, 1, 1, 0, &[])[1], 4);
    assert_eq!(r.windr(18, 1, -1, 1, &[0])[1], 4);
    // Alarms, program, sequence number, speed, modal data, diagnosis, spindle, status.
    assert_eq!(res(&r.windr(23, 0, 0, 0, &[]), 0).1, 0);
    assert_eq!(r.windr(24, 0, 0, 0, &[])[1], 6, "no program loaded");
    assert_eq!(r.windr(25, 0, 0, 0, &[])[1], 5);
    r.mode(ladder_engine::cnc::Mode::Mem);
    r.x();
    r.program("O0012;N30 G01 W-1 F600;N40 M98 P13;O0013;N50 M99");
    r.start();
    assert_eq!(res(&r.windr(24, 0, 0, 0, &[]), 2).2, vec![12, 12]);
    assert_eq!(res(&r.windr(25, 0, 0, 0, &[]), 1).2, vec![30]);
    assert_eq!(res(&r.windr(26, 0, 0, 0, &[]), 1).2, vec![600]);
    assert_eq!(res(&r.windr(75, 0, 2, 0, &[]), 1).2, vec![-1000 + 80]);
    assert_eq!(
        res(&r.windr(74, 0, -1, 0, &[]), 5).2,
        vec![-1, -82, 0, 0, 0],
        "G54 holds 1, 2"
    );
    assert_eq!(r.windr(29, 0, 1, 0, &[])[1], 5);
    assert_eq!(r.windr(29, 0, 9, 0, &[])[1], 4);
    assert_eq!(
        res(&r.windr(32, 0, 0, 0, &[]), 10).2,
        vec![1, 97, 98, 21, 40, 67, 54, 18, 15, 113]
    );
    assert_eq!(r.windr(33, 1, 0, 0, &[])[1], 3);
    assert_eq!(res(&r.windr(76, 0, 0, 0, &[]), 6).2, vec![1, 3, 1, 0, 0, 0]);
    r.set(8, 4, false);
    r.x();
    assert_eq!(res(&r.windr(23, 0, 0, 0, &[]), 1).2, vec![950]);
    assert_eq!(res(&r.windr(76, 0, 0, 0, &[]), 6).2, vec![1, 1, 0, 0, 1, 1]);
    assert_eq!(res(&r.windr(50, 0, 0, 0, &[]), 1).2, vec![0]);
    assert_eq!(res(&r.windr(151, 0, 0, 0, &[]), 3).2, vec![2026, 1, 1]);
    assert_eq!(res(&r.windr(151, 1, 0, 0, &[]), 3).2, vec![0, 0, 0]);
    assert_eq!(res(&r.windr(151, -1, 0, 0, &[]), 6).1, 6);
    assert_eq!(r.windr(151, 2, 0, 0, &[])[1], 3);
    // 988TA-only codes do not exist here.
    assert_eq!(r.windr(5, 0, 0, 0, &[])[1], 1);
    // Macro variables as on the 988TA.
    assert_eq!(r.windr(22, 500, 0, 2, &[-5, 1])[1], 0);
    assert_eq!(res(&r.windr(21, 500, 1, 0, &[]), 2).2, vec![-5, 1]);
}

#[test]
fn a_low_speed_write_completes_on_the_second_scan_and_needs_act_back_at_0() {
    // WINDR 14 (write tool offset 1, type Z = 2) from D0 when X0.0 is 1.
    let p = il::import("LEVEL2\nNETWORK\nLD X0000.0\nWINDR D0000 R0001.0\n")
        .project
        .expect("draws");
    let mut m = Machine::new(&p, true).unwrap();
    let a = |t: &str| Address::parse(t).unwrap();
    for (d, v) in [("D0", 14), ("D2", 1), ("D3", 1), ("D4", 2), ("D6", 1500)] {
        m.plc_mut().write(a(d), 4, v);
    }
    m.plc_mut().write(a("X0.0"), 1, 1);
    m.tick();
    assert!(!m.plc().read_bit(a("R1.0")), "first scan latches");
    assert_eq!(m.cnc().unwrap().status().absolute[1], 0);
    let off = |m: &Machine| {
        m.cnc()
            .unwrap()
            .value(&ladder_engine::cnc::command::CncKey::Offset(
                1,
                ladder_engine::cnc::data::OffsetType::Geometry(1),
            ))
            .unwrap()
            .to_string()
    };
    assert_eq!(off(&m), "0.000");
    m.tick();
    assert!(m.plc().read_bit(a("R1.0")), "complete at the second scan");
    assert_eq!(off(&m), "1.500");
    assert_eq!(m.plc().read(a("D1"), 4), 0, "end code 0");
    m.plc_mut().write(a("D6"), 4, 2500);
    m.tick();
    m.tick();
    assert_eq!(off(&m), "1.500", "ACT held: not executed again");
    m.plc_mut().write(a("X0.0"), 1, 0);
    m.tick();
    m.plc_mut().write(a("X0.0"), 1, 1);
    m.tick();
    m.tick();
    assert_eq!(off(&m), "2.500", "re-armed by ACT = 0");
    // A write with an error also takes two scans.
    m.plc_mut().write(a("X0.0"), 1, 0);
    m.tick();
    m.plc_mut().write(a("D3"), 4, 100);
    m.plc_mut().write(a("X0.0"), 1, 1);
    m.tick();
    assert!(!m.plc().read_bit(a("R1.0")));
    m.tick();
    assert!(m.plc().read_bit(a("R1.0")));
    assert_eq!(m.plc().read(a("D1"), 4), 3);
}

#[test]
fn remaining_end_codes_and_980_positions() {
    let mut r = r988();
    assert_eq!(r.windr(18, 1234, 0, 1, &[0])[1], 3);
    assert_eq!(r.windr(18, 1420, 0, 1, &[0])[1], 4);
    assert_eq!(r.windr(18, 1420, 1, 1, &[240_001])[1], 6);
    let mut short = vec![22, 0, 2, 100, 0, 0, 5];
    ladder_engine::vm::cnc::Cnc::window(&mut r.cnc, &mut short);
    assert_eq!(short[1], 2, "the data runs past the end of D");
    let mut r = r980();
    r.cmd(&["position", "X", "4"]);
    assert_eq!(
        res(&r.windr(28, 0, -1, 0, &[]), 5).2,
        vec![4000, 0, 0, 0, 0]
    );
    assert_eq!(res(&r.windr(27, 0, 1, 0, &[]), 1).2, vec![4000]);
    assert_eq!(
        res(&r.windr(28, 0, 5, 0, &[]), 1).2,
        vec![0],
        "an unused axis reads 0"
    );
    assert_eq!(r.windr(28, 0, 6, 0, &[])[1], 4);
    // The GSK980 parameter words and No.4 from a script command.
    r.cmd(&["param", "4", "16"]);
    assert_eq!(r.v("cnc.param.4"), "16");
    r.cmd(&["offset", "0", "X", "3"]);
    assert_eq!(
        res(&r.windr(13, 0, 1, 0, &[]), 1).2,
        vec![1500],
        "radius on the window"
    );
}
