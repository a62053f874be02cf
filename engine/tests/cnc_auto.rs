//! Automatic operation and the MST interface of the simulated CNC, exact in exchanges
//! (docs/cnc.md, "Automatic operation", "MST interface").

use crate::common::Rig;
use ladder_engine::cnc::Mode;

fn mem(text: &str) -> Rig {
    let mut r = Rig::new();
    r.mode(Mode::Mem);
    r.x();
    r.program(text);
    r
}

#[test]
fn a_block_without_motion_or_mst_takes_one_exchange() {
    let mut r = mem("O0001;N10;N20;N30");
    let s = r.start();
    assert_eq!(r.v("cnc.block"), "10");
    assert_eq!(r.v("cnc.run"), "RUN");
    r.x();
    assert_eq!((r.n, r.v("cnc.block").as_str()), (s + 1, "20"));
    r.x();
    assert_eq!(r.v("cnc.block"), "30");
    // Past the last block without M02/M30: IDLE at the exchange the next would start.
    r.x();
    assert_eq!(r.v("cnc.run"), "IDLE");
    assert_eq!(r.v("cnc.param.6711"), "0", "not counted");
}

#[test]
fn an_mst_only_block_answered_at_once_ends_two_exchanges_later() {
    let mut r = mem("O0001;N10 M03;N20 M08");
    r.auto_fin = true;
    let s = r.start();
    assert!(r.fb(7, 0), "MF rises at s");
    assert_eq!(r.fv(10, 4), 3);
    assert!(r.fb(1, 3), "DEN: no motion to wait for");
    r.x(); // s+1: FIN = 1, MF drops
    assert!(!r.fb(7, 0));
    assert_eq!(r.fv(10, 4), 3, "the code stays until the sequence finishes");
    r.x(); // s+2: FIN = 0: sequence finishes, the block ends
    assert_eq!(r.fv(10, 4), 0);
    assert_eq!(r.v("cnc.block"), "10");
    r.x(); // s+3: next block
    assert_eq!(r.v("cnc.block"), "20");
    assert!(r.fb(7, 0));
    assert_eq!(r.fv(10, 4), 8);
    assert_eq!(r.n, s + 3);
}

#[test]
fn twenty_mm_at_f600_takes_exchanges_s_to_s_plus_249() {
    let mut r = mem("O0001;N10 G01 W-20 F600;N20");
    let s = r.start();
    assert_eq!(r.m(1), -80, "advances at s: 0.08 mm");
    assert!(r.fb(2, 6), "CUT");
    assert!(r.fb(102, 1) && r.fb(106, 1), "MV and MVD of Z");
    r.xs(248);
    assert_eq!(r.n, s + 248);
    assert_eq!(r.v("cnc.block"), "10");
    r.x();
    assert_eq!(r.m(1), -20_000, "at the target exactly at s+249");
    r.x();
    assert_eq!(r.v("cnc.block"), "20", "the next block starts at s+250");
    assert!(!r.fb(102, 1) && r.fb(106, 1), "MVD is kept while stopped");
    assert!(!r.fb(2, 6));
}

#[test]
fn cycle_start_is_refused_for_each_reason_of_the_manual() {
    type Set = fn(&mut Rig);
    let cases: [(&str, Set); 7] = [
        ("MDI with an empty buffer", |r| r.mode(Mode::Mdi)),
        ("JOG mode", |r| r.mode(Mode::Jog)),
        ("feed hold", |r| r.set(8, 5, false)),
        ("E-stop", |r| r.set(8, 4, false)),
        ("ERS", |r| r.set(8, 7, true)),
        ("SRN", |r| r.set(6, 0, true)),
        ("an alarm", |r| r.cmd(&["alarm", "3"])),
    ];
    for (why, set) in cases {
        let mut r = mem("O0001;N10 G04 P1000");
        set(&mut r);
        r.x();
        r.start();
        assert_eq!(r.v("cnc.run"), "IDLE", "{why}");
    }
    // The rising edge does nothing; the falling edge starts.
    let mut r = mem("O0001;N10 G04 P1000");
    r.set(7, 2, true);
    r.x();
    assert_eq!(r.v("cnc.run"), "IDLE");
    r.set(7, 2, false);
    r.x();
    assert_eq!(r.v("cnc.run"), "RUN");
    assert!(r.fb(0, 5) && r.fb(0, 7) && !r.fb(0, 4), "STL and OP");
    // An empty main program is nothing to run.
    let mut r = mem("");
    r.start();
    assert_eq!(r.v("cnc.run"), "IDLE");
}

#[test]
fn feed_hold_stops_motion_and_cycle_start_resumes_it() {
    let mut r = mem("O0001;N10 G01 W-20 F600");
    r.start();
    r.xs(9);
    let z = r.m(1);
    assert_eq!(z, -800);
    r.set(8, 5, false);
    r.x();
    assert_eq!(r.v("cnc.run"), "HOLD");
    assert!(r.fb(0, 4) && !r.fb(0, 5) && r.fb(0, 7), "SPL, OP");
    assert_eq!(r.m(1), z, "no advance from the hold exchange on");
    r.set(8, 5, true);
    r.xs(5);
    assert_eq!(r.v("cnc.run"), "HOLD", "*SP back at 1 leaves HOLD as it is");
    assert_eq!(r.m(1), z);
    r.start();
    assert_eq!(r.v("cnc.run"), "RUN");
    assert_eq!(r.m(1), z - 80, "the motion advances at the resume exchange");
}

#[test]
fn a_block_that_ends_in_hold_stops_automatic_operation() {
    let mut r = mem("O0001;N10 M03;N20 M04");
    let s = r.start();
    assert_eq!(r.n, s);
    r.set(8, 5, false);
    r.x();
    assert_eq!(r.v("cnc.run"), "HOLD");
    r.set(8, 5, true);
    r.set(4, 3, true);
    r.x();
    r.set(4, 3, false);
    r.x();
    assert_eq!(r.v("cnc.run"), "STOP", "the MST-only block ended in HOLD");
    assert!(!r.fb(0, 4) && !r.fb(0, 5) && !r.fb(0, 7));
    r.start();
    assert_eq!(
        r.v("cnc.block"),
        "20",
        "the next block starts at the cycle start"
    );
}

#[test]
fn single_block_stops_after_each_block_and_releasing_it_restarts_nothing() {
    let mut r = mem("O0001;N10;N20;N30");
    r.set(46, 1, true);
    r.x();
    assert!(r.fb(4, 3), "MSBK follows SBK");
    r.start();
    assert_eq!(r.v("cnc.run"), "STOP");
    assert_eq!(r.v("cnc.block"), "10");
    r.set(46, 1, false);
    r.xs(3);
    assert_eq!(r.v("cnc.run"), "STOP");
    assert_eq!(r.v("cnc.block"), "10");
    r.start();
    r.xs(3);
    assert_eq!(r.v("cnc.run"), "IDLE", "runs on continuously to the end");
}

#[test]
fn m30_ends_the_program_counts_parts_and_sets_prtsf() {
    let mut r = mem("O0001;N10 M30");
    r.cmd(&["param", "6713", "2"]);
    r.auto_fin = true;
    let s = r.start();
    assert!(
        r.fb(9, 4),
        "DM30 while MF with code 30 and nothing to wait for"
    );
    r.xs(2);
    assert_eq!(r.n, s + 2);
    assert_eq!(r.v("cnc.run"), "IDLE");
    assert_eq!(r.v("cnc.param.6711"), "1");
    assert_eq!(r.v("cnc.param.6712"), "1");
    assert!(!r.fb(62, 7));
    r.start();
    r.xs(2);
    assert_eq!(r.v("cnc.param.6711"), "2");
    assert!(r.fb(62, 7), "PRTSF once the required count is reached");
}

#[test]
fn m99_loops_the_main_program_and_pulses_dm99() {
    let mut r = mem("O0001;N10;N20 M99");
    r.start();
    r.x();
    assert_eq!(r.v("cnc.block"), "20");
    assert!(r.fb(9, 3), "DM99 at the exchange the M99 block ends");
    assert!(!r.fb(7, 0), "M99 is never output");
    r.x();
    assert!(!r.fb(9, 3), "for that one exchange");
    assert_eq!(r.v("cnc.block"), "10");
    assert_eq!(r.v("cnc.run"), "RUN");
}

#[test]
fn m98_calls_a_subprogram_repeatedly_and_returns() {
    let mut r = mem("O0001;N10 M98 P20002;N20 M30;O0002;N100;N110 M99");
    r.auto_fin = true;
    r.start();
    assert_eq!(r.v("cnc.block"), "10");
    // M98 takes effect at its block's end, here the exchange it started in.
    assert_eq!(r.v("cnc.prog"), "2");
    r.x();
    assert_eq!(
        (r.v("cnc.block").as_str(), r.v("cnc.prog").as_str()),
        ("100", "2")
    );
    r.x();
    assert_eq!(r.v("cnc.block"), "110");
    r.x();
    assert_eq!(r.v("cnc.block"), "100", "called twice");
    r.xs(2);
    assert_eq!(r.v("cnc.block"), "20");
    assert_eq!(r.v("cnc.prog"), "1");
    // Past the last block of a subprogram it returns as M99 would.
    let mut r = mem("O0001;N10 M98 P2;N20;O0002;N100");
    r.start();
    r.x();
    assert_eq!(r.v("cnc.block"), "100");
    r.x();
    assert_eq!(r.v("cnc.block"), "20");
}

#[test]
fn program_errors_raise_their_alarm_and_show_the_block() {
    let cases = [
        ("N10 G01 W-1 X1 X2", 9),
        ("N10 G02.5 X1", 10),
        ("N10 G02 X1 F1", 22),
        ("N10 G01 W-5", 11),
        ("N10 M1 M2 M3 M4", 14),
        ("N10 M98 P55", 76),
        ("N10 G28 U0", 90),
        ("N10 Y5", 9),
        ("N10 T12345", 3),
        ("N10 G31 X1", 10),
        ("N10 M98", 76),
    ];
    for (block, alarm) in cases {
        let mut r = mem(&format!("O0001;N5;{block}"));
        r.start();
        r.x();
        assert_eq!(r.v("cnc.run"), "STOP", "{block}");
        assert_eq!(r.v(&format!("cnc.alarm.{alarm}")), "1", "{block}");
        assert_eq!(r.v("cnc.block"), "10", "{block}");
        assert!(r.fb(1, 0) && !r.fb(1, 7), "AL, no MA: {block}");
        // Reset clears the P/S alarm.
        r.cmd(&["reset"]);
        r.x();
        assert!(r.fb(6, 1) && r.fb(1, 1), "MDIRST and RST");
        assert_eq!(r.v("cnc.alarms"), "0", "{block}");
        assert_eq!(r.v("cnc.run"), "IDLE");
    }
    // Nesting deeper than 4.
    let mut r =
        mem("O0001;M98 P2;O0002;M98 P3;O0003;M98 P4;O0004;M98 P5;O0005;N50 M98 P6;O0006;M99");
    r.start();
    r.xs(5);
    assert_eq!(r.v("cnc.alarm.77"), "1");
    assert_eq!(r.v("cnc.block"), "50");
}

#[test]
fn skipped_blocks_take_no_exchange() {
    let mut r = mem("O0001;N10;/N20;/N30;N40");
    r.set(44, 0, true);
    r.x();
    assert!(r.fb(4, 0), "MBDT1");
    r.start();
    r.x();
    assert_eq!(r.v("cnc.block"), "40");
    let mut r = mem("O0001;N10;/N20;N40");
    r.start();
    r.x();
    assert_eq!(r.v("cnc.block"), "20", "BDT1 = 0: the block runs");
}

#[test]
fn strobes_drop_on_their_own_finish_signals_and_held_fin_waits() {
    let mut r = mem("O0001;N10 M03 S500 T0202;N20");
    let s = r.start();
    assert!(r.fb(7, 0) && r.fb(7, 2) && r.fb(7, 3));
    assert_eq!(
        (r.fv(22, 4), r.fv(26, 4)),
        (500, 2),
        "T code = the tool number"
    );
    r.set(5, 2, true); // SFIN
    r.x();
    assert!(r.fb(7, 0) && !r.fb(7, 2) && r.fb(7, 3));
    r.set(5, 2, false);
    r.set(5, 0, true); // MFIN
    r.set(5, 3, true); // TFIN
    r.x();
    assert!(!r.fb(7, 0) && !r.fb(7, 3));
    r.xs(3);
    assert_eq!(
        r.fv(10, 4),
        3,
        "finish signals held: the sequence does not finish"
    );
    assert!(r.fb(1, 3), "DEN stays");
    assert_eq!(r.v("cnc.block"), "10");
    r.set(5, 0, false);
    r.set(5, 3, false);
    r.x();
    assert_eq!(r.fv(10, 4) + r.fv(22, 4) + r.fv(26, 4), 0);
    r.x();
    assert_eq!(r.v("cnc.block"), "20");
    assert!(r.n > s + 5);
}

#[test]
fn fin_already_high_is_accepted_at_the_next_exchange() {
    let mut r = mem("O0001;N10 M03;N20");
    r.set(4, 3, true);
    let s = r.start();
    assert!(r.fb(7, 0), "the strobe rises even with FIN high");
    r.x();
    assert!(!r.fb(7, 0), "accepted at s+1");
    r.xs(3);
    assert_eq!(r.v("cnc.block"), "10", "FIN held: no finish");
    r.set(4, 3, false);
    r.xs(2);
    assert_eq!(r.v("cnc.block"), "20");
    assert!(r.n >= s + 5);
}

#[test]
fn a_fin_accepted_before_the_motion_ends_gives_no_decode_signal() {
    let mut r = mem("O0001;N10 G01 W-1 F600 M00;N20");
    r.start();
    assert!(r.fb(7, 0) && !r.fb(9, 7), "DM00 waits for the motion");
    assert!(!r.fb(1, 3), "DEN waits for the motion");
    r.set(4, 3, true);
    r.x();
    r.set(4, 3, false);
    r.x();
    assert!(!r.fb(7, 0));
    r.xs(20);
    assert!(!r.fb(9, 7));
    assert_eq!(r.v("cnc.run"), "STOP", "M00 stops after the block");
    assert_eq!(r.m(1), -1000);
}

#[test]
fn afl_suppresses_m_s_and_t_but_the_spindle_still_takes_s() {
    let mut r = mem("O0001;N10 M03 S700 T0101;N20 M30");
    r.set(5, 6, true);
    r.x();
    assert!(r.fb(4, 4), "MAFL");
    r.start();
    assert!(!r.fb(7, 0) && !r.fb(7, 2) && !r.fb(7, 3));
    assert_eq!(r.v("cnc.spindle"), "700");
    r.x();
    assert!(r.fb(7, 0) && r.fb(9, 4), "M30 is still output");
}

#[test]
fn the_tool_already_in_place_is_not_output_and_the_offset_acts_at_block_end() {
    let mut r = mem("O0001;N10 T0203;N20 T0304");
    r.cmd(&["offset", "3", "Z", "1.5"]);
    r.g[201] = 2; // NOWT = 2
    r.x();
    r.start();
    assert!(!r.fb(7, 3), "tool 2 is in place: no T");
    assert_eq!(
        r.v("cnc.abs.Z"),
        "-1.500",
        "offset 3 active at the end of the block (here its first exchange)"
    );
    assert_eq!(
        r.v("cnc.pos.Z"),
        "0.000",
        "an offset change never moves an axis"
    );
    r.x();
    assert!(r.fb(7, 3), "tool 3 is output");
    assert_eq!(r.fv(26, 4), 3);
    r.auto_fin = true;
    r.x();
    assert!(!r.fb(7, 3), "TF dropped with FIN");
    assert_eq!(
        r.v("cnc.abs.Z"),
        "-1.500",
        "offset 4 waits for the end of the block"
    );
    r.x();
    assert_eq!(r.v("cnc.abs.Z"), "0.000");
}

#[test]
fn reset_keeps_modal_data_and_clears_the_mst_signals() {
    let mut r = mem("O0001;N10 G01 F200 M03 S900;N20");
    r.start();
    assert!(r.fb(7, 0));
    r.set(8, 7, true);
    r.x();
    assert!(!r.fb(7, 0) && !r.fb(7, 2) && r.fv(10, 4) == 0 && !r.fb(1, 3));
    assert_eq!(r.v("cnc.run"), "IDLE");
    assert!(r.fb(1, 1), "RST");
    r.set(8, 7, false);
    r.x();
    assert!(!r.fb(1, 1));
    assert_eq!(r.v("cnc.spindle"), "900", "S is kept");
    // #0071 extends RST: ⌈20 / 8⌉ = 3 exchanges after the last reset condition.
    r.cmd(&["param", "71", "20"]);
    r.cmd(&["reset"]);
    r.x();
    for k in 0..3 {
        r.x();
        assert!(r.fb(1, 1), "RST kept {k}");
        assert!(!r.fb(6, 1), "MDIRST only while pressed");
    }
    r.x();
    assert!(!r.fb(1, 1));
}

#[test]
fn leaving_automatic_mode_holds_or_stops_at_the_block_end() {
    let mut r = mem("O0001;N10 G01 W-5 F600;N20 G01 W-5");
    r.start();
    r.mode(Mode::Jog);
    r.x();
    assert_eq!(r.v("cnc.run"), "HOLD");
    assert!(r.fb(3, 2) && !r.fb(3, 5), "MJ");
    let mut r = mem("O0001;N10 G01 W-1 F600;N20 G01 W-5");
    r.start();
    r.mode(Mode::Edit);
    r.x();
    assert_eq!(r.v("cnc.run"), "RUN", "EDIT: the block runs to its end");
    r.xs(20);
    assert_eq!(r.v("cnc.run"), "STOP");
    assert_eq!(r.v("cnc.block"), "10");
}

#[test]
fn a_new_alarm_interrupts_the_block_and_cycle_start_resumes_it_once_cleared() {
    let mut r = mem("O0001;N10 G01 W-10 F600");
    r.start();
    r.xs(4);
    r.a[0] = 1; // PLC alarm A0.0 (no message table: alarm 1000)
    let z = r.m(1);
    r.x();
    assert_eq!(r.v("cnc.run"), "STOP");
    assert_eq!(r.v("cnc.alarm.1000"), "1");
    assert!(r.fb(1, 0) && r.fb(1, 7), "AL; MA stays (a PLC alarm)");
    assert_eq!(r.m(1), z, "no advance at the alarm's exchange");
    r.start();
    assert_eq!(r.v("cnc.run"), "STOP", "ST ignored while AL = 1");
    r.a[0] = 0;
    r.x();
    assert_eq!(r.v("cnc.alarms"), "0", "no reset needed");
    r.start();
    assert_eq!(r.v("cnc.run"), "RUN");
    assert_eq!(r.m(1), z - 80, "the interrupted block goes on");
}

#[test]
fn machine_lock_moves_the_absolute_position_only() {
    let mut r = mem("O0001;N10 G00 W-3");
    r.set(44, 1, true);
    r.x();
    assert!(r.fb(4, 1), "MMLK");
    r.start();
    r.xs(10);
    assert_eq!(r.v("cnc.pos.Z"), "0.000");
    assert_eq!(r.v("cnc.abs.Z"), "-3.000");
}

#[test]
fn dry_run_and_override_set_the_cutting_speed() {
    // DRN: #1410 × JV = 1200 mm/min at 100 %: 0.16 mm per exchange.
    let mut r = mem("O0001;N10 G01 W-10 F60");
    r.set(46, 7, true);
    r.start();
    assert_eq!(r.m(1), -160);
    assert!(r.fb(2, 7), "MDRN");
    // FV = 5: 50 % of F600.
    let mut r = mem("O0001;N10 G01 W-10 F600");
    r.g[12] = 5;
    r.start();
    assert_eq!(r.m(1), -40);
    // OVC fixes 100 %.
    r.set(6, 4, true);
    r.x();
    assert_eq!(r.m(1), -120);
    // Feed per revolution: F0.1 mm/rev × S1000 = 100 mm/min.
    let mut r = mem("O0001;N10 M03 S1000;N20 G99 G01 W-10 F0.1");
    r.auto_fin = true;
    r.start();
    r.xs(3);
    assert_eq!(r.v("cnc.block"), "20");
    assert_eq!(r.m(1), -13, "100 mm/min: 13.3 µm per exchange");
}

#[test]
fn rapid_takes_the_slowest_axis_and_the_rapid_override() {
    // X 20 mm diameter (10 mm radius) and Z 10 mm at #1420 = 6000 (0.8 mm per exchange):
    // both take ⌈12.5⌉ = 13 exchanges; with Z at 3000 Z decides: 25.
    let mut r = mem("O0001;N10 G00 U20 W-10");
    let s = r.start();
    let done = r.until(200, |r| r.m(1) == -10_000);
    assert_eq!(done, s + 12);
    assert_eq!(r.m(0), 20_000);
    let mut r = mem("O0001;N10 G00 U20 W-10");
    r.cmd(&["param", "1420", "2", "3000"]);
    let s = r.start();
    let done = r.until(200, |r| r.m(1) == -10_000);
    assert_eq!(done, s + 24);
    assert_eq!(r.m(0), 20_000);
    // ROV = 25 %.
    let mut r = mem("O0001;N10 G00 W-10");
    r.g[14] = 2;
    r.start();
    assert_eq!(r.m(1), -200);
    assert!(r.fb(2, 1), "RPDO while a rapid advances");
    r.g[14] = 3; // F0: #1421 = 600
    r.x();
    assert_eq!(r.m(1), -280);
    r.set(8, 0, false); // *IT: the rapid stops, and RPDO with it
    r.x();
    assert!(!r.fb(2, 1), "RPDO is 0 once the feed stops");
}

#[test]
fn interlocks_hold_the_axes_and_the_next_blocks() {
    let mut r = mem("O0001;N10 G01 W-10 F600;N20 M03");
    r.start();
    r.set(8, 0, false); // *IT
    r.xs(5);
    assert_eq!(r.m(1), -80);
    assert_eq!(r.v("cnc.run"), "RUN", "RUN stays RUN");
    r.set(8, 0, true);
    r.set(8, 3, false); // *BSL
    r.xs(200);
    assert_eq!(r.v("cnc.block"), "10", "no next block while *BSL = 0");
    r.set(8, 3, true);
    r.x();
    assert_eq!(r.v("cnc.block"), "20");
    // *CSL holds a cutting block back, not a rapid one.
    let mut r = mem("O0001;N10 G00 W-1;N20 G01 W-1 F600");
    r.set(8, 1, false);
    r.start();
    r.xs(30);
    assert_eq!(r.v("cnc.block"), "10");
    assert_eq!(r.m(1), -1000);
}

#[test]
fn coordinates_follow_tool_and_workpiece_offsets() {
    let mut r = mem("O0001;N10 G55 T0101;N20 G00 X10 Z-5");
    r.cmd(&["offset", "1", "X", "2"]);
    r.cmd(&["offset", "1", "WZ", "0.5"]);
    r.cmd(&["workpiece", "G55", "Z", "100"]);
    r.cmd(&["workpiece", "EXT", "Z", "1"]);
    r.auto_fin = true;
    r.start();
    r.until(500, |r| r.v("cnc.run") == "IDLE");
    assert_eq!(r.v("cnc.abs.X"), "10.000");
    assert_eq!(r.v("cnc.abs.Z"), "-5.000");
    assert_eq!(r.v("cnc.pos.X"), "12.000");
    assert_eq!(r.v("cnc.pos.Z"), "96.500");
}

#[test]
fn after_m30_and_after_an_mdi_run_the_screen_marks_where_the_cursor_is() {
    let mut r = mem("O0001\nN10 G04 X0.01\nN20 M30");
    r.auto_fin = true;
    r.start();
    r.xs(10);
    assert_eq!(r.v("cnc.run"), "IDLE");
    let s = r.cnc.status();
    // M30 rewinds: the marker is on the program's first block (line 2), in the program.
    assert_eq!((s.line, s.line_in_mdi), (Some(2), false));
    // An MDI run ends with the cursor in the MDI buffer: its line is the MDI's, not the
    // program's.
    r.mode(ladder_engine::cnc::Mode::Mdi);
    r.x();
    r.cnc
        .apply(&ladder_engine::cnc::command::CncCommand::Mdi(
            "G04 X0.01".into(),
        ))
        .unwrap();
    r.start();
    r.xs(10);
    let s = r.cnc.status();
    assert_eq!(r.v("cnc.run"), "IDLE");
    assert!(s.line_in_mdi && !s.mdi, "{s:?}");
}
