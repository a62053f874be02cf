//! The interface between the PLC and the CNC, for the instructions that talk to it (WINDR,
//! AXCTL, PSGNL, PSGN2) and for the F/G signal exchange. The simulated CNC implements it; so
//! do the test doubles here.

/// What the CNC says about a PLC axis group's current command (AXCTL).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct AxisStatus {
    /// The command has ended (normally or in error).
    pub ended: bool,
    /// It ended in error, or the CNC raised an alarm.
    pub error: bool,
}

/// The CNC as the PLC sees it. `Send`, so a machine (PLC and CNC together) can run on a
/// thread of its own while the user interface reads snapshots of it.
pub trait Cnc: Send {
    /// Whether a WINDR function code is a low-speed (write) function that takes two scans.
    fn window_is_low_speed(&self, function: i32) -> bool;
    /// Executes a WINDR function on a window block (`block[0]` function code, `[1]` end code,
    /// `[2]` data length, `[3]` data number, `[4]` attribute, `[5]` channel, `[6..]` data);
    /// `block` runs to the end of the D area.
    fn window(&mut self, block: &mut [i32]);
    /// The machine coordinate of an axis (1, 2, …; 21, 22, … for the second channel) in least
    /// input increments, or `None` when there is no such axis.
    fn machine_position(&self, axis: u32) -> Option<i64>;
    /// The state of the command of a PLC axis group (1–4), given the group's EBUF bit as the
    /// PLC holds it when it asks (a command issued but not yet read has not ended).
    fn axis_status(&self, group: u8, ebuf: bool) -> AxisStatus;
    /// Once per tick, after the PLC ran: the CNC reads the G signals and the A area (PLC
    /// alarm requests) and sets the F signals. `now_ms` is the virtual time at the end of the
    /// tick.
    fn exchange(&mut self, now_ms: u64, g: &[u8], a: &[u8], f: &mut [u8]);
}

/// No CNC attached: windows answer "function not available" (end code 7), there are no
/// axes, PLC axis commands never end, and F keeps whatever the user sets.
#[derive(Clone, Debug, Default)]
pub struct NoCnc;

impl Cnc for NoCnc {
    fn window_is_low_speed(&self, _function: i32) -> bool {
        false
    }
    fn window(&mut self, block: &mut [i32]) {
        if block.len() > 2 {
            block[1] = 7;
            block[2] = 0;
        }
    }
    fn machine_position(&self, _axis: u32) -> Option<i64> {
        None
    }
    fn axis_status(&self, _group: u8, _ebuf: bool) -> AxisStatus {
        AxisStatus::default()
    }
    fn exchange(&mut self, _now_ms: u64, _g: &[u8], _a: &[u8], _f: &mut [u8]) {}
}

/// A scriptable CNC for tests: fixed positions and axis states, a WINDR that answers with
/// fixed data and counts its calls, and a record of the G signals it saw.
#[derive(Clone, Debug, Default)]
pub struct FakeCnc {
    /// Machine positions of axes 1, 2, …
    pub positions: Vec<i64>,
    /// Axis group states, groups 1–4.
    pub axes: [AxisStatus; 4],
    /// WINDR function codes treated as low-speed.
    pub low_speed: Vec<i32>,
    /// Data a WINDR read returns at `[6..]`.
    pub window_data: Vec<i32>,
    /// How many times WINDR reached the CNC.
    pub window_calls: u32,
    /// The first eight slots of the last block WINDR handed over.
    pub last_block: Vec<i32>,
    /// The G signals after the last tick.
    pub last_g: Vec<u8>,
}

impl Cnc for FakeCnc {
    fn window_is_low_speed(&self, function: i32) -> bool {
        self.low_speed.contains(&function)
    }
    fn window(&mut self, block: &mut [i32]) {
        self.window_calls += 1;
        self.last_block = block.iter().take(8).copied().collect();
        if block.len() < 6 + self.window_data.len() {
            if block.len() > 2 {
                block[1] = 2;
                block[2] = 0;
            }
            return;
        }
        block[1] = 0;
        if !self.low_speed.contains(&block[0]) {
            block[2] = self.window_data.len() as i32;
            block[6..6 + self.window_data.len()].copy_from_slice(&self.window_data);
        }
    }
    fn machine_position(&self, axis: u32) -> Option<i64> {
        self.positions.get((axis as usize).checked_sub(1)?).copied()
    }
    fn axis_status(&self, group: u8, _ebuf: bool) -> AxisStatus {
        self.axes
            .get(usize::from(group).wrapping_sub(1))
            .copied()
            .unwrap_or_default()
    }
    fn exchange(&mut self, _now_ms: u64, g: &[u8], _a: &[u8], _f: &mut [u8]) {
        self.last_g.clear();
        self.last_g.extend_from_slice(g);
    }
}
