//! `sim --cnc` and `bench --cnc` as users see them: every script in `tests/cnc/` passes, bad
//! `cnc` lines are refused with their line before anything runs, commands that cannot apply
//! fail with their line, and `--trace` records CNC values.

use ladder_tests::{here, run, run_scripts, scripts};

fn bench_ladder() -> String {
    here().join("cnc/mst.il").display().to_string()
}

fn script(dir: &tempfile::TempDir, text: &str) -> String {
    let p = dir.path().join("s.script");
    std::fs::write(&p, text).unwrap();
    p.display().to_string()
}

#[test]
fn every_cnc_script_passes() {
    let dir = here().join("cnc");
    let scripts = scripts(&dir);
    assert!(!scripts.is_empty());
    let program = |s: &std::path::Path| {
        let il = s.with_extension("il");
        if il.exists() { il } else { dir.join("mst.il") }
    };
    // The CNC's answers to WINDR, AXCTL and the rest, on each engine.
    for engine in ["interp", "native", "checked"] {
        let (failures, expects) = run_scripts(&scripts, program, &["--cnc", "--engine", engine]);
        assert!(failures.is_empty(), "{engine}: {}", failures.join("\n"));
        assert!(expects >= 30, "{engine}: only {expects} expectations ran");
    }
}

#[test]
fn cnc_lines_without_the_cnc_or_with_a_mistake_are_refused_before_anything_runs() {
    let dir = tempfile::tempdir().unwrap();
    let cases = [
        (
            "scan\ncnc reset\n",
            false,
            2,
            "`cnc` lines drive the simulated CNC",
        ),
        (
            "scan\nexpect cnc.mode MEM\n",
            false,
            2,
            "run with `sim --cnc`",
        ),
        ("scan\ncnc spin\n", true, 2, "unknown cnc command `spin`"),
        ("cnc param 1420 9000\n", true, 1, "needs an axis number"),
        ("cnc offset 1 Q 1\n", true, 1, "the type is"),
        ("cnc alarm 950\n", true, 1, "cannot be raised"),
        ("expect cnc.speed 1\n", true, 1, "unknown CNC value"),
        ("expect cnc.run FAST\n", true, 1, "not a run state"),
        ("set cnc.mode 1\n", true, 1, "CNC value"),
        ("cnc program \"M03\n", true, 1, "closing"),
        (
            "scan\nscan\ncnc program-file missing.nc\n",
            true,
            3,
            "missing.nc",
        ),
        (
            "cnc position X\n",
            true,
            1,
            "usage: cnc position AXIS VALUE",
        ),
    ];
    for (text, cnc, line, message) in cases {
        let s = script(&dir, text);
        let mut args = vec!["sim", "x", "--script", &s];
        let il = bench_ladder();
        args[1] = &il;
        if cnc {
            args.push("--cnc");
        }
        let r = run(&args);
        assert_eq!(r.code, 2, "{text}: {r:?}");
        assert!(
            r.stderr.starts_with(&format!("{s}:{line}: ")) && r.stderr.contains(message),
            "{text}: {}",
            r.stderr
        );
        assert!(r.stdout.is_empty(), "nothing ran: {}", r.stdout);
    }
}

#[test]
fn a_command_that_cannot_apply_now_fails_with_its_line_and_the_run_goes_on() {
    let dir = tempfile::tempdir().unwrap();
    let s = script(
        &dir,
        "set X0001.1 1\nset X0001.2 1\nset X0000 1\ncnc program \"G04 P1000\"\nscan\nset X1.0 1\nscan\nset X1.0 0\nscan\ncnc program \"M03\"\ncnc position Z 5\nexpect cnc.pos.Y 0\nprint cnc.run\n",
    );
    let r = run(&["sim", &bench_ladder(), "--script", &s, "--cnc"]);
    assert_eq!(r.code, 1, "{r:?}");
    let lines: Vec<&str> = r.stdout.lines().collect();
    assert_eq!(
        lines,
        [
            format!(
                "{s}:10: cnc: the program cannot be replaced while automatic operation is RUN (reset first)"
            )
            .as_str(),
            format!("{s}:12: cnc: axis Y is beyond the 2 controlled axes (#8130)").as_str(),
            "cnc.run = RUN",
            "0 passed, 2 failed",
        ]
    );
}

#[test]
fn a_cnc_mismatch_prints_both_values_in_the_keys_units() {
    let dir = tempfile::tempdir().unwrap();
    let s = script(
        &dir,
        "cnc position Z -4.987\nscan\nexpect cnc.pos.Z -5\nprint cnc.pos.Z\nexpect cnc.mode mdi\nexpect cnc.macro.500 vacant\ncnc macro 500 2.5\nexpect cnc.macro.500 2.50\n",
    );
    let r = run(&["sim", &bench_ladder(), "--script", &s, "--cnc"]);
    assert_eq!(r.code, 1);
    assert_eq!(
        r.stdout,
        format!(
            "{s}:3: expect cnc.pos.Z = -5, got -4.987\ncnc.pos.Z = -4.987\n3 passed, 1 failed\n"
        )
    );
}

#[test]
fn the_trace_records_cnc_values_beside_addresses() {
    let dir = tempfile::tempdir().unwrap();
    let trace = dir.path().join("t.csv");
    let s = script(
        &dir,
        "watch cnc.mode\nwatch F0003\nwatch cnc.pos.Z\nset X0001.1 1\nset X0000 5\nset G0010 10\nscan\nset G0100.1 1\nscan 2\n",
    );
    let r = run(&[
        "sim",
        &bench_ladder(),
        "--script",
        &s,
        "--cnc",
        "--trace",
        trace.to_str().unwrap(),
    ]);
    assert_eq!(r.code, 0, "{r:?}");
    assert_eq!(
        std::fs::read_to_string(&trace).unwrap(),
        "tick,ms,cnc.mode,F0003,cnc.pos.Z\n1,8,JOG,4,0.000\n2,16,JOG,4,0.160\n3,24,JOG,4,0.320\n"
    );
}

#[test]
fn the_trace_records_the_macro_handshake_as_the_f_and_g_bits_it_is() {
    // docs/gcode.md, "The PLC handshake": #1100 is F214.0 and #1000 is G214.0 in the trace.
    let dir = tempfile::tempdir().unwrap();
    let trace = dir.path().join("t.csv");
    let program = here().join("cnc/parts/macro-handshake.nc");
    let text = format!(
        "watch F0214.0\nwatch G0214.0\nwatch cnc.macro.500\nset X0001.1 1\nset X0001.2 1\nset X0000 1\ncnc program-file {}\nscan\nset X1.0 1\nscan\nset X1.0 0\nscan 3\n",
        program.display()
    );
    let s = script(&dir, &text);
    let ladder = here().join("cnc/macro.il").display().to_string();
    let r = run(&[
        "sim",
        &ladder,
        "--script",
        &s,
        "--cnc",
        "--trace",
        trace.to_str().unwrap(),
    ]);
    assert_eq!(r.code, 0, "{r:?}");
    assert_eq!(
        std::fs::read_to_string(&trace).unwrap(),
        "tick,ms,F0214.0,G0214.0,cnc.macro.500\n1,8,0,0,vacant\n2,16,0,0,vacant\n3,24,1,0,vacant\n4,32,0,1,vacant\n5,40,0,0,1\n"
    );
}

#[test]
fn bench_with_the_cnc_times_the_exchange_on_a_set_up_machine() {
    let lathe = here().join("../projects/lathe-988ta.ldp");
    let setup = here().join("../projects/lathe-988ta.tests/cycle.script");
    let r = run(&[
        "bench",
        lathe.to_str().unwrap(),
        "--cnc",
        "--no-machine",
        "--script",
        setup.to_str().unwrap(),
        "--scans",
        "2000",
    ]);
    assert_eq!(r.code, 0, "{r:?}");
    let lines: Vec<&str> = r.stdout.lines().collect();
    assert!(lines[0].starts_with("cnc_ns_per_exchange="), "{}", r.stdout);
    assert!(lines[0].contains(" one_hour_s="));
    assert!(lines[1].starts_with("steps=") && lines[1].contains(" ns_per_step="));
    // A set-up script that fails times nothing.
    let dir = tempfile::tempdir().unwrap();
    let bad = script(&dir, "expect cnc.run RUN\n");
    let r = run(&[
        "bench",
        lathe.to_str().unwrap(),
        "--cnc",
        "--no-machine",
        "--script",
        &bad,
    ]);
    assert_eq!(r.code, 1);
    assert!(r.stderr.contains("nothing was timed"), "{}", r.stderr);
}
