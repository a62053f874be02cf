//! The PLC signal page, as a CNC's diagnosis screen shows the PLC: an area (X, Y, F, G, R, A,
//! K, T, C, D, DT, DC) address by address within a range — bit areas a byte a row with its
//! eight bits, value areas a value a row — every bit and byte writable or forceable, and the
//! symbol and comment on hover. Every action goes to the machine through the one door
//! ([`OnlineState::send_command`](super::OnlineState::send_command)).

use super::super::i18n::Msg;
use super::super::theme;
use super::OnlineState;
use crate::gui::context::Context;
use ladder_engine::machine::{MachineCommand, Target};
use ladder_engine::{Address, Area};

/// The page's own state.
#[derive(Clone, Debug)]
pub struct SignalPage {
    /// The area shown.
    pub area: Area,
    /// The first address number shown.
    pub from: u16,
    /// The last address number shown.
    pub to: u16,
    /// A click on a bit forces it (or releases its force) instead of writing it once.
    pub click_forces: bool,
    /// Values being typed, by address.
    pub typed: std::collections::BTreeMap<Address, String>,
}

impl Default for SignalPage {
    fn default() -> Self {
        SignalPage {
            area: Area::X,
            from: 0,
            to: 31,
            click_forces: false,
            typed: Default::default(),
        }
    }
}

/// What a row asked for.
enum Act {
    Invert(Address),
    ToggleForce(Address),
    Write(Address, i64),
    Force(Address, i64),
}

impl OnlineState {
    /// The signal page.
    pub(super) fn signals_ui(&mut self, cx: &mut Context<'_>, ui: &mut egui::Ui) {
        let lang = cx.settings.lang;
        let t = |m: Msg| m.text(lang);
        let Some(doc) = cx.doc() else { return };
        let profile = doc.project().profile();
        let page = &mut self.signals;
        ui.horizontal_wrapped(|ui| {
            let name = ui.label(t(Msg::SignalArea)).id;
            egui::ComboBox::from_id_salt("signal-area")
                .selected_text(page.area.letters())
                .show_ui(ui, |ui| {
                    // Every area with memory (labels and subprograms have none), in table order.
                    for a in Area::ALL.into_iter().filter(|a| a.element_bytes() > 0) {
                        if ui
                            .selectable_value(&mut page.area, a, a.letters())
                            .changed()
                        {
                            let (lo, _) = profile.range(a);
                            page.from = lo;
                            page.to = lo.saturating_add(31);
                            page.typed.clear();
                        }
                    }
                })
                .response
                .labelled_by(name);
            let (lo, hi) = profile.range(page.area);
            let from = ui.label(t(Msg::SignalFrom)).id;
            ui.add(egui::DragValue::new(&mut page.from).range(lo..=hi))
                .labelled_by(from);
            let to = ui.label(t(Msg::SignalTo)).id;
            ui.add(egui::DragValue::new(&mut page.to).range(lo..=hi))
                .labelled_by(to);
            ui.checkbox(&mut page.click_forces, t(Msg::SignalClickForces));
        });
        ui.weak(t(Msg::SignalHint));
        let (lo, hi) = profile.range(page.area);
        let from = page.from.clamp(lo, hi);
        let to = page.to.clamp(lo, hi).max(from);
        let area = page.area;
        let mut acts = Vec::new();
        let numbers: Vec<u16> = (from..=to).collect();
        let row_height = ui.spacing().interact_size.y + 4.0;
        egui::ScrollArea::vertical()
            .id_salt("signal-rows")
            .auto_shrink([false, true])
            .show_rows(ui, row_height, numbers.len(), |ui, rows| {
                egui::Grid::new("signal-grid")
                    .striped(true)
                    .min_row_height(row_height - 4.0)
                    .show(ui, |ui| {
                        for &n in &numbers[rows] {
                            self.signal_row(cx, ui, area, n, &mut acts);
                            ui.end_row();
                        }
                    });
            });
        for act in acts {
            self.send_command(
                cx,
                match act {
                    Act::Invert(a) => MachineCommand::Invert(a),
                    Act::ToggleForce(a) => MachineCommand::ToggleForce(a),
                    Act::Write(a, v) => MachineCommand::Write(Target::whole(a), v),
                    Act::Force(a, v) => MachineCommand::Force(a, v),
                },
            );
        }
    }

    /// One address: its name, value and bits (bit areas) or value field (value areas).
    fn signal_row(
        &mut self,
        cx: &mut Context<'_>,
        ui: &mut egui::Ui,
        area: Area,
        n: u16,
        acts: &mut Vec<Act>,
    ) {
        let lang = cx.settings.lang;
        let whole = Address {
            area,
            number: n,
            bit: None,
        };
        let value = self.session.as_ref().map_or(0, |s| {
            s.source().value(whole, u32::from(area.element_bytes()))
        });
        let tip = self.describe(cx, whole);
        let name = ui.monospace(whole.to_string()).on_hover_text(tip).id;
        if area.has_bits() {
            ui.monospace(format!("{:02X}", value as u8));
            ui.horizontal(|ui| {
                for b in (0..8u8).rev() {
                    let a = Address {
                        bit: Some(b),
                        ..whole
                    };
                    let on = value >> b & 1 == 1;
                    let forced = self.is_forced(a);
                    let mut text = egui::RichText::new(if on { "1" } else { "0" }).monospace();
                    if forced {
                        text = text.color(theme::FORCED).strong();
                    }
                    let cell = egui::Button::new(text)
                        .selected(on)
                        .min_size(egui::vec2(22.0, 0.0));
                    let r = ui.add(cell).on_hover_text(self.describe(cx, a));
                    let label = a.to_string();
                    r.widget_info(|| {
                        egui::WidgetInfo::selected(egui::accesskit::Role::Button, true, on, &label)
                    });
                    if r.clicked() {
                        acts.push(if self.signals.click_forces {
                            Act::ToggleForce(a)
                        } else {
                            Act::Invert(a)
                        });
                    }
                    r.context_menu(|ui| {
                        if ui.button(Msg::WriteOnce.text(lang)).clicked() {
                            acts.push(Act::Invert(a));
                            ui.close();
                        }
                        let m = if forced {
                            Msg::Release
                        } else {
                            Msg::ForceValue
                        };
                        if ui.button(m.text(lang)).clicked() {
                            acts.push(Act::ToggleForce(a));
                            ui.close();
                        }
                    });
                }
            });
        } else {
            ui.monospace(value.to_string());
        }
        // A value typed for the whole byte or value: Enter (or Write) writes it once, Force
        // holds it.
        let typed = self.signals.typed.entry(whole).or_default();
        let r = ui
            .add(egui::TextEdit::singleline(typed).desired_width(70.0))
            .labelled_by(name);
        let enter = r.lost_focus() && ui.input(|i| i.key_pressed(egui::Key::Enter));
        let parsed = super::watch::parse_value(typed, super::super::settings::NumFormat::Dec)
            .map(|v| v as i64);
        let write = ui.small_button(Msg::WriteOnce.text(lang)).clicked() || enter;
        let force = ui.small_button(Msg::ForceValue.text(lang)).clicked();
        if (write || force)
            && let Some(v) = parsed
        {
            acts.push(if force {
                Act::Force(whole, v)
            } else {
                Act::Write(whole, v)
            });
            typed.clear();
        }
    }

    /// An address with its symbol and comment, for a hover.
    fn describe(&self, cx: &Context<'_>, a: Address) -> String {
        let lang = cx.settings.lang;
        let mut s = self.address_note(cx, a);
        if self.is_forced(a) {
            s.push_str(&format!("  ({})", Msg::Forced.text(lang)));
        }
        s
    }
}
