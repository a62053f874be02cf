//! Pagination: the title page, the blocks network by network (a network moves to the next
//! page rather than being cut, unless it is taller than a page), the tables, then the
//! headers and footers once the page count is known.

use crate::font::Metrics;
use crate::ladder::{Grid, Names, Painter, comment_lines};
use crate::options::Options;
use crate::page::{Anchor, Document, Ink, Item, Pt};
use crate::pages::{Frame, MARGIN, Pages};
use ladder_engine::model::{BlockKind, Project};

/// Space between two networks.
const GAP: Pt = 6.0;

/// A block's name in the document's language.
pub(crate) fn section_name(kind: &BlockKind, options: &Options) -> String {
    let lang = options.lang;
    match kind {
        BlockKind::Level1 => format!("LEVEL1  {}", lang.say("Level 1 program", "第1级程序")),
        BlockKind::Level2 => format!("LEVEL2  {}", lang.say("Level 2 program", "第2级程序")),
        BlockKind::Sub { number, name } => {
            let sub = lang.say("subprogram", "子程序");
            if name.is_empty() {
                format!("P{number:04}  {sub}")
            } else {
                format!("P{number:04}  {name}  {sub}")
            }
        }
    }
}

/// Lays out the document of `project`, called `name`.
pub fn document(project: &Project, name: &str, options: &Options) -> Document {
    // The version information's project name is the title; the file's name otherwise.
    let name = match project.version.name.trim() {
        "" => name,
        given => given,
    };
    let (width, height) = options.page_size();
    let mut metrics = Metrics::new();
    let names = Names::new(project);
    let frame = Frame::new(width, height);
    let grid = Grid::new(
        frame.left,
        frame.right - frame.left,
        project.ladder.width,
        options,
    );
    let mut pages = Pages {
        pages: Vec::new(),
        frame,
        y: 0.0,
    };
    pages.new_page("");
    let mut contents: Vec<(String, usize)> = Vec::new();
    for (b, block) in project.ladder.blocks.iter().enumerate() {
        let wanted = options.blocks.includes(&block.kind);
        let chosen: Vec<usize> = (0..block.networks.len())
            .filter(|n| {
                options
                    .only
                    .as_ref()
                    .is_none_or(|only| only.contains(&(b, *n)))
            })
            .collect();
        if !wanted || (options.only.is_some() && chosen.is_empty()) {
            continue;
        }
        let section = section_name(&block.kind, options);
        pages.new_page(&section);
        contents.push((section.clone(), pages.pages.len()));
        let mut painter = Painter {
            grid: &grid,
            names: &names,
            options,
            metrics: &mut metrics,
        };
        if chosen.is_empty() {
            let empty = options.lang.say("(no networks)", "（无网络）");
            pages.put(vec![Item::text(
                grid.x0,
                pages.y + grid.font * 2.0,
                grid.font * 1.2,
                Anchor::Left,
                Ink::Grey,
                empty,
            )]);
            continue;
        }
        for n in chosen {
            let net = &block.networks[n];
            let title = if net.title.is_empty() {
                format!("N{:04}", n + 1)
            } else {
                format!("N{:04}  {}", n + 1, net.title)
            };
            let comments = comment_lines(net, options, painter.metrics, &grid);
            let heights: Vec<Pt> = net.rows.iter().map(|r| grid.row_height(&r.cells)).collect();
            let head =
                grid.header_height(0) + comments.len() as Pt * grid.line * 1.1 + grid.line * 0.3;
            let whole = head + heights.iter().sum::<Pt>() + grid.font;
            let page_room = pages.frame.bottom - pages.frame.top;
            if whole > pages.room() && !pages.fresh() && whole <= page_room {
                pages.new_page(&section);
            }
            // Rows in ranges that each fit the room left; the first range keeps the header,
            // and every range but the last ends with the "continued" marker.
            let marker = grid.font * 1.6;
            let mut start = 0;
            loop {
                let mut used = if start == 0 {
                    head
                } else {
                    grid.header_height(0)
                } + grid.font;
                let mut end = start;
                while end < heights.len() {
                    let need = heights[end] + if end + 1 < heights.len() { marker } else { 0.0 };
                    if end > start && used + need > pages.room() {
                        break;
                    }
                    used += heights[end];
                    end += 1;
                }
                if end < heights.len() {
                    used += marker;
                }
                // Not even one row fits here: the range starts on a new page.
                if used > pages.room() && !pages.fresh() {
                    pages.new_page(&section);
                    continue;
                }
                let (items, h) = painter.network(net, &title, &comments, start..end, pages.y);
                pages.put(items);
                pages.y += h + GAP;
                if end >= heights.len() {
                    break;
                }
                pages.new_page(&section);
                start = end;
            }
        }
    }
    if options.tables {
        crate::tables::tables(project, options, &mut metrics, &mut pages, &mut contents);
    }
    if options.xref {
        crate::tables::xref(project, options, &mut metrics, &mut pages, &mut contents);
    }
    if options.title_page {
        let title_items = crate::title::title_page(
            project,
            name,
            options,
            &pages.frame,
            &contents,
            &mut metrics,
        );
        pages.pages[0].items = title_items;
    } else {
        pages.pages.remove(0);
    }
    let mut doc = Document {
        width,
        height,
        pages: pages.pages,
        title: name.to_string(),
    };
    frame_pages(&mut doc, options, &mut metrics);
    doc
}

/// Headers (project, section, date) and footers (page n/N) on every page.
fn frame_pages(doc: &mut Document, options: &Options, metrics: &mut Metrics) {
    let total = doc.pages.len();
    let (w, h) = (doc.width, doc.height);
    let size = 7.5;
    for (i, page) in doc.pages.iter_mut().enumerate() {
        let n = i + 1;
        let footer = match options.lang {
            crate::options::PrintLang::Zh => format!("第 {n}/{total} 页"),
            crate::options::PrintLang::En => format!("Page {n}/{total}"),
            crate::options::PrintLang::Both => format!("第 {n}/{total} 页  Page {n}/{total}"),
        };
        page.items.push(Item::text(
            w / 2.0,
            h - MARGIN,
            size,
            Anchor::Middle,
            Ink::Grey,
            footer,
        ));
        if i == 0 && options.title_page {
            continue;
        }
        let y = MARGIN + 8.0;
        let left = metrics.fit(&doc.title, size, (w - 2.0 * MARGIN) * 0.3);
        page.items
            .push(Item::text(MARGIN, y, size, Anchor::Left, Ink::Grey, left));
        let section = metrics.fit(&page.section, size, (w - 2.0 * MARGIN) * 0.4);
        page.items.push(Item::text(
            w / 2.0,
            y,
            size,
            Anchor::Middle,
            Ink::Grey,
            section,
        ));
        page.items.push(Item::text(
            w - MARGIN,
            y,
            size,
            Anchor::Right,
            Ink::Grey,
            options.date.clone(),
        ));
        page.items.push(Item::Path {
            segs: vec![
                crate::page::Seg::Move(MARGIN, y + 4.0),
                crate::page::Seg::Line(w - MARGIN, y + 4.0),
            ],
            width: 0.5,
            ink: Ink::Grey,
        });
    }
}
