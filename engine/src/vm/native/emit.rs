//! Code generation: the checked words of an [`Executable`] to x86-64, word by word, in one pass.
//!
//! Bit logic is straight-line code on the image, addressed directly (`[rbx + byte]`): a
//! contact is a `test` and a `setcc` or `cmov`, a coil a masked write into `dl`, a block or
//! branch push one `lea`. Steps are counted at generation time and added to the context's
//! count only where a run can leave or join the straight line (a jump, call, return, label, or level
//! 2's quota check), so a run counts exactly what the interpreter counts. Function
//! instructions call one helper with their index and the accumulator; CALL is a native call
//! with the caller's logic state pushed; RET a native return.
//!
//! A level's own words are generated in more than one copy ([`Copy`]): level 2 with a quota
//! check at every network (a divided level 2, which suspends there) and without (division 1,
//! the usual case); and both levels with a check at every network of whether the monitor
//! watches it, where the run leaves for the interpreter (while something is watched).
//! Subprograms have one copy and never check.

use super::super::IMAGE_BYTES;
use super::super::code::{
    C_INVERT, C_LOAD_OR, C_OR, C_PUSH, C_START, CONTACT_END, Executable, VmOp,
};
use super::asm::{Asm, Cond};
use super::{
    CTX_BUDGET, CTX_EXIT_KIND, CTX_EXIT_PC, CTX_QUOTA, CTX_STEPS, CTX_WATCHED, Copy, ExitKind,
};
use crate::catalog::FnOp;

/// Whether a function instruction does nothing at all while ACT = 0: no image byte, no
/// instruction memory and no CNC question (each is an `if act { … }` and nothing else in
/// `functions::exec`). The generated code calls these only with ACT = 1; the checked engine
/// and `engine/tests/engines.rs` hold it to the interpreter, which always calls.
pub fn idle_without_act(op: FnOp) -> bool {
    matches!(
        op,
        FnOp::Cmp
            | FnOp::Cmpr
            | FnOp::Movn
            | FnOp::Movr
            | FnOp::Codb
            | FnOp::Rotb
            | FnOp::Move
            | FnOp::Wand
            | FnOp::Wor
            | FnOp::Wxor
            | FnOp::Winv
            | FnOp::Wshl
            | FnOp::Wshr
            | FnOp::Dschb
            | FnOp::Psgnl
            | FnOp::Psgn2
            | FnOp::Zcp
    )
}

/// What a network marker checks in a copy.
#[derive(Clone, Copy, Default)]
struct Checks {
    /// Level 2's quota (suspend when reached).
    quota: bool,
    /// Whether the monitor watches the network (leave for the interpreter).
    watch: bool,
}

impl Checks {
    fn any(self) -> bool {
        self.quota || self.watch
    }
}

/// The generated code and where to enter it.
pub(super) struct Generated {
    /// Machine code, entry function first.
    pub bytes: Vec<u8>,
    /// Per [`Copy`], the byte offset of each word's code in it (`u32::MAX`: not in that copy).
    pub offsets: [Vec<u32>; 3],
}

struct Gen<'a> {
    asm: Asm,
    code: &'a Executable,
    helper: u64,
    /// Steps executed since the last point where `r14` was brought up to date.
    pending: u32,
    /// Whether the stacks may hold something (so a rung's start must empty them).
    dirty: bool,
    /// The image byte `dl` holds, changed, for coils in a row that write one byte: written
    /// back before anything may leave the straight line or read the image otherwise.
    cached: Option<u32>,
    /// Whether word indices are jump or call targets (join points).
    targets: Vec<bool>,
    /// rel32 fields to point at a word's code in a copy.
    fixups: Vec<(usize, Copy, u32)>,
    stubs: Vec<(ExitKind, u32, usize)>,
}

/// Generates code for `code`, whose function instructions call `helper`.
pub(super) fn generate(code: &Executable, helper: u64) -> Generated {
    let words = code.words();
    let mut targets = vec![false; words.len()];
    for &w in words {
        if matches!(VmOp::decode(w), Some(VmOp::Jmpb | VmOp::Call | VmOp::Callu)) {
            targets[(w >> 8) as usize] = true;
        }
    }
    let mut g = Gen {
        asm: Asm::default(),
        code,
        helper,
        pending: 0,
        dirty: true,
        cached: None,
        targets,
        fixups: Vec::new(),
        stubs: Vec::new(),
    };
    g.asm.prologue(CTX_EXIT_KIND);
    let exit = g.asm.here();
    g.asm.epilogue();
    // Each level's own words: from its entry to the first RET.
    let own = |entry: u32| {
        let start = entry as usize;
        let end = start
            + words[start..]
                .iter()
                .position(|&w| VmOp::decode(w) == Some(VmOp::Ret))
                .expect("every block ends with RET");
        start..end + 1
    };
    let (l1, l2) = (own(code.level1), own(code.level2));
    let mut offsets = [0, 1, 2].map(|_| vec![u32::MAX; words.len()]);
    for copy in [Copy::Main, Copy::Whole, Copy::Observed] {
        // Which words each copy holds, and what its network markers check.
        let of_copy = (0..words.len()).filter_map(|at| {
            let (one, two) = (l1.contains(&at), l2.contains(&at));
            let checks = match copy {
                // Every word; level 2 checks its quota.
                Copy::Main => Checks {
                    quota: two,
                    watch: false,
                },
                // Level 2 undivided.
                Copy::Whole if two => Checks::default(),
                // Both levels, watched.
                Copy::Observed if one || two => Checks {
                    quota: two,
                    watch: true,
                },
                _ => return None,
            };
            Some((at, checks))
        });
        g.copy(copy, of_copy, &mut offsets);
    }
    for (kind, pc, at) in std::mem::take(&mut g.stubs) {
        let stub = g.asm.here();
        g.asm.patch_rel32(at, stub);
        g.asm.store_ctx32(CTX_EXIT_PC, pc);
        g.asm.store_ctx32(CTX_EXIT_KIND, kind as u32);
        let j = g.asm.jmp();
        g.asm.patch_rel32(j, exit);
    }
    for (at, copy, word) in std::mem::take(&mut g.fixups) {
        let to = offsets[copy as usize][word as usize];
        assert_ne!(to, u32::MAX, "a jump to word {word} left its copy {copy:?}");
        g.asm.patch_rel32(at, to as usize);
    }
    Generated {
        bytes: g.asm.bytes,
        offsets,
    }
}

impl Gen<'_> {
    /// Generates one copy of `words` (with what each network marker checks), contiguous runs
    /// of words, into `offsets[copy]`.
    fn copy(
        &mut self,
        copy: Copy,
        words: impl Iterator<Item = (usize, Checks)>,
        offsets: &mut [Vec<u32>; 3],
    ) {
        self.pending = 0;
        self.cached = None;
        self.dirty = true;
        for (at, checks) in words {
            self.join(at, checks);
            offsets[copy as usize][at] = self.asm.here() as u32;
            self.word(at as u32, checks, copy);
        }
    }

    /// Brings the step count up to date.
    fn flush(&mut self) {
        self.asm.add_steps(CTX_STEPS, self.pending);
        self.pending = 0;
    }

    /// Before word `at`: where a run may enter (a jump or call target, and the network
    /// markers that check something, where a run resumes or comes back from the
    /// interpreter), the step count is up to date and the stacks' contents unknown.
    fn join(&mut self, at: usize, checks: Checks) {
        let resume = checks.any() && VmOp::decode(self.code.words()[at]) == Some(VmOp::Net);
        if self.targets[at] || resume {
            self.spill();
            self.flush();
            self.dirty = true;
        }
    }

    /// Makes `dl` hold the image byte at `disp` (a coil's byte), writing back the byte it
    /// held before.
    fn own(&mut self, disp: u32) {
        if self.cached != Some(disp) {
            self.spill();
            self.asm.load_dl(disp);
            self.cached = Some(disp);
        }
    }

    /// Writes the byte `dl` holds back to the image.
    fn spill(&mut self) {
        if let Some(disp) = self.cached.take() {
            self.asm.store_dl(disp);
        }
    }

    fn stub(&mut self, at: usize, kind: ExitKind, pc: u32) {
        self.stubs.push((kind, pc, at));
    }

    /// Generates word `at` of copy `copy`, whose jumps stay in it; a network marker checks
    /// what `checks` says.
    fn word(&mut self, at: u32, checks: Checks, copy: Copy) {
        let w = self.code.words()[at as usize];
        let arg = w >> 8;
        let op = w & 0xFF;
        let disp = (arg >> 3) & (IMAGE_BYTES as u32 - 1);
        let mask = 1u8 << (arg & 7);
        if op < CONTACT_END {
            self.contact(op, disp, mask);
            self.pending += 1;
            return;
        }
        let Some(vm_op) = VmOp::decode(w) else {
            unreachable!("Executable::checked refused every word without an opcode");
        };
        if matches!(
            vm_op,
            VmOp::Jmpb | VmOp::Call | VmOp::Callu | VmOp::Fn | VmOp::Ret
        ) || (vm_op == VmOp::Net && checks.any())
        {
            // The run may leave the straight line here: the image must be whole.
            self.spill();
        }
        let a = &mut self.asm;
        match vm_op {
            VmOp::Orb | VmOp::Anb => {
                a.pop_blocks();
                if vm_op == VmOp::Orb {
                    a.acc_one_if(Cond::Carry);
                } else {
                    a.acc_zero_if(Cond::NoCarry);
                }
                self.pending += 1;
            }
            VmOp::Mps => {
                a.push_branches();
                self.dirty = true;
                self.pending += 1;
            }
            VmOp::Mrd => {
                a.read_branch();
                self.pending += 1;
            }
            VmOp::Mpp => {
                a.pop_branches();
                a.setcc_al(Cond::Carry);
                self.pending += 1;
            }
            VmOp::Out | VmOp::Outn => {
                let shift = arg as u8 & 7;
                self.own(disp);
                let a = &mut self.asm;
                a.and_dl_imm(!mask);
                if vm_op == VmOp::Out && shift == 0 {
                    a.or_dl_reg(true);
                } else {
                    a.mov_ecx_eax();
                    if vm_op == VmOp::Outn {
                        a.xor_ecx_1();
                    }
                    a.shl_ecx(shift);
                    a.or_dl_reg(false);
                }
                self.pending += 1;
            }
            VmOp::Set => {
                let shift = arg as u8 & 7;
                self.own(disp);
                let a = &mut self.asm;
                if shift == 0 {
                    a.or_dl_reg(true);
                } else {
                    a.mov_ecx_eax();
                    a.shl_ecx(shift);
                    a.or_dl_reg(false);
                }
                self.pending += 2;
            }
            VmOp::Rst => {
                self.own(disp);
                // ecx = acc − 1 (all ones when off) | !mask: !mask when on, 0xFF when off.
                let a = &mut self.asm;
                a.ecx_acc_minus_one();
                a.or_ecx_imm8(!mask);
                a.and_dl_cl();
                self.pending += 2;
            }
            VmOp::Lbl => self.pending += 2,
            VmOp::Jmpb => self.jump(at, arg, copy),
            VmOp::Call | VmOp::Callu => {
                self.pending += 2;
                self.flush();
                let a = &mut self.asm;
                if vm_op == VmOp::Call {
                    a.test_acc();
                    // Over the save (5 bytes), the call (5) and the restore (5).
                    a.jz_short(15);
                }
                a.save_logic();
                let c = a.call();
                a.restore_logic();
                // Subprograms have one copy.
                self.fixups.push((c, Copy::Main, arg));
            }
            VmOp::Net => {
                // `join` brought the step count up to date: a resumed run enters here. The
                // interpreter's order: the quota first, then the monitor.
                if checks.quota {
                    self.asm.cmp_steps_ctx(CTX_STEPS, CTX_QUOTA);
                    let j = self.asm.jcc(Cond::NoCarry);
                    self.stub(j, ExitKind::Suspend, at);
                }
                if checks.watch {
                    self.asm.test_watched(CTX_WATCHED, arg);
                    let j = self.asm.jcc(Cond::NotZero);
                    self.stub(j, ExitKind::Watched, at);
                }
            }
            VmOp::Fn => {
                let f = &self.code.fns[arg as usize];
                self.pending += f.cost;
                if super::timer::tmrb(&mut self.asm, f) {
                    return;
                }
                let skip = idle_without_act(f.op).then(|| {
                    self.asm.test_acc();
                    self.asm.jz_short_forward()
                });
                self.asm.call_helper(self.helper, arg);
                self.asm.test_ecx();
                let j = self.asm.jcc(Cond::NotZero);
                self.stub(j, ExitKind::Panic, at);
                if let Some(skip) = skip {
                    self.asm.patch_rel8_here(skip);
                }
            }
            VmOp::Ret => {
                self.flush();
                self.asm.ret();
                self.dirty = true;
            }
            _ => unreachable!("contacts are handled above"),
        }
    }

    /// A contact: `test` its bit, then load, and or or it into the accumulator.
    fn contact(&mut self, op: u32, disp: u32, mask: u8) {
        let a = &mut self.asm;
        let on = if op & C_INVERT != 0 {
            Cond::Zero
        } else {
            Cond::NotZero
        };
        if op & C_START != 0 && self.dirty {
            a.clear_stacks();
            self.dirty = false;
        }
        if op & C_PUSH != 0 {
            a.push_blocks();
            self.dirty = true;
        }
        if self.cached == Some(disp) {
            a.test_dl(mask);
        } else {
            a.test_mem(disp, mask);
        }
        let off = if op & C_INVERT != 0 {
            Cond::NotZero
        } else {
            Cond::Zero
        };
        match (op & C_OR != 0, op & C_LOAD_OR != 0) {
            // LD: the value itself.
            (false, true) => a.setcc_al(on),
            // AND: off clears the accumulator.
            (false, false) => a.acc_zero_if(off),
            // OR: on sets it.
            (true, _) => a.acc_one_if(on),
        }
    }

    /// JMPB: taken while the accumulator is 1; a backward jump first checks the watchdog.
    fn jump(&mut self, at: u32, target: u32, copy: Copy) {
        self.pending += 2;
        self.flush();
        let a = &mut self.asm;
        a.test_acc();
        let skip = a.jcc(Cond::Zero);
        if target <= at {
            a.cmp_steps_ctx(CTX_STEPS, CTX_BUDGET);
            let j = a.jcc(Cond::Above);
            self.stub(j, ExitKind::Watchdog, at);
        }
        let j = self.asm.jmp();
        self.fixups.push((j, copy, target));
        let here = self.asm.here();
        self.asm.patch_rel32(skip, here);
    }
}
