//! Rung trees → grid: the drawing of rebuilt rungs.
//!
//! Every element's input is at its top row's left edge and its output at its top row's right
//! edge. Parallel terms stack downwards, joined by vertical links at both ends; a shorter term
//! is padded with wire on its top row. Branches of a node stack downwards and are joined at
//! the node's junction; a node that holds only outputs is drawn at the output column. Read
//! back by `lower`, the drawing gives the same tree.

use super::rung::{Expr, Item, Node, Rung};
use crate::model::{Cell, Row};

fn size(e: &Expr) -> (usize, usize) {
    match e {
        Expr::Contact { .. } => (1, 1),
        Expr::And(v) => v
            .iter()
            .map(size)
            .fold((0, 0), |(w, h), (cw, ch)| (w + cw, h.max(ch))),
        Expr::Or(v) => v
            .iter()
            .map(size)
            .fold((0, 0), |(w, h), (cw, ch)| (w.max(cw), h + ch)),
    }
}

fn outputs_only(n: &Node) -> bool {
    n.items.iter().all(|i| matches!(i, Item::Output(_)))
}

fn node_height(n: &Node) -> usize {
    n.items.iter().map(item_height).sum::<usize>().max(1)
}

fn item_height(i: &Item) -> usize {
    match i {
        Item::Output(_) => 1,
        Item::Branch(e, child) => size(e).1.max(node_height(child)),
    }
}

/// The contact columns the rungs need.
pub fn width_needed(rungs: &[Rung]) -> usize {
    fn node(n: &Node, j: usize) -> usize {
        n.items
            .iter()
            .map(|i| match i {
                Item::Output(_) => j,
                Item::Branch(e, child) => node(child, j + size(e).0),
            })
            .max()
            .unwrap_or(j)
    }
    rungs
        .iter()
        .map(|r| match r {
            Rung::Powered(e, n) => node(n, size(e).0),
            Rung::Standalone(_) => 1,
        })
        .max()
        .unwrap_or(1)
}

struct Grid {
    rows: Vec<Row>,
    width: usize,
}

impl Grid {
    fn ensure(&mut self, row: usize) {
        while self.rows.len() <= row {
            self.rows.push(Row::empty(self.width));
        }
    }
    fn set(&mut self, row: usize, col: usize, cell: Cell) {
        self.ensure(row);
        self.rows[row].cells[col] = cell;
    }
    fn wires(&mut self, row: usize, from: usize, to: usize) {
        for c in from..to {
            self.set(row, c, Cell::Wire);
        }
    }
    fn links(&mut self, j: usize, from_row: usize, to_row: usize) {
        if j == 0 {
            return;
        }
        for r in from_row..to_row {
            self.ensure(r + 1);
            self.rows[r].links[j] = true;
        }
    }

    fn expr(&mut self, e: &Expr, row: usize, col: usize) {
        match e {
            Expr::Contact {
                negated, operand, ..
            } => self.set(
                row,
                col,
                Cell::Contact {
                    negated: *negated,
                    operand: operand.clone(),
                },
            ),
            Expr::And(v) => {
                let mut c = col;
                for t in v {
                    self.expr(t, row, c);
                    c += size(t).0;
                }
            }
            Expr::Or(v) => {
                let w = size(e).0;
                let mut r = row;
                let mut last_top = row;
                for t in v {
                    let (tw, th) = size(t);
                    self.expr(t, r, col);
                    self.wires(r, col + tw, col + w);
                    last_top = r;
                    r += th;
                }
                self.links(col, row, last_top);
                self.links(col + w, row, last_top);
            }
        }
    }

    /// Draws `e` from (row, j) and the node after it.
    fn branch(&mut self, e: &Expr, child: &Node, row: usize, j: usize) {
        self.expr(e, row, j);
        let end = j + size(e).0;
        if outputs_only(child) && child.items.len() > 1 {
            self.wires(row, end, self.width);
            self.node(child, row, self.width);
        } else {
            self.node(child, row, end);
        }
    }

    fn node(&mut self, n: &Node, row: usize, j: usize) {
        let mut r = row;
        let mut last_top = row;
        for item in &n.items {
            last_top = r;
            match item {
                Item::Output(o) => {
                    self.wires(r, j, self.width);
                    self.set(r, self.width, Cell::from_output(o.op, o.operands.clone()));
                }
                Item::Branch(e, child) => self.branch(e, child, r, j),
            }
            r += item_height(item);
        }
        self.links(j, row, last_top);
    }
}

/// Draws rungs into rows of a network `width` contact columns wide (at least
/// [`width_needed`]).
pub fn layout(rungs: &[Rung], width: usize) -> Vec<Row> {
    let mut g = Grid {
        rows: Vec::new(),
        width,
    };
    let mut row = 0;
    for rung in rungs {
        match rung {
            Rung::Powered(e, n) => {
                g.branch(e, n, row, 0);
                row += size(e).1.max(node_height(n));
            }
            Rung::Standalone(o) => {
                g.wires(row, 0, width);
                g.set(row, width, Cell::from_output(o.op, o.operands.clone()));
                row += 1;
            }
        }
    }
    g.ensure(0);
    g.rows
}
