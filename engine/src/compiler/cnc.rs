//! CNC-aware checks (docs/diagnostics.md, W012–W018): mistakes in how a ladder talks to the
//! CNC that compile cleanly and only show on the machine, found from the compiled program's
//! data flow ([`Flow`]) and the F/G signal map both profiles share (docs/cnc.md, "Signals").
//!
//! They run only on a program that writes a G signal: one that writes none does not drive a
//! CNC at all (a test bench, a generated load program) and every rule would fire at once.
//! ERS and the mode signals are asked for only once the program writes a G signal besides
//! *ESP: a ladder whose one G signal is the E-stop chain leaves reset and modes to the panel.

use super::Program;
use super::diag::{Origin, Sink};
use super::finding::SignalFinding;
use super::flow::{Flow, InstrPlace, WriteKind, bit};
use super::tables::{MCODES, MESSAGES};
use crate::address::{Address, Area};
use crate::catalog::Op;
use crate::cnc::fsignals::{self as fs, FBit};
use crate::model::tables::message_rows;
use crate::model::{Operand, Project};
use std::collections::BTreeMap;

/// A signal of the map: its name and bit.
type Signal = (&'static str, (Area, u32, u8));

/// An F signal of the CNC's table (`cnc::fsignals`): the checks read the names the CNC writes.
const fn f(s: FBit) -> Signal {
    (s.name, (Area::F, s.byte as u32, s.bit))
}
const fn g(name: &'static str, byte: u32, b: u8) -> Signal {
    (name, (Area::G, byte, b))
}

const FIN: Signal = g("FIN", 4, 3);
const MFIN: Signal = g("MFIN", 5, 0);

/// The strobes and decode signals, each with the finish signals that answer it.
const STROBES: [(Signal, [Signal; 2]); 9] = [
    (f(fs::MF), [FIN, MFIN]),
    (f(fs::SF), [FIN, g("SFIN", 5, 2)]),
    (f(fs::TF), [FIN, g("TFIN", 5, 3)]),
    (f(fs::MF2), [FIN, g("MFIN2", 4, 4)]),
    (f(fs::MF3), [FIN, g("MFIN3", 4, 5)]),
    (f(fs::DM00), [FIN, MFIN]),
    (f(fs::DM01), [FIN, MFIN]),
    (f(fs::DM02), [FIN, MFIN]),
    (f(fs::DM30), [FIN, MFIN]),
];

/// The finish signals.
const FINISHES: [Signal; 6] = [
    FIN,
    MFIN,
    g("SFIN", 5, 2),
    g("TFIN", 5, 3),
    g("MFIN2", 4, 4),
    g("MFIN3", 4, 5),
];

/// The finding of a signal nothing writes, from its name and address.
type Unwritten = fn(String, Address) -> SignalFinding;

/// The signals without which the CNC cannot be stopped, reset or put in a mode, each with
/// its finding: what is lost without it differs from one to the next.
const ESSENTIAL: [(Signal, Unwritten); 5] = [
    (g("*ESP", 8, 4), |name, address| {
        SignalFinding::EmergencyStopUnwritten { name, address }
    }),
    (g("ERS", 8, 7), |name, address| {
        SignalFinding::ResetUnwritten { name, address }
    }),
    (g("MD1", 43, 0), |name, address| {
        SignalFinding::Mode1Unwritten { name, address }
    }),
    (g("MD2", 43, 1), |name, address| {
        SignalFinding::Mode2Unwritten { name, address }
    }),
    (g("MD4", 43, 2), |name, address| {
        SignalFinding::Mode4Unwritten { name, address }
    }),
];

/// F answers and the G request each confirms. (MABSM F4.2 is the inverse of ABSM, so it
/// reads 1 with ABSM never written: no pair.)
const ANSWERS: [(Signal, Signal); 8] = [
    (f(fs::MBDT1), g("BDT1", 44, 0)),
    (f(fs::MMLK), g("MLK", 44, 1)),
    (f(fs::MSBK), g("SBK", 46, 1)),
    (f(fs::MAFL), g("AFL", 5, 6)),
    (f(fs::MREF), g("ZRN", 43, 7)),
    (f(fs::MDRN), g("DRN", 46, 7)),
    (f(fs::STL), g("ST", 7, 2)),
    (f(fs::SPL), g("*SP", 8, 5)),
];

/// The M-code bytes (1st, 2nd, 3rd M code) and the decode signals with their codes.
const M_BYTES: [u16; 3] = [fs::M_CODE.byte, fs::M_CODE2.byte, fs::M_CODE3.byte];
const DECODED: [(u32, (Area, u32, u8)); 4] = [
    (0, f(fs::DM00).1),
    (1, f(fs::DM01).1),
    (2, f(fs::DM02).1),
    (30, f(fs::DM30).1),
];

/// M codes the CNC handles itself and never puts out (docs/cnc.md, "MST interface").
const NEVER_OUTPUT: [u32; 3] = [97, 98, 99];

fn address(s: Signal) -> Address {
    let (area, byte, b) = s.1;
    Address::bit(area, byte as u16, b)
}

/// Runs the CNC-aware checks on a compiled program (symbols resolved).
pub fn check_cnc(project: &Project, program: &Program, sink: &mut Sink) {
    // A program with errors has no reliable data flow; its errors come first.
    if sink.error_count() > 0 {
        return;
    }
    let flow = Flow::of(program);
    let g_written: Vec<(Area, u32, u8)> = flow
        .networks
        .iter()
        .flat_map(|n| &n.writes)
        .map(|(w, _)| w.unit)
        .filter(|u| u.0 == Area::G)
        .collect();
    if g_written.is_empty() {
        return;
    }
    strobes(program, &flow, sink);
    finishes(program, &flow, sink);
    let beyond_estop = g_written.iter().any(|&u| u != ESSENTIAL[0].0.1);
    essentials(program, &flow, beyond_estop, sink);
    answers(program, &flow, sink);
    m_codes(project, program, &flow, sink);
    alarms(project, program, &flow, sink);
}

fn at(program: &Program, sink: &mut Sink, place: InstrPlace) -> Origin {
    let (b, n, origin) = place;
    let label = program
        .blocks
        .get(b)
        .map(|bl| bl.kind.label())
        .unwrap_or_default();
    sink.at(b, &label, n);
    origin
}

/// W012: a strobe read with no path to FIN or its own finish signal.
fn strobes(program: &Program, flow: &Flow, sink: &mut Sink) {
    for (strobe, answers) in STROBES {
        let Some(place) = flow.first_read(strobe.1) else {
            continue;
        };
        if flow.reaches(strobe.1, &answers.map(|s| s.1)) {
            continue;
        }
        let origin = at(program, sink, place);
        sink.find(
            origin,
            SignalFinding::StrobeNoFinish {
                strobe: strobe.0.to_string(),
                address: address(strobe),
                finish: answers[1].0.to_string(),
                finish_address: address(answers[1]),
            },
        );
    }
}

/// W013: a finish signal driven from more than one rung, or latched and never released.
fn finishes(program: &Program, flow: &Flow, sink: &mut Sink) {
    for s in FINISHES {
        let (name, a) = (s.0, address(s));
        let mut drivers: Vec<InstrPlace> = Vec::new();
        let (mut set, mut rst_at) = (None, None);
        for (w, kind) in flow.writes_of(s.1) {
            match kind {
                WriteKind::Set => set = set.or(Some(w.place)),
                WriteKind::Rst => rst_at = rst_at.or(Some(w.place)),
                _ if drivers.iter().any(|p| (p.0, p.1) == (w.place.0, w.place.1)) => {}
                _ => drivers.push(w.place),
            }
        }
        if drivers.len() > 1 {
            let origin = at(program, sink, drivers[1]);
            sink.find(
                origin,
                SignalFinding::FinishWriters {
                    name: name.to_string(),
                    address: a,
                },
            );
        } else if let (Some(_), Some(latch)) = (drivers.first(), set.or(rst_at)) {
            let origin = at(program, sink, latch);
            sink.find(
                origin,
                SignalFinding::FinishDrivenAndLatched {
                    name: name.to_string(),
                    address: a,
                },
            );
        } else if let (Some(place), None) = (set, rst_at) {
            let origin = at(program, sink, place);
            sink.find(
                origin,
                SignalFinding::FinishNeverReset {
                    name: name.to_string(),
                    address: a,
                },
            );
        }
    }
}

/// W015: *ESP, ERS or a mode-select signal written nowhere.
fn essentials(program: &Program, flow: &Flow, beyond_estop: bool, sink: &mut Sink) {
    for (k, (s, finding)) in ESSENTIAL.into_iter().enumerate() {
        if flow.is_written(s.1) || (k > 0 && !beyond_estop) {
            continue;
        }
        // At the program's first element: where an E-stop chain usually begins.
        let first = program
            .blocks
            .iter()
            .enumerate()
            .flat_map(|(b, bl)| {
                bl.networks
                    .iter()
                    .enumerate()
                    .map(move |(n, net)| (b, n, net))
            })
            .find_map(|(b, n, net)| net.instrs.first().map(|i| (b, n, i.origin)))
            .unwrap_or((0, 0, Origin::None));
        let first = at(program, sink, first);
        sink.find(first, finding(s.0.to_string(), address(s)));
    }
}

/// W016: a G request written nowhere although its F answer is read.
fn answers(program: &Program, flow: &Flow, sink: &mut Sink) {
    for (answer, request) in ANSWERS {
        let Some(place) = flow.first_read(answer.1) else {
            continue;
        };
        if flow.is_written(request.1) {
            continue;
        }
        let origin = at(program, sink, place);
        sink.find(
            origin,
            SignalFinding::RequestUnwritten {
                answer: answer.0.to_string(),
                answer_address: address(answer),
                request: request.0.to_string(),
                request_address: address(request),
            },
        );
    }
}

/// The M codes the program decodes, each with where: DECB of an M-code byte whose output bit
/// is read, CMP of an M-code byte with a constant, a decode signal read.
fn decoded(program: &Program, flow: &Flow) -> BTreeMap<u32, InstrPlace> {
    let mut codes = BTreeMap::new();
    let m_byte = |o: &Operand| {
        o.address()
            .is_some_and(|a| a.area == Area::F && a.bit.is_none() && M_BYTES.contains(&a.number))
    };
    for (b, block) in program.blocks.iter().enumerate() {
        for (n, net) in block.networks.iter().enumerate() {
            for instr in &net.instrs {
                let place = (b, n, instr.origin);
                match (instr.op, instr.operands.as_slice()) {
                    (Op::Decb, [_, input, Operand::Int(base), out]) if m_byte(input) => {
                        let Some(o) = out.address() else { continue };
                        for k in 0..8u8 {
                            let unit = bit(o.area, u32::from(o.number), k);
                            // A base no M code reaches (negative, or past u32) decodes none.
                            let code = u32::try_from(*base + i64::from(k));
                            if let (Ok(code), Some(_)) = (code, flow.first_read(unit)) {
                                codes.entry(code).or_insert(place);
                            }
                        }
                    }
                    (Op::Cmp, [_, x, Operand::Int(v), _])
                    | (Op::Cmp, [_, Operand::Int(v), x, _])
                        if m_byte(x) && *v >= 0 =>
                    {
                        codes.entry(*v as u32).or_insert(place);
                    }
                    _ => {}
                }
            }
        }
    }
    for (code, unit) in DECODED {
        if let Some(place) = flow.first_read(unit) {
            codes.entry(code).or_insert(place);
        }
    }
    codes
}

/// W014: the M-code comment table and the decoded M codes disagree (once the table is kept).
fn m_codes(project: &Project, program: &Program, flow: &Flow, sink: &mut Sink) {
    if project.m_codes.is_empty() {
        return;
    }
    let codes = decoded(program, flow);
    sink.at(MCODES, "MCODES", 0);
    for (r, row) in project.m_codes.iter().enumerate() {
        if codes.contains_key(&row.code) || NEVER_OUTPUT.contains(&row.code) {
            continue;
        }
        sink.find(
            Origin::Cell {
                row: r as u32,
                col: 0,
            },
            SignalFinding::MCodeNotDecoded { code: row.code },
        );
    }
    for (&m, &place) in &codes {
        if project.m_codes.iter().any(|r| r.code == m) {
            continue;
        }
        let origin = at(program, sink, place);
        sink.find(origin, SignalFinding::MCodeNotInTable { code: m });
    }
}

/// W017 and W018: an A bit set without a message row, a message row whose A bit nothing
/// writes.
fn alarms(project: &Project, program: &Program, flow: &Flow, sink: &mut Sink) {
    // An empty table is one the project does not keep (an instruction list checked alone).
    if project.messages.rows.iter().all(|m| m.number.is_none()) {
        return;
    }
    let rows = message_rows(project.profile()).min(project.messages.rows.len());
    let mut reported = std::collections::HashSet::new();
    for net in &flow.networks {
        for (w, kind) in &net.writes {
            let (area, byte, b) = w.unit;
            let k = byte as usize * 8 + usize::from(b);
            // A byte write (MOVN 0 A0000) clears a group of alarms; only a bit raises one.
            if area != Area::A
                || matches!(kind, WriteKind::Rst | WriteKind::BoxByte)
                || k >= rows
                || project.messages.rows[k].number.is_some()
                || !reported.insert(k)
            {
                continue;
            }
            let a = crate::model::MessageTable::address(k);
            let origin = at(program, sink, w.place);
            sink.find(origin, SignalFinding::AlarmNoMessage { address: a });
        }
    }
    sink.at(MESSAGES, "MESSAGES", 0);
    for (k, m) in project.messages.rows.iter().enumerate().take(rows) {
        let Some(number) = m.number else { continue };
        let a = crate::model::MessageTable::address(k);
        let (byte, b) = (u32::from(a.number), a.bit.unwrap_or(0));
        let set = flow
            .writes_of(bit(Area::A, byte, b))
            .any(|(_, kind)| kind != WriteKind::Rst);
        if set {
            continue;
        }
        sink.find(
            Origin::Cell {
                row: k as u32,
                col: 1,
            },
            SignalFinding::MessageNeverSet { address: a, number },
        );
    }
}
