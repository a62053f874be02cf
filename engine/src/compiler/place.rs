//! Where an instruction is, and how a message names that place in either language: a
//! diagnostic about two instructions (a coil driven twice, a label defined twice) names the
//! other one's place in its text.

use super::Program;
use super::diag::{Location, Origin};

/// Where an instruction is: (block, network, origin).
pub type InstrPlace = (usize, usize, Origin);

/// The place of `p` in English, as a diagnostic's location reads.
pub(super) fn place_text(program: &Program, p: InstrPlace) -> String {
    let block = program.blocks[p.0].kind.label();
    match p.2 {
        Origin::Line(l) => format!("line {l}"),
        Origin::Cell { row, col } => {
            format!(
                "{block} network {} row {} col {}",
                p.1 + 1,
                row + 1,
                col + 1
            )
        }
        Origin::None => format!("{block} network {}", p.1 + 1),
    }
}

/// The place of `p` in Chinese, as a diagnostic's location reads.
pub(super) fn place_text_zh(program: &Program, p: InstrPlace) -> String {
    describe_zh(&Location {
        block: p.0,
        block_label: program.blocks[p.0].kind.label(),
        network: p.1,
        origin: p.2,
    })
}

/// Where, in Chinese, as a diagnostic's location reads.
fn describe_zh(l: &Location) -> String {
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
