//! [`Engine::Checked`](super::Engine::Checked): every level run natively and then again,
//! from the same state, by the interpreter, which must end with the same memory image,
//! instruction memories, steps and outcome.
//!
//! The CNC answers each call once: the native run talks to the real CNC through
//! [`Recording`], which keeps every answer (and each window block as the CNC left it); the
//! interpreter's run is answered from that record by [`Replay`], which also checks that the
//! interpreter asks the same questions in the same order. So a WINDR write reaches the CNC
//! once, and both runs see the same CNC.

use super::super::cnc::{AxisStatus, Cnc};
use super::super::exec::Level;
use super::super::{Halt, InstState, Vm};
use std::cell::{Cell, RefCell};

/// One question the scan asked the CNC, with its answer.
#[derive(Clone, Debug, PartialEq)]
enum Call {
    LowSpeed(i32, bool),
    /// The block handed over and the block handed back.
    Window(Vec<i32>, Vec<i32>),
    Position(u32, Option<i64>),
    Axis(u8, bool, AxisStatus),
}

/// The real CNC, with a record of every call.
struct Recording<'a> {
    inner: &'a mut dyn Cnc,
    log: RefCell<Vec<Call>>,
}

impl Cnc for Recording<'_> {
    fn window_is_low_speed(&self, function: i32) -> bool {
        let answer = self.inner.window_is_low_speed(function);
        self.log.borrow_mut().push(Call::LowSpeed(function, answer));
        answer
    }
    fn window(&mut self, block: &mut [i32]) {
        let given = block.to_vec();
        self.inner.window(block);
        self.log
            .borrow_mut()
            .push(Call::Window(given, block.to_vec()));
    }
    fn machine_position(&self, axis: u32) -> Option<i64> {
        let answer = self.inner.machine_position(axis);
        self.log.borrow_mut().push(Call::Position(axis, answer));
        answer
    }
    fn axis_status(&self, group: u8, ebuf: bool) -> AxisStatus {
        let answer = self.inner.axis_status(group, ebuf);
        self.log.borrow_mut().push(Call::Axis(group, ebuf, answer));
        answer
    }
    fn exchange(&mut self, now_ms: u64, g: &[u8], a: &[u8], f: &mut [u8]) {
        self.inner.exchange(now_ms, g, a, f);
    }
}

/// The record played back; the first question that differs from the record is kept.
struct Replay<'a> {
    log: &'a [Call],
    next: Cell<usize>,
    differs: RefCell<Option<String>>,
}

impl Replay<'_> {
    /// The recorded call at the current position, if `matches` accepts it.
    fn take<T>(&self, asked: String, answer: impl Fn(&Call) -> Option<T>) -> Option<T> {
        let i = self.next.get();
        self.next.set(i + 1);
        let found = self.log.get(i).and_then(&answer);
        if found.is_none() && self.differs.borrow().is_none() {
            *self.differs.borrow_mut() = Some(format!(
                "CNC call {i}: the interpreter asked {asked}, the native code {:?}",
                self.log.get(i)
            ));
        }
        found
    }
}

impl Cnc for Replay<'_> {
    fn window_is_low_speed(&self, function: i32) -> bool {
        self.take(format!("LowSpeed({function})"), |c| match c {
            Call::LowSpeed(f, a) if *f == function => Some(*a),
            _ => None,
        })
        .unwrap_or(false)
    }
    fn window(&mut self, block: &mut [i32]) {
        let given = block.to_vec();
        if let Some(back) =
            self.take(
                format!("Window({:?})", &given[..8.min(given.len())]),
                |c| match c {
                    Call::Window(g, back) if *g == given => Some(back.clone()),
                    _ => None,
                },
            )
        {
            block.copy_from_slice(&back);
        }
    }
    fn machine_position(&self, axis: u32) -> Option<i64> {
        self.take(format!("Position({axis})"), |c| match c {
            Call::Position(a, p) if *a == axis => Some(*p),
            _ => None,
        })
        .flatten()
    }
    fn axis_status(&self, group: u8, ebuf: bool) -> AxisStatus {
        self.take(format!("Axis({group}, {ebuf})"), |c| match c {
            Call::Axis(g, e, s) if *g == group && *e == ebuf => Some(*s),
            _ => None,
        })
        .unwrap_or_default()
    }
    fn exchange(&mut self, _now_ms: u64, _g: &[u8], _a: &[u8], _f: &mut [u8]) {}
}

/// What a level's run may change.
#[derive(Clone, PartialEq)]
struct State {
    mem: Vec<u8>,
    states: Vec<InstState>,
    latches: Vec<Vec<i32>>,
    executed: u64,
    cycle_steps: u64,
}

impl State {
    fn of(vm: &Vm) -> State {
        State {
            mem: vm.mem.clone(),
            states: vm.states.clone(),
            latches: vm.latches.clone(),
            executed: vm.executed,
            cycle_steps: vm.level2.cycle_steps,
        }
    }

    fn restore(&self, vm: &mut Vm) {
        vm.mem.copy_from_slice(&self.mem);
        vm.states.copy_from_slice(&self.states);
        vm.latches.clone_from(&self.latches);
        vm.executed = self.executed;
        vm.level2.cycle_steps = self.cycle_steps;
    }

    /// The first difference from `other`, in words.
    fn difference(&self, other: &State) -> Option<String> {
        if let Some(i) = (0..self.mem.len()).find(|&i| self.mem[i] != other.mem[i]) {
            return Some(format!(
                "memory byte {i}: native {:#04x}, interpreter {:#04x}",
                self.mem[i], other.mem[i]
            ));
        }
        if let Some(i) = (0..self.states.len()).find(|&i| self.states[i] != other.states[i]) {
            return Some(format!(
                "instruction memory {i}: native {:?}, interpreter {:?}",
                self.states[i], other.states[i]
            ));
        }
        if self.latches != other.latches {
            return Some("a WINDR latch".into());
        }
        if (self.executed, self.cycle_steps) != (other.executed, other.cycle_steps) {
            return Some(format!(
                "steps: native {} ({} this cycle), interpreter {} ({} this cycle)",
                self.executed, self.cycle_steps, other.executed, other.cycle_steps
            ));
        }
        None
    }
}

impl Vm {
    /// Runs a level natively, then from the same state by the interpreter; panics at the
    /// first difference (see the module documentation). The interpreter's result stays.
    pub(super) fn run_checked(
        &mut self,
        pc: u32,
        level: Level,
        quota: u64,
        cnc: &mut dyn Cnc,
    ) -> Result<Option<u32>, Halt> {
        let before = State::of(self);
        let mut recording = Recording {
            inner: cnc,
            log: RefCell::new(Vec::new()),
        };
        let native = self.run_native(pc, level, quota, &mut recording);
        let after_native = State::of(self);
        before.restore(self);
        let log = recording.log.into_inner();
        let mut replay = Replay {
            log: &log,
            next: Cell::new(0),
            differs: RefCell::new(None),
        };
        let interp = self.run_interp(pc, level, quota, &mut replay);
        let mut differs = replay.differs.into_inner();
        if differs.is_none() && replay.next.get() != log.len() {
            differs = Some(format!(
                "the native code asked the CNC {} questions, the interpreter {}",
                log.len(),
                replay.next.get()
            ));
        }
        let differs = differs
            .or_else(|| after_native.difference(&State::of(self)))
            .or_else(|| {
                (native != interp)
                    .then(|| format!("outcome: native {native:?}, interpreter {interp:?}"))
            });
        if let Some(what) = differs {
            panic!(
                "the native scan engine and the interpreter differ at tick {} ({level:?}, from word {pc}): {what}",
                self.ticks
            );
        }
        interp
    }
}
