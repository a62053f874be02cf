//! The engine's typed errors in the user's language: an edit, an operand, an address, a project
//! file or a subprogram command refused.

mod build;
mod comments;
mod coverage;
mod io;
mod print;
mod structure;

pub use crate::quoted::{
    address_error, cnc_error, digit_group_error, expr_error, field_error, model_error,
    operand_error, operand_refusal, table_error, taken,
};
pub use build::{build_error, code_error};
pub use comments::{comments_error, rejection};
pub use coverage::coverage_error;
pub use io::io_error;
pub use print::{networks_error, pdf_error};
pub use structure::{structure_error, width_error_zh};

use crate::{Lang, Msg};
use ladder_engine::file::{FileError, MAGIC, SCHEMA_VERSION};
use ladder_engine::model::{ColumnRule, EditError, Missing, SubError};

/// Why the engine refused a ladder edit.
pub fn edit_error(e: &EditError, lang: Lang) -> String {
    match lang {
        Lang::En => e.to_string(),
        Lang::Zh => match e {
            EditError::NoSuchPlace(what) => format!("这里没有{}", missing_zh(*what)),
            EditError::WrongColumn(rule) => format!("元件不能放在这一列：{}", column_zh(*rule)),
            EditError::FixedBlock => "一级程序和二级程序总是存在；只能增删子程序".to_string(),
            EditError::LastRow => "网络至少保留一行；要删除请删除整个网络".to_string(),
            EditError::NothingAbove => "并联触点需要上一行有元件".to_string(),
            EditError::WrongWidth(w) => {
                format!("网络与本梯形图的宽度不同：{}", width_error_zh(w))
            }
        },
    }
}

/// What an edit named that is not there, in Chinese.
fn missing_zh(m: Missing) -> &'static str {
    match m {
        Missing::Block => "这个程序块",
        Missing::Network => "这个网络",
        Missing::Row => "这一行",
        Missing::Column => "这一列",
        Missing::RowOfWidth => "与梯形图同宽的行",
        Missing::LinkPlace => "可放竖线的位置（竖线连接本行与下一行，位于左母线右侧）",
    }
}

/// The column rule an element broke, in Chinese.
fn column_zh(r: ColumnRule) -> &'static str {
    match r {
        ColumnRule::ContactsLeft => "触点和导线应放在输出列左侧",
        ColumnRule::OutputsRight => "线圈和功能指令应放在最右端的输出列",
    }
}

/// Why a project file could not be read or written (docs/files.md, "Project files (.ldp)").
/// What comes from outside the engine (the system's I/O error, the RON parser's message)
/// stays as it was said; the structure check's detail is the engine's, so it is rendered.
pub fn file_error(e: &FileError, lang: Lang) -> String {
    match lang {
        Lang::En => e.to_string(),
        Lang::Zh => match e {
            FileError::Io { path, source } => {
                format!("{}：文件读写失败（{}）", path.display(), io_error(source, lang))
            }
            FileError::Foreign => format!(
                "不是 Ladder Studio 工程文件：第一行必须以 `{MAGIC} v<版本> crc32=<8 位十六进制数>` 开头"
            ),
            FileError::Damaged(h) => format!(
                "第 1 行：工程文件已损坏：文件头 `{h}` 应以 `{MAGIC}` 开头；请用旁边的 .bak 文件恢复，或只读打开以恢复剩余内容"
            ),
            FileError::ByteOrderMark => "工程文件以字节顺序标记（EF BB BF）开头，Ladder Studio 从不写入它：是文本编辑器加上的；请另存为不带 BOM 的 UTF-8，或用 .bak 文件恢复".into(),
            FileError::LineEnds { intact: true } => "工程文件使用 Windows 换行符（CR LF），Ladder Studio 从不这样写：是文本工具或 git 转换的；内容完好，请转换回来（dos2unix 文件名，或设置 git config core.autocrlf false 后重新检出）".into(),
            FileError::LineEnds { intact: false } => "工程文件使用 Windows 换行符（CR LF），Ladder Studio 从不这样写，而且内容另有改动；请用 .bak 文件恢复，或只读打开以恢复剩余内容".into(),
            FileError::FinalNewline { intact: true } => "工程文件缺少结尾的换行符：是编辑器删掉的，其他内容未变；请在文件末尾加一个换行".into(),
            FileError::FinalNewline { intact: false } => "工程文件缺少结尾的换行符：文件被截短了；请用 .bak 文件恢复，或只读打开以恢复剩余内容".into(),
            FileError::Schema {
                version,
                line,
                column,
                message,
            } => format!(
                "第 1 行写的是格式版本 {version}，但内容不是版本 {version} 的工程（第 {line} 行第 {column} 列：{message}）：文件头被改动过；请用 .bak 文件恢复，或只读打开"
            ),
            FileError::Header(h) => format!(
                "第 1 行：文件头格式错误 `{h}`：应为 `{MAGIC} v<版本> crc32=<8 位十六进制数>`"
            ),
            FileError::Version { found } => format!(
                "第 1 行：文件格式版本 {found} 比本程序能读的（最高 {SCHEMA_VERSION}）新；请升级 Ladder Studio"
            ),
            FileError::Checksum { expected, actual } => format!(
                "校验和不符：文件头为 crc32={expected:08x}，文件为 {actual:08x}；文件已损坏或被手工修改（可只读打开，恢复剩余内容）"
            ),
            FileError::Body {
                line,
                column,
                message,
            } => format!("第 {line} 行第 {column} 列：工程内容无法读取（{message}）"),
            FileError::Encoding(b) => format!("文件不是 UTF-8 文本（第 {b} 字节）"),
            FileError::Structure(s) => {
                format!("梯形图结构错误：{}", structure_error(s, Lang::Zh))
            }
        },
    }
}

/// Whether `s` holds a Chinese character (the renderers' tests).
#[cfg(test)]
pub(crate) fn has_cjk(s: &str) -> bool {
    s.chars().any(|c| ('\u{4e00}'..='\u{9fff}').contains(&c))
}

/// Why a subprogram command was refused.
pub fn sub_error(e: &SubError, lang: Lang) -> String {
    match (lang, e) {
        (Lang::En, e) => e.to_string(),
        (Lang::Zh, SubError::Usage { lo, hi }) => {
            format!("{}: P{lo:04}–P{hi:04}", Msg::SubUsage.text(lang))
        }
        (Lang::Zh, SubError::BadName(name)) => {
            format!("`{name}`: {}", Msg::BadSymbolName.text(lang))
        }
        (Lang::Zh, SubError::Exists(n)) => format!("P{n:04}: {}", Msg::SubExists.text(lang)),
        (Lang::Zh, SubError::NoSuch(n)) => format!("P{n:04}: {}", Msg::NoSuchSub.text(lang)),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use ladder_engine::model::{
        BlockKind, NetworkId, NetworkPlace, OperandError, StructureError, WidthError,
    };

    /// The runs of ASCII digits in `text`.
    fn digit_runs(text: &str) -> Vec<&str> {
        text.split(|c: char| !c.is_ascii_digit())
            .filter(|s| !s.is_empty())
            .collect()
    }

    /// Checks that `zh` is Chinese with no English word in it (a block label such as LEVEL1
    /// or P0001 is a name, not a word) and carries every number of `en`. The levels are
    /// words in Chinese (一级程序), so the digits of their labels are not looked for.
    fn assert_chinese_with_numbers(en: &str, zh: &str) {
        assert!(has_cjk(zh), "not Chinese: {zh} (English: {en})");
        for word in zh.split(|c: char| !c.is_ascii_alphanumeric()) {
            let label = matches!(word, "LEVEL1" | "LEVEL2")
                || (word.len() == 5
                    && word.starts_with('P')
                    && word[1..].bytes().all(|b| b.is_ascii_digit()));
            assert!(
                label || !word.bytes().any(|b| b.is_ascii_alphabetic()),
                "English `{word}` in: {zh} (English: {en})"
            );
        }
        let plain = en.replace("LEVEL1", "").replace("LEVEL2", "");
        for digits in digit_runs(&plain) {
            assert!(
                digit_runs(zh).contains(&digits),
                "`{digits}` missing in: {zh} (English: {en})"
            );
        }
    }

    /// The slot of each width error in [`width_examples`]' coverage. No wildcard: a new
    /// variant fails to compile here until it has a slot, and then the tests until it has
    /// an example.
    fn width_slot(e: &WidthError) -> usize {
        match e {
            WidthError::NoRows => 0,
            WidthError::Row { .. } => 1,
        }
    }
    const WIDTH_VARIANTS: usize = 2;

    /// One example or more of every width error.
    fn width_examples() -> Vec<WidthError> {
        let examples = vec![
            WidthError::NoRows,
            WidthError::Row {
                row: 3,
                cells: 10,
                junctions: 11,
                expected: 12,
            },
        ];
        let mut seen = [false; WIDTH_VARIANTS];
        examples.iter().for_each(|e| seen[width_slot(e)] = true);
        assert_eq!(
            seen, [true; WIDTH_VARIANTS],
            "a width error without an example"
        );
        examples
    }

    /// The slot of each structure error, as [`width_slot`].
    fn structure_slot(e: &StructureError) -> usize {
        match e {
            StructureError::Width(_) => 0,
            StructureError::LevelsFirst => 1,
            StructureError::AfterSubprograms(_) => 2,
            StructureError::SubprogramOrder(_) => 3,
            StructureError::Network { .. } => 4,
            StructureError::DuplicateId { .. } => 5,
        }
    }
    const STRUCTURE_VARIANTS: usize = 6;

    /// One example or more of every structure error, every width error among them.
    fn structure_examples() -> Vec<StructureError> {
        let place = |block, network| NetworkPlace { block, network };
        let sub = BlockKind::Sub {
            number: 7,
            name: "spindle".into(),
        };
        let mut examples = vec![
            StructureError::Width(0),
            StructureError::Width(65),
            StructureError::LevelsFirst,
            StructureError::AfterSubprograms(BlockKind::Level2),
            StructureError::SubprogramOrder(3),
            StructureError::DuplicateId {
                at: place(sub.clone(), 5),
                id: NetworkId(41),
                first: place(BlockKind::Level1, 2),
            },
        ];
        for (error, block) in width_examples().into_iter().zip([BlockKind::Level2, sub]) {
            let at = place(block, 4);
            examples.push(StructureError::Network { at, error });
        }
        let mut seen = [false; STRUCTURE_VARIANTS];
        examples.iter().for_each(|e| seen[structure_slot(e)] = true);
        assert_eq!(
            seen, [true; STRUCTURE_VARIANTS],
            "a structure error without an example"
        );
        examples
    }

    #[test]
    fn every_operand_error_reads_in_chinese_in_a_chinese_ui() {
        for text in ["", "12x", "X1.9", "X1.0.0", "D4.1", "R99999", "1ST?"] {
            let e = ladder_engine::model::Operand::parse(text).unwrap_err();
            let zh = operand_error(&e, Lang::Zh);
            assert!(has_cjk(&zh), "{text}: {zh}");
            assert_eq!(operand_error(&e, Lang::En), e.to_string());
        }
        let e = OperandError::Address(ladder_engine::address::AddressError::UnknownArea(
            "Q1".into(),
            "Q".into(),
        ));
        assert!(has_cjk(&operand_error(&e, Lang::Zh)));
    }

    #[test]
    fn every_file_error_reads_in_chinese_in_a_chinese_ui() {
        let io = std::io::Error::new(std::io::ErrorKind::NotFound, "not found");
        for e in [
            FileError::Io {
                path: "a.ldp".into(),
                source: io,
            },
            FileError::Foreign,
            FileError::Header("LADDER".into()),
            FileError::Version { found: 9 },
            FileError::Checksum {
                expected: 1,
                actual: 2,
            },
            FileError::Body {
                line: 3,
                column: 4,
                message: "expected `)`".into(),
            },
            FileError::Encoding(7),
            FileError::Damaged("LADDER-STUDIO-PROJECX v3".into()),
            FileError::ByteOrderMark,
            FileError::LineEnds { intact: true },
            FileError::LineEnds { intact: false },
            FileError::FinalNewline { intact: true },
            FileError::FinalNewline { intact: false },
            FileError::Schema {
                version: 1,
                line: 4,
                column: 2,
                message: "unexpected field".into(),
            },
        ] {
            let zh = file_error(&e, Lang::Zh);
            assert!(has_cjk(&zh), "{zh}");
            assert_eq!(file_error(&e, Lang::En), e.to_string());
        }
        for s in structure_examples() {
            let zh = structure_error(&s, Lang::Zh);
            assert_chinese_with_numbers(&s.to_string(), &zh);
            assert_eq!(structure_error(&s, Lang::En), s.to_string());
            let e = FileError::Structure(s);
            let (en, zh) = (file_error(&e, Lang::En), file_error(&e, Lang::Zh));
            assert_eq!(en, e.to_string());
            assert_chinese_with_numbers(&en, &zh);
        }
        // The English is what docs/files.md and scripts quote: it stays as it was.
        let e = FileError::Structure(StructureError::DuplicateId {
            at: NetworkPlace {
                block: BlockKind::Level2,
                network: 3,
            },
            id: NetworkId(9),
            first: NetworkPlace {
                block: BlockKind::Level1,
                network: 1,
            },
        });
        assert_eq!(
            e.to_string(),
            "the ladder is malformed: LEVEL2 network 3 has the id 9 of LEVEL1 network 1: give it an id no other network has"
        );
        let v = file_error(&FileError::Version { found: 9 }, Lang::Zh);
        assert!(
            v.contains('9') && v.contains(&SCHEMA_VERSION.to_string()),
            "{v}"
        );
    }

    #[test]
    fn every_refusal_reads_in_chinese_in_a_chinese_ui() {
        let missing = [
            Missing::Block,
            Missing::Network,
            Missing::Row,
            Missing::Column,
            Missing::RowOfWidth,
            Missing::LinkPlace,
        ];
        // Every place and rule has an example: the `match`es fail to compile otherwise.
        for m in missing {
            match m {
                Missing::Block
                | Missing::Network
                | Missing::Row
                | Missing::Column
                | Missing::RowOfWidth
                | Missing::LinkPlace => {}
            }
        }
        let rules = [ColumnRule::ContactsLeft, ColumnRule::OutputsRight];
        for r in rules {
            match r {
                ColumnRule::ContactsLeft | ColumnRule::OutputsRight => {}
            }
        }
        for e in missing
            .into_iter()
            .map(EditError::NoSuchPlace)
            .chain(rules.into_iter().map(EditError::WrongColumn))
            .chain([
                EditError::FixedBlock,
                EditError::LastRow,
                EditError::NothingAbove,
            ])
            .chain(width_examples().into_iter().map(EditError::WrongWidth))
        {
            let zh = edit_error(&e, Lang::Zh);
            assert!(
                zh.chars().any(|c| ('\u{4e00}'..='\u{9fff}').contains(&c)),
                "{zh}"
            );
            assert_eq!(edit_error(&e, Lang::En), e.to_string());
            if matches!(e, EditError::NoSuchPlace(_) | EditError::WrongColumn(_)) {
                assert!(!zh.chars().any(|c| c.is_ascii_alphabetic()), "{zh}");
            }
            if let EditError::WrongWidth(w) = &e {
                assert_chinese_with_numbers(&e.to_string(), &zh);
                assert!(zh.ends_with(&width_error_zh(w)), "{zh}");
            }
        }
        assert_eq!(
            EditError::WrongWidth(WidthError::NoRows).to_string(),
            "the network does not fit this ladder: it has no rows"
        );
        let e = EditError::WrongWidth(WidthError::Row {
            row: 2,
            cells: 9,
            junctions: 9,
            expected: 11,
        });
        assert_eq!(
            e.to_string(),
            "the network does not fit this ladder: row 2 has 9 cells and 9 junctions, not 11"
        );
    }
}
