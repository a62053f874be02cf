//! The mouse in the ladder view (click, Shift+click, double-click, drag, right-click), the
//! editing commands shared by the Edit menu and the right-click menu, and the subprogram
//! commands of the project tree.

use crate::gui::OutputLine;
use crate::gui::context::Context;
use crate::gui::editor::EditState;
use crate::gui::editor::editing::{Cursor, PlaceKind};
use crate::gui::editor::selection::Selection;
use crate::gui::i18n::Msg;
use crate::gui::ladder_view::Hit;
pub use crate::gui::place::BlockKey;
use crate::gui::place::View;
use ladder_engine::model::{Cell, Edit, parse_sub};

impl EditState {
    /// The cursor's cell when the shown block has it (deleting never adds a network first).
    pub fn existing_cursor(&mut self, cx: &mut Context<'_>) -> Option<Cursor> {
        let View::Block(block) = *cx.view else {
            return None;
        };
        let ladder = &cx.doc()?.project().ladder;
        let n = ladder.blocks.get(block)?.networks.len();
        if n == 0 || self.on_new_row(cx) {
            return None;
        }
        self.ensure_network(cx)
    }

    /// Sets the net title or comment typed in the prompt.
    pub fn set_network_text(
        &mut self,
        cx: &mut Context<'_>,
        title: Option<&str>,
        comment: Option<&str>,
    ) {
        if let Some(at) = self.ensure_network(cx) {
            let Some(n) = self
                .ladder(cx)
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
            self.edit(cx, edit);
        }
    }

    /// A drag without the pen selects cells (one network) or networks (across networks).
    pub(crate) fn drag_select(&mut self, cx: &mut Context<'_>, block: usize, a: Hit, z: Hit) {
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
        *cx.selection = Some((block, sel));
        if let Hit::Cell { network, row, col } = z {
            *cx.cursor = Cursor {
                block,
                network,
                row,
                col,
            };
        }
    }

    /// A drag with the pen: along a row, wires over the empty cells; down a column, vertical
    /// links at that column's left edge. One undo step.
    pub fn draw_line(&mut self, cx: &mut Context<'_>, block: usize, a: Hit, z: Hit) {
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
        if let Some(Ok(edit)) = self.ladder(cx).map(|l| l.plan_line(from, to)) {
            cx.begin_group();
            self.edit(cx, edit);
            cx.end_group();
        }
    }

    /// Double-click: edit the element's operands (an empty cell takes a new contact, or a
    /// coil in the output column).
    pub fn edit_element(&mut self, cx: &mut Context<'_>, at: Cursor) {
        *cx.selection = None;
        *cx.cursor = at;
        let Some(cell) = cx
            .doc()
            .and_then(|d| d.project().ladder.blocks.get(at.block))
            .and_then(|b| b.networks.get(at.network))
            .and_then(|n| n.cell(at.row, at.col))
            .cloned()
        else {
            return;
        };
        let width = cx.doc().map_or(0, |d| d.project().ladder.width);
        match cell {
            Cell::Contact { negated, operand } => {
                self.open_prompt(PlaceKind::Contact { negated }, operand.to_string())
            }
            Cell::Coil { negated, operand } => {
                self.open_prompt(PlaceKind::Coil { negated }, operand.to_string())
            }
            Cell::Box { .. } => self.edit_function_box(cx, at),
            Cell::Empty | Cell::Wire if at.col == width => {
                self.open_prompt(PlaceKind::Coil { negated: false }, String::new())
            }
            Cell::Empty | Cell::Wire => {
                self.open_prompt(PlaceKind::Contact { negated: false }, String::new())
            }
        }
    }

    /// "View calls": every CALL and CALLU of subprogram `number`, in the output window.
    pub fn view_calls(&mut self, cx: &mut Context<'_>, number: u16) {
        let lang = cx.settings.lang;
        let Some(doc) = cx.doc() else { return };
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
        cx.output.list(lines);
    }

    /// A new subprogram from `NUMBER [NAME]`, inserted in number order and shown.
    pub fn new_subprogram(&mut self, cx: &mut Context<'_>, text: &str) -> Result<(), String> {
        let lang = cx.settings.lang;
        let sub = |e| crate::gui::errors::sub_error(&e, lang);
        let project = cx.doc().ok_or(Msg::NoProject.text(lang))?.project();
        let (number, name) = parse_sub(text, project.profile()).map_err(sub)?;
        let (index, edit) = project.ladder.plan_new_sub(number, name).map_err(sub)?;
        if cx.apply(edit)? {
            // Blocks from `index` on moved down one place: their tabs follow.
            for v in cx.tabs.iter_mut() {
                if let View::Block(b) = v
                    && *b >= index
                {
                    *b += 1;
                }
            }
            *cx.selection = None;
            *cx.view = View::Block(index);
            *cx.cursor = Cursor {
                block: index,
                network: 0,
                row: 0,
                col: 0,
            };
        }
        Ok(())
    }

    /// Renames (and renumbers) subprogram P`old` from `NUMBER [NAME]`.
    pub fn rename_subprogram(
        &mut self,
        cx: &mut Context<'_>,
        old: u16,
        text: &str,
    ) -> Result<(), String> {
        let lang = cx.settings.lang;
        let sub = |e| crate::gui::errors::sub_error(&e, lang);
        let project = cx.doc().ok_or(Msg::NoProject.text(lang))?.project();
        let (number, name) = parse_sub(text, project.profile()).map_err(sub)?;
        let edit = project
            .ladder
            .plan_rename_sub(old, number, name)
            .map_err(sub)?;
        if cx.apply(edit)?
            && let Some(i) = cx.doc().and_then(|d| d.project().ladder.sub_index(number))
        {
            cx.tabs.clear();
            *cx.view = View::Block(i);
        }
        Ok(())
    }

    /// Deletes subprogram block `index` (one undo step brings it back).
    pub fn delete_subprogram(&mut self, cx: &mut Context<'_>, index: usize) {
        if self.edit(cx, Edit::DeleteBlock { index }) {
            // Later blocks moved up one place: their tabs follow, the deleted one's closes.
            cx.tabs.retain(|v| *v != View::Block(index));
            for v in cx.tabs.iter_mut() {
                if let View::Block(b) = v
                    && *b > index
                {
                    *b -= 1;
                }
            }
            *cx.selection = None;
            *cx.view = View::Block(1);
            *cx.cursor = Cursor {
                block: 1,
                network: 0,
                row: 0,
                col: 0,
            };
        }
    }

    /// Sets a block's information text.
    pub fn set_block_info(
        &mut self,
        cx: &mut Context<'_>,
        key: BlockKey,
        info: &str,
    ) -> Result<(), String> {
        let lang = cx.settings.lang;
        let index = cx
            .doc()
            .and_then(|d| key.index(&d.project().ladder))
            .ok_or_else(|| Msg::NoSuchSub.text(lang).to_string())?;
        let kind = self
            .ladder(cx)
            .map(|l| l.blocks[index].kind.clone())
            .ok_or_else(|| Msg::NoProject.text(lang).to_string())?;
        cx.apply(Edit::SetBlockHeader {
            index,
            kind,
            info: info.to_string(),
        })?;
        Ok(())
    }

    /// One zoom step in or out about `at` (the mouse, for Ctrl+wheel), else the cursor cell.
    pub fn zoom_step(&mut self, cx: &mut Context<'_>, up: bool, at: Option<egui::Pos2>) {
        self.zoom_to(
            cx,
            crate::gui::settings::next_zoom(cx.settings.zoom, up),
            at,
        );
    }

    /// Zooms to `zoom` percent keeping the ladder point at `at` (else at the cursor cell's
    /// centre) where it is on screen: the element looked at does not run away.
    pub fn zoom_to(&mut self, cx: &mut Context<'_>, zoom: u16, at: Option<egui::Pos2>) {
        cx.settings.fit_width = false;
        if zoom == cx.settings.zoom {
            return;
        }
        let g = &self.geometry;
        let c = *cx.cursor;
        let point = at.or_else(|| {
            matches!(*cx.view, View::Block(b) if b == c.block)
                .then(|| g.cell_rect(c.network, c.row, c.col))
                .flatten()
                .map(|r| r.center())
        });
        self.anchor = point.and_then(|p| g.anchor_at(p)).map(|a| (a, 2));
        cx.settings.zoom = zoom;
    }

    /// Keeps the cursor's place in block `b` (labelled `label`) of the open project.
    pub fn remember_cursor(&mut self, cx: &mut Context<'_>, label: &str, b: usize) {
        let c = *cx.cursor;
        let Some(path) = cx.doc().and_then(|d| d.path()) else {
            return;
        };
        if c.block != b {
            return;
        }
        let at = [c.network, c.row, c.col];
        if cx.settings.cursors.get(path).and_then(|t| t.get(label)) != Some(&at) {
            let cursors = cx.settings.cursors.entry(path.to_path_buf()).or_default();
            cursors.insert(label.to_string(), at);
        }
    }

    /// Keeps `top` as the first network on screen of block `label` of the open project.
    pub fn remember_top(&mut self, cx: &mut Context<'_>, label: &str, top: usize) {
        let Some(path) = cx.doc().and_then(|d| d.path()) else {
            return;
        };
        if cx.settings.tops.get(path).and_then(|t| t.get(label)) != Some(&top) {
            let tops = cx.settings.tops.entry(path.to_path_buf()).or_default();
            tops.insert(label.to_string(), top);
        }
    }
}
