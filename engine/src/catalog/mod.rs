//! The instruction catalogue: the one place where an instruction is described.
//!
//! Every instruction's name, operands (in IL order), operand kinds, allowed areas, widths,
//! step cost and help text (zh/en) live in [`CATALOG`]. The compiler's checks, IL export and
//! import, the editor's parameter dialog and the VM's dispatch all read from here; there is no
//! second list of instructions anywhere in the code base.

mod areas;
mod operands;
mod reference;
mod table;
#[cfg(test)]
mod tests;

pub use areas::{BITS_READ, BITS_WRITE, BYTES_READ, BYTES_WRITE};
pub use operands::CODB_TABLE_ENTRY;
pub use reference::reference_markdown;
pub use table::{CATALOG, FnOp, Op};

use crate::address::{Area, AreaSet};
use thiserror::Error;

/// Largest magnitude of a constant (§1.2: D holds −2147483647…2147483647).
pub const CONST_MAX: i64 = 2_147_483_647;

/// What an operand accepts.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
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
    /// What the operand stands for beyond its kind, where other code needs to find it.
    pub role: Role,
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

/// What an operand stands for, for the code that looks for it rather than for its position:
/// the compiler's shared-timer, shared-output and preset warnings, the instruction reference.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Role {
    /// Nothing beyond its kind.
    Plain,
    /// The timer the instruction runs (TMRB's and TMRC's T).
    TimerNumber,
    /// The counter the instruction runs (CTRC's C).
    CounterNumber,
    /// The preset a timer or counter reaches (PT, N).
    Preset,
    /// An output the instruction writes at every execution, whatever ACT, as a coil does
    /// (TMRB's, DECB's, PARI's, DIFU's and DIFD's OUT, WINDR's ERR): a second instruction
    /// writing the same address loses its value to this one every scan (W008).
    Driven,
}

impl Role {
    /// The area of the memory a timer or counter number names.
    pub fn memory_area(self) -> Option<Area> {
        match self {
            Role::TimerNumber => Some(Area::T),
            Role::CounterNumber => Some(Area::C),
            Role::Plain | Role::Preset | Role::Driven => None,
        }
    }
}

/// Where the table of a variadic instruction is (CODB, manual §1.4.11): its entries follow the
/// fixed operands, and a constant operand says how many there are.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct TableShape {
    /// Index of the first entry (the number of fixed operands).
    pub first: usize,
    /// Index of the constant operand that gives the number of entries; its range is the
    /// range of the count.
    pub count_from: usize,
    /// What each entry is.
    pub entry: &'static OperandSpec,
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
    /// Operands in IL order (CODB's table entries follow its fixed operands, see
    /// [`InstrSpec::table`]).
    pub operands: &'static [OperandSpec],
    /// The table of constants after the fixed operands, for the one variadic instruction.
    pub table: Option<TableShape>,
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

    /// The index of the first table entry, for the one variadic instruction.
    pub fn table_start(&self) -> Option<usize> {
        self.table.map(|t| t.first)
    }

    /// The number of table entries a count operand of `value` asks for, when it is in the
    /// count operand's range; `None` without a table.
    pub fn table_len(&self, value: i64) -> Option<usize> {
        let t = self.table?;
        let count = &self.operands[t.count_from];
        (count.min..=count.max)
            .contains(&value)
            .then_some(value as usize)
    }

    /// The operand spec for operand `i`, including CODB's table entries.
    pub fn operand(&self, i: usize) -> Option<&'static OperandSpec> {
        match self.table {
            Some(t) if i >= t.first => Some(t.entry),
            _ => self.operands.get(i),
        }
    }

    /// The index of the first fixed operand with `role`.
    pub fn operand_with(&self, role: Role) -> Option<usize> {
        self.operands.iter().position(|o| o.role == role)
    }

    /// The operand that names the timer or counter this instruction runs, and its area (T or
    /// C): two instructions on one number disturb each other.
    pub fn memory_operand(&self) -> Option<(usize, Area)> {
        self.operands
            .iter()
            .enumerate()
            .find_map(|(i, o)| o.role.memory_area().map(|area| (i, area)))
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

/// Checks a digit-group operand (FMT, OE, H/L) of `op` beyond its digits' range: which
/// rule the value breaks, if any. Each of these instructions has one digit group, so the
/// instruction names the rule.
pub fn check_digit_group(op: Op, value: i64) -> Result<(), DigitGroupError> {
    match op {
        Op::Ctrc if !matches!(value, 0 | 1 | 10 | 11) => Err(DigitGroupError::Ctrc { value }),
        Op::Pari if !matches!(value, 0 | 1) => Err(DigitGroupError::Pari { value }),
        Op::Xmov if value > 999 || !matches!(value % 10, 1 | 2 | 4) => {
            Err(DigitGroupError::Xmov { value })
        }
        _ => Ok(()),
    }
}

/// Control digits an instruction does not define ([`check_digit_group`]): the rule of the
/// instruction's digit group. `Display` gives it in English; `ladder_text::errors` words it
/// in either language for the diagnostics and the editor.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Error)]
pub enum DigitGroupError {
    /// CTRC's FMT other than 0000, 0001, 0010, 0011.
    #[error("CTRC's FMT is 0000, 0001, 0010 or 0011 (00ab: a = initial value, b = down)")]
    Ctrc {
        /// The value written.
        value: i64,
    },
    /// PARI's OE other than 0000, 0001.
    #[error("PARI's OE is 0000 (even) or 0001 (odd)")]
    Pari {
        /// The value written.
        value: i64,
    },
    /// XMOV's FMT not of the form 0nnx with x = 1, 2 or 4.
    #[error("XMOV's FMT is 0nnx: nn elements (00–99) of x = 1, 2 or 4 bytes")]
    Xmov {
        /// The value written.
        value: i64,
    },
}

/// The XMOV element width x and count nn from its FMT `0nnx` (nn of 0 or 1 is one element).
pub fn xmov_format(fmt: i64) -> (u8, u32) {
    let x = (fmt % 10) as u8;
    let nn = ((fmt / 10) % 100).max(1) as u32;
    (x, nn)
}
