//! Online edit: a newly compiled program takes over a running PLC at a tick boundary.
//!
//! The memory image (timers, counters, latched data, outputs), the forces and the clock carry
//! over unchanged, so a machine under test does not notice the swap. Per-instance memories
//! (the edge a timer saw last, its start time, a WINDR in progress) belong to instructions,
//! which an edit may move: they are matched by instruction and operands, so `TMRB T0000 …`
//! keeps counting wherever its network went. Level 2 restarts its cycle, since the old
//! resume point means nothing in the new code.

use super::Vm;
use super::code::FnCall;
use std::collections::HashMap;

/// Why a program cannot take over a PLC: data only, worded by `ladder_text::refusal` (the
/// runner hands it to the editor as a refusal).
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum SwapError {
    /// The controller profile differs, so memory is laid out differently.
    Profile {
        /// The running profile.
        old: &'static str,
        /// The new program's profile.
        new: &'static str,
    },
}

/// What a swap kept.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Swapped {
    /// Function instances whose memory carried over.
    pub kept: usize,
    /// New instances, starting fresh.
    pub fresh: usize,
}

fn key(f: &FnCall) -> String {
    format!("{:?}{:?}{:?}", f.op, f.args, f.table)
}

impl Vm {
    /// Takes over `old`'s state (see the module documentation).
    pub fn take_over(&mut self, old: &Vm) -> Result<Swapped, SwapError> {
        if !std::ptr::eq(self.profile, old.profile) {
            return Err(SwapError::Profile {
                old: old.profile.name,
                new: self.profile.name,
            });
        }
        self.mem.copy_from_slice(&old.mem);
        self.force_mask.copy_from_slice(&old.force_mask);
        self.force_value.copy_from_slice(&old.force_value);
        self.forced_bytes.clone_from(&old.forced_bytes);
        self.ticks = old.ticks;
        self.executed = old.executed;
        self.division = old.division;
        // The engine chosen online stays; the new program's code is generated here, before
        // the tick it takes over at.
        self.set_engine(old.engine);
        // Old instances by instruction and operands; each is taken once, in program order, so
        // two identical instructions keep their own memories as long as their order holds.
        let mut by_key: HashMap<String, Vec<u32>> = HashMap::new();
        for f in old.code.fns.iter().rev() {
            by_key.entry(key(f)).or_default().push(f.state);
        }
        let mut done = vec![false; self.states.len()];
        let mut swapped = Swapped::default();
        for f in &self.code.fns {
            let s = f.state as usize;
            if done[s] {
                continue; // A subprogram called from both levels shares one state.
            }
            done[s] = true;
            match by_key.get_mut(&key(f)).and_then(Vec::pop) {
                Some(o) => {
                    self.states[s] = old.states[o as usize];
                    if self.latches[s].len() == old.latches[o as usize].len() {
                        self.latches[s].clone_from(&old.latches[o as usize]);
                    }
                    swapped.kept += 1;
                }
                None => swapped.fresh += 1,
            }
        }
        self.apply_forces();
        Ok(swapped)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::address::Address;
    use crate::il;
    use crate::vm::cnc::NoCnc;

    fn vm(text: &str) -> Vm {
        Vm::new(&il::import(text).project.expect("valid IL")).expect("compiles")
    }

    fn a(s: &str) -> Address {
        s.parse().unwrap()
    }

    const TIMER: &str = "LEVEL2\nNETWORK\nLD X0000.0\nTMRB T0000 1000 R0000.0\n";

    #[test]
    fn a_running_timer_keeps_counting_after_an_edit_moves_it() {
        let mut old = vm(TIMER);
        old.write(a("X0.0"), 1, 1);
        old.write(a("D0"), 4, 77);
        for _ in 0..10 {
            old.tick(&mut NoCnc);
        }
        assert_eq!(old.read(a("T0"), 4), 72);
        // The edit puts a network before the timer's.
        let mut new = vm(&format!(
            "LEVEL2\nNETWORK\nLD X0000.1\nOUT Y0000.0\n{}",
            &TIMER["LEVEL2\n".len()..]
        ));
        let s = new.take_over(&old).unwrap();
        assert_eq!(s, Swapped { kept: 1, fresh: 0 });
        assert_eq!(new.read(a("D0"), 4), 77, "data kept");
        assert_eq!(new.ticks(), 10, "the clock goes on");
        new.tick(&mut NoCnc);
        assert_eq!(new.read(a("T0"), 4), 80, "still counting, not restarted");
    }

    #[test]
    fn a_new_timer_starts_fresh_and_forces_carry_over() {
        let mut old = vm(TIMER);
        old.force(a("X0.0"), 1);
        old.tick(&mut NoCnc);
        let mut new = vm("LEVEL2\nNETWORK\nLD X0000.0\nTMRB T0001 1000 R0000.1\n");
        let s = new.take_over(&old).unwrap();
        assert_eq!(s, Swapped { kept: 0, fresh: 1 });
        assert!(new.read_bit(a("X0.0")), "the force holds");
        assert_eq!(new.forces().count(), 1);
        new.tick(&mut NoCnc);
        new.tick(&mut NoCnc);
        assert_eq!(new.read(a("T1"), 4), 8, "T1 started at the swap");
    }
}
