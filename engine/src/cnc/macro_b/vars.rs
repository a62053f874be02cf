//! Every macro variable the CNC has, read and written (docs/gcode.md, "Macros", table of
//! variables): locals, commons, the PLC interface, offsets, timers, modal information and
//! positions. Lengths are in the program's unit (mm, or inch under G20), X as a diameter.

use super::expr::{Value, Vars};
use super::{ALARM_BASE, ALARM_MAX};
use crate::cnc::data::{OffsetType, TOOL_OFFSETS};
use crate::cnc::params::{P6004, P6711, P6713};
use crate::cnc::ps;
use crate::cnc::{AXES, SimCnc};

/// Local variables #1–#33 of one call level.
pub type Locals = [Value; LOCALS];

/// How many local variables a level has.
pub const LOCALS: usize = 33;

/// The largest offset or position a macro may write, in increments.
const LENGTH_MAX: f64 = 99_999_999.0;

/// The macro variables an operator sees on the CNC page.
#[derive(Clone, Debug, PartialEq)]
pub struct MacroTable {
    /// The call level of the locals (0: the main program).
    pub level: usize,
    /// #1–#33 of that level.
    pub locals: Locals,
    /// #100–#199.
    pub commons: [Value; 100],
    /// #500–#999.
    pub kept: Vec<Value>,
}

/// What a variable number names, when it is not a plain storage slot.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum System {
    /// A tool offset: number 1–64 and type.
    Offset(usize, OffsetType),
    /// A workpiece offset: system (0 EXT, 1 G54 … 6 G59) and axis slot.
    Work(usize, usize),
    /// #5001+ block end, #5021+ machine, #5041+ absolute, #5061+ skip position (where the
    /// tool is: there is no skip signal), #5081+ tool offset in use, #5101+ servo deviation
    /// (0) of an axis slot.
    Position(u8, usize),
}

fn system(n: i64) -> Option<System> {
    let offset = |base: i64, t: OffsetType| {
        let k = n - base;
        ((1..=64).contains(&k) && (k as usize) < TOOL_OFFSETS)
            .then_some(System::Offset(k as usize, t))
    };
    match n {
        2001..=2064 => offset(2000, OffsetType::Wear(0)),
        2101..=2164 => offset(2100, OffsetType::Wear(1)),
        2201..=2264 => offset(2200, OffsetType::Wear(2)),
        2301..=2364 => offset(2300, OffsetType::Tip),
        2701..=2764 => offset(2700, OffsetType::Geometry(0)),
        2801..=2864 => offset(2800, OffsetType::Geometry(1)),
        2901..=2964 => offset(2900, OffsetType::Geometry(2)),
        2500..=2506 => Some(System::Work((n - 2500) as usize, 0)),
        2600..=2606 => Some(System::Work((n - 2600) as usize, 1)),
        5001..=5005 => Some(System::Position(0, (n - 5001) as usize)),
        5021..=5025 => Some(System::Position(1, (n - 5021) as usize)),
        5041..=5045 => Some(System::Position(2, (n - 5041) as usize)),
        5061..=5065 => Some(System::Position(2, (n - 5061) as usize)),
        5081..=5085 => Some(System::Position(3, (n - 5081) as usize)),
        5101..=5105 => Some(System::Position(4, (n - 5101) as usize)),
        5201..=5340 => {
            let (k, slot) = ((n - 5201) / 20, ((n - 5201) % 20) as usize);
            (k <= 6 && slot < AXES).then_some(System::Work(k as usize, slot))
        }
        _ => None,
    }
}

/// Whether the CNC has variable `n` (docs/gcode.md, "Macros", table of variables).
pub fn exists(n: i64) -> bool {
    matches!(
        n,
        1..=33
            | 100..=199
            | 500..=999
            | 1000..=1032
            | 1100..=1133
            | 3000..=3004
            | 3006
            | 3011
            | 3012
            | 3901
            | 3902
            | 4001..=4130
    ) || system(n).is_some()
}

fn bit(word: u32, k: i64) -> Value {
    Some(f64::from(word >> k & 1))
}

impl Vars for SimCnc {
    fn nat(&self) -> bool {
        self.params.bit(P6004, 0, 0)
    }

    fn read(&self, n: i64) -> Result<Value, u16> {
        let m = &self.macros;
        Ok(match n {
            0 => None,
            1..=33 => self.auto.locals.last().and_then(|l| l[(n - 1) as usize]),
            100..=199 => m.volatile[(n - 100) as usize],
            500..=999 => m.kept[(n - 500) as usize],
            1000..=1031 => bit(self.inp.macro_in, n - 1000),
            1032 => Some(f64::from(self.inp.macro_in as i32)),
            1100..=1131 => bit(m.outputs, n - 1100),
            1132 => Some(f64::from(m.outputs as i32)),
            1133 => Some(f64::from(m.outputs & 0xFF)),
            3000 | 3006 => None,
            3001 => Some(m.timer_base + self.now_ms.saturating_sub(m.timer_at) as f64),
            3002 => Some(m.hours_base + m.run_ms as f64 / 3_600_000.0),
            3003 => Some(f64::from(self.auto.m3003)),
            3004 => Some(f64::from(self.auto.m3004)),
            3901 => Some(self.params.one(P6711) as f64),
            3902 => Some(self.params.one(P6713) as f64),
            3011 | 3012 => {
                let [y, mo, d, h, mi, s] = self.clock();
                let v = if n == 3011 {
                    y * 10_000 + mo * 100 + d
                } else {
                    h * 10_000 + mi * 100 + s
                };
                Some(v as f64)
            }
            4001..=4130 => self.modal_info(n),
            _ => return self.read_system(n),
        })
    }
}

impl SimCnc {
    /// Increments per program unit: 1000 per mm, 25 400 per inch.
    fn per_unit(&self) -> f64 {
        if self.auto.modal.inch {
            25_400.0
        } else {
            1_000.0
        }
    }

    fn read_system(&self, n: i64) -> Result<Value, u16> {
        let per = self.per_unit();
        let len = |v: i64| Some(v as f64 / per);
        Ok(match system(n).ok_or(ps::VARIABLE)? {
            System::Offset(k, OffsetType::Tip) => Some(self.offsets[k].tip as f64),
            System::Offset(k, t) => len(self.offsets[k].get(t)),
            System::Work(sys, slot) => len(self.work[sys][slot]),
            System::Position(kind, slot) => {
                if slot >= self.axis_count() {
                    return Ok(Some(0.0));
                }
                len(match kind {
                    0 => self.block_end(slot),
                    1 => self.axes[slot].m,
                    2 => self.absolute(slot),
                    3 => self.tool_offset_along(slot),
                    _ => 0,
                })
            }
        })
    }

    /// Where the block read last ends on axis slot `n`, in workpiece coordinates.
    fn block_end(&self, n: usize) -> i64 {
        match (self.auto.exec.is_some(), self.auto.segs.last()) {
            (true, Some(s)) => s.target[n] - self.origin(n, &self.auto.modal),
            _ => self.absolute(n),
        }
    }

    /// #4001–#4130: the modal G codes by group and the last B…T words.
    fn modal_info(&self, n: i64) -> Value {
        let a = &self.auto;
        let m = &a.modal;
        let g = |v: u32| Some(f64::from(v));
        match n {
            4001 => g(u32::from(m.motion)),
            4002 => g(if m.css { 96 } else { 97 }),
            4005 => g(if m.per_rev { 99 } else { 98 }),
            4006 => g(if m.inch { 20 } else { 21 }),
            4007 => g(40),
            4009 => g(match m.drill.g {
                0 => 80,
                d => u32::from(d),
            }),
            4012 => g(if a.g66.is_some() { 66 } else { 67 }),
            4014 => g(54 + u32::from(m.work)),
            4015 => g(64),
            4016 => g(18),
            4109 => Some(m.feed / if m.inch { 25.4 } else { 1.0 }),
            4113 => a.last_m.map(f64::from),
            4114 => g(a.read_n),
            4115 => g(self.current_program_number()),
            4119 => a.last_s.map(f64::from),
            4120 => a.last_t.map(f64::from),
            _ => None,
        }
    }

    /// Sets local #`n` (1–33) of the current call level, as an operator does on the CNC page.
    pub(in crate::cnc) fn set_local(&mut self, n: usize, v: Value) {
        if self.auto.locals.is_empty() {
            self.auto.locals.push([None; LOCALS]);
        }
        if let Some(slot) = self.auto.locals.last_mut().and_then(|l| l.get_mut(n - 1)) {
            *slot = v;
        }
    }

    /// The locals of the current call level, the commons #100–#199 and #500–#999, for the
    /// CNC page's table.
    pub fn macro_table(&self) -> MacroTable {
        MacroTable {
            level: self.auto.locals.len().saturating_sub(1),
            locals: self.auto.locals.last().copied().unwrap_or([None; LOCALS]),
            commons: self.macros.volatile,
            kept: self.macros.kept.clone(),
        }
    }

    /// Writes variable `n`; a write #3000 = k gives alarm 3000 + k with `message` as its
    /// error.
    pub(super) fn write_var(&mut self, n: i64, v: Value, message: Option<&str>) -> Result<(), u16> {
        self.auto.macro_writes = self.auto.macro_writes.wrapping_add(1);
        let m = &mut self.macros;
        match n {
            1..=33 => {
                if self.auto.locals.is_empty() {
                    self.auto.locals.push([None; LOCALS]);
                }
                let l = self.auto.locals.last_mut().expect("one level");
                l[(n - 1) as usize] = v;
            }
            100..=199 => m.volatile[(n - 100) as usize] = v,
            500..=999 => m.kept[(n - 500) as usize] = v,
            1100..=1131 => {
                let k = n - 1100;
                let on = match v {
                    None => false,
                    Some(x) if x == 0.0 || x == 1.0 => x == 1.0,
                    Some(_) => return Err(ps::ARGUMENT),
                };
                m.outputs = (m.outputs & !(1 << k)) | (u32::from(on) << k);
            }
            1132 => {
                let x = v.unwrap_or(0.0).round();
                if !(f64::from(i32::MIN)..=f64::from(i32::MAX)).contains(&x) {
                    return Err(ps::ARGUMENT);
                }
                m.outputs = x as i32 as u32;
            }
            1133 => {
                let x = v.unwrap_or(0.0).round();
                if !(0.0..=255.0).contains(&x) {
                    return Err(ps::ARGUMENT);
                }
                m.outputs = (m.outputs & !0xFF) | x as u32;
            }
            3000 => {
                let k = v.unwrap_or(0.0).round();
                if !(0.0..=f64::from(ALARM_MAX)).contains(&k) {
                    return Err(ps::ARGUMENT);
                }
                let number = ALARM_BASE + k as u16;
                m.message = Some((number, message.unwrap_or("").to_string()));
                return Err(number);
            }
            3006 => {
                // Stop with a message: the statement's runner stops after it.
                m.stop_message = Some(message.unwrap_or("").to_string());
            }
            3901 | 3902 => {
                let x = v.unwrap_or(0.0).round();
                if !(0.0..=99_999_999.0).contains(&x) {
                    return Err(ps::ARGUMENT);
                }
                let p = if n == 3901 { P6711 } else { P6713 };
                self.params.set(p, 0, x as i64);
            }
            3001 => {
                m.timer_base = v.unwrap_or(0.0);
                m.timer_at = self.now_ms;
            }
            3002 => {
                m.hours_base = v.unwrap_or(0.0);
                m.run_ms = 0;
            }
            3003 | 3004 => {
                let x = v.unwrap_or(0.0).round();
                if !(0.0..=7.0).contains(&x) {
                    return Err(ps::ARGUMENT);
                }
                if n == 3003 {
                    self.auto.m3003 = x as u8;
                } else {
                    self.auto.m3004 = x as u8;
                }
            }
            0 | 1000..=1032 | 3011 | 3012 | 4001..=4130 | 5001..=5199 => {
                return Err(ps::PROTECTED);
            }
            _ => return self.write_system(n, v),
        }
        Ok(())
    }

    fn write_system(&mut self, n: i64, v: Value) -> Result<(), u16> {
        let s = system(n).ok_or(ps::VARIABLE)?;
        let x = v.unwrap_or(0.0);
        let incr = (x * self.per_unit()).round();
        if incr.abs() > LENGTH_MAX {
            return Err(ps::ARGUMENT);
        }
        match s {
            System::Offset(k, OffsetType::Tip) => {
                if !(0.0..=9.0).contains(&x) || x.fract() != 0.0 {
                    return Err(ps::ARGUMENT);
                }
                self.offsets[k].tip = x as i64;
            }
            System::Offset(k, t) => self.offsets[k].set(t, incr as i64),
            System::Work(sys, slot) => self.work[sys][slot] = incr as i64,
            System::Position(..) => return Err(ps::PROTECTED),
        }
        Ok(())
    }
}
