//! What the shape of a ladder network and of an instruction list read back into one (`compiler/lower.rs`, `decompile.rs`) find, as data.

use crate::compiler::Code;

/// A finding of the shape of a ladder network and of an instruction list read back into one (`compiler/lower.rs`, `decompile.rs`).
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub enum LowerFinding {}

impl LowerFinding {
    /// The diagnostic code of the finding.
    pub fn code(&self) -> Code {
        match *self {}
    }
}
