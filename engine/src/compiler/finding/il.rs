//! What the reading of an instruction-list text (`il.rs`) find, as data.

use crate::catalog::Op;
use crate::compiler::Code;
use crate::model::OperandError;

/// A finding of the reading of an instruction-list text (`il.rs`).
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub enum IlFinding {
    /// A word that names no instruction (L010).
    UnknownInstruction {
        /// The word as written, cut short with `…` when it is long enough to flood the message.
        word: String,
        /// The instruction it is close enough to be a typo of, if any.
        meant: Option<Op>,
    },
    /// A quoted text with no closing quote (L012).
    UnclosedQuote,
    /// A line that starts with a quoted text (L012).
    QuotedLineStart,
    /// Something after `LEVEL1` or `LEVEL2` (L012).
    AfterLevel {
        /// 1 or 2.
        level: u8,
    },
    /// `SUB` without a subprogram number (L012).
    SubWithoutNumber,
    /// A network title written without quotes (L012).
    UnquotedTitle {
        /// The title as written.
        title: String,
    },
    /// An operand written in quotes (L012).
    QuotedOperand {
        /// The operand's text, inside the quotes.
        text: String,
    },
    /// An operand that does not read (L012).
    BadOperand {
        /// The instruction it belongs to.
        op: Op,
        /// Why it does not read.
        error: OperandError,
    },
    /// A network whose drawn ladder does not read back as its list (L017).
    NotReadBack,
}

impl IlFinding {
    /// The diagnostic code of the finding.
    pub fn code(&self) -> Code {
        match self {
            IlFinding::UnknownInstruction { .. } => Code::L010UnknownInstruction,
            IlFinding::UnclosedQuote
            | IlFinding::QuotedLineStart
            | IlFinding::AfterLevel { .. }
            | IlFinding::SubWithoutNumber
            | IlFinding::UnquotedTitle { .. }
            | IlFinding::QuotedOperand { .. }
            | IlFinding::BadOperand { .. } => Code::L012Syntax,
            IlFinding::NotReadBack => Code::L017NotDrawable,
        }
    }
}
