//! The ladder diagram as an engineer works in it: zoom about the pointer at both ends of a
//! block, labels that never overlap, errors marked on the elements, operands typed at the
//! cell, rows opened with Down, and element properties.

mod common;
use common::*;

/// One notch of Ctrl+wheel at `mouse`, in (`up`) or out, and the frames it is smoothed over.
fn wheel(h: &mut Harness<'static, LadderApp>, mouse: egui::Pos2, up: bool) {
    h.hover_at(mouse);
    h.run();
    h.event(egui::Event::MouseWheel {
        unit: egui::MouseWheelUnit::Line,
        delta: egui::vec2(0.0, if up { 1.0 } else { -1.0 }),
        phase: egui::TouchPhase::Move,
        source: egui::MouseWheelSource::Unknown,
        modifiers: egui::Modifiers::COMMAND,
    });
    h.run_steps(30);
}

/// Zooms in and out about the cursor cell's centre and checks it stays under the mouse.
fn zoom_keeps_the_cell_under_the_mouse(h: &mut Harness<'static, LadderApp>) {
    let c = h.state().edit.cursor;
    let cell = |h: &Harness<'static, LadderApp>| {
        h.state()
            .edit
            .geometry
            .cell_rect(c.network, c.row, c.col)
            .expect("the cursor cell is drawn")
    };
    let mouse = cell(h).center();
    for (up, zoom) in [
        (true, 125),
        (true, 150),
        (false, 125),
        (false, 100),
        (false, 75),
    ] {
        wheel(h, mouse, up);
        assert_eq!(h.state().settings.zoom, zoom);
        let now = cell(h);
        assert!(
            now.contains(mouse),
            "at {zoom} % network {} is still under the mouse: {now:?} holds {mouse:?}",
            c.network + 1
        );
    }
}

#[test]
fn zoom_keeps_the_element_under_the_pointer_on_the_last_network() {
    let (mut h, _) = stress_at(1);
    h.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::End);
    h.run();
    h.run();
    let last = h.state().doc.as_ref().unwrap().project().ladder.blocks[1]
        .networks
        .len();
    assert_eq!(h.state().edit.cursor.network, last - 1);
    zoom_keeps_the_cell_under_the_mouse(&mut h);
}

#[test]
fn zoom_keeps_the_element_under_the_pointer_on_the_first_network() {
    let (mut h, _) = stress_at(1);
    h.key_press(egui::Key::ArrowDown);
    h.run();
    zoom_keeps_the_cell_under_the_mouse(&mut h);
}
