//! The words of [`LowerFinding`]: each finding in English and in Chinese, side by side.

use crate::Lang;
use ladder_engine::compiler::LowerFinding;

/// What `f` found and how to fix it, in `lang`.
pub(super) fn text(f: &LowerFinding, lang: Lang) -> String {
    let _ = lang;
    match *f {}
}
