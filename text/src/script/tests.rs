use super::*;
use crate::bilingual::assert_bilingual;
use ladder_engine::address::{Address, AddressError, Target};
use ladder_engine::cnc::CncError;
use ladder_engine::profile::{Profile, ProfileId};
use ladder_engine::scenario::NameError;
use ladder_engine::sim::{
    DeviceQuantity, DeviceReason, Options, ScenarioReason, Script, ScriptError,
};

/// The slot of each reason; no wildcard, so a new variant does not compile here until it
/// has one, and the test fails until it has an example.
fn slot(r: &ScriptReason) -> usize {
    use DeviceReason as D;
    use ScenarioReason as S;
    use ScriptReason as R;
    match r {
        R::Quote(QuoteError::Unclosed) => 0,
        R::Quote(QuoteError::NoSpaceAfter) => 1,
        R::Quote(QuoteError::InsideWord) => 2,
        R::Usage { .. } => 3,
        R::UnknownCommand { .. } => 4,
        R::ByteCount { .. } => 5,
        R::NoValue { .. } => 6,
        R::BitWithByteCount { .. } => 7,
        R::Address(_) => 8,
        R::CncValueNeedsCnc { .. } => 9,
        R::CncLineNeedsCnc => 10,
        R::Cnc(_) => 11,
        R::WritesMemory { .. } => 12,
        R::NotInteger { .. } => 13,
        R::NotBit { .. } => 14,
        R::DoesNotFit { .. } => 15,
        R::NotDuration { .. } => 16,
        R::TooLong { .. } => 17,
        R::NotNumber { .. } => 18,
        R::NotFourBytes { .. } => 19,
        R::NotScanCount { .. } => 20,
        R::TooManyScans { .. } => 21,
        R::Division { .. } => 22,
        R::Device(D::NoModel { .. }) => 23,
        R::Device(D::NoDevice { .. }) => 24,
        R::Device(D::NotBinary { .. }) => 25,
        R::Device(D::NotQuantity { what, .. }) => match what {
            DeviceQuantity::Factor => 26,
            DeviceQuantity::Operations => 27,
            DeviceQuantity::PeriodMs => 28,
        },
        R::Device(D::SlowFactor { .. }) => 29,
        R::Device(D::FlickerPeriod { .. }) => 30,
        R::Device(D::NotInput { .. }) => 31,
        R::Device(D::Driven { .. }) => 32,
        R::Scenario(S::NotScenarioLine { .. }) => 33,
        R::Scenario(S::FaultsOnly) => 34,
        R::Scenario(S::NoPanelItem { .. }) => 35,
        R::Scenario(S::KeyState { .. }) => 36,
        R::Scenario(S::NoKnobPosition { .. }) => 37,
        R::Scenario(S::Lamp { .. }) => 38,
        R::Scenario(S::NoProject) => 39,
        R::Scenario(S::NoScenario { .. }) => 40,
        R::Scenario(S::Broken { .. }) => 41,
    }
}
const VARIANTS: usize = 42;

fn address(text: &str) -> Address {
    Address::parse(text).unwrap()
}

/// One example or more of every reason.
fn examples() -> Vec<ScriptReason> {
    let mut examples = script_examples();
    examples.extend(device_and_scenario_examples());
    let mut seen = [false; VARIANTS];
    examples.iter().for_each(|r| seen[slot(r)] = true);
    assert_eq!(seen, [true; VARIANTS], "a reason without an example");
    examples
}

/// The reasons of the script's own lines.
fn script_examples() -> Vec<ScriptReason> {
    use ScriptReason as R;
    let text = |t: &str| t.to_string();
    vec![
        R::Quote(QuoteError::Unclosed),
        R::Quote(QuoteError::NoSpaceAfter),
        R::Quote(QuoteError::InsideWord),
        R::Usage {
            usage: "set ADDR[:N] VALUE",
        },
        R::UnknownCommand {
            verb: text("sett"),
            near: Some("set"),
        },
        R::UnknownCommand {
            verb: text("frob"),
            near: None,
        },
        R::ByteCount { text: text("R1:3") },
        R::NoValue {
            text: text("L0001"),
        },
        R::BitWithByteCount {
            text: text("X1.0:2"),
        },
        R::Address(AddressError::Syntax(text("Q"))),
        R::CncValueNeedsCnc {
            text: text("cnc.mode"),
        },
        R::CncLineNeedsCnc,
        R::Cnc(CncError::NoSubcommand),
        R::WritesMemory {
            verb: "set",
            text: text("cnc.mode"),
        },
        R::NotInteger { text: text("x") },
        R::NotBit {
            target: Target::whole(address("X0001.0")),
            value: 2,
        },
        R::DoesNotFit {
            value: 256,
            target: Target::whole(address("R0000")),
            lo: -128,
            hi: 255,
        },
        R::NotDuration { text: text("2x") },
        R::TooLong {
            text: text("10000000000000"),
            seconds: 800_000,
            ticks: 100_000_000,
        },
        R::NotNumber { text: text("one") },
        R::NotFourBytes {
            verb: "setf",
            address: address("R0001"),
        },
        R::NotScanCount { text: text("-1") },
        R::TooManyScans {
            text: text("100000001"),
            most: 100_000_000,
        },
        R::Division { text: text("0") },
    ]
}

/// The reasons of `device` and `scenario` lines.
fn device_and_scenario_examples() -> Vec<ScriptReason> {
    use DeviceReason as D;
    use ScenarioReason as S;
    use ScriptReason as R;
    let text = |t: &str| t.to_string();
    let mut examples = vec![
        D::NoModel {
            what: text("device"),
        }
        .into(),
        D::NoDevice {
            name: text("tailstock"),
            devices: vec![text("chuck"), text("turret")],
        }
        .into(),
        D::NotBinary { text: text("2") }.into(),
        D::SlowFactor { text: text("5000") }.into(),
        D::FlickerPeriod {
            text: text("8"),
            min_ms: 16,
        }
        .into(),
        D::NotInput {
            device: text("chuck"),
            address: address("X0009.1"),
            inputs: vec![address("X0002.1"), address("X0002.2")],
        }
        .into(),
        D::Driven {
            verb: "set",
            target: Target::whole(address("X0002.1")),
            input: address("X0002.1"),
            device: text("chuck"),
        }
        .into(),
        S::NotScenarioLine { verb: text("frce") }.into(),
        S::FaultsOnly.into(),
        S::NoPanelItem {
            label: text("Feed"),
        }
        .into(),
        S::KeyState {
            label: text("Cycle start"),
            value: text("2"),
        }
        .into(),
        S::NoKnobPosition {
            label: text("Feed override"),
            value: text("300%"),
            positions: vec![text("0%"), text("50%"), text("100%")],
        }
        .into(),
        S::Lamp {
            label: text("Alarm"),
        }
        .into(),
        S::NoProject.into(),
        S::NoScenario {
            name: text("cold"),
            names: vec![],
        }
        .into(),
        S::NoScenario {
            name: text("cold"),
            names: vec![text("warm"), text("hot")],
        }
        .into(),
        S::Broken {
            scenario: text("warm"),
            error: Box::new(ScriptError {
                line: 2,
                reason: R::NotInteger { text: text("x") },
            }),
        }
        .into(),
    ];
    for what in [
        DeviceQuantity::Factor,
        DeviceQuantity::Operations,
        DeviceQuantity::PeriodMs,
    ] {
        examples.push(
            D::NotQuantity {
                text: text("fast"),
                what,
            }
            .into(),
        );
    }
    examples
}

#[test]
fn every_reason_says_in_chinese_what_it_says_in_english() {
    for r in examples() {
        assert_bilingual(&reason(&r, Lang::En), &reason(&r, Lang::Zh));
    }
    for e in [
        NameError::Empty,
        NameError::Malformed {
            name: "two words".into(),
        },
        NameError::Taken {
            name: "good".into(),
        },
    ] {
        match &e {
            NameError::Empty | NameError::Malformed { .. } | NameError::Taken { .. } => {}
        }
        assert_bilingual(&name_error(&e, Lang::En), &name_error(&e, Lang::Zh));
    }
}

#[test]
fn reasons_keep_their_words() {
    let r = ScriptReason::UnknownCommand {
        verb: "sett".into(),
        near: Some("set"),
    };
    assert_eq!(
        reason(&r, Lang::En),
        "unknown command `sett`; did you mean `set`? (commands: set, setf, force, unforce, scan, run, expect, expectf, print, watch, division, power-cycle, cnc, device, scenario)"
    );
    assert_eq!(
        reason(&r, Lang::Zh),
        "未知命令 `sett`；是不是 `set`？（命令：set、setf、force、unforce、scan、run、expect、expectf、print、watch、division、power-cycle、cnc、device、scenario）"
    );
    let r = ScriptReason::DoesNotFit {
        value: 256,
        target: Target::whole(address("R0000")),
        lo: -128,
        hi: 255,
    };
    assert_eq!(
        reason(&r, Lang::En),
        "256 does not fit R0000 (1 byte: -128…255)"
    );
    assert_eq!(
        reason(&r, Lang::Zh),
        "256 超出 R0000 的范围（1 字节：-128…255）"
    );
    let r: ScriptReason = DeviceReason::NotQuantity {
        text: "fast".into(),
        what: DeviceQuantity::Factor,
    }
    .into();
    assert_eq!(reason(&r, Lang::En), "`fast` is not a factor");
    assert_eq!(reason(&r, Lang::Zh), "`fast` 不是倍数");
    let broken = ScriptError {
        line: 2,
        reason: ScenarioReason::NotScenarioLine {
            verb: "frce".into(),
        }
        .into(),
    };
    assert_eq!(
        broken_scenario("typo", &broken, Lang::En),
        "scenario `typo`, line 2: `frce` cannot be part of a scenario: its lines are `set`, `force`, `panel` and `device NAME fault …`"
    );
    assert_eq!(
        broken_scenario("typo", &broken, Lang::Zh),
        "场景 `typo` 第 2 行：`frce` 不能用在场景中：场景的行只能是 `set`、`force`、`panel` 和 `device NAME fault …`"
    );
    let taken = NameError::Taken {
        name: "good".into(),
    };
    assert_eq!(
        name_error(&taken, Lang::En),
        "scenario name `good` is already used; give each scenario its own"
    );
    assert_eq!(
        name_error(&taken, Lang::Zh),
        "场景名称 `good` 已被使用；请为每个场景取不同的名称"
    );
}

#[test]
fn program_file_errors_name_the_path_in_both_languages() {
    let path = std::path::Path::new("part.nc");
    let big = ProgramFileError::TooLarge(20_000_000);
    assert_eq!(
        program_file_error(&big, path, Lang::En),
        "the NC program part.nc is 20000000 bytes; programs over 16 MiB (16777216 bytes) are refused: split it into programs called with M98"
    );
    assert_bilingual(
        &program_file_error(&big, path, Lang::En),
        &program_file_error(&big, path, Lang::Zh),
    );
    let io = ProgramFileError::Io("denied".into());
    assert_eq!(
        program_file_error(&io, path, Lang::En),
        "cannot read the NC program part.nc: denied"
    );
    assert_eq!(
        program_file_error(&io, path, Lang::Zh),
        "无法读取 NC 程序 part.nc：denied"
    );
}

fn parse(text: &str) -> Result<Script, ScriptError> {
    Script::parse(text, Profile::get(ProfileId::Gsk988ta))
}

fn parse_cnc(text: &str) -> Result<Script, ScriptError> {
    Script::parse_with(
        text,
        Profile::get(ProfileId::Gsk988ta),
        &Options {
            machine: None,
            project: None,
            cnc: true,
            read_file: &|p| Err(format!("cannot read {p}")),
        },
    )
}

#[test]
fn script_errors_say_in_chinese_what_they_say_in_english() {
    let plc = [
        "set R0000 256",
        "sett X1.0 1",
        "frob",
        "set R1000 1",
        "set X1.0 2",
        "set X1.0:2 1",
        "set L0001 1",
        "set R0001:3 1",
        "set R0999:4 1",
        "set R1 x",
        "set Q1 1",
        "set R1.9 1",
        "set D1.3 1",
        "run 2x",
        "scan many",
        "division 0",
        "setf R1 1.5",
        "expectf D1 one",
        "set R1",
        "power-cycle now",
        "cnc reset",
        "expect cnc.mode MEM",
        "print \"R1",
        "print \"R1\"x",
        "print R\"1\"",
        "set cnc.mode 1",
        "scan 100000001",
        "run 10000000000000",
    ];
    for text in plc {
        let e = parse(text).expect_err(text);
        assert_bilingual(&script_error(&e, Lang::En), &script_error(&e, Lang::Zh));
    }
    let e = parse("scan\n\nset R0000 256\n").unwrap_err();
    assert!(script_error(&e, Lang::En).contains("256 does not fit R0000"));
    assert!(script_error(&parse("set R1000 1").unwrap_err(), Lang::En).contains("R0–R999"));
    // The CNC side says the same in Chinese, in the manual's words: no English behind a
    // Chinese prefix.
    let e = parse_cnc("scan\ncnc program-file other.nc").unwrap_err();
    let zh = script_error(&e, Lang::Zh);
    assert!(
        zh.contains("无法读取程序文件") && zh.contains("other.nc"),
        "{zh}"
    );
    let cnc = [
        ("cnc", "子命令"),
        ("cnc spin", "未知的 CNC 命令"),
        ("cnc offset 1 X", "用法"),
        ("cnc param 1420 3000", "轴号"),
        ("cnc param 8130 9", "参数 8130"),
        ("cnc param 1234 1", "没有参数"),
        ("cnc offset 100 X 1", "刀补号"),
        ("cnc offset 1 TIP 10", "刀尖方向"),
        ("cnc workpiece G60 X 1", "工件坐标系"),
        ("cnc macro 1000 1", "宏变量"),
        ("cnc alarm 950", "报警"),
        ("cnc handwheel 20000", "手轮"),
        ("cnc clock 2026-02-30T00:00:00", "日期时间"),
        ("cnc position Q 1", "轴"),
        ("expect cnc.speed 1", "未知的 CNC 值"),
        ("expect cnc.run GO", "运行状态"),
        ("expect cnc.mode AUTO", "方式"),
        ("print cnc.macro.99999", "宏变量"),
    ];
    for (text, word) in cnc {
        let e = parse_cnc(text).expect_err(text);
        let (en, zh) = (script_error(&e, Lang::En), script_error(&e, Lang::Zh));
        assert_bilingual(&en, &zh);
        assert!(zh.contains(word), "{text}: {zh}");
    }
}
