//! The Help windows: the keyboard shortcuts (from the command list), the instructions
//! (from the catalogue) and About.

use super::command::{Command, HelpPage};
use super::i18n::{Lang, Msg};

/// The Help window of `page`, while open (closing it empties `page`).
pub fn ui(page: &mut Option<HelpPage>, ctx: &egui::Context, lang: Lang) {
    let Some(shown) = *page else { return };
    let t = |m: Msg| m.text(lang);
    let mut open = true;
    egui::Window::new(t(Command::Help(shown).text()))
        .open(&mut open)
        .default_size([520.0, 480.0])
        .vscroll(true)
        .show(ctx, |ui| match shown {
            HelpPage::About => {
                ui.heading(format!("Ladder Studio {}", env!("CARGO_PKG_VERSION")));
                ui.label(t(Msg::AboutText));
                ui.label(env!("CARGO_PKG_LICENSE"));
            }
            HelpPage::Shortcuts => {
                egui::Grid::new("shortcuts").striped(true).show(ui, |ui| {
                    for (keys, what) in super::dispatch::shortcut_rows() {
                        ui.monospace(keys);
                        ui.label(t(what));
                        ui.end_row();
                    }
                });
            }
            HelpPage::Instructions => {
                for spec in ladder_engine::catalog::CATALOG.iter() {
                    let (help, cat) = match lang {
                        Lang::Zh => (spec.help_zh, spec.category.name_zh()),
                        Lang::En => (spec.help_en, spec.category.name_en()),
                    };
                    ui.collapsing(format!("{}  ({cat})", spec.name), |ui| {
                        ui.label(help);
                        for o in spec.operands {
                            let h = match lang {
                                Lang::Zh => o.help_zh,
                                Lang::En => o.help_en,
                            };
                            ui.label(format!("{}: {h}", o.name));
                        }
                    });
                }
            }
        });
    if !open {
        *page = None;
    }
}
