//! The table editors (manual §3.4): symbol tables, data-setting tables, display messages,
//! diagnosis, permissions, M-code comments and version information.
//!
//! The rules (what a cell takes, the row menu, the password) are the engine's
//! ([`ladder_engine::model::sheets`]); this is the view. [`tables_ui`] draws the table of a
//! view from the document it is given and returns the edits the user made, each replacing a
//! whole table, once per user action (a text field commits on Enter or when it loses focus),
//! so Ctrl+Z puts the table back exactly. What the user is typing, and why it was refused,
//! stays in [`TableState`] until it is valid: the project never holds an invalid cell because
//! of this editor.
//!
//! The row tables are drawn with `egui_extras::TableBuilder::rows`, which lays out only the
//! visible rows, so the 400-row message table and symbol tables of thousands of rows cost a
//! screenful per frame.

mod error_text;
mod k_page;
pub mod scenarios;
mod sheet;
#[cfg(test)]
mod tests;
mod version;

pub use error_text::{address_error, table_error};
pub use ladder_engine::model::sheets::{Col, RowOp, Sheet};

use super::LadderApp;
use super::document::Document;
use super::i18n::{Lang, Msg};
use super::tree::View;
use crate::gui::online::OnlineState;
use ladder_engine::model::sheets::{TableError, changed_row};
use ladder_engine::model::{Project, TableEdit};
use std::collections::HashMap;

use super::theme::{ERROR as ERROR_RED, OK as OK_GREEN};

/// The tab of the data-setting view (§3.4.4).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum DataTab {
    /// The K page, edited bit by bit.
    #[default]
    K,
    /// The D table.
    D,
    /// The D_FLOAT table.
    DFloat,
    /// The DT table.
    Dt,
    /// The DC table.
    Dc,
}

/// What the user did in the tables, for the caller to carry out.
#[derive(Clone, Debug, PartialEq)]
pub enum TableEvent {
    /// A table edit to apply to the document (and record for undo), in order.
    Apply(TableEdit),
    /// An online command asked for from a page (a scenario's Apply/Release).
    Online(crate::gui::command::Command),
}

/// A cell: its table, row and column.
type CellKey = (Sheet, usize, Col);

/// Text typed into a cell and not committed yet, with the reason it was refused, if it was.
#[derive(Clone, Debug, Default)]
struct Pending {
    text: String,
    error: Option<TableError>,
    /// When it was last typed or refused, so that the latest draft is undone first.
    stamp: u64,
}

/// The password fields of the version view (cleared after every use; never saved).
#[derive(Clone, Default)]
struct PasswordDraft {
    current: String,
    new: String,
    confirm: String,
    /// The outcome of the last button press: an error (red) or a confirmation.
    note: Option<(bool, Msg)>,
}

// By hand, so that logging the UI state never writes a password out.
impl std::fmt::Debug for PasswordDraft {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("PasswordDraft")
            .field("typed", &!(self.current.is_empty() && self.new.is_empty()))
            .field("note", &self.note)
            .finish_non_exhaustive()
    }
}

/// The table editors' UI state.
#[derive(Clone, Debug, Default)]
pub struct TableState {
    /// The tab the data-setting view shows.
    pub data_tab: DataTab,
    /// The selected row of each table; the toolbar's row buttons act on it.
    pub selected: HashMap<Sheet, usize>,
    /// Cells being typed in, or refused.
    pending: HashMap<CellKey, Pending>,
    /// Why the last row-menu action was refused.
    op_error: Option<(Sheet, TableError)>,
    /// A row to bring into view at the next frame.
    scroll_to: Option<(Sheet, usize)>,
    /// Designer, version and remarks being typed, with when they were typed.
    version: [Option<(String, u64)>; 4],
    /// The password fields.
    password: PasswordDraft,
    /// The view and document generation the drafts were typed against.
    seen: Option<(View, u64)>,
    /// The last stamp given to a draft.
    stamp: u64,
    /// The scenario the Scenarios page shows (index in the project).
    pub scenario: usize,
    /// Its name, note and lines as being typed.
    scenario_draft: Option<scenarios::ScenarioDraft>,
    /// For the page's button, set by the editor each frame: (online, the scenario applied).
    scenario_online: (bool, bool),
}

impl TableState {
    /// The row table `view` shows (the data-setting view: its current tab; the K page is not
    /// a row table).
    pub fn sheet_of(&self, view: View) -> Option<Sheet> {
        Some(match view {
            View::Symbols(t) => Sheet::Symbols(t),
            View::Data => match self.data_tab {
                DataTab::K => return None,
                DataTab::D => Sheet::D,
                DataTab::DFloat => Sheet::DFloat,
                DataTab::Dt => Sheet::Dt,
                DataTab::Dc => Sheet::Dc,
            },
            View::Messages => Sheet::Messages,
            View::Diagnosis => Sheet::Diagnosis,
            View::Permissions => Sheet::Permissions,
            View::MCodes => Sheet::MCodes,
            _ => return None,
        })
    }

    /// Ctrl+G in a table (manual §3.2.2 转到): row `row` (0-based) is selected and scrolled
    /// into view; false when the table has no such row.
    pub fn go_to_row(&mut self, sheet: Sheet, row: usize, project: &Project) -> bool {
        if row >= sheet.rows(project) {
            return false;
        }
        self.selected.insert(sheet, row);
        self.scroll_to = Some((sheet, row));
        true
    }

    /// Rows of a table.
    pub fn rows_in(&self, sheet: Sheet, project: &Project) -> usize {
        sheet.rows(project)
    }

    /// Notes that the drafts were typed against `generation` of the document shown in
    /// `view`. [`tables_ui`] does so for the document it drew; the caller does it again after
    /// applying the widget's edits, so that its own edits do not count as a change behind the
    /// drafts' back (which drops them: after an undo or in another document they may be
    /// other rows).
    pub fn seen(&mut self, view: View, generation: u64) {
        self.seen = Some((view, generation));
    }

    /// Ctrl+Z while a draft is pending (a refused cell still red, a field typed in and not
    /// committed): throws the latest draft away, as a text field undoes its typing before
    /// anything else, and returns true; false when there is none, and the caller undoes the
    /// last edit.
    pub fn undo_draft(&mut self) -> bool {
        let cell = self
            .pending
            .iter()
            .max_by_key(|(_, p)| p.stamp)
            .map(|(k, p)| (*k, p.stamp));
        let field = (0..3)
            .filter_map(|i| self.version[i].as_ref().map(|(_, s)| (i, *s)))
            .max_by_key(|(_, s)| *s);
        match (cell, field) {
            (Some((_, c)), Some((i, f))) if f > c => self.version[i] = None,
            (Some((key, _)), _) => {
                self.pending.remove(&key);
            }
            (None, Some((i, _))) => self.version[i] = None,
            (None, None) => return false,
        }
        true
    }

    /// The view that shows the table an edit replaces (`project` on one side of the edit):
    /// for the symbol tables, the one that differs. `None` for the operator panel, which is
    /// shown by the online monitor beside the main area, not in a view of its own.
    pub fn view_of(project: &Project, edit: &TableEdit) -> Option<View> {
        Some(match edit {
            TableEdit::Symbols(_) => match changed_row(project, edit) {
                Some((Sheet::Symbols(t), _)) => View::Symbols(t),
                _ => View::Symbols(0),
            },
            TableEdit::Data(_) => View::Data,
            TableEdit::Messages(_) => View::Messages,
            TableEdit::Diagnosis(_) => View::Diagnosis,
            TableEdit::Permissions(_) => View::Permissions,
            TableEdit::MCodes(_) => View::MCodes,
            TableEdit::Version(_) => View::Version,
            TableEdit::Scenarios(_) => View::Scenarios,
            TableEdit::Panel(_) | TableEdit::Machine(_) => return None,
        })
    }

    /// After an undo or a redo of a table edit: selects the row it changed and scrolls to it
    /// (the data view turns to its tab); returns the view to show. `project` is on one side
    /// of the edit and `edit` holds the other, as the history gives them. `None` keeps the
    /// view shown (see [`TableState::view_of`]).
    pub fn show_change(&mut self, project: &Project, edit: &TableEdit) -> Option<View> {
        match changed_row(project, edit) {
            Some((sheet, row)) => {
                if let Some(tab) = data_tab_of(sheet) {
                    self.data_tab = tab;
                }
                self.selected.insert(sheet, row);
                self.scroll_to = Some((sheet, row));
            }
            // A data edit without a changed row is the K page's.
            None if matches!(edit, TableEdit::Data(_)) => self.data_tab = DataTab::K,
            None => {}
        }
        Self::view_of(project, edit)
    }

    /// The stamp of the newest draft, if any (see [`TableState::mark`]).
    pub fn latest_draft(&self) -> Option<u64> {
        let cells = self.pending.values().map(|p| p.stamp);
        let fields = self.version.iter().flatten().map(|(_, s)| *s);
        cells.chain(fields).max()
    }

    /// A stamp for something that happened now (a change applied to the project), on the
    /// same clock as the drafts' stamps: undo takes back whichever came last.
    pub fn mark(&mut self) -> u64 {
        self.next_stamp()
    }

    /// Drops everything typed and not committed (Escape, another document).
    pub fn forget_drafts(&mut self) {
        self.pending.clear();
        self.op_error = None;
        self.version = Default::default();
        self.password = PasswordDraft::default();
        self.scenario_draft = None;
    }

    /// A stamp for a draft typed or refused now.
    fn next_stamp(&mut self) -> u64 {
        self.stamp += 1;
        self.stamp
    }

    /// The first refusal among a row's cells.
    fn row_error(&self, sheet: Sheet, row: usize) -> Option<&TableError> {
        sheet.columns().iter().find_map(|c| {
            self.pending
                .get(&(sheet, row, *c))
                .and_then(|p| p.error.as_ref())
        })
    }
}

/// The tab that shows a data table.
fn data_tab_of(sheet: Sheet) -> Option<DataTab> {
    Some(match sheet {
        Sheet::D => DataTab::D,
        Sheet::DFloat => DataTab::DFloat,
        Sheet::Dt => DataTab::Dt,
        Sheet::Dc => DataTab::Dc,
        _ => return None,
    })
}

/// Draws the table `view` shows, of `doc`, and returns what the user did: the edits to apply,
/// in order (the caller applies them, then tells `state` the new generation with
/// [`TableState::seen`]). Views that are no table draw nothing.
pub fn tables_ui(
    ui: &mut egui::Ui,
    doc: &Document,
    view: View,
    state: &mut TableState,
    lang: Lang,
) -> Vec<TableEvent> {
    // Drafts belong to the rows they were typed in: after an undo, another document or
    // another view those may be other rows, so the drafts go.
    if state.seen != Some((view, doc.generation())) {
        state.forget_drafts();
    }
    let project = doc.project();
    let mut events = Vec::new();
    match view {
        View::Symbols(t) => match project.symbol_tables.get(t) {
            Some(table) => {
                ui.heading(&table.name);
                sheet::sheet_ui(ui, project, state, Sheet::Symbols(t), lang, &mut events);
            }
            None => {
                ui.label(Msg::TblNoSuchTable.text(lang));
            }
        },
        View::Data => data_ui(ui, project, state, lang, &mut events),
        View::Messages | View::Diagnosis | View::Permissions | View::MCodes => {
            let (title, sheet) = match view {
                View::Messages => (Msg::Messages, Sheet::Messages),
                View::Diagnosis => (Msg::Diagnosis, Sheet::Diagnosis),
                View::Permissions => (Msg::Permissions, Sheet::Permissions),
                _ => (Msg::MCodes, Sheet::MCodes),
            };
            ui.heading(title.text(lang));
            sheet::sheet_ui(ui, project, state, sheet, lang, &mut events);
        }
        // Scrolled: in a small window the password part is below the fold, never out of reach.
        View::Version => {
            egui::ScrollArea::vertical()
                .id_salt("version-page")
                .show(ui, |ui| {
                    version::version_ui(ui, doc, state, lang, &mut events)
                });
        }
        View::Scenarios => scenarios::scenarios_ui(ui, doc, state, lang, &mut events),
        View::Block(_) | View::RefIndex | View::RefBits | View::RefBytes => {}
    }
    state.seen(view, doc.generation());
    events
}

/// The data-setting view: a tab per table, the K page first (§3.4.4).
fn data_ui(
    ui: &mut egui::Ui,
    project: &Project,
    state: &mut TableState,
    lang: Lang,
    events: &mut Vec<TableEvent>,
) {
    ui.horizontal(|ui| {
        for (tab, msg) in [
            (DataTab::K, Msg::TblKPage),
            (DataTab::D, Msg::TblTabD),
            (DataTab::DFloat, Msg::TblTabDFloat),
            (DataTab::Dt, Msg::TblTabDt),
            (DataTab::Dc, Msg::TblTabDc),
        ] {
            ui.selectable_value(&mut state.data_tab, tab, msg.text(lang));
        }
    });
    ui.separator();
    match state.data_tab {
        DataTab::K => k_page::k_page_ui(ui, project, state, lang, events),
        DataTab::D => sheet::sheet_ui(ui, project, state, Sheet::D, lang, events),
        DataTab::DFloat => sheet::sheet_ui(ui, project, state, Sheet::DFloat, lang, events),
        DataTab::Dt => sheet::sheet_ui(ui, project, state, Sheet::Dt, lang, events),
        DataTab::Dc => sheet::sheet_ui(ui, project, state, Sheet::Dc, lang, events),
    }
}

/// The height of a table row.
fn row_height(ui: &egui::Ui) -> f32 {
    ui.spacing().interact_size.y + 6.0
}

impl LadderApp {
    /// Draws the table the project tree selected and applies the edits made in it.
    pub fn tables_ui(&mut self, ui: &mut egui::Ui) {
        if self.view == View::Data {
            let tab = self.tables.data_tab;
            self.with(|o: &mut OnlineState, cx| o.data_online_ui(cx, ui, tab));
        }
        let Some(doc) = self.doc.as_ref() else {
            return;
        };
        let scenario = crate::gui::command::Command::Scenario(self.tables.scenario);
        self.tables.scenario_online = (
            self.enabled(scenario),
            self.checked(scenario).unwrap_or(false),
        );
        let events = tables_ui(ui, doc, self.view, &mut self.tables, self.settings.lang);
        for event in events {
            match event {
                TableEvent::Apply(edit) => {
                    self.with_context(|cx| cx.apply_or_say(edit));
                }
                TableEvent::Online(c) => self.pending.push(c),
            }
        }
        if let Some(doc) = &self.doc {
            self.tables.seen(self.view, doc.generation());
        }
    }
}
