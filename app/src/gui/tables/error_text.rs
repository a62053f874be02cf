//! The tables' refusals in the UI language: the engine's errors carry what happened (which
//! area, which range, which row has it already) and their texts are English, so each case is
//! worded here.

use super::super::i18n::{Lang, Msg};
use ladder_engine::model::sheets::{Sheet, TableError, Taken};
use ladder_engine::{AddressError, Profile};

/// An address error in the UI language (the engine's own texts are English).
pub fn address_error(e: &AddressError, profile: &Profile, lang: Lang) -> String {
    let t = |m: Msg| m.text(lang);
    match e {
        AddressError::Syntax(s) => format!("`{s}` {}", t(Msg::TblErrSyntax)),
        AddressError::UnknownArea(s, letters) => {
            format!("`{s}` {} {letters}", t(Msg::TblErrArea))
        }
        AddressError::Bit(s) => format!("`{s}`: {}", t(Msg::TblErrBit)),
        AddressError::NoBits(s, _) => format!("`{s}`: {}", t(Msg::TblErrNoBits)),
        AddressError::Range { text, area, .. } => {
            let (lo, hi) = profile.range(*area);
            format!("{text} {} ({area}{lo}–{area}{hi})", t(Msg::TblErrRange))
        }
    }
}

/// A data table's name as its tab shows it.
pub fn data_tab_name(sheet: Sheet, lang: Lang) -> &'static str {
    match sheet {
        Sheet::DFloat => Msg::TblTabDFloat,
        Sheet::Dt => Msg::TblTabDt,
        Sheet::Dc => Msg::TblTabDc,
        _ => Msg::TblTabD,
    }
    .text(lang)
}

/// Where a key or a name is already used: the table and the row (1-based), as the row
/// headers number them.
fn taken(at: &Taken, lang: Lang) -> String {
    match at {
        Taken::Symbols { table, row } => format!("{table} #{}", row + 1),
        Taken::Data { sheet, row } => format!("{} #{}", data_tab_name(*sheet, lang), row + 1),
        Taken::Row(row) => format!("#{}", row + 1),
        Taken::Block(p) => format!("{} {p}", ladder_engine::model::tables::BLOCK_SYMBOLS),
    }
}

/// `` `text`: reason ``, or the reason alone when nothing was typed.
fn quoted(text: &str, reason: &str) -> String {
    if text.is_empty() {
        reason.to_string()
    } else {
        format!("`{text}`: {reason}")
    }
}

/// Why a table refused an input, in the UI language; address ranges are the profile's.
pub fn table_error(e: &TableError, profile: &Profile, lang: Lang) -> String {
    let t = |m: Msg| m.text(lang);
    match e {
        TableError::AddressEmpty => t(Msg::TblErrAddressEmpty).into(),
        TableError::Address(e) => address_error(e, profile, lang),
        TableError::AreaNotHere { address, allowed } => {
            format!(
                "{address}: {} {}",
                t(Msg::TblErrAreaHere),
                allowed.describe()
            )
        }
        TableError::AddressTwice { address, at } => {
            format!(
                "{address}: {} {}",
                t(Msg::TblErrAddressTwice),
                taken(at, lang)
            )
        }
        TableError::SymbolName { name } => format!("`{name}`: {}", t(Msg::TblErrSymbolName)),
        TableError::SymbolTwice { name, at } => {
            format!(
                "`{name}`: {} {}",
                t(Msg::TblErrSymbolTwice),
                taken(at, lang)
            )
        }
        TableError::SymbolElsewhere { name, address } => {
            format!("`{name}`: {} {address}", t(Msg::TblErrSymbolElsewhere))
        }
        TableError::CommentTooLong { .. } => t(Msg::TblErrCommentLong).into(),
        TableError::NotInteger { text } => quoted(text, t(Msg::TblErrInteger)),
        TableError::NotReal { text } => quoted(text, t(Msg::TblErrReal)),
        TableError::AlarmRange { text } => quoted(text, t(Msg::TblErrAlarmRange)),
        TableError::AlarmTwice { number, by } => {
            format!("{number}: {} {by}", t(Msg::TblErrAlarmTwice))
        }
        TableError::MCodeRange { text } => quoted(text, t(Msg::TblErrMCode)),
        TableError::MCodeTwice { code, .. } => format!("M{code:02}: {}", t(Msg::TblErrMCodeTwice)),
        TableError::NoFreeKey { .. } => t(Msg::TblErrNoFree).into(),
        TableError::PasswordWrong => t(Msg::TblPasswordWrong).into(),
        TableError::PasswordEmpty => t(Msg::TblPasswordEmpty).into(),
        TableError::PasswordMismatch => t(Msg::TblPasswordMismatch).into(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use ladder_engine::address::{Address, AreaSet};
    use ladder_engine::{Area, ProfileId};

    /// Every refusal reads in both languages, with what the engine said (the address, the
    /// row) in it.
    #[test]
    fn every_refusal_is_worded_in_chinese_and_english() {
        let p = Profile::get(ProfileId::Gsk988ta);
        let a = Address::parse("R10.1").unwrap();
        let cases = [
            (
                TableError::AddressTwice {
                    address: a,
                    at: Taken::Symbols {
                        table: "IO".into(),
                        row: 4,
                    },
                },
                "R0010.1: address already listed: IO #5",
                "R0010.1: 地址已存在： IO #5",
            ),
            (
                TableError::AddressTwice {
                    address: Address::byte(Area::D, 3),
                    at: Taken::Data {
                        sheet: Sheet::DFloat,
                        row: 0,
                    },
                },
                "D0003: address already listed: D_FLOAT #1",
                "D0003: 地址已存在： D_FLOAT #1",
            ),
            (
                TableError::AreaNotHere {
                    address: Address::byte(Area::L, 1),
                    allowed: AreaSet::of(&[Area::X, Area::R]),
                },
                "L0001: only these areas belong here: X R",
                "L0001: 这里只能用这些地址： X R",
            ),
            (
                TableError::Address(AddressError::Range {
                    text: "R1000".into(),
                    area: Area::R,
                    lo: 0,
                    hi: 0,
                }),
                "R1000 is out of range (R0–R999)",
                "R1000 超出范围 (R0–R999)",
            ),
            (
                TableError::NotInteger {
                    text: String::new(),
                },
                "Enter a whole number from -2147483647 to 2147483647",
                "请输入 -2147483647 到 2147483647 之间的整数",
            ),
            (
                TableError::MCodeTwice { code: 3, row: 0 },
                "M03: This M code is already listed",
                "M03: M 代码已存在",
            ),
        ];
        for (e, en, zh) in cases {
            assert_eq!(table_error(&e, p, Lang::En), en);
            assert_eq!(table_error(&e, p, Lang::Zh), zh);
        }
    }
}
