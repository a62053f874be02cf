//! Selection and the clipboard (manual §3.2.2 剪切/复制/粘贴/复制一行/删除选择区域): cells,
//! rows or whole networks of one block. Selection and clipboard are UI state: never saved,
//! and every change they make goes through the engine's edits as one undo step.

use crate::gui::OutputLine;
use crate::gui::context::Context;
use crate::gui::editor::EditState;
use crate::gui::i18n::Msg;
use ladder_engine::model::Cell;
pub use ladder_engine::model::region::{Clip, Region as Selection};

impl EditState {
    pub(crate) fn note(&mut self, cx: &mut Context<'_>, text: String, error: bool) {
        cx.output.push(OutputLine {
            text,
            error,
            target: None,
        });
    }

    /// The selection in the shown block, or the cursor's cell when nothing is selected.
    pub fn effective_selection(&self, cx: &Context<'_>) -> Option<(usize, Selection)> {
        let block = match *cx.view {
            crate::gui::place::View::Block(b) => b,
            _ => return None,
        };
        match *cx.selection {
            Some((b, s)) if b == block => Some((b, s)),
            _ => {
                let c = *cx.cursor;
                (c.block == block).then_some((
                    block,
                    Selection::Cells {
                        network: c.network,
                        rows: (c.row, c.row),
                        cols: (c.col, c.col),
                    },
                ))
            }
        }
    }

    /// Ctrl+C: the selection (or the cursor's cell) to the clipboard.
    pub fn copy(&mut self, cx: &mut Context<'_>) -> bool {
        let Some((block, sel)) = self.effective_selection(cx) else {
            return false;
        };
        match self.ladder(cx).and_then(|l| l.copy_region(block, sel)) {
            Some(clip) => {
                self.clipboard = Some(clip);
                true
            }
            None => false,
        }
    }

    /// Puts the clipboard's text on the system clipboard too: other programs get readable
    /// text, and the window system then sends Ctrl+V back to the editor (it only does so
    /// when the system clipboard holds text).
    pub fn copy_to_system(&self, ctx: &egui::Context) {
        if let Some(clip) = &self.clipboard {
            ctx.copy_text(clip_text(clip));
        }
    }

    /// Ctrl+E: the cursor's row to the clipboard.
    pub fn copy_row(&mut self, cx: &mut Context<'_>) {
        let c = *cx.cursor;
        let row = Selection::Rows {
            network: c.network,
            rows: (c.row, c.row),
        };
        if let Some(clip) = self.ladder(cx).and_then(|l| l.copy_region(c.block, row)) {
            self.clipboard = Some(clip);
        }
    }

    /// Ctrl+X: copy, then delete the selection.
    pub fn cut(&mut self, cx: &mut Context<'_>) {
        if self.copy(cx) {
            self.delete_selection(cx);
        }
    }

    /// Delete with a selection: cells emptied, rows or networks removed, as one undo step. A
    /// network keeps at least one (empty) row, a block at least one network (manual §3.2.2).
    pub fn delete_selection(&mut self, cx: &mut Context<'_>) {
        let Some((block, sel)) = self.effective_selection(cx) else {
            return;
        };
        let Some(edit) = self.ladder(cx).map(|l| l.plan_delete_region(block, sel)) else {
            return;
        };
        self.edit(cx, edit);
        *cx.selection = None;
        // The cursor goes to where the deleted part began, so Ctrl+V puts it back.
        let networks = self
            .ladder(cx)
            .map_or(0, |l| l.blocks[block].networks.len());
        let c = &mut *cx.cursor;
        match sel {
            Selection::Cells {
                network,
                rows,
                cols,
            } => {
                c.network = network;
                c.row = rows.0.min(rows.1);
                c.col = cols.0.min(cols.1);
            }
            Selection::Rows { network, rows } => {
                c.network = network;
                c.row = rows.0.min(rows.1).saturating_sub(1);
            }
            Selection::Networks { networks: ns } => {
                c.network = ns.0.min(ns.1).saturating_sub(1);
                c.row = 0;
            }
        }
        c.network = c.network.min(networks.saturating_sub(1));
    }

    /// Ctrl+V: cells over the cursor's rectangle, rows below the cursor's row, networks below
    /// the cursor's network.
    pub fn paste(&mut self, cx: &mut Context<'_>) {
        let lang = cx.settings.lang;
        let Some(clip) = self.clipboard.clone() else {
            self.note(cx, Msg::ClipboardEmpty.text(lang).into(), false);
            return;
        };
        let Some(at) = self.ensure_row(cx) else {
            return;
        };
        let ok = match self.ladder(cx).map(|l| l.plan_paste(at, clip)) {
            Some(Ok(edit)) => self.edit(cx, edit),
            Some(Err(e)) => {
                self.report_edit_error(cx, &e);
                false
            }
            None => false,
        };
        if ok {
            *cx.selection = None;
        }
    }
}

/// A clip as text: one line per row, cells separated by tabs.
fn clip_text(clip: &Clip) -> String {
    fn cell_text(c: &Cell) -> String {
        match c {
            Cell::Empty => String::new(),
            Cell::Wire => "—".into(),
            Cell::Contact { negated, operand } => {
                format!("{}{operand}", if *negated { "NC " } else { "NO " })
            }
            Cell::Coil { negated, operand } => {
                format!("{}{operand}", if *negated { "OUTN " } else { "OUT " })
            }
            Cell::Box { op, operands } => ladder_engine::il::instr_text(*op, operands),
        }
    }
    fn row_text(cells: &[Cell]) -> String {
        cells.iter().map(cell_text).collect::<Vec<_>>().join("\t")
    }
    match clip {
        Clip::Cells { cells, .. } => cells
            .iter()
            .map(|r| row_text(r))
            .collect::<Vec<_>>()
            .join("\n"),
        Clip::Rows(rows) => rows
            .iter()
            .map(|r| row_text(&r.cells))
            .collect::<Vec<_>>()
            .join("\n"),
        Clip::Networks(ns) => ns
            .iter()
            .map(|n| {
                let rows: Vec<String> = n.rows.iter().map(|r| row_text(&r.cells)).collect();
                format!("{}\n{}", n.title, rows.join("\n"))
            })
            .collect::<Vec<_>>()
            .join("\n\n"),
    }
}
