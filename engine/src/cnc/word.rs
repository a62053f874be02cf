//! The words of one block (docs/gcode.md, "Words"): each address letter with its number kept
//! as written — value and whether it had a decimal point — because what a number means (mm,
//! inch, least increments) depends on G20/G21 and #3401 DPI when the block executes, not when
//! the text is read. G codes are sorted into their groups here.

use super::ps;

/// Largest length, in increments (±99999.999 mm).
pub const COORD_MAX: f64 = 99_999_999.0;

/// Most digits a number may have (P/S 0003 beyond).
const DIGITS_MAX: usize = 8;

/// A number as written after an address letter.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Num {
    /// Its value as written.
    pub value: f64,
    /// It had a decimal point.
    pub decimal: bool,
}

/// How length words read when a block executes: the unit (G20 inch / G21 mm) and #3401 bit 0
/// DPI (1: a number without a point is in mm or inch; 0: in least input increments).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Units {
    /// G20 is in effect.
    pub inch: bool,
    /// #3401 bit 0.
    pub dpi: bool,
}

impl Units {
    /// Millimetres per unit of the program.
    pub fn mm_per_unit(self) -> f64 {
        if self.inch { 25.4 } else { 1.0 }
    }

    /// A length word in increments of 0.001 mm (X as written: a diameter stays a diameter).
    pub fn len(self, n: Num) -> Result<i64, u16> {
        if n.decimal || self.dpi {
            self.units_to_incr(n.value)
        } else {
            self.least_to_incr(n.value)
        }
    }

    /// A word FANUC always reads in least input increments unless it has a point (G76 Q and P
    /// digits, FS15 cycle D and K, G83 Q…), in increments of 0.001 mm.
    pub fn fixed(self, n: Num) -> Result<i64, u16> {
        if n.decimal {
            self.units_to_incr(n.value)
        } else {
            self.least_to_incr(n.value)
        }
    }

    /// A feed word: mm/min (or mm/rev) from inch/min (inch/rev) under G20.
    pub fn feed(self, f: f64) -> f64 {
        f * self.mm_per_unit()
    }

    fn units_to_incr(self, v: f64) -> Result<i64, u16> {
        checked(v * self.mm_per_unit() * 1000.0)
    }

    fn least_to_incr(self, v: f64) -> Result<i64, u16> {
        // The least input increment is 0.001 mm or 0.0001 inch (2.54 µm).
        checked(if self.inch { v * 2.54 } else { v })
    }
}

fn checked(incr: f64) -> Result<i64, u16> {
    let r = incr.round();
    if !r.is_finite() || r.abs() > COORD_MAX {
        Err(ps::DIGITS)
    } else {
        Ok(r as i64)
    }
}

/// G codes of group 00 (one-shot) a block may hold, one per block.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum OneShot {
    /// G04 dwell.
    Dwell,
    /// G10 data setting.
    Data,
    /// G28 reference return.
    Ref,
    /// G30 return to reference point 2, 3 or 4 (P).
    Ref2,
    /// G50 coordinate setting or spindle clamp.
    Coord,
    /// G53 machine coordinates.
    Machine,
    /// G70–G76: a multiple repetitive cycle, the number given.
    Cycle(u8),
}

/// One block's words, as read from the text.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Words {
    /// Group 01 G number: 0, 1, 2, 3, 32, 90, 92, 94.
    pub motion: Option<u8>,
    /// Group 00.
    pub one_shot: Option<OneShot>,
    /// Group 10 G number: 80, 83, 84, 85, 87, 88, 89.
    pub drill: Option<u8>,
    /// Group 14: 0 (G54) … 5 (G59).
    pub work: Option<u8>,
    /// Group 03 (05 on FANUC): `Some(false)` G98, `Some(true)` G99.
    pub per_rev: Option<bool>,
    /// Group 06: `Some(true)` G20, `Some(false)` G21.
    pub inch: Option<bool>,
    /// Group 02: `Some(true)` G96, `Some(false)` G97.
    pub css: Option<bool>,
    /// X, Z, Y: the number and whether it is incremental (U, W, V).
    pub axes: [Option<(Num, bool)>; 3],
    /// I, K: arc centre (I radius-valued) or a cycle's taper / depth.
    pub i: Option<Num>,
    /// K.
    pub k: Option<Num>,
    /// R: arc radius, taper, retract or a cycle's amount.
    pub r: Option<Num>,
    /// Q: a cycle's last sequence number, depth or peck.
    pub q: Option<Num>,
    /// D: FS15-form cycle depth.
    pub d: Option<Num>,
    /// A: thread angle, degrees.
    pub a: Option<Num>,
    /// C: in a G01 block, a chamfer as `,C` (the form without a comma).
    pub c: Option<Num>,
    /// `,C`: a chamfer to the next block, the distance from the corner.
    pub chamfer: Option<Num>,
    /// `,R`: a corner radius to the next block.
    pub corner: Option<Num>,
    /// F as written (mm/min, mm/rev, or the unit of G20; thread lead).
    pub f: Option<f64>,
    /// S as written: r/min, or m/min (ft/min) under G96; G50's clamp.
    pub s: Option<u32>,
    /// T, TTOO.
    pub t: Option<u32>,
    /// M codes in order (up to three).
    pub m: [u32; 3],
    /// How many M codes.
    pub m_count: u8,
    /// P without a decimal point (G04 ms, M98 program, cycle sequence number, G10 number…).
    pub p: Option<u32>,
    /// L, an integer (M98 repeat count, G10 kind).
    pub l: Option<u32>,
    /// G04 time in seconds: P with a decimal point.
    pub dwell_s: Option<f64>,
    /// G04 time given with X or U (seconds when read as a length in mm: see docs/gcode.md).
    pub dwell_x: Option<Num>,
    /// G67: the G66 modal call ends.
    pub g67: bool,
}

impl Words {
    /// The M codes of the block.
    pub fn ms(&self) -> &[u32] {
        &self.m[..usize::from(self.m_count)]
    }

    /// Whether any axis word is given (outside G04, where X/U are the time).
    pub fn moves(&self) -> bool {
        self.axes.iter().any(Option::is_some)
    }

    /// G04.
    pub fn dwell(&self) -> bool {
        self.one_shot == Some(OneShot::Dwell)
    }

    /// G28 or G30: a return to a reference point.
    pub fn g28(&self) -> bool {
        matches!(self.one_shot, Some(OneShot::Ref | OneShot::Ref2))
    }
}

/// The special M codes that end or stop a program (M00, M01, M02, M30).
pub(super) fn special_m(ms: &[u32]) -> Option<u32> {
    ms.iter().copied().find(|m| matches!(m, 0 | 1 | 2 | 30))
}

/// A number as written after a letter, and how many bytes it took.
pub(super) struct Number {
    pub value: f64,
    pub decimal: bool,
    pub text_len: usize,
}

/// Reads a number: sign, digits, at most one point; `None` when there is no digit.
pub(super) fn number(s: &str) -> Option<Number> {
    let b = s.as_bytes();
    let mut i = 0;
    if i < b.len() && (b[i] == b'+' || b[i] == b'-') {
        i += 1;
    }
    let int_start = i;
    while i < b.len() && b[i].is_ascii_digit() {
        i += 1;
    }
    let mut digits = i - int_start;
    let mut decimal = false;
    if i < b.len() && b[i] == b'.' {
        decimal = true;
        i += 1;
        let f = i;
        while i < b.len() && b[i].is_ascii_digit() {
            i += 1;
        }
        digits += i - f;
    }
    if digits == 0 {
        return None;
    }
    let value: f64 = s[..i].parse().ok()?;
    Some(Number {
        value,
        decimal,
        text_len: i,
    })
}

/// Significant digits of a number's text (leading zeros do not count).
fn significant(text: &str) -> usize {
    text.trim_start_matches(['+', '-'])
        .trim_start_matches(['0', '.'])
        .bytes()
        .filter(u8::is_ascii_digit)
        .count()
}

/// Reads the words of a block's text (upper case, no spaces or comments, after N and `/`).
pub(super) fn words(mut body: &str) -> Result<Words, u16> {
    let mut w = Words::default();
    let mut seen = [false; 26];
    let mut groups = [false; GROUPS];
    let mut p_decimal = None;
    while let Some(letter) = body.chars().next() {
        if letter == ',' {
            // `,C` chamfer and `,R` corner rounding (FANUC's direct input).
            let rest = &body[1..];
            let kind = rest.chars().next().ok_or(ps::ADDRESS)?;
            let num = number(&rest[1..]).ok_or(ps::ADDRESS)?;
            body = &rest[1 + num.text_len..];
            let v = Some(Num {
                value: num.value,
                decimal: num.decimal,
            });
            if num.value < 0.0 || w.chamfer.is_some() || w.corner.is_some() {
                return Err(ps::ADDRESS);
            }
            match kind {
                'C' => w.chamfer = v,
                'R' => w.corner = v,
                _ => return Err(ps::ADDRESS),
            }
            continue;
        }
        if !letter.is_ascii_uppercase() {
            return Err(ps::ADDRESS);
        }
        let rest = &body[1..];
        let num = number(rest).ok_or(ps::ADDRESS)?;
        let text = &rest[..num.text_len];
        body = &rest[num.text_len..];
        let slot = (letter as u8 - b'A') as usize;
        if letter != 'G' && letter != 'M' {
            if seen[slot] {
                return Err(ps::ADDRESS);
            }
            seen[slot] = true;
        }
        if letter != 'G' && significant(text) > DIGITS_MAX {
            return Err(ps::DIGITS);
        }
        let v = num.value;
        let raw = Num {
            value: v,
            decimal: num.decimal,
        };
        let integer = |max: f64| -> Result<u32, u16> {
            if num.decimal || v < 0.0 {
                Err(ps::ADDRESS)
            } else if v > max {
                Err(ps::DIGITS)
            } else {
                Ok(v as u32)
            }
        };
        match letter {
            'N' => {
                if num.decimal || v < 1.0 {
                    return Err(ps::ADDRESS);
                }
                if v > 99_999.0 {
                    return Err(ps::DIGITS);
                }
            }
            'G' => g_code(text, &mut w, &mut groups)?,
            'X' | 'Z' | 'Y' | 'U' | 'W' | 'V' => {
                if num.decimal && (v * 1000.0).abs() > COORD_MAX {
                    return Err(ps::DIGITS);
                }
                let (k, inc) = match letter {
                    'X' => (0, false),
                    'Z' => (1, false),
                    'Y' => (2, false),
                    'U' => (0, true),
                    'W' => (1, true),
                    _ => (2, true),
                };
                if w.axes[k].is_some() {
                    return Err(ps::ADDRESS);
                }
                w.axes[k] = Some((raw, inc));
            }
            'I' => w.i = Some(raw),
            'K' => w.k = Some(raw),
            'R' => w.r = Some(raw),
            'Q' => w.q = Some(raw),
            'D' => w.d = Some(raw),
            'A' => w.a = Some(raw),
            'C' => w.c = Some(raw),
            'F' => {
                if v < 0.0 || !v.is_finite() {
                    return Err(ps::ADDRESS);
                }
                w.f = Some(v);
            }
            'S' => w.s = Some(integer(99_999_999.0)?),
            'T' => w.t = Some(integer(9999.0)?),
            'P' if num.decimal && v >= 0.0 => p_decimal = Some(v),
            'P' => w.p = Some(integer(99_999_999.0)?),
            'L' => w.l = Some(integer(9999.0)?),
            'M' => {
                let max = if w.m_count == 0 {
                    99_999_999.0
                } else {
                    65_535.0
                };
                let m = integer(max)?;
                if w.m_count == 3 {
                    return Err(ps::M_COUNT);
                }
                w.m[usize::from(w.m_count)] = m;
                w.m_count += 1;
            }
            _ => return Err(ps::ADDRESS),
        }
    }
    if w.dwell() {
        // G04 X/U: the time, not a coordinate; P with a point: seconds.
        if let Some((v, _)) = w.axes[0].take() {
            w.dwell_x = Some(v);
        }
        w.dwell_s = p_decimal;
    } else if p_decimal.is_some() {
        return Err(ps::ADDRESS);
    }
    Ok(w)
}

/// Group slots: 0 one-shot, 1 motion, 2 feed mode, 3 workpiece, 4 G13.1, 5 G15, 6 plane,
/// 7 unit, 8 compensation, 9 G67, 10 CSS, 11 drilling.
const GROUPS: usize = 12;

fn g_code(code: &str, w: &mut Words, groups: &mut [bool; GROUPS]) -> Result<(), u16> {
    let value: f64 = code.parse().map_err(|_| ps::G_CODE)?;
    let tenths = (value * 10.0).round();
    if (value * 10.0 - tenths).abs() > 1e-9 || code.starts_with(['+', '-']) {
        return Err(ps::G_CODE);
    }
    let one_shot = |w: &mut Words, o: OneShot| {
        w.one_shot = Some(o);
        0
    };
    let t = tenths as i64;
    let group = match t {
        0 | 10 | 20 | 30 | 320 | 900 | 920 | 940 => {
            w.motion = Some((t / 10) as u8);
            1
        }
        40 => one_shot(w, OneShot::Dwell),
        100 => one_shot(w, OneShot::Data),
        280 => one_shot(w, OneShot::Ref),
        300 => one_shot(w, OneShot::Ref2),
        500 => one_shot(w, OneShot::Coord),
        530 => one_shot(w, OneShot::Machine),
        700..=760 if t % 10 == 0 => one_shot(w, OneShot::Cycle((t / 10) as u8)),
        540 | 550 | 560 | 570 | 580 | 590 => {
            w.work = Some(((t - 540) / 10) as u8);
            3
        }
        980 | 990 => {
            w.per_rev = Some(t == 990);
            2
        }
        200 | 210 => {
            w.inch = Some(t == 200);
            7
        }
        960 | 970 => {
            w.css = Some(t == 960);
            10
        }
        800 | 830 | 840 | 850 | 870 | 880 | 890 => {
            w.drill = Some((t / 10) as u8);
            11
        }
        131 => 4,
        150 => 5,
        180 => 6,
        400 | 410 | 420 => 8,
        670 => {
            w.g67 = true;
            9
        }
        _ => return Err(ps::G_CODE),
    };
    if groups[group] {
        return Err(ps::G_CODE);
    }
    groups[group] = true;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lengths_follow_the_point_dpi_and_the_unit() {
        let n = |value, decimal| Num { value, decimal };
        let mm = Units {
            inch: false,
            dpi: true,
        };
        let least = Units {
            inch: false,
            dpi: false,
        };
        let inch = Units {
            inch: true,
            dpi: false,
        };
        assert_eq!(mm.len(n(10.0, false)), Ok(10_000));
        assert_eq!(least.len(n(10.0, false)), Ok(10));
        assert_eq!(least.len(n(10.0, true)), Ok(10_000));
        assert_eq!(inch.len(n(1.0, true)), Ok(25_400));
        // 1000 least increments of 0.0001 inch are 0.1 inch = 2.54 mm.
        assert_eq!(inch.len(n(1000.0, false)), Ok(2_540));
        // Words read in increments ignore DPI.
        assert_eq!(mm.fixed(n(450.0, false)), Ok(450));
        assert_eq!(mm.fixed(n(0.45, true)), Ok(450));
        assert_eq!(mm.len(n(100_000.0, false)), Err(ps::DIGITS));
        assert!((inch.feed(0.01) - 0.254).abs() < 1e-12);
    }

    #[test]
    fn new_letters_and_groups_read() {
        let w = words("G02X10.Z-5.R5.F0.2").unwrap();
        assert_eq!(w.motion, Some(2));
        assert_eq!(w.r.map(|r| r.value), Some(5.0));
        let w = words("G71P10Q20U0.4W0.1D2000F0.25").unwrap();
        assert_eq!(w.one_shot, Some(OneShot::Cycle(71)));
        assert_eq!(
            w.d,
            Some(Num {
                value: 2000.0,
                decimal: false
            })
        );
        let w = words("G20G99G96S180").unwrap();
        assert_eq!(
            (w.inch, w.per_rev, w.css, w.s),
            (Some(true), Some(true), Some(true), Some(180))
        );
        let w = words("G04P1.5").unwrap();
        assert_eq!(w.dwell_s, Some(1.5));
        assert_eq!(words("G01P1.5"), Err(ps::ADDRESS));
        assert_eq!(words("G00G02X1"), Err(ps::G_CODE));
        assert_eq!(words("G04G28"), Err(ps::G_CODE));
        assert_eq!(words("G83Z-10.Q5000").unwrap().drill, Some(83));
        assert_eq!(words("X123456789"), Err(ps::DIGITS));
        assert_eq!(words("X00001234.5678").map(|w| w.moves()), Ok(true));
    }
}
