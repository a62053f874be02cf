//! What the program-wide checks (`compiler/check.rs`, `writes.rs`, `presets.rs`): subprogram numbers, labels, jumps and calls, coils and timers used twice, step limits, stack depth, undefined symbols, operands find, as data.

use crate::compiler::Code;

/// A finding of the program-wide checks (`compiler/check.rs`, `writes.rs`, `presets.rs`): subprogram numbers, labels, jumps and calls, coils and timers used twice, step limits, stack depth, undefined symbols, operands.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub enum CheckFinding {}

impl CheckFinding {
    /// The diagnostic code of the finding.
    pub fn code(&self) -> Code {
        match *self {}
    }
}
