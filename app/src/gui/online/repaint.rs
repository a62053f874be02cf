//! Which of the machine's states are worth a frame. The machine thread publishes whenever its
//! memory or CNC moved — on a running lathe that is every tick — but most of that is off
//! screen. The UI tells the [`Gate`] each frame what it shows (memory bytes, the CNC screen,
//! the devices, or everything for a moving chart); the machine thread asks the gate about
//! each published state and only a change on screen asks for a frame within 33 ms (at most
//! 30 a second). Anything else — the clock, off-screen memory — asks for one within 500 ms,
//! so the toolbar's clock still moves twice a second and nothing is missed for long.

use ladder_engine::machine::Snapshot;
use std::sync::Mutex;
use std::sync::atomic::{AtomicU64, Ordering};
use std::time::Duration;

/// The soonest a change on screen is painted: 30 frames a second at most.
pub const VISIBLE: Duration = Duration::from_millis(33);
/// The soonest anything else is painted: twice a second.
pub const IDLE: Duration = Duration::from_millis(500);

/// What the screen shows of the machine.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Shown {
    /// Memory bytes on screen and the bits of each that are (0xFF: the byte's value).
    pub bytes: Vec<(u32, u8)>,
    /// The CNC screen is open.
    pub cnc: bool,
    /// The devices' states are on screen.
    pub devices: bool,
    /// Something on screen moves with every tick (the trace's time axis, a value window).
    pub everything: bool,
}

/// What the last frame showed, and what it was painted from.
#[derive(Default)]
struct Seen {
    shown: Shown,
    values: Vec<u8>,
    trace: Vec<u8>,
    forces: Vec<(u32, u8, u8)>,
    running: bool,
    halted: bool,
    cnc: Option<ladder_engine::cnc::CncStatus>,
    devices: Vec<ladder_engine::devices::DeviceStatus>,
    /// When the frame asked for last will be painted (a later ask before then adds none).
    due: Option<std::time::Instant>,
}

/// Shared by the UI (which says what it shows) and the machine thread (which asks).
#[derive(Default)]
pub struct Gate {
    seen: Mutex<Seen>,
    visible: AtomicU64,
    idle: AtomicU64,
    frames: AtomicU64,
}

impl Gate {
    /// The UI, each frame: what it shows now.
    pub fn show(&self, shown: Shown) {
        let mut seen = self.seen.lock().unwrap_or_else(|e| e.into_inner());
        if seen.shown != shown {
            seen.shown = shown;
            // Compared afresh: the next state is judged against nothing stale.
            seen.values.clear();
        }
    }

    /// The machine thread, for each published state: how soon a frame is wanted.
    pub fn judge(&self, s: &Snapshot) -> Duration {
        let mut seen = self.seen.lock().unwrap_or_else(|e| e.into_inner());
        let seen = &mut *seen;
        let mut changed = seen.shown.everything
            || s.trace != seen.trace
            || s.forces != seen.forces
            || s.running != seen.running
            || s.halt.is_some() != seen.halted;
        if seen.shown.cnc && s.cnc != seen.cnc {
            changed = true;
            seen.cnc.clone_from(&s.cnc);
        }
        if seen.shown.devices && s.devices != seen.devices {
            changed = true;
            seen.devices.clone_from(&s.devices);
        }
        let values = seen
            .shown
            .bytes
            .iter()
            .map(|&(off, mask)| s.memory.get(off as usize).map_or(0, |b| b & mask));
        if !values.clone().eq(seen.values.iter().copied()) {
            changed = true;
            seen.values.clear();
            seen.values.extend(values);
        }
        seen.trace.clone_from(&s.trace);
        seen.forces.clone_from(&s.forces);
        seen.running = s.running;
        seen.halted = s.halt.is_some();
        let soon = if changed {
            self.visible.fetch_add(1, Ordering::Relaxed);
            VISIBLE
        } else {
            self.idle.fetch_add(1, Ordering::Relaxed);
            IDLE
        };
        // The frames these asks cost, counted as the UI's event loop pays them: asks before
        // a frame already due only bring it forward.
        let now = std::time::Instant::now();
        match seen.due {
            Some(due) if due > now => seen.due = Some(due.min(now + soon)),
            _ => {
                seen.due = Some(now + soon);
                self.frames.fetch_add(1, Ordering::Relaxed);
            }
        }
        soon
    }

    /// Frames the machine's states have asked for so far.
    pub fn frames(&self) -> u64 {
        self.frames.load(Ordering::Relaxed)
    }

    /// States judged so far: (on screen, off screen).
    pub fn counts(&self) -> (u64, u64) {
        (
            self.visible.load(Ordering::Relaxed),
            self.idle.load(Ordering::Relaxed),
        )
    }
}

impl super::OnlineState {
    /// Tells the gate what this frame showed of the machine.
    pub(crate) fn publish_shown(&mut self, cx: &crate::gui::context::Context<'_>) {
        let Some(s) = self.session.as_ref() else {
            return;
        };
        let layout = &s.running.layout;
        let mut addresses: Vec<ladder_engine::Address> = std::mem::take(&mut self.ladder_shown);
        let mut shown = Shown::default();
        if cx.settings.show_online {
            match self.tab {
                super::OnlineTab::Panel => {
                    for item in self.panel(cx).items {
                        addresses.extend(item.kind.input());
                        addresses.extend(item.kind.lamp());
                    }
                    shown.devices = true;
                }
                super::OnlineTab::Cnc => shown.cnc = true,
                super::OnlineTab::Machine => shown.devices = true,
                super::OnlineTab::Trace => shown.everything = true,
                super::OnlineTab::Alarms => {
                    let a = layout.area_range(ladder_engine::Area::A);
                    shown
                        .bytes
                        .extend((a.start as u32..a.end as u32).map(|o| (o, 0xFF)));
                    shown.cnc = true;
                }
                super::OnlineTab::Signals => {
                    let p = &self.signals;
                    let bytes = u32::from(p.area.element_bytes());
                    let (lo, hi) = cx
                        .doc()
                        .map_or((0, 0), |d| d.project().profile().range(p.area));
                    let from = p.from.clamp(lo, hi);
                    let to = p.to.clamp(lo, hi).max(from);
                    let first = ladder_engine::Address::byte(p.area, from);
                    let start = layout.loc(first, false).off;
                    let n = u32::from(to - from) + 1;
                    shown
                        .bytes
                        .extend((start..start + n * bytes).map(|o| (o, 0xFF)));
                }
                super::OnlineTab::Watch | super::OnlineTab::Forces => {
                    if let Some(doc) = cx.doc() {
                        for r in self.watch_rows(cx) {
                            if let Ok(t) = super::watch::resolve(doc.project(), &r.text) {
                                // A bit row watches its bit only.
                                let loc = layout.loc(t.address, false);
                                let n = t.bytes.max(1);
                                match t.address.bit {
                                    Some(b) => shown.bytes.push((loc.off, 1 << b)),
                                    None => shown
                                        .bytes
                                        .extend((loc.off..loc.off + n).map(|o| (o, 0xFF))),
                                }
                            }
                        }
                    }
                    shown.cnc = true;
                }
            }
        }
        shown.everything |= self.values.at.is_some();
        for a in addresses.drain(..) {
            let loc = layout.loc(a, false);
            match a.bit {
                Some(b) => shown.bytes.push((loc.off, 1 << b)),
                None => {
                    let n = if loc.wide { 4 } else { 1 };
                    shown
                        .bytes
                        .extend((loc.off..loc.off + n).map(|o| (o, 0xFF)));
                }
            }
        }
        self.ladder_shown = addresses;
        shown.bytes.sort_unstable();
        shown.bytes.dedup();
        self.gate.show(shown);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn state(memory: &[u8]) -> Snapshot {
        Snapshot {
            memory: memory.to_vec(),
            running: true,
            ..Default::default()
        }
    }

    #[test]
    fn only_a_change_on_screen_asks_for_a_quick_frame() {
        let gate = Gate::default();
        gate.show(Shown {
            bytes: vec![(1, 0b0000_0100)],
            ..Default::default()
        });
        assert_eq!(
            gate.judge(&state(&[0, 0, 0])),
            VISIBLE,
            "the first state is new"
        );
        assert_eq!(
            gate.judge(&state(&[9, 0, 7])),
            IDLE,
            "bytes off screen moved"
        );
        assert_eq!(
            gate.judge(&state(&[9, 0b11, 7])),
            IDLE,
            "bits off screen moved"
        );
        assert_eq!(
            gate.judge(&state(&[9, 0b100, 7])),
            VISIBLE,
            "the shown bit moved"
        );
        let mut s = state(&[9, 0b100, 7]);
        s.ticks = 500;
        s.now_ms = 4000;
        assert_eq!(
            gate.judge(&s),
            IDLE,
            "the clock alone is not worth 30 frames"
        );
        s.forces = vec![(0, 1, 1)];
        assert_eq!(gate.judge(&s), VISIBLE, "a force is always on screen");
        assert_eq!(gate.counts(), (3, 3));
    }

    #[test]
    fn the_cnc_screen_counts_only_while_open() {
        let gate = Gate::default();
        let mut s = state(&[0]);
        gate.judge(&s);
        s.cnc = Some(Default::default());
        assert_eq!(gate.judge(&s), IDLE);
        gate.show(Shown {
            cnc: true,
            ..Default::default()
        });
        s.cnc = Some(ladder_engine::cnc::CncStatus {
            line: Some(3),
            ..Default::default()
        });
        assert_eq!(gate.judge(&s), VISIBLE);
    }
}
