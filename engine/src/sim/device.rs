//! The script lines about the machine model (docs/machine.md, "Script lines"): `device NAME
//! fault …`, `device NAME ok`, `device NAME reset`, the `device.NAME` value, and the refusal
//! to `set` an input a device drives.

use super::{Msg, ScriptCommand, Target, msg};
use crate::address::Address;
use crate::devices::{FLICKER_MIN_MS, Fault, MachineModel, SLOW_MAX, SLOW_MIN};
use crate::machine::{DeviceAction, MachineCommand, Probe};

const USAGE: &str = "device NAME fault stuck 0|1 [ADDR] | fault slow FACTOR | fault fail-after K | fault flicker MS | ok | reset";

fn model<'a>(machine: Option<&'a MachineModel>, what: &str) -> Result<&'a MachineModel, Msg> {
    machine.filter(|m| !m.devices.is_empty()).ok_or_else(|| {
        msg(
            format!(
                "`{what}` needs the machine model: the project has no devices, or `sim` runs with --no-machine"
            ),
            format!("`{what}` 需要机床模型：工程没有设备，或 `sim` 带了 --no-machine"),
        )
    })
}

fn index(m: &MachineModel, name: &str) -> Result<usize, Msg> {
    m.position(name).ok_or_else(|| {
        let names: Vec<&str> = m.devices.iter().map(|d| d.name.as_str()).collect();
        msg(
            format!(
                "no device is named `{name}` (devices: {})",
                names.join(", ")
            ),
            format!("没有名为 `{name}` 的设备（设备：{}）", names.join("、")),
        )
    })
}

/// `device.NAME` as a probe, when `text` is one.
pub fn probe(text: &str, machine: Option<&MachineModel>) -> Option<Result<Probe, Msg>> {
    let name = text
        .get(..7)
        .filter(|p| p.eq_ignore_ascii_case("device."))
        .map(|_| &text[7..])?;
    Some(model(machine, text).and_then(|m| index(m, name).map(Probe::Device)))
}

/// A `device` line.
pub fn line(args: &[&str], machine: Option<&MachineModel>) -> Result<ScriptCommand, Msg> {
    let usage = || msg(format!("usage: {USAGE}"), format!("用法：`{USAGE}`"));
    let m = model(machine, "device")?;
    let (Some(name), Some(verb)) = (args.first(), args.get(1)) else {
        return Err(usage());
    };
    let i = index(m, name)?;
    let rest = &args[2..];
    let action = match (verb.to_ascii_lowercase().as_str(), rest) {
        ("ok", []) => DeviceAction::Ok,
        ("reset", []) => DeviceAction::Reset,
        ("fault", [kind, more @ ..]) => DeviceAction::Fault(fault(m, i, kind, more)?),
        _ => return Err(usage()),
    };
    Ok(ScriptCommand::Do(MachineCommand::Device(i, action)))
}

fn number<T: std::str::FromStr>(text: &str, what: &str, zh: &str) -> Result<T, Msg> {
    text.parse().map_err(|_| {
        msg(
            format!("`{text}` is not {what}"),
            format!("`{text}` 不是{zh}"),
        )
    })
}

fn fault(m: &MachineModel, i: usize, kind: &str, more: &[&str]) -> Result<Fault, Msg> {
    let usage = || msg(format!("usage: {USAGE}"), format!("用法：`{USAGE}`"));
    Ok(match (kind.to_ascii_lowercase().as_str(), more) {
        ("stuck", [v, rest @ ..]) if rest.len() <= 1 => {
            let value = match *v {
                "0" => false,
                "1" => true,
                _ => {
                    return Err(msg(
                        format!("`{v}` is not 0 or 1"),
                        format!("`{v}` 不是 0 或 1"),
                    ));
                }
            };
            let input = match rest.first() {
                Some(a) => Some(input_of(m, i, a)?),
                None => None,
            };
            Fault::Stuck { value, input }
        }
        ("slow", [f]) => {
            let factor: f32 = number(f, "a factor", "倍数")?;
            if !(SLOW_MIN..=SLOW_MAX).contains(&factor) {
                return Err(msg(
                    format!(
                        "`{f}`: the factor is {SLOW_MIN}…{SLOW_MAX} (2 = twice as slow, 0.5 = twice as fast)"
                    ),
                    format!(
                        "`{f}`：倍数应为 {SLOW_MIN}…{SLOW_MAX}（2 表示慢一倍，0.5 表示快一倍）"
                    ),
                ));
            }
            Fault::Slow { factor }
        }
        ("fail-after", [k]) => Fault::FailAfter {
            operations: number(k, "a number of operations", "动作次数")?,
        },
        ("flicker", [ms]) => {
            let period_ms: u32 = number(ms, "a period in ms", "以毫秒计的周期")?;
            if period_ms < FLICKER_MIN_MS {
                return Err(msg(
                    format!("`{ms}`: the period is at least {FLICKER_MIN_MS} ms (two ticks)"),
                    format!("`{ms}`：周期至少 {FLICKER_MIN_MS} ms（两个扫描周期）"),
                ));
            }
            Fault::Flicker { period_ms }
        }
        _ => return Err(usage()),
    })
}

/// `text` as one of device `i`'s inputs.
fn input_of(m: &MachineModel, i: usize, text: &str) -> Result<Address, Msg> {
    let d = &m.devices[i];
    let inputs = d.kind.inputs();
    let a = Address::parse(text)?;
    inputs
        .iter()
        .find(|(_, b)| *b == a)
        .map(|(_, b)| *b)
        .ok_or_else(|| {
            let list: Vec<String> = inputs.iter().map(|(_, b)| b.to_string()).collect();
            msg(
                format!(
                    "device `{}` does not write {a} (it writes {})",
                    d.name,
                    list.join(", ")
                ),
                format!("设备 `{}` 不写 {a}（它写 {}）", d.name, list.join("、")),
            )
        })
}

/// Refuses a write of an input a device drives: the device would overwrite it at the next
/// tick, so the line would test nothing.
pub fn not_driven(t: &Target, verb: &str, machine: Option<&MachineModel>) -> Result<(), Msg> {
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
                return Err(msg(
                    format!(
                        "`{verb} {}`: {a} is driven by device `{}`, which writes it every tick; use `force {a} V` to hold it, `device {} fault stuck 0|1` to simulate a broken sensor, or run with --no-machine",
                        t.text(),
                        d.name,
                        d.name
                    ),
                    format!(
                        "`{verb} {}`：{a} 由设备 `{}` 每个周期驱动；要保持它请用 `force {a} V`，模拟传感器故障请用 `device {} fault stuck 0|1`，或用 --no-machine 运行",
                        t.text(),
                        d.name,
                        d.name
                    ),
                ));
            }
        }
    }
    Ok(())
}
