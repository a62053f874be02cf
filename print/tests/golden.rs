//! One network drawn as SVG, compared with the drawing kept in `tests/golden/`: a change to
//! how contacts, coils, boxes, links or labels are drawn shows up here as a diff to review.
//! After an intended change: `UPDATE_GOLDEN=1 cargo test -p ladder-print --test print golden::`.

use ladder_print::{Labels, Options, PrintLang, document, page_svg};

const LIST: &str = "\
LEVEL1
NETWORK \"Motor start/stop (self-holding)\"
LD   X0002.1
OR   Y0003.7
ANI  X0002.2
MPS
OUT  Y0003.7
MPP
TMRB T0000 2000 Y0004.0
LEVEL2
";

#[test]
fn a_network_draws_as_its_golden_svg() {
    let mut project = ladder_engine::il::import(LIST)
        .project
        .expect("the list draws");
    project.symbol_tables[0]
        .rows
        .push(ladder_engine::model::tables::Symbol {
            name: "START".into(),
            address: ladder_engine::Address::parse("X0002.1").unwrap(),
            comments: [("en".to_string(), "Start button".to_string())].into(),
        });
    let options = Options {
        lang: PrintLang::En,
        labels: Labels::Both,
        title_page: false,
        only: Some(vec![(0, 0)]),
        date: "2026-12-02".into(),
        ..Options::default()
    };
    let doc = document(&project, "start-stop", &options);
    assert_eq!(doc.pages.len(), 1);
    let svg = page_svg(&doc, &doc.pages[0]);
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/golden/start-stop.svg");
    if std::env::var_os("UPDATE_GOLDEN").is_some() {
        std::fs::write(path, &svg).unwrap();
    }
    let golden = std::fs::read_to_string(path).expect("the golden drawing exists");
    if svg != golden {
        let first = svg
            .lines()
            .zip(golden.lines())
            .position(|(a, b)| a != b)
            .unwrap_or(svg.lines().count().min(golden.lines().count()));
        panic!(
            "line {} differs:\n  drawn:  {}\n  golden: {}",
            first + 1,
            svg.lines().nth(first).unwrap_or("(end)"),
            golden.lines().nth(first).unwrap_or("(end)")
        );
    }
    // What the drawing must hold, whatever its coordinates.
    for text in [
        ">N0001  Motor start/stop (self-holding)<",
        ">X0002.1<",
        ">START<",
        ">Start button<",
        ">TMRB<",
        ">Page 1/1<",
    ] {
        assert!(svg.contains(text), "{text}");
    }
}
