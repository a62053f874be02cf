//! The `cnc.KEY` values scripts and the editor read from a running CNC (docs/cnc.md,
//! "Script commands"), with the way `expect` compares each kind: names in any case, lengths
//! rounded to 0.001 mm, macro variables as decimals or `vacant`.

use super::arguments::{axis_name, check_param, int, mm, offset_range, parse_axis};
use super::data::{OffsetType, WORK_SYSTEMS, work_system};
use super::error::{CncError, Quantity};
use super::params;
use super::{Mode, RunState, SimCnc};
use crate::profile::ProfileId;
use std::fmt;

/// A value of the CNC that scripts and the editor read.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum CncKey {
    /// `cnc.mode`.
    Mode,
    /// `cnc.run`.
    Run,
    /// `cnc.block`.
    Block,
    /// `cnc.prog`.
    Prog,
    /// `cnc.pos.AXIS`.
    Pos(u8),
    /// `cnc.abs.AXIS`.
    Abs(u8),
    /// `cnc.spindle`.
    Spindle,
    /// `cnc.alarm.N`.
    Alarm(u16),
    /// `cnc.alarms`.
    Alarms,
    /// `cnc.param.N[.SEL]`.
    Param(u16, Option<u8>),
    /// `cnc.offset.N.TYPE`.
    Offset(u8, OffsetType),
    /// `cnc.work.SYS.AXIS`.
    Work(u8, u8),
    /// `cnc.macro.N`.
    Macro(u16),
}

/// A value read from the CNC.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum CncValue {
    /// A name (mode, run state).
    Name(&'static str),
    /// An integer.
    Int(i64),
    /// A length in increments of 0.001 mm, shown in mm.
    Mm(i64),
    /// A macro variable (`None` = vacant).
    Macro(Option<f64>),
}

impl fmt::Display for CncValue {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            CncValue::Name(n) => f.write_str(n),
            CncValue::Int(v) => write!(f, "{v}"),
            CncValue::Mm(v) => {
                let sign = if v < 0 { "-" } else { "" };
                write!(f, "{sign}{}.{:03}", v.abs() / 1000, v.abs() % 1000)
            }
            CncValue::Macro(None) => f.write_str("vacant"),
            CncValue::Macro(Some(v)) => write!(f, "{v}"),
        }
    }
}

impl CncKey {
    /// Parses `cnc.KEY` (the text starts with `cnc.`, any case).
    pub fn parse(text: &str, profile: ProfileId) -> Result<CncKey, CncError> {
        let lower = text.to_ascii_lowercase();
        let parts: Vec<&str> = lower.split('.').collect();
        let bad = || CncError::UnknownKey { text: text.into() };
        if parts.first() != Some(&"cnc") {
            return Err(bad());
        }
        // A word of the key is refused with the key it was part of.
        let key = || Some(text.to_string());
        let axis = |t: &str| {
            parse_axis(t).ok_or_else(|| CncError::BadAxis {
                text: t.into(),
                key: key(),
            })
        };
        Ok(match parts[1..] {
            ["mode"] => CncKey::Mode,
            ["run"] => CncKey::Run,
            ["block"] => CncKey::Block,
            ["prog"] => CncKey::Prog,
            ["spindle"] => CncKey::Spindle,
            ["alarms"] => CncKey::Alarms,
            ["pos", a] => CncKey::Pos(axis(a)?),
            ["abs", a] => CncKey::Abs(axis(a)?),
            ["alarm", n] => CncKey::Alarm(
                n.parse::<u16>()
                    .ok()
                    .filter(|n| (1..=9999).contains(n))
                    .ok_or_else(|| CncError::KeyAlarm {
                        text: n.into(),
                        key: text.into(),
                    })?,
            ),
            ["param", n] | ["param", n, _] => {
                let number = n.parse::<u16>().map_err(|_| CncError::NotParamNumber {
                    text: n.into(),
                    key: key(),
                })?;
                let selector = match parts.get(3) {
                    Some(s) => Some(s.parse::<u8>().map_err(|_| CncError::NotSelector {
                        text: s.to_string(),
                        key: key(),
                    })?),
                    None => None,
                };
                // Any value in range: only the number and selector are checked here.
                let probe = params::spec(number).map_or(0, |s| s.min);
                check_param(profile, number, selector, probe)?;
                CncKey::Param(number, selector)
            }
            ["offset", n, t] => {
                let range = offset_range(profile);
                let number = n
                    .parse::<u8>()
                    .ok()
                    .filter(|n| range.contains(n))
                    .ok_or_else(|| CncError::OffsetNumber {
                        text: n.into(),
                        key: key(),
                        first: *range.start(),
                        last: *range.end(),
                    })?;
                let kind = OffsetType::parse(t).ok_or_else(|| CncError::OffsetType {
                    text: t.into(),
                    key: key(),
                })?;
                CncKey::Offset(number, kind)
            }
            ["work", s, a] => CncKey::Work(
                work_system(s).ok_or_else(|| CncError::WorkSystem {
                    text: s.into(),
                    key: key(),
                })? as u8,
                axis(a)?,
            ),
            ["macro", n] => {
                let v = n
                    .parse::<i64>()
                    .ok()
                    .filter(|v| super::macro_b::exists(*v))
                    .ok_or_else(|| CncError::KeyMacro {
                        text: n.into(),
                        key: text.into(),
                    })?;
                CncKey::Macro(v as u16)
            }
            _ => return Err(bad()),
        })
    }

    /// The key as printed.
    pub fn text(&self) -> String {
        match *self {
            CncKey::Mode => "cnc.mode".into(),
            CncKey::Run => "cnc.run".into(),
            CncKey::Block => "cnc.block".into(),
            CncKey::Prog => "cnc.prog".into(),
            CncKey::Pos(a) => format!("cnc.pos.{}", axis_name(a)),
            CncKey::Abs(a) => format!("cnc.abs.{}", axis_name(a)),
            CncKey::Spindle => "cnc.spindle".into(),
            CncKey::Alarm(n) => format!("cnc.alarm.{n}"),
            CncKey::Alarms => "cnc.alarms".into(),
            CncKey::Param(n, None) => format!("cnc.param.{n}"),
            CncKey::Param(n, Some(s)) => format!("cnc.param.{n}.{s}"),
            CncKey::Offset(n, t) => format!("cnc.offset.{n}.{}", t.name()),
            CncKey::Work(s, a) => {
                format!("cnc.work.{}.{}", WORK_SYSTEMS[usize::from(s)], axis_name(a))
            }
            CncKey::Macro(n) => format!("cnc.macro.{n}"),
        }
    }

    /// The value an `expect` line wants, read by the key's kind: names case-insensitively,
    /// lengths rounded to 0.001 mm, macros as decimals or `vacant`.
    pub fn expected(&self, text: &str) -> Result<CncValue, CncError> {
        match self {
            CncKey::Mode => Mode::ALL
                .iter()
                .find(|m| m.name().eq_ignore_ascii_case(text))
                .map(|m| CncValue::Name(m.name()))
                .ok_or_else(|| CncError::NotMode { text: text.into() }),
            CncKey::Run => RunState::ALL
                .iter()
                .find(|m| m.name().eq_ignore_ascii_case(text))
                .map(|m| CncValue::Name(m.name()))
                .ok_or_else(|| CncError::NotRunState { text: text.into() }),
            CncKey::Pos(_) | CncKey::Abs(_) | CncKey::Work(..) => mm(text).map(CncValue::Mm),
            CncKey::Offset(_, t) if *t != OffsetType::Tip => mm(text).map(CncValue::Mm),
            CncKey::Macro(_) => {
                if text.eq_ignore_ascii_case("vacant") {
                    Ok(CncValue::Macro(None))
                } else {
                    text.parse::<f64>()
                        .ok()
                        .filter(|v| v.is_finite())
                        .map(|v| CncValue::Macro(Some(v)))
                        .ok_or_else(|| CncError::NotDecimal { text: text.into() })
                }
            }
            _ => int(text, Quantity::Integer).map(CncValue::Int),
        }
    }
}

impl SimCnc {
    /// Reads a value; positions of an axis beyond #8130 cannot be read.
    pub fn value(&self, key: &CncKey) -> Result<CncValue, CncError> {
        let axis = |a: u8| {
            let n = usize::from(a);
            if n >= self.axis_count() {
                Err(CncError::AxisBeyond {
                    axis: a,
                    count: self.axis_count(),
                })
            } else {
                Ok(n)
            }
        };
        Ok(match *key {
            CncKey::Mode => CncValue::Name(self.mode.name()),
            CncKey::Run => CncValue::Name(self.auto.state.name()),
            CncKey::Block => CncValue::Int(i64::from(self.auto.last_n)),
            CncKey::Prog => CncValue::Int(i64::from(self.current_program_number())),
            CncKey::Pos(a) => CncValue::Mm(self.axes[axis(a)?].m),
            CncKey::Abs(a) => CncValue::Mm(self.absolute(axis(a)?)),
            CncKey::Spindle => CncValue::Int(i64::from(self.spindle.s_out)),
            CncKey::Alarm(n) => CncValue::Int(i64::from(self.alarm_active(n))),
            CncKey::Alarms => CncValue::Int(self.alarms.len() as i64),
            CncKey::Param(n, sel) => {
                if self.profile == ProfileId::Gsk980
                    && (1..=params::GSK980_WORDS as u16).contains(&n)
                {
                    CncValue::Int(i64::from(self.params.word980(usize::from(n))))
                } else {
                    let i = params::index(n).ok_or(CncError::NoParameter { number: n })?;
                    let slot = sel.map_or(0, |s| usize::from(s).saturating_sub(1));
                    CncValue::Int(self.params.get(i, slot))
                }
            }
            CncKey::Offset(n, t) => {
                let v = self
                    .offsets
                    .get(usize::from(n))
                    .ok_or(CncError::NoOffset { number: n })?
                    .get(t);
                if t == OffsetType::Tip {
                    CncValue::Int(v)
                } else {
                    CncValue::Mm(v)
                }
            }
            CncKey::Work(s, a) => CncValue::Mm(
                *self
                    .work
                    .get(usize::from(s))
                    .and_then(|w| w.get(usize::from(a)))
                    .ok_or(CncError::NoWorkSlot)?,
            ),
            CncKey::Macro(n) => CncValue::Macro(
                super::macro_b::expr::Vars::read(self, i64::from(n)).unwrap_or(None),
            ),
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn keys_print_canonically_and_read_expectations_by_kind() {
        let k = CncKey::parse("CNC.POS.z", ProfileId::Gsk988ta).unwrap();
        assert_eq!(k.text(), "cnc.pos.Z");
        assert_eq!(k.expected("-5"), Ok(CncValue::Mm(-5000)));
        assert_eq!(CncValue::Mm(-4987).to_string(), "-4.987");
        assert_eq!(CncValue::Mm(-5).to_string(), "-0.005");
        let m = CncKey::parse("cnc.mode", ProfileId::Gsk988ta).unwrap();
        assert_eq!(m.expected("mem"), Ok(CncValue::Name("MEM")));
        assert!(m.expected("AUTO").is_err());
        assert!(CncKey::parse("cnc.pos.Q", ProfileId::Gsk988ta).is_err());
        assert!(CncKey::parse("cnc.param.1420", ProfileId::Gsk988ta).is_err());
        assert!(CncKey::parse("cnc.param.1420.1", ProfileId::Gsk988ta).is_ok());
        assert!(CncKey::parse("cnc.param.77", ProfileId::Gsk980).is_ok());
        assert!(CncKey::parse("cnc.speed", ProfileId::Gsk988ta).is_err());
        assert_eq!(
            CncKey::parse("cnc.macro.500", ProfileId::Gsk988ta)
                .unwrap()
                .expected("vacant"),
            Ok(CncValue::Macro(None))
        );
    }
}
