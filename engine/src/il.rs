//! Instruction-list text (docs/plc.md, "Instruction-list text"): parsing with line-numbered errors, printing in the
//! canonical form, and building a project whose ladder is drawn from the IL.

use crate::catalog::{InstrClass, Op};
use crate::compiler::decompile::decompile;
use crate::compiler::layout::{layout, width_needed};
pub use crate::compiler::text::{instr_text, operand_text};
use crate::compiler::{
    Compiled, IlFinding, Instr, Origin, Program, ProgramBlock, ProgramNetwork, Sink,
    compile_program,
};
use crate::model::{Block, BlockKind, DEFAULT_WIDTH, Ladder, MAX_WIDTH, Network, Operand, Project};
use std::fmt::Write as _;

/// Splits a line into tokens: words and `"quoted strings"`, up to a `;` comment. `None`
/// when a quoted text is not closed.
fn tokenize(line: &str) -> Option<Vec<(bool, String)>> {
    let mut tokens = Vec::new();
    let mut chars = line.chars().peekable();
    while let Some(&c) = chars.peek() {
        if c.is_whitespace() {
            chars.next();
        } else if c == ';' {
            break;
        } else if c == '"' {
            chars.next();
            let mut s = String::new();
            loop {
                match chars.next() {
                    None => return None,
                    Some('"') => break,
                    Some('\\') => match chars.next() {
                        Some('n') => s.push('\n'),
                        Some(other) => s.push(other),
                        None => return None,
                    },
                    Some(other) => s.push(other),
                }
            }
            tokens.push((true, s));
        } else {
            let mut s = String::new();
            while let Some(&c) = chars.peek() {
                if c.is_whitespace() || c == ';' || c == '"' {
                    break;
                }
                s.push(c);
                chars.next();
            }
            tokens.push((false, s));
        }
    }
    Some(tokens)
}

/// One parsed network before the split into networks is settled.
struct RawNetwork {
    title: String,
    comment: Vec<String>,
    instrs: Vec<Instr>,
    broken: bool,
    /// MPS not yet closed by MPP, kept as the lines come so a list without NETWORK lines
    /// is split in one pass rather than by rescanning the network at every line.
    open_mps: i32,
}

impl RawNetwork {
    fn new(title: String) -> RawNetwork {
        RawNetwork {
            title,
            comment: Vec::new(),
            instrs: Vec::new(),
            broken: false,
            open_mps: 0,
        }
    }

    fn push(&mut self, instr: Instr) {
        match instr.op {
            Op::Mps => self.open_mps += 1,
            Op::Mpp => self.open_mps -= 1,
            _ => {}
        }
        self.instrs.push(instr);
    }
}

/// Marks the network a bad line belongs to as broken, creating it when there is none yet.
fn mark_broken(nets: &mut Vec<RawNetwork>) {
    if nets.is_empty() {
        nets.push(RawNetwork::new(String::new()));
    }
    if let Some(n) = nets.last_mut() {
        n.broken = true;
    }
}

/// Parses IL text into a program with line origins. Errors go to `sink`.
pub fn parse(text: &str, sink: &mut Sink) -> Program {
    let mut parser = Parser::new(text);
    for (index, line) in text.lines().enumerate() {
        let origin = Origin::Line(index as u32 + 1);
        if !parser.line(line, origin, sink) {
            break;
        }
    }
    parser.into_program()
}

/// The parse's state between two lines: the blocks read so far (LEVEL1 and LEVEL2 always,
/// then each SUB), the one lines go to, and whether comment lines still make the current
/// network's comment.
struct Parser {
    /// Whether the text splits its networks itself; without NETWORK lines the instructions
    /// are split where a rung ends ([`starts_network`]).
    has_network_lines: bool,
    blocks: Vec<(BlockKind, Origin, Vec<RawNetwork>)>,
    current: usize,
    /// Whether comment lines may still join the current network's comment.
    in_header: bool,
}

impl Parser {
    /// A parser for `text`, which is looked through once for NETWORK lines first: whether
    /// there are any decides how every instruction is placed.
    fn new(text: &str) -> Parser {
        let has_network_lines = text.lines().any(|l| {
            tokenize(l)
                .and_then(|t| {
                    t.first()
                        .map(|(q, w)| !q && w.eq_ignore_ascii_case("NETWORK"))
                })
                .unwrap_or(false)
        });
        Parser {
            has_network_lines,
            blocks: vec![
                (BlockKind::Level1, Origin::None, Vec::new()),
                (BlockKind::Level2, Origin::None, Vec::new()),
            ],
            current: 0,
            in_header: false,
        }
    }

    /// Parses one line, reporting what is wrong with it. `false` at END, after which
    /// nothing is read.
    fn line(&mut self, line: &str, origin: Origin, sink: &mut Sink) -> bool {
        let Some(tokens) = tokenize(line) else {
            sink.find(origin, IlFinding::UnclosedQuote);
            mark_broken(&mut self.blocks[self.current].2);
            return true;
        };
        let Some((quoted, word)) = tokens.first() else {
            self.comment_line(line);
            return true;
        };
        self.in_header = false;
        if *quoted {
            sink.find(origin, IlFinding::QuotedLineStart);
            return true;
        }
        let upper = word.to_ascii_uppercase();
        match upper.as_str() {
            "END" => return false,
            "LEVEL1" | "LEVEL2" => {
                self.current = if upper == "LEVEL1" { 0 } else { 1 };
                self.blocks[self.current].1 = origin;
                if tokens.len() > 1 {
                    let level = self.current as u8 + 1;
                    sink.find(origin, IlFinding::AfterLevel { level });
                }
            }
            "SUB" | "SP" => self.sub(&tokens, origin, sink),
            "NETWORK" => self.network(&tokens, origin, sink),
            _ => self.instruction(word, &upper, &tokens, origin, sink),
        }
        true
    }

    /// A line with no token: a `;` comment right after NETWORK (or another such line) adds
    /// a line to the network's comment; any other comment ends the header.
    fn comment_line(&mut self, line: &str) {
        let trimmed = line.trim_start();
        if self.in_header && trimmed.starts_with(';') {
            let body = trimmed[1..].strip_prefix(' ').unwrap_or(&trimmed[1..]);
            if let Some(net) = self.blocks[self.current].2.last_mut() {
                net.comment.push(body.to_string());
            }
        } else if !trimmed.is_empty() {
            self.in_header = false;
        }
    }

    /// `SUB P0001 "NAME"`: a new subprogram block, which the next lines go to.
    fn sub(&mut self, tokens: &[(bool, String)], origin: Origin, sink: &mut Sink) {
        let number = tokens.get(1).and_then(|(q, t)| {
            (!q).then(|| crate::address::Address::parse(t).ok())
                .flatten()
        });
        match number {
            Some(a) if a.area == crate::address::Area::P && a.bit.is_none() => {
                let name = tokens.get(2).map(|(_, t)| t.clone()).unwrap_or_default();
                self.blocks.push((
                    BlockKind::Sub {
                        number: a.number,
                        name,
                    },
                    origin,
                    Vec::new(),
                ));
                self.current = self.blocks.len() - 1;
            }
            _ => sink.find(origin, IlFinding::SubWithoutNumber),
        }
    }

    /// `NETWORK "TITLE"`: a new network in the current block, whose comment lines follow.
    /// An unquoted title is kept, and reported.
    fn network(&mut self, tokens: &[(bool, String)], origin: Origin, sink: &mut Sink) {
        let title = match tokens.get(1) {
            Some((true, t)) => t.clone(),
            Some((false, t)) => {
                sink.find(origin, IlFinding::UnquotedTitle { title: t.clone() });
                t.clone()
            }
            None => String::new(),
        };
        self.blocks[self.current].2.push(RawNetwork::new(title));
        self.in_header = true;
    }

    /// An instruction line, added to the current network (or to a new one where a rung
    /// starts, when the text has no NETWORK lines). A line that cannot be read marks its
    /// network broken, so the network is not drawn from a partial list.
    fn instruction(
        &mut self,
        word: &str,
        upper: &str,
        tokens: &[(bool, String)],
        origin: Origin,
        sink: &mut Sink,
    ) {
        let Some(op) = Op::from_name(upper) else {
            sink.find(
                origin,
                IlFinding::UnknownInstruction {
                    word: shown(word),
                    meant: meant(upper),
                },
            );
            mark_broken(&mut self.blocks[self.current].2);
            return;
        };
        let Some(operands) = parse_operands(op, &tokens[1..], origin, sink) else {
            mark_broken(&mut self.blocks[self.current].2);
            return;
        };
        let instr = Instr {
            op,
            operands,
            origin,
        };
        let nets = &mut self.blocks[self.current].2;
        if nets.is_empty()
            || (!self.has_network_lines && nets.last().is_some_and(|n| starts_network(n, op)))
        {
            nets.push(RawNetwork::new(String::new()));
        }
        nets.last_mut()
            .expect("a network was just ensured")
            .push(instr);
    }

    /// The program the lines made, its networks' comment lines joined.
    fn into_program(self) -> Program {
        let mut program = Program::default();
        for (kind, origin, nets) in self.blocks {
            program.blocks.push(ProgramBlock {
                kind,
                origin,
                networks: nets
                    .into_iter()
                    .map(|n| ProgramNetwork {
                        title: n.title,
                        comment: n.comment.join("\n"),
                        instrs: n.instrs,
                        broken: n.broken,
                    })
                    .collect(),
            });
        }
        program
    }
}

/// An instruction's operand tokens as operands, or `None` after reporting the first that is
/// quoted or does not parse (the rest of the line is not read).
fn parse_operands(
    op: Op,
    tokens: &[(bool, String)],
    origin: Origin,
    sink: &mut Sink,
) -> Option<Vec<Operand>> {
    let mut operands = Vec::new();
    for (q, t) in tokens {
        if *q {
            sink.find(origin, IlFinding::QuotedOperand { text: t.clone() });
            return None;
        }
        match Operand::parse(t) {
            Ok(o) => operands.push(o),
            Err(error) => {
                sink.find(origin, IlFinding::BadOperand { op, error });
                return None;
            }
        }
    }
    Some(operands)
}

/// Without NETWORK lines: a network starts at an LD/LDI after an output when no MPS is open;
/// LBL and CALLU stand alone, and so does whatever follows them.
fn starts_network(prev: &RawNetwork, op: Op) -> bool {
    let Some(last) = prev.instrs.last() else {
        return false;
    };
    if !last.op.spec().needs_act() || !op.spec().needs_act() {
        return true;
    }
    let mps_open = prev.open_mps > 0;
    matches!(op, Op::Ld | Op::Ldi)
        && matches!(
            last.op.spec().class,
            InstrClass::Coil | InstrClass::Function
        )
        && !mps_open
}

/// The instruction an unknown mnemonic is meant to be: the closest mnemonic by edit distance,
/// when it is close enough to be a typo.
fn meant(upper: &str) -> Option<Op> {
    fn distance(a: &str, b: &str) -> usize {
        let b: Vec<char> = b.chars().collect();
        let mut prev: Vec<usize> = (0..=b.len()).collect();
        for (i, ca) in a.chars().enumerate() {
            let mut cur = vec![i + 1];
            for (j, cb) in b.iter().enumerate() {
                cur.push(
                    (prev[j] + usize::from(ca != *cb))
                        .min(prev[j + 1] + 1)
                        .min(cur[j] + 1),
                );
            }
            prev = cur;
        }
        prev[b.len()]
    }
    // The distance is at least the difference in length, so only names within two
    // characters of the word's length can be close enough; a long word costs one count.
    let len = upper.chars().count();
    crate::catalog::CATALOG
        .iter()
        .filter(|s| s.name.len().abs_diff(len) <= 2)
        // Ties go to the first name in alphabetical order.
        .map(|s| (distance(upper, s.name), s.name, s.op))
        .min()
        .filter(|(d, _, _)| *d <= 2)
        .map(|(_, _, op)| op)
}

/// Characters of an unknown word echoed in its message; the rest is elided.
const SHOWN_CHARS: usize = 40;

/// A word as a message quotes it: a line-long word is cut so the message stays readable.
fn shown(word: &str) -> String {
    match word.char_indices().nth(SHOWN_CHARS) {
        Some((at, _)) => format!("{}…", &word[..at]),
        None => word.to_string(),
    }
}

fn escape(s: &str) -> String {
    s.replace('\\', "\\\\")
        .replace('"', "\\\"")
        .replace('\n', "\\n")
}

/// Prints a program as canonical IL text.
pub fn print(program: &Program) -> String {
    let mut out = String::new();
    for block in &program.blocks {
        match &block.kind {
            BlockKind::Level1 => out.push_str("LEVEL1\n"),
            BlockKind::Level2 => out.push_str("LEVEL2\n"),
            BlockKind::Sub { number, name } => {
                let _ = write!(out, "SUB  P{number:04}");
                if !name.is_empty() {
                    let _ = write!(out, " \"{}\"", escape(name));
                }
                out.push('\n');
            }
        }
        for net in &block.networks {
            out.push_str("NETWORK");
            if !net.title.is_empty() {
                let _ = write!(out, " \"{}\"", escape(&net.title));
            }
            out.push('\n');
            if !net.comment.is_empty() {
                for line in net.comment.lines() {
                    let _ = writeln!(out, "; {line}");
                }
            }
            for i in &net.instrs {
                out.push_str(&instr_text(i.op, &i.operands));
                out.push('\n');
            }
        }
    }
    out.push_str("END\n");
    out
}

/// The result of reading IL into a project.
#[derive(Debug)]
pub struct Imported {
    /// The project, when the IL could be drawn as a ladder.
    pub project: Option<Project>,
    /// The IL checked as a program (diagnostics carry IL lines).
    pub compiled: Compiled,
}

/// Parses, checks and draws IL: the project's ladder is rebuilt from the instructions.
pub fn import(text: &str) -> Imported {
    let mut sink = Sink::default();
    let program = parse(text, &mut sink);
    let mut blocks = Vec::new();
    let mut drawable = sink.error_count() == 0;
    let mut width = DEFAULT_WIDTH;
    for (b, pb) in program.blocks.iter().enumerate() {
        let label = pb.kind.label();
        let mut nets = Vec::new();
        for (n, pn) in pb.networks.iter().enumerate() {
            sink.at(b, &label, n);
            if pn.broken {
                drawable = false;
                continue;
            }
            match decompile(&pn.instrs, &mut sink) {
                Some(rungs) => {
                    width = width.max(width_needed(&rungs));
                    nets.push((pn, rungs));
                }
                None => drawable = false,
            }
        }
        blocks.push((pb, nets));
    }
    let base = Project::default();
    let mut ladder = Ladder::new(width.min(MAX_WIDTH));
    ladder.blocks.clear();
    if drawable && width <= MAX_WIDTH {
        let mut next_id = 1;
        for (b, (pb, nets)) in blocks.into_iter().enumerate() {
            let label = pb.kind.label();
            let mut block = Block::new(pb.kind.clone());
            for (n, (pn, rungs)) in nets.into_iter().enumerate() {
                let mut network = Network::new(crate::model::NetworkId(next_id), width);
                next_id += 1;
                network.title = pn.title.clone();
                network.comment = pn.comment.clone();
                network.rows = layout(&rungs, width);
                network.il = crate::compiler::written::lines_to_keep(&pn.instrs);
                // The drawing must give the list back, or the import would change it unseen.
                if !crate::compiler::written::reads_back(&network, width, &pn.instrs) {
                    sink.at(b, &label, n);
                    sink.find(
                        pn.instrs.first().map(|i| i.origin).unwrap_or(Origin::None),
                        IlFinding::NotReadBack,
                    );
                    drawable = false;
                }
                block.networks.push(network);
            }
            ladder.blocks.push(block);
        }
    }
    let compiled = compile_program(program.clone(), &base, sink);
    if !drawable || width > MAX_WIDTH {
        return Imported {
            project: None,
            compiled,
        };
    }
    // Subprograms in P order, as the ladder keeps them.
    ladder.blocks[2..].sort_by_key(|b| b.kind.sub_number());
    // A project the editor could not open is never made: a subprogram defined twice (L038
    // says where) has no place in the ladder.
    if ladder.check_structure().is_err() {
        return Imported {
            project: None,
            compiled,
        };
    }
    Imported {
        project: Some(Project { ladder, ..base }),
        compiled,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::compiler::Finding;

    fn findings(text: &str) -> Vec<Finding> {
        let mut sink = Sink::default();
        parse(text, &mut sink);
        sink.diagnostics.into_iter().map(|d| d.finding).collect()
    }

    #[test]
    fn an_unknown_word_is_held_cut_short_with_the_instruction_it_is_close_to() {
        assert_eq!(meant("OUTT"), Some(Op::Out));
        assert_eq!(meant("TMRBB"), Some(Op::Tmrb));
        assert_eq!(meant("FROBNICATE"), None);
        let long = "Q".repeat(100);
        assert_eq!(
            findings(&format!("LEVEL1\n{long}\n")),
            [Finding::Il(IlFinding::UnknownInstruction {
                word: format!("{}…", &long[..SHOWN_CHARS]),
                meant: None,
            })]
        );
    }

    #[test]
    fn syntax_findings_hold_what_was_written() {
        assert_eq!(
            findings("LEVEL2 X\nNETWORK T\nLD \"X0000.0\"\nOUT X0000.9\n"),
            [
                Finding::Il(IlFinding::AfterLevel { level: 2 }),
                Finding::Il(IlFinding::UnquotedTitle { title: "T".into() }),
                Finding::Il(IlFinding::QuotedOperand {
                    text: "X0000.0".into()
                }),
                Finding::Il(IlFinding::BadOperand {
                    op: Op::Out,
                    error: crate::model::OperandError::Address(crate::address::AddressError::Bit(
                        "X0000.9".into()
                    )),
                }),
            ]
        );
    }
}
