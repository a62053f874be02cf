//! Editing with the keyboard and the mouse (manual §3.2.2 keys): every change goes through
//! the engine's edit operations and the document's history, so undo is exact.

use super::i18n::Msg;
use super::settings::DisplayMode;
use super::tree::View;
use super::{LadderApp, OutputLine};
use egui::{Key, Modifiers};
use ladder_engine::Op;
use ladder_engine::find::{self, Query};
use ladder_engine::model::{Cell, CellRef, Edit, EditError, Ladder, Operand, TableEdit};

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
    /// Ctrl+H: `FROM TO`, replaced only where the result is valid.
    Replace,
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
    BlockInfo(super::pointer::BlockKey),
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

/// Whether an applied edit's inverse would change nothing, i.e. the edit changed nothing.
fn is_noop(ladder: &Ladder, inverse: &Edit) -> bool {
    let net = |at: &CellRef| {
        ladder
            .blocks
            .get(at.block)
            .and_then(|b| b.networks.get(at.network))
    };
    match inverse {
        Edit::Batch(edits) => edits.iter().all(|e| is_noop(ladder, e)),
        Edit::SetCell { at, cell } => net(at).and_then(|n| n.cell(at.row, at.col)) == Some(cell),
        Edit::SetLink { at, on } => net(at).is_some_and(|n| n.link(at.row, at.col) == *on),
        Edit::SetNetworkText {
            block,
            network,
            title,
            comment,
        } => ladder
            .blocks
            .get(*block)
            .and_then(|b| b.networks.get(*network))
            .is_some_and(|n| n.title == *title && n.comment == *comment),
        _ => false,
    }
}

/// A basic-toolbar button: its name, its keys and what it does.
type ToolbarAction = (Msg, &'static str, fn(&mut LadderApp));

/// The cell cursor (UI state, never saved).
pub type Cursor = CellRef;

impl LadderApp {
    fn block(&self) -> Option<usize> {
        match self.view {
            View::Block(b) => Some(b),
            _ => None,
        }
    }

    /// Applies an edit through the history; a refusal goes to the output window.
    pub fn edit(&mut self, f: impl FnOnce(&mut Ladder) -> Result<Edit, EditError>) -> bool {
        let Some(doc) = self.doc.as_mut() else {
            return false;
        };
        if doc.read_only {
            let text = Msg::ReadOnly.text(self.settings.lang).to_string();
            self.output.push(OutputLine {
                text,
                error: true,
                target: None,
            });
            return false;
        }
        match f(&mut doc.project.ladder) {
            Ok(inverse) => {
                if is_noop(&doc.project.ladder, &inverse) {
                    // Nothing changed (Delete on an empty cell): no undo step, not dirty.
                    return true;
                }
                if std::mem::take(&mut self.merge_next) {
                    doc.history.record_merged(inverse);
                } else {
                    doc.history.record(inverse);
                }
                doc.changed();
                true
            }
            Err(e) => {
                self.output.push(OutputLine {
                    text: e.to_string(),
                    error: true,
                    target: None,
                });
                false
            }
        }
    }

    fn width(&self) -> usize {
        self.doc.as_ref().map_or(0, |d| d.project.ladder.width)
    }

    fn rows_of(&self, block: usize, network: usize) -> usize {
        self.doc
            .as_ref()
            .and_then(|d| d.project.ladder.blocks.get(block))
            .and_then(|b| b.networks.get(network))
            .map_or(0, |n| n.rows.len())
    }

    fn networks_of(&self, block: usize) -> usize {
        self.doc
            .as_ref()
            .and_then(|d| d.project.ladder.blocks.get(block))
            .map_or(0, |b| b.networks.len())
    }

    /// Makes sure the cursor's block has a network to edit in, and the cursor is inside it.
    /// An empty block gets a network first; that insertion is folded into the undo step of
    /// the gesture that needed it. `None` when there is no cell to edit (no project, not a
    /// ladder view, a read-only project with an empty block).
    pub fn ensure_network(&mut self) -> Option<Cursor> {
        let block = self.block()?;
        if self.networks_of(block) == 0 && self.edit(|l| l.insert_network(block, 0)) {
            self.merge_next = true;
        }
        let networks = self.networks_of(block);
        if networks == 0 {
            return None;
        }
        let mut c = self.cursor;
        c.block = block;
        c.network = c.network.min(networks - 1);
        c.row = c.row.min(self.rows_of(block, c.network).saturating_sub(1));
        c.col = c.col.min(self.width());
        self.cursor = c;
        Some(c)
    }

    /// The wires that join a new coil or box at `at` (output column) to the last element
    /// left of it.
    pub fn wires_to_output(ladder: &Ladder, at: Cursor) -> Vec<Edit> {
        // A coil or box is joined to what stands left of it by wire, as GSKLadder draws it.
        let row = &ladder.blocks[at.block].networks[at.network].rows[at.row];
        let last = (0..ladder.width)
            .rev()
            .find(|c| row.cells[*c] != Cell::Empty);
        let from = last.map_or(ladder.width, |c| c + 1);
        (from..ladder.width)
            .map(|col| Edit::SetCell {
                at: Cursor { col, ..at },
                cell: Cell::Wire,
            })
            .collect()
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
        let project = &doc.project;
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
        self.output = lines;
        // The same search again steps past the cursor; a new one may start on it.
        let again = self.last_find == text;
        let c = self.cursor;
        let next = hits
            .iter()
            .find(|h| if again { **h > c } else { **h >= c })
            .or(hits.first())
            .copied();
        self.last_find = text.to_string();
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
            let rows = self.tables.rows_in(sheet, &doc.project);
            let row = text
                .trim()
                .parse::<usize>()
                .map_err(|_| Msg::GoToRowUsage.text(lang).to_string())?;
            if row == 0 || !self.tables.go_to_row(sheet, row - 1, &doc.project) {
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
        self.cursor = Cursor {
            block,
            network: network - 1,
            row: row - 1,
            col: 0,
        };
        self.jump_to = Some(network - 1);
        Ok(())
    }

    /// Ctrl+H: `FROM TO`.
    pub fn replace(&mut self, text: &str) -> Result<(), String> {
        let lang = self.settings.lang;
        let mut words = text.split_whitespace();
        let (Some(from), Some(to), None) = (words.next(), words.next(), words.next()) else {
            return Err(Msg::ReplaceUsage.text(lang).into());
        };
        let query = Query::parse(from)
            .ok_or_else(|| format!("`{from}`: {}", Msg::NothingToFind.text(lang)))?;
        let to = Operand::parse(to).map_err(|e| e.to_string())?;
        let Some(doc) = self.doc.as_ref() else {
            return Ok(());
        };
        let (edit, done, skipped) = find::replace(&doc.project, &query, &to);
        if done > 0 {
            self.edit(|l| l.apply(edit));
        }
        self.output.push(OutputLine {
            text: format!(
                "{done} {}, {skipped} {}",
                Msg::Replaced.text(lang),
                Msg::SkippedInvalid.text(lang)
            ),
            error: false,
            target: None,
        });
        Ok(())
    }

    /// Places what the prompt describes at the cursor.
    pub fn place(&mut self, kind: PlaceKind, text: &str) -> Result<(), String> {
        match kind {
            PlaceKind::Find => return self.find(text),
            PlaceKind::Replace => return self.replace(text),
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
        let operand = |t: &str| Operand::parse(t).map_err(|e| e.to_string());
        // A typing error refuses before anything changes (no network added for nothing).
        if matches!(
            kind,
            PlaceKind::Contact { .. } | PlaceKind::Coil { .. } | PlaceKind::Parallel { .. }
        ) {
            operand(text)?;
        }
        let Some(at) = self.ensure_network() else {
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
                let ok = if matches!(kind, PlaceKind::Parallel { .. }) {
                    self.edit(|l| l.parallel_contact(at, cell))
                } else {
                    self.edit(|l| l.place(at, cell))
                };
                if ok {
                    self.cursor = Cursor {
                        col: at.col + 1,
                        ..at
                    };
                }
            }
            PlaceKind::Find
            | PlaceKind::Replace
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
                let ok = self.edit(|l| {
                    let mut edits = LadderApp::wires_to_output(l, at);
                    edits.push(Edit::SetCell { at, cell });
                    l.apply(Edit::Batch(edits))
                });
                if ok {
                    self.cursor = at;
                }
            }
        }
        Ok(())
    }

    /// Shift+arrow: the selection grows from where it started to the moved cursor.
    fn extend_by(&mut self, dr: i32, dc: i32) {
        let selection = self.selection;
        let from = self.cursor;
        self.move_cursor(dr, dc);
        let to = self.cursor;
        self.selection = selection;
        if selection.is_none() {
            self.cursor = from;
        }
        self.extend_selection(to);
    }

    fn move_cursor(&mut self, dr: i32, dc: i32) {
        let Some(block) = self.block() else { return };
        let mut c = self.cursor;
        c.block = block;
        let width = self.width() as i32;
        self.selection = None;
        c.col = (c.col as i32 + dc).clamp(0, width) as usize;
        let rows = self.rows_of(block, c.network) as i32;
        let row = c.row as i32 + dr;
        if row < 0 && c.network > 0 {
            c.network -= 1;
            c.row = self.rows_of(block, c.network).saturating_sub(1);
        } else if row >= rows && c.network + 1 < self.networks_of(block) {
            c.network += 1;
            c.row = 0;
        } else {
            c.row = row.clamp(0, (rows - 1).max(0)) as usize;
        }
        self.cursor = c;
        self.jump_to = Some(c.network);
    }

    /// The editing keys, when no text field has the keyboard.
    pub fn keys(&mut self, ctx: &egui::Context) {
        if self.prompt.is_some()
            || self.function_dialog.is_some()
            || self.question.is_some()
            || ctx.egui_wants_keyboard_input()
        {
            return;
        }
        let key = |m: Modifiers, k: Key| ctx.input_mut(|i| i.consume_key(m, k));
        let open = |kind| {
            Some(Prompt {
                kind,
                text: String::new(),
                error: None,
            })
        };
        // The most specific combination first: Shift+F1 before F1.
        if key(Modifiers::SHIFT, Key::F1) {
            self.prompt = open(PlaceKind::Contact { negated: true });
        } else if key(Modifiers::NONE, Key::F1) {
            self.prompt = open(PlaceKind::Contact { negated: false });
        } else if key(Modifiers::SHIFT, Key::F2) {
            self.prompt = open(PlaceKind::Coil { negated: true });
        } else if key(Modifiers::NONE, Key::F2) {
            self.prompt = open(PlaceKind::Coil { negated: false });
        } else if key(Modifiers::NONE, Key::F3) {
            self.open_function_dialog();
        } else if key(Modifiers::SHIFT, Key::F6) {
            self.prompt = open(PlaceKind::Parallel { negated: true });
        } else if key(Modifiers::NONE, Key::F6) {
            self.prompt = open(PlaceKind::Parallel { negated: false });
        } else if key(Modifiers::NONE, Key::F4) {
            self.wire();
        } else if key(Modifiers::NONE, Key::F5) {
            self.link();
        } else if key(Modifiers::NONE, Key::Delete) {
            self.run_command(super::pointer::Command::Delete);
        } else if key(Modifiers::COMMAND, Key::X)
            || ctx.input(|i| i.events.iter().any(|e| matches!(e, egui::Event::Cut)))
        {
            self.cut();
            self.copy_to_system(ctx);
        } else if key(Modifiers::COMMAND, Key::C)
            || ctx.input(|i| i.events.iter().any(|e| matches!(e, egui::Event::Copy)))
        {
            self.copy();
            self.copy_to_system(ctx);
        } else if key(Modifiers::COMMAND, Key::V)
            || ctx.input(|i| i.events.iter().any(|e| matches!(e, egui::Event::Paste(_))))
        {
            self.paste();
        } else if key(Modifiers::COMMAND, Key::E) {
            self.copy_row();
            self.copy_to_system(ctx);
        } else if key(Modifiers::NONE, Key::Escape) {
            self.selection = None;
        } else if key(Modifiers::COMMAND, Key::T) {
            self.insert_row(false);
        } else if key(Modifiers::COMMAND, Key::R) {
            self.insert_row(true);
        } else if key(Modifiers::COMMAND, Key::U) {
            self.insert_network(false);
        } else if key(Modifiers::COMMAND, Key::I) {
            self.insert_network(true);
        } else if key(Modifiers::COMMAND, Key::F) {
            self.prompt = Some(Prompt {
                kind: PlaceKind::Find,
                text: self.last_find.clone(),
                error: None,
            });
        } else if key(Modifiers::COMMAND, Key::H) {
            self.prompt = open(PlaceKind::Replace);
        } else if key(Modifiers::COMMAND, Key::G) {
            self.prompt = open(PlaceKind::GoTo);
        } else if key(Modifiers::COMMAND, Key::Z) {
            self.undo();
        } else if key(Modifiers::COMMAND, Key::Y) {
            self.redo();
        } else if key(Modifiers::COMMAND, Key::S) {
            self.save();
        } else if key(Modifiers::COMMAND, Key::N) {
            self.request(super::files::Action::New);
        } else if key(Modifiers::COMMAND, Key::O) {
            self.request(super::files::Action::OpenDialog);
        } else if key(Modifiers::SHIFT, Key::ArrowLeft) {
            self.extend_by(0, -1);
        } else if key(Modifiers::SHIFT, Key::ArrowRight) {
            self.extend_by(0, 1);
        } else if key(Modifiers::SHIFT, Key::ArrowUp) {
            self.extend_by(-1, 0);
        } else if key(Modifiers::SHIFT, Key::ArrowDown) {
            self.extend_by(1, 0);
        } else if key(Modifiers::NONE, Key::ArrowLeft) {
            self.move_cursor(0, -1);
        } else if key(Modifiers::NONE, Key::ArrowRight) {
            self.move_cursor(0, 1);
        } else if key(Modifiers::NONE, Key::ArrowUp) {
            self.move_cursor(-1, 0);
        } else if key(Modifiers::NONE, Key::ArrowDown) {
            self.move_cursor(1, 0);
        }
    }

    /// The ladder edit toolbar: each button does what its key does, at the cursor.
    pub fn toolbar_ui(&mut self, ui: &mut egui::Ui) {
        let lang = self.settings.lang;
        // The basic toolbar and the ladder view toolbar (manual §3.3).
        ui.horizontal(|ui| {
            let basic: [ToolbarAction; 10] = [
                (Msg::New, "Ctrl+N", |a| a.request(super::files::Action::New)),
                (Msg::Open, "Ctrl+O", |a| {
                    a.request(super::files::Action::OpenDialog)
                }),
                (Msg::Save, "Ctrl+S", LadderApp::save),
                (Msg::Cut, "Ctrl+X", LadderApp::cut),
                (Msg::Copy, "Ctrl+C", |a| {
                    a.copy();
                }),
                (Msg::Paste, "Ctrl+V", LadderApp::paste),
                (Msg::Undo, "Ctrl+Z", LadderApp::undo),
                (Msg::Redo, "Ctrl+Y", LadderApp::redo),
                (Msg::GoTo, "Ctrl+G", |a| {
                    a.prompt = Some(Prompt {
                        kind: PlaceKind::GoTo,
                        text: String::new(),
                        error: None,
                    })
                }),
                (Msg::Compile, "F9", LadderApp::compile),
            ];
            for (msg, keys, action) in basic {
                if ui.button(msg.text(lang)).on_hover_text(keys).clicked() {
                    action(self);
                }
            }
            ui.separator();
            egui::ComboBox::new("display", Msg::DisplayModeLabel.text(lang))
                .selected_text(match self.settings.display {
                    DisplayMode::Address => Msg::DisplayAddress.text(lang),
                    DisplayMode::Symbol => Msg::DisplaySymbol.text(lang),
                    DisplayMode::Both => Msg::DisplayBoth.text(lang),
                })
                .show_ui(ui, |ui| {
                    for (mode, msg) in [
                        (DisplayMode::Address, Msg::DisplayAddress),
                        (DisplayMode::Symbol, Msg::DisplaySymbol),
                        (DisplayMode::Both, Msg::DisplayBoth),
                    ] {
                        ui.selectable_value(&mut self.settings.display, mode, msg.text(lang));
                    }
                });
            egui::ComboBox::new("zoom", Msg::ZoomLabel.text(lang))
                .selected_text(format!("{}%", self.settings.zoom))
                .show_ui(ui, |ui| {
                    for z in super::settings::ZOOMS {
                        ui.selectable_value(&mut self.settings.zoom, z, format!("{z}%"));
                    }
                });
        });
        let open = |kind| {
            Some(Prompt {
                kind,
                text: String::new(),
                error: None,
            })
        };
        ui.horizontal(|ui| {
            let tools = [
                (Msg::ToolContact, "─┤ ├─  F1"),
                (Msg::ToolContactNc, "─┤/├─"),
                (Msg::ToolCoil, "─( )─  F2"),
                (Msg::ToolCoilN, "─(/)─"),
                (Msg::ToolFunction, "[ ]  F3"),
                (Msg::ToolWire, "──  F4"),
                (Msg::ToolLink, "│  F5"),
                (Msg::ToolParallel, "┤├  F6"),
                (Msg::ToolDelete, "Del"),
                (Msg::ToolRowBelow, "Ctrl+R"),
                (Msg::ToolNetworkBelow, "Ctrl+I"),
            ];
            ui.toggle_value(&mut self.pen, Msg::PenShort.text(lang))
                .on_hover_text(Msg::Pen.text(lang));
            for (msg, keys) in tools {
                let button = ui.button(msg.text(lang)).on_hover_text(keys);
                if !button.clicked() {
                    continue;
                }
                match msg {
                    Msg::ToolContact => self.prompt = open(PlaceKind::Contact { negated: false }),
                    Msg::ToolContactNc => self.prompt = open(PlaceKind::Contact { negated: true }),
                    Msg::ToolCoil => self.prompt = open(PlaceKind::Coil { negated: false }),
                    Msg::ToolCoilN => self.prompt = open(PlaceKind::Coil { negated: true }),
                    Msg::ToolFunction => self.open_function_dialog(),
                    Msg::ToolParallel => self.prompt = open(PlaceKind::Parallel { negated: false }),
                    Msg::ToolWire => self.wire(),
                    Msg::ToolLink => self.link(),
                    Msg::ToolDelete => {
                        if let Some(at) = self.ensure_network() {
                            self.edit(|l| l.delete_element(at));
                        }
                    }
                    Msg::ToolRowBelow => self.insert_row(true),
                    _ => self.insert_network(true),
                }
            }
        });
    }

    /// F4: a wire at the cursor.
    pub fn wire(&mut self) {
        if let Some(at) = self.ensure_network() {
            let at = Cursor {
                col: at.col.min(self.width() - 1),
                ..at
            };
            if self.edit(|l| l.place(at, Cell::Wire)) {
                self.cursor = Cursor {
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
        let on = !self.doc.as_ref().is_some_and(|d| {
            d.project.ladder.blocks[at.block].networks[at.network].link(at.row, at.col)
        });
        let rows = self.rows_of(at.block, at.network);
        self.edit(|l| {
            let mut edits = Vec::new();
            if at.row + 1 >= rows {
                edits.push(Edit::InsertRow {
                    block: at.block,
                    network: at.network,
                    row: at.row + 1,
                    content: ladder_engine::model::Row::empty(l.width),
                });
            }
            edits.push(Edit::SetLink { at, on });
            l.apply(Edit::Batch(edits))
        });
    }

    /// Ctrl+T (above) and Ctrl+R (below the cursor): a new empty row; the cursor goes to it.
    pub fn insert_row(&mut self, below: bool) {
        if let Some(at) = self.ensure_network() {
            let row = at.row + usize::from(below);
            if self.edit(|l| l.insert_row(at.block, at.network, row)) {
                self.cursor = Cursor { row, ..at };
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
            (self.cursor.network + usize::from(below)).min(n)
        };
        if self.edit(|l| l.insert_network(block, index)) {
            self.cursor = Cursor {
                block,
                network: index,
                row: 0,
                col: 0,
            };
            self.jump_to = Some(index);
        }
    }

    /// Replaces a table through the history (table editors call this for every change).
    pub fn edit_table(&mut self, edit: TableEdit) {
        if self.doc.as_ref().is_some_and(|d| d.read_only) {
            let text = Msg::ReadOnly.text(self.settings.lang).to_string();
            self.output.push(OutputLine {
                text,
                error: true,
                target: None,
            });
            return;
        }
        if let Some(doc) = self.doc.as_mut() {
            let inverse = doc.project.apply_table(edit);
            doc.history.record(inverse);
            doc.changed();
        }
    }

    /// Ctrl+Z.
    pub fn undo(&mut self) {
        if let Some(doc) = self.doc.as_mut()
            && doc.history.undo(&mut doc.project)
        {
            doc.changed();
        }
        self.clamp_ui_state();
    }

    /// Ctrl+Y.
    pub fn redo(&mut self) {
        if let Some(doc) = self.doc.as_mut()
            && doc.history.redo(&mut doc.project)
        {
            doc.changed();
        }
        self.clamp_ui_state();
    }

    /// The operand prompt: a text field; Enter places, Escape cancels.
    pub fn prompt_ui(&mut self, ui: &mut egui::Ui) {
        let Some(mut prompt) = self.prompt.take() else {
            return;
        };
        let lang = self.settings.lang;
        let mut close = false;
        let label = match prompt.kind {
            PlaceKind::NetworkTitle => Msg::TitlePrompt,
            PlaceKind::NetworkComment => Msg::CommentPrompt,
            PlaceKind::NewSub | PlaceKind::RenameSub(_) => Msg::SubPrompt,
            PlaceKind::BlockInfo(_) => Msg::BlockInfoPrompt,
            _ => Msg::Operand,
        };
        let completes = matches!(
            prompt.kind,
            PlaceKind::Contact { .. } | PlaceKind::Coil { .. } | PlaceKind::Parallel { .. }
        );
        let suggestions = if completes {
            self.suggestions(&prompt.text)
        } else {
            Vec::new()
        };
        // Tab takes the first suggestion (before the text field sees the key).
        if !suggestions.is_empty() && ui.input_mut(|i| i.consume_key(Modifiers::NONE, Key::Tab)) {
            prompt.text = suggestions[0].0.clone();
        }
        ui.horizontal(|ui| {
            let label = ui.label(label.text(lang));
            let r = ui
                .add(
                    egui::TextEdit::singleline(&mut prompt.text)
                        .hint_text(if completes { "X0002.1" } else { "" })
                        .desired_width(280.0),
                )
                .labelled_by(label.id);
            r.request_focus();
            if let Some(e) = &prompt.error {
                ui.colored_label(egui::Color32::from_rgb(0xc0, 0x10, 0x10), e);
            }
            if ui.input(|i| i.key_pressed(Key::Escape)) {
                close = true;
            } else if ui.input(|i| i.key_pressed(Key::Enter)) {
                let text = prompt.text.trim().to_string();
                match self.place(prompt.kind, &text) {
                    Ok(()) => close = true,
                    Err(e) => prompt.error = Some(e),
                }
            }
        });
        if !suggestions.is_empty() && !close {
            ui.horizontal_wrapped(|ui| {
                ui.label(Msg::Suggestions.text(lang));
                for (name, shown) in &suggestions {
                    if ui.small_button(shown).clicked() {
                        prompt.text = name.clone();
                    }
                }
            });
        }
        if !close {
            self.prompt = Some(prompt);
        }
    }

    /// Symbols for what has been typed: names starting with it first, then names or comments
    /// containing it; an address typed in full shows its symbol. Up to eight, as (text to
    /// enter, text shown).
    pub fn suggestions(&self, typed: &str) -> Vec<(String, String)> {
        let typed = typed.trim();
        let Some(doc) = self.doc.as_ref().filter(|_| !typed.is_empty()) else {
            return Vec::new();
        };
        let project = &doc.project;
        let lang = self.settings.lang.code();
        let lower = typed.to_lowercase();
        let shown = |s: &ladder_engine::model::Symbol| {
            let comment = s.comments.get(lang).map_or("", String::as_str);
            format!("{}  {}  {comment}", s.name, s.address)
                .trim_end()
                .to_string()
        };
        if let Ok(Operand::Addr(a)) = Operand::parse(typed) {
            return project
                .symbols()
                .filter(|s| s.address == a && !s.name.is_empty())
                .take(1)
                .map(|s| (a.to_string(), shown(s)))
                .collect();
        }
        let named = || project.symbols().filter(|s| !s.name.is_empty());
        let mut out: Vec<(String, String)> = named()
            .filter(|s| s.name.to_lowercase().starts_with(&lower))
            .map(|s| (s.name.clone(), shown(s)))
            .collect();
        out.extend(
            named()
                .filter(|s| {
                    !s.name.to_lowercase().starts_with(&lower)
                        && (s.name.to_lowercase().contains(&lower)
                            || s.comments
                                .values()
                                .any(|c| c.to_lowercase().contains(&lower)))
                })
                .map(|s| (s.name.clone(), shown(s))),
        );
        out.truncate(8);
        out
    }
}
