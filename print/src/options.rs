//! What a printed document holds and how it looks (the page setup).

use crate::page::Pt;

/// Paper sizes (kept in the editor's settings, hence serde).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub enum Paper {
    /// ISO A4, 210 × 297 mm.
    #[default]
    A4,
    /// ISO A3, 297 × 420 mm.
    A3,
    /// US Letter, 8.5 × 11 in.
    Letter,
}

impl Paper {
    /// Width and height in points, portrait.
    pub fn size(self) -> (Pt, Pt) {
        match self {
            Paper::A4 => (595.28, 841.89),
            Paper::A3 => (841.89, 1190.55),
            Paper::Letter => (612.0, 792.0),
        }
    }

    /// Reads `a4`, `a3` or `letter` (any case).
    pub fn parse(text: &str) -> Option<Paper> {
        match text.to_ascii_lowercase().as_str() {
            "a4" => Some(Paper::A4),
            "a3" => Some(Paper::A3),
            "letter" => Some(Paper::Letter),
            _ => None,
        }
    }
}

/// The language of the document's own words and of the comments printed.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum PrintLang {
    /// Chinese.
    #[default]
    Zh,
    /// English.
    En,
    /// Both, Chinese first.
    Both,
}

impl PrintLang {
    /// The comment languages printed, in order.
    pub fn comment_langs(self) -> &'static [&'static str] {
        match self {
            PrintLang::Zh => &["zh"],
            PrintLang::En => &["en"],
            PrintLang::Both => &["zh", "en"],
        }
    }

    /// A word of the document in this language.
    pub fn say(self, en: &str, zh: &str) -> String {
        match self {
            PrintLang::Zh => zh.to_string(),
            PrintLang::En => en.to_string(),
            PrintLang::Both => format!("{zh} {en}"),
        }
    }
}

/// How an element's operand is written, as the editor's display mode.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Labels {
    /// The address.
    #[default]
    Address,
    /// The symbol where there is one, else the address.
    Symbol,
    /// The address and, under it, the symbol.
    Both,
}

/// Which blocks are printed.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Blocks {
    /// Level 1.
    pub level1: bool,
    /// Level 2.
    pub level2: bool,
    /// The subprograms.
    pub subs: bool,
}

impl Blocks {
    /// Whether a block of this kind is printed.
    pub fn includes(&self, kind: &ladder_engine::model::BlockKind) -> bool {
        use ladder_engine::model::BlockKind;
        match kind {
            BlockKind::Level1 => self.level1,
            BlockKind::Level2 => self.level2,
            BlockKind::Sub { .. } => self.subs,
        }
    }
}

impl Default for Blocks {
    fn default() -> Self {
        Blocks {
            level1: true,
            level2: true,
            subs: true,
        }
    }
}

/// Everything the page setup decides.
#[derive(Clone, Debug, PartialEq)]
pub struct Options {
    /// Paper size.
    pub paper: Paper,
    /// Landscape rather than portrait.
    pub landscape: bool,
    /// Language of the document and its comments.
    pub lang: PrintLang,
    /// How operands are written.
    pub labels: Labels,
    /// Element comments under contacts and coils.
    pub element_comments: bool,
    /// The blocks printed.
    pub blocks: Blocks,
    /// Only these networks (block index, network index), when printing a selection.
    pub only: Option<Vec<(usize, usize)>>,
    /// The symbol, data-setting and message tables.
    pub tables: bool,
    /// The cross-reference index.
    pub xref: bool,
    /// The title page (project, controller, version, steps, contents).
    pub title_page: bool,
    /// The date printed on the title page and in the headers (`YYYY-MM-DD`).
    pub date: String,
}

impl Default for Options {
    fn default() -> Self {
        Options {
            paper: Paper::A4,
            landscape: false,
            lang: PrintLang::Zh,
            labels: Labels::Address,
            element_comments: true,
            blocks: Blocks::default(),
            only: None,
            tables: false,
            xref: false,
            title_page: true,
            date: String::new(),
        }
    }
}

impl Options {
    /// Page width and height in points.
    pub fn page_size(&self) -> (Pt, Pt) {
        let (w, h) = self.paper.size();
        if self.landscape { (h, w) } else { (w, h) }
    }
}

/// Today's date (UTC) as `YYYY-MM-DD`, for the title page and the headers.
pub fn today() -> String {
    let secs = std::time::SystemTime::now()
        .duration_since(std::time::UNIX_EPOCH)
        .map_or(0, |d| d.as_secs());
    let (y, m, d) = civil_from_days((secs / 86_400) as i64);
    format!("{y:04}-{m:02}-{d:02}")
}

/// The calendar date of a day counted from 1970-01-01 (proleptic Gregorian).
fn civil_from_days(z: i64) -> (i64, u32, u32) {
    let z = z + 719_468;
    let era = z.div_euclid(146_097);
    let doe = z.rem_euclid(146_097);
    let yoe = (doe - doe / 1460 + doe / 36_524 - doe / 146_096) / 365;
    let doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
    let mp = (5 * doy + 2) / 153;
    let d = (doy - (153 * mp + 2) / 5 + 1) as u32;
    let m = if mp < 10 { mp + 3 } else { mp - 9 } as u32;
    (yoe + era * 400 + i64::from(m <= 2), m, d)
}

/// Why a `BLOCK:N` or `BLOCK:FIRST-LAST` text names no networks (typed, so that each
/// language words it: `ladder_text::errors::networks_error`).
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum NetworksError {
    /// No `:` between the block and the numbers.
    #[error("`{text}`: write the network as BLOCK:N, e.g. LEVEL2:3")]
    Form {
        /// The whole text.
        text: String,
    },
    /// The block is not in the project.
    #[error("`{block}`: no such block (LEVEL1, LEVEL2 or a subprogram P0001…)")]
    NoSuchBlock {
        /// The block as written.
        block: String,
    },
    /// The numbers are not networks of the block (or not a range in order).
    #[error("`{numbers}`: {block} has networks 1 to {count} (write N or FIRST-LAST, e.g. 10-40)")]
    Range {
        /// The numbers as written.
        numbers: String,
        /// The block as written.
        block: String,
        /// Its networks.
        count: usize,
    },
}

/// Finds `BLOCK:N` or `BLOCK:FIRST-LAST` (`LEVEL2:3`, `LEVEL2:10-40`, `P0001:1`) in the
/// project: (block index, network index) of each network, or why the text names none.
pub fn networks(
    project: &ladder_engine::model::Project,
    text: &str,
) -> Result<Vec<(usize, usize)>, NetworksError> {
    let (block, n) = text.split_once(':').ok_or_else(|| NetworksError::Form {
        text: text.to_string(),
    })?;
    let b = project
        .ladder
        .blocks
        .iter()
        .position(|b| b.kind.label().eq_ignore_ascii_case(block))
        .ok_or_else(|| NetworksError::NoSuchBlock {
            block: block.to_string(),
        })?;
    let count = project.ladder.blocks[b].networks.len();
    let (first, last) = n.split_once('-').unwrap_or((n, n));
    let number = |t: &str| {
        t.trim()
            .parse::<usize>()
            .ok()
            .filter(|n| (1..=count).contains(n))
    };
    match (number(first), number(last)) {
        (Some(a), Some(z)) if a <= z => Ok((a - 1..z).map(|i| (b, i)).collect()),
        _ => Err(NetworksError::Range {
            numbers: n.to_string(),
            block: block.to_string(),
            count,
        }),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn days_become_calendar_dates() {
        assert_eq!(civil_from_days(0), (1970, 1, 1));
        assert_eq!(civil_from_days(20_789), (2026, 12, 2));
        assert_eq!(civil_from_days(19_782), (2024, 2, 29));
        assert_eq!(today().len(), 10);
    }
}
