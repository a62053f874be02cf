//! The machine model running: devices resolved once against the memory layout (every
//! binding an offset and a mask, every condition postfix terms), stepped once per tick with
//! no allocation. A device writes only the input bits it is bound to: each step computes the
//! values of its slots, faults bend them, and one loop writes them.

use super::error::ModelError;
use super::expr::{self, Names, Term};
use super::kinds::{self, Cold, Rt};
use super::model::{DeviceKind, MachineModel};
use super::resolved::{Bit, CncView, Resolved};
use super::status::{DeviceStatus, Fault};
use crate::address::Address;
use crate::cnc::{AXES, SimCnc};
use crate::profile::Profile;
use crate::vm::TICK_MS;
use crate::vm::memory::Layout;

/// The machine model, ready to run.
#[derive(Clone, Debug)]
pub struct Plant {
    model: MachineModel,
    pub(super) devices: Vec<Rt>,
    /// Each device's name and power-on state, by index.
    cold: Vec<Cold>,
    /// Every condition's terms, each device holding a range.
    pub(super) terms: Vec<Resolved>,
    /// Every device's states, each device holding a range.
    pub(super) states: Vec<bool>,
    /// Every device's input bits.
    pub(super) slots: Vec<Bit>,
    /// The address of each slot (a stuck fault names one).
    addresses: Vec<Address>,
    /// The values the devices mean to write this tick, by slot.
    pub(super) values: Vec<bool>,
    /// Physical axis positions, increments.
    phys: [i64; AXES],
    last: Option<CncView>,
    start: [i64; AXES],
    now_ms: u64,
}

impl Plant {
    /// Resolves a model against a profile's layout. Refuses what `check` reports as an
    /// error, at the first such device.
    pub fn new(model: &MachineModel, profile: &'static Profile) -> Result<Plant, ModelError> {
        super::check::validate(model, profile)?;
        let layout = Layout::new(profile);
        let names: Vec<(&str, &'static [&'static str])> = model
            .devices
            .iter()
            .map(|d| (d.name.as_str(), d.kind.states()))
            .collect();
        let mut state_base = Vec::with_capacity(names.len());
        let mut n = 0u32;
        for (_, s) in &names {
            state_base.push(n);
            n += s.len() as u32;
        }
        let mut plant = Plant {
            model: model.clone(),
            devices: Vec::new(),
            cold: Vec::new(),
            terms: Vec::new(),
            states: vec![false; n as usize],
            slots: Vec::new(),
            addresses: Vec::new(),
            values: Vec::new(),
            phys: [0; AXES],
            last: None,
            start: [0; AXES],
            now_ms: 0,
        };
        for (k, mm) in model.start_mm.iter().enumerate().take(AXES) {
            plant.start[k] = (mm * 1000.0).round() as i64;
        }
        plant.phys = plant.start;
        for (i, d) in model.devices.iter().enumerate() {
            let mut exprs = Vec::new();
            for (field, text) in d.kind.expressions() {
                let allow = !matches!(d.kind, DeviceKind::Follower(_));
                let terms = expr::parse(
                    text,
                    profile,
                    &Names {
                        devices: &names,
                        states: allow,
                    },
                )
                .map_err(|e| ModelError::Expression {
                    device: d.name.clone(),
                    field,
                    error: e,
                })?;
                let start = plant.terms.len() as u32;
                plant.terms.extend(terms.iter().map(|t| match *t {
                    Term::Bit(a) => {
                        let b = Bit::of(&layout, a);
                        Resolved::Bit(b.off, b.mask)
                    }
                    Term::State(dev, s) => Resolved::State(state_base[dev] + s as u32),
                    Term::Const(v) => Resolved::Const(v),
                    Term::Not => Resolved::Not,
                    Term::And => Resolved::And,
                    Term::Or => Resolved::Or,
                }));
                exprs.push(start..plant.terms.len() as u32);
            }
            let slot_start = plant.slots.len() as u32;
            let mut slot = |a: Option<Address>| {
                a.map(|a| {
                    plant.slots.push(Bit::of(&layout, a));
                    plant.addresses.push(a);
                    plant.slots.len() as u32 - 1
                })
            };
            let kind = kinds::resolve(&d.kind, &layout, &mut slot, &exprs);
            let slots = slot_start..plant.slots.len() as u32;
            let states = state_base[i]..state_base[i] + d.kind.states().len() as u32;
            plant.cold.push(Cold {
                name: d.name.clone(),
                init: kind.clone(),
            });
            plant.devices.push(Rt::new(kind, slots, states));
        }
        plant.values = vec![false; plant.slots.len()];
        plant.reset_states();
        Ok(plant)
    }

    /// Takes over a running plant's state where the model did not change it: the axes'
    /// physical positions and the clock, and each device that kept its name and its
    /// definition (position, timers, counts, fault, failure). A device that is new or was
    /// edited starts from its power-on state; a renamed one keeps its fault by name only
    /// if its definition is unchanged.
    pub fn take_over(&mut self, old: &Plant) {
        self.phys = old.phys;
        self.last = old.last;
        self.now_ms = old.now_ms;
        for (i, d) in self.model.devices.iter().enumerate() {
            let Some(j) = old.find(&d.name) else { continue };
            if old.model.devices[j] == *d {
                // The state only: its bindings are this plant's own (indices may have moved).
                kinds::take_state(&mut self.devices[i], &old.devices[j]);
            } else {
                // Edited: it starts afresh, keeping only its fault.
                self.devices[i].fault = old.devices[j].fault;
            }
        }
        self.reset_states();
    }

    /// Every device back to its power-on state (faults stay).
    pub fn power_cycle(&mut self) {
        for (d, c) in self.devices.iter_mut().zip(&self.cold) {
            d.power_on(&c.init);
        }
        self.reset_states();
    }

    fn reset_states(&mut self) {
        for d in &mut self.devices {
            kinds::publish(d, &mut self.states, &mut self.values);
        }
    }

    /// One tick: each device in order reads outputs and CNC values and writes its inputs.
    /// Runs before the PLC's scan, so the scan reads what the devices wrote, and the devices
    /// see the outputs of the scan before (docs/machine.md, "When devices run").
    pub fn step(&mut self, mem: &mut [u8], cnc: Option<&SimCnc>) {
        let view = cnc.map(CncView::of);
        self.step_with(mem, view.as_ref());
    }

    /// One tick with the CNC's values given directly (tests, and machines without a CNC).
    pub fn step_with(&mut self, mem: &mut [u8], view: Option<&CncView>) {
        self.track_axes(view);
        let now = self.now_ms;
        for i in 0..self.devices.len() {
            let d = &mut self.devices[i];
            let dt_us = d.dt_us();
            if !d.frozen {
                let ctx = kinds::Ctx {
                    mem,
                    terms: &self.terms,
                    states: &self.states,
                    phys: &self.phys,
                    cnc: view,
                    dt_us,
                };
                let ops = kinds::step(&mut d.kind, &ctx);
                if ops > 0 {
                    d.count(ops);
                }
            }
            if d.fault.is_none() {
                // The common case: straight into memory, no second pass.
                let slots = &self.slots;
                kinds::publish_with(d, &mut self.states, |k, v| {
                    slots[k as usize].set(mem, v);
                });
            } else {
                kinds::publish(d, &mut self.states, &mut self.values);
                write_inputs(d, (&self.slots, &self.addresses), &self.values, mem, now);
            }
        }
        self.now_ms += TICK_MS;
    }

    /// Physical positions move with the machine coordinate, except at the exchange where a
    /// reference return (or a power-cycle of the CNC) sets it: the axis does not move then.
    fn track_axes(&mut self, view: Option<&CncView>) {
        let Some(v) = view else { return };
        if let Some(last) = &self.last {
            for k in 0..AXES {
                let set = v.zrf[k] && !last.zrf[k] || !v.zrf[k] && last.zrf[k];
                if !set {
                    self.phys[k] += v.m[k] - last.m[k];
                }
            }
        }
        self.last = Some(*v);
    }

    /// The model it runs.
    pub fn model(&self) -> &MachineModel {
        &self.model
    }

    /// The devices' names, in order.
    pub fn names(&self) -> impl Iterator<Item = &str> {
        self.cold.iter().map(|c| c.name.as_str())
    }

    /// The index of the device named `name` (without case).
    pub fn find(&self, name: &str) -> Option<usize> {
        self.cold
            .iter()
            .position(|c| c.name.eq_ignore_ascii_case(name))
    }

    /// Device `i`'s fault, if it has one.
    pub fn fault(&self, i: usize) -> Option<Fault> {
        self.devices.get(i).and_then(|d| d.fault)
    }

    /// Injects a fault into device `i` (`None` clears it).
    pub fn set_fault(&mut self, i: usize, fault: Option<Fault>) {
        if let Some(d) = self.devices.get_mut(i) {
            d.fault = fault;
            d.fault_ops = 0;
            d.frozen = false;
        }
    }

    /// Puts device `i` back to its power-on state (a refilled lubricator, a reset counter).
    pub fn reset(&mut self, i: usize) {
        if let (Some(d), Some(c)) = (self.devices.get_mut(i), self.cold.get(i)) {
            d.power_on(&c.init);
            kinds::publish(d, &mut self.states, &mut self.values);
        }
    }

    /// Whether any device has a fault.
    pub fn faulted(&self) -> usize {
        self.devices.iter().filter(|d| d.fault.is_some()).count()
    }

    /// The physical position of an axis, mm.
    pub fn axis_mm(&self, axis: usize) -> f64 {
        self.phys.get(axis).map_or(0.0, |&p| p as f64 / 1000.0)
    }

    /// Every device's state, for a monitor.
    pub fn status_into(&self, out: &mut Vec<DeviceStatus>) {
        // Updated in place: the runner copies this out after every batch of ticks, and a
        // name is cloned only when it changed.
        out.truncate(self.devices.len());
        for (k, (d, c)) in self.devices.iter().zip(&self.cold).enumerate() {
            match out.get_mut(k) {
                Some(s) => d.status_into(&c.name, s),
                None => out.push(d.status(&c.name)),
            }
        }
    }

    /// Device `i`'s state.
    pub fn status(&self, i: usize) -> Option<DeviceStatus> {
        Some(self.devices.get(i)?.status(&self.cold.get(i)?.name))
    }

    /// A device's main value, for traces and scripts (docs/machine.md, "Values").
    pub fn value(&self, i: usize) -> Option<i64> {
        self.devices.get(i).map(|d| kinds::value(&d.kind))
    }

    /// The input bits every device writes (for the checks and the tests).
    pub fn written_bits(&self) -> impl Iterator<Item = Bit> + '_ {
        self.slots.iter().copied()
    }
}

/// Writes a faulted device's slots, bent by its fault.
fn write_inputs(
    d: &Rt,
    (slots, addresses): (&[Bit], &[Address]),
    values: &[bool],
    mem: &mut [u8],
    now: u64,
) {
    let flicker = match d.fault {
        Some(Fault::Flicker { period_ms }) => {
            let p = u64::from(period_ms.max(super::FLICKER_MIN_MS));
            now % p < TICK_MS
        }
        _ => false,
    };
    for k in d.slots.clone() {
        let slot = slots[k as usize];
        let mut v = values[k as usize];
        if let Some(Fault::Stuck { value, input }) = d.fault
            && input.is_none_or(|a| a == addresses[k as usize])
        {
            v = value;
        }
        v ^= flicker;
        slot.set(mem, v);
    }
}
