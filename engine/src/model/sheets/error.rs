//! Why a table refused a text or a row operation, with what a message needs to explain it.

use super::Sheet;
use crate::address::{Address, AddressError, AreaSet};
use crate::model::tables::BLOCK_SYMBOLS;
use std::fmt;
use thiserror::Error;

/// Where a key or a name is already used, for the message that says so.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub enum Taken {
    /// Row `row` (0-based) of the user symbol table named `table`.
    Symbols {
        /// The table's name.
        table: String,
        /// The row, 0-based.
        row: usize,
    },
    /// Row `row` (0-based) of a data table (D and D_FLOAT share the D addresses).
    Data {
        /// The data table.
        sheet: Sheet,
        /// The row, 0-based.
        row: usize,
    },
    /// Row `row` (0-based) of the table being edited (diagnosis, permissions).
    Row(usize),
    /// A subprogram's name in the block-symbol table, at its P number.
    Block(Address),
}

impl fmt::Display for Taken {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Taken::Symbols { table, row } => write!(f, "{table} #{}", row + 1),
            Taken::Data { sheet, row } => {
                write!(f, "{} #{}", sheet.data_name().unwrap_or("D"), row + 1)
            }
            Taken::Row(row) => write!(f, "#{}", row + 1),
            Taken::Block(p) => write!(f, "{BLOCK_SYMBOLS} {p}"),
        }
    }
}

/// Why a table refuses what was typed into a cell, a row operation or a password change.
/// `Display` gives it in English; `ladder_text::errors::table_error` in either language.
#[derive(Clone, Debug, PartialEq, Eq, Hash, Error)]
pub enum TableError {
    /// The key cell of an existing row was emptied.
    #[error("an address is required (use Delete row to remove the row)")]
    AddressEmpty,
    /// The text is no address of this controller.
    #[error(transparent)]
    Address(#[from] AddressError),
    /// A valid address of an area this table does not take.
    #[error("{address}: only these areas belong here: {}", allowed.describe())]
    AreaNotHere {
        /// The address typed.
        address: Address,
        /// The areas the table takes.
        allowed: AreaSet,
    },
    /// The address is already in another row (§3.4.3.2 "地址不允许相同").
    #[error("{address}: address already listed: {at}")]
    AddressTwice {
        /// The address typed.
        address: Address,
        /// The row that has it.
        at: Taken,
    },
    /// Not a symbol: wrong characters, too long, or something that reads as an address.
    #[error(
        "`{name}`: a symbol is letters, digits, `_` and Chinese characters, does not start with a digit, has at most 32 characters and is not an address"
    )]
    SymbolName {
        /// The name typed.
        name: String,
    },
    /// The symbol is already defined (§3.4.3.2 "符号不允许相同").
    #[error("`{name}`: symbol already exists: {at}")]
    SymbolTwice {
        /// The name typed.
        name: String,
        /// Where it is defined.
        at: Taken,
    },
    /// A data row's symbol that the symbol tables give another address.
    #[error("`{name}`: this symbol already stands for {address}")]
    SymbolElsewhere {
        /// The name typed.
        name: String,
        /// The address it stands for.
        address: Address,
    },
    /// A comment longer than the CNC keeps (§3.4.3.2).
    #[error("a comment has at most {max} bytes, not {bytes}")]
    CommentTooLong {
        /// Its length in bytes (UTF-8: a Chinese character is 3).
        bytes: usize,
        /// The limit.
        max: usize,
    },
    /// Not an integer; empty when a value was required and left empty.
    #[error("`{text}`: enter a whole number from -2147483647 to 2147483647")]
    NotInteger {
        /// The text typed.
        text: String,
    },
    /// Not a finite number; empty when a value was required and left empty.
    #[error("`{text}`: enter a number")]
    NotReal {
        /// The text typed.
        text: String,
    },
    /// An alarm number outside 1000–9999 (§3.4.5).
    #[error("`{text}`: alarm numbers are {}–{}", super::ALARM_NUMBERS.start(), super::ALARM_NUMBERS.end())]
    AlarmRange {
        /// The text typed.
        text: String,
    },
    /// The alarm number is already another A bit's.
    #[error("{number}: alarm number already used by {by}")]
    AlarmTwice {
        /// The number typed.
        number: u16,
        /// The A bit that has it.
        by: Address,
    },
    /// Not an M code of the table's range.
    #[error("`{text}`: M codes are {}–{}", super::M_CODES.start(), super::M_CODES.end())]
    MCodeRange {
        /// The text typed.
        text: String,
    },
    /// The M code is already in another row.
    #[error("M{code:02}: this M code is already listed (#{})", row + 1)]
    MCodeTwice {
        /// The code typed.
        code: u32,
        /// The row that has it, 0-based.
        row: usize,
    },
    /// Inserting a row needs a free key and the table's area has none left.
    #[error("no free address left to insert")]
    NoFreeKey {
        /// The table.
        sheet: Sheet,
    },
    /// Changing or removing the password takes the current one (§3.4.7).
    #[error("the current password is wrong")]
    PasswordWrong,
    /// A new password is empty.
    #[error("the password is empty")]
    PasswordEmpty,
    /// The new password and its confirmation differ.
    #[error("the two passwords differ")]
    PasswordMismatch,
}
