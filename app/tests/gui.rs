//! The editor driven headless through egui_kittest, by role and label.

use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;
use ladder_studio::gui::LadderApp;
use ladder_studio::gui::i18n::Lang;
use ladder_studio::gui::tree::View;
use std::path::PathBuf;

fn harness(path: Option<PathBuf>, lang: Lang) -> Harness<'static, LadderApp> {
    // Frames 1/60 s apart, as on a screen: two clicks a few frames apart are a double-click.
    Harness::builder()
        .with_size(egui::vec2(1280.0, 800.0))
        .with_step_dt(1.0 / 60.0)
        .build_eframe(move |cc| {
            let mut app = LadderApp::from_creation(cc, path);
            app.settings.lang = lang;
            app
        })
}

#[test]
fn starts_on_the_bundled_sample_with_the_project_tree() {
    let mut h = harness(None, Lang::Zh);
    h.run();
    for label in [
        "梯形图",
        "一级程序",
        "二级程序",
        "子程序",
        "符号表",
        "数据设置表",
        "显示信息表",
        "引用索引表",
        "诊断信息表",
        "权限表",
        "M 代码注释表",
        "梯形图版本信息",
    ] {
        h.get_by_label(label);
    }
    h.get_by_label_contains("P0001");
    assert_eq!(h.state().view, View::Block(1), "level 2 is shown first");
}

#[test]
fn the_language_switches_at_run_time() {
    let mut h = harness(None, Lang::Zh);
    h.run();
    h.get_by_label("查看").click();
    h.run();
    h.get_by_label("English (英文)").click();
    h.run();
    assert_eq!(h.state().settings.lang, Lang::En);
    h.get_by_label("Level 2");
    h.get_by_label("Cross-reference");
    assert!(h.query_by_label("二级程序").is_none());
}

#[test]
fn f9_compiles_into_the_output_window() {
    let mut h = harness(None, Lang::En);
    h.run();
    h.key_press(egui::Key::F9);
    h.run();
    let last = h
        .state()
        .output
        .last()
        .expect("a summary line")
        .text
        .clone();
    assert_eq!(last, "Compiled without errors (716 steps)");
    h.get_by_label_contains("Compiled without errors");
}

#[test]
fn a_compile_error_jumps_to_its_network() {
    let dir = tempfile_dir();
    let path = dir.join("err.ldp");
    let project = ladder_engine::il::import(
        "LEVEL2\nNETWORK\nLD X0001.0\nOUT Y0001.0\nNETWORK\nLD X0001.1\nAND NOWHERE\nOUT Y0001.1\n",
    )
    .project
    .unwrap();
    ladder_engine::file::save(&project, &path).unwrap();
    let mut h = harness(Some(path), Lang::En);
    h.run();
    h.get_by_label("Level 1").click();
    h.run();
    assert_eq!(h.state().view, View::Block(0));
    h.key_press(egui::Key::F9);
    h.run();
    let diag = h.state().output[0].clone();
    let at = diag.target.expect("the diagnostic has a cell");
    assert_eq!((at.block, at.network), (1, 1), "{}", diag.text);
    h.get_by_label_contains("undefined symbol `NOWHERE`")
        .click();
    h.run();
    assert_eq!(h.state().view, View::Block(1), "the error's block is shown");
    assert_eq!(h.state().cursor, at, "the cursor is on the cell");
    assert_eq!(h.state().jump_to, None, "and its network was scrolled to");
}

#[test]
fn the_cross_reference_view_lists_addresses() {
    let mut h = harness(None, Lang::En);
    h.run();
    h.get_by_label("Cross-reference").click();
    h.run();
    h.get_by_label("Bit usage").click();
    h.run();
    assert_eq!(h.state().view, View::RefBits);
    h.get_by_label_contains("BIT     7 6 5 4 3 2 1 0");
}

/// The instructions of a saved project's exported IL, without directives, spaces folded.
fn il_of_saved(path: &std::path::Path) -> Vec<String> {
    let reopened = ladder_engine::file::load(path).unwrap();
    let il = ladder_engine::il::print(&ladder_engine::compiler::compile(&reopened).program);
    il.lines()
        .filter(|l| !matches!(*l, "LEVEL1" | "LEVEL2" | "NETWORK" | "END"))
        .map(|l| l.split_whitespace().collect::<Vec<_>>().join(" "))
        .collect()
}

fn tempfile_dir() -> PathBuf {
    let dir = std::env::temp_dir().join(format!(
        "ladder-gui-test-{}-{:?}",
        std::process::id(),
        std::thread::current().id()
    ));
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// Types into the operand prompt and presses Enter.
fn enter_operand(h: &mut Harness<'static, LadderApp>, text: &str) {
    h.run();
    h.get_by_role_and_label(egui::accesskit::Role::TextInput, "Operand")
        .type_text(text);
    h.run();
    h.key_press(egui::Key::Enter);
    h.run();
}

#[test]
fn the_self_holding_circuit_drawn_with_the_keyboard_exports_the_manual_il() {
    use egui::{Key, Modifiers};
    let dir = tempfile_dir();
    let path = dir.join("self-hold.ldp");
    ladder_engine::file::save(&ladder_engine::model::Project::default(), &path).unwrap();
    let mut h = harness(Some(path.clone()), Lang::En);
    h.run();
    let empty = h.state().doc.as_ref().unwrap().project().ladder.clone();
    h.key_press_modifiers(Modifiers::COMMAND, Key::I); // a network
    h.run();
    h.key_press(Key::F1); // start X2.1
    enter_operand(&mut h, "x2.1");
    h.key_press_modifiers(Modifiers::SHIFT, Key::F1); // stop X2.2, normally closed
    enter_operand(&mut h, "X2.2");
    h.key_press(Key::F2); // the coil
    enter_operand(&mut h, "Y3.7");
    h.key_press_modifiers(Modifiers::COMMAND, Key::R); // a row below
    h.run();
    for _ in 0..12 {
        h.key_press(Key::ArrowLeft);
    }
    h.run();
    h.key_press(Key::F6); // its own contact in parallel with the start button
    enter_operand(&mut h, "Y3.7");
    h.key_press_modifiers(Modifiers::COMMAND, Key::S);
    h.run();
    let drawn = h.state().doc.as_ref().unwrap().project().ladder.clone();
    assert!(!h.state().doc.as_ref().unwrap().dirty, "saved");

    // Reopened from the file, the ladder exports the manual's instruction list.
    assert_eq!(
        il_of_saved(&path),
        ["LD X0002.1", "OR Y0003.7", "ANI X0002.2", "OUT Y0003.7"]
    );

    // Undo back to empty, exactly; redo to the drawing, exactly.
    for _ in 0..20 {
        h.key_press_modifiers(Modifiers::COMMAND, Key::Z);
        h.run();
    }
    assert_eq!(h.state().doc.as_ref().unwrap().project().ladder, empty);
    for _ in 0..20 {
        h.key_press_modifiers(Modifiers::COMMAND, Key::Y);
        h.run();
    }
    assert_eq!(h.state().doc.as_ref().unwrap().project().ladder, drawn);
}

#[test]
fn find_and_replace_an_address() {
    use egui::{Key, Modifiers};
    let dir = tempfile_dir();
    let path = dir.join("find.ldp");
    let p = ladder_engine::il::import(
        "LEVEL2\nNETWORK\nLD X0002.1\nOR Y0003.7\nANI X0002.2\nOUT Y0003.7\nNETWORK\nLD Y0003.7\nOUT Y0004.0\n",
    )
    .project
    .unwrap();
    ladder_engine::file::save(&p, &path).unwrap();
    let mut h = harness(Some(path), Lang::En);
    h.run();
    h.key_press_modifiers(Modifiers::COMMAND, Key::F);
    enter_operand(&mut h, "y3.7");
    let out: Vec<String> = h.state().output.iter().map(|l| l.text.clone()).collect();
    assert_eq!(out.last().unwrap(), "3 found", "{out:?}");
    let at = |h: &Harness<'static, LadderApp>| {
        let c = h.state().cursor;
        (c.network, c.row, c.col)
    };
    assert_eq!(at(&h), (0, 0, 10), "the cursor went to the first match");
    // Ctrl+F, Enter again: the next match ("find next").
    h.key_press_modifiers(Modifiers::COMMAND, Key::F);
    h.run();
    assert_eq!(h.state().prompt.as_ref().unwrap().text, "y3.7");
    h.key_press(Key::Enter);
    h.run();
    assert_eq!(at(&h), (0, 1, 0));
    h.get_by_label_contains("LEVEL2 N0002 1:1").click();
    h.run();
    assert_eq!(h.state().view, View::Block(1));
    // Replace: the coil may take Y4.1; X1.0 would be refused where it is written.
    h.key_press_modifiers(Modifiers::COMMAND, Key::H);
    enter_operand(&mut h, "Y3.7 X1.0");
    assert_eq!(
        h.state().output.last().unwrap().text,
        "2 replaced, 1 skipped where the result would be invalid"
    );
    let project = h.state().doc.as_ref().unwrap().project();
    let il = ladder_engine::il::print(&ladder_engine::compiler::compile(project).program);
    assert!(
        il.contains("OR   X0001.0") && il.contains("OUT  Y0003.7") && il.contains("LD   X0001.0"),
        "{il}"
    );
}

/// A left click at a screen position.
fn click_at(h: &mut Harness<'static, LadderApp>, p: egui::Pos2) {
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
fn click_cell(h: &mut Harness<'static, LadderApp>, network: usize, row: usize, col: usize) {
    let p = h
        .state()
        .geometry
        .cell_center(network, row, col)
        .expect("the cell is on screen");
    click_at(h, p);
    let c = h.state().cursor;
    assert_eq!(
        (c.network, c.row, c.col),
        (network, row, col),
        "the click moved the cursor"
    );
}

#[test]
fn the_self_holding_circuit_drawn_with_the_mouse_exports_the_manual_il() {
    let dir = tempfile_dir();
    let path = dir.join("mouse.ldp");
    ladder_engine::file::save(&ladder_engine::model::Project::default(), &path).unwrap();
    let mut h = harness(Some(path.clone()), Lang::En);
    h.run();
    h.get_by_label("Insert network").click();
    h.run();
    click_cell(&mut h, 0, 0, 0);
    h.get_by_label("NO contact").click();
    enter_operand(&mut h, "X2.1");
    click_cell(&mut h, 0, 0, 1);
    h.get_by_label("NC contact").click();
    enter_operand(&mut h, "X2.2");
    h.get_by_label("Coil").click();
    enter_operand(&mut h, "Y3.7");
    h.get_by_label("Insert row").click();
    h.run();
    click_cell(&mut h, 0, 1, 0);
    h.get_by_label("Parallel contact").click();
    enter_operand(&mut h, "Y3.7");
    h.get_by_label("File").click();
    h.run();
    h.get_by_label("Save Ctrl+S").click();
    h.run();
    assert_eq!(
        il_of_saved(&path),
        ["LD X0002.1", "OR Y0003.7", "ANI X0002.2", "OUT Y0003.7"]
    );
}

#[test]
fn ctrl_g_goes_to_a_network_and_row_and_refuses_one_that_is_not_there() {
    use egui::{Key, Modifiers};
    let mut h = harness(None, Lang::En);
    h.run();
    h.key_press_modifiers(Modifiers::COMMAND, Key::G);
    enter_operand(&mut h, "30 2");
    let c = h.state().cursor;
    assert_eq!((c.block, c.network, c.row, c.col), (1, 29, 1, 0));
    assert!(h.state().prompt.is_none());
    h.key_press_modifiers(Modifiers::COMMAND, Key::G);
    enter_operand(&mut h, "9999");
    let prompt = h.state().prompt.clone().expect("the prompt stays open");
    assert!(
        prompt.error.unwrap().starts_with("No such network: 1–"),
        "an error names the range"
    );
    h.key_press(Key::Escape);
    h.run();
    assert!(h.state().prompt.is_none());
}

/// The app's state of a document: (path, dirty, networks in level 2).
fn doc_state(h: &Harness<'static, LadderApp>) -> Option<(Option<PathBuf>, bool, usize)> {
    h.state().doc.as_ref().map(|d| {
        (
            d.path.clone(),
            d.dirty,
            d.project().ladder.blocks[1].networks.len(),
        )
    })
}

fn scripted(h: &mut Harness<'static, LadderApp>, answers: Vec<Option<PathBuf>>) {
    h.state_mut().dialogs = Box::new(ladder_studio::gui::files::ScriptedDialogs::new(answers));
}

#[test]
fn new_asks_about_unsaved_changes_and_cancel_keeps_them() {
    use egui::{Key, Modifiers};
    let dir = tempfile_dir();
    let path = dir.join("unsaved.ldp");
    ladder_engine::file::save(&ladder_engine::model::Project::default(), &path).unwrap();
    let mut h = harness(Some(path.clone()), Lang::En);
    h.run();
    h.key_press_modifiers(Modifiers::COMMAND, Key::I);
    h.run();
    assert_eq!(doc_state(&h), Some((Some(path.clone()), true, 1)));
    h.key_press_modifiers(Modifiers::COMMAND, Key::N);
    h.run();
    h.get_by_label_contains("Save the changes to “unsaved.ldp”");
    h.get_by_label("Cancel").click();
    h.run();
    assert_eq!(doc_state(&h), Some((Some(path.clone()), true, 1)), "kept");
    h.key_press_modifiers(Modifiers::COMMAND, Key::N);
    h.run();
    h.get_by_label("Don't save").click();
    h.run();
    assert_eq!(
        doc_state(&h),
        Some((None, false, 0)),
        "a new, empty project"
    );
    assert_eq!(
        ladder_engine::file::load(&path).unwrap().ladder.blocks[1]
            .networks
            .len(),
        0,
        "the file was not touched"
    );
}

#[test]
fn closing_the_window_with_unsaved_changes_saves_them_first_when_asked() {
    use egui::{Key, Modifiers};
    let dir = tempfile_dir();
    let path = dir.join("close.ldp");
    ladder_engine::file::save(&ladder_engine::model::Project::default(), &path).unwrap();
    let mut h = harness(Some(path.clone()), Lang::En);
    h.run();
    h.key_press_modifiers(Modifiers::COMMAND, Key::I);
    h.run();
    h.input_mut()
        .viewports
        .entry(egui::ViewportId::ROOT)
        .or_default()
        .events
        .push(egui::ViewportEvent::Close);
    h.step();
    // The window system sends the request once.
    h.input_mut()
        .viewports
        .entry(egui::ViewportId::ROOT)
        .or_default()
        .events
        .clear();
    h.run();
    assert!(!h.state().exit_confirmed, "the window stays while asking");
    h.get_by_label_contains("Save the changes to");
    h.get_by_label("Save changes").click();
    h.run();
    assert!(h.state().exit_confirmed, "saved, then closed");
    let saved = ladder_engine::file::load(&path).unwrap();
    assert_eq!(
        saved.ladder.blocks[1].networks.len(),
        1,
        "the change was saved"
    );
}

#[test]
fn an_untitled_project_is_saved_through_the_save_as_dialog_and_joins_the_recent_files() {
    use egui::{Key, Modifiers};
    let dir = tempfile_dir();
    let path = dir.join("named.ldp");
    let _ = std::fs::remove_file(&path);
    let mut h = harness(None, Lang::En);
    h.run();
    scripted(&mut h, vec![None, Some(path.clone())]);
    h.key_press_modifiers(Modifiers::COMMAND, Key::N);
    h.run();
    h.key_press_modifiers(Modifiers::COMMAND, Key::I);
    h.run();
    h.key_press_modifiers(Modifiers::COMMAND, Key::S); // cancelled in the dialog
    h.run();
    assert_eq!(
        doc_state(&h),
        Some((None, true, 1)),
        "nothing saved on cancel"
    );
    h.key_press_modifiers(Modifiers::COMMAND, Key::S);
    h.run();
    assert_eq!(doc_state(&h), Some((Some(path.clone()), false, 1)));
    assert_eq!(h.state().settings.recent.first(), Some(&path));
    assert_eq!(
        ladder_engine::file::load(&path).unwrap(),
        h.state().doc.as_ref().unwrap().project().clone()
    );
}

#[test]
fn a_damaged_file_opens_read_only_and_is_never_saved_over() {
    let dir = tempfile_dir();
    let path = dir.join("damaged.ldp");
    let p = ladder_engine::il::import("LEVEL2\nNETWORK\nLD X0002.1\nOUT Y0003.7\n")
        .project
        .unwrap();
    ladder_engine::file::save(&p, &path).unwrap();
    let mut text = std::fs::read_to_string(&path).unwrap();
    text = text.replacen("Y0003.7", "Y0003.6", 1);
    std::fs::write(&path, &text).unwrap();
    let mut h = harness(None, Lang::En);
    h.run();
    scripted(&mut h, vec![Some(path.clone()), Some(dir.join("copy.ldp"))]);
    h.state_mut()
        .request(ladder_studio::gui::files::Action::Open(path.clone()));
    h.run();
    h.get_by_label_contains("Open what can be read of it");
    h.get_by_label("Open read-only").click();
    h.run();
    let doc = h.state().doc.as_ref().unwrap();
    assert!(doc.read_only && doc.path.is_none());
    h.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::I);
    h.run();
    assert_eq!(
        h.state().doc.as_ref().unwrap().project().ladder.blocks[1]
            .networks
            .len(),
        1,
        "no edits in a read-only project"
    );
    // Save goes to Save As; the original's name is refused, another name is taken.
    h.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::S);
    h.run();
    assert_eq!(std::fs::read_to_string(&path).unwrap(), text, "untouched");
    assert!(
        h.state()
            .output
            .iter()
            .any(|l| l.text.contains("damaged original is not overwritten"))
    );
    h.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::S);
    h.run();
    let copy = ladder_engine::file::load(&dir.join("copy.ldp")).unwrap();
    let il = ladder_engine::il::print(&ladder_engine::compiler::compile(&copy).program);
    assert!(
        il.contains("OUT  Y0003.6"),
        "what could be read was kept: {il}"
    );
    assert!(!h.state().doc.as_ref().unwrap().read_only);
}

#[test]
fn an_autosaved_recovery_copy_is_offered_after_a_crash_and_restores_the_work() {
    use egui::{Key, Modifiers};
    let dir = tempfile_dir();
    let rec = dir.join("recovery-crash");
    let _ = std::fs::remove_dir_all(&rec);
    let path = dir.join("crash.ldp");
    ladder_engine::file::save(&ladder_engine::model::Project::default(), &path).unwrap();
    {
        let mut h = harness(Some(path.clone()), Lang::En);
        h.state_mut().recovery_dir = Some(rec.clone());
        h.run();
        h.key_press_modifiers(Modifiers::COMMAND, Key::I);
        h.run();
        h.state_mut().autosave_now();
        // The session ends here without closing: a crash.
    }
    let copies = ladder_studio::gui::files::recovery_copies(&rec);
    assert_eq!(copies.len(), 1);
    assert_eq!(copies[0].original.as_ref(), Some(&path));
    let mut h = harness(None, Lang::En);
    h.state_mut().recovery_dir = Some(rec.clone());
    h.state_mut().offer_restore();
    h.run();
    h.get_by_label_contains("did not end normally");
    h.get_by_label("Restore").click();
    h.run();
    assert_eq!(doc_state(&h), Some((Some(path.clone()), true, 1)));
    // Saving the restored work removes the copy.
    h.key_press_modifiers(Modifiers::COMMAND, Key::S);
    h.run();
    assert_eq!(
        ladder_engine::file::load(&path).unwrap().ladder.blocks[1]
            .networks
            .len(),
        1
    );
    assert!(ladder_studio::gui::files::recovery_copies(&rec).is_empty());
}

#[test]
fn export_il_and_comments_from_the_file_menu() {
    let dir = tempfile_dir();
    let il_path = dir.join("export.il");
    let csv_path = dir.join("export.csv");
    let mut h = harness(None, Lang::En);
    h.run();
    scripted(&mut h, vec![Some(il_path.clone()), Some(csv_path.clone())]);
    h.get_by_label("File").click();
    h.run();
    h.get_by_label("Export instruction list…").click();
    h.run();
    h.run();
    let il = std::fs::read_to_string(&il_path).unwrap();
    let project = h.state().doc.as_ref().unwrap().project().clone();
    assert_eq!(
        il,
        ladder_engine::il::print(&ladder_engine::compiler::compile(&project).program)
    );
    h.get_by_label("File").click();
    h.run();
    h.get_by_label("Export comments…").click();
    h.run();
    h.run();
    let csv = std::fs::read_to_string(&csv_path).unwrap();
    assert_eq!(csv, ladder_engine::comments::export(&project, None));
    assert!(csv.lines().count() > 10);
}

/// A project saved in a fresh file, opened in the editor (English).
fn editor_on(il: &str, name: &str) -> (Harness<'static, LadderApp>, PathBuf) {
    let dir = tempfile_dir();
    let path = dir.join(name);
    let p = ladder_engine::il::import(il).project.unwrap();
    ladder_engine::file::save(&p, &path).unwrap();
    let mut h = harness(Some(path.clone()), Lang::En);
    h.run();
    (h, path)
}

/// The instructions the editor's project compiles to (directives kept, spaces folded).
fn il_now(h: &Harness<'static, LadderApp>) -> Vec<String> {
    let project = h.state().doc.as_ref().unwrap().project();
    ladder_engine::il::print(&ladder_engine::compiler::compile(project).program)
        .lines()
        .map(|l| l.split_whitespace().collect::<Vec<_>>().join(" "))
        .collect()
}

fn pointer(h: &mut Harness<'static, LadderApp>, p: egui::Pos2, button: egui::PointerButton) {
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

fn cell_pos(h: &Harness<'static, LadderApp>, network: usize, row: usize, col: usize) -> egui::Pos2 {
    h.state()
        .geometry
        .cell_center(network, row, col)
        .expect("the cell is on screen")
}

/// Drags from one cell to another with the primary button.
fn drag(h: &mut Harness<'static, LadderApp>, from: egui::Pos2, to: egui::Pos2) {
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

const TWO_NETWORKS: &str =
    "LEVEL2\nNETWORK\nLD X0002.1\nOUT Y0003.7\nNETWORK\nLD X0002.2\nOUT Y0003.6\n";

#[test]
fn a_network_selected_by_its_title_is_copied_pasted_and_undone_in_one_step() {
    use egui::{Key, Modifiers};
    let (mut h, _) = editor_on(TWO_NETWORKS, "clip.ldp");
    let header = cell_pos(&h, 0, 0, 3) - egui::vec2(0.0, 24.0);
    pointer(&mut h, header, egui::PointerButton::Primary);
    assert!(
        matches!(
            h.state().selection,
            Some((
                1,
                ladder_studio::gui::selection::Selection::Networks { networks: (0, 0) }
            ))
        ),
        "{:?}",
        h.state().selection
    );
    h.get_by_label_contains("selected 1 Network");
    h.key_press_modifiers(Modifiers::COMMAND, Key::C);
    h.run();
    h.key_press_modifiers(Modifiers::COMMAND, Key::V);
    h.run();
    assert_eq!(
        il_now(&h),
        [
            "LEVEL1",
            "LEVEL2",
            "NETWORK",
            "LD X0002.1",
            "OUT Y0003.7",
            "NETWORK",
            "LD X0002.1",
            "OUT Y0003.7",
            "NETWORK",
            "LD X0002.2",
            "OUT Y0003.6",
            "END"
        ]
    );
    let ids: Vec<u64> = h.state().doc.as_ref().unwrap().project().ladder.blocks[1]
        .networks
        .iter()
        .map(|n| n.id.0)
        .collect();
    assert!(ids[0] != ids[1], "the copy is a new network: {ids:?}");
    h.key_press_modifiers(Modifiers::COMMAND, Key::Z);
    h.run();
    assert_eq!(il_now(&h).len(), 9, "one undo takes the paste back");
    // Cut the second network: it goes, and comes back with Ctrl+V below the first.
    let header2 = cell_pos(&h, 1, 0, 3) - egui::vec2(0.0, 24.0);
    pointer(&mut h, header2, egui::PointerButton::Primary);
    h.key_press_modifiers(Modifiers::COMMAND, Key::X);
    h.run();
    assert_eq!(
        h.state().doc.as_ref().unwrap().project().ladder.blocks[1]
            .networks
            .len(),
        1
    );
}

#[test]
fn cells_selected_with_shift_are_cut_and_pasted_and_ctrl_e_copies_a_row() {
    use egui::{Key, Modifiers};
    let (mut h, _) = editor_on(
        "LEVEL2\nNETWORK\nLD X0002.1\nAND X0002.2\nOUT Y0003.7\n",
        "cells.ldp",
    );
    let p = cell_pos(&h, 0, 0, 0);
    pointer(&mut h, p, egui::PointerButton::Primary);
    h.key_press_modifiers(Modifiers::SHIFT, Key::ArrowRight);
    h.run();
    assert!(matches!(
        h.state().selection,
        Some((
            1,
            ladder_studio::gui::selection::Selection::Cells {
                network: 0,
                rows: (0, 0),
                cols: (0, 1)
            }
        ))
    ));
    h.key_press_modifiers(Modifiers::COMMAND, Key::X);
    h.run();
    let row0 = |h: &Harness<'static, LadderApp>| {
        h.state().doc.as_ref().unwrap().project().ladder.blocks[1].networks[0].rows[0]
            .cells
            .clone()
    };
    assert_eq!(row0(&h)[0], ladder_engine::model::Cell::Empty);
    assert_eq!(row0(&h)[1], ladder_engine::model::Cell::Empty);
    h.key_press_modifiers(Modifiers::COMMAND, Key::V);
    h.run();
    assert_eq!(
        il_now(&h)[3..6],
        ["LD X0002.1", "AND X0002.2", "OUT Y0003.7"],
        "pasted back where they were"
    );
    // Ctrl+E copies the row; Ctrl+V puts it below as a new row.
    h.key_press_modifiers(Modifiers::COMMAND, Key::E);
    h.run();
    h.key_press_modifiers(Modifiers::COMMAND, Key::V);
    h.run();
    let rows = h.state().doc.as_ref().unwrap().project().ladder.blocks[1].networks[0]
        .rows
        .clone();
    assert_eq!(rows.len(), 2);
    assert_eq!(rows[0], rows[1]);
}

#[test]
fn dragging_with_the_pen_draws_wires_along_a_row_and_links_down_a_column() {
    let (mut h, _) = editor_on("LEVEL2\nNETWORK\nLD X0002.1\nOUT Y0003.7\n", "pen.ldp");
    h.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::R); // a second row
    h.run();
    h.get_by_label("Draw lines").click();
    h.run();
    assert!(h.state().pen);
    // A contact in the second row, first column, then a wire and a link to join it.
    let c = cell_pos(&h, 0, 1, 0);
    pointer(&mut h, c, egui::PointerButton::Primary);
    h.key_press(egui::Key::F1);
    enter_operand(&mut h, "X2.2");
    let (a, z) = (cell_pos(&h, 0, 1, 1), cell_pos(&h, 0, 1, 3));
    drag(&mut h, a, z);
    let net = h.state().doc.as_ref().unwrap().project().ladder.blocks[1].networks[0].clone();
    for col in 1..=3 {
        assert_eq!(
            net.rows[1].cells[col],
            ladder_engine::model::Cell::Wire,
            "col {col}"
        );
    }
    let (a, z) = (cell_pos(&h, 0, 0, 4), cell_pos(&h, 0, 1, 4));
    drag(&mut h, a, z);
    let net = h.state().doc.as_ref().unwrap().project().ladder.blocks[1].networks[0].clone();
    assert!(net.link(0, 4), "a link at the left edge of column 5");
    assert_eq!(
        il_now(&h)[3..7],
        ["LD X0002.1", "OR X0002.2", "OUT Y0003.7", "END"],
        "the drawn branch is a parallel contact"
    );
}

#[test]
fn right_click_offers_the_insert_and_delete_commands_at_the_cell() {
    let (mut h, _) = editor_on(TWO_NETWORKS, "menu.ldp");
    let p = cell_pos(&h, 1, 0, 0);
    pointer(&mut h, p, egui::PointerButton::Secondary);
    assert_eq!(
        h.state().cursor.network,
        1,
        "the right click moved the cursor"
    );
    h.get_by_label_contains("Insert network above").click();
    h.run();
    assert_eq!(
        h.state().doc.as_ref().unwrap().project().ladder.blocks[1]
            .networks
            .len(),
        3
    );
    assert!(
        h.state().doc.as_ref().unwrap().project().ladder.blocks[1].networks[1].is_empty(),
        "the new network is above the clicked one"
    );
    let p = cell_pos(&h, 2, 0, 0);
    pointer(&mut h, p, egui::PointerButton::Secondary);
    h.get_by_label("Delete network").click();
    h.run();
    assert_eq!(
        il_now(&h)[3..5],
        ["LD X0002.1", "OUT Y0003.7"],
        "the second network went"
    );
    assert_eq!(
        h.state().doc.as_ref().unwrap().project().ladder.blocks[1]
            .networks
            .len(),
        2
    );
}

#[test]
fn double_clicking_a_contact_edits_its_address() {
    let (mut h, _) = editor_on(TWO_NETWORKS, "dbl.ldp");
    let p = cell_pos(&h, 0, 0, 0);
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
    let prompt = h.state().prompt.clone().expect("the operand prompt opened");
    assert_eq!(prompt.text, "X0002.1", "with the contact's address");
    h.state_mut().prompt.as_mut().unwrap().text.clear();
    enter_operand(&mut h, "X2.3");
    assert_eq!(il_now(&h)[3], "LD X0002.3");
    assert_eq!(
        h.state().doc.as_ref().unwrap().project().ladder.blocks[1].networks[0].rows[0].cells[1],
        ladder_engine::model::Cell::Wire,
        "the wire right of it is untouched"
    );
}

#[test]
fn subprograms_are_created_renamed_listed_by_their_calls_and_deleted_with_undo() {
    let (mut h, _) = editor_on(
        "LEVEL2\nNETWORK\nLD X0002.1\nCALL P0007\nNETWORK\nCALLU P0007\n\
         SUB P0007 \"LUBE\"\nNETWORK\nLD R0001.0\nOUT R0001.1\nEND\n",
        "subs.ldp",
    );
    h.get_by_label("Tools").click();
    h.run();
    h.get_by_label("New subprogram…").click();
    h.run();
    h.get_by_role_and_label(egui::accesskit::Role::TextInput, "Number name")
        .type_text("5 SPINDLE");
    h.run();
    h.key_press(egui::Key::Enter);
    h.run();
    h.get_by_label("P0005 SPINDLE");
    let blocks = h
        .state()
        .doc
        .as_ref()
        .unwrap()
        .project()
        .ladder
        .blocks
        .len();
    assert_eq!(blocks, 4, "P0005 joins P0007");
    assert_eq!(
        h.state().view,
        View::Block(2),
        "the new subprogram is shown"
    );
    // A second one with the same number is refused with the reason.
    h.state_mut()
        .ask(ladder_studio::gui::command::Command::NewSub);
    h.run();
    h.get_by_role_and_label(egui::accesskit::Role::TextInput, "Number name")
        .type_text("P5");
    h.run();
    h.key_press(egui::Key::Enter);
    h.run();
    let out: Vec<String> = h.state().output.iter().map(|l| l.text.clone()).collect();
    assert!(
        h.state()
            .prompt
            .as_ref()
            .and_then(|p| p.error.clone())
            .unwrap_or_else(|| panic!("{out:?}"))
            .contains("already exists")
    );
    h.key_press(egui::Key::Escape);
    h.run();
    // View calls.
    h.state_mut()
        .ask(ladder_studio::gui::command::Command::ViewCalls(7));
    h.run();
    assert_eq!(h.state().output.last().unwrap().text, "P0007: 2 calls");
    h.get_by_label_contains("LEVEL2 N0002 1:  CALLU P0007");
    h.get_by_label_contains("LEVEL2 N0001 1:  CALL P0007");
    // Rename.
    h.state_mut()
        .ask(ladder_studio::gui::command::Command::RenameSub(5));
    h.run();
    assert_eq!(
        h.state().prompt.as_ref().unwrap().text,
        "5 SPINDLE",
        "the prompt shows the current number and name"
    );
    h.state_mut().prompt.as_mut().unwrap().text = "5 SPINDLE_MAIN".into();
    h.run();
    h.key_press(egui::Key::Enter);
    h.run();
    h.get_by_label("P0005 SPINDLE_MAIN");
    // Delete, and undo brings it back.
    h.state_mut()
        .ask(ladder_studio::gui::command::Command::DeleteSub(5));
    h.run();
    assert!(h.query_by_label("P0005 SPINDLE_MAIN").is_none());
    h.state_mut().undo();
    h.run();
    h.get_by_label("P0005 SPINDLE_MAIN");
}

#[test]
fn typing_after_f1_completes_from_the_symbol_table() {
    let mut h = harness(None, Lang::En);
    h.run();
    h.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::I);
    h.run();
    h.key_press(egui::Key::F1);
    h.run();
    h.get_by_role_and_label(egui::accesskit::Role::TextInput, "Operand")
        .type_text("tool_t");
    h.run();
    h.get_by_label_contains("TOOL_T1  X0000.0  Tool station 1 sensor");
    h.key_press(egui::Key::Tab);
    h.run();
    assert_eq!(h.state().prompt.as_ref().unwrap().text, "TOOL_T1");
    h.key_press(egui::Key::Enter);
    h.run();
    let c = h.state().cursor;
    let cell = h.state().doc.as_ref().unwrap().project().ladder.blocks[1].networks[c.network].rows
        [0]
    .cells[0]
        .clone();
    assert_eq!(
        cell,
        ladder_engine::model::Cell::Contact {
            negated: false,
            operand: ladder_engine::model::Operand::Symbol("TOOL_T1".into())
        }
    );
}

fn double_click(h: &mut Harness<'static, LadderApp>, p: egui::Pos2) {
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

#[test]
fn the_reference_index_filters_by_address_and_jumps_to_the_element() {
    let (mut h, _) = editor_on(TWO_NETWORKS, "xref.ldp");
    h.get_by_label("Cross-reference").click();
    h.run();
    h.get_by_label("Index").click();
    h.run();
    h.get_by_role_and_label(egui::accesskit::Role::TextInput, "Address or symbol")
        .click();
    h.run();
    h.get_by_role_and_label(egui::accesskit::Role::TextInput, "Address or symbol")
        .type_text("y3.6");
    h.run();
    assert_eq!(h.state().xref_filter, "y3.6");
    assert!(
        h.query_by_label_contains("Y0003.7").is_none(),
        "the filter leaves only Y3.6"
    );
    let place = h.get_by_label("N0002 1:11").rect().center();
    double_click(&mut h, place);
    assert_eq!(h.state().view, View::Block(1));
    let c = h.state().cursor;
    assert_eq!((c.block, c.network, c.row, c.col), (1, 1, 0, 10));
}

#[test]
fn every_view_opened_gets_a_tab_that_switches_back_to_it() {
    let mut h = harness(None, Lang::En);
    h.run();
    h.get_by_label("Level 1").click();
    h.run();
    h.get_by_label("Display messages").click();
    h.run();
    assert_eq!(
        h.state().tabs,
        [View::Block(1), View::Block(0), View::Messages]
    );
    h.get_by_label("Tab: Level 2").click();
    h.run();
    assert_eq!(h.state().view, View::Block(1));
}

#[test]
fn commands_after_undoing_a_new_subprogram_neither_panic_nor_leave_stray_steps() {
    use egui::{Key, Modifiers};
    let (mut h, _) = editor_on(TWO_NETWORKS, "stale.ldp");
    h.state_mut()
        .ask(ladder_studio::gui::command::Command::NewSub);
    h.run();
    h.get_by_role_and_label(egui::accesskit::Role::TextInput, "Number name")
        .type_text("77 FOO");
    h.run();
    h.key_press(Key::Enter);
    h.run();
    assert_eq!(h.state().view, View::Block(2));
    // The rename prompt is open on P0077 when its creation is undone.
    h.state_mut()
        .ask(ladder_studio::gui::command::Command::RenameSub(77));
    h.run();
    h.state_mut().undo();
    h.run();
    assert_eq!(
        h.state().view,
        View::Block(1),
        "the view left the vanished block"
    );
    h.key_press(Key::Enter);
    h.run();
    let err = h.state().prompt.as_ref().and_then(|p| p.error.clone());
    assert!(err.is_some_and(|e| e.contains("no longer exists")));
    h.key_press(Key::Escape);
    h.run();
    let before = h.state().doc.as_ref().unwrap().history().undo_len();
    for k in [Key::F5, Key::Delete] {
        h.key_press(k);
        h.run();
    }
    h.key_press_modifiers(Modifiers::COMMAND, Key::V);
    h.run();
    // Level 1 is empty: Delete and a refused operand add nothing.
    h.get_by_label("Level 1").click();
    h.run();
    let l1 = |h: &Harness<'static, LadderApp>| {
        h.state().doc.as_ref().unwrap().project().ladder.blocks[0]
            .networks
            .len()
    };
    h.key_press(Key::Delete);
    h.run();
    h.key_press(Key::F1);
    enter_operand(&mut h, "X99999.9");
    assert!(h.state().prompt.as_ref().unwrap().error.is_some());
    h.key_press(Key::Escape);
    h.run();
    h.key_press(Key::F3);
    h.run();
    h.key_press(Key::Escape);
    h.run();
    assert_eq!(l1(&h), 0, "no network was added for nothing");
    // A contact in the empty block is one undo step, network included.
    let steps = h.state().doc.as_ref().unwrap().history().undo_len();
    h.key_press(Key::F1);
    enter_operand(&mut h, "X2.1");
    assert_eq!(l1(&h), 1);
    assert_eq!(
        h.state().doc.as_ref().unwrap().history().undo_len(),
        steps + 1
    );
    h.key_press_modifiers(Modifiers::COMMAND, Key::Z);
    h.run();
    assert_eq!(l1(&h), 0, "one undo takes back the contact and its network");
    assert!(h.state().doc.as_ref().unwrap().history().undo_len() >= before);
}

#[test]
fn escape_keeps_the_recovery_copy_and_an_open_answered_late_still_asks() {
    use egui::{Key, Modifiers};
    let dir = tempfile_dir();
    let rec = dir.join("recovery-esc");
    let _ = std::fs::remove_dir_all(&rec);
    let path = dir.join("late.ldp");
    ladder_engine::file::save(&ladder_engine::model::Project::default(), &path).unwrap();
    {
        let mut h = harness(Some(path.clone()), Lang::En);
        h.state_mut().recovery_dir = Some(rec.clone());
        h.run();
        h.key_press_modifiers(Modifiers::COMMAND, Key::I);
        h.run();
        h.state_mut().autosave_now();
    }
    let mut h = harness(None, Lang::En);
    h.state_mut().recovery_dir = Some(rec.clone());
    h.state_mut().offer_restore();
    h.run();
    h.key_press(Key::Escape);
    h.run();
    assert!(h.state().question.is_none());
    assert_eq!(
        ladder_studio::gui::files::recovery_copies(&rec).len(),
        1,
        "Escape leaves the copy for later"
    );
    // Ctrl+O on an unchanged project, an edit while the dialog is open, then the answer.
    scripted(&mut h, vec![Some(path.clone())]);
    h.state_mut()
        .request(ladder_studio::gui::files::Action::OpenDialog);
    h.state_mut().insert_network(true);
    h.run();
    assert!(
        matches!(
            h.state().question,
            Some(ladder_studio::gui::files::Question::Unsaved { .. })
        ),
        "the edit made meanwhile is not dropped without asking"
    );
}

#[test]
fn ctrl_g_in_a_table_goes_to_a_row_of_the_table() {
    use egui::{Key, Modifiers};
    let mut h = harness(None, Lang::En);
    h.run();
    h.state_mut().view = View::Symbols(0);
    h.run();
    h.key_press_modifiers(Modifiers::COMMAND, Key::G);
    enter_operand(&mut h, "25");
    assert!(h.state().prompt.is_none());
    let sheet = ladder_studio::gui::tables::Sheet::Symbols(0);
    assert_eq!(h.state().tables.selected.get(&sheet), Some(&24));
    assert!(
        h.query_all_by_value("KEY_SP_CCW").next().is_some(),
        "row 25 was scrolled into view (only visible rows are laid out)"
    );
    h.key_press_modifiers(Modifiers::COMMAND, Key::G);
    enter_operand(&mut h, "9999");
    let err = h.state().prompt.clone().unwrap().error.unwrap();
    assert!(err.starts_with("The table has no such row: 1–245"), "{err}");
}

#[test]
fn the_toolbar_delete_deletes_the_selection_and_adds_nothing_to_an_empty_block() {
    use egui::{Key, Modifiers};
    let (mut h, _) = editor_on(
        "LEVEL2\nNETWORK\nLD X0002.1\nAND X0002.2\nOUT Y0003.7\n",
        "tooldel.ldp",
    );
    let p = cell_pos(&h, 0, 0, 0);
    pointer(&mut h, p, egui::PointerButton::Primary);
    h.key_press_modifiers(Modifiers::SHIFT, Key::ArrowRight);
    h.run();
    h.get_by_label("Delete").click();
    h.run();
    let cells = h.state().doc.as_ref().unwrap().project().ladder.blocks[1].networks[0].rows[0]
        .cells
        .clone();
    assert_eq!(
        cells[..2],
        [
            ladder_engine::model::Cell::Empty,
            ladder_engine::model::Cell::Empty
        ],
        "both selected contacts went, as with the Delete key"
    );
    assert_eq!(h.state().doc.as_ref().unwrap().history().undo_len(), 1);
    // On a new project's empty level 2 the button deletes nothing and adds no network.
    h.state_mut()
        .perform(ladder_studio::gui::files::Action::New);
    h.run();
    h.get_by_label("Delete").click();
    h.run();
    let doc = h.state().doc.as_ref().unwrap();
    assert!(doc.project().ladder.blocks[1].networks.is_empty());
    assert_eq!(doc.history().undo_len(), 0);
    assert!(!doc.dirty);
}

#[test]
fn undo_goes_to_the_view_and_the_place_it_changes() {
    use egui::{Key, Modifiers};
    let (mut h, _) = editor_on(TWO_NETWORKS, "undoview.ldp");
    // A change in a table, then the ladder view and a change in its second network.
    let mut tables = h
        .state()
        .doc
        .as_ref()
        .unwrap()
        .project()
        .symbol_tables
        .clone();
    tables[0].rows.push(ladder_engine::model::Symbol {
        name: "START".into(),
        address: ladder_engine::Address::parse("X0002.1").unwrap(),
        comments: Default::default(),
    });
    h.state_mut()
        .edit_table(ladder_engine::model::TableEdit::Symbols(tables));
    h.state_mut().view = View::Messages;
    h.run();
    h.key_press_modifiers(Modifiers::COMMAND, Key::Z);
    h.run();
    assert_eq!(
        h.state().view,
        View::Symbols(0),
        "the undone rename is shown"
    );
    assert!(
        h.state().doc.as_ref().unwrap().project().symbol_tables[0]
            .rows
            .is_empty()
    );
    h.state_mut().view = View::Block(1);
    h.state_mut().cursor.network = 1;
    h.run();
    h.key_press(Key::Delete);
    h.run();
    h.state_mut().cursor.network = 0;
    h.state_mut().view = View::Data;
    h.run();
    h.key_press_modifiers(Modifiers::COMMAND, Key::Z);
    h.run();
    assert_eq!(h.state().view, View::Block(1));
    assert_eq!(
        h.state().cursor.network,
        1,
        "the cursor is on the contact brought back"
    );
}
