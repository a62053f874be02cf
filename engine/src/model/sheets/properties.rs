//! Element properties: an address's symbol and comments edited from the ladder (a contact's
//! or coil's right-click menu, a double-click on its label), written into the symbol tables
//! as one undoable change, as GSKLadder's element properties do.

use super::TableError;
use super::rules::{check_symbol, check_symbol_area, set_comment};
use crate::address::Address;
use crate::model::tables::{Symbol, SymbolTable};
use crate::model::{Cell, CellRef, Change, Edit, Operand, Project, TableEdit};

/// The name of the symbol table a first symbol goes to when the project has none.
const FIRST_TABLE: &str = "Symbols";

/// What element properties set for an address: its symbol (empty for none) and its comment
/// in each language (empty removes it; up to three lines are shown under the element).
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Properties {
    /// The symbol.
    pub name: String,
    /// (language code, comment) pairs.
    pub comments: Vec<(String, String)>,
}

/// The address's properties as the symbol tables hold them now.
pub fn properties_of(project: &Project, address: Address, langs: &[&str]) -> Properties {
    let row = project.symbols().find(|s| s.address == address);
    Properties {
        name: row.map_or(String::new(), |s| s.name.clone()),
        comments: langs
            .iter()
            .map(|l| {
                let text = row
                    .and_then(|s| s.comments.get(*l))
                    .cloned()
                    .unwrap_or_default();
                (l.to_string(), text)
            })
            .collect(),
    }
}

/// The change that gives `address` these properties: its symbol-table row updated (or added
/// to the first table, or removed when nothing is left in it), and, when its symbol is
/// renamed, every element written with the old name rewritten with the new one (or with the
/// address, when the symbol is cleared), so the ladder keeps meaning the same. One change:
/// one undo step.
pub fn plan_properties(
    project: &Project,
    address: Address,
    props: &Properties,
) -> Result<Change, TableError> {
    let name = props.name.trim();
    let mut tables = project.symbol_tables.clone();
    let at = tables.iter().enumerate().find_map(|(t, table)| {
        let r = table.rows.iter().position(|s| s.address == address)?;
        Some((t, r))
    });
    check_symbol(project, name, at)?;
    if !name.is_empty() {
        check_symbol_area(address)?;
    }
    let mut row = at.map_or_else(
        || Symbol {
            name: String::new(),
            address,
            comments: Default::default(),
        },
        |(t, r)| tables[t].rows[r].clone(),
    );
    let old = std::mem::replace(&mut row.name, name.to_string());
    for (lang, text) in &props.comments {
        set_comment(&mut row.comments, lang, text, true)?;
    }
    let empty = row.name.is_empty() && row.comments.is_empty();
    match at {
        Some((t, r)) if empty => {
            tables[t].rows.remove(r);
        }
        Some((t, r)) => tables[t].rows[r] = row,
        None if empty => {}
        None => {
            if tables.is_empty() {
                tables.push(SymbolTable {
                    name: FIRST_TABLE.into(),
                    rows: Vec::new(),
                });
            }
            tables[0].rows.push(row);
        }
    }
    let mut changes = vec![Change::Table(TableEdit::Symbols(tables))];
    if !old.is_empty() && old != name {
        let new = if name.is_empty() {
            Operand::Addr(address)
        } else {
            Operand::Symbol(name.to_string())
        };
        changes.extend(
            renamed_cells(project, &old, &new)
                .into_iter()
                .map(Change::Ladder),
        );
    }
    Ok(match changes.len() {
        1 => changes.remove(0),
        _ => Change::Batch(changes),
    })
}

/// Every element that writes symbol `old`, rewritten with `new`.
fn renamed_cells(project: &Project, old: &str, new: &Operand) -> Vec<Edit> {
    let swap = |o: &Operand| match o {
        Operand::Symbol(s) if s == old => Some(new.clone()),
        _ => None,
    };
    let mut edits = Vec::new();
    for (b, block) in project.ladder.blocks.iter().enumerate() {
        for (n, net) in block.networks.iter().enumerate() {
            for (r, row) in net.rows.iter().enumerate() {
                for (c, cell) in row.cells.iter().enumerate() {
                    let renamed = match cell {
                        Cell::Contact { negated, operand } => {
                            swap(operand).map(|operand| Cell::Contact {
                                negated: *negated,
                                operand,
                            })
                        }
                        Cell::Coil { negated, operand } => {
                            swap(operand).map(|operand| Cell::Coil {
                                negated: *negated,
                                operand,
                            })
                        }
                        Cell::Box { op, operands }
                            if operands.iter().any(|o| swap(o).is_some()) =>
                        {
                            Some(Cell::Box {
                                op: *op,
                                operands: operands
                                    .iter()
                                    .map(|o| swap(o).unwrap_or_else(|| o.clone()))
                                    .collect(),
                            })
                        }
                        _ => None,
                    };
                    if let Some(cell) = renamed {
                        let at = CellRef {
                            block: b,
                            network: n,
                            row: r,
                            col: c,
                        };
                        edits.push(Edit::SetCell { at, cell });
                    }
                }
            }
        }
    }
    edits
}

#[cfg(test)]
mod tests {
    use super::*;

    fn project() -> Project {
        let list = "LEVEL1\nNETWORK\nLD X0002.1\nOUT Y0003.7\nLEVEL2\n";
        let mut p = crate::il::import(list).project.expect("draws");
        p.symbol_tables[0].rows.push(Symbol {
            name: "START".into(),
            address: Address::parse("X0002.1").unwrap(),
            comments: [("en".to_string(), "Start".to_string())].into(),
        });
        p
    }

    fn apply(p: &mut Project, change: Change) {
        p.apply_change(change).expect("applies");
    }

    #[test]
    fn a_new_symbol_and_comments_go_to_the_first_table_in_one_change() {
        let mut p = project();
        let y = Address::parse("Y0003.7").unwrap();
        let props = Properties {
            name: "LAMP".into(),
            comments: vec![
                ("zh".into(), "指示灯".into()),
                ("en".into(), "Lamp\nsecond line".into()),
            ],
        };
        let change = plan_properties(&p, y, &props).unwrap();
        assert!(matches!(change, Change::Table(_)), "one table change");
        apply(&mut p, change);
        assert_eq!(p.resolve_symbol("LAMP"), Some(y));
        assert_eq!(p.comment_of(y, "en"), Some("Lamp\nsecond line"));
        assert_eq!(properties_of(&p, y, &["zh"]).comments[0].1, "指示灯");
    }

    #[test]
    fn renaming_rewrites_the_elements_written_with_the_old_name() {
        let mut p = project();
        let x = Address::parse("X0002.1").unwrap();
        p.ladder.blocks[0].networks[0].rows[0].cells[0] = Cell::Contact {
            negated: false,
            operand: Operand::Symbol("START".into()),
        };
        let props = Properties {
            name: "GO".into(),
            comments: vec![],
        };
        let change = plan_properties(&p, x, &props).unwrap();
        apply(&mut p, change);
        assert_eq!(
            p.ladder.blocks[0].networks[0].rows[0].cells[0],
            Cell::Contact {
                negated: false,
                operand: Operand::Symbol("GO".into())
            }
        );
        assert_eq!(p.comment_of(x, "en"), Some("Start"), "comments kept");
    }

    #[test]
    fn a_taken_or_malformed_name_is_refused_and_an_emptied_row_goes() {
        let p = project();
        let y = Address::parse("Y0003.7").unwrap();
        let named = |n: &str| Properties {
            name: n.into(),
            comments: vec![],
        };
        assert!(matches!(
            plan_properties(&p, y, &named("START")),
            Err(TableError::SymbolTwice { .. })
        ));
        assert!(matches!(
            plan_properties(&p, y, &named("X1")),
            Err(TableError::SymbolName { .. })
        ));
        let x = Address::parse("X0002.1").unwrap();
        let mut q = p.clone();
        let clear = Properties {
            name: String::new(),
            comments: vec![("en".into(), String::new())],
        };
        apply(&mut q, plan_properties(&p, x, &clear).unwrap());
        assert!(q.symbols().all(|s| s.address != x));
    }
}
