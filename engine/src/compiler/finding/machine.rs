//! What the machine model (`compiler/machine.rs`): devices, their addresses, parameters and conditions find, as data.

use crate::compiler::Code;

/// A finding of the machine model (`compiler/machine.rs`): devices, their addresses, parameters and conditions.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub enum MachineFinding {}

impl MachineFinding {
    /// The diagnostic code of the finding.
    pub fn code(&self) -> Code {
        match *self {}
    }
}
