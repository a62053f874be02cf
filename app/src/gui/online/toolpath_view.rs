//! The toolpath plot of the CNC screen (docs/gcode.md, "Toolpath"): the loaded program's whole
//! path as the CNC's dry run gives it, in the lathe's Z–X plane (Z across, X up, machine
//! coordinates), rapids dashed and feeds solid; over it the path the tool has really taken
//! since the program started, the tool's point, and the current block in its own colour. A
//! click on the path picks the block that made it; the plot zooms, pans and fits.

use crate::gui::i18n::{Lang, Msg};
use crate::gui::theme;
use egui_plot::{Line, LineStyle, Plot, PlotPoint, PlotPoints, Points};
use ladder_engine::cnc::toolpath::{PieceKind, Toolpath};
use ladder_engine::cnc::{CncStatus, RunState};
use std::sync::Arc;

/// Most trail points kept; beyond, every other one is dropped.
const TRAIL_MAX: usize = 200_000;

/// One polyline of the drawn path: pieces of one kind in a row.
#[derive(Clone, Debug)]
struct Run {
    kind: PieceKind,
    points: Vec<PlotPoint>,
}

/// The plot's state, kept by the caller between frames (UI state only).
#[derive(Clone, Debug, Default)]
pub struct ToolpathView {
    /// The path drawn, and its polylines built once.
    shown: Option<Arc<Toolpath>>,
    runs: Vec<Run>,
    /// Where the tool has been since the program started, (Z, X) mm.
    trail: Vec<PlotPoint>,
    last_run: RunState,
    /// Refit the plot at the next frame.
    fit: bool,
    /// The line a click on the path picked.
    pub picked: Option<usize>,
}

impl ToolpathView {
    /// Takes the status of this frame: a new path restarts the trail and refits, a program
    /// starting from IDLE restarts the trail, and the tool's point is added to it.
    pub fn update(&mut self, status: &CncStatus) {
        let path = status.toolpath.clone();
        let same = match (&self.shown, &path) {
            (Some(a), Some(b)) => Arc::ptr_eq(a, b),
            (None, None) => true,
            _ => false,
        };
        if !same {
            self.runs = path.as_deref().map(polylines).unwrap_or_default();
            self.shown = path;
            self.trail.clear();
            self.fit = true;
            self.picked = None;
        }
        if self.last_run == RunState::Idle && status.run == RunState::Run {
            self.trail.clear();
        }
        self.last_run = status.run;
        let p = tool_point(status);
        if self.trail.last() != Some(&p) {
            if self.trail.len() >= TRAIL_MAX {
                let kept: Vec<PlotPoint> = self.trail.iter().copied().step_by(2).collect();
                self.trail = kept;
            }
            self.trail.push(p);
        }
    }
}

/// The tool's point (Z, X) in mm, machine coordinates.
fn tool_point(status: &CncStatus) -> PlotPoint {
    PlotPoint::new(
        status.machine[1] as f64 / 1000.0,
        status.machine[0] as f64 / 1000.0,
    )
}

/// The pieces joined into polylines of one kind each.
fn polylines(t: &Toolpath) -> Vec<Run> {
    let mut runs: Vec<Run> = Vec::new();
    for p in &t.pieces {
        let pts = &t.points[p.start as usize..p.end as usize];
        match runs.last_mut() {
            Some(r) if r.kind == p.kind => {
                r.points
                    .extend(pts.iter().skip(1).map(|q| PlotPoint::new(q[0], q[1])));
            }
            _ => runs.push(Run {
                kind: p.kind,
                points: pts.iter().map(|q| PlotPoint::new(q[0], q[1])).collect(),
            }),
        }
    }
    runs
}

/// Draws the plot and its legend line; returns the line a click picked.
pub fn toolpath_ui(
    ui: &mut egui::Ui,
    status: &CncStatus,
    view: &mut ToolpathView,
    lang: Lang,
    height: f32,
) -> Option<usize> {
    let t = |m: Msg| m.text(lang);
    let path = view.shown.clone()?;
    ui.horizontal(|ui| {
        ui.strong(t(Msg::CncToolpath));
        if ui.button(t(Msg::CncFit)).clicked() {
            view.fit = true;
        }
        ui.label(format!("{} {}", path.blocks, t(Msg::CncBlocks)));
        if let Some((alarm, line)) = path.alarm {
            ui.colored_label(
                theme::ERROR,
                format!("{} {line}: {alarm:04}", t(Msg::CncToolpathStops)),
            );
        }
    });
    let mut plot = Plot::new("cnc-toolpath")
        .height(height)
        .data_aspect(1.0)
        .x_axis_label("Z")
        .y_axis_label("X")
        .allow_boxed_zoom(true)
        .show_grid(true);
    if std::mem::take(&mut view.fit) {
        plot = plot.reset();
    }
    let current = status.line;
    let tool = tool_point(status);
    let picked = view.picked;
    let response = plot.show(ui, |pui| {
        for (k, r) in view.runs.iter().enumerate() {
            let (colour, style) = match r.kind {
                PieceKind::Rapid => (theme::TOOLPATH_RAPID, LineStyle::dashed_loose()),
                PieceKind::Feed => (theme::TOOLPATH_FEED, LineStyle::Solid),
                PieceKind::Thread => (theme::TOOLPATH_THREAD, LineStyle::Solid),
            };
            pui.line(
                Line::new(format!("path-{k}"), PlotPoints::Borrowed(&r.points))
                    .color(colour)
                    .style(style)
                    .width(1.0)
                    .allow_hover(false),
            );
        }
        for (name, line, colour) in [
            ("current", current, theme::TOOLPATH_CURRENT),
            ("picked", picked, theme::TOOLPATH_PICKED),
        ] {
            let Some(line) = line else { continue };
            for p in path.pieces.iter().filter(|p| p.line == line) {
                let pts: Vec<PlotPoint> = path.points[p.start as usize..p.end as usize]
                    .iter()
                    .map(|q| PlotPoint::new(q[0], q[1]))
                    .collect();
                pui.line(
                    Line::new(name, PlotPoints::Owned(pts))
                        .color(colour)
                        .width(3.0),
                );
            }
        }
        pui.line(
            Line::new(t(Msg::CncExecuted), PlotPoints::Borrowed(&view.trail))
                .color(theme::TOOLPATH_EXECUTED)
                .width(2.0),
        );
        pui.points(
            Points::new(t(Msg::CncToolPoint), PlotPoints::Owned(vec![tool]))
                .color(theme::TOOLPATH_TOOL)
                .radius(5.0),
        );
    });
    let r = &response.response;
    let label = t(Msg::CncToolpathPlot);
    r.widget_info(|| egui::WidgetInfo::labeled(egui::Role::Canvas, true, label));
    if r.clicked()
        && let Some(pos) = r.interact_pointer_pos()
    {
        let at = response.transform.value_from_position(pos);
        // Within 8 pixels of the path.
        let tolerance = 8.0 * response.transform.dvalue_dpos()[0].abs();
        let piece = path.piece_near([at.x, at.y], tolerance);
        view.picked = piece.map(|k| path.pieces[k].line);
        return view.picked;
    }
    None
}
