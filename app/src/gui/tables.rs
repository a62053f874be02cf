//! The table editors (manual §3.4): symbol tables, data-setting tables, display messages,
//! diagnosis, permissions, M-code comments and version information.
//!
//! Every change builds the new table from a clone of the project's and goes through
//! [`LadderApp::edit_table`], once per user action (a text field commits on Enter or when it
//! loses focus), so Ctrl+Z puts the table back exactly. What the user is typing, and why it
//! was refused, stays in [`TableState`] until it is valid: the project never holds an invalid
//! cell because of this editor.
//!
//! The row tables are drawn with `egui_extras::TableBuilder::rows`, which lays out only the
//! visible rows, so the 400-row message table and symbol tables of thousands of rows cost a
//! screenful per frame.

use super::LadderApp;
use super::i18n::{Lang, Msg};
use super::tree::View;
use egui::{Color32, Key, Sense};
use egui_extras::{Column, TableBuilder};
use ladder_engine::address::AreaSet;
use ladder_engine::model::tables::{
    DESIGNER_MAX, Message, MessageTable, REMARKS_MAX, VERSION_MAX, message_rows,
};
use ladder_engine::model::{
    AddressRow, Comments, DataRow, DataTables, MCodeRow, Operand, PasswordHash, Project, RealRow,
    Symbol, TableEdit, is_symbol_name,
};
use ladder_engine::{Address, AddressError, Area, Profile};
use std::collections::HashMap;
use std::ops::RangeInclusive;

const ERROR_RED: Color32 = Color32::from_rgb(0xc0, 0x10, 0x10);
const OK_GREEN: Color32 = Color32::from_rgb(0x10, 0x80, 0x10);

/// Longest comment in bytes (§3.4.3.2 "注释有长度限制（127 字节）"); the other tables' comments
/// go to the same CNC comment store, so the same limit applies to them.
const COMMENT_MAX_BYTES: usize = 127;

/// Alarm numbers of the message table (§3.4.5 "报警号的范围从 1000 到 9999").
const ALARM_NUMBERS: RangeInclusive<u16> = 1000..=9999;

/// M codes of the comment table. Neither the manual nor the file loader limits them; 0–9999
/// is what the CNC's four-digit M word can carry, so nothing the CNC can call is refused.
const M_CODES: RangeInclusive<u32> = 0..=9999;

/// Areas a user symbol may stand for (§3.4.3.2 "允许输入的类型为：A、X、Y、R、K、F、C、T、D、
/// DT、DC"); P numbers get their names from the block-symbol table, L labels have none.
const SYMBOL_AREAS: AreaSet = AreaSet::of(&[
    Area::A,
    Area::X,
    Area::Y,
    Area::R,
    Area::K,
    Area::F,
    Area::C,
    Area::T,
    Area::D,
    Area::Dt,
    Area::Dc,
]);

/// Areas the diagnosis and permission tables take: every memory area, not labels or
/// subprogram numbers, which hold no value to show or to change.
const VALUE_AREAS: AreaSet = AreaSet::of(&[
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

/// The tab of the data-setting view (§3.4.4).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum DataTab {
    /// The K page, edited bit by bit.
    #[default]
    K,
    /// The D table.
    D,
    /// The D_FLOAT table.
    DFloat,
    /// The DT table.
    Dt,
    /// The DC table.
    Dc,
}

/// A row table drawn by the grid editor.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Sheet {
    /// A user symbol table (index in the project).
    Symbols(usize),
    /// The D data table.
    D,
    /// The D_FLOAT data table.
    DFloat,
    /// The DT data table.
    Dt,
    /// The DC data table.
    Dc,
    /// The display-message table.
    Messages,
    /// The diagnosis table.
    Diagnosis,
    /// The permission table.
    Permissions,
    /// The M-code comment table.
    MCodes,
}

/// A column of a row table.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Col {
    /// The row's address.
    Address,
    /// Its symbol.
    Symbol,
    /// Its comment in the UI language.
    Comment,
    /// A data row's initial value.
    Value,
    /// A data row's minimum.
    Min,
    /// A data row's maximum.
    Max,
    /// A message's alarm number.
    Number,
    /// A message's text in the UI language.
    Text,
    /// An M code.
    Code,
}

/// What the row menu does (§3.4.3.2 行的编辑).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum RowOp {
    /// Empties the row but keeps it (and its key: a row cannot exist without one).
    Clear,
    /// A new row above, at a free address.
    InsertAbove,
    /// A new row below, at a free address.
    InsertBelow,
    /// Removes the row.
    Delete,
}

impl RowOp {
    const ALL: [RowOp; 4] = [
        RowOp::Clear,
        RowOp::InsertAbove,
        RowOp::InsertBelow,
        RowOp::Delete,
    ];

    fn msg(self) -> Msg {
        match self {
            RowOp::Clear => Msg::TblClear,
            RowOp::InsertAbove => Msg::TblInsertAbove,
            RowOp::InsertBelow => Msg::TblInsertBelow,
            RowOp::Delete => Msg::TblDelete,
        }
    }
}

/// A cell: its table, row and column.
type CellKey = (Sheet, usize, Col);

/// Text typed into a cell and not committed yet, with the reason it was refused, if it was.
#[derive(Clone, Debug, Default)]
struct Pending {
    text: String,
    error: Option<String>,
}

/// The password fields of the version view (cleared after every use; never saved).
#[derive(Clone, Default)]
struct PasswordDraft {
    current: String,
    new: String,
    confirm: String,
    /// The outcome of the last button press: an error (red) or a confirmation.
    note: Option<(bool, Msg)>,
}

// By hand, so that logging the UI state never writes a password out.
impl std::fmt::Debug for PasswordDraft {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("PasswordDraft")
            .field("typed", &!(self.current.is_empty() && self.new.is_empty()))
            .field("note", &self.note)
            .finish_non_exhaustive()
    }
}

/// The table editors' UI state.
#[derive(Clone, Debug, Default)]
pub struct TableState {
    /// The tab the data-setting view shows.
    pub data_tab: DataTab,
    /// The selected row of each table; the toolbar's row buttons act on it.
    pub selected: HashMap<Sheet, usize>,
    /// Cells being typed in, or refused.
    pending: HashMap<CellKey, Pending>,
    /// Why the last row-menu action was refused.
    op_error: Option<(Sheet, Msg)>,
    /// A row to bring into view at the next frame.
    scroll_to: Option<(Sheet, usize)>,
    /// Designer, version and remarks being typed.
    version: [Option<String>; 3],
    /// The password fields.
    password: PasswordDraft,
    /// The view and document generation the drafts were typed against.
    seen: Option<(View, u64)>,
}

impl TableState {
    /// The row table `view` shows (the data-setting view: its current tab; the K page is not
    /// a row table).
    pub fn sheet_of(&self, view: View) -> Option<Sheet> {
        Some(match view {
            View::Symbols(t) => Sheet::Symbols(t),
            View::Data => match self.data_tab {
                DataTab::K => return None,
                DataTab::D => Sheet::D,
                DataTab::DFloat => Sheet::DFloat,
                DataTab::Dt => Sheet::Dt,
                DataTab::Dc => Sheet::Dc,
            },
            View::Messages => Sheet::Messages,
            View::Diagnosis => Sheet::Diagnosis,
            View::Permissions => Sheet::Permissions,
            View::MCodes => Sheet::MCodes,
            _ => return None,
        })
    }

    /// Ctrl+G in a table (manual §3.2.2 转到): row `row` (0-based) is selected and scrolled
    /// into view; false when the table has no such row.
    pub fn go_to_row(&mut self, sheet: Sheet, row: usize, project: &Project) -> bool {
        if row >= sheet.len(project) {
            return false;
        }
        self.selected.insert(sheet, row);
        self.scroll_to = Some((sheet, row));
        true
    }

    /// Rows of a table.
    pub fn rows_in(&self, sheet: Sheet, project: &Project) -> usize {
        sheet.len(project)
    }

    /// Drops everything typed and not committed.
    fn forget_drafts(&mut self) {
        self.pending.clear();
        self.op_error = None;
        self.version = Default::default();
        self.password = PasswordDraft::default();
    }

    /// The first refusal among a row's cells.
    fn row_error(&self, sheet: Sheet, row: usize) -> Option<&str> {
        sheet.columns().iter().find_map(|c| {
            self.pending
                .get(&(sheet, row, *c))
                .and_then(|p| p.error.as_deref())
        })
    }
}

/// What the user did in a frame, applied once the frame no longer borrows the project.
enum Action {
    Commit(CellKey, String),
    Op(Sheet, RowOp, usize),
    KBit { number: usize, bit: u8, on: bool },
}

impl Sheet {
    fn columns(self) -> &'static [Col] {
        match self {
            Sheet::Symbols(_) => &[Col::Address, Col::Symbol, Col::Comment],
            Sheet::D | Sheet::DFloat | Sheet::Dt | Sheet::Dc => &[
                Col::Address,
                Col::Value,
                Col::Min,
                Col::Max,
                Col::Symbol,
                Col::Comment,
            ],
            Sheet::Messages => &[Col::Address, Col::Number, Col::Text],
            Sheet::Diagnosis | Sheet::Permissions => &[Col::Address, Col::Comment],
            Sheet::MCodes => &[Col::Code, Col::Comment],
        }
    }

    /// The message table has one row per A bit: rows are neither inserted nor deleted.
    fn fixed(self) -> bool {
        self == Sheet::Messages
    }

    /// The column without which a row cannot exist: typing it in the empty last line adds a
    /// row.
    fn key_col(self) -> Col {
        if self == Sheet::MCodes {
            Col::Code
        } else {
            Col::Address
        }
    }

    fn editable(self, col: Col) -> bool {
        !(self.fixed() && col == Col::Address)
    }

    /// The data area a data table's addresses must be of.
    fn data_area(self) -> Area {
        match self {
            Sheet::Dt => Area::Dt,
            Sheet::Dc => Area::Dc,
            _ => Area::D,
        }
    }

    fn len(self, project: &Project) -> usize {
        match self {
            Sheet::Symbols(t) => project.symbol_tables.get(t).map_or(0, |t| t.rows.len()),
            Sheet::D | Sheet::Dt | Sheet::Dc => int_rows(&project.data, self).len(),
            Sheet::DFloat => project.data.d_float.len(),
            Sheet::Messages => project
                .messages
                .rows
                .len()
                .min(message_rows(project.profile())),
            Sheet::Diagnosis | Sheet::Permissions => address_rows(project, self).len(),
            Sheet::MCodes => project.m_codes.len(),
        }
    }

    /// The table's name in messages.
    fn name(self, project: &Project, lang: Lang) -> String {
        let t = |m: Msg| m.text(lang).to_string();
        match self {
            Sheet::Symbols(i) => project
                .symbol_tables
                .get(i)
                .map(|t| t.name.clone())
                .unwrap_or_default(),
            Sheet::D => t(Msg::TblTabD),
            Sheet::DFloat => t(Msg::TblTabDFloat),
            Sheet::Dt => t(Msg::TblTabDt),
            Sheet::Dc => t(Msg::TblTabDc),
            Sheet::Messages => t(Msg::Messages),
            Sheet::Diagnosis => t(Msg::Diagnosis),
            Sheet::Permissions => t(Msg::Permissions),
            Sheet::MCodes => t(Msg::MCodes),
        }
    }
}

impl Col {
    fn title(self) -> Msg {
        match self {
            Col::Address => Msg::TblAddress,
            Col::Symbol => Msg::TblSymbol,
            Col::Comment => Msg::TblComment,
            Col::Value => Msg::TblValue,
            Col::Min => Msg::TblMin,
            Col::Max => Msg::TblMax,
            Col::Number => Msg::TblAlarmNumber,
            Col::Text => Msg::TblMessageText,
            Col::Code => Msg::TblMCode,
        }
    }

    fn column(self) -> Column {
        let width = match self {
            Col::Address | Col::Code | Col::Number => 100.0,
            Col::Value | Col::Min | Col::Max => 110.0,
            Col::Symbol => 170.0,
            Col::Comment => 280.0,
            Col::Text => 360.0,
        };
        Column::initial(width).at_least(50.0).clip(true)
    }
}

fn int_rows(data: &DataTables, sheet: Sheet) -> &Vec<DataRow> {
    match sheet {
        Sheet::Dt => &data.dt,
        Sheet::Dc => &data.dc,
        _ => &data.d,
    }
}

fn int_rows_mut(data: &mut DataTables, sheet: Sheet) -> &mut Vec<DataRow> {
    match sheet {
        Sheet::Dt => &mut data.dt,
        Sheet::Dc => &mut data.dc,
        _ => &mut data.d,
    }
}

fn address_rows(project: &Project, sheet: Sheet) -> &Vec<AddressRow> {
    if sheet == Sheet::Permissions {
        &project.permissions
    } else {
        &project.diagnosis
    }
}

/// What a cell shows when nobody is typing in it.
fn cell_text(project: &Project, sheet: Sheet, row: usize, col: Col, lang: Lang) -> String {
    let comment = |c: &Comments| c.get(lang.code()).cloned().unwrap_or_default();
    let int = |v: Option<i64>| v.map(|v| v.to_string()).unwrap_or_default();
    let real = |v: Option<f32>| v.map(|v| v.to_string()).unwrap_or_default();
    match sheet {
        Sheet::Symbols(t) => {
            let Some(s) = project.symbol_tables.get(t).and_then(|t| t.rows.get(row)) else {
                return String::new();
            };
            match col {
                Col::Address => s.address.to_string(),
                Col::Symbol => s.name.clone(),
                _ => comment(&s.comments),
            }
        }
        Sheet::D | Sheet::Dt | Sheet::Dc => {
            let Some(r) = int_rows(&project.data, sheet).get(row) else {
                return String::new();
            };
            match col {
                Col::Address => r.address.to_string(),
                Col::Value => r.value.to_string(),
                Col::Min => int(r.min),
                Col::Max => int(r.max),
                Col::Symbol => r.symbol.clone(),
                _ => comment(&r.comments),
            }
        }
        Sheet::DFloat => {
            let Some(r) = project.data.d_float.get(row) else {
                return String::new();
            };
            match col {
                Col::Address => r.address.to_string(),
                Col::Value => r.value.to_string(),
                Col::Min => real(r.min),
                Col::Max => real(r.max),
                Col::Symbol => r.symbol.clone(),
                _ => comment(&r.comments),
            }
        }
        Sheet::Messages => {
            let Some(m) = project.messages.rows.get(row) else {
                return String::new();
            };
            match col {
                Col::Address => MessageTable::address(row).to_string(),
                Col::Number => m.number.map(|n| n.to_string()).unwrap_or_default(),
                _ => comment(&m.texts),
            }
        }
        Sheet::Diagnosis | Sheet::Permissions => {
            let Some(r) = address_rows(project, sheet).get(row) else {
                return String::new();
            };
            match col {
                Col::Address => r.address.to_string(),
                _ => comment(&r.comments),
            }
        }
        Sheet::MCodes => {
            let Some(r) = project.m_codes.get(row) else {
                return String::new();
            };
            match col {
                Col::Code => format!("M{:02}", r.code),
                _ => comment(&r.comments),
            }
        }
    }
}

/// The edit that replaces `old` by `new`, or none when they are equal (a field left as it
/// was must not become an undo step).
fn changed<T: PartialEq>(old: &T, new: T, wrap: impl FnOnce(T) -> TableEdit) -> Option<TableEdit> {
    (*old != new).then(|| wrap(new))
}

/// An address error in the UI language (the engine's own texts are English).
fn address_error(e: &AddressError, profile: &Profile, lang: Lang) -> String {
    let t = |m: Msg| m.text(lang);
    match e {
        AddressError::Syntax(s) => format!("`{s}` {}", t(Msg::TblErrSyntax)),
        AddressError::UnknownArea(s, letters) => {
            format!("`{s}` {} {letters}", t(Msg::TblErrArea))
        }
        AddressError::Bit(s) => format!("`{s}`: {}", t(Msg::TblErrBit)),
        AddressError::NoBits(s, _) => format!("`{s}`: {}", t(Msg::TblErrNoBits)),
        AddressError::Range { text, area, .. } => {
            let (lo, hi) = profile.range(*area);
            format!("{text} {} ({area}{lo}–{area}{hi})", t(Msg::TblErrRange))
        }
    }
}

/// Parses an address against the profile and the areas a table takes.
fn parse_address(
    project: &Project,
    text: &str,
    areas: AreaSet,
    lang: Lang,
) -> Result<Address, String> {
    if text.is_empty() {
        return Err(Msg::TblErrAddressEmpty.text(lang).into());
    }
    let profile = project.profile();
    let a = Address::parse_in(text, profile).map_err(|e| address_error(&e, profile, lang))?;
    if !areas.contains(a.area) {
        return Err(format!(
            "{a}: {} {}",
            Msg::TblErrAreaHere.text(lang),
            areas.describe()
        ));
    }
    Ok(a)
}

/// A symbol table's address: valid, of a symbol area, and in no other row of any symbol
/// table (§3.4.3.2 "地址不允许相同").
fn symbol_address(
    project: &Project,
    text: &str,
    this: Option<(usize, usize)>,
    lang: Lang,
) -> Result<Address, String> {
    let a = parse_address(project, text, SYMBOL_AREAS, lang)?;
    for (t, table) in project.symbol_tables.iter().enumerate() {
        if let Some(r) = table
            .rows
            .iter()
            .enumerate()
            .position(|(r, s)| s.address == a && this != Some((t, r)))
        {
            return Err(format!(
                "{a}: {} {} #{}",
                Msg::TblErrAddressTwice.text(lang),
                table.name,
                r + 1
            ));
        }
    }
    Ok(a)
}

/// Whether a name may be a symbol: the manual's characters, and not something the operand
/// parser would read as an address (`X1` would never reach the symbol).
fn check_symbol_form(name: &str, lang: Lang) -> Result<(), String> {
    let looks_like_address = matches!(Operand::parse(name), Ok(Operand::Addr(_)));
    if !is_symbol_name(name) || looks_like_address {
        return Err(format!("`{name}`: {}", Msg::TblErrSymbolName.text(lang)));
    }
    Ok(())
}

/// A symbol table's symbol: empty (an address with only a comment), or a valid name used by
/// no other row of any symbol table nor by a subprogram (§3.4.3.2 "符号不允许相同").
fn check_symbol(
    project: &Project,
    name: &str,
    this: Option<(usize, usize)>,
    lang: Lang,
) -> Result<(), String> {
    if name.is_empty() {
        return Ok(());
    }
    check_symbol_form(name, lang)?;
    let taken = |place: String| {
        Err(format!(
            "`{name}`: {} {place}",
            Msg::TblErrSymbolTwice.text(lang)
        ))
    };
    for (t, table) in project.symbol_tables.iter().enumerate() {
        if let Some(r) = table
            .rows
            .iter()
            .enumerate()
            .position(|(r, s)| s.name == name && this != Some((t, r)))
        {
            return taken(format!("{} #{}", table.name, r + 1));
        }
    }
    let blocks = project.block_symbols();
    if let Some(s) = blocks.rows.iter().find(|s| s.name == name) {
        return taken(format!("{} {}", blocks.name, s.address));
    }
    Ok(())
}

/// A data row's symbol: a valid name, and not one the symbol tables give another address.
fn check_data_symbol(
    project: &Project,
    name: &str,
    address: Address,
    lang: Lang,
) -> Result<(), String> {
    if name.is_empty() {
        return Ok(());
    }
    check_symbol_form(name, lang)?;
    match project.resolve_symbol(name) {
        Some(a) if a != address => Err(format!(
            "`{name}`: {} {a}",
            Msg::TblErrSymbolElsewhere.text(lang)
        )),
        _ => Ok(()),
    }
}

/// Every address listed in the same space as a data table's, with where it is: D and
/// D_FLOAT share the D addresses (one D holds an integer or a real, not both).
fn data_addresses(project: &Project, sheet: Sheet) -> Vec<(Sheet, usize, Address)> {
    let d = &project.data;
    let ints = |s: Sheet| {
        int_rows(d, s)
            .iter()
            .enumerate()
            .map(move |(i, r)| (s, i, r.address))
    };
    match sheet {
        Sheet::Dt | Sheet::Dc => ints(sheet).collect(),
        _ => ints(Sheet::D)
            .chain(
                d.d_float
                    .iter()
                    .enumerate()
                    .map(|(i, r)| (Sheet::DFloat, i, r.address)),
            )
            .collect(),
    }
}

/// A data table's address: of its area, a whole word, in range and listed once.
fn data_address(
    project: &Project,
    sheet: Sheet,
    text: &str,
    this: Option<usize>,
    lang: Lang,
) -> Result<Address, String> {
    let area = sheet.data_area();
    let a = parse_address(project, text, AreaSet::of(&[area]), lang)?;
    if a.bit.is_some() {
        return Err(format!("`{text}`: {}", Msg::TblErrNoBits.text(lang)));
    }
    if let Some((s, i, _)) = data_addresses(project, sheet)
        .into_iter()
        .find(|(s, i, x)| *x == a && !(*s == sheet && Some(*i) == this))
    {
        return Err(format!(
            "{a}: {} {} #{}",
            Msg::TblErrAddressTwice.text(lang),
            s.name(project, lang),
            i + 1
        ));
    }
    Ok(a)
}

/// A diagnosis or permission address: of a memory area, in range, listed once in its table.
fn plain_address(
    project: &Project,
    sheet: Sheet,
    text: &str,
    this: Option<usize>,
    lang: Lang,
) -> Result<Address, String> {
    let a = parse_address(project, text, VALUE_AREAS, lang)?;
    if let Some(i) = address_rows(project, sheet)
        .iter()
        .enumerate()
        .position(|(i, r)| r.address == a && Some(i) != this)
    {
        return Err(format!(
            "{a}: {} #{}",
            Msg::TblErrAddressTwice.text(lang),
            i + 1
        ));
    }
    Ok(a)
}

/// An M code (`M03`, `m3` or `3`), in range and listed once.
fn m_code(project: &Project, text: &str, this: Option<usize>, lang: Lang) -> Result<u32, String> {
    let digits = text.trim_start_matches(['M', 'm']);
    let code = Some(digits)
        .filter(|d| !d.is_empty() && d.bytes().all(|b| b.is_ascii_digit()))
        .and_then(|d| d.parse::<u32>().ok())
        .filter(|c| M_CODES.contains(c))
        .ok_or_else(|| format!("`{text}`: {}", Msg::TblErrMCode.text(lang)))?;
    if project
        .m_codes
        .iter()
        .enumerate()
        .any(|(i, r)| r.code == code && Some(i) != this)
    {
        return Err(format!("M{code:02}: {}", Msg::TblErrMCodeTwice.text(lang)));
    }
    Ok(code)
}

/// An alarm number: empty for none, else 1000–9999 and used by no other A bit.
fn alarm_number(
    project: &Project,
    text: &str,
    row: usize,
    lang: Lang,
) -> Result<Option<u16>, String> {
    if text.is_empty() {
        return Ok(None);
    }
    let n = text
        .parse::<u16>()
        .ok()
        .filter(|n| ALARM_NUMBERS.contains(n))
        .ok_or_else(|| format!("`{text}`: {}", Msg::TblErrAlarmRange.text(lang)))?;
    if let Some(k) = project
        .messages
        .rows
        .iter()
        .enumerate()
        .position(|(k, m)| m.number == Some(n) && k != row)
    {
        return Err(format!(
            "{n}: {} {}",
            Msg::TblErrAlarmTwice.text(lang),
            MessageTable::address(k)
        ));
    }
    Ok(Some(n))
}

/// An integer cell: empty for none. Beyond ±2147483647 is not an error but clamped by the
/// row's setters, as the manual says; only text that is no integer at all is refused.
fn parse_int(text: &str, lang: Lang) -> Result<Option<i64>, String> {
    if text.is_empty() {
        return Ok(None);
    }
    text.parse::<i128>()
        .map(|v| Some(v.clamp(i128::from(i64::MIN), i128::from(i64::MAX)) as i64))
        .map_err(|_| format!("`{text}`: {}", Msg::TblErrInteger.text(lang)))
}

/// A real cell: empty for none, else a finite number.
fn parse_real(text: &str, lang: Lang) -> Result<Option<f32>, String> {
    if text.is_empty() {
        return Ok(None);
    }
    text.parse::<f32>()
        .ok()
        .filter(|v| v.is_finite())
        .map(Some)
        .ok_or_else(|| format!("`{text}`: {}", Msg::TblErrReal.text(lang)))
}

/// The D_FLOAT minimum, with the rule `DataRow::set_min` applies to integers (§3.4.4.2):
/// limited to the maximum, and the value raised to it.
fn set_real_min(r: &mut RealRow, m: Option<f32>) {
    r.min = m.map(|m| r.max.map_or(m, |x| m.min(x)));
    if let Some(m) = r.min
        && r.value < m
    {
        r.value = m;
    }
}

/// The D_FLOAT maximum: limited to the minimum, and the value lowered to it.
fn set_real_max(r: &mut RealRow, m: Option<f32>) {
    r.max = m.map(|m| r.min.map_or(m, |x| m.max(x)));
    if let Some(m) = r.max
        && r.value > m
    {
        r.value = m;
    }
}

/// Sets the UI language's entry of a comment map; empty removes it.
fn set_comment(
    comments: &mut Comments,
    lang: Lang,
    text: &str,
    limited: bool,
) -> Result<(), String> {
    let text = text.trim();
    if limited && text.len() > COMMENT_MAX_BYTES {
        return Err(Msg::TblErrCommentLong.text(lang).into());
    }
    if text.is_empty() {
        comments.remove(lang.code());
    } else {
        comments.insert(lang.code().into(), text.into());
    }
    Ok(())
}

/// Applies a typed cell: the edit replacing its table, none when nothing changes, or why the
/// text is refused.
fn commit(
    project: &Project,
    sheet: Sheet,
    row: usize,
    col: Col,
    raw: &str,
    lang: Lang,
) -> Result<Option<TableEdit>, String> {
    let text = raw.trim();
    let fresh = row >= sheet.len(project);
    // The empty last line only takes its key: a row cannot exist without its address or code.
    if fresh && (sheet.fixed() || col != sheet.key_col() || text.is_empty()) {
        return Ok(None);
    }
    match sheet {
        Sheet::Symbols(t) => {
            let mut tables = project.symbol_tables.clone();
            let Some(table) = tables.get_mut(t) else {
                return Ok(None);
            };
            if fresh {
                let address = symbol_address(project, text, None, lang)?;
                table.rows.push(Symbol {
                    name: String::new(),
                    address,
                    comments: Comments::new(),
                });
            } else {
                let s = &mut table.rows[row];
                match col {
                    Col::Address => {
                        s.address = symbol_address(project, text, Some((t, row)), lang)?
                    }
                    Col::Symbol => {
                        check_symbol(project, text, Some((t, row)), lang)?;
                        s.name = text.into();
                    }
                    _ => set_comment(&mut s.comments, lang, raw, true)?,
                }
            }
            Ok(changed(&project.symbol_tables, tables, TableEdit::Symbols))
        }
        Sheet::D | Sheet::Dt | Sheet::Dc => {
            let mut data = project.data.clone();
            let rows = int_rows_mut(&mut data, sheet);
            if fresh {
                rows.push(DataRow::new(
                    data_address(project, sheet, text, None, lang)?,
                    0,
                ));
            } else {
                let r = &mut rows[row];
                match col {
                    Col::Address => {
                        r.address = data_address(project, sheet, text, Some(row), lang)?
                    }
                    Col::Value => r.set_value(
                        parse_int(text, lang)?
                            .ok_or_else(|| Msg::TblErrInteger.text(lang).to_string())?,
                    ),
                    Col::Min => r.set_min(parse_int(text, lang)?),
                    Col::Max => r.set_max(parse_int(text, lang)?),
                    Col::Symbol => {
                        check_data_symbol(project, text, r.address, lang)?;
                        r.symbol = text.into();
                    }
                    _ => set_comment(&mut r.comments, lang, raw, true)?,
                }
            }
            Ok(changed(&project.data, data, |d| {
                TableEdit::Data(Box::new(d))
            }))
        }
        Sheet::DFloat => {
            let mut data = project.data.clone();
            let rows = &mut data.d_float;
            if fresh {
                rows.push(real_row(data_address(project, sheet, text, None, lang)?));
            } else {
                let r = &mut rows[row];
                match col {
                    Col::Address => {
                        r.address = data_address(project, sheet, text, Some(row), lang)?
                    }
                    Col::Value => r.set_value(
                        parse_real(text, lang)?
                            .ok_or_else(|| Msg::TblErrReal.text(lang).to_string())?,
                    ),
                    Col::Min => set_real_min(r, parse_real(text, lang)?),
                    Col::Max => set_real_max(r, parse_real(text, lang)?),
                    Col::Symbol => {
                        check_data_symbol(project, text, r.address, lang)?;
                        r.symbol = text.into();
                    }
                    _ => set_comment(&mut r.comments, lang, raw, true)?,
                }
            }
            Ok(changed(&project.data, data, |d| {
                TableEdit::Data(Box::new(d))
            }))
        }
        Sheet::Messages => {
            let mut messages = project.messages.clone();
            let Some(m) = messages.rows.get_mut(row) else {
                return Ok(None);
            };
            match col {
                Col::Number => m.number = alarm_number(project, text, row, lang)?,
                Col::Text => set_comment(&mut m.texts, lang, raw, false)?,
                _ => {}
            }
            Ok(changed(&project.messages, messages, |m| {
                TableEdit::Messages(Box::new(m))
            }))
        }
        Sheet::Diagnosis | Sheet::Permissions => {
            let mut rows = address_rows(project, sheet).clone();
            if fresh {
                rows.push(AddressRow {
                    address: plain_address(project, sheet, text, None, lang)?,
                    comments: Comments::new(),
                });
            } else {
                let r = &mut rows[row];
                match col {
                    Col::Address => {
                        r.address = plain_address(project, sheet, text, Some(row), lang)?
                    }
                    _ => set_comment(&mut r.comments, lang, raw, true)?,
                }
            }
            let wrap = if sheet == Sheet::Permissions {
                TableEdit::Permissions
            } else {
                TableEdit::Diagnosis
            };
            Ok(changed(address_rows(project, sheet), rows, wrap))
        }
        Sheet::MCodes => {
            let mut rows = project.m_codes.clone();
            if fresh {
                rows.push(MCodeRow {
                    code: m_code(project, text, None, lang)?,
                    comments: Comments::new(),
                });
            } else {
                let r = &mut rows[row];
                match col {
                    Col::Code => r.code = m_code(project, text, Some(row), lang)?,
                    _ => set_comment(&mut r.comments, lang, raw, true)?,
                }
            }
            Ok(changed(&project.m_codes, rows, TableEdit::MCodes))
        }
    }
}

fn real_row(address: Address) -> RealRow {
    RealRow {
        address,
        value: 0.0,
        min: None,
        max: None,
        symbol: String::new(),
        comments: Comments::new(),
    }
}

/// The first free address from `seed` on (wrapping round the area's range), bit by bit for
/// a bit address, word by word otherwise.
fn next_free_address(
    seed: Address,
    profile: &Profile,
    used: impl Fn(Address) -> bool,
) -> Option<Address> {
    let (lo, hi) = profile.range(seed.area);
    let per = if seed.bit.is_some() { 8 } else { 1 };
    let total = (usize::from(hi) - usize::from(lo) + 1) * per;
    let start =
        usize::from(seed.number.clamp(lo, hi) - lo) * per + usize::from(seed.bit.unwrap_or(0));
    (0..total)
        .map(|k| (start + k) % total)
        .map(|i| {
            let number = lo + (i / per) as u16;
            if per == 8 {
                Address::bit(seed.area, number, (i % 8) as u8)
            } else {
                Address::byte(seed.area, number)
            }
        })
        .find(|a| !used(*a))
}

/// Applies a row operation to a list; returns the row to select after it. A new row needs
/// a free key, which `fresh` finds (`None`: the area is full).
fn apply_op<T>(
    rows: &mut Vec<T>,
    op: RowOp,
    row: usize,
    clear: impl FnOnce(&mut T),
    fresh: impl FnOnce() -> Option<T>,
) -> Result<usize, Msg> {
    match op {
        RowOp::Clear => {
            if let Some(r) = rows.get_mut(row) {
                clear(r);
            }
            Ok(row)
        }
        RowOp::Delete => {
            if row < rows.len() {
                rows.remove(row);
            }
            Ok(row.min(rows.len().saturating_sub(1)))
        }
        RowOp::InsertAbove | RowOp::InsertBelow => {
            let at = (row + usize::from(op == RowOp::InsertBelow)).min(rows.len());
            rows.insert(at, fresh().ok_or(Msg::TblErrNoFree)?);
            Ok(at)
        }
    }
}

/// The key a new row starts its search for a free one from: the selected row's, else the
/// last row's.
fn seed<T, K>(rows: &[T], row: usize, key: impl Fn(&T) -> K) -> Option<K> {
    rows.get(row).or(rows.last()).map(key)
}

/// Applies a row-menu action: the edit (none when nothing changes) and the row to select.
fn row_op(
    project: &Project,
    sheet: Sheet,
    op: RowOp,
    row: usize,
) -> Result<(Option<TableEdit>, usize), Msg> {
    let profile = project.profile();
    let first = |area: Area| profile.range(area).0;
    match sheet {
        Sheet::Symbols(t) => {
            let mut tables = project.symbol_tables.clone();
            let Some(table) = tables.get_mut(t) else {
                return Ok((None, row));
            };
            let start = seed(&table.rows, row, |s| s.address).unwrap_or(Address::bit(
                Area::R,
                first(Area::R),
                0,
            ));
            let select = apply_op(
                &mut table.rows,
                op,
                row,
                |s| {
                    s.name.clear();
                    s.comments.clear();
                },
                || {
                    next_free_address(start, profile, |a| {
                        project.symbols().any(|s| s.address == a)
                    })
                    .map(|address| Symbol {
                        name: String::new(),
                        address,
                        comments: Comments::new(),
                    })
                },
            )?;
            Ok((
                changed(&project.symbol_tables, tables, TableEdit::Symbols),
                select,
            ))
        }
        Sheet::D | Sheet::Dt | Sheet::Dc | Sheet::DFloat => {
            let area = sheet.data_area();
            let used: Vec<Address> = data_addresses(project, sheet)
                .into_iter()
                .map(|(_, _, a)| a)
                .collect();
            let free = |start: Option<Address>| {
                next_free_address(
                    start.unwrap_or(Address::byte(area, first(area))),
                    profile,
                    |a| used.contains(&a),
                )
            };
            let mut data = project.data.clone();
            let select = if sheet == Sheet::DFloat {
                let rows = &mut data.d_float;
                let start = seed(rows, row, |r| r.address);
                apply_op(
                    rows,
                    op,
                    row,
                    |r| *r = real_row(r.address),
                    || free(start).map(real_row),
                )?
            } else {
                let rows = int_rows_mut(&mut data, sheet);
                let start = seed(rows, row, |r| r.address);
                apply_op(
                    rows,
                    op,
                    row,
                    |r| *r = DataRow::new(r.address, 0),
                    || free(start).map(|a| DataRow::new(a, 0)),
                )?
            };
            Ok((
                changed(&project.data, data, |d| TableEdit::Data(Box::new(d))),
                select,
            ))
        }
        Sheet::Messages => {
            // The rows are the A bits: they can be emptied, not added or removed.
            let mut messages = project.messages.clone();
            if op == RowOp::Clear
                && let Some(m) = messages.rows.get_mut(row)
            {
                *m = Message::default();
            }
            Ok((
                changed(&project.messages, messages, |m| {
                    TableEdit::Messages(Box::new(m))
                }),
                row,
            ))
        }
        Sheet::Diagnosis | Sheet::Permissions => {
            let mut rows = address_rows(project, sheet).clone();
            // Diagnosis shows bits as lamps and words as values; permissions are about the
            // settings a user may change, K bytes first (§3.4).
            let default = if sheet == Sheet::Diagnosis {
                Address::bit(Area::K, first(Area::K), 0)
            } else {
                Address::byte(Area::K, first(Area::K))
            };
            let start = seed(&rows, row, |r| r.address).unwrap_or(default);
            let existing = address_rows(project, sheet);
            let select = apply_op(
                &mut rows,
                op,
                row,
                |r| r.comments.clear(),
                || {
                    next_free_address(start, profile, |a| existing.iter().any(|r| r.address == a))
                        .map(|address| AddressRow {
                            address,
                            comments: Comments::new(),
                        })
                },
            )?;
            let wrap = if sheet == Sheet::Permissions {
                TableEdit::Permissions
            } else {
                TableEdit::Diagnosis
            };
            Ok((changed(existing, rows, wrap), select))
        }
        Sheet::MCodes => {
            let mut rows = project.m_codes.clone();
            let start = seed(&rows, row, |r| r.code).unwrap_or(0);
            let span = M_CODES.end() - M_CODES.start() + 1;
            let select = apply_op(
                &mut rows,
                op,
                row,
                |r| r.comments.clear(),
                || {
                    (0..span)
                        .map(|k| M_CODES.start() + (start - M_CODES.start() + k) % span)
                        .find(|c| !project.m_codes.iter().any(|r| r.code == *c))
                        .map(|code| MCodeRow {
                            code,
                            comments: Comments::new(),
                        })
                },
            )?;
            Ok((changed(&project.m_codes, rows, TableEdit::MCodes), select))
        }
    }
}

/// A salt for a password hash: random per call (std's hasher keys come from the OS), so two
/// projects with the same password get different hashes.
fn new_salt() -> String {
    use std::hash::{BuildHasher, Hasher};
    let nanos = std::time::SystemTime::now()
        .duration_since(std::time::UNIX_EPOCH)
        .map_or(0, |d| d.as_nanos());
    (0..2u8)
        .map(|i| {
            let mut h = std::collections::hash_map::RandomState::new().build_hasher();
            h.write_u128(nanos);
            h.write_u8(i);
            format!("{:016x}", h.finish())
        })
        .collect()
}

/// Draws one row-menu button, disabled with the reason when it cannot act; true when clicked.
fn row_op_button(
    ui: &mut egui::Ui,
    sheet: Sheet,
    op: RowOp,
    row: Option<usize>,
    len: usize,
    lang: Lang,
) -> bool {
    let on_a_row = row.is_some_and(|r| r < len);
    let (enabled, why) = match op {
        RowOp::Clear => (on_a_row, Msg::TblSelectRowFirst),
        RowOp::Delete if sheet.fixed() => (false, Msg::TblFixedRows),
        RowOp::Delete => (on_a_row, Msg::TblSelectRowFirst),
        RowOp::InsertAbove | RowOp::InsertBelow => (!sheet.fixed(), Msg::TblFixedRows),
    };
    ui.add_enabled(enabled, egui::Button::new(op.msg().text(lang)))
        .on_disabled_hover_text(why.text(lang))
        .clicked()
}

/// One editable cell: shows the typed text while there is some, commits it when the field
/// loses focus (Enter included), drops it on Escape.
fn cell_ui(
    ui: &mut egui::Ui,
    state: &mut TableState,
    project: &Project,
    (sheet, row, col): CellKey,
    len: usize,
    lang: Lang,
    actions: &mut Vec<Action>,
) {
    let fresh = row >= len;
    if !sheet.editable(col) || (fresh && col != sheet.key_col()) {
        if !fresh {
            ui.label(cell_text(project, sheet, row, col, lang));
        }
        return;
    }
    let key = (sheet, row, col);
    let pending = state.pending.get(&key);
    let refused = pending.is_some_and(|p| p.error.is_some());
    let mut text = match pending {
        Some(p) => p.text.clone(),
        None => cell_text(project, sheet, row, col, lang),
    };
    let mut edit = egui::TextEdit::singleline(&mut text).desired_width(f32::INFINITY);
    if refused {
        edit = edit.text_color(ERROR_RED);
    }
    if fresh {
        let hint = if sheet == Sheet::MCodes {
            Msg::TblNewRowCode
        } else {
            Msg::TblNewRowAddress
        };
        edit = edit.hint_text(hint.text(lang));
    }
    let r = ui
        .add(edit)
        .accessible_name(format!("{} {}", col.title().text(lang), row + 1));
    if r.gained_focus() {
        state.selected.insert(sheet, row);
    }
    if r.changed() {
        state.pending.entry(key).or_default().text = text.clone();
    }
    if r.lost_focus() {
        if ui.input(|i| i.key_pressed(Key::Escape)) {
            state.pending.remove(&key);
        } else if state.pending.contains_key(&key) {
            actions.push(Action::Commit(key, text));
        }
    }
}

impl LadderApp {
    /// Draws the table the project tree selected.
    pub fn tables_ui(&mut self, ui: &mut egui::Ui) {
        let Some(generation) = self.doc.as_ref().map(|d| d.generation) else {
            return;
        };
        // Drafts belong to the rows they were typed in: after an undo, another document or
        // another view those may be other rows, so the drafts go.
        if self.tables.seen != Some((self.view, generation)) {
            self.tables.forget_drafts();
        }
        let lang = self.settings.lang;
        match self.view {
            View::Symbols(t) => {
                let name = self
                    .doc
                    .as_ref()
                    .and_then(|d| d.project().symbol_tables.get(t))
                    .map(|t| t.name.clone());
                match name {
                    Some(name) => {
                        ui.heading(name);
                        self.sheet_ui(ui, Sheet::Symbols(t));
                    }
                    None => {
                        ui.label(Msg::TblNoSuchTable.text(lang));
                    }
                }
            }
            View::Data => self.data_ui(ui),
            View::Messages => self.titled_sheet_ui(ui, Msg::Messages, Sheet::Messages),
            View::Diagnosis => self.titled_sheet_ui(ui, Msg::Diagnosis, Sheet::Diagnosis),
            View::Permissions => self.titled_sheet_ui(ui, Msg::Permissions, Sheet::Permissions),
            View::MCodes => self.titled_sheet_ui(ui, Msg::MCodes, Sheet::MCodes),
            View::Version => self.version_ui(ui),
            View::Block(_) | View::RefIndex | View::RefBits | View::RefBytes => {}
        }
        if let Some(doc) = &self.doc {
            self.tables.seen = Some((self.view, doc.generation));
        }
    }

    fn titled_sheet_ui(&mut self, ui: &mut egui::Ui, title: Msg, sheet: Sheet) {
        ui.heading(title.text(self.settings.lang));
        self.sheet_ui(ui, sheet);
    }

    /// The data-setting view: a tab per table, the K page first (§3.4.4).
    fn data_ui(&mut self, ui: &mut egui::Ui) {
        let lang = self.settings.lang;
        ui.horizontal(|ui| {
            for (tab, msg) in [
                (DataTab::K, Msg::TblKPage),
                (DataTab::D, Msg::TblTabD),
                (DataTab::DFloat, Msg::TblTabDFloat),
                (DataTab::Dt, Msg::TblTabDt),
                (DataTab::Dc, Msg::TblTabDc),
            ] {
                ui.selectable_value(&mut self.tables.data_tab, tab, msg.text(lang));
            }
        });
        ui.separator();
        match self.tables.data_tab {
            DataTab::K => self.k_page_ui(ui),
            DataTab::D => self.sheet_ui(ui, Sheet::D),
            DataTab::DFloat => self.sheet_ui(ui, Sheet::DFloat),
            DataTab::Dt => self.sheet_ui(ui, Sheet::Dt),
            DataTab::Dc => self.sheet_ui(ui, Sheet::Dc),
        }
    }

    fn row_height(ui: &egui::Ui) -> f32 {
        ui.spacing().interact_size.y + 6.0
    }

    /// A row table: the row toolbar, then the grid with a row header (click selects,
    /// right-click opens the row menu), the cells, and why the row's input was refused.
    fn sheet_ui(&mut self, ui: &mut egui::Ui, sheet: Sheet) {
        let lang = self.settings.lang;
        let t = |m: Msg| m.text(lang);
        let Some(doc) = self.doc.as_ref() else {
            return;
        };
        let project = doc.project();
        let state = &mut self.tables;
        let len = sheet.len(project);
        // Growing tables end in an empty line: typing its address (or code) adds a row.
        let shown = if sheet.fixed() { len } else { len + 1 };
        let selected = state.selected.get(&sheet).copied().filter(|r| *r < shown);
        let mut actions = Vec::new();
        ui.horizontal(|ui| {
            for op in RowOp::ALL {
                if row_op_button(ui, sheet, op, selected, len, lang) {
                    actions.push(Action::Op(sheet, op, selected.unwrap_or(len)));
                }
            }
            if let Some((s, e)) = state.op_error
                && s == sheet
            {
                ui.colored_label(ERROR_RED, t(e));
            }
        });
        let row_height = Self::row_height(ui);
        let mut builder = TableBuilder::new(ui)
            .id_salt(sheet)
            .striped(true)
            .resizable(true)
            .cell_layout(egui::Layout::left_to_right(egui::Align::Center))
            .column(Column::exact(48.0));
        for col in sheet.columns() {
            builder = builder.column(col.column());
        }
        builder = builder.column(Column::remainder().at_least(160.0).clip(true));
        if let Some((_, row)) = state.scroll_to.take_if(|(s, _)| *s == sheet) {
            builder = builder.scroll_to_row(row, None);
        }
        builder
            .header(row_height, |mut header| {
                header.col(|ui| {
                    ui.strong(t(Msg::TblRow));
                });
                for col in sheet.columns() {
                    header.col(|ui| {
                        ui.strong(t(col.title()));
                    });
                }
                header.col(|ui| {
                    ui.strong(t(Msg::TblProblem));
                });
            })
            .body(|body| {
                body.rows(row_height, shown, |mut row| {
                    let i = row.index();
                    row.set_selected(selected == Some(i));
                    row.col(|ui| {
                        let r = ui.add(
                            egui::Label::new((i + 1).to_string())
                                .sense(Sense::click())
                                .selectable(false),
                        );
                        if r.clicked() || r.secondary_clicked() {
                            state.selected.insert(sheet, i);
                        }
                        r.context_menu(|ui| {
                            for op in RowOp::ALL {
                                if row_op_button(ui, sheet, op, Some(i), len, lang) {
                                    actions.push(Action::Op(sheet, op, i));
                                    ui.close();
                                }
                            }
                        });
                    });
                    for &col in sheet.columns() {
                        row.col(|ui| {
                            cell_ui(ui, state, project, (sheet, i, col), len, lang, &mut actions)
                        });
                    }
                    row.col(|ui| {
                        if let Some(e) = state.row_error(sheet, i) {
                            ui.colored_label(ERROR_RED, e).on_hover_text(e);
                        }
                    });
                });
            });
        self.run_actions(actions);
    }

    /// The K page: a line per K byte of the profile, a checkbox per bit (7 … 0), the byte in
    /// hex; hovering a bit shows its symbol and comment from the symbol tables.
    fn k_page_ui(&mut self, ui: &mut egui::Ui) {
        let lang = self.settings.lang;
        let t = |m: Msg| m.text(lang);
        let Some(doc) = self.doc.as_ref() else {
            return;
        };
        let project = doc.project();
        let data = &project.data;
        let (lo, hi) = project.profile().range(Area::K);
        let mut actions = Vec::new();
        let row_height = Self::row_height(ui);
        TableBuilder::new(ui)
            .id_salt("k-page")
            .striped(true)
            .cell_layout(egui::Layout::left_to_right(egui::Align::Center))
            .column(Column::exact(80.0))
            .columns(Column::exact(28.0), 8)
            .column(Column::remainder())
            .header(row_height, |mut header| {
                header.col(|ui| {
                    ui.strong(t(Msg::TblAddress));
                });
                for bit in (0..8).rev() {
                    header.col(|ui| {
                        ui.strong(bit.to_string());
                    });
                }
                header.col(|ui| {
                    ui.strong(t(Msg::TblHex));
                });
            })
            .body(|body| {
                body.rows(row_height, usize::from(hi - lo) + 1, |mut row| {
                    let number = usize::from(lo) + row.index();
                    row.col(|ui| {
                        ui.label(Address::byte(Area::K, number as u16).to_string());
                    });
                    for bit in (0..8u8).rev() {
                        row.col(|ui| {
                            let address = Address::bit(Area::K, number as u16, bit);
                            let mut on = data.k_bit(number, bit);
                            let r = ui
                                .add(egui::Checkbox::without_text(&mut on))
                                .accessible_name(address.to_string());
                            if r.changed() {
                                actions.push(Action::KBit { number, bit, on });
                            }
                            // Looked up only while hovered: a scan of every symbol per bit
                            // per frame would not stay cheap with thousands of symbols.
                            r.on_hover_ui(|ui| {
                                ui.label(address.to_string());
                                if let Some(s) = project.symbols().find(|s| s.address == address) {
                                    ui.label(&s.name);
                                    if let Some(c) = s.comments.get(lang.code()) {
                                        ui.label(c);
                                    }
                                }
                            });
                        });
                    }
                    row.col(|ui| {
                        let byte = data.k.get(number).copied().unwrap_or(0);
                        ui.monospace(format!("{byte:02X}"));
                    });
                });
            });
        self.run_actions(actions);
    }

    /// Applies what the user did this frame, one table edit per action.
    fn run_actions(&mut self, actions: Vec<Action>) {
        let lang = self.settings.lang;
        for action in actions {
            let Some(project) = self.doc.as_ref().map(|d| d.project()) else {
                return;
            };
            match action {
                Action::Commit(key, text) => {
                    let (sheet, row, col) = key;
                    match commit(project, sheet, row, col, &text, lang) {
                        Ok(edit) => {
                            self.tables.pending.remove(&key);
                            if let Some(edit) = edit {
                                self.edit_table(edit);
                            }
                        }
                        Err(e) => {
                            self.tables.pending.insert(
                                key,
                                Pending {
                                    text,
                                    error: Some(e),
                                },
                            );
                        }
                    }
                }
                Action::Op(sheet, op, row) => match row_op(project, sheet, op, row) {
                    Ok((edit, select)) => {
                        // Rows moved: what was typed in this table's rows no longer matches.
                        self.tables
                            .pending
                            .retain(|k, _| k.0 != sheet || (op == RowOp::Clear && k.1 != row));
                        self.tables.op_error = None;
                        self.tables.selected.insert(sheet, select);
                        self.tables.scroll_to = Some((sheet, select));
                        if let Some(edit) = edit {
                            self.edit_table(edit);
                        }
                    }
                    Err(e) => self.tables.op_error = Some((sheet, e)),
                },
                Action::KBit { number, bit, on } => {
                    let mut data = project.data.clone();
                    data.set_k_bit(number, bit, on);
                    if let Some(edit) =
                        changed(&project.data, data, |d| TableEdit::Data(Box::new(d)))
                    {
                        self.edit_table(edit);
                    }
                }
            }
        }
    }

    /// The version information (§3.4.7): designer, version and remarks with their lengths,
    /// and the ladder password, kept only as a salted hash.
    fn version_ui(&mut self, ui: &mut egui::Ui) {
        let lang = self.settings.lang;
        let t = |m: Msg| m.text(lang);
        let Some(doc) = self.doc.as_ref() else {
            return;
        };
        let current = doc.project().version.clone();
        ui.heading(t(Msg::VersionInfo));
        let mut commit = false;
        egui::Grid::new("version-info")
            .num_columns(3)
            .spacing([12.0, 8.0])
            .show(ui, |ui| {
                let fields = [
                    (Msg::TblDesigner, DESIGNER_MAX, &current.designer),
                    (Msg::TblVersion, VERSION_MAX, &current.version),
                    (Msg::TblRemarks, REMARKS_MAX, &current.remarks),
                ];
                for (i, (msg, max, saved)) in fields.into_iter().enumerate() {
                    let label = ui.label(t(msg));
                    let draft = &mut self.tables.version[i];
                    let mut text = draft.clone().unwrap_or_else(|| saved.clone());
                    let edit = if i == 2 {
                        egui::TextEdit::multiline(&mut text).desired_rows(6)
                    } else {
                        egui::TextEdit::singleline(&mut text)
                    };
                    let r = ui
                        .add(edit.char_limit(max).desired_width(480.0))
                        .labelled_by(label.id);
                    if r.changed() {
                        *draft = Some(text.clone());
                    }
                    if r.lost_focus() {
                        if ui.input(|i| i.key_pressed(Key::Escape)) {
                            *draft = None;
                        } else if draft.is_some() {
                            commit = true;
                        }
                    }
                    ui.label(format!("{}/{max}", text.chars().count()));
                    ui.end_row();
                }
            });
        if commit {
            let [d, v, r] = std::mem::take(&mut self.tables.version);
            let mut next = current.clone();
            next.set(
                &d.unwrap_or(current.designer.clone()),
                &v.unwrap_or(current.version.clone()),
                &r.unwrap_or(current.remarks.clone()),
            );
            if let Some(edit) = changed(&current, next, |v| TableEdit::Version(Box::new(v))) {
                self.edit_table(edit);
            }
        }
        ui.separator();
        self.password_ui(ui, &current);
    }

    fn password_ui(&mut self, ui: &mut egui::Ui, current: &ladder_engine::model::VersionInfo) {
        let lang = self.settings.lang;
        let t = |m: Msg| m.text(lang);
        let is_set = current.password.is_some();
        ui.strong(t(Msg::TblPassword));
        ui.label(t(if is_set {
            Msg::TblPasswordIsSet
        } else {
            Msg::TblPasswordNone
        }));
        let draft = &mut self.tables.password;
        egui::Grid::new("version-password")
            .num_columns(2)
            .spacing([12.0, 8.0])
            .show(ui, |ui| {
                let field = |ui: &mut egui::Ui, msg: Msg, text: &mut String| {
                    let label = ui.label(t(msg));
                    ui.add(egui::TextEdit::singleline(text).password(true))
                        .labelled_by(label.id);
                    ui.end_row();
                };
                if is_set {
                    field(ui, Msg::TblPasswordCurrent, &mut draft.current);
                }
                field(ui, Msg::TblPasswordNew, &mut draft.new);
                field(ui, Msg::TblPasswordConfirm, &mut draft.confirm);
            });
        let mut set = false;
        let mut clear = false;
        ui.horizontal(|ui| {
            set = ui.button(t(Msg::TblSetPassword)).clicked();
            clear = ui
                .add_enabled(is_set, egui::Button::new(t(Msg::TblClearPassword)))
                .clicked();
        });
        if set || clear {
            // Changing or removing a password takes the current one, as on the CNC.
            let refusal = if is_set
                && !current
                    .password
                    .as_ref()
                    .is_some_and(|p| p.matches(&draft.current))
            {
                Some(Msg::TblPasswordWrong)
            } else if set && draft.new.is_empty() {
                Some(Msg::TblPasswordEmpty)
            } else if set && draft.new != draft.confirm {
                Some(Msg::TblPasswordMismatch)
            } else {
                None
            };
            let read_only = self.doc.as_ref().is_some_and(|d| d.read_only);
            if let Some(m) = refusal {
                draft.note = Some((true, m));
            } else if read_only {
                draft.note = Some((true, Msg::ReadOnly));
            } else {
                let mut next = current.clone();
                next.password = set.then(|| PasswordHash::new(&draft.new, &new_salt()));
                self.tables.password = PasswordDraft {
                    note: Some((
                        false,
                        if set {
                            Msg::TblPasswordSaved
                        } else {
                            Msg::TblPasswordCleared
                        },
                    )),
                    ..PasswordDraft::default()
                };
                self.edit_table(TableEdit::Version(Box::new(next)));
            }
        }
        if let Some((error, m)) = self.tables.password.note {
            ui.colored_label(if error { ERROR_RED } else { OK_GREEN }, t(m));
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::gui::i18n::Lang;
    use egui::accesskit::Role;
    use egui_kittest::Harness;
    use egui_kittest::kittest::{NodeT, Queryable};
    use ladder_engine::model::SymbolTable;
    use std::path::PathBuf;

    /// The editor on a saved copy of `project`, in English, showing `view`.
    fn harness(project: &Project, name: &str, view: View) -> Harness<'static, LadderApp> {
        let dir: PathBuf =
            std::env::temp_dir().join(format!("ladder-tables-test-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let path = dir.join(format!("{name}.ldp"));
        ladder_engine::file::save(project, &path).unwrap();
        let mut h = Harness::builder()
            .with_size(egui::vec2(1280.0, 800.0))
            .build_eframe(move |cc| {
                let mut app = LadderApp::from_creation(cc, Some(path));
                app.settings.lang = Lang::En;
                app
            });
        h.run();
        h.state_mut().view = view;
        h.run();
        h
    }

    fn project<'a>(h: &'a Harness<'static, LadderApp>) -> &'a Project {
        h.state().doc.as_ref().unwrap().project()
    }

    /// Clicks a cell, replaces its text and presses Enter, as a user does.
    fn enter(h: &mut Harness<'static, LadderApp>, cell: &str, text: &str) {
        enter_as(h, Role::TextInput, cell, text);
    }

    fn enter_as(h: &mut Harness<'static, LadderApp>, role: Role, cell: &str, text: &str) {
        h.get_by_role_and_label(role, cell).click();
        h.run();
        h.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::A);
        h.get_by_role_and_label(role, cell).type_text(text);
        h.run();
        h.key_press(egui::Key::Enter);
        h.run();
    }

    fn cell_value(h: &Harness<'static, LadderApp>, cell: &str) -> String {
        h.get_by_role_and_label(Role::TextInput, cell)
            .value()
            .unwrap_or_default()
    }

    fn undo_all(h: &mut Harness<'static, LadderApp>) {
        while h.state().doc.as_ref().unwrap().history().undo_len() > 0 {
            h.state_mut().undo();
        }
        h.run();
    }

    fn symbols(rows: &[(&str, &str)]) -> Project {
        let mut p = Project::default();
        p.symbol_tables[0].rows = rows
            .iter()
            .map(|(a, n)| Symbol {
                name: (*n).into(),
                address: Address::parse(a).unwrap(),
                comments: Comments::new(),
            })
            .collect();
        p
    }

    #[test]
    fn symbols_are_entered_checked_and_undone() {
        let original = Project::default();
        let mut h = harness(&original, "symbols", View::Symbols(0));
        enter(&mut h, "Address 1", "r10.1");
        enter(&mut h, "Symbol 1", "START");
        enter(&mut h, "Comment 1", "cycle start");
        let row = &project(&h).symbol_tables[0].rows[0];
        assert_eq!(row.address, Address::bit(Area::R, 10, 1));
        assert_eq!(row.name, "START");
        assert_eq!(
            row.comments.get("en").map(String::as_str),
            Some("cycle start")
        );
        assert_eq!(cell_value(&h, "Address 1"), "R0010.1", "shown canonical");

        let before = project(&h).symbol_tables.clone();
        for (text, reason) in [
            ("Z99", "has no such address area"),
            ("R1000", "R1000 is out of range (R0–R999)"),
            ("L1", "only these areas belong here"),
            ("R10.1", "address already listed: 符号表1 #1"),
        ] {
            enter(&mut h, "Address 2", text);
            h.get_by_label_contains(reason);
            assert_eq!(project(&h).symbol_tables, before, "{text} is refused");
            assert_eq!(cell_value(&h, "Address 2"), text, "and stays to be fixed");
        }
        enter(&mut h, "Address 2", "R10.2");
        assert!(
            h.query_by_label_contains("address already listed")
                .is_none(),
            "a valid entry clears the message"
        );
        let before = project(&h).symbol_tables.clone();
        for (text, reason) in [
            ("START", "symbol already exists: 符号表1 #1"),
            ("1ABC", "A symbol is letters"),
            ("X1", "A symbol is letters"),
        ] {
            enter(&mut h, "Symbol 2", text);
            h.get_by_label_contains(reason);
            assert_eq!(project(&h).symbol_tables, before, "{text} is refused");
        }
        h.key_press(egui::Key::Escape);
        h.run();

        // Ctrl+Z (no field has the keyboard after Enter) takes back the last row.
        h.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::Z);
        h.run();
        assert_eq!(project(&h).symbol_tables[0].rows.len(), 1);
        undo_all(&mut h);
        assert_eq!(project(&h).symbol_tables, original.symbol_tables);
    }

    #[test]
    fn the_row_menu_inserts_clears_and_deletes() {
        let original = symbols(&[("R0.0", "A"), ("R0.1", "B"), ("R0.2", "C")]);
        let mut h = harness(&original, "rows", View::Symbols(0));
        let rows = |h: &Harness<'static, LadderApp>| project(h).symbol_tables[0].rows.clone();

        h.get_by_label("2").click();
        h.run();
        h.get_by_label("Insert row above").click();
        h.run();
        let r = rows(&h);
        assert_eq!(r.len(), 4);
        assert_eq!(
            (r[1].address.to_string(), r[1].name.as_str()),
            ("R0000.3".to_string(), ""),
            "a new row at the next free address"
        );
        assert_eq!(h.state().tables.selected[&Sheet::Symbols(0)], 1);
        h.get_by_label("Delete row").click();
        h.run();
        assert_eq!(rows(&h), original.symbol_tables[0].rows);

        h.get_by_label("3").click_secondary();
        h.run();
        let menu = h.get_all_by_label("Clear row").last().unwrap();
        menu.click();
        h.run();
        let r = rows(&h);
        assert_eq!(r[2].name, "", "cleared");
        assert_eq!(
            r[2].address,
            Address::bit(Area::R, 0, 2),
            "its address kept"
        );

        h.get_by_label("1").click();
        h.run();
        h.get_by_label("Insert row below").click();
        h.run();
        assert_eq!(rows(&h)[1].address, Address::bit(Area::R, 0, 3));

        h.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::Z);
        h.run();
        h.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::Z);
        h.run();
        h.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::Z);
        h.run();
        h.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::Z);
        h.run();
        assert_eq!(project(&h).symbol_tables, original.symbol_tables);
    }

    #[test]
    fn a_k_bit_toggles_exactly_that_bit() {
        let original = Project::default();
        let mut h = harness(&original, "kpage", View::Data);
        h.get_by_label("K0003.5").click();
        h.run();
        assert_eq!(project(&h).data.k, vec![0, 0, 0, 0x20]);
        h.get_by_label("K0003.0").click();
        h.run();
        assert_eq!(project(&h).data.k, vec![0, 0, 0, 0x21]);
        h.get_by_label("21");
        h.get_by_label("K0003.5").click();
        h.run();
        assert_eq!(project(&h).data.k, vec![0, 0, 0, 0x01]);
        h.key_press_modifiers(egui::Modifiers::COMMAND, egui::Key::Z);
        h.run();
        assert_eq!(project(&h).data.k, vec![0, 0, 0, 0x21]);
        undo_all(&mut h);
        assert_eq!(
            project(&h).data,
            original.data,
            "the page as it was, length too"
        );
    }

    #[test]
    fn data_values_are_clamped_where_the_user_sees_them() {
        let mut original = Project::default();
        let mut row = DataRow::new(Address::byte(Area::D, 10), 50);
        row.set_max(Some(100));
        original.data.d.push(row);
        let mut h = harness(&original, "data", View::Data);
        h.get_by_label("D").click();
        h.run();
        enter(&mut h, "Initial value 1", "500");
        assert_eq!(project(&h).data.d[0].value, 100);
        assert_eq!(
            cell_value(&h, "Initial value 1"),
            "100",
            "the clamp shows at once"
        );
        enter(&mut h, "Min 1", "200");
        assert_eq!(project(&h).data.d[0].min, Some(100), "a min above the max");
        enter(&mut h, "Initial value 1", "ten");
        h.get_by_label_contains("Enter a whole number");
        assert_eq!(project(&h).data.d[0].value, 100);
        h.key_press(egui::Key::Escape);
        h.run();

        let before = project(&h).data.clone();
        enter(&mut h, "Address 1", "DT5");
        h.get_by_label_contains("only these areas belong here: D");
        enter(&mut h, "Address 1", "D1000");
        h.get_by_label_contains("D1000 is out of range (D0–D999)");
        assert_eq!(project(&h).data, before);
        enter(&mut h, "Address 1", "d11");
        enter(&mut h, "Address 2", "d12");
        assert_eq!(
            project(&h)
                .data
                .d
                .iter()
                .map(|r| r.address.to_string())
                .collect::<Vec<_>>(),
            ["D0011", "D0012"]
        );

        h.get_by_label("D_FLOAT").click();
        h.run();
        enter(&mut h, "Address 1", "D11");
        h.get_by_label_contains("address already listed: D #1");
        assert!(project(&h).data.d_float.is_empty());
        enter(&mut h, "Address 1", "D20");
        enter(&mut h, "Max 1", "2.5");
        enter(&mut h, "Initial value 1", "7.25");
        assert_eq!(project(&h).data.d_float[0].value, 2.5);

        h.get_by_label("DT").click();
        h.run();
        enter(&mut h, "Address 1", "D5");
        h.get_by_label_contains("only these areas belong here: DT");
        assert!(project(&h).data.dt.is_empty());

        undo_all(&mut h);
        assert_eq!(project(&h).data, original.data);
    }

    #[test]
    fn the_message_table_has_a_row_per_a_bit_and_scrolls() {
        let original = Project::default();
        let mut h = harness(&original, "messages", View::Messages);
        h.get_by_label("A0000.0");
        assert!(
            h.query_by_label("A0049.7").is_none(),
            "only visible rows are laid out"
        );
        assert!(
            h.get_by_label("Insert row above")
                .accesskit_node()
                .is_disabled()
        );
        assert!(h.get_by_label("Delete row").accesskit_node().is_disabled());
        let at = h.get_by_label("A0000.0").rect().center();
        h.hover_at(at);
        h.event(egui::Event::MouseWheel {
            unit: egui::MouseWheelUnit::Point,
            delta: egui::vec2(0.0, -100_000.0),
            phase: egui::TouchPhase::Move,
            source: egui::MouseWheelSource::Wheel,
            modifiers: egui::Modifiers::NONE,
        });
        // The wheel scrolls smoothly over a few frames.
        h.run_steps(20);
        h.get_by_label("A0049.7");
        assert!(h.query_by_label("Alarm number 401").is_none(), "400 rows");
        enter(&mut h, "Alarm number 400", "1234");
        enter(&mut h, "Message text 400", "Oil level low");
        let m = &project(&h).messages.rows[399];
        assert_eq!(m.number, Some(1234));
        assert_eq!(m.texts.get("en").map(String::as_str), Some("Oil level low"));
        enter(&mut h, "Alarm number 399", "1234");
        h.get_by_label_contains("1234: alarm number already used by A0049.7");
        enter(&mut h, "Alarm number 399", "999");
        h.get_by_label_contains("Alarm numbers are 1000–9999");
        assert_eq!(project(&h).messages.rows[398], Message::default());

        h.get_by_label("400").click_secondary();
        h.run();
        h.get_all_by_label("Clear row").last().unwrap().click();
        h.run();
        assert_eq!(project(&h).messages, original.messages);
        h.state_mut().undo();
        assert_eq!(project(&h).messages.rows[399].number, Some(1234));
    }

    #[test]
    fn diagnosis_permissions_and_m_codes_are_edited_and_checked() {
        let original = Project::default();
        let mut h = harness(&original, "misc", View::MCodes);
        enter(&mut h, "M code 1", "m3");
        enter(&mut h, "Comment 1", "spindle CW");
        assert_eq!(project(&h).m_codes[0].code, 3);
        assert_eq!(cell_value(&h, "M code 1"), "M03");
        enter(&mut h, "M code 2", "M03");
        h.get_by_label_contains("M03: This M code is already listed");
        enter(&mut h, "M code 2", "10000");
        h.get_by_label_contains("M codes are 0–9999");
        assert_eq!(project(&h).m_codes.len(), 1);
        h.key_press(egui::Key::Escape);
        h.run();

        h.state_mut().view = View::Diagnosis;
        h.run();
        enter(&mut h, "Address 1", "k2.1");
        enter(&mut h, "Address 2", "K2.1");
        h.get_by_label_contains("K0002.1: address already listed: #1");
        enter(&mut h, "Address 2", "P1");
        h.get_by_label_contains("only these areas belong here");
        assert_eq!(project(&h).diagnosis.len(), 1);
        let long = "x".repeat(128);
        enter(&mut h, "Comment 1", &long);
        h.get_by_label_contains("at most 127 bytes");
        assert!(project(&h).diagnosis[0].comments.is_empty());

        h.state_mut().view = View::Permissions;
        h.run();
        h.get_by_label("Insert row below").click();
        h.run();
        assert_eq!(
            project(&h).permissions[0].address,
            Address::byte(Area::K, 0)
        );
        undo_all(&mut h);
        assert_eq!(*project(&h), original);
    }

    #[test]
    fn version_fields_show_their_limits_and_the_password_is_hashed() {
        let original = Project::default();
        let mut h = harness(&original, "version", View::Version);
        enter(&mut h, "Designer", "Li Wei");
        h.get_by_label("6/63");
        enter(&mut h, "Version", &"9".repeat(30));
        assert_eq!(project(&h).version.designer, "Li Wei");
        assert_eq!(project(&h).version.version, "9".repeat(19), "cut at 19");
        h.get_by_label("19/19");

        enter_as(&mut h, Role::PasswordInput, "New password", "s3cret");
        enter_as(&mut h, Role::PasswordInput, "Confirm password", "s3crat");
        h.get_by_label("Set password").click();
        h.run();
        h.get_by_label("The two passwords differ");
        assert_eq!(project(&h).version.password, None);
        enter_as(&mut h, Role::PasswordInput, "Confirm password", "s3cret");
        h.get_by_label("Set password").click();
        h.run();
        let hash = project(&h).version.password.clone().expect("a password");
        assert!(hash.matches("s3cret") && !hash.hash.contains("s3cret"));
        assert!(
            h.state().tables.password.new.is_empty(),
            "the clear text is gone"
        );
        h.get_by_label("A password is set");

        h.get_by_label("Clear password").click();
        h.run();
        h.get_by_label("The current password is wrong");
        enter_as(&mut h, Role::PasswordInput, "Current password", "s3cret");
        h.get_by_label("Clear password").click();
        h.run();
        assert_eq!(project(&h).version.password, None);
        h.state_mut().undo();
        assert_eq!(project(&h).version.password, Some(hash));
        undo_all(&mut h);
        assert_eq!(project(&h).version, original.version);
    }

    #[test]
    fn a_big_symbol_table_lays_out_only_what_is_visible() {
        let p = Project {
            symbol_tables: vec![SymbolTable {
                name: "big".into(),
                rows: (0..8000u32)
                    .map(|i| Symbol {
                        name: format!("S{i}"),
                        address: Address::bit(Area::R, (i / 8) as u16, (i % 8) as u8),
                        comments: Comments::new(),
                    })
                    .collect(),
            }],
            ..Project::default()
        };
        let mut h = harness(&p, "big", View::Symbols(0));
        h.get_by_role_and_label(Role::TextInput, "Symbol 1");
        assert!(
            h.query_by_role_and_label(Role::TextInput, "Symbol 200")
                .is_none()
        );
        enter(&mut h, "Symbol 1", "S7999");
        h.get_by_label_contains("symbol already exists: big #8000");
    }

    #[test]
    fn helpers_find_free_keys_and_clamp_reals() {
        let p = ladder_engine::Profile::get(ladder_engine::ProfileId::Gsk988ta);
        let used = [Address::bit(Area::R, 999, 7), Address::bit(Area::R, 0, 0)];
        assert_eq!(
            next_free_address(Address::bit(Area::R, 999, 7), p, |a| used.contains(&a)),
            Some(Address::bit(Area::R, 0, 1)),
            "wraps round the area"
        );
        assert_eq!(
            next_free_address(Address::byte(Area::Dt, 0), p, |_| true),
            None
        );
        let mut r = real_row(Address::byte(Area::D, 0));
        r.set_value(5.0);
        set_real_max(&mut r, Some(2.0));
        set_real_min(&mut r, Some(3.0));
        assert_eq!((r.min, r.max, r.value), (Some(2.0), Some(2.0), 2.0));
        assert_ne!(new_salt(), new_salt());
    }
}
