//! Editing operations on the ladder, each returning its exact inverse for undo.
//!
//! The editor never changes the model directly: it builds an [`Edit`] (usually through one of
//! the gesture helpers such as [`Ladder::parallel_contact`]) and applies it; the returned
//! inverse goes on the undo stack. A gesture that touches several places is one
//! [`Edit::Batch`], so one undo takes it back whole.

use super::block::{Block, BlockKind};
use super::cell::Cell;
use super::ladder::Ladder;
use super::network::{Network, Row, WidthError};
use thiserror::Error;

/// A position in the grid: block, network, row and column (or junction, for links).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct CellRef {
    /// Block index.
    pub block: usize,
    /// Network index in the block.
    pub network: usize,
    /// Row index.
    pub row: usize,
    /// Column index (for links: the junction, the left edge of this column).
    pub col: usize,
}

/// One reversible change of the ladder.
#[derive(Clone, Debug, PartialEq)]
pub enum Edit {
    /// Replace one cell.
    SetCell {
        /// Where.
        at: CellRef,
        /// The new content.
        cell: Cell,
    },
    /// Set or clear the vertical link from `at.row` down at junction `at.col`.
    SetLink {
        /// Where.
        at: CellRef,
        /// Present or not.
        on: bool,
    },
    /// Insert a row before `row`.
    InsertRow {
        /// Block index.
        block: usize,
        /// Network index.
        network: usize,
        /// Index the new row gets.
        row: usize,
        /// Its content.
        content: Row,
    },
    /// Delete a row.
    DeleteRow {
        /// Block index.
        block: usize,
        /// Network index.
        network: usize,
        /// Row index.
        row: usize,
    },
    /// Insert a network before `index`.
    InsertNetwork {
        /// Block index.
        block: usize,
        /// Index the new network gets.
        index: usize,
        /// The network.
        network: Box<Network>,
    },
    /// Delete a network.
    DeleteNetwork {
        /// Block index.
        block: usize,
        /// Network index.
        index: usize,
    },
    /// Change a network's title and comment.
    SetNetworkText {
        /// Block index.
        block: usize,
        /// Network index.
        network: usize,
        /// New title.
        title: String,
        /// New comment.
        comment: String,
    },
    /// Insert a block (a subprogram) at `index`.
    InsertBlock {
        /// Index in the block list.
        index: usize,
        /// The block.
        block: Box<Block>,
    },
    /// Delete a subprogram block.
    DeleteBlock {
        /// Index in the block list.
        index: usize,
    },
    /// Change a block's header: a subprogram's number and name, any block's info text.
    SetBlockHeader {
        /// Index in the block list.
        index: usize,
        /// The new kind (level 1 and level 2 keep theirs).
        kind: BlockKind,
        /// The new block information.
        info: String,
    },
    /// Several edits applied in order, undone in reverse order.
    Batch(Vec<Edit>),
}

/// What an edit names that the ladder does not have.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Error)]
pub enum Missing {
    /// A block (level or subprogram).
    #[error("block")]
    Block,
    /// A network of the block.
    #[error("network")]
    Network,
    /// A row of the network.
    #[error("row")]
    Row,
    /// A column of the row.
    #[error("column")]
    Column,
    /// A row as wide as the ladder.
    #[error("row of this width")]
    RowOfWidth,
    /// A place a vertical link can take.
    #[error("place for a vertical link (it joins a row to the next, right of the rail)")]
    LinkPlace,
}

/// The column rule an element broke.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Error)]
pub enum ColumnRule {
    /// A contact or wire in the output column.
    #[error("contacts and wires go left of the output column")]
    ContactsLeft,
    /// A coil or box in a contact column.
    #[error("coils and function boxes go in the output column at the right end")]
    OutputsRight,
}

/// Why an edit was refused. Nothing changes when an edit is refused.
#[derive(Clone, Debug, PartialEq, Eq, Error)]
pub enum EditError {
    /// The position does not exist.
    #[error("there is no {0} there")]
    NoSuchPlace(Missing),
    /// A contact or wire in the output column, or a coil or box in a contact column.
    #[error("{0}")]
    WrongColumn(ColumnRule),
    /// Level 1 and level 2 cannot be deleted or duplicated.
    #[error("level 1 and level 2 always exist; only subprograms can be added or deleted")]
    FixedBlock,
    /// A network needs at least one row.
    #[error("a network keeps at least one row; delete the network instead")]
    LastRow,
    /// F6 on the first row has nothing to be parallel with.
    #[error("a parallel contact needs an element in the row above")]
    NothingAbove,
    /// A network from another project (the clipboard) whose rows have another width.
    #[error("the network does not fit this ladder: {0}")]
    WrongWidth(WidthError),
}

impl Ladder {
    fn network_mut(&mut self, block: usize, network: usize) -> Result<&mut Network, EditError> {
        self.blocks
            .get_mut(block)
            .ok_or(EditError::NoSuchPlace(Missing::Block))?
            .networks
            .get_mut(network)
            .ok_or(EditError::NoSuchPlace(Missing::Network))
    }

    /// Checks that `at` names an existing cell.
    pub fn check_cell(&self, at: CellRef) -> Result<(), EditError> {
        let n = self
            .blocks
            .get(at.block)
            .ok_or(EditError::NoSuchPlace(Missing::Block))?
            .networks
            .get(at.network)
            .ok_or(EditError::NoSuchPlace(Missing::Network))?;
        let row = n
            .rows
            .get(at.row)
            .ok_or(EditError::NoSuchPlace(Missing::Row))?;
        if at.col >= row.cells.len() {
            return Err(EditError::NoSuchPlace(Missing::Column));
        }
        Ok(())
    }

    /// Applies an edit and returns its inverse. A refused edit changes nothing (a batch is
    /// rolled back to where it started).
    pub fn apply(&mut self, edit: Edit) -> Result<Edit, EditError> {
        self.apply_with(edit, true)
    }

    /// Applies an inverse from the undo history: the column rules are not checked, because
    /// undo must bring back exactly what was there, even an element the user drew in the
    /// wrong column (which the compiler reports as L005).
    pub fn restore(&mut self, edit: Edit) -> Result<Edit, EditError> {
        self.apply_with(edit, false)
    }

    /// What [`apply`](Self::apply) and [`restore`](Self::restore) share: one helper per kind
    /// of edit, `strict` saying whether the column rules hold.
    fn apply_with(&mut self, edit: Edit, strict: bool) -> Result<Edit, EditError> {
        match edit {
            Edit::SetCell { at, cell } => self.apply_set_cell(at, cell, strict),
            Edit::SetLink { at, on } => self.apply_set_link(at, on),
            Edit::InsertRow {
                block,
                network,
                row,
                content,
            } => self.apply_insert_row(block, network, row, content),
            Edit::DeleteRow {
                block,
                network,
                row,
            } => self.apply_delete_row(block, network, row),
            Edit::InsertNetwork {
                block,
                index,
                network,
            } => self.apply_insert_network(block, index, *network),
            Edit::DeleteNetwork { block, index } => self.apply_delete_network(block, index),
            Edit::SetNetworkText {
                block,
                network,
                title,
                comment,
            } => {
                let n = self.network_mut(block, network)?;
                let old_title = std::mem::replace(&mut n.title, title);
                let old_comment = std::mem::replace(&mut n.comment, comment);
                Ok(Edit::SetNetworkText {
                    block,
                    network,
                    title: old_title,
                    comment: old_comment,
                })
            }
            Edit::InsertBlock { index, block } => self.apply_insert_block(index, *block),
            Edit::DeleteBlock { index } => {
                if index < 2 || index >= self.blocks.len() {
                    return Err(EditError::FixedBlock);
                }
                let block = Box::new(self.blocks.remove(index));
                Ok(Edit::InsertBlock { index, block })
            }
            Edit::SetBlockHeader { index, kind, info } => {
                self.apply_set_block_header(index, kind, info)
            }
            Edit::Batch(edits) => self.apply_batch(edits, strict),
        }
    }

    /// [`Edit::SetCell`]: `strict` holds the column rule (contacts and wires left of the
    /// output column, coils and boxes in it); an undo restores whatever was there.
    fn apply_set_cell(&mut self, at: CellRef, cell: Cell, strict: bool) -> Result<Edit, EditError> {
        self.check_cell(at)?;
        let output_col = at.col == self.width;
        if !strict {
            // Bounds were checked; the column rule is not.
        } else if output_col && !cell.is_output_kind() {
            return Err(EditError::WrongColumn(ColumnRule::ContactsLeft));
        }
        if strict && !output_col && !cell.is_contact_kind() {
            return Err(EditError::WrongColumn(ColumnRule::OutputsRight));
        }
        let n = self.network_mut(at.block, at.network)?;
        let old = std::mem::replace(&mut n.rows[at.row].cells[at.col], cell);
        Ok(Edit::SetCell { at, cell: old })
    }

    /// [`Edit::SetLink`]: a link joins a row to the next, so the last row and the rail's
    /// junction have none.
    fn apply_set_link(&mut self, at: CellRef, on: bool) -> Result<Edit, EditError> {
        self.check_cell(at)?;
        let n = self.network_mut(at.block, at.network)?;
        if at.col == 0 || at.row + 1 >= n.rows.len() {
            return Err(EditError::NoSuchPlace(Missing::LinkPlace));
        }
        let old = std::mem::replace(&mut n.rows[at.row].links[at.col], on);
        Ok(Edit::SetLink { at, on: old })
    }

    /// [`Edit::InsertRow`]: the row must have this ladder's width, as every row of a network
    /// does.
    fn apply_insert_row(
        &mut self,
        block: usize,
        network: usize,
        row: usize,
        content: Row,
    ) -> Result<Edit, EditError> {
        let width = self.width;
        let n = self.network_mut(block, network)?;
        if row > n.rows.len() {
            return Err(EditError::NoSuchPlace(Missing::Row));
        }
        if content.cells.len() != width + 1 || content.links.len() != width + 1 {
            return Err(EditError::NoSuchPlace(Missing::RowOfWidth));
        }
        n.rows.insert(row, content);
        Ok(Edit::DeleteRow {
            block,
            network,
            row,
        })
    }

    /// [`Edit::DeleteRow`]: a network keeps at least one row.
    fn apply_delete_row(
        &mut self,
        block: usize,
        network: usize,
        row: usize,
    ) -> Result<Edit, EditError> {
        let n = self.network_mut(block, network)?;
        if row >= n.rows.len() {
            return Err(EditError::NoSuchPlace(Missing::Row));
        }
        if n.rows.len() == 1 {
            return Err(EditError::LastRow);
        }
        let content = n.rows.remove(row);
        Ok(Edit::InsertRow {
            block,
            network,
            row,
            content,
        })
    }

    /// [`Edit::InsertNetwork`]: a network from elsewhere (the clipboard, another project) must
    /// fit this ladder's width and gets a new id if its own is taken.
    fn apply_insert_network(
        &mut self,
        block: usize,
        index: usize,
        mut network: Network,
    ) -> Result<Edit, EditError> {
        let width = self.width;
        let b = self
            .blocks
            .get_mut(block)
            .ok_or(EditError::NoSuchPlace(Missing::Block))?;
        if index > b.networks.len() {
            return Err(EditError::NoSuchPlace(Missing::Network));
        }
        network.check_width(width).map_err(EditError::WrongWidth)?;
        // Ids stay unique whatever the caller built the network from.
        if self.find_network(network.id).is_some() {
            network.id = self.new_network_id();
        }
        let b = &mut self.blocks[block];
        b.networks.insert(index, network);
        Ok(Edit::DeleteNetwork { block, index })
    }

    /// [`Edit::DeleteNetwork`]: the inverse keeps the whole network, id included.
    fn apply_delete_network(&mut self, block: usize, index: usize) -> Result<Edit, EditError> {
        let b = self
            .blocks
            .get_mut(block)
            .ok_or(EditError::NoSuchPlace(Missing::Block))?;
        if index >= b.networks.len() {
            return Err(EditError::NoSuchPlace(Missing::Network));
        }
        let network = Box::new(b.networks.remove(index));
        Ok(Edit::InsertNetwork {
            block,
            index,
            network,
        })
    }

    /// [`Edit::InsertBlock`]: only subprograms are added, after level 1 and level 2, and
    /// their networks must fit this ladder's width.
    fn apply_insert_block(&mut self, index: usize, block: Block) -> Result<Edit, EditError> {
        if index < 2 || index > self.blocks.len() || block.kind.sub_number().is_none() {
            return Err(EditError::FixedBlock);
        }
        for n in &block.networks {
            n.check_width(self.width).map_err(EditError::WrongWidth)?;
        }
        self.blocks.insert(index, block);
        Ok(Edit::DeleteBlock { index })
    }

    /// [`Edit::SetBlockHeader`]: a subprogram stays a subprogram (its number and name may
    /// change) and level 1 and level 2 keep their kind; any block's info may change.
    fn apply_set_block_header(
        &mut self,
        index: usize,
        kind: BlockKind,
        info: String,
    ) -> Result<Edit, EditError> {
        let b = self
            .blocks
            .get_mut(index)
            .ok_or(EditError::NoSuchPlace(Missing::Block))?;
        if b.kind.sub_number().is_none() != kind.sub_number().is_none()
            || (b.kind.sub_number().is_none() && b.kind != kind)
        {
            return Err(EditError::FixedBlock);
        }
        let old_kind = std::mem::replace(&mut b.kind, kind);
        let old_info = std::mem::replace(&mut b.info, info);
        Ok(Edit::SetBlockHeader {
            index,
            kind: old_kind,
            info: old_info,
        })
    }

    /// [`Edit::Batch`]: the edits in order, their inverses in reverse order; a refused edit
    /// rolls back those already applied, so a refused batch changes nothing.
    fn apply_batch(&mut self, edits: Vec<Edit>, strict: bool) -> Result<Edit, EditError> {
        let mut inverses = Vec::with_capacity(edits.len());
        for e in edits {
            match self.apply_with(e, strict) {
                Ok(inv) => inverses.push(inv),
                Err(err) => {
                    // Roll back what was applied so a refused batch changes nothing.
                    for inv in inverses.into_iter().rev() {
                        let _ = self.apply_with(inv, false);
                    }
                    return Err(err);
                }
            }
        }
        inverses.reverse();
        Ok(Edit::Batch(inverses))
    }

    /// Whether an edit whose inverse is `inverse` changed nothing (see
    /// [`Project::is_unchanged_by`](crate::model::Project::is_unchanged_by)).
    pub fn is_unchanged_by(&self, inverse: &Edit) -> bool {
        let net = |at: &CellRef| {
            self.blocks
                .get(at.block)
                .and_then(|b| b.networks.get(at.network))
        };
        match inverse {
            Edit::Batch(edits) => edits.iter().all(|e| self.is_unchanged_by(e)),
            Edit::SetCell { at, cell } => {
                net(at).and_then(|n| n.cell(at.row, at.col)) == Some(cell)
            }
            Edit::SetLink { at, on } => net(at).is_some_and(|n| n.link(at.row, at.col) == *on),
            Edit::SetNetworkText {
                block,
                network,
                title,
                comment,
            } => self
                .blocks
                .get(*block)
                .and_then(|b| b.networks.get(*network))
                .is_some_and(|n| n.title == *title && n.comment == *comment),
            Edit::SetBlockHeader { index, kind, info } => self
                .blocks
                .get(*index)
                .is_some_and(|b| b.kind == *kind && b.info == *info),
            _ => false,
        }
    }

    /// Places an element (or clears a cell with [`Cell::Empty`]).
    pub fn place(&mut self, at: CellRef, cell: Cell) -> Result<Edit, EditError> {
        self.apply(Edit::SetCell { at, cell })
    }

    /// Deletes the element at a cell, leaving the cell empty.
    pub fn delete_element(&mut self, at: CellRef) -> Result<Edit, EditError> {
        self.apply(Edit::SetCell {
            at,
            cell: Cell::Empty,
        })
    }

    /// Draws (or deletes) the vertical link from `at.row` down, at the left edge of `at.col`.
    pub fn set_link(&mut self, at: CellRef, on: bool) -> Result<Edit, EditError> {
        self.apply(Edit::SetLink { at, on })
    }

    /// F6: places a contact at `at` and links its two ends up to the row above (see
    /// [`Ladder::plan_parallel_contact`]).
    pub fn parallel_contact(&mut self, at: CellRef, contact: Cell) -> Result<Edit, EditError> {
        let edit = Ladder::plan_parallel_contact(at, contact)?;
        self.apply(edit)
    }

    /// Inserts an empty row before `row` (Ctrl+T above, Ctrl+R below the cursor).
    pub fn insert_row(
        &mut self,
        block: usize,
        network: usize,
        row: usize,
    ) -> Result<Edit, EditError> {
        let edit = self.plan_insert_row(block, network, row);
        self.apply(edit)
    }

    /// Deletes a row (see [`Ladder::plan_delete_row`]).
    pub fn delete_row(
        &mut self,
        block: usize,
        network: usize,
        row: usize,
    ) -> Result<Edit, EditError> {
        let edit = self.plan_delete_row(block, network, row)?;
        self.apply(edit)
    }

    /// Inserts an empty network before `index` (Ctrl+U above, Ctrl+I below).
    pub fn insert_network(&mut self, block: usize, index: usize) -> Result<Edit, EditError> {
        let edit = self.plan_insert_network(block, index);
        self.apply(edit)
    }

    /// Deletes a network.
    pub fn delete_network(&mut self, block: usize, index: usize) -> Result<Edit, EditError> {
        self.apply(Edit::DeleteNetwork { block, index })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::change::History;
    use crate::model::operand::Operand;
    use crate::model::project::Project;

    fn contact(a: &str) -> Cell {
        Cell::Contact {
            negated: false,
            operand: Operand::parse(a).unwrap(),
        }
    }

    #[test]
    fn every_edit_undoes_exactly() {
        let mut project = Project {
            ladder: Ladder::new(4),
            ..Project::default()
        };
        let empty = project.clone();
        let mut h = History::new(100);
        h.apply(&mut project, Edit::Batch(vec![])).unwrap();
        let ladder = &mut project.ladder;
        let ins = ladder.insert_network(1, 0).unwrap();
        h.record(ins);
        let at = CellRef {
            block: 1,
            network: 0,
            row: 0,
            col: 0,
        };
        h.record(ladder.place(at, contact("X2.1")).unwrap());
        h.record(ladder.insert_row(1, 0, 1).unwrap());
        h.record(
            ladder
                .parallel_contact(CellRef { row: 1, ..at }, contact("Y3.7"))
                .unwrap(),
        );
        h.record(
            ladder
                .place(
                    CellRef { col: 4, ..at },
                    Cell::Coil {
                        negated: false,
                        operand: Operand::parse("Y3.7").unwrap(),
                    },
                )
                .unwrap(),
        );
        let full = project.clone();
        let ladder = &project.ladder;
        assert!(ladder.blocks[1].networks[0].link(0, 1));
        h.record(project.ladder.delete_row(1, 0, 1).unwrap());
        assert!(
            !project.ladder.blocks[1].networks[0].link(0, 1),
            "links into a deleted row go"
        );
        assert!(h.undo(&mut project));
        assert_eq!(project, full);
        while h.undo(&mut project) {}
        assert_eq!(project, empty);
        while h.redo(&mut project) {}
        assert_eq!(project.ladder.blocks[1].networks[0].rows.len(), 1);
    }

    #[test]
    fn refused_edits_change_nothing() {
        let mut ladder = Ladder::new(4);
        ladder.insert_network(0, 0).unwrap();
        let before = ladder.clone();
        let at = CellRef {
            block: 0,
            network: 0,
            row: 0,
            col: 4,
        };
        assert!(matches!(
            ladder.place(at, contact("X1.0")),
            Err(EditError::WrongColumn(_))
        ));
        let batch = Edit::Batch(vec![
            Edit::SetCell {
                at: CellRef { col: 0, ..at },
                cell: contact("X1.0"),
            },
            Edit::SetLink { at, on: true },
        ]);
        assert!(ladder.apply(batch).is_err());
        assert_eq!(ladder, before);
        assert_eq!(ladder.delete_row(0, 0, 0), Err(EditError::LastRow));
        assert_eq!(
            ladder.apply(Edit::DeleteBlock { index: 0 }),
            Err(EditError::FixedBlock)
        );
    }
}
