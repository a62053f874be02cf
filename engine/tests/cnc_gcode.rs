//! G code beyond straight lines, checked against the figures worked by hand in
//! docs/gcode.md: arcs, units and the decimal point, feed modes, coordinate and data setting,
//! and constant surface speed.

use crate::common::Rig;
use ladder_engine::cnc::Mode;

/// Runs until automatic operation leaves RUN (at most `limit` exchanges after the start).
fn run(r: &mut Rig, limit: u64) {
    r.start();
    r.until(limit, |r| r.v("cnc.run") != "RUN");
}

#[test]
fn a_quarter_arc_by_r_ends_on_its_point_after_197_exchanges() {
    // docs/gcode.md, "Arcs": X0 Z0 → X20 Z-10, R10 at F600: 15.708 mm at 0.08 mm per
    // exchange.
    let mut r = Rig::mem("O1;N1 G02 X20 Z-10 R10 F600;N2");
    let s = r.start();
    r.until(400, |r| r.v("cnc.block") == "2");
    // The motion's last exchange is s + 196; the next block starts at the one after.
    assert_eq!(r.n, s + 197);
    assert_eq!((r.m(0), r.m(1)), (20_000, -10_000));
    // Half way the tool is on the circle around Z0 X(radius)10, below the chord: concave.
    let mut r = Rig::mem("O1;N1 G02 X20 Z-10 R10 F600;N2");
    r.start();
    r.xs(97);
    let (x, z) = (r.m(0) as f64 / 2000.0, r.m(1) as f64 / 1000.0);
    assert!(((z * z + (x - 10.0).powi(2)).sqrt() - 10.0).abs() < 0.002);
    assert!(
        (x - 2.93).abs() < 0.02 && (z + 7.07).abs() < 0.02,
        "{x} {z}"
    );
}

#[test]
fn g03_with_i_k_and_a_full_circle() {
    // From X20 Z0, I-5: centre X(radius)5, a full turn of 31.416 mm at F600 in 393
    // exchanges, through X0 half way.
    let mut r = Rig::mem("O1;N1 G00 X20;N2 G03 I-5 F600;N3");
    r.start();
    r.until(100, |r| r.v("cnc.block") == "2");
    let s = r.n;
    let mut least_x = i64::MAX;
    while r.v("cnc.block") == "2" {
        least_x = least_x.min(r.m(0));
        r.x();
    }
    assert_eq!(r.n - s, 393);
    assert_eq!((r.m(0), r.m(1)), (20_000, 0));
    assert!(least_x.abs() <= 2, "{least_x}");
    // I/K whose end radius differs from the start's by more than #3410 (0.020 mm): P/S 0020.
    let mut r = Rig::mem("O1;N1 G02 X20 Z-10 I10 K0.05 F600");
    run(&mut r, 10);
    assert_eq!(r.v("cnc.alarm.20"), "1");
    assert_eq!((r.m(0), r.m(1)), (0, 0), "nothing moved");
}

#[test]
fn inch_scales_lengths_and_feed_and_sets_inch() {
    // G20: U1. is 25.4 mm of diameter, W-0.5 12.7 mm; F10 is 254 mm/min. Positions stay mm.
    let mut r = Rig::mem("O1;N1 G20 G01 U1. W-0.5 F10;N2 G21;N3");
    r.start();
    assert!(r.fb(2, 0), "INCH F2.0");
    r.until(1000, |r| r.v("cnc.block") == "2");
    assert_eq!(
        (r.v("cnc.pos.X"), r.v("cnc.pos.Z")),
        ("25.400".into(), "-12.700".into())
    );
    // L = hypot(12.7, 12.7) = 17.961 mm at 254 mm/min: 0.033867 mm/exchange → 531 exchanges.
    assert_eq!(r.n, 531 + 2 + 1);
    r.x();
    assert!(!r.fb(2, 0), "G21 clears INCH");
}

#[test]
fn dpi_decides_what_a_number_without_a_point_means() {
    // #3401 bit 0 = 1 (default): X10 is 10 mm. = 0: X10000 is 10 mm, X10. is 10 mm too.
    let mut r = Rig::mem("O1;N1 G00 X10 W-5;N2");
    run(&mut r, 1000);
    assert_eq!((r.m(0), r.m(1)), (10_000, -5_000));
    let mut r = Rig::mem("O1;N1 G00 X10000 W-5.;N2 G04 X500;N3");
    r.cmd(&["param", "3401", "0"]);
    run(&mut r, 1000);
    assert_eq!((r.m(0), r.m(1)), (10_000, -5_000));
    // Under DPI = 0, G04 X500 is 500 ms, P1.5 is 1.5 s whatever DPI says.
    let mut r = Rig::mem("O1;N1 G04 X500;N2 G04 P1.5;N3");
    r.cmd(&["param", "3401", "0"]);
    let s = r.start();
    r.until(100, |r| r.v("cnc.block") == "2");
    assert_eq!(r.n - s, 63, "⌈500 / 8⌉");
    let s = r.n;
    r.until(300, |r| r.v("cnc.block") == "3");
    assert_eq!(r.n - s, 188, "⌈1500 / 8⌉");
}

#[test]
fn fpm_chooses_the_feed_mode_of_power_on_and_reset() {
    // #3402 bit 4 = 0: G99 from power-on, F0.1 at 600 r/min is 60 mm/min: 1 mm in 125
    // exchanges.
    let mut r = Rig::mem("O1;N1 M03 S600;N2 G01 W-1 F0.1;N3");
    r.cmd(&["param", "3402", "0"]);
    r.cnc.power_cycle();
    r.mode(Mode::Mem);
    r.x();
    r.start();
    r.until(50, |r| r.v("cnc.block") == "2");
    let s = r.n;
    r.until(500, |r| r.v("cnc.block") == "3");
    assert_eq!(r.n - s, 125);
    // Bit 4 = 1 (default) is G98: the same block feeds 0.1 mm/min and is still moving.
    let mut r = Rig::mem("O1;N1 M03 S600;N2 G01 W-1 F0.1;N3");
    r.start();
    r.xs(500);
    assert_eq!(r.v("cnc.block"), "2");
    // A reset returns to #3402's mode: G99 written, reset, then per minute again.
    let mut r = Rig::mem("O1;N1 G99;N2");
    run(&mut r, 10);
    r.cmd(&["reset"]);
    r.x();
    r.program("O1;N1 M03 S600;N2 G01 W-1 F0.1;N3");
    r.start();
    r.xs(500);
    assert_eq!(r.v("cnc.block"), "2", "G98 after reset");
}

#[test]
fn g50_sets_the_coordinates_of_the_tool_and_g53_moves_in_machine_coordinates() {
    let mut r = Rig::mem("O1;N1 G50 X100 Z50;N2 G04 P100;N3 G00 X80 Z40;N4 G04 P8;N5 G53 X0 Z0;N6");
    r.start();
    r.until(100, |r| r.v("cnc.block") == "2");
    assert_eq!(
        (r.v("cnc.abs.X"), r.v("cnc.abs.Z")),
        ("100.000".into(), "50.000".into())
    );
    r.until(1000, |r| r.v("cnc.block") == "4");
    assert_eq!((r.m(0), r.m(1)), (-20_000, -10_000));
    r.until(1000, |r| r.v("cnc.block") == "6");
    assert_eq!((r.m(0), r.m(1)), (0, 0));
    assert_eq!(r.v("cnc.abs.X"), "100.000");
}

#[test]
fn g10_sets_workpiece_and_tool_offsets() {
    let mut r = Rig::mem(
        "O1;N1 G10 L2 P1 X0 Z-120.;N2 G10 P10003 X-150. Z-300. R0.4;N3 G10 P3 U0.02 W-0.01;N4 G10 P3 U0.02;N5",
    );
    run(&mut r, 100);
    assert_eq!(r.v("cnc.work.G54.Z"), "-120.000");
    assert_eq!(r.v("cnc.offset.3.X"), "-150.000");
    assert_eq!(r.v("cnc.offset.3.R"), "0.400");
    assert_eq!(r.v("cnc.offset.3.WX"), "0.040", "U adds");
    assert_eq!(r.v("cnc.offset.3.WZ"), "-0.010");
    let mut r = Rig::mem("O1;N1 G10 L2 P7 X0;N2");
    run(&mut r, 10);
    assert_eq!(r.v("cnc.alarm.31"), "1");
}

#[test]
fn constant_surface_speed_follows_the_diameter_under_the_g50_clamp() {
    // docs/gcode.md, "Constant surface speed": 200 m/min at D100 is 637 r/min, at D50
    // 1273, at D20 3183 clamped to G50 S1500.
    let mut r = Rig::mem(
        "O1;N1 G50 S1500;N2 G00 X100;N3 G96 S200 M03;N4 G00 X50;N5 G01 X20 F6000;N6 G97;N7",
    );
    r.start();
    r.until(2000, |r| r.v("cnc.block") == "3");
    assert_eq!(r.v("cnc.spindle"), "637");
    assert!(r.fb(2, 2), "CSS F2.2");
    // During a rapid the speed is the end point's from its first exchange.
    r.until(2000, |r| r.v("cnc.block") == "4");
    assert_eq!(r.v("cnc.spindle"), "1273");
    assert!(r.m(0) > 90_000);
    r.until(2000, |r| r.v("cnc.block") == "5");
    r.until(2000, |r| r.v("cnc.block") == "6");
    assert_eq!(r.v("cnc.spindle"), "1500");
    r.until(100, |r| r.v("cnc.block") == "7");
    assert!(!r.fb(2, 2), "G97 clears CSS");
    assert_eq!(r.v("cnc.spindle"), "1500", "G97 keeps the last speed");
}

/// Records (X, Z) machine positions, one per exchange, while block `n` executes.
fn path_of(r: &mut Rig, n: &str, limit: u64) -> Vec<(i64, i64)> {
    r.until(limit, |r| r.v("cnc.block") == n);
    let mut path = Vec::new();
    while r.v("cnc.block") == n && r.v("cnc.run") == "RUN" {
        path.push((r.m(0), r.m(1)));
        r.x();
    }
    path
}

#[test]
fn g90_turns_in_four_segments_and_repeats_for_an_x_alone() {
    // docs/gcode.md, "Single cycles": from X50 Z2, G90 X40 Z-20 F600 (G98): rapid 5 mm (7
    // exchanges at 0.8 mm), cut 22 mm (275), cut up 5 mm (63), rapid back 22 mm (28): 373.
    let mut r =
        Rig::mem("O1;N1 G00 X50 Z2;N2 G90 X40 Z-20 F600;N3 X30;N4 G00 X60;N5 G90 X40 Z-20 R-2;N6");
    r.start();
    let p = path_of(&mut r, "2", 100);
    assert_eq!(p.len(), 373);
    assert_eq!(p[6], (40_000, 2_000), "the rapid ends at s+6");
    assert_eq!(
        p[6 + 275],
        (40_000, -20_000),
        "the cut along Z ends at s+281"
    );
    assert_eq!(p.last(), Some(&(50_000, 2_000)), "back at the start point");
    // N3 repeats the cycle at X30 with Z-20 kept.
    let p = path_of(&mut r, "3", 10);
    assert!(p.contains(&(30_000, -20_000)));
    // A taper R-2 (radius): the cut starts at X36 and ends at X40 Z-20.
    let p = path_of(&mut r, "5", 1000);
    assert!(p.contains(&(36_000, 2_000)) && p.contains(&(40_000, -20_000)));
}

#[test]
fn g94_faces_and_returns() {
    // From X50 Z2, G94 X20 Z-2 F600: rapid 4 mm (5), cut 15 mm of radius (188), cut back 4 mm
    // (50), rapid 15 mm (19): 262 exchanges.
    let mut r = Rig::mem("O1;N1 G00 X50 Z2;N2 G94 X20 Z-2 F600;N3");
    r.start();
    let p = path_of(&mut r, "2", 100);
    assert_eq!(p.len(), 262);
    assert_eq!(p[4 + 188], (20_000, -2_000));
    assert_eq!((r.m(0), r.m(1)), (50_000, 2_000));
}

#[test]
fn a_thread_waits_for_the_one_rotation_signal_and_follows_the_spindle_not_the_override() {
    // 600 r/min × lead 2 = 1200 mm/min = 0.16 mm per exchange, whatever the feed override.
    let mut r = Rig::mem("O1;N1 M03 S600;N2 G32 W-10 F2;N3");
    r.g[12] = 5; // feed override 50 %: no effect on a thread
    r.start();
    r.until(100, |r| r.v("cnc.block") == "2");
    let mut waited = 0;
    while r.m(1) == 0 {
        assert!(r.fb(2, 3), "THRD while the thread waits");
        waited += 1;
        r.x();
    }
    assert!(
        waited <= 13,
        "one turn is 12.5 exchanges at 600 r/min: {waited}"
    );
    assert_eq!(r.m(1), -160);
    // Spindle override 50 %: 300 r/min, 0.08 mm per exchange.
    r.g[30] = 5;
    r.x();
    assert_eq!(r.m(1), -240);
    assert!(r.fb(2, 3) && r.fb(2, 6), "THRD, and CUT as a cutting feed");
    r.until(500, |r| r.v("cnc.block") == "3");
    assert_eq!(r.m(1), -10_000);
    assert!(!r.fb(2, 3));
}

#[test]
fn feed_hold_waits_for_the_end_of_the_thread() {
    let mut r = Rig::mem("O1;N1 M03 S600;N2 G00 X30 Z5;N3 G92 X20 Z-20 F1.5;N4");
    r.start();
    r.until(1000, |r| {
        r.v("cnc.block") == "3" && r.fb(2, 3) && r.m(1) < 0
    });
    r.set(8, 5, false); // *SP: feed hold
    r.x();
    assert_eq!(r.v("cnc.run"), "RUN", "the thread goes on");
    r.until(1000, |r| r.v("cnc.run") == "HOLD");
    // It stopped where the thread (with its chamfer) ended, before the retract.
    assert_eq!((r.m(0), r.m(1)), (23_000, -20_000));
    r.set(8, 5, true);
    r.start();
    r.until(1000, |r| r.v("cnc.block") == "4");
    assert_eq!((r.m(0), r.m(1)), (30_000, 5_000));
}

#[test]
fn g92_threads_with_a_45_degree_chamfer_of_one_lead() {
    // #5130 = 10: the pull-out starts 1.5 mm (one lead) before Z-20 and ends 1.5 mm higher.
    let mut r = Rig::mem("O1;N1 M03 S600;N2 G00 X30 Z5;N3 G92 X20 Z-20 F1.5;N4 X19.4;N5");
    r.start();
    let p = path_of(&mut r, "3", 1000);
    assert!(p.contains(&(20_000, -18_500)), "the chamfer starts");
    assert!(p.contains(&(23_000, -20_000)), "and ends");
    assert!(p.iter().all(|&(x, _)| x >= 20_000));
    let p = path_of(&mut r, "4", 10);
    assert!(p.contains(&(19_400, -18_500)), "N4 repeats at X19.4");
    assert_eq!((r.m(0), r.m(1)), (30_000, 5_000));
}

#[test]
fn chamfer_and_corner_r_cut_the_corner_to_the_next_g01() {
    // Up the face to X20, then along Z: ,C2 from X16 Z0 to X20 Z-2; ,R2 the same points joined
    // by a quarter circle around X16 Z-2 (radius 8), through X18.828 Z-0.586.
    let mut r = Rig::mem("O1;N1 G01 X20 ,C2 F600;N2 Z-20;N3");
    r.start();
    let p = path_of(&mut r, "1", 10);
    assert!(
        p.contains(&(16_000, 0)) && p.last() == Some(&(20_000, -2_000)),
        "{p:?}"
    );
    let mut r = Rig::mem("O1;N1 G01 X20 ,R2 F600;N2 Z-20;N3");
    r.start();
    let p = path_of(&mut r, "1", 10);
    assert!(p.contains(&(16_000, 0)) && p.last() == Some(&(20_000, -2_000)));
    let near = |&(x, z): &(i64, i64)| (x - 18_828).abs() <= 60 && (z + 586).abs() <= 60;
    assert!(p.iter().any(near), "the arc bulges out: {p:?}");
    // Too large for the moves, or not followed by a G01: FANUC's 0055 and 0052.
    for (text, alarm) in [
        ("O1;N1 G01 X20 ,C12 F600;N2 Z-20", 55),
        ("O1;N1 G01 X20 ,C2 F600;N2 G00 Z-20", 52),
    ] {
        let mut r = Rig::mem(text);
        run(&mut r, 10);
        assert_eq!(r.v(&format!("cnc.alarm.{alarm}")), "1", "{text}");
    }
}

#[test]
fn g30_returns_to_the_second_reference_point() {
    let mut r = Rig::mem("O1;N1 G30 U0 W0;N2");
    r.home(&[0, 1]);
    r.mode(Mode::Mem);
    r.x();
    r.cmd(&["param", "1241", "1", "100000"]);
    r.cmd(&["param", "1241", "2", "50000"]);
    r.start();
    r.until(1000, |r| r.v("cnc.block") == "2");
    assert_eq!((r.m(0), r.m(1)), (100_000, 50_000));
    assert_eq!(r.f[96] & 3, 3, "ZP21, ZP22");
}

#[test]
fn c_and_r_without_a_comma_chamfer_and_round_a_g01_corner() {
    let mut r = Rig::mem("O1;N1 G01 X20 C2 F600;N2 Z-20;N3");
    r.start();
    let p = path_of(&mut r, "1", 10);
    assert!(p.contains(&(16_000, 0)) && p.last() == Some(&(20_000, -2_000)));
    let mut r = Rig::mem("O1;N1 G01 X20 R2 F600;N2 Z-20;N3");
    r.start();
    let p = path_of(&mut r, "1", 10);
    let near = |&(x, z): &(i64, i64)| (x - 18_828).abs() <= 60 && (z + 586).abs() <= 60;
    assert!(p.iter().any(near));
    // C means nothing outside G01.
    let mut r = Rig::mem("O1;N1 G00 X20 C2;N2");
    run(&mut r, 10);
    assert_eq!(r.v("cnc.alarm.9"), "1");
}
