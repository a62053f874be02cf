//! Operation preparation, modes, the spindle, manual operation and overtravel of the
//! simulated CNC (docs/cnc.md, "Operation preparation", "Spindle", "Manual operation").

use crate::common::Rig;
use ladder_engine::cnc::Mode;
use ladder_engine::model::tables::{Message, MessageTable};

#[test]
fn every_mode_code_gives_its_mode_and_confirm_bit() {
    let mut r = Rig::new();
    r.x();
    assert!(r.fb(3, 3), "MDI at G43 = 0");
    let cases = [
        (3u8, "EDIT", (3, 6)),
        (1, "MEM", (3, 5)),
        (0, "MDI", (3, 3)),
        (4, "HANDLE", (3, 1)),
        (5, "JOG", (3, 2)),
        (33, "DNC", (3, 4)),
        (133, "REF", (4, 5)),
    ];
    for (code, name, (byte, bit)) in cases {
        r.g[43] = code;
        r.x();
        assert_eq!(r.v("cnc.mode"), name);
        assert!(r.fb(byte, bit), "{name}");
        let confirms = (0..7).filter(|b| r.fb(3, *b)).count() + usize::from(r.fb(4, 5));
        assert_eq!(confirms, 1, "{name}: one confirm bit");
    }
    // An undefined code keeps the mode; bits outside 0xA7 are ignored.
    r.g[43] = 2;
    r.x();
    assert_eq!(r.v("cnc.mode"), "REF");
    r.g[43] = 1 | 0x08;
    r.x();
    assert_eq!(r.v("cnc.mode"), "MEM");
}

#[test]
fn e_stop_raises_0950_drops_sa_and_ma_stays_for_plc_alarms() {
    let mut r = Rig::new();
    r.x();
    assert!(r.fb(1, 7) && r.fb(0, 6) && !r.fb(1, 0), "MA, SA, no AL");
    r.set(8, 4, false);
    r.x();
    assert_eq!(r.v("cnc.alarm.950"), "1");
    assert!(!r.fb(1, 7) && !r.fb(0, 6) && r.fb(1, 0) && r.fb(1, 1));
    r.set(8, 4, true);
    r.x();
    assert_eq!(
        r.v("cnc.alarms"),
        "0",
        "0950 ends at the first exchange with *ESP = 1"
    );
    assert!(r.fb(1, 7) && r.fb(0, 6));
    // A servo alarm drops SA; reset clears it.
    r.cmd(&["alarm", "410"]);
    r.x();
    assert!(!r.fb(0, 6) && !r.fb(1, 7));
    r.cmd(&["reset"]);
    r.x();
    assert!(r.fb(0, 6) && r.fb(1, 7));
}

#[test]
fn plc_alarms_follow_the_message_table() {
    let mut t = MessageTable::default();
    t.rows[0] = Message {
        number: Some(1001),
        ..Message::default()
    };
    t.rows[1] = Message {
        number: Some(2001),
        ..Message::default()
    };
    let mut r = Rig::with(ladder_engine::ProfileId::Gsk988ta, &t);
    r.a[0] = 0b111;
    r.x();
    assert_eq!(
        r.cnc.alarms(),
        &[1001],
        "2001 is an operator message; A0.2 has no number"
    );
    assert!(r.fb(1, 0) && r.fb(1, 7), "AL, MA");
    r.a[0] = 0;
    r.x();
    assert!(r.cnc.alarms().is_empty());
}

#[test]
fn the_spindle_output_follows_the_table_of_the_manual() {
    let mut r = Rig::new();
    r.mode(Mode::Mdi);
    r.cmd(&["mdi", "S1500"]);
    r.set(4, 3, true);
    r.start();
    assert_eq!(r.v("cnc.spindle"), "1500");
    assert!(r.fb(1, 4), "ENB");
    assert_eq!(r.fv(40, 2), 1500, "AR");
    assert_eq!(
        r.fv(36, 2),
        (4095.0f64 * 1500.0 / 2000.0).round() as u32,
        "S12"
    );
    r.g[30] = 12; // 120 %: 1800
    r.x();
    assert_eq!(r.v("cnc.spindle"), "1800");
    r.g[30] = 20; // saturates at 120 %; gear 1 maximum is 2000
    r.x();
    assert_eq!(r.v("cnc.spindle"), "1800");
    r.g[30] = 15;
    r.g[28] = 0b110; // GR2 GR1 = 11: #3744 = 5000
    r.x();
    assert_eq!(r.v("cnc.spindle"), "1800");
    r.g[30] = 10;
    r.g[28] = 0;
    r.set(29, 6, false);
    r.x();
    assert_eq!(r.v("cnc.spindle"), "0", "*SSTP = 0");
    assert!(!r.fb(1, 4));
    r.set(29, 6, true);
    r.set(38, 7, true); // SIND with RI = 4095: Gmax
    r.g[32] = 0xFF;
    r.g[33] = 0x0F;
    r.x();
    assert_eq!(r.v("cnc.spindle"), "2000");
    assert_eq!(r.fv(36, 2), 4095);
    r.set(8, 4, false);
    r.x();
    assert_eq!(r.v("cnc.spindle"), "0", "E-stop first");
}

#[test]
fn jog_moves_160_increments_of_z_per_exchange_at_1200_and_100_percent() {
    let mut r = Rig::new();
    r.mode(Mode::Jog);
    r.x();
    r.set(100, 1, true);
    r.x();
    assert_eq!(r.m(1), 160);
    r.xs(4);
    assert_eq!(r.m(1), 800);
    assert!(r.fb(102, 1) && !r.fb(106, 1));
    r.set(102, 1, true);
    r.x();
    assert_eq!(r.m(1), 800, "both keys: no motion");
    r.set(100, 1, false);
    r.x();
    assert_eq!(r.m(1), 640);
    assert!(r.fb(106, 1), "MVD");
    r.set(102, 1, false);
    // X is a diameter axis: 320 increments; RT = 1: rapid #1420 = 6000: 800 µm radius.
    r.set(100, 0, true);
    r.x();
    assert_eq!(r.m(0), 320);
    r.set(19, 7, true);
    r.x();
    assert_eq!(r.m(0), 320 + 1600);
    assert!(r.fb(2, 1), "RPDO");
    // Blocked by E-stop, by the PLC claiming the axis, by *IT.
    r.set(19, 7, false);
    let x = r.m(0);
    r.set(136, 0, true);
    r.x();
    assert_eq!(r.m(0), x, "EAX1: the axis is under PLC control");
    r.set(136, 0, false);
    r.set(8, 0, false);
    r.x();
    assert_eq!(r.m(0), x);
    r.set(8, 0, true);
    r.x();
    assert_eq!(r.m(0), x + 320);
}

#[test]
fn manual_absolute_off_keeps_the_absolute_position() {
    let mut r = Rig::new();
    r.mode(Mode::Jog);
    r.set(6, 2, true);
    r.x();
    assert!(!r.fb(4, 2), "MABSM = NOT ABSM");
    r.set(100, 1, true);
    r.xs(5);
    assert_eq!(r.v("cnc.pos.Z"), "0.800");
    assert_eq!(r.v("cnc.abs.Z"), "0.000");
}

#[test]
fn the_handwheel_moves_the_selected_axis_by_pulses_times_the_multiplier() {
    let mut r = Rig::new();
    r.mode(Mode::Handle);
    r.g[18] = 2; // HS1B: axis 2 (Z)
    r.x();
    r.cmd(&["handwheel", "5"]);
    r.x();
    assert_eq!(r.m(1), 5);
    assert!(r.fb(102, 1));
    r.g[19] = 0b01 << 4; // MP1: × 10
    r.cmd(&["handwheel", "-3"]);
    r.x();
    assert_eq!(r.m(1), -25);
    r.g[19] = 0b10 << 4; // MP2: × #7113 = 100
    r.cmd(&["handwheel", "1"]);
    r.x();
    assert_eq!(r.m(1), 75);
    r.cmd(&["param", "7103", "4"]); // HNT: × 10 more
    r.cmd(&["handwheel", "1"]);
    r.x();
    assert_eq!(r.m(1), 1075);
    // Pulses are dropped in another mode or with no axis selected.
    r.g[18] = 0;
    r.cmd(&["handwheel", "1"]);
    r.x();
    r.g[18] = 2;
    r.x();
    assert_eq!(r.m(1), 1075);
}

#[test]
fn reference_return_with_a_dog_establishes_the_reference_point() {
    let mut r = Rig::new();
    r.cmd(&["param", "1240", "2", "50000"]);
    r.mode(Mode::Ref);
    r.x();
    assert!(r.fb(4, 5) && !r.fb(3, 2), "MREF only");
    r.set(100, 1, true);
    r.x();
    r.set(100, 1, false);
    assert_eq!(r.m(1), 800, "rapid towards the dog");
    assert!(r.fb(2, 1));
    r.xs(4);
    assert_eq!(r.m(1), 4000, "goes on without the key");
    r.set(196, 1, false); // on the dog
    r.x();
    assert_eq!(r.m(1), 4016, "FL #1425 = 120 mm/min: 16 µm");
    assert!(!r.fb(2, 1), "not rapid");
    r.xs(2);
    r.set(196, 1, true); // off the dog: the reference point
    r.x();
    assert_eq!(r.m(1), 50_000);
    assert!(r.fb(94, 1) && r.fb(120, 1), "ZP2, ZRF2");
    assert!(!r.fb(102, 1), "the axis does not move at that exchange");
    // A second return goes straight to #1240; moving away drops ZP.
    r.mode(Mode::Jog);
    r.set(100, 1, true);
    r.x();
    assert!(!r.fb(94, 1));
    r.set(100, 1, false);
    r.mode(Mode::Ref);
    r.x();
    r.set(100, 1, true);
    r.x();
    assert_eq!(r.m(1), 50_000);
    assert!(r.fb(94, 1));
}

#[test]
fn g28_goes_through_the_point_to_the_reference_position() {
    let mut r = Rig::new();
    r.home(&[1]);
    assert!(r.fb(120, 1));
    r.set(100, 1, false);
    r.mode(Mode::Mdi);
    r.x();
    r.cmd(&["mdi", "G00 W-8;G28 W4"]);
    r.start();
    r.until(100, |r| r.v("cnc.pos.Z") == "-8.000");
    // Through Z = -4, then to #1240 = 0.
    let mid = r.until(100, |r| r.m(1) == -4000);
    r.x();
    assert!(
        r.m(1) > -4000,
        "the second segment starts the exchange after"
    );
    let end = r.until(100, |r| r.m(1) == 0);
    assert_eq!(
        end - mid,
        5,
        "4 mm at 0.8 mm per exchange, one exchange later"
    );
    assert!(r.fb(94, 1));
}

#[test]
fn hardware_overtravel_stops_automatic_operation_and_blocks_its_direction() {
    let mut r = Rig::new();
    r.mode(Mode::Mem);
    r.x();
    r.program("O0001;G01 W10 F600");
    r.start();
    r.set(114, 1, false); // *+L2
    r.x();
    assert_eq!(r.v("cnc.alarm.506"), "1");
    assert_eq!(r.v("cnc.run"), "STOP");
    assert!(!r.fb(1, 7));
    r.cmd(&["reset"]);
    r.x();
    assert_eq!(
        r.v("cnc.alarm.506"),
        "1",
        "reset while the signal is 0 keeps it"
    );
    r.set(114, 1, true);
    r.mode(Mode::Jog);
    r.set(100, 1, true);
    r.x();
    let z = r.m(1);
    r.x();
    assert_eq!(
        r.m(1),
        z,
        "the stored direction is blocked while the alarm is active"
    );
    r.set(100, 1, false);
    r.set(102, 1, true);
    r.x();
    assert!(r.m(1) < z, "the other way is free");
    r.set(102, 1, false);
    r.cmd(&["reset"]);
    r.x();
    assert_eq!(r.v("cnc.alarms"), "0");
}

#[test]
fn the_stored_stroke_limit_stops_on_the_limit_until_moved_back() {
    let mut r = Rig::new();
    // Reference point established by a dog return at 0.
    r.home(&[1]);
    r.cmd(&["param", "1320", "2", "1000"]);
    r.cmd(&["param", "1301", "64"]); // OTS
    r.mode(Mode::Jog);
    r.set(100, 1, true);
    r.xs(10);
    assert_eq!(r.m(1), 1000, "on the limit");
    assert_eq!(r.v("cnc.alarm.500"), "1");
    assert!(r.fb(6, 0) && r.fb(124, 1), "OTA, +OT2");
    r.set(100, 1, false);
    r.cmd(&["reset"]);
    r.x();
    assert_eq!(r.v("cnc.alarm.500"), "0");
    assert!(r.fb(124, 1), "+OT stays until the axis moves back");
    r.set(100, 1, true);
    r.x();
    assert_eq!(r.m(1), 1000);
    r.set(100, 1, false);
    r.set(102, 1, true);
    r.x();
    assert!(!r.fb(124, 1) && r.m(1) < 1000);
}

#[test]
fn a_direct_reference_return_takes_the_exchanges_of_its_distance() {
    let mut r = Rig::new();
    // Establish Z's reference point at 0 with the dog, move away 10 mm, return at 1000 mm/min.
    r.home(&[1]);
    r.cmd(&["position", "Z", "10"]);
    r.cmd(&["param", "1420", "2", "1000"]);
    r.x();
    r.set(100, 1, true);
    r.x();
    let s = r.n;
    let end = r.until(200, |r| r.m(1) == 0);
    assert_eq!(end - s + 1, 75, "⌈10 / (1000 · 8 / 60000)⌉ exchanges");
    assert!(r.fb(94, 1));
}

#[test]
fn g28_at_the_reference_point_sets_zp() {
    let mut r = Rig::new();
    r.home(&[1]);
    r.set(8, 4, false); // E-stop clears ZP
    r.x();
    r.set(8, 4, true);
    r.x();
    assert!(!r.fb(94, 1));
    r.mode(Mode::Mdi);
    r.cmd(&["mdi", "G28 W0"]);
    r.start();
    r.x();
    assert!(r.fb(94, 1));
}

#[test]
fn leaving_auto_mode_while_no_block_runs_stops_at_once() {
    let mut r = Rig::new();
    r.mode(Mode::Mem);
    r.x();
    r.program("O0001;N10;N20 G00 W1");
    r.set(8, 3, false); // *BSL holds N20 back
    r.start();
    r.x();
    assert_eq!(r.v("cnc.run"), "RUN");
    r.mode(Mode::Edit);
    r.x();
    assert_eq!(r.v("cnc.run"), "STOP");
    r.set(8, 3, true);
    r.xs(3);
    assert_eq!(r.m(1), 0, "no block starts in EDIT");
}
