//! The CNC window (WINDR) functions of both profiles (docs/cnc.md, "WINDR"): reads and writes of offsets, parameters, macro variables, positions,
//! the clock and the status, each with the end codes its table documents.
//!
//! A block is `[0]` function, `[1]` end code, `[2]` data length, `[3]` data number,
//! `[4]` attribute, `[5]` channel, `[6..]` data. On an error the end code is written, the
//! length set to 0 and the data left alone; a successful write leaves the length as it was.

use super::data::{MacroSlot, OffsetType, civil};
use super::params::{self, ParamKind, Selector, TABLE};
use super::program::MDI_NUMBER;
use super::{ALARM_ESTOP, AXES, Mode, RunState, SimCnc};
use crate::profile::ProfileId;
use crate::vm::cnc::Cnc;

/// Largest tool-offset value, increments (±99999.999 mm).
const OFFSET_MAX: i64 = 99_999_999;

fn fail(b: &mut [i32], code: i32) {
    b[1] = code;
    b[2] = 0;
}

fn out(b: &mut [i32], data: &[i64]) {
    if 6 + data.len() > b.len() {
        fail(b, 2);
        return;
    }
    b[1] = 0;
    b[2] = data.len() as i32;
    for (slot, v) in b[6..].iter_mut().zip(data) {
        *slot = (*v).clamp(-i64::from(i32::MAX), i64::from(i32::MAX)) as i32;
    }
}

/// Writes `n` values computed by `f` (no allocation: windows run inside the scan).
fn out_n(b: &mut [i32], n: usize, f: impl Fn(usize) -> i64) {
    if 6 + n > b.len() {
        fail(b, 2);
        return;
    }
    b[1] = 0;
    b[2] = n as i32;
    for (k, slot) in b[6..6 + n].iter_mut().enumerate() {
        *slot = f(k).clamp(-i64::from(i32::MAX), i64::from(i32::MAX)) as i32;
    }
}

fn written(b: &mut [i32]) {
    b[1] = 0;
}

impl SimCnc {
    /// Executes one WINDR block.
    pub(super) fn windr(&mut self, b: &mut [i32]) {
        if b.len() < 6 {
            return;
        }
        // A write's data must lie inside the D area.
        let writes = self.window_is_low_speed(b[0]);
        if writes && (b[2] < 0 || 6 + b[2] as usize > b.len()) {
            return fail(b, 2);
        }
        match self.profile {
            ProfileId::Gsk988ta => self.windr_988(b),
            ProfileId::Gsk980 => self.windr_980(b),
        }
    }

    fn windr_988(&mut self, b: &mut [i32]) {
        let count = self.axis_count() as i64;
        match b[0] {
            0 => out(b, &[988, 2, 0, 100, count]),
            5 => out(b, &[2]),
            13 => {
                let (no, ty) = (b[3], b[4]);
                if !(1..=99).contains(&no) {
                    return fail(b, 3);
                }
                let Some(t) = OffsetType::from_988(ty) else {
                    return fail(b, 4);
                };
                let v = self.offsets[no as usize].get(t);
                out(b, &[v]);
            }
            14 => {
                if b[2] != 1 {
                    return fail(b, 2);
                }
                let (no, ty) = (b[3], b[4]);
                if !(1..=99).contains(&no) {
                    return fail(b, 3);
                }
                let Some(t) = OffsetType::from_988(ty) else {
                    return fail(b, 4);
                };
                let v = i64::from(b[6]);
                if !offset_ok(t, v) {
                    return fail(b, 6);
                }
                self.offsets[no as usize].set(t, v);
                written(b);
            }
            17 => self.param_read_988(b),
            18 => self.param_write_988(b),
            21 => self.macro_read(b),
            22 => self.macro_write(b),
            27 | 28 | 77 | 78 => {
                let n = self.axis_count();
                let Some(sel) = axis_selection(b[4], n, true) else {
                    return fail(b, 4);
                };
                let f = b[0];
                out_n(b, sel.len(), |k| self.axis_value(f, sel.start + k));
            }
            34 | 79 | 83 => {
                if !(1..=count).contains(&i64::from(b[4])) {
                    return fail(b, 4);
                }
                out(b, &[0]);
            }
            80 | 84 | 153 => {
                if b[4] != 1 {
                    return fail(b, 4);
                }
                out(b, &[0]);
            }
            81 => {
                let s = (self.cutting_ms / 1000) as i64;
                out(b, &[s / 3600, s / 60 % 60, s % 60]);
            }
            82 => {
                // No additional axes (#8410 = 0): all of them is none; a single one of the
                // four is unassigned and reads 0.
                match b[4] {
                    -1 => out(b, &[]),
                    1..=4 => out(b, &[0]),
                    _ => fail(b, 4),
                }
            }
            151 => {
                let c = self.clock();
                out(b, &c);
            }
            _ => fail(b, 1),
        }
    }

    fn windr_980(&mut self, b: &mut [i32]) {
        let count = self.axis_count() as i64;
        match b[0] {
            0 => out(b, &[980, 1, 0, 100, count]),
            13 | 14 => self.offset_980(b),
            15 | 16 => self.workpiece_980(b),
            17 | 18 => self.param_980(b),
            21 => self.macro_read(b),
            22 => self.macro_write(b),
            23 => {
                out_n(b, self.alarms.len(), |k| i64::from(self.alarms[k]));
            }
            24 => self.program_numbers_980(b),
            25 => {
                if self.auto.last_n == 0 {
                    return fail(b, 5);
                }
                out(b, &[i64::from(self.auto.last_n)]);
            }
            26 => out(b, &[self.flags.path_speed.round() as i64]),
            27 | 28 | 29 | 74 | 75 => self.axis_values_980(b),
            32 => self.modal_980(b),
            33 => fail(b, 3),
            50 => out(b, &[i64::from(self.spindle.s_out.min(65_535))]),
            76 => self.status_980(b),
            151 => {
                let c = self.clock();
                match b[3] {
                    -1 => out(b, &c),
                    0 => out(b, &c[..3]),
                    1 => out(b, &c[3..]),
                    _ => fail(b, 3),
                }
            }
            _ => fail(b, 1),
        }
    }

    /// GSK980 functions 13 and 14: read or write one tool offset (0–32). With No.4 bit 4 set
    /// the window shows X offsets as radii while the CNC keeps diameters, so both directions
    /// convert.
    fn offset_980(&mut self, b: &mut [i32]) {
        if b[0] == 14 && b[2] != 1 {
            return fail(b, 2);
        }
        let (no, ty) = (b[3], b[4]);
        if !(0..=32).contains(&no) {
            return fail(b, 3);
        }
        let Some(t) = OffsetType::from_980(ty) else {
            return fail(b, 4);
        };
        // No.4 bit 4 = 1: X offsets are radii on the window.
        let radius = self.params.word980(4) >> 4 & 1 == 1;
        let x = matches!(t, Some(OffsetType::Geometry(0) | OffsetType::Wear(0)));
        let o = &mut self.offsets[no as usize];
        if b[0] == 13 {
            let v = t.map_or(0, |t| o.get(t));
            let v = if x && radius {
                (v as f64 / 2.0).round() as i64
            } else {
                v
            };
            out(b, &[v]);
        } else {
            let v = i64::from(b[6]);
            if let Some(t) = t {
                if !offset_ok(t, v) {
                    return fail(b, 6);
                }
                o.set(t, if x && radius { v * 2 } else { v });
            }
            written(b);
        }
    }

    /// GSK980 functions 15 and 16: read or write a work system's (EXT, G54–G59) values for
    /// the selected axes; a write must bring exactly one value per selected axis.
    fn workpiece_980(&mut self, b: &mut [i32]) {
        let sys = b[3];
        if !(0..=6).contains(&sys) {
            return fail(b, 3);
        }
        let Some(sel) = axis_selection(b[4], AXES, true) else {
            return fail(b, 4);
        };
        let sys = sys as usize;
        if b[0] == 15 {
            out_n(b, sel.len(), |k| self.work[sys][sel.start + k]);
        } else {
            let want = sel.len();
            if b[2] as usize != want || b.len() < 6 + want {
                return fail(b, 2);
            }
            for (k, n) in sel.enumerate() {
                self.work[sys][n] = i64::from(b[6 + k]);
            }
            written(b);
        }
    }

    /// GSK980 functions 17 and 18: read or write one of the GSK980's parameter words, which
    /// have no axis attribute.
    fn param_980(&mut self, b: &mut [i32]) {
        let no = b[3];
        if !(1..=params::GSK980_WORDS as i32).contains(&no) {
            return fail(b, 3);
        }
        if b[4] != 0 {
            return fail(b, 4);
        }
        if b[0] == 17 {
            let v = self.params.word980(no as usize);
            out(b, &[i64::from(v)]);
        } else {
            if b[2] != 1 {
                return fail(b, 2);
            }
            self.params.set_word980(no as usize, b[6]);
            written(b);
        }
    }

    /// GSK980 function 24: the running program's number and the main program's (the MDI
    /// number while MDI runs); end code 6 without a program.
    fn program_numbers_980(&self, b: &mut [i32]) {
        if !self.has_program() {
            return fail(b, 6);
        }
        let main = if self.auto.running_mdi() {
            MDI_NUMBER
        } else {
            self.programs.first().map_or(0, |p| p.number)
        };
        let cur = self.current_program_number();
        out(b, &[i64::from(cur), i64::from(main)]);
    }

    /// GSK980 functions 27, 28, 29, 74 and 75: a position or distance per selected axis, 0 for
    /// a slot past the machine's axes; 29, the skip position, answers end code 5 as the
    /// simulator keeps none.
    fn axis_values_980(&self, b: &mut [i32]) {
        let Some(sel) = axis_selection(b[4], AXES, true) else {
            return fail(b, 4);
        };
        if b[0] == 29 {
            return fail(b, 5);
        }
        let f = b[0];
        let count = self.axis_count();
        out_n(b, sel.len(), |k| {
            let n = sel.start + k;
            if n >= count { 0 } else { self.axis_value(f, n) }
        });
    }

    /// GSK980 function 32: the modal G codes; the groups the simulator does not change answer
    /// a fixed code.
    fn modal_980(&self, b: &mut [i32]) {
        let m = &self.auto.modal;
        out(
            b,
            &[
                i64::from(m.motion),
                if m.css { 96 } else { 97 },
                if m.per_rev { 99 } else { 98 },
                if m.inch { 20 } else { 21 },
                40,
                67,
                54 + i64::from(m.work),
                18,
                15,
                113,
            ],
        );
    }

    /// GSK980 function 76: the status word, mode and run state in the 980's own numbering,
    /// then motion, M/S/T in progress, emergency stop (alarm 0950) and any alarm.
    fn status_980(&self, b: &mut [i32]) {
        let mode = match self.mode {
            Mode::Mdi => 0,
            Mode::Mem => 1,
            Mode::Dnc => 2,
            Mode::Edit => 3,
            Mode::Handle => 4,
            Mode::Jog => 5,
            Mode::Ref => 8,
        };
        let run = match self.auto.state {
            RunState::Idle | RunState::Stop => 1,
            RunState::Hold => 2,
            RunState::Run => 3,
        };
        let moving = self.axes.iter().any(|a| a.mv);
        out(
            b,
            &[
                mode,
                run,
                i64::from(moving),
                i64::from(self.mst_open()),
                i64::from(self.alarm_active(ALARM_ESTOP)),
                i64::from(!self.alarms.is_empty()),
            ],
        );
    }

    /// The clock: year, month, day, hour, minute, second.
    pub(super) fn clock(&self) -> [i64; 6] {
        let elapsed = self.now_ms.saturating_sub(self.clock_set_ms) / 1000;
        civil(self.clock_origin + elapsed as i64)
    }

    /// Position values of axis slot `n` for WINDR code `f` (27/74 absolute, 28/77 machine,
    /// 75 distance to go, 78 following error).
    fn axis_value(&self, f: i32, n: usize) -> i64 {
        match f {
            27 | 74 => self.absolute(n),
            28 | 77 => self.axes[n].m,
            75 => self.remaining(n),
            _ => 0,
        }
    }

    fn param_read_988(&mut self, b: &mut [i32]) {
        let Some(i) = params::index(b[3].clamp(0, 65_535) as u16).filter(|_| b[3] >= 0) else {
            return fail(b, 3);
        };
        let spec = &TABLE[i];
        let Some(sel) = self.param_selection(spec.selector, b[4]) else {
            return fail(b, 4);
        };
        out_n(b, sel.len(), |k| self.params.get(i, sel.start + k));
    }

    fn param_write_988(&mut self, b: &mut [i32]) {
        let Some(i) = params::index(b[3].clamp(0, 65_535) as u16).filter(|_| b[3] >= 0) else {
            return fail(b, 3);
        };
        let spec = TABLE[i];
        let Some(sel) = self.param_selection(spec.selector, b[4]) else {
            return fail(b, 4);
        };
        let slots = sel;
        let len = b[2];
        let per_slot = if len == 1 {
            false
        } else if b[4] == -1 && len as usize == slots.len() && b.len() >= 6 + slots.len() {
            true
        } else {
            return fail(b, 2);
        };
        let value = |k: usize| i64::from(b[6 + if per_slot { k } else { 0 }]);
        let (min, max) = match spec.kind {
            ParamKind::Bit => (0, 255),
            ParamKind::Word => (spec.min, spec.max),
        };
        if (0..slots.len()).any(|k| !(min..=max).contains(&value(k))) {
            return fail(b, 6);
        }
        for (k, slot) in slots.clone().enumerate() {
            self.params.write(i, slot, value(k));
        }
        written(b);
    }

    /// The slots a 988TA parameter attribute selects, or `None` (end code 4).
    fn param_selection(&self, selector: Selector, attr: i32) -> Option<std::ops::Range<usize>> {
        let n = match selector {
            Selector::None => return (attr == 0).then_some(0..1),
            Selector::Axis => self.axis_count(),
            Selector::Spindle => 4,
        };
        match attr {
            -1 => Some(0..n),
            k if k >= 1 && k as usize <= n => Some(k as usize - 1..k as usize),
            _ => None,
        }
    }

    fn macro_value(&self, slot: MacroSlot) -> Option<Option<f64>> {
        Some(match slot {
            MacroSlot::Local | MacroSlot::Missing => return None,
            MacroSlot::Volatile(k) => self.macros.volatile[k],
            MacroSlot::Kept(k) => self.macros.kept[k],
            MacroSlot::Input(k) => Some(f64::from(self.inp.macro_in >> k & 1)),
            MacroSlot::Output(k) => Some(f64::from(self.macros.outputs >> k & 1)),
        })
    }

    fn macro_read(&mut self, b: &mut [i32]) {
        let Some(value) = self.macro_value(MacroSlot::of(i64::from(b[3]))) else {
            return fail(b, 3);
        };
        let e = b[4];
        if !(0..=7).contains(&e) {
            return fail(b, 4);
        }
        let Some(v) = value else {
            return fail(b, 6);
        };
        let a = (v * 10f64.powi(e)).round();
        if !a.is_finite() || a.abs() > f64::from(i32::MAX) {
            return fail(b, 6);
        }
        out(b, &[a as i64, i64::from(e)]);
    }

    fn macro_write(&mut self, b: &mut [i32]) {
        if b[2] != 2 {
            return fail(b, 2);
        }
        let slot = MacroSlot::of(i64::from(b[3]));
        match slot {
            MacroSlot::Local | MacroSlot::Missing => return fail(b, 3),
            MacroSlot::Input(_) => return fail(b, 8),
            _ => {}
        }
        let e = b[7];
        if !(0..=7).contains(&e) {
            return fail(b, 6);
        }
        let v = f64::from(b[6]) / 10f64.powi(e);
        if self.set_macro(slot, Some(v)).is_err() {
            return fail(b, 6);
        }
        written(b);
    }

    /// Sets a macro variable; #1100–#1131 take only 0 or 1 (and never vacant).
    pub(super) fn set_macro(&mut self, slot: MacroSlot, v: Option<f64>) -> Result<(), ()> {
        match slot {
            MacroSlot::Volatile(k) => self.macros.volatile[k] = v,
            MacroSlot::Kept(k) => self.macros.kept[k] = v,
            MacroSlot::Output(k) => match v {
                Some(x) if x == 0.0 || x == 1.0 => {
                    self.macros.outputs =
                        (self.macros.outputs & !(1 << k)) | (u32::from(x == 1.0) << k);
                }
                _ => return Err(()),
            },
            _ => return Err(()),
        }
        Ok(())
    }
}

fn offset_ok(t: OffsetType, v: i64) -> bool {
    match t {
        OffsetType::Tip => (0..=9).contains(&v),
        _ => v.abs() <= OFFSET_MAX,
    }
}

/// The axis slots an attribute selects: 1..=n one axis, −1 all n; `None` otherwise.
fn axis_selection(attr: i32, n: usize, all: bool) -> Option<std::ops::Range<usize>> {
    match attr {
        -1 if all => Some(0..n),
        k if k >= 1 && k as usize <= n => Some(k as usize - 1..k as usize),
        _ => None,
    }
}
