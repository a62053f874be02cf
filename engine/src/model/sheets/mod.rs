//! The editing rules of the project's row tables (manual §3.4.3–§3.4.6), shared by the table
//! editor and by `check`: each table as a sheet of columns, what a cell shows, which texts a
//! cell takes ([`commit`]), the row menu ([`row_op`]) and the ladder password (§3.4.7).
//!
//! Every change is a [`TableEdit`] that replaces the whole table, built from a clone of the
//! project's, so the caller records it once and an undo puts the table back exactly. A refused
//! text is a [`TableError`] and changes nothing: the project never holds a cell the editor
//! refused.

mod commit;
mod error;
mod properties;
mod rows;
mod rules;
#[cfg(test)]
mod tests;

pub use commit::{cell_text, commit, set_password};
pub use error::{TableError, Taken};
pub use properties::{Properties, plan_properties, properties_of};
pub use rows::{changed_row, k_bit, next_free_address, row_op, seed};
pub use rules::{
    ALARM_NUMBERS, COMMENT_MAX_BYTES, M_CODES, SYMBOL_AREAS, VALUE_AREAS, alarm_number,
    check_alarm_number, check_comment, check_data_symbol, check_m_code, check_symbol,
    check_symbol_area, check_symbol_form, check_value_area, data_address, data_addresses, m_code,
    parse_address, parse_int, parse_real, plain_address, set_comment, symbol_address,
};

use super::tables::{AddressRow, DataRow, DataTables, message_rows};
use super::{Project, TableEdit};
use crate::address::Area;
use crate::model::tables::LANGUAGES;

// The per-language columns follow the comments CSV's language columns (zh, then en), so a
// table reads like its export.
const ZH: &str = LANGUAGES[0];
const EN: &str = LANGUAGES[1];

/// A row table of the project.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Sheet {
    /// A user symbol table (index in the project).
    Symbols(usize),
    /// The D data table.
    D,
    /// The D_FLOAT data table.
    DFloat,
    /// The DT data table.
    Dt,
    /// The DC data table.
    Dc,
    /// The display-message table.
    Messages,
    /// The diagnosis table.
    Diagnosis,
    /// The permission table.
    Permissions,
    /// The M-code comment table.
    MCodes,
}

/// A column of a row table.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Col {
    /// The row's address.
    Address,
    /// Its symbol.
    Symbol,
    /// Its comment in one language: the key of the row's comment map (`zh`, `en`).
    Comment(&'static str),
    /// A data row's initial value.
    Value,
    /// A data row's minimum.
    Min,
    /// A data row's maximum.
    Max,
    /// A message's alarm number.
    Number,
    /// A message's text in one language: the key of its text map (`zh`, `en`).
    Text(&'static str),
    /// An M code.
    Code,
}

/// What the row menu does (§3.4.3.2 行的编辑).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum RowOp {
    /// Empties the row but keeps it (and its key: a row cannot exist without one).
    Clear,
    /// A new row above, at a free address.
    InsertAbove,
    /// A new row below, at a free address.
    InsertBelow,
    /// Removes the row.
    Delete,
}

impl RowOp {
    /// Every operation, in the order the row menu lists them.
    pub const ALL: [RowOp; 4] = [
        RowOp::Clear,
        RowOp::InsertAbove,
        RowOp::InsertBelow,
        RowOp::Delete,
    ];
}

impl Col {
    /// The language a per-language column (a comment, a message text) shows and writes;
    /// `None` for the columns that are the same in every language.
    pub fn lang(self) -> Option<&'static str> {
        match self {
            Col::Comment(lang) | Col::Text(lang) => Some(lang),
            _ => None,
        }
    }
}

impl Sheet {
    /// The columns, left to right: a comment (a message's text) once per language, in the
    /// order of the comments CSV, so that every language can be read and edited side by side.
    pub fn columns(self) -> &'static [Col] {
        match self {
            Sheet::Symbols(_) => &[
                Col::Address,
                Col::Symbol,
                Col::Comment(ZH),
                Col::Comment(EN),
            ],
            Sheet::D | Sheet::DFloat | Sheet::Dt | Sheet::Dc => &[
                Col::Address,
                Col::Value,
                Col::Min,
                Col::Max,
                Col::Symbol,
                Col::Comment(ZH),
                Col::Comment(EN),
            ],
            Sheet::Messages => &[Col::Address, Col::Number, Col::Text(ZH), Col::Text(EN)],
            Sheet::Diagnosis | Sheet::Permissions => {
                &[Col::Address, Col::Comment(ZH), Col::Comment(EN)]
            }
            Sheet::MCodes => &[Col::Code, Col::Comment(ZH), Col::Comment(EN)],
        }
    }

    /// The message table has one row per A bit: rows are neither inserted nor deleted.
    pub fn fixed(self) -> bool {
        self == Sheet::Messages
    }

    /// The column without which a row cannot exist: typing it in the empty last line adds a
    /// row.
    pub fn key_col(self) -> Col {
        if self == Sheet::MCodes {
            Col::Code
        } else {
            Col::Address
        }
    }

    /// Whether a column can be typed in (a message row's A bit is the row itself).
    pub fn editable(self, col: Col) -> bool {
        !(self.fixed() && col == Col::Address)
    }

    /// The data area a data table's addresses must be of.
    pub fn data_area(self) -> Area {
        match self {
            Sheet::Dt => Area::Dt,
            Sheet::Dc => Area::Dc,
            _ => Area::D,
        }
    }

    /// A data table's name, the same in every language (`D`, `D_FLOAT`, `DT`, `DC`).
    pub fn data_name(self) -> Option<&'static str> {
        Some(match self {
            Sheet::D => "D",
            Sheet::DFloat => "D_FLOAT",
            Sheet::Dt => "DT",
            Sheet::Dc => "DC",
            _ => return None,
        })
    }

    /// Rows of the table in `project` (the message table: one per A bit of the profile).
    pub fn rows(self, project: &Project) -> usize {
        match self {
            Sheet::Symbols(t) => project.symbol_tables.get(t).map_or(0, |t| t.rows.len()),
            Sheet::D | Sheet::Dt | Sheet::Dc => int_rows(&project.data, self).len(),
            Sheet::DFloat => project.data.d_float.len(),
            Sheet::Messages => project
                .messages
                .rows
                .len()
                .min(message_rows(project.profile())),
            Sheet::Diagnosis | Sheet::Permissions => address_rows(project, self).len(),
            Sheet::MCodes => project.m_codes.len(),
        }
    }
}

/// The integer rows of the D, DT or DC table.
fn int_rows(data: &DataTables, sheet: Sheet) -> &Vec<DataRow> {
    match sheet {
        Sheet::Dt => &data.dt,
        Sheet::Dc => &data.dc,
        _ => &data.d,
    }
}

fn int_rows_mut(data: &mut DataTables, sheet: Sheet) -> &mut Vec<DataRow> {
    match sheet {
        Sheet::Dt => &mut data.dt,
        Sheet::Dc => &mut data.dc,
        _ => &mut data.d,
    }
}

/// The rows of the diagnosis or the permission table.
fn address_rows(project: &Project, sheet: Sheet) -> &Vec<AddressRow> {
    if sheet == Sheet::Permissions {
        &project.permissions
    } else {
        &project.diagnosis
    }
}

/// How a new diagnosis or permission table is wrapped into an edit.
fn address_edit(sheet: Sheet) -> fn(Vec<AddressRow>) -> TableEdit {
    if sheet == Sheet::Permissions {
        TableEdit::Permissions
    } else {
        TableEdit::Diagnosis
    }
}

/// The edit that replaces `old` by `new`, or none when they are equal (a field left as it
/// was must not become an undo step).
fn changed<T: PartialEq>(old: &T, new: T, wrap: impl FnOnce(T) -> TableEdit) -> Option<TableEdit> {
    (*old != new).then(|| wrap(new))
}
