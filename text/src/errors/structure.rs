//! A ladder's broken structure in the user's language: the file check's
//! [`StructureError`] and a network's [`WidthError`], in the words of the GSK manual
//! (一级程序, 二级程序, 子程序 P0001, 网络, 行, 列).

use crate::Lang;
use ladder_engine::model::{BlockKind, MAX_WIDTH, NetworkPlace, StructureError, WidthError};

/// Which invariant of the ladder a project file breaks, in `lang`.
pub fn structure_error(e: &StructureError, lang: Lang) -> String {
    match lang {
        Lang::En => e.to_string(),
        Lang::Zh => match e {
            StructureError::Width(w) => {
                format!("每个网络的触点列数为 {w}，应为 1–{MAX_WIDTH}")
            }
            StructureError::LevelsFirst => "前两个程序块必须依次是一级程序和二级程序".to_string(),
            StructureError::AfterSubprograms(kind) => format!(
                "{}排在子程序之间：一级程序和二级程序必须在所有子程序之前",
                block_zh(kind)
            ),
            StructureError::SubprogramOrder(n) => format!(
                "子程序 P{n:04} 的编号顺序错误或重复：子程序须按编号从小到大排列，且编号各不相同"
            ),
            StructureError::Network { at, error } => {
                format!("{}：{}", place_zh(at), width_error_zh(error))
            }
            StructureError::DuplicateId { at, id, first } => format!(
                "{} 与 {} 的编号同为 {}：请给它一个其他网络都没有的编号",
                place_zh(at),
                place_zh(first),
                id.0
            ),
        },
    }
}

/// Why a network does not fit a ladder's width, in Chinese (the English is the error's own
/// text): the detail after "网络与本梯形图的宽度不同" or after the network's place.
pub fn width_error_zh(e: &WidthError) -> String {
    match e {
        WidthError::NoRows => "没有任何行（网络至少要有一行）".to_string(),
        WidthError::Row {
            row,
            cells,
            junctions,
            expected,
        } => format!(
            "第 {row} 行有 {cells} 列、{junctions} 个竖线位置，应各为 {expected} 个（触点列加输出列）"
        ),
    }
}

/// A block as the manual names it: 一级程序, 二级程序, 子程序 P0001.
fn block_zh(kind: &BlockKind) -> String {
    match kind {
        BlockKind::Level1 => "一级程序".to_string(),
        BlockKind::Level2 => "二级程序".to_string(),
        BlockKind::Sub { number, .. } => format!("子程序 P{number:04}"),
    }
}

/// A network's place as the compiler's Chinese diagnostics name it: `二级程序 网络 3`.
fn place_zh(at: &NetworkPlace) -> String {
    format!("{} 网络 {}", block_zh(&at.block), at.network)
}
