//! The spindle (docs/cnc.md, "Spindle"; docs/gcode.md, "Constant surface speed"): the output
//! speed from S, the overrides, the gear and G96, and the position coder whose one-rotation
//! signal starts a thread.

use super::{SimCnc, motion, params};

/// Spindle state.
#[derive(Clone, Copy, Debug, Default)]
pub(super) struct Spindle {
    /// The last S commanded.
    pub(super) s_cmd: u32,
    /// The output speed, r/min.
    pub(super) s_out: u32,
    /// Maximum of the selected gear.
    pub(super) g_max: u32,
    /// The speed constant surface speed gave at the last exchange, r/min (before override).
    pub(super) s_css: u32,
    /// Angle, in revolutions (0–1), from S_out.
    pub(super) angle: f64,
    /// The one-rotation signal came at this exchange.
    pub(super) one_rev: bool,
}

impl SimCnc {
    /// The spindle output (docs/cnc.md, "Spindle").
    pub(super) fn update_spindle(&mut self) {
        let inp = self.inp;
        let g_max = self
            .params
            .get(params::P3741 + usize::from(inp.gear), 0)
            .max(0) as u32;
        let s_out = if inp.estop || inp.sstp {
            0
        } else if inp.sind {
            (f64::from(inp.ri) * f64::from(g_max) / 4095.0).round() as u32
        } else {
            let sov = f64::from(inp.sov.clamp(5, 12)) / 10.0;
            let s = if self.auto.modal.css {
                self.spindle.s_css = self.css_speed(g_max);
                self.spindle.s_css
            } else {
                self.spindle.s_cmd
            };
            ((f64::from(s) * sov).round() as u32).min(g_max)
        };
        self.spindle.s_out = s_out;
        self.spindle.g_max = g_max;
        // The position coder: one rotation signal each time the angle passes zero.
        let sp = &mut self.spindle;
        sp.angle += f64::from(s_out) * 8.0 / 60_000.0;
        sp.one_rev = sp.angle >= 1.0;
        sp.angle = sp.angle.fract();
    }

    /// The spindle speed G96 asks for at the tool's diameter (the end point's during a
    /// rapid): 1000 · V / (π · D) r/min, no more than G50 S (when set) and `g_max`.
    fn css_speed(&self, g_max: u32) -> u32 {
        let m = &self.auto.modal;
        let x = match self.auto.exec.and_then(|e| e.motion) {
            Some(mo) if mo.kind == motion::MotionKind::Rapid => {
                mo.target[0] - self.tool_offset_along(0) - self.work_offset(0)
            }
            _ => self.absolute(0),
        };
        let d_mm = if self.diameter(0) { 1.0 } else { 2.0 } * (x as f64 / 1000.0).abs();
        let limit = if m.s_max > 0 {
            m.s_max.min(g_max)
        } else {
            g_max
        };
        let s = 1000.0 * m.css_speed / (std::f64::consts::PI * d_mm);
        if s.is_finite() {
            (s.round() as u32).min(limit)
        } else {
            limit
        }
    }
}
