//! The cross-reference views (manual §3.4.6): the reference index as a table that jumps to
//! the element on a double-click, and the bit- and byte-usage tables. What they show is
//! derived from the project once per change, not every frame.
//!
//! A widget: [`xref_ui`] takes the document and its own state and returns what the user
//! asked for; the application does it.

use super::document::Document;
use super::i18n::{Lang, Msg};
use super::tree::View;
use egui_extras::{Column, TableBuilder};
use ladder_engine::model::CellRef;
use ladder_engine::xref::{self, Xref};

/// What a double-click in the reference index asks for.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum XrefEvent {
    /// Show this element in its ladder.
    Jump(CellRef),
}

/// The cross-reference views' own state: what the index is filtered by, and what was derived
/// from the project (rebuilt when the document changes).
#[derive(Clone, Debug, Default)]
pub struct XrefState {
    /// What the reference index is filtered by.
    pub filter: String,
    cache: XrefCache,
}

/// The derived views of one project state.
#[derive(Clone, Debug, Default)]
struct XrefCache {
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

impl XrefCache {
    /// Rebuilds the cross-reference when the document changed since it was built.
    fn refresh(&mut self, doc: &Document) {
        let key = (doc.serial(), doc.generation());
        if self.key == Some(key) {
            return;
        }
        let project = doc.project();
        let x = xref::build(project);
        self.rows = x
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
        self.bits = xref::bits_text(&x);
        self.bytes = xref::bytes_text(&x);
        self.xref = x;
        self.key = Some(key);
    }
}

/// Draws `view`, one of the three cross-reference views, of `doc`.
pub fn xref_ui(
    ui: &mut egui::Ui,
    doc: &Document,
    view: View,
    state: &mut XrefState,
    lang: Lang,
) -> Option<XrefEvent> {
    state.cache.refresh(doc);
    let cache = &state.cache;
    let t = |m: Msg| m.text(lang);
    {
        match view {
            View::RefBits => {
                let text = &cache.bits;
                egui::ScrollArea::both().show(ui, |ui| ui.monospace(text.as_str()));
                return None;
            }
            View::RefBytes => {
                let text = &cache.bytes;
                egui::ScrollArea::both().show(ui, |ui| ui.monospace(text.as_str()));
                return None;
            }
            _ => {}
        }
        ui.horizontal(|ui| {
            let label = ui.label(t(Msg::XrefFilter));
            ui.add(
                egui::TextEdit::singleline(&mut state.filter)
                    .hint_text("X0002.1 / TOOL_T1")
                    .desired_width(200.0),
            )
            .labelled_by(label.id);
            ui.label(t(Msg::XrefHint));
        });
        // The filter matches an address in any spelling, or a symbol or text it contains.
        let filter = state.filter.trim().to_lowercase();
        let wanted = ladder_engine::Address::parse(&filter).ok();
        let shown: Vec<usize> = (0..cache.xref.refs.len())
            .filter(|i| {
                let r = &cache.xref.refs[*i];
                let (sym, _, ctx) = &cache.rows[*i];
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
                    let r = cache.xref.refs[i];
                    let (sym, block, ctx) = &cache.rows[i];
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
        jump.map(XrefEvent::Jump)
    }
}
