//! What the app remembers between runs (eframe persistence): language, recent files, zoom,
//! display mode. Projects are never stored here.

use super::i18n::Lang;
use serde::{Deserialize, Serialize};
use std::path::{Path, PathBuf};

/// How operands are shown in the ladder (manual §3.2.3).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub enum DisplayMode {
    /// Addresses.
    #[default]
    Address,
    /// Symbols where they exist.
    Symbol,
    /// `address: symbol`.
    Both,
}

/// How the online monitor writes a value.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub enum NumFormat {
    /// Signed decimal.
    #[default]
    Dec,
    /// Hexadecimal (`0x…`, two digits per byte).
    Hex,
    /// Binary, grouped by four.
    Bin,
    /// A 4-byte value as a real (D_FLOAT style).
    Real,
    /// 0/1 (bits).
    Bit,
}

impl NumFormat {
    /// Every format, in menu order.
    pub const ALL: [NumFormat; 5] = [
        NumFormat::Dec,
        NumFormat::Hex,
        NumFormat::Bin,
        NumFormat::Real,
        NumFormat::Bit,
    ];

    /// Its short name in lists (the same in both languages).
    pub fn name(self) -> &'static str {
        match self {
            NumFormat::Dec => "DEC",
            NumFormat::Hex => "HEX",
            NumFormat::Bin => "BIN",
            NumFormat::Real => "REAL",
            NumFormat::Bit => "BIT",
        }
    }

    /// `value` read at `bytes` wide, written in this format.
    pub fn show(self, value: i64, bytes: u32) -> String {
        let bits = 8 * bytes.clamp(1, 4);
        let raw = (value as u64) & ((1u64 << bits) - 1);
        match self {
            NumFormat::Dec => value.to_string(),
            NumFormat::Hex => format!("0x{raw:0w$X}", w = (bits / 4) as usize),
            NumFormat::Bin => {
                let digits = format!("{raw:0w$b}", w = bits as usize);
                let groups: Vec<&str> = digits
                    .as_bytes()
                    .chunks(4)
                    .map(|c| std::str::from_utf8(c).unwrap_or(""))
                    .collect();
                groups.join("_")
            }
            NumFormat::Real if bytes == 4 => format!("{}", f32::from_bits(raw as u32)),
            NumFormat::Real => value.to_string(),
            NumFormat::Bit => u8::from(value != 0).to_string(),
        }
    }
}

/// A watch-table row: an address or symbol as the user typed it, and its format.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct WatchRow {
    /// `X0002.3`, `D0010:2`, a symbol or `cnc.KEY`.
    pub text: String,
    /// How its value is written.
    pub format: NumFormat,
    /// Whether the signal trace charts it.
    pub traced: bool,
}

/// When a triggered capture fires: on an edge of a bit, or when a value starts to meet a
/// condition.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
pub enum TriggerWhen {
    /// A bit goes from 0 to 1.
    #[default]
    Rising,
    /// A bit goes from 1 to 0.
    Falling,
    /// A value becomes equal to the setup's value.
    Equal,
    /// A value becomes greater than the setup's value.
    Above,
    /// A value becomes less than the setup's value.
    Below,
}

impl TriggerWhen {
    /// Every condition, in the order the menu lists them.
    pub const ALL: [TriggerWhen; 5] = [
        TriggerWhen::Rising,
        TriggerWhen::Falling,
        TriggerWhen::Equal,
        TriggerWhen::Above,
        TriggerWhen::Below,
    ];

    /// Whether going from `before` to `now` meets it (a level that holds does not fire again).
    pub fn fires(self, before: i64, now: i64, value: i64) -> bool {
        let met = |v: i64| match self {
            TriggerWhen::Rising => v != 0,
            TriggerWhen::Falling => v == 0,
            TriggerWhen::Equal => v == value,
            TriggerWhen::Above => v > value,
            TriggerWhen::Below => v < value,
        };
        met(now) && !met(before)
    }
}

/// A trace's trigger, kept per project file with its watch rows.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(default)]
pub struct TriggerSetup {
    /// The signal watched: an address or a symbol.
    pub signal: String,
    /// The condition.
    pub when: TriggerWhen,
    /// The value the value conditions compare with.
    pub value: i64,
    /// Ticks kept before the trigger.
    pub pre: u64,
    /// Ticks kept after it.
    pub post: u64,
}

impl Default for TriggerSetup {
    fn default() -> Self {
        TriggerSetup {
            signal: String::new(),
            when: TriggerWhen::Rising,
            value: 0,
            pre: 125,
            post: 375,
        }
    }
}

/// The zoom steps of the ladder view, in percent.
pub const ZOOMS: [u16; 6] = [50, 75, 100, 125, 150, 175];

/// The zoom one step up or down from `zoom` (a zoom between the steps, as fit width makes,
/// goes to the next step that way).
pub fn next_zoom(zoom: u16, up: bool) -> u16 {
    if up {
        ZOOMS
            .into_iter()
            .find(|z| *z > zoom)
            .unwrap_or(ZOOMS[ZOOMS.len() - 1])
    } else {
        ZOOMS
            .into_iter()
            .rev()
            .find(|z| *z < zoom)
            .unwrap_or(ZOOMS[0])
    }
}

/// The zoom (percent, between the smallest and largest step) at which a ladder of `columns`
/// contact columns, its output column and margins fill `width` pixels.
pub fn fit_zoom(width: f32, columns: usize) -> u16 {
    // At 100 %: a 26 px margin, 84 px a contact column, 150 px the output column; 40 px of
    // room and a scroll bar do not scale.
    let at_100 = 26.0 + 84.0 * columns as f32 + 150.0;
    let z = ((width - 40.0 - 14.0) / at_100 * 100.0).floor();
    z.clamp(f32::from(ZOOMS[0]), f32::from(ZOOMS[ZOOMS.len() - 1])) as u16
}

/// Most recent files kept (GSKLadder lists four).
pub const RECENT_FILES: usize = 4;

/// Persisted settings.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct Settings {
    /// UI language.
    pub lang: Lang,
    /// Most recent first.
    pub recent: Vec<PathBuf>,
    /// Ladder zoom in percent.
    pub zoom: u16,
    /// Operand display.
    pub display: DisplayMode,
    /// Whether network comments are shown.
    pub show_comments: bool,
    /// Whether element comments are written under contacts and coils.
    pub show_element_comments: bool,
    /// Whether network titles are shown.
    pub show_titles: bool,
    /// Whether the toolbars are shown.
    pub show_toolbar: bool,
    /// Whether the output window is shown.
    pub show_output: bool,
    /// The output window's height, in points.
    pub output_height: f32,
    /// Whether the project manager (tree) is shown.
    pub show_tree: bool,
    /// Whether the status bar is shown.
    pub show_status: bool,
    /// Whether the online panel (machine, CNC, watch, forces, trace, alarms) is shown.
    pub show_online: bool,
    /// How function boxes show their live values.
    pub live_format: NumFormat,
    /// Ticks of "step N".
    pub step_ticks: u64,
    /// Watch tables by project file. A watch list is how one user looks at a machine, like
    /// the open tabs, not part of the program: it stays with the user's settings, so sharing
    /// a project never imposes one engineer's watch list on another (and never changes the
    /// project's checksum).
    pub watches: std::collections::BTreeMap<PathBuf, Vec<WatchRow>>,
    /// The trace's trigger by project file, as the watch rows are kept.
    pub triggers: std::collections::BTreeMap<PathBuf, TriggerSetup>,
    /// The ladder's zoom follows the view's width so the output column is always on screen
    /// (on when going online; a zoom step turns it off).
    pub fit_width: bool,
    /// The online panel in a native window of its own rather than beside the ladder.
    pub online_window: bool,
    /// The first network on screen in each block (by label) of each project file: a
    /// project opens again where each of its blocks was being read. Networks, not pixels,
    /// so the place survives another zoom or comments shown.
    pub tops: std::collections::BTreeMap<PathBuf, std::collections::BTreeMap<String, usize>>,
    /// The cursor (network, row, column) in each block of each project file, so the cursor
    /// comes back with the view.
    pub cursors:
        std::collections::BTreeMap<PathBuf, std::collections::BTreeMap<String, [usize; 3]>>,
    /// The page setup of printing, as last left.
    pub page_setup: PageSetup,
}

impl Default for Settings {
    fn default() -> Self {
        Settings {
            lang: Lang::from_locale(std::env::var("LANG").ok().as_deref()),
            recent: Vec::new(),
            zoom: 100,
            display: DisplayMode::Address,
            show_comments: true,
            show_element_comments: false,
            output_height: 140.0,
            show_titles: true,
            show_online: true,
            live_format: NumFormat::Dec,
            step_ticks: 10,
            watches: Default::default(),
            triggers: Default::default(),
            fit_width: false,
            online_window: false,
            tops: Default::default(),
            cursors: Default::default(),
            page_setup: Default::default(),
            show_toolbar: true,
            show_output: true,
            show_tree: true,
            show_status: true,
        }
    }
}

impl Settings {
    /// Puts a path first in the recent list.
    pub fn remember(&mut self, path: PathBuf) {
        let path = canonical(&path);
        self.recent.retain(|p| *p != path);
        self.recent.insert(0, path);
        self.recent.truncate(RECENT_FILES);
    }
}

/// The path with `.`, `..` and links resolved, so that two spellings of one file compare
/// equal; a file that does not exist yet gets its folder resolved.
pub fn canonical(path: &Path) -> PathBuf {
    if let Ok(p) = std::fs::canonicalize(path) {
        return p;
    }
    match (path.parent(), path.file_name()) {
        (Some(dir), Some(name)) => {
            let dir = if dir.as_os_str().is_empty() {
                Path::new(".")
            } else {
                dir
            };
            std::fs::canonicalize(dir).map_or_else(|_| path.to_path_buf(), |d| d.join(name))
        }
        _ => path.to_path_buf(),
    }
}

/// The page setup as the user left it: kept in the settings, never in the project.
#[derive(Clone, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
#[serde(default)]
pub struct PageSetup {
    /// Paper size.
    pub paper: ladder_print::Paper,
    /// Landscape pages.
    pub landscape: bool,
    /// Chinese and English (else the UI's language).
    pub both_languages: bool,
    /// The tables after the ladder.
    pub tables: bool,
    /// The cross-reference index.
    pub xref: bool,
    /// Element comments under contacts and coils.
    pub element_comments: bool,
    /// Only the selected networks (or the cursor's).
    pub selection_only: bool,
    /// Only these networks, as `BLOCK:FIRST-LAST` (`LEVEL2:10-40`); empty for all.
    pub networks: String,
    /// The printer chosen; `None` (or one no longer offered) is the system's default.
    pub printer: Option<String>,
}

impl Default for PageSetup {
    fn default() -> Self {
        PageSetup {
            paper: ladder_print::Paper::A4,
            landscape: false,
            both_languages: false,
            tables: false,
            xref: false,
            element_comments: true,
            selection_only: false,
            networks: String::new(),
            printer: None,
        }
    }
}
