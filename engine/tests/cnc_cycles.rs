//! The multiple repetitive cycles against the figures of docs/gcode.md: G71 and G72 levels and
//! final positions in both forms, G70 running the profile, G73's passes, G74 pecks, G76 pass
//! depths, and FANUC's alarms for bad cycles.

use crate::common::Rig;

/// Runs the program to its end (at most `limit` exchanges) and returns every (X, Z) machine
/// position and every block N seen.
fn run(r: &mut Rig, limit: u64) -> (Vec<(i64, i64)>, Vec<String>) {
    let mut path = Vec::new();
    let mut blocks: Vec<String> = Vec::new();
    r.start();
    for _ in 0..limit {
        path.push((r.m(0), r.m(1)));
        let b = r.v("cnc.block");
        if blocks.last() != Some(&b) {
            blocks.push(b);
        }
        if r.v("cnc.run") != "RUN" {
            break;
        }
        r.x();
    }
    (path, blocks)
}

const PROFILE: &str = "N30 G00 X20;N40 G01 Z-10;N50 X40 Z-20;N60 Z-30;N70 M30";

#[test]
fn g71_cuts_levels_two_mm_apart_down_to_the_allowance_profile() {
    // docs/gcode.md, "Stock removal": from X50 Z2, Δd 2 mm, U0.4 W0.1: levels at radius 23,
    // 21 (to the end Z-29.9), 19, 17, 15, 13, 11 (to the shifted taper).
    for cycle in [
        "N10 G71 U2 R0.5;N20 G71 P30 Q60 U0.4 W0.1 F600",
        "N20 G71 P30 Q60 U0.4 W0.1 D2000 F600",
    ] {
        let text = format!("O1;N1 G00 X50 Z2;{cycle};{PROFILE}");
        let mut r = Rig::mem(&text);
        let (path, blocks) = run(&mut r, 200_000);
        assert_eq!(r.v("cnc.alarms"), "0", "{cycle}");
        assert_eq!(r.v("cnc.run"), "IDLE", "{cycle}: reached M30");
        for (x, z) in [
            (46_000, -29_900),
            (42_000, -29_900),
            (38_000, -18_700),
            (34_000, -16_700),
            (30_000, -14_700),
            (26_000, -12_700),
            (22_000, -10_700),
        ] {
            assert!(path.contains(&(x, z)), "{cycle}: level X{x} ends at Z{z}");
        }
        // The last pass follows the profile moved by the allowance, then goes back to A.
        for p in [
            (20_400, 2_100),
            (20_400, -9_900),
            (40_400, -19_900),
            (40_400, -29_900),
        ] {
            assert!(path.contains(&p), "{cycle}: {p:?}");
        }
        assert!(
            !path.contains(&(18_000, -10_700)),
            "no level below the profile"
        );
        let inside = path.iter().filter(|p| p.1 < 0);
        assert!(
            inside.clone().all(|&(x, _)| x >= 20_400),
            "nothing under the allowance"
        );
        // The profile blocks are not run again after the cycle: on to N70.
        assert!(!blocks.iter().any(|b| b == "30" || b == "60"), "{blocks:?}");
        assert_eq!(blocks.last().map(String::as_str), Some("70"));
    }
}

#[test]
fn g70_runs_the_profile_blocks_and_returns_to_its_start() {
    let text = "O1;N1 G00 X50 Z2;N20 G71 P30 Q60 U0.4 W0.1 F600;N30 G00 X20;N40 G01 Z-10 F300;\
                N50 X40 Z-20;N60 Z-30;N80 G70 P30 Q60;N90 M30";
    let mut r = Rig::mem(text);
    let (path, blocks) = run(&mut r, 200_000);
    assert_eq!(r.v("cnc.alarms"), "0");
    let after: Vec<&str> = blocks
        .iter()
        .skip_while(|b| *b != "80")
        .map(String::as_str)
        .collect();
    assert_eq!(after, ["80", "30", "40", "50", "60", "80", "90"]);
    assert!(path.contains(&(20_000, -10_000)) && path.contains(&(40_000, -30_000)));
    assert_eq!(
        path.last(),
        Some(&(50_000, 2_000)),
        "back at the start point"
    );
}

#[test]
fn g72_faces_in_levels_along_z() {
    // From X50 Z2, Δd 2 in Z: Z0 to the end X10, Z-2 and Z-4 to the shoulder X30.
    let text = "O1;N1 G00 X50 Z2;N10 G72 W2 R0.5;N20 G72 P30 Q60 F600;\
                N30 G00 Z-6;N40 G01 X30;N50 Z-2;N60 X10;N70 M30";
    let mut r = Rig::mem(text);
    let (path, _) = run(&mut r, 200_000);
    assert_eq!(r.v("cnc.alarms"), "0");
    for p in [
        (10_000, 0),
        (30_000, -2_000),
        (30_000, -4_000),
        (30_000, -6_000),
        (10_000, -2_000),
    ] {
        assert!(path.contains(&p), "{p:?}");
    }
    assert!(!path.contains(&(10_000, -4_000)));
    assert_eq!(path.last(), Some(&(50_000, 2_000)));
}

#[test]
fn g73_repeats_the_profile_closer_each_time() {
    // Relief 3 mm in X (radius), 3 passes: offsets 3, 1.5 and 0 (plus U0.4: 0.2).
    for cycle in [
        "N10 G73 U3 W0 R3;N20 G73 P30 Q60 U0.4 W0 F600",
        "N20 G73 P30 Q60 I3 K0 U0.4 W0 D3 F600",
    ] {
        let text = format!("O1;N1 G00 X50 Z2;{cycle};{PROFILE}");
        let mut r = Rig::mem(&text);
        let (path, _) = run(&mut r, 200_000);
        assert_eq!(r.v("cnc.alarms"), "0", "{cycle}");
        for x in [26_400, 23_400, 20_400] {
            assert!(path.contains(&(x, -10_000)), "{cycle}: pass at X{x}");
        }
    }
}

#[test]
fn g74_pecks_with_the_return_of_its_first_block() {
    // From X0 Z2 to Z-20 in pecks of 5 mm, back 1 mm after each.
    let mut r = Rig::mem("O1;N1 G00 X0 Z2;N10 G74 R1;N20 G74 Z-20 Q5000 F600;N30 M30");
    let (path, _) = run(&mut r, 200_000);
    assert_eq!(r.v("cnc.alarms"), "0");
    let mut turns = Vec::new();
    for w in path.windows(3) {
        let (a, b, c) = (w[0].1, w[1].1, w[2].1);
        if (b < a && b < c) || (b > a && b > c) {
            turns.push(b);
        }
    }
    assert_eq!(
        turns,
        [
            -3_000, -2_000, -8_000, -7_000, -13_000, -12_000, -18_000, -17_000, -20_000
        ]
    );
    assert_eq!(path.last(), Some(&(0, 2_000)));
}

#[test]
fn g76_cuts_seven_passes_to_the_root_in_both_forms() {
    // Height 0.975, first 0.4, minimum 0.1, allowance 0.05, one finishing pass: depths 0.4,
    // 0.566, 0.693, 0.8, 0.9, 0.925, 0.975 (see the unit test of repeat.rs).
    for cycle in [
        "N10 G76 P011060 Q100 R0.05;N20 G76 X28.05 Z-20 P975 Q400 F1.5",
        "N20 G76 X28.05 Z-20 K975 D400 F1.5 A60",
    ] {
        let text = format!("O1;N1 M03 S600;N2 G00 X32 Z5;{cycle};N30 M30");
        let mut r = Rig::mem(&text);
        let (path, _) = run(&mut r, 400_000);
        assert_eq!(r.v("cnc.alarms"), "0", "{cycle}");
        // The passes start between Z5 and Z4.67 (the flank infeed moves them up to
        // 0.575 × tan 30° towards the thread).
        let mut passes: Vec<i64> = path
            .iter()
            .filter(|p| p.1 > 4_600 && p.0 < 32_000)
            .map(|p| p.0)
            .collect();
        passes.dedup();
        let want: Vec<i64> = [
            0.4,
            0.4 * 2f64.sqrt(),
            0.4 * 3f64.sqrt(),
            0.8,
            0.9,
            0.925,
            0.975,
        ]
        .iter()
        .map(|d| ((28.05 + 2.0 * (0.975 - d)) * 1000.0).round() as i64)
        .collect();
        passes.dedup();
        passes.retain(|x| want.contains(x));
        assert_eq!(passes, want, "{cycle}: X of each pass");
        assert_eq!(path.last(), Some(&(32_000, 5_000)));
    }
}

#[test]
fn bad_cycles_raise_fanuc_s_alarms() {
    let cases = [
        ("N20 G71 P30 U0.4 F600;N30 G00 X20;N40 G01 Z-10", 61),
        ("N20 G71 P30 Q99 F600;N30 G00 X20;N40 G01 Z-10", 63),
        ("N20 G71 P30 Q40 F600;N30 X20;N40 G01 Z-10", 65),
        ("N20 G71 P30 Q50 F600;N30 G00 X20;N40 G01 Z-10;N50 Z-5", 64),
        (
            "N20 G71 P30 Q50 F600;N30 G00 X20;N40 G01 X30 Z-10;N50 X25 Z-20",
            329,
        ),
        ("N20 G71 P30 Q40 D0 F600;N30 G00 X20;N40 G01 Z-10", 62),
        ("N20 G71 P30 Q40 F600;N30 G00 X20;N40 G04 P5", 66),
        ("N20 G76 X28 Z-20 K0 D400 F1.5", 62),
        // A million pecks of 0.001 mm: refused, not planned.
        ("N20 G74 Z-1000 Q1 F600", 62),
    ];
    for (cycle, alarm) in cases {
        let mut r = Rig::mem(&format!("O1;N1 G00 X50 Z2;{cycle};N90 M30"));
        run(&mut r, 10_000);
        assert_eq!(r.v(&format!("cnc.alarm.{alarm}")), "1", "{cycle}");
        assert_eq!(r.v("cnc.block"), "20", "{cycle}");
        assert_eq!((r.m(0), r.m(1)), (50_000, 2_000), "{cycle}: nothing moved");
    }
    // A type II profile (both axes in block P) may dip: no alarm.
    let mut r = Rig::mem(
        "O1;N1 G00 X50 Z2;N20 G71 P30 Q60 U0 W0 D2000 F600;N30 G00 X20 Z2;N40 G01 X30 Z-10;N50 X25 Z-20;N60 X40 Z-30;N70 M30",
    );
    let (path, _) = run(&mut r, 200_000);
    assert_eq!(r.v("cnc.alarms"), "0");
    assert!(
        path.contains(&(26_000, -19_250)) || path.iter().any(|p| p.0 == 26_000 && p.1 < -15_000),
        "the pocket is cut"
    );
}

#[test]
fn drilling_cycles_peck_dwell_and_stay_modal_until_g80() {
    // G83 from Z5 (the initial level): R-3 to the R point Z2, pecks of 4 mm to Z-8 (4 + 4 +
    // 2), each followed by a return to Z2; then back to Z5. The next block drills at X10.
    let text = "O1;N1 G00 X0 Z5;N2 G83 Z-8 R-3 Q4000 P100 F600;N3 X10;N4 G80;N5 G00 X30;N6 M30";
    let mut r = Rig::mem(text);
    let (path, blocks) = run(&mut r, 100_000);
    assert_eq!(r.v("cnc.alarms"), "0");
    let zs: Vec<i64> = path
        .iter()
        .filter(|p| p.0 == 0)
        .map(|p| p.1)
        .collect::<Vec<_>>()
        .windows(3)
        .filter(|w| (w[1] < w[0] && w[1] < w[2]) || (w[1] > w[0] && w[1] > w[2]))
        .map(|w| w[1])
        .collect();
    assert_eq!(
        zs,
        [5_000, -2_000, 2_000, -6_000, 2_000],
        "Z5 is where N1 arrives"
    );
    assert!(path.contains(&(0, -8_000)) && path.contains(&(10_000, -8_000)));
    assert!(blocks.contains(&"3".to_string()));
    assert_eq!(
        path.last(),
        Some(&(30_000, 5_000)),
        "G80, then a plain rapid"
    );
    // G85 bores out at feed: the way back from the bottom to R takes as long as the way in.
    let mut r = Rig::mem("O1;N1 G00 X0 Z2;N2 G85 Z-10 R0 F600;N3 M30");
    let (path, _) = run(&mut r, 100_000);
    let at_bottom = path.iter().filter(|p| p.1 == -10_000).count();
    let rising = path
        .windows(2)
        .filter(|w| w[1].1 > w[0].1 && w[0].1 < 0)
        .count();
    assert!(
        at_bottom >= 1 && rising == 125,
        "10 mm up to Z0 at 0.08 mm: {rising}"
    );
}

#[test]
fn g71_bores_from_inside_with_a_negative_allowance() {
    // From X18 Z2 (a drilled hole) out to a bore of X40, stepping in to X30: U-0.4 leaves the
    // allowance on the inside. Levels at radius 11 and 13 run to Z-29.9 (the profile ends at
    // radius 14.8); 15, 17 and 19 meet the moved taper from radius 19.8 at Z-9.9 to 14.8 at
    // Z-19.9: at Z-19.5, -15.5 and -11.5.
    let text = "O1;N1 G00 X18 Z2;N20 G71 P30 Q60 U-0.4 W0.1 D2000 F600;\
                N30 G00 X40;N40 G01 Z-10;N50 X30 Z-20;N60 Z-30;N70 M30";
    let mut r = Rig::mem(text);
    let (path, _) = run(&mut r, 400_000);
    assert_eq!(r.v("cnc.alarms"), "0");
    let inside = path.iter().filter(|p| p.1 < 0);
    assert!(
        inside.clone().all(|&(x, _)| x <= 39_600),
        "never past the allowance"
    );
    for (x, z) in [
        (22_000, -29_900),
        (26_000, -29_900),
        (30_000, -19_500),
        (34_000, -15_500),
        (38_000, -11_500),
    ] {
        assert!(path.contains(&(x, z)), "level X{x} ends at Z{z}");
    }
    assert_eq!(path.last(), Some(&(18_000, 2_000)));
}
