//! The toolpath drawn into an image once per view (docs/online.md, "CNC page"): a 30 000-block
//! program has a quarter of a million points, too many to hand egui as lines every frame. The
//! path is rasterised — one pixel wide, rapids dashed — for the plot's bounds and size, and
//! the image is reused for as long as they stay; only zooming and panning draw it again.

use crate::gui::theme;
use egui::{Color32, ColorImage};
use egui_plot::{PlotPoint, PlotTransform};
use ladder_engine::cnc::toolpath::{PieceKind, Toolpath};

/// Pixels drawn, then skipped, along a rapid.
const DASH: (u32, u32) = (6, 4);

/// What an image was drawn for: the bounds, the size in pixels, the path.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RasterKey {
    /// Plot bounds, min and max.
    pub bounds: [[f64; 2]; 2],
    /// Image size, pixels.
    pub size: [usize; 2],
    /// The path's address (a new load is a new path).
    pub path: usize,
}

/// The image of `path` for the plot transform `t` at `pixels_per_point`, and its key.
pub fn rasterise(
    path: &Toolpath,
    t: &PlotTransform,
    pixels_per_point: f32,
) -> (ColorImage, RasterKey) {
    let frame = *t.frame();
    let w = ((frame.width() * pixels_per_point).round() as usize).clamp(1, 8192);
    let h = ((frame.height() * pixels_per_point).round() as usize).clamp(1, 8192);
    let key = RasterKey {
        bounds: [t.bounds().min(), t.bounds().max()],
        size: [w, h],
        path: std::ptr::from_ref(path) as usize,
    };
    let mut img = ColorImage::filled([w, h], Color32::TRANSPARENT);
    let to_px = |q: [f64; 2]| {
        let p = t.position_from_point(&PlotPoint::new(q[0], q[1]));
        [
            f64::from((p.x - frame.min.x) * pixels_per_point),
            f64::from((p.y - frame.min.y) * pixels_per_point),
        ]
    };
    // Programs repeat themselves (passes, loops, subprograms): a piece already drawn at the
    // same pixels (its ends and middle, its kind and length) is not drawn again.
    let mut drawn = std::collections::HashSet::new();
    let px = |q: [f64; 2]| {
        let p = to_px(q);
        [p[0].round() as i32, p[1].round() as i32]
    };
    for piece in &path.pieces {
        let (colour, dashed) = match piece.kind {
            PieceKind::Rapid => (theme::TOOLPATH_RAPID, true),
            PieceKind::Feed => (theme::TOOLPATH_FEED, false),
            PieceKind::Thread => (theme::TOOLPATH_THREAD, false),
        };
        let pts = &path.points[piece.start as usize..piece.end as usize];
        let seen = (
            px(pts[0]),
            px(pts[pts.len() / 2]),
            px(pts[pts.len() - 1]),
            pts.len(),
            piece.kind as u8,
        );
        if !drawn.insert(seen) {
            continue;
        }
        let mut run = 0u32;
        let mut from = to_px(pts[0]);
        for q in &pts[1..] {
            let to = to_px(*q);
            if let Some((a, b)) = clip(from, to, w as f64 - 1.0, h as f64 - 1.0) {
                let a = [a[0].round() as i32, a[1].round() as i32];
                let b = [b[0].round() as i32, b[1].round() as i32];
                line(&mut img, a, b, colour, dashed, &mut run);
            }
            from = to;
        }
    }
    (img, key)
}

/// A one-pixel line from `a` to `b` (pixels inside the image, Bresenham); `run` counts the
/// pixels of a dashed line so the dashes go on across its segments.
fn line(img: &mut ColorImage, a: [i32; 2], b: [i32; 2], c: Color32, dashed: bool, run: &mut u32) {
    let w = img.size[0];
    let (dx, dy) = ((b[0] - a[0]).abs(), -(b[1] - a[1]).abs());
    let (sx, sy) = ((b[0] - a[0]).signum(), (b[1] - a[1]).signum());
    let (mut x, mut y, mut err) = (a[0], a[1], dx + dy);
    loop {
        let on = !dashed || *run % (DASH.0 + DASH.1) < DASH.0;
        *run += 1;
        if on
            && x >= 0
            && y >= 0
            && (x as usize) < w
            && let Some(p) = img.pixels.get_mut(y as usize * w + x as usize)
        {
            *p = c;
        }
        if x == b[0] && y == b[1] {
            break;
        }
        let e2 = 2 * err;
        if e2 >= dy {
            err += dy;
            x += sx;
        }
        if e2 <= dx {
            err += dx;
            y += sy;
        }
    }
}

/// The part of a segment inside [0, w] × [0, h] (Liang–Barsky), if any.
fn clip(a: [f64; 2], b: [f64; 2], w: f64, h: f64) -> Option<([f64; 2], [f64; 2])> {
    let (dx, dy) = (b[0] - a[0], b[1] - a[1]);
    let (mut t0, mut t1) = (0.0f64, 1.0f64);
    for (p, q) in [(-dx, a[0]), (dx, w - a[0]), (-dy, a[1]), (dy, h - a[1])] {
        if p.abs() < 1e-12 {
            if q < 0.0 {
                return None;
            }
        } else {
            let r = q / p;
            if p < 0.0 {
                t0 = t0.max(r);
            } else {
                t1 = t1.min(r);
            }
        }
    }
    if t0 > t1 || !t0.is_finite() || !t1.is_finite() {
        return None;
    }
    Some((
        [a[0] + dx * t0, a[1] + dy * t0],
        [a[0] + dx * t1, a[1] + dy * t1],
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_segment_is_clipped_to_the_image_and_one_outside_is_dropped() {
        let (a, b) = clip([-10.0, 5.0], [20.0, 5.0], 9.0, 9.0).unwrap();
        assert_eq!((a, b), ([0.0, 5.0], [9.0, 5.0]));
        assert!(clip([-10.0, -5.0], [-1.0, -1.0], 9.0, 9.0).is_none());
        let mut img = ColorImage::filled([10, 10], Color32::TRANSPARENT);
        let mut run = 0;
        line(&mut img, [0, 2], [9, 2], Color32::RED, true, &mut run);
        let lit: Vec<bool> = (0..10)
            .map(|x| img.pixels[20 + x] == Color32::RED)
            .collect();
        // Six on, four off.
        assert_eq!(
            lit,
            [
                true, true, true, true, true, true, false, false, false, false
            ]
        );
    }
}
