//! Instruction list → rung trees, by running the instructions symbolically.
//!
//! The accumulator is a position in the tree being built (a node, or the rail) plus the
//! series expression gathered since that position. Outputs and MPS fix the position as a
//! node; AND extends the pending expression; LD…ORB/ANB build blocks; MRD/MPP return to the
//! saved node. Sequences with no ladder drawing (OR after a branch point, LD after an output
//! while MPS is open) are reported at their line.

use super::diag::{Origin, Sink};
use super::finding::LowerFinding;
use super::rung::{Expr, Instr, Item, Node, Output, Rung, and, or};
use crate::catalog::{InstrClass, Op};

#[derive(Clone, Debug)]
struct Acc {
    /// None: the rail.
    node: Option<usize>,
    pending: Option<Expr>,
}

enum AItem {
    Output(Output),
    Branch(Expr, usize),
}

#[derive(Default)]
struct Builder {
    /// Items per node; the rail's are kept apart.
    nodes: Vec<Vec<AItem>>,
    rail: Vec<(Expr, usize)>,
    rungs: Vec<Rung>,
}

impl Builder {
    fn anchor(&mut self, acc: &Acc) -> usize {
        match (&acc.pending, acc.node) {
            (None, Some(n)) => n,
            (pending, node) => {
                let m = self.nodes.len();
                self.nodes.push(Vec::new());
                // The pending expression is never empty at the rail: a rung starts with LD.
                let e = pending.clone().expect("a pending expression at the rail");
                match node {
                    Some(n) => self.nodes[n].push(AItem::Branch(e, m)),
                    None => self.rail.push((e, m)),
                }
                m
            }
        }
    }

    fn take_node(&mut self, n: usize) -> Node {
        let items = std::mem::take(&mut self.nodes[n]);
        Node {
            items: items
                .into_iter()
                .map(|i| match i {
                    AItem::Output(o) => Item::Output(o),
                    AItem::Branch(e, m) => Item::Branch(e, self.take_node(m)),
                })
                .collect(),
        }
    }

    fn finish_rung(&mut self) {
        for (e, n) in std::mem::take(&mut self.rail) {
            let node = self.take_node(n);
            self.rungs.push(Rung::Powered(e, node));
        }
        self.nodes.clear();
    }
}

fn contact(i: &Instr, negated: bool) -> Expr {
    Expr::Contact {
        negated,
        operand: i
            .operands
            .first()
            .cloned()
            .unwrap_or(crate::model::Operand::Int(0)),
        origin: i.origin,
    }
}

/// Reports a sequence with no ladder drawing at `i` and gives up the network: the `None`
/// every step returns once the instructions cannot be drawn.
fn refuse<T>(sink: &mut Sink, i: &Instr, finding: LowerFinding) -> Option<T> {
    sink.find(i.origin, finding);
    None
}

/// The symbolic run's state between two instructions: the tree built so far, the
/// accumulator, the LD blocks and MPS branch points still open, and whether the last
/// instruction was an output (where a new rung may start).
#[derive(Default)]
struct Decompiler {
    b: Builder,
    acc: Option<Acc>,
    blocks: Vec<Acc>,
    branches: Vec<usize>,
    after_output: bool,
}

/// Rebuilds the rungs of one network from its instructions. Returns `None` (after reporting)
/// when the instructions have no ladder drawing.
pub fn decompile(instrs: &[Instr], sink: &mut Sink) -> Option<Vec<Rung>> {
    let mut d = Decompiler::default();
    let mut last_origin = Origin::None;
    for i in instrs {
        last_origin = i.origin;
        d.step(i, sink)?;
    }
    d.finish(last_origin, sink)
}

impl Decompiler {
    /// Runs one instruction, `None` once it has been reported as having no drawing.
    fn step(&mut self, i: &Instr, sink: &mut Sink) -> Option<()> {
        // Only the instruction right after an output may start a rung: each step clears it.
        let was_after_output = std::mem::replace(&mut self.after_output, false);
        match i.op {
            Op::Ld | Op::Ldi => self.load(i, was_after_output, sink),
            Op::And | Op::Ani => self.and(i, sink),
            Op::Or | Op::Ori => self.or(i, sink),
            Op::Orb | Op::Anb => self.join(i, sink),
            Op::Mps | Op::Mrd | Op::Mpp => self.branch(i, sink),
            _ if !i.op.spec().needs_act() => self.standalone(i, was_after_output, sink),
            _ => self.output(i, sink),
        }
    }

    /// LD/LDI: a new rung after an output with nothing open, else a new block (refused
    /// after an output while MPS is open: the contact would hang off nothing).
    fn load(&mut self, i: &Instr, was_after_output: bool, sink: &mut Sink) -> Option<()> {
        let e = contact(i, i.op == Op::Ldi);
        match self.acc.take() {
            None => {}
            Some(_) if was_after_output && self.blocks.is_empty() && self.branches.is_empty() => {
                self.b.finish_rung();
            }
            Some(_) if was_after_output => {
                return refuse(sink, i, LowerFinding::LoadAfterOutput);
            }
            Some(prev) => {
                if prev.node.is_some() && prev.pending.is_some() && !self.branches.is_empty() {
                    // A block opened after a branch point: fine, ANB joins it later.
                }
                self.blocks.push(prev);
            }
        }
        self.acc = Some(Acc {
            node: None,
            pending: Some(e),
        });
        Some(())
    }

    /// AND/ANI: the contact in series with the pending expression.
    fn and(&mut self, i: &Instr, sink: &mut Sink) -> Option<()> {
        let Some(a) = self.acc.as_mut() else {
            return refuse(sink, i, LowerFinding::AndWithoutContact);
        };
        let e = contact(i, i.op == Op::Ani);
        a.pending = Some(match a.pending.take() {
            Some(p) => and(p, e),
            None => e,
        });
        Some(())
    }

    /// OR/ORI: the contact in parallel with the pending expression, which only the rail's
    /// accumulator can take (after a node there is nothing to draw the parallel from).
    fn or(&mut self, i: &Instr, sink: &mut Sink) -> Option<()> {
        let Some(a) = self.acc.as_mut() else {
            return refuse(sink, i, LowerFinding::OrWithoutContact);
        };
        if a.node.is_some() {
            return refuse(sink, i, LowerFinding::OrAfterNode);
        }
        let e = contact(i, i.op == Op::Ori);
        let p = a
            .pending
            .take()
            .expect("a rail accumulator has an expression");
        a.pending = Some(or(p, e));
        Some(())
    }

    /// ORB/ANB: the current block joined to the last open one, in parallel or in series.
    /// Only plain expressions join: a block holding an output or a branch point has no
    /// drawing as one side of a parallel or series pair.
    fn join(&mut self, i: &Instr, sink: &mut Sink) -> Option<()> {
        let (Some(cur), Some(prev)) = (self.acc.take(), self.blocks.pop()) else {
            return refuse(sink, i, LowerFinding::NoBlockToJoin { op: i.op });
        };
        let (None, Some(cur_e)) = (cur.node, cur.pending) else {
            return refuse(sink, i, LowerFinding::JoinedBlockHasNode);
        };
        if i.op == Op::Orb {
            let (None, Some(prev_e)) = (prev.node, prev.pending) else {
                return refuse(sink, i, LowerFinding::OrbAfterBranchPoint);
            };
            self.acc = Some(Acc {
                node: None,
                pending: Some(or(prev_e, cur_e)),
            });
        } else {
            self.acc = Some(Acc {
                node: prev.node,
                pending: Some(match prev.pending {
                    Some(p) => and(p, cur_e),
                    None => cur_e,
                }),
            });
        }
        Some(())
    }

    /// MPS/MRD/MPP: MPS fixes the accumulator as a branch point, MRD returns to the last
    /// one, MPP returns to it and closes it. None may stand inside an open LD block.
    fn branch(&mut self, i: &Instr, sink: &mut Sink) -> Option<()> {
        if !self.blocks.is_empty() {
            return refuse(sink, i, LowerFinding::BranchInBlock);
        }
        let n = if i.op == Op::Mps {
            let Some(a) = self.acc.as_ref() else {
                return refuse(sink, i, LowerFinding::MpsWithoutContact);
            };
            let n = self.b.anchor(a);
            self.branches.push(n);
            n
        } else {
            let top = if i.op == Op::Mrd {
                self.branches.last().copied()
            } else {
                self.branches.pop()
            };
            let Some(n) = top else {
                return refuse(sink, i, LowerFinding::NoOpenMps { op: i.op });
            };
            n
        };
        self.acc = Some(Acc {
            node: Some(n),
            pending: None,
        });
        Some(())
    }

    /// LBL, CALLU and the like: a rung of their own, so only at a rung's boundary (nothing
    /// run yet, or an output with nothing left open); the rung before them ends there.
    fn standalone(&mut self, i: &Instr, was_after_output: bool, sink: &mut Sink) -> Option<()> {
        let boundary = self.acc.is_none()
            || (was_after_output && self.blocks.is_empty() && self.branches.is_empty());
        if !boundary {
            return refuse(sink, i, LowerFinding::StandaloneMidRung { op: i.op });
        }
        if self.acc.take().is_some() {
            self.b.finish_rung();
        }
        self.b.rungs.push(Rung::Standalone(Output {
            op: i.op,
            operands: i.operands.clone(),
            origin: i.origin,
        }));
        Some(())
    }

    /// A coil or function instruction: an output hung at the accumulator's node, which
    /// becomes the position the next instructions continue from.
    fn output(&mut self, i: &Instr, sink: &mut Sink) -> Option<()> {
        debug_assert!(matches!(
            i.op.spec().class,
            InstrClass::Coil | InstrClass::Function
        ));
        let Some(a) = self.acc.as_ref() else {
            return refuse(sink, i, LowerFinding::OutputWithoutCondition { op: i.op });
        };
        if !self.blocks.is_empty() {
            return refuse(sink, i, LowerFinding::BlockOpenAtOutput);
        }
        let n = self.b.anchor(a);
        self.b.nodes[n].push(AItem::Output(Output {
            op: i.op,
            operands: i.operands.clone(),
            origin: i.origin,
        }));
        self.acc = Some(Acc {
            node: Some(n),
            pending: None,
        });
        self.after_output = true;
        Some(())
    }

    /// The end of the network: a rung in progress must have nothing open and end with an
    /// output; each failure is reported at the last instruction, where the fix goes.
    fn finish(mut self, last_origin: Origin, sink: &mut Sink) -> Option<Vec<Rung>> {
        if self.acc.is_some() {
            if !self.blocks.is_empty() {
                sink.find(last_origin, LowerFinding::BlockOpenAtEnd);
                return None;
            }
            if !self.branches.is_empty() {
                sink.find(last_origin, LowerFinding::BranchOpenAtEnd);
                return None;
            }
            if !self.after_output {
                sink.find(last_origin, LowerFinding::NoOutputAtEnd);
                return None;
            }
            self.b.finish_rung();
        }
        Some(self.b.rungs)
    }
}
