//! Compiler benchmark: compiles a generated 5000-step program and prints the time.
//!
//! Run with `cargo bench -p ladder-engine --bench compile`.

use ladder_engine::compiler::compile;
use ladder_engine::generate::{Mix, program_il};
use ladder_engine::il;
use std::time::Instant;

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

fn main() {
    let text = program_il(5000, Mix::Mixed, 1);
    let project = il::import(&text)
        .project
        .expect("the generated program draws as a ladder");
    let first = compile(&project);
    assert_eq!(first.errors(), 0, "the generated program compiles clean");
    let mut times = Vec::new();
    for _ in 0..50 {
        let t = Instant::now();
        let c = compile(&project);
        times.push(t.elapsed().as_secs_f64() * 1e3);
        std::hint::black_box(c);
    }
    let networks: usize = project.ladder.blocks.iter().map(|b| b.networks.len()).sum();
    println!(
        "compile: steps={} networks={} median_ms={:.3} min_ms={:.3}",
        first.steps.total,
        networks,
        median(times.clone()),
        times.iter().copied().fold(f64::INFINITY, f64::min)
    );
    let mut import_times = Vec::new();
    for _ in 0..20 {
        let t = Instant::now();
        std::hint::black_box(il::import(&text));
        import_times.push(t.elapsed().as_secs_f64() * 1e3);
    }
    println!("import-il: median_ms={:.3}", median(import_times));
}
