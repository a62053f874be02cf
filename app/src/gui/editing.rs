//! Editing with the keyboard and the mouse (manual §3.2.2 keys): every change goes through
//! the engine's edit operations and the document's history, so undo is exact.

use super::i18n::Msg;
use super::place::View;
use super::{LadderApp, OutputLine};
use ladder_engine::Op;
use ladder_engine::find::{self, Query};
use ladder_engine::model::{Cell, Change, Edit, EditError, Ladder, Operand, TableEdit};

/// What the operand prompt will place.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PlaceKind {
    /// F1 (NC with Shift).
    Contact {
        /// Normally closed.
        negated: bool,
    },
    /// F2 (OUTN with Shift).
    Coil {
        /// Inverted.
        negated: bool,
    },
    /// F6: a contact in parallel with the row above.
    Parallel {
        /// Normally closed.
        negated: bool,
    },
    /// F3: a function instruction, written as in IL (`TMRB T0000 DT0004 R0300.0`).
    Function,
    /// Ctrl+F: an address (any spelling), symbol, constant or instruction to find.
    Find,
    /// Ctrl+G: `NETWORK [ROW]` of the current block (1-based).
    GoTo,
    /// The cursor's network title.
    NetworkTitle,
    /// The cursor's network comment.
    NetworkComment,
    /// A new subprogram: `NUMBER [NAME]`.
    NewSub,
    /// Renumber or rename subprogram P`0`: `NUMBER [NAME]`.
    RenameSub(u16),
    /// A block's information text.
    BlockInfo(super::place::BlockKey),
}

/// The open operand prompt.
#[derive(Clone, Debug, PartialEq)]
pub struct Prompt {
    /// What Enter places.
    pub kind: PlaceKind,
    /// What the user typed.
    pub text: String,
    /// Why the last Enter was refused.
    pub error: Option<String>,
}

pub use super::place::Cursor;

impl LadderApp {
    fn block(&self) -> Option<usize> {
        match self.view {
            View::Block(b) => Some(b),
            _ => None,
        }
    }

    /// Applies a change through the document's door; a refusal is returned, in the UI's
    /// language, for the caller to show once (the prompt shows it, a command reports it).
    pub fn try_edit(&mut self, change: impl Into<Change>) -> Result<bool, String> {
        let lang = self.settings.lang;
        let doc = self.doc.as_mut().ok_or(Msg::NoProject.text(lang))?;
        let changed = doc
            .apply(change)
            .map_err(|e| super::errors::refused(&e, lang))?;
        if changed {
            self.last_change = self.tables.mark();
        }
        Ok(changed)
    }

    /// Applies a change from a command; a refusal goes to the output window. True when the
    /// change was applied (or changed nothing).
    pub fn edit(&mut self, change: impl Into<Change>) -> bool {
        match self.try_edit(change) {
            Ok(_) => true,
            Err(text) => {
                self.output.push(OutputLine {
                    text,
                    error: true,
                    target: None,
                });
                false
            }
        }
    }

    /// The ladder, to read.
    pub fn ladder(&self) -> Option<&Ladder> {
        self.doc.as_ref().map(|d| &d.project().ladder)
    }

    /// Runs `f` as one undo step: everything it changes is undone together.
    pub fn grouped<R>(&mut self, f: impl FnOnce(&mut LadderApp) -> R) -> R {
        if let Some(d) = self.doc.as_mut() {
            d.begin_group();
        }
        let r = f(self);
        if let Some(d) = self.doc.as_mut() {
            d.end_group();
        }
        r
    }

    fn width(&self) -> usize {
        self.doc.as_ref().map_or(0, |d| d.project().ladder.width)
    }

    fn rows_of(&self, block: usize, network: usize) -> usize {
        self.doc
            .as_ref()
            .and_then(|d| d.project().ladder.blocks.get(block))
            .and_then(|b| b.networks.get(network))
            .map_or(0, |n| n.rows.len())
    }

    fn networks_of(&self, block: usize) -> usize {
        self.doc
            .as_ref()
            .and_then(|d| d.project().ladder.blocks.get(block))
            .map_or(0, |b| b.networks.len())
    }

    /// Whether the cursor is on the new row offered below its network's last row (Down
    /// there): a place to draw that is not in the project until something is drawn in it.
    pub fn on_new_row(&self) -> bool {
        let c = self.edit.cursor;
        self.block() == Some(c.block) && {
            let rows = self.rows_of(c.block, c.network);
            rows > 0 && c.row == rows
        }
    }

    /// As [`LadderApp::ensure_network`], and the new row below a network opened for real
    /// when the cursor is on it: drawing there adds the row, in the gesture's undo step.
    pub fn ensure_row(&mut self) -> Option<Cursor> {
        if self.on_new_row() {
            let c = self.edit.cursor;
            let insert = self.ladder()?.plan_insert_row(c.block, c.network, c.row);
            self.edit(insert);
        }
        self.ensure_network()
    }

    /// Makes sure the cursor's block has a network to edit in, and the cursor is inside it.
    /// An empty block gets a network first; the gesture that needed it runs in an undo group
    /// (every command does), so one undo takes back both. `None` when there is no cell to edit (no project, not a
    /// ladder view, a read-only project with an empty block).
    pub fn ensure_network(&mut self) -> Option<Cursor> {
        let block = self.block()?;
        if self.networks_of(block) == 0 {
            let insert = self.ladder()?.plan_insert_network(block, 0);
            self.edit(insert);
        }
        let networks = self.networks_of(block);
        if networks == 0 {
            return None;
        }
        let mut c = self.edit.cursor;
        c.block = block;
        c.network = c.network.min(networks - 1);
        c.row = c.row.min(self.rows_of(block, c.network).saturating_sub(1));
        c.col = c.col.min(self.width());
        self.edit.cursor = c;
        Some(c)
    }

    /// Ctrl+F: every match goes to the output window (a click shows it) and the cursor goes
    /// to the next match; Ctrl+F, Enter again (the prompt keeps the text) goes on to the one
    /// after, as GSKLadder's "find next".
    pub fn find(&mut self, text: &str) -> Result<(), String> {
        let lang = self.settings.lang;
        let query = Query::parse(text)
            .ok_or_else(|| format!("`{text}`: {}", Msg::NothingToFind.text(lang)))?;
        let Some(doc) = self.doc.as_ref() else {
            return Ok(());
        };
        let project = doc.project();
        let mut hits = find::find(project, &query);
        hits.sort_unstable();
        let mut lines: Vec<OutputLine> = hits
            .iter()
            .map(|at| {
                let r = ladder_engine::xref::Reference {
                    address: ladder_engine::Address::byte(ladder_engine::Area::R, 0),
                    block: at.block,
                    network: at.network,
                    row: at.row,
                    col: at.col,
                    usage: ladder_engine::xref::Use::Read,
                };
                OutputLine {
                    text: format!(
                        "{} N{:04} {}:{}  {}",
                        project.ladder.blocks[at.block].kind.label(),
                        at.network + 1,
                        at.row + 1,
                        at.col + 1,
                        ladder_engine::xref::context(project, &r)
                    ),
                    error: false,
                    target: Some(*at),
                }
            })
            .collect();
        lines.push(OutputLine {
            text: format!("{} {}", hits.len(), Msg::Found.text(lang)),
            error: false,
            target: None,
        });
        self.output.list(lines);
        // The same search again steps past the cursor; a new one may start on it.
        let again = self.edit.last_find == text;
        let c = self.edit.cursor;
        let next = hits
            .iter()
            .find(|h| if again { **h > c } else { **h >= c })
            .or(hits.first())
            .copied();
        self.edit.last_find = text.to_string();
        if let Some(at) = next {
            self.jump(at);
        }
        Ok(())
    }

    /// Ctrl+G: moves the cursor to `NETWORK [ROW]` of the shown block and scrolls to it.
    pub fn go_to(&mut self, text: &str) -> Result<(), String> {
        let lang = self.settings.lang;
        if let Some(sheet) = self.tables.sheet_of(self.view) {
            // In a table view, Ctrl+G goes to a row of the table.
            let Some(doc) = self.doc.as_ref() else {
                return Ok(());
            };
            let rows = self.tables.rows_in(sheet, doc.project());
            let row = text
                .trim()
                .parse::<usize>()
                .map_err(|_| Msg::GoToRowUsage.text(lang).to_string())?;
            if row == 0 || !self.tables.go_to_row(sheet, row - 1, doc.project()) {
                return Err(format!("{}: 1–{rows}", Msg::NoSuchTableRow.text(lang)));
            }
            return Ok(());
        }
        let block = self
            .block()
            .ok_or_else(|| Msg::GoToUsage.text(lang).to_string())?;
        let numbers: Vec<usize> = text
            .split(|c: char| c.is_whitespace() || c == ':' || c == ',')
            .filter(|w| !w.is_empty())
            .map(|w| w.trim_start_matches(['N', 'n']).parse::<usize>())
            .collect::<Result<_, _>>()
            .map_err(|_| Msg::GoToUsage.text(lang).to_string())?;
        let (network, row) = match numbers[..] {
            [n] => (n, 1),
            [n, r] => (n, r),
            _ => return Err(Msg::GoToUsage.text(lang).into()),
        };
        let networks = self.networks_of(block);
        if network == 0 || network > networks {
            return Err(format!("{}: 1–{networks}", Msg::NoSuchNetwork.text(lang)));
        }
        let rows = self.rows_of(block, network - 1);
        if row == 0 || row > rows {
            return Err(format!("{}: 1–{rows}", Msg::NoSuchRow.text(lang)));
        }
        self.edit.cursor = Cursor {
            block,
            network: network - 1,
            row: row - 1,
            col: 0,
        };
        self.edit.jump_to = Some(network - 1);
        Ok(())
    }

    /// Places what the prompt describes at the cursor.
    pub fn place(&mut self, kind: PlaceKind, text: &str) -> Result<(), String> {
        match kind {
            PlaceKind::Find => return self.find(text),
            PlaceKind::GoTo => return self.go_to(text),
            PlaceKind::NetworkTitle => {
                self.set_network_text(Some(text), None);
                return Ok(());
            }
            PlaceKind::NetworkComment => {
                self.set_network_text(None, Some(text));
                return Ok(());
            }
            PlaceKind::NewSub => return self.new_subprogram(text),
            PlaceKind::RenameSub(i) => return self.rename_subprogram(i, text),
            PlaceKind::BlockInfo(key) => return self.set_block_info(key, text),
            _ => {}
        }
        let lang = self.settings.lang;
        let operand =
            |t: &str| Operand::parse(t).map_err(|e| super::errors::operand_error(&e, lang));
        // A typing error refuses before anything changes (no network added for nothing).
        if matches!(
            kind,
            PlaceKind::Contact { .. } | PlaceKind::Coil { .. } | PlaceKind::Parallel { .. }
        ) {
            operand(text)?;
        }
        let Some(at) = self.ensure_row() else {
            return Err(Msg::NoProject.text(self.settings.lang).into());
        };
        let width = self.width();
        match kind {
            PlaceKind::Contact { negated } | PlaceKind::Parallel { negated } => {
                let cell = Cell::Contact {
                    negated,
                    operand: operand(text)?,
                };
                let at = Cursor {
                    col: at.col.min(width - 1),
                    ..at
                };
                let edit = if matches!(kind, PlaceKind::Parallel { .. }) {
                    Ladder::plan_parallel_contact(at, cell)
                        .map_err(|e| super::errors::edit_error(&e, self.settings.lang))?
                } else {
                    Edit::SetCell { at, cell }
                };
                if self.try_edit(edit)? {
                    self.edit.cursor = Cursor {
                        col: at.col + 1,
                        ..at
                    };
                }
            }
            PlaceKind::Find
            | PlaceKind::GoTo
            | PlaceKind::NetworkTitle
            | PlaceKind::NetworkComment
            | PlaceKind::NewSub
            | PlaceKind::RenameSub(_)
            | PlaceKind::BlockInfo(_) => {}
            PlaceKind::Coil { .. } | PlaceKind::Function => {
                let cell = match kind {
                    PlaceKind::Coil { negated } => Cell::Coil {
                        negated,
                        operand: operand(text)?,
                    },
                    _ => {
                        let mut words = text.split_whitespace();
                        let name = words.next().unwrap_or("");
                        let op = Op::from_name(name)
                            .filter(|op| {
                                op.spec().class == ladder_engine::catalog::InstrClass::Function
                            })
                            .ok_or_else(|| format!("`{name}` is not a function instruction"))?;
                        let operands = words.map(operand).collect::<Result<Vec<_>, _>>()?;
                        Cell::Box { op, operands }
                    }
                };
                let at = Cursor { col: width, ..at };
                let edit = self
                    .ladder()
                    .map(|l| l.plan_output(at, cell))
                    .transpose()
                    .map_err(|e| super::errors::edit_error(&e, self.settings.lang))?;
                if let Some(edit) = edit
                    && self.try_edit(edit)?
                {
                    self.edit.cursor = at;
                }
            }
        }
        Ok(())
    }

    /// Shift+arrow: the selection grows from where it started to the moved cursor.
    pub(super) fn extend_by(&mut self, dr: i32, dc: i32) {
        let selection = self.edit.selection;
        let from = self.edit.cursor;
        self.move_cursor(dr, dc);
        let to = self.edit.cursor;
        self.edit.selection = selection;
        if selection.is_none() {
            self.edit.cursor = from;
        }
        self.edit.extend_selection(to);
    }

    pub(super) fn move_cursor(&mut self, dr: i32, dc: i32) {
        let Some(block) = self.block() else { return };
        let mut c = self.edit.cursor;
        c.block = block;
        let width = self.width() as i32;
        self.edit.selection = None;
        c.col = (c.col as i32 + dc).clamp(0, width) as usize;
        let rows = self.rows_of(block, c.network) as i32;
        let row = c.row as i32 + dr;
        if row < 0 && c.network > 0 {
            c.network -= 1;
            c.row = self.rows_of(block, c.network).saturating_sub(1);
        } else if row > rows && c.network + 1 < self.networks_of(block) {
            c.network += 1;
            c.row = 0;
        } else {
            // Down from the last row goes to the new row offered below it (`on_new_row`).
            c.row = row.clamp(0, rows.max(0)) as usize;
        }
        // The view follows with the least scrolling (ladder_view's `follow`), so an arrow
        // key never throws the network to the top of the screen.
        self.edit.cursor = c;
    }

    /// Home, End, PgUp, PgDn, Ctrl+Home, Ctrl+End: the cursor jumps, and the view follows.
    pub(super) fn navigate(&mut self, c: super::command::Command) {
        use super::command::Command;
        /// Networks a page moves: about what a screen shows at 100 %.
        const PAGE: usize = 8;
        let Some(block) = self.block() else { return };
        let networks = self.networks_of(block);
        let width = self.width();
        let mut at = self.edit.cursor;
        at.block = block;
        match c {
            Command::RowStart => at.col = 0,
            Command::RowEnd => at.col = width,
            Command::PageUp => {
                at.network = at.network.saturating_sub(PAGE);
                at.row = 0;
            }
            Command::PageDown => {
                at.network = (at.network + PAGE).min(networks.saturating_sub(1));
                at.row = 0;
            }
            Command::BlockStart => {
                at.network = 0;
                at.row = 0;
                at.col = 0;
            }
            Command::BlockEnd => {
                at.network = networks.saturating_sub(1);
                at.row = self.rows_of(block, at.network).saturating_sub(1);
                at.col = 0;
            }
            _ => return,
        }
        self.edit.selection = None;
        self.edit.cursor = at;
        self.edit.jump_to = Some(at.network);
    }

    /// F4: a wire at the cursor.
    pub fn wire(&mut self) {
        if let Some(at) = self.ensure_row() {
            let at = Cursor {
                col: at.col.min(self.width() - 1),
                ..at
            };
            if self.edit(Edit::SetCell {
                at,
                cell: Cell::Wire,
            }) {
                self.edit.cursor = Cursor {
                    col: at.col + 1,
                    ..at
                };
            }
        }
    }

    /// F5: the vertical link at the left of the cursor, added or removed (a row is added below
    /// when there is none).
    pub fn link(&mut self) {
        let Some(at) = self.ensure_network() else {
            return;
        };
        let planned = self.ladder().map(|l| l.plan_toggle_link(at));
        match planned {
            Some(Ok(edit)) => {
                self.edit(edit);
            }
            Some(Err(e)) => self.report_edit_error(&e),
            None => {}
        }
    }

    /// Ctrl+T (above) and Ctrl+R (below the cursor): a new empty row; the cursor goes to it.
    pub fn insert_row(&mut self, below: bool) {
        if let Some(at) = self.ensure_network() {
            let row = at.row + usize::from(below);
            let Some(insert) = self
                .ladder()
                .map(|l| l.plan_insert_row(at.block, at.network, row))
            else {
                return;
            };
            if self.edit(insert) {
                self.edit.cursor = Cursor { row, ..at };
            }
        }
    }

    /// Ctrl+U (above) and Ctrl+I (below the cursor's network): a new empty network.
    pub fn insert_network(&mut self, below: bool) {
        let Some(block) = self.block() else { return };
        let n = self.networks_of(block);
        let index = if n == 0 {
            0
        } else {
            (self.edit.cursor.network + usize::from(below)).min(n)
        };
        let Some(insert) = self.ladder().map(|l| l.plan_insert_network(block, index)) else {
            return;
        };
        if self.edit(insert) {
            self.edit.cursor = Cursor {
                block,
                network: index,
                row: 0,
                col: 0,
            };
        }
    }

    /// Replaces a table through the document's door (table editors call this for every
    /// change).
    pub fn edit_table(&mut self, edit: TableEdit) {
        self.edit(edit);
    }

    /// Reports an edit the engine refused, in the output window.
    pub fn report_edit_error(&mut self, e: &EditError) {
        let text = super::errors::edit_error(e, self.settings.lang);
        self.output.push(OutputLine {
            text,
            error: true,
            target: None,
        });
    }

    /// Ctrl+Z: a draft being typed in a table goes first, as a text field would; else the last
    /// step of the project is taken back and shown where it changed.
    pub fn undo(&mut self) {
        // A draft typed after the last change goes first, as a text field undoes its typing.
        if self.tables.latest_draft() > Some(self.last_change) && self.tables.undo_draft() {
            return;
        }
        let Some(doc) = self.doc.as_mut() else { return };
        let step = doc.undo().cloned();
        self.after_history(step);
    }

    /// Ctrl+Y: the last undone step again, shown where it changed.
    pub fn redo(&mut self) {
        let Some(doc) = self.doc.as_mut() else { return };
        let step = doc.redo().cloned();
        self.after_history(step);
    }

    /// After an undo or redo: the view and the place of the step (a table's row, a ladder
    /// cell, a block), so a change never comes back unseen.
    fn after_history(&mut self, step: Option<Change>) {
        self.clamp_ui_state();
        let (Some(step), Some(doc)) = (step, self.doc.as_ref()) else {
            return;
        };
        if let Change::Table(t) = &step {
            if let Some(view) = self.tables.show_change(doc.project(), t) {
                self.view = view;
            }
            return;
        }
        match super::place::place_of(&step, doc.project()) {
            Some(super::place::Place::Cell(at)) => self.jump(at),
            Some(super::place::Place::Block(b)) => {
                self.view = View::Block(b);
                self.clamp_ui_state();
            }
            None => {}
        }
    }
}
