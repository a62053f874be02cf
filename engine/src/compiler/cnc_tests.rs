//! The CNC-aware warnings (W012–W018), each planted in a small instruction list and shown
//! absent where the rule is kept.

use super::{Code, Origin, Sink, compile_program};
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

/// The CNC warnings of `text` checked against `project`: (code, block, origin, message).
fn found_in(project: &Project, text: &str) -> Vec<(Code, String, Origin, String)> {
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
                d.message().to_string(),
            )
        })
        .collect()
}

fn found(text: &str) -> Vec<(Code, String, Origin, String)> {
    found_in(&Project::default(), text)
}

/// `GOOD` with `extra` networks added to level 2.
fn with(extra: &str) -> String {
    format!("{GOOD}{extra}END\n")
}

fn codes_and_lines(f: &[(Code, String, Origin, String)]) -> Vec<(Code, Origin)> {
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
    assert!(f[0].3.starts_with("TF F0007.3 is read"), "{f:?}");
    assert!(f[0].3.contains("TFIN G0005.3"), "{f:?}");
    // Through a relay into TFIN, the path exists.
    let kept = with("NETWORK\nLD   F0007.3\nOUT  R0010.0\nNETWORK\nLD   R0010.0\nOUT  G0005.3\n");
    assert_eq!(found(&kept), []);
    // A decode signal read for a lamp only is a strobe too.
    let f = found(&with("NETWORK\nLD   F0009.4\nOUT  Y0001.1\n"));
    assert_eq!(
        codes_and_lines(&f),
        [(Code::W012StrobeNoFinish, Origin::Line(27))]
    );
    assert!(f[0].3.starts_with("DM30 F0009.4"), "{f:?}");
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
    assert!(w013[0].3.contains("more than one rung"));
    // SET with no RST anywhere.
    let latched = GOOD.replace("OUT  G0004.3", "SET  G0004.3");
    let f = found(&format!("{latched}END\n"));
    assert_eq!(
        codes_and_lines(&f),
        [(Code::W013FinishWriters, Origin::Line(25))]
    );
    assert!(f[0].3.contains("latched with SET and never RST"));
    // A coil and a latch on it: reported at the latch.
    let both = format!("{GOOD}NETWORK\nLD   X0004.1\nSET  G0004.3\nEND\n");
    let f = found(&both);
    assert_eq!(
        codes_and_lines(&f),
        [(Code::W013FinishWriters, Origin::Line(28))]
    );
    assert!(
        f[0].3.contains("both driven by a coil or box and latched"),
        "{f:?}"
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
    assert!(f[0].3.starts_with("nothing writes MD4 G0043.2"), "{f:?}");
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
    let names: Vec<_> = f.iter().map(|x| x.3.split(',').next().unwrap()).collect();
    assert_eq!(
        names,
        [
            "nothing writes *ESP G0008.4",
            "nothing writes MD1 G0043.0",
            "nothing writes MD2 G0043.1",
            "nothing writes MD4 G0043.2"
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
    assert!(f[0].3.contains("SBK G0046.1"), "{f:?}");
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
    assert!(f[0].3.starts_with("M05 is in the M-code table"));
    // M04 read from the decode and M30 from its decode signal, both missing from the table:
    // reported where they are decoded.
    let more = with(
        "NETWORK\nLD   R0200.4\nOR   F0009.4\nOUT  Y0000.0\nNETWORK\nLD   X0006.0\nCMP  4 F0010 41 R0300.0\n",
    );
    let f = found_in(&m_table(&[3]), &more);
    let got: Vec<_> = f
        .iter()
        .map(|x| (x.2, x.3.split(' ').next().unwrap()))
        .collect();
    assert_eq!(
        got,
        [
            (Origin::Line(18), "M04"),
            (Origin::Line(28), "M30"),
            (Origin::Line(32), "M41")
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
    assert!(
        f[0].3.starts_with(
            "A0000.2 is set here but its row in the message table has no alarm number"
        )
    );
    assert!(f[1].3.starts_with("A0000.3: alarm 1001 has a message"));
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

/// The codes this corpus reaches (the Chinese-message corpus counts them).
pub(super) const CNC_CODES: &[Code] = &[
    Code::W012StrobeNoFinish,
    Code::W013FinishWriters,
    Code::W014MCodeTable,
    Code::W015CncSignalUnwritten,
    Code::W016RequestUnwritten,
    Code::W017AlarmNoMessage,
    Code::W018MessageNeverSet,
];

#[test]
fn every_cnc_warning_says_in_chinese_what_it_says_in_english() {
    let mut project = m_table(&[3, 5]);
    project.messages = messages(&[(1, 1000), (3, 1001)]).messages;
    let text = "\
LEVEL1
NETWORK
LD   X0000.0
OUT  G0008.7
LEVEL2
NETWORK
LD   F0007.3
DECB 4 F0010 0 R0200
NETWORK
LD   R0200.4
OUT  Y0000.0
NETWORK
LD   F0004.3
SET  G0004.3
NETWORK
LD   X0007.1
OUT  A0000.2
END
";
    let mut sink = Sink::default();
    let program = il::parse(text, &mut sink);
    let compiled = compile_program(program, &project, sink);
    let mut reached = std::collections::BTreeSet::new();
    for d in &compiled.diagnostics {
        super::bilingual::assert_bilingual(d.message(), d.message_zh());
        reached.insert(d.code);
    }
    for code in CNC_CODES {
        assert!(reached.contains(code), "{code:?} not reached: {compiled:?}");
    }
}
