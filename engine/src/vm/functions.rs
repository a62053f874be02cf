//! The function instructions' semantics (docs/plc.md, "Function instructions"), one arm per
//! instruction: the match is over [`FnOp`], so an instruction added to the catalogue without
//! semantics here does not compile.
//!
//! Common rules: ACT=0 leaves outputs unchanged unless the row says otherwise; where an
//! instruction has RST (AXCTL aside) RST=1 is served whatever ACT is and the operation is not
//! performed on that scan; "ERR latched" means a good result does not clear ERR.

// Each arm reads like the manual's row ("ACT=1: …"), so an `if act` inside an arm is kept
// rather than folded into a match guard.
#![allow(clippy::collapsible_match)]

use super::InstState;
use super::cnc::Cnc;
use super::code::{Arg, FnCall};
use super::memory::{self, Loc, read_bit, write_bit};
use crate::catalog::{FnOp, xmov_format};
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

fn real(mem: &[u8], a: Arg) -> f32 {
    match a {
        Arg::Real(r) => r,
        Arg::Int(c) => c as f32,
        Arg::Loc(l) => memory::read_real(mem, l),
        _ => 0.0,
    }
}

fn put(mem: &mut [u8], a: Arg, bytes: u32, v: i32) {
    if let Arg::Loc(l) = a {
        memory::write(mem, l, bytes, v);
    }
}

fn put_real(mem: &mut [u8], a: Arg, v: f32) {
    if let Arg::Loc(l) = a {
        memory::write_real(mem, l, v);
    }
}

fn size(a: Arg) -> u32 {
    match a {
        Arg::Int(n @ (1 | 2 | 4)) => n as u32,
        _ => 1,
    }
}

/// The signed range a result of `bytes` must fit (docs/plc.md, "Memory": ±2147483647 for 4 bytes).
fn fits(v: i64, bytes: u32) -> bool {
    match bytes {
        1 => (-128..=127).contains(&v),
        2 => (-32768..=32767).contains(&v),
        _ => (-2_147_483_647..=2_147_483_647).contains(&v),
    }
}

/// Three result bits from `out`, continuing into the next byte past bit 7.
fn three_bits(mem: &mut [u8], out: Arg, which: u32) {
    if let Arg::Bit(b) = out {
        for k in 0..3 {
            set_bit(mem, Arg::Bit(b + k), k == which);
        }
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

/// The decimal digits of a binary digit group (`0100` written as the integer 100) as bits.
fn binary_digits(v: i32) -> u32 {
    let mut v = v.unsigned_abs();
    let (mut out, mut place) = (0u32, 0);
    while v > 0 && place < 8 {
        out |= ((v % 10) & 1) << place;
        v /= 10;
        place += 1;
    }
    out
}

#[inline(never)]
pub(super) fn exec(f: &FnCall, act: bool, st: &mut InstState, cx: &mut Ctx<'_>) {
    let a = &f.args;
    let mem = &mut *cx.mem;
    match f.op {
        FnOp::Cmp => {
            if act {
                let n = size(a[0]);
                let (x, y) = (int(mem, a[1], n), int(mem, a[2], n));
                three_bits(
                    mem,
                    a[3],
                    if x > y {
                        0
                    } else if x == y {
                        1
                    } else {
                        2
                    },
                );
            }
        }
        FnOp::Cmpr => {
            if act {
                let (x, y) = (real(mem, a[0]), real(mem, a[1]));
                // A NaN compares as "less" (docs/plc.md, function instructions).
                three_bits(
                    mem,
                    a[2],
                    if x > y {
                        0
                    } else if x == y {
                        1
                    } else {
                        2
                    },
                );
            }
        }
        FnOp::Tmrb | FnOp::Tmrc => {
            let Arg::Loc(t) = a[0] else { return };
            if act {
                let pt = int(mem, a[1], 4).max(0);
                let mut value = memory::read(mem, t, 4);
                if st.prev_act {
                    if value < pt {
                        let elapsed = (cx.now - st.last_ms).min(i32::MAX as u64) as i32;
                        value = value.saturating_add(elapsed).min(pt);
                    }
                } else if f.op == FnOp::Tmrb {
                    value = 0;
                }
                memory::write(mem, t, 4, value);
                set_bit(mem, a[2], value >= pt);
            } else if f.op == FnOp::Tmrb {
                memory::write(mem, t, 4, 0);
                set_bit(mem, a[2], false);
            }
            st.prev_act = act;
            st.last_ms = cx.now;
        }
        FnOp::Ctrc => {
            let Arg::Loc(c) = a[2] else { return };
            let fmt = match a[0] {
                Arg::Int(v) => v,
                _ => 0,
            };
            let down = fmt % 10 == 1;
            let initial = (fmt / 10) % 10;
            // C holds 0…2147483647 (docs/plc.md, "Memory"): a negative preset counts as 0.
            let n = int(mem, a[3], 4).max(0);
            let start = if down { n } else { initial };
            if bit(mem, a[1]) {
                memory::write(mem, c, 4, start);
                set_bit(mem, a[4], false);
            } else if act && !st.prev_act {
                let value = memory::read(mem, c, 4);
                if !down {
                    if value >= n {
                        memory::write(mem, c, 4, initial);
                        set_bit(mem, a[4], false);
                    } else {
                        memory::write(mem, c, 4, value + 1);
                        set_bit(mem, a[4], value + 1 >= n);
                    }
                } else if value <= initial {
                    memory::write(mem, c, 4, n);
                    set_bit(mem, a[4], false);
                } else {
                    memory::write(mem, c, 4, value - 1);
                    set_bit(mem, a[4], value - 1 <= initial);
                }
            }
            st.prev_act = act;
        }
        FnOp::Movn => {
            if act {
                let n = size(a[0]);
                let v = int(mem, a[1], n);
                put(mem, a[2], n, v);
            }
        }
        FnOp::Movr => {
            if act {
                let v = real(mem, a[0]);
                put_real(mem, a[1], v);
            }
        }
        FnOp::Decb => {
            let n = size(a[0]);
            let mut out = 0u8;
            if act {
                let mask = if n == 4 {
                    u32::MAX
                } else {
                    (1u32 << (8 * n)) - 1
                };
                let v = int(mem, a[1], n) as u32 & mask;
                let base = int(mem, a[2], 4);
                for k in 0..8 {
                    if v == (base.wrapping_add(k) as u32 & mask) {
                        out |= 1 << k;
                    }
                }
            }
            put(mem, a[3], 1, i32::from(out));
        }
        FnOp::Codb => {
            if act {
                let index = uint(mem, a[2], 1);
                let (start, end) = f.table;
                if let Some(v) = cx
                    .consts
                    .get((start + index) as usize)
                    .filter(|_| start + index < end)
                {
                    put(mem, a[3], size(a[0]), *v);
                }
            }
        }
        FnOp::Rotb => rotb(f, act, mem),
        FnOp::Pari => {
            let oe = matches!(a[0], Arg::Int(1));
            let out = if bit(mem, a[1]) || !act {
                false
            } else {
                (uint(mem, a[2], 1).count_ones() % 2 == 1) != oe
            };
            set_bit(mem, a[3], out);
        }
        FnOp::Addb | FnOp::Subb => {
            if bit(mem, a[3]) {
                set_bit(mem, a[5], false);
            } else if act {
                let n = size(a[0]);
                let (x, y) = (i64::from(int(mem, a[1], n)), i64::from(int(mem, a[2], n)));
                let r = if f.op == FnOp::Addb { x + y } else { x - y };
                if fits(r, n) {
                    put(mem, a[4], n, r as i32);
                    set_bit(mem, a[5], false);
                } else {
                    set_bit(mem, a[5], true);
                }
            }
        }
        FnOp::Addr | FnOp::Subr => {
            if bit(mem, a[2]) {
                set_bit(mem, a[4], false);
            } else if act {
                let (x, y) = (real(mem, a[0]), real(mem, a[1]));
                let r = if f.op == FnOp::Addr { x + y } else { x - y };
                if r.is_finite() {
                    put_real(mem, a[3], r);
                    set_bit(mem, a[4], false);
                } else {
                    set_bit(mem, a[4], true);
                }
            }
        }
        FnOp::Difu | FnOp::Difd => {
            let edge = if f.op == FnOp::Difu {
                act && !st.prev_act
            } else {
                !act && st.prev_act
            };
            set_bit(mem, a[0], edge);
            st.prev_act = act;
        }
        FnOp::Alt => {
            if act && !st.prev_act {
                let v = bit(mem, a[0]);
                set_bit(mem, a[0], !v);
            }
            st.prev_act = act;
        }
        FnOp::Move => {
            if act {
                let (h, l) = match (a[0], a[1]) {
                    (Arg::Int(h), Arg::Int(l)) => (binary_digits(h), binary_digits(l)),
                    _ => (0, 0),
                };
                let v = uint(mem, a[2], 1) & (h << 4 | l);
                put(mem, a[3], 1, v as i32);
            }
        }
        FnOp::Wand | FnOp::Wor | FnOp::Wxor => {
            if act {
                let n = size(a[0]);
                let (x, y) = (int(mem, a[1], n), int(mem, a[2], n));
                let r = match f.op {
                    FnOp::Wand => x & y,
                    FnOp::Wor => x | y,
                    _ => x ^ y,
                };
                put(mem, a[3], n, r);
            }
        }
        FnOp::Winv => {
            if act {
                let n = size(a[0]);
                let v = !int(mem, a[1], n);
                put(mem, a[2], n, v);
            }
        }
        FnOp::Wshl | FnOp::Wshr => {
            if act {
                let n = size(a[0]);
                let by = uint(mem, a[1], 1);
                // IN is a signed read (a constant is taken modulo its width); the shift works
                // on its bits.
                let v =
                    int(mem, a[2], n) as u32 & if n == 4 { u32::MAX } else { (1 << (8 * n)) - 1 };
                let r = if by >= 8 * n {
                    0
                } else if f.op == FnOp::Wshl {
                    v << by
                } else {
                    v >> by
                };
                put(mem, a[3], n, r as i32);
            }
        }
        FnOp::Mulb | FnOp::Divb => {
            if bit(mem, a[2]) {
                put(mem, a[3], 4, 0);
                set_bit(mem, a[4], false);
            } else if act {
                let (x, y) = (uint(mem, a[0], 2) & 0xFFFF, uint(mem, a[1], 2) & 0xFFFF);
                if f.op == FnOp::Mulb {
                    let p = u64::from(x) * u64::from(y);
                    if p > 2_147_483_647 {
                        set_bit(mem, a[4], true);
                    } else {
                        put(mem, a[3], 4, p as i32);
                    }
                } else {
                    match (x.checked_div(y), x.checked_rem(y)) {
                        (Some(q), Some(r)) => put(mem, a[3], 4, (q | r << 16) as i32),
                        _ => set_bit(mem, a[4], true),
                    }
                }
            }
        }
        FnOp::Mulr | FnOp::Divr => {
            if bit(mem, a[2]) {
                put(mem, a[3], 4, 0);
                set_bit(mem, a[4], false);
            } else if act {
                let (x, y) = (real(mem, a[0]), real(mem, a[1]));
                let r = if f.op == FnOp::Mulr { x * y } else { x / y };
                if r.is_finite() && !(f.op == FnOp::Divr && y == 0.0) {
                    put_real(mem, a[3], r);
                } else {
                    set_bit(mem, a[4], true);
                }
            }
        }
        FnOp::Windr => windr(f, act, st, cx),
        FnOp::Axctl => axctl(f, act, st, cx),
        FnOp::Xmov => xmov(f, act, mem),
        FnOp::Dschb => {
            if act {
                let n = size(a[0]);
                let count = uint(mem, a[2], 2);
                let key = int(mem, a[3], n);
                let Arg::Loc(table) = a[1] else { return };
                if count == 0 || element(table, count - 1, n).is_none() {
                    set_bit(mem, a[5], true);
                    return;
                }
                let found = (0..count).find(|k| {
                    element(table, *k, n).is_some_and(|e| memory::read(mem, e, n) == key)
                });
                match found {
                    Some(k) => {
                        put(mem, a[4], n, k as i32);
                        set_bit(mem, a[5], false);
                    }
                    None => set_bit(mem, a[5], true),
                }
            }
        }
        FnOp::Psgnl => {
            if act {
                let axis = uint(mem, a[0], 1);
                let Arg::Loc(area) = a[1] else { return };
                let mut bounds = [0i64; 7];
                for (k, b) in bounds.iter_mut().enumerate() {
                    *b = element(area, k as u32, 4)
                        .map_or(0, |e| i64::from(memory::read(mem, e, 4)));
                }
                let ascending = bounds.windows(2).all(|w| w[0] <= w[1]);
                match cx.cnc.machine_position(axis) {
                    Some(pos) if ascending => {
                        let zone = 1 + bounds.iter().filter(|b| **b <= pos).count() as u32;
                        put(mem, a[2], 1, 1 << (8 - zone));
                        set_bit(mem, a[3], false);
                    }
                    _ => {
                        put(mem, a[2], 1, 0);
                        set_bit(mem, a[3], true);
                    }
                }
            }
        }
        FnOp::Psgn2 => {
            if act {
                let axis = uint(mem, a[0], 1);
                let (lo, hi) = (i64::from(int(mem, a[1], 4)), i64::from(int(mem, a[2], 4)));
                match cx.cnc.machine_position(axis) {
                    Some(pos) if lo >= 0 && lo <= hi => {
                        set_bit(mem, a[3], lo <= pos && pos <= hi);
                        set_bit(mem, a[4], false);
                    }
                    _ => {
                        set_bit(mem, a[3], false);
                        set_bit(mem, a[4], true);
                    }
                }
            }
        }
        FnOp::Zcp => {
            if act {
                let n = size(a[0]);
                let (lo, hi, v) = (int(mem, a[1], n), int(mem, a[2], n), int(mem, a[3], n));
                three_bits(
                    mem,
                    a[4],
                    if lo > v {
                        0
                    } else if v > hi {
                        2
                    } else {
                        1
                    },
                );
            }
        }
        FnOp::Sin | FnOp::Cos | FnOp::Tan | FnOp::Sqrt | FnOp::Dtr | FnOp::Round => {
            // Operands: IN, OUT, RST, ERR.
            if bit(mem, a[2]) {
                set_bit(mem, a[3], false);
                return;
            }
            if !act {
                return;
            }
            if f.op == FnOp::Dtr {
                let v = int(mem, a[0], 4);
                put_real(mem, a[1], v as f32);
                return;
            }
            let x = real(mem, a[0]);
            if f.op == FnOp::Round {
                let r = x.round();
                // Compared in f64: 2147483647 is not representable in f32 (it rounds to 2^31).
                if r.is_nan() || f64::from(r).abs() > 2_147_483_647.0 {
                    set_bit(mem, a[3], true);
                } else {
                    put(mem, a[1], 4, r as i32);
                }
                return;
            }
            let r = match f.op {
                FnOp::Sin => (f64::from(x)).sin() as f32,
                FnOp::Cos => (f64::from(x)).cos() as f32,
                FnOp::Tan => (f64::from(x)).tan() as f32,
                _ if x < 0.0 => f32::NAN,
                _ => x.sqrt(),
            };
            if r.is_finite() {
                put_real(mem, a[1], r);
            } else {
                set_bit(mem, a[3], true);
            }
        }
        // Lowering gives these words of their own (vm/code.rs): they never reach a FnCall.
        FnOp::Set | FnOp::Rst | FnOp::Jmpb | FnOp::Lbl | FnOp::Call | FnOp::Callu => {
            unreachable!("{:?} runs as a VM word, not as a function call", f.op)
        }
    }
}

fn rotb(f: &FnCall, act: bool, mem: &mut [u8]) {
    let a = &f.args;
    if !act {
        return;
    }
    let fmt = match a[0] {
        Arg::Int(v) => v,
        _ => 0,
    };
    let digit = |k: u32| (fmt / 10i32.pow(k)) % 10 == 1;
    let (rn1, shortest, before, steps_out) = (digit(0), digit(1), digit(2), digit(3));
    let n = size(a[2]);
    let cnt = uint(mem, a[1], n) as i64;
    let (cur, target) = (uint(mem, a[3], n) as i64, uint(mem, a[4], n) as i64);
    let first = i64::from(rn1);
    let valid = |p: i64| p >= first && p < first + cnt;
    if cnt <= 0 || !valid(cur) || !valid(target) {
        return;
    }
    if cur == target {
        put(mem, a[5], n, if steps_out { 0 } else { target as i32 });
        set_bit(mem, a[6], false);
        return;
    }
    let forward = (target - cur).rem_euclid(cnt);
    let reverse = cnt - forward;
    let go_reverse = shortest && reverse < forward;
    let steps = if go_reverse { reverse } else { forward };
    let value = if steps_out {
        steps - i64::from(before)
    } else if before {
        // The position one step before the target, in the direction of travel.
        let back = if go_reverse { 1 } else { -1 };
        (target - first + back).rem_euclid(cnt) + first
    } else {
        target
    };
    put(mem, a[5], n, value as i32);
    set_bit(mem, a[6], go_reverse);
}

fn xmov(f: &FnCall, act: bool, mem: &mut [u8]) {
    let a = &f.args;
    if bit(mem, a[6]) {
        set_bit(mem, a[7], false);
        return;
    }
    if !act {
        return;
    }
    let write = matches!(a[0], Arg::Int(1));
    let fmt = match a[1] {
        Arg::Int(v) => i64::from(v),
        _ => 1,
    };
    let (x, nn) = xmov_format(fmt);
    let x = u32::from(x);
    let dl = uint(mem, a[2], 2);
    let (Arg::Loc(ds), Arg::Loc(dd), Arg::Loc(di)) = (a[3], a[4], a[5]) else {
        return;
    };
    // A table that runs past its area moves nothing.
    if dl == 0
        || element(ds, dl - 1, x).is_none()
        || element(dd, nn - 1, x).is_none()
        || element(di, nn - 1, x).is_none()
    {
        set_bit(mem, a[7], true);
        return;
    }
    // Every index is read before anything moves.
    let mut indices = [0u32; 99];
    for (k, slot) in indices.iter_mut().enumerate().take(nn as usize) {
        *slot = element(di, k as u32, x).map_or(u32::MAX, |e| memory::read_unsigned(mem, e, x));
    }
    let mut err = false;
    for (k, &index) in indices.iter().enumerate().take(nn as usize) {
        if index >= dl {
            err = true;
            continue;
        }
        let (Some(src), Some(dst)) = (element(ds, index, x), element(dd, k as u32, x)) else {
            err = true;
            continue;
        };
        if write {
            let v = memory::read(mem, dst, x);
            memory::write(mem, src, x, v);
        } else {
            let v = memory::read(mem, src, x);
            memory::write(mem, dst, x, v);
        }
    }
    set_bit(mem, a[7], err);
}

fn windr(f: &FnCall, act: bool, st: &mut InstState, cx: &mut Ctx<'_>) {
    let a = &f.args;
    if !act {
        set_bit(cx.mem, a[1], false);
        st.phase = 0;
        st.prev_act = false;
        return;
    }
    let Arg::Loc(head) = a[0] else { return };
    let start = head.off as usize;
    let end = cx.d_range.end;
    let slots = (end.saturating_sub(start)) / 4;
    if slots < 6 {
        set_bit(cx.mem, a[1], true);
        return;
    }
    let function = memory::read(cx.mem, head, 4);
    let slot = |k: usize| Loc {
        off: head.off + 4 * k as u32,
        ..head
    };
    if !cx.cnc.window_is_low_speed(function) {
        // High speed: executed on the current block every scan with ACT = 1.
        let block = &mut cx.window[..slots];
        for (k, v) in block.iter_mut().enumerate() {
            *v = memory::read(cx.mem, slot(k), 4);
        }
        cx.cnc.window(block);
        for (k, v) in block.iter().enumerate() {
            memory::write(cx.mem, slot(k), 4, *v);
        }
        set_bit(cx.mem, a[1], true);
        st.prev_act = true;
        return;
    }
    // Low speed (docs/cnc.md, "WINDR"): the block is latched at the first scan, the write is applied
    // from the latched block at the second, then ERR stays 1 until ACT drops.
    let n = slots.min(cx.latch.len());
    match st.phase {
        0 => {
            let latch = &mut cx.latch[..n];
            for (k, v) in latch.iter_mut().enumerate() {
                *v = memory::read(cx.mem, slot(k), 4);
            }
            st.phase = 1;
            set_bit(cx.mem, a[1], false);
        }
        1 => {
            let latch = &mut cx.latch[..n];
            cx.cnc.window(latch);
            // A write answers with its end code and data length only.
            for k in 1..3 {
                let v = latch.get(k).copied().unwrap_or(0);
                memory::write(cx.mem, slot(k), 4, v);
            }
            st.phase = 2;
            set_bit(cx.mem, a[1], true);
        }
        _ => {}
    }
    st.prev_act = true;
}

fn axctl(f: &FnCall, act: bool, st: &mut InstState, cx: &mut Ctx<'_>) {
    let a = &f.args;
    let mem = &mut *cx.mem;
    let group = uint(mem, a[0], 1);
    let valid = (1..=4).contains(&group);
    let base = cx.g_base + 140 + 10 * group.saturating_sub(1);
    let g = |k: u32| Loc {
        off: base + k,
        end: u32::MAX,
        wide: false,
    };
    let set_g_bit = |mem: &mut [u8], byte: u32, b: u32, v: bool| {
        if let Some(x) = mem.get_mut((base + byte) as usize) {
            *x = (*x & !(1 << b)) | (u8::from(v) << b);
        }
    };
    if !valid {
        set_bit(mem, a[6], act);
        set_bit(mem, a[5], false);
        st.prev_act = act;
        return;
    }
    if act {
        let issuing = !st.prev_act;
        if issuing {
            // A new command: CMD to EC0–EC6, DT1 to EIF0–15, DT2 to EID0–31, EBUF inverted.
            // ESBK from an earlier abandoned command is withdrawn (docs/plc.md, "Choices where
            // the manual is silent": the manual only says when it is set; left at 1 it would
            // stop every later command).
            let cmd = uint(mem, a[1], 1) as u8 & 0x7F;
            if let Some(x) = mem.get_mut((base + 1) as usize) {
                *x = (*x & 0x80) | cmd;
            }
            let dt1 = int(mem, a[2], 2);
            let dt2 = int(mem, a[3], 4);
            memory::write(mem, g(2), 2, dt1);
            memory::write(mem, g(4), 4, dt2);
            let ebuf = mem.get(base as usize).is_some_and(|x| x >> 7 & 1 == 1);
            set_g_bit(mem, 0, 7, !ebuf);
            set_g_bit(mem, 0, 3, false);
            st.phase = 1;
        }
        // The CNC sees the new command only at the end of this tick, so on the issuing scan
        // the status it reports is the previous command's: it cannot have ended yet.
        let ebuf = mem.get(base as usize).is_some_and(|x| x >> 7 & 1 == 1);
        let mut status = cx.cnc.axis_status(group as u8, ebuf);
        if issuing {
            status.ended = false;
        }
        if status.ended {
            st.phase = 0;
        }
        let rst = bit(mem, a[4]);
        set_g_bit(mem, 0, 6, rst);
        set_bit(mem, a[5], status.ended || rst);
        set_bit(mem, a[6], status.error);
    } else if st.prev_act {
        set_bit(mem, a[5], false);
        set_bit(mem, a[6], false);
        set_g_bit(mem, 0, 6, false);
        let ebuf = mem.get(base as usize).is_some_and(|x| x >> 7 & 1 == 1);
        if st.phase == 1 && !cx.cnc.axis_status(group as u8, ebuf).ended {
            set_g_bit(mem, 0, 3, true);
        }
        st.phase = 0;
    }
    st.prev_act = act;
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
