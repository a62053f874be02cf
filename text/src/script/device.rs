//! The words of a refused `device` line, `device.NAME` value or write of a device's input
//! (docs/machine.md, "Script lines").

use ladder_engine::devices::{SLOW_MAX, SLOW_MIN};
use ladder_engine::sim::{DeviceQuantity, DeviceReason};

/// What `r` says, in English and in Chinese.
pub(super) fn words(r: &DeviceReason) -> (String, String) {
    use DeviceReason as R;
    match r {
        R::NoModel { what } => (
            format!(
                "`{what}` needs the machine model: the project has no devices, or `sim` runs with --no-machine"
            ),
            format!("`{what}` 需要机床模型：工程没有设备，或 `sim` 带了 --no-machine"),
        ),
        R::NoDevice { name, devices } => (
            format!(
                "no device is named `{name}` (devices: {})",
                devices.join(", ")
            ),
            format!("没有名为 `{name}` 的设备（设备：{}）", devices.join("、")),
        ),
        R::NotBinary { text } => (
            format!("`{text}` is not 0 or 1"),
            format!("`{text}` 不是 0 或 1"),
        ),
        R::NotQuantity { text, what } => {
            let (what_en, what_zh) = quantity(*what);
            (
                format!("`{text}` is not {what_en}"),
                format!("`{text}` 不是{what_zh}"),
            )
        }
        R::SlowFactor { text } => (
            format!(
                "`{text}`: the factor is {SLOW_MIN}…{SLOW_MAX} (2 = twice as slow, 0.5 = twice as fast)"
            ),
            format!("`{text}`：倍数应为 {SLOW_MIN}…{SLOW_MAX}（2 表示慢一倍，0.5 表示快一倍）"),
        ),
        R::FlickerPeriod { text, min_ms } => (
            format!("`{text}`: the period is at least {min_ms} ms (two ticks)"),
            format!("`{text}`：周期至少 {min_ms} ms（两个扫描周期）"),
        ),
        R::NotInput {
            device,
            address,
            inputs,
        } => {
            let list: Vec<String> = inputs.iter().map(ToString::to_string).collect();
            (
                format!(
                    "device `{device}` does not write {address} (it writes {})",
                    list.join(", ")
                ),
                format!("设备 `{device}` 不写 {address}（它写 {}）", list.join("、")),
            )
        }
        R::Driven {
            verb,
            target,
            input: a,
            device: d,
        } => (
            format!(
                "`{verb} {}`: {a} is driven by device `{d}`, which writes it every tick; use `force {a} V` to hold it, `device {d} fault stuck 0|1` to simulate a broken sensor, or run with --no-machine",
                target.text()
            ),
            format!(
                "`{verb} {}`：{a} 由设备 `{d}` 每个周期驱动；要保持它请用 `force {a} V`，模拟传感器故障请用 `device {d} fault stuck 0|1`，或用 --no-machine 运行",
                target.text()
            ),
        ),
    }
}

/// What a fault's number stands for, in English and in Chinese.
fn quantity(q: DeviceQuantity) -> (&'static str, &'static str) {
    match q {
        DeviceQuantity::Factor => ("a factor", "倍数"),
        DeviceQuantity::Operations => ("a number of operations", "动作次数"),
        DeviceQuantity::PeriodMs => ("a period in ms", "以毫秒计的周期"),
    }
}
