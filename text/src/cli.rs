//! Every text the command line says, in Chinese and English (docs/files.md, "Language").
//!
//! The command line names what it has to say as a [`CliText`] with its data (paths, counts,
//! names) and never words it itself; the words are here, one `match` arm per language, so a
//! missing translation is a compile error. The texts are grouped as the subcommands use
//! them, one enum per family, so each family's `match` stays short. The English is what
//! scripts read (`PATH:…: error: MESSAGE [CODE]`, `N passed, M failed`): change it only with
//! them in mind.

mod coverage;
mod files;
mod print;
mod run;

pub use coverage::{CoverageGroup, CoverageText};
pub use files::{CheckText, Counts, FileText, StartText};
pub use print::PrintText;
pub use run::{CaseFailure, RunText, TestText};

use crate::Lang;

/// A text of the command line, by family.
#[derive(Debug)]
pub enum CliText {
    /// Before any subcommand runs.
    Start(StartText),
    /// A file that could not be read or written.
    File(FileText),
    /// A compile's results and what they stop; the comments CSV imported.
    Check(CheckText),
    /// `sim` and `bench`.
    Run(RunText),
    /// `test`.
    Test(TestText),
    /// Rung coverage.
    Coverage(CoverageText),
    /// `print`.
    Print(PrintText),
}

impl CliText {
    /// The text in `lang`.
    pub fn text(&self, lang: Lang) -> String {
        match self {
            CliText::Start(t) => t.text(lang),
            CliText::File(t) => t.text(lang),
            CliText::Check(t) => t.text(lang),
            CliText::Run(t) => t.text(lang),
            CliText::Test(t) => t.text(lang),
            CliText::Coverage(t) => t.text(lang),
            CliText::Print(t) => t.text(lang),
        }
    }
}

/// `From` each family, so a caller names the text alone (`FileText::NoSuchFile { … }`).
macro_rules! families {
    ($($family:ident => $variant:ident,)*) => {
        $(impl From<$family> for CliText {
            fn from(t: $family) -> CliText {
                CliText::$variant(t)
            }
        })*
    };
}

families! {
    StartText => Start,
    FileText => File,
    CheckText => Check,
    RunText => Run,
    TestText => Test,
    CoverageText => Coverage,
    PrintText => Print,
}

#[cfg(test)]
mod tests {
    use super::*;
    use ladder_engine::coverage::State;
    use ladder_engine::file::FileError;

    /// Each row: an example, the pattern of the variant it is an example of, and the data it
    /// carries. The patterns make one exhaustive `match` (nested enums included), so a new
    /// variant does not compile until it has a row here, and a row cannot be written without
    /// its example; `every_example_is_of_its_own_row` checks that each example is of its row.
    macro_rules! every_text {
        ($($example:expr => $pat:pat => $data:expr;)*) => {
            fn examples() -> Vec<CliText> {
                vec![$(CliText::from($example),)*]
            }

            /// The data of a text, which must show in both languages.
            fn data(t: &CliText) -> Vec<String> {
                match t {
                    $($pat => $data,)*
                }
            }

            #[allow(unused_variables)] // The patterns bind what `data` reads.
            fn rows_hold() -> Vec<(bool, CliText)> {
                vec![$((matches!(CliText::from($example), $pat), CliText::from($example)),)*]
            }
        };
    }

    fn s(x: impl ToString) -> String {
        x.to_string()
    }

    fn counts() -> Counts {
        Counts {
            errors: 7,
            warnings: 13,
        }
    }

    fn n(c: &Counts) -> Vec<String> {
        vec![s(c.errors), s(c.warnings)]
    }

    use CliText::{Check, Coverage, File, Print, Run, Start, Test};

    every_text! {
        StartText::ProjectAndSubcommand => Start(StartText::ProjectAndSubcommand) => vec![];
        StartText::NoProjectOrSubcommand { name: "lathe.ldpx".into() }
            => Start(StartText::NoProjectOrSubcommand { name }) => vec![s(name)];
        StartText::NoDisplay => Start(StartText::NoDisplay) => vec![];
        StartText::NoEditor => Start(StartText::NoEditor) => vec![];

        FileText::CannotRead { path: "in/a.ldp".into(), why: "Permission denied (os error 13)".into() }
            => File(FileText::CannotRead { path, why }) => vec![s(path), s(why)];
        FileText::NoSuchFile { path: "in/a.script".into() }
            => File(FileText::NoSuchFile { path }) => vec![s(path)];
        FileText::NotAProjectFile { path: "in/folder".into() }
            => File(FileText::NotAProjectFile { path }) => vec![s(path)];
        FileText::CannotWrite { path: "out/a.csv".into(), why: "Read-only file system (os error 30)".into() }
            => File(FileText::CannotWrite { path, why }) => vec![s(path), s(why)];
        FileText::NoSuchFolder { path: "missing/out.json".into() }
            => File(FileText::NoSuchFolder { path }) => vec![s(path)];
        FileText::CannotSave { path: "out/b.ldp".into(), error: FileError::Encoding(41) }
            => File(FileText::CannotSave { path, .. }) => vec![s(path), s(41)];
        FileText::CannotOpen { path: "in/c.ldp".into(), error: FileError::Foreign }
            => File(FileText::CannotOpen { path, .. }) => vec![s(path)];
        FileText::NotText { path: "in/blob.bin".into() }
            => File(FileText::NotText { path }) => vec![s(path)];
        FileText::IsAProject { path: "in/d.ldp".into() }
            => File(FileText::IsAProject { path }) => vec![s(path)];

        CheckText::Summary(counts()) => Check(CheckText::Summary(c)) => n(c);
        CheckText::IlNotWritten(counts()) => Check(CheckText::IlNotWritten(c)) => n(c);
        CheckText::NotDrawable(counts()) => Check(CheckText::NotDrawable(c)) => n(c);
        CheckText::NoProjectWritten(counts()) => Check(CheckText::NoProjectWritten(c)) => n(c);
        CheckText::WrittenWithErrors { counts: counts(), path: "out/e.ldp".into() }
            => Check(CheckText::WrittenWithErrors { counts, path }) => [n(counts), vec![s(path)]].concat();
        CheckText::CannotRun(counts()) => Check(CheckText::CannotRun(c)) => n(c);
        CheckText::RowsApplied { rows: 17, path: "in/f.ldp".into() }
            => Check(CheckText::RowsApplied { rows, path }) => vec![s(rows), s(path)];
        CheckText::RowsRejected { rows: 19 } => Check(CheckText::RowsRejected { rows }) => vec![s(rows)];

        RunText::Passed { passed: 23, failed: 29 }
            => Run(RunText::Passed { passed, failed }) => vec![s(passed), s(failed)];
        RunText::NoNativeCode => Run(RunText::NoNativeCode) => vec![];
        RunText::SimProgress { script: "t/a.script".into(), line: 31, done: 3700, of: 9100, percent: 40 }
            => Run(RunText::SimProgress { script, line, done, of, percent })
            => vec![s(script), s(line), s(done), s(of), s(percent)];
        RunText::SimStopped { script: "t/b.script".into(), line: 37, done: 4100, of: 9300, ticks: 12000 }
            => Run(RunText::SimStopped { script, line, done, of, ticks })
            => vec![s(script), s(line), s(done), s(of), s(ticks)];
        RunText::BenchProgress { timed: 43000, scans: 97000, percent: 44 }
            => Run(RunText::BenchProgress { timed, scans, percent }) => vec![s(timed), s(scans), s(percent)];
        RunText::BenchHalted { why: "LEVEL2 N0003: division by zero".into() }
            => Run(RunText::BenchHalted { why }) => vec![s(why)];
        RunText::BenchStopped { timed: 47000, scans: 98000 }
            => Run(RunText::BenchStopped { timed, scans }) => vec![s(timed), s(scans)];
        RunText::SetUpFailed => Run(RunText::SetUpFailed) => vec![];
        RunText::NoValgrind { why: "No such file or directory (os error 2)".into() }
            => Run(RunText::NoValgrind { why }) => vec![s(why)];
        RunText::CountFailed { why: "exit status: 1 boom".into() }
            => Run(RunText::CountFailed { why }) => vec![s(why)];
        RunText::NoTotal => Run(RunText::NoTotal) => vec![];

        TestText::NoTestFolder { folder: "p/lathe.tests".into(), why: "No such file or directory (os error 2)".into() }
            => Test(TestText::NoTestFolder { folder, why }) => vec![s(folder), s(why)];
        TestText::NoScripts { folder: "p/mill.tests".into() }
            => Test(TestText::NoScripts { folder }) => vec![s(folder)];
        TestText::CaseOk { name: "lathe.tests/a.script".into(), checks: 53 }
            => Test(TestText::CaseOk { name, checks }) => vec![s(name), s(checks)];
        TestText::CaseFailed { name: "lathe.tests/b.script".into(), why: CaseFailure::CannotRun }
            => Test(TestText::CaseFailed { name, why: CaseFailure::CannotRun }) => vec![s(name)];
        TestText::CaseFailed { name: "lathe.tests/c.script".into(), why: CaseFailure::Stopped }
            => Test(TestText::CaseFailed { name, why: CaseFailure::Stopped }) => vec![s(name)];
        TestText::CaseFailed { name: "lathe.tests/d.script".into(), why: CaseFailure::Checks { failed: 59, checks: 61 } }
            => Test(TestText::CaseFailed { name, why: CaseFailure::Checks { failed, checks } })
            => vec![s(name), s(failed), s(checks)];

        CoverageText::Line { group: CoverageGroup::Level1, covered: 67, networks: 71, percent: 94, elements_covered: 401, elements: 409 }
            => Coverage(CoverageText::Line { group: CoverageGroup::Level1, covered, networks, percent, elements_covered, elements })
            => vec![s(covered), s(networks), s(percent), s(elements_covered), s(elements)];
        CoverageText::Line { group: CoverageGroup::Level2, covered: 73, networks: 79, percent: 92, elements_covered: 419, elements: 421 }
            => Coverage(CoverageText::Line { group: CoverageGroup::Level2, covered, networks, percent, elements_covered, elements })
            => vec![s(covered), s(networks), s(percent), s(elements_covered), s(elements)];
        CoverageText::Line { group: CoverageGroup::Subprograms, covered: 83, networks: 89, percent: 93, elements_covered: 431, elements: 433 }
            => Coverage(CoverageText::Line { group: CoverageGroup::Subprograms, covered, networks, percent, elements_covered, elements })
            => vec![s(covered), s(networks), s(percent), s(elements_covered), s(elements)];
        CoverageText::Title { project: "lathe.ldp".into() }
            => Coverage(CoverageText::Title { project }) => vec![s(project)];
        CoverageText::RunsMerged { runs: 97 } => Coverage(CoverageText::RunsMerged { runs }) => vec![s(runs)];
        CoverageText::NotFullyCovered { networks: 101 }
            => Coverage(CoverageText::NotFullyCovered { networks }) => vec![s(networks)];
        CoverageText::ElementHeading => Coverage(CoverageText::ElementHeading) => vec![];
        CoverageText::StateHeading => Coverage(CoverageText::StateHeading) => vec![];
        CoverageText::SeenHeading => Coverage(CoverageText::SeenHeading) => vec![];
        CoverageText::State(State::Covered) => Coverage(CoverageText::State(State::Covered)) => vec![];
        CoverageText::State(State::Half) => Coverage(CoverageText::State(State::Half)) => vec![];
        CoverageText::State(State::Never) => Coverage(CoverageText::State(State::Never)) => vec![];

        PrintText::OutputKind { path: "out/doc.txt".into() }
            => Print(PrintText::OutputKind { path }) => vec![s(path)];
        PrintText::BadDate { date: "2026-13-40".into() } => Print(PrintText::BadDate { date }) => vec![s(date)];
        PrintText::BlockNotPrinted { network: "LEVEL2:3".into() }
            => Print(PrintText::BlockNotPrinted { network }) => vec![s(network)];
        PrintText::PageRange { page: 103, total: 107 }
            => Print(PrintText::PageRange { page, total }) => vec![s(page), s(total)];
        PrintText::Pages { path: "out/doc.pdf".into(), pages: 109 }
            => Print(PrintText::Pages { path, pages }) => vec![s(path), s(pages)];
    }

    fn has_cjk(t: &str) -> bool {
        t.chars().any(|c| ('\u{4e00}'..='\u{9fff}').contains(&c))
    }

    #[test]
    fn every_example_is_of_its_own_row() {
        for (held, t) in rows_hold() {
            assert!(held, "{t:?} is not of the variant of its row");
        }
    }

    #[test]
    fn every_text_speaks_both_languages_and_carries_its_data() {
        let all = examples();
        assert!(all.len() >= 50, "{} rows", all.len());
        for t in &all {
            let (zh, en) = (t.text(Lang::Zh), t.text(Lang::En));
            assert!(!zh.trim().is_empty() && !en.trim().is_empty(), "{t:?}");
            assert_ne!(zh, en, "{t:?}");
            let data = data(t);
            for d in &data {
                assert!(zh.contains(d.as_str()), "{t:?}: {d} missing from {zh}");
                assert!(en.contains(d.as_str()), "{t:?}: {d} missing from {en}");
            }
            // Words in the English (beyond the data) are words in the Chinese too.
            let mut own = en.clone();
            for d in &data {
                own = own.replace(d.as_str(), "");
            }
            if own.chars().any(|c| c.is_ascii_alphabetic()) {
                assert!(has_cjk(&zh), "{t:?}: no Chinese in {zh}");
            }
        }
    }

    #[test]
    fn the_english_lines_keep_the_shapes_scripts_read() {
        let en = |t: CliText| t.text(Lang::En);
        let one = Counts {
            errors: 1,
            warnings: 0,
        };
        assert_eq!(en(CheckText::Summary(one).into()), "1 error, 0 warnings");
        assert_eq!(
            en(CheckText::Summary(counts()).into()),
            "7 errors, 13 warnings"
        );
        assert_eq!(
            CliText::from(CheckText::Summary(one)).text(Lang::Zh),
            "1 个错误，0 个警告"
        );
        assert_eq!(
            en(RunText::Passed {
                passed: 3,
                failed: 0
            }
            .into()),
            "3 passed, 0 failed"
        );
        assert_eq!(
            en(FileText::NoSuchFile {
                path: "a.script".into()
            }
            .into()),
            "cannot read a.script: no such file"
        );
        assert_eq!(
            CaseFailure::Checks {
                failed: 1,
                checks: 4
            }
            .text(Lang::En),
            "1 of 4 checks failed"
        );
    }
}
