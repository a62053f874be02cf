//! Drilling cycles of group 10 (docs/gcode.md, "Drilling cycles"): G83 face drilling, G84
//! face tapping, G85 face boring along Z, and G87, G88, G89 the same from the side along X;
//! G80 cancels. They are modal: every later block with a position word drills again with the
//! R point, peck, dwell and bottom kept.

use super::modal::Modal;
use super::path::{SegKind, Segment, room};
use super::word::{Num, Units, Words};
use super::{AXES, SimCnc};

impl SimCnc {
    /// Plans one drilling cycle at the block's position, if it gives one.
    pub(super) fn plan_drill(
        &self,
        w: &Words,
        modal: &mut Modal,
        u: Units,
        cur: [i64; AXES],
        target: [i64; AXES],
        segs: &mut Vec<Segment>,
    ) -> Result<(), u16> {
        let mem = &mut modal.drill;
        let side = matches!(mem.g, 87..=89);
        // The drilling axis: Z for face cycles, X for side cycles.
        let (d, p) = if side { (0, 1) } else { (1, 0) };
        if let Some(r) = w.r {
            mem.r = u.len(r)?;
        }
        if let Some(q) = w.q {
            mem.q = u.fixed(q)?.abs();
        }
        if let Some(t) = w.p {
            mem.p = t;
        }
        if w.axes[d].is_some() {
            mem.bottom = Some(target[d]);
        }
        if !w.moves() {
            return Ok(());
        }
        let m = *mem;
        let bottom = m.bottom.ok_or(super::program::ps::CYCLE_VALUE)?;
        let initial = cur[d];
        let r_point = initial + m.r;
        let at = |pos: i64, depth: i64| {
            let mut t = cur;
            t[p] = pos;
            t[d] = depth;
            t
        };
        let pos = target[p];
        let (feed, per_rev) = (modal.feed, modal.per_rev);
        let count =
            w.k.map_or(1, |k: Num| k.value.round().clamp(1.0, 9999.0) as u32);
        for _ in 0..count {
            segs.push(Segment::to(SegKind::Rapid, at(pos, initial)));
            segs.push(Segment::to(SegKind::Rapid, at(pos, r_point)));
            let total = (bottom - r_point).abs();
            let dir = (bottom - r_point).signum();
            if matches!(m.g, 83 | 87) && m.q > 0 {
                let mut done = 0;
                while done < total {
                    room(segs)?;
                    let next = (done + m.q).min(total);
                    if done > 0 {
                        segs.push(Segment::to(SegKind::Rapid, at(pos, r_point + dir * done)));
                    }
                    segs.push(Segment::cut(
                        SegKind::Line,
                        at(pos, r_point + dir * next),
                        feed,
                        per_rev,
                    ));
                    done = next;
                    if done < total {
                        segs.push(Segment::to(SegKind::Rapid, at(pos, r_point)));
                    }
                }
            } else {
                segs.push(Segment::cut(SegKind::Line, at(pos, bottom), feed, per_rev));
            }
            segs.push(Segment::to(
                SegKind::Dwell { ms: f64::from(m.p) },
                at(pos, bottom),
            ));
            if matches!(m.g, 84 | 85 | 88 | 89) {
                // Tapping and boring come back out at feed to the R point.
                segs.push(Segment::cut(SegKind::Line, at(pos, r_point), feed, per_rev));
            }
            segs.push(Segment::to(SegKind::Rapid, at(pos, initial)));
        }
        Ok(())
    }
}
