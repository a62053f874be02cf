//! What the machine model (`compiler/machine.rs`): devices, their addresses, parameters and conditions find, as data.

use crate::address::Address;
use crate::compiler::Code;
use crate::devices::ModelError;

/// A finding of the machine model (`compiler/machine.rs`): devices, their addresses, parameters and conditions.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub enum MachineFinding {
    /// M001–M005: a device that cannot be built, as the model's check refuses it.
    Device(ModelError),
    /// W010: a device reads an output (or a bit of its conditions) that nothing writes.
    ReadsNothing {
        /// The device's name.
        device: String,
        /// The field that reads it.
        field: String,
        /// The bit read.
        address: Address,
    },
    /// W011: an item of the operator panel drives an input a device writes.
    PanelDrivesInput {
        /// The device's name.
        device: String,
        /// The input.
        address: Address,
        /// The panel item's grid row, 0 at the top.
        row: u8,
        /// The panel item's grid column, 0 at the left.
        col: u8,
        /// The panel item's English label.
        label_en: String,
        /// The panel item's Chinese label.
        label_zh: String,
    },
}

impl MachineFinding {
    /// The diagnostic code of the finding.
    pub fn code(&self) -> Code {
        match self {
            MachineFinding::Device(e) => match e {
                ModelError::Name(_) | ModelError::NameTwice { .. } => Code::M001DeviceName,
                ModelError::Address { .. }
                | ModelError::NotInput { .. }
                | ModelError::NotBit { .. } => Code::M002DeviceAddress,
                ModelError::Parameter { .. } | ModelError::Start { .. } => {
                    Code::M003DeviceParameter
                }
                ModelError::Expression { .. } => Code::M004DeviceCondition,
                ModelError::TwoWriters { .. } => Code::M005InputTwice,
            },
            MachineFinding::ReadsNothing { .. } => Code::W010DeviceReadsNothing,
            MachineFinding::PanelDrivesInput { .. } => Code::W011PanelDrivesDeviceInput,
        }
    }
}
