//! The trace's chart, drawn segment by segment: every lane is a row of horizontal and vertical
//! strokes inside its own band, whatever the zoom. Changes closer than a pixel merge into one
//! vertical stroke spanning what the signal took there, so a one-tick pulse is a thin step and
//! a thousand changes cost a pixel column each, never a filled shape.

use super::{TICK_MS, TraceData, TraceSignal};
use crate::gui::theme;
use egui::{Color32, Pos2, Rect, Stroke};

/// A window of ticks shown across the chart's width (fractional while zoomed).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Window {
    /// The tick at the left edge.
    pub from: f64,
    /// The tick at the right edge.
    pub to: f64,
}

impl Window {
    /// Everything recorded.
    pub fn all(data: &TraceData) -> Window {
        Window {
            from: data.first as f64,
            to: (data.last as f64).max(data.first as f64 + 1.0),
        }
    }

    /// The x of a tick in `rect`.
    pub fn x(&self, rect: Rect, tick: f64) -> f32 {
        rect.left() + ((tick - self.from) / (self.to - self.from)) as f32 * rect.width()
    }

    /// The tick at an x in `rect`.
    pub fn tick(&self, rect: Rect, x: f32) -> f64 {
        self.from + f64::from((x - rect.left()) / rect.width()) * (self.to - self.from)
    }

    /// Zoomed by `factor` (< 1 zooms in) around tick `at`, at least 4 ticks wide, and kept
    /// within the recorded ticks.
    pub fn zoomed(self, at: f64, factor: f64, data: &TraceData) -> Window {
        let span = ((self.to - self.from) * factor).max(4.0);
        let left = (at - self.from) / (self.to - self.from);
        Window {
            from: at - span * left,
            to: at - span * left + span,
        }
        .clamped(data)
    }

    /// Moved by `ticks`, kept within the recorded ticks.
    pub fn panned(self, ticks: f64, data: &TraceData) -> Window {
        Window {
            from: self.from + ticks,
            to: self.to + ticks,
        }
        .clamped(data)
    }

    fn clamped(self, data: &TraceData) -> Window {
        let all = Window::all(data);
        let span = (self.to - self.from).min(all.to - all.from);
        let from = self.from.clamp(all.from, all.to - span);
        Window {
            from,
            to: from + span,
        }
    }
}

/// One stroke of a lane.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Seg {
    /// Where it starts.
    pub a: Pos2,
    /// Where it ends (same y for a level, same x for an edge).
    pub b: Pos2,
    /// Its colour: a bit's 1 and 0 differ, edges are their own.
    pub colour: Color32,
}

/// Where a lane's trace runs inside its band: its low and high y.
pub fn levels(band: Rect) -> (f32, f32) {
    let pad = (band.height() * 0.2).max(3.0);
    (band.bottom() - pad, band.top() + pad)
}

/// The strokes of a signal in its band over a window. A bit is low or high, green where it
/// is 1; a value is scaled between the smallest and largest it takes in the window.
pub fn lane_segments(s: &TraceSignal, window: Window, band: Rect) -> Vec<Seg> {
    let (low, high) = levels(band);
    let first = window.from.floor().max(0.0) as u64;
    let last = window.to.ceil().max(0.0) as u64;
    let (lo, hi) = range(s, first, last);
    let y = |v: i64| -> f32 {
        let f = if s.bit {
            f32::from(u8::from(v != 0))
        } else if hi > lo {
            ((v - lo) as f64 / (hi - lo) as f64) as f32
        } else {
            0.5
        };
        low + (high - low) * f
    };
    let level_colour = |v: i64| match (s.bit, v != 0) {
        (true, true) => theme::TRACE_BIT,
        (true, false) => theme::TRACE_BIT_LOW,
        (false, _) => theme::TRACE_VALUE,
    };
    let clip = |x: f32| x.clamp(band.left(), band.right());
    let mut out = Vec::new();
    let mut v = s.value_at(first);
    let mut x0 = band.left();
    // The pixel column of the last edge, and what the signal spanned in it.
    let mut column: Option<(f32, f32, f32)> = None;
    let flush = |out: &mut Vec<Seg>, column: &mut Option<(f32, f32, f32)>| {
        if let Some((x, y0, y1)) = column.take()
            && y0 != y1
        {
            out.push(Seg {
                a: Pos2::new(x, y0),
                b: Pos2::new(x, y1),
                colour: theme::TRACE_EDGE,
            });
        }
    };
    for &(t, nv) in s.points.iter().filter(|(t, _)| *t > first && *t <= last) {
        let x = clip(window.x(band, t as f64).round());
        match &mut column {
            Some((cx, y0, y1)) if *cx == x => {
                *y0 = y0.min(y(nv));
                *y1 = y1.max(y(nv));
            }
            _ => {
                flush(&mut out, &mut column);
                if x > x0 {
                    out.push(Seg {
                        a: Pos2::new(x0, y(v)),
                        b: Pos2::new(x, y(v)),
                        colour: level_colour(v),
                    });
                }
                column = Some((x, y(v).min(y(nv)), y(v).max(y(nv))));
            }
        }
        v = nv;
        x0 = x;
    }
    flush(&mut out, &mut column);
    let right = clip(window.x(band, last as f64));
    if right > x0 {
        out.push(Seg {
            a: Pos2::new(x0, y(v)),
            b: Pos2::new(right, y(v)),
            colour: level_colour(v),
        });
    }
    out
}

/// The smallest and largest value a signal takes from tick `first` to `last`.
pub fn range(s: &TraceSignal, first: u64, last: u64) -> (i64, i64) {
    let start = s.value_at(first);
    s.points
        .iter()
        .filter(|(t, _)| *t > first && *t <= last)
        .fold((start, start), |(lo, hi), (_, v)| (lo.min(*v), hi.max(*v)))
}

/// Time marks for the axis: a round step of seconds giving about one mark per 90 px.
pub fn time_marks(window: Window, width: f32) -> Vec<f64> {
    let secs = |t: f64| t * TICK_MS as f64 / 1000.0;
    let span = secs(window.to) - secs(window.from);
    let wanted = span / f64::from((width / 90.0).max(1.0));
    let step = [1.0, 2.0, 5.0]
        .iter()
        .flat_map(|m| (-3..4).map(move |e| m * 10f64.powi(e)))
        .filter(|s| *s >= wanted)
        .fold(f64::INFINITY, f64::min);
    if !step.is_finite() {
        return Vec::new();
    }
    let mut t = (secs(window.from) / step).ceil() * step;
    let mut out = Vec::new();
    while t <= secs(window.to) + 1e-9 {
        out.push(t);
        t += step;
    }
    out
}

/// Draws the strokes.
pub fn paint(painter: &egui::Painter, segs: &[Seg]) {
    for s in segs {
        painter.line_segment([s.a, s.b], Stroke::new(1.5, s.colour));
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn pulse() -> TraceSignal {
        TraceSignal {
            name: "Y0010.0".into(),
            bit: true,
            points: vec![(500, 1), (501, 0)],
        }
    }

    #[test]
    fn a_one_tick_pulse_is_a_step_within_its_lane_at_any_zoom() {
        let band = Rect::from_min_size(Pos2::new(100.0, 40.0), egui::vec2(600.0, 30.0));
        for window in [
            Window {
                from: 0.0,
                to: 7500.0,
            },
            Window {
                from: 490.0,
                to: 510.0,
            },
        ] {
            let segs = lane_segments(&pulse(), window, band);
            let (low, high) = levels(band);
            for s in &segs {
                assert!(s.a.x == s.b.x || s.a.y == s.b.y, "only steps: {s:?}");
                for p in [s.a, s.b] {
                    assert!(band.contains(p), "{p:?} inside the lane");
                    assert!((high..=low).contains(&p.y), "between low and high");
                }
            }
            let high_run: f32 = segs
                .iter()
                .filter(|s| s.a.y == high && s.b.y == high)
                .map(|s| s.b.x - s.a.x)
                .sum();
            let tick = band.width() / (window.to - window.from) as f32;
            assert!(high_run <= tick.max(1.0) + 0.5, "high for one tick only");
            assert!(
                segs.iter()
                    .any(|s| s.a.y != s.b.y && s.b.y == low.max(s.a.y)),
                "it rises from low"
            );
        }
    }

    #[test]
    fn a_bit_draws_its_1_and_its_0_in_different_colours_centred_on_the_label() {
        let band = Rect::from_min_size(Pos2::new(0.0, 0.0), egui::vec2(200.0, 30.0));
        let segs = lane_segments(
            &pulse(),
            Window {
                from: 490.0,
                to: 510.0,
            },
            band,
        );
        let (low, high) = levels(band);
        let colour_at = |y: f32| segs.iter().find(|s| s.a.y == y && s.b.y == y).unwrap();
        assert_eq!(colour_at(high).colour, theme::TRACE_BIT);
        assert_eq!(colour_at(low).colour, theme::TRACE_BIT_LOW);
        assert!(((low + high) / 2.0 - band.center().y).abs() < 0.01);
    }

    #[test]
    fn thousands_of_changes_cost_a_stroke_per_pixel_column() {
        let s = TraceSignal {
            name: "T0000".into(),
            bit: false,
            points: (0..7500).map(|t| (t, (t % 125) as i64 * 8)).collect(),
        };
        let band = Rect::from_min_size(Pos2::ZERO, egui::vec2(400.0, 30.0));
        let segs = lane_segments(
            &s,
            Window {
                from: 0.0,
                to: 7499.0,
            },
            band,
        );
        assert!(segs.len() <= 2 * 401, "{} strokes", segs.len());
        assert!(
            segs.iter()
                .all(|s| band.contains(s.a) && band.contains(s.b))
        );
    }

    #[test]
    fn zoom_and_pan_stay_within_the_record() {
        let data = TraceData {
            signals: vec![],
            first: 100,
            last: 1100,
        };
        let w = Window::all(&data).zoomed(600.0, 0.1, &data);
        assert!((w.to - w.from - 100.0).abs() < 1e-6);
        assert!(w.from < 600.0 && w.to > 600.0);
        let p = w.panned(-10_000.0, &data);
        assert_eq!(p.from, 100.0);
        let z = w.zoomed(600.0, 100.0, &data);
        assert_eq!((z.from, z.to), (100.0, 1100.0), "zooming out stops at all");
        assert!(!time_marks(Window::all(&data), 600.0).is_empty());
    }
}
