//! The document as PDF, through krilla: it shapes the text with the bundled font, embeds only
//! the glyphs used (a subset, not the 5 MB collection), and writes the ToUnicode maps that
//! keep the text searchable and copyable.

use crate::font::{FONT, Metrics};
use crate::page::{Anchor, Document, Item, Seg};
use krilla::color::luma;
use krilla::geom::{PathBuilder, Point};
use krilla::num::NormalizedF32;
use krilla::page::PageSettings;
use krilla::paint::{Fill, Stroke};
use krilla::text::{Font, GlyphId, KrillaGlyph};

/// Why a PDF could not be made.
#[derive(Debug, thiserror::Error)]
pub enum PdfError {
    /// The bundled font did not load.
    #[error("the bundled font cannot be used")]
    Font,
    /// The PDF writer refused the document.
    #[error("the PDF cannot be written: {0}")]
    Write(String),
}

fn ink(g: u8) -> luma::Color {
    luma::Color::new(g)
}

/// The whole document as PDF bytes.
pub fn pdf(doc: &Document) -> Result<Vec<u8>, PdfError> {
    let font = Font::new(FONT.into(), 0).ok_or(PdfError::Font)?;
    let mut metrics = Metrics::new();
    let mut document = krilla::Document::new();
    document.set_metadata(
        krilla::metadata::Metadata::new()
            .title(doc.title.clone())
            .creator("Ladder Studio".to_string()),
    );
    let settings = || PageSettings::from_wh(doc.width, doc.height).ok_or(PdfError::Font);
    for page in &doc.pages {
        let mut p = document.start_page_with(settings()?);
        let mut surface = p.surface();
        for item in &page.items {
            match item {
                Item::Path {
                    segs,
                    width,
                    ink: k,
                } => {
                    let mut b = PathBuilder::new();
                    for s in segs {
                        match *s {
                            Seg::Move(x, y) => b.move_to(x, y),
                            Seg::Line(x, y) => b.line_to(x, y),
                            Seg::Cubic(a, c, d, e, x, y) => b.cubic_to(a, c, d, e, x, y),
                        }
                    }
                    if let Some(path) = b.finish() {
                        surface.set_fill(None);
                        surface.set_stroke(Some(Stroke {
                            paint: ink(k.grey()).into(),
                            width: *width,
                            ..Stroke::default()
                        }));
                        surface.draw_path(&path);
                    }
                }
                Item::Text {
                    x,
                    y,
                    size,
                    anchor,
                    ink: k,
                    text,
                } => {
                    let w = match anchor {
                        Anchor::Left => 0.0,
                        Anchor::Middle => metrics.width(text, *size) / 2.0,
                        Anchor::Right => metrics.width(text, *size),
                    };
                    surface.set_stroke(None);
                    surface.set_fill(Some(Fill {
                        paint: ink(k.grey()).into(),
                        opacity: NormalizedF32::ONE,
                        rule: Default::default(),
                    }));
                    // Glyphs from the layout's own metrics rather than krilla's shaper, which
                    // builds a shaping face for every text it draws (most of a long print).
                    let glyphs: Vec<KrillaGlyph> = metrics
                        .glyphs(text)
                        .into_iter()
                        .map(|(id, advance, range)| {
                            KrillaGlyph::new(
                                GlyphId::new(u32::from(id)),
                                advance,
                                0.0,
                                0.0,
                                0.0,
                                range,
                                None,
                            )
                        })
                        .collect();
                    surface.draw_glyphs(
                        Point::from_xy(x - w, *y),
                        &glyphs,
                        font.clone(),
                        text,
                        *size,
                        false,
                    );
                }
            }
        }
        surface.finish();
        p.finish();
    }
    document
        .finish()
        .map_err(|e| PdfError::Write(format!("{e:?}")))
}
