//! The CNC-aware warnings (W012–W018), each planted in a small instruction list and shown
//! absent where the rule is kept.

use super::{Code, Finding, Origin, SignalFinding, Sink, compile_program};
use crate::address::Address;
use crate::il;
use crate::model::tables::{MCodeRow, Message};
use crate::model::{Comments, Project};

/// A ladder that keeps every rule: E-stop and reset, the three mode bits, M03 decoded and
/// finished through the spindle output.
const GOOD: &str = "\
LEVEL1
NETWORK
LD   X0000.5
OUT  G0008.4
OUTN G0008.7
LEVEL2
NETWORK
LD   X0002.0
OUT  G0043.0
NETWORK
LD   X0002.1
OUT  G0043.1
NETWORK
LD   X0002.2
OUT  G0043.2
NETWORK
LD   F0007.0
DECB 4 F0010 0 R0200
NETWORK
LD   R0200.3
OUT  Y0000.0
NETWORK
LD   Y0000.0
AND  X0003.0
OUT  G0004.3
";

/// The CNC warnings of `text` checked against `project`: (code, block, origin, finding).
fn found_in(project: &Project, text: &str) -> Vec<(Code, String, Origin, SignalFinding)> {
    let mut sink = Sink::default();
    let program = il::parse(text, &mut sink);
    let compiled = compile_program(program, project, sink);
    compiled
        .diagnostics
        .iter()
        .filter(|d| d.code.as_str() >= "W012" && d.code.as_str() <= "W018")
        .map(|d| {
            (
                d.code,
                d.location.block_label.clone(),
                d.location.origin,
                match &d.finding {
                    Finding::Signal(f) => f.clone(),
                    other => panic!("not a CNC finding: {other:?}"),
                },
            )
        })
        .collect()
}

fn found(text: &str) -> Vec<(Code, String, Origin, SignalFinding)> {
    found_in(&Project::default(), text)
}

/// The address `text`.
fn at(text: &str) -> Address {
    Address::parse(text).unwrap()
}

/// `GOOD` with `extra` networks added to level 2.
fn with(extra: &str) -> String {
    format!("{GOOD}{extra}END\n")
}

fn codes_and_lines(f: &[(Code, String, Origin, SignalFinding)]) -> Vec<(Code, Origin)> {
    f.iter().map(|(c, _, o, _)| (*c, *o)).collect()
}

#[test]
fn a_ladder_that_keeps_every_rule_has_no_cnc_warning() {
    assert_eq!(found(&with("")), []);
}

#[test]
fn a_strobe_with_no_path_to_a_finish_is_reported_where_it_is_read() {
    // TF drives a lamp and nothing else.
    let f = found(&with("NETWORK\nLD   F0007.3\nOUT  Y0001.0\n"));
    assert_eq!(
        codes_and_lines(&f),
        [(Code::W012StrobeNoFinish, Origin::Line(27))]
    );
    assert_eq!(
        f[0].3,
        SignalFinding::StrobeNoFinish {
            strobe: "TF".into(),
            address: at("F0007.3"),
            finish: "TFIN".into(),
            finish_address: at("G0005.3"),
        }
    );
    // Through a relay into TFIN, the path exists.
    let kept = with("NETWORK\nLD   F0007.3\nOUT  R0010.0\nNETWORK\nLD   R0010.0\nOUT  G0005.3\n");
    assert_eq!(found(&kept), []);
    // A decode signal read for a lamp only is a strobe too.
    let f = found(&with("NETWORK\nLD   F0009.4\nOUT  Y0001.1\n"));
    assert_eq!(
        codes_and_lines(&f),
        [(Code::W012StrobeNoFinish, Origin::Line(27))]
    );
    assert!(
        matches!(&f[0].3, SignalFinding::StrobeNoFinish { strobe, address, .. }
            if strobe == "DM30" && *address == at("F0009.4")),
        "{f:?}"
    );
}

#[test]
fn fin_driven_from_two_rungs_or_latched_without_reset_is_reported() {
    let f = found(&with("NETWORK\nLD   X0004.0\nOUT  G0004.3\n"));
    let w013: Vec<_> = f
        .iter()
        .filter(|x| x.0 == Code::W013FinishWriters)
        .collect();
    assert_eq!(w013.len(), 1, "{f:?}");
    assert_eq!(w013[0].2, Origin::Line(28));
    let (name, address) = ("FIN".to_string(), at("G0004.3"));
    assert_eq!(
        w013[0].3,
        SignalFinding::FinishWriters {
            name: name.clone(),
            address
        }
    );
    // SET with no RST anywhere.
    let latched = GOOD.replace("OUT  G0004.3", "SET  G0004.3");
    let f = found(&format!("{latched}END\n"));
    assert_eq!(
        codes_and_lines(&f),
        [(Code::W013FinishWriters, Origin::Line(25))]
    );
    assert_eq!(
        f[0].3,
        SignalFinding::FinishNeverReset {
            name: name.clone(),
            address
        }
    );
    // A coil and a latch on it: reported at the latch.
    let both = format!("{GOOD}NETWORK\nLD   X0004.1\nSET  G0004.3\nEND\n");
    let f = found(&both);
    assert_eq!(
        codes_and_lines(&f),
        [(Code::W013FinishWriters, Origin::Line(28))]
    );
    assert_eq!(
        f[0].3,
        SignalFinding::FinishDrivenAndLatched { name, address }
    );
    // SET here, RST when the strobe drops: a latch, not two writers.
    let paired = format!("{latched}NETWORK\nLDI  F0007.0\nRST  G0004.3\nEND\n");
    assert_eq!(found(&paired), []);
}

#[test]
fn emergency_stop_reset_and_mode_signals_never_written_are_reported() {
    let no_md4 = GOOD.replace(
        "LD   X0002.2\nOUT  G0043.2\n",
        "LD   X0002.2\nOUT  R0001.0\n",
    );
    let f = found(&format!("{no_md4}END\n"));
    assert_eq!(
        codes_and_lines(&f),
        [(Code::W015CncSignalUnwritten, Origin::Line(3))]
    );
    assert_eq!(f[0].1, "LEVEL1");
    assert_eq!(
        f[0].3,
        SignalFinding::Mode4Unwritten {
            name: "MD4".into(),
            address: at("G0043.2")
        }
    );
    // A ladder whose only G signal is the E-stop chain is asked for nothing more.
    assert_eq!(
        found("LEVEL1\nNETWORK\nLD   X0000.5\nOUT  G0008.4\nEND\n"),
        []
    );
    // One that writes no G signal at all does not drive a CNC: no CNC rule applies.
    assert_eq!(
        found("LEVEL1\nNETWORK\nLD   F0007.0\nOUT  Y0000.0\nEND\n"),
        []
    );
    // Without the E-stop chain, *ESP is the one reported.
    let f = found("LEVEL1\nNETWORK\nLD   X0000.0\nOUT  G0008.7\nEND\n");
    let found: Vec<_> = f.into_iter().map(|x| x.3).collect();
    assert_eq!(
        found,
        [
            SignalFinding::EmergencyStopUnwritten {
                name: "*ESP".into(),
                address: at("G0008.4")
            },
            SignalFinding::Mode1Unwritten {
                name: "MD1".into(),
                address: at("G0043.0")
            },
            SignalFinding::Mode2Unwritten {
                name: "MD2".into(),
                address: at("G0043.1")
            },
            SignalFinding::Mode4Unwritten {
                name: "MD4".into(),
                address: at("G0043.2")
            },
        ]
    );
}

#[test]
fn an_answer_read_whose_request_nothing_writes_is_reported() {
    let f = found(&with("NETWORK\nLD   F0004.3\nOUT  Y0002.0\n"));
    assert_eq!(
        codes_and_lines(&f),
        [(Code::W016RequestUnwritten, Origin::Line(27))]
    );
    assert_eq!(
        f[0].3,
        SignalFinding::RequestUnwritten {
            answer: "MSBK".into(),
            answer_address: at("F0004.3"),
            request: "SBK".into(),
            request_address: at("G0046.1"),
        }
    );
    let kept = with("NETWORK\nLD   X0005.0\nOUT  G0046.1\nNETWORK\nLD   F0004.3\nOUT  Y0002.0\n");
    assert_eq!(found(&kept), []);
}

fn m_table(codes: &[u32]) -> Project {
    Project {
        m_codes: codes
            .iter()
            .map(|&code| MCodeRow {
                code,
                comments: Comments::default(),
            })
            .collect(),
        ..Project::default()
    }
}

#[test]
fn the_m_code_table_and_the_decoding_must_agree_once_the_table_is_kept() {
    // GOOD decodes M03 only (R0200.3 is the one decoded bit read).
    assert_eq!(found_in(&m_table(&[3, 98]), &with("")), []);
    // M05 in the table, never decoded: reported at its row.
    let f = found_in(&m_table(&[3, 5]), &with(""));
    assert_eq!(f.len(), 1, "{f:?}");
    assert_eq!(
        (f[0].0, f[0].1.as_str(), f[0].2),
        (
            Code::W014MCodeTable,
            "MCODES",
            Origin::Cell { row: 1, col: 0 }
        )
    );
    assert_eq!(f[0].3, SignalFinding::MCodeNotDecoded { code: 5 });
    // M04 read from the decode and M30 from its decode signal, both missing from the table:
    // reported where they are decoded.
    let more = with(
        "NETWORK\nLD   R0200.4\nOR   F0009.4\nOUT  Y0000.0\nNETWORK\nLD   X0006.0\nCMP  4 F0010 41 R0300.0\n",
    );
    let f = found_in(&m_table(&[3]), &more);
    let got: Vec<_> = f.iter().map(|x| (x.2, x.3.clone())).collect();
    let not_in_table = |code| SignalFinding::MCodeNotInTable { code };
    assert_eq!(
        got,
        [
            (Origin::Line(18), not_in_table(4)),
            (Origin::Line(28), not_in_table(30)),
            (Origin::Line(32), not_in_table(41))
        ],
        "{f:?}"
    );
    // With no table kept, nothing is compared.
    assert_eq!(found(&more), []);
}

fn messages(rows: &[(usize, u16)]) -> Project {
    let mut p = Project::default();
    for &(k, n) in rows {
        p.messages.rows[k] = Message {
            number: Some(n),
            texts: Comments::default(),
        };
    }
    p
}

#[test]
fn alarm_bits_and_message_rows_must_match_once_the_table_is_kept() {
    let text = with(
        "NETWORK\nLD   X0007.0\nSET  A0000.1\nNETWORK\nLD   X0007.1\nOUT  A0000.2\nNETWORK\nLD   X0007.2\nRST  A0000.4\n",
    );
    let f = found_in(&messages(&[(1, 1000), (3, 1001), (4, 1002)]), &text);
    let got: Vec<_> = f.iter().map(|x| (x.0, x.1.as_str(), x.2)).collect();
    assert_eq!(
        got,
        [
            (Code::W017AlarmNoMessage, "LEVEL2", Origin::Line(31)),
            (
                Code::W018MessageNeverSet,
                "MESSAGES",
                Origin::Cell { row: 3, col: 1 }
            ),
            (
                Code::W018MessageNeverSet,
                "MESSAGES",
                Origin::Cell { row: 4, col: 1 }
            ),
        ],
        "{f:?}"
    );
    assert_eq!(
        f[0].3,
        SignalFinding::AlarmNoMessage {
            address: at("A0000.2")
        }
    );
    assert_eq!(
        f[1].3,
        SignalFinding::MessageNeverSet {
            address: at("A0000.3"),
            number: 1001
        }
    );
    // Every row set, every set bit with a row.
    let kept = text.replace("RST  A0000.4", "SET  A0000.4");
    let f = found_in(
        &messages(&[(1, 1000), (2, 1003), (3, 1001), (4, 1002)]),
        &kept,
    );
    assert_eq!(
        codes_and_lines(&f),
        [(Code::W018MessageNeverSet, Origin::Cell { row: 3, col: 1 })]
    );
    // A byte write counts as setting every bit of its byte.
    let byte = format!(
        "{}NETWORK\nLD   X0007.3\nMOVN 1 255 A0000\nEND\n",
        kept.trim_end_matches("END\n")
    );
    assert_eq!(
        found_in(
            &messages(&[(1, 1000), (2, 1003), (3, 1001), (4, 1002)]),
            &byte
        ),
        []
    );
}
