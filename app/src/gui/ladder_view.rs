//! The ladder view: a block's networks drawn with rails, contacts, coils, wires, vertical links
//! and function boxes. Only the networks inside the visible part are laid out and painted, so
//! a 5000-step program scrolls as smoothly as a small one.

use super::settings::DisplayMode;
use egui::{Align2, Color32, FontId, Pos2, Rect, Sense, Stroke, StrokeKind, pos2, vec2};
use ladder_engine::model::{Cell, Network, Operand, Project};

/// Operand colours (manual §3.4.3.3): a symbol mapped to an address is blue, an undefined one
/// red.
const MAPPED: Color32 = Color32::from_rgb(0x1f, 0x4f, 0xd0);
const UNDEFINED: Color32 = Color32::from_rgb(0xd0, 0x20, 0x20);

/// Sizes at a zoom.
#[derive(Clone, Copy, Debug)]
pub struct Metrics {
    /// Width of a contact column.
    pub cell: f32,
    /// Height of a plain row.
    pub row: f32,
    /// Width of the output column.
    pub output: f32,
    /// Height of one operand line in a box.
    pub line: f32,
    /// Height of a network's header.
    pub header: f32,
    /// Font size.
    pub font: f32,
}

impl Metrics {
    /// The sizes at `zoom` percent.
    pub fn at(zoom: u16) -> Metrics {
        let z = f32::from(zoom) / 100.0;
        Metrics {
            cell: 84.0 * z,
            row: 44.0 * z,
            output: 150.0 * z,
            line: 14.0 * z,
            header: 22.0 * z,
            font: 11.0 * z,
        }
    }

    /// Height of a row: function boxes grow with their operands.
    pub fn row_height(&self, cells: &[Cell]) -> f32 {
        let lines = cells
            .iter()
            .map(|c| match c {
                Cell::Box { operands, .. } => operands.len() + 1,
                _ => 0,
            })
            .max()
            .unwrap_or(0);
        self.row.max(lines as f32 * self.line + 10.0)
    }

    /// Height of a whole network.
    pub fn network_height(&self, n: &Network, comments: bool) -> f32 {
        let rows: f32 = n.rows.iter().map(|r| self.row_height(&r.cells)).sum();
        let comment = if comments && !n.comment.is_empty() {
            self.header
        } else {
            0.0
        };
        self.header + comment + rows + 8.0
    }
}

/// How an operand is written and coloured in the current display mode.
pub fn operand_text(project: &Project, o: &Operand, mode: DisplayMode) -> (String, Color32) {
    match o {
        Operand::Symbol(name) => match project.resolve_symbol(name) {
            Some(a) => match mode {
                DisplayMode::Address => (a.to_string(), MAPPED),
                DisplayMode::Symbol => (name.clone(), Color32::BLACK),
                DisplayMode::Both => (format!("{a}:{name}"), Color32::BLACK),
            },
            None => (name.clone(), UNDEFINED),
        },
        Operand::Addr(a) => {
            let symbol = project.symbol_of(*a);
            match (mode, symbol) {
                (DisplayMode::Symbol, Some(s)) => (s.to_string(), Color32::BLACK),
                (DisplayMode::Both, Some(s)) => (format!("{a}:{s}"), Color32::BLACK),
                _ => (a.to_string(), Color32::BLACK),
            }
        }
        other => (other.to_string(), Color32::BLACK),
    }
}

/// How networks are drawn.
struct Style {
    m: Metrics,
    mode: DisplayMode,
    comments: bool,
}

/// Draws one network with its top-left at `origin`.
fn network_ui(
    painter: &egui::Painter,
    project: &Project,
    net: &Network,
    index: usize,
    origin: Pos2,
    style: &Style,
) {
    let Style { m, mode, comments } = style;
    let (mode, comments) = (*mode, *comments);
    let width = project.ladder.width;
    let wire = Stroke::new(1.5, Color32::from_gray(40));
    let font = FontId::proportional(m.font);
    let title = if net.title.is_empty() {
        format!("N{:04}", index + 1)
    } else {
        format!("N{:04}  {}", index + 1, net.title)
    };
    painter.text(
        origin + vec2(4.0, 2.0),
        Align2::LEFT_TOP,
        title,
        FontId::proportional(m.font * 1.1),
        Color32::from_rgb(0, 100, 0),
    );
    let mut y = origin.y + m.header;
    if comments && !net.comment.is_empty() {
        painter.text(
            pos2(origin.x + 4.0, y),
            Align2::LEFT_TOP,
            net.comment.lines().next().unwrap_or(""),
            font.clone(),
            Color32::DARK_GREEN,
        );
        y += m.header;
    }
    let rail_x = origin.x + 8.0;
    let col_x = |c: usize| rail_x + c as f32 * m.cell;
    let right_rail = col_x(width) + m.output + 8.0;
    let top = y;
    let mut row_tops = Vec::with_capacity(net.rows.len());
    for row in &net.rows {
        row_tops.push(y);
        y += m.row_height(&row.cells);
    }
    // Rails.
    painter.line_segment(
        [pos2(rail_x, top), pos2(rail_x, y)],
        Stroke::new(3.0, Color32::from_gray(30)),
    );
    painter.line_segment(
        [pos2(right_rail, top), pos2(right_rail, y)],
        Stroke::new(3.0, Color32::from_gray(30)),
    );
    for (r, row) in net.rows.iter().enumerate() {
        let mid = row_tops[r] + m.row * 0.5;
        for (c, cell) in row.cells.iter().enumerate() {
            let x0 = col_x(c);
            let x1 = if c == width {
                x0 + m.output
            } else {
                x0 + m.cell
            };
            match cell {
                Cell::Empty => {}
                Cell::Wire => {
                    painter.line_segment([pos2(x0, mid), pos2(x1, mid)], wire);
                }
                Cell::Contact { negated, operand } => {
                    let cx = (x0 + x1) * 0.5;
                    let gap = m.cell * 0.12;
                    painter.line_segment([pos2(x0, mid), pos2(cx - gap, mid)], wire);
                    painter.line_segment([pos2(cx + gap, mid), pos2(x1, mid)], wire);
                    let h = m.row * 0.22;
                    painter.line_segment([pos2(cx - gap, mid - h), pos2(cx - gap, mid + h)], wire);
                    painter.line_segment([pos2(cx + gap, mid - h), pos2(cx + gap, mid + h)], wire);
                    if *negated {
                        painter.line_segment(
                            [pos2(cx - gap * 1.4, mid + h), pos2(cx + gap * 1.4, mid - h)],
                            wire,
                        );
                    }
                    let (text, color) = operand_text(project, operand, mode);
                    painter.text(
                        pos2(cx, mid - h - 2.0),
                        Align2::CENTER_BOTTOM,
                        text,
                        font.clone(),
                        color,
                    );
                }
                Cell::Coil { negated, operand } => {
                    let cx = x1 - m.output * 0.3;
                    let rad = m.row * 0.2;
                    painter.line_segment([pos2(x0, mid), pos2(cx - rad, mid)], wire);
                    painter.circle_stroke(pos2(cx, mid), rad, wire);
                    if *negated {
                        painter.line_segment(
                            [
                                pos2(cx - rad * 0.7, mid + rad * 0.7),
                                pos2(cx + rad * 0.7, mid - rad * 0.7),
                            ],
                            wire,
                        );
                    }
                    painter.line_segment([pos2(cx + rad, mid), pos2(right_rail, mid)], wire);
                    let (text, color) = operand_text(project, operand, mode);
                    painter.text(
                        pos2(cx, mid - rad - 2.0),
                        Align2::CENTER_BOTTOM,
                        text,
                        font.clone(),
                        color,
                    );
                }
                Cell::Box { op, operands } => {
                    let h = m.row_height(&row.cells) - 8.0;
                    let rect = Rect::from_min_size(
                        pos2(x0 + 6.0, row_tops[r] + 4.0),
                        vec2(m.output - 12.0, h),
                    );
                    painter.line_segment([pos2(x0, mid), pos2(rect.left(), mid)], wire);
                    painter.line_segment([pos2(rect.right(), mid), pos2(right_rail, mid)], wire);
                    painter.rect_stroke(rect, 2.0, wire, StrokeKind::Middle);
                    painter.text(
                        rect.center_top() + vec2(0.0, 2.0),
                        Align2::CENTER_TOP,
                        op.name(),
                        FontId::proportional(m.font * 1.1),
                        Color32::BLACK,
                    );
                    for (i, o) in operands.iter().enumerate() {
                        let name = op.spec().operand(i).map_or("", |s| s.name);
                        let (text, color) = operand_text(project, o, mode);
                        let p = rect.left_top() + vec2(4.0, m.line * (i as f32 + 1.0) + 2.0);
                        painter.text(
                            p,
                            Align2::LEFT_TOP,
                            format!("{name} {text}"),
                            font.clone(),
                            color,
                        );
                    }
                }
            }
            // A vertical link at the left edge of this column, down to the next row.
            if c > 0 && row.links.get(c).copied().unwrap_or(false) && r + 1 < net.rows.len() {
                let next_mid = row_tops[r + 1] + m.row * 0.5;
                painter.line_segment([pos2(x0, mid), pos2(x0, next_mid)], wire);
            }
        }
    }
}

/// Where a network is in the view (relative to the content's top).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Placed {
    /// Top offset.
    pub top: f32,
    /// Height.
    pub height: f32,
}

/// Where the last frame drew the block: enough to turn a cell into a screen position (for
/// tests and tooltips). UI state, never saved.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Geometry {
    /// Screen position of the content's top-left corner.
    pub origin: Pos2,
    /// Top of each network, relative to the content.
    pub tops: Vec<f32>,
    /// Top of each row of each network, relative to its network's top.
    pub rows: Vec<Vec<f32>>,
    /// Width of a contact column and of the output column.
    pub cell: f32,
    /// Width of the output column.
    pub output: f32,
    /// Contact columns.
    pub width: usize,
}

impl Geometry {
    /// The screen centre of a cell.
    pub fn cell_center(&self, network: usize, row: usize, col: usize) -> Option<Pos2> {
        let top = self.origin.y + self.tops.get(network)? + self.rows.get(network)?.get(row)?;
        let x = self.origin.x + 8.0 + col as f32 * self.cell;
        let w = if col >= self.width {
            self.output
        } else {
            self.cell
        };
        Some(pos2(x + w * 0.5, top + 12.0))
    }
}

/// How a block is shown.
#[derive(Clone, Copy, Debug)]
pub struct ViewOptions {
    /// Zoom in percent.
    pub zoom: u16,
    /// Operand display.
    pub mode: DisplayMode,
    /// Network comments shown.
    pub comments: bool,
    /// The cursor's (network, row, column) in this block.
    pub cursor: Option<(usize, usize, usize)>,
}

/// The top of each row of a network, relative to the network's top (after its header and,
/// when shown, its comment line).
fn row_tops(net: &Network, m: &Metrics, comments: bool) -> Vec<f32> {
    let mut y = m.header;
    if comments && !net.comment.is_empty() {
        y += m.header;
    }
    net.rows
        .iter()
        .map(|r| {
            let top = y;
            y += m.row_height(&r.cells);
            top
        })
        .collect()
}

/// Which cell a point in network `n` (drawn at `origin`) falls on.
fn cell_at(
    project: &Project,
    net: &Network,
    origin: Pos2,
    p: Pos2,
    m: &Metrics,
    comments: bool,
) -> Option<(usize, usize)> {
    let col = ((p.x - origin.x - 8.0) / m.cell).floor();
    if col < 0.0 {
        return None;
    }
    let col = (col as usize).min(project.ladder.width);
    let tops = row_tops(net, m, comments);
    (0..net.rows.len())
        .find(|r| {
            let top = origin.y + tops[*r];
            p.y >= top && p.y < top + m.row_height(&net.rows[*r].cells)
        })
        .map(|r| (r, col))
}

/// Draws block `block` of the project, scrolled; `jump_to` scrolls a network into view once.
/// Returns the (network, row, column) of a cell the user clicked.
pub fn block_ui(
    ui: &mut egui::Ui,
    project: &Project,
    block: usize,
    opts: &ViewOptions,
    jump_to: &mut Option<usize>,
    geometry: &mut Geometry,
) -> Option<(usize, usize, usize)> {
    let b = project.ladder.blocks.get(block)?;
    let (zoom, mode, comments) = (opts.zoom, opts.mode, opts.comments);
    let m = Metrics::at(zoom);
    // Offsets of every network: plain arithmetic over the model, no layout or text.
    let mut placed = Vec::with_capacity(b.networks.len());
    let mut y = 0.0;
    for n in &b.networks {
        let h = m.network_height(n, comments);
        placed.push(Placed { top: y, height: h });
        y += h;
    }
    let total = vec2(
        m.cell * project.ladder.width as f32 + m.output + 40.0,
        y.max(1.0),
    );
    let style = Style { m, mode, comments };
    egui::ScrollArea::both()
        .auto_shrink([false, false])
        .show_viewport(ui, |ui, viewport| {
            let (rect, response) = ui.allocate_exact_size(total, Sense::click());
            geometry.origin = rect.min;
            geometry.cell = m.cell;
            geometry.output = m.output;
            geometry.width = project.ladder.width;
            geometry.tops = placed.iter().map(|p| p.top).collect();
            geometry.rows = b
                .networks
                .iter()
                .map(|n| row_tops(n, &m, comments))
                .collect();
            let mut clicked = None;
            if let Some(p) = response
                .interact_pointer_pos()
                .filter(|_| response.clicked())
            {
                let y = p.y - rect.min.y;
                let i = placed.partition_point(|q| q.top + q.height <= y);
                if let Some(q) = placed.get(i) {
                    let origin = rect.min + vec2(0.0, q.top);
                    clicked = cell_at(project, &b.networks[i], origin, p, &m, comments)
                        .map(|(r, c)| (i, r, c));
                }
            }
            let painter = ui.painter_at(rect);
            // Black on white, like a printed ladder, whatever the UI theme.
            painter.rect_filled(
                rect.intersect(viewport.translate(rect.min.to_vec2())),
                0.0,
                Color32::WHITE,
            );
            if let Some(target) = jump_to.take()
                && let Some(p) = placed.get(target)
            {
                let r = Rect::from_min_size(rect.min + vec2(0.0, p.top), vec2(total.x, p.height));
                ui.scroll_to_rect(r, Some(egui::Align::TOP));
            }
            // Only the networks that intersect the visible part.
            let first = placed.partition_point(|p| p.top + p.height < viewport.min.y);
            for (i, p) in placed.iter().enumerate().skip(first) {
                if p.top > viewport.max.y {
                    break;
                }
                let origin = rect.min + vec2(0.0, p.top);
                network_ui(&painter, project, &b.networks[i], i, origin, &style);
                if let Some((cn, cr, cc)) = opts.cursor
                    && cn == i
                {
                    cursor_ui(
                        &painter,
                        &b.networks[i],
                        origin,
                        cr,
                        cc,
                        project.ladder.width,
                        &style,
                    );
                }
                let sep = origin.y + p.height - 2.0;
                painter.line_segment(
                    [pos2(rect.left(), sep), pos2(rect.right(), sep)],
                    Stroke::new(0.5, Color32::from_gray(200)),
                );
            }
            clicked
        })
        .inner
}

/// Outlines the cursor's cell.
fn cursor_ui(
    painter: &egui::Painter,
    net: &Network,
    origin: Pos2,
    row: usize,
    col: usize,
    width: usize,
    style: &Style,
) {
    let m = &style.m;
    let y = origin.y
        + row_tops(net, m, style.comments)
            .get(row)
            .copied()
            .unwrap_or(m.header);
    let h = net.rows.get(row).map_or(m.row, |r| m.row_height(&r.cells));
    let x = origin.x + 8.0 + col as f32 * m.cell;
    let w = if col >= width { m.output } else { m.cell };
    let rect = Rect::from_min_size(pos2(x, y), vec2(w, h));
    painter.rect_stroke(
        rect,
        2.0,
        Stroke::new(2.0, Color32::from_rgb(0x20, 0x60, 0xff)),
        StrokeKind::Inside,
    );
}
