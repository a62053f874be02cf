//! Painting one network: rails, contacts, coils, wires, links and boxes, and on top of them
//! what the online monitor shows (power flow, live values, forces, the "why?" marks), the
//! selection and the cursor.

use super::label::{BitLabel, Span, address_of};
use super::{ErrorMark, Metrics, OperandPlace, operand_text, row_tops};
use crate::gui::settings::{DisplayMode, NumFormat};
use crate::gui::theme::{self, SELECTED};
use egui::{Align2, FontId, Pos2, Rect, Stroke, StrokeKind, pos2, vec2};
use ladder_engine::Address;
use ladder_engine::model::region::Region as Selection;
use ladder_engine::model::{Cell, Network, Operand, Project};
use ladder_engine::vm::monitor::NetworkView;

/// How networks are drawn.
pub(super) struct Style {
    pub(super) m: Metrics,
    pub(super) mode: DisplayMode,
    pub(super) comments: bool,
    pub(super) titles: bool,
    /// The comment language of element comments under contacts and coils, when shown.
    pub(super) element_comments: Option<&'static str>,
}

/// What the online monitor shows on one network.
pub struct LiveNetwork<'a> {
    /// Power flow, contact states and box values from the scan.
    pub view: &'a NetworkView,
    /// How box values are written.
    pub format: NumFormat,
    /// Whether an address is forced.
    pub forced: &'a dyn Fn(Address) -> bool,
    /// Cells marked by "why?" (row, column).
    pub marked: &'a [(usize, usize)],
}

/// Draws one network with its top-left at `origin`, with what the monitor shows when live.
pub(super) fn network_ui(
    painter: &egui::Painter,
    project: &Project,
    (net, index): (&Network, usize),
    origin: Pos2,
    style: &Style,
    live: Option<&LiveNetwork<'_>>,
    drawn: &mut Vec<(Rect, String)>,
) {
    let m = &style.m;
    let top = header(painter, (net, index), origin, style);
    let width = project.ladder.width;
    let rail_x = origin.x + m.margin;
    let right_rail = rail_x + width as f32 * m.cell + m.output + 8.0;
    let mut row_tops = Vec::with_capacity(net.rows.len());
    let mut y = top;
    for row in &net.rows {
        row_tops.push(y);
        y += m.row_height(&row.cells);
    }
    // Rails: the left one carries power whenever the program runs.
    let left = if live.is_some() {
        theme::POWER
    } else {
        theme::RAIL
    };
    painter.line_segment([pos2(rail_x, top), pos2(rail_x, y)], Stroke::new(3.0, left));
    painter.line_segment(
        [pos2(right_rail, top), pos2(right_rail, y)],
        Stroke::new(3.0, theme::RAIL),
    );
    let font = FontId::proportional(m.font);
    let cells = Cells {
        painter,
        project,
        m,
        mode: style.mode,
        font: &font,
        live,
        wire: Stroke::new(1.5, theme::WIRE),
        power: Stroke::new(3.0, theme::POWER),
        right_rail,
        label: BitLabel {
            project,
            mode: style.mode,
            font: &font,
            size: m.font,
            line: m.line,
            comment: style.element_comments,
        },
    };
    for (r, row) in net.rows.iter().enumerate() {
        for (c, cell) in row.cells.iter().enumerate() {
            let x0 = rail_x + c as f32 * m.cell;
            let x1 = x0 + if c == width { m.output } else { m.cell };
            let at = At {
                r,
                c,
                x0,
                x1,
                top: row_tops[r],
                height: m.row_height(&row.cells),
            };
            cells.cell(cell, &at, drawn);
            // A vertical link at the left edge of this column, down to the next row.
            if c > 0 && row.links.get(c).copied().unwrap_or(false) && r + 1 < net.rows.len() {
                cells.link(&at, row_tops[r + 1]);
            }
        }
    }
}

/// Draws the network's title and, when shown, its comment lines; returns where its rows
/// begin.
fn header(
    painter: &egui::Painter,
    (net, index): (&Network, usize),
    origin: Pos2,
    style: &Style,
) -> f32 {
    let m = &style.m;
    let title = if net.title.is_empty() || !style.titles {
        format!("N{:04}", index + 1)
    } else {
        format!("N{:04}  {}", index + 1, net.title)
    };
    painter.text(
        origin + vec2(4.0, 2.0),
        Align2::LEFT_TOP,
        title,
        FontId::proportional(m.font * 1.1),
        theme::TITLE,
    );
    let mut y = origin.y + m.header;
    if style.comments {
        for line in super::comment_lines(net) {
            painter.text(
                pos2(origin.x + 4.0, y),
                Align2::LEFT_TOP,
                line,
                FontId::proportional(m.font),
                theme::COMMENT,
            );
            y += m.header;
        }
    }
    y
}

/// Where one cell is drawn: its row and column, its left and right edge, its row's top and
/// height.
struct At {
    r: usize,
    c: usize,
    x0: f32,
    x1: f32,
    top: f32,
    height: f32,
}

impl At {
    /// The height of the row's wire.
    fn mid(&self, m: &Metrics) -> f32 {
        self.top + m.mid
    }
}

/// What every cell of one network is drawn with.
struct Cells<'a> {
    painter: &'a egui::Painter,
    project: &'a Project,
    m: &'a Metrics,
    mode: DisplayMode,
    font: &'a FontId,
    live: Option<&'a LiveNetwork<'a>>,
    wire: Stroke,
    power: Stroke,
    right_rail: f32,
    label: BitLabel<'a>,
}

impl Cells<'_> {
    /// What the monitor says of cell (`r`, `c`), when live.
    fn view(&self, r: usize, c: usize) -> Option<&ladder_engine::vm::monitor::CellView> {
        self.live.and_then(|l| l.view.cells.get(r)?.get(c))
    }

    /// A wire's stroke: thick and coloured where power flows.
    fn stroke(&self, on: bool) -> Stroke {
        if on { self.power } else { self.wire }
    }

    /// Whether the operand's address is forced on the running machine.
    fn forced(&self, o: &Operand) -> bool {
        self.live
            .is_some_and(|l| address_of(self.project, o).is_some_and(|a| (l.forced)(a)))
    }

    /// Draws one cell: its "why?" mark, then the element.
    fn cell(&self, cell: &Cell, at: &At, drawn: &mut Vec<(Rect, String)>) {
        let (p_in, p_out) = self
            .view(at.r, at.c)
            .map_or((false, false), |v| (v.power_in, v.power_out));
        if self.live.is_some_and(|l| l.marked.contains(&(at.r, at.c))) {
            self.painter.rect_stroke(
                Rect::from_min_max(
                    pos2(at.x0 + 1.0, at.top + 1.0),
                    pos2(at.x1 - 1.0, at.top + at.height - 1.0),
                ),
                3.0,
                Stroke::new(2.5, theme::WHY),
                StrokeKind::Inside,
            );
        }
        let mid = at.mid(self.m);
        match cell {
            Cell::Empty => {}
            Cell::Wire => {
                self.painter.line_segment(
                    [pos2(at.x0, mid), pos2(at.x1, mid)],
                    self.stroke(p_in && p_out),
                );
            }
            Cell::Contact { negated, operand } => {
                self.contact(*negated, operand, at, (p_in, p_out), drawn);
            }
            Cell::Coil { negated, operand } => self.coil(*negated, operand, at, p_in, drawn),
            Cell::Box { op, operands } => self.function_box(*op, operands, at, p_in),
        }
    }

    /// A contact: filled when closed, as on GSKLadder's monitor screen.
    fn contact(
        &self,
        negated: bool,
        operand: &Operand,
        at: &At,
        (p_in, p_out): (bool, bool),
        drawn: &mut Vec<(Rect, String)>,
    ) {
        let (painter, m, wire) = (self.painter, self.m, self.wire);
        let mid = at.mid(m);
        let cx = (at.x0 + at.x1) * 0.5;
        let gap = m.cell * 0.12;
        let h = m.symbol;
        if self.view(at.r, at.c).and_then(|v| v.closed) == Some(true) {
            painter.rect_filled(
                Rect::from_min_max(pos2(cx - gap, mid - h), pos2(cx + gap, mid + h)),
                0.0,
                theme::POWER_FILL,
            );
        }
        painter.line_segment([pos2(at.x0, mid), pos2(cx - gap, mid)], self.stroke(p_in));
        painter.line_segment([pos2(cx + gap, mid), pos2(at.x1, mid)], self.stroke(p_out));
        painter.line_segment([pos2(cx - gap, mid - h), pos2(cx - gap, mid + h)], wire);
        painter.line_segment([pos2(cx + gap, mid - h), pos2(cx + gap, mid + h)], wire);
        if negated {
            painter.line_segment(
                [pos2(cx - gap * 1.4, mid + h), pos2(cx + gap * 1.4, mid - h)],
                wire,
            );
        }
        self.label.draw(
            painter,
            drawn,
            operand,
            Span {
                centre: cx,
                left: at.x0 + 3.0,
                right: at.x1 - 3.0,
            },
            (mid - h - 3.0, mid + h + 3.0),
            self.forced(operand)
                .then_some(pos2(cx + gap + 2.0, mid + h)),
        );
    }

    /// A coil, its wire on to the right rail.
    fn coil(
        &self,
        negated: bool,
        operand: &Operand,
        at: &At,
        p_in: bool,
        drawn: &mut Vec<(Rect, String)>,
    ) {
        let (painter, m, wire) = (self.painter, self.m, self.wire);
        let mid = at.mid(m);
        let cx = at.x1 - m.output * 0.3;
        let rad = m.symbol * 0.9;
        let h_coil = m.symbol;
        if p_in {
            painter.circle_filled(pos2(cx, mid), rad, theme::POWER_FILL);
        }
        painter.line_segment([pos2(at.x0, mid), pos2(cx - rad, mid)], self.stroke(p_in));
        painter.circle_stroke(pos2(cx, mid), rad, wire);
        if negated {
            painter.line_segment(
                [
                    pos2(cx - rad * 0.7, mid + rad * 0.7),
                    pos2(cx + rad * 0.7, mid - rad * 0.7),
                ],
                wire,
            );
        }
        painter.line_segment([pos2(cx + rad, mid), pos2(self.right_rail, mid)], wire);
        // The coil's label may use the whole output column, never past the rail.
        self.label.draw(
            painter,
            drawn,
            operand,
            Span {
                centre: (at.x0 + self.right_rail) * 0.5,
                left: at.x0 + 3.0,
                right: self.right_rail - 4.0,
            },
            (mid - h_coil - 3.0, mid + h_coil + 3.0),
            self.forced(operand)
                .then_some(pos2(cx + rad + 2.0, mid + rad)),
        );
    }

    /// A function box: its name, an operand a line with its live value on the right.
    fn function_box(&self, op: ladder_engine::Op, operands: &[Operand], at: &At, p_in: bool) {
        let (painter, m, wire) = (self.painter, self.m, self.wire);
        let mid = at.mid(m);
        let rect = Rect::from_min_size(
            pos2(at.x0 + 6.0, at.top + 4.0),
            vec2(m.output - 12.0, at.height - 8.0),
        );
        if p_in {
            painter.rect_filled(rect, 2.0, theme::POWER_BOX);
        }
        painter.line_segment(
            [pos2(at.x0, mid), pos2(rect.left(), mid)],
            self.stroke(p_in),
        );
        painter.line_segment([pos2(rect.right(), mid), pos2(self.right_rail, mid)], wire);
        painter.rect_stroke(rect, 2.0, wire, StrokeKind::Middle);
        painter.text(
            rect.center_top() + vec2(0.0, 2.0),
            Align2::CENTER_TOP,
            op.name(),
            FontId::proportional(m.font * 1.1),
            theme::INK,
        );
        let v = self.view(at.r, at.c);
        for (i, o) in operands.iter().enumerate() {
            let name = op.spec().operand(i).map_or("", |s| s.name);
            let (text, color) = operand_text(
                self.project,
                o,
                self.mode,
                OperandPlace::Box(op, i),
                operands,
            );
            let p = rect.left_top() + vec2(4.0, m.line * (i as f32 + 1.0) + 2.0);
            painter.text(
                p,
                Align2::LEFT_TOP,
                format!("{name} {text}"),
                self.font.clone(),
                color,
            );
            let value = v.and_then(|v| v.values.get(i).copied().flatten());
            if let (Some(l), Some(value)) = (self.live, value) {
                let bytes = address_of(self.project, o)
                    .map_or(4, |a| u32::from(a.area.element_bytes()).max(1));
                let shown = if self.forced(o) {
                    format!("{} F", l.format.show(value, bytes))
                } else {
                    l.format.show(value, bytes)
                };
                painter.text(
                    pos2(rect.right() - 4.0, p.y),
                    Align2::RIGHT_TOP,
                    shown,
                    self.font.clone(),
                    theme::LIVE_VALUE,
                );
            }
        }
    }

    /// A vertical link at the cell's left edge down to the next row (whose top is `next_top`):
    /// it joins the nodes of both rows, so it is powered when either side is.
    fn link(&self, at: &At, next_top: f32) {
        let on = self.view(at.r, at.c - 1).is_some_and(|v| v.power_out)
            || self.view(at.r + 1, at.c - 1).is_some_and(|v| v.power_out);
        self.painter.line_segment(
            [
                pos2(at.x0, at.mid(self.m)),
                pos2(at.x0, next_top + self.m.mid),
            ],
            self.stroke(on),
        );
    }
}

/// Fills what is selected in network `index`.
#[allow(clippy::too_many_arguments)] // One painter call site; a struct would only rename them.
pub(super) fn selection_ui(
    painter: &egui::Painter,
    net: &Network,
    index: usize,
    origin: Pos2,
    height: f32,
    width: f32,
    sel: &Selection,
    style: &Style,
) {
    let m = &style.m;
    if sel.covers_network(index) {
        painter.rect_filled(
            Rect::from_min_size(origin, vec2(width, height - 2.0)),
            0.0,
            SELECTED,
        );
        return;
    }
    let tops = row_tops(net, m, style.comments);
    for (r, row) in net.rows.iter().enumerate() {
        let h = m.row_height(&row.cells);
        for c in 0..row.cells.len() {
            if sel.contains(index, r, c) {
                let x = origin.x + m.margin + c as f32 * m.cell;
                let w = if c + 1 == row.cells.len() {
                    m.output
                } else {
                    m.cell
                };
                painter.rect_filled(
                    Rect::from_min_size(pos2(x, origin.y + tops[r]), vec2(w, h)),
                    0.0,
                    SELECTED,
                );
            }
        }
    }
}

/// A cell's rectangle in a network drawn with its top-left at `origin` (the output column
/// is `width`).
fn cell_rect(
    net: &Network,
    origin: Pos2,
    (row, col): (usize, usize),
    width: usize,
    style: &Style,
) -> Rect {
    let m = &style.m;
    let tops = row_tops(net, m, style.comments);
    // Past the last row: the new row offered below it, a plain row high.
    let y = origin.y
        + tops.get(row).copied().unwrap_or_else(|| {
            tops.last().copied().unwrap_or(m.header)
                + net.rows.last().map_or(0.0, |r| m.row_height(&r.cells))
        });
    let h = net.rows.get(row).map_or(m.row, |r| m.row_height(&r.cells));
    let x = origin.x + m.margin + col.min(width) as f32 * m.cell;
    let w = if col >= width { m.output } else { m.cell };
    Rect::from_min_size(pos2(x, y), vec2(w, h))
}

/// Outlines the cursor's cell.
pub(super) fn cursor_ui(
    painter: &egui::Painter,
    net: &Network,
    origin: Pos2,
    (row, col): (usize, usize),
    width: usize,
    style: &Style,
) {
    painter.rect_stroke(
        cell_rect(net, origin, (row, col), width, style),
        2.0,
        Stroke::new(2.0, theme::CURSOR),
        StrokeKind::Inside,
    );
}

/// Marks a cell the last compile found wrong: a dashed red (warnings: amber) frame, a "!"
/// badge in its corner, and its operand underlined (`labels`: the labels drawn in its
/// network).
pub(super) fn error_mark_ui(
    painter: &egui::Painter,
    net: &Network,
    origin: Pos2,
    mark: &ErrorMark,
    width: usize,
    style: &Style,
    labels: &[(Rect, String)],
) -> Rect {
    let rect = cell_rect(net, origin, (mark.row, mark.col), width, style).shrink(3.0);
    let color = if mark.error {
        theme::ERROR
    } else {
        theme::CAUTION
    };
    let stroke = Stroke::new(1.5, color);
    let c = [
        rect.left_top(),
        rect.right_top(),
        rect.right_bottom(),
        rect.left_bottom(),
        rect.left_top(),
    ];
    for w in c.windows(2) {
        painter.extend(egui::Shape::dashed_line(w, stroke, 4.0, 3.0));
    }
    let at = rect.right_top() + vec2(-6.0, 6.0);
    painter.circle_filled(at, 5.5, color);
    painter.text(
        at,
        Align2::CENTER_CENTER,
        "!",
        FontId::proportional(9.0),
        egui::Color32::WHITE,
    );
    let mid = rect.top() + style.m.mid;
    for (r, _) in labels
        .iter()
        .filter(|(r, _)| rect.contains(r.center()) && r.bottom() < mid)
    {
        painter.line_segment([r.left_bottom(), r.right_bottom()], Stroke::new(1.5, color));
    }
    rect
}

/// Where and with what the networks of a view are drawn.
pub(super) struct Drawn<'a> {
    pub(super) painter: &'a egui::Painter,
    pub(super) project: &'a Project,
    pub(super) style: &'a Style,
    /// The whole block's rectangle on screen.
    pub(super) rect: Rect,
    /// Its width.
    pub(super) width: f32,
}

impl Drawn<'_> {
    /// Network `i` (placed at `p`) in full: its selection, the network with the monitor's
    /// state, the error marks, the cursor and the rule under it; what was drawn goes into
    /// `geometry` (`marks`: a buffer for the "why?" cells of the network).
    pub(super) fn network(
        &self,
        b: &ladder_engine::model::Block,
        (i, p): (usize, &super::Placed),
        opts: &super::ViewOptions<'_>,
        live: Option<&super::Live<'_>>,
        geometry: &mut super::Geometry,
        marks: &mut Vec<(usize, usize)>,
    ) {
        let origin = self.rect.min + vec2(0.0, p.top);
        if let Some(sel) = opts.selection {
            selection_ui(
                self.painter,
                &b.networks[i],
                i,
                origin,
                p.height,
                self.width,
                &sel,
                self.style,
            );
        }
        let view = live.and_then(|l| (l.network)(i));
        let shown = match (live, &view) {
            (Some(l), Some(v)) => {
                marks.clear();
                marks.extend(l.marked.iter().filter(|m| m.0 == i).map(|m| (m.1, m.2)));
                Some(LiveNetwork {
                    view: v,
                    format: l.format,
                    forced: l.forced,
                    marked: marks,
                })
            }
            _ => None,
        };
        for mark in opts.coverage.iter().filter(|m| m.network == i) {
            let width = self.project.ladder.width;
            let r = cell_rect(
                &b.networks[i],
                origin,
                (mark.row, mark.col),
                width,
                self.style,
            )
            .shrink(1.0);
            self.painter
                .rect_filled(r, 2.0, super::cover_tint(mark.state));
            geometry.cover_marks.push((r, mark.state));
        }
        let labels_before = geometry.labels.len();
        network_ui(
            self.painter,
            self.project,
            (&b.networks[i], i),
            origin,
            self.style,
            shown.as_ref(),
            &mut geometry.labels,
        );
        for mark in opts.errors.iter().filter(|e| e.network == i) {
            let drawn = &geometry.labels[labels_before..];
            let width = self.project.ladder.width;
            let r = error_mark_ui(
                self.painter,
                &b.networks[i],
                origin,
                mark,
                width,
                self.style,
                drawn,
            );
            geometry.error_marks.push(r);
        }
        if let Some((cn, cr, cc)) = opts.cursor
            && cn == i
        {
            let width = self.project.ladder.width;
            if cr == b.networks[i].rows.len() {
                self.new_row_ui(&b.networks[i], origin, cr);
            }
            cursor_ui(
                self.painter,
                &b.networks[i],
                origin,
                (cr, cc),
                width,
                self.style,
            );
        }
        let sep = origin.y + p.height - 2.0;
        self.painter.line_segment(
            [pos2(self.rect.left(), sep), pos2(self.rect.right(), sep)],
            Stroke::new(0.5, theme::NETWORK_RULE),
        );
    }

    /// The new row offered below a network's last row (the cursor on it): the rails and the
    /// wire it would have, dashed and faint, so it reads as a place to draw, not yet a row.
    fn new_row_ui(&self, net: &Network, origin: Pos2, row: usize) {
        let m = &self.style.m;
        let width = self.project.ladder.width;
        let cell = cell_rect(net, origin, (row, 0), width, self.style);
        let rail = origin.x + m.margin;
        let right = rail + width as f32 * m.cell + m.output;
        let faint = Stroke::new(1.0, theme::NETWORK_RULE);
        let mid = cell.top() + m.mid;
        for line in [
            [pos2(rail, cell.top()), pos2(rail, cell.bottom())],
            [pos2(right, cell.top()), pos2(right, cell.bottom())],
            [pos2(rail, mid), pos2(right, mid)],
        ] {
            self.painter
                .extend(egui::Shape::dashed_line(&line, faint, 4.0, 4.0));
        }
    }
}
