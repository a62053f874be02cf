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

/// Which of CMP's three result bits is on: 0 for IN1 > IN2, 1 for equal, 2 otherwise (so a
/// NaN, which is neither greater nor equal, reads as "less").
#[inline]
fn greater_equal_less<T: PartialOrd>(x: T, y: T) -> u32 {
    if x > y {
        0
    } else if x == y {
        1
    } else {
        2
    }
}

/// CMP SIZE IN1 IN2 OUT: IN1 > IN2, =, < as signed integers of SIZE.
#[inline]
pub(super) fn cmp(f: &FnCall, act: bool, mem: &mut [u8]) {
    let [data_size, first, second, result_bits, ..] = &f.args;
    if act {
        let n = size(*data_size);
        let (x, y) = (int(mem, *first, n), int(mem, *second, n));
        three_bits(mem, *result_bits, greater_equal_less(x, y));
    }
}

/// CMPR IN1 IN2 OUT: CMP on reals.
#[inline]
pub(super) fn cmpr(f: &FnCall, act: bool, mem: &mut [u8]) {
    let [first, second, result_bits, ..] = &f.args;
    if act {
        let (x, y) = (real(mem, *first), real(mem, *second));
        // A NaN compares as "less" (docs/plc.md, function instructions).
        three_bits(mem, *result_bits, greater_equal_less(x, y));
    }
}

/// ZCP SIZE IN1 IN2 IN3 OUT: IN3 below the zone IN1…IN2, inside it, or above it.
#[inline]
pub(super) fn zcp(f: &FnCall, act: bool, mem: &mut [u8]) {
    let [data_size, lower, upper, value, result_bits, ..] = &f.args;
    if act {
        let n = size(*data_size);
        let (lo, hi, v) = (
            int(mem, *lower, n),
            int(mem, *upper, n),
            int(mem, *value, n),
        );
        three_bits(
            mem,
            *result_bits,
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
