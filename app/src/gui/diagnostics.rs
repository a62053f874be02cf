//! The compiler's findings: F9's list in the output window, stepping from one marked cell
//! of the diagram to the next (F12, Shift+F12), and their count and the message under the
//! cursor in the status bar.

use super::OutputLine;
use super::command::Command;
use super::context::Context;
use super::document::Document;
use super::i18n::{Lang, Msg};
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

/// F9: compiles into the output window, a line per diagnostic (a click goes to its cell)
/// and the summary.
pub fn compile(cx: &mut Context) {
    let lang = cx.settings.lang;
    let Some((compiled, name)) = cx.compile() else {
        return;
    };
    let mut lines: Vec<OutputLine> = compiled
        .diagnostics
        .iter()
        .map(|d| OutputLine {
            // The Chinese rendering keeps the English message for its specifics
            // (docs/diagnostics.md lists each code's meaning, which the title gives).
            text: ladder_text::diagnostics::shown(d, &name, lang),
            error: d.severity() == Severity::Error,
            target: d.location.cell(),
        })
        .collect();
    let summary = if compiled.errors() + compiled.warnings() == 0 {
        format!(
            "{} ({} {})",
            Msg::CompileClean.text(lang),
            compiled.steps.total,
            Msg::StepsUnit.text(lang)
        )
    } else {
        ladder_text::cli::Counts::of(compiled).text(lang)
    };
    lines.push(OutputLine {
        text: summary,
        error: compiled.errors() > 0,
        target: None,
    });
    cx.output.list(lines);
}

/// F12 / Shift+F12: the cursor to the next or previous cell the last compile found wrong
/// (compiling first when nothing was compiled yet).
pub fn step_error(cx: &mut Context, forward: bool) {
    if cx.doc().is_some_and(|d| d.compiled().is_none()) {
        compile(cx);
    }
    let Some(doc) = cx.doc() else { return };
    let marks: Vec<CellRef> = doc.marks().into_iter().map(|(c, _)| c).collect();
    match step(&marks, *cx.cursor, forward) {
        Some(at) => cx.pending.push(Command::ShowCell(at)),
        None => {
            let text = Msg::NoMarks.text(cx.settings.lang).to_string();
            cx.output.say(text, false);
        }
    }
}

/// The status bar's part: how many errors and warnings the diagram carries (their list on
/// hover), and the message of the one under the `cursor`.
pub fn status_ui(ui: &mut egui::Ui, doc: &Document, cursor: CellRef, lang: Lang) {
    let marks = doc.marks();
    if marks.is_empty() {
        return;
    }
    let name = doc.name().unwrap_or_default();
    let render =
        |d: &ladder_engine::compiler::Diagnostic| ladder_text::diagnostics::shown(d, &name, lang);
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
    let counts = ladder_text::cli::Counts { errors, warnings };
    let text = format!("⚠ {} (F12)", counts.text(lang));
    ui.colored_label(color, text).on_hover_ui(|ui| {
        for (_, d) in marks.iter().take(20) {
            ui.label(render(d));
        }
    });
    if let Some((_, d)) = marks.iter().find(|(c, _)| *c == cursor) {
        ui.colored_label(color, render(d));
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
