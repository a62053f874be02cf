//! Online: the ladder and the simulated CNC running behind the editor.
//!
//! [`session`] holds the machine thread and what it published; [`OnlineState`], the feature,
//! carries out the online commands through the editor's narrow `Context`; `ui.rs` draws the
//! online panel (operator panel, CNC, watch table, forces, trace, alarms), the toolbar's
//! clock and the timeline; `live.rs` turns the
//! published state into what the ladder view paints and answers "why?".

pub mod alarms;
pub mod cnc_view;
pub mod data_online;
pub mod live;
mod machine;
pub mod machine_page;
pub mod macro_view;
pub mod panel_view;
pub mod repaint;
mod scenarios;
pub mod session;
pub mod signals;
pub mod toolpath_raster;
pub mod toolpath_view;
pub mod trace;
pub mod trace_view;
mod ui;
pub mod values;
pub mod watch;

use super::command::Command;
use super::i18n::Msg;
use crate::gui::context::Context;
use ladder_engine::Address;
use ladder_engine::machine::{MachineCommand, Target};
use ladder_engine::runner::{Request, Speed};
use session::{Notice, Session, StartError};

/// Whether an address (or any bit of it) is forced in the session's last state.
pub fn forced_in(s: &Session, a: Address) -> bool {
    let loc = s.running.layout.loc(a, false);
    let bytes = if loc.wide { 4 } else { 1 };
    s.published.snapshot.forces.iter().any(|(off, mask, _)| {
        (loc.off..loc.off + bytes).contains(off)
            && match a.bit {
                Some(b) => mask >> b & 1 == 1,
                None => true,
            }
    })
}

/// Which page of the online panel is shown.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum OnlineTab {
    /// The machine operator panel.
    #[default]
    Panel,
    /// The CNC screen.
    Cnc,
    /// The watch table.
    Watch,
    /// The force list.
    Forces,
    /// The PLC's memory by area, byte by byte (the diagnosis screen).
    Signals,
    /// The signal trace.
    Trace,
    /// PLC and CNC alarms.
    Alarms,
    /// The machine model's devices.
    Machine,
}

/// The answer to "why?".
#[derive(Clone, Debug, PartialEq)]
pub struct Why {
    /// Block and network of the output.
    pub block: usize,
    /// Network.
    pub network: usize,
    /// The deciding contacts (row, column).
    pub cells: Vec<(usize, usize)>,
    /// What the output window said.
    pub text: String,
}

/// The online state the app keeps.
#[derive(Default)]
pub struct OnlineState {
    /// The running session, if online.
    pub session: Option<Session>,
    /// The pace asked for.
    pub speed: Speed,
    /// The scan engine asked for (`None`: the build's default, see `vm::Engine`).
    pub engine: Option<ladder_engine::vm::Engine>,
    /// The online panel's page.
    pub tab: OnlineTab,
    /// The last "why?".
    pub why: Option<Why>,
    /// The watch table's UI.
    pub watch: watch::WatchUi,
    /// The signal page.
    pub signals: signals::SignalPage,
    /// Values typed for the data tables' running values, by address.
    pub data_typed: std::collections::BTreeMap<Address, String>,
    /// The PLC alarms with the tick each came on.
    pub alarms: alarms::AlarmList,
    /// The operator panel widget's state.
    pub panel: panel_view::PanelViewState,
    /// The Machine page's state.
    pub machine: machine_page::MachinePageState,
    /// The CNC page's program and MDI texts.
    pub cnc: cnc_view::CncTexts,
    /// The CNC screen's toolpath plot.
    pub toolpath: toolpath_view::ToolpathView,
    /// The signal trace.
    pub trace: TraceUi,
    /// Bytes the panel's power-on values wrote, until the machine answers.
    pub panel_bytes: Vec<(Address, i64)>,
    /// The value window of a function box (online double-click).
    pub values: values::ValueWindow,
    /// Panel keys to press once the machine has run so many ticks (`--run --nc`).
    pub startup: Vec<(u64, Request)>,
    /// The user said yes to forcing once (asked before the first force of the editor's run).
    pub forces_confirmed: bool,
    /// Forces waiting for that answer.
    pub force_pending: Vec<Request>,
    /// What the screen shows of the machine, for the machine thread's repaint requests.
    pub gate: std::sync::Arc<repaint::Gate>,
    /// The addresses the ladder view drew this frame (kept to reuse its allocation).
    pub ladder_shown: Vec<Address>,
    /// The first force waits for the user's answer: the editor asks its question.
    pub ask_first_force: bool,
}

/// The signal trace page's state.
#[derive(Default)]
pub struct TraceUi {
    /// The chart's own state.
    pub view: trace_view::TraceState,
    /// The trace as it was when paused: the machine runs on and the ring moves, the copy
    /// stays.
    pub frozen: Option<trace_view::TraceData>,
    /// The CSV waiting for its file name.
    pub csv: Option<String>,
    /// The trigger.
    pub trigger: trace::TriggerState,
    /// The last triggered capture, kept until cleared.
    pub capture: Option<trace::Capture>,
    /// Whether the chart shows the capture rather than the record.
    pub show_capture: bool,
}

impl OnlineState {
    /// Whether a machine is online.
    pub fn is_online(&self) -> bool {
        self.session.is_some()
    }

    /// Whether the view shows a recorded tick (read-only).
    pub fn scrubbing(&self) -> bool {
        self.session.as_ref().is_some_and(|s| s.scrub.is_some())
    }

    /// Goes online: compiles (errors go to the output window and nothing starts) and starts
    /// the machine, stopped.
    pub fn go_online(&mut self, cx: &mut Context<'_>) -> bool {
        if self.is_online() {
            return true;
        }
        crate::gui::diagnostics::compile(cx);
        let Some(doc) = cx.doc() else {
            return false;
        };
        let ctx = cx.egui.cloned();
        let gate = std::sync::Arc::clone(&self.gate);
        // A frame within 33 ms for a change on screen, within 500 ms for anything else.
        let wake = Box::new(move |snapshot: &ladder_engine::machine::Snapshot| {
            let soon = gate.judge(snapshot);
            if let Some(c) = &ctx {
                c.request_repaint_after(soon);
            }
        });
        match Session::start(doc.project(), doc.generation(), wake) {
            Ok(mut s) => {
                s.set_speed(self.speed);
                if let Some(e) = self.engine {
                    s.set_engine(e);
                }
                // The online window narrows the ladder: keep its coils and boxes in sight.
                cx.settings.fit_width = true;
                self.session = Some(s);
                self.alarms = Default::default();
                self.why = None;
                self.apply_panel_defaults(cx);
                let t = Msg::OnlineStarted.text(cx.settings.lang).to_string();
                cx.output.say(t, false);
                true
            }
            Err(StartError::Compile(..)) => {
                let t = Msg::RunNeedsCompile.text(cx.settings.lang).to_string();
                cx.output.say(t, true);
                false
            }
            Err(StartError::Other(m)) => {
                let t = format!("{}: {m}", Msg::RunFailed.text(cx.settings.lang));
                cx.output.say(t, true);
                false
            }
        }
    }

    /// `--run`: goes online and runs at real time; with an NC program, loads it and starts it
    /// as an operator would: the panel's AUTO key, then Cycle start.
    pub fn start_running(&mut self, cx: &mut Context<'_>, nc: Option<String>) {
        self.execute_online(cx, Command::Run);
        let Some(text) = nc else { return };
        // The CNC page's editor shows what was loaded.
        self.cnc.program = text.clone();
        self.send_command(
            cx,
            MachineCommand::Cnc(ladder_engine::cnc::command::CncCommand::Program(text)),
        );
        let target = |a: Address| Target {
            address: a,
            bytes: 1,
            explicit: false,
        };
        if let (Some(auto), Some(start)) = (
            self.panel_key(cx, "AUTO"),
            self.panel_key(cx, "Cycle start"),
        ) {
            self.startup = vec![
                (2, Request::Press(target(auto))),
                (3, Request::Release(target(auto))),
                (30, Request::Press(target(start))),
                (31, Request::Release(target(start))),
            ];
        }
    }

    /// Leaves online mode and stops the machine thread (closing a project or the window
    /// does this too).
    pub fn go_offline(&mut self, cx: &mut Context<'_>) {
        if let Some(s) = self.session.take() {
            s.stop();
        }
        self.lock_while_replaying(cx);
        self.why = None;
    }

    /// Sends a machine command (what a script line would do); offline it does nothing.
    pub fn send_command(&mut self, cx: &mut Context<'_>, c: MachineCommand) {
        self.send_request(cx, Request::Command(c));
    }

    /// The one door of every online action (the ladder's keys, the watch table, the signal
    /// page, the panel, the CNC page, the value window, the data tables): offline nothing is
    /// sent and the output window says how to go online; while a recording is replayed the
    /// machine is not touched and the output window says why; the first force of the run
    /// asks first.
    pub fn send_request(&mut self, cx: &mut Context<'_>, r: Request) {
        if self.session.is_none() {
            self.say_once(cx, Msg::OfflineHint);
            return;
        }
        let is_force = |c: &MachineCommand| {
            matches!(
                c,
                MachineCommand::Force(..) | MachineCommand::ToggleForce(_)
            )
        };
        let forcing = match &r {
            Request::Command(c) => is_force(c),
            Request::Batch(cs) => cs.iter().any(is_force),
            _ => false,
        };
        if forcing && !self.forces_confirmed && self.session.is_some() {
            self.force_pending.push(r);
            self.ask_first_force = true;
            return;
        }
        if let Some(s) = self.session.as_mut()
            && !s.send(r)
        {
            self.say_once(cx, Msg::Replaying);
        }
    }

    /// Says a refusal, unless it is already the output window's last line.
    fn say_once(&mut self, cx: &mut Context<'_>, m: Msg) {
        let t = m.text(cx.settings.lang).to_string();
        if cx.output.last().is_none_or(|l| l.text != t) {
            cx.output.say(t, true);
        }
    }

    /// The answer to the first force's question: the forces asked for are sent, or dropped.
    pub fn confirm_forces(&mut self, cx: &mut Context<'_>, yes: bool) {
        let pending = std::mem::take(&mut self.force_pending);
        self.forces_confirmed = yes;
        if yes {
            for r in pending {
                self.send_request(cx, r);
            }
        }
    }

    /// Keeps the document read-only exactly while a recorded tick is shown.
    pub(crate) fn lock_while_replaying(&mut self, cx: &mut Context<'_>) {
        let replaying = self.scrubbing();
        cx.set_replaying(replaying);
    }

    /// Carries out an online command.
    pub(crate) fn execute_online(&mut self, cx: &mut Context<'_>, c: Command) {
        match c {
            Command::Run if self.go_online(cx) => {
                self.leave_scrub(cx);
                self.send_command(cx, MachineCommand::Run);
            }
            Command::Stop => self.send_command(cx, MachineCommand::Stop),
            Command::StepTick | Command::StepN if self.go_online(cx) => {
                self.leave_scrub(cx);
                let n = if c == Command::StepTick {
                    1
                } else {
                    cx.settings.step_ticks.clamp(1, 1_000_000)
                };
                self.send_command(cx, MachineCommand::Tick(n));
            }
            Command::PowerCycle => {
                self.send_command(cx, MachineCommand::PowerCycle);
                self.apply_panel_defaults(cx);
            }
            Command::GoOffline => self.go_offline(cx),
            Command::ToggleBit | Command::ForceBit | Command::Unforce => self.at_cursor(cx, c),
            Command::UnforceAll => {
                for a in self.forced_addresses() {
                    self.send_command(cx, MachineCommand::Unforce(a));
                }
            }
            Command::Why => self.why_at_cursor(cx),
            Command::LiveView => self.leave_scrub(cx),
            Command::Speed(s) => {
                self.speed = s;
                if let Some(session) = self.session.as_mut() {
                    session.set_speed(s);
                }
            }
            Command::ScanEngine(e) => {
                self.engine = Some(e);
                if let Some(session) = self.session.as_mut() {
                    session.set_engine(e);
                }
            }
            _ => {}
        }
    }

    /// The engine that runs (or will run) the scan: the one asked for, else the build's
    /// default; the interpreter where native code is unavailable.
    pub fn engine_in_force(&self) -> ladder_engine::vm::Engine {
        use ladder_engine::vm::{Engine, native};
        let asked = self.engine.unwrap_or_else(Engine::default_for_build);
        if native::AVAILABLE {
            asked
        } else {
            Engine::Interpreter
        }
    }

    /// Back from a recorded tick to the present.
    pub fn leave_scrub(&mut self, cx: &mut Context<'_>) {
        if let Some(s) = self.session.as_mut() {
            s.scrub_to(None);
        }
        self.lock_while_replaying(cx);
    }

    /// The bit address of the element at the cursor (a contact or coil).
    fn cursor_bit(&self, cx: &Context<'_>) -> Option<Address> {
        let doc = cx.doc()?;
        let p = doc.project();
        let cell = p.ladder.cell_at(*cx.cursor)?;
        let operand = match cell {
            ladder_engine::model::Cell::Contact { operand, .. }
            | ladder_engine::model::Cell::Coil { operand, .. } => operand,
            _ => return None,
        };
        super::ladder_view::address_of(p, operand).filter(|a| a.bit.is_some())
    }

    /// Reads a bit of the shown state.
    pub fn live_bit(&self, a: Address) -> Option<bool> {
        let s = self.session.as_ref()?;
        Some(s.source().bit(a))
    }

    /// Whether an address (or any bit of it) is forced.
    pub fn is_forced(&self, a: Address) -> bool {
        self.session.as_ref().is_some_and(|s| forced_in(s, a))
    }

    /// Every forced address, as the machine published them: bits of byte areas one by one,
    /// 4-byte values whole.
    pub fn forced_addresses(&self) -> Vec<Address> {
        self.session
            .as_ref()
            .map_or_else(Vec::new, |s| s.published.snapshot.forced.clone())
    }

    fn at_cursor(&mut self, cx: &mut Context<'_>, c: Command) {
        let Some(a) = self.cursor_bit(cx) else {
            let t = Msg::NoBitAtCursor.text(cx.settings.lang).to_string();
            cx.output.say(t, true);
            return;
        };
        // The machine decides which way from its state when the command runs: a second
        // press before the next snapshot must not act on the first one's old state.
        match c {
            Command::ToggleBit => self.send_command(cx, MachineCommand::Invert(a)),
            Command::ForceBit => self.send_command(cx, MachineCommand::ToggleForce(a)),
            _ => self.send_command(cx, MachineCommand::Unforce(a)),
        }
    }

    /// Every frame: takes the machine's news, follows edits, keeps the alarm list.
    pub fn online_frame(&mut self, cx: &mut Context<'_>) {
        let Some(s) = self.session.as_mut() else {
            return;
        };
        let (changed, notices) = s.poll();
        let mut lines = Vec::new();
        let lang = cx.settings.lang;
        for n in notices {
            lines.push(match n {
                Notice::Refused(m) => (
                    format!(
                        "{}: {}",
                        Msg::MachineRefused.text(lang),
                        ladder_text::refusal::refusal(&m, lang)
                    ),
                    true,
                ),
                Notice::Swapped(kept, fresh) => (
                    format!(
                        "{} ({} {kept}, {} {fresh})",
                        Msg::EditSwapped.text(lang),
                        Msg::KeptInstances.text(lang),
                        Msg::FreshInstances.text(lang)
                    ),
                    false,
                ),
                Notice::SwapRefused(m) => (
                    format!(
                        "{}: {}",
                        Msg::EditNotSwapped.text(lang),
                        ladder_text::refusal::refusal(&m, lang)
                    ),
                    true,
                ),
                Notice::Failed(m) => (format!("{}: {m}", Msg::MachineFailed.text(lang)), true),
            });
        }
        let failed = s.published.stopped;
        let now = s.published.snapshot.ticks;
        while self.startup.first().is_some_and(|(at, _)| *at <= now) {
            let (_, r) = self.startup.remove(0);
            s.send(r);
        }
        let was_refused = matches!(s.sync, session::DrawingSync::Refused(..));
        let mut recompile = false;
        if let Some(doc) = cx.doc()
            && s.scrub.is_none()
        {
            if s.follow_edit(doc.project(), doc.generation()).is_some() {
                recompile = true;
                let t = Msg::EditNotCompiled.text(lang).to_string();
                lines.push((t, true));
            } else if was_refused
                && s.sync != session::DrawingSync::Swapping
                && s.drawing_runs(doc.project())
            {
                // Undone back to what runs: the refused edit's errors are gone, and the output
                // window says so rather than keep them.
                recompile = true;
            }
        }
        if recompile {
            crate::gui::diagnostics::compile(cx);
        }
        if changed && let Some(doc) = cx.doc() {
            let s = self.session.as_ref().expect("checked above");
            self.alarms.update(doc.project(), s);
        }
        for (t, e) in lines {
            cx.output.say(t, e);
        }
        if failed {
            self.go_offline(cx);
        }
        self.poll_trigger(cx);
        self.lock_while_replaying(cx);
    }
}
