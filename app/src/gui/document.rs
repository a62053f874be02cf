//! An open project: the model, where it lives, its undo history and whether it changed.

use ladder_engine::compiler::{Compiled, compile};
use ladder_engine::file;
use ladder_engine::model::{History, Project};
use std::path::{Path, PathBuf};

/// The bundled sample, opened on first start.
pub static SAMPLE: &[u8] = include_bytes!("../../../projects/lathe-988ta.ldp");

static NEXT_SERIAL: std::sync::atomic::AtomicU64 = std::sync::atomic::AtomicU64::new(1);

/// An open project.
pub struct Document {
    /// The model.
    pub project: Project,
    /// Where it is saved; `None` for the sample and new projects.
    pub path: Option<PathBuf>,
    /// Undo and redo.
    pub history: History,
    /// Changed since the last save.
    pub dirty: bool,
    /// The last compile, if any.
    pub compiled: Option<Compiled>,
    /// Opened from a damaged file: looked at, never saved over the original.
    pub read_only: bool,
    /// The damaged file a read-only document was recovered from.
    pub recovered_from: Option<PathBuf>,
    /// Tells documents apart (a new or reopened project gets a new one), for caches.
    pub serial: u64,
    /// Counts changes, so views can cache what they derive from the project.
    pub generation: u64,
}

impl Document {
    /// A document for a project.
    pub fn new(project: Project, path: Option<PathBuf>) -> Document {
        Document {
            project,
            path,
            history: History::new(200),
            dirty: false,
            compiled: None,
            generation: 0,
            serial: NEXT_SERIAL.fetch_add(1, std::sync::atomic::Ordering::Relaxed),
            read_only: false,
            recovered_from: None,
        }
    }

    /// Notes a change of the project: unsaved, not compiled, derived views stale.
    pub fn changed(&mut self) {
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

    /// Compiles and keeps the result.
    pub fn compile(&mut self) -> &Compiled {
        self.compiled.insert(compile(&self.project))
    }

    /// The name shown in the title bar.
    pub fn name(&self) -> Option<String> {
        self.path
            .as_ref()
            .and_then(|p| p.file_name())
            .map(|n| n.to_string_lossy().into_owned())
    }
}
