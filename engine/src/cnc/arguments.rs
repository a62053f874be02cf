//! The words of a `cnc` script command and what each may be: axes by name or number,
//! millimetres, integers, parameter settings, tool offset numbers. Both the command parser
//! and the key and value names read them; their refusals are [`CncError`]s.

use super::error::{CncError, Quantity};
use super::params::{self, Params};
use super::{AXES, AXIS_NAMES};
use crate::profile::ProfileId;

/// The name of axis slot `a` ("?" beyond the fifth).
pub fn axis_name(a: u8) -> &'static str {
    AXIS_NAMES.get(usize::from(a)).copied().unwrap_or("?")
}

/// Axis by name (X Z Y 4 5) or number (1–5).
pub fn parse_axis(text: &str) -> Option<u8> {
    let t = text.to_ascii_uppercase();
    AXIS_NAMES
        .iter()
        .position(|n| *n == t)
        .or_else(|| {
            t.parse::<usize>()
                .ok()
                .filter(|n| (1..=AXES).contains(n))
                .map(|n| n - 1)
        })
        .map(|n| n as u8)
}

/// Millimetres as written (`12.5`), in thousandths, within ±99999.999 mm.
pub(super) fn mm(text: &str) -> Result<i64, CncError> {
    let v: f64 = text
        .parse()
        .ok()
        .filter(|v: &f64| v.is_finite())
        .ok_or_else(|| CncError::NotMm { text: text.into() })?;
    let incr = (v * 1000.0).round();
    if incr.abs() > 99_999_999.0 {
        return Err(CncError::MmRange { text: text.into() });
    }
    Ok(incr as i64)
}

/// An integer as written; `what` names it in the refusal.
pub(super) fn int(text: &str, what: Quantity) -> Result<i64, CncError> {
    text.parse::<i64>().map_err(|_| CncError::NotInteger {
        text: text.into(),
        what,
    })
}

/// Checks a parameter reference of a profile: GSK980 words 1–254, or a machine setting.
pub(super) fn check_param(
    profile: ProfileId,
    number: u16,
    selector: Option<u8>,
    value: i64,
) -> Result<(), CncError> {
    if profile == ProfileId::Gsk980 && (1..=params::GSK980_WORDS as u16).contains(&number) {
        if selector.is_some() {
            return Err(CncError::Gsk980Selector { number });
        }
        if i32::try_from(value).is_err() {
            return Err(CncError::Gsk980Value { number });
        }
        return Ok(());
    }
    Params::check(number, selector, value)
        .map(|_| ())
        .map_err(|error| CncError::Param { number, error })
}

/// The tool offset numbers a profile has.
pub(super) fn offset_range(profile: ProfileId) -> std::ops::RangeInclusive<u8> {
    match profile {
        ProfileId::Gsk988ta => 1..=99,
        ProfileId::Gsk980 => 0..=32,
    }
}
