//! The project: target profile, ladder, and every table of manual §3.4.

use super::ladder::Ladder;
use super::panel::Panel;
use super::tables::{
    AddressRow, BLOCK_SYMBOLS, DataTables, MCodeRow, MessageTable, Symbol, SymbolTable, VersionInfo,
};
use crate::address::Address;
use crate::devices::MachineModel;
use crate::profile::{Profile, ProfileId};
use serde::{Deserialize, Serialize};
use std::collections::HashMap;

/// A whole project: what a `.ldp` file holds. Unknown fields are refused, so that a body of
/// another schema is never half read (docs/files.md, "Project files (.ldp)").
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Project {
    /// The target controller.
    pub profile: ProfileId,
    /// Level-2 division count n (docs/plc.md, "Level-2 slices": a project setting, default 1).
    pub level2_division: u32,
    /// The ladder program.
    pub ladder: Ladder,
    /// User symbol tables. The block-symbol table is derived from the subprograms.
    #[serde(default)]
    pub symbol_tables: Vec<SymbolTable>,
    /// K page and D, D_FLOAT, DT, DC tables.
    #[serde(default)]
    pub data: DataTables,
    /// The display-message (PLC alarm) table.
    #[serde(default)]
    pub messages: MessageTable,
    /// The diagnosis table.
    #[serde(default)]
    pub diagnosis: Vec<AddressRow>,
    /// The permission table.
    #[serde(default)]
    pub permissions: Vec<AddressRow>,
    /// The M-code comment table.
    #[serde(default)]
    pub m_codes: Vec<MCodeRow>,
    /// Version information.
    #[serde(default)]
    pub version: VersionInfo,
    /// The operator panel of the online monitor; empty means the profile's preset, and is
    /// not written, so a project that never customised it saves as it did before.
    #[serde(default, skip_serializing_if = "Panel::is_empty")]
    pub panel: Panel,
    /// The machine around the CNC (docs/machine.md); empty means none, and is not written,
    /// so a project without one saves as before it existed (schema 3).
    #[serde(default, skip_serializing_if = "MachineModel::is_empty")]
    pub machine: MachineModel,
    /// The saved scenarios (docs/scenarios.md); written only when there is one, so a project
    /// without keeps its bytes.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub scenarios: Vec<crate::scenario::Scenario>,
}

impl Default for Project {
    fn default() -> Self {
        Project {
            profile: ProfileId::default(),
            level2_division: 1,
            ladder: Ladder::default(),
            symbol_tables: vec![SymbolTable {
                name: "符号表1".into(),
                rows: Vec::new(),
            }],
            data: DataTables::default(),
            messages: MessageTable::default(),
            diagnosis: Vec::new(),
            permissions: Vec::new(),
            m_codes: Vec::new(),
            version: VersionInfo::default(),
            panel: Panel::default(),
            machine: MachineModel::default(),
            scenarios: Vec::new(),
        }
    }
}

/// Symbol names to addresses, built once for a compile or a cross-reference.
#[derive(Clone, Debug, Default)]
pub struct SymbolIndex {
    by_name: HashMap<String, Address>,
}

impl SymbolIndex {
    /// The address a name stands for.
    pub fn get(&self, name: &str) -> Option<Address> {
        self.by_name.get(name).copied()
    }
}

impl Project {
    /// The target profile's ranges.
    pub fn profile(&self) -> &'static Profile {
        Profile::get(self.profile)
    }

    /// Every user symbol row, table by table.
    pub fn symbols(&self) -> impl Iterator<Item = &Symbol> {
        self.symbol_tables.iter().flat_map(|t| &t.rows)
    }

    /// The block-symbol table: each subprogram's name as a symbol of its P number.
    pub fn block_symbols(&self) -> SymbolTable {
        SymbolTable {
            name: BLOCK_SYMBOLS.into(),
            rows: self
                .ladder
                .blocks
                .iter()
                .filter_map(|b| match &b.kind {
                    super::BlockKind::Sub { number, name } if !name.is_empty() => Some(Symbol {
                        name: name.clone(),
                        address: Address::byte(crate::address::Area::P, *number),
                        comments: Default::default(),
                    }),
                    _ => None,
                })
                .collect(),
        }
    }

    /// Names to addresses: user symbols (the first definition of a name wins) and the
    /// block symbols.
    pub fn symbol_index(&self) -> SymbolIndex {
        let mut by_name = HashMap::new();
        for s in self.symbols().chain(self.block_symbols().rows.iter()) {
            if !s.name.is_empty() {
                by_name.entry(s.name.clone()).or_insert(s.address);
            }
        }
        SymbolIndex { by_name }
    }

    /// The address a symbol name stands for.
    pub fn resolve_symbol(&self, name: &str) -> Option<Address> {
        self.symbols()
            .find(|s| !s.name.is_empty() && s.name == name)
            .map(|s| s.address)
            .or_else(|| {
                self.block_symbols()
                    .rows
                    .into_iter()
                    .find(|s| s.name == name)
                    .map(|s| s.address)
            })
    }

    /// The comment of an address in a language (`zh`, `en`), else in any language it has.
    pub fn comment_of(&self, address: Address, lang: &str) -> Option<&str> {
        let row = self
            .symbols()
            .find(|s| s.address == address && !s.comments.is_empty())?;
        row.comments
            .get(lang)
            .or_else(|| row.comments.values().next())
            .map(String::as_str)
            .filter(|c| !c.is_empty())
    }

    /// The operator panel to show: the project's own, or its profile's preset when it has
    /// none.
    pub fn operator_panel(&self) -> std::borrow::Cow<'_, Panel> {
        if self.panel.is_empty() {
            std::borrow::Cow::Owned(Panel::preset(self.profile))
        } else {
            std::borrow::Cow::Borrowed(&self.panel)
        }
    }

    /// The symbol name of an address, if it has one.
    pub fn symbol_of(&self, address: Address) -> Option<&str> {
        self.symbols()
            .find(|s| s.address == address && !s.name.is_empty())
            .map(|s| s.name.as_str())
    }
}
