//! The function-instruction dialog (F3, manual §3.2.2), driven by the instruction catalogue.

use super::LadderApp;
use ladder_engine::model::CellRef;

/// The open dialog.
#[derive(Clone, Debug)]
pub struct FunctionDialog {
    /// Where the box goes.
    pub at: CellRef,
}

impl LadderApp {
    /// F3: opens the dialog for a new box in the output column of the cursor's row.
    pub fn open_function_dialog(&mut self) {
        if let Some(at) = self.ensure_network() {
            self.function_dialog = Some(FunctionDialog { at });
        }
    }

    /// Opens the dialog on the box at `at` to change its operands.
    pub fn edit_function_box(&mut self, at: CellRef) {
        self.function_dialog = Some(FunctionDialog { at });
    }

    /// Draws the dialog while it is open.
    pub fn function_dialog_ui(&mut self, ctx: &egui::Context) {
        let _ = ctx;
    }
}
