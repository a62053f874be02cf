//! Reading a block's text into a macro statement or an NC block with expressions
//! (docs/gcode.md, "Macros"), once when the program is loaded, and pairing each program's
//! DO and END.

use super::expr::{Expr, Parser};
use super::{Assign, MacroBlock, Then, Word, WordValue};
use crate::cnc::ps;
use crate::cnc::word::number;

/// Longest macro block read, in bytes without spaces and comments (0114 beyond).
pub const BLOCK_MAX: usize = 1024;

/// Whether the text (upper case, without spaces, comments, N or `/`) is one a macro reader
/// reads: a statement, a `#` or `[` anywhere, or G65/G66.
fn is_macro(rest: &str) -> bool {
    let b = rest.as_bytes();
    [
        "IF", "WHILE", "GOTO", "DO", "END", "POPEN", "PCLOS", "DPRNT", "BPRNT",
    ]
    .iter()
    .any(|k| rest.starts_with(k))
        || b.contains(&b'#')
        || b.contains(&b'[')
        || has_call(b)
}

/// A G65 or G66 word in the text.
fn has_call(b: &[u8]) -> bool {
    (0..b.len()).any(|i| {
        if b[i] != b'G' {
            return false;
        }
        let digits: Vec<u8> = b[i + 1..]
            .iter()
            .copied()
            .take_while(u8::is_ascii_digit)
            .collect();
        let next = b.get(i + 1 + digits.len());
        let text = String::from_utf8_lossy(&digits);
        next != Some(&b'.') && matches!(text.trim_start_matches('0'), "65" | "66")
    })
}

/// The text after a leading sequence number.
fn strip_n(body: &str) -> &str {
    if let Some(rest) = body.strip_prefix('N') {
        let d = rest.bytes().take_while(u8::is_ascii_digit).count();
        if d > 0 && !rest[d..].starts_with('.') {
            return &rest[d..];
        }
    }
    body
}

/// The first comment of a block's text, for #3000's message.
fn message(text: &str) -> Option<String> {
    let open = text.find('(')?;
    let rest = &text[open + 1..];
    let close = rest.find(')').unwrap_or(rest.len());
    let m = rest[..close].trim();
    (!m.is_empty()).then(|| m.chars().take(60).collect())
}

/// Reads a block's body (upper case, no spaces or comments, after `/`); `None` when it is a
/// plain NC block for the word reader. `text` is the block as written (for its comment).
pub fn parse(body: &str, text: &str) -> Option<Result<MacroBlock, u16>> {
    let rest = strip_n(body);
    if !is_macro(rest) {
        return None;
    }
    if rest.len() > BLOCK_MAX {
        // Longer than any CNC's block buffer, and deep enough to strain the evaluator.
        return Some(Err(ps::FORMAT));
    }
    Some(statement(rest, text))
}

fn statement(rest: &str, text: &str) -> Result<MacroBlock, u16> {
    let mut p = Parser::new(rest);
    if p.eat("IF") {
        if !p.rest().starts_with(b"[") {
            return Err(ps::FORMAT);
        }
        let cond = p.unary()?;
        let then = if p.eat("GOTO") {
            Then::Goto(goto_target(&mut p)?)
        } else if p.eat("THEN") {
            Then::Assign(assignment(&mut p, text)?)
        } else {
            return Err(ps::FORMAT);
        };
        return Ok(MacroBlock::If { cond, then });
    }
    if p.eat("GOTO") {
        return Ok(MacroBlock::Goto(goto_target(&mut p)?));
    }
    if rest == "POPEN" || rest == "PCLOS" {
        return Ok(MacroBlock::Output);
    }
    if (rest.starts_with("DPRNT[") || rest.starts_with("BPRNT[")) && rest.ends_with(']') {
        return Ok(MacroBlock::Output);
    }
    if p.eat("WHILE") {
        if !p.rest().starts_with(b"[") {
            return Err(ps::FORMAT);
        }
        let cond = p.unary()?;
        if !p.eat("DO") {
            return Err(ps::FORMAT);
        }
        let id = loop_number(&mut p)?;
        return Ok(MacroBlock::Do {
            cond: Some(cond),
            id,
            end: Err(ps::LOOP_END),
        });
    }
    if p.eat("DO") {
        let id = loop_number(&mut p)?;
        return Ok(MacroBlock::Do {
            cond: None,
            id,
            end: Err(ps::LOOP_END),
        });
    }
    if p.eat("END") {
        let id = loop_number(&mut p)?;
        return Ok(MacroBlock::End {
            id,
            start: Err(ps::LOOP_END),
        });
    }
    if rest.starts_with('#') {
        return Ok(MacroBlock::Assign(assignment(&mut p, text)?));
    }
    nc_words(rest)
}

/// A GOTO's sequence number: a constant, `#k` or `[e]`; nothing may follow.
fn goto_target(p: &mut Parser) -> Result<Expr, u16> {
    let e = p.unary()?;
    end(p)?;
    Ok(e)
}

/// DO m / END m: the digits of m (checked against 1–3 when loops are paired).
fn loop_number(p: &mut Parser) -> Result<u8, u16> {
    let digits: Vec<u8> = p
        .rest()
        .iter()
        .copied()
        .take_while(u8::is_ascii_digit)
        .collect();
    if digits.is_empty() {
        return Err(ps::FORMAT);
    }
    p.at += digits.len();
    end(p)?;
    let m: u32 = String::from_utf8_lossy(&digits).parse().unwrap_or(0);
    Ok(u8::try_from(m).unwrap_or(0))
}

/// The statement must end here: NC words after it are 0127, anything else 0114.
fn end(p: &Parser) -> Result<(), u16> {
    match p.rest().first() {
        None => Ok(()),
        Some(c) if c.is_ascii_uppercase() => Err(ps::MIXED),
        Some(_) => Err(ps::FORMAT),
    }
}

/// `#i = e`.
fn assignment(p: &mut Parser, text: &str) -> Result<Assign, u16> {
    if !p.rest().starts_with(b"#") {
        return Err(ps::FORMAT);
    }
    let target = p.unary()?;
    if !matches!(target, Expr::Var(_) | Expr::VarAt(_)) || !p.eat("=") {
        return Err(ps::FORMAT);
    }
    let value = p.expr()?;
    end(p)?;
    Ok(Assign {
        target,
        value,
        message: message(text),
    })
}

/// A word's value: an expression (`#`, `[`, a sign before either) or a number as written.
fn word_value(p: &mut Parser) -> Result<WordValue, u16> {
    let r = p.rest();
    let signed = matches!(r.first(), Some(b'-' | b'+'));
    let after = r.get(usize::from(signed));
    if matches!(after, Some(b'#' | b'[')) {
        return Ok(WordValue::Expr(p.unary()?));
    }
    let text = std::str::from_utf8(r).map_err(|_| ps::ADDRESS)?;
    let n = number(text).ok_or(ps::ADDRESS)?;
    p.at += n.text_len;
    Ok(WordValue::Lit(text[..n.text_len].to_string()))
}

/// An NC block whose words hold expressions, or a G65/G66 call.
fn nc_words(rest: &str) -> Result<MacroBlock, u16> {
    let mut p = Parser::new(rest);
    let mut words = Vec::new();
    while let Some(&c) = p.rest().first() {
        p.at += 1;
        let letter = match c {
            b',' => {
                let k = p.rest().first().copied().ok_or(ps::ADDRESS)?;
                p.at += 1;
                match k {
                    b'C' => b'c',
                    b'R' => b'r',
                    _ => return Err(ps::ADDRESS),
                }
            }
            b'=' => return Err(ps::MIXED),
            b'#' if p.rest().contains(&b'=') => return Err(ps::MIXED),
            c if c.is_ascii_uppercase() => c,
            _ => return Err(ps::FORMAT),
        };
        let value = word_value(&mut p)?;
        words.push(Word { letter, value });
    }
    let call = words.iter().position(|w| {
        w.letter == b'G'
            && matches!(&w.value, WordValue::Lit(t)
                if matches!(t.trim_start_matches('0'), "65" | "66"))
    });
    let Some(k) = call else {
        return Ok(MacroBlock::Nc(words));
    };
    let modal = matches!(&words[k].value, WordValue::Lit(t) if t.trim_start_matches('0') == "66");
    words.remove(k);
    let mut program = None;
    let mut count = None;
    let mut args = Vec::new();
    for w in words {
        match w.letter {
            b'P' if program.is_none() => program = Some(w.value),
            b'L' if count.is_none() => count = Some(w.value),
            b'G' | b'L' | b'N' | b'O' | b'P' | b'c' | b'r' => return Err(ps::ARG_ADDRESS),
            _ => args.push((w.letter, w.value)),
        }
    }
    Ok(MacroBlock::Call {
        modal,
        program: program.ok_or(ps::ARG_ADDRESS)?,
        count,
        args,
    })
}

/// Pairs each DO with its END in one program's blocks (their macro statements), innermost first; what does not pair
/// keeps its alarm (0124, or 0126 for a number other than 1–3).
pub fn pair_loops(blocks: &mut [&mut Option<Box<MacroBlock>>]) {
    for b in blocks.iter_mut() {
        match b.as_deref_mut() {
            Some(MacroBlock::Do { end, .. }) => *end = Err(ps::LOOP_END),
            Some(MacroBlock::End { start, .. }) => *start = Err(ps::LOOP_END),
            _ => {}
        }
    }
    let mut open: Vec<(u8, usize)> = Vec::new();
    for i in 0..blocks.len() {
        let Some(m) = blocks[i].as_deref_mut() else {
            continue;
        };
        match m {
            MacroBlock::Do { id, end, .. } => {
                if !(1..=3).contains(id) {
                    *end = Err(ps::LOOP_NUMBER);
                } else if open.iter().any(|(o, _)| o == id) {
                    *end = Err(ps::LOOP_END);
                } else {
                    open.push((*id, i));
                }
            }
            MacroBlock::End { id, start } => {
                if !(1..=3).contains(id) {
                    *start = Err(ps::LOOP_NUMBER);
                } else if open.last().is_some_and(|(o, _)| o == id) {
                    let (_, j) = open.pop().expect("checked");
                    *start = Ok(j);
                    if let Some(MacroBlock::Do { end, .. }) = blocks[j].as_deref_mut() {
                        *end = Ok(i);
                    }
                } else if let Some(k) = open.iter().position(|(o, _)| o == id) {
                    // Crossing loops: the inner DOs lose their END too.
                    open.truncate(k);
                }
            }
            _ => {}
        }
    }
}
