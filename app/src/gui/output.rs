//! The output window: what the editor says (compile lists, find results, refusals, files
//! written) and where a line goes when clicked. It owns its lines and how far it has shown
//! them; everyone else only says things to it.

use super::i18n::{Lang, Msg};
use super::theme;
use ladder_engine::model::CellRef;

/// One line of the output window; diagnostics remember where to jump.
#[derive(Clone, Debug, PartialEq)]
pub struct OutputLine {
    /// The text.
    pub text: String,
    /// An error (shown red).
    pub error: bool,
    /// The cell to show on a click.
    pub target: Option<CellRef>,
}

/// The output window's lines and scroll memory.
#[derive(Default)]
pub struct Output {
    lines: Vec<OutputLine>,
    /// What the window showed last frame (line count, first line), to scroll to what is
    /// new: the first line of a new list, or the last of lines added.
    seen: (usize, String),
    /// A line was said since the window was drawn: it scrolls to the last line.
    to_last: bool,
}

impl std::ops::Deref for Output {
    type Target = [OutputLine];

    fn deref(&self) -> &[OutputLine] {
        &self.lines
    }
}

impl Output {
    /// Adds a line; the window scrolls to it, even after a list replaced what was above.
    pub fn say(&mut self, text: String, error: bool) {
        self.push(OutputLine {
            text,
            error,
            target: None,
        });
        self.to_last = true;
    }

    /// Adds a line (a refusal, a note) without asking the window to scroll to it.
    pub fn push(&mut self, line: OutputLine) {
        self.lines.push(line);
    }

    /// Replaces every line with a new list (a compile, a find); the window shows its top.
    pub fn list(&mut self, lines: Vec<OutputLine>) {
        self.lines = lines;
    }

    /// Empties the window (another project).
    pub fn clear(&mut self) {
        self.lines.clear();
    }

    /// Draws the window; returns the cell of the line clicked, if any.
    pub fn ui(&mut self, ui: &mut egui::Ui, lang: Lang) -> Option<CellRef> {
        ui.horizontal(|ui| {
            ui.label(Msg::Output.text(lang));
            if !self.lines.is_empty() && ui.small_button(Msg::CopyAll.text(lang)).clicked() {
                let all: Vec<&str> = self.lines.iter().map(|l| l.text.as_str()).collect();
                ui.ctx().copy_text(all.join("\n"));
            }
        });
        let first = self.lines.first().map_or("", |l| l.text.as_str());
        let to_last = std::mem::take(&mut self.to_last);
        let new_list = first != self.seen.1 && !to_last;
        let added = to_last || (first == self.seen.1 && self.lines.len() > self.seen.0);
        if new_list || self.lines.len() != self.seen.0 {
            self.seen = (self.lines.len(), first.to_string());
        }
        let mut jump = None;
        egui::ScrollArea::vertical()
            .auto_shrink([false, false])
            .show(ui, |ui| {
                let last = self.lines.len().saturating_sub(1);
                for (i, line) in self.lines.iter().enumerate() {
                    let color = if line.error {
                        theme::ERROR
                    } else {
                        ui.visuals().text_color()
                    };
                    let r = ui.add(
                        egui::Label::new(egui::RichText::new(&line.text).color(color))
                            .sense(egui::Sense::click()),
                    );
                    if r.double_clicked() || r.clicked() {
                        jump = line.target;
                    }
                    r.context_menu(|ui| {
                        if ui.button(Msg::CopyLine.text(lang)).clicked() {
                            ui.ctx().copy_text(line.text.clone());
                            ui.close();
                        }
                    });
                    if (new_list && i == 0) || (added && i == last) {
                        r.scroll_to_me(None);
                    }
                }
            });
        jump
    }
}
