//! Saved scenarios (docs/scenarios.md): a named set of writes, forces, operator-panel states
//! and machine-device faults, kept in the project, applied in one step and released in one
//! step, the release putting back exactly what the application changed.
//!
//! A scenario is kept as lines in the stimulus-script syntax (`force X0002.1 1`, `device
//! chuck fault stuck 0`, `panel "Feed override" 50%`), so the page, the file and a script read
//! it alike; [`crate::sim::scenario`] turns the lines into [`ScenarioAction`]s against a project, and
//! the machine ([`crate::machine::Machine`]) applies them and remembers how to undo each.

use crate::address::{Address, Target};
use crate::devices::Fault;
use serde::{Deserialize, Serialize};

/// The longest scenario name.
pub const NAME_MAX: usize = 32;

/// One saved scenario.
#[derive(Clone, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub struct Scenario {
    /// Its name: letters, digits, `_` and `-`, unique in the project (a script names it).
    pub name: String,
    /// What it sets up, for the reader.
    #[serde(default, skip_serializing_if = "String::is_empty")]
    pub note: String,
    /// Its lines, in the script syntax: `set`, `force`, `panel` and `device … fault`.
    #[serde(default)]
    pub lines: Vec<String>,
}

/// What one line of a scenario does, resolved against a project.
#[derive(Clone, Debug, PartialEq)]
pub enum ScenarioAction {
    /// Write a value once (`set`).
    Write(Target, i64),
    /// Hold a bit or an address at a value (`force`).
    Force(Address, i64),
    /// Put a panel knob at a position: only the knob's bits of its byte change.
    Knob {
        /// The X byte.
        input: Address,
        /// The knob's bits.
        mask: u8,
        /// The position's value.
        value: i64,
    },
    /// Inject a fault into a device of the machine model, by index.
    Fault(usize, Fault),
}

/// A scenario resolved and ready to apply: its name and actions.
#[derive(Clone, Debug, PartialEq)]
pub struct Applied {
    /// The scenario's name.
    pub name: String,
    /// Its actions, in line order.
    pub actions: Vec<ScenarioAction>,
}

/// The force state of the (up to 4) bytes of an address: per byte, the forced bits and their
/// values, so a release puts back a force that was there before, not just none.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct ForceState {
    /// (mask, values) per byte.
    pub bytes: [(u8, u8); 4],
}

/// How to undo one action.
#[derive(Clone, Debug, PartialEq)]
pub enum Undo {
    /// Write this value back.
    Write(Target, i64),
    /// Put a knob's bits of its byte back (the byte's other bits are left as they are).
    Knob {
        /// The X byte.
        input: Address,
        /// The knob's bits.
        mask: u8,
        /// The byte as it was.
        old: i64,
    },
    /// Put the forces of this address back as they were, then its value.
    Force(Address, ForceState, Target, i64),
    /// Put the device's fault back (`None`: no fault), by the device's name: the model may
    /// have been edited online in between.
    Fault(String, Option<Fault>),
}

impl Undo {
    /// Whether undoing this and undoing `other` act on the same thing (a byte of memory, a
    /// device), so their order matters.
    pub fn overlaps(&self, other: &Undo) -> bool {
        match (self.place(), other.place()) {
            (Place::Bytes(a, x0, x1), Place::Bytes(b, y0, y1)) => a == b && x0 < y1 && y0 < x1,
            (Place::Device(a), Place::Device(b)) => a.eq_ignore_ascii_case(b),
            _ => false,
        }
    }

    fn place(&self) -> Place<'_> {
        let bytes = |a: &Address, n: u32| {
            let first = u32::from(a.number);
            Place::Bytes(a.area, first, first + n.max(1))
        };
        match self {
            Undo::Write(t, _) => bytes(
                &t.address,
                if t.address.bit.is_some() { 1 } else { t.bytes },
            ),
            Undo::Knob { input, .. } => bytes(input, 1),
            Undo::Force(a, ..) => bytes(a, 1),
            Undo::Fault(name, _) => Place::Device(name),
        }
    }
}

/// What an undo acts on: an area's elements `[from, to)`, or a device.
enum Place<'a> {
    Bytes(crate::address::Area, u32, u32),
    Device(&'a str),
}

/// Why a scenario's name cannot be used.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub enum NameError {
    /// No name.
    Empty,
    /// Longer than [`NAME_MAX`], or with a character other than a letter, a digit, `_`, `-`.
    Malformed {
        /// The name.
        name: String,
    },
    /// The name of another scenario (letter case aside).
    Taken {
        /// The name.
        name: String,
    },
}

/// Why a scenario's name cannot be used, or `None`.
pub fn name_error(name: &str, others: &[Scenario], own: Option<usize>) -> Option<NameError> {
    if name.is_empty() {
        return Some(NameError::Empty);
    }
    if name.chars().count() > NAME_MAX
        || !name
            .chars()
            .all(|c| c.is_alphanumeric() || c == '_' || c == '-')
    {
        return Some(NameError::Malformed { name: name.into() });
    }
    let taken = others
        .iter()
        .enumerate()
        .any(|(k, s)| Some(k) != own && s.name.eq_ignore_ascii_case(name));
    taken.then(|| NameError::Taken { name: name.into() })
}
