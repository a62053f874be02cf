//! Find and replace over the ladder (manual §3.2.2): by address (every spelling of an address
//! is the same address, and a symbol standing for it counts too), symbol, constant or
//! instruction. Replace changes only operands where the result is valid.

use crate::address::Address;
use crate::catalog::Op;
use crate::compiler::operand_ok;
use crate::model::{Cell, CellRef, Edit, Operand, Project};

/// What to look for.
#[derive(Clone, Debug, PartialEq)]
pub enum Query {
    /// An address (and symbols that stand for it).
    Address(Address),
    /// A symbol name.
    Symbol(String),
    /// An integer constant.
    Const(i64),
    /// An instruction (coils and boxes).
    Instruction(Op),
}

impl Query {
    /// Reads what the user typed: an instruction name, an address, a constant or a symbol.
    pub fn parse(text: &str) -> Option<Query> {
        let t = text.trim();
        if let Some(op) = Op::from_name(t) {
            return Some(Query::Instruction(op));
        }
        match Operand::parse(t).ok()? {
            Operand::Addr(a) => Some(Query::Address(a)),
            Operand::Int(v) => Some(Query::Const(v)),
            Operand::Symbol(s) => Some(Query::Symbol(s)),
            Operand::Real(_) => None,
        }
    }
}

fn operand_matches(project: &Project, q: &Query, o: &Operand) -> bool {
    match (q, o) {
        (Query::Address(a), Operand::Addr(b)) => a == b,
        (Query::Address(a), Operand::Symbol(s)) => project.resolve_symbol(s) == Some(*a),
        (Query::Symbol(s), Operand::Symbol(t)) => s == t,
        (Query::Symbol(s), Operand::Addr(b)) => project.resolve_symbol(s) == Some(*b),
        (Query::Const(v), Operand::Int(w)) => v == w,
        _ => false,
    }
}

/// Every cell that matches, in program order.
pub fn find(project: &Project, q: &Query) -> Vec<CellRef> {
    let mut hits = Vec::new();
    for (b, block) in project.ladder.blocks.iter().enumerate() {
        for (n, net) in block.networks.iter().enumerate() {
            for (r, row) in net.rows.iter().enumerate() {
                for (c, cell) in row.cells.iter().enumerate() {
                    let hit = match (q, cell) {
                        (Query::Instruction(op), _) => {
                            cell.output_instruction().is_some_and(|(o, _)| o == *op)
                        }
                        (_, Cell::Empty | Cell::Wire) => false,
                        _ => cell
                            .operands()
                            .iter()
                            .any(|o| operand_matches(project, q, o)),
                    };
                    if hit {
                        hits.push(CellRef {
                            block: b,
                            network: n,
                            row: r,
                            col: c,
                        });
                    }
                }
            }
        }
    }
    hits
}

/// One place a replace would change: the cell as it is, and as it would be — `None` when the
/// result would not be a valid operand there (a byte address in a contact, an X as a coil…).
#[derive(Clone, Debug, PartialEq)]
pub struct Planned {
    /// Where.
    pub at: CellRef,
    /// The cell now.
    pub before: Cell,
    /// The cell after the replace, or `None` where it is skipped.
    pub after: Option<Cell>,
}

impl Planned {
    /// The edit of this one place (none when skipped).
    pub fn edit(&self) -> Option<Edit> {
        self.after
            .clone()
            .map(|cell| Edit::SetCell { at: self.at, cell })
    }
}

/// Every place a replace of `from` by `to` would touch, in find order: what each cell would
/// become, or that it is skipped. Nothing is changed: the editor previews this list.
pub fn replace_plan(project: &Project, from: &Query, to: &Operand) -> Vec<Planned> {
    let profile = project.profile();
    let mut plan = Vec::new();
    for at in find(project, from) {
        let cell = &project.ladder.blocks[at.block].networks[at.network].rows[at.row].cells[at.col];
        let Some((op, operands)) = (match cell {
            Cell::Contact { negated, operand } => Some((
                if *negated { Op::Ldi } else { Op::Ld },
                vec![operand.clone()],
            )),
            other => other.output_instruction(),
        }) else {
            continue;
        };
        let mut new_operands = operands.clone();
        let mut changed = Vec::new();
        for (i, o) in operands.iter().enumerate() {
            if operand_matches(project, from, o) {
                new_operands[i] = to.clone();
                changed.push(i);
            }
        }
        let resolved: Vec<Operand> = new_operands
            .iter()
            .map(|o| match o {
                Operand::Symbol(s) => project.resolve_symbol(s).map_or(o.clone(), Operand::Addr),
                _ => o.clone(),
            })
            .collect();
        let valid = changed
            .iter()
            .all(|i| operand_ok(op, &resolved, *i, profile));
        let after = valid.then(|| {
            let mut new_cell = cell.clone();
            new_cell.operands_mut().clone_from_slice(&new_operands);
            new_cell
        });
        plan.push(Planned {
            at,
            before: cell.clone(),
            after,
        });
    }
    plan
}

/// The edit that replaces `from` by `to` wherever the result is a valid operand (one undo
/// step), how many places it changes, and how many it skips.
pub fn replace(project: &Project, from: &Query, to: &Operand) -> (Edit, usize, usize) {
    let plan = replace_plan(project, from, to);
    let edits: Vec<Edit> = plan.iter().filter_map(Planned::edit).collect();
    let count = edits.len();
    (Edit::Batch(edits), count, plan.len() - count)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_spelling_finds_the_address_and_replace_keeps_the_program_valid() {
        let p = crate::il::import(
            "LEVEL2\nNETWORK\nLD X0002.1\nOR Y0003.7\nANI X0002.2\nOUT Y0003.7\nNETWORK\nLD R0001.0\nMOVN 1 R0010 R0011\n",
        )
        .project
        .unwrap();
        let q = Query::parse("y3.7").unwrap();
        assert_eq!(find(&p, &q).len(), 2);
        assert_eq!(find(&p, &Query::parse("MOVN").unwrap()).len(), 1);
        // Y3.7 → Y4.0 everywhere; Y3.7 → X1.0 only where X may stand (not the coil).
        let (edit, n, skipped) = replace(&p, &q, &Operand::parse("Y4.0").unwrap());
        assert_eq!((n, skipped), (2, 0));
        let mut l = p.ladder.clone();
        l.apply(edit).unwrap();
        let (_, n, skipped) = replace(&p, &q, &Operand::parse("X1.0").unwrap());
        assert_eq!((n, skipped), (1, 1));
        let (_, n, skipped) = replace(
            &p,
            &Query::parse("R10").unwrap(),
            &Operand::parse("R10.1").unwrap(),
        );
        assert_eq!(
            (n, skipped),
            (0, 1),
            "a bit where MOVN needs a byte is refused"
        );
    }
}
