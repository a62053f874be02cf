//! The command line's words about starting up, reading and writing files, and the compile
//! results of `check`, `export-il`, `import-il`, the comments CSV and every command that
//! needs a program or a drawing.

use crate::Lang;
use crate::errors::file_error;
use ladder_engine::compiler::Compiled;
use ladder_engine::file::FileError;

/// What the command line says before any subcommand runs.
#[derive(Debug)]
pub enum StartText {
    /// A project (or `--run`) given with a subcommand.
    ProjectAndSubcommand,
    /// The one argument is neither a project file that exists nor a subcommand.
    NoProjectOrSubcommand {
        /// The argument as given.
        name: String,
    },
    /// The editor was asked for without a graphical session.
    NoDisplay,
    /// The editor was asked for in a program built without it (the tests' entry point).
    NoEditor,
}

impl StartText {
    /// The text in `lang`.
    pub fn text(&self, lang: Lang) -> String {
        match (self, lang) {
            (StartText::ProjectAndSubcommand, Lang::Zh) => {
                "要打开的工程（或 --run）不能与子命令同时给出（见 --help）".into()
            }
            (StartText::ProjectAndSubcommand, Lang::En) => {
                "a project to open (or --run) and a subcommand cannot be given together (see --help)"
                    .into()
            }
            (StartText::NoProjectOrSubcommand { name }, Lang::Zh) => {
                format!("没有工程文件或子命令 `{name}`（见 --help）")
            }
            (StartText::NoProjectOrSubcommand { name }, Lang::En) => {
                format!("no project file or subcommand `{name}` (see --help)")
            }
            (StartText::NoDisplay, Lang::Zh) => {
                "编辑器需要图形界面（没有 DISPLAY 或 WAYLAND_DISPLAY）；子命令无需图形界面即可运行（见 --help）".into()
            }
            (StartText::NoDisplay, Lang::En) => {
                "the editor needs a graphical session (no DISPLAY or WAYLAND_DISPLAY); the subcommands run without one (see --help)".into()
            }
            (StartText::NoEditor, Lang::Zh) => "本程序不含编辑器".into(),
            (StartText::NoEditor, Lang::En) => "no editor in this program".into(),
        }
    }
}

/// A file that could not be read or written. Paths are as the user gave them (`display`);
/// a `why` is the system's own message, which stays as the system said it.
#[derive(Debug)]
pub enum FileText {
    /// A file that could not be read.
    CannotRead {
        /// The file.
        path: String,
        /// The system's reason.
        why: String,
    },
    /// A file to read that does not exist.
    NoSuchFile {
        /// The file.
        path: String,
    },
    /// A project argument that exists but is not a file (a folder).
    NotAProjectFile {
        /// The path given.
        path: String,
    },
    /// A file that could not be written.
    CannotWrite {
        /// The file.
        path: String,
        /// The system's reason.
        why: String,
    },
    /// A file to write whose folder does not exist.
    NoSuchFolder {
        /// The file.
        path: String,
    },
    /// A project file that could not be saved.
    CannotSave {
        /// The file.
        path: String,
        /// Why, worded in the language asked for ([`file_error`]).
        error: FileError,
    },
    /// A project file that could not be opened.
    CannotOpen {
        /// The file.
        path: String,
        /// Why, worded in the language asked for ([`file_error`]).
        error: FileError,
    },
    /// A PATH that is neither a project nor UTF-8 text.
    NotText {
        /// The file.
        path: String,
    },
    /// `import-il` given a project instead of an instruction list.
    IsAProject {
        /// The file.
        path: String,
    },
}

impl FileText {
    /// The text in `lang`.
    pub fn text(&self, lang: Lang) -> String {
        // The reasons that are the command line's own words, in the language asked for.
        let (no_file, not_project, no_folder) = match lang {
            Lang::Zh => ("文件不存在", "不是工程文件", "文件夹不存在"),
            Lang::En => ("no such file", "not a project file", "no such folder"),
        };
        match (self, lang) {
            (FileText::CannotRead { path, why }, _) => cannot_read(path, why, lang),
            (FileText::NoSuchFile { path }, _) => cannot_read(path, no_file, lang),
            (FileText::NotAProjectFile { path }, _) => cannot_read(path, not_project, lang),
            (FileText::CannotWrite { path, why }, _) => cannot_write(path, why, lang),
            (FileText::NoSuchFolder { path }, _) => cannot_write(path, no_folder, lang),
            (FileText::CannotSave { path, error }, Lang::Zh) => {
                format!("无法保存 {path}：{}", file_error(error, lang))
            }
            (FileText::CannotSave { path, error }, Lang::En) => {
                format!("cannot save {path}: {}", file_error(error, lang))
            }
            (FileText::CannotOpen { path, error }, Lang::Zh) => {
                format!("{path} 无法打开：{}", file_error(error, lang))
            }
            (FileText::CannotOpen { path, error }, Lang::En) => {
                format!("{path} cannot be opened: {}", file_error(error, lang))
            }
            (FileText::NotText { path }, Lang::Zh) => {
                format!("{path} 既不是 Ladder Studio 工程，也不是指令表（不是 UTF-8 文本）")
            }
            (FileText::NotText { path }, Lang::En) => format!(
                "{path} is neither a Ladder Studio project nor an instruction list (it is not UTF-8 text)"
            ),
            (FileText::IsAProject { path }, Lang::Zh) => {
                format!("{path} 是工程文件，不是指令表；用 export-il 导出它的指令表")
            }
            (FileText::IsAProject { path }, Lang::En) => format!(
                "{path} is a project file, not an instruction list; use export-il to get its IL"
            ),
        }
    }
}

/// `cannot read PATH: WHY`.
fn cannot_read(path: &str, why: &str, lang: Lang) -> String {
    match lang {
        Lang::Zh => format!("无法读取 {path}：{why}"),
        Lang::En => format!("cannot read {path}: {why}"),
    }
}

/// `cannot write PATH: WHY`.
fn cannot_write(path: &str, why: &str, lang: Lang) -> String {
    match lang {
        Lang::Zh => format!("无法写入 {path}：{why}"),
        Lang::En => format!("cannot write {path}: {why}"),
    }
}

/// How many errors and warnings a compile found: the summary line, and the start of every
/// line that says what they stop.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Counts {
    /// Errors.
    pub errors: usize,
    /// Warnings.
    pub warnings: usize,
}

impl Counts {
    /// The counts of a compile result.
    pub fn of(compiled: &Compiled) -> Counts {
        Counts {
            errors: compiled.errors(),
            warnings: compiled.warnings(),
        }
    }

    /// `N errors, M warnings` (`N 个错误，M 个警告`): the editor's summary and status bar say
    /// it as `check` does.
    pub fn text(self, lang: Lang) -> String {
        let Counts { errors, warnings } = self;
        match lang {
            Lang::Zh => format!("{errors} 个错误，{warnings} 个警告"),
            Lang::En => {
                let plural =
                    |n: usize, word: &str| format!("{n} {word}{}", if n == 1 { "" } else { "s" });
                format!(
                    "{}, {}",
                    plural(errors, "error"),
                    plural(warnings, "warning")
                )
            }
        }
    }
}

/// A compile's results and what they stop or allow; the comments CSV imported.
#[derive(Debug)]
pub enum CheckText {
    /// `N errors, M warnings`: the last line of `check`.
    Summary(Counts),
    /// `export-il` stopped by a structural error.
    IlNotWritten(Counts),
    /// An instruction list that cannot be drawn, where a drawing is needed (`xref`, `print`,
    /// `export-comments`).
    NotDrawable(Counts),
    /// `import-il` of a list that cannot be drawn.
    NoProjectWritten(Counts),
    /// `import-il` wrote the project, errors and all.
    WrittenWithErrors {
        /// The compile's counts.
        counts: Counts,
        /// The project written.
        path: String,
    },
    /// A program with errors, asked to run (`sim`, `test`, `bench`).
    CannotRun(Counts),
    /// `import-comments` applied every row.
    RowsApplied {
        /// Rows applied.
        rows: usize,
        /// The project changed.
        path: String,
    },
    /// `import-comments` refused the CSV.
    RowsRejected {
        /// Rows rejected.
        rows: usize,
    },
}

impl CheckText {
    /// The text in `lang`.
    pub fn text(&self, lang: Lang) -> String {
        match (self, lang) {
            (CheckText::Summary(c), _) => c.text(lang),
            (CheckText::IlNotWritten(c), Lang::Zh) => format!("{}；未写出指令表", c.text(lang)),
            (CheckText::IlNotWritten(c), Lang::En) => {
                format!("{}; no instruction list written", c.text(lang))
            }
            (CheckText::NotDrawable(c), Lang::Zh) => {
                format!("{}；指令表无法画成梯形图", c.text(lang))
            }
            (CheckText::NotDrawable(c), Lang::En) => {
                format!("{}; the instruction list cannot be drawn", c.text(lang))
            }
            (CheckText::NoProjectWritten(c), Lang::Zh) => {
                format!("{}；指令表无法画成梯形图，未写出工程", c.text(lang))
            }
            (CheckText::NoProjectWritten(c), Lang::En) => format!(
                "{}; the instruction list cannot be drawn as a ladder, no project written",
                c.text(lang)
            ),
            (CheckText::WrittenWithErrors { counts, path }, Lang::Zh) => {
                format!("{}；工程已写入 {path}，其中的错误待修改", counts.text(lang))
            }
            (CheckText::WrittenWithErrors { counts, path }, Lang::En) => format!(
                "{}; project written to {path} with the errors to fix",
                counts.text(lang)
            ),
            (CheckText::CannotRun(c), Lang::Zh) => format!("{}；程序无法运行", c.text(lang)),
            (CheckText::CannotRun(c), Lang::En) => {
                format!("{}; the program cannot run", c.text(lang))
            }
            (CheckText::RowsApplied { rows, path }, Lang::Zh) => {
                format!("{rows} 行已导入 {path}")
            }
            (CheckText::RowsApplied { rows, path }, Lang::En) => {
                format!("{rows} rows applied to {path}")
            }
            (CheckText::RowsRejected { rows }, Lang::Zh) => {
                format!("{rows} 行被拒绝；工程未改动")
            }
            (CheckText::RowsRejected { rows }, Lang::En) => {
                format!("{rows} row(s) rejected; the project was not changed")
            }
        }
    }
}
