//! The signal trace widget: a timing chart of chosen bits and values over virtual time, as a
//! logic analyser draws it. Each signal has its own lane (`chart`): a bit as low and high
//! steps in two colours, a value as a step line scaled to its lane. A cursor (a click on the
//! chart; hovering shows where it would go) reads every signal's value at one tick, shown
//! beside each lane's name and in the toolbar, so the readout is always on screen.
//!
//! A widget: [`trace_ui`] draws [`TraceData`] that the caller records and returns
//! [`TraceEvent`]s; [`trace_csv`] writes the data as `sim --trace` writes its trace file
//! (docs/scripts.md, "Trace file").

use crate::gui::i18n::{Lang, Msg};
use crate::gui::theme;
use std::fmt::Write as _;

pub mod chart;
use chart::Window;

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
    /// The ticks shown while zoomed or panned; `None` shows everything recorded.
    pub window: Option<Window>,
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

/// Value changes labelled in a value lane at most; more would only overlap.
const MAX_VALUE_LABELS: usize = 40;

/// The width of the lane names and values left of the chart.
const LABELS: f32 = 190.0;

/// Draws the trace and returns what the user asked for.
pub fn trace_ui(
    ui: &mut egui::Ui,
    data: &TraceData,
    state: &mut TraceState,
    lang: Lang,
) -> Vec<TraceEvent> {
    let t = |m: Msg| m.text(lang);
    let mut events = Vec::new();
    // The chart's hover comes from the last frame: the toolbar is drawn first.
    let hover_id = ui.scope_id().with("trace-hover");
    let hovered: Option<u64> = ui.data(|d| d.get_temp(hover_id)).flatten();
    let shown = hovered.or(state.cursor).unwrap_or(data.last);
    ui.horizontal_wrapped(|ui| {
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
            state.window = None;
        }
        if ui.button(t(Msg::TraceExport)).clicked() {
            events.push(TraceEvent::ExportCsv);
        }
        if ui.button(t(Msg::TraceClear)).clicked() {
            state.cursor = None;
            state.window = None;
            events.push(TraceEvent::Clear);
        }
        ui.separator();
        ui.label(t(Msg::TraceTick));
        ui.monospace(shown.to_string());
        ui.monospace(format!("{:.3} s", seconds(shown)));
    });
    ui.weak(t(Msg::TraceHint));
    if data.signals.is_empty() {
        ui.label(t(Msg::TraceNoSignal));
        return events;
    }
    let hovered = lanes(ui, data, state, shown, lang, &mut events);
    ui.data_mut(|d| d.insert_temp(hover_id, hovered));
    events
}

/// The lanes: names and values at the readout tick on the left, the chart on the right.
/// Returns the tick under the pointer.
fn lanes(
    ui: &mut egui::Ui,
    data: &TraceData,
    state: &mut TraceState,
    shown: u64,
    lang: Lang,
    events: &mut Vec<TraceEvent>,
) -> Option<u64> {
    let n = data.signals.len();
    let room = ui.available_height();
    let lane = if room.is_finite() {
        ((room - 24.0) / n as f32).clamp(26.0, 44.0)
    } else {
        32.0
    };
    let width = ui.available_width().max(LABELS + 160.0);
    let (all, _) = ui.allocate_exact_size(
        egui::vec2(width, lane * n as f32 + 24.0),
        egui::Sense::hover(),
    );
    let chart = Rect::from_min_max(
        egui::pos2(all.left() + LABELS, all.top()),
        egui::pos2(all.right() - 8.0, all.bottom() - 24.0),
    );
    let window = state.window.unwrap_or_else(|| Window::all(data));
    let response = ui.interact(
        chart,
        ui.scope_id().with("trace-chart"),
        egui::Sense::click_and_drag(),
    );
    let hovered = response.hover_pos().map(|p| {
        window
            .tick(chart, p.x)
            .round()
            .clamp(data.first as f64, data.last as f64) as u64
    });
    steer(ui, &response, data, state, window, chart);
    let window = state.window.unwrap_or_else(|| Window::all(data));
    let painter = ui.painter_at(all);
    painter.rect_filled(chart, 2.0, ui.visuals().extreme_bg_color);
    for (i, s) in data.signals.iter().enumerate() {
        let band = Rect::from_min_size(
            egui::pos2(chart.left(), chart.top() + lane * i as f32),
            egui::vec2(chart.width(), lane),
        );
        if i > 0 {
            painter.hline(
                chart.x_range(),
                band.top(),
                egui::Stroke::new(1.0, ui.visuals().widgets.noninteractive.bg_stroke.color),
            );
        }
        chart::paint(&painter, &chart::lane_segments(s, window, band));
        value_labels(&painter, s, window, band);
        label(ui, s, band, shown, lang, i, events);
    }
    axis(ui, &painter, window, chart);
    if let Some(c) = state.cursor {
        let x = window.x(chart, c as f64);
        if chart.x_range().contains(x) {
            painter.vline(
                x,
                chart.y_range(),
                egui::Stroke::new(1.0, theme::TRACE_CURSOR),
            );
        }
    }
    if let Some(h) = hovered {
        let x = window.x(chart, h as f64);
        painter.vline(
            x,
            chart.y_range(),
            egui::Stroke::new(1.0, ui.visuals().weak_text_color()),
        );
    }
    hovered
}

/// Wheel zooms time around the pointer, a drag or a sideways scroll pans, a click places the
/// cursor, a double-click shows everything.
fn steer(
    ui: &egui::Ui,
    response: &egui::Response,
    data: &TraceData,
    state: &mut TraceState,
    window: Window,
    chart: Rect,
) {
    if response.double_clicked() {
        state.window = None;
        return;
    }
    if response.clicked()
        && let Some(p) = response.interact_pointer_pos()
    {
        let t = window.tick(chart, p.x).round();
        state.cursor = Some(t.clamp(data.first as f64, data.last as f64) as u64);
    }
    let per_px = (window.to - window.from) / f64::from(chart.width());
    if response.dragged() {
        let dx = response.drag_delta().x;
        state.window = Some(window.panned(-f64::from(dx) * per_px, data));
    }
    if response.hovered() {
        let (wheel, side) = ui.input(|i| (i.smooth_scroll_delta.y, i.smooth_scroll_delta.x));
        if wheel != 0.0
            && let Some(p) = response.hover_pos()
        {
            let at = window.tick(chart, p.x);
            state.window = Some(window.zoomed(at, f64::from((-wheel / 200.0).exp()), data));
        } else if side != 0.0 {
            state.window = Some(window.panned(-f64::from(side) * per_px, data));
        }
    }
}

/// A lane's name, its value at the readout tick and its remove button, left of the chart.
fn label(
    ui: &mut egui::Ui,
    s: &TraceSignal,
    band: Rect,
    tick: u64,
    lang: Lang,
    i: usize,
    events: &mut Vec<TraceEvent>,
) {
    let row = Rect::from_min_max(
        egui::pos2(band.left() - LABELS, band.top()),
        egui::pos2(band.left() - 4.0, band.bottom()),
    );
    let x = egui::Rect::from_center_size(
        egui::pos2(row.left() + 10.0, row.center().y),
        egui::vec2(18.0, 18.0),
    );
    if ui
        .put(x, egui::Button::new("×").small())
        .on_hover_text(Msg::TraceRemove.text(lang))
        .clicked()
    {
        events.push(TraceEvent::Remove(i));
    }
    let name = Rect::from_min_max(
        egui::pos2(row.left() + 22.0, row.top()),
        egui::pos2(row.left() + 120.0, row.bottom()),
    );
    ui.put(
        name,
        egui::Label::new(egui::RichText::new(&s.name).monospace()).truncate(),
    );
    let value = Rect::from_min_max(egui::pos2(row.left() + 122.0, row.top()), row.max);
    let v = s.value_at(tick);
    let colour = match (s.bit, v != 0) {
        (true, true) => theme::TRACE_BIT,
        (true, false) => theme::TRACE_BIT_LOW,
        (false, _) => theme::TRACE_VALUE,
    };
    ui.put(
        value,
        egui::Label::new(
            egui::RichText::new(v.to_string())
                .monospace()
                .strong()
                .color(colour),
        ),
    );
}

/// A value lane's numbers where it changes, while few enough to read.
fn value_labels(painter: &egui::Painter, s: &TraceSignal, window: Window, band: Rect) {
    if s.bit {
        return;
    }
    let changes: Vec<_> = s
        .points
        .iter()
        .filter(|(t, _)| (*t as f64) >= window.from && (*t as f64) <= window.to)
        .collect();
    if changes.len() > MAX_VALUE_LABELS {
        return;
    }
    for (t, v) in changes {
        painter.text(
            egui::pos2(window.x(band, *t as f64) + 2.0, band.top() + 1.0),
            egui::Align2::LEFT_TOP,
            v.to_string(),
            egui::FontId::monospace(10.0),
            theme::TRACE_VALUE,
        );
    }
}

/// The time axis under the chart, in seconds.
fn axis(ui: &egui::Ui, painter: &egui::Painter, window: Window, chart: Rect) {
    let colour = ui.visuals().weak_text_color();
    for secs in chart::time_marks(window, chart.width()) {
        let tick = secs * 1000.0 / TICK_MS as f64;
        let x = window.x(chart, tick);
        painter.vline(
            x,
            chart.bottom()..=chart.bottom() + 4.0,
            egui::Stroke::new(1.0, colour),
        );
        painter.text(
            egui::pos2(x, chart.bottom() + 5.0),
            egui::Align2::CENTER_TOP,
            format!("{secs:.3}"),
            egui::FontId::proportional(11.0),
            colour,
        );
    }
}

use egui::Rect;

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
        h.get_all_by_label("×").nth(1).unwrap().click();
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
        // The middle of the chart (x 190–992): ticks 1–5 fill it, so this is about tick 3.
        let at = egui::pos2(595.0, 100.0);
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
