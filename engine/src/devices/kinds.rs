//! Each device kind's behaviour in one tick: its resolved bindings, its state, and what it
//! means to write. Timings are kept in µs so that a slowed device (a fault) still moves in
//! whole numbers; a delay of D ms holds after ⌈D / 8⌉ ticks at normal speed.

use super::expr;
use super::model::DeviceKind;
use super::resolved::{Bit, CncView, Resolved};
use super::status::{DeviceState, DeviceStatus, Fault};
use super::turret::TurretRt;
use crate::address::Address;
use crate::cnc::AXES;
use crate::vm::TICK_MS;
use crate::vm::memory::Layout;
use std::ops::Range;

/// A running device: what a tick touches, kept small so that a long list stays in cache
/// (its name and power-on state live apart, in [`Cold`]).
#[derive(Clone, Debug)]
pub struct Rt {
    pub kind: RtKind,
    pub slots: Range<u32>,
    pub states: Range<u32>,
    pub fault: Option<Fault>,
    /// Operations since the fault was injected.
    pub fault_ops: u32,
    /// A failed device: its state no longer moves.
    pub frozen: bool,
    pub operations: u32,
}

/// What a tick does not touch: a device's name and its power-on state.
#[derive(Clone, Debug)]
pub struct Cold {
    pub name: String,
    pub init: RtKind,
}

impl Rt {
    pub fn new(kind: RtKind, slots: Range<u32>, states: Range<u32>) -> Rt {
        Rt {
            kind,
            slots,
            states,
            fault: None,
            fault_ops: 0,
            frozen: false,
            operations: 0,
        }
    }

    pub fn power_on(&mut self, init: &RtKind) {
        self.kind = init.clone();
        self.operations = 0;
        self.frozen = false;
        self.fault_ops = 0;
    }

    /// This tick's time step: a slowed device lives slower.
    #[inline]
    pub fn dt_us(&self) -> u64 {
        let tick = TICK_MS * 1000;
        match self.fault {
            Some(Fault::Slow { factor }) => {
                let f = f64::from(factor.clamp(super::SLOW_MIN, super::SLOW_MAX));
                ((tick as f64 / f).round() as u64).max(1)
            }
            _ => tick,
        }
    }

    pub fn count(&mut self, ops: u32) {
        self.operations += ops;
        if let Some(Fault::FailAfter { operations }) = self.fault {
            self.fault_ops += ops;
            if self.fault_ops >= operations {
                self.frozen = true;
            }
        }
    }

    /// Writes the status into `s`, reusing its name's buffer.
    pub fn status_into(&self, name: &str, s: &mut DeviceStatus) {
        if s.name != name {
            s.name.clear();
            s.name.push_str(name);
        }
        s.state = state(&self.kind);
        s.busy = busy(&self.kind);
        s.fault = self.fault;
        s.failed = self.frozen;
        s.operations = self.operations;
    }

    pub fn status(&self, name: &str) -> DeviceStatus {
        DeviceStatus {
            name: name.to_string(),
            state: state(&self.kind),
            busy: busy(&self.kind),
            fault: self.fault,
            failed: self.frozen,
            operations: self.operations,
        }
    }
}

/// A device's bindings resolved and its state.
#[derive(Clone, Debug)]
pub enum RtKind {
    Logic {
        when: Range<u32>,
        on_us: u64,
        off_us: u64,
        /// How long the condition has disagreed with the output.
        timer: u64,
        on: bool,
        slot: Option<u32>,
    },
    Actuator {
        advance: Bit,
        retract: Option<Bit>,
        travel_us: u64,
        /// 0 retracted … travel_us advanced.
        pos: u64,
        dir: i8,
        slots: [Option<u32>; 3],
    },
    Turret(Box<TurretRt>),
    Position {
        axis: usize,
        from: i64,
        to: i64,
        active_low: bool,
        on: bool,
        slot: Option<u32>,
    },
    Spindle {
        run: Range<u32>,
        /// rpm per µs of ramp.
        rate: f64,
        tolerance: f64,
        zero_rpm: f64,
        rpm: f64,
        target: u32,
        slots: [Option<u32>; 2],
    },
    Lube {
        pump: Bit,
        build_us: u64,
        decay_us: u64,
        limit: u32,
        /// Pump on: time on; off: time off.
        timer: u64,
        pumping: bool,
        up: bool,
        starts: u32,
        slots: [Option<u32>; 2],
    },
    Pulse {
        enable: Range<u32>,
        period_us: u64,
        on_us: u64,
        phase: u64,
        on: bool,
        slot: Option<u32>,
    },
    Counter {
        source: Range<u32>,
        count: u32,
        seen: u32,
        last: bool,
        slot: Option<u32>,
    },
}

/// What a step reads.
pub struct Ctx<'a> {
    pub mem: &'a [u8],
    pub terms: &'a [Resolved],
    pub states: &'a [bool],
    pub phys: &'a [i64; AXES],
    pub cnc: Option<&'a CncView>,
    pub dt_us: u64,
}

impl Ctx<'_> {
    fn eval(&self, r: &Range<u32>) -> bool {
        expr::eval(
            &self.terms[r.start as usize..r.end as usize],
            |off, mask| self.mem[off as usize] & mask != 0,
            |k| self.states[k as usize],
        )
    }
}

fn us(ms: u32) -> u64 {
    u64::from(ms) * 1000
}

/// Resolves a device's bindings: `slot` registers an input (in [`DeviceKind::inputs`]
/// order) and `exprs` are its conditions' ranges in [`DeviceKind::expressions`] order.
pub fn resolve(
    kind: &DeviceKind,
    layout: &Layout,
    slot: &mut dyn FnMut(Option<Address>) -> Option<u32>,
    exprs: &[Range<u32>],
) -> RtKind {
    let bit = |a: Address| Bit::of(layout, a);
    let e = |k: usize| exprs.get(k).cloned().unwrap_or(0..0);
    match kind {
        DeviceKind::Follower(l) | DeviceKind::Expression(l) => RtKind::Logic {
            when: e(0),
            on_us: us(l.on_ms),
            off_us: us(l.off_ms),
            timer: 0,
            on: false,
            slot: slot(Some(l.input)),
        },
        DeviceKind::Actuator(a) => {
            let travel_us = us(a.travel_ms).max(1);
            RtKind::Actuator {
                advance: bit(a.advance),
                retract: a.retract.map(bit),
                travel_us,
                pos: if a.start_advanced { travel_us } else { 0 },
                dir: 0,
                slots: [slot(a.at_advanced), slot(a.at_retracted), slot(a.moving)],
            }
        }
        DeviceKind::Turret(t) => RtKind::Turret(Box::new(TurretRt::resolve(t, &bit, slot))),
        DeviceKind::PositionSwitch(p) => RtKind::Position {
            axis: usize::from(p.axis).min(AXES - 1),
            from: (p.from_mm * 1000.0).round() as i64,
            to: (p.to_mm * 1000.0).round() as i64,
            active_low: p.active_low,
            on: false,
            slot: slot(Some(p.input)),
        },
        DeviceKind::Spindle(s) => RtKind::Spindle {
            run: e(0),
            rate: if s.ramp_ms == 0 {
                f64::INFINITY
            } else {
                f64::from(s.full_rpm) / us(s.ramp_ms) as f64
            },
            tolerance: f64::from(s.tolerance_pct) / 100.0,
            zero_rpm: f64::from(s.zero_rpm),
            rpm: 0.0,
            target: 0,
            slots: [slot(s.arrival), slot(s.zero)],
        },
        DeviceKind::Lubrication(l) => RtKind::Lube {
            pump: bit(l.pump),
            build_us: us(l.build_ms),
            decay_us: us(l.decay_ms),
            limit: l.operations,
            timer: 0,
            pumping: false,
            up: false,
            starts: 0,
            slots: [slot(l.pressure), slot(l.level_low)],
        },
        DeviceKind::Pulse(p) => RtKind::Pulse {
            enable: e(0),
            period_us: us(p.period_ms).max(1),
            on_us: us(p.on_ms),
            phase: 0,
            on: false,
            slot: slot(Some(p.input)),
        },
        DeviceKind::Counter(c) => RtKind::Counter {
            source: e(0),
            count: c.count,
            seen: 0,
            last: false,
            slot: slot(Some(c.input)),
        },
    }
}

/// Advances a device one tick; returns the operations it completed. Inlined into the tick's
/// loop: a call per device costs more than most devices' work.
#[inline(always)]
pub fn step(kind: &mut RtKind, c: &Ctx) -> u32 {
    let dt = c.dt_us;
    match kind {
        RtKind::Logic {
            when,
            on_us,
            off_us,
            timer,
            on,
            ..
        } => {
            let want = c.eval(when);
            if want == *on {
                *timer = 0;
                return 0;
            }
            *timer += dt;
            let need = if want { *on_us } else { *off_us };
            // The first tick a condition holds already counts 8 ms: a 0 ms delay is at once.
            if *timer >= need {
                *on = want;
                *timer = 0;
                return u32::from(want);
            }
            0
        }
        RtKind::Actuator {
            advance,
            retract,
            travel_us,
            pos,
            dir,
            ..
        } => {
            let a = advance.get(c.mem);
            let r = retract.map(|r| r.get(c.mem));
            *dir = match r {
                Some(r) if a && !r => 1,
                Some(r) if r && !a => -1,
                Some(_) => 0,
                None => {
                    if a {
                        1
                    } else {
                        -1
                    }
                }
            };
            let before = *pos;
            *pos = match *dir {
                1 => (*pos + dt).min(*travel_us),
                -1 => pos.saturating_sub(dt),
                _ => *pos,
            };
            let arrived = before != *pos && (*pos == 0 || *pos == *travel_us);
            if *pos == before {
                *dir = 0;
            }
            u32::from(arrived)
        }
        RtKind::Turret(t) => t.step(c.mem, dt),
        RtKind::Position {
            axis,
            from,
            to,
            active_low,
            on,
            ..
        } => {
            let p = c.phys[*axis];
            *on = (*from <= p && p <= *to) != *active_low;
            0
        }
        RtKind::Spindle {
            run,
            rate,
            rpm,
            target,
            ..
        } => {
            let s = c.cnc.map_or(0, |v| v.s_out);
            *target = if c.eval(run) { s } else { 0 };
            let t = f64::from(*target);
            let step = *rate * dt as f64;
            *rpm = if *rpm < t {
                (*rpm + step).min(t)
            } else {
                (*rpm - step).max(t)
            };
            0
        }
        RtKind::Lube {
            pump,
            build_us,
            decay_us,
            timer,
            pumping,
            up,
            starts,
            ..
        } => {
            let p = pump.get(c.mem);
            let mut ops = 0;
            if p != *pumping {
                *pumping = p;
                *timer = 0;
                if p {
                    *starts += 1;
                    ops = 1;
                }
            }
            // Capped: only whether it passed the longer of the two times matters.
            *timer = (*timer + dt).min(*build_us.max(decay_us));
            if p && *timer >= *build_us {
                *up = true;
            } else if !p && *timer >= *decay_us {
                *up = false;
            }
            ops
        }
        RtKind::Pulse {
            enable,
            period_us,
            on_us,
            phase,
            on,
            ..
        } => {
            if !c.eval(enable) {
                *phase = 0;
                *on = false;
                return 0;
            }
            let was = *on;
            *on = *phase < *on_us;
            *phase = (*phase + dt) % *period_us;
            u32::from(*on && !was)
        }
        RtKind::Counter {
            source, seen, last, ..
        } => {
            let v = c.eval(source);
            let edge = v && !*last;
            *last = v;
            if edge {
                *seen = seen.saturating_add(1);
            }
            u32::from(edge)
        }
    }
}

/// Copies a device's state (not its bindings) from the same device in an older plant.
pub fn take_state(new: &mut Rt, old: &Rt) {
    new.fault = old.fault;
    new.fault_ops = old.fault_ops;
    new.frozen = old.frozen;
    new.operations = old.operations;
    match (&mut new.kind, &old.kind) {
        (
            RtKind::Logic { timer, on, .. },
            RtKind::Logic {
                timer: t, on: o, ..
            },
        ) => {
            (*timer, *on) = (*t, *o);
        }
        (RtKind::Actuator { pos, dir, .. }, RtKind::Actuator { pos: p, dir: d, .. }) => {
            (*pos, *dir) = (*p, *d);
        }
        (RtKind::Turret(a), RtKind::Turret(b)) => a.take_state(b),
        (RtKind::Position { on, .. }, RtKind::Position { on: o, .. }) => *on = *o,
        (
            RtKind::Spindle { rpm, target, .. },
            RtKind::Spindle {
                rpm: r, target: t, ..
            },
        ) => {
            (*rpm, *target) = (*r, *t);
        }
        (
            RtKind::Lube {
                timer,
                pumping,
                up,
                starts,
                ..
            },
            RtKind::Lube {
                timer: t,
                pumping: p,
                up: u,
                starts: s,
                ..
            },
        ) => (*timer, *pumping, *up, *starts) = (*t, *p, *u, *s),
        (
            RtKind::Pulse { phase, on, .. },
            RtKind::Pulse {
                phase: p, on: o, ..
            },
        ) => {
            (*phase, *on) = (*p, *o);
        }
        (
            RtKind::Counter { seen, last, .. },
            RtKind::Counter {
                seen: s, last: l, ..
            },
        ) => {
            (*seen, *last) = (*s, *l);
        }
        _ => {}
    }
}

/// Publishes a device's states and the values it means to write.
#[inline(always)]
pub fn publish(d: &Rt, states: &mut [bool], values: &mut [bool]) {
    publish_with(d, states, |k, v| values[k as usize] = v);
}

/// Publishes a device's states, handing each value it means to write to `write` with its
/// slot: the tick writes a device without a fault straight into memory.
#[inline(always)]
pub fn publish_with(d: &Rt, states: &mut [bool], mut write: impl FnMut(u32, bool)) {
    let s = &mut states[d.states.start as usize..d.states.end as usize];
    let mut put = |slot: Option<u32>, v: bool| {
        if let Some(k) = slot {
            write(k, v);
        }
    };
    match &d.kind {
        RtKind::Logic { on, slot, .. }
        | RtKind::Position { on, slot, .. }
        | RtKind::Pulse { on, slot, .. } => {
            s[0] = *on;
            put(*slot, *on);
        }
        RtKind::Counter {
            seen, count, slot, ..
        } => {
            let on = *seen >= *count;
            s[0] = on;
            put(*slot, on);
        }
        RtKind::Actuator {
            pos,
            travel_us,
            slots,
            ..
        } => {
            let adv = *pos == *travel_us;
            let ret = *pos == 0;
            let moving = !adv && !ret;
            s.copy_from_slice(&[adv, ret, moving]);
            put(slots[0], adv);
            put(slots[1], ret);
            put(slots[2], moving);
        }
        RtKind::Turret(t) => t.publish(s, put),
        RtKind::Spindle {
            rpm,
            target,
            tolerance,
            zero_rpm,
            slots,
            ..
        } => {
            let t = f64::from(*target);
            let at_speed = *target > 0 && (*rpm - t).abs() <= t * *tolerance;
            let stopped = *rpm <= *zero_rpm;
            s.copy_from_slice(&[at_speed, stopped]);
            put(slots[0], at_speed);
            put(slots[1], stopped);
        }
        RtKind::Lube {
            up,
            starts,
            limit,
            slots,
            ..
        } => {
            let low = *limit > 0 && *starts >= *limit;
            s.copy_from_slice(&[*up, low]);
            put(slots[0], *up);
            put(slots[1], low);
        }
    }
}

fn state(k: &RtKind) -> DeviceState {
    match k {
        RtKind::Logic { on, .. } | RtKind::Position { on, .. } | RtKind::Pulse { on, .. } => {
            DeviceState::Switch { on: *on }
        }
        RtKind::Counter { seen, count, .. } => DeviceState::Counter {
            seen: *seen,
            count: *count,
        },
        RtKind::Actuator {
            pos,
            travel_us,
            dir,
            ..
        } => DeviceState::Actuator {
            position: *pos as f32 / *travel_us as f32,
            moving: *dir,
        },
        RtKind::Turret(t) => t.state(),
        RtKind::Spindle { rpm, target, .. } => DeviceState::Spindle {
            rpm: *rpm as f32,
            target: *target,
        },
        RtKind::Lube {
            up, starts, limit, ..
        } => DeviceState::Lube {
            pressure: *up,
            starts: *starts,
            low: *limit > 0 && *starts >= *limit,
        },
    }
}

fn busy(k: &RtKind) -> bool {
    match k {
        RtKind::Logic { timer, .. } => *timer > 0,
        RtKind::Actuator { dir, .. } => *dir != 0,
        RtKind::Turret(t) => t.moving(),
        RtKind::Spindle { rpm, target, .. } => *rpm != f64::from(*target),
        RtKind::Lube { pumping, up, .. } => *pumping != *up,
        _ => false,
    }
}

/// A device's main value (docs/machine.md, "Values").
pub fn value(k: &RtKind) -> i64 {
    match state(k) {
        DeviceState::Switch { on } => i64::from(on),
        DeviceState::Counter { seen, .. } => i64::from(seen),
        DeviceState::Actuator { position, .. } => (position * 100.0).round() as i64,
        DeviceState::Turret { station, .. } => i64::from(station),
        DeviceState::Spindle { rpm, .. } => rpm.round() as i64,
        DeviceState::Lube { pressure, .. } => i64::from(pressure),
    }
}
