//! The online session: the machine thread, what it last published, the program it runs and
//! how that compares with the drawing, the scan recorder and the scrub position. No egui
//! here: the views in this module's siblings read it, and commands change it.

use ladder_engine::compiler::{Program, compile};
use ladder_engine::devices::{MachineModel, check};
use ladder_engine::machine::{Machine, MachineCommand};
use ladder_engine::model::{Ladder, Project};
use ladder_engine::recorder::Recorder;
use ladder_engine::refusal::Refusal;
use ladder_engine::runner::{Published, Reply, Request, Runner, Speed};
use ladder_engine::vm::monitor::Source;
use ladder_engine::vm::{Executable, Layout, Vm};
use ladder_text::Lang;
use std::collections::BTreeSet;
use std::sync::Arc;

/// Virtual seconds the scan recorder keeps by default.
pub const RECORD_SECONDS: u64 = 60;
/// The ticks the scan recorder keeps.
pub const RECORD_TICKS: u64 = RECORD_SECONDS * 1000 / ladder_engine::vm::TICK_MS;

/// A program the machine runs (or is about to): what was compiled, and from which drawing.
pub struct Running {
    /// The ladder it was compiled from: the drawing equals the running program while the
    /// project's ladder equals this.
    pub ladder: Ladder,
    /// The compiled program (cell origins of each instruction).
    pub program: Program,
    /// Its lowered code (networks, word sources).
    pub code: Executable,
    /// The memory layout.
    pub layout: Layout,
    /// Its number in swap requests (0 for the program the machine started with).
    pub number: u64,
}

/// Whether what runs is what is drawn.
#[derive(Clone, Debug, PartialEq)]
pub enum DrawingSync {
    /// The running program is the drawing.
    Same,
    /// An edited program was sent and has not taken over yet.
    Swapping,
    /// The drawing changed and cannot run: the reason (compile errors, a refused swap), in
    /// English and Chinese.
    Refused(String, String),
}

/// What went wrong starting a machine.
#[derive(Clone, Debug, PartialEq)]
pub enum StartError {
    /// The project has compile errors: how many, and the first, where it is, in English and
    /// Chinese.
    Compile(usize, String, String),
    /// The program could not be lowered or the thread could not start.
    Other(String),
}

/// Something the session tells the user (the output window).
#[derive(Clone, Debug, PartialEq)]
pub enum Notice {
    /// A command was refused by the machine.
    Refused(Refusal),
    /// An edit runs now: function instances kept and new.
    Swapped(usize, usize),
    /// An edit could not take over.
    SwapRefused(Refusal),
    /// The machine thread failed.
    Failed(String),
}

/// The online session.
pub struct Session {
    runner: Runner,
    /// The last published state.
    pub published: Published,
    /// The program the published state comes from.
    pub running: Arc<Running>,
    pending: Option<Arc<Running>>,
    sent: u64,
    /// The scan recorder, fed from the journal each publication carries (the machine
    /// thread never waits for it).
    recorder: Recorder,
    /// The tick shown instead of the present, while scrubbing.
    pub scrub: Option<u64>,
    scrub_image: Vec<u8>,
    /// Whether what runs is what is drawn.
    pub sync: DrawingSync,
    /// The machine model that runs (docs/machine.md).
    pub model: MachineModel,
    /// The project change counter last compared.
    pub seen_generation: u64,
    watched: BTreeSet<usize>,
}

/// The project compiled, or why it cannot run: how many errors, the first one, where.
fn compiled(project: &Project) -> Result<Program, StartError> {
    let compiled = compile(project);
    if compiled.errors() > 0 {
        let first = compiled
            .diagnostics
            .iter()
            .find(|d| d.severity() == ladder_engine::compiler::Severity::Error);
        let (en, zh) = first.map_or_else(Default::default, |d| {
            let en = ladder_text::diagnostics::render(d, "", Lang::En);
            (
                en.trim_start_matches(':').to_string(),
                ladder_text::diagnostics::shown(d, "", Lang::Zh)
                    .trim()
                    .to_string(),
            )
        });
        return Err(StartError::Compile(compiled.errors(), en, zh));
    }
    Ok(compiled.program)
}

/// What runs, from the PLC that runs it.
fn running(project: &Project, program: Program, plc: &Vm, number: u64) -> Running {
    Running {
        ladder: project.ladder.clone(),
        program,
        code: plc.code().clone(),
        layout: plc.layout().clone(),
        number,
    }
}

/// An edited drawing's PLC, to take over the running one's memory (a swap).
fn build(project: &Project, number: u64) -> Result<(Vm, Running), StartError> {
    let program = compiled(project)?;
    let mut vm = Vm::from_program(&program, project.profile())
        .map_err(|e| StartError::Other(e.to_string()))?;
    vm.set_division(project.level2_division);
    let running = running(project, program, &vm, number);
    Ok((vm, running))
}

/// Whether a request changes the machine's state (what a replay must not do). Watching and
/// the pace only change what is recorded and how fast.
pub fn changes_machine(r: &Request) -> bool {
    !matches!(
        r,
        Request::Speed(_)
            | Request::Coverage(_)
            | Request::Engine(_)
            | Request::Command(MachineCommand::Watch(_) | MachineCommand::WatchNetwork(..))
    )
}

impl Session {
    /// Compiles the project and starts its machine (PLC and simulated CNC) stopped, with the
    /// data tables loaded; `wake` asks the UI to draw again.
    pub fn start(
        project: &Project,
        generation: u64,
        wake: ladder_engine::runner::Wake,
    ) -> Result<Session, StartError> {
        let program = compiled(project)?;
        let machine = Machine::from_program(project, &program, true)
            .map_err(|e| StartError::Other(e.to_string()))?;
        let running = running(project, program, machine.plc(), 0);
        let size = running.layout.size as usize;
        let recorder = Recorder::new(size, RECORD_TICKS);
        let runner = Runner::start(machine, Box::new(|_| {}), wake)
            .map_err(|e| StartError::Other(e.to_string()))?;
        Ok(Session {
            runner,
            published: Published::default(),
            running: Arc::new(running),
            pending: None,
            sent: 0,
            recorder,
            scrub: None,
            scrub_image: Vec::new(),
            sync: DrawingSync::Same,
            model: project.machine.clone(),
            seen_generation: generation,
            watched: BTreeSet::new(),
        })
    }

    /// Sends a request. While a recorded tick is shown, a request that would change the
    /// machine is refused (`false`): the replay is read-only.
    pub fn send(&mut self, r: Request) -> bool {
        if self.scrub.is_some() && changes_machine(&r) {
            return false;
        }
        self.sent += 1;
        self.runner.send(r);
        true
    }

    /// Sends a machine command (what a script line would do); `false` when refused.
    pub fn command(&mut self, c: MachineCommand) -> bool {
        self.send(Request::Command(c))
    }

    /// Whether the state shown includes every request sent.
    pub fn caught_up(&self) -> bool {
        self.published.handled >= self.sent
    }

    /// Takes what the machine published; returns the notices for the user, and whether
    /// anything changed.
    pub fn poll(&mut self) -> (bool, Vec<Notice>) {
        if !self.runner.take(&mut self.published) {
            return (false, Vec::new());
        }
        let journal = std::mem::take(&mut self.published.journal);
        if let Some((tick, image)) = &journal.base {
            self.recorder.record(*tick, image);
        }
        for (tick, changes) in journal.each_tick() {
            self.recorder.record_changes(tick, changes);
        }
        let mut notices = Vec::new();
        for r in std::mem::take(&mut self.published.replies) {
            match r {
                Reply::Refused(m) => notices.push(Notice::Refused(m)),
                Reply::Swapped(n, s) => {
                    if let Some(p) = self.pending.take_if(|p| p.number == n) {
                        self.running = p;
                        self.watched.clear();
                        if self.sync == DrawingSync::Swapping {
                            self.sync = DrawingSync::Same;
                        }
                    }
                    notices.push(Notice::Swapped(s.kept, s.fresh));
                }
                Reply::SwapRefused(n, m) => {
                    if self.pending.as_ref().is_some_and(|p| p.number == n) {
                        self.pending = None;
                        self.sync = DrawingSync::Refused(
                            ladder_text::refusal::refusal(&m, ladder_text::Lang::En),
                            ladder_text::refusal::refusal(&m, ladder_text::Lang::Zh),
                        );
                    }
                    notices.push(Notice::SwapRefused(m));
                }
                Reply::Failed(m) => notices.push(Notice::Failed(m)),
            }
        }
        (true, notices)
    }

    /// After an edit: compiles the drawing and swaps it in at the next tick boundary, or
    /// says why it cannot run. Returns the compile error count when it has errors.
    pub fn follow_edit(&mut self, project: &Project, generation: u64) -> Option<usize> {
        if generation == self.seen_generation {
            return None;
        }
        self.seen_generation = generation;
        // An edited machine model takes over at the next tick, its devices' faults kept by
        // name; one with errors waits until it checks clean (the Machine page says why).
        if project.machine != self.model
            && check::errors(&project.machine, project.profile()).is_empty()
        {
            self.model = project.machine.clone();
            self.command(MachineCommand::LoadModel(Box::new(self.model.clone())));
        }
        let target = self.pending.as_ref().unwrap_or(&self.running);
        if project.ladder == target.ladder {
            if self.pending.is_none() {
                self.sync = DrawingSync::Same;
            }
            return None;
        }
        let number = self
            .running
            .number
            .max(self.pending.as_ref().map_or(0, |p| p.number))
            + 1;
        match build(project, number) {
            Ok((vm, running)) => {
                let running = Arc::new(running);
                self.pending = Some(Arc::clone(&running));
                self.sync = DrawingSync::Swapping;
                self.send(Request::Swap(Box::new(vm), number));
                None
            }
            Err(StartError::Compile(n, en, zh)) => {
                self.sync = DrawingSync::Refused(
                    format!("{n} compile error(s); the first: {en}"),
                    format!("{n} 个编译错误；第一个：{zh}"),
                );
                Some(n)
            }
            Err(StartError::Other(m)) => {
                self.sync = DrawingSync::Refused(m.clone(), m);
                None
            }
        }
    }

    /// Whether the drawing is the program that runs.
    pub fn drawing_runs(&self, project: &Project) -> bool {
        self.sync == DrawingSync::Same && project.ladder == self.running.ladder
    }

    /// The pace.
    pub fn set_speed(&mut self, s: Speed) {
        self.send(Request::Speed(s));
    }

    /// The scan engine.
    pub fn set_engine(&mut self, e: ladder_engine::vm::Engine) {
        self.send(Request::Engine(e));
    }

    /// Shows tick `t` from the recorder instead of the present (`None`: back to live).
    pub fn scrub_to(&mut self, t: Option<u64>) {
        let mut image = std::mem::take(&mut self.scrub_image);
        self.scrub = t.filter(|t| self.recorder().image_at(*t, &mut image));
        self.scrub_image = image;
    }

    /// The scan recorder.
    pub fn recorder(&self) -> &Recorder {
        &self.recorder
    }

    /// Throws the recorded ticks away (the trace's Clear).
    pub fn clear_record(&mut self) {
        self.recorder.clear();
    }

    /// The memory shown: the recorded tick while scrubbing, else the last published state.
    pub fn memory(&self) -> &[u8] {
        if self.scrub.is_some() {
            &self.scrub_image
        } else {
            &self.published.snapshot.memory
        }
    }

    /// What the monitor reads. While scrubbing, or before the state of the running program
    /// has arrived, contacts come from memory instead of the scan's record.
    pub fn source(&self) -> Source<'_> {
        let live = self.scrub.is_none()
            && self.published.program == self.running.number
            && self.published.snapshot.trace.len() == self.running.code.words().len();
        Source {
            code: &self.running.code,
            layout: &self.running.layout,
            memory: self.memory(),
            trace: live.then_some((
                &self.published.snapshot.trace[..],
                &self.published.snapshot.watched[..],
            )),
        }
    }

    /// Records the scan of exactly the code networks of `networks` (ladder networks of
    /// `block` on screen): networks nobody looks at cost nothing.
    pub fn watch_visible(&mut self, block: usize, networks: std::ops::Range<usize>) {
        let code = &self.running.code;
        let want: BTreeSet<usize> = code
            .networks
            .iter()
            .enumerate()
            .filter(|(_, n)| n.block == block && networks.contains(&n.network))
            .map(|(i, _)| i)
            .collect();
        if want == self.watched {
            return;
        }
        let off: Vec<usize> = self.watched.difference(&want).copied().collect();
        let on: Vec<usize> = want.difference(&self.watched).copied().collect();
        for n in off {
            self.command(MachineCommand::WatchNetwork(n, false));
        }
        for n in on {
            self.command(MachineCommand::WatchNetwork(n, true));
        }
        self.watched = want;
    }

    /// Whether the machine is ticking on its own.
    pub fn is_running(&self) -> bool {
        self.published.snapshot.running
    }

    /// Stops the thread and waits for it.
    pub fn stop(self) {
        let _ = self.runner.stop();
    }
}
