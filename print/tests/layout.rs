//! The laid-out pages of the sample project, read as geometry: element comments stay clear
//! of the power rails and the vertical links, and wrap inside their cell instead of being
//! cut after a few characters.

use ladder_print::{Ink, Item, Labels, Metrics, Options, PrintLang, Seg, document};

fn sample() -> ladder_engine::model::Project {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/../projects/lathe-988ta.ldp");
    ladder_engine::file::load(std::path::Path::new(path)).expect("the sample loads")
}

/// Every vertical stroke of a page: x, top, bottom.
fn verticals(items: &[Item]) -> Vec<(f32, f32, f32)> {
    let mut out = Vec::new();
    for i in items {
        if let Item::Path { segs, .. } = i {
            let mut at = None;
            for s in segs {
                match *s {
                    Seg::Move(x, y) => at = Some((x, y)),
                    Seg::Line(x, y) => {
                        if let Some((x0, y0)) = at
                            && (x0 - x).abs() < 0.01
                            && (y0 - y).abs() > 0.01
                        {
                            out.push((x, y0.min(y), y0.max(y)));
                        }
                        at = Some((x, y));
                    }
                    Seg::Cubic(.., x, y) => at = Some((x, y)),
                }
            }
        }
    }
    out
}

#[test]
fn element_comments_never_cross_a_rail_or_a_link_and_wrap_in_their_cell() {
    let project = sample();
    let mut metrics = Metrics::new();
    for lang in [PrintLang::En, PrintLang::Zh, PrintLang::Both] {
        let options = Options {
            lang,
            labels: Labels::Both,
            date: "2026-12-03".into(),
            ..Options::default()
        };
        let doc = document(&project, "lathe", &options);
        let mut comments = 0;
        let mut wrapped = 0;
        for page in &doc.pages {
            let lines = verticals(&page.items);
            for i in &page.items {
                let Item::Text {
                    x,
                    y,
                    size,
                    ink: Ink::Grey,
                    text,
                    ..
                } = i
                else {
                    continue;
                };
                comments += 1;
                // The line under another of the same comment: same centre, one line down.
                wrapped += usize::from(page.items.iter().any(|o| {
                    matches!(o,
                    Item::Text { x: ox, y: oy, ink: Ink::Grey, .. }
                        if (ox - x).abs() < 0.01 && *oy < *y && y - oy < size * 1.6)
                }));
                let w = metrics.width(text, *size);
                let (left, right, top, bottom) = (x - w / 2.0, x + w / 2.0, y - size, *y);
                for (lx, lt, lb) in &lines {
                    let crosses = *lx > left && *lx < right && *lb > top && *lt < bottom;
                    assert!(
                        !crosses,
                        "{lang:?}: `{text}` [{left:.1}–{right:.1}] × [{top:.1}–{bottom:.1}] crosses the line at x {lx:.1} ({lt:.1}–{lb:.1})"
                    );
                }
            }
        }
        assert!(comments > 100, "{lang:?}: {comments} comment lines");
        assert!(
            wrapped > 20,
            "{lang:?}: long comments wrap to more lines: {wrapped}"
        );
    }
}

#[test]
fn the_title_is_the_project_name_of_the_version_information() {
    let mut project = sample();
    let options = Options {
        date: "2026-12-03".into(),
        ..Options::default()
    };
    let title = |p: &ladder_engine::model::Project| {
        document(p, "lathe-988ta", &options).pages[0]
            .texts()
            .next()
            .unwrap_or_default()
            .to_string()
    };
    assert_eq!(
        title(&project),
        "lathe-988ta",
        "the file's name without one"
    );
    project.version.name = "CK6140 lathe, order 2026-117".into();
    assert_eq!(title(&project), "CK6140 lathe, order 2026-117");
}
