//! Automatic operation (docs/cnc.md, "Automatic operation" and "MST interface"): the run
//! states, cycle start and feed hold, starting and ending blocks, subprograms, program end,
//! the output of a block's M/S/T functions, and program motion; `mst.rs` runs the
//! handshake.

use super::motion::{Motion, MotionKind};
use super::mst::{MF, MF2, MF3, Mst, SF, TF};
use super::params::{P1240, P1410, P1420, P1421, P6711, P6712};
use super::program::{MDI_NUMBER, NcBlock, NcProgram, Words, ps};
use super::{AXES, Mode, SimCnc};

/// The automatic operation state.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum RunState {
    /// Reset state, or the program has not started or has ended (rewound).
    #[default]
    Idle,
    /// Cycle start state.
    Run,
    /// Feed hold state.
    Hold,
    /// Stopped inside the program (single block, M00, an alarm…).
    Stop,
}

impl RunState {
    /// The script and display name.
    pub fn name(self) -> &'static str {
        match self {
            RunState::Idle => "IDLE",
            RunState::Run => "RUN",
            RunState::Hold => "HOLD",
            RunState::Stop => "STOP",
        }
    }

    /// Every state, for name look-ups.
    pub const ALL: [RunState; 4] = [
        RunState::Idle,
        RunState::Run,
        RunState::Hold,
        RunState::Stop,
    ];
}

/// Blocks skipped (or subprogram ends passed) in a row before P/S 0079 is raised.
const PASS_LIMIT: u32 = 100_000;

/// Program index of the MDI buffer in a [`Cursor`].
const MDI: usize = usize::MAX;

/// A block position: program index (or [`MDI`]) and block index.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub(super) struct Cursor {
    prog: usize,
    block: usize,
}

/// A caller of a subprogram.
#[derive(Clone, Copy, Debug)]
struct Frame {
    ret: Cursor,
    sub: usize,
    repeats: u32,
}

/// The executing block.
#[derive(Clone, Copy, Debug)]
pub(super) struct Exec {
    pub(super) motion: Option<Motion>,
    /// G28: 0 none, 1 first segment, 2 second segment.
    pub(super) g28_stage: u8,
    pub(super) g28_axes: u8,
    pub(super) first_done_at: u64,
    pub(super) dwell_ms: f64,
    pub(super) dwell_total: f64,
    pub(super) feed: f64,
    pub(super) per_rev: bool,
    pub(super) mst: Mst,
    pub(super) stop_after: bool,
    pub(super) end: bool,
    pub(super) call: Option<(usize, u32)>,
    pub(super) ret: bool,
    pub(super) offset: Option<u8>,
    pub(super) line: usize,
}

impl Exec {
    pub(super) fn motion_done(&self) -> bool {
        self.motion.is_none_or(|m| m.done())
            && self.g28_stage != 1
            && self.dwell_ms >= self.dwell_total
    }

    /// The machine target minus position of the executing motion, per axis.
    pub(super) fn remaining(&self, n: usize) -> i64 {
        self.motion
            .map_or(0, |m| m.target[n] - m.position_at(n, m.covered))
    }
}

/// Modal state of the program.
#[derive(Clone, Copy, Debug, Default)]
pub(super) struct Modal {
    /// Group 01: 0 G00, 1 G01.
    pub motion: u8,
    /// G99.
    pub per_rev: bool,
    /// G54 + work.
    pub work: u8,
    /// F (0 = none).
    pub feed: f64,
}

/// Automatic operation.
#[derive(Clone, Debug, Default)]
pub(super) struct Auto {
    pub state: RunState,
    /// The program run or resumed is the MDI buffer.
    mdi: bool,
    cursor: Cursor,
    stack: Vec<Frame>,
    pub exec: Option<Exec>,
    interrupted: bool,
    pending_stop: bool,
    pub last_n: u32,
    pub modal: Modal,
    pub tool_offset: u8,
    pub dm99: bool,
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
    }

    /// A reset condition: IDLE and rewound; modal data, S and the tool offset are kept.
    pub fn reset(&mut self) {
        self.state = RunState::Idle;
        self.rewind_all();
        self.dm99 = false;
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
                    block: 0,
                };
            }
            Some(f) => {
                self.cursor = f.ret;
                self.stack.pop();
            }
            None => self.cursor.block = 0,
        }
    }
}

fn special_m(ms: &[u32]) -> Option<u32> {
    ms.iter().copied().find(|m| matches!(m, 0 | 1 | 2 | 30))
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
        if self.auto.state == RunState::Run && inp.feed_hold {
            self.auto.state = RunState::Hold;
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
                }
                RunState::Run => {}
            }
        }
        if self.auto.state == RunState::Run && self.auto.exec.is_none() && self.auto.pending_stop {
            // The mode was left while no block executed (held back by *BSL or *CSL): stop now.
            self.auto.state = RunState::Stop;
            self.auto.pending_stop = false;
        }
        if self.auto.state == RunState::Run && self.auto.exec.is_none() && !self.flags.halted {
            self.start_next_block();
        }
    }

    fn start_next_block(&mut self) {
        let mut guard = 0u32;
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
            break;
        }
        if self.check(1) && self.inp.bsl {
            return;
        }
        let b = self.block_at(self.auto.cursor).expect("found above");
        let (n, line, words) = (b.n, b.line, b.words);
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
        let cutting = motion_mode == 1 && words.moves() && !words.dwell && !words.g28;
        if cutting && self.check(1) && self.inp.csl {
            return;
        }
        if let Some(n) = n {
            self.auto.last_n = n;
        }
        let call = match self.check_block(&words, cutting) {
            Ok(call) => call,
            Err(alarm) => {
                self.program_error(alarm);
                return;
            }
        };
        self.execute(&words, line, call);
    }

    /// The checks that depend on the machine (docs/cnc.md, "Program errors"); returns the
    /// program an M98 calls.
    fn check_block(&self, w: &Words, cutting: bool) -> Result<Option<(usize, u32)>, u16> {
        if !w.dwell && w.axes[2].is_some() && self.axis_count() < 3 {
            return Err(ps::ADDRESS);
        }
        if cutting && w.f.unwrap_or(self.auto.modal.feed) <= 0.0 {
            return Err(ps::NO_FEED);
        }
        let mut call = None;
        if special_m(w.ms()).is_none() && w.ms().contains(&98) {
            let p = w.p.ok_or(ps::NO_PROGRAM)?;
            let find = |number: u32| self.programs.iter().position(|prog| prog.number == number);
            // P names the program itself when one has that number; else its last four
            // digits are the program and the digits before them the count (docs/gcode.md).
            let (k, count) = match find(p) {
                Some(k) => (k, 1),
                None => (find(p % 10_000).ok_or(ps::NO_PROGRAM)?, (p / 10_000).max(1)),
            };
            if self.auto.stack.len() >= 4 {
                return Err(ps::NESTING);
            }
            let times = w.l.map_or(count, |l| l.max(1));
            call = Some((k, times));
        }
        if !w.dwell {
            for k in 0..3 {
                if w.axes[k].is_none() {
                    continue;
                }
                if w.g28 && !self.axes[k].zrf {
                    return Err(ps::NO_REFERENCE);
                }
                if self.inp.eax >> k & 1 == 1 && (w.g28 || self.word_moves(w, k)) {
                    return Err(ps::AXIS_CLAIM);
                }
            }
        }
        Ok(call)
    }

    /// Whether the axis word of slot `k` moves that axis (a G28 always may).
    fn word_moves(&self, w: &Words, k: usize) -> bool {
        let cur = self.axes[k].m - self.axes[k].sh;
        match w.axes[k] {
            Some((v, true)) => v != 0,
            Some((v, false)) => v + self.tool_offset_along(k) + self.work_offset(k) != cur,
            None => false,
        }
    }

    fn execute(&mut self, w: &Words, line: usize, call: Option<(usize, u32)>) {
        let inp = self.inp;
        let modal = &mut self.auto.modal;
        if let Some(m) = w.motion {
            modal.motion = m;
        }
        if let Some(p) = w.per_rev {
            modal.per_rev = p;
        }
        if let Some(k) = w.work {
            modal.work = k;
        }
        if let Some(f) = w.f {
            modal.feed = f;
        }
        let modal = *modal;
        if let Some(s) = w.s {
            self.spindle.s_cmd = s;
        }
        let mut e = Exec {
            motion: None,
            g28_stage: 0,
            g28_axes: 0,
            first_done_at: 0,
            dwell_ms: 0.0,
            dwell_total: 0.0,
            feed: modal.feed,
            per_rev: modal.per_rev,
            mst: Mst::default(),
            stop_after: false,
            end: false,
            call: None,
            ret: false,
            offset: None,
            line,
        };
        if w.dwell {
            e.dwell_total = match (w.p, w.dwell_s) {
                (Some(p), _) => f64::from(p),
                (None, Some(s)) => (s * 1000.0).round(),
                _ => 0.0,
            };
        } else if w.moves() {
            let cur: [i64; AXES] = std::array::from_fn(|n| self.axes[n].m - self.axes[n].sh);
            let mut target = cur;
            for (k, word) in w.axes.iter().enumerate() {
                if let Some((v, inc)) = *word {
                    target[k] = if inc {
                        cur[k] + v
                    } else {
                        v + self.tool_offset_along(k) + self.work_offset(k)
                    };
                }
            }
            let kind = if w.g28 || modal.motion == 0 {
                MotionKind::Rapid
            } else {
                MotionKind::Cut
            };
            let m = Motion::new(kind, cur, target, self.diameters());
            if w.g28 {
                e.g28_stage = 1;
                e.g28_axes = w
                    .axes
                    .iter()
                    .enumerate()
                    .filter(|(_, a)| a.is_some())
                    .fold(0, |acc, (k, _)| acc | 1 << k);
            }
            if !m.is_empty() {
                e.motion = Some(m);
            } else if w.g28 {
                self.g28_second(&mut e);
            }
        }
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
                for (i, m) in ms.iter().filter(|m| !matches!(m, 98 | 99)).enumerate() {
                    mst.m[i] = *m;
                    mst.strobes |= [MF, MF2, MF3][i];
                }
            }
            e.call = call;
            e.ret = ms.contains(&99);
        }
        if let Some(s) = w.s
            && !inp.afl
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
    }

    /// Starts the second segment of a G28: rapid to reference point 1 of the named axes.
    fn g28_second(&mut self, e: &mut Exec) {
        let cur: [i64; AXES] = std::array::from_fn(|n| self.axes[n].m - self.axes[n].sh);
        let mut target = cur;
        for (n, t) in target.iter_mut().enumerate() {
            if e.g28_axes >> n & 1 == 1 {
                *t = self.params.get(P1240, n) - self.axes[n].sh;
            }
        }
        e.g28_stage = 2;
        let m = Motion::new(MotionKind::Rapid, cur, target, self.diameters());
        e.motion = (!m.is_empty()).then_some(m);
        if e.motion.is_none() {
            e.first_done_at = self.exchange_no;
            self.g28_arrived(e.g28_axes);
        }
    }

    /// The named axes of a G28 are at reference point 1: ZP, and the shift is cleared.
    fn g28_arrived(&mut self, axes: u8) {
        if self.inp.mlk {
            return;
        }
        for n in 0..AXES {
            if axes >> n & 1 == 1 {
                self.axes[n].sh = 0;
                self.axes[n].zp = true;
            }
        }
    }

    /// The rapid rate of axis slot `n` with the rapid override (F0: #1421).
    pub(super) fn rapid_rate(&self, n: usize) -> f64 {
        match self.inp.rov {
            3 => self.params.one(P1421) as f64,
            r => self.params.get(P1420, n) as f64 * [1.0, 0.5, 0.25][usize::from(r)],
        }
    }

    /// Cutting feed override, 0–1.5.
    pub(super) fn fov(&self) -> f64 {
        if self.inp.ovc {
            1.0
        } else {
            f64::from(self.inp.fv.min(15)) / 10.0
        }
    }

    /// JOG override, 0–1.5.
    pub(super) fn jov(&self) -> f64 {
        f64::from(self.inp.jv.min(15)) / 10.0
    }

    fn program_speed(&self, m: &Motion, feed: f64, per_rev: bool) -> f64 {
        match m.kind {
            MotionKind::Rapid => m.rapid_speed(|n| self.rapid_rate(n)),
            MotionKind::Cut if self.inp.drn => {
                if self.inp.rt {
                    (0..AXES)
                        .filter(|n| m.axes >> n & 1 == 1)
                        .map(|n| self.rapid_rate(n))
                        .fold(f64::INFINITY, f64::min)
                } else {
                    self.params.one(P1410) as f64 * self.jov()
                }
            }
            MotionKind::Cut if per_rev => feed * f64::from(self.spindle.s_out) * self.fov(),
            MotionKind::Cut => feed * self.fov(),
        }
    }

    /// Step (e) for the program: its dwell and motion advance by 8 ms.
    pub(super) fn advance_program(&mut self) {
        let a = &self.auto;
        if self.flags.halted || a.state != RunState::Run || a.interrupted {
            return;
        }
        let Some(mut e) = a.exec else { return };
        if e.dwell_ms < e.dwell_total {
            e.dwell_ms += 8.0;
        }
        if e.g28_stage == 1
            && e.motion.is_none_or(|m| m.done())
            && e.first_done_at < self.exchange_no
        {
            self.g28_second(&mut e);
        }
        self.auto.exec = Some(e);
        let Some(mut m) = e.motion.filter(|m| !m.done()) else {
            return;
        };
        let inp = self.inp;
        if self.check(0) && inp.interlock {
            return;
        }
        if self.check(2) && m.axes & inp.axis_interlock != 0 {
            return;
        }
        let v = self.program_speed(&m, e.feed, e.per_rev);
        if v <= 0.0 || !v.is_finite() {
            return;
        }
        let covered = m.next_covered(v);
        let mut delta = [0i64; AXES];
        for (n, d) in delta.iter_mut().enumerate() {
            *d = m.position_at(n, covered) - m.position_at(n, m.covered);
        }
        if !inp.mlk {
            for (n, &d) in delta.iter().enumerate() {
                if d == 0 {
                    continue;
                }
                let dir = usize::from(d < 0);
                if self.axes[n].hard_limit[dir] {
                    return;
                }
                let from = self.axes[n].m;
                if let Some(stop) = self.stroke_stop(n, from, from + d) {
                    self.apply_delta(n, stop - from, false, false);
                    self.stroke_alarm(n, dir);
                    return;
                }
            }
        }
        for (n, &d) in delta.iter().enumerate() {
            self.apply_delta(n, d, inp.mlk, false);
        }
        m.covered = covered;
        match m.kind {
            MotionKind::Rapid => self.flags.rapid = true,
            MotionKind::Cut => self.flags.cut = true,
        }
        self.flags.path_speed = v;
        if m.done() {
            e.first_done_at = self.exchange_no;
            if e.g28_stage == 2 {
                self.g28_arrived(e.g28_axes);
            }
        }
        e.motion = Some(m);
        self.auto.exec = Some(e);
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
        if let Some((sub, times)) = e.call {
            let ret = Cursor {
                block: a.cursor.block + 1,
                ..a.cursor
            };
            a.stack.push(Frame {
                ret,
                sub,
                repeats: times - 1,
            });
            a.cursor = Cursor {
                prog: sub,
                block: 0,
            };
        } else if e.ret {
            a.return_from_sub();
        } else {
            a.cursor.block += 1;
        }
        match a.state {
            RunState::Run if self.inp.sbk || e.stop_after || a.pending_stop => {
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
