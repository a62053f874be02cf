//! PLC addresses: areas, parsing of every input spelling, the canonical text, range checks.
//!
//! Input is case-insensitive with optional zero padding (`x1.3`, `X0001.3`); output is always
//! canonical (`X0001.3`), so find/replace can compare addresses instead of strings.

pub use crate::area::{Area, AreaSet};
use crate::profile::Profile;
use serde::{Deserialize, Serialize};
use std::fmt;
use std::str::FromStr;
use thiserror::Error;

/// An address: area, number, and a bit for bit addresses. Saved as its canonical text.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize)]
#[serde(into = "String", try_from = "String")]
pub struct Address {
    /// The area.
    pub area: Area,
    /// The address number (range-checked against a profile, not at parse time).
    pub number: u16,
    /// Bit 0–7 for bit addresses.
    pub bit: Option<u8>,
}

/// Why an address text was refused.
#[derive(Clone, Debug, PartialEq, Eq, Hash, Error)]
pub enum AddressError {
    /// Not of the form letters, digits, optional `.bit`.
    #[error("`{0}` is not an address (write e.g. X0002.1, R100, D4, DT0004)")]
    Syntax(String),
    /// The letters name no area.
    #[error("`{0}` has no address area `{1}` (areas: X Y F G R A K T C DT DC D L P)")]
    UnknownArea(String, String),
    /// The bit is not 0–7.
    #[error("`{0}`: the bit must be 0–7")]
    Bit(String),
    /// A bit address on an area without bits.
    #[error("`{0}`: {1} addresses have no bits (bits exist on X Y F G R A K)")]
    NoBits(String, Area),
    /// The number is outside the profile's range.
    #[error("{text} is out of range ({area}{lo}–{area}{hi})")]
    Range {
        /// The address as canonical text.
        text: String,
        /// Its area.
        area: Area,
        /// First valid number.
        lo: u16,
        /// Last valid number.
        hi: u16,
    },
}

impl Address {
    /// A byte (or word) address.
    pub const fn byte(area: Area, number: u16) -> Address {
        Address {
            area,
            number,
            bit: None,
        }
    }

    /// A bit address.
    pub const fn bit(area: Area, number: u16, bit: u8) -> Address {
        Address {
            area,
            number,
            bit: Some(bit),
        }
    }

    /// Parses any spelling of an address, without a range check.
    pub fn parse(text: &str) -> Result<Address, AddressError> {
        let s = text.trim();
        let letters_end = s
            .find(|c: char| !c.is_ascii_alphabetic())
            .unwrap_or(s.len());
        let (letters, rest) = s.split_at(letters_end);
        if letters.is_empty() || rest.is_empty() {
            return Err(AddressError::Syntax(s.to_string()));
        }
        let Some(area) = Area::from_letters(letters) else {
            return Err(AddressError::UnknownArea(
                s.to_string(),
                letters.to_ascii_uppercase(),
            ));
        };
        let (num_text, bit_text) = match rest.split_once('.') {
            Some((n, b)) => (n, Some(b)),
            None => (rest, None),
        };
        if num_text.is_empty() || !num_text.bytes().all(|b| b.is_ascii_digit()) {
            return Err(AddressError::Syntax(s.to_string()));
        }
        // Leading zeros are padding; more than five significant digits cannot be a number of
        // any area, so it is reported as a range error on a saturated number.
        let significant = num_text.trim_start_matches('0');
        let number = if significant.len() > 5 {
            u32::MAX
        } else {
            significant.parse::<u32>().unwrap_or(0)
        };
        let bit = match bit_text {
            None => None,
            Some(b) => {
                if b.len() != 1 || !b.as_bytes()[0].is_ascii_digit() {
                    return Err(if b.bytes().all(|c| c.is_ascii_digit()) && !b.is_empty() {
                        AddressError::Bit(s.to_string())
                    } else {
                        AddressError::Syntax(s.to_string())
                    });
                }
                let v = b.as_bytes()[0] - b'0';
                if v > 7 {
                    return Err(AddressError::Bit(s.to_string()));
                }
                Some(v)
            }
        };
        if bit.is_some() && !area.has_bits() {
            return Err(AddressError::NoBits(s.to_string(), area));
        }
        if number > u32::from(u16::MAX) {
            return Err(AddressError::Range {
                text: s.to_ascii_uppercase(),
                area,
                lo: 0,
                hi: 0,
            });
        }
        Ok(Address {
            area,
            number: number as u16,
            bit,
        })
    }

    /// Parses and range-checks against a profile.
    pub fn parse_in(text: &str, profile: &Profile) -> Result<Address, AddressError> {
        let address = Address::parse(text).map_err(|e| match e {
            AddressError::Range { text, area, .. } => {
                let (lo, hi) = profile.range(area);
                AddressError::Range { text, area, lo, hi }
            }
            other => other,
        })?;
        address.check_range(profile)?;
        Ok(address)
    }

    /// Checks the number against the profile's range for its area.
    pub fn check_range(&self, profile: &Profile) -> Result<(), AddressError> {
        self.check_span(profile, 1)
    }

    /// Checks that `count` consecutive addresses starting here exist in the profile.
    pub fn check_span(&self, profile: &Profile, count: u32) -> Result<(), AddressError> {
        let (lo, hi) = profile.range(self.area);
        let first = u32::from(self.number);
        let last = first + count.max(1) - 1;
        if first < u32::from(lo) || last > u32::from(hi) {
            let text = if count > 1 && first <= u32::from(hi) {
                format!(
                    "{}–{}",
                    self,
                    Address::byte(self.area, last.min(u32::from(u16::MAX)) as u16)
                )
            } else {
                self.to_string()
            };
            return Err(AddressError::Range {
                text,
                area: self.area,
                lo,
                hi,
            });
        }
        Ok(())
    }

    /// The same address without its bit.
    pub fn byte_address(&self) -> Address {
        Address::byte(self.area, self.number)
    }

    /// The bit `k` bits after this bit address (X0000.7 + 1 is X0001.0); `None` for a byte
    /// address or past the last number.
    pub fn offset_bits(&self, k: u32) -> Option<Address> {
        let at = u32::from(self.number) * 8 + u32::from(self.bit?) + k;
        Some(Address::bit(
            self.area,
            u16::try_from(at / 8).ok()?,
            (at % 8) as u8,
        ))
    }
}

impl fmt::Display for Address {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}{:04}", self.area.letters(), self.number)?;
        if let Some(b) = self.bit {
            write!(f, ".{b}")?;
        }
        Ok(())
    }
}

impl From<Address> for String {
    fn from(a: Address) -> String {
        a.to_string()
    }
}

impl TryFrom<String> for Address {
    type Error = AddressError;
    fn try_from(s: String) -> Result<Address, AddressError> {
        Address::parse(&s)
    }
}

impl FromStr for Address {
    type Err = AddressError;
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        Address::parse(s)
    }
}

/// An address with a byte count, as scripts write it (`D0010:2`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Target {
    /// The address.
    pub address: Address,
    /// Bytes: given with `:N`, else the area's natural width (1 for bits).
    pub bytes: u32,
    /// Whether `:N` was written.
    pub explicit: bool,
}

impl Target {
    /// An address as a whole: a bit, a byte, or a 4-byte value, at its own width.
    pub fn whole(address: Address) -> Target {
        Target {
            address,
            bytes: u32::from(address.area.element_bytes()).max(1),
            explicit: false,
        }
    }

    /// The address as printed in messages: canonical, with `:N` when it was given.
    pub fn text(&self) -> String {
        if self.explicit {
            format!("{}:{}", self.address, self.bytes)
        } else {
            self.address.to_string()
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::profile::{Profile, ProfileId};

    fn p() -> &'static Profile {
        Profile::get(ProfileId::Gsk988ta)
    }

    #[test]
    fn every_spelling_gives_the_canonical_text() {
        for (input, canonical) in [
            ("x1.3", "X0001.3"),
            ("X0001.3", "X0001.3"),
            ("  r100 ", "R0100"),
            ("dt4", "DT0004"),
            ("Dc1", "DC0001"),
            ("d0", "D0000"),
            ("t0", "T0000"),
            ("C0001", "C0001"),
            ("l1", "L0001"),
            ("P0001", "P0001"),
            ("a49.7", "A0049.7"),
            ("k00000039", "K0039"),
        ] {
            assert_eq!(
                Address::parse_in(input, p()).unwrap().to_string(),
                canonical
            );
        }
    }

    #[test]
    fn errors_name_the_range_and_the_fix() {
        let e = Address::parse_in("R1000", p()).unwrap_err();
        assert_eq!(e.to_string(), "R1000 is out of range (R0–R999)");
        let e = Address::parse_in("L0", p()).unwrap_err();
        assert_eq!(e.to_string(), "L0000 is out of range (L1–L9999)");
        let e = Address::parse_in("X99999999", p()).unwrap_err();
        assert!(e.to_string().contains("out of range (X0–X127)"), "{e}");
        assert!(matches!(
            Address::parse("D1.3"),
            Err(AddressError::NoBits(..))
        ));
        assert!(matches!(Address::parse("R1.8"), Err(AddressError::Bit(_))));
        assert!(matches!(
            Address::parse("Q1"),
            Err(AddressError::UnknownArea(..))
        ));
        assert!(matches!(Address::parse("R"), Err(AddressError::Syntax(_))));
        assert!(matches!(
            Address::parse("R1."),
            Err(AddressError::Syntax(_))
        ));
        assert!(matches!(
            Address::parse("R-1"),
            Err(AddressError::Syntax(_))
        ));
    }

    #[test]
    fn spans_past_the_end_are_refused() {
        let a = Address::parse("R998").unwrap();
        assert!(a.check_span(p(), 2).is_ok());
        let e = a.check_span(p(), 4).unwrap_err();
        assert_eq!(e.to_string(), "R0998–R1001 is out of range (R0–R999)");
    }
}
