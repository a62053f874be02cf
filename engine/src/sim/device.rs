//! The script lines about the machine model (docs/machine.md, "Script lines"): `device NAME
//! fault …`, `device NAME ok`, `device NAME reset`, the `device.NAME` value, and the refusal
//! to `set` an input a device drives.

use super::{DeviceQuantity, DeviceReason, ScriptCommand, ScriptReason, Target};
use crate::address::Address;
use crate::devices::{FLICKER_MIN_MS, Fault, MachineModel, SLOW_MAX, SLOW_MIN};
use crate::machine::{DeviceAction, MachineCommand, Probe};

const USAGE: ScriptReason = ScriptReason::Usage {
    usage: "device NAME fault stuck 0|1 [ADDR] | fault slow FACTOR | fault fail-after K | fault flicker MS | ok | reset",
};

fn model<'a>(
    machine: Option<&'a MachineModel>,
    what: &str,
) -> Result<&'a MachineModel, ScriptReason> {
    machine
        .filter(|m| !m.devices.is_empty())
        .ok_or_else(|| DeviceReason::NoModel { what: what.into() }.into())
}

fn index(m: &MachineModel, name: &str) -> Result<usize, ScriptReason> {
    m.position(name).ok_or_else(|| {
        DeviceReason::NoDevice {
            name: name.into(),
            devices: m.devices.iter().map(|d| d.name.clone()).collect(),
        }
        .into()
    })
}

/// `device.NAME` as a probe, when `text` is one.
pub fn probe(text: &str, machine: Option<&MachineModel>) -> Option<Result<Probe, ScriptReason>> {
    let name = text
        .get(..7)
        .filter(|p| p.eq_ignore_ascii_case("device."))
        .map(|_| &text[7..])?;
    Some(model(machine, text).and_then(|m| index(m, name).map(Probe::Device)))
}

/// A `device` line.
pub fn line(args: &[&str], machine: Option<&MachineModel>) -> Result<ScriptCommand, ScriptReason> {
    let m = model(machine, "device")?;
    let (Some(name), Some(verb)) = (args.first(), args.get(1)) else {
        return Err(USAGE);
    };
    let i = index(m, name)?;
    let rest = &args[2..];
    let action = match (verb.to_ascii_lowercase().as_str(), rest) {
        ("ok", []) => DeviceAction::Ok,
        ("reset", []) => DeviceAction::Reset,
        ("fault", [kind, more @ ..]) => DeviceAction::Fault(fault(m, i, kind, more)?),
        _ => return Err(USAGE),
    };
    Ok(ScriptCommand::Do(MachineCommand::Device(i, action)))
}

fn number<T: std::str::FromStr>(text: &str, what: DeviceQuantity) -> Result<T, ScriptReason> {
    text.parse().map_err(|_| {
        DeviceReason::NotQuantity {
            text: text.into(),
            what,
        }
        .into()
    })
}

fn fault(m: &MachineModel, i: usize, kind: &str, more: &[&str]) -> Result<Fault, ScriptReason> {
    Ok(match (kind.to_ascii_lowercase().as_str(), more) {
        ("stuck", [v, rest @ ..]) if rest.len() <= 1 => {
            let value = match *v {
                "0" => false,
                "1" => true,
                _ => {
                    return Err(DeviceReason::NotBinary { text: (*v).into() }.into());
                }
            };
            let input = match rest.first() {
                Some(a) => Some(input_of(m, i, a)?),
                None => None,
            };
            Fault::Stuck { value, input }
        }
        ("slow", [f]) => {
            let factor: f32 = number(f, DeviceQuantity::Factor)?;
            if !(SLOW_MIN..=SLOW_MAX).contains(&factor) {
                return Err(DeviceReason::SlowFactor { text: (*f).into() }.into());
            }
            Fault::Slow { factor }
        }
        ("fail-after", [k]) => Fault::FailAfter {
            operations: number(k, DeviceQuantity::Operations)?,
        },
        ("flicker", [ms]) => {
            let period_ms: u32 = number(ms, DeviceQuantity::PeriodMs)?;
            if period_ms < FLICKER_MIN_MS {
                return Err(DeviceReason::FlickerPeriod {
                    text: (*ms).into(),
                    min_ms: FLICKER_MIN_MS,
                }
                .into());
            }
            Fault::Flicker { period_ms }
        }
        _ => return Err(USAGE),
    })
}

/// `text` as one of device `i`'s inputs.
fn input_of(m: &MachineModel, i: usize, text: &str) -> Result<Address, ScriptReason> {
    let d = &m.devices[i];
    let inputs = d.kind.inputs();
    let a = Address::parse(text)?;
    inputs
        .iter()
        .find(|(_, b)| *b == a)
        .map(|(_, b)| *b)
        .ok_or_else(|| {
            DeviceReason::NotInput {
                device: d.name.clone(),
                address: a,
                inputs: inputs.iter().map(|(_, b)| *b).collect(),
            }
            .into()
        })
}

/// Refuses a write of an input a device drives: the device would overwrite it at the next
/// tick, so the line would test nothing.
pub fn not_driven(
    t: &Target,
    verb: &'static str,
    machine: Option<&MachineModel>,
) -> Result<(), ScriptReason> {
    let Some(m) = machine else { return Ok(()) };
    let bytes = t.bytes.max(1);
    for d in &m.devices {
        for (_, a) in d.kind.inputs() {
            let hit = match t.address.bit {
                Some(_) => a == t.address,
                None => {
                    a.area == t.address.area
                        && a.number >= t.address.number
                        && u32::from(a.number) < u32::from(t.address.number) + bytes
                }
            };
            if hit {
                return Err(DeviceReason::Driven {
                    verb,
                    target: *t,
                    input: a,
                    device: d.name.clone(),
                }
                .into());
            }
        }
    }
    Ok(())
}
