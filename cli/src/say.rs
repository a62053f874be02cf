//! The language the command line speaks: `--lang zh|en`, else the locale (`LC_ALL`,
//! `LC_MESSAGES`, `LANG`; English when none is set, as in the C locale). The words
//! themselves are not here: each is a [`CliText`] of `ladder_text`, the one table of zh and
//! en texts shared with the editor, and the command line names them with their data.
//!
//! The shape of every line stays the same in both languages (`PATH:…: error: MESSAGE
//! [CODE]`), so scripts that read `check`'s output read it in either.

use ladder_engine::compiler::{Compiled, Diagnostic};
use ladder_engine::file::FileError;
use ladder_text::cli::{CheckText, Counts, FileText, RunText};
use ladder_text::{CliText, Lang};
use std::fmt::Display;
use std::path::Path;

/// The language the command line speaks.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Say {
    /// Chinese (else English).
    pub zh: bool,
}

impl Say {
    /// `--lang` when given, else the language of `locale` (`zh_CN.UTF-8`, `C`).
    pub fn new(lang: Option<&str>, locale: &str) -> Say {
        let zh = match lang {
            Some(l) => l == "zh",
            None => Lang::from_locale(Some(locale)) == Lang::Zh,
        };
        Say { zh }
    }

    /// The locale messages follow: `LC_ALL`, else `LC_MESSAGES`, else `LANG`, else `C`.
    pub fn system_locale() -> String {
        ["LC_ALL", "LC_MESSAGES", "LANG"]
            .iter()
            .find_map(|v| std::env::var(v).ok().filter(|s| !s.is_empty()))
            .unwrap_or_else(|| "C".to_string())
    }

    /// The language as the text table names it.
    pub fn lang(self) -> Lang {
        if self.zh { Lang::Zh } else { Lang::En }
    }

    /// A text of the command line in this language; every word the command line says comes
    /// from the one table ([`CliText`], docs/files.md, "Language").
    pub fn text(self, t: impl Into<CliText>) -> String {
        t.into().text(self.lang())
    }

    /// The last line of `sim` and `test`: `N passed, M failed` (checks, or scripts).
    pub fn passed(self, passed: usize, failed: usize) -> String {
        self.text(RunText::Passed { passed, failed })
    }

    /// One diagnostic line.
    pub fn diagnostic(self, d: &Diagnostic, path: &str) -> String {
        ladder_text::diagnostics::render(d, path, self.lang())
    }

    /// `N errors, M warnings`.
    pub fn summary(self, compiled: &Compiled) -> String {
        self.text(CheckText::Summary(Counts::of(compiled)))
    }

    /// A file that could not be read, with the system's reason (the engine's own, such as
    /// the size limit, in this language).
    pub fn cannot_read(self, path: &Path, e: std::io::Error) -> String {
        self.text(FileText::CannotRead {
            path: shown(path),
            why: ladder_text::errors::io_error(&e, self.lang()),
        })
    }

    /// A file that could not be written, with the system's reason.
    pub fn cannot_write(self, path: &Path, e: impl Display) -> String {
        self.text(FileText::CannotWrite {
            path: shown(path),
            why: e.to_string(),
        })
    }

    /// A project file that could not be saved.
    pub fn cannot_save(self, path: &Path, error: FileError) -> String {
        self.text(FileText::CannotSave {
            path: shown(path),
            error,
        })
    }

    /// A project file that could not be opened.
    pub fn cannot_open(self, path: &Path, error: FileError) -> String {
        self.text(FileText::CannotOpen {
            path: shown(path),
            error,
        })
    }
}

/// A path as the texts show it: as the user gave it.
pub fn shown(path: &Path) -> String {
    path.display().to_string()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_option_decides_and_the_summary_speaks_its_language() {
        let c = ladder_engine::il::import("LEVEL2\nNETWORK\nLD NOWHERE\nOUT Y0000.0\n").compiled;
        assert_eq!(
            Say::new(Some("en"), "zh_CN").summary(&c),
            "1 error, 0 warnings"
        );
        assert_eq!(Say::new(Some("zh"), "C").summary(&c), "1 个错误，0 个警告");
        assert!(Say::new(None, "zh_CN.UTF-8").zh);
        assert!(!Say::new(None, "C").zh && !Say::new(None, "en_US.UTF-8").zh);
        let d = &c.diagnostics[0];
        let zh = Say::new(Some("zh"), "C").diagnostic(d, "a.il");
        assert!(zh.starts_with("a.il:3: error: "), "{zh}");
        assert!(zh.contains("未定义"), "{zh}");
    }
}
