//! Diagnostics: a stable code, a severity, a location and a message that says how to fix it.
//!
//! Every code has a line with an example in `docs/diagnostics.md`.

use super::finding::Finding;
use std::fmt;

/// How bad a diagnostic is.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Severity {
    /// The program still compiles.
    Warning,
    /// The program does not compile.
    Error,
}

impl fmt::Display for Severity {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Severity::Warning => "warning",
            Severity::Error => "error",
        })
    }
}

/// Where an element or instruction came from: a grid cell of its network, or an IL line.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord, Default)]
pub enum Origin {
    /// Not tied to a place (generated code).
    #[default]
    None,
    /// Row and column (0-based) in the network's grid.
    Cell {
        /// Row, 0-based.
        row: u32,
        /// Column, 0-based.
        col: u32,
    },
    /// Line (1-based) of an instruction-list text.
    Line(u32),
}

/// Where a diagnostic points.
#[derive(Clone, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct Location {
    /// Block index in the ladder.
    pub block: usize,
    /// Block label (`LEVEL1`, `LEVEL2`, `P0001`).
    pub block_label: String,
    /// Network index in the block.
    pub network: usize,
    /// Cell or line in that network.
    pub origin: Origin,
}

/// Stable diagnostic codes.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
#[allow(missing_docs)] // Each code is documented in docs/diagnostics.md with an example.
pub enum Code {
    L001NotConnected,
    L002OpenBranch,
    L003ShortCircuit,
    L004Bridge,
    L005WrongColumn,
    L006NoContact,
    L007NotStandalone,
    L010UnknownInstruction,
    L011OperandCount,
    L012Syntax,
    L013BlockStack,
    L014BranchStack,
    L015LoadAfterOutput,
    L016NoOutput,
    L017NotDrawable,
    L018StackDepth,
    L020UndefinedSymbol,
    L021OperandKind,
    L022Area,
    L023AddressRange,
    L024ConstRange,
    L025ReadOnly,
    L030LabelTwice,
    L031UndefinedLabel,
    L032JumpOutOfBlock,
    L033UndefinedSub,
    L034Recursion,
    L035Level1Steps,
    L036ProgramSteps,
    L038SubNumber,
    T001SymbolName,
    T002SymbolTwice,
    T003DataAddress,
    T004DataValue,
    T005MessageNumber,
    T006TableName,
    T007SymbolArea,
    T008TableKey,
    M001DeviceName,
    M002DeviceAddress,
    M003DeviceParameter,
    M004DeviceCondition,
    M005InputTwice,
    W001CoilTwice,
    W002TimerTwice,
    W003BitsSpill,
    W004AddressTwice,
    W005MessageHalf,
    W006VersionLength,
    W007CommentLength,
    W008OutputTwice,
    W009PresetRange,
    W010DeviceReadsNothing,
    W011PanelDrivesDeviceInput,
    /// Strobe with no path to its finish signal.
    W012StrobeNoFinish,
    /// Finish signal written by several rungs or latched.
    W013FinishWriters,
    /// M-code table and decoding disagree.
    W014MCodeTable,
    /// Emergency stop, reset or mode signal never written.
    W015CncSignalUnwritten,
    /// Answer read but its request never written.
    W016RequestUnwritten,
    /// Alarm bit without a message row.
    W017AlarmNoMessage,
    /// Message row whose alarm bit is never set.
    W018MessageNeverSet,
    /// Saved scenario that cannot be applied.
    W019ScenarioBroken,
}

impl Code {
    /// Every code, in the order of docs/diagnostics.md.
    pub const ALL: &'static [Code] = &[
        Code::L001NotConnected,
        Code::L002OpenBranch,
        Code::L003ShortCircuit,
        Code::L004Bridge,
        Code::L005WrongColumn,
        Code::L006NoContact,
        Code::L007NotStandalone,
        Code::L010UnknownInstruction,
        Code::L011OperandCount,
        Code::L012Syntax,
        Code::L013BlockStack,
        Code::L014BranchStack,
        Code::L015LoadAfterOutput,
        Code::L016NoOutput,
        Code::L017NotDrawable,
        Code::L018StackDepth,
        Code::L020UndefinedSymbol,
        Code::L021OperandKind,
        Code::L022Area,
        Code::L023AddressRange,
        Code::L024ConstRange,
        Code::L025ReadOnly,
        Code::L030LabelTwice,
        Code::L031UndefinedLabel,
        Code::L032JumpOutOfBlock,
        Code::L033UndefinedSub,
        Code::L034Recursion,
        Code::L035Level1Steps,
        Code::L036ProgramSteps,
        Code::L038SubNumber,
        Code::T001SymbolName,
        Code::T002SymbolTwice,
        Code::T003DataAddress,
        Code::T004DataValue,
        Code::T005MessageNumber,
        Code::T006TableName,
        Code::T007SymbolArea,
        Code::T008TableKey,
        Code::M001DeviceName,
        Code::M002DeviceAddress,
        Code::M003DeviceParameter,
        Code::M004DeviceCondition,
        Code::M005InputTwice,
        Code::W001CoilTwice,
        Code::W002TimerTwice,
        Code::W003BitsSpill,
        Code::W004AddressTwice,
        Code::W005MessageHalf,
        Code::W006VersionLength,
        Code::W007CommentLength,
        Code::W008OutputTwice,
        Code::W009PresetRange,
        Code::W010DeviceReadsNothing,
        Code::W011PanelDrivesDeviceInput,
        Code::W012StrobeNoFinish,
        Code::W013FinishWriters,
        Code::W014MCodeTable,
        Code::W015CncSignalUnwritten,
        Code::W016RequestUnwritten,
        Code::W017AlarmNoMessage,
        Code::W018MessageNeverSet,
        Code::W019ScenarioBroken,
    ];

    /// The code as printed: `L012`, `W001`.
    pub fn as_str(self) -> &'static str {
        match self {
            Code::L001NotConnected => "L001",
            Code::L002OpenBranch => "L002",
            Code::L003ShortCircuit => "L003",
            Code::L004Bridge => "L004",
            Code::L005WrongColumn => "L005",
            Code::L006NoContact => "L006",
            Code::L007NotStandalone => "L007",
            Code::L010UnknownInstruction => "L010",
            Code::L011OperandCount => "L011",
            Code::L012Syntax => "L012",
            Code::L013BlockStack => "L013",
            Code::L014BranchStack => "L014",
            Code::L015LoadAfterOutput => "L015",
            Code::L016NoOutput => "L016",
            Code::L017NotDrawable => "L017",
            Code::L018StackDepth => "L018",
            Code::L020UndefinedSymbol => "L020",
            Code::L021OperandKind => "L021",
            Code::L022Area => "L022",
            Code::L023AddressRange => "L023",
            Code::L024ConstRange => "L024",
            Code::L025ReadOnly => "L025",
            Code::L030LabelTwice => "L030",
            Code::L031UndefinedLabel => "L031",
            Code::L032JumpOutOfBlock => "L032",
            Code::L033UndefinedSub => "L033",
            Code::L034Recursion => "L034",
            Code::L035Level1Steps => "L035",
            Code::L036ProgramSteps => "L036",
            Code::L038SubNumber => "L038",
            Code::T001SymbolName => "T001",
            Code::T002SymbolTwice => "T002",
            Code::T003DataAddress => "T003",
            Code::T004DataValue => "T004",
            Code::T005MessageNumber => "T005",
            Code::T006TableName => "T006",
            Code::T007SymbolArea => "T007",
            Code::T008TableKey => "T008",
            Code::W004AddressTwice => "W004",
            Code::W005MessageHalf => "W005",
            Code::W006VersionLength => "W006",
            Code::W007CommentLength => "W007",
            Code::W008OutputTwice => "W008",
            Code::W009PresetRange => "W009",
            Code::M001DeviceName => "M001",
            Code::M002DeviceAddress => "M002",
            Code::M003DeviceParameter => "M003",
            Code::M004DeviceCondition => "M004",
            Code::M005InputTwice => "M005",
            Code::W010DeviceReadsNothing => "W010",
            Code::W011PanelDrivesDeviceInput => "W011",
            Code::W012StrobeNoFinish => "W012",
            Code::W013FinishWriters => "W013",
            Code::W014MCodeTable => "W014",
            Code::W015CncSignalUnwritten => "W015",
            Code::W016RequestUnwritten => "W016",
            Code::W017AlarmNoMessage => "W017",
            Code::W018MessageNeverSet => "W018",
            Code::W019ScenarioBroken => "W019",
            Code::W001CoilTwice => "W001",
            Code::W002TimerTwice => "W002",
            Code::W003BitsSpill => "W003",
        }
    }

    /// Whether the problem leaves a network without a valid instruction list (export is
    /// refused: the list would not be what the ladder says).
    pub fn is_structural(self) -> bool {
        matches!(
            self,
            Code::L001NotConnected
                | Code::L002OpenBranch
                | Code::L003ShortCircuit
                | Code::L004Bridge
                | Code::L005WrongColumn
                | Code::L006NoContact
                | Code::L007NotStandalone
                | Code::L010UnknownInstruction
                | Code::L011OperandCount
                | Code::L012Syntax
                | Code::L013BlockStack
                | Code::L014BranchStack
                | Code::L015LoadAfterOutput
                | Code::L016NoOutput
                | Code::L017NotDrawable
        )
    }

    /// Warnings start with `W`, errors with `L`.
    pub fn severity(self) -> Severity {
        if self.as_str().starts_with('W') {
            Severity::Warning
        } else {
            Severity::Error
        }
    }
}

/// One finding of the compiler: where, which check, and what it found as data
/// (`ladder_text::diagnostics` words it, with how to fix it).
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct Diagnostic {
    /// Where.
    pub location: Location,
    /// Which check: always `finding.code()`, kept beside it to match on.
    pub code: Code,
    /// What is wrong, with the addresses, names, numbers and places it is about.
    pub finding: Finding,
}

impl Diagnostic {
    /// Error or warning.
    pub fn severity(&self) -> Severity {
        self.code.severity()
    }
}

impl Location {
    /// The ladder cell it points at, when it points at one (a click on the diagnostic goes
    /// there; the diagram marks it).
    pub fn cell(&self) -> Option<crate::model::CellRef> {
        match self.origin {
            Origin::Cell { row, col } => Some(crate::model::CellRef {
                block: self.block,
                network: self.network,
                row: row as usize,
                col: col as usize,
            }),
            _ => None,
        }
    }
}

/// Collects diagnostics for one block and network at a time.
#[derive(Debug, Default)]
pub struct Sink {
    /// Everything reported so far.
    pub diagnostics: Vec<Diagnostic>,
    block: usize,
    block_label: String,
    network: usize,
}

impl Sink {
    /// Sets the block and network that following reports are about.
    pub fn at(&mut self, block: usize, block_label: &str, network: usize) {
        self.block = block;
        if self.block_label != block_label {
            self.block_label = block_label.to_string();
        }
        self.network = network;
    }

    /// Reports `finding` at `origin` in the current network.
    pub fn find(&mut self, origin: Origin, finding: impl Into<Finding>) {
        let finding = finding.into();
        self.diagnostics.push(Diagnostic {
            location: Location {
                block: self.block,
                block_label: self.block_label.clone(),
                network: self.network,
                origin,
            },
            code: finding.code(),
            finding,
        });
    }

    /// Number of errors so far.
    pub fn error_count(&self) -> usize {
        self.diagnostics
            .iter()
            .filter(|d| d.severity() == Severity::Error)
            .count()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_list_of_codes_is_the_documented_list() {
        let doc = include_str!("../../../docs/diagnostics.md");
        let documented: Vec<&str> = doc
            .lines()
            .filter_map(|l| l.strip_prefix("| "))
            .filter_map(|l| l.split(' ').next())
            .filter(|c| c.len() == 4 && c[1..].bytes().all(|b| b.is_ascii_digit()))
            .collect();
        let listed: Vec<&str> = Code::ALL.iter().map(|c| c.as_str()).collect();
        assert_eq!(listed, documented);
    }
}
