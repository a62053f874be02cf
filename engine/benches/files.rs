//! Project-file and cross-reference benchmarks: `cargo bench -p ladder-engine --bench files`.
//!
//! Loads (verify + parse) and saves `projects/stress-5000.ldp`, and builds its
//! cross-reference, printing median times.

use ladder_engine::{file, xref};
use std::time::Instant;

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

fn main() {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/../projects/stress-5000.ldp");
    let bytes = std::fs::read(path).expect("projects/stress-5000.ldp exists");
    let project = file::from_bytes(&bytes).expect("the stress project loads");
    let dir = std::env::temp_dir().join(format!("ladder-bench-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let out = dir.join("stress.ldp");
    let (mut load, mut save, mut x) = (Vec::new(), Vec::new(), Vec::new());
    for _ in 0..30 {
        let t = Instant::now();
        let b = std::fs::read(path).unwrap();
        std::hint::black_box(file::from_bytes(&b).unwrap());
        load.push(t.elapsed().as_secs_f64() * 1e3);
        let t = Instant::now();
        file::save(&project, &out).unwrap();
        save.push(t.elapsed().as_secs_f64() * 1e3);
        let t = Instant::now();
        std::hint::black_box(xref::build(&project));
        x.push(t.elapsed().as_secs_f64() * 1e3);
    }
    let _ = std::fs::remove_dir_all(&dir);
    println!(
        "stress-5000.ldp ({} bytes): load+verify+parse median_ms={:.2}  save median_ms={:.2}  xref median_ms={:.3}",
        bytes.len(),
        median(load),
        median(save),
        median(x)
    );
}
