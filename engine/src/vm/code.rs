//! The executable form: one `u32` word per instruction (opcode in the low byte, a bit index,
//! jump target or table index above it), plus a table of resolved function-instruction
//! arguments. Built once from a compiled program; the scan loop only reads it.

use super::memory::{Layout, Loc};
use crate::address::{Address, Area};
use crate::catalog::{FnOp, InstrClass, Op, OperandKind};
use crate::compiler::{Instr, Program};
use crate::model::{BlockKind, Operand};
use thiserror::Error;

/// Flag bits of a contact opcode: the opcode *is* its flags, so the loop runs
/// every contact form with one straight-line body: `v = bit ^ INVERT`, then
/// `acc = (acc & (v | OR)) | (v & LOAD_OR)`, pushing the old accumulator when PUSH and
/// emptying the stacks when START.
pub const C_INVERT: u32 = 1;
/// The contact is in parallel (OR, ORI).
pub const C_OR: u32 = 2;
/// The contact's value passes on its own (LD) or in parallel (OR).
pub const C_LOAD_OR: u32 = 4;
/// The old accumulator is pushed on the block stack (LD inside a rung).
pub const C_PUSH: u32 = 8;
/// Start of a rung: both stacks are emptied.
pub const C_START: u32 = 16;
/// Opcodes below this are contacts (every combination of the `C_*` flags fits).
pub const CONTACT_END: u32 = 32;

/// Declares the VM's opcodes once: [`VmOp`], its byte constants in [`byte`] (the hot loop's
/// match patterns) and the decoding table all come from one line per opcode, so they cannot
/// disagree. Contacts come first; the build stops if one lies outside `0..CONTACT_END` or
/// another opcode inside it.
macro_rules! vm_ops {
    (
        contacts { $( $(#[doc = $cdoc:literal])* $cop:ident $cbyte:ident = $cvalue:expr; )* }
        others { $( $(#[doc = $doc:literal])* $op:ident $byte:ident = $value:expr; )* }
    ) => {
        /// VM opcodes. Contacts and coils carry a bit index (byte offset × 8 + bit).
        #[derive(Clone, Copy, Debug, PartialEq, Eq)]
        #[repr(u8)]
        pub enum VmOp {
            $( $(#[doc = $cdoc])* $cop = $cvalue, )*
            $( $(#[doc = $doc])* $op = $value, )*
        }

        /// The opcode bytes as `u32`, for matching the low byte of a word without decoding it.
        // One per opcode, whether or not a loop matches it: the interpreter matches contacts
        // by range, not by byte.
        #[allow(dead_code)]
        pub mod byte {
            $(
                #[doc = concat!("The byte of [`VmOp::", stringify!($cop), "`](super::VmOp::", stringify!($cop), ").")]
                pub const $cbyte: u32 = super::VmOp::$cop as u32;
            )*
            $(
                #[doc = concat!("The byte of [`VmOp::", stringify!($op), "`](super::VmOp::", stringify!($op), ").")]
                pub const $byte: u32 = super::VmOp::$op as u32;
            )*
        }

        impl VmOp {
            /// Every opcode, in the order of the table.
            pub const ALL: &[VmOp] = &[$(VmOp::$cop,)* $(VmOp::$op),*];

            /// Whether the opcode is a contact, whose byte is its `C_*` flags (the table's
            /// test checks the bytes against it).
            #[cfg(test)]
            pub const fn is_contact(self) -> bool {
                matches!(self, $(VmOp::$cop)|*)
            }
        }

        const _: () = {
            $( assert!(($cvalue as u32) < CONTACT_END, "a contact's byte is its flags"); )*
            $( assert!(($value as u32) >= CONTACT_END, "bytes below CONTACT_END are contacts"); )*
        };
    };
}

vm_ops! {
    contacts {
        /// AND: a contact in series.
        And AND = 0;
        /// ANI: a normally-closed contact in series.
        Ani ANI = C_INVERT as u8;
        /// OR: a contact in parallel.
        Or OR = (C_OR | C_LOAD_OR) as u8;
        /// ORI: a normally-closed contact in parallel.
        Ori ORI = (C_OR | C_LOAD_OR | C_INVERT) as u8;
        /// LD inside a rung: the old result is pushed on the block stack.
        Ld LD = (C_LOAD_OR | C_PUSH) as u8;
        /// LDI inside a rung.
        Ldi LDI = (C_LOAD_OR | C_PUSH | C_INVERT) as u8;
        /// LD at the start of a rung: no block to push.
        LdStart LD_START = (C_LOAD_OR | C_START) as u8;
        /// LDI at the start of a rung.
        LdiStart LDI_START = (C_LOAD_OR | C_START | C_INVERT) as u8;
    }
    others {
        /// ORB: or of the two last blocks.
        Orb ORB = 32;
        /// ANB: and of the two last blocks.
        Anb ANB = 33;
        /// OUT: a coil.
        Out OUT = 34;
        /// OUTN: an inverted coil.
        Outn OUTN = 35;
        /// MPS: push the branch point.
        Mps MPS = 36;
        /// MRD: read the branch point.
        Mrd MRD = 37;
        /// MPP: pop the branch point.
        Mpp MPP = 38;
        /// SET: the bit := 1 while the result is 1.
        Set SET = 39;
        /// RST: the bit := 0 while the result is 1.
        Rst RST = 40;
        /// Jump to the word index in the argument when ACT = 1.
        Jmpb JMPB = 41;
        /// A label: costs its steps, does nothing.
        Lbl LBL = 42;
        /// Call the code at the word index in the argument when ACT = 1.
        Call CALL = 43;
        /// Call the code at the word index in the argument whatever ACT is.
        Callu CALLU = 44;
        /// Start of a network: the argument indexes [`Executable::networks`].
        Net NET = 45;
        /// A function instruction: the argument indexes [`Executable::fns`].
        Fn FN = 46;
        /// End of a block or subprogram.
        Ret RET = 47;
    }
}

// OUT and OUTN differ in their low bit only: the hot loop writes `result ^ (opcode & 1)`.
const _: () = assert!(VmOp::Out as u8 & 1 == 0 && VmOp::Outn as u8 == VmOp::Out as u8 | 1);

/// Opcode byte → opcode, `None` for a byte that is no opcode. Built from [`VmOp::ALL`]; two
/// opcodes on one byte stop the build.
static DECODE: [Option<VmOp>; 256] = {
    let mut table = [None; 256];
    let mut i = 0;
    while i < VmOp::ALL.len() {
        let op = VmOp::ALL[i];
        assert!(table[op as usize].is_none(), "two opcodes share a byte");
        table[op as usize] = Some(op);
        i += 1;
    }
    table
};

impl VmOp {
    /// Decodes the low byte of a word; `None` when it is no opcode ([`Executable`] refuses such
    /// words when it is built, so the loop never meets one).
    #[inline(always)]
    pub fn decode(word: u32) -> Option<VmOp> {
        DECODE[(word & 0xFF) as usize]
    }
}

/// Packs an opcode and its argument.
pub fn word(op: VmOp, arg: u32) -> u32 {
    debug_assert!(arg < 1 << 24);
    op as u32 | arg << 8
}

/// A resolved operand of a function instruction.
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub enum Arg {
    /// No operand.
    #[default]
    None,
    /// An integer constant.
    Int(i32),
    /// A real constant.
    Real(f32),
    /// A byte or word location.
    Loc(Loc),
    /// A bit: byte offset × 8 + bit.
    Bit(u32),
}

/// Most operands a function instruction has (AXCTL, XMOV: 8).
pub const MAX_ARGS: usize = 8;

/// One function instruction instance.
#[derive(Clone, Debug)]
pub struct FnCall {
    /// Which instruction.
    pub op: FnOp,
    /// Its operands in IL order.
    pub args: [Arg; MAX_ARGS],
    /// CODB's table: a range of [`Executable::consts`].
    pub table: (u32, u32),
    /// Index of its per-instance state (edge, timer and window memories).
    pub state: u32,
    /// Steps it costs.
    pub cost: u32,
}

/// Where a network's code is, for monitoring and for naming the place of a halt.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct NetworkInfo {
    /// Block index in the ladder.
    pub block: usize,
    /// Network index in the block.
    pub network: usize,
    /// Block label.
    pub label: String,
    /// First word of the network.
    pub start: u32,
    /// One past its last word.
    pub end: u32,
}

/// The executable program. Only lowering builds one, and `Executable::checked` sees every word
/// on the way out: the scan loop then takes each opcode and index as valid without testing it.
#[derive(Clone, Debug)]
pub struct Executable {
    /// Instruction words (read through [`Executable::words`]: nothing may change them once checked).
    words: Vec<u32>,
    /// Function-instruction instances.
    pub(crate) fns: Vec<FnCall>,
    /// CODB tables.
    pub(crate) consts: Vec<i32>,
    /// Networks in code order (a subprogram called from both levels appears twice).
    pub networks: Vec<NetworkInfo>,
    /// Entry of level 1.
    pub(crate) level1: u32,
    /// Entry of level 2.
    pub(crate) level2: u32,
    /// Level 2's static step count (S of the slice quota).
    pub(crate) level2_steps: u32,
    /// Number of per-instance states.
    pub(crate) states: u32,
    /// For each word, the source instruction it came from (block, network, index in the
    /// network's instruction list), or none for markers.
    pub source: Vec<Option<(u16, u32, u32)>>,
}

/// A word the scan loop could not run.
#[derive(Clone, Debug, Error, PartialEq, Eq)]
pub enum CodeError {
    /// The low byte is no opcode of the VM.
    #[error("word {at}: {byte:#04x} is not an opcode of the VM")]
    UnknownOpcode {
        /// Index of the word.
        at: usize,
        /// Its low byte.
        byte: u8,
    },
    /// A jump or call target, network or function-instruction index past what it indexes.
    #[error("word {at}: {op} {index} is past the {len} {what}")]
    OutOfRange {
        /// Index of the word.
        at: usize,
        /// Its opcode, by name (the opcodes themselves are the VM's own).
        op: String,
        /// Its argument.
        index: u32,
        /// How many there are.
        len: usize,
        /// What it indexes.
        what: &'static str,
    },
    /// A level's entry past the code.
    #[error("level entry {entry} is past the {len} words")]
    Entry {
        /// The entry word.
        entry: u32,
        /// Number of words.
        len: usize,
    },
}

impl Executable {
    /// The instruction words.
    pub fn words(&self) -> &[u32] {
        &self.words
    }

    /// The code, once every word has an opcode of [`VmOp`] and every jump, call, network and
    /// function-instruction argument is inside what it indexes. Checked here once rather than
    /// at every word of every scan.
    fn checked(self) -> Result<Executable, CodeError> {
        let len = self.words.len();
        for (at, &w) in self.words.iter().enumerate() {
            let Some(op) = VmOp::decode(w) else {
                return Err(CodeError::UnknownOpcode { at, byte: w as u8 });
            };
            let index = w >> 8;
            let limit = match op {
                VmOp::Jmpb | VmOp::Call | VmOp::Callu => Some((len, "words")),
                VmOp::Net => Some((self.networks.len(), "networks")),
                VmOp::Fn => Some((self.fns.len(), "function instructions")),
                _ => None,
            };
            if let Some((len, what)) = limit
                && index as usize >= len
            {
                return Err(CodeError::OutOfRange {
                    at,
                    op: format!("{op:?}"),
                    index,
                    len,
                    what,
                });
            }
        }
        for entry in [self.level1, self.level2] {
            if entry as usize >= len {
                return Err(CodeError::Entry { entry, len });
            }
        }
        Ok(self)
    }
}

/// Why a program cannot be run.
#[derive(Clone, Debug, Error, PartialEq)]
pub enum LowerError {
    /// The program still has compile errors.
    #[error("the program has {0} compile error(s); run check and fix them first")]
    CompileErrors(usize),
    /// An operand the compiler should have resolved.
    #[error("{0}")]
    Unresolved(String),
    /// Lowering made a word the loop could not run.
    #[error("invalid code: {0}")]
    Code(#[from] CodeError),
    /// The project's machine model cannot run (typed, so that it can be said in Chinese too).
    #[error("{0}")]
    Model(crate::devices::ModelError),
}

struct Lowerer<'a> {
    program: &'a Program,
    layout: &'a Layout,
    code: Executable,
    /// Entry word of each block for each level context, once lowered.
    entries: Vec<[Option<u32>; 2]>,
    /// Jumps to patch: (word index, block, label number, context).
    jumps: Vec<(usize, usize, u16)>,
    /// Calls to patch: (word index, its opcode, target block, context).
    calls: Vec<(usize, VmOp, usize, usize)>,
    /// Label word per (block, context): label number → word.
    labels: Vec<(usize, usize, u16, u32)>,
    /// The memory slot of each function instruction in the program text: a subprogram lowered
    /// for both levels shares it (docs/plc.md, "Scan": memories belong to the instruction).
    states: std::collections::HashMap<(u16, u32, u32), u32>,
}

fn bit_index(loc: Loc, a: Address) -> u32 {
    loc.off * 8 + u32::from(a.bit.unwrap_or(0))
}

impl Lowerer<'_> {
    fn arg(&self, op: Op, i: usize, o: &Operand, latched: bool) -> Result<Arg, LowerError> {
        let spec = op.spec().operand(i);
        Ok(match o {
            Operand::Int(v) => {
                if spec.is_some_and(|s| s.kind == OperandKind::RealOrD) {
                    Arg::Real(*v as f32)
                } else {
                    Arg::Int(*v as i32)
                }
            }
            Operand::Real(v) => Arg::Real(*v),
            Operand::Addr(a) => match a.area {
                Area::L | Area::P => Arg::Int(i32::from(a.number)),
                _ => {
                    let loc = self.layout.loc(*a, latched);
                    if a.bit.is_some() {
                        Arg::Bit(bit_index(loc, *a))
                    } else {
                        Arg::Loc(loc)
                    }
                }
            },
            Operand::Symbol(s) => {
                return Err(LowerError::Unresolved(format!(
                    "symbol `{s}` is not resolved"
                )));
            }
        })
    }

    fn bit(&self, o: Option<&Operand>, latched: bool) -> Result<u32, LowerError> {
        match o {
            Some(Operand::Addr(a)) if a.bit.is_some() => {
                Ok(bit_index(self.layout.loc(*a, latched), *a))
            }
            other => Err(LowerError::Unresolved(format!(
                "expected a bit address, found {other:?}"
            ))),
        }
    }

    /// Lowers block `b` in context `ctx` (0: level 1, 1: level 2) if not yet done.
    fn block(&mut self, b: usize, ctx: usize) -> Result<u32, LowerError> {
        if let Some(entry) = self.entries[b][ctx] {
            return Ok(entry);
        }
        let latched = ctx == 1;
        let entry = self.code.words.len() as u32;
        self.entries[b][ctx] = Some(entry);
        let block = &self.program.blocks[b];
        let mut pending_subs = Vec::new();
        for (n, net) in block.networks.iter().enumerate() {
            let net_index = self.code.networks.len() as u32;
            self.code.networks.push(NetworkInfo {
                block: b,
                network: n,
                label: block.kind.label(),
                start: self.code.words.len() as u32,
                end: 0,
            });
            self.push(word(VmOp::Net, net_index), None);
            let mut mps_depth = 0i32;
            let mut rung_start = true;
            for (k, instr) in net.instrs.iter().enumerate() {
                let src = Some((b as u16, n as u32, k as u32));
                self.instr(
                    instr,
                    latched,
                    b,
                    ctx,
                    &mut rung_start,
                    &mut mps_depth,
                    src,
                    &mut pending_subs,
                )?;
            }
            let end = self.code.words.len() as u32;
            self.code.networks[net_index as usize].end = end;
        }
        self.push(word(VmOp::Ret, 0), None);
        for target in pending_subs {
            self.block(target, ctx)?;
        }
        Ok(entry)
    }

    fn push(&mut self, w: u32, src: Option<(u16, u32, u32)>) {
        self.code.words.push(w);
        self.code.source.push(src);
    }

    #[allow(clippy::too_many_arguments)]
    fn instr(
        &mut self,
        instr: &Instr,
        latched: bool,
        block: usize,
        ctx: usize,
        rung_start: &mut bool,
        mps_depth: &mut i32,
        src: Option<(u16, u32, u32)>,
        pending_subs: &mut Vec<usize>,
    ) -> Result<(), LowerError> {
        let first = instr.operands.first();
        let op = instr.op;
        let at = self.code.words.len();
        let w = match op {
            Op::Ld | Op::Ldi => {
                let b = self.bit(first, latched)?;
                let vm = match (op, *rung_start) {
                    (Op::Ld, true) => VmOp::LdStart,
                    (Op::Ldi, true) => VmOp::LdiStart,
                    (Op::Ld, false) => VmOp::Ld,
                    _ => VmOp::Ldi,
                };
                word(vm, b)
            }
            Op::And => word(VmOp::And, self.bit(first, latched)?),
            Op::Ani => word(VmOp::Ani, self.bit(first, latched)?),
            Op::Or => word(VmOp::Or, self.bit(first, latched)?),
            Op::Ori => word(VmOp::Ori, self.bit(first, latched)?),
            Op::Orb => word(VmOp::Orb, 0),
            Op::Anb => word(VmOp::Anb, 0),
            Op::Mps => word(VmOp::Mps, 0),
            Op::Mrd => word(VmOp::Mrd, 0),
            Op::Mpp => word(VmOp::Mpp, 0),
            Op::Out => word(VmOp::Out, self.bit(first, false)?),
            Op::Outn => word(VmOp::Outn, self.bit(first, false)?),
            Op::Set => word(VmOp::Set, self.bit(first, false)?),
            Op::Rst => word(VmOp::Rst, self.bit(first, false)?),
            Op::Lbl => {
                if let Some(Operand::Addr(a)) = first {
                    self.labels.push((block, ctx, a.number, at as u32));
                }
                word(VmOp::Lbl, 0)
            }
            Op::Jmpb => {
                if let Some(Operand::Addr(a)) = first {
                    self.jumps.push((at, block * 2 + ctx, a.number));
                }
                word(VmOp::Jmpb, 0)
            }
            Op::Call | Op::Callu => {
                let Some(Operand::Addr(a)) = first else {
                    return Err(LowerError::Unresolved("CALL without a subprogram".into()));
                };
                let target = self
                    .program
                    .blocks
                    .iter()
                    .position(
                        |bl| matches!(bl.kind, BlockKind::Sub { number, .. } if number == a.number),
                    )
                    .ok_or_else(|| LowerError::Unresolved(format!("no subprogram {a}")))?;
                let vm = if op == Op::Call {
                    VmOp::Call
                } else {
                    VmOp::Callu
                };
                self.calls.push((at, vm, target, ctx));
                pending_subs.push(target);
                word(vm, 0)
            }
            _ => {
                let Some(function) = op.function() else {
                    unreachable!("every basic instruction has its own arm above");
                };
                let next = self.code.states;
                let state = *self.states.entry(src.unwrap_or_default()).or_insert(next);
                if state == next {
                    self.code.states += 1;
                }
                let mut call = FnCall {
                    op: function,
                    args: [Arg::None; MAX_ARGS],
                    table: (0, 0),
                    state,
                    cost: op.spec().steps(instr.operands.len()),
                };
                let fixed = op.spec().operands.len();
                for (i, o) in instr.operands.iter().enumerate().take(fixed.min(MAX_ARGS)) {
                    call.args[i] = self.arg(op, i, o, latched)?;
                }
                if let Some(table) = op.spec().table {
                    let start = self.code.consts.len() as u32;
                    for o in instr.operands.iter().skip(table.first) {
                        if let Operand::Int(v) = o {
                            self.code.consts.push(*v as i32);
                        }
                    }
                    call.table = (start, self.code.consts.len() as u32);
                }
                let index = self.code.fns.len() as u32;
                self.code.fns.push(call);
                word(VmOp::Fn, index)
            }
        };
        self.push(w, src);
        match op.spec().class {
            InstrClass::Coil | InstrClass::Function => *rung_start = *mps_depth == 0,
            _ => {
                *rung_start = false;
                match op {
                    Op::Mps => *mps_depth += 1,
                    Op::Mpp => *mps_depth -= 1,
                    _ => {}
                }
            }
        }
        Ok(())
    }
}

/// Lowers a compiled, error-free program to executable code.
pub fn lower(program: &Program, layout: &Layout) -> Result<Executable, LowerError> {
    let mut l = Lowerer {
        program,
        layout,
        code: Executable {
            words: Vec::new(),
            fns: Vec::new(),
            consts: Vec::new(),
            networks: Vec::new(),
            level1: 0,
            level2: 0,
            level2_steps: 0,
            states: 0,
            source: Vec::new(),
        },
        entries: vec![[None, None]; program.blocks.len()],
        jumps: Vec::new(),
        calls: Vec::new(),
        labels: Vec::new(),
        states: Default::default(),
    };
    l.code.level1 = l.block(0, 0)?;
    l.code.level2 = l.block(1, 1)?;
    for (at, key, number) in std::mem::take(&mut l.jumps) {
        let (block, ctx) = (key / 2, key % 2);
        let target = l
            .labels
            .iter()
            .find(|(b, c, n, _)| *b == block && *c == ctx && *n == number)
            .map(|t| t.3)
            .ok_or_else(|| LowerError::Unresolved(format!("no label L{number:04} in the block")))?;
        l.code.words[at] = word(VmOp::Jmpb, target);
    }
    for (at, op, target, ctx) in std::mem::take(&mut l.calls) {
        let entry = l.entries[target][ctx].expect("every called block was lowered");
        l.code.words[at] = word(op, entry);
    }
    l.code.level2_steps = program.blocks[1]
        .networks
        .iter()
        .flat_map(|n| &n.instrs)
        .map(|i| i.op.spec().steps(i.operands.len()))
        .sum();
    Ok(l.code.checked()?)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn code(words: Vec<u32>) -> Executable {
        Executable {
            source: vec![None; words.len()],
            words,
            fns: Vec::new(),
            consts: Vec::new(),
            networks: Vec::new(),
            level1: 0,
            level2: 0,
            level2_steps: 0,
            states: 0,
        }
    }

    #[test]
    fn a_word_with_an_unknown_opcode_is_refused() {
        assert!(
            code(vec![word(VmOp::Orb, 0), word(VmOp::Ret, 0)])
                .checked()
                .is_ok()
        );
        let bad = code(vec![word(VmOp::Ld, 9), 0xFF | 3 << 8, word(VmOp::Ret, 0)]);
        assert_eq!(
            bad.checked().err(),
            Some(CodeError::UnknownOpcode { at: 1, byte: 0xFF })
        );
        // A contact byte that is no contact of the table (OR without LOAD_OR) is refused too.
        let bad = code(vec![C_OR | 5 << 8, word(VmOp::Ret, 0)]);
        assert_eq!(
            bad.checked().err(),
            Some(CodeError::UnknownOpcode {
                at: 0,
                byte: C_OR as u8
            })
        );
    }

    #[test]
    fn every_byte_decodes_to_its_opcode_or_to_none() {
        for byte in 0..=255u32 {
            let op = VmOp::ALL.iter().find(|op| **op as u32 == byte).copied();
            assert_eq!(VmOp::decode(byte | 7 << 8), op, "byte {byte}");
            if let Some(op) = op {
                assert_eq!(op.is_contact(), byte < CONTACT_END, "{op:?}");
            }
        }
        assert_eq!(VmOp::ALL.len(), 24);
    }

    #[test]
    fn indices_past_what_they_index_are_refused() {
        let ret = word(VmOp::Ret, 0);
        for (w, what) in [
            (word(VmOp::Jmpb, 2), "words"),
            (word(VmOp::Callu, 5), "words"),
            (word(VmOp::Net, 0), "networks"),
            (word(VmOp::Fn, 0), "function instructions"),
        ] {
            let err = code(vec![w, ret]).checked().err();
            assert!(
                matches!(err, Some(CodeError::OutOfRange { at: 0, what: w, .. }) if w == what),
                "{err:?}"
            );
        }
        let mut entry = code(vec![ret]);
        entry.level2 = 1;
        assert_eq!(
            entry.checked().err(),
            Some(CodeError::Entry { entry: 1, len: 1 })
        );
    }
}
