//! The K page (§3.4.4.1): a line per K byte of the profile, a checkbox per bit (7 … 0), the
//! byte in hex; hovering a bit shows its symbol and comment from the symbol tables.

use super::super::i18n::{Lang, Msg};
use super::sheet::{Action, run_actions};
use super::{TableEvent, TableState, row_height};
use egui_extras::{Column, TableBuilder};
use ladder_engine::model::Project;
use ladder_engine::{Address, Area};

/// Draws the K page; a clicked bit becomes an edit of the data tables.
pub(super) fn k_page_ui(
    ui: &mut egui::Ui,
    project: &Project,
    state: &mut TableState,
    lang: Lang,
    events: &mut Vec<TableEvent>,
) {
    let t = |m: Msg| m.text(lang);
    let data = &project.data;
    let (lo, hi) = project.profile().range(Area::K);
    let mut actions = Vec::new();
    let row_height = row_height(ui);
    TableBuilder::new(ui)
        .id_salt("k-page")
        .striped(true)
        .cell_layout(egui::Layout::left_to_right(egui::Align::Center))
        .column(Column::exact(80.0))
        .columns(Column::exact(28.0), 8)
        .column(Column::remainder())
        .header(row_height, |mut header| {
            header.col(|ui| {
                ui.strong(t(Msg::TblAddress));
            });
            for bit in (0..8).rev() {
                header.col(|ui| {
                    ui.strong(bit.to_string());
                });
            }
            header.col(|ui| {
                ui.strong(t(Msg::TblHex));
            });
        })
        .body(|body| {
            body.rows(row_height, usize::from(hi - lo) + 1, |mut row| {
                let number = usize::from(lo) + row.index();
                row.col(|ui| {
                    ui.label(Address::byte(Area::K, number as u16).to_string());
                });
                for bit in (0..8u8).rev() {
                    row.col(|ui| {
                        let address = Address::bit(Area::K, number as u16, bit);
                        let mut on = data.k_bit(number, bit);
                        let r = ui
                            .add(egui::Checkbox::without_text(&mut on))
                            .accessible_name(address.to_string());
                        if r.changed() {
                            actions.push(Action::KBit { number, bit, on });
                        }
                        // Looked up only while hovered: a scan of every symbol per bit per
                        // frame would not stay cheap with thousands of symbols.
                        r.on_hover_ui(|ui| {
                            ui.label(address.to_string());
                            if let Some(s) = project.symbols().find(|s| s.address == address) {
                                ui.label(&s.name);
                                if let Some(c) = s.comments.get(lang.code()) {
                                    ui.label(c);
                                }
                            }
                        });
                    });
                }
                row.col(|ui| {
                    let byte = data.k.get(number).copied().unwrap_or(0);
                    ui.monospace(format!("{byte:02X}"));
                });
            });
        });
    run_actions(project, state, actions, events);
}
