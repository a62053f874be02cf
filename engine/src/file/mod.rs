//! Project files (`.ldp`, docs/files.md, "Project files (.ldp)"): a header line with the schema
//! version and a CRC-32 of the body, then the project serialized as RON. This is the engine's
//! only I/O.

mod atomic;

pub use atomic::write_atomic;

use crate::model::{Project, StructureError};
use std::fs;
use std::io::Write;
use std::path::{Path, PathBuf};
use thiserror::Error;

/// The first word of every project file.
pub const MAGIC: &str = "LADDER-STUDIO-PROJECT";
/// The schema version this build writes.
///
/// History: v1 had one symbol list and no other tables; v2 has the symbol tables, data-setting
/// tables, message, diagnosis, permission and M-code tables and the version information; v3
/// keeps an imported network's instruction list as written ([`crate::model::Network::il`]) and
/// its checksum covers the header too; v4 adds the machine model ([`crate::devices`]); v5 the
/// saved scenarios ([`crate::scenario`]). A project is written at the lowest version that
/// holds what it has (v3 without a machine model or scenarios), so its bytes do not change.
pub const SCHEMA_VERSION: u32 = 5;

/// Why a project file could not be read or written.
#[derive(Debug, Error)]
pub enum FileError {
    /// The file system refused.
    #[error("{path}: {source}")]
    Io {
        /// The file.
        path: PathBuf,
        /// The cause.
        source: std::io::Error,
    },
    /// Not a project file at all.
    #[error(
        "not a Ladder Studio project: the first line must start with `{MAGIC} v<version> crc32=<8 hex digits>`"
    )]
    Foreign,
    /// A project file whose first word was changed.
    #[error(
        "line 1: the project file is damaged: its header `{0}` should start with `{MAGIC}`; restore it from the .bak file beside it, or open it read-only to recover what is left"
    )]
    Damaged(String),
    /// A byte-order mark before the header.
    #[error(
        "the project file starts with a byte-order mark (EF BB BF), which Ladder Studio never writes: a text editor added it; save the file as UTF-8 without BOM, or restore it from the .bak file"
    )]
    ByteOrderMark,
    /// Windows line ends.
    #[error(
        "the project file has Windows line ends (CR LF), which Ladder Studio never writes: a text tool or git converted it; {}",
        if *.intact {
            "its content is intact, convert it back (dos2unix FILE, or git config core.autocrlf false and check it out again)"
        } else {
            "and it was changed besides; restore it from the .bak file, or open it read-only to recover what is left"
        }
    )]
    LineEnds {
        /// Whether the file reads correctly with LF line ends.
        intact: bool,
    },
    /// The last byte, a newline, is missing.
    #[error(
        "the project file ends without its final newline: {}",
        if *.intact {
            "an editor removed it and nothing else changed; add a newline at the end"
        } else {
            "it was cut short; restore it from the .bak file, or open it read-only to recover what is left"
        }
    )]
    FinalNewline {
        /// Whether the file reads correctly with the newline added.
        intact: bool,
    },
    /// The header is malformed.
    #[error("line 1: malformed header `{0}`: expected `{MAGIC} v<version> crc32=<8 hex digits>`")]
    Header(String),
    /// A version this build does not know.
    #[error(
        "line 1: schema version {found} is newer than this program reads (up to {SCHEMA_VERSION}); update Ladder Studio"
    )]
    Version {
        /// The version in the file.
        found: u32,
    },
    /// The header names an older schema the body does not have.
    #[error(
        "line 1 says schema version {version}, but the body is not a version-{version} project (line {line}, column {column}: {message}): the header was changed; restore the file from its .bak, or open it read-only"
    )]
    Schema {
        /// The version the header names.
        version: u32,
        /// Line in the file.
        line: usize,
        /// Column.
        column: usize,
        /// What the parser said.
        message: String,
    },
    /// The checksum does not match: the file was changed or cut short.
    #[error(
        "checksum mismatch: the header says crc32={expected:08x} but the file's is {actual:08x}; the file was damaged or edited by hand (open it read-only to recover what is left)"
    )]
    Checksum {
        /// From the header.
        expected: u32,
        /// Of the file.
        actual: u32,
    },
    /// The body is not a valid project.
    #[error("line {line}, column {column}: {message}")]
    Body {
        /// Line in the file (the header is line 1).
        line: usize,
        /// Column.
        column: usize,
        /// What the parser said.
        message: String,
    },
    /// The file is not UTF-8 text.
    #[error("the file is not UTF-8 text (byte {0})")]
    Encoding(usize),
    /// The body parses but the ladder breaks the model's invariants.
    #[error("the ladder is malformed: {0}")]
    Structure(StructureError),
}

/// Refuses a project whose ladder breaks the invariants the editor and compiler rely on.
fn checked(p: Project) -> Result<Project, FileError> {
    p.ladder.check_structure().map_err(FileError::Structure)?;
    Ok(p)
}

/// The "ladder checksum" of the version-information dialog (§3.4.7): the CRC-32 the header
/// of the saved file records.
pub fn ladder_checksum(saved: &[u8]) -> Option<u32> {
    let header = saved.split(|b| *b == b'\n').next()?;
    let header = std::str::from_utf8(header).ok()?;
    let hex = header.rsplit_once("crc32=")?.1;
    u32::from_str_radix(hex, 16).ok()
}

const BOM: &[u8] = b"\xEF\xBB\xBF";

/// Whether `text` is (or was, before some damage) a project file rather than an instruction
/// list: it starts with the header word give or take a few changed bytes, or a byte-order
/// mark, or its first line names a `crc32=`. No instruction list begins like that, so a
/// damaged project is reported as damaged, never read as IL.
pub fn is_project_text(text: &[u8]) -> bool {
    let text = text.strip_prefix(BOM).unwrap_or(text);
    let magic = MAGIC.as_bytes();
    let first_line = text.split(|b| *b == b'\n').next().unwrap_or(&[]);
    let changed = text
        .iter()
        .take(magic.len())
        .zip(magic)
        .filter(|(a, b)| a != b)
        .count()
        + magic.len().saturating_sub(text.len());
    changed <= 3 || first_line.windows(6).any(|w| w == b"crc32=")
}

/// The checksum the header records: of the body alone up to v2; from v3 of every byte of the
/// file except the eight hex digits themselves, so that no byte deciding how the file is read
/// (the version included) can change unnoticed.
fn checksum(version: u32, body: &str) -> u32 {
    if version < 3 {
        return crc32fast::hash(body.as_bytes());
    }
    let mut h = crc32fast::Hasher::new();
    h.update(format!("{MAGIC} v{version} crc32=\n").as_bytes());
    h.update(body.as_bytes());
    h.update(b"\n");
    h.finalize()
}

/// Serializes a project to the file format.
pub fn to_string(project: &Project) -> String {
    // Rows are deep enough in the tree to be written on one line each.
    let config = ron::ser::PrettyConfig::new()
        .indentor(" ".to_string())
        .depth_limit(7);
    let body = ron::ser::to_string_pretty(project, config)
        .expect("a project always serializes: it holds only plain data");
    let version = if !project.scenarios.is_empty() {
        5
    } else if !project.machine.is_empty() {
        4
    } else {
        3
    };
    let crc = checksum(version, &body);
    format!("{MAGIC} v{version} crc32={crc:08x}\n{body}\n")
}

/// Parses the file format, verifying header and checksum.
pub fn from_bytes(bytes: &[u8]) -> Result<Project, FileError> {
    if bytes.starts_with(BOM) && is_project_text(bytes) {
        return Err(FileError::ByteOrderMark);
    }
    if !bytes.starts_with(MAGIC.as_bytes()) {
        if !is_project_text(bytes) {
            return Err(FileError::Foreign);
        }
        let first = bytes.split(|b| *b == b'\n').next().unwrap_or(&[]);
        return Err(FileError::Damaged(
            String::from_utf8_lossy(first).chars().take(80).collect(),
        ));
    }
    let text = std::str::from_utf8(bytes).map_err(|e| FileError::Encoding(e.valid_up_to()))?;
    let (header, body) = text
        .split_once('\n')
        .ok_or_else(|| FileError::Header(text.chars().take(80).collect()))?;
    if header.ends_with('\r') {
        let lf = text.replace("\r\n", "\n");
        return Err(FileError::LineEnds {
            intact: from_bytes(lf.as_bytes()).is_ok(),
        });
    }
    let mut parts = header.split(' ');
    let (Some(MAGIC), Some(version), Some(crc), None) =
        (parts.next(), parts.next(), parts.next(), parts.next())
    else {
        return Err(FileError::Header(header.chars().take(80).collect()));
    };
    let version: u32 = version
        .strip_prefix('v')
        .and_then(|v| v.parse().ok())
        .ok_or_else(|| FileError::Header(header.into()))?;
    let expected = crc
        .strip_prefix("crc32=")
        .filter(|h| h.len() == 8)
        .and_then(|h| u32::from_str_radix(h, 16).ok())
        .ok_or_else(|| FileError::Header(header.into()))?;
    // Only the exact spelling this program writes is accepted, so that no byte of the header
    // can change without the file being refused (`v01`, `CRC32=`, upper-case hex).
    if header != format!("{MAGIC} v{version} crc32={expected:08x}") {
        return Err(FileError::Header(header.chars().take(80).collect()));
    }
    if version > SCHEMA_VERSION || version == 0 {
        return Err(FileError::Version { found: version });
    }
    let Some(body) = body.strip_suffix('\n') else {
        return Err(FileError::FinalNewline {
            intact: checksum(version, body) == expected,
        });
    };
    let actual = checksum(version, body);
    if actual != expected {
        if body.contains("\r\n") && checksum(version, &body.replace("\r\n", "\n")) == expected {
            return Err(FileError::LineEnds { intact: true });
        }
        return Err(FileError::Checksum { expected, actual });
    }
    parse_versioned(body, version)
}

fn body_error(e: ron::error::SpannedError) -> FileError {
    // The body starts on line 2 of the file.
    FileError::Body {
        line: e.span.start.line + 1,
        column: e.span.start.col,
        message: e.code.to_string(),
    }
}

/// Parses a body of a given schema version, migrating older ones. A body that does not read
/// as the older version it claims is refused rather than half read: a changed version digit
/// must not drop the tables.
fn parse_versioned(body: &str, version: u32) -> Result<Project, FileError> {
    // A field the version does not have, or lacks one it must have: another schema's body.
    let as_schema = |e: ron::error::SpannedError| match (&e.code, body_error(e.clone())) {
        (
            ron::Error::NoSuchStructField { .. } | ron::Error::MissingStructField { .. },
            FileError::Body {
                line,
                column,
                message,
            },
        ) if version < SCHEMA_VERSION => FileError::Schema {
            version,
            line,
            column,
            message,
        },
        (_, other) => other,
    };
    let p = match version {
        1 => ron::from_str::<v1::Project>(body)
            .map(v1::migrate)
            .map_err(as_schema)?,
        2 => {
            let p = ron::from_str::<Project>(body).map_err(as_schema)?;
            // v2 knew no kept instruction lists.
            if p.ladder
                .blocks
                .iter()
                .flat_map(|b| &b.networks)
                .any(|n| !n.il.is_empty())
            {
                return Err(FileError::Schema {
                    version,
                    line: 1,
                    column: 1,
                    message:
                        "a network keeps an instruction list (`il`), which version 3 introduced"
                            .into(),
                });
            }
            p
        }
        _ => ron::from_str::<Project>(body).map_err(body_error)?,
    };
    // Before version 4 there was no machine model.
    if version < 4 && !p.machine.is_empty() {
        return Err(FileError::Schema {
            version,
            line: 1,
            column: 1,
            message: "the project has a machine model (`machine`), which version 4 introduced"
                .into(),
        });
    }
    // Before version 5 there were no scenarios.
    if version < 5 && !p.scenarios.is_empty() {
        return Err(FileError::Schema {
            version,
            line: 1,
            column: 1,
            message: "the project has saved scenarios (`scenarios`), which version 5 introduced"
                .into(),
        });
    }
    checked(p)
}

/// Parses a body without checking a checksum (the read-only recovery open).
pub fn parse_body(body: &str) -> Result<Project, FileError> {
    checked(ron::from_str::<Project>(body).map_err(body_error)?)
}

/// Opens a damaged file as far as it can be read, for a read-only look: the checksum is not
/// verified, and the body is read as the version its header names, else as any version that
/// reads it. The caller must not save over the original with it.
pub fn recover(bytes: &[u8]) -> Result<Project, FileError> {
    if !is_project_text(bytes) {
        return Err(FileError::Foreign);
    }
    let bytes = bytes.strip_prefix(BOM).unwrap_or(bytes);
    let text = String::from_utf8_lossy(bytes).replace("\r\n", "\n");
    let (header, body) = text.split_once('\n').unwrap_or((&text, ""));
    let version = header
        .split(' ')
        .nth(1)
        .and_then(|v| v.strip_prefix('v'))
        .and_then(|v| v.parse().ok())
        .unwrap_or(SCHEMA_VERSION)
        .clamp(1, SCHEMA_VERSION);
    let body = body.strip_suffix('\n').unwrap_or(body);
    parse_versioned(body, version).or_else(|e| {
        (1..=SCHEMA_VERSION)
            .rev()
            .find_map(|v| parse_versioned(body, v).ok())
            .ok_or(e)
    })
}

/// Schema version 1 and its migration.
mod v1 {
    use crate::address::Address;
    use crate::model::{Comments, Ladder, SymbolTable, tables};
    use crate::profile::ProfileId;
    use serde::Deserialize;

    #[derive(Deserialize)]
    #[serde(deny_unknown_fields)]
    pub struct Symbol {
        name: String,
        address: Address,
        #[serde(default)]
        comment: String,
    }

    #[derive(Deserialize)]
    #[serde(deny_unknown_fields)]
    pub struct Project {
        profile: ProfileId,
        level2_division: u32,
        ladder: Ladder,
        #[serde(default)]
        symbols: Vec<Symbol>,
    }

    /// v1 → v2: the one symbol list becomes the first symbol table, its comments Chinese.
    pub fn migrate(old: Project) -> crate::model::Project {
        let rows = old
            .symbols
            .into_iter()
            .map(|s| tables::Symbol {
                name: s.name,
                address: s.address,
                comments: if s.comment.is_empty() {
                    Comments::new()
                } else {
                    Comments::from([("zh".to_string(), s.comment)])
                },
            })
            .collect();
        let mut p = crate::model::Project {
            profile: old.profile,
            level2_division: old.level2_division,
            ladder: old.ladder,
            ..Default::default()
        };
        p.symbol_tables = vec![SymbolTable {
            name: "符号表1".into(),
            rows,
        }];
        p
    }
}

/// The largest input file read whole (a project, an instruction list, a script, a comments
/// CSV, a coverage report): 64 MiB, far past any real one, so that a wrong path (a device,
/// a disk image) is refused before it fills the memory.
pub const INPUT_MAX: u64 = 64 << 20;

/// The reason [`read_limited`] gives a file past its limit: the engine's own words inside an
/// I/O error, typed so that each language can say them (the system's reasons stay as said).
#[derive(Clone, Copy, Debug, PartialEq, Eq, thiserror::Error)]
#[error("the file is larger than {mib} MiB, the most Ladder Studio reads")]
pub struct TooLarge {
    /// The limit, in MiB.
    pub mib: u64,
}

/// Reads a whole input file of at most `limit` bytes. A larger one, and a device that never
/// ends (`/dev/zero`), is refused with [`std::io::ErrorKind::FileTooLarge`] once `limit + 1`
/// bytes were seen (a regular file's size is checked before anything is read).
pub fn read_limited(path: &Path, limit: u64) -> std::io::Result<Vec<u8>> {
    use std::io::Read;
    let too_large = || {
        std::io::Error::new(
            std::io::ErrorKind::FileTooLarge,
            TooLarge { mib: limit >> 20 },
        )
    };
    let file = fs::File::open(path)?;
    if file
        .metadata()
        .is_ok_and(|m| m.is_file() && m.len() > limit)
    {
        return Err(too_large());
    }
    let mut bytes = Vec::new();
    file.take(limit + 1).read_to_end(&mut bytes)?;
    if bytes.len() as u64 > limit {
        return Err(too_large());
    }
    Ok(bytes)
}

/// Reads a whole input file of at most [`INPUT_MAX`] bytes ([`read_limited`]).
pub fn read_input(path: &Path) -> std::io::Result<Vec<u8>> {
    read_limited(path, INPUT_MAX)
}

/// [`read_input`] as UTF-8 text (`InvalidData` otherwise, as `fs::read_to_string` says it).
pub fn read_input_text(path: &Path) -> std::io::Result<String> {
    String::from_utf8(read_input(path)?).map_err(|_| {
        std::io::Error::new(
            std::io::ErrorKind::InvalidData,
            "stream did not contain valid UTF-8",
        )
    })
}

/// Reads and verifies a project file.
pub fn load(path: &Path) -> Result<Project, FileError> {
    let bytes = read_input(path).map_err(|source| FileError::Io {
        path: path.to_path_buf(),
        source,
    })?;
    from_bytes(&bytes)
}

/// Where a save can be interrupted, for the crash tests.
#[doc(hidden)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Interrupt {
    /// Run to the end.
    Never,
    /// Stop after writing half of the temporary file.
    MidWrite,
    /// Stop after the temporary file is complete, before the backup and the rename.
    BeforeRename,
    /// Stop halfway through writing the new backup.
    MidBackup,
}

/// The file a write to `path` must replace: `path` itself, or, where `path` is a symbolic
/// link (a chain of them), the file it leads to, so that the link stays a link and the file
/// it names changes. Every writer of the project writes through this (and [`keep_mode`]).
pub fn write_target(path: &Path) -> std::path::PathBuf {
    let mut target = path.to_path_buf();
    // A loop of links ends here too: the write then fails at the link, as the system says.
    for _ in 0..40 {
        let Ok(link) = fs::read_link(&target) else {
            break;
        };
        target = match target.parent() {
            Some(dir) if link.is_relative() => dir.join(link),
            _ => link,
        };
    }
    target
}

/// Gives `new` (a temporary file about to replace `old`) the permissions of `old`, where
/// `old` exists: a project kept at 0640 stays 0640 after a save, its backup too.
pub fn keep_mode(old: &Path, new: &Path) -> std::io::Result<()> {
    match fs::metadata(old) {
        Ok(m) => fs::set_permissions(new, m.permissions()),
        Err(_) => Ok(()),
    }
}

/// Saves atomically: writes a temporary file in the same folder, flushes it to disk, keeps the
/// previous file as `NAME.ldp.bak` (itself written to a temporary file and renamed, so a crash
/// never leaves a truncated backup in place of the last good one), then renames the new one
/// over the old. A crash at any point leaves the old file or the new one, never a mix.
/// Temporary files that a killed save left beside the project are removed.
pub fn save(project: &Project, path: &Path) -> Result<(), FileError> {
    save_interruptible(project, path, Interrupt::Never)
}

/// [`save`], stopping where `interrupt` says as if the process had been killed there.
#[doc(hidden)]
pub fn save_interruptible(
    project: &Project,
    path: &Path,
    interrupt: Interrupt,
) -> Result<(), FileError> {
    let io = |source| FileError::Io {
        path: path.to_path_buf(),
        source,
    };
    // Every file this program writes opens again: a structurally invalid project is refused
    // here, before anything on disk changes.
    project
        .ladder
        .check_structure()
        .map_err(FileError::Structure)?;
    let text = to_string(project);
    let target = write_target(path);
    let path = target.as_path();
    let dir = path
        .parent()
        .filter(|p| !p.as_os_str().is_empty())
        .unwrap_or(Path::new("."));
    let name = path
        .file_name()
        .map(|n| n.to_string_lossy().into_owned())
        .unwrap_or_else(|| "project.ldp".into());
    let tmp = dir.join(format!(".{name}.{}.tmp", std::process::id()));
    let bak_tmp = dir.join(format!(".{name}.bak.{}.tmp", std::process::id()));
    remove_stale_temporaries(dir, &name);
    let result = (|| {
        let mut f = fs::File::create(&tmp)?;
        if interrupt == Interrupt::MidWrite {
            f.write_all(&text.as_bytes()[..text.len() / 2])?;
            return Err(std::io::Error::other("interrupted"));
        }
        f.write_all(text.as_bytes())?;
        f.sync_all()?;
        keep_mode(path, &tmp)?;
        if interrupt == Interrupt::BeforeRename {
            return Err(std::io::Error::other("interrupted"));
        }
        if path.exists() {
            let old = fs::read(path)?;
            let mut b = fs::File::create(&bak_tmp)?;
            if interrupt == Interrupt::MidBackup {
                b.write_all(&old[..old.len() / 2])?;
                return Err(std::io::Error::other("interrupted"));
            }
            b.write_all(&old)?;
            b.sync_all()?;
            keep_mode(path, &bak_tmp)?;
            fs::rename(&bak_tmp, dir.join(format!("{name}.bak")))?;
        }
        fs::rename(&tmp, path)
    })();
    // A real crash leaves the temporary files behind; the simulated one does too.
    if result.is_err() && interrupt == Interrupt::Never {
        let _ = fs::remove_file(&tmp);
        let _ = fs::remove_file(&bak_tmp);
    }
    result.map_err(io)
}

/// Removes the temporary files of `name` (`.NAME.<pid>.tmp`, `.NAME.bak.<pid>.tmp`) that no
/// running save owns: their process is gone (Linux), or they are over an hour old (where the
/// process cannot be asked). Another save of the same file that is running keeps its own.
fn remove_stale_temporaries(dir: &Path, name: &str) {
    let Ok(entries) = fs::read_dir(dir) else {
        return;
    };
    let own = std::process::id();
    let proc_fs = Path::new("/proc/self").exists();
    for entry in entries.flatten() {
        let file = entry.file_name();
        let Some(file) = file.to_str() else { continue };
        let Some(rest) = file.strip_prefix('.').and_then(|f| f.strip_prefix(name)) else {
            continue;
        };
        let rest = rest.strip_prefix(".bak").unwrap_or(rest);
        let Some(pid) = rest
            .strip_prefix('.')
            .and_then(|r| r.strip_suffix(".tmp"))
            .and_then(|p| p.parse::<u32>().ok())
        else {
            continue;
        };
        let stale = if pid == own {
            false
        } else if proc_fs {
            !Path::new("/proc").join(pid.to_string()).exists()
        } else {
            entry
                .metadata()
                .and_then(|m| m.modified())
                .ok()
                .and_then(|t| t.elapsed().ok())
                .is_some_and(|age| age.as_secs() > 3600)
        };
        if stale {
            let _ = fs::remove_file(entry.path());
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_saved_project_reads_back_and_a_changed_byte_is_refused() {
        let p = crate::il::import("LD X1.0\nOUT Y1.0\n").project.unwrap();
        let text = to_string(&p);
        assert_eq!(from_bytes(text.as_bytes()).unwrap(), p);
        let mut bytes = text.clone().into_bytes();
        let pos = text.find("Y").unwrap();
        bytes[pos] = b'G';
        assert!(matches!(
            from_bytes(&bytes),
            Err(FileError::Checksum { .. })
        ));
        assert!(matches!(from_bytes(b"LD X1.0\n"), Err(FileError::Foreign)));
        let future = text.replacen(" v3 ", " v9 ", 1);
        assert!(matches!(
            from_bytes(future.as_bytes()),
            Err(FileError::Version { found: 9 })
        ));
        let cut = &text[..text.len() / 2];
        assert!(matches!(
            from_bytes(cut.as_bytes()),
            Err(FileError::FinalNewline { intact: false })
        ));
        let cut = &text[..text.len() - 1];
        assert!(matches!(
            from_bytes(cut.as_bytes()),
            Err(FileError::FinalNewline { intact: true })
        ));
    }

    #[test]
    fn a_checksummed_file_with_a_malformed_ladder_is_refused_with_the_reason() {
        let mut p = crate::il::import("LD X1.0\nOUT Y1.0\n").project.unwrap();
        p.ladder.blocks[0].networks[0].rows[0].cells.pop();
        let err = from_bytes(to_string(&p).as_bytes()).unwrap_err();
        let FileError::Structure(StructureError::Network { at, error }) = &err else {
            panic!("{err}");
        };
        assert_eq!((at.block.label().as_str(), at.network), ("LEVEL1", 1));
        // A saved row keeps its links as junction numbers, so it reads back with a junction
        // per cell: both are one short.
        assert_eq!(
            *error,
            crate::model::WidthError::Row {
                row: 1,
                cells: 10,
                junctions: 10,
                expected: 11
            }
        );
        assert!(
            err.to_string()
                .contains("LEVEL1 network 1: row 1 has 10 cells and 10 junctions, not 11"),
            "{err}"
        );
        let mut p = Project::default();
        p.ladder.blocks.swap(0, 1);
        assert!(matches!(
            from_bytes(to_string(&p).as_bytes()),
            Err(FileError::Structure(StructureError::LevelsFirst))
        ));
        let mut p = Project::default();
        p.ladder.width = 0;
        assert!(matches!(
            from_bytes(to_string(&p).as_bytes()),
            Err(FileError::Structure(StructureError::Width(0)))
        ));
    }
}
