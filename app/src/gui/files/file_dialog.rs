//! File dialogs that always answer: the system's dialog where one can appear, else the
//! editor's own (egui_file), drawn in the window like any other.
//!
//! rfd talks to the xdg desktop portal over D-Bus and falls back to `zenity`; with neither
//! (minimal desktops, Xvfb, some remote sessions) it returns "no file" at once, exactly as a
//! cancel does, and Open or Save As would silently do nothing. So the choice is made twice:
//! before starting (is there a portal or a zenity at all?) and after (a "cancel" that came
//! back faster than a person can click means the dialog never appeared). Either way the
//! in-app dialog opens on the same question, and stays the choice for the session.

use crate::gui::files::dialogs::{DialogKind, FileDialogs, NativeDialogs};
use crate::gui::i18n::{Lang, Msg};
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

/// A native dialog that answers "cancelled" sooner than this never appeared on screen.
const TOO_FAST: Duration = Duration::from_millis(400);

/// The system's dialogs, with the in-app dialog when they cannot appear.
pub struct SystemDialogs {
    native: Box<dyn FileDialogs>,
    /// Whether the system's dialogs are tried at all.
    native_usable: bool,
    /// The native dialog waited on: its question and when it was asked.
    asked: Option<(DialogKind, Option<PathBuf>, Instant)>,
    in_app: Option<InApp>,
    answer: Option<(DialogKind, Option<PathBuf>)>,
}

/// The in-app dialog open on one question.
struct InApp {
    kind: DialogKind,
    suggested: Option<PathBuf>,
    /// The dialog, built on its first frame in the UI language (and again if that changes).
    dialog: Option<(Lang, egui_file::FileDialog)>,
}

impl Default for SystemDialogs {
    fn default() -> Self {
        SystemDialogs::new(native_dialog_can_appear())
    }
}

impl SystemDialogs {
    /// The dialogs; `native_usable` false uses the in-app dialog from the start.
    pub fn new(native_usable: bool) -> SystemDialogs {
        SystemDialogs::over(Box::new(NativeDialogs::default()), native_usable)
    }

    /// The in-app dialog as the fallback of `native` (tests give scripted ones).
    pub fn over(native: Box<dyn FileDialogs>, native_usable: bool) -> SystemDialogs {
        SystemDialogs {
            native,
            native_usable,
            asked: None,
            in_app: None,
            answer: None,
        }
    }

    /// The dialogs of the editor's own only (tests, and systems without a portal).
    pub fn in_app_only() -> SystemDialogs {
        SystemDialogs::new(false)
    }

    /// Whether the in-app dialog is on screen.
    pub fn in_app_open(&self) -> bool {
        self.in_app.is_some()
    }

    fn open_in_app(&mut self, kind: DialogKind, suggested: Option<PathBuf>) {
        self.in_app = Some(InApp {
            kind,
            suggested,
            dialog: None,
        });
    }
}

impl FileDialogs for SystemDialogs {
    fn start(&mut self, ctx: &egui::Context, kind: DialogKind, suggested: Option<PathBuf>) {
        if self.busy() {
            return;
        }
        if self.native_usable {
            self.asked = Some((kind, suggested.clone(), Instant::now()));
            self.native.start(ctx, kind, suggested);
        } else {
            self.open_in_app(kind, suggested);
        }
        ctx.request_repaint();
    }

    fn poll(&mut self) -> Option<(DialogKind, Option<PathBuf>)> {
        if let Some(answer) = self.answer.take() {
            return Some(answer);
        }
        let (kind, path) = self.native.poll()?;
        let (_, suggested, at) = self.asked.take()?;
        if path.is_none() && at.elapsed() < TOO_FAST {
            // Nobody cancels that fast: the system's dialog could not appear. Ask here
            // instead, and from now on.
            self.native_usable = false;
            self.open_in_app(kind, suggested);
            return None;
        }
        Some((kind, path))
    }

    fn busy(&self) -> bool {
        self.native.busy() || self.in_app.is_some() || self.answer.is_some()
    }

    fn show(&mut self, ctx: &egui::Context, lang: Lang) {
        let Some(open) = &mut self.in_app else {
            return;
        };
        if open.dialog.as_ref().is_none_or(|(l, _)| *l != lang) {
            // The texts follow the UI language, also when it changes while the dialog is open.
            let mut d = texts(
                in_app_dialog(open.kind, open.suggested.as_deref()),
                open.kind,
                lang,
            );
            d.open();
            open.dialog = Some((lang, d));
        }
        let Some((_, dialog)) = &mut open.dialog else {
            return;
        };
        dialog.show(ctx);
        let answer = match dialog.state() {
            egui_file::State::Selected => dialog
                .path()
                .map(|p| with_extension(open.kind, p.to_path_buf())),
            egui_file::State::Cancelled | egui_file::State::Closed => None,
            egui_file::State::Open => return,
        };
        let kind = open.kind;
        self.in_app = None;
        self.answer = Some((kind, answer));
        ctx.request_repaint();
    }
}

/// The in-app dialog for a question, opening where `suggested` points.
fn in_app_dialog(kind: DialogKind, suggested: Option<&Path>) -> egui_file::FileDialog {
    let saves = kind.saves();
    let mut d = if saves {
        egui_file::FileDialog::save_file()
    } else {
        egui_file::FileDialog::open_file()
    };
    let dir = suggested
        .and_then(|s| s.parent())
        .filter(|d| !d.as_os_str().is_empty() && d.is_dir())
        .map(Path::to_path_buf)
        .or_else(|| std::env::current_dir().ok());
    if let Some(dir) = dir {
        d = d.initial_path(dir);
    }
    if let Some(name) = suggested.and_then(|s| s.file_name()) {
        d = d.default_filename(name.to_string_lossy());
    }
    let (_, exts) = kind.filter();
    d.id(egui::Id::unique("in-app-file-dialog"))
        .default_size(egui::vec2(560.0, 420.0))
        .keep_on_top(true)
        .show_rename(false)
        .show_files_filter(Box::new(move |p: &Path| {
            p.extension()
                .and_then(|e| e.to_str())
                .is_some_and(|e| exts.iter().any(|x| x.eq_ignore_ascii_case(e)))
        }))
}

/// The dialog's texts in the UI language.
fn texts(d: egui_file::FileDialog, kind: DialogKind, lang: Lang) -> egui_file::FileDialog {
    let t = |m: Msg| std::borrow::Cow::Borrowed(m.text(lang));
    let title = match kind {
        DialogKind::OpenProject => Msg::Open,
        DialogKind::SaveProjectAs => Msg::SaveAs,
        DialogKind::ExportIl => Msg::ExportIl,
        DialogKind::ExportComments => Msg::ExportComments,
        DialogKind::ImportComments => Msg::ImportComments,
        DialogKind::ExportTrace => Msg::TraceExport,
        DialogKind::ExportDocument => Msg::ExportDocument,
        DialogKind::OpenCoverage => Msg::CoverageFile,
    };
    d.title(title.text(lang))
        .open_button_text(t(Msg::DialogOpen))
        .save_button_text(t(Msg::DialogSave))
        .cancel_button_text(t(Msg::Cancel))
        .new_folder_button_text(t(Msg::NewFolder))
        .new_folder_name_text(t(Msg::NewFolderName))
        .refresh_button_hover_text(t(Msg::Refresh))
        .parent_folder_button_hover_text(t(Msg::ParentFolder))
        .file_label_text(t(Msg::FileLabel))
        .show_hidden_checkbox_text(t(Msg::ShowHidden))
}

/// A name typed without its extension gets the one the question is about, as the system's
/// dialogs do (`machine` saves as `machine.ldp`).
fn with_extension(kind: DialogKind, path: PathBuf) -> PathBuf {
    if !kind.saves() || path.extension().is_some() {
        return path;
    }
    let (_, exts) = kind.filter();
    path.with_extension(exts[0])
}

/// Whether the system's dialog can appear here at all: always outside Linux and the BSDs;
/// there, when `zenity` is installed or a desktop portal is on a session bus.
pub fn native_dialog_can_appear() -> bool {
    if !cfg!(all(unix, not(target_os = "macos"))) {
        return true;
    }
    let path = std::env::var_os("PATH").unwrap_or_default();
    let zenity = std::env::split_paths(&path).any(|d| d.join("zenity").is_file());
    let bus = std::env::var_os("DBUS_SESSION_BUS_ADDRESS").is_some_and(|a| !a.is_empty());
    zenity || (bus && portal_installed())
}

/// Whether the desktop portal's D-Bus service is installed (its service file, where D-Bus
/// looks for it).
fn portal_installed() -> bool {
    let dirs = std::env::var("XDG_DATA_DIRS")
        .ok()
        .filter(|d| !d.is_empty())
        .unwrap_or_else(|| "/usr/local/share:/usr/share".to_string());
    dirs.split(':').any(|d| {
        Path::new(d)
            .join("dbus-1/services/org.freedesktop.portal.Desktop.service")
            .is_file()
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_name_typed_without_extension_gets_the_questions_extension() {
        let p = with_extension(DialogKind::SaveProjectAs, PathBuf::from("/tmp/machine"));
        assert_eq!(p, PathBuf::from("/tmp/machine.ldp"));
        let p = with_extension(DialogKind::ExportIl, PathBuf::from("/tmp/list.txt"));
        assert_eq!(p, PathBuf::from("/tmp/list.txt"));
        let p = with_extension(DialogKind::OpenProject, PathBuf::from("/tmp/any"));
        assert_eq!(p, PathBuf::from("/tmp/any"));
    }

    #[test]
    fn without_a_portal_or_zenity_the_in_app_dialog_is_used() {
        let mut d = SystemDialogs::in_app_only();
        let ctx = egui::Context::default();
        d.start(&ctx, DialogKind::OpenProject, None);
        assert!(d.in_app_open() && d.busy());
        assert_eq!(d.poll(), None, "no answer before the user gives one");
    }

    #[test]
    fn a_system_dialog_that_cancels_at_once_never_appeared_and_the_in_app_one_opens() {
        use crate::gui::files::dialogs::ScriptedDialogs;
        let ctx = egui::Context::default();
        // An empty script answers "cancelled" at once, as rfd does without portal or zenity.
        let mut d = SystemDialogs::over(Box::new(ScriptedDialogs::new([])), true);
        d.start(
            &ctx,
            DialogKind::SaveProjectAs,
            Some(PathBuf::from("a.ldp")),
        );
        assert_eq!(d.poll(), None, "not taken for the user's cancel");
        assert!(d.in_app_open());
        // From then on the in-app dialog is asked first.
        assert!(!d.native_usable);
        d.in_app = None;
        d.start(&ctx, DialogKind::ExportIl, None);
        assert!(d.in_app_open() && !d.native.busy());
    }

    #[test]
    fn a_system_dialog_answered_with_a_file_is_the_answer() {
        use crate::gui::files::dialogs::ScriptedDialogs;
        let ctx = egui::Context::default();
        let scripted = ScriptedDialogs::new([Some(PathBuf::from("/tmp/x.ldp"))]);
        let mut d = SystemDialogs::over(Box::new(scripted), true);
        d.start(&ctx, DialogKind::OpenProject, None);
        assert_eq!(
            d.poll(),
            Some((DialogKind::OpenProject, Some(PathBuf::from("/tmp/x.ldp"))))
        );
        assert!(!d.in_app_open() && !d.busy());
    }
}
