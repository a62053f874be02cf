//! The virtual machine operator panel: the keys, switches, lamps and selector knobs an
//! online monitor draws so that a user can drive the simulated machine as an operator drives
//! a real one. The panel is plain data saved with the project; which bit a key writes and
//! which lamp it lights are the project's wiring, so they live here and not in the editor.
//!
//! An empty panel means "the preset of the profile" ([`Panel::preset`]): a project that never
//! customised its panel is saved exactly as before the panel existed.

use crate::address::{Address, AddressError, Area};
use crate::profile::{Profile, ProfileId};
use serde::{Deserialize, Serialize};
use thiserror::Error;

/// An operator panel: its items on a grid.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct Panel {
    /// The items, in the order they were added (the grid position decides where they show).
    pub items: Vec<PanelItem>,
}

/// One key, switch, lamp or knob of the panel.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct PanelItem {
    /// The Chinese label, as the panel prints it.
    pub label_zh: String,
    /// The English label.
    pub label_en: String,
    /// What it is and which addresses it is wired to.
    pub kind: PanelKind,
    /// Grid row, 0 at the top.
    pub row: u8,
    /// Grid column, 0 at the left.
    pub col: u8,
    /// What a switch (0/1) or a knob (its position's value) reads when the machine starts:
    /// a released E-stop and closed limit switches read 1, so a simulated machine starts
    /// ready to run, as a real one does when it is wired right.
    #[serde(default)]
    pub initial: i64,
}

/// What a panel item is and how it is wired.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub enum PanelKind {
    /// A momentary push button: its X bit is 1 while the key is held.
    Key {
        /// The X bit it drives.
        input: Address,
    },
    /// A latching toggle: each operation flips its X bit (a normally closed E-stop chain
    /// reads 1 while released).
    Switch {
        /// The X bit it drives.
        input: Address,
    },
    /// A key with its own lamp (the mode keys: X key, Y lamp).
    LampKey {
        /// The X bit it drives while held.
        input: Address,
        /// The bit that lights it.
        lamp: Address,
    },
    /// An indicator lit by a bit (any bit address, usually a Y output).
    Lamp {
        /// The bit that lights it.
        lamp: Address,
    },
    /// A selector writing one of a few values into an X byte (the override switches).
    Knob {
        /// The X byte it drives.
        input: Address,
        /// Each position's label and value. The knob owns only the bits its values use
        /// ([`PanelKind::knob_mask`]), so two knobs can share a byte (feed and rapid override
        /// on X5).
        positions: Vec<(String, i64)>,
    },
}

impl Default for PanelKind {
    fn default() -> Self {
        PanelKind::Key {
            input: Address::bit(Area::X, 0, 0),
        }
    }
}

impl PanelKind {
    /// The address the item writes, if it writes one.
    pub fn input(&self) -> Option<Address> {
        match self {
            PanelKind::Key { input }
            | PanelKind::Switch { input }
            | PanelKind::LampKey { input, .. }
            | PanelKind::Knob { input, .. } => Some(*input),
            PanelKind::Lamp { .. } => None,
        }
    }

    /// Whether the item writes the bit `a` (a knob: a bit of its mask).
    pub fn drives(&self, a: Address) -> bool {
        match self {
            PanelKind::Knob { input, .. } => {
                input.byte_address() == a.byte_address()
                    && a.bit.is_some_and(|b| self.knob_mask() >> b & 1 == 1)
            }
            _ => self.input() == Some(a),
        }
    }

    /// The bit that lights the item, if it has a lamp.
    pub fn lamp(&self) -> Option<Address> {
        match self {
            PanelKind::LampKey { lamp, .. } | PanelKind::Lamp { lamp } => Some(*lamp),
            _ => None,
        }
    }

    /// The bits of its byte a knob drives: every bit one of its values uses (0 for items
    /// that are not knobs).
    pub fn knob_mask(&self) -> u8 {
        match self {
            PanelKind::Knob { positions, .. } => positions
                .iter()
                .fold(0, |m, (_, v)| m | (*v as u64 & 0xff) as u8),
            _ => 0,
        }
    }

    /// The knob position a byte value selects: the one whose value equals the byte's bits
    /// under the mask (`None` when the byte is at no position, as after power-on).
    pub fn knob_position(&self, byte: i64) -> Option<usize> {
        let PanelKind::Knob { positions, .. } = self else {
            return None;
        };
        let mask = i64::from(self.knob_mask());
        positions.iter().position(|(_, v)| *v == byte & mask)
    }

    /// The byte to write for a knob position `value` when the byte reads `byte` now: the
    /// knob's own bits set to the value, every other bit kept (another knob or switch may
    /// own them).
    pub fn knob_write(&self, byte: i64, value: i64) -> i64 {
        let mask = i64::from(self.knob_mask());
        (byte & 0xff & !mask) | (value & mask)
    }
}

/// Why a panel was refused. Each names the item (1-based, with its label) and what to fix.
#[derive(Clone, Debug, PartialEq, Eq, Error)]
pub enum PanelError {
    /// Neither label was typed.
    #[error("panel item {item}: it has no label; type a Chinese or an English label")]
    NoLabel {
        /// The item, 1-based.
        item: usize,
    },
    /// A key, switch or lamp on a byte address.
    #[error(
        "panel item {item} `{label}`: {address} is a byte; write a bit address such as X0002.3"
    )]
    NotBit {
        /// The item, 1-based.
        item: usize,
        /// Its label.
        label: String,
        /// The address.
        address: Address,
    },
    /// A knob on a bit address.
    #[error(
        "panel item {item} `{label}`: a knob writes a byte; write a byte address such as X0005"
    )]
    NotByte {
        /// The item, 1-based.
        item: usize,
        /// Its label.
        label: String,
        /// The address.
        address: Address,
    },
    /// An input outside X: the ladder or the CNC would overwrite it at the next scan.
    #[error(
        "panel item {item} `{label}`: {address} is not a machine input; keys, switches and knobs write X addresses"
    )]
    NotInput {
        /// The item, 1-based.
        item: usize,
        /// Its label.
        label: String,
        /// The address.
        address: Address,
    },
    /// An address the profile does not have.
    #[error("panel item {item} `{label}`: {error}")]
    Range {
        /// The item, 1-based.
        item: usize,
        /// Its label.
        label: String,
        /// The range error.
        error: AddressError,
    },
    /// Two items drive the same input bit, so each would undo the other.
    #[error(
        "panel item {item} `{label}`: {address} is already driven by item {other} `{other_label}`; give it another input"
    )]
    Taken {
        /// The item, 1-based.
        item: usize,
        /// Its label.
        label: String,
        /// The bit both drive.
        address: Address,
        /// The other item, 1-based.
        other: usize,
        /// Its label.
        other_label: String,
    },
    /// Two items on one grid cell, so one would hide the other.
    #[error(
        "panel item {item} `{label}`: row {row}, column {col} already holds item {other} `{other_label}`; move it to a free cell"
    )]
    SameCell {
        /// The item, 1-based.
        item: usize,
        /// Its label.
        label: String,
        /// Grid row.
        row: u8,
        /// Grid column.
        col: u8,
        /// The other item, 1-based.
        other: usize,
        /// Its label.
        other_label: String,
    },
    /// A knob without positions.
    #[error("panel item {item} `{label}`: the knob has no positions; add at least one")]
    NoPositions {
        /// The item, 1-based.
        item: usize,
        /// Its label.
        label: String,
    },
    /// A knob position outside a byte, or given twice (it could not be read back).
    #[error(
        "panel item {item} `{label}`: position value {value} is outside 0–255 or used twice; give each position its own byte value"
    )]
    BadPosition {
        /// The item, 1-based.
        item: usize,
        /// Its label.
        label: String,
        /// The value.
        value: i64,
    },
}

impl PanelItem {
    /// An item at a grid cell.
    pub fn new(zh: &str, en: &str, kind: PanelKind, row: u8, col: u8) -> PanelItem {
        PanelItem {
            label_zh: zh.into(),
            label_en: en.into(),
            kind,
            row,
            col,
            initial: 0,
        }
    }

    /// The item with its power-on value.
    pub fn starting_at(mut self, initial: i64) -> PanelItem {
        self.initial = initial;
        self
    }

    /// The label in messages: the English one, or the Chinese when there is no English.
    fn name(&self) -> String {
        if self.label_en.is_empty() {
            self.label_zh.clone()
        } else {
            self.label_en.clone()
        }
    }
}

impl Panel {
    /// Whether the panel has no item (the project then uses its profile's preset).
    pub fn is_empty(&self) -> bool {
        self.items.is_empty()
    }

    /// The preset panel of a profile. The GSK980 has no sample project of its own yet, and
    /// every address of the GSK988TA preset exists on it, so it gets the same panel.
    pub fn preset(profile: ProfileId) -> Panel {
        match profile {
            ProfileId::Gsk988ta | ProfileId::Gsk980 => Panel::preset_988ta(),
        }
    }

    /// The GSK988TA lathe panel, wired as the bundled sample `projects/lathe-988ta.ldp`
    /// (its symbol table names every address used here).
    pub fn preset_988ta() -> Panel {
        use PanelKind::*;
        let x = |n: u16, b: u8| Address::bit(Area::X, n, b);
        let y = |n: u16, b: u8| Address::bit(Area::Y, n, b);
        let key = |zh: &str, en: &str, n, b, row, col| {
            PanelItem::new(zh, en, Key { input: x(n, b) }, row, col)
        };
        let switch = |zh: &str, en: &str, n, b, row, col| {
            PanelItem::new(zh, en, Switch { input: x(n, b) }, row, col)
        };
        let lamp_key = |zh: &str, en: &str, b, row, col| {
            // Mode, cycle and feed-hold keys are X2.b with their lamps on Y1.b.
            PanelItem::new(
                zh,
                en,
                LampKey {
                    input: x(2, b),
                    lamp: y(1, b),
                },
                row,
                col,
            )
        };
        let lamp = |zh: &str, en: &str, n, b, row, col| {
            PanelItem::new(zh, en, Lamp { lamp: y(n, b) }, row, col)
        };
        let knob = |zh: &str, en: &str, n, positions: Vec<(String, i64)>, row, col| {
            PanelItem::new(
                zh,
                en,
                Knob {
                    input: Address::byte(Area::X, n),
                    positions,
                },
                row,
                col,
            )
        };
        // The feed override switch is Gray-coded on X5.0–X5.3; the ladder's CODB table turns
        // the code into FV = 0…15 (× 10 %), which is the inverse of the Gray code: the
        // position for k × 10 % is gray(k) = k ⊕ (k >> 1). 100 % is Gray 1111 (15).
        let feed = (0..=15)
            .map(|k: i64| (format!("{}%", k * 10), k ^ (k >> 1)))
            .collect();
        // The rapid override bits X5.4/X5.5 go straight to ROV1/ROV2: 00 = 100 %, 01 = 50 %,
        // 10 = 25 %, 11 = F0.
        let rapid = [("F0", 0x30), ("25%", 0x20), ("50%", 0x10), ("100%", 0)]
            .map(|(l, v)| (l.to_string(), v))
            .into();
        // The spindle override switch is binary on X6.0–X6.2; the ladder's CODB maps 0…7 to
        // SOV 5…12, i.e. 50 %…120 % (5 = 100 %).
        let spindle = (0..=7)
            .map(|k: i64| (format!("{}%", 50 + k * 10), k))
            .collect();
        let mut items = vec![
            lamp_key("编辑", "EDIT", 0, 0, 0),
            lamp_key("自动", "AUTO", 1, 0, 1),
            lamp_key("录入", "MDI", 2, 0, 2),
            lamp_key("机械回零", "REF", 5, 0, 3),
            lamp_key("手脉", "HANDLE", 4, 0, 4),
            lamp_key("手动", "JOG", 3, 0, 5),
            key("手脉 ×1", "Handwheel ×1", 4, 4, 1, 0),
            key("手脉 ×10", "Handwheel ×10", 4, 5, 1, 1),
            key("手脉 ×100", "Handwheel ×100", 4, 6, 1, 2),
            switch("手脉轴 Z", "Handwheel on Z", 4, 7, 1, 3),
            key("快速", "Rapid", 3, 6, 1, 4),
            key("X+", "X+", 4, 0, 2, 0),
            key("X-", "X-", 4, 1, 2, 1),
            key("Z+", "Z+", 4, 2, 2, 2),
            key("Z-", "Z-", 4, 3, 2, 3),
            key("主轴正转", "Spindle CW", 3, 0, 3, 0),
            key("主轴停止", "Spindle stop", 3, 1, 3, 1),
            key("主轴反转", "Spindle CCW", 3, 2, 3, 2),
            PanelItem::new(
                "冷却",
                "Coolant",
                LampKey {
                    input: x(3, 3),
                    lamp: y(2, 0),
                },
                3,
                3,
            ),
            PanelItem::new(
                "润滑",
                "Lube",
                LampKey {
                    input: x(3, 4),
                    lamp: y(2, 1),
                },
                3,
                4,
            ),
            key("换刀", "Tool change", 3, 5, 3, 5),
            lamp_key("循环启动", "Cycle start", 6, 4, 0),
            lamp_key("进给保持", "Feed hold", 7, 4, 1),
            knob("进给倍率", "Feed override", 5, feed, 4, 2).starting_at(15),
            knob("快速倍率", "Rapid override", 5, rapid, 4, 3),
            knob("主轴倍率", "Spindle override", 6, spindle, 4, 4).starting_at(5),
            lamp("报警（红）", "Red (alarm)", 2, 2, 5, 0),
            lamp("运行（绿）", "Green (running)", 2, 6, 5, 1),
            lamp("待机（黄）", "Yellow (idle)", 2, 7, 5, 2),
            lamp("X 回零完成", "X ref done", 2, 4, 5, 3),
            lamp("Z 回零完成", "Z ref done", 2, 5, 5, 4),
            // The machine side: what the electrician wires, for simulating faults.
            switch("急停（常闭）", "E-stop (NC)", 0, 5, 6, 0).starting_at(1),
            switch("X+ 限位（常闭）", "X+ limit (NC)", 1, 0, 6, 1).starting_at(1),
            switch("X- 限位（常闭）", "X- limit (NC)", 1, 1, 6, 2).starting_at(1),
            switch("Z+ 限位（常闭）", "Z+ limit (NC)", 1, 2, 6, 3).starting_at(1),
            switch("Z- 限位（常闭）", "Z- limit (NC)", 1, 3, 6, 4).starting_at(1),
            switch("主轴驱动准备好", "Spindle drive ready", 1, 5, 7, 0).starting_at(1),
            switch("卡盘夹紧到位", "Chuck clamped", 1, 6, 7, 1).starting_at(1),
            key("卡盘脚踏", "Chuck foot switch", 0, 6, 7, 2),
            switch("润滑油位低", "Lube level low", 0, 7, 7, 3),
            switch("X 减速开关（常闭）", "X dec. dog (NC)", 7, 0, 7, 4).starting_at(1),
            switch("Z 减速开关（常闭）", "Z dec. dog (NC)", 7, 1, 7, 5).starting_at(1),
        ];
        for t in 0..4u8 {
            let (zh, en) = (format!("{} 号刀位", t + 1), format!("Tool {}", t + 1));
            // The tool post stands at station 1.
            items.push(switch(&zh, &en, 0, t, 8, t).starting_at(i64::from(t == 0)));
        }
        Panel { items }
    }

    /// Checks the panel against a profile: every item labelled, each address of the right
    /// kind and in range, inputs in X and driven by one item only, one item per grid cell.
    pub fn check(&self, profile: &Profile) -> Result<(), PanelError> {
        // Every input bit claimed so far: (byte address, bit mask, item index).
        let mut claimed: Vec<(Address, u8, usize)> = Vec::new();
        for (i, it) in self.items.iter().enumerate() {
            let item = i + 1;
            if it.label_zh.trim().is_empty() && it.label_en.trim().is_empty() {
                return Err(PanelError::NoLabel { item });
            }
            let label = it.name();
            let range = |a: &Address| {
                a.check_range(profile).map_err(|error| PanelError::Range {
                    item,
                    label: label.clone(),
                    error,
                })
            };
            let is_bit = |a: &Address| match a.bit {
                Some(_) => Ok(()),
                None => Err(PanelError::NotBit {
                    item,
                    label: label.clone(),
                    address: *a,
                }),
            };
            if let Some(lamp) = it.kind.lamp() {
                is_bit(&lamp)?;
                range(&lamp)?;
            }
            if let Some(input) = it.kind.input() {
                let mask = match &it.kind {
                    PanelKind::Knob { positions, .. } => {
                        if input.bit.is_some() {
                            return Err(PanelError::NotByte {
                                item,
                                label,
                                address: input,
                            });
                        }
                        if positions.is_empty() {
                            return Err(PanelError::NoPositions { item, label });
                        }
                        for (k, (_, v)) in positions.iter().enumerate() {
                            let twice = positions[..k].iter().any(|(_, w)| w == v);
                            if !(0..=255).contains(v) || twice {
                                return Err(PanelError::BadPosition {
                                    item,
                                    label,
                                    value: *v,
                                });
                            }
                        }
                        it.kind.knob_mask()
                    }
                    _ => {
                        is_bit(&input)?;
                        1 << input.bit.unwrap_or(0)
                    }
                };
                if input.area != Area::X {
                    return Err(PanelError::NotInput {
                        item,
                        label,
                        address: input,
                    });
                }
                range(&input)?;
                let byte = input.byte_address();
                if let Some((_, m, other)) =
                    claimed.iter().find(|(a, m, _)| *a == byte && m & mask != 0)
                {
                    let bit = (m & mask).trailing_zeros() as u8;
                    return Err(PanelError::Taken {
                        item,
                        label,
                        address: Address::bit(Area::X, byte.number, bit),
                        other: other + 1,
                        other_label: self.items[*other].name(),
                    });
                }
                claimed.push((byte, mask, i));
            }
            if let Some(other) = self.items[..i]
                .iter()
                .position(|o| (o.row, o.col) == (it.row, it.col))
            {
                return Err(PanelError::SameCell {
                    item,
                    label,
                    row: it.row,
                    col: it.col,
                    other: other + 1,
                    other_label: self.items[other].name(),
                });
            }
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::file;
    use crate::model::{History, Project, TableEdit};

    fn p988() -> &'static Profile {
        Profile::get(ProfileId::Gsk988ta)
    }

    fn sample_path() -> std::path::PathBuf {
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../projects/lathe-988ta.ldp")
    }

    fn one(kind: PanelKind) -> Panel {
        Panel {
            items: vec![PanelItem::new("键", "Key", kind, 0, 0)],
        }
    }

    fn x(n: u16, b: u8) -> Address {
        Address::bit(Area::X, n, b)
    }

    #[test]
    fn the_preset_passes_its_check_on_both_profiles() {
        let panel = Panel::preset_988ta();
        assert_eq!(panel.check(p988()), Ok(()));
        assert_eq!(
            Panel::preset(ProfileId::Gsk980).check(Profile::get(ProfileId::Gsk980)),
            Ok(())
        );
        assert!(panel.items.len() > 40);
        for it in &panel.items {
            assert!(!it.label_zh.is_empty() && !it.label_en.is_empty(), "{it:?}");
        }
    }

    #[test]
    fn every_preset_address_has_a_symbol_in_the_sample_project() {
        let project = file::load(&sample_path()).expect("the sample loads");
        for it in &Panel::preset_988ta().items {
            for a in it.kind.input().into_iter().chain(it.kind.lamp()) {
                assert!(
                    project.symbol_of(a).is_some(),
                    "{} of `{}` has no symbol in the sample",
                    a,
                    it.label_en
                );
            }
        }
    }

    #[test]
    fn the_preset_wires_the_mode_keys_and_the_knobs_as_the_sample_decodes_them() {
        let panel = Panel::preset_988ta();
        let find = |en: &str| {
            panel
                .items
                .iter()
                .find(|i| i.label_en == en)
                .unwrap_or_else(|| panic!("no item {en}"))
        };
        assert_eq!(
            find("JOG").kind,
            PanelKind::LampKey {
                input: x(2, 3),
                lamp: Address::bit(Area::Y, 1, 3)
            }
        );
        assert_eq!(
            find("E-stop (NC)").kind,
            PanelKind::Switch { input: x(0, 5) }
        );
        // The scripts' healthy values: X5 = 15 is 100 % feed, X6 = 5 is 100 % spindle.
        let feed = &find("Feed override").kind;
        let PanelKind::Knob { positions, .. } = feed else {
            panic!("{feed:?}")
        };
        assert_eq!(positions[feed.knob_position(15).unwrap()].0, "100%");
        assert_eq!(positions[feed.knob_position(8).unwrap()].0, "150%");
        assert_eq!(positions[feed.knob_position(0).unwrap()].0, "0%");
        let sp = &find("Spindle override").kind;
        let PanelKind::Knob { positions, .. } = sp else {
            panic!("{sp:?}")
        };
        assert_eq!(positions[sp.knob_position(5).unwrap()].0, "100%");
        assert_eq!(positions[sp.knob_position(7).unwrap()].0, "120%");
        let rapid = &find("Rapid override").kind;
        assert_eq!(rapid.knob_mask(), 0x30);
        // Turning the rapid knob to 50 % (X5.4) keeps the feed knob's Gray code.
        assert_eq!(rapid.knob_write(15, 0x10), 0x1f);
        assert_eq!(feed.knob_write(0x1f, 8), 0x18);
    }

    #[test]
    fn a_project_with_a_custom_panel_saves_and_loads_it() {
        let mut p = Project {
            panel: one(PanelKind::Knob {
                input: Address::byte(Area::X, 9),
                positions: vec![("低".into(), 0), ("高".into(), 3)],
            }),
            ..Project::default()
        };
        p.panel.items.push(PanelItem::new(
            "灯",
            "Lamp",
            PanelKind::Lamp {
                lamp: Address::bit(Area::R, 10, 2),
            },
            2,
            5,
        ));
        let text = file::to_string(&p);
        assert!(text.contains("\n panel:"), "{text}");
        let back = file::from_bytes(text.as_bytes()).expect("it loads");
        assert_eq!(back.panel, p.panel);
        assert_eq!(back, p);
    }

    #[test]
    fn a_project_without_a_panel_saves_exactly_as_before() {
        let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../projects");
        for name in ["lathe-988ta.ldp", "start-stop.ldp", "stress-5000.ldp"] {
            let bytes = std::fs::read(dir.join(name)).unwrap();
            let p = file::from_bytes(&bytes).unwrap();
            assert!(p.panel.is_empty(), "{name} uses the preset");
            assert_eq!(p.operator_panel().into_owned(), Panel::preset(p.profile));
            let text = file::to_string(&p);
            assert!(!text.contains("\n panel:"), "{name}: no panel field");
            assert!(
                text.as_bytes() == bytes.as_slice(),
                "{name}: same bytes, same CRC"
            );
        }
    }

    #[test]
    fn a_panel_edit_is_undone_and_redone() {
        let mut p = Project::default();
        let mut h = History::new(10);
        let preset = Panel::preset_988ta();
        h.apply(&mut p, TableEdit::Panel(Box::new(preset.clone())))
            .unwrap();
        assert_eq!(p.panel, preset);
        assert!(h.undo(&mut p));
        assert!(p.panel.is_empty());
        assert!(h.redo(&mut p));
        assert_eq!(p.panel, preset);
        assert!(p.is_unchanged_by(&TableEdit::Panel(Box::new(preset)).into()));
    }

    #[test]
    fn check_names_the_item_and_refuses_what_cannot_work() {
        let p = p988();
        let byte_key = one(PanelKind::Key {
            input: Address::byte(Area::X, 2),
        });
        assert!(matches!(
            byte_key.check(p),
            Err(PanelError::NotBit { item: 1, .. })
        ));
        let y_key = one(PanelKind::Switch {
            input: Address::bit(Area::Y, 2, 0),
        });
        let e = y_key.check(p).unwrap_err();
        assert!(matches!(e, PanelError::NotInput { .. }), "{e:?}");
        assert!(e.to_string().contains("item 1 `Key`"), "{e}");
        let far = one(PanelKind::Key { input: x(200, 0) });
        assert!(matches!(far.check(p), Err(PanelError::Range { .. })));
        let bit_knob = one(PanelKind::Knob {
            input: x(5, 0),
            positions: vec![("a".into(), 1)],
        });
        assert!(matches!(bit_knob.check(p), Err(PanelError::NotByte { .. })));
        let knob = |positions: Vec<(String, i64)>| {
            one(PanelKind::Knob {
                input: Address::byte(Area::X, 5),
                positions,
            })
        };
        assert!(matches!(
            knob(vec![]).check(p),
            Err(PanelError::NoPositions { .. })
        ));
        assert!(matches!(
            knob(vec![("a".into(), 300)]).check(p),
            Err(PanelError::BadPosition { value: 300, .. })
        ));
        assert!(matches!(
            knob(vec![("a".into(), 1), ("b".into(), 1)]).check(p),
            Err(PanelError::BadPosition { value: 1, .. })
        ));

        let mut two = one(PanelKind::Key { input: x(2, 3) });
        two.items.push(PanelItem::new(
            "",
            "Other",
            PanelKind::Switch { input: x(2, 3) },
            0,
            1,
        ));
        let e = two.check(p).unwrap_err();
        assert!(
            matches!(&e, PanelError::Taken { item: 2, other: 1, address, .. } if *address == x(2, 3)),
            "{e:?}"
        );
        two.items[1].kind = PanelKind::Lamp { lamp: x(2, 3) };
        assert_eq!(two.check(p), Ok(()), "a lamp may read a key's bit");
        two.items[1].col = 0;
        assert!(matches!(
            two.check(p),
            Err(PanelError::SameCell {
                item: 2,
                other: 1,
                ..
            })
        ));
        two.items[1].label_en.clear();
        assert_eq!(two.check(p), Err(PanelError::NoLabel { item: 2 }));
        // A key inside a knob's bits is taken; beside them it is free.
        let mut shared = knob(vec![("a".into(), 0), ("b".into(), 3)]);
        shared.items.push(PanelItem::new(
            "键",
            "K",
            PanelKind::Key { input: x(5, 1) },
            0,
            1,
        ));
        assert!(matches!(shared.check(p), Err(PanelError::Taken { .. })));
        shared.items[1].kind = PanelKind::Key { input: x(5, 2) };
        assert_eq!(shared.check(p), Ok(()));
    }
}
