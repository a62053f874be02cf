//! A device's parameters as a list of named fields, for the Machine page's form: each field's
//! text, what it holds, and the one parser that takes a typed
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

/// Why a typed text was refused (`ladder_text::errors::field_error` words it).
#[derive(Clone, Debug, PartialEq)]
pub enum FieldError {
    /// The device has no field of this name.
    NoField(String),
    /// The condition does not read.
    Condition(super::expr::ExprError),
    /// Not `true` or `false`.
    NotFlag(String),
    /// Not a length in mm within ±100000.
    NotLength(String),
    /// Not one of the station-code encodings.
    NotEncoding(String),
    /// Not a whole number within `lo..=hi`.
    NotNumber {
        /// The text typed.
        text: String,
        /// The least number.
        lo: u64,
        /// The greatest number.
        hi: u64,
    },
    /// The address does not read or is beyond the controller's range.
    Address(crate::address::AddressError),
    /// A byte address where a bit is needed.
    Byte(Address),
    /// Not an input (X) where the device writes one.
    NotInput(Address),
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
                    return Err(FieldError::NoField(name.to_string()));
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
                Err(e) => return Err(FieldError::Condition(e)),
            }
        }
        Slot::U32(v, lo, hi) => *v = number(text, u64::from(lo), u64::from(hi))? as u32,
        Slot::U8(v, lo, hi) => *v = number(text, u64::from(lo), u64::from(hi))? as u8,
        Slot::Flag(b) => {
            *b = match text.to_ascii_lowercase().as_str() {
                "true" | "1" | "yes" | "是" => true,
                "false" | "0" | "no" | "否" => false,
                _ => {
                    return Err(FieldError::NotFlag(text.to_string()));
                }
            }
        }
        Slot::Mm(v) => {
            *v = text
                .parse::<f64>()
                .ok()
                .filter(|v| v.is_finite() && v.abs() <= 100_000.0)
                .ok_or_else(|| FieldError::NotLength(text.to_string()))?
        }
        Slot::Enc(e) => {
            *e = Encoding::ALL
                .into_iter()
                .find(|e| format!("{e:?}").eq_ignore_ascii_case(text))
                .ok_or_else(|| FieldError::NotEncoding(text.to_string()))?
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
        .ok_or_else(|| FieldError::NotNumber {
            text: text.to_string(),
            lo,
            hi,
        })
}

fn address(text: &str, input: bool, profile: &Profile) -> Result<Address, FieldError> {
    let a = Address::parse_in(text, profile).map_err(FieldError::Address)?;
    if a.bit.is_none() {
        return Err(FieldError::Byte(a));
    }
    if input && a.area != Area::X {
        return Err(FieldError::NotInput(a));
    }
    Ok(a)
}
