//! An NC block's expression words turned into the text the G-code reader reads
//! (docs/gcode.md, "Macros", "Values in words"): each value rounded to its address's least
//! increment, a vacant value leaving its address out.

use super::expr::Vars;
use super::{Word, WordValue};
use crate::cnc::SimCnc;
use crate::cnc::word::{Words, words};
use std::fmt::Write;

/// Addresses whose value is a whole number (a code, a count, a program or sequence number).
fn integer_letter(letter: u8) -> bool {
    matches!(
        letter,
        b'N' | b'O' | b'P' | b'L' | b'M' | b'S' | b'T' | b'H'
    )
}

/// Rounded half away from zero to `places` decimals, written without a negative zero.
fn fixed(v: f64, places: usize) -> String {
    let scale = 10f64.powi(places as i32);
    let r = (v * scale).round() / scale;
    let r = if r == 0.0 { 0.0 } else { r };
    format!("{r:.places$}")
}

/// The text of one value at an address.
pub(super) fn value_text(letter: u8, v: f64, inch: bool, sequence_q: bool) -> String {
    if integer_letter(letter) || (letter == b'Q' && sequence_q) {
        return fixed(v, 0);
    }
    match letter {
        b'G' => {
            let t = fixed(v, 1);
            t.strip_suffix(".0").map_or(t.clone(), str::to_string)
        }
        b'F' => {
            let t = fixed(v, 4);
            let t = t.trim_end_matches('0');
            t.to_string()
        }
        _ => fixed(v, if inch { 4 } else { 3 }),
    }
}

impl SimCnc {
    /// The words of an NC block with expressions, evaluated now.
    pub(in crate::cnc) fn render_words(&self, ws: &[Word]) -> Result<Words, u16> {
        let mut values = Vec::with_capacity(ws.len());
        for w in ws {
            values.push(match &w.value {
                WordValue::Lit(t) => Some(Err(t.as_str())),
                WordValue::Expr(e) => e.eval(self as &dyn Vars)?.map(Ok),
            });
        }
        // Q is a sequence number in G70–G73 (P always is a whole number).
        let sequence_q = ws.iter().zip(&values).any(|(w, v)| {
            w.letter == b'G'
                && match v {
                    Some(Err(t)) => t.parse::<f64>().is_ok_and(|g| (70.0..=73.0).contains(&g)),
                    Some(Ok(g)) => (70.0..=73.0).contains(g),
                    None => false,
                }
        });
        let inch = self.auto.modal.inch;
        let mut text = String::new();
        for (w, v) in ws.iter().zip(values) {
            let Some(v) = v else { continue };
            match w.letter {
                b'c' => text.push_str(",C"),
                b'r' => text.push_str(",R"),
                l => text.push(char::from(l)),
            }
            match v {
                Err(lit) => text.push_str(lit),
                Ok(x) => {
                    let _ = write!(text, "{}", value_text(w.letter, x, inch, sequence_q));
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
        assert_eq!(value_text(b'X', 1.2345, false, false), "1.235");
        assert_eq!(value_text(b'X', -1.2345, false, false), "-1.235");
        assert_eq!(value_text(b'X', 1.23456, true, false), "1.2346");
        assert_eq!(value_text(b'X', -0.0001, false, false), "0.000");
        assert_eq!(value_text(b'M', 2.5, false, false), "3");
        assert_eq!(value_text(b'G', 1.0, false, false), "1");
        assert_eq!(value_text(b'G', 13.1, false, false), "13.1");
        assert_eq!(value_text(b'F', 0.25, false, false), "0.25");
        assert_eq!(value_text(b'F', 100.0, false, false), "100.");
        assert_eq!(value_text(b'Q', 20.0, false, true), "20");
        assert_eq!(value_text(b'Q', 2.0, false, false), "2.000");
    }
}
