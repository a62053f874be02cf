//! The toolpath plot of the CNC screen (docs/gcode.md, "Toolpath"): the loaded program's whole
//! path as the CNC's dry run gives it, in the lathe's Z–X plane (Z across, X up, machine
//! coordinates), rapids dashed and feeds solid; over it the path the tool has really taken
//! since the program started, the tool's point, and the current block in its own colour. A
//! click on the path picks the block that made it; the plot zooms, pans and fits.

use super::toolpath_raster::{RasterKey, rasterise};
use crate::gui::i18n::{Lang, Msg};
use crate::gui::theme;
use egui_plot::{Line, Plot, PlotBounds, PlotImage, PlotPoint, PlotPoints, Points};
use ladder_engine::cnc::toolpath::Toolpath;
use ladder_engine::cnc::{CncStatus, RunState};
use std::sync::Arc;

/// Most trail points kept; beyond, every other one is dropped.
const TRAIL_MAX: usize = 200_000;

/// The path's image on the GPU.
#[derive(Clone)]
struct Texture(egui::TextureHandle);

impl std::fmt::Debug for Texture {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "Texture({:?})", self.0.id())
    }
}

/// The plot's state, kept by the caller between frames (UI state only).
#[derive(Clone, Debug, Default)]
pub struct ToolpathView {
    /// The path drawn, its bounding box (min, max of (Z, X)), and its image for the view.
    shown: Option<Arc<Toolpath>>,
    bbox: Option<([f64; 2], [f64; 2])>,
    raster: Option<(RasterKey, Texture)>,
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
            self.bbox = path.as_deref().and_then(bounding_box);
            self.raster = None;
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

/// The smallest box holding every point of the path.
fn bounding_box(t: &Toolpath) -> Option<([f64; 2], [f64; 2])> {
    let first = *t.points.first()?;
    Some(t.points.iter().fold((first, first), |(lo, hi), p| {
        (
            [lo[0].min(p[0]), lo[1].min(p[1])],
            [hi[0].max(p[0]), hi[1].max(p[1])],
        )
    }))
}

/// The plot bounds that show the whole box with a margin in a frame of `size` (points), one
/// millimetre as long across as up.
fn fitted(bbox: ([f64; 2], [f64; 2]), size: egui::Vec2) -> PlotBounds {
    let (lo, hi) = bbox;
    let span = [(hi[0] - lo[0]).max(1.0), (hi[1] - lo[1]).max(1.0)];
    let (w, h) = (f64::from(size.x.max(1.0)), f64::from(size.y.max(1.0)));
    // mm per point: the larger of what either direction needs, plus 5 %.
    let scale = (span[0] / w).max(span[1] / h) * 1.1;
    let centre = [(lo[0] + hi[0]) / 2.0, (lo[1] + hi[1]) / 2.0];
    let half = [scale * w / 2.0, scale * h / 2.0];
    PlotBounds::from_min_max(
        [centre[0] - half[0], centre[1] - half[1]],
        [centre[0] + half[0], centre[1] + half[1]],
    )
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
    // The bounds are the view's own: fitted to the path on demand, then as the user zooms and
    // pans (auto bounds would grow around the path's image every frame).
    let plot = Plot::new("cnc-toolpath")
        .height(height)
        .data_aspect(1.0)
        .auto_bounds(false)
        .allow_double_click_reset(false)
        .x_axis_label("Z")
        .y_axis_label("X")
        .allow_boxed_zoom(true)
        .show_grid(true);
    let fit = std::mem::take(&mut view.fit);
    let current = status.line;
    let tool = tool_point(status);
    let picked = view.picked;
    let bbox = view.bbox;
    let raster = &mut view.raster;
    let response = plot.show(ui, |pui| {
        let frame = pui.transform().frame().size();
        let mut fit_later = false;
        match bbox {
            // The frame's size is known from the second frame on.
            Some(_) if fit && frame.x < 2.0 => fit_later = true,
            Some(b) if fit => pui.set_plot_bounds(fitted(b, frame)),
            _ => draw_image(pui, &path, raster),
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
        fit_later
    });
    if response.inner {
        view.fit = true;
        ui.ctx().request_repaint();
    }
    let r = &response.response;
    if r.double_clicked() {
        view.fit = true;
    }
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

/// Puts the path's image in the plot, drawn again when the bounds or the size have changed
/// since it was made (the transform is the last frame's, so the image fits the bounds it was
/// drawn for and is placed by them).
fn draw_image(
    pui: &mut egui_plot::PlotUi<'_>,
    path: &Toolpath,
    raster: &mut Option<(RasterKey, Texture)>,
) {
    let t = *pui.transform();
    if t.frame().width() < 2.0 || t.frame().height() < 2.0 {
        return;
    }
    let ppp = pui.ctx().pixels_per_point();
    let want = RasterKey {
        bounds: [t.bounds().min(), t.bounds().max()],
        size: [
            ((t.frame().width() * ppp).round() as usize).clamp(1, 8192),
            ((t.frame().height() * ppp).round() as usize).clamp(1, 8192),
        ],
        path: std::ptr::from_ref(path) as usize,
    };
    if raster.as_ref().is_none_or(|(k, _)| *k != want) {
        let (img, key) = rasterise(path, &t, ppp);
        let options = egui::TextureOptions::NEAREST;
        match raster {
            Some((k, tex)) => {
                tex.0.set(img, options);
                *k = key;
            }
            None => {
                let tex = pui.ctx().load_texture("cnc-toolpath", img, options);
                *raster = Some((key, Texture(tex)));
            }
        }
    }
    let Some((key, tex)) = raster.as_ref() else {
        return;
    };
    let [lo, hi] = key.bounds;
    let centre = PlotPoint::new((lo[0] + hi[0]) / 2.0, (lo[1] + hi[1]) / 2.0);
    let size = egui::vec2((hi[0] - lo[0]) as f32, (hi[1] - lo[1]) as f32);
    pui.image(PlotImage::new("path", tex.0.id(), centre, size).allow_hover(false));
}
