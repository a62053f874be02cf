//! An import that would leave `check` an error it did not have is refused at the CSV line
//! to correct, and changes nothing.

use super::{CommentsError, Rejection, import};
use crate::address::Address;
use crate::compiler::Code;
use crate::compiler::compile;
use crate::model::tables::{DataRow, MessageTable};
use crate::model::{Project, Symbol};
use crate::profile::ProfileId;

const HEAD: &str = "kind,table,key,symbol,zh,en\n";

/// Imports `rows` into `p` and returns the rejected rows; panics when the import applies, and
/// checks that a refused import leaves the project as it was.
fn refused(p: &mut Project, rows: &str) -> Vec<(u64, Rejection)> {
    let before = p.clone();
    match import(p, &format!("{HEAD}{rows}"), None) {
        Err(CommentsError::Rejected(r)) => {
            assert_eq!(*p, before, "a refused import changes nothing");
            r
        }
        other => panic!("not refused: {other:?}"),
    }
}

/// The reason of a row refused for what it says.
fn row(r: &(u64, Rejection)) -> &str {
    match &r.1 {
        Rejection::Row(why) => why,
        other => panic!("not refused for the row itself: {other:?}"),
    }
}

/// The error `check` would report after the import, for a row refused for it.
fn breaks(r: &(u64, Rejection)) -> &crate::compiler::Diagnostic {
    match &r.1 {
        Rejection::WouldBreak(d) => d,
        other => panic!("not refused for what `check` would say: {other:?}"),
    }
}

fn addr(a: &str) -> Address {
    Address::parse(a).unwrap()
}

fn symbol(p: &mut Project, a: &str, name: &str) {
    p.symbol_tables[0].rows.push(Symbol {
        name: name.into(),
        address: addr(a),
        comments: Default::default(),
    });
}

fn errors(p: &Project) -> usize {
    compile(p).errors()
}

#[test]
fn an_alarm_number_another_a_bit_has_is_refused_at_its_line() {
    let mut p = Project::default();
    p.messages.rows[1].number = Some(1001);
    let r = refused(
        &mut p,
        "message,,A0000.2,1002,甲,a\nmessage,,A0000.3,1001,乙,b\n",
    );
    assert_eq!(r.len(), 1, "{r:?}");
    assert_eq!(r[0].0, 3);
    assert!(
        row(&r[0]).starts_with("alarm number 1001 would be used by both A0000.1 and A0000.3"),
        "{r:?}"
    );
}

#[test]
fn two_rows_giving_one_symbol_are_refused_at_the_later() {
    let mut p = Project::default();
    let r = refused(&mut p, "symbol,,X0002.1,START,,\nsymbol,,X0002.2,START,,\n");
    assert_eq!(r.len(), 1, "{r:?}");
    assert_eq!(r[0].0, 3);
    assert!(
        row(&r[0]).contains("symbol `START` would be defined twice"),
        "{r:?}"
    );
    // A symbol a table already has, given to another address.
    symbol(&mut p, "X0002.1", "STOP");
    let r = refused(&mut p, "symbol,,X0002.3,STOP,,\n");
    assert_eq!(r[0].0, 2, "{r:?}");
}

#[test]
fn renaming_a_symbol_the_ladder_uses_is_refused() {
    let text = "LEVEL2\nNETWORK\nLD   START\nOUT  Y0001.0\nEND\n";
    let mut p = crate::il::import(text).project.expect("drawable");
    symbol(&mut p, "X0002.1", "START");
    assert_eq!(errors(&p), 0);
    let r = refused(&mut p, "symbol,,X0002.1,BEGIN,,\n");
    assert_eq!(r.len(), 1, "{r:?}");
    assert_eq!(r[0].0, 2);
    let d = breaks(&r[0]);
    assert_eq!(d.code, Code::L020UndefinedSymbol, "{r:?}");
    assert!(format!("{:?}", d.finding).contains("START"), "{r:?}");
}

#[test]
fn a_data_rows_symbol_that_stands_for_another_address_is_refused() {
    let mut p = Project::default();
    symbol(&mut p, "X0002.1", "START");
    p.data.d.push(DataRow::new(addr("D0004"), 0));
    let r = refused(&mut p, "data,D,D0004,START,,\n");
    assert_eq!(r.len(), 1, "{r:?}");
    assert_eq!(r[0].0, 2);
    let d = breaks(&r[0]);
    assert_eq!(d.code, Code::T002SymbolTwice, "{r:?}");
    assert_eq!(d.location.block_label, "DATA", "{r:?}");
    assert_eq!(d.location.network, 0, "{r:?}");
    assert_eq!(d.location.cell().map(|c| c.row), Some(0), "{r:?}");
    let r = refused(&mut p, "data,D,D0004,9LIVES,,\n");
    assert!(row(&r[0]).contains("not a valid symbol name"), "{r:?}");
}

#[test]
fn rows_check_would_refuse_on_their_own_are_refused() {
    let mut p = Project {
        profile: ProfileId::Gsk980,
        ..Project::default()
    };
    let r = refused(&mut p, "message,,A0030.0,1001,甲,a\nsymbol,,L0001,LOOP,,\n");
    assert_eq!(r.len(), 2, "{r:?}");
    assert_eq!(r[0].0, 2);
    assert!(
        row(&r[0]).contains("beyond this controller's A range"),
        "{r:?}"
    );
    assert_eq!(r[1].0, 3);
    assert!(row(&r[1]).contains("T007"), "{r:?}");
}

#[test]
fn an_import_that_leaves_the_errors_as_they_were_applies() {
    let mut p = Project::default();
    // An error the project already has is not the import's.
    p.messages.rows[1].number = Some(1001);
    p.messages.rows[2].number = Some(1001);
    let before = errors(&p);
    let csv = format!("{HEAD}message,,A0000.1,1001,甲,a\nsymbol,,X0002.1,START,启动,start\n");
    assert_eq!(import(&mut p, &csv, None).unwrap(), 2);
    assert_eq!(errors(&p), before);
    assert_eq!(p.messages.rows[1].texts["zh"], "甲");
    assert_eq!(MessageTable::address(1).to_string(), "A0000.1");
}
