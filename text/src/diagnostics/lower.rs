//! The words of [`LowerFinding`]: each finding in English and in Chinese, side by side.

use crate::Lang;
use ladder_engine::catalog::InstrClass;
use ladder_engine::compiler::LowerFinding;

/// What `f` found and how to fix it, in `lang`.
pub(super) fn text(f: &LowerFinding, lang: Lang) -> String {
    match f {
        LowerFinding::ElementNotConnected => match lang {
            Lang::En => String::from(
                "this element is not connected to the left rail; draw a wire or vertical link to it",
            ),
            Lang::Zh => "该元件未连接到左母线；请画一条导线或竖线连到它".into(),
        },
        LowerFinding::OutputNotConnected { op } => {
            let coil = op.spec().class == InstrClass::Coil;
            match lang {
                Lang::En => format!(
                    "this {} is not connected to the left rail; draw the contacts that drive it",
                    if coil { "coil" } else { "function box" }
                ),
                Lang::Zh => format!(
                    "该{}未连接到左母线；请画出驱动它的触点",
                    if coil { "线圈" } else { "功能指令" }
                ),
            }
        }
        LowerFinding::OpenElement => match lang {
            Lang::En => String::from(
                "open branch: nothing after this element leads to a coil or function box; connect it or delete it",
            ),
            Lang::Zh => "开路分支：该元件之后没有连到任何线圈或功能指令；请连接或删除它".into(),
        },
        LowerFinding::OpenBranch { contacts } => match lang {
            Lang::En => format!(
                "open branch of {contacts} contacts from here: nothing after them leads to a coil or function box; connect the branch or delete it"
            ),
            Lang::Zh => format!(
                "从此处起的开路分支（{contacts} 个触点）：之后没有连到任何线圈或功能指令；请连接或删除该分支"
            ),
        },
        LowerFinding::ShortCircuit => match lang {
            Lang::En => String::from(
                "this branch is short-circuited by a plain wire in parallel with it; delete the wire or put a contact in it",
            ),
            Lang::Zh => "该分支被与之并联的导线短路；请删除该导线，或在导线中加一个触点".into(),
        },
        LowerFinding::Bridge => match lang {
            Lang::En => String::from(
                "these branches join again after a branch point (or form a bridge), which no instruction list can express; draw each output's contacts as separate parallel branches",
            ),
            Lang::Zh => String::from(
                "这些分支在分支点之后重新汇合（或形成桥接），指令表无法表达；请把每个输出的触点画成各自独立的并联分支",
            ),
        },
        LowerFinding::OutputLeftOfColumn => match lang {
            Lang::En => String::from(
                "a coil or function box must stand in the output column at the right end of the rung",
            ),
            Lang::Zh => "线圈或功能指令必须放在梯级最右端的输出列".into(),
        },
        LowerFinding::ElementInOutputColumn => match lang {
            Lang::En => String::from(
                "only coils and function boxes go in the output column; move the contact or wire left",
            ),
            Lang::Zh => "输出列只能放线圈和功能指令；请把触点或导线移到左边".into(),
        },
        LowerFinding::RungWithoutContact => match lang {
            Lang::En => String::from(
                "this rung has no contact: an output needs at least one contact between it and the rail",
            ),
            Lang::Zh => "该梯级没有触点：输出与母线之间至少要有一个触点".into(),
        },
        LowerFinding::OutputAtRail => match lang {
            Lang::En => String::from(
                "this output is connected straight to the rail; put a contact before it",
            ),
            Lang::Zh => "该输出直接连在母线上；请在它前面加一个触点".into(),
        },
        LowerFinding::OutputWithoutCondition { op } => match lang {
            Lang::En => format!("{} needs a condition: put LD/LDI before it", op.name()),
            Lang::Zh => format!("{} 需要执行条件：请在它前面加 LD/LDI", op.name()),
        },
        LowerFinding::StandaloneShared { op } => match lang {
            Lang::En => format!(
                "{} stands alone: remove the contacts and other outputs on its rung",
                op.name(),
            ),
            Lang::Zh => format!(
                "{} 必须单独成网络：请删除同一梯级上的触点和其他输出",
                op.name()
            ),
        },
        LowerFinding::StandaloneMidRung { op } => match lang {
            Lang::En => format!(
                "{} stands alone: end the rung before it with an output",
                op.name(),
            ),
            Lang::Zh => format!(
                "{} 必须单独成网络：请先用一个输出结束它前面的梯级",
                op.name()
            ),
        },
        LowerFinding::AndWithoutContact
        | LowerFinding::OrWithoutContact
        | LowerFinding::NoBlockToJoin { .. }
        | LowerFinding::BranchInBlock
        | LowerFinding::BlockOpenAtOutput
        | LowerFinding::BlockOpenAtEnd
        | LowerFinding::MpsWithoutContact
        | LowerFinding::NoOpenMps { .. }
        | LowerFinding::BranchOpenAtEnd
        | LowerFinding::LoadAfterOutput
        | LowerFinding::NoOutputAtEnd
        | LowerFinding::OrAfterNode
        | LowerFinding::JoinedBlockHasNode
        | LowerFinding::OrbAfterBranchPoint => list_text(f, lang),
    }
}

/// The words of the findings about a list's LD blocks and MPS branch points, and about what
/// has no drawing (L013–L017); apart from [`text`] only to keep each function short.
fn list_text(f: &LowerFinding, lang: Lang) -> String {
    match f {
        LowerFinding::AndWithoutContact => match lang {
            Lang::En => "AND/ANI needs a contact before it: start the rung with LD or LDI".into(),
            Lang::Zh => "AND/ANI 前面需要有触点：梯级应以 LD 或 LDI 开始".into(),
        },
        LowerFinding::OrWithoutContact => match lang {
            Lang::En => "OR/ORI needs a contact before it: start the rung with LD or LDI".into(),
            Lang::Zh => "OR/ORI 前面需要有触点：梯级应以 LD 或 LDI 开始".into(),
        },
        LowerFinding::NoBlockToJoin { op } => match lang {
            Lang::En => format!(
                "{} has no open block to join: each ORB/ANB needs an LD or LDI block before it",
                op.name(),
            ),
            Lang::Zh => format!(
                "{} 没有可连接的逻辑块：每个 ORB/ANB 前面都需要一个以 LD 或 LDI 开始的逻辑块",
                op.name(),
            ),
        },
        LowerFinding::BranchInBlock => match lang {
            Lang::En => String::from(
                "MPS/MRD/MPP inside an open LD block: close the block with ORB or ANB first",
            ),
            Lang::Zh => {
                String::from("MPS/MRD/MPP 位于未闭合的 LD 逻辑块中：请先用 ORB 或 ANB 闭合该逻辑块")
            }
        },
        LowerFinding::BlockOpenAtOutput => match lang {
            Lang::En => String::from(
                "an LD block is still open before this output: join it with ORB or ANB",
            ),
            Lang::Zh => "该输出之前还有未闭合的 LD 逻辑块：请用 ORB 或 ANB 连接".into(),
        },
        LowerFinding::BlockOpenAtEnd => match lang {
            Lang::En => String::from(
                "the network ends with an LD block still open: join it with ORB or ANB",
            ),
            Lang::Zh => "网络结束时仍有未闭合的 LD 逻辑块：请用 ORB 或 ANB 连接".into(),
        },
        LowerFinding::MpsWithoutContact => match lang {
            Lang::En => "MPS needs a contact before it".into(),
            Lang::Zh => "MPS 前面需要有触点".into(),
        },
        LowerFinding::NoOpenMps { op } => match lang {
            Lang::En => format!("{} without MPS: every MRD/MPP needs an open MPS", op.name()),
            Lang::Zh => format!(
                "{} 没有对应的 MPS：每个 MRD/MPP 都需要一个未闭合的 MPS",
                op.name(),
            ),
        },
        LowerFinding::BranchOpenAtEnd => match lang {
            Lang::En => "the network ends with an MPS still open: close it with MPP".into(),
            Lang::Zh => "网络结束时仍有未闭合的 MPS：请用 MPP 闭合".into(),
        },
        LowerFinding::LoadAfterOutput => match lang {
            Lang::En => String::from(
                "LD/LDI right after an output while MPS is open: use MRD or MPP to return to the branch point first",
            ),
            Lang::Zh => "MPS 未闭合时在输出之后直接 LD/LDI：请先用 MRD 或 MPP 回到分支点".into(),
        },
        LowerFinding::NoOutputAtEnd => match lang {
            Lang::En => String::from(
                "the network ends without an output: finish the rung with a coil or function instruction",
            ),
            Lang::Zh => "网络结束时没有输出：请用线圈或功能指令结束该梯级".into(),
        },
        LowerFinding::OrAfterNode => match lang {
            Lang::En => String::from(
                "OR/ORI after a branch point or output has no ladder drawing: write the parallel part as LD … ORB, then ANB",
            ),
            Lang::Zh => String::from(
                "分支点或输出之后的 OR/ORI 无法画成梯形图：请把并联部分写成 LD … ORB，再用 ANB",
            ),
        },
        LowerFinding::JoinedBlockHasNode => match lang {
            Lang::En => String::from(
                "a block that contains an output or a branch point cannot be joined by ORB/ANB",
            ),
            Lang::Zh => "含有输出或分支点的逻辑块不能用 ORB/ANB 连接".into(),
        },
        LowerFinding::OrbAfterBranchPoint => match lang {
            Lang::En => String::from(
                "ORB joins a block to a branch point's path, which has no ladder drawing: move the parallel block before the MPS",
            ),
            Lang::Zh => String::from(
                "ORB 把逻辑块并联到分支点之后的支路上，无法画成梯形图：请把并联的逻辑块移到 MPS 之前",
            ),
        },
        shape => unreachable!("{shape:?} is worded by `text`"),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use ladder_engine::catalog::Op;

    /// The slot of each finding; no wildcard, so a new variant does not compile here until it
    /// has one, and the test fails until it has an example.
    fn slot(f: &LowerFinding) -> usize {
        match f {
            LowerFinding::ElementNotConnected => 0,
            LowerFinding::OutputNotConnected { .. } => 1,
            LowerFinding::OpenElement => 2,
            LowerFinding::OpenBranch { .. } => 3,
            LowerFinding::ShortCircuit => 4,
            LowerFinding::Bridge => 5,
            LowerFinding::OutputLeftOfColumn => 6,
            LowerFinding::ElementInOutputColumn => 7,
            LowerFinding::RungWithoutContact => 8,
            LowerFinding::OutputAtRail => 9,
            LowerFinding::OutputWithoutCondition { .. } => 10,
            LowerFinding::StandaloneShared { .. } => 11,
            LowerFinding::StandaloneMidRung { .. } => 12,
            LowerFinding::AndWithoutContact => 13,
            LowerFinding::OrWithoutContact => 14,
            LowerFinding::NoBlockToJoin { .. } => 15,
            LowerFinding::BranchInBlock => 16,
            LowerFinding::BlockOpenAtOutput => 17,
            LowerFinding::BlockOpenAtEnd => 18,
            LowerFinding::MpsWithoutContact => 19,
            LowerFinding::NoOpenMps { .. } => 20,
            LowerFinding::BranchOpenAtEnd => 21,
            LowerFinding::LoadAfterOutput => 22,
            LowerFinding::NoOutputAtEnd => 23,
            LowerFinding::OrAfterNode => 24,
            LowerFinding::JoinedBlockHasNode => 25,
            LowerFinding::OrbAfterBranchPoint => 26,
        }
    }
    const VARIANTS: usize = 27;

    fn examples() -> Vec<LowerFinding> {
        vec![
            LowerFinding::ElementNotConnected,
            LowerFinding::OutputNotConnected { op: Op::Out },
            LowerFinding::OutputNotConnected { op: Op::Tmrb },
            LowerFinding::OpenElement,
            LowerFinding::OpenBranch { contacts: 3 },
            LowerFinding::ShortCircuit,
            LowerFinding::Bridge,
            LowerFinding::OutputLeftOfColumn,
            LowerFinding::ElementInOutputColumn,
            LowerFinding::RungWithoutContact,
            LowerFinding::OutputAtRail,
            LowerFinding::OutputWithoutCondition { op: Op::Out },
            LowerFinding::StandaloneShared { op: Op::Lbl },
            LowerFinding::StandaloneMidRung { op: Op::Callu },
            LowerFinding::AndWithoutContact,
            LowerFinding::OrWithoutContact,
            LowerFinding::NoBlockToJoin { op: Op::Orb },
            LowerFinding::BranchInBlock,
            LowerFinding::BlockOpenAtOutput,
            LowerFinding::BlockOpenAtEnd,
            LowerFinding::MpsWithoutContact,
            LowerFinding::NoOpenMps { op: Op::Mrd },
            LowerFinding::BranchOpenAtEnd,
            LowerFinding::LoadAfterOutput,
            LowerFinding::NoOutputAtEnd,
            LowerFinding::OrAfterNode,
            LowerFinding::JoinedBlockHasNode,
            LowerFinding::OrbAfterBranchPoint,
        ]
    }

    #[test]
    fn every_finding_reads_in_both_languages() {
        let mut seen = [false; VARIANTS];
        for f in &examples() {
            seen[slot(f)] = true;
            crate::bilingual::assert_bilingual(&text(f, Lang::En), &text(f, Lang::Zh));
        }
        assert_eq!(seen, [true; VARIANTS], "a finding without an example");
    }

    #[test]
    fn findings_name_their_instruction_and_count() {
        let open = LowerFinding::OpenBranch { contacts: 3 };
        assert_eq!(
            text(&open, Lang::En),
            "open branch of 3 contacts from here: nothing after them leads to a coil or function box; connect the branch or delete it"
        );
        assert_eq!(
            text(&open, Lang::Zh),
            "从此处起的开路分支（3 个触点）：之后没有连到任何线圈或功能指令；请连接或删除该分支"
        );
        let lbl = LowerFinding::StandaloneShared { op: Op::Lbl };
        assert_eq!(
            text(&lbl, Lang::En),
            "LBL stands alone: remove the contacts and other outputs on its rung"
        );
        assert_eq!(
            text(&lbl, Lang::Zh),
            "LBL 必须单独成网络：请删除同一梯级上的触点和其他输出"
        );
        let coil = LowerFinding::OutputNotConnected { op: Op::Out };
        let tmrb = LowerFinding::OutputNotConnected { op: Op::Tmrb };
        assert_eq!(
            text(&coil, Lang::En),
            "this coil is not connected to the left rail; draw the contacts that drive it"
        );
        assert_eq!(
            text(&tmrb, Lang::Zh),
            "该功能指令未连接到左母线；请画出驱动它的触点"
        );
        let mrd = LowerFinding::NoOpenMps { op: Op::Mpp };
        assert_eq!(
            text(&mrd, Lang::En),
            "MPP without MPS: every MRD/MPP needs an open MPS"
        );
        assert_eq!(
            text(&LowerFinding::MpsWithoutContact, Lang::Zh),
            "MPS 前面需要有触点"
        );
    }
}
