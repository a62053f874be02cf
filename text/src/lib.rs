//! Every text Ladder Studio shows a user, in Chinese and English, in one place for the editor
//! and the command line alike (docs/files.md, "Language"; ARCHITECTURE.md, "Languages").
//!
//! The engine says what happened in types (enums with data, no prose); this crate says it in
//! words. A missing translation is a compile error: each text is a `match` with an arm per
//! language.

#[cfg(test)]
pub(crate) mod bilingual;
pub mod cli;
pub mod diagnostics;
pub mod errors;
pub mod halt;
pub mod machine;
pub mod quoted;
pub mod refusal;
pub mod script;
pub mod sim;
pub mod ui;

pub use cli::CliText;
pub use ui::Msg;

use serde::{Deserialize, Serialize};

/// A UI language.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub enum Lang {
    /// 中文.
    #[default]
    Zh,
    /// English.
    En,
}

impl Lang {
    /// The language a user of this system most likely reads: Chinese when the locale says so.
    pub fn from_locale(locale: Option<&str>) -> Lang {
        match locale {
            Some(l) if l.to_ascii_lowercase().starts_with("zh") => Lang::Zh,
            Some(_) => Lang::En,
            None => Lang::Zh,
        }
    }

    /// The code used for per-language comments (`zh`, `en`).
    pub fn code(self) -> &'static str {
        match self {
            Lang::Zh => "zh",
            Lang::En => "en",
        }
    }
}
