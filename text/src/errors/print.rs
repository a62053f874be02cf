//! Why a print could not be made, in the user's language: the networks asked for
//! ([`NetworksError`]) and the PDF writer ([`PdfError`]).

use crate::Lang;
use ladder_print::PdfError;
use ladder_print::options::NetworksError;

/// Why `BLOCK:N` or `BLOCK:FIRST-LAST` names no networks, in `lang`. Block labels (LEVEL2,
/// P0001) are names, the same in both languages.
pub fn networks_error(e: &NetworksError, lang: Lang) -> String {
    match lang {
        Lang::En => e.to_string(),
        Lang::Zh => match e {
            NetworksError::Form { text } => {
                format!("`{text}`：网络应写成 程序块:编号，例如 LEVEL2:3")
            }
            NetworksError::NoSuchBlock { block } => {
                format!("`{block}`：没有这个程序块（应为 LEVEL1、LEVEL2 或子程序 P0001…）")
            }
            NetworksError::Range {
                numbers,
                block,
                count,
            } => format!(
                "`{numbers}`：{block} 的网络为 1 到 {count}（写编号 N 或范围 起-止，例如 10-40）"
            ),
        },
    }
}

/// Why the PDF could not be made, in `lang`; the PDF writer's own reason stays as it said it.
pub fn pdf_error(e: &PdfError, lang: Lang) -> String {
    match lang {
        Lang::En => e.to_string(),
        Lang::Zh => match e {
            PdfError::Font => "无法使用内置字体".into(),
            PdfError::Write(why) => format!("无法写出 PDF：{why}"),
        },
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The slot of each networks error, with no wildcard (see `build.rs`).
    fn slot(e: &NetworksError) -> usize {
        match e {
            NetworksError::Form { .. } => 0,
            NetworksError::NoSuchBlock { .. } => 1,
            NetworksError::Range { .. } => 2,
        }
    }
    const VARIANTS: usize = 3;

    #[test]
    fn every_networks_error_reads_in_chinese_and_keeps_its_english() {
        let examples = [
            NetworksError::Form {
                text: "LEVEL2".into(),
            },
            NetworksError::NoSuchBlock {
                block: "LEVEL9".into(),
            },
            NetworksError::Range {
                numbers: "10-4".into(),
                block: "LEVEL2".into(),
                count: 7,
            },
        ];
        let mut seen = [false; VARIANTS];
        for e in &examples {
            seen[slot(e)] = true;
            let zh = networks_error(e, Lang::Zh);
            assert!(crate::errors::has_cjk(&zh), "{zh}");
            assert!(!zh.contains("write") && !zh.contains("block"), "{zh}");
            assert_eq!(networks_error(e, Lang::En), e.to_string());
        }
        assert_eq!(
            seen, [true; VARIANTS],
            "a networks error without an example"
        );
    }

    #[test]
    fn every_pdf_error_reads_in_chinese_and_keeps_its_english() {
        for e in [PdfError::Font, PdfError::Write("stream too long".into())] {
            // No wildcard: a new variant fails to compile here until it has an example.
            match &e {
                PdfError::Font | PdfError::Write(_) => {}
            }
            let zh = pdf_error(&e, Lang::Zh);
            assert!(crate::errors::has_cjk(&zh), "{zh}");
            assert!(!zh.contains("cannot"), "{zh}");
            assert_eq!(pdf_error(&e, Lang::En), e.to_string());
        }
    }
}
