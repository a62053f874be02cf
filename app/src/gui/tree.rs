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

fn leaf(ui: &mut egui::Ui, current: &mut View, view: View, text: &str) -> egui::Response {
    let r = ui.selectable_label(*current == view, text);
    if r.clicked() {
        *current = view;
    }
    r
}

/// What the tree's right-click menus ask for.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum TreeAction {
    /// A new subprogram.
    NewSub,
    /// Renumber or rename block `0`.
    RenameSub(usize),
    /// Delete block `0`.
    DeleteSub(usize),
    /// Edit block `0`'s information.
    BlockInfo(usize),
    /// List the calls of subprogram `0` (its P number).
    ViewCalls(u16),
}

/// Draws the tree; a click selects what the main area shows, a right-click offers the block
/// commands.
pub fn tree_ui(
    ui: &mut egui::Ui,
    project: &Project,
    lang: Lang,
    current: &mut View,
) -> Option<TreeAction> {
    let t = |m: Msg| m.text(lang);
    let mut action = None;
    egui::CollapsingHeader::new(t(Msg::Ladder))
        .default_open(true)
        .show(ui, |ui| {
            for (i, m) in [(0, Msg::Level1), (1, Msg::Level2)] {
                leaf(ui, current, View::Block(i), t(m)).context_menu(|ui| {
                    if ui.button(t(Msg::BlockInfo)).clicked() {
                        action = Some(TreeAction::BlockInfo(i));
                        ui.close();
                    }
                });
            }
            let subs = egui::CollapsingHeader::new(t(Msg::Subprograms))
                .default_open(true)
                .show(ui, |ui| {
                    for (i, b) in project.ladder.blocks.iter().enumerate().skip(2) {
                        if let BlockKind::Sub { number, name } = &b.kind {
                            let r =
                                leaf(ui, current, View::Block(i), &format!("P{number:04} {name}"));
                            let r = if b.info.is_empty() {
                                r
                            } else {
                                r.on_hover_text(&b.info)
                            };
                            r.context_menu(|ui| {
                                for (m, a) in [
                                    (Msg::ViewCalls, TreeAction::ViewCalls(*number)),
                                    (Msg::RenameSub, TreeAction::RenameSub(i)),
                                    (Msg::BlockInfo, TreeAction::BlockInfo(i)),
                                    (Msg::DeleteSub, TreeAction::DeleteSub(i)),
                                    (Msg::NewSub, TreeAction::NewSub),
                                ] {
                                    if ui.button(t(m)).clicked() {
                                        action = Some(a);
                                        ui.close();
                                    }
                                }
                            });
                        }
                    }
                });
            subs.header_response.context_menu(|ui| {
                if ui.button(t(Msg::NewSub)).clicked() {
                    action = Some(TreeAction::NewSub);
                    ui.close();
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
    action
}
