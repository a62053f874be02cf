//! The questions the editor asks about files and how they are answered: the file dialogs
//! behind a small trait (native ones on a named thread; tests script the answers and never
//! open one), the actions that wait on the unsaved-changes question, and the recovery copies.
//! A leaf module: the files feature (`files/mod.rs`) builds on it.

use std::collections::VecDeque;
use std::path::PathBuf;
use std::sync::mpsc;
use std::time::SystemTime;

/// What a file dialog is asked for; the answer is handled by the same kind.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum DialogKind {
    /// Pick a project to open.
    OpenProject,
    /// Pick where to save the project.
    SaveProjectAs,
    /// Pick where to write the instruction list.
    ExportIl,
    /// Pick where to write the comments CSV.
    ExportComments,
    /// Pick a comments CSV to import.
    ImportComments,
    /// Pick where to write the signal trace (CSV, the `sim --trace` format).
    ExportTrace,
    /// Pick where to write the printed document (PDF, or SVG pages).
    ExportDocument,
    /// Pick a coverage file to show (JSON, from `test --coverage`).
    OpenCoverage,
}

impl DialogKind {
    /// Whether the answer is a file to write (else one to read).
    pub fn saves(self) -> bool {
        matches!(
            self,
            DialogKind::SaveProjectAs
                | DialogKind::ExportIl
                | DialogKind::ExportComments
                | DialogKind::ExportTrace
                | DialogKind::ExportDocument
        )
    }

    /// The file type's name and extensions, the first one the default.
    pub fn filter(self) -> (&'static str, &'static [&'static str]) {
        match self {
            DialogKind::OpenProject | DialogKind::SaveProjectAs => ("Ladder project", &["ldp"]),
            DialogKind::ExportIl => ("Instruction list", &["il", "txt"]),
            DialogKind::ExportComments | DialogKind::ImportComments | DialogKind::ExportTrace => {
                ("CSV", &["csv"])
            }
            DialogKind::ExportDocument => ("PDF / SVG", &["pdf", "svg"]),
            DialogKind::OpenCoverage => ("Coverage", &["json"]),
        }
    }
}

/// File dialogs: started from the UI, answered later so the UI never blocks.
pub trait FileDialogs {
    /// Starts a dialog (at most one at a time); `suggested` is the file name or path offered.
    fn start(&mut self, ctx: &egui::Context, kind: DialogKind, suggested: Option<PathBuf>);
    /// The answer of the dialog started last, once there is one: `None` inside means cancelled.
    fn poll(&mut self) -> Option<(DialogKind, Option<PathBuf>)>;
    /// Whether a dialog is open.
    fn busy(&self) -> bool;
    /// Draws a dialog that lives in the editor's window, once a frame (system dialogs have
    /// their own window and draw nothing here).
    fn show(&mut self, _ctx: &egui::Context, _lang: crate::gui::i18n::Lang) {}
}

/// The system's dialogs (rfd: the xdg portal, else zenity), each on its own thread.
#[derive(Default)]
pub struct NativeDialogs {
    answer: Option<mpsc::Receiver<(DialogKind, Option<PathBuf>)>>,
}

impl FileDialogs for NativeDialogs {
    fn start(&mut self, ctx: &egui::Context, kind: DialogKind, suggested: Option<PathBuf>) {
        if self.answer.is_some() {
            return;
        }
        let (tx, rx) = mpsc::channel();
        self.answer = Some(rx);
        let ctx = ctx.clone();
        // rfd blocks until the user answers: a thread keeps the editor drawing meanwhile.
        let spawned = std::thread::Builder::new()
            .name("file-dialog".into())
            .spawn(move || {
                let (name, exts) = kind.filter();
                let mut d = rfd::FileDialog::new().add_filter(name, exts);
                if let Some(s) = &suggested {
                    if let Some(dir) = s.parent().filter(|d| d.is_dir()) {
                        d = d.set_directory(dir);
                    }
                    if let Some(f) = s.file_name() {
                        d = d.set_file_name(f.to_string_lossy());
                    }
                }
                let path = if kind.saves() {
                    d.save_file()
                } else {
                    d.pick_file()
                };
                let _ = tx.send((kind, path));
                ctx.request_repaint();
            });
        if spawned.is_err() {
            // No thread, no dialog: the editor is not left waiting for an answer.
            self.answer = None;
        }
    }

    fn poll(&mut self) -> Option<(DialogKind, Option<PathBuf>)> {
        let answer = self.answer.as_ref()?.try_recv();
        match answer {
            Ok(a) => {
                self.answer = None;
                Some(a)
            }
            Err(mpsc::TryRecvError::Empty) => None,
            Err(mpsc::TryRecvError::Disconnected) => {
                self.answer = None;
                None
            }
        }
    }

    fn busy(&self) -> bool {
        self.answer.is_some()
    }
}

/// Dialogs that answer from a list, for tests and scripted runs.
#[derive(Debug, Default)]
pub struct ScriptedDialogs {
    /// The answers, in order; an empty list answers "cancelled".
    pub answers: VecDeque<Option<PathBuf>>,
    /// Every dialog asked for, in order.
    pub asked: Vec<DialogKind>,
    pending: Option<DialogKind>,
}

impl ScriptedDialogs {
    /// Dialogs that will answer `answers` in turn.
    pub fn new(answers: impl IntoIterator<Item = Option<PathBuf>>) -> ScriptedDialogs {
        ScriptedDialogs {
            answers: answers.into_iter().collect(),
            ..Default::default()
        }
    }
}

impl FileDialogs for ScriptedDialogs {
    fn start(&mut self, _ctx: &egui::Context, kind: DialogKind, _suggested: Option<PathBuf>) {
        self.asked.push(kind);
        self.pending = Some(kind);
    }

    fn poll(&mut self) -> Option<(DialogKind, Option<PathBuf>)> {
        let kind = self.pending.take()?;
        Some((kind, self.answers.pop_front().flatten()))
    }

    fn busy(&self) -> bool {
        self.pending.is_some()
    }
}

/// Something that closes the current project, and so first asks about unsaved changes.
#[derive(Clone, Debug, PartialEq)]
pub enum CloseAction {
    /// A new, empty project.
    New,
    /// Pick a project in a dialog, then open it.
    OpenDialog,
    /// Open this file.
    Open(PathBuf),
    /// Close the project.
    Close,
    /// Quit the editor.
    Exit,
}

/// A question the editor is waiting on.
#[derive(Clone, Debug, PartialEq)]
pub enum Question {
    /// The project has unsaved changes: save them before `then`?
    Unsaved {
        /// What happens after the answer.
        then: CloseAction,
    },
    /// The file is damaged: open what can be read, read-only?
    Damaged {
        /// The file.
        path: PathBuf,
        /// Why it could not be opened.
        error: String,
    },
    /// A recovery copy was left by a session that did not end: restore it?
    Restore(RecoveryCopy),
    /// The first force of this run of the editor: force really?
    FirstForce,
}

/// An autosaved recovery copy on disk.
#[derive(Clone, Debug, PartialEq)]
pub struct RecoveryCopy {
    /// The copy.
    pub copy: PathBuf,
    /// The project's own file, if it had one.
    pub original: Option<PathBuf>,
    /// When the copy was written.
    pub saved: Option<SystemTime>,
}
