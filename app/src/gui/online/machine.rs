//! The machine side of the online panel: the operator panel (keys → X, lamps ← Y), the CNC
//! screen, and the signal trace drawn from the scan recorder.

use super::super::i18n::Msg;
use super::OnlineState;
use super::cnc_view::{CncEvent, cnc_ui};
use super::panel_view::{PanelEvent, panel_ui};
use crate::gui::context::Context;
use ladder_engine::Address;
use ladder_engine::cnc::command::CncCommand;
use ladder_engine::machine::{MachineCommand, Target};
use ladder_engine::model::{Panel, PanelKind, TableEdit};
use ladder_engine::runner::Request;

fn target(a: Address) -> Target {
    Target {
        address: a,
        bytes: 1,
        explicit: false,
    }
}

impl OnlineState {
    /// The panel in use: the project's own, else the profile's preset.
    pub fn panel(&self, cx: &Context<'_>) -> Panel {
        cx.doc()
            .map(|d| d.project().operator_panel().into_owned())
            .unwrap_or_default()
    }

    /// At power-on the panel's switches and knobs are where the panel says (a released
    /// E-stop, closed limit switches, the override knobs at their first-listed value), so
    /// the machine starts as one ready to run.
    pub(super) fn apply_panel_defaults(&mut self, cx: &mut Context<'_>) {
        self.panel_bytes.clear();
        let driven = self.device_inputs(cx);
        for item in self.panel(cx).items {
            // An input a device drives is the device's: its switch on the panel is only a lamp.
            if item.kind.input().is_some_and(|a| driven.contains(&a)) {
                continue;
            }
            match item.kind {
                PanelKind::Switch { input } => self.send_command(
                    cx,
                    MachineCommand::Write(target(input), i64::from(item.initial != 0)),
                ),
                PanelKind::Knob { input, .. } => {
                    // Knobs sharing a byte each set their own bits (feed and rapid on X5).
                    let mask = i64::from(item.kind.knob_mask());
                    let byte = self.panel_byte(input);
                    let v = (byte & !mask) | (item.initial & mask);
                    self.panel_bytes.push((input, v));
                    self.send_command(cx, MachineCommand::Write(target(input), v));
                }
                _ => {}
            }
        }
    }

    /// The input of the panel key with this English name ("Cycle start", "AUTO").
    pub fn panel_key(&self, cx: &Context<'_>, en: &str) -> Option<Address> {
        self.panel(cx)
            .items
            .into_iter()
            .find_map(|i| (i.label_en == en).then(|| i.kind.input()).flatten())
    }

    /// The inputs the project's machine model drives.
    fn device_inputs(&self, cx: &Context<'_>) -> Vec<Address> {
        cx.doc().map_or_else(Vec::new, |d| {
            d.project()
                .machine
                .devices
                .iter()
                .flat_map(|dev| dev.kind.inputs())
                .map(|(_, a)| a)
                .collect()
        })
    }

    /// A byte as the defaults being applied left it (the machine has not answered yet).
    fn panel_byte(&self, a: Address) -> i64 {
        self.panel_bytes
            .iter()
            .rev()
            .find(|(b, _)| *b == a)
            .map_or(0, |(_, v)| *v)
    }

    pub(super) fn machine_panel_ui(&mut self, cx: &mut Context<'_>, ui: &mut egui::Ui) {
        let Some(doc) = cx.doc() else { return };
        let profile = doc.project().profile();
        // Borrowed, not rebuilt: the preset is made only for a project without a panel.
        let mut panel = doc.project().operator_panel();
        // Outside the edit mode, a key or switch on an input a device drives shows the
        // device's answer as a lamp: clicking it would change nothing.
        let driven = self.device_inputs(cx);
        if !self.panel.editing
            && panel
                .items
                .iter()
                .any(|i| i.kind.input().is_some_and(|a| driven.contains(&a)))
        {
            for item in &mut panel.to_mut().items {
                if let Some(a) = item.kind.input().filter(|a| driven.contains(a)) {
                    item.kind = PanelKind::Lamp { lamp: a };
                }
            }
        }
        let lang = cx.settings.lang;
        let session = self.session.as_ref();
        let memory = |a: Address| -> i64 {
            session.map_or(0, |s| {
                let v = s.source().value(a, 1);
                if a.bit.is_some() { v } else { v & 0xFF }
            })
        };
        let events = panel_ui(ui, &panel, &memory, profile, lang, &mut self.panel);
        let live = self.is_online() && !self.scrubbing();
        for e in events {
            match e {
                PanelEvent::Press(a) if live => self.send_request(cx, Request::Press(target(a))),
                PanelEvent::Release(a) if live => {
                    self.send_request(cx, Request::Release(target(a)))
                }
                PanelEvent::Set(a, v) if live => {
                    self.send_command(cx, MachineCommand::Write(target(a), v))
                }
                PanelEvent::Edited(p) => {
                    if let Err(e) = cx.apply(TableEdit::Panel(Box::new(p))) {
                        cx.output.say(e, true);
                    }
                }
                _ => {}
            }
        }
    }

    pub(super) fn cnc_page_ui(&mut self, cx: &mut Context<'_>, ui: &mut egui::Ui) {
        let lang = cx.settings.lang;
        let status = self
            .session
            .as_ref()
            .and_then(|s| s.published.snapshot.cnc.clone());
        let message = status.as_ref().and_then(|s| s.macro_message.clone());
        let alarm = |n: u16| {
            let text =
                ladder_engine::cnc::alarm_text::alarm_text(n, lang == super::super::i18n::Lang::Zh);
            match &message {
                // #3000's alarm shows the program's own message.
                Some((k, m)) if *k == n && !m.is_empty() => format!("{text}: {m}"),
                _ => text.into_owned(),
            }
        };
        let online = &mut *self;
        let events = cnc_ui(
            ui,
            status.as_ref(),
            &mut online.cnc,
            &mut online.toolpath,
            lang,
            &alarm,
        );
        for e in events {
            let c = match e {
                CncEvent::Program(text) => CncCommand::Program(text),
                CncEvent::Mdi(text) => {
                    let blocks = text.lines().filter(|l| !l.trim().is_empty()).count();
                    self.cnc.mdi_sent = self.is_online().then(|| {
                        format!(
                            "{} {blocks}. {}",
                            Msg::CncMdiSent.text(lang),
                            Msg::CncMdiHow.text(lang)
                        )
                    });
                    CncCommand::Mdi(text)
                }
                CncEvent::Reset => CncCommand::Reset,
                CncEvent::Macro { number, value } => CncCommand::Macro { number, value },
                CncEvent::CycleStart | CncEvent::FeedHold => {
                    // As the operator does it: the panel's key, pressed and let go (held
                    // long enough for the ladder to see it).
                    let name = if e == CncEvent::CycleStart {
                        "Cycle start"
                    } else {
                        "Feed hold"
                    };
                    match self.panel_key(cx, name) {
                        Some(a) => {
                            self.send_request(cx, Request::Press(target(a)));
                            self.send_request(cx, Request::Release(target(a)));
                        }
                        None => {
                            let m = format!("{name}: {}", Msg::NoPanelKey.text(lang));
                            cx.output.say(m, true);
                        }
                    }
                    continue;
                }
            };
            self.send_command(cx, MachineCommand::Cnc(c));
        }
    }

    /// The CNC alarm's text in the UI language.
    pub(super) fn cnc_alarm_text(&self, cx: &Context<'_>, n: u16) -> String {
        let text = ladder_engine::cnc::alarm_text::alarm_text(
            n,
            cx.settings.lang == super::super::i18n::Lang::Zh,
        );
        let message = self
            .session
            .as_ref()
            .and_then(|s| s.published.snapshot.cnc.as_ref())
            .and_then(|c| c.macro_message.clone());
        match message {
            // #3000's alarm shows the program's own message.
            Some((k, m)) if k == n && !m.is_empty() => format!("{text}: {m}"),
            _ => text.into_owned(),
        }
    }
}
