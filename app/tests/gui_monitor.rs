//! The online monitor as an engineer at the machine uses it: every key press of a frame acts,
//! in order; a recorded past cannot be changed.

use crate::common::online::*;
use crate::common::*;
use ladder_studio::gui::command::Command;
use ladder_studio::gui::editor::EditState;
use ladder_studio::gui::online::OnlineState;
use ladder_studio::gui::tables::TableState;

/// Two presses queued before one frame: both act (a fast typist, a slow frame).
fn two_presses(h: &mut Harness<'static, LadderApp>, m: egui::Modifiers, key: egui::Key) {
    h.key_press_modifiers(m, key);
    h.key_press_modifiers(m, key);
    h.step();
}

#[test]
fn two_key_presses_in_one_frame_move_the_cursor_twice() {
    let mut h = harness(Some(il_project(RUNG)), Lang::En);
    h.run();
    on_level2(&mut h);
    click_cell(&mut h, 0, 0, 0);
    two_presses(&mut h, egui::Modifiers::NONE, egui::Key::ArrowRight);
    h.run();
    assert_eq!(h.state().cursor().col, 2, "Right Right moved twice");
}

#[test]
fn two_force_presses_in_one_frame_force_and_release_the_bit_at_the_cursor() {
    let mut h = harness(Some(il_project(RUNG)), Lang::En);
    h.run();
    on_level2(&mut h);
    command(&mut h, Command::StepTick);
    click_cell(&mut h, 0, 0, 0);
    h.state_mut()
        .with(|f: &mut OnlineState, _| f.forces_confirmed = true);
    // The first press forces X0010.0 to 1; the second, sent before any snapshot showed the
    // force, releases it rather than forcing again from the old state.
    two_presses(&mut h, egui::Modifiers::SHIFT, egui::Key::F7);
    settle(&mut h);
    assert!(
        h.state()
            .feature::<OnlineState>()
            .forced_addresses()
            .is_empty(),
        "forced, then released"
    );
    assert_eq!(
        value(&h, "X0010.0"),
        1,
        "the forced value stays until written"
    );
    // One press forces to the inverse of what the machine holds: 0.
    h.key_press_modifiers(egui::Modifiers::SHIFT, egui::Key::F7);
    settle(&mut h);
    ticks(&mut h, 1);
    assert_eq!(value(&h, "X0010.0"), 0);
    assert_eq!(
        h.state().feature::<OnlineState>().forced_addresses().len(),
        1
    );
}

#[test]
fn two_toggle_presses_in_one_frame_write_the_bit_back() {
    let mut h = harness(Some(il_project(RUNG)), Lang::En);
    h.run();
    on_level2(&mut h);
    command(&mut h, Command::StepTick);
    click_cell(&mut h, 0, 0, 0);
    two_presses(&mut h, egui::Modifiers::NONE, egui::Key::F7);
    settle(&mut h);
    assert_eq!(value(&h, "X0010.0"), 0, "on, then off again");
    h.key_press(egui::Key::F7);
    settle(&mut h);
    assert_eq!(value(&h, "X0010.0"), 1);
}

#[test]
fn undo_is_disabled_while_replaying_and_nothing_changes_the_project_or_the_machine() {
    use ladder_engine::model::{Cell, CellRef, Edit, Operand};
    let mut h = harness(Some(il_project(RUNG)), Lang::En);
    h.run();
    on_level2(&mut h);
    command(&mut h, Command::StepTick);
    // An edit to undo later: X0010.1 becomes X0010.3, swapped in.
    let at = CellRef {
        block: 1,
        network: 0,
        row: 0,
        col: 1,
    };
    let contact = |a: &str| Cell::Contact {
        negated: false,
        operand: Operand::parse(a).unwrap(),
    };
    h.state_mut()
        .with_context(|cx| {
            cx.apply(Edit::SetCell {
                at,
                cell: contact("X0010.3"),
            })
        })
        .unwrap();
    h.step();
    settle(&mut h);
    ticks(&mut h, 3);
    let past = h
        .state()
        .feature::<OnlineState>()
        .session
        .as_ref()
        .unwrap()
        .published
        .snapshot
        .ticks
        - 1;
    h.state_mut()
        .with(|f: &mut OnlineState, _| f.session.as_mut().unwrap().scrub_to(Some(past)));
    h.step();
    assert!(h.state().feature::<OnlineState>().scrubbing());
    assert!(!h.state().enabled(Command::Undo), "Undo is greyed out");
    // Ctrl+Z, an edit and a write all leave the project and the machine as they were.
    h.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::Z);
    h.step();
    assert!(
        h.state_mut()
            .with_context(|cx| cx.apply(Edit::SetCell {
                at,
                cell: contact("X0010.4"),
            }))
            .is_err()
    );
    let x =
        ladder_studio::gui::online::watch::resolve(h.state().doc().unwrap().project(), "X0010.2")
            .unwrap();
    h.state_mut().with(|o: &mut OnlineState, cx| {
        o.send_command(cx, ladder_engine::machine::MachineCommand::Write(x, 1))
    });
    assert!(output(&h).contains("nothing can change until Back to live"));
    command(&mut h, Command::LiveView);
    settle(&mut h);
    let p = h.state().doc().unwrap().project().clone();
    let cell = &p.ladder.blocks[1].networks[0].rows[0].cells[1];
    assert_eq!(*cell, contact("X0010.3"), "the edit was not undone");
    assert!(
        h.state()
            .feature::<OnlineState>()
            .session
            .as_ref()
            .unwrap()
            .drawing_runs(&p),
        "the program that ran runs on"
    );
    assert_eq!(value(&h, "X0010.2"), 0, "the write was not sent");
    assert!(h.state().enabled(Command::Undo), "live again: Undo works");
}

fn write(h: &mut Harness<'static, LadderApp>, a: &str, v: i64) {
    let t =
        ladder_studio::gui::online::watch::resolve(h.state().doc().unwrap().project(), a).unwrap();
    h.state_mut().with(|o: &mut OnlineState, cx| {
        o.send_command(cx, ladder_engine::machine::MachineCommand::Write(t, v))
    });
}

fn now(h: &Harness<'static, LadderApp>) -> u64 {
    h.state()
        .feature::<OnlineState>()
        .session
        .as_ref()
        .unwrap()
        .published
        .snapshot
        .ticks
}

#[test]
fn a_triggered_capture_survives_two_minutes_of_running_and_a_pause_keeps_its_copy() {
    use ladder_studio::gui::settings::{TriggerSetup, TriggerWhen};
    let mut h = harness(Some(il_project(RUNG)), Lang::En);
    h.run();
    command(&mut h, Command::StepTick);
    h.state_mut()
        .with(|o: &mut OnlineState, cx| o.add_watch(cx, "X0010.0"))
        .unwrap();
    h.state_mut()
        .with(|o: &mut OnlineState, cx| o.add_watch(cx, "Y0010.0"))
        .unwrap();
    let key = h
        .state_mut()
        .with(|o: &mut OnlineState, cx| o.watch_key(cx));
    h.state_mut().settings_mut().triggers.insert(
        key,
        TriggerSetup {
            signal: "X0010.0".into(),
            when: TriggerWhen::Rising,
            value: 0,
            pre: 10,
            post: 20,
        },
    );
    h.state_mut()
        .with(|f: &mut OnlineState, _| f.tab = ladder_studio::gui::online::OnlineTab::Trace);
    h.run();
    h.get_by_label("Arm").click();
    h.run();
    h.get_by_label("Armed, waiting…");
    ticks(&mut h, 25);
    write(&mut h, "X0010.1", 1);
    write(&mut h, "X0010.0", 1);
    ticks(&mut h, 1);
    let edge = now(&h);
    ticks(&mut h, 30);
    h.run();
    let capture = h
        .state()
        .feature::<OnlineState>()
        .trace
        .capture
        .clone()
        .expect("captured");
    assert_eq!(capture.at, edge);
    assert_eq!(
        (capture.data.first, capture.data.last),
        (edge - 10, edge + 20)
    );
    let x = &capture.data.signals[0];
    assert_eq!(x.name, "X0010.0");
    assert_eq!((x.value_at(edge - 1), x.value_at(edge)), (0, 1));
    let y = &capture.data.signals[1];
    assert_eq!(y.value_at(edge), 1, "Y0010.0 follows in the same tick");
    h.get_by_label_contains("Captured: triggered at tick");
    // Pause shows its own copy while the machine runs on.
    h.state_mut()
        .with(|f: &mut OnlineState, _| f.trace.show_capture = false);
    h.run();
    h.get_by_label("Pause").click();
    h.run();
    let paused = h
        .state_mut()
        .with(|o: &mut OnlineState, cx| o.shown_trace(cx));
    write(&mut h, "X0010.0", 0);
    ticks(&mut h, 50);
    assert_ne!(
        h.state_mut()
            .with(|o: &mut OnlineState, cx| o.trace_data(cx)),
        paused,
        "the record moved on"
    );
    assert_eq!(
        h.state_mut()
            .with(|o: &mut OnlineState, cx| o.shown_trace(cx)),
        paused,
        "the paused chart did not"
    );
    // Two minutes later the ring has long dropped the edge; the capture has not.
    ticks(&mut h, 15_000);
    let oldest = h
        .state()
        .feature::<OnlineState>()
        .session
        .as_ref()
        .unwrap()
        .recorder()
        .oldest()
        .unwrap();
    assert!(oldest > edge + 20, "the ring moved past the capture");
    assert_eq!(
        h.state().feature::<OnlineState>().trace.capture.as_ref(),
        Some(&capture)
    );
    h.state_mut()
        .with(|f: &mut OnlineState, _| f.trace.show_capture = true);
    assert_eq!(
        h.state_mut()
            .with(|o: &mut OnlineState, cx| o.shown_trace(cx)),
        capture.data
    );
    // The export writes what is shown.
    let csv = ladder_studio::gui::online::trace_view::trace_csv(
        &h.state_mut()
            .with(|o: &mut OnlineState, cx| o.shown_trace(cx)),
    );
    assert!(csv.starts_with("tick,ms,X0010.0,Y0010.0\n"), "{csv}");
    assert_eq!(csv.lines().count(), 1 + 31);
}

/// Whether the output column of the cursor's row is on screen.
fn output_on_screen(h: &Harness<'static, LadderApp>) -> bool {
    let app = h.state();
    let g = &app.feature::<EditState>().geometry;
    let c = app.cursor();
    let width = app.doc().unwrap().project().ladder.width;
    let cell = g.cell_rect(c.network, c.row, width).expect("drawn");
    g.visible.expect("drawn").contains_rect(cell.shrink(2.0))
}

#[test]
fn fit_width_shows_the_output_column_at_1280_by_800_with_the_online_window_open() {
    let mut h = harness_sized(Some(lathe()), Lang::En, egui::vec2(1280.0, 800.0));
    h.run();
    on_level2(&mut h);
    command(&mut h, Command::StepTick);
    h.state_mut().settings_mut().show_online = true;
    h.run();
    assert!(
        h.state().settings().fit_width,
        "going online fits the width"
    );
    assert!(output_on_screen(&h), "the coils are on screen");
    let zoom = h.state().feature::<EditState>().geometry.zoom;
    assert!((50..100).contains(&zoom), "zoom {zoom}");
    // A zoom step leaves fit width; End still brings the output column into view.
    command(&mut h, Command::ZoomIn);
    h.run();
    assert!(!h.state().settings().fit_width);
    command(&mut h, Command::ZoomIn);
    h.run();
    h.key_press(egui::Key::Home);
    h.run();
    h.key_press(egui::Key::End);
    h.run();
    h.run();
    assert!(
        output_on_screen(&h),
        "the view followed the cursor sideways"
    );
    h.key_press(egui::Key::Home);
    h.run();
    let g = &h.state().feature::<EditState>().geometry;
    let first = g.cell_rect(0, 0, 0).unwrap();
    assert!(
        g.visible.unwrap().contains_rect(first.shrink(2.0)),
        "Home: back left"
    );
    // Arrow by arrow to the output column: the view follows each step.
    let width = h.state().doc().unwrap().project().ladder.width;
    for _ in 0..width {
        h.key_press(egui::Key::ArrowRight);
        h.run();
    }
    assert_eq!(h.state().cursor().col, width);
    assert!(output_on_screen(&h), "Right arrows: the view followed");
}

#[test]
fn a_refused_edit_is_shown_at_the_bottom_of_the_output_and_its_errors_go_with_undo() {
    use ladder_engine::model::{Cell, CellRef, Edit, Operand};
    let mut h = harness(Some(il_project(RUNG)), Lang::En);
    h.run();
    on_level2(&mut h);
    command(&mut h, Command::StepTick);
    h.state_mut()
        .with_context(|cx| {
            cx.apply(Edit::SetCell {
                at: CellRef {
                    block: 1,
                    network: 0,
                    row: 0,
                    col: 1,
                },
                cell: Cell::Contact {
                    negated: false,
                    operand: Operand::parse("NO_SUCH_SYMBOL").unwrap(),
                },
            })
        })
        .unwrap();
    h.step();
    settle(&mut h);
    h.run();
    let last = h.state().output().last().unwrap().text.clone();
    assert!(last.contains("was not swapped in"), "{last}");
    // The newest line is on screen, inside the window.
    let node = h.get_by_label_contains("was not swapped in");
    let r = node.rect();
    assert!(r.max.y <= 800.0 && r.min.y >= 0.0, "{r:?}");
    command(&mut h, Command::Undo);
    h.run();
    let out = output(&h);
    assert!(!out.contains("NO_SUCH_SYMBOL"), "{out}");
    h.get_by_label_contains("Running program = drawing");
}

#[test]
fn the_first_force_asks_first_and_the_status_bar_counts_forces_in_amber() {
    let mut h = harness(Some(il_project(RUNG)), Lang::En);
    h.run();
    on_level2(&mut h);
    command(&mut h, Command::StepTick);
    click_cell(&mut h, 0, 0, 0);
    h.key_press_modifiers(egui::Modifiers::SHIFT, egui::Key::F7);
    h.run();
    h.get_by_label("Force a signal");
    h.get_by_label("Cancel").click();
    h.run();
    settle(&mut h);
    assert!(
        h.state()
            .feature::<OnlineState>()
            .forced_addresses()
            .is_empty(),
        "cancelled: nothing forced"
    );
    h.key_press_modifiers(egui::Modifiers::SHIFT, egui::Key::F7);
    h.run();
    h.get_by_label("Force").click();
    h.run();
    settle(&mut h);
    assert_eq!(
        h.state().feature::<OnlineState>().forced_addresses().len(),
        1
    );
    h.get_by_label_contains("Forces active (1)");
    // Asked once: the next press releases at once.
    h.key_press_modifiers(egui::Modifiers::SHIFT, egui::Key::F7);
    settle(&mut h);
    assert!(
        h.state()
            .feature::<OnlineState>()
            .forced_addresses()
            .is_empty()
    );
    assert!(h.query_by_label("Force a signal").is_none());
}

#[test]
fn the_toolbar_shows_the_scan_in_steps_and_the_watchdog_limit() {
    let mut h = harness(Some(il_project(RUNG)), Lang::En);
    h.run();
    ticks(&mut h, 3);
    let (last, max) = h
        .state()
        .feature::<OnlineState>()
        .session
        .as_ref()
        .unwrap()
        .published
        .snapshot
        .tick_steps;
    // Two networks: LD, AND, OUT and LD, TMRB (with its R coil) run every tick.
    assert!(last >= 5 && max >= last, "{last} {max}");
    h.get_by_label_contains(&format!("Scan {last}/{max}/200000"));
}

#[test]
fn the_cnc_page_sends_mdi_with_feedback_starts_it_and_keeps_its_codes_and_strobes() {
    use ladder_engine::machine::Target;
    use ladder_engine::runner::Request;
    let mut h = harness(Some(lathe()), Lang::En);
    h.run();
    command(&mut h, Command::StepTick);
    let mdi = h
        .state_mut()
        .with(|o: &mut OnlineState, cx| o.panel_key(cx, "MDI"))
        .expect("the preset has an MDI key");
    let key = Target {
        address: mdi,
        bytes: 1,
        explicit: false,
    };
    h.state_mut()
        .with(|o: &mut OnlineState, cx| o.send_request(cx, Request::Press(key)));
    h.state_mut()
        .with(|o: &mut OnlineState, cx| o.send_request(cx, Request::Release(key)));
    ticks(&mut h, 20);
    h.state_mut()
        .with(|f: &mut OnlineState, _| f.tab = ladder_studio::gui::online::OnlineTab::Cnc);
    h.state_mut()
        .with(|f: &mut OnlineState, _| f.cnc.mdi = "M08".into());
    h.run();
    h.get_by_label("Send MDI").click();
    h.run();
    settle(&mut h);
    h.get_by_label_contains("Sent to the CNC's MDI buffer, blocks: 1");
    h.get_by_label("Cycle start").click();
    h.run();
    settle(&mut h);
    ticks(&mut h, 60);
    let status = h
        .state()
        .feature::<OnlineState>()
        .session
        .as_ref()
        .unwrap()
        .published
        .snapshot
        .cnc
        .clone()
        .unwrap();
    assert_eq!(status.mst.last[0], 8, "{status:?}");
    assert_eq!(status.mst.m, 0, "the strobe is long over");
    h.get_by_label_contains("MF ×1");
    assert!(
        status.line_in_mdi,
        "the marker is in the MDI editor, not the program's"
    );
}

#[test]
fn the_988ta_panel_fits_its_page_and_the_tabs_stay_put_at_both_sizes() {
    use ladder_studio::gui::online::OnlineTab;
    for size in [egui::vec2(1280.0, 800.0), egui::vec2(900.0, 600.0)] {
        let mut h = harness_sized(Some(lathe()), Lang::En, size);
        h.run();
        command(&mut h, Command::StepTick);
        h.state_mut()
            .with(|f: &mut OnlineState, _| f.tab = OnlineTab::Panel);
        h.run();
        h.run();
        let labels: Vec<String> = h
            .state_mut()
            .with(|o: &mut OnlineState, cx| o.panel(cx))
            .items
            .iter()
            .map(|i| i.label_en.clone())
            .collect();
        let page = h.get_by_label("Panel").rect();
        for l in &labels {
            for n in h.get_all_by_label(l) {
                let r = n.rect();
                assert!(
                    r.max.x <= size.x + 0.5 && r.min.x >= page.min.x - 1.0,
                    "{l} at {r:?} in a {size:?} window"
                );
            }
        }
        // Every page: the tab row does not move.
        let tabs = |h: &Harness<'static, LadderApp>| h.get_by_label("Forces").rect();
        let first = tabs(&h);
        for tab in [
            OnlineTab::Cnc,
            OnlineTab::Watch,
            OnlineTab::Trace,
            OnlineTab::Machine,
            OnlineTab::Panel,
        ] {
            h.state_mut().with(|f: &mut OnlineState, _| f.tab = tab);
            h.run();
            assert_eq!(tabs(&h), first, "{tab:?} at {size:?}");
        }
    }
}

#[test]
fn the_signal_page_writes_and_forces_a_bit_and_writes_a_byte() {
    use ladder_studio::gui::online::OnlineTab;
    let mut h = harness(Some(il_project(RUNG)), Lang::En);
    h.run();
    command(&mut h, Command::StepTick);
    h.state_mut()
        .with(|f: &mut OnlineState, _| f.forces_confirmed = true);
    h.state_mut()
        .with(|f: &mut OnlineState, _| f.tab = OnlineTab::Signals);
    h.state_mut()
        .with(|f: &mut OnlineState, _| f.signals.from = 8);
    h.state_mut()
        .with(|f: &mut OnlineState, _| f.signals.to = 12);
    h.run();
    // X0010.2 starts the timer: a click writes it once.
    h.get_by_label("X0010.2").click();
    h.run();
    settle(&mut h);
    assert_eq!(value(&h, "X0010.2"), 1);
    assert!(
        h.state()
            .feature::<OnlineState>()
            .forced_addresses()
            .is_empty()
    );
    // With "a click forces" a click forces X0010.0 to the opposite of its value.
    h.get_by_label("A click forces or releases").click();
    h.run();
    h.get_by_label("X0010.0").click();
    h.run();
    settle(&mut h);
    ticks(&mut h, 1);
    let forced: Vec<String> = h
        .state()
        .feature::<OnlineState>()
        .forced_addresses()
        .iter()
        .map(|a| a.to_string())
        .collect();
    assert_eq!(forced, ["X0010.0"]);
    assert_eq!(value(&h, "X0010.0"), 1);
    // A whole byte typed and written.
    h.get_by_role_and_label(egui::accesskit::Role::TextInput, "X0011")
        .click();
    h.run();
    h.get_by_role_and_label(egui::accesskit::Role::TextInput, "X0011")
        .type_text("5");
    h.run();
    h.key_press(egui::Key::Enter);
    h.run();
    settle(&mut h);
    assert_eq!(value(&h, "X0011"), 5);
}

#[test]
fn prepared_values_are_written_in_one_tick_and_rows_show_symbols_units_and_presets() {
    use ladder_studio::gui::online::OnlineTab;
    let mut h = harness(Some(il_project(RUNG)), Lang::En);
    h.run();
    for a in ["X0010.0", "X0010.1", "T0000"] {
        h.state_mut()
            .with(|o: &mut OnlineState, cx| o.add_watch(cx, a))
            .unwrap();
    }
    command(&mut h, Command::StepTick);
    h.state_mut()
        .with(|f: &mut OnlineState, _| f.tab = OnlineTab::Watch);
    h.run();
    h.get_by_label_contains(" ms / 1000 ms");
    // Running as fast as it can: two separate writes would land ticks apart.
    h.state_mut()
        .with(|f: &mut OnlineState, _| f.speed = ladder_engine::runner::Speed::Max);
    command(&mut h, Command::Speed(ladder_engine::runner::Speed::Max));
    command(&mut h, Command::Run);
    h.state_mut().with(|f: &mut OnlineState, _| {
        f.watch.values = vec!["1".into(), "1".into(), String::new()]
    });
    h.run();
    h.get_by_label_contains("2 rows have a prepared value");
    h.get_by_label("Write prepared values").click();
    h.run();
    settle(&mut h);
    command(&mut h, Command::Stop);
    let s = h.state().feature::<OnlineState>().session.as_ref().unwrap();
    let layout = &s.running.layout;
    let off = layout.loc("X0010.0".parse().unwrap(), false).off;
    let newest = s.recorder().newest().unwrap();
    let rec = s.recorder();
    let (mut c0, mut c1) = (None, None);
    let mut changes = Vec::new();
    rec.changes_of(off, 1, newest, &mut changes);
    for (tick, v) in &changes {
        if v & 1 == 1 && c0.is_none() {
            c0 = Some(*tick);
        }
        if v & 2 == 2 && c1.is_none() {
            c1 = Some(*tick);
        }
    }
    assert!(
        c0.is_some() && c0 == c1,
        "both bits came on in the same tick: {changes:?}"
    );
}

#[test]
fn data_tables_show_running_values_edit_them_and_save_them_as_one_undo_step() {
    use ladder_studio::gui::tables::DataTab;
    // A D row in the file: D0010 = 5.
    let mut p = ladder_engine::il::import(RUNG).project.unwrap();
    p.data.d.push(ladder_engine::model::tables::DataRow::new(
        "D0010".parse().unwrap(),
        5,
    ));
    let path = tempfile_dir().join("d.ldp");
    ladder_engine::file::save(&p, &path).unwrap();
    let mut h = harness(Some(path), Lang::En);
    h.run();
    command(&mut h, Command::StepTick);
    h.state_mut().ask(Command::ShowView(View::Data));
    h.state_mut()
        .with(|f: &mut TableState, _| f.data_tab = DataTab::D);
    h.run();
    h.get_by_label("Running values (online)");
    h.get_by_label_contains("0 rows differ");
    // Typed while running: written on the machine, not into the file.
    let field = egui::accesskit::Role::TextInput;
    h.get_by_role_and_label(field, "D0010").click();
    h.run();
    h.get_by_role_and_label(field, "D0010").type_text("42");
    h.key_press(egui::Key::Enter);
    h.run();
    settle(&mut h);
    assert_eq!(value(&h, "D0010"), 42);
    let file_value =
        |h: &Harness<'static, LadderApp>| h.state().doc().unwrap().project().data.d[0].value;
    assert_eq!(file_value(&h), 5);
    h.get_by_label_contains("1 rows differ");
    h.get_by_label("Save running values into the project")
        .click();
    h.run();
    assert_eq!(file_value(&h), 42);
    command(&mut h, Command::Undo);
    assert_eq!(
        file_value(&h),
        5,
        "one undo step puts the file's values back"
    );
}

#[test]
fn the_online_window_can_stand_on_its_own_and_the_ladder_takes_the_width() {
    let mut h = harness(Some(lathe()), Lang::En);
    h.run();
    on_level2(&mut h);
    command(&mut h, Command::StepTick);
    h.run();
    let beside = h
        .state()
        .feature::<EditState>()
        .geometry
        .visible
        .unwrap()
        .width();
    command(&mut h, Command::DetachOnline);
    h.run();
    h.run();
    assert!(h.state().settings().online_window);
    // Headless there is no second native window: it stands as a window over the editor,
    // and the ladder has the whole width.
    let alone = h
        .state()
        .feature::<EditState>()
        .geometry
        .visible
        .unwrap()
        .width();
    assert!(alone > beside + 200.0, "{beside} → {alone}");
    h.get_by_label("Panel");
    command(&mut h, Command::DetachOnline);
    h.run();
    assert!(!h.state().settings().online_window);
}

#[test]
fn a_refusal_from_the_machine_is_in_the_ui_language() {
    let mut h = harness(Some(il_project(RUNG)), Lang::Zh);
    h.run();
    command(&mut h, Command::StepTick);
    h.state_mut().with(|o: &mut OnlineState, cx| {
        o.send_command(
            cx,
            ladder_engine::machine::MachineCommand::Device(
                0,
                ladder_engine::machine::DeviceAction::Reset,
            ),
        )
    });
    settle(&mut h);
    let out = output(&h);
    assert!(out.contains("没有运行机床模型"), "{out}");
    assert!(!out.contains("no machine model"), "{out}");
}
