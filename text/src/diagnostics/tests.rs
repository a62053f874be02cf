use super::*;
use ladder_engine::address::Address;
use ladder_engine::compiler::{CheckFinding, SignalFinding};

/// A diagnostic at a place, of an undefined symbol (an error) or, with `warning`, of an alarm
/// bit without a message (W017).
fn diagnostic(block_label: &str, network: usize, origin: Origin, warning: bool) -> Diagnostic {
    let finding = if warning {
        Finding::Signal(SignalFinding::AlarmNoMessage {
            address: Address::parse("A0000.2").unwrap(),
        })
    } else {
        Finding::Check(CheckFinding::UndefinedSymbol {
            name: "NOWHERE".into(),
        })
    };
    Diagnostic {
        location: Location {
            block: 1,
            block_label: block_label.into(),
            network,
            origin,
        },
        code: finding.code(),
        finding,
    }
}

const EN: &str = "undefined symbol `NOWHERE`: define it in the symbol table or write the address";
const ZH: &str = "符号 `NOWHERE` 未定义：请在符号表中定义，或直接写地址";

#[test]
fn the_chinese_rendering_names_the_place_and_keeps_the_specifics() {
    let cell = Origin::Cell { row: 0, col: 1 };
    let d = diagnostic("LEVEL2", 2, cell, false);
    assert_eq!(
        shown(&d, "err.ldp", Lang::Zh),
        format!("err.ldp 二级程序 网络 3 行 1 列 2：错误：[L020] {ZH}")
    );
    let w = diagnostic("P0001", 0, Origin::None, true);
    assert!(
        shown(&w, "a", Lang::Zh)
            .starts_with("a 子程序 P0001 网络 1：警告：[W017] 此处置位 A0000.2"),
        "{}",
        shown(&w, "a", Lang::Zh)
    );
    let t = diagnostic("DATA", 1, cell, false);
    assert!(shown(&t, "a", Lang::Zh).starts_with("a 数据表 DT 行 1 列 2："));
    let il = diagnostic("LEVEL1", 0, Origin::Line(5), false);
    assert_eq!(
        shown(&il, "a.il", Lang::Zh),
        format!("a.il 第 5 行：错误：[L020] {ZH}")
    );
    assert_eq!(
        render(&d, "err.ldp", Lang::En),
        format!("err.ldp:LEVEL2:3:1:2: error: {EN} [L020]")
    );
    assert_eq!(
        shown(&d, "err.ldp", Lang::En),
        render(&d, "err.ldp", Lang::En)
    );
    assert_eq!(
        render(&d, "err.ldp", Lang::Zh),
        format!("err.ldp:LEVEL2:3:1:2: error: {ZH} [L020]")
    );
    assert!(
        render(&w, "a", Lang::Zh).starts_with("a:P0001:1:0:0: warning: 此处置位 A0000.2"),
        "{}",
        render(&w, "a", Lang::Zh)
    );
    assert!(render(&w, "a", Lang::Zh).ends_with(" [W017]"));
    assert_eq!(
        render(&il, "a.il", Lang::Zh),
        format!("a.il:5: error: {ZH} [L020]")
    );
    assert_eq!(message(&d, Lang::Zh), ZH);
    assert_eq!(message(&d, Lang::En), EN);
}

#[test]
fn a_place_reads_as_check_names_it() {
    let at = |label: &str, network, origin| Location {
        block: 0,
        block_label: label.into(),
        network,
        origin,
    };
    let cell = Origin::Cell { row: 0, col: 4 };
    assert_eq!(
        place(&at("LEVEL2", 2, cell), Lang::En),
        "LEVEL2 network 3 row 1 col 5"
    );
    assert_eq!(place(&at("DATA", 1, cell), Lang::En), "DATA 2 row 1 col 5");
    assert_eq!(place(&at("DATA", 1, cell), Lang::Zh), "数据表 DT 行 1 列 5");
    assert_eq!(
        place(&at("P0003", 0, Origin::None), Lang::En),
        "P0003 network 1"
    );
    assert_eq!(
        place(&at("LEVEL1", 0, Origin::Line(7)), Lang::Zh),
        "第 7 行"
    );
}
