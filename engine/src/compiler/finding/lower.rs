//! What the shape of a ladder network and of an instruction list read back into one (`compiler/lower.rs`, `decompile.rs`) find, as data.

use crate::catalog::Op;
use crate::compiler::Code;

/// A finding of the shape of a ladder network and of an instruction list read back into one (`compiler/lower.rs`, `decompile.rs`).
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub enum LowerFinding {
    /// A contact or wire the left rail does not reach (L001).
    ElementNotConnected,
    /// An output the left rail does not reach (L001).
    OutputNotConnected {
        /// The coil or function instruction; its class says which of the two it is.
        op: Op,
    },
    /// A branch of at most one contact that leads to no output (L002).
    OpenElement,
    /// A branch of several contacts that leads to no output (L002).
    OpenBranch {
        /// How many contacts the branch holds.
        contacts: usize,
    },
    /// A branch shorted by a plain wire in parallel with it (L003).
    ShortCircuit,
    /// Branches that join again after a branch point, or a bridge (L004).
    Bridge,
    /// A coil or function box left of the output column (L005).
    OutputLeftOfColumn,
    /// A contact or wire in the output column (L005).
    ElementInOutputColumn,
    /// A rung from the rail to its outputs through wires only (L006).
    RungWithoutContact,
    /// An output drawn straight at the rail (L006).
    OutputAtRail,
    /// An output instruction with no LD/LDI before it in a list (L006).
    OutputWithoutCondition {
        /// The output instruction.
        op: Op,
    },
    /// A standalone instruction (LBL, CALLU) sharing its drawn rung (L007).
    StandaloneShared {
        /// The standalone instruction.
        op: Op,
    },
    /// A standalone instruction in a list before the rung ahead of it ended (L007).
    StandaloneMidRung {
        /// The standalone instruction.
        op: Op,
    },
    /// AND/ANI with no contact before it (L013).
    AndWithoutContact,
    /// OR/ORI with no contact before it (L013).
    OrWithoutContact,
    /// ORB/ANB with no open block to join (L013).
    NoBlockToJoin {
        /// ORB or ANB.
        op: Op,
    },
    /// MPS/MRD/MPP while an LD block is open (L013).
    BranchInBlock,
    /// An output while an LD block is open (L013).
    BlockOpenAtOutput,
    /// The network ends while an LD block is open (L013).
    BlockOpenAtEnd,
    /// MPS with no contact before it (L014).
    MpsWithoutContact,
    /// MRD/MPP with no open MPS (L014).
    NoOpenMps {
        /// MRD or MPP.
        op: Op,
    },
    /// The network ends while an MPS is open (L014).
    BranchOpenAtEnd,
    /// LD/LDI right after an output while an MPS is open (L015).
    LoadAfterOutput,
    /// The network ends with no output (L016).
    NoOutputAtEnd,
    /// OR/ORI after a branch point or output (L017).
    OrAfterNode,
    /// ORB/ANB joining a block that holds an output or a branch point (L017).
    JoinedBlockHasNode,
    /// ORB joining a block to a branch point's path (L017).
    OrbAfterBranchPoint,
}

impl LowerFinding {
    /// The diagnostic code of the finding.
    pub fn code(&self) -> Code {
        match self {
            LowerFinding::ElementNotConnected | LowerFinding::OutputNotConnected { .. } => {
                Code::L001NotConnected
            }
            LowerFinding::OpenElement | LowerFinding::OpenBranch { .. } => Code::L002OpenBranch,
            LowerFinding::ShortCircuit => Code::L003ShortCircuit,
            LowerFinding::Bridge => Code::L004Bridge,
            LowerFinding::OutputLeftOfColumn | LowerFinding::ElementInOutputColumn => {
                Code::L005WrongColumn
            }
            LowerFinding::RungWithoutContact
            | LowerFinding::OutputAtRail
            | LowerFinding::OutputWithoutCondition { .. } => Code::L006NoContact,
            LowerFinding::StandaloneShared { .. } | LowerFinding::StandaloneMidRung { .. } => {
                Code::L007NotStandalone
            }
            LowerFinding::AndWithoutContact
            | LowerFinding::OrWithoutContact
            | LowerFinding::NoBlockToJoin { .. }
            | LowerFinding::BranchInBlock
            | LowerFinding::BlockOpenAtOutput
            | LowerFinding::BlockOpenAtEnd => Code::L013BlockStack,
            LowerFinding::MpsWithoutContact
            | LowerFinding::NoOpenMps { .. }
            | LowerFinding::BranchOpenAtEnd => Code::L014BranchStack,
            LowerFinding::LoadAfterOutput => Code::L015LoadAfterOutput,
            LowerFinding::NoOutputAtEnd => Code::L016NoOutput,
            LowerFinding::OrAfterNode
            | LowerFinding::JoinedBlockHasNode
            | LowerFinding::OrbAfterBranchPoint => Code::L017NotDrawable,
        }
    }
}
