//! The program reader as automatic operation sees it (docs/gcode.md, "Reader"): M98's
//! program number and count rules, L repeats, and the alarm that ends a program looping
//! through skipped blocks only.

use crate::common::Rig;

/// Runs until IDLE or STOP (at most `limit` exchanges) and returns the N of the block
/// executing at each exchange (N numbers are unique in these programs).
fn trace(r: &mut Rig, limit: u32) -> Vec<String> {
    let mut seen = Vec::new();
    r.start();
    for _ in 0..limit {
        if r.v("cnc.run") == "IDLE" || r.v("cnc.run") == "STOP" {
            break;
        }
        seen.push(r.v("cnc.block"));
        r.x();
    }
    seen
}

#[test]
fn m98_p_names_an_existing_program_whole_else_count_and_number() {
    // O20003 exists: P20003 calls it once (not O0003 twice).
    let mut r = Rig::mem("O1;N1 M98 P20003;N2 M30;O20003;N30 M99;O3;N40 M99");
    let t = trace(&mut r, 50);
    assert_eq!(t[..3], ["1", "30", "2"], "O20003 once, never O3");
    assert_eq!(r.v("cnc.alarms"), "0");
    // No O20002: P20002 is program 2, twice.
    let mut r = Rig::mem("O1;N1 M98 P20002;N2 M30;O2;N50 M99");
    let t = trace(&mut r, 50);
    assert_eq!(t[..4], ["1", "50", "50", "2"], "O2 twice");
    assert_eq!(r.v("cnc.param.6711"), "1", "ended with M30");
}

#[test]
fn l_repeats_a_call_and_five_digit_programs_are_called_by_number() {
    let mut r = Rig::mem("O1;N1 M98 P12345 L3;N2 M30;O12345;N70 M99");
    let t = trace(&mut r, 50);
    assert_eq!(t[..5], ["1", "70", "70", "70", "2"]);
    assert_eq!(r.v("cnc.alarms"), "0");
}

#[test]
fn a_program_on_a_tape_with_leader_runs() {
    let mut r = Rig::mem("HEADER (ANY TEXT, EVEN G1X..)\n%\nO2001\nN1 G04 P8\nN2 M30\n%\n");
    let t = trace(&mut r, 20);
    assert_eq!(t.first().map(String::as_str), Some("1"), "{t:?}");
    assert_eq!(r.v("cnc.alarms"), "0");
    assert_eq!(r.v("cnc.param.6711"), "1");
}

#[test]
fn a_program_that_only_skips_blocks_ends_with_an_alarm_not_a_silent_stop() {
    // A subprogram of ten skipped blocks (its end returns as M99 would) called 9999 times
    // with BDT1 on: 9999 × 11 passes without a block to execute.
    let sub: String = (1..=10).map(|k| format!("/N{k};")).collect();
    let mut r = Rig::mem(&format!("O1;N5 M98 P2 L9999;N6 M30;O2;{sub}"));
    r.set(44, 0, true);
    r.start();
    r.xs(5);
    assert_eq!(r.v("cnc.alarm.79"), "1");
    assert_eq!(r.v("cnc.run"), "STOP");
    assert!(r.fb(1, 0), "AL");
    // With BDT1 off the same program runs its blocks and ends.
    let mut r = Rig::mem("O1;N5 M98 P2 L2;N6 M30;O2;/N1;/N2;M99");
    let t = trace(&mut r, 100);
    assert_eq!(t.iter().filter(|s| *s == "1").count(), 2, "{t:?}");
    assert_eq!(r.v("cnc.alarms"), "0");
}

#[test]
fn m97_calls_a_block_of_the_same_program_and_m99_returns() {
    // Haas's local call: M97 P100 runs from N100 to its M99, L2 twice; M97 is not put out.
    let mut r = Rig::mem("O1;N1 M97 P100 L2;N2 M30;N100;N110 M99");
    let t = trace(&mut r, 50);
    assert_eq!(t[..6], ["1", "100", "110", "100", "110", "2"]);
    assert_eq!(r.v("cnc.alarms"), "0");
    // M97 without P is an M code for the ladder; with a P no block has: P/S 0063.
    let mut r = Rig::mem("O1;N1 M97 P555;N2 M30");
    trace(&mut r, 10);
    assert_eq!(r.v("cnc.alarm.63"), "1");
    let mut r = Rig::mem("O1;N1 M97;N2 M30");
    r.start();
    assert!(r.fb(7, 0) && r.fv(10, 4) == 97, "MF with M97");
}
