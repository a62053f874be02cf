//! The engine's errors that diagnostics, refusals and the editor quote, in the user's
//! language: an address that does not read, an operand the instruction refuses, a table row
//! that does not fit, a device of the machine model that cannot be built. In English each is
//! its `Display`; the Chinese says the same specifics.

mod cnc;
#[cfg(test)]
mod tests;

use crate::Lang;
use ladder_engine::address::AddressError;
use ladder_engine::catalog::DigitGroupError;
use ladder_engine::catalog::OperandKind;
use ladder_engine::cnc::CncError;
use ladder_engine::compiler::OperandRefusal;
use ladder_engine::devices::fields::FieldError;
use ladder_engine::devices::{ExprError, Limit, ModelError};
use ladder_engine::model::OperandError;
use ladder_engine::model::sheets::{ALARM_NUMBERS, M_CODES, TableError, Taken};
use ladder_engine::model::tables::BLOCK_SYMBOLS;

/// Why an address does not read or is beyond the controller's range, in `lang`.
pub fn address_error(e: &AddressError, lang: Lang) -> String {
    match lang {
        Lang::En => e.to_string(),
        Lang::Zh => address_zh(e),
    }
}

/// Why an instruction refuses an operand, in `lang`.
pub fn operand_refusal(e: &OperandRefusal, lang: Lang) -> String {
    match lang {
        Lang::En => e.to_string(),
        Lang::Zh => operand_refusal_zh(e),
    }
}

/// The rule of an instruction's control digits, in `lang`.
pub fn digit_group_error(e: &DigitGroupError, lang: Lang) -> String {
    match lang {
        Lang::En => e.to_string(),
        Lang::Zh => digit_group_zh(e).to_string(),
    }
}

/// Why a table row cannot be taken, in `lang`.
pub fn table_error(e: &TableError, lang: Lang) -> String {
    match lang {
        Lang::En => e.to_string(),
        Lang::Zh => table_error_zh(e),
    }
}

/// What already holds a name or number a table row wants, in `lang`.
pub fn taken(t: &Taken, lang: Lang) -> String {
    match lang {
        Lang::En => t.to_string(),
        Lang::Zh => taken_zh(t),
    }
}

/// Why a device of the machine model cannot be built, in `lang`.
pub fn model_error(e: &ModelError, lang: Lang) -> String {
    match lang {
        Lang::En => e.to_string(),
        Lang::Zh => model_error_zh(e),
    }
}

/// Why a device's condition does not read, in `lang`.
pub fn expr_error(e: &ExprError, lang: Lang) -> String {
    match lang {
        Lang::En => e.to_string(),
        Lang::Zh => expr_error_zh(e),
    }
}

/// Why an operand does not read, in `lang`.
pub fn operand_error(e: &OperandError, lang: Lang) -> String {
    match lang {
        Lang::En => e.to_string(),
        Lang::Zh => operand_error_zh(e),
    }
}

/// Why a device field refused the text typed into it, in `lang`.
pub fn field_error(e: &FieldError, lang: Lang) -> String {
    match (e, lang) {
        (FieldError::NoField(name), Lang::En) => format!("no field `{name}`"),
        (FieldError::NoField(name), Lang::Zh) => format!("没有字段 `{name}`"),
        (FieldError::Condition(e), _) => expr_error(e, lang),
        (FieldError::NotFlag(text), Lang::En) => format!("`{text}`: write true or false"),
        (FieldError::NotFlag(text), Lang::Zh) => format!("`{text}`：请写 true 或 false"),
        (FieldError::NotLength(text), Lang::En) => {
            format!("`{text}` is not a length in mm (−100000…100000)")
        }
        (FieldError::NotLength(text), Lang::Zh) => {
            format!("`{text}` 不是以 mm 计的长度（−100000…100000）")
        }
        (FieldError::NotEncoding(text), Lang::En) => {
            format!("`{text}`: the encoding is Binary, Bcd, OneHot or Gray")
        }
        (FieldError::NotEncoding(text), Lang::Zh) => {
            format!("`{text}`：编码应为 Binary、Bcd、OneHot 或 Gray")
        }
        (FieldError::NotNumber { text, lo, hi }, Lang::En) => {
            format!("`{text}`: write a whole number {lo}…{hi}")
        }
        (FieldError::NotNumber { text, lo, hi }, Lang::Zh) => {
            format!("`{text}`：请写 {lo}…{hi} 的整数")
        }
        (FieldError::Address(e), _) => address_error(e, lang),
        (FieldError::Byte(a), Lang::En) => {
            format!("{a} is a byte; write a bit address such as {a}.0")
        }
        (FieldError::Byte(a), Lang::Zh) => format!("{a} 是字节，请写位地址（例如 {a}.0）"),
        (FieldError::NotInput(a), Lang::En) => {
            format!("{a} is not an input; a device writes X bits")
        }
        (FieldError::NotInput(a), Lang::Zh) => format!("{a} 不是输入；设备只写 X 位"),
    }
}

/// Why the simulated CNC refuses a command or a key, in `lang`.
pub fn cnc_error(e: &CncError, lang: Lang) -> String {
    match lang {
        Lang::En => e.en(),
        Lang::Zh => cnc::cnc_zh(e),
    }
}

/// `AddressError` in Chinese, with the same specifics as its English.
fn address_zh(e: &AddressError) -> String {
    match e {
        AddressError::Syntax(s) => {
            format!("`{s}` 不是地址（应写成 X0002.1、R100、D4、DT0004 等形式）")
        }
        AddressError::UnknownArea(s, letters) => {
            format!("`{s}` 中没有地址区 `{letters}`（地址区：X Y F G R A K T C DT DC D L P）")
        }
        AddressError::Bit(s) => format!("`{s}`：位号应为 0–7"),
        AddressError::NoBits(s, area) => {
            format!("`{s}`：{area} 地址没有位（只有 X Y F G R A K 有位）")
        }
        AddressError::Range { text, area, lo, hi } => {
            format!("{text} 超出范围（{area}{lo}–{area}{hi}）")
        }
    }
}

/// `OperandError` in Chinese, with the same specifics as its English.
fn operand_error_zh(e: &OperandError) -> String {
    match e {
        OperandError::Empty => "缺少操作数".into(),
        OperandError::Number(s) => {
            format!("`{s}` 不是数字（应写成 12、-5、0x1F 或 1.5 等形式）")
        }
        OperandError::Address(e) => address_zh(e),
        OperandError::Unrecognised(s) => format!("`{s}` 既不是地址、常数，也不是符号名"),
    }
}

/// `Taken` in Chinese, with the same specifics as its English.
fn taken_zh(e: &Taken) -> String {
    match e {
        Taken::Symbols { table, row } => format!("{table} 第 {} 行", row + 1),
        Taken::Data { sheet, row } => {
            format!(
                "数据表 {} 第 {} 行",
                sheet.data_name().unwrap_or("D"),
                row + 1
            )
        }
        Taken::Row(row) => format!("第 {} 行", row + 1),
        Taken::Block(p) => format!("{BLOCK_SYMBOLS} {p}"),
    }
}

/// `TableError` in Chinese, with the same specifics as its English.
fn table_error_zh(e: &TableError) -> String {
    match e {
        TableError::AddressEmpty => "必须填写地址（要删除该行，请用“删除行”）".into(),
        TableError::Address(e) => address_zh(e),
        TableError::AreaNotHere { address, allowed } => {
            format!("{address}：此处只允许这些地址区：{}", allowed.describe())
        }
        TableError::AddressTwice { address, at } => {
            format!("{address}：地址已在 {} 中列出", taken_zh(at))
        }
        TableError::SymbolName { name } => format!(
            "`{name}`：符号由字母、数字、`_` 和汉字组成，不以数字开头，最多 32 个字符，且不能是地址"
        ),
        TableError::SymbolTwice { name, at } => {
            format!("`{name}`：符号已存在：{}", taken_zh(at))
        }
        TableError::SymbolElsewhere { name, address } => {
            format!("`{name}`：该符号已代表 {address}")
        }
        TableError::CommentTooLong { bytes, max } => {
            format!("注释最多 {max} 字节，现为 {bytes} 字节")
        }
        TableError::NotInteger { text } => {
            format!("`{text}`：请输入 -2147483647 到 2147483647 之间的整数")
        }
        TableError::NotReal { text } => format!("`{text}`：请输入数字"),
        TableError::AlarmRange { text } => format!(
            "`{text}`：报警号为 {}–{}",
            ALARM_NUMBERS.start(),
            ALARM_NUMBERS.end()
        ),
        TableError::AlarmTwice { number, by } => {
            format!("{number}：报警号已被 {by} 使用")
        }
        TableError::MCodeRange { text } => {
            format!("`{text}`：M 代码为 {}–{}", M_CODES.start(), M_CODES.end())
        }
        TableError::MCodeTwice { code, row } => {
            format!("M{code:02}：该 M 代码已列出（第 {} 行）", row + 1)
        }
        TableError::NoFreeKey { .. } => "已没有可插入的空闲地址".into(),
        TableError::PasswordWrong => "当前密码错误".into(),
        TableError::PasswordEmpty => "密码为空".into(),
        TableError::PasswordMismatch => "两次输入的密码不一致".into(),
    }
}

/// `ModelError` in Chinese, with the same specifics as its English.
fn model_error_zh(e: &ModelError) -> String {
    match e {
        ModelError::Name(n) => format!(
            "设备名 `{n}` 无效：请用字母开头、由字母数字和 _ 组成、不像地址的名称（最多 24 个字符）"
        ),
        ModelError::NameTwice { name, first } => {
            format!(
                "设备名 `{name}` 已被设备 {} 使用：请另起一个名称",
                first + 1
            )
        }
        ModelError::Address {
            device,
            field,
            error,
        } => format!("设备 `{device}` 的 {field}：{}", address_zh(error)),
        ModelError::NotInput {
            device,
            field,
            address,
        } => format!("设备 `{device}` 的 {field}：{address} 不是输入；设备只写 X 位（PLC 的输入）"),
        ModelError::NotBit {
            device,
            field,
            address,
        } => {
            format!("设备 `{device}` 的 {field}：{address} 是字节，应写位地址（例如 {address}.0）")
        }
        ModelError::Parameter {
            device,
            field,
            limit,
        } => format!(
            "设备 `{device}` 的 {field} 不可能：允许 {}",
            limit_zh(*limit)
        ),
        ModelError::Expression {
            device,
            field,
            error,
        } => format!("设备 `{device}` 的 {field}：{}", expr_error_zh(error)),
        ModelError::Start { axis } => format!(
            "第 {} 轴的上电位置（start_mm）不可能：应为 −100000…100000 mm，且最多 5 个轴",
            axis + 1
        ),
        ModelError::TwoWriters {
            device,
            address,
            other,
        } => format!(
            "设备 `{device}` 和设备 `{other}` 都写 {address}：一个输入只能由一个设备驱动，请删去其中一个绑定"
        ),
    }
}

/// What an impossible device parameter must be, in Chinese.
fn limit_zh(limit: Limit) -> String {
    match limit {
        Limit::Range(lo, hi) => format!("{lo}…{hi}"),
        Limit::AtLeast(lo) => format!("{lo}…"),
        Limit::Station => "1…stations".into(),
        Limit::CodeBits => "足以为每个刀位编码的位数，最多 32 位".into(),
        Limit::WindowTick => "至少一个周期的到位窗口：station_ms × window_pct ≥ 800".into(),
        Limit::OneDirection => "CCW 输出与方向输出只能二选一".into(),
        Limit::Ordered => "from_mm ≤ to_mm，且两者均为有限值".into(),
        Limit::PulseOn => "period_ms ≥ 1，且 on_ms ≤ period_ms".into(),
    }
}

/// `ExprError` in Chinese, with the same specifics as its English.
fn expr_error_zh(e: &ExprError) -> String {
    match e {
        ExprError::Unexpected { at, found } if found.is_empty() => {
            format!("条件在第 {at} 个字符处结束，此处应有地址、`设备名.状态`、0、1、`!` 或 `(`")
        }
        ExprError::Unexpected { at, found } => format!(
            "第 {at} 个字符处的 `{found}` 不应出现在此（例如写 Y0000.6 & !X0001.6、chuck.advanced | door.moving）"
        ),
        ExprError::Unclosed => "有 `(` 未闭合：请补上 `)`".to_string(),
        ExprError::Address(e) => address_zh(e),
        ExprError::NotBit(a) => format!("{a} 是字节：条件只读位（例如 {a}.0）"),
        ExprError::UnknownDevice(d) => {
            format!("没有名为 `{d}` 的设备：请使用本机床模型中的设备名")
        }
        ExprError::UnknownState {
            device,
            state,
            states,
        } => format!(
            "设备 `{device}` 没有状态 `{state}`；它的状态有：{}",
            states.join("、")
        ),
        ExprError::StateInFollower(s) => {
            format!("`{s}`：跟随器只能读地址；要读设备状态请改用表达式设备")
        }
        ExprError::TooDeep => {
            "条件嵌套过深（最多 60 层括号、64 个待算值）：请拆到表达式设备中".to_string()
        }
    }
}

/// `DigitGroupError` in Chinese, with the same specifics as its English.
fn digit_group_zh(e: &DigitGroupError) -> &'static str {
    match e {
        DigitGroupError::Ctrc { .. } => {
            "CTRC 的 FMT 为 0000、0001、0010 或 0011（00ab：a = 初始值，b = 减计数）"
        }
        DigitGroupError::Pari { .. } => "PARI 的 OE 为 0000（偶校验）或 0001（奇校验）",
        DigitGroupError::Xmov { .. } => {
            "XMOV 的 FMT 为 0nnx：nn 个元素（00–99），每个元素 x = 1、2 或 4 字节"
        }
    }
}

/// `OperandRefusal` in Chinese, with the same specifics as its English.
fn operand_refusal_zh(e: &OperandRefusal) -> String {
    match e {
        OperandRefusal::TooMany => "该指令没有这么多操作数".into(),
        OperandRefusal::Kind { expected, found } => {
            format!("应为{}，实为 `{found}`", expected_text_zh(*expected))
        }
        OperandRefusal::WantsBit(a) => format!("应为位地址，如 R0010.0，实为 `{a}`"),
        OperandRefusal::WantsByte(a) => {
            format!("应为不带位的字节地址，如 R0010，实为 `{a}`")
        }
        OperandRefusal::Size(v) => format!("大小应为 1、2 或 4，不能是 {v}"),
        OperandRefusal::Digits { value, binary } => format!(
            "应写 4 位{}数字，不能是 `{value}`",
            if *binary { "二进制" } else { "十进制" }
        ),
        OperandRefusal::DigitGroup(e) => digit_group_zh(e).into(),
        OperandRefusal::ConstRange { value, min, max } => {
            format!("{value} 超出范围（{min}–{max}）")
        }
        OperandRefusal::ConstTooBig(v) => format!("{v} 超出范围（−2147483647–2147483647）"),
        OperandRefusal::ReadOnly { address, .. } => {
            format!("{address} 不能写入：X 和 F 是输入，对程序只读")
        }
        OperandRefusal::Area { address, allowed } => {
            format!("此处不允许使用 {address}；请用 {}", allowed.describe())
        }
        OperandRefusal::Range(e) => address_zh(e),
    }
}

/// What an operand of this kind looks like, in Chinese words.
fn expected_text_zh(kind: OperandKind) -> &'static str {
    match kind {
        OperandKind::Size => "大小 1、2 或 4",
        OperandKind::Const => "常数",
        OperandKind::Digits { .. } => "4 位数字组，如 0000",
        OperandKind::Bit => "位地址，如 R0010.0",
        OperandKind::Byte => "地址，如 R0010 或 D0004",
        OperandKind::ConstOrByte => "整数常数或地址",
        OperandKind::RealOrD => "实数常数或 D 地址",
        OperandKind::BitOrByte => "位地址或字节地址",
        OperandKind::Label => "标号，如 L0001",
        OperandKind::Subprogram => "子程序，如 P0001",
        OperandKind::Timer => "定时器，如 T0001",
        OperandKind::Counter => "计数器，如 C0001",
    }
}
