//! Every variant of every quoted engine error, in both languages: the Chinese is Chinese and
//! carries the numbers and quoted names of the English, and the English is the error's own
//! `Display` (the device fields' refusals have no `Display`; their English is worded here).
//!
//! Each `slot` matches every variant without a wildcard, so a new variant does not compile
//! until it is named there, and the test then fails until it has an example.

use super::*;
use crate::bilingual::assert_bilingual;
use ladder_engine::address::{Address, Area, AreaSet};
use ladder_engine::catalog::{Op, check_digit_group};
use ladder_engine::devices::expr::{self, Names};
use ladder_engine::devices::{DeviceKind, Limit};
use ladder_engine::model::Operand;
use ladder_engine::model::sheets::{self, Sheet};
use ladder_engine::profile::{Profile, ProfileId};
use std::fmt::Debug;

fn profile() -> &'static Profile {
    Profile::get(ProfileId::Gsk988ta)
}

fn addr(text: &str) -> Address {
    Address::parse(text).expect("a valid address")
}

/// The refusal of `text` as an address of the default controller.
fn addr_err(text: &str) -> AddressError {
    Address::parse_in(text, profile()).expect_err("an address the controller refuses")
}

/// The refusal of a condition, with an actuator `chuck` and a turret `turret` to name.
fn expr_err(text: &str, states: bool) -> ExprError {
    let kinds = DeviceKind::templates();
    let state_of = |name: &str| {
        let kind = kinds.iter().find(|k| k.name() == name).expect("a template");
        kind.states()
    };
    let devices = [
        ("chuck", state_of("actuator")),
        ("turret", state_of("turret")),
    ];
    let names = Names {
        devices: &devices,
        states,
    };
    expr::parse(text, profile(), &names).expect_err("a condition that does not read")
}

/// The refusal of `text` typed into field `field` of the template of kind `kind`.
fn field_err(kind: &str, field: &str, text: &str) -> FieldError {
    let mut kinds = DeviceKind::templates();
    let device = kinds
        .iter_mut()
        .find(|k| k.name() == kind)
        .expect("a template");
    ladder_engine::devices::fields::set(device, field, text, profile())
        .expect_err("a text the field refuses")
}

/// Checks every example in both languages and that each slot has one.
fn walk<E: Debug>(
    examples: &[E],
    variants: usize,
    slot: fn(&E) -> usize,
    text: fn(&E, Lang) -> String,
) {
    let mut seen = vec![false; variants];
    for e in examples {
        seen[slot(e)] = true;
        assert_bilingual(&text(e, Lang::En), &text(e, Lang::Zh));
    }
    let missing: Vec<usize> = (0..variants).filter(|&i| !seen[i]).collect();
    assert!(
        missing.is_empty(),
        "variants without an example: {missing:?} of {examples:?}"
    );
}

fn address_slot(e: &AddressError) -> usize {
    match e {
        AddressError::Syntax(_) => 0,
        AddressError::UnknownArea(..) => 1,
        AddressError::Bit(_) => 2,
        AddressError::NoBits(..) => 3,
        AddressError::Range { .. } => 4,
    }
}

fn address_examples() -> Vec<AddressError> {
    ["R", "Q0010.1", "R0010.8", "D0004.1", "R9999.1", "X0200.0"]
        .into_iter()
        .map(addr_err)
        .collect()
}

#[test]
fn every_address_error_reads_in_both_languages() {
    let examples = address_examples();
    walk(&examples, 5, address_slot, address_error);
    for e in &examples {
        assert_eq!(address_error(e, Lang::En), e.to_string());
    }
    let e = addr_err("R0010.8");
    assert_eq!(
        address_error(&e, Lang::En),
        "`R0010.8`: the bit must be 0–7"
    );
    assert_eq!(address_error(&e, Lang::Zh), "`R0010.8`：位号应为 0–7");
}

fn operand_error_slot(e: &OperandError) -> usize {
    match e {
        OperandError::Empty => 0,
        OperandError::Number(_) => 1,
        OperandError::Address(_) => 2,
        OperandError::Unrecognised(_) => 3,
    }
}

#[test]
fn every_operand_error_reads_in_both_languages() {
    let examples: Vec<OperandError> = ["", "12x", "0x1G", "R0010.9", "D0004.1", "a-b"]
        .into_iter()
        .map(|t| Operand::parse(t).expect_err("an operand that does not read"))
        .collect();
    walk(&examples, 4, operand_error_slot, operand_error);
    for e in &examples {
        assert_eq!(operand_error(e, Lang::En), e.to_string());
    }
    let e = Operand::parse("12x").expect_err("not a number");
    assert_eq!(
        operand_error(&e, Lang::En),
        "`12x` is not a number (write 12, -5, 0x1F or 1.5)"
    );
    assert_eq!(
        operand_error(&e, Lang::Zh),
        "`12x` 不是数字（应写成 12、-5、0x1F 或 1.5 等形式）"
    );
}

fn digit_group_slot(e: &DigitGroupError) -> usize {
    match e {
        DigitGroupError::Ctrc { .. } => 0,
        DigitGroupError::Pari { .. } => 1,
        DigitGroupError::Xmov { .. } => 2,
    }
}

fn digit_group_examples() -> Vec<DigitGroupError> {
    [
        (Op::Ctrc, 111),
        (Op::Pari, 10),
        (Op::Xmov, 3),
        (Op::Xmov, 1002),
    ]
    .into_iter()
    .map(|(op, v)| check_digit_group(op, v).expect_err("digits the rule refuses"))
    .collect()
}

#[test]
fn every_digit_group_error_reads_in_both_languages() {
    let examples = digit_group_examples();
    walk(&examples, 3, digit_group_slot, digit_group_error);
    for e in &examples {
        assert_eq!(digit_group_error(e, Lang::En), e.to_string());
    }
    let e = check_digit_group(Op::Pari, 10).expect_err("not an OE");
    assert_eq!(
        digit_group_error(&e, Lang::En),
        "PARI's OE is 0000 (even) or 0001 (odd)"
    );
    assert_eq!(
        digit_group_error(&e, Lang::Zh),
        "PARI 的 OE 为 0000（偶校验）或 0001（奇校验）"
    );
}

fn refusal_slot(e: &OperandRefusal) -> usize {
    match e {
        OperandRefusal::TooMany => 0,
        OperandRefusal::Kind { .. } => 1,
        OperandRefusal::WantsBit(_) => 2,
        OperandRefusal::WantsByte(_) => 3,
        OperandRefusal::Size(_) => 4,
        OperandRefusal::Digits { .. } => 5,
        OperandRefusal::DigitGroup(_) => 6,
        OperandRefusal::ConstRange { .. } => 7,
        OperandRefusal::ConstTooBig(_) => 8,
        OperandRefusal::ReadOnly { .. } => 9,
        OperandRefusal::Area { .. } => 10,
        OperandRefusal::Range(_) => 11,
    }
}

/// Every kind an operand may expect, so that each of their Chinese words is checked.
const KINDS: [OperandKind; 13] = [
    OperandKind::Size,
    OperandKind::Const,
    OperandKind::Digits { max_digit: 1 },
    OperandKind::Digits { max_digit: 9 },
    OperandKind::Bit,
    OperandKind::Byte,
    OperandKind::ConstOrByte,
    OperandKind::RealOrD,
    OperandKind::BitOrByte,
    OperandKind::Label,
    OperandKind::Subprogram,
    OperandKind::Timer,
    OperandKind::Counter,
];

fn refusal_examples() -> Vec<OperandRefusal> {
    use OperandRefusal as R;
    let writable = AreaSet::of(&[Area::Y, Area::G, Area::R, Area::K, Area::D]);
    let mut list = vec![
        R::TooMany,
        R::WantsBit(addr("R0010")),
        R::WantsByte(addr("R0010.1")),
        R::Size(3),
        R::Digits {
            value: 1021,
            binary: true,
        },
        R::Digits {
            value: 12345,
            binary: false,
        },
        R::ConstRange {
            value: 40000,
            min: 0,
            max: 32767,
        },
        R::ConstRange {
            value: -1,
            min: 1,
            max: 9999,
        },
        R::ConstTooBig(3_000_000_000),
        R::ReadOnly {
            address: addr("X0008.2"),
            allowed: writable,
        },
        R::Area {
            address: addr("T0002"),
            allowed: writable,
        },
        R::Range(addr_err("R9999")),
    ];
    list.extend(digit_group_examples().into_iter().map(R::DigitGroup));
    let found = [
        Operand::parse("1.5"),
        Operand::parse("R0010.1"),
        Operand::parse("12"),
    ];
    for (i, expected) in KINDS.into_iter().enumerate() {
        let found = found[i % found.len()].clone().expect("an operand");
        list.push(R::Kind { expected, found });
    }
    list
}

#[test]
fn every_operand_refusal_reads_in_both_languages() {
    let examples = refusal_examples();
    walk(&examples, 12, refusal_slot, operand_refusal);
    for e in &examples {
        assert_eq!(operand_refusal(e, Lang::En), e.to_string());
    }
    let e = OperandRefusal::WantsBit(addr("R0010"));
    assert_eq!(
        operand_refusal(&e, Lang::En),
        "expects a bit address such as R0010.0, found `R0010`"
    );
    assert_eq!(
        operand_refusal(&e, Lang::Zh),
        "应为位地址，如 R0010.0，实为 `R0010`"
    );
}

fn taken_slot(t: &Taken) -> usize {
    match t {
        Taken::Symbols { .. } => 0,
        Taken::Data { .. } => 1,
        Taken::Row(_) => 2,
        Taken::Block(_) => 3,
    }
}

fn taken_examples() -> Vec<Taken> {
    vec![
        Taken::Symbols {
            table: "MAIN".into(),
            row: 2,
        },
        Taken::Data {
            sheet: Sheet::DFloat,
            row: 0,
        },
        Taken::Data {
            sheet: Sheet::Dt,
            row: 11,
        },
        Taken::Row(6),
        Taken::Block(addr("P0003")),
    ]
}

#[test]
fn every_taken_reads_in_both_languages() {
    let examples = taken_examples();
    walk(&examples, 4, taken_slot, taken);
    for t in &examples {
        assert_eq!(taken(t, Lang::En), t.to_string());
    }
    let t = &examples[0];
    assert_eq!(taken(t, Lang::En), "MAIN #3");
    assert_eq!(taken(t, Lang::Zh), "MAIN 第 3 行");
}

fn table_slot(e: &TableError) -> usize {
    match e {
        TableError::AddressEmpty => 0,
        TableError::Address(_) => 1,
        TableError::AreaNotHere { .. } => 2,
        TableError::AddressTwice { .. } => 3,
        TableError::SymbolName { .. } => 4,
        TableError::SymbolTwice { .. } => 5,
        TableError::SymbolElsewhere { .. } => 6,
        TableError::CommentTooLong { .. } => 7,
        TableError::NotInteger { .. } => 8,
        TableError::NotReal { .. } => 9,
        TableError::AlarmRange { .. } => 10,
        TableError::AlarmTwice { .. } => 11,
        TableError::MCodeRange { .. } => 12,
        TableError::MCodeTwice { .. } => 13,
        TableError::NoFreeKey { .. } => 14,
        TableError::PasswordWrong => 15,
        TableError::PasswordEmpty => 16,
        TableError::PasswordMismatch => 17,
    }
}

fn table_examples() -> Vec<TableError> {
    use TableError as T;
    let refused = |r: Result<(), TableError>| r.expect_err("a refused cell");
    let mut list = vec![
        T::AddressEmpty,
        T::Address(addr_err("Q0001.0")),
        refused(sheets::check_symbol_area(addr("L0001"))),
        refused(sheets::check_value_area(addr("P0003"))),
        refused(sheets::check_symbol_form("1START")),
        refused(sheets::check_symbol_form("X0001.0")),
        T::SymbolElsewhere {
            name: "START".into(),
            address: addr("R0010.1"),
        },
        refused(sheets::check_comment(&"主轴".repeat(22))),
        sheets::parse_int("12a").expect_err("not an integer"),
        sheets::parse_real("1,5").expect_err("not a number"),
        refused(sheets::check_alarm_number(999)),
        T::AlarmTwice {
            number: 1001,
            by: addr("A0000.1"),
        },
        refused(sheets::check_m_code(10000)),
        T::MCodeTwice { code: 5, row: 2 },
        T::NoFreeKey { sheet: Sheet::D },
        T::PasswordWrong,
        T::PasswordEmpty,
        T::PasswordMismatch,
    ];
    for at in taken_examples() {
        list.push(T::AddressTwice {
            address: addr("R0010.1"),
            at: at.clone(),
        });
        list.push(T::SymbolTwice {
            name: "START".into(),
            at,
        });
    }
    list
}

#[test]
fn every_table_error_reads_in_both_languages() {
    let examples = table_examples();
    walk(&examples, 18, table_slot, table_error);
    for e in &examples {
        assert_eq!(table_error(e, Lang::En), e.to_string());
    }
    let e = TableError::MCodeTwice { code: 5, row: 2 };
    assert_eq!(
        table_error(&e, Lang::En),
        "M05: this M code is already listed (#3)"
    );
    assert_eq!(table_error(&e, Lang::Zh), "M05：该 M 代码已列出（第 3 行）");
}

fn model_slot(e: &ModelError) -> usize {
    match e {
        ModelError::Name(_) => 0,
        ModelError::NameTwice { .. } => 1,
        ModelError::Address { .. } => 2,
        ModelError::NotInput { .. } => 3,
        ModelError::NotBit { .. } => 4,
        ModelError::Parameter { .. } => 5,
        ModelError::Expression { .. } => 6,
        ModelError::Start { .. } => 7,
        ModelError::TwoWriters { .. } => 8,
    }
}

/// The model errors, with a parameter error for every kind of limit.
fn model_examples() -> Vec<ModelError> {
    use ModelError as M;
    let device = || "chuck".to_string();
    vec![
        M::Name("1x".into()),
        M::NameTwice {
            name: device(),
            first: 2,
        },
        M::Address {
            device: device(),
            field: "at_advanced",
            error: addr_err("X0200.0"),
        },
        M::NotInput {
            device: device(),
            field: "at_advanced",
            address: addr("Y0001.0"),
        },
        M::NotBit {
            device: device(),
            field: "at_advanced",
            address: addr("X0001"),
        },
        M::Parameter {
            device: device(),
            field: "travel_ms",
            limit: Limit::Range(1, 600_000),
        },
        M::Parameter {
            device: "turret".into(),
            field: "stations",
            limit: Limit::Range(2, 32),
        },
        M::Expression {
            device: "door".into(),
            field: "when",
            error: expr_err("Y0000.6 & chuck.open", true),
        },
        M::Start { axis: 5 },
        M::TwoWriters {
            device: "door".into(),
            address: addr("X0001.6"),
            other: device(),
        },
    ]
}

#[test]
fn every_model_error_reads_in_both_languages() {
    let examples = model_examples();
    walk(&examples, 9, model_slot, model_error);
    for e in &examples {
        assert_eq!(model_error(e, Lang::En), e.to_string());
    }
    // Every kind of limit, with no wildcard: a new one does not compile until it is here.
    let limits = [
        Limit::Range(1, 600_000),
        Limit::AtLeast(1),
        Limit::Station,
        Limit::CodeBits,
        Limit::WindowTick,
        Limit::OneDirection,
        Limit::Ordered,
        Limit::PulseOn,
    ];
    for limit in limits {
        match limit {
            Limit::Range(..)
            | Limit::AtLeast(_)
            | Limit::Station
            | Limit::CodeBits
            | Limit::WindowTick
            | Limit::OneDirection
            | Limit::Ordered
            | Limit::PulseOn => {}
        }
        let e = ModelError::Parameter {
            device: "turret".into(),
            field: "window_pct",
            limit,
        };
        assert_eq!(model_error(&e, Lang::En), e.to_string());
        assert_bilingual(&model_error(&e, Lang::En), &model_error(&e, Lang::Zh));
    }
    let e = &examples[4];
    assert_eq!(
        model_error(e, Lang::En),
        "device `chuck`, at_advanced: X0001 is a byte; write a bit address such as X0001.0"
    );
    assert_eq!(
        model_error(e, Lang::Zh),
        "设备 `chuck` 的 at_advanced：X0001 是字节，应写位地址（例如 X0001.0）"
    );
}

fn expr_slot(e: &ExprError) -> usize {
    match e {
        ExprError::Unexpected { .. } => 0,
        ExprError::Unclosed => 1,
        ExprError::Address(_) => 2,
        ExprError::NotBit(_) => 3,
        ExprError::UnknownDevice(_) => 4,
        ExprError::UnknownState { .. } => 5,
        ExprError::StateInFollower(_) => 6,
        ExprError::TooDeep => 7,
    }
}

fn expr_examples() -> Vec<ExprError> {
    let deep = format!("{}X0001.0{}", "(".repeat(70), ")".repeat(70));
    let mut list: Vec<ExprError> = [
        "Y0000.6 &",
        "Y0000.6 ) X0001.6",
        "(Y0000.6 | X0001.6",
        "X0001.9",
        "X0200.0",
        "Y0000",
        "door.open",
        "chuck.open",
        deep.as_str(),
    ]
    .into_iter()
    .map(|t| expr_err(t, true))
    .collect();
    list.push(expr_err("chuck.advanced", false));
    list
}

#[test]
fn every_expr_error_reads_in_both_languages() {
    let examples = expr_examples();
    walk(&examples, 8, expr_slot, expr_error);
    // The end of the text and a word found are worded apart.
    for at_end in [true, false] {
        assert!(examples.iter().any(
            |e| matches!(e, ExprError::Unexpected { found, .. } if found.is_empty() == at_end)
        ));
    }
    for e in &examples {
        assert_eq!(expr_error(e, Lang::En), e.to_string());
    }
    let e = expr_err("chuck.open", true);
    assert_eq!(
        expr_error(&e, Lang::En),
        "device `chuck` has no state `open`; its states: advanced, retracted, moving"
    );
    assert_eq!(
        expr_error(&e, Lang::Zh),
        "设备 `chuck` 没有状态 `open`；它的状态有：advanced、retracted、moving"
    );
}

fn field_slot(e: &FieldError) -> usize {
    match e {
        FieldError::NoField(_) => 0,
        FieldError::Condition(_) => 1,
        FieldError::NotFlag(_) => 2,
        FieldError::NotLength(_) => 3,
        FieldError::NotEncoding(_) => 4,
        FieldError::NotNumber { .. } => 5,
        FieldError::Address(_) => 6,
        FieldError::Byte(_) => 7,
        FieldError::NotInput(_) => 8,
    }
}

fn field_examples() -> Vec<FieldError> {
    [
        ("actuator", "speed", "5"),
        ("follower", "when", "Y0000.6 &"),
        ("actuator", "start_advanced", "maybe"),
        ("position-switch", "from_mm", "12 mm"),
        ("turret", "code.encoding", "Hex"),
        ("actuator", "travel_ms", "0"),
        ("turret", "stations", "40"),
        ("actuator", "advance", "Y0000.9"),
        ("actuator", "advance", "Y0001"),
        ("actuator", "at_advanced", "Y0001.0"),
    ]
    .into_iter()
    .map(|(kind, field, text)| field_err(kind, field, text))
    .collect()
}

#[test]
fn every_field_error_reads_in_both_languages() {
    let examples = field_examples();
    walk(&examples, 9, field_slot, field_error);
    for e in &examples {
        match e {
            FieldError::Condition(c) => assert_eq!(field_error(e, Lang::En), c.to_string()),
            FieldError::Address(a) => assert_eq!(field_error(e, Lang::En), a.to_string()),
            _ => {}
        }
    }
    let e = field_err("actuator", "travel_ms", "0");
    assert_eq!(
        field_error(&e, Lang::En),
        "`0`: write a whole number 1…600000"
    );
    assert_eq!(field_error(&e, Lang::Zh), "`0`：请写 1…600000 的整数");
}
