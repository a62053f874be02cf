//! What each network of a compiled program reads and writes, bit by bit: the data flow the
//! CNC-aware checks ([`super::cnc`]) follow from a strobe to its finish signal.
//!
//! A network is the unit: every bit it reads is taken to reach every bit it writes. That is
//! coarser than the rungs (two independent rungs of one network look connected), so a check
//! built on it can miss a broken path but never reports a path missing that exists.

use super::Program;
use super::writes::{Unit, units, writes};
use crate::address::Area;
use crate::catalog::{InstrClass, Op};
use crate::model::Operand;
use std::collections::{HashMap, HashSet, VecDeque};

pub use super::place::InstrPlace;

/// How an instruction writes a bit.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum WriteKind {
    /// A coil (OUT, OUTN): written at every scan.
    Coil,
    /// SET.
    Set,
    /// RST.
    Rst,
    /// A function box's bit output (TMRB's OUT, CMP's result bits, DIFU's bit).
    BoxBit,
    /// A function box's byte output (MOVN, DECB's OUT): every bit of the bytes.
    BoxByte,
}

/// One read or write of one bit.
#[derive(Clone, Copy, Debug)]
pub struct Access {
    /// The bit.
    pub unit: Unit,
    /// The instruction.
    pub place: InstrPlace,
}

/// One network's reads and writes.
#[derive(Clone, Debug, Default)]
pub struct NetFlow {
    /// Every bit read (contacts, box inputs), in order.
    pub reads: Vec<Access>,
    /// Every bit written, with how.
    pub writes: Vec<(Access, WriteKind)>,
}

/// The reads and writes of a whole program, per network.
#[derive(Clone, Debug, Default)]
pub struct Flow {
    /// In program order.
    pub networks: Vec<NetFlow>,
    /// Per bit, the networks that read it.
    readers: HashMap<Unit, Vec<usize>>,
}

/// A bit as a unit.
pub fn bit(area: Area, byte: u32, bit: u8) -> Unit {
    (area, byte, bit)
}

impl Flow {
    /// Collects the reads and writes of `program` (symbols resolved).
    pub fn of(program: &Program) -> Flow {
        let mut flow = Flow::default();
        for (b, block) in program.blocks.iter().enumerate() {
            for (n, net) in block.networks.iter().enumerate() {
                let mut nf = NetFlow::default();
                for instr in &net.instrs {
                    let place = (b, n, instr.origin);
                    collect(instr.op, &instr.operands, place, &mut nf);
                }
                let k = flow.networks.len();
                for r in &nf.reads {
                    let readers = flow.readers.entry(r.unit).or_default();
                    if readers.last() != Some(&k) {
                        readers.push(k);
                    }
                }
                flow.networks.push(nf);
            }
        }
        flow
    }

    /// The first read of `unit`, if anything reads it.
    pub fn first_read(&self, unit: Unit) -> Option<InstrPlace> {
        let k = *self.readers.get(&unit)?.first()?;
        self.networks[k]
            .reads
            .iter()
            .find(|r| r.unit == unit)
            .map(|r| r.place)
    }

    /// Every write of `unit`, in program order.
    pub fn writes_of(&self, unit: Unit) -> impl Iterator<Item = (Access, WriteKind)> + '_ {
        self.networks
            .iter()
            .flat_map(|n| &n.writes)
            .filter(move |(a, _)| a.unit == unit)
            .copied()
    }

    /// Whether anything in the program writes `unit`.
    pub fn is_written(&self, unit: Unit) -> bool {
        self.writes_of(unit).next().is_some()
    }

    /// Whether a value read from `from` can reach any of `to` through the networks: a network
    /// that reads a bit passes it to every bit it writes.
    pub fn reaches(&self, from: Unit, to: &[Unit]) -> bool {
        let mut seen: HashSet<Unit> = HashSet::from([from]);
        let mut queue = VecDeque::from([from]);
        let mut visited = HashSet::new();
        while let Some(u) = queue.pop_front() {
            for &k in self.readers.get(&u).into_iter().flatten() {
                if !visited.insert(k) {
                    continue;
                }
                for (w, _) in &self.networks[k].writes {
                    if to.contains(&w.unit) {
                        return true;
                    }
                    if seen.insert(w.unit) {
                        queue.push_back(w.unit);
                    }
                }
            }
        }
        false
    }
}

/// Adds one instruction's reads and writes.
fn collect(op: Op, operands: &[Operand], place: InstrPlace, nf: &mut NetFlow) {
    let spec = op.spec();
    for (i, operand) in operands.iter().enumerate() {
        let (Some(ospec), Some(a)) = (spec.operand(i), operand.address()) else {
            continue;
        };
        // Timer and counter numbers name the instruction's own memory, not a signal.
        if ospec.role.memory_area().is_some() {
            continue;
        }
        let covered = units(ospec, operands, a);
        let written = writes(ospec, operands);
        if written {
            let kind = match (spec.class, op.name(), a.bit) {
                (InstrClass::Coil, _, _) => WriteKind::Coil,
                (_, "SET", _) => WriteKind::Set,
                (_, "RST", _) => WriteKind::Rst,
                (_, _, Some(_)) => WriteKind::BoxBit,
                (_, _, None) => WriteKind::BoxByte,
            };
            nf.writes
                .extend(covered.iter().map(|&unit| (Access { unit, place }, kind)));
        }
        let read = match ospec.access {
            crate::catalog::Access::Read | crate::catalog::Access::ReadWrite => true,
            crate::catalog::Access::Write => false,
            // An operand written only for some values of another is read otherwise.
            crate::catalog::Access::WriteWhen { .. } => !written,
        };
        if read {
            nf.reads
                .extend(covered.into_iter().map(|unit| Access { unit, place }));
        }
    }
}
