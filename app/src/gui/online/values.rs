//! Writing values online: a double-click on a contact or coil toggles its bit once; on a
//! function box it opens the box's value window, where each address operand shows its value
//! and takes a new one, written once or forced.

use super::super::i18n::Msg;
use super::super::ladder_view::address_of;
use super::super::place::Cursor;
use super::super::theme;
use super::OnlineState;
use super::watch::{force_command, parse_value, write_command};
use crate::gui::context::Context;
use ladder_engine::machine::{MachineCommand, Target};
use ladder_engine::model::Cell;

/// The open value window: which box, and the text typed per operand.
#[derive(Clone, Debug, Default)]
pub struct ValueWindow {
    /// The box's cell.
    pub at: Option<Cursor>,
    /// Typed values, per operand.
    pub texts: Vec<String>,
}

impl OnlineState {
    /// Online double-click: toggles a bit (once), or opens a box's value window.
    pub fn operate_element(&mut self, cx: &mut Context<'_>, at: Cursor) {
        *cx.selection = None;
        *cx.cursor = at;
        let cell = cx
            .doc()
            .and_then(|d| d.project().ladder.cell_at(at).cloned());
        match cell {
            Some(Cell::Contact { .. } | Cell::Coil { .. }) if !self.scrubbing() => {
                self.execute_online(cx, super::super::command::Command::ToggleBit)
            }
            Some(Cell::Box { operands, .. }) => {
                self.values = ValueWindow {
                    at: Some(at),
                    texts: vec![String::new(); operands.len()],
                };
            }
            _ => {}
        }
    }

    /// The value window, when open.
    pub fn value_window_ui(&mut self, cx: &mut Context<'_>, ctx: &egui::Context) {
        let Some(at) = self.values.at else {
            return;
        };
        let lang = cx.settings.lang;
        let t = |m: Msg| m.text(lang);
        let (Some(doc), true) = (cx.doc(), self.is_online()) else {
            self.values = ValueWindow::default();
            return;
        };
        let p = doc.project();
        let Some(Cell::Box { op, operands }) = p.ladder.cell_at(at).cloned() else {
            self.values = ValueWindow::default();
            return;
        };
        let format = cx.settings.live_format;
        let scrubbing = self.scrubbing();
        let mut open = true;
        let mut commands = Vec::new();
        let rows: Vec<(String, Option<Target>, i64, bool)> = operands
            .iter()
            .enumerate()
            .map(|(i, o)| {
                let name = op.spec().operand(i).map_or("", |s| s.name).to_string();
                let a = address_of(p, o);
                let target = a.map(|a| Target {
                    address: a,
                    bytes: u32::from(a.area.element_bytes()).max(1),
                    explicit: false,
                });
                let value = target.map_or(0, |t| {
                    self.session
                        .as_ref()
                        .map_or(0, |s| s.source().value(t.address, t.bytes))
                });
                let forced = a.is_some_and(|a| self.is_forced(a));
                (format!("{name} {o}"), target, value, forced)
            })
            .collect();
        self.values.texts.resize(rows.len(), String::new());
        egui::Window::new(format!("{} — {}", op.name(), t(Msg::ValuesTitle)))
            .open(&mut open)
            .collapsible(false)
            .show(ctx, |ui| {
                egui::Grid::new("box-values").striped(true).show(ui, |ui| {
                    for (i, (name, target, value, forced)) in rows.iter().enumerate() {
                        ui.label(name);
                        let Some(target) = target else {
                            ui.label("—");
                            ui.end_row();
                            continue;
                        };
                        let shown = format.show(*value, target.bytes);
                        if *forced {
                            ui.colored_label(theme::FORCED, format!("{shown}  F"));
                        } else {
                            ui.monospace(shown);
                        }
                        let field = &mut self.values.texts[i];
                        ui.add_enabled(
                            !scrubbing,
                            egui::TextEdit::singleline(field)
                                .desired_width(80.0)
                                .hint_text(format.name()),
                        );
                        let parsed = parse_value(field, format);
                        let ok = !scrubbing && parsed.is_some();
                        if ui
                            .add_enabled(ok, egui::Button::new(t(Msg::WriteOnce)))
                            .clicked()
                            && let Some(v) = parsed
                        {
                            commands.push(write_command(*target, format, v));
                        }
                        if ui
                            .add_enabled(ok, egui::Button::new(t(Msg::ForceValue)))
                            .clicked()
                            && let Some(v) = parsed
                        {
                            commands.push(force_command(*target, format, v));
                        }
                        if ui
                            .add_enabled(*forced && !scrubbing, egui::Button::new(t(Msg::Release)))
                            .clicked()
                        {
                            commands.push(MachineCommand::Unforce(target.address));
                        }
                        ui.end_row();
                    }
                });
            });
        for c in commands {
            self.send_command(cx, c);
        }
        if !open {
            self.values = ValueWindow::default();
        }
    }
}
