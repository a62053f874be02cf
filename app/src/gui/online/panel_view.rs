//! The operator panel widget: the project's [`Panel`] drawn on its grid like a machine's
//! operator panel, driven by the current memory values, and an edit mode that changes the
//! panel's items.
//!
//! A widget: [`panel_ui`] reads the memory through a closure and returns [`PanelEvent`]s;
//! the application writes the inputs and turns an edited panel into an undoable
//! `TableEdit::Panel`.
//!
//! Every item is one accessible widget named by its label in the UI language, so a test (or
//! a screen reader) finds it by that label: keys, lamp keys and switches are buttons (a lit
//! lamp or a switch that is on reports itself toggled), lamps are status widgets (toggled
//! while lit), and knobs are combo boxes.

use crate::gui::errors::operand_error;
use crate::gui::i18n::{Lang, Msg};
use crate::gui::theme;
use egui::accesskit::Role;
use ladder_engine::Profile;
use ladder_engine::address::Address;
use ladder_engine::model::{OperandError, Panel, PanelError, PanelItem, PanelKind};

/// What the user did on the panel.
#[derive(Clone, Debug, PartialEq)]
pub enum PanelEvent {
    /// A key went down: its input bit should read 1.
    Press(Address),
    /// A key was let go: its input bit should read 0.
    Release(Address),
    /// A switch was flipped or a knob turned: write this value (a bit's 0/1, a knob's whole
    /// byte with the bits it does not own kept).
    Set(Address, i64),
    /// The panel was edited: the whole new panel. An empty panel is the profile's preset.
    Edited(Panel),
}

/// The panel widget's own state.
#[derive(Clone, Debug, Default)]
pub struct PanelViewState {
    /// Whether the edit mode is on (items are then changed, not operated).
    pub editing: bool,
    /// Keys held down now, so that each press gets exactly one release.
    held: Vec<Address>,
    /// The item form of the edit mode, when one is open.
    draft: Option<Draft>,
    /// Why the last Apply was refused.
    error: Option<String>,
    /// The panel's width at full size, as last drawn: the next frame scales to fit.
    natural: Option<f32>,
    /// A cell's size at the scale drawn now.
    cell: egui::Vec2,
}

/// Which kind the item form edits.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
enum KindChoice {
    #[default]
    Key,
    Switch,
    LampKey,
    Lamp,
    Knob,
}

impl KindChoice {
    const ALL: [KindChoice; 5] = [
        KindChoice::Key,
        KindChoice::Switch,
        KindChoice::LampKey,
        KindChoice::Lamp,
        KindChoice::Knob,
    ];

    fn msg(self) -> Msg {
        match self {
            KindChoice::Key => Msg::PanelKey,
            KindChoice::Switch => Msg::PanelSwitch,
            KindChoice::LampKey => Msg::PanelLampKey,
            KindChoice::Lamp => Msg::PanelLamp,
            KindChoice::Knob => Msg::PanelKnob,
        }
    }

    fn has_input(self) -> bool {
        self != KindChoice::Lamp
    }

    fn has_lamp(self) -> bool {
        matches!(self, KindChoice::LampKey | KindChoice::Lamp)
    }
}

/// The item form: the fields as typed, turned into an item only on Apply.
#[derive(Clone, Debug, Default, PartialEq)]
struct Draft {
    /// The item it changes; `None` adds a new one.
    index: Option<usize>,
    label_zh: String,
    label_en: String,
    kind: KindChoice,
    input: String,
    lamp: String,
    positions: String,
    row: u8,
    col: u8,
    /// The power-on value, kept through an edit.
    initial: i64,
}

impl Draft {
    /// The form for an existing item.
    fn of(index: usize, item: &PanelItem) -> Draft {
        let text = |a: Option<Address>| a.map(|a| a.to_string()).unwrap_or_default();
        let (kind, positions) = match &item.kind {
            PanelKind::Key { .. } => (KindChoice::Key, String::new()),
            PanelKind::Switch { .. } => (KindChoice::Switch, String::new()),
            PanelKind::LampKey { .. } => (KindChoice::LampKey, String::new()),
            PanelKind::Lamp { .. } => (KindChoice::Lamp, String::new()),
            PanelKind::Knob { positions, .. } => (
                KindChoice::Knob,
                positions
                    .iter()
                    .map(|(l, v)| format!("{l}={v}"))
                    .collect::<Vec<_>>()
                    .join("; "),
            ),
        };
        Draft {
            index: Some(index),
            label_zh: item.label_zh.clone(),
            label_en: item.label_en.clone(),
            kind,
            input: text(item.kind.input()),
            lamp: text(item.kind.lamp()),
            positions,
            row: item.row,
            col: item.col,
            initial: item.initial,
        }
    }

    /// The form for a new key, on the first cell of a new row below the panel.
    fn new_item(panel: &Panel) -> Draft {
        let row = panel
            .items
            .iter()
            .map(|i| i.row.saturating_add(1))
            .max()
            .unwrap_or(0);
        Draft {
            row,
            ..Draft::default()
        }
    }

    /// The item the form describes, or why the text does not make one. The panel's own
    /// rules (labels, areas, overlaps) are [`Panel::check`]'s.
    fn build(&self, profile: &Profile, lang: Lang) -> Result<PanelItem, String> {
        let address = |text: &str| {
            Address::parse_in(text, profile)
                .map_err(|e| operand_error(&OperandError::Address(e), lang))
        };
        let input = || address(&self.input);
        let lamp = || address(&self.lamp);
        let kind = match self.kind {
            KindChoice::Key => PanelKind::Key { input: input()? },
            KindChoice::Switch => PanelKind::Switch { input: input()? },
            KindChoice::LampKey => PanelKind::LampKey {
                input: input()?,
                lamp: lamp()?,
            },
            KindChoice::Lamp => PanelKind::Lamp { lamp: lamp()? },
            KindChoice::Knob => PanelKind::Knob {
                input: input()?,
                positions: parse_positions(&self.positions)
                    .ok_or_else(|| Msg::PanelBadPositions.text(lang).to_string())?,
            },
        };
        Ok(PanelItem {
            label_zh: self.label_zh.trim().to_string(),
            label_en: self.label_en.trim().to_string(),
            kind,
            row: self.row,
            col: self.col,
            initial: self.initial,
        })
    }
}

/// Knob positions written `name=value; name=value`. The value is after the last `=`, so a
/// name may hold one.
fn parse_positions(text: &str) -> Option<Vec<(String, i64)>> {
    text.split(';')
        .map(str::trim)
        .filter(|p| !p.is_empty())
        .map(|p| {
            let (name, value) = p.rsplit_once('=')?;
            let value = value.trim().parse::<i64>().ok()?;
            Some((name.trim().to_string(), value))
        })
        .collect()
}

/// An item's label in a language, the other language's when it has none in this one.
pub fn item_label(item: &PanelItem, lang: Lang) -> &str {
    let (mine, other) = match lang {
        Lang::Zh => (&item.label_zh, &item.label_en),
        Lang::En => (&item.label_en, &item.label_zh),
    };
    if mine.trim().is_empty() { other } else { mine }
}

/// Why a panel was refused, in the UI language (the English is the error's own text).
pub fn panel_error_text(e: &PanelError, lang: Lang) -> String {
    if lang == Lang::En {
        return e.to_string();
    }
    let item = |n: usize, label: &str| format!("{} {n}「{label}」：", Msg::PanelItemNo.text(lang));
    let t = |m: Msg| m.text(lang);
    match e {
        PanelError::NoLabel { item: n } => {
            format!("{} {n}：{}", t(Msg::PanelItemNo), t(Msg::PanelErrNoLabel))
        }
        PanelError::NotBit {
            item: n,
            label,
            address,
        } => format!("{}{address} {}", item(*n, label), t(Msg::PanelErrNotBit)),
        PanelError::NotByte { item: n, label, .. } => {
            format!("{}{}", item(*n, label), t(Msg::PanelErrNotByte))
        }
        PanelError::NotInput {
            item: n,
            label,
            address,
        } => format!("{}{address} {}", item(*n, label), t(Msg::PanelErrNotInput)),
        PanelError::Range {
            item: n,
            label,
            error,
        } => format!(
            "{}{}",
            item(*n, label),
            operand_error(&OperandError::Address(error.clone()), lang)
        ),
        PanelError::Taken {
            item: n,
            label,
            address,
            other,
            other_label,
        } => format!(
            "{}{address} {} {} {other}「{other_label}」",
            item(*n, label),
            t(Msg::PanelErrTaken),
            t(Msg::PanelItemNo)
        ),
        PanelError::SameCell {
            item: n,
            label,
            other,
            other_label,
            ..
        } => format!(
            "{}{} {} {other}「{other_label}」",
            item(*n, label),
            t(Msg::PanelErrSameCell),
            t(Msg::PanelItemNo)
        ),
        PanelError::NoPositions { item: n, label } => {
            format!("{}{}", item(*n, label), t(Msg::PanelErrNoPositions))
        }
        PanelError::BadPosition {
            item: n,
            label,
            value,
        } => format!(
            "{}{value}：{}",
            item(*n, label),
            t(Msg::PanelErrBadPosition)
        ),
    }
}

/// The size of one grid cell.
const CELL: egui::Vec2 = egui::vec2(88.0, 34.0);

/// Draws the panel and returns what the user did. `memory` gives the value at an address: 0
/// or 1 for a bit address, the unsigned byte for a byte address. `profile` checks the
/// addresses typed in the edit mode.
pub fn panel_ui(
    ui: &mut egui::Ui,
    panel: &Panel,
    memory: &dyn Fn(Address) -> i64,
    profile: &Profile,
    lang: Lang,
    state: &mut PanelViewState,
) -> Vec<PanelEvent> {
    let t = |m: Msg| m.text(lang);
    let mut events = Vec::new();
    ui.horizontal(|ui| {
        let toggle = if state.editing {
            Msg::PanelDone
        } else {
            Msg::PanelEdit
        };
        if ui.button(t(toggle)).clicked() {
            state.editing = !state.editing;
            state.draft = None;
            state.error = None;
        }
        if state.editing {
            if ui.button(t(Msg::PanelAdd)).clicked() {
                state.draft = Some(Draft::new_item(panel));
                state.error = None;
            }
            if ui.button(t(Msg::PanelReset)).clicked() {
                // Empty is the preset: the project then saves as if never customised.
                events.push(PanelEvent::Edited(Panel::default()));
                state.draft = None;
                state.error = None;
            }
            ui.weak(t(Msg::PanelEditHint));
        }
    });
    let mut drawn = Vec::new();
    // The whole panel in sight: scaled down (to 60 % at most) to the width there is, as
    // measured at full size last frame, so no column hides behind a scroll bar.
    let room = ui.available_width();
    // In steps of 5 %: a grid re-measures its columns when they change, and a scale that
    // followed every pixel would never settle. Narrower than 60 % would be unreadable: then
    // each row of the panel wraps instead, its keys in order.
    let fit = state.natural.map_or(1.0, |w| room / w.max(1.0));
    let wrap = fit < MIN_SCALE;
    let scale = if wrap {
        WRAP_SCALE
    } else {
        ((fit * 20.0).floor() / 20.0).clamp(MIN_SCALE, 1.0)
    };
    state.cell = CELL * scale;
    let grid = ui.scope(|ui| {
        scale_style(ui.style_mut(), scale);
        let mut d = Drawing {
            panel,
            memory,
            lang,
            events: &mut events,
            drawn: &mut drawn,
        };
        if wrap {
            panel_rows(ui, &mut d, state);
        } else {
            panel_grid(ui, &mut d, state);
        }
    });
    // The full-size width is measured on the grid only (a wrapped panel is as wide as its
    // room).
    let natural = grid.response.rect.width() / scale;
    if !wrap && state.natural.is_none_or(|w| (w - natural).abs() > 8.0) {
        state.natural = Some(natural);
    }
    // A key that is no longer drawn (edit mode, removed) cannot be let go: release it now.
    state.held.retain(|a| {
        let keep = drawn.contains(a);
        if !keep {
            events.push(PanelEvent::Release(*a));
        }
        keep
    });
    if state.editing {
        form_ui(ui, panel, profile, lang, state, &mut events);
    }
    events
}

/// The smallest scale the panel's grid is drawn at to fit; narrower than that, it wraps.
const MIN_SCALE: f32 = 0.6;
/// The scale of a wrapped panel.
const WRAP_SCALE: f32 = 0.85;

/// Text, paddings and spacings scaled (the panel drawn smaller to fit its room).
fn scale_style(style: &mut egui::Style, scale: f32) {
    for font in style.text_styles.values_mut() {
        font.size *= scale;
    }
    let s = &mut style.spacing;
    s.button_padding *= scale;
    s.interact_size *= scale;
    s.item_spacing *= scale;
}

/// What drawing the panel's items needs besides the Ui and the view's state, and what it
/// gives back (the events, the keys drawn).
struct Drawing<'a> {
    panel: &'a Panel,
    memory: &'a dyn Fn(Address) -> i64,
    lang: Lang,
    events: &'a mut Vec<PanelEvent>,
    drawn: &'a mut Vec<Address>,
}

impl Drawing<'_> {
    /// Item `i`: its form button in the edit mode, else the item in operation.
    fn item(&mut self, ui: &mut egui::Ui, state: &mut PanelViewState, i: usize) {
        if state.editing {
            edit_cell(ui, self.panel, i, self.lang, state);
        } else {
            let item = &self.panel.items[i];
            operate_cell(ui, item, i, self.memory, self.lang, state, self.events);
            self.drawn.extend(item.kind.input());
        }
    }

    /// The number of rows the panel uses.
    fn rows(&self) -> u8 {
        self.panel
            .items
            .iter()
            .map(|i| i.row)
            .max()
            .map_or(0, |r| r + 1)
    }
}

/// The panel's items on their grid of rows and columns.
fn panel_grid(ui: &mut egui::Ui, d: &mut Drawing<'_>, state: &mut PanelViewState) {
    let cols = d
        .panel
        .items
        .iter()
        .map(|i| i.col)
        .max()
        .map_or(0, |c| c + 1);
    let gap = 6.0 * state.cell.x / CELL.x;
    egui::Grid::new("operator-panel")
        .spacing([gap, gap])
        .min_col_width(state.cell.x)
        .show(ui, |ui| {
            for row in 0..d.rows() {
                for col in 0..cols {
                    let at = d
                        .panel
                        .items
                        .iter()
                        .position(|i| (i.row, i.col) == (row, col));
                    match at {
                        Some(i) => d.item(ui, state, i),
                        None => {
                            ui.allocate_space(state.cell);
                        }
                    }
                }
                ui.end_row();
            }
        });
}

/// The panel's rows one after another, each wrapping to the room there is.
fn panel_rows(ui: &mut egui::Ui, d: &mut Drawing<'_>, state: &mut PanelViewState) {
    ui.set_max_width(ui.available_width());
    for row in 0..d.rows() {
        let mut items: Vec<usize> = (0..d.panel.items.len())
            .filter(|&i| d.panel.items[i].row == row)
            .collect();
        items.sort_by_key(|&i| d.panel.items[i].col);
        ui.horizontal_wrapped(|ui| {
            for i in items {
                d.item(ui, state, i);
            }
        });
    }
}

/// One item in operation.
fn operate_cell(
    ui: &mut egui::Ui,
    item: &PanelItem,
    index: usize,
    memory: &dyn Fn(Address) -> i64,
    lang: Lang,
    state: &mut PanelViewState,
    events: &mut Vec<PanelEvent>,
) {
    let label = item_label(item, lang);
    let lit = item.kind.lamp().is_some_and(|a| memory(a) != 0);
    match &item.kind {
        PanelKind::Key { input } | PanelKind::LampKey { input, .. } => {
            let mut button = egui::Button::new(egui::RichText::new(label).color(if lit {
                theme::INK
            } else {
                ui.visuals().text_color()
            }))
            .min_size(state.cell)
            // A click alone stops counting as held once it is too long for a click; a drag
            // is held until the button is let go, as a key is.
            .sense(egui::Sense::click_and_drag());
            if item.kind.lamp().is_some() {
                button = button.selected(lit);
            }
            if lit {
                button = button.fill(theme::PANEL_LIT);
            }
            let resp = ui.add(button).on_hover_text(wiring(item));
            key_events(&resp, *input, state, events);
        }
        PanelKind::Switch { input } => {
            let on = memory(*input) != 0;
            let resp = ui
                .add(egui::Button::new(label).min_size(state.cell).selected(on))
                .on_hover_text(wiring(item));
            if resp.clicked() {
                events.push(PanelEvent::Set(*input, i64::from(!on)));
            }
        }
        PanelKind::Lamp { .. } => {
            let text = ui.painter().layout_no_wrap(
                label.to_string(),
                egui::TextStyle::Button.resolve(ui.style()),
                ui.visuals().text_color(),
            );
            // A long label widens the cell rather than run into the next one.
            let size = egui::vec2(state.cell.x.max(24.0 + text.size().x), state.cell.y);
            let (rect, resp) = ui.allocate_exact_size(size, egui::Sense::hover());
            let centre = egui::pos2(rect.left() + 10.0, rect.center().y);
            let fill = if lit {
                theme::PANEL_LIT
            } else {
                theme::PANEL_DARK
            };
            let painter = ui.painter();
            painter.circle(centre, 8.0, fill, egui::Stroke::new(1.0, theme::PANEL_RIM));
            let at = egui::pos2(rect.left() + 24.0, rect.center().y - text.size().y / 2.0);
            painter.galley(at, text, ui.visuals().text_color());
            resp.widget_info(|| egui::WidgetInfo::selected(Role::Status, true, lit, label));
            resp.on_hover_text(wiring(item));
        }
        PanelKind::Knob { input, positions } => {
            let byte = memory(*input);
            let at = item.kind.knob_position(byte);
            let shown = match at {
                Some(k) => positions[k].0.clone(),
                None => format!("{} {byte}", Msg::PanelNoPosition.text(lang)),
            };
            // Placed as one piece of its cell's size, so a wrapping row can move it whole.
            let size = egui::vec2(state.cell.x, state.cell.y * 1.5);
            let layout = egui::Layout::top_down(egui::Align::Min);
            ui.allocate_ui_with_layout(size, layout, |ui| {
                ui.set_width(state.cell.x);
                let name = ui.small(label);
                // Tall enough for every position: a knob's positions are read at a glance.
                let rows = positions.len() as f32;
                let row = ui.spacing().interact_size.y + ui.spacing().item_spacing.y;
                let resp = egui::ComboBox::from_id_salt(("panel-knob", index))
                    .width(state.cell.x)
                    .height(rows * row + 16.0)
                    .selected_text(shown)
                    .show_ui(ui, |ui| {
                        for (k, (text, value)) in positions.iter().enumerate() {
                            if ui.selectable_label(at == Some(k), text).clicked() && at != Some(k) {
                                let byte = item.kind.knob_write(byte, *value);
                                events.push(PanelEvent::Set(*input, byte));
                            }
                        }
                    })
                    .response;
                resp.labelled_by(name.id).on_hover_text(wiring(item));
            });
        }
    }
}

/// Press and release of a key from the pointer held on it. A press and a release within one
/// frame (a quick click, the keyboard, a test harness) still give both, in order.
fn key_events(
    resp: &egui::Response,
    input: Address,
    state: &mut PanelViewState,
    events: &mut Vec<PanelEvent>,
) {
    let down = resp.is_pointer_button_down_on();
    let held = state.held.contains(&input);
    match (down, held) {
        (true, false) => {
            state.held.push(input);
            events.push(PanelEvent::Press(input));
        }
        (false, true) => {
            state.held.retain(|a| *a != input);
            events.push(PanelEvent::Release(input));
        }
        (false, false) if resp.clicked() => {
            events.push(PanelEvent::Press(input));
            events.push(PanelEvent::Release(input));
        }
        _ => {}
    }
}

/// The addresses an item is wired to, for its tooltip.
fn wiring(item: &PanelItem) -> String {
    let parts: Vec<String> = item
        .kind
        .input()
        .into_iter()
        .chain(item.kind.lamp())
        .map(|a| a.to_string())
        .collect();
    parts.join(" / ")
}

/// One item in the edit mode: a button that opens its form.
fn edit_cell(
    ui: &mut egui::Ui,
    panel: &Panel,
    index: usize,
    lang: Lang,
    state: &mut PanelViewState,
) {
    let item = &panel.items[index];
    let open = state.draft.as_ref().and_then(|d| d.index) == Some(index);
    let resp = ui
        .add(
            egui::Button::new(item_label(item, lang))
                .min_size(state.cell)
                .selected(open),
        )
        .on_hover_text(wiring(item));
    if resp.clicked() {
        state.draft = Some(Draft::of(index, item));
        state.error = None;
    }
}

/// The item form: labels, kind, addresses, positions and cell; Apply checks the whole panel.
fn form_ui(
    ui: &mut egui::Ui,
    panel: &Panel,
    profile: &Profile,
    lang: Lang,
    state: &mut PanelViewState,
    events: &mut Vec<PanelEvent>,
) {
    let t = |m: Msg| m.text(lang);
    let Some(draft) = state.draft.as_mut() else {
        return;
    };
    ui.separator();
    let mut apply = false;
    let mut remove = false;
    let mut cancel = false;
    egui::Grid::new("operator-panel-form")
        .num_columns(2)
        .show(ui, |ui| {
            let field = |ui: &mut egui::Ui, m: Msg, text: &mut String| {
                let label = ui.label(t(m));
                ui.add(egui::TextEdit::singleline(text).desired_width(260.0))
                    .labelled_by(label.id);
                ui.end_row();
            };
            field(ui, Msg::PanelLabelZh, &mut draft.label_zh);
            field(ui, Msg::PanelLabelEn, &mut draft.label_en);
            let label = ui.label(t(Msg::PanelKindLabel));
            egui::ComboBox::from_id_salt("panel-form-kind")
                .width(260.0)
                .selected_text(t(draft.kind.msg()))
                .show_ui(ui, |ui| {
                    for k in KindChoice::ALL {
                        ui.selectable_value(&mut draft.kind, k, t(k.msg()));
                    }
                })
                .response
                .labelled_by(label.id);
            ui.end_row();
            if draft.kind.has_input() {
                field(ui, Msg::PanelInput, &mut draft.input);
            }
            if draft.kind.has_lamp() {
                field(ui, Msg::PanelLampAddress, &mut draft.lamp);
            }
            if draft.kind == KindChoice::Knob {
                field(ui, Msg::PanelPositions, &mut draft.positions);
            }
            for (m, value) in [
                (Msg::PanelRow, &mut draft.row),
                (Msg::PanelCol, &mut draft.col),
            ] {
                let label = ui.label(t(m));
                ui.add(egui::DragValue::new(value).range(0..=63))
                    .labelled_by(label.id);
                ui.end_row();
            }
        });
    ui.horizontal(|ui| {
        apply = ui.button(t(Msg::PanelApply)).clicked();
        if draft.index.is_some() {
            remove = ui.button(t(Msg::PanelRemove)).clicked();
        }
        cancel = ui.button(t(Msg::PanelCancel)).clicked();
    });
    if let Some(e) = &state.error {
        ui.colored_label(theme::ERROR, e);
    }
    if cancel {
        state.draft = None;
        state.error = None;
        return;
    }
    let mut next = panel.clone();
    if remove {
        if let Some(i) = draft.index {
            next.items.remove(i);
        }
    } else if apply {
        match draft.build(profile, lang) {
            Ok(item) => match draft.index {
                Some(i) => next.items[i] = item,
                None => next.items.push(item),
            },
            Err(e) => {
                state.error = Some(e);
                return;
            }
        }
        if let Err(e) = next.check(profile) {
            state.error = Some(panel_error_text(&e, lang));
            return;
        }
    } else {
        return;
    }
    events.push(PanelEvent::Edited(next));
    state.draft = None;
    state.error = None;
}

#[cfg(test)]
mod tests;
