//! Ctrl+H: find and replace with a preview. Every place the replace would touch is listed
//! (where, the cell before and after, or why it is skipped) with the counts, before anything
//! changes; *Replace all* is one undo step, *Replace the selected one* changes one place.

use super::command::Command;
use super::context::Context;
use super::i18n::Msg;
use super::theme;
use ladder_engine::find::{self, Planned, Query};
use ladder_engine::model::{Cell, Edit, Operand};

/// The replace window's state (UI state: never saved).
#[derive(Clone, Debug, Default)]
pub struct ReplaceDialog {
    /// What to find.
    pub from: String,
    /// What to put instead.
    pub to: String,
    /// The place selected in the preview.
    pub selected: usize,
    /// Why the last replace was refused.
    pub error: Option<String>,
    /// Just opened: the first field takes the keyboard.
    pub focus_first: bool,
    /// The preview, for the texts and the document change it was made from.
    plan: Option<(PlanKey, Result<Vec<Planned>, String>)>,
}

/// What a preview was made from: the two texts, the document and its change count.
type PlanKey = (String, String, u64, u64);

/// How a cell reads in the preview: its operands as written.
fn cell_text(cell: &Cell) -> String {
    match cell {
        Cell::Contact { operand, .. } | Cell::Coil { operand, .. } => operand.to_string(),
        Cell::Box { op, operands } => {
            let ops: Vec<String> = operands.iter().map(Operand::to_string).collect();
            format!("{} {}", op.name(), ops.join(" "))
        }
        other => format!("{other:?}"),
    }
}

/// The find-and-replace feature: its window, while open.
#[derive(Default)]
pub struct Replace {
    /// The open window.
    pub dialog: Option<ReplaceDialog>,
}

impl Replace {
    /// Opens the window, with `last_find` (the last text searched for) as what to find.
    pub fn open(&mut self, last_find: &str) {
        if self.dialog.is_none() {
            self.dialog = Some(ReplaceDialog {
                from: last_find.to_string(),
                focus_first: true,
                ..Default::default()
            });
        }
    }

    /// The preview of `d` on the open project, computed again only when the texts or the
    /// project changed.
    fn plan(cx: &Context, d: &mut ReplaceDialog) {
        let lang = cx.settings.lang;
        let Some(doc) = cx.doc() else {
            d.plan = None;
            return;
        };
        let key = (d.from.clone(), d.to.clone(), doc.serial(), doc.generation());
        if d.plan.as_ref().is_some_and(|(k, _)| *k == key) {
            return;
        }
        let plan = (|| {
            let (from, to) = (d.from.trim(), d.to.trim());
            if from.is_empty() {
                return Ok(Vec::new());
            }
            let query = Query::parse(from)
                .ok_or_else(|| format!("`{from}`: {}", Msg::NothingToFind.text(lang)))?;
            if to.is_empty() {
                return Ok(Vec::new());
            }
            let to = Operand::parse(to).map_err(|e| super::errors::operand_error(&e, lang))?;
            Ok(find::replace_plan(doc.project(), &query, &to))
        })();
        d.selected = d
            .selected
            .min(plan.as_ref().map_or(0, |p| p.len().saturating_sub(1)));
        d.plan = Some((key, plan));
    }

    /// Draws the replace window while it is open.
    /// The window stays inside `area` (below the menu bar).
    pub fn ui(&mut self, ctx: &egui::Context, cx: &mut Context, area: egui::Rect) {
        let Some(mut d) = self.dialog.take() else {
            return;
        };
        let lang = cx.settings.lang;
        let t = |m: Msg| m.text(lang);
        Replace::plan(cx, &mut d);
        let mut open = true;
        let mut apply: Option<Edit> = None;
        let mut show = None;
        egui::Window::new(t(Msg::ReplaceTitle))
            .id(egui::Id::unique("replace"))
            .open(&mut open)
            .default_size([520.0, 340.0])
            .default_pos(area.min + egui::vec2(40.0, 40.0))
            .constrain_to(area)
            .resizable(true)
            .collapsible(false)
            .show(ctx, |ui| {
                egui::Grid::new("replace-fields")
                    .num_columns(2)
                    .show(ui, |ui| {
                        let l = ui.label(t(Msg::ReplaceFrom));
                        let from = ui
                            .add(
                                egui::TextEdit::singleline(&mut d.from)
                                    .hint_text("X0002.1 · START · R100")
                                    .desired_width(220.0),
                            )
                            .labelled_by(l.id);
                        // Opened: the keyboard goes to the first field.
                        if std::mem::take(&mut d.focus_first) {
                            from.request_focus();
                        }
                        ui.end_row();
                        let l = ui.label(t(Msg::ReplaceTo));
                        ui.add(
                            egui::TextEdit::singleline(&mut d.to)
                                .hint_text("X0003.1")
                                .desired_width(220.0),
                        )
                        .labelled_by(l.id);
                        ui.end_row();
                    });
                let plan = d.plan.as_ref().map(|(_, p)| p);
                match plan {
                    Some(Err(e)) => {
                        ui.colored_label(theme::ERROR, e);
                    }
                    Some(Ok(plan)) if !plan.is_empty() => {
                        let change = plan.iter().filter(|p| p.after.is_some()).count();
                        ui.label(format!(
                            "{} {}: {change} {}, {} {}",
                            plan.len(),
                            t(Msg::ReplacePlaces),
                            t(Msg::ReplaceWillChange),
                            plan.len() - change,
                            t(Msg::ReplaceSkipped)
                        ));
                        egui::ScrollArea::vertical()
                            .max_height(ui.available_height() - 36.0)
                            .auto_shrink([false, true])
                            .show(ui, |ui| {
                                for (i, p) in plan.iter().enumerate() {
                                    let project = cx.doc().map(|d| d.project());
                                    let block = project
                                        .and_then(|pr| pr.ladder.blocks.get(p.at.block))
                                        .map_or(String::new(), |b| b.kind.label());
                                    let place = format!(
                                        "{block} N{:04} {}:{}",
                                        p.at.network + 1,
                                        p.at.row + 1,
                                        p.at.col + 1
                                    );
                                    let (text, color) = match &p.after {
                                        Some(after) => (
                                            format!(
                                                "{place}   {} → {}",
                                                cell_text(&p.before),
                                                cell_text(after)
                                            ),
                                            ui.visuals().text_color(),
                                        ),
                                        None => (
                                            format!(
                                                "{place}   {}   ({})",
                                                cell_text(&p.before),
                                                t(Msg::ReplaceSkipped)
                                            ),
                                            theme::CAUTION,
                                        ),
                                    };
                                    let r = ui.selectable_label(
                                        d.selected == i,
                                        egui::RichText::new(text).color(color),
                                    );
                                    if r.clicked() {
                                        d.selected = i;
                                        show = Some(p.at);
                                    }
                                }
                            });
                        ui.horizontal(|ui| {
                            let one = plan.get(d.selected).and_then(Planned::edit);
                            if ui
                                .add_enabled(one.is_some(), egui::Button::new(t(Msg::ReplaceOne)))
                                .clicked()
                            {
                                apply = one;
                            }
                            let all: Vec<Edit> = plan.iter().filter_map(Planned::edit).collect();
                            let label = format!("{} ({})", t(Msg::ReplaceAll), all.len());
                            if ui
                                .add_enabled(!all.is_empty(), egui::Button::new(label))
                                .clicked()
                            {
                                apply = Some(Edit::Batch(all));
                            }
                        });
                    }
                    Some(Ok(_)) if !d.from.trim().is_empty() && !d.to.trim().is_empty() => {
                        ui.label(t(Msg::ReplaceNone));
                    }
                    _ => {}
                }
                if let Some(e) = &d.error {
                    ui.colored_label(theme::ERROR, e);
                }
            });
        if let Some(at) = show {
            cx.pending.push(Command::ShowCell(at));
        }
        if let Some(edit) = apply {
            // One apply: the whole replace is one undo step.
            match cx.apply(edit) {
                Ok(_) => d.error = None,
                Err(e) => d.error = Some(e),
            }
        }
        if open && !ctx.input(|i| i.key_pressed(egui::Key::Escape)) {
            self.dialog = Some(d);
        }
    }
}
