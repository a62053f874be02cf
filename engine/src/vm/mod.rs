//! The scan engine: runs a compiled program the way the GSK PLC does (docs/plc.md).
//!
//! `code` lowers the compiled program once to compact words with addresses resolved;
//! `exec` runs them (no allocation, hashing or string work in the loop); `functions`
//! holds the function instructions' semantics; `memory` the image and its width rules;
//! [`cnc`] the interface to the CNC.
//!
//! Those internals are private to the engine. The rest of the workspace runs a PLC through
//! [`Vm`] (build, tick, read, write, force, watch), chooses its [`Engine`], plugs a CNC in
//! through [`cnc::Cnc`] and reads what a scan showed through [`monitor`]. The lowered program
//! ([`Executable`]) and the image's [`Layout`] are handed out whole, for monitors that read
//! a machine on another thread; their encoding stays inside.

pub mod cnc;
pub(crate) mod code;
#[cfg(test)]
mod differential_tests;
pub use code::{CodeError, Executable, LowerError, NetworkInfo};
mod exec;
pub(crate) use exec::decides;
mod functions;
pub mod native;
pub use native::Engine;
pub(crate) mod memory;
pub use memory::{Layout, Loc};
pub mod monitor;
pub(crate) mod swap;
pub use swap::{SwapError, Swapped};
mod why;
pub use why::deciding_contacts;

use crate::address::{Address, Area};
use crate::compiler::{Program, compile};
use crate::model::Project;
use crate::profile::Profile;
use cnc::Cnc;
use code::lower;

/// Bytes of the memory image: a fixed power of two, so the hot loop's masked byte index needs
/// no bounds check. Every profile's layout fits (the GSK988TA uses about 10.6 KiB).
pub const IMAGE_BYTES: usize = 16 * 1024;

/// Virtual milliseconds per tick.
pub const TICK_MS: u64 = 8;
/// Executed steps after which a level is stopped (per tick for level 1, per cycle for level 2).
pub const WATCHDOG_STEPS: u64 = 200_000;

/// Per-instance memory of an instruction: edges, timers, window phases. Laid out as in C,
/// since the native engine's timers read and write it (`vm/native/timer.rs`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
#[repr(C)]
pub(crate) struct InstState {
    /// ACT at the previous execution.
    pub prev_act: bool,
    /// Virtual time of the previous execution.
    pub last_ms: u64,
    /// Instruction-specific phase (WINDR low-speed, AXCTL command in progress).
    pub phase: u8,
}

/// Why the PLC stopped, and where: data only, worded by `ladder_text::halt`.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Halt {
    /// Block label where it happened.
    pub block: String,
    /// Network (1-based).
    pub network: usize,
    /// What happened.
    pub reason: HaltReason,
}

/// What stopped the PLC.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum HaltReason {
    /// A JMPB loop ran past the watchdog's steps in one scan of level 1 (`level` 1) or one
    /// cycle of level 2 (`level` 2); the PLC stays stopped until a power cycle.
    Watchdog {
        /// The program level, 1 or 2.
        level: u8,
        /// The steps the watchdog allows.
        steps: u64,
    },
}

/// Level 2's progress through its cycle.
#[derive(Clone, Copy, Debug, Default)]
struct Level2 {
    /// Where the next slice resumes; `None` at the start of a cycle.
    resume: Option<u32>,
    /// Steps executed in this cycle so far.
    cycle_steps: u64,
    /// Division n in force for this cycle.
    division: u32,
}

/// A saved caller: where to return and its logic state.
#[derive(Clone, Copy, Debug, Default)]
struct Frame {
    ret: u32,
    acc: u32,
    blocks: u64,
    branches: u64,
}

/// A running PLC.
pub struct Vm {
    code: Executable,
    layout: Layout,
    mem: Vec<u8>,
    states: Vec<InstState>,
    frames: Vec<Frame>,
    /// Scratch for WINDR blocks (sized once).
    window: Vec<i32>,
    /// Per instance state: the block a low-speed WINDR latched at its first scan (allocated
    /// once for each WINDR; empty for other instructions).
    latches: Vec<Vec<i32>>,
    force_mask: Vec<u8>,
    force_value: Vec<u8>,
    forced_bytes: Vec<u32>,
    ticks: u64,
    executed: u64,
    /// Steps the last tick executed, and the most any tick has since power-on.
    tick_steps: (u64, u64),
    division: u32,
    level2: Level2,
    halt: Option<Halt>,
    watched: Vec<bool>,
    watch_count: usize,
    /// How many of the watched networks are in subprograms (the level then runs interpreted).
    watched_in_subs: usize,
    /// While the interpreter runs watched networks for the native engine: stop at the first
    /// unwatched network of the level itself.
    handing_back: bool,
    /// Per word of code: the value a contact read or the power an output received, for
    /// watched networks (0/1), written only while tracing.
    trace: Vec<u8>,
    /// Whether coverage is being measured: the trace's seen bits since it was turned on.
    covering: bool,
    /// The engine chosen for the scan.
    engine: Engine,
    /// The program's machine code, when generated (see [`native`]).
    native: Option<native::Native>,
    profile: &'static Profile,
}

/// Why a [`Vm`] could not be built.
pub type BuildError = LowerError;

impl Vm {
    /// Compiles a project and builds a PLC running it.
    pub fn new(project: &Project) -> Result<Vm, BuildError> {
        let compiled = compile(project);
        if compiled.errors() > 0 {
            return Err(LowerError::CompileErrors(compiled.errors()));
        }
        let mut vm = Vm::from_program(&compiled.program, project.profile())?;
        vm.division = project.level2_division.max(1);
        vm.load_data_tables(project);
        Ok(vm)
    }

    /// Builds a PLC running an already compiled, error-free program.
    pub fn from_program(program: &Program, profile: &'static Profile) -> Result<Vm, BuildError> {
        let layout = Layout::new(profile);
        assert!(
            layout.size as usize <= IMAGE_BYTES,
            "the {} memory image does not fit {IMAGE_BYTES} bytes",
            profile.name
        );
        let code = lower(program, &layout)?;
        let size = IMAGE_BYTES;
        let d = layout.area_range(Area::D);
        let mut latches = vec![Vec::new(); code.states as usize];
        for f in &code.fns {
            if f.op == crate::catalog::FnOp::Windr {
                latches[f.state as usize] = vec![0; d.len() / 4];
            }
        }
        let engine = Engine::default_for_build();
        let native = match engine {
            Engine::Interpreter => None,
            Engine::Native | Engine::Checked => native::Native::new(&code),
        };
        Ok(Vm {
            engine,
            native,
            latches,
            states: vec![InstState::default(); code.states as usize],
            frames: Vec::with_capacity(program.blocks.len() + 1),
            window: vec![0; d.len() / 4],
            watched: vec![false; code.networks.len()],
            trace: vec![0; code.words().len()],
            covering: false,
            watch_count: 0,
            watched_in_subs: 0,
            handing_back: false,
            mem: vec![0; size],
            force_mask: vec![0; size],
            force_value: vec![0; size],
            forced_bytes: Vec::new(),
            ticks: 0,
            executed: 0,
            tick_steps: (0, 0),
            division: 1,
            level2: Level2::default(),
            halt: None,
            code,
            layout,
            profile,
        })
    }

    /// Power-on values of the retained areas from the project's data-setting tables: the K
    /// page, D, DT and DC rows, and reals from D_FLOAT.
    pub fn load_data_tables(&mut self, project: &Project) {
        let profile = self.profile;
        let k = self.layout.area_range(Area::K);
        for (i, byte) in project.data.k.iter().enumerate().take(k.len()) {
            self.mem[k.start + i] = *byte;
        }
        let data = &project.data;
        for row in data.d.iter().chain(&data.dt).chain(&data.dc) {
            if row.address.check_range(profile).is_ok() && row.address.bit.is_none() {
                let loc = self.layout.loc(row.address, false);
                memory::write(&mut self.mem, loc, 4, row.value as i32);
            }
        }
        for row in &data.d_float {
            if row.address.area == Area::D && row.address.check_range(profile).is_ok() {
                let loc = self.layout.loc(row.address, false);
                memory::write_real(&mut self.mem, loc, row.value);
            }
        }
        self.apply_forces();
    }

    /// The executable code.
    pub fn code(&self) -> &Executable {
        &self.code
    }

    /// Ticks run since start.
    pub fn ticks(&self) -> u64 {
        self.ticks
    }

    /// Steps executed since start (jumped-over instructions not counted, called ones counted).
    pub fn executed_steps(&self) -> u64 {
        self.executed
    }

    /// The scan time in steps: the last tick's and the most of any tick since power-on (the
    /// watchdog stops a level at [`WATCHDOG_STEPS`]).
    pub fn tick_steps(&self) -> (u64, u64) {
        self.tick_steps
    }

    /// Virtual time in ms.
    pub fn now_ms(&self) -> u64 {
        self.ticks * TICK_MS
    }

    /// Why the PLC is stopped, if it is.
    pub fn halt(&self) -> Option<&Halt> {
        self.halt.as_ref()
    }

    /// Sets the level-2 division count; it takes effect at the next level-2 cycle.
    pub fn set_division(&mut self, n: u32) {
        self.division = n.max(1);
    }

    /// Power off and on: R, A, Y, G and every edge and timer memory are cleared; K, D, T, C,
    /// DT and DC keep their values; level 2 starts a new cycle; a halted PLC runs again.
    /// Forces stay.
    pub fn power_cycle(&mut self) {
        self.tick_steps = (0, 0);
        for area in [Area::R, Area::A, Area::Y, Area::G] {
            let r = self.layout.area_range(area);
            self.mem[r].fill(0);
        }
        self.states
            .iter_mut()
            .for_each(|s| *s = InstState::default());
        self.level2 = Level2::default();
        self.halt = None;
        self.apply_forces();
    }

    /// Runs one 8 ms tick: level 1 whole, then the next slice of level 2, then the exchange
    /// with the CNC. A halted PLC does nothing, but the CNC still exchanges (it sees the
    /// frozen G). The VM does not own the CNC: the caller (usually a `Machine`) lends it for
    /// the tick, so the CNC stays readable between ticks.
    pub fn tick(&mut self, cnc: &mut dyn Cnc) {
        let before = self.executed;
        if self.halt.is_none() {
            self.apply_forces();
            self.run_level1(cnc);
            if self.halt.is_none() {
                self.run_level2_slice(cnc);
            }
        }
        let steps = self.executed - before;
        self.tick_steps = (steps, self.tick_steps.1.max(steps));
        self.ticks += 1;
        // Y and G go out at the end of the tick; the CNC answers in F, which the next tick
        // samples. A halted PLC's outputs stay as they were, and the CNC keeps running.
        let g = self.layout.area_range(Area::G);
        let f = self.layout.area_range(Area::F);
        let a = self.layout.area_range(Area::A);
        let now = self.now_ms();
        // Layout order X Y F G R A …: F lies before G, and G before A, so one split gives F
        // mutably and G and A shared.
        let (f_part, rest) = self.mem.split_at_mut(g.start);
        let g_bytes = &rest[..g.len()];
        let a_bytes = &rest[a.start - g.start..a.end - g.start];
        cnc.exchange(now, g_bytes, a_bytes, &mut f_part[f]);
        self.apply_forces();
    }

    fn run_level1(&mut self, cnc: &mut dyn Cnc) {
        let start = self.code.level1;
        if let Err(h) = self.run(start, exec::Level::One, u64::MAX, cnc) {
            self.halt = Some(h);
        }
    }

    fn run_level2_slice(&mut self, cnc: &mut dyn Cnc) {
        let l2 = &mut self.level2;
        let pc = match l2.resume {
            Some(pc) => pc,
            None => {
                l2.division = self.division;
                l2.cycle_steps = 0;
                // Start of a level-2 cycle: latch X and F for level 2.
                let x = self.layout.area_range(Area::X);
                let f = self.layout.area_range(Area::F);
                let xl = self.layout.x_latch as usize;
                let fl = self.layout.f_latch as usize;
                self.mem.copy_within(x.clone(), xl);
                self.mem.copy_within(f.clone(), fl);
                self.code.level2
            }
        };
        // With n = 1 the whole of level 2 runs every tick (docs/plc.md, "Scan"), however many steps its
        // calls and loops execute; only a division above 1 slices it.
        let quota = match self.level2.division {
            0 | 1 => u64::MAX,
            n => u64::from(self.code.level2_steps).div_ceil(u64::from(n)),
        };
        match self.run(pc, exec::Level::Two, quota.max(1), cnc) {
            Ok(resume) => self.level2.resume = resume,
            Err(h) => self.halt = Some(h),
        }
    }

    /// Reads `bytes` (1, 2, 4) at an address as a signed value (docs/plc.md width rule).
    pub fn read(&self, a: Address, bytes: u32) -> i64 {
        if let Some(bit) = a.bit {
            return i64::from(self.read_bit(Address {
                bit: Some(bit),
                ..a
            }));
        }
        i64::from(memory::read(&self.mem, self.layout.loc(a, false), bytes))
    }

    /// Reads a bit.
    pub fn read_bit(&self, a: Address) -> bool {
        let loc = self.layout.loc(a, false);
        self.mem
            .get(loc.off as usize)
            .is_some_and(|b| b >> a.bit.unwrap_or(0) & 1 == 1)
    }

    /// Reads a real from a 4-byte address.
    pub fn read_real(&self, a: Address) -> f32 {
        memory::read_real(&self.mem, self.layout.loc(a, false))
    }

    /// Writes `bytes` of `value` at an address (a bit address takes 0 or 1). Forced bits keep
    /// their forced value.
    pub fn write(&mut self, a: Address, bytes: u32, value: i64) {
        let loc = self.layout.loc(a, false);
        match a.bit {
            Some(bit) => {
                if let Some(b) = self.mem.get_mut(loc.off as usize) {
                    *b = (*b & !(1 << bit)) | (u8::from(value != 0) << bit);
                }
            }
            None => memory::write(&mut self.mem, loc, bytes, value as i32),
        }
        self.apply_forces();
    }

    /// Writes a real into a 4-byte address.
    pub fn write_real(&mut self, a: Address, value: f32) {
        memory::write_real(&mut self.mem, self.layout.loc(a, false), value);
        self.apply_forces();
    }

    /// Holds a bit (or every bit of an address) at `value` until [`Vm::unforce`], whatever
    /// the program or a later write does.
    pub fn force(&mut self, a: Address, value: i64) {
        let loc = self.layout.loc(a, false);
        let bytes = if loc.wide { 4 } else { 1 };
        let image = if loc.wide {
            (value as i32).to_le_bytes()
        } else {
            [value as u8, 0, 0, 0]
        };
        for (k, byte) in image.iter().enumerate().take(bytes) {
            let off = loc.off as usize + k;
            let (mask, val) = match a.bit {
                Some(bit) => (1u8 << bit, u8::from(value != 0) << bit),
                None => (0xFF, *byte),
            };
            self.force_mask[off] |= mask;
            self.force_value[off] = (self.force_value[off] & !mask) | val;
            if !self.forced_bytes.contains(&(off as u32)) {
                self.forced_bytes.push(off as u32);
            }
        }
        self.apply_forces();
    }

    /// Releases a force; the last forced value stays until something writes it.
    pub fn unforce(&mut self, a: Address) {
        let loc = self.layout.loc(a, false);
        let bytes = if loc.wide { 4 } else { 1 };
        for k in 0..bytes {
            let off = loc.off as usize + k;
            let mask = a.bit.map_or(0xFF, |b| 1u8 << b);
            self.force_mask[off] &= !mask;
        }
        let mask = &self.force_mask;
        self.forced_bytes.retain(|o| mask[*o as usize] != 0);
    }

    /// The force state of an address's bytes (a saved scenario puts it back on release).
    pub fn force_state(&self, a: Address) -> crate::scenario::ForceState {
        let loc = self.layout.loc(a, false);
        let mut st = crate::scenario::ForceState::default();
        let bytes = if loc.wide { 4 } else { 1 };
        for (k, slot) in st.bytes.iter_mut().enumerate().take(bytes) {
            let off = loc.off as usize + k;
            let mask = self.force_mask.get(off).copied().unwrap_or(0);
            *slot = (mask, self.force_value.get(off).copied().unwrap_or(0) & mask);
        }
        st
    }

    /// Puts an address's bytes' forces back as `state` recorded them.
    pub fn restore_force(&mut self, a: Address, state: crate::scenario::ForceState) {
        let loc = self.layout.loc(a, false);
        let bytes = if loc.wide { 4 } else { 1 };
        // A bit address owns only its bit: the byte's other forces stay as they are now.
        let own = a.bit.map_or(0xFF, |b| 1u8 << b);
        for (k, (mask, value)) in state.bytes.iter().copied().enumerate().take(bytes) {
            let off = loc.off as usize + k;
            self.force_mask[off] = (self.force_mask[off] & !own) | (mask & own);
            self.force_value[off] = (self.force_value[off] & !own) | (value & own);
            let mask = self.force_mask[off];
            if mask != 0 && !self.forced_bytes.contains(&(off as u32)) {
                self.forced_bytes.push(off as u32);
            }
        }
        let m = &self.force_mask;
        self.forced_bytes.retain(|o| m[*o as usize] != 0);
        self.apply_forces();
    }

    /// Whether any bit of an address is forced (for a bit address, that bit).
    pub fn is_forced(&self, a: Address) -> bool {
        let loc = self.layout.loc(a, false);
        let bytes = if loc.wide { 4 } else { 1 };
        let mask = a.bit.map_or(0xFF, |b| 1u8 << b);
        (0..bytes).any(|k| {
            self.force_mask
                .get(loc.off as usize + k)
                .is_some_and(|m| m & mask != 0)
        })
    }

    pub(super) fn apply_forces(&mut self) {
        for &off in &self.forced_bytes {
            let o = off as usize;
            self.mem[o] =
                (self.mem[o] & !self.force_mask[o]) | (self.force_value[o] & self.force_mask[o]);
        }
    }

    /// Turns the recording of a network's values on or off (networks as in
    /// [`Executable::networks`]). Recording costs nothing for networks nobody watches.
    pub fn watch(&mut self, network: usize, on: bool) {
        // While coverage is measured every network stays recorded.
        if self.covering && !on {
            return;
        }
        if let Some(w) = self.watched.get_mut(network)
            && *w != on
        {
            *w = on;
            // Blocks 0 and 1 are the levels; the rest are subprograms.
            let in_sub = usize::from(self.code.networks[network].block >= 2);
            if on {
                self.watch_count += 1;
                self.watched_in_subs += in_sub;
            } else {
                self.watch_count -= 1;
                self.watched_in_subs -= in_sub;
            }
        }
    }

    /// Turns rung coverage on (every network recorded, and every value each word reads or
    /// receives kept, from now on) or off. Off, the scan does no coverage work at all.
    pub fn set_coverage(&mut self, on: bool) {
        self.trace.fill(0);
        self.covering = false;
        for n in 0..self.watched.len() {
            self.watch(n, on);
        }
        self.covering = on;
    }

    /// What coverage has seen since it was turned on, per word of code (see [`Vm::trace`]),
    /// with [`Executable::source`] to place each word; `None` while off.
    pub fn coverage(&self) -> Option<(&[u8], &Executable)> {
        self.covering.then_some((&self.trace[..], &self.code))
    }

    /// Whether a code network is being recorded.
    pub fn is_watched(&self, network: usize) -> bool {
        self.watched.get(network).copied().unwrap_or(false)
    }

    /// What the last execution of each word recorded in bit 0 (contacts: the bit read;
    /// outputs: their ACT), valid for watched networks. The other bits are coverage's: for a
    /// contact, bit 1 + (2·value + accumulator) for each pair it met; for an output, bits 1
    /// and 2 whether its ACT was seen 0 and 1, and for a compare bits 3 to 5 the results it
    /// took.
    pub fn trace(&self) -> &[u8] {
        &self.trace
    }

    /// The value of a location, for monitors: `bytes` at `loc`.
    pub fn read_loc(&self, loc: Loc, bytes: u32) -> i32 {
        memory::read(&self.mem, loc, bytes)
    }

    /// The whole memory image (areas as [`Vm::layout`] places them).
    pub fn image(&self) -> &[u8] {
        &self.mem
    }

    /// The memory image to write into between ticks (the machine model's inputs). Forces
    /// are not applied here: the next tick applies them before its scan, so a force wins.
    pub fn image_mut(&mut self) -> &mut [u8] {
        &mut self.mem
    }

    /// Every forced byte: its offset in the image, the mask of forced bits and their values.
    pub fn forces(&self) -> impl Iterator<Item = (u32, u8, u8)> + '_ {
        self.forced_bytes.iter().map(|&o| {
            let i = o as usize;
            (
                o,
                self.force_mask[i],
                self.force_value[i] & self.force_mask[i],
            )
        })
    }

    /// Sets every byte of an area to 0 (forced bits keep their value): the CNC's F image at
    /// power-on.
    pub fn clear_area(&mut self, area: Area) {
        let r = self.layout.area_range(area);
        self.mem[r].fill(0);
        self.apply_forces();
    }

    /// The memory layout.
    pub fn layout(&self) -> &Layout {
        &self.layout
    }

    /// The target profile.
    pub fn profile(&self) -> &'static Profile {
        self.profile
    }
}
