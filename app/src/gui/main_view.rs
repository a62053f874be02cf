//! The main area's ladder view and what its pointer does: clicks, drags and double-clicks
//! turned into the editor's actions and the other features' commands.

use super::LadderApp;
use super::command::Command;
use super::ladder_view::{Hit, ViewEvents};
use super::place::View;
use crate::gui::editor::EditState;
use crate::gui::editor::editing::Cursor;
use crate::gui::editor::selection::Selection;
use crate::gui::online::OnlineState;
use crate::gui::properties::ElementProperties;

impl LadderApp {
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
                    self.with(|o: &mut EditState, cx| o.draw_line(cx, block, a, z));
                }
            } else if a != z {
                self.with(|o: &mut EditState, cx| o.drag_select(cx, block, a, z));
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
                        crate::gui::editor::extend_selection(
                            &mut self.cursor,
                            &mut self.selection,
                            cell(network, row, col),
                        );
                    } else {
                        self.selection = None;
                        self.cursor = cell(network, row, col);
                    }
                }
                Hit::Header { network } => {
                    let first = match self.selection {
                        Some((b, Selection::Networks { networks })) if b == block && mods.shift => {
                            networks.0
                        }
                        _ if mods.shift && self.cursor.block == block => self.cursor.network,
                        _ => network,
                    };
                    self.selection = Some((
                        block,
                        Selection::Networks {
                            networks: (first, network),
                        },
                    ));
                    self.cursor = cell(network, 0, 0);
                }
                Hit::Margin { network, row } => {
                    let first = match self.selection {
                        Some((b, Selection::Rows { network: n, rows }))
                            if b == block && n == network && mods.shift =>
                        {
                            rows.0
                        }
                        _ => row,
                    };
                    self.selection = Some((
                        block,
                        Selection::Rows {
                            network,
                            rows: (first, row),
                        },
                    ));
                    self.cursor = cell(network, row, 0);
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
                Hit::Cell { network, row, col } => {
                    self.with(|o: &mut EditState, cx| o.edit_element(cx, cell(network, row, col)))
                }
                Hit::Header { network } => {
                    self.cursor = cell(network, 0, 0);
                    self.ask(Command::NetworkTitle);
                }
                Hit::Margin { .. } => {}
            }
        }
        if let Some(Hit::Cell { network, row, col }) = ev.secondary {
            let inside = self
                .selection
                .is_some_and(|(b, s)| b == block && s.contains(network, row, col));
            if !inside {
                self.selection = None;
                self.cursor = cell(network, row, col);
            }
        }
        if let Some(response) = ev.response {
            let mut asked = Vec::new();
            response.context_menu(|ui| {
                let mut menus = super::menus::Menus::new(self);
                menus.commands_ui(ui);
                asked = menus.asked;
            });
            self.pending.append(&mut asked);
        }
    }

    /// After a feature ran: a change it applied marks the tables' draft clock (undo takes
    /// back the later of a change and a draft); another document in place starts the editor
    /// over on it.
    pub(crate) fn after_feature(&mut self, changed: bool, replaced: bool) {
        if changed {
            self.last_change = self.tables.mark();
        }
        if replaced {
            self.reset_view();
        }
    }

    /// Back to level 1 at its first cell (where the manual's editor opens), with nothing
    /// pending from the old project.
    pub fn reset_view(&mut self) {
        // Another project (or none): the old one's machine stops with it.
        self.with(|o: &mut OnlineState, cx| o.go_offline(cx));
        self.view = View::Block(0);
        self.replace.dialog = None;
        self.tables = Default::default();
        self.online.machine = Default::default();
        // A coverage file belongs to its project.
        self.coverage = Default::default();
        // Nothing of the old project stays: cursor, selection, drag, tabs, and its output —
        // each document starts with its own (what opening it says comes after). The clipboard
        // stays: copying between projects is how networks move from one machine's ladder to
        // another's.
        self.edit.start_over();
        self.cursor = super::place::block_start(0);
        self.selection = None;
        self.tabs.clear();
        self.output.clear();
    }
}
