//! CNC parameters (docs/cnc.md, "Parameters"): the GSK988TA machine settings the simulator
//! acts on, with their kinds, selectors, defaults and ranges, and the GSK980's plain table of
//! words 1–254.
//!
//! Values are kept per selector slot (axis 1–5 or spindle 1–4; slot 0 for a parameter without
//! a selector). A power-on-effective parameter written by WINDR is stored as pending and takes
//! effect at the next power-cycle; `cnc param` sets the effective value at once.

/// Whether a parameter is a bit (status) byte or a word.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ParamKind {
    /// One byte, 0–255, read and written whole.
    Bit,
    /// A signed word.
    Word,
}

/// What a parameter's selector chooses.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Selector {
    /// No selector (WINDR attribute 0).
    None,
    /// A controlled axis 1–#8130.
    Axis,
    /// A spindle 1–4.
    Spindle,
}

/// One row of the parameter table.
#[derive(Clone, Copy, Debug)]
pub struct ParamSpec {
    /// Parameter number.
    pub number: u16,
    /// Bit or word.
    pub kind: ParamKind,
    /// Its selector.
    pub selector: Selector,
    /// Takes effect only after a power-cycle when written by WINDR.
    pub power_on: bool,
    /// Default per slot (slot 0 = axis 1 / spindle 1 / no selector).
    pub default: [i64; 5],
    /// Smallest value.
    pub min: i64,
    /// Largest value.
    pub max: i64,
}

const fn p(
    number: u16,
    kind: ParamKind,
    selector: Selector,
    power_on: bool,
    d: i64,
    min: i64,
    max: i64,
) -> ParamSpec {
    ParamSpec {
        number,
        kind,
        selector,
        power_on,
        default: [d; 5],
        min,
        max,
    }
}

use ParamKind::{Bit, Word};
use Selector::{Axis, None as NoSel, Spindle};

const BIG: i64 = 99_999_999;
const FEED: i64 = 240_000;

/// The GSK988TA parameters the simulator knows, in number order.
pub static TABLE: [ParamSpec; 59] = [
    p(71, Word, NoSel, false, 0, 0, 60_000),
    ParamSpec {
        number: 1006,
        kind: Bit,
        selector: Axis,
        power_on: true,
        default: [8, 0, 0, 0, 0],
        min: 0,
        max: 255,
    },
    p(1240, Word, Axis, false, 0, -BIG, BIG),
    p(1241, Word, Axis, false, 0, -BIG, BIG),
    p(1242, Word, Axis, false, 0, -BIG, BIG),
    p(1243, Word, Axis, false, 0, -BIG, BIG),
    p(1301, Bit, NoSel, false, 0, 0, 255),
    p(1320, Word, Axis, false, BIG, -BIG, BIG),
    p(1321, Word, Axis, false, -BIG, -BIG, BIG),
    p(1326, Word, Axis, false, BIG, -BIG, BIG),
    p(1327, Word, Axis, false, -BIG, -BIG, BIG),
    p(1410, Word, NoSel, false, 1200, 0, FEED),
    p(1420, Word, Axis, false, 6000, 0, FEED),
    p(1421, Word, NoSel, false, 600, 0, FEED),
    p(1423, Word, Axis, false, 1200, 0, FEED),
    p(1424, Word, Axis, false, 6000, 0, FEED),
    p(1425, Word, Axis, false, 120, 0, FEED),
    p(3003, Bit, NoSel, false, 35, 0, 255),
    p(3401, Bit, NoSel, false, 1, 0, 255),
    p(3402, Bit, NoSel, false, 16, 0, 255),
    p(3410, Word, NoSel, false, 20, 0, BIG),
    p(3411, Word, NoSel, false, 0, 0, BIG),
    p(3412, Word, NoSel, false, 0, 0, BIG),
    p(3413, Word, NoSel, false, 0, 0, BIG),
    p(3414, Word, NoSel, false, 0, 0, BIG),
    p(3415, Word, NoSel, false, 0, 0, BIG),
    p(3416, Word, NoSel, false, 0, 0, BIG),
    p(3417, Word, NoSel, false, 0, 0, BIG),
    p(3418, Word, NoSel, false, 0, 0, BIG),
    p(3419, Word, NoSel, false, 0, 0, BIG),
    p(3420, Word, NoSel, false, 0, 0, BIG),
    p(3741, Word, Spindle, false, 2000, 0, 99_999),
    p(3742, Word, Spindle, false, 3000, 0, 99_999),
    p(3743, Word, Spindle, false, 4000, 0, 99_999),
    p(3744, Word, Spindle, false, 5000, 0, 99_999),
    p(5130, Word, NoSel, false, 10, 0, 127),
    p(5132, Word, NoSel, false, 1000, 0, BIG),
    p(5133, Word, NoSel, false, 500, 0, BIG),
    p(5135, Word, NoSel, false, 0, -BIG, BIG),
    p(5136, Word, NoSel, false, 0, -BIG, BIG),
    p(5137, Word, NoSel, false, 1, 1, 99_999),
    p(5139, Word, NoSel, false, 500, 0, BIG),
    p(5140, Word, NoSel, false, 100, 0, BIG),
    p(5141, Word, NoSel, false, 50, 0, BIG),
    p(5142, Word, NoSel, false, 1, 1, 99),
    p(5143, Word, NoSel, false, 60, 0, 120),
    p(6000, Bit, NoSel, false, 0, 0, 255),
    p(6001, Bit, NoSel, false, 0, 0, 255),
    p(6004, Bit, NoSel, false, 0, 0, 255),
    p(6711, Word, NoSel, false, 0, 0, BIG),
    p(6712, Word, NoSel, false, 0, 0, BIG),
    p(6713, Word, NoSel, false, 0, 0, BIG),
    p(7103, Bit, NoSel, false, 0, 0, 255),
    p(7113, Word, NoSel, false, 100, 1, 2000),
    p(7114, Word, NoSel, false, 1000, 1, 2000),
    p(8002, Bit, NoSel, false, 0, 0, 255),
    p(8010, Word, Axis, false, 0, 0, 4),
    p(8130, Word, NoSel, true, 2, 2, 5),
    p(8410, Word, NoSel, false, 0, 0, 0),
];

const ROWS: usize = TABLE.len();

/// Index of a parameter number in [`TABLE`].
pub fn index(number: u16) -> Option<usize> {
    TABLE[..ROWS].iter().position(|s| s.number == number)
}

/// The row of a parameter number.
pub fn spec(number: u16) -> Option<&'static ParamSpec> {
    index(number).map(|i| &TABLE[i])
}

/// Number of slots a selector has (1 without one).
pub fn slots(selector: Selector) -> usize {
    match selector {
        Selector::None => 1,
        Selector::Axis => 5,
        Selector::Spindle => 4,
    }
}

macro_rules! idx {
    ($($name:ident = $n:expr),* $(,)?) => {
        $(
            #[doc = concat!("Index of parameter ", stringify!($n), ".")]
            pub const $name: usize = {
                let mut i = 0;
                while TABLE[i].number != $n {
                    i += 1;
                }
                i
            };
        )*
    };
}

idx! {
    P0071 = 71, P1006 = 1006, P1240 = 1240, P1301 = 1301, P1320 = 1320, P1321 = 1321,
    P1326 = 1326, P1327 = 1327, P1410 = 1410, P1420 = 1420, P1421 = 1421, P1423 = 1423,
    P1424 = 1424, P1425 = 1425, P3003 = 3003, P3401 = 3401, P3402 = 3402, P3410 = 3410, P3411 = 3411,
    P3741 = 3741, P5130 = 5130, P5132 = 5132, P5133 = 5133, P5135 = 5135, P5136 = 5136,
    P5137 = 5137, P5139 = 5139, P5140 = 5140, P5141 = 5141, P5142 = 5142, P5143 = 5143, P6000 = 6000, P6001 = 6001, P6004 = 6004, P6711 = 6711, P6712 = 6712,
    P6713 = 6713, P7103 = 7103, P7113 = 7113, P7114 = 7114, P8002 = 8002, P8010 = 8010,
    P8130 = 8130,
}

/// Why a parameter write was refused.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum ParamError {
    /// No such parameter.
    Number,
    /// The selector does not fit the parameter.
    Selector,
    /// The value is outside the parameter's range.
    Value,
}

/// Number of plain words of the GSK980 table (1–254).
pub const GSK980_WORDS: usize = 254;

/// The parameter values of one CNC.
#[derive(Clone, Debug)]
pub struct Params {
    values: [[i64; 5]; ROWS],
    pending: [[Option<i64>; 5]; ROWS],
    /// The GSK980's words 1–254 (index 0 = No.1).
    words980: [i32; GSK980_WORDS],
}

impl Default for Params {
    fn default() -> Self {
        let mut values = [[0; 5]; ROWS];
        for (v, s) in values.iter_mut().zip(&TABLE[..ROWS]) {
            *v = s.default;
        }
        Params {
            values,
            pending: [[None; 5]; ROWS],
            words980: [0; GSK980_WORDS],
        }
    }
}

impl Params {
    /// Effective value of parameter row `i` at selector slot `slot` (0-based).
    #[inline]
    pub fn get(&self, i: usize, slot: usize) -> i64 {
        self.values[i][slot]
    }

    /// Effective value of a parameter without a selector.
    #[inline]
    pub fn one(&self, i: usize) -> i64 {
        self.values[i][0]
    }

    /// Whether bit `b` of a bit parameter is 1.
    #[inline]
    pub fn bit(&self, i: usize, slot: usize, b: u32) -> bool {
        self.values[i][slot] >> b & 1 == 1
    }

    /// Checks a parameter number, selector (1-based, `None` = 0) and value.
    pub fn check(number: u16, sel: Option<u8>, value: i64) -> Result<(usize, usize), ParamError> {
        let i = index(number).ok_or(ParamError::Number)?;
        let s = &TABLE[i];
        let slot = match (s.selector, sel) {
            (Selector::None, None) => 0,
            (Selector::None, Some(_)) | (_, None) => return Err(ParamError::Selector),
            (kind, Some(k)) => {
                let k = usize::from(k);
                if k == 0 || k > slots(kind) {
                    return Err(ParamError::Selector);
                }
                k - 1
            }
        };
        if value < s.min || value > s.max {
            return Err(ParamError::Value);
        }
        Ok((i, slot))
    }

    /// Sets the effective value at once (machine set-up, `cnc param`).
    pub fn set(&mut self, i: usize, slot: usize, value: i64) {
        self.values[i][slot] = value;
        self.pending[i][slot] = None;
    }

    /// A write from the PLC (WINDR 18): a power-on-effective parameter is kept pending.
    pub fn write(&mut self, i: usize, slot: usize, value: i64) {
        if TABLE[i].power_on {
            self.pending[i][slot] = Some(value);
        } else {
            self.values[i][slot] = value;
        }
    }

    /// Power-cycle: pending values take effect.
    pub fn power_cycle(&mut self) {
        for (v, p) in self.values.iter_mut().zip(self.pending.iter_mut()) {
            for (v, p) in v.iter_mut().zip(p.iter_mut()) {
                if let Some(x) = p.take() {
                    *v = x;
                }
            }
        }
    }

    /// The GSK980 word No.`n` (1–254).
    pub fn word980(&self, n: usize) -> i32 {
        self.words980[n - 1]
    }

    /// Sets the GSK980 word No.`n` (1–254).
    pub fn set_word980(&mut self, n: usize, v: i32) {
        self.words980[n - 1] = v;
    }

    /// Adds 1 to a counter parameter, saturating at its maximum.
    pub fn count(&mut self, i: usize) {
        let max = TABLE[i].max;
        let v = &mut self.values[i][0];
        *v = (*v + 1).min(max);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn indices_match_the_table_and_defaults_hold() {
        assert_eq!(TABLE[P8130].number, 8130);
        assert_eq!(TABLE[P3741].number, 3741);
        let p = Params::default();
        assert_eq!(p.get(P1006, 0), 8, "X is a diameter axis");
        assert_eq!(p.get(P1006, 1), 0);
        assert_eq!(p.one(P3003), 35);
        assert_eq!(p.get(P1320, 3), 99_999_999);
        assert_eq!(p.get(index(3744).unwrap(), 2), 5000);
        assert!(TABLE[..ROWS].windows(2).all(|w| w[0].number < w[1].number));
    }

    #[test]
    fn checks_name_the_wrong_part() {
        assert_eq!(Params::check(1420, Some(2), 3000), Ok((P1420, 1)));
        assert_eq!(Params::check(1420, None, 3000), Err(ParamError::Selector));
        assert_eq!(Params::check(3003, Some(1), 3), Err(ParamError::Selector));
        assert_eq!(Params::check(3741, Some(5), 3), Err(ParamError::Selector));
        assert_eq!(Params::check(8130, None, 6), Err(ParamError::Value));
        assert_eq!(Params::check(9999, None, 0), Err(ParamError::Number));
    }

    #[test]
    fn a_power_on_parameter_written_by_the_plc_waits_for_power_cycle() {
        let mut p = Params::default();
        p.write(P8130, 0, 3);
        assert_eq!(p.one(P8130), 2);
        p.power_cycle();
        assert_eq!(p.one(P8130), 3);
    }
}
