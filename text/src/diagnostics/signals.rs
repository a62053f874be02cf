//! The words of [`SignalFinding`]: each finding in English and in Chinese, side by side.

use crate::Lang;
use ladder_engine::address::Address;
use ladder_engine::compiler::SignalFinding;

/// What `f` found and how to fix it, in `lang`.
pub(super) fn text(f: &SignalFinding, lang: Lang) -> String {
    match f {
        SignalFinding::StrobeNoFinish {
            strobe: name,
            address: a,
            finish: own,
            finish_address: own_a,
        } => match lang {
            Lang::En => format!(
                "{name} {a} is read, but nothing it drives leads to FIN G0004.3 or {own} {own_a}: the CNC waits for the finish forever; end the function's logic in FIN"
            ),
            Lang::Zh => format!(
                "读取了 {name} {a}，但由它驱动的逻辑都不通向 FIN G0004.3 或 {own} {own_a}：CNC 将一直等待完成信号；请让该功能的逻辑最终输出 FIN"
            ),
        },
        SignalFinding::FinishWriters { name, address: a } => match lang {
            Lang::En => format!(
                "{name} {a} is written by more than one rung: the last write of the scan wins and a finish can be lost or held; gather every completion into one rung"
            ),
            Lang::Zh => format!(
                "{name} {a} 被多个梯级写入：以扫描中最后一次写入为准，完成信号可能丢失或一直保持；请把所有完成条件归并到一个梯级"
            ),
        },
        SignalFinding::FinishDrivenAndLatched { name, address: a } => match lang {
            Lang::En => format!(
                "{name} {a} is both driven by a coil or box and latched with SET/RST here: the coil rewrites it every scan, so the latch does nothing or fights it; use one or the other"
            ),
            Lang::Zh => format!(
                "{name} {a} 既由线圈或功能指令驱动，又在此处用 SET/RST 锁存：线圈每个扫描都会改写它，锁存无效或与之冲突；请只用其中一种"
            ),
        },
        SignalFinding::FinishNeverReset { name, address: a } => match lang {
            Lang::En => format!(
                "{name} {a} is latched with SET and never RST: once set, the CNC sees every later M, S, T function finished at once and the sequence cannot end; reset it when the strobe drops"
            ),
            Lang::Zh => format!(
                "{name} {a} 用 SET 置位却从不 RST：一旦置位，之后的每个 M、S、T 功能都立即被当作完成，且完成序列无法结束；请在选通信号消失时复位"
            ),
        },
        SignalFinding::MCodeNotDecoded { code: m } => match lang {
            Lang::En => format!(
                "M{m:02} is in the M-code table but no rung decodes it: the CNC waits for its finish forever; decode it (DECB or CMP of F0010) or remove the row"
            ),
            Lang::Zh => format!(
                "M{m:02} 在 M 代码表中，但没有梯级对它译码：CNC 将一直等待它完成；请对它译码（DECB 或 CMP F0010）或删除该行"
            ),
        },
        SignalFinding::MCodeNotInTable { code: m } => match lang {
            Lang::En => format!(
                "M{m:02} is decoded here but has no row in the M-code table: add a row saying what it does"
            ),
            Lang::Zh => format!("此处对 M{m:02} 译码，但 M 代码表中没有它：请添加一行说明其功能"),
        },
        SignalFinding::EmergencyStopUnwritten { name, address } => unwritten(
            name,
            address,
            lang,
            ("the CNC stays in emergency stop", "CNC 一直处于急停状态"),
        ),
        SignalFinding::ResetUnwritten { name, address } => unwritten(
            name,
            address,
            lang,
            (
                "nothing on the machine (an M30 end, a reset button, the E-stop) can reset the CNC",
                "机床侧（M30 结束、复位按钮、急停）无法使 CNC 复位",
            ),
        ),
        SignalFinding::Mode1Unwritten { name, address } => unwritten(
            name,
            address,
            lang,
            (
                "no EDIT, MEM (automatic), JOG, DNC or REF mode can be selected",
                "无法选择编辑、自动、手动、DNC 或回零方式",
            ),
        ),
        SignalFinding::Mode2Unwritten { name, address } => unwritten(
            name,
            address,
            lang,
            ("the EDIT mode cannot be selected", "无法选择编辑方式"),
        ),
        SignalFinding::Mode4Unwritten { name, address } => unwritten(
            name,
            address,
            lang,
            (
                "no HANDLE, JOG or REF mode can be selected",
                "无法选择手脉、手动或回零方式",
            ),
        ),
        SignalFinding::RequestUnwritten {
            answer: an,
            answer_address: aa,
            request: rn,
            request_address: ra,
        } => match lang {
            Lang::En => format!(
                "{an} {aa} is read, but nothing writes {rn} {ra}, the request it answers: the answer never comes; drive {rn} or read something else"
            ),
            Lang::Zh => format!(
                "读取了 {an} {aa}，但它所应答的请求信号 {rn} {ra} 没有任何指令写：应答永远不会出现；请驱动 {rn} 或改读其它信号"
            ),
        },
        SignalFinding::AlarmNoMessage { address: a } => match lang {
            Lang::En => format!(
                "{a} is set here but its row in the message table has no alarm number: the CNC shows no alarm for it; give the row an alarm number and a text"
            ),
            Lang::Zh => format!(
                "此处置位 {a}，但信息表中它的行没有报警号：CNC 不会为它显示报警；请为该行填写报警号和文本"
            ),
        },
        SignalFinding::MessageNeverSet { address: a, number } => match lang {
            Lang::En => format!(
                "{a}: alarm {number} has a message but nothing in the program sets {a}: it can never show; set the bit where the fault is detected, or clear the row"
            ),
            Lang::Zh => format!(
                "{a}：报警 {number} 有信息，但程序中没有任何指令置位 {a}，它永远不会显示；请在检测到故障处置位该位，或清除该行"
            ),
        },
    }
}

/// W015 in `lang`: nothing writes `name` `address`; `lost` says in English and in Chinese
/// what the machine cannot do without it.
fn unwritten(name: &str, address: &Address, lang: Lang, lost: (&str, &str)) -> String {
    let (lost_en, lost_zh) = lost;
    match lang {
        Lang::En => format!(
            "nothing writes {name} {address}, so the CNC always sees it at 0: {lost_en}; drive it from the machine's inputs"
        ),
        Lang::Zh => format!(
            "没有任何指令写 {name} {address}，CNC 看到的始终是 0：{lost_zh}；请由机床的输入驱动它"
        ),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The slot of each finding; no wildcard, so a new variant does not compile here until it
    /// has one, and the test fails until it has an example.
    fn slot(f: &SignalFinding) -> usize {
        match f {
            SignalFinding::StrobeNoFinish { .. } => 0,
            SignalFinding::FinishWriters { .. } => 1,
            SignalFinding::FinishDrivenAndLatched { .. } => 2,
            SignalFinding::FinishNeverReset { .. } => 3,
            SignalFinding::MCodeNotDecoded { .. } => 4,
            SignalFinding::MCodeNotInTable { .. } => 5,
            SignalFinding::EmergencyStopUnwritten { .. } => 6,
            SignalFinding::ResetUnwritten { .. } => 7,
            SignalFinding::Mode1Unwritten { .. } => 8,
            SignalFinding::Mode2Unwritten { .. } => 9,
            SignalFinding::Mode4Unwritten { .. } => 10,
            SignalFinding::RequestUnwritten { .. } => 11,
            SignalFinding::AlarmNoMessage { .. } => 12,
            SignalFinding::MessageNeverSet { .. } => 13,
        }
    }
    const VARIANTS: usize = 14;

    fn at(text: &str) -> Address {
        Address::parse(text).unwrap()
    }

    fn examples() -> Vec<SignalFinding> {
        let signal = |name: &str, a: &str| (name.to_string(), at(a));
        let (fin, fin_a) = signal("MFIN", "G0005.0");
        let mut v = vec![
            SignalFinding::StrobeNoFinish {
                strobe: "TF".into(),
                address: at("F0007.3"),
                finish: "TFIN".into(),
                finish_address: at("G0005.3"),
            },
            SignalFinding::FinishWriters {
                name: fin.clone(),
                address: fin_a,
            },
            SignalFinding::FinishDrivenAndLatched {
                name: fin.clone(),
                address: fin_a,
            },
            SignalFinding::FinishNeverReset {
                name: fin,
                address: fin_a,
            },
            SignalFinding::MCodeNotDecoded { code: 5 },
            SignalFinding::MCodeNotInTable { code: 41 },
            SignalFinding::RequestUnwritten {
                answer: "MSBK".into(),
                answer_address: at("F0004.3"),
                request: "SBK".into(),
                request_address: at("G0046.1"),
            },
            SignalFinding::AlarmNoMessage {
                address: at("A0000.2"),
            },
            SignalFinding::MessageNeverSet {
                address: at("A0000.3"),
                number: 1001,
            },
        ];
        let (name, address) = signal("*ESP", "G0008.4");
        v.push(SignalFinding::EmergencyStopUnwritten { name, address });
        let (name, address) = signal("ERS", "G0008.7");
        v.push(SignalFinding::ResetUnwritten { name, address });
        let (name, address) = signal("MD1", "G0043.0");
        v.push(SignalFinding::Mode1Unwritten { name, address });
        let (name, address) = signal("MD2", "G0043.1");
        v.push(SignalFinding::Mode2Unwritten { name, address });
        let (name, address) = signal("MD4", "G0043.2");
        v.push(SignalFinding::Mode4Unwritten { name, address });
        v
    }

    #[test]
    fn every_cnc_finding_says_in_chinese_what_it_says_in_english() {
        let mut seen = [false; VARIANTS];
        for f in &examples() {
            seen[slot(f)] = true;
            crate::bilingual::assert_bilingual(&text(f, Lang::En), &text(f, Lang::Zh));
        }
        assert_eq!(seen, [true; VARIANTS], "a CNC finding without an example");
    }

    #[test]
    fn cnc_findings_read_as_they_always_have() {
        let strobe = &examples()[0];
        assert_eq!(
            text(strobe, Lang::En),
            "TF F0007.3 is read, but nothing it drives leads to FIN G0004.3 or TFIN G0005.3: the CNC waits for the finish forever; end the function's logic in FIN"
        );
        assert_eq!(
            text(strobe, Lang::Zh),
            "读取了 TF F0007.3，但由它驱动的逻辑都不通向 FIN G0004.3 或 TFIN G0005.3：CNC 将一直等待完成信号；请让该功能的逻辑最终输出 FIN"
        );
        let m = SignalFinding::MCodeNotDecoded { code: 5 };
        assert_eq!(
            text(&m, Lang::En),
            "M05 is in the M-code table but no rung decodes it: the CNC waits for its finish forever; decode it (DECB or CMP of F0010) or remove the row"
        );
        assert_eq!(
            text(&m, Lang::Zh),
            "M05 在 M 代码表中，但没有梯级对它译码：CNC 将一直等待它完成；请对它译码（DECB 或 CMP F0010）或删除该行"
        );
        let md4 = SignalFinding::Mode4Unwritten {
            name: "MD4".into(),
            address: at("G0043.2"),
        };
        assert_eq!(
            text(&md4, Lang::En),
            "nothing writes MD4 G0043.2, so the CNC always sees it at 0: no HANDLE, JOG or REF mode can be selected; drive it from the machine's inputs"
        );
        assert_eq!(
            text(&md4, Lang::Zh),
            "没有任何指令写 MD4 G0043.2，CNC 看到的始终是 0：无法选择手脉、手动或回零方式；请由机床的输入驱动它"
        );
        let alarm = SignalFinding::MessageNeverSet {
            address: at("A0000.3"),
            number: 1001,
        };
        assert_eq!(
            text(&alarm, Lang::En),
            "A0000.3: alarm 1001 has a message but nothing in the program sets A0000.3: it can never show; set the bit where the fault is detected, or clear the row"
        );
        assert_eq!(
            text(&alarm, Lang::Zh),
            "A0000.3：报警 1001 有信息，但程序中没有任何指令置位 A0000.3，它永远不会显示；请在检测到故障处置位该位，或清除该行"
        );
    }
}
