//! One network drawn as the editor draws it — rails, contacts, coils, wires, links and boxes,
//! each element with its address and/or symbol above it and its comment below — as page
//! items. A network is measured first and drawn a range of rows at a time, so one taller than
//! a page continues on the next.

use crate::font::Metrics;
use crate::options::{Labels, Options};
use crate::page::{Anchor, Ink, Item, Pt, Seg};
use ladder_engine::Address;
use ladder_engine::model::{Cell, Network, Operand, Project};
use std::collections::HashMap;
use std::ops::Range;

/// What the labels of an address need: its symbol and comments, indexed once per document
/// (the project's own lookups walk every symbol table).
pub(crate) struct Names<'a> {
    symbols: HashMap<&'a str, Address>,
    of: HashMap<Address, (&'a str, &'a ladder_engine::model::tables::Comments)>,
}

impl<'a> Names<'a> {
    pub(crate) fn new(project: &'a Project) -> Names<'a> {
        let mut symbols = HashMap::new();
        let mut of = HashMap::new();
        for s in project.symbols() {
            if !s.name.is_empty() {
                symbols.entry(s.name.as_str()).or_insert(s.address);
            }
            let e = of
                .entry(s.address)
                .or_insert((s.name.as_str(), &s.comments));
            if e.0.is_empty() {
                e.0 = s.name.as_str();
            }
            if e.1.is_empty() {
                e.1 = &s.comments;
            }
        }
        Names { symbols, of }
    }

    fn address(&self, o: &Operand) -> Option<Address> {
        match o {
            Operand::Addr(a) => Some(*a),
            Operand::Symbol(s) => self.symbols.get(s.as_str()).copied(),
            _ => None,
        }
    }

    pub(crate) fn symbol(&self, a: Address) -> Option<&'a str> {
        self.of.get(&a).map(|e| e.0).filter(|s| !s.is_empty())
    }

    fn comment(&self, a: Address, lang: &str) -> Option<&'a str> {
        self.of
            .get(&a)
            .and_then(|e| e.1.get(lang))
            .map(|c| c.lines().next().unwrap_or(""))
            .filter(|c| !c.is_empty())
    }

    /// The label lines of a contact's or coil's operand.
    fn lines(&self, o: &Operand, labels: Labels) -> Vec<String> {
        let a = self.address(o);
        match (labels, a) {
            (_, None) => vec![o.to_string()],
            (Labels::Address, Some(a)) => vec![a.to_string()],
            (Labels::Symbol, Some(a)) => {
                vec![self.symbol(a).map_or_else(|| a.to_string(), str::to_string)]
            }
            (Labels::Both, Some(a)) => {
                vec![a.to_string(), self.symbol(a).unwrap_or("").to_string()]
            }
        }
    }

    /// A box operand on one line, as the editor writes it.
    fn inline(&self, o: &Operand, labels: Labels) -> String {
        match (labels, self.address(o)) {
            (Labels::Address, Some(a)) => a.to_string(),
            (Labels::Symbol, Some(a)) => {
                self.symbol(a).map_or_else(|| a.to_string(), str::to_string)
            }
            (Labels::Both, Some(a)) => match self.symbol(a) {
                Some(s) => format!("{a}:{s}"),
                None => a.to_string(),
            },
            (_, None) => o.to_string(),
        }
    }
}

/// The sizes of the ladder on a page.
pub(crate) struct Grid {
    /// Left of the content.
    pub x0: Pt,
    /// Width of a contact column.
    pub cell: Pt,
    /// Width of the output column.
    pub output: Pt,
    /// Label font size.
    pub font: Pt,
    /// Height of one label line.
    pub line: Pt,
    /// Contact columns.
    pub width: usize,
    /// Label lines above an element.
    label_lines: usize,
    /// Comment lines under an element.
    comment_lines: usize,
}

const ELEMENT: Pt = 2.2; // element height, in label font sizes
/// Most lines of an element comment, per language; longer ones end with "…".
const COMMENT_LINES: usize = 3;
const PAD: Pt = 2.0;

impl Grid {
    pub(crate) fn new(x0: Pt, content: Pt, width: usize, options: &Options) -> Grid {
        let rail = 12.0;
        let cell = (content - 2.0 * rail) / (width as Pt + 2.4);
        let font = (cell * 0.15).clamp(4.5, 8.0);
        Grid {
            x0: x0 + rail,
            cell,
            output: cell * 2.4,
            font,
            line: font * 1.25,
            width,
            label_lines: if options.labels == Labels::Both { 2 } else { 1 },
            comment_lines: if options.element_comments {
                options.lang.comment_langs().len() * COMMENT_LINES
            } else {
                0
            },
        }
    }

    fn col_x(&self, c: usize) -> Pt {
        self.x0 + c as Pt * self.cell
    }

    fn right_rail(&self) -> Pt {
        self.col_x(self.width) + self.output
    }

    /// From a row's top to its wire.
    fn wire(&self) -> Pt {
        PAD + self.label_lines as Pt * self.line + self.font * ELEMENT / 2.0
    }

    /// The height of a row.
    pub(crate) fn row_height(&self, cells: &[Cell]) -> Pt {
        let plain = 2.0 * PAD
            + (self.label_lines + self.comment_lines) as Pt * self.line
            + self.font * ELEMENT;
        let boxed = cells
            .iter()
            .map(|c| match c {
                Cell::Box { operands, .. } => {
                    self.wire() - self.font + self.box_height(operands.len()) + PAD
                }
                _ => 0.0,
            })
            .fold(0.0, Pt::max);
        plain.max(boxed)
    }

    fn box_height(&self, operands: usize) -> Pt {
        (operands + 1) as Pt * self.line + 4.0
    }

    /// The height of a network's title and comment lines.
    pub(crate) fn header_height(&self, comment_lines: usize) -> Pt {
        self.font * 2.2 + comment_lines as Pt * self.line * 1.1
    }
}

/// The text lines of a network's header: its comment in the languages printed, wrapped.
pub(crate) fn comment_lines(
    net: &Network,
    options: &Options,
    metrics: &mut Metrics,
    grid: &Grid,
) -> Vec<String> {
    let width = grid.right_rail() - grid.x0;
    let mut out = Vec::new();
    if !net.comment.trim().is_empty() {
        out.extend(metrics.wrap(net.comment.trim_end(), grid.font * 1.05, width));
    }
    for lang in options.lang.comment_langs() {
        if let Some(c) = net.comments.get(*lang).filter(|c| !c.trim().is_empty()) {
            out.extend(metrics.wrap(c.trim_end(), grid.font * 1.05, width));
        }
    }
    out
}

/// What draws a network.
pub(crate) struct Painter<'a, 'm> {
    pub grid: &'a Grid,
    pub names: &'a Names<'a>,
    pub options: &'a Options,
    pub metrics: &'m mut Metrics,
}

impl Painter<'_, '_> {
    /// Draws `rows` of `net` with its top at `y`: the title (or a "continued" title when the
    /// range does not start at row 0) and comment, then the rows. Returns the items and the
    /// height used.
    pub(crate) fn network(
        &mut self,
        net: &Network,
        title: &str,
        comments: &[String],
        rows: Range<usize>,
        y: Pt,
    ) -> (Vec<Item>, Pt) {
        let g = self.grid;
        let mut items = Vec::new();
        let first = rows.start == 0;
        let heading = if first {
            title.to_string()
        } else {
            format!("{title} ({})", self.options.lang.say("continued", "续"))
        };
        items.push(Item::text(
            g.x0 - 8.0,
            y + g.font * 1.4,
            g.font * 1.25,
            Anchor::Left,
            Ink::Black,
            heading,
        ));
        let mut top = y + g.header_height(0);
        if first {
            for line in comments {
                top += g.line * 1.1;
                items.push(Item::text(
                    g.x0,
                    top - g.line * 0.25,
                    g.font * 1.05,
                    Anchor::Left,
                    Ink::Grey,
                    line.clone(),
                ));
            }
            top += if comments.is_empty() {
                0.0
            } else {
                g.line * 0.3
            };
        }
        let rail_top = top;
        let mut wires = Vec::new();
        for r in rows.clone() {
            let row = &net.rows[r];
            let h = g.row_height(&row.cells);
            let wire = top + g.wire();
            wires.push(wire);
            for (c, cell) in row.cells.iter().enumerate() {
                if c < g.width {
                    self.contact_cell(cell, g.col_x(c), top, wire, &mut items);
                } else {
                    self.output_cell(cell, top, wire, &mut items);
                }
            }
            top += h;
        }
        // Links down at each junction, within the rows drawn; one into the next page's rows
        // runs to the bottom edge.
        for (i, r) in rows.clone().enumerate() {
            let row = &net.rows[r];
            for (j, link) in row.links.iter().enumerate() {
                if !*link {
                    continue;
                }
                let x = g.col_x(j);
                let to = wires.get(i + 1).copied().unwrap_or(top);
                items.push(Item::line(x, wires[i], x, to, 0.8));
            }
        }
        let continues = rows.end < net.rows.len();
        items.push(Item::line(g.x0, rail_top, g.x0, top, 1.6));
        items.push(Item::line(
            g.right_rail(),
            rail_top,
            g.right_rail(),
            top,
            1.6,
        ));
        if continues {
            let say = self
                .options
                .lang
                .say("continued on the next page", "接下页");
            items.push(Item::text(
                g.right_rail(),
                top + g.font * 1.3,
                g.font,
                Anchor::Right,
                Ink::Grey,
                format!("▼ {say}"),
            ));
            top += g.font * 1.6;
        }
        (items, top - y + g.font)
    }

    /// The label lines above an element and its comments below, centred on `mid`.
    fn labels(&mut self, o: &Operand, mid: Pt, span: Pt, top: Pt, items: &mut Vec<Item>) {
        let g = self.grid;
        let lines = self.names.lines(o, self.options.labels);
        for (i, l) in lines.iter().enumerate() {
            let text = self.metrics.fit(l, g.font, span - 2.0);
            items.push(Item::text(
                mid,
                top + PAD + (i as Pt + 0.8) * g.line,
                g.font,
                Anchor::Middle,
                Ink::Black,
                text,
            ));
        }
        if self.options.element_comments
            && let Some(a) = self.names.address(o)
        {
            let below = top + g.wire() + g.font * ELEMENT / 2.0;
            // Clear of the rails and links at the cell's edges by a good margin.
            let width = span - g.font;
            let size = g.font * 0.9;
            let mut line = 0;
            for lang in self.options.lang.comment_langs() {
                let Some(c) = self.names.comment(a, lang) else {
                    continue;
                };
                let mut wrapped = self.metrics.wrap(c.trim_end(), size, width);
                if wrapped.len() > COMMENT_LINES {
                    let rest = wrapped.split_off(COMMENT_LINES - 1).join(" ");
                    wrapped.push(self.metrics.fit(&rest, size, width));
                }
                for text in wrapped {
                    // A word longer than the cell is cut too.
                    let text = self.metrics.fit(&text, size, width);
                    items.push(Item::text(
                        mid,
                        below + (line as Pt + 0.85) * g.line,
                        size,
                        Anchor::Middle,
                        Ink::Grey,
                        text,
                    ));
                    line += 1;
                }
            }
        }
    }

    fn contact_cell(&mut self, cell: &Cell, x: Pt, top: Pt, wire: Pt, items: &mut Vec<Item>) {
        let g = self.grid;
        let w = g.cell;
        match cell {
            Cell::Empty | Cell::Coil { .. } | Cell::Box { .. } => {}
            Cell::Wire => items.push(Item::line(x, wire, x + w, wire, 0.8)),
            Cell::Contact { negated, operand } => {
                let (a, b) = (x + w * 0.38, x + w * 0.62);
                let h = g.font * 0.9;
                items.push(Item::line(x, wire, a, wire, 0.8));
                items.push(Item::line(b, wire, x + w, wire, 0.8));
                items.push(Item::line(a, wire - h, a, wire + h, 1.0));
                items.push(Item::line(b, wire - h, b, wire + h, 1.0));
                if *negated {
                    items.push(Item::line(a - 1.0, wire + h, b + 1.0, wire - h, 0.8));
                }
                self.labels(operand, x + w / 2.0, w, top, items);
            }
        }
    }

    fn output_cell(&mut self, cell: &Cell, top: Pt, wire: Pt, items: &mut Vec<Item>) {
        let g = self.grid;
        let x = g.col_x(g.width);
        match cell {
            Cell::Coil { negated, operand } => {
                let mid = x + g.output / 2.0;
                let r = g.font * 0.9;
                items.push(Item::line(x, wire, mid - r, wire, 0.8));
                items.push(Item::line(mid + r, wire, g.right_rail(), wire, 0.8));
                items.push(circle(mid, wire, r));
                if *negated {
                    items.push(Item::line(
                        mid - r * 0.5,
                        wire + r * 0.8,
                        mid + r * 0.5,
                        wire - r * 0.8,
                        0.8,
                    ));
                }
                self.labels(operand, mid, g.output, top, items);
            }
            Cell::Box { op, operands } => {
                let (bx, bw) = (x + 4.0, g.output - 8.0);
                let by = wire - g.font;
                items.push(Item::line(x, wire, bx, wire, 0.8));
                items.push(Item::rect(
                    bx,
                    by,
                    bw,
                    g.box_height(operands.len()),
                    1.0,
                    Ink::Black,
                ));
                items.push(Item::text(
                    bx + bw / 2.0,
                    by + g.line * 0.85,
                    g.font * 1.05,
                    Anchor::Middle,
                    Ink::Black,
                    op.name(),
                ));
                let spec = op.spec();
                for (i, o) in operands.iter().enumerate() {
                    let name = spec.operand(i).map_or("", |s| s.name);
                    let text = format!("{name} {}", self.names.inline(o, self.options.labels));
                    let text = self.metrics.fit(text.trim_start(), g.font * 0.95, bw - 4.0);
                    items.push(Item::text(
                        bx + 2.5,
                        by + (i as Pt + 1.85) * g.line,
                        g.font * 0.95,
                        Anchor::Left,
                        Ink::Black,
                        text,
                    ));
                }
            }
            Cell::Empty | Cell::Wire | Cell::Contact { .. } => {
                if matches!(cell, Cell::Wire) {
                    items.push(Item::line(x, wire, g.right_rail(), wire, 0.8));
                }
            }
        }
    }
}

/// A circle of radius `r` about (`x`, `y`): four Bézier quarters (the coil, as the editor
/// draws it).
fn circle(x: Pt, y: Pt, r: Pt) -> Item {
    // The control distance that makes a cubic quarter follow the circle within 0.03 %.
    let k = r * 0.552_284_8;
    Item::Path {
        segs: vec![
            Seg::Move(x + r, y),
            Seg::Cubic(x + r, y + k, x + k, y + r, x, y + r),
            Seg::Cubic(x - k, y + r, x - r, y + k, x - r, y),
            Seg::Cubic(x - r, y - k, x - k, y - r, x, y - r),
            Seg::Cubic(x + k, y - r, x + r, y - k, x + r, y),
        ],
        width: 1.0,
        ink: Ink::Black,
    }
}
