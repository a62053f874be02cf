//! NC program text (docs/cnc.md, "NC programs"): split into programs and blocks, each block
//! read into its words once when the text is loaded. Errors that depend only on the text are
//! found here and kept with the block; like a real CNC, the simulator raises them only when the
//! block is about to execute. Errors that depend on the machine state (an axis beyond #8130,
//! G01 without F, M98 to a missing program…) are checked at that moment by `auto.rs`.

use super::macro_b::{MacroBlock, parse::pair_loops};
use super::word::{Words, number, words};

/// P/S alarm numbers of program errors.
pub use super::ps;

/// Largest program file read (docs/gcode.md, "Reader"): 16 MiB.
pub const FILE_MAX: u64 = 16 * 1024 * 1024;

/// Why a program file could not be read.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum ProgramFileError {
    /// The file is larger than [`FILE_MAX`] bytes (its size given); nothing was read.
    TooLarge(u64),
    /// The system's error reading it.
    Io(String),
}

/// Reads a program file as a CNC reads a tape: bytes, so comments may hold any encoding
/// (Latin-1, GBK…; bytes that are not UTF-8 become U+FFFD, which only comments may hold).
/// A file over [`FILE_MAX`] is refused before it is read.
pub fn read_program_file(path: &std::path::Path) -> Result<String, ProgramFileError> {
    let size = std::fs::metadata(path)
        .map_err(|e| ProgramFileError::Io(e.to_string()))?
        .len();
    if size > FILE_MAX {
        return Err(ProgramFileError::TooLarge(size));
    }
    // Bounded as it reads too: a device reports no size (`/dev/zero`).
    let bytes = crate::file::read_limited(path, FILE_MAX).map_err(|e| {
        if e.kind() == std::io::ErrorKind::FileTooLarge {
            ProgramFileError::TooLarge(FILE_MAX + 1)
        } else {
            ProgramFileError::Io(e.to_string())
        }
    })?;
    Ok(String::from_utf8_lossy(&bytes).into_owned())
}

/// One block.
#[derive(Clone, Debug, PartialEq)]
pub struct NcBlock {
    /// 1-based line of the text it came from.
    pub line: usize,
    /// Its text, as written.
    pub text: String,
    /// It began with `/` (skipped while BDT1 = 1).
    pub slash: bool,
    /// Its sequence number.
    pub n: Option<u32>,
    /// Its words, or the P/S alarm its text gives. A macro block's are P/S 0066 (a cycle's
    /// profile cannot hold one).
    pub words: Result<Words, u16>,
    /// The macro statement or the NC words with expressions it holds (docs/gcode.md,
    /// "Macros").
    pub mac: Option<Box<MacroBlock>>,
}

/// One program: O number and blocks.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct NcProgram {
    /// O number, 1–99999999 (0 for text before the first O line; [`MDI_NUMBER`] for MDI).
    pub number: u32,
    /// Blocks in order (O lines, blank lines and comments are not blocks).
    pub blocks: Vec<NcBlock>,
}

/// Program number reported for the MDI buffer.
pub const MDI_NUMBER: u32 = 10_000;

/// Whether a line is a tape mark: `%` (or the full-width `％`) first on the line.
fn tape_mark(line: &str) -> bool {
    let t = line.trim_start();
    t.starts_with('%') || t.starts_with('％')
}

/// The lines of the tape with their 1-based numbers: when the text has a `%` line, the
/// text before the first one is leader and the text after the second one is past the end of
/// the tape; both are ignored (docs/gcode.md, "Reader").
fn tape(text: &str) -> impl Iterator<Item = (usize, &str)> {
    let marks = text.lines().filter(|l| tape_mark(l)).take(2).count();
    let mut seen = 0;
    text.lines().enumerate().filter_map(move |(i, l)| {
        if tape_mark(l) {
            seen += 1;
            return None;
        }
        let inside = marks == 0 || seen == 1;
        inside.then_some((i + 1, l))
    })
}

/// Splits text into programs: `O`n or `:`n (n of 1–8 digits) starts one; text before the
/// first is O0000.
pub fn parse_programs(text: &str) -> Vec<NcProgram> {
    let mut programs: Vec<NcProgram> = Vec::new();
    for (line, segment) in segments(text) {
        let clean = clean(segment);
        if clean.is_empty() {
            continue;
        }
        let mut body = clean.as_str();
        if let Some(rest) = body.strip_prefix('O').or_else(|| body.strip_prefix(':')) {
            let digits = rest.bytes().take_while(u8::is_ascii_digit).count();
            let number: Option<u32> = rest[..digits].parse().ok().filter(|_| digits <= 8);
            match number {
                Some(o) if o >= 1 => {
                    programs.push(NcProgram {
                        number: o,
                        blocks: Vec::new(),
                    });
                    body = &rest[digits..];
                    if body.is_empty() {
                        continue;
                    }
                }
                _ => {
                    // A malformed O line is a block that cannot execute.
                    let alarm = if digits > 8 { ps::DIGITS } else { ps::ADDRESS };
                    push(
                        &mut programs,
                        NcBlock {
                            line,
                            text: segment.trim().to_string(),
                            slash: false,
                            n: None,
                            words: Err(alarm),
                            mac: None,
                        },
                    );
                    continue;
                }
            }
        }
        let block = parse_block(line, segment.trim(), body);
        push(&mut programs, block);
    }
    for p in &mut programs {
        pair(&mut p.blocks);
    }
    programs
}

/// Pairs the DO and END statements of one program's blocks.
fn pair(blocks: &mut [NcBlock]) {
    let mut macs: Vec<&mut Option<Box<MacroBlock>>> =
        blocks.iter_mut().map(|b| &mut b.mac).collect();
    pair_loops(&mut macs);
}

fn push(programs: &mut Vec<NcProgram>, block: NcBlock) {
    if programs.is_empty() {
        programs.push(NcProgram::default());
    }
    programs.last_mut().expect("one program").blocks.push(block);
}

/// The MDI buffer: every block of the text as one program.
pub fn parse_mdi(text: &str) -> NcProgram {
    let mut blocks: Vec<NcBlock> = parse_programs(text)
        .into_iter()
        .flat_map(|p| p.blocks)
        .collect();
    pair(&mut blocks);
    NcProgram {
        number: MDI_NUMBER,
        blocks,
    }
}

/// Blocks of text with their 1-based lines: `;` and newlines end blocks.
fn segments(text: &str) -> impl Iterator<Item = (usize, &str)> {
    tape(text).flat_map(|(i, l)| blocks_of_line(l).map(move |s| (i, s)))
}

/// A line's blocks: split at each `;` outside a `( … )` comment.
fn blocks_of_line(line: &str) -> impl Iterator<Item = &str> {
    let mut depth = 0u32;
    let mut start = 0;
    let mut ends = Vec::new();
    for (k, c) in line.char_indices() {
        match c {
            '(' => depth += 1,
            ')' => depth = depth.saturating_sub(1),
            ';' if depth == 0 => ends.push(k),
            _ => {}
        }
    }
    ends.push(line.len());
    ends.into_iter().map(move |e| {
        let s = &line[start..e];
        start = (e + 1).min(line.len());
        s
    })
}

/// Upper case, without spaces and `( … )` comments.
fn clean(segment: &str) -> String {
    let mut out = String::with_capacity(segment.len());
    let mut depth = 0;
    for c in segment.chars() {
        match c {
            '(' => depth += 1,
            ')' if depth > 0 => depth -= 1,
            _ if depth > 0 => {}
            c if c.is_whitespace() => {}
            c => out.push(c.to_ascii_uppercase()),
        }
    }
    out
}

fn parse_block(line: usize, text: &str, body: &str) -> NcBlock {
    let (slash, body) = match body.strip_prefix('/') {
        Some(rest) => (true, rest),
        None => (false, body),
    };
    let mut block = NcBlock {
        line,
        text: text.to_string(),
        slash,
        n: None,
        words: Ok(Words::default()),
        mac: None,
    };
    // The N comes first; read it even when a later word is wrong, so the alarm can name it.
    if let Some(rest) = body.strip_prefix('N')
        && let Some(num) = number(rest)
        && !num.decimal
        && num.value >= 1.0
        && num.value <= 99_999.0
    {
        block.n = Some(num.value as u32);
    }
    block.words = match super::macro_b::parse::parse(body, text) {
        None => words(body),
        Some(Ok(m)) => {
            block.mac = Some(Box::new(m));
            Err(ps::CYCLE_COMMAND)
        }
        Some(Err(alarm)) => Err(alarm),
    };
    block
}

/// The index of the block numbered `n` in `prog`, searched from `from` to the end, then from
/// the start.
pub fn find_sequence(prog: &NcProgram, n: u32, from: usize) -> Option<usize> {
    let at = |i: usize| prog.blocks[i].n == Some(n);
    (from..prog.blocks.len())
        .find(|&i| at(i))
        .or_else(|| (0..from.min(prog.blocks.len())).find(|&i| at(i)))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn block(text: &str) -> NcBlock {
        let p = parse_programs(text);
        p[0].blocks[0].clone()
    }

    #[test]
    fn programs_split_at_o_lines_and_text_before_is_o0000() {
        let p = parse_programs("G00 X1;\nO0001 (MAIN)\nM03 S800;T0202\n\nO12;M99");
        assert_eq!(p.len(), 3);
        assert_eq!((p[0].number, p[0].blocks.len()), (0, 1));
        assert_eq!((p[1].number, p[1].blocks.len()), (1, 2));
        assert_eq!(p[2].number, 12);
        assert_eq!(p[1].blocks[1].line, 3);
    }

    #[test]
    fn the_tape_runs_from_the_first_percent_line_to_the_second() {
        // Leader before the first `%` (any text, even what would be an error), the tape,
        // and text after the second `%` are told apart; lines keep their numbers.
        let text = "LEADER X1..2 #@!\n%\nO0007\nN1 G00 X1\n%\nTRAILER Q\n";
        let p = parse_programs(text);
        assert_eq!(p.len(), 1);
        assert_eq!(p[0].number, 7);
        assert_eq!(p[0].blocks.len(), 1);
        assert_eq!(p[0].blocks[0].line, 4);
        // A full-width percent sign counts, and one `%` alone opens a tape to the end.
        let p = parse_programs("junk\n\u{ff05}\nO8;N2 M30");
        assert_eq!((p[0].number, p[0].blocks.len()), (8, 1));
        // Without any `%` every line is program text, as before.
        assert_eq!(parse_programs("N1;N2")[0].blocks.len(), 2);
    }

    #[test]
    fn program_numbers_have_one_to_eight_digits_after_o_or_colon() {
        let p = parse_programs("O12345678;N1;:2001 (COLON);N2");
        assert_eq!(p[0].number, 12_345_678);
        assert_eq!(p[1].number, 2001);
        assert_eq!(p[1].blocks.len(), 1);
        let p = parse_programs("O123456789;N1");
        assert_eq!(p[0].blocks[0].words, Err(ps::DIGITS));
        let p = parse_programs("O0;N1");
        assert_eq!(p[0].blocks[0].words, Err(ps::ADDRESS));
    }

    #[test]
    fn comments_may_hold_any_text_and_l_is_a_count() {
        let b = block("N5 M98 P1234 L3 (\u{fffd}\u{fffd} GBK \u{5200}\u{5177} %;)");
        let w = b.words.unwrap();
        assert_eq!((w.p, w.l), (Some(1234), Some(3)));
        // A `;` inside a comment does not end the block; outside one it does.
        let p = parse_programs("N1 G00 X1 (ROUGH; THEN FINISH);N2 M30");
        assert_eq!(p[0].blocks.len(), 2);
        assert!(p[0].blocks.iter().all(|b| b.words.is_ok()));
    }

    #[test]
    fn a_program_file_is_read_as_bytes_and_a_huge_one_is_refused_unread() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("gbk.nc");
        // "O0001 (刀具)" with the comment in GBK, then a block.
        let mut bytes = b"O0001 (".to_vec();
        bytes.extend_from_slice(&[0xB5, 0xB6, 0xBE, 0xDF]);
        bytes.extend_from_slice(b")\nN10 G00 X5\n");
        std::fs::write(&path, &bytes).unwrap();
        let text = read_program_file(&path).unwrap();
        let p = parse_programs(&text);
        assert_eq!((p[0].number, p[0].blocks[0].n), (1, Some(10)));
        assert!(p[0].blocks[0].words.is_ok());
        let big = dir.path().join("big.nc");
        let f = std::fs::File::create(&big).unwrap();
        f.set_len(FILE_MAX + 1).unwrap();
        let e = read_program_file(&big).unwrap_err();
        assert_eq!(e, ProgramFileError::TooLarge(FILE_MAX + 1));
        let missing = read_program_file(&dir.path().join("none.nc")).unwrap_err();
        assert!(matches!(missing, ProgramFileError::Io(_)));
    }

    #[test]
    fn words_read_as_written() {
        let b = block("/N20 G01 X10 W-5.5 F100 M03 M08 S800 T0202");
        assert!(b.slash);
        assert_eq!(b.n, Some(20));
        let w = b.words.unwrap();
        assert_eq!(w.motion, Some(1));
        let num = |value, decimal| super::super::word::Num { value, decimal };
        assert_eq!(w.axes[0], Some((num(10.0, false), false)));
        assert_eq!(w.axes[1], Some((num(-5.5, true), true)));
        assert_eq!(w.ms(), &[3, 8]);
        assert_eq!((w.s, w.t, w.f), (Some(800), Some(202), Some(100.0)));
        let w = block("G04 X1.5").words.unwrap();
        assert_eq!(
            (w.dwell(), w.dwell_x, w.axes[0]),
            (true, Some(num(1.5, true)), None)
        );
        assert!(block("g13.1 g18 g21 g40 g67 g97 g15").words.is_ok());
    }

    #[test]
    fn text_errors_give_their_alarm_and_keep_the_n() {
        let cases = [
            ("N10 G01 X1 X2", 9),
            ("N10 E5", 9),
            ("N10 L1.5", 9),
            ("N10 X", 9),
            ("N10 X1..2", 9),
            ("N10 G02.5 X1", 10),
            ("N10 G00 G01 X1", 10),
            ("N10 X123456789", 3),
            ("N10 T12345", 3),
            ("N10 M1 M2 M3 M4", 14),
            ("N10 M1 M70000", 3),
            ("N10 G00 X1 #1=2", 127),
            ("N10 #1=[2", 114),
            ("N10 S1.5", 9),
        ];
        for (text, alarm) in cases {
            let b = block(text);
            assert_eq!(b.words, Err(alarm), "{text}");
            assert_eq!(b.n, Some(10), "{text}");
        }
        assert_eq!(block("N123456 X1").words, Err(3));
        assert_eq!(block("N123456 X1").n, None);
    }

    #[test]
    fn mdi_is_one_program() {
        let m = parse_mdi("M03 S500;O0005;G04 P100");
        assert_eq!(m.number, MDI_NUMBER);
        assert_eq!(m.blocks.len(), 2);
    }
}
