//! Where commands meet the application: whether a command can run now, the keys that ask
//! for one, and the one place that runs it. Menus, toolbars and right-click menus only queue
//! commands during the frame ([`LadderApp::ask`]); [`LadderApp::run_pending`] runs them after
//! it, so a command never acts on half-drawn state.

use super::LadderApp;
use super::command::Command;
use super::diagnostics;
use super::files::{CloseAction, DialogKind};
use super::place::{BlockKey, View};
use crate::gui::editor::EditState;
use crate::gui::editor::editing::PlaceKind;
use crate::gui::files::FileState;
use crate::gui::online::OnlineState;
use crate::gui::printing::PrintState;
use crate::gui::properties::ElementProperties;

impl LadderApp {
    /// Queues a command; it runs after the frame.
    pub fn ask(&mut self, c: Command) {
        self.pending.push(c);
    }

    /// Runs the commands queued during the frame, in order.
    pub fn run_pending(&mut self) {
        self.with(|o: &mut OnlineState, cx| o.lock_while_replaying(cx));
        let pending = std::mem::take(&mut self.pending);
        if !pending.is_empty()
            && let Some(ctx) = &self.ctx
        {
            // The frame was drawn before the commands ran: draw what they changed.
            ctx.request_repaint();
        }
        for c in pending {
            if self.enabled(c) {
                // One command, one undo step, however many edits it makes.
                self.with_context(|cx| cx.begin_group());
                self.execute(c);
                self.with_context(|cx| cx.end_group());
            }
        }
        // What the commands asked for in turn (a feature's jump to a cell) runs now too,
        // not a frame later; a command that keeps asking again waits for the next frame.
        let follow = std::mem::take(&mut self.pending);
        for c in follow {
            if self.enabled(c) {
                self.with_context(|cx| cx.begin_group());
                self.execute(c);
                self.with_context(|cx| cx.end_group());
            }
        }
    }

    /// Whether a command can run now (menus grey out the others, keys pass them by).
    pub fn enabled(&self, c: Command) -> bool {
        let doc = self.doc.as_ref();
        let in_ladder = matches!(self.view, View::Block(_)) && doc.is_some();
        match c {
            // A replayed past is read-only: one rule for the project and the machine.
            Command::Undo => {
                doc.is_some_and(|d| d.history().undo_len() > 0) && !self.online.scrubbing()
            }
            Command::Redo => {
                doc.is_some_and(|d| d.history().redo_len() > 0) && !self.online.scrubbing()
            }
            Command::Paste => in_ladder && self.edit.clipboard.is_some(),
            Command::New | Command::Open | Command::Exit | Command::OpenRecent(_) => true,
            Command::Language(_) | Command::Display(_) | Command::Help(_) => true,
            Command::ZoomIn
            | Command::ZoomOut
            | Command::ZoomFit
            | Command::ClearSelection
            | Command::Pen => true,
            Command::ToggleComments
            | Command::ToggleElementComments
            | Command::ToggleTitles
            | Command::ToggleTree
            | Command::ToggleOutput
            | Command::ToggleToolbar
            | Command::ToggleStatus => true,
            Command::Run => {
                doc.is_some() && !self.online.session.as_ref().is_some_and(|s| s.is_running())
            }
            Command::Stop => self.online.session.as_ref().is_some_and(|s| s.is_running()),
            Command::StepTick | Command::StepN => {
                doc.is_some() && !self.online.session.as_ref().is_some_and(|s| s.is_running())
            }
            Command::PowerCycle | Command::GoOffline | Command::UnforceAll => {
                self.online.is_online()
            }
            Command::ToggleBit | Command::ForceBit | Command::Unforce => {
                self.online.is_online() && in_ladder && !self.online.scrubbing()
            }
            Command::Why => self.online.is_online() && in_ladder,
            Command::LiveView => self.online.scrubbing(),
            Command::Speed(_) | Command::ToggleOnline | Command::DetachOnline => true,
            Command::ScanEngine(e) => {
                e == ladder_engine::vm::Engine::Interpreter || ladder_engine::vm::native::AVAILABLE
            }
            Command::MachineModel => doc.is_some(),
            Command::Scenario(i) => {
                self.online.is_online()
                    && !self.online.scrubbing()
                    && doc.is_some_and(|d| i < d.project().scenarios.len())
            }
            c if c.navigates() => in_ladder,
            // A recorded past is read-only: no edits while the view shows one.
            c if c.edits_ladder() => in_ladder && !self.online.scrubbing(),
            _ => doc.is_some(),
        }
    }

    /// For the switches among the commands: whether they are on now.
    pub fn checked(&self, c: Command) -> Option<bool> {
        let s = &self.settings;
        Some(match c {
            Command::Pen => self.edit.pen,
            Command::ZoomFit => s.fit_width,
            Command::ToggleComments => s.show_comments,
            Command::ToggleElementComments => s.show_element_comments,
            Command::ToggleCoverage => self.coverage.shown,
            Command::ToggleTitles => s.show_titles,
            Command::ToggleTree => s.show_tree,
            Command::ToggleOutput => s.show_output,
            Command::ToggleToolbar => s.show_toolbar,
            Command::ToggleStatus => s.show_status,
            Command::ToggleOnline => s.show_online,
            Command::DetachOnline => s.online_window,
            Command::Speed(sp) => self.online.speed == sp,
            Command::ScanEngine(e) => self.online.engine_in_force() == e,
            Command::Display(m) => s.display == m,
            Command::Language(l) => s.lang == l,
            Command::Scenario(i) => self.doc.as_ref().is_some_and(|d| {
                d.project()
                    .scenarios
                    .get(i)
                    .is_some_and(|sc| self.online.is_applied(&sc.name))
            }),
            _ => return None,
        })
    }

    /// The keys of this frame, turned into commands. While a text field, a prompt or a dialog
    /// has the keyboard only the global keys act (F9), so typing never edits the ladder.
    pub fn keys(&mut self, ctx: &egui::Context) {
        let typing = self.edit.prompt.is_some()
            || self.edit.function_dialog.is_some()
            || self.files.question.is_some()
            || ctx.egui_wants_keyboard_input();
        // Whether each command is enabled is decided when it runs (after the frame, in
        // order): a press that an earlier press of the same frame enables still counts.
        let keyed: Vec<(Command, egui::KeyboardShortcut)> = Command::keyed()
            .iter()
            .filter(|&&c| !typing || c.global())
            .filter_map(|&c| c.shortcut().map(|s| (c, s)))
            .collect();
        // Every key press of the frame, in order, becomes its command (Down Down moves twice;
        // two quick force keys force twice): a frame can hold more than one press.
        let found = ctx.input_mut(|i| {
            let mut found = Vec::new();
            i.events.retain(|e| {
                let egui::Event::Key {
                    key,
                    pressed: true,
                    modifiers,
                    ..
                } = e
                else {
                    return true;
                };
                let hit = keyed.iter().find(|(_, s)| {
                    s.logical_key == *key && modifiers.matches_logically(s.modifiers)
                });
                match hit {
                    Some((c, _)) => {
                        found.push(*c);
                        false
                    }
                    None => true,
                }
            });
            found
        });
        for c in found {
            self.ask(c);
        }
        if typing {
            return;
        }
        // The system's own cut, copy and paste (what Ctrl+X/C/V become on some platforms).
        let event = ctx.input(|i| {
            i.events.iter().find_map(|e| match e {
                egui::Event::Cut => Some(Command::Cut),
                egui::Event::Copy => Some(Command::Copy),
                egui::Event::Paste(_) => Some(Command::Paste),
                _ => None,
            })
        });
        if let Some(c) = event.filter(|c| self.enabled(*c)) {
            self.ask(c);
        }
    }

    /// Runs a command now. Only [`LadderApp::run_pending`] calls this.
    fn execute(&mut self, c: Command) {
        match c {
            Command::New => self.with(|o: &mut FileState, cx| o.request(cx, CloseAction::New)),
            Command::Open => {
                self.with(|o: &mut FileState, cx| o.request(cx, CloseAction::OpenDialog))
            }
            Command::OpenRecent(i) => {
                if let Some(p) = self.settings.recent.get(i).cloned() {
                    self.with(|o: &mut FileState, cx| o.request(cx, CloseAction::Open(p)));
                }
            }
            Command::Save => self.with(|o: &mut FileState, cx| o.save(cx)),
            Command::SaveAs => {
                self.with(|o: &mut FileState, cx| o.start_dialog(cx, DialogKind::SaveProjectAs))
            }
            Command::Close => self.with(|o: &mut FileState, cx| o.request(cx, CloseAction::Close)),
            Command::ExportIl => {
                self.with(|o: &mut FileState, cx| o.start_dialog(cx, DialogKind::ExportIl))
            }
            Command::ExportComments => {
                self.with(|o: &mut FileState, cx| o.start_dialog(cx, DialogKind::ExportComments))
            }
            Command::ImportComments => {
                self.with(|o: &mut FileState, cx| o.start_dialog(cx, DialogKind::ImportComments))
            }
            Command::PageSetup => {
                self.print.setup_open = true;
                self.print.refresh_printers();
            }
            Command::PrintPreview => self.with(|p: &mut PrintState, cx| p.open_preview(cx)),
            Command::Print => self.with(|p: &mut PrintState, cx| p.print_now(cx)),
            Command::ExportDocument => {
                self.with(|o: &mut FileState, cx| o.start_dialog(cx, DialogKind::ExportDocument))
            }
            Command::Exit => self.with(|o: &mut FileState, cx| o.request(cx, CloseAction::Exit)),
            Command::Undo => self.undo(),
            Command::Redo => self.redo(),
            Command::Find => self
                .edit
                .open_prompt(PlaceKind::Find, self.edit.last_find.clone()),
            Command::Replace => {
                let last = self.edit.last_find.clone();
                self.replace.open(&last);
            }
            Command::GoTo => {
                // In a table view Ctrl+G goes to a row of the table.
                let rows = self.tables.sheet_of(self.view).and_then(|sheet| {
                    let doc = self.doc.as_ref()?;
                    Some(self.tables.rows_in(sheet, doc.project()))
                });
                let kind = rows.map_or(PlaceKind::GoTo, PlaceKind::GoToRow);
                self.edit.open_prompt(kind, String::new());
            }
            Command::GoToRow(row) => {
                if let (Some(sheet), Some(doc)) = (self.tables.sheet_of(self.view), &self.doc) {
                    self.tables.go_to_row(sheet, row, doc.project());
                }
            }
            Command::ClearSelection => {
                // Escape abandons what was typed in a table and not taken.
                self.selection = None;
                self.tables.forget_drafts();
            }
            Command::ToggleComments => self.settings.show_comments ^= true,
            Command::ToggleElementComments => self.settings.show_element_comments ^= true,
            Command::ToggleCoverage if self.online.is_online() => {
                // Online: measured on the running machine, from now on.
                let on = !self.coverage.live;
                if let Some(s) = self.online.session.as_mut() {
                    s.send(ladder_engine::runner::Request::Coverage(on));
                }
                self.with(|v: &mut super::coverage_view::CoverageView, cx| v.set_live(cx, on));
            }
            Command::ToggleCoverage if self.coverage.report.is_some() => {
                self.coverage.shown ^= true;
            }
            Command::ToggleCoverage | Command::LoadCoverage => {
                // The switch reads the project's own coverage file when there is one.
                let beside = (c == Command::ToggleCoverage)
                    .then(|| self.doc.as_ref().and_then(|d| d.path()))
                    .flatten()
                    .map(super::coverage_view::beside)
                    .filter(|p| p.is_file());
                match beside {
                    Some(p) => {
                        self.with(|v: &mut super::coverage_view::CoverageView, cx| v.open(cx, &p))
                    }
                    None => self
                        .with(|f: &mut FileState, cx| f.start_dialog(cx, DialogKind::OpenCoverage)),
                }
            }
            Command::ToggleTitles => self.settings.show_titles ^= true,
            Command::ToggleTree => self.settings.show_tree ^= true,
            Command::ToggleOutput => self.settings.show_output ^= true,
            Command::ToggleToolbar => self.settings.show_toolbar ^= true,
            Command::ToggleStatus => self.settings.show_status ^= true,
            Command::ZoomFit => self.settings.fit_width = !self.settings.fit_width,
            Command::Compile => self.with_context(diagnostics::compile),
            Command::NextError => self.with_context(|cx| diagnostics::step_error(cx, true)),
            Command::Properties => self.with(|p: &mut ElementProperties, cx| p.open(cx, None)),
            Command::PreviousError => self.with_context(|cx| diagnostics::step_error(cx, false)),
            Command::ToggleOnline => self.settings.show_online = !self.settings.show_online,
            Command::DetachOnline => {
                self.settings.online_window = !self.settings.online_window;
                self.settings.show_online = true;
            }
            Command::MachineModel => {
                self.settings.show_online = true;
                self.online.tab = super::online::OnlineTab::Machine;
            }
            Command::ScenariosPage => self.show_view(View::Scenarios),
            Command::Scenario(i) => self.with(|o: &mut OnlineState, cx| o.toggle_scenario(cx, i)),
            Command::Run
            | Command::Stop
            | Command::StepTick
            | Command::StepN
            | Command::PowerCycle
            | Command::GoOffline
            | Command::ToggleBit
            | Command::ForceBit
            | Command::Unforce
            | Command::UnforceAll
            | Command::Why
            | Command::LiveView
            | Command::Speed(_)
            | Command::ScanEngine(_) => {
                self.with(|o: &mut OnlineState, cx| o.execute_online(cx, c))
            }
            Command::ConfirmForces(yes) => {
                self.with(|o: &mut OnlineState, cx| o.confirm_forces(cx, yes))
            }
            Command::Language(l) => self.settings.lang = l,
            Command::Display(m) => self.settings.display = m,
            Command::ShowView(v) => self.show_view(v),
            Command::ShowCell(at) => self.jump(at),
            Command::ExportTraceCsv => {
                self.with(|o: &mut FileState, cx| o.start_dialog(cx, DialogKind::ExportTrace))
            }
            Command::Help(p) => self.help = Some(p),
            // The ladder editor's own commands.
            c => self.with(|e: &mut EditState, cx| e.execute(cx, c)),
        }
    }

    /// Shows a view (a click in the tree or on a tab, a Tools menu entry).
    /// A block shown again gets its cursor back where it was left (its first cell the first
    /// time), so the status bar and Ctrl+G speak of the block on screen.
    pub fn show_view(&mut self, v: View) {
        if let View::Block(b) = v
            && b != self.cursor.block
            && let Some(ladder) = self.doc.as_ref().map(|d| &d.project().ladder)
        {
            let key = |i: usize| ladder.blocks.get(i).map(|bl| BlockKey::of(&bl.kind));
            let (from, to) = (key(self.cursor.block), key(b));
            if let Some(from) = from {
                self.edit.block_cursors.insert(from, self.cursor);
            }
            let back = to.and_then(|k| self.edit.block_cursors.get(&k)).copied();
            self.cursor = match back {
                Some(c) => super::place::Cursor { block: b, ..c },
                None => super::place::block_start(b),
            };
            self.clamp_ui_state();
        }
        self.view = v;
    }
}

/// The Help page listing the keys, for tests and the Help window.
pub fn shortcut_rows() -> Vec<(String, super::i18n::Msg)> {
    Command::keyed()
        .iter()
        .filter_map(|c| Some((c.shortcut_text()?, c.text())))
        .collect()
}
