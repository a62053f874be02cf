//! The bundled sample projects: clean, fully commented, and behaving like a lathe.

use ladder_engine::address::Area;
use ladder_engine::compiler::compile;
use ladder_engine::{file, xref};
use ladder_tests::{here, run};

fn lathe() -> ladder_engine::model::Project {
    file::load(&here().join("../projects/lathe-988ta.ldp")).expect("the sample loads")
}

#[test]
fn the_lathe_sample_compiles_clean_with_over_300_steps() {
    let p = lathe();
    let c = compile(&p);
    let d: Vec<String> = c.diagnostics.iter().map(|d| d.render("lathe")).collect();
    assert!(d.is_empty(), "{d:#?}");
    assert!(c.steps.total >= 300, "{} steps", c.steps.total);
    assert!(c.steps.level1 < 600);
    assert!(
        p.ladder.blocks.len() >= 4,
        "level 1, level 2 and at least two subprograms"
    );
}

#[test]
fn every_address_of_the_lathe_has_a_symbol_with_both_comments() {
    let p = lathe();
    let x = xref::build(&p);
    for r in &x.refs {
        if matches!(r.address.area, Area::L | Area::P) {
            continue;
        }
        let s = p
            .symbols()
            .find(|s| s.address == r.address)
            .unwrap_or_else(|| panic!("{} has no symbol row", r.address));
        assert!(!s.name.is_empty(), "{} has no symbol name", r.address);
        for lang in ["zh", "en"] {
            assert!(
                s.comments.get(lang).is_some_and(|c| !c.is_empty()),
                "{} ({}) has no {lang} comment",
                r.address,
                s.name
            );
        }
    }
    assert!(
        p.messages
            .rows
            .iter()
            .filter(|m| m.number.is_some())
            .count()
            >= 3
    );
    assert!(!p.data.dt.is_empty() && !p.data.k.is_empty());
}

#[test]
fn the_lathe_scripts_pass_against_the_project() {
    let ldp = here().join("../projects/lathe-988ta.ldp");
    let mut scripts: Vec<_> = std::fs::read_dir(here().join("lathe"))
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|x| x == "script"))
        .collect();
    scripts.sort();
    assert!(scripts.len() >= 7);
    for s in scripts {
        let r = run(&[
            "sim",
            ldp.to_str().unwrap(),
            "--script",
            s.to_str().unwrap(),
        ]);
        let last = r.stdout.lines().last().unwrap_or("");
        assert!(
            r.code == 0 && last.ends_with(" passed, 0 failed"),
            "{}:\n{}{}",
            s.display(),
            r.stdout,
            r.stderr
        );
    }
}

#[test]
fn every_bundled_project_checks_clean() {
    for name in ["lathe-988ta.ldp", "start-stop.ldp", "stress-5000.ldp"] {
        let path = here().join("../projects").join(name);
        let r = run(&["check", path.to_str().unwrap()]);
        assert_eq!(
            (r.code, r.stdout.as_str()),
            (0, "0 errors, 0 warnings\n"),
            "{name}"
        );
    }
}
