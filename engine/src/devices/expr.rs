//! Device conditions (docs/machine.md, "Expressions"): `Y0000.6 & !X0001.6`,
//! `chuck.advanced | (Y0002.0 AND NOT door.moving)`. Read once into postfix terms; the tick
//! evaluates them on a bit stack without allocating.

use crate::address::{Address, AddressError};
use crate::profile::Profile;
use std::fmt;

/// One postfix term of a condition.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Term {
    /// A bit address.
    Bit(Address),
    /// A device state: device index, state index in [`super::DeviceKind::states`].
    State(usize, usize),
    /// 0 or 1.
    Const(bool),
    /// Negates the top.
    Not,
    /// Ands the top two.
    And,
    /// Ors the top two.
    Or,
}

/// Why a condition was refused.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub enum ExprError {
    /// Something where a term or operator was expected.
    Unexpected {
        /// Character position, from 1.
        at: usize,
        /// What was found (empty at the end).
        found: String,
    },
    /// A `(` without its `)`.
    Unclosed,
    /// An address that does not read or is not a bit in range.
    Address(AddressError),
    /// A byte address where a bit is needed.
    NotBit(Address),
    /// `NAME.state` naming no device.
    UnknownDevice(String),
    /// A device without that state.
    UnknownState {
        /// The device.
        device: String,
        /// The state asked for.
        state: String,
        /// The states it has.
        states: &'static [&'static str],
    },
    /// A device state in a follower (which reads addresses only).
    StateInFollower(String),
    /// The deepest nesting exceeds what the evaluator holds.
    TooDeep,
}

impl fmt::Display for ExprError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ExprError::Unexpected { at, found } if found.is_empty() => write!(
                f,
                "the condition ends at character {at} where an address, NAME.state, 0, 1, ! or ( must follow"
            ),
            ExprError::Unexpected { at, found } => write!(
                f,
                "`{found}` at character {at} is not expected here (write e.g. Y0000.6 & !X0001.6, chuck.advanced | door.moving)"
            ),
            ExprError::Unclosed => write!(f, "a `(` is not closed: add `)`"),
            ExprError::Address(e) => write!(f, "{e}"),
            ExprError::NotBit(a) => write!(f, "{a} is a byte: a condition reads bits (e.g. {a}.0)"),
            ExprError::UnknownDevice(d) => {
                write!(
                    f,
                    "no device is named `{d}`: use a device name of this machine"
                )
            }
            ExprError::UnknownState {
                device,
                state,
                states,
            } => write!(
                f,
                "device `{device}` has no state `{state}`; its states: {}",
                states.join(", ")
            ),
            ExprError::StateInFollower(s) => write!(
                f,
                "`{s}`: a follower reads addresses only; make it an expression device to read device states"
            ),
            ExprError::TooDeep => write!(
                f,
                "the condition nests too deep (60 parentheses, 64 values pending at most): split it over an expression device"
            ),
        }
    }
}

/// What a condition may name besides addresses.
pub struct Names<'a> {
    /// Each device's name and states, by index.
    pub devices: &'a [(&'a str, &'static [&'static str])],
    /// Whether device states are allowed (expression devices) or refused (followers).
    pub states: bool,
}

/// Reads a condition into postfix terms. An empty text is `1` (always).
pub fn parse(text: &str, profile: &Profile, names: &Names) -> Result<Vec<Term>, ExprError> {
    let tokens = tokens(text);
    if tokens.is_empty() {
        return Ok(vec![Term::Const(true)]);
    }
    let mut p = Parser {
        tokens: &tokens,
        at: 0,
        out: Vec::new(),
        profile,
        names,
        depth: 0,
        end: text.chars().count() + 1,
    };
    p.or()?;
    if let Some((pos, t)) = tokens.get(p.at) {
        return Err(ExprError::Unexpected {
            at: *pos,
            found: t.clone(),
        });
    }
    // The evaluator's stack is one u64: a condition that would hold more than 64 pending
    // values at once is refused rather than evaluated wrong.
    let mut depth = 0usize;
    for t in &p.out {
        match t {
            Term::Bit(_) | Term::State(..) | Term::Const(_) => depth += 1,
            Term::And | Term::Or => depth -= 1,
            Term::Not => {}
        }
        if depth > 64 {
            return Err(ExprError::TooDeep);
        }
    }
    Ok(p.out)
}

/// Splits into tokens with their 1-based character positions.
fn tokens(text: &str) -> Vec<(usize, String)> {
    let mut out = Vec::new();
    let chars: Vec<char> = text.chars().collect();
    let mut i = 0;
    while i < chars.len() {
        let c = chars[i];
        if c.is_whitespace() {
            i += 1;
        } else if c.is_alphanumeric() || c == '_' || c == '.' {
            let start = i;
            while i < chars.len() && (chars[i].is_alphanumeric() || "_.".contains(chars[i])) {
                i += 1;
            }
            out.push((start + 1, chars[start..i].iter().collect()));
        } else {
            out.push((i + 1, c.to_string()));
            i += 1;
        }
    }
    out
}

struct Parser<'a> {
    tokens: &'a [(usize, String)],
    at: usize,
    out: Vec<Term>,
    profile: &'a Profile,
    names: &'a Names<'a>,
    depth: usize,
    end: usize,
}

impl Parser<'_> {
    fn peek(&self) -> Option<&str> {
        self.tokens.get(self.at).map(|(_, t)| t.as_str())
    }

    fn is(&self, words: &[&str]) -> bool {
        self.peek()
            .is_some_and(|t| words.iter().any(|w| t.eq_ignore_ascii_case(w)))
    }

    fn or(&mut self) -> Result<(), ExprError> {
        self.and()?;
        while self.is(&["|", "OR"]) {
            self.at += 1;
            self.and()?;
            self.out.push(Term::Or);
        }
        Ok(())
    }

    fn and(&mut self) -> Result<(), ExprError> {
        self.factor()?;
        while self.is(&["&", "AND"]) {
            self.at += 1;
            self.factor()?;
            self.out.push(Term::And);
        }
        Ok(())
    }

    fn factor(&mut self) -> Result<(), ExprError> {
        self.depth += 1;
        if self.depth > 60 {
            return Err(ExprError::TooDeep);
        }
        let Some((pos, tok)) = self.tokens.get(self.at).cloned() else {
            return Err(ExprError::Unexpected {
                at: self.end,
                found: String::new(),
            });
        };
        self.at += 1;
        if tok == "!" || tok.eq_ignore_ascii_case("NOT") {
            self.factor()?;
            self.out.push(Term::Not);
        } else if tok == "(" {
            self.or()?;
            match self.tokens.get(self.at) {
                Some((_, t)) if t == ")" => {}
                Some((pos, t)) => {
                    return Err(ExprError::Unexpected {
                        at: *pos,
                        found: t.clone(),
                    });
                }
                None => return Err(ExprError::Unclosed),
            }
            self.at += 1;
        } else if tok == "0" || tok == "1" {
            self.out.push(Term::Const(tok == "1"));
        } else if tok.starts_with(|c: char| c.is_alphabetic()) {
            let term = self.name(&tok)?;
            self.out.push(term);
        } else {
            return Err(ExprError::Unexpected {
                at: pos,
                found: tok,
            });
        }
        self.depth -= 1;
        Ok(())
    }

    /// An address, or `device.state`.
    fn name(&self, tok: &str) -> Result<Term, ExprError> {
        let parsed = Address::parse(tok);
        if let Ok(a) = parsed {
            a.check_range(self.profile).map_err(ExprError::Address)?;
            if a.bit.is_none() {
                return Err(ExprError::NotBit(a));
            }
            return Ok(Term::Bit(a));
        }
        let Some((device, state)) = tok.split_once('.') else {
            return Err(parsed.map_or_else(ExprError::Address, |_| ExprError::Unclosed));
        };
        let Some(d) = self
            .names
            .devices
            .iter()
            .position(|(n, _)| n.eq_ignore_ascii_case(device))
        else {
            // `X0001.9` and the like: say what is wrong with the address.
            if let Err(e) = parsed
                && !matches!(e, AddressError::UnknownArea(..) | AddressError::Syntax(_))
            {
                return Err(ExprError::Address(e));
            }
            return Err(ExprError::UnknownDevice(device.to_string()));
        };
        if !self.names.states {
            return Err(ExprError::StateInFollower(tok.to_string()));
        }
        let states = self.names.devices[d].1;
        let s = states
            .iter()
            .position(|s| s.eq_ignore_ascii_case(state))
            .ok_or_else(|| ExprError::UnknownState {
                device: device.to_string(),
                state: state.to_string(),
                states,
            })?;
        Ok(Term::State(d, s))
    }
}

/// Evaluates postfix terms; `bit` reads an address term, `state` a device state.
pub fn eval(
    terms: &[super::resolved::Resolved],
    bit: impl Fn(u32, u8) -> bool,
    state: impl Fn(u32) -> bool,
) -> bool {
    use super::resolved::Resolved;
    // A bit stack: bit 0 is the top.
    let mut stack: u64 = 0;
    for t in terms {
        match *t {
            Resolved::Bit(off, mask) => stack = stack << 1 | u64::from(bit(off, mask)),
            Resolved::State(k) => stack = stack << 1 | u64::from(state(k)),
            Resolved::Const(v) => stack = stack << 1 | u64::from(v),
            Resolved::Not => stack ^= 1,
            Resolved::And => stack = (stack >> 1) & (stack | !1),
            Resolved::Or => stack = (stack >> 1) | (stack & 1),
        }
    }
    stack & 1 == 1
}
