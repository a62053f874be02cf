//! The machine around the CNC (docs/machine.md): devices that answer the ladder's outputs
//! with its inputs — a turret that turns while its motor output is on and shows its station
//! on the sensors, a chuck whose clamp switch closes after its travel time, dogs and limit
//! switches worked by the axes — so that a program runs against its machine with no hand
//! on the keyboard. The model is data in the project ([`model`]); [`Plant`] runs it once
//! per tick, before the PLC scan; faults are injected at run time and never saved.

pub mod check;
pub mod expr;
pub mod fields;
mod kinds;
pub mod model;
pub mod run;

pub use expr::ExprError;
pub use model::{Device, DeviceKind, MachineModel};
pub use run::Plant;

use crate::address::{Address, AddressError};
use std::fmt;

/// A fault injected into a running device (never saved with the project).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Fault {
    /// Its inputs (or the one named, by its index in [`DeviceKind::inputs`]) read `value`
    /// whatever the device does.
    Stuck {
        /// The value they read.
        value: bool,
        /// One input only.
        input: Option<u32>,
    },
    /// It does everything `factor` times slower.
    Slow {
        /// How many times slower, > 0.
        factor: f32,
    },
    /// After this many more operations it stops moving (its inputs keep their values).
    FailAfter {
        /// Operations until it fails.
        operations: u32,
    },
    /// Every `period_ms` its inputs read inverted for one tick.
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
    /// Operations completed since power-on (moves, station changes, pump starts, edges).
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

/// Why a machine model cannot run (`check` codes M001–M005).
#[derive(Clone, Debug, PartialEq)]
pub enum ModelError {
    /// M001: not a name.
    Name(String),
    /// M001: a name used twice.
    NameTwice {
        /// The name.
        name: String,
        /// The first device with it.
        first: usize,
    },
    /// M002: an address that does not read or is out of range.
    Address {
        /// The device.
        device: String,
        /// The field.
        field: &'static str,
        /// Why.
        error: AddressError,
    },
    /// M002: an input binding outside X.
    NotInput {
        /// The device.
        device: String,
        /// The field.
        field: &'static str,
        /// The address.
        address: Address,
    },
    /// M002: a byte address where a bit is needed.
    NotBit {
        /// The device.
        device: String,
        /// The field.
        field: &'static str,
        /// The address.
        address: Address,
    },
    /// M003: an impossible parameter.
    Parameter {
        /// The device.
        device: String,
        /// The field.
        field: &'static str,
        /// Its allowed values.
        limit: &'static str,
    },
    /// M004: a condition that does not read.
    Expression {
        /// The device.
        device: String,
        /// The field.
        field: &'static str,
        /// Why.
        error: ExprError,
    },
    /// M005: two devices write one input.
    TwoWriters {
        /// The later device.
        device: String,
        /// The input.
        address: Address,
        /// The device that writes it first.
        other: String,
    },
}

impl ModelError {
    /// The diagnostic code.
    pub fn code(&self) -> &'static str {
        match self {
            ModelError::Name(_) | ModelError::NameTwice { .. } => "M001",
            ModelError::Address { .. }
            | ModelError::NotInput { .. }
            | ModelError::NotBit { .. } => "M002",
            ModelError::Parameter { .. } => "M003",
            ModelError::Expression { .. } => "M004",
            ModelError::TwoWriters { .. } => "M005",
        }
    }

    /// The message in Chinese.
    pub fn zh(&self) -> String {
        match self {
            ModelError::Name(n) => format!(
                "设备名 `{n}` 无效：请用字母开头、由字母数字和 _ 组成、不像地址的名称（最多 24 个字符）"
            ),
            ModelError::NameTwice { name, first } => {
                format!(
                    "设备名 `{name}` 已被设备 {} 使用：请另起一个名称",
                    first + 1
                )
            }
            ModelError::Address {
                device,
                field,
                error,
            } => format!("设备 `{device}` 的 {field}：{}", error.zh()),
            ModelError::NotInput {
                device,
                field,
                address,
            } => format!(
                "设备 `{device}` 的 {field}：{address} 不是输入；设备只写 X 位（PLC 的输入）"
            ),
            ModelError::NotBit {
                device,
                field,
                address,
            } => format!(
                "设备 `{device}` 的 {field}：{address} 是字节，应写位地址（例如 {address}.0）"
            ),
            ModelError::Parameter {
                device,
                field,
                limit,
            } => format!("设备 `{device}` 的 {field} 不可能：允许 {limit}"),
            ModelError::Expression {
                device,
                field,
                error,
            } => format!("设备 `{device}` 的 {field}：{}", error.zh()),
            ModelError::TwoWriters {
                device,
                address,
                other,
            } => format!(
                "设备 `{device}` 和设备 `{other}` 都写 {address}：一个输入只能由一个设备驱动，请删去其中一个绑定"
            ),
        }
    }
}

impl fmt::Display for ModelError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ModelError::Name(n) => write!(
                f,
                "device name `{n}` is not valid: use letters, digits and _, starting with a letter, not an address, at most 24 characters"
            ),
            ModelError::NameTwice { name, first } => write!(
                f,
                "device name `{name}` is taken by device {}: give it another name",
                first + 1
            ),
            ModelError::Address {
                device,
                field,
                error,
            } => write!(f, "device `{device}`, {field}: {error}"),
            ModelError::NotInput {
                device,
                field,
                address,
            } => write!(
                f,
                "device `{device}`, {field}: {address} is not an input; a device writes X bits (the PLC's inputs)"
            ),
            ModelError::NotBit {
                device,
                field,
                address,
            } => write!(
                f,
                "device `{device}`, {field}: {address} is a byte; write a bit address such as {address}.0"
            ),
            ModelError::Parameter {
                device,
                field,
                limit,
            } => write!(
                f,
                "device `{device}`, {field} is impossible: allowed {limit}"
            ),
            ModelError::Expression {
                device,
                field,
                error,
            } => write!(f, "device `{device}`, {field}: {error}"),
            ModelError::TwoWriters {
                device,
                address,
                other,
            } => write!(
                f,
                "devices `{other}` and `{device}` both write {address}: one input is driven by one device; remove one of the bindings"
            ),
        }
    }
}
