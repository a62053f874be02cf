//! The words of [`TableFinding`]: each finding in English and in Chinese, side by side.

use crate::Lang;
use crate::quoted::{address_error, table_error};
use ladder_engine::address::Address;
use ladder_engine::compiler::TableFinding;
use ladder_engine::model::sheets::Sheet;

/// What `f` found and how to fix it, in `lang`.
pub(super) fn text(f: &TableFinding, lang: Lang) -> String {
    let (en, zh) = words(f);
    match lang {
        Lang::En => en,
        Lang::Zh => zh,
    }
}

/// A data table's name, the same in both languages.
fn table(sheet: Sheet) -> &'static str {
    sheet.data_name().unwrap_or("D")
}

/// What `f` says, in English and in Chinese. Rows and tables count from 1 in the words.
fn words(f: &TableFinding) -> (String, String) {
    use TableFinding as F;
    let (en, zh) = (Lang::En, Lang::Zh);
    match f {
        F::CommentTooLong { lang, error } => (
            format!(
                "the `{lang}` comment: {}; shorten it",
                table_error(error, en)
            ),
            format!("`{lang}` 注释：{}；请缩短", table_error(error, zh)),
        ),
        F::DataSymbolName { error } | F::MCodeRange { error } => {
            (table_error(error, en), table_error(error, zh))
        }
        F::DataSymbolElsewhere { address, error } => (
            format!(
                "{address}: {}; use another symbol or none",
                table_error(error, en)
            ),
            format!(
                "{address}：{}；请换一个符号，或不用符号",
                table_error(error, zh)
            ),
        ),
        F::KeyArea { error } => (
            format!(
                "{}; this table lists memory addresses",
                table_error(error, en)
            ),
            format!("{}；此表只列存储器地址", table_error(error, zh)),
        ),
        F::KeyRange { error } | F::AddressRange { error } => {
            (address_error(error, en), address_error(error, zh))
        }
        F::KeyTwice { address, row } => (
            format!(
                "{address} is also in row {}; keep one row per address",
                row + 1
            ),
            format!("{address} 也在第 {} 行；每个地址只保留一行", row + 1),
        ),
        F::SymbolTableName { name } => (
            format!(
                "symbol table name `{name}` is empty, taken, or the block-symbol table's: give it a unique name"
            ),
            format!(
                "符号表名称 `{name}` 为空、已被占用或与程序块符号表同名：请另起一个不重复的名称"
            ),
        ),
        F::SymbolArea { error } => (
            format!(
                "{} (labels have no symbols; a subprogram is named in its block)",
                table_error(error, en)
            ),
            format!(
                "{}（标号不能定义符号；子程序在其程序块中命名）",
                table_error(error, zh)
            ),
        ),
        F::SymbolAddressTwice {
            address,
            table,
            row,
        } => symbol_address_twice(*address, *table, *row),
        F::SymbolName { name } => (
            format!(
                "`{name}` is not a valid symbol: use letters, digits, `_` and Chinese, not starting with a digit, at most 32 characters, and not an address"
            ),
            format!(
                "`{name}` 不是有效的符号：请使用字母、数字、`_` 和汉字，不以数字开头，最多 32 个字符，且不能是地址"
            ),
        ),
        F::SymbolTwice { name, table, row } => symbol_twice(name, *table, *row),
        F::DataAddressTwice {
            address,
            sheet,
            row,
        } => data_address_twice(*address, *sheet, *row),
        F::DataAddressArea { address, sheet } => {
            let name = table(*sheet);
            (
                format!("{address} does not belong in the {name} table; use {name} addresses"),
                format!("{address} 不属于数据表 {name}；请使用 {name} 地址"),
            )
        }
        F::DataValue {
            address,
            value,
            min,
            max,
        } => (
            format!("{address} = {value} lies outside its limits {min}…{max}"),
            format!("{address} = {value} 超出其上下限 {min}…{max}"),
        ),
        F::CounterPreset { address, value } => (
            format!("{address} = {value}: a counter preset is 0…2147483647"),
            format!("{address} = {value}：计数器预置值为 0…2147483647"),
        ),
        F::RealAddress { address } => (
            format!("{address} is not a D address of this controller"),
            format!("{address} 不是本控制器的 D 地址"),
        ),
        F::RealValue { address, value } => {
            let value = f32::from_bits(*value);
            (
                format!("{address} = {value} lies outside its limits"),
                format!("{address} = {value} 超出其上下限"),
            )
        }
        F::AlarmRange { bit, number } => (
            format!("{bit}: alarm number {number} is outside 1000–9999"),
            format!("{bit}：报警号 {number} 超出 1000–9999"),
        ),
        F::AlarmTwice { bit, number, by } => (
            format!("{bit}: alarm number {number} is already used by {by}"),
            format!("{bit}：报警号 {number} 已被 {by} 使用"),
        ),
        F::AlarmWithoutText { bit, number } => (
            format!("{bit}: alarm {number} has no text"),
            format!("{bit}：报警 {number} 没有信息文本"),
        ),
        F::TextWithoutAlarm { bit } => (
            format!("{bit}: a message text without an alarm number"),
            format!("{bit}：信息文本没有报警号"),
        ),
        F::MessageBeyondRange { bit, last } => (
            format!("{bit} is beyond this controller's A range (A0000.0–{last}): clear the row"),
            format!("{bit} 超出本控制器的 A 地址范围（A0000.0–{last}）：请清空该行"),
        ),
        F::MCodeTwice { code, row } => (
            format!(
                "M{code:02} is also in row {}; keep one row per M code",
                row + 1
            ),
            format!("M{code:02} 也在第 {} 行；每个 M 代码只保留一行", row + 1),
        ),
        F::VersionNameLength { max } => too_long("name", "工程名称", *max),
        F::VersionDesignerLength { max } => too_long("designer", "设计者", *max),
        F::VersionVersionLength { max } => too_long("version", "版本", *max),
        F::VersionRemarksLength { max } => too_long("remarks", "备注", *max),
    }
}

/// A symbol row's address that row `row` of symbol table `table` lists too (W004).
fn symbol_address_twice(address: Address, table: usize, row: usize) -> (String, String) {
    (
        format!(
            "{address} is also in table {} row {}; keep one row per address",
            table + 1,
            row + 1
        ),
        format!(
            "{address} 也在符号表 {} 第 {} 行；每个地址只保留一行",
            table + 1,
            row + 1
        ),
    )
}

/// A symbol row's name that row `row` of symbol table `table` defines too (T002).
fn symbol_twice(name: &str, table: usize, row: usize) -> (String, String) {
    (
        format!(
            "symbol `{name}` already exists (table {} row {}); symbols are unique",
            table + 1,
            row + 1
        ),
        format!(
            "符号 `{name}` 已存在（符号表 {} 第 {} 行）；符号不能重复",
            table + 1,
            row + 1
        ),
    )
}

/// A data row's address that row `row` of data table `sheet` lists too (T003).
fn data_address_twice(address: Address, sheet: Sheet, row: usize) -> (String, String) {
    (
        format!(
            "{address} is also in the {} table row {}; keep one row per address",
            table(sheet),
            row + 1
        ),
        format!(
            "{address} 也在数据表 {} 第 {} 行；每个地址只保留一行",
            table(sheet),
            row + 1
        ),
    )
}

/// A field of the version information longer than `max` characters (W006), named in each
/// language.
fn too_long(field_en: &str, field_zh: &str, max: usize) -> (String, String) {
    (
        format!("the {field_en} is longer than {max} characters"),
        format!("{field_zh}超过 {max} 个字符"),
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use ladder_engine::address::{AddressError, Area};
    use ladder_engine::model::sheets::{
        TableError, check_comment, check_m_code, check_symbol_area, check_value_area,
    };

    fn a(text: &str) -> Address {
        Address::parse(text).unwrap()
    }

    /// The slot of each finding; no wildcard, so a new variant does not compile here until it
    /// has one, and the test fails until it has an example.
    fn slot(f: &TableFinding) -> usize {
        use TableFinding as F;
        match f {
            F::CommentTooLong { .. } => 0,
            F::DataSymbolName { .. } => 1,
            F::DataSymbolElsewhere { .. } => 2,
            F::KeyArea { .. } => 3,
            F::KeyRange { .. } => 4,
            F::KeyTwice { .. } => 5,
            F::SymbolTableName { .. } => 6,
            F::SymbolArea { .. } => 7,
            F::AddressRange { .. } => 8,
            F::SymbolAddressTwice { .. } => 9,
            F::SymbolName { .. } => 10,
            F::SymbolTwice { .. } => 11,
            F::DataAddressTwice { .. } => 12,
            F::DataAddressArea { .. } => 13,
            F::DataValue { .. } => 14,
            F::CounterPreset { .. } => 15,
            F::RealAddress { .. } => 16,
            F::RealValue { .. } => 17,
            F::AlarmRange { .. } => 18,
            F::AlarmTwice { .. } => 19,
            F::AlarmWithoutText { .. } => 20,
            F::TextWithoutAlarm { .. } => 21,
            F::MessageBeyondRange { .. } => 22,
            F::MCodeRange { .. } => 23,
            F::MCodeTwice { .. } => 24,
            F::VersionNameLength { .. } => 25,
            F::VersionDesignerLength { .. } => 26,
            F::VersionVersionLength { .. } => 27,
            F::VersionRemarksLength { .. } => 28,
        }
    }
    const VARIANTS: usize = 29;

    fn examples() -> Vec<TableFinding> {
        use TableFinding as F;
        let range = AddressError::Range {
            text: "R9999".into(),
            area: Area::R,
            lo: 0,
            hi: 1999,
        };
        vec![
            F::CommentTooLong {
                lang: "en".into(),
                error: check_comment(&"x".repeat(130)).unwrap_err(),
            },
            F::DataSymbolName {
                error: TableError::SymbolName {
                    name: "9LIVES".into(),
                },
            },
            F::DataSymbolElsewhere {
                address: a("D0004"),
                error: TableError::SymbolElsewhere {
                    name: "START".into(),
                    address: a("X0002.1"),
                },
            },
            F::KeyArea {
                error: check_value_area(a("P0001")).unwrap_err(),
            },
            F::KeyRange {
                error: range.clone(),
            },
            F::KeyTwice {
                address: a("R0010"),
                row: 2,
            },
            F::SymbolTableName { name: "IO".into() },
            F::SymbolArea {
                error: check_symbol_area(a("L0001")).unwrap_err(),
            },
            F::AddressRange { error: range },
            F::SymbolAddressTwice {
                address: a("X0002.1"),
                table: 1,
                row: 4,
            },
            F::SymbolName {
                name: "9LIVES".into(),
            },
            F::SymbolTwice {
                name: "START".into(),
                table: 0,
                row: 6,
            },
            F::DataAddressTwice {
                address: a("D0001"),
                sheet: Sheet::D,
                row: 0,
            },
            F::DataAddressArea {
                address: a("R0001"),
                sheet: Sheet::Dt,
            },
            F::DataValue {
                address: a("D0002"),
                value: 50,
                min: 0,
                max: 10,
            },
            F::CounterPreset {
                address: a("DC0002"),
                value: -5,
            },
            F::RealAddress {
                address: a("D9999"),
            },
            F::RealValue {
                address: a("D0008"),
                value: 2.5f32.to_bits(),
            },
            F::AlarmRange {
                bit: a("A0000.1"),
                number: 99,
            },
            F::AlarmTwice {
                bit: a("A0000.5"),
                number: 1001,
                by: a("A0000.1"),
            },
            F::AlarmWithoutText {
                bit: a("A0001.0"),
                number: 1234,
            },
            F::TextWithoutAlarm { bit: a("A0001.1") },
            F::MessageBeyondRange {
                bit: a("A0030.0"),
                last: a("A0024.7"),
            },
            F::MCodeRange {
                error: check_m_code(12345).unwrap_err(),
            },
            F::MCodeTwice { code: 3, row: 0 },
            F::VersionNameLength { max: 63 },
            F::VersionDesignerLength { max: 63 },
            F::VersionVersionLength { max: 19 },
            F::VersionRemarksLength { max: 511 },
        ]
    }

    #[test]
    fn every_table_finding_reads_in_chinese_with_the_englishs_specifics() {
        let mut seen = [false; VARIANTS];
        for f in &examples() {
            seen[slot(f)] = true;
            crate::bilingual::assert_bilingual(&text(f, Lang::En), &text(f, Lang::Zh));
        }
        assert_eq!(seen, [true; VARIANTS], "a table finding without an example");
    }

    #[test]
    fn findings_read_as_check_prints_them() {
        let f = TableFinding::MessageBeyondRange {
            bit: a("A0030.0"),
            last: a("A0024.7"),
        };
        assert_eq!(
            text(&f, Lang::En),
            "A0030.0 is beyond this controller's A range (A0000.0–A0024.7): clear the row"
        );
        assert_eq!(
            text(&f, Lang::Zh),
            "A0030.0 超出本控制器的 A 地址范围（A0000.0–A0024.7）：请清空该行"
        );
        let f = TableFinding::SymbolAddressTwice {
            address: a("X0002.1"),
            table: 1,
            row: 4,
        };
        assert_eq!(
            text(&f, Lang::En),
            "X0002.1 is also in table 2 row 5; keep one row per address"
        );
        assert_eq!(
            text(&f, Lang::Zh),
            "X0002.1 也在符号表 2 第 5 行；每个地址只保留一行"
        );
        let f = TableFinding::DataAddressTwice {
            address: a("D0001"),
            sheet: Sheet::DFloat,
            row: 2,
        };
        assert_eq!(
            text(&f, Lang::En),
            "D0001 is also in the D_FLOAT table row 3; keep one row per address"
        );
        assert_eq!(
            text(&f, Lang::Zh),
            "D0001 也在数据表 D_FLOAT 第 3 行；每个地址只保留一行"
        );
        let f = TableFinding::CommentTooLong {
            lang: "en".into(),
            error: check_comment(&"x".repeat(130)).unwrap_err(),
        };
        assert_eq!(
            text(&f, Lang::En),
            "the `en` comment: a comment has at most 127 bytes, not 130; shorten it"
        );
        assert_eq!(
            text(&f, Lang::Zh),
            "`en` 注释：注释最多 127 字节，现为 130 字节；请缩短"
        );
        let f = TableFinding::RealValue {
            address: a("D0008"),
            value: f32::NAN.to_bits(),
        };
        assert_eq!(text(&f, Lang::En), "D0008 = NaN lies outside its limits");
        let f = TableFinding::VersionRemarksLength { max: 511 };
        assert_eq!(
            text(&f, Lang::En),
            "the remarks is longer than 511 characters"
        );
        assert_eq!(text(&f, Lang::Zh), "备注超过 511 个字符");
    }
}
