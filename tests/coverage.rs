//! Rung coverage from the command line: `sim --coverage` on programs written so that the
//! exact figures are known, and `test --coverage` merging the scripts of a test folder.

use ladder_engine::coverage::{Coverage, State};
use ladder_tests::run;
use std::path::Path;

/// One network energised through one branch only; a compare whose "greater" result is never
/// seen (so it is not covered, though its ACT was seen both ways), read by the next network.
const PROGRAM: &str = "\
LEVEL1
NETWORK \"one branch\"
LD   X0000.0
OR   X0000.1
OUT  Y0000.0
LEVEL2
NETWORK \"compare\"
LD   X0002.1
CMP  1 R0100 R0200 R0300.0
NETWORK \"greater\"
LD   R0300.0
OUT  Y0001.0
END
";

/// X0000.0 on then off; the compare run with R100 < R200, then equal, then not run.
const SCRIPT: &str = "\
set X0000.0 1
scan 4
set X0000.0 0
scan 4
set X0002.1 1
set R0100 1
set R0200 2
scan 4
expect R0300.2 1
set R0100 2
scan 4
expect R0300.1 1
set X0002.1 0
scan 4
expect Y0001.0 0
";

fn write(dir: &Path, name: &str, text: &str) -> String {
    let p = dir.join(name);
    std::fs::write(&p, text).unwrap();
    p.to_str().unwrap().to_string()
}

fn states(c: &Coverage, network: usize) -> Vec<(String, State)> {
    c.networks[network]
        .elements
        .iter()
        .map(|e| (e.il.clone(), e.state()))
        .collect()
}

/// `sim` of [`PROGRAM`] under [`SCRIPT`] with `option OUT` (OUT a file `out` in a fresh
/// folder, or in a folder that does not exist); returns the run and OUT.
fn sim_with(option: &str, out: &str) -> (ladder_tests::Run, std::path::PathBuf, tempfile::TempDir) {
    let dir = tempfile::tempdir().unwrap();
    let il = write(dir.path(), "plant.il", PROGRAM);
    let script = write(dir.path(), "run.script", SCRIPT);
    let path = dir.path().join(out);
    let r = run(&[
        "sim",
        &il,
        "--script",
        &script,
        option,
        path.to_str().unwrap(),
    ]);
    (r, path, dir)
}

#[test]
fn sim_measures_the_branch_never_taken_and_the_result_never_seen() {
    let (r, json, _dir) = sim_with("--coverage", "cov.json");
    assert_eq!(r.code, 0, "{}{}", r.stdout, r.stderr);
    assert_eq!(
        r.stdout,
        "level 1: 0/1 networks fully covered, 0 % (2/3 elements)\n\
         level 2: 0/2 networks fully covered, 0 % (1/4 elements)\n\
         3 passed, 0 failed\n"
    );
    let c = Coverage::from_json(&std::fs::read_to_string(&json).unwrap()).unwrap();
    let s = |il: &str, st: State| (il.to_string(), st);
    assert_eq!(
        states(&c, 0),
        [
            s("LD X0000.0", State::Covered),
            s("OR X0000.1", State::Half),
            s("OUT Y0000.0", State::Covered)
        ]
    );
    // The compare: ACT seen off and on, "less" and "equal" seen, "greater" never.
    let cmp = &c.networks[1].elements[1];
    assert_eq!((cmp.seen0, cmp.seen1), (true, true));
    assert_eq!(cmp.outcomes, Some([false, true, true]));
    assert_eq!(cmp.state(), State::Half);
    assert_eq!(c.networks[1].state(), State::Half);
    assert_eq!(
        states(&c, 2),
        [s("LD R0300.0", State::Half), s("OUT Y0001.0", State::Half)]
    );
    // Where each element is: the IL's own lines have no grid cell.
    assert!(c.networks[0].elements.iter().all(|e| e.cell.is_none()));
}

#[test]
fn a_contact_counts_only_where_it_decides_its_step() {
    let dir = tempfile::tempdir().unwrap();
    let il = write(
        dir.path(),
        "series.il",
        "LEVEL1\nNETWORK\nLD   X0000.0\nAND  X0000.1\nOUT  Y0000.0\nEND\n",
    );
    // X0.1 flips while X0.0 is open: the series contact never decides the rung then.
    let script = write(
        dir.path(),
        "s.script",
        "set X0000.1 1\nscan 2\nset X0000.1 0\nscan 2\nexpect Y0000.0 0\n",
    );
    let json = dir.path().join("cov.json");
    let r = run(&[
        "sim",
        &il,
        "--script",
        &script,
        "--coverage",
        json.to_str().unwrap(),
    ]);
    assert_eq!(r.code, 0, "{}{}", r.stdout, r.stderr);
    let c = Coverage::from_json(&std::fs::read_to_string(&json).unwrap()).unwrap();
    let s = |il: &str, st: State| (il.to_string(), st);
    assert_eq!(
        states(&c, 0),
        [
            s("LD X0000.0", State::Half),
            s("AND X0000.1", State::Never),
            s("OUT Y0000.0", State::Half)
        ]
    );
    // With power at its left, its closing and opening decide: covered.
    let script = write(
        dir.path(),
        "t.script",
        "set X0000.0 1\nset X0000.1 1\nscan 2\nset X0000.1 0\nscan 2\nexpect Y0000.0 0\n",
    );
    let r = run(&[
        "sim",
        &il,
        "--script",
        &script,
        "--coverage",
        json.to_str().unwrap(),
    ]);
    assert_eq!(r.code, 0, "{}{}", r.stdout, r.stderr);
    let c = Coverage::from_json(&std::fs::read_to_string(&json).unwrap()).unwrap();
    assert_eq!(c.networks[0].elements[1].state(), State::Covered);
}

#[test]
fn test_merges_the_coverage_of_every_script() {
    let dir = tempfile::tempdir().unwrap();
    let il = write(dir.path(), "plant.il", PROGRAM);
    std::fs::create_dir(dir.path().join("plant.tests")).unwrap();
    let tests = dir.path().join("plant.tests");
    // Each script takes one branch: together they cover the first network.
    write(
        &tests,
        "a.script",
        "set X0000.0 1\nscan 2\nset X0000.0 0\nscan 2\nexpect Y0000.0 0\n",
    );
    write(
        &tests,
        "b.script",
        "set X0000.1 1\nscan 2\nset X0000.1 0\nscan 2\nexpect Y0000.0 0\n",
    );
    let json = dir.path().join("cov.json");
    let r = run(&["test", &il, "--coverage", json.to_str().unwrap()]);
    assert_eq!(r.code, 0, "{}{}", r.stdout, r.stderr);
    assert!(
        r.stdout
            .contains("level 1: 1/1 networks fully covered, 100 % (3/3 elements)\n"),
        "{}",
        r.stdout
    );
    let c = Coverage::from_json(&std::fs::read_to_string(&json).unwrap()).unwrap();
    assert_eq!(c.runs, 2);
    // Neither script ran the compare.
    assert_eq!(c.networks[1].state(), State::Half);
}

#[test]
fn a_coverage_file_that_could_not_be_written_is_refused_before_the_run() {
    let (r, _, _dir) = sim_with("--coverage", "missing/cov.json");
    assert_eq!((r.code, r.stdout.as_str()), (2, ""), "{}", r.stderr);
    assert!(r.stderr.contains("no such folder"), "{}", r.stderr);
}

#[test]
fn a_coverage_file_that_is_not_one_is_refused_by_the_reader() {
    assert!(
        Coverage::from_json("{\"format\":\"something else\",\"runs\":1,\"networks\":[]}").is_err()
    );
}

#[test]
fn the_html_page_lists_the_networks_left_to_cover_and_their_elements() {
    let (r, page, _dir) = sim_with("--coverage-html", "cov.html");
    assert_eq!(r.code, 0, "{}{}", r.stdout, r.stderr);
    let html = std::fs::read_to_string(&page).unwrap();
    assert!(
        html.starts_with("<!DOCTYPE html>")
            && html.contains("<title>Rung coverage of plant.il</title>")
    );
    assert!(
        html.contains("<h2>3 networks not fully covered</h2>"),
        "{html}"
    );
    assert!(html.contains("<h3>LEVEL1 N0001 one branch</h3>"));
    assert!(
        html.contains(
            "<tr class=\"half\"><td><code>OR X0000.1</code></td><td>half</td><td>0</td></tr>"
        ),
        "{html}"
    );
    // The compare is listed with the results it saw, and the network reading "greater".
    assert!(
        html.contains(
            "<tr class=\"half\"><td><code>CMP 1 R0100 R0200 R0300.0</code></td><td>half</td><td>0, 1 · = &lt;</td></tr>"
        ),
        "{html}"
    );
    assert!(html.contains("<h3>LEVEL2 N0002 greater</h3>"));
    // Self-contained: no link to anything outside the page.
    assert!(!html.contains("http") && !html.contains("<link") && !html.contains("<script"));
}
