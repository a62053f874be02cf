//! The project tree (manual §3.4): the nine nodes, the ladder's blocks and subprograms.

use super::command::Command;
use super::i18n::{Lang, Msg};
use super::place::BlockKey;
pub use super::place::View;
use ladder_engine::model::{BlockKind, Project};

/// What a click or a right-click menu in the tree asked for.
type Asked = Option<Command>;

fn leaf(
    ui: &mut egui::Ui,
    asked: &mut Asked,
    current: View,
    view: View,
    text: &str,
) -> egui::Response {
    let r = ui.selectable_label(current == view, text);
    if r.clicked() {
        *asked = Some(Command::ShowView(view));
    }
    r
}

/// A right-click menu's entries.
fn menu(ui: &mut egui::Ui, asked: &mut Asked, lang: Lang, entries: &[Command]) {
    for c in entries {
        if ui.button(c.text().text(lang)).clicked() {
            *asked = Some(*c);
            ui.close();
        }
    }
}

/// Draws the tree of the project and returns what the user asked for: a click shows a view,
/// a right-click offers the block commands. A widget: the caller runs the command.
pub fn tree_ui(ui: &mut egui::Ui, project: &Project, lang: Lang, current: View) -> Option<Command> {
    let t = |m: Msg| m.text(lang);
    let mut asked = None;
    let a = &mut asked;
    egui::CollapsingHeader::new(t(Msg::Ladder))
        .default_open(true)
        .show(ui, |ui| {
            for (i, m, key) in [
                (0, Msg::Level1, BlockKey::Level1),
                (1, Msg::Level2, BlockKey::Level2),
            ] {
                leaf(ui, a, current, View::Block(i), t(m))
                    .context_menu(|ui| menu(ui, a, lang, &[Command::BlockInfo(key)]));
            }
            let subs = egui::CollapsingHeader::new(t(Msg::Subprograms))
                .default_open(true)
                .show(ui, |ui| {
                    for (i, b) in project.ladder.blocks.iter().enumerate().skip(2) {
                        if let BlockKind::Sub { number, name } = &b.kind {
                            let r = leaf(
                                ui,
                                a,
                                current,
                                View::Block(i),
                                &format!("P{number:04} {name}"),
                            );
                            let r = if b.info.is_empty() {
                                r
                            } else {
                                r.on_hover_text(&b.info)
                            };
                            let n = *number;
                            r.context_menu(|ui| {
                                menu(
                                    ui,
                                    a,
                                    lang,
                                    &[
                                        Command::ViewCalls(n),
                                        Command::RenameSub(n),
                                        Command::BlockInfo(BlockKey::Sub(n)),
                                        Command::DeleteSub(n),
                                        Command::NewSub,
                                    ],
                                )
                            });
                        }
                    }
                });
            subs.header_response
                .context_menu(|ui| menu(ui, a, lang, &[Command::NewSub]));
        });
    egui::CollapsingHeader::new(t(Msg::SymbolTables))
        .default_open(true)
        .show(ui, |ui| {
            for (i, table) in project.symbol_tables.iter().enumerate() {
                leaf(ui, a, current, View::Symbols(i), &table.name);
            }
        });
    leaf(ui, a, current, View::Data, t(Msg::DataTables));
    leaf(ui, a, current, View::Messages, t(Msg::Messages));
    egui::CollapsingHeader::new(t(Msg::Reference))
        .default_open(false)
        .show(ui, |ui| {
            leaf(ui, a, current, View::RefIndex, t(Msg::RefIndex));
            leaf(ui, a, current, View::RefBits, t(Msg::RefBits));
            leaf(ui, a, current, View::RefBytes, t(Msg::RefBytes));
        });
    leaf(ui, a, current, View::Diagnosis, t(Msg::Diagnosis));
    leaf(ui, a, current, View::Permissions, t(Msg::Permissions));
    leaf(ui, a, current, View::MCodes, t(Msg::MCodes));
    leaf(ui, a, current, View::Version, t(Msg::VersionInfo));
    leaf(ui, a, current, View::Scenarios, t(Msg::Scenarios));
    asked
}
