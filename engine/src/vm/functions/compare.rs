//! Compare (docs/plc.md, "Compare"): CMP, CMPR and ZCP, each setting one of three result bits.

use super::{Arg, FnCall, int, real, set_bit, size};

/// Three result bits from `out`, continuing into the next byte past bit 7.
fn three_bits(mem: &mut [u8], out: Arg, which: u32) {
    if let Arg::Bit(b) = out {
        for k in 0..3 {
            set_bit(mem, Arg::Bit(b + k), k == which);
        }
    }
}

/// CMP SIZE IN1 IN2 OUT: IN1 > IN2, =, < as signed integers of SIZE.
#[inline]
pub(super) fn cmp(f: &FnCall, act: bool, mem: &mut [u8]) {
    let a = &f.args;
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

/// CMPR IN1 IN2 OUT: CMP on reals.
#[inline]
pub(super) fn cmpr(f: &FnCall, act: bool, mem: &mut [u8]) {
    let a = &f.args;
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

/// ZCP SIZE IN1 IN2 IN3 OUT: IN3 below the zone IN1…IN2, inside it, or above it.
#[inline]
pub(super) fn zcp(f: &FnCall, act: bool, mem: &mut [u8]) {
    let a = &f.args;
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
