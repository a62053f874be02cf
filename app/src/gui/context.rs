//! What a feature may use of the editor while it runs: the open document (to read, and to
//! change through its one `apply`), the settings, the output window, the command queue and
//! the ladder cursor and selection. A feature owns its own state and takes this narrow
//! context instead of the whole app (rerun's `ViewerContext` is the model), so a new page
//! or command touches its feature and the command list only.

use super::command::Command;
use super::document::Document;
use super::i18n::Msg;
use super::output::Output;
use super::place::View;
use super::settings::Settings;
use ladder_engine::model::region::Region as Selection;
use ladder_engine::model::{CellRef, Change};

/// The editor as a feature sees it.
pub struct Context<'a> {
    /// The open project.
    doc: &'a mut Option<Document>,
    /// The settings (a feature's own persisted choices live there).
    pub settings: &'a mut Settings,
    /// The output window.
    pub output: &'a mut Output,
    /// Commands to run after the frame (another feature's dialog, a jump to a cell).
    pub pending: &'a mut Vec<Command>,
    /// The ladder cursor.
    pub cursor: &'a mut CellRef,
    /// The ladder selection: its block and region.
    pub selection: &'a mut Option<(usize, Selection)>,
    /// The view the main area shows.
    pub view: &'a mut View,
    /// The view tabs, in the order they were opened.
    pub tabs: &'a mut Vec<View>,
    /// The window's egui context (file dialogs, the machine thread's wake-ups, closing).
    pub egui: Option<&'a egui::Context>,
    /// A change was applied through [`Context::apply`].
    changed: bool,
    /// Another document (or none) took the open one's place.
    replaced: bool,
}

impl<'a> Context<'a> {
    /// The context over these parts of the editor.
    pub fn new(
        doc: &'a mut Option<Document>,
        settings: &'a mut Settings,
        output: &'a mut Output,
        pending: &'a mut Vec<Command>,
        (cursor, selection): (&'a mut CellRef, &'a mut Option<(usize, Selection)>),
        (view, tabs): (&'a mut View, &'a mut Vec<View>),
        egui: Option<&'a egui::Context>,
    ) -> Context<'a> {
        Context {
            doc,
            settings,
            output,
            pending,
            cursor,
            selection,
            view,
            tabs,
            egui,
            changed: false,
            replaced: false,
        }
    }

    /// The open project's document, to read.
    pub fn doc(&self) -> Option<&Document> {
        self.doc.as_ref()
    }

    /// The document to read beside the settings and the output to change, at once.
    pub fn parts(&mut self) -> (Option<&Document>, &mut Settings, &mut Output) {
        (self.doc.as_ref(), self.settings, self.output)
    }

    /// Hands a change to the document's one apply (read-only check, undo record, change
    /// count); a refusal comes back in the UI's language.
    pub fn apply(&mut self, change: impl Into<Change>) -> Result<bool, String> {
        let lang = self.settings.lang;
        let doc = self.doc.as_mut().ok_or(Msg::NoProject.text(lang))?;
        let changed = doc
            .apply(change)
            .map_err(|e| super::errors::refused(&e, lang))?;
        self.changed |= changed;
        Ok(changed)
    }

    /// Applies a change from a command or a table; a refusal goes to the output window. True
    /// when the change was applied (or changed nothing).
    pub fn apply_or_say(&mut self, change: impl Into<Change>) -> bool {
        match self.apply(change) {
            Ok(_) => true,
            Err(text) => {
                self.output.say(text, true);
                false
            }
        }
    }

    /// Compiles the open project (the document keeps the result) and gives the result with
    /// the project's name as diagnostics cite it.
    pub fn compile(&mut self) -> Option<(&ladder_engine::compiler::Compiled, String)> {
        let lang = self.settings.lang;
        let doc = self.doc.as_mut()?;
        let name = doc
            .name()
            .unwrap_or_else(|| Msg::Untitled.text(lang).to_string());
        Some((doc.compile(), name))
    }

    /// Keeps the document read-only while a recorded tick is shown (the online feature's
    /// replay).
    pub fn set_replaying(&mut self, on: bool) {
        if let Some(d) = self.doc.as_mut() {
            d.set_replaying(on);
        }
    }

    /// Starts one undo step: the changes applied until [`Context::end_group`] are undone
    /// together.
    pub fn begin_group(&mut self) {
        if let Some(d) = self.doc.as_mut() {
            d.begin_group();
        }
    }

    /// Ends the undo step [`Context::begin_group`] started.
    pub fn end_group(&mut self) {
        if let Some(d) = self.doc.as_mut() {
            d.end_group();
        }
    }

    /// The open document, for what the document does besides changing the project (saving
    /// it, under its name or another): its metadata changes only through its own methods,
    /// the project only through [`Context::apply`].
    pub fn doc_mut(&mut self) -> Option<&mut Document> {
        self.doc.as_mut()
    }

    /// Puts another document (or none) in the open one's place; the editor starts over on it
    /// after the feature returns (the view, the cursor, the features' state of the old one).
    pub fn replace_document(&mut self, doc: Option<Document>) {
        *self.doc = doc;
        self.replaced = true;
    }

    /// Whether another document took the open one's place.
    pub fn replaced(&self) -> bool {
        self.replaced
    }

    /// Whether a change was applied.
    pub fn changed(&self) -> bool {
        self.changed
    }
}
