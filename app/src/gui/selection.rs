//! Selection and the clipboard (manual §3.2.2 剪切/复制/粘贴/复制一行/删除选择区域): cells,
//! rows or whole networks of one block. Selection and clipboard are UI state: never saved,
//! and every change they make goes through the engine's edits as one undo step.

use super::i18n::Msg;
use super::{LadderApp, OutputLine};
use ladder_engine::model::{Cell, CellRef, Edit, Ladder, Network, NetworkId, Row};

/// What is selected in one block.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Selection {
    /// A rectangle of cells in one network (inclusive bounds, any order).
    Cells {
        /// Network.
        network: usize,
        /// First and last row.
        rows: (usize, usize),
        /// First and last column.
        cols: (usize, usize),
    },
    /// Whole rows of one network.
    Rows {
        /// Network.
        network: usize,
        /// First and last row.
        rows: (usize, usize),
    },
    /// Whole networks.
    Networks {
        /// First and last network.
        networks: (usize, usize),
    },
}

fn span((a, b): (usize, usize)) -> std::ops::RangeInclusive<usize> {
    a.min(b)..=a.max(b)
}

impl Selection {
    /// Whether the selection covers cell (network, row, col).
    pub fn contains(&self, network: usize, row: usize, col: usize) -> bool {
        match *self {
            Selection::Cells {
                network: n,
                rows,
                cols,
            } => n == network && span(rows).contains(&row) && span(cols).contains(&col),
            Selection::Rows { network: n, rows } => n == network && span(rows).contains(&row),
            Selection::Networks { networks } => span(networks).contains(&network),
        }
    }

    /// Whether the selection covers all of network `n`.
    pub fn covers_network(&self, n: usize) -> bool {
        matches!(*self, Selection::Networks { networks } if span(networks).contains(&n))
    }
}

/// What Ctrl+C or Ctrl+X put aside.
#[derive(Clone, Debug, PartialEq)]
pub enum Clip {
    /// A rectangle of cells; `links[r][j]` is the link at junction `col0 + j` from row `r`
    /// down, for the junctions strictly inside the rectangle.
    Cells {
        /// The cells, row by row.
        cells: Vec<Vec<Cell>>,
        /// Links inside the rectangle.
        links: Vec<Vec<bool>>,
    },
    /// Whole rows.
    Rows(Vec<Row>),
    /// Whole networks.
    Networks(Vec<Network>),
}

impl LadderApp {
    fn ladder(&self) -> Option<&Ladder> {
        self.doc.as_ref().map(|d| &d.project.ladder)
    }

    fn note(&mut self, text: String, error: bool) {
        self.output.push(OutputLine {
            text,
            error,
            target: None,
        });
    }

    /// The selection in the shown block, or the cursor's cell when nothing is selected.
    pub fn effective_selection(&self) -> Option<(usize, Selection)> {
        let block = match self.view {
            super::tree::View::Block(b) => b,
            _ => return None,
        };
        match self.selection {
            Some((b, s)) if b == block => Some((b, s)),
            _ => {
                let c = self.cursor;
                (c.block == block).then_some((
                    block,
                    Selection::Cells {
                        network: c.network,
                        rows: (c.row, c.row),
                        cols: (c.col, c.col),
                    },
                ))
            }
        }
    }

    /// Extends the selection from the cursor to `to` (Shift+click, Shift+arrows): cells within
    /// one network, whole networks across networks.
    pub fn extend_selection(&mut self, to: CellRef) {
        let from = match self.selection {
            Some((b, s)) if b == to.block => match s {
                Selection::Cells {
                    network,
                    rows,
                    cols,
                } => CellRef {
                    block: b,
                    network,
                    row: rows.0,
                    col: cols.0,
                },
                Selection::Rows { network, rows } => CellRef {
                    block: b,
                    network,
                    row: rows.0,
                    col: 0,
                },
                Selection::Networks { networks } => CellRef {
                    block: b,
                    network: networks.0,
                    row: 0,
                    col: 0,
                },
            },
            _ => self.cursor,
        };
        let sel = if from.network != to.network {
            Selection::Networks {
                networks: (from.network, to.network),
            }
        } else if matches!(self.selection, Some((_, Selection::Rows { .. }))) {
            Selection::Rows {
                network: to.network,
                rows: (from.row, to.row),
            }
        } else {
            Selection::Cells {
                network: to.network,
                rows: (from.row, to.row),
                cols: (from.col, to.col),
            }
        };
        self.selection = Some((to.block, sel));
        self.cursor = to;
    }

    /// What the selection holds, for the clipboard.
    fn clip_of(&self, block: usize, sel: Selection) -> Option<Clip> {
        let b = self.ladder()?.blocks.get(block)?;
        Some(match sel {
            Selection::Cells {
                network,
                rows,
                cols,
            } => {
                let n = b.networks.get(network)?;
                let (rows, cols) = (span(rows), span(cols));
                let rows: Vec<&Row> = rows.filter_map(|r| n.rows.get(r)).collect();
                Clip::Cells {
                    cells: rows
                        .iter()
                        .map(|r| {
                            cols.clone()
                                .filter_map(|c| r.cells.get(c).cloned())
                                .collect()
                        })
                        .collect(),
                    links: rows
                        .iter()
                        .map(|r| {
                            cols.clone()
                                .map(|c| r.links.get(c).copied().unwrap_or(false))
                                .collect()
                        })
                        .collect(),
                }
            }
            Selection::Rows { network, rows } => {
                let n = b.networks.get(network)?;
                Clip::Rows(span(rows).filter_map(|r| n.rows.get(r).cloned()).collect())
            }
            Selection::Networks { networks } => Clip::Networks(
                span(networks)
                    .filter_map(|i| b.networks.get(i).cloned())
                    .collect(),
            ),
        })
    }

    /// Ctrl+C: the selection (or the cursor's cell) to the clipboard.
    pub fn copy(&mut self) -> bool {
        let Some((block, sel)) = self.effective_selection() else {
            return false;
        };
        match self.clip_of(block, sel) {
            Some(clip) => {
                self.clipboard = Some(clip);
                true
            }
            None => false,
        }
    }

    /// Puts the clipboard's text on the system clipboard too: other programs get readable
    /// text, and the window system then sends Ctrl+V back to the editor (it only does so
    /// when the system clipboard holds text).
    pub fn copy_to_system(&self, ctx: &egui::Context) {
        if let Some(clip) = &self.clipboard {
            ctx.copy_text(clip_text(clip));
        }
    }

    /// Ctrl+E: the cursor's row to the clipboard.
    pub fn copy_row(&mut self) {
        let c = self.cursor;
        if let Some(clip) = self.clip_of(
            c.block,
            Selection::Rows {
                network: c.network,
                rows: (c.row, c.row),
            },
        ) {
            self.clipboard = Some(clip);
        }
    }

    /// Ctrl+X: copy, then delete the selection.
    pub fn cut(&mut self) {
        if self.copy() {
            self.delete_selection();
        }
    }

    /// Delete with a selection: cells emptied, rows or networks removed, as one undo step. A
    /// network keeps at least one (empty) row, a block at least one network (manual §3.2.2).
    pub fn delete_selection(&mut self) {
        let Some((block, sel)) = self.effective_selection() else {
            return;
        };
        self.edit(|l| {
            let edits = delete_edits(l, block, sel);
            l.apply(Edit::Batch(edits))
        });
        self.selection = None;
        // The cursor goes to where the deleted part began, so Ctrl+V puts it back.
        let networks = self.ladder().map_or(0, |l| l.blocks[block].networks.len());
        let c = &mut self.cursor;
        match sel {
            Selection::Cells {
                network,
                rows,
                cols,
            } => {
                c.network = network;
                c.row = rows.0.min(rows.1);
                c.col = cols.0.min(cols.1);
            }
            Selection::Rows { network, rows } => {
                c.network = network;
                c.row = rows.0.min(rows.1).saturating_sub(1);
            }
            Selection::Networks { networks: ns } => {
                c.network = ns.0.min(ns.1).saturating_sub(1);
                c.row = 0;
            }
        }
        c.network = c.network.min(networks.saturating_sub(1));
    }

    /// Ctrl+V: cells over the cursor's rectangle, rows below the cursor's row, networks below
    /// the cursor's network.
    pub fn paste(&mut self) {
        let lang = self.settings.lang;
        let Some(clip) = self.clipboard.clone() else {
            self.note(Msg::ClipboardEmpty.text(lang).into(), false);
            return;
        };
        let Some(at) = self.ensure_network() else {
            return;
        };
        let ok = self.edit(|l| {
            let edits = paste_edits(l, at, clip);
            l.apply(Edit::Batch(edits))
        });
        if ok {
            self.selection = None;
        }
    }
}

/// A clip as text: one line per row, cells separated by tabs.
fn clip_text(clip: &Clip) -> String {
    fn cell_text(c: &Cell) -> String {
        match c {
            Cell::Empty => String::new(),
            Cell::Wire => "—".into(),
            Cell::Contact { negated, operand } => {
                format!("{}{operand}", if *negated { "NC " } else { "NO " })
            }
            Cell::Coil { negated, operand } => {
                format!("{}{operand}", if *negated { "OUTN " } else { "OUT " })
            }
            Cell::Box { op, operands } => ladder_engine::il::instr_text(*op, operands),
        }
    }
    fn row_text(cells: &[Cell]) -> String {
        cells.iter().map(cell_text).collect::<Vec<_>>().join("\t")
    }
    match clip {
        Clip::Cells { cells, .. } => cells
            .iter()
            .map(|r| row_text(r))
            .collect::<Vec<_>>()
            .join("\n"),
        Clip::Rows(rows) => rows
            .iter()
            .map(|r| row_text(&r.cells))
            .collect::<Vec<_>>()
            .join("\n"),
        Clip::Networks(ns) => ns
            .iter()
            .map(|n| {
                let rows: Vec<String> = n.rows.iter().map(|r| row_text(&r.cells)).collect();
                format!("{}\n{}", n.title, rows.join("\n"))
            })
            .collect::<Vec<_>>()
            .join("\n\n"),
    }
}

/// The edits that delete a selection.
fn delete_edits(l: &Ladder, block: usize, sel: Selection) -> Vec<Edit> {
    let mut edits = Vec::new();
    let Some(b) = l.blocks.get(block) else {
        return edits;
    };
    match sel {
        Selection::Cells {
            network,
            rows,
            cols,
        } => {
            let Some(n) = b.networks.get(network) else {
                return edits;
            };
            for r in span(rows).filter(|r| *r < n.rows.len()) {
                for c in span(cols).filter(|c| *c <= l.width) {
                    let at = CellRef {
                        block,
                        network,
                        row: r,
                        col: c,
                    };
                    if n.rows[r].cells[c] != Cell::Empty {
                        edits.push(Edit::SetCell {
                            at,
                            cell: Cell::Empty,
                        });
                    }
                    // A link at the left edge of a deleted cell goes with it.
                    if n.link(r, c) {
                        edits.push(Edit::SetLink { at, on: false });
                    }
                }
            }
        }
        Selection::Rows { network, rows } => {
            let Some(n) = b.networks.get(network) else {
                return edits;
            };
            let doomed: Vec<usize> = span(rows).filter(|r| *r < n.rows.len()).collect();
            if doomed.len() == n.rows.len() {
                edits.push(Edit::InsertRow {
                    block,
                    network,
                    row: n.rows.len(),
                    content: Row::empty(l.width),
                });
            }
            // The rows above the last deleted one lose links that led into it.
            for r in doomed.iter().rev() {
                if *r > 0 && *r + 1 == n.rows.len() {
                    for (j, on) in n.rows[r - 1].links.iter().enumerate() {
                        if *on {
                            edits.push(Edit::SetLink {
                                at: CellRef {
                                    block,
                                    network,
                                    row: r - 1,
                                    col: j,
                                },
                                on: false,
                            });
                        }
                    }
                }
                edits.push(Edit::DeleteRow {
                    block,
                    network,
                    row: *r,
                });
            }
        }
        Selection::Networks { networks } => {
            let doomed: Vec<usize> = span(networks).filter(|i| *i < b.networks.len()).collect();
            for i in doomed.iter().rev() {
                edits.push(Edit::DeleteNetwork { block, index: *i });
            }
            if doomed.len() == b.networks.len() {
                edits.push(Edit::InsertNetwork {
                    block,
                    index: 0,
                    network: Box::new(l.new_network()),
                });
            }
        }
    }
    edits
}

/// The edits that paste a clip at `at`.
fn paste_edits(l: &Ladder, at: CellRef, clip: Clip) -> Vec<Edit> {
    let mut edits = Vec::new();
    let n = &l.blocks[at.block].networks[at.network];
    match clip {
        Clip::Cells { cells, links } => {
            // Rows the paste needs beyond the network's end come first.
            let need = at.row + cells.len();
            for r in n.rows.len()..need {
                edits.push(Edit::InsertRow {
                    block: at.block,
                    network: at.network,
                    row: r,
                    content: Row::empty(l.width),
                });
            }
            for (dr, row) in cells.iter().enumerate() {
                for (dc, cell) in row.iter().enumerate() {
                    edits.push(Edit::SetCell {
                        at: CellRef {
                            row: at.row + dr,
                            col: at.col + dc,
                            ..at
                        },
                        cell: cell.clone(),
                    });
                }
            }
            for (dr, row) in links.iter().enumerate() {
                for (dc, on) in row.iter().enumerate() {
                    let col = at.col + dc;
                    if *on && col > 0 && dr + 1 < cells.len() {
                        edits.push(Edit::SetLink {
                            at: CellRef {
                                row: at.row + dr,
                                col,
                                ..at
                            },
                            on: true,
                        });
                    }
                }
            }
        }
        Clip::Rows(rows) => {
            for (i, row) in rows.into_iter().enumerate() {
                edits.push(Edit::InsertRow {
                    block: at.block,
                    network: at.network,
                    row: at.row + 1 + i,
                    content: row,
                });
            }
        }
        Clip::Networks(networks) => {
            let first = l.new_network_id().0;
            for (i, mut net) in networks.into_iter().enumerate() {
                // Pasted networks are new networks: new identities.
                net.id = NetworkId(first + i as u64);
                edits.push(Edit::InsertNetwork {
                    block: at.block,
                    index: at.network + 1 + i,
                    network: Box::new(net),
                });
            }
        }
    }
    edits
}
