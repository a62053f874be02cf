//! Chamfering and corner rounding between two G01 blocks (docs/gcode.md, "Chamfer and corner
//! R"): `,C`c cuts the corner with a straight line from c before it to c after it; `,R`r
//! rounds it with an arc of radius r tangent to both lines. The block with the word ends at the
//! start of the chamfer or arc and cuts it; the next block then starts where it ended, on its
//! own line, so it needs no change.

use super::arc::center_from_radius;
use super::modal::Modal;
use super::path::{SegKind, Segment};
use super::ps;
use super::word::{Units, Words};
use super::{AXES, SimCnc};

impl SimCnc {
    /// Plans a G01 block from `cur` to `target` whose corner with the next block is cut by `,C`
    /// or rounded by `,R`.
    pub(super) fn plan_corner(
        &self,
        w: &Words,
        modal: &Modal,
        u: Units,
        cur: [i64; AXES],
        target: [i64; AXES],
        segs: &mut Vec<Segment>,
    ) -> Result<(), u16> {
        let next = self.next_line_end(modal, target)?;
        let (a, b, c) = (
            self.plane_mm(cur),
            self.plane_mm(target),
            self.plane_mm(next),
        );
        let len1 = (b[0] - a[0]).hypot(b[1] - a[1]);
        let len2 = (c[0] - b[0]).hypot(c[1] - b[1]);
        if len1 < 1e-9 || len2 < 1e-9 {
            return Err(ps::CORNER_SIZE);
        }
        let d1 = [(b[0] - a[0]) / len1, (b[1] - a[1]) / len1];
        let d2 = [(c[0] - b[0]) / len2, (c[1] - b[1]) / len2];
        let cut = |kind: SegKind, t: [i64; AXES]| Segment::cut(kind, t, modal.feed, modal.per_rev);
        let (dist, round) = match (w.chamfer, w.corner) {
            (Some(ch), _) => (u.len(ch)? as f64 / 1000.0, None),
            (None, Some(r)) => {
                let r = u.len(r)? as f64 / 1000.0;
                // The tangent length of a radius r between the two directions.
                let turn = (d1[0] * d2[0] + d1[1] * d2[1]).clamp(-1.0, 1.0).acos();
                ((turn / 2.0).tan() * r, Some(r))
            }
            (None, None) => (0.0, None),
        };
        if dist > len1 + 1e-9 || dist > len2 + 1e-9 || !dist.is_finite() {
            return Err(ps::CORNER_SIZE);
        }
        let p1 = [b[0] - d1[0] * dist, b[1] - d1[1] * dist];
        let p2 = [b[0] + d2[0] * dist, b[1] + d2[1] * dist];
        let t1 = self.plane_incr(p1, target);
        let t2 = self.plane_incr(p2, target);
        segs.push(cut(SegKind::Line, t1));
        match round {
            None => segs.push(cut(SegKind::Line, t2)),
            Some(r) => {
                // Turning clockwise (Z across, X up) makes a G02.
                let cw = d1[0] * d2[1] - d1[1] * d2[0] < 0.0;
                let centre = center_from_radius(p1, p2, r, cw, 1e-3)?;
                let c = self.plane_incr(centre, target);
                let kind = SegKind::Arc {
                    cw,
                    center: [c[0], c[1]],
                    full: false,
                };
                segs.push(cut(kind, t2));
            }
        }
        Ok(())
    }

    /// The end point of the block after the executing one, which must be a G01 move.
    fn next_line_end(&self, modal: &Modal, from: [i64; AXES]) -> Result<[i64; AXES], u16> {
        let (prog, here) = self.running_program().ok_or(ps::CORNER_NEXT)?;
        let b = prog.blocks.get(here + 1).ok_or(ps::CORNER_NEXT)?;
        let w = self.block_words(b).map_err(|_| ps::CORNER_NEXT)?;
        let motion = w.motion.unwrap_or(modal.motion);
        if motion != 1 || w.one_shot.is_some() || !w.moves() {
            return Err(ps::CORNER_NEXT);
        }
        let mut m = *modal;
        if let Some(inch) = w.inch {
            m.inch = inch;
        }
        self.end_point(&w, self.units(m.inch), &m, from)
    }
}
