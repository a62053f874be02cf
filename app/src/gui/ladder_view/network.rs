//! Painting one network: rails, contacts, coils, wires, links and boxes, and on top of them
//! what the online monitor shows (power flow, live values, forces, the "why?" marks), the
//! selection and the cursor.

use super::{Metrics, Place, operand_text, row_tops};
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

/// The address an operand stands for (a symbol through the symbol tables).
pub fn address_of(project: &Project, o: &Operand) -> Option<Address> {
    match o {
        Operand::Addr(a) => Some(*a),
        Operand::Symbol(s) => project.resolve_symbol(s),
        _ => None,
    }
}

/// Draws one network with its top-left at `origin`, with what the monitor shows when live.
pub(super) fn network_ui(
    painter: &egui::Painter,
    project: &Project,
    net: &Network,
    index: usize,
    origin: Pos2,
    style: &Style,
    live: Option<&LiveNetwork<'_>>,
) {
    let Style {
        m,
        mode,
        comments,
        titles,
    } = style;
    let (mode, comments) = (*mode, *comments);
    let width = project.ladder.width;
    let wire = Stroke::new(1.5, theme::WIRE);
    let power = Stroke::new(3.0, theme::POWER);
    let font = FontId::proportional(m.font);
    let title = if net.title.is_empty() || !titles {
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
    if comments && !net.comment.is_empty() {
        painter.text(
            pos2(origin.x + 4.0, y),
            Align2::LEFT_TOP,
            net.comment.lines().next().unwrap_or(""),
            font.clone(),
            theme::COMMENT,
        );
        y += m.header;
    }
    let rail_x = origin.x + m.margin;
    let col_x = |c: usize| rail_x + c as f32 * m.cell;
    let right_rail = col_x(width) + m.output + 8.0;
    let top = y;
    let mut row_tops = Vec::with_capacity(net.rows.len());
    for row in &net.rows {
        row_tops.push(y);
        y += m.row_height(&row.cells);
    }
    // Rails: the left one carries power whenever the program runs.
    painter.line_segment(
        [pos2(rail_x, top), pos2(rail_x, y)],
        Stroke::new(
            3.0,
            if live.is_some() {
                theme::POWER
            } else {
                theme::RAIL
            },
        ),
    );
    painter.line_segment(
        [pos2(right_rail, top), pos2(right_rail, y)],
        Stroke::new(3.0, theme::RAIL),
    );
    let cell_view = |r: usize, c: usize| live.and_then(|l| l.view.cells.get(r)?.get(c));
    let stroke = |on: bool| if on { power } else { wire };
    let forced =
        |o: &Operand| live.is_some_and(|l| address_of(project, o).is_some_and(|a| (l.forced)(a)));
    for (r, row) in net.rows.iter().enumerate() {
        let mid = row_tops[r] + m.row * 0.5;
        for (c, cell) in row.cells.iter().enumerate() {
            let x0 = col_x(c);
            let x1 = if c == width {
                x0 + m.output
            } else {
                x0 + m.cell
            };
            let v = cell_view(r, c);
            let (p_in, p_out) = v.map_or((false, false), |v| (v.power_in, v.power_out));
            if live.is_some_and(|l| l.marked.contains(&(r, c))) {
                let h = m.row_height(&row.cells);
                painter.rect_stroke(
                    Rect::from_min_max(
                        pos2(x0 + 1.0, row_tops[r] + 1.0),
                        pos2(x1 - 1.0, row_tops[r] + h - 1.0),
                    ),
                    3.0,
                    Stroke::new(2.5, theme::WHY),
                    StrokeKind::Inside,
                );
            }
            match cell {
                Cell::Empty => {}
                Cell::Wire => {
                    painter.line_segment([pos2(x0, mid), pos2(x1, mid)], stroke(p_in && p_out));
                }
                Cell::Contact { negated, operand } => {
                    let cx = (x0 + x1) * 0.5;
                    let gap = m.cell * 0.12;
                    let h = m.row * 0.22;
                    if v.and_then(|v| v.closed) == Some(true) {
                        // A closed contact is filled, as on GSKLadder's monitor screen.
                        painter.rect_filled(
                            Rect::from_min_max(pos2(cx - gap, mid - h), pos2(cx + gap, mid + h)),
                            0.0,
                            theme::POWER_FILL,
                        );
                    }
                    painter.line_segment([pos2(x0, mid), pos2(cx - gap, mid)], stroke(p_in));
                    painter.line_segment([pos2(cx + gap, mid), pos2(x1, mid)], stroke(p_out));
                    painter.line_segment([pos2(cx - gap, mid - h), pos2(cx - gap, mid + h)], wire);
                    painter.line_segment([pos2(cx + gap, mid - h), pos2(cx + gap, mid + h)], wire);
                    if *negated {
                        painter.line_segment(
                            [pos2(cx - gap * 1.4, mid + h), pos2(cx + gap * 1.4, mid - h)],
                            wire,
                        );
                    }
                    let label = BitLabel {
                        project,
                        mode,
                        font: &font,
                        size: m.font,
                    };
                    label.draw(
                        painter,
                        operand,
                        pos2(cx, mid - h - 2.0),
                        forced(operand),
                        pos2(cx + gap + 2.0, mid + h),
                    );
                }
                Cell::Coil { negated, operand } => {
                    let cx = x1 - m.output * 0.3;
                    let rad = m.row * 0.2;
                    if p_in {
                        painter.circle_filled(pos2(cx, mid), rad, theme::POWER_FILL);
                    }
                    painter.line_segment([pos2(x0, mid), pos2(cx - rad, mid)], stroke(p_in));
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
                    let label = BitLabel {
                        project,
                        mode,
                        font: &font,
                        size: m.font,
                    };
                    label.draw(
                        painter,
                        operand,
                        pos2(cx, mid - rad - 2.0),
                        forced(operand),
                        pos2(cx + rad + 2.0, mid + rad),
                    );
                }
                Cell::Box { op, operands } => {
                    let h = m.row_height(&row.cells) - 8.0;
                    let rect = Rect::from_min_size(
                        pos2(x0 + 6.0, row_tops[r] + 4.0),
                        vec2(m.output - 12.0, h),
                    );
                    if p_in {
                        painter.rect_filled(rect, 2.0, theme::POWER_BOX);
                    }
                    painter.line_segment([pos2(x0, mid), pos2(rect.left(), mid)], stroke(p_in));
                    painter.line_segment([pos2(rect.right(), mid), pos2(right_rail, mid)], wire);
                    painter.rect_stroke(rect, 2.0, wire, StrokeKind::Middle);
                    painter.text(
                        rect.center_top() + vec2(0.0, 2.0),
                        Align2::CENTER_TOP,
                        op.name(),
                        FontId::proportional(m.font * 1.1),
                        theme::INK,
                    );
                    for (i, o) in operands.iter().enumerate() {
                        let name = op.spec().operand(i).map_or("", |s| s.name);
                        let (text, color) =
                            operand_text(project, o, mode, Place::Box(*op, i), operands);
                        let p = rect.left_top() + vec2(4.0, m.line * (i as f32 + 1.0) + 2.0);
                        painter.text(
                            p,
                            Align2::LEFT_TOP,
                            format!("{name} {text}"),
                            font.clone(),
                            color,
                        );
                        let value = v.and_then(|v| v.values.get(i).copied().flatten());
                        if let (Some(l), Some(value)) = (live, value) {
                            let bytes = address_of(project, o)
                                .map_or(4, |a| u32::from(a.area.element_bytes()).max(1));
                            let shown = if forced(o) {
                                format!("{} F", l.format.show(value, bytes))
                            } else {
                                l.format.show(value, bytes)
                            };
                            painter.text(
                                pos2(rect.right() - 4.0, p.y),
                                Align2::RIGHT_TOP,
                                shown,
                                font.clone(),
                                theme::LIVE_VALUE,
                            );
                        }
                    }
                }
            }
            // A vertical link at the left edge of this column, down to the next row.
            if c > 0 && row.links.get(c).copied().unwrap_or(false) && r + 1 < net.rows.len() {
                let next_mid = row_tops[r + 1] + m.row * 0.5;
                // The link joins the nodes of both rows: powered when either side is.
                let on = cell_view(r, c - 1).is_some_and(|v| v.power_out)
                    || cell_view(r + 1, c - 1).is_some_and(|v| v.power_out);
                painter.line_segment([pos2(x0, mid), pos2(x0, next_mid)], stroke(on));
            }
        }
    }
}

/// How a contact's or coil's operand is labelled.
struct BitLabel<'a> {
    project: &'a Project,
    mode: DisplayMode,
    font: &'a FontId,
    size: f32,
}

impl BitLabel<'_> {
    /// The operand's text centred above `above`, and the force mark at `mark` when forced.
    fn draw(
        &self,
        painter: &egui::Painter,
        operand: &Operand,
        above: Pos2,
        forced: bool,
        mark: Pos2,
    ) {
        let (text, color) = operand_text(
            self.project,
            operand,
            self.mode,
            Place::Bit,
            std::slice::from_ref(operand),
        );
        painter.text(above, Align2::CENTER_BOTTOM, text, self.font.clone(), color);
        if forced {
            force_mark(painter, mark, self.size);
        }
    }
}

/// The mark of a forced element: a small "F" badge.
fn force_mark(painter: &egui::Painter, at: Pos2, font: f32) {
    let r = painter.text(
        at,
        Align2::LEFT_TOP,
        "F",
        FontId::monospace(font),
        theme::FORCED,
    );
    painter.rect_stroke(
        r.expand(1.0),
        2.0,
        Stroke::new(1.0, theme::FORCED),
        StrokeKind::Outside,
    );
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

/// Outlines the cursor's cell.
pub(super) fn cursor_ui(
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
    let x = origin.x + m.margin + col as f32 * m.cell;
    let w = if col >= width { m.output } else { m.cell };
    let rect = Rect::from_min_size(pos2(x, y), vec2(w, h));
    painter.rect_stroke(
        rect,
        2.0,
        Stroke::new(2.0, theme::CURSOR),
        StrokeKind::Inside,
    );
}
