//! An NC block's expression words turned into the text the G-code reader reads
//! (docs/gcode.md, "Macros", "Values in words"): each value rounded to its address's least
//! increment, a vacant value leaving its address out.

use super::expr::Vars;
use super::{Word, WordValue};
use crate::cnc::SimCnc;
use crate::cnc::word::{Words, words};
use std::fmt::Write;

/// Addresses whose value is a whole number (a code, a count, a program or sequence number;
/// Q too: on a lathe it is a sequence number or a depth in least increments, never mm).
fn integer_letter(letter: u8) -> bool {
    matches!(
        letter,
        b'N' | b'O' | b'P' | b'L' | b'M' | b'S' | b'T' | b'H' | b'Q'
    )
}

/// Rounded half away from zero to `places` decimals, written without a negative zero.
fn fixed(v: f64, places: usize) -> String {
    let scale = 10f64.powi(places as i32);
    let r = (v * scale).round() / scale;
    let r = if r == 0.0 { 0.0 } else { r };
    format!("{r:.places$}")
}

/// Decimal places of an address's least increment: what its values round to.
pub(super) fn places(letter: u8, inch: bool) -> usize {
    match letter {
        _ if integer_letter(letter) => 0,
        b'G' => 1,
        // F: 0.0001 mm (/rev), and six places in inch so a thread lead like 1/13 holds.
        b'F' if inch => 6,
        b'F' => 4,
        _ if inch => 4,
        _ => 3,
    }
}

/// The text of one value at an address.
pub(super) fn value_text(letter: u8, v: f64, inch: bool) -> String {
    let t = fixed(v, places(letter, inch));
    match letter {
        b'G' => t.strip_suffix(".0").map_or(t.clone(), str::to_string),
        b'F' => t.trim_end_matches('0').to_string(),
        _ => t,
    }
}

impl SimCnc {
    /// The words of an NC block with expressions, evaluated now.
    pub(in crate::cnc) fn render_words(&self, ws: &[Word]) -> Result<Words, u16> {
        let inch = self.auto.modal.inch;
        let mut text = String::new();
        for w in ws {
            let value = match &w.value {
                WordValue::Lit(t) => Err(t.as_str()),
                // ROUND in an address rounds to the address's least increment.
                WordValue::Expr(e) => {
                    match e.eval_in(self as &dyn Vars, Some(places(w.letter, inch) as i32))? {
                        Some(x) => Ok(x),
                        // A vacant value leaves its address out.
                        None => continue,
                    }
                }
            };
            match w.letter {
                b'c' => text.push_str(",C"),
                b'r' => text.push_str(",R"),
                l => text.push(char::from(l)),
            }
            match value {
                Err(lit) => text.push_str(lit),
                Ok(x) => {
                    let _ = write!(text, "{}", value_text(w.letter, x, inch));
                }
            }
        }
        words(&text)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn values_round_to_the_least_increment_of_their_address() {
        assert_eq!(value_text(b'X', 1.2345, false), "1.235");
        assert_eq!(value_text(b'X', -1.2345, false), "-1.235");
        assert_eq!(value_text(b'X', 1.23456, true), "1.2346");
        assert_eq!(value_text(b'X', -0.0001, false), "0.000");
        assert_eq!(value_text(b'M', 2.5, false), "3");
        assert_eq!(value_text(b'G', 1.0, false), "1");
        assert_eq!(value_text(b'G', 13.1, false), "13.1");
        assert_eq!(value_text(b'F', 0.25, false), "0.25");
        assert_eq!(value_text(b'F', 100.0, false), "100.");
        assert_eq!(value_text(b'F', 1.0 / 13.0, true), "0.076923");
        assert_eq!(value_text(b'Q', 2000.0, false), "2000");
    }
}
