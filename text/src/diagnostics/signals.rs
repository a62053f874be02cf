//! The words of [`SignalFinding`]: each finding in English and in Chinese, side by side.

use crate::Lang;
use ladder_engine::compiler::SignalFinding;

/// What `f` found and how to fix it, in `lang`.
pub(super) fn text(f: &SignalFinding, lang: Lang) -> String {
    let _ = lang;
    match *f {}
}
