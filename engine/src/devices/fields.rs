//! A device's parameters as a list of named fields, for the Machine page's form: each field's
//! text, what it holds, its label in both languages, and the one parser that takes a typed
//! text into the device or says why not. One list per kind (`slots`) drives reading and
//! writing, so the form and the model cannot disagree.

use super::model::{DeviceKind, Encoding, TurretLock};
use crate::address::{Address, Area};
use crate::profile::Profile;

/// What a field holds.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FieldKind {
    /// An input bit the device writes (X).
    Input,
    /// An output bit the device reads.
    Output,
    /// A condition (docs/machine.md, "Expressions").
    Condition,
    /// A whole number.
    Number,
    /// A number of mm.
    Millimetres,
    /// Yes or no.
    Flag,
    /// A station-code encoding.
    Encoding,
}

/// One field as the form shows it.
#[derive(Clone, Debug, PartialEq)]
pub struct Field {
    /// Its name (`travel_ms`), as scripts and messages name it.
    pub name: &'static str,
    /// What it holds.
    pub kind: FieldKind,
    /// Whether it may be left empty (an optional binding).
    pub optional: bool,
    /// Its value as text.
    pub text: String,
}

/// Why a typed text was refused, in both languages.
#[derive(Clone, Debug, PartialEq)]
pub struct FieldError {
    /// English.
    pub en: String,
    /// Chinese.
    pub zh: String,
}

fn err(en: String, zh: String) -> FieldError {
    FieldError { en, zh }
}

enum Slot<'a> {
    Addr(&'a mut Address, bool),
    OptAddr(&'a mut Option<Address>, bool),
    Text(&'a mut String),
    U32(&'a mut u32, u32, u32),
    U8(&'a mut u8, u8, u8),
    Flag(&'a mut bool),
    Mm(&'a mut f64),
    Enc(&'a mut Encoding),
    /// The turret's lock stage, by its unlock output (empty: none).
    Lock(&'a mut Option<TurretLock>),
}

/// Every field of a kind, in form order.
fn slots(kind: &mut DeviceKind) -> Vec<(&'static str, Slot<'_>)> {
    use Slot::*;
    match kind {
        DeviceKind::Follower(l) | DeviceKind::Expression(l) => vec![
            ("input", Addr(&mut l.input, true)),
            ("when", Text(&mut l.when)),
            ("on_ms", U32(&mut l.on_ms, 0, 3_600_000)),
            ("off_ms", U32(&mut l.off_ms, 0, 3_600_000)),
        ],
        DeviceKind::Actuator(a) => vec![
            ("advance", Addr(&mut a.advance, false)),
            ("retract", OptAddr(&mut a.retract, false)),
            ("travel_ms", U32(&mut a.travel_ms, 1, 600_000)),
            ("at_advanced", OptAddr(&mut a.at_advanced, true)),
            ("at_retracted", OptAddr(&mut a.at_retracted, true)),
            ("moving", OptAddr(&mut a.moving, true)),
            ("start_advanced", Flag(&mut a.start_advanced)),
        ],
        DeviceKind::Turret(t) => {
            let mut v = vec![
                ("stations", U8(&mut t.stations, 2, 32)),
                ("cw", Addr(&mut t.cw, false)),
                ("ccw", OptAddr(&mut t.ccw, false)),
                ("direction", OptAddr(&mut t.direction, false)),
                ("ccw_locks", Flag(&mut t.ccw_locks)),
                ("station_ms", U32(&mut t.station_ms, 1, 600_000)),
                ("window_pct", U8(&mut t.window_pct, 1, 100)),
                ("code.first", Addr(&mut t.code.first, true)),
                ("code.bits", U8(&mut t.code.bits, 1, 32)),
                ("code.encoding", Enc(&mut t.code.encoding)),
                ("code.active_low", Flag(&mut t.code.active_low)),
                ("in_position", OptAddr(&mut t.in_position, true)),
                ("start_station", U8(&mut t.start_station, 1, 32)),
            ];
            // The lock stage's own fields follow from `lock_slots` when it exists.
            v.push(("lock.unlock", Lock(&mut t.lock)));
            v
        }
        DeviceKind::PositionSwitch(p) => vec![
            ("input", Addr(&mut p.input, true)),
            ("axis", U8(&mut p.axis, 0, 4)),
            ("from_mm", Mm(&mut p.from_mm)),
            ("to_mm", Mm(&mut p.to_mm)),
            ("active_low", Flag(&mut p.active_low)),
        ],
        DeviceKind::Spindle(s) => vec![
            ("run", Text(&mut s.run)),
            ("arrival", OptAddr(&mut s.arrival, true)),
            ("zero", OptAddr(&mut s.zero, true)),
            ("ramp_ms", U32(&mut s.ramp_ms, 0, 600_000)),
            ("full_rpm", U32(&mut s.full_rpm, 1, 100_000)),
            ("tolerance_pct", U8(&mut s.tolerance_pct, 0, 100)),
            ("zero_rpm", U32(&mut s.zero_rpm, 0, 100_000)),
        ],
        DeviceKind::Lubrication(l) => vec![
            ("pump", Addr(&mut l.pump, false)),
            ("pressure", OptAddr(&mut l.pressure, true)),
            ("build_ms", U32(&mut l.build_ms, 0, 3_600_000)),
            ("decay_ms", U32(&mut l.decay_ms, 0, 3_600_000)),
            ("level_low", OptAddr(&mut l.level_low, true)),
            ("operations", U32(&mut l.operations, 0, 100_000_000)),
        ],
        DeviceKind::Pulse(p) => vec![
            ("input", Addr(&mut p.input, true)),
            ("period_ms", U32(&mut p.period_ms, 1, 3_600_000)),
            ("on_ms", U32(&mut p.on_ms, 0, 3_600_000)),
            ("enable", Text(&mut p.enable)),
        ],
        DeviceKind::Counter(c) => vec![
            ("input", Addr(&mut c.input, true)),
            ("source", Text(&mut c.source)),
            ("count", U32(&mut c.count, 1, 100_000_000)),
        ],
    }
}

/// The lock stage's own fields, when the turret has one.
fn lock_slots(kind: &mut DeviceKind) -> Vec<(&'static str, Slot<'_>)> {
    match kind {
        DeviceKind::Turret(t) => match &mut t.lock {
            Some(l) => vec![
                ("lock.ms", Slot::U32(&mut l.ms, 0, 600_000)),
                ("lock.unlocked", Slot::OptAddr(&mut l.unlocked, true)),
                ("lock.locked", Slot::OptAddr(&mut l.locked, true)),
            ],
            None => Vec::new(),
        },
        _ => Vec::new(),
    }
}

fn addr_text(a: &Option<Address>) -> String {
    a.map(|a| a.to_string()).unwrap_or_default()
}

/// Every field of a device kind with its text.
pub fn fields(kind: &DeviceKind) -> Vec<Field> {
    let mut copy = kind.clone();
    let mut out: Vec<Field> = slots(&mut copy)
        .into_iter()
        .map(|(name, s)| field(name, s))
        .collect();
    let mut copy = kind.clone();
    out.extend(
        lock_slots(&mut copy)
            .into_iter()
            .map(|(name, s)| field(name, s)),
    );
    out
}

fn field(name: &'static str, s: Slot<'_>) -> Field {
    let (kind, optional, text) = match s {
        Slot::Addr(a, input) => (io(input), false, a.to_string()),
        Slot::OptAddr(a, input) => (io(input), true, addr_text(a)),
        Slot::Text(t) => (FieldKind::Condition, true, t.clone()),
        Slot::U32(v, ..) => (FieldKind::Number, false, v.to_string()),
        Slot::U8(v, ..) => (FieldKind::Number, false, v.to_string()),
        Slot::Flag(b) => (FieldKind::Flag, false, b.to_string()),
        Slot::Mm(v) => (FieldKind::Millimetres, false, format!("{v}")),
        Slot::Enc(e) => (FieldKind::Encoding, false, format!("{e:?}")),
        Slot::Lock(l) => (
            FieldKind::Output,
            true,
            l.as_ref().map(|l| l.unlock.to_string()).unwrap_or_default(),
        ),
    };
    Field {
        name,
        kind,
        optional,
        text,
    }
}

fn io(input: bool) -> FieldKind {
    if input {
        FieldKind::Input
    } else {
        FieldKind::Output
    }
}

/// Takes a typed text into field `name` of a device, or says why not. Conditions are only
/// read here for their form; the whole model's check names unknown devices.
pub fn set(
    kind: &mut DeviceKind,
    name: &str,
    text: &str,
    profile: &Profile,
) -> Result<(), FieldError> {
    let text = text.trim();
    let mut all = slots(kind);
    let slot = match all.iter().position(|(n, _)| *n == name) {
        Some(k) => all.swap_remove(k).1,
        None => {
            drop(all);
            let mut locks = lock_slots(kind);
            match locks.iter().position(|(n, _)| *n == name) {
                Some(k) => locks.swap_remove(k).1,
                None => {
                    return Err(err(
                        format!("no field `{name}`"),
                        format!("没有字段 `{name}`"),
                    ));
                }
            }
        }
    };
    match slot {
        Slot::Addr(a, input) => *a = address(text, input, profile)?,
        Slot::OptAddr(a, input) => {
            *a = if text.is_empty() {
                None
            } else {
                Some(address(text, input, profile)?)
            }
        }
        Slot::Text(t) => {
            let names = super::expr::Names {
                devices: &[],
                states: true,
            };
            match super::expr::parse(text, profile, &names) {
                Ok(_) | Err(super::expr::ExprError::UnknownDevice(_)) => *t = text.to_string(),
                Err(e) => return Err(err(e.to_string(), e.zh())),
            }
        }
        Slot::U32(v, lo, hi) => *v = number(text, u64::from(lo), u64::from(hi))? as u32,
        Slot::U8(v, lo, hi) => *v = number(text, u64::from(lo), u64::from(hi))? as u8,
        Slot::Flag(b) => {
            *b = match text.to_ascii_lowercase().as_str() {
                "true" | "1" | "yes" | "是" => true,
                "false" | "0" | "no" | "否" => false,
                _ => {
                    return Err(err(
                        format!("`{text}`: write true or false"),
                        format!("`{text}`：请写 true 或 false"),
                    ));
                }
            }
        }
        Slot::Mm(v) => {
            *v = text
                .parse::<f64>()
                .ok()
                .filter(|v| v.is_finite() && v.abs() <= 100_000.0)
                .ok_or_else(|| {
                    err(
                        format!("`{text}` is not a length in mm (−100000…100000)"),
                        format!("`{text}` 不是以 mm 计的长度（−100000…100000）"),
                    )
                })?
        }
        Slot::Enc(e) => {
            *e = Encoding::ALL
                .into_iter()
                .find(|e| format!("{e:?}").eq_ignore_ascii_case(text))
                .ok_or_else(|| {
                    err(
                        format!("`{text}`: the encoding is Binary, Bcd, OneHot or Gray"),
                        format!("`{text}`：编码应为 Binary、Bcd、OneHot 或 Gray"),
                    )
                })?
        }
        Slot::Lock(l) => {
            *l = if text.is_empty() {
                None
            } else {
                let unlock = address(text, false, profile)?;
                Some(match l.take() {
                    Some(old) => TurretLock { unlock, ..old },
                    None => TurretLock {
                        unlock,
                        ms: 200,
                        unlocked: None,
                        locked: None,
                    },
                })
            }
        }
    }
    Ok(())
}

fn number(text: &str, lo: u64, hi: u64) -> Result<u64, FieldError> {
    text.parse::<u64>()
        .ok()
        .filter(|v| (lo..=hi).contains(v))
        .ok_or_else(|| {
            err(
                format!("`{text}`: write a whole number {lo}…{hi}"),
                format!("`{text}`：请写 {lo}…{hi} 的整数"),
            )
        })
}

fn address(text: &str, input: bool, profile: &Profile) -> Result<Address, FieldError> {
    let a = Address::parse_in(text, profile).map_err(|e| err(e.to_string(), e.zh()))?;
    if a.bit.is_none() {
        return Err(err(
            format!("{a} is a byte; write a bit address such as {a}.0"),
            format!("{a} 是字节，请写位地址（例如 {a}.0）"),
        ));
    }
    if input && a.area != Area::X {
        return Err(err(
            format!("{a} is not an input; a device writes X bits"),
            format!("{a} 不是输入；设备只写 X 位"),
        ));
    }
    Ok(a)
}

/// A field's label: (Chinese, English).
pub fn label(name: &str) -> (&'static str, &'static str) {
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
