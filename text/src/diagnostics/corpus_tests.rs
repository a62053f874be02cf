//! Every diagnostic says in Chinese what it says in English: a corpus of broken inputs, one
//! or more per code, compiled, and each message pair compared for its specifics. The CNC
//! interface's and the scenarios' codes are reached by their own examples (`signals.rs`,
//! `scenario.rs`).

use crate::Lang;
use crate::bilingual::assert_bilingual;
use ladder_engine::address::Address;
use ladder_engine::catalog::Op;
use ladder_engine::compiler::{Code, Diagnostic, compile};
use ladder_engine::il;
use ladder_engine::model::{
    AddressRow, Cell, Comments, DataRow, Ladder, MCodeRow, Network, NetworkId, Operand, Project,
    RealRow, Row, Symbol, SymbolTable,
};
use ladder_engine::profile::ProfileId;
use std::collections::BTreeSet;

/// Checks every diagnostic and returns their codes.
fn check_all(diagnostics: &[Diagnostic]) -> BTreeSet<Code> {
    for d in diagnostics {
        assert_bilingual(&super::message(d, Lang::En), &super::message(d, Lang::Zh));
    }
    diagnostics.iter().map(|d| d.code).collect()
}

/// The IL corpus of `check` (tests/il/invalid), and lines that reach the messages it leaves
/// out.
const IL: &[&str] = &[
    include_str!("../../../tests/il/invalid/areas.il"),
    include_str!("../../../tests/il/invalid/operands.il"),
    include_str!("../../../tests/il/invalid/program.il"),
    include_str!("../../../tests/il/invalid/stack-depth.il"),
    include_str!("../../../tests/il/invalid/stacks.il"),
    include_str!("../../../tests/il/invalid/steps.il"),
    include_str!("../../../tests/il/invalid/syntax.il"),
    "LEVEL1 X\nNETWORK title\nLD X0001.0\nOUT Y0001.0\n\"quoted\"\nLD \"X0001.0\"\nLD XYZZY1\nLD R1.0.0\n",
    "LEVEL1\nNETWORK\nAND X0001.0\nOUT R0001.0\nNETWORK\nORI X0001.0\nOUT R0001.1\n",
    "LEVEL1\nNETWORK\nLD X0001.0\nMRD\nOUT R0001.0\nNETWORK\nMPS\nOUT R0001.1\n",
    "LEVEL1\nNETWORK\nLD X0001.0\nLD X0001.1\nMPS\nOUT R0001.0\n",
    "LEVEL1\nNETWORK\nLD X0001.0\nLD X0001.1\nORB\nLD X0001.2\n",
    "LEVEL1\nNETWORK\nLD X0001.0\nMPS\nLD X0001.1\nORB\nOUT R0001.0\nMPP\nOUT R0001.1\n",
    "LEVEL1\nNETWORK\nLD X0001.0\nOUT R0001.0\nLD X0001.1\nOUT R0001.1\nLD X0001.2\nANB\nOUT R0001.2\n",
    "LEVEL1\nNETWORK\nLD X0001.0\nMOVN 0 R0001 R0002\nLD X0001.0\nCTRC 0001 R0001.1 DT0001 10 R0002.1\nLD X0001.0\nPARI 0002 R0001 R0002.2\n",
    "LEVEL1\nNETWORK\nLD X0001.0\nOUT R0001.0.1\nLD X0001.0\nMOVN 1 R0001.1 R0002\nLD X0001.0\nMOVN 1 R0001 R0002 R0003\n",
    "LEVEL1\nNETWORK\nLD X0001.0\nCODB 1 2 R0001 R0002 1\nLD X0001.0\nTMRB T0001 100 R0001.1 R0001.2\n",
    "LEVEL1\nNETWORK\nLD X0001.0\nXMOV 0 0011 4 D0001 D0002 D0003 R0001.1 R0001.2\nLD X0001.0\nMOVN 1 1.5 R0001\n",
    "LEVEL1\nNETWORK\nLD X0001.0\nMOVN 1 99999999999 R0001\nLD X0001.0\nSUB\nEND\n",
    "LEVEL1\nNETWORK\nLD X0001.0\nFROBNICATE X0001.0\nLD D0001.1\nLD Q0001.0\nLD R\n",
    "LEVEL1\nNETWORK\nLD X0001.0\nCTRC 0100 R0001.1 C0001 10 R0002.1\nLD X0001.0\nPARI 0010 X0001.1 R0001 R0002.2\nLD X0001.0\nCODB 1 R0001 R0002\n",
];

/// The codes the IL corpus reaches.
const IL_CODES: &[Code] = &[
    Code::L010UnknownInstruction,
    Code::L011OperandCount,
    Code::L012Syntax,
    Code::L013BlockStack,
    Code::L014BranchStack,
    Code::L015LoadAfterOutput,
    Code::L016NoOutput,
    Code::L017NotDrawable,
    Code::L018StackDepth,
    Code::L020UndefinedSymbol,
    Code::L021OperandKind,
    Code::L022Area,
    Code::L023AddressRange,
    Code::L024ConstRange,
    Code::L025ReadOnly,
    Code::L030LabelTwice,
    Code::L031UndefinedLabel,
    Code::L032JumpOutOfBlock,
    Code::L033UndefinedSub,
    Code::L034Recursion,
    Code::L035Level1Steps,
    Code::L036ProgramSteps,
    Code::L038SubNumber,
    Code::W001CoilTwice,
    Code::W002TimerTwice,
    Code::W003BitsSpill,
    Code::W008OutputTwice,
];

/// The codes the drawn networks reach.
const DRAWN_CODES: &[Code] = &[
    Code::L001NotConnected,
    Code::L002OpenBranch,
    Code::L003ShortCircuit,
    Code::L004Bridge,
    Code::L005WrongColumn,
    Code::L006NoContact,
    Code::L007NotStandalone,
    Code::L020UndefinedSymbol,
    Code::W001CoilTwice,
];

/// The codes the tables reach.
const TABLE_CODES: &[Code] = &[
    Code::T001SymbolName,
    Code::T002SymbolTwice,
    Code::T003DataAddress,
    Code::T004DataValue,
    Code::T005MessageNumber,
    Code::T006TableName,
    Code::T007SymbolArea,
    Code::T008TableKey,
    Code::W004AddressTwice,
    Code::W005MessageHalf,
    Code::W006VersionLength,
    Code::W007CommentLength,
    Code::W009PresetRange,
];

#[test]
fn every_diagnostic_of_the_il_corpus_is_in_chinese_with_its_specifics() {
    let mut codes = BTreeSet::new();
    for text in IL {
        codes.extend(check_all(&il::import(text).compiled.diagnostics));
    }
    for code in IL_CODES {
        assert!(codes.contains(code), "{code:?} not reached by the corpus");
    }
}

/// A network drawn as in engine/tests/structure.rs: `X1.0` a contact, `/X1.0` a normally
/// closed one, `-` a wire, `.` empty, `(Y1.0)` a coil, `[MOVN_1_R1_R2]` a box; a line `| 1 3`
/// puts vertical links below the previous row at junctions 1 and 3.
fn drawn(id: u64, width: usize, drawing: &[&str]) -> Network {
    let op = |s: &str| Operand::parse(s).unwrap();
    let cell = |t: &str| match t {
        "." => Cell::Empty,
        "-" => Cell::Wire,
        t if t.starts_with('(') => Cell::Coil {
            negated: false,
            operand: op(&t[1..t.len() - 1]),
        },
        t if t.starts_with('[') => {
            let parts: Vec<&str> = t[1..t.len() - 1].split('_').collect();
            Cell::Box {
                op: Op::from_name(parts[0]).unwrap(),
                operands: parts[1..].iter().map(|p| op(p)).collect(),
            }
        }
        t if t.starts_with('/') => Cell::Contact {
            negated: true,
            operand: op(&t[1..]),
        },
        t => Cell::Contact {
            negated: false,
            operand: op(t),
        },
    };
    let mut rows: Vec<Row> = Vec::new();
    for line in drawing {
        if let Some(links) = line.strip_prefix('|') {
            let last = rows.last_mut().expect("a row before its links");
            for j in links.split_whitespace() {
                last.links[j.parse::<usize>().unwrap()] = true;
            }
        } else {
            rows.push(Row {
                cells: line.split_whitespace().map(cell).collect(),
                links: vec![false; width + 1],
            });
        }
    }
    let mut n = Network::new(NetworkId(id), width);
    n.rows = rows;
    n
}

#[test]
fn every_diagnostic_of_a_drawn_ladder_is_in_chinese_with_its_specifics() {
    const WIDTH: usize = 4;
    let drawings: &[&[&str]] = &[
        &[". X1.0 - - (Y1.0)"],
        &[". . . . (Y1.1)"],
        &[". . . . [MOVN_1_R1_R2]"],
        &["X1.0 - - - (Y1.2)", "| 1", ". X1.1 . . ."],
        &["X1.0 X1.1 - - (Y1.3)", "| 1 2", ". - . . ."],
        &[
            "X1.0 - - - (Y1.4)",
            "| 1",
            ". X1.1 - - (Y1.5)",
            "| 2",
            "X1.2 - . . .",
        ],
        &["X1.0 (Y1.6) - - X1.1"],
        &["- - - - (Y1.7)"],
        &["X1.0 - - - [LBL_L1]"],
        &["X1.0 - - - (START)"],
        &["X1.0 - - - (Y2.0)"],
        &["X1.1 - - - (Y2.0)"],
    ];
    let mut ladder = Ladder::new(WIDTH);
    for (i, drawing) in drawings.iter().enumerate() {
        let network = drawn(i as u64 + 1, WIDTH, drawing);
        ladder.blocks[1].networks.push(network);
    }
    let project = Project {
        ladder,
        ..Project::default()
    };
    let codes = check_all(&compile(&project).diagnostics);
    for code in DRAWN_CODES {
        assert!(codes.contains(code), "{code:?} not reached by the drawings");
    }
}

fn addr(text: &str) -> Address {
    Address::parse(text).unwrap()
}

fn comments(lang: &str, text: &str) -> Comments {
    Comments::from([(lang.to_string(), text.to_string())])
}

#[test]
fn every_diagnostic_of_the_tables_is_in_chinese_with_its_specifics() {
    let mut p = Project::default();
    let symbol = |a: &str, name: &str| Symbol {
        name: name.into(),
        address: addr(a),
        comments: Comments::new(),
    };
    p.symbol_tables[0].rows = vec![
        symbol("P2", "TOOL"),
        symbol("L1", "LOOP"),
        symbol("R0.0", "A"),
        symbol("R0.0", "B"),
        symbol("R1.0", "1ST"),
        symbol("R2.0", "A"),
        symbol("R9999", "BIG"),
    ];
    p.symbol_tables[0].rows[2].comments = comments("zh", &"字".repeat(43));
    let name = p.symbol_tables[0].name.clone();
    p.symbol_tables.push(SymbolTable {
        name,
        rows: Vec::new(),
    });
    p.data.d.push(DataRow::new(addr("D4"), 0));
    p.data.d_float.push(RealRow::new(addr("D4"), 0.0));
    p.data.d_float.push(RealRow::new(addr("D9999"), 0.0));
    let mut capped = RealRow::new(addr("D5"), 5.0);
    capped.max = Some(1.0);
    p.data.d_float.push(capped);
    p.data.dt.push(DataRow::new(addr("DT0"), 0));
    p.data.dt[0].symbol = "A".into();
    p.data.dt[0].comments = comments("en", &"x".repeat(130));
    let mut high = DataRow::new(addr("DT4"), 70000);
    high.max = Some(60000);
    p.data.dt.push(high);
    p.data.dt.push(DataRow::new(addr("DT9999"), 0));
    p.data.dt.push(DataRow::new(addr("DT5"), 0));
    p.data.dt[3].symbol = "1ST".into();
    p.data.dc.push(DataRow::new(addr("DT6"), 0));
    // A timer reading a negative preset from the DT table.
    p.data.dt.push(DataRow::new(addr("DT7"), -5));
    p.ladder = Ladder::new(4);
    let timer = drawn(1, 4, &["X1.0 - - - [TMRB_T1_DT7_R1.0]"]);
    p.ladder.blocks[1].networks.push(timer);
    p.messages.rows[0].number = Some(999);
    p.messages.rows[1].number = Some(1001);
    p.messages.rows[1].texts = comments("zh", "报警");
    p.messages.rows[2].number = Some(1001);
    p.messages.rows[3].texts = comments("zh", "无号");
    p.diagnosis = ["P1", "X0.0", "X0.0", "R9999"]
        .iter()
        .map(|a| AddressRow {
            address: addr(a),
            comments: Comments::new(),
        })
        .collect();
    p.permissions = p.diagnosis.clone();
    p.m_codes = [3, 3, 10_000]
        .into_iter()
        .map(|code| MCodeRow {
            code,
            comments: Comments::new(),
        })
        .collect();
    p.version.designer = "d".repeat(70);
    p.version.version = "v".repeat(20);
    p.version.remarks = "r".repeat(600);
    let mut codes = check_all(&compile(&p).diagnostics);

    // A message row beyond the GSK980's A range.
    let mut small = Project {
        profile: ProfileId::Gsk980,
        ..Project::default()
    };
    let row = ladder_engine::model::MessageTable::row_of(addr("A0030.0")).unwrap();
    small.messages.rows[row].number = Some(1002);
    let beyond = compile(&small).diagnostics;
    assert!(beyond.iter().any(|d| d.code == Code::T005MessageNumber));
    codes.extend(check_all(&beyond));

    for code in TABLE_CODES {
        assert!(codes.contains(code), "{code:?} not reached by the tables");
    }
}

/// The codes of the CNC interface checks, reached by the examples of `signals.rs`.
const CNC_CODES: &[Code] = &[
    Code::W012StrobeNoFinish,
    Code::W013FinishWriters,
    Code::W014MCodeTable,
    Code::W015CncSignalUnwritten,
    Code::W016RequestUnwritten,
    Code::W017AlarmNoMessage,
    Code::W018MessageNeverSet,
];

/// The codes the machine model reaches.
const MACHINE_CODES: &[Code] = &[
    Code::M001DeviceName,
    Code::M002DeviceAddress,
    Code::M003DeviceParameter,
    Code::M004DeviceCondition,
    Code::M005InputTwice,
    Code::W010DeviceReadsNothing,
    Code::W011PanelDrivesDeviceInput,
];

#[test]
fn every_machine_model_diagnostic_is_in_chinese_with_its_specifics() {
    use ladder_engine::devices::model::{Actuator, Logic};
    use ladder_engine::devices::{Device, DeviceKind};
    let follower = |name: &str, input: &str, when: &str| Device {
        name: name.into(),
        kind: DeviceKind::Follower(Logic {
            input: addr(input),
            when: when.into(),
            on_ms: 0,
            off_ms: 0,
        }),
    };
    let mut p = Project::default();
    p.machine.devices = vec![
        follower("R10", "X0001.0", "1"),
        follower("ok", "X0001.1", "Y0000.1 &"),
        follower("ok", "X0001.2", "1"),
        follower("bad", "Y0001.0", "1"),
        Device {
            name: "chuck".into(),
            kind: DeviceKind::Actuator(Actuator {
                advance: addr("Y0000.6"),
                retract: None,
                travel_ms: 0,
                at_advanced: Some(addr("X0001.6")),
                at_retracted: None,
                moving: None,
                start_advanced: false,
            }),
        },
        follower("twice", "X0001.6", "Y0000.2"),
    ];
    p.panel.items.push(ladder_engine::model::PanelItem::new(
        "开关",
        "switch",
        ladder_engine::model::PanelKind::Switch {
            input: addr("X0001.2"),
        },
        0,
        0,
    ));
    let codes = check_all(&compile(&p).diagnostics);
    for code in MACHINE_CODES {
        assert!(
            codes.contains(code),
            "{code:?} not reached by the machine model"
        );
    }
}

#[test]
fn the_corpus_reaches_every_code() {
    let reached: BTreeSet<Code> = [
        IL_CODES,
        DRAWN_CODES,
        TABLE_CODES,
        MACHINE_CODES,
        CNC_CODES,
        &[Code::W019ScenarioBroken],
    ]
    .concat()
    .into_iter()
    .collect();
    let all: BTreeSet<Code> = Code::ALL.iter().copied().collect();
    assert_eq!(reached, all);
}

#[test]
fn the_check_itself_catches_a_lost_specific() {
    let lost = std::panic::catch_unwind(|| {
        assert_bilingual("label L0001 at line 12", "标号 L0001 在第 13 行")
    });
    assert!(lost.is_err(), "a changed number is found");
    let lost = std::panic::catch_unwind(|| {
        assert_bilingual("undefined symbol `START`", "符号 START 未定义")
    });
    assert!(lost.is_err(), "an unquoted name is found");
    let lost = std::panic::catch_unwind(|| assert_bilingual("no output", "no output"));
    assert!(lost.is_err(), "English is found");
    let lost = std::panic::catch_unwind(|| assert_bilingual("a, b", "甲, 乙"));
    assert!(lost.is_err(), "an ASCII comma is found");
    assert_bilingual("LEVEL1 network 2", "一级程序 网络 2");
}
