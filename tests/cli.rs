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

#[cfg(unix)]
#[test]
fn an_output_through_a_link_is_written_to_the_file_it_names_with_its_mode() {
    use std::os::unix::fs::{PermissionsExt, symlink};
    let dir = tempfile::tempdir().unwrap();
    let real = dir.path().join("plc.il");
    std::fs::write(&real, "old").unwrap();
    std::fs::set_permissions(&real, std::fs::Permissions::from_mode(0o640)).unwrap();
    let link = dir.path().join("latest.il");
    symlink(&real, &link).unwrap();
    let source = il_path("valid/branches.il");
    let r = run(&["export-il", &source, "-o", link.to_str().unwrap()]);
    assert_eq!(r.code, 0, "{r:?}");
    assert!(link.symlink_metadata().unwrap().file_type().is_symlink());
    assert_eq!(read(&real), read(std::path::Path::new(&source)));
    let mode = real.metadata().unwrap().permissions().mode() & 0o777;
    assert_eq!(mode, 0o640, "the file keeps its permissions");
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
    assert!(
        r.stderr
            .contains("no project file or subcommand `frobnicate`"),
        "{}",
        r.stderr
    );
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

#[test]
fn sim_counts_expectations_and_names_failing_lines() {
    let dir = tempfile::tempdir().unwrap();
    let script = dir.path().join("s.script");
    std::fs::write(
        &script,
        "set X2.1 1\nscan\nexpect Y3.7 1\nexpect Y3.7 0   # wrong on purpose\nwatch Y3.7\nset X2.1 0\nset X2.2 1\nscan 2\nexpect Y3.7 0\nprint Y3\n",
    )
    .unwrap();
    let trace = dir.path().join("t.csv");
    let il = il_path("valid/self-holding.il");
    let r = run(&[
        "sim",
        &il,
        "--script",
        script.to_str().unwrap(),
        "--trace",
        trace.to_str().unwrap(),
    ]);
    assert_eq!(r.code, 1, "{r:?}");
    let lines: Vec<&str> = r.stdout.lines().collect();
    assert_eq!(
        lines[0],
        format!("{}:4: expect Y0003.7 = 0, got 1", script.display())
    );
    assert_eq!(lines[1], "Y0003 = 0");
    assert_eq!(*lines.last().unwrap(), "2 passed, 1 failed");
    assert_eq!(read(&trace), "tick,ms,Y0003.7\n2,16,0\n3,24,0\n");
    // In Chinese the line keeps its words, so a tool reads it, and says what it means.
    let r = run(&[
        "sim",
        &il,
        "--script",
        script.to_str().unwrap(),
        "--lang",
        "zh",
    ]);
    let lines: Vec<&str> = r.stdout.lines().collect();
    assert_eq!(
        lines[0],
        format!(
            "{}:4: expect Y0003.7 = 0, got 1（实际值与期望值不符）",
            script.display()
        )
    );
    assert_eq!(*lines.last().unwrap(), "2 项通过，1 项失败");
}

#[test]
fn a_script_error_stops_before_running_with_exit_2() {
    let dir = tempfile::tempdir().unwrap();
    let script = dir.path().join("s.script");
    std::fs::write(&script, "scan\n\nset R0000 256\n").unwrap();
    let r = run(&[
        "sim",
        &il_path("valid/self-holding.il"),
        "--script",
        script.to_str().unwrap(),
    ]);
    assert_eq!(r.code, 2);
    assert!(r.stdout.is_empty());
    assert!(
        r.stderr
            .starts_with(&format!("{}:3: 256 does not fit R0000", script.display())),
        "{}",
        r.stderr
    );
}

#[test]
fn sim_of_a_program_with_errors_exits_1() {
    let dir = tempfile::tempdir().unwrap();
    let script = dir.path().join("s.script");
    std::fs::write(&script, "scan\n").unwrap();
    let r = run(&[
        "sim",
        &il_path("invalid/operands.il"),
        "--script",
        script.to_str().unwrap(),
    ]);
    assert_eq!(r.code, 1);
    assert!(r.stderr.contains("the program cannot run"), "{}", r.stderr);
}

#[test]
fn the_watchdog_names_the_loop_in_sim() {
    let dir = tempfile::tempdir().unwrap();
    let il = dir.path().join("loop.il");
    std::fs::write(
        &il,
        "LEVEL2\nNETWORK\nLBL L0001\nNETWORK\nLD X0000.0\nJMPB L0001\n",
    )
    .unwrap();
    let script = dir.path().join("s.script");
    std::fs::write(&script, "set X0.0 1\nscan 5\nexpect X0.0 1\n").unwrap();
    let r = run(&[
        "sim",
        il.to_str().unwrap(),
        "--script",
        script.to_str().unwrap(),
    ]);
    assert_eq!(r.code, 0, "{r:?}");
    assert!(
        r.stdout
            .contains("PLC halted at LEVEL2 network 2: a JMPB loop ran past 200000 steps"),
        "{}",
        r.stdout
    );
}

#[test]
fn bench_prints_its_figures_last() {
    let r = run(&["bench", &il_path("valid/functions.il"), "--scans", "50"]);
    assert_eq!(r.code, 0, "{r:?}");
    let last = r.stdout.lines().last().unwrap();
    let keys: Vec<&str> = last
        .split(' ')
        .map(|kv| kv.split('=').next().unwrap())
        .collect();
    assert_eq!(
        keys,
        ["steps", "scans", "ns_per_scan", "ns_per_step", "engine"],
        "{last}"
    );
    assert!(
        last.starts_with("steps=") && last.contains(" scans=50 "),
        "{last}"
    );
}

#[test]
fn bench_takes_one_to_a_hundred_million_scans() {
    for bad in ["0", "100000001", "18446744073709551615"] {
        let r = run(&["bench", &il_path("valid/functions.il"), "--scans", bad]);
        assert_eq!(r.code, 2, "--scans {bad}: {r:?}");
        assert!(r.stderr.contains("--scans"), "{}", r.stderr);
    }
}

#[test]
fn a_script_line_longer_than_a_hundred_million_ticks_is_refused_before_anything_runs() {
    let dir = tempfile::tempdir().unwrap();
    let script = dir.path().join("long.script");
    std::fs::write(&script, "scan 1\nrun 10000000000000\n").unwrap();
    let r = run(&[
        "sim",
        &il_path("valid/functions.il"),
        "--script",
        script.to_str().unwrap(),
    ]);
    assert_eq!(r.code, 2, "{r:?}");
    assert!(
        r.stderr.contains(
            "long.script:2: `10000000000000` is longer than one line may run: at most 800000s"
        ),
        "{}",
        r.stderr
    );
}

#[test]
fn sim_streams_its_trace_and_keeps_none_without_one() {
    let dir = tempfile::tempdir().unwrap();
    let script = dir.path().join("t.script");
    std::fs::write(&script, "watch R0000\nwatch X0000\nscan 3\n").unwrap();
    let trace = dir.path().join("t.csv");
    let il = il_path("valid/functions.il");
    let r = run(&[
        "sim",
        &il,
        "--script",
        script.to_str().unwrap(),
        "--trace",
        trace.to_str().unwrap(),
    ]);
    assert_eq!(r.code, 0, "{r:?}");
    let csv = std::fs::read_to_string(&trace).unwrap();
    assert_eq!(csv.lines().count(), 4, "{csv}");
    assert!(csv.starts_with("tick,ms,R0000,X0000\n1,8,"), "{csv}");
    let missing = dir.path().join("no/such/folder/t.csv");
    let r = run(&[
        "sim",
        &il,
        "--script",
        script.to_str().unwrap(),
        "--trace",
        missing.to_str().unwrap(),
    ]);
    assert_eq!(r.code, 2, "{r:?}");
    assert!(r.stderr.contains("cannot write"), "{}", r.stderr);
}

#[test]
fn xref_prints_the_index_and_both_usage_tables() {
    let il = il_path("valid/branches.il");
    let r = run(&["xref", &il]);
    assert_eq!(r.code, 0, "{r:?}");
    let lines: Vec<&str> = r.stdout.lines().collect();
    assert!(lines[0].starts_with("ADDRESS"));
    assert!(
        lines
            .iter()
            .any(|l| l.starts_with("Y0000.0   W   LEVEL2  1:1:11")),
        "{}",
        r.stdout
    );
    let r = run(&["xref", &il, "--bits"]);
    assert!(
        r.stdout.lines().any(|l| l == "Y0000_   . . X X X X X X"),
        "{}",
        r.stdout
    );
    let r = run(&["xref", &il_path("valid/functions.il"), "--bytes"]);
    assert!(
        r.stdout.lines().any(|l| l == "T000_   X X . . . . . . . ."),
        "{}",
        r.stdout
    );
    let r = run(&["xref", &il, "--bits", "--bytes"]);
    assert_eq!(r.code, 2, "one table at a time");
}

#[test]
fn comments_export_and_import_all_or_nothing() {
    let dir = tempfile::tempdir().unwrap();
    let ldp = dir.path().join("p.ldp");
    assert_eq!(
        run(&[
            "import-il",
            &il_path("valid/self-holding.il"),
            "-o",
            ldp.to_str().unwrap()
        ])
        .code,
        0
    );
    let csv = dir.path().join("c.csv");
    std::fs::write(
        &csv,
        "kind,table,key,symbol,zh,en\nsymbol,,X0002.1,START,启动,start\nnetwork,LEVEL2,1,start/stop,自保持,self-holding\nmessage,,A0000.1,1001,换刀超时,tool change timeout\n",
    )
    .unwrap();
    let r = run(&[
        "import-comments",
        ldp.to_str().unwrap(),
        csv.to_str().unwrap(),
    ]);
    assert_eq!(r.code, 0, "{r:?}");
    let r = run(&["export-comments", ldp.to_str().unwrap()]);
    assert_eq!(
        r.stdout,
        "kind,table,key,symbol,zh,en\nsymbol,符号表1,X0002.1,START,启动,start\nnetwork,LEVEL1,1,E-stop,,\nnetwork,LEVEL2,1,start/stop,自保持,self-holding\nmessage,,A0000.1,1001,换刀超时,tool change timeout\n"
    );
    let r = run(&["export-comments", ldp.to_str().unwrap(), "--lang", "en"]);
    assert!(
        r.stdout
            .starts_with("kind,table,key,symbol,en\nsymbol,符号表1,X0002.1,START,start\n"),
        "{}",
        r.stdout
    );
    // One bad row: nothing changes, and every bad row is listed with its line.
    let before = read(&ldp);
    std::fs::write(
        &csv,
        "kind,table,key,symbol,zh,en\nsymbol,,X0002.2,STOP,停止,stop\nmessage,,A0000.2,99,x,x\nsymbol,,X0002.3,9LIVES,,\n",
    )
    .unwrap();
    let r = run(&[
        "import-comments",
        ldp.to_str().unwrap(),
        csv.to_str().unwrap(),
    ]);
    assert_eq!(r.code, 1);
    assert!(
        r.stderr.contains(":3: alarm number `99` is not 1000–9999"),
        "{}",
        r.stderr
    );
    assert!(
        r.stderr.contains(":4: `9LIVES` is not a valid symbol name"),
        "{}",
        r.stderr
    );
    assert_eq!(read(&ldp), before, "nothing changed");
}

#[test]
fn an_import_of_comments_that_check_would_reject_is_refused_at_its_line() {
    let dir = tempfile::tempdir().unwrap();
    let ldp = dir.path().join("p.ldp");
    let il = il_path("valid/self-holding.il");
    assert_eq!(
        run(&["import-il", &il, "-o", ldp.to_str().unwrap()]).code,
        0
    );
    let csv = dir.path().join("c.csv");
    let head = "kind,table,key,symbol,zh,en\n";
    std::fs::write(&csv, format!("{head}message,,A0000.1,1001,甲,a\n")).unwrap();
    let import = || {
        run(&[
            "import-comments",
            ldp.to_str().unwrap(),
            csv.to_str().unwrap(),
        ])
    };
    assert_eq!(import().code, 0);
    let before = read(&ldp);
    std::fs::write(&csv, format!("{head}message,,A0000.2,1001,乙,b\n")).unwrap();
    let r = import();
    assert_eq!(r.code, 1, "{r:?}");
    assert!(
        r.stderr.contains(
            ":2: alarm number 1001 would be used by both A0000.1 and A0000.2, which `check` refuses (T005)"
        ),
        "{}",
        r.stderr
    );
    assert_eq!(read(&ldp), before, "nothing changed");
    assert_eq!(run(&["check", ldp.to_str().unwrap()]).code, 0);
}

#[test]
fn the_editor_online_options_refuse_what_cannot_work() {
    let lathe = here().join("../projects/lathe-988ta.ldp");
    let lathe = lathe.to_str().unwrap();
    let r = run(&["--nc", "part.nc", lathe]);
    assert_eq!(r.code, 2, "{r:?}");
    assert!(r.stderr.contains("--run"), "{}", r.stderr);
    let r = run(&["--run", "--nc", "/no/such/part.nc", lathe]);
    assert_eq!(r.code, 2, "{r:?}");
    assert!(
        r.stderr
            .contains("cannot read the NC program /no/such/part.nc"),
        "{}",
        r.stderr
    );
}

#[test]
fn lang_zh_speaks_chinese_in_the_same_line_shapes() {
    let path = il_path("invalid/stacks.il");
    let r = run(&["--lang", "zh", "check", &path]);
    assert_eq!(r.code, 1, "{r:?}");
    let lines: Vec<&str> = r.stdout.lines().collect();
    assert_eq!(*lines.last().unwrap(), "9 个错误，0 个警告");
    assert!(
        lines[0].starts_with(&format!("{path}:4: error: ")) && lines[0].ends_with("[L013]"),
        "the shape scripts read is kept: {}",
        lines[0]
    );
    assert!(
        lines[0].contains("ORB") && !lines[0].contains("has no open block"),
        "{}",
        lines[0]
    );
    // After the subcommand too, and for unusable input.
    let r = run(&["check", "/no/such/file.ldp", "--lang", "zh"]);
    assert_eq!(r.code, 2);
    assert!(
        r.stderr.contains("无法读取 /no/such/file.ldp"),
        "{}",
        r.stderr
    );
    // A script error in Chinese, with its line.
    let dir = tempfile::tempdir().unwrap();
    let script = dir.path().join("s.script");
    std::fs::write(&script, "scan 1\nsett X0000.0 1\n").unwrap();
    let program = il_path("valid/functions.il");
    let r = run(&[
        "sim",
        &program,
        "--script",
        script.to_str().unwrap(),
        "--lang",
        "zh",
    ]);
    assert_eq!(r.code, 2, "{r:?}");
    let line = r.stderr.lines().next().unwrap();
    assert!(
        line.starts_with(&format!("{}:2: ", script.display())),
        "{line}"
    );
    assert!(
        line.chars().any(|c| ('\u{4e00}'..='\u{9fff}').contains(&c)),
        "{line}"
    );
    // An unknown language is refused like any bad argument.
    assert_eq!(run(&["--lang", "fr", "check", &path]).code, 2);
}

#[test]
fn bench_runs_on_the_engine_asked_for_and_refuses_an_unknown_one() {
    for engine in ["interp", "native", "checked"] {
        let r = run(&[
            "bench",
            &il_path("valid/functions.il"),
            "--scans",
            "20",
            "--engine",
            engine,
        ]);
        assert_eq!(r.code, 0, "{r:?}");
        let last = r.stdout.lines().last().unwrap();
        let expected = if ladder_engine::vm::native::AVAILABLE {
            engine
        } else {
            "interp"
        };
        assert!(last.ends_with(&format!(" engine={expected}")), "{last}");
    }
    let r = run(&["bench", &il_path("valid/functions.il"), "--engine", "jit"]);
    assert_eq!(r.code, 2, "{r:?}");
    assert!(
        r.stderr
            .contains("possible values: interp, native, checked"),
        "{}",
        r.stderr
    );
}

#[test]
fn an_endless_input_is_refused_past_the_size_limit_before_it_fills_the_memory() {
    if !std::path::Path::new("/dev/zero").exists() {
        return;
    }
    let r = run(&["check", "/dev/zero"]);
    assert_ne!(r.code, 0, "{r:?}");
    assert!(r.stderr.contains("larger than 64 MiB"), "{}", r.stderr);
    let r = run(&[
        "sim",
        &il_path("valid/functions.il"),
        "--script",
        "/dev/zero",
    ]);
    assert_ne!(r.code, 0, "{r:?}");
    assert!(r.stderr.contains("larger than 64 MiB"), "{}", r.stderr);
    // The limit is the program's own reason, so it is said in Chinese too.
    let r = run(&["--lang", "zh", "check", "/dev/zero"]);
    assert_eq!(
        r.stderr,
        "ladder-studio: 无法读取 /dev/zero：文件大于 64 MiB，超出 Ladder Studio 能读取的上限\n"
    );
}

/// Whether `s` holds a Chinese character.
fn has_cjk(s: &str) -> bool {
    s.chars().any(|c| ('\u{4e00}'..='\u{9fff}').contains(&c))
}

#[test]
fn lang_zh_says_the_print_and_comments_reasons_in_chinese() {
    let dir = tempfile::tempdir().unwrap();
    let ldp = dir.path().join("p.ldp");
    std::fs::copy(here().join("../projects/start-stop.ldp"), &ldp).unwrap();
    let (ldp, pdf) = (ldp.to_str().unwrap(), dir.path().join("p.pdf"));
    let pdf = pdf.to_str().unwrap();
    // Each reason `print --network` can give, in Chinese after the option's name, and in
    // English as it was.
    for (network, english) in [
        (
            "LEVEL2",
            "`LEVEL2`: write the network as BLOCK:N, e.g. LEVEL2:3",
        ),
        ("LEVEL9:1", "`LEVEL9`: no such block"),
        ("LEVEL2:99", "`99`: LEVEL2 has networks 1 to"),
    ] {
        let zh = run(&[
            "--lang",
            "zh",
            "print",
            ldp,
            "-o",
            pdf,
            "--network",
            network,
        ]);
        assert_eq!(zh.code, 2, "{zh:?}");
        let line = zh.stderr.trim_end();
        assert!(line.starts_with("ladder-studio: --network `"), "{line}");
        assert!(has_cjk(line), "{line}");
        for word in ["write", "no such", "has networks"] {
            assert!(!line.contains(word), "English `{word}` in: {line}");
        }
        let en = run(&[
            "--lang",
            "en",
            "print",
            ldp,
            "-o",
            pdf,
            "--network",
            network,
        ]);
        assert_eq!(en.code, 2, "{en:?}");
        assert!(
            en.stderr
                .starts_with(&format!("ladder-studio: --network {english}")),
            "{}",
            en.stderr
        );
    }
    // A comments CSV that cannot be read: its header, and the CSV reader's own reason (the
    // reader's words stay, inside the Chinese line).
    let csv = dir.path().join("c.csv");
    let csv_s = csv.to_str().unwrap();
    std::fs::write(&csv, "name,comment\nSTART,x\n").unwrap();
    let zh = run(&["--lang", "zh", "import-comments", ldp, csv_s]);
    assert_eq!(zh.code, 2, "{zh:?}");
    assert_eq!(
        zh.stderr,
        format!(
            "ladder-studio: {csv_s}: 第 1 行：表头必须列出 kind、table、key、symbol 列，以及每种语言一列\n"
        )
    );
    let en = run(&["--lang", "en", "import-comments", ldp, csv_s]);
    assert_eq!(
        en.stderr,
        format!(
            "ladder-studio: {csv_s}: line 1: the header must name the columns kind,table,key,symbol and one per language\n"
        )
    );
    std::fs::write(&csv, "kind,table,key,symbol,zh\nsymbol,,X0002.1\n").unwrap();
    let zh = run(&["--lang", "zh", "import-comments", ldp, csv_s]);
    assert_eq!(zh.code, 2, "{zh:?}");
    assert!(
        zh.stderr
            .starts_with(&format!("ladder-studio: {csv_s}: 第 2 行：")),
        "{}",
        zh.stderr
    );
    let en = run(&["--lang", "en", "import-comments", ldp, csv_s]);
    assert!(
        en.stderr
            .starts_with(&format!("ladder-studio: {csv_s}: line 2: ")),
        "{}",
        en.stderr
    );
}
