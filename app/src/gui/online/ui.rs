//! The online panel and the online parts of the toolbar and status bar: the clock, the pace,
//! "step N", whether the drawing runs, and the scan recorder's timeline.

use super::super::command::Command;
use super::super::i18n::Msg;
use super::super::theme;
use super::OnlineState;
use super::OnlineTab;
use super::alarms::AlarmList;
use super::session::DrawingSync;
use crate::gui::context::Context;
use ladder_engine::machine::MachineCommand;
use ladder_engine::runner::Speed;
use ladder_engine::vm::TICK_MS;

/// `ticks` as virtual time, `h:mm:ss.mmm`.
pub fn clock_text(ticks: u64) -> String {
    let ms = ticks * TICK_MS;
    format!(
        "{}:{:02}:{:02}.{:03}",
        ms / 3_600_000,
        ms / 60_000 % 60,
        ms / 1000 % 60,
        ms % 1000
    )
}

impl OnlineState {
    /// The toolbar's online part after the run buttons: pace, N, clock and ticks.
    pub fn online_toolbar_ui(&mut self, cx: &mut Context<'_>, ui: &mut egui::Ui) {
        let lang = cx.settings.lang;
        let t = |m: Msg| m.text(lang);
        egui::ComboBox::new("speed", t(Msg::SpeedLabel))
            .width(84.0)
            .selected_text(Command::Speed(self.speed).text().text(lang))
            .show_ui(ui, |ui| {
                for s in Speed::ALL {
                    let c = Command::Speed(s);
                    if ui
                        .selectable_label(self.speed == s, c.text().text(lang))
                        .clicked()
                    {
                        cx.pending.push(c);
                    }
                }
            });
        egui::ComboBox::new("live-format", t(Msg::LiveFormat))
            .width(56.0)
            .selected_text(cx.settings.live_format.name())
            .show_ui(ui, |ui| {
                for f in super::super::settings::NumFormat::ALL {
                    ui.selectable_value(&mut cx.settings.live_format, f, f.name());
                }
            });
        ui.add(
            egui::DragValue::new(&mut cx.settings.step_ticks)
                .range(1..=1_000_000)
                .prefix("N = "),
        )
        .on_hover_text(t(Msg::StepNHint));
        if let Some(s) = &self.session {
            let snap = &s.published.snapshot;
            ui.separator();
            // The virtual clock and the tick count (#), named on hover.
            ui.monospace(format!("{} #{}", clock_text(snap.ticks), snap.ticks))
                .on_hover_text(t(Msg::Ticks));
            ui.label(if snap.running {
                t(Msg::StateRunning)
            } else {
                t(Msg::StateStopped)
            });
            let (last, max) = snap.tick_steps;
            // Compact (the toolbar is one row at 1280 px); the hover says what each figure is.
            let text = format!(
                "{} {last}/{max}/{}",
                t(Msg::ScanSteps),
                ladder_engine::vm::WATCHDOG_STEPS
            );
            ui.add(egui::Label::new(text).wrap_mode(egui::TextWrapMode::Extend))
                .on_hover_text(t(Msg::ScanHint));
            if let Some(h) = &snap.halt {
                let why = ladder_text::halt::halt(h, lang);
                ui.colored_label(theme::ERROR, format!("{}: {why}", t(Msg::PlcHalted)));
            }
        }
    }

    /// The status bar's online part: whether the drawing is what runs.
    pub fn online_status_ui(
        &self,
        doc: &crate::gui::document::Document,
        lang: super::super::i18n::Lang,
        ui: &mut egui::Ui,
    ) {
        let t = |m: Msg| m.text(lang);
        let Some(s) = &self.session else {
            return;
        };
        ui.separator();
        if s.scrub.is_some() {
            ui.colored_label(theme::CAUTION, t(Msg::ShowingPast));
        }
        let snap = &s.published.snapshot;
        if !snap.forces.is_empty() {
            let n = self.forced_addresses().len();
            let badge = egui::RichText::new(format!(" {} ({n}) ", t(Msg::ForcedCount)))
                .strong()
                .color(egui::Color32::BLACK)
                .background_color(theme::AMBER);
            ui.label(badge);
        }
        let faults = snap.devices.iter().filter(|d| d.fault.is_some()).count();
        if faults > 0 {
            ui.colored_label(theme::ERROR, format!("{}: {faults}", t(Msg::DeviceFaults)));
        }
        match &s.sync {
            _ if s.drawing_runs(doc.project()) => {
                ui.colored_label(theme::OK, t(Msg::DrawingRuns));
            }
            DrawingSync::Swapping => {
                ui.colored_label(theme::CAUTION, t(Msg::DrawingSwapping));
            }
            DrawingSync::Refused(en, zh) => {
                let why = if lang == super::super::i18n::Lang::Zh {
                    zh
                } else {
                    en
                };
                ui.colored_label(theme::ERROR, format!("{}: {why}", t(Msg::DrawingDiffers)));
            }
            DrawingSync::Same => {
                ui.colored_label(theme::CAUTION, t(Msg::DrawingDiffers));
            }
        }
    }

    /// The scan recorder's timeline: a slider over the recorded ticks; moving it shows that
    /// tick (read-only), "live" goes back to the present.
    pub fn timeline_ui(&mut self, cx: &mut Context<'_>, ui: &mut egui::Ui) {
        let lang = cx.settings.lang;
        let t = |m: Msg| m.text(lang);
        let Some(s) = self.session.as_mut() else {
            return;
        };
        let (oldest, newest) = {
            let r = s.recorder();
            (r.oldest(), r.newest())
        };
        let (Some(oldest), Some(newest)) = (oldest, newest) else {
            ui.label(t(Msg::RecorderEmpty));
            return;
        };
        let mut at = s.scrub.unwrap_or(newest);
        ui.horizontal(|ui| {
            let width = (ui.available_width() - 360.0).max(120.0);
            ui.spacing_mut().slider_width = width;
            let r = ui.add(
                egui::Slider::new(&mut at, oldest..=newest)
                    .text(t(Msg::Timeline))
                    .show_value(false)
                    .clamping(egui::SliderClamping::Always),
            );
            ui.monospace(format!("{} ({at})", clock_text(at)));
            let live = s.scrub.is_none();
            if r.changed() {
                s.scrub_to(if at >= newest && live { None } else { Some(at) });
            }
            if ui
                .add_enabled(!live, egui::Button::new(t(Msg::LiveView)))
                .clicked()
            {
                s.scrub_to(None);
            }
        });
    }

    /// The online panel in a native window of its own (in a window inside the main one where
    /// the platform has no second window); closing it puts the panel back beside the ladder.
    pub(crate) fn online_viewport(&mut self, cx: &mut Context<'_>, ctx: &egui::Context) {
        let title = format!(
            "Ladder Studio — {}",
            Msg::OnlineWindow.text(cx.settings.lang)
        );
        let builder = egui::ViewportBuilder::default()
            .with_title(title)
            .with_inner_size([720.0, 820.0]);
        let id = egui::ViewportId::from_hash_of("online-window");
        ctx.show_viewport_immediate(id, builder, |ui, class| {
            if class == egui::ViewportClass::EmbeddedWindow {
                self.online_panel_ui(cx, ui);
            } else {
                egui::Frame::central_panel(ui.style()).show(ui, |ui| {
                    ui.set_min_size(ui.available_size());
                    self.online_panel_ui(cx, ui);
                });
            }
            if ui.input(|i| i.viewport().close_requested()) {
                cx.settings.online_window = false;
            }
        });
    }

    /// The online panel: its pages.
    pub fn online_panel_ui(&mut self, cx: &mut Context<'_>, ui: &mut egui::Ui) {
        let lang = cx.settings.lang;
        let t = |m: Msg| m.text(lang);
        ui.horizontal_wrapped(|ui| {
            for (tab, m) in [
                (OnlineTab::Panel, Msg::TabPanel),
                (OnlineTab::Machine, Msg::TabMachine),
                (OnlineTab::Cnc, Msg::TabCnc),
                (OnlineTab::Watch, Msg::TabWatch),
                (OnlineTab::Forces, Msg::TabForces),
                (OnlineTab::Signals, Msg::TabSignals),
                (OnlineTab::Trace, Msg::TabTrace),
                (OnlineTab::Alarms, Msg::TabAlarms),
            ] {
                ui.selectable_value(&mut self.tab, tab, t(m));
            }
        });
        ui.separator();
        if self.session.is_none() && !matches!(self.tab, OnlineTab::Watch | OnlineTab::Machine) {
            ui.label(t(Msg::OfflineHint));
        }
        // Each page keeps its own scroll position across tab switches.
        egui::ScrollArea::both()
            .id_salt(("online-page", self.tab))
            .auto_shrink([false, false])
            .show(ui, |ui| match self.tab {
                OnlineTab::Panel => self.machine_panel_ui(cx, ui),
                OnlineTab::Cnc => self.cnc_page_ui(cx, ui),
                OnlineTab::Watch => self.watch_ui(cx, ui),
                OnlineTab::Forces => self.forces_ui(cx, ui),
                OnlineTab::Signals => self.signals_ui(cx, ui),
                OnlineTab::Trace => self.trace_page_ui(cx, ui),
                OnlineTab::Alarms => self.alarms_ui(cx, ui),
                OnlineTab::Machine => self.machine_page_ui(cx, ui),
            });
    }

    fn forces_ui(&mut self, cx: &mut Context<'_>, ui: &mut egui::Ui) {
        let lang = cx.settings.lang;
        let t = |m: Msg| m.text(lang);
        let forced = self.forced_addresses();
        if forced.is_empty() {
            ui.label(t(Msg::NoForces));
            return;
        }
        let mut release = Vec::new();
        egui::Grid::new("forces").striped(true).show(ui, |ui| {
            for a in &forced {
                let bytes = u32::from(a.area.element_bytes()).max(1);
                let value = self
                    .session
                    .as_ref()
                    .map_or(0, |s| s.source().value(*a, bytes));
                ui.colored_label(theme::FORCED, a.to_string());
                let sym = cx
                    .doc()
                    .and_then(|d| d.project().symbol_of(*a).map(str::to_string))
                    .unwrap_or_default();
                ui.label(sym);
                ui.monospace(value.to_string());
                if ui.button(t(Msg::Release)).clicked() {
                    release.push(*a);
                }
                ui.end_row();
            }
        });
        if ui.button(t(Msg::ReleaseAll)).clicked() {
            cx.pending.push(Command::UnforceAll);
        }
        for a in release {
            self.send_command(cx, MachineCommand::Unforce(a));
        }
    }

    fn alarms_ui(&mut self, cx: &mut Context<'_>, ui: &mut egui::Ui) {
        let lang = cx.settings.lang;
        let t = |m: Msg| m.text(lang);
        let Some(doc) = cx.doc() else { return };
        ui.strong(t(Msg::PlcAlarms));
        if self.alarms.on.is_empty() {
            ui.label(t(Msg::NoAlarms));
        }
        egui::Grid::new("plc-alarms").striped(true).show(ui, |ui| {
            for a in &self.alarms.on {
                ui.colored_label(theme::ERROR, format!("{:04}", a.number));
                ui.label(AlarmList::text(doc.project(), a, lang.code()));
                ui.monospace(a.bit.to_string());
                ui.monospace(clock_text(a.since));
                ui.end_row();
            }
        });
        ui.separator();
        ui.strong(t(Msg::CncAlarms));
        let cnc = self
            .session
            .as_ref()
            .and_then(|s| s.published.snapshot.cnc.as_ref())
            .map(|c| c.alarms.clone())
            .unwrap_or_default();
        let cnc: Vec<u16> = cnc.into_iter().filter(|n| *n < 1000).collect();
        if cnc.is_empty() {
            ui.label(t(Msg::NoAlarms));
        }
        for n in cnc {
            ui.colored_label(
                theme::ERROR,
                format!("{n:04}  {}", self.cnc_alarm_text(cx, n)),
            );
        }
    }
}
