//! Every `tests/sim/<name>.script` runs against `<name>.il` through `ladder-studio sim` and
//! must end with `N passed, 0 failed` (the manual's worked examples and the edge cases of
//! the instruction reference); every function instruction of the catalogue is used by one of
//! these scripts' programs or, for those that talk to the CNC, by one in `tests/cnc/`, and
//! that script expects a value of an address the instruction writes there.

use ladder_engine::catalog::InstrClass;
use ladder_engine::{Address, CATALOG, Op};
use ladder_tests::{here, read, run_scripts, scripts};
use std::collections::BTreeMap;

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

/// For each mnemonic written as an instruction in the programs of the scripts in `folder`
/// (the first word of each line of a `.il` beside a `.script`; docs/plc.md, "Instruction-list
/// text": `;` starts a comment), whether one of those scripts expects a value of an address
/// the instruction may write in its program: the byte, or a bit of it, that an output
/// operand names.
fn instructions_checked(folder: &str) -> BTreeMap<String, bool> {
    let mut used = BTreeMap::new();
    for script in scripts(&here().join(folder)) {
        let il = script.with_extension("il");
        if !il.exists() {
            continue;
        }
        let expected: Vec<(char, u32)> = read(&script)
            .lines()
            .filter_map(|l| {
                let mut words = l.split_whitespace();
                (words.next()? == "expect").then_some(())?;
                let target = words.next()?.split(':').next()?;
                byte_of(target)
            })
            .collect();
        for line in read(&il).lines() {
            let code = line.split(';').next().unwrap_or("");
            let mut words = code.split_whitespace();
            let Some(word) = words.next() else { continue };
            let name = word.to_ascii_uppercase();
            let operands: Vec<&str> = words.collect();
            let checked = Op::from_name(&name).is_some_and(|op| {
                operands.iter().enumerate().any(|(i, o)| {
                    op.spec().operand(i).is_some_and(|s| s.may_write())
                        && byte_of(o).is_some_and(|b| expected.contains(&b))
                })
            });
            *used.entry(name).or_insert(false) |= checked;
        }
    }
    used
}

/// The area letter and byte number an address names (`R0050.0` → `('R', 50)`).
fn byte_of(text: &str) -> Option<(char, u32)> {
    let a: Address = text.parse().ok()?;
    Some((a.area.to_string().chars().next()?, u32::from(a.number)))
}

#[test]
fn every_function_instruction_has_a_script_that_checks_what_it_writes() {
    let mut checked = instructions_checked("sim");
    for (name, c) in instructions_checked("cnc") {
        *checked.entry(name).or_insert(false) |= c;
    }
    let missing: Vec<&str> = CATALOG
        .iter()
        .filter(|s| s.class == InstrClass::Function && !checked.contains_key(s.name))
        .map(|s| s.name)
        .collect();
    assert!(
        missing.is_empty(),
        "no script in tests/sim/ or tests/cnc/ runs {missing:?}: add a NAME.il using it and a \
         NAME.script whose expects fail when it does nothing (tests/sim/README.md)"
    );
    // Jumps, labels and calls write no operand: what they do shows in the instructions they
    // skip or run, which those scripts expect.
    let unchecked: Vec<&str> = CATALOG
        .iter()
        .filter(|s| s.class == InstrClass::Function && s.operands.iter().any(|o| o.may_write()))
        .filter(|s| checked.get(s.name) == Some(&false))
        .map(|s| s.name)
        .collect();
    assert!(
        unchecked.is_empty(),
        "the scripts running {unchecked:?} expect nothing that they write: add an `expect` of \
         an output operand's address"
    );
}
