//! Custom Macro B on the simulated CNC, each construct against the result worked by hand in
//! docs/gcode.md, "Macros": arithmetic and functions, vacant variables, loops, G65/G66
//! calls, #3000, the #1000/#1100 handshake with the PLC, look-ahead and the macro alarms.

use crate::common::{Rig, Rng};
use ladder_engine::cnc::command::CncValue;

/// Runs a program from cycle start until it leaves RUN (at most `limit` exchanges).
fn run(text: &str, limit: u64) -> Rig {
    let mut r = Rig::mem(text);
    r.start();
    if r.v("cnc.run") == "RUN" {
        r.until(limit, |r| r.v("cnc.run") != "RUN");
    }
    r
}

/// A macro variable's value (`None`: vacant).
fn var(r: &Rig, n: u32) -> Option<f64> {
    match r.value(&format!("cnc.macro.{n}")) {
        CncValue::Macro(v) => v,
        v => panic!("{v:?}"),
    }
}

fn close(r: &Rig, n: u32, want: f64) {
    let v = var(r, n).unwrap_or_else(|| panic!("#{n} is vacant"));
    assert!((v - want).abs() < 1e-9, "#{n} = {v}, want {want}");
}

#[test]
fn arithmetic_follows_fanucs_precedence_and_functions_their_ranges() {
    let r = run(
        "O1;#100=1+2*3;#101=[1+2]*3;#102=10/4;#103=7MOD3;#104=-7MOD3;#105=2+3*4-6/2;\
         #106=SIN[30];#107=COS[180];#108=ATAN[1]/[-1];#109=ATAN[-1,-1];#110=ATAN[1];\
         #111=ROUND[-2.5];#112=FIX[-1.2];#113=FUP[-1.2];#114=FUP[1.2];#115=FIX[1.7];\
         #116=BCD[12];#117=BIN[18];#118=BIN[BCD[1234]];#119=5AND3;#120=5OR3;#121=5XOR3;\
         #122=POW[2,10];#123=LN[EXP[2]];#124=ABS[-3];#125=ACOS[0];#126=ASIN[-1];\
         #127=SQRT[16];#128=-#100;#129=TAN[45];#130=#[100+1]*2;#131=1+2 EQ 3;\
         #132=[1 EQ 1] AND [2 GT 1];#133=3*-2;M30",
        100,
    );
    let want = [
        (100, 7.0),
        (101, 9.0),
        (102, 2.5),
        (103, 1.0),
        (104, -1.0),
        (105, 11.0),
        (106, 0.5),
        (107, -1.0),
        (108, 135.0),
        (109, 225.0),
        (110, 45.0),
        (111, -3.0),
        (112, -1.0),
        (113, -2.0),
        (114, 2.0),
        (115, 1.0),
        (116, 18.0),
        (117, 12.0),
        (118, 1234.0),
        (119, 1.0),
        (120, 7.0),
        (121, 6.0),
        (122, 1024.0),
        (123, 2.0),
        (124, 3.0),
        (125, 90.0),
        (126, 270.0),
        (127, 4.0),
        (128, -7.0),
        (129, 1.0),
        (130, 18.0),
        (131, 1.0),
        (132, 1.0),
        (133, -6.0),
    ];
    assert!(r.cnc.alarms().is_empty(), "{:?}", r.cnc.alarms());
    for (n, v) in want {
        close(&r, n, v);
    }
}

#[test]
fn vacant_stays_vacant_alone_is_zero_in_arithmetic_and_differs_from_zero_in_eq() {
    let r = run(
        "O1;#100=#1;#101=#1*5;#102=#1+#1;IF[#1EQ#0]THEN#103=1;IF[#1EQ0]THEN#104=1;\
         IF[#1NE0]THEN#105=1;IF[#1GE0]THEN#106=1;IF[#1GT0]THEN#107=1;#108=-#1;\
         #109=SQRT[#1];N9 G00 X#1 W-1;M30",
        400,
    );
    assert!(r.cnc.alarms().is_empty(), "{:?}", r.cnc.alarms());
    assert_eq!(var(&r, 100), None);
    close(&r, 101, 0.0);
    close(&r, 102, 0.0);
    close(&r, 103, 1.0);
    assert_eq!(var(&r, 104), None, "vacant is not 0 for EQ");
    close(&r, 105, 1.0);
    close(&r, 106, 1.0);
    assert_eq!(var(&r, 107), None);
    assert_eq!(var(&r, 108), None, "the sign keeps vacant vacant");
    close(&r, 109, 0.0);
    // X#1 with #1 vacant: the address is left out, so only W moves.
    assert_eq!((r.m(0), r.m(1)), (0, -1_000));
}

#[test]
fn while_goto_and_nested_loops_count_as_worked_by_hand() {
    // Sum 1..10 = 55; 5! = 120 by IF/GOTO; three nested loops 3 × 4 × 5 = 60 passes.
    let r = run(
        "O1;#1=1;#100=0;WHILE[#1LE10]DO1;#100=#100+#1;#1=#1+1;END1;\
         #2=5;#101=1;N10#101=#101*#2;#2=#2-1;IF[#2GT1]GOTO10;\
         #102=0;#3=0;WHILE[#3LT3]DO1;#4=0;WHILE[#4LT4]DO2;#5=0;WHILE[#5LT5]DO3;\
         #102=#102+1;#5=#5+1;END3;#4=#4+1;END2;#3=#3+1;END1;#103=#2;M30",
        100,
    );
    assert!(r.cnc.alarms().is_empty(), "{:?}", r.cnc.alarms());
    close(&r, 100, 55.0);
    close(&r, 101, 120.0);
    close(&r, 102, 60.0);
    close(&r, 103, 1.0);
}

#[test]
fn g65_maps_arguments_by_both_specifications_and_gives_the_macro_its_own_locals() {
    let r = run(
        "O1;#1=99;G65P9001A1.B2.I3.J4.K5.I6.X7.Z8.;#110=#1;G65P9002L3;M30;\
         O9001;#101=#1;#102=#2;#104=#4;#105=#5;#106=#6;#107=#7;#124=#24;#126=#26;#103=#3;M99;\
         O9002;#111=#111+1;M99",
        200,
    );
    assert!(r.cnc.alarms().is_empty(), "{:?}", r.cnc.alarms());
    for (n, v) in [
        (101, 1.0),
        (102, 2.0),
        (104, 3.0),
        (105, 4.0),
        (106, 5.0),
        (107, 6.0),
        (124, 7.0),
        (126, 8.0),
    ] {
        close(&r, n, v);
    }
    assert_eq!(var(&r, 103), None, "C was not given");
    close(&r, 110, 99.0);
    // L3: three calls; #111 starts vacant (0 in arithmetic).
    close(&r, 111, 3.0);
}

#[test]
fn g66_calls_after_each_move_until_g67_and_not_for_moves_inside_the_macro() {
    let r = run(
        "O1;G66P9003A2.;G01W-1.F6000;G01W-1.;G04X0.01;G67;G01W-1.;M30;\
         O9003;#120=#120+#1;#121=#5001;G01U0.1;M99",
        2_000,
    );
    assert!(r.cnc.alarms().is_empty(), "{:?}", r.cnc.alarms());
    // Two moves under G66 (the dwell is not a move): A2 added twice.
    close(&r, 120, 4.0);
    // #5001: the X end point of the block read last (the macro's own U0.1 moves from 0.1).
    close(&r, 121, 0.1);
    assert_eq!((r.m(0), r.m(1)), (200, -3_000));
}

#[test]
fn a_3000_alarm_stops_with_its_number_and_message_and_reset_clears_it() {
    let mut r = run("O1;#100=5;#3000=12(DOOR OPEN);#100=6;M30", 50);
    assert_eq!(r.cnc.alarms(), &[3012]);
    assert_eq!(r.cnc.macro_alarm_message(3012), Some("DOOR OPEN"));
    assert_eq!(r.v("cnc.run"), "STOP");
    close(&r, 100, 5.0);
    // MA (F1.7) falls as for any CNC alarm; reset clears the alarm (and #100, CCV = 0).
    assert!(!r.fb(1, 7));
    r.cmd(&["reset"]);
    r.xs(2);
    assert!(r.cnc.alarms().is_empty());
    assert_eq!(var(&r, 100), None);
    // #6001 bit 6 CCV = 1 keeps the common variables over a reset.
    let mut r = run("O1;#100=5;M30", 50);
    r.cmd(&["param", "6001", "64"]);
    r.cmd(&["reset"]);
    r.xs(2);
    close(&r, 100, 5.0);
}

/// One exchange with a "ladder" that answers #1100 (F214.0) on #1000 (G214.0) from the F of
/// the exchange before, as a scan between exchanges would.
fn echo(r: &mut Rig) {
    let answer = r.fb(214, 0);
    r.set(214, 0, answer);
    r.x();
}

#[test]
fn a_macro_waiting_in_while_sees_the_plc_answer_at_the_next_exchange() {
    let mut r = Rig::mem(
        "O1;N1#1100=1;N2WHILE[#1000EQ0]DO1;N3END1;N4#1100=0;N5WHILE[#1000EQ1]DO1;N6END1;\
         N7#101=#101+1;N8M30",
    );
    let s = r.start();
    // The start exchange: #1100 = 1 goes out in that exchange's F; the loop waits.
    assert!(r.fb(214, 0));
    assert_eq!(r.n, s);
    // The ladder answers from that F; the next exchange reads #1000 = 1, leaves the loop and
    // takes #1100 back to 0 in the same exchange.
    echo(&mut r);
    assert!(!r.fb(214, 0));
    assert_eq!(r.v("cnc.run"), "RUN");
    // The ladder drops G214.0; the second loop ends and the program reaches M30.
    echo(&mut r);
    r.xs(3);
    assert_eq!(r.v("cnc.run"), "IDLE");
    close(&r, 101, 1.0);
    assert!(r.cnc.alarms().is_empty());
}

#[test]
fn a_dispatcher_waits_a_long_time_for_an_idle_plc_without_an_alarm() {
    // An hour's dispatcher loop with nobody answering: one pass per exchange, no P/S 0079.
    let mut r = Rig::mem("O1;N1#1100=1;N2WHILE[#1000EQ0]DO1;N3#102=#3001;N4END1;N5M30");
    r.start();
    r.xs(7_500); // one minute
    assert_eq!(r.v("cnc.run"), "RUN");
    assert!(r.cnc.alarms().is_empty(), "{:?}", r.cnc.alarms());
    // #3001 counts milliseconds of the virtual clock.
    let t = var(&r, 102).unwrap();
    assert!((59_000.0..=60_100.0).contains(&t), "{t}");
    // Reset stops it.
    r.cmd(&["reset"]);
    r.xs(2);
    assert_eq!(r.v("cnc.run"), "IDLE");
}

#[test]
fn statements_after_a_move_run_when_it_starts_unless_its_m_code_is_in_3411() {
    // N2 runs ahead: #1100 is 1 while N1 still moves (10 mm at F600: 125 exchanges).
    let mut r = Rig::mem("O1;N1G01W-10.F600;N2#1100=1;N3G01W-1.;N4M30");
    let s = r.start();
    assert!(r.fb(214, 0), "set in the exchange N1 starts");
    assert_eq!(r.n, s);
    assert_eq!(r.v("cnc.block"), "1");
    // An M code of #3411–#3420 stops the look-ahead: #1100 waits for M50's FIN.
    let mut r = Rig::mem("O1;N1G01W-10.F600M50;N2#1100=1;N3M30");
    r.cmd(&["param", "3411", "50"]);
    r.start();
    r.xs(20);
    assert!(!r.fb(214, 0));
    let k = r.until(400, |r| r.fb(214, 0));
    assert_eq!(r.m(1), -10_000, "set only after N1 ended (exchange {k})");
    // Single block: no look-ahead, and the statements do not stop (#6000 bit 5 SBM = 0).
    let mut r = Rig::mem("O1;N1G01W-1.F600;N2#1100=1;N3#101=2;N4G01W-1.;N5M30");
    r.set(46, 1, true); // SBK
    r.start();
    r.until(100, |r| r.v("cnc.run") == "STOP");
    assert!(!r.fb(214, 0));
    assert_eq!(r.v("cnc.block"), "1");
    r.start();
    r.until(100, |r| r.v("cnc.run") == "STOP");
    assert!(r.fb(214, 0));
    close(&r, 101, 2.0);
    assert_eq!(r.v("cnc.block"), "4");
    assert_eq!(r.m(1), -2_000);
}

#[test]
fn each_macro_alarm_names_its_block() {
    let cases = [
        ("#1=1/0", 112),
        ("#1=7MOD0", 112),
        ("#1=[1+", 114),
        ("#1=SIN 30", 114),
        ("#200=1", 115),
        ("#1=#9999", 115),
        ("#1000=1", 116),
        ("#0=1", 116),
        ("#5001=1", 116),
        ("#1=[[[[[[1]]]]]]", 118),
        ("#1=SQRT[-1]", 119),
        ("#1=BIN[10]", 119),
        ("#1100=2", 119),
        ("#3000=201", 119),
        ("WHILE[1]DO1", 124),
        ("END1", 124),
        ("WHILE[1]DO4", 126),
        ("G00X1#1=2", 127),
        ("#1=2X1", 127),
        ("GOTO99", 128),
        ("GOTO0", 128),
        ("G65P9001G1", 129),
        ("G65A1", 129),
        ("G65P7777", 76),
        ("#1=EXP[1000]", 111),
    ];
    for (block, alarm) in cases {
        let r = run(&format!("O1;N5#100=1;N7{block};N8#100=2;M30;O9001;M99"), 20);
        assert_eq!(r.cnc.alarms(), &[alarm], "{block}");
        assert_eq!(r.v("cnc.block"), "7", "{block}");
        assert_eq!(r.v("cnc.run"), "STOP", "{block}");
        close(&r, 100, 1.0);
    }
    // Macro calls nest five deep; the sixth is P/S 0077.
    let r = run("O1;#100=0;G65P9001;M30;O9001;#100=#100+1;G65P9001;M99", 50);
    assert_eq!(r.cnc.alarms(), &[77]);
    close(&r, 100, 5.0);
}

#[test]
fn system_variables_read_offsets_modal_state_clock_and_positions() {
    let mut r = Rig::mem(
        "O1;G98G01W-2.F300T0101S500;#100=#4001;#101=#4005;#102=#4109;#103=#4120;\
         #104=#2001;#105=#2701;#106=#5041;#107=#5021;#108=#5002;#109=#3011;#110=#3012;\
         #2002=-0.05;#2801=1.5;#2501=10.;#111=#4115;#112=#4114;N77#113=#4114;M30",
    );
    r.cmd(&["offset", "1", "wx", "0.02"]);
    r.cmd(&["offset", "1", "x", "-100"]);
    r.cmd(&["clock", "2026-03-04T05:06:07"]);
    r.start();
    r.until(2_000, |r| r.v("cnc.run") != "RUN");
    assert!(r.cnc.alarms().is_empty(), "{:?}", r.cnc.alarms());
    close(&r, 100, 1.0);
    close(&r, 101, 98.0);
    close(&r, 102, 300.0);
    close(&r, 103, 101.0);
    close(&r, 104, 0.02);
    close(&r, 105, -100.0);
    // Read ahead, as the G01 starts: the tool is still at Z0, the block ends at Z−2.
    close(&r, 106, 0.0);
    close(&r, 107, 0.0);
    close(&r, 108, -2.0);
    close(&r, 109, 20_260_304.0);
    assert!(var(&r, 110).unwrap() >= 50_607.0);
    assert_eq!(r.v("cnc.offset.2.WX"), "-0.050");
    assert_eq!(r.v("cnc.offset.1.Z"), "1.500");
    assert_eq!(r.v("cnc.work.G54.X"), "10.000");
    close(&r, 111, 1.0);
    close(&r, 113, 77.0);
}

/// A random expression of depth at most `depth`, valid or not.
fn expression(r: &mut Rng, depth: u32) -> String {
    const ATOMS: [&str; 14] = [
        "#1", "#2", "#100", "#0", "#[#1+1]", "1.5", "-2", "0", "#1000", "#3001", "#4001", "#5041",
        "#9999", "#[-1]",
    ];
    const OPS: [&str; 15] = [
        "+", "-", "*", "/", " MOD ", " AND ", " OR ", " XOR ", " EQ ", " NE ", " GT ", " LE ", "",
        "[", "]",
    ];
    const FUNCS: [&str; 17] = [
        "SIN", "COS", "TAN", "ASIN", "ACOS", "ATAN", "SQRT", "ABS", "ROUND", "FIX", "FUP", "LN",
        "EXP", "BIN", "BCD", "POW", "ATA",
    ];
    if depth == 0 || r.index(3) == 0 {
        return ATOMS[r.index(ATOMS.len())].to_string();
    }
    match r.index(4) {
        0 => {
            // Mostly operators that read; now and then a broken one.
            let op = if r.index(10) == 0 {
                OPS[r.index(OPS.len())]
            } else {
                OPS[r.index(12)]
            };
            format!(
                "{}{op}{}",
                expression(r, depth - 1),
                expression(r, depth - 1)
            )
        }
        1 => format!("[{}]", expression(r, depth - 1)),
        2 => format!(
            "{}[{}]",
            FUNCS[r.index(FUNCS.len() - 2)],
            expression(r, depth - 1)
        ),
        _ => format!(
            "{}[{},{}]",
            FUNCS[r.index(FUNCS.len())],
            expression(r, depth - 1),
            expression(r, depth - 1)
        ),
    }
}

/// A random block: a statement, a word with an expression, a loop keyword or a call.
fn block(r: &mut Rng, n: usize) -> String {
    let e = expression(r, 4);
    let target = ["#1", "#2", "#100", "#[#1]", "#1100", "#3000", "#0", "#5001"][r.index(8)];
    match r.index(10) {
        0 => format!("N{n} IF[{e}]GOTO{}", r.index(12)),
        1 => format!("N{n} IF[{e}]THEN{target}={}", expression(r, 2)),
        2 => format!("N{n} WHILE[{e}]DO{}", r.index(5)),
        3 => format!("N{n} END{}", r.index(5)),
        4 => format!("N{n} G01 U[{e}] W-0.1 F6000"),
        5 => format!("N{n} G65 P9{} A[{e}] I1 J2 K3 I4", r.index(3)),
        6 => format!("N{n} GOTO[{e}]"),
        7 => format!("N{n} G#{} X#1", r.index(3)),
        _ => format!("N{n} {target}={e}"),
    }
}

#[test]
fn random_macro_text_never_panics_or_hangs_and_reset_stops_any_loop() {
    // Seeded: the same programs every run. Each runs 300 exchanges (statements are bounded
    // per exchange, so an endless loop only keeps the program in RUN), then reset must leave
    // it IDLE.
    for seed in 1..=200u64 {
        let mut r = Rng(seed.wrapping_mul(0x9E37_79B9_7F4A_7C15) | 1);
        let mut text = String::from("O1\n");
        for n in 1..=12 {
            text.push_str(&block(&mut r, n));
            text.push('\n');
        }
        text.push_str("M30\nO90\n#1=#1+1\nM99\nO91\nG65P91\nM99\nO92\nWHILE[1]DO1\nEND1\n");
        let mut rig = Rig::mem(&text);
        rig.set(214, 0, r.index(2) == 1);
        rig.start();
        rig.xs(300);
        let run = rig.v("cnc.run");
        assert!(["RUN", "STOP", "IDLE"].contains(&run.as_str()), "{text}");
        let _ = rig.cnc.toolpath();
        rig.cmd(&["reset"]);
        rig.xs(2);
        assert_eq!(rig.v("cnc.run"), "IDLE", "seed {seed}:\n{text}");
    }
}

#[test]
fn asin_and_atan_follow_nat_and_round_in_an_address_rounds_to_its_increment() {
    // #6004 bit 0 NAT = 0 (the default): ASIN 270…90°, ATAN[y,x] 0…360°; NAT = 1: −90…90° and
    // −180…180°.
    let r = run("O1;#100=ASIN[-0.5];#101=ATAN[-1,-1];#102=ATAN[-1];M30", 50);
    close(&r, 100, 330.0);
    close(&r, 101, 225.0);
    close(&r, 102, 315.0);
    let mut r = Rig::mem("O1;#100=ASIN[-0.5];#101=ATAN[-1,-1];#102=ATAN[-1];M30");
    r.cmd(&["param", "6004", "1"]);
    r.start();
    r.xs(5);
    close(&r, 100, -30.0);
    close(&r, 101, -135.0);
    close(&r, 102, -45.0);
    // ROUND in X rounds to 0.001 mm; in a statement to a whole number.
    let r = run("O1;#1=12.3456;#100=ROUND[#1];G00X[ROUND[#1]];M30", 500);
    close(&r, 100, 12.0);
    assert_eq!(r.m(0), 12_346);
}

#[test]
fn variables_work_in_profiles_corners_and_cycle_depths() {
    // A G71 profile whose X comes from a variable, finished by G70.
    let r = run(
        "O1;#1=30.;G00X40.Z2.;G71U1.R0.5;G71P10Q20U0.2W0.1F6000;N10G00X#1;N20G01Z-10.;\
         G70P10Q20;M30",
        20_000,
    );
    assert!(r.cnc.alarms().is_empty(), "{:?}", r.cnc.alarms());
    assert_eq!(r.v("cnc.run"), "IDLE");
    // `,C` before a block whose Z is a variable.
    let r = run("O1;#1=-10.;G01X20.,C1.F3000;Z#1;M30", 2_000);
    assert!(r.cnc.alarms().is_empty(), "{:?}", r.cnc.alarms());
    assert_eq!((r.m(0), r.m(1)), (20_000, -10_000));
    // Q from a variable is whole least increments, as Q2000 written: the same pecks.
    let count = |text: &str| {
        let mut r = Rig::mem(text);
        r.start();
        let mut retracts = 0;
        let mut last = 0;
        while r.v("cnc.run") == "RUN" && r.n < 20_000 {
            r.x();
            if r.m(1) > last {
                retracts += 1;
            }
            last = r.m(1);
        }
        assert!(r.cnc.alarms().is_empty(), "{text}: {:?}", r.cnc.alarms());
        retracts
    };
    let written = count("O1;G74R1.;G74Z-10.Q2000F600;M30");
    assert_eq!(count("O1;#17=2000;G74R1.;G74Z-10.Q#17F600;M30"), written);
    assert!(written > 3, "{written}");
}

#[test]
fn g66_is_not_called_from_a_g70_profile_and_long_text_is_refused_not_overflowed() {
    let r = run(
        "O1;G00X20.Z2.;G66P9003;G70P10Q20;G67;#101=1;M30;N10G01X10.F6000;N20Z-1.;\
         O9003;#120=#120+1;M99",
        5_000,
    );
    assert_eq!(r.v("cnc.run"), "IDLE");
    close(&r, 101, 1.0);
    // The profile's moves run under G66 but call nothing (the G00 came before G66).
    assert_eq!(var(&r, 120), None);
    // A run of 30 000 signs is no stack overflow: the block is too long (0114).
    let long = format!("O1;#100={}1;M30", "-".repeat(30_000));
    let r = run(&long, 20);
    assert_eq!(r.cnc.alarms(), &[114]);
    // 500 signs fit in a block and read as one minus sign's parity.
    let r = run(&format!("O1;#100={}1;M30", "-".repeat(501)), 20);
    close(&r, 100, -1.0);
    let chain = format!("O1;#100=1{};M30", "+1".repeat(500));
    let r = run(&chain, 20);
    close(&r, 100, 501.0);
}

#[test]
fn macro_3003_suppresses_single_block_and_3004_feed_hold() {
    // #3003 = 1: N2 runs through in single block. N4 (#3003 = 0) runs ahead while N3 moves,
    // so single block is back when N3 ends and the program stops there.
    let mut r = Rig::mem("O1;N1#3003=1;N2G01W-1.F6000;N3G01W-1.;N4#3003=0;N5G01W-1.;N6M30");
    r.set(46, 1, true); // SBK
    r.start();
    r.until(200, |r| r.v("cnc.run") != "RUN");
    assert_eq!(r.v("cnc.run"), "STOP");
    assert_eq!(r.v("cnc.block"), "3");
    assert_eq!(r.m(1), -2_000);
    // #3004 = 1: feed hold does nothing while it is set. N4 runs ahead of N3 (the dwell
    // stops the look-ahead at N2), so N2 moves through feed hold and N3 holds.
    let mut r = Rig::mem("O1;N1#3004=1;N2G01W-10.F600;N3G04X1.;N4#3004=0;N5G01W-10.;N6M30");
    r.start();
    r.xs(10);
    r.set(8, 5, false); // *SP: feed hold
    r.xs(10);
    assert_eq!(
        (r.v("cnc.run").as_str(), r.v("cnc.block").as_str()),
        ("RUN", "2")
    );
    r.until(400, |r| r.v("cnc.run") != "RUN");
    assert_eq!(r.v("cnc.run"), "HOLD");
    assert_eq!(r.v("cnc.block"), "3");
    assert_eq!(r.m(1), -10_000);
}

#[test]
fn the_toolpath_runs_macro_statements_dry_and_ends_at_a_loop_waiting_for_the_plc() {
    // Three rapids computed in WHILE (X10, X12, X14), then a wait for #1000 that the dry run
    // cannot pass: the path has the three moves and no alarm; the CNC's variables are not
    // touched.
    let r = Rig::mem(
        "O1;#1=0;WHILE[#1LT3]DO1;G00X[10+#1*2];#1=#1+1;END1;WHILE[#1000EQ0]DO1;END1;G00X40.;M30",
    );
    let t = r.cnc.toolpath();
    assert_eq!(t.alarm, None);
    assert_eq!(t.blocks, 3);
    assert_eq!(t.pieces.len(), 3);
    let last = t.points.last().unwrap();
    assert!((last[1] - 14.0).abs() < 1e-9, "{last:?}");
    assert_eq!(var(&r, 1), None);
}

#[test]
fn a_3006_stop_waits_for_cycle_start_and_output_commands_do_nothing() {
    // #3006 stops after its block with the message; cycle start goes on. POPEN, DPRNT and
    // PCLOS have no device and pass; #3901/#3902 are the parts counters (#6711/#6713).
    let mut r = Rig::mem(
        "O1;N1#100=1;N2#3006=1(TURN THE PART OVER);N3POPEN;N4DPRNT[PART*#100[30]];N5PCLOS;\
         N6#3901=#3901+5;N7#3902=9;N8#101=#5081+#5101;N9M30",
    );
    r.start();
    r.xs(3);
    assert_eq!(r.v("cnc.run"), "STOP");
    assert_eq!(r.v("cnc.block"), "2");
    assert_eq!(
        r.cnc.status().stop_message.as_deref(),
        Some("TURN THE PART OVER")
    );
    assert!(r.cnc.alarms().is_empty());
    r.start();
    r.xs(5);
    assert_eq!(r.v("cnc.run"), "IDLE");
    assert_eq!(r.cnc.status().stop_message, None);
    // M30 counted one more on top of the 5 the program added.
    assert_eq!(r.v("cnc.param.6711"), "6");
    assert_eq!(r.v("cnc.param.6713"), "9");
    close(&r, 101, 0.0);
}

#[test]
fn statements_waiting_ahead_go_on_during_the_move_when_the_plc_answers() {
    // N2-N4 run ahead of N1's 10 mm at F600 (125 exchanges) and wait; the ladder answers at
    // s+1 and N5 sets #1101 in that exchange, while Z still moves. N6 waits for N1's end.
    let mut r = Rig::mem(
        "O1;N1G01W-10.F600;N2#1100=1;N3WHILE[#1000EQ0]DO1;N4END1;N5#1101=1;N6G01W-1.;N7M30",
    );
    let s = r.start();
    assert!(r.fb(214, 0) && !r.fb(214, 1));
    echo(&mut r);
    assert_eq!(r.n, s + 1);
    assert!(r.fb(214, 1), "#1101 set during the move");
    assert_eq!(r.v("cnc.block"), "1");
    assert!(r.m(1) > -1_000, "Z has hardly moved: {}", r.m(1));
    r.until(400, |r| r.v("cnc.block") == "6");
    // N6 starts once N1 has ended at Z−10 and moves 0.08 mm in its first exchange.
    assert_eq!(r.m(1), -10_080);
}

#[test]
fn m99_p_returns_to_the_numbered_block_of_the_caller_or_of_the_main_program() {
    // From O2, M99 P4 skips N3; in the main program M99 P1 loops to N1 until #100 reaches 3.
    let r = run(
        "O1;N1#100=0;N2M98P2;N3#100=#100+100;N4#100=#100+1;N5M30;O2;N10#101=1;N20M99P4",
        50,
    );
    close(&r, 100, 1.0);
    close(&r, 101, 1.0);
    let r = run("O1;N1#100=#100+1;N2IF[#100GE3]GOTO9;N3M99P1;N9M30", 50);
    close(&r, 100, 3.0);
    assert_eq!(r.v("cnc.run"), "IDLE");
    let r = run("O1;N1M98P2;N2M30;O2;N10M99P77", 50);
    assert_eq!(r.cnc.alarms(), &[63]);
}

#[test]
fn a_statement_run_ahead_that_fails_names_its_own_block_and_line() {
    let mut r = Rig::mem("O1\nN1 G01 W-10. F600\nN2 #1=1/0\nN3 M30\n");
    r.start();
    r.x();
    assert_eq!(r.cnc.alarms(), &[112]);
    assert_eq!(r.v("cnc.block"), "2");
    assert_eq!(r.cnc.status().line, Some(3));
    assert_eq!(r.v("cnc.run"), "STOP");
}

#[test]
fn a_3006_run_ahead_or_in_then_stops_and_m99_p_leaves_a_repeated_call() {
    // Run ahead of N1: the stop comes when N1 has ended; cycle start goes on with N3.
    let mut r = Rig::mem("O1;N1G01W-1.F600;N2#3006=1(FLIP);N3G01W-1.;N4M30");
    r.start();
    r.until(100, |r| r.v("cnc.run") != "RUN");
    assert_eq!(r.v("cnc.run"), "STOP");
    assert_eq!(r.m(1), -1_000);
    assert_eq!(r.cnc.status().stop_message.as_deref(), Some("FLIP"));
    r.start();
    r.until(100, |r| r.v("cnc.run") != "RUN");
    assert_eq!((r.v("cnc.run").as_str(), r.m(1)), ("IDLE", -2_000));
    // IF … THEN #3006 stops too.
    let r = run("O1;N1IF[#1EQ#0]THEN#3006=2(NO DATA);N2#100=1;N3M30", 20);
    assert_eq!(r.v("cnc.run"), "STOP");
    assert_eq!(var(&r, 100), None);
    // M99 P3 from a call with a repeat left returns to the caller's N3 at once.
    let r = run("O1;N1M98P2L2;N2#100=5;N3M30;O2;N10#101=#101+1;N20M99P3", 50);
    assert_eq!(var(&r, 100), None);
    close(&r, 101, 1.0);
    assert!(r.cnc.alarms().is_empty());
}

#[test]
fn the_dry_run_reports_a_statement_that_fails_ahead_and_passes_a_3006_stop() {
    let r = Rig::mem("O1\nG00U1.\n#1=1/0\nG00U1.\nM30\n");
    assert_eq!(r.cnc.toolpath().alarm, Some((112, 3)));
    let r = Rig::mem("O1;#3006=1(LOAD);G00U2.;M30");
    let t = r.cnc.toolpath();
    assert_eq!((t.alarm, t.pieces.len()), (None, 1));
}
