//! The cross-reference views (manual §3.4.6): the reference index as a table that jumps to
//! the element on a double-click, and the bit- and byte-usage tables. What they show is
//! derived from the project once per change, not every frame.

use super::LadderApp;
use super::i18n::Msg;
use super::tree::View;
use egui_extras::{Column, TableBuilder};
use ladder_engine::model::CellRef;
use ladder_engine::xref::{self, Xref};

/// The derived views of one project state.
#[derive(Clone, Debug, Default)]
pub struct XrefCache {
    /// Which document and change it was built for.
    key: Option<(u64, u64)>,
    /// The references.
    xref: Xref,
    /// Each reference's symbol and element text, in the same order.
    rows: Vec<(String, String, String)>,
    /// The bit-usage text.
    bits: String,
    /// The byte-usage text.
    bytes: String,
}

impl LadderApp {
    /// Rebuilds the cross-reference when the project changed since it was built.
    fn refresh_xref(&mut self) {
        let Some(doc) = self.doc.as_ref() else { return };
        let key = (doc.serial, doc.generation);
        if self.xref.key == Some(key) {
            return;
        }
        let project = doc.project();
        let x = xref::build(project);
        self.xref.rows = x
            .refs
            .iter()
            .map(|r| {
                (
                    project.symbol_of(r.address).unwrap_or("").to_string(),
                    project.ladder.blocks[r.block].kind.label(),
                    xref::context(project, r),
                )
            })
            .collect();
        self.xref.bits = xref::bits_text(&x);
        self.xref.bytes = xref::bytes_text(&x);
        self.xref.xref = x;
        self.xref.key = Some(key);
    }

    /// Draws the view the tree selected among the three cross-reference views.
    pub fn xref_ui(&mut self, ui: &mut egui::Ui) {
        self.refresh_xref();
        let lang = self.settings.lang;
        let t = |m: Msg| m.text(lang);
        match self.view {
            View::RefBits => {
                let text = &self.xref.bits;
                egui::ScrollArea::both().show(ui, |ui| ui.monospace(text.as_str()));
                return;
            }
            View::RefBytes => {
                let text = &self.xref.bytes;
                egui::ScrollArea::both().show(ui, |ui| ui.monospace(text.as_str()));
                return;
            }
            _ => {}
        }
        ui.horizontal(|ui| {
            let label = ui.label(t(Msg::XrefFilter));
            ui.add(
                egui::TextEdit::singleline(&mut self.xref_filter)
                    .hint_text("X0002.1 / TOOL_T1")
                    .desired_width(200.0),
            )
            .labelled_by(label.id);
            ui.label(t(Msg::XrefHint));
        });
        // The filter matches an address in any spelling, or a symbol or text it contains.
        let filter = self.xref_filter.trim().to_lowercase();
        let wanted = ladder_engine::Address::parse(&filter).ok();
        let shown: Vec<usize> = (0..self.xref.xref.refs.len())
            .filter(|i| {
                let r = &self.xref.xref.refs[*i];
                let (sym, _, ctx) = &self.xref.rows[*i];
                filter.is_empty()
                    || wanted == Some(r.address)
                    || (wanted.is_none()
                        && (sym.to_lowercase().contains(&filter)
                            || ctx.to_lowercase().contains(&filter)
                            || r.address.to_string().to_lowercase().starts_with(&filter)))
            })
            .collect();
        let mut jump = None;
        // Rows take the clicks; text that could be selected would swallow them.
        ui.style_mut().interaction.selectable_labels = false;
        TableBuilder::new(ui)
            .striped(true)
            .sense(egui::Sense::click())
            .column(Column::auto().at_least(80.0))
            .column(Column::auto().at_least(120.0))
            .column(Column::auto().at_least(40.0))
            .column(Column::auto().at_least(70.0))
            .column(Column::auto().at_least(110.0))
            .column(Column::remainder())
            .header(20.0, |mut h| {
                for m in [
                    Msg::TblAddress,
                    Msg::TblSymbol,
                    Msg::XrefUse,
                    Msg::XrefBlock,
                    Msg::XrefPlace,
                    Msg::XrefElement,
                ] {
                    h.col(|ui| {
                        ui.strong(t(m));
                    });
                }
            })
            .body(|body| {
                body.rows(18.0, shown.len(), |mut row| {
                    let i = shown[row.index()];
                    let r = self.xref.xref.refs[i];
                    let (sym, block, ctx) = &self.xref.rows[i];
                    let texts = [
                        r.address.to_string(),
                        sym.clone(),
                        r.usage.letters().to_string(),
                        block.clone(),
                        format!("N{:04} {}:{}", r.network + 1, r.row + 1, r.col + 1),
                        ctx.clone(),
                    ];
                    let mut hit = false;
                    for text in texts {
                        row.col(|ui| {
                            let l = egui::Label::new(egui::RichText::new(text).monospace())
                                .sense(egui::Sense::click());
                            let resp = ui.add(l);
                            // A third quick click is still a double-click to a user.
                            hit |= resp.double_clicked() || resp.triple_clicked();
                        });
                    }
                    if hit || row.response().double_clicked() {
                        jump = Some(CellRef {
                            block: r.block,
                            network: r.network,
                            row: r.row,
                            col: r.col,
                        });
                    }
                });
            });
        if let Some(at) = jump {
            self.jump(at);
        }
    }
}
