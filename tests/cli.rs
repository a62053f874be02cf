//! The command line as users and scripts see it: output formats, exit codes, files.

use ladder_tests::{here, read, run};

fn il_path(name: &str) -> String {
    here().join("il").join(name).display().to_string()
}

#[test]
fn check_reports_lines_and_a_summary_and_exits_1_on_errors() {
    let path = il_path("invalid/stacks.il");
    let r = run(&["check", &path]);
    assert_eq!(r.code, 1, "{r:?}");
    let lines: Vec<&str> = r.stdout.lines().collect();
    assert_eq!(*lines.last().unwrap(), "9 errors, 0 warnings");
    assert!(
        lines[0].starts_with(&format!("{path}:4: error: ORB has no open block")),
        "{}",
        lines[0]
    );
}

#[test]
fn check_of_a_clean_program_exits_0() {
    let r = run(&["check", &il_path("valid/functions.il")]);
    assert_eq!((r.code, r.stdout.as_str()), (0, "0 errors, 0 warnings\n"));
}

#[test]
fn project_diagnostics_name_block_network_row_and_column() {
    let dir = tempfile::tempdir().unwrap();
    let il = dir.path().join("p.il");
    std::fs::write(
        &il,
        "LEVEL2\nNETWORK\nLD X1.0\nOUT Y1.0\nNETWORK\nLD X1.1\nAND UNDEFINED\nOUT Y1.1\n",
    )
    .unwrap();
    let ldp = dir.path().join("p.ldp");
    let r = run(&[
        "import-il",
        il.to_str().unwrap(),
        "-o",
        ldp.to_str().unwrap(),
    ]);
    assert_eq!(r.code, 1, "imported with an error to fix: {r:?}");
    let r = run(&["check", ldp.to_str().unwrap()]);
    assert_eq!(r.code, 1);
    let first = r.stdout.lines().next().unwrap();
    assert_eq!(
        first,
        format!(
            "{}:LEVEL2:2:1:2: error: undefined symbol `UNDEFINED`: define it in the symbol table or write the address [L020]",
            ldp.display()
        )
    );
}

#[test]
fn import_then_export_gives_the_list_back() {
    let dir = tempfile::tempdir().unwrap();
    let source = il_path("valid/branches.il");
    let ldp = dir.path().join("b.ldp");
    let r = run(&["import-il", &source, "-o", ldp.to_str().unwrap()]);
    assert_eq!(r.code, 0, "{r:?}");
    let out = dir.path().join("b.il");
    let r = run(&[
        "export-il",
        ldp.to_str().unwrap(),
        "-o",
        out.to_str().unwrap(),
    ]);
    assert_eq!(r.code, 0, "{r:?}");
    assert_eq!(read(&out), read(std::path::Path::new(&source)));
    let r = run(&["export-il", ldp.to_str().unwrap()]);
    assert_eq!(r.stdout, read(std::path::Path::new(&source)));
}

#[test]
fn a_damaged_project_is_refused_with_exit_2() {
    let dir = tempfile::tempdir().unwrap();
    let ldp = dir.path().join("s.ldp");
    let r = run(&[
        "import-il",
        &il_path("valid/self-holding.il"),
        "-o",
        ldp.to_str().unwrap(),
    ]);
    assert_eq!(r.code, 0, "{r:?}");
    let text = read(&ldp).replace("X0002.1", "X0002.2");
    std::fs::write(&ldp, text).unwrap();
    let r = run(&["check", ldp.to_str().unwrap()]);
    assert_eq!(r.code, 2);
    assert!(r.stderr.contains("checksum mismatch"), "{}", r.stderr);
}

#[test]
fn unusable_input_exits_2_with_a_message() {
    let r = run(&["check", "/nonexistent/x.il"]);
    assert_eq!(r.code, 2);
    assert!(
        r.stderr.contains("cannot read /nonexistent/x.il"),
        "{}",
        r.stderr
    );
    let r = run(&["frobnicate"]);
    assert_eq!(r.code, 2);
    let r = run(&["--help"]);
    assert_eq!(r.code, 0);
    for sub in ["check", "export-il", "import-il"] {
        assert!(r.stdout.contains(sub), "{sub} missing from --help");
    }
    let dir = tempfile::tempdir().unwrap();
    let bin = dir.path().join("x.il");
    std::fs::write(&bin, [0xff, 0xfe, 0x00]).unwrap();
    let r = run(&["check", bin.to_str().unwrap()]);
    assert_eq!(r.code, 2, "{r:?}");
}

#[test]
fn undrawable_il_is_not_imported() {
    let dir = tempfile::tempdir().unwrap();
    let ldp = dir.path().join("x.ldp");
    let r = run(&[
        "import-il",
        &il_path("invalid/stacks.il"),
        "-o",
        ldp.to_str().unwrap(),
    ]);
    assert_eq!(r.code, 1);
    assert!(!ldp.exists());
    assert!(r.stderr.contains("no project written"), "{}", r.stderr);
}

#[test]
fn the_sample_project_is_clean() {
    let sample = here().join("../projects/start-stop.ldp");
    let r = run(&["check", sample.to_str().unwrap()]);
    assert_eq!(
        (r.code, r.stdout.as_str()),
        (0, "0 errors, 0 warnings\n"),
        "{r:?}"
    );
    let r = run(&["export-il", sample.to_str().unwrap()]);
    assert_eq!(
        r.stdout,
        read(&here().join("../projects/start-stop.il"))
            .lines()
            .skip(1)
            .map(|l| format!("{l}\n"))
            .collect::<String>()
    );
}
