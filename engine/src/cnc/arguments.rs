//! The words of a `cnc` script command and what each may be: axes by name or number,
//! millimetres, integers, parameter settings with their refusals in both languages, tool
//! offset numbers. Both the command parser and the key and value names read them.

use super::params::{self, ParamError, Params, Selector, TABLE};
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
pub(super) fn mm(text: &str) -> Result<i64, String> {
    let v: f64 = text
        .parse()
        .ok()
        .filter(|v: &f64| v.is_finite())
        .ok_or_else(|| format!("`{text}` is not a number of mm"))?;
    let incr = (v * 1000.0).round();
    if incr.abs() > 99_999_999.0 {
        return Err(format!("{text} mm is beyond ±99999.999 mm"));
    }
    Ok(incr as i64)
}

/// An integer as written; `what` names it in the refusal.
pub(super) fn int(text: &str, what: &str) -> Result<i64, String> {
    text.parse::<i64>()
        .map_err(|_| format!("`{text}` is not an integer ({what})"))
}

/// [`param_error`] in Chinese.
pub(super) fn param_error_zh(e: ParamError, number: u16) -> String {
    match e {
        ParamError::Number => format!("没有参数 {number}"),
        ParamError::Selector => {
            let s = params::spec(number).expect("number checked first");
            match s.selector {
                Selector::None => format!("参数 {number} 不带轴号或主轴号"),
                Selector::Axis => format!("参数 {number} 需要轴号 1–5"),
                Selector::Spindle => format!("参数 {number} 需要主轴号 1–4"),
            }
        }
        ParamError::Value => {
            let s = params::spec(number).expect("number checked first");
            format!("参数 {number} 的范围为 {}…{}", s.min, s.max)
        }
    }
}

/// Why a parameter setting was refused, in English.
pub(super) fn param_error(e: ParamError, number: u16) -> String {
    match e {
        ParamError::Number => format!(
            "no parameter {number} (the simulator has {})",
            TABLE
                .iter()
                .map(|s| format!("{:04}", s.number))
                .collect::<Vec<_>>()
                .join(", ")
        ),
        ParamError::Selector => {
            let s = params::spec(number).expect("number checked first");
            match s.selector {
                Selector::None => format!("parameter {number} takes no axis or spindle number"),
                Selector::Axis => format!("parameter {number} needs an axis number 1–5"),
                Selector::Spindle => format!("parameter {number} needs a spindle number 1–4"),
            }
        }
        ParamError::Value => {
            let s = params::spec(number).expect("number checked first");
            format!("parameter {number} is {}…{}", s.min, s.max)
        }
    }
}

/// Checks a parameter reference of a profile: GSK980 words 1–254, or a machine setting.
pub(super) fn check_param(
    profile: ProfileId,
    number: u16,
    selector: Option<u8>,
    value: i64,
) -> Result<(), String> {
    if profile == ProfileId::Gsk980 && (1..=params::GSK980_WORDS as u16).contains(&number) {
        if selector.is_some() {
            return Err(format!("GSK980 parameter {number} takes no selector"));
        }
        if i32::try_from(value).is_err() {
            return Err(format!("GSK980 parameter {number} holds a 32-bit integer"));
        }
        return Ok(());
    }
    Params::check(number, selector, value)
        .map(|_| ())
        .map_err(|e| param_error(e, number))
}

/// The tool offset numbers a profile has.
pub(super) fn offset_range(profile: ProfileId) -> std::ops::RangeInclusive<u8> {
    match profile {
        ProfileId::Gsk988ta => 1..=99,
        ProfileId::Gsk980 => 0..=32,
    }
}
