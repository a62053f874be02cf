//! The words of [`ScenarioFinding`]: each finding in English and in Chinese, side by side.

use crate::Lang;
use crate::script::{broken_scenario, name_error};
use ladder_engine::compiler::ScenarioFinding;

/// What `f` found and how to fix it, in `lang`.
pub(super) fn text(f: &ScenarioFinding, lang: Lang) -> String {
    match f {
        ScenarioFinding::Name(e) => name_error(e, lang),
        ScenarioFinding::Line { scenario, error } => broken_scenario(scenario, error, lang),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bilingual::assert_bilingual;
    use ladder_engine::scenario::NameError;
    use ladder_engine::sim::{ScenarioReason, ScriptError};

    /// The slot of each finding; no wildcard, so a new variant does not compile here until it
    /// has one, and the test fails until it has an example.
    fn slot(f: &ScenarioFinding) -> usize {
        match f {
            ScenarioFinding::Name(NameError::Empty) => 0,
            ScenarioFinding::Name(NameError::Malformed { .. }) => 1,
            ScenarioFinding::Name(NameError::Taken { .. }) => 2,
            ScenarioFinding::Line { .. } => 3,
        }
    }
    const VARIANTS: usize = 4;

    #[test]
    fn every_finding_reads_in_both_languages_with_its_words() {
        let line = ScenarioFinding::Line {
            scenario: "typo".into(),
            error: ScriptError {
                line: 2,
                reason: ScenarioReason::NotScenarioLine {
                    verb: "frce".into(),
                }
                .into(),
            },
        };
        let examples = [
            ScenarioFinding::Name(NameError::Empty),
            ScenarioFinding::Name(NameError::Malformed {
                name: "two words".into(),
            }),
            ScenarioFinding::Name(NameError::Taken {
                name: "good".into(),
            }),
            line.clone(),
        ];
        let mut seen = [false; VARIANTS];
        for f in &examples {
            seen[slot(f)] = true;
            assert_bilingual(&text(f, Lang::En), &text(f, Lang::Zh));
        }
        assert_eq!(seen, [true; VARIANTS], "a finding without an example");
        assert_eq!(
            text(&examples[2], Lang::En),
            "scenario name `good` is already used; give each scenario its own"
        );
        assert_eq!(
            text(&examples[1], Lang::Zh),
            "场景名称 `two words`：最多 32 个字母、数字、`_` 或 `-`（脚本行会用到它）"
        );
        assert_eq!(
            text(&line, Lang::En),
            "scenario `typo`, line 2: `frce` cannot be part of a scenario: its lines are `set`, `force`, `panel` and `device NAME fault …`"
        );
        assert_eq!(
            text(&line, Lang::Zh),
            "场景 `typo` 第 2 行：`frce` 不能用在场景中：场景的行只能是 `set`、`force`、`panel` 和 `device NAME fault …`"
        );
    }
}
