//! Instruction-level checks: operands against the catalogue, labels, calls, stacks, step
//! limits, and the warnings about doubly driven coils and shared timers.

use super::diag::Sink;
use super::finding::CheckFinding;
use super::operands::operand_error;
use super::place::{InstrPlace, location};
use super::rung::Instr;
use super::{Program, StepCounts};
use crate::address::{Address, Area};
use crate::catalog::{InstrClass, Op, Width};
use crate::model::{BlockKind, Operand, Project, SymbolIndex};
use crate::profile::Profile;
use std::collections::{BTreeMap, BTreeSet, HashMap};

/// Block stack limit (docs/plc.md, "Basic instructions").
pub const BLOCK_STACK_DEPTH: usize = 32;
/// Branch (MPS) stack limit (docs/plc.md, "Basic instructions").
pub const BRANCH_STACK_DEPTH: usize = 16;

/// Checks a whole program and resolves its symbols in place. Returns the step counts.
pub fn check_program(program: &mut Program, project: &Project, sink: &mut Sink) -> StepCounts {
    let profile = project.profile();
    let subs = number_subprograms(program, profile, sink);
    let labels = check_instructions(program, &project.symbol_index(), profile, sink);

    super::writes::check_writes(program, profile, sink);
    super::presets::check_presets(program, project, sink);

    // Jumps and calls, now that every label and subprogram is known.
    let calls = check_jumps_and_calls(program, &labels, &subs, sink);
    check_recursion(program, &calls, sink);
    count_steps(program, profile, &calls, sink)
}

/// Each subprogram's number: in the P range, and defined once (L038). Returns the block
/// each number names; the first definition is the one calls reach.
fn number_subprograms(
    program: &Program,
    profile: &Profile,
    sink: &mut Sink,
) -> BTreeMap<u16, usize> {
    let mut subs: BTreeMap<u16, usize> = BTreeMap::new();
    for (b, block) in program.blocks.iter().enumerate() {
        if let BlockKind::Sub { number, .. } = block.kind {
            sink.at(b, &block.kind.label(), 0);
            if !profile.contains(Area::P, u32::from(number)) {
                let (lo, hi) = profile.range(Area::P);
                sink.find(
                    block.origin,
                    CheckFinding::SubNumberRange { number, lo, hi },
                );
            } else if let std::collections::btree_map::Entry::Vacant(e) = subs.entry(number) {
                // The first definition is the one calls reach.
                e.insert(b);
            } else {
                sink.find(block.origin, CheckFinding::SubTwice { number });
            }
        }
    }
    subs
}

/// What the instructions define, in program order, to find the second definition of each:
/// labels (by number), coils and the timers or counters an instruction keeps.
#[derive(Default)]
struct Definitions {
    labels: BTreeMap<u16, InstrPlace>,
    coils: HashMap<Address, InstrPlace>,
    timers: HashMap<Address, InstrPlace>,
}

/// Every instruction's operands (resolving symbols in place), what it defines, and each
/// network's stack depths. Returns the labels, for the jumps.
fn check_instructions(
    program: &mut Program,
    symbols: &SymbolIndex,
    profile: &Profile,
    sink: &mut Sink,
) -> BTreeMap<u16, InstrPlace> {
    let mut defs = Definitions::default();
    for b in 0..program.blocks.len() {
        let label = program.blocks[b].kind.label();
        for n in 0..program.blocks[b].networks.len() {
            sink.at(b, &label, n);
            for k in 0..program.blocks[b].networks[n].instrs.len() {
                let instr = &mut program.blocks[b].networks[n].instrs[k];
                check_operands(instr, symbols, profile, sink);
                let instr = &program.blocks[b].networks[n].instrs[k];
                defs.note(program, instr, (b, n, instr.origin), sink);
            }
            check_stacks(&program.blocks[b].networks[n].instrs, sink);
        }
    }
    defs.labels
}

impl Definitions {
    /// Notes what `instr` at `here` defines, reporting a second definition at the place of
    /// the first: a label (L030), a coil (W001) or a timer or counter (W002).
    fn note(&mut self, program: &Program, instr: &Instr, here: InstrPlace, sink: &mut Sink) {
        let first_addr = instr.operands.first().and_then(Operand::address);
        match instr.op {
            Op::Lbl => {
                if let Some(a) = first_addr {
                    if let Some(prev) = self.labels.get(&a.number) {
                        let first = location(program, *prev);
                        sink.find(instr.origin, CheckFinding::LabelTwice { label: a, first });
                    } else {
                        self.labels.insert(a.number, here);
                    }
                }
            }
            Op::Out | Op::Outn => {
                if let Some(a) = first_addr {
                    if let Some(prev) = self.coils.get(&a) {
                        let first = location(program, *prev);
                        sink.find(instr.origin, CheckFinding::CoilTwice { coil: a, first });
                    } else {
                        self.coils.insert(a, here);
                    }
                }
            }
            _ if let Some((i, area)) = instr.op.spec().memory_operand() => {
                let number = instr.operands.get(i).and_then(Operand::address);
                if let Some(a) = number.filter(|a| a.area == area) {
                    if let Some(prev) = self.timers.get(&a) {
                        let first = location(program, *prev);
                        sink.find(instr.origin, CheckFinding::TimerTwice { number: a, first });
                    } else {
                        self.timers.insert(a, here);
                    }
                }
            }
            _ => {}
        }
    }
}

/// Every JMPB's label defined, in its own block (L031, L032), and every CALL/CALLU's
/// subprogram defined (L033). Returns the calls by calling block: (called block, place).
fn check_jumps_and_calls(
    program: &Program,
    labels: &BTreeMap<u16, InstrPlace>,
    subs: &BTreeMap<u16, usize>,
    sink: &mut Sink,
) -> BTreeMap<usize, Vec<(usize, InstrPlace)>> {
    let mut calls: BTreeMap<usize, Vec<(usize, InstrPlace)>> = BTreeMap::new();
    for (b, block) in program.blocks.iter().enumerate() {
        let label = block.kind.label();
        for (n, net) in block.networks.iter().enumerate() {
            sink.at(b, &label, n);
            for instr in &net.instrs {
                let Some(a) = instr.operands.first().and_then(Operand::address) else {
                    continue;
                };
                match instr.op {
                    Op::Jmpb if a.area == Area::L => match labels.get(&a.number) {
                        None => sink.find(instr.origin, CheckFinding::UndefinedLabel { label: a }),
                        Some(target) if target.0 != b => sink.find(
                            instr.origin,
                            CheckFinding::JumpOutOfBlock {
                                label: a,
                                target: location(program, *target),
                            },
                        ),
                        Some(_) => {}
                    },
                    Op::Call | Op::Callu if a.area == Area::P => match subs.get(&a.number) {
                        None => sink.find(
                            instr.origin,
                            CheckFinding::UndefinedSub {
                                op: instr.op,
                                sub: a,
                            },
                        ),
                        Some(&target) => calls
                            .entry(b)
                            .or_default()
                            .push((target, (b, n, instr.origin))),
                    },
                    _ => {}
                }
            }
        }
    }
    calls
}

/// The program's step counts, and the limits they must keep (L035, L036): level 1 counts
/// the subprograms it reaches through `calls`, since they run within its time.
fn count_steps(
    program: &Program,
    profile: &Profile,
    calls: &BTreeMap<usize, Vec<(usize, InstrPlace)>>,
    sink: &mut Sink,
) -> StepCounts {
    let block_steps: Vec<u32> = program
        .blocks
        .iter()
        .map(|b| {
            b.networks
                .iter()
                .flat_map(|n| &n.instrs)
                .map(|i| i.op.spec().steps(i.operands.len()))
                .sum()
        })
        .collect();
    let reach = |start: usize| {
        let mut seen = BTreeSet::from([start]);
        let mut todo = vec![start];
        while let Some(b) = todo.pop() {
            for (t, _) in calls.get(&b).into_iter().flatten() {
                if seen.insert(*t) {
                    todo.push(*t);
                }
            }
        }
        seen
    };
    let level1: u32 = reach(0).iter().map(|b| block_steps[*b]).sum();
    let total: u32 = block_steps.iter().sum();
    let steps = StepCounts {
        level1,
        level2: block_steps.get(1).copied().unwrap_or(0),
        subprograms: block_steps.iter().skip(2).sum(),
        total,
    };
    sink.at(0, "LEVEL1", 0);
    let head = program.blocks.first().map(|b| b.origin).unwrap_or_default();
    if level1 >= profile.level1_step_limit {
        sink.find(
            head,
            CheckFinding::Level1Steps {
                steps: level1,
                limit: profile.level1_step_limit,
            },
        );
    }
    if total > profile.program_step_limit {
        sink.find(
            head,
            CheckFinding::ProgramSteps {
                steps: total,
                limit: profile.program_step_limit,
            },
        );
    }
    steps
}

fn check_recursion(
    program: &Program,
    calls: &BTreeMap<usize, Vec<(usize, InstrPlace)>>,
    sink: &mut Sink,
) {
    // Depth-first search with colours; a back edge closes a cycle.
    fn visit(
        b: usize,
        calls: &BTreeMap<usize, Vec<(usize, InstrPlace)>>,
        colour: &mut [u8],
        found: &mut Vec<(InstrPlace, usize)>,
    ) {
        colour[b] = 1;
        for (t, place) in calls.get(&b).into_iter().flatten() {
            match colour[*t] {
                0 => visit(*t, calls, colour, found),
                1 => found.push((*place, *t)),
                _ => {}
            }
        }
        colour[b] = 2;
    }
    let mut colour = vec![0u8; program.blocks.len()];
    let mut found = Vec::new();
    for b in 0..program.blocks.len() {
        if colour[b] == 0 {
            visit(b, calls, &mut colour, &mut found);
        }
    }
    for ((b, n, origin), target) in found {
        sink.at(b, &program.blocks[b].kind.label(), n);
        // Calls reach subprograms only (`number_subprograms`), so the target has a number.
        if let Some(callee) = program.blocks[target].kind.sub_number() {
            sink.find(origin, CheckFinding::Recursion { callee });
        }
    }
}

/// Block and branch stack depths of one network.
fn check_stacks(instrs: &[Instr], sink: &mut Sink) {
    let (mut blocks, mut branches) = (0usize, 0usize);
    let mut in_rung = false;
    let mut after_output = false;
    for i in instrs {
        match i.op {
            Op::Ld | Op::Ldi => {
                if in_rung && !after_output {
                    blocks += 1;
                    if blocks == BLOCK_STACK_DEPTH + 1 {
                        let limit = BLOCK_STACK_DEPTH;
                        sink.find(i.origin, CheckFinding::BlockStackDepth { limit });
                    }
                }
                in_rung = true;
            }
            Op::Orb | Op::Anb => blocks = blocks.saturating_sub(1),
            Op::Mps => {
                branches += 1;
                if branches == BRANCH_STACK_DEPTH + 1 {
                    let limit = BRANCH_STACK_DEPTH;
                    sink.find(i.origin, CheckFinding::BranchStackDepth { limit });
                }
            }
            Op::Mpp => branches = branches.saturating_sub(1),
            _ => {}
        }
        after_output =
            matches!(i.op.spec().class, InstrClass::Coil | InstrClass::Function) && branches == 0;
        if after_output {
            blocks = 0;
        }
    }
}

fn const_value(o: Option<&Operand>) -> Option<i64> {
    match o {
        Some(Operand::Int(v)) => Some(*v),
        _ => None,
    }
}

fn check_operands(instr: &mut Instr, symbols: &SymbolIndex, profile: &Profile, sink: &mut Sink) {
    let spec = instr.op.spec();
    let fixed = spec.operands.len();
    let expected = match spec.table {
        Some(t) => const_value(instr.operands.get(t.count_from))
            .and_then(|v| spec.table_len(v))
            .map(|n| t.first + n),
        None => Some(fixed),
    };
    match expected {
        Some(expected) if expected != instr.operands.len() => {
            let (op, found) = (instr.op, instr.operands.len());
            sink.find(
                instr.origin,
                CheckFinding::OperandCount {
                    op,
                    expected,
                    found,
                },
            );
            return;
        }
        None if instr.operands.len() < fixed => {
            let op = instr.op;
            sink.find(instr.origin, CheckFinding::TableOperandCount { op });
            return;
        }
        _ => {}
    }
    // Resolve symbols first so the checks below see addresses.
    for operand in instr.operands.iter_mut() {
        if let Operand::Symbol(name) = operand {
            match symbols.get(name) {
                Some(a) => *operand = Operand::Addr(a),
                None => {
                    let name = name.clone();
                    sink.find(instr.origin, CheckFinding::UndefinedSymbol { name });
                    return;
                }
            }
        }
    }
    for i in 0..instr.operands.len() {
        let Some(ospec) = spec.operand(i) else {
            continue;
        };
        if let Err(refusal) = operand_error(instr.op, &instr.operands, i, profile) {
            sink.find(
                instr.origin,
                CheckFinding::Operand {
                    op: instr.op,
                    operand: ospec.name.to_string(),
                    refusal,
                },
            );
            continue;
        }
        if let (Width::Bits3, Operand::Addr(a)) = (ospec.width, &instr.operands[i])
            && a.bit.is_some_and(|b| b > 5)
        {
            sink.find(
                instr.origin,
                CheckFinding::BitsSpill {
                    op: instr.op,
                    out: *a,
                    next: Address::byte(a.area, a.number + 1),
                },
            );
        }
    }
}
