//! Frame-time benchmark of the ladder view: `cargo bench -p ladder-studio --bench frame`.
//!
//! Opens `projects/stress-5000.ldp` in the real app, headless (egui_kittest, no GPU), and
//! times UI passes while jumping through level 2's networks, so each frame lays out and
//! paints a different part of the program: first offline, then online with the machine
//! (PLC and simulated CNC) running at real time on its thread, so every frame also takes
//! the machine's latest state and draws the power flow of what it shows.

use egui_kittest::Harness;
use ladder_studio::gui::LadderApp;
use ladder_studio::gui::command::Command;
use ladder_studio::gui::editor::EditState;
use ladder_studio::gui::online::OnlineState;
use std::path::PathBuf;
use std::time::Instant;

fn frames(h: &mut Harness<'static, LadderApp>, networks: usize) -> Vec<f64> {
    let mut times = Vec::new();
    for k in 0..300 {
        h.state_mut()
            .with(|f: &mut EditState, _| f.jump_to = Some(k * 7 % networks.max(1)));
        let t = Instant::now();
        h.step();
        h.step();
        times.push(t.elapsed().as_secs_f64() * 1e3 / 2.0);
    }
    times.sort_by(f64::total_cmp);
    times
}

fn print(what: &str, networks: usize, times: &[f64]) {
    println!(
        "ladder view {what}, stress-5000 ({networks} networks in level 2), 1280x800: median_ms_per_frame={:.3} p95_ms={:.3} max_ms={:.3}",
        times[times.len() / 2],
        times[times.len() * 95 / 100],
        times[times.len() - 1]
    );
}

fn main() {
    let path = PathBuf::from(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../projects/stress-5000.ldp"
    ));
    let mut h = Harness::builder()
        .with_size(egui::vec2(1280.0, 800.0))
        .build_eframe(move |cc| LadderApp::from_creation(cc, Some(path)));
    h.run();
    // The editor opens on level 1; the stress program is in level 2.
    h.state_mut()
        .ask(Command::ShowView(ladder_studio::gui::place::View::Block(1)));
    h.run();
    let networks = h
        .state()
        .doc()
        .map_or(0, |d| d.project().ladder.blocks[1].networks.len());
    let offline = frames(&mut h, networks);
    print("offline", networks, &offline);
    // Element comments and both address and symbol: the most text a frame draws.
    h.state_mut().settings_mut().show_element_comments = true;
    h.state_mut().settings_mut().display = ladder_studio::gui::settings::DisplayMode::Both;
    let labelled = frames(&mut h, networks);
    print(
        "offline, address+symbol and element comments",
        networks,
        &labelled,
    );
    h.state_mut().settings_mut().show_element_comments = false;
    h.state_mut().settings_mut().display = ladder_studio::gui::settings::DisplayMode::Address;
    h.state_mut().ask(Command::Run);
    h.step();
    std::thread::sleep(std::time::Duration::from_millis(200));
    h.step();
    assert!(
        h.state().feature::<OnlineState>().is_online(),
        "the stress project runs"
    );
    let online = frames(&mut h, networks);
    print("monitored, running at real time", networks, &online);
    let ticks = h
        .state()
        .feature::<OnlineState>()
        .session
        .as_ref()
        .map_or(0, |s| s.published.snapshot.ticks);
    println!("machine ticks meanwhile: {ticks}");
    h.state_mut().ask(Command::GoOffline);
    h.run();
    idle_paints();
}

/// Frames a second the running machine asks the UI for: the sample lathe online at real
/// time with no part program (nothing on screen changes but the clock), then cutting its
/// part program with the CNC page open (positions change every tick).
fn idle_paints() {
    let path = PathBuf::from(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../projects/lathe-988ta.ldp"
    ));
    let nc = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../projects/lathe-988ta.nc"
    ))
    .expect("the sample part program");
    for (what, program) in [
        ("idle, nothing on screen changing", None),
        ("cutting, CNC page", Some(nc)),
    ] {
        let mut h = Harness::builder()
            .with_size(egui::vec2(1280.0, 800.0))
            .build_eframe({
                let path = path.clone();
                move |cc| LadderApp::from_creation(cc, Some(path))
            });
        h.run();
        let cutting = program.is_some();
        h.state_mut()
            .with(|o: &mut OnlineState, cx| o.start_running(cx, program));
        if cutting {
            h.state_mut()
                .with(|f: &mut OnlineState, _| f.tab = ladder_studio::gui::online::OnlineTab::Cnc);
        }
        // Settle (power-on writes, the cycle start), then count over 5 s of real time with
        // the UI stepping at 60 Hz.
        let settle = Instant::now();
        while settle.elapsed().as_secs_f64() < 1.0 {
            h.step();
            std::thread::sleep(std::time::Duration::from_millis(16));
        }
        let gate = std::sync::Arc::clone(&h.state().feature::<OnlineState>().gate);
        let (f0, (v0, i0)) = (gate.frames(), gate.counts());
        let t = Instant::now();
        while t.elapsed().as_secs_f64() < 5.0 {
            h.step();
            std::thread::sleep(std::time::Duration::from_millis(16));
        }
        let secs = t.elapsed().as_secs_f64();
        let (f1, (v1, i1)) = (gate.frames(), gate.counts());
        println!(
            "machine-driven repaints, lathe-988ta running at real time, {what}: frames_per_s={:.1} states_on_screen_per_s={:.1} states_off_screen_per_s={:.1}",
            (f1 - f0) as f64 / secs,
            (v1 - v0) as f64 / secs,
            (i1 - i0) as f64 / secs
        );
        h.state_mut()
            .with(|o: &mut OnlineState, cx| o.go_offline(cx));
    }
}
