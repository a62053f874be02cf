//! The online monitor, driven as a user drives it: run and step, force and release, the
//! watch table, online edit, the scan recorder and "why?", the machine panel and the CNC.
//! The machine runs on its own thread; the tests step it tick by tick and wait for the state
//! it publishes, so nothing depends on the speed of the machine the tests run on.

use crate::common::online::*;
use crate::common::*;
use ladder_engine::model::{Cell, CellRef, Edit, Operand};
use ladder_studio::gui::command::Command;
use ladder_studio::gui::editor::EditState;
use ladder_studio::gui::online::OnlineState;

#[test]
fn the_cursor_keys_force_an_input_and_release_it() {
    let mut h = harness(Some(il_project(RUNG)), Lang::En);
    h.run();
    // Asked once per run of the editor (gui_monitor.rs tests the question).
    h.state_mut()
        .with(|f: &mut OnlineState, _| f.forces_confirmed = true);
    on_level2(&mut h);
    command(&mut h, Command::StepTick);
    assert!(
        h.state().feature::<OnlineState>().is_online(),
        "a step goes online"
    );
    // Cursor on X0000.0 (network 1, row 1, column 1): Shift+F7 forces it to 1.
    click_cell(&mut h, 0, 0, 0);
    h.key_press_modifiers(egui::Modifiers::SHIFT, egui::Key::F7);
    settle(&mut h);
    ticks(&mut h, 1);
    assert_eq!(value(&h, "X0010.0"), 1);
    let forced = h.state().feature::<OnlineState>().forced_addresses();
    assert_eq!(forced.len(), 1, "{forced:?}");
    assert_eq!(forced[0].to_string(), "X0010.0");
    // The force list shows it with a release button.
    h.state_mut()
        .with(|f: &mut OnlineState, _| f.tab = ladder_studio::gui::online::OnlineTab::Forces);
    h.step();
    h.get_by_label("X0010.0");
    h.get_by_label("Release all").click();
    h.step();
    settle(&mut h);
    assert!(
        h.state()
            .feature::<OnlineState>()
            .forced_addresses()
            .is_empty(),
        "released"
    );
    assert_eq!(
        value(&h, "X0010.0"),
        1,
        "the last forced value stays until written"
    );
    // F7 toggles the bit once: it can be written again.
    h.key_press(egui::Key::F7);
    settle(&mut h);
    assert_eq!(value(&h, "X0010.0"), 0);
}

#[test]
fn the_watch_table_shows_a_timer_counting() {
    let mut h = harness(Some(il_project(RUNG)), Lang::En);
    h.run();
    // Asked once per run of the editor (gui_monitor.rs tests the question).
    h.state_mut()
        .with(|f: &mut OnlineState, _| f.forces_confirmed = true);
    h.state_mut()
        .with(|o: &mut OnlineState, cx| o.add_watch(cx, "T0000"))
        .unwrap();
    h.state_mut()
        .with(|o: &mut OnlineState, cx| o.add_watch(cx, "X0010.2"))
        .unwrap();
    command(&mut h, Command::StepTick);
    h.state_mut().with(|o: &mut OnlineState, cx| {
        o.send_command(
            cx,
            ladder_engine::machine::MachineCommand::Force("X0010.2".parse().unwrap(), 1),
        )
    });
    h.state_mut()
        .with(|f: &mut OnlineState, _| f.tab = ladder_studio::gui::online::OnlineTab::Watch);
    ticks(&mut h, 10);
    let first = value(&h, "T0000");
    ticks(&mut h, 10);
    let second = value(&h, "T0000");
    assert_eq!(second - first, 80, "10 ticks of 8 ms");
    h.step();
    h.get_by_role_and_label(egui::accesskit::Role::Label, "T0000");
    // The elapsed time with its unit and the preset TMRB runs it to.
    h.get_by_label(&format!("{second} ms / 1000 ms"));
}

fn set_cell(h: &mut Harness<'static, LadderApp>, network: usize, col: usize, cell: Cell) {
    let at = CellRef {
        block: 1,
        network,
        row: 0,
        col,
    };
    h.state_mut()
        .with_context(|cx| cx.apply(Edit::SetCell { at, cell }))
        .expect("the edit applies");
    h.step();
    settle(h);
}

#[test]
fn an_online_edit_is_swapped_in_without_resetting_a_running_timer() {
    let mut h = harness(Some(il_project(RUNG)), Lang::En);
    h.run();
    // Asked once per run of the editor (gui_monitor.rs tests the question).
    h.state_mut()
        .with(|f: &mut OnlineState, _| f.forces_confirmed = true);
    command(&mut h, Command::StepTick);
    h.state_mut().with(|o: &mut OnlineState, cx| {
        o.send_command(
            cx,
            ladder_engine::machine::MachineCommand::Force("X0002.0".parse().unwrap(), 0),
        )
    });
    // Start the timer: X0000.2 on.
    h.state_mut().with(|o: &mut OnlineState, cx| {
        o.send_command(
            cx,
            ladder_engine::machine::MachineCommand::Force("X0010.2".parse().unwrap(), 1),
        )
    });
    ticks(&mut h, 11);
    let before = value(&h, "T0000");
    assert_eq!(before, 80);
    // Edit network 1: X0000.1 becomes X0000.3.
    set_cell(
        &mut h,
        0,
        1,
        Cell::Contact {
            negated: false,
            operand: Operand::parse("X0010.3").unwrap(),
        },
    );
    assert!(output(&h).contains("The edit runs now"), "{}", output(&h));
    assert!(
        h.state()
            .feature::<OnlineState>()
            .session
            .as_ref()
            .unwrap()
            .drawing_runs(h.state().doc().unwrap().project())
    );
    ticks(&mut h, 1);
    assert_eq!(value(&h, "T0000"), before + 8, "the timer went on counting");
    h.get_by_label("Running program = drawing");
}

#[test]
fn an_edit_that_does_not_compile_is_refused_and_the_status_says_so() {
    let mut h = harness(Some(il_project(RUNG)), Lang::En);
    h.run();
    command(&mut h, Command::StepTick);
    set_cell(
        &mut h,
        0,
        1,
        Cell::Contact {
            negated: false,
            operand: Operand::parse("NO_SUCH_SYMBOL").unwrap(),
        },
    );
    let out = output(&h);
    assert!(
        out.contains("does not compile and was not swapped in"),
        "{out}"
    );
    assert!(
        out.contains("NO_SUCH_SYMBOL"),
        "the compile error is listed: {out}"
    );
    // The status bar names the first error, where it is.
    let status = "Running program ≠ drawing: 1 compile error(s); the first: LEVEL2:1:1:2: error:";
    h.get_by_label_contains(status);
    assert!(
        h.query_all_by_label_contains("NO_SUCH_SYMBOL").count() >= 2,
        "the error is named in the status bar as in the output window"
    );
    // The machine runs on with the old program.
    ticks(&mut h, 2);
    assert!(h.state().feature::<OnlineState>().is_online());
}

#[test]
fn scrubbing_back_shows_an_earlier_state_and_why_names_the_contact_that_broke_the_rung() {
    let mut h = harness(Some(il_project(RUNG)), Lang::En);
    h.run();
    command(&mut h, Command::StepTick);
    let write = |h: &mut Harness<'static, LadderApp>, a: &str, v: i64| {
        let t = ladder_studio::gui::online::watch::resolve(h.state().doc().unwrap().project(), a)
            .unwrap();
        h.state_mut().with(|o: &mut OnlineState, cx| {
            o.send_command(cx, ladder_engine::machine::MachineCommand::Write(t, v))
        });
    };
    write(&mut h, "X0010.0", 1);
    write(&mut h, "X0010.1", 1);
    ticks(&mut h, 5);
    assert_eq!(value(&h, "Y0010.0"), 1);
    let on_tick = h
        .state()
        .feature::<OnlineState>()
        .session
        .as_ref()
        .unwrap()
        .published
        .snapshot
        .ticks;
    write(&mut h, "X0010.1", 0);
    ticks(&mut h, 5);
    assert_eq!(value(&h, "Y0010.0"), 0);
    // Back to a tick where the coil was on: the view shows it, read-only.
    h.state_mut()
        .with(|f: &mut OnlineState, _| f.session.as_mut().unwrap().scrub_to(Some(on_tick)));
    h.step();
    assert_eq!(value(&h, "Y0010.0"), 1, "the recorded state");
    assert!(
        !h.state().enabled(Command::Contact),
        "no edits while replaying"
    );
    h.get_by_label("Replay (read-only)");
    command(&mut h, Command::LiveView);
    assert_eq!(value(&h, "Y0010.0"), 0);
    // Why is the coil off? X0000.1 broke the rung, and changed at the tick after `on_tick`.
    let width = h.state().doc().unwrap().project().ladder.width;
    h.state_mut().with_context(|cx| {
        *cx.cursor = CellRef {
            block: 1,
            network: 0,
            row: 0,
            col: width,
        }
    });
    command(&mut h, Command::Why);
    let out = output(&h);
    assert!(
        out.contains("X0010.1") && out.contains("broke the rung"),
        "{out}"
    );
    let why = h.state().feature::<OnlineState>().why.clone().unwrap();
    assert_eq!(why.cells, vec![(0, 1)]);
    let s = h.state().feature::<OnlineState>().session.as_ref().unwrap();
    assert_eq!(
        s.scrub,
        Some(on_tick + 1),
        "the timeline went to the change"
    );
}

#[test]
fn closing_the_project_or_the_window_while_running_stops_the_machine() {
    let mut h = harness(Some(il_project(RUNG)), Lang::En);
    h.run();
    command(&mut h, Command::Run);
    for _ in 0..5 {
        h.step();
        std::thread::sleep(std::time::Duration::from_millis(5));
    }
    assert!(h.state().feature::<OnlineState>().is_online());
    command(&mut h, Command::Close);
    assert!(
        !h.state().feature::<OnlineState>().is_online(),
        "the machine went with the project"
    );
    // Run again on a new project, then drop the whole app while running.
    command(&mut h, Command::New);
    drop(h);
}

#[test]
fn a_project_with_compile_errors_does_not_run_and_says_why() {
    let mut h = harness(Some(il_project(RUNG)), Lang::En);
    h.run();
    set_cell(
        &mut h,
        0,
        1,
        Cell::Contact {
            negated: false,
            operand: Operand::parse("NO_SUCH_SYMBOL").unwrap(),
        },
    );
    command(&mut h, Command::Run);
    assert!(!h.state().feature::<OnlineState>().is_online());
    assert!(
        output(&h).contains("compile errors and cannot run"),
        "{}",
        output(&h)
    );
}

/// Clicks a panel or CNC page button by its label.
fn click(h: &mut Harness<'static, LadderApp>, label: &str) {
    // A wide panel scrolls inside the online panel, as for a user.
    h.get_by_label(label).scroll_to_me();
    for _ in 0..30 {
        h.step();
    }
    h.get_by_label(label).click();
    h.step();
    settle(h);
}

#[test]
fn the_jog_key_of_the_panel_selects_jog_and_lights_its_lamp() {
    let mut h = harness(Some(lathe()), Lang::En);
    h.run();
    command(&mut h, Command::StepTick);
    h.state_mut()
        .with(|f: &mut OnlineState, _| f.tab = ladder_studio::gui::online::OnlineTab::Panel);
    ticks(&mut h, 2);
    assert_eq!(value(&h, "G0043"), 0, "power-on: MDI");
    click(&mut h, "JOG");
    ticks(&mut h, 12);
    assert_eq!(value(&h, "X0002.3"), 0, "the key is up again");
    assert_eq!(value(&h, "G0043"), 5, "MD4 + MD1: JOG");
    assert_eq!(value(&h, "Y0001.3"), 1, "the JOG lamp");
    assert!(
        h.state().feature::<OnlineState>().alarms.on.is_empty(),
        "a healthy machine"
    );
}

#[test]
fn an_m03_program_from_the_cnc_page_runs_the_spindle_coil_and_fin_comes_back() {
    let mut h = harness(Some(lathe()), Lang::En);
    h.run();
    command(&mut h, Command::StepTick);
    ticks(&mut h, 2);
    h.state_mut()
        .with(|f: &mut OnlineState, _| f.tab = ladder_studio::gui::online::OnlineTab::Cnc);
    h.state_mut()
        .with(|f: &mut OnlineState, _| f.cnc.program = "O0001; M03 S800; M30".into());
    h.step();
    click(&mut h, "Load program");
    h.state_mut()
        .with(|f: &mut OnlineState, _| f.tab = ladder_studio::gui::online::OnlineTab::Panel);
    h.step();
    click(&mut h, "AUTO");
    ticks(&mut h, 12);
    click(&mut h, "Cycle start");
    // The CNC starts when cycle start is let go; a click is held for 10 ticks.
    ticks(&mut h, 13);
    assert_eq!(value(&h, "F0007.0"), 1, "MF");
    assert_eq!(value(&h, "Y0000.0"), 1, "spindle CW");
    // The spindle coil is drawn energised in the ladder view.
    let (b, n, r) = {
        let p = h.state().doc().unwrap().project();
        let width = p.ladder.width;
        let mut at = None;
        for (bi, block) in p.ladder.blocks.iter().enumerate() {
            for (ni, net) in block.networks.iter().enumerate() {
                for (ri, row) in net.rows.iter().enumerate() {
                    if let Some(Cell::Coil { operand, .. }) = row.cells.get(width)
                        && operand.to_string() == "Y0000.0"
                    {
                        at = at.or(Some((bi, ni, ri)));
                    }
                }
            }
        }
        at.expect("the sample has a Y0000.0 coil")
    };
    h.state_mut().jump(CellRef {
        block: b,
        network: n,
        row: r,
        col: 0,
    });
    h.step();
    settle(&mut h);
    ticks(&mut h, 1);
    let view = h
        .state_mut()
        .with(|o: &mut OnlineState, cx| o.live_network_view(cx, b, n))
        .expect("on screen");
    let width = h.state().doc().unwrap().project().ladder.width;
    assert!(view.cells[r][width].power_in, "the coil is energised");
    // FIN comes back within the M code time (200 ms), and the CNC goes on to M30.
    ticks(&mut h, 40);
    assert_ne!(value(&h, "F0010:4"), 3, "M03 is done");
    let s = h.state().feature::<OnlineState>().session.as_ref().unwrap();
    let fin = s.running.layout.loc("G0004.3".parse().unwrap(), false).off;
    let mut changes = Vec::new();
    let newest = s.recorder().newest().unwrap();
    s.recorder().changes_of(fin, 0, newest, &mut changes);
    assert!(
        changes.iter().any(|(_, v)| v & 0b1000 != 0),
        "FIN (G4.3) was 1: {changes:?}"
    );
}

#[test]
fn no_sequence_of_run_stop_step_force_edit_undo_and_close_panics() {
    let mut h = harness(Some(il_project(RUNG)), Lang::En);
    h.run();
    let commands = [
        Command::Run,
        Command::Stop,
        Command::StepTick,
        Command::StepN,
        Command::PowerCycle,
        Command::ToggleBit,
        Command::ForceBit,
        Command::Unforce,
        Command::UnforceAll,
        Command::Why,
        Command::LiveView,
        Command::Undo,
        Command::Redo,
        Command::GoOffline,
        Command::Close,
        Command::New,
        Command::Speed(ladder_engine::runner::Speed::Max),
        Command::Speed(ladder_engine::runner::Speed::RealTime),
    ];
    // A fixed pseudo-random walk: the same sequence every run.
    let mut seed: u64 = 0x9e37_79b9_7f4a_7c15;
    for i in 0..300 {
        seed = seed
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        let pick = (seed >> 33) as usize;
        if i % 7 == 3 && h.state().doc().is_some() {
            // An edit, valid or not, where the cursor is.
            let operand = if pick.is_multiple_of(2) {
                "X0010.3"
            } else {
                "NO_SUCH"
            };
            let _ = h.state_mut().with_context(|cx| {
                cx.apply(Edit::SetCell {
                    at: CellRef {
                        block: 1,
                        network: 0,
                        row: 0,
                        col: 1,
                    },
                    cell: Cell::Contact {
                        negated: false,
                        operand: Operand::parse(operand).unwrap(),
                    },
                })
            });
        } else if i % 11 == 5 {
            let scrub = h
                .state()
                .feature::<OnlineState>()
                .session
                .as_ref()
                .and_then(|s| {
                    let r = s.recorder();
                    r.oldest()
                });
            h.state_mut().with(|o: &mut OnlineState, _| {
                if let Some(s) = o.session.as_mut() {
                    s.scrub_to(scrub);
                }
            });
        } else {
            let c = commands[pick % commands.len()];
            h.state_mut().ask(c);
        }
        h.step();
    }
    settle(&mut h);
    drop(h);
}

/// A double-click with frames between the presses, as a user's.
fn double_click_cell(h: &mut Harness<'static, LadderApp>, network: usize, row: usize, col: usize) {
    let p = h
        .state()
        .feature::<EditState>()
        .geometry
        .cell_center(network, row, col)
        .expect("the cell is on screen");
    h.hover_at(p);
    h.step();
    for pressed in [true, false, true, false] {
        h.event(egui::Event::PointerButton {
            pos: p,
            button: egui::PointerButton::Primary,
            pressed,
            modifiers: egui::Modifiers::NONE,
        });
        h.step();
    }
    settle(h);
}

#[test]
fn online_a_double_click_toggles_a_contact_and_writes_a_box_operand() {
    let path = il_project(RUNG);
    let mut h = Harness::builder()
        .with_size(egui::vec2(1920.0, 1000.0))
        .with_step_dt(1.0 / 60.0)
        .build_eframe(move |cc| {
            let mut app = LadderApp::from_creation(cc, Some(path));
            app.settings_mut().lang = Lang::En;
            app
        });
    h.run();
    on_level2(&mut h);
    command(&mut h, Command::StepTick);
    double_click_cell(&mut h, 0, 0, 0);
    assert_eq!(value(&h, "X0010.0"), 1, "the contact's bit was toggled");
    assert!(
        h.state().feature::<EditState>().function_dialog.is_none(),
        "online, no edit dialog"
    );
    let width = h.state().doc().unwrap().project().ladder.width;
    double_click_cell(&mut h, 1, 0, width);
    assert!(
        h.state().feature::<OnlineState>().values.at.is_some(),
        "the box's value window"
    );
    h.state_mut()
        .with(|f: &mut OnlineState, _| f.values.texts[0] = "500".into());
    h.step();
    // The first row's Write: T0000 (the preset is a constant and has none).
    h.get_all_by_label("Write").next().unwrap().click();
    h.step();
    settle(&mut h);
    assert_eq!(value(&h, "T0000"), 500, "written once");
}

#[test]
fn an_actuator_added_on_the_machine_page_answers_the_ladder_and_a_fault_raises_its_alarm() {
    use ladder_studio::gui::online::OnlineTab;
    // Y0010.0 clamps; X0011.0 is the clamp switch, which lights Y0011.0; if it has not
    // closed 1 s after clamping, A0000.0 (alarm 1001) comes on.
    let il = "LEVEL2\nNETWORK\nLDI X0012.0\nOUT Y0010.0\n\
NETWORK\nLD X0011.0\nOUT Y0011.0\n\
NETWORK\nLD Y0010.0\nANI X0011.0\nTMRB T0001 1000 R0001.0\n\
NETWORK\nLD R0001.0\nOUT A0000.0\n";
    let mut p = ladder_engine::il::import(il).project.expect("valid IL");
    p.messages.rows[0].number = Some(1001);
    p.messages.rows[0]
        .texts
        .insert("en".into(), "Clamp timeout".into());
    let path = tempfile_dir().join("machine.ldp");
    ladder_engine::file::save(&p, &path).unwrap();
    let mut h = harness(Some(path), Lang::En);
    h.run();
    // Offline: the Machine page adds an actuator and binds it.
    h.state_mut().ask(Command::MachineModel);
    h.run();
    assert_eq!(h.state().feature::<OnlineState>().tab, OnlineTab::Machine);
    h.state_mut()
        .with(|f: &mut OnlineState, _| f.machine.add_kind = 1);
    h.run();
    h.get_by_label("Add device").click();
    h.run();
    fill(&mut h, "advance output", "Y10.0");
    fill(&mut h, "advanced switch", "X0200.0");
    h.get_by_label_contains("out of range");
    fill(&mut h, "advanced switch", "X11.0");
    fill(&mut h, "travel time, ms", "400");
    h.get_by_label("Apply").click();
    h.run();
    let machine = h.state().doc().unwrap().project().machine.clone();
    assert_eq!(machine.devices.len(), 1, "{machine:?}");
    assert_eq!(machine.devices[0].name, "actuator");
    // One undoable change.
    h.state_mut().ask(Command::Undo);
    h.run();
    assert!(h.state().doc().unwrap().project().machine.is_empty());
    h.state_mut().ask(Command::Redo);
    h.run();
    assert_eq!(h.state().doc().unwrap().project().machine, machine);
    // Run: the cylinder travels 400 ms, then its switch closes and lights the contact.
    command(&mut h, Command::StepTick);
    ticks(&mut h, 20);
    assert_eq!(value(&h, "X0011.0"), 0, "still travelling");
    h.get_by_label_contains("advancing");
    ticks(&mut h, 40);
    assert_eq!(value(&h, "X0011.0"), 1, "the clamp switch");
    assert_eq!(value(&h, "Y0011.0"), 1);
    h.get_by_label("advanced");
    let level2 = h.state().doc().unwrap().project().ladder.blocks.len() - 1;
    h.state_mut().jump(CellRef {
        block: level2,
        network: 1,
        row: 0,
        col: 0,
    });
    h.step();
    settle(&mut h);
    ticks(&mut h, 1);
    let view = h
        .state_mut()
        .with(|o: &mut OnlineState, cx| o.live_network_view(cx, level2, 1))
        .expect("on screen");
    assert!(view.cells[0][0].power_out, "the X0011.0 contact is lit");
    assert!(h.state().feature::<OnlineState>().alarms.on.is_empty());
    // A stuck clamp switch: the ladder's timer raises its alarm 1 s later.
    h.get_by_label("Fault").click();
    h.run();
    h.get_by_label("fault: stuck at 0").click();
    settle(&mut h);
    ticks(&mut h, 130);
    assert_eq!(value(&h, "X0011.0"), 0);
    assert_eq!(value(&h, "A0000.0"), 1);
    h.get_by_label("Device faults: 1");
    h.state_mut()
        .with(|f: &mut OnlineState, _| f.tab = OnlineTab::Alarms);
    h.run();
    h.get_by_label("Clamp timeout");
    h.get_by_label("1001");
}

/// The lathe with one saved scenario, in a temporary folder.
fn lathe_with_scenario() -> PathBuf {
    let mut p = ladder_engine::file::load(&lathe()).unwrap();
    p.scenarios = vec![ladder_engine::scenario::Scenario {
        name: "lube-low".into(),
        note: "R0010 marked, R0500.0 held".into(),
        lines: vec!["set R0010 7".into(), "force R0500.0 1".into()],
    }];
    let path = tempfile_dir().join("scen.ldp");
    ladder_engine::file::save(&p, &path).unwrap();
    path
}

#[test]
fn the_scenarios_page_edits_the_list_as_undoable_changes() {
    let mut h = harness(Some(lathe_with_scenario()), Lang::En);
    h.run();
    command(&mut h, Command::ScenariosPage);
    h.run();
    h.get_by_label("lube-low");
    h.get_by_label_contains("Every line can be applied");
    fill(&mut h, "Name", "low-lube");
    h.key_press(egui::Key::Enter);
    h.run();
    let names = |h: &Harness<'static, LadderApp>| -> Vec<String> {
        let p = h.state().doc().unwrap().project();
        p.scenarios.iter().map(|s| s.name.clone()).collect()
    };
    assert_eq!(names(&h), ["low-lube"]);
    // A name a script line could not carry stays a draft, with the reason.
    fill(&mut h, "Name", "two words");
    h.key_press(egui::Key::Enter);
    h.run();
    h.get_by_label_contains("use at most 32 letters, digits");
    assert_eq!(names(&h), ["low-lube"]);
    h.get_by_label("New scenario").click();
    h.run();
    assert_eq!(names(&h), ["low-lube", "S1"]);
    command(&mut h, Command::Undo);
    command(&mut h, Command::Undo);
    h.run();
    assert_eq!(names(&h), ["lube-low"]);
}

#[test]
fn a_scenario_applies_from_the_plc_menu_and_its_release_restores_memory() {
    let mut h = harness(Some(lathe_with_scenario()), Lang::En);
    h.run();
    command(&mut h, Command::StepTick);
    let before = (value(&h, "R0010"), value(&h, "R0500.0"));
    assert_eq!(h.state().checked(Command::Scenario(0)), Some(false));
    command(&mut h, Command::Scenario(0));
    assert_eq!((value(&h, "R0010"), value(&h, "R0500.0")), (7, 1));
    assert_eq!(h.state().checked(Command::Scenario(0)), Some(true));
    assert!(
        output(&h).contains("Apply scenario `lube-low`"),
        "{}",
        output(&h)
    );
    command(&mut h, Command::Scenario(0));
    assert_eq!((value(&h, "R0010"), value(&h, "R0500.0")), before);
    assert_eq!(h.state().checked(Command::Scenario(0)), Some(false));
    assert!(
        h.state()
            .feature::<OnlineState>()
            .forced_addresses()
            .is_empty()
    );
}

#[test]
fn a_click_on_a_table_or_scenario_warning_opens_its_page_at_its_row() {
    let mut p = ladder_engine::file::load(&lathe()).unwrap();
    p.scenarios[1].lines.push("frce X0002.1 1".into());
    // Alarm 1009 on A0001.3, which nothing sets (W018).
    p.messages.rows[11].number = Some(1009);
    let path = tempfile_dir().join("warn.ldp");
    ladder_engine::file::save(&p, &path).unwrap();
    let mut h = harness(Some(path), Lang::En);
    h.run();
    h.key_press(egui::Key::F9);
    h.run();
    h.get_by_label_contains("scenario `station-3-broken`, line 2: `frce`")
        .click();
    h.run();
    h.run();
    assert_eq!(h.state().view(), ladder_studio::gui::place::View::Scenarios);
    // The page shows that scenario, with the line's reason (and the output window still has it).
    assert_eq!(
        h.state()
            .feature::<ladder_studio::gui::tables::TableState>()
            .scenario,
        1
    );
    assert_eq!(
        h.query_all_by_label_contains("2: `frce` cannot be part of a scenario")
            .count(),
        2
    );
    h.get_by_label_contains("A0001.3: alarm 1009 has a message")
        .click();
    h.run();
    h.run();
    assert_eq!(h.state().view(), ladder_studio::gui::place::View::Messages);
    let sheet = ladder_studio::gui::tables::Sheet::Messages;
    assert_eq!(
        h.state()
            .feature::<ladder_studio::gui::tables::TableState>()
            .selected
            .get(&sheet),
        Some(&11)
    );
}

#[test]
fn the_scan_engine_is_chosen_online_and_stays_through_an_online_edit() {
    use ladder_engine::vm::{Engine, native};
    let mut h = harness(Some(il_project(RUNG)), Lang::En);
    h.run();
    command(&mut h, Command::Run);
    let engine = |h: &Harness<'static, LadderApp>| {
        let online = h.state().feature::<OnlineState>();
        online.session.as_ref().and_then(|s| s.published.engine)
    };
    command(&mut h, Command::ScanEngine(Engine::Interpreter));
    ticks(&mut h, 3);
    assert_eq!(engine(&h), Some(Engine::Interpreter));
    assert_eq!(
        h.state().checked(Command::ScanEngine(Engine::Interpreter)),
        Some(true)
    );
    if !native::AVAILABLE {
        assert!(!h.state().enabled(Command::ScanEngine(Engine::Native)));
        return;
    }
    command(&mut h, Command::ScanEngine(Engine::Native));
    ticks(&mut h, 3);
    assert_eq!(engine(&h), Some(Engine::Native));
    assert_eq!(
        h.state().checked(Command::ScanEngine(Engine::Interpreter)),
        Some(false)
    );
    // An online edit swaps a new program in: it runs on the engine chosen.
    set_cell(
        &mut h,
        0,
        1,
        Cell::Contact {
            negated: true,
            operand: Operand::parse("X0010.0").unwrap(),
        },
    );
    ticks(&mut h, 3);
    let program = h
        .state()
        .feature::<OnlineState>()
        .session
        .as_ref()
        .map(|s| s.published.program);
    assert!(
        program > Some(0),
        "the edit swapped a program in: {program:?}"
    );
    assert_eq!(engine(&h), Some(Engine::Native));
}
