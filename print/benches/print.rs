//! Print benchmark: `cargo bench -p ladder-print --bench print`.
//!
//! Lays out and writes the PDF of `projects/stress-5000.ldp` (all blocks, A4 portrait) and
//! of the sample lathe project with every table and the cross-reference, printing median
//! times, page counts and sizes.

use ladder_engine::file;
use ladder_print::{Options, document, pdf};
use std::time::Instant;

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

fn time(name: &str, path: &str, options: &Options) {
    let project = file::load(std::path::Path::new(path)).expect("the project loads");
    let (mut layout, mut write) = (Vec::new(), Vec::new());
    let mut last = (0, 0);
    for _ in 0..5 {
        let t = Instant::now();
        let doc = document(&project, name, options);
        layout.push(t.elapsed().as_secs_f64() * 1e3);
        let t = Instant::now();
        let bytes = pdf(&doc).expect("the PDF is written");
        write.push(t.elapsed().as_secs_f64() * 1e3);
        last = (doc.pages.len(), bytes.len());
    }
    let (l, w) = (median(layout), median(write));
    println!(
        "{name}: pages={} bytes={} layout median_ms={l:.1} pdf median_ms={w:.1} total_ms={:.1}",
        last.0,
        last.1,
        l + w
    );
}

fn main() {
    let root = concat!(env!("CARGO_MANIFEST_DIR"), "/../projects/");
    time(
        "stress-5000",
        &format!("{root}stress-5000.ldp"),
        &Options::default(),
    );
    let all = Options {
        tables: true,
        xref: true,
        ..Options::default()
    };
    time(
        "lathe-988ta + tables + xref",
        &format!("{root}lathe-988ta.ldp"),
        &all,
    );
}
