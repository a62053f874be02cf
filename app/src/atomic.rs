//! Writing an output file whole or not at all: through a temporary file beside it, renamed
//! over it, so a failed write never leaves half a file under the name asked for.

use std::io::Write;
use std::path::Path;

/// Writes `bytes` to `path` atomically; a temporary file left by a failure is removed.
/// Through a symbolic link to the file it names, keeping that file's permissions
/// (`file::write_target`, `file::keep_mode`).
pub(crate) fn write_atomic(path: &Path, bytes: &[u8]) -> std::io::Result<()> {
    let target = ladder_engine::file::write_target(path);
    let path = target.as_path();
    let name = path
        .file_name()
        .map_or("out".into(), |n| n.to_string_lossy());
    sweep_stale(path, &name);
    let tmp = path.with_file_name(format!(".{name}.{}.tmp", std::process::id()));
    let written = std::fs::File::create(&tmp).and_then(|mut f| {
        f.write_all(bytes)?;
        f.sync_all()?;
        ladder_engine::file::keep_mode(path, &tmp)
    });
    written
        .and_then(|()| std::fs::rename(&tmp, path))
        .inspect_err(|_| {
            let _ = std::fs::remove_file(&tmp);
        })
}

/// Removes what a killed write to `path` (named `name`) left beside it: the temporary files
/// of processes that no longer run (where that cannot be told, of any older than an hour).
fn sweep_stale(path: &Path, name: &str) {
    let dir = match path.parent() {
        Some(d) if !d.as_os_str().is_empty() => d,
        _ => Path::new("."),
    };
    let Ok(entries) = std::fs::read_dir(dir) else {
        return;
    };
    let prefix = format!(".{name}.");
    for e in entries.flatten() {
        let file = e.file_name();
        let Some(pid) = file
            .to_str()
            .and_then(|f| f.strip_prefix(&prefix))
            .and_then(|f| f.strip_suffix(".tmp"))
            .and_then(|p| p.parse::<u32>().ok())
        else {
            continue;
        };
        if pid != std::process::id() && !running(pid, &e) {
            let _ = std::fs::remove_file(e.path());
        }
    }
}

/// Whether process `pid`, which left `file`, may still be writing it.
fn running(pid: u32, file: &std::fs::DirEntry) -> bool {
    let proc = Path::new("/proc");
    if proc.join("self").exists() {
        return proc.join(pid.to_string()).exists();
    }
    file.metadata()
        .and_then(|m| m.modified())
        .ok()
        .and_then(|t| t.elapsed().ok())
        .is_none_or(|age| age < std::time::Duration::from_secs(3600))
}

#[cfg(all(test, unix))]
mod tests {
    use super::write_atomic;
    use std::os::unix::fs::{PermissionsExt, symlink};

    #[test]
    fn an_output_through_a_link_replaces_the_file_it_names_and_keeps_its_mode() {
        let dir = tempfile::tempdir().unwrap();
        let real = dir.path().join("report.svg");
        std::fs::write(&real, "old").unwrap();
        std::fs::set_permissions(&real, std::fs::Permissions::from_mode(0o640)).unwrap();
        let link = dir.path().join("latest.svg");
        symlink(&real, &link).unwrap();
        write_atomic(&link, b"new").unwrap();
        assert!(
            std::fs::symlink_metadata(&link)
                .unwrap()
                .file_type()
                .is_symlink()
        );
        assert_eq!(std::fs::read_to_string(&real).unwrap(), "new");
        let mode = std::fs::metadata(&real).unwrap().permissions().mode() & 0o777;
        assert_eq!(mode, 0o640);
    }
}
