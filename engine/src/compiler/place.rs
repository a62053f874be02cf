//! Where an instruction is, and how a message names that place in either language: a
//! diagnostic about two instructions (a coil driven twice, a label defined twice) names the
//! other one's place in its text.

use super::Program;
use super::diag::{Location, Origin};

/// Where an instruction is: (block, network, origin).
pub type InstrPlace = (usize, usize, Origin);

/// The place of `p` in English, as a diagnostic's location reads.
pub(super) fn place_text(program: &Program, p: InstrPlace) -> String {
    let block = program.blocks[p.0].kind.label();
    match p.2 {
        Origin::Line(l) => format!("line {l}"),
        Origin::Cell { row, col } => {
            format!(
                "{block} network {} row {} col {}",
                p.1 + 1,
                row + 1,
                col + 1
            )
        }
        Origin::None => format!("{block} network {}", p.1 + 1),
    }
}

/// The place of `p` in Chinese, as a diagnostic's location reads.
pub(super) fn place_text_zh(program: &Program, p: InstrPlace) -> String {
    Location {
        block: p.0,
        block_label: program.blocks[p.0].kind.label(),
        network: p.1,
        origin: p.2,
    }
    .describe_zh()
}
