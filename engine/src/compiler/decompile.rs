//! Instruction list → rung trees, by running the instructions symbolically.
//!
//! The accumulator is a position in the tree being built (a node, or the rail) plus the
//! series expression gathered since that position. Outputs and MPS fix the position as a
//! node; AND extends the pending expression; LD…ORB/ANB build blocks; MRD/MPP return to the
//! saved node. Sequences with no ladder drawing (OR after a branch point, LD after an output
//! while MPS is open) are reported at their line.

use super::diag::{Code, Origin, Sink};
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
fn refuse<T>(sink: &mut Sink, i: &Instr, code: Code, msg: &str, msg_zh: &str) -> Option<T> {
    sink.report(i.origin, code, msg, msg_zh);
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
                return refuse(
                    sink,
                    i,
                    Code::L015LoadAfterOutput,
                    "LD/LDI right after an output while MPS is open: use MRD or MPP to return to the branch point first",
                    "MPS 未闭合时在输出之后直接 LD/LDI：请先用 MRD 或 MPP 回到分支点",
                );
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
            return refuse(
                sink,
                i,
                Code::L013BlockStack,
                "AND/ANI needs a contact before it: start the rung with LD or LDI",
                "AND/ANI 前面需要有触点：梯级应以 LD 或 LDI 开始",
            );
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
            return refuse(
                sink,
                i,
                Code::L013BlockStack,
                "OR/ORI needs a contact before it: start the rung with LD or LDI",
                "OR/ORI 前面需要有触点：梯级应以 LD 或 LDI 开始",
            );
        };
        if a.node.is_some() {
            return refuse(
                sink,
                i,
                Code::L017NotDrawable,
                "OR/ORI after a branch point or output has no ladder drawing: write the parallel part as LD … ORB, then ANB",
                "分支点或输出之后的 OR/ORI 无法画成梯形图：请把并联部分写成 LD … ORB，再用 ANB",
            );
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
            return refuse(
                sink,
                i,
                Code::L013BlockStack,
                &format!(
                    "{} has no open block to join: each ORB/ANB needs an LD or LDI block before it",
                    i.op.name()
                ),
                &format!(
                    "{} 没有可连接的逻辑块：每个 ORB/ANB 前面都需要一个以 LD 或 LDI 开始的逻辑块",
                    i.op.name()
                ),
            );
        };
        let (None, Some(cur_e)) = (cur.node, cur.pending) else {
            return refuse(
                sink,
                i,
                Code::L017NotDrawable,
                "a block that contains an output or a branch point cannot be joined by ORB/ANB",
                "含有输出或分支点的逻辑块不能用 ORB/ANB 连接",
            );
        };
        if i.op == Op::Orb {
            let (None, Some(prev_e)) = (prev.node, prev.pending) else {
                return refuse(
                    sink,
                    i,
                    Code::L017NotDrawable,
                    "ORB joins a block to a branch point's path, which has no ladder drawing: move the parallel block before the MPS",
                    "ORB 把逻辑块并联到分支点之后的支路上，无法画成梯形图：请把并联的逻辑块移到 MPS 之前",
                );
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
            return refuse(
                sink,
                i,
                Code::L013BlockStack,
                "MPS/MRD/MPP inside an open LD block: close the block with ORB or ANB first",
                "MPS/MRD/MPP 位于未闭合的 LD 逻辑块中：请先用 ORB 或 ANB 闭合该逻辑块",
            );
        }
        let n = if i.op == Op::Mps {
            let Some(a) = self.acc.as_ref() else {
                return refuse(
                    sink,
                    i,
                    Code::L014BranchStack,
                    "MPS needs a contact before it",
                    "MPS 前面需要有触点",
                );
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
                return refuse(
                    sink,
                    i,
                    Code::L014BranchStack,
                    &format!(
                        "{} without MPS: every MRD/MPP needs an open MPS",
                        i.op.name()
                    ),
                    &format!(
                        "{} 没有对应的 MPS：每个 MRD/MPP 都需要一个未闭合的 MPS",
                        i.op.name()
                    ),
                );
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
            return refuse(
                sink,
                i,
                Code::L007NotStandalone,
                &format!(
                    "{} stands alone: end the rung before it with an output",
                    i.op.name()
                ),
                &format!(
                    "{} 必须单独成网络：请先用一个输出结束它前面的梯级",
                    i.op.name()
                ),
            );
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
            return refuse(
                sink,
                i,
                Code::L006NoContact,
                &format!("{} needs a condition: put LD/LDI before it", i.op.name()),
                &format!("{} 需要执行条件：请在它前面加 LD/LDI", i.op.name()),
            );
        };
        if !self.blocks.is_empty() {
            return refuse(
                sink,
                i,
                Code::L013BlockStack,
                "an LD block is still open before this output: join it with ORB or ANB",
                "该输出之前还有未闭合的 LD 逻辑块：请用 ORB 或 ANB 连接",
            );
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
                sink.report(
                    last_origin,
                    Code::L013BlockStack,
                    "the network ends with an LD block still open: join it with ORB or ANB",
                    "网络结束时仍有未闭合的 LD 逻辑块：请用 ORB 或 ANB 连接",
                );
                return None;
            }
            if !self.branches.is_empty() {
                sink.report(
                    last_origin,
                    Code::L014BranchStack,
                    "the network ends with an MPS still open: close it with MPP",
                    "网络结束时仍有未闭合的 MPS：请用 MPP 闭合",
                );
                return None;
            }
            if !self.after_output {
                sink.report(
                    last_origin,
                    Code::L016NoOutput,
                    "the network ends without an output: finish the rung with a coil or function instruction",
                    "网络结束时没有输出：请用线圈或功能指令结束该梯级",
                );
                return None;
            }
            self.b.finish_rung();
        }
        Some(self.b.rungs)
    }
}
