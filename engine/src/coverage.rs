//! Rung coverage: which elements of a program have been seen both ways while it ran
//! (docs/scripts.md, "Coverage").
//!
//! The VM keeps, per word of code, whether the word read or received 0 and whether 1, and
//! which results a compare took ([`Vm::set_coverage`]); this module places those words back on
//! the program's instructions. A contact is covered once it was seen closed and open where it
//! decided its step of the rung (LD always; a series contact with power reaching it; a
//! parallel one while the branch it joins is off), a coil or a function box once its ACT (the
//! rung's power reaching it) was seen on and off, a compare once each of its three results was
//! seen too; a network is fully covered when all of its elements are. Reports of several runs
//! of one program merge.

use crate::catalog::InstrClass;
use crate::compiler::{Origin, Program};
use crate::il::instr_text;
use crate::vm::Vm;
use serde::{Deserialize, Serialize};

/// The format line of a coverage file.
pub const FORMAT: &str = "ladder-studio coverage 2";

/// How far an element was exercised.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum State {
    /// Never run (or never reached).
    Never,
    /// Seen one way only.
    Half,
    /// Seen both ways.
    Covered,
}

/// One element (a contact, a coil, a function box) and what was seen of it.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct Element {
    /// The instruction as the instruction list writes it (`AND X0002.1`).
    pub il: String,
    /// Its cell in the network's grid (row, column), when it has one.
    pub cell: Option<(u32, u32)>,
    /// Read open (a contact) or without power (an output).
    pub seen0: bool,
    /// Read closed (a contact) or with power (an output).
    pub seen1: bool,
    /// A compare's (CMP, CMPR, ZCP) results seen, in the order of its result bits: greater,
    /// equal, less (ZCP: below, within, above). `None` for every other element.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub outcomes: Option<[bool; 3]>,
}

impl Element {
    /// How far it was exercised: a compare is covered only once each of its results was seen.
    pub fn state(&self) -> State {
        let results = self.outcomes.is_none_or(|o| o.iter().all(|&x| x));
        match (self.seen0, self.seen1) {
            (true, true) if results => State::Covered,
            (false, false) => State::Never,
            _ => State::Half,
        }
    }

    /// The names of a compare's results, in [`Element::outcomes`] order.
    pub fn outcome_names(&self) -> [&'static str; 3] {
        if self.il.starts_with("ZCP") {
            ["below", "within", "above"]
        } else {
            [">", "=", "<"]
        }
    }
}

/// One network's elements.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct NetworkCoverage {
    /// Its block's label (`LEVEL1`, `LEVEL2`, `P0001`).
    pub block: String,
    /// Its index in the block (0-based).
    pub network: usize,
    /// Its title.
    pub title: String,
    /// Its elements, in instruction-list order.
    pub elements: Vec<Element>,
}

impl NetworkCoverage {
    /// Covered when every element is; never when none was seen at all.
    pub fn state(&self) -> State {
        let states = self.elements.iter().map(Element::state);
        if self.elements.iter().all(|e| e.state() == State::Covered) {
            State::Covered
        } else if states.clone().all(|s| s == State::Never) {
            State::Never
        } else {
            State::Half
        }
    }
}

/// The coverage of a whole program.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct Coverage {
    /// [`FORMAT`].
    pub format: String,
    /// Runs merged into this report.
    pub runs: u32,
    /// The networks that have elements, in program order.
    pub networks: Vec<NetworkCoverage>,
}

/// Why two reports cannot be merged, or a file is not a coverage report.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum CoverageError {
    /// The text is not a coverage report.
    #[error("not a coverage file: {0}")]
    NotCoverage(String),
    /// The reports are of different programs.
    #[error("the coverage is of another program (network {0} differs)")]
    OtherProgram(Differs),
}

/// Where two coverage reports first differ (typed, so that it can be said in either language).
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum Differs {
    /// They have different numbers of networks.
    #[error("{ours} networks against {theirs}")]
    Count {
        /// Networks of the report merged into.
        ours: usize,
        /// Networks of the report merged.
        theirs: usize,
    },
    /// This network is not the same in both.
    #[error("{block} N{number:04}")]
    Network {
        /// Its block's label (`LEVEL2`, `P0001`).
        block: String,
        /// Its number, from 1.
        number: usize,
    },
}

/// One line of the summary: a group of blocks and how many of its networks are covered.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Line {
    /// `LEVEL1`, `LEVEL2` or `SUB` (every subprogram).
    pub group: &'static str,
    /// Networks fully covered.
    pub covered: usize,
    /// Networks with elements.
    pub networks: usize,
    /// Elements covered.
    pub elements_covered: usize,
    /// Elements.
    pub elements: usize,
}

impl Line {
    /// The share of networks fully covered, in whole percent (rounded down, so 100 % means
    /// every one).
    pub fn percent(&self) -> usize {
        (self.covered * 100)
            .checked_div(self.networks)
            .unwrap_or(100)
    }
}

impl Coverage {
    /// What the VM has seen since coverage was turned on, placed on `program` (the program it
    /// runs); `None` while coverage is off.
    pub fn measure(vm: &Vm, program: &Program) -> Option<Coverage> {
        let (seen, code) = vm.coverage()?;
        Some(Coverage::from_trace(seen, code, program))
    }

    /// The coverage a trace carries ([`Vm::trace`]: bits 1 and 2 of each word), placed on the
    /// program the code was lowered from (a running machine's published trace, say).
    pub fn from_trace(
        seen: &[u8],
        code: &crate::vm::code::Executable,
        program: &Program,
    ) -> Coverage {
        // Per instruction, what its words saw.
        let mut by_instr: std::collections::HashMap<(usize, usize, usize), u8> =
            std::collections::HashMap::new();
        for (w, src) in code.source.iter().enumerate() {
            if let Some((b, n, i)) = *src {
                let bits = seen.get(w).copied().unwrap_or(0) >> 1;
                let op = code.words().get(w).map_or(u32::MAX, |x| x & 0xFF);
                *by_instr
                    .entry((usize::from(b), n as usize, i as usize))
                    .or_default() |= if op < crate::vm::code::CONTACT_END {
                    contact_seen(op, bits)
                } else {
                    bits
                };
            }
        }
        let mut networks = Vec::new();
        for (b, block) in program.blocks.iter().enumerate() {
            for (n, net) in block.networks.iter().enumerate() {
                let elements: Vec<Element> = net
                    .instrs
                    .iter()
                    .enumerate()
                    .filter(|(_, ins)| counted(ins.op))
                    .map(|(i, ins)| {
                        let bits = by_instr.get(&(b, n, i)).copied().unwrap_or(0);
                        Element {
                            il: instr_text(ins.op, &ins.operands)
                                .split_whitespace()
                                .collect::<Vec<_>>()
                                .join(" "),
                            cell: match ins.origin {
                                Origin::Cell { row, col } => Some((row, col)),
                                _ => None,
                            },
                            seen0: bits & 1 != 0,
                            seen1: bits & 2 != 0,
                            outcomes: compares(ins.op).then_some([
                                bits & 4 != 0,
                                bits & 8 != 0,
                                bits & 16 != 0,
                            ]),
                        }
                    })
                    .collect();
                if !elements.is_empty() {
                    networks.push(NetworkCoverage {
                        block: block.kind.label(),
                        network: n,
                        title: net.title.clone(),
                        elements,
                    });
                }
            }
        }
        Coverage {
            format: FORMAT.into(),
            runs: 1,
            networks,
        }
    }

    /// Adds what `other`, a run of the same program, saw.
    pub fn merge(&mut self, other: &Coverage) -> Result<(), CoverageError> {
        let same = |a: &NetworkCoverage, b: &NetworkCoverage| {
            a.block == b.block
                && a.network == b.network
                && a.elements.len() == b.elements.len()
                && a.elements
                    .iter()
                    .zip(&b.elements)
                    .all(|(x, y)| x.il == y.il)
        };
        if self.networks.len() != other.networks.len() {
            return Err(CoverageError::OtherProgram(Differs::Count {
                ours: self.networks.len(),
                theirs: other.networks.len(),
            }));
        }
        if let Some((a, _)) = self
            .networks
            .iter()
            .zip(&other.networks)
            .find(|(a, b)| !same(a, b))
        {
            return Err(CoverageError::OtherProgram(Differs::Network {
                block: a.block.clone(),
                number: a.network + 1,
            }));
        }
        for (a, b) in self.networks.iter_mut().zip(&other.networks) {
            for (x, y) in a.elements.iter_mut().zip(&b.elements) {
                x.seen0 |= y.seen0;
                x.seen1 |= y.seen1;
                if let (Some(o), Some(p)) = (&mut x.outcomes, y.outcomes) {
                    for (u, v) in o.iter_mut().zip(p) {
                        *u |= v;
                    }
                }
            }
        }
        self.runs += other.runs;
        Ok(())
    }

    /// Per group of blocks (level 1, level 2, the subprograms), networks and elements
    /// covered; groups without networks are left out.
    pub fn summary(&self) -> Vec<Line> {
        let group = |label: &str| match label {
            "LEVEL1" => "LEVEL1",
            "LEVEL2" => "LEVEL2",
            _ => "SUB",
        };
        ["LEVEL1", "LEVEL2", "SUB"]
            .into_iter()
            .filter_map(|g| {
                let nets: Vec<&NetworkCoverage> = self
                    .networks
                    .iter()
                    .filter(|n| group(&n.block) == g)
                    .collect();
                let elements = nets.iter().flat_map(|n| &n.elements);
                (!nets.is_empty()).then(|| Line {
                    group: g,
                    covered: nets.iter().filter(|n| n.state() == State::Covered).count(),
                    networks: nets.len(),
                    elements_covered: elements
                        .clone()
                        .filter(|e| e.state() == State::Covered)
                        .count(),
                    elements: elements.count(),
                })
            })
            .collect()
    }

    /// The report as JSON.
    pub fn to_json(&self) -> String {
        serde_json::to_string_pretty(self).unwrap_or_default()
    }

    /// A report read back from its JSON.
    pub fn from_json(text: &str) -> Result<Coverage, CoverageError> {
        let c: Coverage =
            serde_json::from_str(text).map_err(|e| CoverageError::NotCoverage(e.to_string()))?;
        if c.format != FORMAT {
            return Err(CoverageError::NotCoverage(format!(
                "format \"{}\", not \"{FORMAT}\"",
                c.format
            )));
        }
        Ok(c)
    }
}

/// A contact's values seen where it decided its step (bit 0 open, bit 1 closed), from the
/// pairs of value and accumulator its word recorded (bit 2·value + acc).
fn contact_seen(op: u32, pairs: u8) -> u8 {
    let mut out = 0;
    for value in 0..2u32 {
        for acc in 0..2u32 {
            if pairs >> (value << 1 | acc) & 1 == 1 && crate::vm::decides(op, acc) {
                out |= 1 << value;
            }
        }
    }
    out
}

/// Whether an instruction is a compare whose results coverage tells apart.
fn compares(op: crate::catalog::Op) -> bool {
    use crate::catalog::Op;
    matches!(op, Op::Cmp | Op::Cmpr | Op::Zcp)
}

/// Whether an instruction is an element coverage counts: contacts, and the outputs that take
/// the rung's power (LBL and CALLU stand alone; block and branch operations are no element).
fn counted(op: crate::catalog::Op) -> bool {
    let spec = op.spec();
    match spec.class {
        InstrClass::Contact => true,
        InstrClass::Coil | InstrClass::Function => spec.needs_act(),
        InstrClass::Stack => false,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::il;
    use crate::machine::Machine;
    use crate::model::Project;

    /// Runs `text` with coverage on, `scans` times with the inputs `set` before each scan.
    fn run(text: &str, inputs: &[&[(&str, bool)]]) -> Coverage {
        let imported = il::import(text);
        assert_eq!(
            imported.compiled.errors(),
            0,
            "{:?}",
            imported.compiled.diagnostics
        );
        let program = imported.compiled.program;
        let mut m = Machine::from_program(&Project::default(), &program, false).unwrap();
        m.plc_mut().set_coverage(true);
        for scan in inputs {
            for (a, v) in *scan {
                let a = crate::address::Address::parse(a).unwrap();
                m.plc_mut().write(a, 1, i64::from(*v));
            }
            m.tick();
        }
        Coverage::measure(m.plc(), &program).unwrap()
    }

    #[test]
    fn a_branch_never_taken_leaves_its_network_half_covered() {
        let text = "LEVEL1\nNETWORK \"two branches\"\nLD X0000.0\nOR X0000.1\nOUT Y0000.0\nLEVEL2\nNETWORK \"idle\"\nLD R0000.0\nOUT R0000.1\n";
        let c = run(
            text,
            &[
                &[("X0000.0", false)],
                &[("X0000.0", true)],
                &[("X0000.0", false)],
            ],
        );
        let n = &c.networks[0];
        let states: Vec<(&str, State)> = n
            .elements
            .iter()
            .map(|e| (e.il.as_str(), e.state()))
            .collect();
        assert_eq!(
            states,
            [
                ("LD X0000.0", State::Covered),
                ("OR X0000.1", State::Half),
                ("OUT Y0000.0", State::Covered)
            ]
        );
        assert_eq!(n.state(), State::Half);
        // Level 2's rung never saw R0000.0 set: half covered too.
        assert_eq!(c.networks[1].state(), State::Half);
        let lines = c.summary();
        assert_eq!(
            (
                lines[0].group,
                lines[0].covered,
                lines[0].networks,
                lines[0].elements_covered,
                lines[0].elements
            ),
            ("LEVEL1", 0, 1, 2, 3)
        );
        assert_eq!(lines[0].percent(), 0);
    }

    #[test]
    fn runs_of_one_program_merge_and_another_program_is_refused() {
        let text = "LEVEL1\nNETWORK \"or\"\nLD X0000.0\nOR X0000.1\nOUT Y0000.0\n";
        let mut a = run(text, &[&[("X0000.0", true)], &[("X0000.0", false)]]);
        let b = run(text, &[&[("X0000.1", true)], &[("X0000.1", false)]]);
        a.merge(&b).unwrap();
        assert_eq!(a.runs, 2);
        assert_eq!(a.networks[0].state(), State::Covered);
        assert_eq!(a.summary()[0].percent(), 100);
        let other = run("LEVEL1\nNETWORK \"x\"\nLD X0000.2\nOUT Y0000.0\n", &[&[]]);
        assert!(matches!(
            a.merge(&other),
            Err(CoverageError::OtherProgram(_))
        ));
        let back = Coverage::from_json(&a.to_json()).unwrap();
        assert_eq!(back, a);
        assert!(Coverage::from_json("{}").is_err());
    }

    #[test]
    fn a_subprogram_never_called_is_never_covered_and_off_costs_nothing() {
        let text = "LEVEL1\nNETWORK \"n\"\nLD X0000.0\nOUT Y0000.0\nLEVEL2\nNETWORK \"call\"\nLD R0000.0\nCALL P0001\nSUB P0001\nNETWORK \"s\"\nLD X0000.3\nOUT Y0000.3\n";
        let c = run(text, &[&[("X0000.0", true)], &[("X0000.0", false)]]);
        let sub = c.networks.iter().find(|n| n.block == "P0001").unwrap();
        assert_eq!(sub.state(), State::Never);
        // Off, nothing is measured.
        let imported = il::import(text);
        let m =
            Machine::from_program(&Project::default(), &imported.compiled.program, false).unwrap();
        assert!(Coverage::measure(m.plc(), &imported.compiled.program).is_none());
    }
}
