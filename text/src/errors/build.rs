//! Why a program cannot run in the user's language: building the machine ([`LowerError`],
//! the engine's `BuildError`) and the scan loop's check of its code ([`CodeError`]).

use crate::Lang;
use ladder_engine::vm::{CodeError, LowerError};

/// Why the machine for a program could not be built, in `lang`. The English is the error's
/// own; an operand left unresolved is a compiler fault whose detail stays as the engine
/// words it.
pub fn build_error(e: &LowerError, lang: Lang) -> String {
    match lang {
        Lang::En => e.to_string(),
        Lang::Zh => match e {
            LowerError::CompileErrors(n) => {
                format!("程序有 {n} 个编译错误；请先运行 check 并改正")
            }
            LowerError::Unresolved(detail) => format!("程序无法运行：{detail}"),
            LowerError::Code(c) => format!("代码无效：{}", code_error(c, lang)),
            LowerError::Model(m) => super::model_error(m, Lang::Zh),
        },
    }
}

/// Why the scan loop refused a word of the code, in `lang`.
pub fn code_error(e: &CodeError, lang: Lang) -> String {
    match lang {
        Lang::En => e.to_string(),
        Lang::Zh => match e {
            CodeError::UnknownOpcode { at, byte } => {
                format!("第 {at} 字：{byte:#04x} 不是虚拟机的操作码")
            }
            CodeError::OutOfRange {
                at,
                op,
                index,
                len,
                what,
            } => format!(
                "第 {at} 字：{op} {index} 超出范围（共 {len} 个{}）",
                indexed_zh(what)
            ),
            CodeError::Entry { entry, len } => {
                format!("程序级入口 {entry} 超出代码范围（共 {len} 个字）")
            }
        },
    }
}

/// What an out-of-range index indexes, in Chinese (the engine names it in English).
fn indexed_zh(what: &str) -> &str {
    match what {
        "words" => "字",
        "networks" => "网络",
        "function instructions" => "功能指令",
        // A new kind of index: its engine name, rather than nothing.
        other => other,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use ladder_engine::devices::ModelError;

    /// The slot of each error; no wildcard, so a new variant does not compile here until it
    /// has one, and the test fails until it has an example.
    fn slot(e: &LowerError) -> usize {
        match e {
            LowerError::CompileErrors(_) => 0,
            LowerError::Unresolved(_) => 1,
            LowerError::Code(CodeError::UnknownOpcode { .. }) => 2,
            LowerError::Code(CodeError::OutOfRange { .. }) => 3,
            LowerError::Code(CodeError::Entry { .. }) => 4,
            LowerError::Model(_) => 5,
        }
    }
    const VARIANTS: usize = 6;

    #[test]
    fn every_build_error_reads_in_chinese_and_keeps_its_english() {
        let mut examples = vec![
            LowerError::CompileErrors(3),
            LowerError::Unresolved("symbol `START` is not resolved".into()),
            LowerError::Code(CodeError::UnknownOpcode { at: 7, byte: 0xfe }),
            LowerError::Code(CodeError::Entry { entry: 90, len: 80 }),
            LowerError::Model(ModelError::Name("1x".into())),
        ];
        for what in ["words", "networks", "function instructions"] {
            examples.push(LowerError::Code(CodeError::OutOfRange {
                at: 4,
                op: "Net".into(),
                index: 12,
                len: 10,
                what,
            }));
        }
        let mut seen = [false; VARIANTS];
        for e in &examples {
            seen[slot(e)] = true;
            let zh = build_error(e, Lang::Zh);
            assert!(crate::errors::has_cjk(&zh), "{zh}");
            assert_eq!(build_error(e, Lang::En), e.to_string());
            if let LowerError::Code(c) = e {
                assert!(zh.ends_with(&code_error(c, Lang::Zh)), "{zh}");
                assert_eq!(code_error(c, Lang::En), c.to_string());
                assert!(!zh.contains(" words") && !zh.contains("networks"), "{zh}");
            }
        }
        assert_eq!(seen, [true; VARIANTS], "a build error without an example");
        assert_eq!(
            LowerError::CompileErrors(3).to_string(),
            "the program has 3 compile error(s); run check and fix them first"
        );
        let m = ModelError::Name("1x".into());
        assert_eq!(LowerError::Model(m.clone()).to_string(), m.to_string());
        assert_eq!(
            build_error(&LowerError::Model(m.clone()), Lang::Zh),
            super::super::model_error(&m, Lang::Zh)
        );
    }
}
