//! Why rung coverage reports cannot be merged or read, in the user's language.

use crate::Lang;
use ladder_engine::coverage::{CoverageError, Differs};

/// Why two coverage reports cannot be merged, or a file is not one, in `lang`. A file that is
/// not a report keeps the JSON reader's reason as it said it.
pub fn coverage_error(e: &CoverageError, lang: Lang) -> String {
    match lang {
        Lang::En => e.to_string(),
        Lang::Zh => match e {
            CoverageError::NotCoverage(why) => format!("不是覆盖率文件：{why}"),
            CoverageError::OtherProgram(Differs::Count { ours, theirs }) => {
                format!("覆盖率属于另一个程序（网络数 {ours} 与 {theirs} 不同）")
            }
            CoverageError::OtherProgram(Differs::Network { block, number }) => {
                format!("覆盖率属于另一个程序（网络 {block} N{number:04} 不同）")
            }
        },
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The slot of each error, with no wildcard (see `build.rs`).
    fn slot(e: &CoverageError) -> usize {
        match e {
            CoverageError::NotCoverage(_) => 0,
            CoverageError::OtherProgram(Differs::Count { .. }) => 1,
            CoverageError::OtherProgram(Differs::Network { .. }) => 2,
        }
    }
    const VARIANTS: usize = 3;

    #[test]
    fn every_coverage_error_reads_in_chinese_and_keeps_its_english() {
        let examples = [
            CoverageError::NotCoverage("expected value at line 1 column 1".into()),
            CoverageError::OtherProgram(Differs::Count {
                ours: 12,
                theirs: 13,
            }),
            CoverageError::OtherProgram(Differs::Network {
                block: "LEVEL2".into(),
                number: 3,
            }),
        ];
        let mut seen = [false; VARIANTS];
        for e in &examples {
            seen[slot(e)] = true;
            let zh = coverage_error(e, Lang::Zh);
            assert!(crate::errors::has_cjk(&zh), "{zh}");
            assert!(!zh.contains("program") && !zh.contains("against"), "{zh}");
            assert_eq!(coverage_error(e, Lang::En), e.to_string());
        }
        assert_eq!(
            seen, [true; VARIANTS],
            "a coverage error without an example"
        );
        // The English is what it was before the reasons were typed.
        assert_eq!(
            examples[1].to_string(),
            "the coverage is of another program (network 12 networks against 13 differs)"
        );
        assert_eq!(
            examples[2].to_string(),
            "the coverage is of another program (network LEVEL2 N0003 differs)"
        );
    }
}
