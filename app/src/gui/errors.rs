//! The engine's refusals in the user's language. The engine's errors are typed and speak
//! English; the editor shows each one in Chinese or English, here and nowhere else.

use super::document::Refused;
use super::i18n::{Lang, Msg};
use ladder_engine::model::EditError;

/// Why the document refused a change.
pub fn refused(e: &Refused, lang: Lang) -> String {
    match e {
        Refused::ReadOnly => Msg::ReadOnly.text(lang).to_string(),
        Refused::Edit(e) => edit_error(e, lang),
    }
}

/// Why the engine refused a ladder edit.
pub fn edit_error(e: &EditError, lang: Lang) -> String {
    match lang {
        Lang::En => e.to_string(),
        Lang::Zh => match e {
            EditError::NoSuchPlace(what) => format!("这个位置不存在（{what}）"),
            EditError::WrongColumn(why) => format!("元件不能放在这一列：{why}"),
            EditError::FixedBlock => "一级程序和二级程序总是存在；只能增删子程序".to_string(),
            EditError::LastRow => "网络至少保留一行；要删除请删除整个网络".to_string(),
            EditError::NothingAbove => "并联触点需要上一行有元件".to_string(),
            EditError::WrongWidth(w) => format!("网络与本梯形图的宽度不同：{w}"),
        },
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_refusal_reads_in_chinese_in_a_chinese_ui() {
        for e in [
            EditError::NoSuchPlace("row"),
            EditError::WrongColumn("a coil belongs in the output column"),
            EditError::FixedBlock,
            EditError::LastRow,
            EditError::NothingAbove,
            EditError::WrongWidth("9 columns".into()),
        ] {
            let zh = edit_error(&e, Lang::Zh);
            assert!(
                zh.chars().any(|c| ('\u{4e00}'..='\u{9fff}').contains(&c)),
                "{zh}"
            );
            assert_eq!(edit_error(&e, Lang::En), e.to_string());
        }
    }
}
