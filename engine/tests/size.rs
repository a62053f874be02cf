//! Large inputs stay linear (docs/files.md, "Input size"): what each command makes of a huge
//! box, a long ORB chain, a list without NETWORK lines or a line-long unknown word is bounded
//! by the input, never by its square. The times are measured by `cargo bench --bench size`;
//! these tests check the shapes that made them quadratic.

use ladder_engine::address::{Address, Area};
use ladder_engine::compiler::Code;
use ladder_engine::model::{Cell, Operand, Project};
use ladder_engine::{Op, il, xref};

/// A project whose first network ends in one box of `n` byte operands.
fn big_box(n: usize) -> Project {
    let mut project = Project::default();
    let mut network = project.ladder.new_network();
    let width = project.ladder.width;
    network.rows[0].cells[width] = Cell::Box {
        op: Op::Move,
        operands: (0..n)
            .map(|i| {
                Operand::Addr(Address {
                    area: Area::R,
                    number: (i % 1000) as u16,
                    bit: None,
                })
            })
            .collect(),
    };
    project.ladder.blocks[0].networks.push(network);
    project
}

#[test]
fn the_index_of_a_huge_box_grows_with_its_references_not_their_square() {
    let n = 17_000;
    let project = big_box(n);
    let x = xref::build(&project);
    assert_eq!(x.refs.len(), n, "every operand is a reference");
    let text = xref::index_text(&project, &x);
    // Each line names the box and its first operands only: a full operand list on each of
    // the 17 000 lines would be 17 000 × 17 000 operands.
    let longest = text.lines().map(str::len).max().unwrap();
    assert!(longest < 200, "a line of {longest} bytes");
    let line = text.lines().nth(1).unwrap();
    assert!(line.contains("MOVE") && line.contains("(+16992)"), "{line}");
}

#[test]
fn a_short_box_is_shown_whole_in_the_index() {
    let project = big_box(3);
    let x = xref::build(&project);
    let text = xref::index_text(&project, &x);
    assert!(
        text.lines()
            .nth(1)
            .unwrap()
            .ends_with("MOVE R0000 R0001 R0002"),
        "{text}"
    );
}

#[test]
fn a_chain_of_seventy_thousand_orbs_is_drawn_without_running_out_of_stack() {
    let n = 70_000;
    let mut text = String::from("LEVEL1\nNETWORK\nLD X0000.0\n");
    for i in 1..n {
        text.push_str(&format!("LD X{:04}.{}\nORB\n", i % 100, i % 8));
    }
    text.push_str("OUT R0000.0\nLEVEL2\n");
    // The test thread's stack is small (2 MiB): recursion as deep as the chain would abort.
    let imported = il::import(&text);
    let project = imported.project.expect("the chain is drawn");
    let network = &project.ladder.blocks[0].networks[0];
    assert_eq!(network.rows.len(), n, "one row per contact");
    let listed = il::print(&ladder_engine::compiler::compile(&project).program);
    assert_eq!(listed.matches("ORB").count(), n - 1);
}

#[test]
fn a_hundred_thousand_ands_without_network_lines_are_one_network() {
    let mut text = String::from("LEVEL1\nLD X0000.0\n");
    for i in 0..100_000 {
        text.push_str(&format!("AND X{:04}.{}\n", i % 100, i % 8));
    }
    text.push_str("OUT R0000.0\nLD X0001.0\nOUT R0000.1\nLEVEL2\n");
    let mut sink = ladder_engine::compiler::Sink::default();
    let program = il::parse(&text, &mut sink);
    let sizes: Vec<usize> = program.blocks[0]
        .networks
        .iter()
        .map(|n| n.instrs.len())
        .collect();
    assert_eq!(sizes, vec![100_002, 2], "split at the second LD only");
}

#[test]
fn an_mps_left_open_keeps_the_next_ld_in_its_network() {
    let text = "LEVEL1\nLD X0000.0\nMPS\nOUT R0000.0\nMPP\nOUT R0000.1\nLD X0000.1\n\
                MPS\nOUT R0000.2\nLD X0000.2\nANB\nMPP\nOUT R0000.3\nLEVEL2\n";
    let mut sink = ladder_engine::compiler::Sink::default();
    let program = il::parse(text, &mut sink);
    let sizes: Vec<usize> = program.blocks[0]
        .networks
        .iter()
        .map(|n| n.instrs.len())
        .collect();
    assert_eq!(sizes, vec![5, 7], "the LD under the open MPS stays");
}

#[test]
fn a_line_long_unknown_word_gets_a_short_message() {
    let word = "Q".repeat(1 << 20);
    let text = format!("LEVEL1\nNETWORK\n{word} X0000.0\nLEVEL2\n");
    let imported = il::import(&text);
    let d = imported
        .compiled
        .diagnostics
        .iter()
        .find(|d| d.code == Code::L010UnknownInstruction)
        .expect("the word is refused");
    assert!(d.message.len() < 200, "{} bytes", d.message.len());
    assert!(d.message.contains("QQQQ…"), "{}", d.message);
    assert!(d.message_zh.len() < 300, "{} bytes", d.message_zh.len());
}

#[test]
fn a_typo_still_gets_its_suggestion() {
    let imported = il::import("LEVEL1\nNETWORK\nLD X0000.0\nOUTT R0000.0\nLEVEL2\n");
    let d = &imported.compiled.diagnostics[0];
    assert!(d.message.contains("did you mean OUT?"), "{}", d.message);
    let imported = il::import("LEVEL1\nNETWORK\nLD X0000.0\nTMRBB T0000 DT0000 R0000.0\n");
    let d = &imported.compiled.diagnostics[0];
    assert!(d.message.contains("did you mean TMRB?"), "{}", d.message);
}
