//! CNC-aware checks (docs/diagnostics.md, W012–W018): mistakes in how a ladder talks to the
//! CNC that compile cleanly and only show on the machine, found from the compiled program's
//! data flow ([`Flow`]) and the F/G signal map both profiles share (docs/cnc.md, "Signals").
//!
//! They run only on a program that writes a G signal: one that writes none does not drive a
//! CNC at all (a test bench, a generated load program) and every rule would fire at once.
//! ERS and the mode signals are asked for only once the program writes a G signal besides
//! *ESP: a ladder whose one G signal is the E-stop chain leaves reset and modes to the panel.

use super::Program;
use super::diag::{Code, Origin, Sink};
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

/// The signals without which the CNC cannot be stopped, reset or put in a mode.
const ESSENTIAL: [(Signal, &str, &str); 5] = [
    (
        g("*ESP", 8, 4),
        "the CNC stays in emergency stop",
        "CNC 一直处于急停状态",
    ),
    (
        g("ERS", 8, 7),
        "nothing on the machine (an M30 end, a reset button, the E-stop) can reset the CNC",
        "机床侧（M30 结束、复位按钮、急停）无法使 CNC 复位",
    ),
    (
        g("MD1", 43, 0),
        "no EDIT, MEM (automatic), JOG, DNC or REF mode can be selected",
        "无法选择编辑、自动、手动、DNC 或回零方式",
    ),
    (
        g("MD2", 43, 1),
        "the EDIT mode cannot be selected",
        "无法选择编辑方式",
    ),
    (
        g("MD4", 43, 2),
        "no HANDLE, JOG or REF mode can be selected",
        "无法选择手脉、手动或回零方式",
    ),
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
        let (name, a) = (strobe.0, address(strobe));
        let (own, own_a) = (answers[1].0, address(answers[1]));
        let origin = at(program, sink, place);
        sink.report(
            origin,
            Code::W012StrobeNoFinish,
            format!(
                "{name} {a} is read, but nothing it drives leads to FIN G0004.3 or {own} {own_a}: the CNC waits for the finish forever; end the function's logic in FIN"
            ),
            format!(
                "读取了 {name} {a}，但由它驱动的逻辑都不通向 FIN G0004.3 或 {own} {own_a}：CNC 将一直等待完成信号；请让该功能的逻辑最终输出 FIN"
            ),
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
            sink.report(
                origin,
                Code::W013FinishWriters,
                format!(
                    "{name} {a} is written by more than one rung: the last write of the scan wins and a finish can be lost or held; gather every completion into one rung"
                ),
                format!(
                    "{name} {a} 被多个梯级写入：以扫描中最后一次写入为准，完成信号可能丢失或一直保持；请把所有完成条件归并到一个梯级"
                ),
            );
        } else if let (Some(_), Some(latch)) = (drivers.first(), set.or(rst_at)) {
            let origin = at(program, sink, latch);
            sink.report(
                origin,
                Code::W013FinishWriters,
                format!(
                    "{name} {a} is both driven by a coil or box and latched with SET/RST here: the coil rewrites it every scan, so the latch does nothing or fights it; use one or the other"
                ),
                format!(
                    "{name} {a} 既由线圈或功能指令驱动，又在此处用 SET/RST 锁存：线圈每个扫描都会改写它，锁存无效或与之冲突；请只用其中一种"
                ),
            );
        } else if let (Some(place), None) = (set, rst_at) {
            let origin = at(program, sink, place);
            sink.report(
                origin,
                Code::W013FinishWriters,
                format!(
                    "{name} {a} is latched with SET and never RST: once set, the CNC sees every later M, S, T function finished at once and the sequence cannot end; reset it when the strobe drops"
                ),
                format!(
                    "{name} {a} 用 SET 置位却从不 RST：一旦置位，之后的每个 M、S、T 功能都立即被当作完成，且完成序列无法结束；请在选通信号消失时复位"
                ),
            );
        }
    }
}

/// W015: *ESP, ERS or a mode-select signal written nowhere.
fn essentials(program: &Program, flow: &Flow, beyond_estop: bool, sink: &mut Sink) {
    for (k, (s, en, zh)) in ESSENTIAL.into_iter().enumerate() {
        if flow.is_written(s.1) || (k > 0 && !beyond_estop) {
            continue;
        }
        let (name, a) = (s.0, address(s));
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
        sink.report(
            first,
            Code::W015CncSignalUnwritten,
            format!("nothing writes {name} {a}, so the CNC always sees it at 0: {en}; drive it from the machine's inputs"),
            format!("没有任何指令写 {name} {a}，CNC 看到的始终是 0：{zh}；请由机床的输入驱动它"),
        );
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
        let (an, aa, rn, ra) = (answer.0, address(answer), request.0, address(request));
        let origin = at(program, sink, place);
        sink.report(
            origin,
            Code::W016RequestUnwritten,
            format!(
                "{an} {aa} is read, but nothing writes {rn} {ra}, the request it answers: the answer never comes; drive {rn} or read something else"
            ),
            format!(
                "读取了 {an} {aa}，但它所应答的请求信号 {rn} {ra} 没有任何指令写：应答永远不会出现；请驱动 {rn} 或改读其它信号"
            ),
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
        let m = row.code;
        sink.report(
            Origin::Cell {
                row: r as u32,
                col: 0,
            },
            Code::W014MCodeTable,
            format!(
                "M{m:02} is in the M-code table but no rung decodes it: the CNC waits for its finish forever; decode it (DECB or CMP of F0010) or remove the row"
            ),
            format!(
                "M{m:02} 在 M 代码表中，但没有梯级对它译码：CNC 将一直等待它完成；请对它译码（DECB 或 CMP F0010）或删除该行"
            ),
        );
    }
    for (&m, &place) in &codes {
        if project.m_codes.iter().any(|r| r.code == m) {
            continue;
        }
        let origin = at(program, sink, place);
        sink.report(
            origin,
            Code::W014MCodeTable,
            format!("M{m:02} is decoded here but has no row in the M-code table: add a row saying what it does"),
            format!("此处对 M{m:02} 译码，但 M 代码表中没有它：请添加一行说明其功能"),
        );
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
            sink.report(
                origin,
                Code::W017AlarmNoMessage,
                format!(
                    "{a} is set here but its row in the message table has no alarm number: the CNC shows no alarm for it; give the row an alarm number and a text"
                ),
                format!("此处置位 {a}，但信息表中它的行没有报警号：CNC 不会为它显示报警；请为该行填写报警号和文本"),
            );
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
        sink.report(
            Origin::Cell {
                row: k as u32,
                col: 1,
            },
            Code::W018MessageNeverSet,
            format!(
                "{a}: alarm {number} has a message but nothing in the program sets {a}: it can never show; set the bit where the fault is detected, or clear the row"
            ),
            format!("{a}：报警 {number} 有信息，但程序中没有任何指令置位 {a}，它永远不会显示；请在检测到故障处置位该位，或清除该行"),
        );
    }
}
