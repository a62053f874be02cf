//! The trace page: the traced watch rows charted from the scan recorder, a paused copy that
//! stays put while the machine runs on, and the triggered capture: a window of ticks around
//! a bit edge or a value condition, kept outside the recorder's ring until cleared.

use super::super::i18n::Msg;
use super::super::settings::{TriggerSetup, TriggerWhen};
use super::OnlineState;
use super::session::{RECORD_TICKS, Session};
use super::trace_view::{TraceData, TraceEvent, TraceSignal, trace_csv, trace_ui};
use super::watch::resolve;
use crate::gui::context::Context;
use ladder_engine::machine::Target;
use ladder_engine::recorder::Recorder;

/// A capture the trigger took: its trigger tick and the window around it.
#[derive(Clone, Debug, PartialEq)]
pub struct Capture {
    /// The tick the condition was met.
    pub at: u64,
    /// The traced signals from `pre` ticks before it to `post` ticks after.
    pub data: TraceData,
}

/// Where the trigger is.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum TriggerState {
    /// Not armed.
    #[default]
    Idle,
    /// Watching the ticks from `next` on.
    Armed {
        /// The first tick not yet examined.
        next: u64,
    },
    /// The condition was met at tick `at`; waiting for the ticks after it.
    Fired {
        /// The trigger tick.
        at: u64,
    },
}

/// A signal's values from tick `first` to `last` as steps, from the recorder. `image` is the
/// memory as of `first`.
fn signal_points(
    rec: &Recorder,
    s: &Session,
    t: &Target,
    image: &[u8],
    first: u64,
    last: u64,
) -> Vec<(u64, i64)> {
    let loc = s.running.layout.loc(t.address, false);
    let (off, n) = (loc.off as usize, t.bytes as usize);
    let mut bytes: Vec<u8> = image.get(off..off + n).map_or(vec![0; n], <[u8]>::to_vec);
    let value = |b: &[u8]| -> i64 {
        match t.address.bit {
            Some(bit) => i64::from(b[0] >> bit & 1),
            None => {
                let mut raw = [0u8; 4];
                raw[..n].copy_from_slice(b);
                let v = u32::from_le_bytes(raw);
                let shift = 32 - 8 * n as u32;
                i64::from(((v << shift) as i32) >> shift)
            }
        }
    };
    let mut points = vec![(first, value(&bytes))];
    // Every change of any of its bytes, in tick order.
    let mut all: Vec<(u64, usize, u8)> = Vec::new();
    let mut changes = Vec::new();
    for k in 0..n {
        changes.clear();
        rec.changes_of((off + k) as u32, first + 1, last, &mut changes);
        all.extend(changes.iter().map(|&(tick, v)| (tick, k, v)));
    }
    all.sort_by_key(|c| c.0);
    for (tick, k, v) in all {
        bytes[k] = v;
        let now = value(&bytes);
        match points.last_mut() {
            Some(p) if p.0 == tick => p.1 = now,
            Some(p) if p.1 == now => {}
            _ => points.push((tick, now)),
        }
    }
    points
}

impl OnlineState {
    /// Writes the signal trace taken when Export CSV was pressed.
    pub fn export_trace(&mut self, cx: &mut Context<'_>, path: &std::path::Path) {
        let lang = cx.settings.lang;
        let Some(text) = self.trace.csv.take() else {
            return;
        };
        match crate::gui::files::write_atomic(path, &text) {
            Ok(()) => cx.output.say(
                format!("{} {}", Msg::Written.text(lang), path.display()),
                false,
            ),
            Err(e) => cx.output.say(format!("{}: {e}", path.display()), true),
        }
    }

    /// The traced watch rows, resolved (rows that no longer resolve are left out).
    fn traced(&self, cx: &Context<'_>) -> Vec<(String, Target)> {
        let Some(doc) = cx.doc() else {
            return Vec::new();
        };
        self.watch_rows(cx)
            .iter()
            .filter(|r| r.traced)
            .filter_map(|r| resolve(doc.project(), &r.text).ok())
            .map(|t| (t.text(), t))
            .collect()
    }

    /// Signals from tick `first` to `last` (clipped to what the recorder holds), exact to the
    /// tick at any speed.
    fn trace_window(&self, signals: &[(String, Target)], first: u64, last: u64) -> TraceData {
        let mut data = TraceData::default();
        let Some(s) = self.session.as_ref() else {
            return data;
        };
        let rec = s.recorder();
        let (Some(oldest), Some(newest)) = (rec.oldest(), rec.newest()) else {
            return data;
        };
        let (first, last) = (first.max(oldest), last.min(newest));
        let mut image = Vec::new();
        if first > last || !rec.image_at(first, &mut image) {
            return data;
        }
        data.first = first;
        data.last = last;
        for (name, t) in signals {
            data.signals.push(TraceSignal {
                name: name.clone(),
                bit: t.address.bit.is_some(),
                points: signal_points(rec, s, t, &image, first, last),
            });
        }
        data
    }

    /// The traced watch rows over the whole recorded window.
    pub fn trace_data(&self, cx: &Context<'_>) -> TraceData {
        self.trace_window(&self.traced(cx), 0, u64::MAX)
    }

    /// What the chart shows: the capture when chosen, the paused copy, else the record.
    pub fn shown_trace(&self, cx: &Context<'_>) -> TraceData {
        let t = &self.trace;
        match (&t.capture, &t.frozen) {
            (Some(c), _) if t.show_capture => c.data.clone(),
            (_, Some(f)) => f.clone(),
            _ => self.trace_data(cx),
        }
    }

    /// This project's trigger setup.
    pub fn trigger_setup(&self, cx: &Context<'_>) -> TriggerSetup {
        cx.settings
            .triggers
            .get(&self.watch_key(cx))
            .cloned()
            .unwrap_or_default()
    }

    /// Arms the trigger from the newest recorded tick on; says why when its signal is wrong.
    pub fn arm_trigger(&mut self, cx: &mut Context<'_>) -> Result<(), String> {
        let setup = self.trigger_setup(cx);
        let doc = cx.doc().ok_or_else(String::new)?;
        resolve(doc.project(), &setup.signal).map_err(|e| e.text(cx.settings.lang))?;
        let next = self
            .session
            .as_ref()
            .and_then(|s| s.recorder().newest())
            .map_or(0, |t| t + 1);
        self.trace.trigger = TriggerState::Armed { next };
        Ok(())
    }

    /// Every frame while online: looks for the trigger in the ticks recorded since the last
    /// look, and once the ticks after it are recorded, keeps the capture.
    pub(super) fn poll_trigger(&mut self, cx: &mut Context<'_>) {
        let state = self.trace.trigger;
        if state == TriggerState::Idle {
            return;
        }
        let setup = self.trigger_setup(cx);
        let Some(newest) = self.session.as_ref().and_then(|s| s.recorder().newest()) else {
            return;
        };
        let Some(doc) = cx.doc() else { return };
        let Ok(target) = resolve(doc.project(), &setup.signal) else {
            self.trace.trigger = TriggerState::Idle;
            return;
        };
        if let TriggerState::Armed { next } = state {
            if newest < next {
                return;
            }
            // From the tick before `next`: its value is the "before" of the first change.
            let from = next.saturating_sub(1);
            let data = self.trace_window(&[(setup.signal.clone(), target)], from, newest);
            let fired = data.signals.first().and_then(|s| {
                s.points
                    .windows(2)
                    .find(|w| setup.when.fires(w[0].1, w[1].1, setup.value))
                    .map(|w| w[1].0)
            });
            self.trace.trigger = match fired {
                Some(at) => TriggerState::Fired { at },
                None => TriggerState::Armed { next: newest + 1 },
            };
        }
        if let TriggerState::Fired { at } = self.trace.trigger
            && newest >= at.saturating_add(setup.post)
        {
            let mut signals = self.traced(cx);
            if !signals.iter().any(|(_, t)| *t == target) {
                signals.insert(0, (target.text(), target));
            }
            let data = self.trace_window(
                &signals,
                at.saturating_sub(setup.pre),
                at.saturating_add(setup.post),
            );
            self.trace.capture = Some(Capture { at, data });
            self.trace.show_capture = true;
            self.trace.trigger = TriggerState::Idle;
        }
    }

    /// The trace page: the trigger's row, then the chart of what is shown (the capture, the
    /// paused copy or the record).
    pub(super) fn trace_page_ui(&mut self, cx: &mut Context<'_>, ui: &mut egui::Ui) {
        let lang = cx.settings.lang;
        if !self.watch_rows(cx).iter().any(|r| r.traced) {
            ui.label(Msg::TraceHint.text(lang));
        }
        self.trigger_ui(cx, ui);
        let data = self.shown_trace(cx);
        let events = trace_ui(ui, &data, &mut self.trace.view, lang);
        for e in events {
            match e {
                TraceEvent::Pause(on) => {
                    self.trace.frozen = on.then(|| self.trace_data(cx));
                }
                TraceEvent::Remove(i) => {
                    // A lane is named by its address; its row may be typed as a symbol or in
                    // lower case: rows are matched by what they name.
                    let key = self.watch_key(cx);
                    let name = data.signals.get(i).map(|s| s.name.clone());
                    let (Some(doc), settings, _) = cx.parts() else {
                        continue;
                    };
                    let names = |text: &str| resolve(doc.project(), text).ok().map(|t| t.text());
                    if let (Some(list), Some(name)) = (settings.watches.get_mut(&key), name) {
                        for r in list.iter_mut() {
                            if r.traced && names(&r.text).as_deref() == Some(name.as_str()) {
                                r.traced = false;
                            }
                        }
                    }
                }
                TraceEvent::ExportCsv => {
                    self.trace.csv = Some(trace_csv(&data));
                    cx.pending
                        .push(super::super::command::Command::ExportTraceCsv);
                }
                TraceEvent::Clear => {
                    if let Some(s) = self.session.as_mut() {
                        s.clear_record();
                    }
                }
            }
        }
    }

    /// The trigger's row: signal, condition, value, ticks before and after, arm; the capture's
    /// switch and its clear button.
    fn trigger_ui(&mut self, cx: &mut Context<'_>, ui: &mut egui::Ui) {
        let lang = cx.settings.lang;
        let t = |m: Msg| m.text(lang);
        let key = self.watch_key(cx);
        let mut setup = self.trigger_setup(cx);
        let state = self.trace.trigger;
        let mut arm = None;
        ui.horizontal_wrapped(|ui| {
            let name = ui.label(t(Msg::Trigger)).id;
            ui.add(
                egui::TextEdit::singleline(&mut setup.signal)
                    .desired_width(90.0)
                    .hint_text("X0010.0"),
            )
            .labelled_by(name);
            egui::ComboBox::from_id_salt("trigger-when")
                .selected_text(t(when_msg(setup.when)))
                .show_ui(ui, |ui| {
                    for w in TriggerWhen::ALL {
                        ui.selectable_value(&mut setup.when, w, t(when_msg(w)));
                    }
                })
                .response
                .labelled_by(name);
            if !matches!(setup.when, TriggerWhen::Rising | TriggerWhen::Falling) {
                ui.add(egui::DragValue::new(&mut setup.value))
                    .labelled_by(name);
            }
            // Before and after together fit the recorder's window.
            let window = RECORD_TICKS - 1;
            let pre = ui.label(t(Msg::TriggerPre)).id;
            ui.add(egui::DragValue::new(&mut setup.pre).range(0..=window))
                .labelled_by(pre);
            let post = ui.label(t(Msg::TriggerPost)).id;
            ui.add(egui::DragValue::new(&mut setup.post).range(0..=window - setup.pre.min(window)))
                .labelled_by(post);
            let (label, status) = match state {
                TriggerState::Idle => (Msg::TriggerArm, None),
                TriggerState::Armed { .. } => (Msg::TriggerDisarm, Some(t(Msg::TriggerArmed))),
                TriggerState::Fired { .. } => (Msg::TriggerDisarm, Some(t(Msg::TriggerFired))),
            };
            if ui.button(t(label)).clicked() {
                arm = Some(state == TriggerState::Idle);
            }
            if let Some(status) = status {
                ui.colored_label(super::super::theme::FORCED, status);
            }
        });
        if let Some(c) = &self.trace.capture {
            let mut show = self.trace.show_capture;
            let mut clear = false;
            ui.horizontal_wrapped(|ui| {
                ui.checkbox(&mut show, t(Msg::TriggerShowCapture));
                ui.label(format!(
                    "{} {} ({:.3} s)",
                    t(Msg::TriggerCapturedAt),
                    c.at,
                    c.at as f64 * ladder_engine::vm::TICK_MS as f64 / 1000.0
                ));
                clear = ui.button(t(Msg::TriggerClearCapture)).clicked();
            });
            self.trace.show_capture = show;
            if clear {
                self.trace.capture = None;
            }
        }
        if cx.settings.triggers.get(&key) != Some(&setup) {
            cx.settings.triggers.insert(key, setup);
        }
        match arm {
            Some(true) => {
                if let Err(e) = self.arm_trigger(cx) {
                    let msg = format!("{}: {e}", t(Msg::TriggerBadSignal));
                    cx.output.say(msg, true);
                }
            }
            Some(false) => self.trace.trigger = TriggerState::Idle,
            None => {}
        }
    }
}

fn when_msg(w: TriggerWhen) -> Msg {
    match w {
        TriggerWhen::Rising => Msg::TriggerRising,
        TriggerWhen::Falling => Msg::TriggerFalling,
        TriggerWhen::Equal => Msg::TriggerEqual,
        TriggerWhen::Above => Msg::TriggerAbove,
        TriggerWhen::Below => Msg::TriggerBelow,
    }
}
