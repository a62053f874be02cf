//! G-code figures (docs/gcode.md, "Speed"): `cargo bench -p ladder-engine --bench gcode`.
//!
//! Prints the median time to expand a G71 over a 50-block profile (lines and arcs) and to work
//! out the toolpath of a 30 000-block program, both through `SimCnc::toolpath`, the dry run of
//! the interpreter (targets: 1 ms and 1 s).

use ladder_engine::ProfileId;
use ladder_engine::cnc::SimCnc;
use ladder_engine::cnc::command::CncCommand;
use ladder_engine::model::tables::MessageTable;
use std::fmt::Write;
use std::time::Instant;

#[path = "common/programs.rs"]
mod programs;

/// A G71 over a 50-block profile: steps down from X20 to X120 with arcs at the corners.
fn g71_program() -> String {
    let mut p = String::from("O1\nG00 X130 Z2\nG71 U2 R0.5\nG71 P100 Q149 U0.4 W0.1 F600\n");
    let _ = writeln!(p, "N100 G00 X20");
    let (mut x, mut z) = (20.0, 0.0);
    for k in 1..49 {
        if k % 2 == 1 {
            z -= 5.0;
            let _ = writeln!(p, "N{} G01 Z{z}", 100 + k);
        } else {
            x += 4.0;
            z -= 2.0;
            let _ = writeln!(p, "N{} G03 X{x} Z{z} R2", 100 + k);
        }
    }
    let _ = writeln!(p, "N149 G01 X130");
    p.push_str("M30\n");
    p
}

fn median_ms(runs: usize, mut f: impl FnMut()) -> f64 {
    let mut t: Vec<f64> = (0..runs)
        .map(|_| {
            let s = Instant::now();
            f();
            s.elapsed().as_secs_f64() * 1000.0
        })
        .collect();
    t.sort_by(f64::total_cmp);
    t[runs / 2]
}

fn cnc_with(program: &str) -> SimCnc {
    let mut cnc = SimCnc::new(ProfileId::Gsk988ta, &MessageTable::default());
    cnc.apply(&CncCommand::Program(program.into()))
        .expect("loads");
    cnc
}

fn main() {
    let cnc = cnc_with(&g71_program());
    let t = cnc.toolpath();
    assert!(t.alarm.is_none(), "{:?}", t.alarm);
    let ms = median_ms(50, || {
        std::hint::black_box(cnc.toolpath());
    });
    println!(
        "g71_50_block_profile: pieces={} median_ms={ms:.3} (target 1 ms)",
        t.pieces.len()
    );
    let cnc = cnc_with(&programs::turning_30000(0.0));
    let t = cnc.toolpath();
    assert!(t.alarm.is_none(), "{:?}", t.alarm);
    let ms = median_ms(5, || {
        std::hint::black_box(cnc.toolpath());
    });
    println!(
        "toolpath_30000_blocks: blocks={} pieces={} points={} median_ms={ms:.1} (target 1000 ms)",
        t.blocks,
        t.pieces.len(),
        t.points.len()
    );
}
