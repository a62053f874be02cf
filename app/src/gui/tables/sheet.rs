//! The row tables: the row toolbar, then the grid with a row header (click selects,
//! right-click opens the row menu), the cells, and why the row's input was refused.

use super::super::i18n::{Lang, Msg};
use super::error_text::table_error;
use super::{CellKey, ERROR_RED, Pending, TableEvent, TableState, row_height};
use egui::{Key, Sense};
use egui_extras::{Column, TableBuilder};
use ladder_engine::model::Project;
use ladder_engine::model::sheets::{Col, RowOp, Sheet, cell_text, commit, k_bit, row_op};

/// What the user did in a frame, carried out once the frame no longer borrows the state.
pub(super) enum Action {
    /// Text typed into a cell, to commit.
    Commit(CellKey, String),
    /// A row-menu action on a row.
    Op(Sheet, RowOp, usize),
    /// A bit of the K page clicked.
    KBit { number: usize, bit: u8, on: bool },
}

fn op_msg(op: RowOp) -> Msg {
    match op {
        RowOp::Clear => Msg::TblClear,
        RowOp::InsertAbove => Msg::TblInsertAbove,
        RowOp::InsertBelow => Msg::TblInsertBelow,
        RowOp::Delete => Msg::TblDelete,
    }
}

/// A column's title: a per-language column names its language, so that the columns of one
/// row read "Comment (zh)", "Comment (en)" whatever the UI language.
fn col_title(col: Col, lang: Lang) -> String {
    let msg = match col {
        Col::Address => Msg::TblAddress,
        Col::Symbol => Msg::TblSymbol,
        Col::Comment(_) => Msg::TblComment,
        Col::Value => Msg::TblValue,
        Col::Min => Msg::TblMin,
        Col::Max => Msg::TblMax,
        Col::Number => Msg::TblAlarmNumber,
        Col::Text(_) => Msg::TblMessageText,
        Col::Code => Msg::TblMCode,
    };
    match col.lang() {
        Some(code) => format!("{} ({code})", msg.text(lang)),
        None => msg.text(lang).to_string(),
    }
}

/// A column's width: room for a typical entry at first, and never less than a few
/// characters when the user narrows it. A table wider than the window scrolls sideways
/// rather than squeezing every language's text.
fn col_column(col: Col) -> Column {
    let (width, least) = match col {
        Col::Address | Col::Code | Col::Number => (100.0, 64.0),
        Col::Value | Col::Min | Col::Max => (100.0, 64.0),
        Col::Symbol => (160.0, 80.0),
        Col::Comment(_) => (230.0, 100.0),
        Col::Text(_) => (300.0, 120.0),
    };
    Column::initial(width).at_least(least).clip(true)
}

/// Carries out what the user did this frame: one table edit per action, each judged against
/// the tables as the actions before it left them (the caller applies the edits in order).
pub(super) fn run_actions(
    project: &Project,
    state: &mut TableState,
    actions: Vec<Action>,
    events: &mut Vec<TableEvent>,
) {
    let last = actions.len().saturating_sub(1);
    // Only a frame with several actions needs the tables as the earlier ones left them.
    let mut working: Option<Project> = None;
    for (i, action) in actions.into_iter().enumerate() {
        let now = working.as_ref().unwrap_or(project);
        let edit = match action {
            Action::Commit(key, text) => {
                let (sheet, row, col) = key;
                match commit(now, sheet, row, col, &text) {
                    Ok(edit) => {
                        state.pending.remove(&key);
                        edit
                    }
                    Err(e) => {
                        let stamp = state.next_stamp();
                        state.pending.insert(
                            key,
                            Pending {
                                text,
                                error: Some(e),
                                stamp,
                            },
                        );
                        None
                    }
                }
            }
            Action::Op(sheet, op, row) => match row_op(now, sheet, op, row) {
                Ok((edit, select)) => {
                    // Rows moved: what was typed in this table's rows no longer matches.
                    state
                        .pending
                        .retain(|k, _| k.0 != sheet || (op == RowOp::Clear && k.1 != row));
                    state.op_error = None;
                    state.selected.insert(sheet, select);
                    state.scroll_to = Some((sheet, select));
                    edit
                }
                Err(e) => {
                    state.op_error = Some((sheet, e));
                    None
                }
            },
            Action::KBit { number, bit, on } => k_bit(now, number, bit, on),
        };
        if let Some(edit) = edit {
            if i < last {
                working
                    .get_or_insert_with(|| project.clone())
                    .apply_table(edit.clone());
            }
            events.push(TableEvent::Apply(edit));
        }
    }
}

/// Draws one row-menu button, disabled with the reason when it cannot act; true when clicked.
fn row_op_button(
    ui: &mut egui::Ui,
    sheet: Sheet,
    op: RowOp,
    row: Option<usize>,
    len: usize,
    lang: Lang,
) -> bool {
    let on_a_row = row.is_some_and(|r| r < len);
    let (enabled, why) = match op {
        RowOp::Clear => (on_a_row, Msg::TblSelectRowFirst),
        RowOp::Delete if sheet.fixed() => (false, Msg::TblFixedRows),
        RowOp::Delete => (on_a_row, Msg::TblSelectRowFirst),
        RowOp::InsertAbove | RowOp::InsertBelow => (!sheet.fixed(), Msg::TblFixedRows),
    };
    ui.add_enabled(enabled, egui::Button::new(op_msg(op).text(lang)))
        .on_disabled_hover_text(why.text(lang))
        .clicked()
}

/// Whether symbol row `row` has nothing but its address (a row just inserted).
fn blank_symbol(project: &Project, sheet: Sheet, row: usize) -> bool {
    let Sheet::Symbols(t) = sheet else {
        return false;
    };
    project
        .symbol_tables
        .get(t)
        .and_then(|t| t.rows.get(row))
        .is_some_and(|s| s.name.is_empty() && s.comments.values().all(String::is_empty))
}

/// One editable cell: shows the typed text while there is some, commits it when the field
/// loses focus (Enter included), drops it on Escape. Returns the field's rectangle when it
/// has just taken the keyboard, for the grid to bring it into view sideways.
fn cell_ui(
    ui: &mut egui::Ui,
    state: &mut TableState,
    project: &Project,
    (sheet, row, col): CellKey,
    len: usize,
    lang: Lang,
    actions: &mut Vec<Action>,
) -> Option<egui::Rect> {
    let fresh = row >= len;
    if !sheet.editable(col) || (fresh && col != sheet.key_col()) {
        if !fresh {
            ui.label(cell_text(project, sheet, row, col));
        }
        return None;
    }
    let key = (sheet, row, col);
    let pending = state.pending.get(&key);
    let refused = pending.is_some_and(|p| p.error.is_some());
    // A row just inserted holds only the next free address: shown as a suggestion (grey, in
    // the hint) until the row gets a name or a comment or the address is typed, so it never
    // reads as data someone entered.
    let suggested =
        pending.is_none() && col == sheet.key_col() && blank_symbol(project, sheet, row);
    let mut text = match pending {
        Some(p) => p.text.clone(),
        None if suggested => String::new(),
        None => cell_text(project, sheet, row, col),
    };
    let shown = cell_text(project, sheet, row, col);
    let mut edit = egui::TextEdit::singleline(&mut text).desired_width(f32::INFINITY);
    if suggested {
        edit = edit.hint_text(shown);
    }
    if refused {
        edit = edit.text_color(ERROR_RED);
    }
    if fresh {
        let hint = if sheet == Sheet::MCodes {
            Msg::TblNewRowCode
        } else {
            Msg::TblNewRowAddress
        };
        edit = edit.hint_text(hint.text(lang));
    }
    let r = ui
        .add(edit)
        .accessible_name(format!("{} {}", col_title(col, lang), row + 1));
    let focused = r.gained_focus();
    if focused {
        state.selected.insert(sheet, row);
        // A cell half hidden at the top or bottom edge comes fully into view. (The rows'
        // scroll area drops the sideways part of this; the grid's caller does that.)
        r.scroll_to_me(None);
    }
    if r.changed() {
        let stamp = state.next_stamp();
        let p = state.pending.entry(key).or_default();
        p.text = text.clone();
        p.stamp = stamp;
    }
    if r.lost_focus() {
        if ui.input(|i| i.key_pressed(Key::Escape)) {
            state.pending.remove(&key);
        } else if state.pending.contains_key(&key) {
            actions.push(Action::Commit(key, text));
        }
    }
    focused.then_some(r.rect)
}

/// A row table: the row toolbar, then the grid with a row header (click selects,
/// right-click opens the row menu), the cells, and why the row's input was refused.
pub(super) fn sheet_ui(
    ui: &mut egui::Ui,
    project: &Project,
    state: &mut TableState,
    sheet: Sheet,
    lang: Lang,
    events: &mut Vec<TableEvent>,
) {
    let profile = project.profile();
    let len = sheet.rows(project);
    // Growing tables end in an empty line: typing its address (or code) adds a row.
    let shown = if sheet.fixed() { len } else { len + 1 };
    let selected = state.selected.get(&sheet).copied().filter(|r| *r < shown);
    let mut actions = Vec::new();
    ui.horizontal(|ui| {
        for op in RowOp::ALL {
            if row_op_button(ui, sheet, op, selected, len, lang) {
                actions.push(Action::Op(sheet, op, selected.unwrap_or(len)));
            }
        }
        if let Some((s, e)) = &state.op_error
            && *s == sheet
        {
            ui.colored_label(ERROR_RED, table_error(e, profile, lang));
        }
    });
    // One comment column per language makes the grid wider than a small window: it scrolls
    // sideways, the header with it, and the rows still scroll on their own below the header.
    egui::ScrollArea::horizontal()
        .id_salt(("sheet columns", sheet))
        .show(ui, |ui| {
            // Tab walks the columns: the cell that took the keyboard comes into view, left or
            // right, from outside the rows' own (vertical) scroll area.
            if let Some(rect) = grid_ui(ui, project, state, sheet, selected, lang, &mut actions) {
                ui.scroll_to_rect(rect, None);
            }
        });
    run_actions(project, state, actions, events);
}

/// The grid of a row table, only its visible rows laid out: the row header, a cell per
/// column, and the first refusal of the row's cells. Returns the rectangle of the cell that
/// took the keyboard this frame, if one did.
fn grid_ui(
    ui: &mut egui::Ui,
    project: &Project,
    state: &mut TableState,
    sheet: Sheet,
    selected: Option<usize>,
    lang: Lang,
    actions: &mut Vec<Action>,
) -> Option<egui::Rect> {
    let t = |m: Msg| m.text(lang);
    let mut focused = None;
    let profile = project.profile();
    let len = sheet.rows(project);
    let shown = if sheet.fixed() { len } else { len + 1 };
    let row_height = row_height(ui);
    let mut builder = TableBuilder::new(ui)
        .id_salt(sheet)
        .striped(true)
        .resizable(true)
        .cell_layout(egui::Layout::left_to_right(egui::Align::Center))
        .column(Column::exact(48.0));
    for col in sheet.columns() {
        builder = builder.column(col_column(*col));
    }
    builder = builder.column(Column::remainder().at_least(160.0).clip(true));
    if let Some((_, row)) = state.scroll_to.take_if(|(s, _)| *s == sheet) {
        builder = builder.scroll_to_row(row, None);
    }
    builder
        .header(row_height, |mut header| {
            header.col(|ui| {
                ui.strong(t(Msg::TblRow));
            });
            for col in sheet.columns() {
                header.col(|ui| {
                    ui.strong(col_title(*col, lang));
                });
            }
            header.col(|ui| {
                ui.strong(t(Msg::TblProblem));
            });
        })
        .body(|body| {
            body.rows(row_height, shown, |mut row| {
                let i = row.index();
                row.set_selected(selected == Some(i));
                row.col(|ui| {
                    let r = ui.add(
                        egui::Label::new((i + 1).to_string())
                            .sense(Sense::click())
                            .selectable(false),
                    );
                    if r.clicked() || r.secondary_clicked() {
                        state.selected.insert(sheet, i);
                    }
                    r.context_menu(|ui| {
                        for op in RowOp::ALL {
                            if row_op_button(ui, sheet, op, Some(i), len, lang) {
                                actions.push(Action::Op(sheet, op, i));
                                ui.close();
                            }
                        }
                    });
                });
                for &col in sheet.columns() {
                    row.col(|ui| {
                        let cell = (sheet, i, col);
                        if let Some(rect) = cell_ui(ui, state, project, cell, len, lang, actions) {
                            focused = Some(rect);
                        }
                    });
                }
                row.col(|ui| {
                    if let Some(e) = state.row_error(sheet, i) {
                        let e = table_error(e, profile, lang);
                        // On its own pale ground: red on the selection's blue is unreadable.
                        let text = egui::RichText::new(&e)
                            .color(ERROR_RED)
                            .background_color(super::super::theme::ERROR_GROUND);
                        ui.add(egui::Label::new(text).truncate()).on_hover_text(e);
                    }
                });
            });
        });
    focused
}
