//! The turret or indexer in one tick: its position along the circle of stations, the station
//! its sensors show (a window centred on each station, and a station stepped over in one tick
//! shown for that tick), the CCW lock of a one-way tool post and the lock stage.

use super::model::{Encoding, Turret};
use super::resolved::Bit;
use super::status::DeviceState;
use crate::address::Address;
use std::ops::Range;

/// A turret's bindings and state.
#[derive(Clone, Debug)]
pub struct TurretRt {
    stations: u64,
    cw: Bit,
    ccw: Option<Bit>,
    direction: Option<Bit>,
    ccw_locks: bool,
    station_us: u64,
    window_us: u64,
    lock: Option<(Bit, u64)>,
    encoding: Encoding,
    active_low: bool,
    code: Range<u32>,
    in_position: Option<u32>,
    lock_slots: [Option<u32>; 2],
    /// Where it stands, µs of turning from station 1.
    pos: u64,
    moving: i8,
    /// Pulled onto the pawl (one-way tool post).
    pawl: bool,
    /// Unlock progress, 0 locked … the lock time unlocked.
    unlock: u64,
    /// A station whose window the last tick's motion crossed whole (a fast or slowed turret
    /// may step over a narrow window): shown for that one tick, 0 for none.
    passed: u32,
}

impl TurretRt {
    /// The station at the sensors (1…), 0 between stations; a station stepped over in the
    /// last tick shows for that tick.
    fn station(&self) -> u32 {
        match self.at_window() {
            0 => self.passed,
            s => s,
        }
    }

    /// The station whose window holds the turret now (1…), 0 between stations.
    fn at_window(&self) -> u32 {
        let total = self.stations * self.station_us;
        let k = (self.pos + self.station_us / 2) / self.station_us % self.stations;
        let centre = k * self.station_us;
        let d = self
            .pos
            .abs_diff(centre)
            .min(total - self.pos.abs_diff(centre));
        if d * 2 <= self.window_us {
            k as u32 + 1
        } else {
            0
        }
    }

    fn locked(&self) -> bool {
        match self.lock {
            Some(_) => self.unlock == 0,
            None => self.ccw_locks && self.pawl,
        }
    }
}

impl TurretRt {
    /// Resolves a turret's bindings: `bit` an output's bit, `slot` registers an input (code
    /// bits, in-position, the lock stage's switches, in [`super::DeviceKind::inputs`] order).
    pub fn resolve(
        t: &Turret,
        bit: &dyn Fn(Address) -> Bit,
        slot: &mut dyn FnMut(Option<Address>) -> Option<u32>,
    ) -> TurretRt {
        let first = slot(t.code.first.offset_bits(0));
        for k in 1..t.code.bits {
            slot(t.code.first.offset_bits(u32::from(k)));
        }
        let code = first.map_or(0..0, |f| f..f + u32::from(t.code.bits));
        let in_position = slot(t.in_position);
        let lock_slots = match &t.lock {
            Some(l) => [slot(l.unlocked), slot(l.locked)],
            None => [None, None],
        };
        let station_us = u64::from(t.station_ms).max(1) * 1000;
        TurretRt {
            stations: u64::from(t.stations.max(1)),
            cw: bit(t.cw),
            ccw: t.ccw.map(bit),
            direction: t.direction.map(bit),
            ccw_locks: t.ccw_locks,
            station_us,
            window_us: station_us * u64::from(t.window_pct.clamp(1, 100)) / 100,
            lock: t
                .lock
                .as_ref()
                .map(|l| (bit(l.unlock), u64::from(l.ms) * 1000)),
            encoding: t.code.encoding,
            active_low: t.code.active_low,
            code,
            in_position,
            lock_slots,
            pos: u64::from(t.start_station.clamp(1, t.stations.max(1)) - 1) * station_us,
            moving: 0,
            pawl: true,
            unlock: 0,
            passed: 0,
        }
    }

    /// Whether it turns.
    pub fn moving(&self) -> bool {
        self.moving != 0
    }

    /// Its state for a monitor.
    pub fn state(&self) -> DeviceState {
        DeviceState::Turret {
            station: self.station() as u8,
            angle: self.pos as f32 / self.station_us as f32,
            moving: self.moving,
            locked: self.locked(),
        }
    }

    /// Its states (`moving`, `in_position`, `locked`) into `s`, its inputs to `put`.
    #[inline(always)]
    pub fn publish(&self, s: &mut [bool], mut put: impl FnMut(Option<u32>, bool)) {
        let station = self.station();
        let code = self.encoding.code(station);
        for (i, k) in self.code.clone().enumerate() {
            put(Some(k), (code >> i & 1 == 1) != self.active_low);
        }
        let in_pos = station != 0 && self.moving == 0;
        s.copy_from_slice(&[self.moving != 0, in_pos, self.locked()]);
        put(self.in_position, in_pos);
        if let Some((_, ms)) = self.lock {
            put(self.lock_slots[0], self.unlock >= ms);
            put(self.lock_slots[1], self.unlock == 0);
        }
    }

    /// Takes the state (not the bindings) of the same turret in an older plant.
    pub fn take_state(&mut self, old: &TurretRt) {
        self.pos = old.pos;
        self.moving = old.moving;
        self.pawl = old.pawl;
        self.unlock = old.unlock;
        self.passed = old.passed;
    }

    /// Advances it `dt` µs; returns 1 when it stopped after a motion (an operation).
    #[inline(always)]
    pub fn step(&mut self, mem: &[u8], dt: u64) -> u32 {
        step(self, mem, dt)
    }
}

#[inline(always)]
fn step(t: &mut TurretRt, mem: &[u8], dt: u64) -> u32 {
    let (cw, ccw) = match t.direction {
        Some(d) => {
            let run = t.cw.get(mem);
            let back = d.get(mem);
            (run && !back, run && back)
        }
        None => (t.cw.get(mem), t.ccw.is_some_and(|b| b.get(mem))),
    };
    if let Some((out, ms)) = t.lock {
        t.unlock = if out.get(mem) {
            (t.unlock + dt).min(ms)
        } else {
            t.unlock.saturating_sub(dt)
        };
    }
    let free = t.lock.is_none_or(|(_, ms)| t.unlock >= ms);
    let total = t.stations * t.station_us;
    let was = t.moving;
    let from = t.pos;
    t.moving = 0;
    t.passed = 0;
    if cw && !ccw && free {
        t.pos = (t.pos + dt) % total;
        t.moving = 1;
        t.pawl = false;
    } else if ccw && !cw && t.ccw_locks {
        // Reversed onto the pawl: it stops at the nearest station and locks.
        let k = (t.pos + t.station_us / 2) / t.station_us % t.stations;
        t.pos = k * t.station_us;
        t.pawl = true;
    } else if ccw && !cw && free {
        t.pos = (t.pos + total - dt % total) % total;
        t.moving = -1;
        t.pawl = false;
    }
    if t.moving != 0 && t.at_window() == 0 {
        t.passed = crossed(t, from);
    }
    u32::from(was != 0 && t.moving == 0)
}

/// The station whose centre the turret crossed moving from `from` to where it is, if it was
/// in no station's window before or after (the step was wider than the window).
fn crossed(t: &TurretRt, from: u64) -> u32 {
    let total = t.stations * t.station_us;
    // The way travelled, forward from the lower end, in [0, total).
    let (start, len) = if t.moving > 0 {
        (from, (t.pos + total - from) % total)
    } else {
        (t.pos, (from + total - t.pos) % total)
    };
    // The first station centre at or after `start`.
    let next = start.div_ceil(t.station_us) * t.station_us;
    if next - start <= len && len > 0 {
        ((next / t.station_us) % t.stations) as u32 + 1
    } else {
        0
    }
}
