//! The few x86-64 instructions the scan's machine code is made of, as bytes.
//!
//! Register roles are fixed for the whole generated code (see `emit.rs`): the accumulator in
//! `eax` (always 0 or 1), the memory image's base in `rbx`, the block stack in `r12`, the
//! branch stack in `r13`, the constants 0 in `ebp` and 1 in `r14d`, the run's context in
//! `r15` (the step count lives there, at `CTX_STEPS`); `dl` holds a coil byte being written;
//! `ecx` and the other caller-saved registers are scratch. Every encoding here is written out with its
//! operands named, so a reader can check it against the Intel manual's opcode tables.

/// A condition for [`Asm::setcc_al`], the `cmov`s and [`Asm::jcc`]: the low nibble
/// of the `0F 9x` / `0F 8x` opcodes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Cond {
    /// Carry set (a bit shifted out was 1).
    Carry = 0x2,
    /// Carry clear.
    NoCarry = 0x3,
    /// Zero.
    Zero = 0x4,
    /// Not zero.
    NotZero = 0x5,
    /// Above, unsigned.
    Above = 0x7,
    /// Greater or equal, signed.
    GreaterEq = 0xD,
}

/// Machine code being written (the emitter keeps the places to patch).
#[derive(Default)]
pub(super) struct Asm {
    /// The bytes so far.
    pub bytes: Vec<u8>,
}

impl Asm {
    /// Puts raw bytes: encodings written out at their one place of use, each with its
    /// assembly in a comment there.
    pub fn raw(&mut self, bytes: &[u8]) {
        self.put(bytes);
    }

    /// Puts a four-byte little-endian value (an immediate or displacement).
    pub fn raw32(&mut self, v: u32) {
        self.put32(v);
    }

    /// An instruction `opcode` with `[rbx + disp]` as its memory operand and `reg` in the
    /// ModRM reg field (a register or an opcode extension).
    pub fn rbx_op(&mut self, opcode: &[u8], reg: u8, disp: u32) {
        self.put(opcode);
        self.rbx_disp(reg, disp);
    }

    /// Where the next byte goes.
    pub fn here(&self) -> usize {
        self.bytes.len()
    }

    fn put(&mut self, bytes: &[u8]) {
        self.bytes.extend_from_slice(bytes);
    }

    fn put32(&mut self, v: u32) {
        self.put(&v.to_le_bytes());
    }

    /// Writes `target - (at + 4)` into the rel32 field at `at`.
    pub fn patch_rel32(&mut self, at: usize, target: usize) {
        let rel = target as i64 - (at as i64 + 4);
        let rel = i32::try_from(rel).expect("generated code stays far below 2 GiB");
        self.bytes[at..at + 4].copy_from_slice(&rel.to_le_bytes());
    }

    /// ModRM (and displacement) for `[rbx + disp]` with `reg` in the reg field: a byte
    /// displacement when it fits, else four bytes.
    fn rbx_disp(&mut self, reg: u8, disp: u32) {
        if disp < 0x80 {
            self.put(&[0x40 | reg << 3 | 3, disp as u8]);
        } else {
            self.put(&[0x80 | reg << 3 | 3]);
            self.put32(disp);
        }
    }

    /// `test byte [rbx + disp], mask`
    pub fn test_mem(&mut self, disp: u32, mask: u8) {
        self.put(&[0xF6]);
        self.rbx_disp(0, disp);
        self.put(&[mask]);
    }

    /// `movzx edx, byte [rbx + disp]`: a coil byte into the register that holds it.
    pub fn load_dl(&mut self, disp: u32) {
        self.put(&[0x0F, 0xB6]);
        self.rbx_disp(2, disp);
    }

    /// `mov byte [rbx + disp], dl`
    pub fn store_dl(&mut self, disp: u32) {
        self.put(&[0x88]);
        self.rbx_disp(2, disp);
    }

    /// `test dl, mask`
    pub fn test_dl(&mut self, mask: u8) {
        self.put(&[0xF6, 0xC2, mask]);
    }

    /// `and dl, imm`
    pub fn and_dl_imm(&mut self, imm: u8) {
        self.put(&[0x80, 0xE2, imm]);
    }

    /// `or dl, cl` (or `al` when `al`).
    pub fn or_dl_reg(&mut self, al: bool) {
        self.put(&[0x08, if al { 0xC2 } else { 0xCA }]);
    }

    /// `and dl, cl`
    pub fn and_dl_cl(&mut self) {
        self.put(&[0x20, 0xCA]);
    }

    /// `setCC al`
    pub fn setcc_al(&mut self, c: Cond) {
        self.put(&[0x0F, 0x90 | c as u8, 0xC0]);
    }

    /// `lea r12, [rax + r12*2]`: push the accumulator on the block stack.
    pub fn push_blocks(&mut self) {
        self.put(&[0x4E, 0x8D, 0x24, 0x60]);
    }

    /// `lea r13, [rax + r13*2]`: push the accumulator on the branch stack.
    pub fn push_branches(&mut self) {
        self.put(&[0x4E, 0x8D, 0x2C, 0x68]);
    }

    /// `shr r12, 1`: pop the block stack into the carry flag.
    pub fn pop_blocks(&mut self) {
        self.put(&[0x49, 0xD1, 0xEC]);
    }

    /// `shr r13, 1`: pop the branch stack into the carry flag.
    pub fn pop_branches(&mut self) {
        self.put(&[0x49, 0xD1, 0xED]);
    }

    /// `xor r12d, r12d; xor r13d, r13d`: empty both stacks.
    pub fn clear_stacks(&mut self) {
        self.put(&[0x45, 0x31, 0xE4, 0x45, 0x31, 0xED]);
    }

    /// `mov eax, r13d; and eax, 1`: the accumulator := the top branch point.
    pub fn read_branch(&mut self) {
        self.put(&[0x44, 0x89, 0xE8, 0x83, 0xE0, 0x01]);
    }

    /// `mov ecx, eax`
    pub fn mov_ecx_eax(&mut self) {
        self.put(&[0x89, 0xC1]);
    }

    /// `lea ecx, [rax - 1]`: 0 for a set accumulator, all ones for a clear one.
    pub fn ecx_acc_minus_one(&mut self) {
        self.put(&[0x8D, 0x48, 0xFF]);
    }

    /// `xor ecx, 1`
    pub fn xor_ecx_1(&mut self) {
        self.put(&[0x83, 0xF1, 0x01]);
    }

    /// `or ecx, imm8` (sign-extended).
    pub fn or_ecx_imm8(&mut self, imm: u8) {
        self.put(&[0x83, 0xC9, imm]);
    }

    /// `shl ecx, n` (nothing for 0).
    pub fn shl_ecx(&mut self, n: u8) {
        if n > 0 {
            self.put(&[0xC1, 0xE1, n]);
        }
    }

    /// `add qword [r15 + steps], n` (nothing for 0).
    pub fn add_steps(&mut self, steps: u8, n: u32) {
        // The immediate is sign-extended: a count this large cannot come from a program the
        // profiles' step limits allow.
        assert!(n < 1 << 31, "{n} steps between two joins");
        if n == 0 {
        } else if n < 0x80 {
            self.put(&[0x49, 0x83, 0x47, steps, n as u8]);
        } else {
            self.put(&[0x49, 0x81, 0x47, steps]);
            self.put32(n);
        }
    }

    /// `mov rcx, [r15 + steps]; cmp rcx, [r15 + disp8]`
    pub fn cmp_steps_ctx(&mut self, steps: u8, disp: u8) {
        self.put(&[0x49, 0x8B, 0x4F, steps, 0x49, 0x3B, 0x4F, disp]);
    }

    /// `mov rcx, [r15 + watched]; cmp byte [rcx + network], 0`: whether the monitor watches
    /// the network (the flags say not zero when it does).
    pub fn test_watched(&mut self, watched: u8, network: u32) {
        self.put(&[0x49, 0x8B, 0x4F, watched, 0x80, 0xB9]);
        self.put32(network);
        self.put(&[0]);
    }

    /// `cmovCC eax, ebp`: the accumulator := 0 on the condition (`ebp` is always 0).
    pub fn acc_zero_if(&mut self, c: Cond) {
        self.put(&[0x0F, 0x40 | c as u8, 0xC5]);
    }

    /// `cmovCC eax, r14d`: the accumulator := 1 on the condition (`r14d` is always 1).
    pub fn acc_one_if(&mut self, c: Cond) {
        self.put(&[0x41, 0x0F, 0x40 | c as u8, 0xC6]);
    }

    /// `test eax, eax`
    pub fn test_acc(&mut self) {
        self.put(&[0x85, 0xC0]);
    }

    /// `jCC rel32`; returns where the rel32 field is, for [`Asm::patch_rel32`].
    pub fn jcc(&mut self, c: Cond) -> usize {
        self.put(&[0x0F, 0x80 | c as u8]);
        let at = self.here();
        self.put32(0);
        at
    }

    /// `jz rel8` over `len` bytes that follow.
    pub fn jz_short(&mut self, len: u8) {
        self.put(&[0x74, len]);
    }

    /// `jz rel8` to a place not yet known; returns where the rel8 field is.
    pub fn jz_short_forward(&mut self) -> usize {
        self.put(&[0x74, 0]);
        self.here() - 1
    }

    /// Points the rel8 field at `at` to [`Asm::here`].
    pub fn patch_rel8_here(&mut self, at: usize) {
        let rel = u8::try_from(self.here() - (at + 1)).expect("a short jump spans < 128 bytes");
        assert!(rel < 0x80, "a short jump spans < 128 bytes");
        self.bytes[at] = rel;
    }

    /// `jmp rel32`; returns where the rel32 field is.
    pub fn jmp(&mut self) -> usize {
        self.put(&[0xE9]);
        let at = self.here();
        self.put32(0);
        at
    }

    /// `call rel32`; returns where the rel32 field is.
    pub fn call(&mut self) -> usize {
        self.put(&[0xE8]);
        let at = self.here();
        self.put32(0);
        at
    }

    /// `ret`
    pub fn ret(&mut self) {
        self.put(&[0xC3]);
    }

    /// `push rax; push r12; push r13`: a caller's logic state, 24 bytes, so that with the
    /// return address the stack keeps its 16-byte alignment.
    pub fn save_logic(&mut self) {
        self.put(&[0x50, 0x41, 0x54, 0x41, 0x55]);
    }

    /// `pop r13; pop r12; pop rax`
    pub fn restore_logic(&mut self) {
        self.put(&[0x41, 0x5D, 0x41, 0x5C, 0x58]);
    }

    /// Calls `helper(r15, index, eax)` (System V: rdi, esi, edx) with the accumulator kept,
    /// and leaves the helper's `u32` result in `ecx`.
    pub fn call_helper(&mut self, helper: u64, index: u32) {
        // push rax (the accumulator; also aligns the stack to 16 for the call)
        self.put(&[0x50]);
        // mov rdi, r15
        self.put(&[0x4C, 0x89, 0xFF]);
        // mov esi, index
        self.put(&[0xBE]);
        self.put32(index);
        // mov edx, eax
        self.put(&[0x89, 0xC2]);
        // mov rax, helper
        self.put(&[0x48, 0xB8]);
        self.put(&helper.to_le_bytes());
        // call rax
        self.put(&[0xFF, 0xD0]);
        // mov ecx, eax; pop rax
        self.put(&[0x89, 0xC1, 0x58]);
    }

    /// `test ecx, ecx`
    pub fn test_ecx(&mut self) {
        self.put(&[0x85, 0xC9]);
    }

    /// `mov dword [r15 + disp8], imm32`
    pub fn store_ctx32(&mut self, disp: u8, imm: u32) {
        self.put(&[0x41, 0xC7, 0x47, disp]);
        self.put32(imm);
    }

    /// The entry, called as `extern "C" fn(ctx, mem, target)`: saves the callee-saved
    /// registers, keeps `rsp` in `ctx[0]` for the exits, sets the constants `ebp` = 0 and
    /// `r14d` = 1, empties the logic state and calls `target`. When the code returns, the
    /// exit kind is 0 (done); the common exit follows.
    pub fn prologue(&mut self, exit_kind_at: u8) {
        // push rbx, rbp, r12, r13, r14, r15; sub rsp, 8 (16-byte alignment at the call)
        self.put(&[0x53, 0x55, 0x41, 0x54, 0x41, 0x55, 0x41, 0x56, 0x41, 0x57]);
        self.put(&[0x48, 0x83, 0xEC, 0x08]);
        // mov r15, rdi; mov rbx, rsi; mov [r15], rsp; xor ebp, ebp; mov r14d, 1
        self.put(&[0x49, 0x89, 0xFF, 0x48, 0x89, 0xF3, 0x49, 0x89, 0x27]);
        self.put(&[0x31, 0xED, 0x41, 0xBE, 1, 0, 0, 0]);
        // xor eax, eax; empty stacks; call rdx
        self.put(&[0x31, 0xC0]);
        self.clear_stacks();
        self.put(&[0xFF, 0xD2]);
        self.store_ctx32(exit_kind_at, 0);
    }

    /// The common exit, at [`Asm::here`] when called: restores `rsp` from `ctx[0]` and the
    /// callee-saved registers, and returns to the caller of the entry.
    pub fn epilogue(&mut self) {
        // mov rsp, [r15]; add rsp, 8
        self.put(&[0x49, 0x8B, 0x27, 0x48, 0x83, 0xC4, 0x08]);
        // pop r15, r14, r13, r12, rbp, rbx; ret
        self.put(&[
            0x41, 0x5F, 0x41, 0x5E, 0x41, 0x5D, 0x41, 0x5C, 0x5D, 0x5B, 0xC3,
        ]);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn memory_operands_take_a_short_displacement_when_it_fits() {
        let mut a = Asm::default();
        a.test_mem(0x10, 0x04);
        assert_eq!(a.bytes, [0xF6, 0x43, 0x10, 0x04]);
        let mut a = Asm::default();
        a.test_mem(0x1234, 0x80);
        assert_eq!(a.bytes, [0xF6, 0x83, 0x34, 0x12, 0, 0, 0x80]);
        let mut a = Asm::default();
        a.store_dl(0x200);
        assert_eq!(a.bytes, [0x88, 0x93, 0, 2, 0, 0]);
    }

    #[test]
    fn jumps_are_patched_relative_to_their_end() {
        let mut a = Asm::default();
        let at = a.jmp();
        a.ret();
        a.patch_rel32(at, 0);
        // From the end of the five-byte jump back to its start: -5.
        assert_eq!(&a.bytes[1..5], &(-5i32).to_le_bytes());
    }
}
