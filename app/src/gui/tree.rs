//! The project tree (manual §3.4): the nine nodes, the ladder's blocks and subprograms.

use super::i18n::{Lang, Msg};
use ladder_engine::model::{BlockKind, Project};

/// What the main area shows.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum View {
    /// A ladder block (index in the ladder).
    Block(usize),
    /// A symbol table.
    Symbols(usize),
    /// The data-setting tables.
    Data,
    /// The message table.
    Messages,
    /// The reference index.
    RefIndex,
    /// The bit-usage table.
    RefBits,
    /// The byte-usage table.
    RefBytes,
    /// The diagnosis table.
    Diagnosis,
    /// The permission table.
    Permissions,
    /// The M-code comments.
    MCodes,
    /// The version information.
    Version,
}

fn leaf(ui: &mut egui::Ui, current: &mut View, view: View, text: &str) {
    if ui.selectable_label(*current == view, text).clicked() {
        *current = view;
    }
}

/// Draws the tree; a click selects what the main area shows.
pub fn tree_ui(ui: &mut egui::Ui, project: &Project, lang: Lang, current: &mut View) {
    let t = |m: Msg| m.text(lang);
    egui::CollapsingHeader::new(t(Msg::Ladder))
        .default_open(true)
        .show(ui, |ui| {
            leaf(ui, current, View::Block(0), t(Msg::Level1));
            leaf(ui, current, View::Block(1), t(Msg::Level2));
            egui::CollapsingHeader::new(t(Msg::Subprograms))
                .default_open(true)
                .show(ui, |ui| {
                    for (i, b) in project.ladder.blocks.iter().enumerate().skip(2) {
                        if let BlockKind::Sub { number, name } = &b.kind {
                            leaf(ui, current, View::Block(i), &format!("P{number:04} {name}"));
                        }
                    }
                });
        });
    egui::CollapsingHeader::new(t(Msg::SymbolTables))
        .default_open(true)
        .show(ui, |ui| {
            for (i, table) in project.symbol_tables.iter().enumerate() {
                leaf(ui, current, View::Symbols(i), &table.name);
            }
        });
    leaf(ui, current, View::Data, t(Msg::DataTables));
    leaf(ui, current, View::Messages, t(Msg::Messages));
    egui::CollapsingHeader::new(t(Msg::Reference))
        .default_open(false)
        .show(ui, |ui| {
            leaf(ui, current, View::RefIndex, t(Msg::RefIndex));
            leaf(ui, current, View::RefBits, t(Msg::RefBits));
            leaf(ui, current, View::RefBytes, t(Msg::RefBytes));
        });
    leaf(ui, current, View::Diagnosis, t(Msg::Diagnosis));
    leaf(ui, current, View::Permissions, t(Msg::Permissions));
    leaf(ui, current, View::MCodes, t(Msg::MCodes));
    leaf(ui, current, View::Version, t(Msg::VersionInfo));
}
