//! Every `tests/sim/<name>.script` runs against `<name>.il` through `ladder-studio sim` and
//! must end with `N passed, 0 failed` (the manual's worked examples and the edge cases of
//! the instruction reference).

use ladder_tests::{here, run_scripts, scripts};

#[test]
fn every_manual_example_script_passes() {
    let scripts = scripts(&here().join("sim"));
    assert!(scripts.len() >= 40, "only {} scripts", scripts.len());
    let (failures, expects) = run_scripts(&scripts, |s| s.with_extension("il"), &[]);
    assert!(failures.is_empty(), "{}", failures.join("\n"));
    assert!(expects > 500, "only {expects} expectations ran");
}
