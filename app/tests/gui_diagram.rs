//! The ladder diagram as an engineer works in it: zoom about the pointer at both ends of a
//! block, labels that never overlap, errors marked on the elements, operands typed at the
//! cell, rows opened with Down, and element properties.

use crate::common::*;
use ladder_studio::gui::editor::EditState;
use ladder_studio::gui::properties::ElementProperties;

/// One notch of Ctrl+wheel at `mouse`, in (`up`) or out, and the frames it is smoothed over.
fn wheel(h: &mut Harness<'static, LadderApp>, mouse: egui::Pos2, up: bool) {
    h.hover_at(mouse);
    h.run();
    h.event(egui::Event::MouseWheel {
        unit: egui::MouseWheelUnit::Line,
        delta: egui::vec2(0.0, if up { 1.0 } else { -1.0 }),
        phase: egui::TouchPhase::Move,
        source: egui::MouseWheelSource::Unknown,
        modifiers: egui::Modifiers::COMMAND,
    });
    h.run_steps(30);
}

/// Zooms in and out about the cursor cell's centre and checks it stays under the mouse.
fn zoom_keeps_the_cell_under_the_mouse(h: &mut Harness<'static, LadderApp>) {
    let c = h.state().cursor();
    let cell = |h: &Harness<'static, LadderApp>| {
        h.state()
            .feature::<EditState>()
            .geometry
            .cell_rect(c.network, c.row, c.col)
            .expect("the cursor cell is drawn")
    };
    let mouse = cell(h).center();
    for (up, zoom) in [
        (true, 125),
        (true, 150),
        (false, 125),
        (false, 100),
        (false, 75),
    ] {
        wheel(h, mouse, up);
        assert_eq!(h.state().settings().zoom, zoom);
        let now = cell(h);
        assert!(
            now.contains(mouse),
            "at {zoom} % network {} is still under the mouse: {now:?} holds {mouse:?}",
            c.network + 1
        );
    }
}

#[test]
fn zoom_keeps_the_element_under_the_pointer_on_the_last_network() {
    let (mut h, _) = stress_at(1);
    h.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::End);
    h.run();
    h.run();
    let last = h.state().doc().unwrap().project().ladder.blocks[1]
        .networks
        .len();
    assert_eq!(h.state().cursor().network, last - 1);
    zoom_keeps_the_cell_under_the_mouse(&mut h);
}

#[test]
fn zoom_keeps_the_element_under_the_pointer_on_the_first_network() {
    // The block's first element: the view cannot scroll before the block's start, so this
    // is the hardest place to keep still when zooming out.
    let (mut h, _) = stress_at(1);
    zoom_keeps_the_cell_under_the_mouse(&mut h);
}

/// The bundled lathe project on level 2: symbols and element comments on most contacts.
fn lathe() -> Harness<'static, LadderApp> {
    let path = PathBuf::from(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../projects/lathe-988ta.ldp"
    ));
    let mut h = harness(Some(path), Lang::En);
    h.run();
    on_level2(&mut h);
    h
}

#[test]
fn no_label_is_drawn_over_another_or_across_its_cell_in_any_display_mode() {
    use ladder_studio::gui::command::DISPLAY_MODES;
    let mut h = lathe();
    h.key_press(egui::Key::F11);
    h.run();
    assert!(h.state().settings().show_element_comments);
    for zoom in [75, 100, 150] {
        for mode in DISPLAY_MODES {
            h.state_mut().settings_mut().zoom = zoom;
            h.state_mut().settings_mut().display = mode;
            h.run();
            h.run();
            let g = h.state().feature::<EditState>().geometry.clone();
            let labels: Vec<_> = g.labels.iter().filter(|(_, t)| !t.is_empty()).collect();
            assert!(labels.len() > 20, "{mode:?}: {} labels", labels.len());
            assert!(
                labels.iter().any(|(r, _)| labels
                    .iter()
                    .any(|(q, _)| q.top() > r.bottom() && q.top() - r.bottom() < g.cell)),
                "comments are drawn under the contacts"
            );
            for (i, (a, ta)) in labels.iter().enumerate() {
                for (b, tb) in &labels[i + 1..] {
                    assert!(
                        !a.intersects(*b),
                        "{mode:?} at {zoom} %: {ta:?} {a:?} overlaps {tb:?} {b:?}"
                    );
                }
                // The label is inside one cell, clear of the cursor's 2 px outline.
                let inside = (0..g.tops.len()).any(|n| {
                    (0..g.rows[n].len()).any(|r| {
                        (0..=g.width).any(|c| {
                            g.cell_rect(n, r, c).is_some_and(|cell| {
                                let cell = if c == g.width {
                                    cell.with_max_x(cell.max.x + g.cell)
                                } else {
                                    cell
                                };
                                cell.shrink(2.0).contains_rect(*a)
                            })
                        })
                    })
                });
                assert!(
                    inside,
                    "{mode:?} at {zoom} %: {ta:?} {a:?} crosses its cell's edge"
                );
            }
        }
    }
}

#[test]
fn a_compile_error_is_marked_on_its_element_and_f12_goes_to_it() {
    let mut h = lathe();
    h.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::G);
    enter_operand(&mut h, "5 1");
    // A new network with a lone contact: it leads to no coil, an error.
    h.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::I);
    h.run();
    let wrong = h.state().cursor();
    h.key_press(egui::Key::F1);
    enter_operand(&mut h, "X0.0");
    h.run();
    // Before the first compile nothing is marked: a drawing in progress is not an error.
    assert!(
        h.state()
            .feature::<EditState>()
            .geometry
            .error_marks
            .is_empty()
    );
    h.key_press(egui::Key::F9);
    h.run();
    h.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::Home);
    h.run();
    h.key_press(egui::Key::F12);
    h.run();
    h.run();
    let c = h.state().cursor();
    assert_eq!(
        (c.network, c.row, c.col),
        (wrong.network, 0, 0),
        "F12 went to it"
    );
    let g = h.state().feature::<EditState>().geometry.clone();
    let cell = g.cell_rect(c.network, c.row, c.col).unwrap();
    assert!(
        g.error_marks.iter().any(|m| cell.contains_rect(*m)),
        "the element carries the mark: {cell:?} in {:?}",
        g.error_marks
    );
    assert!(
        h.query_by_label_contains("1 error, 0 warnings (F12)")
            .is_some(),
        "the status bar counts it"
    );
    // Shift+F12 from the first cell wraps round to the last mark: the same one.
    h.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::Home);
    h.run();
    h.key_press_modifiers(egui::Modifiers::SHIFT, egui::Key::F12);
    h.run();
    assert_eq!(h.state().cursor().network, wrong.network);
    // Fixed (the contact taken back), the mark goes without compiling again.
    h.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::Z);
    h.run();
    h.run();
    assert!(
        h.state()
            .feature::<EditState>()
            .geometry
            .error_marks
            .is_empty()
    );
    assert!(
        h.query_by_label_contains("1 error, 0 warnings (F12)")
            .is_none()
    );
}

#[test]
fn down_past_the_last_row_offers_a_new_row_and_an_impossible_f6_is_refused_before_typing() {
    let mut h = lathe();
    h.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::G);
    enter_operand(&mut h, "2 1");
    let rows = |h: &Harness<'static, LadderApp>| {
        h.state().doc().unwrap().project().ladder.blocks[1].networks[1]
            .rows
            .len()
    };
    let before = rows(&h);
    let undo_depth = h.state().doc().unwrap().history().undo_len();
    // F6 on the first row: refused at once, no prompt to type into.
    h.key_press(egui::Key::F6);
    h.run();
    assert!(
        h.state().feature::<EditState>().prompt.is_none(),
        "no operand is asked for"
    );
    assert!(
        h.state().output().last().is_some_and(|l| l.error),
        "the refusal is said: {:?}",
        h.state().output().last()
    );
    for _ in 0..before {
        h.key_press(egui::Key::ArrowDown);
        h.run();
    }
    let c = h.state().cursor();
    assert_eq!(
        (c.network, c.row),
        (1, before),
        "on the new row below the last"
    );
    assert!(
        h.state()
            .feature::<EditState>()
            .geometry
            .cell_rect(1, before, c.col)
            .is_some(),
        "the new row is drawn"
    );
    assert_eq!(rows(&h), before, "offered, not yet added");
    // F6 there: a contact in parallel with the last row, the row added with it, one undo step.
    h.key_press(egui::Key::F6);
    enter_operand(&mut h, "X0.3");
    h.run();
    assert_eq!(rows(&h), before + 1);
    let doc = h.state().doc().unwrap();
    assert_eq!(doc.history().undo_len(), undo_depth + 1, "one undo step");
    // Down again from an offered row goes on to the next network.
    h.key_press(egui::Key::ArrowDown);
    h.run();
    h.key_press(egui::Key::ArrowDown);
    h.run();
    assert_eq!(h.state().cursor().network, 2);
}

#[test]
fn at_900_by_600_the_ladder_keeps_half_the_height_and_replace_opens_ready_to_type() {
    use egui::accesskit::Role;
    for lang in [Lang::En, Lang::Zh] {
        let path = PathBuf::from(concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/../projects/lathe-988ta.ldp"
        ));
        let mut h = harness_sized(Some(path), lang, egui::vec2(900.0, 600.0));
        h.run();
        h.run();
        let shown = h
            .state()
            .feature::<EditState>()
            .geometry
            .visible
            .expect("the ladder is drawn");
        assert!(
            shown.height() >= 300.0,
            "{lang:?}: the ladder has {} px of 600",
            shown.height()
        );
        // The tools that do not fit are in the overflow menu.
        h.get_by_label("»").click();
        h.run();
        let more = match lang {
            Lang::En => "Single tick (8 ms)",
            Lang::Zh => "单步（1 个 8 ms",
        };
        assert!(h.query_by_label_contains(more).is_some(), "{lang:?}");
        h.key_press(egui::Key::Escape);
        h.run();
        h.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::H);
        h.run();
        h.run();
        let find = ladder_studio::gui::i18n::Msg::ReplaceFrom.text(lang);
        let field = h.get_by_role_and_label(Role::TextInput, find);
        assert!(
            field.is_focused(),
            "{lang:?}: the first field has the keyboard"
        );
        let window = h.get_by_label(match lang {
            Lang::En => "Replace",
            Lang::Zh => "替换",
        });
        let menu = h.get_by_label(match lang {
            Lang::En => "File",
            Lang::Zh => "文件",
        });
        let (w, m) = (window.rect(), menu.rect());
        assert!(
            w.min.y >= m.max.y,
            "{lang:?}: the window {w:?} is below the menu {m:?}"
        );
    }
}

#[test]
fn an_operand_is_typed_in_place_at_the_cell_and_nothing_moves() {
    use egui::accesskit::Role;
    use ladder_studio::gui::i18n::Msg;
    let mut h = lathe();
    h.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::G);
    enter_operand(&mut h, "3 1");
    h.key_press(egui::Key::ArrowRight);
    h.run();
    let c = h.state().cursor();
    let before = h.state().feature::<EditState>().geometry.clone();
    let cell = before.cell_rect(c.network, c.row, c.col).unwrap();
    h.key_press(egui::Key::F1);
    h.run();
    h.run();
    let field = h.get_by_role_and_label(Role::TextInput, Msg::Operand.text(Lang::En));
    assert!(field.is_focused());
    let at = field.rect();
    assert!(
        cell.expand(40.0).contains(at.left_top()) && at.top() >= cell.top() - 1.0,
        "the field {at:?} is at the cell {cell:?}"
    );
    assert_eq!(
        h.state().feature::<EditState>().geometry.origin,
        before.origin,
        "the ladder did not move"
    );
    // The suggestions come under the field.
    field.type_text("KEY_A");
    h.run();
    use egui_kittest::kittest::NodeT;
    let first = h
        .get_all_by_role(Role::Button)
        .find(|b| {
            b.accesskit_node()
                .label()
                .is_some_and(|l| l.starts_with("KEY_AUTO"))
        })
        .expect("a suggestion");
    assert!(first.rect().top() >= at.bottom(), "under the field");
    h.key_press(egui::Key::Escape);
    h.run();
    assert!(h.state().feature::<EditState>().prompt.is_none());
    // A title is typed at the network's header.
    h.state_mut()
        .ask(ladder_studio::gui::command::Command::NetworkTitle);
    h.run();
    h.run();
    let field = h.get_by_role_and_label(Role::TextInput, Msg::TitlePrompt.text(Lang::En));
    let top = before.origin.y + before.tops[c.network];
    assert!(
        (field.rect().top() - top).abs() < 30.0,
        "the title field {:?} is at the header ({top})",
        field.rect()
    );
}

#[test]
fn element_properties_edit_the_symbol_table_in_one_undo_step() {
    use egui::accesskit::Role;
    use ladder_studio::gui::i18n::Msg;
    let mut h = lathe();
    h.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::G);
    enter_operand(&mut h, "3 1");
    let c = h.state().cursor();
    let project = h.state().doc().unwrap().project();
    let Some(ladder_engine::model::Cell::Contact { operand, .. }) =
        project.ladder.blocks[1].networks[c.network].cell(c.row, c.col)
    else {
        panic!("a contact at the cursor")
    };
    let x = ladder_studio::gui::ladder_view::address_of(project, operand).unwrap();
    let name = project
        .symbols()
        .find(|s| s.address == x)
        .unwrap()
        .name
        .clone();
    let taken = project
        .symbols()
        .find(|s| s.address != x && !s.name.is_empty())
        .unwrap()
        .name
        .clone();
    let symbols =
        |h: &Harness<'static, LadderApp>| h.state().doc().unwrap().project().symbol_tables.clone();
    let before = symbols(&h);
    let depth = h.state().doc().unwrap().history().undo_len();
    // A double-click on the contact's label opens its properties over it.
    let g = h.state().feature::<EditState>().geometry.clone();
    let cell = g.cell_rect(c.network, c.row, c.col).unwrap();
    let label = g
        .labels
        .iter()
        .find(|(r, _)| cell.contains_rect(*r))
        .expect("the contact's label")
        .0;
    double_click(&mut h, label.center());
    h.run();
    let form = h
        .state()
        .feature::<ElementProperties>()
        .form
        .clone()
        .expect("the properties are open");
    assert_eq!(form.address, x);
    assert_eq!(form.props.name, name);
    let symbol = h.get_by_role_and_label(Role::TextInput, Msg::SymbolLabel.text(Lang::En));
    assert!(symbol.is_focused());
    assert!(
        cell.expand(cell.height())
            .contains(symbol.rect().left_top()),
        "in place"
    );
    h.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::A);
    symbol.type_text("AUTO_KEY");
    h.get_by_role_and_label(Role::MultilineTextInput, "Comment (en)")
        .focus();
    h.run();
    h.key_press(egui::Key::End);
    h.get_by_role_and_label(Role::MultilineTextInput, "Comment (en)")
        .type_text(" (front panel)\nsecond line");
    h.run();
    h.get_by_role_and_label(Role::Button, "OK").click();
    h.run();
    assert!(
        h.state().feature::<ElementProperties>().form.is_none(),
        "closed on OK: {:?}",
        h.state().feature::<ElementProperties>().form
    );
    let p = h.state().doc().unwrap().project();
    assert_eq!(p.resolve_symbol("AUTO_KEY"), Some(x));
    assert!(
        p.comment_of(x, "en")
            .unwrap()
            .ends_with("(front panel)\nsecond line")
    );
    assert_eq!(
        h.state().doc().unwrap().history().undo_len(),
        depth + 1,
        "one undo step"
    );
    h.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::Z);
    h.run();
    assert_eq!(symbols(&h), before, "undone whole");
    // The undo showed the symbol table it changed; back to the ladder.
    on_level2(&mut h);
    // Alt+Enter opens them from the keyboard; a taken name is refused in the form.
    h.key_press_modifiers(egui::Modifiers::ALT, egui::Key::Enter);
    h.run();
    h.run();
    let symbol = h.get_by_role_and_label(Role::TextInput, Msg::SymbolLabel.text(Lang::En));
    h.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::A);
    symbol.type_text(&taken);
    h.run();
    h.get_by_role_and_label(Role::Button, "OK").click();
    h.run();
    let form = h
        .state()
        .feature::<ElementProperties>()
        .form
        .clone()
        .expect("still open");
    assert!(form.error.is_some_and(|e| e.contains(&taken)));
    assert_eq!(symbols(&h), before, "nothing written");
}
