//! File → Page setup, Print preview, Print (Ctrl+P) and Export as PDF/SVG (docs/printing.md,
//! "In the editor"). The pages are the `ladder-print` layout the command line prints; the
//! preview paints the same items. The system's print queue sits behind a small trait, like
//! the file dialogs, so tests script it.

mod preview;
mod queue;

pub use preview::paint_page;
pub use queue::{LpQueue, PrintQueue, Printers, ScriptedQueue, parse_lpstat};

use super::command::Command;
use super::context::Context;
use super::i18n::{Lang, Msg};
pub use super::settings::PageSetup;
use super::settings::{DisplayMode, Settings};
use ladder_print::{Document, Labels, Options, PrintLang};
use std::path::Path;

/// The print preview's pages and where the user is in them.
pub struct Preview {
    /// The laid-out document.
    pub doc: Document,
    /// The page shown (0 is the first).
    pub page: usize,
    /// Zoom, in percent of 72 dpi.
    pub zoom: u16,
    /// The page fills the window's width (the zoom follows it); a zoom step leaves it.
    pub fit: bool,
}

/// Printing's state in the editor.
pub struct PrintState {
    /// Whether the page setup window is open.
    pub setup_open: bool,
    /// The open preview.
    pub preview: Option<Preview>,
    /// The print queue.
    pub queue: Box<dyn PrintQueue>,
    /// The printers the queue offered when the page setup or the preview opened.
    pub printers: Printers,
    /// What the last Print said when it could not print (no queue, a refusal): shown in
    /// the page setup and the preview too, which cover the output window.
    pub notice: Option<String>,
}

impl Default for PrintState {
    fn default() -> Self {
        PrintState {
            setup_open: false,
            preview: None,
            queue: Box::new(LpQueue),
            printers: Printers::default(),
            notice: None,
        }
    }
}

pub(super) const ZOOMS: &[u16] = &[50, 75, 100, 125, 150, 200];

impl PrintState {
    /// The document options from the page setup, the view and the selection.
    fn options(cx: &Context) -> Options {
        let s = &cx.settings.page_setup;
        let only = if s.selection_only {
            let networks: Vec<(usize, usize)> = match &*cx.selection {
                Some((block, region)) => {
                    let count = cx
                        .doc()
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
                None => vec![(cx.cursor.block, cx.cursor.network)],
            };
            Some(networks)
        } else {
            // A range that does not read is shown in the page setup and prints everything.
            cx.doc()
                .filter(|_| !s.networks.trim().is_empty())
                .and_then(|d| ladder_print::networks(d.project(), s.networks.trim()).ok())
        };
        Options {
            paper: s.paper,
            landscape: s.landscape,
            lang: match (s.both_languages, cx.settings.lang) {
                (true, _) => PrintLang::Both,
                (false, Lang::Zh) => PrintLang::Zh,
                (false, Lang::En) => PrintLang::En,
            },
            labels: match cx.settings.display {
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
    fn name(cx: &Context) -> String {
        cx.doc()
            .and_then(|d| d.path().or(d.recovered_from()))
            .and_then(|p| p.file_stem())
            .map_or_else(
                || "project".to_string(),
                |s| s.to_string_lossy().into_owned(),
            )
    }

    /// The document as the page setup says.
    pub fn document(cx: &Context) -> Option<Document> {
        let doc = cx.doc()?;
        Some(ladder_print::document(
            doc.project(),
            &PrintState::name(cx),
            &PrintState::options(cx),
        ))
    }

    /// File → Print preview: the pages, from the first.
    pub fn open_preview(&mut self, cx: &Context) {
        if let Some(doc) = PrintState::document(cx) {
            let zoom = self.preview.as_ref().map_or(100, |p| p.zoom);
            self.preview = Some(Preview {
                doc,
                page: 0,
                zoom,
                fit: true,
            });
            self.refresh_printers();
        }
    }

    /// File → Print (Ctrl+P): the PDF to the print queue, or, with none, to a file the user
    /// picks. The output window says which.
    pub fn print_now(&mut self, cx: &mut Context) {
        let lang = cx.settings.lang;
        let Some(doc) = PrintState::document(cx) else {
            return;
        };
        if !self.queue.available() {
            let text = Msg::NoPrintQueue.text(lang).to_string();
            self.notice = Some(text.clone());
            cx.output.say(text, false);
            cx.pending.push(Command::ExportDocument);
            return;
        }
        let printer = self.chosen_printer(cx.settings);
        let bytes = match ladder_print::pdf(&doc) {
            Ok(b) => b,
            Err(e) => {
                return cx
                    .output
                    .say(format!("{}: {e}", Msg::PrintFailed.text(lang)), true);
            }
        };
        let name = doc.title.clone();
        match self.queue.submit(&bytes, &name, printer.as_deref()) {
            Ok(reply) => cx.output.say(
                format!(
                    "{} ({} {}) {reply}",
                    Msg::SentToPrinter.text(lang),
                    doc.pages.len(),
                    Msg::Pages.text(lang)
                ),
                false,
            ),
            Err(e) => {
                let text = format!("{}: {e}", Msg::PrintFailed.text(lang));
                self.notice = Some(text.clone());
                cx.output.say(text, true)
            }
        }
    }

    /// The printer a print goes to: the one chosen in the page setup while the queue still
    /// offers it, else the system's default.
    pub fn chosen_printer(&self, settings: &Settings) -> Option<String> {
        let p = &self.printers;
        settings
            .page_setup
            .printer
            .clone()
            .filter(|name| p.names.contains(name))
            .or_else(|| p.default.clone())
    }

    /// Asks the queue for its printers (when the page setup or the preview opens).
    pub fn refresh_printers(&mut self) {
        self.printers = self.queue.printers();
        self.notice = None;
    }

    /// The answer of the Export as PDF/SVG dialog: `.svg` writes one file per page
    /// (`NAME-1.svg` …), anything else a PDF.
    pub fn export(cx: &mut Context, path: &Path) {
        let lang = cx.settings.lang;
        let Some(doc) = PrintState::document(cx) else {
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
                if let Err(e) = ladder_engine::file::write_atomic(
                    &p,
                    ladder_print::page_svg(&doc, page).as_bytes(),
                ) {
                    result = Err(e);
                    break;
                }
            }
            result
        } else {
            match ladder_print::pdf(&doc) {
                Ok(bytes) => {
                    ladder_engine::file::write_atomic(path, &bytes).map(|()| path.to_path_buf())
                }
                Err(e) => {
                    return cx
                        .output
                        .say(format!("{}: {e}", Msg::PrintFailed.text(lang)), true);
                }
            }
        };
        match written {
            Ok(p) => cx.output.say(
                format!(
                    "{} {} ({} {})",
                    Msg::Written.text(lang),
                    p.display(),
                    doc.pages.len(),
                    Msg::Pages.text(lang)
                ),
                false,
            ),
            Err(e) => cx.output.say(format!("{}: {e}", path.display()), true),
        }
    }
}
