//! Helpers shared by the end-to-end tests: running the command line in-process, and reading
//! the IL corpus.

use std::path::{Path, PathBuf};

/// What a command-line run produced.
#[derive(Debug)]
pub struct Run {
    /// Exit code.
    pub code: i32,
    /// Standard output.
    pub stdout: String,
    /// Standard error.
    pub stderr: String,
}

/// Runs `ladder-studio ARGS` in-process.
pub fn run(args: &[&str]) -> Run {
    let mut out = Vec::new();
    let mut err = Vec::new();
    let mut full = vec!["ladder-studio"];
    full.extend_from_slice(args);
    // In the C locale, whatever the machine's: the messages are English unless `--lang zh`.
    let code = ladder_cli::run_in(full, "C", &mut out, &mut err);
    Run {
        code,
        stdout: String::from_utf8(out).expect("UTF-8 output"),
        stderr: String::from_utf8(err).expect("UTF-8 output"),
    }
}

/// The folder of this crate (the workspace's `tests/`).
pub fn here() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// The `.il` files of a corpus folder, sorted.
pub fn corpus(folder: &str) -> Vec<PathBuf> {
    let dir = here().join("il").join(folder);
    let mut files: Vec<PathBuf> = std::fs::read_dir(&dir)
        .unwrap_or_else(|e| panic!("{}: {e}", dir.display()))
        .map(|e| e.expect("a directory entry").path())
        .filter(|p| p.extension().is_some_and(|x| x == "il"))
        .collect();
    files.sort();
    assert!(!files.is_empty(), "no IL files in {}", dir.display());
    files
}

/// Reads a file to a string.
pub fn read(path: &Path) -> String {
    std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
}

/// The `.script` files of a folder, sorted.
pub fn scripts(dir: &Path) -> Vec<PathBuf> {
    let mut scripts: Vec<PathBuf> = std::fs::read_dir(dir)
        .unwrap_or_else(|e| panic!("{}: {e}", dir.display()))
        .map(|e| e.expect("a directory entry").path())
        .filter(|p| p.extension().is_some_and(|x| x == "script"))
        .collect();
    scripts.sort();
    scripts
}

/// Runs `sim PROGRAM --script SCRIPT EXTRA…` for each script, the program chosen per script.
/// Returns the failures (script, output) and the number of expectations that passed.
pub fn run_scripts(
    scripts: &[PathBuf],
    program: impl Fn(&Path) -> PathBuf,
    extra: &[&str],
) -> (Vec<String>, usize) {
    let mut failures = Vec::new();
    let mut expects = 0;
    for script in scripts {
        let target = program(script);
        let mut args = vec![
            "sim",
            target.to_str().expect("UTF-8 path"),
            "--script",
            script.to_str().expect("UTF-8 path"),
        ];
        args.extend_from_slice(extra);
        let r = run(&args);
        let last = r.stdout.lines().last().unwrap_or("").to_string();
        let passed: usize = last
            .split(' ')
            .next()
            .and_then(|n| n.parse().ok())
            .unwrap_or(0);
        expects += passed;
        if r.code != 0 || !last.ends_with(" passed, 0 failed") || passed == 0 {
            failures.push(format!("{}:\n{}{}", script.display(), r.stdout, r.stderr));
        }
    }
    (failures, expects)
}
