//! What the CNC interface checks (`compiler/cnc.rs`): strobes and finish signals, the M-code table, CNC signals and alarms find, as data.

use crate::compiler::Code;

/// A finding of the CNC interface checks (`compiler/cnc.rs`): strobes and finish signals, the M-code table, CNC signals and alarms.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub enum SignalFinding {}

impl SignalFinding {
    /// The diagnostic code of the finding.
    pub fn code(&self) -> Code {
        match *self {}
    }
}
