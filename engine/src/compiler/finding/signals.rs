//! What the CNC interface checks (`compiler/cnc.rs`): strobes and finish signals, the M-code table, CNC signals and alarms find, as data.

use crate::address::Address;
use crate::compiler::Code;

/// A finding of the CNC interface checks (`compiler/cnc.rs`): strobes and finish signals, the M-code table, CNC signals and alarms.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub enum SignalFinding {
    /// W012: a strobe is read but nothing it drives leads to FIN or its own finish signal.
    StrobeNoFinish {
        /// The strobe's name (`TF`, `DM30`).
        strobe: String,
        /// The strobe's F bit.
        address: Address,
        /// The name of the finish signal that answers it besides FIN (`TFIN`).
        finish: String,
        /// That finish signal's G bit.
        finish_address: Address,
    },
    /// W013: a finish signal is written by more than one rung.
    FinishWriters {
        /// The finish signal's name.
        name: String,
        /// Its G bit.
        address: Address,
    },
    /// W013: a finish signal driven by a coil or box is also latched with SET/RST here.
    FinishDrivenAndLatched {
        /// The finish signal's name.
        name: String,
        /// Its G bit.
        address: Address,
    },
    /// W013: a finish signal is latched with SET and never reset.
    FinishNeverReset {
        /// The finish signal's name.
        name: String,
        /// Its G bit.
        address: Address,
    },
    /// W014: an M code of the M-code table that no rung decodes.
    MCodeNotDecoded {
        /// The M code.
        code: u32,
    },
    /// W014: an M code decoded here that has no row in the M-code table.
    MCodeNotInTable {
        /// The M code.
        code: u32,
    },
    /// W015: nothing writes *ESP (emergency stop): the CNC stays in emergency stop.
    EmergencyStopUnwritten {
        /// The signal's name.
        name: String,
        /// Its G bit.
        address: Address,
    },
    /// W015: nothing writes ERS (external reset): nothing on the machine can reset the CNC.
    ResetUnwritten {
        /// The signal's name.
        name: String,
        /// Its G bit.
        address: Address,
    },
    /// W015: nothing writes MD1 (mode select): no EDIT, MEM, JOG, DNC or REF mode can be selected.
    Mode1Unwritten {
        /// The signal's name.
        name: String,
        /// Its G bit.
        address: Address,
    },
    /// W015: nothing writes MD2 (mode select): the EDIT mode cannot be selected.
    Mode2Unwritten {
        /// The signal's name.
        name: String,
        /// Its G bit.
        address: Address,
    },
    /// W015: nothing writes MD4 (mode select): no HANDLE, JOG or REF mode can be selected.
    Mode4Unwritten {
        /// The signal's name.
        name: String,
        /// Its G bit.
        address: Address,
    },
    /// W016: an F answer is read but nothing writes the G request it answers.
    RequestUnwritten {
        /// The answer's name.
        answer: String,
        /// The answer's F bit.
        answer_address: Address,
        /// The request's name.
        request: String,
        /// The request's G bit.
        request_address: Address,
    },
    /// W017: an A bit is set here but its row of the message table has no alarm number.
    AlarmNoMessage {
        /// The A bit.
        address: Address,
    },
    /// W018: a message row with an alarm number whose A bit nothing sets.
    MessageNeverSet {
        /// The A bit of the row.
        address: Address,
        /// The row's alarm number.
        number: u16,
    },
}

impl SignalFinding {
    /// The diagnostic code of the finding.
    pub fn code(&self) -> Code {
        match self {
            SignalFinding::StrobeNoFinish { .. } => Code::W012StrobeNoFinish,
            SignalFinding::FinishWriters { .. }
            | SignalFinding::FinishDrivenAndLatched { .. }
            | SignalFinding::FinishNeverReset { .. } => Code::W013FinishWriters,
            SignalFinding::MCodeNotDecoded { .. } | SignalFinding::MCodeNotInTable { .. } => {
                Code::W014MCodeTable
            }
            SignalFinding::EmergencyStopUnwritten { .. }
            | SignalFinding::ResetUnwritten { .. }
            | SignalFinding::Mode1Unwritten { .. }
            | SignalFinding::Mode2Unwritten { .. }
            | SignalFinding::Mode4Unwritten { .. } => Code::W015CncSignalUnwritten,
            SignalFinding::RequestUnwritten { .. } => Code::W016RequestUnwritten,
            SignalFinding::AlarmNoMessage { .. } => Code::W017AlarmNoMessage,
            SignalFinding::MessageNeverSet { .. } => Code::W018MessageNeverSet,
        }
    }
}
