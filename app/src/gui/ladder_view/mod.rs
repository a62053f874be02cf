//! The ladder view: a block's networks drawn with rails, contacts, coils, wires, vertical links
//! and function boxes. Only the networks inside the visible part are laid out and painted, so
//! a 5000-step program scrolls as smoothly as a small one.

mod label;
mod network;
mod scroll;

pub use label::address_of;
pub use network::LiveNetwork;
use network::{Drawn, Style};
pub use scroll::Anchor;

use super::settings::{DisplayMode, NumFormat};
use super::theme;
use egui::{Color32, Pos2, Rect, Sense, pos2, vec2};
use ladder_engine::Address;
use ladder_engine::model::region::Region as Selection;
use ladder_engine::model::{Cell, Network, Operand, Project};
use ladder_engine::vm::monitor::NetworkView;
use std::ops::Range;

pub use super::theme::WRONG_TYPE;
use super::theme::{MAPPED, UNDEFINED};

/// Where an operand stands, for its type check.
#[derive(Clone, Copy, Debug)]
pub enum OperandPlace {
    /// On a contact or coil: a bit.
    Bit,
    /// Operand `i` of a function instruction.
    Box(ladder_engine::Op, usize),
}

/// Whether an operand has the type its place needs (undefined symbols are not wrong-typed:
/// they are red).
fn right_type(project: &Project, o: &Operand, place: OperandPlace, operands: &[Operand]) -> bool {
    match place {
        OperandPlace::Bit => match o {
            Operand::Addr(a) => a.bit.is_some(),
            Operand::Symbol(name) => project.resolve_symbol(name).is_none_or(|a| a.bit.is_some()),
            _ => false,
        },
        OperandPlace::Box(op, i) => {
            if let Operand::Symbol(name) = o
                && project.resolve_symbol(name).is_none()
            {
                return true;
            }
            ladder_engine::compiler::operand_ok(op, operands, i, project.profile())
        }
    }
}

/// The space under a network's last row, at every zoom.
pub const NETWORK_GAP: f32 = 8.0;

/// Most lines of an element comment in the diagram: longer comments end with "…".
pub const COMMENT_LINES: usize = 3;

/// Sizes at a zoom.
#[derive(Clone, Copy, Debug)]
pub struct Metrics {
    /// Width of a contact column.
    pub cell: f32,
    /// Height of a plain row.
    pub row: f32,
    /// Width of the output column.
    pub output: f32,
    /// Height of one operand line in a box, and of one label line.
    pub line: f32,
    /// Height of a network's header.
    pub header: f32,
    /// Font size.
    pub font: f32,
    /// Left of the left rail: row numbers, and where a click selects a whole row.
    pub margin: f32,
    /// How far below a row's top its wire runs (contacts and coils sit on it).
    pub mid: f32,
    /// Half the height of a contact; a coil's radius is a little less.
    pub symbol: f32,
    /// Label lines above a contact or coil (1, or 2 for "address and symbol").
    pub above: usize,
    /// Label lines below it (the element comment's, when shown).
    pub below: usize,
}

/// Room between a label and the row's edge or the symbol.
const LABEL_PAD: f32 = 3.0;

impl Metrics {
    /// The sizes at `zoom` percent, with one label line above each contact.
    pub fn at(zoom: u16) -> Metrics {
        Metrics::with_labels(zoom, DisplayMode::Address, false)
    }

    /// The sizes at `zoom` with room for the labels: one line above a contact (two for
    /// "address and symbol"), and the element comment's lines under it when shown. Each
    /// row holds its own labels, so no label reaches into the row above or below.
    pub fn with_labels(zoom: u16, mode: DisplayMode, element_comments: bool) -> Metrics {
        let z = f32::from(zoom) / 100.0;
        // Whole pixels: text rows are laid out on the pixel grid.
        let line = (14.0 * z).ceil();
        let symbol = 44.0 * z * 0.22;
        let above = if mode == DisplayMode::Both { 2 } else { 1 };
        let below = if element_comments { COMMENT_LINES } else { 0 };
        let top = LABEL_PAD + above as f32 * line + LABEL_PAD + symbol;
        let bottom = symbol + LABEL_PAD + below as f32 * line + LABEL_PAD;
        let row = (44.0 * z).max(top + bottom);
        Metrics {
            cell: 84.0 * z,
            row,
            output: 150.0 * z,
            line,
            header: 22.0 * z,
            font: 11.0 * z,
            margin: 26.0 * z,
            // What is left over goes half above, half below: the symbol stays central.
            mid: top + (row - top - bottom) * 0.5,
            symbol,
            above,
            below,
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
        let comment = if comments {
            comment_line_count(n) as f32 * self.header
        } else {
            0.0
        };
        self.header + comment + rows + NETWORK_GAP
    }
}

/// How an operand is written and coloured in the current display mode, orange when it has
/// the wrong type for its place.
pub fn operand_text(
    project: &Project,
    o: &Operand,
    mode: DisplayMode,
    place: OperandPlace,
    operands: &[Operand],
) -> (String, Color32) {
    let (text, color) = plain_operand_text(project, o, mode);
    if color != UNDEFINED && !right_type(project, o, place, operands) {
        (text, WRONG_TYPE)
    } else {
        (text, color)
    }
}

fn plain_operand_text(project: &Project, o: &Operand, mode: DisplayMode) -> (String, Color32) {
    match o {
        Operand::Symbol(name) => match project.resolve_symbol(name) {
            Some(a) => match mode {
                DisplayMode::Address => (a.to_string(), MAPPED),
                DisplayMode::Symbol => (name.clone(), theme::INK),
                DisplayMode::Both => (format!("{a}:{name}"), theme::INK),
            },
            None => (name.clone(), UNDEFINED),
        },
        Operand::Addr(a) => {
            let symbol = project.symbol_of(*a);
            match (mode, symbol) {
                (DisplayMode::Symbol, Some(s)) => (s.to_string(), theme::INK),
                (DisplayMode::Both, Some(s)) => (format!("{a}:{s}"), theme::INK),
                _ => (a.to_string(), theme::INK),
            }
        }
        other => (other.to_string(), theme::INK),
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
    /// Width of the left margin.
    pub margin: f32,
    /// Height of each network.
    pub heights: Vec<f32>,
    /// The zoom it was drawn at, in percent.
    pub zoom: u16,
    /// How far below a row's top its wire runs (where contacts and coils sit).
    pub mid: f32,
    /// Every contact and coil label drawn (operand lines and element comments): where, and
    /// the text as shown, ellipsis included.
    pub labels: Vec<(Rect, String)>,
    /// Every cell drawn with an error mark (frame) last frame.
    pub error_marks: Vec<Rect>,
    /// Every cell tinted with its coverage last frame.
    pub cover_marks: Vec<(Rect, ladder_engine::coverage::State)>,
    /// The part of the ladder on screen, in screen coordinates.
    pub visible: Option<Rect>,
}

impl Geometry {
    /// Takes the sizes of a block laid out at `zoom` in `style`: network tops and heights,
    /// row tops (with the new row offered below network `new_row`); the labels and marks
    /// drawn last frame are forgotten.
    fn lay_out(
        &mut self,
        b: &ladder_engine::model::Block,
        placed: &[Placed],
        style: &Style,
        zoom: u16,
        new_row: Option<usize>,
    ) {
        let m = &style.m;
        self.cell = m.cell;
        self.output = m.output;
        self.margin = m.margin;
        self.zoom = zoom;
        self.mid = m.mid;
        self.labels.clear();
        self.error_marks.clear();
        self.cover_marks.clear();
        self.tops = placed.iter().map(|p| p.top).collect();
        self.heights = placed.iter().map(|p| p.height).collect();
        self.rows = b
            .networks
            .iter()
            .enumerate()
            .map(|(i, n)| {
                let mut tops = row_tops(n, m, style.comments);
                if new_row == Some(i) {
                    let end = tops.last().copied().unwrap_or(m.header)
                        + n.rows.last().map_or(0.0, |r| m.row_height(&r.cells));
                    tops.push(end);
                }
                tops
            })
            .collect();
    }

    /// The screen centre of a cell.
    pub fn cell_center(&self, network: usize, row: usize, col: usize) -> Option<Pos2> {
        let top = self.origin.y + self.tops.get(network)? + self.rows.get(network)?.get(row)?;
        let x = self.origin.x + self.margin + col as f32 * self.cell;
        let w = if col >= self.width {
            self.output
        } else {
            self.cell
        };
        // On the element itself, not on its label above.
        Some(pos2(x + w * 0.5, top + self.mid))
    }
}

/// A cell the last compile found wrong, in the block shown.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ErrorMark {
    /// The network.
    pub network: usize,
    /// The row.
    pub row: usize,
    /// The column (the output column is the ladder's width).
    pub col: usize,
    /// An error (else a warning).
    pub error: bool,
}

/// An element's coverage, in the block shown (View → Coverage).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CoverMark {
    /// The network.
    pub network: usize,
    /// The row.
    pub row: usize,
    /// The column (the output column is the ladder's width).
    pub col: usize,
    /// Covered, half or never.
    pub state: ladder_engine::coverage::State,
}

/// The tint of a coverage state.
pub fn cover_tint(state: ladder_engine::coverage::State) -> egui::Color32 {
    match state {
        ladder_engine::coverage::State::Covered => theme::COVER_FULL,
        ladder_engine::coverage::State::Half => theme::COVER_HALF,
        ladder_engine::coverage::State::Never => theme::COVER_NEVER,
    }
}

/// How a block is shown.
#[derive(Clone, Copy, Debug)]
pub struct ViewOptions<'a> {
    /// Zoom in percent.
    pub zoom: u16,
    /// Operand display.
    pub mode: DisplayMode,
    /// Network comments shown.
    pub comments: bool,
    /// Network titles shown.
    pub titles: bool,
    /// The cursor's (network, row, column) in this block.
    pub cursor: Option<(usize, usize, usize)>,
    /// The selection in this block.
    pub selection: Option<Selection>,
    /// Tells the open documents apart, so each document's blocks keep their own scroll
    /// position and a project never opens where the last one was scrolled to.
    pub document: u64,
    /// A point to keep where it is on screen: the zoom has just changed.
    pub anchor: Option<Anchor>,
    /// Bring the cursor cell into sight: it moved, or the ladder changed under it.
    pub follow: bool,
    /// Element comments under contacts and coils, in this language (`zh`, `en`).
    pub element_comments: Option<&'static str>,
    /// The cells of this block the last compile found wrong.
    pub errors: &'a [ErrorMark],
    /// The coverage of this block's elements, while View → Coverage is on.
    pub coverage: &'a [CoverMark],
}

/// The top of each row of a network, relative to the network's top (after its header and,
/// when shown, its comment lines).
fn row_tops(net: &Network, m: &Metrics, comments: bool) -> Vec<f32> {
    let mut y = m.header;
    if comments {
        y += comment_line_count(net) as f32 * m.header;
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

/// The comment lines under a network's title: its comment, then one line per language that
/// has one, in the order of the comments CSV (`zh`, then `en`, then any other), each marked
/// with its language. Only the first line of a many-line comment is drawn.
pub fn comment_lines(net: &Network) -> Vec<String> {
    let mut lines = Vec::new();
    if let Some(first) = net.comment.lines().next().filter(|l| !l.is_empty()) {
        lines.push(first.to_string());
    }
    let order = |lang: &str| match lang {
        "zh" => 0,
        "en" => 1,
        _ => 2,
    };
    let mut langs: Vec<(&String, &String)> = net.comments.iter().collect();
    langs.sort_by_key(|(l, _)| (order(l), l.as_str()));
    for (lang, text) in langs {
        if let Some(first) = text.lines().next().filter(|l| !l.is_empty()) {
            lines.push(format!("[{lang}] {first}"));
        }
    }
    lines
}

/// How many lines [`comment_lines`] gives, without building them (every network's height is
/// worked out every frame).
fn comment_line_count(net: &Network) -> usize {
    let shown = |t: &str| t.lines().next().is_some_and(|l| !l.is_empty());
    usize::from(shown(&net.comment)) + net.comments.values().filter(|t| shown(t)).count()
}

/// Where a point of the ladder view falls.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Hit {
    /// A cell.
    Cell {
        /// Network.
        network: usize,
        /// Row.
        row: usize,
        /// Column (the output column is `width`).
        col: usize,
    },
    /// A network's title line (selects the network).
    Header {
        /// Network.
        network: usize,
    },
    /// The margin left of the rail (selects the row).
    Margin {
        /// Network.
        network: usize,
        /// Row.
        row: usize,
    },
}

impl Hit {
    /// The network hit.
    pub fn network(self) -> usize {
        match self {
            Hit::Cell { network, .. } | Hit::Header { network } | Hit::Margin { network, .. } => {
                network
            }
        }
    }
}

/// What the pointer did in the ladder view this frame.
#[derive(Clone, Debug, Default)]
pub struct ViewEvents {
    /// A primary click, and the modifiers held.
    pub click: Option<(Hit, egui::Modifiers)>,
    /// A double click.
    pub double_click: Option<Hit>,
    /// Where the double click was, on screen.
    pub double_click_at: Option<Pos2>,
    /// A drag started this frame, where the button went down.
    pub drag_start: Option<Hit>,
    /// Where a drag in progress (or ending) is now.
    pub drag_now: Option<Hit>,
    /// The drag ended this frame.
    pub drag_done: bool,
    /// A secondary (right) click.
    pub secondary: Option<Hit>,
    /// The view's response, for its context menu.
    pub response: Option<egui::Response>,
    /// The networks drawn (the online monitor records only these).
    pub visible: Range<usize>,
    /// What the pointer rests on.
    pub hover: Option<Hit>,
    /// Ctrl+wheel over the view: zoom in (`true`) or out, about the pointer's position.
    pub zoom: Option<(bool, Pos2)>,
}

/// What the online monitor puts on the ladder view.
pub struct Live<'a> {
    /// The view of network `i` of the block from the last scan (or a recorded tick).
    pub network: &'a dyn Fn(usize) -> Option<NetworkView>,
    /// How box values are written.
    pub format: NumFormat,
    /// Whether an address is forced.
    pub forced: &'a dyn Fn(Address) -> bool,
    /// Cells marked by "why?": (network, row, column).
    pub marked: &'a [(usize, usize, usize)],
    /// The view shows a recorded past tick, not the present (the paper is tinted).
    pub past: bool,
}

/// What a point in network `net` (drawn at `origin`) falls on.
fn hit_in(
    project: &Project,
    net: &Network,
    index: usize,
    origin: Pos2,
    p: Pos2,
    m: &Metrics,
    comments: bool,
) -> Option<Hit> {
    let tops = row_tops(net, m, comments);
    let first = tops.first().copied().unwrap_or(m.header);
    if p.y < origin.y + first {
        return Some(Hit::Header { network: index });
    }
    let row = (0..net.rows.len()).find(|r| {
        let top = origin.y + tops[*r];
        p.y >= top && p.y < top + m.row_height(&net.rows[*r].cells)
    })?;
    let x = p.x - origin.x - m.margin;
    if x < 0.0 {
        return Some(Hit::Margin {
            network: index,
            row,
        });
    }
    let col = ((x / m.cell).floor() as usize).min(project.ladder.width);
    Some(Hit::Cell {
        network: index,
        row,
        col,
    })
}

/// Draws block `block` of the project, scrolled; `jump_to` scrolls a network into view once.
/// Returns what the pointer did.
pub fn block_ui(
    ui: &mut egui::Ui,
    project: &Project,
    block: usize,
    opts: &ViewOptions<'_>,
    jump_to: &mut Option<usize>,
    geometry: &mut Geometry,
    live: Option<&Live<'_>>,
) -> ViewEvents {
    let Some(b) = project.ladder.blocks.get(block) else {
        return ViewEvents::default();
    };
    let (zoom, mode, comments) = (opts.zoom, opts.mode, opts.comments);
    let m = Metrics::with_labels(zoom, mode, opts.element_comments.is_some());
    // Offsets of every network: plain arithmetic over the model, no layout or text.
    let mut placed = Vec::with_capacity(b.networks.len());
    let mut y = 0.0;
    // The cursor on the new row below a network's last row: the network shows that row.
    let new_row = opts
        .cursor
        .filter(|(n, r, _)| b.networks.get(*n).is_some_and(|net| *r == net.rows.len()))
        .map(|c| c.0);
    for (i, n) in b.networks.iter().enumerate() {
        let extra = if new_row == Some(i) { m.row } else { 0.0 };
        let h = m.network_height(n, comments) + extra;
        placed.push(Placed { top: y, height: h });
        y += h;
    }
    let total = vec2(
        m.margin + m.cell * project.ladder.width as f32 + m.output + 40.0,
        y.max(1.0),
    );
    let style = Style {
        m,
        mode,
        comments,
        titles: opts.titles,
        element_comments: opts.element_comments,
    };
    let mut area = egui::ScrollArea::both()
        .id_salt(("ladder", opts.document, block))
        .auto_shrink([false, false]);
    // Past the last network there is room for what the view shows: an anchored zoom at the
    // end of a block may need the last network higher than the block's end allows, and the
    // room stays while the view is there (it shrinks as the view scrolls back up).
    let mut room = 0.0f32;
    // No spring past the edges: the first frame of a zoom sets an offset beyond the old
    // content's end, which a rubber band would take for an overscroll and pull back from.
    ui.spacing_mut().scroll.kinetic.rubber_band = false;
    if let Some(a) = &opts.anchor {
        let view = ui.available_rect_before_wrap();
        if let Some(off) = scroll::offset_for(a, b, &placed, &m, zoom, comments, view.min) {
            area = area.scroll_offset(off);
            room = off.y + view.height();
            ui.ctx().request_repaint();
        }
    }
    area.show_viewport(ui, |ui, viewport| {
        let total = vec2(total.x, total.y.max(room).max(viewport.max.y));
        let (rect, response) = ui.allocate_exact_size(total, Sense::click_and_drag());
        geometry.origin = rect.min;
        geometry.visible = Some(viewport.translate(rect.min.to_vec2()));
        geometry.width = project.ladder.width;
        geometry.lay_out(b, &placed, &style, zoom, new_row);
        let hit = |p: Pos2| {
            let y = p.y - rect.min.y;
            let i = placed.partition_point(|q| q.top + q.height <= y);
            let q = placed.get(i)?;
            let origin = rect.min + vec2(0.0, q.top);
            hit_in(project, &b.networks[i], i, origin, p, &m, comments)
        };
        let mut events = pointer_events(ui, &response, hit);
        let painter = ui.painter_at(rect);
        // Black on white, like a printed ladder, whatever the UI theme.
        painter.rect_filled(
            rect.intersect(viewport.translate(rect.min.to_vec2())),
            0.0,
            if live.is_some_and(|l| l.past) {
                theme::PAPER_PAST
            } else {
                theme::PAPER
            },
        );
        if let Some(target) = jump_to.take()
            && let Some(p) = placed.get(target)
        {
            // The network at the top, and sideways the cursor's cell in sight (End goes to
            // the coils); one scroll target holds both axes, so the x is worked out here.
            let cell = opts
                .cursor
                .filter(|c| c.0 == target)
                .and_then(|(n, r, c)| geometry.cell_rect(n, r, c));
            let left = cell.map_or(0.0, |cell| {
                let pad = m.cell * 0.15;
                let (a, b) = (cell.min.x - rect.min.x - pad, cell.max.x - rect.min.x + pad);
                if a < viewport.min.x {
                    a
                } else if b > viewport.max.x {
                    b - viewport.width()
                } else {
                    viewport.min.x
                }
            });
            // Aligned to the top-left, egui leaves an item spacing before the target.
            let x = rect.min.x + left.max(0.0) + ui.spacing().item_spacing.x;
            let r = Rect::from_min_max(
                pos2(x, rect.min.y + p.top),
                pos2(x + 1.0, rect.min.y + p.top + p.height),
            );
            ui.scroll_to_rect(r, Some(egui::Align::TOP));
        } else if opts.follow
            && let Some((n, r, c)) = opts.cursor
            && let Some(cell) = geometry.cell_rect(n, r, c)
        {
            // The least scrolling that shows the cell with a little room around it.
            ui.scroll_to_rect(cell.expand(m.cell * 0.15), None);
        }
        if response.contains_pointer() {
            events.zoom = wheel_zoom(ui, response.id.with("zoom"));
        }
        // Only the networks that intersect the visible part.
        let first = placed.partition_point(|p| p.top + p.height < viewport.min.y);
        events.visible = first..first;
        let mut marks = Vec::new();
        for (i, p) in placed.iter().enumerate().skip(first) {
            if p.top > viewport.max.y {
                break;
            }
            events.visible.end = i + 1;
            let drawn = Drawn {
                painter: &painter,
                project,
                style: &style,
                rect,
                width: total.x,
            };
            drawn.network(b, (i, p), opts, live, geometry, &mut marks);
        }
        events.response = Some(response);
        events
    })
    .inner
}

/// Ctrl+wheel over the view: one zoom step per wheel notch, in (`true`) or out, about the
/// pointer. egui spreads a notch over several frames (about ln 1.22 of zoom in all); the step
/// is taken once half a notch has come and the notch's tail then pays back the rest, so no
/// remainder carries into the next notch and turns one notch into two steps.
fn wheel_zoom(ui: &egui::Ui, id: egui::Id) -> Option<(bool, Pos2)> {
    const NOTCH: f32 = 0.2;
    let delta = ui.input(|i| i.zoom_delta());
    if delta == 1.0 {
        // The wheel has stopped: what is left of a gesture is dropped.
        ui.data_mut(|d| d.remove::<f32>(id));
        return None;
    }
    let acc = ui.data_mut(|d| {
        let acc = d.get_temp_mut_or_default::<f32>(id);
        *acc += delta.ln();
        *acc
    });
    if acc.abs() < NOTCH / 2.0 {
        return None;
    }
    ui.data_mut(|d| d.insert_temp(id, acc - NOTCH.copysign(acc)));
    let pos = ui.input(|i| i.pointer.hover_pos())?;
    Some((acc > 0.0, pos))
}

/// What the pointer did over the view this frame, each place read through `hit`.
fn pointer_events(
    ui: &egui::Ui,
    response: &egui::Response,
    hit: impl Fn(Pos2) -> Option<Hit>,
) -> ViewEvents {
    let mut events = ViewEvents::default();
    let pointer = response.interact_pointer_pos();
    if response.clicked() {
        let mods = ui.input(|i| i.modifiers);
        events.click = pointer.and_then(&hit).map(|h| (h, mods));
    }
    // A third quick click is still a double-click to a user.
    if response.double_clicked() || response.triple_clicked() {
        events.double_click = pointer.and_then(&hit);
        events.double_click_at = pointer;
    }
    if response.secondary_clicked() {
        events.secondary = pointer.and_then(&hit);
    }
    if response.hovered() {
        events.hover = ui.input(|i| i.pointer.hover_pos()).and_then(&hit);
    }
    if response.drag_started() {
        events.drag_start = ui.input(|i| i.pointer.press_origin()).and_then(&hit);
    }
    if response.dragged() || response.drag_stopped() {
        let now = pointer.or_else(|| ui.input(|i| i.pointer.latest_pos()));
        events.drag_now = now.and_then(&hit);
        events.drag_done = response.drag_stopped();
    }
    events
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn operands_are_blue_red_or_orange_as_the_manual_says() {
        let mut p = Project::default();
        p.symbol_tables[0].rows.push(ladder_engine::model::Symbol {
            name: "START".into(),
            address: ladder_engine::Address::parse("X0002.1").unwrap(),
            comments: Default::default(),
        });
        p.symbol_tables[0].rows.push(ladder_engine::model::Symbol {
            name: "SPEED".into(),
            address: ladder_engine::Address::parse("D0010").unwrap(),
            comments: Default::default(),
        });
        let o = |t: &str| Operand::parse(t).unwrap();
        let bit =
            |t: &str| operand_text(&p, &o(t), DisplayMode::Address, OperandPlace::Bit, &[o(t)]);
        assert_eq!(bit("START"), ("X0002.1".into(), MAPPED));
        assert_eq!(bit("NOWHERE"), ("NOWHERE".into(), UNDEFINED));
        assert_eq!(bit("X0002.1").1, theme::INK);
        assert_eq!(bit("R0010").1, WRONG_TYPE, "a byte on a contact");
        assert_eq!(
            bit("SPEED").1,
            WRONG_TYPE,
            "a symbol of a byte on a contact"
        );
        let tmrb = [o("T0000"), o("DT0004"), o("R0300.0")];
        let boxed = |i: usize, ops: &[Operand]| {
            operand_text(
                &p,
                &ops[i],
                DisplayMode::Address,
                OperandPlace::Box(ladder_engine::Op::Tmrb, i),
                ops,
            )
            .1
        };
        assert_eq!(boxed(0, &tmrb), theme::INK);
        let wrong = [o("Y0001.0"), o("DT0004"), o("R0300.0")];
        assert_eq!(boxed(0, &wrong), WRONG_TYPE, "TMRB takes a T address first");
    }

    #[test]
    fn a_network_shows_its_comment_and_a_line_per_language_in_the_csv_order() {
        let mut n = Network::new(ladder_engine::model::NetworkId(1), 9);
        n.comment = "free text\nsecond line".into();
        n.comments.insert("en".into(), "Spindle start".into());
        n.comments.insert("zh".into(), "主轴启动".into());
        n.comments.insert("ja".into(), String::new());
        let lines = comment_lines(&n);
        assert_eq!(lines, ["free text", "[zh] 主轴启动", "[en] Spindle start"]);
        assert_eq!(comment_line_count(&n), lines.len());
        let m = Metrics::at(100);
        assert_eq!(
            m.network_height(&n, true) - m.network_height(&n, false),
            3.0 * m.header,
            "room for each line"
        );
    }
}
