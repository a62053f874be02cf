//! The scan recorder: the last N ticks of PLC memory, so a monitor can scrub back through
//! virtual time and show the image as it was at the end of any recorded tick.
//!
//! # Design
//!
//! The recording is a queue of *segments*. A segment starts with a keyframe (a full copy of
//! the image at the end of its first tick) followed by the byte changes of each of its ticks.
//! A change is one `u32`: the byte offset (16 bits), the value before and the value after. Each
//! tick's changes are in increasing offset order (the image is compared front to back), so a
//! lookup of one byte in one tick is a binary search.
//!
//! - Recording compares the image with the previous one 256 bytes at a time and looks at the
//!   words of a block only when the block differs, so a quiet image costs one pass of wide
//!   compares. Buffers of segments that fall out of the window are reused, so once the window
//!   is full recording allocates only when a segment sees more changes than any before it.
//! - A segment is closed when it holds [`Recorder::new`]'s image length in changes (rebuilding a
//!   state then costs one keyframe copy plus at most about two images' worth of changes,
//!   whatever the activity) or when it spans an eighth of the capacity (at most 1024 ticks), so
//!   the window keeps at most that many ticks beyond the capacity and a quiet image costs about
//!   one keyframe per eighth of the window.
//! - The value before each change lets [`Recorder::last_change`] tell which bits changed
//!   without rebuilding anything; each segment also keeps a bitset of the bytes that changed
//!   in it, so looking for a byte skips the segments where it never changed.
//! - The oldest rebuildable tick is `newest − capacity + 1` (or the first tick recorded, if
//!   later). A segment is dropped only once the next one starts at or before that tick, so the
//!   segment holding the oldest tick, with its keyframe, always stays.
//!
//! Ticks are recorded consecutively. A call with any other tick than the newest + 1 (a power
//! cycle, a new program, a machine restarted at tick 0) starts a new recording whose base is
//! that call's image, exactly as after [`Recorder::clear`]: there is no state between the two
//! to rebuild.

use crate::vm::TICK_MS;
use std::collections::VecDeque;

/// Ticks recorded by default: the last 60 s of virtual time.
pub const DEFAULT_CAPACITY_TICKS: u64 = 60_000 / TICK_MS;

/// Most ticks one segment spans: bounds what is kept beyond the capacity.
const MAX_SEGMENT_TICKS: u64 = 1024;

/// Bytes of the image compared at once before looking at single words: with 256 the
/// optimiser unrolls the compare into wide XORs and one test per block, the fastest of the
/// sizes measured (64 to 1024) on a 10 KiB image.
const BLOCK: usize = 256;

/// One keyframe and the changes of the ticks after it.
#[derive(Debug, Default)]
struct Segment {
    /// The tick of the keyframe.
    start: u64,
    /// The image at the end of tick `start`.
    key: Vec<u8>,
    /// Changes, tick after tick: offset << 16 | before << 8 | after.
    changes: Vec<u32>,
    /// `ends[i]`: end in `changes` of tick `start + i` (the keyframe tick's own changes, from
    /// the tick before it, come first).
    ends: Vec<u32>,
    /// One bit per image byte: whether the byte changed in some tick of the segment.
    touched: Vec<u64>,
}

impl Segment {
    /// The last tick recorded in the segment.
    fn last(&self) -> u64 {
        self.start + self.ends.len() as u64 - 1
    }

    /// The changes of tick `t` (which the segment holds).
    fn tick(&self, t: u64) -> &[u32] {
        let i = (t - self.start) as usize;
        let from = if i == 0 { 0 } else { self.ends[i - 1] as usize };
        &self.changes[from..self.ends[i] as usize]
    }

    /// Whether byte `off` changed in some tick of the segment.
    fn touches(&self, off: usize) -> bool {
        self.touched[off / 64] >> (off % 64) & 1 == 1
    }

    /// Appends the changes from `prev` to `cur` (equal lengths, starting at image offset
    /// `base`) and makes `prev` a copy of `cur`: 8 bytes at a time, then the bytes left over.
    fn diff_words(&mut self, base: usize, cur: &[u8], prev: &mut [u8]) {
        let (cur_words, cur_rest) = cur.as_chunks::<8>();
        let (prev_words, prev_rest) = prev.as_chunks_mut::<8>();
        for (w, (c, p)) in cur_words.iter().zip(prev_words.iter_mut()).enumerate() {
            let (cw, pw) = (u64::from_le_bytes(*c), u64::from_le_bytes(*p));
            let mut x = cw ^ pw;
            if x == 0 {
                continue;
            }
            while x != 0 {
                let k = x.trailing_zeros() / 8;
                x &= !(0xFF << (k * 8));
                let at = base + w * 8 + k as usize;
                self.change(at, (pw >> (k * 8)) as u8, (cw >> (k * 8)) as u8);
            }
            *p = *c;
        }
        let base = base + cur_words.len() * 8;
        for (k, (c, p)) in cur_rest.iter().zip(prev_rest.iter_mut()).enumerate() {
            if c != p {
                self.change(base + k, *p, *c);
                *p = *c;
            }
        }
    }

    #[inline]
    fn change(&mut self, off: usize, before: u8, after: u8) {
        self.changes.push(entry(off, before, after));
        self.touched[off / 64] |= 1 << (off % 64);
    }

    fn heap_bytes(&self) -> usize {
        self.key.capacity()
            + self.changes.capacity() * 4
            + self.ends.capacity() * 4
            + self.touched.capacity() * 8
    }
}

/// Whether two blocks differ: the XOR of their 16-byte words, ORed together, with one test at
/// the end (an early exit per word would keep the optimiser from using wide registers).
#[inline]
fn differs(cur: &[u8; BLOCK], prev: &[u8; BLOCK]) -> bool {
    let (cur, _) = cur.as_chunks::<16>();
    let (prev, _) = prev.as_chunks::<16>();
    let mut acc = 0u128;
    for (c, p) in cur.iter().zip(prev) {
        acc |= u128::from_ne_bytes(*c) ^ u128::from_ne_bytes(*p);
    }
    acc != 0
}

/// The entry of one changed byte.
#[inline]
fn entry(off: usize, before: u8, after: u8) -> u32 {
    (off as u32) << 16 | u32::from(before) << 8 | u32::from(after)
}

#[inline]
fn entry_offset(e: u32) -> u32 {
    e >> 16
}

#[inline]
fn entry_before(e: u32) -> u8 {
    (e >> 8) as u8
}

#[inline]
fn entry_after(e: u32) -> u8 {
    e as u8
}

/// The change of byte `off` among one tick's changes (sorted by offset).
fn find(changes: &[u32], off: u32) -> Option<u32> {
    let i = changes.partition_point(|&e| entry_offset(e) < off);
    changes.get(i).copied().filter(|&e| entry_offset(e) == off)
}

/// A ring of the last ticks of a PLC memory image (see the module documentation).
#[derive(Debug)]
pub struct Recorder {
    image_len: usize,
    capacity: u64,
    /// Ticks a segment spans at most.
    span: u64,
    /// Changes after which a segment is closed.
    budget: usize,
    /// The image as of the newest tick.
    prev: Vec<u8>,
    segments: VecDeque<Segment>,
    /// Dropped segments, kept for their buffers.
    spare: Vec<Segment>,
    /// The first tick of the current recording.
    first: u64,
    /// The newest tick; `None` before the first record.
    newest: Option<u64>,
}

impl Recorder {
    /// A recorder of the first `image_len` bytes of an image (the layout size,
    /// [`crate::vm::Layout::size`]) over the last `capacity_ticks` ticks (at least 1;
    /// [`DEFAULT_CAPACITY_TICKS`] is 60 s).
    ///
    /// # Panics
    ///
    /// If `image_len` is over 64 KiB: a change stores its offset in 16 bits (the PLC image is
    /// 16 KiB, [`crate::vm::IMAGE_BYTES`]).
    pub fn new(image_len: usize, capacity_ticks: u64) -> Recorder {
        assert!(
            image_len <= 1 << 16,
            "a recorded image is at most 64 KiB, not {image_len} bytes"
        );
        let capacity = capacity_ticks.max(1);
        Recorder {
            image_len,
            capacity,
            span: (capacity / 8).clamp(1, MAX_SEGMENT_TICKS),
            budget: image_len.max(64),
            prev: vec![0; image_len],
            segments: VecDeque::new(),
            spare: Vec::new(),
            first: 0,
            newest: None,
        }
    }

    /// Records the image as of the end of `tick` (only its first `image_len` bytes; bytes past
    /// the end of a shorter image keep their last recorded value, 0 in a base). The first call,
    /// and any call whose tick is not the newest + 1, starts a new recording with this image as
    /// its base.
    pub fn record(&mut self, tick: u64, image: &[u8]) {
        if self.newest.and_then(|n| n.checked_add(1)) != Some(tick) {
            self.clear();
            let n = self.image_len.min(image.len());
            self.prev[..n].copy_from_slice(&image[..n]);
            self.prev[n..].fill(0);
            self.first = tick;
            self.newest = Some(tick);
            self.open(tick);
            self.segment_mut().ends.push(0);
            return;
        }
        let full = self.open_if_full(tick);
        self.diff(image);
        self.close_tick(tick, full);
    }

    /// Records the tick after the newest as the changes it made (offset, new value; in
    /// offset order), as the runner's journal gives them: no image to compare. A tick that
    /// does not follow the newest starts a new recording from the last image with these
    /// changes.
    pub fn record_changes(&mut self, tick: u64, changes: &[(u32, u8)]) {
        if self.newest.and_then(|n| n.checked_add(1)) != Some(tick) {
            let mut image = self.prev.clone();
            for &(off, v) in changes {
                if let Some(b) = image.get_mut(off as usize) {
                    *b = v;
                }
            }
            self.record(tick, &image);
            return;
        }
        let full = self.open_if_full(tick);
        let s = self.segments.back_mut().expect("a recording has a segment");
        for &(off, v) in changes {
            let at = off as usize;
            if let Some(before) = self.prev.get_mut(at)
                && *before != v
            {
                s.change(at, *before, v);
                *before = v;
            }
        }
        self.close_tick(tick, full);
    }

    /// Opens a new segment at `tick` when the current one is full; whether it did.
    fn open_if_full(&mut self, tick: u64) -> bool {
        let full = {
            let s = self.segments.back().expect("a recording has a segment");
            s.ends.len() as u64 >= self.span || s.changes.len() >= self.budget
        };
        if full {
            self.open(tick);
        }
        full
    }

    /// Ends `tick`'s changes (a new segment's keyframe is the image after them) and drops
    /// the segments the ring no longer covers.
    fn close_tick(&mut self, tick: u64, opened: bool) {
        let s = self.segments.back_mut().expect("a recording has a segment");
        if opened {
            s.key.extend_from_slice(&self.prev);
        }
        let end = s.changes.len() as u32;
        s.ends.push(end);
        self.newest = Some(tick);
        let oldest = self.oldest().expect("a tick was recorded");
        while self.segments.len() > 1 && self.segments[1].start <= oldest {
            let dropped = self.segments.pop_front().expect("more than one segment");
            self.spare.push(dropped);
        }
    }

    /// Starts a segment at `tick` with empty buffers (its keyframe still to be copied, except
    /// for the base of a recording, which is copied here).
    fn open(&mut self, tick: u64) {
        let mut s = self.spare.pop().unwrap_or_default();
        s.start = tick;
        s.key.clear();
        s.changes.clear();
        s.ends.clear();
        s.ends.reserve(self.span as usize);
        s.touched.clear();
        s.touched.resize(self.image_len.div_ceil(64), 0);
        if self.segments.is_empty() {
            s.key.extend_from_slice(&self.prev);
        }
        self.segments.push_back(s);
    }

    fn segment_mut(&mut self) -> &mut Segment {
        self.segments.back_mut().expect("a recording has a segment")
    }

    /// Appends the bytes where `image` differs from the previous image to the current
    /// segment, and makes `image` the previous one.
    fn diff(&mut self, image: &[u8]) {
        let n = self.image_len.min(image.len());
        let s = self.segments.back_mut().expect("a recording has a segment");
        let (cur_blocks, cur_tail) = image[..n].as_chunks::<BLOCK>();
        let (prev_blocks, prev_tail) = self.prev[..n].as_chunks_mut::<BLOCK>();
        for (b, (cur, prev)) in cur_blocks.iter().zip(prev_blocks.iter_mut()).enumerate() {
            if differs(cur, prev) {
                s.diff_words(b * BLOCK, cur, prev);
            }
        }
        s.diff_words(cur_blocks.len() * BLOCK, cur_tail, prev_tail);
    }

    /// The oldest tick whose state can be rebuilt; `None` when nothing is recorded.
    pub fn oldest(&self) -> Option<u64> {
        let newest = self.newest?;
        Some(self.first.max((newest + 1).saturating_sub(self.capacity)))
    }

    /// The newest recorded tick; `None` when nothing is recorded.
    pub fn newest(&self) -> Option<u64> {
        self.newest
    }

    /// Index of the segment holding `tick` (which must be in the window).
    fn segment_of(&self, tick: u64) -> usize {
        self.segments.partition_point(|s| s.start <= tick) - 1
    }

    /// The window `(oldest, newest)`, if anything is recorded.
    fn window(&self) -> Option<(u64, u64)> {
        Some((self.oldest()?, self.newest?))
    }

    /// Rebuilds the image as of the end of `tick` into `out` (resized to the image length);
    /// false, leaving `out` as it was, if the tick is not recorded.
    pub fn image_at(&self, tick: u64, out: &mut Vec<u8>) -> bool {
        let Some((oldest, newest)) = self.window() else {
            return false;
        };
        if tick < oldest || tick > newest {
            return false;
        }
        let s = &self.segments[self.segment_of(tick)];
        out.clear();
        out.extend_from_slice(&s.key);
        // The keyframe already holds the first tick's changes; apply the later ticks'.
        let from = s.ends[0] as usize;
        let to = s.ends[(tick - s.start) as usize] as usize;
        for &e in &s.changes[from..to] {
            out[entry_offset(e) as usize] = entry_after(e);
        }
        true
    }

    /// The latest tick `t` with oldest < t ≤ `at` at the end of which some bit of `mask` at byte
    /// `offset` had changed; `None` if there is none in the window. The oldest tick itself
    /// never counts: the state before it is not recorded.
    pub fn last_change(&self, at: u64, offset: u32, mask: u8) -> Option<u64> {
        let (oldest, newest) = self.window()?;
        let at = at.min(newest);
        if at <= oldest || offset as usize >= self.image_len || mask == 0 {
            return None;
        }
        for i in (0..=self.segment_of(at)).rev() {
            let s = &self.segments[i];
            if s.touches(offset as usize) {
                let low = s.start.max(oldest + 1);
                for t in (low..=at.min(s.last())).rev() {
                    if let Some(e) = find(s.tick(t), offset)
                        && (entry_before(e) ^ entry_after(e)) & mask != 0
                    {
                        return Some(t);
                    }
                }
            }
            if s.start <= oldest + 1 {
                break;
            }
        }
        None
    }

    /// Every recorded change of byte `offset` in ticks `from..=to`, oldest first, as (tick,
    /// value after the change), replacing what `out` held: the points of a trace over the
    /// window. Changes at the oldest tick are left out, as in [`Recorder::last_change`].
    pub fn changes_of(&self, offset: u32, from: u64, to: u64, out: &mut Vec<(u64, u8)>) {
        out.clear();
        let Some((oldest, newest)) = self.window() else {
            return;
        };
        let (from, to) = (from.max(oldest + 1), to.min(newest));
        if from > to || offset as usize >= self.image_len {
            return;
        }
        for s in self.segments.range(self.segment_of(from)..) {
            if s.start > to {
                break;
            }
            if !s.touches(offset as usize) {
                continue;
            }
            for t in from.max(s.start)..=to.min(s.last()) {
                if let Some(e) = find(s.tick(t), offset) {
                    out.push((t, entry_after(e)));
                }
            }
        }
    }

    /// Heap bytes held (buffer capacities, spare buffers included): the recording's memory.
    pub fn bytes_used(&self) -> usize {
        self.prev.capacity()
            + (self.segments.capacity() + self.spare.capacity()) * size_of::<Segment>()
            + self
                .segments
                .iter()
                .chain(&self.spare)
                .map(Segment::heap_bytes)
                .sum::<usize>()
    }

    /// Forgets every recorded tick; the buffers are kept for the next recording.
    pub fn clear(&mut self) {
        self.spare.extend(self.segments.drain(..));
        self.newest = None;
        self.first = 0;
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    /// A small deterministic generator for the images (xorshift64*).
    struct Rng(u64);

    impl Rng {
        fn next(&mut self) -> u64 {
            self.0 ^= self.0 >> 12;
            self.0 ^= self.0 << 25;
            self.0 ^= self.0 >> 27;
            self.0.wrapping_mul(0x2545_F491_4F6C_DD1D)
        }

        fn below(&mut self, n: usize) -> usize {
            (self.next() % n as u64) as usize
        }
    }

    /// The images of `ticks` ticks: mostly a few bytes changing, sometimes none, sometimes
    /// most of the image (a power-on, a table load), so segments close both ways.
    fn history(len: usize, ticks: usize, seed: u64) -> Vec<Vec<u8>> {
        let mut rng = Rng(seed | 1);
        let mut image: Vec<u8> = (0..len).map(|_| rng.next() as u8).collect();
        let mut out = Vec::with_capacity(ticks);
        for _ in 0..ticks {
            let changes = match rng.below(20) {
                0 => len,
                1..=4 => 0,
                _ => 1 + rng.below(4),
            };
            for _ in 0..changes {
                let i = rng.below(len);
                // Often a single bit, as a coil does.
                image[i] ^= if rng.below(2) == 0 {
                    1 << rng.below(8)
                } else {
                    rng.next() as u8
                };
            }
            out.push(image.clone());
        }
        out
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(24))]

        /// Fed the runner's journal (each tick's changes) instead of images, the recorder
        /// holds exactly the same history.
        #[test]
        fn recording_changes_is_recording_images(
            len in 1usize..200,
            capacity in 1u64..100,
            extra in 0usize..200,
            seed: u64,
        ) {
            let images = history(len, capacity as usize + extra, seed);
            let mut by_image = Recorder::new(len, capacity);
            let mut by_changes = Recorder::new(len, capacity);
            let mut journal = crate::runner::journal::Journaler::new(len);
            for (i, image) in images.iter().enumerate() {
                by_image.record(i as u64, image);
                journal.note(i as u64, image);
            }
            let mut out = crate::runner::journal::Journal::default();
            journal.hand_over(&mut out);
            let (t0, base) = out.base.clone().expect("a base");
            by_changes.record(t0, &base);
            for (t, changes) in out.each_tick() {
                by_changes.record_changes(t, changes);
            }
            prop_assert_eq!(by_image.oldest(), by_changes.oldest());
            prop_assert_eq!(by_image.newest(), by_changes.newest());
            let (mut a, mut b) = (Vec::new(), Vec::new());
            for t in by_image.oldest().unwrap()..=by_image.newest().unwrap() {
                prop_assert!(by_image.image_at(t, &mut a) && by_changes.image_at(t, &mut b));
                prop_assert_eq!(&a, &b, "tick {}", t);
            }
        }
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(48))]

        /// Scrubbing to any recorded tick shows exactly the image of that tick, and the change
        /// queries agree with the images, however far past the capacity recording went.
        #[test]
        fn every_recorded_tick_rebuilds_and_changes_match(
            len in 1usize..300,
            capacity in 1u64..150,
            extra in 0usize..400,
            first in 0u64..1000,
            seed: u64,
        ) {
            let ticks = capacity as usize + extra;
            let images = history(len, ticks, seed);
            let mut rec = Recorder::new(len, capacity);
            for (i, image) in images.iter().enumerate() {
                rec.record(first + i as u64, image);
            }
            let newest = first + ticks as u64 - 1;
            let oldest = first.max(newest + 1 - capacity.min(newest + 1));
            prop_assert_eq!(rec.newest(), Some(newest));
            prop_assert_eq!(rec.oldest(), Some(oldest));
            let at = |t: u64| &images[(t - first) as usize];
            let mut out = Vec::new();
            for t in oldest..=newest {
                prop_assert!(rec.image_at(t, &mut out), "tick {}", t);
                prop_assert_eq!(&out, at(t), "tick {}", t);
            }
            if oldest > 0 {
                prop_assert!(!rec.image_at(oldest - 1, &mut out));
            }
            prop_assert!(!rec.image_at(newest + 1, &mut out));

            let mut rng = Rng(seed ^ 0x9E37_79B9);
            let mut got = Vec::new();
            for _ in 0..20 {
                let off = rng.below(len);
                let mask = rng.next() as u8 | 1;
                let to = oldest + rng.below((newest - oldest + 1) as usize) as u64;
                let expected = (oldest + 1..=to)
                    .rev()
                    .find(|&t| (at(t)[off] ^ at(t - 1)[off]) & mask != 0);
                prop_assert_eq!(rec.last_change(to, off as u32, mask), expected);
                let from = oldest + rng.below((to - oldest + 1) as usize) as u64;
                let expected: Vec<(u64, u8)> = (from.max(oldest + 1)..=to)
                    .filter(|&t| at(t)[off] != at(t - 1)[off])
                    .map(|t| (t, at(t)[off]))
                    .collect();
                rec.changes_of(off as u32, from, to, &mut got);
                prop_assert_eq!(&got, &expected);
            }
        }
    }

    #[test]
    fn last_change_names_the_tick_a_bit_of_the_mask_changed() {
        let mut rec = Recorder::new(100, 1000);
        let mut image = vec![0u8; 100];
        for t in 0..=20u64 {
            match t {
                5 => image[10] |= 0x08,
                8 => image[10] |= 0x01,
                12 => image[11] = 0xFF,
                _ => {}
            }
            rec.record(t, &image);
        }
        assert_eq!(rec.last_change(20, 10, 0x08), Some(5));
        assert_eq!(rec.last_change(20, 10, 0x01), Some(8));
        assert_eq!(rec.last_change(20, 10, 0xFF), Some(8));
        assert_eq!(rec.last_change(7, 10, 0xFF), Some(5));
        assert_eq!(rec.last_change(4, 10, 0xFF), None);
        assert_eq!(
            rec.last_change(20, 10, 0xF0),
            None,
            "bits that never changed"
        );
        assert_eq!(rec.last_change(20, 11, 0x80), Some(12));
        assert_eq!(rec.last_change(20, 500, 0xFF), None, "past the image");
        let mut trace = Vec::new();
        rec.changes_of(10, 0, 20, &mut trace);
        assert_eq!(trace, [(5, 0x08), (8, 0x09)]);
        rec.changes_of(10, 6, 20, &mut trace);
        assert_eq!(trace, [(8, 0x09)]);
    }

    #[test]
    fn the_window_keeps_the_capacity_and_oldest_advances() {
        let mut rec = Recorder::new(64, 100);
        let mut image = vec![0u8; 64];
        let mut out = Vec::new();
        for t in 0..1000u64 {
            image[(t % 60) as usize] = t as u8;
            match t {
                900 => image[60] = 1,
                901 => image[61] = 1,
                _ => {}
            }
            rec.record(t, &image);
            assert_eq!(rec.oldest(), Some(t.saturating_sub(99)));
            assert_eq!(rec.newest(), Some(t));
        }
        assert!(!rec.image_at(899, &mut out), "older than the capacity");
        assert!(rec.image_at(900, &mut out));
        assert_eq!(out[(900 % 60) as usize], (900 % 256) as u8);
        assert_eq!(out[60], 1);
        // A change at the oldest tick is not reported, even if still held in memory: what the
        // byte was before it is no longer known.
        assert_eq!(rec.last_change(999, 60, 0xFF), None);
        assert_eq!(rec.last_change(999, 61, 0xFF), Some(901));
    }

    #[test]
    fn a_tick_out_of_sequence_or_clear_starts_a_new_recording() {
        let mut rec = Recorder::new(16, 100);
        let mut out = Vec::new();
        for t in 0..50u64 {
            rec.record(t, &[t as u8; 16]);
        }
        // A new program restarts the machine at tick 0.
        rec.record(0, &[7; 16]);
        assert_eq!((rec.oldest(), rec.newest()), (Some(0), Some(0)));
        assert!(rec.image_at(0, &mut out));
        assert_eq!(out, [7; 16]);
        rec.record(1, &[8; 16]);
        assert_eq!(rec.last_change(1, 0, 0xFF), Some(1));
        // A gap (ticks run unrecorded) restarts too: the state in between is unknown.
        rec.record(10, &[9; 16]);
        assert_eq!((rec.oldest(), rec.newest()), (Some(10), Some(10)));
        assert!(!rec.image_at(1, &mut out));
        rec.clear();
        assert_eq!((rec.oldest(), rec.newest()), (None, None));
        assert!(!rec.image_at(10, &mut out));
        assert_eq!(rec.last_change(10, 0, 0xFF), None);
        rec.record(11, &[1; 16]);
        assert_eq!((rec.oldest(), rec.newest()), (Some(11), Some(11)));
    }

    #[test]
    fn memory_stops_growing_once_the_window_is_full() {
        // The size of the GSK988TA image, the default 60 s, five bytes changing each tick.
        let len = 10_880;
        let capacity = DEFAULT_CAPACITY_TICKS;
        let mut rec = Recorder::new(len, capacity);
        let mut image = vec![0u8; len];
        let mut run = |rec: &mut Recorder, ticks: std::ops::Range<u64>| {
            for t in ticks {
                for k in 0..5u64 {
                    image[((t * 37 + k * 1999) % len as u64) as usize] ^= 1 << (t % 8);
                }
                rec.record(t, &image);
            }
        };
        run(&mut rec, 0..2 * capacity);
        let full = rec.bytes_used();
        run(&mut rec, 2 * capacity..6 * capacity);
        assert_eq!(rec.bytes_used(), full, "no growth once the window is full");
        // Five changes and a tick end per tick, about 9 keyframes: some 270 KB of data.
        assert!(full < 1_000_000, "{full} bytes for 60 s");
    }
}
