//! Frame-time benchmark of the CNC page's toolpath plot: `cargo bench -p ladder-studio --bench
//! toolpath`.
//!
//! Works out the toolpath of a 30 000-block turning program with the CNC's dry run, then times
//! UI passes (headless, egui_kittest, no GPU) drawing it in the plot at 1280x800 while the
//! executed trail grows, as the CNC page does while the program runs. Target: 4 ms a frame.

use egui_kittest::Harness;
use ladder_engine::ProfileId;
use ladder_engine::cnc::SimCnc;
use ladder_engine::cnc::command::CncCommand;
use ladder_engine::model::tables::MessageTable;
use ladder_studio::gui::i18n::Lang;
use ladder_studio::gui::online::toolpath_raster::rasterise;
use ladder_studio::gui::online::toolpath_view::{ToolpathView, toolpath_ui};
use std::time::Instant;

#[path = "../../engine/benches/common/programs.rs"]
mod programs;

fn main() {
    let p = programs::turning_30000(0.0);
    let mut cnc = SimCnc::new(ProfileId::Gsk988ta, &MessageTable::default());
    cnc.apply(&CncCommand::Program(p)).expect("loads");
    let t = Instant::now();
    let status = cnc.status();
    let dry_ms = t.elapsed().as_secs_f64() * 1e3;
    let points = status.toolpath.as_ref().map_or(0, |t| t.points.len());
    let mut h = Harness::builder()
        .with_size(egui::vec2(1280.0, 800.0))
        .build_ui_state(
            |ui, (status, view): &mut (ladder_engine::cnc::CncStatus, ToolpathView)| {
                view.update(status);
                toolpath_ui(ui, status, view, Lang::En, 700.0);
            },
            (status, ToolpathView::default()),
        );
    h.run();
    let mut times = Vec::new();
    for k in 0..200 {
        // The tool moves on: the trail grows by a point a frame.
        h.state_mut().0.machine[1] = -(k as i64) * 100;
        let t = Instant::now();
        h.step();
        times.push(t.elapsed().as_secs_f64() * 1e3);
    }
    times.sort_by(f64::total_cmp);
    // A frame that zooms or pans draws the image again: time that alone.
    let path = h.state().0.toolpath.clone().expect("a path");
    let frame = egui::Rect::from_min_size(egui::pos2(0.0, 0.0), egui::vec2(1200.0, 700.0));
    let bounds = egui_plot::PlotBounds::from_min_max([-30.0, 0.0], [5.0, 65.0]);
    let transform = egui_plot::PlotTransform::new(frame, bounds, egui::Vec2b::FALSE);
    let mut raster: Vec<f64> = (0..20)
        .map(|_| {
            let t = Instant::now();
            std::hint::black_box(rasterise(&path, &transform, 1.0));
            t.elapsed().as_secs_f64() * 1e3
        })
        .collect();
    raster.sort_by(f64::total_cmp);
    println!(
        "toolpath image drawn again (a zoom or pan frame), 1200x700: median_ms={:.3}",
        raster[raster.len() / 2]
    );
    // The same without repetition: every pass of the program at its own diameter.
    let p = programs::turning_30000(0.002);
    let mut cnc = SimCnc::new(ProfileId::Gsk988ta, &MessageTable::default());
    cnc.apply(&CncCommand::Program(p)).expect("loads");
    let unique = cnc.status().toolpath.expect("a path");
    let mut raster: Vec<f64> = (0..10)
        .map(|_| {
            let t = Instant::now();
            std::hint::black_box(rasterise(&unique, &transform, 1.0));
            t.elapsed().as_secs_f64() * 1e3
        })
        .collect();
    raster.sort_by(f64::total_cmp);
    println!(
        "the same, 30000 blocks that never repeat: median_ms={:.3}",
        raster[raster.len() / 2]
    );
    println!(
        "toolpath plot, 30000 blocks ({points} points, dry run {dry_ms:.1} ms), 1280x800: median_ms_per_frame={:.3} p95_ms={:.3} max_ms={:.3} (target 4 ms)",
        times[times.len() / 2],
        times[times.len() * 95 / 100],
        times[times.len() - 1]
    );
}
