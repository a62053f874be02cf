//! Online: the ladder and the simulated CNC running behind the editor.
//!
//! [`session`] holds the machine thread and what it published; the LadderApp methods here
//! carry out the online commands; `ui.rs` draws the online panel (operator panel, CNC, watch
//! table, forces, trace, alarms), the toolbar's clock and the timeline; `live.rs` turns the
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
pub mod session;
pub mod signals;
pub mod toolpath_raster;
pub mod toolpath_view;
pub mod trace;
pub mod trace_view;
mod ui;
pub mod values;
pub mod watch;

use super::LadderApp;
use super::command::Command;
use super::i18n::{self, Msg};
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

impl LadderApp {
    /// Whether a machine is online.
    pub fn online(&self) -> bool {
        self.online.session.is_some()
    }

    /// Whether the view shows a recorded tick (read-only).
    pub fn scrubbing(&self) -> bool {
        self.online
            .session
            .as_ref()
            .is_some_and(|s| s.scrub.is_some())
    }

    /// Goes online: compiles (errors go to the output window and nothing starts) and starts
    /// the machine, stopped.
    pub fn go_online(&mut self) -> bool {
        if self.online() {
            return true;
        }
        self.compile();
        let Some(doc) = self.doc.as_ref() else {
            return false;
        };
        let ctx = self.ctx.clone();
        let gate = std::sync::Arc::clone(&self.online.gate);
        // A frame within 33 ms for a change on screen, within 500 ms for anything else.
        let wake = Box::new(move |snapshot: &ladder_engine::machine::Snapshot| {
            let soon = gate.judge(snapshot);
            if let Some(c) = &ctx {
                c.request_repaint_after(soon);
            }
        });
        match Session::start(doc.project(), doc.generation(), wake) {
            Ok(mut s) => {
                s.set_speed(self.online.speed);
                // The online window narrows the ladder: keep its coils and boxes in sight.
                self.settings.fit_width = true;
                self.online.session = Some(s);
                self.online.alarms = Default::default();
                self.online.why = None;
                self.apply_panel_defaults();
                let t = self.t(Msg::OnlineStarted).to_string();
                self.output.say(t, false);
                true
            }
            Err(StartError::Compile(..)) => {
                let t = self.t(Msg::RunNeedsCompile).to_string();
                self.output.say(t, true);
                false
            }
            Err(StartError::Other(m)) => {
                let t = format!("{}: {m}", self.t(Msg::RunFailed));
                self.output.say(t, true);
                false
            }
        }
    }

    /// `--run`: goes online and runs at real time; with an NC program, loads it and starts it
    /// as an operator would: the panel's AUTO key, then Cycle start.
    pub fn start_running(&mut self, nc: Option<String>) {
        self.execute_online(Command::Run);
        let Some(text) = nc else { return };
        // The CNC page's editor shows what was loaded.
        self.online.cnc.program = text.clone();
        self.send_command(MachineCommand::Cnc(
            ladder_engine::cnc::command::CncCommand::Program(text),
        ));
        let target = |a: Address| Target {
            address: a,
            bytes: 1,
            explicit: false,
        };
        if let (Some(auto), Some(start)) = (self.panel_key("AUTO"), self.panel_key("Cycle start")) {
            self.online.startup = vec![
                (2, Request::Press(target(auto))),
                (3, Request::Release(target(auto))),
                (30, Request::Press(target(start))),
                (31, Request::Release(target(start))),
            ];
        }
    }

    /// Leaves online mode and stops the machine thread (closing a project or the window
    /// does this too).
    pub fn go_offline(&mut self) {
        if let Some(s) = self.online.session.take() {
            s.stop();
        }
        self.lock_while_replaying();
        self.online.why = None;
    }

    /// Sends a machine command (what a script line would do); offline it does nothing.
    pub fn send_command(&mut self, c: MachineCommand) {
        self.send_request(Request::Command(c));
    }

    /// The one door of every online action (the ladder's keys, the watch table, the signal
    /// page, the panel, the CNC page, the value window, the data tables): offline nothing is
    /// sent and the output window says how to go online; while a recording is replayed the
    /// machine is not touched and the output window says why; the first force of the run
    /// asks first.
    pub fn send_request(&mut self, r: Request) {
        if self.online.session.is_none() {
            self.say_once(Msg::OfflineHint);
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
        if forcing && !self.online.forces_confirmed && self.online.session.is_some() {
            self.online.force_pending.push(r);
            self.files.question = Some(super::dialogs::Question::FirstForce);
            return;
        }
        if let Some(s) = self.online.session.as_mut()
            && !s.send(r)
        {
            self.say_once(Msg::Replaying);
        }
    }

    /// Says a refusal, unless it is already the output window's last line.
    fn say_once(&mut self, m: Msg) {
        let t = self.t(m).to_string();
        if self.output.last().is_none_or(|l| l.text != t) {
            self.output.say(t, true);
        }
    }

    /// The answer to the first force's question: the forces asked for are sent, or dropped.
    pub fn confirm_forces(&mut self, yes: bool) {
        let pending = std::mem::take(&mut self.online.force_pending);
        self.online.forces_confirmed = yes;
        if yes {
            for r in pending {
                self.send_request(r);
            }
        }
    }

    /// Keeps the document read-only exactly while a recorded tick is shown.
    pub(crate) fn lock_while_replaying(&mut self) {
        let replaying = self.scrubbing();
        if let Some(d) = self.doc.as_mut() {
            d.set_replaying(replaying);
        }
    }

    /// Carries out an online command.
    pub(crate) fn execute_online(&mut self, c: Command) {
        match c {
            Command::Run if self.go_online() => {
                self.leave_scrub();
                self.send_command(MachineCommand::Run);
            }
            Command::Stop => self.send_command(MachineCommand::Stop),
            Command::StepTick | Command::StepN if self.go_online() => {
                self.leave_scrub();
                let n = if c == Command::StepTick {
                    1
                } else {
                    self.settings.step_ticks.clamp(1, 1_000_000)
                };
                self.send_command(MachineCommand::Tick(n));
            }
            Command::PowerCycle => {
                self.send_command(MachineCommand::PowerCycle);
                self.apply_panel_defaults();
            }
            Command::GoOffline => self.go_offline(),
            Command::ToggleBit | Command::ForceBit | Command::Unforce => self.at_cursor(c),
            Command::UnforceAll => {
                for a in self.forced_addresses() {
                    self.send_command(MachineCommand::Unforce(a));
                }
            }
            Command::Why => self.why_at_cursor(),
            Command::LiveView => self.leave_scrub(),
            Command::Speed(s) => {
                self.online.speed = s;
                if let Some(session) = self.online.session.as_mut() {
                    session.set_speed(s);
                }
            }
            _ => {}
        }
    }

    /// Back from a recorded tick to the present.
    pub fn leave_scrub(&mut self) {
        if let Some(s) = self.online.session.as_mut() {
            s.scrub_to(None);
        }
        self.lock_while_replaying();
    }

    /// The bit address of the element at the cursor (a contact or coil).
    fn cursor_bit(&self) -> Option<Address> {
        let doc = self.doc.as_ref()?;
        let p = doc.project();
        let cell = p.ladder.cell_at(self.edit.cursor)?;
        let operand = match cell {
            ladder_engine::model::Cell::Contact { operand, .. }
            | ladder_engine::model::Cell::Coil { operand, .. } => operand,
            _ => return None,
        };
        super::ladder_view::address_of(p, operand).filter(|a| a.bit.is_some())
    }

    /// Reads a bit of the shown state.
    pub fn live_bit(&self, a: Address) -> Option<bool> {
        let s = self.online.session.as_ref()?;
        Some(s.source().bit(a))
    }

    /// Whether an address (or any bit of it) is forced.
    pub fn is_forced(&self, a: Address) -> bool {
        self.online
            .session
            .as_ref()
            .is_some_and(|s| forced_in(s, a))
    }

    /// Every forced address, as the machine published them: bits of byte areas one by one,
    /// 4-byte values whole.
    pub fn forced_addresses(&self) -> Vec<Address> {
        self.online
            .session
            .as_ref()
            .map_or_else(Vec::new, |s| s.published.snapshot.forced.clone())
    }

    fn at_cursor(&mut self, c: Command) {
        let Some(a) = self.cursor_bit() else {
            let t = self.t(Msg::NoBitAtCursor).to_string();
            self.output.say(t, true);
            return;
        };
        // The machine decides which way from its state when the command runs: a second
        // press before the next snapshot must not act on the first one's old state.
        match c {
            Command::ToggleBit => self.send_command(MachineCommand::Invert(a)),
            Command::ForceBit => self.send_command(MachineCommand::ToggleForce(a)),
            _ => self.send_command(MachineCommand::Unforce(a)),
        }
    }

    /// Every frame: takes the machine's news, follows edits, keeps the alarm list.
    pub fn online_frame(&mut self) {
        let Some(s) = self.online.session.as_mut() else {
            return;
        };
        let (changed, notices) = s.poll();
        let mut lines = Vec::new();
        let lang = self.settings.lang;
        for n in notices {
            lines.push(match n {
                Notice::Refused(m) => (
                    format!(
                        "{}: {}",
                        Msg::MachineRefused.text(lang),
                        m.text(lang == i18n::Lang::Zh)
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
                        m.text(lang == i18n::Lang::Zh)
                    ),
                    true,
                ),
                Notice::Failed(m) => (format!("{}: {m}", Msg::MachineFailed.text(lang)), true),
            });
        }
        let failed = s.published.stopped;
        let now = s.published.snapshot.ticks;
        while self
            .online
            .startup
            .first()
            .is_some_and(|(at, _)| *at <= now)
        {
            let (_, r) = self.online.startup.remove(0);
            s.send(r);
        }
        let was_refused = matches!(s.sync, session::Sync::Refused(..));
        let mut recompile = false;
        if let Some(doc) = self.doc.as_ref()
            && s.scrub.is_none()
        {
            if s.follow_edit(doc.project(), doc.generation()).is_some() {
                recompile = true;
                let t = Msg::EditNotCompiled.text(lang).to_string();
                lines.push((t, true));
            } else if was_refused
                && s.sync != session::Sync::Swapping
                && s.drawing_runs(doc.project())
            {
                // Undone back to what runs: the refused edit's errors are gone, and the output
                // window says so rather than keep them.
                recompile = true;
            }
        }
        if recompile {
            self.compile();
        }
        if changed && let Some(doc) = self.doc.as_ref() {
            let s = self.online.session.as_ref().expect("checked above");
            self.online.alarms.update(doc.project(), s);
        }
        for (t, e) in lines {
            self.output.say(t, e);
        }
        if failed {
            self.go_offline();
        }
        self.poll_trigger();
        self.lock_while_replaying();
    }
}
