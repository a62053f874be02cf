//! The interpreter loop. Logic state lives in locals: the accumulator as 0/1, and the block
//! and branch stacks as bit stacks in two `u64` (their depth limits, 32 and 16, fit), so
//! pushing and popping is a shift. The loop is instantiated twice: without tracing (the
//! normal case, no extra work) and with tracing for watched networks; a `Net` word switches.

use super::cnc::Cnc;
use super::code::{C_INVERT, CONTACT_END, VmOp, byte};
use super::functions::{self, Ctx};
use super::memory::write_bit;
use super::{Frame, Halt, HaltReason, IMAGE_BYTES, Vm, WATCHDOG_STEPS};

use crate::address::Area;

/// Which level is running.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Level {
    One,
    Two,
}

enum Exit {
    /// The level's code ended.
    Done,
    /// Level 2 reached its quota; resume at this word next tick.
    Suspend(u32),
    /// Continue at this word in the other tracing mode.
    Switch(u32),
    /// The watchdog stopped the PLC at this word.
    Watchdog(u32),
    /// An unwatched network of the level itself starts at this word: native code may run it
    /// (only while [`Vm::run_watched`] runs).
    Native(u32),
}

/// How the interpreter's part of a native run ended ([`Vm::run_watched`]).
pub(super) enum Handback {
    /// Native code goes on at this network marker.
    Native(u32),
    /// The level's code ended.
    Done,
    /// Level 2 reached its quota at this word.
    Suspend(u32),
    /// The watchdog stopped the PLC at this word.
    Watchdog(u32),
}

impl Vm {
    /// Runs a level from word `pc` in the interpreter. Returns where level 2 stopped for this
    /// tick (`None` when it reached its end), or why the PLC halted.
    pub(super) fn run_interp(
        &mut self,
        pc: u32,
        level: Level,
        quota: u64,
        cnc: &mut dyn Cnc,
    ) -> Result<Option<u32>, Halt> {
        let mut pc = pc;
        let mut tracing = false;
        let mut steps = 0u64;
        let result = loop {
            let exit = if tracing {
                self.exec::<true>(pc, level, quota, &mut steps, cnc)
            } else {
                self.exec::<false>(pc, level, quota, &mut steps, cnc)
            };
            match exit {
                Exit::Switch(p) => {
                    pc = p;
                    tracing = !tracing;
                }
                Exit::Done => break Ok(None),
                Exit::Suspend(p) => break Ok(Some(p)),
                Exit::Watchdog(at) => break Err(self.halt_at(at, level)),
                Exit::Native(_) => unreachable!("only `run_watched` hands back"),
            }
        };
        self.end_run(level, steps);
        result
    }

    /// After a level's run on either engine: its steps counted, no caller left.
    pub(super) fn end_run(&mut self, level: Level, steps: u64) {
        if level == Level::Two {
            self.level2.cycle_steps += steps;
        }
        self.executed += steps;
        self.frames.clear();
    }

    /// The watchdog's budget for a run of `level`: a level-1 scan's limit, or what is left
    /// of level 2's for its cycle.
    pub(super) fn watchdog_budget(&self, level: Level) -> u64 {
        if level == Level::One {
            WATCHDOG_STEPS
        } else {
            WATCHDOG_STEPS.saturating_sub(self.level2.cycle_steps)
        }
    }

    /// Runs the watched network at word `pc` and on in the interpreter, recording for the
    /// monitor, until the level reaches an unwatched network of its own (outside any call),
    /// where native code takes over again; `steps` counts on.
    pub(super) fn run_watched(
        &mut self,
        pc: u32,
        level: Level,
        quota: u64,
        steps: &mut u64,
        cnc: &mut dyn Cnc,
    ) -> Handback {
        self.handing_back = true;
        let mut pc = pc;
        let mut tracing = true;
        let handback = loop {
            let exit = if tracing {
                self.exec::<true>(pc, level, quota, steps, cnc)
            } else {
                self.exec::<false>(pc, level, quota, steps, cnc)
            };
            match exit {
                Exit::Switch(p) => {
                    pc = p;
                    tracing = !tracing;
                }
                Exit::Native(p) => break Handback::Native(p),
                Exit::Done => break Handback::Done,
                Exit::Suspend(p) => break Handback::Suspend(p),
                Exit::Watchdog(p) => break Handback::Watchdog(p),
            }
        };
        self.handing_back = false;
        handback
    }

    pub(super) fn halt_at(&self, pc: u32, level: Level) -> Halt {
        let net = self
            .code
            .networks
            .iter()
            .find(|n| n.start <= pc && pc < n.end.max(n.start + 1));
        let (block, network) =
            net.map_or(("?".to_string(), 0), |n| (n.label.clone(), n.network + 1));
        Halt {
            block,
            network,
            reason: HaltReason::Watchdog {
                level: if level == Level::One { 1 } else { 2 },
                steps: WATCHDOG_STEPS,
            },
        }
    }

    fn exec<const TRACE: bool>(
        &mut self,
        pc: u32,
        level: Level,
        quota: u64,
        steps_out: &mut u64,
        cnc: &mut dyn Cnc,
    ) -> Exit {
        let budget = self.watchdog_budget(level);
        let now = self.now_ms();
        let forcing = !self.forced_bytes.is_empty();
        let watching = self.switching::<TRACE>();
        let mut r = Regs {
            pc,
            acc: 0,
            blocks: 0,
            branches: 0,
            steps: *steps_out,
        };
        // Level 1 never stops at a network; level 2 stops when its quota is reached.
        let quota = if level == Level::One { u64::MAX } else { quota };
        loop {
            let image: &mut [u8; IMAGE_BYTES] = (&mut self.mem[..])
                .try_into()
                .expect("the image is IMAGE_BYTES long");
            let at = hot::<TRACE>(
                self.code.words(),
                image,
                &mut self.trace,
                &mut r,
                &Stops {
                    // While handing back, stop at every network marker: the check is here.
                    quota: if self.handing_back { 0 } else { quota },
                    watching,
                    watched: &self.watched,
                    forcing,
                },
            );
            let w = self.code.words()[at as usize];
            let arg = w >> 8;
            r.pc = at + 1;
            let Some(op) = VmOp::decode(w) else {
                unreachable!("Executable::checked refused every word without an opcode");
            };
            match op {
                VmOp::Net => {
                    if level == Level::Two && self.frames.is_empty() && r.steps >= quota {
                        *steps_out = r.steps;
                        return Exit::Suspend(at);
                    }
                    if self.handing_back && self.frames.is_empty() && !self.watched[arg as usize] {
                        *steps_out = r.steps;
                        return Exit::Native(at);
                    }
                    if watching && self.watched[arg as usize] != TRACE {
                        *steps_out = r.steps;
                        return Exit::Switch(at);
                    }
                }
                VmOp::Out | VmOp::Outn => {
                    // Only while forcing: the write is followed by the forces.
                    if TRACE {
                        record(&mut self.trace, at, r.acc);
                    }
                    let v = r.acc ^ u32::from(op == VmOp::Outn);
                    write_bit(&mut self.mem, arg, v);
                    self.apply_forces();
                    r.steps += 1;
                }
                VmOp::Set | VmOp::Rst => {
                    if TRACE {
                        record(&mut self.trace, at, r.acc);
                    }
                    if r.acc != 0 {
                        write_bit(&mut self.mem, arg, u32::from(op == VmOp::Set));
                        self.apply_forces();
                    }
                    r.steps += 2;
                }
                VmOp::Lbl => r.steps += 2,
                VmOp::Jmpb => {
                    if TRACE {
                        record(&mut self.trace, at, r.acc);
                    }
                    r.steps += 2;
                    if r.acc != 0 {
                        if arg < r.pc && r.steps > budget {
                            *steps_out = r.steps;
                            return Exit::Watchdog(at);
                        }
                        r.pc = arg;
                    }
                }
                VmOp::Call | VmOp::Callu => {
                    let unconditional = op == VmOp::Callu;
                    if TRACE {
                        record(&mut self.trace, at, r.acc);
                    }
                    r.steps += 2;
                    if r.acc != 0 || unconditional {
                        self.frames.push(Frame {
                            ret: r.pc,
                            acc: r.acc,
                            blocks: r.blocks,
                            branches: r.branches,
                        });
                        r.pc = arg;
                    }
                }
                VmOp::Fn => {
                    if TRACE {
                        record(&mut self.trace, at, r.acc);
                    }
                    r.steps += u64::from(self.code.fns[arg as usize].cost);
                    self.exec_fn(arg, r.acc != 0, now, cnc);
                    if TRACE && r.acc != 0 {
                        self.record_outcome(at, arg);
                    }
                }
                VmOp::Ret => match self.frames.pop() {
                    None => {
                        *steps_out = r.steps;
                        return Exit::Done;
                    }
                    Some(fr) => {
                        r.pc = fr.ret;
                        r.acc = fr.acc;
                        r.blocks = fr.blocks;
                        r.branches = fr.branches;
                    }
                },
                VmOp::And
                | VmOp::Ani
                | VmOp::Or
                | VmOp::Ori
                | VmOp::Ld
                | VmOp::Ldi
                | VmOp::LdStart
                | VmOp::LdiStart
                | VmOp::Orb
                | VmOp::Anb
                | VmOp::Mps
                | VmOp::Mrd
                | VmOp::Mpp => unreachable!("the hot loop runs every other basic word"),
            }
        }
    }
}

impl Vm {
    /// Runs function instruction `index` with ACT = `act`, then the forces: the one way both
    /// engines run one.
    pub(super) fn exec_fn(&mut self, index: u32, act: bool, now: u64, cnc: &mut dyn Cnc) {
        let g_base = self.layout.area_range(Area::G).start as u32;
        let d_range = self.layout.area_range(Area::D);
        let Vm {
            code,
            mem,
            states,
            window,
            latches,
            ..
        } = self;
        let f = &code.fns[index as usize];
        let mut cx = Ctx {
            mem,
            consts: &code.consts,
            now,
            cnc,
            window,
            latch: &mut latches[f.state as usize],
            g_base,
            d_range,
        };
        functions::exec(f, act, &mut states[f.state as usize], &mut cx);
        if !self.forced_bytes.is_empty() {
            self.apply_forces();
        }
    }

    /// Whether recording may start or stop at a network marker: recording, unless every
    /// network is recorded (coverage); not recording, when any network is watched.
    fn switching<const TRACE: bool>(&self) -> bool {
        if TRACE {
            !self.covering
        } else {
            self.watch_count > 0
        }
    }
}

impl Vm {
    /// Records the result the compare of function instruction `index` at word `at` took.
    fn record_outcome(&mut self, at: u32, index: u32) {
        let outcome = functions::outcome(&self.code.fns[index as usize], &self.mem);
        record_outcome(&mut self.trace, at, outcome);
    }
}

/// Records a compare's result (bits 3 to 5) for coverage; nothing for [`functions::NO_OUTCOME`].
fn record_outcome(trace: &mut [u8], at: u32, outcome: u8) {
    if outcome < functions::NO_OUTCOME {
        trace[at as usize] |= 8 << outcome;
    }
}

/// Records what word `at` read or received (bit 0, for the monitor) and that this value was
/// seen (bit 1 for 0, bit 2 for 1, for coverage): one write either way.
#[inline(always)]
fn record(trace: &mut [u8], at: u32, v: u32) {
    let t = &mut trace[at as usize];
    *t = (*t & SEEN) | (v as u8 & 1) | (2 << (v & 1));
}

/// Per contact opcode (bits 2·op and 2·op + 1 for the accumulator at 0 and at 1): whether
/// the contact's value decides the step's result. With the flags of `code::C_*`, the result
/// is `(acc & (v | OR)) | (v & LOAD_OR)`, which depends on v exactly when
/// `(acc | LOAD_OR) ^ (acc & OR)` is 1: LD always, AND with power on its left, OR while the
/// branch it joins is off.
const DECIDES: u64 = {
    let mut table = 0u64;
    let mut op = 0;
    while op < CONTACT_END as u64 {
        let (or, load_or) = (op >> 1 & 1, op >> 2 & 1);
        let mut acc = 0;
        while acc < 2 {
            table |= (((acc | load_or) ^ (acc & or)) & 1) << (op << 1 | acc);
            acc += 1;
        }
        op += 1;
    }
    table
};

/// Whether a contact with opcode `op` decides its step when it meets accumulator `acc`.
pub(crate) fn decides(op: u32, acc: u32) -> bool {
    op < CONTACT_END && DECIDES >> (op << 1 | (acc & 1)) & 1 == 1
}

/// Records what a contact read (bit 0, for the monitor) and, for coverage, that this value
/// met this accumulator: bit 1 + (2·value + acc). The same few operations as [`record`].
#[inline(always)]
fn record_contact(trace: &mut [u8], at: u32, raw: u32, acc: u32) {
    let t = &mut trace[at as usize];
    // Both are 0 or 1 here (a bit read; the accumulator), so no masking.
    *t = (*t & SEEN) | raw as u8 | (2u8 << (raw * 2 + acc));
}

/// The bits of a trace byte that say what was seen: bits 1 and 2 the values 0 and 1, bits 3
/// to 5 a compare's three results ([`functions::NO_OUTCOME`]); a contact's bits 1 to 4 the
/// four pairs of its value and the accumulator it met ([`record_contact`]).
pub(super) const SEEN: u8 = 0b11_1110;

/// What the hot loop needs to know besides code, memory and registers.
#[derive(Clone, Copy)]
struct Stops<'a> {
    /// Level 2's quota for this slice (`u64::MAX`: never stop at a network; 0: at every one).
    quota: u64,
    /// Whether recording may start or stop at a network marker (see `Vm::exec`).
    watching: bool,
    /// Which networks are.
    watched: &'a [bool],
    /// Whether forces are active (coil writes then go through the outer loop).
    forcing: bool,
}

/// The logic registers.
struct Regs {
    pc: u32,
    acc: u32,
    blocks: u64,
    branches: u64,
    steps: u64,
}

/// Runs basic bit words (and passes network markers) until a word that needs the rest of
/// the machine; returns its index. Kept small so its few values stay in registers.
#[inline(never)]
fn hot<const TRACE: bool>(
    words: &[u32],
    mem: &mut [u8; IMAGE_BYTES],
    trace: &mut [u8],
    r: &mut Regs,
    stops: &Stops<'_>,
) -> u32 {
    let Stops {
        quota,
        watching,
        watched,
        forcing,
    } = *stops;
    // As long as the code (one trace byte per word): an index that reads a word needs no
    // second bounds check to record it. Untouched when nothing records.
    let trace = if TRACE {
        &mut trace[..words.len()]
    } else {
        trace
    };
    let mut pc = r.pc;
    let mut acc = r.acc;
    let mut blocks = r.blocks;
    let mut branches = r.branches;
    let mut steps = r.steps;
    let stop = loop {
        let at = pc;
        let w = words[pc as usize];
        let arg = w >> 8;
        // Masking keeps the index inside the fixed-size image, so no bounds check is needed;
        // lowering only ever writes indices inside the layout.
        let index = (arg >> 3) as usize & (IMAGE_BYTES - 1);
        let shift = arg & 7;
        pc += 1;
        let op = w & 0xFF;
        match op {
            0..CONTACT_END => {
                // Every contact form: the opcode's bits are its flags (see `code::C_*`).
                let raw = u32::from(mem[index] >> shift) & 1;
                if TRACE {
                    // With the accumulator it met: coverage counts the value only where it
                    // decided the step ([`decides`]), worked out when the report is made.
                    record_contact(trace, at, raw, acc);
                }
                let v = raw ^ (op & C_INVERT);
                let push = u64::from(op >> 3 & 1);
                let keep = u64::from(op >> 4 & 1).wrapping_sub(1);
                blocks = (blocks << push | u64::from(acc) & push) & keep;
                branches &= keep;
                acc = (acc & (v | (op >> 1 & 1))) | (v & (op >> 2 & 1));
            }
            byte::ORB => {
                acc |= (blocks & 1) as u32;
                blocks >>= 1;
            }
            byte::ANB => {
                acc &= (blocks & 1) as u32;
                blocks >>= 1;
            }
            byte::MPS => branches = branches << 1 | u64::from(acc),
            byte::MRD => acc = (branches & 1) as u32,
            byte::MPP => {
                acc = (branches & 1) as u32;
                branches >>= 1;
            }
            byte::OUT | byte::OUTN => {
                if forcing {
                    break at;
                }
                if TRACE {
                    record(trace, at, acc);
                }
                let byte = &mut mem[index];
                *byte = (*byte & !(1 << shift)) | (((acc ^ (op & 1)) as u8) << shift);
            }
            byte::SET | byte::RST => {
                // As the coils: here unless forces must follow the write. Two steps.
                if forcing {
                    break at;
                }
                if TRACE {
                    record(trace, at, acc);
                }
                if acc != 0 {
                    let byte = &mut mem[index];
                    *byte = (*byte & !(1 << shift)) | (u8::from(op == byte::SET) << shift);
                }
                steps += 1;
            }
            byte::NET => {
                // Leave only to suspend level 2, or where recording starts or stops.
                if steps >= quota || (watching && watched[arg as usize] != TRACE) {
                    break at;
                }
                continue;
            }
            _ => break at,
        }
        steps += 1;
    };
    r.pc = pc;
    r.acc = acc;
    r.blocks = blocks;
    r.branches = branches;
    r.steps = steps;
    stop
}

#[cfg(test)]
mod tests {
    use super::super::cnc::NoCnc;
    use super::super::{Halt, HaltReason, Vm, WATCHDOG_STEPS};
    use crate::address::Address;

    /// A PLC whose level (`LEVEL1` or `LEVEL2`) spins in a JMPB loop while X0001.0 is on.
    fn spinning(level: &str) -> Vm {
        let text = format!(
            "LEVEL1\nNETWORK\nLD X0000.0\nOUT R0000.0\n{level}\nNETWORK\nLBL L0001\nNETWORK\nLD X0001.0\nJMPB L0001\n"
        );
        let project = crate::il::import(&text).project.expect("draws");
        let mut vm = Vm::new(&project).unwrap();
        vm.write(Address::parse("X1.0").unwrap(), 1, 1);
        vm.tick(&mut NoCnc);
        vm
    }

    #[test]
    fn a_halt_names_its_level_network_and_the_watchdog_steps() {
        for (level, n) in [("LEVEL1", 1), ("LEVEL2", 2)] {
            let vm = spinning(level);
            let halt = vm.halt().expect("halted");
            let network = if level == "LEVEL1" { 3 } else { 2 };
            assert_eq!(
                *halt,
                Halt {
                    block: level.to_string(),
                    network,
                    reason: HaltReason::Watchdog {
                        level: n,
                        steps: WATCHDOG_STEPS,
                    },
                }
            );
        }
    }
}
