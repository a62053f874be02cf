//! The project: target profile, ladder, symbols and scan settings.

use super::ladder::Ladder;
use crate::address::Address;
use crate::profile::{Profile, ProfileId};
use serde::{Deserialize, Serialize};

/// One row of a symbol table: an address with an optional name and a comment.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Symbol {
    /// The symbol's name; empty for an address that carries only a comment.
    pub name: String,
    /// The address it stands for.
    pub address: Address,
    /// Comment.
    #[serde(default)]
    pub comment: String,
}

/// A whole project.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Project {
    /// The target controller.
    pub profile: ProfileId,
    /// Level-2 division count n (§5: a project setting, default 1).
    pub level2_division: u32,
    /// The ladder program.
    pub ladder: Ladder,
    /// The symbol table.
    #[serde(default)]
    pub symbols: Vec<Symbol>,
}

impl Default for Project {
    fn default() -> Self {
        Project {
            profile: ProfileId::default(),
            level2_division: 1,
            ladder: Ladder::default(),
            symbols: Vec::new(),
        }
    }
}

impl Project {
    /// The target profile's ranges.
    pub fn profile(&self) -> &'static Profile {
        Profile::get(self.profile)
    }

    /// The address a symbol name stands for.
    pub fn resolve_symbol(&self, name: &str) -> Option<Address> {
        self.symbols
            .iter()
            .find(|s| !s.name.is_empty() && s.name == name)
            .map(|s| s.address)
    }

    /// The symbol name of an address, if it has one.
    pub fn symbol_of(&self, address: Address) -> Option<&str> {
        self.symbols
            .iter()
            .find(|s| s.address == address && !s.name.is_empty())
            .map(|s| s.name.as_str())
    }
}
