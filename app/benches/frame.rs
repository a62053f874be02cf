//! Frame-time benchmark of the ladder view: `cargo bench -p ladder-studio --bench frame`.
//!
//! Opens `projects/stress-5000.ldp` in the real app, headless (egui_kittest, no GPU), and
//! times UI passes while jumping through level 2's networks, so each frame lays out and
//! paints a different part of the program.

use egui_kittest::Harness;
use ladder_studio::gui::LadderApp;
use std::path::PathBuf;
use std::time::Instant;

fn main() {
    let path = PathBuf::from(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../projects/stress-5000.ldp"
    ));
    let mut h = Harness::builder()
        .with_size(egui::vec2(1280.0, 800.0))
        .build_eframe(move |cc| LadderApp::from_creation(cc, Some(path)));
    h.run();
    let networks = h
        .state()
        .doc
        .as_ref()
        .map_or(0, |d| d.project().ladder.blocks[1].networks.len());
    let mut times = Vec::new();
    for k in 0..300 {
        h.state_mut().edit.jump_to = Some(k * 7 % networks.max(1));
        let t = Instant::now();
        h.step();
        h.step();
        times.push(t.elapsed().as_secs_f64() * 1e3 / 2.0);
    }
    times.sort_by(f64::total_cmp);
    println!(
        "ladder view, stress-5000 ({networks} networks in level 2), 1280x800: median_ms_per_frame={:.3} p95_ms={:.3} max_ms={:.3}",
        times[times.len() / 2],
        times[times.len() * 95 / 100],
        times[times.len() - 1]
    );
}
