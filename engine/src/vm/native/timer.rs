//! TMRB in generated code: the timer every ladder has by the dozen, run without the helper
//! call, as `functions::exec` runs it (docs/plc.md, TMRB):
//!
//! ```text
//! ACT = 1: PT := max(preset, 0); V := T
//!          previous ACT = 1: if V < PT, V := min(V + min(now − last, i32::MAX), PT) (saturating)
//!          previous ACT = 0: V := 0
//!          T := V; OUT := V ≥ PT
//! ACT = 0: T := 0; OUT := 0
//! then previous ACT := ACT; last := now
//! ```
//!
//! Only the usual operands are generated here (T as a 4-byte location, the preset a constant
//! or a 4-byte location, OUT a bit, all inside the image); any other TMRB goes through the
//! helper. The checked engine and `engine/tests/engines.rs` hold this to the interpreter.

use super::super::IMAGE_BYTES;
use super::super::code::{Arg, FnCall};
use super::asm::{Asm, Cond};
use super::{CTX_NOW, CTX_STATES};
use crate::catalog::FnOp;

/// Byte size of an instruction memory, and its fields' offsets (`InstState` is `repr(C)`).
const STATE_BYTES: u32 = std::mem::size_of::<super::super::InstState>() as u32;
const PREV_ACT: u8 = std::mem::offset_of!(super::super::InstState, prev_act) as u8;
const LAST_MS: u8 = std::mem::offset_of!(super::super::InstState, last_ms) as u8;
const _: () = assert!(PREV_ACT == 0 && LAST_MS == 8);

/// The preset as generated code reads it.
enum Preset {
    /// A constant, already `max(c, 0)`.
    Const(u32),
    /// Four bytes at this image offset.
    At(u32),
}

/// The operands of a TMRB the generated code runs itself: T's offset, the preset, OUT's bit
/// index; `None` for any other instruction or operands.
fn operands(f: &FnCall) -> Option<(u32, Preset, u32)> {
    let inside = |off: u32| off as usize + 4 <= IMAGE_BYTES;
    if f.op != FnOp::Tmrb {
        return None;
    }
    let t = match f.args[0] {
        Arg::Loc(t) if inside(t.off) => t.off,
        _ => return None,
    };
    let preset = match f.args[1] {
        Arg::Int(c) => Preset::Const(c.max(0) as u32),
        Arg::Loc(l) if inside(l.off) => Preset::At(l.off),
        _ => return None,
    };
    let out = match f.args[2] {
        Arg::Bit(b) if ((b >> 3) as usize) < IMAGE_BYTES => b,
        _ => return None,
    };
    Some((t, preset, out))
}

/// Generates `f` when it is a TMRB with the usual operands; returns whether it did. The
/// accumulator (`eax`) is ACT and stays; the coil byte in `dl` was written back before.
pub(super) fn tmrb(a: &mut Asm, f: &FnCall) -> bool {
    let Some((t, preset, out)) = operands(f) else {
        return false;
    };
    // The instance's offset is a sign-extended immediate.
    let Some(state_at) = f.state.checked_mul(STATE_BYTES).filter(|&o| o < 1 << 31) else {
        return false;
    };
    let (out_byte, out_bit) = (out >> 3, (out & 7) as u8);
    // mov rsi, [r15 + states]; add rsi, state × size: this instance's memory.
    a.raw(&[0x49, 0x8B, 0x77, CTX_STATES, 0x48, 0x81, 0xC6]);
    a.raw32(state_at);
    // mov rdi, [r15 + now]
    a.raw(&[0x49, 0x8B, 0x7F, CTX_NOW]);
    a.test_acc();
    let off = a.jcc(Cond::Zero);
    // ecx := PT
    match preset {
        Preset::Const(c) => {
            // mov ecx, c
            a.raw(&[0xB9]);
            a.raw32(c);
        }
        Preset::At(p) => {
            // mov ecx, [rbx + p]; test ecx, ecx; cmovs ecx, ebp (max with 0)
            a.rbx_op(&[0x8B], 1, p);
            a.raw(&[0x85, 0xC9, 0x0F, 0x48, 0xCD]);
        }
    }
    // mov edx, [rbx + t]: V
    a.rbx_op(&[0x8B], 2, t);
    // cmp byte [rsi + prev_act], 0
    a.raw(&[0x80, 0x7E, PREV_ACT, 0x00]);
    let fresh = a.jcc(Cond::Zero);
    // cmp edx, ecx: V ≥ PT keeps V
    a.raw(&[0x39, 0xCA]);
    let store_done = a.jcc(Cond::GreaterEq);
    // r8 := min(now − last, i32::MAX): mov r8, rdi; sub r8, [rsi + last];
    // mov r9d, 0x7fffffff; cmp r8, r9; cmova r8, r9
    a.raw(&[0x49, 0x89, 0xF8, 0x4C, 0x2B, 0x46, LAST_MS, 0x41, 0xB9]);
    a.raw32(i32::MAX as u32);
    a.raw(&[0x4D, 0x39, 0xC8, 0x4D, 0x0F, 0x47, 0xC1]);
    // add edx, r8d; jno +5; mov edx, i32::MAX (saturate)
    a.raw(&[0x44, 0x01, 0xC2, 0x71, 0x05, 0xBA]);
    a.raw32(i32::MAX as u32);
    // cmp edx, ecx; cmovg edx, ecx: min with PT
    a.raw(&[0x39, 0xCA, 0x0F, 0x4F, 0xD1]);
    let store = a.jmp();
    let fresh_at = a.here();
    a.patch_rel32(fresh, fresh_at);
    // xor edx, edx: a new start counts from 0
    a.raw(&[0x31, 0xD2]);
    let store_at = a.here();
    a.patch_rel32(store, store_at);
    a.patch_rel32(store_done, store_at);
    // mov [rbx + t], edx; cmp edx, ecx; setge dl; movzx edx, dl; shl edx, bit
    a.rbx_op(&[0x89], 2, t);
    a.raw(&[0x39, 0xCA, 0x0F, 0x9D, 0xC2, 0x0F, 0xB6, 0xD2]);
    if out_bit > 0 {
        a.raw(&[0xC1, 0xE2, out_bit]);
    }
    // and byte [rbx + out], !mask; or byte [rbx + out], dl
    a.rbx_op(&[0x80], 4, out_byte);
    a.raw(&[!(1u8 << out_bit)]);
    a.rbx_op(&[0x08], 2, out_byte);
    let end = a.jmp();
    let off_at = a.here();
    a.patch_rel32(off, off_at);
    // ACT = 0: mov dword [rbx + t], 0; and byte [rbx + out], !mask
    a.rbx_op(&[0xC7], 0, t);
    a.raw32(0);
    a.rbx_op(&[0x80], 4, out_byte);
    a.raw(&[!(1u8 << out_bit)]);
    let end_at = a.here();
    a.patch_rel32(end, end_at);
    // mov [rsi + prev_act], al; mov [rsi + last], rdi
    a.raw(&[0x88, 0x46, PREV_ACT, 0x48, 0x89, 0x7E, LAST_MS]);
    true
}
