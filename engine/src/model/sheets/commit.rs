//! A cell's text both ways: what a cell shows, and the edit that a typed text makes.

use super::rules::{
    alarm_number, check_data_symbol, check_symbol, data_address, m_code, parse_int, parse_real,
    plain_address, set_comment, symbol_address,
};
use super::{Col, Sheet, TableError, address_edit, address_rows, changed, int_rows, int_rows_mut};
use crate::model::tables::{
    AddressRow, Comments, DataRow, MCodeRow, MessageTable, PasswordHash, RealRow, Symbol,
    VersionInfo,
};
use crate::model::{Project, TableEdit};

/// What a cell shows when nobody is typing in it; a comment or message-text column shows its
/// own language. Empty past the last row, and in a column the table does not have.
pub fn cell_text(project: &Project, sheet: Sheet, row: usize, col: Col) -> String {
    let comment = |c: &Comments, lang: &str| c.get(lang).cloned().unwrap_or_default();
    let int = |v: Option<i64>| v.map(|v| v.to_string()).unwrap_or_default();
    let real = |v: Option<f32>| v.map(|v| v.to_string()).unwrap_or_default();
    match sheet {
        Sheet::Symbols(t) => {
            let Some(s) = project.symbol_tables.get(t).and_then(|t| t.rows.get(row)) else {
                return String::new();
            };
            match col {
                Col::Address => s.address.to_string(),
                Col::Symbol => s.name.clone(),
                Col::Comment(lang) => comment(&s.comments, lang),
                _ => String::new(),
            }
        }
        Sheet::D | Sheet::Dt | Sheet::Dc => {
            let Some(r) = int_rows(&project.data, sheet).get(row) else {
                return String::new();
            };
            match col {
                Col::Address => r.address.to_string(),
                Col::Value => r.value.to_string(),
                Col::Min => int(r.min),
                Col::Max => int(r.max),
                Col::Symbol => r.symbol.clone(),
                Col::Comment(lang) => comment(&r.comments, lang),
                _ => String::new(),
            }
        }
        Sheet::DFloat => {
            let Some(r) = project.data.d_float.get(row) else {
                return String::new();
            };
            match col {
                Col::Address => r.address.to_string(),
                Col::Value => r.value.to_string(),
                Col::Min => real(r.min),
                Col::Max => real(r.max),
                Col::Symbol => r.symbol.clone(),
                Col::Comment(lang) => comment(&r.comments, lang),
                _ => String::new(),
            }
        }
        Sheet::Messages => {
            let Some(m) = project.messages.rows.get(row) else {
                return String::new();
            };
            match col {
                Col::Address => MessageTable::address(row).to_string(),
                Col::Number => m.number.map(|n| n.to_string()).unwrap_or_default(),
                Col::Text(lang) => comment(&m.texts, lang),
                _ => String::new(),
            }
        }
        Sheet::Diagnosis | Sheet::Permissions => {
            let Some(r) = address_rows(project, sheet).get(row) else {
                return String::new();
            };
            match col {
                Col::Address => r.address.to_string(),
                Col::Comment(lang) => comment(&r.comments, lang),
                _ => String::new(),
            }
        }
        Sheet::MCodes => {
            let Some(r) = project.m_codes.get(row) else {
                return String::new();
            };
            match col {
                Col::Code => format!("M{:02}", r.code),
                Col::Comment(lang) => comment(&r.comments, lang),
                _ => String::new(),
            }
        }
    }
}

/// Applies text typed into a cell (a comment or message-text column writes its own language
/// only): the edit replacing its table, none when nothing changes, or why the text is
/// refused. A row past the last is the empty last line of a growing table, which takes only
/// the key that creates a row; a column the table does not have takes nothing.
pub fn commit(
    project: &Project,
    sheet: Sheet,
    row: usize,
    col: Col,
    raw: &str,
) -> Result<Option<TableEdit>, TableError> {
    let text = raw.trim();
    let fresh = row >= sheet.rows(project);
    // The empty last line only takes its key: a row cannot exist without its address or code.
    if fresh && (sheet.fixed() || col != sheet.key_col() || text.is_empty()) {
        return Ok(None);
    }
    match sheet {
        Sheet::Symbols(t) => {
            let mut tables = project.symbol_tables.clone();
            let Some(table) = tables.get_mut(t) else {
                return Ok(None);
            };
            if fresh {
                let address = symbol_address(project, text, None)?;
                table.rows.push(Symbol {
                    name: String::new(),
                    address,
                    comments: Comments::new(),
                });
            } else {
                let s = &mut table.rows[row];
                match col {
                    Col::Address => s.address = symbol_address(project, text, Some((t, row)))?,
                    Col::Symbol => {
                        check_symbol(project, text, Some((t, row)))?;
                        s.name = text.into();
                    }
                    Col::Comment(lang) => set_comment(&mut s.comments, lang, raw, true)?,
                    _ => {}
                }
            }
            Ok(changed(&project.symbol_tables, tables, TableEdit::Symbols))
        }
        Sheet::D | Sheet::Dt | Sheet::Dc => {
            let mut data = project.data.clone();
            let rows = int_rows_mut(&mut data, sheet);
            if fresh {
                rows.push(DataRow::new(data_address(project, sheet, text, None)?, 0));
            } else {
                let r = &mut rows[row];
                match col {
                    Col::Address => r.address = data_address(project, sheet, text, Some(row))?,
                    Col::Value => r.set_value(parse_int(text)?.ok_or(TableError::NotInteger {
                        text: String::new(),
                    })?),
                    Col::Min => r.set_min(parse_int(text)?),
                    Col::Max => r.set_max(parse_int(text)?),
                    Col::Symbol => {
                        check_data_symbol(project, text, r.address)?;
                        r.symbol = text.into();
                    }
                    Col::Comment(lang) => set_comment(&mut r.comments, lang, raw, true)?,
                    _ => {}
                }
            }
            Ok(changed(&project.data, data, |d| {
                TableEdit::Data(Box::new(d))
            }))
        }
        Sheet::DFloat => {
            let mut data = project.data.clone();
            let rows = &mut data.d_float;
            if fresh {
                rows.push(RealRow::new(data_address(project, sheet, text, None)?, 0.0));
            } else {
                let r = &mut rows[row];
                match col {
                    Col::Address => r.address = data_address(project, sheet, text, Some(row))?,
                    Col::Value => r.set_value(parse_real(text)?.ok_or(TableError::NotReal {
                        text: String::new(),
                    })?),
                    Col::Min => r.set_min(parse_real(text)?),
                    Col::Max => r.set_max(parse_real(text)?),
                    Col::Symbol => {
                        check_data_symbol(project, text, r.address)?;
                        r.symbol = text.into();
                    }
                    Col::Comment(lang) => set_comment(&mut r.comments, lang, raw, true)?,
                    _ => {}
                }
            }
            Ok(changed(&project.data, data, |d| {
                TableEdit::Data(Box::new(d))
            }))
        }
        Sheet::Messages => {
            let mut messages = project.messages.clone();
            let Some(m) = messages.rows.get_mut(row) else {
                return Ok(None);
            };
            match col {
                Col::Number => m.number = alarm_number(project, text, row)?,
                Col::Text(lang) => set_comment(&mut m.texts, lang, raw, false)?,
                _ => {}
            }
            Ok(changed(&project.messages, messages, |m| {
                TableEdit::Messages(Box::new(m))
            }))
        }
        Sheet::Diagnosis | Sheet::Permissions => {
            let mut rows = address_rows(project, sheet).clone();
            if fresh {
                rows.push(AddressRow {
                    address: plain_address(project, sheet, text, None)?,
                    comments: Comments::new(),
                });
            } else {
                let r = &mut rows[row];
                match col {
                    Col::Address => r.address = plain_address(project, sheet, text, Some(row))?,
                    Col::Comment(lang) => set_comment(&mut r.comments, lang, raw, true)?,
                    _ => {}
                }
            }
            Ok(changed(
                address_rows(project, sheet),
                rows,
                address_edit(sheet),
            ))
        }
        Sheet::MCodes => {
            let mut rows = project.m_codes.clone();
            if fresh {
                rows.push(MCodeRow {
                    code: m_code(project, text, None)?,
                    comments: Comments::new(),
                });
            } else {
                let r = &mut rows[row];
                match col {
                    Col::Code => r.code = m_code(project, text, Some(row))?,
                    Col::Comment(lang) => set_comment(&mut r.comments, lang, raw, true)?,
                    _ => {}
                }
            }
            Ok(changed(&project.m_codes, rows, TableEdit::MCodes))
        }
    }
}

/// Sets (`new` is `Some((password, confirmation))`) or removes (`None`) the ladder password
/// (§3.4.7): the version information with the new salted hash. Either takes the current
/// password when one is set, as on the CNC. The salt comes from the caller, which has a
/// source of randomness: two projects with the same password then get different hashes.
pub fn set_password(
    version: &VersionInfo,
    current: &str,
    new: Option<(&str, &str)>,
    salt: &str,
) -> Result<VersionInfo, TableError> {
    if version
        .password
        .as_ref()
        .is_some_and(|p| !p.matches(current))
    {
        return Err(TableError::PasswordWrong);
    }
    let mut next = version.clone();
    next.password = match new {
        None => None,
        Some(("", _)) => return Err(TableError::PasswordEmpty),
        Some((password, confirm)) if password != confirm => {
            return Err(TableError::PasswordMismatch);
        }
        Some((password, _)) => Some(PasswordHash::new(password, salt)),
    };
    Ok(next)
}
