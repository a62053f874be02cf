//! What the saved scenarios (`diagnose.rs`): a scenario that would not apply find, as data.

use crate::compiler::Code;

/// A finding of the saved scenarios (`diagnose.rs`): a scenario that would not apply.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub enum ScenarioFinding {}

impl ScenarioFinding {
    /// The diagnostic code of the finding.
    pub fn code(&self) -> Code {
        match *self {}
    }
}
