//! The label of a contact or coil: its operand (address, symbol or both) above the element,
//! its element comment below it in the chosen language, and the mark of a forced address.

use super::{COMMENT_LINES, OperandPlace, operand_text};
use crate::gui::settings::DisplayMode;
use crate::gui::theme;
use egui::{Align2, FontId, Pos2, Rect, Stroke, StrokeKind, pos2, vec2};
use ladder_engine::Address;
use ladder_engine::model::{Operand, Project};

/// The address an operand stands for (a symbol through the symbol tables).
pub fn address_of(project: &Project, o: &Operand) -> Option<Address> {
    match o {
        Operand::Addr(a) => Some(*a),
        Operand::Symbol(s) => project.resolve_symbol(s),
        _ => None,
    }
}

/// How a contact's or coil's operand is labelled.
pub(super) struct BitLabel<'a> {
    /// The project, for symbols and comments.
    pub(super) project: &'a Project,
    /// Address, symbol or both.
    pub(super) mode: DisplayMode,
    /// The label's font.
    pub(super) font: &'a FontId,
    /// Its size.
    pub(super) size: f32,
    /// The distance between two label lines.
    pub(super) line: f32,
    /// The language of the element comment written under it, when comments are shown.
    pub(super) comment: Option<&'static str>,
}

/// The horizontal room of a label: centred on `centre`, never past `left` or `right`.
#[derive(Clone, Copy)]
pub(super) struct Span {
    /// Where the label is centred.
    pub(super) centre: f32,
    /// Its leftmost edge.
    pub(super) left: f32,
    /// Its rightmost edge.
    pub(super) right: f32,
}

impl BitLabel<'_> {
    /// The operand's text above `ys.0` (address over symbol in "both" mode, each on its own
    /// line), the element comment below `ys.1` when shown, and the force mark at `mark`
    /// (given when the element is forced).
    /// Every line is cut with an ellipsis at the span's edges: the tooltip shows it whole.
    pub(super) fn draw(
        &self,
        painter: &egui::Painter,
        drawn: &mut Vec<(Rect, String)>,
        operand: &Operand,
        span: Span,
        ys: (f32, f32),
        mark: Option<Pos2>,
    ) {
        let (text, color) = operand_text(
            self.project,
            operand,
            self.mode,
            OperandPlace::Bit,
            std::slice::from_ref(operand),
        );
        let line = self.line;
        // "ADDRESS:SYMBOL" is one text for the find and the tooltip; drawn, it is two lines.
        let lines: Vec<&str> = match (self.mode, text.split_once(':')) {
            (DisplayMode::Both, Some((a, s))) => vec![a, s],
            _ => vec![text.as_str()],
        };
        for (i, t) in lines.iter().rev().enumerate() {
            let y = ys.0 - line * i as f32;
            drawn.push(self.line(painter, t, span, y, Align2::CENTER_BOTTOM, color));
        }
        if let Some(lang) = self.comment
            && let Some(a) = address_of(self.project, operand)
            && let Some(c) = self.project.comment_of(a, lang)
        {
            drawn.push(self.comment(painter, c, span, ys.1));
        }
        if let Some(at) = mark {
            force_mark(painter, at, self.size);
        }
    }

    /// An element comment from height `y` down: wrapped to the span (its own line breaks
    /// kept), at most [`COMMENT_LINES`] lines, the last ending with "…" when more is left.
    fn comment(&self, painter: &egui::Painter, text: &str, span: Span, y: f32) -> (Rect, String) {
        let width = (span.right - span.left).max(self.size);
        let mut job = egui::text::LayoutJob::default();
        job.append(
            text,
            0.0,
            egui::TextFormat {
                font_id: self.font.clone(),
                color: theme::COMMENT,
                line_height: Some(self.line),
                ..Default::default()
            },
        );
        job.halign = egui::Align::Center;
        job.wrap = egui::text::TextWrapping {
            max_width: width,
            max_rows: COMMENT_LINES,
            break_anywhere: false,
            overflow_character: Some('…'),
        };
        let galley = painter.layout_job(job);
        // A centred galley is laid out about x = 0; its rectangle says how far each way.
        let r = galley.rect;
        let x = span
            .centre
            .clamp(span.left - r.min.x, (span.right - r.max.x).max(span.left));
        let rect = r.translate(vec2(x, y));
        let shown = galley
            .rows
            .iter()
            .flat_map(|r| r.glyphs.iter().map(|g| g.chr))
            .collect();
        painter.galley(pos2(x, y), galley, theme::COMMENT);
        (rect, shown)
    }

    /// One line of text at height `y`, shortened with "…" to fit the span; returns where
    /// it went and what it says.
    fn line(
        &self,
        painter: &egui::Painter,
        text: &str,
        span: Span,
        y: f32,
        align: Align2,
        color: egui::Color32,
    ) -> (Rect, String) {
        let width = (span.right - span.left).max(self.size);
        let mut job =
            egui::text::LayoutJob::simple_singleline(text.into(), self.font.clone(), color);
        job.wrap = egui::text::TextWrapping {
            max_width: width,
            max_rows: 1,
            break_anywhere: true,
            overflow_character: Some('…'),
        };
        let galley = painter.layout_job(job);
        let w = galley.size().x;
        let x = (span.centre - w * 0.5).clamp(span.left, (span.right - w).max(span.left));
        let top = match align.y() {
            egui::Align::Max => y - galley.size().y,
            _ => y,
        };
        let rect = Rect::from_min_size(pos2(x, top), galley.size());
        // What is on screen, the ellipsis included (the galley's text is the whole one).
        let shown = galley
            .rows
            .iter()
            .flat_map(|r| r.glyphs.iter().map(|g| g.chr))
            .collect();
        painter.galley(rect.min, galley, color);
        (rect, shown)
    }
}

/// The mark of a forced element: a small "F" badge.
fn force_mark(painter: &egui::Painter, at: Pos2, font: f32) {
    let r = painter.text(
        at,
        Align2::LEFT_TOP,
        "F",
        FontId::monospace(font),
        theme::FORCED,
    );
    painter.rect_stroke(
        r.expand(1.0),
        2.0,
        Stroke::new(1.0, theme::FORCED),
        StrokeKind::Outside,
    );
}
