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

fn tempfile_dir() -> PathBuf {
    let dir = std::env::temp_dir().join(format!(
        "ladder-gui-test-{}-{:?}",
        std::process::id(),
        std::thread::current().id()
    ));
    std::fs::create_dir_all(&dir).unwrap();
    dir
}
