//! Where the editor points in a project: the cell cursor and blocks named by what they are.
//! A leaf module, so commands, views and the application can all name a place.

use ladder_engine::model::{BlockKind, CellRef, Change, Edit, Ladder, Project};

/// What the main area shows.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum View {
    /// A ladder block (index in the ladder).
    Block(usize),
    /// A symbol table.
    Symbols(usize),
    /// The data-setting tables.
    Data,
    /// The message table.
    Messages,
    /// The reference index.
    RefIndex,
    /// The bit-usage table.
    RefBits,
    /// The byte-usage table.
    RefBytes,
    /// The diagnosis table.
    Diagnosis,
    /// The permission table.
    Permissions,
    /// The M-code comments.
    MCodes,
    /// The version information.
    Version,
    /// The saved scenarios.
    Scenarios,
}

/// The view a diagnostic of a table, the machine model or the scenarios points at (its
/// "block" is one of the compiler's pseudo-blocks), with the row to go to; `None` for a
/// ladder block. The machine model is no view: `Some((None, _))`.
pub fn table_view(at: CellRef) -> Option<(Option<View>, Option<usize>)> {
    use ladder_engine::compiler::pseudo_blocks as block;
    use ladder_engine::diagnose::SCENARIOS;
    let row = Some(at.row);
    Some(match at.block {
        block::SYMBOLS => (Some(View::Symbols(at.network)), row),
        block::DATA => (Some(View::Data), None),
        block::MESSAGES => (Some(View::Messages), row),
        block::DIAGNOSIS => (Some(View::Diagnosis), row),
        block::PERMISSIONS => (Some(View::Permissions), row),
        block::MCODES => (Some(View::MCodes), row),
        block::VERSION => (Some(View::Version), None),
        SCENARIOS => (Some(View::Scenarios), None),
        block::MACHINE => (None, None),
        _ => return None,
    })
}

/// The cell cursor (UI state, never saved).
pub type Cursor = CellRef;

/// The first cell of a block: where the cursor goes when a block is shown afresh.
pub fn block_start(block: usize) -> Cursor {
    Cursor {
        block,
        network: 0,
        row: 0,
        col: 0,
    }
}

/// A block named by what it is rather than by its place in the list, which undo and
/// subprogram edits change.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum BlockKey {
    /// Level 1.
    Level1,
    /// Level 2.
    Level2,
    /// Subprogram P`0`.
    Sub(u16),
}

impl BlockKey {
    /// The key of a block.
    pub fn of(kind: &BlockKind) -> BlockKey {
        match kind {
            BlockKind::Level1 => BlockKey::Level1,
            BlockKind::Level2 => BlockKey::Level2,
            BlockKind::Sub { number, .. } => BlockKey::Sub(*number),
        }
    }

    /// Where the block is now, if it still exists.
    pub fn index(self, ladder: &Ladder) -> Option<usize> {
        match self {
            BlockKey::Level1 => Some(0),
            BlockKey::Level2 => Some(1),
            BlockKey::Sub(n) => ladder.sub_index(n),
        }
    }
}

/// Where a change of the project can be seen: undo and redo go there.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Place {
    /// A cell of the ladder.
    Cell(CellRef),
    /// A block as a whole (a subprogram added, renamed or its information changed).
    Block(usize),
}

/// Where `change` (a step of the history, applied or about to be) shows in `project`.
pub fn place_of(change: &Change, project: &Project) -> Option<Place> {
    match change {
        Change::Batch(cs) => cs.iter().find_map(|c| place_of(c, project)),
        Change::Whole(_) => None,
        Change::Ladder(e) => edit_place(e, project),
        // A table shows its own changes (the tables view selects the row).
        Change::Table(_) => None,
    }
}

fn edit_place(e: &Edit, project: &Project) -> Option<Place> {
    let blocks = project.ladder.blocks.len();
    let at = |block: usize, network: usize, row: usize| {
        (block < blocks).then_some(Place::Cell(CellRef {
            block,
            network,
            row,
            col: 0,
        }))
    };
    match e {
        Edit::SetCell { at: c, .. } | Edit::SetLink { at: c, .. } => Some(Place::Cell(*c)),
        Edit::InsertRow {
            block,
            network,
            row,
            ..
        }
        | Edit::DeleteRow {
            block,
            network,
            row,
        } => at(*block, *network, *row),
        Edit::InsertNetwork { block, index, .. } | Edit::DeleteNetwork { block, index } => {
            at(*block, *index, 0)
        }
        Edit::SetNetworkText { block, network, .. } => at(*block, *network, 0),
        Edit::InsertBlock { index, .. } | Edit::SetBlockHeader { index, .. } => {
            Some(Place::Block((*index).min(blocks - 1)))
        }
        Edit::DeleteBlock { .. } => Some(Place::Block(1)),
        Edit::Batch(es) => es.iter().find_map(|e| edit_place(e, project)),
    }
}
