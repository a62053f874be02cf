//! The path of the executing block (docs/cnc.md, "Motion"; docs/gcode.md, "Segments"): a
//! block is planned into a queue of segments — rapid, line, arc, thread, dwell — and the
//! queue advances here, one exchange at a time, under the same rules for every segment
//! (speed, overrides, interlocks, machine lock, stroke limits). A segment after the first
//! starts at the exchange after the one its predecessor ended in; a segment that moves
//! nothing is passed at once.

use super::modal::RunState;
use super::motion::{Motion, MotionKind};
use super::params::{P1410, P1420, P1421};
use super::{AXES, SimCnc};

/// Most segments one block may plan: a cycle asked for more (a peck of 0.001 mm over a metre)
/// is refused with P/S 0062 instead of filling memory.
pub const SEG_MAX: usize = 200_000;

/// Room for more segments in `segs`, or P/S 0062.
pub fn room(segs: &[Segment]) -> Result<(), u16> {
    if segs.len() >= SEG_MAX {
        Err(super::program::ps::CYCLE_VALUE)
    } else {
        Ok(())
    }
}

/// What one segment does.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum SegKind {
    /// Positioning at the rapid rate (G00, G28, G53, a cycle's approach and return).
    Rapid,
    /// Linear cutting feed.
    Line,
    /// Circular cutting feed in the Z–X plane around `center` (frame increments, X as written:
    /// a diameter on a diameter axis); `cw` for G02.
    Arc {
        /// G02.
        cw: bool,
        /// Centre: X, Z.
        center: [i64; 2],
        /// A closed arc is a full circle (I/K given), not a point.
        full: bool,
    },
    /// Thread cutting: waits for the one-rotation signal, then feeds `lead` mm per revolution
    /// of the actual spindle speed with the feed override at 100 %.
    Thread {
        /// Lead, mm per revolution along the longer axis.
        lead: f64,
    },
    /// Dwell, ms.
    Dwell {
        /// Time, ms.
        ms: f64,
    },
}

/// One segment of a block's path.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Segment {
    /// What it does.
    pub kind: SegKind,
    /// Where it ends, per axis, in machine increments less the shift (M − SH).
    pub target: [i64; AXES],
    /// Feed, mm/min or mm/rev (cutting kinds).
    pub feed: f64,
    /// The feed is per revolution.
    pub per_rev: bool,
    /// The reference point its end arrives at (G28's and G30's second leg).
    pub home: Home,
}

/// Axes arriving at a reference point at the end of a segment.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Home {
    /// The axes (bit n−1 for axis n); 0: no arrival.
    pub axes: u8,
    /// Reference point 1 (G28) or 2–4 (G30 P2–P4).
    pub point: u8,
}

impl Home {
    /// No arrival.
    pub const NONE: Home = Home { axes: 0, point: 0 };
}

impl Segment {
    /// A segment of `kind` to `target` with no feed.
    pub fn to(kind: SegKind, target: [i64; AXES]) -> Segment {
        Segment {
            kind,
            target,
            feed: 0.0,
            per_rev: false,
            home: Home::NONE,
        }
    }

    /// A cutting segment of `kind` to `target` at `feed` (per revolution when `per_rev`).
    pub fn cut(kind: SegKind, target: [i64; AXES], feed: f64, per_rev: bool) -> Segment {
        Segment {
            kind,
            target,
            feed,
            per_rev,
            home: Home::NONE,
        }
    }

    /// The motion that takes the tool from `start` along this segment (none for a dwell).
    pub fn motion(&self, start: [i64; AXES], diameter: [bool; AXES]) -> Option<Motion> {
        Some(match self.kind {
            SegKind::Dwell { .. } => return None,
            SegKind::Rapid => Motion::new(MotionKind::Rapid, start, self.target, diameter),
            SegKind::Arc { cw, center, full } => {
                Motion::arc(start, self.target, center, cw, full, diameter)
            }
            SegKind::Line | SegKind::Thread { .. } => {
                Motion::new(MotionKind::Cut, start, self.target, diameter)
            }
        })
    }
}

impl SimCnc {
    /// The position the program moves from: M − SH per axis.
    pub(super) fn frame_position(&self) -> [i64; AXES] {
        std::array::from_fn(|n| self.axes[n].m - self.axes[n].sh)
    }

    /// Starts the next segments of the executing block: passes those that move nothing and
    /// stops at the first that takes time.
    pub(super) fn next_segment(&mut self) {
        let Some(mut e) = self.auto.exec else { return };
        e.motion = None;
        e.dwell_ms = 0.0;
        e.dwell_total = 0.0;
        while e.seg < e.seg_count {
            let s = self.auto.segs[usize::from(e.seg)];
            e.seg += 1;
            e.current = s;
            if let SegKind::Dwell { ms } = s.kind {
                self.auto.prev_thread = false;
                if ms > 0.0 {
                    e.dwell_total = ms;
                    break;
                }
                continue;
            }
            let Some(m) = s.motion(self.frame_position(), self.diameters()) else {
                continue;
            };
            if m.is_empty() {
                self.arrived(s.home);
                continue;
            }
            // A thread waits for the one-rotation signal, unless it follows a thread
            // directly (consecutive G32 blocks are one thread).
            let thread = matches!(s.kind, SegKind::Thread { .. });
            e.wait_rev = thread && !self.auto.prev_thread;
            self.auto.prev_thread = thread;
            e.motion = Some(m);
            break;
        }
        self.auto.exec = Some(e);
    }

    /// Whether a thread is being cut (or waits for its one-rotation signal): feed hold waits
    /// for its end.
    pub(super) fn threading(&self) -> bool {
        let is_thread = |k: SegKind| matches!(k, SegKind::Thread { .. });
        self.auto.exec.is_some_and(|e| {
            let next = self.auto.segs.get(usize::from(e.seg)).map(|s| s.kind);
            is_thread(e.current.kind)
                && (!e.segment_done() || (e.seg < e.seg_count && next.is_some_and(is_thread)))
        })
    }

    /// The named axes of a G28 are at reference point 1: ZP, and the shift is cleared; those
    /// of a G30 at point 2–4: ZP2–ZP4.
    fn arrived(&mut self, home: Home) {
        if self.inp.mlk {
            return;
        }
        for n in 0..AXES {
            if home.axes >> n & 1 == 1 {
                match home.point {
                    1 => {
                        self.axes[n].sh = 0;
                        self.axes[n].zp = true;
                    }
                    p @ 2..=4 => self.axes[n].zp_n[usize::from(p) - 2] = true,
                    _ => {}
                }
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
        if self.inp.ovc || self.auto.m3004 & 2 != 0 {
            // OVC, or #3004 bit 1: override ineffective.
            1.0
        } else {
            f64::from(self.inp.fv.min(15)) / 10.0
        }
    }

    /// JOG override, 0–1.5.
    pub(super) fn jov(&self) -> f64 {
        f64::from(self.inp.jv.min(15)) / 10.0
    }

    fn program_speed(&self, m: &Motion, seg: &Segment) -> f64 {
        let (kind, feed, per_rev) = (seg.kind, seg.feed, seg.per_rev);
        let s = f64::from(self.spindle.s_out);
        match m.kind {
            MotionKind::Rapid => m.rapid_speed(|n| self.rapid_rate(n)),
            // Threading follows the spindle: the lead is along the longer axis, no dry run, no
            // feed override.
            _ if matches!(kind, SegKind::Thread { .. }) => {
                let long = m.axis_mm.iter().fold(0.0, |a: f64, &b| a.max(b));
                feed * s * m.length / long
            }
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
            MotionKind::Cut if per_rev => feed * s * self.fov(),
            MotionKind::Cut => feed * self.fov(),
        }
    }

    /// Step (e) for the program: its dwell and motion advance by 8 ms.
    pub(super) fn advance_program(&mut self) {
        let a = &self.auto;
        if self.flags.halted || a.state != RunState::Run || a.interrupted {
            return;
        }
        let Some(e) = a.exec else { return };
        if e.segment_done() && e.seg < e.seg_count && e.done_at < self.exchange_no {
            self.next_segment();
        }
        let Some(mut e) = self.auto.exec else { return };
        if e.dwell_ms < e.dwell_total {
            e.dwell_ms += 8.0;
            if e.dwell_ms >= e.dwell_total {
                e.done_at = self.exchange_no;
            }
        }
        self.auto.exec = Some(e);
        let Some(mut m) = e.motion.filter(|m| !m.done()) else {
            return;
        };
        if matches!(e.current.kind, SegKind::Thread { .. }) {
            self.flags.thread = true;
            if e.wait_rev {
                if !self.spindle.one_rev {
                    return;
                }
                e.wait_rev = false;
                self.auto.exec = Some(e);
            }
        }
        let inp = self.inp;
        if self.check(0) && inp.interlock {
            return;
        }
        if self.check(2) && m.axes & inp.axis_interlock != 0 {
            return;
        }
        let v = self.program_speed(&m, &e.current);
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
            e.done_at = self.exchange_no;
            self.arrived(e.current.home);
        }
        e.motion = Some(m);
        self.auto.exec = Some(e);
    }
}
