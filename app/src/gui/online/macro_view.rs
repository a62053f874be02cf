//! The CNC page's macro-variable table (docs/gcode.md, "Macros"): the locals of the current
//! call level, the commons #100–#199 and #500–#999, as the CNC reports them in its status.
//! While the program is not running a value can be typed in (a number, or `vacant`), which
//! becomes a `cnc macro` command.

use crate::gui::i18n::{Lang, Msg};
use crate::gui::theme;
use ladder_engine::cnc::{CncStatus, RunState};

/// Which variables the table shows.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum MacroGroup {
    /// #1–#33 of the current call level.
    #[default]
    Locals,
    /// #100–#199.
    Commons,
    /// #500–#999.
    Kept,
}

/// The table's state, owned by the caller with the editor buffers.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct MacroEdit {
    /// The group shown.
    pub group: MacroGroup,
    /// The variable being typed into and its text.
    pub editing: Option<(u16, String)>,
    /// The last text refused, with its variable.
    pub refused: Option<u16>,
    /// The edit has just started: its field takes the keyboard.
    pub focus: bool,
}

/// The width of one variable: its number and its value.
const CELL_WIDTH: f32 = 44.0 + 80.0 + 12.0;

/// A value as the table shows it.
pub fn value_text(v: Option<f64>, lang: Lang) -> String {
    match v {
        None => Msg::CncMacroVacant.text(lang).to_string(),
        Some(x) => {
            let t = format!("{x:.6}");
            let t = t.trim_end_matches('0').trim_end_matches('.');
            if t == "-0" { "0".into() } else { t.into() }
        }
    }
}

/// What a typed value means: `Some(None)` for vacant, `None` when it is neither a number
/// nor vacant.
pub fn parse_value(text: &str) -> Option<Option<f64>> {
    let t = text.trim();
    if t.is_empty() || t.eq_ignore_ascii_case("vacant") || t == "空" {
        return Some(None);
    }
    t.parse::<f64>().ok().filter(|v| v.is_finite()).map(Some)
}

/// A variable typed in: its number and value (`None`: vacant).
pub type Typed = (u16, Option<f64>);

/// Draws the table under its heading; a value typed and confirmed with Enter is pushed to
/// `events`.
pub fn macro_ui(
    ui: &mut egui::Ui,
    s: &CncStatus,
    edit: &mut MacroEdit,
    lang: Lang,
    events: &mut Vec<Typed>,
) {
    let Some(table) = s.macros.as_deref() else {
        return;
    };
    let t = |m: Msg| m.text(lang);
    let editable = s.run != RunState::Run;
    egui::CollapsingHeader::new(t(Msg::CncMacros))
        .id_salt("cnc-macros")
        .show(ui, |ui| {
            // Wraps in a narrow panel rather than running off its edge.
            ui.horizontal_wrapped(|ui| {
                let locals = format!("{} {}", t(Msg::CncMacroLocals), table.level);
                ui.selectable_value(&mut edit.group, MacroGroup::Locals, locals);
                ui.selectable_value(&mut edit.group, MacroGroup::Commons, "#100–#199");
                ui.selectable_value(&mut edit.group, MacroGroup::Kept, "#500–#999");
            });
            let hint = if editable {
                Msg::CncMacroEditHint
            } else {
                Msg::CncMacroRunning
            };
            ui.weak(t(hint));
            if let Some(n) = edit.refused {
                ui.colored_label(theme::ERROR, format!("#{n}: {}", t(Msg::CncMacroBad)));
            }
            let (first, values): (u16, &[Option<f64>]) = match edit.group {
                MacroGroup::Locals => (1, &table.locals),
                MacroGroup::Commons => (100, &table.commons),
                MacroGroup::Kept => (500, &table.kept),
            };
            // As many variables to a row as the panel holds.
            let per_row = ((ui.available_width() / CELL_WIDTH).floor() as usize).clamp(1, 8);
            let rows = values.len().div_ceil(per_row);
            let height = ui.spacing().interact_size.y;
            egui::ScrollArea::vertical()
                .id_salt("cnc-macro-rows")
                .max_height(200.0)
                .show_rows(ui, height, rows, |ui, range| {
                    for row in range {
                        ui.horizontal(|ui| {
                            let start = row * per_row;
                            let end = (start + per_row).min(values.len());
                            for (k, v) in values[start..end].iter().enumerate() {
                                let n = first + (start + k) as u16;
                                cell(ui, n, *v, editable, edit, lang, events);
                            }
                        });
                    }
                });
        });
    if !editable {
        edit.editing = None;
    }
}

/// One variable: its number and its value, a button to type into while editable.
fn cell(
    ui: &mut egui::Ui,
    n: u16,
    v: Option<f64>,
    editable: bool,
    edit: &mut MacroEdit,
    lang: Lang,
    events: &mut Vec<Typed>,
) {
    let name = ui.add_sized([44.0, 18.0], egui::Label::new(format!("#{n}")));
    let width = 80.0;
    match &mut edit.editing {
        Some((k, text)) if *k == n && editable => {
            let mut out = egui::TextEdit::singleline(text)
                .id_salt(("cnc-macro-edit", n))
                .desired_width(width)
                .show(ui);
            if std::mem::take(&mut edit.focus) {
                // The value is selected, so what is typed replaces it.
                out.response.request_focus();
                let all = egui::text::CCursorRange::two(
                    egui::text::CCursor::new(0),
                    egui::text::CCursor::new(text.chars().count()),
                );
                out.state.cursor.set_char_range(Some(all));
                out.state.store(ui.ctx(), out.response.id);
            }
            let r = (*out.response).clone().labelled_by(name.id);
            if r.lost_focus() {
                if ui.input(|i| i.key_pressed(egui::Key::Enter)) {
                    match parse_value(text) {
                        Some(value) => {
                            events.push((n, value));
                            edit.refused = None;
                        }
                        None => edit.refused = Some(n),
                    }
                }
                edit.editing = None;
            }
        }
        _ => {
            let shown = value_text(v, lang);
            if editable {
                let b = ui
                    .add_sized([width, 18.0], egui::Button::new(&shown))
                    .on_hover_text(format!("#{n}"));
                if b.clicked() {
                    let start = if v.is_some() { shown } else { String::new() };
                    edit.editing = Some((n, start));
                    edit.focus = true;
                }
            } else {
                ui.add_sized([width, 18.0], egui::Label::new(shown));
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn values_show_as_decimals_and_typed_text_reads_back() {
        assert_eq!(value_text(Some(2.5), Lang::En), "2.5");
        assert_eq!(value_text(Some(-3.0), Lang::En), "-3");
        assert_eq!(value_text(Some(1.0 / 3.0), Lang::En), "0.333333");
        assert_eq!(value_text(None, Lang::En), "<vacant>");
        assert_eq!(value_text(None, Lang::Zh), "<空>");
        assert_eq!(parse_value(" 12.5 "), Some(Some(12.5)));
        assert_eq!(parse_value("vacant"), Some(None));
        assert_eq!(parse_value(""), Some(None));
        assert_eq!(parse_value("1,5"), None);
        assert_eq!(parse_value("inf"), None);
    }
}
