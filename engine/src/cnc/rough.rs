//! Stock removal (docs/gcode.md, "Stock removal"): G71 (along Z), G72 (along X) and G73
//! (pattern repeating) turned into segments. G71 and G72 share one algorithm in a plane
//! (u, v) where u is the cutting direction and v the depth: the profile is moved by the
//! finishing allowance, the stock above it is cut in levels Δd apart, each level from the start
//! point to the profile (and, in type II, into every pocket), and a last pass follows the
//! allowance profile.

use super::arc::ArcPath;
use super::path::{SegKind, Segment, room};
use super::profile::{Elem, Profile};
use super::ps;
use super::{AXES, SimCnc};

const EPS: f64 = 1e-6;

/// The (u, v) plane of a stock removal cycle.
#[derive(Clone, Copy, Debug)]
struct Plane {
    /// u is X (G72), else Z (G71).
    swap: bool,
    su: f64,
    sv: f64,
}

impl Plane {
    fn uv(&self, p: [f64; 2]) -> [f64; 2] {
        let (a, b) = if self.swap {
            (p[1], p[0])
        } else {
            (p[0], p[1])
        };
        [self.su * a, self.sv * b]
    }

    fn zx(&self, q: [f64; 2]) -> [f64; 2] {
        let (a, b) = (q[0] * self.su, q[1] * self.sv);
        if self.swap { [b, a] } else { [a, b] }
    }

    /// Whether an arc's sense is reversed in (u, v).
    fn flips(&self) -> bool {
        self.swap ^ (self.su * self.sv < 0.0)
    }
}

/// A profile element in (u, v).
#[derive(Clone, Copy, Debug)]
struct UvElem {
    from: [f64; 2],
    to: [f64; 2],
    arc: Option<ArcPath>,
}

impl UvElem {
    fn u_range(&self) -> (f64, f64) {
        (self.from[0].min(self.to[0]), self.from[0].max(self.to[0]))
    }

    /// v where the element crosses u (it is u-monotonic), if it spans u.
    fn v_at(&self, u: f64) -> Option<f64> {
        let (lo, hi) = self.u_range();
        if u < lo - EPS || u > hi + EPS {
            return None;
        }
        match &self.arc {
            None if (self.to[0] - self.from[0]).abs() < EPS => Some(self.from[1].min(self.to[1])),
            None => {
                let f = (u - self.from[0]) / (self.to[0] - self.from[0]);
                Some(self.from[1] + (self.to[1] - self.from[1]) * f)
            }
            Some(a) => {
                let r = (a.r0 + a.r1) / 2.0;
                let h = (r * r - (u - a.center[0]).powi(2)).max(0.0).sqrt();
                let mid = a.point(0.5);
                let side = if mid[1] >= a.center[1] { 1.0 } else { -1.0 };
                Some(a.center[1] + side * h)
            }
        }
    }

    /// The u where the element meets the level v.
    fn crossings(&self, v: f64, out: &mut Vec<f64>) {
        match &self.arc {
            None => {
                let (a, b) = (self.from, self.to);
                if (b[1] - a[1]).abs() > EPS {
                    let f = (v - a[1]) / (b[1] - a[1]);
                    if (-EPS..=1.0 + EPS).contains(&f) {
                        out.push(a[0] + (b[0] - a[0]) * f);
                    }
                }
            }
            Some(arc) => {
                let r = (arc.r0 + arc.r1) / 2.0;
                let d = r * r - (v - arc.center[1]).powi(2);
                if d >= 0.0 {
                    for s in [-1.0, 1.0] {
                        let u = arc.center[0] + s * d.sqrt();
                        let (lo, hi) = self.u_range();
                        if u >= lo - EPS
                            && u <= hi + EPS
                            && self.v_at(u).is_some_and(|x| (x - v).abs() < 1e-4)
                        {
                            out.push(u);
                        }
                    }
                }
            }
        }
    }

    /// Lowest v on the element.
    fn v_min(&self) -> f64 {
        let mut m = self.from[1].min(self.to[1]);
        if let Some(a) = &self.arc {
            for k in 0..=16 {
                m = m.min(a.point(f64::from(k) / 16.0)[1]);
            }
        }
        m
    }
}

/// Whether an arc's sweep passes the angle `t` strictly inside.
fn passes(a: &ArcPath, t: f64) -> bool {
    let tau = std::f64::consts::TAU;
    let (lo, hi) = if a.sweep >= 0.0 {
        (a.a0, a.a0 + a.sweep)
    } else {
        (a.a0 + a.sweep, a.a0)
    };
    (-2..=2).any(|k| {
        let x = t + f64::from(k) * tau;
        x > lo + 1e-9 && x < hi - 1e-9
    })
}

/// What a G71/G72 needs besides the profile.
#[derive(Clone, Copy, Debug)]
pub(super) struct Rough {
    /// 71 or 72.
    pub g: u8,
    /// Depth of cut Δd, mm (radius for G71).
    pub depth: f64,
    /// Retract e, mm.
    pub escape: f64,
    /// Finishing allowance (Z, X radius), mm.
    pub allowance: [f64; 2],
    /// Feed, mm/min or mm/rev.
    pub feed: f64,
    /// Per revolution.
    pub per_rev: bool,
}

impl SimCnc {
    /// G71 or G72: the segments of the whole cycle.
    pub(super) fn plan_rough(
        &self,
        p: &Profile,
        r: &Rough,
        cur: [i64; AXES],
        segs: &mut Vec<Segment>,
    ) -> Result<(), u16> {
        if r.depth <= 0.0 || r.escape < 0.0 {
            return Err(ps::CYCLE_VALUE);
        }
        let shifted: Vec<Elem> = p.elems.iter().map(|e| e.shifted(r.allowance)).collect();
        let first = [p.first[0] + r.allowance[0], p.first[1] + r.allowance[1]];
        let end = shifted.last().map_or(first, |e| e.to);
        let swap = r.g == 72;
        let raw = |q: [f64; 2]| if swap { [q[1], q[0]] } else { q };
        let sign = |d: f64| if d < 0.0 { -1.0 } else { 1.0 };
        let plane = Plane {
            swap,
            su: sign(raw(p.start)[0] - raw(end)[0]),
            sv: sign(raw(p.start)[1] - raw(first)[1]),
        };
        let elems = self.to_uv(&plane, &shifted)?;
        self.check_monotonic(&plane, &elems, p.type2)?;
        let s = plane.uv(p.start);
        let a1 = plane.uv(first);
        let v_min = elems.iter().map(UvElem::v_min).fold(a1[1], f64::min);
        let f = |u: f64| {
            if u > a1[0] + EPS {
                return a1[1];
            }
            elems
                .iter()
                .find_map(|e| e.v_at(u))
                .unwrap_or(f64::NEG_INFINITY)
        };
        let u_end = elems.last().map_or(a1[0], |e| e.to[0]);
        let mut out = Out {
            cnc: self,
            plane: &plane,
            cur,
            r,
            segs,
        };
        let mut v = s[1];
        let mut crossings = Vec::new();
        for _ in 0..10_000 {
            v -= r.depth;
            if v <= v_min + EPS {
                break;
            }
            room(out.segs)?;
            crossings.clear();
            crossings.push(s[0]);
            crossings.push(u_end);
            for e in &elems {
                e.crossings(v, &mut crossings);
            }
            crossings.retain(|&u| u <= s[0] + EPS && u >= u_end - EPS);
            crossings.sort_by(|a, b| b.total_cmp(a));
            crossings.dedup_by(|a, b| (*a - *b).abs() < 1e-6);
            let mut first_interval = true;
            for pair in crossings.windows(2) {
                let (hi, lo) = (pair[0], pair[1]);
                if f((hi + lo) / 2.0) >= v - EPS {
                    continue;
                }
                out.level_pass(s, hi, lo, v, first_interval && (hi - s[0]).abs() < EPS, p);
                first_interval = false;
            }
        }
        // The last pass along the allowance profile, then back to the start point.
        out.rapid([s[0], s[1]]);
        out.go(a1, p.first_rapid);
        for e in &shifted {
            out.follow(e);
        }
        let b = plane.uv(end);
        out.rapid([b[0], b[1].max(s[1])]);
        out.rapid(s);
        Ok(())
    }

    fn to_uv(&self, plane: &Plane, elems: &[Elem]) -> Result<Vec<UvElem>, u16> {
        Ok(elems
            .iter()
            .map(|e| UvElem {
                from: plane.uv(e.from),
                to: plane.uv(e.to),
                arc: e.arc.map(|c| {
                    let cw = c.cw ^ plane.flips();
                    ArcPath::new(
                        plane.uv(e.from),
                        plane.uv(e.to),
                        plane.uv(c.center),
                        cw,
                        false,
                    )
                }),
            })
            .collect())
    }

    /// The profile must go on in the cutting direction (and, in type I, in depth too).
    fn check_monotonic(&self, plane: &Plane, elems: &[UvElem], type2: bool) -> Result<(), u16> {
        // Z is the first axis of the plane: its alarm is 0064, X's 0329.
        let (u_alarm, v_alarm) = if plane.swap {
            (ps::NOT_MONOTONIC_X, ps::NOT_MONOTONIC_Z)
        } else {
            (ps::NOT_MONOTONIC_Z, ps::NOT_MONOTONIC_X)
        };
        let mut v_dir = 0.0;
        for e in elems {
            if e.to[0] > e.from[0] + 1e-4 {
                return Err(u_alarm);
            }
            if let Some(a) = &e.arc
                && (passes(a, 0.0) || passes(a, std::f64::consts::PI))
            {
                return Err(u_alarm);
            }
            if type2 {
                continue;
            }
            let dv = e.to[1] - e.from[1];
            let turns = e.arc.as_ref().is_some_and(|a| {
                passes(a, std::f64::consts::FRAC_PI_2) || passes(a, -std::f64::consts::FRAC_PI_2)
            });
            if turns || (dv.abs() > 1e-4 && v_dir * dv < 0.0) {
                return Err(v_alarm);
            }
            if dv.abs() > 1e-4 {
                v_dir = dv;
            }
        }
        Ok(())
    }
}

/// Builds a cycle's segments in (u, v).
struct Out<'a> {
    cnc: &'a SimCnc,
    plane: &'a Plane,
    cur: [i64; AXES],
    r: &'a Rough,
    segs: &'a mut Vec<Segment>,
}

impl Out<'_> {
    fn point(&self, q: [f64; 2]) -> [i64; AXES] {
        self.cnc.plane_incr(self.plane.zx(q), self.cur)
    }

    fn rapid(&mut self, q: [f64; 2]) {
        let t = self.point(q);
        self.segs.push(Segment::to(SegKind::Rapid, t));
    }

    fn feed(&mut self, q: [f64; 2]) {
        let t = self.point(q);
        self.segs
            .push(Segment::cut(SegKind::Line, t, self.r.feed, self.r.per_rev));
    }

    fn go(&mut self, q: [f64; 2], rapid: bool) {
        if rapid { self.rapid(q) } else { self.feed(q) }
    }

    /// Follows a profile element (real plane) at feed.
    fn follow(&mut self, e: &Elem) {
        let s = self
            .cnc
            .elem_segment(e, self.cur, self.r.feed, self.r.per_rev);
        self.segs.push(s);
    }

    /// One level: down to `v` at u = `hi`, cut to `lo`, retract at 45°, back up.
    fn level_pass(&mut self, s: [f64; 2], hi: f64, lo: f64, v: f64, open: bool, p: &Profile) {
        let e = self.r.escape;
        if open {
            // From the start side: straight down to the level, as block P moves.
            self.rapid([s[0], (v + self.r.depth + e).min(s[1])]);
            self.go([s[0], v], p.first_rapid);
        } else {
            // A pocket (type II): over the top at the start level, down, plunge at feed.
            self.rapid([s[0], s[1]]);
            self.rapid([hi, s[1]]);
            self.rapid([hi, (v + self.r.depth + e).min(s[1])]);
            self.feed([hi, v]);
        }
        self.feed([lo, v]);
        self.rapid([lo + e, v + e]);
        self.rapid([s[0], v + e]);
    }
}
