//! The whole path of the loaded program, worked out by running the same interpreter dry
//! (docs/gcode.md, "Toolpath"): a copy of the CNC runs the memory program from its first block
//! with every block's segments taken at once — no time, no handshake, M00/M01 passed, the
//! reference points taken as established — and each segment becomes a piece of polyline in
//! the Z–X plane, in machine coordinates (mm, X as the axis shows it). It stops at the
//! program's end, at an M99 of the main program (one pass), or at the first alarm, which it
//! reports with its line.

use super::SimCnc;
use super::modal::RunState;
use super::path::SegKind;
use super::signals::Inputs;

/// What a piece of the toolpath is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PieceKind {
    /// Positioning at rapid (drawn dashed).
    Rapid,
    /// Cutting feed, line or arc.
    Feed,
    /// Thread cutting.
    Thread,
}

/// One segment of the path: its kind, the program line of its block, and its points.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Piece {
    /// Rapid, feed or thread.
    pub kind: PieceKind,
    /// 1-based line of the block in the program text.
    pub line: usize,
    /// Its points: `Toolpath::points[start..end]`, the first being the previous piece's last.
    pub start: u32,
    /// One past its last point.
    pub end: u32,
}

/// The dry run of the memory program.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Toolpath {
    /// Points (Z, X) in mm, machine coordinates.
    pub points: Vec<[f64; 2]>,
    /// The pieces in program order.
    pub pieces: Vec<Piece>,
    /// Blocks executed.
    pub blocks: usize,
    /// The alarm that ended the dry run and the line of its block.
    pub alarm: Option<(u16, usize)>,
    /// The run was cut short at [`BLOCK_LIMIT`] blocks.
    pub truncated: bool,
}

/// Blocks a dry run executes at most.
pub const BLOCK_LIMIT: usize = 2_000_000;

/// Exchanges' shares of macro statements a dry run goes on through without an NC block
/// (a million statements): a loop that computes for longer ends the path there.
const STATEMENT_RUNS: u32 = 100;

/// Degrees per point of a drawn arc.
const ARC_STEP: f64 = 3.0;

impl Toolpath {
    /// The index of the piece nearest to `p` (Z, X mm) within `tolerance` mm.
    pub fn piece_near(&self, p: [f64; 2], tolerance: f64) -> Option<usize> {
        let mut best = (tolerance, None);
        for (k, piece) in self.pieces.iter().enumerate() {
            let pts = &self.points[piece.start as usize..piece.end as usize];
            for w in pts.windows(2) {
                let d = distance_to_segment(p, w[0], w[1]);
                if d <= best.0 {
                    best = (d, Some(k));
                }
            }
        }
        best.1
    }
}

fn distance_to_segment(p: [f64; 2], a: [f64; 2], b: [f64; 2]) -> f64 {
    let (dx, dy) = (b[0] - a[0], b[1] - a[1]);
    let len2 = dx * dx + dy * dy;
    let t = if len2 > 0.0 {
        (((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / len2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    ((p[0] - a[0] - t * dx).powi(2) + (p[1] - a[1] - t * dy).powi(2)).sqrt()
}

impl SimCnc {
    /// Runs the memory program dry from the current position and returns its path.
    pub fn toolpath(&self) -> Toolpath {
        let mut c = self.clone();
        c.toolpath = Default::default();
        c.alarms.clear();
        c.pending_alarms.clear();
        c.inp = Inputs::healthy();
        c.inp.afl = true;
        c.flags = Default::default();
        for a in &mut c.axes {
            a.zrf = true;
        }
        c.auto.reset();
        c.auto.state = RunState::Run;
        let mut out = Toolpath::default();
        out.points.push(self.machine_mm());
        let mut statement_runs = 0;
        while out.blocks < BLOCK_LIMIT {
            if c.auto.state == RunState::Idle {
                // M02/M30 or the end of the program.
                return out;
            }
            let before = (c.auto.cursor, c.auto.macro_writes);
            c.start_next_block();
            if let Some(&n) = c.alarms.first() {
                // A program error, or a statement run ahead of the block that failed.
                let line = c.auto.current_line(&c.programs, &c.mdi).unwrap_or(0);
                out.alarm = Some((n, line));
                return out;
            }
            if c.auto.exec.is_none()
                && c.auto.state == RunState::Stop
                && statement_runs < STATEMENT_RUNS
            {
                // A #3006 stop between blocks is passed, as M00 is.
                c.auto.state = RunState::Run;
                c.macros.stop_message = None;
                statement_runs += 1;
                continue;
            }
            let busy = c.auto.exec.is_none()
                && c.auto.state == RunState::Run
                && before != (c.auto.cursor, c.auto.macro_writes);
            if busy && statement_runs < STATEMENT_RUNS {
                // Macro statements used up an exchange's share and went on: so does the dry
                // run. A loop waiting for the PLC changes nothing and ends the path.
                statement_runs += 1;
                continue;
            }
            let Some(mut e) = c.auto.exec else {
                return out;
            };
            if c.auto.state != RunState::Run {
                return out;
            }
            out.blocks += 1;
            for k in 0..c.auto.segs.len() {
                let s = c.auto.segs[k];
                let kind = match s.kind {
                    SegKind::Rapid => PieceKind::Rapid,
                    SegKind::Thread { .. } => PieceKind::Thread,
                    _ => PieceKind::Feed,
                };
                let Some(m) = s.motion(c.frame_position(), c.diameters()) else {
                    continue;
                };
                for (n, t) in s.target.iter().enumerate() {
                    c.axes[n].m = t + c.axes[n].sh;
                }
                if m.is_empty() {
                    continue;
                }
                let first = out.points.len() as u32 - 1;
                if let Some(a) = &m.arc {
                    let steps = (a.sweep.abs().to_degrees() / ARC_STEP).ceil().max(1.0) as usize;
                    for i in 1..steps {
                        let f = i as f64 / steps as f64;
                        let at = |n: usize| m.position_at(n, m.length * f) as f64 / 1000.0;
                        out.points.push([at(1), at(0)]);
                    }
                }
                out.points.push(c.machine_mm());
                out.pieces.push(Piece {
                    kind,
                    line: e.line,
                    start: first,
                    end: out.points.len() as u32,
                });
            }
            let main_m99 = e.ret && c.auto.stack.is_empty();
            e.seg = e.seg_count;
            e.motion = None;
            e.dwell_total = 0.0;
            e.mst.open = false;
            c.auto.exec = Some(e);
            c.end_of_block();
            if main_m99 {
                return out;
            }
            if c.auto.state == RunState::Stop {
                c.auto.state = RunState::Run;
            }
        }
        out.truncated = true;
        out
    }

    /// The machine position (Z, X) in mm.
    fn machine_mm(&self) -> [f64; 2] {
        [
            self.axes[1].m as f64 / 1000.0,
            self.axes[0].m as f64 / 1000.0,
        ]
    }
}

/// The toolpath of the loaded program, worked out once per load when first asked for.
#[derive(Clone, Debug, Default)]
pub(super) struct ToolpathCache(std::sync::OnceLock<std::sync::Arc<Toolpath>>);

impl ToolpathCache {
    /// The cached path, computed by `f` the first time.
    pub fn get(&self, f: impl FnOnce() -> Toolpath) -> std::sync::Arc<Toolpath> {
        self.0.get_or_init(|| std::sync::Arc::new(f())).clone()
    }
}
