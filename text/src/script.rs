//! Why a stimulus script's line, a scenario's line or a scenario's name cannot be used, and
//! why an NC program file was not read, in the user's language (docs/scripts.md,
//! docs/scenarios.md). The command line prints a script's error as `SCRIPT:LINE: MESSAGE`;
//! the message is [`script_error`].

mod device;
mod scenario;
#[cfg(test)]
mod tests;

pub use scenario::{broken_scenario, name_error};

use crate::Lang;
use crate::quoted::{address_error, cnc_error};
use ladder_engine::cnc::program::{FILE_MAX, ProgramFileError};
use ladder_engine::sim::{COMMANDS, QuoteError, ScriptError, ScriptReason};

/// What is wrong with the line of `e` and how to fix it, in `lang` (without the line).
pub fn script_error(e: &ScriptError, lang: Lang) -> String {
    reason(&e.reason, lang)
}

/// What is wrong with a script line and how to fix it, in `lang`.
pub fn reason(r: &ScriptReason, lang: Lang) -> String {
    let (en, zh) = words(r);
    match lang {
        Lang::En => en,
        Lang::Zh => zh,
    }
}

/// What `r` says about a line as a whole, in English and in Chinese; what it says about a
/// target or a value is [`value_words`].
fn words(r: &ScriptReason) -> (String, String) {
    use ScriptReason as R;
    let (en, zh) = (Lang::En, Lang::Zh);
    match r {
        R::Quote(q) => {
            let (e, z) = quote(*q);
            (e.into(), z.into())
        }
        R::Usage { usage } => (format!("usage: {usage}"), format!("用法：`{usage}`")),
        R::UnknownCommand { verb, near } => (
            format!(
                "unknown command `{verb}`{} (commands: {})",
                near.map_or(String::new(), |c| format!("; did you mean `{c}`?")),
                COMMANDS.join(", ")
            ),
            format!(
                "未知命令 `{verb}`{}（命令：{}）",
                near.map_or(String::new(), |c| format!("；是不是 `{c}`？")),
                COMMANDS.join("、")
            ),
        ),
        R::CncValueNeedsCnc { text } => (
            format!("`{text}` is a CNC value: run with `sim --cnc`"),
            format!("`{text}` 是 CNC 的值：请用 `sim --cnc` 运行"),
        ),
        R::CncLineNeedsCnc => (
            "`cnc` lines drive the simulated CNC: run with `sim --cnc`".into(),
            "`cnc` 行驱动的是模拟 CNC：请用 `sim --cnc` 运行".into(),
        ),
        R::Cnc(e) => (cnc_error(e, en), cnc_error(e, zh)),
        R::NotDuration { text } => (
            format!("`{text}` is not a duration (write 250ms, 2s or a number of ms)"),
            format!("`{text}` 不是时间长度（应写成 250ms、2s 或毫秒数）"),
        ),
        R::TooLong {
            text,
            seconds,
            ticks,
        } => (
            format!(
                "`{text}` is longer than one line may run: at most {seconds}s ({ticks} ticks); split it over several lines"
            ),
            format!(
                "`{text}` 超过一行允许的运行时间：最多 {seconds}s（{ticks} 个节拍）；请分成几行"
            ),
        ),
        R::NotScanCount { text } => (
            format!("`{text}` is not a number of scans"),
            format!("`{text}` 不是扫描次数"),
        ),
        R::TooManyScans { text, most } => (
            format!(
                "`scan {text}` is more than one line may run: at most {most} scans; split it over several lines"
            ),
            format!("`scan {text}` 超过一行允许的次数：最多 {most} 次；请分成几行"),
        ),
        R::Division { text } => (
            format!("`{text}`: the division is a number 1–1000"),
            format!("`{text}`：二级程序分割数应为 1–1000"),
        ),
        R::Device(d) => device::words(d),
        R::Scenario(s) => scenario::words(s),
        R::ByteCount { .. }
        | R::NoValue { .. }
        | R::BitWithByteCount { .. }
        | R::Address(_)
        | R::WritesMemory { .. }
        | R::NotInteger { .. }
        | R::NotNumber { .. }
        | R::NotBit { .. }
        | R::DoesNotFit { .. }
        | R::NotFourBytes { .. } => value_words(r),
    }
}

/// What `r` says about the target or the value of a line, in English and in Chinese.
fn value_words(r: &ScriptReason) -> (String, String) {
    use ScriptReason as R;
    let (en, zh) = (Lang::En, Lang::Zh);
    match r {
        R::ByteCount { text } => (
            format!("`{text}`: the byte count after `:` is 1, 2 or 4"),
            format!("`{text}`：`:` 后的字节数应为 1、2 或 4"),
        ),
        R::NoValue { text } => (
            format!("`{text}`: labels and subprograms hold no value"),
            format!("`{text}`：标号和子程序没有值"),
        ),
        R::BitWithByteCount { text } => (
            format!("`{text}`: a bit address takes no byte count"),
            format!("`{text}`：位地址不能带字节数"),
        ),
        R::Address(e) => (address_error(e, en), address_error(e, zh)),
        R::WritesMemory { verb, text } => (
            format!("`{verb}` writes PLC memory; `{text}` is a CNC value (use a `cnc` command)"),
            format!("`{verb}` 写入的是 PLC 存储器；`{text}` 是 CNC 的值（请用 `cnc` 命令）"),
        ),
        R::NotInteger { text } => (
            format!("`{text}` is not an integer"),
            format!("`{text}` 不是整数"),
        ),
        R::NotNumber { text } => (
            format!("`{text}` is not a number"),
            format!("`{text}` 不是数字"),
        ),
        R::NotBit { target, value } => (
            format!(
                "{} is a bit: the value is 0 or 1, not {value}",
                target.text()
            ),
            format!("{} 是位：值只能是 0 或 1，不能是 {value}", target.text()),
        ),
        R::DoesNotFit {
            value,
            target,
            lo,
            hi,
        } => (
            format!(
                "{value} does not fit {} ({} byte{}: {lo}…{hi})",
                target.text(),
                target.bytes,
                if target.bytes == 1 { "" } else { "s" }
            ),
            format!(
                "{value} 超出 {} 的范围（{} 字节：{lo}…{hi}）",
                target.text(),
                target.bytes
            ),
        ),
        R::NotFourBytes { verb, address } => (
            format!("{verb} needs a 4-byte address (D, T, C, DT, DC), not {address}"),
            format!("{verb} 需要 4 字节地址（D、T、C、DT、DC），不能是 {address}"),
        ),
        // The line as a whole: `words` says those and never sends them here.
        R::Quote(_)
        | R::Usage { .. }
        | R::UnknownCommand { .. }
        | R::CncValueNeedsCnc { .. }
        | R::CncLineNeedsCnc
        | R::Cnc(_)
        | R::NotDuration { .. }
        | R::TooLong { .. }
        | R::NotScanCount { .. }
        | R::TooManyScans { .. }
        | R::Division { .. }
        | R::Device(_)
        | R::Scenario(_) => words(r),
    }
}

/// Why a line does not split into words, in English and in Chinese.
fn quote(q: QuoteError) -> (&'static str, &'static str) {
    match q {
        QuoteError::Unclosed => (
            "a quoted string has no closing `\"`",
            "带引号的字符串缺少结尾的 `\"`",
        ),
        QuoteError::NoSpaceAfter => (
            "a quoted string must be followed by a space",
            "带引号的字符串后面必须跟一个空格",
        ),
        QuoteError::InsideWord => ("a quote must start a word", "引号只能位于单词开头"),
    }
}

/// Why the NC program file at `path` was not read, in `lang`, naming the path and what to do.
pub fn program_file_error(e: &ProgramFileError, path: &std::path::Path, lang: Lang) -> String {
    let p = path.display();
    match (e, lang) {
        (ProgramFileError::TooLarge(n), Lang::En) => format!(
            "the NC program {p} is {n} bytes; programs over 16 MiB ({FILE_MAX} bytes) are refused: split it into programs called with M98"
        ),
        (ProgramFileError::TooLarge(n), Lang::Zh) => format!(
            "NC 程序 {p} 有 {n} 字节，超过 16 MiB（{FILE_MAX} 字节）的程序不读入：请拆成用 M98 调用的子程序"
        ),
        (ProgramFileError::Io(e), Lang::En) => format!("cannot read the NC program {p}: {e}"),
        (ProgramFileError::Io(e), Lang::Zh) => format!("无法读取 NC 程序 {p}：{e}"),
    }
}
