//! What an import must not do: leave the project with an error that `check` did not find
//! before. Rows are applied one by one, so a clash between two of them, or between a row and
//! the project, shows only once all are applied; this looks at the result and names the CSV
//! line to correct.
//!
//! Symbols and alarm numbers given twice are found here with their own message; anything
//! else `check` would newly reject (a renamed symbol the ladder still uses, a data row's
//! symbol that a symbol table gives another address, …) is found by compiling the project
//! before and after, and put on the line that changed the place the diagnostic points at, or
//! that names what it names.

use super::Rejection;
use crate::compiler::{Diagnostic, Severity, compile};
use crate::model::Project;
use crate::model::tables::MessageTable;
use std::collections::HashMap;

/// The place in the project a CSV row changed.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Target {
    /// Row `row` of symbol table `table` (indexes in the project after the import).
    Symbol {
        /// The table.
        table: usize,
        /// The row.
        row: usize,
    },
    /// Row `row` of data table `table` (0 D, 1 DT, 2 DC, 3 D_FLOAT, as `check` numbers them).
    Data {
        /// The table.
        table: usize,
        /// The row.
        row: usize,
    },
    /// Message row `k` (the A bit's index).
    Message(usize),
    /// A place no check looks at for errors (a network's title, a table's comments).
    Other,
}

/// One applied CSV row: its line, what it changed, and the names it gave or took away (a
/// symbol's old and new name, an alarm number), for a diagnostic that names them.
#[derive(Clone, Debug)]
pub(super) struct Touch {
    /// The CSV line.
    pub line: u64,
    /// What it changed.
    pub target: Target,
    /// Names a diagnostic could quote.
    pub names: Vec<String>,
}

/// The errors of a project, each with how often it occurs.
fn errors(project: &Project) -> HashMap<Diagnostic, usize> {
    let mut found = HashMap::new();
    for d in compile(project).diagnostics {
        if d.severity() == Severity::Error {
            *found.entry(d).or_insert(0) += 1;
        }
    }
    found
}

/// The rows that changed `target`.
fn setters(touches: &[Touch], target: Target) -> impl Iterator<Item = &Touch> {
    touches.iter().filter(move |t| t.target == target)
}

/// Symbols given to two rows: the line of each row the import set, naming the other row.
fn symbols_twice(before: &Project, after: &Project, touches: &[Touch]) -> Vec<(u64, Rejection)> {
    let name_before = |t: usize, r: usize| {
        before
            .symbol_tables
            .get(t)
            .and_then(|table| table.rows.get(r))
            .map(|s| s.name.as_str())
    };
    let mut first: HashMap<&str, (usize, usize)> = HashMap::new();
    let mut found = Vec::new();
    for (t, table) in after.symbol_tables.iter().enumerate() {
        for (r, s) in table.rows.iter().enumerate() {
            if s.name.is_empty() {
                continue;
            }
            let Some(&(pt, pr)) = first.get(s.name.as_str()) else {
                first.insert(&s.name, (t, r));
                continue;
            };
            // Two rows that had the name before are the project's error, not the import's.
            if name_before(t, r) == Some(&s.name) && name_before(pt, pr) == Some(&s.name) {
                continue;
            }
            let other = &after.symbol_tables[pt];
            let here = Target::Symbol { table: t, row: r };
            let there = Target::Symbol { table: pt, row: pr };
            // The row the import named is the one to correct; with both named by it, the later.
            let line = setters(touches, here)
                .chain(setters(touches, there))
                .map(|t| t.line)
                .next();
            if let Some(line) = line {
                found.push((
                    line,
                    Rejection::Row(format!(
                        "symbol `{}` would be defined twice, for {} ({} row {}) and {} ({} row {}), which `check` refuses (T002): give one of them another name",
                        s.name,
                        other.rows[pr].address,
                        other.name,
                        pr + 1,
                        s.address,
                        table.name,
                        r + 1
                    )),
                ));
            }
        }
    }
    found
}

/// Alarm numbers given to two A bits: the line of each message row the import set.
fn alarms_twice(before: &Project, after: &Project, touches: &[Touch]) -> Vec<(u64, Rejection)> {
    let number_before = |k: usize| before.messages.rows.get(k).and_then(|m| m.number);
    let mut first: HashMap<u16, usize> = HashMap::new();
    let mut found = Vec::new();
    for (k, m) in after.messages.rows.iter().enumerate() {
        let Some(n) = m.number else { continue };
        let Some(&prev) = first.get(&n) else {
            first.insert(n, k);
            continue;
        };
        if number_before(k) == Some(n) && number_before(prev) == Some(n) {
            continue;
        }
        let line = setters(touches, Target::Message(k))
            .chain(setters(touches, Target::Message(prev)))
            .map(|t| t.line)
            .next();
        if let Some(line) = line {
            found.push((
                line,
                Rejection::Row(format!(
                    "alarm number {n} would be used by both {} and {}, which `check` refuses (T005): give each alarm its own number (1000–9999)",
                    MessageTable::address(prev),
                    MessageTable::address(k)
                )),
            ));
        }
    }
    found
}

/// The target a table diagnostic points at, in the numbering of [`Target`].
fn target_of(d: &Diagnostic) -> Option<Target> {
    let crate::compiler::Origin::Cell { row, .. } = d.location.origin else {
        return None;
    };
    let (table, row) = (d.location.network, row as usize);
    match d.location.block_label.as_str() {
        "SYMBOLS" => Some(Target::Symbol { table, row }),
        "DATA" => Some(Target::Data { table, row }),
        "MESSAGES" => Some(Target::Message(row)),
        _ => None,
    }
}

/// The CSV line a new error comes from: the row that changed its place, else the row that
/// gave or took a name it quotes, else none (line 0).
fn line_of(d: &Diagnostic, touches: &[Touch]) -> u64 {
    let at = target_of(d);
    // The finding's data, as `Debug` writes it, holds every name and number it quotes.
    let quoted = format!("{:?}", d.finding);
    touches
        .iter()
        .rev()
        .find(|t| Some(t.target) == at)
        .or_else(|| {
            touches.iter().rev().find(|t| {
                t.names
                    .iter()
                    .filter(|n| !n.is_empty())
                    .any(|n| quoted.contains(&format!("\"{n}\"")) || mentions(&quoted, n))
            })
        })
        .map_or(0, |t| t.line)
}

/// Whether `text` has `word` standing alone (an alarm number, not part of another number).
fn mentions(text: &str, word: &str) -> bool {
    text.split(|c: char| !c.is_ascii_alphanumeric())
        .any(|w| w == word)
}

/// What the import would break, by CSV line; empty when `after` has no error that `before`
/// lacks.
pub(super) fn refusals(
    before: &Project,
    after: &Project,
    touches: &[Touch],
) -> Vec<(u64, Rejection)> {
    let mut found = symbols_twice(before, after, touches);
    found.extend(alarms_twice(before, after, touches));
    if !found.is_empty() {
        return found;
    }
    let mut known = errors(before);
    let mut new: Vec<Diagnostic> = Vec::new();
    for d in compile(after).diagnostics {
        if d.severity() != Severity::Error {
            continue;
        }
        match known.get_mut(&d) {
            Some(n) if *n > 0 => *n -= 1,
            _ => new.push(d),
        }
    }
    new.into_iter()
        .map(|d| (line_of(&d, touches), Rejection::WouldBreak(d)))
        .collect()
}
