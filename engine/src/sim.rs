//! Stimulus scripts (formats.md §2): parsed whole before anything runs, so a typo on line 40
//! is reported before line 1 executes; then run against a [`Vm`], counting `expect`s.

use crate::address::{Address, AddressError};
use crate::profile::Profile;
use crate::vm::{TICK_MS, Vm};
use std::fmt::Write as _;
use thiserror::Error;

/// An address with an optional byte count (`D0010:2`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Target {
    /// The address.
    pub address: Address,
    /// Bytes: given with `:N`, else the area's natural width (1 for bits).
    pub bytes: u32,
    /// Whether `:N` was written.
    pub explicit: bool,
}

impl Target {
    /// The address as printed in messages: canonical, with `:N` when it was given.
    pub fn text(&self) -> String {
        if self.explicit {
            format!("{}:{}", self.address, self.bytes)
        } else {
            self.address.to_string()
        }
    }
}

/// One script command.
#[derive(Clone, Debug, PartialEq)]
pub enum Command {
    /// `set ADDR[:N] VALUE`.
    Set(Target, i64),
    /// `setf ADDR VALUE`.
    SetReal(Address, f32),
    /// `force ADDR VALUE`.
    Force(Address, i64),
    /// `unforce ADDR`.
    Unforce(Address),
    /// `scan [N]` and `run DURATION` (as ticks).
    Scan(u64),
    /// `expect ADDR[:N] VALUE`.
    Expect(Target, i64),
    /// `expectf ADDR VALUE [TOL]`.
    ExpectReal(Address, f32, Option<f32>),
    /// `print ADDR[:N]`.
    Print(Target),
    /// `watch ADDR[:N]`.
    Watch(Target),
    /// `division N`.
    Division(u32),
    /// `power-cycle`.
    PowerCycle,
}

/// A script line that cannot be used.
#[derive(Clone, Debug, PartialEq, Eq, Error)]
#[error("line {line}: {message}")]
pub struct ScriptError {
    /// 1-based line.
    pub line: usize,
    /// What is wrong and how to fix it.
    pub message: String,
}

/// A parsed script: commands with their lines.
#[derive(Clone, Debug, PartialEq, Default)]
pub struct Script {
    /// (line, command).
    pub commands: Vec<(usize, Command)>,
}

const COMMANDS: &[&str] = &[
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
];

fn target(text: &str, profile: &Profile) -> Result<Target, String> {
    let (addr, bytes) = match text.split_once(':') {
        Some((a, n)) => {
            let n: u32 = n
                .parse()
                .ok()
                .filter(|n| matches!(n, 1 | 2 | 4))
                .ok_or_else(|| format!("`{text}`: the byte count after `:` is 1, 2 or 4"))?;
            (a, Some(n))
        }
        None => (text, None),
    };
    let address = Address::parse_in(addr, profile).map_err(|e: AddressError| e.to_string())?;
    if matches!(
        address.area,
        crate::address::Area::L | crate::address::Area::P
    ) {
        return Err(format!("`{text}`: labels and subprograms hold no value"));
    }
    if address.bit.is_some() && bytes.is_some() {
        return Err(format!("`{text}`: a bit address takes no byte count"));
    }
    let natural = if address.bit.is_some() {
        1
    } else {
        u32::from(address.area.element_bytes())
    };
    let bytes = bytes.unwrap_or(natural);
    if address.bit.is_none() && address.area.element_bytes() == 1 {
        address
            .check_span(profile, bytes)
            .map_err(|e| e.to_string())?;
    }
    Ok(Target {
        address,
        bytes,
        explicit: bytes != natural,
    })
}

fn integer(text: &str) -> Result<i64, String> {
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
    .map_err(|_| format!("`{text}` is not an integer"))?;
    Ok(if neg { -v } else { v })
}

fn fits(target: &Target, v: i64) -> Result<(), String> {
    if target.address.bit.is_some() {
        return if v == 0 || v == 1 {
            Ok(())
        } else {
            Err(format!(
                "{} is a bit: the value is 0 or 1, not {v}",
                target.text()
            ))
        };
    }
    let bits = 8 * target.bytes;
    let (lo, hi) = (-(1i64 << (bits - 1)), (1i64 << bits) - 1);
    if v < lo || v > hi {
        return Err(format!(
            "{v} does not fit {} ({} byte{}: {lo}…{hi})",
            target.text(),
            target.bytes,
            if target.bytes == 1 { "" } else { "s" }
        ));
    }
    Ok(())
}

fn duration(text: &str) -> Result<u64, String> {
    let bad = || format!("`{text}` is not a duration (write 250ms, 2s or a number of ms)");
    let (number, scale) = if let Some(n) = text.strip_suffix("ms") {
        (n, 1.0)
    } else if let Some(n) = text.strip_suffix('s') {
        (n, 1000.0)
    } else {
        (text, 1.0)
    };
    let v: f64 = number.parse().map_err(|_| bad())?;
    if !v.is_finite() || v < 0.0 || v * scale > 1e13 {
        return Err(bad());
    }
    Ok(((v * scale) / TICK_MS as f64).ceil() as u64)
}

fn real(text: &str) -> Result<f32, String> {
    text.parse::<f32>()
        .map_err(|_| format!("`{text}` is not a number"))
}

impl Script {
    /// Parses a whole script, or says which line is wrong.
    pub fn parse(text: &str, profile: &Profile) -> Result<Script, ScriptError> {
        let mut commands = Vec::new();
        for (i, raw) in text.lines().enumerate() {
            let line = i + 1;
            let body = raw.split(['#', ';']).next().unwrap_or("");
            let words: Vec<&str> = body.split_whitespace().collect();
            let Some(&verb) = words.first() else {
                continue;
            };
            let err = |message: String| ScriptError { line, message };
            let args = &words[1..];
            let want = |n: std::ops::RangeInclusive<usize>, usage: &str| {
                if n.contains(&args.len()) {
                    Ok(())
                } else {
                    Err(err(format!("usage: {usage}")))
                }
            };
            let lower = verb.to_ascii_lowercase();
            let command = match lower.as_str() {
                "set" => {
                    want(2..=2, "set ADDR[:N] VALUE")?;
                    let t = target(args[0], profile).map_err(err)?;
                    let v = integer(args[1]).map_err(err)?;
                    fits(&t, v).map_err(err)?;
                    Command::Set(t, v)
                }
                "setf" => {
                    want(2..=2, "setf ADDR VALUE")?;
                    let t = target(args[0], profile).map_err(err)?;
                    if t.address.bit.is_some() || t.address.area.element_bytes() != 4 {
                        return Err(err(format!(
                            "setf needs a 4-byte address (D, T, C, DT, DC), not {}",
                            t.address
                        )));
                    }
                    Command::SetReal(t.address, real(args[1]).map_err(err)?)
                }
                "force" => {
                    want(2..=2, "force ADDR VALUE")?;
                    let t = target(args[0], profile).map_err(err)?;
                    let v = integer(args[1]).map_err(err)?;
                    fits(&t, v).map_err(err)?;
                    Command::Force(t.address, v)
                }
                "unforce" => {
                    want(1..=1, "unforce ADDR")?;
                    Command::Unforce(target(args[0], profile).map_err(err)?.address)
                }
                "scan" => {
                    want(0..=1, "scan [N]")?;
                    let n = match args.first() {
                        Some(n) => n
                            .parse::<u64>()
                            .ok()
                            .filter(|n| *n <= 100_000_000)
                            .ok_or_else(|| err(format!("`{n}` is not a number of scans")))?,
                        None => 1,
                    };
                    Command::Scan(n)
                }
                "run" => {
                    want(1..=1, "run DURATION")?;
                    Command::Scan(duration(args[0]).map_err(err)?)
                }
                "expect" => {
                    want(2..=2, "expect ADDR[:N] VALUE")?;
                    let t = target(args[0], profile).map_err(err)?;
                    let v = integer(args[1]).map_err(err)?;
                    fits(&t, v).map_err(err)?;
                    Command::Expect(t, v)
                }
                "expectf" => {
                    want(2..=3, "expectf ADDR VALUE [TOL]")?;
                    let t = target(args[0], profile).map_err(err)?;
                    if t.address.bit.is_some() || t.address.area.element_bytes() != 4 {
                        return Err(err(format!(
                            "expectf needs a 4-byte address (D, T, C, DT, DC), not {}",
                            t.address
                        )));
                    }
                    let tol = match args.get(2) {
                        Some(t) => Some(real(t).map_err(err)?),
                        None => None,
                    };
                    Command::ExpectReal(t.address, real(args[1]).map_err(err)?, tol)
                }
                "print" => {
                    want(1..=1, "print ADDR[:N]")?;
                    Command::Print(target(args[0], profile).map_err(err)?)
                }
                "watch" => {
                    want(1..=1, "watch ADDR[:N]")?;
                    Command::Watch(target(args[0], profile).map_err(err)?)
                }
                "division" => {
                    want(1..=1, "division N")?;
                    let n = args[0]
                        .parse::<u32>()
                        .ok()
                        .filter(|n| (1..=1000).contains(n))
                        .ok_or_else(|| {
                            err(format!("`{}`: the division is a number 1–1000", args[0]))
                        })?;
                    Command::Division(n)
                }
                "power-cycle" => {
                    want(0..=0, "power-cycle")?;
                    Command::PowerCycle
                }
                _ => {
                    let prefix: String = lower.chars().take(3).collect();
                    let near = COMMANDS
                        .iter()
                        .find(|c| c.starts_with(&prefix))
                        .map(|c| format!("; did you mean `{c}`?"))
                        .unwrap_or_default();
                    return Err(err(format!(
                        "unknown command `{verb}`{near} (commands: {})",
                        COMMANDS.join(", ")
                    )));
                }
            };
            commands.push((line, command));
        }
        Ok(Script { commands })
    }
}

/// What running a script produced.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Outcome {
    /// Lines to print (expect failures, `print`s, halts), in order.
    pub output: Vec<String>,
    /// `expect`/`expectf` that held.
    pub passed: usize,
    /// `expect`/`expectf` that did not.
    pub failed: usize,
    /// The trace as CSV (header and one row per tick), when anything was watched.
    pub trace_csv: String,
}

fn masked(v: i64, bytes: u32) -> u64 {
    if bytes >= 8 {
        v as u64
    } else {
        (v as u64) & ((1u64 << (8 * bytes)) - 1)
    }
}

fn value(vm: &Vm, t: &Target) -> i64 {
    vm.read(t.address, t.bytes)
}

/// Runs a parsed script. `name` prefixes failure lines (`SCRIPT:LINE: expect …`).
pub fn run(vm: &mut Vm, script: &Script, name: &str) -> Outcome {
    let mut out = Outcome::default();
    let mut watched: Vec<Target> = Vec::new();
    let mut reported_halt = false;
    for (line, command) in &script.commands {
        match command {
            Command::Set(t, v) => vm.write(t.address, t.bytes, *v),
            Command::SetReal(a, v) => vm.write_real(*a, *v),
            Command::Force(a, v) => vm.force(*a, *v),
            Command::Unforce(a) => vm.unforce(*a),
            Command::Division(n) => vm.set_division(*n),
            Command::PowerCycle => {
                vm.power_cycle();
                reported_halt = false;
            }
            Command::Watch(t) => {
                if !watched.contains(t) {
                    watched.push(*t);
                }
            }
            Command::Scan(n) => {
                for _ in 0..*n {
                    vm.tick();
                    if !watched.is_empty() {
                        if out.trace_csv.is_empty() {
                            out.trace_csv.push_str("tick,ms");
                            for t in &watched {
                                let _ = write!(out.trace_csv, ",{}", t.text());
                            }
                            out.trace_csv.push('\n');
                        }
                        let _ = write!(out.trace_csv, "{},{}", vm.ticks(), vm.now_ms());
                        for t in &watched {
                            let _ = write!(out.trace_csv, ",{}", value(vm, t));
                        }
                        out.trace_csv.push('\n');
                    }
                    if let Some(h) = vm.halt()
                        && !reported_halt
                    {
                        out.output.push(format!("{name}:{line}: PLC halted at {h}"));
                        reported_halt = true;
                    }
                    if vm.halt().is_some() {
                        // Nothing changes while halted: skip the remaining ticks' work.
                        continue;
                    }
                }
            }
            Command::Print(t) => {
                out.output.push(format!("{} = {}", t.text(), value(vm, t)));
            }
            Command::Expect(t, want) => {
                let got = value(vm, t);
                if masked(got, t.bytes) == masked(*want, t.bytes) {
                    out.passed += 1;
                } else {
                    // Show the value the way the expectation was written.
                    let shown = if *want >= 0 {
                        masked(got, t.bytes).to_string()
                    } else {
                        got.to_string()
                    };
                    out.output.push(format!(
                        "{name}:{line}: expect {} = {want}, got {shown}",
                        t.text()
                    ));
                    out.failed += 1;
                }
            }
            Command::ExpectReal(a, want, tol) => {
                let got = vm.read_real(*a);
                let tol = tol.unwrap_or(1e-4);
                let ok = if *want == 0.0 {
                    got.abs() <= tol
                } else {
                    ((got - want) / want).abs() <= tol
                };
                if ok && !got.is_nan() {
                    out.passed += 1;
                } else {
                    out.output
                        .push(format!("{name}:{line}: expect {a} = {want}, got {got}"));
                    out.failed += 1;
                }
            }
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::profile::ProfileId;

    fn parse(text: &str) -> Result<Script, ScriptError> {
        Script::parse(text, Profile::get(ProfileId::Gsk988ta))
    }

    #[test]
    fn errors_name_the_line() {
        let e = parse("scan\n\nset R0000 256\n").unwrap_err();
        assert_eq!(e.line, 3);
        assert!(
            e.message.contains("256 does not fit R0000"),
            "{}",
            e.message
        );
        let e = parse("# comment\nsett X1.0 1").unwrap_err();
        assert_eq!(e.line, 2);
        assert!(e.message.contains("did you mean `set`"), "{}", e.message);
        assert!(
            parse("set R1000 1")
                .unwrap_err()
                .message
                .contains("R0–R999")
        );
        assert!(parse("set X1.0 2").is_err());
        assert!(parse("run 2x").is_err());
        assert!(parse("expect D1:3 0").is_err());
        assert!(parse("setf R1 1.5").is_err());
    }

    #[test]
    fn durations_round_up_to_ticks() {
        let s = parse("run 250ms\nrun 2s\nrun 9\nscan 3 ; three\nrun 0").unwrap();
        let ticks: Vec<u64> = s
            .commands
            .iter()
            .map(|(_, c)| match c {
                Command::Scan(n) => *n,
                _ => 0,
            })
            .collect();
        assert_eq!(ticks, vec![32, 250, 2, 3, 0]);
    }

    #[test]
    fn both_spellings_of_a_byte_match() {
        assert_eq!(masked(255, 1), masked(-1, 1));
        assert_ne!(masked(255, 2), masked(-1, 2));
    }
}
