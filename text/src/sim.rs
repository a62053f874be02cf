//! What a stimulus script's run reports, in words: `print` values, `expect`s that did not
//! hold, halts and refusals. Both languages keep the line's machine-readable shape
//! (docs/scripts.md): `SCRIPT:LINE: expect ADDR = VALUE, got ACTUAL` and `SCRIPT:LINE: cnc:
//! MESSAGE` keep their words, the Chinese saying what they mean after them, so a tool that
//! reads one language reads the other.

use crate::Lang;
use ladder_engine::sim::{Event, Report};

/// One reported line of the script `script`, in `lang`.
pub fn report(script: &str, r: &Report, lang: Lang) -> String {
    let zh = lang == Lang::Zh;
    let at = format!("{script}:{}", r.line);
    match (&r.event, zh) {
        (Event::Value { probe, value }, _) => format!("{probe} = {value}"),
        (Event::Halted(h), false) => format!("{at}: PLC halted at {}", crate::halt::halt(h, lang)),
        (Event::Halted(h), true) => format!("{at}: PLC 停止于 {}", crate::halt::halt(h, lang)),
        (Event::Refused(part, r), _) => {
            format!(
                "{at}: {}: {}",
                part.word(),
                crate::refusal::refusal(r, lang)
            )
        }
        (Event::Expected { probe, want, got }, false) => {
            format!("{at}: expect {probe} = {want}, got {got}")
        }
        (Event::Expected { probe, want, got }, true) => {
            format!("{at}: expect {probe} = {want}, got {got}（实际值与期望值不符）")
        }
        (Event::Unreadable(part, e), false) => format!("{at}: {}: {}", part.word(), e.en()),
        (Event::Unreadable(part, e), true) => format!(
            "{at}: {}: {}",
            part.word(),
            crate::errors::cnc_error(e, crate::Lang::Zh)
        ),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use ladder_engine::cnc::CncError;
    use ladder_engine::refusal::Refusal;
    use ladder_engine::sim::Part;
    use ladder_engine::vm::{Halt, HaltReason};

    /// One report of every kind; the `match` fails to compile when a kind is added without
    /// an example here.
    fn examples() -> Vec<Event> {
        let all = vec![
            Event::Value {
                probe: "R0010".into(),
                value: "42".into(),
            },
            Event::Halted(Halt {
                block: "LEVEL2".into(),
                network: 3,
                reason: HaltReason::Watchdog {
                    level: 2,
                    steps: 200_000,
                },
            }),
            Event::Refused(Part::Scenario, Refusal::ScenarioNotApplied("once".into())),
            Event::Expected {
                probe: "Y0000.3".into(),
                want: "1".into(),
                got: "0".into(),
            },
            Event::Unreadable(Part::Device, CncError::NoMachineModel),
        ];
        for e in &all {
            match e {
                Event::Value { .. }
                | Event::Halted(_)
                | Event::Refused(..)
                | Event::Expected { .. }
                | Event::Unreadable(..) => {}
            }
        }
        all
    }

    fn has_cjk(s: &str) -> bool {
        s.chars().any(|c| ('\u{4e00}'..='\u{9fff}').contains(&c))
    }

    #[test]
    fn every_report_reads_in_both_languages_in_one_shape() {
        for event in examples() {
            let r = Report { line: 7, event };
            let (en, zh) = (
                report("t.script", &r, Lang::En),
                report("t.script", &r, Lang::Zh),
            );
            if let Event::Value { .. } = r.event {
                assert_eq!((en.as_str(), zh.as_str()), ("R0010 = 42", "R0010 = 42"));
                continue;
            }
            // The place and the part stay as written, so a tool reads either language; the
            // Chinese says in Chinese what the line means.
            assert!(en.starts_with("t.script:7: "), "{en}");
            assert!(zh.starts_with("t.script:7: "), "{zh}");
            assert!(has_cjk(&zh), "{zh}");
            assert!(!has_cjk(&en), "{en}");
        }
        let expected = Report {
            line: 3,
            event: examples().swap_remove(3),
        };
        assert_eq!(
            report("s", &expected, Lang::En),
            "s:3: expect Y0000.3 = 1, got 0"
        );
        assert_eq!(
            report("s", &expected, Lang::Zh),
            "s:3: expect Y0000.3 = 1, got 0（实际值与期望值不符）"
        );
    }
}
