//! The title of each diagnostic code: what is wrong in one phrase, in the words of the GSK
//! manual in Chinese (docs/diagnostics.md gives each code's meaning).

use crate::Lang;
use ladder_engine::compiler::Code;

/// What `code` means, in one phrase in `lang`: `未知指令`, `unknown instruction`.
pub fn title(code: Code, lang: Lang) -> &'static str {
    let (zh, en) = titles(code);
    match lang {
        Lang::Zh => zh,
        Lang::En => en,
    }
}

/// Both titles in one exhaustive match, so a new code cannot go without either.
fn titles(code: Code) -> (&'static str, &'static str) {
    if let Some(t) = warning_titles(code) {
        return t;
    }
    match code {
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
fn warning_titles(code: Code) -> Option<(&'static str, &'static str)> {
    Some(match code {
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

#[cfg(test)]
mod tests {
    use super::*;

    fn is_cjk(c: char) -> bool {
        ('\u{4e00}'..='\u{9fff}').contains(&c)
    }

    #[test]
    fn every_code_has_a_chinese_and_an_english_title() {
        for code in Code::ALL {
            let zh = title(*code, Lang::Zh);
            assert!(zh.chars().any(is_cjk), "{code:?}: {zh}");
            let en = title(*code, Lang::En);
            assert!(!en.is_empty() && en.is_ascii(), "{code:?}: {en}");
        }
    }
}
