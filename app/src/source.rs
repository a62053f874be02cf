//! Reading a PATH argument: a project file or an instruction list, told apart by content.

use crate::cli::Say;
use anyhow::{Result, anyhow, bail};
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
    /// Errors are said in `say`'s language.
    pub fn read(path: &Path, say: Say) -> Result<Source> {
        let bytes = file::read_input(path).map_err(|e| anyhow!(say.cannot_read(path, e)))?;
        if file::is_project_text(&bytes) {
            let project =
                file::from_bytes(&bytes).map_err(|e| anyhow!(say.cannot_open(path, &e)))?;
            return Ok(Source::Project(project));
        }
        let Ok(text) = String::from_utf8(bytes) else {
            bail!(say.pick(
                format!(
                    "{} is neither a Ladder Studio project nor an instruction list (it is not UTF-8 text)",
                    path.display()
                ),
                format!(
                    "{} 既不是 Ladder Studio 工程，也不是指令表（不是 UTF-8 文本）",
                    path.display()
                )
            ));
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
