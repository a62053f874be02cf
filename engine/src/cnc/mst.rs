//! The M/S/T interface of a block (docs/cnc.md, "MST interface"): strobes drop on FIN or
//! their own finish signal, the sequence finishes when every finish signal is 0 again, and
//! the F image of the strobes, codes, DEN and the decode signals.

use super::fsignals as fs;
use super::modal::RunState;
use super::signals::FImage;
use super::{MstStatus, SimCnc};

/// Strobe bits of an open MST sequence.
pub(super) const MF: u8 = 1;
pub(super) const MF2: u8 = 2;
pub(super) const MF3: u8 = 4;
pub(super) const SF: u8 = 8;
pub(super) const TF: u8 = 16;

/// The M/S/T sequence of a block.
#[derive(Clone, Copy, Debug, Default)]
pub(super) struct Mst {
    pub(super) open: bool,
    pub(super) strobes: u8,
    pub(super) started: u64,
    pub(super) m: [u32; 3],
    pub(super) s: u32,
    pub(super) t: u32,
}

/// The strobes seen so far: each rising edge counted, the codes it sent kept.
#[derive(Clone, Debug, Default)]
pub(super) struct MstLog {
    /// MF, SF, TF and FIN at the last exchange.
    prev: [bool; 4],
    /// The last M, S and T codes strobed.
    last: [u32; 3],
    /// Rising edges of MF, SF, TF and FIN.
    strobes: [u64; 4],
}

impl SimCnc {
    /// Step (f): strobes drop on FIN or their own finish signal; the sequence finishes when
    /// every finish signal is 0 again.
    pub(super) fn mst_acceptance(&mut self) {
        let inp = self.inp;
        let n = self.exchange_no;
        let Some(e) = &mut self.auto.exec else { return };
        let mst = &mut e.mst;
        if !mst.open || n <= mst.started {
            return;
        }
        let own = [inp.mfin, inp.mfin2, inp.mfin3, inp.sfin, inp.tfin];
        for (i, bit) in [MF, MF2, MF3, SF, TF].into_iter().enumerate() {
            if mst.strobes & bit != 0 && (inp.fin || own[i]) {
                mst.strobes &= !bit;
            }
        }
        if mst.strobes == 0 && !inp.fin && !own.iter().any(|x| *x) {
            *mst = Mst::default();
        }
    }

    /// The automatic-operation part of F.
    pub(super) fn auto_f(&self, img: &mut FImage) {
        let a = &self.auto;
        let run = a.state == RunState::Run;
        let hold = a.state == RunState::Hold;
        img.set(fs::STL, run);
        img.set(fs::SPL, hold);
        img.set(fs::OP, run || hold);
        img.set(fs::DM99, a.dm99);
        let Some(e) = &a.exec else { return };
        let mst = &e.mst;
        if !mst.open {
            return;
        }
        let done = e.motion_done();
        img.put(fs::M_CODE, mst.m[0]);
        img.put(fs::M_CODE2, mst.m[1]);
        img.put(fs::M_CODE3, mst.m[2]);
        img.put(fs::S_CODE, mst.s);
        img.put(fs::T_CODE, mst.t);
        img.set(fs::MF, mst.strobes & MF != 0);
        img.set(fs::SF, mst.strobes & SF != 0);
        img.set(fs::TF, mst.strobes & TF != 0);
        img.set(fs::MF2, mst.strobes & MF2 != 0);
        img.set(fs::MF3, mst.strobes & MF3 != 0);
        img.set(fs::DEN, done);
        if done && mst.strobes & MF != 0 {
            match mst.m[0] {
                0 => img.set(fs::DM00, true),
                1 => img.set(fs::DM01, true),
                2 => img.set(fs::DM02, true),
                30 => img.set(fs::DM30, true),
                _ => {}
            }
        }
    }

    /// Counts the strobes that rose in this exchange and keeps the codes they sent.
    pub(super) fn note_strobes(&mut self) {
        let now = self.mst_status();
        let up = [now.mf, now.sf, now.tf, now.fin];
        let codes = [now.m, now.s, now.t];
        let log = &mut self.mst_log;
        for k in 0..4 {
            if up[k] && !log.prev[k] {
                log.strobes[k] += 1;
                if k < 3 {
                    log.last[k] = codes[k];
                }
            }
        }
        log.prev = up;
    }

    /// The M/S/T lamps.
    pub(super) fn mst_status(&self) -> MstStatus {
        let mut s = MstStatus {
            fin: self.inp.fin,
            last: self.mst_log.last,
            strobes: self.mst_log.strobes,
            ..MstStatus::default()
        };
        if let Some(e) = &self.auto.exec
            && e.mst.open
        {
            let m = &e.mst;
            s.m = m.m[0];
            s.s = m.s;
            s.t = m.t;
            s.mf = m.strobes & MF != 0;
            s.sf = m.strobes & SF != 0;
            s.tf = m.strobes & TF != 0;
            s.den = e.motion_done();
        }
        s
    }
}
