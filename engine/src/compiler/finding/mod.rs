//! What a diagnostic found, as data with no words: the check that failed and the addresses,
//! names, numbers and places it is about. `ladder-text` words each finding in Chinese and in
//! English, so the editor and the command line say the same thing from one table
//! (docs/diagnostics.md lists every code with an example).

mod check;
mod il;
mod lower;
mod machine;
mod scenario;
mod signals;
mod tables;

pub use check::CheckFinding;
pub use il::IlFinding;
pub use lower::LowerFinding;
pub use machine::MachineFinding;
pub use scenario::ScenarioFinding;
pub use signals::SignalFinding;
pub use tables::TableFinding;

use super::Code;

/// What a diagnostic found, by the part of the compiler that found it.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub enum Finding {
    /// Found by the program-wide checks.
    Check(CheckFinding),
    /// Found by the tables.
    Table(TableFinding),
    /// Found by the shape of a ladder network and of an instruction list read back into one.
    Lower(LowerFinding),
    /// Found by the reading of an instruction-list text.
    Il(IlFinding),
    /// Found by the CNC interface checks.
    Signal(SignalFinding),
    /// Found by the machine model.
    Machine(MachineFinding),
    /// Found by the saved scenarios.
    Scenario(ScenarioFinding),
}

impl Finding {
    /// The diagnostic code of the finding.
    pub fn code(&self) -> Code {
        match self {
            Finding::Check(f) => f.code(),
            Finding::Table(f) => f.code(),
            Finding::Lower(f) => f.code(),
            Finding::Il(f) => f.code(),
            Finding::Signal(f) => f.code(),
            Finding::Machine(f) => f.code(),
            Finding::Scenario(f) => f.code(),
        }
    }
}

impl From<CheckFinding> for Finding {
    fn from(f: CheckFinding) -> Finding {
        Finding::Check(f)
    }
}

impl From<TableFinding> for Finding {
    fn from(f: TableFinding) -> Finding {
        Finding::Table(f)
    }
}

impl From<LowerFinding> for Finding {
    fn from(f: LowerFinding) -> Finding {
        Finding::Lower(f)
    }
}

impl From<IlFinding> for Finding {
    fn from(f: IlFinding) -> Finding {
        Finding::Il(f)
    }
}

impl From<SignalFinding> for Finding {
    fn from(f: SignalFinding) -> Finding {
        Finding::Signal(f)
    }
}

impl From<MachineFinding> for Finding {
    fn from(f: MachineFinding) -> Finding {
        Finding::Machine(f)
    }
}

impl From<ScenarioFinding> for Finding {
    fn from(f: ScenarioFinding) -> Finding {
        Finding::Scenario(f)
    }
}
