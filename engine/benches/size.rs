//! Input-size benchmarks: `cargo bench -p ladder-engine --bench size`.
//!
//! The inputs that once grew with the square of their size, each timed as the commands run
//! them: the cross-reference index of a box with 17 000 operands, importing 70 000 `ORB`s,
//! 100 000 `AND`s without a `NETWORK` line, a 1 MB unknown word, 70 000 `LD`s closed by as
//! many `ORB`s, a project whose title holds a million escapes, and a network 5 000 rows tall
//! drawn with vertical links. Each should take well under half a second.

use ladder_engine::address::{Address, Area};
use ladder_engine::model::{Cell, Operand, Project};
use ladder_engine::{Op, compiler, file, il, xref};
use std::time::Instant;

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

/// Runs `f` a few times and prints its median in milliseconds.
fn time(name: &str, runs: usize, mut f: impl FnMut()) {
    let v = (0..runs)
        .map(|_| {
            let t = Instant::now();
            f();
            t.elapsed().as_secs_f64() * 1e3
        })
        .collect();
    println!("{name:<48} median_ms={:.1}", median(v));
}

fn main() {
    let mut project = Project::default();
    let mut network = project.ladder.new_network();
    let width = project.ladder.width;
    network.rows[0].cells[width] = Cell::Box {
        op: Op::Move,
        operands: (0..17_000)
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
    time("xref index, one box of 17 000 operands", 5, || {
        let x = xref::build(&project);
        std::hint::black_box(xref::index_text(&project, &x));
    });

    let mut orbs = String::from("LEVEL1\nNETWORK\nLD X0000.0\n");
    for i in 1..70_000 {
        orbs.push_str(&format!("LD X{:04}.{}\nORB\n", i % 100, i % 8));
    }
    orbs.push_str("OUT R0000.0\nLEVEL2\n");
    time("import-il, 70 000 LD + ORB", 5, || {
        std::hint::black_box(il::import(&orbs));
    });

    let mut ands = String::from("LEVEL1\nLD X0000.0\n");
    for i in 0..100_000 {
        ands.push_str(&format!("AND X{:04}.{}\n", i % 100, i % 8));
    }
    ands.push_str("OUT R0000.0\nLEVEL2\n");
    time("import-il, 100 000 AND without NETWORK", 5, || {
        std::hint::black_box(il::import(&ands));
    });

    let word = format!("LEVEL1\nNETWORK\n{} X0000.0\nLEVEL2\n", "Q".repeat(1 << 20));
    time("import-il, a 1 MB unknown word", 5, || {
        std::hint::black_box(il::import(&word));
    });

    let mut stacked = String::from("LEVEL1\nNETWORK\n");
    for i in 0..70_000 {
        stacked.push_str(&format!("LD X{:04}.{}\n", i % 100, i % 8));
    }
    stacked.push_str(&"ORB\n".repeat(69_999));
    stacked.push_str("OUT R0000.0\nLEVEL2\n");
    time("import-il + check, 70 000 LD then 69 999 ORB", 3, || {
        let project = il::import(&stacked).project.unwrap();
        std::hint::black_box(compiler::compile(&project));
    });

    let mut titled = Project::default();
    let mut network = titled.ladder.new_network();
    network.title = "\n".repeat(1_000_000);
    network.comment = (0..20_000).map(|i| format!("line \"{i}\"\n")).collect();
    titled.ladder.blocks[0].networks.push(network);
    let saved = file::to_string(&titled);
    time("open, a title of a million escapes", 5, || {
        std::hint::black_box(file::from_bytes(saved.as_bytes()).unwrap());
    });

    let x = |i: usize| format!("X{:04}.{}", i / 8 % 128, i % 8);
    let mut tall = String::from("LEVEL1\nLEVEL2\nNETWORK\n");
    for g in 0..2_500 {
        tall.push_str(&format!(
            "LD {}\nAND {}\nLD {}\nOR {}\nANB\n",
            x(g),
            x(g + 1),
            x(g + 2),
            x(g + 3)
        ));
        if g > 0 {
            tall.push_str("ORB\n");
        }
    }
    for o in 0..5_000 {
        let stack = ["MRD", "MPS", "MPP"][usize::from(o == 0) + 2 * usize::from(o == 4_999)];
        tall.push_str(&format!(
            "{stack}\nANI {}\nOUT R{:04}.{}\n",
            x(o),
            100 + o / 8,
            o % 8
        ));
    }
    let tall = il::import(&tall).project.unwrap();
    time("check, a network 5 000 rows tall with links", 5, || {
        std::hint::black_box(compiler::compile(&tall));
    });
}
