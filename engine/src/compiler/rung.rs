//! The rung tree: the logic of a network as series/parallel expressions and branch points.
//!
//! Both directions meet here. The compiler reduces a grid to rung trees and emits IL from
//! them; the IL importer rebuilds rung trees from IL and lays them out as a grid. Because
//! both go through the same tree and the same emitter, ladder → IL → ladder → IL is a fixed
//! point.

use super::diag::Origin;
use crate::catalog::Op;
use crate::model::Operand;

/// A series/parallel expression of contacts.
///
/// Invariant (kept by [`and`] and [`or`]): an `And` holds no `And`, an `Or` holds no `Or`,
/// and each holds at least two terms.
#[derive(Clone, Debug, PartialEq)]
pub enum Expr {
    /// A contact.
    Contact {
        /// Normally closed.
        negated: bool,
        /// The bit read.
        operand: Operand,
        /// Where it came from.
        origin: Origin,
    },
    /// Terms in series, left to right.
    And(Terms),
    /// Terms in parallel, top to bottom.
    Or(Terms),
}

/// The terms of a series or parallel expression. A deque, so that joining a term at either
/// end is cheap (see [`or`]).
pub type Terms = std::collections::VecDeque<Expr>;

/// Series combination, flattening nested series.
pub fn and(a: Expr, b: Expr) -> Expr {
    Expr::And(join(a, b, |e| match e {
        Expr::And(v) => Ok(v),
        other => Err(other),
    }))
}

/// Parallel combination, flattening nested parallels.
pub fn or(a: Expr, b: Expr) -> Expr {
    Expr::Or(join(a, b, |e| match e {
        Expr::Or(v) => Ok(v),
        other => Err(other),
    }))
}

/// The terms of `a` then `b`, each opened into its terms when `open` says it is a list of the
/// same kind. The longer list takes in the shorter one at its front or back, so a chain built
/// from either end (`LD a … LD z` then `ORB`s, or `LD a / OR b / OR c …`) costs time linear in
/// its length rather than copying the growing list at every step.
fn join(a: Expr, b: Expr, open: impl Fn(Expr) -> Result<Terms, Expr>) -> Terms {
    match (open(a), open(b)) {
        (Ok(mut x), Ok(mut y)) => {
            if x.len() >= y.len() {
                x.append(&mut y);
                x
            } else {
                while let Some(t) = x.pop_back() {
                    y.push_front(t);
                }
                y
            }
        }
        (Ok(mut x), Err(b)) => {
            x.push_back(b);
            x
        }
        (Err(a), Ok(mut y)) => {
            y.push_front(a);
            y
        }
        (Err(a), Err(b)) => Terms::from([a, b]),
    }
}

/// An output instruction: a coil (OUT/OUTN) or a function box.
#[derive(Clone, Debug, PartialEq)]
pub struct Output {
    /// The instruction.
    pub op: Op,
    /// Its operands.
    pub operands: Vec<Operand>,
    /// Where it came from.
    pub origin: Origin,
}

/// A point of the rung where power is known: what hangs off it, top to bottom.
#[derive(Clone, Debug, PartialEq, Default)]
pub struct Node {
    /// Outputs and further branches in row order.
    pub items: Vec<Item>,
}

/// One thing hanging off a node.
#[derive(Clone, Debug, PartialEq)]
pub enum Item {
    /// An output driven by the node's power.
    Output(Output),
    /// A series expression leading to a further node.
    Branch(Expr, Node),
}

/// One rung of a network.
#[derive(Clone, Debug, PartialEq)]
pub enum Rung {
    /// Contacts from the rail to a node.
    Powered(Expr, Node),
    /// An instruction that stands alone without contacts (LBL, CALLU).
    Standalone(Output),
}

/// An instruction of an instruction list, with where it came from.
#[derive(Clone, Debug, PartialEq)]
pub struct Instr {
    /// The opcode.
    pub op: Op,
    /// Operands in IL order.
    pub operands: Vec<Operand>,
    /// Grid cell or IL line.
    pub origin: Origin,
}

impl Instr {
    fn new(op: Op, operands: Vec<Operand>, origin: Origin) -> Instr {
        Instr {
            op,
            operands,
            origin,
        }
    }
}

/// Emits the instruction list of some rungs, the way a GSK programmer writes it: LD/AND/OR
/// chains, ORB/ANB for blocks, outputs in parallel without MPS, MPS/MRD/MPP at branch points.
pub fn emit(rungs: &[Rung], out: &mut Vec<Instr>) {
    for rung in rungs {
        match rung {
            Rung::Powered(expr, node) => {
                emit_load(expr, out);
                emit_node(node, out);
            }
            Rung::Standalone(o) => emit_output(o, out),
        }
    }
}

fn emit_output(o: &Output, out: &mut Vec<Instr>) {
    out.push(Instr::new(o.op, o.operands.clone(), o.origin));
}

/// Whether `emit_and(e)` begins with LD/LDI (a parallel block first).
fn and_starts_with_load(e: &Expr) -> bool {
    match e {
        Expr::Contact { .. } => false,
        Expr::Or(_) => true,
        Expr::And(terms) => and_starts_with_load(&terms[0]),
    }
}

fn emit_node(node: &Node, out: &mut Vec<Instr>) {
    let mut leading = node
        .items
        .iter()
        .take_while(|i| matches!(i, Item::Output(_)))
        .count();
    // An LD right after an output starts a new rung in IL, so a lone branch that opens with a
    // parallel block goes under MPS/MPP together with the outputs before it.
    if let [Item::Branch(e, _)] = &node.items[leading..]
        && leading > 0
        && and_starts_with_load(e)
    {
        leading = 0;
    }
    for item in &node.items[..leading] {
        if let Item::Output(o) = item {
            emit_output(o, out);
        }
    }
    let rest = &node.items[leading..];
    if rest.len() == 1 {
        if let Item::Branch(e, child) = &rest[0] {
            emit_and(e, out);
            emit_node(child, out);
        }
        return;
    }
    for (k, item) in rest.iter().enumerate() {
        let stack_op = if k == 0 {
            Op::Mps
        } else if k + 1 == rest.len() {
            Op::Mpp
        } else {
            Op::Mrd
        };
        out.push(Instr::new(stack_op, Vec::new(), Origin::None));
        match item {
            Item::Output(o) => emit_output(o, out),
            Item::Branch(e, child) => {
                emit_and(e, out);
                emit_node(child, out);
            }
        }
    }
}

/// Emits `e` as a new block (LD/LDI first).
fn emit_load(e: &Expr, out: &mut Vec<Instr>) {
    match e {
        Expr::Contact {
            negated,
            operand,
            origin,
        } => out.push(Instr::new(
            if *negated { Op::Ldi } else { Op::Ld },
            vec![operand.clone()],
            *origin,
        )),
        Expr::And(terms) => {
            emit_load(&terms[0], out);
            for t in terms.iter().skip(1) {
                emit_and(t, out);
            }
        }
        Expr::Or(terms) => {
            emit_load(&terms[0], out);
            for t in terms.iter().skip(1) {
                emit_or(t, out);
            }
        }
    }
}

/// Emits `acc := acc ∧ e`.
fn emit_and(e: &Expr, out: &mut Vec<Instr>) {
    match e {
        Expr::Contact {
            negated,
            operand,
            origin,
        } => out.push(Instr::new(
            if *negated { Op::Ani } else { Op::And },
            vec![operand.clone()],
            *origin,
        )),
        Expr::And(terms) => terms.iter().for_each(|t| emit_and(t, out)),
        Expr::Or(_) => {
            emit_load(e, out);
            out.push(Instr::new(Op::Anb, Vec::new(), Origin::None));
        }
    }
}

/// Emits `acc := acc ∨ e`.
fn emit_or(e: &Expr, out: &mut Vec<Instr>) {
    match e {
        Expr::Contact {
            negated,
            operand,
            origin,
        } => out.push(Instr::new(
            if *negated { Op::Ori } else { Op::Or },
            vec![operand.clone()],
            *origin,
        )),
        Expr::Or(terms) => terms.iter().for_each(|t| emit_or(t, out)),
        Expr::And(_) => {
            emit_load(e, out);
            out.push(Instr::new(Op::Orb, Vec::new(), Origin::None));
        }
    }
}
