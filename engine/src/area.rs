//! PLC memory areas (X, Y, F, G, R, …) and sets of them: what an address names before its
//! number, and what a profile gives a range to. Kept apart from addresses so that profiles,
//! which addresses are checked against, need nothing of addresses themselves.

use serde::{Deserialize, Serialize};
use std::fmt;

/// A PLC memory area.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord, Serialize, Deserialize)]
pub enum Area {
    /// Machine → PLC inputs.
    X,
    /// PLC → machine outputs.
    Y,
    /// CNC → PLC signals.
    F,
    /// PLC → CNC signals.
    G,
    /// Internal relays.
    R,
    /// Message (alarm) requests.
    A,
    /// Keep relays.
    K,
    /// Timer values.
    T,
    /// Counter values.
    C,
    /// Timer presets.
    Dt,
    /// Counter presets.
    Dc,
    /// Data registers.
    D,
    /// Jump labels.
    L,
    /// Subprogram numbers.
    P,
}

impl Area {
    /// Number of areas.
    pub const COUNT: usize = 14;
    /// Every area, in table order.
    pub const ALL: [Area; Area::COUNT] = [
        Area::X,
        Area::Y,
        Area::F,
        Area::G,
        Area::R,
        Area::A,
        Area::K,
        Area::T,
        Area::C,
        Area::Dt,
        Area::Dc,
        Area::D,
        Area::L,
        Area::P,
    ];

    /// Position in [`Area::ALL`].
    pub fn index(self) -> usize {
        self as usize
    }

    /// The area's letters as written in addresses.
    pub fn letters(self) -> &'static str {
        match self {
            Area::X => "X",
            Area::Y => "Y",
            Area::F => "F",
            Area::G => "G",
            Area::R => "R",
            Area::A => "A",
            Area::K => "K",
            Area::T => "T",
            Area::C => "C",
            Area::Dt => "DT",
            Area::Dc => "DC",
            Area::D => "D",
            Area::L => "L",
            Area::P => "P",
        }
    }

    /// The area for a spelling of its letters (any case).
    pub fn from_letters(s: &str) -> Option<Area> {
        Area::ALL
            .into_iter()
            .find(|a| a.letters().eq_ignore_ascii_case(s))
    }

    /// Bytes per address: 1 for the relay areas, 4 for T C DT DC D, 0 for labels and subprograms.
    pub fn element_bytes(self) -> u8 {
        match self {
            Area::X | Area::Y | Area::F | Area::G | Area::R | Area::A | Area::K => 1,
            Area::T | Area::C | Area::Dt | Area::Dc | Area::D => 4,
            Area::L | Area::P => 0,
        }
    }

    /// Whether the area has bit addresses (`R0002.0`).
    pub fn has_bits(self) -> bool {
        self.element_bytes() == 1
    }

    /// Whether the program may write the area (X and F are read-only, §1.2.1, §1.2.3).
    pub fn writable(self) -> bool {
        !matches!(self, Area::X | Area::F | Area::L | Area::P)
    }

    /// Whether the area keeps its value across a power cycle.
    pub fn retained(self) -> bool {
        matches!(
            self,
            Area::K | Area::T | Area::C | Area::Dt | Area::Dc | Area::D
        )
    }
}

impl fmt::Display for Area {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.letters())
    }
}

/// A set of areas, as allowed for one operand.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Default)]
pub struct AreaSet(u16);

impl AreaSet {
    /// The empty set.
    pub const EMPTY: AreaSet = AreaSet(0);

    /// Every memory area: every area but labels (L) and subprogram numbers (P), which hold
    /// no value to read or write.
    pub const MEMORY: AreaSet = AreaSet::of(&[
        Area::X,
        Area::Y,
        Area::F,
        Area::G,
        Area::R,
        Area::A,
        Area::K,
        Area::T,
        Area::C,
        Area::Dt,
        Area::Dc,
        Area::D,
    ]);

    /// A set of the given areas.
    pub const fn of(areas: &[Area]) -> AreaSet {
        let mut bits = 0u16;
        let mut i = 0;
        while i < areas.len() {
            bits |= 1 << areas[i] as u16;
            i += 1;
        }
        AreaSet(bits)
    }

    /// Whether `area` is in the set.
    pub fn contains(self, area: Area) -> bool {
        self.0 & (1 << area as u16) != 0
    }

    /// The areas of the set in table order.
    pub fn iter(self) -> impl Iterator<Item = Area> {
        Area::ALL.into_iter().filter(move |a| self.contains(*a))
    }

    /// The set as text for messages: `Y G R K A`.
    pub fn describe(self) -> String {
        self.iter().map(Area::letters).collect::<Vec<_>>().join(" ")
    }
}
