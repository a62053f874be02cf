//! Networks imported from an instruction list keep the list as written (docs/plc.md, "What
//! import keeps").
//!
//! Other tools and controllers write the same logic in several ways (`LD a / MPS / OUT b /
//! MPP / OUT c` or `LD a / OUT b / OUT c`; `LD a / LD b / ANB` or `LD a / AND b`). The editor
//! draws them alike and its emitter writes one of them, so without the imported text an
//! import → export round trip would change the list, and with it the step count and where a
//! level-2 slice ends. A network therefore keeps its imported lines ([`Network::il`]), and the
//! compiler emits them instead of the drawing's own list as long as both read as the same
//! rungs: the imported lines' canonical emission (decompiled, then emitted) equals the
//! drawing's. An edit that changes the logic breaks that equality and the drawing is the
//! truth again; undoing the edit restores it.

use super::decompile::decompile;
use super::diag::{Origin, Sink};
use super::rung::{Instr, emit};
use crate::catalog::Op;
use crate::model::{Network, Operand};

/// One kept line (`LD   X0000.0`, `MOVN 4 D0010 D0020`): its mnemonic and operands.
fn parse_line(line: &str) -> Option<(Op, Vec<Operand>)> {
    let mut words = line.split_whitespace();
    let op = Op::from_name(words.next()?)?;
    let operands = words
        .map(|w| Operand::parse(w).ok())
        .collect::<Option<Vec<_>>>()?;
    Some((op, operands))
}

/// The lines to keep for an imported network: empty when the list as written is already the
/// one the drawing compiles to, so the file holds only what it must.
pub fn lines_to_keep(instrs: &[Instr]) -> Vec<String> {
    let mut sink = Sink::default();
    let Some(rungs) = decompile(instrs, &mut sink) else {
        return Vec::new();
    };
    let mut canonical = Vec::new();
    emit(&rungs, &mut canonical);
    if same_list(&canonical, instrs) {
        return Vec::new();
    }
    instrs
        .iter()
        .map(|i| super::text::instr_text(i.op, &i.operands))
        .collect()
}

/// Whether a network drawn from `instrs` compiles back to them: through its kept lines, or,
/// keeping none, through the drawing's own emission.
pub fn reads_back(network: &Network, width: usize, instrs: &[Instr]) -> bool {
    let rungs = super::lower::lower_network(network, width, &mut Sink::default());
    let mut drawn = Vec::new();
    emit(&rungs, &mut drawn);
    if network.il.is_empty() {
        same_list(&drawn, instrs)
    } else {
        as_written(network, &drawn).is_some_and(|kept| same_list(&kept, instrs))
    }
}

/// Whether two lists hold the same instructions, wherever they came from.
fn same_list(a: &[Instr], b: &[Instr]) -> bool {
    a.len() == b.len()
        && a.iter()
            .zip(b)
            .all(|(x, y)| x.op == y.op && x.operands == y.operands)
}

/// The network's kept list with the drawing's cells as origins, when it still reads as the
/// same rungs as `drawn` (the drawing's canonical emission); else `None`.
pub fn as_written(network: &Network, drawn: &[Instr]) -> Option<Vec<Instr>> {
    if network.il.is_empty() {
        return None;
    }
    let mut instrs = network
        .il
        .iter()
        .enumerate()
        .map(|(k, line)| {
            let (op, operands) = parse_line(line)?;
            Some(Instr {
                op,
                operands,
                // The position, so the canonical emission tells which kept line each of its
                // contacts and outputs came from.
                origin: Origin::Line(k as u32),
            })
        })
        .collect::<Option<Vec<_>>>()?;
    let rungs = decompile(&instrs, &mut Sink::default())?;
    let mut canonical = Vec::new();
    emit(&rungs, &mut canonical);
    if !same_list(&canonical, drawn) {
        return None;
    }
    // Each contact and output takes the cell of its drawn counterpart; a stack instruction
    // (no counterpart) the cell of the next element, or of the last one at the end.
    let mut cells = vec![Origin::None; instrs.len()];
    for (c, d) in canonical.iter().zip(drawn) {
        if let Origin::Line(k) = c.origin {
            cells[k as usize] = d.origin;
        }
    }
    let mut next = Origin::None;
    for k in (0..cells.len()).rev() {
        if cells[k] == Origin::None {
            cells[k] = next;
        } else {
            next = cells[k];
        }
    }
    let mut last = Origin::None;
    for (instr, cell) in instrs.iter_mut().zip(cells) {
        if cell != Origin::None {
            last = cell;
        }
        instr.origin = if cell == Origin::None { last } else { cell };
    }
    Some(instrs)
}
