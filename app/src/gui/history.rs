//! Undo and redo of the project, across the editor: a table draft typed after the last
//! change goes first, and the view follows the step taken back to where it changed.

use super::LadderApp;
use super::place::View;
use ladder_engine::model::Change;

impl LadderApp {
    /// Ctrl+Z: a draft being typed in a table goes first, as a text field would; else the last
    /// step of the project is taken back and shown where it changed.
    pub fn undo(&mut self) {
        // A draft typed after the last change goes first, as a text field undoes its typing.
        if self.tables.latest_draft() > Some(self.last_change) && self.tables.undo_draft() {
            return;
        }
        let Some(doc) = self.doc.as_mut() else { return };
        let step = doc.undo().cloned();
        self.after_history(step);
    }

    /// Ctrl+Y: the last undone step again, shown where it changed.
    pub fn redo(&mut self) {
        let Some(doc) = self.doc.as_mut() else { return };
        let step = doc.redo().cloned();
        self.after_history(step);
    }

    /// After an undo or redo: the view and the place of the step (a table's row, a ladder
    /// cell, a block), so a change never comes back unseen.
    fn after_history(&mut self, step: Option<Change>) {
        self.clamp_ui_state();
        let (Some(step), Some(doc)) = (step, self.doc.as_ref()) else {
            return;
        };
        if let Change::Table(t) = &step {
            if let Some(view) = self.tables.show_change(doc.project(), t) {
                self.view = view;
            }
            return;
        }
        match super::place::place_of(&step, doc.project()) {
            Some(super::place::Place::Cell(at)) => self.jump(at),
            Some(super::place::Place::Block(b)) => {
                self.view = View::Block(b);
                self.clamp_ui_state();
            }
            None => {}
        }
    }
}
