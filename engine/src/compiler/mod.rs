//! The compiler: ladder → instruction list, with checks that point at the cell (or IL line)
//! and say how to fix what they find.
//!
//! Phases: `lower` reads each network's grid as rung trees (structure checks), `rung`
//! emits their instructions, `check` checks operands, labels, calls, stacks and step
//! limits against the catalogue and the profile, `writes` looks for outputs two instructions
//! fight over, `presets` for table presets out of their instruction's range. The IL importer
//! runs the other way through `decompile` and `layout`; `written` keeps an imported network's
//! list as written.
//!
//! The phases are private to the engine: the rest of the workspace compiles through
//! [`compile`] and [`compile_program`] and reads a [`Compiled`] program and its
//! [`Diagnostic`]s. What the editor needs beside them is re-exported here: the operand check
//! it colours and refuses operands with ([`operand_ok`], [`operand_error`], [`OperandRefusal`]),
//! and the pseudo-blocks a diagnostic of a table or the machine model points at
//! ([`pseudo_blocks`]).

pub(crate) mod check;
pub(crate) mod cnc;
#[cfg(test)]
mod cnc_tests;
pub(crate) mod decompile;
pub(crate) mod diag;
pub mod finding;
pub(crate) mod flow;
pub(crate) mod layout;
pub(crate) mod lower;
pub(crate) mod machine;
pub(crate) mod operands;
mod place;
pub(crate) mod presets;
#[cfg(test)]
mod roundtrip_tests;
pub(crate) mod rung;
pub(crate) mod tables;
pub(crate) mod text;
#[cfg(test)]
mod warn_tests;
pub(crate) mod writes;
pub(crate) mod written;
#[cfg(test)]
mod written_tests;

pub use diag::{Code, Diagnostic, Location, Origin, Severity, Sink};
pub use finding::{
    CheckFinding, Finding, IlFinding, LowerFinding, MachineFinding, ScenarioFinding, SignalFinding,
    TableFinding,
};
pub use operands::{OperandRefusal, operand_error, operand_ok};
pub use rung::Instr;

/// The pseudo-blocks of [`Location::block`]: a diagnostic of a table or of the machine model
/// is not in a ladder block, so its "block" is one of these numbers (at the top of `usize`,
/// past any ladder block) and its "network" the table's number or the device's index.
pub mod pseudo_blocks {
    pub use super::machine::MACHINE;
    pub use super::tables::{DATA, DIAGNOSIS, MCODES, MESSAGES, PERMISSIONS, SYMBOLS, VERSION};
}

use crate::model::{BlockKind, Project};

/// A compiled network: its texts and instructions.
#[derive(Clone, Debug, PartialEq)]
pub struct ProgramNetwork {
    /// Title.
    pub title: String,
    /// Comment.
    pub comment: String,
    /// Instructions in order.
    pub instrs: Vec<Instr>,
    /// Whether a line of the network could not be parsed (its instructions are incomplete, so
    /// structure checks would only repeat the syntax error).
    pub broken: bool,
}

/// A compiled block.
#[derive(Clone, Debug, PartialEq)]
pub struct ProgramBlock {
    /// Which block.
    pub kind: BlockKind,
    /// Where its header is (IL line), for block-level diagnostics.
    pub origin: Origin,
    /// Its networks.
    pub networks: Vec<ProgramNetwork>,
}

/// An instruction list: level 1, level 2, then subprograms.
#[derive(Clone, Debug, PartialEq, Default)]
pub struct Program {
    /// The blocks.
    pub blocks: Vec<ProgramBlock>,
}

impl Program {
    /// Every instruction with its block and network index.
    pub fn instrs(&self) -> impl Iterator<Item = (usize, usize, &Instr)> {
        self.blocks.iter().enumerate().flat_map(|(b, block)| {
            block
                .networks
                .iter()
                .enumerate()
                .flat_map(move |(n, net)| net.instrs.iter().map(move |i| (b, n, i)))
        })
    }
}

/// Steps per part of the program (docs/plc.md, "Blocks and steps": a basic instruction is 1
/// step, a function instruction 1 + its operands).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct StepCounts {
    /// Level 1 plus every subprogram it reaches (each once).
    pub level1: u32,
    /// Level 2 alone.
    pub level2: u32,
    /// All subprograms.
    pub subprograms: u32,
    /// The whole program.
    pub total: u32,
}

/// What the compiler produced.
#[derive(Clone, Debug)]
pub struct Compiled {
    /// The instruction list, symbols resolved to addresses.
    pub program: Program,
    /// Errors and warnings, in program order.
    pub diagnostics: Vec<Diagnostic>,
    /// Step counts.
    pub steps: StepCounts,
}

impl Compiled {
    /// The result with `more` diagnostics, all in the one order: IL diagnostics read best in
    /// line order, ladder ones in block, network, cell order.
    pub fn with(mut self, more: Vec<Diagnostic>) -> Compiled {
        self.diagnostics.extend(more);
        self.diagnostics.sort_by(|a, b| {
            let key = |d: &Diagnostic| match d.location.origin {
                Origin::Line(l) => (0, l, None),
                _ => (1, 0, Some(d.location.clone())),
            };
            key(a).cmp(&key(b)).then(a.code.cmp(&b.code))
        });
        self.diagnostics.dedup();
        self
    }

    /// Number of errors.
    pub fn errors(&self) -> usize {
        self.diagnostics
            .iter()
            .filter(|d| d.severity() == Severity::Error)
            .count()
    }

    /// Number of warnings.
    pub fn warnings(&self) -> usize {
        self.diagnostics.len() - self.errors()
    }
}

/// Emits a project's ladder as an instruction list, without checks beyond the structure.
fn ladder_program(project: &Project, sink: &mut Sink) -> Program {
    let width = project.ladder.width;
    let mut program = Program::default();
    for (b, block) in project.ladder.blocks.iter().enumerate() {
        let label = block.kind.label();
        let mut networks = Vec::with_capacity(block.networks.len());
        for (n, net) in block.networks.iter().enumerate() {
            sink.at(b, &label, n);
            let rungs = lower::lower_network(net, width, sink);
            let mut instrs = Vec::new();
            rung::emit(&rungs, &mut instrs);
            // An imported network runs and exports as it was written while it is unchanged.
            if let Some(kept) = written::as_written(net, &instrs) {
                instrs = kept;
            }
            networks.push(ProgramNetwork {
                title: net.title.clone(),
                comment: net.comment.clone(),
                instrs,
                broken: false,
            });
        }
        program.blocks.push(ProgramBlock {
            kind: block.kind.clone(),
            origin: Origin::None,
            networks,
        });
    }
    program
}

/// Compiles a project's ladder: structure, operands, labels, calls, limits, the tables, the
/// CNC-aware checks and the machine model. Saved scenarios are checked above the compiler,
/// by `diagnose`, which the commands and the editor call for the whole list.
pub fn compile(project: &Project) -> Compiled {
    let mut sink = Sink::default();
    let mut program = ladder_program(project, &mut sink);
    let steps = check::check_program(&mut program, project, &mut sink);
    // Before the tables' checks: an error there says nothing about the program's data flow.
    cnc::check_cnc(project, &program, &mut sink);
    tables::check_tables(project, &mut sink);
    machine::check_machine(project, &program, &mut sink);
    finish(program, sink, steps)
}

/// Checks an already parsed program (from IL) against a project's symbols and profile.
pub fn compile_program(mut program: Program, project: &Project, mut sink: Sink) -> Compiled {
    let steps = check::check_program(&mut program, project, &mut sink);
    cnc::check_cnc(project, &program, &mut sink);
    finish(program, sink, steps)
}

fn finish(program: Program, sink: Sink, steps: StepCounts) -> Compiled {
    Compiled {
        program,
        diagnostics: Vec::new(),
        steps,
    }
    .with(sink.diagnostics)
}
