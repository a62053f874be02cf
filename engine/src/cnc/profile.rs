//! The finishing profile of a multiple repetitive cycle (docs/gcode.md, "Stock removal"): the
//! blocks from sequence number P to Q of the running program, read for their geometry only —
//! G00/G01/G02/G03 and X/Z/U/W/R/I/K; their F, S, T and M are for G70 and ignored here. The
//! result is a chain of lines and arcs in the Z–X plane, in mm with X as a radius.

use super::modal::Modal;
use super::path::{SegKind, Segment};
use super::program::find_sequence;
use super::ps;
use super::word::Words;
use super::{AXES, SimCnc};

/// A circle an element follows: centre (Z, X radius) in mm and direction.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) struct Circle {
    /// Centre, (Z, X radius), mm.
    pub center: [f64; 2],
    /// G02.
    pub cw: bool,
}

/// One element of a profile: a line or an arc from `from` to `to`, (Z, X radius) in mm.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) struct Elem {
    /// Start point.
    pub from: [f64; 2],
    /// End point.
    pub to: [f64; 2],
    /// The circle of an arc.
    pub arc: Option<Circle>,
}

impl Elem {
    /// The element moved by `d` (Z, X radius).
    pub fn shifted(&self, d: [f64; 2]) -> Elem {
        let add = |p: [f64; 2]| [p[0] + d[0], p[1] + d[1]];
        Elem {
            from: add(self.from),
            to: add(self.to),
            arc: self.arc.map(|c| Circle {
                center: add(c.center),
                cw: c.cw,
            }),
        }
    }
}

/// A finishing profile.
#[derive(Clone, Debug, Default)]
pub(super) struct Profile {
    /// The cycle's start point A, (Z, X radius) in mm.
    pub start: [f64; 2],
    /// The first point of the profile A′ (the end of block P).
    pub first: [f64; 2],
    /// Block P moves at rapid (G00), else at feed.
    pub first_rapid: bool,
    /// Block P names both axes: FANUC's type II (pockets allowed).
    pub type2: bool,
    /// The elements from A′ to the end point B.
    pub elems: Vec<Elem>,
    /// The block after Q when the profile directly follows the cycle's block: where the
    /// program goes on (FANUC skips the profile blocks it has just used).
    pub resume: Option<usize>,
}

/// P/S 0063: no block with the sequence number P (or Q), or Q before P.
pub(super) const NO_SEQUENCE: u16 = ps::NO_SEQUENCE;

impl SimCnc {
    /// (Z, X radius) in mm of a frame position.
    pub(super) fn plane_mm(&self, p: [i64; AXES]) -> [f64; 2] {
        [p[1] as f64 / self.per_mm(1), p[0] as f64 / self.per_mm(0)]
    }

    /// A frame position from (Z, X radius) in mm, the other axes from `base`.
    pub(super) fn plane_incr(&self, q: [f64; 2], base: [i64; AXES]) -> [i64; AXES] {
        let mut p = base;
        p[0] = (q[1] * self.per_mm(0)).round() as i64;
        p[1] = (q[0] * self.per_mm(1)).round() as i64;
        p
    }

    /// Increments per mm of radius on axis slot `n` (2000 on a diameter axis).
    fn per_mm(&self, n: usize) -> f64 {
        if self.diameter(n) { 2000.0 } else { 1000.0 }
    }

    /// Reads the profile from block P (`ns`) to block Q (`nf`) of the running program, starting
    /// from the cycle's start point `cur`.
    pub(super) fn read_profile(
        &self,
        ns: u32,
        nf: u32,
        modal: &Modal,
        cur: [i64; AXES],
    ) -> Result<Profile, u16> {
        let (prog, here) = self.running_program().ok_or(NO_SEQUENCE)?;
        let first = find_sequence(prog, ns, here + 1).ok_or(NO_SEQUENCE)?;
        let last = find_sequence(prog, nf, first).ok_or(NO_SEQUENCE)?;
        if last < first {
            return Err(NO_SEQUENCE);
        }
        let u = self.units(modal.inch);
        let mut m = *modal;
        let mut pos = cur;
        let mut profile = Profile {
            start: self.plane_mm(cur),
            resume: (first == here + 1).then_some(last + 1),
            ..Profile::default()
        };
        for (k, b) in prog.blocks[first..=last].iter().enumerate() {
            let w: Words = self.block_words(b)?;
            if w.one_shot.is_some() || w.drill.is_some() || w.motion.is_some_and(|g| g > 3) {
                return Err(ps::CYCLE_COMMAND);
            }
            if let Some(g) = w.motion {
                m.motion = g;
            }
            if k == 0 {
                if !matches!(w.motion, Some(0 | 1)) {
                    return Err(ps::CYCLE_FIRST_BLOCK);
                }
                profile.first_rapid = m.motion == 0;
                profile.type2 = w.axes[0].is_some() && w.axes[1].is_some();
            }
            let target = self.end_point(&w, u, &m, pos)?;
            let from = self.plane_mm(pos);
            let to = self.plane_mm(target);
            let arc = match m.motion {
                2 | 3 if target != pos || w.i.is_some() || w.k.is_some() => {
                    match self.arc_kind(&w, u, m.motion == 2, pos, target)? {
                        SegKind::Arc { cw, center, .. } => Some(Circle {
                            center: self.plane_mm(self.plane_point(center, pos)),
                            cw,
                        }),
                        _ => None,
                    }
                }
                _ => None,
            };
            if k == 0 {
                profile.first = to;
            } else if from != to {
                profile.elems.push(Elem { from, to, arc });
            }
            pos = target;
        }
        Ok(profile)
    }

    /// The cutting segment along a profile element, at `feed`.
    pub(super) fn elem_segment(
        &self,
        e: &Elem,
        cur: [i64; AXES],
        feed: f64,
        per_rev: bool,
    ) -> Segment {
        let kind = match e.arc {
            Some(c) => {
                let centre = self.plane_incr(c.center, cur);
                SegKind::Arc {
                    cw: c.cw,
                    center: [centre[0], centre[1]],
                    full: false,
                }
            }
            None => SegKind::Line,
        };
        Segment::cut(kind, self.plane_incr(e.to, cur), feed, per_rev)
    }

    /// A frame position with X and Z from an arc centre (X, Z) and the rest from `base`.
    fn plane_point(&self, xz: [i64; 2], base: [i64; AXES]) -> [i64; AXES] {
        let mut p = base;
        p[0] = xz[0];
        p[1] = xz[1];
        p
    }
}
