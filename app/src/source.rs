//! Reading a PATH argument: a project file or an instruction list, told apart by content.

use anyhow::{Context, Result, bail};
use ladder_engine::compiler::{Compiled, compile};
use ladder_engine::model::Project;
use ladder_engine::{file, il};
use std::path::Path;

/// What a PATH held.
pub enum Source {
    /// A project file.
    Project(Project),
    /// An instruction list: its text, and the project drawn from it when it could be drawn.
    Il {
        /// The text.
        text: String,
        /// The import result (diagnostics carry IL lines).
        imported: il::Imported,
    },
}

impl Source {
    /// Reads a `.ldp` project or an `.il` text; the content decides, not the extension.
    pub fn read(path: &Path) -> Result<Source> {
        let bytes =
            std::fs::read(path).with_context(|| format!("cannot read {}", path.display()))?;
        if file::is_project_text(&bytes) {
            let project = file::from_bytes(&bytes)
                .with_context(|| format!("{} cannot be opened", path.display()))?;
            return Ok(Source::Project(project));
        }
        let Ok(text) = String::from_utf8(bytes) else {
            bail!(
                "{} is neither a Ladder Studio project nor an instruction list (it is not UTF-8 text)",
                path.display()
            );
        };
        let imported = il::import(&text);
        Ok(Source::Il { text, imported })
    }

    /// The compile result: for a project, its ladder compiled; for IL, the IL checked.
    pub fn compiled(&self) -> Compiled {
        match self {
            Source::Project(p) => compile(p),
            Source::Il { imported, .. } => imported.compiled.clone(),
        }
    }
}
