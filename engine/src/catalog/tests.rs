use super::*;
use crate::address::Area;

#[test]
fn the_catalogue_has_13_basic_and_48_function_instructions() {
    let basic = CATALOG
        .iter()
        .filter(|s| s.class != InstrClass::Function)
        .count();
    let function = CATALOG
        .iter()
        .filter(|s| s.class == InstrClass::Function)
        .count();
    assert_eq!((basic, function), (13, 48));
}

#[test]
fn each_entry_sits_at_its_opcode_and_names_are_unique() {
    for (i, s) in CATALOG.iter().enumerate() {
        assert_eq!(s.op as usize, i, "{}", s.name);
        assert_eq!(Op::from_name(&s.name.to_lowercase()), Some(s.op));
        assert!(!s.help_zh.is_empty() && !s.help_en.is_empty(), "{}", s.name);
        for o in s.operands {
            assert!(
                !o.help_zh.is_empty() && !o.help_en.is_empty(),
                "{} {}",
                s.name,
                o.name
            );
            assert!(o.min <= o.max);
            if let Width::SizeOf(i) = o.width {
                assert_eq!(s.operands[i as usize].kind, OperandKind::Size, "{}", s.name);
            }
        }
    }
}

#[test]
fn step_cost_follows_the_operand_count() {
    assert_eq!(Op::Ld.spec().steps(1), 1);
    assert_eq!(Op::Tmrb.spec().steps(3), 4);
    assert_eq!(Op::Codb.spec().steps(8), 9);
}

#[test]
fn function_opcodes_are_exactly_the_function_rows() {
    for s in CATALOG {
        let function = s.op.function();
        assert_eq!(
            function.is_some(),
            s.class == InstrClass::Function,
            "{}",
            s.name
        );
        if let Some(f) = function {
            assert_eq!(f.op(), s.op);
            assert_eq!(f as u8, s.op as u8, "{}", s.name);
        }
    }
    assert_eq!(FnOp::ALL.len(), 48);
}

#[test]
fn codb_alone_has_a_table_after_its_fixed_operands() {
    for s in CATALOG {
        let Some(t) = s.table else { continue };
        assert_eq!(s.op, Op::Codb);
        assert_eq!(
            t.first,
            s.operands.len(),
            "the entries follow the fixed operands"
        );
        assert_eq!(s.operands[t.count_from].name, "SIZE2");
        assert_eq!(s.table_len(256), Some(256));
        assert_eq!(s.table_len(0), None);
        assert_eq!(s.operand(t.first + 3), Some(&CODB_TABLE_ENTRY));
    }
    assert_eq!(Op::Codb.spec().table_start(), Some(4));
    assert_eq!(Op::Movn.spec().table_len(1), None);
}

#[test]
fn timers_and_counters_name_their_number_and_preset() {
    assert_eq!(Op::Tmrb.spec().memory_operand(), Some((0, Area::T)));
    assert_eq!(Op::Tmrc.spec().memory_operand(), Some((0, Area::T)));
    assert_eq!(Op::Ctrc.spec().memory_operand(), Some((2, Area::C)));
    assert_eq!(Op::Tmrb.spec().operand_with(Role::Preset), Some(1));
    assert_eq!(Op::Ctrc.spec().operand_with(Role::Preset), Some(3));
    let numbered: Vec<&str> = CATALOG
        .iter()
        .filter(|s| s.memory_operand().is_some())
        .map(|s| s.name)
        .collect();
    assert_eq!(numbered, ["TMRB", "TMRC", "CTRC"]);
    for s in CATALOG {
        for o in s.operands {
            let number = matches!(o.kind, OperandKind::Timer | OperandKind::Counter);
            assert_eq!(
                number,
                o.role.memory_area().is_some(),
                "{} {}",
                s.name,
                o.name
            );
        }
    }
}

#[test]
fn the_outputs_written_whatever_act_are_marked_driven() {
    // What the VM writes at ACT = 0 too (docs/plc.md, "Common rules"); W008 reads the mark.
    let driven: Vec<String> = CATALOG
        .iter()
        .flat_map(|s| {
            s.operands
                .iter()
                .filter(|o| o.role == Role::Driven)
                .map(move |o| format!("{} {}", s.name, o.name))
        })
        .collect();
    assert_eq!(
        driven,
        [
            "TMRB OUT",
            "DECB OUT",
            "PARI OUT",
            "DIFU OUT",
            "DIFD OUT",
            "WINDR ERR"
        ]
    );
}

#[test]
fn every_digit_group_refusal_names_its_rule_in_both_languages() {
    let refused = [
        (Op::Ctrc, 2),
        (Op::Pari, 10),
        (Op::Xmov, 13),
        (Op::Xmov, 1001),
    ];
    let mut seen = [false; 3];
    for (op, value) in refused {
        let e = check_digit_group(op, value).unwrap_err();
        // No wildcard: a new rule fails to compile here until it has an example above.
        let (i, carried) = match e {
            DigitGroupError::Ctrc { value } => (0, value),
            DigitGroupError::Pari { value } => (1, value),
            DigitGroupError::Xmov { value } => (2, value),
        };
        assert_eq!(carried, value);
        seen[i] = true;
        assert!(e.to_string().starts_with(op.name()), "{e}");
    }
    assert_eq!(seen, [true; 3]);
    for (op, value) in [
        (Op::Ctrc, 11),
        (Op::Pari, 1),
        (Op::Xmov, 994),
        (Op::Rotb, 1111),
    ] {
        assert_eq!(check_digit_group(op, value), Ok(()), "{op:?} {value}");
    }
}
