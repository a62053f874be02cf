//! What a feature may use of the editor while it runs: the open document (to read), the
//! settings, the output window, the command queue and where the cursor and the selection
//! are. A feature owns its own state and takes this narrow context instead of the whole
//! app (rerun's `ViewerContext` is the model), so a new page or command touches its feature
//! and the command list only.

use super::command::Command;
use super::document::Document;
use super::output::Output;
use super::selection::Selection;
use super::settings::Settings;
use ladder_engine::model::CellRef;

/// The editor as a feature sees it.
pub struct Context<'a> {
    /// The open project, to read (changes go through commands).
    pub doc: Option<&'a Document>,
    /// The settings (a feature's own persisted choices live there).
    pub settings: &'a mut Settings,
    /// The output window.
    pub output: &'a mut Output,
    /// Commands to run after the frame (another feature's dialog, a file to pick).
    pub pending: &'a mut Vec<Command>,
    /// The ladder cursor.
    pub cursor: CellRef,
    /// The ladder selection: its block and region.
    pub selection: Option<(usize, Selection)>,
}
