//! The compiler's diagnostics in words: each [`Finding`] in English and in Chinese, the place
//! it points at, and the line `check` prints (docs/diagnostics.md; docs/files.md,
//! "Diagnostics").

mod check;
mod il;
mod lower;
mod machine;
mod scenario;
mod signals;
mod tables;
mod titles;

pub use titles::title;

use crate::Lang;
use ladder_engine::compiler::{Diagnostic, Finding, Location, Origin, Severity};

/// What `d` found and how to fix it, in `lang`.
pub fn message(d: &Diagnostic, lang: Lang) -> String {
    finding(&d.finding, lang)
}

/// What a finding says, in `lang`.
pub fn finding(f: &Finding, lang: Lang) -> String {
    match f {
        Finding::Check(f) => check::text(f, lang),
        Finding::Table(f) => tables::text(f, lang),
        Finding::Lower(f) => lower::text(f, lang),
        Finding::Il(f) => il::text(f, lang),
        Finding::Signal(f) => signals::text(f, lang),
        Finding::Machine(f) => machine::text(f, lang),
        Finding::Scenario(f) => scenario::text(f, lang),
    }
}

/// The line `check` prints for `d` with `path` in front (docs/files.md, "Diagnostics"):
/// `PATH:BLOCK:NETWORK:ROW:COL: error: MESSAGE [CODE]` for a ladder cell (1-based), or
/// `PATH:LINE: error: MESSAGE [CODE]` for an IL line. In Chinese only the message changes, so
/// the shape stays machine-readable.
pub fn render(d: &Diagnostic, path: &str, lang: Lang) -> String {
    let l = &d.location;
    let place = match l.origin {
        Origin::Line(line) => format!("{path}:{line}"),
        Origin::Cell { row, col } => format!(
            "{path}:{}:{}:{}:{}",
            l.block_label,
            l.network + 1,
            row + 1,
            col + 1
        ),
        Origin::None => format!("{path}:{}:{}:0:0", l.block_label, l.network + 1),
    };
    format!(
        "{place}: {}: {} [{}]",
        d.severity(),
        message(d, lang),
        d.code.as_str()
    )
}

/// `d` as the editor lists it, with `name` (the file) in front: in English the line `check`
/// prints; in Chinese `NAME 二级程序 网络 3 行 1 列 2：错误：[L020] MESSAGE`.
pub fn shown(d: &Diagnostic, name: &str, lang: Lang) -> String {
    match lang {
        Lang::En => render(d, name, Lang::En),
        Lang::Zh => {
            let severity = match d.severity() {
                Severity::Error => "错误",
                Severity::Warning => "警告",
            };
            format!(
                "{name} {}：{severity}：[{}] {}",
                place(&d.location, Lang::Zh),
                d.code.as_str(),
                message(d, Lang::Zh)
            )
        }
    }
}

/// Where `l` points, in `lang`. In English as `check` names blocks and tables
/// (`LEVEL2 network 3 row 1 col 2`, `DATA 2 row 1 col 5`, `line 5`); in Chinese
/// `二级程序 网络 3 行 1 列 2`, `数据表 DT 行 1 列 5`, `第 5 行`. Rows and columns count from 1.
pub fn place(l: &Location, lang: Lang) -> String {
    match lang {
        Lang::En => place_en(l),
        Lang::Zh => place_zh(l),
    }
}

fn place_en(l: &Location) -> String {
    let label = l.block_label.as_str();
    let ladder = label.starts_with("LEVEL")
        || label
            .strip_prefix('P')
            .is_some_and(|n| n.bytes().all(|b| b.is_ascii_digit()));
    let what = if ladder {
        format!("{label} network {}", l.network + 1)
    } else {
        format!("{label} {}", l.network + 1)
    };
    match l.origin {
        Origin::Cell { row, col } => format!("{what} row {} col {}", row + 1, col + 1),
        Origin::Line(line) => format!("line {line}"),
        Origin::None => what,
    }
}

fn place_zh(l: &Location) -> String {
    let network = l.network + 1;
    let place = match l.block_label.as_str() {
        "LEVEL1" => format!("一级程序 网络 {network}"),
        "LEVEL2" => format!("二级程序 网络 {network}"),
        "SYMBOLS" => format!("符号表 {network}"),
        // The data tables' numbers (1 D, 2 DT, 3 DC, 4 D_FLOAT) as their names.
        "DATA" => match l.network {
            0 => "数据表 D".to_string(),
            1 => "数据表 DT".to_string(),
            2 => "数据表 DC".to_string(),
            3 => "数据表 D_FLOAT".to_string(),
            _ => format!("数据表 {network}"),
        },
        "MESSAGES" => "显示信息表".to_string(),
        "DIAGNOSIS" => "诊断信息表".to_string(),
        "PERMISSIONS" => "权限表".to_string(),
        "MCODES" => "M 代码表".to_string(),
        "VERSION" => "梯形图版本信息".to_string(),
        "MACHINE" => format!("机床模型 设备 {network}"),
        "SCENARIOS" => format!("场景 {network}"),
        sub if sub.starts_with('P') => format!("子程序 {sub} 网络 {network}"),
        other => format!("{other} 网络 {network}"),
    };
    match l.origin {
        Origin::Line(line) => format!("第 {line} 行"),
        Origin::Cell { row, col } => format!("{place} 行 {} 列 {}", row + 1, col + 1),
        Origin::None => place,
    }
}

#[cfg(test)]
mod corpus_tests;
#[cfg(test)]
mod tests;
