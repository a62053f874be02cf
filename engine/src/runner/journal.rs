//! What changed in memory at each tick, kept on the machine thread between two publications
//! and handed over with them, so the editor's scan recorder is fed without a lock the machine
//! thread would wait on. The first tick after a start (or after the editor fell behind by
//! more than the journal holds) carries the whole image as a base.

/// Ticks of changes the published journal holds at most: an editor that falls further
/// behind (no frames drawn) gets a fresh base instead, its recording restarting there.
pub const MAX_TICKS: usize = 7_500;

/// Ticks the machine thread gathers before it hands them over without waiting for a
/// publication (a quiet image at full speed publishes rarely).
pub const HAND_OVER_TICKS: usize = 1_024;

/// Memory changes tick by tick.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Journal {
    /// A whole image and its tick, from which the ticks below follow.
    pub base: Option<(u64, Vec<u8>)>,
    /// Each tick and the end (exclusive) of its changes in `changes`.
    pub ticks: Vec<(u64, u32)>,
    /// Changed bytes: offset and new value, in offset order within a tick.
    pub changes: Vec<(u32, u8)>,
}

impl Journal {
    /// Whether nothing is in it.
    pub fn is_empty(&self) -> bool {
        self.base.is_none() && self.ticks.is_empty()
    }

    /// The changes of each tick, in order.
    pub fn each_tick(&self) -> impl Iterator<Item = (u64, &[(u32, u8)])> {
        let mut from = 0usize;
        self.ticks.iter().map(move |&(t, end)| {
            let c = &self.changes[from..end as usize];
            from = end as usize;
            (t, c)
        })
    }
}

/// The machine thread's side: the image as of the last tick noted, and the journal being
/// filled.
#[derive(Debug, Default)]
pub struct Journaler {
    prev: Vec<u8>,
    size: usize,
    out: Journal,
    /// The last tick noted.
    last: u64,
}

impl Journaler {
    /// Journals the first `size` bytes of the image.
    pub fn new(size: usize) -> Journaler {
        Journaler {
            prev: Vec::new(),
            size,
            out: Journal::default(),
            last: 0,
        }
    }

    /// Notes the image as of the end of `tick`.
    pub fn note(&mut self, tick: u64, image: &[u8]) {
        let image = &image[..self.size.min(image.len())];
        self.last = tick;
        if self.prev.len() != image.len() {
            self.prev.clear();
            self.prev.extend_from_slice(image);
            self.out.ticks.clear();
            self.out.changes.clear();
            self.out.base = Some((tick, self.prev.clone()));
            return;
        }
        for (i, (p, c)) in self.prev.iter_mut().zip(image).enumerate() {
            if p != c {
                *p = *c;
                self.out.changes.push((i as u32, *c));
            }
        }
        self.out.ticks.push((tick, self.out.changes.len() as u32));
    }

    /// Ticks noted and not handed over yet.
    pub fn pending(&self) -> usize {
        self.out.ticks.len()
    }

    /// Moves what was noted into `into` (appending), leaving this journal empty. When `into`
    /// would hold more than [`MAX_TICKS`] (the editor has not taken it for that long), it is
    /// replaced by a base of the image as of the last tick noted.
    pub fn hand_over(&mut self, into: &mut Journal) {
        if into.ticks.len() + self.out.ticks.len() > MAX_TICKS {
            self.out.base = Some((self.last, self.prev.clone()));
            self.out.ticks.clear();
            self.out.changes.clear();
        }
        if let Some(base) = self.out.base.take() {
            // A new base makes whatever the editor had not taken yet irrelevant.
            into.base = Some(base);
            into.ticks.clear();
            into.changes.clear();
        }
        let offset = into.changes.len() as u32;
        into.ticks
            .extend(self.out.ticks.drain(..).map(|(t, end)| (t, end + offset)));
        into.changes.append(&mut self.out.changes);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_first_tick_is_a_base_and_the_next_ones_their_changes() {
        let mut j = Journaler::new(4);
        j.note(1, &[0, 0, 0, 0, 9]);
        j.note(2, &[0, 5, 0, 0, 9]);
        j.note(3, &[0, 5, 0, 0, 9]);
        j.note(4, &[7, 5, 0, 1, 9]);
        let mut out = Journal::default();
        j.hand_over(&mut out);
        assert_eq!(out.base, Some((1, vec![0, 0, 0, 0])));
        let ticks: Vec<_> = out.each_tick().map(|(t, c)| (t, c.to_vec())).collect();
        assert_eq!(
            ticks,
            [(2, vec![(1, 5)]), (3, vec![]), (4, vec![(0, 7), (3, 1)])]
        );
        // Handed over twice before the editor took it: appended.
        j.note(5, &[7, 6, 0, 1]);
        j.hand_over(&mut out);
        assert_eq!(out.each_tick().last().unwrap(), (5, &[(1, 6)][..]));
        assert!(!out.is_empty());
    }

    #[test]
    fn an_editor_that_takes_nothing_for_long_gets_a_base_not_an_endless_journal() {
        let mut j = Journaler::new(2);
        let mut out = Journal::default();
        j.note(0, &[0, 0]);
        for t in 1..=(MAX_TICKS as u64 + 10) {
            j.note(t, &[t as u8, 1]);
            if j.pending() >= HAND_OVER_TICKS {
                j.hand_over(&mut out);
            }
        }
        j.hand_over(&mut out);
        assert!(out.ticks.len() <= MAX_TICKS, "{}", out.ticks.len());
        let (t, image) = out.base.clone().expect("a fresh base");
        assert!(t > 0, "the base is a recent tick");
        assert_eq!(image[1], 1);
        // What follows the base carries on from it.
        let last = out.each_tick().last().map_or(t, |(t, _)| t);
        assert_eq!(last, MAX_TICKS as u64 + 10);
    }
}
