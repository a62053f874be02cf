//! The application's state in groups, each with what one part of the editor owns: the
//! ladder editor's place and gestures, and the file side (dialogs, questions, recovery). A
//! function that needs one group borrows that group, not the whole application.

use super::dialogs::{Action, FileDialogs, Question};
use super::file_dialog::SystemDialogs;
use super::ladder_view::{Geometry, Hit};
use super::place::{BlockKey, Cursor};
use ladder_engine::model::CellRef;
use ladder_engine::model::region::{Clip, Region as Selection};
use std::collections::HashMap;
use std::path::PathBuf;
use std::time::Instant;

/// The ladder editor's state: where the user is and what their gestures hold. UI state only,
/// never saved in the project.
#[derive(Debug, Default)]
pub struct EditState {
    /// Where the cursor was left in each block not shown now: the cursor goes with its block.
    pub block_cursors: HashMap<BlockKey, Cursor>,
    /// What Ctrl+C, Ctrl+X or Ctrl+E put aside (kept across projects: copying between
    /// projects is how networks move from one machine's ladder to another's).
    pub clipboard: Option<Clip>,
    /// Dragging draws wires and links instead of selecting cells.
    pub pen: bool,
    /// Where the drag in progress in the ladder view started.
    pub drag_from: Option<Hit>,
    /// A network to scroll into view at the next frame.
    pub jump_to: Option<usize>,
    /// Where the ladder view was drawn last frame.
    pub geometry: Geometry,
    /// The last text searched for (Ctrl+F offers it again, to find the next match).
    pub last_find: String,
    /// A ladder point to keep in place, and for how many more frames: the zoom has just
    /// changed. It is applied twice because the scroll area bounds an offset by the content
    /// size of the frame before, which is the old zoom's on the first frame.
    pub anchor: Option<(super::ladder_view::Anchor, u8)>,
    /// The cursor and the document's change count the view last followed: when either
    /// differs, the view brings the cursor into sight.
    pub followed: Option<(Cursor, u64, u64)>,
    /// The open operand prompt (F1, F2, F3, F6, Ctrl+G, titles).
    pub prompt: Option<super::editing::Prompt>,
    /// The open function-instruction dialog (F3, or a double-click on a box).
    pub function_dialog: Option<super::function_dialog::FunctionDialog>,
    /// The (document, block) pairs shown since they were opened: the first showing scrolls
    /// to where the block was left in an earlier session.
    pub shown: std::collections::HashSet<(u64, usize)>,
}

impl EditState {
    /// The ladder point to keep in place this frame, if the zoom changed a frame or two ago.
    pub fn next_anchor(&mut self) -> Option<super::ladder_view::Anchor> {
        let (a, left) = self.anchor.as_mut()?;
        let a = *a;
        *left = left.saturating_sub(1);
        if *left == 0 {
            self.anchor = None;
        }
        Some(a)
    }

    /// Another project: nothing of the old one stays pointed at (cursor, selection, drag,
    /// saved cursors, search). The clipboard and the pen stay: copying between projects is
    /// how networks move from one machine's ladder to another's.
    pub fn start_over(&mut self) {
        *self = EditState {
            clipboard: self.clipboard.take(),
            pen: self.pen,
            ..Default::default()
        };
    }
}

/// The file side: the file dialogs, the question the editor waits on and the recovery copies.
pub struct FileState {
    /// File dialogs (native, or scripted in tests).
    pub dialogs: Box<dyn FileDialogs>,
    /// The question the editor waits on (unsaved changes, damaged file, restore).
    pub question: Option<Question>,
    /// What to do once the pending Save or Save As succeeds.
    pub after_save: Option<Action>,
    /// The user agreed to quit.
    pub exit_confirmed: bool,
    /// Where recovery copies are autosaved; `None` turns autosave off.
    pub recovery_dir: Option<PathBuf>,
    /// When the recovery copy was last written.
    pub last_autosave: Option<Instant>,
}

impl Default for FileState {
    fn default() -> FileState {
        FileState {
            dialogs: Box::new(SystemDialogs::default()),
            question: None,
            after_save: None,
            exit_confirmed: false,
            recovery_dir: None,
            last_autosave: None,
        }
    }
}

/// Extends the selection from the cursor to `to` (Shift+click, Shift+arrows): cells within
/// one network, whole networks across networks.
pub fn extend_selection(
    cursor: &mut CellRef,
    selection: &mut Option<(usize, Selection)>,
    to: CellRef,
) {
    {
        let from = match *selection {
            Some((b, s)) if b == to.block => match s {
                Selection::Cells {
                    network,
                    rows,
                    cols,
                } => CellRef {
                    block: b,
                    network,
                    row: rows.0,
                    col: cols.0,
                },
                Selection::Rows { network, rows } => CellRef {
                    block: b,
                    network,
                    row: rows.0,
                    col: 0,
                },
                Selection::Networks { networks } => CellRef {
                    block: b,
                    network: networks.0,
                    row: 0,
                    col: 0,
                },
            },
            _ => *cursor,
        };
        let sel = if from.network != to.network {
            Selection::Networks {
                networks: (from.network, to.network),
            }
        } else if matches!(selection, Some((_, Selection::Rows { .. }))) {
            Selection::Rows {
                network: to.network,
                rows: (from.row, to.row),
            }
        } else {
            Selection::Cells {
                network: to.network,
                rows: (from.row, to.row),
                cols: (from.col, to.col),
            }
        };
        *selection = Some((to.block, sel));
        *cursor = to;
    }
}
