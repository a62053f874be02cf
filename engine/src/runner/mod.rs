//! The machine on its own thread: what the editor's online monitor runs.
//!
//! A [`Runner`] owns a [`Machine`] on a named thread (`plc-machine`) and ticks it at real
//! time (one 8 ms tick per 8 ms), at ×10 or ×100, or as fast as it can. The UI never touches
//! the machine: it sends [`Request`]s (the same [`MachineCommand`]s a stimulus script is made
//! of, plus what only a live user does: pressing and releasing a panel key, swapping in an
//! edited program) and reads the latest [`Published`] state, which the thread copies out
//! after each batch of ticks. Neither side waits for the other longer than that copy.

mod clock;
pub(crate) mod journal;

pub use clock::{Lateness, Speed};

use crate::machine::{Machine, MachineCommand, Snapshot, Target};
use crate::vm::Vm;
use crate::vm::swap::Swapped;
use clock::Clock;
use std::sync::mpsc::{self, Receiver, RecvTimeoutError, Sender};
use std::sync::{Arc, Mutex, MutexGuard};
use std::thread::JoinHandle;
use std::time::{Duration, Instant};

/// Ticks a momentary key stays pressed at least (80 ms of virtual time): longer than a
/// level-2 cycle at any division up to 9, so the ladder sees a click however short it was.
pub const MIN_PRESS_TICKS: u64 = 10;

/// How often an unchanged state is published anyway while running (the clock moves).
const IDLE_PUBLISH: Duration = Duration::from_millis(250);

/// What the UI asks of the machine.
pub enum Request {
    /// A command, as a script line would give it.
    Command(MachineCommand),
    /// Commands carried out together between two ticks (prepared values written at once).
    Batch(Vec<MachineCommand>),
    /// A momentary key goes down: its bit is written 1 now.
    Press(Target),
    /// The key is let go: its bit is written 0 once it has been 1 for [`MIN_PRESS_TICKS`].
    Release(Target),
    /// Online edit: the compiled program takes over at the next tick boundary. The number
    /// names the program in the reply.
    Swap(Box<Vm>, u64),
    /// The pace.
    Speed(Speed),
    /// Rung coverage measured from now on (from zero), or no longer ([`Vm::set_coverage`]);
    /// the published trace then carries what was seen.
    Coverage(bool),
    /// The scan engine from the next tick on ([`Vm::set_engine`]); a program swapped in
    /// later keeps it.
    Engine(crate::vm::Engine),
}

/// What the machine answered to a request.
#[derive(Clone, Debug, PartialEq)]
pub enum Reply {
    /// A command could not be carried out, and why.
    Refused(crate::refusal::Refusal),
    /// Program `n` runs now.
    Swapped(u64, Swapped),
    /// Program `n` could not take over, and why; the old one runs on.
    SwapRefused(u64, crate::refusal::Refusal),
    /// The machine thread failed; it has stopped.
    Failed(String),
}

/// The state the thread publishes.
#[derive(Clone, Debug, Default)]
pub struct Published {
    /// The machine's state after the last tick.
    pub snapshot: Snapshot,
    /// Counts publications: a UI redraws only when it moved.
    pub seq: u64,
    /// Requests carried out so far: a UI that counts what it sent knows when the state it
    /// shows includes all of it.
    pub handled: u64,
    /// The program running (the number of its [`Request::Swap`], 0 for the first).
    pub program: u64,
    /// The pace.
    pub speed: Speed,
    /// The scan engine in force (the interpreter where native code is unavailable).
    pub engine: Option<crate::vm::Engine>,
    /// How late ticks were at real time.
    pub lateness: Lateness,
    /// Replies not yet taken.
    pub replies: Vec<Reply>,
    /// The thread has ended (after a failure).
    pub stopped: bool,
    /// Memory changes tick by tick since the editor last took them (the scan recorder's
    /// feed).
    pub journal: journal::Journal,
}

struct Shared {
    state: Mutex<Published>,
}

impl Shared {
    fn lock(&self) -> MutexGuard<'_, Published> {
        // A poisoned lock only means the thread failed while publishing; the data is whole.
        self.state.lock().unwrap_or_else(|e| e.into_inner())
    }
}

/// A machine running on its own thread.
pub struct Runner {
    tx: Option<Sender<Request>>,
    shared: Arc<Shared>,
    handle: Option<JoinHandle<Machine>>,
}

/// Called on the machine thread after every tick (benchmarks, tests).
pub type TickHook = Box<dyn FnMut(&Machine) + Send>;
/// Called on the machine thread when there is something new to show, with the state just
/// published: the UI decides there whether it changes what is on screen (a repaint request).
pub type Wake = Box<dyn Fn(&Snapshot) + Send>;

impl Runner {
    /// Starts the thread. The machine keeps its running state: send
    /// `Command(MachineCommand::Run)` to start ticking.
    pub fn start(machine: Machine, on_tick: TickHook, wake: Wake) -> std::io::Result<Runner> {
        let machine_size = machine.plc().layout().size as usize;
        let (tx, rx) = mpsc::channel();
        let shared = Arc::new(Shared {
            state: Mutex::new(Published::default()),
        });
        let thread_shared = Arc::clone(&shared);
        let handle = std::thread::Builder::new()
            .name("plc-machine".into())
            .spawn(move || {
                let mut worker = Worker {
                    machine,
                    rx,
                    shared: thread_shared,
                    on_tick,
                    journaler: journal::Journaler::new(machine_size),
                    wake,
                    clock: Clock::new(Speed::RealTime),
                    releases: Vec::new(),
                    presses: Vec::new(),
                    program: 0,
                    replies: Vec::new(),
                    snapshot: Snapshot::default(),
                    last_publish: Instant::now(),
                    published_memory: Vec::new(),
                    published_cnc: None,
                    handled: 0,
                    covering: false,
                    published_handled: 0,
                };
                worker.publish(true);
                let result = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
                    worker.run();
                }));
                if let Err(e) = result {
                    let msg = e
                        .downcast_ref::<&str>()
                        .map(|s| s.to_string())
                        .or_else(|| e.downcast_ref::<String>().cloned())
                        .unwrap_or_else(|| "unknown failure".into());
                    let mut s = worker.shared.lock();
                    s.replies.push(Reply::Failed(msg));
                    s.stopped = true;
                    drop(s);
                    (worker.wake)(&worker.snapshot);
                }
                worker.machine
            })?;
        Ok(Runner {
            tx: Some(tx),
            shared,
            handle: Some(handle),
        })
    }

    /// Sends a request; a machine that has stopped ignores it.
    pub fn send(&self, request: Request) {
        if let Some(tx) = &self.tx {
            let _ = tx.send(request);
        }
    }

    /// Copies the published state into `into` when it changed since `into` was filled, and
    /// hands over the replies. Returns whether anything was new.
    pub fn take(&self, into: &mut Published) -> bool {
        let mut s = self.shared.lock();
        let replies = std::mem::take(&mut s.replies);
        if s.seq == into.seq && replies.is_empty() && into.seq != 0 {
            return false;
        }
        into.snapshot.clone_from(&s.snapshot);
        into.seq = s.seq;
        into.handled = s.handled;
        into.program = s.program;
        into.speed = s.speed;
        into.engine = s.engine;
        into.lateness = s.lateness;
        into.stopped = s.stopped;
        into.replies = replies;
        into.journal = std::mem::take(&mut s.journal);
        true
    }

    /// Stops the thread and returns the machine (`None` if the thread failed).
    pub fn stop(mut self) -> Option<Machine> {
        self.shutdown()
    }

    fn shutdown(&mut self) -> Option<Machine> {
        // Dropping the sender ends the thread's receive loop.
        self.tx = None;
        self.handle.take().and_then(|h| h.join().ok())
    }
}

impl Drop for Runner {
    fn drop(&mut self) {
        self.shutdown();
    }
}

struct Worker {
    machine: Machine,
    rx: Receiver<Request>,
    shared: Arc<Shared>,
    on_tick: TickHook,
    journaler: journal::Journaler,
    wake: Wake,
    clock: Clock,
    /// Keys let go but not yet written 0: the target and the tick from which it may be.
    releases: Vec<(Target, u64)>,
    /// Keys down: the target and the tick at which they went down.
    presses: Vec<(Target, u64)>,
    program: u64,
    replies: Vec<Reply>,
    snapshot: Snapshot,
    last_publish: Instant,
    published_memory: Vec<u8>,
    published_cnc: Option<crate::cnc::CncStatus>,
    /// Whether rung coverage is measured (kept across an online edit).
    covering: bool,
    handled: u64,
    published_handled: u64,
}

impl Worker {
    fn run(&mut self) {
        loop {
            // Wait for a request, or until the next tick is due.
            let request = if self.machine.running() {
                let wait = self.clock.until_due(Instant::now());
                match self.rx.recv_timeout(wait) {
                    Ok(r) => Some(r),
                    Err(RecvTimeoutError::Timeout) => None,
                    Err(RecvTimeoutError::Disconnected) => return,
                }
            } else {
                match self.rx.recv() {
                    Ok(r) => Some(r),
                    Err(_) => return,
                }
            };
            let mut changed = false;
            if let Some(r) = request {
                self.handle(r);
                changed = true;
                // Take whatever else is queued before ticking.
                while let Ok(r) = self.rx.try_recv() {
                    self.handle(r);
                }
            }
            if self.machine.running() {
                let due = self
                    .clock
                    .due_ticks(Instant::now(), self.machine.plc().ticks());
                for _ in 0..due {
                    self.tick();
                }
                changed |= due > 0;
            }
            if changed {
                self.publish(false);
            }
        }
    }

    fn tick(&mut self) {
        let now = Instant::now();
        self.clock.ticked(now, self.machine.plc().ticks());
        self.machine.tick();
        (self.on_tick)(&self.machine);
        self.journaler
            .note(self.machine.plc().ticks(), self.machine.plc().image());
        if self.journaler.pending() >= journal::HAND_OVER_TICKS {
            // A quiet image at full speed publishes rarely: hand the ticks over now, so the
            // machine thread's own buffer stays small (the editor takes them at its next look).
            let mut s = self.shared.lock();
            self.journaler.hand_over(&mut s.journal);
        }
        let t = self.machine.plc().ticks();
        let mut k = 0;
        while k < self.releases.len() {
            if self.releases[k].1 <= t {
                let (target, _) = self.releases.swap_remove(k);
                self.command(MachineCommand::Write(target, 0));
            } else {
                k += 1;
            }
        }
    }

    fn command(&mut self, cmd: MachineCommand) {
        let was_running = self.machine.running();
        if let MachineCommand::Tick(n) = cmd {
            for _ in 0..n {
                self.tick();
            }
        } else if let Err(e) = self.machine.apply(&cmd) {
            self.replies.push(Reply::Refused(e));
        }
        if !was_running && self.machine.running() {
            self.clock
                .restart(Instant::now(), self.machine.plc().ticks());
        }
    }

    fn handle(&mut self, r: Request) {
        self.handled += 1;
        match r {
            Request::Command(c) => self.command(c),
            Request::Batch(cs) => {
                for c in cs {
                    self.command(c);
                }
            }
            Request::Press(t) => {
                self.releases.retain(|(r, _)| *r != t);
                self.presses.retain(|(p, _)| *p != t);
                self.presses.push((t, self.machine.plc().ticks()));
                self.command(MachineCommand::Write(t, 1));
            }
            Request::Release(t) => {
                let since = self
                    .presses
                    .iter()
                    .position(|(p, _)| *p == t)
                    .map(|i| self.presses.swap_remove(i).1)
                    .unwrap_or(0);
                let from = since + MIN_PRESS_TICKS;
                if from <= self.machine.plc().ticks() {
                    self.command(MachineCommand::Write(t, 0));
                } else {
                    self.releases.push((t, from));
                }
            }
            Request::Swap(vm, n) => match self.machine.swap(*vm) {
                Ok(s) => {
                    // Coverage goes on over the new program, from zero: its words differ.
                    if self.covering {
                        self.machine.plc_mut().set_coverage(true);
                    }
                    self.program = n;
                    self.replies.push(Reply::Swapped(n, s));
                }
                Err(e) => self
                    .replies
                    .push(Reply::SwapRefused(n, crate::refusal::Refusal::Swap(e))),
            },
            Request::Speed(s) => {
                self.clock = Clock::new(s);
                self.clock
                    .restart(Instant::now(), self.machine.plc().ticks());
            }
            Request::Coverage(on) => {
                self.covering = on;
                self.machine.plc_mut().set_coverage(on);
            }
            Request::Engine(engine) => {
                self.machine.plc_mut().set_engine(engine);
            }
        }
    }

    /// Copies the state out; wakes the UI when it changed (or now and then while running,
    /// for the clock).
    fn publish(&mut self, force: bool) {
        self.machine.snapshot_into(&mut self.snapshot);
        let now = Instant::now();
        let moved = self.snapshot.memory != self.published_memory
            || self.snapshot.cnc != self.published_cnc;
        let wake = force
            || moved
            || self.handled != self.published_handled
            || !self.replies.is_empty()
            || now.duration_since(self.last_publish) >= IDLE_PUBLISH
            || !self.machine.running();
        if !wake {
            return;
        }
        self.published_memory.clone_from(&self.snapshot.memory);
        self.published_cnc.clone_from(&self.snapshot.cnc);
        self.published_handled = self.handled;
        self.last_publish = now;
        {
            let mut s = self.shared.lock();
            s.seq += 1;
            s.handled = self.handled;
            s.program = self.program;
            s.speed = self.clock.speed();
            s.engine = Some(self.machine.plc().engine());
            s.lateness = self.clock.lateness();
            s.replies.append(&mut self.replies);
            self.journaler.hand_over(&mut s.journal);
            // The state stays in our copy too, for the wake's look at it after the lock.
            s.snapshot.clone_from(&self.snapshot);
        }
        (self.wake)(&self.snapshot);
    }
}

#[cfg(test)]
mod tests;
