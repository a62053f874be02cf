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
    let a = &f.args;
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

/// ADDR / SUBR IN1 IN2 RST OUT ERR: real sum or difference; ERR not latched.
#[inline]
pub(super) fn addr_subr(f: &FnCall, act: bool, mem: &mut [u8]) {
    let a = &f.args;
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

/// MULB / DIVB IN1 IN2 RST OUT ERR: unsigned 16-bit product, or quotient and remainder, into
/// 4 bytes; ERR latched.
#[inline]
pub(super) fn mulb_divb(f: &FnCall, act: bool, mem: &mut [u8]) {
    let a = &f.args;
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

/// MULR / DIVR IN1 IN2 RST OUT ERR: real product or quotient; ERR latched.
#[inline]
pub(super) fn mulr_divr(f: &FnCall, act: bool, mem: &mut [u8]) {
    let a = &f.args;
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

/// SIN / COS / TAN / SQRT / DTR / ROUND IN OUT RST ERR: one real function of IN; ERR latched.
#[inline]
pub(super) fn real_function(f: &FnCall, act: bool, mem: &mut [u8]) {
    let a = &f.args;
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
