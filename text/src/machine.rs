//! The words of the Machine page: the label of each device field (docs/machine.md names the
//! fields; `ladder_engine::devices::fields` lists them per kind).

use crate::Lang;

/// The label of the device field `name` in `lang` (`travel_ms` → `行程时间 ms`); empty for a
/// name no device has.
pub fn field_label(name: &str, lang: Lang) -> &'static str {
    let (zh, en) = labels(name);
    match lang {
        Lang::Zh => zh,
        Lang::En => en,
    }
}

/// Both labels of a field: (Chinese, English); empty for a name no device has.
fn labels(name: &str) -> (&'static str, &'static str) {
    match name {
        "input" => ("输入", "input"),
        "when" => ("条件", "when"),
        "on_ms" => ("接通延时 ms", "on delay, ms"),
        "off_ms" => ("断开延时 ms", "off delay, ms"),
        "advance" => ("伸出（夹紧）输出", "advance output"),
        "retract" => ("缩回（松开）输出", "retract output"),
        "travel_ms" => ("行程时间 ms", "travel time, ms"),
        "at_advanced" => ("伸出到位开关", "advanced switch"),
        "at_retracted" => ("缩回到位开关", "retracted switch"),
        "moving" => ("行程中信号", "moving signal"),
        "start_advanced" => ("上电时伸出", "starts advanced"),
        "stations" => ("刀位数", "stations"),
        "cw" => ("正转输出", "CW output"),
        "ccw" => ("反转输出", "CCW output"),
        "direction" => ("方向输出（接通为反转）", "direction output (on: CCW)"),
        "ccw_locks" => ("反转锁紧（单向刀架）", "CCW locks (one-way post)"),
        "station_ms" => ("每刀位时间 ms", "time per station, ms"),
        "window_pct" => ("刀位信号宽度 %", "sensor window, %"),
        "code.first" => ("刀位信号首位", "station code, first bit"),
        "code.bits" => ("刀位信号位数", "station code, bits"),
        "code.encoding" => ("刀位编码", "station code, encoding"),
        "code.active_low" => ("低电平有效", "active low"),
        "in_position" => ("到位信号", "in-position signal"),
        "start_station" => ("上电刀位", "station at power-on"),
        "lock.unlock" => ("松开输出（锁紧级）", "unlock output (lock stage)"),
        "lock.ms" => ("松开/锁紧时间 ms", "unlock/lock time, ms"),
        "lock.unlocked" => ("松开到位开关", "unlocked switch"),
        "lock.locked" => ("锁紧到位开关", "locked switch"),
        "axis" => ("轴（0 = X）", "axis (0 = X)"),
        "from_mm" => ("范围起点 mm", "range from, mm"),
        "to_mm" => ("范围终点 mm", "range to, mm"),
        "active_low" => ("范围内为 0（常闭）", "0 inside (normally closed)"),
        "run" => ("运转条件", "runs while"),
        "arrival" => ("速度到达信号", "speed-arrival input"),
        "zero" => ("零速信号", "zero-speed input"),
        "ramp_ms" => ("加速时间 ms", "ramp time, ms"),
        "full_rpm" => ("加速时间对应转速", "rpm of the ramp time"),
        "tolerance_pct" => ("到达允差 %", "arrival tolerance, %"),
        "zero_rpm" => ("零速转速", "zero speed, rpm"),
        "pump" => ("泵输出", "pump output"),
        "pressure" => ("压力开关", "pressure switch"),
        "build_ms" => ("建压时间 ms", "pressure build time, ms"),
        "decay_ms" => ("泄压时间 ms", "pressure decay time, ms"),
        "level_low" => ("油位低开关", "level-low switch"),
        "operations" => ("油位低前的泵启动次数", "pump starts until level low"),
        "period_ms" => ("周期 ms", "period, ms"),
        "enable" => ("使能条件", "enabled while"),
        "source" => ("计数条件", "counts edges of"),
        "count" => ("计数值", "count"),
        _ => ("", ""),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use ladder_engine::devices::{DeviceKind, fields};

    #[test]
    fn every_field_of_every_kind_has_a_label_in_both_languages() {
        for kind in DeviceKind::templates() {
            for f in fields::fields(&kind) {
                let zh = field_label(f.name, Lang::Zh);
                assert!(crate::errors::has_cjk(zh), "{}: {zh}", f.name);
                assert!(!field_label(f.name, Lang::En).is_empty(), "{}", f.name);
            }
        }
    }
}
