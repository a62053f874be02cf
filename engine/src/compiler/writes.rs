//! W008: an output of a function instruction that another instruction of the same scan level
//! also writes, where one of the two writes it at every execution whatever its ACT (a coil, or
//! an operand the catalogue gives [`Role::Driven`]): the other write never lasts.
//!
//! Two writes that happen only while their ACT is 1 (MOVN, ADDB, SET, RST, ALT, ROTB, …) are
//! not reported: writing one address from several rungs under different conditions is how a
//! value is selected (MOVN 1 → R0104 here, MOVN F0026 → R0104 there) or a bit latched
//! (SET here, RST there). Two coils are W001's.
//!
//! A scan level is level 1, or level 2 with the subprograms: each runs as a whole before the
//! other can look at the result.

use super::Program;
use super::diag::Sink;
use super::finding::CheckFinding;
use super::operands::operand_error;
use super::place::{InstrPlace, location};
use crate::address::{Address, Area};
use crate::catalog::{Access, InstrClass, Op, OperandSpec, Role, Width};
use crate::model::{BlockKind, Operand};
use crate::profile::Profile;
use std::collections::{HashMap, HashSet};

/// The smallest thing two writes can share: a bit of a 1-byte area, or a whole address of a
/// 4-byte area (bit 0). Numbers are wide enough for a write running past the area's end.
pub(super) type Unit = (Area, u32, u8);

/// One operand an instruction writes.
struct Writer {
    /// Which instruction, counted through the program: its own operands never clash.
    instr: usize,
    place: InstrPlace,
    op: Op,
    /// The operand's name in the catalogue (`OUT`, `ERR`).
    operand: &'static str,
    address: Address,
    coil: bool,
    /// Written at every execution whatever ACT.
    driven: bool,
}

impl Writer {
    /// Whether this write and an earlier one fight over their shared address.
    fn clashes_with(&self, earlier: &Writer) -> bool {
        self.instr != earlier.instr
            && !(self.coil && earlier.coil)
            && (self.driven || earlier.driven)
    }
}

/// Whether operand `i` is written with the operands as they are.
pub(super) fn writes(spec: &OperandSpec, operands: &[Operand]) -> bool {
    match spec.access {
        Access::Read => false,
        Access::Write | Access::ReadWrite => true,
        Access::WriteWhen { operand, value } => {
            matches!(operands.get(usize::from(operand)), Some(Operand::Int(v)) if *v == i64::from(value))
        }
    }
}

/// The units a write of `spec` at `a` covers (docs/plc.md, "Width rule"). A table whose
/// length comes from memory counts as its first element.
pub(super) fn units(spec: &OperandSpec, operands: &[Operand], a: Address) -> Vec<Unit> {
    let number = u32::from(a.number);
    if let Some(bit) = a.bit {
        let count = if spec.width == Width::Bits3 { 3 } else { 1 };
        return (0..count)
            .map(|k| {
                let b = u32::from(bit) + k;
                (a.area, number + b / 8, (b % 8) as u8)
            })
            .collect();
    }
    if a.area.element_bytes() != 1 {
        return vec![(a.area, number, 0)];
    }
    let bytes = match spec.width {
        Width::Bytes(n) => u32::from(n),
        Width::SizeOf(i) => match operands.get(usize::from(i)) {
            Some(Operand::Int(v @ (1 | 2 | 4))) => *v as u32,
            _ => 1,
        },
        _ => 1,
    };
    (0..bytes)
        .flat_map(|k| (0..8).map(move |b| (a.area, number + k, b)))
        .collect()
}

/// Index of the scan level a block runs in: 0 for level 1, 1 for level 2 and subprograms.
fn level(kind: &BlockKind) -> usize {
    usize::from(!matches!(kind, BlockKind::Level1))
}

/// Reports W008 for every write that clashes with an earlier one of its scan level, at the
/// later write, naming the earliest it clashes with. Symbols must be resolved already.
pub fn check_writes(program: &Program, profile: &Profile, sink: &mut Sink) {
    let mut writers: Vec<Writer> = Vec::new();
    let mut by_unit: [HashMap<Unit, Vec<usize>>; 2] = [HashMap::new(), HashMap::new()];
    // Every coil address so far, as W001 sees them: a coil W001 reports gets no W008 too.
    let mut coils: HashSet<Address> = HashSet::new();
    let mut count = 0;
    for (b, block) in program.blocks.iter().enumerate() {
        let label = block.kind.label();
        let by_unit = &mut by_unit[level(&block.kind)];
        for (n, net) in block.networks.iter().enumerate() {
            sink.at(b, &label, n);
            for instr in &net.instrs {
                count += 1;
                let spec = instr.op.spec();
                let coil = spec.class == InstrClass::Coil;
                let w001 = coil
                    && instr
                        .operands
                        .first()
                        .and_then(Operand::address)
                        .is_some_and(|a| !coils.insert(a));
                for (i, operand) in instr.operands.iter().enumerate() {
                    let (Some(ospec), Some(address)) = (spec.operand(i), operand.address()) else {
                        continue;
                    };
                    // Timer and counter numbers are W002's.
                    if ospec.role.memory_area().is_some()
                        || !writes(ospec, &instr.operands)
                        || operand_error(instr.op, &instr.operands, i, profile).is_err()
                    {
                        continue;
                    }
                    let writer = Writer {
                        instr: count,
                        place: (b, n, instr.origin),
                        op: instr.op,
                        operand: ospec.name,
                        address,
                        coil,
                        driven: coil || ospec.role == Role::Driven,
                    };
                    let covered = units(ospec, &instr.operands, address);
                    let first = covered
                        .iter()
                        .filter_map(|u| by_unit.get(u))
                        .flatten()
                        .copied()
                        .filter(|&k| writer.clashes_with(&writers[k]))
                        .min();
                    if let (Some(k), false) = (first, w001) {
                        let earlier = &writers[k];
                        sink.find(
                            instr.origin,
                            CheckFinding::OutputTwice {
                                op: writer.op,
                                operand: writer.operand.to_string(),
                                address: writer.address,
                                first_op: earlier.op,
                                first_operand: earlier.operand.to_string(),
                                first_address: earlier.address,
                                first: location(program, earlier.place),
                            },
                        );
                    }
                    let k = writers.len();
                    for u in covered {
                        by_unit.entry(u).or_default().push(k);
                    }
                    writers.push(writer);
                }
            }
        }
    }
}
