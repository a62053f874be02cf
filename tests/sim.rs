//! Every `tests/sim/<name>.script` runs against `<name>.il` through `ladder-studio sim` and
//! must end with `N passed, 0 failed` (the manual's worked examples and the edge cases of
//! isa.md).

use ladder_tests::{here, run};

#[test]
fn every_manual_example_script_passes() {
    let dir = here().join("sim");
    let mut scripts: Vec<_> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|x| x == "script"))
        .collect();
    scripts.sort();
    assert!(scripts.len() >= 40, "only {} scripts", scripts.len());
    let mut failures = Vec::new();
    let mut expects = 0;
    for script in &scripts {
        let il = script.with_extension("il");
        let r = run(&[
            "sim",
            il.to_str().unwrap(),
            "--script",
            script.to_str().unwrap(),
        ]);
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
    assert!(failures.is_empty(), "{}", failures.join("\n"));
    assert!(expects > 500, "only {expects} expectations ran");
}
