//! What the saved scenarios (`diagnose.rs`): a scenario that would not apply find, as data.

use crate::compiler::Code;
use crate::scenario::NameError;
use crate::script::ScriptError;

/// A finding of the saved scenarios (`diagnose.rs`): a scenario that would not apply.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub enum ScenarioFinding {
    /// A name a script line cannot carry, or that an earlier scenario has.
    Name(NameError),
    /// A line that does not read against the project.
    Line {
        /// The scenario's name.
        scenario: String,
        /// Why the line does not read; its `line` counts the scenario's lines from 1.
        error: ScriptError,
    },
}

impl ScenarioFinding {
    /// The diagnostic code of the finding.
    pub fn code(&self) -> Code {
        match self {
            ScenarioFinding::Name(_) | ScenarioFinding::Line { .. } => Code::W019ScenarioBroken,
        }
    }
}
