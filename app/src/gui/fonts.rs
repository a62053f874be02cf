//! The bundled CJK font (WenQuanYi Micro Hei, Apache-2.0, `assets/fonts/`), installed as the
//! fallback of both families so Chinese looks the same on every machine and in tests.

use egui::epaint::text::{FontInsert, FontPriority, InsertFontFamily};
use egui::{FontData, FontFamily};

/// The same bytes the printed documents embed: one copy of the 5 MB font in the program.
static CJK: &[u8] = ladder_print::FONT;

/// Adds the CJK font to a context (before the first frame).
pub fn install(ctx: &egui::Context) {
    let families = [FontFamily::Proportional, FontFamily::Monospace]
        .into_iter()
        .map(|family| InsertFontFamily {
            family,
            priority: FontPriority::Lowest,
        })
        .collect();
    ctx.add_font(FontInsert::new(
        "wqy-microhei",
        FontData::from_static(CJK),
        families,
    ));
}
