//! PLC axis control (docs/cnc.md, "PLC axis control"): groups A–D, their three-command
//! buffers, every command code, overrides, errors, and the F signals the AXCTL instruction
//! waits for.

use super::fsignals as fs;
use super::manual::{Return, Run};
use super::motion::{Motion, MotionKind};
use super::params::{P1240, P1420, P1421, P1424, P8002, P8010};
use super::ps;
use super::signals::FImage;
use super::{ALARM_HARD_LIMIT, ALARM_STROKE, AXES, SimCnc};
use crate::vm::cnc::AxisStatus;

/// A command as read from the group's G signals.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
struct Cmd {
    ec: u8,
    eif: u16,
    eid: i32,
    emsbk: bool,
    id: u32,
}

/// How a PLC move's speed is found at each exchange.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Rate {
    /// Rapid at the lowest #1420 of the group's axes (or EIF with RPD), × rapid override.
    Rapid(Option<f64>),
    /// Cutting feed, mm/min × feed override.
    Feed(f64),
    /// Feed per revolution, mm/rev × spindle speed × feed override.
    PerRev(f64),
}

/// What an executing command does.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Work {
    Move {
        motion: Motion,
        rate: Rate,
        /// Reference point reached at the end: 0 none, 1 ZP, 2–4 ZP2–ZP4.
        point: u8,
    },
    Dwell {
        elapsed: f64,
        total: f64,
    },
    Return {
        axes: [Option<Return>; AXES],
        rapid: Option<f64>,
        dog_rapid: usize,
    },
    Continuous {
        speed: u16,
        dir: i64,
        runs: [Run; AXES],
    },
    Speed {
        eif: i16,
    },
    Aux {
        strobe: u8,
        code: u16,
        started: u64,
    },
}

#[derive(Clone, Copy, Debug, PartialEq)]
struct Running {
    cmd: Cmd,
    axes: u8,
    work: Work,
}

/// One PLC axis group.
#[derive(Clone, Debug, Default)]
pub(super) struct Group {
    waiting: Vec<Cmd>,
    exec: Option<Running>,
    ebsy: bool,
    eial: bool,
    eial_alarm: u16,
    eot: [bool; 2],
    eot_alarm: [u16; 2],
    egen: bool,
    /// ESTPg as sampled at the last exchange.
    paused: bool,
    next_id: u32,
    last_read: u32,
    last_ended: bool,
    last_error: bool,
    emsbk_end_at: Option<u64>,
}

impl Group {
    fn held(&self) -> usize {
        self.waiting.len() + usize::from(self.exec.is_some())
    }

    fn finished(&mut self, id: u32, error: bool) {
        if id == self.last_read {
            self.last_ended = true;
            self.last_error = error;
        }
    }

    fn drop_waiting(&mut self, error: bool) {
        for c in std::mem::take(&mut self.waiting) {
            self.finished(c.id, error);
        }
    }

    /// Whether axis slot `n` has an unfinished PLC motion here (paused included).
    fn moving(&self, n: usize) -> bool {
        self.exec.is_some_and(|r| {
            r.axes >> n & 1 == 1
                && match r.work {
                    Work::Move { .. } | Work::Return { .. } | Work::Continuous { .. } => true,
                    Work::Speed { eif } => eif != 0 && !self.paused,
                    _ => false,
                }
        })
    }
}

fn exclusive(ec: u8) -> bool {
    matches!(ec, 0x05 | 0x07..=0x0A | 0x20)
}

fn known(ec: u8) -> bool {
    matches!(
        ec,
        0x00 | 0x01 | 0x02 | 0x04 | 0x05 | 0x06 | 0x07..=0x0A | 0x10 | 0x12 | 0x14 | 0x15 | 0x20
    )
}

impl SimCnc {
    /// `axis_status` of the PLC's port.
    pub(super) fn plc_axis_status(&self, group: u8, ebuf: bool) -> AxisStatus {
        let Some(g) = self.groups.get(usize::from(group).wrapping_sub(1)) else {
            return AxisStatus::default();
        };
        AxisStatus {
            ended: g.last_ended && ebuf == g.ebsy,
            error: g.last_error || g.eial,
        }
    }

    /// Whether the PLC holds axis slot `n` in an unfinished motion.
    pub(super) fn plc_moving(&self, n: usize) -> bool {
        self.groups.iter().any(|g| g.moving(n))
    }

    fn end_command(&mut self, k: usize, error: bool, eial: Option<u16>) {
        let n = self.exchange_no;
        let g = &mut self.groups[k];
        if let Some(r) = g.exec.take() {
            g.finished(r.cmd.id, error);
            if r.cmd.emsbk {
                g.emsbk_end_at = Some(n);
            }
        }
        if error {
            g.drop_waiting(true);
        }
        if let Some(alarm) = eial {
            g.eial = true;
            g.eial_alarm = alarm;
        }
    }

    fn overtravel_end(&mut self, k: usize, n: usize, dir: usize) {
        let alarm = if self.axes[n].hard_limit[dir] {
            ALARM_HARD_LIMIT[dir]
        } else {
            ALARM_STROKE[dir]
        };
        let g = &mut self.groups[k];
        g.eot[dir] = true;
        g.eot_alarm[dir] = alarm;
        self.end_command(k, true, Some(alarm));
    }

    /// The EAX checks (docs/cnc.md P/S 0139), with the alarm sources of step (b).
    pub(super) fn claims(&mut self) {
        let (now, before) = (self.inp.eax, self.prev.eax);
        let changed = now ^ before;
        if changed == 0 {
            return;
        }
        for n in 0..self.axis_count() {
            if changed >> n & 1 == 0 {
                continue;
            }
            if self.eaxsl {
                self.raise(ps::AXIS_CLAIM);
                let g = self.params.get(P8010, n);
                if (1..=4).contains(&g) {
                    let k = (g - 1) as usize;
                    if self.groups[k].exec.is_some() {
                        self.end_command(k, true, Some(ps::AXIS_CLAIM));
                    } else {
                        self.groups[k].eial = true;
                        self.groups[k].eial_alarm = ps::AXIS_CLAIM;
                    }
                }
            } else if now >> n & 1 == 1 {
                if self.remaining(n) != 0 {
                    self.raise(ps::AXIS_CLAIM);
                }
                if self.manual.moving(n) {
                    self.manual.stop_axis(n);
                }
            }
        }
    }

    /// The first axis whose move of `delta` the stroke rules stop (hardware limit, a stored
    /// direction, or a stored stroke limit it would pass).
    fn blocked_axis(&self, delta: &[i64; AXES]) -> Option<(usize, i64)> {
        delta.iter().enumerate().find_map(|(n, &d)| {
            if d == 0 {
                return None;
            }
            let from = self.axes[n].m;
            let blocked = self.axes[n].hard_limit[usize::from(d < 0)]
                || self.stroke_stop(n, from, from + d).is_some();
            blocked.then_some((n, d))
        })
    }

    /// Moves group `k`'s axes by `delta`. Every axis is checked first: when one must stop
    /// (on its limit, with the alarm) the others do not advance either, and the command ends
    /// in error; returns whether the move went on.
    fn move_group(&mut self, k: usize, delta: &[i64; AXES]) -> bool {
        if let Some((n, d)) = self.blocked_axis(delta) {
            self.guarded_move(n, d, false, false);
            self.overtravel_end(k, n, usize::from(d < 0));
            return false;
        }
        for (n, &d) in delta.iter().enumerate() {
            self.apply_delta(n, d, false, false);
        }
        true
    }

    fn rapid_of_group(&self, axes: u8, rpd: Option<f64>) -> f64 {
        match self.inp.rov {
            3 => self.params.one(P1421) as f64,
            r => {
                let base = rpd.unwrap_or_else(|| {
                    (0..AXES)
                        .filter(|n| axes >> n & 1 == 1)
                        .map(|n| self.params.get(P1420, n) as f64)
                        .fold(f64::INFINITY, f64::min)
                });
                base * [1.0, 0.5, 0.25][usize::from(r)]
            }
        }
    }

    fn start_command(&mut self, k: usize, cmd: Cmd) {
        let count = self.axis_count();
        let axes = (0..count)
            .filter(|&n| self.params.get(P8010, n) == k as i64 + 1 && self.inp.eax >> n & 1 == 1)
            .fold(0u8, |acc, n| acc | 1 << n);
        self.groups[k].exec = Some(Running {
            cmd,
            axes,
            work: Work::Speed { eif: 0 },
        });
        if self.inp.estop {
            self.end_command(k, true, None);
            return;
        }
        if let Some(&servo) = self.alarms.iter().find(|a| (401..=499).contains(*a)) {
            self.end_command(k, true, Some(servo));
            return;
        }
        if axes == 0 || !known(cmd.ec) {
            self.raise(ps::PLC_AXIS);
            self.end_command(k, true, Some(ps::PLC_AXIS));
            return;
        }
        let rpd = self.params.bit(P8002, 0, 0).then_some(f64::from(cmd.eif));
        let dia = self.diameters();
        let from: [i64; AXES] = std::array::from_fn(|n| self.axes[n].m);
        let to = |f: &dyn Fn(usize) -> i64| -> [i64; AXES] {
            std::array::from_fn(|n| if axes >> n & 1 == 1 { f(n) } else { from[n] })
        };
        let mv = |kind, target, rate, point| Work::Move {
            motion: Motion::new(kind, from, target, dia),
            rate,
            point,
        };
        let work = match cmd.ec {
            0x00 => mv(
                MotionKind::Rapid,
                to(&|n| from[n] + i64::from(cmd.eid)),
                Rate::Rapid(rpd),
                0,
            ),
            0x01 => mv(
                MotionKind::Cut,
                to(&|n| from[n] + i64::from(cmd.eid)),
                Rate::Feed(f64::from(cmd.eif)),
                0,
            ),
            0x02 => mv(
                MotionKind::Cut,
                to(&|n| from[n] + i64::from(cmd.eid)),
                Rate::PerRev(f64::from(cmd.eif) * 0.0001),
                0,
            ),
            0x04 => Work::Dwell {
                elapsed: 0.0,
                total: f64::from(cmd.eid.max(0)),
            },
            0x07 if (0..AXES).all(|n| axes >> n & 1 == 0 || self.axes[n].zrf) => mv(
                MotionKind::Rapid,
                to(&|n| self.params.get(P1240, n)),
                Rate::Rapid(rpd),
                1,
            ),
            0x05 | 0x07 => Work::Return {
                axes: std::array::from_fn(|n| {
                    (axes >> n & 1 == 1).then(|| self.start_return(n, self.axes[n].zrf))
                }),
                // EIF (RPD) replaces the rapid of 07h's straight return only; 05h is a manual
                // reference return, and the dog phase of 07h runs at #1424.
                rapid: if cmd.ec == 0x07 { rpd } else { None },
                dog_rapid: if cmd.ec == 0x07 { P1424 } else { P1420 },
            },
            0x06 => Work::Continuous {
                speed: cmd.eif,
                dir: if cmd.eid < 0 { -1 } else { 1 },
                runs: [Run::new(if cmd.eid < 0 { -1 } else { 1 }); AXES],
            },
            0x08..=0x0A => {
                if (0..AXES).any(|n| axes >> n & 1 == 1 && !self.axes[n].zrf) {
                    self.raise(ps::NO_REFERENCE);
                    self.end_command(k, true, None);
                    return;
                }
                let p = P1240 + usize::from(cmd.ec - 0x07);
                mv(
                    MotionKind::Rapid,
                    to(&|n| self.params.get(p, n)),
                    Rate::Rapid(rpd),
                    cmd.ec - 0x06,
                )
            }
            0x10 => Work::Speed {
                eif: cmd.eif as i16,
            },
            0x12 | 0x14 | 0x15 => Work::Aux {
                strobe: match cmd.ec {
                    0x12 => 0,
                    0x14 => 1,
                    _ => 2,
                },
                code: cmd.eid as u16,
                started: self.exchange_no,
            },
            _ => mv(
                MotionKind::Rapid,
                to(&|_| i64::from(cmd.eid)),
                Rate::Rapid(rpd),
                0,
            ),
        };
        if let Some(r) = &mut self.groups[k].exec {
            r.work = work;
        }
    }

    /// Step (e) for the PLC axes, group by group: ECLR, reading, start, advance.
    pub(super) fn advance_plc_axes(&mut self) {
        for k in 0..4 {
            self.groups[k].egen = false;
            let gi = self.group_in[k];
            if self.groups[k].held() > 0 {
                if self.inp.estop {
                    self.end_command(k, true, None);
                } else if let Some(&servo) = self.alarms.iter().find(|a| (401..=499).contains(*a)) {
                    self.end_command(k, true, Some(servo));
                }
            }
            if gi.eclr {
                self.clear_group(k, gi.ebuf);
                continue;
            }
            self.read_command(k);
            let g = &self.groups[k];
            let n = self.exchange_no;
            if g.exec.is_none()
                && !g.waiting.is_empty()
                && (!gi.esbk || g.emsbk_end_at == Some(n - 1))
            {
                let cmd = self.groups[k].waiting.remove(0);
                self.start_command(k, cmd);
            }
            self.advance_group(k);
        }
        self.eaxsl = self.groups.iter().any(|g| g.held() > 0);
    }

    fn clear_group(&mut self, k: usize, ebuf: bool) {
        let n = self.exchange_no;
        let g = &mut self.groups[k];
        if let Some(r) = g.exec.take() {
            g.finished(r.cmd.id, false);
            if r.cmd.emsbk {
                g.emsbk_end_at = Some(n);
            }
        }
        g.drop_waiting(false);
        if ebuf != g.ebsy {
            g.ebsy = ebuf;
            g.next_id += 1;
            g.last_read = g.next_id;
            g.last_ended = true;
            g.last_error = false;
        }
        let active = |a: u16| self.alarms.contains(&a);
        let g = &mut self.groups[k];
        if g.eial && !active(g.eial_alarm) {
            g.eial = false;
        }
        for d in 0..2 {
            if g.eot[d] && !active(g.eot_alarm[d]) {
                g.eot[d] = false;
            }
        }
    }

    fn read_command(&mut self, k: usize) {
        let gi = self.group_in[k];
        let g = &mut self.groups[k];
        if gi.ebuf == g.ebsy {
            return;
        }
        if let Some(r) = &mut g.exec
            && matches!(r.cmd.ec, 0x06 | 0x10)
        {
            // Read at once and not held: the same command changes its speed.
            g.ebsy = gi.ebuf;
            if gi.ec == r.cmd.ec {
                match &mut r.work {
                    Work::Continuous { speed, dir, runs } => {
                        let d = if gi.eid < 0 { -1 } else { 1 };
                        *speed = gi.eif;
                        if d != *dir {
                            *dir = d;
                            for run in runs.iter_mut() {
                                *run = Run::new(d);
                            }
                        }
                    }
                    Work::Speed { eif } => *eif = gi.eif as i16,
                    _ => {}
                }
            }
            g.last_read = r.cmd.id;
            g.last_ended = false;
            g.last_error = false;
            return;
        }
        let held = g.held();
        let any_exclusive = g.waiting.iter().any(|c| exclusive(c.ec))
            || g.exec.is_some_and(|r| exclusive(r.cmd.ec));
        let ok = held < 3
            && (!gi.embuf || held == 0)
            && !any_exclusive
            && (!exclusive(gi.ec) || held == 0);
        if !ok {
            return;
        }
        g.ebsy = gi.ebuf;
        g.next_id += 1;
        let cmd = Cmd {
            ec: gi.ec,
            eif: gi.eif,
            eid: gi.eid,
            emsbk: gi.emsbk,
            id: g.next_id,
        };
        g.waiting.push(cmd);
        g.last_read = cmd.id;
        g.last_ended = false;
        g.last_error = false;
    }

    fn advance_group(&mut self, k: usize) {
        let Some(mut r) = self.groups[k].exec else {
            return;
        };
        let gi = self.group_in[k];
        let paused = gi.estp;
        self.groups[k].paused = paused;
        let mut ended = false;
        match &mut r.work {
            Work::Aux { started, .. } => {
                ended = gi.efin && self.exchange_no > *started;
            }
            Work::Dwell { elapsed, total } => {
                if !paused {
                    *elapsed += 8.0;
                }
                ended = *elapsed >= *total;
            }
            Work::Speed { eif } => {
                self.groups[k].egen = *eif != 0 && !paused;
            }
            _ if paused => {}
            Work::Move {
                motion,
                rate,
                point,
            } => {
                let v = match *rate {
                    Rate::Rapid(rpd) => self.rapid_of_group(r.axes, rpd),
                    Rate::Feed(f) => f * self.fov(),
                    Rate::PerRev(x) => x * f64::from(self.spindle.s_out) * self.fov(),
                };
                if motion.is_empty() || v > 0.0 {
                    let covered = motion.next_covered(v);
                    let delta: [i64; AXES] = std::array::from_fn(|n| {
                        motion.position_at(n, covered) - motion.position_at(n, motion.covered)
                    });
                    if !self.move_group(k, &delta) {
                        return;
                    }
                    motion.covered = covered;
                    if !motion.is_empty() {
                        self.groups[k].egen = true;
                        match motion.kind {
                            MotionKind::Rapid => self.flags.rapid = true,
                            MotionKind::Cut => self.flags.cut = true,
                        }
                    }
                    if motion.is_empty() || motion.done() {
                        ended = true;
                        for n in 0..AXES {
                            if r.axes >> n & 1 == 1 {
                                match *point {
                                    1 => {
                                        self.axes[n].sh = 0;
                                        self.axes[n].zp = true;
                                    }
                                    2..=4 => self.axes[n].zp_n[usize::from(*point) - 2] = true,
                                    _ => {}
                                }
                            }
                        }
                    }
                }
            }
            Work::Return {
                axes,
                rapid,
                dog_rapid,
            } => {
                for (n, slot) in axes.iter_mut().enumerate() {
                    let Some(ret) = *slot else { continue };
                    let rate = if matches!(ret, Return::Direct(_)) {
                        self.rapid_of_group(r.axes, *rapid)
                    } else {
                        match self.inp.rov {
                            3 => self.params.one(P1421) as f64,
                            ro => {
                                self.params.get(*dog_rapid, n) as f64
                                    * [1.0, 0.5, 0.25][usize::from(ro)]
                            }
                        }
                    };
                    let dir = self.return_direction(&ret);
                    match self.return_step(n, ret, rate) {
                        Ok(next) => *slot = next,
                        Err(()) => {
                            self.overtravel_end(k, n, dir);
                            return;
                        }
                    }
                    if self.axes[n].mv {
                        self.groups[k].egen = true;
                    }
                }
                ended = axes.iter().all(Option::is_none);
            }
            Work::Continuous { speed, runs, .. } => {
                let v = f64::from(*speed) * self.fov();
                let mut delta = [0i64; AXES];
                for (n, run) in runs.iter_mut().enumerate() {
                    if r.axes >> n & 1 == 1 {
                        delta[n] = run.step(v, self.diameter(n));
                    }
                }
                if !self.move_group(k, &delta) {
                    return;
                }
                if v > 0.0 {
                    self.groups[k].egen = true;
                    self.flags.cut = true;
                }
            }
        }
        self.groups[k].exec = Some(r);
        if ended {
            self.end_command(k, false, None);
        }
    }

    /// The PLC-axis part of F.
    pub(super) fn plc_axes_f(&self, img: &mut FImage) {
        let mut eacnt = 0u8;
        let mut eaden = 0xFFu8;
        for (k, g) in self.groups.iter().enumerate() {
            let aux = g.exec.and_then(|r| match r.work {
                Work::Aux { strobe, code, .. } => Some((strobe, code)),
                _ => None,
            });
            img.group(k, fs::EINP, !g.egen);
            img.group(k, fs::EIAL, g.eial);
            img.group(k, fs::EDEN, aux.is_some());
            img.group(k, fs::EGEN, g.egen);
            img.group(k, fs::EOTP, g.eot[0]);
            img.group(k, fs::EOTN, g.eot[1]);
            img.group(k, fs::EBSY, g.ebsy);
            if let Some((strobe, code)) = aux {
                img.group(k, [fs::EMF, fs::EMF2, fs::EMF3][usize::from(strobe)], true);
                img.group_put(k, fs::EM_CODE, u32::from(code));
            }
            img.group(k, fs::EABUF, g.held() >= 3);
            if g.held() > 0 {
                for n in 0..self.axis_count() {
                    if self.params.get(P8010, n) == k as i64 + 1 {
                        eacnt |= 1 << n;
                    }
                }
            }
            for n in 0..AXES {
                if g.moving(n) {
                    eaden &= !(1 << n);
                }
            }
        }
        img.axes(fs::EACNT, eacnt);
        img.axes(fs::EADEN, eaden);
        img.set(fs::EOV0, self.fov() == 0.0);
        img.set(fs::EAXSL, self.eaxsl);
    }
}
