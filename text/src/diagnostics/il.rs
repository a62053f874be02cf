//! The words of [`IlFinding`]: each finding in English and in Chinese, side by side.

use crate::Lang;
use ladder_engine::compiler::IlFinding;

/// What `f` found and how to fix it, in `lang`.
pub(super) fn text(f: &IlFinding, lang: Lang) -> String {
    let _ = lang;
    match *f {}
}
