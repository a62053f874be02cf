//! Target profiles: the address ranges of one controller's PLC.
//!
//! Ranges are data, not code, so that a second controller (the GSK980 series) is a new table
//! rather than new branches through the compiler and the VM.

use crate::area::Area;
use serde::{Deserialize, Serialize};

/// Which controller a project is written for.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum ProfileId {
    /// GSK988TA lathe controller, PLC-N5 (the manual in the references).
    #[default]
    Gsk988ta,
    /// GSK980 series.
    Gsk980,
}

/// The address ranges of one target PLC.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Profile {
    /// Which profile this is.
    pub id: ProfileId,
    /// Name shown to the user.
    pub name: &'static str,
    /// Inclusive `(first, last)` address number per area, indexed by [`Area::index`].
    ranges: [(u16, u16); Area::COUNT],
    /// Most steps level 1 may have (subprograms it calls included).
    pub level1_step_limit: u32,
    /// Most steps the whole program may have.
    pub program_step_limit: u32,
}

impl Profile {
    /// The profile with this id.
    pub fn get(id: ProfileId) -> &'static Profile {
        match id {
            ProfileId::Gsk988ta => &GSK988TA,
            ProfileId::Gsk980 => &GSK980,
        }
    }

    /// Inclusive range of address numbers of an area.
    pub fn range(&self, area: Area) -> (u16, u16) {
        self.ranges[area.index()]
    }

    /// Whether `number` is a valid address number of `area`.
    pub fn contains(&self, area: Area, number: u32) -> bool {
        let (lo, hi) = self.range(area);
        number >= u32::from(lo) && number <= u32::from(hi)
    }
}

// Order of `Area::ALL`: X Y F G R A K T C DT DC D L P.
static GSK988TA: Profile = Profile {
    id: ProfileId::Gsk988ta,
    name: "GSK988TA",
    ranges: [
        (0, 127),
        (0, 127),
        (0, 511),
        (0, 511),
        (0, 999),
        (0, 49),
        (0, 39),
        (0, 199),
        (0, 199),
        (0, 199),
        (0, 199),
        (0, 999),
        (1, 9999),
        (1, 9999),
    ],
    level1_step_limit: 600,
    program_step_limit: 5000,
};

// The GSK980TDc/TDi PLC ranges as published for that series. The 980 PLC manual is not among
// the project's references yet, so these figures are to be confirmed against it when it is.
static GSK980: Profile = Profile {
    id: ProfileId::Gsk980,
    name: "GSK980",
    ranges: [
        (0, 29),
        (0, 19),
        (0, 255),
        (0, 255),
        (0, 999),
        (0, 24),
        (0, 39),
        (0, 127),
        (0, 127),
        (0, 127),
        (0, 127),
        (0, 999),
        (1, 9999),
        (1, 9999),
    ],
    level1_step_limit: 600,
    program_step_limit: 5000,
};
