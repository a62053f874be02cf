//! The words of [`IlFinding`]: each finding in English and in Chinese, side by side.

use crate::Lang;
use crate::quoted::operand_error;
use ladder_engine::compiler::IlFinding;

/// What `f` found and how to fix it, in `lang`.
pub(super) fn text(f: &IlFinding, lang: Lang) -> String {
    match f {
        IlFinding::UnknownInstruction { word, meant } => match (lang, meant) {
            (Lang::En, Some(op)) => {
                format!("unknown instruction `{word}`: did you mean {}?", op.name())
            }
            (Lang::Zh, Some(op)) => format!("未知指令 `{word}`：是不是 {}？", op.name()),
            (Lang::En, None) => format!(
                "unknown instruction `{word}`: see the instruction list in the manual (LD, AND, OUT, TMRB, …)"
            ),
            (Lang::Zh, None) => {
                format!("未知指令 `{word}`：请查阅手册中的指令表（LD、AND、OUT、TMRB 等）")
            }
        },
        IlFinding::UnclosedQuote => match lang {
            Lang::En => "a quoted text is not closed: add the closing \"".into(),
            Lang::Zh => "带引号的文字没有结束：请补上结尾的 \"".into(),
        },
        IlFinding::QuotedLineStart => match lang {
            Lang::En => {
                String::from("a line starts with an instruction or a directive, not a quoted text")
            }
            Lang::Zh => "每行应以指令或伪指令开头，而不是带引号的文字".into(),
        },
        IlFinding::AfterLevel { level } => match lang {
            Lang::En => format!("LEVEL{level} takes nothing after it"),
            Lang::Zh => format!("LEVEL{level} 后面不能再写其他内容"),
        },
        IlFinding::SubWithoutNumber => match lang {
            Lang::En => "SUB needs a subprogram number: `SUB P0001 \"NAME\"`".into(),
            Lang::Zh => "SUB 需要子程序号：`SUB P0001 \"NAME\"`".into(),
        },
        IlFinding::UnquotedTitle { title } => match lang {
            Lang::En => format!("write the network title in quotes: NETWORK \"{title}\""),
            Lang::Zh => format!("网络标题要写在引号内：NETWORK \"{title}\""),
        },
        IlFinding::QuotedOperand { text } => match lang {
            Lang::En => format!("`\"{text}\"`: operands are not quoted"),
            Lang::Zh => format!("`\"{text}\"`：操作数不加引号"),
        },
        IlFinding::BadOperand { op, error } => match lang {
            Lang::En => format!("{} operand: {}", op.name(), operand_error(error, lang)),
            Lang::Zh => format!("{} 的操作数：{}", op.name(), operand_error(error, lang)),
        },
        IlFinding::NotReadBack => match lang {
            Lang::En => String::from(
                "the ladder drawn from this network does not read back as its instruction list, so it cannot be imported unchanged: write its branches with MPS/MRD/MPP and its blocks with ORB/ANB",
            ),
            Lang::Zh => String::from(
                "由该网络画出的梯形图读回后与其指令表不一致，无法原样导入：请用 MPS/MRD/MPP 写分支、用 ORB/ANB 写逻辑块",
            ),
        },
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use ladder_engine::address::AddressError;
    use ladder_engine::catalog::Op;
    use ladder_engine::model::OperandError;

    /// The slot of each finding; no wildcard, so a new variant does not compile here until it
    /// has one, and the test fails until it has an example.
    fn slot(f: &IlFinding) -> usize {
        match f {
            IlFinding::UnknownInstruction { .. } => 0,
            IlFinding::UnclosedQuote => 1,
            IlFinding::QuotedLineStart => 2,
            IlFinding::AfterLevel { .. } => 3,
            IlFinding::SubWithoutNumber => 4,
            IlFinding::UnquotedTitle { .. } => 5,
            IlFinding::QuotedOperand { .. } => 6,
            IlFinding::BadOperand { .. } => 7,
            IlFinding::NotReadBack => 8,
        }
    }
    const VARIANTS: usize = 9;

    #[test]
    fn every_finding_reads_in_both_languages() {
        let examples = [
            IlFinding::UnknownInstruction {
                word: "OUTT".into(),
                meant: Some(Op::Out),
            },
            IlFinding::UnknownInstruction {
                word: "FROB".into(),
                meant: None,
            },
            IlFinding::UnclosedQuote,
            IlFinding::QuotedLineStart,
            IlFinding::AfterLevel { level: 2 },
            IlFinding::SubWithoutNumber,
            IlFinding::UnquotedTitle {
                title: "START".into(),
            },
            IlFinding::QuotedOperand {
                text: "X0000.0".into(),
            },
            IlFinding::BadOperand {
                op: Op::Ld,
                error: OperandError::Address(AddressError::Bit("X0000.9".into())),
            },
            IlFinding::BadOperand {
                op: Op::Tmrb,
                error: OperandError::Number("1x".into()),
            },
            IlFinding::NotReadBack,
        ];
        let mut seen = [false; VARIANTS];
        for f in &examples {
            seen[slot(f)] = true;
            crate::bilingual::assert_bilingual(&text(f, Lang::En), &text(f, Lang::Zh));
        }
        assert_eq!(seen, [true; VARIANTS], "a finding without an example");
    }

    #[test]
    fn an_unknown_word_gets_the_meant_instruction_or_where_to_look() {
        let typo = IlFinding::UnknownInstruction {
            word: "OUTT".into(),
            meant: Some(Op::Out),
        };
        assert_eq!(
            text(&typo, Lang::En),
            "unknown instruction `OUTT`: did you mean OUT?"
        );
        assert_eq!(text(&typo, Lang::Zh), "未知指令 `OUTT`：是不是 OUT？");
        let unknown = IlFinding::UnknownInstruction {
            word: "QQQQ…".into(),
            meant: None,
        };
        assert_eq!(
            text(&unknown, Lang::En),
            "unknown instruction `QQQQ…`: see the instruction list in the manual (LD, AND, OUT, TMRB, …)"
        );
        assert_eq!(
            text(&unknown, Lang::Zh),
            "未知指令 `QQQQ…`：请查阅手册中的指令表（LD、AND、OUT、TMRB 等）"
        );
    }

    #[test]
    fn syntax_findings_quote_what_was_written() {
        let bad = IlFinding::BadOperand {
            op: Op::Ld,
            error: OperandError::Address(AddressError::Bit("X0000.9".into())),
        };
        assert_eq!(
            text(&bad, Lang::En),
            "LD operand: `X0000.9`: the bit must be 0–7"
        );
        assert_eq!(text(&bad, Lang::Zh), "LD 的操作数：`X0000.9`：位号应为 0–7");
        let level = IlFinding::AfterLevel { level: 1 };
        assert_eq!(text(&level, Lang::En), "LEVEL1 takes nothing after it");
        assert_eq!(text(&level, Lang::Zh), "LEVEL1 后面不能再写其他内容");
        let title = IlFinding::UnquotedTitle {
            title: "START".into(),
        };
        assert_eq!(
            text(&title, Lang::En),
            "write the network title in quotes: NETWORK \"START\""
        );
        assert_eq!(
            text(&IlFinding::QuotedOperand { text: "R1".into() }, Lang::Zh),
            "`\"R1\"`：操作数不加引号"
        );
    }
}
