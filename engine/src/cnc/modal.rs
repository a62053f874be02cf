//! The state automatic operation keeps between blocks: whether it runs, and the program's
//! modal state (G groups, feed, surface speed, the last single and drilling cycles). Kept
//! apart from `auto.rs`, which runs blocks, so that the parts a block reaches (MST, paths,
//! cycles, drilling, the tool path) read it without importing the runner back.

/// The automatic operation state.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum RunState {
    /// Reset state, or the program has not started or has ended (rewound).
    #[default]
    Idle,
    /// Cycle start state.
    Run,
    /// Feed hold state.
    Hold,
    /// Stopped inside the program (single block, M00, an alarm…).
    Stop,
}

impl RunState {
    /// The script and display name.
    pub fn name(self) -> &'static str {
        match self {
            RunState::Idle => "IDLE",
            RunState::Run => "RUN",
            RunState::Hold => "HOLD",
            RunState::Stop => "STOP",
        }
    }

    /// Every state, for name look-ups.
    pub const ALL: [RunState; 4] = [
        RunState::Idle,
        RunState::Run,
        RunState::Hold,
        RunState::Stop,
    ];
}

/// Modal state of the program.
#[derive(Clone, Copy, Debug, Default)]
pub(super) struct Modal {
    /// Group 01 G number: 0, 1, 2, 3, 32, 90, 92, 94.
    pub motion: u8,
    /// G99.
    pub per_rev: bool,
    /// G54 + work.
    pub work: u8,
    /// F in mm/min or mm/rev (0 = none).
    pub feed: f64,
    /// G20.
    pub inch: bool,
    /// G96.
    pub css: bool,
    /// G96's surface speed, m/min.
    pub css_speed: f64,
    /// G50 S: the highest spindle speed under G96, r/min (0: none).
    pub s_max: u32,
    /// The last single cycle's end point and taper.
    pub cycle: CycleMemory,
    /// The drilling cycle in effect and its data.
    pub drill: DrillMemory,
}

/// The remembered end point and taper of the modal single cycle (frame increments; X as the
/// axis counts it, the taper as a radius).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub(super) struct CycleMemory {
    /// X of the cycle's end point.
    pub x: i64,
    /// Z of the cycle's end point.
    pub z: i64,
    /// Taper R (I for G90/G92, K for G94 in the FS15 form), radius increments.
    pub r: i64,
}

/// The remembered data of the modal drilling cycle.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub(super) struct DrillMemory {
    /// The cycle: 0 or 80 none, else 83–89.
    pub g: u8,
    /// R: from the initial level to the R point along the drilling axis, increments.
    pub r: i64,
    /// Q: peck depth, increments (0: one feed to the bottom).
    pub q: i64,
    /// P: dwell at the bottom, ms.
    pub p: u32,
    /// The bottom (frame increments on the drilling axis), once given.
    pub bottom: Option<i64>,
}
