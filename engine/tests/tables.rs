//! The table editors' rules (manual §3.4.3–§3.4.7), written as texts typed into cells: what a
//! table takes, what it refuses and why, the row menu, and `check` finding in a file what the
//! editor refuses.

use ladder_engine::address::{Address, AddressError, Area};
use ladder_engine::compiler::{Code, compile};
use ladder_engine::model::sheets::{
    Col, RowOp, SYMBOL_AREAS, Sheet, TableError, Taken, VALUE_AREAS, cell_text, changed_row,
    commit, k_bit, next_free_address, row_op, set_password,
};
use ladder_engine::model::{
    AddressRow, BlockKind, Comments, DataRow, MCodeRow, Project, RealRow, Symbol, TableEdit,
    VersionInfo,
};
use ladder_engine::{Profile, ProfileId};

/// Types `text` into a cell and applies the edit, as the editor does on Enter; returns why
/// the text was refused, leaving the project as it was.
fn enter(
    p: &mut Project,
    sheet: Sheet,
    row: usize,
    col: Col,
    text: &str,
) -> Result<(), TableError> {
    if let Some(edit) = commit(p, sheet, row, col, text)? {
        p.apply_table(edit);
    }
    Ok(())
}

/// Like [`enter`], for a text the table must refuse: the error, and the project unchanged.
fn refused(p: &mut Project, sheet: Sheet, row: usize, col: Col, text: &str) -> TableError {
    let before = p.clone();
    let e = enter(p, sheet, row, col, text).expect_err(text);
    assert_eq!(*p, before, "{text} changed nothing");
    e
}

fn addr(text: &str) -> Address {
    Address::parse(text).unwrap()
}

fn symbols(rows: &[(&str, &str)]) -> Project {
    let mut p = Project::default();
    p.symbol_tables[0].rows = rows
        .iter()
        .map(|(a, n)| Symbol {
            name: (*n).into(),
            address: addr(a),
            comments: Comments::new(),
        })
        .collect();
    p
}

/// A row operation applied; the row selected after it.
fn op(p: &mut Project, sheet: Sheet, op: RowOp, row: usize) -> usize {
    let (edit, select) = row_op(p, sheet, op, row).unwrap();
    if let Some(edit) = edit {
        p.apply_table(edit);
    }
    select
}

/// The codes `compile` reports on the tables, with their table and row (1-based).
fn table_codes(p: &Project) -> Vec<(&'static str, String, u32)> {
    compile(p)
        .diagnostics
        .iter()
        .filter_map(|d| match d.location.origin {
            ladder_engine::compiler::Origin::Cell { row, .. }
                if d.location.block > p.ladder.blocks.len() =>
            {
                Some((d.code.as_str(), d.location.block_label.clone(), row + 1))
            }
            _ => None,
        })
        .collect()
}

const S: Sheet = Sheet::Symbols(0);

#[test]
fn symbols_are_entered_canonical_and_shown() {
    let mut p = Project::default();
    // The empty last line takes only its key.
    enter(&mut p, S, 0, Col::Symbol, "START").unwrap();
    assert!(p.symbol_tables[0].rows.is_empty());
    enter(&mut p, S, 0, Col::Address, " r10.1 ").unwrap();
    enter(&mut p, S, 0, Col::Symbol, "START").unwrap();
    enter(&mut p, S, 0, Col::Comment("en"), "cycle start").unwrap();
    let row = &p.symbol_tables[0].rows[0];
    assert_eq!(row.address, Address::bit(Area::R, 10, 1));
    assert_eq!(row.name, "START");
    assert_eq!(row.comments["en"], "cycle start");
    assert_eq!(cell_text(&p, S, 0, Col::Address), "R0010.1");
    assert_eq!(
        cell_text(&p, S, 0, Col::Comment("zh")),
        "",
        "no Chinese comment"
    );
    assert_eq!(
        commit(&p, S, 0, Col::Symbol, "START"),
        Ok(None),
        "a field left as it was is no edit"
    );
    enter(&mut p, S, 0, Col::Comment("en"), "  ").unwrap();
    assert!(p.symbol_tables[0].rows[0].comments.is_empty(), "emptied");
}

#[test]
fn symbol_tables_refuse_bad_addresses_and_names_with_the_reason() {
    let mut p = symbols(&[("R10.1", "START")]);
    assert_eq!(
        refused(&mut p, S, 1, Col::Address, "Z99"),
        TableError::Address(AddressError::UnknownArea("Z99".into(), "Z".into()))
    );
    assert!(matches!(
        refused(&mut p, S, 1, Col::Address, "R1000"),
        TableError::Address(AddressError::Range {
            area: Area::R,
            lo: 0,
            hi: 999,
            ..
        })
    ));
    for text in ["L1", "P2"] {
        assert_eq!(
            refused(&mut p, S, 1, Col::Address, text),
            TableError::AreaNotHere {
                address: addr(text),
                allowed: SYMBOL_AREAS
            }
        );
    }
    assert_eq!(
        refused(&mut p, S, 1, Col::Address, "R10.1"),
        TableError::AddressTwice {
            address: addr("R10.1"),
            at: Taken::Symbols {
                table: "符号表1".into(),
                row: 0
            }
        }
    );
    assert_eq!(
        refused(&mut p, S, 0, Col::Address, ""),
        TableError::AddressEmpty
    );
    enter(&mut p, S, 1, Col::Address, "R10.2").unwrap();
    assert_eq!(
        refused(&mut p, S, 1, Col::Symbol, "START"),
        TableError::SymbolTwice {
            name: "START".into(),
            at: Taken::Symbols {
                table: "符号表1".into(),
                row: 0
            }
        }
    );
    for name in ["1ABC", "X1", "A-B"] {
        assert_eq!(
            refused(&mut p, S, 1, Col::Symbol, name),
            TableError::SymbolName { name: name.into() }
        );
    }
    p.ladder.blocks.push(ladder_engine::model::Block {
        kind: BlockKind::Sub {
            number: 3,
            name: "TOOL".into(),
        },
        ..p.ladder.blocks[1].clone()
    });
    let e = refused(&mut p, S, 1, Col::Symbol, "TOOL");
    assert_eq!(
        e,
        TableError::SymbolTwice {
            name: "TOOL".into(),
            at: Taken::Block(Address::byte(Area::P, 3))
        }
    );
    assert_eq!(
        e.to_string(),
        "`TOOL`: symbol already exists: 程序块符号 P0003"
    );
    assert_eq!(
        refused(&mut p, S, 0, Col::Comment("en"), &"字".repeat(43)),
        TableError::CommentTooLong {
            bytes: 129,
            max: 127
        }
    );
}

#[test]
fn data_values_are_clamped_and_addresses_kept_apart() {
    let mut p = Project::default();
    let mut row = DataRow::new(Address::byte(Area::D, 10), 50);
    row.set_max(Some(100));
    p.data.d.push(row);
    enter(&mut p, Sheet::D, 0, Col::Value, "500").unwrap();
    assert_eq!(p.data.d[0].value, 100, "clamped to the max");
    enter(&mut p, Sheet::D, 0, Col::Min, "200").unwrap();
    assert_eq!(p.data.d[0].min, Some(100), "a min above the max");
    assert_eq!(
        refused(&mut p, Sheet::D, 0, Col::Value, "ten"),
        TableError::NotInteger { text: "ten".into() }
    );
    assert_eq!(
        refused(&mut p, Sheet::D, 0, Col::Value, ""),
        TableError::NotInteger {
            text: String::new()
        },
        "a value is required"
    );
    assert_eq!(
        refused(&mut p, Sheet::D, 0, Col::Address, "DT5"),
        TableError::AreaNotHere {
            address: addr("DT5"),
            allowed: ladder_engine::address::AreaSet::of(&[Area::D])
        }
    );
    enter(&mut p, Sheet::D, 1, Col::Address, "d12").unwrap();
    assert_eq!(cell_text(&p, Sheet::D, 1, Col::Address), "D0012");
    // One D holds an integer or a real, not both.
    assert_eq!(
        refused(&mut p, Sheet::DFloat, 0, Col::Address, "D12"),
        TableError::AddressTwice {
            address: addr("D12"),
            at: Taken::Data {
                sheet: Sheet::D,
                row: 1
            }
        }
    );
    enter(&mut p, Sheet::DFloat, 0, Col::Address, "D20").unwrap();
    enter(&mut p, Sheet::DFloat, 0, Col::Max, "2.5").unwrap();
    enter(&mut p, Sheet::DFloat, 0, Col::Value, "7.25").unwrap();
    assert_eq!(p.data.d_float[0].value, 2.5);
    assert_eq!(
        refused(&mut p, Sheet::DFloat, 0, Col::Value, "inf"),
        TableError::NotReal { text: "inf".into() }
    );
    p.symbol_tables[0].rows.push(Symbol {
        name: "LIMIT".into(),
        address: addr("D30"),
        comments: Comments::new(),
    });
    assert_eq!(
        refused(&mut p, Sheet::D, 0, Col::Symbol, "LIMIT"),
        TableError::SymbolElsewhere {
            name: "LIMIT".into(),
            address: addr("D30")
        }
    );
    enter(&mut p, Sheet::D, 0, Col::Address, "D30").unwrap();
    enter(&mut p, Sheet::D, 0, Col::Symbol, "LIMIT").unwrap();
    assert_eq!(p.data.d[0].symbol, "LIMIT", "the symbol of its own address");
}

#[test]
fn messages_numbers_m_codes_and_diagnosis_rows_are_checked() {
    let mut p = Project::default();
    let m = Sheet::Messages;
    enter(&mut p, m, 399, Col::Number, "1234").unwrap();
    enter(&mut p, m, 399, Col::Text("en"), "Oil level low").unwrap();
    assert_eq!(p.messages.rows[399].number, Some(1234));
    assert_eq!(cell_text(&p, m, 399, Col::Address), "A0049.7");
    assert_eq!(
        refused(&mut p, m, 398, Col::Number, "1234"),
        TableError::AlarmTwice {
            number: 1234,
            by: addr("A49.7")
        }
    );
    assert_eq!(
        refused(&mut p, m, 398, Col::Number, "999"),
        TableError::AlarmRange { text: "999".into() }
    );
    assert_eq!(
        commit(&p, m, 400, Col::Number, "1000"),
        Ok(None),
        "400 rows"
    );

    let c = Sheet::MCodes;
    enter(&mut p, c, 0, Col::Code, "m3").unwrap();
    assert_eq!(cell_text(&p, c, 0, Col::Code), "M03");
    assert_eq!(
        refused(&mut p, c, 1, Col::Code, "M03"),
        TableError::MCodeTwice { code: 3, row: 0 }
    );
    assert_eq!(
        refused(&mut p, c, 1, Col::Code, "10000"),
        TableError::MCodeRange {
            text: "10000".into()
        }
    );

    let d = Sheet::Diagnosis;
    enter(&mut p, d, 0, Col::Address, "k2.1").unwrap();
    assert_eq!(
        refused(&mut p, d, 1, Col::Address, "K2.1"),
        TableError::AddressTwice {
            address: addr("K2.1"),
            at: Taken::Row(0)
        }
    );
    assert_eq!(
        refused(&mut p, d, 1, Col::Address, "P1"),
        TableError::AreaNotHere {
            address: addr("P1"),
            allowed: VALUE_AREAS
        }
    );
    assert_eq!(
        refused(&mut p, d, 0, Col::Comment("en"), &"x".repeat(128)),
        TableError::CommentTooLong {
            bytes: 128,
            max: 127
        }
    );
    enter(&mut p, Sheet::Permissions, 0, Col::Address, "K2.1").unwrap();
    assert_eq!(p.permissions.len(), 1, "each table lists its own addresses");
}

#[test]
fn the_row_menu_inserts_clears_and_deletes_and_says_what_to_select() {
    let original = symbols(&[("R0.0", "A"), ("R0.1", "B"), ("R0.2", "C")]);
    let mut p = original.clone();
    assert_eq!(op(&mut p, S, RowOp::InsertAbove, 1), 1);
    let rows = &p.symbol_tables[0].rows;
    assert_eq!(rows.len(), 4);
    assert_eq!(
        (rows[1].address, rows[1].name.as_str()),
        (addr("R0.3"), ""),
        "a new row at the next free address"
    );
    assert_eq!(op(&mut p, S, RowOp::Delete, 1), 1);
    assert_eq!(p, original);
    assert_eq!(op(&mut p, S, RowOp::Clear, 2), 2);
    assert_eq!(p.symbol_tables[0].rows[2].name, "", "cleared");
    assert_eq!(p.symbol_tables[0].rows[2].address, addr("R0.2"), "key kept");
    assert_eq!(op(&mut p, S, RowOp::InsertBelow, 0), 1);
    assert_eq!(p.symbol_tables[0].rows[1].address, addr("R0.3"));
    assert_eq!(op(&mut p, S, RowOp::Delete, 3), 2, "the last row goes");

    // The message rows are the A bits: cleared, never inserted or deleted.
    let mut p = Project::default();
    p.messages.rows[5].number = Some(1001);
    for o in [RowOp::InsertAbove, RowOp::InsertBelow, RowOp::Delete] {
        assert_eq!(row_op(&p, Sheet::Messages, o, 5), Ok((None, 5)));
    }
    op(&mut p, Sheet::Messages, RowOp::Clear, 5);
    assert_eq!(p.messages, Project::default().messages);

    // Empty tables start at the area's first address.
    op(&mut p, Sheet::Permissions, RowOp::InsertBelow, 0);
    assert_eq!(p.permissions[0].address, Address::byte(Area::K, 0));
    op(&mut p, Sheet::Diagnosis, RowOp::InsertBelow, 0);
    assert_eq!(p.diagnosis[0].address, Address::bit(Area::K, 0, 0));
    op(&mut p, Sheet::MCodes, RowOp::InsertAbove, 0);
    assert_eq!(p.m_codes[0].code, 0);
    op(&mut p, Sheet::DFloat, RowOp::InsertAbove, 0);
    p.data.d.push(DataRow::new(Address::byte(Area::D, 1), 0));
    op(&mut p, Sheet::D, RowOp::InsertBelow, 0);
    assert_eq!(
        p.data.d.iter().map(|r| r.address).collect::<Vec<_>>(),
        [Address::byte(Area::D, 1), Address::byte(Area::D, 2)],
        "D0000 is D_FLOAT's"
    );

    // A full area has no free key.
    let profile = p.profile();
    let (lo, hi) = profile.range(Area::Dt);
    p.data.dt = (lo..=hi)
        .map(|n| DataRow::new(Address::byte(Area::Dt, n), 0))
        .collect();
    assert_eq!(
        row_op(&p, Sheet::Dt, RowOp::InsertBelow, 0),
        Err(TableError::NoFreeKey { sheet: Sheet::Dt })
    );
}

#[test]
fn free_keys_wrap_round_and_reals_clamp() {
    let p = Profile::get(ProfileId::Gsk988ta);
    let used = [Address::bit(Area::R, 999, 7), Address::bit(Area::R, 0, 0)];
    assert_eq!(
        next_free_address(Address::bit(Area::R, 999, 7), p, |a| used.contains(&a)),
        Some(Address::bit(Area::R, 0, 1)),
        "wraps round the area"
    );
    assert_eq!(
        next_free_address(Address::byte(Area::Dt, 0), p, |_| true),
        None
    );
    let mut r = RealRow::new(Address::byte(Area::D, 0), 0.0);
    r.set_value(5.0);
    r.set_max(Some(2.0));
    r.set_min(Some(3.0));
    assert_eq!((r.min, r.max, r.value), (Some(2.0), Some(2.0), 2.0));
}

#[test]
fn the_k_page_and_changed_rows() {
    let mut p = Project::default();
    let on = k_bit(&p, 3, 5, true).unwrap();
    assert_eq!(changed_row(&p, &on), None, "the K page has no rows");
    p.apply_table(on);
    assert_eq!(p.data.k, [0, 0, 0, 0x20]);
    assert_eq!(k_bit(&p, 3, 5, true), None, "already on");

    let before = symbols(&[("R0.0", "A"), ("R0.1", "B")]);
    let mut after = before.clone();
    after.symbol_tables.push(after.symbol_tables[0].clone());
    after.symbol_tables[1].rows[1].name = "C".into();
    let edit = TableEdit::Symbols(before.symbol_tables.clone());
    assert_eq!(changed_row(&after, &edit), Some((Sheet::Symbols(1), 0)));
    let mut p = before.clone();
    enter(&mut p, S, 1, Col::Symbol, "B2").unwrap();
    assert_eq!(
        changed_row(&p, &TableEdit::Symbols(before.symbol_tables.clone())),
        Some((S, 1))
    );
    // An undone insert at the end: the last row is shown.
    let mut p = before.clone();
    let (edit, _) = row_op(&p, S, RowOp::InsertBelow, 1).unwrap();
    let inverse = p.apply_table(edit.unwrap());
    let redo = p.apply_table(inverse);
    assert_eq!(changed_row(&p, &redo), Some((S, 1)));
    let mut p = Project::default();
    p.diagnosis.push(AddressRow {
        address: addr("X0.0"),
        comments: Comments::new(),
    });
    p.m_codes.push(MCodeRow {
        code: 8,
        comments: Comments::new(),
    });
    assert_eq!(
        changed_row(&p, &TableEdit::Diagnosis(Vec::new())),
        Some((Sheet::Diagnosis, 0))
    );
    assert_eq!(
        changed_row(&p, &TableEdit::MCodes(p.m_codes.clone())),
        None,
        "equal tables"
    );
}

#[test]
fn passwords_take_the_current_one_and_keep_only_a_hash() {
    let v = VersionInfo::default();
    assert_eq!(
        set_password(&v, "", Some(("", "")), "00"),
        Err(TableError::PasswordEmpty)
    );
    assert_eq!(
        set_password(&v, "", Some(("s3cret", "s3crat")), "00"),
        Err(TableError::PasswordMismatch)
    );
    let set = set_password(&v, "", Some(("s3cret", "s3cret")), "a1b2").unwrap();
    let hash = set.password.clone().unwrap();
    assert!(hash.matches("s3cret") && hash.salt == "a1b2" && !hash.hash.contains("s3cret"));
    assert_eq!(
        set_password(&set, "wrong", None, "00"),
        Err(TableError::PasswordWrong)
    );
    assert_eq!(
        set_password(&set, "wrong", Some(("new", "new")), "00"),
        Err(TableError::PasswordWrong)
    );
    assert_eq!(set_password(&set, "s3cret", None, "00").unwrap(), v);
}

#[test]
fn check_finds_in_a_file_what_the_tables_refuse() {
    let p = symbols(&[("R0.0", "A"), ("X1.0", "B")]);
    assert!(table_codes(&p).is_empty(), "{:?}", table_codes(&p));
    // A file (or an import) may hold rows the editor never lets in.
    let mut p = symbols(&[
        ("P2", "TOOL"),
        ("L1", "LOOP"),
        ("G4.0", "GATE"),
        ("R0.0", "A"),
    ]);
    p.symbol_tables[0].rows[3]
        .comments
        .insert("zh".into(), "字".repeat(43));
    p.diagnosis = ["P1", "X0.0", "X0.0"]
        .iter()
        .map(|a| AddressRow {
            address: addr(a),
            comments: Comments::new(),
        })
        .collect();
    p.m_codes = [3, 3, 10_000]
        .into_iter()
        .map(|code| MCodeRow {
            code,
            comments: Comments::new(),
        })
        .collect();
    p.data.d.push(DataRow::new(addr("D4"), 0));
    p.data.d_float.push(RealRow::new(addr("D4"), 0.0));
    p.data.dt.push(DataRow::new(addr("DT0"), 0));
    p.data.dt[0].symbol = "A".into();
    let found = table_codes(&p);
    let want = [
        ("T007", "SYMBOLS", 1),
        ("T007", "SYMBOLS", 2),
        ("W007", "SYMBOLS", 4),
        ("T003", "DATA", 1),
        ("T002", "DATA", 1),
        ("T008", "DIAGNOSIS", 1),
        ("T008", "DIAGNOSIS", 3),
        ("T008", "MCODES", 2),
        ("T008", "MCODES", 3),
    ];
    for (code, table, row) in want {
        assert!(
            found.contains(&(code, table.to_string(), row)),
            "{code} {table} row {row} in {found:?}"
        );
    }
    assert_eq!(found.len(), want.len(), "{found:?}");
    let c = compile(&p);
    let t007 = c
        .diagnostics
        .iter()
        .find(|d| d.code == Code::T007SymbolArea)
        .unwrap();
    let message = ladder_text::diagnostics::message(t007, ladder_text::Lang::En);
    assert!(
        message.starts_with("P0002: only these areas belong here"),
        "{message}"
    );
}

#[test]
fn the_editor_and_check_agree_on_symbol_areas() {
    for text in [
        "A0.0", "X1.0", "Y2.1", "R3", "K4.0", "F5.0", "C1", "T1", "D4", "DT1", "DC1", "G4.0", "L1",
        "P2",
    ] {
        let mut typed = Project::default();
        let refused_by_editor = matches!(
            enter(&mut typed, S, 0, Col::Address, text),
            Err(TableError::AreaNotHere { .. })
        );
        let mut file = Project::default();
        file.symbol_tables[0].rows.push(Symbol {
            name: String::new(),
            address: addr(text),
            comments: Comments::new(),
        });
        let refused_by_check = table_codes(&file).iter().any(|(c, ..)| *c == "T007");
        assert_eq!(refused_by_editor, refused_by_check, "{text}");
        assert_eq!(refused_by_editor, ["L1", "P2"].contains(&text));
    }
}

#[test]
fn a_comment_too_long_is_reported_at_its_own_languages_column() {
    use ladder_engine::compiler::Origin;
    let mut p = symbols(&[("R0.0", "A")]);
    p.symbol_tables[0].rows[0]
        .comments
        .insert("en".into(), "x".repeat(200));
    p.symbol_tables[0].rows[0]
        .comments
        .insert("zh".into(), "字".repeat(43));
    let mut cols: Vec<(bool, u32)> = compile(&p)
        .diagnostics
        .iter()
        .filter(|d| d.code == Code::W007CommentLength)
        .filter_map(|d| match d.location.origin {
            Origin::Cell { col, .. } => {
                let message = ladder_text::diagnostics::message(d, ladder_text::Lang::En);
                Some((message.contains("`en`"), col))
            }
            _ => None,
        })
        .collect();
    cols.sort();
    // Address, symbol, then the zh and the en comment columns (0-based 2 and 3).
    assert_eq!(cols, [(false, 2), (true, 3)]);
}
