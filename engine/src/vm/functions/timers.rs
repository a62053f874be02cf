//! The instructions that remember the previous scan's ACT in their instruction memory
//! (docs/plc.md, "Timer/counter" and "Bit output"): TMRB/TMRC, CTRC, DIFU/DIFD and ALT.

use super::{Arg, FnCall, FnOp, InstState, bit, int, memory, set_bit};

/// TMRB T PT OUT (on-delay) and TMRC (retentive): virtual milliseconds counted in T up to PT.
#[inline]
pub(super) fn timer(f: &FnCall, act: bool, st: &mut InstState, mem: &mut [u8], now: u64) {
    let [timer_number, preset, time_up, ..] = &f.args;
    let Arg::Loc(t) = *timer_number else { return };
    if act {
        let pt = int(mem, *preset, 4).max(0);
        let mut value = memory::read(mem, t, 4);
        if st.prev_act {
            if value < pt {
                let elapsed = (now - st.last_ms).min(i32::MAX as u64) as i32;
                value = value.saturating_add(elapsed).min(pt);
            }
        } else if f.op == FnOp::Tmrb {
            value = 0;
        }
        memory::write(mem, t, 4, value);
        set_bit(mem, *time_up, value >= pt);
    } else if f.op == FnOp::Tmrb {
        memory::write(mem, t, 4, 0);
        set_bit(mem, *time_up, false);
    }
    st.prev_act = act;
    st.last_ms = now;
}

/// CTRC FMT RST C N OUT: a ring counter up or down on ACT's rising edge, reset by RST.
#[inline]
pub(super) fn ctrc(f: &FnCall, act: bool, st: &mut InstState, mem: &mut [u8]) {
    let [format, reset, counter, preset, reached, ..] = &f.args;
    let Arg::Loc(c) = *counter else { return };
    let fmt = match *format {
        Arg::Int(v) => v,
        _ => 0,
    };
    let down = fmt % 10 == 1;
    let initial = (fmt / 10) % 10;
    // C holds 0…2147483647 (docs/plc.md, "Memory"): a negative preset counts as 0.
    let n = int(mem, *preset, 4).max(0);
    let start = if down { n } else { initial };
    if bit(mem, *reset) {
        memory::write(mem, c, 4, start);
        set_bit(mem, *reached, false);
    } else if act && !st.prev_act {
        let value = memory::read(mem, c, 4);
        if !down {
            if value >= n {
                memory::write(mem, c, 4, initial);
                set_bit(mem, *reached, false);
            } else {
                memory::write(mem, c, 4, value + 1);
                set_bit(mem, *reached, value + 1 >= n);
            }
        } else if value <= initial {
            memory::write(mem, c, 4, n);
            set_bit(mem, *reached, false);
        } else {
            memory::write(mem, c, 4, value - 1);
            set_bit(mem, *reached, value - 1 <= initial);
        }
    }
    st.prev_act = act;
}

/// DIFU OUT / DIFD OUT: OUT on for the one scan where ACT rose (DIFU) or fell (DIFD).
#[inline]
pub(super) fn edge(f: &FnCall, act: bool, st: &mut InstState, mem: &mut [u8]) {
    let [output, ..] = &f.args;
    let edge = if f.op == FnOp::Difu {
        act && !st.prev_act
    } else {
        !act && st.prev_act
    };
    set_bit(mem, *output, edge);
    st.prev_act = act;
}

/// ALT OUT: OUT toggles on each rising edge of ACT.
#[inline]
pub(super) fn alt(f: &FnCall, act: bool, st: &mut InstState, mem: &mut [u8]) {
    let [output, ..] = &f.args;
    if act && !st.prev_act {
        let v = bit(mem, *output);
        set_bit(mem, *output, !v);
    }
    st.prev_act = act;
}
