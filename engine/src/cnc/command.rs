//! What a user does to a running CNC and what they read back (docs/cnc.md, "Script
//! commands"): the `cnc …` commands as values, checked when they are parsed so a script is
//! refused before it runs, and the `cnc.KEY` values with their comparison rules.

use super::data::{MacroSlot, OffsetType, parse_clock, work_system};
use super::params::{self, Params};
use super::{AXIS_NAMES, RunState, SimCnc};
use crate::profile::ProfileId;
use crate::refusal::Refusal;

pub use super::arguments::{axis_name, parse_axis};
use super::arguments::{check_param, int, mm, offset_range};
pub use super::error::{CncError, Quantity};
pub use super::keys::{CncKey, CncValue};

/// A command to the CNC.
#[derive(Clone, Debug, PartialEq)]
pub enum CncCommand {
    /// Replaces every memory program (the text) and rewinds.
    Program(String),
    /// Replaces the MDI buffer.
    Mdi(String),
    /// Sets a parameter's effective value.
    Param {
        /// Number.
        number: u16,
        /// Axis or spindle, 1-based.
        selector: Option<u8>,
        /// Value.
        value: i64,
    },
    /// Sets a tool offset.
    Offset {
        /// Offset number.
        number: u8,
        /// Which value.
        kind: OffsetType,
        /// Increments (tip: 0–9).
        value: i64,
    },
    /// Sets a workpiece offset.
    Workpiece {
        /// EXT = 0, G54 = 1 …
        system: u8,
        /// Axis slot (0 = X).
        axis: u8,
        /// Increments.
        value: i64,
    },
    /// Sets a macro variable (`None` = vacant).
    Macro {
        /// Variable number.
        number: u16,
        /// Value.
        value: Option<f64>,
    },
    /// Sets the machine position of a still axis.
    Position {
        /// Axis slot.
        axis: u8,
        /// Increments.
        value: i64,
    },
    /// Raises an alarm at the next exchange.
    Alarm(u16),
    /// Presses the RESET key for the next exchange.
    Reset,
    /// Handwheel pulses for the next exchange.
    Handwheel(i64),
    /// Sets the clock (seconds from 1970) at the current virtual time.
    Clock(i64),
}

fn writable_macro(n: i64) -> bool {
    matches!(
        MacroSlot::of(n),
        MacroSlot::Local | MacroSlot::Volatile(_) | MacroSlot::Kept(_) | MacroSlot::Output(_)
    )
}

impl CncCommand {
    /// Parses the words after `cnc`. `read_file` reads a program file named in the script.
    pub fn parse(
        words: &[&str],
        profile: ProfileId,
        read_file: &dyn Fn(&str) -> Result<String, String>,
    ) -> Result<CncCommand, CncError> {
        let Some(&sub) = words.first() else {
            return Err(CncError::NoSubcommand);
        };
        let args = &words[1..];
        Ok(match sub.to_ascii_lowercase().as_str() {
            "program" => {
                want(args, 1, "program \"TEXT\"")?;
                CncCommand::Program(args[0].to_string())
            }
            "program-file" => {
                want(args, 1, "program-file PATH")?;
                CncCommand::Program(read_file(args[0]).map_err(|message| CncError::ReadFile {
                    path: args[0].into(),
                    message,
                })?)
            }
            "mdi" => {
                want(args, 1, "mdi \"TEXT\"")?;
                CncCommand::Mdi(args[0].to_string())
            }
            "param" => Self::parse_param(args, profile)?,
            "offset" => Self::parse_offset(args, profile)?,
            "workpiece" => Self::parse_workpiece(args)?,
            "macro" => Self::parse_macro(args)?,
            "position" => Self::parse_position(args)?,
            "alarm" => Self::parse_alarm(args)?,
            "reset" => {
                want(args, 0, "reset")?;
                CncCommand::Reset
            }
            "handwheel" => Self::parse_handwheel(args)?,
            "clock" => {
                want(args, 1, "clock YYYY-MM-DDTHH:MM:SS")?;
                CncCommand::Clock(parse_clock(args[0]).ok_or_else(|| CncError::NotClock {
                    text: args[0].into(),
                })?)
            }
            _ => return Err(CncError::UnknownCommand { text: sub.into() }),
        })
    }

    /// `param N [SEL] VALUE`: the selector is optional, so the count is checked here rather
    /// than by [`want`]; the value is checked against the profile's parameter table.
    fn parse_param(args: &[&str], profile: ProfileId) -> Result<CncCommand, CncError> {
        if !(2..=3).contains(&args.len()) {
            return Err(CncError::Usage {
                usage: "param N [SEL] VALUE",
            });
        }
        let number = args[0]
            .parse::<u16>()
            .map_err(|_| CncError::NotParamNumber {
                text: args[0].into(),
                key: None,
            })?;
        let selector = match args.len() {
            3 => Some(args[1].parse::<u8>().map_err(|_| CncError::NotSelector {
                text: args[1].into(),
                key: None,
            })?),
            _ => None,
        };
        let value = int(args[args.len() - 1], Quantity::ParamValue)?;
        check_param(profile, number, selector, value)?;
        Ok(CncCommand::Param {
            number,
            selector,
            value,
        })
    }

    /// `offset N TYPE VALUE`: N within the profile's offsets; TIP takes a direction 0–9, every
    /// other type a length in mm.
    fn parse_offset(args: &[&str], profile: ProfileId) -> Result<CncCommand, CncError> {
        want(args, 3, "offset N TYPE VALUE")?;
        let range = offset_range(profile);
        let number = args[0]
            .parse::<u8>()
            .ok()
            .filter(|n| range.contains(n))
            .ok_or_else(|| CncError::OffsetNumber {
                text: args[0].into(),
                key: None,
                first: *range.start(),
                last: *range.end(),
            })?;
        let kind = OffsetType::parse(args[1]).ok_or_else(|| CncError::OffsetType {
            text: args[1].into(),
            key: None,
        })?;
        let value = if kind == OffsetType::Tip {
            let v = int(args[2], Quantity::TipDirection)?;
            if !(0..=9).contains(&v) {
                return Err(CncError::TipRange { value: v });
            }
            v
        } else {
            mm(args[2])?
        };
        Ok(CncCommand::Offset {
            number,
            kind,
            value,
        })
    }

    /// `workpiece SYS AXIS VALUE`: a work system by name, an axis, a value in mm.
    fn parse_workpiece(args: &[&str]) -> Result<CncCommand, CncError> {
        want(args, 3, "workpiece SYS AXIS VALUE")?;
        let system = work_system(args[0]).ok_or_else(|| CncError::WorkSystem {
            text: args[0].into(),
            key: None,
        })? as u8;
        let axis = parse_axis(args[1]).ok_or_else(|| CncError::BadAxis {
            text: args[1].into(),
            key: None,
        })?;
        Ok(CncCommand::Workpiece {
            system,
            axis,
            value: mm(args[2])?,
        })
    }

    /// `macro N VALUE`: only the variables a script may write, `vacant` or a finite number,
    /// and 0 or 1 for a signal bit.
    fn parse_macro(args: &[&str]) -> Result<CncCommand, CncError> {
        want(args, 2, "macro N VALUE")?;
        let n = int(args[0], Quantity::Variable)?;
        if !writable_macro(n) {
            return Err(CncError::MacroNotWritable { number: n });
        }
        let value = if args[1].eq_ignore_ascii_case("vacant") {
            None
        } else {
            Some(
                args[1]
                    .parse::<f64>()
                    .ok()
                    .filter(|v| v.is_finite())
                    .ok_or_else(|| CncError::NotDecimal {
                        text: args[1].into(),
                    })?,
            )
        };
        if matches!(MacroSlot::of(n), MacroSlot::Output(_))
            && !matches!(value, Some(v) if v == 0.0 || v == 1.0)
        {
            return Err(CncError::MacroSignalBit { number: n });
        }
        Ok(CncCommand::Macro {
            number: n as u16,
            value,
        })
    }

    /// `position AXIS VALUE`: an axis and a machine position in mm.
    fn parse_position(args: &[&str]) -> Result<CncCommand, CncError> {
        want(args, 2, "position AXIS VALUE")?;
        let axis = parse_axis(args[0]).ok_or_else(|| CncError::BadAxis {
            text: args[0].into(),
            key: None,
        })?;
        Ok(CncCommand::Position {
            axis,
            value: mm(args[1])?,
        })
    }

    /// `alarm N`: the alarms the machine itself raises are refused, so a script cannot fake
    /// them.
    fn parse_alarm(args: &[&str]) -> Result<CncCommand, CncError> {
        want(args, 1, "alarm N")?;
        let n = int(args[0], Quantity::Alarm)?;
        if !(1..=999).contains(&n) || matches!(n, 500 | 501 | 506 | 507 | 950) {
            return Err(CncError::AlarmNotRaisable { number: n });
        }
        Ok(CncCommand::Alarm(n as u16))
    }

    /// `handwheel COUNT`: at most 10000 pulses either way in one exchange.
    fn parse_handwheel(args: &[&str]) -> Result<CncCommand, CncError> {
        want(args, 1, "handwheel COUNT")?;
        let n = int(args[0], Quantity::Pulses)?;
        if !(-10_000..=10_000).contains(&n) {
            return Err(CncError::HandwheelRange { pulses: n });
        }
        Ok(CncCommand::Handwheel(n))
    }
}

/// Checks that a command has exactly `n` words after its name; `usage` is its usage, the
/// answer to a command given the wrong words.
fn want(args: &[&str], n: usize, usage: &'static str) -> Result<(), CncError> {
    if args.len() == n {
        Ok(())
    } else {
        Err(CncError::Usage { usage })
    }
}

impl SimCnc {
    /// Carries out a command between ticks; its effect on F appears at the next exchange.
    /// A command that cannot apply now says why.
    pub fn apply(&mut self, cmd: &CncCommand) -> Result<(), Refusal> {
        if matches!(
            cmd,
            CncCommand::Param { .. } | CncCommand::Offset { .. } | CncCommand::Workpiece { .. }
        ) {
            // The drawn path depends on these (DPI, offsets): work it out again when next asked.
            self.toolpath = Default::default();
        }
        match cmd {
            CncCommand::Program(text) | CncCommand::Mdi(text) => {
                if self.auto.state != RunState::Idle {
                    return Err(Refusal::ProgramBusy(self.auto.state));
                }
                if matches!(cmd, CncCommand::Program(_)) {
                    self.load_programs(text);
                } else {
                    self.load_mdi(text);
                }
            }
            CncCommand::Param {
                number,
                selector,
                value,
            } => {
                if self.profile == ProfileId::Gsk980
                    && (1..=params::GSK980_WORDS as u16).contains(number)
                {
                    self.params.set_word980(usize::from(*number), *value as i32);
                } else {
                    let (i, slot) = Params::check(*number, *selector, *value).map_err(|error| {
                        CncError::Param {
                            number: *number,
                            error,
                        }
                    })?;
                    self.params.set(i, slot, *value);
                    if i == params::P3402 && self.auto.state == RunState::Idle {
                        // Set up before a run, the feed mode is the one power-on would give.
                        self.auto.modal.per_rev = self.fpm_per_rev();
                    }
                }
            }
            CncCommand::Offset {
                number,
                kind,
                value,
            } => {
                let range = offset_range(self.profile);
                if !range.contains(number) {
                    let (a, b) = (range.start(), range.end());
                    return Err(Refusal::OffsetNumber {
                        lo: *a,
                        hi: *b,
                        number: *number,
                    });
                }
                if *kind == OffsetType::Tip && !(0..=9).contains(value) {
                    return Err(CncError::TipRange { value: *value }.into());
                }
                self.offsets[usize::from(*number)].set(*kind, *value);
            }
            CncCommand::Workpiece {
                system,
                axis,
                value,
            } => {
                let slot = self
                    .work
                    .get_mut(usize::from(*system))
                    .and_then(|w| w.get_mut(usize::from(*axis)))
                    .ok_or(CncError::NoWorkSlot)?;
                *slot = *value;
            }
            CncCommand::Macro { number, value } => match MacroSlot::of(i64::from(*number)) {
                MacroSlot::Local => self.set_local(usize::from(*number), *value),
                slot => self
                    .set_macro(slot, *value)
                    .map_err(|()| Refusal::MacroValue(*number))?,
            },
            CncCommand::Position { axis, value } => {
                let n = usize::from(*axis);
                let name = AXIS_NAMES.get(n).unwrap_or(&"?");
                if n >= self.axis_count() {
                    return Err(CncError::AxisBeyond {
                        axis: *axis,
                        count: self.axis_count(),
                    }
                    .into());
                }
                if self.remaining(n) != 0 || self.manual.moving(n) || self.plc_moving(n) {
                    return Err(Refusal::AxisMoving(name));
                }
                self.axes[n].m = (*value).clamp(-99_999_999, 99_999_999);
            }
            CncCommand::Alarm(n) => self.pending_alarms.push(*n),
            CncCommand::Reset => self.reset_key_pending = true,
            CncCommand::Handwheel(n) => {
                // Pulses queued for one exchange: a real handwheel gives at most a few hundred.
                self.manual.pulses =
                    (self.manual.pulses + (*n).clamp(-10_000, 10_000)).clamp(-1_000_000, 1_000_000);
            }
            CncCommand::Clock(t) => {
                self.clock_origin = *t;
                self.clock_set_ms = self.now_ms;
            }
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn parse(words: &[&str]) -> Result<CncCommand, CncError> {
        CncCommand::parse(words, ProfileId::Gsk988ta, &|p| Err(format!("no file {p}")))
    }

    #[test]
    fn commands_are_checked_when_parsed() {
        assert_eq!(
            parse(&["param", "1420", "2", "3000"]),
            Ok(CncCommand::Param {
                number: 1420,
                selector: Some(2),
                value: 3000
            })
        );
        assert!(
            parse(&["param", "1420", "3000"])
                .unwrap_err()
                .en()
                .contains("axis number")
        );
        assert!(
            parse(&["param", "3003", "1", "3"])
                .unwrap_err()
                .en()
                .contains("no axis")
        );
        assert!(
            parse(&["param", "8130", "9"])
                .unwrap_err()
                .en()
                .contains("2…5")
        );
        assert!(
            parse(&["offset", "100", "X", "1"])
                .unwrap_err()
                .en()
                .contains("1–99")
        );
        assert!(parse(&["offset", "1", "TIP", "10"]).is_err());
        assert_eq!(
            parse(&["offset", "2", "wz", "-0.5"]),
            Ok(CncCommand::Offset {
                number: 2,
                kind: OffsetType::Wear(1),
                value: -500
            })
        );
        assert!(parse(&["alarm", "950"]).is_err());
        assert!(parse(&["alarm", "401"]).is_ok());
        assert!(parse(&["macro", "1000", "1"]).is_err());
        assert!(parse(&["macro", "1100", "2"]).is_err());
        assert!(parse(&["macro", "100", "vacant"]).is_ok());
        assert!(parse(&["handwheel", "20000"]).is_err());
        assert!(parse(&["clock", "2026-02-30T00:00:00"]).is_err());
        assert!(
            parse(&["spin"])
                .unwrap_err()
                .en()
                .contains("unknown cnc command")
        );
        assert!(
            parse(&["program-file", "x.nc"])
                .unwrap_err()
                .en()
                .contains("no file")
        );
        assert!(parse(&["position", "Q", "1"]).is_err());
    }
}
