//! Why a command to the machine was not carried out, in both languages the editor speaks:
//! a script prints the English, the editor's output window the user's language.

use std::fmt;

/// A refusal in English and Chinese, with the same specifics.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Refusal {
    /// In English.
    pub en: String,
    /// In Chinese.
    pub zh: String,
}

impl Refusal {
    /// A refusal from its two texts.
    pub fn new(en: impl Into<String>, zh: impl Into<String>) -> Refusal {
        Refusal {
            en: en.into(),
            zh: zh.into(),
        }
    }

    /// The text in Chinese when `zh`, else in English.
    pub fn text(&self, zh: bool) -> &str {
        if zh { &self.zh } else { &self.en }
    }

    /// Whether either text contains `s` (for tests and filters).
    pub fn contains(&self, s: &str) -> bool {
        self.en.contains(s) || self.zh.contains(s)
    }
}

impl fmt::Display for Refusal {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.en)
    }
}
