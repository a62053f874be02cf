//! Networks: a title, comments and a grid of cells joined by vertical links.

use super::cell::Cell;
use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;
use thiserror::Error;

/// A stable identity of a network, unique within a project and never reused.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize)]
#[serde(transparent)]
pub struct NetworkId(pub u64);

/// One row of a network's grid.
///
/// `cells` has `width + 1` entries: `width` contact columns, then the output column.
/// `links[j]` is a vertical link from this row down to the next one at junction `j`, the left
/// edge of column `j` (F5 "adds a downward line at the left of the selected position", §3.2.2).
/// Junction 0 is the left rail, where every row is joined anyway, so `links[0]` stays false.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(into = "RowRepr", try_from = "RowRepr")]
pub struct Row {
    /// The cells, left to right.
    pub cells: Vec<Cell>,
    /// Vertical links down to the next row, per junction.
    pub links: Vec<bool>,
}

/// The saved form of a row: its cells and the junctions that have a link down.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
struct RowRepr(Vec<Cell>, #[serde(default)] Vec<usize>);

impl From<Row> for RowRepr {
    fn from(r: Row) -> RowRepr {
        let links = (0..r.links.len()).filter(|j| r.links[*j]).collect();
        RowRepr(r.cells, links)
    }
}

impl TryFrom<RowRepr> for Row {
    type Error = String;
    fn try_from(r: RowRepr) -> Result<Row, String> {
        let mut links = vec![false; r.0.len()];
        for j in r.1 {
            if j == 0 || j >= links.len() {
                return Err(format!(
                    "a vertical link at junction {j} lies outside the row's {} cells",
                    r.0.len()
                ));
            }
            links[j] = true;
        }
        Ok(Row { cells: r.0, links })
    }
}

impl Row {
    /// An empty row for a network of `width` contact columns.
    pub fn empty(width: usize) -> Row {
        Row {
            cells: vec![Cell::Empty; width + 1],
            links: vec![false; width + 1],
        }
    }

    /// Whether the row holds nothing at all.
    pub fn is_empty(&self) -> bool {
        self.cells.iter().all(|c| *c == Cell::Empty) && !self.links.iter().any(|l| *l)
    }
}

/// Why a network does not fit a ladder's width ([`Network::check_width`]). The words are
/// rendered from the data (the English here, the Chinese in the text crate), so a Chinese
/// message never quotes the English.
#[derive(Clone, Debug, PartialEq, Eq, Error)]
pub enum WidthError {
    /// The network has no row at all.
    #[error("it has no rows")]
    NoRows,
    /// A row whose cells or junctions are not one per contact column plus the output column.
    #[error("row {row} has {cells} cells and {junctions} junctions, not {expected}")]
    Row {
        /// The row, counted from 1.
        row: usize,
        /// How many cells it has.
        cells: usize,
        /// How many junctions (places for a vertical link) it has.
        junctions: usize,
        /// How many of each the ladder's width asks for (`width + 1`).
        expected: usize,
    },
}

/// A network (rung group) with its title and comments.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Network {
    /// Stable identity.
    pub id: NetworkId,
    /// Title shown above the network (and in IL as `NETWORK "title"`).
    pub title: String,
    /// Free comment.
    pub comment: String,
    /// Comments per language code (`zh`, `en`).
    #[serde(default)]
    pub comments: BTreeMap<String, String>,
    /// The grid, top to bottom.
    pub rows: Vec<Row>,
    /// The instruction list this network was imported from, one instruction per line, when it
    /// differs from the list the drawing compiles to. While the drawing still reads as this
    /// list, the compiler emits it as written (its steps, its stack instructions), so an
    /// imported list exports and runs unchanged; once an edit changes what the drawing reads
    /// as, the drawing is the truth (docs/plc.md, "What import keeps").
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub il: Vec<String>,
}

impl Network {
    /// Whether the network fits a ladder `width` contact columns wide: at least one row, each
    /// with `width + 1` cells and junctions.
    pub fn check_width(&self, width: usize) -> Result<(), WidthError> {
        if self.rows.is_empty() {
            return Err(WidthError::NoRows);
        }
        for (r, row) in self.rows.iter().enumerate() {
            if row.cells.len() != width + 1 || row.links.len() != width + 1 {
                return Err(WidthError::Row {
                    row: r + 1,
                    cells: row.cells.len(),
                    junctions: row.links.len(),
                    expected: width + 1,
                });
            }
        }
        Ok(())
    }

    /// An empty network of one empty row.
    pub fn new(id: NetworkId, width: usize) -> Network {
        Network {
            id,
            title: String::new(),
            comment: String::new(),
            comments: BTreeMap::new(),
            rows: vec![Row::empty(width)],
            il: Vec::new(),
        }
    }

    /// The cell at `row`, `col`, if it exists.
    pub fn cell(&self, row: usize, col: usize) -> Option<&Cell> {
        self.rows.get(row).and_then(|r| r.cells.get(col))
    }

    /// Whether there is a vertical link from `row` down at junction `j`.
    pub fn link(&self, row: usize, j: usize) -> bool {
        self.rows
            .get(row)
            .and_then(|r| r.links.get(j))
            .copied()
            .unwrap_or(false)
    }

    /// Whether the network holds no element at all.
    pub fn is_empty(&self) -> bool {
        self.rows.iter().all(Row::is_empty)
    }
}
