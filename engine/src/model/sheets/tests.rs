//! The per-language columns: each writes its own language's entry of a row's comment (or a
//! message's text) map and leaves the other languages alone.

use super::{Col, Sheet, TableError, cell_text, commit};
use crate::address::{Address, Area};
use crate::model::Project;
use crate::model::tables::LANGUAGES;
use crate::model::tables::{AddressRow, Comments, DataRow, MCodeRow, RealRow, Symbol};

/// Every row table that has per-language comments or texts.
const SHEETS: [Sheet; 9] = [
    Sheet::Symbols(0),
    Sheet::D,
    Sheet::DFloat,
    Sheet::Dt,
    Sheet::Dc,
    Sheet::Messages,
    Sheet::Diagnosis,
    Sheet::Permissions,
    Sheet::MCodes,
];

/// A project with one row in every table, commented in both languages.
fn project() -> Project {
    let both = || {
        Comments::from([
            ("zh".to_string(), "原注释".to_string()),
            ("en".to_string(), "old comment".to_string()),
        ])
    };
    let mut p = Project::default();
    p.symbol_tables[0].rows.push(Symbol {
        name: "START".into(),
        address: Address::bit(Area::R, 10, 1),
        comments: both(),
    });
    for (rows, area) in [
        (&mut p.data.d, Area::D),
        (&mut p.data.dt, Area::Dt),
        (&mut p.data.dc, Area::Dc),
    ] {
        let mut r = DataRow::new(Address::byte(area, 4), 0);
        r.comments = both();
        rows.push(r);
    }
    let mut r = RealRow::new(Address::byte(Area::D, 20), 0.0);
    r.comments = both();
    p.data.d_float.push(r);
    p.messages.rows[0].texts = both();
    for rows in [&mut p.diagnosis, &mut p.permissions] {
        rows.push(AddressRow {
            address: Address::bit(Area::K, 2, 1),
            comments: both(),
        });
    }
    p.m_codes.push(MCodeRow {
        code: 3,
        comments: both(),
    });
    p
}

/// The comment (message text) map of row 0 of a table, read from the model itself.
fn comments(p: &Project, sheet: Sheet) -> &Comments {
    match sheet {
        Sheet::Symbols(t) => &p.symbol_tables[t].rows[0].comments,
        Sheet::D => &p.data.d[0].comments,
        Sheet::Dt => &p.data.dt[0].comments,
        Sheet::Dc => &p.data.dc[0].comments,
        Sheet::DFloat => &p.data.d_float[0].comments,
        Sheet::Messages => &p.messages.rows[0].texts,
        Sheet::Diagnosis => &p.diagnosis[0].comments,
        Sheet::Permissions => &p.permissions[0].comments,
        Sheet::MCodes => &p.m_codes[0].comments,
    }
}

/// The column of `sheet` for language `lang`.
fn lang_col(sheet: Sheet, lang: &str) -> Col {
    *sheet
        .columns()
        .iter()
        .find(|c| c.lang() == Some(lang))
        .unwrap_or_else(|| panic!("{sheet:?} has a `{lang}` column"))
}

/// Types `text` into row 0 of a column and applies the edit, as the editor does on Enter.
fn enter(p: &mut Project, sheet: Sheet, col: Col, text: &str) -> Result<(), TableError> {
    if let Some(edit) = commit(p, sheet, 0, col, text)? {
        p.apply_table(edit);
    }
    Ok(())
}

fn get<'a>(c: &'a Comments, lang: &str) -> Option<&'a str> {
    c.get(lang).map(String::as_str)
}

#[test]
fn every_table_has_a_column_per_language_in_the_order_of_the_csv() {
    for sheet in SHEETS {
        let langs: Vec<_> = sheet.columns().iter().filter_map(|c| c.lang()).collect();
        assert_eq!(langs, LANGUAGES, "{sheet:?}");
        let kinds: Vec<_> = sheet
            .columns()
            .iter()
            .filter(|c| c.lang().is_some())
            .map(|c| matches!(c, Col::Text(_)))
            .collect();
        let texts = sheet == Sheet::Messages;
        assert!(
            kinds.iter().all(|k| *k == texts),
            "{sheet:?}: comments, or a message's texts"
        );
    }
}

#[test]
fn each_language_column_shows_its_own_language() {
    let p = project();
    for sheet in SHEETS {
        assert_eq!(cell_text(&p, sheet, 0, lang_col(sheet, "zh")), "原注释");
        assert_eq!(
            cell_text(&p, sheet, 0, lang_col(sheet, "en")),
            "old comment"
        );
        assert_eq!(
            cell_text(&p, sheet, 1, lang_col(sheet, "en")),
            "",
            "past the end"
        );
    }
}

#[test]
fn writing_one_language_column_changes_only_that_language() {
    for sheet in SHEETS {
        let mut p = project();
        enter(&mut p, sheet, lang_col(sheet, "zh"), " 新注释 ").unwrap();
        let c = comments(&p, sheet);
        assert_eq!(get(c, "zh"), Some("新注释"), "{sheet:?}: trimmed");
        assert_eq!(get(c, "en"), Some("old comment"), "{sheet:?}: en kept");

        let mut p = project();
        enter(&mut p, sheet, lang_col(sheet, "en"), "new comment").unwrap();
        let c = comments(&p, sheet);
        assert_eq!(get(c, "en"), Some("new comment"), "{sheet:?}");
        assert_eq!(get(c, "zh"), Some("原注释"), "{sheet:?}: zh kept");
        assert_eq!(c.len(), 2, "{sheet:?}: no other language appears");
    }
}

#[test]
fn clearing_one_language_leaves_the_other() {
    for sheet in SHEETS {
        let mut p = project();
        enter(&mut p, sheet, lang_col(sheet, "en"), "  ").unwrap();
        let c = comments(&p, sheet);
        assert_eq!(get(c, "en"), None, "{sheet:?}: en removed");
        assert_eq!(get(c, "zh"), Some("原注释"), "{sheet:?}");

        enter(&mut p, sheet, lang_col(sheet, "zh"), "").unwrap();
        assert!(comments(&p, sheet).is_empty(), "{sheet:?}: both gone");
        let before = p.clone();
        enter(&mut p, sheet, lang_col(sheet, "zh"), "").unwrap();
        assert_eq!(p, before, "{sheet:?}");
        assert_eq!(
            commit(&p, sheet, 0, lang_col(sheet, "zh"), ""),
            Ok(None),
            "{sheet:?}: clearing an empty cell is no edit"
        );
    }
}

#[test]
fn a_comment_too_long_is_refused_in_either_language() {
    let p = project();
    for sheet in SHEETS {
        if sheet == Sheet::Messages {
            continue; // A message's text is not held to the comment limit.
        }
        for lang in LANGUAGES {
            let e = commit(&p, sheet, 0, lang_col(sheet, lang), &"x".repeat(128));
            assert!(
                matches!(e, Err(TableError::CommentTooLong { .. })),
                "{sheet:?} {lang}: {e:?}"
            );
        }
    }
}

#[test]
fn a_column_the_table_does_not_have_takes_nothing() {
    let p = project();
    assert_eq!(
        commit(&p, Sheet::Messages, 0, Col::Comment("en"), "x"),
        Ok(None)
    );
    assert_eq!(cell_text(&p, Sheet::Messages, 0, Col::Comment("en")), "");
    assert_eq!(
        commit(&p, Sheet::Symbols(0), 0, Col::Text("en"), "x"),
        Ok(None)
    );
}
