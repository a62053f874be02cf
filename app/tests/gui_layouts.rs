//! The editor in a small window (900×600): the F3 dialog, the version page and the tables
//! fit, fields keep a usable width, and the dialog's rows stay put as messages come and go.

use crate::common::*;
use egui::Key;
use egui::accesskit::Role;
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;

const SMALL: egui::Vec2 = egui::vec2(900.0, 600.0);

fn small(project: Option<std::path::PathBuf>, lang: Lang) -> Harness<'static, LadderApp> {
    let mut h = harness_sized(project, lang, SMALL);
    h.run();
    h
}

fn inside(r: egui::Rect) -> bool {
    r.left() >= 0.0 && r.top() >= 0.0 && r.right() <= SMALL.x && r.bottom() <= SMALL.y
}

#[test]
fn the_f3_dialog_fits_900_by_600_and_its_rows_stay_under_the_pointer() {
    let dir = tempfile_dir();
    let path = dir.join("f3.ldp");
    let p = ladder_engine::il::import("LEVEL1\nNETWORK\nLD X0002.1\nOUT Y0000.0\n")
        .project
        .unwrap();
    ladder_engine::file::save(&p, &path).unwrap();
    let mut h = small(Some(path), Lang::En);
    click_cell(&mut h, 0, 0, 1);
    h.key_press(Key::F3);
    h.run();
    fill(&mut h, "Instruction line", "TMRB T0000 DT0004 R0300.0");
    for (role, label) in [
        (Role::TextInput, "Instruction line"),
        (Role::TextInput, "Search"),
        (Role::TextInput, "T"),
        (Role::TextInput, "PT"),
        (Role::TextInput, "OUT"),
        (Role::Button, "OK"),
        (Role::Button, "Cancel"),
    ] {
        let r = h.get_by_role_and_label(role, label).rect();
        assert!(inside(r), "{label} is on screen at 900×600: {r:?}");
        if role == Role::TextInput {
            assert!(
                r.width() >= 100.0,
                "{label} is wide enough to type in: {r:?}"
            );
        }
    }
    // A refusal appears under T; OUT's row does not move.
    let before = h.get_by_role_and_label(Role::TextInput, "OUT").rect();
    fill(&mut h, "T", "X0000.0");
    let refused = ["not allowed", "needs a", "beyond"]
        .iter()
        .any(|t| h.query_all_by_label_contains(t).next().is_some());
    assert!(refused, "the refusal is shown");
    let after = h.get_by_role_and_label(Role::TextInput, "OUT").rect();
    assert_eq!(before, after, "the rows stay where they were");
}

#[test]
fn the_version_page_and_the_symbol_table_fit_900_by_600() {
    let mut h = small(None, Lang::Zh);
    h.state_mut()
        .show_view(ladder_studio::gui::place::View::Version);
    h.run();
    let fields: Vec<egui::Rect> = h
        .get_all_by_role(Role::TextInput)
        .chain(h.get_all_by_role(Role::MultilineTextInput))
        .map(|n| n.rect())
        .collect();
    assert!(fields.len() >= 3, "the version fields are shown");
    for r in &fields {
        assert!(
            r.right() <= SMALL.x,
            "a version field runs off the window: {r:?}"
        );
        assert!(
            r.width() >= 150.0,
            "a version field is too narrow to read: {r:?}"
        );
    }
    // The password part below the fold can be scrolled to.
    h.get_by_label("设置密码").scroll_to_me();
    h.run();
    let r = h.get_by_label("设置密码").rect();
    assert!(inside(r), "the password buttons can be reached: {r:?}");
    h.state_mut()
        .show_view(ladder_studio::gui::place::View::Symbols(0));
    h.run();
    let cells: Vec<egui::Rect> = h
        .get_all_by_role(Role::TextInput)
        .map(|n| n.rect())
        .filter(|r| r.top() < SMALL.y && r.bottom() > 0.0)
        .collect();
    assert!(!cells.is_empty());
    for r in &cells {
        assert!(r.width() >= 40.0, "no one-character columns: {r:?}");
    }
    // The toolbars wrap: every tool and choice is inside the window.
    for role in [Role::Button, Role::ComboBox, Role::CheckBox, Role::Label] {
        for n in h.query_all_by_role(role) {
            let r = n.rect();
            if r.top() < 140.0 {
                assert!(r.right() <= SMALL.x + 0.5, "a tool is off screen: {n:?}");
            }
        }
    }
}

#[test]
fn a_row_inserted_below_shows_its_address_as_a_suggestion_not_as_typed_text() {
    let mut h = small(None, Lang::En);
    h.state_mut()
        .show_view(ladder_studio::gui::place::View::Symbols(0));
    h.run();
    h.get_by_role_and_label(Role::TextInput, "Symbol 1").click();
    h.run();
    h.key_press(Key::Escape);
    h.run();
    h.get_by_label("Insert row below").click();
    h.run();
    let rows = &h.state().doc().unwrap().project().symbol_tables[0].rows;
    assert!(rows[1].name.is_empty(), "a new, blank row 2");
    let proposed = rows[1].address.to_string();
    let field = h.get_by_role_and_label(Role::TextInput, "Address 2");
    assert_eq!(
        field.value().as_deref(),
        Some(""),
        "the address is not written as text"
    );
    // Once the row has a name, its address is real data and reads as such.
    h.get_by_role_and_label(Role::TextInput, "Symbol 2").click();
    h.run();
    h.get_by_role_and_label(Role::TextInput, "Symbol 2")
        .type_text("NEW_SIGNAL");
    h.key_press(Key::Enter);
    h.run();
    let field = h.get_by_role_and_label(Role::TextInput, "Address 2");
    assert_eq!(field.value().as_deref(), Some(proposed.as_str()));
}
