//! Online monitoring: what each element of a network showed in the last scan.
//!
//! The VM records, for watched networks only, the bit each contact read and the ACT each
//! output received ([`Vm::watch`], [`Vm::trace`]). This module maps those records back to the
//! network's cells and computes the power flowing into and out of every cell over the grid,
//! the way the rung was evaluated; function boxes also get their operands' current values.
//!
//! It reads a [`Source`], not a [`Vm`]: the editor monitors a machine running on another
//! thread from the snapshots it publishes, and a recorded past state from an image the scan
//! recorder rebuilt, so the view must not need the VM itself. [`deciding_contacts`](super::deciding_contacts) reads
//! a view back: which contacts decide an output.

use super::Vm;
use super::code::Executable;
use super::memory::{self, Layout};
use crate::address::Address;
use crate::compiler::{Origin, Program};
use crate::model::{Cell, Network, Operand};

/// What a monitor reads: the code that runs, its memory image and, when live, the scan's
/// record of watched networks.
#[derive(Clone, Copy)]
pub struct Source<'a> {
    /// The running code (networks and word sources).
    pub code: &'a Executable,
    /// Where each area is in the image.
    pub layout: &'a Layout,
    /// The memory image.
    pub memory: &'a [u8],
    /// Per code word, what the last scan recorded ([`Vm::trace`]), with per code network
    /// whether it was recorded. `None` shows everything from memory (a recorded past state).
    pub trace: Option<(&'a [u8], &'a [bool])>,
}

impl Source<'_> {
    /// Reads a bit of the image.
    pub fn bit(&self, a: Address) -> bool {
        let loc = self.layout.loc(a, false);
        self.memory
            .get(loc.off as usize)
            .is_some_and(|b| b >> a.bit.unwrap_or(0) & 1 == 1)
    }

    /// Reads `bytes` at an address, signed (a bit address reads 0 or 1).
    pub fn value(&self, a: Address, bytes: u32) -> i64 {
        if a.bit.is_some() {
            return i64::from(self.bit(a));
        }
        let loc = self.layout.loc(a, false);
        if (loc.off + bytes) as usize > self.memory.len() {
            return 0;
        }
        i64::from(memory::read(self.memory, loc, bytes))
    }

    fn watched(&self, network: usize) -> Option<&[u8]> {
        let (trace, watched) = self.trace?;
        watched
            .get(network)
            .copied()
            .unwrap_or(false)
            .then_some(trace)
    }
}

impl Vm {
    /// The VM as a monitor [`Source`], with its scan record.
    pub fn source<'a>(&'a self, watched: &'a [bool]) -> Source<'a> {
        Source {
            code: &self.code,
            layout: &self.layout,
            memory: &self.mem,
            trace: Some((&self.trace, watched)),
        }
    }

    /// Which code networks are recorded, one flag per [`Executable::networks`] entry.
    pub fn watched(&self) -> &[bool] {
        &self.watched
    }
}

/// What one cell shows.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct CellView {
    /// Power at the cell's left edge.
    pub power_in: bool,
    /// Power at its right edge (through a closed contact or a wire).
    pub power_out: bool,
    /// For contacts: whether the contact was closed (NO with the bit 1, NC with the bit 0).
    pub closed: Option<bool>,
    /// For boxes: each operand's value (`None` for constants and labels).
    pub values: Vec<Option<i64>>,
}

/// What a whole network shows: one [`CellView`] per cell, row by row.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct NetworkView {
    /// Rows of cells.
    pub cells: Vec<Vec<CellView>>,
}

/// The code network (see [`Executable::networks`]) of a ladder network.
pub fn code_network(vm: &Vm, block: usize, network: usize) -> Option<usize> {
    code_network_of(vm.code(), block, network)
}

/// The code network of a ladder network, in given code.
pub fn code_network_of(code: &Executable, block: usize, network: usize) -> Option<usize> {
    code.networks
        .iter()
        .position(|n| n.block == block && n.network == network)
}

/// The view of ladder network `network` of block `block`, from the last scan. Call
/// [`Vm::watch`] for it first; an unwatched network shows its contacts from memory.
pub fn network_view(
    src: &Source<'_>,
    program: &Program,
    block: usize,
    network: usize,
    grid: &Network,
    width: usize,
) -> NetworkView {
    let rows = grid.rows.len();
    let mut view = NetworkView {
        cells: vec![vec![CellView::default(); width + 1]; rows],
    };
    // Contact bits and output ACTs recorded by the VM, by cell.
    let mut recorded: Vec<Vec<Option<bool>>> = vec![vec![None; width + 1]; rows];
    if let (Some(code_net), Some(net)) = (
        code_network_of(src.code, block, network),
        program
            .blocks
            .get(block)
            .and_then(|b| b.networks.get(network)),
    ) {
        let info = &src.code.networks[code_net];
        if let Some(trace) = src.watched(code_net) {
            for word in info.start..info.end {
                let Some((_, _, k)) = src.code.source[word as usize] else {
                    continue;
                };
                if let Some(Origin::Cell { row, col }) =
                    net.instrs.get(k as usize).map(|i| i.origin)
                    && let Some(slot) = recorded
                        .get_mut(row as usize)
                        .and_then(|r| r.get_mut(col as usize))
                {
                    *slot = trace.get(word as usize).map(|t| *t & 1 == 1);
                }
            }
        }
    }
    // Contacts: closed or open, from the record or else from memory.
    for (r, row) in grid.rows.iter().enumerate() {
        for (c, cell) in row.cells.iter().enumerate().take(width) {
            if let Cell::Contact { negated, operand } = cell {
                let bit = recorded[r][c].or_else(|| match operand {
                    Operand::Addr(a) if a.bit.is_some() => Some(src.bit(*a)),
                    _ => None,
                });
                view.cells[r][c].closed = bit.map(|b| b != *negated);
            }
        }
    }
    // Power flow, left to right: a junction's nodes (joined by vertical links) are powered
    // when any cell ending there passes power; the rail is always powered.
    let mut power_at = vec![vec![false; width + 1]; rows];
    for row in power_at.iter_mut() {
        row[0] = true;
    }
    for j in 1..=width {
        let c = j - 1;
        for (r, powered) in power_at.iter_mut().enumerate() {
            let passes = match &grid.rows[r].cells[c] {
                Cell::Wire => true,
                Cell::Contact { .. } => view.cells[r][c].closed.unwrap_or(false),
                _ => false,
            };
            powered[j] = powered[c] && passes;
        }
        // Spread along vertical links (both directions) until nothing changes.
        let mut changed = true;
        while changed {
            changed = false;
            for r in 0..rows.saturating_sub(1) {
                if grid.link(r, j) && power_at[r][j] != power_at[r + 1][j] {
                    power_at[r][j] = true;
                    power_at[r + 1][j] = true;
                    changed = true;
                }
            }
        }
    }
    for r in 0..rows {
        for c in 0..=width {
            let cell = &grid.rows[r].cells[c];
            let v = &mut view.cells[r][c];
            v.power_in = power_at[r][c] && *cell != Cell::Empty;
            v.power_out = if c < width {
                power_at[r][c + 1] && v.power_in
            } else {
                false
            };
            if c == width {
                // Outputs show the ACT they received in the scan, when recorded.
                v.power_in = recorded[r][c].unwrap_or(v.power_in);
                if let Cell::Box { operands, .. } = cell {
                    v.values = operands
                        .iter()
                        .map(|o| match o {
                            Operand::Addr(a) if a.area.element_bytes() > 0 => {
                                Some(src.value(*a, u32::from(a.area.element_bytes()).max(1)))
                            }
                            _ => None,
                        })
                        .collect();
                }
            }
        }
    }
    view
}
