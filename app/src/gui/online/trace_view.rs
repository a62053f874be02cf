//! The signal trace widget: a timing chart of chosen bits and values over virtual time, as a
//! logic analyser draws it. Each signal has its own lane: a bit as low and high steps, a
//! value as a step line scaled to its lane. A cursor (a click on the chart; hovering shows
//! where it would go) reads every signal's value at one tick in a table beside the chart.
//!
//! A widget: [`trace_ui`] draws [`TraceData`] that the caller records and returns
//! [`TraceEvent`]s; [`trace_csv`] writes the data as `sim --trace` writes its trace file
//! (docs/scripts.md, "Trace file").

use crate::gui::i18n::{Lang, Msg};
use crate::gui::theme;
use egui_plot::{GridMark, HoverPosition, Line, Plot, PlotPoint, Text, VLine};
use std::fmt::Write as _;

/// Virtual milliseconds per tick (the engine's).
pub use ladder_engine::vm::TICK_MS;

/// One traced signal: its values as steps, one point per change.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct TraceSignal {
    /// The name shown and written in the CSV header (an address or `cnc.KEY`).
    pub name: String,
    /// Whether it is a bit (a digital lane) or a value (a step line).
    pub bit: bool,
    /// `(tick, value from that tick on)`, in ascending tick order.
    pub points: Vec<(u64, i64)>,
}

impl TraceSignal {
    /// The value at a tick: that of the last point at or before it, 0 before the first.
    pub fn value_at(&self, tick: u64) -> i64 {
        let after = self.points.partition_point(|(t, _)| *t <= tick);
        after.checked_sub(1).map_or(0, |k| self.points[k].1)
    }
}

/// What the trace shows: the signals and the ticks recorded.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct TraceData {
    /// The signals, one lane each, in this order from the top.
    pub signals: Vec<TraceSignal>,
    /// The first tick shown.
    pub first: u64,
    /// The last tick shown.
    pub last: u64,
}

/// The trace widget's own state.
#[derive(Clone, Debug, Default)]
pub struct TraceState {
    /// Whether recording is paused (the Pause button flips it and says so in an event).
    pub paused: bool,
    /// The tick the cursor was placed on.
    pub cursor: Option<u64>,
    /// Fit the whole trace into the chart at the next frame.
    fit: bool,
}

/// What the user asked of the trace.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum TraceEvent {
    /// Pause (`true`) or resume recording.
    Pause(bool),
    /// Stop tracing the signal at this index of [`TraceData::signals`].
    Remove(usize),
    /// Save the trace as CSV ([`trace_csv`]).
    ExportCsv,
    /// Throw the recorded values away.
    Clear,
}

/// The trace as `sim --trace` writes it: a header `tick,ms,NAME…`, then one line per tick
/// from the first to the last, `tick,8 × tick,value…`. With no signal the text is empty, as
/// a trace with nothing watched is.
pub fn trace_csv(data: &TraceData) -> String {
    let mut out = String::new();
    if data.signals.is_empty() {
        return out;
    }
    out.push_str("tick,ms");
    for s in &data.signals {
        let _ = write!(out, ",{}", s.name);
    }
    out.push('\n');
    // One cursor per signal: the rows go forward, so each point is passed once.
    let mut next = vec![0usize; data.signals.len()];
    let mut value = vec![0i64; data.signals.len()];
    for tick in data.first..=data.last {
        let _ = write!(out, "{tick},{}", tick * TICK_MS);
        for (k, s) in data.signals.iter().enumerate() {
            while let Some(&(_, v)) = s.points.get(next[k]).filter(|(t, _)| *t <= tick) {
                value[k] = v;
                next[k] += 1;
            }
            let _ = write!(out, ",{}", value[k]);
        }
        out.push('\n');
    }
    out
}

/// Seconds of virtual time at a tick.
fn seconds(tick: u64) -> f64 {
    (tick * TICK_MS) as f64 / 1000.0
}

/// The tick nearest to a time in seconds, within the data.
fn tick_at(data: &TraceData, x: f64) -> u64 {
    let t = (x * 1000.0 / TICK_MS as f64).round().max(0.0) as u64;
    t.clamp(data.first, data.last.max(data.first))
}

/// Lane `i`'s bottom: the first signal is the top lane.
fn lane_base(count: usize, i: usize) -> f64 {
    (count - 1 - i) as f64
}

/// Where a lane's trace runs: from `LOW` to `HIGH` above the lane's bottom.
const LOW: f64 = 0.1;
const HIGH: f64 = 0.8;

/// A signal as step-line points in plot coordinates, from the first tick to the last.
fn steps(s: &TraceSignal, data: &TraceData, base: f64) -> Vec<[f64; 2]> {
    let (lo, hi) = range(s, data);
    let y = |v: i64| {
        let f = if s.bit {
            f64::from(u8::from(v != 0))
        } else if hi > lo {
            (v - lo) as f64 / (hi - lo) as f64
        } else {
            0.5
        };
        base + LOW + (HIGH - LOW) * f
    };
    let mut v = s.value_at(data.first);
    let mut pts = vec![[seconds(data.first), y(v)]];
    for &(t, nv) in s
        .points
        .iter()
        .filter(|(t, _)| *t > data.first && *t <= data.last)
    {
        pts.push([seconds(t), y(v)]);
        pts.push([seconds(t), y(nv)]);
        v = nv;
    }
    pts.push([seconds(data.last), y(v)]);
    pts
}

/// The smallest and largest value a signal takes in the ticks shown.
fn range(s: &TraceSignal, data: &TraceData) -> (i64, i64) {
    let start = s.value_at(data.first);
    s.points
        .iter()
        .filter(|(t, _)| *t > data.first && *t <= data.last)
        .fold((start, start), |(lo, hi), (_, v)| (lo.min(*v), hi.max(*v)))
}

/// Value changes labelled in a value lane at most; more would only overlap.
const MAX_VALUE_LABELS: usize = 40;

/// Draws the trace and returns what the user asked for.
pub fn trace_ui(
    ui: &mut egui::Ui,
    data: &TraceData,
    state: &mut TraceState,
    lang: Lang,
) -> Vec<TraceEvent> {
    let t = |m: Msg| m.text(lang);
    let mut events = Vec::new();
    ui.horizontal(|ui| {
        let pause = if state.paused {
            Msg::TraceResume
        } else {
            Msg::TracePause
        };
        if ui.button(t(pause)).clicked() {
            state.paused = !state.paused;
            events.push(TraceEvent::Pause(state.paused));
        }
        if ui.button(t(Msg::TraceFit)).clicked() {
            state.fit = true;
        }
        if ui.button(t(Msg::TraceExport)).clicked() {
            events.push(TraceEvent::ExportCsv);
        }
        if ui.button(t(Msg::TraceClear)).clicked() {
            state.cursor = None;
            events.push(TraceEvent::Clear);
        }
        ui.weak(t(Msg::TraceHint));
    });
    if data.signals.is_empty() {
        ui.label(t(Msg::TraceNoSignal));
        return events;
    }
    let readout_width = 240.0;
    let mut hovered = None;
    ui.horizontal_top(|ui| {
        let width = (ui.available_width() - readout_width).max(200.0);
        // At least a readable lane per signal; all the room there is when it is bounded.
        let wanted = 60.0 + 28.0 * data.signals.len() as f32;
        let room = ui.available_height();
        let height = if room.is_finite() {
            room.max(wanted)
        } else {
            wanted
        };
        hovered = chart(ui, data, state, lang, width, height);
        ui.vertical(|ui| readout(ui, data, state, hovered, lang, &mut events));
    });
    events
}

/// The chart; returns the tick under the pointer, if any.
fn chart(
    ui: &mut egui::Ui,
    data: &TraceData,
    state: &mut TraceState,
    lang: Lang,
    width: f32,
    height: f32,
) -> Option<u64> {
    let n = data.signals.len();
    let names: Vec<&str> = data.signals.iter().map(|s| s.name.as_str()).collect();
    let centre = |i: usize| lane_base(n, i) + (LOW + HIGH) / 2.0;
    let mut plot = Plot::new("signal-trace")
        .width(width)
        .height(height)
        // Lanes are fixed: only time zooms and pans.
        .allow_zoom([true, false])
        .allow_drag([true, false])
        // The wheel zooms time, as on a logic analyser (below); a sideways scroll pans.
        .allow_scroll([true, false])
        .allow_boxed_zoom(true)
        .x_axis_label(Msg::TraceTime.text(lang))
        .x_axis_formatter(|m: GridMark, _| format!("{:.3}", m.value))
        .y_grid_spacer(move |_| {
            (0..n)
                .map(|i| GridMark {
                    value: centre(i),
                    step_size: 1.0,
                })
                .collect()
        })
        .y_axis_formatter(move |m: GridMark, _| {
            (0..n)
                .find(|i| (centre(*i) - m.value).abs() < 1e-6)
                .map(|i| names[i].to_string())
                .unwrap_or_default()
        })
        .y_axis_min_width(60.0)
        .label_formatter(|pos: &HoverPosition<'_>| match pos {
            HoverPosition::NearDataPoint {
                plot_name,
                position,
                ..
            } => Some(format!("{plot_name}\n{:.3} s", position.x)),
            HoverPosition::Elsewhere { position } => Some(format!("{:.3} s", position.x)),
        });
    if std::mem::take(&mut state.fit) {
        plot = plot.reset();
    }
    let cursor = state.cursor;
    let response = plot.show(ui, |pui| {
        pui.set_plot_bounds_y(-0.1..=n as f64);
        for (i, s) in data.signals.iter().enumerate() {
            let base = lane_base(n, i);
            let colour = if s.bit {
                theme::TRACE_BIT
            } else {
                theme::TRACE_VALUE
            };
            pui.line(
                Line::new(s.name.clone(), steps(s, data, base))
                    .color(colour)
                    .width(1.5),
            );
            if !s.bit {
                let changes: Vec<_> = s
                    .points
                    .iter()
                    .filter(|(t, _)| *t >= data.first && *t <= data.last)
                    .collect();
                if changes.len() <= MAX_VALUE_LABELS {
                    for (t, v) in changes {
                        let at = PlotPoint::new(seconds(*t), base + HIGH);
                        pui.text(
                            Text::new(s.name.clone(), at, v.to_string())
                                .color(colour)
                                .anchor(egui::Align2::LEFT_BOTTOM),
                        );
                    }
                }
            }
        }
        if let Some(c) = cursor {
            pui.vline(VLine::new("cursor", seconds(c)).color(theme::TRACE_CURSOR));
        }
        let hovering = pui.response().hovered();
        let wheel = pui.ctx().input(|i| i.smooth_scroll_delta.y);
        if hovering && wheel != 0.0 {
            pui.zoom_bounds_around_hovered(egui::vec2((wheel / 200.0).exp(), 1.0));
        }
        let pointer = hovering.then(|| pui.pointer_coordinate()).flatten();
        (
            pointer.map(|p| tick_at(data, p.x)),
            pui.response().clicked(),
        )
    });
    let (hovered, clicked) = response.inner;
    if clicked && let Some(tick) = hovered {
        state.cursor = Some(tick);
    }
    hovered
}

/// The value of every signal at the cursor (or at the pointer while it is over the chart, or
/// at the last tick), with a button to stop tracing each.
fn readout(
    ui: &mut egui::Ui,
    data: &TraceData,
    state: &TraceState,
    hovered: Option<u64>,
    lang: Lang,
    events: &mut Vec<TraceEvent>,
) {
    let t = |m: Msg| m.text(lang);
    let tick = hovered.or(state.cursor).unwrap_or(data.last);
    ui.horizontal(|ui| {
        ui.label(t(Msg::TraceTick));
        ui.monospace(tick.to_string());
        ui.monospace(format!("{:.3} s", seconds(tick)));
    });
    egui::Grid::new("signal-trace-readout")
        .striped(true)
        .num_columns(3)
        .show(ui, |ui| {
            ui.strong(t(Msg::TraceSignal));
            ui.strong(t(Msg::TraceValue));
            ui.label("");
            ui.end_row();
            for (i, s) in data.signals.iter().enumerate() {
                ui.monospace(&s.name);
                ui.monospace(s.value_at(tick).to_string());
                if ui.small_button(t(Msg::TraceRemove)).clicked() {
                    events.push(TraceEvent::Remove(i));
                }
                ui.end_row();
            }
        });
}

#[cfg(test)]
mod tests {
    use super::*;
    use egui_kittest::Harness;
    use egui_kittest::kittest::Queryable;

    fn signal(name: &str, bit: bool, points: &[(u64, i64)]) -> TraceSignal {
        TraceSignal {
            name: name.into(),
            bit,
            points: points.to_vec(),
        }
    }

    fn sample() -> TraceData {
        TraceData {
            signals: vec![
                signal("Y0003.7", true, &[(2, 1), (4, 0)]),
                signal("T0000", false, &[(1, 0), (3, 8), (5, 16)]),
            ],
            first: 1,
            last: 5,
        }
    }

    #[test]
    fn the_value_at_a_tick_is_the_last_point_at_or_before_it() {
        let s = signal("D0010", false, &[(3, 7), (5, -2), (9, 4)]);
        assert_eq!(s.value_at(0), 0, "before the first point");
        assert_eq!(s.value_at(2), 0);
        assert_eq!(s.value_at(3), 7, "at a point");
        assert_eq!(s.value_at(4), 7);
        assert_eq!(s.value_at(5), -2);
        assert_eq!(s.value_at(8), -2);
        assert_eq!(s.value_at(9), 4);
        assert_eq!(s.value_at(1000), 4, "after the last point");
        assert_eq!(signal("X", true, &[]).value_at(5), 0);
    }

    #[test]
    fn the_csv_is_the_sim_trace_format() {
        let expected = "tick,ms,Y0003.7,T0000\n\
                        1,8,0,0\n\
                        2,16,1,0\n\
                        3,24,1,8\n\
                        4,32,0,8\n\
                        5,40,0,16\n";
        assert_eq!(trace_csv(&sample()), expected);
    }

    #[test]
    fn the_csv_of_no_signal_is_empty_and_points_before_the_first_tick_count() {
        assert_eq!(trace_csv(&TraceData::default()), "");
        let data = TraceData {
            signals: vec![signal("cnc.spindle", false, &[(1, 800), (7, 0)])],
            first: 5,
            last: 7,
        };
        assert_eq!(
            trace_csv(&data),
            "tick,ms,cnc.spindle\n5,40,800\n6,48,800\n7,56,0\n"
        );
    }

    #[test]
    fn steps_rise_and_fall_at_the_changes_within_the_lane() {
        let data = sample();
        let pts = steps(&data.signals[0], &data, 1.0);
        // In tenths of a lane: low at 1.1, high at 1.8.
        let ys: Vec<i64> = pts.iter().map(|p| (p[1] * 10.0).round() as i64).collect();
        assert_eq!(ys, [11, 11, 18, 18, 11, 11]);
        assert_eq!(pts[1][0], seconds(2));
        assert_eq!(pts.last().unwrap()[0], seconds(5));
    }

    type Shown = (TraceData, TraceState, Vec<TraceEvent>);

    #[test]
    fn the_buttons_ask_for_export_pause_and_removal() {
        let mut h = Harness::builder()
            .with_size(egui::vec2(1000.0, 500.0))
            .build_ui_state(
                |ui, (data, state, events): &mut Shown| {
                    events.extend(trace_ui(ui, data, state, Lang::En));
                },
                (sample(), TraceState::default(), Vec::new()),
            );
        h.run();
        h.get_by_label("Export CSV").click();
        h.run();
        assert_eq!(h.state().2, [TraceEvent::ExportCsv]);
        h.get_by_label("Pause").click();
        h.run();
        assert_eq!(h.state().2[1], TraceEvent::Pause(true));
        assert!(h.state().1.paused);
        h.get_by_label("Resume");
        h.get_all_by_label("Remove").nth(1).unwrap().click();
        h.run();
        assert_eq!(h.state().2[2], TraceEvent::Remove(1));
        // The readout shows the values at the last tick without a cursor.
        h.get_by_label("16");
    }

    #[test]
    fn a_click_on_the_chart_places_the_cursor_and_the_readout_follows_it() {
        let mut h = Harness::builder()
            .with_size(egui::vec2(1000.0, 400.0))
            .build_ui_state(
                |ui, (data, state, events): &mut Shown| {
                    events.extend(trace_ui(ui, data, state, Lang::En));
                },
                (sample(), TraceState::default(), Vec::new()),
            );
        h.run();
        // The middle of the chart: ticks 1–5 fill it, so this is about tick 3.
        let at = egui::pos2(440.0, 200.0);
        h.hover_at(at);
        h.run();
        for pressed in [true, false] {
            h.event(egui::Event::PointerButton {
                pos: at,
                button: egui::PointerButton::Primary,
                pressed,
                modifiers: egui::Modifiers::default(),
            });
        }
        h.run();
        let cursor = h.state().1.cursor.expect("the click placed the cursor");
        assert!((2..=4).contains(&cursor), "tick {cursor}");
        // Away from the chart the readout shows the cursor's tick.
        h.hover_at(egui::pos2(990.0, 390.0));
        h.run();
        h.get_by_label(&cursor.to_string());
        let t0 = sample().signals[1].value_at(cursor).to_string();
        assert!(h.query_all_by_label(&t0).count() >= 1);
        assert!(
            h.state().2.is_empty(),
            "placing the cursor asks nothing of the app"
        );
    }
}
