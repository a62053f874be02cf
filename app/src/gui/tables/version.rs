//! The version information (§3.4.7): designer, version and remarks with their lengths, and
//! the ladder password, kept only as a salted hash.

use super::super::document::Document;
use super::super::i18n::{Lang, Msg};
use super::{ERROR_RED, OK_GREEN, PasswordDraft, TableEvent, TableState};
use egui::Key;
use ladder_engine::model::sheets::{TableError, set_password};
use ladder_engine::model::tables::{DESIGNER_MAX, NAME_MAX, REMARKS_MAX, VERSION_MAX};

/// The field of the remarks, the one of several lines.
const REMARKS: usize = 3;
use ladder_engine::model::{TableEdit, VersionInfo};

/// Draws the version view.
pub(super) fn version_ui(
    ui: &mut egui::Ui,
    doc: &Document,
    state: &mut TableState,
    lang: Lang,
    events: &mut Vec<TableEvent>,
) {
    let t = |m: Msg| m.text(lang);
    let current = &doc.project().version;
    ui.heading(t(Msg::VersionInfo));
    let mut commit = false;
    // Sized from the window, not the text: a Grid gives a TextEdit only its text's width,
    // which left one character per line in a small window. 900×600 still shows 200 points.
    let field_width = (ui.available_width() - 200.0).clamp(200.0, 480.0);
    egui::Grid::new("version-info")
        .num_columns(3)
        .spacing([12.0, 8.0])
        .show(ui, |ui| {
            let fields = [
                (Msg::TblProjectName, NAME_MAX, &current.name),
                (Msg::TblDesigner, DESIGNER_MAX, &current.designer),
                (Msg::TblVersion, VERSION_MAX, &current.version),
                (Msg::TblRemarks, REMARKS_MAX, &current.remarks),
            ];
            for (i, (msg, max, saved)) in fields.into_iter().enumerate() {
                let label = ui.label(t(msg));
                let mut text = state.version[i]
                    .as_ref()
                    .map_or_else(|| saved.clone(), |(d, _)| d.clone());
                let edit = if i == REMARKS {
                    egui::TextEdit::multiline(&mut text).desired_rows(6)
                } else {
                    egui::TextEdit::singleline(&mut text)
                };
                let height = if i == REMARKS {
                    6.0 * ui.text_style_height(&egui::TextStyle::Body) + 8.0
                } else {
                    ui.spacing().interact_size.y
                };
                let r = ui
                    .add_sized(
                        [field_width, height],
                        edit.char_limit(max).desired_width(field_width),
                    )
                    .labelled_by(label.id);
                if r.changed() {
                    let stamp = state.next_stamp();
                    state.version[i] = Some((text.clone(), stamp));
                }
                if r.lost_focus() {
                    if ui.input(|i| i.key_pressed(Key::Escape)) {
                        state.version[i] = None;
                    } else if state.version[i].is_some() {
                        commit = true;
                    }
                }
                ui.label(format!("{}/{max}", text.chars().count()));
                ui.end_row();
            }
        });
    if commit {
        let [n, d, v, r] = std::mem::take(&mut state.version).map(|f| f.map(|(text, _)| text));
        let mut next = current.clone();
        next.set(
            &n.unwrap_or(current.name.clone()),
            &d.unwrap_or(current.designer.clone()),
            &v.unwrap_or(current.version.clone()),
            &r.unwrap_or(current.remarks.clone()),
        );
        if next != *current {
            events.push(TableEvent::Apply(TableEdit::Version(Box::new(next))));
        }
    }
    ui.separator();
    password_ui(ui, current, doc.is_read_only(), state, lang, events);
}

fn password_ui(
    ui: &mut egui::Ui,
    current: &VersionInfo,
    read_only: bool,
    state: &mut TableState,
    lang: Lang,
    events: &mut Vec<TableEvent>,
) {
    let t = |m: Msg| m.text(lang);
    let is_set = current.password.is_some();
    ui.strong(t(Msg::TblPassword));
    ui.label(t(if is_set {
        Msg::TblPasswordIsSet
    } else {
        Msg::TblPasswordNone
    }));
    let draft = &mut state.password;
    egui::Grid::new("version-password")
        .num_columns(2)
        .spacing([12.0, 8.0])
        .show(ui, |ui| {
            let field = |ui: &mut egui::Ui, msg: Msg, text: &mut String| {
                let label = ui.label(t(msg));
                ui.add_sized(
                    [240.0, ui.spacing().interact_size.y],
                    egui::TextEdit::singleline(text).password(true),
                )
                .labelled_by(label.id);
                ui.end_row();
            };
            if is_set {
                field(ui, Msg::TblPasswordCurrent, &mut draft.current);
            }
            field(ui, Msg::TblPasswordNew, &mut draft.new);
            field(ui, Msg::TblPasswordConfirm, &mut draft.confirm);
        });
    let mut set = false;
    let mut clear = false;
    ui.horizontal(|ui| {
        set = ui.button(t(Msg::TblSetPassword)).clicked();
        clear = ui
            .add_enabled(is_set, egui::Button::new(t(Msg::TblClearPassword)))
            .clicked();
    });
    if set || clear {
        let new = set.then_some((draft.new.as_str(), draft.confirm.as_str()));
        match set_password(current, &draft.current, new, &new_salt()) {
            Err(e) => draft.note = Some((true, refusal(&e))),
            Ok(_) if read_only => draft.note = Some((true, Msg::ReadOnly)),
            Ok(next) => {
                *draft = PasswordDraft {
                    note: Some((
                        false,
                        if set {
                            Msg::TblPasswordSaved
                        } else {
                            Msg::TblPasswordCleared
                        },
                    )),
                    ..PasswordDraft::default()
                };
                events.push(TableEvent::Apply(TableEdit::Version(Box::new(next))));
            }
        }
    }
    if let Some((error, m)) = state.password.note {
        ui.colored_label(if error { ERROR_RED } else { OK_GREEN }, t(m));
    }
}

/// The note for a refused password change.
fn refusal(e: &TableError) -> Msg {
    match e {
        TableError::PasswordEmpty => Msg::TblPasswordEmpty,
        TableError::PasswordMismatch => Msg::TblPasswordMismatch,
        _ => Msg::TblPasswordWrong,
    }
}

/// A salt for a password hash: random per call (std's hasher keys come from the OS), so two
/// projects with the same password get different hashes.
pub(super) fn new_salt() -> String {
    use std::hash::{BuildHasher, Hasher};
    let nanos = std::time::SystemTime::now()
        .duration_since(std::time::UNIX_EPOCH)
        .map_or(0, |d| d.as_nanos());
    (0..2u8)
        .map(|i| {
            let mut h = std::collections::hash_map::RandomState::new().build_hasher();
            h.write_u128(nanos);
            h.write_u8(i);
            format!("{:016x}", h.finish())
        })
        .collect()
}
