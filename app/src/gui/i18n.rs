//! The editor's two languages and its fixed texts, from the one message table
//! (`ladder_text`).

pub use ladder_text::{Lang, Msg};
