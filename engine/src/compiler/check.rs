//! Instruction-level checks: operands against the catalogue, labels, calls, stacks, step
//! limits, and the warnings about doubly driven coils and shared timers.

use super::diag::{Code, Origin, Sink};
use super::rung::Instr;
use super::{Program, StepCounts};
use crate::address::{Address, Area};
use crate::catalog::{
    Access, CONST_MAX, InstrClass, Op, OperandKind, OperandSpec, Width, check_digit_group,
    xmov_format,
};
use crate::model::{BlockKind, Operand, Project, SymbolIndex};
use crate::profile::Profile;
use std::collections::{BTreeMap, BTreeSet, HashMap};

/// Block stack limit (docs/plc.md, "Basic instructions").
pub const BLOCK_STACK_DEPTH: usize = 32;
/// Branch (MPS) stack limit (docs/plc.md, "Basic instructions").
pub const BRANCH_STACK_DEPTH: usize = 16;

/// Where an instruction is: (block, network, origin).
type Place = (usize, usize, Origin);

fn place_text(program: &Program, p: Place) -> String {
    let block = program.blocks[p.0].kind.label();
    match p.2 {
        Origin::Line(l) => format!("line {l}"),
        Origin::Cell { row, col } => {
            format!(
                "{block} network {} row {} col {}",
                p.1 + 1,
                row + 1,
                col + 1
            )
        }
        Origin::None => format!("{block} network {}", p.1 + 1),
    }
}

/// Checks a whole program and resolves its symbols in place. Returns the step counts.
pub fn check_program(program: &mut Program, project: &Project, sink: &mut Sink) -> StepCounts {
    let profile = project.profile();
    let symbols = project.symbol_index();
    let mut labels: BTreeMap<u16, Place> = BTreeMap::new();
    let mut coils: HashMap<Address, Place> = HashMap::new();
    let mut timers: HashMap<Address, Place> = HashMap::new();
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
                );
            }
        }
    }

    for b in 0..program.blocks.len() {
        let label = program.blocks[b].kind.label();
        for n in 0..program.blocks[b].networks.len() {
            sink.at(b, &label, n);
            for k in 0..program.blocks[b].networks[n].instrs.len() {
                let instr = &mut program.blocks[b].networks[n].instrs[k];
                check_operands(instr, &symbols, profile, sink);
                let instr = &program.blocks[b].networks[n].instrs[k];
                let here = (b, n, instr.origin);
                let first_addr = instr.operands.first().and_then(Operand::address);
                match instr.op {
                    Op::Lbl => {
                        if let Some(a) = first_addr {
                            if let Some(prev) = labels.get(&a.number) {
                                sink.report(
                                    instr.origin,
                                    Code::L030LabelTwice,
                                    format!(
                                        "label {a} is already defined at {}; each label is defined once in the project",
                                        place_text(program, *prev)
                                    ),
                                );
                            } else {
                                labels.insert(a.number, here);
                            }
                        }
                    }
                    Op::Out | Op::Outn => {
                        if let Some(a) = first_addr {
                            if let Some(prev) = coils.get(&a) {
                                sink.report(
                                    instr.origin,
                                    Code::W001CoilTwice,
                                    format!(
                                        "coil {a} is also driven at {}; the later one wins each scan",
                                        place_text(program, *prev)
                                    ),
                                );
                            } else {
                                coils.insert(a, here);
                            }
                        }
                    }
                    _ if let Some((i, area)) = instr.op.spec().memory_operand() => {
                        let number = instr.operands.get(i).and_then(Operand::address);
                        if let Some(a) = number.filter(|a| a.area == area) {
                            if let Some(prev) = timers.get(&a) {
                                sink.report(
                                    instr.origin,
                                    Code::W002TimerTwice,
                                    format!(
                                        "{a} is also used by the instruction at {}; two instructions sharing a timer or counter disturb each other",
                                        place_text(program, *prev)
                                    ),
                                );
                            } else {
                                timers.insert(a, here);
                            }
                        }
                    }
                    _ => {}
                }
            }
            check_stacks(&program.blocks[b].networks[n].instrs, sink);
        }
    }

    // Jumps and calls, now that every label and subprogram is known.
    let mut calls: BTreeMap<usize, Vec<(usize, Place)>> = BTreeMap::new();
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
                        ),
                        Some(target) if target.0 != b => sink.report(
                            instr.origin,
                            Code::L032JumpOutOfBlock,
                            format!(
                                "JMPB to {a} at {}: a jump stays inside its own block (use CALL to reach a subprogram)",
                                place_text(program, *target)
                            ),
                        ),
                        Some(_) => {}
                    },
                    Op::Call | Op::Callu if a.area == Area::P => match subs.get(&a.number) {
                        None => sink.report(
                            instr.origin,
                            Code::L033UndefinedSub,
                            format!("{} {a}: there is no subprogram {a}; create it or correct the number", instr.op.name()),
                        ),
                        Some(&target) => calls.entry(b).or_default().push((target, (b, n, instr.origin))),
                    },
                    _ => {}
                }
            }
        }
    }
    check_recursion(program, &calls, sink);

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
        );
    }
    steps
}

fn check_recursion(
    program: &Program,
    calls: &BTreeMap<usize, Vec<(usize, Place)>>,
    sink: &mut Sink,
) {
    // Depth-first search with colours; a back edge closes a cycle.
    fn visit(
        b: usize,
        calls: &BTreeMap<usize, Vec<(usize, Place)>>,
        colour: &mut [u8],
        found: &mut Vec<(Place, usize)>,
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

/// Bytes of one access of this operand, if known from constants.
fn access_bytes(instr: &Instr, spec: &OperandSpec) -> Option<u32> {
    match spec.width {
        Width::Bytes(n) => Some(u32::from(n)),
        Width::SizeOf(i) => const_value(instr.operands.get(i as usize))
            .filter(|v| matches!(v, 1 | 2 | 4))
            .map(|v| v as u32),
        _ => None,
    }
}

/// (element bytes, element count) of a table operand, if known from constants.
fn table_shape(instr: &Instr, name: &str) -> Option<(u32, u32)> {
    let c = |i: usize| const_value(instr.operands.get(i));
    match (instr.op, name) {
        (Op::Xmov, "DS") => {
            let (x, _) = xmov_format(c(1)?);
            Some((u32::from(x), c(2)?.max(1) as u32))
        }
        (Op::Xmov, "DD" | "DI") => {
            let (x, nn) = xmov_format(c(1)?);
            Some((u32::from(x), nn))
        }
        (Op::Dschb, "IN1") => Some((c(0)? as u32, c(2)?.max(1) as u32)),
        (Op::Windr, "IN") => Some((4, 6)),
        _ => None,
    }
}

/// Addresses covered from `a` by `count` elements of `bytes` (element rule, docs/plc.md).
fn covered(a: Address, bytes: u32, count: u32) -> u32 {
    if a.area.element_bytes() == 1 {
        bytes * count
    } else {
        count
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
        if let Err(msg) = check_operand(instr, i, ospec, profile) {
            let (code, text) = msg;
            sink.report(
                instr.origin,
                code,
                format!("{} {}: {text}", spec.name, ospec.name),
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
            );
        }
    }
}

/// Whether operand `i` of an instruction is acceptable as written (kind, area, range), for
/// editors that must not produce an invalid operand (replace).
pub fn operand_ok(op: Op, operands: &[Operand], i: usize, profile: &Profile) -> bool {
    let instr = Instr {
        op,
        operands: operands.to_vec(),
        origin: Origin::None,
    };
    match op.spec().operand(i) {
        Some(spec) => check_operand(&instr, i, spec, profile).is_ok(),
        None => false,
    }
}

fn check_operand(
    instr: &Instr,
    i: usize,
    spec: &OperandSpec,
    profile: &Profile,
) -> Result<(), (Code, String)> {
    let operand = &instr.operands[i];
    let kind_error = |what: &str| {
        Err((
            Code::L021OperandKind,
            format!("expects {what}, found `{operand}`"),
        ))
    };
    match operand {
        Operand::Int(v) => {
            if !spec.accepts_const() {
                return kind_error(expected_text(spec));
            }
            let v = *v;
            match spec.kind {
                OperandKind::Size if !matches!(v, 1 | 2 | 4) => Err((
                    Code::L024ConstRange,
                    format!("the size is 1, 2 or 4, not {v}"),
                )),
                OperandKind::Digits { max_digit } => {
                    let digits_ok = (0..=9999).contains(&v)
                        && v.to_string().bytes().all(|d| d - b'0' <= max_digit);
                    if !digits_ok {
                        return Err((
                            Code::L024ConstRange,
                            format!(
                                "write 4 {} digits, not `{v}`",
                                if max_digit == 1 { "binary" } else { "decimal" }
                            ),
                        ));
                    }
                    check_digit_group(instr.op, spec.name, v).map_err(|m| (Code::L024ConstRange, m))
                }
                _ if v < spec.min || v > spec.max => Err((
                    Code::L024ConstRange,
                    format!("{v} is out of range ({}–{})", spec.min, spec.max),
                )),
                _ if v.abs() > CONST_MAX => Err((
                    Code::L024ConstRange,
                    format!("{v} is out of range (−2147483647–2147483647)"),
                )),
                _ => Ok(()),
            }
        }
        Operand::Real(_) => {
            if spec.kind == OperandKind::RealOrD {
                Ok(())
            } else {
                kind_error(expected_text(spec))
            }
        }
        Operand::Symbol(_) => Ok(()), // resolved before, or already reported
        Operand::Addr(a) => {
            let a = *a;
            let wants_bit = match spec.kind {
                OperandKind::Bit => Some(true),
                OperandKind::BitOrByte => None,
                OperandKind::Size | OperandKind::Const | OperandKind::Digits { .. } => {
                    return kind_error(expected_text(spec));
                }
                _ => Some(false),
            };
            match (wants_bit, a.bit.is_some()) {
                (Some(true), false) => return kind_error("a bit address such as R0010.0"),
                (Some(false), true) => {
                    return kind_error("a byte address without a bit, such as R0010");
                }
                _ => {}
            }
            let writes = match spec.access {
                Access::Read => false,
                Access::Write | Access::ReadWrite => true,
                Access::WriteWhen { operand, value } => {
                    const_value(instr.operands.get(operand as usize)) == Some(i64::from(value))
                }
            };
            if writes && matches!(a.area, Area::X | Area::F) {
                return Err((
                    Code::L025ReadOnly,
                    format!("{a} cannot be written: X and F are inputs, read-only to the program"),
                ));
            }
            if !spec.areas.contains(a.area) {
                return Err((
                    Code::L022Area,
                    format!("{a} is not allowed here; use {}", spec.areas.describe()),
                ));
            }
            let count = match spec.width {
                Width::Bits3 => {
                    if a.bit.is_some_and(|b| b > 5) {
                        2
                    } else {
                        1
                    }
                }
                Width::Elements4(k) => covered(a, 4, u32::from(k)),
                Width::Table => table_shape(instr, spec.name)
                    .map(|(bytes, n)| covered(a, bytes, n))
                    .unwrap_or(1),
                _ => access_bytes(instr, spec)
                    .map(|bytes| covered(a, bytes, 1))
                    .unwrap_or(1),
            };
            a.check_span(profile, count)
                .map_err(|e| (Code::L023AddressRange, e.to_string()))
        }
    }
}

fn expected_text(spec: &OperandSpec) -> &'static str {
    match spec.kind {
        OperandKind::Size => "a size 1, 2 or 4",
        OperandKind::Const => "a constant",
        OperandKind::Digits { .. } => "a 4-digit group such as 0000",
        OperandKind::Bit => "a bit address such as R0010.0",
        OperandKind::Byte => "an address such as R0010 or D0004",
        OperandKind::ConstOrByte => "an integer constant or an address",
        OperandKind::RealOrD => "a real constant or a D address",
        OperandKind::BitOrByte => "a bit or byte address",
        OperandKind::Label => "a label such as L0001",
        OperandKind::Subprogram => "a subprogram such as P0001",
        OperandKind::Timer => "a timer such as T0001",
        OperandKind::Counter => "a counter such as C0001",
    }
}
