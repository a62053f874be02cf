//! The editor's file handling driven headless: new, open, save, the unsaved-changes question, damaged files, recovery copies, export and import.

use crate::common::*;
use ladder_studio::gui::editor::EditState;
use ladder_studio::gui::files::FileState;

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
        ladder_engine::file::load(&path).unwrap().ladder.blocks[0]
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
    assert!(
        !h.state().feature::<FileState>().exit_confirmed,
        "the window stays while asking"
    );
    h.get_by_label_contains("Save the changes to");
    h.get_by_label("Save changes").click();
    h.run();
    assert!(
        h.state().feature::<FileState>().exit_confirmed,
        "saved, then closed"
    );
    let saved = ladder_engine::file::load(&path).unwrap();
    assert_eq!(
        saved.ladder.blocks[0].networks.len(),
        1,
        "the change (a network in level 1, where the editor opens) was saved"
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
    assert_eq!(h.state().settings().recent.first(), Some(&path));
    assert_eq!(
        ladder_engine::file::load(&path).unwrap(),
        h.state().doc().unwrap().project().clone()
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
    h.state_mut().with(|o: &mut FileState, cx| {
        o.request(
            cx,
            ladder_studio::gui::files::CloseAction::Open(path.clone()),
        )
    });
    h.run();
    h.get_by_label_contains("Open what can be read of it");
    h.get_by_label("Open read-only").click();
    h.run();
    let doc = h.state().doc().unwrap();
    assert!(doc.is_read_only() && doc.path().is_none());
    h.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::I);
    h.run();
    assert_eq!(
        h.state().doc().unwrap().project().ladder.blocks[1]
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
            .output()
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
    assert!(!h.state().doc().unwrap().is_read_only());
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
        h.state_mut()
            .with(|f: &mut FileState, _| f.recovery_dir = Some(rec.clone()));
        h.run();
        h.key_press_modifiers(Modifiers::COMMAND, Key::I);
        h.run();
        h.state_mut()
            .with(|o: &mut FileState, cx| o.autosave_now(cx));
        // The session ends here without closing: a crash.
    }
    let copies = ladder_studio::gui::files::recovery_copies(&rec);
    assert_eq!(copies.len(), 1);
    assert_eq!(copies[0].original.as_ref(), Some(&path));
    let mut h = harness(None, Lang::En);
    h.state_mut()
        .with(|f: &mut FileState, _| f.recovery_dir = Some(rec.clone()));
    h.state_mut().with(|f: &mut FileState, _| f.offer_restore());
    h.run();
    h.get_by_label_contains("did not end normally");
    h.get_by_label("Restore").click();
    h.run();
    assert_eq!(doc_state(&h), Some((Some(path.clone()), true, 1)));
    // Saving the restored work removes the copy.
    h.key_press_modifiers(Modifiers::COMMAND, Key::S);
    h.run();
    assert_eq!(
        ladder_engine::file::load(&path).unwrap().ladder.blocks[0]
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
    let project = h.state().doc().unwrap().project().clone();
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
        h.state_mut()
            .with(|f: &mut FileState, _| f.recovery_dir = Some(rec.clone()));
        h.run();
        h.key_press_modifiers(Modifiers::COMMAND, Key::I);
        h.run();
        h.state_mut()
            .with(|o: &mut FileState, cx| o.autosave_now(cx));
    }
    let mut h = harness(None, Lang::En);
    h.state_mut()
        .with(|f: &mut FileState, _| f.recovery_dir = Some(rec.clone()));
    h.state_mut().with(|f: &mut FileState, _| f.offer_restore());
    h.run();
    h.key_press(Key::Escape);
    h.run();
    assert!(h.state().feature::<FileState>().question.is_none());
    assert_eq!(
        ladder_studio::gui::files::recovery_copies(&rec).len(),
        1,
        "Escape leaves the copy for later"
    );
    // Ctrl+O on an unchanged project, an edit while the dialog is open, then the answer.
    scripted(&mut h, vec![Some(path.clone())]);
    h.state_mut().with(|o: &mut FileState, cx| {
        o.request(cx, ladder_studio::gui::files::CloseAction::OpenDialog)
    });
    h.state_mut()
        .with(|o: &mut EditState, cx| o.insert_network(cx, true));
    h.run();
    assert!(
        matches!(
            h.state().feature::<FileState>().question,
            Some(ladder_studio::gui::files::Question::Unsaved { .. })
        ),
        "the edit made meanwhile is not dropped without asking"
    );
}

#[test]
fn the_window_title_names_the_project_and_marks_unsaved_changes() {
    let dir = tempfile_dir();
    let path = dir.join("mill.ldp");
    ladder_engine::file::save(&ladder_engine::model::Project::default(), &path).unwrap();
    let mut h = harness(Some(path), Lang::En);
    h.run();
    assert_eq!(h.state().title(), "mill.ldp — Ladder Studio");
    h.key_press(egui::Key::F4);
    h.run();
    assert!(h.state().doc().unwrap().is_dirty(), "a wire was drawn");
    assert_eq!(h.state().title(), "mill.ldp* — Ladder Studio");
    h.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::S);
    h.run();
    assert_eq!(h.state().title(), "mill.ldp — Ladder Studio", "saved");
}

#[test]
fn without_a_system_dialog_save_as_asks_in_the_window_and_saves_under_the_typed_name() {
    use egui::accesskit::Role;
    use egui::{Key, Modifiers};
    let dir = tempfile_dir();
    let first = dir.join("first.ldp");
    ladder_engine::file::save(&ladder_engine::model::Project::default(), &first).unwrap();
    // egui_file's two text fields carry no accessible name (its labels stand beside them):
    // the check that every input is named is off for this one test.
    let open = first.clone();
    let mut h = egui_kittest::Harness::builder()
        .with_size(egui::vec2(1280.0, 800.0))
        .with_step_dt(1.0 / 60.0)
        .with_accessibility_check(false)
        .build_eframe(move |cc| {
            let mut app = LadderApp::from_creation(cc, Some(open));
            app.settings_mut().lang = Lang::Zh;
            app
        });
    h.state_mut().with(|f: &mut FileState, _| {
        f.dialogs = Box::new(ladder_studio::gui::files::file_dialog::SystemDialogs::in_app_only())
    });
    h.run();
    h.get_by_label("文件").click();
    h.run();
    h.get_by_label("另存为…").click();
    h.run();
    // The editor's own dialog, in the UI language, on the project's folder and name.
    h.get_by_label_contains("💾  另存为");
    h.get_by_label("文件名：");
    // The file-name field is the dialog's last text field (the folder path comes first).
    h.get_all_by_role(Role::TextInput).last().unwrap().click();
    h.run();
    h.key_press_modifiers(Modifiers::COMMAND, Key::A);
    h.get_all_by_role(Role::TextInput)
        .last()
        .unwrap()
        .type_text("second");
    h.run();
    h.key_press(Key::Enter);
    h.run();
    let second = dir.join("second.ldp");
    assert_eq!(doc_state(&h), Some((Some(second.clone()), false, 0)));
    assert!(
        ladder_engine::file::load(&second).is_ok(),
        "saved and reads back"
    );
    assert!(first.exists(), "the first file is left as it was");
}

#[test]
fn each_project_starts_with_its_own_output() {
    use ladder_studio::gui::command::Command;
    use ladder_studio::gui::files::CloseAction;
    let dir = tempfile_dir();
    // A project that does not compile: its red summary in the output window.
    let bad = ladder_engine::il::import("LEVEL2\nNETWORK\nLD X0010.0\nOUT Y0010.0\n")
        .project
        .unwrap();
    let mut bad = bad;
    if let ladder_engine::model::Cell::Contact { operand, .. } =
        &mut bad.ladder.blocks[1].networks[0].rows[0].cells[0]
    {
        *operand = ladder_engine::model::Operand::parse("NO_SUCH_SYMBOL").unwrap();
    }
    let bad_path = dir.join("bad.ldp");
    ladder_engine::file::save(&bad, &bad_path).unwrap();
    let good_path = dir.join("good.ldp");
    ladder_engine::file::save(&ladder_engine::model::Project::default(), &good_path).unwrap();
    let mut h = harness(Some(bad_path), Lang::En);
    h.run();
    h.state_mut().ask(Command::Compile);
    h.run();
    assert!(
        h.state().output().iter().any(|l| l.error),
        "the errors are listed"
    );
    h.state_mut()
        .with(|o: &mut FileState, cx| o.perform(cx, CloseAction::Open(good_path)));
    h.run();
    assert!(
        h.state()
            .output()
            .iter()
            .all(|l| !l.error && !l.text.contains("NO_SUCH_SYMBOL")),
        "nothing of the other project: {:?}",
        h.state()
            .output()
            .iter()
            .map(|l| &l.text)
            .collect::<Vec<_>>()
    );
}
