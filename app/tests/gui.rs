//! The editor driven headless through egui_kittest, by role and label.

use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;
use ladder_studio::gui::LadderApp;
use ladder_studio::gui::i18n::Lang;
use ladder_studio::gui::tree::View;
use std::path::PathBuf;

fn harness(path: Option<PathBuf>, lang: Lang) -> Harness<'static, LadderApp> {
    Harness::builder()
        .with_size(egui::vec2(1280.0, 800.0))
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
    assert_eq!(last, "Compiled without errors (706 steps)");
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
    assert_eq!(diag.target, Some((1, 1)), "{}", diag.text);
    h.get_by_label_contains("undefined symbol `NOWHERE`")
        .click();
    h.run();
    assert_eq!(h.state().view, View::Block(1), "the error's block is shown");
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
    let empty = h.state().doc.as_ref().unwrap().project.ladder.clone();
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
    let drawn = h.state().doc.as_ref().unwrap().project.ladder.clone();
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
    assert_eq!(h.state().doc.as_ref().unwrap().project.ladder, empty);
    for _ in 0..20 {
        h.key_press_modifiers(Modifiers::COMMAND, Key::Y);
        h.run();
    }
    assert_eq!(h.state().doc.as_ref().unwrap().project.ladder, drawn);
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
    let project = &h.state().doc.as_ref().unwrap().project;
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
    h.get_by_label_contains("Save").click();
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
