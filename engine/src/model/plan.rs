//! The ladder's editing gestures planned as data: each function reads the ladder and returns
//! the [`Edit`] that does the gesture, without changing anything. An editor applies the edit
//! through its one door (which records the inverse for undo); the `&mut` helpers in `edit.rs`
//! apply it at once.

use super::cell::Cell;
use super::edit::{CellRef, Edit, EditError};
use super::ladder::Ladder;
use super::network::Row;

impl Ladder {
    /// F6: a contact at `at` with both its ends linked up to the row above, so that it is in
    /// parallel with what stands above it. Refused on the first row.
    pub fn plan_parallel_contact(at: CellRef, contact: Cell) -> Result<Edit, EditError> {
        Ladder::can_parallel(at)?;
        let above = CellRef {
            row: at.row - 1,
            ..at
        };
        let mut edits = vec![Edit::SetCell { at, cell: contact }];
        if at.col > 0 {
            edits.push(Edit::SetLink {
                at: above,
                on: true,
            });
        }
        edits.push(Edit::SetLink {
            at: CellRef {
                col: at.col + 1,
                ..above
            },
            on: true,
        });
        Ok(Edit::Batch(edits))
    }

    /// Whether F6 can place a contact at `at`: there must be a row above to be parallel
    /// with. The editor asks before the operand is typed.
    pub fn can_parallel(at: CellRef) -> Result<(), EditError> {
        if at.row == 0 {
            return Err(EditError::NothingAbove);
        }
        Ok(())
    }

    /// An empty row before `row`.
    pub fn plan_insert_row(&self, block: usize, network: usize, row: usize) -> Edit {
        Edit::InsertRow {
            block,
            network,
            row,
            content: Row::empty(self.width),
        }
    }

    /// Deleting a row. Deleting the last row also clears the links of the row above that led
    /// into it, which would otherwise hang in the air.
    pub fn plan_delete_row(
        &self,
        block: usize,
        network: usize,
        row: usize,
    ) -> Result<Edit, EditError> {
        let mut edits = Vec::new();
        let n = self
            .blocks
            .get(block)
            .and_then(|b| b.networks.get(network))
            .ok_or(EditError::NoSuchPlace(super::edit::Missing::Network))?;
        let last = row + 1 == n.rows.len();
        if last && row > 0 {
            for (j, on) in n.rows[row - 1].links.iter().enumerate() {
                if *on {
                    edits.push(Edit::SetLink {
                        at: CellRef {
                            block,
                            network,
                            row: row - 1,
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
            row,
        });
        Ok(Edit::Batch(edits))
    }

    /// An empty network before `index`, with a fresh id.
    pub fn plan_insert_network(&self, block: usize, index: usize) -> Edit {
        Edit::InsertNetwork {
            block,
            index,
            network: Box::new(self.new_network()),
        }
    }

    /// A coil or function box in the output column of `at`'s row, joined by wire to the last
    /// element left of it, as GSKLadder draws it. Refused outside an existing row.
    pub fn plan_output(&self, at: CellRef, cell: Cell) -> Result<Edit, EditError> {
        let row = self
            .blocks
            .get(at.block)
            .and_then(|b| b.networks.get(at.network))
            .and_then(|n| n.rows.get(at.row))
            .ok_or(EditError::NoSuchPlace(super::edit::Missing::Row))?;
        let at = CellRef {
            col: self.width,
            ..at
        };
        let last = (0..self.width).rev().find(|c| row.cells[*c] != Cell::Empty);
        let from = last.map_or(self.width, |c| c + 1);
        let mut edits: Vec<Edit> = (from..self.width)
            .map(|col| Edit::SetCell {
                at: CellRef { col, ..at },
                cell: Cell::Wire,
            })
            .collect();
        edits.push(Edit::SetCell { at, cell });
        Ok(Edit::Batch(edits))
    }

    /// F5: the vertical link at the left of `at` switched; a row is added below when there is
    /// none for the link to reach.
    pub fn plan_toggle_link(&self, at: CellRef) -> Result<Edit, EditError> {
        let n = self
            .blocks
            .get(at.block)
            .and_then(|b| b.networks.get(at.network))
            .ok_or(EditError::NoSuchPlace(super::edit::Missing::Network))?;
        let on = !n.link(at.row, at.col);
        let mut edits = Vec::new();
        if at.row + 1 >= n.rows.len() {
            edits.push(self.plan_insert_row(at.block, at.network, at.row + 1));
        }
        edits.push(Edit::SetLink { at, on });
        Ok(Edit::Batch(edits))
    }

    /// A line drawn with the pen from `from` to `to` in one network: along a row, wires over
    /// the empty cells; down a column, vertical links at that column's left edge.
    pub fn plan_line(&self, from: CellRef, to: CellRef) -> Result<Edit, EditError> {
        let n = self
            .blocks
            .get(from.block)
            .and_then(|b| b.networks.get(from.network))
            .filter(|n| from.row.max(to.row) < n.rows.len() && self.width > 0)
            .ok_or(EditError::NoSuchPlace(super::edit::Missing::Row))?;
        let (r0, r1, c0, c1) = (from.row, to.row, from.col, to.col);
        let at = |row, col| CellRef { row, col, ..from };
        let mut edits = Vec::new();
        if r0.abs_diff(r1) <= c0.abs_diff(c1) {
            for col in c0.min(c1)..=c0.max(c1).min(self.width - 1) {
                if n.rows[r0].cells[col] == Cell::Empty {
                    edits.push(Edit::SetCell {
                        at: at(r0, col),
                        cell: Cell::Wire,
                    });
                }
            }
        } else {
            let col = c0.clamp(1, self.width);
            for row in r0.min(r1)..r0.max(r1) {
                edits.push(Edit::SetLink {
                    at: at(row, col),
                    on: true,
                });
            }
        }
        Ok(Edit::Batch(edits))
    }
}
