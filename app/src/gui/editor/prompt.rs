//! The prompt where operands, titles and the texts of Find, Go to and the subprogram
//! commands are typed. What belongs to a cell (an operand after F1, F2, F6) or to a network
//! (its title or comment) is typed in place, in a field over it with the symbol suggestions
//! under it: the eye stays on the rung and nothing moves. The rest is typed in a bar under
//! the toolbar.

use crate::gui::context::Context;
use crate::gui::editor::EditState;
use crate::gui::editor::editing::PlaceKind;
use crate::gui::i18n::Msg;
use crate::gui::place::View;
use egui::{Key, Modifiers};
use ladder_engine::model::Operand;

/// Where a prompt of this kind is typed in place: the cursor's cell, the output column for
/// a coil, the network's header for its title or comment.
fn in_place(kind: PlaceKind) -> bool {
    matches!(
        kind,
        PlaceKind::Contact { .. }
            | PlaceKind::Coil { .. }
            | PlaceKind::Parallel { .. }
            | PlaceKind::NetworkTitle
            | PlaceKind::NetworkComment
    )
}

impl EditState {
    /// Where the open prompt is typed in place on screen (the rectangle it covers), when it
    /// belongs to a cell or network that was drawn last frame.
    pub fn prompt_place(&self, cx: &Context<'_>) -> Option<egui::Rect> {
        let prompt = self.prompt.as_ref().filter(|p| in_place(p.kind))?;
        let c = *cx.cursor;
        if *cx.view != View::Block(c.block) {
            return None;
        }
        let g = &self.geometry;
        let rect = match prompt.kind {
            PlaceKind::NetworkTitle | PlaceKind::NetworkComment => {
                let top = g.origin.y + g.tops.get(c.network)?;
                egui::Rect::from_min_size(
                    egui::pos2(g.origin.x + g.margin, top),
                    egui::vec2(g.cell * 4.0, g.cell * 0.3),
                )
            }
            PlaceKind::Coil { .. } => g.cell_rect(c.network, c.row, g.width)?,
            _ => g.cell_rect(c.network, c.row, c.col.min(g.width.saturating_sub(1)))?,
        };
        // Only where it can be seen: else the bar takes it.
        g.visible.filter(|v| v.contains(rect.center()))?;
        Some(rect)
    }

    /// The prompt in place over its cell or network, when it has one on screen (else the bar
    /// under the toolbar shows it).
    pub fn prompt_window(&mut self, cx: &mut Context<'_>, ctx: &egui::Context) {
        let Some(rect) = self.prompt_place(cx) else {
            return;
        };
        egui::Area::new(egui::Id::unique("prompt-in-place"))
            .order(egui::Order::Foreground)
            .fixed_pos(rect.left_top())
            .show(ctx, |ui| {
                egui::Frame::popup(ui.style()).show(ui, |ui| {
                    ui.set_max_width(rect.width().max(220.0));
                    self.prompt_ui(cx, ui);
                });
            });
    }

    /// The operand prompt: a text field; Enter places, Escape cancels.
    pub fn prompt_ui(&mut self, cx: &mut Context<'_>, ui: &mut egui::Ui) {
        let Some(mut prompt) = self.prompt.take() else {
            return;
        };
        let lang = cx.settings.lang;
        let mut close = false;
        let label = match prompt.kind {
            PlaceKind::Find => Msg::FindPrompt,
            PlaceKind::GoToRow(_) => Msg::GoToRowPrompt,
            PlaceKind::GoTo => Msg::GoToPrompt,
            PlaceKind::NetworkTitle => Msg::TitlePrompt,
            PlaceKind::NetworkComment => Msg::CommentPrompt,
            PlaceKind::NewSub | PlaceKind::RenameSub(_) => Msg::SubPrompt,
            PlaceKind::BlockInfo(_) => Msg::BlockInfoPrompt,
            _ => Msg::Operand,
        };
        let completes = matches!(
            prompt.kind,
            PlaceKind::Contact { .. } | PlaceKind::Coil { .. } | PlaceKind::Parallel { .. }
        );
        let suggestions = if completes {
            self.suggestions(cx, &prompt.text)
        } else {
            Vec::new()
        };
        // Tab takes the first suggestion (before the text field sees the key).
        if !suggestions.is_empty() && ui.input_mut(|i| i.consume_key(Modifiers::NONE, Key::Tab)) {
            prompt.text = suggestions[0].0.clone();
        }
        let placed = in_place(prompt.kind);
        // In place the field fills its frame and the suggestions are a list under it.
        let width = if placed {
            ui.max_rect().width().max(200.0)
        } else {
            280.0
        };
        ui.horizontal(|ui| {
            let label = ui.label(label.text(lang));
            let r = ui
                .add(
                    egui::TextEdit::singleline(&mut prompt.text)
                        .hint_text(match prompt.kind {
                            _ if completes => "X0002.1",
                            PlaceKind::Find => "X0002.1 · X2.1 · START · MOVN · 100",
                            PlaceKind::GoToRow(_) => "25",
                            PlaceKind::GoTo => "12 3",
                            _ => "",
                        })
                        .desired_width(width),
                )
                .labelled_by(label.id);
            r.request_focus();
            if let Some(e) = &prompt.error {
                ui.colored_label(crate::gui::theme::ERROR, e);
            }
            if ui.input(|i| i.key_pressed(Key::Escape)) {
                close = true;
            } else if ui.input(|i| i.key_pressed(Key::Enter)) {
                let text = prompt.text.trim().to_string();
                cx.begin_group();
                let placed = self.place(cx, prompt.kind, &text);
                cx.end_group();
                match placed {
                    Ok(()) => close = true,
                    Err(e) => prompt.error = Some(e),
                }
            }
        });
        if !suggestions.is_empty() && !close {
            let mut pick = |ui: &mut egui::Ui| {
                for (name, shown) in &suggestions {
                    if ui.small_button(shown).clicked() {
                        prompt.text = name.clone();
                    }
                }
            };
            if placed {
                ui.label(Msg::Suggestions.text(lang));
                pick(ui);
            } else {
                ui.horizontal_wrapped(|ui| {
                    ui.label(Msg::Suggestions.text(lang));
                    pick(ui);
                });
            }
        }
        if !close {
            self.prompt = Some(prompt);
        }
    }

    /// Symbols for what has been typed: names starting with it first, then names or comments
    /// containing it; an address typed in full shows its symbol. Up to eight, as (text to
    /// enter, text shown).
    pub fn suggestions(&self, cx: &Context<'_>, typed: &str) -> Vec<(String, String)> {
        let typed = typed.trim();
        let Some(doc) = cx.doc().filter(|_| !typed.is_empty()) else {
            return Vec::new();
        };
        let project = doc.project();
        let lang = cx.settings.lang.code();
        let lower = typed.to_lowercase();
        let shown = |s: &ladder_engine::model::Symbol| {
            let comment = s.comments.get(lang).map_or("", String::as_str);
            format!("{}  {}  {comment}", s.name, s.address)
                .trim_end()
                .to_string()
        };
        if let Ok(Operand::Addr(a)) = Operand::parse(typed) {
            return project
                .symbols()
                .filter(|s| s.address == a && !s.name.is_empty())
                .take(1)
                .map(|s| (a.to_string(), shown(s)))
                .collect();
        }
        let named = || project.symbols().filter(|s| !s.name.is_empty());
        let mut out: Vec<(String, String)> = named()
            .filter(|s| s.name.to_lowercase().starts_with(&lower))
            .map(|s| (s.name.clone(), shown(s)))
            .collect();
        out.extend(
            named()
                .filter(|s| {
                    !s.name.to_lowercase().starts_with(&lower)
                        && (s.name.to_lowercase().contains(&lower)
                            || s.comments
                                .values()
                                .any(|c| c.to_lowercase().contains(&lower)))
                })
                .map(|s| (s.name.clone(), shown(s))),
        );
        out.truncate(8);
        out
    }
}
