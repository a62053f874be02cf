//! The function-instruction dialog driven headless.

use super::*;
use crate::gui::LadderApp;
use crate::gui::i18n::Lang;
use egui::Modifiers;
use egui::accesskit::Role;
use egui_kittest::Harness;
use egui_kittest::kittest::Queryable;
use ladder_engine::model::Ladder;

type H = Harness<'static, LadderApp>;

/// The app on `project`, saved first into a fresh temporary folder.
fn harness(project: &Project, _name: &str, lang: Lang) -> H {
    crate::gui::test_harness::on_project(project, lang)
}

/// An empty project with one network holding the contact X2.1; the cursor after it.
fn with_contact(name: &str) -> H {
    let mut h = harness(&Project::default(), name, Lang::En);
    h.key_press_modifiers(Modifiers::COMMAND, Key::I);
    h.run();
    h.key_press(Key::F1);
    h.run();
    h.get_by_role_and_label(Role::TextInput, "Operand")
        .type_text("X2.1");
    h.run();
    h.key_press(Key::Enter);
    h.run();
    h
}

/// Replaces the text of the field labelled `label`.
fn fill(h: &mut H, label: &str, text: &str) {
    h.get_by_role_and_label(Role::TextInput, label).click();
    h.run();
    h.key_press_modifiers(Modifiers::COMMAND, Key::A);
    h.run();
    h.get_by_role_and_label(Role::TextInput, label)
        .type_text(text);
    h.run();
}

fn ladder(h: &H) -> Ladder {
    h.state().doc.as_ref().unwrap().project().ladder.clone()
}

/// The compiled instructions, without directives, spaces folded.
fn il(h: &H) -> Vec<String> {
    let project = h.state().doc.as_ref().unwrap().project();
    let text = ladder_engine::il::print(&ladder_engine::compiler::compile(project).program);
    text.lines()
        .filter(|l| !matches!(*l, "LEVEL1" | "LEVEL2" | "NETWORK" | "END"))
        .map(|l| l.split_whitespace().collect::<Vec<_>>().join(" "))
        .collect()
}

fn shown(h: &H, role: Role, label: &str) -> bool {
    h.query_all_by_role_and_label(role, label).next().is_some()
}

fn shown_containing(h: &H, text: &str) -> bool {
    h.query_all_by_label_contains(text).next().is_some()
}

#[test]
fn f3_search_pick_fill_and_ok_places_the_tmrb_box() {
    let mut h = with_contact("tmrb");
    h.key_press(Key::F3);
    h.run();
    h.get_by_label("Function instruction");
    fill(&mut h, "Search", "tmr");
    assert!(shown(&h, Role::Button, "TMRB") && shown(&h, Role::Button, "TMRC"));
    assert!(!shown(&h, Role::Button, "ADDB"), "the search filters");
    h.get_by_role_and_label(Role::Button, "TMRB").click();
    h.run();
    assert!(shown_containing(&h, "On-delay timer"), "the help is shown");
    assert!(shown_containing(&h, "Timer number"), "and each operand's");
    fill(&mut h, "T", "T0");
    fill(&mut h, "PT", "dt4");
    fill(&mut h, "OUT", "R300.0");
    h.get_by_label("TMRB T0000 DT0004 R0300.0");
    h.key_press(Key::Enter);
    h.run();
    assert!(
        h.state().edit.function_dialog.is_none(),
        "OK closes the dialog"
    );
    assert_eq!(il(&h), ["LD X0002.1", "TMRB T0000 DT0004 R0300.0"]);
    let width = ladder(&h).width;
    assert_eq!(
        h.state().cursor.col,
        width,
        "the box is in the output column"
    );
}

#[test]
fn an_operand_in_a_wrong_area_is_red_and_ok_does_nothing() {
    let mut h = with_contact("wrong-area");
    h.key_press(Key::F3);
    h.run();
    fill(&mut h, "Search", "tmrb");
    h.get_by_role_and_label(Role::Button, "TMRB").click();
    h.run();
    fill(&mut h, "T", "Y0");
    fill(&mut h, "PT", "DT4");
    fill(&mut h, "OUT", "R300.0");
    assert!(shown_containing(
        &h,
        "T: not allowed here: allowed areas: T; no constants"
    ));
    let dialog = h.state().edit.function_dialog.clone().unwrap();
    let project = h.state().doc.as_ref().unwrap().project();
    assert!(matches!(dialog.checks(project, Lang::En)[0], Check::Bad(_)));
    let before = ladder(&h);
    h.get_by_role_and_label(Role::Button, "OK").click();
    h.run();
    h.key_press(Key::Enter);
    h.run();
    assert!(
        h.state().edit.function_dialog.is_some(),
        "the dialog stays open"
    );
    assert_eq!(ladder(&h), before, "nothing was placed");
    fill(&mut h, "T", "T0");
    h.get_by_role_and_label(Role::Button, "OK").click();
    h.run();
    assert!(h.state().edit.function_dialog.is_none());
    assert_eq!(il(&h)[1], "TMRB T0000 DT0004 R0300.0");
}

#[test]
fn escape_cancels_without_a_change() {
    let mut h = with_contact("escape");
    let before = ladder(&h);
    h.key_press(Key::F3);
    h.run();
    h.get_by_role_and_label(Role::TextInput, "Instruction line")
        .type_text("SET R10.0");
    h.run();
    assert_eq!(
        h.state().edit.function_dialog.as_ref().unwrap().selected(),
        Some(Op::Set)
    );
    h.key_press(Key::Escape);
    h.run();
    assert!(h.state().edit.function_dialog.is_none());
    assert_eq!(ladder(&h), before);
    // Cancel does the same.
    h.key_press(Key::F3);
    h.run();
    h.get_by_role_and_label(Role::Button, "Cancel").click();
    h.run();
    assert!(h.state().edit.function_dialog.is_none());
    assert_eq!(ladder(&h), before);
}

#[test]
fn editing_a_box_changes_its_operand_and_one_undo_restores_it() {
    let project =
        ladder_engine::il::import("LEVEL2\nNETWORK\nLD X0002.1\nTMRB T0000 DT0004 R0300.0\n")
            .project
            .unwrap();
    let mut h = harness(&project, "edit", Lang::En);
    let before = ladder(&h);
    let row = &before.blocks[1].networks[0].rows[0];
    let col = row
        .cells
        .iter()
        .position(|c| matches!(c, Cell::Box { .. }))
        .expect("the imported box");
    let at = CellRef {
        block: 1,
        network: 0,
        row: 0,
        col,
    };
    h.state_mut()
        .with(|e: &mut crate::gui::editor::EditState, cx| e.edit_function_box(cx, at));
    h.run();
    h.get_by_label("Change function instruction");
    let t = h.get_by_role_and_label(Role::TextInput, "T").value();
    assert_eq!(
        t.as_deref(),
        Some("T0000"),
        "the box's operands are filled in"
    );
    fill(&mut h, "T", "T0001");
    h.get_by_role_and_label(Role::Button, "OK").click();
    h.run();
    assert!(h.state().edit.function_dialog.is_none());
    assert_eq!(il(&h), ["LD X0002.1", "TMRB T0001 DT0004 R0300.0"]);
    h.state_mut().undo();
    h.run();
    assert_eq!(ladder(&h), before, "one undo step restores the box");
}

#[test]
fn every_function_instruction_of_the_catalogue_is_listed_under_all() {
    let mut h = with_contact("all");
    h.key_press(Key::F3);
    h.run();
    h.get_by_role_and_label(Role::Button, "Timer/counter")
        .click();
    h.run();
    assert!(shown(&h, Role::Button, "TMRB") && !shown(&h, Role::Button, "ADDB"));
    h.get_by_role_and_label(Role::Button, "All").click();
    h.run();
    for s in CATALOG.iter().filter(|s| s.class == InstrClass::Function) {
        assert!(shown(&h, Role::Button, s.name), "{} is listed", s.name);
    }
    for s in CATALOG.iter().filter(|s| s.class != InstrClass::Function) {
        assert!(!shown(&h, Role::Button, s.name), "{} is not", s.name);
    }
    for c in categories() {
        assert!(shown(&h, Role::Button, c.name_en()), "{c:?}");
    }
    assert_eq!(
        categories().count(),
        Category::ALL.len() - 1,
        "all but Basic"
    );
}

#[test]
fn the_instruction_line_fills_the_choice_and_the_operands() {
    let mut h = with_contact("line");
    h.key_press(Key::F3);
    h.run();
    h.get_by_role_and_label(Role::TextInput, "Instruction line")
        .type_text("FOO R1");
    h.run();
    assert!(shown_containing(&h, "`FOO` is not a function instruction"));
    fill(&mut h, "Instruction line", "tmrb t0 dt4 r300.0");
    assert_eq!(
        h.state().edit.function_dialog.as_ref().unwrap().selected(),
        Some(Op::Tmrb)
    );
    let pt = h.get_by_role_and_label(Role::TextInput, "PT").value();
    assert_eq!(pt.as_deref(), Some("dt4"));
    h.key_press(Key::Enter);
    h.run();
    assert_eq!(il(&h), ["LD X0002.1", "TMRB T0000 DT0004 R0300.0"]);
}

#[test]
fn codb_table_entries_are_added_and_removed_with_size2() {
    let mut h = with_contact("codb");
    h.key_press(Key::F3);
    h.run();
    h.get_by_role_and_label(Role::TextInput, "Instruction line")
        .type_text("CODB 1 3 R10 R20 5 6 7");
    h.run();
    assert!(shown(&h, Role::TextInput, "TABLE 3"));
    h.get_by_role_and_label(Role::Button, "Add entry").click();
    h.run();
    let size2 = h.get_by_role_and_label(Role::TextInput, "SIZE2").value();
    assert_eq!(size2.as_deref(), Some("4"));
    assert!(
        shown_containing(&h, "TABLE 4: missing"),
        "a new entry must be filled"
    );
    fill(&mut h, "TABLE 4", "8");
    h.get_by_role_and_label(Role::Button, "Remove entry")
        .click();
    h.run();
    h.get_by_role_and_label(Role::Button, "Add entry").click();
    h.run();
    let entry = h.get_by_role_and_label(Role::TextInput, "TABLE 4").value();
    assert_eq!(entry.as_deref(), Some("8"), "a removed entry comes back");
    h.get_by_role_and_label(Role::Button, "OK").click();
    h.run();
    assert_eq!(il(&h), ["LD X0002.1", "CODB 1 4 R0010 R0020 5 6 7 8"]);
}

#[test]
fn the_dialog_speaks_the_ui_language() {
    let mut h = harness(&Project::default(), "zh", Lang::Zh);
    h.key_press(Key::F3);
    h.run();
    assert!(shown(&h, Role::Button, "所有功能指令"));
    assert!(shown(&h, Role::Button, "定时/计数"));
    h.get_by_role_and_label(Role::Button, "TMRB").click();
    h.run();
    assert!(shown_containing(&h, "定时器：ACT=1 计时"));
    assert!(shown_containing(&h, "T: 未填写"));
}

#[test]
fn refusals_say_what_is_allowed() {
    let project = Project::default();
    let at = CellRef {
        block: 1,
        network: 0,
        row: 0,
        col: 0,
    };
    let check = |line: &str| {
        let mut d = FunctionDialog::new(at);
        d.line = line.into();
        d.fill_from_line(Lang::En);
        d.checks(&project, Lang::En)
    };
    let bad = |c: &Check| match c {
        Check::Bad(why) => why.clone(),
        other => panic!("{other:?}"),
    };
    let c = check("TMRB Y0 DT4 R300.0");
    assert_eq!(
        bad(&c[0]),
        "not allowed here: allowed areas: T; no constants"
    );
    assert_eq!(&c[1..], [Check::Ok, Check::Ok]);
    assert!(bad(&check("TMRB T0 DT4 R300")[2]).starts_with("needs a bit address"));
    assert!(bad(&check("SET X0.0")[0]).starts_with("not allowed here"));
    assert!(bad(&check("MOVN 3 1 R10")[0]).ends_with("allowed constants: 1, 2, 4"));
    assert!(bad(&check("CTRC 0100 X0.0 C0 10 R0.0")[0]).contains("0000, 0001, 0010 or 0011"));
    assert!(bad(&check("TMRB T9999 DT4 R300.0")[0]).contains("out of range"));
    assert!(bad(&check("TMRB T0 D?x R300.0")[1]).contains("neither"));
    assert_eq!(
        check("TMRB T0 DT4 NOSUCH")[2],
        Check::Warn(Msg::FnUndefinedSymbol.text(Lang::En).into())
    );
    assert_eq!(check("TMRB T0 DT4")[2], Check::Empty);
}

#[test]
fn a_wrong_operand_is_explained_in_the_ui_language() {
    let project = Project::default();
    let mut d = FunctionDialog::new(CellRef {
        block: 1,
        network: 0,
        row: 0,
        col: 0,
    });
    d.line = "SET X0.9".into();
    d.fill_from_line(Lang::Zh);
    match &d.checks(&project, Lang::Zh)[0] {
        Check::Bad(why) => assert_eq!(why, "`X0.9`：位号应为 0–7"),
        other => panic!("{other:?}"),
    }
}
