//! Why the PLC stopped, in words: the editor's status line, `bench` and a script's
//! `SCRIPT:LINE: PLC halted at …` line say the same.

use crate::Lang;
use ladder_engine::vm::{Halt, HaltReason};

/// Where and why the PLC stopped: `LEVEL2 network 2: a JMPB loop …`, `LEVEL2 网络 2：…`.
pub fn halt(h: &Halt, lang: Lang) -> String {
    let (block, network) = (&h.block, h.network);
    match lang {
        Lang::En => format!("{block} network {network}: {}", reason(h.reason, lang)),
        Lang::Zh => format!("{block} 网络 {network}：{}", reason(h.reason, lang)),
    }
}

/// What stopped the PLC, without the place.
pub fn reason(r: HaltReason, lang: Lang) -> String {
    match (r, lang) {
        (HaltReason::Watchdog { level, steps }, Lang::En) => format!(
            "a JMPB loop ran past {steps} steps in {}; the PLC is stopped until power-cycle",
            if level == 1 {
                "one level-1 scan"
            } else {
                "one level-2 cycle"
            }
        ),
        (HaltReason::Watchdog { level, steps }, Lang::Zh) => format!(
            "{}中 JMPB 循环超过 {steps} 步；PLC 已停止，需重新上电",
            if level == 1 {
                "一级程序的一次扫描"
            } else {
                "二级程序的一个周期"
            }
        ),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_halt_reads_in_both_languages_with_its_place_and_steps() {
        for (level, word) in [(1, "一级程序"), (2, "二级程序")] {
            let h = Halt {
                block: format!("LEVEL{level}"),
                network: 3,
                reason: HaltReason::Watchdog {
                    level,
                    steps: 200_000,
                },
            };
            // The `match` names every reason, so a new one needs its example here.
            match h.reason {
                HaltReason::Watchdog { .. } => {}
            }
            let (en, zh) = (halt(&h, Lang::En), halt(&h, Lang::Zh));
            assert!(
                en.starts_with(&format!(
                    "LEVEL{level} network 3: a JMPB loop ran past 200000 steps"
                )),
                "{en}"
            );
            assert!(zh.starts_with(&format!("LEVEL{level} 网络 3：")), "{zh}");
            assert!(zh.contains(word) && zh.contains("200000"), "{zh}");
        }
    }
}
