//! The short texts a CNC screen shows next to an alarm number, in Chinese and English, for
//! the editor's CNC panel (docs/cnc.md, "Alarms", "Program errors", "Overtravel", "PLC axis
//! control").
//!
//! Every alarm the simulator raises by itself has its own text in [`TEXTS`]. Numbers it only
//! raises on request (`cnc alarm N`) get the text of their range: servo for 0401–0499, P/S for
//! the rest of 1–999. PLC alarms (1000–1999) get a generic text: their own text is the
//! project's message table row, which the editor shows itself.

use super::ps;
use super::{ALARM_ESTOP, ALARM_HARD_LIMIT, ALARM_STROKE};
use std::borrow::Cow;

/// The texts of one alarm.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct AlarmText {
    /// The alarm number.
    pub number: u16,
    /// Chinese text.
    pub zh: &'static str,
    /// English text.
    pub en: &'static str,
}

const fn text(number: u16, zh: &'static str, en: &'static str) -> AlarmText {
    AlarmText { number, zh, en }
}

/// Every alarm the simulator raises by itself, in number order. The numbers come from the
/// simulator's own constants, so a text cannot drift from the alarm it names.
pub const TEXTS: &[AlarmText] = &[
    text(ps::DIGITS, "数字位数太多", "Too many digits"),
    text(ps::ADDRESS, "非法地址或数值", "Improper address or value"),
    text(ps::G_CODE, "G代码错误", "Improper G code"),
    text(ps::NO_FEED, "未指定进给速度", "No feedrate commanded"),
    text(ps::M_COUNT, "M代码过多", "Too many M codes"),
    text(
        ps::ARC_RADIUS,
        "圆弧半径误差过大",
        "Arc radius out of tolerance",
    ),
    text(ps::NO_RADIUS, "圆弧未指定R或I、K", "Arc without R or I, K"),
    text(ps::G10_P, "G10的P或L指令错误", "Improper P or L in G10"),
    text(
        ps::CORNER_NEXT,
        "倒角或拐角圆弧后不是G01",
        "No G01 after a chamfer or corner R",
    ),
    text(
        ps::CORNER_SIZE,
        "倒角或拐角圆弧过大",
        "Chamfer or corner R too large",
    ),
    text(
        ps::CYCLE_PQ,
        "复合循环中未指定P或Q",
        "P or Q missing in a multiple repetitive cycle",
    ),
    text(
        ps::CYCLE_VALUE,
        "复合循环指令值错误",
        "Improper value in a multiple repetitive cycle",
    ),
    text(
        ps::NO_SEQUENCE,
        "未找到P或Q指定的程序段",
        "Block of sequence number P or Q not found",
    ),
    text(
        ps::NOT_MONOTONIC_Z,
        "精加工形状Z方向非单调变化",
        "Finishing shape not monotonic along Z",
    ),
    text(
        ps::CYCLE_FIRST_BLOCK,
        "精加工形状首段无G00或G01",
        "No G00 or G01 in the first block of the shape",
    ),
    text(
        ps::CYCLE_COMMAND,
        "精加工形状中有不可用的指令",
        "Unavailable command in the shape blocks",
    ),
    text(ps::NO_PROGRAM, "子程序未找到", "Subprogram not found"),
    text(
        ps::NESTING,
        "子程序或宏程序嵌套过多",
        "Subprograms or macros nested too deep",
    ),
    text(
        ps::NO_PROGRESS,
        "程序只有跳过的程序段（无可执行程序段）",
        "Program loops through skipped blocks only",
    ),
    text(
        ps::NO_REFERENCE,
        "未建立参考点",
        "Reference point not established",
    ),
    text(ps::OVERFLOW, "运算结果溢出", "Calculated data overflow"),
    text(ps::DIVISION, "除数为零", "Division by zero"),
    text(
        ps::FORMAT,
        "宏语句格式错误",
        "Illegal macro expression format",
    ),
    text(
        ps::VARIABLE,
        "变量号超出范围",
        "Variable number out of range",
    ),
    text(ps::PROTECTED, "变量写保护", "Write-protected variable"),
    text(ps::BRACKETS, "括号嵌套过多", "Too many brackets nested"),
    text(ps::ARGUMENT, "函数自变量错误", "Illegal argument"),
    text(ps::LOOP_END, "DO与END不配对", "DO and END do not pair"),
    text(ps::LOOP_NUMBER, "循环号错误", "Illegal loop number"),
    text(
        ps::MIXED,
        "NC语句与宏语句在同一程序段",
        "NC and macro statement in one block",
    ),
    text(
        ps::SEQUENCE,
        "转移目标顺序号错误",
        "Illegal macro sequence number",
    ),
    text(
        ps::ARG_ADDRESS,
        "宏调用自变量地址错误",
        "Illegal argument address",
    ),
    text(
        ps::PLC_AXIS,
        "PLC轴控制指令错误",
        "PLC axis command refused",
    ),
    text(
        ps::AXIS_CLAIM,
        "PLC控制轴冲突",
        "Axis claimed by both CNC and PLC",
    ),
    text(
        ps::NOT_MONOTONIC_X,
        "精加工形状X方向非单调变化",
        "Finishing shape not monotonic along X",
    ),
    text(
        ALARM_STROKE[0],
        "正向软限位超程",
        "Soft limit overtravel (+)",
    ),
    text(
        ALARM_STROKE[1],
        "负向软限位超程",
        "Soft limit overtravel (-)",
    ),
    text(
        ALARM_HARD_LIMIT[0],
        "正向硬限位超程",
        "Hard limit overtravel (+)",
    ),
    text(
        ALARM_HARD_LIMIT[1],
        "负向硬限位超程",
        "Hard limit overtravel (-)",
    ),
    text(ALARM_ESTOP, "急停报警", "Emergency stop"),
];

/// The text of a range: what a number without its own text shows.
fn generic(number: u16, zh: bool) -> &'static str {
    let (z, e) = match number {
        401..=499 => ("伺服报警", "Servo alarm"),
        1000..=1999 => ("PLC报警", "PLC alarm"),
        3000..=3200 => ("宏程序报警", "Macro alarm"),
        2000..=9999 => ("操作信息", "Operator message"),
        _ => ("P/S报警", "P/S alarm"),
    };
    if zh { z } else { e }
}

/// The short text of alarm `number`, in Chinese when `zh`, else English: its own text if the
/// simulator raises it by itself, else its range's (see the module documentation).
pub fn alarm_text(number: u16, zh: bool) -> Cow<'static, str> {
    let own = TEXTS.iter().find(|t| t.number == number);
    Cow::Borrowed(match own {
        Some(t) if zh => t.zh,
        Some(t) => t.en,
        None => generic(number, zh),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The numbers the simulator's sources name as alarms: the `ps` constants of
    /// `ps.rs` and the `ALARM_` constants of `mod.rs`, read from the text so a new
    /// constant is found without anyone listing it.
    fn constants_in_sources() -> Vec<u16> {
        let ps = include_str!("ps.rs")
            .lines()
            .filter(|l| l.trim_start().starts_with("pub const"))
            .map(str::to_owned);
        let alarms = include_str!("mod.rs")
            .lines()
            .filter(|l| l.starts_with("pub const ALARM_"))
            .map(str::to_owned);
        let mut numbers = Vec::new();
        for line in ps.chain(alarms) {
            let value = line.split('=').nth(1).expect("a constant has a value");
            for n in value.split(|c: char| !c.is_ascii_digit()) {
                if !n.is_empty() {
                    numbers.push(n.parse().expect("an alarm number"));
                }
            }
        }
        numbers
    }

    #[test]
    fn every_alarm_constant_of_the_simulator_has_its_own_text_in_both_languages() {
        let numbers = constants_in_sources();
        assert!(numbers.len() >= 15, "{numbers:?}");
        for n in numbers {
            let own = TEXTS.iter().find(|t| t.number == n);
            assert!(own.is_some(), "alarm {n:04} has no text in TEXTS");
            for zh in [true, false] {
                let text = alarm_text(n, zh);
                assert_ne!(text, generic(n, zh), "alarm {n:04}");
                assert!(!text.is_empty());
            }
            assert!(
                alarm_text(n, true).chars().any(|c| c > '\u{2E80}'),
                "alarm {n:04}: the Chinese text has Chinese in it"
            );
        }
    }

    #[test]
    fn the_simulator_raises_alarms_only_through_named_constants() {
        // A literal number passed to `raise` would escape the test above.
        let dir = std::path::PathBuf::from(concat!(env!("CARGO_MANIFEST_DIR"), "/src/cnc"));
        let mut dirs = vec![dir];
        let mut files = Vec::new();
        while let Some(d) = dirs.pop() {
            for entry in std::fs::read_dir(d).expect("the cnc sources") {
                let path = entry.expect("a directory entry").path();
                if path.is_dir() {
                    dirs.push(path);
                } else {
                    files.push(path);
                }
            }
        }
        assert!(files.len() > 20);
        for path in files {
            let source = std::fs::read_to_string(&path).expect("a source file");
            for call in source.split("raise(").skip(1) {
                assert!(
                    !call.starts_with(|c: char| c.is_ascii_digit()),
                    "{}: raise({}",
                    path.display(),
                    &call[..call.find(')').unwrap_or(call.len())]
                );
            }
        }
    }

    #[test]
    fn texts_are_listed_once_in_number_order() {
        assert!(TEXTS.windows(2).all(|w| w[0].number < w[1].number));
    }

    #[test]
    fn numbers_without_their_own_text_get_their_range() {
        assert_eq!(alarm_text(950, true), "急停报警");
        assert_eq!(alarm_text(950, false), "Emergency stop");
        assert_eq!(alarm_text(500, true), "正向软限位超程");
        assert_eq!(alarm_text(411, false), "Servo alarm");
        assert_eq!(alarm_text(411, true), "伺服报警");
        assert_eq!(alarm_text(1003, false), "PLC alarm");
        assert_eq!(alarm_text(1003, true), "PLC报警");
        assert_eq!(alarm_text(123, false), "P/S alarm");
        assert_eq!(alarm_text(600, true), "P/S报警");
        assert_eq!(alarm_text(3012, false), "Macro alarm");
        assert_eq!(alarm_text(3201, false), "Operator message");
    }
}
