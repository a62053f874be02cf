//! Every `tests/sim/<name>.script` runs against `<name>.il` through `ladder-studio sim` and
//! must end with `N passed, 0 failed` (the manual's worked examples and the edge cases of
//! the instruction reference); every function instruction of the catalogue is used by one of
//! these scripts' programs or, for those that talk to the CNC, by one in `tests/cnc/`.

use ladder_engine::CATALOG;
use ladder_engine::catalog::InstrClass;
use ladder_tests::{here, read, run_scripts, scripts};
use std::collections::BTreeSet;

/// On each engine: the interpreter, the native code, and both checked against each other
/// after every level of every tick.
#[test]
fn every_manual_example_script_passes_on_every_engine() {
    let scripts = scripts(&here().join("sim"));
    assert!(scripts.len() >= 40, "only {} scripts", scripts.len());
    for engine in ["interp", "native", "checked"] {
        let (failures, expects) =
            run_scripts(&scripts, |s| s.with_extension("il"), &["--engine", engine]);
        assert!(failures.is_empty(), "{engine}: {}", failures.join("\n"));
        assert!(expects > 500, "{engine}: only {expects} expectations ran");
    }
}

/// The mnemonics written as instructions in the programs of the scripts in `folder`: the
/// first word of each line of a `.il` beside a `.script` (docs/plc.md, "Instruction-list
/// text": `;` starts a comment).
fn instructions_used(folder: &str) -> BTreeSet<String> {
    let mut used = BTreeSet::new();
    for script in scripts(&here().join(folder)) {
        let il = script.with_extension("il");
        if !il.exists() {
            continue;
        }
        for line in read(&il).lines() {
            let code = line.split(';').next().unwrap_or("");
            if let Some(word) = code.split_whitespace().next() {
                used.insert(word.to_ascii_uppercase());
            }
        }
    }
    used
}

#[test]
fn every_function_instruction_has_a_script() {
    let used: BTreeSet<String> = instructions_used("sim")
        .into_iter()
        .chain(instructions_used("cnc"))
        .collect();
    let missing: Vec<&str> = CATALOG
        .iter()
        .filter(|s| s.class == InstrClass::Function && !used.contains(s.name))
        .map(|s| s.name)
        .collect();
    assert!(
        missing.is_empty(),
        "no script in tests/sim/ or tests/cnc/ runs {missing:?}: add a NAME.il using it and a \
         NAME.script whose expects fail when it does nothing (tests/sim/README.md)"
    );
}
