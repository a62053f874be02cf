//! Data transfer (docs/plc.md, "Data transfer"): MOVN, MOVR, MOVE, DECB, CODB, XMOV and
//! DSCHB, the moves, decodes and table look-ups.

use super::{Arg, FnCall, bit, element, int, memory, put, put_real, real, set_bit, size, uint};
use crate::catalog::xmov_format;

/// MOVN SIZE IN OUT: OUT := IN, SIZE bytes.
#[inline]
pub(super) fn movn(f: &FnCall, act: bool, mem: &mut [u8]) {
    let [data_size, source, dest, ..] = &f.args;
    if act {
        let n = size(*data_size);
        let v = int(mem, *source, n);
        put(mem, *dest, n, v);
    }
}

/// MOVR IN OUT: copies a real.
#[inline]
pub(super) fn movr(f: &FnCall, act: bool, mem: &mut [u8]) {
    let [source, dest, ..] = &f.args;
    if act {
        let v = real(mem, *source);
        put_real(mem, *dest, v);
    }
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

/// MOVE H L IN OUT: OUT := IN masked by the binary digit groups H and L.
#[inline]
pub(super) fn move_masked(f: &FnCall, act: bool, mem: &mut [u8]) {
    let [high_mask, low_mask, source, dest, ..] = &f.args;
    if act {
        let (h, l) = match (*high_mask, *low_mask) {
            (Arg::Int(h), Arg::Int(l)) => (binary_digits(h), binary_digits(l)),
            _ => (0, 0),
        };
        let v = uint(mem, *source, 1) & (h << 4 | l);
        put(mem, *dest, 1, v as i32);
    }
}

/// DECB SIZE IN BASE OUT: bit k of OUT := (IN = BASE + k); ACT = 0 clears OUT, so the byte is
/// written on every scan.
#[inline]
pub(super) fn decb(f: &FnCall, act: bool, mem: &mut [u8]) {
    let [data_size, source, range_base, dest, ..] = &f.args;
    let n = size(*data_size);
    let mut out = 0u8;
    if act {
        let mask = if n == 4 {
            u32::MAX
        } else {
            (1u32 << (8 * n)) - 1
        };
        let v = int(mem, *source, n) as u32 & mask;
        let base = int(mem, *range_base, 4);
        for k in 0..8 {
            if v == (base.wrapping_add(k) as u32 & mask) {
                out |= 1 << k;
            }
        }
    }
    put(mem, *dest, 1, i32::from(out));
}

/// CODB SIZE1 SIZE2 IN OUT T…: OUT := entry IN of the instruction's constant table, whose
/// entries the lowering put in `consts`; an IN past the table leaves OUT alone.
#[inline]
pub(super) fn codb(f: &FnCall, act: bool, mem: &mut [u8], consts: &[i32]) {
    // SIZE2 is not read: the entries as written, whose range is `f.table`, are the table.
    let [out_size, _entry_count, table_index, dest, ..] = &f.args;
    if act {
        let index = uint(mem, *table_index, 1);
        let (start, end) = f.table;
        if let Some(v) = consts
            .get((start + index) as usize)
            .filter(|_| start + index < end)
        {
            put(mem, *dest, size(*out_size), *v);
        }
    }
}

/// XMOV RW FMT DL DS DD DI RST ERR: indexed moves between a table and a list of elements.
pub(super) fn xmov(f: &FnCall, act: bool, mem: &mut [u8]) {
    let [
        read_write,
        format,
        table_length,
        table_start,
        data_start,
        index_start,
        reset,
        error_out,
        ..,
    ] = &f.args;
    if bit(mem, *reset) {
        set_bit(mem, *error_out, false);
        return;
    }
    if !act {
        return;
    }
    let write = matches!(*read_write, Arg::Int(1));
    let fmt = match *format {
        Arg::Int(v) => i64::from(v),
        _ => 1,
    };
    let (x, nn) = xmov_format(fmt);
    let x = u32::from(x);
    let dl = uint(mem, *table_length, 2);
    let (Arg::Loc(ds), Arg::Loc(dd), Arg::Loc(di)) = (*table_start, *data_start, *index_start)
    else {
        return;
    };
    // A table that runs past its area moves nothing.
    if dl == 0
        || element(ds, dl - 1, x).is_none()
        || element(dd, nn - 1, x).is_none()
        || element(di, nn - 1, x).is_none()
    {
        set_bit(mem, *error_out, true);
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
    set_bit(mem, *error_out, err);
}

/// DSCHB SIZE IN1 INL DS DI ERR: the index of the first table element equal to the key.
#[inline]
pub(super) fn dschb(f: &FnCall, act: bool, mem: &mut [u8]) {
    let [
        data_size,
        table_start,
        entry_count,
        search_value,
        index_out,
        error_out,
        ..,
    ] = &f.args;
    if act {
        let n = size(*data_size);
        let count = uint(mem, *entry_count, 2);
        let key = int(mem, *search_value, n);
        let Arg::Loc(table) = *table_start else {
            return;
        };
        if count == 0 || element(table, count - 1, n).is_none() {
            set_bit(mem, *error_out, true);
            return;
        }
        let found = (0..count)
            .find(|k| element(table, *k, n).is_some_and(|e| memory::read(mem, e, n) == key));
        match found {
            Some(k) => {
                put(mem, *index_out, n, k as i32);
                set_bit(mem, *error_out, false);
            }
            None => set_bit(mem, *error_out, true),
        }
    }
}
