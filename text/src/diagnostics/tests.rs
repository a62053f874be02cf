use super::*;
use ladder_engine::compiler::Code;

fn diagnostic(block_label: &str, network: usize, origin: Origin, code: Code) -> Diagnostic {
    Diagnostic {
        location: Location {
            block: 1,
            block_label: block_label.into(),
            network,
            origin,
        },
        code,
        finding: Finding::Worded {
            code,
            en: "undefined symbol `NOWHERE`".into(),
            zh: "符号 `NOWHERE` 未定义".into(),
        },
    }
}

#[test]
fn the_chinese_rendering_names_the_place_and_keeps_the_specifics() {
    let cell = Origin::Cell { row: 0, col: 1 };
    let d = diagnostic("LEVEL2", 2, cell, Code::L020UndefinedSymbol);
    assert_eq!(
        shown(&d, "err.ldp", Lang::Zh),
        "err.ldp 二级程序 网络 3 行 1 列 2：错误：[L020] 符号 `NOWHERE` 未定义"
    );
    let w = diagnostic("P0001", 0, Origin::None, Code::W001CoilTwice);
    assert_eq!(
        shown(&w, "a", Lang::Zh),
        "a 子程序 P0001 网络 1：警告：[W001] 符号 `NOWHERE` 未定义"
    );
    let t = diagnostic("DATA", 1, cell, Code::T004DataValue);
    assert!(shown(&t, "a", Lang::Zh).starts_with("a 数据表 DT 行 1 列 2："));
    let il = diagnostic("LEVEL1", 0, Origin::Line(5), Code::L012Syntax);
    assert_eq!(
        shown(&il, "a.il", Lang::Zh),
        "a.il 第 5 行：错误：[L012] 符号 `NOWHERE` 未定义"
    );
    assert_eq!(
        render(&d, "err.ldp", Lang::En),
        "err.ldp:LEVEL2:3:1:2: error: undefined symbol `NOWHERE` [L020]"
    );
    assert_eq!(
        shown(&d, "err.ldp", Lang::En),
        render(&d, "err.ldp", Lang::En)
    );
    assert_eq!(
        render(&d, "err.ldp", Lang::Zh),
        "err.ldp:LEVEL2:3:1:2: error: 符号 `NOWHERE` 未定义 [L020]"
    );
    assert_eq!(
        render(&w, "a", Lang::Zh),
        "a:P0001:1:0:0: warning: 符号 `NOWHERE` 未定义 [W001]"
    );
    assert_eq!(
        render(&il, "a.il", Lang::Zh),
        "a.il:5: error: 符号 `NOWHERE` 未定义 [L012]"
    );
    assert_eq!(message(&d, Lang::Zh), "符号 `NOWHERE` 未定义");
    assert_eq!(message(&d, Lang::En), "undefined symbol `NOWHERE`");
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
