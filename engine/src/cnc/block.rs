//! Planning one block (docs/gcode.md): its words, read in the units of the moment, become the
//! segments of `path.rs` or a change of CNC data (G10, G50). Nothing is changed until the
//! whole block has been checked, so a block refused with a P/S alarm leaves no trace.

use super::arc::{ArcPath, center_from_radius};
use super::modal::Modal;
use super::params::{P1240, P3401, P3410};
use super::path::{Home, SegKind, Segment};
use super::ps;
use super::word::{Num, OneShot, Units, Words};
use super::{AXES, SimCnc};

use super::program::ps::G10_P as PS_G10_P;

/// What a planned block changes besides its path.
#[derive(Clone, Copy, Debug, Default)]
pub(super) struct Effects {
    /// G50 X/Z: the new coordinate shift per axis.
    pub shift: Option<[i64; AXES]>,
    /// G70: the blocks P and Q (indices in the running program) and the start point.
    pub g70: Option<(usize, usize, [i64; AXES])>,
    /// G71–G73 whose profile follows it: the block index the program goes on at.
    pub resume: Option<usize>,
}

impl SimCnc {
    /// How length words read under the modal unit `inch`.
    pub(super) fn units(&self, inch: bool) -> Units {
        Units {
            inch,
            dpi: self.params.bit(P3401, 0, 0),
        }
    }

    /// Where the program zero of axis slot `k` lies in the frame (M − SH): tool offset plus
    /// workpiece offset of `modal`'s system plus the G50 shift.
    pub(super) fn origin(&self, k: usize, modal: &Modal) -> i64 {
        self.tool_offset_along(k) + self.work_offset_of(k, modal.work) + self.auto.shift[k]
    }

    /// The end point of a block's axis words from `cur`.
    pub(super) fn end_point(
        &self,
        w: &Words,
        u: Units,
        modal: &Modal,
        cur: [i64; AXES],
    ) -> Result<[i64; AXES], u16> {
        let mut target = cur;
        for (k, word) in w.axes.iter().enumerate() {
            if let Some((v, inc)) = *word {
                let v = u.len(v)?;
                target[k] = if inc {
                    cur[k] + v
                } else {
                    v + self.origin(k, modal)
                };
            }
        }
        Ok(target)
    }

    /// Plans the block into `self.auto.segs` with the block's modal state (already updated by
    /// its G codes and F); returns what else it changes.
    pub(super) fn plan(&mut self, w: &Words, modal: &mut Modal) -> Result<Effects, u16> {
        let u = self.units(modal.inch);
        let cur = self.frame_position();
        let mut segs = std::mem::take(&mut self.auto.segs);
        segs.clear();
        let r = self.plan_into(w, modal, u, cur, &mut segs);
        self.auto.segs = segs;
        r
    }

    fn plan_into(
        &mut self,
        w: &Words,
        modal: &mut Modal,
        u: Units,
        cur: [i64; AXES],
        segs: &mut Vec<Segment>,
    ) -> Result<Effects, u16> {
        let mut fx = Effects::default();
        match w.one_shot {
            Some(OneShot::Dwell) => {
                segs.push(Segment::to(
                    SegKind::Dwell {
                        ms: self.dwell_ms(w, u),
                    },
                    cur,
                ));
                return Ok(fx);
            }
            Some(OneShot::Ref) | Some(OneShot::Ref2) => {
                // G28: point 1; G30: P2 (default), P3 or P4 (#1241–#1243).
                let point = match (w.one_shot, w.p) {
                    (Some(OneShot::Ref), _) => 1,
                    (_, None) => 2,
                    (_, Some(p @ 2..=4)) => p as u8,
                    _ => return Err(ps::ADDRESS),
                };
                let mid = self.end_point(w, u, modal, cur)?;
                segs.push(Segment::to(SegKind::Rapid, mid));
                let mut target = mid;
                let mut axes = 0u8;
                for (k, a) in w.axes.iter().enumerate() {
                    if a.is_some() {
                        axes |= 1 << k;
                        let p = P1240 + usize::from(point) - 1;
                        target[k] = self.params.get(p, k) - self.axes[k].sh;
                    }
                }
                let mut s = Segment::to(SegKind::Rapid, target);
                s.home = Home { axes, point };
                segs.push(s);
                return Ok(fx);
            }
            Some(OneShot::Machine) => {
                let mut target = cur;
                for (k, word) in w.axes.iter().enumerate() {
                    if let Some((v, false)) = *word {
                        target[k] = u.len(v)? - self.axes[k].sh;
                    }
                }
                segs.push(Segment::to(SegKind::Rapid, target));
                return Ok(fx);
            }
            Some(OneShot::Coord) => {
                if w.moves() {
                    let mut shift = self.auto.shift;
                    for (k, word) in w.axes.iter().enumerate() {
                        if let Some((v, inc)) = *word {
                            let v = u.len(v)?;
                            // The current point gets the coordinate written (U/W: moves the
                            // coordinate by that much).
                            let now = cur[k] - self.origin(k, modal);
                            let want = if inc { now + v } else { v };
                            shift[k] += now - want;
                        }
                    }
                    fx.shift = Some(shift);
                }
                return Ok(fx);
            }
            Some(OneShot::Data) => {
                self.check_g10(w, u)?;
                return Ok(fx);
            }
            Some(OneShot::Cycle(g)) => {
                return self.plan_repetitive(g, w, modal, u, cur, segs);
            }
            None => {}
        }
        // C and R in a G01 block are a chamfer and a corner R, as `,C` and `,R` (the form
        // without a comma); C means nothing elsewhere.
        let mut w = *w;
        if modal.motion == 1 && w.drill.is_none() {
            w.chamfer = w.chamfer.or(w.c);
            if w.i.is_none() && w.k.is_none() {
                w.corner = w.corner.or(w.r);
            }
        } else if w.c.is_some() {
            return Err(ps::ADDRESS);
        }
        let w = &w;
        let target = self.end_point(w, u, modal, cur)?;
        if matches!(modal.drill.g, 83..=89) {
            if w.moves() && modal.feed <= 0.0 {
                return Err(ps::NO_FEED);
            }
            self.plan_drill(w, modal, u, cur, target, segs)?;
            return Ok(fx);
        }
        match modal.motion {
            0 if w.moves() => segs.push(Segment::to(SegKind::Rapid, target)),
            1 if w.moves() && (w.chamfer.is_some() || w.corner.is_some()) => {
                self.plan_corner(w, modal, u, cur, target, segs)?;
            }
            _ if w.chamfer.is_some() || w.corner.is_some() => return Err(ps::CORNER_NEXT),
            1 if w.moves() => segs.push(Segment::cut(
                SegKind::Line,
                target,
                modal.feed,
                modal.per_rev,
            )),
            2 | 3 if w.moves() || w.i.is_some() || w.k.is_some() => {
                let kind = self.arc_kind(w, u, modal.motion == 2, cur, target)?;
                segs.push(Segment::cut(kind, target, modal.feed, modal.per_rev));
            }
            0..=3 => {}
            _ => self.plan_cycle(w, modal, u, cur, target, segs)?,
        }
        Ok(fx)
    }

    /// G04's time, ms: P an integer of ms, P with a point seconds, X/U seconds (read like a
    /// length without a point: under DPI = 0, `X1` is 1 ms).
    fn dwell_ms(&self, w: &Words, u: Units) -> f64 {
        match (w.p, w.dwell_s, w.dwell_x) {
            (Some(p), _, _) => f64::from(p),
            (None, Some(s), _) => (s * 1000.0).round(),
            (None, None, Some(x)) if x.decimal || u.dpi => (x.value * 1000.0).round(),
            (None, None, Some(x)) => x.value.round(),
            _ => 0.0,
        }
    }

    /// The segment of a G02/G03 from `cur` to `target`: its centre from R or from I/K
    /// (I radius-valued), checked against #3410.
    pub(super) fn arc_kind(
        &self,
        w: &Words,
        u: Units,
        cw: bool,
        cur: [i64; AXES],
        target: [i64; AXES],
    ) -> Result<SegKind, u16> {
        let tol = self.params.one(P3410) as f64 / 1000.0;
        let (start, end) = (self.plane_mm(cur), self.plane_mm(target));
        let len = |n: Option<Num>| n.map_or(Ok(0), |v| u.len(v));
        let (center, full) = match w.r {
            Some(r) if w.i.is_none() && w.k.is_none() => {
                let r = u.len(r)? as f64 / 1000.0;
                (center_from_radius(start, end, r, cw, tol)?, false)
            }
            _ if w.i.is_none() && w.k.is_none() => return Err(ps::NO_RADIUS),
            _ => {
                let (i, k) = (len(w.i)? as f64 / 1000.0, len(w.k)? as f64 / 1000.0);
                let c = [start[0] + k, start[1] + i];
                let a = ArcPath::new(start, end, c, cw, true);
                if tol > 0.0 && (a.r0 - a.r1).abs() > tol {
                    return Err(ps::ARC_RADIUS);
                }
                (c, true)
            }
        };
        let c = self.plane_incr(center, cur);
        Ok(SegKind::Arc {
            cw,
            center: [c[0], c[1]],
            full,
        })
    }

    /// Checks a G10 block (L2 workpiece offsets; L10/L11 or P tool offsets).
    fn check_g10(&self, w: &Words, u: Units) -> Result<(), u16> {
        let p = w.p.ok_or(PS_G10_P)?;
        match w.l {
            Some(2) if p <= 6 => {}
            Some(10 | 11) if (1..100).contains(&p) => {}
            None | Some(1) if (1..100).contains(&p) || (10_001..10_100).contains(&p) => {}
            _ => return Err(PS_G10_P),
        }
        for v in w.axes.iter().flatten() {
            u.len(v.0)?;
        }
        if let Some(r) = w.r {
            u.len(r)?;
        }
        Ok(())
    }

    /// Carries out a checked G10 block.
    pub(super) fn apply_g10(&mut self, w: &Words, inch: bool) {
        let u = self.units(inch);
        let Some(p) = w.p else { return };
        let get = |n: Option<Num>| n.and_then(|v| u.len(v).ok());
        if w.l == Some(2) {
            let sys = p as usize;
            for (k, word) in w.axes.iter().enumerate() {
                if let Some((v, inc)) = *word
                    && let Ok(v) = u.len(v)
                {
                    let slot = &mut self.work[sys][k];
                    *slot = if inc { *slot + v } else { v };
                }
            }
            return;
        }
        let (geometry, number) = match (w.l, p) {
            (Some(10), p) => (true, p),
            (Some(11), p) => (false, p),
            (_, p) if p > 10_000 => (true, p - 10_000),
            (_, p) => (false, p),
        };
        let o = &mut self.offsets[number as usize];
        let values = if geometry {
            &mut o.geometry
        } else {
            &mut o.wear
        };
        // X Z Y absolute, U W V incremental; R the nose radius.
        for (k, slot) in [(0, 0), (1, 1), (2, 3)] {
            if let Some((v, inc)) = w.axes[k]
                && let Ok(v) = u.len(v)
            {
                values[slot] = if inc { values[slot] + v } else { v };
            }
        }
        if let Some(r) = get(w.r) {
            values[2] = r;
        }
        if let Some(q) = w.q
            && (0.0..=9.0).contains(&q.value)
        {
            o.tip = q.value as i64;
        }
    }
}
