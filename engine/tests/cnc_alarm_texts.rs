//! The CNC panel's alarm texts for alarms raised the way a machine raises them: program
//! errors, E-stop, overtravel and a PLC alarm (docs/cnc.md, "Alarms").

use crate::common::Rig;
use ladder_engine::cnc::Mode;
use ladder_engine::cnc::alarm_text::{TEXTS, alarm_text};

/// Every active alarm of the rig has its own text in both languages; returns them.
fn texts_of_active(r: &Rig) -> Vec<(u16, String, String)> {
    let active = r.cnc.alarms();
    assert!(!active.is_empty(), "an alarm is active");
    active
        .iter()
        .map(|&n| {
            assert!(
                TEXTS.iter().any(|t| t.number == n),
                "alarm {n:04} raised by the simulator has no text of its own"
            );
            (n, alarm_text(n, true).into(), alarm_text(n, false).into())
        })
        .collect()
}

#[test]
fn program_errors_show_their_own_text() {
    let cases = [
        ("N10 T12345", 3, "Too many digits"),
        ("N10 G01 W-1 X1 X2", 9, "Improper address or value"),
        ("N10 G02.5 X1", 10, "Improper G code"),
        ("N10 G02 W-1 F1", 22, "Arc without R or I, K"),
        ("N10 G02 W-30 R10 F1", 20, "Arc radius out of tolerance"),
        ("N10 G01 W-5", 11, "No feedrate commanded"),
        ("N10 M1 M2 M3 M4", 14, "Too many M codes"),
        ("N10 M98 P55", 76, "Subprogram not found"),
        ("N10 G28 U0", 90, "Reference point not established"),
    ];
    for (block, alarm, en) in cases {
        let mut r = Rig::new();
        r.mode(Mode::Mem);
        r.x();
        r.program(&format!("O0001;N5;{block}"));
        r.start();
        r.x();
        assert_eq!(
            texts_of_active(&r),
            [(alarm, alarm_text(alarm, true).into(), en.into())]
        );
    }
}

#[test]
fn machine_alarms_show_their_own_text() {
    // E-stop.
    let mut r = Rig::new();
    r.set(8, 4, false);
    r.x();
    assert_eq!(
        texts_of_active(&r),
        [(950, "急停报警".into(), "Emergency stop".into())]
    );
    // Hardware overtravel, + and − of Z.
    for (byte, alarm, zh) in [(114, 506, "正向硬限位超程"), (116, 507, "负向硬限位超程")]
    {
        let mut r = Rig::new();
        r.set(byte, 1, false);
        r.x();
        let texts = texts_of_active(&r);
        assert_eq!(texts.len(), 1);
        assert_eq!((texts[0].0, texts[0].1.as_str()), (alarm, zh));
    }
    // The stored stroke limit, running into +1 mm of Z in JOG.
    let mut r = Rig::new();
    r.home(&[1]);
    r.cmd(&["param", "1320", "2", "1000"]);
    r.mode(Mode::Jog);
    r.set(100, 1, true);
    r.xs(10);
    assert_eq!(
        texts_of_active(&r),
        [(
            500,
            "正向软限位超程".into(),
            "Soft limit overtravel (+)".into()
        )]
    );
}

#[test]
fn a_plc_alarm_shows_the_generic_text_the_message_table_replaces() {
    let mut r = Rig::new();
    r.a[0] = 1; // A0.0, no message table: alarm 1000
    r.x();
    assert_eq!(r.cnc.alarms(), [1000]);
    assert_eq!(alarm_text(1000, false), "PLC alarm");
    assert_eq!(alarm_text(1000, true), "PLC报警");
}
