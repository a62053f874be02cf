//! `ladder-studio test`: a project's test folder run as a suite, with its JUnit report read
//! back by an independent JUnit reader.

use ladder_tests::{here, run};
use std::path::{Path, PathBuf};

/// A copy of the start/stop program with a test folder of three scripts: one that passes,
/// one whose check fails, one that cannot run (a typo).
fn plant(dir: &Path) -> PathBuf {
    let program = dir.join("plant.il");
    std::fs::copy(here().join("../projects/start-stop.il"), &program).unwrap();
    let tests = dir.join("plant.tests");
    std::fs::create_dir(&tests).unwrap();
    let healthy = "set X0000.5 1\n";
    std::fs::write(
        tests.join("a-start.script"),
        format!("{healthy}set X0002.1 1\nscan 2\nexpect Y0003.7 1\nexpect G0008.4 1\n"),
    )
    .unwrap();
    std::fs::write(
        tests.join("b-lamp.script"),
        format!("{healthy}set X0002.1 1\nscan 2\nexpect Y0004.0 1  # only after 2 s\n"),
    )
    .unwrap();
    std::fs::write(tests.join("c-typo.script"), "sett X0002.1 1\n").unwrap();
    std::fs::write(tests.join("notes.txt"), "not a script\n").unwrap();
    program
}

fn junit(path: &Path) -> junit_parser::TestSuites {
    let file = std::fs::File::open(path).unwrap();
    junit_parser::from_reader(std::io::BufReader::new(file)).expect("JUnit XML that a reader reads")
}

#[test]
fn a_failing_script_fails_the_suite_and_the_junit_report_says_which() {
    let dir = tempfile::tempdir().unwrap();
    let program = plant(dir.path());
    let xml = dir.path().join("results.xml");
    let r = run(&[
        "test",
        program.to_str().unwrap(),
        "--junit",
        xml.to_str().unwrap(),
    ]);
    assert_eq!(r.code, 1, "{}{}", r.stdout, r.stderr);
    let lines: Vec<&str> = r.stdout.lines().collect();
    assert_eq!(lines[0], "ok    plant.tests/a-start.script (2 checks)");
    assert_eq!(
        lines[1],
        "FAIL  plant.tests/b-lamp.script (1 of 1 checks failed)"
    );
    assert!(
        lines[2].starts_with("      ") && lines[2].contains("expect Y0004.0"),
        "{}",
        r.stdout
    );
    assert!(
        r.stdout
            .contains("FAIL  plant.tests/c-typo.script (cannot run)"),
        "{}",
        r.stdout
    );
    assert!(
        r.stdout.contains("c-typo.script:1:"),
        "the script error is shown: {}",
        r.stdout
    );
    assert_eq!(lines.last(), Some(&"1 passed, 2 failed"));

    let report = junit(&xml);
    assert_eq!((report.tests, report.failures, report.errors), (3, 1, 1));
    let suite = &report.suites[0];
    assert_eq!(suite.name, "plant.il");
    let names: Vec<&str> = suite
        .cases
        .iter()
        .map(|c| c.original_name.as_str())
        .collect();
    assert_eq!(
        names,
        [
            "plant.tests/a-start.script",
            "plant.tests/b-lamp.script",
            "plant.tests/c-typo.script"
        ]
    );
    assert!(suite.cases[0].status.is_success());
    match &suite.cases[1].status {
        junit_parser::TestStatus::Failure(f) => {
            assert_eq!(f.message, "1 of 1 checks failed");
            assert!(f.text.contains("expect Y0004.0"), "{}", f.text);
        }
        s => panic!("b-lamp should fail: {s:?}"),
    }
    assert!(matches!(
        &suite.cases[2].status,
        junit_parser::TestStatus::Error(e) if e.message.contains("c-typo.script:1:")
    ));
}

#[test]
fn scripts_run_in_parallel_give_what_they_give_one_by_one() {
    let dir = tempfile::tempdir().unwrap();
    let program = plant(dir.path());
    let outcome = |jobs: &str| {
        let xml = dir.path().join(format!("jobs-{jobs}.xml"));
        let r = run(&[
            "test",
            program.to_str().unwrap(),
            "--jobs",
            jobs,
            "--junit",
            xml.to_str().unwrap(),
        ]);
        let report = junit(&xml);
        let cases: Vec<String> = report.suites[0]
            .cases
            .iter()
            .map(|c| format!("{} {:?}", c.name, c.status))
            .collect();
        (r.code, r.stdout, cases)
    };
    let serial = outcome("1");
    assert_eq!(outcome("3"), serial);
    assert_eq!(outcome("8"), serial);
}

#[test]
fn a_project_without_a_test_folder_is_refused_with_where_to_put_one() {
    let dir = tempfile::tempdir().unwrap();
    let program = dir.path().join("plant.il");
    std::fs::copy(here().join("../projects/start-stop.il"), &program).unwrap();
    let r = run(&["test", program.to_str().unwrap()]);
    assert_eq!(r.code, 2);
    assert!(
        r.stderr.contains("plant.tests: no test folder"),
        "{}",
        r.stderr
    );
    std::fs::create_dir(dir.path().join("plant.tests")).unwrap();
    let r = run(&["test", program.to_str().unwrap()]);
    assert_eq!(r.code, 2);
    assert!(r.stderr.contains("no .script files to run"), "{}", r.stderr);
    let r = run(&["test", dir.path().to_str().unwrap()]);
    assert_eq!(r.code, 2);
    assert!(r.stderr.contains("not a project file"), "{}", r.stderr);
}

#[test]
fn a_report_that_could_not_be_written_is_refused_before_anything_runs() {
    let dir = tempfile::tempdir().unwrap();
    let program = plant(dir.path());
    let nowhere = dir.path().join("no-such-folder/results.xml");
    let r = run(&[
        "test",
        program.to_str().unwrap(),
        "--junit",
        nowhere.to_str().unwrap(),
    ]);
    assert_eq!((r.code, r.stdout.as_str()), (2, ""), "{}", r.stderr);
    assert!(r.stderr.contains("no such folder"), "{}", r.stderr);
}

#[test]
fn the_sample_lathe_passes_its_test_folder() {
    let ldp = here().join("../projects/lathe-988ta.ldp");
    let r = run(&["test", ldp.to_str().unwrap()]);
    assert_eq!(r.code, 0, "{}{}", r.stdout, r.stderr);
    let checks: usize = r
        .stdout
        .lines()
        .filter_map(|l| {
            l.rsplit_once('(')?
                .1
                .strip_suffix(" checks)")?
                .parse::<usize>()
                .ok()
        })
        .sum();
    assert!(checks > 425, "only {checks} checks ran:\n{}", r.stdout);
    assert!(r.stdout.ends_with("16 passed, 0 failed\n"), "{}", r.stdout);
    // The scripts with the machine model ran with it: nothing there sets a sensor by hand.
    assert!(
        r.stdout
            .contains("ok    lathe-988ta.tests/machine-part-program.script")
    );
}
