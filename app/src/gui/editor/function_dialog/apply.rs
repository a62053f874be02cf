//! The dialog's entry points in the application: opening it for a new or an existing box,
//! drawing it, and placing the box it describes through the document's door.

use super::{Action, FunctionDialog};
use crate::gui::context::Context;
use crate::gui::editor::EditState;
use crate::gui::i18n::{Lang, Msg};
use egui::{Key, Modifiers};
use ladder_engine::model::{Cell, CellRef, Edit, EditError};

impl EditState {
    /// F3: opens the dialog for a new box in the output column of the cursor's row.
    pub fn open_function_dialog(&mut self, cx: &mut Context<'_>) {
        // No network is added yet: an empty block gets one only when OK places the box, in
        // the same undo step.
        if let crate::gui::place::View::Block(block) = *cx.view {
            let at = CellRef {
                block,
                ..*cx.cursor
            };
            self.function_dialog = Some(FunctionDialog::new(at));
        }
    }

    /// Opens the dialog on the box at `at` to change its operands (or its instruction); any
    /// other cell opens it for a new box in that row.
    pub fn edit_function_box(&mut self, cx: &Context<'_>, at: CellRef) {
        let cell = cx
            .doc()
            .and_then(|d| d.project().ladder.blocks.get(at.block))
            .and_then(|b| b.networks.get(at.network))
            .and_then(|n| n.cell(at.row, at.col))
            .cloned();
        self.function_dialog = Some(match cell {
            Some(Cell::Box { op, operands }) => FunctionDialog::for_box(at, op, &operands),
            _ => FunctionDialog::new(at),
        });
    }

    /// Draws the dialog while it is open: Enter or OK places (or replaces) the box as one undo
    /// step, Escape or Cancel closes it without a change.
    pub fn function_dialog_ui(&mut self, cx: &mut Context<'_>, ctx: &egui::Context) {
        let Some(mut dialog) = self.function_dialog.take() else {
            return;
        };
        let Some(doc) = cx.doc() else {
            return;
        };
        if ctx.input_mut(|i| i.consume_key(Modifiers::NONE, Key::Escape)) {
            return;
        }
        let lang = cx.settings.lang;
        let project = doc.project();
        let action = egui::Modal::new(egui::Id::unique("function_dialog"))
            .show(ctx, |ui| dialog.ui(ui, project, lang))
            .inner;
        match action {
            Action::Cancel => {}
            Action::None => self.function_dialog = Some(dialog),
            Action::Ok => {
                if let Err(e) = self.place_function_box(cx, &dialog, lang) {
                    dialog.error = Some(e);
                    self.function_dialog = Some(dialog);
                }
            }
        }
    }

    /// Puts the dialog's box into the ladder as one undo step: over the box it was opened on,
    /// or in the output column of its row, wired to the last element left of it.
    pub(crate) fn place_function_box(
        &mut self,
        cx: &mut Context<'_>,
        dialog: &FunctionDialog,
        lang: Lang,
    ) -> Result<(), String> {
        let cell = dialog
            .cell()
            .ok_or_else(|| Msg::FnChoose.text(lang).to_string())?;
        let mut dialog = dialog.clone();
        if !dialog.editing {
            // The cursor's row; in an empty block, a new network (folded into this step).
            *cx.cursor = CellRef {
                block: dialog.at.block,
                ..*cx.cursor
            };
            dialog.at = self
                .ensure_row(cx)
                .ok_or_else(|| Msg::NoProject.text(lang).to_string())?;
        }
        let ladder = cx
            .doc()
            .map(|d| &d.project().ladder)
            .ok_or_else(|| Msg::NoProject.text(lang).to_string())?;
        let row_exists = ladder
            .blocks
            .get(dialog.at.block)
            .and_then(|b| b.networks.get(dialog.at.network))
            .is_some_and(|n| dialog.at.row < n.rows.len());
        if !row_exists {
            let e = EditError::NoSuchPlace(ladder_engine::model::Missing::Row);
            return Err(crate::gui::errors::edit_error(&e, lang));
        }
        let at = if dialog.editing {
            dialog.at
        } else {
            CellRef {
                col: ladder.width,
                ..dialog.at
            }
        };
        let edit = if dialog.editing {
            Edit::SetCell { at, cell }
        } else {
            ladder
                .plan_output(at, cell)
                .map_err(|e| crate::gui::errors::edit_error(&e, lang))?
        };
        // The refusal is shown in the dialog, once.
        cx.apply(edit)?;
        *cx.cursor = at;
        Ok(())
    }
}
