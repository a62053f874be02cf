//! The last compile's findings on the diagram: stepping from one marked cell to the next
//! (F12, Shift+F12), and their count and the message under the cursor in the status bar.

use super::LadderApp;
use super::i18n::Msg;
use super::theme;
use ladder_engine::compiler::Severity;
use ladder_engine::model::CellRef;

/// The marked cell after (`forward`) or before `from` in ladder order, wrapping around.
pub fn step(marks: &[CellRef], from: CellRef, forward: bool) -> Option<CellRef> {
    if forward {
        marks.iter().find(|m| **m > from).or(marks.first()).copied()
    } else {
        marks
            .iter()
            .rev()
            .find(|m| **m < from)
            .or(marks.last())
            .copied()
    }
}

impl LadderApp {
    /// F12 / Shift+F12: the cursor to the next or previous cell the last compile found wrong
    /// (compiling first when nothing was compiled yet).
    pub fn step_error(&mut self, forward: bool) {
        if self.doc.as_ref().is_some_and(|d| d.compiled().is_none()) {
            self.compile();
        }
        let Some(doc) = self.doc.as_ref() else { return };
        let marks: Vec<CellRef> = doc.marks().into_iter().map(|(c, _)| c).collect();
        match step(&marks, self.edit.cursor, forward) {
            Some(at) => self.jump(at),
            None => {
                let text = Msg::NoMarks.text(self.settings.lang).to_string();
                self.output.say(text, false);
            }
        }
    }

    /// The status bar's part: how many errors and warnings the diagram carries (their list
    /// on hover), and the message of the one under the cursor.
    pub(crate) fn marks_status_ui(&self, ui: &mut egui::Ui) {
        let Some(doc) = self.doc.as_ref() else { return };
        let marks = doc.marks();
        if marks.is_empty() {
            return;
        }
        let lang = self.settings.lang;
        let name = doc.name().unwrap_or_default();
        let render = |d: &ladder_engine::compiler::Diagnostic| match lang {
            super::i18n::Lang::Zh => d.render_zh(&name),
            super::i18n::Lang::En => d.render(&name),
        };
        let errors = marks
            .iter()
            .filter(|(_, d)| d.severity() == Severity::Error)
            .count();
        let warnings = marks.len() - errors;
        ui.separator();
        let color = if errors > 0 {
            theme::ERROR
        } else {
            theme::CAUTION
        };
        let text = format!(
            "⚠ {errors} {}, {warnings} {} (F12)",
            Msg::ErrorsInDiagram.text(lang),
            Msg::WarningsInDiagram.text(lang)
        );
        ui.colored_label(color, text).on_hover_ui(|ui| {
            for (_, d) in marks.iter().take(20) {
                ui.label(render(d));
            }
        });
        if let Some((_, d)) = marks.iter().find(|(c, _)| *c == self.edit.cursor) {
            ui.colored_label(color, render(d));
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn at(network: usize, row: usize, col: usize) -> CellRef {
        CellRef {
            block: 1,
            network,
            row,
            col,
        }
    }

    #[test]
    fn steps_go_in_ladder_order_and_wrap_around() {
        let marks = [at(2, 0, 3), at(2, 1, 0), at(7, 0, 0)];
        assert_eq!(step(&marks, at(0, 0, 0), true), Some(at(2, 0, 3)));
        assert_eq!(step(&marks, at(2, 0, 3), true), Some(at(2, 1, 0)));
        assert_eq!(step(&marks, at(7, 0, 0), true), Some(at(2, 0, 3)), "wraps");
        assert_eq!(step(&marks, at(2, 1, 0), false), Some(at(2, 0, 3)));
        assert_eq!(step(&marks, at(1, 0, 0), false), Some(at(7, 0, 0)), "wraps");
        assert_eq!(step(&[], at(1, 0, 0), true), None);
    }
}
