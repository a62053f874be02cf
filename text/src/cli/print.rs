//! The command line's words about `print` (docs/printing.md).

use crate::Lang;

/// What `print` says.
#[derive(Debug)]
pub enum PrintText {
    /// `-o` names neither a PDF nor an SVG file.
    OutputKind {
        /// The output given.
        path: String,
    },
    /// `--date` not written as `YYYY-MM-DD`.
    BadDate {
        /// The date given.
        date: String,
    },
    /// `--network` names a block `--blocks` leaves out.
    BlockNotPrinted {
        /// The `--network` given.
        network: String,
    },
    /// `--page` beyond the document.
    PageRange {
        /// The page asked for.
        page: usize,
        /// The document's pages.
        total: usize,
    },
    /// The PDF written.
    Pages {
        /// The PDF file.
        path: String,
        /// Its pages.
        pages: usize,
    },
}

impl PrintText {
    /// The text in `lang`.
    pub fn text(&self, lang: Lang) -> String {
        match (self, lang) {
            (PrintText::OutputKind { path }, Lang::Zh) => {
                format!("{path}：输出文件须为 .pdf 或 .svg")
            }
            (PrintText::OutputKind { path }, Lang::En) => {
                format!("{path}: the output is a .pdf or a .svg file")
            }
            (PrintText::BadDate { date }, Lang::Zh) => {
                format!("--date {date}：日期应写成 YYYY-MM-DD，例如 2026-12-02")
            }
            (PrintText::BadDate { date }, Lang::En) => {
                format!("--date {date}: write the date as YYYY-MM-DD, e.g. 2026-12-02")
            }
            (PrintText::BlockNotPrinted { network }, Lang::Zh) => format!(
                "--network {network}：该程序块不在 --blocks 所选之中；请加上它或去掉 --blocks"
            ),
            (PrintText::BlockNotPrinted { network }, Lang::En) => format!(
                "--network {network}: that block is not among the --blocks printed; add it or leave --blocks out"
            ),
            (PrintText::PageRange { page, total }, Lang::Zh) => {
                format!("--page {page}：文档只有第 1 至 {total} 页")
            }
            (PrintText::PageRange { page, total }, Lang::En) => {
                format!("--page {page}: the document has pages 1 to {total}")
            }
            (PrintText::Pages { path, pages }, Lang::Zh) => format!("{path}：{pages} 页"),
            (PrintText::Pages { path, pages }, Lang::En) => format!("{path}: {pages} pages"),
        }
    }
}
