//! The table editors driven headless on the bundled sample: a comment column per language,
//! each edited in place, undone, exported, walked with Tab, and reachable in a small window.

use crate::common::*;
use egui::accesskit::Role;
use ladder_engine::model::Project;

fn project<'a>(h: &'a Harness<'static, LadderApp>) -> &'a Project {
    h.state().doc().expect("the sample is open").project()
}

/// The sample's first symbol table shown, in English.
fn on_symbols(size: egui::Vec2) -> Harness<'static, LadderApp> {
    let mut h = harness(None, Lang::En);
    h.set_size(size);
    h.run();
    h.state_mut().show_view(View::Symbols(0));
    h.run();
    h
}

fn cell_value(h: &Harness<'static, LadderApp>, cell: &str) -> String {
    h.get_by_role_and_label(Role::TextInput, cell)
        .value()
        .unwrap_or_default()
}

fn cell_rect(h: &Harness<'static, LadderApp>, cell: &str) -> egui::Rect {
    h.get_by_role_and_label(Role::TextInput, cell).rect()
}

/// Clicks a cell, replaces its text (deleting what was there) and presses Enter, as a user
/// does.
fn enter(h: &mut Harness<'static, LadderApp>, cell: &str, text: &str) {
    h.get_by_role_and_label(Role::TextInput, cell).click();
    h.run();
    h.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::A);
    h.key_press(egui::Key::Backspace);
    h.get_by_role_and_label(Role::TextInput, cell)
        .type_text(text);
    h.run();
    h.key_press(egui::Key::Enter);
    h.run();
}

/// The comments CSV's line of a symbol.
fn csv_line(p: &Project, table: usize, row: usize) -> String {
    let t = &p.symbol_tables[table];
    let prefix = format!(
        "symbol,{},{},{},",
        t.name, t.rows[row].address, t.rows[row].name
    );
    ladder_engine::comments::export(p, None)
        .lines()
        .find(|l| l.starts_with(&prefix))
        .unwrap_or_else(|| panic!("a line {prefix}…"))
        .to_string()
}

#[test]
fn both_languages_of_a_comment_are_shown_and_each_is_edited_in_place() {
    let mut h = on_symbols(egui::vec2(1280.0, 800.0));
    let original = project(&h).clone();
    let first = &original.symbol_tables[0].rows[0];
    let (zh, en) = (first.comments["zh"].clone(), first.comments["en"].clone());
    assert!(
        !zh.is_empty() && !en.is_empty() && zh != en,
        "the sample has both"
    );

    for title in ["Comment (zh)", "Comment (en)"] {
        h.get_by_label(title);
    }
    assert!(
        h.query_by_label("Comment").is_none(),
        "no single comment column"
    );
    assert_eq!(cell_value(&h, "Comment (zh) 1"), zh);
    assert_eq!(cell_value(&h, "Comment (en) 1"), en);
    // Side by side in one frame, both inside the window.
    for cell in ["Comment (zh) 1", "Comment (en) 1"] {
        let r = cell_rect(&h, cell);
        assert!(r.left() >= 0.0 && r.right() <= 1280.0, "{cell} at {r:?}");
    }
    assert_eq!(
        cell_rect(&h, "Comment (zh) 1").center().y,
        cell_rect(&h, "Comment (en) 1").center().y,
        "in the same row"
    );

    enter(&mut h, "Comment (en) 1", "Tool station sensors as one byte");
    let c = &project(&h).symbol_tables[0].rows[0].comments;
    assert_eq!(c["en"], "Tool station sensors as one byte");
    assert_eq!(c["zh"], zh, "the Chinese comment is not touched");
    assert_eq!(c.len(), 2);
    let mut expected = original.symbol_tables.clone();
    expected[0].rows[0]
        .comments
        .insert("en".into(), "Tool station sensors as one byte".into());
    assert_eq!(project(&h).symbol_tables, expected, "nothing else changed");
    assert_eq!(
        csv_line(project(&h), 0, 0),
        format!(
            "symbol,{},X0000,TOOL_SENSORS,{zh},Tool station sensors as one byte",
            original.symbol_tables[0].name
        ),
        "the export's en column has the new text"
    );

    h.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::Z);
    h.run();
    assert_eq!(project(&h).symbol_tables, original.symbol_tables, "undone");
    assert_eq!(cell_value(&h, "Comment (en) 1"), en);
    assert_eq!(csv_line(project(&h), 0, 0), csv_line(&original, 0, 0));

    enter(&mut h, "Comment (zh) 1", "");
    let c = &project(&h).symbol_tables[0].rows[0].comments;
    assert_eq!((c.get("zh"), c.get("en")), (None, Some(&en)), "cleared one");
}

#[test]
fn a_comment_too_long_is_refused_in_its_own_column() {
    let mut h = on_symbols(egui::vec2(1280.0, 800.0));
    let original = project(&h).clone();
    let long = "x".repeat(128);
    enter(&mut h, "Comment (en) 2", &long);
    h.get_by_label_contains("at most 127 bytes");
    assert_eq!(project(&h).symbol_tables, original.symbol_tables);
    assert_eq!(cell_value(&h, "Comment (en) 2"), long, "kept to be fixed");
    assert_eq!(
        cell_value(&h, "Comment (zh) 2"),
        original.symbol_tables[0].rows[1].comments["zh"],
        "the other language's cell as it was"
    );
}

#[test]
fn tab_walks_from_one_language_to_the_next_committing_on_the_way() {
    let mut h = on_symbols(egui::vec2(1280.0, 800.0));
    let en = project(&h).symbol_tables[0].rows[0].comments["en"].clone();
    h.get_by_role_and_label(Role::TextInput, "Comment (zh) 1")
        .click();
    h.run();
    h.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::A);
    h.get_by_role_and_label(Role::TextInput, "Comment (zh) 1")
        .type_text("刀位信号");
    h.run();
    h.key_press(egui::Key::Tab);
    h.run();
    assert!(
        h.get_by_role_and_label(Role::TextInput, "Comment (en) 1")
            .is_focused(),
        "Tab goes on to the English comment of the same row"
    );
    let c = &project(&h).symbol_tables[0].rows[0].comments;
    assert_eq!((c["zh"].as_str(), &c["en"]), ("刀位信号", &en));
    h.key_press_modifiers(egui::Modifiers::SHIFT, egui::Key::Tab);
    h.run();
    assert!(
        h.get_by_role_and_label(Role::TextInput, "Comment (zh) 1")
            .is_focused(),
        "and Shift+Tab back"
    );
}

#[test]
fn a_small_window_scrolls_the_columns_sideways_to_the_cell_being_edited() {
    let (width, height) = (900.0, 600.0);
    let mut h = on_symbols(egui::vec2(width, height));
    for cell in ["Address 1", "Symbol 1", "Comment (zh) 1", "Comment (en) 1"] {
        let w = cell_rect(&h, cell).width();
        assert!(w >= 60.0, "{cell} is {w} wide");
    }
    assert!(
        cell_rect(&h, "Comment (en) 1").right() > width,
        "the grid is wider than the window"
    );
    h.get_by_role_and_label(Role::TextInput, "Comment (zh) 1")
        .click();
    h.run();
    h.key_press(egui::Key::Tab);
    h.run();
    let r = cell_rect(&h, "Comment (en) 1");
    assert!(
        r.right() <= width && r.left() >= 0.0,
        "scrolled into view: {r:?}"
    );
    h.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::A);
    h.get_by_role_and_label(Role::TextInput, "Comment (en) 1")
        .type_text("Tool sensors");
    h.run();
    h.key_press(egui::Key::Enter);
    h.run();
    assert_eq!(
        project(&h).symbol_tables[0].rows[0].comments["en"],
        "Tool sensors"
    );
}

#[test]
fn message_texts_and_data_comments_have_a_column_per_language_too() {
    let (width, height) = (900.0, 600.0);
    let mut h = harness(None, Lang::En);
    h.set_size(egui::vec2(width, height));
    h.run();
    h.state_mut().show_view(View::Messages);
    h.run();
    let texts = project(&h).messages.rows[0].texts.clone();
    assert_eq!(cell_value(&h, "Message text (zh) 1"), texts["zh"]);
    assert_eq!(cell_value(&h, "Message text (en) 1"), texts["en"]);
    enter(&mut h, "Message text (zh) 1", "刀架换刀时间过长");
    let now = &project(&h).messages.rows[0].texts;
    assert_eq!(now["zh"], "刀架换刀时间过长");
    assert_eq!(now["en"], texts["en"], "the English text is not touched");

    h.state_mut().show_view(View::Data);
    h.run();
    h.get_by_label("D").click();
    h.run();
    let comments = project(&h).data.d[0].comments.clone();
    for cell in [
        "Address 1",
        "Initial value 1",
        "Min 1",
        "Max 1",
        "Symbol 1",
        "Comment (zh) 1",
        "Comment (en) 1",
    ] {
        let w = cell_rect(&h, cell).width();
        assert!(w >= 60.0, "{cell} is {w} wide");
    }
    // From the symbol, Tab walks into both comments, each brought into the window.
    h.get_by_role_and_label(Role::TextInput, "Symbol 1").click();
    h.run();
    for cell in ["Comment (zh) 1", "Comment (en) 1"] {
        h.key_press(egui::Key::Tab);
        h.run();
        assert!(
            h.get_by_role_and_label(Role::TextInput, cell).is_focused(),
            "{cell} has the keyboard"
        );
        let r = cell_rect(&h, cell);
        assert!(r.right() <= width && r.left() >= 0.0, "{cell} at {r:?}");
    }
    h.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::A);
    h.get_by_role_and_label(Role::TextInput, "Comment (en) 1")
        .type_text("Tool post stations");
    h.run();
    h.key_press(egui::Key::Enter);
    h.run();
    let now = &project(&h).data.d[0].comments;
    assert_eq!(now["en"], "Tool post stations");
    assert_eq!(now["zh"], comments["zh"]);
}
