//! The function instructions' semantics (docs/plc.md, "Function instructions"): [`exec`]
//! dispatches on [`FnOp`] to one helper per instruction, kept in one file per instruction
//! family of the manual, so an instruction added to the catalogue without semantics here does
//! not compile. This file holds the dispatch and the operand rules every family shares.
//!
//! Common rules: ACT=0 leaves outputs unchanged unless the row says otherwise; where an
//! instruction has RST (AXCTL aside) RST=1 is served whatever ACT is and the operation is not
//! performed on that scan; "ERR latched" means a good result does not clear ERR.
//!
//! Everything here runs inside the scan: no allocation, hashing or string work. The helpers
//! that were arms of the one match are `#[inline]`, so the dispatch costs what that match did.
//! Each helper names its operands as docs/instructions.md lists them by binding references into
//! `f.args` (`let [data_size, first, ..] = &f.args`) and reading them where they are used:
//! bound by value instead, the inlined helpers' operands were loaded at the top of [`exec`],
//! a larger frame on every call, where references compile to the positional reads they replace.

mod arith;
mod cnc_interface;
mod compare;
mod logic;
mod timers;
mod transfer;

use super::InstState;
use super::cnc::Cnc;
use super::code::{Arg, FnCall};
use super::memory::{self, Loc, read_bit, write_bit};
use crate::catalog::FnOp;
use std::ops::Range;

/// What a function instruction may touch besides its own operands.
pub(super) struct Ctx<'a> {
    pub mem: &'a mut [u8],
    pub consts: &'a [i32],
    pub now: u64,
    pub cnc: &'a mut dyn Cnc,
    pub window: &'a mut [i32],
    /// This instance's latched WINDR block.
    pub latch: &'a mut [i32],
    pub g_base: u32,
    pub d_range: Range<usize>,
}

/// [`outcome`] of an execution that compared nothing.
pub(super) const NO_OUTCOME: u8 = 3;

/// The result a compare (CMP, CMPR, ZCP) that just ran with ACT = 1 took, as the index of the
/// result bit it set (0, 1, 2); [`NO_OUTCOME`] for any other instruction. Read back from its
/// result bits, so only coverage pays for it.
pub(super) fn outcome(f: &FnCall, mem: &[u8]) -> u8 {
    let out = match f.op {
        FnOp::Cmp => f.args[3],
        FnOp::Cmpr => f.args[2],
        FnOp::Zcp => f.args[4],
        _ => return NO_OUTCOME,
    };
    let Arg::Bit(b) = out else {
        return NO_OUTCOME;
    };
    (0..3u8)
        .find(|&k| bit(mem, Arg::Bit(b + u32::from(k))))
        .unwrap_or(NO_OUTCOME)
}

/// Runs one function instruction with its ACT. One arm per instruction (or per pair the manual
/// describes together), each handing the helper only what it touches: the image for most, the
/// instruction's memory for those that remember the previous scan, the CNC for its interface.
#[inline(never)]
pub(super) fn exec(f: &FnCall, act: bool, st: &mut InstState, cx: &mut Ctx<'_>) {
    let mem = &mut *cx.mem;
    match f.op {
        FnOp::Cmp => compare::cmp(f, act, mem),
        FnOp::Cmpr => compare::cmpr(f, act, mem),
        FnOp::Tmrb | FnOp::Tmrc => timers::timer(f, act, st, mem, cx.now),
        FnOp::Ctrc => timers::ctrc(f, act, st, mem),
        FnOp::Movn => transfer::movn(f, act, mem),
        FnOp::Movr => transfer::movr(f, act, mem),
        FnOp::Decb => transfer::decb(f, act, mem),
        FnOp::Codb => transfer::codb(f, act, mem, cx.consts),
        FnOp::Rotb => logic::rotb(f, act, mem),
        FnOp::Pari => logic::pari(f, act, mem),
        FnOp::Addb | FnOp::Subb => arith::addb_subb(f, act, mem),
        FnOp::Addr | FnOp::Subr => arith::addr_subr(f, act, mem),
        FnOp::Difu | FnOp::Difd => timers::edge(f, act, st, mem),
        FnOp::Alt => timers::alt(f, act, st, mem),
        FnOp::Move => transfer::move_masked(f, act, mem),
        FnOp::Wand | FnOp::Wor | FnOp::Wxor => logic::word_logic(f, act, mem),
        FnOp::Winv => logic::winv(f, act, mem),
        FnOp::Wshl | FnOp::Wshr => logic::shift(f, act, mem),
        FnOp::Mulb | FnOp::Divb => arith::mulb_divb(f, act, mem),
        FnOp::Mulr | FnOp::Divr => arith::mulr_divr(f, act, mem),
        FnOp::Windr => cnc_interface::windr(f, act, st, cx),
        FnOp::Axctl => cnc_interface::axctl(f, act, st, cx),
        FnOp::Xmov => transfer::xmov(f, act, mem),
        FnOp::Dschb => transfer::dschb(f, act, mem),
        FnOp::Psgnl => cnc_interface::psgnl(f, act, mem, &*cx.cnc),
        FnOp::Psgn2 => cnc_interface::psgn2(f, act, mem, &*cx.cnc),
        FnOp::Zcp => compare::zcp(f, act, mem),
        FnOp::Sin | FnOp::Cos | FnOp::Tan | FnOp::Sqrt | FnOp::Dtr | FnOp::Round => {
            arith::real_function(f, act, mem)
        }
        // Lowering gives these words of their own (vm/code.rs): they never reach a FnCall.
        FnOp::Set | FnOp::Rst | FnOp::Jmpb | FnOp::Lbl | FnOp::Call | FnOp::Callu => {
            unreachable!("{:?} runs as a VM word, not as a function call", f.op)
        }
    }
}

/// Reads a real operand: a real constant as written, an integer constant converted, a
/// location as the 4-byte float it holds.
fn real(mem: &[u8], a: Arg) -> f32 {
    match a {
        Arg::Real(r) => r,
        Arg::Int(c) => c as f32,
        Arg::Loc(l) => memory::read_real(mem, l),
        _ => 0.0,
    }
}

/// Writes `bytes` of `v` to an output operand; anything but a location (a constant the
/// compiler let through) receives nothing.
fn put(mem: &mut [u8], a: Arg, bytes: u32, v: i32) {
    if let Arg::Loc(l) = a {
        memory::write(mem, l, bytes, v);
    }
}

/// Writes a real to an output operand, as [`put`] does an integer.
fn put_real(mem: &mut [u8], a: Arg, v: f32) {
    if let Arg::Loc(l) = a {
        memory::write_real(mem, l, v);
    }
}

/// A SIZE operand's byte width: 1, 2 or 4, anything else taken as 1.
fn size(a: Arg) -> u32 {
    match a {
        Arg::Int(n @ (1 | 2 | 4)) => n as u32,
        _ => 1,
    }
}

/// Element `k` of a table of `bytes`-wide elements at `loc` (docs/plc.md element rule), or
/// `None` when it lies past the area's end.
fn element(loc: Loc, k: u32, bytes: u32) -> Option<Loc> {
    let step = if loc.wide { 4 } else { bytes };
    let off = loc.off.checked_add(k.checked_mul(step)?)?;
    let need = if loc.wide { 4 } else { bytes };
    (off + need <= loc.end).then_some(Loc { off, ..loc })
}

/// Reads a signed operand of `bytes` (a constant is taken modulo its width).
#[inline]
pub(super) fn int(mem: &[u8], a: Arg, bytes: u32) -> i32 {
    match a {
        Arg::Int(c) => memory::sign_extend(c as u32, bytes),
        Arg::Loc(l) => memory::read(mem, l, bytes),
        Arg::Real(r) => r as i32,
        Arg::Bit(b) => read_bit(mem, b) as i32,
        Arg::None => 0,
    }
}

/// Reads an unsigned operand (a constant as written).
#[inline]
pub(super) fn uint(mem: &[u8], a: Arg, bytes: u32) -> u32 {
    match a {
        Arg::Int(c) => c as u32,
        Arg::Loc(l) => memory::read_unsigned(mem, l, bytes),
        Arg::Real(r) => r as u32,
        Arg::Bit(b) => read_bit(mem, b),
        Arg::None => 0,
    }
}

/// Reads a bit operand.
#[inline]
pub(super) fn bit(mem: &[u8], a: Arg) -> bool {
    match a {
        Arg::Bit(b) => read_bit(mem, b) == 1,
        _ => false,
    }
}

/// Writes a bit operand (a byte operand receives 0 or 1, as WINDR's ERR may be).
#[inline]
pub(super) fn set_bit(mem: &mut [u8], a: Arg, v: bool) {
    match a {
        Arg::Bit(b) => write_bit(mem, b, u32::from(v)),
        Arg::Loc(l) => memory::write(mem, l, if l.wide { 4 } else { 1 }, i32::from(v)),
        _ => {}
    }
}
