//! The mouse in the ladder view (click, Shift+click, double-click, drag, right-click), the
//! editing commands shared by the Edit menu and the right-click menu, and the subprogram
//! commands of the project tree.

use super::command::Command;
use super::editing::{Cursor, PlaceKind};
use super::i18n::Msg;
use super::ladder_view::{Hit, ViewEvents};
pub use super::place::BlockKey;
use super::place::View;
use super::selection::Selection;
use super::{LadderApp, OutputLine};
use crate::gui::online::OnlineState;
use crate::gui::properties::ElementProperties;
use ladder_engine::model::{Cell, Edit, parse_sub};

impl LadderApp {
    /// The cursor's cell when the shown block has it (deleting never adds a network first).
    pub fn existing_cursor(&mut self) -> Option<Cursor> {
        let View::Block(block) = self.view else {
            return None;
        };
        let ladder = &self.doc.as_ref()?.project().ladder;
        let n = ladder.blocks.get(block)?.networks.len();
        if n == 0 || self.on_new_row() {
            return None;
        }
        self.ensure_network()
    }

    /// Sets the net title or comment typed in the prompt.
    pub fn set_network_text(&mut self, title: Option<&str>, comment: Option<&str>) {
        if let Some(at) = self.ensure_network() {
            let Some(n) = self
                .ladder()
                .and_then(|l| l.blocks.get(at.block))
                .and_then(|b| b.networks.get(at.network))
            else {
                return;
            };
            let edit = Edit::SetNetworkText {
                block: at.block,
                network: at.network,
                title: title.map_or(n.title.clone(), str::to_string),
                comment: comment.map_or(n.comment.clone(), str::to_string),
            };
            self.edit(edit);
        }
    }

    /// Handles what the pointer did in the ladder view of `block`.
    pub fn pointer_events(&mut self, block: usize, ev: ViewEvents) {
        let cell = |network, row, col| Cursor {
            block,
            network,
            row,
            col,
        };
        if let Some(start) = ev.drag_start {
            self.edit.drag_from = Some(start);
        }
        if let (Some(a), Some(z)) = (self.edit.drag_from, ev.drag_now) {
            if self.edit.pen {
                if ev.drag_done {
                    self.draw_line(block, a, z);
                }
            } else if a != z {
                self.drag_select(block, a, z);
            }
        }
        if ev.drag_done {
            self.edit.drag_from = None;
        }
        if ev.drag_now.is_some() {
            // A drag is not also a click.
        } else if let Some((hit, mods)) = ev.click {
            match hit {
                Hit::Cell { network, row, col } => {
                    if mods.shift {
                        self.edit.extend_selection(cell(network, row, col));
                    } else {
                        self.edit.selection = None;
                        self.edit.cursor = cell(network, row, col);
                    }
                }
                Hit::Header { network } => {
                    let first = match self.edit.selection {
                        Some((b, Selection::Networks { networks })) if b == block && mods.shift => {
                            networks.0
                        }
                        _ if mods.shift && self.edit.cursor.block == block => {
                            self.edit.cursor.network
                        }
                        _ => network,
                    };
                    self.edit.selection = Some((
                        block,
                        Selection::Networks {
                            networks: (first, network),
                        },
                    ));
                    self.edit.cursor = cell(network, 0, 0);
                }
                Hit::Margin { network, row } => {
                    let first = match self.edit.selection {
                        Some((b, Selection::Rows { network: n, rows }))
                            if b == block && n == network && mods.shift =>
                        {
                            rows.0
                        }
                        _ => row,
                    };
                    self.edit.selection = Some((
                        block,
                        Selection::Rows {
                            network,
                            rows: (first, row),
                        },
                    ));
                    self.edit.cursor = cell(network, row, 0);
                }
            }
        }
        if let Some(hit) = ev.double_click {
            match hit {
                // Online, a double-click operates the element instead of editing it.
                Hit::Cell { network, row, col } if self.online.is_online() => self
                    .with(|o: &mut OnlineState, cx| o.operate_element(cx, cell(network, row, col))),
                // On the element's label (its address, symbol or comment): its properties.
                Hit::Cell { network, row, col }
                    if ev.double_click_at.is_some_and(|p| {
                        self.edit.geometry.labels.iter().any(|(r, _)| r.contains(p))
                    }) =>
                {
                    let at = Some(cell(network, row, col));
                    self.with(|p: &mut ElementProperties, cx| p.open(cx, at))
                }
                Hit::Cell { network, row, col } => self.edit_element(cell(network, row, col)),
                Hit::Header { network } => {
                    self.edit.cursor = cell(network, 0, 0);
                    self.ask(Command::NetworkTitle);
                }
                Hit::Margin { .. } => {}
            }
        }
        if let Some(Hit::Cell { network, row, col }) = ev.secondary {
            let inside = self
                .edit
                .selection
                .is_some_and(|(b, s)| b == block && s.contains(network, row, col));
            if !inside {
                self.edit.selection = None;
                self.edit.cursor = cell(network, row, col);
            }
        }
        if let Some(response) = ev.response {
            response.context_menu(|ui| self.commands_ui(ui));
        }
    }

    /// A drag without the pen selects cells (one network) or networks (across networks).
    fn drag_select(&mut self, block: usize, a: Hit, z: Hit) {
        let sel = match (a, z) {
            (
                Hit::Cell {
                    network: n,
                    row: r0,
                    col: c0,
                },
                Hit::Cell {
                    network,
                    row: r1,
                    col: c1,
                },
            ) if n == network => Selection::Cells {
                network,
                rows: (r0, r1),
                cols: (c0, c1),
            },
            _ => Selection::Networks {
                networks: (a.network(), z.network()),
            },
        };
        self.edit.selection = Some((block, sel));
        if let Hit::Cell { network, row, col } = z {
            self.edit.cursor = Cursor {
                block,
                network,
                row,
                col,
            };
        }
    }

    /// A drag with the pen: along a row, wires over the empty cells; down a column, vertical
    /// links at that column's left edge. One undo step.
    pub fn draw_line(&mut self, block: usize, a: Hit, z: Hit) {
        let (
            Hit::Cell {
                network,
                row: r0,
                col: c0,
            },
            Hit::Cell {
                network: n1,
                row: r1,
                col: c1,
            },
        ) = (a, z)
        else {
            return;
        };
        if network != n1 || (r0 == r1 && c0 == c1) {
            return;
        }
        let from = Cursor {
            block,
            network,
            row: r0,
            col: c0,
        };
        let to = Cursor {
            row: r1,
            col: c1,
            ..from
        };
        // The drag began on this frame's drawing, but the ladder may have changed since: a
        // line that no longer fits is not drawn.
        if let Some(Ok(edit)) = self.ladder().map(|l| l.plan_line(from, to)) {
            self.grouped(|app| app.edit(edit));
        }
    }

    /// Double-click: edit the element's operands (an empty cell takes a new contact, or a
    /// coil in the output column).
    pub fn edit_element(&mut self, at: Cursor) {
        self.edit.selection = None;
        self.edit.cursor = at;
        let Some(cell) = self
            .doc
            .as_ref()
            .and_then(|d| d.project().ladder.blocks.get(at.block))
            .and_then(|b| b.networks.get(at.network))
            .and_then(|n| n.cell(at.row, at.col))
            .cloned()
        else {
            return;
        };
        let width = self.doc.as_ref().map_or(0, |d| d.project().ladder.width);
        match cell {
            Cell::Contact { negated, operand } => {
                self.open_prompt(PlaceKind::Contact { negated }, operand.to_string())
            }
            Cell::Coil { negated, operand } => {
                self.open_prompt(PlaceKind::Coil { negated }, operand.to_string())
            }
            Cell::Box { .. } => self.edit_function_box(at),
            Cell::Empty | Cell::Wire if at.col == width => {
                self.open_prompt(PlaceKind::Coil { negated: false }, String::new())
            }
            Cell::Empty | Cell::Wire => {
                self.open_prompt(PlaceKind::Contact { negated: false }, String::new())
            }
        }
    }

    /// "View calls": every CALL and CALLU of subprogram `number`, in the output window.
    pub fn view_calls(&mut self, number: u16) {
        let lang = self.settings.lang;
        let Some(doc) = self.doc.as_ref() else { return };
        let project = doc.project();
        let mut lines: Vec<OutputLine> = ladder_engine::xref::calls_of(project, number)
            .into_iter()
            .map(|c| OutputLine {
                text: format!(
                    "{} N{:04} {}:  {} P{number:04}",
                    project.ladder.blocks[c.at.block].kind.label(),
                    c.at.network + 1,
                    c.at.row + 1,
                    c.op.name()
                ),
                error: false,
                target: Some(c.at),
            })
            .collect();
        lines.push(OutputLine {
            text: format!(
                "P{number:04}: {} {}",
                lines.len(),
                Msg::CallsFound.text(lang)
            ),
            error: false,
            target: None,
        });
        self.output.list(lines);
    }

    /// A new subprogram from `NUMBER [NAME]`, inserted in number order and shown.
    pub fn new_subprogram(&mut self, text: &str) -> Result<(), String> {
        let lang = self.settings.lang;
        let sub = |e| super::errors::sub_error(&e, lang);
        let project = self
            .doc
            .as_ref()
            .ok_or(Msg::NoProject.text(lang))?
            .project();
        let (number, name) = parse_sub(text, project.profile()).map_err(sub)?;
        let (index, edit) = project.ladder.plan_new_sub(number, name).map_err(sub)?;
        if self.try_edit(edit)? {
            // Blocks from `index` on moved down one place: their tabs follow.
            for v in &mut self.tabs {
                if let View::Block(b) = v
                    && *b >= index
                {
                    *b += 1;
                }
            }
            self.edit.selection = None;
            self.view = View::Block(index);
            self.edit.cursor = Cursor {
                block: index,
                network: 0,
                row: 0,
                col: 0,
            };
        }
        Ok(())
    }

    /// Renames (and renumbers) subprogram P`old` from `NUMBER [NAME]`.
    pub fn rename_subprogram(&mut self, old: u16, text: &str) -> Result<(), String> {
        let lang = self.settings.lang;
        let sub = |e| super::errors::sub_error(&e, lang);
        let project = self
            .doc
            .as_ref()
            .ok_or(Msg::NoProject.text(lang))?
            .project();
        let (number, name) = parse_sub(text, project.profile()).map_err(sub)?;
        let edit = project
            .ladder
            .plan_rename_sub(old, number, name)
            .map_err(sub)?;
        if self.try_edit(edit)?
            && let Some(i) = self
                .doc
                .as_ref()
                .and_then(|d| d.project().ladder.sub_index(number))
        {
            self.tabs.clear();
            self.view = View::Block(i);
        }
        Ok(())
    }

    /// Deletes subprogram block `index` (one undo step brings it back).
    pub fn delete_subprogram(&mut self, index: usize) {
        if self.edit(Edit::DeleteBlock { index }) {
            // Later blocks moved up one place: their tabs follow, the deleted one's closes.
            self.tabs.retain(|v| *v != View::Block(index));
            for v in &mut self.tabs {
                if let View::Block(b) = v
                    && *b > index
                {
                    *b -= 1;
                }
            }
            self.edit.selection = None;
            self.view = View::Block(1);
            self.edit.cursor = Cursor {
                block: 1,
                network: 0,
                row: 0,
                col: 0,
            };
        }
    }

    /// Sets a block's information text.
    pub fn set_block_info(&mut self, key: BlockKey, info: &str) -> Result<(), String> {
        let lang = self.settings.lang;
        let index = self
            .doc
            .as_ref()
            .and_then(|d| key.index(&d.project().ladder))
            .ok_or_else(|| Msg::NoSuchSub.text(lang).to_string())?;
        let kind = self
            .ladder()
            .map(|l| l.blocks[index].kind.clone())
            .ok_or_else(|| Msg::NoProject.text(lang).to_string())?;
        self.try_edit(Edit::SetBlockHeader {
            index,
            kind,
            info: info.to_string(),
        })?;
        Ok(())
    }

    /// One zoom step in or out about `at` (the mouse, for Ctrl+wheel), else the cursor cell.
    pub fn zoom_step(&mut self, up: bool, at: Option<egui::Pos2>) {
        self.zoom_to(super::settings::next_zoom(self.settings.zoom, up), at);
    }

    /// Zooms to `zoom` percent keeping the ladder point at `at` (else at the cursor cell's
    /// centre) where it is on screen: the element looked at does not run away.
    pub fn zoom_to(&mut self, zoom: u16, at: Option<egui::Pos2>) {
        self.settings.fit_width = false;
        if zoom == self.settings.zoom {
            return;
        }
        let g = &self.edit.geometry;
        let c = self.edit.cursor;
        let point = at.or_else(|| {
            matches!(self.view, View::Block(b) if b == c.block)
                .then(|| g.cell_rect(c.network, c.row, c.col))
                .flatten()
                .map(|r| r.center())
        });
        self.edit.anchor = point.and_then(|p| g.anchor_at(p)).map(|a| (a, 2));
        self.settings.zoom = zoom;
    }

    /// Keeps the cursor's place in block `b` (labelled `label`) of the open project.
    pub fn remember_cursor(&mut self, label: &str, b: usize) {
        let c = self.edit.cursor;
        let Some(path) = self.doc.as_ref().and_then(|d| d.path()) else {
            return;
        };
        if c.block != b {
            return;
        }
        let at = [c.network, c.row, c.col];
        if self.settings.cursors.get(path).and_then(|t| t.get(label)) != Some(&at) {
            let cursors = self.settings.cursors.entry(path.to_path_buf()).or_default();
            cursors.insert(label.to_string(), at);
        }
    }

    /// Keeps `top` as the first network on screen of block `label` of the open project.
    pub fn remember_top(&mut self, label: &str, top: usize) {
        let Some(path) = self.doc.as_ref().and_then(|d| d.path()) else {
            return;
        };
        if self.settings.tops.get(path).and_then(|t| t.get(label)) != Some(&top) {
            let tops = self.settings.tops.entry(path.to_path_buf()).or_default();
            tops.insert(label.to_string(), top);
        }
    }
}
