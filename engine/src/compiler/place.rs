//! Where an instruction is: a diagnostic about two instructions (a coil driven twice, a label
//! defined twice) holds the other one's place as a [`Location`].

use super::Program;
use super::diag::{Location, Origin};

/// Where an instruction is: (block, network, origin).
pub type InstrPlace = (usize, usize, Origin);

/// The place of `p` as a diagnostic's location, to quote in a finding.
pub(super) fn location(program: &Program, p: InstrPlace) -> Location {
    Location {
        block: p.0,
        block_label: program.blocks[p.0].kind.label(),
        network: p.1,
        origin: p.2,
    }
}
