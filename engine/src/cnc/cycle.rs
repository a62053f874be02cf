//! Thread cutting and the single cycles of group 01 (docs/gcode.md, "Threading" and "Single
//! cycles"): G32, G90 turning, G92 threading and G94 facing, each planned as segments from the
//! block's start point. The cycles are modal: a later block with only X/U or Z/W repeats the
//! cycle with that value and the others kept.

use super::modal::Modal;
use super::params::P5130;
use super::path::{SegKind, Segment};
use super::word::{Num, Units, Words};
use super::{AXES, SimCnc};

impl SimCnc {
    /// Increments per mm of radius on X.
    fn x_per_radius(&self) -> i64 {
        if self.diameter(0) { 2 } else { 1 }
    }

    /// Plans G32, G90, G92 or G94 (`modal.motion`) from `cur` to `target`.
    pub(super) fn plan_cycle(
        &self,
        w: &Words,
        modal: &mut Modal,
        u: Units,
        cur: [i64; AXES],
        target: [i64; AXES],
        segs: &mut Vec<Segment>,
    ) -> Result<(), u16> {
        if modal.motion == 32 {
            segs.push(self.thread(target, modal.feed));
            return Ok(());
        }
        // A block without X/U or Z/W does not run the cycle (it may carry M, S, T…).
        if w.axes[0].is_none() && w.axes[1].is_none() {
            return Ok(());
        }
        let taper_word: Option<Num> = match modal.motion {
            94 => w.r.or(w.k),
            _ => w.r.or(w.i),
        };
        let mem = &mut modal.cycle;
        if w.axes[0].is_some() {
            mem.x = target[0];
        }
        if w.axes[1].is_some() {
            mem.z = target[1];
        }
        if let Some(t) = taper_word {
            mem.r = u.len(t)?;
        } else if w.axes[0].is_some() && w.axes[1].is_some() {
            mem.r = 0;
        }
        let m = *mem;
        let (x0, z0) = (cur[0], cur[1]);
        let at = |x: i64, z: i64| {
            let mut p = cur;
            p[0] = x;
            p[1] = z;
            p
        };
        let cut = |kind: SegKind, p: [i64; AXES]| Segment::cut(kind, p, modal.feed, modal.per_rev);
        let taper = m.r * self.x_per_radius();
        match modal.motion {
            90 => {
                segs.push(Segment::to(SegKind::Rapid, at(m.x + taper, z0)));
                segs.push(cut(SegKind::Line, at(m.x, m.z)));
                segs.push(cut(SegKind::Line, at(x0, m.z)));
                segs.push(Segment::to(SegKind::Rapid, at(x0, z0)));
            }
            94 => {
                segs.push(Segment::to(SegKind::Rapid, at(x0, m.z + m.r)));
                segs.push(cut(SegKind::Line, at(m.x, m.z)));
                segs.push(cut(SegKind::Line, at(m.x, z0)));
                segs.push(Segment::to(SegKind::Rapid, at(x0, z0)));
            }
            _ => {
                segs.push(Segment::to(SegKind::Rapid, at(m.x + taper, z0)));
                self.thread_with_chamfer(at(m.x + taper, z0), at(m.x, m.z), x0, modal.feed, segs);
                segs.push(Segment::to(SegKind::Rapid, at(x0, z0)));
            }
        }
        Ok(())
    }

    /// A thread segment to `target` with lead `lead` mm/rev.
    pub(super) fn thread(&self, target: [i64; AXES], lead: f64) -> Segment {
        Segment::cut(SegKind::Thread { lead }, target, lead, true)
    }

    /// The threading pass of G92 and G76 from `from` to `to`, pulled out towards `x_out` over
    /// the chamfer of #5130 (tenths of the lead, 45°) at its end; then the rapid retract in X.
    pub(super) fn thread_with_chamfer(
        &self,
        from: [i64; AXES],
        to: [i64; AXES],
        x_out: i64,
        lead: f64,
        segs: &mut Vec<Segment>,
    ) {
        let chamfer = (self.params.one(P5130) as f64 * lead * 100.0).round() as i64;
        let dz = to[1] - from[1];
        let out = (x_out - to[0]).signum();
        if chamfer > 0 && dz.abs() > chamfer && out != 0 {
            let f = (dz.abs() - chamfer) as f64 / dz.abs() as f64;
            let mut a = to;
            a[0] = from[0] + ((to[0] - from[0]) as f64 * f).round() as i64;
            a[1] = from[1] + dz.signum() * (dz.abs() - chamfer);
            segs.push(self.thread(a, lead));
            let mut b = to;
            b[0] = a[0] + out * chamfer * self.x_per_radius();
            segs.push(self.thread(b, lead));
            let mut c = b;
            c[0] = x_out;
            segs.push(Segment::to(SegKind::Rapid, c));
        } else {
            segs.push(self.thread(to, lead));
            let mut c = to;
            c[0] = x_out;
            segs.push(Segment::to(SegKind::Rapid, c));
        }
    }
}
