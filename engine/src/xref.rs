//! The cross-reference (manual §3.4.6): every reference to an address in the ladder, and the
//! bit-usage and byte-usage tables. Built from the model itself, so it is current after any
//! edit without compiling; the context text is made only when shown.

use crate::address::{Address, Area};
use crate::catalog::{Access, Op};
use crate::il::instr_text;
use crate::model::{Cell, CellRef, Operand, Project};
use std::collections::BTreeMap;
use std::fmt::Write as _;

/// How an element uses an address.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Use {
    /// Read.
    Read,
    /// Written.
    Write,
    /// Read and written.
    ReadWrite,
}

impl Use {
    /// `R`, `W` or `RW`.
    pub fn letters(self) -> &'static str {
        match self {
            Use::Read => "R",
            Use::Write => "W",
            Use::ReadWrite => "RW",
        }
    }
}

/// One reference: an address used by the element in a cell.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct Reference {
    /// The address (a symbol resolved).
    pub address: Address,
    /// Block index.
    pub block: usize,
    /// Network index.
    pub network: usize,
    /// Row.
    pub row: usize,
    /// Column.
    pub col: usize,
    /// Read or write.
    pub usage: Use,
}

/// Every reference of a project, ordered by address, then position.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Xref {
    /// The references.
    pub refs: Vec<Reference>,
}

fn access_use(op: Op, i: usize, operands: &[Operand]) -> Use {
    match op.spec().operand(i).map(|s| s.access) {
        Some(Access::Write) => Use::Write,
        Some(Access::ReadWrite) => Use::ReadWrite,
        Some(Access::WriteWhen { operand, value }) => {
            if matches!(operands.get(operand as usize), Some(Operand::Int(v)) if *v == i64::from(value))
            {
                Use::Write
            } else {
                Use::Read
            }
        }
        _ => Use::Read,
    }
}

/// Builds the cross-reference of a project.
pub fn build(project: &Project) -> Xref {
    let symbols = project.symbol_index();
    let resolve = |o: &Operand| match o {
        Operand::Addr(a) => Some(*a),
        Operand::Symbol(s) => symbols.get(s),
        _ => None,
    };
    let mut refs = Vec::new();
    for (b, block) in project.ladder.blocks.iter().enumerate() {
        for (n, net) in block.networks.iter().enumerate() {
            for (r, row) in net.rows.iter().enumerate() {
                for (c, cell) in row.cells.iter().enumerate() {
                    let mut push = |address: Address, usage: Use| {
                        refs.push(Reference {
                            address,
                            block: b,
                            network: n,
                            row: r,
                            col: c,
                            usage,
                        })
                    };
                    match cell {
                        Cell::Contact { operand, .. } => {
                            if let Some(a) = resolve(operand) {
                                push(a, Use::Read);
                            }
                        }
                        Cell::Coil { operand, .. } => {
                            if let Some(a) = resolve(operand) {
                                push(a, Use::Write);
                            }
                        }
                        Cell::Box { op, operands } => {
                            for (i, o) in operands.iter().enumerate() {
                                if let Some(a) = resolve(o) {
                                    push(a, access_use(*op, i, operands));
                                }
                            }
                        }
                        _ => {}
                    }
                }
            }
        }
    }
    refs.sort_unstable();
    Xref { refs }
}

/// A CALL or CALLU of a subprogram, where it stands.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Call {
    /// The calling box's cell.
    pub at: CellRef,
    /// CALL or CALLU.
    pub op: Op,
}

/// Every CALL and CALLU of subprogram P`number`, in ladder order ("view calls"); a call
/// written with the subprogram's symbol counts.
pub fn calls_of(project: &Project, number: u16) -> Vec<Call> {
    let mut out = Vec::new();
    for (bi, b) in project.ladder.blocks.iter().enumerate() {
        for (ni, n) in b.networks.iter().enumerate() {
            for (ri, row) in n.rows.iter().enumerate() {
                for (ci, cell) in row.cells.iter().enumerate() {
                    let Cell::Box { op, operands } = cell else {
                        continue;
                    };
                    if !matches!(op, Op::Call | Op::Callu) {
                        continue;
                    }
                    let target = match operands.first() {
                        Some(Operand::Addr(a)) => Some(*a),
                        Some(Operand::Symbol(s)) => project.resolve_symbol(s),
                        _ => None,
                    };
                    if target.is_some_and(|a| a.area == Area::P && a.number == number) {
                        out.push(Call {
                            at: CellRef {
                                block: bi,
                                network: ni,
                                row: ri,
                                col: ci,
                            },
                            op: *op,
                        });
                    }
                }
            }
        }
    }
    out
}

/// The element a reference points at, as text (`LD X0002.1`, `TMRB T0000 DT0004 R0300.0`).
pub fn context(project: &Project, r: &Reference) -> String {
    let cell = project
        .ladder
        .blocks
        .get(r.block)
        .and_then(|b| b.networks.get(r.network))
        .and_then(|n| n.cell(r.row, r.col));
    match cell {
        Some(Cell::Contact { negated, operand }) => {
            format!(
                "{} {operand}",
                if *negated {
                    "─┤/├─"
                } else {
                    "─┤ ├─"
                }
            )
        }
        Some(Cell::Coil { negated, operand }) => instr_text(
            if *negated { Op::Outn } else { Op::Out },
            std::slice::from_ref(operand),
        ),
        Some(Cell::Box { op, operands }) => box_context(*op, operands),
        _ => String::new(),
    }
}

/// Operands shown in a box's context before the rest is counted.
const CONTEXT_OPERANDS: usize = 8;

/// A box as context: its first operands and how many more there are. Every reference of a
/// box shares this text, so it is bounded — a full CODB table on each of its references
/// would make the index grow with the square of the table.
fn box_context(op: Op, operands: &[Operand]) -> String {
    if operands.len() <= CONTEXT_OPERANDS {
        return instr_text(op, operands);
    }
    let mut s = instr_text(op, &operands[..CONTEXT_OPERANDS]);
    let _ = write!(s, " … (+{})", operands.len() - CONTEXT_OPERANDS);
    s
}

/// The reference index as text: one line per reference.
pub fn index_text(project: &Project, x: &Xref) -> String {
    let mut out = String::from("ADDRESS   USE BLOCK   NETWORK:ROW:COL  CONTEXT\n");
    for r in &x.refs {
        let block = project.ladder.blocks[r.block].kind.label();
        let _ = writeln!(
            out,
            "{:<9} {:<3} {:<7} {:<16} {}",
            r.address.to_string(),
            r.usage.letters(),
            block,
            format!("{}:{}:{}", r.network + 1, r.row + 1, r.col + 1),
            context(project, r)
        );
    }
    out
}

/// The bit-usage table: for each byte with a bit referenced, which bits are.
pub fn bit_usage(x: &Xref) -> BTreeMap<Address, [bool; 8]> {
    let mut t: BTreeMap<Address, [bool; 8]> = BTreeMap::new();
    for r in &x.refs {
        if let Some(bit) = r.address.bit {
            t.entry(r.address.byte_address()).or_default()[usize::from(bit)] = true;
        }
    }
    t
}

/// The bit-usage table as text, bits 7 … 0 as the manual draws it.
pub fn bits_text(x: &Xref) -> String {
    let mut out = String::from("BIT     7 6 5 4 3 2 1 0\n");
    for (a, bits) in bit_usage(x) {
        let name = a.to_string();
        let _ = write!(out, "{name}_");
        out.push_str(&" ".repeat(7usize.saturating_sub(name.len())));
        for b in (0..8).rev() {
            out.push_str(if bits[b] { " X" } else { " ." });
        }
        out.push('\n');
    }
    out
}

/// The byte-usage table: per area and tens, which of the ten addresses are referenced as
/// bytes or words.
pub fn byte_usage(x: &Xref) -> BTreeMap<(Area, u16), [bool; 10]> {
    let mut t: BTreeMap<(Area, u16), [bool; 10]> = BTreeMap::new();
    for r in &x.refs {
        if r.address.bit.is_none() && !matches!(r.address.area, Area::L | Area::P) {
            let n = r.address.number;
            t.entry((r.address.area, n / 10)).or_default()[usize::from(n % 10)] = true;
        }
    }
    t
}

/// The byte-usage table as text, ten addresses a row (`C000_` is C0000–C0009).
pub fn bytes_text(x: &Xref) -> String {
    let mut out = String::from("BYTE    0 1 2 3 4 5 6 7 8 9\n");
    for ((area, tens), used) in byte_usage(x) {
        let name = format!("{}{:03}_", area.letters(), tens);
        let _ = write!(out, "{name}");
        out.push_str(&" ".repeat(8usize.saturating_sub(name.len() + 1)));
        for u in used {
            out.push_str(if u { " X" } else { " ." });
        }
        out.push('\n');
    }
    out
}
