//! Automatic operation (docs/cnc.md, "Automatic operation" and "MST interface"): the run
//! states, cycle start and feed hold, starting and ending blocks, subprograms, program end,
//! the output of a block's M/S/T functions, and program motion; `mst.rs` runs the
//! handshake.

use super::frame::{Cursor, Frame, MDI};
use super::macro_b::run::Flow;
use super::macro_b::{Locals, MacroBlock, MacroCall};
use super::modal::{Modal, RunState};
use super::motion::Motion;
use super::mst::{MF, MF2, MF3, Mst, SF, TF};
use super::params::{P6711, P6712};
use super::path::{SegKind, Segment};
use super::program::{MDI_NUMBER, NcBlock, NcProgram};
use super::ps;
use super::word::{OneShot, Words, special_m};
use super::{AXES, Mode, SimCnc};

/// Blocks skipped (or subprogram ends passed) in a row before P/S 0079 is raised.
const PASS_LIMIT: u32 = 100_000;

/// The executing block.
#[derive(Clone, Copy, Debug)]
pub(super) struct Exec {
    /// The motion of the current segment.
    pub(super) motion: Option<Motion>,
    /// The current segment (its kind, feed and reference-point arrival).
    pub(super) current: Segment,
    /// Index of the next segment in `Auto::segs`.
    pub(super) seg: u16,
    /// Segments of the block.
    pub(super) seg_count: u16,
    /// The exchange the last segment ended in.
    pub(super) done_at: u64,
    /// The current thread segment waits for the one-rotation signal.
    pub(super) wait_rev: bool,
    pub(super) dwell_ms: f64,
    pub(super) dwell_total: f64,
    pub(super) mst: Mst,
    pub(super) stop_after: bool,
    pub(super) end: bool,
    /// M98/M97: the program and block called, and how many times.
    pub(super) call: Option<(usize, usize, u32)>,
    pub(super) ret: bool,
    /// M99 P: the sequence number of the caller's block to return to.
    pub(super) ret_to: Option<u32>,
    pub(super) offset: Option<u8>,
    pub(super) line: usize,
    /// G70: run blocks P to Q (indices), then come back to the start point.
    pub(super) g70: Option<(usize, usize, [i64; AXES])>,
    /// G71–G73: the block the program goes on at.
    pub(super) resume: Option<usize>,
    /// Macro statements ran ahead of the block: where the program goes on.
    pub(super) next: Option<Cursor>,
    /// The statements that ran ahead stopped in a loop: they go on each exchange.
    pub(super) ahead_waiting: bool,
    /// A move under G66: the modal call follows the block.
    pub(super) modal_call: bool,
}

impl Exec {
    /// The current segment's motion and dwell are over.
    pub(super) fn segment_done(&self) -> bool {
        self.motion.is_none_or(|m| m.done()) && self.dwell_ms >= self.dwell_total
    }

    /// Every segment of the block is over.
    pub(super) fn motion_done(&self) -> bool {
        self.segment_done() && self.seg >= self.seg_count
    }

    /// The machine target minus position of the executing motion, per axis.
    pub(super) fn remaining(&self, n: usize) -> i64 {
        self.motion
            .map_or(0, |m| m.target[n] - m.position_at(n, m.covered))
    }
}

/// Automatic operation.
#[derive(Clone, Debug, Default)]
pub(super) struct Auto {
    pub state: RunState,
    /// The program run or resumed is the MDI buffer.
    mdi: bool,
    pub(super) cursor: Cursor,
    pub(super) stack: Vec<Frame>,
    pub exec: Option<Exec>,
    /// The executing block's segments (kept to reuse its allocation).
    pub segs: Vec<Segment>,
    /// G50 X/Z coordinate shift per axis, part of the workpiece offset.
    pub shift: [i64; AXES],
    /// The last motion segment started was a thread.
    pub prev_thread: bool,
    /// The G70 block returned to after its profile: the start point it moves back to.
    pub g70_return: Option<[i64; AXES]>,
    /// Feed hold came during a thread: it takes effect when the thread ends.
    hold_after_thread: bool,
    pub interrupted: bool,
    pending_stop: bool,
    pub last_n: u32,
    pub modal: Modal,
    pub tool_offset: u8,
    pub dm99: bool,
    /// Local variables per macro call level (level 0 first; empty until one is written).
    pub(super) locals: Vec<Locals>,
    /// The G66 call in effect.
    pub(super) g66: Option<MacroCall>,
    /// #3003 and #3004.
    pub(super) m3003: u8,
    pub(super) m3004: u8,
    /// Macro variables written so far (a loop that writes none waits for the next exchange).
    pub(super) macro_writes: u64,
    /// The last jump back of a macro loop: program, block and writes then.
    pub(super) idle_mark: Option<(usize, usize, u64)>,
    /// The last M, S and T words read (#4113, #4119, #4120).
    pub(super) last_m: Option<u32>,
    pub(super) last_s: Option<u32>,
    pub(super) last_t: Option<u32>,
    /// The sequence number of the block read last, statement or NC block (#4114).
    pub(super) read_n: u32,
}

impl Auto {
    /// Rewinds the program being run to its first block.
    pub fn rewind_all(&mut self) {
        self.cursor = Cursor {
            prog: if self.mdi { MDI } else { 0 },
            block: 0,
        };
        self.stack.clear();
        self.exec = None;
        self.interrupted = false;
        self.pending_stop = false;
        self.prev_thread = false;
        self.hold_after_thread = false;
        self.g70_return = None;
        self.locals.clear();
        self.g66 = None;
        self.idle_mark = None;
    }

    /// A reset condition: IDLE and rewound; modal data, S and the tool offset are kept.
    pub fn reset(&mut self) {
        self.state = RunState::Idle;
        self.rewind_all();
        self.dm99 = false;
        self.m3003 = 0;
        self.m3004 = 0;
    }

    /// The mode changes to `new`.
    pub fn mode_change(&mut self, new: Mode) {
        if self.state == RunState::Run {
            match new {
                Mode::Jog | Mode::Handle | Mode::Ref => self.state = RunState::Hold,
                _ => self.pending_stop = true,
            }
        }
    }

    /// Whether the program being run is the MDI buffer.
    pub fn running_mdi(&self) -> bool {
        self.mdi && self.state != RunState::Idle
    }

    /// Whether the cursor (or the executing block) is in the MDI buffer.
    pub fn at_mdi(&self) -> bool {
        self.cursor.prog == MDI
    }

    /// The line of the block at the cursor.
    pub fn current_line(&self, programs: &[NcProgram], mdi: &NcProgram) -> Option<usize> {
        if let Some(e) = &self.exec {
            return Some(e.line);
        }
        let p = if self.cursor.prog == MDI {
            mdi
        } else {
            programs.get(self.cursor.prog)?
        };
        p.blocks.get(self.cursor.block).map(|b| b.line)
    }

    fn return_from_sub(&mut self) {
        match self.stack.last_mut() {
            Some(f) if f.repeats > 0 => {
                f.repeats -= 1;
                self.cursor = Cursor {
                    prog: f.sub,
                    block: f.start,
                };
                if let (Some(args), Some(l)) = (f.args, self.locals.last_mut()) {
                    *l = args;
                }
            }
            Some(f) => {
                self.cursor = f.ret;
                if f.args.is_some() {
                    self.locals.pop();
                }
                self.stack.pop();
            }
            None => self.cursor.block = 0,
        }
    }
}

impl SimCnc {
    fn program_ref(&self, prog: usize) -> Option<&NcProgram> {
        if prog == MDI {
            Some(&self.mdi)
        } else {
            self.programs.get(prog)
        }
    }

    fn block_at(&self, c: Cursor) -> Option<&NcBlock> {
        self.program_ref(c.prog)?.blocks.get(c.block)
    }

    /// The program being run and the index of the block at the cursor.
    pub(super) fn running_program(&self) -> Option<(&NcProgram, usize)> {
        let c = self.auto.cursor;
        Some((self.program_ref(c.prog)?, c.block))
    }

    /// The O number `cnc.prog` reports.
    pub(super) fn current_program_number(&self) -> u32 {
        let a = &self.auto;
        let main = self.programs.first().map_or(0, |p| p.number);
        if a.state == RunState::Idle && a.exec.is_none() {
            return main;
        }
        match a.cursor.prog {
            MDI => MDI_NUMBER,
            k => self.programs.get(k).map_or(main, |p| p.number),
        }
    }

    /// Whether any program has been loaded (WINDR 24 reports none otherwise).
    pub(super) fn has_program(&self) -> bool {
        !self.programs.is_empty() || (self.auto.mdi && !self.mdi.blocks.is_empty())
    }

    /// The executing block's remaining distance on axis slot `n` (0 when none moves).
    pub(super) fn remaining(&self, n: usize) -> i64 {
        self.auto.exec.as_ref().map_or(0, |e| e.remaining(n))
    }

    /// Whether an MST sequence is open.
    pub(super) fn mst_open(&self) -> bool {
        self.auto.exec.is_some_and(|e| e.mst.open)
    }

    /// A new alarm while RUN or HOLD: automatic operation stops, the block interrupted.
    pub(super) fn auto_alarm_stop(&mut self) {
        let a = &mut self.auto;
        if matches!(a.state, RunState::Run | RunState::Hold) {
            a.state = RunState::Stop;
            a.interrupted = a.exec.is_some();
        }
    }

    fn auto_to_idle(&mut self) {
        self.auto.state = RunState::Idle;
        self.auto.rewind_all();
    }

    fn program_error(&mut self, alarm: u16) {
        self.raise(alarm);
        let a = &mut self.auto;
        a.state = RunState::Stop;
        a.exec = None;
        a.interrupted = false;
    }

    /// Step (d): feed hold, cycle start, and the start of a block.
    pub(super) fn automatic(&mut self) {
        self.auto.dm99 = false;
        let inp = self.inp;
        // #3004 bit 0: feed hold ineffective while a macro says so.
        let feed_hold = inp.feed_hold && self.auto.m3004 & 1 == 0;
        if self.auto.state == RunState::Run && (feed_hold || self.auto.hold_after_thread) {
            // Feed hold during a thread takes effect at the thread's end.
            if self.threading() {
                self.auto.hold_after_thread = true;
            } else {
                self.auto.state = RunState::Hold;
                self.auto.hold_after_thread = false;
            }
        }
        let fall = self.prev.st && !inp.st;
        let auto_mode = matches!(self.mode, Mode::Mem | Mode::Mdi);
        if fall
            && auto_mode
            && !inp.feed_hold
            && !inp.estop
            && !inp.ers
            && !self.reset_key
            && self.alarms.is_empty()
            && self.auto.state != RunState::Run
            && !inp.srn
        {
            match self.auto.state {
                RunState::Idle => {
                    let mdi = self.mode == Mode::Mdi;
                    let empty = if mdi {
                        self.mdi.blocks.is_empty()
                    } else {
                        self.programs.first().is_none_or(|p| p.blocks.is_empty())
                    };
                    if !empty {
                        self.auto.mdi = mdi;
                        self.auto.rewind_all();
                        self.auto.state = RunState::Run;
                    }
                }
                RunState::Stop | RunState::Hold => {
                    self.auto.state = RunState::Run;
                    self.auto.interrupted = false;
                    self.macros.stop_message = None;
                }
                RunState::Run => {}
            }
        }
        if self.auto.state == RunState::Run && self.auto.exec.is_none() && self.auto.pending_stop {
            // The mode was left while no block executed (held back by *BSL or *CSL): stop now.
            self.auto.state = RunState::Stop;
            self.auto.pending_stop = false;
        }
        if self.auto.state == RunState::Run && !self.flags.halted {
            if self.auto.exec.is_none() {
                self.start_next_block();
            } else {
                self.continue_ahead();
            }
        }
    }

    pub(super) fn start_next_block(&mut self) {
        let mut guard = 0u32;
        let mut budget = super::macro_b::run::STATEMENTS_PER_EXCHANGE;
        loop {
            guard += 1;
            if guard > PASS_LIMIT {
                // Skipped blocks and M99 returns only: the program would never execute a
                // block again. Stop with an alarm rather than hang or end silently.
                self.program_error(ps::NO_PROGRESS);
                return;
            }
            let cur = self.auto.cursor;
            let Some(b) = self.block_at(cur) else {
                if self.auto.stack.is_empty() {
                    // Past the last block without M02/M30: IDLE, rewound, not counted.
                    self.auto_to_idle();
                    return;
                }
                self.auto.return_from_sub();
                continue;
            };
            if b.slash && self.inp.bdt1 {
                self.auto.cursor.block += 1;
                continue;
            }
            if b.mac
                .as_ref()
                .is_some_and(|m| !matches!(**m, MacroBlock::Nc(_)))
            {
                // A macro statement or call: no time, no NC block (docs/gcode.md, "Macros").
                guard -= 1;
                if let Some(n) = b.n {
                    self.auto.last_n = n;
                }
                if budget == 0 {
                    return;
                }
                budget -= 1;
                match self.macro_step() {
                    Flow::Next => continue,
                    Flow::Yield => return,
                    Flow::Stop => {
                        self.auto.state = RunState::Stop;
                        return;
                    }
                    Flow::Alarm(n) => {
                        self.program_error(n);
                        return;
                    }
                }
            }
            break;
        }
        if self.check(1) && self.inp.bsl {
            return;
        }
        let b = self.block_at(self.auto.cursor).expect("found above");
        let (n, line) = (b.n, b.line);
        let words = self.block_words(b);
        let words = match words {
            Ok(w) => w,
            Err(alarm) => {
                if let Some(n) = n {
                    self.auto.last_n = n;
                }
                self.program_error(alarm);
                return;
            }
        };
        let motion_mode = words.motion.unwrap_or(self.auto.modal.motion);
        let arc_ik = matches!(motion_mode, 2 | 3) && (words.i.is_some() || words.k.is_some());
        let cutting = motion_mode != 0 && words.one_shot.is_none() && (words.moves() || arc_ik);
        if cutting && self.check(1) && self.inp.csl {
            return;
        }
        if let Some(n) = n {
            self.auto.last_n = n;
            self.auto.read_n = n;
        }
        let planned = self
            .check_block(&words, cutting)
            .and_then(|call| self.execute(&words, line, call));
        match planned {
            Err(alarm) => self.program_error(alarm),
            Ok(()) => self.look_ahead(),
        }
    }

    fn execute(
        &mut self,
        w: &Words,
        line: usize,
        call: Option<(usize, usize, u32)>,
    ) -> Result<(), u16> {
        let inp = self.inp;
        let mut modal = self.modal_after(w);
        let cur = self.frame_position();
        let fx = self.plan(w, &mut modal)?;
        self.check_claims(w, cur)?;
        // Checked: from here the block takes effect.
        let g50 = w.one_shot == Some(OneShot::Coord);
        if let Some(shift) = fx.shift {
            self.auto.shift = shift;
        }
        if w.one_shot == Some(OneShot::Data) {
            self.apply_g10(w, modal.inch);
        }
        match w.s {
            Some(s) if g50 => modal.s_max = s,
            Some(s) if modal.css => {
                let per_unit = if modal.inch { 0.3048 } else { 1.0 };
                modal.css_speed = f64::from(s) * per_unit;
            }
            Some(s) => self.spindle.s_cmd = s,
            None => {}
        }
        if self.auto.modal.css && !modal.css && w.s.is_none() {
            // G97 without S keeps the speed constant surface speed last gave.
            self.spindle.s_cmd = self.spindle.s_css;
        }
        self.auto.modal = modal;
        self.auto.idle_mark = None;
        if let Some(&m) = w.ms().last() {
            self.auto.last_m = Some(m);
        }
        self.auto.last_s = w.s.or(self.auto.last_s);
        self.auto.last_t = w.t.or(self.auto.last_t);
        if w.g67 {
            self.auto.g66 = None;
        }
        // No modal call from inside the called macro or from a G70 profile's blocks.
        let modal_call = self.auto.g66.is_some()
            && w.moves()
            && w.one_shot.is_none()
            && !self.auto.stack.iter().any(|f| f.modal || f.until.is_some());
        let mut e = Exec {
            motion: None,
            current: Segment::to(SegKind::Rapid, self.frame_position()),
            seg: 0,
            seg_count: self.auto.segs.len() as u16,
            done_at: self.exchange_no,
            wait_rev: false,
            dwell_ms: 0.0,
            dwell_total: 0.0,
            mst: Mst::default(),
            stop_after: false,
            end: false,
            call: None,
            ret: false,
            ret_to: None,
            offset: None,
            line,
            g70: fx.g70,
            resume: fx.resume,
            next: None,
            ahead_waiting: false,
            modal_call,
        };
        // The M/S/T sequence.
        let ms = w.ms();
        let mut mst = Mst {
            started: self.exchange_no,
            ..Mst::default()
        };
        if let Some(sp) = special_m(ms) {
            mst.m[0] = sp;
            mst.strobes |= MF;
            e.stop_after = sp <= 1;
            e.end = sp >= 2;
        } else {
            if !inp.afl {
                // M98, M99 and an M97 with P (a local call) are the CNC's own.
                let called = |m: u32| matches!(m, 98 | 99) || (m == 97 && w.p.is_some());
                for (i, m) in ms.iter().filter(|m| !called(**m)).enumerate() {
                    mst.m[i] = *m;
                    mst.strobes |= [MF, MF2, MF3][i];
                }
            }
            e.call = call;
            e.ret = ms.contains(&99);
            e.ret_to = w.p.filter(|_| e.ret);
        }
        if let Some(s) = w.s
            && !inp.afl
            && !g50
        {
            mst.s = s;
            mst.strobes |= SF;
        }
        if let Some(v) = w.t {
            let tool = v / 100;
            e.offset = Some((v % 100) as u8);
            if tool != u32::from(inp.nowt) && !inp.afl {
                mst.t = tool;
                mst.strobes |= TF;
            }
        }
        mst.open = mst.strobes != 0;
        e.mst = mst;
        self.auto.exec = Some(e);
        self.next_segment();
        Ok(())
    }

    /// Step (g): the executing block ends when its motion, dwell and MST sequence are done.
    pub(super) fn end_of_block(&mut self) {
        let a = &self.auto;
        if !matches!(a.state, RunState::Run | RunState::Hold) || a.interrupted {
            return;
        }
        let Some(e) = a.exec else { return };
        if !e.motion_done() || e.mst.open {
            return;
        }
        self.auto.exec = None;
        if let Some(o) = e.offset {
            self.auto.tool_offset = o;
        }
        if e.ret {
            self.auto.dm99 = true;
        }
        if e.end {
            self.params.count(P6711);
            self.params.count(P6712);
            self.auto_to_idle();
            return;
        }
        let a = &mut self.auto;
        if let Some((first, last, home)) = e.g70 {
            a.stack.push(Frame {
                ret: a.cursor,
                sub: a.cursor.prog,
                start: first,
                repeats: 0,
                until: Some((last, home)),
                args: None,
                modal: false,
            });
            a.cursor.block = first;
        } else if let Some((sub, start, times)) = e.call {
            let ret = Cursor {
                block: a.cursor.block + 1,
                ..a.cursor
            };
            a.stack.push(Frame {
                ret,
                sub,
                start,
                repeats: times - 1,
                until: None,
                args: None,
                modal: false,
            });
            a.cursor = Cursor {
                prog: sub,
                block: start,
            };
        } else if e.ret {
            if e.ret_to.is_some()
                && let Some(f) = a.stack.last_mut()
            {
                // M99 P leaves the subprogram whatever repeats remain.
                f.repeats = 0;
            }
            a.return_from_sub();
            if let Some(n) = e.ret_to {
                // M99 Pn: to block n of the program returned to (of the main program itself).
                let c = self.auto.cursor;
                let found = self
                    .program_ref(c.prog)
                    .and_then(|p| super::program::find_sequence(p, n, 0));
                match found {
                    Some(k) => self.auto.cursor.block = k,
                    None => {
                        self.program_error(ps::NO_SEQUENCE);
                        return;
                    }
                }
            }
        } else if let Some(k) = e.resume {
            a.cursor.block = k;
        } else if let Some(call) = a.g66.filter(|_| e.modal_call) {
            let ret = Cursor {
                block: a.cursor.block + 1,
                ..a.cursor
            };
            if let Err(alarm) = self.push_call(call, ret, true) {
                self.program_error(alarm);
                return;
            }
        } else if let Some(f) = a.stack.last()
            && f.sub == a.cursor.prog
            && f.until.is_some_and(|(last, _)| last == a.cursor.block)
        {
            // The end of a G70 profile: back to the G70 block, which returns to its start.
            a.g70_return = f.until.map(|(_, home)| home);
            a.cursor = f.ret;
            a.stack.pop();
        } else if let Some(next) = e.next {
            a.cursor = next;
        } else {
            a.cursor.block += 1;
        }
        let sbk = self.single_block();
        let a = &mut self.auto;
        match a.state {
            RunState::Run if sbk || e.stop_after || a.pending_stop => {
                a.state = RunState::Stop;
                a.pending_stop = false;
            }
            RunState::Hold => {
                a.state = RunState::Stop;
                a.pending_stop = false;
            }
            _ => {}
        }
    }
}
