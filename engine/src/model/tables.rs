//! The project's tables besides the ladder (manual §3.4): symbol tables, data-setting tables,
//! the display-message table, the diagnosis, permission and M-code comment tables, and the
//! version information. All plain data; the editing rules of the manual are methods here.

use crate::address::{Address, Area};
use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;

/// Comments per language code (`zh`, `en`, …).
pub type Comments = BTreeMap<String, String>;

/// The comment languages, in the order the tables show their columns and a comments CSV
/// writes them when none is chosen.
pub const LANGUAGES: [&str; 2] = ["zh", "en"];

/// Largest magnitude of a data-table value (§3.4.4.2).
pub const VALUE_LIMIT: i64 = 2_147_483_647;

/// One row of a symbol table: an address, its symbol (may be empty: an address with only a
/// comment) and comments.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Symbol {
    /// The symbol; empty for an address that carries only a comment.
    pub name: String,
    /// The address it stands for.
    pub address: Address,
    /// Comments per language.
    #[serde(default)]
    pub comments: Comments,
}

/// A user symbol table.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct SymbolTable {
    /// The table's name (unique, and not the block-symbol table's).
    pub name: String,
    /// Its rows.
    pub rows: Vec<Symbol>,
}

/// The name of the fixed block-symbol table (subprogram names to P numbers), which is
/// derived from the ladder's subprograms and not stored.
pub const BLOCK_SYMBOLS: &str = "程序块符号";

/// A row of the D, DT or DC data-setting table.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct DataRow {
    /// The address (D, DT or DC).
    pub address: Address,
    /// Initial value.
    pub value: i64,
    /// Smallest value allowed, if set.
    #[serde(default)]
    pub min: Option<i64>,
    /// Largest value allowed, if set.
    #[serde(default)]
    pub max: Option<i64>,
    /// Symbol shown in the table.
    #[serde(default)]
    pub symbol: String,
    /// Comments per language.
    #[serde(default)]
    pub comments: Comments,
}

impl DataRow {
    /// A row with a value and no limits.
    pub fn new(address: Address, value: i64) -> DataRow {
        DataRow {
            address,
            value: value.clamp(-VALUE_LIMIT, VALUE_LIMIT),
            min: None,
            max: None,
            symbol: String::new(),
            comments: Comments::new(),
        }
    }

    /// Enters a value: limited to min…max when they are set, else to ±2147483647 (§3.4.4.2
    /// "小于最小值则赋予最小值，大于最大值则赋予最大值").
    pub fn set_value(&mut self, v: i64) {
        let lo = self.min.unwrap_or(-VALUE_LIMIT);
        let hi = self.max.unwrap_or(VALUE_LIMIT);
        self.value = v.clamp(lo, hi.max(lo));
    }

    /// Enters a minimum: limited to −2147483647…max; the value is raised to it if below.
    pub fn set_min(&mut self, m: Option<i64>) {
        self.min = m.map(|m| m.clamp(-VALUE_LIMIT, self.max.unwrap_or(VALUE_LIMIT)));
        if let Some(m) = self.min
            && self.value < m
        {
            self.value = m;
        }
    }

    /// Enters a maximum: limited to min…2147483647; the value is lowered to it if above.
    pub fn set_max(&mut self, m: Option<i64>) {
        self.max = m.map(|m| m.clamp(self.min.unwrap_or(-VALUE_LIMIT), VALUE_LIMIT));
        if let Some(m) = self.max
            && self.value > m
        {
            self.value = m;
        }
    }
}

/// A row of the D_FLOAT table: a real kept in a D address.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct RealRow {
    /// The D address.
    pub address: Address,
    /// Initial value.
    pub value: f32,
    /// Smallest value allowed, if set.
    #[serde(default)]
    pub min: Option<f32>,
    /// Largest value allowed, if set.
    #[serde(default)]
    pub max: Option<f32>,
    /// Symbol shown in the table.
    #[serde(default)]
    pub symbol: String,
    /// Comments per language.
    #[serde(default)]
    pub comments: Comments,
}

impl RealRow {
    /// A row with a value and no limits (a value that is no number becomes 0).
    pub fn new(address: Address, value: f32) -> RealRow {
        RealRow {
            address,
            value: if value.is_finite() { value } else { 0.0 },
            min: None,
            max: None,
            symbol: String::new(),
            comments: Comments::new(),
        }
    }

    /// Enters a minimum, with the rule [`DataRow::set_min`] applies to integers (§3.4.4.2):
    /// limited to the maximum, and the value raised to it.
    pub fn set_min(&mut self, m: Option<f32>) {
        self.min = m.map(|m| self.max.map_or(m, |x| m.min(x)));
        if let Some(m) = self.min
            && self.value < m
        {
            self.value = m;
        }
    }

    /// Enters a maximum: limited to the minimum, and the value lowered to it.
    pub fn set_max(&mut self, m: Option<f32>) {
        self.max = m.map(|m| self.min.map_or(m, |x| m.max(x)));
        if let Some(m) = self.max
            && self.value > m
        {
            self.value = m;
        }
    }

    /// Enters a value, limited to min…max when set.
    pub fn set_value(&mut self, v: f32) {
        let mut v = if v.is_finite() { v } else { 0.0 };
        if let Some(m) = self.min {
            v = v.max(m);
        }
        if let Some(m) = self.max {
            v = v.min(m);
        }
        self.value = v;
    }
}

/// The data-setting tables (§3.4.4): the K page and the D, D_FLOAT, DT and DC tables.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct DataTables {
    /// K0, K1, … as bytes, edited bit by bit.
    #[serde(default)]
    pub k: Vec<u8>,
    /// D rows.
    #[serde(default)]
    pub d: Vec<DataRow>,
    /// D_FLOAT rows.
    #[serde(default)]
    pub d_float: Vec<RealRow>,
    /// DT rows (timer presets, ms).
    #[serde(default)]
    pub dt: Vec<DataRow>,
    /// DC rows (counter presets).
    #[serde(default)]
    pub dc: Vec<DataRow>,
}

impl DataTables {
    /// Sets one bit of the K page, growing it as needed.
    pub fn set_k_bit(&mut self, number: usize, bit: u8, on: bool) {
        if self.k.len() <= number {
            self.k.resize(number + 1, 0);
        }
        let mask = 1u8 << (bit & 7);
        if on {
            self.k[number] |= mask;
        } else {
            self.k[number] &= !mask;
        }
    }

    /// A bit of the K page.
    pub fn k_bit(&self, number: usize, bit: u8) -> bool {
        self.k.get(number).is_some_and(|b| b >> (bit & 7) & 1 == 1)
    }

    /// The integer table an area's rows live in.
    pub fn table_for(&mut self, area: Area) -> Option<&mut Vec<DataRow>> {
        match area {
            Area::D => Some(&mut self.d),
            Area::Dt => Some(&mut self.dt),
            Area::Dc => Some(&mut self.dc),
            _ => None,
        }
    }
}

/// Message rows of the GSK988TA: one per A bit, A0000.0 … A0049.7.
///
/// The manual (§3.4.5) says both "固定的 200 行" and "A0000.0 到 A0049.7"; the latter is 400
/// bits and the whole A area (§1.1: A0–A49), whose only purpose is to request messages, so
/// the table has a row for every A bit of the profile (200 on the GSK980's A0–A24).
pub const MESSAGE_ROWS: usize = 400;

/// Message rows of a profile: one per A bit.
pub fn message_rows(profile: &crate::profile::Profile) -> usize {
    let (lo, hi) = profile.range(Area::A);
    (usize::from(hi) - usize::from(lo) + 1) * 8
}

/// A display-message (PLC alarm) row.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct Message {
    /// Alarm number 1000–9999, unique.
    #[serde(default)]
    pub number: Option<u16>,
    /// Text per language.
    #[serde(default)]
    pub texts: Comments,
}

/// The display-message table: row k is A(k/8).(k%8), a row per A bit. Saved sparse: only the
/// rows in use, keyed by their A bit.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(
    into = "BTreeMap<Address, Message>",
    try_from = "BTreeMap<Address, Message>"
)]
pub struct MessageTable {
    /// Exactly [`MESSAGE_ROWS`] rows.
    pub rows: Vec<Message>,
}

impl Default for MessageTable {
    fn default() -> Self {
        MessageTable {
            rows: vec![Message::default(); MESSAGE_ROWS],
        }
    }
}

impl From<MessageTable> for BTreeMap<Address, Message> {
    fn from(t: MessageTable) -> Self {
        t.rows
            .into_iter()
            .enumerate()
            .filter(|(_, m)| *m != Message::default())
            .map(|(k, m)| (MessageTable::address(k), m))
            .collect()
    }
}

impl TryFrom<BTreeMap<Address, Message>> for MessageTable {
    type Error = String;
    fn try_from(map: BTreeMap<Address, Message>) -> Result<Self, String> {
        let mut t = MessageTable::default();
        for (a, m) in map {
            let k = MessageTable::row_of(a)
                .ok_or_else(|| format!("{a} is not a message row (A0000.0–A0049.7)"))?;
            t.rows[k] = m;
        }
        Ok(t)
    }
}

impl MessageTable {
    /// The A bit of row `k`.
    pub fn address(k: usize) -> Address {
        Address::bit(Area::A, (k / 8) as u16, (k % 8) as u8)
    }

    /// The row of an A bit.
    pub fn row_of(a: Address) -> Option<usize> {
        (a.area == Area::A && a.bit.is_some())
            .then(|| usize::from(a.number) * 8 + usize::from(a.bit.unwrap_or(0)))
            .filter(|k| *k < MESSAGE_ROWS)
    }
}

/// A row of the diagnosis, permission or M-code table: a key (an address, or an M code) and
/// comments.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct AddressRow {
    /// The address.
    pub address: Address,
    /// Comments per language.
    #[serde(default)]
    pub comments: Comments,
}

/// A row of the M-code comment table.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct MCodeRow {
    /// The M code number (M03 → 3).
    pub code: u32,
    /// Comments per language.
    #[serde(default)]
    pub comments: Comments,
}

/// A salted password hash (SHA-256 of salt ‖ password), never the password itself.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct PasswordHash {
    /// Salt, hex.
    pub salt: String,
    /// Hash, hex.
    pub hash: String,
}

impl PasswordHash {
    /// Hashes a password with a salt.
    pub fn new(password: &str, salt: &str) -> PasswordHash {
        use sha2::{Digest, Sha256};
        let mut h = Sha256::new();
        h.update(salt.as_bytes());
        h.update(password.as_bytes());
        let hash = h.finalize().iter().map(|b| format!("{b:02x}")).collect();
        PasswordHash {
            salt: salt.to_string(),
            hash,
        }
    }

    /// Whether `password` is the one hashed.
    pub fn matches(&self, password: &str) -> bool {
        PasswordHash::new(password, &self.salt).hash == self.hash
    }
}

/// Limits of the version information (§3.4.7), in characters.
pub const DESIGNER_MAX: usize = 63;
/// Longest project name.
pub const NAME_MAX: usize = 63;
/// Longest version text.
pub const VERSION_MAX: usize = 19;
/// Longest remarks.
pub const REMARKS_MAX: usize = 511;

/// The ladder version information (§3.4.7).
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
pub struct VersionInfo {
    /// 工程名称: the project's name (the machine, the customer's order), ≤ 63 characters;
    /// the printout's title. Not written while empty, so older projects save unchanged.
    #[serde(default, skip_serializing_if = "String::is_empty")]
    pub name: String,
    /// 梯形图设计: designer, ≤ 63 characters.
    #[serde(default)]
    pub designer: String,
    /// 梯形图版本: version, ≤ 19 characters.
    #[serde(default)]
    pub version: String,
    /// 备注: remarks, ≤ 511 characters.
    #[serde(default)]
    pub remarks: String,
    /// 梯形图密码, stored only as a salted hash.
    #[serde(default)]
    pub password: Option<PasswordHash>,
}

impl VersionInfo {
    /// Sets the fields, cutting each to its limit.
    pub fn set(&mut self, name: &str, designer: &str, version: &str, remarks: &str) {
        let cut = |s: &str, n: usize| s.chars().take(n).collect::<String>();
        self.name = cut(name, NAME_MAX);
        self.designer = cut(designer, DESIGNER_MAX);
        self.version = cut(version, VERSION_MAX);
        self.remarks = cut(remarks, REMARKS_MAX);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn data_values_are_clamped_as_the_manual_says() {
        let mut r = DataRow::new(Address::byte(Area::Dt, 0), 1000);
        r.set_max(Some(500));
        assert_eq!(
            (r.value, r.max),
            (500, Some(500)),
            "lowering the max lowers the value"
        );
        r.set_min(Some(600));
        assert_eq!(r.min, Some(500), "a min above the max becomes the max");
        r.set_min(Some(100));
        r.set_value(50);
        assert_eq!(r.value, 100);
        r.set_value(9_999_999_999);
        assert_eq!(r.value, 500);
        r.set_max(None);
        r.set_value(9_999_999_999);
        assert_eq!(r.value, VALUE_LIMIT);
        r.set_min(Some(-9_999_999_999));
        assert_eq!(r.min, Some(-VALUE_LIMIT));
    }

    #[test]
    fn the_k_page_is_edited_bit_by_bit_and_messages_map_to_a_bits() {
        let mut t = DataTables::default();
        t.set_k_bit(3, 5, true);
        assert!(t.k_bit(3, 5) && !t.k_bit(3, 4) && t.k[3] == 0x20);
        assert_eq!(MessageTable::address(13).to_string(), "A0001.5");
        assert_eq!(
            MessageTable::row_of(Address::bit(Area::A, 49, 7)),
            Some(399)
        );
        assert_eq!(MessageTable::default().rows.len(), 400);
        let p980 = crate::profile::Profile::get(crate::profile::ProfileId::Gsk980);
        assert_eq!(message_rows(p980), 200);
    }

    #[test]
    fn passwords_are_kept_as_salted_hashes() {
        let h = PasswordHash::new("secret", "a1b2");
        assert!(h.matches("secret") && !h.matches("Secret"));
        assert!(!h.hash.contains("secret"));
        assert_ne!(h.hash, PasswordHash::new("secret", "c3d4").hash);
    }
}
