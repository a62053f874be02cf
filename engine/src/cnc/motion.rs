//! Straight-line motion (docs/cnc.md, "Motion"): a start and a target per axis, the path
//! length in millimetres of radius, and the distance covered so far. Every motion of the
//! simulator — program blocks, G28 segments, PLC axis moves — advances through this one type,
//! so the timing rule (⌈L / (v · 8 / 60000)⌉ exchanges, the first being the one it starts in)
//! holds everywhere.

use super::AXES;
use super::arc::ArcPath;

/// Millimetres covered in one exchange at 1 mm/min.
pub const MM_PER_EXCHANGE: f64 = 8.0 / 60_000.0;

/// Whether a motion is rapid-type (RPDO) or a cutting feed (CUT).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum MotionKind {
    /// G00, G28, PLC rapid.
    Rapid,
    /// G01, PLC cutting feed.
    Cut,
}

/// One straight-line motion.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Motion {
    /// Rapid or cutting.
    pub kind: MotionKind,
    /// Axes that move (bit n−1 for axis n).
    pub axes: u8,
    /// Start position per axis, increments.
    pub start: [i64; AXES],
    /// Target per axis, increments.
    pub target: [i64; AXES],
    /// |Δ| per axis in mm of radius.
    pub axis_mm: [f64; AXES],
    /// Path length, mm of radius.
    pub length: f64,
    /// Distance covered, mm.
    pub covered: f64,
    /// For circular motion, the arc that X (slot 0) and Z (slot 1) follow; the other axes move
    /// linearly with it.
    pub arc: Option<ArcPath>,
    /// Increments per mm of X and Z, to turn the arc's points into positions.
    pub scale: [f64; 2],
}

/// Increments per mm of radius on axis slot `n`.
fn per_mm(diameter: &[bool; AXES], n: usize) -> f64 {
    if diameter[n] { 2000.0 } else { 1000.0 }
}

impl Motion {
    /// A motion from `start` to `target`; `diameter[n]` says axis n+1 counts ΔX/2.
    pub fn new(
        kind: MotionKind,
        start: [i64; AXES],
        target: [i64; AXES],
        diameter: [bool; AXES],
    ) -> Motion {
        let mut axes = 0u8;
        let mut axis_mm = [0.0; AXES];
        let mut sum = 0.0;
        for n in 0..AXES {
            let d = target[n] - start[n];
            if d != 0 {
                axes |= 1 << n;
                let k = if diameter[n] { 2000.0 } else { 1000.0 };
                let mm = (d as f64 / k).abs();
                axis_mm[n] = mm;
                sum += mm * mm;
            }
        }
        Motion {
            kind,
            axes,
            start,
            target,
            axis_mm,
            length: sum.sqrt(),
            covered: 0.0,
            arc: None,
            scale: [per_mm(&diameter, 0), per_mm(&diameter, 1)],
        }
    }

    /// A cutting motion along an arc from `start` to `target` around `center` (X, Z in
    /// increments as the axes count them), clockwise when `cw`; a closed arc is a full turn
    /// when `full`. Other axes move linearly (a helix).
    pub fn arc(
        start: [i64; AXES],
        target: [i64; AXES],
        center: [i64; 2],
        cw: bool,
        full: bool,
        diameter: [bool; AXES],
    ) -> Motion {
        let mut m = Motion::new(MotionKind::Cut, start, target, diameter);
        let plane = |p: [i64; AXES]| {
            [
                p[1] as f64 / per_mm(&diameter, 1),
                p[0] as f64 / per_mm(&diameter, 0),
            ]
        };
        let c = [
            center[1] as f64 / per_mm(&diameter, 1),
            center[0] as f64 / per_mm(&diameter, 0),
        ];
        let path = ArcPath::new(plane(start), plane(target), c, cw, full);
        if path.sweep == 0.0 {
            return m;
        }
        let other: f64 = (2..AXES).map(|n| m.axis_mm[n] * m.axis_mm[n]).sum();
        m.axes |= 0b11;
        m.length = path.length().hypot(other.sqrt());
        m.arc = Some(path);
        m
    }

    /// Whether the motion has nothing to do.
    pub fn is_empty(&self) -> bool {
        self.axes == 0
    }

    /// Whether it is complete.
    pub fn done(&self) -> bool {
        self.covered >= self.length - 1e-9
    }

    /// The position of axis slot `n` after covering `covered` mm.
    pub fn position_at(&self, n: usize, covered: f64) -> i64 {
        if self.axes >> n & 1 == 0 {
            return self.target[n];
        }
        if covered >= self.length - 1e-9 {
            return self.target[n];
        }
        let f = (covered / self.length).min(1.0);
        if let Some(a) = &self.arc
            && n < 2
        {
            // The arc works in (Z, X) mm: slot 0 (X) is its second coordinate.
            return (a.point(f)[1 - n] * self.scale[n]).round() as i64;
        }
        self.start[n] + ((self.target[n] - self.start[n]) as f64 * f).round() as i64
    }

    /// The distance after one more exchange at `v` mm/min (not applied).
    pub fn next_covered(&self, v: f64) -> f64 {
        self.covered + v * MM_PER_EXCHANGE
    }

    /// The rapid speed along the path: each axis at most at its own rate (mm/min), the
    /// slowest one deciding. 0 when a moving axis has rate 0.
    pub fn rapid_speed(&self, rate: impl Fn(usize) -> f64) -> f64 {
        let mut t: f64 = 0.0;
        for n in 0..AXES {
            if self.axes >> n & 1 == 1 {
                let r = rate(n);
                if r <= 0.0 {
                    return 0.0;
                }
                t = t.max(self.axis_mm[n] / r);
            }
        }
        if t > 0.0 { self.length / t } else { 0.0 }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn twenty_mm_at_f600_takes_250_exchanges() {
        let mut m = Motion::new(
            MotionKind::Cut,
            [0; AXES],
            [0, -20_000, 0, 0, 0],
            [true, false, false, false, false],
        );
        let mut n = 0;
        while !m.done() {
            m.covered = m.next_covered(600.0);
            n += 1;
        }
        assert_eq!(n, 250);
        assert_eq!(m.position_at(1, m.covered), -20_000);
    }

    #[test]
    fn a_diameter_axis_counts_half_and_rapid_takes_the_slowest_axis() {
        let m = Motion::new(
            MotionKind::Rapid,
            [0; AXES],
            [20_000, 10_000, 0, 0, 0],
            [true, false, false, false, false],
        );
        assert!((m.length - 200f64.sqrt()).abs() < 1e-12);
        let v = m.rapid_speed(|n| if n == 0 { 6000.0 } else { 3000.0 });
        // Z needs 10 mm at 3000: the path takes 10/3000 min.
        assert!((v - m.length / (10.0 / 3000.0)).abs() < 1e-9);
    }
}
