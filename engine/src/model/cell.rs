//! The contents of one grid cell of a network.

use super::operand::Operand;
use crate::catalog::{InstrClass, Op};
use serde::{Deserialize, Deserializer, Serialize, Serializer};

/// One cell of a network's grid.
///
/// Contact columns hold [`Cell::Empty`], [`Cell::Wire`] and [`Cell::Contact`]; the output
/// column (the last one) holds [`Cell::Empty`], [`Cell::Coil`] and [`Cell::Box`].
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(into = "CellRepr", from = "CellRepr")]
pub enum Cell {
    /// Nothing.
    #[default]
    Empty,
    /// A horizontal wire.
    Wire,
    /// A contact: normally open, or normally closed when `negated`.
    Contact {
        /// Normally closed.
        negated: bool,
        /// The bit read.
        operand: Operand,
    },
    /// A coil: OUT, or OUTN when `negated`.
    Coil {
        /// Inverted output (OUTN).
        negated: bool,
        /// The bit written.
        operand: Operand,
    },
    /// A function instruction box with its operands in IL order.
    Box {
        /// Which instruction.
        op: Op,
        /// Its operands.
        operands: Vec<Operand>,
    },
}

/// The saved form of a cell: short variant names keep project files readable.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
enum CellRepr {
    #[serde(rename = "_")]
    Empty,
    #[serde(rename = "W")]
    Wire,
    NO(Operand),
    NC(Operand),
    Out(Operand),
    OutN(Operand),
    Box(Op, Vec<Operand>),
}

impl From<Cell> for CellRepr {
    fn from(c: Cell) -> CellRepr {
        match c {
            Cell::Empty => CellRepr::Empty,
            Cell::Wire => CellRepr::Wire,
            Cell::Contact {
                negated: false,
                operand,
            } => CellRepr::NO(operand),
            Cell::Contact {
                negated: true,
                operand,
            } => CellRepr::NC(operand),
            Cell::Coil {
                negated: false,
                operand,
            } => CellRepr::Out(operand),
            Cell::Coil {
                negated: true,
                operand,
            } => CellRepr::OutN(operand),
            Cell::Box { op, operands } => CellRepr::Box(op, operands),
        }
    }
}

impl From<CellRepr> for Cell {
    fn from(c: CellRepr) -> Cell {
        match c {
            CellRepr::Empty => Cell::Empty,
            CellRepr::Wire => Cell::Wire,
            CellRepr::NO(operand) => Cell::Contact {
                negated: false,
                operand,
            },
            CellRepr::NC(operand) => Cell::Contact {
                negated: true,
                operand,
            },
            CellRepr::Out(operand) => Cell::Coil {
                negated: false,
                operand,
            },
            CellRepr::OutN(operand) => Cell::Coil {
                negated: true,
                operand,
            },
            CellRepr::Box(op, operands) => Cell::Box { op, operands },
        }
    }
}

impl Cell {
    /// Whether the cell may stand in a contact column.
    pub fn is_contact_kind(&self) -> bool {
        matches!(self, Cell::Empty | Cell::Wire | Cell::Contact { .. })
    }

    /// Whether the cell may stand in the output column.
    pub fn is_output_kind(&self) -> bool {
        matches!(self, Cell::Empty | Cell::Coil { .. } | Cell::Box { .. })
    }

    /// The opcode and operands of an output cell as an instruction.
    pub fn output_instruction(&self) -> Option<(Op, Vec<Operand>)> {
        match self {
            Cell::Coil { negated, operand } => Some((
                if *negated { Op::Outn } else { Op::Out },
                vec![operand.clone()],
            )),
            Cell::Box { op, operands } => Some((*op, operands.clone())),
            _ => None,
        }
    }

    /// The output cell for an OUT/OUTN or function instruction.
    pub fn from_output(op: Op, operands: Vec<Operand>) -> Cell {
        match op {
            Op::Out | Op::Outn => Cell::Coil {
                negated: op == Op::Outn,
                operand: operands.into_iter().next().unwrap_or(Operand::Int(0)),
            },
            _ => {
                debug_assert_eq!(op.spec().class, InstrClass::Function);
                Cell::Box { op, operands }
            }
        }
    }

    /// Every operand in the cell.
    pub fn operands(&self) -> &[Operand] {
        match self {
            Cell::Contact { operand, .. } | Cell::Coil { operand, .. } => {
                std::slice::from_ref(operand)
            }
            Cell::Box { operands, .. } => operands,
            _ => &[],
        }
    }

    /// Every operand in the cell, for replacing.
    pub fn operands_mut(&mut self) -> &mut [Operand] {
        match self {
            Cell::Contact { operand, .. } | Cell::Coil { operand, .. } => {
                std::slice::from_mut(operand)
            }
            Cell::Box { operands, .. } => operands,
            _ => &mut [],
        }
    }
}

// Opcodes are saved by mnemonic so that files do not depend on the catalogue's order.
impl Serialize for Op {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.serialize_str(self.name())
    }
}

impl<'de> Deserialize<'de> for Op {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Op, D::Error> {
        let name = String::deserialize(d)?;
        Op::from_name(&name)
            .ok_or_else(|| serde::de::Error::custom(format!("unknown instruction `{name}`")))
    }
}
