//! The command line's own words in the user's language: `--lang zh|en`, else the locale
//! (`LC_ALL`, `LC_MESSAGES`, `LANG`; English when none is set, as in the C locale).
//!
//! The shape of every line stays the same in both languages (`PATH:…: error: MESSAGE
//! [CODE]`), so scripts that read `check`'s output read it in either.

use ladder_engine::compiler::{Compiled, Diagnostic};
use ladder_engine::file::FileError;
use ladder_text::Lang;
use ladder_text::errors::file_error;
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

    /// The language as the message table takes it.
    pub fn lang(self) -> Lang {
        if self.zh { Lang::Zh } else { Lang::En }
    }

    /// The locale messages follow: `LC_ALL`, else `LC_MESSAGES`, else `LANG`, else `C`.
    pub fn system_locale() -> String {
        ["LC_ALL", "LC_MESSAGES", "LANG"]
            .iter()
            .find_map(|v| std::env::var(v).ok().filter(|s| !s.is_empty()))
            .unwrap_or_else(|| "C".to_string())
    }

    /// The last line of `sim` and `test`: `N passed, M failed` (checks, or scripts).
    pub fn passed(self, passed: usize, failed: usize) -> String {
        self.pick(
            format!("{passed} passed, {failed} failed"),
            format!("{passed} 项通过，{failed} 项失败"),
        )
    }

    /// `en` or `zh`, as the language is.
    pub fn pick(self, en: impl Display, zh: impl Display) -> String {
        if self.zh {
            zh.to_string()
        } else {
            en.to_string()
        }
    }

    /// One diagnostic line.
    pub fn diagnostic(self, d: &Diagnostic, path: &str) -> String {
        d.render_in(path, self.zh)
    }

    /// `N errors, M warnings`.
    pub fn summary(self, compiled: &Compiled) -> String {
        let (e, w) = (compiled.errors(), compiled.warnings());
        let plural = |n: usize, word: &str| format!("{n} {word}{}", if n == 1 { "" } else { "s" });
        self.pick(
            format!("{}, {}", plural(e, "error"), plural(w, "warning")),
            format!("{e} 个错误，{w} 个警告"),
        )
    }

    /// A file that could not be read.
    pub fn cannot_read(self, path: &Path, e: impl Display) -> String {
        self.pick(
            format!("cannot read {}: {e}", path.display()),
            format!("无法读取 {}：{e}", path.display()),
        )
    }

    /// A file that could not be written.
    pub fn cannot_write(self, path: &Path, e: impl Display) -> String {
        self.pick(
            format!("cannot write {}: {e}", path.display()),
            format!("无法写入 {}：{e}", path.display()),
        )
    }

    /// A project file that could not be saved.
    pub fn cannot_save(self, path: &Path, e: &FileError) -> String {
        self.pick(
            format!("cannot save {}: {e}", path.display()),
            format!("无法保存 {}：{}", path.display(), self.file(e)),
        )
    }

    /// A project file that could not be opened.
    pub fn cannot_open(self, path: &Path, e: &FileError) -> String {
        self.pick(
            format!("{} cannot be opened: {e}", path.display()),
            format!("{} 无法打开：{}", path.display(), self.file(e)),
        )
    }

    /// A project file's error by itself.
    pub fn file(self, e: &FileError) -> String {
        file_error(e, if self.zh { Lang::Zh } else { Lang::En })
    }
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
