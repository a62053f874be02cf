//! The printed PDF read back: every network title and every address of a network are in
//! its text, in the language asked for, and networks are never cut when they fit a page.

use crate::common::pdf_pages;
use ladder_engine::model::{Cell, Operand, Project};
use ladder_print::{Labels, Options, Paper, PrintLang, document, pdf};

fn lathe() -> Project {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/../projects/lathe-988ta.ldp");
    ladder_engine::file::load(std::path::Path::new(path)).unwrap()
}

fn options(lang: PrintLang) -> Options {
    Options {
        lang,
        date: "2026-12-02".into(),
        ..Options::default()
    }
}

/// The addresses a network's elements name, as the editor's address view shows them.
fn addresses(project: &Project, block: usize, network: usize) -> Vec<String> {
    let mut out = Vec::new();
    for row in &project.ladder.blocks[block].networks[network].rows {
        for cell in &row.cells {
            let ops: Vec<&Operand> = match cell {
                Cell::Contact { operand, .. } | Cell::Coil { operand, .. } => vec![operand],
                Cell::Box { operands, .. } => operands.iter().collect(),
                _ => vec![],
            };
            for o in ops {
                match o {
                    Operand::Addr(a) => out.push(a.to_string()),
                    Operand::Symbol(s) => out.push(project.resolve_symbol(s).unwrap().to_string()),
                    _ => {}
                }
            }
        }
    }
    out
}

#[test]
fn the_pdf_holds_every_network_title_and_the_addresses_of_a_network() {
    let project = lathe();
    let doc = document(&project, "lathe-988ta", &options(PrintLang::Zh));
    let bytes = pdf(&doc).unwrap();
    assert!(bytes.starts_with(b"%PDF-"));
    let pages = pdf_pages(&bytes);
    assert_eq!(pages.len(), doc.pages.len());
    let all = pages.concat();
    for (b, block) in project.ladder.blocks.iter().enumerate() {
        for (n, net) in block.networks.iter().enumerate() {
            let title = format!("N{:04}  {}", n + 1, net.title);
            assert!(
                all.contains(title.trim_end()),
                "block {b}: {title} not printed"
            );
        }
    }
    // A sampled network: every address of its elements is on the page that holds it.
    let (b, n) = (1, 2);
    let title = format!("N{:04}", n + 1);
    let page = pages
        .iter()
        .find(|p| p.contains("第2级程序") && p.contains(&title))
        .expect("the network's page");
    let wanted = addresses(&project, b, n);
    assert!(!wanted.is_empty());
    for a in wanted {
        assert!(page.contains(&a), "{a} missing from\n{page}");
    }
    assert!(
        pages[0].contains("lathe-988ta") && pages[0].contains("控制器"),
        "{}",
        pages[0]
    );
    assert!(
        pages[1].contains(&format!("第 2/{} 页", pages.len())),
        "{}",
        pages[1]
    );
}

#[test]
fn english_and_both_languages_are_printed_when_asked() {
    let project = lathe();
    let en =
        pdf_pages(&pdf(&document(&project, "lathe", &options(PrintLang::En))).unwrap()).concat();
    assert!(
        en.contains("Level 1 program") && en.contains("Controller"),
        "{en}"
    );
    assert!(!en.contains("第1级程序"));
    let both =
        pdf_pages(&pdf(&document(&project, "lathe", &options(PrintLang::Both))).unwrap()).concat();
    assert!(both.contains("第1级程序 Level 1 program"), "{both}");
    // Element comments in both languages: a symbol row with zh and en comments.
    let s = project
        .symbols()
        .find(|s| s.comments.contains_key("zh") && s.comments.contains_key("en"))
        .unwrap();
    let zh = s.comments["zh"].lines().next().unwrap();
    assert!(
        both.contains(zh) || both.contains(&zh.chars().take(3).collect::<String>()),
        "{zh}"
    );
}

#[test]
fn symbols_are_printed_in_the_symbol_view() {
    let project = lathe();
    let opts = Options {
        labels: Labels::Symbol,
        ..options(PrintLang::En)
    };
    let text = pdf_pages(&pdf(&document(&project, "lathe", &opts)).unwrap()).concat();
    // A symbol on a contact of level 2: its name stands where the address would.
    let name = project.ladder.blocks[1]
        .networks
        .iter()
        .flat_map(|n| n.rows.iter().flat_map(|r| r.cells.iter()))
        .find_map(|c| match c {
            Cell::Contact {
                operand: Operand::Addr(a),
                ..
            } => project.symbol_of(*a),
            _ => None,
        })
        .expect("a contact with a symbol");
    assert!(text.contains(name), "{name}");
}

#[test]
fn the_page_count_grows_with_the_project_and_a_network_that_fits_is_never_cut() {
    let project = lathe();
    let one = document(&project, "lathe", &options(PrintLang::Zh));
    let mut bigger = project.clone();
    let extra = bigger.ladder.blocks[1].networks.clone();
    for mut n in extra {
        n.id = bigger.ladder.new_network_id();
        bigger.ladder.blocks[1].networks.push(n);
    }
    let two = document(&bigger, "lathe", &options(PrintLang::Zh));
    assert!(
        two.pages.len() > one.pages.len(),
        "{} → {}",
        one.pages.len(),
        two.pages.len()
    );
    for doc in [&one, &two] {
        for p in &doc.pages {
            assert!(!p.texts().any(|t| t.starts_with('▼')), "no network is cut");
        }
    }
    // Each network title is on exactly one page.
    for (n, net) in project.ladder.blocks[1].networks.iter().enumerate() {
        let title = format!("N{:04}  {}", n + 1, net.title);
        let on = one
            .pages
            .iter()
            .filter(|p| p.texts().any(|t| t == title.trim_end()))
            .count();
        assert_eq!(on, 1, "{title}");
    }
}

#[test]
fn a_network_taller_than_a_page_continues_with_a_marker() {
    let imported = ladder_engine::il::import(&{
        let mut t = String::from("LEVEL1\nNETWORK \"tall\"\n");
        for i in 0..120 {
            t.push_str(&format!(
                "LD X{:04}.{}\nOUT R{:04}.{}\n",
                i / 8,
                i % 8,
                i / 8,
                i % 8
            ));
        }
        t.push_str("LEVEL2\n");
        t
    });
    let project = imported.project.unwrap();
    let doc = document(&project, "tall", &options(PrintLang::En));
    let marked: Vec<usize> = (0..doc.pages.len())
        .filter(|i| {
            doc.pages[*i]
                .texts()
                .any(|t| t.contains("continued on the next page"))
        })
        .collect();
    assert!(!marked.is_empty(), "the network runs over");
    for i in marked {
        assert!(
            doc.pages[i + 1]
                .texts()
                .any(|t| t == "N0001  tall (continued)")
        );
    }
}

#[test]
fn landscape_a3_pages_are_wider_than_they_are_tall() {
    let opts = Options {
        paper: Paper::A3,
        landscape: true,
        ..options(PrintLang::En)
    };
    let doc = document(&lathe(), "lathe", &opts);
    assert!((doc.width - 1190.55).abs() < 0.1 && (doc.height - 841.89).abs() < 0.1);
}

#[test]
fn tables_and_the_cross_reference_are_printed_when_asked() {
    let project = lathe();
    let opts = Options {
        tables: true,
        xref: true,
        ..options(PrintLang::En)
    };
    let doc = document(&project, "lathe", &opts);
    let text = pdf_pages(&pdf(&doc).unwrap()).concat();
    for title in [
        "Symbol table",
        "D data table",
        "DT data table",
        "Display messages",
        "Cross-reference",
    ] {
        assert!(text.contains(title), "{title}");
    }
    let plain = document(&project, "lathe", &options(PrintLang::En));
    assert!(doc.pages.len() > plain.pages.len());
}

/// Writes the sample's first pages as SVG and the whole document as PDF, each a complete
/// file; with `PRINT_LOOK_DIR` set they stay in that folder for a look.
#[test]
fn the_bilingual_sample_writes_whole_svg_pages_and_a_pdf() {
    let project = lathe();
    let doc = document(
        &project,
        "lathe-988ta",
        &Options {
            labels: Labels::Both,
            ..options(PrintLang::Both)
        },
    );
    let temp = tempfile::tempdir().unwrap();
    let dir = std::env::var_os("PRINT_LOOK_DIR").map_or(temp.path().to_path_buf(), Into::into);
    for (i, p) in doc.pages.iter().enumerate().take(6) {
        let svg = ladder_print::page_svg(&doc, p);
        assert!(svg.starts_with("<svg") && svg.trim_end().ends_with("</svg>"));
        assert!(svg.contains("<text"), "page {} has text", i + 1);
        std::fs::write(dir.join(format!("page-{}.svg", i + 1)), svg).unwrap();
    }
    let bytes = pdf(&doc).unwrap();
    assert!(bytes.starts_with(b"%PDF-"));
    assert!(bytes.trim_ascii_end().ends_with(b"%%EOF"));
    std::fs::write(dir.join("lathe.pdf"), bytes).unwrap();
}
