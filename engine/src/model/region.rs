//! Regions of a block and the clipboard (manual §3.2.2 剪切/复制/粘贴/复制一行/删除选择区域):
//! cells, rows or whole networks of one block; what copying a region holds; and the edits
//! that delete a region or paste a clip. The editor keeps which region is selected (UI
//! state); the rules of what cut, copy, paste and delete do live here, so they are tested
//! over text grids like the rest of the model.

use super::cell::Cell;
use super::edit::{CellRef, Edit, EditError};
use super::ladder::Ladder;
use super::network::{Network, NetworkId, Row};

/// A part of one block: what a selection covers, what cut, copy and delete act on.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Region {
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

impl Region {
    /// Whether the selection covers cell (network, row, col).
    pub fn contains(&self, network: usize, row: usize, col: usize) -> bool {
        match *self {
            Region::Cells {
                network: n,
                rows,
                cols,
            } => n == network && span(rows).contains(&row) && span(cols).contains(&col),
            Region::Rows { network: n, rows } => n == network && span(rows).contains(&row),
            Region::Networks { networks } => span(networks).contains(&network),
        }
    }

    /// Whether the selection covers all of network `n`.
    pub fn covers_network(&self, n: usize) -> bool {
        matches!(*self, Region::Networks { networks } if span(networks).contains(&n))
    }
}

/// What Ctrl+C or Ctrl+X put aside: a copy of a region, independent of where it came from.
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

impl Ladder {
    /// What a region of `block` holds, for the clipboard; `None` when it is not there.
    pub fn copy_region(&self, block: usize, sel: Region) -> Option<Clip> {
        let b = self.blocks.get(block)?;
        Some(match sel {
            Region::Cells {
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
            Region::Rows { network, rows } => {
                let n = b.networks.get(network)?;
                Clip::Rows(span(rows).filter_map(|r| n.rows.get(r).cloned()).collect())
            }
            Region::Networks { networks } => Clip::Networks(
                span(networks)
                    .filter_map(|i| b.networks.get(i).cloned())
                    .collect(),
            ),
        })
    }

    /// Deleting a region as one edit: cells emptied (with the links at their left edges),
    /// rows or networks removed. A network keeps at least one (empty) row and a block at least
    /// one network (manual §3.2.2); deleting the last row of a network clears the links of
    /// the row above that led into it.
    pub fn plan_delete_region(&self, block: usize, sel: Region) -> Edit {
        Edit::Batch(self.delete_edits(block, sel))
    }

    fn delete_edits(&self, block: usize, sel: Region) -> Vec<Edit> {
        let l = self;
        let mut edits = Vec::new();
        let Some(b) = l.blocks.get(block) else {
            return edits;
        };
        match sel {
            Region::Cells {
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
            Region::Rows { network, rows } => {
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
            Region::Networks { networks } => {
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

    /// Pasting a clip at `at` as one edit: cells over the rectangle from `at` (rows added
    /// below the network's end as needed), rows below `at`'s row, networks below `at`'s
    /// network with new identities. Refused when `at` is not in the ladder.
    pub fn plan_paste(&self, at: CellRef, clip: Clip) -> Result<Edit, EditError> {
        let l = self;
        let mut edits = Vec::new();
        let n = l
            .blocks
            .get(at.block)
            .and_then(|b| b.networks.get(at.network))
            .ok_or(EditError::NoSuchPlace(super::edit::Missing::Network))?;
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
        Ok(Edit::Batch(edits))
    }
}
