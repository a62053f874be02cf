//! What the tables (`compiler/tables.rs`): symbols, data, messages, diagnosis, permission and M-code tables, version and comments find, as data.

use crate::address::{Address, AddressError};
use crate::compiler::Code;
use crate::model::sheets::{Sheet, TableError};

/// A finding of the tables (`compiler/tables.rs`): symbols, data, messages, diagnosis, permission and M-code tables, version and comments.
///
/// Rows and tables are counted from 0, as the project holds them; a message counts from 1.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub enum TableFinding {
    /// A comment longer than the CNC keeps (W007).
    CommentTooLong {
        /// The comment's language code (`zh`, `en`, …).
        lang: String,
        /// The table's refusal, with the length and the limit.
        error: TableError,
    },
    /// A data row's symbol that is no valid name (T001).
    DataSymbolName {
        /// The table's refusal, with the name.
        error: TableError,
    },
    /// A data row's symbol that the symbol tables give another address (T002).
    DataSymbolElsewhere {
        /// The data row's address.
        address: Address,
        /// The table's refusal, with the name and the address it stands for.
        error: TableError,
    },
    /// A diagnosis or permission row's address of an area these tables do not list (T008).
    KeyArea {
        /// The table's refusal, with the address and the areas allowed.
        error: TableError,
    },
    /// A diagnosis or permission row's address beyond this controller's range (T008).
    KeyRange {
        /// The range error.
        error: AddressError,
    },
    /// A diagnosis or permission row's address that an earlier row of the table lists (T008).
    KeyTwice {
        /// The address.
        address: Address,
        /// The earlier row.
        row: usize,
    },
    /// A symbol table's name that is empty, taken by another table, or the block-symbol
    /// table's (T006).
    SymbolTableName {
        /// The name.
        name: String,
    },
    /// A symbol row's address of an area that takes no symbols (T007).
    SymbolArea {
        /// The table's refusal, with the address and the areas allowed.
        error: TableError,
    },
    /// A symbol or data row's address beyond this controller's range (T003).
    AddressRange {
        /// The range error.
        error: AddressError,
    },
    /// A symbol row's address that an earlier row of any symbol table lists (W004).
    SymbolAddressTwice {
        /// The address.
        address: Address,
        /// The earlier row's table.
        table: usize,
        /// The earlier row.
        row: usize,
    },
    /// A symbol row's name that is no valid symbol (T001).
    SymbolName {
        /// The name.
        name: String,
    },
    /// A symbol row's name that an earlier row of any symbol table defines (T002).
    SymbolTwice {
        /// The name.
        name: String,
        /// The earlier row's table.
        table: usize,
        /// The earlier row.
        row: usize,
    },
    /// A data row's address that an earlier row of a data table lists; D and D_FLOAT share
    /// the D addresses (T003).
    DataAddressTwice {
        /// The address.
        address: Address,
        /// The data table of the earlier row.
        sheet: Sheet,
        /// The earlier row.
        row: usize,
    },
    /// A D, DT or DC row's address of another area, or with a bit (T003).
    DataAddressArea {
        /// The address.
        address: Address,
        /// The data table holding it.
        sheet: Sheet,
    },
    /// A D, DT or DC row's value outside its limits, or limits the wrong way round (T004).
    DataValue {
        /// The row's address.
        address: Address,
        /// The value.
        value: i64,
        /// The lower limit (the table's own when the row sets none).
        min: i64,
        /// The upper limit (the table's own when the row sets none).
        max: i64,
    },
    /// A DC row's negative value: a counter counts from 0 (T004).
    CounterPreset {
        /// The row's address.
        address: Address,
        /// The value.
        value: i64,
    },
    /// A D_FLOAT row's address that is no D address of this controller (T003).
    RealAddress {
        /// The address.
        address: Address,
    },
    /// A D_FLOAT row's value that is no number or lies outside its limits (T004).
    RealValue {
        /// The row's address.
        address: Address,
        /// The value's bits (`f32::to_bits`), since a float is neither `Eq` nor `Hash`.
        value: u32,
    },
    /// An alarm number outside 1000–9999 (T005).
    AlarmRange {
        /// The A bit of the message row.
        bit: Address,
        /// The alarm number.
        number: u16,
    },
    /// An alarm number that an earlier A bit already has (T005).
    AlarmTwice {
        /// The A bit of the message row.
        bit: Address,
        /// The alarm number.
        number: u16,
        /// The earlier A bit.
        by: Address,
    },
    /// An alarm number without a message text (W005).
    AlarmWithoutText {
        /// The A bit of the message row.
        bit: Address,
        /// The alarm number.
        number: u16,
    },
    /// A message text without an alarm number (W005).
    TextWithoutAlarm {
        /// The A bit of the message row.
        bit: Address,
    },
    /// A message row past this controller's A range that is not empty (T005).
    MessageBeyondRange {
        /// The A bit of the message row.
        bit: Address,
        /// The last A bit of this controller.
        last: Address,
    },
    /// An M code outside the table's range (T008).
    MCodeRange {
        /// The table's refusal, with the code.
        error: TableError,
    },
    /// An M code that an earlier row lists (T008).
    MCodeTwice {
        /// The M code.
        code: u32,
        /// The earlier row.
        row: usize,
    },
    /// The version information's project name, longer than it may be (W006).
    VersionNameLength {
        /// The most characters it may have.
        max: usize,
    },
    /// The version information's designer, longer than it may be (W006).
    VersionDesignerLength {
        /// The most characters it may have.
        max: usize,
    },
    /// The version information's version, longer than it may be (W006).
    VersionVersionLength {
        /// The most characters it may have.
        max: usize,
    },
    /// The version information's remarks, longer than they may be (W006).
    VersionRemarksLength {
        /// The most characters they may have.
        max: usize,
    },
}

impl TableFinding {
    /// The diagnostic code of the finding.
    pub fn code(&self) -> Code {
        use TableFinding as F;
        match self {
            F::DataSymbolName { .. } | F::SymbolName { .. } => Code::T001SymbolName,
            F::DataSymbolElsewhere { .. } | F::SymbolTwice { .. } => Code::T002SymbolTwice,
            F::AddressRange { .. }
            | F::DataAddressTwice { .. }
            | F::DataAddressArea { .. }
            | F::RealAddress { .. } => Code::T003DataAddress,
            F::DataValue { .. } | F::CounterPreset { .. } | F::RealValue { .. } => {
                Code::T004DataValue
            }
            F::AlarmRange { .. } | F::AlarmTwice { .. } | F::MessageBeyondRange { .. } => {
                Code::T005MessageNumber
            }
            F::SymbolTableName { .. } => Code::T006TableName,
            F::SymbolArea { .. } => Code::T007SymbolArea,
            F::KeyArea { .. }
            | F::KeyRange { .. }
            | F::KeyTwice { .. }
            | F::MCodeRange { .. }
            | F::MCodeTwice { .. } => Code::T008TableKey,
            F::SymbolAddressTwice { .. } => Code::W004AddressTwice,
            F::AlarmWithoutText { .. } | F::TextWithoutAlarm { .. } => Code::W005MessageHalf,
            F::VersionNameLength { .. }
            | F::VersionDesignerLength { .. }
            | F::VersionVersionLength { .. }
            | F::VersionRemarksLength { .. } => Code::W006VersionLength,
            F::CommentTooLong { .. } => Code::W007CommentLength,
        }
    }
}
