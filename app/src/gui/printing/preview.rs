//! The page setup and print preview windows: the preview paints the same items the PDF
//! and SVG writers write.

use super::super::context::Context;
use super::super::i18n::{Lang as UiLang, Msg};
use super::super::settings::Settings;
use super::super::theme;
use super::PrintState;
use super::ZOOMS;
use egui::{Align2, FontId, Pos2, Rect, Stroke, vec2};
use ladder_print::{Anchor, Ink, Item, Paper, Seg};

impl PrintState {
    /// The page setup and preview windows, when open.
    /// They stay inside `area` (below the menu bar).
    pub fn ui(&mut self, ctx: &egui::Context, cx: &mut Context, area: Rect) {
        if self.setup_open {
            self.page_setup_ui(ctx, cx, area);
        }
        if self.preview.is_some() {
            self.preview_ui(ctx, cx, area);
        }
    }

    /// The printer choice: the print system's printers, the default preselected.
    fn printer_ui(&mut self, ui: &mut egui::Ui, settings: &mut Settings) {
        let lang = settings.lang;
        let chosen = self.chosen_printer(settings);
        let printers = self.printers.names.clone();
        let label = ui.label(Msg::Printer.text(lang));
        if printers.is_empty() {
            ui.label(Msg::NoPrinters.text(lang)).labelled_by(label.id);
            return;
        }
        egui::ComboBox::from_id_salt("printer")
            .selected_text(chosen.clone().unwrap_or_default())
            .show_ui(ui, |ui| {
                for name in printers {
                    let on = chosen.as_deref() == Some(name.as_str());
                    let shown = if self.printers.default.as_deref() == Some(&name) {
                        format!("{name} ({})", Msg::DefaultPrinter.text(lang))
                    } else {
                        name.clone()
                    };
                    if ui.selectable_label(on, shown).clicked() {
                        settings.page_setup.printer = Some(name);
                    }
                }
            })
            .response
            .labelled_by(label.id);
    }

    /// What the last Print could not do, in the window that covers the output.
    fn notice_ui(&self, ui: &mut egui::Ui) {
        if let Some(n) = &self.notice {
            ui.colored_label(theme::CAUTION, n);
        }
    }

    fn page_setup_ui(&mut self, ctx: &egui::Context, cx: &mut Context, area: Rect) {
        let lang = cx.settings.lang;
        let mut open = true;
        let mut preview = false;
        let range_error = cx.doc().and_then(|d| {
            let text = cx.settings.page_setup.networks.trim();
            (!text.is_empty())
                .then(|| ladder_print::networks(d.project(), text).err())
                .flatten()
                .map(|e| ladder_text::errors::networks_error(&e, lang))
        });
        egui::Window::new(Msg::PageSetup.text(lang))
            .constrain_to(area)
            .open(&mut open)
            .collapsible(false)
            .resizable(false)
            .show(ctx, |ui| {
                egui::Grid::new("page-setup").num_columns(2).show(ui, |ui| {
                    let s = &mut cx.settings.page_setup;
                    let l = ui.label(Msg::Paper.text(lang));
                    egui::ComboBox::from_id_salt("paper")
                        .selected_text(format!("{:?}", s.paper))
                        .show_ui(ui, |ui| {
                            for p in [Paper::A4, Paper::A3, Paper::Letter] {
                                ui.selectable_value(&mut s.paper, p, format!("{p:?}"));
                            }
                        })
                        .response
                        .labelled_by(l.id);
                    ui.end_row();
                    ui.label(Msg::Orientation.text(lang));
                    ui.horizontal(|ui| {
                        ui.radio_value(&mut s.landscape, false, Msg::Portrait.text(lang));
                        ui.radio_value(&mut s.landscape, true, Msg::Landscape.text(lang));
                    });
                    ui.end_row();
                    let l = ui.label(Msg::PrintNetworks.text(lang));
                    ui.add(
                        egui::TextEdit::singleline(&mut s.networks)
                            .hint_text("LEVEL2:10-40")
                            .desired_width(160.0),
                    )
                    .labelled_by(l.id);
                    ui.end_row();
                    self.printer_ui(ui, cx.settings);
                    ui.end_row();
                });
                if let Some(e) = &range_error {
                    ui.colored_label(theme::ERROR, e);
                }
                let s = &mut cx.settings.page_setup;
                ui.checkbox(&mut s.both_languages, Msg::BothLanguages.text(lang));
                ui.checkbox(&mut s.element_comments, Msg::ElementComments.text(lang));
                ui.checkbox(&mut s.tables, Msg::PrintTables.text(lang));
                ui.checkbox(&mut s.xref, Msg::PrintXref.text(lang));
                ui.checkbox(&mut s.selection_only, Msg::SelectionOnly.text(lang));
                self.notice_ui(ui);
                if ui.button(Msg::PrintPreview.text(lang)).clicked() {
                    preview = true;
                }
            });
        self.setup_open = open && !preview;
        if preview {
            self.open_preview(cx);
        }
    }

    fn preview_ui(&mut self, ctx: &egui::Context, cx: &mut Context, area: Rect) {
        let lang = cx.settings.lang;
        let mut open = true;
        let (mut print, mut export) = (false, false);
        egui::Window::new(Msg::PrintPreview.text(lang))
            .constrain_to(area)
            .default_pos(area.min + vec2(16.0, 16.0))
            .open(&mut open)
            .default_size(vec2(760.0, 780.0))
            .show(ctx, |ui| {
                ui.horizontal(|ui| {
                    let Some(preview) = self.preview.as_mut() else {
                        return;
                    };
                    preview_toolbar(ui, preview, lang);
                    ui.separator();
                    print = ui.button(Msg::Print.text(lang)).clicked();
                    export = ui.button(Msg::ExportDocument.text(lang)).clicked();
                    self.printer_ui(ui, cx.settings);
                });
                self.notice_ui(ui);
                ui.separator();
                let Some(preview) = self.preview.as_mut() else {
                    return;
                };
                egui::ScrollArea::both().show(ui, |ui| {
                    if preview.fit {
                        // The page's width and its margins fill the window.
                        let z = (ui.available_width() - 24.0) / preview.doc.width * 100.0;
                        preview.zoom = z.clamp(25.0, 400.0) as u16;
                    }
                    let scale = f32::from(preview.zoom) / 100.0;
                    let size = vec2(preview.doc.width, preview.doc.height) * scale;
                    let (rect, _) =
                        ui.allocate_exact_size(size + vec2(16.0, 16.0), egui::Sense::hover());
                    let painter = ui.painter_at(rect);
                    painter.rect_filled(rect, 0.0, theme::PRINT_DESK);
                    let page_rect = Rect::from_min_size(rect.min + vec2(8.0, 8.0), size);
                    if let Some(page) = preview.doc.pages.get(preview.page) {
                        paint_page(&painter, page_rect, &page.items, scale);
                    }
                });
            });
        if !open {
            self.preview = None;
        }
        if print {
            cx.pending.push(super::super::command::Command::Print);
        }
        if export {
            cx.pending
                .push(super::super::command::Command::ExportDocument);
        }
    }
}

/// The preview's page and zoom buttons.
fn preview_toolbar(ui: &mut egui::Ui, preview: &mut super::Preview, lang: UiLang) {
    let total = preview.doc.pages.len();
    if ui
        .add_enabled(preview.page > 0, egui::Button::new("◀"))
        .on_hover_text(Msg::PreviousPage.text(lang))
        .clicked()
    {
        preview.page -= 1;
    }
    let n = preview.page + 1;
    ui.label(match lang {
        UiLang::Zh => format!("第 {n}/{total} 页"),
        UiLang::En => format!("Page {n}/{total}"),
    });
    if ui
        .add_enabled(preview.page + 1 < total, egui::Button::new("▶"))
        .on_hover_text(Msg::NextPage.text(lang))
        .clicked()
    {
        preview.page += 1;
    }
    ui.separator();
    // A zoom step from fit width goes to the step beyond the fitted zoom.
    let down = ZOOMS.iter().rev().find(|z| **z < preview.zoom).copied();
    let up = ZOOMS.iter().find(|z| **z > preview.zoom).copied();
    if let Some(z) = down
        && ui.button("−").clicked()
    {
        preview.zoom = z;
        preview.fit = false;
    }
    ui.label(format!("{}%", preview.zoom));
    if let Some(z) = up
        && ui.button("+").clicked()
    {
        preview.zoom = z;
        preview.fit = false;
    }
    ui.toggle_value(&mut preview.fit, Msg::ZoomFit.text(lang));
}

/// Paints a page's items into `rect` at `scale` screen points per printed point.
pub fn paint_page(painter: &egui::Painter, rect: Rect, items: &[Item], scale: f32) {
    painter.rect_filled(rect, 0.0, theme::PAPER);
    let at = |x: f32, y: f32| rect.min + vec2(x, y) * scale;
    let ink = |k: Ink| match k {
        Ink::Black => theme::INK,
        Ink::Grey => theme::PRINT_GREY,
    };
    for item in items {
        match item {
            Item::Path {
                segs,
                width,
                ink: k,
            } => {
                let stroke = Stroke::new((width * scale).max(0.6), ink(*k));
                let mut last = Pos2::ZERO;
                for s in segs {
                    match *s {
                        Seg::Move(x, y) => last = at(x, y),
                        Seg::Line(x, y) => {
                            let p = at(x, y);
                            painter.line_segment([last, p], stroke);
                            last = p;
                        }
                        Seg::Cubic(a, b, c, d, x, y) => {
                            let p = at(x, y);
                            painter.add(egui::epaint::CubicBezierShape::from_points_stroke(
                                [last, at(a, b), at(c, d), p],
                                false,
                                egui::Color32::TRANSPARENT,
                                stroke,
                            ));
                            last = p;
                        }
                    }
                }
            }
            Item::Text {
                x,
                y,
                size,
                anchor,
                ink: k,
                text,
            } => {
                let align = match anchor {
                    Anchor::Left => Align2::LEFT_BOTTOM,
                    Anchor::Middle => Align2::CENTER_BOTTOM,
                    Anchor::Right => Align2::RIGHT_BOTTOM,
                };
                // The text's baseline is y; egui places the bottom of the line, a little
                // below the baseline.
                let pos = at(*x, *y) + vec2(0.0, size * scale * 0.22);
                painter.text(
                    pos,
                    align,
                    text,
                    FontId::proportional((size * scale).max(1.0)),
                    ink(*k),
                );
            }
        }
    }
}
