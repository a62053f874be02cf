//! What makes a machine model unrunnable: a bad name, a wrong address, an impossible
//! parameter, a condition that does not read, two devices writing one input. `check`
//! reports each as a diagnostic (M001–M005); a plant is built only from a model without them.

use super::error::{Limit, ModelError};
use super::model::{DeviceKind, MachineModel};
use crate::address::{Address, Area};
use crate::cnc::AXES;
use crate::profile::Profile;
use std::collections::HashMap;

/// Every error of a model, each with its device's index.
pub fn errors(model: &MachineModel, profile: &Profile) -> Vec<(usize, ModelError)> {
    let mut out = Vec::new();
    let mut names: HashMap<String, usize> = HashMap::new();
    let states: Vec<(&str, &'static [&'static str])> = model
        .devices
        .iter()
        .map(|d| (d.name.as_str(), d.kind.states()))
        .collect();
    let mut writers: HashMap<Address, usize> = HashMap::new();
    for (axis, mm) in model.start_mm.iter().enumerate() {
        if axis >= AXES || !mm.is_finite() || mm.abs() > 100_000.0 {
            out.push((0, ModelError::Start { axis }));
        }
    }
    for (i, d) in model.devices.iter().enumerate() {
        let valid = d.name.starts_with(|c: char| c.is_ascii_alphabetic())
            && d.name
                .chars()
                .all(|c| c.is_ascii_alphanumeric() || c == '_')
            && d.name.len() <= 24
            && Address::parse(&d.name).is_err();
        if !valid {
            out.push((i, ModelError::Name(d.name.clone())));
        } else if let Some(&first) = names.get(&d.name.to_ascii_lowercase()) {
            out.push((
                i,
                ModelError::NameTwice {
                    name: d.name.clone(),
                    first,
                },
            ));
        } else {
            names.insert(d.name.to_ascii_lowercase(), i);
        }
        for (field, a) in d.kind.inputs() {
            if let Err(e) = address(a, profile, true) {
                out.push((i, e.at(&d.name, field)));
            } else if let Some(&other) = writers.get(&a) {
                out.push((
                    i,
                    ModelError::TwoWriters {
                        device: d.name.clone(),
                        address: a,
                        other: model.devices[other].name.clone(),
                    },
                ));
            } else {
                writers.insert(a, i);
            }
        }
        for (field, a) in d.kind.outputs() {
            if let Err(e) = address(a, profile, false) {
                out.push((i, e.at(&d.name, field)));
            }
        }
        for (field, text) in d.kind.expressions() {
            let names = super::expr::Names {
                devices: &states,
                states: !matches!(d.kind, DeviceKind::Follower(_)),
            };
            if let Err(error) = super::expr::parse(text, profile, &names) {
                out.push((
                    i,
                    ModelError::Expression {
                        device: d.name.clone(),
                        field,
                        error,
                    },
                ));
            }
        }
        if let Some((field, limit)) = parameter(&d.kind) {
            out.push((
                i,
                ModelError::Parameter {
                    device: d.name.clone(),
                    field,
                    limit,
                },
            ));
        }
    }
    out
}

/// The first error, for [`super::Plant::new`].
pub fn validate(model: &MachineModel, profile: &Profile) -> Result<(), ModelError> {
    match errors(model, profile).into_iter().next() {
        Some((_, e)) => Err(e),
        None => Ok(()),
    }
}

/// An address's problem before the device and field are known.
enum Wrong {
    Address(crate::address::AddressError),
    NotInput(Address),
    NotBit(Address),
}

impl Wrong {
    fn at(self, device: &str, field: &'static str) -> ModelError {
        let device = device.to_string();
        match self {
            Wrong::Address(error) => ModelError::Address {
                device,
                field,
                error,
            },
            Wrong::NotInput(address) => ModelError::NotInput {
                device,
                field,
                address,
            },
            Wrong::NotBit(address) => ModelError::NotBit {
                device,
                field,
                address,
            },
        }
    }
}

fn address(a: Address, profile: &Profile, input: bool) -> Result<(), Wrong> {
    a.check_range(profile).map_err(Wrong::Address)?;
    if a.bit.is_none() {
        return Err(Wrong::NotBit(a));
    }
    if input && a.area != Area::X {
        return Err(Wrong::NotInput(a));
    }
    Ok(())
}

/// The first impossible parameter: its field and the rule it breaks.
fn parameter(kind: &DeviceKind) -> Option<(&'static str, Limit)> {
    match kind {
        DeviceKind::Actuator(a) if a.travel_ms == 0 => {
            Some(("travel_ms", Limit::Range(1, 600_000)))
        }
        DeviceKind::Actuator(a) if a.travel_ms > 600_000 => {
            Some(("travel_ms", Limit::Range(1, 600_000)))
        }
        DeviceKind::Turret(t) if !(2..=32).contains(&t.stations) => {
            Some(("stations", Limit::Range(2, 32)))
        }
        DeviceKind::Turret(t) if t.start_station == 0 || t.start_station > t.stations => {
            Some(("start_station", Limit::Station))
        }
        DeviceKind::Turret(t)
            if u32::from(t.code.bits) < t.code.encoding.bits_for(u32::from(t.stations))
                || t.code.bits > 32 =>
        {
            Some(("code.bits", Limit::CodeBits))
        }
        DeviceKind::Turret(t) if t.station_ms == 0 || t.station_ms > 600_000 => {
            Some(("station_ms", Limit::Range(1, 600_000)))
        }
        DeviceKind::Turret(t) if t.window_pct == 0 || t.window_pct > 100 => {
            Some(("window_pct", Limit::Range(1, 100)))
        }
        // A window shorter than a tick could be stepped over between two samples.
        DeviceKind::Turret(t) if u64::from(t.station_ms) * u64::from(t.window_pct) < 800 => {
            Some(("window_pct", Limit::WindowTick))
        }
        DeviceKind::Turret(t) if t.lock.as_ref().is_some_and(|l| l.ms == 0) => {
            Some(("lock.ms", Limit::Range(1, 600_000)))
        }
        DeviceKind::Turret(t) if t.ccw.is_some() && t.direction.is_some() => {
            Some(("direction", Limit::OneDirection))
        }
        DeviceKind::PositionSwitch(p) if usize::from(p.axis) >= AXES => {
            Some(("axis", Limit::Range(0, 4)))
        }
        DeviceKind::PositionSwitch(p)
            if p.from_mm.partial_cmp(&p.to_mm).is_none_or(|o| o.is_gt())
                || !p.from_mm.is_finite()
                || !p.to_mm.is_finite() =>
        {
            Some(("to_mm", Limit::Ordered))
        }
        DeviceKind::Spindle(s) if s.full_rpm == 0 => Some(("full_rpm", Limit::AtLeast(1))),
        DeviceKind::Spindle(s) if s.tolerance_pct > 100 => {
            Some(("tolerance_pct", Limit::Range(0, 100)))
        }
        DeviceKind::Pulse(p) if p.period_ms == 0 || p.on_ms > p.period_ms => {
            Some(("on_ms", Limit::PulseOn))
        }
        DeviceKind::Counter(c) if c.count == 0 => Some(("count", Limit::AtLeast(1))),
        _ => None,
    }
}
