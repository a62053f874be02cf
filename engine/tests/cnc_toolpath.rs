//! The toolpath of the loaded program (docs/gcode.md, "Toolpath"): the interpreter run dry.

use crate::common::Rig;
use ladder_engine::cnc::toolpath::PieceKind;

#[test]
fn the_dry_run_draws_every_segment_with_its_line_and_leaves_the_cnc_alone() {
    let mut r = Rig::new();
    r.x();
    r.program(
        "O1\nG00 X20 Z2\nG01 Z-10 F100\nG02 X30 Z-15 R5\nM00\nG90 X16 Z-8 F100\nM98 P2\nM30\nO2\nG00 U2\nM99",
    );
    let t = r.cnc.toolpath();
    assert_eq!(t.alarm, None);
    let kinds: Vec<(PieceKind, usize)> = t.pieces.iter().map(|p| (p.kind, p.line)).collect();
    use PieceKind::{Feed, Rapid};
    assert_eq!(
        kinds,
        [
            (Rapid, 2),
            (Feed, 3),
            (Feed, 4),
            (Rapid, 6),
            (Feed, 6),
            (Feed, 6),
            (Rapid, 6),
            (Rapid, 10),
        ]
    );
    // The arc is drawn as points on its circle: 90° in 3° steps.
    let arc = t.pieces[2];
    assert_eq!(arc.end - arc.start, 31);
    assert_eq!(t.points[arc.end as usize - 1], [-15.0, 30.0]);
    assert_eq!(t.points[t.points.len() - 1], [-15.0, 32.0]);
    assert_eq!(t.blocks, 9, "M00, M98 and M99 are blocks too");
    // Nothing of the running CNC moved or changed.
    assert_eq!((r.m(0), r.m(1)), (0, 0));
    assert_eq!(r.v("cnc.run"), "IDLE");
    // A click near the arc finds it.
    assert_eq!(t.piece_near([-13.5, 23.0], 0.5), Some(2));
    assert_eq!(t.piece_near([-40.0, 80.0], 0.5), None);
}

#[test]
fn the_dry_run_stops_at_the_first_alarm_and_names_its_line() {
    let mut r = Rig::new();
    r.x();
    r.program("O1\nG00 X20\nG01 Z-5\nM30");
    let t = r.cnc.toolpath();
    assert_eq!(t.alarm, Some((11, 3)), "G01 without F");
    assert_eq!(t.pieces.len(), 1);
    // A main program ending in M99 is drawn once.
    r.program("O1\nG00 X20\nG00 X0\nM99");
    let t = r.cnc.toolpath();
    assert_eq!((t.pieces.len(), t.alarm), (2, None));
}

#[test]
fn a_parameter_or_offset_set_after_loading_redraws_the_path() {
    let mut r = Rig::new();
    r.x();
    r.program("O1\nG00 X10000 Z-5000\nM30");
    let before = r.cnc.status().toolpath.unwrap();
    assert_eq!(
        before.points.last(),
        Some(&[-5000.0, 10000.0]),
        "DPI = 1: mm"
    );
    r.cmd(&["param", "3401", "0"]);
    let after = r.cnc.status().toolpath.unwrap();
    assert_eq!(
        after.points.last(),
        Some(&[-5.0, 10.0]),
        "DPI = 0: increments"
    );
}
