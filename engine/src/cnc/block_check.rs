//! The checks of a block that depend on the machine (docs/cnc.md, "Program errors"): an
//! axis the CNC does not have, no feed, the program an M98/M97 calls and how deep calls
//! nest, a return to a reference point not yet established, an axis the PLC holds; and the
//! modal state a block leaves.

use super::macro_b::MacroBlock;
use super::modal::DrillMemory;
use super::modal::Modal;
use super::path::SegKind;
use super::program::NcBlock;
use super::ps;
use super::word::{Words, special_m};
use super::{AXES, SimCnc};

impl SimCnc {
    /// A block's words: as read at load, or, for an NC block with expressions, evaluated now
    /// (a macro statement's are the alarm a cycle's profile gives for it).
    pub(in crate::cnc) fn block_words(&self, b: &NcBlock) -> Result<Words, u16> {
        match b.mac.as_deref() {
            Some(MacroBlock::Nc(ws)) => self.render_words(ws),
            _ => b.words,
        }
    }

    /// The checks that depend on the machine (docs/cnc.md, "Program errors"); returns the
    /// program an M98 calls.
    pub(super) fn check_block(
        &self,
        w: &Words,
        cutting: bool,
    ) -> Result<Option<(usize, usize, u32)>, u16> {
        if w.axes[2].is_some() && self.axis_count() < 3 {
            return Err(ps::ADDRESS);
        }
        if cutting && w.f.unwrap_or(self.auto.modal.feed) <= 0.0 {
            return Err(ps::NO_FEED);
        }
        let mut call = None;
        if special_m(w.ms()).is_none() && w.ms().contains(&98) {
            let p = w.p.ok_or(ps::NO_PROGRAM)?;
            let find = |number: u32| self.programs.iter().position(|prog| prog.number == number);
            // P names the program itself when one has that number; else its last four
            // digits are the program and the digits before them the count (docs/gcode.md).
            let (k, count) = match find(p) {
                Some(k) => (k, 1),
                None => (find(p % 10_000).ok_or(ps::NO_PROGRAM)?, (p / 10_000).max(1)),
            };
            if self.subprogram_levels() >= 4 {
                return Err(ps::NESTING);
            }
            let times = w.l.map_or(count, |l| l.max(1));
            call = Some((k, 0, times));
        } else if special_m(w.ms()).is_none() && w.ms().contains(&97) && w.p.is_some() {
            // M97 P: the block numbered P of this program as a subprogram (Haas's local call).
            let (prog, here) = self.running_program().ok_or(ps::NO_SEQUENCE)?;
            let n = w.p.unwrap_or(0);
            let block = super::program::find_sequence(prog, n, here + 1).ok_or(ps::NO_SEQUENCE)?;
            if self.subprogram_levels() >= 4 {
                return Err(ps::NESTING);
            }
            call = Some((self.auto.cursor.prog, block, w.l.map_or(1, |l| l.max(1))));
        }
        if w.g28() {
            for k in 0..3 {
                if w.axes[k].is_some() && !self.axes[k].zrf {
                    return Err(ps::NO_REFERENCE);
                }
            }
        }
        Ok(call)
    }

    /// Subprogram calls (M98, M97, G70) nested at the cursor; macro calls count apart.
    fn subprogram_levels(&self) -> usize {
        self.auto.stack.iter().filter(|f| f.args.is_none()).count()
    }

    /// P/S 0139 when a planned segment would move an axis the PLC holds (EAX = 1); a G28
    /// counts for every axis it names.
    pub(super) fn check_claims(&self, w: &Words, cur: [i64; AXES]) -> Result<(), u16> {
        for (k, &from) in cur.iter().enumerate().take(3) {
            if self.inp.eax >> k & 1 == 0 {
                continue;
            }
            let named = w.g28() && w.axes[k].is_some();
            let moves =
                self.auto.segs.iter().any(|s| {
                    s.target[k] != from || (k < 2 && matches!(s.kind, SegKind::Arc { .. }))
                });
            if named || moves {
                return Err(ps::AXIS_CLAIM);
            }
        }
        Ok(())
    }

    /// The block's modal state once its G codes and F are read.
    pub(super) fn modal_after(&self, w: &Words) -> Modal {
        let mut modal = self.auto.modal;
        if let Some(m) = w.motion {
            modal.motion = m;
            // A group 01 code cancels a drilling cycle.
            modal.drill = DrillMemory::default();
        }
        match w.drill {
            Some(80) => modal.drill = DrillMemory::default(),
            // The cycle's data stay until G80 or a group 01 code.
            Some(g) => modal.drill.g = g,
            None => {}
        }
        if let Some(p) = w.per_rev {
            modal.per_rev = p;
        }
        if let Some(k) = w.work {
            modal.work = k;
        }
        if let Some(inch) = w.inch {
            modal.inch = inch;
        }
        if let Some(f) = w.f {
            modal.feed = self.units(modal.inch).feed(f);
        }
        if let Some(css) = w.css {
            modal.css = css;
        }
        modal
    }
}
