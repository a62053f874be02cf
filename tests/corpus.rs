//! The IL corpus: valid programs compile clean and come back unchanged through the ladder;
//! every invalid line is reported with exactly the codes its marker names.

use ladder_engine::compiler::{Origin, compile};
use ladder_engine::il;
use ladder_tests::{corpus, read};
use std::collections::BTreeSet;

fn sequence(text: &str) -> Vec<String> {
    // The instruction lines alone, canonical, without directives or comments.
    let mut sink = ladder_engine::compiler::Sink::default();
    let program = il::parse(text, &mut sink);
    program
        .instrs()
        .map(|(_, _, i)| il::instr_text(i.op, &i.operands))
        .collect()
}

#[test]
fn valid_programs_compile_clean_and_round_trip() {
    for path in corpus("valid") {
        let text = read(&path);
        let name = path.file_name().unwrap().to_string_lossy().to_string();
        let imported = il::import(&text);
        let messages: Vec<String> = imported
            .compiled
            .diagnostics
            .iter()
            .map(|d| ladder_text::diagnostics::render(d, &name, ladder_text::Lang::En))
            .collect();
        assert!(messages.is_empty(), "{name}: {messages:#?}");
        let project = imported.project.unwrap_or_else(|| panic!("{name} draws"));
        let compiled = compile(&project);
        assert_eq!(compiled.errors() + compiled.warnings(), 0, "{name}");
        let exported = il::print(&compiled.program);
        if name.starts_with("loose-") {
            assert_eq!(sequence(&exported), sequence(&text), "{name}");
        } else {
            assert_eq!(exported, text, "{name}: IL → ladder → IL changed the text");
        }
        // And once more through the ladder: a fixed point.
        let again = il::import(&exported).project.expect("the export draws");
        assert_eq!(
            again.ladder, project.ladder,
            "{name}: ladder → IL → ladder changed"
        );
    }
}

/// The (line, code) pairs the `; <- CODE` markers of a file ask for.
fn expected(text: &str) -> BTreeSet<(u32, String)> {
    let mut set = BTreeSet::new();
    for (i, line) in text.lines().enumerate() {
        if let Some((_, codes)) = line.split_once("; <-") {
            for code in codes.split_whitespace() {
                set.insert((i as u32 + 1, code.to_string()));
            }
        }
    }
    set
}

#[test]
fn invalid_programs_report_exactly_the_marked_lines() {
    let mut codes_seen = BTreeSet::new();
    for path in corpus("invalid") {
        let text = read(&path);
        let name = path.file_name().unwrap().to_string_lossy().to_string();
        let imported = il::import(&text);
        let found: BTreeSet<(u32, String)> = imported
            .compiled
            .diagnostics
            .iter()
            .map(|d| match d.location.origin {
                Origin::Line(l) => (l, d.code.as_str().to_string()),
                other => panic!("{name}: an IL diagnostic without a line: {other:?}"),
            })
            .collect();
        let want = expected(&text);
        assert!(!want.is_empty(), "{name} has no markers");
        assert_eq!(found, want, "{name}: reported (left) vs marked (right)");
        codes_seen.extend(want.into_iter().map(|(_, c)| c));
    }
    // Every IL-level check has a case in the corpus.
    for code in [
        "L006", "L007", "L010", "L011", "L012", "L013", "L014", "L015", "L016", "L017", "L018",
        "L020", "L021", "L022", "L023", "L024", "L025", "L030", "L031", "L032", "L033", "L034",
        "L035", "L036", "L038", "W001", "W002", "W003", "W008",
    ] {
        assert!(codes_seen.contains(code), "no corpus case for {code}");
    }
}

#[test]
fn every_code_is_documented_with_an_example() {
    let doc = read(&ladder_tests::here().join("../docs/diagnostics.md"));
    for path in corpus("invalid") {
        for (_, code) in expected(&read(&path)) {
            assert!(
                doc.contains(&format!("| {code} |")),
                "{code} is missing from docs/diagnostics.md"
            );
        }
    }
}
