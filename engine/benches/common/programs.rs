//! Part programs the G-code benchmarks share (`engine/benches/gcode.rs`,
//! `app/benches/toolpath.rs`).

use std::fmt::Write;

/// 30 000 blocks of turning: 7 500 passes of rapid in, cut along Z, an arc out, rapid back.
/// With `step` 0 the passes cycle through 20 diameters (they repeat); otherwise pass k is at
/// its own diameter, `step` mm apart.
pub fn turning_30000(step: f64) -> String {
    let mut p = String::from("O1\nG00 X60 Z2\n");
    for k in 0..7_500 {
        let x = if step > 0.0 {
            20.0 + k as f64 * step
        } else {
            20.0 + (k % 20) as f64
        };
        let _ = writeln!(
            p,
            "G00 X{x:.3} Z2\nG01 Z-20 F300\nG02 X{:.3} Z-25 R5\nG00 X60",
            x + 10.0
        );
    }
    p.push_str("M30\n");
    p
}
