//! The desktop editor (eframe/egui). All UI code is in this library so tests drive it without
//! a window; `main.rs` only starts it.

pub mod command;
pub mod context;
pub mod coverage_view;
pub mod diagnostics;
pub mod dispatch;
pub mod document;
pub mod editor;
pub mod errors;
pub mod files;
pub mod fonts;
pub mod help;
pub mod history;
pub mod i18n;
pub mod ladder_view;
pub mod main_view;
pub mod menus;
pub mod online;
pub mod output;
pub mod place;
pub mod printing;
pub mod properties;
pub mod replace;
pub mod settings;
pub mod tables;
pub mod tabs;
#[cfg(test)]
mod test_harness;
pub mod theme;
pub mod tree;
pub mod xref_view;

use crate::gui::editor::EditState;
use crate::gui::files::FileState;
use crate::gui::online::OnlineState;
use crate::gui::printing::PrintState;
use crate::gui::properties::ElementProperties;
use crate::gui::replace::Replace;
pub use command::HelpPage;
use document::Document;
use i18n::Msg;
use ladder_engine::compiler::Severity;
use ladder_engine::coverage::Coverage;
use ladder_engine::model;
use settings::Settings;
use std::path::{Path, PathBuf};
use tree::View;

/// The application's name for eframe (window title, storage folder).
pub const APP_ID: &str = "Ladder Studio";

pub use output::OutputLine;

/// The editor's shell: the settings, the open document, the view, the cursor and selection,
/// the output, and one state per feature (each reached through [`LadderApp::with`]; see
/// ARCHITECTURE.md).
pub struct LadderApp {
    /// Persisted settings.
    settings: Settings,
    /// The open project.
    doc: Option<Document>,
    /// What the main area shows.
    view: View,
    /// The view tabs above the main area, in the order they were opened.
    tabs: Vec<View>,
    /// The output window.
    output: output::Output,
    /// Find and replace: its window, while open.
    replace: replace::Replace,
    /// The ladder cursor: the cell the editor's commands act on.
    cursor: model::CellRef,
    /// The ladder selection: its block and region, if any.
    selection: Option<(usize, editor::selection::Selection)>,
    /// The ladder editor: clipboard, gestures, the view's geometry.
    edit: editor::EditState,
    /// Files: dialogs, the question waited on, recovery copies.
    files: files::FileState,
    /// The open Help window.
    help: Option<HelpPage>,
    /// Element properties: the form, while open.
    properties: properties::ElementProperties,
    /// The table editors' UI state (selected row, text being typed, caches).
    tables: tables::TableState,
    /// The cross-reference views: the index filter and what was derived from the project.
    xref: xref_view::XrefState,
    /// View → Coverage: the coverage file shown over the ladder.
    coverage: coverage_view::CoverageView,
    /// Printing: the page setup, the preview, the print queue.
    print: printing::PrintState,
    /// The egui context, for starting dialogs outside a frame's closures.
    ctx: Option<egui::Context>,
    /// Commands asked for during this frame; they run after it.
    pending: Vec<command::Command>,
    /// When the project last changed, on the tables' draft clock (undo takes back the later
    /// of a change and a draft).
    last_change: u64,
    /// Online: the machine running behind the editor, and the online views' state.
    online: online::OnlineState,
    /// The window title last sent, so it is sent only when it changes.
    title: String,
}

/// A part of the editor with its own state in the app, reached through the one door
/// [`LadderApp::with`] with the narrow [`context::Context`] beside it: a new feature adds its
/// state, this line and its commands, nothing else.
pub trait Feature {
    /// The feature's state and the context over the rest of the editor, borrowed apart.
    fn split(app: &mut LadderApp) -> (&mut Self, context::Context<'_>);
    /// The feature's state, to read.
    fn of(app: &LadderApp) -> &Self;
}

/// The context over an app's parts other than its features.
macro_rules! context_of {
    ($a:expr) => {
        context::Context::new(
            &mut $a.doc,
            &mut $a.settings,
            &mut $a.output,
            &mut $a.pending,
            (&mut $a.cursor, &mut $a.selection),
            (&mut $a.view, &mut $a.tabs),
            $a.ctx.as_ref(),
        )
    };
}

macro_rules! features {
    ($($ty:ty => $field:ident),* $(,)?) => {$(
        impl Feature for $ty {
            fn split(app: &mut LadderApp) -> (&mut Self, context::Context<'_>) {
                (&mut app.$field, context_of!(app))
            }
            fn of(app: &LadderApp) -> &Self {
                &app.$field
            }
        }
    )*};
}

features! {
    printing::PrintState => print,
    tables::TableState => tables,
    xref_view::XrefState => xref,
    coverage_view::CoverageView => coverage,
    replace::Replace => replace,
    properties::ElementProperties => properties,
    online::OnlineState => online,
    editor::EditState => edit,
    files::FileState => files,
}

/// The window's title: the project's file name, `*` while it has unsaved changes, and
/// the program's name (as GSKLadder and most editors show it).
pub fn window_title(doc: Option<&Document>, lang: i18n::Lang) -> String {
    match doc {
        Some(doc) => {
            let name = doc
                .name()
                .unwrap_or_else(|| Msg::Untitled.text(lang).to_string());
            let mark = if doc.is_dirty() { "*" } else { "" };
            format!("{name}{mark} — Ladder Studio")
        }
        None => "Ladder Studio".to_string(),
    }
}

impl LadderApp {
    /// The one door of the features: runs `f` on feature `F` with the part of the editor it
    /// may use. A change it applied marks the tables' draft clock, so undo takes back the
    /// later of a change and a draft.
    pub fn with<F: Feature, R>(&mut self, f: impl FnOnce(&mut F, &mut context::Context) -> R) -> R {
        let (feature, mut cx) = F::split(self);
        let r = f(feature, &mut cx);
        let (changed, replaced) = (cx.changed(), cx.replaced());
        self.after_feature(changed, replaced);
        r
    }

    /// A feature's state, to read.
    pub fn feature<F: Feature>(&self) -> &F {
        F::of(self)
    }

    /// The open project's document, to read.
    pub fn doc(&self) -> Option<&Document> {
        self.doc.as_ref()
    }

    /// The settings.
    pub fn settings(&self) -> &Settings {
        &self.settings
    }

    /// The settings, to change (the View menu's switches, the language).
    pub fn settings_mut(&mut self) -> &mut Settings {
        &mut self.settings
    }

    /// What the main area shows.
    pub fn view(&self) -> View {
        self.view
    }

    /// The view tabs, in the order they were opened.
    pub fn tabs(&self) -> &[View] {
        &self.tabs
    }

    /// The output window's lines.
    pub fn output(&self) -> &output::Output {
        &self.output
    }

    /// The ladder cursor.
    pub fn cursor(&self) -> model::CellRef {
        self.cursor
    }

    /// The ladder selection: its block and region.
    pub fn selection(&self) -> Option<(usize, editor::selection::Selection)> {
        self.selection
    }

    /// The window title last sent.
    pub fn title(&self) -> &str {
        &self.title
    }

    /// Starts on `path`, else the last project, else the bundled sample (README, "The editor").
    pub fn new(settings: Settings, path: Option<&Path>) -> LadderApp {
        let mut app = LadderApp {
            settings,
            doc: None,
            view: View::Block(0),
            tabs: Vec::new(),
            output: Default::default(),
            replace: Default::default(),
            cursor: place::block_start(0),
            selection: None,
            edit: Default::default(),
            files: Default::default(),
            help: None,
            properties: Default::default(),
            tables: tables::TableState::default(),
            xref: Default::default(),
            print: Default::default(),
            coverage: Default::default(),
            ctx: None,
            pending: Vec::new(),
            last_change: 0,
            online: Default::default(),
            title: String::new(),
        };
        let start = path
            .map(Path::to_path_buf)
            .or_else(|| app.settings.recent.first().cloned());
        match start {
            Some(p) if app.with(|o: &mut FileState, cx| o.open(cx, &p)) => {}
            _ => app.doc = Some(Document::sample()),
        }
        app
    }

    /// The creator eframe calls: fonts, then settings from storage.
    pub fn from_creation(cc: &eframe::CreationContext<'_>, path: Option<PathBuf>) -> LadderApp {
        fonts::install(&cc.egui_ctx);
        // Ctrl+plus and Ctrl+minus zoom the ladder, as Ctrl+wheel does, not the whole UI.
        cc.egui_ctx.options_mut(|o| o.zoom_with_keyboard = false);
        let settings = cc
            .storage
            .and_then(|s| eframe::get_value(s, eframe::APP_KEY))
            .unwrap_or_default();
        let mut app = LadderApp::new(settings, path.as_deref());
        app.ctx = Some(cc.egui_ctx.clone());

        // Only a real run (with eframe's storage) autosaves into the user's data folder.
        if cc.storage.is_some() {
            app.files.recovery_dir = eframe::storage_dir(APP_ID).map(|d| d.join("recovery"));
            app.files.offer_restore();
        }
        app
    }

    /// Runs `f` with the part of the editor a feature without state of its own may use.
    pub fn with_context<R>(&mut self, f: impl FnOnce(&mut context::Context) -> R) -> R {
        let mut cx = context_of!(self);
        let r = f(&mut cx);
        let (changed, replaced) = (cx.changed(), cx.replaced());
        self.after_feature(changed, replaced);
        r
    }

    /// Shows a cell (of a diagnostic, a find result, a reference): its block, scrolled to its
    /// network, with the cursor on it. A place that no longer exists is clamped.
    pub fn jump(&mut self, at: model::CellRef) {
        // A table's, the machine model's or a scenario's diagnostic: its page, at its row.
        if let Some((view, row)) = place::table_view(at) {
            match view {
                Some(v) => {
                    if v == View::Scenarios {
                        self.tables.scenario = at.network;
                    }
                    self.show_view(v);
                    if let Some(r) = row {
                        self.pending.push(command::Command::GoToRow(r));
                    }
                }
                None => self.pending.push(command::Command::MachineModel),
            }
            return;
        }
        self.view = View::Block(at.block);
        self.edit.jump_to = Some(at.network);
        self.selection = None;
        self.cursor = at;
        self.clamp_ui_state();
    }

    /// Brings the UI state back inside the project after anything that may have shrunk it
    /// (undo, redo, a deleted subprogram, another project): the view, the cursor, the
    /// selection, the drag and the tabs never point past the end.
    pub fn clamp_ui_state(&mut self) {
        let Some(doc) = self.doc.as_ref() else {
            self.selection = None;
            self.edit.drag_from = None;
            return;
        };
        let p = doc.project();
        let blocks = &p.ladder.blocks;
        let tables = p.symbol_tables.len();
        let valid = |v: &View| match v {
            View::Block(b) => *b < blocks.len(),
            View::Symbols(t) => *t < tables,
            _ => true,
        };
        if !valid(&self.view) {
            self.view = View::Block(1);
            self.edit.drag_from = None;
        }
        self.tabs.retain(valid);
        let c = &mut self.cursor;
        if c.block >= blocks.len() {
            *c = model::CellRef {
                block: 1,
                network: 0,
                row: 0,
                col: 0,
            };
        }
        let networks = &blocks[c.block].networks;
        c.network = c.network.min(networks.len().saturating_sub(1));
        // A network's row count is a valid row: the new row offered below its last one.
        let rows = networks.get(c.network).map_or(0, |n| n.rows.len());
        c.row = c.row.min(rows);
        c.col = c.col.min(p.ladder.width);
        if let Some((b, sel)) = self.selection {
            let fits = |n: usize, r: usize| {
                blocks
                    .get(b)
                    .and_then(|bl| bl.networks.get(n))
                    .is_some_and(|net| r < net.rows.len())
            };
            let ok = match sel {
                editor::selection::Selection::Cells {
                    network,
                    rows,
                    cols,
                } => fits(network, rows.0.max(rows.1)) && cols.0.max(cols.1) <= p.ladder.width,
                editor::selection::Selection::Rows { network, rows } => {
                    fits(network, rows.0.max(rows.1))
                }
                editor::selection::Selection::Networks { networks } => {
                    fits(networks.0.max(networks.1), 0)
                }
            };
            if !ok {
                self.selection = None;
            }
        }
    }

    fn main_ui(&mut self, ui: &mut egui::Ui) {
        let lang = self.settings.lang;
        let Some(doc) = self.doc.as_ref() else {
            ui.label(Msg::NoProject.text(lang));
            return;
        };
        match self.view {
            View::Block(b) => {
                let cursor = (self.cursor.block == b).then_some((
                    self.cursor.network,
                    self.cursor.row,
                    self.cursor.col,
                ));
                let selection = self.selection.and_then(|(sb, s)| (sb == b).then_some(s));
                let Some(block) = doc.project().ladder.blocks.get(b) else {
                    return;
                };
                let label = block.kind.label();
                if self.edit.shown.insert((doc.serial(), b))
                    && self.edit.jump_to.is_none()
                    && let Some(path) = doc.path()
                {
                    self.edit.jump_to = self
                        .settings
                        .tops
                        .get(path)
                        .and_then(|t| t.get(&label))
                        .copied();
                    // The cursor comes back with the view (clamped if the block shrank).
                    if let Some(&[network, row, col]) =
                        self.settings.cursors.get(path).and_then(|c| c.get(&label))
                        && let Some(net) = block.networks.get(network)
                    {
                        self.cursor = model::CellRef {
                            block: b,
                            network,
                            row: row.min(net.rows.len().saturating_sub(1)),
                            col: col.min(doc.project().ladder.width),
                        };
                    }
                }
                if self.settings.fit_width {
                    let columns = doc.project().ladder.width;
                    self.settings.zoom = settings::fit_zoom(ui.available_width(), columns);
                }
                let errors: Vec<ladder_view::ErrorMark> = doc
                    .marks()
                    .into_iter()
                    .filter(|(c, _)| c.block == b)
                    .map(|(c, d)| ladder_view::ErrorMark {
                        network: c.network,
                        row: c.row,
                        col: c.col,
                        error: d.severity() == Severity::Error,
                    })
                    .collect();
                if let Some(s) = &self.online.session {
                    let running = &s.running;
                    let trace = &s.published.snapshot.trace;
                    self.coverage.refresh_live(s.published.seq, || {
                        (trace.len() == running.code.words().len())
                            .then(|| Coverage::from_trace(trace, &running.code, &running.program))
                    });
                } else if self.coverage.live {
                    // Offline: the machine and its measuring are gone.
                    self.coverage.live = false;
                    self.coverage.shown = false;
                }
                let cover = self.coverage.marks(doc.project(), b);
                self.coverage.legend_ui(ui, self.settings.lang);
                let seen = (self.cursor, doc.serial(), doc.generation());
                let follow = self.edit.followed != Some(seen);
                self.edit.followed = Some(seen);
                let opts = ladder_view::ViewOptions {
                    zoom: self.settings.zoom,
                    mode: self.settings.display,
                    comments: self.settings.show_comments,
                    titles: self.settings.show_titles,
                    cursor,
                    selection,
                    document: doc.serial(),
                    anchor: self.edit.next_anchor(),
                    follow,
                    element_comments: self
                        .settings
                        .show_element_comments
                        .then_some(self.settings.lang.code()),
                    errors: &errors,
                    coverage: &cover,
                };
                // The view's scroll target and geometry are the editor's; the online feature
                // draws with them while it holds the cursor.
                let mut jump_to = self.edit.jump_to.take();
                let mut geometry = std::mem::take(&mut self.edit.geometry);
                let events = self.with(|o: &mut OnlineState, cx| {
                    o.live_block_ui(cx, ui, b, &opts, &mut jump_to, &mut geometry)
                });
                self.edit.jump_to = jump_to;
                self.edit.geometry = geometry;
                if let Some((up, at)) = events.zoom {
                    self.with(|o: &mut EditState, cx| o.zoom_step(cx, up, Some(at)));
                }
                self.with(|o: &mut EditState, cx| o.remember_top(cx, &label, events.visible.start));
                self.with(|o: &mut EditState, cx| o.remember_cursor(cx, &label, b));
                self.pointer_events(b, events);
            }
            View::RefIndex | View::RefBits | View::RefBytes => {
                let lang = self.settings.lang;
                let event = xref_view::xref_ui(ui, doc, self.view, &mut self.xref, lang);
                if let Some(xref_view::XrefEvent::Jump(at)) = event {
                    self.jump(at);
                }
            }
            _ => self.tables_ui(ui),
        }
    }

    fn status_ui(&self, ui: &mut egui::Ui) {
        let lang = self.settings.lang;
        let t = |m: Msg| m.text(lang);
        let Some(doc) = &self.doc else { return };
        let name = doc.name().unwrap_or_else(|| t(Msg::Untitled).into());
        let steps = doc.compiled().map(|c| c.steps.total);
        ui.horizontal(|ui| {
            ui.label(name);
            if doc.is_dirty() {
                ui.label(t(Msg::Modified));
            }
            ui.separator();
            ui.label(if doc.is_read_only() {
                t(Msg::ModeReadOnly)
            } else {
                t(Msg::ModeEdit)
            });
            if let View::Block(b) = self.view
                && self.cursor.block == b
            {
                let c = self.cursor;
                let label = doc
                    .project()
                    .ladder
                    .blocks
                    .get(b)
                    .map_or(String::new(), |b| b.kind.label());
                ui.separator();
                ui.label(format!(
                    "{}: {label} {} {}  {} {}  {} {}",
                    t(Msg::Cursor),
                    t(Msg::Network),
                    c.network + 1,
                    t(Msg::Row),
                    c.row + 1,
                    t(Msg::Column),
                    c.col + 1
                ));
                if let Some((sb, sel)) = self.selection
                    && sb == b
                {
                    let what = match sel {
                        editor::selection::Selection::Cells { rows, cols, .. } => format!(
                            "{}×{}",
                            rows.0.abs_diff(rows.1) + 1,
                            cols.0.abs_diff(cols.1) + 1
                        ),
                        editor::selection::Selection::Rows { rows, .. } => {
                            format!("{} {}", rows.0.abs_diff(rows.1) + 1, t(Msg::Row))
                        }
                        editor::selection::Selection::Networks { networks } => format!(
                            "{} {}",
                            networks.0.abs_diff(networks.1) + 1,
                            t(Msg::Network)
                        ),
                    };
                    ui.label(format!("{} {what}", t(Msg::Selected)));
                }
            }
            if let Some(s) = steps {
                ui.separator();
                ui.label(format!("{}: {s}", t(Msg::Steps)));
            }
            diagnostics::status_ui(ui, doc, self.cursor, self.settings.lang);
            self.online.online_status_ui(doc, self.settings.lang, ui);
            ui.separator();
            ui.label(format!("{}%", self.settings.zoom));
        });
    }
}

impl eframe::App for LadderApp {
    fn ui(&mut self, ui: &mut egui::Ui, _frame: &mut eframe::Frame) {
        let ctx = ui.ctx().clone();
        self.ctx = Some(ctx.clone());
        self.clamp_ui_state();
        if let Some(doc) = self.doc.as_mut() {
            doc.recheck();
        }
        self.files.dialogs.show(&ctx, self.settings.lang);
        match self.with(|f: &mut FileState, cx| f.poll_dialogs(cx)) {
            Some((files::DialogKind::ExportTrace, path)) => {
                self.with(|o: &mut OnlineState, cx| o.export_trace(cx, &path))
            }
            Some((files::DialogKind::OpenCoverage, path)) => {
                self.with(|c: &mut coverage_view::CoverageView, cx| c.open(cx, &path))
            }
            Some((_, path)) => self.with_context(|cx| PrintState::export(cx, &path)),
            None => {}
        }
        self.with(|o: &mut FileState, cx| o.dropped_files(cx, &ctx));
        self.with(|o: &mut FileState, cx| o.close_requested(cx, &ctx));
        self.with(|o: &mut FileState, cx| o.autosave_tick(cx));
        self.with(|o: &mut OnlineState, cx| o.online_frame(cx));
        let title = window_title(self.doc.as_ref(), self.settings.lang);
        if title != self.title {
            ctx.send_viewport_cmd(egui::ViewportCommand::Title(title.clone()));
            self.title = title;
        }
        if self.files.question.is_some() {
            self.with(|o: &mut FileState, cx| o.question_ui(cx, &ctx));
        }
        egui::Panel::top("menu").show(ui, |ui| {
            let mut menus = menus::Menus::new(self);
            menus.menu_ui(ui);
            let mut asked = menus.asked;
            self.pending.append(&mut asked);
        });
        // Below the menu bar: the replace window never covers it. It reads its keys
        // (Enter, Escape) before the editor's.
        let area = ui.available_rect_before_wrap();
        self.with(|r: &mut Replace, cx| r.ui(&ctx, cx, area));
        self.keys(&ctx);
        if self.settings.show_toolbar {
            egui::Panel::top("toolbar").show(ui, |ui| self.toolbar_ui(ui));
        }
        if self.edit.prompt.is_some()
            && self
                .with(|o: &mut EditState, cx| o.prompt_place(cx))
                .is_none()
        {
            egui::Panel::top("prompt").show(ui, |ui| {
                self.with(|o: &mut EditState, cx| o.prompt_ui(cx, ui))
            });
        }
        if self.settings.show_status {
            egui::Panel::bottom("status").show(ui, |ui| self.status_ui(ui));
        }
        if self.online.is_online() {
            egui::Panel::bottom("timeline").show(ui, |ui| {
                self.with(|o: &mut OnlineState, cx| o.timeline_ui(cx, ui))
            });
        }
        if self.settings.show_output {
            // Resizable by its top edge; the height is kept in the settings for next time.
            let shown = egui::Panel::bottom("output")
                .resizable(true)
                .default_size(self.settings.output_height)
                .min_size(60.0)
                .show(ui, |ui| {
                    if let Some(at) = self.output.ui(ui, self.settings.lang) {
                        self.jump(at);
                    }
                });
            let height = shown.response.rect.height();
            if (height - self.settings.output_height).abs() >= 1.0 {
                self.settings.output_height = height;
            }
        }
        if self.settings.show_tree {
            let mut asked = None;
            egui::Panel::left("tree")
                .resizable(true)
                .default_size(220.0)
                .min_size(160.0)
                .show(ui, |ui| {
                    let lang = self.settings.lang;
                    ui.heading(Msg::Project.text(lang));
                    if let Some(doc) = &self.doc {
                        egui::ScrollArea::vertical().show(ui, |ui| {
                            asked = tree::tree_ui(ui, doc.project(), lang, self.view)
                        });
                    }
                });
            if let Some(c) = asked {
                self.ask(c);
            }
        }
        // The online panel takes its room only while online: offline the tables and the
        // ladder keep the whole width.
        // The Machine page is also where the machine model is edited offline.
        let online_shown = self.settings.show_online
            && (self.online.is_online() || self.online.tab == online::OnlineTab::Machine);
        if online_shown && self.settings.online_window {
            self.with(|o: &mut OnlineState, cx| o.online_viewport(cx, &ctx));
        } else if online_shown {
            // At most half the window: the ladder stays the main view; a wide page scrolls.
            let max = (ui.available_width() * 0.5).max(260.0);
            egui::Panel::right("online")
                .resizable(true)
                .default_size(600.0_f32.min(max))
                .min_size(240.0)
                .max_size(max)
                .show(ui, |ui| {
                    self.with(|o: &mut OnlineState, cx| o.online_panel_ui(cx, ui))
                });
        }
        egui::CentralPanel::default().show(ui, |ui| {
            let project = self.doc.as_ref().map(|d| d.project());
            let lang = self.settings.lang;
            if let Some(c) = tabs::tabs_ui(ui, &mut self.view, &mut self.tabs, project, lang) {
                self.ask(c);
            }
            self.main_ui(ui)
        });
        self.with(|o: &mut EditState, cx| o.prompt_window(cx, &ctx));
        if self.properties.form.is_some() {
            // The form sits under its element as drawn; the geometry is read while the
            // feature holds the cursor, hence the copy (only while the form is open).
            let geometry = self.edit.geometry.clone();
            self.with(|p: &mut ElementProperties, cx| p.ui(&ctx, cx, &geometry));
        }
        if self.edit.function_dialog.is_some() {
            self.with(|o: &mut EditState, cx| o.function_dialog_ui(cx, &ctx));
        }
        help::ui(&mut self.help, &ctx, self.settings.lang);
        self.with(|p: &mut PrintState, cx| p.ui(&ctx, cx, area));
        self.with(|o: &mut OnlineState, cx| o.value_window_ui(cx, &ctx));
        self.with(|o: &mut OnlineState, cx| o.publish_shown(cx));
        self.run_pending();
        // The first force waits for the user's yes: the question is the editor's one modal.
        if std::mem::take(&mut self.online.ask_first_force) {
            self.files.question = Some(files::Question::FirstForce);
            ctx.request_repaint();
        }
    }

    fn save(&mut self, storage: &mut dyn eframe::Storage) {
        eframe::set_value(storage, eframe::APP_KEY, &self.settings);
    }

    fn on_exit(&mut self) {
        // The machine thread ends with the window.
        self.with(|o: &mut OnlineState, cx| o.go_offline(cx));
    }
}

/// How the editor starts (the command line's options).
#[derive(Clone, Debug, Default)]
pub struct Start {
    /// The project to open.
    pub project: Option<PathBuf>,
    /// Go online and run at once.
    pub run: bool,
    /// An NC program to load and start from the operator panel.
    pub nc: Option<String>,
    /// The UI language asked for on the command line (else the saved setting).
    pub lang: Option<i18n::Lang>,
}

/// Opens the editor window (blocks until it closes).
pub fn run(start: Start) -> anyhow::Result<()> {
    let options = eframe::NativeOptions {
        viewport: egui::ViewportBuilder::default()
            .with_title("Ladder Studio")
            .with_inner_size([1280.0, 800.0]),
        ..Default::default()
    };
    eframe::run_native(
        APP_ID,
        options,
        Box::new(move |cc| {
            let mut app = LadderApp::from_creation(cc, start.project.clone());
            if let Some(lang) = start.lang {
                app.settings.lang = lang;
            }
            if start.run {
                app.with(|o: &mut OnlineState, cx| o.start_running(cx, start.nc.clone()));
            }
            Ok(Box::new(app))
        }),
    )
    .map_err(|e| anyhow::anyhow!("cannot open the window: {e}"))
}
