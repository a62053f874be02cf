//! Checks of the project's tables (manual §3.4.3–§3.4.7), reported like compile diagnostics:
//! the "block" is the table (`SYMBOLS`, `DATA`, `MESSAGES`, `DIAGNOSIS`, `PERMISSIONS`,
//! `MCODES`, `VERSION`), the "network" the table's number, the row and column the cell. The
//! rules are the table editor's ([`crate::model::sheets`]), so a file holds no row that the
//! editor would refuse without `check` saying so.

use super::TableFinding;
use super::diag::{Origin, Sink};
use crate::address::{Address, Area};
use crate::model::Project;
use crate::model::sheets::{
    Sheet, TableError, check_comment, check_data_symbol, check_m_code, check_symbol_area,
    check_symbol_form, check_value_area,
};
use crate::model::tables::{
    AddressRow, Comments, DESIGNER_MAX, MessageTable, NAME_MAX, REMARKS_MAX, VALUE_LIMIT,
    VERSION_MAX,
};
use std::collections::HashMap;

/// The "block" numbers of the tables, after every ladder block, in the tree's order (a
/// diagnostic's place names them; the editor turns them into the table's view).
pub const SYMBOLS: usize = usize::MAX - 6;
/// The data-setting tables.
pub const DATA: usize = usize::MAX - 5;
/// The display-message table.
pub const MESSAGES: usize = usize::MAX - 4;
/// The diagnosis table.
pub const DIAGNOSIS: usize = usize::MAX - 3;
/// The permission table.
pub const PERMISSIONS: usize = usize::MAX - 2;
/// The M-code comment table.
pub const MCODES: usize = usize::MAX - 1;
/// The version information.
pub const VERSION: usize = usize::MAX;

/// Reports every comment of a row longer than the CNC keeps (W007), each at its language's
/// column: the tables show one comment column per language (`model::tables::LANGUAGES`, in that
/// order) from `origin`'s column on; another language counts after them.
fn comments(sink: &mut Sink, origin: Origin, comments: &Comments) {
    for (lang, text) in comments {
        if let Err(e) = check_comment(text) {
            let shift = crate::model::tables::LANGUAGES
                .iter()
                .position(|l| l == lang)
                .unwrap_or(crate::model::tables::LANGUAGES.len()) as u32;
            let origin = match origin {
                Origin::Cell { row, col } => Origin::Cell {
                    row,
                    col: col + shift,
                },
                other => other,
            };
            sink.find(
                origin,
                TableFinding::CommentTooLong {
                    lang: lang.clone(),
                    error: e,
                },
            );
        }
    }
}

/// A data row's symbol: a valid name (T001) that no symbol table gives another address (T002).
fn data_symbol(sink: &mut Sink, project: &Project, origin: Origin, name: &str, address: Address) {
    match check_data_symbol(project, name, address) {
        Err(error @ TableError::SymbolName { .. }) => {
            sink.find(origin, TableFinding::DataSymbolName { error })
        }
        Err(error) => sink.find(origin, TableFinding::DataSymbolElsewhere { address, error }),
        Ok(()) => {}
    }
}

/// The diagnosis or permission table: memory areas in range, each address once (T008).
fn address_table(sink: &mut Sink, project: &Project, rows: &[AddressRow]) {
    let mut seen: HashMap<Address, usize> = HashMap::new();
    for (r, row) in rows.iter().enumerate() {
        if let Err(error) = check_value_area(row.address) {
            sink.find(at(r, 0), TableFinding::KeyArea { error });
        } else if let Err(error) = row.address.check_range(project.profile()) {
            sink.find(at(r, 0), TableFinding::KeyRange { error });
        }
        if let Some(prev) = seen.insert(row.address, r) {
            sink.find(
                at(r, 0),
                TableFinding::KeyTwice {
                    address: row.address,
                    row: prev,
                },
            );
        }
        comments(sink, at(r, 1), &row.comments);
    }
}

fn at(row: usize, col: u32) -> Origin {
    Origin::Cell {
        row: row as u32,
        col,
    }
}

/// Checks every table of a project, in the tree's order (the order of the "block" numbers
/// above), so the diagnostics read table by table as the editor lists them.
pub fn check_tables(project: &Project, sink: &mut Sink) {
    symbol_tables(sink, project);
    // D and D_FLOAT share the D addresses: one map sees every data table.
    let mut listed: HashMap<Address, (Sheet, usize)> = HashMap::new();
    integer_data_tables(sink, project, &mut listed);
    real_data_table(sink, project, &mut listed);
    message_table(sink, project);
    // Diagnosis and permissions: memory addresses, each once.
    sink.at(DIAGNOSIS, "DIAGNOSIS", 0);
    address_table(sink, project, &project.diagnosis);
    sink.at(PERMISSIONS, "PERMISSIONS", 0);
    address_table(sink, project, &project.permissions);
    m_code_table(sink, project);
    version_info(sink, project);
}

/// Symbol tables: each table's name (T006), then every row's address and name. Names and
/// addresses are unique across all the tables, so the maps of those seen span them all.
fn symbol_tables(sink: &mut Sink, project: &Project) {
    let mut names: HashMap<&str, (usize, usize)> = HashMap::new();
    let mut addresses: HashMap<Address, (usize, usize)> = HashMap::new();
    let mut table_names: HashMap<&str, usize> = HashMap::new();
    for (t, table) in project.symbol_tables.iter().enumerate() {
        sink.at(SYMBOLS, "SYMBOLS", t);
        if table.name.is_empty()
            || table.name == crate::model::tables::BLOCK_SYMBOLS
            || table_names.insert(&table.name, t).is_some()
        {
            sink.find(
                at(0, 0),
                TableFinding::SymbolTableName {
                    name: table.name.clone(),
                },
            );
        }
        for (r, s) in table.rows.iter().enumerate() {
            symbol_address(sink, project, (t, r), s, &mut addresses);
            if s.name.is_empty() {
                continue;
            }
            symbol_name(sink, (t, r), &s.name, &mut names);
        }
    }
}

/// A symbol row's address: an area that takes symbols (T007) in range (T003), its comments,
/// and listed once over all the symbol tables (W004), since `addresses` spans them all.
/// `place` is (table, row).
fn symbol_address(
    sink: &mut Sink,
    project: &Project,
    place: (usize, usize),
    s: &crate::model::tables::Symbol,
    addresses: &mut HashMap<Address, (usize, usize)>,
) {
    let (t, r) = place;
    if let Err(error) = check_symbol_area(s.address) {
        sink.find(at(r, 0), TableFinding::SymbolArea { error });
    } else if let Err(error) = s.address.check_range(project.profile()) {
        sink.find(at(r, 0), TableFinding::AddressRange { error });
    }
    comments(sink, at(r, 2), &s.comments);
    if let Some((table, row)) = addresses.insert(s.address, (t, r)) {
        sink.find(
            at(r, 0),
            TableFinding::SymbolAddressTwice {
                address: s.address,
                table,
                row,
            },
        );
    }
}

/// A symbol row's (non-empty) name: well formed (T001), and unique over all the symbol
/// tables (T002), since an operand names its address by the symbol alone. `place` is
/// (table, row).
fn symbol_name<'p>(
    sink: &mut Sink,
    place: (usize, usize),
    name: &'p str,
    names: &mut HashMap<&'p str, (usize, usize)>,
) {
    let (t, r) = place;
    if check_symbol_form(name).is_err() {
        sink.find(at(r, 1), TableFinding::SymbolName { name: name.into() });
    } else if let Some((table, row)) = names.insert(name, (t, r)) {
        sink.find(
            at(r, 1),
            TableFinding::SymbolTwice {
                name: name.into(),
                table,
                row,
            },
        );
    }
}

/// Reports a data row whose address an earlier row of any data table already lists (T003),
/// at the later row. `listed` maps each address seen to its table and row, and is shared by
/// the tables because D and D_FLOAT set the same D addresses.
fn data_listed_twice(
    sink: &mut Sink,
    listed: &mut HashMap<Address, (Sheet, usize)>,
    sheet: Sheet,
    r: usize,
    address: Address,
) {
    if let Some((sheet, row)) = listed.insert(address, (sheet, r)) {
        sink.find(
            at(r, 0),
            TableFinding::DataAddressTwice {
                address,
                sheet,
                row,
            },
        );
    }
}

/// The D, DT and DC data tables (DATA 0–2): each row's area, listed once, its value inside
/// its limits (a DC preset never negative), its symbol and comments.
fn integer_data_tables(
    sink: &mut Sink,
    project: &Project,
    listed: &mut HashMap<Address, (Sheet, usize)>,
) {
    let data = &project.data;
    let tables = [
        (Sheet::D, Area::D, &data.d),
        (Sheet::Dt, Area::Dt, &data.dt),
        (Sheet::Dc, Area::Dc, &data.dc),
    ];
    for (t, (sheet, area, rows)) in tables.into_iter().enumerate() {
        sink.at(DATA, "DATA", t);
        for (r, row) in rows.iter().enumerate() {
            data_listed_twice(sink, listed, sheet, r, row.address);
            data_symbol(sink, project, at(r, 4), &row.symbol, row.address);
            comments(sink, at(r, 5), &row.comments);
            if row.address.area != area || row.address.bit.is_some() {
                sink.find(
                    at(r, 0),
                    TableFinding::DataAddressArea {
                        address: row.address,
                        sheet,
                    },
                );
            } else if let Err(error) = row.address.check_range(project.profile()) {
                sink.find(at(r, 0), TableFinding::AddressRange { error });
            }
            let lo = row.min.unwrap_or(-VALUE_LIMIT);
            let hi = row.max.unwrap_or(VALUE_LIMIT);
            if row.value < lo || row.value > hi || lo > hi {
                sink.find(
                    at(r, 1),
                    TableFinding::DataValue {
                        address: row.address,
                        value: row.value,
                        min: lo,
                        max: hi,
                    },
                );
            }
            // DC holds counter presets, and a counter counts 0…N (docs/plc.md, CTRC).
            if area == Area::Dc && row.value < 0 {
                sink.find(
                    at(r, 1),
                    TableFinding::CounterPreset {
                        address: row.address,
                        value: row.value,
                    },
                );
            }
        }
    }
}

/// The D_FLOAT table (DATA 3): D addresses of this controller, listed once with the integer
/// tables' D rows, a finite value inside its limits, its symbol and comments.
fn real_data_table(
    sink: &mut Sink,
    project: &Project,
    listed: &mut HashMap<Address, (Sheet, usize)>,
) {
    sink.at(DATA, "DATA", 3);
    for (r, row) in project.data.d_float.iter().enumerate() {
        data_listed_twice(sink, listed, Sheet::DFloat, r, row.address);
        data_symbol(sink, project, at(r, 4), &row.symbol, row.address);
        comments(sink, at(r, 5), &row.comments);
        if row.address.area != Area::D
            || row.address.bit.is_some()
            || row.address.check_range(project.profile()).is_err()
        {
            sink.find(
                at(r, 0),
                TableFinding::RealAddress {
                    address: row.address,
                },
            );
        }
        if !row.value.is_finite()
            || row.min.is_some_and(|m| row.value < m)
            || row.max.is_some_and(|m| row.value > m)
        {
            sink.find(
                at(r, 1),
                TableFinding::RealValue {
                    address: row.address,
                    value: row.value.to_bits(),
                },
            );
        }
    }
}

/// The message table: alarm numbers 1000–9999, each once, number and text together; then
/// the rows past this controller's A range, which must stay empty.
fn message_table(sink: &mut Sink, project: &Project) {
    sink.at(MESSAGES, "MESSAGES", 0);
    let mut numbers: HashMap<u16, usize> = HashMap::new();
    for (r, m) in project.messages.rows.iter().enumerate() {
        let has_text = m.texts.values().any(|t| !t.is_empty());
        let bit = MessageTable::address(r);
        match m.number {
            Some(number) if !(1000..=9999).contains(&number) => {
                sink.find(at(r, 1), TableFinding::AlarmRange { bit, number })
            }
            Some(number) => {
                if let Some(prev) = numbers.insert(number, r) {
                    let by = MessageTable::address(prev);
                    sink.find(at(r, 1), TableFinding::AlarmTwice { bit, number, by });
                }
                if !has_text {
                    sink.find(at(r, 2), TableFinding::AlarmWithoutText { bit, number });
                }
            }
            None if has_text => sink.find(at(r, 1), TableFinding::TextWithoutAlarm { bit }),
            None => {}
        }
    }
    messages_beyond_range(sink, project);
}

/// The message table keeps a row per A bit of the largest profile; a smaller profile (the
/// 980's A0–A24) must leave the rows beyond its range empty (T005).
fn messages_beyond_range(sink: &mut Sink, project: &Project) {
    let rows = crate::model::tables::message_rows(project.profile());
    for (k, m) in project.messages.rows.iter().enumerate().skip(rows) {
        if *m != crate::model::Message::default() {
            sink.find(
                at(k, 0),
                TableFinding::MessageBeyondRange {
                    bit: MessageTable::address(k),
                    last: MessageTable::address(rows - 1),
                },
            );
        }
    }
}

/// The M-code comment table: codes in range, each once (T008), and their comments.
fn m_code_table(sink: &mut Sink, project: &Project) {
    sink.at(MCODES, "MCODES", 0);
    let mut codes: HashMap<u32, usize> = HashMap::new();
    for (r, row) in project.m_codes.iter().enumerate() {
        if let Err(error) = check_m_code(row.code) {
            sink.find(at(r, 0), TableFinding::MCodeRange { error });
        }
        if let Some(prev) = codes.insert(row.code, r) {
            sink.find(
                at(r, 0),
                TableFinding::MCodeTwice {
                    code: row.code,
                    row: prev,
                },
            );
        }
        comments(sink, at(r, 1), &row.comments);
    }
}

/// The version information: each field within its length (W006).
fn version_info(sink: &mut Sink, project: &Project) {
    sink.at(VERSION, "VERSION", 0);
    let v = &project.version;
    // Each field with its limit and the finding that names it.
    for (text, max, finding) in [
        (
            &v.name,
            NAME_MAX,
            TableFinding::VersionNameLength { max: NAME_MAX },
        ),
        (
            &v.designer,
            DESIGNER_MAX,
            TableFinding::VersionDesignerLength { max: DESIGNER_MAX },
        ),
        (
            &v.version,
            VERSION_MAX,
            TableFinding::VersionVersionLength { max: VERSION_MAX },
        ),
        (
            &v.remarks,
            REMARKS_MAX,
            TableFinding::VersionRemarksLength { max: REMARKS_MAX },
        ),
    ] {
        if text.chars().count() > max {
            sink.find(at(0, 0), finding);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::compiler::{Code, Finding, compile};
    use crate::model::DataRow;
    use crate::profile::ProfileId;

    fn t005(p: &Project) -> Vec<Finding> {
        compile(p)
            .diagnostics
            .into_iter()
            .filter(|d| d.code == Code::T005MessageNumber)
            .map(|d| d.finding)
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
        assert_eq!(
            found[0],
            Finding::Table(TableFinding::MessageBeyondRange {
                bit: a,
                last: Address::parse("A0024.7").unwrap(),
            })
        );
        p.profile = ProfileId::Gsk988ta;
        assert!(t005(&p).is_empty(), "the 988TA has A0–A49");
    }

    /// (table number, row, column) of every diagnostic of `code`, in order.
    fn places(p: &Project, code: Code) -> Vec<(usize, u32, u32)> {
        compile(p)
            .diagnostics
            .iter()
            .filter(|d| d.code == code)
            .map(|d| match d.location.origin {
                Origin::Cell { row, col } => (d.location.network, row, col),
                other => panic!("a table diagnostic without a cell: {other:?}"),
            })
            .collect()
    }

    #[test]
    fn a_data_address_listed_twice_is_refused_at_the_later_row() {
        let a = |t: &str| Address::parse(t).unwrap();
        let mut p = Project::default();
        p.data.d = vec![DataRow::new(a("D0001"), 1), DataRow::new(a("D0001"), 2)];
        p.data.dt = vec![DataRow::new(a("DT0001"), 1), DataRow::new(a("DT0001"), 2)];
        p.data.dc = vec![DataRow::new(a("DC0001"), 1), DataRow::new(a("DC0001"), 2)];
        // D_FLOAT shares the D addresses: D0001 is a third time there.
        p.data.d_float = vec![crate::model::RealRow::new(a("D0001"), 1.0)];
        assert_eq!(
            places(&p, Code::T003DataAddress),
            [(0, 1, 0), (1, 1, 0), (2, 1, 0), (3, 0, 0)]
        );
    }

    #[test]
    fn an_m_code_or_an_alarm_number_listed_twice_is_refused_at_the_later_row() {
        let m_codes = [3, 8, 3]
            .into_iter()
            .map(|code| crate::model::MCodeRow {
                code,
                comments: Default::default(),
            })
            .collect();
        let mut p = Project {
            m_codes,
            ..Project::default()
        };
        assert_eq!(places(&p, Code::T008TableKey), [(0, 2, 0)]);
        for (k, n) in [(1, 1001), (2, 1002), (5, 1001)] {
            p.messages.rows[k].number = Some(n);
            p.messages.rows[k].texts.insert("zh".into(), "报警".into());
        }
        assert_eq!(places(&p, Code::T005MessageNumber), [(0, 5, 1)]);
    }

    #[test]
    fn a_negative_counter_preset_in_the_dc_table_is_refused_at_its_value() {
        let mut p = Project::default();
        p.data
            .dc
            .push(DataRow::new(Address::parse("DC0001").unwrap(), 5));
        p.data
            .dc
            .push(DataRow::new(Address::parse("DC0002").unwrap(), -5));
        // A negative D or DT value is no counter preset.
        p.data
            .d
            .push(DataRow::new(Address::parse("D0001").unwrap(), -5));
        p.data
            .dt
            .push(DataRow::new(Address::parse("DT0001").unwrap(), -5));
        let found: Vec<_> = compile(&p)
            .diagnostics
            .into_iter()
            .filter(|d| d.code == Code::T004DataValue)
            .collect();
        assert_eq!(found.len(), 1, "{found:?}");
        let d = &found[0];
        assert_eq!(
            (d.location.block_label.as_str(), d.location.network),
            ("DATA", 2)
        );
        assert_eq!(d.location.origin, Origin::Cell { row: 1, col: 1 });
        assert_eq!(
            d.finding,
            Finding::Table(TableFinding::CounterPreset {
                address: Address::parse("DC0002").unwrap(),
                value: -5,
            })
        );
    }
}
