//! What the tables (`compiler/tables.rs`): symbols, data, messages, diagnosis, permission and M-code tables, version and comments find, as data.

use crate::compiler::Code;

/// A finding of the tables (`compiler/tables.rs`): symbols, data, messages, diagnosis, permission and M-code tables, version and comments.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub enum TableFinding {}

impl TableFinding {
    /// The diagnostic code of the finding.
    pub fn code(&self) -> Code {
        match *self {}
    }
}
