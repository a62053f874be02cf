//! Applying and releasing saved scenarios on a machine (docs/scenarios.md): each action
//! records what it is about to change, so the release writes back exactly that.

use super::{Machine, Target};
use crate::refusal::Refusal;
use crate::scenario::{Applied, ScenarioAction, Undo};

impl Machine {
    /// The names of the scenarios applied now, oldest first.
    pub fn applied_scenarios(&self) -> impl Iterator<Item = &str> {
        self.applied.iter().map(|(n, _)| n.as_str())
    }

    /// Applies a scenario; a scenario already applied is refused (release it first).
    pub(super) fn apply_scenario(&mut self, applied: &Applied) -> Result<(), Refusal> {
        let name = &applied.name;
        if self.applied.iter().any(|(n, _)| n == name) {
            return Err(Refusal::ScenarioApplied(name.clone()));
        }
        // Every fault's device must exist before anything changes: all or nothing.
        for a in &applied.actions {
            if let ScenarioAction::Fault(i, _) = a
                && self.plant.as_ref().is_none_or(|p| *i >= p.names().count())
            {
                return Err(Refusal::ScenarioNeedsModel {
                    name: name.clone(),
                    device: *i,
                });
            }
        }
        let mut undo = Vec::with_capacity(applied.actions.len());
        for a in &applied.actions {
            undo.push(self.act(a));
        }
        self.applied.push((name.clone(), undo));
        Ok(())
    }

    /// Carries out one action and says how to undo it.
    fn act(&mut self, a: &ScenarioAction) -> Undo {
        match a {
            ScenarioAction::Write(t, v) => {
                let old = self.plc.read(t.address, t.bytes);
                self.plc.write(t.address, t.bytes, *v);
                Undo::Write(*t, old)
            }
            ScenarioAction::Force(addr, v) => {
                let t = Target::whole(*addr);
                let state = self.plc.force_state(*addr);
                let old = self.plc.read(t.address, t.bytes);
                self.plc.force(*addr, *v);
                Undo::Force(*addr, state, t, old)
            }
            ScenarioAction::Knob { input, mask, value } => {
                let old = self.plc.read(*input, 1);
                let m = i64::from(*mask);
                self.plc.write(*input, 1, (old & 0xff & !m) | (value & m));
                Undo::Knob {
                    input: *input,
                    mask: *mask,
                    old,
                }
            }
            ScenarioAction::Fault(i, f) => {
                let plant = self.plant.as_mut().expect("checked before acting");
                let old = plant.fault(*i);
                plant.set_fault(*i, Some(*f));
                let name = plant.names().nth(*i).unwrap_or_default().to_string();
                Undo::Fault(name, old)
            }
        }
    }

    /// Releases an applied scenario: its actions are undone last first. A scenario applied
    /// later that changed the same thing must be released first, or each release would put
    /// back a state the other one made.
    pub(super) fn release_scenario(&mut self, name: &str) -> Result<(), Refusal> {
        let Some(k) = self.applied.iter().position(|(n, _)| n == name) else {
            return Err(Refusal::ScenarioNotApplied(name.to_string()));
        };
        let later = self.applied[k + 1..].iter().find(|(_, theirs)| {
            theirs
                .iter()
                .any(|t| self.applied[k].1.iter().any(|u| u.overlaps(t)))
        });
        if let Some((other, _)) = later {
            return Err(Refusal::ScenarioOrder {
                name: name.to_string(),
                other: other.clone(),
            });
        }
        let (_, undo) = self.applied.remove(k);
        for u in undo.into_iter().rev() {
            match u {
                Undo::Write(t, v) => self.plc.write(t.address, t.bytes, v),
                Undo::Knob { input, mask, old } => {
                    let now = self.plc.read(input, 1);
                    let m = i64::from(mask);
                    self.plc.write(input, 1, (now & 0xff & !m) | (old & m));
                }
                Undo::Force(a, state, t, v) => {
                    // The value first: a force put back wins over it, as it did before.
                    self.plc.unforce(a);
                    self.plc.write(t.address, t.bytes, v);
                    self.plc.restore_force(a, state);
                }
                Undo::Fault(device, f) => {
                    if let Some(p) = &mut self.plant
                        && let Some(i) = p.find(&device)
                    {
                        p.set_fault(i, f);
                    }
                }
            }
        }
        Ok(())
    }
}
