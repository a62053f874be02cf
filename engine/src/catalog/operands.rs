//! The building blocks of the table: operand constructors and the operand lists several
//! instructions share, so each operand is described once.

use super::areas::*;
use super::{Access, CONST_MAX, OperandKind, OperandSpec, Role, Width};
use crate::address::AreaSet;

pub(super) const fn spec(
    name: &'static str,
    kind: OperandKind,
    areas: AreaSet,
    width: Width,
    access: Access,
    help_zh: &'static str,
    help_en: &'static str,
) -> OperandSpec {
    OperandSpec {
        name,
        kind,
        areas,
        width,
        access,
        role: Role::Plain,
        min: -CONST_MAX,
        max: CONST_MAX,
        help_zh,
        help_en,
    }
}

/// The same operand with the manual's own list of areas.
pub(super) const fn only(mut s: OperandSpec, areas: AreaSet) -> OperandSpec {
    s.areas = areas;
    s
}

/// The same operand in a role other code looks for.
pub(super) const fn with_role(mut s: OperandSpec, role: Role) -> OperandSpec {
    s.role = role;
    s
}

pub(super) const fn with_range(mut s: OperandSpec, min: i64, max: i64) -> OperandSpec {
    s.min = min;
    s.max = max;
    s
}

pub(super) const fn size(zh: &'static str, en: &'static str) -> OperandSpec {
    with_range(
        spec(
            "SIZE",
            OperandKind::Size,
            AreaSet::EMPTY,
            Width::None,
            Access::Read,
            zh,
            en,
        ),
        1,
        4,
    )
}
pub(super) const fn konst(
    name: &'static str,
    min: i64,
    max: i64,
    zh: &'static str,
    en: &'static str,
) -> OperandSpec {
    with_range(
        spec(
            name,
            OperandKind::Const,
            AreaSet::EMPTY,
            Width::None,
            Access::Read,
            zh,
            en,
        ),
        min,
        max,
    )
}
pub(super) const fn digits(
    name: &'static str,
    max_digit: u8,
    zh: &'static str,
    en: &'static str,
) -> OperandSpec {
    with_range(
        spec(
            name,
            OperandKind::Digits { max_digit },
            AreaSet::EMPTY,
            Width::None,
            Access::Read,
            zh,
            en,
        ),
        0,
        9999,
    )
}
pub(super) const fn bit_in(name: &'static str, zh: &'static str, en: &'static str) -> OperandSpec {
    spec(
        name,
        OperandKind::Bit,
        BITS_READ,
        Width::None,
        Access::Read,
        zh,
        en,
    )
}
pub(super) const fn bit_out(
    name: &'static str,
    areas: AreaSet,
    zh: &'static str,
    en: &'static str,
) -> OperandSpec {
    spec(
        name,
        OperandKind::Bit,
        areas,
        Width::None,
        Access::Write,
        zh,
        en,
    )
}
pub(super) const fn bits3_out(areas: AreaSet, zh: &'static str, en: &'static str) -> OperandSpec {
    spec(
        "OUT",
        OperandKind::Bit,
        areas,
        Width::Bits3,
        Access::Write,
        zh,
        en,
    )
}
pub(super) const fn byte_in(
    name: &'static str,
    width: Width,
    zh: &'static str,
    en: &'static str,
) -> OperandSpec {
    spec(
        name,
        OperandKind::Byte,
        BYTES_READ,
        width,
        Access::Read,
        zh,
        en,
    )
}
pub(super) const fn byte_out(
    name: &'static str,
    areas: AreaSet,
    width: Width,
    zh: &'static str,
    en: &'static str,
) -> OperandSpec {
    spec(name, OperandKind::Byte, areas, width, Access::Write, zh, en)
}
pub(super) const fn signed_in(
    name: &'static str,
    width: Width,
    zh: &'static str,
    en: &'static str,
) -> OperandSpec {
    spec(
        name,
        OperandKind::ConstOrByte,
        BYTES_READ,
        width,
        Access::Read,
        zh,
        en,
    )
}
pub(super) const fn unsigned_in(
    name: &'static str,
    width: Width,
    max: i64,
    zh: &'static str,
    en: &'static str,
) -> OperandSpec {
    with_range(
        spec(
            name,
            OperandKind::ConstOrByte,
            BYTES_READ,
            width,
            Access::Read,
            zh,
            en,
        ),
        0,
        max,
    )
}
pub(super) const fn real_in(name: &'static str, zh: &'static str, en: &'static str) -> OperandSpec {
    spec(
        name,
        OperandKind::RealOrD,
        D_ONLY,
        Width::Bytes(4),
        Access::Read,
        zh,
        en,
    )
}
pub(super) const fn real_out(zh: &'static str, en: &'static str) -> OperandSpec {
    spec(
        "OUT",
        OperandKind::Byte,
        D_ONLY,
        Width::Bytes(4),
        Access::Write,
        zh,
        en,
    )
}
pub(super) const fn rst(zh: &'static str, en: &'static str) -> OperandSpec {
    bit_in("RST", zh, en)
}
pub(super) const fn err(zh: &'static str, en: &'static str) -> OperandSpec {
    bit_out("ERR", BITS_WRITE, zh, en)
}

pub(super) const SIZE_STD: OperandSpec =
    size("数据长度：1、2 或 4 字节", "Data size: 1, 2 or 4 bytes");
// The real-number instructions' RST and ERR take only X Y R K and Y R K (§1.4.19, §1.4.33,
// §1.4.43–46), unlike the integer ones.
pub(super) const RST_ERR: OperandSpec = only(
    rst(
        "复位：为 1 时清除 ERR，不执行运算",
        "Reset: 1 clears ERR and skips the operation",
    ),
    REAL_RST,
);
pub(super) const RST_OUT: OperandSpec =
    rst("复位：为 1 时 OUT、ERR 清 0", "Reset: 1 clears OUT and ERR");
pub(super) const ERR_STD: OperandSpec = err(
    "错误输出：溢出或错误时为 1",
    "Error output: 1 on overflow or error",
);
pub(super) const ERR_LATCHED: OperandSpec = err(
    "错误输出：出错时置 1，保持到 RST",
    "Error output: set on error, kept until RST",
);
pub(super) const REAL_ERR_LATCHED: OperandSpec = only(ERR_LATCHED, REAL_ERR);
pub(super) const REAL_ERR_STD: OperandSpec = only(ERR_STD, REAL_ERR);
pub(super) const REAL_RST_OUT: OperandSpec = only(RST_OUT, REAL_RST);

/// CODB's table entries: constants of SIZE1 width.
pub static CODB_TABLE_ENTRY: OperandSpec = spec(
    "TABLE",
    OperandKind::Const,
    AreaSet::EMPTY,
    Width::None,
    Access::Read,
    "转换表数据（SIZE1 宽度的常数）",
    "Conversion-table entry (a constant of width SIZE1)",
);

pub(super) const ARITH_B: &[OperandSpec] = &[
    SIZE_STD,
    signed_in(
        "IN1",
        Width::SizeOf(0),
        "第一个操作数：常数或地址",
        "First operand: constant or address",
    ),
    signed_in(
        "IN2",
        Width::SizeOf(0),
        "第二个操作数：常数或地址",
        "Second operand: constant or address",
    ),
    rst(
        "复位：为 1 时 ERR 清 0，OUT 不变",
        "Reset: 1 clears ERR, OUT unchanged",
    ),
    byte_out(
        "OUT",
        BYTES_WRITE,
        Width::SizeOf(0),
        "结果输出地址",
        "Result address",
    ),
    ERR_STD,
];
pub(super) const ARITH_R: &[OperandSpec] = &[
    real_in(
        "IN1",
        "第一个实数：常数或 D 地址",
        "First real: constant or D address",
    ),
    real_in(
        "IN2",
        "第二个实数：常数或 D 地址",
        "Second real: constant or D address",
    ),
    RST_ERR,
    real_out("实数结果（D 地址）", "Real result (D address)"),
    REAL_ERR_STD,
];
pub(super) const MUL_DIV_B: &[OperandSpec] = &[
    unsigned_in(
        "IN1",
        Width::Bytes(2),
        65535,
        "第一个操作数：0–65535 的常数或 16 位地址",
        "First operand: constant 0–65535 or a 16-bit address",
    ),
    unsigned_in(
        "IN2",
        Width::Bytes(2),
        65535,
        "第二个操作数：0–65535 的常数或 16 位地址",
        "Second operand: constant 0–65535 or a 16-bit address",
    ),
    RST_OUT,
    byte_out(
        "OUT",
        BYTES_WRITE,
        Width::Bytes(4),
        "32 位结果地址",
        "32-bit result address",
    ),
    ERR_LATCHED,
];
pub(super) const MUL_DIV_R: &[OperandSpec] = &[
    real_in(
        "IN1",
        "第一个实数：常数或 D 地址",
        "First real: constant or D address",
    ),
    real_in(
        "IN2",
        "第二个实数：常数或 D 地址",
        "Second real: constant or D address",
    ),
    REAL_RST_OUT,
    real_out("实数结果（D 地址）", "Real result (D address)"),
    REAL_ERR_LATCHED,
];
pub(super) const WORD_LOGIC: &[OperandSpec] = &[
    SIZE_STD,
    signed_in(
        "IN1",
        Width::SizeOf(0),
        "第一个操作数：常数或地址",
        "First operand: constant or address",
    ),
    signed_in(
        "IN2",
        Width::SizeOf(0),
        "第二个操作数：常数或地址",
        "Second operand: constant or address",
    ),
    byte_out(
        "OUT",
        BYTES_WRITE,
        Width::SizeOf(0),
        "结果输出地址",
        "Result address",
    ),
];
pub(super) const SHIFT: &[OperandSpec] = &[
    SIZE_STD,
    unsigned_in(
        "N",
        Width::Bytes(1),
        255,
        "移位位数：常数或 1 字节地址",
        "Shift count: constant or 1-byte address",
    ),
    signed_in(
        "IN",
        Width::SizeOf(0),
        "被移位的数据：常数或地址",
        "Data to shift: constant or address",
    ),
    byte_out(
        "OUT",
        BYTES_WRITE,
        Width::SizeOf(0),
        "结果输出地址",
        "Result address",
    ),
];
const TIMER_T: OperandSpec = with_role(
    spec(
        "T",
        OperandKind::Timer,
        T_ONLY,
        Width::Bytes(4),
        Access::ReadWrite,
        "定时器号 T0–T199",
        "Timer number T0–T199",
    ),
    Role::TimerNumber,
);
// A negative preset counts as 0 (docs/plc.md, "Timer/counter"), so a constant is 0 or more,
// as CTRC's N.
const TIMER_PT: OperandSpec = with_role(
    with_range(
        spec(
            "PT",
            OperandKind::ConstOrByte,
            DT_ONLY,
            Width::Bytes(4),
            Access::Read,
            "设定时间（ms）：0–2147483647 的常数或 DT 地址",
            "Preset time (ms): constant 0–2147483647 or DT address",
        ),
        0,
        CONST_MAX,
    ),
    Role::Preset,
);
const TIMER_OUT: OperandSpec = bit_out(
    "OUT",
    BITS_WRITE,
    "定时到输出",
    "Output when the time is up",
);
/// TMRB clears OUT whenever ACT = 0, so its OUT is written at every execution.
pub(super) const TMRB_OPERANDS: &[OperandSpec] =
    &[TIMER_T, TIMER_PT, with_role(TIMER_OUT, Role::Driven)];
/// TMRC keeps T and OUT while ACT = 0.
pub(super) const TMRC_OPERANDS: &[OperandSpec] = &[TIMER_T, TIMER_PT, TIMER_OUT];
pub(super) const TRIG: &[OperandSpec] = &[
    real_in(
        "IN",
        "输入（弧度）：实数常数或 D 地址",
        "Input in radians: real constant or D address",
    ),
    real_out("实数结果（D 地址）", "Real result (D address)"),
    RST_ERR,
    REAL_ERR_LATCHED,
];
/// DIFU's and DIFD's OUT: 1 for the scan of the edge, 0 at every other execution.
pub(super) const ONE_BIT_OUT: &[OperandSpec] = &[with_role(
    bit_out("OUT", BITS_WRITE, "输出位地址", "Output bit address"),
    Role::Driven,
)];

impl OperandSpec {
    /// The same operand, refusing constants when `allow` is false (ROTB's positions are
    /// addresses in the manual's parameter list).
    pub const fn with_const(mut self, allow: bool) -> OperandSpec {
        if !allow {
            self.kind = OperandKind::Byte;
        }
        self
    }
}
