//! The table editors driven as a user drives them: clicks, typed text, Enter, Ctrl+Z.

use super::*;
use crate::gui::i18n::Lang;
use egui::accesskit::Role;
use egui_kittest::Harness;
use egui_kittest::kittest::{NodeT, Queryable};
use ladder_engine::model::{Comments, DataRow, Message, Symbol, SymbolTable};
use ladder_engine::{Address, Area};

/// The editor on a saved copy of `project`, in English, showing `view`.
fn harness(project: &Project, _name: &str, view: View) -> Harness<'static, LadderApp> {
    let mut h = crate::gui::test_harness::on_project(project, Lang::En);
    h.state_mut().view = view;
    h.run();
    h
}

fn project<'a>(h: &'a Harness<'static, LadderApp>) -> &'a Project {
    h.state().doc.as_ref().unwrap().project()
}

/// Clicks a cell, replaces its text and presses Enter, as a user does.
fn enter(h: &mut Harness<'static, LadderApp>, cell: &str, text: &str) {
    enter_as(h, Role::TextInput, cell, text);
}

fn enter_as(h: &mut Harness<'static, LadderApp>, role: Role, cell: &str, text: &str) {
    h.get_by_role_and_label(role, cell).click();
    h.run();
    h.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::A);
    h.get_by_role_and_label(role, cell).type_text(text);
    h.run();
    h.key_press(egui::Key::Enter);
    h.run();
}

fn cell_value(h: &Harness<'static, LadderApp>, cell: &str) -> String {
    h.get_by_role_and_label(Role::TextInput, cell)
        .value()
        .unwrap_or_default()
}

fn undo_all(h: &mut Harness<'static, LadderApp>) {
    while h.state().doc.as_ref().unwrap().history().undo_len() > 0 {
        h.state_mut().undo();
    }
    h.run();
}

fn symbols(rows: &[(&str, &str)]) -> Project {
    let mut p = Project::default();
    p.symbol_tables[0].rows = rows
        .iter()
        .map(|(a, n)| Symbol {
            name: (*n).into(),
            address: Address::parse(a).unwrap(),
            comments: Comments::new(),
        })
        .collect();
    p
}

#[test]
fn symbols_are_entered_checked_and_undone() {
    let original = Project::default();
    let mut h = harness(&original, "symbols", View::Symbols(0));
    enter(&mut h, "Address 1", "r10.1");
    enter(&mut h, "Symbol 1", "START");
    enter(&mut h, "Comment (en) 1", "cycle start");
    let row = &project(&h).symbol_tables[0].rows[0];
    assert_eq!(row.address, Address::bit(Area::R, 10, 1));
    assert_eq!(row.name, "START");
    assert_eq!(
        row.comments.get("en").map(String::as_str),
        Some("cycle start")
    );
    assert_eq!(cell_value(&h, "Address 1"), "R0010.1", "shown canonical");
    assert_eq!(
        cell_value(&h, "Comment (zh) 1"),
        "",
        "no Chinese comment yet"
    );
    enter(&mut h, "Comment (zh) 1", "循环启动");
    let comments = &project(&h).symbol_tables[0].rows[0].comments;
    assert_eq!(
        (comments["zh"].as_str(), comments["en"].as_str()),
        ("循环启动", "cycle start"),
        "each column its own language"
    );

    let before = project(&h).symbol_tables.clone();
    for (text, reason) in [
        ("Z99", "has no such address area"),
        ("R1000", "R1000 is out of range (R0–R999)"),
        ("L1", "only these areas belong here"),
        ("R10.1", "address already listed: 符号表1 #1"),
    ] {
        enter(&mut h, "Address 2", text);
        h.get_by_label_contains(reason);
        assert_eq!(project(&h).symbol_tables, before, "{text} is refused");
        assert_eq!(cell_value(&h, "Address 2"), text, "and stays to be fixed");
    }
    enter(&mut h, "Address 2", "R10.2");
    assert!(
        h.query_by_label_contains("address already listed")
            .is_none(),
        "a valid entry clears the message"
    );
    let before = project(&h).symbol_tables.clone();
    for (text, reason) in [
        ("START", "symbol already exists: 符号表1 #1"),
        ("1ABC", "A symbol is letters"),
        ("X1", "A symbol is letters"),
    ] {
        enter(&mut h, "Symbol 2", text);
        h.get_by_label_contains(reason);
        assert_eq!(project(&h).symbol_tables, before, "{text} is refused");
    }
    h.key_press(egui::Key::Escape);
    h.run();

    // Ctrl+Z (no field has the keyboard after Enter) takes back the last row.
    h.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::Z);
    h.run();
    assert_eq!(project(&h).symbol_tables[0].rows.len(), 1);
    undo_all(&mut h);
    assert_eq!(project(&h).symbol_tables, original.symbol_tables);
}

#[test]
fn the_row_menu_inserts_clears_and_deletes() {
    let original = symbols(&[("R0.0", "A"), ("R0.1", "B"), ("R0.2", "C")]);
    let mut h = harness(&original, "rows", View::Symbols(0));
    let rows = |h: &Harness<'static, LadderApp>| project(h).symbol_tables[0].rows.clone();

    h.get_by_label("2").click();
    h.run();
    h.get_by_label("Insert row above").click();
    h.run();
    let r = rows(&h);
    assert_eq!(r.len(), 4);
    assert_eq!(
        (r[1].address.to_string(), r[1].name.as_str()),
        ("R0000.3".to_string(), ""),
        "a new row at the next free address"
    );
    assert_eq!(h.state().tables.selected[&Sheet::Symbols(0)], 1);
    h.get_by_label("Delete row").click();
    h.run();
    assert_eq!(rows(&h), original.symbol_tables[0].rows);

    h.get_by_label("3").click_secondary();
    h.run();
    let menu = h.get_all_by_label("Clear row").last().unwrap();
    menu.click();
    h.run();
    let r = rows(&h);
    assert_eq!(r[2].name, "", "cleared");
    assert_eq!(
        r[2].address,
        Address::bit(Area::R, 0, 2),
        "its address kept"
    );

    h.get_by_label("1").click();
    h.run();
    h.get_by_label("Insert row below").click();
    h.run();
    assert_eq!(rows(&h)[1].address, Address::bit(Area::R, 0, 3));

    h.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::Z);
    h.run();
    h.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::Z);
    h.run();
    h.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::Z);
    h.run();
    h.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::Z);
    h.run();
    assert_eq!(project(&h).symbol_tables, original.symbol_tables);
}

#[test]
fn a_k_bit_toggles_exactly_that_bit() {
    let original = Project::default();
    let mut h = harness(&original, "kpage", View::Data);
    h.get_by_label("K0003.5").click();
    h.run();
    assert_eq!(project(&h).data.k, vec![0, 0, 0, 0x20]);
    h.get_by_label("K0003.0").click();
    h.run();
    assert_eq!(project(&h).data.k, vec![0, 0, 0, 0x21]);
    h.get_by_label("21");
    h.get_by_label("K0003.5").click();
    h.run();
    assert_eq!(project(&h).data.k, vec![0, 0, 0, 0x01]);
    h.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::Z);
    h.run();
    assert_eq!(project(&h).data.k, vec![0, 0, 0, 0x21]);
    undo_all(&mut h);
    assert_eq!(
        project(&h).data,
        original.data,
        "the page as it was, length too"
    );
}

#[test]
fn data_values_are_clamped_where_the_user_sees_them() {
    let mut original = Project::default();
    let mut row = DataRow::new(Address::byte(Area::D, 10), 50);
    row.set_max(Some(100));
    original.data.d.push(row);
    let mut h = harness(&original, "data", View::Data);
    h.get_by_label("D").click();
    h.run();
    enter(&mut h, "Initial value 1", "500");
    assert_eq!(project(&h).data.d[0].value, 100);
    assert_eq!(
        cell_value(&h, "Initial value 1"),
        "100",
        "the clamp shows at once"
    );
    enter(&mut h, "Min 1", "200");
    assert_eq!(project(&h).data.d[0].min, Some(100), "a min above the max");
    enter(&mut h, "Initial value 1", "ten");
    h.get_by_label_contains("Enter a whole number");
    assert_eq!(project(&h).data.d[0].value, 100);
    h.key_press(egui::Key::Escape);
    h.run();

    let before = project(&h).data.clone();
    enter(&mut h, "Address 1", "DT5");
    h.get_by_label_contains("only these areas belong here: D");
    enter(&mut h, "Address 1", "D1000");
    h.get_by_label_contains("D1000 is out of range (D0–D999)");
    assert_eq!(project(&h).data, before);
    enter(&mut h, "Address 1", "d11");
    enter(&mut h, "Address 2", "d12");
    assert_eq!(
        project(&h)
            .data
            .d
            .iter()
            .map(|r| r.address.to_string())
            .collect::<Vec<_>>(),
        ["D0011", "D0012"]
    );

    h.get_by_label("D_FLOAT").click();
    h.run();
    enter(&mut h, "Address 1", "D11");
    h.get_by_label_contains("address already listed: D #1");
    assert!(project(&h).data.d_float.is_empty());
    enter(&mut h, "Address 1", "D20");
    enter(&mut h, "Max 1", "2.5");
    enter(&mut h, "Initial value 1", "7.25");
    assert_eq!(project(&h).data.d_float[0].value, 2.5);

    h.get_by_label("DT").click();
    h.run();
    enter(&mut h, "Address 1", "D5");
    h.get_by_label_contains("only these areas belong here: DT");
    assert!(project(&h).data.dt.is_empty());

    undo_all(&mut h);
    assert_eq!(project(&h).data, original.data);
}

#[test]
fn the_message_table_has_a_row_per_a_bit_and_scrolls() {
    let original = Project::default();
    let mut h = harness(&original, "messages", View::Messages);
    h.get_by_label("A0000.0");
    assert!(
        h.query_by_label("A0049.7").is_none(),
        "only visible rows are laid out"
    );
    assert!(
        h.get_by_label("Insert row above")
            .accesskit_node()
            .is_disabled()
    );
    assert!(h.get_by_label("Delete row").accesskit_node().is_disabled());
    let at = h.get_by_label("A0000.0").rect().center();
    h.hover_at(at);
    h.event(egui::Event::MouseWheel {
        unit: egui::MouseWheelUnit::Point,
        delta: egui::vec2(0.0, -100_000.0),
        phase: egui::TouchPhase::Move,
        source: egui::MouseWheelSource::Wheel,
        modifiers: egui::Modifiers::NONE,
    });
    // The wheel scrolls smoothly over a few frames.
    h.run_steps(20);
    h.get_by_label("A0049.7");
    assert!(h.query_by_label("Alarm number 401").is_none(), "400 rows");
    enter(&mut h, "Alarm number 400", "1234");
    enter(&mut h, "Message text (en) 400", "Oil level low");
    let m = &project(&h).messages.rows[399];
    assert_eq!(m.number, Some(1234));
    assert_eq!(m.texts.get("en").map(String::as_str), Some("Oil level low"));
    enter(&mut h, "Alarm number 399", "1234");
    h.get_by_label_contains("1234: alarm number already used by A0049.7");
    enter(&mut h, "Alarm number 399", "999");
    h.get_by_label_contains("Alarm numbers are 1000–9999");
    assert_eq!(project(&h).messages.rows[398], Message::default());

    h.get_by_label("400").click_secondary();
    h.run();
    h.get_all_by_label("Clear row").last().unwrap().click();
    h.run();
    assert_eq!(project(&h).messages, original.messages);
    h.state_mut().undo();
    assert_eq!(project(&h).messages.rows[399].number, Some(1234));
}

#[test]
fn diagnosis_permissions_and_m_codes_are_edited_and_checked() {
    let original = Project::default();
    let mut h = harness(&original, "misc", View::MCodes);
    enter(&mut h, "M code 1", "m3");
    enter(&mut h, "Comment (en) 1", "spindle CW");
    assert_eq!(project(&h).m_codes[0].code, 3);
    assert_eq!(cell_value(&h, "M code 1"), "M03");
    enter(&mut h, "M code 2", "M03");
    h.get_by_label_contains("M03: This M code is already listed");
    enter(&mut h, "M code 2", "10000");
    h.get_by_label_contains("M codes are 0–9999");
    assert_eq!(project(&h).m_codes.len(), 1);
    h.key_press(egui::Key::Escape);
    h.run();

    h.state_mut().view = View::Diagnosis;
    h.run();
    enter(&mut h, "Address 1", "k2.1");
    enter(&mut h, "Address 2", "K2.1");
    h.get_by_label_contains("K0002.1: address already listed: #1");
    enter(&mut h, "Address 2", "P1");
    h.get_by_label_contains("only these areas belong here");
    assert_eq!(project(&h).diagnosis.len(), 1);
    let long = "x".repeat(128);
    enter(&mut h, "Comment (en) 1", &long);
    h.get_by_label_contains("at most 127 bytes");
    assert!(project(&h).diagnosis[0].comments.is_empty());

    h.state_mut().view = View::Permissions;
    h.run();
    h.get_by_label("Insert row below").click();
    h.run();
    assert_eq!(
        project(&h).permissions[0].address,
        Address::byte(Area::K, 0)
    );
    undo_all(&mut h);
    assert_eq!(*project(&h), original);
}

#[test]
fn version_fields_show_their_limits_and_the_password_is_hashed() {
    let original = Project::default();
    let mut h = harness(&original, "version", View::Version);
    enter(&mut h, "Designer", "Li Wei");
    h.get_by_label("6/63");
    enter(&mut h, "Version", &"9".repeat(30));
    assert_eq!(project(&h).version.designer, "Li Wei");
    assert_eq!(project(&h).version.version, "9".repeat(19), "cut at 19");
    h.get_by_label("19/19");

    enter_as(&mut h, Role::PasswordInput, "New password", "s3cret");
    enter_as(&mut h, Role::PasswordInput, "Confirm password", "s3crat");
    h.get_by_label("Set password").click();
    h.run();
    h.get_by_label("The two passwords differ");
    assert_eq!(project(&h).version.password, None);
    enter_as(&mut h, Role::PasswordInput, "Confirm password", "s3cret");
    h.get_by_label("Set password").click();
    h.run();
    let hash = project(&h).version.password.clone().expect("a password");
    assert!(hash.matches("s3cret") && !hash.hash.contains("s3cret"));
    assert!(
        h.state().tables.password.new.is_empty(),
        "the clear text is gone"
    );
    h.get_by_label("A password is set");

    h.get_by_label("Clear password").click();
    h.run();
    h.get_by_label("The current password is wrong");
    enter_as(&mut h, Role::PasswordInput, "Current password", "s3cret");
    h.get_by_label("Clear password").click();
    h.run();
    assert_eq!(project(&h).version.password, None);
    h.state_mut().undo();
    assert_eq!(project(&h).version.password, Some(hash));
    undo_all(&mut h);
    assert_eq!(project(&h).version, original.version);
}

#[test]
fn a_big_symbol_table_lays_out_only_what_is_visible() {
    let p = Project {
        symbol_tables: vec![SymbolTable {
            name: "big".into(),
            rows: (0..8000u32)
                .map(|i| Symbol {
                    name: format!("S{i}"),
                    address: Address::bit(Area::R, (i / 8) as u16, (i % 8) as u8),
                    comments: Comments::new(),
                })
                .collect(),
        }],
        ..Project::default()
    };
    let mut h = harness(&p, "big", View::Symbols(0));
    h.get_by_role_and_label(Role::TextInput, "Symbol 1");
    assert!(
        h.query_by_role_and_label(Role::TextInput, "Symbol 200")
            .is_none()
    );
    enter(&mut h, "Symbol 1", "S7999");
    h.get_by_label_contains("symbol already exists: big #8000");
}

// The free keys and the D_FLOAT limits are the engine's (engine/tests/tables.rs); the salt
// comes from the editor, which has a source of randomness.
#[test]
fn a_salt_is_new_every_time() {
    assert_ne!(version::new_salt(), version::new_salt());
}

/// Ctrl+Z as the editor will have it: the latest refused draft goes first, then the edits.
fn undo_draft_first(h: &mut Harness<'static, LadderApp>) {
    if !h.state_mut().tables.undo_draft() {
        h.state_mut().undo();
    }
    h.run();
}

#[test]
fn an_undo_takes_back_a_refused_draft_before_an_edit_of_another_table() {
    let original = symbols(&[("R0.0", "START")]);
    let mut h = harness(&original, "drafts", View::Symbols(0));
    enter(&mut h, "Symbol 1", "RUN");
    assert_eq!(project(&h).symbol_tables[0].rows[0].name, "RUN");

    h.state_mut().view = View::Messages;
    h.run();
    enter(&mut h, "Alarm number 1", "999");
    enter(&mut h, "Alarm number 2", "1000");
    enter(&mut h, "Alarm number 3", "1000");
    h.get_by_label_contains("Alarm numbers are 1000–9999");
    h.get_by_label_contains("1000: alarm number already used by A0000.1");

    // The latest draft goes first, then the one before; the rename stays meanwhile.
    undo_draft_first(&mut h);
    assert!(h.query_by_label_contains("already used by").is_none());
    assert_eq!(cell_value(&h, "Alarm number 3"), "", "the saved cell again");
    h.get_by_label_contains("Alarm numbers are 1000–9999");
    undo_draft_first(&mut h);
    assert!(h.query_by_label_contains("Alarm numbers are").is_none());
    assert_eq!(project(&h).symbol_tables[0].rows[0].name, "RUN");
    assert_eq!(project(&h).messages.rows[1].number, Some(1000));

    // No draft left: the edits come back in order.
    assert!(!h.state_mut().tables.undo_draft());
    undo_draft_first(&mut h);
    assert_eq!(project(&h).messages, original.messages);
    assert_eq!(project(&h).symbol_tables[0].rows[0].name, "RUN");
    undo_draft_first(&mut h);
    assert_eq!(*project(&h), original);
}

#[test]
fn a_draft_being_typed_is_a_draft_too() {
    let mut h = harness(&Project::default(), "typing", View::Version);
    h.get_by_role_and_label(Role::TextInput, "Designer").click();
    h.run();
    h.get_by_role_and_label(Role::TextInput, "Designer")
        .type_text("Li");
    h.run();
    assert!(h.state_mut().tables.undo_draft());
    assert!(!h.state_mut().tables.undo_draft());
    h.key_press(egui::Key::Enter);
    h.run();
    assert_eq!(project(&h).version.designer, "", "nothing left to commit");
}

#[test]
fn an_undone_table_edit_is_shown_at_its_row() {
    let p = Project {
        symbol_tables: vec![
            SymbolTable {
                name: "small".into(),
                rows: Vec::new(),
            },
            SymbolTable {
                name: "big".into(),
                rows: (0..2000u32)
                    .map(|i| Symbol {
                        name: format!("S{i}"),
                        address: Address::bit(Area::R, (i / 8) as u16, (i % 8) as u8),
                        comments: Comments::new(),
                    })
                    .collect(),
            },
        ],
        ..Project::default()
    };
    let mut h = harness(&p, "show", View::Symbols(0));
    // The other side of a rename of row 1900 of the second table, as an undo gives it.
    let mut renamed = p.symbol_tables.clone();
    renamed[1].rows[1899].name = "LAST".into();
    let edit = TableEdit::Symbols(renamed);
    assert_eq!(TableState::view_of(&p, &edit), Some(View::Symbols(1)));
    let view = h.state_mut().tables.show_change(&p, &edit);
    h.state_mut().view = view.expect("a symbol table is a view");
    h.run();
    assert_eq!(h.state().tables.selected[&Sheet::Symbols(1)], 1899);
    assert_eq!(cell_value(&h, "Symbol 1900"), "S1899", "scrolled to it");

    // A data table's edit turns the data view to its tab; the K page's to the K page.
    let mut data = p.data.clone();
    data.dt.push(DataRow::new(Address::byte(Area::Dt, 4), 100));
    let edit = TableEdit::Data(Box::new(data));
    assert_eq!(
        h.state_mut().tables.show_change(&p, &edit),
        Some(View::Data)
    );
    assert_eq!(h.state().tables.data_tab, DataTab::Dt);
    let mut k = p.data.clone();
    k.set_k_bit(1, 1, true);
    h.state_mut()
        .tables
        .show_change(&p, &TableEdit::Data(Box::new(k)));
    assert_eq!(h.state().tables.data_tab, DataTab::K);
}

#[test]
fn the_widget_returns_edits_and_leaves_the_document_alone() {
    use crate::gui::document::Document;
    type Shown = (Document, TableState, Vec<TableEvent>);
    // An ASCII name: this harness has egui's own fonts only, without Chinese.
    let mut project = Project::default();
    project.symbol_tables[0].name = "IO".into();
    let doc = Document::new(project.clone(), None);
    let mut h = Harness::builder()
        .with_size(egui::vec2(1000.0, 600.0))
        .build_ui_state(
            |ui, (doc, state, events): &mut Shown| {
                events.extend(tables_ui(ui, doc, View::Symbols(0), state, Lang::En));
            },
            (doc, TableState::default(), Vec::new()),
        );
    h.run();
    h.get_by_role_and_label(Role::TextInput, "Address 1")
        .click();
    h.run();
    h.get_by_role_and_label(Role::TextInput, "Address 1")
        .type_text("x1.0");
    h.run();
    h.key_press(egui::Key::Enter);
    h.run();
    let (doc, _, events) = h.state();
    assert_eq!(*doc.project(), project, "the caller applies edits");
    let [TableEvent::Apply(TableEdit::Symbols(tables))] = &events[..] else {
        panic!("one symbol-table edit: {events:?}");
    };
    assert_eq!(tables[0].rows[0].address, Address::bit(Area::X, 1, 0));
}
