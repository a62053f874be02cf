//! Instruction-level checks: operands against the catalogue, labels, calls, stacks, step
//! limits, and the warnings about doubly driven coils and shared timers.

use super::diag::{Code, Sink};
use super::operands::operand_error;
use super::place::{InstrPlace, place_text, place_text_zh};
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
                sink.report(
                    block.origin,
                    Code::L038SubNumber,
                    format!("subprogram number P{number:04} is out of range (P{lo}–P{hi})"),
                    format!("子程序号 P{number:04} 超出范围（P{lo}–P{hi}）"),
                );
            } else if let std::collections::btree_map::Entry::Vacant(e) = subs.entry(number) {
                // The first definition is the one calls reach.
                e.insert(b);
            } else {
                sink.report(
                    block.origin,
                    Code::L038SubNumber,
                    format!(
                        "subprogram P{number:04} is defined twice: give one of them another number"
                    ),
                    format!("子程序 P{number:04} 重复定义：请给其中一个换一个子程序号"),
                );
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
                        sink.report(
                            instr.origin,
                            Code::L030LabelTwice,
                            format!(
                                "label {a} is already defined at {}; each label is defined once in the project",
                                place_text(program, *prev)
                            ),
                            format!(
                                "标号 {a} 已在 {} 定义；工程中每个标号只能定义一次",
                                place_text_zh(program, *prev)
                            ),
                        );
                    } else {
                        self.labels.insert(a.number, here);
                    }
                }
            }
            Op::Out | Op::Outn => {
                if let Some(a) = first_addr {
                    if let Some(prev) = self.coils.get(&a) {
                        sink.report(
                            instr.origin,
                            Code::W001CoilTwice,
                            format!(
                                "coil {a} is also driven at {}; the later one wins each scan",
                                place_text(program, *prev)
                            ),
                            format!(
                                "线圈 {a} 也在 {} 输出；每次扫描以后面的输出为准",
                                place_text_zh(program, *prev)
                            ),
                        );
                    } else {
                        self.coils.insert(a, here);
                    }
                }
            }
            _ if let Some((i, area)) = instr.op.spec().memory_operand() => {
                let number = instr.operands.get(i).and_then(Operand::address);
                if let Some(a) = number.filter(|a| a.area == area) {
                    if let Some(prev) = self.timers.get(&a) {
                        sink.report(
                            instr.origin,
                            Code::W002TimerTwice,
                            format!(
                                "{a} is also used by the instruction at {}; two instructions sharing a timer or counter disturb each other",
                                place_text(program, *prev)
                            ),
                            format!(
                                "{a} 也被 {} 的指令使用；两条指令共用一个定时器或计数器会互相干扰",
                                place_text_zh(program, *prev)
                            ),
                        );
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
                        None => sink.report(
                            instr.origin,
                            Code::L031UndefinedLabel,
                            format!("JMPB to {a}, which no LBL defines: add `LBL {a}` in this block or correct the label"),
                            format!("JMPB 跳转到 {a}，但没有 LBL 定义该标号：请在本程序块中加入 `LBL {a}`，或改正标号"),
                        ),
                        Some(target) if target.0 != b => sink.report(
                            instr.origin,
                            Code::L032JumpOutOfBlock,
                            format!(
                                "JMPB to {a} at {}: a jump stays inside its own block (use CALL to reach a subprogram)",
                                place_text(program, *target)
                            ),
                            format!(
                                "JMPB 跳转到位于 {} 的 {a}：跳转只能在本程序块内进行（要进入子程序请用 CALL）",
                                place_text_zh(program, *target)
                            ),
                        ),
                        Some(_) => {}
                    },
                    Op::Call | Op::Callu if a.area == Area::P => match subs.get(&a.number) {
                        None => sink.report(
                            instr.origin,
                            Code::L033UndefinedSub,
                            format!("{} {a}: there is no subprogram {a}; create it or correct the number", instr.op.name()),
                            format!("{} {a}：不存在子程序 {a}；请新建该子程序或改正子程序号", instr.op.name()),
                        ),
                        Some(&target) => calls.entry(b).or_default().push((target, (b, n, instr.origin))),
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
        sink.report(
            head,
            Code::L035Level1Steps,
            format!(
                "level 1 has {level1} steps with the subprograms it calls; it must stay under {} (move work to level 2)",
                profile.level1_step_limit
            ),
            format!(
                "一级程序连同其调用的子程序共 {level1} 步；必须少于 {} 步（请把部分程序移到二级程序）",
                profile.level1_step_limit
            ),
        );
    }
    if total > profile.program_step_limit {
        sink.report(
            head,
            Code::L036ProgramSteps,
            format!(
                "the program has {total} steps; at most {} fit the PLC",
                profile.program_step_limit
            ),
            format!(
                "程序共 {total} 步；PLC 最多容纳 {} 步",
                profile.program_step_limit
            ),
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
        sink.report(
            origin,
            Code::L034Recursion,
            format!(
                "this call of {} makes the subprograms call themselves in a loop, which never ends within a scan",
                program.blocks[target].kind.label()
            ),
            format!(
                "此处调用 {} 使子程序循环调用自身，一次扫描内永远不会结束",
                program.blocks[target].kind.label()
            ),
        );
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
                        sink.report(
                            i.origin,
                            Code::L018StackDepth,
                            format!("more than {BLOCK_STACK_DEPTH} nested logic blocks: split the rung or use intermediate relays"),
                            format!("嵌套的逻辑块超过 {BLOCK_STACK_DEPTH} 个：请拆分该梯级，或使用中间继电器"),
                        );
                    }
                }
                in_rung = true;
            }
            Op::Orb | Op::Anb => blocks = blocks.saturating_sub(1),
            Op::Mps => {
                branches += 1;
                if branches == BRANCH_STACK_DEPTH + 1 {
                    sink.report(
                        i.origin,
                        Code::L018StackDepth,
                        format!("more than {BRANCH_STACK_DEPTH} nested branch points (MPS): split the rung or use intermediate relays"),
                        format!("嵌套的分支点（MPS）超过 {BRANCH_STACK_DEPTH} 个：请拆分该梯级，或使用中间继电器"),
                    );
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
    let names = || {
        spec.operands
            .iter()
            .map(|o| o.name)
            .collect::<Vec<_>>()
            .join(" ")
    };
    match expected {
        Some(n) if n != instr.operands.len() => {
            let extra = spec.table.map_or(String::new(), |t| {
                format!(" and {} table entries", spec.operands[t.count_from].name)
            });
            let extra_zh = spec.table.map_or(String::new(), |t| {
                format!("，以及 {} 个表格数据", spec.operands[t.count_from].name)
            });
            sink.report(
                instr.origin,
                Code::L011OperandCount,
                format!(
                    "{} takes {n} operand{} ({}{extra}), found {}",
                    spec.name,
                    if n == 1 { "" } else { "s" },
                    names(),
                    instr.operands.len()
                ),
                format!(
                    "{} 需要 {n} 个操作数（{}{extra_zh}），实有 {} 个",
                    spec.name,
                    names(),
                    instr.operands.len()
                ),
            );
            return;
        }
        None if instr.operands.len() < fixed => {
            sink.report(
                instr.origin,
                Code::L011OperandCount,
                format!(
                    "{} takes {} and {} table entries",
                    spec.name,
                    names(),
                    spec.table.map_or("", |t| spec.operands[t.count_from].name)
                ),
                format!(
                    "{} 需要操作数 {}，以及 {} 个表格数据",
                    spec.name,
                    names(),
                    spec.table.map_or("", |t| spec.operands[t.count_from].name)
                ),
            );
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
                    sink.report(
                        instr.origin,
                        Code::L020UndefinedSymbol,
                        format!("undefined symbol `{name}`: define it in the symbol table or write the address"),
                        format!("符号 `{name}` 未定义：请在符号表中定义，或直接写地址"),
                    );
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
            let (code, text) = (refusal.code(), refusal.to_string());
            sink.report(
                instr.origin,
                code,
                format!("{} {}: {text}", spec.name, ospec.name),
                format!("{} 的操作数 {}：{}", spec.name, ospec.name, refusal.zh()),
            );
            continue;
        }
        if let (Width::Bits3, Operand::Addr(a)) = (ospec.width, &instr.operands[i])
            && a.bit.is_some_and(|b| b > 5)
        {
            sink.report(
                instr.origin,
                Code::W003BitsSpill,
                format!(
                    "{} OUT {a}: the three result bits continue into {}",
                    spec.name,
                    Address::byte(a.area, a.number + 1)
                ),
                format!(
                    "{} 的 OUT {a}：三个结果位会延续到 {}",
                    spec.name,
                    Address::byte(a.area, a.number + 1)
                ),
            );
        }
    }
}
