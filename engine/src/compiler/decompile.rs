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

/// Rebuilds the rungs of one network from its instructions. Returns `None` (after reporting)
/// when the instructions have no ladder drawing.
pub fn decompile(instrs: &[Instr], sink: &mut Sink) -> Option<Vec<Rung>> {
    let mut b = Builder::default();
    let mut acc: Option<Acc> = None;
    let mut blocks: Vec<Acc> = Vec::new();
    let mut branches: Vec<usize> = Vec::new();
    let mut after_output = false;
    let mut last_origin = Origin::None;
    for i in instrs {
        last_origin = i.origin;
        let fail = |sink: &mut Sink, code: Code, msg: &str, msg_zh: &str| {
            sink.report(i.origin, code, msg, msg_zh);
            None
        };
        let spec = i.op.spec();
        let was_after_output = std::mem::replace(&mut after_output, false);
        match i.op {
            Op::Ld | Op::Ldi => {
                let e = contact(i, i.op == Op::Ldi);
                match acc.take() {
                    None => {}
                    Some(_) if was_after_output && blocks.is_empty() && branches.is_empty() => {
                        b.finish_rung();
                    }
                    Some(_) if was_after_output => {
                        return fail(
                            sink,
                            Code::L015LoadAfterOutput,
                            "LD/LDI right after an output while MPS is open: use MRD or MPP to return to the branch point first",
                            "MPS 未闭合时在输出之后直接 LD/LDI：请先用 MRD 或 MPP 回到分支点",
                        );
                    }
                    Some(prev) => {
                        if prev.node.is_some() && prev.pending.is_some() && !branches.is_empty() {
                            // A block opened after a branch point: fine, ANB joins it later.
                        }
                        blocks.push(prev);
                    }
                }
                acc = Some(Acc {
                    node: None,
                    pending: Some(e),
                });
            }
            Op::And | Op::Ani => {
                let Some(a) = acc.as_mut() else {
                    return fail(
                        sink,
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
            }
            Op::Or | Op::Ori => {
                let Some(a) = acc.as_mut() else {
                    return fail(
                        sink,
                        Code::L013BlockStack,
                        "OR/ORI needs a contact before it: start the rung with LD or LDI",
                        "OR/ORI 前面需要有触点：梯级应以 LD 或 LDI 开始",
                    );
                };
                if a.node.is_some() {
                    return fail(
                        sink,
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
            }
            Op::Orb | Op::Anb => {
                let (Some(cur), Some(prev)) = (acc.take(), blocks.pop()) else {
                    return fail(
                        sink,
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
                    return fail(
                        sink,
                        Code::L017NotDrawable,
                        "a block that contains an output or a branch point cannot be joined by ORB/ANB",
                        "含有输出或分支点的逻辑块不能用 ORB/ANB 连接",
                    );
                };
                if i.op == Op::Orb {
                    let (None, Some(prev_e)) = (prev.node, prev.pending) else {
                        return fail(
                            sink,
                            Code::L017NotDrawable,
                            "ORB joins a block to a branch point's path, which has no ladder drawing: move the parallel block before the MPS",
                            "ORB 把逻辑块并联到分支点之后的支路上，无法画成梯形图：请把并联的逻辑块移到 MPS 之前",
                        );
                    };
                    acc = Some(Acc {
                        node: None,
                        pending: Some(or(prev_e, cur_e)),
                    });
                } else {
                    acc = Some(Acc {
                        node: prev.node,
                        pending: Some(match prev.pending {
                            Some(p) => and(p, cur_e),
                            None => cur_e,
                        }),
                    });
                }
            }
            Op::Mps | Op::Mrd | Op::Mpp => {
                if !blocks.is_empty() {
                    return fail(
                        sink,
                        Code::L013BlockStack,
                        "MPS/MRD/MPP inside an open LD block: close the block with ORB or ANB first",
                        "MPS/MRD/MPP 位于未闭合的 LD 逻辑块中：请先用 ORB 或 ANB 闭合该逻辑块",
                    );
                }
                match i.op {
                    Op::Mps => {
                        let Some(a) = acc.as_ref() else {
                            return fail(
                                sink,
                                Code::L014BranchStack,
                                "MPS needs a contact before it",
                                "MPS 前面需要有触点",
                            );
                        };
                        let n = b.anchor(a);
                        branches.push(n);
                        acc = Some(Acc {
                            node: Some(n),
                            pending: None,
                        });
                    }
                    _ => {
                        let top = if i.op == Op::Mrd {
                            branches.last().copied()
                        } else {
                            branches.pop()
                        };
                        let Some(n) = top else {
                            return fail(
                                sink,
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
                        acc = Some(Acc {
                            node: Some(n),
                            pending: None,
                        });
                    }
                }
            }
            _ if !spec.needs_act() => {
                let boundary =
                    acc.is_none() || (was_after_output && blocks.is_empty() && branches.is_empty());
                if !boundary {
                    return fail(
                        sink,
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
                if acc.take().is_some() {
                    b.finish_rung();
                }
                b.rungs.push(Rung::Standalone(Output {
                    op: i.op,
                    operands: i.operands.clone(),
                    origin: i.origin,
                }));
            }
            _ => {
                debug_assert!(matches!(
                    spec.class,
                    InstrClass::Coil | InstrClass::Function
                ));
                let Some(a) = acc.as_ref() else {
                    return fail(
                        sink,
                        Code::L006NoContact,
                        &format!("{} needs a condition: put LD/LDI before it", i.op.name()),
                        &format!("{} 需要执行条件：请在它前面加 LD/LDI", i.op.name()),
                    );
                };
                if !blocks.is_empty() {
                    return fail(
                        sink,
                        Code::L013BlockStack,
                        "an LD block is still open before this output: join it with ORB or ANB",
                        "该输出之前还有未闭合的 LD 逻辑块：请用 ORB 或 ANB 连接",
                    );
                }
                let n = b.anchor(a);
                b.nodes[n].push(AItem::Output(Output {
                    op: i.op,
                    operands: i.operands.clone(),
                    origin: i.origin,
                }));
                acc = Some(Acc {
                    node: Some(n),
                    pending: None,
                });
                after_output = true;
            }
        }
    }
    if acc.is_some() {
        if !blocks.is_empty() {
            sink.report(
                last_origin,
                Code::L013BlockStack,
                "the network ends with an LD block still open: join it with ORB or ANB",
                "网络结束时仍有未闭合的 LD 逻辑块：请用 ORB 或 ANB 连接",
            );
            return None;
        }
        if !branches.is_empty() {
            sink.report(
                last_origin,
                Code::L014BranchStack,
                "the network ends with an MPS still open: close it with MPP",
                "网络结束时仍有未闭合的 MPS：请用 MPP 闭合",
            );
            return None;
        }
        if !after_output {
            sink.report(
                last_origin,
                Code::L016NoOutput,
                "the network ends without an output: finish the rung with a coil or function instruction",
                "网络结束时没有输出：请用线圈或功能指令结束该梯级",
            );
            return None;
        }
        b.finish_rung();
    }
    Some(b.rungs)
}
