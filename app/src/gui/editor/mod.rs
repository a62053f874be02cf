//! The ladder editor: the feature that places and deletes elements, wires, rows and networks,
//! moves the cursor and the selection, keeps the clipboard and the operand prompt, and opens
//! the function-instruction dialog. Its state is [`EditState`]; it changes the project only
//! through the narrow `Context` (see `context.rs`).

pub mod commands;
pub mod editing;
pub mod function_dialog;
pub mod pointer;
pub mod prompt;
pub mod selection;

use crate::gui::ladder_view::{Geometry, Hit};
use crate::gui::place::{BlockKey, Cursor};
use ladder_engine::model::CellRef;
use ladder_engine::model::region::{Clip, Region as Selection};
use std::collections::HashMap;

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
    pub prompt: Option<crate::gui::editor::editing::Prompt>,
    /// The open function-instruction dialog (F3, or a double-click on a box).
    pub function_dialog: Option<crate::gui::editor::function_dialog::FunctionDialog>,
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
