//! Large inputs stay linear (docs/files.md, "Input size"): what each command makes of a huge
//! box, a long ORB chain, a list without NETWORK lines or a line-long unknown word is bounded
//! by the input, never by its square. The times are measured by `cargo bench --bench size`;
//! these tests check the shapes that made them quadratic, and count the memory asked for at
//! two sizes where a shape alone would pass a quadratic build.

// The one exception to the workspace's rule: a counting global allocator needs `unsafe impl`.
#![allow(unsafe_code)]

use ladder_engine::address::{Address, Area};
use ladder_engine::compiler::{Code, Diagnostic, Finding, IlFinding};
use ladder_engine::file;
use ladder_engine::model::{Cell, Operand, Project};
use ladder_engine::{Op, il, xref};
use std::alloc::{GlobalAlloc, Layout, System};
use std::cell::Cell as Counter;

/// The system allocator, counting the bytes each thread asks for: a work that copies a growing
/// list at every step asks for the square of its input, which no clock on a shared machine
/// tells as surely.
struct Counting;

thread_local! {
    static ASKED: Counter<u64> = const { Counter::new(0) };
}

// SAFETY: every call is handed to the system allocator unchanged; counting touches only a
// thread-local integer, which allocates nothing.
unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        let _ = ASKED.try_with(|c| c.set(c.get() + layout.size() as u64));
        unsafe { System.alloc(layout) }
    }
    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        unsafe { System.dealloc(ptr, layout) }
    }
    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        let _ = ASKED.try_with(|c| c.set(c.get() + new_size as u64));
        unsafe { System.realloc(ptr, layout, new_size) }
    }
}

#[global_allocator]
static ALLOCATOR: Counting = Counting;

/// The bytes asked of the allocator by `work` on this thread.
fn bytes_asked(work: impl FnOnce()) -> u64 {
    let before = ASKED.with(Counter::get);
    work();
    ASKED.with(Counter::get) - before
}

/// Asserts that `work` on an input twice as large asks for about twice the memory, not four
/// times: linear, not quadratic.
fn asks_linearly(what: &str, n: usize, work: impl Fn(usize)) {
    let small = bytes_asked(|| work(n));
    let large = bytes_asked(|| work(2 * n));
    let ratio = large as f64 / small as f64;
    assert!(
        ratio < 2.8,
        "{what}: {small} bytes for {n}, {large} for {}: ×{ratio:.2}, quadratic",
        2 * n
    );
}

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

/// `n` loads then `n − 1` ORBs: the stack is `n` deep and each ORB joins one contact in
/// front of the parallel block built so far.
fn stacked_orbs(n: usize) -> String {
    let mut text = String::from("LEVEL1\nNETWORK\n");
    for i in 0..n {
        text.push_str(&format!("LD X{:04}.{}\n", i % 100, i % 8));
    }
    text.push_str(&"ORB\n".repeat(n - 1));
    text.push_str("OUT R0000.0\nLEVEL2\n");
    text
}

#[test]
fn seventy_thousand_loads_closed_by_as_many_orbs_are_one_parallel_block() {
    // Each ORB once copied the growing block to put one contact in front of it: 70 000 took
    // minutes. Joined at the front of a deque, the whole import is linear.
    let n = 70_000;
    let imported = il::import(&stacked_orbs(n));
    let project = imported.project.expect("the block is drawn");
    let network = &project.ladder.blocks[0].networks[0];
    assert_eq!(network.rows.len(), n, "one row per contact");
    let first = |r: usize| match &network.rows[r].cells[0] {
        Cell::Contact { operand, .. } => operand.to_string(),
        other => panic!("row {r} starts with {other:?}"),
    };
    assert_eq!(
        (first(0), first(1), first(n - 1)),
        (
            "X0000.0".into(),
            "X0001.1".into(),
            format!("X{:04}.{}", (n - 1) % 100, (n - 1) % 8)
        ),
        "the contacts stay in the order they were loaded"
    );
    // The drawing compiles to the list as written: the loads, then the ORBs.
    let listed = il::print(&ladder_engine::compiler::compile(&project).program);
    let orbs = listed.lines().filter(|l| l.trim() == "ORB").count();
    assert_eq!(orbs, n - 1);
    let lines: Vec<&str> = listed.lines().collect();
    let first_orb = lines.iter().position(|l| l.trim() == "ORB").unwrap();
    let last_ld = lines.iter().rposition(|l| l.starts_with("LD ")).unwrap();
    assert!(last_ld < first_orb, "every LD comes before the first ORB");
}

#[test]
fn loads_closed_by_orbs_cost_memory_linear_in_their_number() {
    asks_linearly("import + compile of n LD, n − 1 ORB", 5_000, |n| {
        let project = il::import(&stacked_orbs(n)).project.unwrap();
        std::hint::black_box(ladder_engine::compiler::compile(&project));
    });
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
    // The finding holds the word already cut, so neither language repeats a megabyte.
    let Finding::Il(IlFinding::UnknownInstruction { word, meant }) = &d.finding else {
        panic!("{d:?}");
    };
    assert_eq!((word.chars().count(), *meant), (41, None));
    assert!(word.ends_with("QQQQ…"), "{word}");
    let en = ladder_text::diagnostics::message(d, ladder_text::Lang::En);
    let zh = ladder_text::diagnostics::message(d, ladder_text::Lang::Zh);
    assert!(en.len() < 200, "{} bytes", en.len());
    assert!(en.contains("QQQQ…"), "{en}");
    assert!(zh.len() < 300, "{} bytes", zh.len());
}

#[test]
fn a_typo_still_gets_its_suggestion() {
    let imported = il::import("LEVEL1\nNETWORK\nLD X0000.0\nOUTT R0000.0\nLEVEL2\n");
    let en = |d| ladder_text::diagnostics::message(d, ladder_text::Lang::En);
    let meant = |d: &Diagnostic| match &d.finding {
        Finding::Il(IlFinding::UnknownInstruction { meant, .. }) => *meant,
        other => panic!("{other:?}"),
    };
    let first = &imported.compiled.diagnostics[0];
    assert_eq!(meant(first), Some(Op::Out));
    let d = en(first);
    assert!(d.contains("did you mean OUT?"), "{d}");
    let imported = il::import("LEVEL1\nNETWORK\nLD X0000.0\nTMRBB T0000 DT0000 R0000.0\n");
    let first = &imported.compiled.diagnostics[0];
    assert_eq!(meant(first), Some(Op::Tmrb));
    let d = en(first);
    assert!(d.contains("did you mean TMRB?"), "{d}");
}

/// An instruction list of one network `n` rows tall once drawn: `n / 2` two-row parallel
/// groups joined by ORB, in series with `n` outputs branching off one MPS, so the drawing has
/// vertical links all the way down on both sides.
fn tall_network(n: usize) -> String {
    let x = |i: usize| format!("X{:04}.{}", i / 8 % 128, i % 8);
    let mut text = String::from("LEVEL1\nLEVEL2\nNETWORK \"tall\"\n");
    for g in 0..n / 2 {
        text.push_str(&format!(
            "LD {}\nAND {}\nLD {}\nOR {}\nANB\n",
            x(g),
            x(g + 1),
            x(g + 2),
            x(g + 3)
        ));
        if g > 0 {
            text.push_str("ORB\n");
        }
    }
    let outputs = n;
    for o in 0..outputs {
        let stack = match o {
            0 => "MPS",
            _ if o + 1 == outputs => "MPP",
            _ => "MRD",
        };
        text.push_str(&format!(
            "{stack}\nANI {}\nOUT R{:04}.{}\n",
            x(o),
            100 + o / 8,
            o % 8
        ));
    }
    text.push_str("END\n");
    text
}

#[test]
fn a_network_of_thousands_of_linked_rows_is_checked_saved_and_indexed_in_linear_memory() {
    asks_linearly(
        "import, compile, save, open and index a tall network",
        2_500,
        |n| {
            let imported = il::import(&tall_network(n));
            let project = imported.project.expect("the network is drawn");
            let network = &project.ladder.blocks[1].networks[0];
            assert!(
                network.rows.len() >= n,
                "{} rows for {n}",
                network.rows.len()
            );
            assert!(
                network
                    .rows
                    .iter()
                    .filter(|r| r.links.contains(&true))
                    .count()
                    >= n - 2
            );
            let compiled = ladder_engine::compiler::compile(&project);
            assert!(compiled.steps.level2 as usize > 5 * n, "every row compiles");
            assert_eq!(compiled.errors(), 1, "only the program's size is wrong");
            let text = file::to_string(&project);
            let opened = file::from_bytes(text.as_bytes()).expect("the saved network opens");
            assert_eq!(opened.ladder.blocks[1].networks[0], *network);
            std::hint::black_box(xref::index_text(&project, &xref::build(&project)));
        },
    );
}

#[test]
fn a_title_of_a_million_escaped_newlines_opens_as_written() {
    // The file reader once scanned the rest of a string at each escape in it: a 2 MB title
    // took half a minute to open (`cargo bench --bench size` times it now).
    let mut project = Project::default();
    let mut network = project.ladder.new_network();
    network.title = "\n".repeat(1_000_000);
    network.comment = (0..20_000).map(|i| format!("line \"{i}\"\n")).collect();
    project.ladder.blocks[0].networks.push(network);
    let saved = file::to_string(&project);
    assert!(
        saved.len() > 2_000_000,
        "each newline is written as an escape"
    );
    let opened = file::from_bytes(saved.as_bytes()).expect("the project opens");
    assert_eq!(opened, project);
}
