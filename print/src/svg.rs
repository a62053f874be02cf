//! One page as SVG text: the same items the PDF draws, text left as text (searchable, and
//! drawn with a CJK font of the viewer's system).

use crate::page::{Anchor, Document, Item, Page, Seg};
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

fn escape(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            c if (c as u32) < 0x20 && c != '\t' => {}
            c => out.push(c),
        }
    }
    out
}

/// Page `page` of `doc` as a standalone SVG document, sized in points.
pub fn page_svg(doc: &Document, page: &Page) -> String {
    let (w, h) = (doc.width, doc.height);
    let mut out = String::new();
    let _ = writeln!(
        out,
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="{w:.2}pt" height="{h:.2}pt" viewBox="0 0 {w:.2} {h:.2}">"#
    );
    let _ = writeln!(out, "<title>{}</title>", escape(&doc.title));
    let _ = writeln!(out, r#"<rect width="100%" height="100%" fill="white"/>"#);
    let _ = writeln!(
        out,
        r#"<g font-family="WenQuanYi Micro Hei, Noto Sans CJK SC, Microsoft YaHei, sans-serif" fill="none" stroke-linecap="round">"#
    );
    for item in &page.items {
        match item {
            Item::Path { segs, width, ink } => {
                let mut d = String::new();
                for s in segs {
                    let _ = match s {
                        Seg::Move(x, y) => write!(d, "M{x:.2} {y:.2}"),
                        Seg::Line(x, y) => write!(d, "L{x:.2} {y:.2}"),
                        Seg::Cubic(a, b, c, e, x, y) => {
                            write!(d, "C{a:.2} {b:.2} {c:.2} {e:.2} {x:.2} {y:.2}")
                        }
                    };
                }
                let g = ink.grey();
                let _ = writeln!(
                    out,
                    r#"<path d="{d}" stroke="rgb({g},{g},{g})" stroke-width="{width:.2}"/>"#
                );
            }
            Item::Text {
                x,
                y,
                size,
                anchor,
                ink,
                text,
            } => {
                let anchor = match anchor {
                    Anchor::Left => "start",
                    Anchor::Middle => "middle",
                    Anchor::Right => "end",
                };
                let g = ink.grey();
                let _ = writeln!(
                    out,
                    r#"<text x="{x:.2}" y="{y:.2}" font-size="{size:.2}" text-anchor="{anchor}" fill="rgb({g},{g},{g})" stroke="none">{}</text>"#,
                    escape(text)
                );
            }
        }
    }
    out.push_str("</g>\n</svg>\n");
    out
}

/// Where page `index` (from 0) of a document of `count` pages goes when `output` is asked
/// for: `output` itself for a single page, else `STEM-N.svg` beside it, N from 1.
pub fn svg_page_path(output: &Path, index: usize, count: usize) -> PathBuf {
    if count == 1 {
        return output.to_path_buf();
    }
    let stem = output
        .file_stem()
        .map(|s| s.to_string_lossy().into_owned())
        .unwrap_or_default();
    output.with_file_name(format!("{stem}-{}.svg", index + 1))
}
