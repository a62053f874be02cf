//! Stimulus scripts (docs/scripts.md; docs/cnc.md, "Script commands" for the `cnc` lines): parsed
//! whole before anything runs, so a typo on line 40 is reported before line 1 executes;
//! then run against a [`Machine`](crate::machine::Machine), counting `expect`s. Every line that acts on the machine
//! becomes a [`MachineCommand`], the same commands the editor sends to a running machine.

mod device;
mod lex;
mod run;
pub mod scenario;

use crate::address::{Address, Area};
use crate::cnc::command::{CncCommand, CncKey, CncValue};
use crate::machine::{MachineCommand, Probe};
use crate::profile::Profile;
use crate::vm::TICK_MS;

pub use crate::address::Target;
pub use crate::script::{
    DeviceQuantity, DeviceReason, QuoteError, ScenarioReason, ScriptError, ScriptReason,
};
pub use run::{Control, Event, Outcome, Part, Progress, Report, Stopped, run, run_with};

/// The most ticks one `scan` or `run` line may ask for: 100 000 000 ticks are 800 000 s
/// (nine days) of virtual time, a few minutes of a real one.
pub const MAX_TICKS: u64 = 100_000_000;

/// One script line.
#[derive(Clone, Debug, PartialEq)]
pub enum ScriptCommand {
    /// Something done to the machine: `set`, `setf`, `force`, `unforce`, `scan`, `run`,
    /// `watch`, `division`, `power-cycle`, `cnc …`.
    Do(MachineCommand),
    /// `expect ADDR[:N] VALUE`.
    Expect(Target, i64),
    /// `expectf ADDR VALUE [TOL]`.
    ExpectReal(Address, f32, Option<f32>),
    /// `expect cnc.KEY VALUE`, with the value as written.
    ExpectCnc(CncKey, CncValue, String),
    /// `print ADDR[:N]` or `print cnc.KEY`.
    Print(Probe),
    /// `expect device.NAME VALUE`, by the device's index.
    ExpectDevice(usize, i64),
}

/// A parsed script: commands with their lines.
#[derive(Clone, Debug, PartialEq, Default)]
pub struct Script {
    /// (line, command).
    pub commands: Vec<(usize, ScriptCommand)>,
}

/// How a script is read.
pub struct Options<'a> {
    /// `sim --cnc`: the `cnc` lines and `cnc.KEY` values are allowed.
    pub cnc: bool,
    /// Reads a file a `cnc program-file` line names (relative to the script's folder).
    pub read_file: &'a dyn Fn(&str) -> Result<String, String>,
    /// The machine model the script runs with (none: `--no-machine`, or no devices): it
    /// names the `device` lines' devices and refuses `set` of the inputs they drive.
    pub machine: Option<&'a crate::devices::MachineModel>,
    /// The project the script runs on (none for an instruction list): its saved scenarios
    /// and operator panel serve the `scenario` lines.
    pub project: Option<&'a crate::model::Project>,
}

/// The commands of a script line, as a refusal of an unknown one lists them.
pub const COMMANDS: &[&str] = &[
    "set",
    "setf",
    "force",
    "unforce",
    "scan",
    "run",
    "expect",
    "expectf",
    "print",
    "watch",
    "division",
    "power-cycle",
    "cnc",
    "device",
    "scenario",
];

fn target(text: &str, profile: &Profile) -> Result<Target, ScriptReason> {
    let (addr, bytes) = match text.split_once(':') {
        Some((a, n)) => {
            let n: u32 = n
                .parse()
                .ok()
                .filter(|n| matches!(n, 1 | 2 | 4))
                .ok_or_else(|| ScriptReason::ByteCount { text: text.into() })?;
            (a, Some(n))
        }
        None => (text, None),
    };
    let address = Address::parse_in(addr, profile)?;
    if matches!(address.area, Area::L | Area::P) {
        return Err(ScriptReason::NoValue { text: text.into() });
    }
    if address.bit.is_some() && bytes.is_some() {
        return Err(ScriptReason::BitWithByteCount { text: text.into() });
    }
    let natural = if address.bit.is_some() {
        1
    } else {
        u32::from(address.area.element_bytes())
    };
    let bytes = bytes.unwrap_or(natural);
    if address.bit.is_none() && address.area.element_bytes() == 1 {
        address.check_span(profile, bytes)?;
    }
    Ok(Target {
        address,
        bytes,
        explicit: bytes != natural,
    })
}

fn is_cnc_key(text: &str) -> bool {
    text.get(..4)
        .is_some_and(|p| p.eq_ignore_ascii_case("cnc."))
}

fn probe(text: &str, profile: &Profile, options: &Options<'_>) -> Result<Probe, ScriptReason> {
    if let Some(p) = device::probe(text, options.machine) {
        return p;
    }
    if is_cnc_key(text) {
        if !options.cnc {
            return Err(ScriptReason::CncValueNeedsCnc { text: text.into() });
        }
        return Ok(Probe::Cnc(CncKey::parse(text, profile.id)?));
    }
    target(text, profile).map(Probe::Memory)
}

fn memory_target(
    text: &str,
    profile: &Profile,
    verb: &'static str,
) -> Result<Target, ScriptReason> {
    if is_cnc_key(text) {
        return Err(ScriptReason::WritesMemory {
            verb,
            text: text.into(),
        });
    }
    target(text, profile)
}

fn integer(text: &str) -> Result<i64, ScriptReason> {
    let (neg, digits) = match text.strip_prefix('-') {
        Some(d) => (true, d),
        None => (false, text.strip_prefix('+').unwrap_or(text)),
    };
    let v = match digits
        .strip_prefix("0x")
        .or_else(|| digits.strip_prefix("0X"))
    {
        Some(hex) => i64::from_str_radix(hex, 16),
        None => digits.parse::<i64>(),
    }
    .map_err(|_| ScriptReason::NotInteger { text: text.into() })?;
    Ok(if neg { -v } else { v })
}

fn fits(target: &Target, value: i64) -> Result<(), ScriptReason> {
    if target.address.bit.is_some() {
        return if value == 0 || value == 1 {
            Ok(())
        } else {
            Err(ScriptReason::NotBit {
                target: *target,
                value,
            })
        };
    }
    let bits = 8 * target.bytes;
    let (lo, hi) = (-(1i64 << (bits - 1)), (1i64 << bits) - 1);
    if value < lo || value > hi {
        return Err(ScriptReason::DoesNotFit {
            value,
            target: *target,
            lo,
            hi,
        });
    }
    Ok(())
}

fn duration(text: &str) -> Result<u64, ScriptReason> {
    let bad = || ScriptReason::NotDuration { text: text.into() };
    let (number, scale) = if let Some(n) = text.strip_suffix("ms") {
        (n, 1.0)
    } else if let Some(n) = text.strip_suffix('s') {
        (n, 1000.0)
    } else {
        (text, 1.0)
    };
    let v: f64 = number.parse().map_err(|_| bad())?;
    if !v.is_finite() || v < 0.0 {
        return Err(bad());
    }
    let ticks = ((v * scale) / TICK_MS as f64).ceil();
    if ticks > MAX_TICKS as f64 {
        return Err(ScriptReason::TooLong {
            text: text.into(),
            seconds: MAX_TICKS * TICK_MS / 1000,
            ticks: MAX_TICKS,
        });
    }
    Ok(ticks as u64)
}

fn real(text: &str) -> Result<f32, ScriptReason> {
    text.parse::<f32>()
        .map_err(|_| ScriptReason::NotNumber { text: text.into() })
}

fn four_byte(t: &Target, verb: &'static str) -> Result<(), ScriptReason> {
    if t.address.bit.is_some() || t.address.area.element_bytes() != 4 {
        return Err(ScriptReason::NotFourBytes {
            verb,
            address: t.address,
        });
    }
    Ok(())
}

fn no_files(path: &str) -> Result<String, String> {
    Err(format!("cannot read `{path}`: no files here"))
}

impl Script {
    /// Parses a whole script for the PLC alone (no `cnc` lines), or says which line is wrong.
    pub fn parse(text: &str, profile: &Profile) -> Result<Script, ScriptError> {
        Script::parse_with(
            text,
            profile,
            &Options {
                cnc: false,
                read_file: &no_files,
                machine: None,
                project: None,
            },
        )
    }

    /// Parses a whole script, or says which line is wrong.
    pub fn parse_with(
        text: &str,
        profile: &Profile,
        options: &Options<'_>,
    ) -> Result<Script, ScriptError> {
        let mut commands = Vec::new();
        for (i, raw) in text.lines().enumerate() {
            let line = i + 1;
            let err = |reason: ScriptReason| ScriptError { line, reason };
            let words = lex::words(raw).map_err(|e| err(e.into()))?;
            let Some(&verb) = words.first() else {
                continue;
            };
            let command = parse_line(verb, &words[1..], profile, options).map_err(err)?;
            commands.push((line, command));
        }
        Ok(Script { commands })
    }
}

/// The N of `scan N`: a number of ticks one line may run.
fn scan_count(n: &str) -> Result<u64, ScriptReason> {
    let count = n
        .parse::<u64>()
        .map_err(|_| ScriptReason::NotScanCount { text: n.into() })?;
    if count > MAX_TICKS {
        return Err(ScriptReason::TooManyScans {
            text: n.into(),
            most: MAX_TICKS,
        });
    }
    Ok(count)
}

fn parse_line(
    verb: &str,
    args: &[&str],
    profile: &Profile,
    options: &Options<'_>,
) -> Result<ScriptCommand, ScriptReason> {
    let want = |n: std::ops::RangeInclusive<usize>, usage: &'static str| {
        if n.contains(&args.len()) {
            Ok(())
        } else {
            Err(ScriptReason::Usage { usage })
        }
    };
    let lower = verb.to_ascii_lowercase();
    let act = |c: MachineCommand| Ok(ScriptCommand::Do(c));
    match lower.as_str() {
        "set" => {
            want(2..=2, "set ADDR[:N] VALUE")?;
            let t = memory_target(args[0], profile, "set")?;
            device::not_driven(&t, "set", options.machine)?;
            let v = integer(args[1])?;
            fits(&t, v)?;
            act(MachineCommand::Write(t, v))
        }
        "setf" => {
            want(2..=2, "setf ADDR VALUE")?;
            let t = memory_target(args[0], profile, "setf")?;
            device::not_driven(&t, "setf", options.machine)?;
            four_byte(&t, "setf")?;
            act(MachineCommand::WriteReal(t.address, real(args[1])?))
        }
        "force" => {
            want(2..=2, "force ADDR VALUE")?;
            let t = memory_target(args[0], profile, "force")?;
            let v = integer(args[1])?;
            fits(&t, v)?;
            act(MachineCommand::Force(t.address, v))
        }
        "unforce" => {
            want(1..=1, "unforce ADDR")?;
            act(MachineCommand::Unforce(
                memory_target(args[0], profile, "unforce")?.address,
            ))
        }
        "scan" => {
            want(0..=1, "scan [N]")?;
            let n = match args.first() {
                Some(n) => scan_count(n)?,
                None => 1,
            };
            act(MachineCommand::Tick(n))
        }
        "run" => {
            want(1..=1, "run DURATION")?;
            act(MachineCommand::Tick(duration(args[0])?))
        }
        "expect" => {
            want(2..=2, "expect ADDR[:N] VALUE")?;
            match probe(args[0], profile, options)? {
                Probe::Cnc(k) => Ok(ScriptCommand::ExpectCnc(
                    k,
                    k.expected(args[1])?,
                    args[1].into(),
                )),
                Probe::Memory(t) => {
                    let v = integer(args[1])?;
                    fits(&t, v)?;
                    Ok(ScriptCommand::Expect(t, v))
                }
                Probe::Device(i) => Ok(ScriptCommand::ExpectDevice(i, integer(args[1])?)),
            }
        }
        "expectf" => {
            want(2..=3, "expectf ADDR VALUE [TOL]")?;
            let t = memory_target(args[0], profile, "expectf")?;
            four_byte(&t, "expectf")?;
            let tol = match args.get(2) {
                Some(t) => Some(real(t)?),
                None => None,
            };
            Ok(ScriptCommand::ExpectReal(t.address, real(args[1])?, tol))
        }
        "print" => {
            want(1..=1, "print ADDR[:N]")?;
            Ok(ScriptCommand::Print(probe(args[0], profile, options)?))
        }
        "watch" => {
            want(1..=1, "watch ADDR[:N]")?;
            act(MachineCommand::Watch(probe(args[0], profile, options)?))
        }
        "division" => {
            want(1..=1, "division N")?;
            let n = args[0]
                .parse::<u32>()
                .ok()
                .filter(|n| (1..=1000).contains(n))
                .ok_or_else(|| ScriptReason::Division {
                    text: args[0].into(),
                })?;
            act(MachineCommand::Division(n))
        }
        "power-cycle" => {
            want(0..=0, "power-cycle")?;
            act(MachineCommand::PowerCycle)
        }
        "cnc" => {
            if !options.cnc {
                return Err(ScriptReason::CncLineNeedsCnc);
            }
            act(MachineCommand::Cnc(CncCommand::parse(
                args,
                profile.id,
                options.read_file,
            )?))
        }
        "device" => device::line(args, options.machine),
        "scenario" => scenario::line(args, options),
        _ => {
            let prefix: String = lower.chars().take(3).collect();
            Err(ScriptReason::UnknownCommand {
                verb: verb.into(),
                near: COMMANDS.iter().find(|c| c.starts_with(&prefix)).copied(),
            })
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::address::AddressError;
    use crate::cnc::command::CncError;
    use crate::profile::ProfileId;

    fn parse(text: &str) -> Result<Script, ScriptError> {
        Script::parse(text, Profile::get(ProfileId::Gsk988ta))
    }

    fn parse_cnc(text: &str) -> Result<Script, ScriptError> {
        Script::parse_with(
            text,
            Profile::get(ProfileId::Gsk988ta),
            &Options {
                machine: None,
                project: None,
                cnc: true,
                read_file: &|p| {
                    if p == "part.nc" {
                        Ok("O0001;M30".into())
                    } else {
                        Err(format!("cannot read {p}"))
                    }
                },
            },
        )
    }

    fn reason(text: &str) -> ScriptReason {
        parse(text).expect_err(text).reason
    }

    #[test]
    fn errors_name_the_line() {
        let e = parse("scan\n\nset R0000 256\n").unwrap_err();
        assert_eq!(e.line, 3);
        assert!(
            matches!(
                e.reason,
                ScriptReason::DoesNotFit {
                    value: 256,
                    lo: -128,
                    hi: 255,
                    ..
                }
            ),
            "{e:?}"
        );
        let e = parse("# comment\nsett X1.0 1").unwrap_err();
        assert_eq!(e.line, 2);
        assert_eq!(
            e.reason,
            ScriptReason::UnknownCommand {
                verb: "sett".into(),
                near: Some("set")
            }
        );
        assert!(matches!(
            reason("set R1000 1"),
            ScriptReason::Address(AddressError::Range { lo: 0, hi: 999, .. })
        ));
        assert!(matches!(
            reason("set X1.0 2"),
            ScriptReason::NotBit { value: 2, .. }
        ));
        assert!(matches!(reason("run 2x"), ScriptReason::NotDuration { .. }));
        assert!(matches!(
            reason("expect D1:3 0"),
            ScriptReason::ByteCount { .. }
        ));
        assert!(matches!(
            reason("setf R1 1.5"),
            ScriptReason::NotFourBytes { verb: "setf", .. }
        ));
        assert_eq!(
            reason("print \"R1"),
            ScriptReason::Quote(QuoteError::Unclosed)
        );
    }

    #[test]
    fn cnc_lines_need_the_cnc_and_are_checked_before_anything_runs() {
        let e = parse("scan\ncnc reset").unwrap_err();
        assert_eq!(e.line, 2);
        assert_eq!(e.reason, ScriptReason::CncLineNeedsCnc);
        assert!(matches!(
            reason("expect cnc.mode MEM"),
            ScriptReason::CncValueNeedsCnc { .. }
        ));
        assert!(parse_cnc("cnc program \"O0001;M03 S800;M30\"").is_ok());
        assert!(parse_cnc("cnc program-file part.nc").is_ok());
        let e = parse_cnc("scan\ncnc program-file other.nc").unwrap_err();
        assert_eq!(e.line, 2);
        assert!(
            matches!(&e.reason, ScriptReason::Cnc(CncError::ReadFile { path, .. }) if path == "other.nc"),
            "{e:?}"
        );
        assert!(matches!(
            parse_cnc("set cnc.mode 1").unwrap_err().reason,
            ScriptReason::WritesMemory { verb: "set", .. }
        ));
        assert!(parse_cnc("force cnc.pos.X 1").is_err());
        assert!(parse_cnc("expect cnc.run GO").is_err());
        assert!(parse_cnc("expect cnc.pos.X").is_err());
        assert!(parse_cnc("cnc program \"M03").is_err());
        assert!(parse_cnc("watch cnc.pos.Z\nprint cnc.spindle").is_ok());
    }

    #[test]
    fn a_line_runs_at_most_a_hundred_million_ticks() {
        assert!(parse("scan 100000000\nrun 800000s").is_ok());
        assert_eq!(
            reason("scan 100000001"),
            ScriptReason::TooManyScans {
                text: "100000001".into(),
                most: 100_000_000
            }
        );
        let e = parse("scan 1\nrun 10000000000000").unwrap_err();
        assert_eq!(e.line, 2);
        assert_eq!(
            e.reason,
            ScriptReason::TooLong {
                text: "10000000000000".into(),
                seconds: 800_000,
                ticks: 100_000_000
            }
        );
        assert!(matches!(
            reason("scan -1"),
            ScriptReason::NotScanCount { .. }
        ));
    }

    #[test]
    fn durations_round_up_to_ticks() {
        let s = parse("run 250ms\nrun 2s\nrun 9\nscan 3 ; three\nrun 0").unwrap();
        let ticks: Vec<u64> = s
            .commands
            .iter()
            .map(|(_, c)| match c {
                ScriptCommand::Do(MachineCommand::Tick(n)) => *n,
                _ => 0,
            })
            .collect();
        assert_eq!(ticks, vec![32, 250, 2, 3, 0]);
    }
}
