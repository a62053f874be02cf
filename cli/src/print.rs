//! `print PATH -o OUT.pdf|OUT.svg`: the project as a printed document (docs/printing.md).

use super::say::{Say, shown};
use super::source::project_of;
use clap::ValueEnum;
use ladder_engine::file::write_atomic;
use ladder_print::{Blocks, Labels, Options, Paper, PrintLang};
use ladder_text::cli::PrintText;
use ladder_text::errors::{networks_error, pdf_error};
use std::io::Write;
use std::path::{Path, PathBuf};

/// Paper sizes on the command line.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum PaperArg {
    /// ISO A4.
    A4,
    /// ISO A3.
    A3,
    /// US Letter.
    Letter,
}

/// How operands are printed.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum OperandsArg {
    /// Addresses.
    Address,
    /// Symbols where they exist.
    Symbol,
    /// Address and symbol.
    Both,
}

/// The document's language.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum LanguageArg {
    /// Chinese.
    Zh,
    /// English.
    En,
    /// Chinese and English.
    Both,
}

/// A block on the command line.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum BlockArg {
    /// Level 1.
    Level1,
    /// Level 2.
    Level2,
    /// Every subprogram.
    Subs,
}

/// What `print` was asked for: its command-line arguments.
#[derive(clap::Args, Debug)]
pub struct PrintArgs {
    /// A project (.ldp) or an instruction list (.il).
    pub path: PathBuf,
    /// The document to write: OUT.pdf, or OUT.svg (one file per page, OUT-1.svg …).
    #[arg(short, long)]
    pub output: PathBuf,
    /// The blocks to print (default: all).
    #[arg(long, value_delimiter = ',', value_enum)]
    pub blocks: Vec<BlockArg>,
    /// Only this network or range of networks, as BLOCK:N or BLOCK:FIRST-LAST (LEVEL2:3,
    /// LEVEL2:10-40, P0001:1), without the title page.
    #[arg(long, visible_alias = "networks")]
    pub network: Option<String>,
    /// Also the symbol, data-setting and message tables.
    #[arg(long)]
    pub tables: bool,
    /// Also the cross-reference index.
    #[arg(long)]
    pub xref: bool,
    /// Paper size.
    #[arg(long, value_enum, default_value = "a4")]
    pub paper: PaperArg,
    /// Landscape pages.
    #[arg(long)]
    pub landscape: bool,
    /// The document's language (default: that of the messages).
    #[arg(long, value_enum)]
    pub language: Option<LanguageArg>,
    /// How operands are printed.
    #[arg(long, value_enum, default_value = "address")]
    pub operands: OperandsArg,
    /// Leave out the element comments under contacts and coils.
    #[arg(long)]
    pub no_comments: bool,
    /// Only this page (1 is the title page).
    #[arg(long)]
    pub page: Option<usize>,
    /// The date printed (YYYY-MM-DD; default: today).
    #[arg(long)]
    pub date: Option<String>,
}

enum Kind {
    Pdf,
    Svg,
}

/// Runs `print`.
pub(super) fn print(
    args: &PrintArgs,
    say: Say,
    out: &mut dyn Write,
    err: &mut dyn Write,
) -> anyhow::Result<i32> {
    let kind = match args
        .output
        .extension()
        .map(|e| e.to_string_lossy().to_ascii_lowercase())
        .as_deref()
    {
        Some("pdf") => Kind::Pdf,
        Some("svg") => Kind::Svg,
        _ => anyhow::bail!(say.text(PrintText::OutputKind {
            path: shown(&args.output)
        })),
    };
    if let Some(d) = args.date.as_deref()
        && !valid_date(d)
    {
        anyhow::bail!(say.text(PrintText::BadDate {
            date: d.to_string()
        }));
    }
    let project = match project_of(&args.path, say, err)? {
        Ok(p) => p,
        Err(code) => return Ok(code),
    };
    let only = match args.network.as_deref() {
        // The option's name stays as typed; the reason is in the language asked for.
        Some(text) => Some(
            ladder_print::networks(&project, text)
                .map_err(|e| anyhow::anyhow!("--network {}", networks_error(&e, say.lang())))?,
        ),
        None => None,
    };
    let blocks = if args.blocks.is_empty() {
        Blocks::default()
    } else {
        Blocks {
            level1: args.blocks.contains(&BlockArg::Level1),
            level2: args.blocks.contains(&BlockArg::Level2),
            subs: args.blocks.contains(&BlockArg::Subs),
        }
    };
    if let (Some(text), Some(&[(b, _), ..])) = (args.network.as_deref(), only.as_deref())
        && !blocks.includes(&project.ladder.blocks[b].kind)
    {
        anyhow::bail!(say.text(PrintText::BlockNotPrinted {
            network: text.to_string()
        }));
    }
    let lang = match args.language {
        Some(LanguageArg::Zh) => PrintLang::Zh,
        Some(LanguageArg::En) => PrintLang::En,
        Some(LanguageArg::Both) => PrintLang::Both,
        None if say.zh => PrintLang::Zh,
        None => PrintLang::En,
    };
    let options = Options {
        paper: match args.paper {
            PaperArg::A4 => Paper::A4,
            PaperArg::A3 => Paper::A3,
            PaperArg::Letter => Paper::Letter,
        },
        landscape: args.landscape,
        lang,
        labels: match args.operands {
            OperandsArg::Address => Labels::Address,
            OperandsArg::Symbol => Labels::Symbol,
            OperandsArg::Both => Labels::Both,
        },
        element_comments: !args.no_comments,
        blocks,
        title_page: only.is_none(),
        only,
        tables: args.tables,
        xref: args.xref,
        date: args.date.clone().unwrap_or_else(ladder_print::today),
    };
    let name = args
        .path
        .file_stem()
        .map(|s| s.to_string_lossy().into_owned())
        .unwrap_or_default();
    let doc = ladder_print::document(&project, &name, &options);
    let total = doc.pages.len();
    if let Some(p) = args.page
        && !(1..=total).contains(&p)
    {
        anyhow::bail!(say.text(PrintText::PageRange { page: p, total }));
    }
    let cannot = |p: &Path, e: std::io::Error| anyhow::anyhow!(say.cannot_write(p, e));
    match kind {
        Kind::Pdf => {
            let mut doc = doc;
            if let Some(p) = args.page {
                doc.pages = vec![doc.pages.swap_remove(p - 1)];
            }
            let bytes =
                ladder_print::pdf(&doc).map_err(|e| anyhow::anyhow!(pdf_error(&e, say.lang())))?;
            write_atomic(&args.output, &bytes).map_err(|e| cannot(&args.output, e))?;
            let n = doc.pages.len();
            let _ = writeln!(
                out,
                "{}",
                say.text(PrintText::Pages {
                    path: shown(&args.output),
                    pages: n
                })
            );
        }
        Kind::Svg => {
            let pages: Vec<usize> = match args.page {
                Some(p) => vec![p - 1],
                None => (0..total).collect(),
            };
            let count = pages.len();
            for i in pages {
                let path = ladder_print::svg_page_path(&args.output, i, count);
                let svg = ladder_print::page_svg(&doc, &doc.pages[i]);
                write_atomic(&path, svg.as_bytes()).map_err(|e| cannot(&path, e))?;
                let _ = writeln!(out, "{}", path.display());
            }
            if args.page.is_none() {
                remove_stale_pages(&args.output, count);
            }
        }
    }
    Ok(0)
}

/// Removes the pages an earlier, longer SVG print of the same name left after this one's
/// `count` (`OUT-<count+1>.svg` on; all numbered pages when this one is `OUT.svg` itself), so
/// the folder holds one document.
fn remove_stale_pages(output: &Path, count: usize) {
    let from = if count == 1 { 0 } else { count };
    for i in from.. {
        // Numbered as in a document of more than one page.
        let stale = ladder_print::svg_page_path(output, i, usize::MAX);
        if std::fs::remove_file(&stale).is_err() {
            break;
        }
    }
}

/// Whether `d` reads as `YYYY-MM-DD` with a month 1–12 and a day 1–31.
fn valid_date(d: &str) -> bool {
    let parts: Vec<&str> = d.split('-').collect();
    let num = |s: &str, len: usize| {
        (s.len() == len && s.bytes().all(|b| b.is_ascii_digit()))
            .then(|| s.parse::<u32>().ok())
            .flatten()
    };
    matches!(
        parts.as_slice(),
        [y, m, day] if num(y, 4).is_some()
            && num(m, 2).is_some_and(|m| (1..=12).contains(&m))
            && num(day, 2).is_some_and(|d| (1..=31).contains(&d))
    )
}
