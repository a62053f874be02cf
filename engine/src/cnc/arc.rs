//! Circular interpolation in the lathe's Z–X plane (docs/gcode.md, "Arcs"): the centre of an
//! arc given by its radius R, and the path from a centre, worked in millimetres of radius with
//! Z as the first plane coordinate and X the second. Seen as the drawing is drawn (Z to the
//! right, X up, the view from +Y), G02 turns clockwise.

use std::f64::consts::TAU;

use super::program::ps::ARC_RADIUS as PS_RADIUS;

/// An arc: centre, start and end radius, start angle and signed sweep (negative clockwise).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ArcPath {
    /// Centre, (Z, X radius) in mm.
    pub center: [f64; 2],
    /// Radius at the start, mm.
    pub r0: f64,
    /// Radius at the end, mm (the path blends from `r0` to `r1`, so it ends on the target).
    pub r1: f64,
    /// Start angle, radians from +Z towards +X.
    pub a0: f64,
    /// Swept angle, radians, negative for G02.
    pub sweep: f64,
}

impl ArcPath {
    /// The arc from `start` to `end` around `center` (all (Z, X) in mm), clockwise when `cw`;
    /// a closed arc is a full turn when `full`, else nothing.
    pub fn new(start: [f64; 2], end: [f64; 2], center: [f64; 2], cw: bool, full: bool) -> ArcPath {
        let angle = |p: [f64; 2]| (p[1] - center[1]).atan2(p[0] - center[0]);
        let dist = |p: [f64; 2]| (p[0] - center[0]).hypot(p[1] - center[1]);
        let a0 = angle(start);
        let mut sweep = angle(end) - a0;
        let closed = (start[0] - end[0]).abs() < 1e-9 && (start[1] - end[1]).abs() < 1e-9;
        if cw {
            while sweep > 1e-12 {
                sweep -= TAU;
            }
            if closed || sweep.abs() < 1e-12 {
                sweep = if full { -TAU } else { 0.0 };
            }
        } else {
            while sweep < -1e-12 {
                sweep += TAU;
            }
            if closed || sweep.abs() < 1e-12 {
                sweep = if full { TAU } else { 0.0 };
            }
        }
        ArcPath {
            center,
            r0: dist(start),
            r1: dist(end),
            a0,
            sweep,
        }
    }

    /// Length along the arc, mm.
    pub fn length(&self) -> f64 {
        self.sweep.abs() * (self.r0 + self.r1) / 2.0
    }

    /// The point (Z, X radius in mm) at fraction `f` (0–1) of the arc.
    pub fn point(&self, f: f64) -> [f64; 2] {
        let a = self.a0 + self.sweep * f;
        let r = self.r0 + (self.r1 - self.r0) * f;
        [self.center[0] + r * a.cos(), self.center[1] + r * a.sin()]
    }
}

/// The centre of the arc from `start` to `end` (Z, X radius in mm) of radius `|r|`: the minor
/// arc for R > 0, the major one (over 180°) for R < 0. `tol` (mm) is how much longer than 2R
/// the chord may be; within it the centre is the chord's midpoint.
pub fn center_from_radius(
    start: [f64; 2],
    end: [f64; 2],
    r: f64,
    cw: bool,
    tol: f64,
) -> Result<[f64; 2], u16> {
    let (dz, dx) = (end[0] - start[0], end[1] - start[1]);
    let chord = dz.hypot(dx);
    let half = chord / 2.0;
    let radius = r.abs();
    if half > radius + tol {
        return Err(PS_RADIUS);
    }
    let mid = [(start[0] + end[0]) / 2.0, (start[1] + end[1]) / 2.0];
    if chord < 1e-12 {
        return Ok(mid);
    }
    let h = (radius * radius - half * half).max(0.0).sqrt();
    // The centre of a clockwise arc under 180° lies right of the chord (start → end).
    let right = [dx / chord, -dz / chord];
    let side = if cw == (r > 0.0) { 1.0 } else { -1.0 };
    Ok([mid[0] + side * h * right[0], mid[1] + side * h * right[1]])
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::FRAC_PI_2;

    fn close(a: [f64; 2], b: [f64; 2]) -> bool {
        (a[0] - b[0]).abs() < 1e-9 && (a[1] - b[1]).abs() < 1e-9
    }

    #[test]
    fn a_convex_quarter_turned_from_the_face_is_g03_with_its_centre_inside() {
        // From Z0 X(radius)10 to Z-10 X20, radius 10: G03 has the centre at Z-10 X10.
        let c = center_from_radius([0.0, 10.0], [-10.0, 20.0], 10.0, false, 0.0).unwrap();
        assert!(close(c, [-10.0, 10.0]), "{c:?}");
        let a = ArcPath::new([0.0, 10.0], [-10.0, 20.0], c, false, false);
        assert!((a.sweep - FRAC_PI_2).abs() < 1e-12);
        assert!((a.length() - 10.0 * FRAC_PI_2).abs() < 1e-12);
        assert!(close(a.point(1.0), [-10.0, 20.0]));
        // The same end points with G02 bulge the other way: centre Z0 X20.
        let c = center_from_radius([0.0, 10.0], [-10.0, 20.0], 10.0, true, 0.0).unwrap();
        assert!(close(c, [0.0, 20.0]), "{c:?}");
        // A negative R takes the major arc: 270°.
        let c = center_from_radius([0.0, 10.0], [-10.0, 20.0], -10.0, false, 0.0).unwrap();
        let a = ArcPath::new([0.0, 10.0], [-10.0, 20.0], c, false, false);
        assert!((a.sweep - 3.0 * FRAC_PI_2).abs() < 1e-9);
    }

    #[test]
    fn a_chord_longer_than_the_diameter_is_alarm_0020_beyond_the_tolerance() {
        let r = center_from_radius([0.0, 0.0], [-20.02, 0.0], 10.0, true, 0.02);
        assert!(r.is_ok());
        let r = center_from_radius([0.0, 0.0], [-20.1, 0.0], 10.0, true, 0.02);
        assert_eq!(r, Err(PS_RADIUS));
    }

    #[test]
    fn a_closed_arc_is_a_full_turn_only_when_asked() {
        let a = ArcPath::new([0.0, 10.0], [0.0, 10.0], [0.0, 5.0], true, true);
        assert!((a.sweep + TAU).abs() < 1e-12);
        let a = ArcPath::new([0.0, 10.0], [0.0, 10.0], [0.0, 5.0], true, false);
        assert_eq!(a.sweep, 0.0);
    }
}
