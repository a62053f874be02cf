//! Element properties (Alt+Enter, the right-click menu, a double-click on a contact's or
//! coil's label): its address's symbol and comments (zh, en) edited in place, in a small
//! form over the element, and written into the symbol tables as one undoable change
//! (`ladder_engine::model::sheets::plan_properties`).

use super::context::Context;
use super::i18n::Msg;
use super::ladder_view::{Geometry, address_of};
use super::theme;
use ladder_engine::Address;
use ladder_engine::model::sheets::{Properties, plan_properties, properties_of};
use ladder_engine::model::{Cell, CellRef};

/// The languages whose comments the form edits, in its order.
const LANGS: [&str; 2] = ["zh", "en"];

/// The open element-properties form (UI state: never saved).
#[derive(Clone, Debug)]
pub struct PropertiesForm {
    /// The element's cell.
    pub at: CellRef,
    /// Its address.
    pub address: Address,
    /// What the form holds.
    pub props: Properties,
    /// Why the last OK was refused.
    pub error: Option<String>,
    /// Just opened: the symbol field takes the keyboard.
    focus: bool,
}

/// The element-properties feature: its form, while open.
#[derive(Default)]
pub struct ElementProperties {
    /// The open form.
    pub form: Option<PropertiesForm>,
}

impl ElementProperties {
    /// Opens the properties of the contact or coil at `at` (the cursor's cell when `None`);
    /// an element without an address (a constant, an undefined symbol) says why not.
    pub fn open(&mut self, cx: &mut Context, at: Option<CellRef>) {
        let at = at.unwrap_or(*cx.cursor);
        let lang = cx.settings.lang;
        let Some(project) = cx.doc().map(|d| d.project()) else {
            return;
        };
        let cell = project
            .ladder
            .blocks
            .get(at.block)
            .and_then(|b| b.networks.get(at.network))
            .and_then(|n| n.cell(at.row, at.col));
        let address = match cell {
            Some(Cell::Contact { operand, .. } | Cell::Coil { operand, .. }) => {
                address_of(project, operand)
            }
            _ => None,
        };
        let Some(address) = address else {
            cx.output
                .say(Msg::PropertiesNoAddress.text(lang).into(), true);
            return;
        };
        let props = properties_of(project, address, &LANGS);
        *cx.cursor = at;
        self.form = Some(PropertiesForm {
            at,
            address,
            props,
            error: None,
            focus: true,
        });
    }

    /// The form, under its element as drawn in `geometry` (or near the top left when the
    /// element is not in view).
    pub fn ui(&mut self, ctx: &egui::Context, cx: &mut Context, geometry: &Geometry) {
        let Some(mut form) = self.form.take() else {
            return;
        };
        let lang = cx.settings.lang;
        let t = |m: Msg| m.text(lang);
        let g = geometry;
        let pos = g
            .cell_rect(form.at.network, form.at.row, form.at.col)
            .filter(|r| g.visible.is_some_and(|v| v.contains(r.center())))
            .map_or(egui::pos2(120.0, 120.0), |r| r.left_bottom());
        let (mut ok, mut close) = (false, false);
        egui::Area::new(egui::Id::unique("element-properties"))
            .order(egui::Order::Foreground)
            .fixed_pos(pos)
            .show(ctx, |ui| {
                egui::Frame::popup(ui.style()).show(ui, |ui| {
                    ui.set_min_width(360.0);
                    ui.strong(format!("{}  {}", t(Msg::ElementProperties), form.address));
                    egui::Grid::new("properties").num_columns(2).show(ui, |ui| {
                        let l = ui.label(t(Msg::SymbolLabel));
                        let r = ui
                            .add(
                                egui::TextEdit::singleline(&mut form.props.name)
                                    .desired_width(220.0),
                            )
                            .labelled_by(l.id);
                        if std::mem::take(&mut form.focus) {
                            r.request_focus();
                        }
                        if r.lost_focus() && ui.input(|i| i.key_pressed(egui::Key::Enter)) {
                            ok = true;
                        }
                        ui.end_row();
                        for (code, text) in &mut form.props.comments {
                            let l = ui.label(format!("{} ({code})", t(Msg::CommentLabel)));
                            ui.add(
                                egui::TextEdit::multiline(text)
                                    .desired_rows(3)
                                    .desired_width(220.0),
                            )
                            .labelled_by(l.id);
                            ui.end_row();
                        }
                    });
                    ui.small(t(Msg::PropertiesHint));
                    if let Some(e) = &form.error {
                        ui.colored_label(theme::ERROR, e);
                    }
                    ui.horizontal(|ui| {
                        ok |= ui.button(t(Msg::FnOk)).clicked();
                        close = ui.button(t(Msg::Cancel)).clicked();
                    });
                });
            });
        close |= ctx.input(|i| i.key_pressed(egui::Key::Escape));
        if ok {
            match apply(cx, &form) {
                Ok(()) => close = true,
                Err(e) => form.error = Some(e),
            }
        }
        if !close {
            self.form = Some(form);
        }
    }
}

/// Writes the form into the symbol tables: one change, one undo step.
fn apply(cx: &mut Context, form: &PropertiesForm) -> Result<(), String> {
    let lang = cx.settings.lang;
    let doc = cx.doc().ok_or(Msg::NoProject.text(lang))?;
    let project = doc.project();
    let change = plan_properties(project, form.address, &form.props)
        .map_err(|e| super::tables::table_error(&e, project.profile(), lang))?;
    cx.apply(change).map(|_| ())
}
