//! The command line's words while it runs the program: `sim`, `bench` (with callgrind's
//! count) and `test`, a project's test folder.

use crate::Lang;

/// What `sim` and `bench` say.
#[derive(Debug)]
pub enum RunText {
    /// `N passed, M failed`: the last line of `sim` (checks) and `test` (scripts).
    Passed {
        /// Checks or scripts that passed.
        passed: usize,
        /// Checks or scripts that failed.
        failed: usize,
    },
    /// `--engine native` asked for where no native code can be made.
    NoNativeCode,
    /// A progress line of a long `sim`.
    SimProgress {
        /// The script, as named on the command line.
        script: String,
        /// The script line running.
        line: usize,
        /// Ticks of that line run.
        done: u64,
        /// Ticks the line asks for.
        of: u64,
        /// `done` in whole percent of `of`.
        percent: u64,
    },
    /// A `sim` stopped by Ctrl+C.
    SimStopped {
        /// The script, as named on the command line.
        script: String,
        /// The script line it stopped in.
        line: usize,
        /// Ticks of that line run.
        done: u64,
        /// Ticks the line asked for.
        of: u64,
        /// Ticks run in all.
        ticks: u64,
    },
    /// A progress line of a long `bench`.
    BenchProgress {
        /// Scans timed.
        timed: u64,
        /// Scans asked for.
        scans: u64,
        /// `timed` in whole percent of `scans`.
        percent: u64,
    },
    /// The PLC halted while `bench` timed it.
    BenchHalted {
        /// The halt, already in the language asked for.
        why: String,
    },
    /// A `bench` stopped by Ctrl+C.
    BenchStopped {
        /// Scans timed.
        timed: u64,
        /// Scans asked for.
        scans: u64,
    },
    /// `bench --script`'s set-up script failed.
    SetUpFailed,
    /// `bench --instructions` could not start valgrind.
    NoValgrind {
        /// The system's reason.
        why: String,
    },
    /// A run under callgrind failed.
    CountFailed {
        /// What went wrong, as the run said it.
        why: String,
    },
    /// A run under callgrind printed no total (its `Collected :` line).
    NoTotal,
}

impl RunText {
    /// The text in `lang`.
    pub fn text(&self, lang: Lang) -> String {
        match (self, lang) {
            (RunText::Passed { passed, failed }, Lang::Zh) => {
                format!("{passed} 项通过，{failed} 项失败")
            }
            (RunText::Passed { passed, failed }, Lang::En) => {
                format!("{passed} passed, {failed} failed")
            }
            (RunText::NoNativeCode, Lang::Zh) => "本机无法生成本机代码：扫描由解释器执行".into(),
            (RunText::NoNativeCode, Lang::En) => {
                "native code is unavailable on this machine: the interpreter runs the scan".into()
            }
            (
                RunText::SimProgress {
                    script,
                    line,
                    done,
                    of,
                    percent,
                },
                Lang::Zh,
            ) => format!(
                "{script}:{line}：已运行 {done} / {of} 个节拍（{percent}%）；按 Ctrl+C 停止并给出已有结果"
            ),
            (
                RunText::SimProgress {
                    script,
                    line,
                    done,
                    of,
                    percent,
                },
                Lang::En,
            ) => format!(
                "{script}:{line}: {done} of {of} ticks ({percent}%); Ctrl+C stops with the results so far"
            ),
            (
                RunText::SimStopped {
                    script,
                    line,
                    done,
                    of,
                    ticks,
                },
                Lang::Zh,
            ) => format!(
                "{script}:{line}：按 Ctrl+C 停止，本行已运行 {done} / {of} 个节拍，共 {ticks} 个；已有结果如下："
            ),
            (
                RunText::SimStopped {
                    script,
                    line,
                    done,
                    of,
                    ticks,
                },
                Lang::En,
            ) => format!(
                "{script}:{line}: stopped by Ctrl+C after {done} of {of} ticks of this line, {ticks} in all; the results so far:"
            ),
            (
                RunText::BenchProgress {
                    timed,
                    scans,
                    percent,
                },
                Lang::Zh,
            ) => format!(
                "已计时 {timed} / {scans} 次扫描（{percent}%）；按 Ctrl+C 停止并给出已有结果"
            ),
            (
                RunText::BenchProgress {
                    timed,
                    scans,
                    percent,
                },
                Lang::En,
            ) => format!(
                "{timed} of {scans} scans ({percent}%); Ctrl+C stops with the figures so far"
            ),
            (RunText::BenchHalted { why }, Lang::Zh) => format!("计时中 PLC 停止：{why}"),
            (RunText::BenchHalted { why }, Lang::En) => {
                format!("the PLC halted during the benchmark: {why}")
            }
            (RunText::BenchStopped { timed, scans }, Lang::Zh) => {
                format!("按 Ctrl+C 停止，已计时 {timed} / {scans} 次扫描；结果按已计时的扫描计算")
            }
            (RunText::BenchStopped { timed, scans }, Lang::En) => {
                format!("stopped by Ctrl+C after {timed} of {scans} scans; the figures cover those")
            }
            (RunText::SetUpFailed, Lang::Zh) => "准备脚本失败；未计时".into(),
            (RunText::SetUpFailed, Lang::En) => {
                "the set-up script failed; nothing was timed".into()
            }
            (RunText::NoValgrind { why }, Lang::Zh) => {
                format!("无法启动 valgrind（{why}）：请用 `scripts/setup-debian.sh --bench` 安装")
            }
            (RunText::NoValgrind { why }, Lang::En) => format!(
                "cannot start valgrind ({why}): install it with `scripts/setup-debian.sh --bench`"
            ),
            (RunText::CountFailed { why }, Lang::Zh) => format!("在 callgrind 下计数失败：{why}"),
            (RunText::CountFailed { why }, Lang::En) => {
                format!("counting under callgrind failed: {why}")
            }
            (RunText::NoTotal, Lang::Zh) => {
                "在 callgrind 下计数失败：输出中没有 `Collected :` 行".into()
            }
            (RunText::NoTotal, Lang::En) => {
                "counting under callgrind failed: no `Collected :` line".into()
            }
        }
    }
}

/// What `test` says about its folder and each script.
#[derive(Debug)]
pub enum TestText {
    /// The project has no test folder.
    NoTestFolder {
        /// The folder looked for.
        folder: String,
        /// The system's reason.
        why: String,
    },
    /// The test folder holds no script.
    NoScripts {
        /// The folder.
        folder: String,
    },
    /// A script that passed.
    CaseOk {
        /// The script, as `FOLDER/NAME.script`.
        name: String,
        /// Its checks.
        checks: usize,
    },
    /// A script that did not pass.
    CaseFailed {
        /// The script, as `FOLDER/NAME.script`.
        name: String,
        /// Why.
        why: CaseFailure,
    },
}

impl TestText {
    /// The text in `lang`.
    pub fn text(&self, lang: Lang) -> String {
        match (self, lang) {
            (TestText::NoTestFolder { folder, why }, Lang::Zh) => {
                format!("{folder}：没有测试文件夹（{why}）；请把工程的脚本以 NAME.script 放入其中")
            }
            (TestText::NoTestFolder { folder, why }, Lang::En) => format!(
                "{folder}: no test folder ({why}); put the project's scripts in it as NAME.script"
            ),
            (TestText::NoScripts { folder }, Lang::Zh) => {
                format!("{folder}：没有可运行的 .script 文件")
            }
            (TestText::NoScripts { folder }, Lang::En) => {
                format!("{folder}: no .script files to run")
            }
            // The two-space gap lines the names up under `ok    ` and `FAIL  `.
            (TestText::CaseOk { name, checks }, Lang::Zh) => {
                format!("通过  {name}（{checks} 项检查）")
            }
            (TestText::CaseOk { name, checks }, Lang::En) => {
                format!("ok    {name} ({checks} checks)")
            }
            (TestText::CaseFailed { name, why }, Lang::Zh) => {
                format!("失败  {name}（{}）", why.text(lang))
            }
            (TestText::CaseFailed { name, why }, Lang::En) => {
                format!("FAIL  {name} ({})", why.text(lang))
            }
        }
    }
}

/// Why a script of a test folder did not pass. Also the message of its JUnit failure, in
/// English there whatever the language, as CI servers show it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CaseFailure {
    /// The program or the script could not run at all.
    CannotRun,
    /// Ctrl+C stopped it.
    Stopped,
    /// Checks failed.
    Checks {
        /// Checks that failed.
        failed: usize,
        /// Checks in all.
        checks: usize,
    },
}

impl CaseFailure {
    /// The text in `lang`.
    pub fn text(self, lang: Lang) -> String {
        match (self, lang) {
            (CaseFailure::CannotRun, Lang::Zh) => "无法运行".into(),
            (CaseFailure::CannotRun, Lang::En) => "cannot run".into(),
            (CaseFailure::Stopped, Lang::Zh) => "按 Ctrl+C 停止".into(),
            (CaseFailure::Stopped, Lang::En) => "stopped by Ctrl+C".into(),
            (CaseFailure::Checks { failed, checks }, Lang::Zh) => {
                format!("{checks} 项检查中 {failed} 项失败")
            }
            (CaseFailure::Checks { failed, checks }, Lang::En) => {
                format!("{failed} of {checks} checks failed")
            }
        }
    }
}
