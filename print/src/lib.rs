//! Printed documents of a Ladder Studio project (docs/printing.md): the pages laid out from
//! the project — a title page, the ladder network by network, optionally the tables and the
//! cross-reference — and written as PDF or as SVG pages. No GUI dependency: the command line
//! and the editor's preview share this one layout.

mod compose;
mod font;
mod ladder;
pub mod options;
pub mod page;
mod pages;
mod pdf;
mod svg;
mod tables;
mod title;

pub use compose::document;
pub use font::{FONT, Metrics};
pub use options::{Blocks, Labels, NetworksError, Options, Paper, PrintLang, networks, today};
pub use page::{Anchor, Document, Ink, Item, Page, Pt, Seg};
pub use pdf::{PdfError, pdf};
pub use svg::{page_svg, svg_page_path};
