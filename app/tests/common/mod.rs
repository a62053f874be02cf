//! The one harness of the editor's UI tests: the app driven headless through egui_kittest, on
//! projects saved in fresh temporary folders, and the gestures the tests share.
#![allow(dead_code, unused_imports)] // Each test file uses some of the helpers.

pub mod online;

pub use egui_kittest::Harness;
pub use egui_kittest::kittest::Queryable;
pub use ladder_studio::gui::LadderApp;
use ladder_studio::gui::editor::EditState;
use ladder_studio::gui::files::FileState;
pub use ladder_studio::gui::i18n::Lang;
pub use ladder_studio::gui::tree::View;
pub use std::path::PathBuf;

pub fn harness(path: Option<PathBuf>, lang: Lang) -> Harness<'static, LadderApp> {
    harness_sized(path, lang, egui::vec2(1280.0, 800.0))
}

/// The editor in a window of `size`, as [`harness`] builds it.
pub fn harness_sized(
    path: Option<PathBuf>,
    lang: Lang,
    size: egui::Vec2,
) -> Harness<'static, LadderApp> {
    // Frames 1/60 s apart, as on a screen: two clicks a few frames apart are a double-click.
    Harness::builder()
        .with_size(size)
        .with_step_dt(1.0 / 60.0)
        // A tooltip fades in over a few frames wherever the mouse rests on an element.
        .with_max_steps(16)
        .build_eframe(move |cc| {
            let mut app = LadderApp::from_creation(cc, path);
            app.settings_mut().lang = lang;
            app
        })
}

/// The instructions of a saved project's exported IL, without directives, spaces folded.
pub fn il_of_saved(path: &std::path::Path) -> Vec<String> {
    let reopened = ladder_engine::file::load(path).unwrap();
    let il = ladder_engine::il::print(&ladder_engine::compiler::compile(&reopened).program);
    il.lines()
        .filter(|l| !matches!(*l, "LEVEL1" | "LEVEL2" | "NETWORK" | "END"))
        .map(|l| l.split_whitespace().collect::<Vec<_>>().join(" "))
        .collect()
}

thread_local! {
    /// The folders made for the test running on this thread. Each test runs on a thread of
    /// its own, whose thread-locals are dropped when it ends: after the test's harness, which
    /// may still write recovery copies as it closes, and so after the last write.
    static FOLDERS: std::cell::RefCell<Vec<tempfile::TempDir>> =
        const { std::cell::RefCell::new(Vec::new()) };
}

/// A fresh temporary folder for one test's files, removed when the test's thread ends.
pub fn tempfile_dir() -> PathBuf {
    let dir = tempfile::Builder::new()
        .prefix("ladder-gui-")
        .tempdir()
        .expect("a temporary folder");
    let path = dir.path().to_path_buf();
    FOLDERS.with(|f| f.borrow_mut().push(dir));
    path
}

/// Types into the prompt (operand, find, go to…: the text field that has the keyboard) and
/// presses Enter.
pub fn enter_operand(h: &mut Harness<'static, LadderApp>, text: &str) {
    h.run();
    h.get_all_by_role(egui::accesskit::Role::TextInput)
        .find(|n| n.is_focused())
        .expect("a prompt has the keyboard")
        .type_text(text);
    h.run();
    h.key_press(egui::Key::Enter);
    h.run();
}

/// A left click at a screen position.
pub fn click_at(h: &mut Harness<'static, LadderApp>, p: egui::Pos2) {
    h.hover_at(p);
    h.run();
    for pressed in [true, false] {
        h.event(egui::Event::PointerButton {
            pos: p,
            button: egui::PointerButton::Primary,
            pressed,
            modifiers: egui::Modifiers::NONE,
        });
    }
    h.run();
}

/// Clicks the ladder cell (network, row, column) where the view drew it.
pub fn click_cell(h: &mut Harness<'static, LadderApp>, network: usize, row: usize, col: usize) {
    let p = h
        .state()
        .feature::<EditState>()
        .geometry
        .cell_center(network, row, col)
        .expect("the cell is on screen");
    click_at(h, p);
    let c = h.state().cursor();
    assert_eq!(
        (c.network, c.row, c.col),
        (network, row, col),
        "the click moved the cursor"
    );
}

/// The app's state of a document: (path, dirty, networks in the whole ladder).
pub fn doc_state(h: &Harness<'static, LadderApp>) -> Option<(Option<PathBuf>, bool, usize)> {
    h.state().doc().map(|d| {
        (
            d.path().map(|p| p.to_path_buf()),
            d.is_dirty(),
            d.project()
                .ladder
                .blocks
                .iter()
                .map(|b| b.networks.len())
                .sum(),
        )
    })
}

pub fn scripted(h: &mut Harness<'static, LadderApp>, answers: Vec<Option<PathBuf>>) {
    h.state_mut().with(|f: &mut FileState, _| {
        f.dialogs = Box::new(ladder_studio::gui::files::ScriptedDialogs::new(answers))
    });
}

/// A project saved in a fresh file, opened in the editor (English).
pub fn editor_on(il: &str, name: &str) -> (Harness<'static, LadderApp>, PathBuf) {
    let dir = tempfile_dir();
    let path = dir.join(name);
    let p = ladder_engine::il::import(il).project.unwrap();
    ladder_engine::file::save(&p, &path).unwrap();
    let mut h = harness(Some(path.clone()), Lang::En);
    h.run();
    on_level2(&mut h);
    (h, path)
}

/// Shows level 2, as a click on it in the project tree does (the editor opens on level 1).
pub fn on_level2(h: &mut Harness<'static, LadderApp>) {
    use ladder_studio::gui::command::Command;
    use ladder_studio::gui::place::View;
    h.state_mut().ask(Command::ShowView(View::Block(1)));
    h.run();
}

/// The instructions the editor's project compiles to (directives kept, spaces folded).
pub fn il_now(h: &Harness<'static, LadderApp>) -> Vec<String> {
    let project = h.state().doc().unwrap().project();
    ladder_engine::il::print(&ladder_engine::compiler::compile(project).program)
        .lines()
        .map(|l| l.split_whitespace().collect::<Vec<_>>().join(" "))
        .collect()
}

pub fn pointer(h: &mut Harness<'static, LadderApp>, p: egui::Pos2, button: egui::PointerButton) {
    h.hover_at(p);
    h.run();
    for pressed in [true, false] {
        h.event(egui::Event::PointerButton {
            pos: p,
            button,
            pressed,
            modifiers: egui::Modifiers::NONE,
        });
    }
    h.run();
}

pub fn cell_pos(
    h: &Harness<'static, LadderApp>,
    network: usize,
    row: usize,
    col: usize,
) -> egui::Pos2 {
    h.state()
        .feature::<EditState>()
        .geometry
        .cell_center(network, row, col)
        .expect("the cell is on screen")
}

/// Drags from one cell to another with the primary button.
pub fn drag(h: &mut Harness<'static, LadderApp>, from: egui::Pos2, to: egui::Pos2) {
    h.hover_at(from);
    h.run();
    h.event(egui::Event::PointerButton {
        pos: from,
        button: egui::PointerButton::Primary,
        pressed: true,
        modifiers: egui::Modifiers::NONE,
    });
    h.step();
    for i in 1..=6 {
        let t = i as f32 / 6.0;
        h.event(egui::Event::PointerMoved(from + (to - from) * t));
        h.step();
    }
    h.event(egui::Event::PointerButton {
        pos: to,
        button: egui::PointerButton::Primary,
        pressed: false,
        modifiers: egui::Modifiers::NONE,
    });
    h.run();
}

pub const TWO_NETWORKS: &str =
    "LEVEL2\nNETWORK\nLD X0002.1\nOUT Y0003.7\nNETWORK\nLD X0002.2\nOUT Y0003.6\n";

pub fn double_click(h: &mut Harness<'static, LadderApp>, p: egui::Pos2) {
    h.hover_at(p);
    h.run();
    for pressed in [true, false, true, false] {
        h.event(egui::Event::PointerButton {
            pos: p,
            button: egui::PointerButton::Primary,
            pressed,
            modifiers: egui::Modifiers::NONE,
        });
        h.step();
    }
    h.run();
}

/// Replaces the text of the field labelled `label`.
pub fn fill(h: &mut Harness<'static, LadderApp>, label: &str, text: &str) {
    use egui_kittest::kittest::Queryable;
    h.get_by_role_and_label(egui::accesskit::Role::TextInput, label)
        .click();
    h.run();
    h.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::A);
    h.run();
    h.get_by_role_and_label(egui::accesskit::Role::TextInput, label)
        .type_text(text);
    h.run();
}

/// The stress project on level 2, in a window, with the cursor sent to network `n` (1-based).
pub fn stress_at(n: usize) -> (Harness<'static, LadderApp>, PathBuf) {
    let path = PathBuf::from(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../projects/stress-5000.ldp"
    ));
    let mut h = harness(Some(path.clone()), Lang::En);
    h.run();
    on_level2(&mut h);
    h.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::G);
    enter_operand(&mut h, &format!("{n} 1"));
    h.run();
    (h, ladder_studio::gui::settings::canonical(&path))
}
