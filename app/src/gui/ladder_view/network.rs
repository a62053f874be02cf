//! Painting one network: rails, contacts, coils, wires, links and boxes, and on top of them
//! what the online monitor shows (power flow, live values, forces, the "why?" marks), the
//! selection and the cursor.

use super::{COMMENT_LINES, ErrorMark, Metrics, Place, operand_text, row_tops};
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
    (net, index): (&Network, usize),
    origin: Pos2,
    style: &Style,
    live: Option<&LiveNetwork<'_>>,
    drawn: &mut Vec<(Rect, String)>,
) {
    let Style {
        m,
        mode,
        comments,
        titles,
        element_comments,
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
    if comments {
        for line in super::comment_lines(net) {
            painter.text(
                pos2(origin.x + 4.0, y),
                Align2::LEFT_TOP,
                line,
                font.clone(),
                theme::COMMENT,
            );
            y += m.header;
        }
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
    let label = BitLabel {
        project,
        mode,
        font: &font,
        size: m.font,
        line: m.line,
        comment: *element_comments,
    };
    for (r, row) in net.rows.iter().enumerate() {
        let mid = row_tops[r] + m.mid;
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
                    let h = m.symbol;
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
                    label.draw(
                        painter,
                        drawn,
                        operand,
                        Span {
                            centre: cx,
                            left: x0 + 3.0,
                            right: x1 - 3.0,
                        },
                        (mid - h - 3.0, mid + h + 3.0),
                        forced(operand).then_some(pos2(cx + gap + 2.0, mid + h)),
                    );
                }
                Cell::Coil { negated, operand } => {
                    let cx = x1 - m.output * 0.3;
                    let rad = m.symbol * 0.9;
                    let h_coil = m.symbol;
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
                    // The coil's label may use the whole output column, never past the rail.
                    label.draw(
                        painter,
                        drawn,
                        operand,
                        Span {
                            centre: (x0 + right_rail) * 0.5,
                            left: x0 + 3.0,
                            right: right_rail - 4.0,
                        },
                        (mid - h_coil - 3.0, mid + h_coil + 3.0),
                        forced(operand).then_some(pos2(cx + rad + 2.0, mid + rad)),
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
                let next_mid = row_tops[r + 1] + m.mid;
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
    /// The distance between two label lines.
    line: f32,
    /// The language of the element comment written under it, when comments are shown.
    comment: Option<&'static str>,
}

/// The horizontal room of a label: centred on `centre`, never past `left` or `right`.
#[derive(Clone, Copy)]
struct Span {
    centre: f32,
    left: f32,
    right: f32,
}

impl BitLabel<'_> {
    /// The operand's text above `ys.0` (address over symbol in "both" mode, each on its own
    /// line), the element comment below `ys.1` when shown, and the force mark at `mark`
    /// (given when the element is forced).
    /// Every line is cut with an ellipsis at the span's edges: the tooltip shows it whole.
    fn draw(
        &self,
        painter: &egui::Painter,
        drawn: &mut Vec<(Rect, String)>,
        operand: &Operand,
        span: Span,
        ys: (f32, f32),
        mark: Option<Pos2>,
    ) {
        let (text, color) = operand_text(
            self.project,
            operand,
            self.mode,
            Place::Bit,
            std::slice::from_ref(operand),
        );
        let line = self.line;
        // "ADDRESS:SYMBOL" is one text for the find and the tooltip; drawn, it is two lines.
        let lines: Vec<&str> = match (self.mode, text.split_once(':')) {
            (DisplayMode::Both, Some((a, s))) => vec![a, s],
            _ => vec![text.as_str()],
        };
        for (i, t) in lines.iter().rev().enumerate() {
            let y = ys.0 - line * i as f32;
            drawn.push(self.line(painter, t, span, y, Align2::CENTER_BOTTOM, color));
        }
        if let Some(lang) = self.comment
            && let Some(a) = address_of(self.project, operand)
            && let Some(c) = self.project.comment_of(a, lang)
        {
            drawn.push(self.comment(painter, c, span, ys.1));
        }
        if let Some(at) = mark {
            force_mark(painter, at, self.size);
        }
    }

    /// An element comment from height `y` down: wrapped to the span (its own line breaks
    /// kept), at most [`COMMENT_LINES`] lines, the last ending with "…" when more is left.
    fn comment(&self, painter: &egui::Painter, text: &str, span: Span, y: f32) -> (Rect, String) {
        let width = (span.right - span.left).max(self.size);
        let mut job = egui::text::LayoutJob::default();
        job.append(
            text,
            0.0,
            egui::TextFormat {
                font_id: self.font.clone(),
                color: theme::COMMENT,
                line_height: Some(self.line),
                ..Default::default()
            },
        );
        job.halign = egui::Align::Center;
        job.wrap = egui::text::TextWrapping {
            max_width: width,
            max_rows: COMMENT_LINES,
            break_anywhere: false,
            overflow_character: Some('…'),
        };
        let galley = painter.layout_job(job);
        // A centred galley is laid out about x = 0; its rectangle says how far each way.
        let r = galley.rect;
        let x = span
            .centre
            .clamp(span.left - r.min.x, (span.right - r.max.x).max(span.left));
        let rect = r.translate(vec2(x, y));
        let shown = galley
            .rows
            .iter()
            .flat_map(|r| r.glyphs.iter().map(|g| g.chr))
            .collect();
        painter.galley(pos2(x, y), galley, theme::COMMENT);
        (rect, shown)
    }

    /// One line of text at height `y`, shortened with "…" to fit the span; returns where
    /// it went and what it says.
    fn line(
        &self,
        painter: &egui::Painter,
        text: &str,
        span: Span,
        y: f32,
        align: Align2,
        color: egui::Color32,
    ) -> (Rect, String) {
        let width = (span.right - span.left).max(self.size);
        let mut job =
            egui::text::LayoutJob::simple_singleline(text.into(), self.font.clone(), color);
        job.wrap = egui::text::TextWrapping {
            max_width: width,
            max_rows: 1,
            break_anywhere: true,
            overflow_character: Some('…'),
        };
        let galley = painter.layout_job(job);
        let w = galley.size().x;
        let x = (span.centre - w * 0.5).clamp(span.left, (span.right - w).max(span.left));
        let top = match align.y() {
            egui::Align::Max => y - galley.size().y,
            _ => y,
        };
        let rect = Rect::from_min_size(pos2(x, top), galley.size());
        // What is on screen, the ellipsis included (the galley's text is the whole one).
        let shown = galley
            .rows
            .iter()
            .flat_map(|r| r.glyphs.iter().map(|g| g.chr))
            .collect();
        painter.galley(rect.min, galley, color);
        (rect, shown)
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
