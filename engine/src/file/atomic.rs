//! Writing an output file whole or not at all: through a temporary file beside it, renamed
//! over it, so a failed write never leaves half a file under the name asked for.

use std::io::Write;
use std::path::Path;

/// Writes `bytes` to `path` atomically; a temporary file left by a failure is removed.
/// Through a symbolic link to the file it names, keeping that file's permissions
/// (`file::write_target`, `file::keep_mode`). A target that is no regular file (a device such
/// as `/dev/stdout`, a pipe) is written in place: it holds no old content to keep whole, and
/// renaming over it would replace it.
pub fn write_atomic(path: &Path, bytes: &[u8]) -> std::io::Result<()> {
    // Asked of the name as given: the system follows `/dev/stdout` to a pipe that has no
    // path of its own.
    if std::fs::metadata(path).is_ok_and(|m| !m.is_file() && !m.is_dir()) {
        return std::fs::OpenOptions::new()
            .write(true)
            .open(path)
            .and_then(|mut f| f.write_all(bytes));
    }
    let target = super::write_target(path);
    let path = target.as_path();
    let name = path
        .file_name()
        .map_or("out".into(), |n| n.to_string_lossy());
    sweep_stale(path, &name);
    let tmp = path.with_file_name(format!(".{name}.{}.tmp", std::process::id()));
    let written = std::fs::File::create(&tmp).and_then(|mut f| {
        f.write_all(bytes)?;
        f.sync_all()?;
        super::keep_mode(path, &tmp)
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

    #[test]
    fn an_output_to_a_device_is_written_in_place() {
        // Renaming a temporary file over /dev/null would replace the device for every program.
        write_atomic(std::path::Path::new("/dev/null"), b"gone").unwrap();
        let null = std::fs::symlink_metadata("/dev/null").unwrap();
        assert!(!null.is_file(), "/dev/null is still a device");
    }

    #[test]
    fn a_failed_write_leaves_what_was_there_and_no_temporary() {
        let dir = tempfile::tempdir().unwrap();
        let taken = dir.path().join("out.il");
        std::fs::create_dir(&taken).unwrap();
        std::fs::write(taken.join("kept"), "old").unwrap();
        // A folder under the name: the rename fails after the temporary was written.
        assert!(write_atomic(&taken, b"new").is_err());
        assert_eq!(std::fs::read_to_string(taken.join("kept")).unwrap(), "old");
        let left: Vec<_> = std::fs::read_dir(dir.path())
            .unwrap()
            .map(|e| e.unwrap().file_name())
            .collect();
        assert_eq!(left, ["out.il"], "no temporary left beside it");
    }
}
