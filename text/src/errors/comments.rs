//! Why a comments CSV could not be imported, in the user's language.

use crate::Lang;
use crate::diagnostics;
use ladder_engine::comments::{CommentsError, Rejection};
use ladder_engine::compiler::Code;

/// Why a comments CSV could not be imported, in `lang`, each rejected row on a line of its
/// own. The CSV reader's reason and a row's own reason stay as they were said (they quote
/// the CSV).
pub fn comments_error(e: &CommentsError, lang: Lang) -> String {
    match (e, lang) {
        (CommentsError::Rejected(rows), Lang::En) => {
            let mut text = format!("{} row(s) rejected, nothing changed:", rows.len());
            for (line, why) in rows {
                text.push_str(&format!("\nline {line}: {}", rejection(why, lang)));
            }
            text
        }
        (_, Lang::En) => e.to_string(),
        (CommentsError::Csv { line, message }, Lang::Zh) => format!("第 {line} 行：{message}"),
        (CommentsError::Header, Lang::Zh) => {
            "第 1 行：表头必须列出 kind、table、key、symbol 列，以及每种语言一列".into()
        }
        (CommentsError::Rejected(rows), Lang::Zh) => {
            let mut text = format!("{} 行被拒绝，未作任何改动：", rows.len());
            for (line, why) in rows {
                text.push_str(&format!("\n第 {line} 行：{}", rejection(why, lang)));
            }
            text
        }
    }
}

/// Why one row of a comments CSV is refused, in `lang`: the row's own reason as it was
/// said, or the error `check` would report after the import, where, and what to do.
pub fn rejection(r: &Rejection, lang: Lang) -> String {
    let d = match r {
        Rejection::Row(why) => return why.clone(),
        Rejection::WouldBreak(d) => d,
    };
    let code = d.code.as_str();
    let place = diagnostics::place(&d.location, lang);
    let message = diagnostics::message(d, lang);
    let renamed = d.code == Code::L020UndefinedSymbol;
    match lang {
        Lang::En => {
            let fix = if renamed {
                "rename its uses in the ladder first (replace), or keep the name"
            } else {
                "correct the row, or the project first"
            };
            format!("after the import `check` would report {code} at {place}: {message} ({fix})")
        }
        Lang::Zh => {
            let fix = if renamed {
                "请先在梯形图中替换它的各处用法，或保留原名"
            } else {
                "请改正该行，或先改正工程"
            };
            format!("导入后 `check` 将在 {place} 报告 {code}：{message}（{fix}）")
        }
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
            CommentsError::Rejected(vec![(2, Rejection::Row("R9999: no such address".into()))]),
        ];
        let mut seen = [false; VARIANTS];
        for e in &examples {
            seen[slot(e)] = true;
            let zh = comments_error(e, Lang::Zh);
            assert!(crate::errors::has_cjk(&zh), "{zh}");
            assert!(!zh.contains("line ") && !zh.contains("header"), "{zh}");
            assert!(comments_error(e, Lang::En).starts_with(&e.to_string()));
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
