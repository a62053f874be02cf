//! Why a comments CSV could not be imported, in the user's language.

use crate::Lang;
use ladder_engine::comments::CommentsError;

/// Why a comments CSV could not be imported, in `lang`. The CSV reader's reason and a
/// rejected row's reason stay as they were said (the command line prints rejected rows
/// itself, one a line).
pub fn comments_error(e: &CommentsError, lang: Lang) -> String {
    match lang {
        Lang::En => e.to_string(),
        Lang::Zh => match e {
            CommentsError::Csv { line, message } => format!("第 {line} 行：{message}"),
            CommentsError::Header => {
                "第 1 行：表头必须列出 kind、table、key、symbol 列，以及每种语言一列".into()
            }
            CommentsError::Rejected(rows) => {
                let mut text = format!("{} 行被拒绝，未作任何改动：", rows.len());
                for (line, why) in rows {
                    text.push_str(&format!("\n第 {line} 行：{why}"));
                }
                text
            }
        },
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The slot of each error, with no wildcard (see `build.rs`).
    fn slot(e: &CommentsError) -> usize {
        match e {
            CommentsError::Csv { .. } => 0,
            CommentsError::Header => 1,
            CommentsError::Rejected(_) => 2,
        }
    }
    const VARIANTS: usize = 3;

    #[test]
    fn every_comments_error_reads_in_chinese_and_keeps_its_english() {
        let examples = [
            CommentsError::Csv {
                line: 4,
                message: "found record with 3 fields, but the previous record has 5 fields".into(),
            },
            CommentsError::Header,
            CommentsError::Rejected(vec![(2, "R9999: no such address".into())]),
        ];
        let mut seen = [false; VARIANTS];
        for e in &examples {
            seen[slot(e)] = true;
            let zh = comments_error(e, Lang::Zh);
            assert!(crate::errors::has_cjk(&zh), "{zh}");
            assert!(!zh.contains("line ") && !zh.contains("header"), "{zh}");
            assert_eq!(comments_error(e, Lang::En), e.to_string());
        }
        assert_eq!(
            seen, [true; VARIANTS],
            "a comments error without an example"
        );
        assert_eq!(
            CommentsError::Header.to_string(),
            "line 1: the header must name the columns kind,table,key,symbol and one per language"
        );
    }
}
