//! Files: new, open, save, save as, close and exit with the unsaved-changes prompt; native
//! dialogs behind a small trait (tests script the answers, and never open one); export of the
//! instruction list, export and import of comments; the read-only recovery open of a damaged
//! file; and the autosaved recovery copy offered back after a crash.

pub mod dialogs;
pub mod file_dialog;

use crate::gui::context::Context;
use crate::gui::document::Document;
use crate::gui::files::file_dialog::SystemDialogs;
use crate::gui::i18n::Msg;
pub use crate::gui::settings::canonical;
pub use dialogs::{
    CloseAction, DialogKind, FileDialogs, NativeDialogs, Question, RecoveryCopy, ScriptedDialogs,
};
use ladder_engine::file::{self, FileError};
use ladder_engine::model::{Change, Project};
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

/// The file side: the file dialogs, the question the editor waits on and the recovery copies.
pub struct FileState {
    /// File dialogs (native, or scripted in tests).
    pub dialogs: Box<dyn FileDialogs>,
    /// The question the editor waits on (unsaved changes, damaged file, restore).
    pub question: Option<Question>,
    /// What to do once the pending Save or Save As succeeds.
    pub after_save: Option<CloseAction>,
    /// The user agreed to quit.
    pub exit_confirmed: bool,
    /// Where recovery copies are autosaved; `None` turns autosave off.
    pub recovery_dir: Option<PathBuf>,
    /// When the recovery copy was last written.
    pub last_autosave: Option<Instant>,
}

impl Default for FileState {
    fn default() -> FileState {
        FileState {
            dialogs: Box::new(SystemDialogs::default()),
            question: None,
            after_save: None,
            exit_confirmed: false,
            recovery_dir: None,
            last_autosave: None,
        }
    }
}

/// Minutes between autosaves of the recovery copy.
pub const AUTOSAVE_MINUTES: u64 = 3;

/// The recovery copy's file for a project file (or an untitled project): the same name in the
/// recovery folder, with a hash of the full path so two `main.ldp` in different folders differ.
pub fn recovery_path(dir: &Path, original: Option<&Path>) -> PathBuf {
    match original {
        None => dir.join("untitled.ldp"),
        Some(p) => {
            // FNV-1a: stable across runs and builds, unlike std's hasher.
            let mut h: u32 = 0x811c_9dc5;
            for b in p.to_string_lossy().bytes() {
                h = (h ^ u32::from(b)).wrapping_mul(0x0100_0193);
            }
            let stem = p
                .file_stem()
                .map_or("project".into(), |s| s.to_string_lossy());
            dir.join(format!("{stem}-{h:08x}.ldp"))
        }
    }
}

/// The recovery copies left in `dir`, newest first.
pub fn recovery_copies(dir: &Path) -> Vec<RecoveryCopy> {
    let Ok(entries) = std::fs::read_dir(dir) else {
        return Vec::new();
    };
    let mut copies: Vec<RecoveryCopy> = entries
        .filter_map(Result::ok)
        .map(|e| e.path())
        .filter(|p| p.extension().is_some_and(|x| x == "ldp"))
        .map(|copy| {
            let original = std::fs::read_to_string(copy.with_extension("origin"))
                .ok()
                .map(|s| PathBuf::from(s.trim_end_matches('\n')))
                .filter(|p| !p.as_os_str().is_empty());
            let saved = std::fs::metadata(&copy).and_then(|m| m.modified()).ok();
            RecoveryCopy {
                copy,
                original,
                saved,
            }
        })
        .collect();
    copies.sort_by_key(|c| std::cmp::Reverse(c.saved));
    copies
}

/// Removes a recovery copy and what goes with it.
fn remove_copy(copy: &Path) {
    for ext in ["ldp", "origin", "ldp.bak"] {
        let _ = std::fs::remove_file(copy.with_extension(ext));
    }
}

/// Writes `text` to `path` through a temporary file in the same folder and a rename, so a
/// crash leaves the old file or the new one.
pub(crate) fn write_atomic(path: &Path, text: &str) -> std::io::Result<()> {
    ladder_engine::file::write_atomic(path, text.as_bytes())
}

impl FileState {
    /// Asks for `action`: at once when nothing is unsaved, else after the unsaved-changes
    /// question.
    pub fn request(&mut self, cx: &mut Context<'_>, action: CloseAction) {
        if cx.doc().is_some_and(|d| d.is_dirty()) {
            self.question = Some(Question::Unsaved { then: action });
        } else {
            self.perform(cx, action);
        }
    }

    /// Does `action` now, whatever is unsaved.
    pub fn perform(&mut self, cx: &mut Context<'_>, action: CloseAction) {
        match action {
            CloseAction::OpenDialog => {
                self.start_dialog(cx, DialogKind::OpenProject);
                return;
            }
            CloseAction::Open(path) => {
                self.open(cx, &path);
                return;
            }
            CloseAction::Exit => {
                self.exit_confirmed = true;
                self.drop_recovery_copy(cx);
                if let Some(ctx) = &cx.egui {
                    ctx.send_viewport_cmd(egui::ViewportCommand::Close);
                }
                return;
            }
            CloseAction::New | CloseAction::Close => {}
        }
        self.drop_recovery_copy(cx);
        cx.replace_document(
            (action == CloseAction::New).then(|| Document::new(Project::default(), None)),
        );
    }

    pub(super) fn start_dialog(&mut self, cx: &mut Context<'_>, kind: DialogKind) {
        let doc = cx.doc();
        let stem = doc
            .and_then(|d| d.path().or(d.recovered_from()))
            .and_then(|p| p.file_stem())
            .map_or("project".to_string(), |s| s.to_string_lossy().into_owned());
        let ext = match kind {
            DialogKind::OpenProject | DialogKind::ImportComments | DialogKind::OpenCoverage => None,
            DialogKind::SaveProjectAs => Some("ldp"),
            DialogKind::ExportIl => Some("il"),
            DialogKind::ExportComments | DialogKind::ExportTrace => Some("csv"),
            DialogKind::ExportDocument => Some("pdf"),
        };
        let dir = doc.and_then(|d| d.path()).and_then(|p| p.parent());
        let suggested = ext.map(|e| {
            let name = format!("{stem}.{e}");
            dir.map_or(PathBuf::from(&name), |d| d.join(&name))
        });
        if self.dialogs.busy() {
            // One dialog at a time; what was waiting for this one is dropped with it.
            self.after_save = None;
            return;
        }
        if let Some(ctx) = cx.egui.cloned() {
            self.dialogs.start(&ctx, kind, suggested);
        }
    }

    /// Handles a dialog's answer.
    /// What another feature writes (the trace's CSV, the printed document) comes back with
    /// its file name for that feature.
    pub fn poll_dialogs(&mut self, cx: &mut Context<'_>) -> Option<(DialogKind, PathBuf)> {
        let (kind, answer) = self.dialogs.poll()?;
        let Some(path) = answer else {
            // Cancelled: a Save As asked for by the unsaved-changes question cancels its action.
            self.after_save = None;
            return None;
        };
        match kind {
            // The editor kept working while the dialog was open: ask again about what
            // changed meanwhile.
            DialogKind::OpenProject => self.request(cx, CloseAction::Open(path)),
            DialogKind::SaveProjectAs => self.save_as(cx, &path),
            DialogKind::ExportIl => self.export_il(cx, &path),
            DialogKind::ExportComments => self.export_comments(cx, &path),
            DialogKind::ImportComments => self.import_comments(cx, &path),
            DialogKind::ExportTrace | DialogKind::ExportDocument | DialogKind::OpenCoverage => {
                return Some((kind, path));
            }
        }
        None
    }

    /// Opens a project file. A damaged one (bad checksum, header or body) is offered read-only.
    pub fn open(&mut self, cx: &mut Context<'_>, path: &Path) -> bool {
        let path = &canonical(path);
        match Document::open(path) {
            Ok(doc) => {
                self.drop_recovery_copy(cx);
                cx.replace_document(Some(doc));
                cx.settings.remember(path.to_path_buf());
                true
            }
            Err(e) => {
                let lang = cx.settings.lang;
                cx.output.say(
                    format!(
                        "{} {}: {}",
                        Msg::OpenFailed.text(lang),
                        path.display(),
                        crate::gui::errors::file_error(&e, lang)
                    ),
                    true,
                );
                if !matches!(e, FileError::Io { .. }) {
                    self.question = Some(Question::Damaged {
                        path: path.to_path_buf(),
                        error: crate::gui::errors::file_error(&e, lang),
                    });
                }
                false
            }
        }
    }

    /// Opens what can be read of a damaged file, read-only: it can be looked at, compiled and
    /// saved under another name, never over the original.
    pub fn open_recovered(&mut self, cx: &mut Context<'_>, path: &Path) -> bool {
        let path = &canonical(path);
        let lang = cx.settings.lang;
        let result = file::read_input(path)
            .map_err(|e| e.to_string())
            .and_then(|b| file::recover(&b).map_err(|e| crate::gui::errors::file_error(&e, lang)));
        match result {
            Ok(project) => {
                let doc = Document::recovered(project, path.to_path_buf());
                self.drop_recovery_copy(cx);
                cx.replace_document(Some(doc));
                cx.output.say(
                    format!("{}: {}", Msg::OpenedReadOnly.text(lang), path.display()),
                    false,
                );
                true
            }
            Err(e) => {
                cx.output.say(
                    format!("{} {}: {e}", Msg::CannotRecover.text(lang), path.display()),
                    true,
                );
                false
            }
        }
    }

    /// Ctrl+S: saves to the project's file; an untitled project asks where (Save As).
    pub fn save(&mut self, cx: &mut Context<'_>) {
        let lang = cx.settings.lang;
        let Some(doc) = cx.doc_mut() else { return };
        if doc.is_read_only() || doc.path().is_none() {
            if doc.is_read_only() {
                cx.output.say(Msg::ReadOnlySaveAs.text(lang).into(), false);
            }
            self.start_dialog(cx, DialogKind::SaveProjectAs);
            return;
        }
        let saved = doc.save();
        if saved.is_ok() {
            self.drop_recovery_copy(cx);
        }
        self.after_saving(cx, saved);
    }

    /// After a save: what waited on it runs; a failure is said, and what waited is dropped.
    fn after_saving(&mut self, cx: &mut Context<'_>, saved: Result<(), FileError>) {
        match saved {
            Ok(()) => {
                if let Some(then) = self.after_save.take() {
                    self.perform(cx, then);
                }
            }
            Err(e) => {
                self.after_save = None;
                let lang = cx.settings.lang;
                cx.output
                    .say(crate::gui::errors::file_error(&e, lang), true);
            }
        }
    }

    /// Saves under a new name; the project then lives there.
    pub fn save_as(&mut self, cx: &mut Context<'_>, path: &Path) {
        let lang = cx.settings.lang;
        let Some(doc) = cx.doc_mut() else { return };
        let path = &canonical(path);
        if doc.recovered_from() == Some(path.as_path()) {
            self.after_save = None;
            cx.output.say(Msg::NotOverDamaged.text(lang).into(), true);
            return;
        }
        let old_copy = self
            .recovery_dir
            .as_ref()
            .map(|d| recovery_path(d, doc.path()));
        let saved = doc.save_as(path);
        if saved.is_ok() {
            if let Some(c) = old_copy {
                remove_copy(&c);
            }
            cx.settings.remember(path.to_path_buf());
        }
        self.after_saving(cx, saved);
    }

    /// Writes the compiled instruction list (as `export-il` does: refused while a network has
    /// no valid list, other errors are reported and the list written).
    pub fn export_il(&mut self, cx: &mut Context<'_>, path: &Path) {
        crate::gui::diagnostics::compile(cx);
        let lang = cx.settings.lang;
        let Some(doc) = cx.doc() else { return };
        let Some(compiled) = doc.compiled() else {
            return;
        };
        if compiled.diagnostics.iter().any(|d| d.code.is_structural()) {
            cx.output.say(Msg::IlNotWritten.text(lang).into(), true);
            return;
        }
        let text = ladder_engine::il::print(&compiled.program);
        match write_atomic(path, &text) {
            Ok(()) => cx.output.say(
                format!("{} {}", Msg::Written.text(lang), path.display()),
                false,
            ),
            Err(e) => cx.output.say(format!("{}: {e}", path.display()), true),
        }
    }

    /// Writes every comment, all languages, as CSV.
    pub fn export_comments(&mut self, cx: &mut Context<'_>, path: &Path) {
        let lang = cx.settings.lang;
        let Some(doc) = cx.doc() else { return };
        let text = ladder_engine::comments::export(doc.project(), None);
        match write_atomic(path, &text) {
            Ok(()) => cx.output.say(
                format!("{} {}", Msg::Written.text(lang), path.display()),
                false,
            ),
            Err(e) => cx.output.say(format!("{}: {e}", path.display()), true),
        }
    }

    /// Applies a comments CSV: all rows or none, one undo step.
    pub fn import_comments(&mut self, cx: &mut Context<'_>, path: &Path) {
        let lang = cx.settings.lang;
        let Some(doc) = cx.doc() else { return };
        if doc.is_read_only() {
            cx.output.say(Msg::ReadOnly.text(lang).into(), true);
            return;
        }
        let text = match file::read_input_text(path) {
            Ok(t) => t,
            Err(e) => {
                cx.output.say(format!("{}: {e}", path.display()), true);
                return;
            }
        };
        let Some(mut project) = cx.doc().map(|d| d.project().clone()) else {
            return;
        };
        match ladder_engine::comments::import(&mut project, &text, None) {
            Ok(n) => match cx.apply(Change::Whole(Box::new(project))) {
                Ok(_) => cx
                    .output
                    .say(format!("{n} {}", Msg::RowsApplied.text(lang)), false),
                Err(e) => cx.output.say(e, true),
            },
            Err(e) => cx.output.say(
                format!(
                    "{}: {}",
                    path.display(),
                    ladder_text::errors::comments_error(&e, lang)
                ),
                true,
            ),
        }
    }

    /// Writes the recovery copy of an unsaved project now.
    pub fn autosave_now(&mut self, cx: &mut Context<'_>) {
        self.last_autosave = Some(Instant::now());
        let (Some(dir), Some(doc)) = (self.recovery_dir.as_ref(), cx.doc()) else {
            return;
        };
        if !doc.is_dirty() || doc.is_read_only() {
            return;
        }
        let copy = recovery_path(dir, doc.path());
        let written = std::fs::create_dir_all(dir)
            .map_err(|e| e.to_string())
            .and_then(|()| {
                file::save(doc.project(), &copy)
                    .map_err(|e| crate::gui::errors::file_error(&e, cx.settings.lang))
            })
            .and_then(|()| {
                let origin = doc
                    .path()
                    .as_ref()
                    .map_or(String::new(), |p| p.to_string_lossy().into_owned());
                write_atomic(&copy.with_extension("origin"), &origin).map_err(|e| e.to_string())
            });
        if let Err(e) = written {
            let lang = cx.settings.lang;
            cx.output
                .say(format!("{}: {e}", Msg::AutosaveFailed.text(lang)), true);
        }
    }

    /// Autosaves when the interval has passed.
    pub fn autosave_tick(&mut self, cx: &mut Context<'_>) {
        let due = self
            .last_autosave
            .is_none_or(|t| t.elapsed() >= Duration::from_secs(AUTOSAVE_MINUTES * 60));
        if self.last_autosave.is_none() {
            // The clock starts with the session: the first copy a full interval later.
            self.last_autosave = Some(Instant::now());
        } else if due {
            self.autosave_now(cx);
        }
    }

    /// The current project's recovery copy is no longer needed (saved, closed, replaced).
    pub fn drop_recovery_copy(&mut self, cx: &mut Context<'_>) {
        if let (Some(dir), Some(doc)) = (self.recovery_dir.as_ref(), cx.doc()) {
            remove_copy(&recovery_path(dir, doc.path()));
        }
    }

    /// At start: a recovery copy left by a session that did not end is offered back.
    pub fn offer_restore(&mut self) {
        let Some(dir) = self.recovery_dir.as_ref() else {
            return;
        };
        if let Some(copy) = recovery_copies(dir).into_iter().next()
            && self.question.is_none()
        {
            self.question = Some(Question::Restore(copy));
        }
    }

    /// Restores a recovery copy: the project as it was, unsaved, under its own file name.
    pub fn restore(&mut self, cx: &mut Context<'_>, copy: &RecoveryCopy) {
        let lang = cx.settings.lang;
        match file::load(&copy.copy) {
            Ok(project) => {
                cx.replace_document(Some(Document::restored(project, copy.original.clone())));
                cx.output.say(Msg::Restored.text(lang).into(), false);
            }
            Err(e) => {
                remove_copy(&copy.copy);
                let e = crate::gui::errors::file_error(&e, lang);
                cx.output
                    .say(format!("{}: {e}", Msg::CannotRecover.text(lang)), true);
            }
        }
    }

    /// The open question, as a modal window.
    pub fn question_ui(&mut self, cx: &mut Context<'_>, ctx: &egui::Context) {
        let Some(q) = self.question.clone() else {
            return;
        };
        let lang = cx.settings.lang;
        let t = |m: Msg| m.text(lang);
        let mut answer: Option<usize> = None;
        let (title, text, buttons): (&str, String, Vec<Msg>) = match &q {
            Question::Unsaved { .. } => {
                let name = cx
                    .doc()
                    .and_then(Document::name)
                    .unwrap_or_else(|| t(Msg::Untitled).into());
                (
                    t(Msg::UnsavedTitle),
                    format!("{} “{name}”?", t(Msg::SaveChangesTo)),
                    vec![Msg::SaveChanges, Msg::DontSave, Msg::Cancel],
                )
            }
            Question::Damaged { path, error } => (
                t(Msg::DamagedTitle),
                format!(
                    "{}\n{error}\n\n{}",
                    path.display(),
                    t(Msg::OpenReadOnlyQuestion)
                ),
                vec![Msg::OpenReadOnly, Msg::Cancel],
            ),
            Question::Restore(copy) => {
                let name = copy
                    .original
                    .as_ref()
                    .map_or(t(Msg::Untitled).to_string(), |p| p.display().to_string());
                let age = copy
                    .saved
                    .and_then(|s| s.elapsed().ok())
                    .map_or(String::new(), |d| {
                        format!(" ({} {})", d.as_secs() / 60, t(Msg::MinutesAgo))
                    });
                (
                    t(Msg::RestoreTitle),
                    format!("{}\n{name}{age}", t(Msg::RestoreQuestion)),
                    vec![Msg::Restore, Msg::Discard],
                )
            }
            Question::FirstForce => (
                t(Msg::FirstForceTitle),
                t(Msg::FirstForceQuestion).to_string(),
                vec![Msg::ForceValue, Msg::Cancel],
            ),
        };
        egui::Modal::new(egui::Id::unique("question")).show(ctx, |ui| {
            ui.heading(title);
            ui.label(&text);
            ui.separator();
            ui.horizontal(|ui| {
                for (i, b) in buttons.iter().enumerate() {
                    if ui.button(t(*b)).clicked() {
                        answer = Some(i);
                    }
                }
            });
            if ui.input(|i| i.key_pressed(egui::Key::Escape)) {
                // Escape never discards: it cancels, or leaves the recovery copy for later.
                answer = Some(usize::MAX);
            }
        });
        let Some(answer) = answer else { return };
        self.question = None;
        match (q, answer) {
            (Question::Unsaved { then }, 0) => {
                self.after_save = Some(then);
                self.save(cx);
            }
            (Question::Unsaved { then }, 1) => self.perform(cx, then),
            (Question::Damaged { path, .. }, 0) => {
                self.open_recovered(cx, &path);
            }
            (Question::Restore(copy), 0) => self.restore(cx, &copy),
            (Question::Restore(copy), 1) => remove_copy(&copy.copy),
            (Question::FirstForce, 0) => cx
                .pending
                .push(crate::gui::command::Command::ConfirmForces(true)),
            (Question::FirstForce, _) => cx
                .pending
                .push(crate::gui::command::Command::ConfirmForces(false)),
            _ => {}
        }
    }

    /// Files dropped on the window are opened (the first project among them).
    pub fn dropped_files(&mut self, cx: &mut Context<'_>, ctx: &egui::Context) {
        let dropped: Vec<PathBuf> = ctx.input(|i| {
            i.raw
                .dropped_files
                .iter()
                .map(|f| f.path().to_path_buf())
                .filter(|p| !p.as_os_str().is_empty())
                .collect()
        });
        if let Some(p) = dropped.into_iter().next() {
            self.request(cx, CloseAction::Open(p));
        }
    }

    /// The window's close button: asks about unsaved changes first.
    pub fn close_requested(&mut self, cx: &mut Context<'_>, ctx: &egui::Context) {
        if !self.exit_confirmed && ctx.input(|i| i.viewport().close_requested()) {
            if cx.doc().is_some_and(|d| d.is_dirty()) {
                ctx.send_viewport_cmd(egui::ViewportCommand::CancelClose);
                self.question = Some(Question::Unsaved {
                    then: CloseAction::Exit,
                });
            } else {
                self.drop_recovery_copy(cx);
            }
        }
    }
}
