//! The bundled CJK font and the widths of texts set in it: layout measures with the very
//! font the PDF embeds, so a label that fits on the page fits in print.

use std::collections::HashMap;

/// WenQuanYi Micro Hei (a TrueType collection; face 0 is used), for Chinese and Latin alike.
pub static FONT: &[u8] = include_bytes!("../../assets/fonts/wqy-microhei.ttc");

/// The font's characters' glyphs and advance widths in em, looked up once each.
pub struct Metrics {
    face: ttf_parser::Face<'static>,
    em: f32,
    cache: HashMap<char, (u16, f32)>,
}

impl Metrics {
    /// The metrics of the bundled font.
    pub fn new() -> Metrics {
        let face = ttf_parser::Face::parse(FONT, 0).expect("the bundled font parses");
        let em = f32::from(face.units_per_em());
        Metrics {
            face,
            em,
            cache: HashMap::new(),
        }
    }

    /// The glyphs that set `text`, one per character with its advance in em and the byte
    /// range of the character: the same advances [`Metrics::width`] measures, so text is
    /// printed exactly as wide as the layout made room for. (The labels are plain Chinese and
    /// Latin, which need no shaping beyond this; a character the font lacks is glyph 0.)
    pub fn glyphs(&mut self, text: &str) -> Vec<(u16, f32, std::ops::Range<usize>)> {
        text.char_indices()
            .map(|(i, c)| {
                let (id, advance) = self.glyph(c);
                (id, advance, i..i + c.len_utf8())
            })
            .collect()
    }

    /// The glyph of `c` (0 where the font lacks it) and its advance in em.
    fn glyph(&mut self, c: char) -> (u16, f32) {
        if let Some(g) = self.cache.get(&c) {
            return *g;
        }
        let id = self.face.glyph_index(c);
        let advance = id
            .and_then(|g| self.face.glyph_hor_advance(g))
            .map_or(if c.is_ascii() { 0.55 } else { 1.0 }, |a| {
                f32::from(a) / self.em
            });
        let g = (id.map_or(0, |g| g.0), advance);
        self.cache.insert(c, g);
        g
    }

    fn advance(&mut self, c: char) -> f32 {
        self.glyph(c).1
    }

    /// The width of `text` at `size` points.
    pub fn width(&mut self, text: &str, size: f32) -> f32 {
        text.chars().map(|c| self.advance(c)).sum::<f32>() * size
    }

    /// `text` cut to fit `width` at `size`, with `…` where it was cut.
    pub fn fit(&mut self, text: &str, size: f32, width: f32) -> String {
        if self.width(text, size) <= width {
            return text.to_string();
        }
        let room = width - self.width("…", size);
        let mut used = 0.0;
        let mut out = String::new();
        for c in text.chars() {
            let a = self.advance(c) * size;
            if used + a > room {
                break;
            }
            used += a;
            out.push(c);
        }
        out.push('…');
        out
    }

    /// `text` broken into lines of at most `width` at `size`: at spaces where it can, inside
    /// a word (or between Chinese characters) where it must.
    pub fn wrap(&mut self, text: &str, size: f32, width: f32) -> Vec<String> {
        let mut lines = Vec::new();
        for para in text.lines() {
            let mut line = String::new();
            let mut used = 0.0;
            // Where the line may break: after a space, or before a CJK character (Chinese
            // is broken between any two characters, so `X 轴正向…` does not leave `X` alone).
            let mut last_break: Option<usize> = None;
            for c in para.chars() {
                let a = self.advance(c) * size;
                // A closing mark (`）`, `，`, `。`) never starts a line: it goes down with the
                // character before it.
                let cjk = is_cjk(c) && !closes(c);
                if used + a > width && !line.is_empty() {
                    let at = if c == ' ' {
                        None
                    } else if cjk {
                        Some(line.len())
                    } else {
                        last_break
                    };
                    match at {
                        Some(at) => {
                            let rest = line.split_off(at);
                            lines.push(line.trim_end().to_string());
                            line = rest.trim_start().to_string();
                        }
                        None => lines.push(std::mem::take(&mut line).trim_end().to_string()),
                    }
                    used = self.width(&line, size);
                    last_break = None;
                    if c == ' ' && line.is_empty() {
                        continue;
                    }
                }
                if cjk {
                    last_break = Some(line.len());
                }
                line.push(c);
                used += a;
                if c == ' ' {
                    last_break = Some(line.len());
                }
            }
            lines.push(line);
        }
        lines
    }
}

/// Whether `c` closes a phrase (a bracket, a comma, a full stop): no line starts with it.
fn closes(c: char) -> bool {
    matches!(
        c,
        '）' | '」'
            | '』'
            | '】'
            | '》'
            | '〉'
            | '，'
            | '。'
            | '、'
            | '：'
            | '；'
            | '！'
            | '？'
            | ')'
    )
}

/// Whether `c` is a CJK ideograph or punctuation: a line may break before it.
fn is_cjk(c: char) -> bool {
    matches!(c as u32, 0x3000..=0x303F | 0x3400..=0x4DBF | 0x4E00..=0x9FFF | 0xF900..=0xFAFF | 0xFF00..=0xFFEF)
}

impl Default for Metrics {
    fn default() -> Self {
        Metrics::new()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn chinese_is_wider_than_latin_and_long_text_is_cut() {
        let mut m = Metrics::new();
        assert!(m.width("主轴", 10.0) > m.width("ab", 10.0));
        let cut = m.fit("Spindle forward rotation", 10.0, 40.0);
        assert!(cut.ends_with('…') && m.width(&cut, 10.0) <= 40.0, "{cut}");
        assert_eq!(m.fit("X0002.1", 10.0, 100.0), "X0002.1");
    }

    #[test]
    fn chinese_breaks_between_characters_so_a_latin_word_before_it_stays_on_its_line() {
        let mut m = Metrics::new();
        let text = "X 轴正向硬限位开关（常闭）";
        let width = m.width("X 轴正向硬", 10.0) + 0.5;
        let lines = m.wrap(text, 10.0, width);
        assert_eq!(lines[0], "X 轴正向硬", "{lines:?}");
        assert_eq!(lines.concat(), text.replace(' ', "").replacen("X", "X ", 1));
    }

    #[test]
    fn a_closing_bracket_never_starts_a_line() {
        let mut m = Metrics::new();
        let text = "主轴驱动器准备好（无报警）";
        let width = m.width("主轴驱动器准备好（无报警", 10.0) + 0.5;
        let lines = m.wrap(text, 10.0, width);
        assert!(lines.iter().all(|l| !l.starts_with('）')), "{lines:?}");
        assert_eq!(lines.concat(), text);
    }

    #[test]
    fn wrapping_breaks_at_spaces_and_keeps_every_word() {
        let mut m = Metrics::new();
        let lines = m.wrap("the spindle turns when the door is closed", 10.0, 80.0);
        assert!(lines.len() > 1, "{lines:?}");
        assert_eq!(lines.join(" "), "the spindle turns when the door is closed");
        for l in &lines {
            assert!(m.width(l, 10.0) <= 80.0, "{l}");
        }
        let zh = m.wrap("主轴正转时防护门必须关闭否则报警", 10.0, 50.0);
        assert_eq!(zh.concat(), "主轴正转时防护门必须关闭否则报警");
    }
}
