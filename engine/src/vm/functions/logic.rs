//! Logic and rotate/shift (docs/plc.md, "Logic" and "Rotate/shift"): WAND/WOR/WXOR, WINV,
//! PARI, WSHL/WSHR and ROTB, the instructions that work on a value's bits or positions.

use super::{Arg, FnCall, FnOp, bit, int, put, set_bit, size, uint};

/// ROTB FMT CNT SIZE IN_W IN_D OUTE OUTO: which way and how far a turret turns to its target.
pub(super) fn rotb(f: &FnCall, act: bool, mem: &mut [u8]) {
    let [
        format,
        positions,
        data_size,
        current_pos,
        target_pos,
        position_out,
        direction_out,
        ..,
    ] = &f.args;
    if !act {
        return;
    }
    let fmt = match *format {
        Arg::Int(v) => v,
        _ => 0,
    };
    let digit = |k: u32| (fmt / 10i32.pow(k)) % 10 == 1;
    let (rn1, shortest, before, steps_out) = (digit(0), digit(1), digit(2), digit(3));
    let n = size(*data_size);
    let cnt = uint(mem, *positions, n) as i64;
    let (cur, target) = (
        uint(mem, *current_pos, n) as i64,
        uint(mem, *target_pos, n) as i64,
    );
    let first = i64::from(rn1);
    let valid = |p: i64| p >= first && p < first + cnt;
    if cnt <= 0 || !valid(cur) || !valid(target) {
        return;
    }
    if cur == target {
        put(
            mem,
            *position_out,
            n,
            if steps_out { 0 } else { target as i32 },
        );
        set_bit(mem, *direction_out, false);
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
    put(mem, *position_out, n, value as i32);
    set_bit(mem, *direction_out, go_reverse);
}

/// PARI OE RST IN OUT: OUT := IN's parity is not the one OE expects; it does not hold, so
/// RST = 1 or ACT = 0 write 0.
#[inline]
pub(super) fn pari(f: &FnCall, act: bool, mem: &mut [u8]) {
    let [odd_even, reset, input, parity_error, ..] = &f.args;
    let oe = matches!(*odd_even, Arg::Int(1));
    let out = if bit(mem, *reset) || !act {
        false
    } else {
        (uint(mem, *input, 1).count_ones() % 2 == 1) != oe
    };
    set_bit(mem, *parity_error, out);
}

/// WAND / WOR / WXOR SIZE IN1 IN2 OUT: bitwise and, or, exclusive or.
#[inline]
pub(super) fn word_logic(f: &FnCall, act: bool, mem: &mut [u8]) {
    let [data_size, first, second, result, ..] = &f.args;
    if act {
        let n = size(*data_size);
        let (x, y) = (int(mem, *first, n), int(mem, *second, n));
        let r = match f.op {
            FnOp::Wand => x & y,
            FnOp::Wor => x | y,
            _ => x ^ y,
        };
        put(mem, *result, n, r);
    }
}

/// WINV SIZE IN OUT: the bitwise complement.
#[inline]
pub(super) fn winv(f: &FnCall, act: bool, mem: &mut [u8]) {
    let [data_size, source, result, ..] = &f.args;
    if act {
        let n = size(*data_size);
        let v = !int(mem, *source, n);
        put(mem, *result, n, v);
    }
}

/// WSHL / WSHR SIZE N IN OUT: a SIZE-byte pattern shifted by N bits, zeros shifted in.
#[inline]
pub(super) fn shift(f: &FnCall, act: bool, mem: &mut [u8]) {
    let [data_size, shift_count, source, result, ..] = &f.args;
    if act {
        let n = size(*data_size);
        let by = uint(mem, *shift_count, 1);
        // IN is a signed read (a constant is taken modulo its width); the shift works
        // on its bits.
        let v = int(mem, *source, n) as u32 & if n == 4 { u32::MAX } else { (1 << (8 * n)) - 1 };
        let r = if by >= 8 * n {
            0
        } else if f.op == FnOp::Wshl {
            v << by
        } else {
            v >> by
        };
        put(mem, *result, n, r as i32);
    }
}
