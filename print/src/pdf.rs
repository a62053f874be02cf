//! The document as PDF, through krilla: it sets the text in the bundled font's glyphs, embeds only
//! the glyphs used (a subset, not the 5 MB collection), and writes the ToUnicode maps that
//! keep the text searchable and copyable.

use crate::font::{FONT, Metrics};
use crate::page::{Anchor, Document, Item, Seg};
use krilla::color::luma;
use krilla::geom::{PathBuilder, Point};
use krilla::num::NormalizedF32;
use krilla::page::PageSettings;
use krilla::paint::{Fill, Stroke};
use krilla::surface::Surface;
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
    for page in &doc.pages {
        let settings = PageSettings::from_wh(doc.width, doc.height).ok_or(PdfError::Font)?;
        let mut p = document.start_page_with(settings);
        let mut surface = p.surface();
        let mut lines = Lines::default();
        for item in &page.items {
            match item {
                Item::Path {
                    segs,
                    width,
                    ink: k,
                } => lines.add(&mut surface, segs, *width, k.grey()),
                Item::Text {
                    x,
                    y,
                    size,
                    anchor,
                    ink: k,
                    text,
                } => {
                    // A text goes over the lines drawn before it, as the layout ordered them.
                    lines.flush(&mut surface);
                    let w = match anchor {
                        Anchor::Left => 0.0,
                        Anchor::Middle => metrics.width(text, *size) / 2.0,
                        Anchor::Right => metrics.width(text, *size),
                    };
                    text_at(
                        &mut surface,
                        &mut metrics,
                        (&font, *size),
                        Point::from_xy(x - w, *y),
                        text,
                        k.grey(),
                    );
                }
            }
        }
        lines.flush(&mut surface);
        surface.finish();
        p.finish();
    }
    document
        .finish()
        .map_err(|e| PdfError::Write(format!("{e:?}")))
}

/// Consecutive paths of one stroke width and ink, drawn as one path: a page of ladder is
/// thousands of short wires, and one drawing operation each cost a fifth of the print.
#[derive(Default)]
struct Lines {
    path: Option<PathBuilder>,
    stroke: (f32, u8),
}

impl Lines {
    /// Adds a path of `width` and ink `grey`, first drawing what is pending in another stroke.
    fn add(&mut self, surface: &mut Surface<'_>, segs: &[Seg], width: f32, grey: u8) {
        if self.path.is_some() && self.stroke != (width, grey) {
            self.flush(surface);
        }
        self.stroke = (width, grey);
        let b = self.path.get_or_insert_with(PathBuilder::new);
        for s in segs {
            match *s {
                Seg::Move(x, y) => b.move_to(x, y),
                Seg::Line(x, y) => b.line_to(x, y),
                Seg::Cubic(a, c, d, e, x, y) => b.cubic_to(a, c, d, e, x, y),
            }
        }
    }

    /// Draws what is pending.
    fn flush(&mut self, surface: &mut Surface<'_>) {
        let Some(path) = self.path.take().and_then(PathBuilder::finish) else {
            return;
        };
        let (width, grey) = self.stroke;
        surface.set_fill(None);
        surface.set_stroke(Some(Stroke {
            paint: ink(grey).into(),
            width,
            ..Stroke::default()
        }));
        surface.draw_path(&path);
    }
}

/// Draws `text` at `at` in the font and size of `face` and ink `grey`, in glyphs from the
/// layout's own metrics rather than krilla's shaper, which builds a shaping face for every
/// text it draws.
fn text_at(
    surface: &mut Surface<'_>,
    metrics: &mut Metrics,
    (font, size): (&Font, f32),
    at: Point,
    text: &str,
    grey: u8,
) {
    surface.set_stroke(None);
    surface.set_fill(Some(Fill {
        paint: ink(grey).into(),
        opacity: NormalizedF32::ONE,
        rule: Default::default(),
    }));
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
    surface.draw_glyphs(at, &glyphs, font.clone(), text, size, false);
}
