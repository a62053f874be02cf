//! Input-size benchmarks: `cargo bench -p ladder-engine --bench size`.
//!
//! The inputs that once grew with the square of their size, each timed as the commands run
//! them: the cross-reference index of a box with 17 000 operands, importing 70 000 `ORB`s,
//! 100 000 `AND`s without a `NETWORK` line, and a 1 MB unknown word. Each should take well
//! under half a second.

use ladder_engine::address::{Address, Area};
use ladder_engine::model::{Cell, Operand, Project};
use ladder_engine::{Op, il, xref};
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
}
