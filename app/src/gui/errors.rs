//! The document's refusals in the user's language; the engine's own errors are rendered by
//! `ladder_text::errors`, re-exported here for the editor's call sites.

use super::document::Refused;
use super::i18n::{Lang, Msg};
pub use ladder_text::errors::{edit_error, file_error, operand_error, sub_error};

/// Why the document refused a change.
pub fn refused(e: &Refused, lang: Lang) -> String {
    match e {
        Refused::ReadOnly => Msg::ReadOnly.text(lang).to_string(),
        Refused::Replaying => Msg::Replaying.text(lang).to_string(),
        Refused::Edit(e) => edit_error(e, lang),
    }
}
