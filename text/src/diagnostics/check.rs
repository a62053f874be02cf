//! The words of [`CheckFinding`]: each finding in English and in Chinese, side by side.

use super::place;
use crate::Lang;
use crate::quoted::operand_refusal;
use ladder_engine::address::Address;
use ladder_engine::catalog::{InstrClass, Op};
use ladder_engine::compiler::{CheckFinding, Location, OperandRefusal};

/// What `f` found and how to fix it, in `lang`.
pub(super) fn text(f: &CheckFinding, lang: Lang) -> String {
    match f {
        CheckFinding::SubNumberRange { number, lo, hi } => match lang {
            Lang::En => format!("subprogram number P{number:04} is out of range (P{lo}–P{hi})"),
            Lang::Zh => format!("子程序号 P{number:04} 超出范围（P{lo}–P{hi}）"),
        },
        CheckFinding::SubTwice { number } => match lang {
            Lang::En => {
                format!("subprogram P{number:04} is defined twice: give one of them another number")
            }
            Lang::Zh => format!("子程序 P{number:04} 重复定义：请给其中一个换一个子程序号"),
        },
        CheckFinding::LabelTwice { label, first } => match lang {
            Lang::En => format!(
                "label {label} is already defined at {}; each label is defined once in the project",
                place(first, lang)
            ),
            Lang::Zh => format!(
                "标号 {label} 已在 {} 定义；工程中每个标号只能定义一次",
                place(first, lang)
            ),
        },
        CheckFinding::CoilTwice { coil, first } => match lang {
            Lang::En => format!(
                "coil {coil} is also driven at {}; the later one wins each scan",
                place(first, lang)
            ),
            Lang::Zh => format!(
                "线圈 {coil} 也在 {} 输出；每次扫描以后面的输出为准",
                place(first, lang)
            ),
        },
        CheckFinding::TimerTwice { number, first } => match lang {
            Lang::En => format!(
                "{number} is also used by the instruction at {}; two instructions sharing a timer or counter disturb each other",
                place(first, lang)
            ),
            Lang::Zh => format!(
                "{number} 也被 {} 的指令使用；两条指令共用一个定时器或计数器会互相干扰",
                place(first, lang)
            ),
        },
        CheckFinding::UndefinedLabel { label } => match lang {
            Lang::En => format!(
                "JMPB to {label}, which no LBL defines: add `LBL {label}` in this block or correct the label"
            ),
            Lang::Zh => format!(
                "JMPB 跳转到 {label}，但没有 LBL 定义该标号：请在本程序块中加入 `LBL {label}`，或改正标号"
            ),
        },
        CheckFinding::JumpOutOfBlock { label, target } => match lang {
            Lang::En => format!(
                "JMPB to {label} at {}: a jump stays inside its own block (use CALL to reach a subprogram)",
                place(target, lang)
            ),
            Lang::Zh => format!(
                "JMPB 跳转到位于 {} 的 {label}：跳转只能在本程序块内进行（要进入子程序请用 CALL）",
                place(target, lang)
            ),
        },
        CheckFinding::UndefinedSub { op, sub } => undefined_sub(*op, *sub, lang),
        CheckFinding::Recursion { callee } => match lang {
            Lang::En => format!(
                "this call of P{callee:04} makes the subprograms call themselves in a loop, which never ends within a scan"
            ),
            Lang::Zh => {
                format!("此处调用 P{callee:04} 使子程序循环调用自身，一次扫描内永远不会结束")
            }
        },
        CheckFinding::Level1Steps { steps, limit } => match lang {
            Lang::En => format!(
                "level 1 has {steps} steps with the subprograms it calls; it must stay under {limit} (move work to level 2)"
            ),
            Lang::Zh => format!(
                "一级程序连同其调用的子程序共 {steps} 步；必须少于 {limit} 步（请把部分程序移到二级程序）"
            ),
        },
        CheckFinding::ProgramSteps { steps, limit } => match lang {
            Lang::En => format!("the program has {steps} steps; at most {limit} fit the PLC"),
            Lang::Zh => format!("程序共 {steps} 步；PLC 最多容纳 {limit} 步"),
        },
        CheckFinding::BlockStackDepth { limit } => match lang {
            Lang::En => format!(
                "more than {limit} nested logic blocks: split the rung or use intermediate relays"
            ),
            Lang::Zh => format!("嵌套的逻辑块超过 {limit} 个：请拆分该梯级，或使用中间继电器"),
        },
        CheckFinding::BranchStackDepth { limit } => match lang {
            Lang::En => format!(
                "more than {limit} nested branch points (MPS): split the rung or use intermediate relays"
            ),
            Lang::Zh => {
                format!("嵌套的分支点（MPS）超过 {limit} 个：请拆分该梯级，或使用中间继电器")
            }
        },
        CheckFinding::OperandCount {
            op,
            expected,
            found,
        } => operand_count(*op, *expected, *found, lang),
        CheckFinding::TableOperandCount { op } => table_operand_count(*op, lang),
        CheckFinding::UndefinedSymbol { name } => match lang {
            Lang::En => format!(
                "undefined symbol `{name}`: define it in the symbol table or write the address"
            ),
            Lang::Zh => format!("符号 `{name}` 未定义：请在符号表中定义，或直接写地址"),
        },
        CheckFinding::Operand {
            op,
            operand,
            refusal,
        } => refused(*op, operand, refusal, lang),
        CheckFinding::BitsSpill { op, out, next } => bits_spill(*op, *out, *next, lang),
        CheckFinding::OutputTwice {
            op,
            operand,
            address,
            first_op,
            first_operand,
            first_address,
            first,
        } => output_twice(
            (*op, operand, *address),
            (*first_op, first_operand, *first_address),
            first,
            lang,
        ),
        CheckFinding::PresetRange {
            op,
            operand,
            address,
            row,
            value,
            min,
            max,
        } => preset_range((*op, operand, *address), *row, *value, (*min, *max), lang),
    }
}

/// L033: `op` (CALL, CALLU) calls the subprogram `sub`, which does not exist.
fn undefined_sub(op: Op, sub: Address, lang: Lang) -> String {
    let name = op.name();
    match lang {
        Lang::En => {
            format!("{name} {sub}: there is no subprogram {sub}; create it or correct the number")
        }
        Lang::Zh => format!("{name} {sub}：不存在子程序 {sub}；请新建该子程序或改正子程序号"),
    }
}

/// W003: the three result bits of `op` from `out` on run into the byte `next`.
fn bits_spill(op: Op, out: Address, next: Address, lang: Lang) -> String {
    let name = op.name();
    match lang {
        Lang::En => format!("{name} OUT {out}: the three result bits continue into {next}"),
        Lang::Zh => format!("{name} 的 OUT {out}：三个结果位会延续到 {next}"),
    }
}

/// The names of `op`'s fixed operands, as its catalogue entry lists them (`ACT IN OUT`).
fn operand_names(op: Op) -> String {
    let names: Vec<&str> = op.spec().operands.iter().map(|o| o.name).collect();
    names.join(" ")
}

/// The name of the operand that counts the table entries of `op`, if it has a table.
fn table_count(op: Op) -> &'static str {
    let spec = op.spec();
    spec.table.map_or("", |t| spec.operands[t.count_from].name)
}

/// L011: `op` takes `expected` operands and `found` are written.
fn operand_count(op: Op, expected: usize, found: usize, lang: Lang) -> String {
    let (name, names) = (op.name(), operand_names(op));
    let table = op.spec().table.is_some();
    let count = table_count(op);
    match lang {
        Lang::En => {
            let extra = if table {
                format!(" and {count} table entries")
            } else {
                String::new()
            };
            let s = if expected == 1 { "" } else { "s" };
            format!("{name} takes {expected} operand{s} ({names}{extra}), found {found}")
        }
        Lang::Zh => {
            let extra = if table {
                format!("，以及 {count} 个表格数据")
            } else {
                String::new()
            };
            format!("{name} 需要 {expected} 个操作数（{names}{extra}），实有 {found} 个")
        }
    }
}

/// L011: `op` has fewer operands than its fixed ones, and its table no constant count.
fn table_operand_count(op: Op, lang: Lang) -> String {
    let (name, names, count) = (op.name(), operand_names(op), table_count(op));
    match lang {
        Lang::En => format!("{name} takes {names} and {count} table entries"),
        Lang::Zh => format!("{name} 需要操作数 {names}，以及 {count} 个表格数据"),
    }
}

/// L011, L021–L025: `op` refuses its operand named `operand`, for `refusal`.
fn refused(op: Op, operand: &str, refusal: &OperandRefusal, lang: Lang) -> String {
    let why = operand_refusal(refusal, lang);
    match lang {
        Lang::En => format!("{} {operand}: {why}", op.name()),
        Lang::Zh => format!("{} 的操作数 {operand}：{why}", op.name()),
    }
}

/// W008: the output `later` overlaps `earlier`, written by the instruction at `first`. Each
/// output is (instruction, operand name, address); a coil's is named as the coil.
fn output_twice(
    later: (Op, &str, Address),
    earlier: (Op, &str, Address),
    first: &Location,
    lang: Lang,
) -> String {
    let output = |(op, operand, address): (Op, &str, Address)| {
        let coil = op.spec().class == InstrClass::Coil;
        match (lang, coil) {
            (Lang::En, true) => format!("coil {address}"),
            (Lang::En, false) => format!("{} {operand} {address}", op.name()),
            (Lang::Zh, true) => format!("线圈 {address}"),
            (Lang::Zh, false) => format!("{} 的 {operand} {address}", op.name()),
        }
    };
    let (later, earlier, at) = (output(later), output(earlier), place(first, lang));
    match lang {
        Lang::En => format!(
            "{later} overlaps {earlier} at {at}, and one of the two writes it at every execution whatever its condition, so the other write never lasts: give each output its own address"
        ),
        Lang::Zh => format!(
            "{later} 与 {at} 的 {earlier} 重叠，且其中一条指令无论条件如何每次执行都写入，另一条写入的值无法保持：请给每个输出使用各自的地址"
        ),
    }
}

/// W009: the data table sets the entry `address` that the preset (instruction, operand name,
/// entry) names, on its `row`, to `value`, outside the preset's `range`.
fn preset_range(
    (op, operand, address): (Op, &str, Address),
    row: usize,
    value: i64,
    (min, max): (i64, i64),
    lang: Lang,
) -> String {
    let (name, table) = (op.name(), address.area);
    let counted = value.clamp(min, max);
    match lang {
        Lang::En => format!(
            "{name} {operand} {address}: the {table} table (row {row}) sets {address} to {value}, outside the preset range {min}…{max}, so {name} counts it as {counted}: correct the table's value"
        ),
        Lang::Zh => format!(
            "{name} 的 {operand} {address}：数据表 {table}（第 {row} 行）将 {address} 设为 {value}，超出预置值范围 {min}…{max}，{name} 按 {counted} 处理：请改正数据表中的值"
        ),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use ladder_engine::address::Area;
    use ladder_engine::catalog::OperandKind;
    use ladder_engine::compiler::Origin;
    use ladder_engine::model::Operand;

    /// The slot of each finding; no wildcard, so a new variant does not compile here until it
    /// has one, and the test fails until it has an example.
    fn slot(f: &CheckFinding) -> usize {
        match f {
            CheckFinding::SubNumberRange { .. } => 0,
            CheckFinding::SubTwice { .. } => 1,
            CheckFinding::LabelTwice { .. } => 2,
            CheckFinding::CoilTwice { .. } => 3,
            CheckFinding::TimerTwice { .. } => 4,
            CheckFinding::UndefinedLabel { .. } => 5,
            CheckFinding::JumpOutOfBlock { .. } => 6,
            CheckFinding::UndefinedSub { .. } => 7,
            CheckFinding::Recursion { .. } => 8,
            CheckFinding::Level1Steps { .. } => 9,
            CheckFinding::ProgramSteps { .. } => 10,
            CheckFinding::BlockStackDepth { .. } => 11,
            CheckFinding::BranchStackDepth { .. } => 12,
            CheckFinding::OperandCount { .. } => 13,
            CheckFinding::TableOperandCount { .. } => 14,
            CheckFinding::UndefinedSymbol { .. } => 15,
            CheckFinding::Operand { .. } => 16,
            CheckFinding::BitsSpill { .. } => 17,
            CheckFinding::OutputTwice { .. } => 18,
            CheckFinding::PresetRange { .. } => 19,
        }
    }
    const VARIANTS: usize = 20;

    fn at(block_label: &str, network: usize, origin: Origin) -> Location {
        Location {
            block: 1,
            block_label: block_label.into(),
            network,
            origin,
        }
    }

    fn examples() -> Vec<CheckFinding> {
        let cell = Origin::Cell { row: 0, col: 3 };
        let label = Address::byte(Area::L, 7);
        let r = |n, b| Address::bit(Area::R, n, b);
        vec![
            CheckFinding::SubNumberRange {
                number: 600,
                lo: 1,
                hi: 512,
            },
            CheckFinding::SubTwice { number: 3 },
            CheckFinding::LabelTwice {
                label,
                first: at("P0002", 1, cell),
            },
            CheckFinding::CoilTwice {
                coil: r(10, 2),
                first: at("LEVEL2", 4, cell),
            },
            CheckFinding::TimerTwice {
                number: Address::byte(Area::T, 5),
                first: at("LEVEL1", 0, Origin::Line(4)),
            },
            CheckFinding::UndefinedLabel { label },
            CheckFinding::JumpOutOfBlock {
                label,
                target: at("P0003", 2, Origin::None),
            },
            CheckFinding::UndefinedSub {
                op: Op::Callu,
                sub: Address::byte(Area::P, 9),
            },
            CheckFinding::Recursion { callee: 12 },
            CheckFinding::Level1Steps {
                steps: 5200,
                limit: 5000,
            },
            CheckFinding::ProgramSteps {
                steps: 24100,
                limit: 24000,
            },
            CheckFinding::BlockStackDepth { limit: 32 },
            CheckFinding::BranchStackDepth { limit: 16 },
            CheckFinding::OperandCount {
                op: Op::Movn,
                expected: 3,
                found: 2,
            },
            CheckFinding::OperandCount {
                op: Op::Codb,
                expected: 6,
                found: 5,
            },
            CheckFinding::TableOperandCount { op: Op::Codb },
            CheckFinding::UndefinedSymbol {
                name: "START".into(),
            },
            CheckFinding::Operand {
                op: Op::Movn,
                operand: "IN".into(),
                refusal: OperandRefusal::Kind {
                    expected: OperandKind::Byte,
                    found: Operand::Real(1.5),
                },
            },
            CheckFinding::Operand {
                op: Op::Movn,
                operand: "SIZE".into(),
                refusal: OperandRefusal::Size(3),
            },
            CheckFinding::BitsSpill {
                op: Op::Cmp,
                out: r(19, 6),
                next: Address::byte(Area::R, 20),
            },
            CheckFinding::OutputTwice {
                op: Op::Movn,
                operand: "OUT".into(),
                address: Address::byte(Area::R, 10),
                first_op: Op::Out,
                first_operand: "b".into(),
                first_address: r(10, 2),
                first: at("LEVEL2", 0, Origin::Line(4)),
            },
            CheckFinding::OutputTwice {
                op: Op::Set,
                operand: "OUT".into(),
                address: r(20, 0),
                first_op: Op::Tmrb,
                first_operand: "OUT".into(),
                first_address: r(20, 0),
                first: at("LEVEL2", 2, cell),
            },
            CheckFinding::PresetRange {
                op: Op::Tmrb,
                operand: "PT".into(),
                address: Address::byte(Area::Dt, 4),
                row: 2,
                value: -5,
                min: 0,
                max: 2147483647,
            },
        ]
    }

    #[test]
    fn every_check_finding_reads_in_chinese_with_the_specifics_of_its_english() {
        let mut seen = [false; VARIANTS];
        for f in examples() {
            seen[slot(&f)] = true;
            crate::bilingual::assert_bilingual(&text(&f, Lang::En), &text(&f, Lang::Zh));
        }
        assert_eq!(seen, [true; VARIANTS], "a check finding without an example");
    }

    #[test]
    fn findings_read_as_the_check_words_them() {
        let words = |f: &CheckFinding| (text(f, Lang::En), text(f, Lang::Zh));
        let coil = CheckFinding::CoilTwice {
            coil: Address::bit(Area::R, 10, 2),
            first: at("LEVEL2", 4, Origin::Cell { row: 0, col: 3 }),
        };
        assert_eq!(
            words(&coil),
            (
                "coil R0010.2 is also driven at LEVEL2 network 5 row 1 col 4; the later one wins each scan".into(),
                "线圈 R0010.2 也在 二级程序 网络 5 行 1 列 4 输出；每次扫描以后面的输出为准".into()
            )
        );
        let count = CheckFinding::OperandCount {
            op: Op::Codb,
            expected: 6,
            found: 5,
        };
        let (en, zh) = words(&count);
        assert!(
            en.starts_with("CODB takes 6 operands (") && en.ends_with(" table entries), found 5"),
            "{en}"
        );
        assert!(zh.starts_with("CODB 需要 6 个操作数（"), "{zh}");
        let refused = CheckFinding::Operand {
            op: Op::Movn,
            operand: "SIZE".into(),
            refusal: OperandRefusal::Size(3),
        };
        assert_eq!(
            words(&refused),
            (
                "MOVN SIZE: the size is 1, 2 or 4, not 3".into(),
                "MOVN 的操作数 SIZE：大小应为 1、2 或 4，不能是 3".into()
            )
        );
        let output = &examples()[20];
        assert_eq!(
            words(output),
            (
                "MOVN OUT R0010 overlaps coil R0010.2 at line 4, and one of the two writes it at every execution whatever its condition, so the other write never lasts: give each output its own address".into(),
                "MOVN 的 OUT R0010 与 第 4 行 的 线圈 R0010.2 重叠，且其中一条指令无论条件如何每次执行都写入，另一条写入的值无法保持：请给每个输出使用各自的地址".into()
            )
        );
        let preset = examples().pop().unwrap();
        assert_eq!(
            words(&preset).0,
            "TMRB PT DT0004: the DT table (row 2) sets DT0004 to -5, outside the preset range 0…2147483647, so TMRB counts it as 0: correct the table's value"
        );
        assert_eq!(
            text(&CheckFinding::Recursion { callee: 12 }, Lang::Zh),
            "此处调用 P0012 使子程序循环调用自身，一次扫描内永远不会结束"
        );
    }
}
