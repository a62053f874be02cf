//! Why a command to the running machine was not carried out: data only. The command line
//! and the editor word it in the user's language (`ladder_text::refusal`).

use crate::cnc::{CncError, RunState};
use crate::devices::ModelError;
use crate::vm::SwapError;

/// A command the machine refused, with what the words need.
#[derive(Clone, Debug, PartialEq)]
pub enum Refusal {
    /// A `cnc` command the CNC refuses for what it says (a parameter's value, an axis).
    Cnc(CncError),
    /// A new program while automatic operation is not idle.
    ProgramBusy(RunState),
    /// A tool offset number outside the profile's range.
    OffsetNumber {
        /// The first offset number.
        lo: u8,
        /// The last offset number.
        hi: u8,
        /// The number asked for.
        number: u8,
    },
    /// A macro variable that cannot take the value (a system variable, or out of range).
    MacroValue(u16),
    /// A position set on an axis that is moving (axis name).
    AxisMoving(&'static str),
    /// A CNC command with no CNC attached.
    NoCnc,
    /// A device command with no machine model running.
    NoMachineModel,
    /// A device number beyond the model's devices (0-based).
    NoDevice(usize),
    /// A machine model that cannot be loaded.
    Model(ModelError),
    /// An edited program that cannot take over the running one.
    Swap(SwapError),
    /// A scenario applied twice (its name).
    ScenarioApplied(String),
    /// A scenario that injects a fault into a device that is not running.
    ScenarioNeedsModel {
        /// The scenario.
        name: String,
        /// The device (0-based).
        device: usize,
    },
    /// A scenario released that is not applied (its name).
    ScenarioNotApplied(String),
    /// A scenario released before one applied after it that changed the same thing.
    ScenarioOrder {
        /// The scenario released.
        name: String,
        /// The later scenario to release first.
        other: String,
    },
}

/// A refusal of the running CNC says what a refusal when parsed says.
impl From<CncError> for Refusal {
    fn from(e: CncError) -> Refusal {
        Refusal::Cnc(e)
    }
}
