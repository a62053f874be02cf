//! Operands as the user writes them: addresses, integer or real constants, symbol names.

use crate::address::{Address, AddressError};
use serde::{Deserialize, Serialize};
use std::fmt;
use std::hash::{Hash, Hasher};
use thiserror::Error;

/// One operand of a contact, coil or function box.
///
/// Symbols stay symbols in the model (they may be defined after use); the compiler resolves
/// them against the symbol table. Saved as its text (`"X0002.1"`, `"-5"`, `"1.5"`), which
/// parses back to the same operand.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(into = "String", try_from = "String")]
pub enum Operand {
    /// An address such as `X0002.1` or `D0010`.
    Addr(Address),
    /// An integer constant (digit groups such as FMT `0111` are kept as the integer 111).
    Int(i64),
    /// A real constant (binary32, as the PLC keeps it).
    Real(f32),
    /// A symbol name from the symbol table.
    Symbol(String),
}

/// Why operand text was refused.
#[derive(Clone, Debug, PartialEq, Eq, Hash, Error)]
pub enum OperandError {
    /// Nothing was written.
    #[error("an operand is missing")]
    Empty,
    /// A malformed number.
    #[error("`{0}` is not a number (write 12, -5, 0x1F or 1.5)")]
    Number(String),
    /// A malformed address.
    #[error(transparent)]
    Address(#[from] AddressError),
    /// Neither address, number nor symbol name.
    #[error("`{0}` is neither an address, a constant nor a symbol name")]
    Unrecognised(String),
}

/// Whether `name` is a well-formed symbol name: letters, digits, `_` and Chinese characters,
/// not starting with a digit, at most 32 characters.
pub fn is_symbol_name(name: &str) -> bool {
    let mut chars = name.chars();
    let Some(first) = chars.next() else {
        return false;
    };
    let ok = |c: char| c == '_' || c.is_alphanumeric();
    !first.is_ascii_digit() && ok(first) && chars.all(ok) && name.chars().count() <= 32
}

impl Operand {
    /// Parses operand text: a number, an address, or a symbol name.
    pub fn parse(text: &str) -> Result<Operand, OperandError> {
        let s = text.trim();
        let first = s.chars().next().ok_or(OperandError::Empty)?;
        if first.is_ascii_digit() || first == '-' || first == '+' {
            return parse_number(s);
        }
        match Address::parse(s) {
            Ok(a) => Ok(Operand::Addr(a)),
            Err(AddressError::Syntax(_) | AddressError::UnknownArea(..)) if is_symbol_name(s) => {
                Ok(Operand::Symbol(s.to_string()))
            }
            Err(AddressError::Syntax(_) | AddressError::UnknownArea(..)) => {
                Err(OperandError::Unrecognised(s.to_string()))
            }
            Err(e) => Err(e.into()),
        }
    }

    /// The address, if the operand is one.
    pub fn address(&self) -> Option<Address> {
        match self {
            Operand::Addr(a) => Some(*a),
            _ => None,
        }
    }
}

// A real operand is always finite (`parse` refuses the others), so equality is an
// equivalence; +0.0 and -0.0 are equal and hash alike.
impl Eq for Operand {}

impl Hash for Operand {
    fn hash<H: Hasher>(&self, state: &mut H) {
        std::mem::discriminant(self).hash(state);
        match self {
            Operand::Addr(a) => a.hash(state),
            Operand::Int(v) => v.hash(state),
            Operand::Real(v) => (if *v == 0.0 { 0 } else { v.to_bits() }).hash(state),
            Operand::Symbol(s) => s.hash(state),
        }
    }
}

impl From<Operand> for String {
    fn from(o: Operand) -> String {
        o.to_string()
    }
}

impl TryFrom<String> for Operand {
    type Error = OperandError;
    fn try_from(s: String) -> Result<Operand, OperandError> {
        Operand::parse(&s)
    }
}

fn parse_number(s: &str) -> Result<Operand, OperandError> {
    let bad = || OperandError::Number(s.to_string());
    let (neg, digits) = match s.as_bytes()[0] {
        b'-' => (true, &s[1..]),
        b'+' => (false, &s[1..]),
        _ => (false, s),
    };
    if digits.is_empty() {
        return Err(bad());
    }
    if let Some(hex) = digits
        .strip_prefix("0x")
        .or_else(|| digits.strip_prefix("0X"))
    {
        let v = i64::from_str_radix(hex, 16).map_err(|_| bad())?;
        return Ok(Operand::Int(if neg { -v } else { v }));
    }
    if digits.bytes().all(|b| b.is_ascii_digit()) {
        // Saturate absurdly long numbers; the compiler reports the range.
        let v = digits.parse::<i64>().unwrap_or(i64::MAX / 2);
        return Ok(Operand::Int(if neg { -v } else { v }));
    }
    let looks_real = digits
        .bytes()
        .all(|b| b.is_ascii_digit() || matches!(b, b'.' | b'e' | b'E' | b'-' | b'+'))
        && digits.as_bytes()[0].is_ascii_digit();
    if looks_real {
        let v: f32 = s.parse().map_err(|_| bad())?;
        if v.is_finite() {
            return Ok(Operand::Real(v));
        }
    }
    Err(bad())
}

impl fmt::Display for Operand {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Operand::Addr(a) => a.fmt(f),
            Operand::Int(v) => write!(f, "{v}"),
            Operand::Real(v) => {
                let text = format!("{v}");
                if text.contains('.') {
                    f.write_str(&text)
                } else {
                    write!(f, "{text}.0")
                }
            }
            Operand::Symbol(s) => f.write_str(s),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn operands_parse_by_their_look() {
        assert_eq!(Operand::parse("x2.1").unwrap().to_string(), "X0002.1");
        assert_eq!(Operand::parse("-56").unwrap(), Operand::Int(-56));
        assert_eq!(Operand::parse("0x1F").unwrap(), Operand::Int(31));
        assert_eq!(Operand::parse("1.5").unwrap(), Operand::Real(1.5));
        assert_eq!(Operand::parse("1e3").unwrap(), Operand::Real(1000.0));
        assert_eq!(Operand::Real(3.0).to_string(), "3.0");
        assert_eq!(
            Operand::parse("主轴_CW").unwrap(),
            Operand::Symbol("主轴_CW".into())
        );
        assert_eq!(
            Operand::parse("QSTOP").unwrap(),
            Operand::Symbol("QSTOP".into())
        );
        assert!(Operand::parse("R1.9").is_err());
        assert!(Operand::parse("D1.3").is_err());
        assert!(Operand::parse("1.2.3").is_err());
        assert!(Operand::parse("a-b").is_err());
        assert!(Operand::parse("").is_err());
    }
}
