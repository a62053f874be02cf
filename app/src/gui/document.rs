//! An open project: the model, where it lives, its undo history and whether it changed.
//!
//! The document is the one door into the project: [`Document::apply`] is the only way to
//! change it. It refuses every change of a read-only (recovered) project, drops changes that
//! change nothing, records the inverse for undo (steps of one gesture inside
//! [`Document::begin_group`] … [`Document::end_group`] become one undo step) and counts the
//! change, so views that cache what they derive from the project know to refresh.

use ladder_engine::compiler::Compiled;
use ladder_engine::diagnose::diagnose;
use ladder_engine::file;
use ladder_engine::model::{CellRef, Change, EditError, History, Project};
use std::path::{Path, PathBuf};

/// The bundled sample, opened on first start.
pub static SAMPLE: &[u8] = include_bytes!("../../../projects/lathe-988ta.ldp");

static NEXT_SERIAL: std::sync::atomic::AtomicU64 = std::sync::atomic::AtomicU64::new(1);

/// Why a change was not applied.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Refused {
    /// The project was recovered from a damaged file and is read-only.
    ReadOnly,
    /// A recorded tick is on screen (replay): nothing changes until back to live.
    Replaying,
    /// The engine refused the edit (the place does not exist, the wrong column…).
    Edit(EditError),
}

/// An open project.
pub struct Document {
    project: Project,
    history: History,
    /// An undo group is open: changes from this undo depth on become one step.
    group: Option<usize>,
    /// Where it is saved; `None` for the sample and new projects.
    path: Option<PathBuf>,
    /// Changed since the last save.
    dirty: bool,
    /// The last compile, if any.
    compiled: Option<Compiled>,
    /// Opened from a damaged file: looked at, never saved over the original.
    read_only: bool,
    /// A recorded past of the machine is on screen: no change, undo or redo, so the program
    /// that runs at "back to live" is the one that ran.
    replaying: bool,
    /// The damaged file a read-only document was recovered from.
    recovered_from: Option<PathBuf>,
    /// Tells documents apart (a new or reopened project gets a new one), for caches.
    serial: u64,
    /// Counts changes, so views can cache what they derive from the project.
    generation: u64,
    /// Compiled once by the user: from then on every change is checked again, so the
    /// diagram's error marks follow the drawing.
    checking: bool,
}

impl Document {
    /// A document for a project.
    pub fn new(project: Project, path: Option<PathBuf>) -> Document {
        Document {
            project,
            history: History::new(200),
            group: None,
            path,
            dirty: false,
            compiled: None,
            generation: 0,
            serial: NEXT_SERIAL.fetch_add(1, std::sync::atomic::Ordering::Relaxed),
            read_only: false,
            replaying: false,
            recovered_from: None,
            checking: false,
        }
    }

    /// The project, to read.
    pub fn project(&self) -> &Project {
        &self.project
    }

    /// The undo history, to read (what can be undone or redone).
    pub fn history(&self) -> &History {
        &self.history
    }

    /// Applies a change: `Ok(true)` when the project changed, `Ok(false)` when the change
    /// changed nothing (no undo step, not unsaved).
    pub fn apply(&mut self, change: impl Into<Change>) -> Result<bool, Refused> {
        if self.read_only {
            return Err(Refused::ReadOnly);
        }
        if self.replaying {
            return Err(Refused::Replaying);
        }
        let inverse = self
            .project
            .apply_change(change.into())
            .map_err(Refused::Edit)?;
        if self.project.is_unchanged_by(&inverse) {
            return Ok(false);
        }
        match self.group {
            Some(depth) if self.history.undo_len() > depth => self.history.record_merged(inverse),
            _ => self.history.record(inverse),
        }
        self.changed();
        Ok(true)
    }

    /// Opens an undo group: every change until [`Document::end_group`] is one undo step (a
    /// network added to an empty block for the contact placed in it). Groups do not nest: an
    /// inner begin is part of the outer group.
    pub fn begin_group(&mut self) {
        if self.group.is_none() {
            self.group = Some(self.history.undo_len());
        }
    }

    /// Closes the undo group.
    pub fn end_group(&mut self) {
        self.group = None;
    }

    /// Takes back the last step; returns the step that a redo would do again (it names the
    /// place that changed), `None` when there was nothing to undo.
    pub fn undo(&mut self) -> Option<&Change> {
        self.group = None;
        if self.replaying {
            return None;
        }
        if self.history.undo(&mut self.project) {
            self.changed();
            self.history.last_redo()
        } else {
            None
        }
    }

    /// Does the last undone step again; returns it inverted, as [`Document::undo`] does.
    pub fn redo(&mut self) -> Option<&Change> {
        self.group = None;
        if self.replaying {
            return None;
        }
        if self.history.redo(&mut self.project) {
            self.changed();
            self.history.last_undo()
        } else {
            None
        }
    }

    /// Notes a change of the project: unsaved, not compiled, derived views stale.
    fn changed(&mut self) {
        self.dirty = true;
        self.compiled = None;
        self.generation += 1;
    }

    /// Opens a project file.
    pub fn open(path: &Path) -> Result<Document, file::FileError> {
        Ok(Document::new(file::load(path)?, Some(path.to_path_buf())))
    }

    /// The bundled sample project.
    pub fn sample() -> Document {
        let project = file::from_bytes(SAMPLE).expect("the bundled sample is a valid project");
        Document::new(project, None)
    }

    /// Saves to its path.
    pub fn save(&mut self) -> Result<(), file::FileError> {
        if let Some(path) = &self.path {
            file::save(&self.project, path)?;
            self.dirty = false;
        }
        Ok(())
    }

    /// Saves under a new name; the project then lives there and is no longer read-only.
    pub fn save_as(&mut self, path: &Path) -> Result<(), file::FileError> {
        file::save(&self.project, path)?;
        self.path = Some(path.to_path_buf());
        self.dirty = false;
        self.read_only = false;
        self.recovered_from = None;
        Ok(())
    }

    /// Where it is saved; `None` for the sample and new projects.
    pub fn path(&self) -> Option<&Path> {
        self.path.as_deref()
    }

    /// Changed since the last save.
    pub fn is_dirty(&self) -> bool {
        self.dirty
    }

    /// Opened from a damaged file: looked at, never saved over the original.
    pub fn is_read_only(&self) -> bool {
        self.read_only
    }

    /// A recorded past of the machine is on screen.
    pub fn is_replaying(&self) -> bool {
        self.replaying
    }

    /// The damaged file a read-only document was recovered from.
    pub fn recovered_from(&self) -> Option<&Path> {
        self.recovered_from.as_deref()
    }

    /// The last compile, if the project has not changed since.
    pub fn compiled(&self) -> Option<&Compiled> {
        self.compiled.as_ref()
    }

    /// Tells documents apart (a new or reopened project gets a new one), for caches.
    pub fn serial(&self) -> u64 {
        self.serial
    }

    /// Counts changes, so views can cache what they derive from the project.
    pub fn generation(&self) -> u64 {
        self.generation
    }

    /// What could be read of the damaged file `from`: read-only, never saved over it.
    pub fn recovered(project: Project, from: PathBuf) -> Document {
        let mut doc = Document::new(project, None);
        doc.read_only = true;
        doc.recovered_from = Some(from);
        doc
    }

    /// A recovery copy restored: the project as it was, unsaved, under its own file's name.
    pub fn restored(project: Project, original: Option<PathBuf>) -> Document {
        let mut doc = Document::new(project, original);
        doc.dirty = true;
        doc
    }

    /// Read-only exactly while a recorded past of the machine is shown.
    pub fn set_replaying(&mut self, on: bool) {
        self.replaying = on;
    }

    /// Compiles and keeps the result; from now on changes are checked as they are made.
    pub fn compile(&mut self) -> &Compiled {
        self.checking = true;
        self.compiled.insert(diagnose(&self.project))
    }

    /// Compiles again after a change, once the user has compiled (a drawing in progress is
    /// not marked with errors before it is first compiled).
    pub fn recheck(&mut self) {
        if self.checking && self.compiled.is_none() {
            self.compiled = Some(diagnose(&self.project));
        }
    }

    /// The last compile's diagnostics that point at a cell, in ladder order: where, and
    /// whether it is an error (else a warning).
    pub fn marks(&self) -> Vec<(CellRef, &ladder_engine::compiler::Diagnostic)> {
        let Some(c) = &self.compiled else {
            return Vec::new();
        };
        let mut marks: Vec<_> = c
            .diagnostics
            .iter()
            .filter_map(|d| Some((d.location.cell()?, d)))
            .collect();
        marks.sort_by_key(|m| m.0);
        marks
    }

    /// The name shown in the title bar.
    pub fn name(&self) -> Option<String> {
        self.path
            .as_ref()
            .and_then(|p| p.file_name())
            .map(|n| n.to_string_lossy().into_owned())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use ladder_engine::model::{Cell, CellRef, Edit, TableEdit};

    fn at(network: usize, col: usize) -> CellRef {
        CellRef {
            block: 1,
            network,
            row: 0,
            col,
        }
    }

    #[test]
    fn a_group_is_one_undo_step_and_a_change_of_nothing_is_none() {
        let mut d = Document::new(Project::default(), None);
        let insert = d.project().ladder.plan_insert_network(1, 0);
        d.begin_group();
        assert_eq!(d.apply(insert), Ok(true));
        assert_eq!(
            d.apply(Edit::SetCell {
                at: at(0, 0),
                cell: Cell::Wire
            }),
            Ok(true)
        );
        d.end_group();
        assert_eq!(d.history().undo_len(), 1, "one gesture, one step");
        let generation = d.generation;
        let same = Edit::SetCell {
            at: at(0, 0),
            cell: Cell::Wire,
        };
        assert_eq!(d.apply(same), Ok(false));
        assert_eq!(
            d.generation, generation,
            "nothing changed, nothing to refresh"
        );
        let tables = TableEdit::MCodes(d.project().m_codes.clone());
        assert_eq!(d.apply(tables), Ok(false));
        assert!(d.undo().is_some());
        assert!(d.project().ladder.blocks[1].networks.is_empty());
        assert!(d.undo().is_none());
    }

    #[test]
    fn a_read_only_document_refuses_every_change() {
        let mut d = Document::new(Project::default(), None);
        d.read_only = true;
        let insert = d.project().ladder.plan_insert_network(1, 0);
        assert_eq!(d.apply(insert), Err(Refused::ReadOnly));
        assert!(!d.dirty);
        let bad = Edit::SetCell {
            at: at(5, 0),
            cell: Cell::Wire,
        };
        d.read_only = false;
        assert!(matches!(d.apply(bad), Err(Refused::Edit(_))));
    }
}
