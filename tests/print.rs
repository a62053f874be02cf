//! `ladder-studio print`: the sample project as a PDF and as SVG pages, and bad requests
//! refused with a message and exit 2 (docs/printing.md).

use ladder_tests::run;

fn sample_path() -> String {
    sample()
}

fn sample() -> String {
    ladder_tests::here()
        .join("../projects/lathe-988ta.ldp")
        .display()
        .to_string()
}

#[test]
fn the_sample_prints_as_a_pdf_whose_pages_grow_with_what_is_asked() {
    let dir = tempfile::tempdir().unwrap();
    let plain = dir.path().join("plain.pdf");
    let r = run(&[
        "print",
        &sample(),
        "-o",
        plain.to_str().unwrap(),
        "--date",
        "2026-12-02",
    ]);
    assert_eq!(r.code, 0, "{r:?}");
    let full = dir.path().join("full.pdf");
    let r2 = run(&[
        "print",
        &sample(),
        "-o",
        full.to_str().unwrap(),
        "--tables",
        "--xref",
        "--paper",
        "a3",
        "--landscape",
        "--language",
        "both",
        "--operands",
        "both",
    ]);
    assert_eq!(r2.code, 0, "{r2:?}");
    let pages = |p: &std::path::Path| {
        let bytes = std::fs::read(p).unwrap();
        lopdf::Document::load_mem(&bytes)
            .expect("a valid PDF")
            .get_pages()
            .len()
    };
    let (a, b) = (pages(&plain), pages(&full));
    assert!(a > 3, "{a}");
    assert!(r.stdout.contains(&format!("{a} pages")), "{}", r.stdout);
    assert!(
        b > a / 2,
        "A3 landscape with the tables: {b} pages against {a}"
    );
    let blocks = dir.path().join("level1.pdf");
    let r = run(&[
        "print",
        &sample(),
        "-o",
        blocks.to_str().unwrap(),
        "--blocks",
        "level1",
    ]);
    assert_eq!(r.code, 0, "{r:?}");
    assert!(pages(&blocks) < a, "level 1 alone is shorter");
}

#[test]
fn svg_pages_are_one_file_each_and_one_network_is_one_page() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("lathe.svg");
    let r = run(&[
        "print",
        &sample(),
        "-o",
        out.to_str().unwrap(),
        "--blocks",
        "level1",
    ]);
    assert_eq!(r.code, 0, "{r:?}");
    let files: Vec<&str> = r.stdout.lines().collect();
    assert!(files.len() >= 2, "{files:?}");
    assert!(files[0].ends_with("lathe-1.svg"), "{files:?}");
    let first = std::fs::read_to_string(dir.path().join("lathe-1.svg")).unwrap();
    assert!(first.starts_with("<svg xmlns=\"http://www.w3.org/2000/svg\""));
    let one = dir.path().join("net.svg");
    let r = run(&[
        "print",
        &sample(),
        "-o",
        one.to_str().unwrap(),
        "--network",
        "LEVEL2:1",
        "--language",
        "en",
    ]);
    assert_eq!(r.code, 0, "{r:?}");
    let svg = std::fs::read_to_string(&one).unwrap();
    assert!(svg.contains(">N0001  "), "the network's title");
    assert!(
        svg.contains("LEVEL2  Level 2 program"),
        "its block in the header"
    );
    assert!(!svg.contains(">N0002"), "no other network");
}

#[test]
fn bad_requests_are_refused_with_a_message() {
    let dir = tempfile::tempdir().unwrap();
    let sample = sample();
    let ok = dir.path().join("x.pdf");
    let ok = ok.to_str().unwrap();
    let cases: Vec<(Vec<&str>, &str)> = vec![
        (
            vec!["print", &sample, "-o", "/no/such/folder/x.pdf"],
            "cannot write /no/such/folder/x.pdf",
        ),
        (
            vec!["print", &sample, "-o", ok, "--paper", "b5"],
            "possible values: a4, a3, letter",
        ),
        (vec!["print", &sample, "-o", ok, "--colour"], "--colour"),
        (
            vec!["print", &sample, "-o", "x.docx"],
            "the output is a .pdf or a .svg file",
        ),
        (
            vec!["print", &sample, "-o", ok, "--network", "LEVEL2:99"],
            "LEVEL2 has networks 1 to",
        ),
        (
            vec!["print", &sample, "-o", ok, "--network", "3"],
            "write the network as BLOCK:N",
        ),
        (
            vec!["print", &sample, "-o", ok, "--page", "999"],
            "--page 999: the document has pages 1 to",
        ),
        (
            vec!["print", &sample, "-o", ok, "--date", "2.12.2026"],
            "write the date as YYYY-MM-DD",
        ),
        (vec!["print", "no-such.ldp", "-o", ok], "no-such.ldp"),
        (
            vec!["print", &sample, "-o", ok, "--networks", "LEVEL2:9-3"],
            "write N or FIRST-LAST",
        ),
        (
            vec![
                "print",
                &sample,
                "-o",
                ok,
                "--network",
                "LEVEL1:1",
                "--blocks",
                "level2",
            ],
            "not among the --blocks printed",
        ),
    ];
    for (args, says) in cases {
        let r = run(&args);
        assert_eq!(r.code, 2, "{args:?}: {r:?}");
        assert!(r.stderr.contains(says), "{args:?}: {}", r.stderr);
    }
    assert!(!dir.path().join("x.pdf").exists(), "nothing written");
    let leftovers = std::fs::read_dir(dir.path()).unwrap().count();
    assert_eq!(leftovers, 0, "no temporary file left");
}

#[test]
fn an_instruction_list_prints_through_its_drawing() {
    let dir = tempfile::tempdir().unwrap();
    let il = ladder_tests::here().join("../projects/start-stop.il");
    let out = dir.path().join("start-stop.pdf");
    let r = run(&["print", il.to_str().unwrap(), "-o", out.to_str().unwrap()]);
    assert_eq!(r.code, 0, "{r:?}");
    assert!(std::fs::read(&out).unwrap().starts_with(b"%PDF-"));
}

#[test]
fn a_range_of_networks_prints_those_networks_only() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("range.svg");
    let r = run(&[
        "print",
        &sample(),
        "-o",
        out.to_str().unwrap(),
        "--networks",
        "LEVEL2:3-5",
        "--language",
        "en",
    ]);
    assert_eq!(r.code, 0, "{r:?}");
    let text: String = r
        .stdout
        .lines()
        .map(|f| std::fs::read_to_string(f).unwrap())
        .collect();
    for n in ["N0003", "N0004", "N0005"] {
        assert!(text.contains(&format!(">{n}  ")), "{n} printed");
    }
    for n in ["N0002", "N0006"] {
        assert!(!text.contains(&format!(">{n}")), "{n} not printed");
    }
}

#[test]
fn a_shorter_svg_print_removes_the_stale_pages_of_a_longer_one() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("doc.svg");
    let print = |extra: &[&str]| {
        let mut args = vec!["print", &sample_path(), "-o", out.to_str().unwrap()]
            .into_iter()
            .map(String::from)
            .collect::<Vec<_>>();
        args.extend(extra.iter().map(|s| s.to_string()));
        let r = run(&args.iter().map(String::as_str).collect::<Vec<_>>());
        assert_eq!(r.code, 0, "{r:?}");
        r.stdout.lines().count()
    };
    let long = print(&[]);
    assert!(long > 3);
    assert!(dir.path().join(format!("doc-{long}.svg")).exists());
    let short = print(&["--blocks", "level1"]);
    assert!(short < long);
    let files = std::fs::read_dir(dir.path()).unwrap().count();
    assert_eq!(files, short, "only the new document's pages are left");
    // One page is OUT.svg itself: every numbered page goes.
    print(&["--network", "LEVEL2:1"]);
    let files: Vec<_> = std::fs::read_dir(dir.path())
        .unwrap()
        .map(|e| e.unwrap().file_name())
        .collect();
    assert_eq!(files, ["doc.svg"]);
}

#[test]
fn a_killed_print_leaves_no_temporary_file_for_ever() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("doc.pdf");
    // What a print killed while writing leaves: its temporary file, named for its process.
    let left = dir.path().join(".doc.pdf.4000000000.tmp");
    std::fs::write(&left, b"%PDF-1.7 half").unwrap();
    let r = run(&["print", &sample(), "-o", out.to_str().unwrap()]);
    assert_eq!(r.code, 0, "{r:?}");
    assert!(!left.exists(), "the next print of that name removed it");
    assert!(out.exists());
}

#[test]
fn the_cross_reference_names_each_address_once_then_its_uses() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("x.svg");
    let r = run(&[
        "print",
        &sample(),
        "-o",
        out.to_str().unwrap(),
        "--xref",
        "--blocks",
        "level1",
        "--language",
        "en",
    ]);
    assert_eq!(r.code, 0, "{r:?}");
    // The index's pages: those with its column heads.
    let index: String = r
        .stdout
        .lines()
        .map(|f| std::fs::read_to_string(f).unwrap())
        .filter(|page| page.contains("Network:row:col"))
        .collect();
    // R0000.0 is used on many lines of the sample; its address is written once.
    assert!(index.matches(">LEVEL1<").count() > 10, "many uses listed");
    assert_eq!(index.matches(">R0000.0<").count(), 1, "the address once");
    assert!(index.matches(">Always 1<").count() <= 1, "the symbol once");
}
