//! The words of [`TableFinding`]: each finding in English and in Chinese, side by side.

use crate::Lang;
use ladder_engine::compiler::TableFinding;

/// What `f` found and how to fix it, in `lang`.
pub(super) fn text(f: &TableFinding, lang: Lang) -> String {
    let _ = lang;
    match *f {}
}
