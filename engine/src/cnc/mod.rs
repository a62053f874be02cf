//! The simulated GSK CNC (docs/cnc.md): operation preparation and modes, automatic operation
//! of NC programs with the M/S/T handshakes, motion of up to five axes, the spindle, manual
//! operation, overtravel, alarms, CNC data for WINDR, and PLC axis control (AXCTL).
//!
//! [`SimCnc`] implements the PLC's [`Cnc`] port. Once per tick the PLC calls
//! [`Cnc::exchange`], which runs the steps of one exchange in a fixed order (docs/cnc.md,
//! "Tick and exchange"): sample G and A, alarms and reset, mode, automatic operation, motion,
//! MST acceptance, end of block, and finally the F image. Everything is virtual time and
//! integer or f64 arithmetic with fixed formulas, so a run is reproducible byte for byte.
//!
//! The module is split by responsibility: `signals` (G sampled, F written), `params`,
//! `data` (offsets, macros, clock), `program` (NC text), `word` (a block's words and units),
//! `block` (a block planned into segments), `cycle` (threads and single cycles), `profile`,
//! `rough`, `repeat` and `drill` (the compound and drilling cycles), `path` (the
//! segment queue), `arc` and `motion` (straight and circular moves), `auto`
//! (automatic operation), `mst` (the M/S/T handshake), `manual` (JOG, handwheel, reference
//! return, overtravel), `plc_axes` (AXCTL groups), `windr` (the window functions), `command`
//! (what scripts and the editor do to a running CNC), `keys` (the values they read back) and
//! `error` (why either was refused, in English and Chinese).

pub mod alarm_text;
pub(crate) mod arc;
mod arguments;
mod auto;
mod block;
mod block_check;
pub mod command;
mod corner;
mod cycle;
pub mod data;
mod drill;
pub(crate) mod error;
mod frame;
pub mod fsignals;
mod keys;
pub mod macro_b;
mod manual;
mod modal;
pub(crate) mod motion;
mod mst;
pub(crate) mod params;
mod path;
mod plc_axes;
mod profile;
pub mod program;
pub mod ps;
mod repeat;
mod rough;
pub(crate) mod signals;
mod spindle;
mod status;
pub mod toolpath;
mod windr;
pub(crate) mod word;

use crate::model::tables::MessageTable;
use crate::profile::ProfileId;
use crate::vm::cnc::{AxisStatus, Cnc};
use auto::Auto;
use data::{Macros, TOOL_OFFSETS, ToolOffset};
use fsignals as fs;
use manual::Manual;
use params::{P0071, P1006, P3003, Params};
use plc_axes::Group;
use program::{NcProgram, parse_mdi, parse_programs};
use signals::{FImage, GroupInputs, Inputs};
use spindle::Spindle;

pub use error::{CncError, KEY_FORMS, Quantity, SUBCOMMANDS};
pub use modal::RunState;
pub use params::{ParamError, Selector};
pub use status::{CncStatus, MstStatus};

/// Whether alarm `n` is a PLC alarm (1000–1999): the A area sets and clears it, not reset.
fn is_plc_alarm(n: u16) -> bool {
    (1000..2000).contains(&n)
}

/// The parameter numbers of the simulator's table, in order (docs/cnc.md, "Parameters").
pub fn param_numbers() -> impl Iterator<Item = u16> {
    params::TABLE.iter().map(|s| s.number)
}

/// The selector and the range (least, greatest) of parameter `number`; `None` for a number
/// the table does not have.
pub fn param_rule(number: u16) -> Option<(Selector, i64, i64)> {
    params::spec(number).map(|s| (s.selector, s.min, s.max))
}

/// Axes the simulator can have (#8130 is 2–5).
pub const AXES: usize = 5;

/// Axis names in axis order: 1 = X, 2 = Z, 3 = Y, 4, 5.
pub const AXIS_NAMES: [&str; AXES] = ["X", "Z", "Y", "4", "5"];

/// The E-stop alarm.
pub const ALARM_ESTOP: u16 = 950;
/// Stored stroke limit, + and −.
pub const ALARM_STROKE: [u16; 2] = [500, 501];
/// Hardware overtravel, + and −.
pub const ALARM_HARD_LIMIT: [u16; 2] = [506, 507];

/// The operation mode.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum Mode {
    /// Program editing.
    Edit,
    /// Automatic operation from memory.
    Mem,
    /// Manual data input (the power-on mode: G43 = 0).
    #[default]
    Mdi,
    /// Handwheel.
    Handle,
    /// Jog.
    Jog,
    /// DNC.
    Dnc,
    /// Reference return.
    Ref,
}

impl Mode {
    /// The script and display name.
    pub fn name(self) -> &'static str {
        match self {
            Mode::Edit => "EDIT",
            Mode::Mem => "MEM",
            Mode::Mdi => "MDI",
            Mode::Handle => "HANDLE",
            Mode::Jog => "JOG",
            Mode::Dnc => "DNC",
            Mode::Ref => "REF",
        }
    }

    /// Every mode, for name look-ups.
    pub const ALL: [Mode; 7] = [
        Mode::Edit,
        Mode::Mem,
        Mode::Mdi,
        Mode::Handle,
        Mode::Jog,
        Mode::Dnc,
        Mode::Ref,
    ];

    fn from_code(code: u8) -> Option<Mode> {
        Some(match code {
            3 => Mode::Edit,
            1 => Mode::Mem,
            0 => Mode::Mdi,
            4 => Mode::Handle,
            5 => Mode::Jog,
            33 => Mode::Dnc,
            133 => Mode::Ref,
            _ => return None,
        })
    }
}

/// One axis.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct AxisState {
    /// Machine position, increments (X as a diameter).
    pub m: i64,
    /// Shift SH (machine lock, manual absolute off, reset by a reference return).
    pub sh: i64,
    /// Reference point established.
    pub zrf: bool,
    /// At reference point 1 (ZP).
    pub zp: bool,
    /// At reference points 2–4 (ZP2–ZP4).
    pub zp_n: [bool; 3],
    /// Moved at this exchange.
    pub mv: bool,
    /// The last move was negative.
    pub mvd: bool,
    /// Hardware overtravel alarm stored, + and −.
    pub hard_limit: [bool; 2],
    /// Stored stroke direction blocked, + and −.
    pub stroke: [bool; 2],
}

/// Per-exchange results that F reports.
#[derive(Clone, Copy, Debug, Default)]
struct Flags {
    /// A reset condition held at this exchange: no CNC motion advances.
    halted: bool,
    /// A rapid-type motion advanced.
    rapid: bool,
    /// A cutting feed advanced.
    cut: bool,
    /// A thread was cut.
    thread: bool,
    /// Path speed of program motion, mm/min.
    path_speed: f64,
}

/// The simulated CNC.
#[derive(Clone, Debug)]
pub struct SimCnc {
    profile: ProfileId,
    params: Params,
    offsets: Vec<ToolOffset>,
    work: [[i64; AXES]; 7],
    macros: Macros,
    clock_origin: i64,
    clock_set_ms: u64,
    cutting_ms: u64,
    now_ms: u64,
    exchange_no: u64,
    mst_log: mst::MstLog,
    /// Alarm number per A bit (0: not an alarm).
    plc_alarm_of_bit: Vec<u16>,
    prev_a: Vec<u8>,
    alarms: Vec<u16>,
    pending_alarms: Vec<u16>,
    inp: Inputs,
    prev: Inputs,
    group_in: [GroupInputs; 4],
    mode: Mode,
    reset_key_pending: bool,
    reset_key: bool,
    last_reset: Option<u64>,
    rst: bool,
    axes: [AxisState; AXES],
    auto: Auto,
    /// Shared, so a running macro statement can hold its program while it changes the CNC.
    programs: std::sync::Arc<Vec<NcProgram>>,
    program_text: String,
    mdi: std::sync::Arc<NcProgram>,
    mdi_text: String,
    spindle: Spindle,
    manual: Manual,
    groups: [Group; 4],
    flags: Flags,
    eaxsl: bool,
    toolpath: toolpath::ToolpathCache,
}

/// Seconds from 1970 of the clock's origin, 2026-01-01 00:00:00.
const CLOCK_ORIGIN: i64 = 1_767_225_600;

impl SimCnc {
    /// A CNC of a profile, with the project's display-message table deciding which A bits are
    /// alarms (docs/cnc.md, "Alarms": numbers 1000–1999 are alarms, 2000–9999 operator
    /// messages; a table with no number at all, as an instruction list gives, makes every
    /// A bit k alarm 1000 + k).
    pub fn new(profile: ProfileId, messages: &MessageTable) -> SimCnc {
        let any = messages.rows.iter().any(|m| m.number.is_some());
        let plc_alarm_of_bit = messages
            .rows
            .iter()
            .enumerate()
            .map(|(k, m)| match m.number {
                Some(n) if (1000..2000).contains(&n) => n,
                Some(_) => 0,
                None if !any => 1000 + k as u16,
                None => 0,
            })
            .collect();
        SimCnc {
            profile,
            params: Params::default(),
            offsets: vec![ToolOffset::default(); TOOL_OFFSETS],
            work: [[0; AXES]; 7],
            macros: Macros::default(),
            clock_origin: CLOCK_ORIGIN,
            clock_set_ms: 0,
            cutting_ms: 0,
            now_ms: 0,
            exchange_no: 0,
            mst_log: mst::MstLog::default(),
            plc_alarm_of_bit,
            prev_a: Vec::new(),
            alarms: Vec::with_capacity(16),
            pending_alarms: Vec::new(),
            inp: Inputs::zero(),
            prev: Inputs::zero(),
            group_in: [GroupInputs::default(); 4],
            mode: Mode::Mdi,
            reset_key_pending: false,
            reset_key: false,
            last_reset: None,
            rst: false,
            axes: [AxisState::default(); AXES],
            auto: Auto::default(),
            programs: Default::default(),
            program_text: String::new(),
            mdi: Default::default(),
            mdi_text: String::new(),
            spindle: Spindle::default(),
            manual: Manual::default(),
            groups: Default::default(),
            flags: Flags::default(),
            eaxsl: false,
            toolpath: Default::default(),
        }
    }

    /// The profile.
    pub fn profile(&self) -> ProfileId {
        self.profile
    }

    /// Controlled axes (#8130).
    pub fn axis_count(&self) -> usize {
        self.params.one(params::P8130).clamp(2, AXES as i64) as usize
    }

    /// The spindle speed output S_out (docs/cnc.md, "Spindle").
    pub fn spindle_output(&self) -> u32 {
        self.spindle.s_out
    }

    /// Every axis's state.
    pub fn axes(&self) -> &[AxisState; AXES] {
        &self.axes
    }

    /// The mode.
    pub fn mode(&self) -> Mode {
        self.mode
    }

    /// Active alarms in order of occurrence.
    pub fn alarms(&self) -> &[u16] {
        &self.alarms
    }

    /// The parameters.
    pub fn params(&self) -> &Params {
        &self.params
    }

    /// Whether axis slot `n` is a diameter axis (#1006 bit 3).
    fn diameter(&self, n: usize) -> bool {
        self.params.bit(P1006, n, 3)
    }

    fn diameters(&self) -> [bool; AXES] {
        std::array::from_fn(|n| self.diameter(n))
    }

    /// Whether an interlock check of #3003 is enabled.
    fn check(&self, bit: u32) -> bool {
        self.params.bit(P3003, 0, bit)
    }

    /// The message of a macro alarm (3000–3200, raised by `#3000 = n (MESSAGE)`) while it is
    /// active.
    pub fn macro_alarm_message(&self, n: u16) -> Option<&str> {
        match &self.macros.message {
            Some((k, m)) if *k == n && self.alarms.contains(&n) => Some(m),
            _ => None,
        }
    }

    /// Whether alarm `n` is active.
    pub fn alarm_active(&self, n: u16) -> bool {
        self.alarms.contains(&n)
    }

    fn servo_alarm(&self) -> bool {
        self.alarms.iter().any(|a| (401..=499).contains(a))
    }

    /// Raises an alarm; a new one in RUN or HOLD stops automatic operation.
    fn raise(&mut self, n: u16) {
        if self.alarms.contains(&n) {
            return;
        }
        self.alarms.push(n);
        self.auto_alarm_stop();
    }

    fn clear_alarm(&mut self, n: u16) {
        self.alarms.retain(|a| *a != n);
    }

    /// The absolute position of axis slot `n`: M − TO − WO − SH.
    pub fn absolute(&self, n: usize) -> i64 {
        let a = &self.axes[n];
        a.m - self.tool_offset_along(n) - self.work_offset(n) - a.sh
    }

    fn tool_offset_along(&self, n: usize) -> i64 {
        match self.auto.tool_offset {
            0 => 0,
            k => self.offsets[usize::from(k)].along(n),
        }
    }

    fn work_offset(&self, n: usize) -> i64 {
        self.work_offset_of(n, self.auto.modal.work) + self.auto.shift[n]
    }

    /// EXT plus the offset of workpiece system G54 + `work` on axis slot `n`.
    fn work_offset_of(&self, n: usize, work: u8) -> i64 {
        self.work[0][n] + self.work[1 + usize::from(work)][n]
    }

    /// The virtual time of the last exchange, ms.
    pub fn now_ms(&self) -> u64 {
        self.now_ms
    }

    /// Replaces every memory program and rewinds.
    fn load_programs(&mut self, text: &str) {
        self.toolpath = Default::default();
        self.programs = std::sync::Arc::new(parse_programs(text));
        self.program_text = text.to_string();
        self.auto.rewind_all();
    }

    fn load_mdi(&mut self, text: &str) {
        self.mdi = std::sync::Arc::new(parse_mdi(text));
        self.mdi_text = text.to_string();
        self.auto.rewind_all();
    }

    /// The memory programs' text.
    pub fn program_text(&self) -> &str {
        &self.program_text
    }

    /// The MDI buffer's text.
    pub fn mdi_text(&self) -> &str {
        &self.mdi_text
    }

    /// Power off and on (docs/cnc.md, "power-cycle").
    pub fn power_cycle(&mut self) {
        self.params.power_cycle();
        self.mst_log = mst::MstLog::default();
        self.alarms.clear();
        self.pending_alarms.clear();
        self.auto = Auto::default();
        self.auto.modal.per_rev = self.fpm_per_rev();
        self.manual = Manual::default();
        self.groups = Default::default();
        self.spindle = Spindle::default();
        for a in &mut self.axes {
            *a = AxisState {
                m: a.m,
                ..AxisState::default()
            };
        }
        self.macros.volatile = [None; 100];
        self.macros.outputs = 0;
        self.macros.timer_base = 0.0;
        self.macros.timer_at = self.now_ms;
        self.inp = Inputs::zero();
        self.prev = Inputs::zero();
        self.group_in = [GroupInputs::default(); 4];
        self.mode = Mode::Mdi;
        self.reset_key_pending = false;
        self.reset_key = false;
        self.last_reset = None;
        self.rst = false;
        self.eaxsl = false;
        self.prev_a.clear();
        self.flags = Flags::default();
    }

    /// The feed mode of power-on and reset: #3402 bit 4 FPM = 1 G98, 0 G99.
    fn fpm_per_rev(&self) -> bool {
        !self.params.bit(params::P3402, 0, 4)
    }

    /// Alarm sources and reset: step (b) of an exchange.
    fn alarms_and_reset(&mut self, a: &[u8]) {
        let inp = self.inp;
        if inp.estop {
            self.raise(ALARM_ESTOP);
        } else {
            self.clear_alarm(ALARM_ESTOP);
        }
        let pending = std::mem::take(&mut self.pending_alarms);
        for n in &pending {
            self.raise(*n);
        }
        self.pending_alarms = pending;
        self.pending_alarms.clear();
        if self.check(5) {
            for n in 0..self.axis_count() {
                for (d, bits) in [inp.limit_plus, inp.limit_minus].into_iter().enumerate() {
                    if bits >> n & 1 == 1 {
                        self.axes[n].hard_limit[d] = true;
                        self.raise(ALARM_HARD_LIMIT[d]);
                    }
                }
            }
        }
        self.plc_alarms(a);
        let c = inp.estop || inp.ers || self.reset_key;
        if c {
            self.reset();
            self.last_reset = Some(self.exchange_no);
        }
        let e = (self.params.one(P0071) as u64).div_ceil(8);
        self.rst = self.last_reset.is_some_and(|k| self.exchange_no - k <= e);
        if inp.estop || self.servo_alarm() {
            for a in &mut self.axes {
                a.zp = false;
                a.zp_n = [false; 3];
            }
        }
        self.claims();
    }

    fn plc_alarms(&mut self, a: &[u8]) {
        if self.prev_a.as_slice() == a {
            return;
        }
        for k in 0..self.plc_alarm_of_bit.len() {
            let n = self.plc_alarm_of_bit[k];
            if n == 0 {
                continue;
            }
            let on = a.get(k / 8).is_some_and(|b| b >> (k % 8) & 1 == 1);
            if on {
                self.raise(n);
            } else {
                self.clear_alarm(n);
            }
        }
        self.prev_a.clear();
        self.prev_a.extend_from_slice(a);
    }

    /// A reset condition (docs/cnc.md, "Reset").
    fn reset(&mut self) {
        self.auto.reset();
        self.auto.modal.per_rev = self.fpm_per_rev();
        self.manual.stop_all();
        self.flags.halted = true;
        self.alarms
            .retain(|&n| is_plc_alarm(n) || n == ALARM_ESTOP || ALARM_HARD_LIMIT.contains(&n));
        self.macros.stop_message = None;
        if !self.params.bit(params::P6001, 0, 6) {
            // #6001 bit 6 CCV = 0: reset clears the common variables #100–#199.
            self.macros.volatile = [None; 100];
        }
        let inp = self.inp;
        for (n, a) in self.axes.iter_mut().enumerate() {
            if inp.limit_plus >> n & 1 == 0 {
                a.hard_limit[0] = false;
            }
            if inp.limit_minus >> n & 1 == 0 {
                a.hard_limit[1] = false;
            }
        }
        for (d, alarm) in ALARM_HARD_LIMIT.into_iter().enumerate() {
            if !self.axes.iter().any(|a| a.hard_limit[d]) {
                self.clear_alarm(alarm);
            }
        }
    }

    /// The mode: step (c).
    fn update_mode(&mut self) {
        let Some(new) = Mode::from_code(self.inp.mode_code) else {
            return;
        };
        if new == self.mode {
            return;
        }
        self.auto.mode_change(new);
        self.manual.stop_all();
        self.mode = new;
    }

    fn bookkeeping(&mut self) {
        let p = &self.params;
        for (n, a) in self.axes.iter_mut().enumerate() {
            if a.zp && a.m != p.get(params::P1240, n) {
                a.zp = false;
            }
            for k in 0..3 {
                if a.zp_n[k] && a.m != p.get(params::P1240 + 1 + k, n) {
                    a.zp_n[k] = false;
                }
            }
        }
        if self.flags.cut {
            self.cutting_ms += 8;
        }
        if self.auto.state == RunState::Run {
            self.macros.run_ms += 8;
        }
    }

    /// Writes the F image (step (h)).
    fn write_f(&self, f: &mut [u8]) {
        let mut img = FImage::new();
        self.auto_f(&mut img);
        let inp = &self.inp;
        let cnc_alarm = self.alarms.iter().any(|&n| !is_plc_alarm(n));
        img.set(fs::SA, !inp.estop && !self.servo_alarm());
        img.set(fs::AL, !self.alarms.is_empty());
        img.set(fs::RST, self.rst);
        img.set(fs::MA, !cnc_alarm);
        img.set(fs::ENB, self.spindle.s_out != 0);
        img.set(fs::INCH, self.auto.modal.inch);
        img.set(fs::RPDO, self.flags.rapid);
        img.set(fs::CSS, self.auto.modal.css);
        img.set(fs::THRD, self.flags.thread);
        img.set(fs::CUT, self.flags.cut);
        img.set(fs::MDRN, inp.drn);
        let mode = match self.mode {
            Mode::Edit => fs::MEDT,
            Mode::Mem => fs::MMEM,
            Mode::Mdi => fs::MMDI,
            Mode::Handle => fs::MH,
            Mode::Jog => fs::MJ,
            Mode::Dnc => fs::MRMT,
            Mode::Ref => fs::MREF,
        };
        img.set(mode, true);
        img.set(fs::MBDT1, inp.bdt1);
        img.set(fs::MMLK, inp.mlk);
        img.set(fs::MABSM, !inp.absm);
        img.set(fs::MSBK, inp.sbk);
        img.set(fs::MAFL, inp.afl);
        img.set(
            fs::OTA,
            self.alarm_active(ALARM_STROKE[0]) || self.alarm_active(ALARM_STROKE[1]),
        );
        img.set(fs::MDIRST, self.reset_key);
        // Spindle.
        let sp = &self.spindle;
        let s12 = if inp.sind {
            u32::from(inp.ri)
        } else if sp.g_max > 0 {
            (4095.0 * f64::from(sp.s_out) / f64::from(sp.g_max)).round() as u32
        } else {
            0
        };
        img.put(fs::S12, s12.min(4095));
        img.put(fs::AR, sp.s_out.min(65_535));
        let p = &self.params;
        let (made, wanted) = (p.one(params::P6711), p.one(params::P6713));
        img.set(fs::PRTSF, wanted > 0 && made >= wanted);
        // Axes.
        let ots = p.bit(params::P1301, 0, 6);
        for (n, a) in self.axes.iter().enumerate() {
            img.axis(fs::ZP, n, a.zp);
            img.axis(fs::ZP2, n, a.zp_n[0]);
            img.axis(fs::ZP3, n, a.zp_n[1]);
            img.axis(fs::ZP4, n, a.zp_n[2]);
            img.axis(fs::MV, n, a.mv);
            img.axis(fs::MVD, n, a.mvd);
            img.axis(fs::ZRF, n, a.zrf);
            img.axis(fs::OTP, n, ots && a.stroke[0]);
            img.axis(fs::OTN, n, ots && a.stroke[1]);
        }
        self.plc_axes_f(&mut img);
        img.put(fs::MACRO_OUT, self.macros.outputs);
        img.store(f);
    }

    /// A snapshot of what a CNC screen shows.
    pub fn status(&self) -> CncStatus {
        let count = self.axis_count();
        CncStatus {
            mode: self.mode,
            run: self.auto.state,
            block: self.auto.last_n,
            program: self.current_program_number(),
            line: self.auto.current_line(&self.programs, &self.mdi),
            mdi: self.auto.running_mdi(),
            line_in_mdi: self.auto.at_mdi(),
            axes: count,
            machine: std::array::from_fn(|n| self.axes[n].m),
            absolute: std::array::from_fn(|n| self.absolute(n)),
            spindle: self.spindle.s_out,
            alarms: self.alarms.clone(),
            mst: self.mst_status(),
            toolpath: (!self.programs.is_empty()).then(|| self.toolpath.get(|| self.toolpath())),
            macro_message: self
                .macros
                .message
                .clone()
                .filter(|(n, _)| self.alarms.contains(n)),
            macros: Some(std::sync::Arc::new(self.macro_table())),
            stop_message: self.macros.stop_message.clone(),
        }
    }
}

impl Cnc for SimCnc {
    fn window_is_low_speed(&self, function: i32) -> bool {
        match self.profile {
            ProfileId::Gsk988ta => matches!(function, 14 | 18 | 22),
            ProfileId::Gsk980 => matches!(function, 14 | 16 | 18 | 22),
        }
    }

    fn window(&mut self, block: &mut [i32]) {
        self.windr(block);
    }

    fn machine_position(&self, axis: u32) -> Option<i64> {
        let n = axis as usize;
        (1..=self.axis_count())
            .contains(&n)
            .then(|| self.axes[n - 1].m)
    }

    fn axis_status(&self, group: u8, ebuf: bool) -> AxisStatus {
        self.plc_axis_status(group, ebuf)
    }

    fn exchange(&mut self, now_ms: u64, g: &[u8], a: &[u8], f: &mut [u8]) {
        self.now_ms = now_ms;
        self.exchange_no += 1;
        // (a) sample.
        self.prev = self.inp;
        self.inp = Inputs::read(g);
        for (k, gi) in self.group_in.iter_mut().enumerate() {
            *gi = GroupInputs::read(g, k);
        }
        self.reset_key = std::mem::take(&mut self.reset_key_pending);
        self.flags = Flags::default();
        for a in &mut self.axes {
            a.mv = false;
        }
        // (b)–(c).
        self.alarms_and_reset(a);
        self.update_mode();
        // (d).
        self.automatic();
        self.update_spindle();
        // (e).
        self.advance_program();
        self.advance_manual();
        self.advance_plc_axes();
        // (f)–(g).
        self.mst_acceptance();
        self.end_of_block();
        self.bookkeeping();
        // (h).
        self.write_f(f);
        self.note_strobes();
    }
}
