//! What a running device shows a monitor, and the faults it can be given.

/// The smallest `slow` factor (ten times faster).
pub const SLOW_MIN: f32 = 0.1;
/// The largest `slow` factor.
pub const SLOW_MAX: f32 = 1000.0;
/// The shortest flicker period, ms: two ticks, so the inputs read right in between.
pub const FLICKER_MIN_MS: u32 = 16;

/// A fault injected into a running device (never saved with the project).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Fault {
    /// Its inputs (or the one named) read `value` whatever the device does.
    Stuck {
        /// The value they read.
        value: bool,
        /// One input only: one of the device's own inputs.
        input: Option<crate::address::Address>,
    },
    /// It does everything `factor` times slower.
    Slow {
        /// How many times slower, [`SLOW_MIN`]…[`SLOW_MAX`] (below 1: faster).
        factor: f32,
    },
    /// After this many more operations it stops moving (its inputs keep their values).
    FailAfter {
        /// Operations until it fails.
        operations: u32,
    },
    /// Every `period_ms` (at least two ticks) its inputs read inverted for one tick.
    Flicker {
        /// The period, ms.
        period_ms: u32,
    },
}

/// A device as a monitor shows it.
#[derive(Clone, Debug, PartialEq)]
pub struct DeviceStatus {
    /// Its name.
    pub name: String,
    /// Its state.
    pub state: DeviceState,
    /// Moving, or a timer running: it is about to change.
    pub busy: bool,
    /// The fault injected, if any.
    pub fault: Option<Fault>,
    /// A `FailAfter` fault has struck: it no longer moves.
    pub failed: bool,
    /// Operations completed since power-on (docs/machine.md, "Faults": an actuator's arrival,
    /// a turret's stop, a pump start, a pulse, a counted edge, a follower coming on).
    pub operations: u32,
}

/// A device's state by kind.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum DeviceState {
    /// A follower, expression, position switch or pulse: its input.
    Switch {
        /// On.
        on: bool,
    },
    /// A counter: edges seen and the count it waits for.
    Counter {
        /// Edges seen.
        seen: u32,
        /// The count.
        count: u32,
    },
    /// An actuator.
    Actuator {
        /// 0 retracted … 1 advanced.
        position: f32,
        /// +1 advancing, −1 retracting, 0 still.
        moving: i8,
    },
    /// A turret.
    Turret {
        /// The station at the sensors, 0 between stations.
        station: u8,
        /// Where it stands, in stations from station 1 (0.5 is halfway to station 2).
        angle: f32,
        /// +1 CW, −1 CCW, 0 still.
        moving: i8,
        /// Locked.
        locked: bool,
    },
    /// Spindle feedback.
    Spindle {
        /// The motor's speed.
        rpm: f32,
        /// The speed it follows.
        target: u32,
    },
    /// Lubrication.
    Lube {
        /// Pressure up.
        pressure: bool,
        /// Pump starts since power-on.
        starts: u32,
        /// The level is low.
        low: bool,
    },
}
