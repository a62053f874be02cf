//! Comments as CSV (docs/files.md, "Comments CSV"): symbols, network
//! comments, messages and the other tables' comments, one column per language.
//!
//! Columns: `kind,table,key,symbol,<lang>…`. `kind` is `symbol` (table: the symbol table),
//! `network` (table: LEVEL1/LEVEL2/P0001, key: network number, symbol: its title), `message`
//! (key: the A bit, symbol: the alarm number), `data` (table: D/DT/DC/D_FLOAT), `diagnosis`,
//! `permission` or `mcode` (key: the M code). Import changes nothing unless every row applies
//! and the result gives `check` no error it did not have before.

mod guard;

use crate::address::Address;
use crate::compiler::Diagnostic;
use crate::model::sheets::{check_symbol_area, check_symbol_form};
use crate::model::tables::{Comments, MessageTable, Symbol, SymbolTable, message_rows};
use crate::model::{Operand, Project, is_symbol_name};
use guard::{Target, Touch};
use thiserror::Error;

pub use crate::model::tables::LANGUAGES;

/// Why a comments file could not be imported.
#[derive(Debug, Error)]
pub enum CommentsError {
    /// The CSV itself is malformed.
    #[error("line {line}: {message}")]
    Csv {
        /// Line.
        line: u64,
        /// What the CSV reader said.
        message: String,
    },
    /// The header does not name the columns the import needs.
    #[error("line 1: the header must name the columns kind,table,key,symbol and one per language")]
    Header,
    /// Some rows cannot be applied, each at its CSV line; nothing was changed.
    #[error("{} row(s) rejected, nothing changed", .0.len())]
    Rejected(Vec<(u64, Rejection)>),
}

/// Why one row of a comments file is refused.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub enum Rejection {
    /// The row does not read, or names what the project cannot take. The reason quotes the
    /// CSV and stays in English (docs/files.md, "Comments CSV").
    Row(String),
    /// Applied, the rows would leave `check` this error, which the project did not have.
    WouldBreak(Diagnostic),
}

fn lang_columns(lang: Option<&str>) -> Vec<String> {
    match lang {
        Some(l) => vec![l.to_string()],
        None => LANGUAGES.iter().map(|s| s.to_string()).collect(),
    }
}

/// Writes a project's comments as CSV (all languages, or one).
pub fn export(project: &Project, lang: Option<&str>) -> String {
    let langs = lang_columns(lang);
    let mut w = csv::Writer::from_writer(Vec::new());
    let mut header = vec![
        "kind".to_string(),
        "table".into(),
        "key".into(),
        "symbol".into(),
    ];
    header.extend(langs.iter().cloned());
    let _ = w.write_record(&header);
    let mut row = |kind: &str, table: &str, key: String, symbol: &str, comments: &Comments| {
        let mut r = vec![kind.to_string(), table.to_string(), key, symbol.to_string()];
        r.extend(
            langs
                .iter()
                .map(|l| comments.get(l).cloned().unwrap_or_default()),
        );
        let _ = w.write_record(&r);
    };
    for t in &project.symbol_tables {
        for s in &t.rows {
            row(
                "symbol",
                &t.name,
                s.address.to_string(),
                &s.name,
                &s.comments,
            );
        }
    }
    for b in &project.ladder.blocks {
        for (n, net) in b.networks.iter().enumerate() {
            if !net.title.is_empty() || !net.comments.is_empty() {
                row(
                    "network",
                    &b.kind.label(),
                    (n + 1).to_string(),
                    &net.title,
                    &net.comments,
                );
            }
        }
    }
    for (k, m) in project.messages.rows.iter().enumerate() {
        if m.number.is_some() || !m.texts.is_empty() {
            let number = m.number.map(|n| n.to_string()).unwrap_or_default();
            row(
                "message",
                "",
                MessageTable::address(k).to_string(),
                &number,
                &m.texts,
            );
        }
    }
    let d = &project.data;
    for (table, rows) in [("D", &d.d), ("DT", &d.dt), ("DC", &d.dc)] {
        for r in rows {
            row("data", table, r.address.to_string(), &r.symbol, &r.comments);
        }
    }
    for r in &d.d_float {
        row(
            "data",
            "D_FLOAT",
            r.address.to_string(),
            &r.symbol,
            &r.comments,
        );
    }
    for r in &project.diagnosis {
        row("diagnosis", "", r.address.to_string(), "", &r.comments);
    }
    for r in &project.permissions {
        row("permission", "", r.address.to_string(), "", &r.comments);
    }
    for r in &project.m_codes {
        row("mcode", "", format!("M{:02}", r.code), "", &r.comments);
    }
    String::from_utf8(w.into_inner().unwrap_or_default()).unwrap_or_default()
}

fn set_langs(target: &mut Comments, langs: &[(String, String)]) {
    for (l, text) in langs {
        if text.is_empty() {
            target.remove(l);
        } else {
            target.insert(l.clone(), text.clone());
        }
    }
}

/// Applies a comments CSV to a project: all rows or none. `lang` limits the import to one
/// language column.
pub fn import(
    project: &mut Project,
    csv_text: &str,
    lang: Option<&str>,
) -> Result<usize, CommentsError> {
    let mut reader = csv::ReaderBuilder::new()
        .flexible(false)
        .from_reader(csv_text.as_bytes());
    let headers = reader
        .headers()
        .map_err(|e| CommentsError::Csv {
            line: 1,
            message: e.to_string(),
        })?
        .clone();
    let col = |name: &str| headers.iter().position(|h| h.trim() == name);
    let (Some(kind_c), Some(table_c), Some(key_c), Some(symbol_c)) =
        (col("kind"), col("table"), col("key"), col("symbol"))
    else {
        return Err(CommentsError::Header);
    };
    let lang_cols: Vec<(String, usize)> = headers
        .iter()
        .enumerate()
        .filter(|(i, _)| ![kind_c, table_c, key_c, symbol_c].contains(i))
        .map(|(i, h)| (h.trim().to_string(), i))
        .filter(|(h, _)| lang.is_none_or(|l| l == h))
        .collect();
    let mut work = project.clone();
    let mut rejected = Vec::new();
    let mut touches = Vec::new();
    for record in reader.records() {
        let record = record.map_err(|e| CommentsError::Csv {
            line: e.position().map_or(0, |p| p.line()),
            message: e.to_string(),
        })?;
        let line = record.position().map_or(0, |p| p.line());
        let get = |i: usize| record.get(i).unwrap_or("").trim().to_string();
        let langs: Vec<(String, String)> = lang_cols
            .iter()
            .map(|(l, i)| (l.clone(), get(*i)))
            .collect();
        match apply_row(
            &mut work,
            &get(kind_c),
            &get(table_c),
            &get(key_c),
            &get(symbol_c),
            &langs,
        ) {
            Ok((target, names)) => touches.push(Touch {
                line,
                target,
                names,
            }),
            Err(m) => rejected.push((line, Rejection::Row(m))),
        }
    }
    if rejected.is_empty() {
        rejected = guard::refusals(project, &work, &touches);
    }
    if !rejected.is_empty() {
        rejected.sort_by_key(|(line, _)| *line);
        rejected.dedup();
        return Err(CommentsError::Rejected(rejected));
    }
    *project = work;
    Ok(touches.len())
}

fn address(key: &str) -> Result<Address, String> {
    Address::parse(key).map_err(|e| e.to_string())
}

/// What applying one row gives: the place it changed, with the names it gave or took away
/// (for the guard's checks), or why it cannot apply.
type Applied = Result<(Target, Vec<String>), String>;

/// Applies one row: what it changed, with the names it gave or took away, or why it cannot
/// apply.
fn apply_row(
    p: &mut Project,
    kind: &str,
    table: &str,
    key: &str,
    symbol: &str,
    langs: &[(String, String)],
) -> Applied {
    match kind {
        "symbol" => apply_symbol(p, table, key, symbol, langs),
        "network" => apply_network(p, table, key, symbol, langs),
        "message" => apply_message(p, key, symbol, langs),
        "data" => apply_data(p, table, key, symbol, langs),
        "diagnosis" | "permission" => apply_address_row(p, kind, key, langs),
        "mcode" => apply_m_code(p, key, langs),
        other => Err(format!(
            "unknown kind `{other}` (symbol, network, message, data, diagnosis, permission, mcode)"
        )),
    }
}

/// A `symbol` row: the symbol and comments of an address in a symbol table, the row (and
/// the table) made when missing. The name must be one `check` accepts, and the area one
/// that takes symbols, so the import brings in no T001 or T007.
fn apply_symbol(
    p: &mut Project,
    table: &str,
    key: &str,
    symbol: &str,
    langs: &[(String, String)],
) -> Applied {
    let a = Address::parse_in(key, p.profile()).map_err(|e| e.to_string())?;
    if !symbol.is_empty()
        && (!is_symbol_name(symbol) || matches!(Operand::parse(symbol), Ok(Operand::Addr(_))))
    {
        return Err(format!("`{symbol}` is not a valid symbol name"));
    }
    check_symbol_area(a).map_err(|e| {
        format!("{e}: labels have no symbols, and a subprogram is named in its block (T007)")
    })?;
    let name = if table.is_empty() {
        "符号表1"
    } else {
        table
    };
    if name == crate::model::tables::BLOCK_SYMBOLS {
        return Err(
            "the block-symbol table is derived from the subprograms; rename the subprogram instead"
                .into(),
        );
    }
    let t = match p.symbol_tables.iter().position(|t| t.name == name) {
        Some(i) => i,
        None => {
            p.symbol_tables.push(SymbolTable {
                name: name.to_string(),
                rows: Vec::new(),
            });
            p.symbol_tables.len() - 1
        }
    };
    let rows = &mut p.symbol_tables[t].rows;
    let r = rows.iter().position(|s| s.address == a).unwrap_or_else(|| {
        rows.push(Symbol {
            name: String::new(),
            address: a,
            comments: Comments::new(),
        });
        rows.len() - 1
    });
    let row = &mut rows[r];
    let old = std::mem::replace(&mut row.name, symbol.to_string());
    set_langs(&mut row.comments, langs);
    Ok((
        Target::Symbol { table: t, row: r },
        vec![old, symbol.into()],
    ))
}

/// A `network` row: the title (the symbol column) and comments of an existing network,
/// numbered from 1 in its block.
fn apply_network(
    p: &mut Project,
    table: &str,
    key: &str,
    symbol: &str,
    langs: &[(String, String)],
) -> Applied {
    let block = p
        .ladder
        .blocks
        .iter_mut()
        .find(|b| b.kind.label() == table)
        .ok_or_else(|| format!("there is no block `{table}` (LEVEL1, LEVEL2 or P0001…)"))?;
    let n: usize = key
        .parse()
        .map_err(|_| format!("`{key}` is not a network number"))?;
    let net = n
        .checked_sub(1)
        .and_then(|i| block.networks.get_mut(i))
        .ok_or_else(|| format!("{table} has no network {n}"))?;
    net.title = symbol.to_string();
    set_langs(&mut net.comments, langs);
    Ok((Target::Other, Vec::new()))
}

/// A `message` row: the alarm number (the symbol column) and texts of an A bit within this
/// controller's range, since `check` refuses a row beyond it.
fn apply_message(p: &mut Project, key: &str, symbol: &str, langs: &[(String, String)]) -> Applied {
    let a = address(key)?;
    let k =
        MessageTable::row_of(a).ok_or_else(|| format!("{a} is not a message row (an A bit)"))?;
    let rows = message_rows(p.profile());
    if k >= rows {
        return Err(format!(
            "{a} is beyond this controller's A range (A0000.0–{}), which `check` refuses (T005): use an A bit of that range",
            MessageTable::address(rows - 1)
        ));
    }
    let number = if symbol.is_empty() {
        None
    } else {
        Some(
            symbol
                .parse::<u16>()
                .ok()
                .filter(|n| (1000..=9999).contains(n))
                .ok_or_else(|| format!("alarm number `{symbol}` is not 1000–9999"))?,
        )
    };
    let m = p
        .messages
        .rows
        .get_mut(k)
        .ok_or_else(|| format!("{a} is not a message row"))?;
    let old = std::mem::replace(&mut m.number, number);
    set_langs(&mut m.texts, langs);
    let names = [old, number]
        .into_iter()
        .flatten()
        .map(|n| n.to_string())
        .collect();
    Ok((Target::Message(k), names))
}

/// A `data` row: the symbol and comments of a row already in a data table; the symbol's
/// form is checked here, the rest of what `check` would refuse by the guard once every row
/// has applied.
fn apply_data(
    p: &mut Project,
    table: &str,
    key: &str,
    symbol: &str,
    langs: &[(String, String)],
) -> Applied {
    let a = address(key)?;
    if !symbol.is_empty() && check_symbol_form(symbol).is_err() {
        return Err(format!(
            "`{symbol}` is not a valid symbol name, which `check` refuses (T001)"
        ));
    }
    let d = &mut p.data;
    // The table's number as `check` counts the data tables: 0 D, 1 DT, 2 DC, 3 D_FLOAT.
    let (n, found) = match table {
        "D_FLOAT" => (
            3,
            d.d_float
                .iter_mut()
                .enumerate()
                .find(|(_, r)| r.address == a)
                .map(|(i, r)| (i, &mut r.symbol, &mut r.comments)),
        ),
        "D" | "DT" | "DC" => {
            let (n, rows) = match table {
                "D" => (0, &mut d.d),
                "DT" => (1, &mut d.dt),
                _ => (2, &mut d.dc),
            };
            (
                n,
                rows.iter_mut()
                    .enumerate()
                    .find(|(_, r)| r.address == a)
                    .map(|(i, r)| (i, &mut r.symbol, &mut r.comments)),
            )
        }
        _ => {
            return Err(format!(
                "`{table}` is not a data table (D, D_FLOAT, DT, DC)"
            ));
        }
    };
    let (r, sym, comments) = found.ok_or_else(|| {
        format!("the {table} table has no row {a}; add the row in the table first")
    })?;
    let old = std::mem::replace(sym, symbol.to_string());
    set_langs(comments, langs);
    Ok((Target::Data { table: n, row: r }, vec![old, symbol.into()]))
}

/// A `diagnosis` or `permission` row (`kind` says which): the comments of an existing row.
fn apply_address_row(
    p: &mut Project,
    kind: &str,
    key: &str,
    langs: &[(String, String)],
) -> Applied {
    let a = address(key)?;
    let rows = if kind == "diagnosis" {
        &mut p.diagnosis
    } else {
        &mut p.permissions
    };
    let row = rows
        .iter_mut()
        .find(|r| r.address == a)
        .ok_or_else(|| format!("the {kind} table has no row {a}"))?;
    set_langs(&mut row.comments, langs);
    Ok((Target::Other, Vec::new()))
}

/// An `mcode` row: the comments of an existing M code, written `M03` or `3`.
fn apply_m_code(p: &mut Project, key: &str, langs: &[(String, String)]) -> Applied {
    let code: u32 = key
        .trim_start_matches(['M', 'm'])
        .parse()
        .map_err(|_| format!("`{key}` is not an M code"))?;
    let row = p
        .m_codes
        .iter_mut()
        .find(|r| r.code == code)
        .ok_or_else(|| format!("the M-code table has no M{code:02}"))?;
    set_langs(&mut row.comments, langs);
    Ok((Target::Other, Vec::new()))
}

#[cfg(test)]
mod tests;
