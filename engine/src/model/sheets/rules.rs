//! What each cell of the tables takes. The `check_*` functions judge a value already in a
//! table (`check` runs them on a file); the others read a typed text and judge it against the
//! project, `this` naming the row being edited so that it does not collide with itself.

use super::{Sheet, TableError, Taken, address_rows, int_rows};
use crate::address::{Address, AddressError, Area, AreaSet};
use crate::model::tables::{Comments, MessageTable};
use crate::model::{Operand, Project, is_symbol_name};
use std::ops::RangeInclusive;

/// Longest comment in bytes (§3.4.3.2 "注释有长度限制（127 字节）"); the other tables' comments
/// go to the same CNC comment store, so the same limit applies to them.
pub const COMMENT_MAX_BYTES: usize = 127;

/// Alarm numbers of the message table (§3.4.5 "报警号的范围从 1000 到 9999").
pub const ALARM_NUMBERS: RangeInclusive<u16> = 1000..=9999;

/// M codes of the comment table. Neither the manual nor the file loader limits them; 0–9999
/// is what the CNC's four-digit M word can carry, so nothing the CNC can call is refused.
pub const M_CODES: RangeInclusive<u32> = 0..=9999;

/// Areas a user symbol may stand for (§3.4.3.2 "允许输入的类型为：A、X、Y、R、K、F、C、T、D、
/// DT、DC"); P numbers get their names from the block-symbol table, L labels have none. G is
/// taken too, though the manual's list leaves it out: the PLC's signals to the CNC are named
/// like its F inputs, and the bundled sample (projects/src/lathe-988ta.symbols.csv) names
/// its G signals, which `check` must not refuse.
pub const SYMBOL_AREAS: AreaSet = AreaSet::of(&[
    Area::A,
    Area::X,
    Area::Y,
    Area::R,
    Area::K,
    Area::F,
    Area::G,
    Area::C,
    Area::T,
    Area::D,
    Area::Dt,
    Area::Dc,
]);

/// Areas the diagnosis and permission tables take: every memory area, not labels or
/// subprogram numbers, which hold no value to show or to change.
pub const VALUE_AREAS: AreaSet = AreaSet::MEMORY;

fn area_in(address: Address, allowed: AreaSet) -> Result<(), TableError> {
    if allowed.contains(address.area) {
        Ok(())
    } else {
        Err(TableError::AreaNotHere { address, allowed })
    }
}

/// Whether a symbol table may give this address a symbol ([`SYMBOL_AREAS`]).
pub fn check_symbol_area(address: Address) -> Result<(), TableError> {
    area_in(address, SYMBOL_AREAS)
}

/// Whether the diagnosis and permission tables take this address ([`VALUE_AREAS`]).
pub fn check_value_area(address: Address) -> Result<(), TableError> {
    area_in(address, VALUE_AREAS)
}

/// Parses an address against the profile and the areas a table takes.
pub fn parse_address(project: &Project, text: &str, areas: AreaSet) -> Result<Address, TableError> {
    if text.is_empty() {
        return Err(TableError::AddressEmpty);
    }
    let a = Address::parse_in(text, project.profile())?;
    area_in(a, areas)?;
    Ok(a)
}

/// A symbol table's address: valid, of a symbol area, and in no other row of any symbol
/// table (§3.4.3.2 "地址不允许相同"). `this` is the (table, row) being edited.
pub fn symbol_address(
    project: &Project,
    text: &str,
    this: Option<(usize, usize)>,
) -> Result<Address, TableError> {
    let a = parse_address(project, text, SYMBOL_AREAS)?;
    for (t, table) in project.symbol_tables.iter().enumerate() {
        if let Some(r) = table
            .rows
            .iter()
            .enumerate()
            .position(|(r, s)| s.address == a && this != Some((t, r)))
        {
            return Err(TableError::AddressTwice {
                address: a,
                at: Taken::Symbols {
                    table: table.name.clone(),
                    row: r,
                },
            });
        }
    }
    Ok(a)
}

/// Whether a name may be a symbol: the manual's characters, and not something the operand
/// parser would read as an address (`X1` would never reach the symbol).
pub fn check_symbol_form(name: &str) -> Result<(), TableError> {
    let looks_like_address = matches!(Operand::parse(name), Ok(Operand::Addr(_)));
    if !is_symbol_name(name) || looks_like_address {
        return Err(TableError::SymbolName { name: name.into() });
    }
    Ok(())
}

/// A symbol table's symbol: empty (an address with only a comment), or a valid name used by
/// no other row of any symbol table nor by a subprogram (§3.4.3.2 "符号不允许相同").
pub fn check_symbol(
    project: &Project,
    name: &str,
    this: Option<(usize, usize)>,
) -> Result<(), TableError> {
    if name.is_empty() {
        return Ok(());
    }
    check_symbol_form(name)?;
    let taken = |at: Taken| {
        Err(TableError::SymbolTwice {
            name: name.into(),
            at,
        })
    };
    for (t, table) in project.symbol_tables.iter().enumerate() {
        if let Some(r) = table
            .rows
            .iter()
            .enumerate()
            .position(|(r, s)| s.name == name && this != Some((t, r)))
        {
            return taken(Taken::Symbols {
                table: table.name.clone(),
                row: r,
            });
        }
    }
    let blocks = project.block_symbols();
    if let Some(s) = blocks.rows.iter().find(|s| s.name == name) {
        return taken(Taken::Block(s.address));
    }
    Ok(())
}

/// A data row's symbol: a valid name, and not one the symbol tables give another address.
pub fn check_data_symbol(
    project: &Project,
    name: &str,
    address: Address,
) -> Result<(), TableError> {
    if name.is_empty() {
        return Ok(());
    }
    check_symbol_form(name)?;
    match project.resolve_symbol(name) {
        Some(a) if a != address => Err(TableError::SymbolElsewhere {
            name: name.into(),
            address: a,
        }),
        _ => Ok(()),
    }
}

/// Every address listed in the same space as a data table's, with where it is: D and
/// D_FLOAT share the D addresses (one D holds an integer or a real, not both).
pub fn data_addresses(project: &Project, sheet: Sheet) -> Vec<(Sheet, usize, Address)> {
    let d = &project.data;
    let ints = |s: Sheet| {
        int_rows(d, s)
            .iter()
            .enumerate()
            .map(move |(i, r)| (s, i, r.address))
    };
    match sheet {
        Sheet::Dt | Sheet::Dc => ints(sheet).collect(),
        _ => ints(Sheet::D)
            .chain(
                d.d_float
                    .iter()
                    .enumerate()
                    .map(|(i, r)| (Sheet::DFloat, i, r.address)),
            )
            .collect(),
    }
}

/// A data table's address: of its area, a whole word, in range and listed once. `this` is the
/// row being edited.
pub fn data_address(
    project: &Project,
    sheet: Sheet,
    text: &str,
    this: Option<usize>,
) -> Result<Address, TableError> {
    let area = sheet.data_area();
    let a = parse_address(project, text, AreaSet::of(&[area]))?;
    if a.bit.is_some() {
        // The data areas have no bits, so the parser refuses these already; kept so that a
        // table of another area would not take bits either.
        return Err(AddressError::NoBits(text.into(), a.area).into());
    }
    if let Some((s, i, _)) = data_addresses(project, sheet)
        .into_iter()
        .find(|(s, i, x)| *x == a && !(*s == sheet && Some(*i) == this))
    {
        return Err(TableError::AddressTwice {
            address: a,
            at: Taken::Data { sheet: s, row: i },
        });
    }
    Ok(a)
}

/// A diagnosis or permission address: of a memory area, in range, listed once in its table.
pub fn plain_address(
    project: &Project,
    sheet: Sheet,
    text: &str,
    this: Option<usize>,
) -> Result<Address, TableError> {
    let a = parse_address(project, text, VALUE_AREAS)?;
    if let Some(i) = address_rows(project, sheet)
        .iter()
        .enumerate()
        .position(|(i, r)| r.address == a && Some(i) != this)
    {
        return Err(TableError::AddressTwice {
            address: a,
            at: Taken::Row(i),
        });
    }
    Ok(a)
}

/// Whether an M code is in the table's range ([`M_CODES`]).
pub fn check_m_code(code: u32) -> Result<(), TableError> {
    if M_CODES.contains(&code) {
        Ok(())
    } else {
        Err(TableError::MCodeRange {
            text: format!("M{code:02}"),
        })
    }
}

/// An M code (`M03`, `m3` or `3`), in range and listed once.
pub fn m_code(project: &Project, text: &str, this: Option<usize>) -> Result<u32, TableError> {
    let digits = text.trim_start_matches(['M', 'm']);
    let code = Some(digits)
        .filter(|d| !d.is_empty() && d.bytes().all(|b| b.is_ascii_digit()))
        .and_then(|d| d.parse::<u32>().ok())
        .filter(|c| M_CODES.contains(c))
        .ok_or_else(|| TableError::MCodeRange { text: text.into() })?;
    if let Some(row) = project
        .m_codes
        .iter()
        .enumerate()
        .position(|(i, r)| r.code == code && Some(i) != this)
    {
        return Err(TableError::MCodeTwice { code, row });
    }
    Ok(code)
}

/// Whether an alarm number is in the message table's range ([`ALARM_NUMBERS`]).
pub fn check_alarm_number(number: u16) -> Result<(), TableError> {
    if ALARM_NUMBERS.contains(&number) {
        Ok(())
    } else {
        Err(TableError::AlarmRange {
            text: number.to_string(),
        })
    }
}

/// An alarm number for message row `row`: empty for none, else 1000–9999 and used by no
/// other A bit.
pub fn alarm_number(project: &Project, text: &str, row: usize) -> Result<Option<u16>, TableError> {
    if text.is_empty() {
        return Ok(None);
    }
    let n = text
        .parse::<u16>()
        .ok()
        .filter(|n| ALARM_NUMBERS.contains(n))
        .ok_or_else(|| TableError::AlarmRange { text: text.into() })?;
    if let Some(k) = project
        .messages
        .rows
        .iter()
        .enumerate()
        .position(|(k, m)| m.number == Some(n) && k != row)
    {
        return Err(TableError::AlarmTwice {
            number: n,
            by: MessageTable::address(k),
        });
    }
    Ok(Some(n))
}

/// An integer cell: empty for none. Beyond ±2147483647 is not an error but clamped by the
/// row's setters, as the manual says (§3.4.4.2); only text that is no integer at all is
/// refused.
pub fn parse_int(text: &str) -> Result<Option<i64>, TableError> {
    if text.is_empty() {
        return Ok(None);
    }
    text.parse::<i128>()
        .map(|v| Some(v.clamp(i128::from(i64::MIN), i128::from(i64::MAX)) as i64))
        .map_err(|_| TableError::NotInteger { text: text.into() })
}

/// A real cell: empty for none, else a finite number.
pub fn parse_real(text: &str) -> Result<Option<f32>, TableError> {
    if text.is_empty() {
        return Ok(None);
    }
    text.parse::<f32>()
        .ok()
        .filter(|v| v.is_finite())
        .map(Some)
        .ok_or_else(|| TableError::NotReal { text: text.into() })
}

/// Whether a comment fits the CNC's comment store ([`COMMENT_MAX_BYTES`]).
pub fn check_comment(text: &str) -> Result<(), TableError> {
    if text.len() > COMMENT_MAX_BYTES {
        return Err(TableError::CommentTooLong {
            bytes: text.len(),
            max: COMMENT_MAX_BYTES,
        });
    }
    Ok(())
}

/// Sets language `lang`'s entry of a comment map, trimmed; empty removes it. `limited`: the
/// text is a comment of [`COMMENT_MAX_BYTES`] at most (a message text is not).
pub fn set_comment(
    comments: &mut Comments,
    lang: &str,
    text: &str,
    limited: bool,
) -> Result<(), TableError> {
    let text = text.trim();
    if limited {
        check_comment(text)?;
    }
    if text.is_empty() {
        comments.remove(lang);
    } else {
        comments.insert(lang.into(), text.into());
    }
    Ok(())
}
