//! The editor's ladder editing driven headless through egui_kittest, by role and label: keys, mouse, clipboard, pen, subprograms.

use crate::common::*;
use ladder_studio::gui::editor::EditState;
use ladder_studio::gui::files::FileState;
use ladder_studio::gui::replace::Replace;

#[test]
fn the_self_holding_circuit_drawn_with_the_keyboard_exports_the_manual_il() {
    use egui::{Key, Modifiers};
    let dir = tempfile_dir();
    let path = dir.join("self-hold.ldp");
    ladder_engine::file::save(&ladder_engine::model::Project::default(), &path).unwrap();
    let mut h = harness(Some(path.clone()), Lang::En);
    h.run();
    let empty = h.state().doc().unwrap().project().ladder.clone();
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
    let drawn = h.state().doc().unwrap().project().ladder.clone();
    assert!(!h.state().doc().unwrap().is_dirty(), "saved");

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
    assert_eq!(h.state().doc().unwrap().project().ladder, empty);
    for _ in 0..20 {
        h.key_press_modifiers(Modifiers::COMMAND, Key::Y);
        h.run();
    }
    assert_eq!(h.state().doc().unwrap().project().ladder, drawn);
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
    let out: Vec<String> = h.state().output().iter().map(|l| l.text.clone()).collect();
    assert_eq!(out.last().unwrap(), "3 found", "{out:?}");
    let at = |h: &Harness<'static, LadderApp>| {
        let c = h.state().cursor();
        (c.network, c.row, c.col)
    };
    assert_eq!(at(&h), (0, 0, 10), "the cursor went to the first match");
    // Ctrl+F, Enter again: the next match ("find next").
    h.key_press_modifiers(Modifiers::COMMAND, Key::F);
    h.run();
    assert_eq!(
        h.state()
            .feature::<EditState>()
            .prompt
            .as_ref()
            .unwrap()
            .text,
        "y3.7"
    );
    h.key_press(Key::Enter);
    h.run();
    assert_eq!(at(&h), (0, 1, 0));
    h.get_by_label_contains("LEVEL2 N0002 1:1").click();
    h.run();
    assert_eq!(h.state().view(), View::Block(1));
    // Replace: the contacts may take X1.0; the coil would be refused (an X is an input).
    h.key_press_modifiers(Modifiers::COMMAND, Key::H);
    h.run();
    // The window opens with the last text searched for; the replacement is typed.
    let to = "Replace with (an operand)";
    h.get_by_role_and_label(egui::accesskit::Role::TextInput, to)
        .click();
    h.run();
    h.get_by_role_and_label(egui::accesskit::Role::TextInput, to)
        .type_text("X1.0");
    h.run();
    // The preview lists every place with the count, before anything changes.
    h.get_by_label("3 places: 2 to change, 1 skipped (the result is not valid there)");
    h.get_by_label_contains("LEVEL2 N0001 2:1   Y0003.7 → X0001.0");
    h.get_by_label_contains("LEVEL2 N0001 1:11   Y0003.7   (skipped");
    assert_eq!(h.state().doc().unwrap().history().undo_len(), 0);
    h.get_by_label("Replace all (2)").click();
    h.run();
    let project = h.state().doc().unwrap().project();
    let il = ladder_engine::il::print(&ladder_engine::compiler::compile(project).program);
    assert!(
        il.contains("OR   X0001.0") && il.contains("OUT  Y0003.7") && il.contains("LD   X0001.0"),
        "{il}"
    );
    assert_eq!(
        h.state().doc().unwrap().history().undo_len(),
        1,
        "the whole replace is one undo step"
    );
    h.key_press(Key::Escape);
    h.run();
    assert!(
        h.state().feature::<Replace>().dialog.is_none(),
        "Escape closes the replace window"
    );
    h.key_press_modifiers(Modifiers::COMMAND, Key::Z);
    h.run();
    let project = h.state().doc().unwrap().project();
    let il = ladder_engine::il::print(&ladder_engine::compiler::compile(project).program);
    assert!(
        !il.contains("X0001.0"),
        "one Ctrl+Z undoes every place: {il}"
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
    on_level2(&mut h);
    h.key_press_modifiers(Modifiers::COMMAND, Key::G);
    enter_operand(&mut h, "30 2");
    let c = h.state().cursor();
    assert_eq!((c.block, c.network, c.row, c.col), (1, 29, 1, 0));
    assert!(h.state().feature::<EditState>().prompt.is_none());
    h.key_press_modifiers(Modifiers::COMMAND, Key::G);
    enter_operand(&mut h, "9999");
    let prompt = h
        .state()
        .feature::<EditState>()
        .prompt
        .clone()
        .expect("the prompt stays open");
    assert!(
        prompt.error.unwrap().starts_with("No such network: 1–"),
        "an error names the range"
    );
    h.key_press(Key::Escape);
    h.run();
    assert!(h.state().feature::<EditState>().prompt.is_none());
}

#[test]
fn a_network_selected_by_its_title_is_copied_pasted_and_undone_in_one_step() {
    use egui::{Key, Modifiers};
    let (mut h, _) = editor_on(TWO_NETWORKS, "clip.ldp");
    // Just above the first row: the network's header.
    let header = h
        .state()
        .feature::<EditState>()
        .geometry
        .cell_rect(0, 0, 3)
        .unwrap()
        .center_top()
        - egui::vec2(0.0, 8.0);
    pointer(&mut h, header, egui::PointerButton::Primary);
    assert!(
        matches!(
            h.state().selection(),
            Some((
                1,
                ladder_studio::gui::editor::selection::Selection::Networks { networks: (0, 0) }
            ))
        ),
        "{:?}",
        h.state().selection()
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
    let ids: Vec<u64> = h.state().doc().unwrap().project().ladder.blocks[1]
        .networks
        .iter()
        .map(|n| n.id.0)
        .collect();
    assert!(ids[0] != ids[1], "the copy is a new network: {ids:?}");
    h.key_press_modifiers(Modifiers::COMMAND, Key::Z);
    h.run();
    assert_eq!(il_now(&h).len(), 9, "one undo takes the paste back");
    // Cut the second network: it goes, and comes back with Ctrl+V below the first.
    let header2 = h
        .state()
        .feature::<EditState>()
        .geometry
        .cell_rect(1, 0, 3)
        .unwrap()
        .center_top()
        - egui::vec2(0.0, 8.0);
    pointer(&mut h, header2, egui::PointerButton::Primary);
    h.key_press_modifiers(Modifiers::COMMAND, Key::X);
    h.run();
    assert_eq!(
        h.state().doc().unwrap().project().ladder.blocks[1]
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
        h.state().selection(),
        Some((
            1,
            ladder_studio::gui::editor::selection::Selection::Cells {
                network: 0,
                rows: (0, 0),
                cols: (0, 1)
            }
        ))
    ));
    h.key_press_modifiers(Modifiers::COMMAND, Key::X);
    h.run();
    let row0 = |h: &Harness<'static, LadderApp>| {
        h.state().doc().unwrap().project().ladder.blocks[1].networks[0].rows[0]
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
    let rows = h.state().doc().unwrap().project().ladder.blocks[1].networks[0]
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
    assert!(h.state().feature::<EditState>().pen);
    // A contact in the second row, first column, then a wire and a link to join it.
    let c = cell_pos(&h, 0, 1, 0);
    pointer(&mut h, c, egui::PointerButton::Primary);
    h.key_press(egui::Key::F1);
    enter_operand(&mut h, "X2.2");
    let (a, z) = (cell_pos(&h, 0, 1, 1), cell_pos(&h, 0, 1, 3));
    drag(&mut h, a, z);
    let net = h.state().doc().unwrap().project().ladder.blocks[1].networks[0].clone();
    for col in 1..=3 {
        assert_eq!(
            net.rows[1].cells[col],
            ladder_engine::model::Cell::Wire,
            "col {col}"
        );
    }
    let (a, z) = (cell_pos(&h, 0, 0, 4), cell_pos(&h, 0, 1, 4));
    drag(&mut h, a, z);
    let net = h.state().doc().unwrap().project().ladder.blocks[1].networks[0].clone();
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
        h.state().cursor().network,
        1,
        "the right click moved the cursor"
    );
    h.get_by_label_contains("Insert network above").click();
    h.run();
    assert_eq!(
        h.state().doc().unwrap().project().ladder.blocks[1]
            .networks
            .len(),
        3
    );
    assert!(
        h.state().doc().unwrap().project().ladder.blocks[1].networks[1].is_empty(),
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
        h.state().doc().unwrap().project().ladder.blocks[1]
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
    let prompt = h
        .state()
        .feature::<EditState>()
        .prompt
        .clone()
        .expect("the operand prompt opened");
    assert_eq!(prompt.text, "X0002.1", "with the contact's address");
    h.state_mut()
        .with(|f: &mut EditState, _| f.prompt.as_mut().unwrap().text.clear());
    enter_operand(&mut h, "X2.3");
    assert_eq!(il_now(&h)[3], "LD X0002.3");
    assert_eq!(
        h.state().doc().unwrap().project().ladder.blocks[1].networks[0].rows[0].cells[1],
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
    let blocks = h.state().doc().unwrap().project().ladder.blocks.len();
    assert_eq!(blocks, 4, "P0005 joins P0007");
    assert_eq!(
        h.state().view(),
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
    let out: Vec<String> = h.state().output().iter().map(|l| l.text.clone()).collect();
    assert!(
        h.state()
            .feature::<EditState>()
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
    assert_eq!(h.state().output().last().unwrap().text, "P0007: 2 calls");
    h.get_by_label_contains("LEVEL2 N0002 1:  CALLU P0007");
    h.get_by_label_contains("LEVEL2 N0001 1:  CALL P0007");
    // Rename.
    h.state_mut()
        .ask(ladder_studio::gui::command::Command::RenameSub(5));
    h.run();
    assert_eq!(
        h.state()
            .feature::<EditState>()
            .prompt
            .as_ref()
            .unwrap()
            .text,
        "5 SPINDLE",
        "the prompt shows the current number and name"
    );
    h.state_mut()
        .with(|f: &mut EditState, _| f.prompt.as_mut().unwrap().text = "5 SPINDLE_MAIN".into());
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
    on_level2(&mut h);
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
    assert_eq!(
        h.state()
            .feature::<EditState>()
            .prompt
            .as_ref()
            .unwrap()
            .text,
        "TOOL_T1"
    );
    h.key_press(egui::Key::Enter);
    h.run();
    let c = h.state().cursor();
    let cell = h.state().doc().unwrap().project().ladder.blocks[1].networks[c.network].rows[0]
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
    assert_eq!(h.state().view(), View::Block(2));
    // The rename prompt is open on P0077 when its creation is undone.
    h.state_mut()
        .ask(ladder_studio::gui::command::Command::RenameSub(77));
    h.run();
    h.state_mut().undo();
    h.run();
    assert_eq!(
        h.state().view(),
        View::Block(1),
        "the view left the vanished block"
    );
    h.key_press(Key::Enter);
    h.run();
    let err = h
        .state()
        .feature::<EditState>()
        .prompt
        .as_ref()
        .and_then(|p| p.error.clone());
    assert!(err.is_some_and(|e| e.contains("no longer exists")));
    h.key_press(Key::Escape);
    h.run();
    let before = h.state().doc().unwrap().history().undo_len();
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
        h.state().doc().unwrap().project().ladder.blocks[0]
            .networks
            .len()
    };
    h.key_press(Key::Delete);
    h.run();
    h.key_press(Key::F1);
    enter_operand(&mut h, "X99999.9");
    assert!(
        h.state()
            .feature::<EditState>()
            .prompt
            .as_ref()
            .unwrap()
            .error
            .is_some()
    );
    h.key_press(Key::Escape);
    h.run();
    h.key_press(Key::F3);
    h.run();
    h.key_press(Key::Escape);
    h.run();
    assert_eq!(l1(&h), 0, "no network was added for nothing");
    // A contact in the empty block is one undo step, network included.
    let steps = h.state().doc().unwrap().history().undo_len();
    h.key_press(Key::F1);
    enter_operand(&mut h, "X2.1");
    assert_eq!(l1(&h), 1);
    assert_eq!(h.state().doc().unwrap().history().undo_len(), steps + 1);
    h.key_press_modifiers(Modifiers::COMMAND, Key::Z);
    h.run();
    assert_eq!(l1(&h), 0, "one undo takes back the contact and its network");
    assert!(h.state().doc().unwrap().history().undo_len() >= before);
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
    let cells = h.state().doc().unwrap().project().ladder.blocks[1].networks[0].rows[0]
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
    assert_eq!(h.state().doc().unwrap().history().undo_len(), 1);
    // On a new project's empty level 2 the button deletes nothing and adds no network.
    h.state_mut()
        .with(|o: &mut FileState, cx| o.perform(cx, ladder_studio::gui::files::CloseAction::New));
    h.run();
    h.get_by_label("Delete").click();
    h.run();
    let doc = h.state().doc().unwrap();
    assert!(doc.project().ladder.blocks[1].networks.is_empty());
    assert_eq!(doc.history().undo_len(), 0);
    assert!(!doc.is_dirty());
}
