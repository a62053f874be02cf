//! The multiple repetitive cycles G70–G76 (docs/gcode.md, "Stock removal", "Grooving" and
//! "Compound threading"), in both FANUC 0i's two-block form and the one-block form of FS15
//! (and Haas), told apart by their words: a first block (no P/Q for G71–G73, no X/Z for
//! G74–G76) sets the cycle's parameters #5130–#5143 as FANUC does; a block with D, K or I/K
//! is the one-block form. Each cycle becomes segments from the block's start point.

use super::block::Effects;
use super::modal::Modal;
use super::params::{P5130, P5132, P5133, P5135, P5136, P5137, P5139, P5140, P5141, P5142, P5143};
use super::path::{SegKind, Segment, room};
use super::profile::Profile;
use super::program::find_sequence;
use super::ps;
use super::rough::Rough;
use super::word::{Num, Units, Words};
use super::{AXES, SimCnc};

impl SimCnc {
    /// A parameter of #5130–#5143 in mm (they hold 0.001 mm).
    fn param_mm(&self, i: usize) -> f64 {
        self.params.one(i) as f64 / 1000.0
    }

    /// Sets a cycle parameter as a first block does, refusing a value outside its range.
    fn set_cycle_param(&mut self, i: usize, value: i64) -> Result<(), u16> {
        let spec = &super::params::TABLE[i];
        if value < spec.min || value > spec.max {
            return Err(ps::CYCLE_VALUE);
        }
        self.params.set(i, 0, value);
        Ok(())
    }

    /// Plans G70–G76 (`g`).
    pub(super) fn plan_repetitive(
        &mut self,
        g: u8,
        w: &Words,
        modal: &Modal,
        u: Units,
        cur: [i64; AXES],
        segs: &mut Vec<Segment>,
    ) -> Result<Effects, u16> {
        let mut fx = Effects::default();
        let len = |n: Option<Num>| n.map_or(Ok(None), |v| u.len(v).map(Some));
        let axis = |k: usize| w.axes[k].map_or(Ok(None), |(v, _)| u.len(v).map(Some));
        let has_pq = w.p.is_some() && w.q.is_some();
        match g {
            70 => {
                if let Some(home) = self.auto.g70_return.take() {
                    segs.push(Segment::to(SegKind::Rapid, home));
                    return Ok(fx);
                }
                let (p, q) = self.sequence_words(w)?;
                let (prog, here) = self.running_program().ok_or(ps::NO_SEQUENCE)?;
                let first = find_sequence(prog, p, here + 1).ok_or(ps::NO_SEQUENCE)?;
                let last = find_sequence(prog, q, first).ok_or(ps::NO_SEQUENCE)?;
                if last < first {
                    return Err(ps::NO_SEQUENCE);
                }
                fx.g70 = Some((first, last, cur));
            }
            71 | 72 if !has_pq && w.p.is_none() && w.q.is_none() => {
                // First block: G71 U(depth) R(escape), G72 W(depth) R(escape).
                let depth = axis(if g == 71 { 0 } else { 1 })?;
                if let Some(d) = depth {
                    self.set_cycle_param(P5132, d)?;
                }
                if let Some(e) = len(w.r)? {
                    self.set_cycle_param(P5133, e)?;
                }
            }
            71 | 72 => {
                let (p, q) = self.sequence_words(w)?;
                let depth = match w.d {
                    Some(d) => u.fixed(d)? as f64 / 1000.0,
                    None => self.param_mm(P5132),
                };
                let profile = self.read_profile(p, q, modal, cur)?;
                let rough = Rough {
                    g,
                    depth,
                    escape: self.param_mm(P5133),
                    allowance: self.allowance(w, u)?,
                    feed: self.cycle_feed(modal)?,
                    per_rev: modal.per_rev,
                };
                self.plan_rough(&profile, &rough, cur, segs)?;
                fx.resume = profile.resume;
            }
            73 if w.p.is_none() && w.q.is_none() => {
                if let Some(i) = axis(0)? {
                    self.set_cycle_param(P5135, i)?;
                }
                if let Some(k) = axis(1)? {
                    self.set_cycle_param(P5136, k)?;
                }
                if let Some(r) = w.r {
                    self.set_cycle_param(P5137, r.value.round() as i64)?;
                }
            }
            73 => {
                let (p, q) = self.sequence_words(w)?;
                let relief = [
                    len(w.k)?.map_or(self.param_mm(P5136), |k| k as f64 / 1000.0),
                    len(w.i)?.map_or(self.param_mm(P5135), |i| i as f64 / 1000.0),
                ];
                let count = match w.d {
                    Some(d) => d.value.round() as i64,
                    None => self.params.one(P5137),
                };
                if count < 1 {
                    return Err(ps::CYCLE_VALUE);
                }
                let profile = self.read_profile(p, q, modal, cur)?;
                let allowance = self.allowance(w, u)?;
                let feed = self.cycle_feed(modal)?;
                self.plan_pattern(
                    &profile,
                    relief,
                    allowance,
                    count,
                    (feed, modal.per_rev),
                    cur,
                    segs,
                )?;
                fx.resume = profile.resume;
            }
            74 | 75 if !w.moves() => {
                if let Some(e) = len(w.r)? {
                    self.set_cycle_param(P5139, e)?;
                }
            }
            74 | 75 => self.plan_g74_block(g, w, modal, u, cur, segs)?,
            76 if !w.moves() => {
                if let Some(p) = w.p {
                    let (m, r, a) = (p / 10_000, p / 100 % 100, p % 100);
                    self.set_cycle_param(P5142, i64::from(m))?;
                    self.set_cycle_param(P5130, i64::from(r))?;
                    self.set_cycle_param(P5143, i64::from(a))?;
                }
                if let Some(q) = w.q {
                    self.set_cycle_param(P5140, u.fixed(q)?)?;
                }
                if let Some(r) = len(w.r)? {
                    self.set_cycle_param(P5141, r)?;
                }
            }
            _ => self.plan_g76_block(w, modal, u, cur, segs)?,
        }
        Ok(fx)
    }

    /// The second block of G74/G75 (or its one-block form).
    fn plan_g74_block(
        &self,
        g: u8,
        w: &Words,
        modal: &Modal,
        u: Units,
        cur: [i64; AXES],
        segs: &mut Vec<Segment>,
    ) -> Result<(), u16> {
        let target = self.end_point(w, u, modal, cur)?;
        let step_x = match (w.p, w.i) {
            (Some(p), _) => u.fixed(Num {
                value: f64::from(p),
                decimal: false,
            })?,
            (None, Some(i)) => u.fixed(i)?,
            _ => 0,
        };
        let step_z = match (w.q, w.k) {
            (Some(q), _) | (None, Some(q)) => u.fixed(q)?,
            _ => 0,
        };
        let relief = match (w.p.is_some() || w.q.is_some(), w.r, w.d) {
            (true, Some(r), _) => u.len(r)?,
            (_, _, Some(d)) => u.fixed(d)?,
            _ => 0,
        };
        let feed = self.cycle_feed(modal)?;
        let groove = Groove {
            along_x: g == 75,
            step: [step_z as f64 / 1000.0, step_x as f64 / 1000.0],
            relief: relief as f64 / 1000.0,
            escape: self.param_mm(P5139),
            feed: (feed, modal.per_rev),
        };
        self.plan_groove(&groove, cur, target, segs)?;
        Ok(())
    }

    /// The second block of G76, or its one-block form (told by K or D).
    fn plan_g76_block(
        &self,
        w: &Words,
        modal: &Modal,
        u: Units,
        cur: [i64; AXES],
        segs: &mut Vec<Segment>,
    ) -> Result<(), u16> {
        let len = |n: Option<Num>| n.map_or(Ok(None), |v| u.len(v).map(Some));
        let target = self.end_point(w, u, modal, cur)?;
        let one_block = w.k.is_some() || w.d.is_some();
        let fixed = |n: Option<Num>| n.map_or(Ok(0), |v| u.fixed(v));
        let (height, first, taper, angle) = if one_block {
            let angle = w.a.map_or(self.params.one(P5143) as f64, |a| a.value);
            (fixed(w.k)?, fixed(w.d)?, len(w.i)?.unwrap_or(0), angle)
        } else {
            let p = w.p.map(|p| Num {
                value: f64::from(p),
                decimal: false,
            });
            let angle = self.params.one(P5143) as f64;
            (fixed(p)?, fixed(w.q)?, len(w.r)?.unwrap_or(0), angle)
        };
        if modal.feed <= 0.0 {
            return Err(ps::NO_FEED);
        }
        let t = Thread76 {
            height: height as f64 / 1000.0,
            first: first as f64 / 1000.0,
            taper: taper as f64 / 1000.0,
            angle,
            lead: modal.feed,
            min_step: self.param_mm(P5140),
            finish: self.param_mm(P5141),
            finish_passes: self.params.one(P5142),
        };
        self.plan_thread76(&t, cur, target, segs)?;
        Ok(())
    }

    /// P and Q of G70–G73 as sequence numbers.
    fn sequence_words(&self, w: &Words) -> Result<(u32, u32), u16> {
        let q =
            w.q.filter(|q| !q.decimal && q.value >= 1.0 && q.value <= 99_999.0);
        match (w.p, q) {
            (Some(p), Some(q)) => Ok((p, q.value as u32)),
            _ => Err(ps::CYCLE_PQ),
        }
    }

    /// The finishing allowance U (X, diameter as written) and W: (Z, X radius) in mm.
    fn allowance(&self, w: &Words, u: Units) -> Result<[f64; 2], u16> {
        let get = |k: usize| w.axes[k].map_or(Ok(0), |(v, _)| u.len(v));
        let mut d = [0; AXES];
        (d[0], d[1]) = (get(0)?, get(1)?);
        Ok(self.plane_mm(d))
    }

    fn cycle_feed(&self, modal: &Modal) -> Result<f64, u16> {
        if modal.feed <= 0.0 {
            Err(ps::NO_FEED)
        } else {
            Ok(modal.feed)
        }
    }

    /// G73: the profile moved by allowance plus relief × (n − k)/(n − 1), k = 1…n.
    #[allow(clippy::too_many_arguments)]
    fn plan_pattern(
        &self,
        p: &Profile,
        relief: [f64; 2],
        allowance: [f64; 2],
        count: i64,
        (feed, per_rev): (f64, bool),
        cur: [i64; AXES],
        segs: &mut Vec<Segment>,
    ) -> Result<(), u16> {
        let start = self.plane_incr(p.start, cur);
        for k in 1..=count {
            room(segs)?;
            let f = if count > 1 {
                (count - k) as f64 / (count - 1) as f64
            } else {
                0.0
            };
            let d = [allowance[0] + relief[0] * f, allowance[1] + relief[1] * f];
            let first = self.plane_incr([p.first[0] + d[0], p.first[1] + d[1]], cur);
            let kind = if p.first_rapid {
                SegKind::Rapid
            } else {
                SegKind::Line
            };
            segs.push(Segment::cut(kind, first, feed, per_rev));
            for e in &p.elems {
                segs.push(self.elem_segment(&e.shifted(d), cur, feed, per_rev));
            }
            segs.push(Segment::to(SegKind::Rapid, start));
        }
        Ok(())
    }
}

/// What G74 or G75 needs.
struct Groove {
    /// G75: pecks along X, steps along Z.
    along_x: bool,
    /// Step between grooves / peck depth: (Z, X radius) in mm.
    step: [f64; 2],
    /// Relief at the bottom, mm.
    relief: f64,
    /// Return after each peck (#5139), mm.
    escape: f64,
    feed: (f64, bool),
}

/// What G76 needs, in mm (radius).
struct Thread76 {
    height: f64,
    first: f64,
    taper: f64,
    angle: f64,
    lead: f64,
    min_step: f64,
    finish: f64,
    finish_passes: i64,
}

impl SimCnc {
    /// G74 (pecks along Z, grooves stepped along X) or G75 (the reverse).
    fn plan_groove(
        &self,
        g: &Groove,
        cur: [i64; AXES],
        target: [i64; AXES],
        segs: &mut Vec<Segment>,
    ) -> Result<(), u16> {
        // Work in (peck axis, step axis), mm: for G74 (Z, X radius), for G75 (X radius, Z).
        let s = self.plane_mm(cur);
        let t = self.plane_mm(target);
        let (pk, st) = if g.along_x { (1, 0) } else { (0, 1) };
        let depth_total = (t[pk] - s[pk]).abs();
        let dir_p = (t[pk] - s[pk]).signum();
        let span = (t[st] - s[st]).abs();
        let dir_s = (t[st] - s[st]).signum();
        let peck = if g.step[pk] > 0.0 {
            g.step[pk]
        } else {
            depth_total
        };
        let step = g.step[st];
        if depth_total > 0.0 && peck <= 0.0 || (span > 1e-9 && step <= 0.0) {
            return Err(ps::CYCLE_VALUE);
        }
        let at = |p: f64, q: f64| {
            let mut v = [0.0; 2];
            v[pk] = p;
            v[st] = q;
            self.plane_incr(v, cur)
        };
        let (feed, per_rev) = g.feed;
        let mut offset: f64 = 0.0;
        for _ in 0..100_000 {
            let q = s[st] + dir_s * offset.min(span);
            segs.push(Segment::to(SegKind::Rapid, at(s[pk], q)));
            let mut done = 0.0;
            while done < depth_total - 1e-9 {
                room(segs)?;
                let next = (done + peck).min(depth_total);
                segs.push(Segment::cut(
                    SegKind::Line,
                    at(s[pk] + dir_p * next, q),
                    feed,
                    per_rev,
                ));
                done = next;
                if done < depth_total - 1e-9 {
                    let back = (done - g.escape).max(0.0);
                    segs.push(Segment::to(SegKind::Rapid, at(s[pk] + dir_p * back, q)));
                }
            }
            let relief = if offset > 0.0 { g.relief } else { 0.0 };
            let q_out = q - dir_s * relief;
            segs.push(Segment::to(
                SegKind::Rapid,
                at(s[pk] + dir_p * depth_total, q_out),
            ));
            segs.push(Segment::to(SegKind::Rapid, at(s[pk], q_out)));
            if offset >= span - 1e-9 {
                break;
            }
            offset += step;
        }
        segs.push(Segment::to(SegKind::Rapid, cur));
        Ok(())
    }

    /// G76: passes of decreasing depth along the flank, then the finishing passes.
    fn plan_thread76(
        &self,
        t: &Thread76,
        cur: [i64; AXES],
        target: [i64; AXES],
        segs: &mut Vec<Segment>,
    ) -> Result<(), u16> {
        if t.height <= 0.0 || t.first <= 0.0 {
            return Err(ps::CYCLE_VALUE);
        }
        let s = self.plane_mm(cur);
        let e = self.plane_mm(target);
        let out = if s[1] >= e[1] { 1.0 } else { -1.0 };
        let dir_z = (e[0] - s[0]).signum();
        let flank = (t.angle.to_radians() / 2.0).tan();
        for depth in thread_depths(t) {
            let left = t.height - depth;
            let z0 = s[0] + dir_z * (depth - t.first.min(depth)) * flank;
            let from = self.plane_incr([z0, e[1] + t.taper + out * left], cur);
            let to = self.plane_incr([e[0], e[1] + out * left], cur);
            let mut p = cur;
            p[1] = from[1];
            segs.push(Segment::to(SegKind::Rapid, p));
            segs.push(Segment::to(SegKind::Rapid, from));
            self.thread_with_chamfer(from, to, cur[0], t.lead, segs);
            segs.push(Segment::to(SegKind::Rapid, cur));
        }
        Ok(())
    }
}

/// The depths (radius, mm) of G76's passes: first · √n, each at least the minimum step more
/// than the last, up to height − allowance; then the finishing passes at the full height.
fn thread_depths(t: &Thread76) -> Vec<f64> {
    let rough_end = (t.height - t.finish).max(0.0);
    let mut depths = Vec::new();
    let mut last = 0.0;
    for n in 1..10_000 {
        if last >= rough_end - 1e-9 {
            break;
        }
        let mut d = t.first * f64::from(n).sqrt();
        if d - last < t.min_step {
            d = last + t.min_step.max(1e-3);
        }
        d = d.min(rough_end);
        depths.push(d);
        last = d;
    }
    for _ in 0..t.finish_passes.max(1) {
        depths.push(t.height);
    }
    depths
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn thread_depths_grow_with_the_square_root_and_keep_the_minimum_step() {
        let t = Thread76 {
            height: 0.975,
            first: 0.4,
            taper: 0.0,
            angle: 60.0,
            lead: 1.5,
            min_step: 0.1,
            finish: 0.05,
            finish_passes: 1,
        };
        let d = thread_depths(&t);
        // 0.4·√n for n = 1…4; √5 · 0.4 = 0.894 is less than 0.1 deeper than 0.8, so 0.9; then
        // the rough end 0.975 − 0.05, and one finishing pass at the full height.
        let want = [
            0.4,
            0.4 * 2f64.sqrt(),
            0.4 * 3f64.sqrt(),
            0.8,
            0.9,
            0.925,
            0.975,
        ];
        assert_eq!(d.len(), want.len(), "{d:?}");
        for (a, b) in d.iter().zip(want) {
            assert!((a - b).abs() < 1e-12, "{d:?}");
        }
    }
}
