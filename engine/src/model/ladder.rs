//! The ladder: every block of a project and the network width they share.

use super::block::{Block, BlockKind};
use super::network::{Network, NetworkId, WidthError};
use serde::{Deserialize, Serialize};
use std::fmt;
use thiserror::Error;

/// Contact columns per network by default: ten contacts and the output column fit a 1366-pixel
/// laptop screen at 100 % zoom next to the project tree.
pub const DEFAULT_WIDTH: usize = 10;
/// The widest network a project may use.
pub const MAX_WIDTH: usize = 64;

/// Where a network is: its block and its place in the block, counted from 1, as a
/// structure error names it (`LEVEL1 network 2`).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct NetworkPlace {
    /// The block.
    pub block: BlockKind,
    /// The network's number in the block, counted from 1.
    pub network: usize,
}

impl fmt::Display for NetworkPlace {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{} network {}", self.block, self.network)
    }
}

/// Which invariant of [`Ladder::check_structure`] a ladder breaks. The words are rendered
/// from the data (the English here, the Chinese in the text crate), so a Chinese message
/// never quotes the English.
#[derive(Clone, Debug, PartialEq, Eq, Error)]
pub enum StructureError {
    /// A width of no contact columns, or more than [`MAX_WIDTH`].
    #[error("width {0} is not 1–{MAX_WIDTH}")]
    Width(usize),
    /// The first two blocks are not level 1 and level 2, in that order.
    #[error("the first two blocks must be LEVEL1 and LEVEL2")]
    LevelsFirst,
    /// A level block among the subprograms.
    #[error("{0} appears after the subprograms begin")]
    AfterSubprograms(BlockKind),
    /// A subprogram number not greater than the one before it.
    #[error("P{0:04} is out of order or repeated")]
    SubprogramOrder(u16),
    /// A network that does not fit the ladder's width.
    #[error("{at}: {error}")]
    Network {
        /// The network.
        at: NetworkPlace,
        /// How it does not fit.
        error: WidthError,
    },
    /// Two networks with one id.
    #[error("{at} has the id {} of {first}: give it an id no other network has", .id.0)]
    DuplicateId {
        /// The later network.
        at: NetworkPlace,
        /// The id both have.
        id: NetworkId,
        /// The earlier network.
        first: NetworkPlace,
    },
}

/// The ladder program of a project.
///
/// Invariant: `blocks[0]` is level 1, `blocks[1]` level 2, and the rest are subprograms with
/// distinct P numbers in ascending order.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Ladder {
    /// Contact columns per network (the output column comes after them).
    pub width: usize,
    /// Level 1, level 2, then subprograms.
    pub blocks: Vec<Block>,
}

impl Default for Ladder {
    fn default() -> Self {
        Ladder::new(DEFAULT_WIDTH)
    }
}

impl Ladder {
    /// The cell at a place, if it exists.
    pub fn cell_at(&self, at: super::CellRef) -> Option<&super::Cell> {
        self.blocks
            .get(at.block)?
            .networks
            .get(at.network)?
            .cell(at.row, at.col)
    }

    /// An empty ladder with level 1 and level 2 and no subprograms.
    pub fn new(width: usize) -> Ladder {
        Ladder {
            width: width.clamp(1, MAX_WIDTH),
            blocks: vec![Block::new(BlockKind::Level1), Block::new(BlockKind::Level2)],
        }
    }

    /// A network id no network of the ladder has.
    ///
    /// Derived from the ids in use rather than kept in a counter, so that undoing an insertion
    /// restores the ladder exactly.
    pub fn new_network_id(&self) -> NetworkId {
        let max = self
            .blocks
            .iter()
            .flat_map(|b| &b.networks)
            .map(|n| n.id.0)
            .max()
            .unwrap_or(0);
        NetworkId(max + 1)
    }

    /// Checks the invariants the editor and compiler rely on: a width of 1…`MAX_WIDTH`,
    /// level 1 and level 2 first, then subprograms with distinct P numbers in ascending
    /// order, every network at least one row, every row `width + 1` cells and junctions.
    /// A file that breaks them is refused rather than opened and crashed on later.
    pub fn check_structure(&self) -> Result<(), StructureError> {
        if !(1..=MAX_WIDTH).contains(&self.width) {
            return Err(StructureError::Width(self.width));
        }
        match self.blocks.get(..2).map(|b| (&b[0].kind, &b[1].kind)) {
            Some((BlockKind::Level1, BlockKind::Level2)) => {}
            _ => return Err(StructureError::LevelsFirst),
        }
        let mut last = None;
        for b in &self.blocks[2..] {
            let Some(n) = b.kind.sub_number() else {
                return Err(StructureError::AfterSubprograms(b.kind.clone()));
            };
            if last.is_some_and(|l| l >= n) {
                return Err(StructureError::SubprogramOrder(n));
            }
            last = Some(n);
        }
        let mut ids = std::collections::HashMap::new();
        for b in &self.blocks {
            for (i, n) in b.networks.iter().enumerate() {
                let at = NetworkPlace {
                    block: b.kind.clone(),
                    network: i + 1,
                };
                if let Err(error) = n.check_width(self.width) {
                    return Err(StructureError::Network { at, error });
                }
                // The id is what undo, the monitor and the settings know a network by.
                if let Some(first) = ids.insert(n.id, at.clone()) {
                    return Err(StructureError::DuplicateId {
                        at,
                        id: n.id,
                        first,
                    });
                }
            }
        }
        Ok(())
    }

    /// A new empty network with a fresh id.
    pub fn new_network(&self) -> Network {
        let id = self.new_network_id();
        Network::new(id, self.width)
    }

    /// The block index of subprogram `number`.
    pub fn sub_index(&self, number: u16) -> Option<usize> {
        self.blocks
            .iter()
            .position(|b| b.kind.sub_number() == Some(number))
    }

    /// Where a subprogram with `number` belongs to keep subprograms sorted.
    pub fn sub_insert_index(&self, number: u16) -> usize {
        2 + self.blocks[2..]
            .iter()
            .take_while(|b| b.kind.sub_number().is_some_and(|n| n < number))
            .count()
    }

    /// Finds a network by id: (block index, network index).
    pub fn find_network(&self, id: NetworkId) -> Option<(usize, usize)> {
        self.blocks.iter().enumerate().find_map(|(b, block)| {
            block
                .networks
                .iter()
                .position(|n| n.id == id)
                .map(|n| (b, n))
        })
    }
}
