//! Diagnostics: a stable code, a severity, a location and a message that says how to fix it.
//!
//! Every code has a line with an example in `docs/diagnostics.md`.

use std::fmt;

/// How bad a diagnostic is.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Severity {
    /// The program still compiles.
    Warning,
    /// The program does not compile.
    Error,
}

impl fmt::Display for Severity {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Severity::Warning => "warning",
            Severity::Error => "error",
        })
    }
}

/// Where an element or instruction came from: a grid cell of its network, or an IL line.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord, Default)]
pub enum Origin {
    /// Not tied to a place (generated code).
    #[default]
    None,
    /// Row and column (0-based) in the network's grid.
    Cell {
        /// Row, 0-based.
        row: u32,
        /// Column, 0-based.
        col: u32,
    },
    /// Line (1-based) of an instruction-list text.
    Line(u32),
}

/// Where a diagnostic points.
#[derive(Clone, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct Location {
    /// Block index in the ladder.
    pub block: usize,
    /// Block label (`LEVEL1`, `LEVEL2`, `P0001`).
    pub block_label: String,
    /// Network index in the block.
    pub network: usize,
    /// Cell or line in that network.
    pub origin: Origin,
}

/// Stable diagnostic codes.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
#[allow(missing_docs)] // Each code is documented in docs/diagnostics.md with an example.
pub enum Code {
    L001NotConnected,
    L002OpenBranch,
    L003ShortCircuit,
    L004Bridge,
    L005WrongColumn,
    L006NoContact,
    L007NotStandalone,
    L010UnknownInstruction,
    L011OperandCount,
    L012Syntax,
    L013BlockStack,
    L014BranchStack,
    L015LoadAfterOutput,
    L016NoOutput,
    L017NotDrawable,
    L018StackDepth,
    L020UndefinedSymbol,
    L021OperandKind,
    L022Area,
    L023AddressRange,
    L024ConstRange,
    L025ReadOnly,
    L030LabelTwice,
    L031UndefinedLabel,
    L032JumpOutOfBlock,
    L033UndefinedSub,
    L034Recursion,
    L035Level1Steps,
    L036ProgramSteps,
    L038SubNumber,
    T001SymbolName,
    T002SymbolTwice,
    T003DataAddress,
    T004DataValue,
    T005MessageNumber,
    T006TableName,
    T007SymbolArea,
    T008TableKey,
    M001DeviceName,
    M002DeviceAddress,
    M003DeviceParameter,
    M004DeviceCondition,
    M005InputTwice,
    W001CoilTwice,
    W002TimerTwice,
    W003BitsSpill,
    W004AddressTwice,
    W005MessageHalf,
    W006VersionLength,
    W007CommentLength,
    W008OutputTwice,
    W009PresetRange,
    W010DeviceReadsNothing,
    W011PanelDrivesDeviceInput,
    /// Strobe with no path to its finish signal.
    W012StrobeNoFinish,
    /// Finish signal written by several rungs or latched.
    W013FinishWriters,
    /// M-code table and decoding disagree.
    W014MCodeTable,
    /// Emergency stop, reset or mode signal never written.
    W015CncSignalUnwritten,
    /// Answer read but its request never written.
    W016RequestUnwritten,
    /// Alarm bit without a message row.
    W017AlarmNoMessage,
    /// Message row whose alarm bit is never set.
    W018MessageNeverSet,
    /// Saved scenario that cannot be applied.
    W019ScenarioBroken,
}

impl Code {
    /// Every code, in the order of docs/diagnostics.md.
    pub const ALL: &'static [Code] = &[
        Code::L001NotConnected,
        Code::L002OpenBranch,
        Code::L003ShortCircuit,
        Code::L004Bridge,
        Code::L005WrongColumn,
        Code::L006NoContact,
        Code::L007NotStandalone,
        Code::L010UnknownInstruction,
        Code::L011OperandCount,
        Code::L012Syntax,
        Code::L013BlockStack,
        Code::L014BranchStack,
        Code::L015LoadAfterOutput,
        Code::L016NoOutput,
        Code::L017NotDrawable,
        Code::L018StackDepth,
        Code::L020UndefinedSymbol,
        Code::L021OperandKind,
        Code::L022Area,
        Code::L023AddressRange,
        Code::L024ConstRange,
        Code::L025ReadOnly,
        Code::L030LabelTwice,
        Code::L031UndefinedLabel,
        Code::L032JumpOutOfBlock,
        Code::L033UndefinedSub,
        Code::L034Recursion,
        Code::L035Level1Steps,
        Code::L036ProgramSteps,
        Code::L038SubNumber,
        Code::T001SymbolName,
        Code::T002SymbolTwice,
        Code::T003DataAddress,
        Code::T004DataValue,
        Code::T005MessageNumber,
        Code::T006TableName,
        Code::T007SymbolArea,
        Code::T008TableKey,
        Code::M001DeviceName,
        Code::M002DeviceAddress,
        Code::M003DeviceParameter,
        Code::M004DeviceCondition,
        Code::M005InputTwice,
        Code::W001CoilTwice,
        Code::W002TimerTwice,
        Code::W003BitsSpill,
        Code::W004AddressTwice,
        Code::W005MessageHalf,
        Code::W006VersionLength,
        Code::W007CommentLength,
        Code::W008OutputTwice,
        Code::W009PresetRange,
        Code::W010DeviceReadsNothing,
        Code::W011PanelDrivesDeviceInput,
        Code::W012StrobeNoFinish,
        Code::W013FinishWriters,
        Code::W014MCodeTable,
        Code::W015CncSignalUnwritten,
        Code::W016RequestUnwritten,
        Code::W017AlarmNoMessage,
        Code::W018MessageNeverSet,
        Code::W019ScenarioBroken,
    ];

    /// What is wrong, in one Chinese phrase in the words of the GSK manual (docs/diagnostics.md
    /// gives each code's meaning): `未知指令`.
    pub fn title_zh(self) -> &'static str {
        self.titles().0
    }

    /// What is wrong, in one English phrase (docs/diagnostics.md): `unknown instruction`.
    pub fn title_en(self) -> &'static str {
        self.titles().1
    }

    /// Both titles in one exhaustive match, so a new code cannot go without either.
    fn titles(self) -> (&'static str, &'static str) {
        if let Some(t) = self.warning_titles() {
            return t;
        }
        match self {
            Code::L001NotConnected => (
                "元件未连接到左母线",
                "element not connected to the left rail",
            ),
            Code::L002OpenBranch => (
                "开路分支：其后没有线圈或功能指令",
                "open branch: no coil or box after it",
            ),
            Code::L003ShortCircuit => ("分支被并联的导线短路", "branch short-circuited by a wire"),
            Code::L004Bridge => (
                "分支在分支点后重新汇合或形成桥接",
                "branches rejoin or form a bridge",
            ),
            Code::L005WrongColumn => ("元件所在的列不对", "element in the wrong column"),
            Code::L006NoContact => ("输出之前没有触点", "output with no contact before it"),
            Code::L007NotStandalone => (
                "标号或子程序调用未单独成网络",
                "LBL/CALLU not standing alone",
            ),
            Code::L010UnknownInstruction => ("未知指令", "unknown instruction"),
            Code::L011OperandCount => ("操作数个数不对", "wrong operand count"),
            Code::L012Syntax => ("语法错误", "syntax error"),
            Code::L013BlockStack => (
                "ORB/ANB 没有可连接的逻辑块，或逻辑块未闭合",
                "no block for ORB/ANB, or a block left open",
            ),
            Code::L014BranchStack => (
                "MRD/MPP 没有对应的 MPS，或 MPS 未闭合",
                "MRD/MPP without MPS, or MPS left open",
            ),
            Code::L015LoadAfterOutput => (
                "MPS 未闭合时在输出之后直接取（LD）",
                "LD after an output while MPS is open",
            ),
            Code::L016NoOutput => ("网络没有输出", "network without an output"),
            Code::L017NotDrawable => (
                "指令序列无法画成梯形图",
                "instructions with no ladder drawing",
            ),
            Code::L018StackDepth => (
                "堆栈嵌套过深（超过 32 个逻辑块或 16 个分支点）",
                "stack too deep",
            ),
            Code::L020UndefinedSymbol => ("符号未定义", "undefined symbol"),
            Code::L021OperandKind => ("操作数类型不对", "wrong operand kind"),
            Code::L022Area => (
                "操作数不允许使用该地址区",
                "area not allowed for the operand",
            ),
            Code::L023AddressRange => ("地址或访问范围超出", "address or access out of range"),
            Code::L024ConstRange => (
                "常数超出范围或数字组格式不对",
                "constant out of range or malformed",
            ),
            Code::L025ReadOnly => ("写入只读地址区", "write to a read-only area"),
            Code::L030LabelTwice => ("标号重复定义", "label defined twice"),
            Code::L031UndefinedLabel => ("跳转到未定义的标号", "jump to an undefined label"),
            Code::L032JumpOutOfBlock => ("跳转超出所在程序块", "jump out of its block"),
            Code::L033UndefinedSub => ("调用未定义的子程序", "call of an undefined subprogram"),
            Code::L034Recursion => ("子程序递归调用", "recursive call"),
            Code::L035Level1Steps => (
                "一级程序步数过多（含所调用的子程序）",
                "too many steps in level 1",
            ),
            Code::L036ProgramSteps => ("程序总步数超出 PLC 容量", "too many steps in the program"),
            Code::L038SubNumber => (
                "子程序号重复或超出范围",
                "subprogram number twice or out of range",
            ),
            Code::T001SymbolName => ("符号名称无效", "invalid symbol name"),
            Code::T002SymbolTwice => ("符号重复定义", "symbol defined twice"),
            Code::T003DataAddress => (
                "数据表地址不对：地址区不符、超出范围或重复",
                "wrong data-table address",
            ),
            Code::T004DataValue => (
                "数据表的值超出上下限",
                "data-table value outside its limits",
            ),
            Code::T005MessageNumber => (
                "报警号超出范围或重复，或信息行超出 A 地址范围",
                "invalid or repeated alarm number",
            ),
            Code::T006TableName => (
                "符号表名称为空或已被占用",
                "symbol table name empty or taken",
            ),
            Code::T007SymbolArea => (
                "该地址区不能定义符号（标号、子程序号）",
                "no symbols for this area",
            ),
            Code::T008TableKey => (
                "诊断、权限或 M 代码表的地址或代码无效或重复",
                "invalid or repeated table key",
            ),
            Code::M001DeviceName => ("设备名无效或重复", "invalid or repeated device name"),
            Code::M002DeviceAddress => (
                "设备的地址无效、超出范围或不是输入位",
                "wrong device address",
            ),
            Code::M003DeviceParameter => ("设备参数不可能", "impossible device parameter"),
            Code::M004DeviceCondition => ("设备条件写法有误", "device condition does not read"),
            Code::M005InputTwice => ("两个设备驱动同一个输入", "two devices drive one input"),
            // Every warning has its titles above.
            _ => ("", ""),
        }
    }

    /// The titles of the warnings (`None` for an error).
    fn warning_titles(self) -> Option<(&'static str, &'static str)> {
        Some(match self {
            Code::W001CoilTwice => ("线圈重复输出", "coil driven twice"),
            Code::W002TimerTwice => ("定时器或计数器号重复使用", "timer or counter used twice"),
            Code::W003BitsSpill => (
                "比较结果位延续到下一个字节",
                "result bits continue into the next byte",
            ),
            Code::W004AddressTwice => ("地址在多个符号行中出现", "address in two symbol rows"),
            Code::W005MessageHalf => (
                "报警号没有信息文本，或文本没有报警号",
                "alarm number or text missing",
            ),
            Code::W006VersionLength => ("版本信息超出长度限制", "version information too long"),
            Code::W007CommentLength => (
                "注释超过 CNC 保存的 127 字节",
                "comment longer than 127 bytes",
            ),
            Code::W008OutputTwice => (
                "功能指令的输出地址被另一条指令覆盖",
                "box output also written by another instruction",
            ),
            Code::W009PresetRange => (
                "数据表中的定时器或计数器预置值超出范围",
                "table preset out of its instruction's range",
            ),
            Code::W010DeviceReadsNothing => (
                "设备读取的地址没有任何程序或设备写入",
                "device reads an address nothing writes",
            ),
            Code::W011PanelDrivesDeviceInput => (
                "操作面板也驱动设备的输入",
                "panel item drives a device's input",
            ),
            Code::W012StrobeNoFinish => (
                "选通信号没有通向完成信号的逻辑",
                "strobe with no path to its finish signal",
            ),
            Code::W013FinishWriters => (
                "完成信号多处写入或只置位不复位",
                "finish signal written by several rungs or latched",
            ),
            Code::W014MCodeTable => ("M 代码表与译码不一致", "M-code table and decoding disagree"),
            Code::W015CncSignalUnwritten => (
                "急停、复位或方式信号无人写",
                "emergency stop, reset or mode signal never written",
            ),
            Code::W016RequestUnwritten => (
                "读取应答信号但其请求信号无人写",
                "answer read but its request never written",
            ),
            Code::W017AlarmNoMessage => ("报警位没有信息行", "alarm bit without a message row"),
            Code::W018MessageNeverSet => (
                "信息行的报警位无人置位",
                "message row whose alarm bit is never set",
            ),
            Code::W019ScenarioBroken => ("场景无法应用", "scenario that cannot be applied"),
            _ => return None,
        })
    }

    /// The code as printed: `L012`, `W001`.
    pub fn as_str(self) -> &'static str {
        match self {
            Code::L001NotConnected => "L001",
            Code::L002OpenBranch => "L002",
            Code::L003ShortCircuit => "L003",
            Code::L004Bridge => "L004",
            Code::L005WrongColumn => "L005",
            Code::L006NoContact => "L006",
            Code::L007NotStandalone => "L007",
            Code::L010UnknownInstruction => "L010",
            Code::L011OperandCount => "L011",
            Code::L012Syntax => "L012",
            Code::L013BlockStack => "L013",
            Code::L014BranchStack => "L014",
            Code::L015LoadAfterOutput => "L015",
            Code::L016NoOutput => "L016",
            Code::L017NotDrawable => "L017",
            Code::L018StackDepth => "L018",
            Code::L020UndefinedSymbol => "L020",
            Code::L021OperandKind => "L021",
            Code::L022Area => "L022",
            Code::L023AddressRange => "L023",
            Code::L024ConstRange => "L024",
            Code::L025ReadOnly => "L025",
            Code::L030LabelTwice => "L030",
            Code::L031UndefinedLabel => "L031",
            Code::L032JumpOutOfBlock => "L032",
            Code::L033UndefinedSub => "L033",
            Code::L034Recursion => "L034",
            Code::L035Level1Steps => "L035",
            Code::L036ProgramSteps => "L036",
            Code::L038SubNumber => "L038",
            Code::T001SymbolName => "T001",
            Code::T002SymbolTwice => "T002",
            Code::T003DataAddress => "T003",
            Code::T004DataValue => "T004",
            Code::T005MessageNumber => "T005",
            Code::T006TableName => "T006",
            Code::T007SymbolArea => "T007",
            Code::T008TableKey => "T008",
            Code::W004AddressTwice => "W004",
            Code::W005MessageHalf => "W005",
            Code::W006VersionLength => "W006",
            Code::W007CommentLength => "W007",
            Code::W008OutputTwice => "W008",
            Code::W009PresetRange => "W009",
            Code::M001DeviceName => "M001",
            Code::M002DeviceAddress => "M002",
            Code::M003DeviceParameter => "M003",
            Code::M004DeviceCondition => "M004",
            Code::M005InputTwice => "M005",
            Code::W010DeviceReadsNothing => "W010",
            Code::W011PanelDrivesDeviceInput => "W011",
            Code::W012StrobeNoFinish => "W012",
            Code::W013FinishWriters => "W013",
            Code::W014MCodeTable => "W014",
            Code::W015CncSignalUnwritten => "W015",
            Code::W016RequestUnwritten => "W016",
            Code::W017AlarmNoMessage => "W017",
            Code::W018MessageNeverSet => "W018",
            Code::W019ScenarioBroken => "W019",
            Code::W001CoilTwice => "W001",
            Code::W002TimerTwice => "W002",
            Code::W003BitsSpill => "W003",
        }
    }

    /// Whether the problem leaves a network without a valid instruction list (export is
    /// refused: the list would not be what the ladder says).
    pub fn is_structural(self) -> bool {
        matches!(
            self,
            Code::L001NotConnected
                | Code::L002OpenBranch
                | Code::L003ShortCircuit
                | Code::L004Bridge
                | Code::L005WrongColumn
                | Code::L006NoContact
                | Code::L007NotStandalone
                | Code::L010UnknownInstruction
                | Code::L011OperandCount
                | Code::L012Syntax
                | Code::L013BlockStack
                | Code::L014BranchStack
                | Code::L015LoadAfterOutput
                | Code::L016NoOutput
                | Code::L017NotDrawable
        )
    }

    /// Warnings start with `W`, errors with `L`.
    pub fn severity(self) -> Severity {
        if self.as_str().starts_with('W') {
            Severity::Warning
        } else {
            Severity::Error
        }
    }
}

/// One finding of the compiler.
#[derive(Clone, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct Diagnostic {
    /// Where.
    pub location: Location,
    /// Which check.
    pub code: Code,
    /// What is wrong and how to fix it.
    pub message: String,
    /// The same message in Chinese, with the same specifics (addresses, names, numbers).
    pub message_zh: String,
}

impl Diagnostic {
    /// Error or warning.
    pub fn severity(&self) -> Severity {
        self.code.severity()
    }

    /// Formats the diagnostic as `check` prints it (docs/files.md, "Diagnostics"), with `path`
    /// in front: `PATH:BLOCK:NETWORK:ROW:COL: error: MESSAGE` for ladder cells (1-based), or
    /// `PATH:LINE: error: MESSAGE` for IL lines.
    pub fn render(&self, path: &str) -> String {
        self.render_in(path, false)
    }

    /// The diagnostic for a Chinese reader, with `name` (the file) in front:
    /// `NAME 二级程序 网络 3 行 1 列 2：错误：[L020] MESSAGE_ZH`, the place as
    /// [`Location::describe_zh`] writes it.
    pub fn render_zh(&self, name: &str) -> String {
        let severity = match self.severity() {
            Severity::Error => "错误",
            Severity::Warning => "警告",
        };
        format!(
            "{name} {}：{severity}：[{}] {}",
            self.location.describe_zh(),
            self.code.as_str(),
            self.message_zh
        )
    }

    /// [`Diagnostic::render`] with the message in Chinese when `zh` is set: the same
    /// machine-readable shape `PATH:BLOCK:NETWORK:ROW:COL: error: MESSAGE_ZH [CODE]` (the
    /// place and the `error`/`warning` keyword stay as they are), or exactly `render(path)`.
    pub fn render_in(&self, path: &str, zh: bool) -> String {
        let l = &self.location;
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
            self.severity(),
            self.message_in(zh),
            self.code.as_str()
        )
    }

    /// The message in Chinese when `zh` is set, else in English.
    pub fn message_in(&self, zh: bool) -> &str {
        if zh { &self.message_zh } else { &self.message }
    }
}

impl Location {
    /// The ladder cell it points at, when it points at one (a click on the diagnostic goes
    /// there; the diagram marks it).
    pub fn cell(&self) -> Option<crate::model::CellRef> {
        match self.origin {
            Origin::Cell { row, col } => Some(crate::model::CellRef {
                block: self.block,
                network: self.network,
                row: row as usize,
                col: col as usize,
            }),
            _ => None,
        }
    }

    /// Where, in Chinese: `二级程序 网络 3 行 1 列 2`, `符号表 1 行 2 列 1`, `第 5 行` for an IL
    /// line. Rows and columns count from 1, as `render` prints them (docs/diagnostics.md).
    pub fn describe_zh(&self) -> String {
        let network = self.network + 1;
        let place = match self.block_label.as_str() {
            "LEVEL1" => format!("一级程序 网络 {network}"),
            "LEVEL2" => format!("二级程序 网络 {network}"),
            "SYMBOLS" => format!("符号表 {network}"),
            // The data tables' numbers (1 D, 2 DT, 3 DC, 4 D_FLOAT) as their names.
            "DATA" => match self.network {
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
        match self.origin {
            Origin::Line(line) => format!("第 {line} 行"),
            Origin::Cell { row, col } => format!("{place} 行 {} 列 {}", row + 1, col + 1),
            Origin::None => place,
        }
    }
}

/// Collects diagnostics for one block and network at a time.
#[derive(Debug, Default)]
pub struct Sink {
    /// Everything reported so far.
    pub diagnostics: Vec<Diagnostic>,
    block: usize,
    block_label: String,
    network: usize,
}

impl Sink {
    /// Sets the block and network that following reports are about.
    pub fn at(&mut self, block: usize, block_label: &str, network: usize) {
        self.block = block;
        if self.block_label != block_label {
            self.block_label = block_label.to_string();
        }
        self.network = network;
    }

    /// Reports at `origin` in the current network, in English and in Chinese.
    pub fn report(
        &mut self,
        origin: Origin,
        code: Code,
        message: impl Into<String>,
        message_zh: impl Into<String>,
    ) {
        self.diagnostics.push(Diagnostic {
            location: Location {
                block: self.block,
                block_label: self.block_label.clone(),
                network: self.network,
                origin,
            },
            code,
            message: message.into(),
            message_zh: message_zh.into(),
        });
    }

    /// Number of errors so far.
    pub fn error_count(&self) -> usize {
        self.diagnostics
            .iter()
            .filter(|d| d.severity() == Severity::Error)
            .count()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn is_cjk(c: char) -> bool {
        ('\u{4e00}'..='\u{9fff}').contains(&c)
    }

    #[test]
    fn every_code_has_a_chinese_and_an_english_title() {
        for code in Code::ALL {
            let zh = code.title_zh();
            assert!(zh.chars().any(is_cjk), "{code:?}: {zh}");
            assert!(!code.title_en().is_empty(), "{code:?}");
            assert!(code.title_en().is_ascii(), "{code:?}");
        }
    }

    #[test]
    fn the_list_of_codes_is_the_documented_list() {
        let doc = include_str!("../../../docs/diagnostics.md");
        let documented: Vec<&str> = doc
            .lines()
            .filter_map(|l| l.strip_prefix("| "))
            .filter_map(|l| l.split(' ').next())
            .filter(|c| c.len() == 4 && c[1..].bytes().all(|b| b.is_ascii_digit()))
            .collect();
        let listed: Vec<&str> = Code::ALL.iter().map(|c| c.as_str()).collect();
        assert_eq!(listed, documented);
    }

    fn diagnostic(block_label: &str, network: usize, origin: Origin, code: Code) -> Diagnostic {
        Diagnostic {
            location: Location {
                block: 1,
                block_label: block_label.into(),
                network,
                origin,
            },
            code,
            message: "undefined symbol `NOWHERE`".into(),
            message_zh: "符号 `NOWHERE` 未定义".into(),
        }
    }

    #[test]
    fn the_chinese_rendering_names_the_place_and_keeps_the_specifics() {
        let cell = Origin::Cell { row: 0, col: 1 };
        let d = diagnostic("LEVEL2", 2, cell, Code::L020UndefinedSymbol);
        assert_eq!(
            d.render_zh("err.ldp"),
            "err.ldp 二级程序 网络 3 行 1 列 2：错误：[L020] 符号 `NOWHERE` 未定义"
        );
        let w = diagnostic("P0001", 0, Origin::None, Code::W001CoilTwice);
        assert_eq!(
            w.render_zh("a"),
            "a 子程序 P0001 网络 1：警告：[W001] 符号 `NOWHERE` 未定义"
        );
        let t = diagnostic("DATA", 1, cell, Code::T004DataValue);
        assert!(t.render_zh("a").starts_with("a 数据表 DT 行 1 列 2："));
        let il = diagnostic("LEVEL1", 0, Origin::Line(5), Code::L012Syntax);
        assert_eq!(
            il.render_zh("a.il"),
            "a.il 第 5 行：错误：[L012] 符号 `NOWHERE` 未定义"
        );
        assert_eq!(
            d.render("err.ldp"),
            "err.ldp:LEVEL2:3:1:2: error: undefined symbol `NOWHERE` [L020]"
        );
        assert_eq!(d.render_in("err.ldp", false), d.render("err.ldp"));
        assert_eq!(
            d.render_in("err.ldp", true),
            "err.ldp:LEVEL2:3:1:2: error: 符号 `NOWHERE` 未定义 [L020]"
        );
        assert_eq!(
            w.render_in("a", true),
            "a:P0001:1:0:0: warning: 符号 `NOWHERE` 未定义 [W001]"
        );
        assert_eq!(
            il.render_in("a.il", true),
            "a.il:5: error: 符号 `NOWHERE` 未定义 [L012]"
        );
        assert_eq!(d.message_in(true), "符号 `NOWHERE` 未定义");
        assert_eq!(d.message_in(false), "undefined symbol `NOWHERE`");
    }
}
