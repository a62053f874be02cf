//! Whether an operand may stand where it is written, and if not, why: one function for the
//! compiler's check, the editor's function dialog, replace and the operand colours. The
//! refusal is structured ([`OperandRefusal`]), so the compiler keeps it in a diagnostic (with
//! its code) and the editor and `ladder-text` word it in the user's language.

use super::diag::Code;
use crate::address::{Address, AddressError, Area, AreaSet};
use crate::catalog::{
    Access, CONST_MAX, DigitGroupError, Op, OperandKind, OperandSpec, Width, check_digit_group,
    xmov_format,
};
use crate::model::Operand;
use crate::profile::Profile;
use std::fmt;

/// Why an operand is refused where it stands.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub enum OperandRefusal {
    /// The instruction takes fewer operands.
    TooMany,
    /// A constant, real or address where the operand's kind takes none of that kind.
    Kind {
        /// What the operand takes.
        expected: OperandKind,
        /// What is written.
        found: Operand,
    },
    /// A byte address where a bit address is needed.
    WantsBit(Address),
    /// A bit address where a byte address is needed.
    WantsByte(Address),
    /// A size other than 1, 2 or 4.
    Size(i64),
    /// A group of four binary or decimal digits written with other digits.
    Digits {
        /// The value written.
        value: i64,
        /// Binary digits (0 and 1) rather than decimal ones.
        binary: bool,
    },
    /// Control digits the instruction does not define (CTRC's FMT, PARI's OE, XMOV's FMT).
    DigitGroup(DigitGroupError),
    /// A constant outside the operand's range.
    ConstRange {
        /// The value written.
        value: i64,
        /// The smallest allowed.
        min: i64,
        /// The largest allowed.
        max: i64,
    },
    /// A constant beyond what a constant can hold (±2147483647).
    ConstTooBig(i64),
    /// An input (X, F) written by the instruction.
    ReadOnly {
        /// The address.
        address: Address,
        /// The areas the operand takes (the editor may say this instead).
        allowed: AreaSet,
    },
    /// An area the operand does not take.
    Area {
        /// The address.
        address: Address,
        /// The areas the operand takes.
        allowed: AreaSet,
    },
    /// Beyond the profile's range (the address, or the elements the instruction reaches).
    Range(AddressError),
}

impl OperandRefusal {
    /// The compiler's diagnostic code for this refusal.
    pub fn code(&self) -> Code {
        match self {
            OperandRefusal::TooMany => Code::L011OperandCount,
            OperandRefusal::Kind { .. }
            | OperandRefusal::WantsBit(_)
            | OperandRefusal::WantsByte(_) => Code::L021OperandKind,
            OperandRefusal::Size(_)
            | OperandRefusal::Digits { .. }
            | OperandRefusal::DigitGroup(_)
            | OperandRefusal::ConstRange { .. }
            | OperandRefusal::ConstTooBig(_) => Code::L024ConstRange,
            OperandRefusal::ReadOnly { .. } => Code::L025ReadOnly,
            OperandRefusal::Area { .. } => Code::L022Area,
            OperandRefusal::Range(_) => Code::L023AddressRange,
        }
    }
}

/// What an operand of this kind looks like, in words.
pub fn expected_text(kind: OperandKind) -> &'static str {
    match kind {
        OperandKind::Size => "a size 1, 2 or 4",
        OperandKind::Const => "a constant",
        OperandKind::Digits { .. } => "a 4-digit group such as 0000",
        OperandKind::Bit => "a bit address such as R0010.0",
        OperandKind::Byte => "an address such as R0010 or D0004",
        OperandKind::ConstOrByte => "an integer constant or an address",
        OperandKind::RealOrD => "a real constant or a D address",
        OperandKind::BitOrByte => "a bit or byte address",
        OperandKind::Label => "a label such as L0001",
        OperandKind::Subprogram => "a subprogram such as P0001",
        OperandKind::Timer => "a timer such as T0001",
        OperandKind::Counter => "a counter such as C0001",
    }
}

impl fmt::Display for OperandRefusal {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            OperandRefusal::TooMany => f.write_str("the instruction takes fewer operands"),
            OperandRefusal::Kind { expected, found } => {
                write!(f, "expects {}, found `{found}`", expected_text(*expected))
            }
            OperandRefusal::WantsBit(a) => {
                write!(f, "expects a bit address such as R0010.0, found `{a}`")
            }
            OperandRefusal::WantsByte(a) => write!(
                f,
                "expects a byte address without a bit, such as R0010, found `{a}`"
            ),
            OperandRefusal::Size(v) => write!(f, "the size is 1, 2 or 4, not {v}"),
            OperandRefusal::Digits { value, binary } => write!(
                f,
                "write 4 {} digits, not `{value}`",
                if *binary { "binary" } else { "decimal" }
            ),
            OperandRefusal::DigitGroup(e) => write!(f, "{e}"),
            OperandRefusal::ConstRange { value, min, max } => {
                write!(f, "{value} is out of range ({min}–{max})")
            }
            OperandRefusal::ConstTooBig(v) => {
                write!(f, "{v} is out of range (−2147483647–2147483647)")
            }
            OperandRefusal::ReadOnly { address, .. } => write!(
                f,
                "{address} cannot be written: X and F are inputs, read-only to the program"
            ),
            OperandRefusal::Area { address, allowed } => {
                write!(
                    f,
                    "{address} is not allowed here; use {}",
                    allowed.describe()
                )
            }
            OperandRefusal::Range(e) => write!(f, "{e}"),
        }
    }
}

/// Whether operand `i` of an instruction is acceptable as written (kind, area, range), for
/// editors that must not produce an invalid operand (replace, the operand colours).
pub fn operand_ok(op: Op, operands: &[Operand], i: usize, profile: &Profile) -> bool {
    operand_error(op, operands, i, profile).is_ok()
}

fn const_value(o: Option<&Operand>) -> Option<i64> {
    match o {
        Some(Operand::Int(v)) => Some(*v),
        _ => None,
    }
}

/// Checks operand `i` of `op` with the operands written (symbols already resolved to
/// addresses; a symbol left is accepted here, the compiler reports it as undefined).
pub fn operand_error(
    op: Op,
    operands: &[Operand],
    i: usize,
    profile: &Profile,
) -> Result<(), OperandRefusal> {
    let Some(spec) = op.spec().operand(i) else {
        return Err(OperandRefusal::TooMany);
    };
    let Some(operand) = operands.get(i) else {
        return Err(OperandRefusal::TooMany);
    };
    let kind_error = || {
        Err(OperandRefusal::Kind {
            expected: spec.kind,
            found: operand.clone(),
        })
    };
    match operand {
        Operand::Int(v) => {
            if !spec.accepts_const() {
                return kind_error();
            }
            let v = *v;
            match spec.kind {
                OperandKind::Size if !matches!(v, 1 | 2 | 4) => Err(OperandRefusal::Size(v)),
                OperandKind::Digits { max_digit } => {
                    let digits_ok = (0..=9999).contains(&v)
                        && v.to_string().bytes().all(|d| d - b'0' <= max_digit);
                    if !digits_ok {
                        return Err(OperandRefusal::Digits {
                            value: v,
                            binary: max_digit == 1,
                        });
                    }
                    check_digit_group(op, v).map_err(OperandRefusal::DigitGroup)
                }
                _ if v < spec.min || v > spec.max => Err(OperandRefusal::ConstRange {
                    value: v,
                    min: spec.min,
                    max: spec.max,
                }),
                _ if v.abs() > CONST_MAX => Err(OperandRefusal::ConstTooBig(v)),
                _ => Ok(()),
            }
        }
        Operand::Real(_) if spec.kind == OperandKind::RealOrD => Ok(()),
        Operand::Real(_) => kind_error(),
        Operand::Symbol(_) => Ok(()), // resolved before, or reported as undefined
        Operand::Addr(a) => address_error(op, operands, spec, *a, profile),
    }
}

fn address_error(
    op: Op,
    operands: &[Operand],
    spec: &OperandSpec,
    a: Address,
    profile: &Profile,
) -> Result<(), OperandRefusal> {
    let wants_bit = match spec.kind {
        OperandKind::Bit => Some(true),
        OperandKind::BitOrByte => None,
        OperandKind::Size | OperandKind::Const | OperandKind::Digits { .. } => {
            return Err(OperandRefusal::Kind {
                expected: spec.kind,
                found: Operand::Addr(a),
            });
        }
        _ => Some(false),
    };
    match (wants_bit, a.bit.is_some()) {
        (Some(true), false) => return Err(OperandRefusal::WantsBit(a)),
        (Some(false), true) => return Err(OperandRefusal::WantsByte(a)),
        _ => {}
    }
    let writes = match spec.access {
        Access::Read => false,
        Access::Write | Access::ReadWrite => true,
        Access::WriteWhen { operand, value } => {
            const_value(operands.get(operand as usize)) == Some(i64::from(value))
        }
    };
    if writes && matches!(a.area, Area::X | Area::F) {
        return Err(OperandRefusal::ReadOnly {
            address: a,
            allowed: spec.areas,
        });
    }
    if !spec.areas.contains(a.area) {
        return Err(OperandRefusal::Area {
            address: a,
            allowed: spec.areas,
        });
    }
    let c = |i: usize| const_value(operands.get(i));
    // Bytes of one access of this operand, if known from constants.
    let access_bytes = || match spec.width {
        Width::Bytes(n) => Some(u32::from(n)),
        Width::SizeOf(i) => c(i as usize)
            .filter(|v| matches!(v, 1 | 2 | 4))
            .map(|v| v as u32),
        _ => None,
    };
    // (element bytes, element count) of a table operand, if known from constants.
    let table_shape = || match (op, spec.name) {
        (Op::Xmov, "DS") => {
            let (x, _) = xmov_format(c(1)?);
            Some((u32::from(x), c(2)?.max(1) as u32))
        }
        (Op::Xmov, "DD" | "DI") => {
            let (x, nn) = xmov_format(c(1)?);
            Some((u32::from(x), nn))
        }
        (Op::Dschb, "IN1") => Some((c(0)? as u32, c(2)?.max(1) as u32)),
        (Op::Windr, "IN") => Some((4, 6)),
        _ => None,
    };
    let count = match spec.width {
        Width::Bits3 => {
            if a.bit.is_some_and(|b| b > 5) {
                2
            } else {
                1
            }
        }
        Width::Elements4(k) => covered(a, 4, u32::from(k)),
        Width::Table => table_shape()
            .map(|(bytes, n)| covered(a, bytes, n))
            .unwrap_or(1),
        _ => access_bytes()
            .map(|bytes| covered(a, bytes, 1))
            .unwrap_or(1),
    };
    a.check_span(profile, count).map_err(OperandRefusal::Range)
}

/// Addresses covered from `a` by `count` elements of `bytes` (element rule, docs/plc.md).
fn covered(a: Address, bytes: u32, count: u32) -> u32 {
    if a.area.element_bytes() == 1 {
        bytes * count
    } else {
        count
    }
}
