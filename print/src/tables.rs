//! The tables printed after the ladder: symbols, data settings, display messages and the
//! cross-reference index, each with its header row repeated on every page.

use crate::font::Metrics;
use crate::options::Options;
use crate::page::{Anchor, Ink, Item, Pt, Seg};
use crate::pages::Pages;
use ladder_engine::model::Project;
use ladder_engine::model::tables::Comments;

const SIZE: Pt = 7.5;
const ROW: Pt = 11.0;

/// One table: a title, column headers with their share of the width, and rows.
struct Table {
    title: String,
    columns: Vec<(String, Pt)>,
    rows: Vec<Vec<String>>,
}

fn comments(c: &Comments, options: &Options) -> String {
    options
        .lang
        .comment_langs()
        .iter()
        .filter_map(|l| c.get(*l).map(|t| t.lines().next().unwrap_or("")))
        .filter(|t| !t.is_empty())
        .collect::<Vec<_>>()
        .join(" / ")
}

fn opt<T: ToString>(v: Option<T>) -> String {
    v.map(|v| v.to_string()).unwrap_or_default()
}

/// One row of a data-setting table, integer or real.
fn data_row<T: ToString>(
    address: ladder_engine::Address,
    value: T,
    min: Option<T>,
    max: Option<T>,
    symbol: &str,
    c: &Comments,
    options: &Options,
) -> Vec<String> {
    vec![
        address.to_string(),
        value.to_string(),
        opt(min),
        opt(max),
        symbol.to_string(),
        comments(c, options),
    ]
}

/// Lays a table out on pages, a new page first.
fn put(
    table: &Table,
    pages: &mut Pages,
    metrics: &mut Metrics,
    contents: &mut Vec<(String, usize)>,
) {
    pages.new_page(&table.title);
    contents.push((table.title.clone(), pages.pages.len()));
    let left = pages.frame.left;
    let width = pages.frame.right - left;
    let xs: Vec<Pt> = table
        .columns
        .iter()
        .scan(left, |x, (_, share)| {
            let at = *x;
            *x += share * width;
            Some(at)
        })
        .collect();
    let title = table.title.clone();
    let header = |pages: &mut Pages, metrics: &mut Metrics| {
        let y = pages.y;
        let mut items = vec![Item::text(
            left,
            y + 12.0,
            11.0,
            Anchor::Left,
            Ink::Black,
            title.clone(),
        )];
        for (i, (name, share)) in table.columns.iter().enumerate() {
            let text = metrics.fit(name, SIZE, share * width - 4.0);
            items.push(Item::text(
                xs[i] + 2.0,
                y + 28.0,
                SIZE,
                Anchor::Left,
                Ink::Grey,
                text,
            ));
        }
        items.push(Item::Path {
            segs: vec![Seg::Move(left, y + 31.0), Seg::Line(left + width, y + 31.0)],
            width: 0.6,
            ink: Ink::Grey,
        });
        pages.put(items);
        pages.y += 31.0;
    };
    header(pages, metrics);
    if table.rows.is_empty() {
        let none = "—".to_string();
        pages.put(vec![Item::text(
            left + 2.0,
            pages.y + ROW - 2.5,
            SIZE,
            Anchor::Left,
            Ink::Grey,
            none,
        )]);
        pages.y += ROW;
    }
    for row in &table.rows {
        if pages.room() < ROW {
            pages.new_page(&table.title);
            header(pages, metrics);
        }
        let y = pages.y + ROW - 2.5;
        let items = row
            .iter()
            .enumerate()
            .filter(|(_, t)| !t.is_empty())
            .map(|(i, t)| {
                let text = metrics.fit(t, SIZE, table.columns[i].1 * width - 4.0);
                Item::text(xs[i] + 2.0, y, SIZE, Anchor::Left, Ink::Black, text)
            })
            .collect();
        pages.put(items);
        pages.y += ROW;
    }
}

/// The symbol, data-setting and message tables.
pub(crate) fn tables(
    project: &Project,
    options: &Options,
    metrics: &mut Metrics,
    pages: &mut Pages,
    contents: &mut Vec<(String, usize)>,
) {
    let heads = Heads::new(options);
    let mut all = symbol_tables(project, options, &heads);
    all.push(k_table(project, options, &heads));
    all.extend(data_tables(project, options, &heads));
    all.push(message_table(project, options, &heads));
    for table in &all {
        put(table, pages, metrics, contents);
    }
}

/// The column heads the tables share, in the document's language.
struct Heads {
    addr: String,
    symbol: String,
    comment: String,
    value: String,
}

impl Heads {
    fn new(options: &Options) -> Heads {
        let lang = options.lang;
        Heads {
            addr: lang.say("Address", "地址"),
            symbol: lang.say("Symbol", "符号"),
            comment: lang.say("Comment", "注释"),
            value: lang.say("Value", "值"),
        }
    }
}

/// One table per symbol table: address, symbol, comments.
fn symbol_tables(project: &Project, options: &Options, heads: &Heads) -> Vec<Table> {
    let lang = options.lang;
    project
        .symbol_tables
        .iter()
        .map(|t| Table {
            title: format!("{}  {}", lang.say("Symbol table", "符号表"), t.name),
            columns: vec![
                (heads.addr.clone(), 0.14),
                (heads.symbol.clone(), 0.26),
                (heads.comment.clone(), 0.60),
            ],
            rows: t
                .rows
                .iter()
                .map(|s| {
                    vec![
                        s.address.to_string(),
                        s.name.clone(),
                        comments(&s.comments, options),
                    ]
                })
                .collect(),
        })
        .collect()
}

/// The K keep relays: each byte in bits and as a value.
fn k_table(project: &Project, options: &Options, heads: &Heads) -> Table {
    let lang = options.lang;
    Table {
        title: lang.say("K keep relays", "K 保持继电器"),
        columns: vec![
            (heads.addr.clone(), 0.2),
            (lang.say("Bits 7…0", "位 7…0"), 0.3),
            (heads.value.clone(), 0.5),
        ],
        rows: project
            .data
            .k
            .iter()
            .enumerate()
            .map(|(i, v)| vec![format!("K{i:04}"), format!("{v:08b}"), v.to_string()])
            .collect(),
    }
}

/// The D, DT, DC and D_FLOAT data tables, one row per entry with its range and comments.
fn data_tables(project: &Project, options: &Options, heads: &Heads) -> Vec<Table> {
    let lang = options.lang;
    let data = &project.data;
    let columns = vec![
        (heads.addr.clone(), 0.12),
        (heads.value.clone(), 0.12),
        (lang.say("Min", "最小"), 0.1),
        (lang.say("Max", "最大"), 0.1),
        (heads.symbol.clone(), 0.18),
        (heads.comment.clone(), 0.38),
    ];
    // A macro rather than a closure: the integer rows and D_FLOAT's are different types
    // with the same fields.
    macro_rules! rows {
        ($rows:expr) => {
            $rows
                .iter()
                .map(|r| {
                    data_row(
                        r.address,
                        r.value,
                        r.min,
                        r.max,
                        &r.symbol,
                        &r.comments,
                        options,
                    )
                })
                .collect::<Vec<_>>()
        };
    }
    let tables: [(&str, Vec<Vec<String>>); 4] = [
        ("D", rows!(data.d)),
        ("DT", rows!(data.dt)),
        ("DC", rows!(data.dc)),
        ("D_FLOAT", rows!(data.d_float)),
    ];
    tables
        .into_iter()
        .map(|(name, rows)| Table {
            title: lang.say(&format!("{name} data table"), &format!("{name} 数据表")),
            columns: columns.clone(),
            rows,
        })
        .collect()
}

/// The display messages that have a number or a text, by their A bit.
fn message_table(project: &Project, options: &Options, heads: &Heads) -> Table {
    let lang = options.lang;
    Table {
        title: lang.say("Display messages", "信息显示表"),
        columns: vec![
            (heads.addr.clone(), 0.12),
            (lang.say("Number", "编号"), 0.1),
            (lang.say("Text", "内容"), 0.78),
        ],
        rows: project
            .messages
            .rows
            .iter()
            .enumerate()
            .filter(|(_, m)| m.number.is_some() || !m.texts.is_empty())
            .map(|(i, m)| {
                vec![
                    format!("A{:04}.{}", i / 8, i % 8),
                    opt(m.number),
                    comments(&m.texts, options),
                ]
            })
            .collect(),
    }
}

/// The cross-reference index.
pub(crate) fn xref(
    project: &Project,
    options: &Options,
    metrics: &mut Metrics,
    pages: &mut Pages,
    contents: &mut Vec<(String, usize)>,
) {
    let lang = options.lang;
    let x = ladder_engine::xref::build(project);
    let names = crate::ladder::Names::new(project);
    // Grouped by address: the address and its symbol once, then each use on its own line.
    let mut last = None;
    let rows = x
        .refs
        .iter()
        .map(|r| {
            let first = last.replace(r.address) != Some(r.address);
            let (address, symbol) = if first {
                (
                    r.address.to_string(),
                    names.symbol(r.address).unwrap_or("").to_string(),
                )
            } else {
                (String::new(), String::new())
            };
            vec![
                address,
                symbol,
                r.usage.letters().to_string(),
                project.ladder.blocks[r.block].kind.label(),
                format!("N{:04} {}:{}", r.network + 1, r.row + 1, r.col + 1),
                ladder_engine::xref::context(project, r),
            ]
        })
        .collect();
    put(
        &Table {
            title: lang.say("Cross-reference", "交叉引用表"),
            columns: vec![
                (lang.say("Address", "地址"), 0.11),
                (lang.say("Symbol", "符号"), 0.17),
                (lang.say("Use", "用法"), 0.06),
                (lang.say("Block", "程序块"), 0.1),
                (lang.say("Network:row:col", "网络:行:列"), 0.14),
                (lang.say("Element", "元件"), 0.42),
            ],
            rows,
        },
        pages,
        metrics,
        contents,
    );
}
