//! What the program-wide checks (`compiler/check.rs`, `writes.rs`, `presets.rs`): subprogram numbers, labels, jumps and calls, coils and timers used twice, step limits, stack depth, undefined symbols, operands find, as data.

use crate::address::Address;
use crate::catalog::Op;
use crate::compiler::{Code, Location, OperandRefusal};

/// A finding of the program-wide checks (`compiler/check.rs`, `writes.rs`, `presets.rs`): subprogram numbers, labels, jumps and calls, coils and timers used twice, step limits, stack depth, undefined symbols, operands.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub enum CheckFinding {
    /// L038: a subprogram number outside the profile's P range.
    SubNumberRange {
        /// The subprogram's number.
        number: u16,
        /// The first number of the P range.
        lo: u16,
        /// The last number of the P range.
        hi: u16,
    },
    /// L038: a second subprogram with the number of an earlier one.
    SubTwice {
        /// The subprogram's number.
        number: u16,
    },
    /// L030: a label defined a second time.
    LabelTwice {
        /// The label.
        label: Address,
        /// Where it is defined first.
        first: Location,
    },
    /// W001: a coil driven a second time.
    CoilTwice {
        /// The coil's address.
        coil: Address,
        /// The first instruction driving it.
        first: Location,
    },
    /// W002: a timer or counter kept by a second instruction.
    TimerTwice {
        /// The timer or counter.
        number: Address,
        /// The first instruction keeping it.
        first: Location,
    },
    /// L031: a JMPB to a label no LBL defines.
    UndefinedLabel {
        /// The label.
        label: Address,
    },
    /// L032: a JMPB to a label of another block.
    JumpOutOfBlock {
        /// The label.
        label: Address,
        /// Where the label is defined.
        target: Location,
    },
    /// L033: a CALL or CALLU of a subprogram that does not exist.
    UndefinedSub {
        /// The calling instruction (CALL, CALLU).
        op: Op,
        /// The subprogram called.
        sub: Address,
    },
    /// L034: a call that closes a loop of subprograms calling each other.
    Recursion {
        /// The number of the subprogram called.
        callee: u16,
    },
    /// L035: level 1, with the subprograms it calls, has too many steps.
    Level1Steps {
        /// Its steps.
        steps: u32,
        /// The profile's level-1 limit, which the steps must stay under.
        limit: u32,
    },
    /// L036: the program has more steps than the PLC holds.
    ProgramSteps {
        /// Its steps.
        steps: u32,
        /// The most the profile holds.
        limit: u32,
    },
    /// L018: logic blocks nested deeper than the block stack.
    BlockStackDepth {
        /// The depth of the block stack.
        limit: usize,
    },
    /// L018: branch points (MPS) nested deeper than the branch stack.
    BranchStackDepth {
        /// The depth of the branch stack.
        limit: usize,
    },
    /// L011: an instruction with another number of operands than its catalogue entry (and,
    /// for a table instruction, its constant count) gives.
    OperandCount {
        /// The instruction.
        op: Op,
        /// How many operands it takes.
        expected: usize,
        /// How many are written.
        found: usize,
    },
    /// L011: a table instruction with fewer operands than its fixed ones, and no constant
    /// count to say how many table entries follow.
    TableOperandCount {
        /// The instruction.
        op: Op,
    },
    /// L020: a symbol the symbol tables do not define.
    UndefinedSymbol {
        /// The symbol's name.
        name: String,
    },
    /// L011, L021–L025: an operand the instruction refuses where it stands.
    Operand {
        /// The instruction.
        op: Op,
        /// The operand's name in the catalogue (`OUT`, `SIZE`).
        operand: String,
        /// Why it is refused; its code is the finding's.
        refusal: OperandRefusal,
    },
    /// W003: a comparison's three result bits running into the next byte.
    BitsSpill {
        /// The instruction (CMP, CMPR, ZCP).
        op: Op,
        /// Its OUT operand, the first result bit.
        out: Address,
        /// The next byte, which the last result bits fall into.
        next: Address,
    },
    /// W008: an output another instruction of the same scan level also writes, one of the two
    /// at every execution whatever its condition. A coil's operand is named as the coil.
    OutputTwice {
        /// The later instruction.
        op: Op,
        /// Its operand's name in the catalogue (`OUT`, `ERR`).
        operand: String,
        /// The address it writes.
        address: Address,
        /// The earlier instruction.
        first_op: Op,
        /// Its operand's name in the catalogue.
        first_operand: String,
        /// The address it writes.
        first_address: Address,
        /// Where the earlier instruction is.
        first: Location,
    },
    /// W009: a timer's or counter's preset naming a data-table entry outside its range.
    PresetRange {
        /// The instruction.
        op: Op,
        /// The preset operand's name in the catalogue (`PT`, `N`).
        operand: String,
        /// The data-table entry the preset names; its area names the table.
        address: Address,
        /// The entry's row in its table, counting from 1.
        row: usize,
        /// The value the table sets.
        value: i64,
        /// The smallest preset the instruction takes.
        min: i64,
        /// The largest preset the instruction takes.
        max: i64,
    },
}

impl CheckFinding {
    /// The diagnostic code of the finding.
    pub fn code(&self) -> Code {
        match self {
            CheckFinding::SubNumberRange { .. } | CheckFinding::SubTwice { .. } => {
                Code::L038SubNumber
            }
            CheckFinding::LabelTwice { .. } => Code::L030LabelTwice,
            CheckFinding::CoilTwice { .. } => Code::W001CoilTwice,
            CheckFinding::TimerTwice { .. } => Code::W002TimerTwice,
            CheckFinding::UndefinedLabel { .. } => Code::L031UndefinedLabel,
            CheckFinding::JumpOutOfBlock { .. } => Code::L032JumpOutOfBlock,
            CheckFinding::UndefinedSub { .. } => Code::L033UndefinedSub,
            CheckFinding::Recursion { .. } => Code::L034Recursion,
            CheckFinding::Level1Steps { .. } => Code::L035Level1Steps,
            CheckFinding::ProgramSteps { .. } => Code::L036ProgramSteps,
            CheckFinding::BlockStackDepth { .. } | CheckFinding::BranchStackDepth { .. } => {
                Code::L018StackDepth
            }
            CheckFinding::OperandCount { .. } | CheckFinding::TableOperandCount { .. } => {
                Code::L011OperandCount
            }
            CheckFinding::UndefinedSymbol { .. } => Code::L020UndefinedSymbol,
            CheckFinding::Operand { refusal, .. } => refusal.code(),
            CheckFinding::BitsSpill { .. } => Code::W003BitsSpill,
            CheckFinding::OutputTwice { .. } => Code::W008OutputTwice,
            CheckFinding::PresetRange { .. } => Code::W009PresetRange,
        }
    }
}
