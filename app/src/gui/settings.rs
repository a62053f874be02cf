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

/// The zoom steps of the ladder view, in percent.
pub const ZOOMS: [u16; 5] = [75, 100, 125, 150, 175];

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
    /// Whether network titles are shown.
    pub show_titles: bool,
    /// Whether the toolbars are shown.
    pub show_toolbar: bool,
    /// Whether the output window is shown.
    pub show_output: bool,
    /// Whether the project manager (tree) is shown.
    pub show_tree: bool,
    /// Whether the status bar is shown.
    pub show_status: bool,
}

impl Default for Settings {
    fn default() -> Self {
        Settings {
            lang: Lang::from_locale(std::env::var("LANG").ok().as_deref()),
            recent: Vec::new(),
            zoom: 100,
            display: DisplayMode::Address,
            show_comments: true,
            show_titles: true,
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

    /// The next zoom step up or down.
    pub fn step_zoom(&mut self, up: bool) {
        let i = ZOOMS.iter().position(|z| *z == self.zoom).unwrap_or(1);
        let i = if up {
            (i + 1).min(ZOOMS.len() - 1)
        } else {
            i.saturating_sub(1)
        };
        self.zoom = ZOOMS[i];
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
