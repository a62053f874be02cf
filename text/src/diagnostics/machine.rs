//! The words of [`MachineFinding`]: each finding in English and in Chinese, side by side.

use crate::Lang;
use crate::quoted::model_error;
use ladder_engine::compiler::MachineFinding;

/// What `f` found and how to fix it, in `lang`.
pub(super) fn text(f: &MachineFinding, lang: Lang) -> String {
    match f {
        MachineFinding::Device(e) => model_error(e, lang),
        MachineFinding::ReadsNothing {
            device,
            field,
            address: a,
        } => match lang {
            Lang::En => format!(
                "device `{device}`, {field}: nothing writes {a} (no coil, box or device): the device never sees it change; bind an output the program drives"
            ),
            Lang::Zh => format!(
                "设备 `{device}` 的 {field}：没有线圈、功能指令或设备写 {a}，设备看不到它变化；请绑定程序驱动的输出"
            ),
        },
        MachineFinding::PanelDrivesInput {
            device,
            address: a,
            row,
            col,
            label_en,
            label_zh,
        } => {
            // Counted from 1, as the panel editor shows them.
            let (row, col) = (u32::from(*row) + 1, u32::from(*col) + 1);
            match lang {
                Lang::En => format!(
                    "device `{device}` writes {a}, which the panel item in row {row}, column {col} ({label_en}) also drives: the device wins at every tick; make the item a lamp or unbind the device"
                ),
                Lang::Zh => format!(
                    "设备 `{device}` 写 {a}，第 {row} 行第 {col} 列的面板项（{label_zh}）也驱动它：每个周期都以设备为准；请把该项改为指示灯或解除设备的绑定"
                ),
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::quoted::expr_error;
    use ladder_engine::address::Address;
    use ladder_engine::devices::{ExprError, ModelError};

    /// The slot of each finding; no wildcard, so a new variant does not compile here until it
    /// has one, and the test fails until it has an example.
    fn slot(f: &MachineFinding) -> usize {
        match f {
            MachineFinding::Device(_) => 0,
            MachineFinding::ReadsNothing { .. } => 1,
            MachineFinding::PanelDrivesInput { .. } => 2,
        }
    }
    const VARIANTS: usize = 3;

    fn at(text: &str) -> Address {
        Address::parse(text).unwrap()
    }

    /// A condition that does not read (M004).
    fn condition() -> ModelError {
        ModelError::Expression {
            device: "door".into(),
            field: "condition",
            error: ExprError::Unclosed,
        }
    }

    fn examples() -> Vec<MachineFinding> {
        vec![
            MachineFinding::Device(ModelError::Name("R10".into())),
            MachineFinding::Device(ModelError::NameTwice {
                name: "door".into(),
                first: 1,
            }),
            MachineFinding::Device(ModelError::NotInput {
                device: "door".into(),
                field: "closed",
                address: at("Y0001.2"),
            }),
            MachineFinding::Device(ModelError::Start { axis: 5 }),
            MachineFinding::Device(condition()),
            MachineFinding::Device(ModelError::TwoWriters {
                device: "clamp".into(),
                address: at("X0001.6"),
                other: "door".into(),
            }),
            MachineFinding::ReadsNothing {
                device: "clamp".into(),
                field: "close".into(),
                address: at("Y0000.6"),
            },
            MachineFinding::PanelDrivesInput {
                device: "door".into(),
                address: at("X0001.6"),
                row: 2,
                col: 4,
                label_en: "Door".into(),
                label_zh: "门".into(),
            },
        ]
    }

    #[test]
    fn every_machine_finding_says_in_chinese_what_it_says_in_english() {
        let mut seen = [false; VARIANTS];
        for f in &examples() {
            seen[slot(f)] = true;
            crate::bilingual::assert_bilingual(&text(f, Lang::En), &text(f, Lang::Zh));
        }
        assert_eq!(
            seen, [true; VARIANTS],
            "a machine finding without an example"
        );
    }

    #[test]
    fn machine_findings_read_as_they_always_have() {
        let m = condition();
        for lang in [Lang::En, Lang::Zh] {
            let words = text(&MachineFinding::Device(m.clone()), lang);
            assert_eq!(words, model_error(&m, lang));
            assert!(
                words.ends_with(&expr_error(&ExprError::Unclosed, lang)),
                "{words}"
            );
        }
        let reads = &examples()[6];
        assert_eq!(
            text(reads, Lang::En),
            "device `clamp`, close: nothing writes Y0000.6 (no coil, box or device): the device never sees it change; bind an output the program drives"
        );
        assert_eq!(
            text(reads, Lang::Zh),
            "设备 `clamp` 的 close：没有线圈、功能指令或设备写 Y0000.6，设备看不到它变化；请绑定程序驱动的输出"
        );
        let panel = &examples()[7];
        assert_eq!(
            text(panel, Lang::En),
            "device `door` writes X0001.6, which the panel item in row 3, column 5 (Door) also drives: the device wins at every tick; make the item a lamp or unbind the device"
        );
        assert_eq!(
            text(panel, Lang::Zh),
            "设备 `door` 写 X0001.6，第 3 行第 5 列的面板项（门）也驱动它：每个周期都以设备为准；请把该项改为指示灯或解除设备的绑定"
        );
    }
}
