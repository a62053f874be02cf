//! The simulated CNC's refusals in Chinese, in the words of the GSK manuals, with the same
//! specifics as their English (`CncError`'s `Display`, which docs/cnc.md quotes): the words
//! written, the numbers, the usage in backticks.

use ladder_engine::cnc::data::WORK_SYSTEMS;
use ladder_engine::cnc::{
    AXIS_NAMES, CncError, KEY_FORMS, Mode, ParamError, Quantity, RunState, SUBCOMMANDS, Selector,
    param_numbers, param_rule,
};

/// `e` in Chinese.
pub(super) fn cnc_zh(e: &CncError) -> String {
    match e {
        CncError::NoSubcommand => {
            format!("`cnc` 需要子命令（{}）", SUBCOMMANDS.join("、"))
        }
        CncError::UnknownCommand { text } => format!(
            "未知的 CNC 命令 `{text}`（命令：{}）",
            SUBCOMMANDS.join("、")
        ),
        CncError::Usage { usage } => format!("用法：`cnc {usage}`"),
        // A reader that already speaks Chinese (the command line in a Chinese run) names
        // the file ite; an English one is the system's text, given after ours.
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
            format!("`{text}` 不是整数（{}）", quantity_zh(*what))
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

/// What an integer written in a command stands for, in Chinese.
fn quantity_zh(q: Quantity) -> &'static str {
    match q {
        Quantity::ParamValue => "参数值",
        Quantity::TipDirection => "刀尖方向 0–9",
        Quantity::Variable => "宏变量号",
        Quantity::Alarm => "报警号",
        Quantity::Pulses => "手轮脉冲数",
        Quantity::Integer => "整数",
    }
}

/// The name of axis slot `a`, as the refusals print it.
fn axis(a: u8) -> &'static str {
    AXIS_NAMES.get(usize::from(a)).copied().unwrap_or("?")
}

/// The numbers of the parameter table, as the "no parameter" refusal lists them.
fn table_numbers() -> Vec<String> {
    param_numbers().map(|n| format!("{n:04}")).collect()
}

/// The selector and range of a parameter a refusal names (the number was checked first).
fn rule(number: u16) -> (Selector, i64, i64) {
    param_rule(number).unwrap_or((Selector::None, 0, 0))
}

fn param_zh(number: u16, error: ParamError) -> String {
    match error {
        ParamError::Number => format!(
            "没有参数 {number}（模拟器的参数为 {}）",
            table_numbers().join("、")
        ),
        ParamError::Selector => match rule(number).0 {
            Selector::None => format!("参数 {number} 不带轴号或主轴号"),
            Selector::Axis => format!("参数 {number} 需要轴号 1–5"),
            Selector::Spindle => format!("参数 {number} 需要主轴号 1–4"),
        },
        ParamError::Value => {
            let (_, min, max) = rule(number);
            format!("参数 {number} 的范围为 {min}…{max}")
        }
    }
}

/// The written word, with the key it belongs to when there is one.
fn at_zh(text: &str, key: &Option<String>) -> String {
    match key {
        Some(k) => format!("`{k}` 中的 `{text}`"),
        None => format!("`{text}`"),
    }
}

fn is_cjk(c: char) -> bool {
    ('\u{4e00}'..='\u{9fff}').contains(&c)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bilingual::assert_bilingual;
    use ladder_engine::cnc::{ParamError, Quantity};

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
            let (en, zh) = (e.en(), cnc_zh(e));
            assert!(!en.is_empty() && !zh.is_empty(), "{e:?}");
            assert_eq!(e.to_string(), en);
            assert_bilingual(&en, &zh);
            for d in data {
                assert!(en.contains(d), "`{d}` missing in: {en}");
                assert!(zh.contains(d), "`{d}` missing in: {zh}");
            }
            let refusal = ladder_engine::refusal::Refusal::from(e.clone());
            assert_eq!(refusal, ladder_engine::refusal::Refusal::Cnc(e.clone()));
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
        assert_eq!(cnc_zh(&e), "无法读取 NC 程序 /d/a.nc：拒绝访问");
    }
}
