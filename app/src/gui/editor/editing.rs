//! Editing with the keyboard and the mouse (manual §3.2.2 keys): every change goes through
//! the engine's edit operations and the document's history, so undo is exact.

use crate::gui::OutputLine;
use crate::gui::context::Context;
use crate::gui::editor::EditState;
use crate::gui::i18n::Msg;
use crate::gui::place::View;
use ladder_engine::Op;
use ladder_engine::find::{self, Query};
use ladder_engine::model::{Cell, Change, Edit, EditError, Ladder, Operand};

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
    /// Ctrl+G in a table view: a row of the table of so many rows (1-based).
    GoToRow(usize),
    /// The cursor's network title.
    NetworkTitle,
    /// The cursor's network comment.
    NetworkComment,
    /// A new subprogram: `NUMBER [NAME]`.
    NewSub,
    /// Renumber or rename subprogram P`0`: `NUMBER [NAME]`.
    RenameSub(u16),
    /// A block's information text.
    BlockInfo(crate::gui::place::BlockKey),
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

pub use crate::gui::place::Cursor;

impl EditState {
    pub(crate) fn open_prompt(&mut self, kind: PlaceKind, text: String) {
        self.prompt = Some(Prompt {
            kind,
            text,
            error: None,
        });
    }

    /// Selects `what` in the cursor's block and deletes it (Delete row, Delete network).
    pub(crate) fn delete_at_cursor(
        &mut self,
        cx: &mut Context<'_>,
        what: impl FnOnce(crate::gui::place::Cursor) -> crate::gui::editor::selection::Selection,
    ) {
        if let Some(at) = self.existing_cursor(cx) {
            *cx.selection = Some((at.block, what(at)));
            self.delete_selection(cx);
        }
    }

    pub(crate) fn block(&self, cx: &Context<'_>) -> Option<usize> {
        match *cx.view {
            View::Block(b) => Some(b),
            _ => None,
        }
    }

    /// Applies a change from a command; a refusal goes to the output window. True when the
    /// change was applied (or changed nothing).
    pub fn edit(&mut self, cx: &mut Context<'_>, change: impl Into<Change>) -> bool {
        cx.apply_or_say(change)
    }

    /// The ladder, to read.
    pub fn ladder<'c>(&self, cx: &'c Context<'_>) -> Option<&'c Ladder> {
        cx.doc().map(|d| &d.project().ladder)
    }

    pub(crate) fn width(&self, cx: &Context<'_>) -> usize {
        cx.doc().map_or(0, |d| d.project().ladder.width)
    }

    pub(crate) fn rows_of(&self, cx: &Context<'_>, block: usize, network: usize) -> usize {
        cx.doc()
            .and_then(|d| d.project().ladder.blocks.get(block))
            .and_then(|b| b.networks.get(network))
            .map_or(0, |n| n.rows.len())
    }

    pub(crate) fn networks_of(&self, cx: &Context<'_>, block: usize) -> usize {
        cx.doc()
            .and_then(|d| d.project().ladder.blocks.get(block))
            .map_or(0, |b| b.networks.len())
    }

    /// Whether the cursor is on the new row offered below its network's last row (Down
    /// there): a place to draw that is not in the project until something is drawn in it.
    pub fn on_new_row(&self, cx: &Context<'_>) -> bool {
        let c = *cx.cursor;
        self.block(cx) == Some(c.block) && {
            let rows = self.rows_of(cx, c.block, c.network);
            rows > 0 && c.row == rows
        }
    }

    /// As [`EditState::ensure_network`], and the new row below a network opened for real
    /// when the cursor is on it: drawing there adds the row, in the gesture's undo step.
    pub fn ensure_row(&mut self, cx: &mut Context<'_>) -> Option<Cursor> {
        if self.on_new_row(cx) {
            let c = *cx.cursor;
            let insert = self.ladder(cx)?.plan_insert_row(c.block, c.network, c.row);
            self.edit(cx, insert);
        }
        self.ensure_network(cx)
    }

    /// Makes sure the cursor's block has a network to edit in, and the cursor is inside it.
    /// An empty block gets a network first; the gesture that needed it runs in an undo group
    /// (every command does), so one undo takes back both. `None` when there is no cell to edit (no project, not a
    /// ladder view, a read-only project with an empty block).
    pub fn ensure_network(&mut self, cx: &mut Context<'_>) -> Option<Cursor> {
        let block = self.block(cx)?;
        if self.networks_of(cx, block) == 0 {
            let insert = self.ladder(cx)?.plan_insert_network(block, 0);
            self.edit(cx, insert);
        }
        let networks = self.networks_of(cx, block);
        if networks == 0 {
            return None;
        }
        let mut c = *cx.cursor;
        c.block = block;
        c.network = c.network.min(networks - 1);
        c.row = c
            .row
            .min(self.rows_of(cx, block, c.network).saturating_sub(1));
        c.col = c.col.min(self.width(cx));
        *cx.cursor = c;
        Some(c)
    }

    /// Ctrl+F: every match goes to the output window (a click shows it) and the cursor goes
    /// to the next match; Ctrl+F, Enter again (the prompt keeps the text) goes on to the one
    /// after, as GSKLadder's "find next".
    pub fn find(&mut self, cx: &mut Context<'_>, text: &str) -> Result<(), String> {
        let lang = cx.settings.lang;
        let query = Query::parse(text)
            .ok_or_else(|| format!("`{text}`: {}", Msg::NothingToFind.text(lang)))?;
        let Some(doc) = cx.doc() else {
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
        cx.output.list(lines);
        // The same search again steps past the cursor; a new one may start on it.
        let again = self.last_find == text;
        let c = *cx.cursor;
        let next = hits
            .iter()
            .find(|h| if again { **h > c } else { **h >= c })
            .or(hits.first())
            .copied();
        self.last_find = text.to_string();
        if let Some(at) = next {
            cx.pending.push(crate::gui::command::Command::ShowCell(at));
        }
        Ok(())
    }

    /// Ctrl+G: moves the cursor to `NETWORK [ROW]` of the shown block and scrolls to it.
    pub fn go_to(&mut self, cx: &mut Context<'_>, text: &str) -> Result<(), String> {
        let lang = cx.settings.lang;
        let block = self
            .block(cx)
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
        let networks = self.networks_of(cx, block);
        if network == 0 || network > networks {
            return Err(format!("{}: 1–{networks}", Msg::NoSuchNetwork.text(lang)));
        }
        let rows = self.rows_of(cx, block, network - 1);
        if row == 0 || row > rows {
            return Err(format!("{}: 1–{rows}", Msg::NoSuchRow.text(lang)));
        }
        *cx.cursor = Cursor {
            block,
            network: network - 1,
            row: row - 1,
            col: 0,
        };
        self.jump_to = Some(network - 1);
        Ok(())
    }

    /// Ctrl+G in a table view: row `text` (1-based) of a table of `rows` rows; the tables
    /// move to it after the frame.
    pub fn go_to_row(
        &mut self,
        cx: &mut Context<'_>,
        text: &str,
        rows: usize,
    ) -> Result<(), String> {
        let lang = cx.settings.lang;
        let row = text
            .trim()
            .parse::<usize>()
            .map_err(|_| Msg::GoToRowUsage.text(lang).to_string())?;
        if row == 0 || row > rows {
            return Err(format!("{}: 1–{rows}", Msg::NoSuchTableRow.text(lang)));
        }
        cx.pending
            .push(crate::gui::command::Command::GoToRow(row - 1));
        Ok(())
    }

    /// Places what the prompt describes at the cursor.
    pub fn place(
        &mut self,
        cx: &mut Context<'_>,
        kind: PlaceKind,
        text: &str,
    ) -> Result<(), String> {
        match kind {
            PlaceKind::Find => return self.find(cx, text),
            PlaceKind::GoTo => return self.go_to(cx, text),
            PlaceKind::GoToRow(rows) => return self.go_to_row(cx, text, rows),
            PlaceKind::NetworkTitle => {
                self.set_network_text(cx, Some(text), None);
                return Ok(());
            }
            PlaceKind::NetworkComment => {
                self.set_network_text(cx, None, Some(text));
                return Ok(());
            }
            PlaceKind::NewSub => return self.new_subprogram(cx, text),
            PlaceKind::RenameSub(i) => return self.rename_subprogram(cx, i, text),
            PlaceKind::BlockInfo(key) => return self.set_block_info(cx, key, text),
            _ => {}
        }
        let lang = cx.settings.lang;
        let operand =
            |t: &str| Operand::parse(t).map_err(|e| crate::gui::errors::operand_error(&e, lang));
        // A typing error refuses before anything changes (no network added for nothing).
        if matches!(
            kind,
            PlaceKind::Contact { .. } | PlaceKind::Coil { .. } | PlaceKind::Parallel { .. }
        ) {
            operand(text)?;
        }
        let Some(at) = self.ensure_row(cx) else {
            return Err(Msg::NoProject.text(cx.settings.lang).into());
        };
        let width = self.width(cx);
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
                        .map_err(|e| crate::gui::errors::edit_error(&e, cx.settings.lang))?
                } else {
                    Edit::SetCell { at, cell }
                };
                if cx.apply(edit)? {
                    *cx.cursor = Cursor {
                        col: at.col + 1,
                        ..at
                    };
                }
            }
            PlaceKind::Find
            | PlaceKind::GoTo
            | PlaceKind::GoToRow(_)
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
                    .ladder(cx)
                    .map(|l| l.plan_output(at, cell))
                    .transpose()
                    .map_err(|e| crate::gui::errors::edit_error(&e, cx.settings.lang))?;
                if let Some(edit) = edit
                    && cx.apply(edit)?
                {
                    *cx.cursor = at;
                }
            }
        }
        Ok(())
    }

    /// Shift+arrow: the selection grows from where it started to the moved cursor.
    pub(super) fn extend_by(&mut self, cx: &mut Context<'_>, dr: i32, dc: i32) {
        let selection = *cx.selection;
        let from = *cx.cursor;
        self.move_cursor(cx, dr, dc);
        let to = *cx.cursor;
        *cx.selection = selection;
        if selection.is_none() {
            *cx.cursor = from;
        }
        crate::gui::editor::extend_selection(&mut *cx.cursor, &mut *cx.selection, to);
    }

    pub(super) fn move_cursor(&mut self, cx: &mut Context<'_>, dr: i32, dc: i32) {
        let Some(block) = self.block(cx) else { return };
        let mut c = *cx.cursor;
        c.block = block;
        let width = self.width(cx) as i32;
        *cx.selection = None;
        c.col = (c.col as i32 + dc).clamp(0, width) as usize;
        let rows = self.rows_of(cx, block, c.network) as i32;
        let row = c.row as i32 + dr;
        if row < 0 && c.network > 0 {
            c.network -= 1;
            c.row = self.rows_of(cx, block, c.network).saturating_sub(1);
        } else if row > rows && c.network + 1 < self.networks_of(cx, block) {
            c.network += 1;
            c.row = 0;
        } else {
            // Down from the last row goes to the new row offered below it (`on_new_row`).
            c.row = row.clamp(0, rows.max(0)) as usize;
        }
        // The view follows with the least scrolling (ladder_view's `follow`), so an arrow
        // key never throws the network to the top of the screen.
        *cx.cursor = c;
    }

    /// Home, End, PgUp, PgDn, Ctrl+Home, Ctrl+End: the cursor jumps, and the view follows.
    pub(super) fn navigate(&mut self, cx: &mut Context<'_>, c: crate::gui::command::Command) {
        use crate::gui::command::Command;
        /// Networks a page moves: about what a screen shows at 100 %.
        const PAGE: usize = 8;
        let Some(block) = self.block(cx) else { return };
        let networks = self.networks_of(cx, block);
        let width = self.width(cx);
        let mut at = *cx.cursor;
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
                at.row = self.rows_of(cx, block, at.network).saturating_sub(1);
                at.col = 0;
            }
            _ => return,
        }
        *cx.selection = None;
        *cx.cursor = at;
        self.jump_to = Some(at.network);
    }

    /// F4: a wire at the cursor.
    pub fn wire(&mut self, cx: &mut Context<'_>) {
        if let Some(at) = self.ensure_row(cx) {
            let at = Cursor {
                col: at.col.min(self.width(cx) - 1),
                ..at
            };
            if self.edit(
                cx,
                Edit::SetCell {
                    at,
                    cell: Cell::Wire,
                },
            ) {
                *cx.cursor = Cursor {
                    col: at.col + 1,
                    ..at
                };
            }
        }
    }

    /// F5: the vertical link at the left of the cursor, added or removed (a row is added below
    /// when there is none).
    pub fn link(&mut self, cx: &mut Context<'_>) {
        let Some(at) = self.ensure_network(cx) else {
            return;
        };
        let planned = self.ladder(cx).map(|l| l.plan_toggle_link(at));
        match planned {
            Some(Ok(edit)) => {
                self.edit(cx, edit);
            }
            Some(Err(e)) => self.report_edit_error(cx, &e),
            None => {}
        }
    }

    /// Ctrl+T (above) and Ctrl+R (below the cursor): a new empty row; the cursor goes to it.
    pub fn insert_row(&mut self, cx: &mut Context<'_>, below: bool) {
        if let Some(at) = self.ensure_network(cx) {
            let row = at.row + usize::from(below);
            let Some(insert) = self
                .ladder(cx)
                .map(|l| l.plan_insert_row(at.block, at.network, row))
            else {
                return;
            };
            if self.edit(cx, insert) {
                *cx.cursor = Cursor { row, ..at };
            }
        }
    }

    /// Ctrl+U (above) and Ctrl+I (below the cursor's network): a new empty network.
    pub fn insert_network(&mut self, cx: &mut Context<'_>, below: bool) {
        let Some(block) = self.block(cx) else { return };
        let n = self.networks_of(cx, block);
        let index = if n == 0 {
            0
        } else {
            (cx.cursor.network + usize::from(below)).min(n)
        };
        let Some(insert) = self.ladder(cx).map(|l| l.plan_insert_network(block, index)) else {
            return;
        };
        if self.edit(cx, insert) {
            *cx.cursor = Cursor {
                block,
                network: index,
                row: 0,
                col: 0,
            };
        }
    }

    /// Reports an edit the engine refused, in the output window.
    pub fn report_edit_error(&mut self, cx: &mut Context<'_>, e: &EditError) {
        let text = crate::gui::errors::edit_error(e, cx.settings.lang);
        cx.output.push(OutputLine {
            text,
            error: true,
            target: None,
        });
    }
}
