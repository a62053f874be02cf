//! The runner's pace: when each tick is due at real time or a multiple of it, and how late
//! ticks were.

use crate::vm::TICK_MS;
use std::time::{Duration, Instant};

/// How fast the machine runs.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Speed {
    /// One 8 ms tick per 8 ms, as on the controller.
    #[default]
    RealTime,
    /// Ten times real time.
    Times10,
    /// A hundred times real time.
    Times100,
    /// As fast as the processor allows.
    Max,
}

impl Speed {
    /// Every speed, slowest first.
    pub const ALL: [Speed; 4] = [Speed::RealTime, Speed::Times10, Speed::Times100, Speed::Max];

    /// Real time multiplied by this (`None` for as fast as possible).
    pub fn factor(self) -> Option<u32> {
        match self {
            Speed::RealTime => Some(1),
            Speed::Times10 => Some(10),
            Speed::Times100 => Some(100),
            Speed::Max => None,
        }
    }
}

/// How late ticks started against their real-time due time (real time only).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Lateness {
    /// The latest a tick started, ms.
    pub max_ms: f64,
    /// Ticks that started more than one tick (8 ms) late.
    pub over_a_tick: u64,
    /// Ticks timed.
    pub timed: u64,
}

/// Ticks run in one go at full speed before the runner publishes and reads requests again.
const MAX_BATCH: u64 = 64;

pub(super) struct Clock {
    speed: Speed,
    origin: Instant,
    origin_ticks: u64,
    next_due: Instant,
    lateness: Lateness,
}

impl Clock {
    pub(super) fn new(speed: Speed) -> Clock {
        Clock {
            speed,
            origin: Instant::now(),
            origin_ticks: 0,
            next_due: Instant::now(),
            lateness: Lateness::default(),
        }
    }

    pub(super) fn speed(&self) -> Speed {
        self.speed
    }

    pub(super) fn lateness(&self) -> Lateness {
        self.lateness
    }

    fn period(&self) -> Option<Duration> {
        self.speed
            .factor()
            .map(|f| Duration::from_micros(TICK_MS * 1000 / u64::from(f)))
    }

    /// Counts ticks from `now`: the next tick (after `ticks` run) is due at once.
    pub(super) fn restart(&mut self, now: Instant, ticks: u64) {
        self.origin = now;
        self.origin_ticks = ticks;
        self.next_due = now;
    }

    fn due_at(&self, period: Duration, ticks: u64) -> Instant {
        let n = ticks.saturating_sub(self.origin_ticks);
        self.origin + period.saturating_mul(n.min(u64::from(u32::MAX)) as u32)
    }

    /// How long until the next tick is due.
    pub(super) fn until_due(&self, now: Instant) -> Duration {
        // Set by the last `due_ticks`: the tick after the batch it gave.
        self.next_due.saturating_duration_since(now)
    }

    /// How many ticks are due now, after `ticks` have run. A machine more than a second
    /// behind (the system was suspended) starts counting again instead of racing to catch up.
    pub(super) fn due_ticks(&mut self, now: Instant, ticks: u64) -> u64 {
        let Some(p) = self.period() else {
            self.next_due = now;
            return MAX_BATCH;
        };
        let since = now.saturating_duration_since(self.origin);
        let elapsed = (since.as_nanos() / p.as_nanos().max(1)) as u64 + 1;
        let done = ticks.saturating_sub(self.origin_ticks);
        let mut due = elapsed.saturating_sub(done);
        let second = 1000 / TICK_MS * u64::from(self.speed.factor().unwrap_or(1));
        if due > second {
            self.restart(now, ticks);
            due = 1;
        }
        let due = due.min(second / 8 + 1);
        self.next_due = self.due_at(p, ticks + due);
        due
    }

    /// Notes that tick number `ticks` + 1 starts now.
    pub(super) fn ticked(&mut self, now: Instant, ticks: u64) {
        if self.speed != Speed::RealTime {
            return;
        }
        let Some(p) = self.period() else { return };
        let late = now.saturating_duration_since(self.due_at(p, ticks));
        let ms = late.as_secs_f64() * 1000.0;
        let l = &mut self.lateness;
        l.timed += 1;
        if ms > l.max_ms {
            l.max_ms = ms;
        }
        if ms > TICK_MS as f64 {
            l.over_a_tick += 1;
        }
    }
}
