//! File → Page setup, Print preview, Print (Ctrl+P) and Export as PDF/SVG (docs/printing.md,
//! "In the editor"). The pages are the `ladder-print` layout the command line prints; the
//! preview paints the same items. The system's print queue sits behind a small trait, like
//! the file dialogs, so tests script it.

use super::LadderApp;
use super::dialogs::DialogKind;
use super::i18n::{Lang as UiLang, Msg};
use super::settings::DisplayMode;
use super::theme;
use egui::{Align2, FontId, Pos2, Rect, Stroke, vec2};
use ladder_print::{Anchor, Document, Ink, Item, Labels, Lang, Options, Paper, Seg};
use std::path::Path;
use std::sync::{Arc, Mutex};

/// Where a print job goes.
pub trait PrintQueue {
    /// Whether there is a queue to send to.
    fn available(&self) -> bool;
    /// Sends a PDF; the answer is the queue's own words (`request id is …`) or why it refused.
    fn submit(&mut self, pdf: &[u8], title: &str) -> Result<String, String>;
}

/// The system's queue: CUPS's `lp`, where it is on the PATH.
#[derive(Default)]
pub struct LpQueue;

fn on_path(program: &str) -> bool {
    std::env::var_os("PATH")
        .is_some_and(|paths| std::env::split_paths(&paths).any(|d| d.join(program).is_file()))
}

impl PrintQueue for LpQueue {
    fn available(&self) -> bool {
        on_path("lp")
    }

    fn submit(&mut self, pdf: &[u8], title: &str) -> Result<String, String> {
        let file =
            std::env::temp_dir().join(format!("ladder-studio-print-{}.pdf", std::process::id()));
        std::fs::write(&file, pdf).map_err(|e| format!("{}: {e}", file.display()))?;
        // lp copies the file into the spool before it answers, so it can go at once.
        let run = std::process::Command::new("lp")
            .arg("-t")
            .arg(title)
            .arg("--")
            .arg(&file)
            .output();
        let _ = std::fs::remove_file(&file);
        match run {
            Ok(o) if o.status.success() => {
                Ok(String::from_utf8_lossy(&o.stdout).trim().to_string())
            }
            Ok(o) => Err(String::from_utf8_lossy(&o.stderr).trim().to_string()),
            Err(e) => Err(format!("lp: {e}")),
        }
    }
}

/// A queue for tests: it keeps every PDF it is sent.
#[derive(Clone, Default)]
pub struct ScriptedQueue {
    /// The PDFs received, in order.
    pub jobs: Arc<Mutex<Vec<Vec<u8>>>>,
    /// Whether the system has a queue (else Print saves the PDF).
    pub present: bool,
}

impl PrintQueue for ScriptedQueue {
    fn available(&self) -> bool {
        self.present
    }

    fn submit(&mut self, pdf: &[u8], _title: &str) -> Result<String, String> {
        let mut jobs = self
            .jobs
            .lock()
            .map_err(|_| "the queue is gone".to_string())?;
        jobs.push(pdf.to_vec());
        Ok(format!("request id is scripted-{}", jobs.len()))
    }
}

/// The page setup as the user left it: UI state of the session, never in the project.
#[derive(Clone, Debug, PartialEq)]
pub struct PageSetup {
    /// Paper size.
    pub paper: Paper,
    /// Landscape pages.
    pub landscape: bool,
    /// Chinese and English (else the UI's language).
    pub both_languages: bool,
    /// The tables after the ladder.
    pub tables: bool,
    /// The cross-reference index.
    pub xref: bool,
    /// Element comments under contacts and coils.
    pub element_comments: bool,
    /// Only the selected networks (or the cursor's).
    pub selection_only: bool,
}

impl Default for PageSetup {
    fn default() -> Self {
        PageSetup {
            paper: Paper::A4,
            landscape: false,
            both_languages: false,
            tables: false,
            xref: false,
            element_comments: true,
            selection_only: false,
        }
    }
}

/// The print preview's pages and where the user is in them.
pub struct Preview {
    /// The laid-out document.
    pub doc: Document,
    /// The page shown (0 is the first).
    pub page: usize,
    /// Zoom, in percent of 72 dpi.
    pub zoom: u16,
}

/// Printing's state in the editor.
pub struct PrintState {
    /// The page setup.
    pub setup: PageSetup,
    /// Whether the page setup window is open.
    pub setup_open: bool,
    /// The open preview.
    pub preview: Option<Preview>,
    /// The print queue.
    pub queue: Box<dyn PrintQueue>,
}

impl Default for PrintState {
    fn default() -> Self {
        PrintState {
            setup: PageSetup::default(),
            setup_open: false,
            preview: None,
            queue: Box::new(LpQueue),
        }
    }
}

const ZOOMS: &[u16] = &[50, 75, 100, 125, 150, 200];

impl LadderApp {
    /// The document options from the page setup, the view and the selection.
    fn print_options(&self) -> Options {
        let s = &self.print.setup;
        let only = if s.selection_only {
            let networks: Vec<(usize, usize)> = match &self.edit.selection {
                Some((block, region)) => {
                    let count = self
                        .doc
                        .as_ref()
                        .and_then(|d| d.project().ladder.blocks.get(*block))
                        .map_or(0, |b| b.networks.len());
                    (0..count)
                        .filter(|n| {
                            use ladder_engine::model::region::Region;
                            match region {
                                Region::Networks { .. } => region.covers_network(*n),
                                Region::Cells { network, .. } | Region::Rows { network, .. } => {
                                    network == n
                                }
                            }
                        })
                        .map(|n| (*block, n))
                        .collect()
                }
                None => vec![(self.edit.cursor.block, self.edit.cursor.network)],
            };
            Some(networks)
        } else {
            None
        };
        Options {
            paper: s.paper,
            landscape: s.landscape,
            lang: match (s.both_languages, self.settings.lang) {
                (true, _) => Lang::Both,
                (false, UiLang::Zh) => Lang::Zh,
                (false, UiLang::En) => Lang::En,
            },
            labels: match self.settings.display {
                DisplayMode::Address => Labels::Address,
                DisplayMode::Symbol => Labels::Symbol,
                DisplayMode::Both => Labels::Both,
            },
            element_comments: s.element_comments,
            only,
            tables: s.tables,
            xref: s.xref,
            date: ladder_print::today(),
            ..Options::default()
        }
    }

    /// The project's name as printed.
    fn print_name(&self) -> String {
        self.doc
            .as_ref()
            .and_then(|d| d.path.as_ref().or(d.recovered_from.as_ref()))
            .and_then(|p| p.file_stem())
            .map_or_else(
                || "project".to_string(),
                |s| s.to_string_lossy().into_owned(),
            )
    }

    /// The document as the page setup says.
    pub fn print_document(&self) -> Option<Document> {
        let doc = self.doc.as_ref()?;
        Some(ladder_print::document(
            doc.project(),
            &self.print_name(),
            &self.print_options(),
        ))
    }

    /// File → Print preview: the pages, from the first.
    pub fn open_preview(&mut self) {
        if let Some(doc) = self.print_document() {
            let zoom = self.print.preview.as_ref().map_or(75, |p| p.zoom);
            self.print.preview = Some(Preview { doc, page: 0, zoom });
        }
    }

    /// File → Print (Ctrl+P): the PDF to the print queue, or, with none, to a file the user
    /// picks. The output window says which.
    pub fn print_now(&mut self) {
        let lang = self.settings.lang;
        let Some(doc) = self.print_document() else {
            return;
        };
        if !self.print.queue.available() {
            self.say(Msg::NoPrintQueue.text(lang).into(), false);
            self.start_dialog(DialogKind::ExportDocument);
            return;
        }
        let bytes = match ladder_print::pdf(&doc) {
            Ok(b) => b,
            Err(e) => return self.say(format!("{}: {e}", Msg::PrintFailed.text(lang)), true),
        };
        let name = doc.title.clone();
        match self.print.queue.submit(&bytes, &name) {
            Ok(reply) => self.say(
                format!(
                    "{} ({} {}) {reply}",
                    Msg::SentToPrinter.text(lang),
                    doc.pages.len(),
                    Msg::Pages.text(lang)
                ),
                false,
            ),
            Err(e) => self.say(format!("{}: {e}", Msg::PrintFailed.text(lang)), true),
        }
    }

    /// The answer of the Export as PDF/SVG dialog: `.svg` writes one file per page
    /// (`NAME-1.svg` …), anything else a PDF.
    pub fn export_document(&mut self, path: &Path) {
        let lang = self.settings.lang;
        let Some(doc) = self.print_document() else {
            return;
        };
        let svg = path
            .extension()
            .is_some_and(|e| e.eq_ignore_ascii_case("svg"));
        let written = if svg {
            let count = doc.pages.len();
            let mut result = Ok(ladder_print::svg_page_path(path, 0, count));
            for (i, page) in doc.pages.iter().enumerate() {
                let p = ladder_print::svg_page_path(path, i, count);
                if let Err(e) =
                    crate::atomic::write_atomic(&p, ladder_print::page_svg(&doc, page).as_bytes())
                {
                    result = Err(e);
                    break;
                }
            }
            result
        } else {
            match ladder_print::pdf(&doc) {
                Ok(bytes) => crate::atomic::write_atomic(path, &bytes).map(|()| path.to_path_buf()),
                Err(e) => return self.say(format!("{}: {e}", Msg::PrintFailed.text(lang)), true),
            }
        };
        match written {
            Ok(p) => self.say(
                format!(
                    "{} {} ({} {})",
                    Msg::Written.text(lang),
                    p.display(),
                    doc.pages.len(),
                    Msg::Pages.text(lang)
                ),
                false,
            ),
            Err(e) => self.say(format!("{}: {e}", path.display()), true),
        }
    }

    /// The page setup and preview windows, when open.
    pub fn print_ui(&mut self, ctx: &egui::Context) {
        let lang = self.settings.lang;
        if self.print.setup_open {
            let mut open = true;
            let mut preview = false;
            let s = &mut self.print.setup;
            egui::Window::new(Msg::PageSetup.text(lang))
                .open(&mut open)
                .collapsible(false)
                .resizable(false)
                .show(ctx, |ui| {
                    egui::Grid::new("page-setup").num_columns(2).show(ui, |ui| {
                        ui.label(Msg::Paper.text(lang));
                        egui::ComboBox::from_id_salt("paper")
                            .selected_text(format!("{:?}", s.paper))
                            .show_ui(ui, |ui| {
                                for p in [Paper::A4, Paper::A3, Paper::Letter] {
                                    ui.selectable_value(&mut s.paper, p, format!("{p:?}"));
                                }
                            });
                        ui.end_row();
                        ui.label(Msg::Orientation.text(lang));
                        ui.horizontal(|ui| {
                            ui.radio_value(&mut s.landscape, false, Msg::Portrait.text(lang));
                            ui.radio_value(&mut s.landscape, true, Msg::Landscape.text(lang));
                        });
                        ui.end_row();
                    });
                    ui.checkbox(&mut s.both_languages, Msg::BothLanguages.text(lang));
                    ui.checkbox(&mut s.element_comments, Msg::ElementComments.text(lang));
                    ui.checkbox(&mut s.tables, Msg::PrintTables.text(lang));
                    ui.checkbox(&mut s.xref, Msg::PrintXref.text(lang));
                    ui.checkbox(&mut s.selection_only, Msg::SelectionOnly.text(lang));
                    if ui.button(Msg::PrintPreview.text(lang)).clicked() {
                        preview = true;
                    }
                });
            self.print.setup_open = open && !preview;
            if preview {
                self.open_preview();
            }
        }
        let Some(preview) = self.print.preview.as_mut() else {
            return;
        };
        let mut open = true;
        let (mut print, mut export) = (false, false);
        let total = preview.doc.pages.len();
        egui::Window::new(Msg::PrintPreview.text(lang))
            .open(&mut open)
            .default_size(vec2(760.0, 780.0))
            .show(ctx, |ui| {
                ui.horizontal(|ui| {
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
                    let at = ZOOMS.iter().position(|z| *z == preview.zoom).unwrap_or(1);
                    if ui.add_enabled(at > 0, egui::Button::new("−")).clicked() {
                        preview.zoom = ZOOMS[at - 1];
                    }
                    ui.label(format!("{}%", preview.zoom));
                    if ui
                        .add_enabled(at + 1 < ZOOMS.len(), egui::Button::new("+"))
                        .clicked()
                    {
                        preview.zoom = ZOOMS[at + 1];
                    }
                    ui.separator();
                    print = ui.button(Msg::Print.text(lang)).clicked();
                    export = ui.button(Msg::ExportDocument.text(lang)).clicked();
                });
                ui.separator();
                egui::ScrollArea::both().show(ui, |ui| {
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
            self.print.preview = None;
        }
        if print {
            self.pending.push(super::command::Command::Print);
        }
        if export {
            self.pending.push(super::command::Command::ExportDocument);
        }
    }
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
