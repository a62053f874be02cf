//! The command line's words about rung coverage: the summary lines `sim` and `test` print and
//! the texts of the HTML page (docs/scripts.md, "Coverage").

use crate::Lang;
use ladder_engine::coverage::State;

/// A group of blocks of the coverage summary.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CoverageGroup {
    /// Level 1.
    Level1,
    /// Level 2.
    Level2,
    /// Every subprogram.
    Subprograms,
}

impl CoverageGroup {
    /// The group a summary line names (`LEVEL1`, `LEVEL2`, `SUB`).
    pub fn of(code: &str) -> CoverageGroup {
        match code {
            "LEVEL1" => CoverageGroup::Level1,
            "LEVEL2" => CoverageGroup::Level2,
            _ => CoverageGroup::Subprograms,
        }
    }

    fn text(self, lang: Lang) -> &'static str {
        match (self, lang) {
            (CoverageGroup::Level1, Lang::Zh) => "一级程序",
            (CoverageGroup::Level1, Lang::En) => "level 1",
            (CoverageGroup::Level2, Lang::Zh) => "二级程序",
            (CoverageGroup::Level2, Lang::En) => "level 2",
            (CoverageGroup::Subprograms, Lang::Zh) => "子程序",
            (CoverageGroup::Subprograms, Lang::En) => "subprograms",
        }
    }
}

/// What the coverage summary and page say.
#[derive(Debug)]
pub enum CoverageText {
    /// A summary line: `level 2: 412/520 networks fully covered, 78 % (…)`.
    Line {
        /// The blocks counted.
        group: CoverageGroup,
        /// Networks fully covered.
        covered: usize,
        /// Networks with elements.
        networks: usize,
        /// `covered` in whole percent of `networks`.
        percent: usize,
        /// Elements covered.
        elements_covered: usize,
        /// Elements.
        elements: usize,
    },
    /// The page's title.
    Title {
        /// The project's file name, escaped for HTML.
        project: String,
    },
    /// How many runs the page merges.
    RunsMerged {
        /// Runs.
        runs: u32,
    },
    /// The heading over the networks listed.
    NotFullyCovered {
        /// Networks not fully covered.
        networks: usize,
    },
    /// The heading of the elements' column.
    ElementHeading,
    /// The heading of the states' column.
    StateHeading,
    /// The heading of the column of values seen.
    SeenHeading,
    /// How far an element was exercised.
    State(State),
}

impl CoverageText {
    /// The text in `lang`.
    pub fn text(&self, lang: Lang) -> String {
        match (self, lang) {
            (
                CoverageText::Line {
                    group,
                    covered,
                    networks,
                    percent,
                    elements_covered,
                    elements,
                },
                Lang::Zh,
            ) => format!(
                "{}：{covered}/{networks} 个网络完全覆盖，{percent} %（元素 {elements_covered}/{elements}）",
                group.text(lang)
            ),
            (
                CoverageText::Line {
                    group,
                    covered,
                    networks,
                    percent,
                    elements_covered,
                    elements,
                },
                Lang::En,
            ) => format!(
                "{}: {covered}/{networks} networks fully covered, {percent} % ({elements_covered}/{elements} elements)",
                group.text(lang)
            ),
            (CoverageText::Title { project }, Lang::Zh) => format!("{project} 的梯形图覆盖率"),
            (CoverageText::Title { project }, Lang::En) => format!("Rung coverage of {project}"),
            (CoverageText::RunsMerged { runs }, Lang::Zh) => format!("合并了 {runs} 次运行。"),
            (CoverageText::RunsMerged { runs }, Lang::En) => format!("{runs} runs merged."),
            (CoverageText::NotFullyCovered { networks }, Lang::Zh) => {
                format!("{networks} 个网络未完全覆盖")
            }
            (CoverageText::NotFullyCovered { networks }, Lang::En) => {
                format!("{networks} networks not fully covered")
            }
            (CoverageText::ElementHeading, Lang::Zh) => "元素".into(),
            (CoverageText::ElementHeading, Lang::En) => "Element".into(),
            (CoverageText::StateHeading, Lang::Zh) => "状态".into(),
            (CoverageText::StateHeading, Lang::En) => "State".into(),
            (CoverageText::SeenHeading, Lang::Zh) => "见到".into(),
            (CoverageText::SeenHeading, Lang::En) => "Seen".into(),
            (CoverageText::State(State::Covered), Lang::Zh) => "已覆盖".into(),
            (CoverageText::State(State::Covered), Lang::En) => "covered".into(),
            (CoverageText::State(State::Half), Lang::Zh) => "部分".into(),
            (CoverageText::State(State::Half), Lang::En) => "half".into(),
            (CoverageText::State(State::Never), Lang::Zh) => "从未".into(),
            (CoverageText::State(State::Never), Lang::En) => "never".into(),
        }
    }
}
