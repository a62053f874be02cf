//! Stimulus scripts (docs/scripts.md; docs/cnc.md, "Script commands" for the `cnc` lines): parsed
//! whole before anything runs, so a typo on line 40 is reported before line 1 executes;
//! then run against a [`Machine`](crate::machine::Machine), counting `expect`s. Every line that acts on the machine
//! becomes a [`MachineCommand`], the same commands the editor sends to a running machine.

mod device;
mod lex;
mod run;
pub mod scenario;

use crate::address::{Address, AddressError, Area};
use crate::cnc::command::{CncCommand, CncError, CncKey, CncValue};
use crate::machine::{MachineCommand, Probe};
use crate::profile::Profile;
use crate::vm::TICK_MS;
use thiserror::Error;

pub use crate::address::Target;
pub use run::{Control, Event, Outcome, Part, Progress, Report, Stopped, run, run_with};

/// The most ticks one `scan` or `run` line may ask for: 100 000 000 ticks are 800 000 s
/// (nine days) of virtual time, a few minutes of a real one.
pub const MAX_TICKS: u64 = 100_000_000;

/// One script line.
#[derive(Clone, Debug, PartialEq)]
pub enum ScriptCommand {
    /// Something done to the machine: `set`, `setf`, `force`, `unforce`, `scan`, `run`,
    /// `watch`, `division`, `power-cycle`, `cnc …`.
    Do(MachineCommand),
    /// `expect ADDR[:N] VALUE`.
    Expect(Target, i64),
    /// `expectf ADDR VALUE [TOL]`.
    ExpectReal(Address, f32, Option<f32>),
    /// `expect cnc.KEY VALUE`, with the value as written.
    ExpectCnc(CncKey, CncValue, String),
    /// `print ADDR[:N]` or `print cnc.KEY`.
    Print(Probe),
    /// `expect device.NAME VALUE`, by the device's index.
    ExpectDevice(usize, i64),
}

/// A script line that cannot be used.
#[derive(Clone, Debug, PartialEq, Eq, Error)]
#[error("line {line}: {message}")]
pub struct ScriptError {
    /// 1-based line.
    pub line: usize,
    /// What is wrong and how to fix it.
    pub message: String,
    /// The same message in Chinese, with the same specifics (addresses, names, numbers).
    pub message_zh: String,
}

impl ScriptError {
    /// The message in Chinese when `zh` is set, else in English.
    pub fn message_in(&self, zh: bool) -> &str {
        if zh { &self.message_zh } else { &self.message }
    }
}

/// Why a line is refused, in English and in Chinese.
#[derive(Clone, Debug, PartialEq, Eq)]
struct Msg {
    en: String,
    zh: String,
}

fn msg(en: impl Into<String>, zh: impl Into<String>) -> Msg {
    Msg {
        en: en.into(),
        zh: zh.into(),
    }
}

/// A refusal of the CNC side (`cnc` lines, `cnc.KEY` values), in its own two wordings.
fn cnc_refusal(e: CncError) -> Msg {
    Msg {
        en: e.en(),
        zh: e.zh(),
    }
}

impl From<AddressError> for Msg {
    fn from(e: AddressError) -> Msg {
        Msg {
            en: e.to_string(),
            zh: e.zh(),
        }
    }
}

/// A parsed script: commands with their lines.
#[derive(Clone, Debug, PartialEq, Default)]
pub struct Script {
    /// (line, command).
    pub commands: Vec<(usize, ScriptCommand)>,
}

/// How a script is read.
pub struct Options<'a> {
    /// `sim --cnc`: the `cnc` lines and `cnc.KEY` values are allowed.
    pub cnc: bool,
    /// Reads a file a `cnc program-file` line names (relative to the script's folder).
    pub read_file: &'a dyn Fn(&str) -> Result<String, String>,
    /// The machine model the script runs with (none: `--no-machine`, or no devices): it
    /// names the `device` lines' devices and refuses `set` of the inputs they drive.
    pub machine: Option<&'a crate::devices::MachineModel>,
    /// The project the script runs on (none for an instruction list): its saved scenarios
    /// and operator panel serve the `scenario` lines.
    pub project: Option<&'a crate::model::Project>,
}

const COMMANDS: &[&str] = &[
    "set",
    "setf",
    "force",
    "unforce",
    "scan",
    "run",
    "expect",
    "expectf",
    "print",
    "watch",
    "division",
    "power-cycle",
    "cnc",
    "device",
    "scenario",
];

fn target(text: &str, profile: &Profile) -> Result<Target, Msg> {
    let (addr, bytes) = match text.split_once(':') {
        Some((a, n)) => {
            let n: u32 = n
                .parse()
                .ok()
                .filter(|n| matches!(n, 1 | 2 | 4))
                .ok_or_else(|| {
                    msg(
                        format!("`{text}`: the byte count after `:` is 1, 2 or 4"),
                        format!("`{text}`：`:` 后的字节数应为 1、2 或 4"),
                    )
                })?;
            (a, Some(n))
        }
        None => (text, None),
    };
    let address = Address::parse_in(addr, profile)?;
    if matches!(address.area, Area::L | Area::P) {
        return Err(msg(
            format!("`{text}`: labels and subprograms hold no value"),
            format!("`{text}`：标号和子程序没有值"),
        ));
    }
    if address.bit.is_some() && bytes.is_some() {
        return Err(msg(
            format!("`{text}`: a bit address takes no byte count"),
            format!("`{text}`：位地址不能带字节数"),
        ));
    }
    let natural = if address.bit.is_some() {
        1
    } else {
        u32::from(address.area.element_bytes())
    };
    let bytes = bytes.unwrap_or(natural);
    if address.bit.is_none() && address.area.element_bytes() == 1 {
        address.check_span(profile, bytes)?;
    }
    Ok(Target {
        address,
        bytes,
        explicit: bytes != natural,
    })
}

fn is_cnc_key(text: &str) -> bool {
    text.get(..4)
        .is_some_and(|p| p.eq_ignore_ascii_case("cnc."))
}

fn probe(text: &str, profile: &Profile, options: &Options<'_>) -> Result<Probe, Msg> {
    if let Some(p) = device::probe(text, options.machine) {
        return p;
    }
    if is_cnc_key(text) {
        if !options.cnc {
            return Err(msg(
                format!("`{text}` is a CNC value: run with `sim --cnc`"),
                format!("`{text}` 是 CNC 的值：请用 `sim --cnc` 运行"),
            ));
        }
        return CncKey::parse(text, profile.id)
            .map(Probe::Cnc)
            .map_err(cnc_refusal);
    }
    target(text, profile).map(Probe::Memory)
}

fn memory_target(text: &str, profile: &Profile, verb: &str) -> Result<Target, Msg> {
    if is_cnc_key(text) {
        return Err(msg(
            format!("`{verb}` writes PLC memory; `{text}` is a CNC value (use a `cnc` command)"),
            format!("`{verb}` 写入的是 PLC 存储器；`{text}` 是 CNC 的值（请用 `cnc` 命令）"),
        ));
    }
    target(text, profile)
}

fn integer(text: &str) -> Result<i64, Msg> {
    let (neg, digits) = match text.strip_prefix('-') {
        Some(d) => (true, d),
        None => (false, text.strip_prefix('+').unwrap_or(text)),
    };
    let v = match digits
        .strip_prefix("0x")
        .or_else(|| digits.strip_prefix("0X"))
    {
        Some(hex) => i64::from_str_radix(hex, 16),
        None => digits.parse::<i64>(),
    }
    .map_err(|_| {
        msg(
            format!("`{text}` is not an integer"),
            format!("`{text}` 不是整数"),
        )
    })?;
    Ok(if neg { -v } else { v })
}

fn fits(target: &Target, v: i64) -> Result<(), Msg> {
    if target.address.bit.is_some() {
        return if v == 0 || v == 1 {
            Ok(())
        } else {
            Err(msg(
                format!("{} is a bit: the value is 0 or 1, not {v}", target.text()),
                format!("{} 是位：值只能是 0 或 1，不能是 {v}", target.text()),
            ))
        };
    }
    let bits = 8 * target.bytes;
    let (lo, hi) = (-(1i64 << (bits - 1)), (1i64 << bits) - 1);
    if v < lo || v > hi {
        return Err(msg(
            format!(
                "{v} does not fit {} ({} byte{}: {lo}…{hi})",
                target.text(),
                target.bytes,
                if target.bytes == 1 { "" } else { "s" }
            ),
            format!(
                "{v} 超出 {} 的范围（{} 字节：{lo}…{hi}）",
                target.text(),
                target.bytes
            ),
        ));
    }
    Ok(())
}

fn duration(text: &str) -> Result<u64, Msg> {
    let bad = || {
        msg(
            format!("`{text}` is not a duration (write 250ms, 2s or a number of ms)"),
            format!("`{text}` 不是时间长度（应写成 250ms、2s 或毫秒数）"),
        )
    };
    let (number, scale) = if let Some(n) = text.strip_suffix("ms") {
        (n, 1.0)
    } else if let Some(n) = text.strip_suffix('s') {
        (n, 1000.0)
    } else {
        (text, 1.0)
    };
    let v: f64 = number.parse().map_err(|_| bad())?;
    if !v.is_finite() || v < 0.0 {
        return Err(bad());
    }
    let ticks = ((v * scale) / TICK_MS as f64).ceil();
    if ticks > MAX_TICKS as f64 {
        let most = MAX_TICKS * TICK_MS / 1000;
        return Err(msg(
            format!(
                "`{text}` is longer than one line may run: at most {most}s ({MAX_TICKS} ticks); split it over several lines"
            ),
            format!(
                "`{text}` 超过一行允许的运行时间：最多 {most}s（{MAX_TICKS} 个节拍）；请分成几行"
            ),
        ));
    }
    Ok(ticks as u64)
}

fn real(text: &str) -> Result<f32, Msg> {
    text.parse::<f32>().map_err(|_| {
        msg(
            format!("`{text}` is not a number"),
            format!("`{text}` 不是数字"),
        )
    })
}

fn four_byte(t: &Target, verb: &str) -> Result<(), Msg> {
    if t.address.bit.is_some() || t.address.area.element_bytes() != 4 {
        return Err(msg(
            format!(
                "{verb} needs a 4-byte address (D, T, C, DT, DC), not {}",
                t.address
            ),
            format!(
                "{verb} 需要 4 字节地址（D、T、C、DT、DC），不能是 {}",
                t.address
            ),
        ));
    }
    Ok(())
}

fn no_files(path: &str) -> Result<String, String> {
    Err(format!("cannot read `{path}`: no files here"))
}

impl Script {
    /// Parses a whole script for the PLC alone (no `cnc` lines), or says which line is wrong.
    pub fn parse(text: &str, profile: &Profile) -> Result<Script, ScriptError> {
        Script::parse_with(
            text,
            profile,
            &Options {
                cnc: false,
                read_file: &no_files,
                machine: None,
                project: None,
            },
        )
    }

    /// Parses a whole script, or says which line is wrong.
    pub fn parse_with(
        text: &str,
        profile: &Profile,
        options: &Options<'_>,
    ) -> Result<Script, ScriptError> {
        let mut commands = Vec::new();
        for (i, raw) in text.lines().enumerate() {
            let line = i + 1;
            let err = |m: Msg| ScriptError {
                line,
                message: m.en,
                message_zh: m.zh,
            };
            let words = lex::words(raw).map_err(err)?;
            let Some(&verb) = words.first() else {
                continue;
            };
            let command = parse_line(verb, &words[1..], profile, options).map_err(err)?;
            commands.push((line, command));
        }
        Ok(Script { commands })
    }
}

/// The N of `scan N`: a number of ticks one line may run.
fn scan_count(n: &str) -> Result<u64, Msg> {
    let count = n.parse::<u64>().map_err(|_| {
        msg(
            format!("`{n}` is not a number of scans"),
            format!("`{n}` 不是扫描次数"),
        )
    })?;
    if count > MAX_TICKS {
        return Err(msg(
            format!(
                "`scan {n}` is more than one line may run: at most {MAX_TICKS} scans; split it over several lines"
            ),
            format!("`scan {n}` 超过一行允许的次数：最多 {MAX_TICKS} 次；请分成几行"),
        ));
    }
    Ok(count)
}

fn parse_line(
    verb: &str,
    args: &[&str],
    profile: &Profile,
    options: &Options<'_>,
) -> Result<ScriptCommand, Msg> {
    let want = |n: std::ops::RangeInclusive<usize>, usage: &str| {
        if n.contains(&args.len()) {
            Ok(())
        } else {
            Err(msg(format!("usage: {usage}"), format!("用法：`{usage}`")))
        }
    };
    let lower = verb.to_ascii_lowercase();
    let act = |c: MachineCommand| Ok(ScriptCommand::Do(c));
    match lower.as_str() {
        "set" => {
            want(2..=2, "set ADDR[:N] VALUE")?;
            let t = memory_target(args[0], profile, "set")?;
            device::not_driven(&t, "set", options.machine)?;
            let v = integer(args[1])?;
            fits(&t, v)?;
            act(MachineCommand::Write(t, v))
        }
        "setf" => {
            want(2..=2, "setf ADDR VALUE")?;
            let t = memory_target(args[0], profile, "setf")?;
            device::not_driven(&t, "setf", options.machine)?;
            four_byte(&t, "setf")?;
            act(MachineCommand::WriteReal(t.address, real(args[1])?))
        }
        "force" => {
            want(2..=2, "force ADDR VALUE")?;
            let t = memory_target(args[0], profile, "force")?;
            let v = integer(args[1])?;
            fits(&t, v)?;
            act(MachineCommand::Force(t.address, v))
        }
        "unforce" => {
            want(1..=1, "unforce ADDR")?;
            act(MachineCommand::Unforce(
                memory_target(args[0], profile, "unforce")?.address,
            ))
        }
        "scan" => {
            want(0..=1, "scan [N]")?;
            let n = match args.first() {
                Some(n) => scan_count(n)?,
                None => 1,
            };
            act(MachineCommand::Tick(n))
        }
        "run" => {
            want(1..=1, "run DURATION")?;
            act(MachineCommand::Tick(duration(args[0])?))
        }
        "expect" => {
            want(2..=2, "expect ADDR[:N] VALUE")?;
            match probe(args[0], profile, options)? {
                Probe::Cnc(k) => Ok(ScriptCommand::ExpectCnc(
                    k,
                    k.expected(args[1]).map_err(cnc_refusal)?,
                    args[1].into(),
                )),
                Probe::Memory(t) => {
                    let v = integer(args[1])?;
                    fits(&t, v)?;
                    Ok(ScriptCommand::Expect(t, v))
                }
                Probe::Device(i) => Ok(ScriptCommand::ExpectDevice(i, integer(args[1])?)),
            }
        }
        "expectf" => {
            want(2..=3, "expectf ADDR VALUE [TOL]")?;
            let t = memory_target(args[0], profile, "expectf")?;
            four_byte(&t, "expectf")?;
            let tol = match args.get(2) {
                Some(t) => Some(real(t)?),
                None => None,
            };
            Ok(ScriptCommand::ExpectReal(t.address, real(args[1])?, tol))
        }
        "print" => {
            want(1..=1, "print ADDR[:N]")?;
            Ok(ScriptCommand::Print(probe(args[0], profile, options)?))
        }
        "watch" => {
            want(1..=1, "watch ADDR[:N]")?;
            act(MachineCommand::Watch(probe(args[0], profile, options)?))
        }
        "division" => {
            want(1..=1, "division N")?;
            let n = args[0]
                .parse::<u32>()
                .ok()
                .filter(|n| (1..=1000).contains(n))
                .ok_or_else(|| {
                    msg(
                        format!("`{}`: the division is a number 1–1000", args[0]),
                        format!("`{}`：二级程序分割数应为 1–1000", args[0]),
                    )
                })?;
            act(MachineCommand::Division(n))
        }
        "power-cycle" => {
            want(0..=0, "power-cycle")?;
            act(MachineCommand::PowerCycle)
        }
        "cnc" => {
            if !options.cnc {
                return Err(msg(
                    "`cnc` lines drive the simulated CNC: run with `sim --cnc`",
                    "`cnc` 行驱动的是模拟 CNC：请用 `sim --cnc` 运行",
                ));
            }
            act(MachineCommand::Cnc(
                CncCommand::parse(args, profile.id, options.read_file).map_err(cnc_refusal)?,
            ))
        }
        "device" => device::line(args, options.machine),
        "scenario" => scenario::line(args, options),
        _ => {
            let prefix: String = lower.chars().take(3).collect();
            let near = COMMANDS.iter().find(|c| c.starts_with(&prefix));
            let (near_en, near_zh) = near.map_or((String::new(), String::new()), |c| {
                (
                    format!("; did you mean `{c}`?"),
                    format!("；是不是 `{c}`？"),
                )
            });
            Err(msg(
                format!(
                    "unknown command `{verb}`{near_en} (commands: {})",
                    COMMANDS.join(", ")
                ),
                format!(
                    "未知命令 `{verb}`{near_zh}（命令：{}）",
                    COMMANDS.join("、")
                ),
            ))
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::compiler::bilingual::assert_bilingual;
    use crate::profile::ProfileId;

    fn parse(text: &str) -> Result<Script, ScriptError> {
        Script::parse(text, Profile::get(ProfileId::Gsk988ta))
    }

    fn parse_cnc(text: &str) -> Result<Script, ScriptError> {
        Script::parse_with(
            text,
            Profile::get(ProfileId::Gsk988ta),
            &Options {
                machine: None,
                project: None,
                cnc: true,
                read_file: &|p| {
                    if p == "part.nc" {
                        Ok("O0001;M30".into())
                    } else {
                        Err(format!("cannot read {p}"))
                    }
                },
            },
        )
    }

    #[test]
    fn errors_name_the_line() {
        let e = parse("scan\n\nset R0000 256\n").unwrap_err();
        assert_eq!(e.line, 3);
        assert!(
            e.message.contains("256 does not fit R0000"),
            "{}",
            e.message
        );
        let e = parse("# comment\nsett X1.0 1").unwrap_err();
        assert_eq!(e.line, 2);
        assert!(e.message.contains("did you mean `set`"), "{}", e.message);
        assert!(
            parse("set R1000 1")
                .unwrap_err()
                .message
                .contains("R0–R999")
        );
        assert!(parse("set X1.0 2").is_err());
        assert!(parse("run 2x").is_err());
        assert!(parse("expect D1:3 0").is_err());
        assert!(parse("setf R1 1.5").is_err());
    }

    #[test]
    fn cnc_lines_need_the_cnc_and_are_checked_before_anything_runs() {
        let e = parse("scan\ncnc reset").unwrap_err();
        assert_eq!(e.line, 2);
        assert!(e.message.contains("--cnc"), "{}", e.message);
        assert!(
            parse("expect cnc.mode MEM")
                .unwrap_err()
                .message
                .contains("--cnc")
        );
        assert!(parse_cnc("cnc program \"O0001;M03 S800;M30\"").is_ok());
        assert!(parse_cnc("cnc program-file part.nc").is_ok());
        let e = parse_cnc("scan\ncnc program-file other.nc").unwrap_err();
        assert_eq!(e.line, 2);
        assert!(e.message.contains("other.nc"));
        assert!(
            parse_cnc("set cnc.mode 1")
                .unwrap_err()
                .message
                .contains("CNC value")
        );
        assert!(parse_cnc("force cnc.pos.X 1").is_err());
        assert!(parse_cnc("expect cnc.run GO").is_err());
        assert!(parse_cnc("expect cnc.pos.X").is_err());
        assert!(parse_cnc("cnc program \"M03").is_err());
        assert!(parse_cnc("watch cnc.pos.Z\nprint cnc.spindle").is_ok());
    }

    #[test]
    fn script_errors_say_in_chinese_what_they_say_in_english() {
        let plc = [
            "set R0000 256",
            "sett X1.0 1",
            "frob",
            "set R1000 1",
            "set X1.0 2",
            "set X1.0:2 1",
            "set L0001 1",
            "set R0001:3 1",
            "set R0999:4 1",
            "set R1 x",
            "set Q1 1",
            "set R1.9 1",
            "set D1.3 1",
            "run 2x",
            "scan many",
            "division 0",
            "setf R1 1.5",
            "expectf D1 one",
            "set R1",
            "power-cycle now",
            "cnc reset",
            "expect cnc.mode MEM",
            "print \"R1",
            "print \"R1\"x",
            "print R\"1\"",
            "set cnc.mode 1",
        ];
        for text in plc {
            let e = parse(text).expect_err(text);
            assert_bilingual(&e.message, &e.message_zh);
            assert_eq!(e.message_in(false), e.message);
            assert_eq!(e.message_in(true), e.message_zh);
        }
        // The CNC side says the same in Chinese, in the manual's words: no English behind a
        // Chinese prefix.
        let e = parse_cnc("scan\ncnc program-file other.nc").unwrap_err();
        assert!(
            e.message_zh.contains("无法读取程序文件"),
            "{}",
            e.message_zh
        );
        assert!(e.message_zh.contains("other.nc"), "{}", e.message_zh);
        let cnc = [
            ("cnc", "子命令"),
            ("cnc spin", "未知的 CNC 命令"),
            ("cnc offset 1 X", "用法"),
            ("cnc param 1420 3000", "轴号"),
            ("cnc param 8130 9", "参数 8130"),
            ("cnc param 1234 1", "没有参数"),
            ("cnc offset 100 X 1", "刀补号"),
            ("cnc offset 1 TIP 10", "刀尖方向"),
            ("cnc workpiece G60 X 1", "工件坐标系"),
            ("cnc macro 1000 1", "宏变量"),
            ("cnc alarm 950", "报警"),
            ("cnc handwheel 20000", "手轮"),
            ("cnc clock 2026-02-30T00:00:00", "日期时间"),
            ("cnc position Q 1", "轴"),
            ("expect cnc.speed 1", "未知的 CNC 值"),
            ("expect cnc.run GO", "运行状态"),
            ("expect cnc.mode AUTO", "方式"),
            ("print cnc.macro.99999", "宏变量"),
        ];
        for (text, word) in cnc {
            let e = parse_cnc(text).expect_err(text);
            assert_bilingual(&e.message, &e.message_zh);
            assert!(e.message_zh.contains(word), "{text}: {}", e.message_zh);
        }
    }

    #[test]
    fn a_line_runs_at_most_a_hundred_million_ticks() {
        assert!(parse("scan 100000000\nrun 800000s").is_ok());
        let e = parse("scan 100000001").unwrap_err();
        assert!(
            e.message.contains("at most 100000000 scans"),
            "{}",
            e.message
        );
        assert_bilingual(&e.message, &e.message_zh);
        let e = parse("scan 1\nrun 10000000000000").unwrap_err();
        assert_eq!(e.line, 2);
        assert!(e.message.contains("at most 800000s"), "{}", e.message);
        assert_bilingual(&e.message, &e.message_zh);
        let e = parse("scan -1").unwrap_err();
        assert!(e.message.contains("not a number of scans"), "{}", e.message);
    }

    #[test]
    fn durations_round_up_to_ticks() {
        let s = parse("run 250ms\nrun 2s\nrun 9\nscan 3 ; three\nrun 0").unwrap();
        let ticks: Vec<u64> = s
            .commands
            .iter()
            .map(|(_, c)| match c {
                ScriptCommand::Do(MachineCommand::Tick(n)) => *n,
                _ => 0,
            })
            .collect();
        assert_eq!(ticks, vec![32, 250, 2, 3, 0]);
    }
}
