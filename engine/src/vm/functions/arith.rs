//! Integer and real maths (docs/plc.md, "Integer maths" and "Real maths"): ADDB/SUBB,
//! MULB/DIVB, ADDR/SUBR, MULR/DIVR and the real functions SIN, COS, TAN, SQRT, DTR, ROUND.

use super::{FnCall, FnOp, bit, int, put, put_real, real, set_bit, size, uint};

/// The signed range a result of `bytes` must fit (docs/plc.md, "Memory": ±2147483647 for 4 bytes).
fn fits(v: i64, bytes: u32) -> bool {
    match bytes {
        1 => (-128..=127).contains(&v),
        2 => (-32768..=32767).contains(&v),
        _ => (-2_147_483_647..=2_147_483_647).contains(&v),
    }
}

/// ADDB / SUBB SIZE IN1 IN2 RST OUT ERR: signed sum or difference at SIZE bytes; ERR not
/// latched (a good result clears it).
#[inline]
pub(super) fn addb_subb(f: &FnCall, act: bool, mem: &mut [u8]) {
    let [data_size, first, second, reset, result, error_out, ..] = &f.args;
    if bit(mem, *reset) {
        set_bit(mem, *error_out, false);
    } else if act {
        let n = size(*data_size);
        let (x, y) = (
            i64::from(int(mem, *first, n)),
            i64::from(int(mem, *second, n)),
        );
        let r = if f.op == FnOp::Addb { x + y } else { x - y };
        if fits(r, n) {
            put(mem, *result, n, r as i32);
            set_bit(mem, *error_out, false);
        } else {
            set_bit(mem, *error_out, true);
        }
    }
}

/// ADDR / SUBR IN1 IN2 RST OUT ERR: real sum or difference; ERR not latched.
#[inline]
pub(super) fn addr_subr(f: &FnCall, act: bool, mem: &mut [u8]) {
    let [first, second, reset, result, error_out, ..] = &f.args;
    if bit(mem, *reset) {
        set_bit(mem, *error_out, false);
    } else if act {
        let (x, y) = (real(mem, *first), real(mem, *second));
        let r = if f.op == FnOp::Addr { x + y } else { x - y };
        if r.is_finite() {
            put_real(mem, *result, r);
            set_bit(mem, *error_out, false);
        } else {
            set_bit(mem, *error_out, true);
        }
    }
}

/// MULB / DIVB IN1 IN2 RST OUT ERR: unsigned 16-bit product, or quotient and remainder, into
/// 4 bytes; ERR latched.
#[inline]
pub(super) fn mulb_divb(f: &FnCall, act: bool, mem: &mut [u8]) {
    let [first, second, reset, result, error_out, ..] = &f.args;
    if bit(mem, *reset) {
        put(mem, *result, 4, 0);
        set_bit(mem, *error_out, false);
    } else if act {
        let (x, y) = (
            uint(mem, *first, 2) & 0xFFFF,
            uint(mem, *second, 2) & 0xFFFF,
        );
        if f.op == FnOp::Mulb {
            let p = u64::from(x) * u64::from(y);
            if p > 2_147_483_647 {
                set_bit(mem, *error_out, true);
            } else {
                put(mem, *result, 4, p as i32);
            }
        } else {
            match (x.checked_div(y), x.checked_rem(y)) {
                (Some(q), Some(r)) => put(mem, *result, 4, (q | r << 16) as i32),
                _ => set_bit(mem, *error_out, true),
            }
        }
    }
}

/// MULR / DIVR IN1 IN2 RST OUT ERR: real product or quotient; ERR latched.
#[inline]
pub(super) fn mulr_divr(f: &FnCall, act: bool, mem: &mut [u8]) {
    let [first, second, reset, result, error_out, ..] = &f.args;
    if bit(mem, *reset) {
        put(mem, *result, 4, 0);
        set_bit(mem, *error_out, false);
    } else if act {
        let (x, y) = (real(mem, *first), real(mem, *second));
        let r = if f.op == FnOp::Mulr { x * y } else { x / y };
        if r.is_finite() && !(f.op == FnOp::Divr && y == 0.0) {
            put_real(mem, *result, r);
        } else {
            set_bit(mem, *error_out, true);
        }
    }
}

/// SIN / COS / TAN / SQRT / DTR / ROUND IN OUT RST ERR: one real function of IN; ERR latched.
#[inline]
pub(super) fn real_function(f: &FnCall, act: bool, mem: &mut [u8]) {
    let [input, result, reset, error_out, ..] = &f.args;
    if bit(mem, *reset) {
        set_bit(mem, *error_out, false);
        return;
    }
    if !act {
        return;
    }
    if f.op == FnOp::Dtr {
        let v = int(mem, *input, 4);
        put_real(mem, *result, v as f32);
        return;
    }
    let x = real(mem, *input);
    if f.op == FnOp::Round {
        let r = x.round();
        // Compared in f64: 2147483647 is not representable in f32 (it rounds to 2^31).
        if r.is_nan() || f64::from(r).abs() > 2_147_483_647.0 {
            set_bit(mem, *error_out, true);
        } else {
            put(mem, *result, 4, r as i32);
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
        put_real(mem, *result, r);
    } else {
        set_bit(mem, *error_out, true);
    }
}
