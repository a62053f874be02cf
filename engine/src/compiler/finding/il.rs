//! What the reading of an instruction-list text (`il.rs`) find, as data.

use crate::compiler::Code;

/// A finding of the reading of an instruction-list text (`il.rs`).
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub enum IlFinding {}

impl IlFinding {
    /// The diagnostic code of the finding.
    pub fn code(&self) -> Code {
        match *self {}
    }
}
