//! Manual operation and the stroke rules (docs/cnc.md, "Manual operation" and "Overtravel"):
//! JOG, the handwheel, reference return with or without a deceleration dog, and the stored
//! stroke check that every motion of the simulator passes through.

use super::motion::{MM_PER_EXCHANGE, Motion, MotionKind};
use super::params::{P1006, P1240, P1320, P1321, P1326, P1327, P1423, P1425, P7103, P7113, P7114};
use super::{ALARM_STROKE, AXES, Mode, SimCnc};

/// A JOG (or the continuous phase of a reference return) in progress on one axis.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) struct Run {
    /// +1 or −1.
    dir: i64,
    /// Distance summed since it started, mm.
    s: f64,
    /// Increments applied so far.
    done: i64,
}

impl Run {
    pub(super) fn new(dir: i64) -> Run {
        Run {
            dir,
            s: 0.0,
            done: 0,
        }
    }

    /// Advances at `v` mm/min; returns the increments to move at this exchange.
    pub(super) fn step(&mut self, v: f64, diameter: bool) -> i64 {
        self.s += v * MM_PER_EXCHANGE;
        let k = if diameter { 2000.0 } else { 1000.0 };
        let total = (self.s * k).round() as i64 * self.dir;
        let d = total - self.done;
        self.done = total;
        d
    }
}

/// A reference return of one axis.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) enum Return {
    /// Rapid straight to #1240 (the reference point is known), timed like every motion:
    /// from, to (increments), length (mm), distance covered (mm).
    Direct(Straight),
    /// Rapid towards the dog.
    Rapid(Run),
    /// On the dog at the FL speed.
    Slow(Run),
}

/// A straight single-axis move, with the timing rule of [`Motion`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) struct Straight {
    from: i64,
    to: i64,
    length: f64,
    covered: f64,
}

impl Straight {
    fn new(from: i64, to: i64, diameter: bool) -> Straight {
        let m = Motion::new(
            MotionKind::Rapid,
            [from; AXES],
            {
                let mut t = [from; AXES];
                t[0] = to;
                t
            },
            [diameter; AXES],
        );
        Straight {
            from,
            to,
            length: m.length,
            covered: 0.0,
        }
    }

    fn position(&self, covered: f64) -> i64 {
        if covered >= self.length - 1e-9 {
            self.to
        } else {
            self.from + ((self.to - self.from) as f64 * (covered / self.length)).round() as i64
        }
    }
}

/// Manual motion state.
#[derive(Clone, Copy, Debug, Default)]
pub(super) struct Manual {
    jog: [Option<Run>; AXES],
    returns: [Option<Return>; AXES],
    /// Handwheel pulses queued for the next exchange.
    pub pulses: i64,
}

impl Manual {
    /// Every manual motion stops (mode change, reset).
    pub fn stop_all(&mut self) {
        self.jog = [None; AXES];
        self.returns = [None; AXES];
    }

    /// Whether axis slot `n` has a manual motion in progress.
    pub fn moving(&self, n: usize) -> bool {
        self.jog[n].is_some() || self.returns[n].is_some()
    }

    /// Stops the manual motion of axis slot `n` (the PLC claimed it).
    pub fn stop_axis(&mut self, n: usize) {
        self.jog[n] = None;
        self.returns[n] = None;
    }
}

impl SimCnc {
    /// Where a move of axis slot `n` from `from` to `to` must stop under the stored stroke
    /// check, or `None` when it may go on. Applies only once the reference point is known.
    pub(super) fn stroke_stop(&self, n: usize, from: i64, to: i64) -> Option<i64> {
        let a = &self.axes[n];
        if !a.zrf || to == from {
            return None;
        }
        let dir = usize::from(to < from);
        if a.stroke[dir] {
            return Some(from);
        }
        let (plus, minus) = if self.inp.exlm {
            (P1326, P1327)
        } else {
            (P1320, P1321)
        };
        let hi = self.params.get(plus, n);
        let lo = self.params.get(minus, n);
        if dir == 0 && to > hi {
            return Some(if from <= hi { hi } else { from });
        }
        if dir == 1 && to < lo {
            return Some(if from >= lo { lo } else { from });
        }
        None
    }

    /// A move stopped by the stroke check: the direction is stored and the alarm raised.
    pub(super) fn stroke_alarm(&mut self, n: usize, dir: usize) {
        self.axes[n].stroke[dir] = true;
        self.raise(ALARM_STROKE[dir]);
    }

    /// Moves axis slot `n` by `d` increments: the machine position, or under machine lock
    /// the shift; `absolute_off` (ABSM in manual) adds the move to the shift so the absolute
    /// position stays.
    pub(super) fn apply_delta(&mut self, n: usize, d: i64, lock: bool, absolute_off: bool) {
        if d == 0 {
            return;
        }
        let a = &mut self.axes[n];
        if lock {
            a.sh -= d;
        } else {
            a.m += d;
        }
        if absolute_off {
            a.sh += d;
        }
        a.mv = true;
        a.mvd = d < 0;
        // Moving away from a stored stroke direction releases it (the machine must move:
        // under machine lock only the distribution advances).
        if !lock {
            a.stroke[usize::from(d > 0)] = false;
        }
    }

    /// Whether manual motion of axis slot `n` is blocked now (E-stop, servo alarm, an
    /// interlock, PLC control).
    fn manual_blocked(&self, n: usize) -> bool {
        let inp = &self.inp;
        inp.estop
            || self.servo_alarm()
            || (self.check(0) && inp.interlock)
            || (self.check(2) && inp.axis_interlock >> n & 1 == 1)
            || inp.eax >> n & 1 == 1
    }

    /// A manual move of `d` increments on axis slot `n` (machine lock and ABSM as the
    /// inputs say), under the stroke rules. Returns whether the axis could move the whole way.
    fn manual_move(&mut self, n: usize, d: i64) -> bool {
        let (lock, absm) = (self.inp.mlk, self.inp.absm);
        self.guarded_move(n, d, lock, absm)
    }

    /// A move of `d` increments on axis slot `n` under the hardware and stored stroke rules:
    /// stopped on the limit with the alarm when it would pass one. Returns whether the axis
    /// could move the whole way.
    pub(super) fn guarded_move(&mut self, n: usize, d: i64, lock: bool, absm: bool) -> bool {
        if d == 0 {
            return true;
        }
        let dir = usize::from(d < 0);
        if self.axes[n].hard_limit[dir] {
            return false;
        }
        let from = self.axes[n].m;
        if !lock && let Some(stop) = self.stroke_stop(n, from, from + d) {
            self.apply_delta(n, stop - from, false, absm);
            self.stroke_alarm(n, dir);
            return false;
        }
        self.apply_delta(n, d, lock, absm);
        true
    }

    /// Step (e) for manual operation.
    pub(super) fn advance_manual(&mut self) {
        let pulses = std::mem::take(&mut self.manual.pulses);
        if self.flags.halted {
            return;
        }
        match self.mode {
            Mode::Jog => self.jog(),
            Mode::Handle => self.handwheel(pulses),
            Mode::Ref => self.reference_return(),
            _ => {}
        }
    }

    fn jog(&mut self) {
        let inp = self.inp;
        for n in 0..self.axis_count() {
            let plus = inp.jog_plus >> n & 1 == 1;
            let minus = inp.jog_minus >> n & 1 == 1;
            let dir = match (plus, minus) {
                (true, false) => 1,
                (false, true) => -1,
                _ => 0,
            };
            let d = usize::from(dir < 0);
            let blocked = dir == 0
                || self.manual_blocked(n)
                || self.axes[n].hard_limit[d]
                || (self.axes[n].zrf && self.axes[n].stroke[d]);
            if blocked {
                self.manual.jog[n] = None;
                continue;
            }
            let mut run = match self.manual.jog[n] {
                Some(r) if r.dir == dir => r,
                _ => Run::new(dir),
            };
            let v = if inp.rt {
                self.rapid_rate(n)
            } else {
                self.params.get(P1423, n) as f64 * self.jov()
            };
            let step = run.step(v, self.diameter(n));
            if step != 0 && inp.rt {
                self.flags.rapid = true;
            }
            if self.manual_move(n, step) {
                self.manual.jog[n] = Some(run);
            } else {
                self.manual.jog[n] = None;
            }
        }
    }

    fn handwheel(&mut self, pulses: i64) {
        let inp = self.inp;
        let axis = usize::from(inp.hs);
        if pulses == 0 || axis == 0 || axis > self.axis_count() {
            return;
        }
        let n = axis - 1;
        if self.manual_blocked(n) {
            return;
        }
        let mut m = match inp.mp {
            0 => 1,
            1 => 10,
            2 => self.params.one(P7113),
            _ => self.params.one(P7114),
        };
        if self.params.bit(P7103, 0, 2) {
            m *= 10;
        }
        let d = pulses * m;
        let dir = usize::from(d < 0);
        if self.axes[n].zrf && self.axes[n].stroke[dir] {
            return;
        }
        self.manual_move(n, d);
    }

    fn reference_return(&mut self) {
        let inp = self.inp;
        let prev = self.prev;
        for n in 0..self.axis_count() {
            let minus = self.params.bit(P1006, n, 5);
            let (now, before) = if minus {
                (inp.jog_minus, prev.jog_minus)
            } else {
                (inp.jog_plus, prev.jog_plus)
            };
            if self.manual.returns[n].is_none() && now >> n & 1 == 1 && before >> n & 1 == 0 {
                self.manual.returns[n] = Some(self.start_return(n, self.axes[n].zrf));
            }
            let Some(ret) = self.manual.returns[n] else {
                continue;
            };
            if inp.estop || self.servo_alarm() {
                self.manual.returns[n] = None;
                continue;
            }
            if self.manual_blocked(n) {
                continue;
            }
            self.manual.returns[n] = self.return_step(n, ret, self.rapid_rate(n)).unwrap_or(None);
        }
    }

    /// One exchange of a reference return of axis slot `n` (manual, or PLC 05h/07h with its
    /// own rapid rate); returns the state after it (`None` when
    /// arrived), or `Err` when an overtravel stopped it.
    pub(super) fn return_step(
        &mut self,
        n: usize,
        ret: Return,
        rapid: f64,
    ) -> Result<Option<Return>, ()> {
        let on_dog = self.inp.dec >> n & 1 == 1;
        let dia = self.diameter(n);
        let reference = self.params.get(P1240, n);
        // A reference return moves the machine itself: machine lock and ABSM do not apply,
        // and arriving sets the shift to 0 anyway.
        match ret {
            Return::Direct(mut m) => {
                if m.from == m.to {
                    self.arrive(n);
                    return Ok(None);
                }
                if rapid <= 0.0 {
                    return Ok(Some(Return::Direct(m)));
                }
                let covered = m.covered + rapid * MM_PER_EXCHANGE;
                let d = m.position(covered) - m.position(m.covered);
                if !self.guarded_move(n, d, false, false) {
                    return Err(());
                }
                self.flags.rapid = true;
                m.covered = covered;
                if covered >= m.length - 1e-9 {
                    self.axes[n].m = reference;
                    self.arrive(n);
                    Ok(None)
                } else {
                    Ok(Some(Return::Direct(m)))
                }
            }
            Return::Rapid(run) if on_dog => {
                self.return_step(n, Return::Slow(Run::new(run.dir)), rapid)
            }
            Return::Rapid(mut run) => {
                let d = run.step(rapid, dia);
                if d != 0 {
                    self.flags.rapid = true;
                }
                if self.guarded_move(n, d, false, false) {
                    Ok(Some(Return::Rapid(run)))
                } else {
                    Err(())
                }
            }
            Return::Slow(_) if !on_dog => {
                let a = &mut self.axes[n];
                a.m = reference;
                a.zrf = true;
                self.arrive(n);
                Ok(None)
            }
            Return::Slow(mut run) => {
                let d = run.step(self.params.get(P1425, n) as f64, dia);
                if self.guarded_move(n, d, false, false) {
                    Ok(Some(Return::Slow(run)))
                } else {
                    Err(())
                }
            }
        }
    }

    fn arrive(&mut self, n: usize) {
        let a = &mut self.axes[n];
        a.sh = 0;
        a.zp = true;
    }

    /// Starts a reference return of axis slot `n` as a PLC command does.
    pub(super) fn start_return(&self, n: usize, direct: bool) -> Return {
        let dir = if self.params.bit(P1006, n, 5) { -1 } else { 1 };
        if direct {
            let to = self.params.get(P1240, n);
            Return::Direct(Straight::new(self.axes[n].m, to, self.diameter(n)))
        } else {
            Return::Rapid(Run::new(dir))
        }
    }

    /// The direction (0 +, 1 −) a reference return of axis slot `n` moves in now.
    pub(super) fn return_direction(&self, ret: &Return) -> usize {
        match ret {
            Return::Direct(m) => usize::from(m.to < m.from),
            Return::Rapid(r) | Return::Slow(r) => usize::from(r.dir < 0),
        }
    }
}
