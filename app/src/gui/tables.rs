//! The table editors (manual §3.4): symbol tables, data-setting tables, display messages,
//! diagnosis, permissions, M-code comments and version information.

use super::LadderApp;

/// The table editors' UI state.
#[derive(Clone, Debug, Default)]
pub struct TableState {}

impl LadderApp {
    /// Draws the table the project tree selected.
    pub fn tables_ui(&mut self, ui: &mut egui::Ui) {
        let _ = ui;
    }
}
