//! Diagnostics: a stable code, a severity, a location and a message that says how to fix it.
//!
//! Every code has a line with an example in `docs/diagnostics.md`.

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
    W001CoilTwice,
    W002TimerTwice,
    W003BitsSpill,
    W004AddressTwice,
    W005MessageHalf,
    W006VersionLength,
    W007CommentLength,
}

impl Code {
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

/// One finding of the compiler.
#[derive(Clone, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct Diagnostic {
    /// Where.
    pub location: Location,
    /// Which check.
    pub code: Code,
    /// What is wrong and how to fix it.
    pub message: String,
}

impl Diagnostic {
    /// Error or warning.
    pub fn severity(&self) -> Severity {
        self.code.severity()
    }

    /// Formats the diagnostic as `check` prints it (docs/files.md, "Diagnostics"), with `path`
    /// in front: `PATH:BLOCK:NETWORK:ROW:COL: error: MESSAGE` for ladder cells (1-based), or
    /// `PATH:LINE: error: MESSAGE` for IL lines.
    pub fn render(&self, path: &str) -> String {
        let l = &self.location;
        let place = match l.origin {
            Origin::Line(line) => format!("{path}:{line}"),
            Origin::Cell { row, col } => format!(
                "{path}:{}:{}:{}:{}",
                l.block_label,
                l.network + 1,
                row + 1,
                col + 1
            ),
            Origin::None => format!("{path}:{}:{}:0:0", l.block_label, l.network + 1),
        };
        format!(
            "{place}: {}: {} [{}]",
            self.severity(),
            self.message,
            self.code.as_str()
        )
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

    /// Reports at `origin` in the current network.
    pub fn report(&mut self, origin: Origin, code: Code, message: impl Into<String>) {
        self.diagnostics.push(Diagnostic {
            location: Location {
                block: self.block,
                block_label: self.block_label.clone(),
                network: self.network,
                origin,
            },
            code,
            message: message.into(),
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
