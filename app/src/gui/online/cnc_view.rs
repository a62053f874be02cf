//! The CNC screen widget: mode and run state, the NC program and MDI editors with the block
//! being executed marked, axis positions, spindle, the M/S/T handshake lamps and the active
//! alarms, as the simulated CNC reports them in its [`CncStatus`].
//!
//! A widget: [`cnc_ui`] takes the status (none while no machine runs) and the editor buffers,
//! which the caller owns so they outlive a machine, and returns [`CncEvent`]s that the
//! application sends to the CNC.

use super::macro_view::{MacroEdit, macro_ui};
use super::toolpath_view::{ToolpathView, toolpath_ui};
use crate::gui::i18n::{Lang, Msg};
use crate::gui::theme;
use egui::accesskit::Role;
use ladder_engine::cnc::{AXIS_NAMES, CncStatus, Mode, RunState};

/// What the user asked the CNC for.
#[derive(Clone, Debug, PartialEq)]
pub enum CncEvent {
    /// Load this text as the memory programs ("Load program"): `CncCommand::Program`.
    Program(String),
    /// Put this text in the MDI buffer: `CncCommand::Mdi`.
    Mdi(String),
    /// The CNC's RESET key: `CncCommand::Reset`.
    Reset,
    /// The operator panel's Cycle start key, pressed and let go.
    CycleStart,
    /// The operator panel's Feed hold key, pressed and let go.
    FeedHold,
    /// A macro variable typed into the table: `CncCommand::Macro`.
    Macro {
        /// Variable number.
        number: u16,
        /// Its value, `None` for vacant.
        value: Option<f64>,
    },
}

/// The editor buffers of the CNC screen, owned by the caller.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct CncTexts {
    /// The NC program text (one or more `O` programs).
    pub program: String,
    /// The MDI text.
    pub mdi: String,
    /// Scroll the program listing to this line at the next frame (a toolpath click).
    pub jump: Option<usize>,
    /// The macro-variable table's group and the value being typed.
    pub macros: MacroEdit,
    /// What the last "Send MDI" did, shown under the MDI editor.
    pub mdi_sent: Option<String>,
    /// The strobe lamps held lit: the strobe counts last seen and until when each lamp
    /// stays lit (UI time, s), so a strobe of one exchange is seen for 200 ms.
    pub held: ([u64; 4], [f64; 4]),
}

/// How long a strobe lamp stays lit after its strobe rose, at least.
pub const LAMP_HOLD_S: f64 = 0.2;

/// The name of a mode in the UI language.
pub fn mode_text(mode: Mode, lang: Lang) -> &'static str {
    let m = match mode {
        Mode::Edit => Msg::CncModeEdit,
        Mode::Mem => Msg::CncModeMem,
        Mode::Mdi => Msg::CncModeMdi,
        Mode::Handle => Msg::CncModeHandle,
        Mode::Jog => Msg::CncModeJog,
        Mode::Dnc => Msg::CncModeDnc,
        Mode::Ref => Msg::CncModeRef,
    };
    m.text(lang)
}

/// The name of a run state in the UI language.
pub fn run_text(run: RunState, lang: Lang) -> &'static str {
    let m = match run {
        RunState::Idle => Msg::CncRunIdle,
        RunState::Run => Msg::CncRunRun,
        RunState::Hold => Msg::CncRunHold,
        RunState::Stop => Msg::CncRunStop,
    };
    m.text(lang)
}

/// A position in increments (0.001 mm) as millimetres with three decimals.
pub fn mm_text(increments: i64) -> String {
    let sign = if increments < 0 { "-" } else { "" };
    let a = increments.unsigned_abs();
    format!("{sign}{}.{:03}", a / 1000, a % 1000)
}

/// Draws the CNC screen and returns what the user asked for. `alarm_text` gives an alarm
/// number's text in the UI language.
pub fn cnc_ui(
    ui: &mut egui::Ui,
    status: Option<&CncStatus>,
    texts: &mut CncTexts,
    view: &mut ToolpathView,
    lang: Lang,
    alarm_text: &dyn Fn(u16) -> String,
) -> Vec<CncEvent> {
    let t = |m: Msg| m.text(lang);
    let mut events = Vec::new();
    let mut jump = None;
    // The page scrolls when the panel is short: nothing of it is out of reach.
    egui::ScrollArea::vertical()
        .id_salt("cnc-page")
        .auto_shrink(false)
        .show(ui, |ui| {
            match status {
                None => {
                    ui.label(t(Msg::CncNotRunning));
                }
                Some(s) => {
                    status_ui(ui, s, &mut texts.held, lang, alarm_text);
                    ui.horizontal(|ui| {
                        if ui.button(t(Msg::CncCycleStart)).clicked() {
                            events.push(CncEvent::CycleStart);
                        }
                        if ui.button(t(Msg::CncFeedHold)).clicked() {
                            events.push(CncEvent::FeedHold);
                        }
                        if ui.button(t(Msg::CncReset)).clicked() {
                            events.push(CncEvent::Reset);
                        }
                    });
                    let mut typed = Vec::new();
                    macro_ui(ui, s, &mut texts.macros, lang, &mut typed);
                    events.extend(
                        typed
                            .into_iter()
                            .map(|(number, value)| CncEvent::Macro { number, value }),
                    );
                    view.update(s);
                }
            }
            ui.separator();
            let path = status.filter(|s| s.toolpath.is_some());
            match path {
                // Wide enough: the editors on the left, the toolpath on the right.
                Some(s) if ui.available_width() >= 820.0 => {
                    ui.columns(2, |cols| {
                        editors_ui(&mut cols[0], status, texts, view.picked, lang, &mut events);
                        jump = toolpath_ui(&mut cols[1], s, view, lang, 420.0);
                    });
                }
                // Narrow: the toolpath first, under the status, then the editors.
                Some(s) => {
                    jump = toolpath_ui(ui, s, view, lang, 260.0);
                    ui.separator();
                    editors_ui(ui, status, texts, view.picked, lang, &mut events);
                }
                None => editors_ui(ui, status, texts, None, lang, &mut events),
            }
        });
    if let Some(line) = jump {
        // Scroll the listing to the picked block at the next frame.
        texts.jump = Some(line);
        ui.ctx().request_repaint();
    }
    events
}

/// The program and MDI editors with their buttons.
fn editors_ui(
    ui: &mut egui::Ui,
    status: Option<&CncStatus>,
    texts: &mut CncTexts,
    picked: Option<usize>,
    lang: Lang,
    events: &mut Vec<CncEvent>,
) {
    let t = |m: Msg| m.text(lang);
    // The block being executed is in the program or in the MDI buffer.
    let program_line = status.filter(|s| !s.line_in_mdi).and_then(|s| s.line);
    let mdi_line = status.filter(|s| s.line_in_mdi).and_then(|s| s.line);
    let heading = ui.horizontal(|ui| {
        let heading = ui.strong(t(Msg::CncProgram));
        if ui.button(t(Msg::CncLoadProgram)).clicked() {
            events.push(CncEvent::Program(texts.program.clone()));
        }
        if let Some(line) = program_line {
            ui.label(format!("{} {line}", t(Msg::CncCurrentLine)));
        }
        if let Some(line) = picked {
            let text = texts.program.split('\n').nth(line - 1).unwrap_or("").trim();
            ui.colored_label(
                theme::TOOLPATH_PICKED,
                format!("{} {line}: {text}", t(Msg::CncPickedLine)),
            );
        }
        heading.id
    });
    let jump = texts.jump.take();
    nc_editor(
        ui,
        "cnc-program",
        &mut texts.program,
        Marks {
            current: program_line,
            picked,
            jump,
        },
        12,
        heading.inner,
    );
    let heading = ui.horizontal(|ui| {
        let heading = ui.strong(t(Msg::CncMdi));
        if ui.button(t(Msg::CncSendMdi)).clicked() {
            events.push(CncEvent::Mdi(texts.mdi.clone()));
        }
        heading.id
    });
    let marks = Marks {
        current: mdi_line,
        picked: None,
        jump: None,
    };
    nc_editor(ui, "cnc-mdi", &mut texts.mdi, marks, 3, heading.inner);
    if let Some(sent) = &texts.mdi_sent {
        ui.colored_label(theme::OK, sent);
    }
}

/// The lines an NC editor marks.
#[derive(Clone, Copy, Debug, Default)]
struct Marks {
    /// The executing block.
    current: Option<usize>,
    /// The block picked on the toolpath.
    picked: Option<usize>,
    /// Scroll to this line now.
    jump: Option<usize>,
}

/// Mode, state, positions, spindle, M/S/T and alarms.
fn status_ui(
    ui: &mut egui::Ui,
    s: &CncStatus,
    held: &mut ([u64; 4], [f64; 4]),
    lang: Lang,
    alarm_text: &dyn Fn(u16) -> String,
) {
    let t = |m: Msg| m.text(lang);
    ui.horizontal(|ui| {
        ui.label(t(Msg::CncMode));
        ui.strong(mode_text(s.mode, lang));
        ui.separator();
        ui.label(t(Msg::CncState));
        ui.strong(run_text(s.run, lang));
        ui.separator();
        ui.label(t(Msg::CncProgramNo));
        ui.monospace(format!("O{:04}", s.program));
        ui.label(t(Msg::CncBlockNo));
        ui.monospace(format!("N{:04}", s.block));
    });
    egui::Grid::new("cnc-positions")
        .striped(true)
        .num_columns(3)
        .show(ui, |ui| {
            for m in [Msg::CncAxis, Msg::CncMachinePos, Msg::CncAbsolutePos] {
                ui.strong(t(m));
            }
            ui.end_row();
            let axes = AXIS_NAMES.iter().zip(s.machine.iter().zip(&s.absolute));
            for (name, (machine, absolute)) in axes.take(s.axes) {
                ui.monospace(*name);
                ui.monospace(format!("{:>11}", mm_text(*machine)));
                ui.monospace(format!("{:>11}", mm_text(*absolute)));
                ui.end_row();
            }
        });
    ui.horizontal(|ui| {
        ui.label(t(Msg::CncSpindle));
        ui.monospace(format!("{:>5}", s.spindle));
        ui.label(t(Msg::CncRpm));
    });
    let m = &s.mst;
    let lit = hold_lamps(ui, m, held);
    ui.horizontal_wrapped(|ui| {
        // The codes in effect (the signals fall with their strobes; the screen keeps them),
        // each strobe lamp with how many times it rose.
        ui.label(t(Msg::CncMCode));
        ui.monospace(format!("{:02}", m.last[0]));
        lamp(
            ui,
            &format!("{} ×{}", t(Msg::CncStrobeMf), m.strobes[0]),
            lit[0],
        );
        ui.separator();
        ui.label(t(Msg::CncSCode));
        ui.monospace(format!("{}", m.last[1]));
        lamp(
            ui,
            &format!("{} ×{}", t(Msg::CncStrobeSf), m.strobes[1]),
            lit[1],
        );
        ui.separator();
        ui.label(t(Msg::CncTCode));
        ui.monospace(format!("{:04}", m.last[2]));
        lamp(
            ui,
            &format!("{} ×{}", t(Msg::CncStrobeTf), m.strobes[2]),
            lit[2],
        );
        ui.separator();
        lamp(ui, &format!("{} ×{}", t(Msg::CncFin), m.strobes[3]), lit[3]);
        lamp(ui, t(Msg::CncDen), m.den);
    });
    ui.horizontal(|ui| {
        ui.strong(t(Msg::CncAlarms));
        if s.alarms.is_empty() {
            ui.label(t(Msg::CncNoAlarm));
        }
    });
    for &n in &s.alarms {
        ui.horizontal(|ui| {
            ui.colored_label(
                theme::ERROR,
                egui::RichText::new(format!("{n:04}")).monospace(),
            );
            ui.colored_label(theme::ERROR, alarm_text(n));
        });
    }
    if let Some(m) = &s.stop_message {
        // `#3006 = n (MESSAGE)` stopped the program: cycle start goes on.
        ui.colored_label(theme::CAUTION, format!("{}: {m}", t(Msg::CncStopMessage)));
    }
}

/// MF, SF, TF and FIN as lamps a person can see: lit while the signal is, and for at least
/// [`LAMP_HOLD_S`] after each rise (counted by the CNC, so a rise between two frames counts).
fn hold_lamps(
    ui: &egui::Ui,
    m: &ladder_engine::cnc::MstStatus,
    held: &mut ([u64; 4], [f64; 4]),
) -> [bool; 4] {
    let now = ui.input(|i| i.time);
    let on = [m.mf, m.sf, m.tf, m.fin];
    let mut lit = [false; 4];
    for k in 0..4 {
        if m.strobes[k] != held.0[k] {
            held.0[k] = m.strobes[k];
            held.1[k] = now + LAMP_HOLD_S;
        }
        let holding = now < held.1[k];
        if holding {
            // Nothing from the machine may come to put it out: ask for that frame.
            ui.ctx()
                .request_repaint_after(std::time::Duration::from_secs_f64(held.1[k] - now));
        }
        lit[k] = on[k] || holding;
    }
    lit
}

/// A signal lamp with its name: a small circle, lit while the signal is 1. It reports itself
/// toggled while lit, so it can be read without looking at colours.
fn lamp(ui: &mut egui::Ui, name: &str, on: bool) {
    let height = ui.text_style_height(&egui::TextStyle::Body);
    let galley = ui.painter().layout_no_wrap(
        name.to_string(),
        egui::TextStyle::Body.resolve(ui.style()),
        ui.visuals().text_color(),
    );
    let size = egui::vec2(height + 4.0 + galley.size().x, height);
    let (rect, resp) = ui.allocate_exact_size(size, egui::Sense::hover());
    let r = height * 0.35;
    let centre = egui::pos2(rect.left() + height / 2.0, rect.center().y);
    let fill = if on {
        theme::CNC_LAMP_ON
    } else {
        theme::PANEL_DARK
    };
    ui.painter()
        .circle(centre, r, fill, egui::Stroke::new(1.0, theme::PANEL_RIM));
    let text_pos = egui::pos2(
        rect.left() + height + 4.0,
        rect.center().y - galley.size().y / 2.0,
    );
    ui.painter()
        .galley(text_pos, galley, ui.visuals().text_color());
    resp.widget_info(|| egui::WidgetInfo::selected(Role::Status, true, on, name));
}

/// The NC editors' inner margin.
const MARGIN: egui::Vec2 = egui::vec2(4.0, 2.0);

/// A monospace NC editor with a line-number gutter; the executing line is marked in the
/// gutter (`>`) and highlighted in the text.
fn nc_editor(
    ui: &mut egui::Ui,
    id: &str,
    text: &mut String,
    marks: Marks,
    rows: usize,
    label: egui::Id,
) {
    let current = marks.current;
    let font = egui::TextStyle::Monospace.resolve(ui.style());
    let colour = ui.visuals().text_color();
    let lines = text.split('\n').count().max(rows);
    let gutter: String = (1..=lines)
        .map(|n| {
            let mark = if Some(n) == current { '>' } else { ' ' };
            format!("{mark}{n:>4}")
        })
        .collect::<Vec<_>>()
        .join("\n");
    let mut layouter = |ui: &egui::Ui, buf: &dyn egui::TextBuffer, wrap: f32| {
        let mut job = egui::text::LayoutJob::default();
        for (k, line) in buf.as_str().split_inclusive('\n').enumerate() {
            let mut format = egui::TextFormat::simple(font.clone(), colour);
            if Some(k + 1) == current {
                format.background = theme::CNC_CURRENT_LINE;
                format.color = theme::INK;
            } else if Some(k + 1) == marks.picked {
                format.background = theme::CNC_PICKED_LINE;
                format.color = theme::INK;
            }
            job.append(line, 0.0, format);
        }
        // A listing does not wrap: a long comment scrolls sideways, and the gutter's numbers
        // stay on their lines.
        let _ = wrap;
        job.wrap.max_width = f32::INFINITY;
        ui.fonts_mut(|f| f.layout_job(job))
    };
    let row = ui.text_style_height(&egui::TextStyle::Monospace);
    // The editor fills the visible width at least (the gutter takes about six characters).
    let width = ui.available_width() - 7.0 * ui.fonts_mut(|f| f.glyph_width(&font, '0'));
    let mut area = egui::ScrollArea::both()
        .id_salt(id)
        .max_height(row * (rows as f32 + 1.0));
    if let Some(line) = marks.jump {
        area = area.vertical_scroll_offset(row * line.saturating_sub(3) as f32);
    }
    area.show(ui, |ui| {
        ui.horizontal_top(|ui| {
            // The gutter's top margin is the editor's, so the numbers stay on their rows.
            egui::Frame::NONE
                .inner_margin(egui::Margin::symmetric(0, MARGIN.y as i8))
                .show(ui, |ui| {
                    ui.add(
                        egui::Label::new(egui::RichText::new(gutter).monospace().weak())
                            .selectable(false),
                    );
                });
            ui.add(
                egui::TextEdit::multiline(text)
                    .id_salt(id)
                    .code_editor()
                    .margin(MARGIN)
                    .desired_rows(rows)
                    .desired_width(width)
                    .layouter(&mut layouter),
            )
            .labelled_by(label);
        });
    });
}

#[cfg(test)]
mod tests {
    use super::*;
    use egui::accesskit::Toggled;
    use egui_kittest::Harness;
    use egui_kittest::kittest::{NodeT, Queryable};
    use ladder_engine::cnc::MstStatus;

    type Shown = (Option<CncStatus>, CncTexts, ToolpathView, Vec<CncEvent>);

    fn harness(status: Option<CncStatus>) -> Harness<'static, Shown> {
        let mut h = Harness::builder()
            .with_size(egui::vec2(900.0, 800.0))
            .build_ui_state(
                |ui, (status, texts, view, events): &mut Shown| {
                    let alarm = |n: u16| format!("alarm text {n}");
                    let e = cnc_ui(ui, status.as_ref(), texts, view, Lang::En, &alarm);
                    events.extend(e);
                },
                (
                    status,
                    CncTexts::default(),
                    ToolpathView::default(),
                    Vec::new(),
                ),
            );
        h.run();
        h
    }

    #[test]
    fn the_toolpath_is_drawn_and_a_click_on_it_picks_its_block() {
        use ladder_engine::cnc::SimCnc;
        use ladder_engine::cnc::command::CncCommand;
        let mut cnc = SimCnc::new(
            ladder_engine::ProfileId::Gsk988ta,
            &ladder_engine::model::tables::MessageTable::default(),
        );
        let program = "O1\nG01 Z-100 F500\nG00 X10\nG00 X-10\nM30";
        cnc.apply(&CncCommand::Program(program.into())).unwrap();
        let status = cnc.status();
        assert!(status.toolpath.is_some());
        let mut h = harness(Some(status));
        h.state_mut().1.program = program.into();
        h.run();
        h.get_by_label_contains("4 blocks");
        // The cut along Z at X0 runs through the middle of the fitted plot (X from -10 to 10).
        let centre = h.get_by_label_contains("Toolpath plot").rect().center();
        h.event(egui::Event::PointerMoved(centre));
        h.run();
        for pressed in [true, false] {
            h.event(egui::Event::PointerButton {
                pos: centre,
                button: egui::PointerButton::Primary,
                pressed,
                modifiers: egui::Modifiers::default(),
            });
        }
        h.run();
        h.get_by_label_contains("Picked block: line 2: G01 Z-100 F500");
        assert_eq!(h.state().2.picked, Some(2));
    }

    #[test]
    fn load_program_sends_the_text_typed() {
        let mut h = harness(None);
        h.get_by_label_contains("The CNC runs with the PLC");
        fn editor<'h>(h: &'h Harness<'static, Shown>) -> egui_kittest::Node<'h> {
            h.get_by_role_and_label(Role::MultilineTextInput, "NC program")
        }
        editor(&h).click();
        h.run();
        editor(&h).type_text("O0001\nG00 X10\nM30");
        h.run();
        h.get_by_label("Load program").click();
        h.run();
        assert_eq!(
            h.state().3,
            [CncEvent::Program("O0001\nG00 X10\nM30".into())]
        );
        h.get_by_label("Send MDI").click();
        h.run();
        assert_eq!(h.state().3[1], CncEvent::Mdi(String::new()));
        assert!(h.query_by_label("RESET").is_none(), "no CNC to reset");
    }

    #[test]
    fn the_status_shows_alarms_positions_and_lamps() {
        let mut status = CncStatus {
            mode: Mode::Mem,
            run: RunState::Run,
            axes: 2,
            alarms: vec![950, 1001],
            spindle: 800,
            mst: MstStatus {
                m: 3,
                mf: true,
                ..MstStatus::default()
            },
            line: Some(2),
            ..CncStatus::default()
        };
        status.machine[0] = 12_345;
        status.absolute[1] = -2_560;
        let mut h = harness(Some(status));
        h.get_by_label("0950");
        h.get_by_label("alarm text 950");
        h.get_by_label("1001");
        h.get_by_label("AUTO");
        h.get_by_label("Running");
        h.get_by_label_contains("12.345");
        h.get_by_label_contains("-2.560");
        h.get_by_label_contains("Current block: line 2");
        let lamp = |h: &Harness<'static, Shown>, name: &str| {
            h.get_by_role_and_label(Role::Status, name)
                .accesskit_node()
                .toggled()
        };
        assert_eq!(lamp(&h, "MF ×0"), Some(Toggled::True));
        assert_eq!(lamp(&h, "FIN ×0"), Some(Toggled::False));
        h.get_by_label("RESET").click();
        h.run();
        h.get_by_label("Cycle start").click();
        h.run();
        h.get_by_label("Feed hold").click();
        h.run();
        assert_eq!(
            h.state().3,
            [CncEvent::Reset, CncEvent::CycleStart, CncEvent::FeedHold]
        );
    }

    #[test]
    fn a_strobe_shorter_than_a_frame_lights_its_lamp_for_200_ms_and_is_counted() {
        let mut h = harness(Some(CncStatus::default()));
        let status = CncStatus {
            mst: MstStatus {
                m: 0,
                mf: false,
                last: [8, 0, 0],
                strobes: [1, 0, 0, 1],
                ..MstStatus::default()
            },
            ..CncStatus::default()
        };
        h.state_mut().0 = Some(status);
        h.step();
        let lamp = |h: &Harness<'static, Shown>, name: &str| {
            h.get_by_role_and_label(Role::Status, name)
                .accesskit_node()
                .toggled()
        };
        // MF rose and fell between two frames: the count says so and the lamp is lit.
        assert_eq!(lamp(&h, "MF ×1"), Some(Toggled::True));
        assert_eq!(lamp(&h, "SF ×0"), Some(Toggled::False));
        h.get_by_label("08");
        // 0.3 s of frames later it is out.
        for _ in 0..20 {
            h.step();
        }
        assert_eq!(lamp(&h, "MF ×1"), Some(Toggled::False));
    }

    #[test]
    fn a_macro_variable_is_typed_in_while_stopped_and_read_only_while_running() {
        use ladder_engine::cnc::macro_b::{LOCALS, MacroTable};
        let mut table = MacroTable {
            level: 1,
            locals: [None; LOCALS],
            commons: [None; 100],
            kept: vec![None; 500],
        };
        table.locals[0] = Some(2.5);
        table.commons[1] = Some(-3.0);
        let status = CncStatus {
            run: RunState::Stop,
            macros: Some(std::sync::Arc::new(table)),
            ..CncStatus::default()
        };
        let mut h = harness(Some(status));
        h.get_by_label("Macro variables").click();
        h.run();
        h.get_by_label("Locals #1–#33, call level 1");
        h.get_by_label("#1");
        h.get_by_label("2.5").click();
        h.run();
        // The value is selected when the field opens: typing replaces it.
        h.get_by_role_and_label(Role::TextInput, "#1")
            .type_text("7.25");
        h.run();
        h.key_press(egui::Key::Enter);
        h.run();
        assert_eq!(
            h.state().3,
            [CncEvent::Macro {
                number: 1,
                value: Some(7.25)
            }]
        );
        // A text that is neither a number nor vacant is refused with the variable named.
        h.get_by_label("#100–#199").click();
        h.run();
        h.get_by_label("-3").click();
        h.run();
        h.get_by_role_and_label(Role::TextInput, "#101")
            .type_text("x");
        h.run();
        h.key_press(egui::Key::Enter);
        h.run();
        assert_eq!(h.state().3.len(), 1);
        h.get_by_label_contains("#101: neither a number nor vacant");
        // While the program runs the values are labels, not buttons.
        h.state_mut().0.as_mut().unwrap().run = RunState::Run;
        h.run();
        h.get_by_label("The program runs: read only");
        assert!(h.query_by_role_and_label(Role::Button, "-3").is_none());
        // A #3006 stop shows its message until cycle start.
        h.state_mut().0.as_mut().unwrap().stop_message = Some("TURN THE PART OVER".into());
        h.run();
        h.get_by_label("Program stopped (cycle start goes on): TURN THE PART OVER");
    }

    #[test]
    fn increments_read_as_millimetres_with_three_decimals() {
        assert_eq!(mm_text(0), "0.000");
        assert_eq!(mm_text(12_345), "12.345");
        assert_eq!(mm_text(-5), "-0.005");
        assert_eq!(mm_text(-2_560), "-2.560");
    }
}
