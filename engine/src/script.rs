//! Why a script line (or a scenario line) cannot be used, as data: what was written and what
//! it broke. `ladder_text::script` words it. It lies below the compiler, which holds one in a
//! diagnostic of a saved scenario (W019), and `sim` re-exports it.

use crate::address::{Address, AddressError, Target};
use crate::cnc::command::CncError;

/// A script line that cannot be used.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct ScriptError {
    /// 1-based line.
    pub line: usize,
    /// What is wrong.
    pub reason: ScriptReason,
}

/// What is wrong with a script line.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub enum ScriptReason {
    /// The words of the line do not split.
    Quote(QuoteError),
    /// A line with the wrong number of words for its command.
    Usage {
        /// The command's usage, as the script syntax writes it.
        usage: &'static str,
    },
    /// A command none of [`COMMANDS`](crate::sim::COMMANDS).
    UnknownCommand {
        /// The command as written.
        verb: String,
        /// A command with the same first three letters, if any.
        near: Option<&'static str>,
    },
    /// `ADDR:N` with N none of 1, 2, 4.
    ByteCount {
        /// The target as written.
        text: String,
    },
    /// A label or subprogram given where a value is read or written.
    NoValue {
        /// The target as written.
        text: String,
    },
    /// A bit address with `:N`.
    BitWithByteCount {
        /// The target as written.
        text: String,
    },
    /// An address that does not read or is beyond the controller's range.
    Address(AddressError),
    /// A `cnc.KEY` read in a script run without the simulated CNC.
    CncValueNeedsCnc {
        /// The key as written.
        text: String,
    },
    /// A `cnc` line in a script run without the simulated CNC.
    CncLineNeedsCnc,
    /// A `cnc` line or `cnc.KEY` the simulated CNC refuses.
    Cnc(CncError),
    /// A command writing PLC memory given a `cnc.KEY`.
    WritesMemory {
        /// The command.
        verb: &'static str,
        /// The key as written.
        text: String,
    },
    /// A value that is no integer.
    NotInteger {
        /// The value as written.
        text: String,
    },
    /// A bit given a value other than 0 or 1.
    NotBit {
        /// The bit.
        target: Target,
        /// The value given.
        value: i64,
    },
    /// A value beyond what the target's bytes hold.
    DoesNotFit {
        /// The value given.
        value: i64,
        /// The target.
        target: Target,
        /// The least value it holds.
        lo: i64,
        /// The greatest value it holds.
        hi: i64,
    },
    /// A duration that does not read.
    NotDuration {
        /// The duration as written.
        text: String,
    },
    /// A duration longer than one line may run.
    TooLong {
        /// The duration as written.
        text: String,
        /// The longest a line may run, in seconds.
        seconds: u64,
        /// The same in ticks.
        ticks: u64,
    },
    /// A value that is no number.
    NotNumber {
        /// The value as written.
        text: String,
    },
    /// `setf` or `expectf` of an address that does not hold 4 bytes.
    NotFourBytes {
        /// The command.
        verb: &'static str,
        /// The address.
        address: Address,
    },
    /// The N of `scan N` that is no number.
    NotScanCount {
        /// N as written.
        text: String,
    },
    /// `scan N` with more scans than one line may run.
    TooManyScans {
        /// N as written.
        text: String,
        /// The most scans a line may run.
        most: u64,
    },
    /// `division N` with N outside 1–1000.
    Division {
        /// N as written.
        text: String,
    },
    /// A refusal of a `device` line or a `device.NAME` value.
    Device(DeviceReason),
    /// A refusal of a scenario line or of the `scenario` script line.
    Scenario(ScenarioReason),
}

/// Why a line does not split into words.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum QuoteError {
    /// A `"` with no closing one.
    Unclosed,
    /// A closing `"` followed by something other than a space or a comment.
    NoSpaceAfter,
    /// A `"` inside a word.
    InsideWord,
}

/// What the number a `device … fault` word should be stands for.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum DeviceQuantity {
    /// The factor of `fault slow`.
    Factor,
    /// The count of `fault fail-after`.
    Operations,
    /// The period of `fault flicker`.
    PeriodMs,
}

/// Why a `device` line, a `device.NAME` value or a write of a device's input is refused.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub enum DeviceReason {
    /// A device line or value with no machine model to act on.
    NoModel {
        /// What needs it: `device` or the `device.NAME` text.
        what: String,
    },
    /// A device name the model does not have.
    NoDevice {
        /// The name as written.
        name: String,
        /// The model's devices.
        devices: Vec<String>,
    },
    /// A stuck value other than 0 or 1.
    NotBinary {
        /// The value as written.
        text: String,
    },
    /// A fault's number that does not read.
    NotQuantity {
        /// The number as written.
        text: String,
        /// What it stands for.
        what: DeviceQuantity,
    },
    /// A slow factor outside `SLOW_MIN…SLOW_MAX`.
    SlowFactor {
        /// The factor as written.
        text: String,
    },
    /// A flicker period below the shortest.
    FlickerPeriod {
        /// The period as written.
        text: String,
        /// The shortest period, in ms.
        min_ms: u32,
    },
    /// A stuck input the device does not write.
    NotInput {
        /// The device.
        device: String,
        /// The address given.
        address: Address,
        /// The inputs the device writes.
        inputs: Vec<Address>,
    },
    /// A write of an input a device writes every tick.
    Driven {
        /// The command (`set`, `setf`, `panel`).
        verb: &'static str,
        /// The target written.
        target: Target,
        /// The device's input it covers.
        input: Address,
        /// The device.
        device: String,
    },
}

/// Why a scenario line or the `scenario` script line is refused.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub enum ScenarioReason {
    /// A scenario line of a command a scenario does not hold.
    NotScenarioLine {
        /// The command as written.
        verb: String,
    },
    /// A scenario's `device` line that is not a fault.
    FaultsOnly,
    /// `panel LABEL` naming no item of the operator panel.
    NoPanelItem {
        /// The label as written.
        label: String,
    },
    /// A key or switch given a state other than 0 or 1.
    KeyState {
        /// The label as written.
        label: String,
        /// The state as written.
        value: String,
    },
    /// A knob given a position it does not have.
    NoKnobPosition {
        /// The label as written.
        label: String,
        /// The position as written.
        value: String,
        /// The knob's positions.
        positions: Vec<String>,
    },
    /// `panel` of a lamp.
    Lamp {
        /// The label as written.
        label: String,
    },
    /// A `scenario` line in a script run without a project.
    NoProject,
    /// A `scenario` line naming no scenario of the project.
    NoScenario {
        /// The name as written.
        name: String,
        /// The project's scenarios.
        names: Vec<String>,
    },
    /// A `scenario` line whose scenario does not apply.
    Broken {
        /// The scenario.
        scenario: String,
        /// Its line that does not apply (`line` counts the scenario's lines from 1).
        error: Box<ScriptError>,
    },
}

impl From<AddressError> for ScriptReason {
    fn from(e: AddressError) -> ScriptReason {
        ScriptReason::Address(e)
    }
}

impl From<CncError> for ScriptReason {
    fn from(e: CncError) -> ScriptReason {
        ScriptReason::Cnc(e)
    }
}

impl From<QuoteError> for ScriptReason {
    fn from(e: QuoteError) -> ScriptReason {
        ScriptReason::Quote(e)
    }
}

impl From<DeviceReason> for ScriptReason {
    fn from(e: DeviceReason) -> ScriptReason {
        ScriptReason::Device(e)
    }
}

impl From<ScenarioReason> for ScriptReason {
    fn from(e: ScenarioReason) -> ScriptReason {
        ScriptReason::Scenario(e)
    }
}
