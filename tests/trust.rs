//! What engineers trust the tool with: an instruction list runs and comes back as written, and
//! no changed byte of a project file is ever read as something else (docs/files.md).

use ladder_engine::generate::SplitMix64;
use ladder_tests::{read, run};
use std::path::Path;

const SLICED: &str = "LEVEL2
NETWORK
LD X0000.0
MPS
OUT R0000.0
MPP
OUT R0000.1
NETWORK
LD X0000.0
OUT R0000.2
NETWORK
LD X0000.0
OUT R0000.3
";

fn write(dir: &Path, name: &str, text: &[u8]) -> String {
    let path = dir.join(name);
    std::fs::write(&path, text).unwrap();
    path.display().to_string()
}

#[test]
fn a_list_runs_with_its_own_steps_from_the_list_and_from_its_project() {
    let dir = tempfile::tempdir().unwrap();
    let il = write(dir.path(), "a.il", SLICED.as_bytes());
    // Five steps in the first network: with division 2 the first slice ends after it.
    let script = write(
        dir.path(),
        "a.script",
        b"division 2\nset X0000.0 1\nscan 1\nexpect R0000 3\nscan 1\nexpect R0000 15\n",
    );
    let r = run(&["sim", &il, "--script", &script]);
    assert_eq!(r.code, 0, "{r:?}");
    assert!(r.stdout.ends_with("2 passed, 0 failed\n"), "{}", r.stdout);

    let ldp = dir.path().join("a.ldp").display().to_string();
    assert_eq!(run(&["import-il", &il, "-o", &ldp]).code, 0);
    let r = run(&["sim", &ldp, "--script", &script]);
    assert_eq!(r.code, 0, "{r:?}");
    let r = run(&["export-il", &ldp]);
    let lines = |t: &str| {
        t.lines()
            .filter(|l| !matches!(*l, "LEVEL1" | "END"))
            .map(|l| l.split_whitespace().collect::<Vec<_>>().join(" "))
            .collect::<Vec<_>>()
    };
    assert_eq!(lines(&r.stdout), lines(SLICED));
    let r = run(&["check", &il]);
    assert!(r.stdout.contains("0 errors"), "{}", r.stdout);
}

#[test]
fn a_list_with_a_subprogram_defined_twice_writes_no_project() {
    let dir = tempfile::tempdir().unwrap();
    let il = write(
        dir.path(),
        "twice.il",
        b"LEVEL2\nNETWORK\nLD X0000.0\nCALL P0001\nSUB P0001\nNETWORK\nLD X0000.1\nOUT R0000.0\nSUB P0001\nNETWORK\nLD X0000.2\nOUT R0000.1\n",
    );
    let ldp = dir.path().join("twice.ldp");
    let r = run(&["import-il", &il, "-o", ldp.to_str().unwrap()]);
    assert_eq!(r.code, 1, "{r:?}");
    assert!(
        r.stderr
            .contains(":9: error: subprogram P0001 is defined twice"),
        "{}",
        r.stderr
    );
    assert!(r.stderr.contains("no project written"), "{}", r.stderr);
    assert!(!ldp.exists());
}

/// A small project as the tool writes it.
fn small_project(dir: &Path) -> Vec<u8> {
    let il = write(dir, "s.il", SLICED.as_bytes());
    let ldp = dir.join("s.ldp");
    assert_eq!(
        run(&["import-il", &il, "-o", ldp.to_str().unwrap()]).code,
        0
    );
    std::fs::read(&ldp).unwrap()
}

#[test]
fn a_damaged_header_is_a_damaged_project_not_an_instruction_list() {
    let dir = tempfile::tempdir().unwrap();
    let text = small_project(dir.path());
    let mut damaged = text.clone();
    damaged[3] = b'X';
    let path = write(dir.path(), "d.ldp", &damaged);
    let r = run(&["check", &path]);
    assert_eq!(r.code, 2, "{r:?}");
    assert!(
        r.stderr.contains("the project file is damaged"),
        "{}",
        r.stderr
    );
    assert!(!r.stdout.contains("unknown instruction"), "{}", r.stdout);

    let bom = [b"\xEF\xBB\xBF".as_slice(), &text].concat();
    let r = run(&["check", &write(dir.path(), "b.ldp", &bom)]);
    assert_eq!(r.code, 2, "{r:?}");
    assert!(r.stderr.contains("byte-order mark"), "{}", r.stderr);

    let crlf = String::from_utf8(text.clone())
        .unwrap()
        .replace('\n', "\r\n");
    let r = run(&["check", &write(dir.path(), "c.ldp", crlf.as_bytes())]);
    assert_eq!(r.code, 2, "{r:?}");
    assert!(r.stderr.contains("Windows line ends"), "{}", r.stderr);

    let r = run(&[
        "check",
        &write(dir.path(), "n.ldp", &text[..text.len() - 1]),
    ]);
    assert_eq!(r.code, 2, "{r:?}");
    assert!(
        r.stderr.contains("without its final newline"),
        "{}",
        r.stderr
    );
}

#[test]
fn every_changed_byte_of_a_small_project_is_refused_with_exit_2() {
    let dir = tempfile::tempdir().unwrap();
    let text = small_project(dir.path());
    assert_eq!(run(&["check", &write(dir.path(), "ok.ldp", &text)]).code, 0);
    let mut rng = SplitMix64::new(0x1d5);
    let path = dir.path().join("f.ldp");
    let path_text = path.display().to_string();
    for pos in 0..text.len() {
        let mut damaged = text.clone();
        damaged[pos] = (u64::from(text[pos]) + 1 + rng.below(255)) as u8;
        std::fs::write(&path, &damaged).unwrap();
        let r = run(&["check", &path_text]);
        assert_eq!(
            r.code, 2,
            "byte {pos}: {:?} → {:?} gave {r:?}",
            text[pos] as char, damaged[pos] as char
        );
        assert!(r.stderr.contains("cannot be opened"), "byte {pos}: {r:?}");
    }
    assert!(text.len() > 300, "{} bytes", text.len());
    // The header bytes were among them.
    assert!(read(&dir.path().join("s.ldp")).starts_with("LADDER-STUDIO-PROJECT v3 "));
}
