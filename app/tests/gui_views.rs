//! The editor's views driven headless: the project tree, languages, compiling, the cross-reference, tabs, go to, and undo going to what it changes.

use crate::common::*;
use ladder_studio::gui::editor::EditState;
use ladder_studio::gui::tables::TableState;
use ladder_studio::gui::xref_view::XrefState;

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
    assert_eq!(
        h.state().view(),
        View::Block(0),
        "level 1 is shown first, as in the manual's editor"
    );
}

#[test]
fn the_language_switches_at_run_time() {
    let mut h = harness(None, Lang::Zh);
    h.run();
    h.get_by_label("查看").click();
    h.run();
    h.get_by_label("English (英文)").click();
    h.run();
    assert_eq!(h.state().settings().lang, Lang::En);
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
        .output()
        .last()
        .expect("a summary line")
        .text
        .clone();
    assert_eq!(last, "Compiled without errors (717 steps)");
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
    assert_eq!(h.state().view(), View::Block(0));
    h.key_press(egui::Key::F9);
    h.run();
    let diag = h.state().output()[0].clone();
    let at = diag.target.expect("the diagnostic has a cell");
    assert_eq!((at.block, at.network), (1, 1), "{}", diag.text);
    h.get_by_label_contains("undefined symbol `NOWHERE`")
        .click();
    h.run();
    assert_eq!(
        h.state().view(),
        View::Block(1),
        "the error's block is shown"
    );
    assert_eq!(h.state().cursor(), at, "the cursor is on the cell");
    assert_eq!(
        h.state().feature::<EditState>().jump_to,
        None,
        "and its network was scrolled to"
    );
}

#[test]
fn a_compile_error_reads_in_chinese_in_a_chinese_ui() {
    let dir = tempfile_dir();
    let path = dir.join("err.ldp");
    let project = ladder_engine::il::import(
        "LEVEL2\nNETWORK\nLD X0001.0\nOUT Y0001.0\nNETWORK\nLD X0001.1\nAND NOWHERE\nOUT Y0001.1\n",
    )
    .project
    .unwrap();
    ladder_engine::file::save(&project, &path).unwrap();
    let mut h = harness(Some(path), Lang::Zh);
    h.run();
    h.key_press(egui::Key::F9);
    h.run();
    let diag = h.state().output()[0].clone();
    assert!(
        diag.text
            .starts_with("err.ldp 二级程序 网络 2 行 1 列 2：错误：[L020] 符号 `NOWHERE` 未定义"),
        "{}",
        diag.text
    );
    assert!(
        diag.text.contains("`NOWHERE`"),
        "the specifics are kept: {}",
        diag.text
    );
    assert!(diag.target.is_some(), "it still jumps to its cell");
    h.get_by_label_contains("[L020] 符号 `NOWHERE` 未定义");
    assert!(
        !diag.text.contains("undefined"),
        "no English inside the Chinese: {}",
        diag.text
    );
}

#[test]
fn the_cross_reference_view_lists_addresses() {
    let mut h = harness(None, Lang::En);
    h.run();
    h.get_by_label("Cross-reference").click();
    h.run();
    h.get_by_label("Bit usage").click();
    h.run();
    assert_eq!(h.state().view(), View::RefBits);
    h.get_by_label_contains("BIT     7 6 5 4 3 2 1 0");
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
    assert_eq!(h.state().feature::<XrefState>().filter, "y3.6");
    assert!(
        h.query_by_label_contains("Y0003.7").is_none(),
        "the filter leaves only Y3.6"
    );
    let place = h.get_by_label("N0002 1:11").rect().center();
    double_click(&mut h, place);
    assert_eq!(h.state().view(), View::Block(1));
    let c = h.state().cursor();
    assert_eq!((c.block, c.network, c.row, c.col), (1, 1, 0, 10));
}

#[test]
fn every_view_opened_gets_a_tab_that_switches_back_to_it() {
    let mut h = harness(None, Lang::En);
    h.run();
    h.get_by_label("Level 2").click();
    h.run();
    h.get_by_label("Display messages").click();
    h.run();
    assert_eq!(
        h.state().tabs(),
        [View::Block(0), View::Block(1), View::Messages]
    );
    h.get_by_label("Tab: Level 1").click();
    h.run();
    assert_eq!(h.state().view(), View::Block(0));
}

#[test]
fn ctrl_g_in_a_table_goes_to_a_row_of_the_table() {
    use egui::{Key, Modifiers};
    let mut h = harness(None, Lang::En);
    h.run();
    h.state_mut().show_view(View::Symbols(0));
    h.run();
    h.key_press_modifiers(Modifiers::COMMAND, Key::G);
    enter_operand(&mut h, "25");
    assert!(h.state().feature::<EditState>().prompt.is_none());
    let sheet = ladder_studio::gui::tables::Sheet::Symbols(0);
    assert_eq!(
        h.state().feature::<TableState>().selected.get(&sheet),
        Some(&24)
    );
    assert!(
        h.query_all_by_value("KEY_SP_CCW").next().is_some(),
        "row 25 was scrolled into view (only visible rows are laid out)"
    );
    h.key_press_modifiers(Modifiers::COMMAND, Key::G);
    enter_operand(&mut h, "9999");
    let err = h
        .state()
        .feature::<EditState>()
        .prompt
        .clone()
        .unwrap()
        .error
        .unwrap();
    assert!(err.starts_with("The table has no such row: 1–246"), "{err}");
}

#[test]
fn undo_goes_to_the_view_and_the_place_it_changes() {
    use egui::{Key, Modifiers};
    let (mut h, _) = editor_on(TWO_NETWORKS, "undoview.ldp");
    // A change in a table, then the ladder view and a change in its second network.
    let mut tables = h.state().doc().unwrap().project().symbol_tables.clone();
    tables[0].rows.push(ladder_engine::model::Symbol {
        name: "START".into(),
        address: ladder_engine::Address::parse("X0002.1").unwrap(),
        comments: Default::default(),
    });
    h.state_mut()
        .with_context(|cx| cx.apply_or_say(ladder_engine::model::TableEdit::Symbols(tables)));
    h.state_mut().show_view(View::Messages);
    h.run();
    h.key_press_modifiers(Modifiers::COMMAND, Key::Z);
    h.run();
    assert_eq!(
        h.state().view(),
        View::Symbols(0),
        "the undone rename is shown"
    );
    assert!(
        h.state().doc().unwrap().project().symbol_tables[0]
            .rows
            .is_empty()
    );
    h.state_mut().show_view(View::Block(1));
    h.state_mut().with_context(|cx| cx.cursor.network = 1);
    h.run();
    h.key_press(Key::Delete);
    h.run();
    h.state_mut().with_context(|cx| cx.cursor.network = 0);
    h.state_mut().show_view(View::Data);
    h.run();
    h.key_press_modifiers(Modifiers::COMMAND, Key::Z);
    h.run();
    assert_eq!(h.state().view(), View::Block(1));
    assert_eq!(
        h.state().cursor().network,
        1,
        "the cursor is on the contact brought back"
    );
}

/// A level 2 of `level2` networks and a subprogram P0001 of two.
fn long_level2(level2: usize) -> String {
    let mut il = String::from("LEVEL2\n");
    for i in 0..level2 {
        il.push_str(&format!(
            "NETWORK\nLD X0001.{}\nOUT Y0001.{}\n",
            i % 8,
            i % 8
        ));
    }
    il.push_str("SUB P0001 \"SHORT\"\nNETWORK\nLD X0002.0\nOUT Y0002.0\nNETWORK\nLD X0002.1\nOUT Y0002.1\nEND\n");
    il
}

#[test]
fn each_block_keeps_its_own_cursor_and_the_status_bar_speaks_of_the_block_shown() {
    use egui::{Key, Modifiers};
    let (mut h, _) = editor_on(&long_level2(45), "cursor.ldp");
    h.key_press_modifiers(Modifiers::COMMAND, Key::G);
    h.run();
    // The go-to bar says what it takes.
    h.get_by_role_and_label(egui::accesskit::Role::TextInput, "Go to network [row]:")
        .type_text("43");
    h.run();
    h.key_press(Key::Enter);
    h.run();
    assert_eq!(h.state().cursor().network, 42);
    h.get_by_label_contains("P0001").click();
    h.run();
    assert_eq!(h.state().view(), View::Block(2));
    assert_eq!(
        (h.state().cursor().block, h.state().cursor().network),
        (2, 0)
    );
    h.get_by_label_contains("Cursor: P0001 Network 1 ");
    assert!(h.query_by_label_contains("Network 43").is_none());
    // Back in level 2 the cursor is where it was left.
    h.get_by_label("Level 2").click();
    h.run();
    assert_eq!(
        (h.state().cursor().block, h.state().cursor().network),
        (1, 42)
    );
}

#[test]
fn closing_the_project_leaves_no_tab_and_no_output_behind() {
    let (mut h, _) = editor_on(&long_level2(2), "close.ldp");
    h.key_press(egui::Key::F9);
    h.run();
    assert!(!h.state().output().is_empty());
    h.get_by_label("File").click();
    h.run();
    h.get_by_label("Close").click();
    h.run();
    assert!(h.state().doc().is_none());
    assert!(h.state().tabs().is_empty(), "{:?}", h.state().tabs());
    assert!(h.state().output().is_empty());
    assert!(h.query_by_label_contains("Tab:").is_none());
}

#[test]
fn home_end_page_and_ctrl_end_move_the_cursor_and_the_view_follows() {
    let path = PathBuf::from(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../projects/stress-5000.ldp"
    ));
    let mut h = harness(Some(path), Lang::En);
    h.run();
    on_level2(&mut h);
    let (networks, width) = {
        let p = h.state().doc().unwrap().project();
        (p.ladder.blocks[1].networks.len(), p.ladder.width)
    };
    h.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::End);
    h.run();
    h.run();
    let c = h.state().cursor();
    assert_eq!(c.network, networks - 1, "Ctrl+End: the last network");
    let p = h
        .state()
        .feature::<EditState>()
        .geometry
        .cell_center(c.network, c.row, 0)
        .expect("drawn");
    assert!((0.0..800.0).contains(&p.y), "the view followed: {p:?}");
    h.key_press(egui::Key::End);
    h.run();
    assert_eq!(h.state().cursor().col, width, "End: the output column");
    h.key_press(egui::Key::Home);
    h.run();
    assert_eq!(h.state().cursor().col, 0, "Home: the first column");
    h.key_press(egui::Key::PageUp);
    h.run();
    assert_eq!(h.state().cursor().network, networks - 9, "PgUp: a page up");
    h.key_press(egui::Key::PageDown);
    h.run();
    assert_eq!(h.state().cursor().network, networks - 1);
    h.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::Home);
    h.run();
    let c = h.state().cursor();
    assert_eq!(
        (c.network, c.row, c.col),
        (0, 0, 0),
        "Ctrl+Home: the first cell"
    );
}

#[test]
fn ctrl_wheel_zooms_and_the_element_under_the_mouse_stays_under_it() {
    let (mut h, _) = stress_at(40);
    let c = h.state().cursor();
    // Ctrl+plus zooms in about the cursor cell: it stays where it was.
    let g = h.state().feature::<EditState>().geometry.clone();
    let before = g.cell_rect(c.network, c.row, c.col).unwrap().center();
    h.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::Plus);
    h.run();
    assert_eq!(h.state().settings().zoom, 125);
    let g = h.state().feature::<EditState>().geometry.clone();
    let after = g.cell_rect(c.network, c.row, c.col).unwrap();
    assert!(
        after.contains(before),
        "the cursor cell stays where it was: {after:?} holds {before:?}"
    );
    // The mouse on the fifth column of the next network's first row; one notch of
    // Ctrl+wheel zooms in about it.
    let mouse = g.cell_rect(c.network + 1, 0, 4).unwrap().center();
    h.hover_at(mouse);
    h.run();
    h.event(egui::Event::MouseWheel {
        unit: egui::MouseWheelUnit::Line,
        delta: egui::vec2(0.0, 1.0),
        phase: egui::TouchPhase::Move,
        source: egui::MouseWheelSource::Unknown,
        modifiers: egui::Modifiers::COMMAND,
    });
    // The wheel's motion is smoothed over a few frames.
    h.run_steps(30);
    assert_eq!(h.state().settings().zoom, 150, "one notch, one zoom step");
    let g = h.state().feature::<EditState>().geometry.clone();
    let a = g.anchor_at(mouse).unwrap();
    assert_eq!(
        (a.network, a.row),
        (c.network + 1, Some(0)),
        "the same row is under the mouse"
    );
    let cell = g.cell_rect(c.network + 1, 0, 4).unwrap();
    assert!(cell.contains(mouse), "{cell:?} holds {mouse:?}");
}

#[test]
fn the_view_follows_the_cursor_after_an_insert_and_a_paste() {
    let (mut h, _) = stress_at(60);
    let visible = |h: &Harness<'static, LadderApp>| {
        let c = h.state().cursor();
        let g = &h.state().feature::<EditState>().geometry;
        let r = g.cell_rect(c.network, c.row, c.col).unwrap();
        let screen = h.ctx.content_rect();
        r.top() >= 0.0 && r.bottom() <= screen.bottom()
    };
    assert!(visible(&h), "after the jump");
    // Copy a network, then insert and paste below it several times: each lands below the
    // screen's bottom unless the view follows.
    h.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::C);
    h.run();
    for _ in 0..6 {
        h.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::I);
        h.run();
        h.run();
        assert!(visible(&h), "after Ctrl+I");
        h.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::V);
        h.run();
        h.run();
        assert!(visible(&h), "after Ctrl+V");
    }
}

#[test]
fn each_block_opens_again_where_it_was_left_cursor_included() {
    let (mut h, path) = stress_at(120);
    h.run();
    // The cursor one column along, as a user leaves it.
    h.key_press(egui::Key::ArrowRight);
    h.run();
    let cursor = h.state().cursor();
    assert_eq!((cursor.network, cursor.col), (119, 1));
    let top = h.state().settings().tops[&path]["LEVEL2"];
    assert!(
        (100..=119).contains(&top),
        "network 120 is on screen: top {top}"
    );
    let settings = h.state().settings().clone();
    drop(h);
    // Another session with the same settings: level 1 first, then level 2 where it was.
    let mut h = egui_kittest::Harness::builder()
        .with_size(egui::vec2(1280.0, 800.0))
        .build_eframe(move |cc| {
            let mut app = LadderApp::from_creation(cc, Some(path));
            *app.settings_mut() = settings;
            app
        });
    h.run();
    assert_eq!(h.state().view(), View::Block(0));
    on_level2(&mut h);
    h.run();
    let g = h.state().feature::<EditState>().geometry.clone();
    let shown = g.cell_rect(top, 0, 0).unwrap();
    assert!(
        shown.top() >= 0.0 && shown.top() < 200.0,
        "network {top} is at the top again: {shown:?}"
    );
    assert_eq!(
        h.state().cursor(),
        cursor,
        "the cursor came back with the view"
    );
}

#[test]
fn element_comments_and_long_names_fit_their_cells_and_the_tooltip_shows_them_whole() {
    use ladder_studio::gui::command::Command;
    use ladder_studio::gui::settings::DisplayMode;
    let dir = tempfile_dir();
    let path = dir.join("names.ldp");
    let mut p =
        ladder_engine::il::import("LEVEL1\nNETWORK\nLD X0000.0\nAND X0000.1\nOUT Y0000.0\n")
            .project
            .unwrap();
    let long = "SPINDLE_ORIENTATION_FINISHED_CONFIRMATION";
    let comment = "主轴定向完成确认信号（来自主轴驱动器的到位输出）";
    let symbol = |name: &str, addr: &str, zh: &str| ladder_engine::model::Symbol {
        name: name.into(),
        address: ladder_engine::Address::parse(addr).unwrap(),
        comments: [("zh".to_string(), zh.to_string())].into(),
    };
    p.symbol_tables[0]
        .rows
        .push(symbol(long, "X0000.0", comment));
    p.symbol_tables[0]
        .rows
        .push(symbol("DOOR", "X0000.1", "防护门"));
    p.symbol_tables[0].rows.push(symbol(
        "SPINDLE_RUNNING_LAMP_OUTPUT",
        "Y0000.0",
        "主轴运转灯",
    ));
    ladder_engine::file::save(&p, &path).unwrap();
    let mut h = harness(Some(path), Lang::Zh);
    h.run();
    h.state_mut().ask(Command::Display(DisplayMode::Both));
    h.key_press(egui::Key::F11); // element comments on
    h.run();
    h.run();
    assert!(h.state().settings().show_element_comments);
    let g = h.state().feature::<EditState>().geometry.clone();
    let texts: Vec<&str> = g.labels.iter().map(|(_, t)| t.as_str()).collect();
    assert!(
        texts.contains(&"X0000.0") && texts.contains(&"防护门"),
        "{texts:?}"
    );
    let cut = texts
        .iter()
        .find(|t| t.starts_with("SPINDLE_O"))
        .expect("the long name is drawn");
    assert!(
        cut.ends_with('…') && cut.len() < long.len(),
        "shortened: {cut}"
    );
    assert!(
        texts
            .iter()
            .any(|t| t.starts_with("主轴定向") && t.ends_with('…')),
        "the long comment is shortened: {texts:?}"
    );
    // No two labels overlap; none runs into the next column or over the right rail.
    let rail = g.origin.x + g.margin + g.width as f32 * g.cell + g.output + 8.0;
    for (i, (a, ta)) in g.labels.iter().enumerate() {
        assert!(a.right() <= rail, "{ta} runs over the right rail");
        for (b, tb) in &g.labels[i + 1..] {
            assert!(!a.shrink(0.5).intersects(*b), "{ta} overlaps {tb}");
        }
    }
    let first = g.cell_rect(0, 0, 0).unwrap();
    for (r, t) in &g.labels {
        if r.center().x < first.right() {
            assert!(
                r.left() >= first.left() && r.right() <= first.right(),
                "{t} leaves its cell"
            );
        }
    }
    // Offline, the tooltip gives the whole name and comment.
    h.hover_at(first.center());
    h.run_steps(40);
    let whole = format!("X0000.0  {long}  — {comment}");
    assert!(h.query_all_by_label_contains(&whole).next().is_some());
}

#[test]
fn the_output_window_resizes_keeps_its_height_lists_a_branch_once_and_copies_a_line() {
    // An open branch of three contacts, and an undefined symbol.
    let il =
        "LEVEL2\nNETWORK\nLD X0001.0\nOUT Y0001.0\nNETWORK\nLD X0001.1\nAND NOWHERE\nOUT Y0001.1\n";
    let (mut h, _) = editor_on(il, "out.ldp");
    // Draw the open branch under network 1: a link down, then three contacts.
    click_cell(&mut h, 0, 0, 1);
    h.key_press(egui::Key::F5);
    h.run();
    h.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::R);
    h.run();
    for col in 1..4 {
        click_cell(&mut h, 0, 1, col);
        h.key_press(egui::Key::F1);
        enter_operand(&mut h, &format!("X0002.{col}"));
    }
    h.key_press(egui::Key::F9);
    h.run();
    let lines: Vec<String> = h.state().output().iter().map(|l| l.text.clone()).collect();
    assert_eq!(
        lines.iter().filter(|l| l.contains("[L002]")).count(),
        1,
        "one line for the branch: {lines:?}"
    );
    // Copy one line from its right-click menu.
    h.get_by_label_contains("[L020]").click_secondary();
    h.run();
    h.get_by_label("Copy this line").click();
    h.step();
    let copied = h.output().platform_output.commands.iter().any(|c| {
        matches!(c, egui::OutputCommand::CopyText(t) if t.contains("[L020]") && t.contains("NOWHERE"))
    });
    assert!(copied, "{:?}", h.output().platform_output.commands);
    h.run();
    // Drag the window's top edge up by 100 points: it grows, and the settings keep it.
    let before = h.state().settings().output_height;
    let top = h.get_by_label("Output").rect().top() - 4.0;
    drag(
        &mut h,
        egui::pos2(600.0, top),
        egui::pos2(600.0, top - 100.0),
    );
    h.run();
    let after = h.state().settings().output_height;
    assert!(after > before + 60.0, "{before} → {after}");
}

#[test]
fn network_comments_show_a_line_per_language_as_the_csv_has_them() {
    use ladder_studio::gui::command::Command;
    let dir = tempfile_dir();
    let path = dir.join("langs.ldp");
    let mut p = ladder_engine::il::import("LEVEL1\nNETWORK\nLD X0000.0\nOUT Y0000.0\n")
        .project
        .unwrap();
    let net = &mut p.ladder.blocks[0].networks[0];
    net.comments.insert("zh".into(), "主轴启动".into());
    net.comments.insert("en".into(), "Spindle start".into());
    ladder_engine::file::save(&p, &path).unwrap();
    let csv = ladder_engine::comments::export(&p, None);
    assert!(csv.contains("主轴启动") && csv.contains("Spindle start"));
    let mut h = harness(Some(path), Lang::En);
    h.run();
    assert!(h.state().settings().show_comments);
    let header = 22.0 * f32::from(h.state().settings().zoom) / 100.0;
    let first_row = h.state().feature::<EditState>().geometry.rows[0][0];
    assert_eq!(first_row, 3.0 * header, "title, then a zh and an en line");
    h.state_mut().ask(Command::ToggleComments);
    h.run();
    assert_eq!(
        h.state().feature::<EditState>().geometry.rows[0][0],
        header,
        "hidden: the title only"
    );
}
