//! The instruction catalogue: the one place where an instruction is described.
//!
//! Every instruction's name, operands (in IL order), operand kinds, allowed areas, widths,
//! step cost and help text (zh/en) live in [`CATALOG`]. The compiler's checks, IL export and
//! import, the editor's parameter dialog and the VM's dispatch all read from here; there is no
//! second list of instructions anywhere in the code base.

use crate::address::{Area, AreaSet};

/// Bit addresses a contact may read.
pub const BITS_READ: AreaSet = AreaSet::of(&[
    Area::X,
    Area::Y,
    Area::F,
    Area::G,
    Area::R,
    Area::A,
    Area::K,
]);
/// Bit addresses a coil may write.
pub const BITS_WRITE: AreaSet = AreaSet::of(&[Area::Y, Area::G, Area::R, Area::A, Area::K]);
/// Every data area a byte or word operand may read.
pub const BYTES_READ: AreaSet = AreaSet::of(&[
    Area::X,
    Area::Y,
    Area::F,
    Area::G,
    Area::R,
    Area::A,
    Area::K,
    Area::T,
    Area::C,
    Area::Dt,
    Area::Dc,
    Area::D,
]);
/// Every data area a byte or word operand may write.
pub const BYTES_WRITE: AreaSet = AreaSet::of(&[
    Area::Y,
    Area::G,
    Area::R,
    Area::A,
    Area::K,
    Area::T,
    Area::C,
    Area::Dt,
    Area::Dc,
    Area::D,
]);
/// The relay areas a byte result may go to (DECB OUT, MOVE OUT, CMP OUT).
const RELAYS_WRITE: AreaSet = BITS_WRITE;
/// CMPR's OUT (§1.4.4: R Y K).
const CMPR_OUT: AreaSet = AreaSet::of(&[Area::R, Area::Y, Area::K]);
/// CODB's OUT (§1.4.11: R Y G K A D DT DC).
const CODB_OUT: AreaSet = AreaSet::of(&[
    Area::R,
    Area::Y,
    Area::G,
    Area::K,
    Area::A,
    Area::D,
    Area::Dt,
    Area::Dc,
]);
const D_ONLY: AreaSet = AreaSet::of(&[Area::D]);
/// Relay and data areas without timers, counters and presets (CODB IN, PARI IN, MOVE IN).
const RELAYS_AND_D: AreaSet = AreaSet::of(&[
    Area::X,
    Area::Y,
    Area::F,
    Area::G,
    Area::R,
    Area::A,
    Area::K,
    Area::D,
]);
/// MOVE OUT (§1.4.25: R A K Y G D).
const MOVE_OUT: AreaSet = AreaSet::of(&[Area::Y, Area::G, Area::R, Area::A, Area::K, Area::D]);
/// ROTB IN_W/IN_D, DSCHB IN1/INL/DS (§1.4.16, §1.4.39: no T or C).
const NO_TC_READ: AreaSet = AreaSet::of(&[
    Area::X,
    Area::Y,
    Area::F,
    Area::G,
    Area::R,
    Area::A,
    Area::K,
    Area::D,
    Area::Dc,
    Area::Dt,
]);
/// ROTB OUTE, DSCHB DI (§1.4.16, §1.4.39: no T or C).
const NO_TC_WRITE: AreaSet = AreaSet::of(&[
    Area::Y,
    Area::G,
    Area::R,
    Area::A,
    Area::K,
    Area::D,
    Area::Dc,
    Area::Dt,
]);
/// ZCP inputs (§1.4.42: no DC or DT).
const NO_PRESETS_READ: AreaSet = AreaSet::of(&[
    Area::X,
    Area::Y,
    Area::F,
    Area::G,
    Area::R,
    Area::A,
    Area::K,
    Area::D,
    Area::C,
    Area::T,
]);
/// RST of the real-number instructions (§1.4.19, §1.4.33, §1.4.43–46: X Y R K).
const REAL_RST: AreaSet = AreaSet::of(&[Area::X, Area::Y, Area::R, Area::K]);
/// ERR of the real-number instructions (Y R K).
const REAL_ERR: AreaSet = AreaSet::of(&[Area::Y, Area::R, Area::K]);
const DT_ONLY: AreaSet = AreaSet::of(&[Area::Dt]);
const DC_ONLY: AreaSet = AreaSet::of(&[Area::Dc]);
const T_ONLY: AreaSet = AreaSet::of(&[Area::T]);
const C_ONLY: AreaSet = AreaSet::of(&[Area::C]);
const L_ONLY: AreaSet = AreaSet::of(&[Area::L]);
const P_ONLY: AreaSet = AreaSet::of(&[Area::P]);

/// Largest magnitude of a constant (§1.2: D holds −2147483647…2147483647).
pub const CONST_MAX: i64 = 2_147_483_647;

/// What an operand accepts.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum OperandKind {
    /// A size constant: 1, 2 or 4 bytes.
    Size,
    /// An integer constant in `min..=max`.
    Const,
    /// A group of 4 digits (FMT, H/L, OE), each at most `max_digit`.
    Digits {
        /// Largest digit allowed (1 for binary groups, 9 for decimal ones).
        max_digit: u8,
    },
    /// A bit address.
    Bit,
    /// A byte or word address.
    Byte,
    /// An integer constant or a byte/word address.
    ConstOrByte,
    /// A real constant or a D address.
    RealOrD,
    /// A bit address or a byte/word address (WINDR's ERR).
    BitOrByte,
    /// A jump label `L`.
    Label,
    /// A subprogram number `P`.
    Subprogram,
    /// A timer number `T`.
    Timer,
    /// A counter number `C`.
    Counter,
}

/// How wide a byte/word access of an operand is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Width {
    /// Not a data access (labels, subprograms, constants only).
    None,
    /// A fixed number of bytes.
    Bytes(u8),
    /// The value of the SIZE operand at this index.
    SizeOf(u8),
    /// Three result bits starting at the operand's bit (CMP, CMPR, ZCP).
    Bits3,
    /// `count` elements of 4 bytes (PSGNL's AREA).
    Elements4(u8),
    /// A table whose element width and length are known only from other operands.
    Table,
}

/// Whether an instruction reads or writes an operand.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Access {
    /// Read only.
    Read,
    /// Written (and not read).
    Write,
    /// Read and written (ALT, timers' and counters' numbers).
    ReadWrite,
    /// Written when the constant operand at `operand` equals `value`, else read (XMOV's DS/DD).
    WriteWhen {
        /// Index of the controlling constant operand.
        operand: u8,
        /// Its value for which this operand is written.
        value: i8,
    },
}

/// One operand of an instruction.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct OperandSpec {
    /// The operand's name as the manual writes it (`SIZE`, `IN1`, `OUT`).
    pub name: &'static str,
    /// What it accepts.
    pub kind: OperandKind,
    /// Areas an address operand may name.
    pub areas: AreaSet,
    /// Width of the data access.
    pub width: Width,
    /// Read, written, or both.
    pub access: Access,
    /// Smallest constant accepted.
    pub min: i64,
    /// Largest constant accepted.
    pub max: i64,
    /// Help text in Chinese.
    pub help_zh: &'static str,
    /// Help text in English.
    pub help_en: &'static str,
}

impl OperandSpec {
    /// Whether this operand may be written by its instruction in some configuration.
    pub fn may_write(&self) -> bool {
        !matches!(self.access, Access::Read)
    }

    /// Whether a constant is accepted here.
    pub fn accepts_const(&self) -> bool {
        matches!(
            self.kind,
            OperandKind::Size
                | OperandKind::Const
                | OperandKind::Digits { .. }
                | OperandKind::ConstOrByte
                | OperandKind::RealOrD
        )
    }
}

/// Basic instructions are one step and carry the rung's logic; function instructions are boxes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum InstrClass {
    /// A contact: LD LDI AND ANI OR ORI.
    Contact,
    /// A block or branch operation: ORB ANB MPS MRD MPP.
    Stack,
    /// A coil: OUT OUTN.
    Coil,
    /// A function instruction (a box at the right end of a rung).
    Function,
}

/// The categories of the function-instruction menu (§3.2.2, with the rest added).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Category {
    /// Basic instructions.
    Basic,
    /// 位输出: SET RST DIFU DIFD ALT.
    BitOutput,
    /// 标号/跳转: JMPB LBL CALL CALLU.
    LabelJump,
    /// 定时/计数: TMRB TMRC CTRC.
    TimerCounter,
    /// 旋转/移位: ROTB WSHL WSHR.
    RotateShift,
    /// 整数数学运算: ADDB SUBB MULB DIVB.
    IntegerMath,
    /// Comparison: CMP CMPR ZCP.
    Compare,
    /// Data transfer and conversion: MOVN MOVR MOVE DECB CODB XMOV DSCHB.
    DataTransfer,
    /// Logic operations: WAND WOR WXOR WINV PARI.
    Logic,
    /// Real maths: ADDR SUBR MULR DIVR SIN COS TAN SQRT DTR ROUND.
    RealMath,
    /// CNC interface: WINDR AXCTL PSGNL PSGN2.
    Cnc,
}

impl Category {
    /// Every category in menu order.
    pub const ALL: [Category; 11] = [
        Category::Basic,
        Category::BitOutput,
        Category::LabelJump,
        Category::TimerCounter,
        Category::RotateShift,
        Category::IntegerMath,
        Category::Compare,
        Category::DataTransfer,
        Category::Logic,
        Category::RealMath,
        Category::Cnc,
    ];

    /// The category's name in Chinese.
    pub fn name_zh(self) -> &'static str {
        match self {
            Category::Basic => "基本指令",
            Category::BitOutput => "位输出",
            Category::LabelJump => "标号/跳转",
            Category::TimerCounter => "定时/计数",
            Category::RotateShift => "旋转/移位",
            Category::IntegerMath => "整数数学运算",
            Category::Compare => "比较",
            Category::DataTransfer => "数据传送/转换",
            Category::Logic => "逻辑运算",
            Category::RealMath => "实数运算",
            Category::Cnc => "CNC 接口",
        }
    }

    /// The category's name in English.
    pub fn name_en(self) -> &'static str {
        match self {
            Category::Basic => "Basic",
            Category::BitOutput => "Bit output",
            Category::LabelJump => "Label/jump",
            Category::TimerCounter => "Timer/counter",
            Category::RotateShift => "Rotate/shift",
            Category::IntegerMath => "Integer maths",
            Category::Compare => "Compare",
            Category::DataTransfer => "Data transfer",
            Category::Logic => "Logic",
            Category::RealMath => "Real maths",
            Category::Cnc => "CNC interface",
        }
    }
}

/// One instruction of the catalogue.
#[derive(Debug, PartialEq, Eq)]
pub struct InstrSpec {
    /// Its opcode.
    pub op: Op,
    /// Its mnemonic as written in IL.
    pub name: &'static str,
    /// What kind of instruction it is.
    pub class: InstrClass,
    /// Menu category.
    pub category: Category,
    /// Operands in IL order (CODB's table entries follow its fixed operands, see [`Op::Codb`]).
    pub operands: &'static [OperandSpec],
    /// Help text in Chinese.
    pub help_zh: &'static str,
    /// Help text in English.
    pub help_en: &'static str,
}

impl InstrSpec {
    /// Whether the instruction takes the rung's power as ACT. LBL and CALLU stand alone.
    pub fn needs_act(&self) -> bool {
        !matches!(self.op, Op::Lbl | Op::Callu)
    }

    /// Whether the instruction ends a rung's logic (a coil or a box).
    pub fn is_output(&self) -> bool {
        matches!(self.class, InstrClass::Coil | InstrClass::Function)
    }

    /// Steps the instruction costs with `operand_count` operands (docs/plc.md, "Blocks and
    /// steps": a basic instruction is 1 step, a function instruction 1 + its operands, CODB's
    /// table included).
    pub fn steps(&self, operand_count: usize) -> u32 {
        match self.class {
            InstrClass::Function => 1 + operand_count as u32,
            _ => 1,
        }
    }

    /// The index of the first CODB table entry, for the one variadic instruction.
    pub fn table_start(&self) -> Option<usize> {
        (self.op == Op::Codb).then_some(4)
    }

    /// The operand spec for operand `i`, including CODB's table entries.
    pub fn operand(&self, i: usize) -> Option<&'static OperandSpec> {
        match self.table_start() {
            Some(start) if i >= start => Some(&CODB_TABLE_ENTRY),
            _ => self.operands.get(i),
        }
    }
}

const fn spec(
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
        min: -CONST_MAX,
        max: CONST_MAX,
        help_zh,
        help_en,
    }
}

/// The same operand with the manual's own list of areas.
const fn only(mut s: OperandSpec, areas: AreaSet) -> OperandSpec {
    s.areas = areas;
    s
}

const fn with_range(mut s: OperandSpec, min: i64, max: i64) -> OperandSpec {
    s.min = min;
    s.max = max;
    s
}

const fn size(zh: &'static str, en: &'static str) -> OperandSpec {
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
const fn konst(
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
const fn digits(
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
const fn bit_in(name: &'static str, zh: &'static str, en: &'static str) -> OperandSpec {
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
const fn bit_out(
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
const fn bits3_out(areas: AreaSet, zh: &'static str, en: &'static str) -> OperandSpec {
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
const fn byte_in(
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
const fn byte_out(
    name: &'static str,
    areas: AreaSet,
    width: Width,
    zh: &'static str,
    en: &'static str,
) -> OperandSpec {
    spec(name, OperandKind::Byte, areas, width, Access::Write, zh, en)
}
const fn signed_in(
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
const fn unsigned_in(
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
const fn real_in(name: &'static str, zh: &'static str, en: &'static str) -> OperandSpec {
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
const fn real_out(zh: &'static str, en: &'static str) -> OperandSpec {
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
const fn rst(zh: &'static str, en: &'static str) -> OperandSpec {
    bit_in("RST", zh, en)
}
const fn err(zh: &'static str, en: &'static str) -> OperandSpec {
    bit_out("ERR", BITS_WRITE, zh, en)
}

const SIZE_STD: OperandSpec = size("数据长度：1、2 或 4 字节", "Data size: 1, 2 or 4 bytes");
// The real-number instructions' RST and ERR take only X Y R K and Y R K (§1.4.19, §1.4.33,
// §1.4.43–46), unlike the integer ones.
const RST_ERR: OperandSpec = only(
    rst(
        "复位：为 1 时清除 ERR，不执行运算",
        "Reset: 1 clears ERR and skips the operation",
    ),
    REAL_RST,
);
const RST_OUT: OperandSpec = rst("复位：为 1 时 OUT、ERR 清 0", "Reset: 1 clears OUT and ERR");
const ERR_STD: OperandSpec = err(
    "错误输出：溢出或错误时为 1",
    "Error output: 1 on overflow or error",
);
const ERR_LATCHED: OperandSpec = err(
    "错误输出：出错时置 1，保持到 RST",
    "Error output: set on error, kept until RST",
);
const REAL_ERR_LATCHED: OperandSpec = only(ERR_LATCHED, REAL_ERR);
const REAL_ERR_STD: OperandSpec = only(ERR_STD, REAL_ERR);
const REAL_RST_OUT: OperandSpec = only(RST_OUT, REAL_RST);

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

const ARITH_B: &[OperandSpec] = &[
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
const ARITH_R: &[OperandSpec] = &[
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
const MUL_DIV_B: &[OperandSpec] = &[
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
const MUL_DIV_R: &[OperandSpec] = &[
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
const WORD_LOGIC: &[OperandSpec] = &[
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
const SHIFT: &[OperandSpec] = &[
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
const TIMER: &[OperandSpec] = &[
    spec(
        "T",
        OperandKind::Timer,
        T_ONLY,
        Width::Bytes(4),
        Access::ReadWrite,
        "定时器号 T0–T199",
        "Timer number T0–T199",
    ),
    spec(
        "PT",
        OperandKind::ConstOrByte,
        DT_ONLY,
        Width::Bytes(4),
        Access::Read,
        "设定时间（ms）：常数或 DT 地址",
        "Preset time (ms): constant or DT address",
    ),
    bit_out(
        "OUT",
        BITS_WRITE,
        "定时到输出",
        "Output when the time is up",
    ),
];
const TRIG: &[OperandSpec] = &[
    real_in(
        "IN",
        "输入（弧度）：实数常数或 D 地址",
        "Input in radians: real constant or D address",
    ),
    real_out("实数结果（D 地址）", "Real result (D address)"),
    RST_ERR,
    REAL_ERR_LATCHED,
];
const ONE_BIT_OUT: &[OperandSpec] = &[bit_out(
    "OUT",
    BITS_WRITE,
    "输出位地址",
    "Output bit address",
)];

macro_rules! catalog {
    ($( $variant:ident $name:literal $class:ident $cat:ident [$($operand:expr),* $(,)?] $ops:ident? $zh:literal $en:literal; )*) => {
        /// An opcode: the identity of an instruction; [`Op::spec`] describes it.
        #[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
        #[repr(u8)]
        pub enum Op {
            $(
                #[doc = $en]
                $variant,
            )*
        }

        /// Every instruction, indexed by `Op as usize`.
        pub static CATALOG: &[InstrSpec] = &[
            $(InstrSpec {
                op: Op::$variant,
                name: $name,
                class: InstrClass::$class,
                category: Category::$cat,
                operands: catalog!(@ops $ops [$($operand),*]),
                help_zh: $zh,
                help_en: $en,
            },)*
        ];
    };
    (@ops none []) => { &[] };
    (@ops list [$($operand:expr),*]) => { &[$($operand),*] };
    (@ops shared [$operand:expr]) => { $operand };
}

catalog! {
    Ld "LD" Contact Basic [bit_in("b", "常开触点地址", "Normally-open contact address")] list?
        "取：以常开触点开始一个逻辑块" "Load: start a logic block with a normally-open contact";
    Ldi "LDI" Contact Basic [bit_in("b", "常闭触点地址", "Normally-closed contact address")] list?
        "取反：以常闭触点开始一个逻辑块" "Load inverse: start a logic block with a normally-closed contact";
    And "AND" Contact Basic [bit_in("b", "串联常开触点地址", "Series normally-open contact address")] list?
        "与：串联一个常开触点" "And: a normally-open contact in series";
    Ani "ANI" Contact Basic [bit_in("b", "串联常闭触点地址", "Series normally-closed contact address")] list?
        "与非：串联一个常闭触点" "And inverse: a normally-closed contact in series";
    Or "OR" Contact Basic [bit_in("b", "并联常开触点地址", "Parallel normally-open contact address")] list?
        "或：并联一个常开触点" "Or: a normally-open contact in parallel";
    Ori "ORI" Contact Basic [bit_in("b", "并联常闭触点地址", "Parallel normally-closed contact address")] list?
        "或非：并联一个常闭触点" "Or inverse: a normally-closed contact in parallel";
    Orb "ORB" Stack Basic [] none?
        "块或：把两个串联块并联" "Or block: connect two series blocks in parallel";
    Anb "ANB" Stack Basic [] none?
        "块与：把两个并联块串联" "And block: connect two parallel blocks in series";
    Mps "MPS" Stack Basic [] none?
        "进栈：保存分支点的运算结果" "Push: save the result at a branch point";
    Mrd "MRD" Stack Basic [] none?
        "读栈：读取分支点的运算结果" "Read: read the result saved at the branch point";
    Mpp "MPP" Stack Basic [] none?
        "出栈：读取并清除分支点的运算结果" "Pop: read and drop the result saved at the branch point";
    Out "OUT" Coil Basic [bit_out("b", BITS_WRITE, "输出线圈地址", "Output coil address")] list?
        "输出：线圈 := 运算结果" "Out: coil := result";
    Outn "OUTN" Coil Basic [bit_out("b", BITS_WRITE, "取反输出线圈地址", "Inverted output coil address")] list?
        "取反输出：线圈 := 运算结果取反" "Out inverted: coil := not result";

    Set "SET" Function BitOutput [bit_out("OUT", BITS_WRITE, "置位的位地址", "Bit to set")] list?
        "置位：ACT=1 时 OUT := 1" "Set: OUT := 1 while ACT = 1";
    Rst "RST" Function BitOutput [bit_out("OUT", BITS_WRITE, "复位的位地址", "Bit to reset")] list?
        "复位：ACT=1 时 OUT := 0" "Reset: OUT := 0 while ACT = 1";
    Cmp "CMP" Function Compare [
        SIZE_STD,
        signed_in("IN1", Width::SizeOf(0), "比较数据 1：常数或地址", "Value 1: constant or address"),
        signed_in("IN2", Width::SizeOf(0), "比较数据 2：常数或地址", "Value 2: constant or address"),
        bits3_out(RELAYS_WRITE, "结果：OUT=IN1>IN2，OUT+1=相等，OUT+2=IN1<IN2", "Result: OUT = IN1>IN2, OUT+1 = equal, OUT+2 = IN1<IN2"),
    ] list? "二进制数据比较" "Compare binary data";
    Cmpr "CMPR" Function Compare [
        real_in("IN1", "比较实数 1：常数或 D 地址", "Real 1: constant or D address"),
        real_in("IN2", "比较实数 2：常数或 D 地址", "Real 2: constant or D address"),
        bits3_out(CMPR_OUT, "结果：OUT=IN1>IN2，OUT+1=相等，OUT+2=IN1<IN2", "Result: OUT = IN1>IN2, OUT+1 = equal, OUT+2 = IN1<IN2"),
    ] list? "实数比较" "Compare real numbers";
    Tmrb "TMRB" Function TimerCounter [TIMER] shared?
        "定时器：ACT=1 计时，T≥PT 时 OUT=1；ACT=0 时 T、OUT 清 0" "On-delay timer: times while ACT = 1, OUT = 1 once T ≥ PT; ACT = 0 clears T and OUT";
    Tmrc "TMRC" Function TimerCounter [TIMER] shared?
        "累计定时器：ACT=0 时保持 T 与 OUT" "Retentive timer: ACT = 0 keeps T and OUT";
    Ctrc "CTRC" Function TimerCounter [
        digits("FMT", 1, "格式 00ab：b=0 加计数/1 减计数，a=初始值 0/1", "Format 00ab: b = 0 up / 1 down, a = initial value 0 / 1"),
        rst("复位：为 1 时 C 回到起始值，OUT := 0", "Reset: 1 returns C to its start value, OUT := 0"),
        spec("C", OperandKind::Counter, C_ONLY, Width::Bytes(4), Access::ReadWrite, "计数器号 C0–C199", "Counter number C0–C199"),
        with_range(spec("N", OperandKind::ConstOrByte, DC_ONLY, Width::Bytes(4), Access::Read, "计数预置值：0–2147483647 的常数或 DC 地址", "Preset: constant 0–2147483647 or DC address"), 0, CONST_MAX),
        bit_out("OUT", BITS_WRITE, "计数到输出", "Output when the count is reached"),
    ] list? "二进制计数器：ACT 每次上升沿计数一次" "Binary counter: counts each rising edge of ACT";
    Movn "MOVN" Function DataTransfer [
        SIZE_STD,
        signed_in("IN", Width::SizeOf(0), "源数据：常数或地址", "Source: constant or address"),
        byte_out("OUT", BYTES_WRITE, Width::SizeOf(0), "目标地址", "Destination address"),
    ] list? "二进制数据传送：OUT := IN" "Move binary data: OUT := IN";
    Movr "MOVR" Function DataTransfer [
        real_in("IN", "源实数：常数或 D 地址", "Source real: constant or D address"),
        real_out("目标 D 地址", "Destination D address"),
    ] list? "实数拷贝：OUT := IN" "Copy a real: OUT := IN";
    Decb "DECB" Function DataTransfer [
        SIZE_STD,
        byte_in("IN", Width::SizeOf(0), "译码数据地址", "Address of the code to decode"),
        konst("BASE", -CONST_MAX, CONST_MAX, "译码基数", "Base of the decoded range"),
        byte_out("OUT", RELAYS_WRITE, Width::Bytes(1), "译码结果字节：IN=BASE+k 时位 k 为 1", "Result byte: bit k is 1 when IN = BASE+k"),
    ] list? "二进制译码：判断 IN 是否为 BASE…BASE+7" "Decode binary: tests IN against BASE…BASE+7";
    Codb "CODB" Function DataTransfer [
        size("SIZE1：输出数据长度 1、2 或 4 字节", "SIZE1: output size 1, 2 or 4 bytes"),
        konst("SIZE2", 1, 256, "转换表数据个数 1–256", "Number of table entries, 1–256"),
        spec("IN", OperandKind::Byte, RELAYS_AND_D, Width::Bytes(1), Access::Read, "表内序号地址（1 字节，无符号）", "Table index address (1 byte, unsigned)"),
        byte_out("OUT", CODB_OUT, Width::SizeOf(0), "输出地址", "Output address"),
    ] list? "二进制代码转换：OUT := 表[IN]" "Code conversion: OUT := table[IN]";
    Jmpb "JMPB" Function LabelJump [spec("L", OperandKind::Label, L_ONLY, Width::None, Access::Read, "跳转目标标号", "Target label")] list?
        "标号跳转：ACT=1 时跳到同一程序块内的 LBL" "Jump: while ACT = 1, go to the LBL in the same block";
    Lbl "LBL" Function LabelJump [spec("L", OperandKind::Label, L_ONLY, Width::None, Access::Read, "标号（每个工程内唯一）", "Label (unique in the project)")] list?
        "标号：JMPB 的目标，单独占一个网络" "Label: target of JMPB, stands alone";
    Call "CALL" Function LabelJump [spec("P", OperandKind::Subprogram, P_ONLY, Width::None, Access::Read, "子程序号", "Subprogram number")] list?
        "调用子程序：ACT=1 时执行子程序 P" "Call: runs subprogram P while ACT = 1";
    Callu "CALLU" Function LabelJump [spec("P", OperandKind::Subprogram, P_ONLY, Width::None, Access::Read, "子程序号", "Subprogram number")] list?
        "无条件调用子程序" "Unconditional subprogram call";
    Rotb "ROTB" Function RotateShift [
        digits("FMT", 1, "格式 abcd：d=编号从 1 起，c=就近旋转，b=目标前一位置，a=输出步数", "Format abcd: d = numbered from 1, c = shortest path, b = position before target, a = output steps"),
        unsigned_in("CNT", Width::SizeOf(2), CONST_MAX, "转子分度数：常数或地址", "Number of positions: constant or address"),
        SIZE_STD,
        only(unsigned_in("IN_W", Width::SizeOf(2), CONST_MAX, "当前位置地址", "Current position address").with_const(false), NO_TC_READ),
        only(unsigned_in("IN_D", Width::SizeOf(2), CONST_MAX, "目标位置地址", "Target position address").with_const(false), NO_TC_READ),
        byte_out("OUTE", NO_TC_WRITE, Width::SizeOf(2), "位置或步数输出地址", "Position or step count output"),
        bit_out("OUTO", BITS_WRITE, "旋转方向：0 正转，1 反转", "Direction: 0 forward, 1 reverse"),
    ] list? "二进制旋转控制：计算刀架等转子的旋转方向和步数" "Rotation control: direction and steps of a turret";
    Pari "PARI" Function Logic [
        digits("OE", 1, "0000 偶校验，0001 奇校验", "0000 even, 0001 odd parity"),
        rst("复位：为 1 时 OUT := 0", "Reset: 1 makes OUT := 0"),
        only(byte_in("IN", Width::Bytes(1), "校验数据（1 字节）", "Data to check (1 byte)"), RELAYS_AND_D),
        bit_out("OUT", BITS_WRITE, "校验出错输出", "Parity-error output"),
    ] list? "奇偶校验" "Parity check";
    Addb "ADDB" Function IntegerMath [ARITH_B] shared? "二进制加法：OUT := IN1 + IN2" "Binary add: OUT := IN1 + IN2";
    Addr "ADDR" Function RealMath [ARITH_R] shared? "实数加法" "Real add";
    Subb "SUBB" Function IntegerMath [ARITH_B] shared? "二进制减法：OUT := IN1 − IN2" "Binary subtract: OUT := IN1 − IN2";
    Subr "SUBR" Function RealMath [ARITH_R] shared? "实数减法" "Real subtract";
    Difu "DIFU" Function BitOutput [ONE_BIT_OUT] shared? "上升沿置位：ACT 由 0 变 1 的一个扫描周期 OUT=1" "Rising edge: OUT = 1 for the scan where ACT goes 0→1";
    Difd "DIFD" Function BitOutput [ONE_BIT_OUT] shared? "下降沿置位：ACT 由 1 变 0 的一个扫描周期 OUT=1" "Falling edge: OUT = 1 for the scan where ACT goes 1→0";
    Alt "ALT" Function BitOutput [
        spec("OUT", OperandKind::Bit, BITS_WRITE, Width::None, Access::ReadWrite, "交替输出的位地址", "Bit to toggle"),
    ] list? "交替输出：ACT 每次上升沿 OUT 取反" "Alternate: OUT toggles on each rising edge of ACT";
    Move "MOVE" Function DataTransfer [
        digits("H", 1, "高 4 位屏蔽（二进制）", "High 4 mask bits (binary)"),
        digits("L", 1, "低 4 位屏蔽（二进制）", "Low 4 mask bits (binary)"),
        only(byte_in("IN", Width::Bytes(1), "源字节地址", "Source byte address"), RELAYS_AND_D),
        byte_out("OUT", MOVE_OUT, Width::Bytes(1), "目标字节地址", "Destination byte address"),
    ] list? "逻辑乘：OUT := IN ∧ 屏蔽" "Logical product: OUT := IN ∧ mask";
    Wand "WAND" Function Logic [WORD_LOGIC] shared? "二进制字节与" "Bitwise and";
    Wor "WOR" Function Logic [WORD_LOGIC] shared? "二进制字节或" "Bitwise or";
    Wxor "WXOR" Function Logic [WORD_LOGIC] shared? "二进制字节异或" "Bitwise exclusive or";
    Winv "WINV" Function Logic [
        SIZE_STD,
        signed_in("IN", Width::SizeOf(0), "源数据：常数或地址", "Source: constant or address"),
        byte_out("OUT", BYTES_WRITE, Width::SizeOf(0), "结果输出地址", "Result address"),
    ] list? "二进制字节取反" "Bitwise not";
    Wshl "WSHL" Function RotateShift [SHIFT] shared? "二进制数据左移" "Shift left";
    Wshr "WSHR" Function RotateShift [SHIFT] shared? "二进制数据右移" "Shift right";
    Mulb "MULB" Function IntegerMath [MUL_DIV_B] shared? "二进制乘法：16 位 × 16 位 → 32 位" "Binary multiply: 16 × 16 → 32 bits";
    Mulr "MULR" Function RealMath [MUL_DIV_R] shared? "实数乘法" "Real multiply";
    Divb "DIVB" Function IntegerMath [MUL_DIV_B] shared? "16 位二进制除法：低 16 位商，高 16 位余数" "16-bit divide: quotient in the low, remainder in the high 16 bits";
    Divr "DIVR" Function RealMath [MUL_DIV_R] shared? "实数除法" "Real divide";
    Windr "WINDR" Function Cnc [
        spec("IN", OperandKind::Byte, D_ONLY, Width::Table, Access::ReadWrite, "窗口数据块首地址（D）", "First D address of the window block"),
        spec("ERR", OperandKind::BitOrByte, BYTES_WRITE, Width::Bytes(1), Access::Write, "完成输出：处理结束时为 1", "Completion output: 1 when processing has ended"),
    ] list? "读写 CNC 窗口数据" "CNC window read/write";
    Axctl "AXCTL" Function Cnc [
        with_range(unsigned_in("GRP", Width::Bytes(1), 4, "控制组 1–4（A–D）", "Control group 1–4 (A–D)"), 1, 4),
        unsigned_in("CMD", Width::Bytes(1), 255, "控制指令（见轴控指令表）", "Command (see the axis-command table)"),
        signed_in("DT1", Width::Bytes(2), "数据 1：速度", "Data 1: speed"),
        signed_in("DT2", Width::Bytes(4), "数据 2：距离、位置、时间或代码", "Data 2: distance, position, time or code"),
        rst("复位：为 1 时复位 PLC 轴", "Reset: 1 resets the PLC axis"),
        bit_out("FIN", BITS_WRITE, "完成输出", "Completion output"),
        err("错误输出", "Error output"),
    ] list? "PLC 轴控制" "PLC axis control";
    Xmov "XMOV" Function DataTransfer [
        konst("RW", 0, 1, "0 读表，1 写表", "0 read from the table, 1 write to it"),
        digits("FMT", 9, "格式 0nnx：nn 个数，x 元素宽度 1/2/4", "Format 0nnx: nn elements of x bytes (1/2/4)"),
        unsigned_in("DL", Width::Bytes(2), 16384, "表长度：常数或地址", "Table length: constant or address"),
        spec("DS", OperandKind::Byte, BYTES_READ, Width::Table, Access::WriteWhen { operand: 0, value: 1 }, "数据表首地址", "First address of the table"),
        spec("DD", OperandKind::Byte, BYTES_WRITE, Width::Table, Access::WriteWhen { operand: 0, value: 0 }, "输入/输出数据地址", "Data address read or written"),
        only(byte_in("DI", Width::Table, "索引地址（从 0 开始）", "Index address (from 0)"), BYTES_WRITE),
        rst("复位：为 1 时 ERR := 0，不传送", "Reset: 1 makes ERR := 0 and moves nothing"),
        err("错误输出：索引超出表长", "Error output: an index past the table"),
    ] list? "二进制索引数据传送" "Indexed table move";
    Dschb "DSCHB" Function DataTransfer [
        SIZE_STD,
        only(byte_in("IN1", Width::Table, "数据表首地址", "First address of the table"), NO_TC_READ),
        only(unsigned_in("INL", Width::Bytes(2), 65535, "表中数据个数：常数或地址", "Number of entries: constant or address"), NO_TC_READ),
        only(signed_in("DS", Width::SizeOf(0), "检索数据：常数或地址", "Value to search for: constant or address"), NO_TC_READ),
        byte_out("DI", NO_TC_WRITE, Width::SizeOf(0), "检索结果（序号）地址", "Result (index) address"),
        err("错误输出：未找到时为 1", "Error output: 1 when not found"),
    ] list? "数据检索：在表中查找数据" "Search a table for a value";
    Psgnl "PSGNL" Function Cnc [
        unsigned_in("AXIS", Width::Bytes(1), 255, "轴号：1、2…；第二通道 21、22…", "Axis number: 1, 2 …; second channel 21, 22 …"),
        spec("AREA", OperandKind::Byte, BYTES_READ, Width::Elements4(7), Access::Read, "7 个递增的区域边界（4 字节）", "7 ascending zone boundaries (4 bytes each)"),
        byte_out("OUT", BYTES_WRITE, Width::Bytes(1), "区域输出字节", "Zone output byte"),
        err("错误输出", "Error output"),
    ] list? "位置信号输出：机床坐标所在的区域" "Position signal: the zone of the machine coordinate";
    Psgn2 "PSGN2" Function Cnc [
        unsigned_in("AXIS", Width::Bytes(1), 255, "轴号", "Axis number"),
        signed_in("MIN", Width::Bytes(4), "区域下限（非负）", "Lower bound (not negative)"),
        signed_in("MAX", Width::Bytes(4), "区域上限", "Upper bound"),
        bit_out("OUT", BITS_WRITE, "在区域内时为 1", "1 inside the zone"),
        err("错误输出", "Error output"),
    ] list? "位置信号输出 2：机床坐标是否在区域内" "Position signal 2: is the machine coordinate inside the zone";
    Zcp "ZCP" Function Compare [
        SIZE_STD,
        only(signed_in("IN1", Width::SizeOf(0), "区域下限", "Lower bound"), NO_PRESETS_READ),
        only(signed_in("IN2", Width::SizeOf(0), "区域上限", "Upper bound"), NO_PRESETS_READ),
        only(signed_in("IN3", Width::SizeOf(0), "比较数据", "Value to compare"), NO_PRESETS_READ),
        bits3_out(RELAYS_WRITE, "结果：OUT=低于下限，OUT+1=区域内，OUT+2=高于上限", "Result: OUT = below, OUT+1 = inside, OUT+2 = above"),
    ] list? "区域比较" "Zone compare";
    Sin "SIN" Function RealMath [TRIG] shared? "正弦" "Sine";
    Cos "COS" Function RealMath [TRIG] shared? "余弦" "Cosine";
    Tan "TAN" Function RealMath [TRIG] shared? "正切" "Tangent";
    Sqrt "SQRT" Function RealMath [
        real_in("IN", "输入：实数常数或 D 地址", "Input: real constant or D address"),
        real_out("实数结果（D 地址）", "Real result (D address)"),
        RST_ERR,
        REAL_ERR_LATCHED,
    ] list? "求平方根" "Square root";
    Dtr "DTR" Function RealMath [
        spec("IN", OperandKind::ConstOrByte, D_ONLY, Width::Bytes(4), Access::Read, "整数：常数或 D 地址", "Integer: constant or D address"),
        real_out("实数结果（D 地址）", "Real result (D address)"),
        RST_ERR,
        REAL_ERR_LATCHED,
    ] list? "整数转换为实数" "Integer to real";
    Round "ROUND" Function RealMath [
        real_in("IN", "实数：常数或 D 地址", "Real: constant or D address"),
        real_out("整数结果（D 地址）", "Integer result (D address)"),
        RST_ERR,
        REAL_ERR_LATCHED,
    ] list? "实数四舍五入转换为整数" "Round a real to an integer";
}

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

impl Op {
    /// The catalogue entry of this opcode.
    pub fn spec(self) -> &'static InstrSpec {
        &CATALOG[self as usize]
    }

    /// The mnemonic.
    pub fn name(self) -> &'static str {
        self.spec().name
    }

    /// Looks up a mnemonic (any case). `SP` and `SUB` are directives, not instructions.
    pub fn from_name(name: &str) -> Option<Op> {
        CATALOG
            .iter()
            .find(|s| s.name.eq_ignore_ascii_case(name))
            .map(|s| s.op)
    }
}

/// Checks a digit-group operand (FMT, OE, H/L) of `op` beyond its digits' range, returning
/// what is wrong in words.
pub fn check_digit_group(op: Op, operand: &str, value: i64) -> Result<(), String> {
    let ok = match (op, operand) {
        (Op::Ctrc, _) => matches!(value, 0 | 1 | 10 | 11),
        (Op::Pari, _) => matches!(value, 0 | 1),
        (Op::Xmov, _) => value <= 999 && matches!(value % 10, 1 | 2 | 4),
        _ => true,
    };
    if ok {
        Ok(())
    } else {
        Err(match op {
            Op::Ctrc => {
                "CTRC's FMT is 0000, 0001, 0010 or 0011 (00ab: a = initial value, b = down)".into()
            }
            Op::Pari => "PARI's OE is 0000 (even) or 0001 (odd)".into(),
            _ => "XMOV's FMT is 0nnx: nn elements (00–99) of x = 1, 2 or 4 bytes".into(),
        })
    }
}

/// The XMOV element width x and count nn from its FMT `0nnx` (nn of 0 or 1 is one element).
pub fn xmov_format(fmt: i64) -> (u8, u32) {
    let x = (fmt % 10) as u8;
    let nn = ((fmt / 10) % 100).max(1) as u32;
    (x, nn)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_catalogue_has_13_basic_and_48_function_instructions() {
        let basic = CATALOG
            .iter()
            .filter(|s| s.class != InstrClass::Function)
            .count();
        let function = CATALOG
            .iter()
            .filter(|s| s.class == InstrClass::Function)
            .count();
        assert_eq!((basic, function), (13, 48));
    }

    #[test]
    fn each_entry_sits_at_its_opcode_and_names_are_unique() {
        for (i, s) in CATALOG.iter().enumerate() {
            assert_eq!(s.op as usize, i, "{}", s.name);
            assert_eq!(Op::from_name(&s.name.to_lowercase()), Some(s.op));
            assert!(!s.help_zh.is_empty() && !s.help_en.is_empty(), "{}", s.name);
            for o in s.operands {
                assert!(
                    !o.help_zh.is_empty() && !o.help_en.is_empty(),
                    "{} {}",
                    s.name,
                    o.name
                );
                assert!(o.min <= o.max);
                if let Width::SizeOf(i) = o.width {
                    assert_eq!(s.operands[i as usize].kind, OperandKind::Size, "{}", s.name);
                }
            }
        }
    }

    #[test]
    fn step_cost_follows_the_operand_count() {
        assert_eq!(Op::Ld.spec().steps(1), 1);
        assert_eq!(Op::Tmrb.spec().steps(3), 4);
        assert_eq!(Op::Codb.spec().steps(8), 9);
    }
}
