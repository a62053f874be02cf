//! What a CNC screen shows, copied out for the editor each frame: modes, positions, the
//! executing line, alarms, and the M/S/T interface with its strobes counted, so a monitor
//! that paints 30 times a second still shows a strobe that lasted one exchange.

use super::{AXES, Mode, RunState, macro_b, toolpath};

/// What a CNC screen shows, copied out for the editor each frame.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct CncStatus {
    /// Mode.
    pub mode: Mode,
    /// Automatic operation state.
    pub run: RunState,
    /// `cnc.block`.
    pub block: u32,
    /// `cnc.prog`.
    pub program: u32,
    /// 1-based line of the executing (or next) block in its text, if any.
    pub line: Option<usize>,
    /// The running program is the MDI buffer.
    pub mdi: bool,
    /// `line` is a line of the MDI buffer (also once an MDI run has ended), not of the
    /// program.
    pub line_in_mdi: bool,
    /// Controlled axes.
    pub axes: usize,
    /// Machine positions, increments.
    pub machine: [i64; AXES],
    /// Absolute positions, increments.
    pub absolute: [i64; AXES],
    /// Spindle output, r/min.
    pub spindle: u32,
    /// Active alarms.
    pub alarms: Vec<u16>,
    /// M/S/T lamps.
    pub mst: MstStatus,
    /// The loaded program's path, run dry once per load (docs/gcode.md, "Toolpath").
    pub toolpath: Option<std::sync::Arc<toolpath::Toolpath>>,
    /// The active macro alarm (3000–3200) and its message.
    pub macro_message: Option<(u16, String)>,
    /// The macro variables an operator sees (docs/gcode.md, "Macros").
    pub macros: Option<std::sync::Arc<macro_b::MacroTable>>,
    /// The message of a stop by `#3006 = n (MESSAGE)`, until cycle start or reset.
    pub stop_message: Option<String>,
}

/// The M/S/T interface as lamps and codes.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct MstStatus {
    /// M code and MF.
    pub m: u32,
    /// MF.
    pub mf: bool,
    /// S code.
    pub s: u32,
    /// SF.
    pub sf: bool,
    /// T code.
    pub t: u32,
    /// TF.
    pub tf: bool,
    /// FIN as last sampled.
    pub fin: bool,
    /// DEN.
    pub den: bool,
    /// The last M, S and T codes sent (kept after their strobes fall, as a CNC screen
    /// shows the codes in effect).
    pub last: [u32; 3],
    /// MF, SF, TF and FIN rising edges since power-on.
    pub strobes: [u64; 4],
}
