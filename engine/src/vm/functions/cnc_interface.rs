//! CNC interface (docs/plc.md, "CNC interface"): WINDR, AXCTL, PSGNL and PSGN2, the
//! instructions that ask the CNC or command it, through [`Ctx`]'s [`Cnc`].

use super::{Arg, Cnc, Ctx, FnCall, InstState, Loc, bit, element, int, memory, put, set_bit, uint};

/// PSGNL AXIS AREA OUT ERR: which of eight zones, bounded by AREA's seven boundaries, the
/// axis's machine position is in.
#[inline]
pub(super) fn psgnl(f: &FnCall, act: bool, mem: &mut [u8], cnc: &dyn Cnc) {
    let [axis_number, boundary_table, zone_out, error_out, ..] = &f.args;
    if act {
        let axis = uint(mem, *axis_number, 1);
        let Arg::Loc(area) = *boundary_table else {
            return;
        };
        let mut bounds = [0i64; 7];
        for (k, b) in bounds.iter_mut().enumerate() {
            *b = element(area, k as u32, 4).map_or(0, |e| i64::from(memory::read(mem, e, 4)));
        }
        let ascending = bounds.windows(2).all(|w| w[0] <= w[1]);
        match cnc.machine_position(axis) {
            Some(pos) if ascending => {
                let zone = 1 + bounds.iter().filter(|b| **b <= pos).count() as u32;
                put(mem, *zone_out, 1, 1 << (8 - zone));
                set_bit(mem, *error_out, false);
            }
            _ => {
                put(mem, *zone_out, 1, 0);
                set_bit(mem, *error_out, true);
            }
        }
    }
}

/// PSGN2 AXIS MIN MAX OUT ERR: OUT := MIN ≤ the axis's machine position ≤ MAX.
#[inline]
pub(super) fn psgn2(f: &FnCall, act: bool, mem: &mut [u8], cnc: &dyn Cnc) {
    let [axis_number, minimum, maximum, inside, error_out, ..] = &f.args;
    if act {
        let axis = uint(mem, *axis_number, 1);
        let (lo, hi) = (
            i64::from(int(mem, *minimum, 4)),
            i64::from(int(mem, *maximum, 4)),
        );
        match cnc.machine_position(axis) {
            Some(pos) if lo >= 0 && lo <= hi => {
                set_bit(mem, *inside, lo <= pos && pos <= hi);
                set_bit(mem, *error_out, false);
            }
            _ => {
                set_bit(mem, *inside, false);
                set_bit(mem, *error_out, true);
            }
        }
    }
}

/// WINDR IN ERR: a window call on the D block at IN, at once for a high-speed function, over
/// two scans (latch, then apply) for a low-speed one.
pub(super) fn windr(f: &FnCall, act: bool, st: &mut InstState, cx: &mut Ctx<'_>) {
    let [window_block, done, ..] = &f.args;
    if !act {
        set_bit(cx.mem, *done, false);
        st.phase = 0;
        st.prev_act = false;
        return;
    }
    let Arg::Loc(head) = *window_block else {
        return;
    };
    let start = head.off as usize;
    let end = cx.d_range.end;
    let slots = (end.saturating_sub(start)) / 4;
    if slots < 6 {
        set_bit(cx.mem, *done, true);
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
        set_bit(cx.mem, *done, true);
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
            set_bit(cx.mem, *done, false);
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
            set_bit(cx.mem, *done, true);
        }
        _ => {}
    }
    st.prev_act = true;
}

/// AXCTL GRP CMD DT1 DT2 RST FIN ERR: issues a PLC-axis command to group GRP when ACT rises and
/// reports its end and errors while ACT stays 1; a command abandoned when ACT falls is
/// stopped through the block-stop signal.
pub(super) fn axctl(f: &FnCall, act: bool, st: &mut InstState, cx: &mut Ctx<'_>) {
    let [
        group_number,
        command,
        data1,
        data2,
        reset,
        finished,
        error_out,
        ..,
    ] = &f.args;
    let mem = &mut *cx.mem;
    let group = uint(mem, *group_number, 1);
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
        set_bit(mem, *error_out, act);
        set_bit(mem, *finished, false);
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
            let cmd = uint(mem, *command, 1) as u8 & 0x7F;
            if let Some(x) = mem.get_mut((base + 1) as usize) {
                *x = (*x & 0x80) | cmd;
            }
            let dt1 = int(mem, *data1, 2);
            let dt2 = int(mem, *data2, 4);
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
        let rst = bit(mem, *reset);
        set_g_bit(mem, 0, 6, rst);
        set_bit(mem, *finished, status.ended || rst);
        set_bit(mem, *error_out, status.error);
    } else if st.prev_act {
        set_bit(mem, *finished, false);
        set_bit(mem, *error_out, false);
        set_g_bit(mem, 0, 6, false);
        let ebuf = mem.get(base as usize).is_some_and(|x| x >> 7 & 1 == 1);
        if st.phase == 1 && !cx.cnc.axis_status(group as u8, ebuf).ended {
            set_g_bit(mem, 0, 3, true);
        }
        st.phase = 0;
    }
    st.prev_act = act;
}
