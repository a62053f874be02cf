//! Why a `cnc` script command, a `cnc.KEY` name, an expected value or a read of the CNC was
//! refused (docs/cnc.md, "Script commands"). The variants hold what was written and the
//! numbers involved, never prose. The English (scripts, docs/cnc.md's examples) is
//! [`CncError::en`] and `Display`; `ladder_text::errors::cnc_error` words a refusal in either
//! language with the same specifics.

use super::AXIS_NAMES;
use super::data::WORK_SYSTEMS;
use super::params::{self, ParamError, Selector, TABLE};
use super::{Mode, RunState};
use std::fmt;

/// The subcommands, as a refusal of a missing or unknown one lists them.
pub const SUBCOMMANDS: [&str; 12] = [
    "program",
    "program-file",
    "mdi",
    "param",
    "offset",
    "workpiece",
    "macro",
    "position",
    "alarm",
    "reset",
    "handwheel",
    "clock",
];

/// The forms of `cnc.KEY`, as the refusal of an unknown key lists them.
pub const KEY_FORMS: [&str; 13] = [
    "cnc.mode",
    "cnc.run",
    "cnc.block",
    "cnc.prog",
    "cnc.pos.AXIS",
    "cnc.abs.AXIS",
    "cnc.spindle",
    "cnc.alarm.N",
    "cnc.alarms",
    "cnc.param.N[.SEL]",
    "cnc.offset.N.TYPE",
    "cnc.work.SYS.AXIS",
    "cnc.macro.N",
];

/// What an integer written in a command stands for, named in the refusal of a word that is
/// not an integer.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Quantity {
    /// The value of `cnc param`.
    ParamValue,
    /// The tip direction of `cnc offset N TIP`.
    TipDirection,
    /// The variable number of `cnc macro`.
    Variable,
    /// The number of `cnc alarm`.
    Alarm,
    /// The count of `cnc handwheel`.
    Pulses,
    /// An expected value of an integer `cnc.KEY`.
    Integer,
}

impl Quantity {
    /// Its name in English.
    fn name(self) -> &'static str {
        match self {
            Quantity::ParamValue => "a parameter value",
            Quantity::TipDirection => "the tip direction 0–9",
            Quantity::Variable => "a variable number",
            Quantity::Alarm => "an alarm number",
            Quantity::Pulses => "pulses",
            Quantity::Integer => "an integer",
        }
    }
}

/// A refused `cnc` command, `cnc.KEY`, expected value or CNC read.
///
/// Where a field `key` is present, `Some` is the `cnc.KEY` text the word `text` was part of
/// (the refusal then names both), `None` a word of a `cnc` command.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub enum CncError {
    /// `cnc` alone.
    NoSubcommand,
    /// `cnc WORD` with an unknown subcommand.
    UnknownCommand {
        /// The subcommand as written.
        text: String,
    },
    /// A command with the wrong number of words.
    Usage {
        /// Its usage after `cnc` (`offset N TYPE VALUE`).
        usage: &'static str,
    },
    /// `cnc program-file PATH` whose file could not be read.
    ReadFile {
        /// The path as written.
        path: String,
        /// What the reader said (it comes from the file system, in the run's language).
        message: String,
    },
    /// `cnc clock` with a text that is no date and time.
    NotClock {
        /// The text as written.
        text: String,
    },
    /// A length that is no number.
    NotMm {
        /// The text as written.
        text: String,
    },
    /// A length beyond ±99999.999 mm.
    MmRange {
        /// The text as written.
        text: String,
    },
    /// A word that should be an integer.
    NotInteger {
        /// The text as written.
        text: String,
        /// What the integer stands for.
        what: Quantity,
    },
    /// A parameter number, selector or value the parameter table refuses.
    Param {
        /// The parameter number.
        number: u16,
        /// What is wrong.
        error: ParamError,
    },
    /// A GSK980 parameter word (1–254) given a selector.
    Gsk980Selector {
        /// The parameter number.
        number: u16,
    },
    /// A GSK980 parameter word given a value beyond 32 bits.
    Gsk980Value {
        /// The parameter number.
        number: u16,
    },
    /// A parameter number that is no number.
    NotParamNumber {
        /// The text as written.
        text: String,
        /// The key it is part of.
        key: Option<String>,
    },
    /// An axis or spindle selector that is no number.
    NotSelector {
        /// The text as written.
        text: String,
        /// The key it is part of.
        key: Option<String>,
    },
    /// An axis that is neither a name nor 1–5.
    BadAxis {
        /// The text as written.
        text: String,
        /// The key it is part of.
        key: Option<String>,
    },
    /// A tool offset number outside the profile's offsets.
    OffsetNumber {
        /// The text as written.
        text: String,
        /// The key it is part of.
        key: Option<String>,
        /// The first offset number of the profile.
        first: u8,
        /// The last offset number of the profile.
        last: u8,
    },
    /// A tool offset type that is none of X Z R Y, WX WZ WR WY, TIP.
    OffsetType {
        /// The text as written.
        text: String,
        /// The key it is part of.
        key: Option<String>,
    },
    /// A workpiece system that is none of EXT, G54–G59.
    WorkSystem {
        /// The text as written.
        text: String,
        /// The key it is part of.
        key: Option<String>,
    },
    /// A tip direction outside 0–9.
    TipRange {
        /// The value given.
        value: i64,
    },
    /// A macro variable a script may not set.
    MacroNotWritable {
        /// The variable number.
        number: i64,
    },
    /// A macro value that is neither a decimal nor `vacant`.
    NotDecimal {
        /// The text as written.
        text: String,
    },
    /// A signal-bit variable (#1100–#1131) given other than 0 or 1.
    MacroSignalBit {
        /// The variable number.
        number: i64,
    },
    /// An alarm a script may not raise (outside 1–999, or one the machine raises).
    AlarmNotRaisable {
        /// The alarm number.
        number: i64,
    },
    /// More handwheel pulses than one exchange takes.
    HandwheelRange {
        /// The pulses given.
        pulses: i64,
    },
    /// A `cnc.KEY` of no known form.
    UnknownKey {
        /// The key as written.
        text: String,
    },
    /// `cnc.alarm.N` with N outside 1–9999.
    KeyAlarm {
        /// N as written.
        text: String,
        /// The key.
        key: String,
    },
    /// `cnc.macro.N` of a variable that does not exist.
    KeyMacro {
        /// N as written.
        text: String,
        /// The key.
        key: String,
    },
    /// An expected `cnc.mode` that is no mode.
    NotMode {
        /// The text as written.
        text: String,
    },
    /// An expected `cnc.run` that is no run state.
    NotRunState {
        /// The text as written.
        text: String,
    },
    /// An axis beyond the controlled axes (#8130).
    AxisBeyond {
        /// The axis slot (0 = X).
        axis: u8,
        /// The controlled axes.
        count: usize,
    },
    /// A read of a parameter the table does not have.
    NoParameter {
        /// The parameter number.
        number: u16,
    },
    /// A read of a tool offset the CNC does not have.
    NoOffset {
        /// The offset number.
        number: u8,
    },
    /// A workpiece system or axis the CNC does not have.
    NoWorkSlot,
    /// A `cnc.KEY` read from a machine without the simulated CNC.
    NoCnc,
    /// A `device.NAME` read from a machine without a machine model.
    NoMachineModel,
}

/// The name of axis slot `a`, as the refusals print it.
fn axis(a: u8) -> &'static str {
    AXIS_NAMES.get(usize::from(a)).copied().unwrap_or("?")
}

/// The written word, with the key it belongs to when there is one.
fn at_en(text: &str, key: &Option<String>) -> String {
    match key {
        Some(k) => format!("`{text}` in `{k}`"),
        None => format!("`{text}`"),
    }
}

/// The numbers of the parameter table, as the "no parameter" refusal lists them.
fn table_numbers() -> Vec<String> {
    TABLE.iter().map(|s| format!("{:04}", s.number)).collect()
}

/// The selector or range a parameter takes (the number was checked first).
fn spec(number: u16) -> &'static params::ParamSpec {
    params::spec(number).expect("a selector or value error names a known parameter")
}

fn param_en(number: u16, error: ParamError) -> String {
    match error {
        ParamError::Number => format!(
            "no parameter {number} (the simulator has {})",
            table_numbers().join(", ")
        ),
        ParamError::Selector => match spec(number).selector {
            Selector::None => format!("parameter {number} takes no axis or spindle number"),
            Selector::Axis => format!("parameter {number} needs an axis number 1–5"),
            Selector::Spindle => format!("parameter {number} needs a spindle number 1–4"),
        },
        ParamError::Value => {
            let s = spec(number);
            format!("parameter {number} is {}…{}", s.min, s.max)
        }
    }
}

impl CncError {
    /// The refusal in English, as scripts print it and docs/cnc.md quotes it.
    pub fn en(&self) -> String {
        match self {
            CncError::NoSubcommand => {
                format!("`cnc` needs a subcommand ({})", SUBCOMMANDS.join(", "))
            }
            CncError::UnknownCommand { text } => format!(
                "unknown cnc command `{text}` (commands: {})",
                SUBCOMMANDS.join(", ")
            ),
            CncError::Usage { usage } => format!("usage: cnc {usage}"),
            // The reader words its own refusal, path included.
            CncError::ReadFile { message, .. } => message.clone(),
            CncError::NotClock { text } => {
                format!("`{text}` is not a date and time YYYY-MM-DDTHH:MM:SS")
            }
            CncError::NotMm { text } => format!("`{text}` is not a number of mm"),
            CncError::MmRange { text } => format!("{text} mm is beyond ±99999.999 mm"),
            CncError::NotInteger { text, what } => {
                format!("`{text}` is not an integer ({})", what.name())
            }
            CncError::Param { number, error } => param_en(*number, *error),
            CncError::Gsk980Selector { number } => {
                format!("GSK980 parameter {number} takes no selector")
            }
            CncError::Gsk980Value { number } => {
                format!("GSK980 parameter {number} holds a 32-bit integer")
            }
            CncError::NotParamNumber { text, key } => {
                format!("{} is not a parameter number", at_en(text, key))
            }
            CncError::NotSelector { text, key } => {
                format!("{} is not an axis or spindle number", at_en(text, key))
            }
            CncError::BadAxis { text, key } => {
                format!("{}: the axis is X, Z, Y, 4, 5 or 1–5", at_en(text, key))
            }
            CncError::OffsetNumber {
                text,
                key,
                first,
                last,
            } => format!("{}: tool offsets are {first}–{last}", at_en(text, key)),
            CncError::OffsetType { text, key } => format!(
                "{}: the type is X Z R Y, WX WZ WR WY or TIP",
                at_en(text, key)
            ),
            CncError::WorkSystem { text, key } => format!(
                "{}: the system is {}",
                at_en(text, key),
                WORK_SYSTEMS.join(", ")
            ),
            CncError::TipRange { value } => format!("the tip direction is 0–9, not {value}"),
            CncError::MacroNotWritable { number } => format!(
                "#{number} cannot be set: the variables are #1–#33 (the current level's locals), #100–#199, #500–#999 and #1100–#1131"
            ),
            CncError::NotDecimal { text } => {
                format!("`{text}` is not a decimal number or `vacant`")
            }
            CncError::MacroSignalBit { number } => format!("#{number} is a signal bit: 0 or 1"),
            CncError::AlarmNotRaisable { number } => format!(
                "alarm {number} cannot be raised by a script: 1–999 except 500, 501, 506, 507 and 950 (those come from the machine)"
            ),
            CncError::HandwheelRange { pulses } => {
                format!("{pulses} pulses: the count is −10000…10000")
            }
            CncError::UnknownKey { text } => {
                format!("unknown CNC value `{text}` ({})", KEY_FORMS.join(", "))
            }
            CncError::KeyAlarm { text, key } => {
                format!("`{text}` in `{key}`: alarm numbers are 1–9999")
            }
            CncError::KeyMacro { text, key } => format!(
                "`{text}` in `{key}`: no such variable (the variables are #1–#33, #100–#199, #500–#999, #1000–#1133, #2001–#2964, #3000–#3012, #4001–#4130 and #5001–#5340: docs/gcode.md, \"Macros\")"
            ),
            CncError::NotMode { text } => format!(
                "`{text}` is not a mode ({})",
                Mode::ALL.map(Mode::name).join(" ")
            ),
            CncError::NotRunState { text } => format!(
                "`{text}` is not a run state ({})",
                RunState::ALL.map(RunState::name).join(" ")
            ),
            CncError::AxisBeyond { axis: a, count } => format!(
                "axis {} is beyond the {count} controlled axes (#8130)",
                axis(*a)
            ),
            CncError::NoParameter { number } => format!("no parameter {number}"),
            CncError::NoOffset { number } => format!("no tool offset {number}"),
            CncError::NoWorkSlot => "no such workpiece system or axis".into(),
            CncError::NoCnc => "no CNC is attached".into(),
            CncError::NoMachineModel => "no machine model is running".into(),
        }
    }
}

/// The English, for the many places that print a refusal as scripts do.
impl fmt::Display for CncError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.en())
    }
}

impl std::error::Error for CncError {}
