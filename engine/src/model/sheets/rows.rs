//! The row menu (§3.4.3.2 行的编辑), the K page's bits, and which row a table edit changes.

use super::rules::{M_CODES, data_addresses};
use super::{RowOp, Sheet, TableError, address_edit, address_rows, changed, int_rows_mut};
use crate::address::{Address, Area};
use crate::model::tables::{AddressRow, Comments, DataRow, MCodeRow, Message, RealRow, Symbol};
use crate::model::{Project, TableEdit};
use crate::profile::Profile;

/// The first free address from `seed` on (wrapping round the area's range), bit by bit for
/// a bit address, word by word otherwise; `None` when every one is used.
pub fn next_free_address(
    seed: Address,
    profile: &Profile,
    used: impl Fn(Address) -> bool,
) -> Option<Address> {
    let (lo, hi) = profile.range(seed.area);
    let per = if seed.bit.is_some() { 8 } else { 1 };
    let total = (usize::from(hi) - usize::from(lo) + 1) * per;
    let start =
        usize::from(seed.number.clamp(lo, hi) - lo) * per + usize::from(seed.bit.unwrap_or(0));
    (0..total)
        .map(|k| (start + k) % total)
        .map(|i| {
            let number = lo + (i / per) as u16;
            if per == 8 {
                Address::bit(seed.area, number, (i % 8) as u8)
            } else {
                Address::byte(seed.area, number)
            }
        })
        .find(|a| !used(*a))
}

/// The key a new row starts its search for a free one from: the selected row's, else the
/// last row's; `None` for an empty table.
pub fn seed<T, K>(rows: &[T], row: usize, key: impl Fn(&T) -> K) -> Option<K> {
    rows.get(row).or(rows.last()).map(key)
}

/// Applies a row operation to a list; returns the row to select after it. A new row needs
/// a free key, which `fresh` finds (`None`: the area is full).
fn apply_op<T>(
    rows: &mut Vec<T>,
    sheet: Sheet,
    op: RowOp,
    row: usize,
    clear: impl FnOnce(&mut T),
    fresh: impl FnOnce() -> Option<T>,
) -> Result<usize, TableError> {
    match op {
        RowOp::Clear => {
            if let Some(r) = rows.get_mut(row) {
                clear(r);
            }
            Ok(row)
        }
        RowOp::Delete => {
            if row < rows.len() {
                rows.remove(row);
            }
            Ok(row.min(rows.len().saturating_sub(1)))
        }
        RowOp::InsertAbove | RowOp::InsertBelow => {
            let at = (row + usize::from(op == RowOp::InsertBelow)).min(rows.len());
            rows.insert(at, fresh().ok_or(TableError::NoFreeKey { sheet })?);
            Ok(at)
        }
    }
}

/// Applies a row-menu action to row `row` (past the last: the empty last line): the edit
/// (none when nothing changes) and the row to select after it. A new row gets the first
/// free key from the selected row's on; the message table's rows, one per A bit, can only be
/// cleared.
pub fn row_op(
    project: &Project,
    sheet: Sheet,
    op: RowOp,
    row: usize,
) -> Result<(Option<TableEdit>, usize), TableError> {
    match sheet {
        Sheet::Symbols(t) => symbol_row_op(project, t, op, row),
        Sheet::D | Sheet::Dt | Sheet::Dc | Sheet::DFloat => data_row_op(project, sheet, op, row),
        Sheet::Messages => {
            // The rows are the A bits: they can be emptied, not added or removed.
            let mut messages = project.messages.clone();
            if op == RowOp::Clear
                && let Some(m) = messages.rows.get_mut(row)
            {
                *m = Message::default();
            }
            Ok((
                changed(&project.messages, messages, |m| {
                    TableEdit::Messages(Box::new(m))
                }),
                row,
            ))
        }
        Sheet::Diagnosis | Sheet::Permissions => address_row_op(project, sheet, op, row),
        Sheet::MCodes => m_code_row_op(project, op, row),
    }
}

/// [`row_op`] on symbol table `t`: a cleared row keeps its address, a new one takes the first
/// address no table of the project uses (from the first R for an empty table).
fn symbol_row_op(
    project: &Project,
    t: usize,
    op: RowOp,
    row: usize,
) -> Result<(Option<TableEdit>, usize), TableError> {
    let profile = project.profile();
    let mut tables = project.symbol_tables.clone();
    let Some(table) = tables.get_mut(t) else {
        return Ok((None, row));
    };
    let start = seed(&table.rows, row, |s| s.address).unwrap_or(Address::bit(
        Area::R,
        profile.range(Area::R).0,
        0,
    ));
    let select = apply_op(
        &mut table.rows,
        Sheet::Symbols(t),
        op,
        row,
        |s| {
            s.name.clear();
            s.comments.clear();
        },
        || {
            next_free_address(start, profile, |a| {
                project.symbols().any(|s| s.address == a)
            })
            .map(|address| Symbol {
                name: String::new(),
                address,
                comments: Comments::new(),
            })
        },
    )?;
    Ok((
        changed(&project.symbol_tables, tables, TableEdit::Symbols),
        select,
    ))
}

/// [`row_op`] on a data sheet (D, DT, DC, D as reals): a cleared row keeps its address with a
/// value of 0; a new one takes the first address of its area that no sheet of the same space
/// lists, since D and D as reals share the D addresses.
fn data_row_op(
    project: &Project,
    sheet: Sheet,
    op: RowOp,
    row: usize,
) -> Result<(Option<TableEdit>, usize), TableError> {
    let profile = project.profile();
    let area = sheet.data_area();
    let used: Vec<Address> = data_addresses(project, sheet)
        .into_iter()
        .map(|(_, _, a)| a)
        .collect();
    let free = |start: Option<Address>| {
        next_free_address(
            start.unwrap_or(Address::byte(area, profile.range(area).0)),
            profile,
            |a| used.contains(&a),
        )
    };
    let mut data = project.data.clone();
    let select = if sheet == Sheet::DFloat {
        let rows = &mut data.d_float;
        let start = seed(rows, row, |r| r.address);
        apply_op(
            rows,
            sheet,
            op,
            row,
            |r| *r = RealRow::new(r.address, 0.0),
            || free(start).map(|a| RealRow::new(a, 0.0)),
        )?
    } else {
        let rows = int_rows_mut(&mut data, sheet);
        let start = seed(rows, row, |r| r.address);
        apply_op(
            rows,
            sheet,
            op,
            row,
            |r| *r = DataRow::new(r.address, 0),
            || free(start).map(|a| DataRow::new(a, 0)),
        )?
    };
    Ok((
        changed(&project.data, data, |d| TableEdit::Data(Box::new(d))),
        select,
    ))
}

/// [`row_op`] on the diagnosis or permissions sheet, rows of an address and its comments: a
/// new row takes the first K address the sheet does not list yet.
fn address_row_op(
    project: &Project,
    sheet: Sheet,
    op: RowOp,
    row: usize,
) -> Result<(Option<TableEdit>, usize), TableError> {
    let profile = project.profile();
    let mut rows = address_rows(project, sheet).clone();
    // Diagnosis shows bits as lamps and words as values; permissions are about the
    // settings a user may change, K bytes first (§3.4).
    let default = if sheet == Sheet::Diagnosis {
        Address::bit(Area::K, profile.range(Area::K).0, 0)
    } else {
        Address::byte(Area::K, profile.range(Area::K).0)
    };
    let start = seed(&rows, row, |r| r.address).unwrap_or(default);
    let existing = address_rows(project, sheet);
    let select = apply_op(
        &mut rows,
        sheet,
        op,
        row,
        |r| r.comments.clear(),
        || {
            next_free_address(start, profile, |a| existing.iter().any(|r| r.address == a)).map(
                |address| AddressRow {
                    address,
                    comments: Comments::new(),
                },
            )
        },
    )?;
    Ok((changed(existing, rows, address_edit(sheet)), select))
}

/// [`row_op`] on the M-code sheet: a new row takes the first M code from the selected one on,
/// wrapping round the range, that has no row yet.
fn m_code_row_op(
    project: &Project,
    op: RowOp,
    row: usize,
) -> Result<(Option<TableEdit>, usize), TableError> {
    let mut rows = project.m_codes.clone();
    let start = seed(&rows, row, |r| r.code).unwrap_or(0);
    let span = M_CODES.end() - M_CODES.start() + 1;
    let select = apply_op(
        &mut rows,
        Sheet::MCodes,
        op,
        row,
        |r| r.comments.clear(),
        || {
            (0..span)
                .map(|k| M_CODES.start() + (start - M_CODES.start() + k) % span)
                .find(|c| !project.m_codes.iter().any(|r| r.code == *c))
                .map(|code| MCodeRow {
                    code,
                    comments: Comments::new(),
                })
        },
    )?;
    Ok((changed(&project.m_codes, rows, TableEdit::MCodes), select))
}

/// Sets bit `bit` of K byte `number` on the K page (§3.4.4.1): the edit, none when the bit
/// already is so.
pub fn k_bit(project: &Project, number: usize, bit: u8, on: bool) -> Option<TableEdit> {
    let mut data = project.data.clone();
    data.set_k_bit(number, bit, on);
    changed(&project.data, data, |d| TableEdit::Data(Box::new(d)))
}

/// The first index where two lists differ, if they do.
fn first_difference<T: PartialEq>(a: &[T], b: &[T]) -> Option<usize> {
    (0..a.len().max(b.len())).find(|&i| a.get(i) != b.get(i))
}

/// The row of `project` that a table edit changes, or changed: `edit` holds the table on
/// one side of the change and `project` the other, as before an edit is applied or after
/// its inverse was. The first row that differs, moved onto the last row when rows were
/// removed from the end; `None` when the tables are equal, or for the K page, the version
/// information and the operator panel, which are no sheets of rows.
pub fn changed_row(project: &Project, edit: &TableEdit) -> Option<(Sheet, usize)> {
    let at = |sheet: Sheet, i: usize| (sheet, i.min(sheet.rows(project).saturating_sub(1)));
    match edit {
        TableEdit::Symbols(tables) => {
            let t = first_difference(&project.symbol_tables, tables)?;
            let t = t.min(project.symbol_tables.len().checked_sub(1)?);
            let mine = &project.symbol_tables[t].rows;
            let other = tables.get(t).map_or(&[][..], |t| &t.rows);
            Some(at(
                Sheet::Symbols(t),
                first_difference(mine, other).unwrap_or(0),
            ))
        }
        TableEdit::Data(data) => {
            let d = &project.data;
            [
                (Sheet::D, first_difference(&d.d, &data.d)),
                (Sheet::DFloat, first_difference(&d.d_float, &data.d_float)),
                (Sheet::Dt, first_difference(&d.dt, &data.dt)),
                (Sheet::Dc, first_difference(&d.dc, &data.dc)),
            ]
            .into_iter()
            .find_map(|(sheet, i)| i.map(|i| at(sheet, i)))
        }
        TableEdit::Messages(m) => {
            first_difference(&project.messages.rows, &m.rows).map(|i| at(Sheet::Messages, i))
        }
        TableEdit::Diagnosis(rows) => {
            first_difference(&project.diagnosis, rows).map(|i| at(Sheet::Diagnosis, i))
        }
        TableEdit::Permissions(rows) => {
            first_difference(&project.permissions, rows).map(|i| at(Sheet::Permissions, i))
        }
        TableEdit::MCodes(rows) => {
            first_difference(&project.m_codes, rows).map(|i| at(Sheet::MCodes, i))
        }
        // The version information has no rows; the panel, the machine model and the
        // scenarios are no sheets.
        TableEdit::Version(_)
        | TableEdit::Panel(_)
        | TableEdit::Machine(_)
        | TableEdit::Scenarios(_) => None,
    }
}
