//! The machine model as plain data saved with the project (docs/machine.md): the devices
//! around the CNC, each a kind with its timings in ms and its address bindings. What a
//! device reads are PLC outputs (any bit address, usually Y) or CNC values; what it writes
//! are PLC inputs (X bits).

use crate::address::Address;
use serde::{Deserialize, Serialize};

/// The machine around the CNC: its devices and where the axes stand at power-on.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct MachineModel {
    /// The devices, in the order they run each tick.
    pub devices: Vec<Device>,
    /// Where each axis physically stands at power-on, mm from its reference point (X as a
    /// diameter). An axis not listed starts at 0. Position switches see this position, which
    /// a reference return does not move (it only sets the CNC's machine coordinate).
    #[serde(default)]
    pub start_mm: Vec<f64>,
}

impl MachineModel {
    /// Whether the model has no device (a project without a machine).
    pub fn is_empty(&self) -> bool {
        self.devices.is_empty() && self.start_mm.is_empty()
    }

    /// The device named `name` (names compare without case).
    pub fn position(&self, name: &str) -> Option<usize> {
        self.devices
            .iter()
            .position(|d| d.name.eq_ignore_ascii_case(name))
    }
}

/// One device: a name the scripts and expressions use, and what it is.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Device {
    /// A name: letters, digits and `_`, starting with a letter (`chuck`, `turret`).
    pub name: String,
    /// What it is and how it is wired.
    pub kind: DeviceKind,
}

/// The kinds of device.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub enum DeviceKind {
    /// An input that follows a boolean of outputs after on and off delays (pump running,
    /// pressure switch, contactor feedback).
    Follower(Logic),
    /// Two end positions with a travel time and end switches (chuck, tailstock, door).
    Actuator(Actuator),
    /// A tool turret or indexer with N stations.
    Turret(Turret),
    /// An input on while an axis's physical position lies in a range (dogs, limits, cams).
    PositionSwitch(PositionSwitch),
    /// Speed-arrival and zero-speed inputs from the CNC's spindle output.
    Spindle(SpindleFeedback),
    /// A lubrication unit: pressure switch and oil level.
    Lubrication(Lubrication),
    /// A periodic input (a part counter's sensor, a clock).
    Pulse(Pulse),
    /// An input that comes on after K rising edges of a condition (end of bar, parts bin
    /// full).
    Counter(Counter),
    /// The escape hatch: an input := a boolean expression of addresses and device states.
    Expression(Logic),
}

impl DeviceKind {
    /// The kind's name as scripts and the Machine page write it.
    pub fn name(&self) -> &'static str {
        match self {
            DeviceKind::Follower(_) => "follower",
            DeviceKind::Actuator(_) => "actuator",
            DeviceKind::Turret(_) => "turret",
            DeviceKind::PositionSwitch(_) => "position-switch",
            DeviceKind::Spindle(_) => "spindle",
            DeviceKind::Lubrication(_) => "lubrication",
            DeviceKind::Pulse(_) => "pulse",
            DeviceKind::Counter(_) => "counter",
            DeviceKind::Expression(_) => "expression",
        }
    }

    /// Every kind with default parameters, in the order the Machine page offers them.
    pub fn templates() -> Vec<DeviceKind> {
        let x = Address::parse("X0000.0").expect("a valid address");
        let y = Address::parse("Y0000.0").expect("a valid address");
        vec![
            DeviceKind::Follower(Logic {
                input: x,
                when: "Y0000.0".into(),
                on_ms: 100,
                off_ms: 100,
            }),
            DeviceKind::Actuator(Actuator {
                advance: y,
                retract: None,
                travel_ms: 500,
                at_advanced: Some(x),
                at_retracted: None,
                moving: None,
                start_advanced: false,
            }),
            DeviceKind::Turret(Turret {
                stations: 4,
                cw: y,
                ccw: None,
                direction: None,
                ccw_locks: false,
                station_ms: 500,
                window_pct: 30,
                lock: None,
                code: StationCode {
                    first: x,
                    bits: 4,
                    encoding: Encoding::OneHot,
                    active_low: false,
                },
                in_position: None,
                start_station: 1,
            }),
            DeviceKind::PositionSwitch(PositionSwitch {
                input: x,
                axis: 0,
                from_mm: -5.0,
                to_mm: 0.0,
                active_low: false,
            }),
            DeviceKind::Spindle(SpindleFeedback {
                run: String::new(),
                arrival: Some(x),
                zero: None,
                ramp_ms: 1000,
                full_rpm: 3000,
                tolerance_pct: 10,
                zero_rpm: 10,
            }),
            DeviceKind::Lubrication(Lubrication {
                pump: y,
                pressure: Some(x),
                build_ms: 2000,
                decay_ms: 3000,
                level_low: None,
                operations: 0,
            }),
            DeviceKind::Pulse(Pulse {
                input: x,
                period_ms: 1000,
                on_ms: 100,
                enable: String::new(),
            }),
            DeviceKind::Counter(Counter {
                input: x,
                source: "Y0000.0".into(),
                count: 10,
            }),
            DeviceKind::Expression(Logic {
                input: x,
                when: "Y0000.0 & !Y0000.1".into(),
                on_ms: 0,
                off_ms: 0,
            }),
        ]
    }

    /// The PLC inputs the device writes, with a name for each binding.
    pub fn inputs(&self) -> Vec<(&'static str, Address)> {
        let mut v = Vec::new();
        let mut put = |name, a: Option<Address>| {
            if let Some(a) = a {
                v.push((name, a));
            }
        };
        match self {
            DeviceKind::Follower(l) | DeviceKind::Expression(l) => put("input", Some(l.input)),
            DeviceKind::Actuator(a) => {
                put("at_advanced", a.at_advanced);
                put("at_retracted", a.at_retracted);
                put("moving", a.moving);
            }
            DeviceKind::Turret(t) => {
                for k in 0..t.code.bits {
                    put("code", t.code.first.offset_bits(u32::from(k)));
                }
                put("in_position", t.in_position);
                if let Some(l) = &t.lock {
                    put("unlocked", l.unlocked);
                    put("locked", l.locked);
                }
            }
            DeviceKind::PositionSwitch(p) => put("input", Some(p.input)),
            DeviceKind::Spindle(s) => {
                put("arrival", s.arrival);
                put("zero", s.zero);
            }
            DeviceKind::Lubrication(l) => {
                put("pressure", l.pressure);
                put("level_low", l.level_low);
            }
            DeviceKind::Pulse(p) => put("input", Some(p.input)),
            DeviceKind::Counter(c) => put("input", Some(c.input)),
        }
        v
    }

    /// The outputs the device reads by address (expressions are read separately).
    pub fn outputs(&self) -> Vec<(&'static str, Address)> {
        let mut v = Vec::new();
        match self {
            DeviceKind::Actuator(a) => {
                v.push(("advance", a.advance));
                if let Some(r) = a.retract {
                    v.push(("retract", r));
                }
            }
            DeviceKind::Turret(t) => {
                v.push(("cw", t.cw));
                if let Some(c) = t.ccw {
                    v.push(("ccw", c));
                }
                if let Some(d) = t.direction {
                    v.push(("direction", d));
                }
                if let Some(l) = &t.lock {
                    v.push(("unlock", l.unlock));
                }
            }
            DeviceKind::Lubrication(l) => v.push(("pump", l.pump)),
            _ => {}
        }
        v
    }

    /// The expressions the device reads: (field, text).
    pub fn expressions(&self) -> Vec<(&'static str, &str)> {
        match self {
            DeviceKind::Follower(l) | DeviceKind::Expression(l) => vec![("when", &l.when)],
            DeviceKind::Spindle(s) => vec![("run", &s.run)],
            DeviceKind::Pulse(p) => vec![("enable", &p.enable)],
            DeviceKind::Counter(c) => vec![("source", &c.source)],
            _ => Vec::new(),
        }
    }

    /// The boolean states other devices' expressions may name as `NAME.state`.
    pub fn states(&self) -> &'static [&'static str] {
        match self {
            DeviceKind::Follower(_)
            | DeviceKind::Expression(_)
            | DeviceKind::PositionSwitch(_)
            | DeviceKind::Pulse(_)
            | DeviceKind::Counter(_) => &["on"],
            DeviceKind::Actuator(_) => &["advanced", "retracted", "moving"],
            DeviceKind::Turret(_) => &["moving", "in_position", "locked"],
            DeviceKind::Spindle(_) => &["at_speed", "stopped"],
            DeviceKind::Lubrication(_) => &["pressure", "low"],
        }
    }
}

/// A follower or an expression device: `input` follows `when` after the delays.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Logic {
    /// The input it writes.
    pub input: Address,
    /// The condition (docs/machine.md, "Expressions"); a follower's names addresses only.
    pub when: String,
    /// How long `when` must hold before the input comes on, ms.
    pub on_ms: u32,
    /// How long `when` must be false before the input goes off, ms.
    pub off_ms: u32,
}

/// A two-position actuator: a cylinder with one or two solenoids.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Actuator {
    /// The output that drives it to its advanced end (the chuck's clamp solenoid).
    pub advance: Address,
    /// The output that drives it back; none: a spring returns it when `advance` is off.
    pub retract: Option<Address>,
    /// Travel time from end to end, ms.
    pub travel_ms: u32,
    /// The switch on at the advanced end.
    pub at_advanced: Option<Address>,
    /// The switch on at the retracted end.
    pub at_retracted: Option<Address>,
    /// An input on while it travels (mid-travel state).
    pub moving: Option<Address>,
    /// Whether it starts at the advanced end.
    pub start_advanced: bool,
}

/// How a turret's station is coded on its sensor inputs.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub enum Encoding {
    /// The station number in binary.
    Binary,
    /// The station number in BCD.
    Bcd,
    /// One input per station.
    OneHot,
    /// The station number in Gray code.
    Gray,
}

impl Encoding {
    /// Every encoding.
    pub const ALL: [Encoding; 4] = [
        Encoding::Binary,
        Encoding::Bcd,
        Encoding::OneHot,
        Encoding::Gray,
    ];

    /// The code of station `s` (1…), without polarity; 0 codes no station.
    pub fn code(self, s: u32) -> u32 {
        match self {
            Encoding::Binary => s,
            Encoding::Bcd => ((s / 10) << 4) | (s % 10),
            Encoding::OneHot => {
                if s == 0 {
                    0
                } else {
                    1 << (s - 1)
                }
            }
            Encoding::Gray => s ^ (s >> 1),
        }
    }

    /// How many bits `stations` need.
    pub fn bits_for(self, stations: u32) -> u32 {
        let top = (1..=stations).map(|s| self.code(s)).max().unwrap_or(0);
        32 - top.leading_zeros()
    }
}

/// The station sensors of a turret.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct StationCode {
    /// The input of the code's lowest bit; the others follow bit by bit (X0.7 → X1.0).
    pub first: Address,
    /// How many inputs.
    pub bits: u8,
    /// How the station is coded.
    pub encoding: Encoding,
    /// Inputs read 0 when active.
    pub active_low: bool,
}

/// A turret's lock stage: it turns only while unlocked.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct TurretLock {
    /// The output that unlocks it.
    pub unlock: Address,
    /// Unlocking (and locking again) takes this long, ms.
    pub ms: u32,
    /// The input on while unlocked.
    pub unlocked: Option<Address>,
    /// The input on while locked.
    pub locked: Option<Address>,
}

/// A turret or indexer.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Turret {
    /// Number of stations, 2…32.
    pub stations: u8,
    /// The output that turns it CW (with `direction`: the run output).
    pub cw: Address,
    /// The output that turns it CCW (or locks it, with `ccw_locks`).
    pub ccw: Option<Address>,
    /// One run output and a direction: this output on turns it CCW.
    pub direction: Option<Address>,
    /// CCW does not turn it back but pulls it onto the station's pawl and locks it (the
    /// one-way electric tool post).
    pub ccw_locks: bool,
    /// Time from one station to the next, ms.
    pub station_ms: u32,
    /// The share of the way between two stations over which a station's sensor is on,
    /// centred on the station, %.
    pub window_pct: u8,
    /// The lock/unlock stage, if it has one.
    pub lock: Option<TurretLock>,
    /// The station sensors.
    pub code: StationCode,
    /// An input on while it stands at a station.
    pub in_position: Option<Address>,
    /// The station it stands at, at power-on.
    pub start_station: u8,
}

/// A switch worked by an axis.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct PositionSwitch {
    /// The input it writes.
    pub input: Address,
    /// The axis, 0 = the first (X).
    pub axis: u8,
    /// The range's low end, mm (X as a diameter).
    pub from_mm: f64,
    /// The range's high end, mm.
    pub to_mm: f64,
    /// The input reads 0 inside the range (a normally closed deceleration dog or limit).
    pub active_low: bool,
}

/// The spindle drive's feedback.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct SpindleFeedback {
    /// While this holds the motor follows the CNC's S output (empty: always).
    pub run: String,
    /// The speed-arrival input.
    pub arrival: Option<Address>,
    /// The zero-speed input.
    pub zero: Option<Address>,
    /// Time to go from 0 to `full_rpm`, ms.
    pub ramp_ms: u32,
    /// The speed the ramp time is given for.
    pub full_rpm: u32,
    /// Arrival within this share of the commanded speed, %.
    pub tolerance_pct: u8,
    /// Zero speed at or below this speed.
    pub zero_rpm: u32,
}

/// A lubrication unit.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Lubrication {
    /// The pump output.
    pub pump: Address,
    /// The pressure switch.
    pub pressure: Option<Address>,
    /// Pressure is up after the pump has run this long, ms.
    pub build_ms: u32,
    /// Pressure is gone after the pump has stopped this long, ms.
    pub decay_ms: u32,
    /// The level-low switch.
    pub level_low: Option<Address>,
    /// Pump starts until the level is low (0: never).
    pub operations: u32,
}

/// A periodic input.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Pulse {
    /// The input it writes.
    pub input: Address,
    /// Period, ms.
    pub period_ms: u32,
    /// On time in each period, ms.
    pub on_ms: u32,
    /// It pulses while this holds (empty: always).
    pub enable: String,
}

/// An input on after K rising edges of a condition.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Counter {
    /// The input it writes.
    pub input: Address,
    /// The condition whose rising edges it counts.
    pub source: String,
    /// Edges until the input comes on.
    pub count: u32,
}
