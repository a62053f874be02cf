//! Why a `cnc` script command, a `cnc.KEY` name, an expected value or a read of the CNC was
//! refused (docs/cnc.md, "Script commands"). The variants hold what was written and the
//! numbers involved, never prose, so the same refusal can be worded in English (scripts,
//! docs/cnc.md's examples) and in Chinese (a Chinese run, the editor) with the same specifics.

use super::AXIS_NAMES;
use super::data::WORK_SYSTEMS;
use super::params::{self, ParamError, Selector, TABLE};
use super::{Mode, RunState};
use std::fmt;

/// The subcommands, as a refusal of a missing or unknown one lists them.
const SUBCOMMANDS: [&str; 12] = [
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
const KEY_FORMS: [&str; 13] = [
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
    /// Its name in English and in Chinese.
    fn names(self) -> (&'static str, &'static str) {
        match self {
            Quantity::ParamValue => ("a parameter value", "参数值"),
            Quantity::TipDirection => ("the tip direction 0–9", "刀尖方向 0–9"),
            Quantity::Variable => ("a variable number", "宏变量号"),
            Quantity::Alarm => ("an alarm number", "报警号"),
            Quantity::Pulses => ("pulses", "手轮脉冲数"),
            Quantity::Integer => ("an integer", "整数"),
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

/// [`at_en`] in Chinese.
fn at_zh(text: &str, key: &Option<String>) -> String {
    match key {
        Some(k) => format!("`{k}` 中的 `{text}`"),
        None => format!("`{text}`"),
    }
}

fn is_cjk(c: char) -> bool {
    ('\u{4e00}'..='\u{9fff}').contains(&c)
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

fn param_zh(number: u16, error: ParamError) -> String {
    match error {
        ParamError::Number => format!(
            "没有参数 {number}（模拟器的参数为 {}）",
            table_numbers().join("、")
        ),
        ParamError::Selector => match spec(number).selector {
            Selector::None => format!("参数 {number} 不带轴号或主轴号"),
            Selector::Axis => format!("参数 {number} 需要轴号 1–5"),
            Selector::Spindle => format!("参数 {number} 需要主轴号 1–4"),
        },
        ParamError::Value => {
            let s = spec(number);
            format!("参数 {number} 的范围为 {}…{}", s.min, s.max)
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
                format!("`{text}` is not an integer ({})", what.names().0)
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

    /// The refusal in Chinese, in the words of the GSK manuals, with the same specifics as
    /// [`CncError::en`]: the words written, the numbers, the usage in backticks.
    pub fn zh(&self) -> String {
        match self {
            CncError::NoSubcommand => {
                format!("`cnc` 需要子命令（{}）", SUBCOMMANDS.join("、"))
            }
            CncError::UnknownCommand { text } => format!(
                "未知的 CNC 命令 `{text}`（命令：{}）",
                SUBCOMMANDS.join("、")
            ),
            CncError::Usage { usage } => format!("用法：`cnc {usage}`"),
            // A reader that already speaks Chinese (the command line in a Chinese run) names
            // the file itself; an English one is the system's text, given after ours.
            CncError::ReadFile { path, message } => {
                if message.chars().any(is_cjk) {
                    message.clone()
                } else {
                    format!("无法读取程序文件 `{path}`：{message}")
                }
            }
            CncError::NotClock { text } => {
                format!("`{text}` 不是日期时间（格式为 `YYYY-MM-DDTHH:MM:SS`）")
            }
            CncError::NotMm { text } => format!("`{text}` 不是以 mm 为单位的数值"),
            CncError::MmRange { text } => format!("{text} mm 超出 ±99999.999 mm"),
            CncError::NotInteger { text, what } => {
                format!("`{text}` 不是整数（{}）", what.names().1)
            }
            CncError::Param { number, error } => param_zh(*number, *error),
            CncError::Gsk980Selector { number } => {
                format!("GSK980 的参数 {number} 不带轴号或主轴号")
            }
            CncError::Gsk980Value { number } => {
                format!("GSK980 的参数 {number} 是 32 位整数")
            }
            CncError::NotParamNumber { text, key } => {
                format!("{} 不是参数号", at_zh(text, key))
            }
            CncError::NotSelector { text, key } => {
                format!("{} 不是轴号或主轴号", at_zh(text, key))
            }
            CncError::BadAxis { text, key } => {
                format!("{}：轴应为 X、Z、Y、4、5 或 1–5", at_zh(text, key))
            }
            CncError::OffsetNumber {
                text,
                key,
                first,
                last,
            } => format!("{}：刀补号为 {first}–{last}", at_zh(text, key)),
            CncError::OffsetType { text, key } => format!(
                "{}：刀具偏置的类型为 X Z R Y、WX WZ WR WY 或 TIP",
                at_zh(text, key)
            ),
            CncError::WorkSystem { text, key } => format!(
                "{}：工件坐标系为 {}",
                at_zh(text, key),
                WORK_SYSTEMS.join("、")
            ),
            CncError::TipRange { value } => format!("刀尖方向为 0–9，不是 {value}"),
            CncError::MacroNotWritable { number } => format!(
                "宏变量 #{number} 不能设定：可设定的宏变量为 #1–#33（当前层的局部变量）、#100–#199、#500–#999 和 #1100–#1131"
            ),
            CncError::NotDecimal { text } => {
                format!("`{text}` 不是十进制数，也不是 `vacant`")
            }
            CncError::MacroSignalBit { number } => {
                format!("宏变量 #{number} 是信号位：只能为 0 或 1")
            }
            CncError::AlarmNotRaisable { number } => format!(
                "脚本不能产生报警 {number}：报警号为 1–999，500、501、506、507 和 950 除外（这些报警由机床产生）"
            ),
            CncError::HandwheelRange { pulses } => {
                format!("手轮脉冲数 {pulses} 超出范围：应为 −10000…10000")
            }
            CncError::UnknownKey { text } => {
                format!("未知的 CNC 值 `{text}`（{}）", KEY_FORMS.join("、"))
            }
            CncError::KeyAlarm { text, key } => {
                format!("`{key}` 中的 `{text}`：报警号为 1–9999")
            }
            CncError::KeyMacro { text, key } => format!(
                "`{key}` 中的 `{text}`：没有此宏变量（宏变量为 #1–#33、#100–#199、#500–#999、#1000–#1133、#2001–#2964、#3000–#3012、#4001–#4130 和 #5001–#5340，见 docs/gcode.md 的“Macros”一节）"
            ),
            CncError::NotMode { text } => format!(
                "`{text}` 不是方式（{}）",
                Mode::ALL.map(Mode::name).join(" ")
            ),
            CncError::NotRunState { text } => format!(
                "`{text}` 不是运行状态（{}）",
                RunState::ALL.map(RunState::name).join(" ")
            ),
            CncError::AxisBeyond { axis: a, count } => {
                format!("{} 轴超出 {count} 个控制轴（#8130）", axis(*a))
            }
            CncError::NoParameter { number } => format!("没有参数 {number}"),
            CncError::NoOffset { number } => format!("没有刀补号 {number}"),
            CncError::NoWorkSlot => "没有此工件坐标系或轴".into(),
            CncError::NoCnc => "没有连接模拟 CNC".into(),
            CncError::NoMachineModel => "没有运行中的机床模型".into(),
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::compiler::bilingual::assert_bilingual;

    /// Where `e` is in the example list: one arm per variant, no wildcard, so a new variant
    /// does not compile until it is named here, and the test below then wants an example.
    fn slot(e: &CncError) -> usize {
        match e {
            CncError::NoSubcommand => 0,
            CncError::UnknownCommand { .. } => 1,
            CncError::Usage { .. } => 2,
            CncError::ReadFile { .. } => 3,
            CncError::NotClock { .. } => 4,
            CncError::NotMm { .. } => 5,
            CncError::MmRange { .. } => 6,
            CncError::NotInteger { .. } => 7,
            CncError::Param { .. } => 8,
            CncError::Gsk980Selector { .. } => 9,
            CncError::Gsk980Value { .. } => 10,
            CncError::NotParamNumber { .. } => 11,
            CncError::NotSelector { .. } => 12,
            CncError::BadAxis { .. } => 13,
            CncError::OffsetNumber { .. } => 14,
            CncError::OffsetType { .. } => 15,
            CncError::WorkSystem { .. } => 16,
            CncError::TipRange { .. } => 17,
            CncError::MacroNotWritable { .. } => 18,
            CncError::NotDecimal { .. } => 19,
            CncError::MacroSignalBit { .. } => 20,
            CncError::AlarmNotRaisable { .. } => 21,
            CncError::HandwheelRange { .. } => 22,
            CncError::UnknownKey { .. } => 23,
            CncError::KeyAlarm { .. } => 24,
            CncError::KeyMacro { .. } => 25,
            CncError::NotMode { .. } => 26,
            CncError::NotRunState { .. } => 27,
            CncError::AxisBeyond { .. } => 28,
            CncError::NoParameter { .. } => 29,
            CncError::NoOffset { .. } => 30,
            CncError::NoWorkSlot => 31,
            CncError::NoCnc => 32,
            CncError::NoMachineModel => 33,
        }
    }

    const VARIANTS: usize = 34;

    /// An example with the specifics both of its texts must carry.
    type Example = (CncError, Vec<&'static str>);

    fn s(t: &str) -> String {
        t.to_string()
    }

    /// The refusals of `cnc` command words, every [`ParamError`] and [`Quantity`] among them.
    fn command_examples() -> Vec<Example> {
        use CncError as E;
        let usage = "offset N TYPE VALUE";
        let mut list = vec![
            (E::NoSubcommand, vec!["program-file", "clock"]),
            (E::UnknownCommand { text: s("spin") }, vec!["`spin`"]),
            (E::Usage { usage }, vec!["cnc offset N TYPE VALUE"]),
            (
                E::ReadFile {
                    path: s("other.nc"),
                    message: s("cannot read other.nc"),
                },
                vec!["other.nc"],
            ),
            (E::NotClock { text: s("2026-1") }, vec!["`2026-1`"]),
            (E::NotMm { text: s("1x") }, vec!["`1x`"]),
            (E::MmRange { text: s("1e9") }, vec!["1e9", "99999.999"]),
            (E::Gsk980Selector { number: 77 }, vec!["GSK980", "77"]),
            (E::Gsk980Value { number: 78 }, vec!["GSK980", "78", "32"]),
            (E::TipRange { value: 10 }, vec!["0–9", "10"]),
            (E::MacroNotWritable { number: 1000 }, vec!["#1000", "#1131"]),
            (E::NotDecimal { text: s("q") }, vec!["`q`", "`vacant`"]),
            (E::MacroSignalBit { number: 1100 }, vec!["#1100"]),
            (E::AlarmNotRaisable { number: 950 }, vec!["950", "1–999"]),
            (E::HandwheelRange { pulses: 20000 }, vec!["20000", "10000"]),
        ];
        let params = [
            (1234, ParamError::Number, "8410"),
            (1420, ParamError::Selector, "1–5"),
            (3003, ParamError::Selector, "3003"),
            (3741, ParamError::Selector, "1–4"),
            (8130, ParamError::Value, "2…5"),
        ];
        for (number, error, d) in params {
            list.push((E::Param { number, error }, vec![d]));
        }
        let quantities = [
            Quantity::ParamValue,
            Quantity::TipDirection,
            Quantity::Variable,
            Quantity::Alarm,
            Quantity::Pulses,
            Quantity::Integer,
        ];
        for what in quantities {
            list.push((
                E::NotInteger {
                    text: s("x1"),
                    what,
                },
                vec!["`x1`"],
            ));
        }
        list
    }

    /// The refusals of words within a command or a key, of keys, expected values and reads.
    fn key_examples() -> Vec<Example> {
        use CncError as E;
        let mut list = vec![
            (
                E::UnknownKey { text: s("cnc.sp") },
                vec!["`cnc.sp`", "cnc.macro.N"],
            ),
            (E::NotMode { text: s("AUTO") }, vec!["`AUTO`", "MEM"]),
            (E::NotRunState { text: s("GO") }, vec!["`GO`", "HOLD"]),
            (E::AxisBeyond { axis: 2, count: 2 }, vec!["Y", "2", "#8130"]),
            (E::NoParameter { number: 1234 }, vec!["1234"]),
            (E::NoOffset { number: 200 }, vec!["200"]),
            (E::NoWorkSlot, vec![]),
            (E::NoCnc, vec!["CNC"]),
            (E::NoMachineModel, vec![]),
        ];
        // A word of a command alone, a word of a key with the key; the data are the word in
        // backticks and, within a key, the key.
        type Word = fn(String, Option<String>) -> CncError;
        let words: [(Word, &str); 6] = [
            (|text, key| E::NotParamNumber { text, key }, "`p7`"),
            (|text, key| E::NotSelector { text, key }, "`s7`"),
            (|text, key| E::BadAxis { text, key }, "`Q`"),
            (|text, key| E::OffsetType { text, key }, "`W`"),
            (|text, key| E::WorkSystem { text, key }, "`G60`"),
            (
                |text, key| E::OffsetNumber {
                    text,
                    key,
                    first: 1,
                    last: 99,
                },
                "`100`",
            ),
        ];
        for (make, written) in words {
            let text = s(written.trim_matches('`'));
            list.push((make(text.clone(), None), vec![written]));
            let key = Some(s("cnc.x.y"));
            list.push((make(text, key), vec![written, "`cnc.x.y`"]));
        }
        let (text, key) = (s("0"), s("cnc.alarm.0"));
        list.push((E::KeyAlarm { text, key }, vec!["`cnc.alarm.0`", "1–9999"]));
        let (text, key) = (s("7"), s("cnc.macro.7"));
        list.push((E::KeyMacro { text, key }, vec!["`cnc.macro.7`", "#5340"]));
        list
    }

    #[test]
    fn every_refusal_reads_in_both_languages_with_its_specifics() {
        let examples = [command_examples(), key_examples()].concat();
        let mut seen = [false; VARIANTS];
        for (e, data) in &examples {
            seen[slot(e)] = true;
            let (en, zh) = (e.en(), e.zh());
            assert!(!en.is_empty() && !zh.is_empty(), "{e:?}");
            assert_eq!(e.to_string(), en);
            assert_bilingual(&en, &zh);
            for d in data {
                assert!(en.contains(d), "`{d}` missing in: {en}");
                assert!(zh.contains(d), "`{d}` missing in: {zh}");
            }
            let refusal = crate::refusal::Refusal::from(e.clone());
            assert_eq!(refusal, crate::refusal::Refusal::Cnc(e.clone()));
        }
        let missing: Vec<usize> = (0..VARIANTS).filter(|&i| !seen[i]).collect();
        assert!(
            missing.is_empty(),
            "variants without an example: {missing:?}"
        );
    }

    #[test]
    fn a_reader_that_speaks_chinese_is_not_translated_again() {
        let e = CncError::ReadFile {
            path: "a.nc".into(),
            message: "无法读取 NC 程序 /d/a.nc：拒绝访问".into(),
        };
        assert_eq!(e.zh(), "无法读取 NC 程序 /d/a.nc：拒绝访问");
    }
}
