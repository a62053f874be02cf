//! Checks of the project's tables (manual §3.4.3–§3.4.7), reported like compile diagnostics:
//! the "block" is the table (`SYMBOLS`, `DATA`, `MESSAGES`, `VERSION`), the "network" the
//! table's number, the row and column the cell.

use super::diag::{Code, Origin, Sink};
use crate::address::{Address, Area};
use crate::model::tables::{DESIGNER_MAX, MessageTable, REMARKS_MAX, VALUE_LIMIT, VERSION_MAX};
use crate::model::{Operand, Project, is_symbol_name};
use std::collections::HashMap;

fn at(row: usize, col: u32) -> Origin {
    Origin::Cell {
        row: row as u32,
        col,
    }
}

/// Checks every table of a project.
pub fn check_tables(project: &Project, sink: &mut Sink) {
    let profile = project.profile();
    // Symbol tables: names, uniqueness, addresses.
    let mut names: HashMap<&str, (usize, usize)> = HashMap::new();
    let mut addresses: HashMap<Address, (usize, usize)> = HashMap::new();
    let mut table_names: HashMap<&str, usize> = HashMap::new();
    for (t, table) in project.symbol_tables.iter().enumerate() {
        sink.at(usize::MAX - 3, "SYMBOLS", t);
        if table.name.is_empty()
            || table.name == crate::model::tables::BLOCK_SYMBOLS
            || table_names.insert(&table.name, t).is_some()
        {
            sink.report(
                at(0, 0),
                Code::T006TableName,
                format!(
                    "symbol table name `{}` is empty, taken, or the block-symbol table's: give it a unique name",
                    table.name
                ),
            );
        }
        for (r, s) in table.rows.iter().enumerate() {
            if let Err(e) = s.address.check_range(profile) {
                sink.report(at(r, 0), Code::T003DataAddress, e.to_string());
            }
            if let Some((pt, pr)) = addresses.insert(s.address, (t, r)) {
                sink.report(
                    at(r, 0),
                    Code::W004AddressTwice,
                    format!(
                        "{} is also in table {} row {}; keep one row per address",
                        s.address,
                        pt + 1,
                        pr + 1
                    ),
                );
            }
            if s.name.is_empty() {
                continue;
            }
            let looks_like_address = matches!(Operand::parse(&s.name), Ok(Operand::Addr(_)));
            if !is_symbol_name(&s.name) || looks_like_address {
                sink.report(
                    at(r, 1),
                    Code::T001SymbolName,
                    format!(
                        "`{}` is not a valid symbol: use letters, digits, `_` and Chinese, not starting with a digit, at most 32 characters, and not an address",
                        s.name
                    ),
                );
            } else if let Some((pt, pr)) = names.insert(&s.name, (t, r)) {
                sink.report(
                    at(r, 1),
                    Code::T002SymbolTwice,
                    format!(
                        "symbol `{}` already exists (table {} row {}); symbols are unique",
                        s.name,
                        pt + 1,
                        pr + 1
                    ),
                );
            }
        }
    }
    // Data tables: each row's area, and its value inside its limits.
    let data = &project.data;
    let tables = [
        ("D", Area::D, &data.d),
        ("DT", Area::Dt, &data.dt),
        ("DC", Area::Dc, &data.dc),
    ];
    for (t, (name, area, rows)) in tables.into_iter().enumerate() {
        sink.at(usize::MAX - 2, "DATA", t);
        for (r, row) in rows.iter().enumerate() {
            if row.address.area != area || row.address.bit.is_some() {
                sink.report(
                    at(r, 0),
                    Code::T003DataAddress,
                    format!(
                        "{} does not belong in the {name} table; use {name} addresses",
                        row.address
                    ),
                );
            } else if let Err(e) = row.address.check_range(profile) {
                sink.report(at(r, 0), Code::T003DataAddress, e.to_string());
            }
            let lo = row.min.unwrap_or(-VALUE_LIMIT);
            let hi = row.max.unwrap_or(VALUE_LIMIT);
            if row.value < lo || row.value > hi || lo > hi {
                sink.report(
                    at(r, 1),
                    Code::T004DataValue,
                    format!(
                        "{} = {} lies outside its limits {lo}…{hi}",
                        row.address, row.value
                    ),
                );
            }
            if area == Area::C && row.value < 0 {
                sink.report(
                    at(r, 1),
                    Code::T004DataValue,
                    "a counter value is 0…2147483647",
                );
            }
        }
    }
    sink.at(usize::MAX - 2, "DATA", 3);
    for (r, row) in data.d_float.iter().enumerate() {
        if row.address.area != Area::D
            || row.address.bit.is_some()
            || row.address.check_range(profile).is_err()
        {
            sink.report(
                at(r, 0),
                Code::T003DataAddress,
                format!("{} is not a D address of this controller", row.address),
            );
        }
        if !row.value.is_finite()
            || row.min.is_some_and(|m| row.value < m)
            || row.max.is_some_and(|m| row.value > m)
        {
            sink.report(
                at(r, 1),
                Code::T004DataValue,
                format!("{} = {} lies outside its limits", row.address, row.value),
            );
        }
    }
    // Messages: numbers 1000–9999, unique, number and text together.
    sink.at(usize::MAX - 1, "MESSAGES", 0);
    let mut numbers: HashMap<u16, usize> = HashMap::new();
    for (r, m) in project.messages.rows.iter().enumerate() {
        let has_text = m.texts.values().any(|t| !t.is_empty());
        match m.number {
            Some(n) if !(1000..=9999).contains(&n) => sink.report(
                at(r, 1),
                Code::T005MessageNumber,
                format!(
                    "{}: alarm number {n} is outside 1000–9999",
                    MessageTable::address(r)
                ),
            ),
            Some(n) => {
                if let Some(prev) = numbers.insert(n, r) {
                    sink.report(
                        at(r, 1),
                        Code::T005MessageNumber,
                        format!(
                            "{}: alarm number {n} is already used by {}",
                            MessageTable::address(r),
                            MessageTable::address(prev)
                        ),
                    );
                }
                if !has_text {
                    sink.report(
                        at(r, 2),
                        Code::W005MessageHalf,
                        format!("{}: alarm {n} has no text", MessageTable::address(r)),
                    );
                }
            }
            None if has_text => sink.report(
                at(r, 1),
                Code::W005MessageHalf,
                format!(
                    "{}: a message text without an alarm number",
                    MessageTable::address(r)
                ),
            ),
            None => {}
        }
    }
    // The table keeps a row per A bit of the largest profile; a smaller profile (the 980's
    // A0–A24) must leave the rows beyond its range empty.
    let rows = crate::model::tables::message_rows(profile);
    for (k, m) in project.messages.rows.iter().enumerate().skip(rows) {
        if *m != crate::model::Message::default() {
            sink.report(
                at(k, 0),
                Code::T005MessageNumber,
                format!(
                    "{} is beyond this controller's A range (A0000.0–{}): clear the row",
                    MessageTable::address(k),
                    MessageTable::address(rows - 1)
                ),
            );
        }
    }
    // Version information.
    sink.at(usize::MAX, "VERSION", 0);
    let v = &project.version;
    for (field, text, max) in [
        ("designer", &v.designer, DESIGNER_MAX),
        ("version", &v.version, VERSION_MAX),
        ("remarks", &v.remarks, REMARKS_MAX),
    ] {
        if text.chars().count() > max {
            sink.report(
                at(0, 0),
                Code::W006VersionLength,
                format!("the {field} is longer than {max} characters"),
            );
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::compiler::compile;
    use crate::profile::ProfileId;

    fn t005(p: &Project) -> Vec<String> {
        compile(p)
            .diagnostics
            .iter()
            .filter(|d| d.code == Code::T005MessageNumber)
            .map(|d| d.message.clone())
            .collect()
    }

    #[test]
    fn a_gsk980_project_has_a_message_row_per_a_bit_of_its_own_range() {
        let mut p = Project {
            profile: ProfileId::Gsk980,
            ..Project::default()
        };
        assert!(t005(&p).is_empty(), "an empty 980 project compiles clean");
        let a = Address::parse("A0030.0").unwrap();
        let k = MessageTable::row_of(a).unwrap();
        p.messages.rows[k].number = Some(1001);
        let found = t005(&p);
        assert_eq!(found.len(), 1, "{found:?}");
        assert!(found[0].contains("A0030.0 is beyond this controller's A range"));
        p.profile = ProfileId::Gsk988ta;
        assert!(t005(&p).is_empty(), "the 988TA has A0–A49");
    }
}
