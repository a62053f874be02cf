//! Program blocks: level 1, level 2 and subprograms.

use super::network::Network;
use serde::{Deserialize, Serialize};
use std::fmt;

/// Which block a block is.
#[derive(Clone, Debug, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum BlockKind {
    /// The first-level program (every 8 ms).
    Level1,
    /// The second-level program.
    Level2,
    /// A subprogram reached by CALL/CALLU.
    Sub {
        /// Its P number.
        number: u16,
        /// Its name.
        name: String,
    },
}

impl BlockKind {
    /// The short label used in diagnostics: `LEVEL1`, `LEVEL2`, `P0001`.
    pub fn label(&self) -> String {
        match self {
            BlockKind::Level1 => "LEVEL1".into(),
            BlockKind::Level2 => "LEVEL2".into(),
            BlockKind::Sub { number, .. } => format!("P{number:04}"),
        }
    }

    /// The subprogram number, for subprograms.
    pub fn sub_number(&self) -> Option<u16> {
        match self {
            BlockKind::Sub { number, .. } => Some(*number),
            _ => None,
        }
    }
}

impl fmt::Display for BlockKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.label())
    }
}

/// A block of networks.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Block {
    /// Which block.
    pub kind: BlockKind,
    /// Block information (the "block info" text of the project tree).
    #[serde(default)]
    pub info: String,
    /// The networks in order.
    pub networks: Vec<Network>,
}

impl Block {
    /// An empty block.
    pub fn new(kind: BlockKind) -> Block {
        Block {
            kind,
            info: String::new(),
            networks: Vec::new(),
        }
    }
}
