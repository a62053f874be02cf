//! The ladder editor's own commands: placing and deleting elements, wires, rows and
//! networks, the clipboard, moving the cursor, subprograms and the zoom. The editor's
//! dispatch hands every command it does not run itself to [`EditState::execute`].

use crate::gui::command::Command;
use crate::gui::context::Context;
use crate::gui::editor::EditState;
use crate::gui::editor::editing::PlaceKind;
use crate::gui::editor::selection::Selection;
use crate::gui::place::View;

impl EditState {
    /// Runs a ladder editing command.
    pub fn execute(&mut self, cx: &mut Context<'_>, c: Command) {
        match c {
            Command::Contact => self.open_prompt(PlaceKind::Contact { negated: false }, "".into()),
            Command::ContactNc => self.open_prompt(PlaceKind::Contact { negated: true }, "".into()),
            Command::Coil => self.open_prompt(PlaceKind::Coil { negated: false }, "".into()),
            Command::CoilN => self.open_prompt(PlaceKind::Coil { negated: true }, "".into()),
            Command::Function => self.open_function_dialog(cx),
            Command::Wire => self.wire(cx),
            Command::Link => self.link(cx),
            Command::Parallel | Command::ParallelNc => {
                // Refused before any typing when there is nothing above to be parallel with.
                let at = *cx.cursor;
                match ladder_engine::model::Ladder::can_parallel(at) {
                    Err(e) if *cx.view == View::Block(at.block) => self.report_edit_error(cx, &e),
                    _ => {
                        let negated = c == Command::ParallelNc;
                        self.open_prompt(PlaceKind::Parallel { negated }, "".into())
                    }
                }
            }
            Command::Cut => {
                self.cut(cx);
                self.copy_to_clipboard(cx);
            }
            Command::Copy => {
                self.copy(cx);
                self.copy_to_clipboard(cx);
            }
            Command::Paste => self.paste(cx),
            Command::CopyRow => {
                self.copy_row(cx);
                self.copy_to_clipboard(cx);
            }
            Command::Delete => {
                // The selection when there is one, else the element at the cursor; never a
                // network added to an empty block only to delete nothing in it.
                if cx.selection.is_some() {
                    self.delete_selection(cx);
                } else if let Some(at) = self.existing_cursor(cx) {
                    self.edit(
                        cx,
                        ladder_engine::model::Edit::SetCell {
                            at,
                            cell: ladder_engine::model::Cell::Empty,
                        },
                    );
                }
            }
            Command::DeleteLink => {
                if let Some(at) = self.existing_cursor(cx) {
                    self.edit(cx, ladder_engine::model::Edit::SetLink { at, on: false });
                }
            }
            Command::InsertRowAbove => self.insert_row(cx, false),
            Command::InsertRowBelow => self.insert_row(cx, true),
            Command::DeleteRow => self.delete_at_cursor(cx, |at| Selection::Rows {
                network: at.network,
                rows: (at.row, at.row),
            }),
            Command::InsertNetworkAbove => self.insert_network(cx, false),
            Command::InsertNetworkBelow => self.insert_network(cx, true),
            Command::DeleteNetwork => self.delete_at_cursor(cx, |at| Selection::Networks {
                networks: (at.network, at.network),
            }),
            Command::NetworkTitle | Command::NetworkComment => {
                if let Some(at) = self.ensure_network(cx)
                    && let Some(n) = cx
                        .doc()
                        .and_then(|d| d.project().ladder.blocks.get(at.block))
                        .and_then(|b| b.networks.get(at.network))
                {
                    let (kind, text) = if c == Command::NetworkTitle {
                        (PlaceKind::NetworkTitle, n.title.clone())
                    } else {
                        (PlaceKind::NetworkComment, n.comment.clone())
                    };
                    self.open_prompt(kind, text);
                }
            }
            Command::Pen => self.pen = !self.pen,
            Command::ZoomIn => self.zoom_step(cx, true, None),
            Command::ZoomOut => self.zoom_step(cx, false, None),
            Command::ZoomTo(z) => self.zoom_to(cx, z, None),
            Command::NewSub => self.open_prompt(PlaceKind::NewSub, String::new()),
            Command::ViewCalls(n) => self.view_calls(cx, n),
            Command::RenameSub(n) => {
                let name = cx.doc().and_then(|d| {
                    let l = &d.project().ladder;
                    l.sub_index(n).map(|i| l.blocks[i].kind.clone())
                });
                if let Some(ladder_engine::model::BlockKind::Sub { number, name }) = name {
                    let text = format!("{number} {name}").trim().to_string();
                    self.open_prompt(PlaceKind::RenameSub(number), text);
                }
            }
            Command::DeleteSub(n) => {
                if let Some(i) = cx.doc().and_then(|d| d.project().ladder.sub_index(n)) {
                    self.delete_subprogram(cx, i);
                }
            }
            Command::BlockInfo(key) => {
                let info = cx.doc().and_then(|d| {
                    let l = &d.project().ladder;
                    key.index(l).map(|i| l.blocks[i].info.clone())
                });
                if let Some(info) = info {
                    self.open_prompt(PlaceKind::BlockInfo(key), info);
                }
            }
            Command::Move(d) => {
                let (dr, dc) = d.delta();
                self.move_cursor(cx, dr, dc);
            }
            Command::RowStart
            | Command::RowEnd
            | Command::PageUp
            | Command::PageDown
            | Command::BlockStart
            | Command::BlockEnd => self.navigate(cx, c),
            Command::Extend(d) => {
                let (dr, dc) = d.delta();
                self.extend_by(cx, dr, dc);
            }
            _ => {}
        }
    }

    /// What Ctrl+C, Ctrl+X or Ctrl+E put aside goes to the system clipboard too, as text.
    fn copy_to_clipboard(&self, cx: &Context<'_>) {
        if let Some(ctx) = cx.egui {
            self.copy_to_system(ctx);
        }
    }
}
